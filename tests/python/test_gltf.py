"""matc.compile_gltf is `matc gltf` (docs/gltf.md): the same bytes as the CLI writes, the metals
compiled as matc.compile compiles them, and the CLI's refusals as Python's exceptions."""

import json

import numpy as np
import pytest

import matc
from conftest import BAD_INPUTS, SOURCE_DIR, run_matc

TRIM = SOURCE_DIR / "examples" / "gltf" / "trim.gltf"
COSINES = [0.0, 0.1, 1.0 / 7.0, 0.5, 1.0]


def test_the_bytes_are_matc_gltfs(tmp_path):
    for options, arguments in (({}, []), ({"basis": "f82"}, ["--basis", "f82"]),
                               ({"basis": "auto"}, ["--basis", "auto"])):
        written = tmp_path / "trim_matc.gltf"
        run_matc("gltf", "-q", TRIM, "-o", written, *arguments)
        asset = matc.compile_gltf(TRIM, **options)
        assert isinstance(asset, matc.GltfAsset)
        assert asset.bytes == written.read_bytes()


def test_a_textured_schlick_metal_carries_its_coefficients_at_zero_f0(tmp_path):
    """Schlick's curve is linear in F0: the rows at F0 = 0 give the compile at the factor."""
    path = tmp_path / "textured.gltf"
    path.write_text(json.dumps({
        "asset": {"version": "2.0"}, "textures": [{"source": 0}], "images": [{"uri": "t.png"}],
        "materials": [{"name": "Trim", "pbrMetallicRoughness": {
            "baseColorFactor": [0.9, 0.8, 0.6, 1], "baseColorTexture": {"index": 0}}}]}))
    asset = matc.compile_gltf(path)
    extension = json.loads(asset.bytes)["materials"][0]["extensions"]["MATC_materials_fresnel"]
    zero = np.array(extension["zeroF0Coefficients"])
    assert zero[:, 0].tolist() == [0.0] * 3 and zero[:, 1].tolist() == [1.0] * 3
    compiled = asset.materials[0].coefficients
    f0 = compiled[:, :1]
    np.testing.assert_allclose(f0 * np.array([1.0, 0.0, 0.0, 0.0]) + (1.0 - f0) * zero, compiled,
                               rtol=0, atol=1e-12)


def test_the_metals_are_compiled_as_compile_compiles_them():
    asset = matc.compile_gltf(TRIM, basis="f82")
    assert [m.name for m in asset.materials] == ["Edge_Chrome", "LacqueredCopper"]
    document = json.loads(asset.bytes)
    extensions = [m["extensions"]["MATC_materials_fresnel"] for m in document["materials"][:2]]
    assert "MATC_materials_fresnel" not in document["materials"][2].get("extensions", {})
    loaded = matc.load(TRIM)
    for compiled, extension, material in zip(asset.materials, extensions, loaded):
        assert extension["name"] == compiled.name and extension["basis"] == "f82"
        assert extension["coefficients"] == compiled.coefficients.tolist()
        assert compiled.coefficients.tolist() == matc.compile(material, basis="f82").coefficients.tolist()
        np.testing.assert_array_equal(compiled.fresnel(COSINES),
                                      matc.compile(material, basis="f82").fresnel(COSINES))
        assert [str(d) for d in compiled.diagnostics] == [
            str(d) for d in matc.compile(material, basis="f82").diagnostics]
    assert asset.materials[1].coat is not None


def test_a_per_material_build_gives_each_metal_its_basis():
    # --basis auto: the edge-coloured chrome (F82-tint) takes f82, the lacquered copper powers, and
    # each extension names its own.
    asset = matc.compile_gltf(TRIM, basis="auto")
    document = json.loads(asset.bytes)
    bases = [m["extensions"]["MATC_materials_fresnel"]["basis"] for m in document["materials"][:2]]
    assert bases == [m.basis for m in asset.materials] == ["f82", "powers"]
    for compiled, material in zip(asset.materials, matc.load(TRIM)):
        assert compiled.coefficients.tolist() == matc.compile(material, basis="auto").coefficients.tolist()


def test_refusals_are_the_clis(tmp_path):
    with pytest.raises(matc.MaterialError) as refused:
        matc.compile_gltf(BAD_INPUTS / "gltf_out_duplicate_key.gltf")
    [diagnostic] = refused.value.errors
    assert (diagnostic.line, diagnostic.column, diagnostic.field) == (1, 63, "materials[0].name")
    assert "given twice" in diagnostic.message
    # An asset without a metal is no refusal: its bytes back, no material.
    plain = matc.compile_gltf(BAD_INPUTS / "gltf_no_metal.gltf")
    assert plain.materials == [] and plain.bytes == (BAD_INPUTS / "gltf_no_metal.gltf").read_bytes()
    with pytest.raises(matc.MaterialError, match="cannot read"):
        matc.compile_gltf(tmp_path / "missing.glb")
    with pytest.raises(ValueError, match="names no glTF asset"):
        matc.compile_gltf(SOURCE_DIR / "examples" / "materials" / "gold.json")
    with pytest.raises(ValueError, match="basis"):
        matc.compile_gltf(TRIM, basis="nope")
    with pytest.raises(ValueError, match="NUL"):
        matc.compile_gltf("a\0.gltf")
    with pytest.raises(TypeError, match="asset"):
        matc.compile_gltf(42)
