"""The Python module's speed (docs/performance.md, "From Python"): F on a million cosines against
the C++ runtime (bench/fresnel_eval_benchmark.cpp, timed by bench/python-bench.sh) and against the
exact conductor Fresnel written in plain numpy; one batch call over generated materials against
the `matc` process. Prints the Markdown block.
    python3 bench/python_bench.py MATC_BINARY MATERIALS_DIR CPP_EACH_MS CPP_SPAN_MS"""

import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

import matc

COSINES = 1_000_000
REPEATS = 21


def fastest(function, repeats=REPEATS):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def numpy_conductor_fresnel(mu, n, k):
    """The exact unpolarised conductor Fresnel reflectance, vectorised in numpy (complex IOR
    n + ik per channel): the plain-numpy way to get the curve matc fits."""
    eta2 = (n + 1j * k) ** 2
    c = mu[:, None]
    t = np.sqrt(eta2 - (1.0 - c * c))
    r_s = (c - t) / (c + t)
    r_p = (eta2 * c - t) / (eta2 * c + t)
    return 0.5 * (np.abs(r_s) ** 2 + np.abs(r_p) ** 2)


def fresnel_rows(cpp_each_ms, cpp_span_ms):
    root = pathlib.Path(__file__).resolve().parents[1]
    gold = matc.compile(root / "examples" / "materials" / "gold_rgb_ior.json")
    mu = np.random.default_rng(1).random(COSINES)
    n, k = gold.ior[:, 0], gold.ior[:, 1]
    assert np.max(np.abs(numpy_conductor_fresnel(mu[:1000], n, k) - gold.exact(mu[:1000]))) < 1e-12
    ours = fastest(lambda: gold.fresnel(mu))
    plain_numpy = fastest(lambda: numpy_conductor_fresnel(mu, n, k), 7)
    cpus = os.sched_getaffinity(0)
    os.sched_setaffinity(0, {min(cpus)})  # the same call on one CPU
    ours_one_cpu = fastest(lambda: gold.fresnel(mu))
    os.sched_setaffinity(0, cpus)
    return [
        ("C++ runtime, `evaluate_fresnel` per cosine, 1 thread", cpp_each_ms / 1e3),
        ("C++ runtime, `evaluate_fresnel` over a span, 1 thread", cpp_span_ms / 1e3),
        (f"`CompiledMaterial.fresnel(mu)`, {len(cpus)} threads", ours),
        ("`CompiledMaterial.fresnel(mu)`, pinned to 1 CPU", ours_one_cpu),
        ("plain numpy, exact conductor Fresnel (complex arithmetic)", plain_numpy),
    ], ours, ours_one_cpu, plain_numpy


def batch_rows(matc_binary, materials):
    files = sorted(pathlib.Path(materials).glob("*.json"))
    work = pathlib.Path(tempfile.mkdtemp())
    build = matc.Build()

    def cli():
        shutil.rmtree(work / "cli", ignore_errors=True)
        subprocess.run([matc_binary, "-q", "-j", "2", "-o", work / "cli", *files], check=True,
                       stderr=subprocess.DEVNULL)

    def module():
        shutil.rmtree(work / "py", ignore_errors=True)
        build.compile_batch(files, work / "py", jobs=2)

    try:
        cli_seconds, module_seconds = fastest(cli, 3), fastest(module, 3)
    finally:
        shutil.rmtree(work)
    return len(files), cli_seconds, module_seconds


def main():
    matc_binary, materials, cpp_each_ms, cpp_span_ms = sys.argv[1:5]
    rows, ours, ours_one_cpu, plain_numpy = fresnel_rows(float(cpp_each_ms), float(cpp_span_ms))
    count, cli_seconds, module_seconds = batch_rows(matc_binary, materials)
    print(f"Measured on {os.cpu_count()} CPU(s), numpy {np.__version__}: F of `gold_rgb_ior` "
          f"(examples/materials) on {COSINES:,} random cosines, the fastest of {REPEATS} calls "
          "(7 for plain numpy):\n")
    print("| evaluation | time (ms) |")
    print("|---|---:|")
    for label, seconds in rows:
        print(f"| {label} | {seconds * 1e3:.2f} |")
    print(f"\nThe module pinned to one CPU takes {ours_one_cpu / (float(cpp_each_ms) / 1e3):.2f}x "
          "the C++ runtime's per-cosine loop; on every CPU it is "
          f"{plain_numpy / ours:.0f}x faster than plain numpy ({plain_numpy / ours_one_cpu:.0f}x "
          "on one).\n")
    print(f"A batch of {count} generated artistic materials with every output, `-j 2`, the "
          "fastest of three runs each:\n")
    print("| run | time (s) |")
    print("|---|---:|")
    print(f"| `matc -q -j 2 -o DIR` (the process) | {cli_seconds:.2f} |")
    print(f"| `Build().compile_batch(files, DIR, jobs=2)` (the call) | {module_seconds:.2f} |")
    print(f"\nThe Python call takes {module_seconds / cli_seconds:.2f}x the CLI's time.")


if __name__ == "__main__":
    main()
