"""NumPy arrays in and out of libfluidsurf: checks that name the argument, the
zero-copy rule for positions, and images turned into arrays."""
import math

import numpy as np


def positions_columns(positions, name="positions"):
    """(x, y, z, copied): three contiguous float32 columns of an N x 3 array.

    fluidsurf's particles are structure-of-arrays, so a float32 array whose
    columns are contiguous (Fortran order) is used in place; anything else is
    converted once into such an array."""
    a = np.asarray(positions)
    if a.ndim != 2 or a.shape[1] != 3 or a.shape[0] < 1:
        raise ValueError(f"{name}: expected an N x 3 array with N >= 1, got shape {a.shape}")
    if a.dtype not in (np.float32, np.float64):
        raise ValueError(f"{name}: expected float32 or float64, got {a.dtype}")
    copied = not (a.dtype == np.float32 and a.strides[0] == 4)
    with np.errstate(over="ignore"):  # an overflow becomes inf, refused below
        cols = np.asfortranarray(a, dtype=np.float32) if copied else a
    finite = np.isfinite(cols)
    if not finite.all():
        row = int(np.argwhere(~finite)[0][0])
        raise ValueError(f"{name}: {int((~finite).sum())} values are NaN or infinite in float32 (the first in row {row})")
    return cols[:, 0], cols[:, 1], cols[:, 2], copied


def colors_array(colors, n, name="colors"):
    """An N x 3 C-ordered float32 array of linear RGB."""
    c = np.ascontiguousarray(colors, dtype=np.float32)
    if c.shape != (n, 3):
        raise ValueError(f"{name}: expected shape ({n}, 3), got {c.shape}")
    if not np.isfinite(c).all():
        raise ValueError(f"{name}: NaN or infinite values")
    return c


def positive(value, name):
    """value as a float > 0 and finite, else ValueError naming it."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected a number, got {value!r}") from None
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name}: must be positive and finite, got {value!r}")
    return v


def size(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 1 <= value <= 16384:
        raise ValueError(f"{name}: expected an integer from 1 to 16384, got {value!r}")
    return int(value)


def vector3(value, name):
    v = np.asarray(value, dtype=np.float64)
    if v.shape != (3,) or not np.isfinite(v).all():
        raise ValueError(f"{name}: expected 3 finite numbers, got {value!r}")
    return [float(x) for x in v]


def layer(ffi, ptr, w, h, ncomp):
    """A copy of an image layer as an H x W (x ncomp) float32 array."""
    a = np.frombuffer(ffi.buffer(ptr, w * h * ncomp * 4), dtype=np.float32).copy()
    return a.reshape((h, w)) if ncomp == 1 else a.reshape((h, w, ncomp))


def rows(ffi, ptr, n, dtype):
    """A copy of n rows of 3 values of dtype at ptr as an n x 3 array (empty when n is 0)."""
    if n == 0 or ptr == ffi.NULL:
        return np.zeros((0, 3), dtype)
    return np.frombuffer(ffi.buffer(ptr, n * 3 * np.dtype(dtype).itemsize), dtype=dtype).reshape((n, 3)).copy()


def image_array(value, shape, name, required=True):
    """value as a C-ordered float32 array of this shape (None when not required)."""
    if value is None:
        if required:
            raise ValueError(f"{name}: missing")
        return None
    a = np.ascontiguousarray(value, dtype=np.float32)
    if a.shape != shape:
        raise ValueError(f"{name}: expected shape {shape}, got {a.shape}")
    return a
