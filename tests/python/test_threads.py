"""Calls from several Python threads at once are safe and give the single-threaded results:
compiles, evaluations, table bakes and batches (the GIL is released inside them)."""

import concurrent.futures

import numpy as np

import matc
from conftest import EXAMPLE_FILES, directory_bytes

MU = np.linspace(0, 1, 10001)


def _evaluate(path):
    compiled = matc.compile(path)
    return (compiled.coefficients, compiled.fresnel(MU), compiled.exact(MU[::100]),
            compiled.fbar(MU[::100], MU[::-100]))


def test_compile_and_evaluate_from_eight_threads():
    expected = {path: _evaluate(path) for path in EXAMPLE_FILES}
    work = [path for _ in range(4) for path in EXAMPLE_FILES]
    with concurrent.futures.ThreadPoolExecutor(max_workers=8) as pool:
        results = list(pool.map(_evaluate, work))
    for path, result in zip(work, results):
        for got, want in zip(result, expected[path]):
            np.testing.assert_array_equal(got, want)


def test_tables_baked_once_from_many_threads():
    with concurrent.futures.ThreadPoolExecutor(max_workers=8) as pool:
        tables = list(pool.map(lambda _: matc.preintegrated_table(size=24, samples=32), range(16)))
    assert all(table.texels is not None for table in tables)
    for table in tables[1:]:
        np.testing.assert_array_equal(table.texels, tables[0].texels)


def test_batches_from_several_threads(tmp_path):
    build = matc.Build(lut_size=16, lut_samples=16)
    outputs = [tmp_path / f"out{i}" for i in range(4)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        list(pool.map(lambda out: build.compile_batch(EXAMPLE_FILES, out, jobs=2), outputs))
    first = directory_bytes(outputs[0])
    assert first
    for out in outputs[1:]:
        assert directory_bytes(out) == first
