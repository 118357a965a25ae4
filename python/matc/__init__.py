"""matc from Python: accurate, preintegrable Fresnel for real-time renderers.

Materials are parsed and validated by libmatc (errors raise :class:`MaterialError` with the
located diagnostics ``matc`` prints), compiled to the four-term decomposition
``F(mu) = sum_i c_i b_i(mu)`` per RGB channel, evaluated over numpy arrays exactly as the CPU
runtime and the generated shaders compute it, and written as ``matc`` writes them::

    import matc
    gold = matc.compile({"name": "gold",
                         "artistic": {"reflectivity": [0.95, 0.64, 0.27],
                                      "edge_tint": [1.0, 0.98, 0.62]}})
    gold.coefficients           # (3, 4): rows R, G, B; columns c_0..c_3
    gold.fresnel([1.0, 0.5])    # (2, 3)
    matc.compile_batch(["materials/gold.json"], "out")   # what `matc -o out ...` writes

docs/python.md describes every function.
"""

import collections as _collections
import json as _json
import math as _math
import numbers as _numbers
import os as _os

try:
    import numpy as _numpy  # every array matc takes or returns is numpy's
except ImportError as _missing:
    raise ImportError(
        f"matc needs numpy, which this Python cannot import ({_missing}). On Debian: "
        "apt-get install python3-numpy; in a virtual environment: pip install numpy, or make "
        "the environment with --system-site-packages (docs/python.md, 'In a virtual "
        "environment')") from _missing

try:
    from . import _matc
except ImportError as _unloadable:
    import pathlib as _pathlib
    import sys as _sys
    _built = sorted(p.name for p in _pathlib.Path(__file__).parent.glob("_matc.*"))
    raise ImportError(
        f"matc's compiled module ({', '.join(_built) or 'none found'}) does not load in this "
        f"Python {_sys.version_info.major}.{_sys.version_info.minor} ({_sys.executable}): "
        f"{_unloadable}. Run the interpreter it was built for (Debian's /usr/bin/python3 by "
        f"default), or build it for this one: cmake -DPython3_EXECUTABLE={_sys.executable} "
        "(docs/python.md)") from _unloadable
from ._defaults import default_build as _default_build
from ._matc import (
    BatchResult,
    Build,
    CoefficientTable,
    CompiledMaterial,
    Diagnostic,
    Material,
    PreintegratedTable,
    __version__,
    coefficient_table,
    describe_basis,
    fresnel_from_coefficients,
    output_file_names,
    preintegrated_table,
)
from .errors import BatchError, MaterialError

__all__ = [
    "BatchError",
    "BatchResult",
    "Build",
    "CoefficientTable",
    "CompiledMaterial",
    "Diagnostic",
    "GltfAsset",
    "Material",
    "MaterialError",
    "PreintegratedTable",
    "coefficient_table",
    "compile",
    "compile_batch",
    "compile_gltf",
    "describe_basis",
    "evaluate",
    "fresnel_from_coefficients",
    "load",
    "output_file_names",
    "parse",
    "parse_materialx",
    "preintegrated_table",
    "shader_sources",
]


def _json_value(value):
    # numpy arrays and scalars in a material dict become JSON lists and numbers.
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not a JSON value (a number, string, list or dict)")


def _check_finite(value, field):
    # JSON has no NaN or infinity: name the field here rather than leave a syntax error.
    if hasattr(value, "tolist"):
        value = value.tolist()
    if isinstance(value, dict):
        for key, member in value.items():
            _check_finite(member, f"{field}.{key}" if field else str(key))
    elif isinstance(value, (list, tuple)):
        for index, member in enumerate(value):
            _check_finite(member, f"{field}[{index}]")
    elif isinstance(value, float) and not _math.isfinite(value):
        raise ValueError(f"{field}: is {value}; a finite number (JSON has no NaN or infinity)")


def _path(value, argument):
    """``os.fspath(value)`` as text, refusing what no file path can hold: a NUL character would
    end the path at the operating system's boundary, so another file would be read or written."""
    try:
        path = _os.fspath(value)
    except TypeError:
        raise TypeError(
            f"{argument}: a path (str, bytes or os.PathLike), not {type(value).__name__}") from None
    if isinstance(path, bytes):
        path = _os.fsdecode(path)
    if not path:
        raise ValueError(f"{argument}: is empty; a file path")
    nul = path.find("\0")
    if nul >= 0:
        raise ValueError(f"{argument}: the path holds a NUL character (at index {nul}), "
                         "which no file path can")
    return path


def _native_path(value, argument):
    # As the operating system names it: bytes, so undecodable names (surrogate escapes) pass.
    return _os.fsencode(_path(value, argument))


def _text_bytes(text):
    # Text for the parser as bytes: what is not UTF-8 (a bytes object's, or a str's surrogate
    # escapes) reaches it as it is and gets its located "not UTF-8" error there.
    if isinstance(text, bytes):
        return text
    try:
        return text.encode("utf-8", "surrogateescape")
    except UnicodeEncodeError:
        return text.encode("utf-8", "surrogatepass")


def _dict_text(material):
    _check_finite(material, "")
    return _json.dumps(material, indent=2, default=_json_value)


def _looks_like_json(text):
    return text.lstrip().startswith("{")


def parse(source, path=None):
    """A :class:`Material` from a dict or the JSON text of a material file.

    ``path`` names it in diagnostics (default ``<dict>`` or ``<string>``); relative spectral
    files resolve against its folder. Raises :class:`MaterialError` for an invalid material.
    """
    if isinstance(source, Material):
        return source
    if isinstance(source, dict):
        return _matc._parse_json(_dict_text(source), _native_path(path or "<dict>", "path"))
    if isinstance(source, (bytes, str)):
        return _matc._parse_json(_text_bytes(source), _native_path(path or "<string>", "path"))
    raise TypeError(
        f"parse: a dict or JSON text, not {type(source).__name__} (files: matc.load)")


def parse_materialx(text, path="<string>.mtlx"):
    """The metals of a MaterialX document's text (Standard Surface or OpenPBR), as a list of
    :class:`Material`; ``path`` names it in diagnostics. Raises :class:`MaterialError`."""
    if not isinstance(text, (bytes, str)):
        raise TypeError(f"parse_materialx: text, not {type(text).__name__}")
    path = _path(path, "path")
    if not path.lower().endswith(".mtlx"):
        path = f"{path}.mtlx"
    return _matc._parse_input(_text_bytes(text), _os.fsencode(path))


def load(path):
    """The materials a file holds, as a list of :class:`Material`: a material file (``.json``)
    holds one, a MaterialX document (``.mtlx``) or a glTF asset (``.gltf``, ``.glb``; its
    metallic materials) any number. Raises :class:`MaterialError`."""
    return _matc._load(_native_path(path, "path"))


def _one_material(source):
    """A Material from anything compile() takes: a Material, a dict, JSON text, or the path of a
    file that holds exactly one material."""
    if isinstance(source, (Material, dict, bytes)):
        return parse(source)
    if isinstance(source, str) and _looks_like_json(source):
        return parse(source)
    if isinstance(source, (str, _os.PathLike)):
        materials = load(source)
        if len(materials) != 1:
            names = ", ".join(m.name for m in materials)
            raise ValueError(f"{_path(source, 'material')!r} holds {len(materials)} materials "
                         f"({names}): pick one from matc.load()")
        return materials[0]
    raise TypeError(
        "material: a matc.Material, a dict, JSON text or a file path, not "
        f"{type(source).__name__}")


def _build_compile(self, material):
    """Compiles ``material`` (a :class:`Material`, dict, JSON text or file path) with this
    build's basis and colour options: a :class:`CompiledMaterial`."""
    return self._compile(_one_material(material))


def _batch_source(source):
    if isinstance(source, tuple) and len(source) == 2:
        path, text = source
        if not isinstance(text, (bytes, str)):
            raise TypeError(f"sources: a (path, text) pair's text is {type(text).__name__}, "
                            "not str or bytes")
        return (_native_path(path, "sources"), _text_bytes(text))
    if isinstance(source, dict):
        return (_os.fsencode(f"{source.get('name', 'material')}.json"),
                _text_bytes(_dict_text(source)))
    if isinstance(source, Material):
        path = source.path if source.path.lower().endswith(".json") else f"{source.name}.json"
        return (_os.fsencode(path), _text_bytes(source.json))
    if isinstance(source, (str, bytes, _os.PathLike)):
        return (_native_path(source, "sources"), None)
    raise TypeError(
        "sources: paths, (path, text) pairs, dicts or matc.Material values, not "
        f"{type(source).__name__}")


def _build_compile_batch(self, sources, output=None, *, jobs=0, keep_going=False,
                         no_shared=False, shared_only=False, depfile=None,
                         extra_dependencies=None, progress=None):
    """Compiles ``sources`` as ``matc -o output FILES...`` does, through the library's batch:
    the same files, manifest and depfile (``extra_dependencies`` default to this module's own
    file, as the CLI's name the matc program).

    ``sources``: file paths (``.json``, ``.mtlx``), ``(path, text)`` pairs held in memory,
    dicts or :class:`Material` values. ``output``: a directory, or None to keep the files in
    memory (``result.files``). ``progress(done, total, name)`` is called after each material;
    an exception it raises (or Ctrl-C) cancels the batch and is raised again. Raises
    :class:`BatchError` (with ``.result``) when a material failed; returns a
    :class:`BatchResult`. The GIL is released while materials compile.
    """
    if isinstance(sources, (str, bytes, dict, _os.PathLike)):
        raise TypeError("sources: a list of sources, not one")
    pairs = [_batch_source(s) for s in sources]
    if extra_dependencies is None:
        extra_dependencies = [_matc.__file__]
    return _matc._compile_batch(
        self, pairs, None if output is None else _native_path(output, "output"), jobs, keep_going,
        no_shared, shared_only, None if depfile is None else _native_path(depfile, "depfile"),
        [_native_path(d, "extra_dependencies") for d in extra_dependencies], progress)


Build.compile = _build_compile
Build.compile_batch = _build_compile_batch


def compile(material, **options):
    """A :class:`CompiledMaterial` from a :class:`Material`, dict, JSON text or file path.

    Options are :class:`Build`'s (``basis``, ``color_space``, ``gamut_mapping``; the table
    options matter for shaders and files only). Raises :class:`MaterialError`.
    """
    return _default_build(**options).compile(material)


def compile_batch(sources, output=None, *, jobs=0, keep_going=False, no_shared=False,
                  shared_only=False, depfile=None, extra_dependencies=None, progress=None,
                  **options):
    """:meth:`Build.compile_batch` with a :class:`Build` of ``options``."""
    return _default_build(**options).compile_batch(
        sources, output, jobs=jobs, keep_going=keep_going, no_shared=no_shared,
        shared_only=shared_only, depfile=depfile, extra_dependencies=extra_dependencies,
        progress=progress)


GltfAsset = _collections.namedtuple("GltfAsset", ["bytes", "materials"])
GltfAsset.__doc__ = """What :func:`compile_gltf` returns: ``bytes``, the asset written back (in its own
container), and ``materials``, its metals as :class:`CompiledMaterial` values in the asset's
order."""


def compile_gltf(asset, **options):
    """What ``matc gltf`` writes (docs/gltf.md): the glTF asset at ``asset`` (a ``.glb``, or a
    ``.gltf`` with its buffers beside it) with each metal's compiled coefficients (and coat) in
    the vendor extension ``MATC_materials_fresnel``, every other byte as it was, as a
    :class:`GltfAsset`. The bytes are returned, not written: a ``.gltf`` that names files beside
    it needs them beside it wherever it goes. Options are :class:`Build`'s (``basis``,
    ``color_space``, ``gamut_mapping``). Raises :class:`MaterialError` for an asset ``matc gltf``
    refuses.
    """
    names = _default_build(**options).options
    data, materials = _matc._compile_gltf(_native_path(asset, "asset"), names["basis"],
                                          names["color_space"], names["gamut_mapping"])
    return GltfAsset(data, materials)


def evaluate(material, mu=(), ndotv=(), roughness=(), *, reference=True, quad_light=None,
             metalness=None, **options):
    """What ``matc eval`` prints for ``material`` (anything :func:`compile` takes), as a dict:
    ``F`` and ``F_exact`` at the cosines ``mu``; ``Fbar`` (from the table), ``Fbar_analytic`` and
    ``Fbar_reference`` at the (``ndotv``, ``roughness``) pairs; a coated material's lobes; with
    ``quad_light`` ("x,y,z;x,y,z;x,y,z;x,y,z" in the shading frame) its radiance by LTC beside the
    exact integral. ``reference=False`` leaves out the Monte-Carlo references (``Fbar_reference``,
    a coated material's layered ones, ``L_reference``): the shaders' values alone, fast.
    ``metalness`` (in [0, 1], ``matc eval --metalness``): glTF's metal-rough mix of the metal
    with glTF's dielectric (under a coated metal's coat, the dielectric times the coat's
    transmission), ``F_metal_rough`` and ``Fbar_metal_rough`` beside the dielectric's own
    (docs/gltf.md). Options are ``matc eval``'s: ``light_samples``, ``lut_size``,
    ``lut_samples``, ``lut_precision``, ``coefficient_table_precision``, ``basis``,
    ``color_space``, ``gamut_mapping``. Raises ``ValueError`` for options out of range."""
    return _matc._evaluate(_one_material(material), _float_list(mu, "mu"),
                           _float_list(ndotv, "ndotv"), _float_list(roughness, "roughness"),
                           reference, quad_light, _metalness(metalness), **options)


def _metalness(value):
    # A real number (numpy's too), or None; bool is refused though it is an int.
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise TypeError(f"metalness: a real number in [0, 1], not {type(value).__name__}")
    return float(value)


def _float_list(values, argument):
    try:
        return [float(v) for v in _numpy.atleast_1d(_numpy.asarray(values, dtype=float)).ravel()]
    except (TypeError, ValueError) as error:
        raise TypeError(f"{argument}: real numbers, not {values!r:.60}") from None


def shader_sources(material, languages=("glsl", "hlsl", "wgsl"), **options):
    """The material's shader snippets by language (``{"glsl": "...", ...}``), as ``matc`` writes
    ``<name>.glsl``, ``.hlsl`` and ``.wgsl``; options are :class:`Build`'s."""
    build = _default_build(**options)
    compiled = build.compile(material)
    if isinstance(languages, str):
        languages = (languages,)
    return {language: build.shader(compiled, language) for language in languages}
