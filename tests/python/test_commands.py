"""matc.evaluate, matc.describe_basis and matc.output_file_names: what `matc eval`, `matc basis`
and `matc layout` print, through the same public API, equal to the CLI's output."""

import json

import pytest

import matc
from conftest import EXAMPLES, matc_eval, run_matc


@pytest.mark.parametrize("name", ["gold.json", "copper_lacquered.json", "tinted_steel.json"])
def test_evaluate_is_matc_eval(name):
    args = ["--mu", "1,0.5,0", "--ndotv", "0.2,0.9", "--roughness", "0.1,0.6", "--lut-size", "16",
            "--lut-samples", "64"]
    ours = matc.evaluate(EXAMPLES / name, mu=[1, 0.5, 0], ndotv=[0.2, 0.9], roughness=[0.1, 0.6],
                         lut_size=16, lut_samples=64)
    assert ours == matc_eval(EXAMPLES / name, *args)


def test_evaluate_with_a_quad_light_and_options():
    quad = "-1,-1,2;1,-1,2;1,1,2;-1,1,2"
    ours = matc.evaluate(EXAMPLES / "gold.json", ndotv=0.5, roughness=0.4, quad_light=quad,
                         light_samples=1024, lut_size=16, lut_samples=64, basis="extended")
    cli = matc_eval(EXAMPLES / "gold.json", "--ndotv", "0.5", "--roughness", "0.4",
                    "--quad-light", quad, "--light-samples", "1024", "--lut-size", "16",
                    "--lut-samples", "64", "--basis", "extended")
    assert ours == cli
    assert "L_reference" in ours


def test_evaluate_with_metalness_is_matc_eval():
    ours = matc.evaluate(EXAMPLES / "chromium.json", mu=[1, 0.5, 0.1], ndotv=[0.3], roughness=[0.5],
                         reference=False, metalness=0.4, lut_size=16, lut_samples=64)
    cli = matc_eval(EXAMPLES / "chromium.json", "--mu", "1,0.5,0.1", "--ndotv", "0.3",
                    "--roughness", "0.5", "--no-reference", "--metalness", "0.4", "--lut-size", "16",
                    "--lut-samples", "64")
    assert ours == cli
    assert ours["F_metal_rough"][0] == pytest.approx(
        [0.6 * 0.04 + 0.4 * f for f in ours["F"][0]], abs=1e-15)


def test_evaluate_with_metalness_under_a_coat_is_matc_eval():
    # The coat lobe lies over the mix; the dielectric under it is scaled by the coat's
    # transmission at NdotV (mu for F): 1 - the coat lobe's F there.
    ours = matc.evaluate(EXAMPLES / "copper_lacquered.json", mu=[1, 0.5, 0.1], ndotv=[0.3],
                         roughness=[0.5], reference=False, metalness=0.4, lut_size=16,
                         lut_samples=64)
    cli = matc_eval(EXAMPLES / "copper_lacquered.json", "--mu", "1,0.5,0.1", "--ndotv", "0.3",
                    "--roughness", "0.5", "--no-reference", "--metalness", "0.4", "--lut-size",
                    "16", "--lut-samples", "64")
    assert ours == cli
    for i in range(3):
        coat = ours["F_coat"][i]
        assert ours["F_metal_rough"][i] == pytest.approx(
            [coat + 0.6 * d * (1 - coat) + 0.4 * b
             for d, b in zip(ours["F_dielectric"][i], ours["F_base"][i])], abs=1e-14)
    assert ours["Fbar_metal_rough"][0] != pytest.approx(ours["Fbar"][0], abs=1e-3)


@pytest.mark.parametrize("call, error, message", [
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu=0.5, metalness=1.5), ValueError,
     "metalness: element 0 is 1.5"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu=0.5, metalness=float("nan")), ValueError,
     "metalness: element 0 is nan"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu=0.5, metalness="0.5"), TypeError,
     "metalness: a real number"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu=0.5, metalness=True), TypeError,
     "metalness: a real number"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json"), ValueError, "both empty"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu=1.5), ValueError, "mu: element 0 is 1.5"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", ndotv=[0.5], roughness=[]), ValueError,
     "one roughness per NdotV"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", ndotv=0.5, roughness=0.5,
                           quad_light="1,2,3"), ValueError, "4 vertices"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu="x"), TypeError, "mu: real numbers"),
    (lambda: matc.evaluate(EXAMPLES / "gold.json", mu=0.5, lut_precision="f8"), ValueError,
     "lut_precision: 'f8' is not one of"),
    (lambda: matc.describe_basis("schlick"), ValueError, "basis: 'schlick' is not one of"),
    (lambda: matc.output_file_names(["no/slash"]), ValueError, "'no/slash'"),
    (lambda: matc.output_file_names(["gold"], emit=["msl"]), ValueError, "emit: 'msl'"),
])
def test_bad_arguments_raise_naming_them(call, error, message):
    with pytest.raises(error, match=message):
        call()


@pytest.mark.parametrize("basis", ["powers", "extended"])
def test_describe_basis_is_matc_basis(basis):
    cli = json.loads(run_matc("basis", "--json", "--basis", basis).stdout)
    ours = matc.describe_basis(basis)
    assert ours["mu"] == cli["mu"] and ours["probes"] == cli["probes"]
    assert [[row[i] for row in ours["b"]] for i in range(4)] == cli["b"]
    assert ours["closed_form"] == (basis == "powers")


def test_output_file_names_are_matc_layout():
    cli = run_matc("layout", "--emit", "glsl,json,lut", "--lut", "dds", "gold", "copper").stdout
    ours = matc.output_file_names(["gold", "copper"], emit=["glsl", "json", "lut"],
                                  lut_format="dds")
    assert ours == cli.splitlines()
    assert matc.output_file_names(["gold"], no_shared=True) == run_matc(
        "layout", "--no-shared", "gold").stdout.splitlines()
