"""A folder of materials to a shader bundle, as an asset pipeline script would do it:
    python3 examples/python/pipeline.py MATERIALS_DIR OUTPUT_DIR
writes what `matc -o OUTPUT_DIR MATERIALS_DIR/*` writes (through the library's batch, one call),
then OUTPUT_DIR/bundle.json: each material's coefficients, F0 and accuracy beside Schlick's."""

import json
import pathlib
import sys

import matc


def main(materials_dir, output_dir):
    sources = sorted(p for p in pathlib.Path(materials_dir).iterdir()
                     if p.suffix in (".json", ".mtlx"))

    def progress(done, total, name):
        print(f"\r[{done}/{total}] {name:<32}", end="", file=sys.stderr, flush=True)

    build = matc.Build()
    try:
        result = build.compile_batch(sources, output_dir, progress=progress)
    except matc.MaterialError as error:
        print(f"\n{error}", file=sys.stderr)
        return 1
    print(file=sys.stderr)
    for diagnostic in result.diagnostics:
        if diagnostic.severity == "warning":
            print(diagnostic, file=sys.stderr)

    index = {}
    for source in sources:
        for material in matc.load(source):
            compiled = build.compile(material)
            accuracy = compiled.accuracy
            index[compiled.name] = {
                "source": source.name,
                "coefficients": compiled.coefficients.round(6).tolist(),
                "f0": compiled.f0.round(6).tolist(),
                "max_error": float(accuracy["max_error"].max()),
                "schlick_max_error": float(accuracy["schlick_max_error"].max()),
            }
    bundle = pathlib.Path(output_dir) / "bundle.json"
    bundle.write_text(json.dumps(dict(sorted(index.items())), indent=2) + "\n")
    print(f"{result.done} materials, {result.written} files written, {result.unchanged} unchanged; "
          f"index in {bundle}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
