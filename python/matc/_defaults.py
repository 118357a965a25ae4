"""One shared Build per set of options for the module-level functions (matc.compile, ...):
a build makes the shader library once and bakes its tables on first use."""

import threading

from ._matc import Build

_lock = threading.Lock()
_builds = {}


def _hashable(value):
    if isinstance(value, (list, tuple, set)):
        return tuple(value)
    return value


def default_build(**options):
    key = tuple(sorted((name, _hashable(value)) for name, value in options.items()))
    with _lock:
        build = _builds.get(key)
        if build is None:
            build = _builds[key] = Build(**options)
        return build
