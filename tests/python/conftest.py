"""Shared fixtures of the Python module's tests: the matc binary the CLI comparisons run, and the
repository's examples. ctest sets PYTHONPATH to build/python and MATC_BINARY to build/matc."""

import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("MATC_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE_DIR / "examples" / "materials"
MATERIALX = SOURCE_DIR / "examples" / "materialx"
BAD_INPUTS = SOURCE_DIR / "tests" / "data" / "bad_inputs"
EXAMPLE_FILES = sorted(EXAMPLES.glob("*.json"))


def matc_binary():
    binary = os.environ.get("MATC_BINARY")
    if not binary:
        pytest.fail("MATC_BINARY is not set: run these tests through ctest")
    return binary


def run_matc(*args, cwd=None, check=True):
    """Runs the matc CLI; returns the completed process (text)."""
    process = subprocess.run([matc_binary(), *map(str, args)], cwd=cwd, capture_output=True,
                             text=True)
    if check and process.returncode != 0:
        raise AssertionError(f"matc {' '.join(map(str, args))} exited {process.returncode}:\n"
                             f"{process.stderr}")
    return process


def matc_eval(material_file, *args):
    """`matc eval`'s JSON for a material file."""
    return json.loads(run_matc("eval", material_file, *args).stdout)


def directory_bytes(directory):
    """Every file under `directory` by relative path, with its bytes."""
    root = pathlib.Path(directory)
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture(scope="session")
def example_files():
    return EXAMPLE_FILES
