"""Every way in is checked: the bad-input catalogue through Python gives the CLI's located
messages and writes nothing; bad types and out-of-range arguments raise TypeError or ValueError
with the argument named, never a crash."""

import math
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import matc
from conftest import BAD_INPUTS, EXAMPLE_FILES, MATERIALX

GOLD = EXAMPLE_FILES[[p.stem for p in EXAMPLE_FILES].index("gold")]


def _default_cases():
    # The cases the CLI runs as `matc -q -o out <case>.json` (no .args of their own).
    return sorted(p.stem for p in BAD_INPUTS.glob("*.expected")
                  if not (BAD_INPUTS / f"{p.stem}.args").exists())


@pytest.mark.parametrize("case", _default_cases())
def test_catalogue_case_through_python(case, tmp_path, monkeypatch):
    shutil.copytree(BAD_INPUTS, tmp_path, dirs_exist_ok=True)
    monkeypatch.chdir(tmp_path)
    if (tmp_path / f"{case}.setup").exists():
        subprocess.run(["bash", "-e", f"{case}.setup"], check=True)
    # Messages quote input bytes that need not be UTF-8: compared as surrogate escapes.
    lines = (BAD_INPUTS / f"{case}.expected").read_text(errors="surrogateescape").splitlines()
    status, expected = lines[0], lines[1:]
    if status == "exit 0":
        result = matc.compile_batch([f"{case}.json"], "out")
        text = "\n".join(str(d) for d in result.diagnostics)
    else:
        with pytest.raises(matc.MaterialError) as raised:
            matc.compile_batch([f"{case}.json"], "out")
        text = str(raised.value)
        assert raised.value.errors, "an error without an error diagnostic"
        assert isinstance(raised.value, matc.BatchError) and raised.value.result.failed >= 0
        out = pathlib.Path("out")
        assert not out.is_dir() or not any(out.iterdir())
    for line in expected:
        assert line in text


def test_diagnostics_are_located_values():
    with pytest.raises(matc.MaterialError) as raised:
        matc.parse('{"name": "x",\n "ior": {"n": [1, 2], "k": 1}}', path="memory/x.json")
    (error,) = raised.value.diagnostics
    assert (error.path, error.line, error.column, error.severity) == ("memory/x.json", 2, 15,
                                                                       "error")
    assert error.field == "ior.n" and "3" in error.allowed
    assert str(error) == str(raised.value)
    assert isinstance(raised.value, ValueError)


def test_parse_and_load_errors():
    with pytest.raises(matc.MaterialError, match="cannot read"):
        matc.load("no/such/file.json")
    with pytest.raises(matc.MaterialError, match="syntax error"):
        matc.parse("{")
    with pytest.raises(matc.MaterialError, match="XML|xml"):
        matc.parse_materialx("<materialx")
    with pytest.raises(ValueError, match=r"holds \d+ materials"):
        matc.compile(MATERIALX / "metals.mtlx")
    with pytest.raises(ValueError, match=r"ior.n\[1\]: is nan"):
        matc.parse({"name": "x", "ior": {"n": [1.0, math.nan, 1.0], "k": 1}})
    with pytest.raises(ValueError, match=r"ior.k\[0\]: is inf"):
        matc.parse({"name": "x", "ior": {"n": 1, "k": np.array([np.inf, 1, 1])}})


@pytest.mark.parametrize("call", [
    lambda: matc.compile(42),
    lambda: matc.parse([1, 2, 3]),
    lambda: matc.parse({"name": "x", "ior": {"n": object(), "k": 1}}),
    lambda: matc.parse_materialx(7),
    lambda: matc.compile_batch("gold.json"),
    lambda: matc.compile_batch([3.5]),
    lambda: matc.compile(GOLD).fresnel("abc"),
    lambda: matc.compile(GOLD).fbar({}, 0.5),
    lambda: matc.Build(lut_size=-1),
    lambda: matc.Build(emit="glsl"),
])
def test_bad_types_raise_type_error(call):
    with pytest.raises(TypeError):
        call()


@pytest.mark.parametrize("call, message", [
    (lambda: matc.Build(lut_size=1), r"lut_size: 1 is out of range; an integer in \[2, 4096\]"),
    (lambda: matc.Build(lut_samples=0), "lut_samples: 0 is out of range"),
    (lambda: matc.Build(embed_lut=65), "embed_lut: 65 is out of range"),
    (lambda: matc.Build(basis="nope"), "basis: 'nope' is not one of auto, powers"),
    (lambda: matc.Build(emit=["glsl", "msl"]), "emit: 'msl' is not one of"),
    (lambda: matc.Build(emit=[]), "emit: an empty list"),
    (lambda: matc.Build(lut_format="png"), "lut_format: 'png' is not one of ktx2"),
    (lambda: matc.Build(color_space="cmyk"), "color_space: 'cmyk' is not one of"),
    (lambda: matc.Build(gamut_mapping="clip"), "gamut_mapping: 'clip' is not one of none"),
    (lambda: matc.compile(GOLD, basis="x"), "basis: 'x'"),
    (lambda: matc.compile(GOLD).fresnel([0.5, 1.5]), r"mu: element 1 is 1.5; a number in \[0, 1\]"),
    (lambda: matc.compile(GOLD).exact(np.nan), "mu: element 0 is nan"),
    (lambda: matc.compile(GOLD).fbar(0.5, -0.1), "roughness: element 0 is -0.1"),
    (lambda: matc.compile(GOLD).fbar(np.nan, 0.5), "ndotv: element 0 is nan"),
    (lambda: matc.compile(GOLD).fbar_reference(0.5, 0.5, samples=1), "samples: 1 is out of range"),
    (lambda: matc.Build().shader(matc.compile(GOLD), "msl"), "language: 'msl' is not one of"),
    (lambda: matc.preintegrated_table(size=1), "out of range"),
    (lambda: matc.preintegrated_table(precision="f64"), "precision: 'f64' is not one of"),
    (lambda: matc.coefficient_table().coefficients([2, 0, 0], [0, 0, 0]),
     r"reflectivity: element 0 is 2; a number in \[0, 1\]"),
    (lambda: matc.compile_batch([GOLD], shared_only=True), "shared"),
    (lambda: matc.compile_batch([GOLD], None, depfile="x.d"), "depfile"),
])
def test_bad_values_raise_value_error(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_batch_error_keeps_the_result(tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text('{"name": "broken", "ior": {"n": -1, "k": 1}}')
    with pytest.raises(matc.BatchError) as raised:
        matc.compile_batch([GOLD, broken], tmp_path / "out", keep_going=True)
    assert raised.value.result.failed == 1 and raised.value.result.done == 1
    assert "broken.json:1:33: error: ior.n: -1 is out of range" in str(raised.value)
    assert (tmp_path / "out" / "gold.glsl").exists()
