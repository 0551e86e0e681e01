"""Particle sets: NumPy arrays handed to libfluidsurf in place, particle files
read, and what `fluidsurf info` reports on them."""
import numpy as np

from . import _arrays
from ._lib import check, existing_path, ffi, lib, text


class Particles:
    """A libfluidsurf particle set over NumPy columns; keeps them alive."""

    def __init__(self, positions, colors=None):
        x, y, z, self.copied = _arrays.positions_columns(positions)
        self._keep = [x, y, z]
        out = ffi.new("fluidsurf_particles **")
        check(lib.fluidsurf_particles_wrap(len(x), *(ffi.from_buffer("float[]", c) for c in (x, y, z)), out))
        self.handle = ffi.gc(out[0], lib.fluidsurf_particles_free)
        if colors is not None:
            c = _arrays.colors_array(colors, len(x))
            self._keep.append(c)
            check(lib.fluidsurf_particles_set_color(self.handle, ffi.from_buffer("float[]", c)))

    def column(self, name):
        """The address libfluidsurf reads column name from (zero-copy checks)."""
        return int(ffi.cast("uintptr_t", lib.fluidsurf_particles_column(self.handle, name.encode(), ffi.NULL)))


def read_particles(path, format=None):
    """A particle file as a dict: 'positions' (N x 3 float32) and the attributes
    it holds: 'velocity' (N x 3), 'color' (N x 3 linear RGB), 'phase' (N int32),
    'radius' (when the file stores one), and 'arrays', the file's other point
    arrays that `fluidsurf info` lists, by name (N or N x K of float32, float64,
    int32 or uint32: DualSPHysics' Idp and Rhop, SPlisHSPlasH's id)."""
    out = ffi.new("fluidsurf_particles **")
    check(lib.fluidsurf_particles_read(existing_path(path, "path"), format.encode() if format else ffi.NULL, out))
    p = ffi.gc(out[0], lib.fluidsurf_particles_free)
    n = lib.fluidsurf_particles_count(p)

    def column(name, dtype, ncomp):
        ptr = lib.fluidsurf_particles_column(p, name.encode(), ffi.NULL)
        if ptr == ffi.NULL:
            return None
        a = np.frombuffer(ffi.buffer(ptr, n * ncomp * 4), dtype=dtype).copy()
        return a.reshape((n, ncomp)) if ncomp > 1 else a

    result = {"positions": np.stack([column(c, np.float32, 1) for c in "xyz"], axis=1)}
    if column("vx", np.float32, 1) is not None:
        result["velocity"] = np.stack([column(c, np.float32, 1) for c in ("vx", "vy", "vz")], axis=1)
    for name, dtype, ncomp in (("color", np.float32, 3), ("phase", np.int32, 1)):
        a = column(name, dtype, ncomp)
        if a is not None:
            result[name] = a
    if lib.fluidsurf_particles_radius(p) > 0:
        result["radius"] = float(lib.fluidsurf_particles_radius(p))
    arrays = _point_arrays(p, n)
    if arrays:
        result["arrays"] = arrays
    return result


_ARRAY_TYPES = {lib.FLUIDSURF_ARRAY_F32: np.float32, lib.FLUIDSURF_ARRAY_F64: np.float64,
                lib.FLUIDSURF_ARRAY_I32: np.int32, lib.FLUIDSURF_ARRAY_U32: np.uint32}


def _point_arrays(p, n):
    """The read set p's other point arrays as {name: copied array}."""
    name, ncomp, kind = ffi.new("const char **"), ffi.new("int *"), ffi.new("int *")
    out = {}
    for i in range(lib.fluidsurf_particles_array_count(p)):
        ptr = lib.fluidsurf_particles_array(p, i, name, ncomp, kind)
        dtype = np.dtype(_ARRAY_TYPES[kind[0]])
        a = np.frombuffer(ffi.buffer(ptr, n * ncomp[0] * dtype.itemsize), dtype=dtype).copy()
        out[text(name[0])] = a.reshape((n, ncomp[0])) if ncomp[0] > 1 else a
    return out


def estimate_radius(positions):
    """The particle radius r the spacing of positions (N x 3) implies, as render(),
    compare() and mesh() estimate it without radius=: r = (volume per particle)^(1/3) / 2
    (fluidsurf's lattice spacing is 2r), the volume per particle from the 32
    nearest neighbours of a fixed sample of 4096 particles. ValueError for fewer
    than 2 particles or no spacing (all at one point)."""
    p = Particles(positions)
    r = ffi.new("double *")
    check(lib.fluidsurf_particles_estimate_radius(p.handle, r))
    return float(r[0])


_SOURCES = {lib.FLUIDSURF_R_GIVEN: "given", lib.FLUIDSURF_R_FILE: "file",
            lib.FLUIDSURF_R_ESTIMATED: "estimated", lib.FLUIDSURF_R_DEFAULT: "default"}


def info(positions, radius=None, volume_scale=1.0):
    """What `fluidsurf info` reports on positions (N x 3), as a dict: 'count',
    'bbox_min' and 'bbox_max' (3 floats each); 'radius', the r the numbers use,
    and 'radius_source': 'given' (radius=) or 'estimated' (from the spacing, as
    estimate_radius(); 'default' when there is none); 'estimated_radius' (None
    without a spacing); 'nn_median', the median nearest-neighbour distance, and
    'nn_median_r' in r; 'density_median', the median normalised density phi at
    particle centres (cubic kernel, support 4r, V = volume_scale (2r)^3), which
    reads about 1 inside a fluid at the right r and volume_scale; and
    'volume_scale_for_unit_density', the volume_scale that would make it 1.
    The spacing and density are measured on a fixed sample of 4096 particles."""
    r = 0.0 if radius is None else _arrays.positive(radius, "radius")
    vs = _arrays.positive(volume_scale, "volume_scale")
    p = Particles(positions)
    s = ffi.new("fluidsurf_particles_info *")
    check(lib.fluidsurf_particles_stats(p.handle, r, vs, s))
    return {"count": int(s.count), "bbox_min": list(s.bbox_min), "bbox_max": list(s.bbox_max),
            "radius": s.radius, "radius_source": _SOURCES[s.radius_source],
            "estimated_radius": s.estimated_radius if s.estimated_radius > 0 else None,
            "nn_median": s.nn_median, "nn_median_r": s.nn_median / s.radius, "density_median": s.density_median,
            "volume_scale": s.volume_scale,
            "volume_scale_for_unit_density": s.volume_scale / s.density_median if s.density_median > 0 else None}
