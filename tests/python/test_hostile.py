"""The Python face under hostile and careless input (docs/reliability.md, the hostile-input
checklist): paths with NUL, bytes that are not UTF-8, complex, NaN and infinite numbers, arrays
too large to allocate, and property-based tests over shapes, dtypes and values. Every call either
returns finite values of the documented shape or raises TypeError, ValueError, MemoryError or
MaterialError naming what was wrong; none ends the interpreter."""

import os
import pathlib
import resource
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import matc

GOLD = {"name": "gold",
        "artistic": {"reflectivity": [0.95, 0.64, 0.27], "edge_tint": [1.0, 0.98, 0.62]}}
COPPER_LACQUERED = {"name": "copper_lacquered", "ior": {"n": [0.27, 0.68, 1.14],
                                                         "k": [3.6, 2.6, 2.4]},
                    "coat": {"ior": 1.5, "roughness": 0.1}}


@pytest.fixture(scope="module")
def gold():
    return matc.compile(GOLD)


# --- paths and text ------------------------------------------------------------------------------

@pytest.mark.parametrize("call", [
    lambda p: matc.load(p / "gold\0.json"),
    lambda p: matc.compile(str(p / "gold.json\0x")),
    lambda p: matc.compile_batch([str(p / "a\0.json")], p / "out"),
    lambda p: matc.compile_batch([GOLD], str(p / "out\0side")),
    lambda p: matc.compile_batch([GOLD], p / "out", depfile=str(p / "d\0.d")),
    lambda p: matc.parse(GOLD, path="x\0.json"),
    lambda p: matc.parse_materialx("<materialx/>", path="x\0y"),
    lambda p: matc.load(os.fsencode(str(p / "gold.json")) + b"\0"),
    lambda p: matc.compile_gltf(str(p / "car\0.glb")),
])
def test_a_nul_in_a_path_is_refused_and_nothing_is_made(call, tmp_path):
    (tmp_path / "gold.json").write_text('{"name": "gold", "ior": {"n": 0.2, "k": 3}}')
    before = sorted(tmp_path.rglob("*"))
    with pytest.raises(ValueError, match="NUL character"):
        call(tmp_path)
    assert sorted(tmp_path.rglob("*")) == before  # no folder named by the cut path


@pytest.mark.parametrize("source", [
    b'{"name": "g\xff", "ior": {"n": 0.2, "k": 3}}',
    '{"name": "g\udcff", "ior": {"n": 0.2, "k": 3}}',   # a surrogate escape of that byte
    '{"name": "g\ud800", "ior": {"n": 0.2, "k": 3}}',   # a lone surrogate
])
def test_text_that_is_not_utf8_is_a_located_material_error(source):
    with pytest.raises(matc.MaterialError) as raised:
        matc.parse(source)
    error = raised.value.errors[0]
    assert error.line == 1 and error.column in (12, 13)  # at the bytes that are not UTF-8
    assert "UTF-8" in error.message


def test_materialx_bytes_that_are_not_utf8_are_a_located_material_error():
    with pytest.raises(matc.MaterialError) as raised:
        matc.parse_materialx(b'<?xml version="1.0"?>\n<materialx name="\xc3"/>')
    error = raised.value.errors[0]
    assert error.line == 2 and "not UTF-8" in error.message


def test_a_batch_text_that_is_not_utf8_fails_that_material(tmp_path):
    with pytest.raises(matc.BatchError) as raised:
        matc.compile_batch([("bad.json", b'{"name": "\xfe"}')], tmp_path / "out")
    assert raised.value.result.failed == 1
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_a_nul_in_a_material_text_is_a_located_error():
    with pytest.raises(matc.MaterialError) as raised:
        matc.parse('{"name": "gold", "ior": {"n": 0.2, "k": 3}}\0{"more": 1}')
    assert "NUL byte" in raised.value.errors[0].message
    assert raised.value.errors[0].column == 44


# --- numbers -------------------------------------------------------------------------------------

@pytest.mark.parametrize("call", [
    lambda m: m.fresnel(np.array([0.5 + 0.5j])),
    lambda m: m.exact([0.5 + 0j]),
    lambda m: m.fbar(0.5, np.array([0.3 + 0.1j])),
    lambda m: m.fbar_reference(np.complex64(0.5), 0.5),
    lambda m: matc.preintegrated_table(size=8).sample(0.5 + 1j, 0.5),
    lambda m: matc.fresnel_from_coefficients(m.coefficients.astype(complex), 0.5),
])
def test_complex_numbers_are_refused_not_truncated(gold, call):
    with pytest.raises(TypeError, match="complex numbers"):
        call(gold)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_coefficients_must_be_finite(gold, value):
    coefficients = gold.coefficients.copy()
    coefficients[1, 2] = value
    with pytest.raises(ValueError, match=r"coefficients: \[1, 2\] is"):
        matc.fresnel_from_coefficients(coefficients, [0.5])


@pytest.mark.parametrize("values", [["a", "b"], [None], [{}], [[0.1, 0.2], [0.3]]])
def test_values_that_are_not_numbers_name_the_argument(gold, values):
    with pytest.raises((TypeError, ValueError), match="^mu: "):
        gold.fresnel(values)


# Out of memory: run in a child under an address-space limit, so a crash is a failed test (its
# exit status), not a lost interpreter, and numpy's allocations fail instead of the machine's.
OUT_OF_MEMORY_CALLS = {
    "fbar": "m.fbar(big_column, big_row)",
    "fbar_coated": "c.fbar(big_column, big_row)",
    "fbar_reference": "m.fbar_reference(big_column, big_row, samples=16)",
    "sample": "matc.preintegrated_table(size=8).sample(big_column, big_row)",
    "fresnel_huge_view": "m.fresnel(np.broadcast_to(np.float32(0.5), (10**6, 10**5)))",
    "exact_huge_view": "m.exact(np.broadcast_to(0.5, (10**7, 10**5)))",
}


@pytest.mark.parametrize("name", sorted(OUT_OF_MEMORY_CALLS))
def test_out_of_memory_is_a_memory_error_naming_the_arguments(name):
    script = textwrap.dedent(f"""
        import resource, numpy as np, matc
        m = matc.compile({GOLD!r})
        c = matc.compile({COPPER_LACQUERED!r})
        big_column = np.linspace(0, 1, 200000)[:, None]
        big_row = np.linspace(0, 1, 200000)[None, :]
        limit = 3 << 30
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        try:
            {OUT_OF_MEMORY_CALLS[name]}
        except MemoryError as error:
            print("MemoryError:", error)
        """)
    process = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                             timeout=120)
    assert process.returncode == 0, process.stderr
    assert process.stdout.startswith("MemoryError: "), process.stdout + process.stderr
    argument = "ndotv and roughness" if "big_row" in OUT_OF_MEMORY_CALLS[name] else "mu"
    assert process.stdout.startswith(f"MemoryError: {argument}: "), process.stdout


def test_import_without_numpy_says_what_is_missing():
    script = "import sys; sys.modules['numpy'] = None\nimport matc"
    process = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                             env=dict(os.environ))
    assert process.returncode != 0
    assert "matc needs numpy" in process.stderr and "pip install numpy" in process.stderr


# --- properties ----------------------------------------------------------------------------------

SHAPES = hnp.array_shapes(min_dims=0, max_dims=3, min_side=0, max_side=5)
DTYPES = st.one_of(hnp.floating_dtypes(), hnp.integer_dtypes(), hnp.boolean_dtypes(),
                   hnp.complex_number_dtypes())
EVALUATIONS = ["fresnel", "exact", "schlick"]
ALLOWED = (TypeError, ValueError, MemoryError)
PROPERTY_SETTINGS = settings(max_examples=150, deadline=None, derandomize=True, database=None,
                             suppress_health_check=[HealthCheck.function_scoped_fixture])


@pytest.fixture
def address_space_limit():
    """At most 4 GiB of address space while the test runs: an allocation too large fails."""
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = 4 << 30
    resource.setrlimit(resource.RLIMIT_AS, (limit if hard == resource.RLIM_INFINITY
                                            else min(limit, hard), hard))
    yield
    resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def arrays_of_any_kind():
    return DTYPES.flatmap(lambda dtype: hnp.arrays(dtype, SHAPES))


@PROPERTY_SETTINGS
@given(values=arrays_of_any_kind(), evaluation=st.sampled_from(EVALUATIONS))
def test_evaluations_return_finite_rgb_or_raise(gold, address_space_limit, values, evaluation):
    try:
        result = getattr(gold, evaluation)(values)
    except ALLOWED as error:
        assert str(error).startswith("mu: "), error
        return
    assert values.dtype.kind in "biuf"
    assert result.shape == values.shape + (3,)
    assert np.all(np.isfinite(result))
    assert np.all((values >= 0) & (values <= 1))


@PROPERTY_SETTINGS
@given(ndotv=arrays_of_any_kind(), roughness=arrays_of_any_kind(), coated=st.booleans())
def test_fbar_broadcasts_or_raises(gold, address_space_limit, ndotv, roughness, coated):
    material = matc.compile(COPPER_LACQUERED) if coated else gold
    try:
        result = material.fbar(ndotv, roughness)
    except ALLOWED as error:
        assert str(error).split(":")[0] in ("ndotv", "roughness", "ndotv and roughness"), error
        return
    assert result.shape == np.broadcast_shapes(ndotv.shape, roughness.shape) + (3,)
    assert np.all(np.isfinite(result))


@PROPERTY_SETTINGS
@given(coefficients=hnp.arrays(np.float64, st.sampled_from([(3, 4), (4, 3), (3,), (3, 4, 1)]),
                               elements=st.floats(allow_nan=True, allow_infinity=True, width=64)),
       mu=hnp.arrays(np.float64, SHAPES, elements=st.floats(0, 1)))
def test_fresnel_from_coefficients_is_finite_or_raises(address_space_limit, coefficients, mu):
    try:
        result = matc.fresnel_from_coefficients(coefficients, mu)
    except ValueError as error:
        assert str(error).startswith("coefficients: "), error
        return
    assert coefficients.shape == (3, 4) and np.all(np.isfinite(coefficients))
    assert result.shape == mu.shape + (3,)
    # Finite coefficients can still overflow: what matters is no crash and no silent NaN input.
    assert not np.any(np.isnan(result)) or not np.all(np.abs(coefficients) < 1e300)


@settings(max_examples=100, deadline=None, derandomize=True, database=None)
@given(text=st.one_of(st.binary(max_size=200), st.text(max_size=200)))
def test_any_text_parses_or_raises_a_located_material_error(text):
    try:
        matc.parse(text)
    except matc.MaterialError as error:
        assert error.errors and all(d.line >= 0 for d in error.errors)
    except ValueError as error:  # a dict-like text with NaN: JSON has none
        assert "finite" in str(error)


# Any path (also one naming a glTF asset) to the calls that take one: a located MaterialError, or
# a ValueError for a NUL, an empty path, or (compile_gltf) a path that names no glTF asset.
@pytest.mark.parametrize("call, also_refused", [(matc.load, None),
                                                (matc.compile_gltf, "names no glTF asset")])
@settings(max_examples=100, deadline=None, derandomize=True, database=None)
@given(path=st.one_of(st.text(max_size=40), st.text(max_size=40).map(lambda text: text + ".gltf")))
def test_any_path_reads_or_raises(call, also_refused, path):
    try:
        call(path)
    except matc.MaterialError as error:
        assert error.errors
    except ValueError as error:
        assert ("NUL character" in str(error) and "\0" in path) or (
            "is empty" in str(error) and not path) or (
            also_refused is not None and also_refused in str(error))
