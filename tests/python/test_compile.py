"""The module's numbers are the C++ runtime's: coefficients, F, the exact curve and Fbar equal
what `matc eval` (the same library, through the CLI) and `matc`'s <name>.json print, bit for
bit."""

import json

import numpy as np
import pytest

import matc
from conftest import EXAMPLE_FILES, MATERIALX, matc_eval, run_matc

COSINES = [0.0, 0.001, 0.05, 1.0 / 7.0, 0.25, 0.5, 0.745, 0.9, 0.999, 1.0]
NDOTV = [0.0, 0.02, 0.3, 0.5, 0.77, 1.0]
ROUGHNESS = [0.0, 0.1, 0.25, 0.5, 0.8, 1.0]


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.stem)
def test_f_and_fbar_equal_matc_eval_bit_for_bit(path):
    compiled = matc.compile(path)
    printed = matc_eval(path, "--mu", ",".join(map(repr, COSINES)), "--ndotv",
                        ",".join(map(repr, NDOTV)), "--roughness", ",".join(map(repr, ROUGHNESS)),
                        "--no-reference")
    assert compiled.name == printed["name"]
    assert compiled.basis == printed["basis"]
    assert compiled.color_space == printed["color_space"]
    np.testing.assert_array_equal(compiled.fresnel(COSINES), np.array(printed["F"]))
    np.testing.assert_array_equal(compiled.exact(COSINES), np.array(printed["F_exact"]))
    np.testing.assert_array_equal(compiled.fbar(NDOTV, ROUGHNESS), np.array(printed["Fbar"]))


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.stem)
def test_coefficients_equal_the_compiled_json(path, tmp_path):
    run_matc("-q", "--emit", "json", "-o", tmp_path, path)
    compiled = matc.compile(path)
    written = json.loads((tmp_path / f"{compiled.name}.json").read_text())
    summary = compiled.to_dict()
    written.pop("inputs_hash")
    assert summary == written
    np.testing.assert_array_equal(compiled.coefficients, np.array(written["coefficients"]))


def test_other_bases_and_colour_spaces_match_matc_eval():
    path = EXAMPLE_FILES[0]
    for basis in ("paper", "f82"):
        compiled = matc.compile(path, basis=basis, color_space="acescg")
        printed = matc_eval(path, "--mu", "0.1,0.6", "--basis", basis, "--color-space",
                            "acescg")
        assert compiled.basis == basis
        np.testing.assert_array_equal(compiled.fresnel([0.1, 0.6]), np.array(printed["F"]))
        np.testing.assert_array_equal(compiled.exact([0.1, 0.6]), np.array(printed["F_exact"]))


def test_a_basis_per_material_matches_matc_eval_and_the_build():
    # --basis auto: the F82-tint example takes f82 (its curve exactly), a measured metal powers.
    tinted = next(p for p in EXAMPLE_FILES if p.stem == "aluminium_brushed_openpbr")
    for path, basis in ((tinted, "f82"), (EXAMPLE_FILES[0], "powers")):
        compiled = matc.compile(path, basis="auto")
        printed = matc_eval(path, "--mu", "0.1,0.6", "--basis", "auto", "--no-reference")
        assert compiled.basis == printed["basis"] == basis
        np.testing.assert_array_equal(compiled.fresnel([0.1, 0.6]), np.array(printed["F"]))
        build = matc.Build(basis="auto")
        assert build.compile(path).basis == basis
        assert json.loads(build.files(compiled)[f"{compiled.name}.json"])["basis"][
            "lut_layer"] == (1 if basis == "f82" else 0)
    assert max(matc.compile(tinted, basis="auto").accuracy["max_error"]) < 1e-12


def test_materialx_document_materials_compile_like_matc_eval():
    document = MATERIALX / "metals.mtlx"
    materials = matc.load(document)
    assert len(materials) > 1
    for material in materials:
        compiled = matc.compile(material)
        printed = matc_eval(document, "--material", material.name, "--mu", "0.2,0.8")
        np.testing.assert_array_equal(compiled.fresnel([0.2, 0.8]), np.array(printed["F"]))


def test_shapes_follow_the_inputs():
    gold = matc.compile(EXAMPLE_FILES[0])
    assert gold.coefficients.shape == (3, 4)
    assert gold.fresnel(0.5).shape == (3,)
    assert gold.fresnel(np.linspace(0, 1, 12).reshape(3, 4)).shape == (3, 4, 3)
    assert gold.fbar(0.5, [0.1, 0.2, 0.3]).shape == (3, 3)
    assert gold.fbar(np.full((2, 1), 0.5), np.array([0.1, 0.2, 0.3])).shape == (2, 3, 3)
    # F(90 degrees) = 1: c_0 + c_1 = 1 per channel.
    np.testing.assert_allclose(gold.coefficients[:, 0] + gold.coefficients[:, 1], 1.0, atol=1e-15)


def test_schlick_is_schlicks_formula_with_the_exact_f0():
    gold = matc.compile(EXAMPLE_FILES[0])
    mu = np.linspace(0, 1, 101)
    expected = gold.f0 + (1 - gold.f0) * (1 - mu[:, None]) ** 5
    np.testing.assert_allclose(gold.schlick(mu), expected, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(gold.exact(1.0), gold.f0)


def test_fbar_reference_is_the_split_sum_of_matc_eval():
    path = EXAMPLE_FILES[0]
    compiled = matc.compile(path)
    printed = matc_eval(path, "--ndotv", "0.3,0.9", "--roughness", "0.2,0.6")
    np.testing.assert_array_equal(compiled.fbar_reference([0.3, 0.9], [0.2, 0.6]),
                                  np.array(printed["Fbar_reference"]))


def test_accuracy_and_inputs_are_reported():
    compiled = matc.compile({"name": "brass", "ior": {"n": [0.44, 0.53, 1.10],
                                                      "k": [3.70, 2.90, 2.10]}})
    assert compiled.ior.shape == (3, 2)
    np.testing.assert_array_equal(compiled.ior[:, 0], [0.44, 0.53, 1.10])
    assert set(compiled.artistic) == {"reflectivity", "edge_tint"}
    accuracy = compiled.accuracy
    assert accuracy["max_error"].shape == (3,)
    assert np.all(accuracy["max_error"] < accuracy["schlick_max_error"])
    assert compiled.material.model == "ior"
    assert compiled.material.inputs["k"] == [3.70, 2.90, 2.10]


def test_a_film_changes_the_exact_curve_and_none_is_the_bare_metal():
    bare = matc.compile({"name": "ti", "spectral": {"preset": "Ti"}})
    none = matc.compile({"name": "ti", "spectral": {"preset": "Ti"}, "film": {"thickness": 0}})
    filmed = matc.compile({"name": "ti", "spectral": {"preset": "Ti"},
                           "film": {"ior": 2.4, "thickness": 45}})
    np.testing.assert_array_equal(none.exact(COSINES), bare.exact(COSINES))
    np.testing.assert_array_equal(none.coefficients, bare.coefficients)
    # 45 nm of titania turns grey titanium blue at normal incidence.
    f0 = filmed.exact([1.0])[0]
    assert f0[2] > 2 * f0[0] and f0[2] > 2 * f0[1]
    assert filmed.ior is None


def test_a_thick_film_is_evaluated_through_its_own_table():
    # 300 nm oscillates with the angle: the 4-term fit misses it, the film's table
    # (docs/thin-film.md) is what fresnel() and fbar() read.
    filmed = matc.compile({"name": "ti", "spectral": {"preset": "Ti"},
                           "film": {"ior": 2.3, "thickness": 300}})
    mu = np.linspace(0.05, 1.0, 96)
    assert np.max(np.abs(filmed.fresnel(mu) - filmed.exact(mu))) < 0.004
    assert np.max(filmed.accuracy["max_error"]) < 0.004
    fbar = filmed.fbar([0.5, 0.9], [0.3, 0.6])
    assert fbar.shape == (2, 3) and np.all((fbar > 0) & (fbar < 1))
    # The table itself, as <name>.film.<ext> holds it: row 0 is F at mu = (i / 64)^2.
    table = filmed.film_table
    assert table.shape == (18, 65, 4) and table.dtype == np.float32
    nodes = (np.arange(65) / 64.0) ** 2
    np.testing.assert_allclose(table[0, :, :3], filmed.fresnel(nodes), atol=1e-6)
    np.testing.assert_array_equal(table[:, :, 3], 1.0)
    assert matc.compile({"name": "ti", "spectral": {"preset": "Ti"}}).film_table is None
