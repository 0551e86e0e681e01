"""fluidsurf: surfaces of particle fluids rendered by published methods, with an
exact reference and metrics, from NumPy arrays (docs/DESIGN.md, "The library").

    import fluidsurf
    out = fluidsurf.render(positions, 0.025, method="raycast_pca", width=256, height=256)
    out["depth"], out["normal"], out["rgb"], out["timings"]
    fluidsurf.write_image(out, "view.exr")          # read_gbuffer() gives it back
    m = fluidsurf.mesh(positions, 0.025)            # vertices, faces, normals = m
    fluidsurf.write_mesh(m, "surface.ply")          # with its provenance
    fluidsurf.info(positions), fluidsurf.estimate_radius(positions)

A thin layer over libfluidsurf.so (include/fluidsurf/fluidsurf.h) through cffi's
ABI mode: the C declarations are read from the header installed beside this
file, and every call into the library releases the GIL. Set FLUIDSURF_LIBRARY to
load another build of the library."""
import copy
import functools
import os
import re
import warnings

import numpy as np

from . import _arrays
from ._images import image_dict as _image_dict
from ._images import image_from_dict as _image_from_dict
from ._images import metrics, read_gbuffer, write_image
from ._lib import Error, c_strings, existing_path, ffi, lib
from ._lib import check as _check
from ._lib import text as _text
from ._meshes import Mesh, mesh_result, write_mesh
from ._particles import Particles as _Particles
from ._particles import estimate_radius, info, read_particles

__all__ = ["Error", "Mesh", "read_particles", "read_gbuffer", "render", "compare", "mesh", "metrics", "methods",
           "version", "write_image", "write_mesh", "info", "estimate_radius"]


def version():
    """'0.1.0 (commit ...)' of the loaded library."""
    return _text(lib.fluidsurf_version())


# ---- scenes -----------------------------------------------------------------

_FIELD_KEYS = ("volume_scale", "iso", "support", "kernel")
# splashsurf's (and pysplashsurf's) names of the mesh's settings, as ours:
# cube_size is our cube (both in r); its smoothing length is half our support H
# (its compact support is twice the smoothing length, both in r); its iso-surface
# threshold is our iso (of the same normalised density).
_SPLASHSURF_PARAMS = {"cube_size": "cube"}
_SPLASHSURF_FIELD = {"smoothing_length": ("support", 2.0), "iso_surface_threshold": ("iso", 1.0)}


def _scene(scene, radius, up=None, field=None):
    """A scene: the file's (scene=) or the defaults, with the caller's r, up axis
    ("auto", "x", "y", "z") and field settings ({volume_scale, iso, support, kernel})."""
    out = ffi.new("fluidsurf_scene **")
    if scene is None:
        _check(lib.fluidsurf_scene_new(out))
    else:
        _check(lib.fluidsurf_scene_load(existing_path(scene, "scene"), out))
    s = ffi.gc(out[0], lib.fluidsurf_scene_free)
    if radius is not None:
        _check(lib.fluidsurf_scene_set_radius(s, _arrays.positive(radius, "radius")))
    if up is not None:
        if up not in ("auto", "x", "y", "z"):
            raise ValueError(f"up={up!r}: expected 'auto', 'x', 'y' or 'z'")
        _check(lib.fluidsurf_scene_set_up(s, up.encode()))
    if field:
        _set_field(s, field)
    return s


def _splashsurf_field(field):
    """field with splashsurf's names as ours: smoothing_length l is support 2 l."""
    out = {}
    for key, value in field.items():
        ours, scale = _SPLASHSURF_FIELD.get(key, (key, 1.0))
        if ours in out:
            raise ValueError(f"field: {key!r} and {ours!r} are one setting: give one of them")
        if scale != 1.0:
            value = scale * _arrays.positive(value, f"field['{key}']")
        out[ours] = value
    return out


def _set_field(s, field):
    """field= over the scene's field; r stays as it was settled (radius=, the scene's, or unset)."""
    if not isinstance(field, dict):
        raise ValueError(f"field: expected a dict of {', '.join(_FIELD_KEYS)}, got {type(field).__name__}")
    field = _splashsurf_field(field)
    unknown = sorted(set(field) - set(_FIELD_KEYS))
    if unknown:
        raise ValueError(f"field: unknown key(s) {', '.join(map(repr, unknown))}; expected {', '.join(_FIELD_KEYS)} "
                         "(or splashsurf's smoothing_length, iso_surface_threshold)")
    f = ffi.new("fluidsurf_field *")
    _check(lib.fluidsurf_scene_get_field(s, f))
    for key in ("volume_scale", "iso", "support"):
        if key in field:
            setattr(f, key, _arrays.positive(field[key], f"field['{key}']"))
    if "kernel" in field:
        if not isinstance(field["kernel"], str):
            raise ValueError(f"field['kernel']={field['kernel']!r}: expected cubic, poly6, spiky or wyvill")
        f.kernel = field["kernel"].encode()[:15]
    f.radius = 0  # keeps r as it is: set_radius above, or unset
    _check(lib.fluidsurf_scene_set_field(s, f))


# what the warnings for an estimated r add: README.md's "r." has the measured spread
_R_ESTIMATED_CAVEAT = "low or high on a simulation's own frames; pass radius="


def _warn_estimated(prov):
    """Python's form of the command line's note: r came from the spacing, not the caller."""
    if prov.get("fluidsurf:r_source") == "estimated":
        warnings.warn(f"no radius given: r = {float(prov['fluidsurf:r']):.6g} estimated from the particle spacing "
                      f"({_R_ESTIMATED_CAVEAT})", stacklevel=3)


def _view(s, width, height, camera):
    """The image size and, when given, the camera of scene s: a dict, or the command
    line's --camera text ("eye=X,Y,Z;target=X,Y,Z[;up=..][;fov=..][;size=WxH]")."""
    _check(lib.fluidsurf_scene_set_size(s, _arrays.size(width, "width"), _arrays.size(height, "height")))
    if isinstance(camera, str):
        _check(lib.fluidsurf_scene_set_camera_text(s, camera.encode()))
    elif camera is not None:
        _check(lib.fluidsurf_scene_set_camera(s, _camera(camera, width, height)))
    return s


def _camera(camera, width, height):
    if not isinstance(camera, dict) or "eye" not in camera or "target" not in camera:
        raise ValueError("camera: expected a dict with 'eye' and 'target' (and optionally 'up', 'fov'), or a text "
                         "'eye=X,Y,Z;target=X,Y,Z[;up=..][;fov=..]'")
    unknown = set(camera) - {"eye", "target", "up", "fov"}
    if unknown:
        raise ValueError(f"camera: unknown keys {sorted(unknown)}")
    c = ffi.new("fluidsurf_camera *")
    c.eye = _arrays.vector3(camera["eye"], "camera['eye']")
    c.target = _arrays.vector3(camera["target"], "camera['target']")
    # without 'up' (0, 0, 0): the scene's up axis, as --camera without up=
    c.up = _arrays.vector3(camera.get("up", (0, 0, 0)), "camera['up']")
    c.fov_deg = _arrays.positive(camera.get("fov", 40), "camera['fov']")
    c.width, c.height = width, height
    return c


_PATTERN = re.compile(r"\{\}|%[0-9]*d")


def _source(s, path, frames):
    """Scene s reads path, as the command line's input: a particle file, or a frame
    pattern ('f_{}.vtk', 'f_%04d.vtk') with frames 'FIRST:LAST[:STEP]' or a number."""
    text = os.fsdecode(os.fspath(path))
    if not _PATTERN.search(text):
        if frames is not None:
            raise ValueError(f"frames: {text} is not a frame pattern ({{}} or %04d)")
        existing_path(text, "positions")  # FileNotFoundError naming it
        span = (0, 0, 0)
    elif isinstance(frames, int) and not isinstance(frames, bool):
        span = (frames, frames, 1)
    else:
        m = re.fullmatch(r"(\d+):(\d+)(?::(\d+))?", frames) if isinstance(frames, str) else None
        if not m:
            raise ValueError(f"frames={frames!r}: {text} is a frame pattern: give 'FIRST:LAST[:STEP]' or a frame number")
        span = (int(m[1]), int(m[2]), int(m[3] or 1))
    _check(lib.fluidsurf_scene_set_source(s, os.fsencode(text), *span))
    return span[0]


class _Frame:
    """A frame the library read from the scene's source (fluidsurf_scene_read_frame)."""

    def __init__(self, s, frame):
        out = ffi.new("fluidsurf_particles **")
        _check(lib.fluidsurf_scene_read_frame(s, frame, out))
        self.handle = ffi.gc(out[0], lib.fluidsurf_particles_free)


# ---- methods and their parameters ---------------------------------------------

def _typed(kind, value, choices):
    """A parameter's number from the library as Python's type: an enum's name, int, bool, float."""
    if kind == "enum":
        return choices[int(value)]
    return {"int": int, "bool": bool}.get(kind, float)(value)


@functools.lru_cache(maxsize=None)
def _registry():
    """{method: its methods() entry, with 'table': {parameter: its entry}}, read once."""
    info = ffi.new("fluidsurf_param *")
    result = {}
    for i in range(lib.fluidsurf_method_count()):
        name = lib.fluidsurf_method_name(i)
        params = []
        for j in range(lib.fluidsurf_param_count(name)):
            _check(lib.fluidsurf_param_info(name, j, info))
            kind, choices = _text(info.type), [c for c in _text(info.choices).split("|") if c]
            ranged = kind in ("int", "float")
            params.append({"name": _text(info.name), "type": kind, "default": _typed(kind, info.default_value, choices),
                           "min": _typed(kind, info.min, choices) if ranged else None,
                           "max": _typed(kind, info.max, choices) if ranged else None,
                           "choices": choices, "help": _text(info.help)})
        result[_text(name)] = {"name": _text(name), "description": _text(lib.fluidsurf_method_description(name)),
                               "paper": _text(lib.fluidsurf_method_paper(name)),
                               "needs_gl": bool(lib.fluidsurf_method_needs_gl(name)), "params": params}
    return result


def _method(name, arg):
    """name, a registered method, else ValueError naming the argument and listing them."""
    if not isinstance(name, str):
        raise ValueError(f"{arg}: expected a method name, got {name!r}")
    if name not in _registry():
        raise ValueError(f"{arg}: unknown method {name!r} (methods: {', '.join(_registry())})")
    return name


def _value_text(p, value):
    """(text, None): value for parameter p (a methods() entry) as the library's
    text, or (None, what is wrong with it)."""
    kind = p["type"]
    if kind == "enum":
        ok = isinstance(value, str) and value in p["choices"]
        return (value, None) if ok else (None, f"expected one of {', '.join(map(repr, p['choices']))}")
    if kind == "bool":
        if isinstance(value, str) and value in ("on", "off", "true", "false"):
            return value, None
        ok = isinstance(value, (bool, np.bool_, int, np.integer)) and value in (0, 1)
        return ("on" if value else "off", None) if ok else (None, "expected True or False")
    number = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))
    if not number or not np.isfinite(value) or (kind == "int" and value != int(value)):
        return None, f"expected {'an integer' if kind == 'int' else 'a number'}"
    if not p["min"] <= value <= p["max"]:
        return None, f"outside [{p['min']}, {p['max']}]"
    return repr(int(value) if kind == "int" else float(value)), None


def _setting(method, param, value, where):
    """'param=value' for method, checked; where: the caller's argument, as written."""
    table = {p["name"]: p for p in _registry()[method]["params"]}
    if param not in table:
        raise ValueError(f"{where}: {method} has no parameter {param!r} (its parameters: {', '.join(table) or 'none'})")
    text, wrong = _value_text(table[param], value)
    if wrong:
        raise ValueError(f"{where}: {method}.{param} {value!r}: {wrong}")
    return f"{param}={text}"


def _split(key, value, arg):
    """One flat key of params as (method, param, value, where): 'method.param' or
    'param' (method None); where names the argument as the caller wrote it."""
    if not isinstance(key, str):
        raise ValueError(f"{arg}: expected parameter names as keys, got {key!r}")
    method, _, param = key.rpartition(".")
    return method or None, param, value, f"{arg}={{{key!r}: {value!r}}}"


def _settings(method, params, arg="params"):
    """params of one render of method, {parameter: value} or {'method.parameter':
    value}, as the library's "param=value" texts, every one checked."""
    if params is None:
        return []
    if not isinstance(params, dict):
        raise ValueError(f"{arg}: expected a dict of parameter values, got {type(params).__name__}")
    texts = []
    for key, value in params.items():
        m, param, v, where = _split(key, value, arg)
        if m is not None and m != method:
            raise ValueError(f"{where}: {m!r} is not the method rendered ({method!r})")
        texts.append(_setting(method, param, v, where))
    return texts


def _study_settings(params, names, arg="params"):
    """compare's params, {method: {parameter: value}} or {'method.parameter': value},
    as {method: ["param=value", ...]} for the methods named (names), every one checked."""
    if params is None:
        return {}
    if not isinstance(params, dict):
        raise ValueError(f"{arg}: expected {{method: {{parameter: value}}}} or {{'method.parameter': value}}")
    per = {}
    for key, value in params.items():
        m, param, v, where = _split(key, value, arg)
        if m is None:  # {method: {parameter: value}}
            m, param = param, None
        if m not in names:
            raise ValueError(f"{where}: {m!r} is not a method of this comparison ({', '.join(names)}); "
                             f"expected {{method: {{parameter: value}}}} or {{'method.parameter': value}}")
        if param is not None:
            items = [(param, v, where)]
        elif isinstance(value, dict):
            items = [(p, v, f"{arg}={{{key!r}: {{{p!r}: {v!r}}}}}") for p, v in value.items()]
        else:
            raise ValueError(f"{where}: expected a dict of parameter values of {m}")
        for p, v, w in items:
            per.setdefault(m, []).append(_setting(m, p, v, w))
    return per


def methods():
    """Every method: name, description, paper, needs_gl and its parameters, each
    with name, type ('float', 'int', 'bool', 'enum'), default (of that type: an
    enum's name), min and max (numbers; None for bool and enum), choices (an
    enum's names) and help."""
    return copy.deepcopy(list(_registry().values()))


# ---- renders ----------------------------------------------------------------

_c_settings = c_strings


def _render_handle(scene, particles, method, settings):
    """An image handle: method on particles, with its checked "param=value" settings."""
    arr, n, _keep = _c_settings(settings)
    out = ffi.new("fluidsurf_image **")
    _check(lib.fluidsurf_render(scene, particles.handle, method.encode(), arr, n, out))
    return ffi.gc(out[0], lib.fluidsurf_image_free)


def render(positions, radius=None, method="raycast_pca", width=512, height=512, camera=None, params=None,
           scene=None, colors=None, up=None, field=None, frame=None, save_scene=None):
    """Renders positions (N x 3, float32 or float64, any order) with one method.
    positions may also be a particle file's path, or a frame pattern ('f_{}.vtk',
    'f_%04d.vtk') with frame=N, read by the library as `fluidsurf render` reads it;
    save_scene: a .json path (positions a path) to write the scene as rendered, as
    `render --save-scene` does: rendering that file gives the same image.

    radius: r (None: the scene's, else the r the spacing implies, as the command
    line estimates, with a UserWarning saying so; provenance['r_source'] tells);
    up: 'auto' (the default without scene=: the particles decide, as the command
    line's --up auto; provenance['up'] says which), 'x', 'y' or 'z';
    field: {'volume_scale', 'iso', 'support', 'kernel'} over the scene's;
    camera: {'eye', 'target', 'up', 'fov'} (without 'up' the scene's up axis),
    or --camera's text 'eye=X,Y,Z;target=X,Y,Z[;up=..][;fov=..][;size=WxH]', or
    read_gbuffer(path)['camera'] (None: frames the particles as the command line
    does); params: {parameter: value} (or {'method.parameter':
    value}) of the method, values of the types methods() gives (an enum's name,
    True/False); scene: a scene file whose field, light and settings to use;
    colors: N x 3 linear RGB. A missing file raises FileNotFoundError; an unknown
    method or parameter, or a bad value, ValueError naming it.
    Returns a dict of H x W float32 arrays 'depth' (inf where empty), 'normal'
    (view space), 'thickness', 'coverage', 'rgb' (linear, the shared shading),
    'alpha', the method's AOVs by name, and 'timings', 'provenance', 'radius'
    'camera' (the framing chosen: pass it on to keep a sequence's view),
    'width', 'height' and 'r_source' (provenance['fluidsurf:r_source'])."""
    method = _method(method, "method")
    settings = _settings(method, params)
    s = _scene(scene, radius, up, field)
    is_path = isinstance(positions, (str, bytes, os.PathLike))
    if frame is not None and (not isinstance(frame, int) or isinstance(frame, bool)):
        raise ValueError(f"frame={frame!r}: expected one frame number")
    if save_scene is not None and not is_path:
        raise ValueError("save_scene: give positions as a particle file or a frame pattern (the scene names it)")
    p = _Frame(s, _source(s, positions, frame)) if is_path else _Particles(positions, colors)
    s = _view(s, width, height, camera)
    image = _image_dict(_render_handle(s, p, method, settings))
    if save_scene is not None:
        _check(lib.fluidsurf_scene_save(s, p.handle, os.fsencode(os.fspath(save_scene))))
    _warn_estimated(image["provenance"])
    return image


def _table(text):
    """A study table (CSV text after its provenance line) as a list of dicts:
    integers and numbers as such, an empty cell of a numeric column as NaN."""
    import csv
    import io
    lines = text.splitlines()
    rows = list(csv.DictReader(io.StringIO("\n".join(lines[1:]))))

    def number(v):
        for kind in (int, float):
            try:
                return kind(v)
            except ValueError:
                pass
        return None

    numeric = {k for r in rows for k, v in r.items() if v != "" and number(v) is not None}
    numeric -= {k for r in rows for k, v in r.items() if v != "" and number(v) is None}
    return [{k: (number(v) if v != "" else float("nan")) if k in numeric else v for k, v in r.items()} for r in rows]


def _frames(positions, colors):
    """positions: one N x 3 array, or a list of them (a sequence); None: the scene's own frames."""
    if positions is None:
        return []
    if isinstance(positions, (list, tuple)):
        if not positions:
            raise ValueError("positions: an empty list of frames")
        return [_Particles(p, c) for p, c in zip(positions, colors if colors is not None else [None] * len(positions))]
    return [_Particles(positions, colors)]


def _sweep_sets(sweep, names):
    """sweep {'method.param': [v1, v2, ...]} as compare's --set M.P=v1,v2 texts, every value checked."""
    sets = []
    for key, values in (sweep or {}).items():
        m, param, _, where = _split(key, values, "sweep")
        if m is None or m not in names:
            raise ValueError(f"{where}: expected 'method.parameter' of a method of this comparison ({', '.join(names)})")
        if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or len(values) < 2:
            raise ValueError(f"{where}: expected a list of two or more values")
        texts = [_setting(m, param, v, where).split("=", 1)[1] for v in values]
        sets.append(f"{m}.{param}={','.join(texts)}")
    return sets


def compare(positions=None, radius=None, methods=("raycast_pca",), width=None, height=None, camera=None,
            params=None, reference="reference", scene=None, colors=None, up=None, field=None, sweep=None,
            repeat=3, counters=False, tables=False, out=None, force=False, frames=None):
    """Each method variant against the reference on a particle set or a sequence,
    through the engine of `fluidsurf compare` (common/study, fluidsurf_compare):
    the same metrics, the same timing protocol (a warm-up, then `repeat` timed
    renders, their median as frame_ms), the same tables.
    positions: an N x 3 array, a list of them (a sequence), a particle file's
    path, a frame pattern ('f_{}.vtk', 'f_%04d.vtk') with frames='FIRST:LAST[:STEP]'
    (read frame by frame, as `fluidsurf compare PATTERN --frames`), or None with
    scene= (the scene file's own particle source, as `fluidsurf compare s.json`).
    radius, up, field, scene as render(); width and height default to 512 (a
    scene file's own size with scene=). params: {method: {parameter: value}} or
    {'method.parameter': value}; sweep: {'method.parameter': [v1, v2, ...]}, as
    --set M.P=v1,v2. reference: a spec or a list of them ("reference",
    "reference:param=value,...", "analytic"). Every method and parameter is
    checked before the first render (ValueError naming it).
    Returns the metrics table (the columns of metrics.csv, one row per variant,
    reference and frame): a pandas DataFrame when pandas is there, else a list of
    dicts; tables=True returns {"metrics", "timings", "temporal" (a sequence),
    "counters" (counters=True)}, each such a table.
    out: a folder to write the study into, as `fluidsurf compare -o DIR --no-cache`
    writes it (images, heatmaps, panel.png, the tables, report.md, report.html;
    fluidsurf_compare_to_dir); force=True removes an earlier run's files there
    first (without it such a folder is refused)."""
    if isinstance(methods, str) or not all(isinstance(m, str) for m in methods):
        raise ValueError(f"methods: expected a list of method names, got {methods!r}")
    for name in methods:
        _method(name, "methods")
    refs = [reference] if isinstance(reference, str) else list(reference)
    for spec in refs:
        if spec != "analytic":
            _method(spec.split(":", 1)[0], "reference")
    names = list(dict.fromkeys([*methods, "reference"]))
    settings = _study_settings(params, names)
    sets = [f"{m}.{t}" for m, texts in settings.items() for t in texts] + _sweep_sets(sweep, names)
    s = _scene(scene, radius, up, field)
    own_source = scene is not None
    if isinstance(positions, (str, bytes, os.PathLike)):
        _source(s, positions, frames)
        positions, own_source = None, True
    elif frames is not None:
        raise ValueError("frames: give positions as a frame pattern ('f_{}.vtk')")
    given = _frames(positions, colors)
    if not given and not own_source:
        raise ValueError("positions: give particles, or scene= a scene file with its own particle source")
    if width is not None or height is not None or scene is None:
        _view(s, width or 512, height or 512, camera)
    elif camera is not None:
        raise ValueError("camera: give width and height with it")
    c_sets, nsets, _keep = _c_settings(sets)
    c_refs, nrefs, _keep_refs = _c_settings(refs)
    handles = ffi.new("fluidsurf_particles *[]", [f.handle for f in given]) if given else ffi.NULL
    flags = (lib.FLUIDSURF_STUDY_COUNTERS if counters else 0) | (lib.FLUIDSURF_STUDY_FORCE if force else 0)
    made = ffi.new("fluidsurf_study **")
    if out is None:
        _check(lib.fluidsurf_compare(s, handles, len(given), ",".join(methods).encode(), c_sets, nsets, c_refs, nrefs,
                                     int(repeat), flags, made))
    else:
        _check(lib.fluidsurf_compare_to_dir(s, handles, len(given), ",".join(methods).encode(), c_sets, nsets, c_refs,
                                            nrefs, int(repeat), flags, os.fspath(out).encode(), made))
    study = ffi.gc(made[0], lib.fluidsurf_study_free)
    texts = {}
    for name in ("metrics", "timings", "temporal", "counters"):
        t = lib.fluidsurf_study_table(study, name.encode())
        if t != ffi.NULL:
            texts[name] = _text(t)
    if "r_source=estimated" in texts["metrics"].splitlines()[0]:
        warnings.warn(f"no radius given: r estimated from the particle spacing ({_R_ESTIMATED_CAVEAT})", stacklevel=2)
    result = {name: _frame_table(_table(t)) for name, t in texts.items()}
    return result if tables else result["metrics"]


def _frame_table(rows):
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows)


def _splashsurf_params(params):
    """params with splashsurf's names as ours: {'cube_size': 1.5} is {'cube': 1.5}."""
    if not isinstance(params, dict):
        return params
    out = {}
    for key, value in params.items():
        method, _, name = key.rpartition(".") if isinstance(key, str) else ("", "", key)
        ours = _SPLASHSURF_PARAMS.get(name, name)
        k = f"{method}.{ours}" if method else ours
        if k in out:
            raise ValueError(f"params: {key!r} and {k!r} are one parameter: give one of them")
        out[k] = value
    return out


def mesh(positions, radius=None, params=None, scene=None, field=None):
    """The surface of positions (N x 3) as a triangle mesh, as `fluidsurf mesh`
    makes it: marching cubes of the scene's field (the mesh method,
    methods/mesh/README.md), without rendering. Returns a Mesh (vertices,
    faces, normals), which unpacks as pysplashsurf's triple: N x 3 float32 in
    scene units, M x 3 int64 vertex indices wound counter-clockwise seen from
    outside, N x 3 float32 unit outward normals (the field's gradient; with
    smooth=weighted splashsurf's smoothed face normals); its .provenance is what
    write_mesh() writes into the file.
    radius (splashsurf's particle_radius), field and scene as render() (a mesh
    has no up). params: {parameter: value} of the method mesh: cube, the voxel
    size in r (splashsurf's cube_size, accepted by that name: splashsurf's
    README uses 1.5); smooth ('laplacian', 'taubin', or 'weighted':
    splashsurf's weighted smoothing) and smooth_iters; field ('isotropic',
    'anisotropic', 'zhu_bridson'); ... (methods() lists them all).
    field={'support': H in r} is the kernel's compact support: splashsurf's
    smoothing length is half of it (its -l=2 is our support 4, the default;
    field={'smoothing_length': 2} says the same); field={'iso': 0.6} is
    splashsurf's iso-surface threshold (also field={'iso_surface_threshold': 0.6}).
    Unlike splashsurf, faces that smoothing leaves with no area are collapsed
    (pieces shrunk to a point or a line are removed) and a normal that comes
    out of length 0 is taken from its faces or the field's gradient, so every
    normal is unit and every face has an area (methods/mesh/README.md,
    "Deviations"). Every argument is checked before the mesh is built
    (ValueError naming it). A library built without OpenVDB refuses
    (ValueError naming the option)."""
    # without OpenVDB the method is not registered: the library's refusal says why
    settings = _settings("mesh", _splashsurf_params(params)) if "mesh" in _registry() else []
    p = _Particles(positions)
    s = _scene(scene, radius, None, field)
    if radius is None and scene is None:  # arrays carry no r: the library estimates it
        warnings.warn(f"no radius given: r estimated from the particle spacing ({_R_ESTIMATED_CAVEAT})", stacklevel=2)
    arr, n, _keep = _c_settings(settings)
    out = ffi.new("fluidsurf_mesh **")
    _check(lib.fluidsurf_mesh_build(s, p.handle, arr, n, out))
    return mesh_result(ffi.gc(out[0], lib.fluidsurf_mesh_free))
