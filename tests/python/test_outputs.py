"""What the module writes is what `matc` writes: shader sources, per-material files, shared
files, the tables' texels, and a batch's directory, manifest and depfile, byte for byte."""

import json
import os
import threading

import numpy as np
import pytest

import matc
from conftest import EXAMPLE_FILES, MATERIALX, directory_bytes, run_matc

GOLD = EXAMPLE_FILES[[p.stem for p in EXAMPLE_FILES].index("gold")]


def test_shader_sources_and_files_equal_the_cli(tmp_path):
    run_matc("-q", "-o", tmp_path, GOLD)
    build = matc.Build()
    gold = build.compile(GOLD)
    for language in ("glsl", "hlsl", "wgsl"):
        assert build.shader(gold, language) == (tmp_path / f"gold.{language}").read_text()
        assert build.library(language) == (tmp_path / f"matc_fresnel.{language}").read_text()
    for name, data in build.files(gold).items():
        assert data == (tmp_path / name).read_bytes(), name
    for name, data in build.shared_files().items():
        assert data == (tmp_path / name).read_bytes(), name
    assert matc.shader_sources(GOLD, "glsl") == {"glsl": (tmp_path / "gold.glsl").read_text()}


def test_tables_hold_the_texels_of_the_written_files(tmp_path):
    run_matc("-q", "--lut", "raw", "--emit", "lut,coefficient-table", "-o", tmp_path, GOLD)
    lut = matc.preintegrated_table()
    assert lut.texels.shape == (128, 128, 4) and lut.texels.dtype == np.float32
    # The default build's table: a layer per basis side by side, powers' then f82's.
    written = np.fromfile(tmp_path / "matc_lut.bin", dtype="<f4").reshape(128, 256, 4)
    np.testing.assert_array_equal(lut.texels, written[:, :128])
    np.testing.assert_array_equal(matc.preintegrated_table(basis="f82").texels, written[:, 128:])
    build = matc.Build()
    np.testing.assert_array_equal(build.lut.texels, written[:, :128])
    assert build.lut_layer("f82").basis == "f82"
    np.testing.assert_array_equal(build.lut_layer("f82").texels, written[:, 128:])
    with pytest.raises(ValueError, match="no layer of the extended basis"):
        build.lut_layer("extended")
    # Hostile names: refused with the name escaped and the names the option takes.
    for name, shown in (("x\x1b[31m", r"'x\\x1B\[31m'"), ("auto", "'auto'")):
        with pytest.raises(ValueError, match=rf"basis: {shown} is not one of powers, extended"):
            build.lut_layer(name)
    run_matc("-q", "--lut", "raw", "--emit", "lut", "--basis", "powers", "-o", tmp_path / "one", GOLD)
    one = np.fromfile(tmp_path / "one" / "matc_lut.bin", dtype="<f4").reshape(128, 128, 4)
    np.testing.assert_array_equal(matc.Build(basis="powers").lut.texels, one)
    table = matc.coefficient_table()
    stored = np.fromfile(tmp_path / "matc_coefficient_table.bin", dtype="<f2").astype(np.float32)
    np.testing.assert_array_equal(table.texels, stored.reshape(table.size, table.size, 2))
    assert "NdotV" in matc.PreintegratedTable.layout and "sqrt(1 - g)" in table.layout
    with pytest.raises(ValueError, match="read-only"):
        lut.texels[0, 0, 0] = 1.0


def test_table_sampling_is_what_fbar_reads():
    gold = matc.compile(GOLD)
    lut = matc.preintegrated_table()
    ndotv, roughness = np.linspace(0, 1, 7), np.linspace(1, 0, 7)
    bbar = lut.sample(ndotv, roughness)
    assert bbar.shape == (7, 4)
    manual = np.maximum(0.0, bbar @ gold.coefficients.T)
    np.testing.assert_allclose(gold.fbar(ndotv, roughness, table=lut), manual, rtol=0,
                               atol=1e-15)
    small = matc.preintegrated_table(size=16, samples=64)
    assert small.size == 16 and small is not lut
    with pytest.raises(ValueError, match="basis"):
        gold.fbar(0.5, 0.5, table=matc.preintegrated_table(basis="paper", size=8, samples=16))


def test_coefficient_table_path_matches_matc_eval():
    table = matc.coefficient_table()
    r, g = [0.95, 0.64, 0.27], [1.0, 0.98, 0.62]
    printed = run_matc("eval", "--reflectivity", "0.95,0.64,0.27", "--edge-tint", "1,0.98,0.62",
                       "--mu", "0.5").stdout
    coefficients = table.coefficients(r, g)
    assert coefficients.shape == (3, 4)
    np.testing.assert_array_equal(matc.fresnel_from_coefficients(coefficients, [0.5]),
                                  np.array(json.loads(printed)["F_table"]))
    with pytest.raises(ValueError, match="shape"):
        matc.fresnel_from_coefficients(np.zeros((3, 3)), 0.5)


def _batch_inputs():
    return [*EXAMPLE_FILES, MATERIALX / "metals.mtlx"]


def test_batch_writes_the_bytes_matc_writes(tmp_path):
    cli, module = tmp_path / "cli", tmp_path / "module"
    inputs = _batch_inputs()
    run_matc("-q", "--depfile", cli / "out.d", "-o", cli, *inputs)
    progress = []
    result = matc.compile_batch(inputs, module, depfile=module / "out.d",
                                progress=lambda done, total, name: progress.append(
                                    (done, total, name)))
    cli_files, module_files = directory_bytes(cli), directory_bytes(module)
    cli_depfile = cli_files.pop("out.d").decode()
    module_depfile = module_files.pop("out.d").decode()
    assert cli_files == module_files
    # The depfile names the same inputs; its last dependency is the program: matc or _matc.
    assert cli_depfile.replace(str(cli), "D").replace(os.environ["MATC_BINARY"], "TOOL") == \
        module_depfile.replace(str(module), "D").replace(matc._matc.__file__, "TOOL")
    assert result.done == len(progress) == progress[-1][1]
    assert result.failed == 0 and result.written == len(module_files)
    again = matc.compile_batch(inputs, module, depfile=module / "out.d")
    assert again.written == 0 and again.unchanged == result.written


def test_batch_in_memory_holds_the_directory_bytes(tmp_path):
    inputs = _batch_inputs()
    run_matc("-q", "-o", tmp_path, *inputs)
    result = matc.compile_batch(inputs)
    assert result.files == directory_bytes(tmp_path)


def test_batch_sources_in_memory_dicts_and_materials(tmp_path):
    gold_text = GOLD.read_text()
    brass = {"name": "brass", "ior": {"n": [0.44, 0.53, 1.10], "k": [3.70, 2.90, 2.10]}}
    silver = matc.parse('{"name": "silver_memory", "spectral": {"preset": "Ag"}}',
                        path="memory/silver_memory.json")
    result = matc.compile_batch([(str(GOLD), gold_text), brass, silver], emit=["json"])
    assert sorted(result.files) == ["brass.json", "gold.json", "matc_manifest.json",
                                    "silver_memory.json"]
    run_matc("-q", "--emit", "json", "-o", tmp_path, GOLD)
    assert result.files["gold.json"] == (tmp_path / "gold.json").read_bytes()


def test_progress_exception_cancels_and_propagates(tmp_path):
    class Stop(Exception):
        pass

    def stop(done, total, name):
        raise Stop(name)

    with pytest.raises(Stop):
        matc.compile_batch(_batch_inputs(), tmp_path, jobs=1, progress=stop)
    # Nothing shared was written by a cancelled batch.
    assert not (tmp_path / "matc_manifest.json").exists()
    with pytest.raises(TypeError, match="callable"):
        matc.compile_batch([GOLD], progress=42)


def test_build_options_and_description():
    build = matc.Build(lut_size=32, lut_samples=64, lut_format="dds", embed_lut=8,
                       emit=["glsl", "lut"], basis="extended", color_space="acescg")
    options = build.options
    assert options["lut_size"] == 32 and options["lut_format"] == "dds"
    assert options["emit"] == ["glsl", "lut"] and options["basis"] == "extended"
    description = build.description()
    assert description["basis"] == "extended" and description["lut"]["size"] == 32
    assert build.lut.size == 32 and build.lut.basis == "extended"
    gold = build.compile(GOLD)
    assert gold.basis == "extended" and gold.color_space == "acescg"
    with pytest.raises(ValueError, match="compile it with the outputs' options"):
        matc.Build().shader(gold, "glsl")


def test_batch_releases_the_gil(tmp_path):
    # A Python thread keeps counting while the batch compiles on the others.
    ticks = []
    running = threading.Event()

    def count():
        while not running.is_set():
            ticks.append(1)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        matc.compile_batch(EXAMPLE_FILES, tmp_path, jobs=1)
    finally:
        running.set()
        counter.join()
    assert len(ticks) > 1000
