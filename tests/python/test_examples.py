"""examples/python runs as documented: the pipeline script writes matc's files and an index of
every material, and the plot script draws the image docs/python.md shows, byte for byte."""

import json
import os
import subprocess
import sys

from conftest import EXAMPLES, SOURCE_DIR, directory_bytes, run_matc

SCRIPTS = SOURCE_DIR / "examples" / "python"


def _run(script, *args):
    return subprocess.run([sys.executable, str(SCRIPTS / script), *map(str, args)],
                          capture_output=True, text=True, check=True, env=os.environ)


def test_pipeline_script_writes_the_cli_files_and_an_index(tmp_path):
    _run("pipeline.py", EXAMPLES, tmp_path / "bundle")
    run_matc("-q", "-o", tmp_path / "cli", *sorted(EXAMPLES.glob("*.json")))
    written = directory_bytes(tmp_path / "bundle")
    index = json.loads(written.pop("bundle.json"))
    assert written == directory_bytes(tmp_path / "cli")
    assert sorted(index) == sorted(p.stem for p in EXAMPLES.glob("*.json"))
    assert all(entry["max_error"] < entry["schlick_max_error"] for entry in index.values())


def test_plot_script_draws_the_documented_image(tmp_path):
    out = tmp_path / "plot.png"
    printed = _run("plot_fresnel.py", EXAMPLES / "chromium.json", out).stdout
    assert "chromium" in printed
    assert out.read_bytes() == (SOURCE_DIR / "docs" / "images" / "python_fresnel.png").read_bytes(), \
        "docs/images/python_fresnel.png is stale: rerun examples/python/plot_fresnel.py"
