"""libfluidsurf loaded through cffi's ABI mode, and its errors as Python's.

The C declarations are the header's text between its cffi markers, read from
the copy installed beside this file; FLUIDSURF_LIBRARY loads another build of
the library."""
import errno
import os

from cffi import FFI

from . import _paths

_here = os.path.dirname(os.path.abspath(__file__))


def _declarations():
    with open(os.path.join(_here, "fluidsurf.h"), encoding="utf-8") as f:
        text = f.read()
    begin, end = "/* cffi:begin */", "/* cffi:end */"
    return text[text.index(begin) + len(begin):text.index(end)]


ffi = FFI()
ffi.cdef(_declarations())
lib = ffi.dlopen(os.environ.get("FLUIDSURF_LIBRARY") or
                 os.path.normpath(os.path.join(_here, _paths.LIB_FROM_PACKAGE, _paths.SONAME)))
if lib.fluidsurf_api_version() < lib.FLUIDSURF_API_VERSION:
    raise ImportError(f"libfluidsurf's API version {lib.fluidsurf_api_version()} is older than this module's")


class Error(RuntimeError):
    """A failure inside fluidsurf that is not the caller's input (OpenGL, memory)."""


def check(rc):
    """The library's return code as an exception: ValueError for bad input, Error otherwise."""
    if rc != lib.FLUIDSURF_OK:
        msg = ffi.string(lib.fluidsurf_last_error()).decode("utf-8", "replace")
        raise (ValueError if rc == lib.FLUIDSURF_ERR_INPUT else Error)(msg)


def text(ptr):
    return ffi.string(ptr).decode("utf-8", "replace") if ptr != ffi.NULL else None


def existing_path(path, name):
    """path for the library, as bytes; FileNotFoundError naming the argument when
    nothing is there (the library would say ValueError, as for a bad file)."""
    p = os.fspath(path)
    if not os.path.exists(p):
        raise FileNotFoundError(errno.ENOENT, f"{name}: no such file", os.fsdecode(p))
    return os.fsencode(p)


def output_path(path, name, extensions):
    """path to write, as bytes: one of extensions, in a folder that exists, else
    ValueError (or FileNotFoundError for the folder) naming the argument."""
    try:
        p = os.fsdecode(os.fspath(path))
    except TypeError:
        raise ValueError(f"{name}: expected a path, got {path!r}") from None
    if not p.lower().endswith(tuple(extensions)):
        raise ValueError(f"{name} {p!r}: expected a file ending in {', '.join(extensions)}")
    folder = os.path.dirname(os.path.abspath(p))
    if not os.path.isdir(folder):
        raise FileNotFoundError(errno.ENOENT, f"{name}: no such folder", folder)
    if os.path.isdir(p):
        raise ValueError(f"{name} {p!r}: is a folder")
    return os.fsencode(p)


def c_strings(texts):
    """("char *[]" or NULL, its count, the strings to keep alive) of texts."""
    keep = [ffi.new("char[]", t.encode()) for t in texts]
    return (ffi.new("char *[]", keep) if keep else ffi.NULL), len(keep), keep


def provenance_pairs(provenance, name):
    """A provenance dict ({'fluidsurf:NAME': 'value'}) checked, as (bytes, bytes) pairs."""
    if provenance is None:
        return []
    if not isinstance(provenance, dict):
        raise ValueError(f"{name}: expected a dict of 'fluidsurf:NAME': text, got {type(provenance).__name__}")
    pairs = []
    for k, v in provenance.items():
        if not isinstance(k, str) or not k.startswith("fluidsurf:") or not isinstance(v, str):
            raise ValueError(f"{name}: {k!r}: {v!r}: expected 'fluidsurf:NAME': text")
        pairs.append((k.encode(), v.encode()))
    return pairs
