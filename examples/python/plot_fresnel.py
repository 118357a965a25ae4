"""A metal's Fresnel curve three ways, with matplotlib: exact, Schlick's (exact F0) and matc's
four-term decomposition, and each approximation's error against the exact curve.
    python3 examples/python/plot_fresnel.py [MATERIAL] [OUTPUT.png]
Defaults: examples/materials/chromium.json into docs/images/python_fresnel.png."""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import matc  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
CHANNELS = (("R", "#d62728"), ("G", "#2ca02c"), ("B", "#1f77b4"))


def main(material_path, output):
    metal = matc.compile(material_path)
    degrees = np.linspace(0.0, 90.0, 721)
    mu = np.cos(np.radians(degrees))
    exact, ours, schlick = metal.exact(mu), metal.fresnel(mu), metal.schlick(mu)

    figure, (curves, errors) = plt.subplots(1, 2, figsize=(10, 4), dpi=100)
    for c, (channel, colour) in enumerate(CHANNELS):
        curves.plot(degrees, exact[:, c], color=colour, linewidth=2.2, alpha=0.35,
                    label=f"{channel} exact")
        curves.plot(degrees, ours[:, c], color=colour, linewidth=1.0, label=f"{channel} matc")
        curves.plot(degrees, schlick[:, c], color=colour, linewidth=1.0, linestyle=":",
                    label=f"{channel} Schlick")
        errors.semilogy(degrees, np.abs(ours[:, c] - exact[:, c]) + 1e-7, color=colour,
                        linewidth=1.0)
        errors.semilogy(degrees, np.abs(schlick[:, c] - exact[:, c]) + 1e-7, color=colour,
                        linewidth=1.0, linestyle=":")
    curves.set(title=f"{metal.name}: F(theta)", xlabel="angle of incidence (degrees)",
               ylabel="reflectance", xlim=(0, 90), ylim=(0, 1.02))
    curves.legend(ncol=3, fontsize=7, loc="lower left")
    worst_ours = metal.accuracy["max_error"].max()
    worst_schlick = metal.accuracy["schlick_max_error"].max()
    errors.set(title=f"|F - exact|: matc {worst_ours:.4f}, Schlick {worst_schlick:.3f} (max)",
               xlabel="angle of incidence (degrees)", xlim=(0, 90), ylim=(1e-6, 1))
    errors.plot([], [], color="black", linewidth=1.0, label="matc")
    errors.plot([], [], color="black", linewidth=1.0, linestyle=":", label="Schlick")
    errors.legend(fontsize=8, loc="lower left")
    figure.tight_layout()
    # No date or version in the file: the same inputs give the same bytes.
    figure.savefig(output, metadata={"Software": None})
    print(f"{output}: {metal.name}, max error matc {worst_ours:.4f}, Schlick {worst_schlick:.3f}")


if __name__ == "__main__":
    material = sys.argv[1] if len(sys.argv) > 1 else ROOT / "examples/materials/chromium.json"
    out = sys.argv[2] if len(sys.argv) > 2 else ROOT / "docs/images/python_fresnel.png"
    main(material, out)
