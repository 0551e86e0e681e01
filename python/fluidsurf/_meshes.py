"""Triangle meshes: the mesh method's surface of particles without rendering,
and mesh files written with their provenance."""
import collections

import numpy as np

from . import _arrays
from ._lib import check, ffi, lib, output_path, provenance_pairs, text


class Mesh(collections.namedtuple("Mesh", ["vertices", "faces", "normals"])):
    """mesh()'s result: (vertices, faces, normals), which unpacks as
    pysplashsurf's triple, and .provenance, the {'fluidsurf:NAME': text} that
    write_mesh() writes into the file (version, commit, r, field, method,
    params, ...)."""

    def __new__(cls, vertices, faces, normals, provenance=None):
        self = super().__new__(cls, vertices, faces, normals)
        self.provenance = dict(provenance or {})
        return self


def _provenance(m):
    return {text(lib.fluidsurf_mesh_provenance_name(m, i)): text(lib.fluidsurf_mesh_provenance_value(m, i))
            for i in range(lib.fluidsurf_mesh_provenance_count(m))}


def mesh_result(m):
    """A libfluidsurf mesh as a Mesh of copies of its arrays."""
    nv, nt = lib.fluidsurf_mesh_vertex_count(m), lib.fluidsurf_mesh_triangle_count(m)
    vertices = _arrays.rows(ffi, lib.fluidsurf_mesh_vertices(m), nv, np.float32)
    normals = _arrays.rows(ffi, lib.fluidsurf_mesh_normals(m), nv, np.float32)
    faces = _arrays.rows(ffi, lib.fluidsurf_mesh_triangles(m), nt, np.uint32).astype(np.int64)
    return Mesh(vertices, faces, normals, _provenance(m))


def _mesh_arrays(mesh):
    """(vertices, normals or None, faces) of a Mesh or a (vertices, faces[, normals]) tuple, checked."""
    if not isinstance(mesh, (tuple, list)) or len(mesh) not in (2, 3):
        raise ValueError("mesh: expected (vertices, faces) or (vertices, faces, normals), as mesh() returns")
    v = np.ascontiguousarray(mesh[0], dtype=np.float32)
    if v.ndim != 2 or v.shape[1] != 3 or not np.isfinite(v).all():
        raise ValueError(f"mesh vertices: expected N x 3 finite numbers, got shape {v.shape}")
    f = np.asarray(mesh[1])
    if f.ndim != 2 or f.shape[1] != 3 or not np.issubdtype(f.dtype, np.integer):
        raise ValueError(f"mesh faces: expected M x 3 integer vertex indices, got shape {f.shape} of {f.dtype}")
    if f.size and (f.min() < 0 or f.max() >= len(v)):
        raise ValueError(f"mesh faces: indices from 0 to {len(v) - 1}, got {f.min()} to {f.max()}")
    n = None
    if len(mesh) == 3 and mesh[2] is not None:
        n = np.ascontiguousarray(mesh[2], dtype=np.float32)
        if n.shape != v.shape or not np.isfinite(n).all():
            raise ValueError(f"mesh normals: expected {v.shape} finite numbers like the vertices, got shape {n.shape}")
    return v, n, np.ascontiguousarray(f, dtype=np.uint32)


def write_mesh(mesh, path, provenance=None):
    """Writes mesh (as mesh() returns it, or your own (vertices, faces) or
    (vertices, faces, normals)) as `fluidsurf mesh` writes it, by the
    extension: .ply (binary), .obj, .vtk or .vtp (those two through VTK), with
    the provenance in the file: "comment fluidsurf:NAME=VALUE" lines of a PLY,
    "# fluidsurf:NAME=VALUE" lines of an OBJ, one-string field-data arrays of
    VTK. provenance: {'fluidsurf:NAME': text}, over mesh.provenance. Normals
    missing: the area-weighted mean of the adjacent faces' normals. Atomic: a
    failure leaves no file. ValueError for another extension or bad arrays."""
    p = output_path(path, "path", (".ply", ".obj", ".vtk", ".vtp"))
    v, n, f = _mesh_arrays(mesh)
    pairs = provenance_pairs(getattr(mesh, "provenance", None), "mesh.provenance")
    pairs += provenance_pairs(provenance, "provenance")  # set after mesh's: the same name replaces its value
    out = ffi.new("fluidsurf_mesh **")
    check(lib.fluidsurf_mesh_from_arrays(len(v), ffi.from_buffer("float[]", v),
                                         ffi.NULL if n is None else ffi.from_buffer("float[]", n), len(f),
                                         ffi.from_buffer("uint32_t[]", f), out))
    m = ffi.gc(out[0], lib.fluidsurf_mesh_free)
    for k, val in pairs:
        check(lib.fluidsurf_mesh_set_provenance(m, k, val))
    check(lib.fluidsurf_mesh_write(m, p))
