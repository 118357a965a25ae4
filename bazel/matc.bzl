"""Bazel rules for matc: one hermetic action per material, one for the shared files.

    load("//bazel:matc.bzl", "matc_material", "matc_shared")

    matc_shared(name = "matc_shared", matc = "//tools:matc")
    matc_material(name = "gold", src = "materials/gold.json", matc = "//tools:matc")
    matc_material(
        name = "gold_measured_file",
        src = "materials/gold_measured_file.json",
        data = ["materials/spectra/gold_pbrt_v4.csv"],  # files the material names
        matc = "//tools:matc",
    )

Each action runs `matc --no-shared` (or `--shared-only`) with its inputs declared: the material,
the spectral files it names (`data`) and the matc binary, so a remote cache keys on exactly what
the outputs depend on. The outputs are the bytes a batch writes (docs/scaling.md). A material's
outputs are named after its JSON "name", which Bazel cannot read at analysis time: the rule's
name must equal it (or give `material_name`). For the same reason a filmed metal says so
(`film = True`): its own table, <name>.film.<ext>, is then declared (docs/thin-film.md).
"""

# The file names, generated from matc's output layout (`matc layout --generate bazel`).
load(":matc_layout.bzl", "FILM_TABLE_INFIX", "MATERIAL_EXTENSIONS", "OUTPUT_KINDS", "SHARED_FILES", "TABLE_EXTENSIONS", "TABLE_STEMS")

_COMMON_ATTRS = {
    "matc": attr.label(
        mandatory = True,
        executable = True,
        cfg = "exec",
        allow_single_file = True,
        doc = "The matc binary.",
    ),
    "emit": attr.string_list(default = OUTPUT_KINDS, doc = "Output kinds (matc --emit)."),
    "out_dir": attr.string(default = "matc", doc = "Directory of the outputs, in the package."),
    "options": attr.string_list(doc = "Other matc options (e.g. --lut-size 64)."),
}

def _run_matc(ctx, outputs, inputs, arguments, mnemonic, message):
    ctx.actions.run(
        executable = ctx.executable.matc,
        arguments = ["-q", "--emit", ",".join(ctx.attr.emit)] + ctx.attr.options + arguments,
        inputs = inputs,
        outputs = outputs,
        mnemonic = mnemonic,
        progress_message = message,
    )

def _matc_material_impl(ctx):
    name = ctx.attr.material_name or ctx.label.name
    outputs = []
    for kind in OUTPUT_KINDS:
        if kind in ctx.attr.emit and kind in MATERIAL_EXTENSIONS:
            file = "%s/%s%s" % (ctx.attr.out_dir, name, MATERIAL_EXTENSIONS[kind])
            outputs.append(ctx.actions.declare_file(file))
    if not outputs:
        fail("matc_material: emit names no per-material output (glsl, hlsl, wgsl, spirv, header, json)")
    # A filmed metal's own table (docs/thin-film.md), written with the tables.
    if ctx.attr.film and "lut" in ctx.attr.emit:
        table = "%s/%s%s%s" % (ctx.attr.out_dir, name, FILM_TABLE_INFIX, TABLE_EXTENSIONS[ctx.attr.lut_format])
        outputs.append(ctx.actions.declare_file(table))
    _run_matc(
        ctx,
        outputs,
        [ctx.file.src] + ctx.files.data,
        ["--no-shared", "--lut", ctx.attr.lut_format, "-o", outputs[0].dirname, ctx.file.src.path],
        "Matc",
        "matc: %s" % name,
    )
    return [DefaultInfo(files = depset(outputs))]

matc_material = rule(
    implementation = _matc_material_impl,
    attrs = dict(_COMMON_ATTRS, **{
        "src": attr.label(mandatory = True, allow_single_file = [".json"], doc = "The material file."),
        "data": attr.label_list(allow_files = True, doc = "Files the material names (spectral CSVs)."),
        "material_name": attr.string(doc = "The material's JSON \"name\" (default: the rule's name)."),
        "film": attr.bool(
            default = False,
            doc = "The material has a film (a \"film\" block of thickness and coverage above 0 and an index " +
                  "other than 1): with " +
                  "lut among emit, its own table <name>.film.<ext> is an output too. Bazel cannot read the " +
                  "material at analysis time; without it the table is written and left out.",
        ),
        "lut_format": attr.string(
            default = "ktx2",
            values = TABLE_EXTENSIONS.keys(),
            doc = "The format of a filmed metal's table (matc --lut), as matc_shared's tables'.",
        ),
    }),
    doc = "One material's own files (matc --no-shared).",
)

def _matc_shared_impl(ctx):
    outputs = []
    table_extension = TABLE_EXTENSIONS[ctx.attr.lut_format]
    for kind in OUTPUT_KINDS:
        if kind not in ctx.attr.emit:
            continue
        if kind in SHARED_FILES:
            outputs.append(ctx.actions.declare_file("%s/%s" % (ctx.attr.out_dir, SHARED_FILES[kind])))
        if kind in TABLE_STEMS:
            table = "%s/%s%s" % (ctx.attr.out_dir, TABLE_STEMS[kind], table_extension)
            outputs.append(ctx.actions.declare_file(table))
            outputs.append(ctx.actions.declare_file(table + ".json"))
    if not outputs:
        fail("matc_shared: emit names no shared output (glsl, hlsl, wgsl, spirv, lut, coefficient-table, ltc)")
    _run_matc(
        ctx,
        outputs,
        [],
        ["--shared-only", "--lut", ctx.attr.lut_format, "-o", outputs[0].dirname],
        "MatcShared",
        "matc: shared files",
    )
    return [DefaultInfo(files = depset(outputs))]

matc_shared = rule(
    implementation = _matc_shared_impl,
    attrs = dict(_COMMON_ATTRS, **{
        "lut_format": attr.string(default = "ktx2", values = TABLE_EXTENSIONS.keys()),
    }),
    doc = "The shared files: matc_fresnel.*, the tables (matc --shared-only).",
)
