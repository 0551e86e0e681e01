"""fluidsurf: surfaces of particle fluids rendered by published methods, with an
exact reference and metrics, from NumPy arrays (docs/DESIGN.md, "The library").

    import fluidsurf
    out = fluidsurf.render(positions, 0.025, method="raycast_pca", width=256, height=256)
    out["depth"], out["normal"], out["rgb"], out["timings"]
    vertices, faces, normals = fluidsurf.mesh(positions, 0.025)

A thin layer over libfluidsurf.so (include/fluidsurf/fluidsurf.h) through cffi's
ABI mode: the C declarations are read from the header installed beside this
file, and every call into the library releases the GIL. Set FLUIDSURF_LIBRARY to
load another build of the library."""
import copy
import errno
import functools
import os
import warnings

import numpy as np
from cffi import FFI

from . import _arrays, _paths

__all__ = ["Error", "read_particles", "read_gbuffer", "render", "compare", "mesh", "metrics", "methods", "version"]

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


def _check(rc):
    if rc != lib.FLUIDSURF_OK:
        msg = ffi.string(lib.fluidsurf_last_error()).decode("utf-8", "replace")
        raise (ValueError if rc == lib.FLUIDSURF_ERR_INPUT else Error)(msg)


def _text(ptr):
    return ffi.string(ptr).decode("utf-8", "replace") if ptr != ffi.NULL else None


def version():
    """'0.1.0 (commit ...)' of the loaded library."""
    return _text(lib.fluidsurf_version())


def _path(path, name):
    """path for the library, as bytes; FileNotFoundError naming the argument when
    nothing is there (the library would say ValueError, as for a bad file)."""
    p = os.fspath(path)
    if not os.path.exists(p):
        raise FileNotFoundError(errno.ENOENT, f"{name}: no such file", os.fsdecode(p))
    return os.fsencode(p)


# ---- particles --------------------------------------------------------------

class _Particles:
    """A libfluidsurf particle set over NumPy columns; keeps them alive."""

    def __init__(self, positions, colors=None):
        x, y, z, self.copied = _arrays.positions_columns(positions)
        self._keep = [x, y, z]
        out = ffi.new("fluidsurf_particles **")
        _check(lib.fluidsurf_particles_wrap(len(x), *(ffi.from_buffer("float[]", c) for c in (x, y, z)), out))
        self.handle = ffi.gc(out[0], lib.fluidsurf_particles_free)
        if colors is not None:
            c = _arrays.colors_array(colors, len(x))
            self._keep.append(c)
            _check(lib.fluidsurf_particles_set_color(self.handle, ffi.from_buffer("float[]", c)))

    def column(self, name):
        """The address libfluidsurf reads column name from (zero-copy checks)."""
        return int(ffi.cast("uintptr_t", lib.fluidsurf_particles_column(self.handle, name.encode(), ffi.NULL)))


def read_particles(path, format=None):
    """A particle file as a dict: 'positions' (N x 3 float32) and the attributes
    it holds: 'velocity' (N x 3), 'color' (N x 3 linear RGB), 'phase' (N int32),
    'radius' (when the file stores one)."""
    out = ffi.new("fluidsurf_particles **")
    _check(lib.fluidsurf_particles_read(_path(path, "path"), format.encode() if format else ffi.NULL, out))
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
    return result


# ---- scenes -----------------------------------------------------------------

_FIELD_KEYS = ("volume_scale", "iso", "support", "kernel")


def _scene(scene, radius, up=None, field=None):
    """A scene: the file's (scene=) or the defaults, with the caller's r, up axis
    ("auto", "x", "y", "z") and field settings ({volume_scale, iso, support, kernel})."""
    out = ffi.new("fluidsurf_scene **")
    if scene is None:
        _check(lib.fluidsurf_scene_new(out))
    else:
        _check(lib.fluidsurf_scene_load(_path(scene, "scene"), out))
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


def _set_field(s, field):
    """field= over the scene's field; r stays as it was settled (radius=, the scene's, or unset)."""
    unknown = sorted(set(field) - set(_FIELD_KEYS))
    if unknown:
        raise ValueError(f"field: unknown key(s) {', '.join(map(repr, unknown))}; expected {', '.join(_FIELD_KEYS)}")
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


def _warn_estimated(prov):
    """Python's form of the command line's note: r came from the spacing, not the caller."""
    if prov.get("fluidsurf:r_source") == "estimated":
        warnings.warn(f"no radius given: r = {float(prov['fluidsurf:r']):.6g} estimated from the particle spacing "
                      "(a few percent low on compressed SPH output; pass radius=)", stacklevel=3)


def _view(s, width, height, camera):
    """The image size and, when given, the camera of scene s."""
    _check(lib.fluidsurf_scene_set_size(s, _arrays.size(width, "width"), _arrays.size(height, "height")))
    if camera is not None:
        _check(lib.fluidsurf_scene_set_camera(s, _camera(camera, width, height)))
    return s


def _camera(camera, width, height):
    if not isinstance(camera, dict) or "eye" not in camera or "target" not in camera:
        raise ValueError("camera: expected a dict with 'eye' and 'target' (and optionally 'up', 'fov')")
    unknown = set(camera) - {"eye", "target", "up", "fov"}
    if unknown:
        raise ValueError(f"camera: unknown keys {sorted(unknown)}")
    c = ffi.new("fluidsurf_camera *")
    c.eye = _arrays.vector3(camera["eye"], "camera['eye']")
    c.target = _arrays.vector3(camera["target"], "camera['target']")
    c.up = _arrays.vector3(camera.get("up", (0, 1, 0)), "camera['up']")
    c.fov_deg = _arrays.positive(camera.get("fov", 40), "camera['fov']")
    c.width, c.height = width, height
    return c


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


# ---- images -----------------------------------------------------------------

def _provenance(im):
    return {_text(lib.fluidsurf_image_provenance_name(im, i)): _text(lib.fluidsurf_image_provenance_value(im, i))
            for i in range(lib.fluidsurf_image_provenance_count(im))}


def _image_dict(im):
    """A libfluidsurf image as arrays: the G-buffer, rgb, AOVs, timings, provenance."""
    w, h = lib.fluidsurf_image_width(im), lib.fluidsurf_image_height(im)
    ncomp = ffi.new("int *")

    def layer(name):
        ptr = lib.fluidsurf_image_layer(im, name.encode(), ncomp)
        return None if ptr == ffi.NULL else _arrays.layer(ffi, ptr, w, h, ncomp[0])

    d = {name: layer(name) for name in ("depth", "normal", "thickness", "coverage")}
    rgba = layer("rgba")
    if rgba is not None:
        d["rgb"], d["alpha"] = rgba[..., :3].copy(), rgba[..., 3].copy()
    for i in range(lib.fluidsurf_image_aov_count(im)):
        name = _text(lib.fluidsurf_image_aov_name(im, i))
        d[name] = layer(name)
    d["timings"] = [{"stage": _text(lib.fluidsurf_image_stage_name(im, i)),
                     "ms": lib.fluidsurf_image_stage_ms(im, i),
                     "renderer": _text(lib.fluidsurf_image_stage_renderer(im, i))}
                    for i in range(lib.fluidsurf_image_stage_count(im))]
    d["provenance"] = _provenance(im)
    d["radius"] = lib.fluidsurf_image_radius(im)
    cam = ffi.new("fluidsurf_camera *")
    if lib.fluidsurf_image_camera(im, cam) == lib.FLUIDSURF_OK:
        d["camera"] = {"eye": list(cam.eye), "target": list(cam.target), "up": list(cam.up), "fov": cam.fov_deg}
    return d


def _c_settings(texts):
    """("char *[]" or NULL, its count, the strings to keep alive) of "param=value" texts."""
    keep = [ffi.new("char[]", t.encode()) for t in texts]
    return (ffi.new("char *[]", keep) if keep else ffi.NULL), len(keep), keep


def _render_handle(scene, particles, method, settings):
    """An image handle: method on particles, with its checked "param=value" settings."""
    arr, n, _keep = _c_settings(settings)
    out = ffi.new("fluidsurf_image **")
    _check(lib.fluidsurf_render(scene, particles.handle, method.encode(), arr, n, out))
    return ffi.gc(out[0], lib.fluidsurf_image_free)


def render(positions, radius=None, method="raycast_pca", width=512, height=512, camera=None, params=None,
           scene=None, colors=None, up=None, field=None):
    """Renders positions (N x 3, float32 or float64, any order) with one method.

    radius: r (None: the scene's, else the r the spacing implies, as the command
    line estimates, with a UserWarning saying so; provenance['r_source'] tells);
    up: 'auto' (the default without scene=: the particles decide, as the command
    line's --up auto; provenance['up'] says which), 'x', 'y' or 'z';
    field: {'volume_scale', 'iso', 'support', 'kernel'} over the scene's;
    camera: {'eye', 'target', 'up', 'fov'} (None: frames the particles as the
    command line does); params: {parameter: value} (or {'method.parameter':
    value}) of the method, values of the types methods() gives (an enum's name,
    True/False); scene: a scene file whose field, light and settings to use;
    colors: N x 3 linear RGB. A missing file raises FileNotFoundError; an unknown
    method or parameter, or a bad value, ValueError naming it.
    Returns a dict of H x W float32 arrays 'depth' (inf where empty), 'normal'
    (view space), 'thickness', 'coverage', 'rgb' (linear, the shared shading),
    'alpha', the method's AOVs by name, and 'timings', 'provenance', 'radius'
    and 'camera' (the framing chosen: pass it on to keep a sequence's view)."""
    method = _method(method, "method")
    settings = _settings(method, params)
    p = _Particles(positions, colors)
    s = _view(_scene(scene, radius, up, field), width, height, camera)
    image = _image_dict(_render_handle(s, p, method, settings))
    _warn_estimated(image["provenance"])
    return image


def read_gbuffer(path):
    """A G-buffer EXR that fluidsurf wrote (render -o OUT.exr, compare), as render's dict."""
    out = ffi.new("fluidsurf_image **")
    _check(lib.fluidsurf_image_read(_path(path, "path"), out))
    return _image_dict(ffi.gc(out[0], lib.fluidsurf_image_free))


def _metrics_dict(m, d):
    names = ("mask_iou", "depth_bias_r", "depth_rmse_r", "depth_p95_r", "normal_mean_deg", "normal_p95_deg",
             "interior_normal_mean_deg", "psnr_db", "ssim", "n_both", "n_union", "n_interior")
    depth = ("depth_median_r", "depth_abs_p50_r", "depth_abs_p95_r", "depth_abs_p99_r", "depth_over_1r_frac")
    return {**{k: getattr(m, k) for k in names}, **{k: getattr(d, k) for k in depth}}


def _metrics(image, reference, radius):
    """fluidsurf_metrics_compute2 of two image handles, as a dict."""
    m, d = ffi.new("fluidsurf_metrics *"), ffi.new("fluidsurf_depth_metrics *")
    _check(lib.fluidsurf_metrics_compute2(image, reference, radius, m, d))
    return _metrics_dict(m, d)


def _image_from_dict(d, name):
    if not isinstance(d, dict) or "depth" not in d:
        raise ValueError(f"{name}: expected a dict as render() returns")
    depth = np.ascontiguousarray(d["depth"], dtype=np.float32)
    if depth.ndim != 2:
        raise ValueError(f"{name}['depth']: expected an H x W array, got shape {depth.shape}")
    h, w = depth.shape
    normal = _arrays.image_array(d.get("normal"), (h, w, 3), f"{name}['normal']")
    coverage = _arrays.image_array(d.get("coverage"), (h, w), f"{name}['coverage']")
    thickness = _arrays.image_array(d.get("thickness"), (h, w), f"{name}['thickness']", required=False)
    rgba = None
    if d.get("rgb") is not None:
        rgb = _arrays.image_array(d["rgb"], (h, w, 3), f"{name}['rgb']")
        alpha = _arrays.image_array(d.get("alpha", np.ones((h, w))), (h, w), f"{name}['alpha']")
        rgba = np.ascontiguousarray(np.dstack([rgb, alpha]), dtype=np.float32)
    keep = [depth, normal, coverage, thickness, rgba]
    ptr = [ffi.from_buffer("float[]", a) if a is not None else ffi.NULL for a in keep]
    out = ffi.new("fluidsurf_image **")
    _check(lib.fluidsurf_image_from_arrays(w, h, ptr[0], ptr[1], ptr[3], ptr[2], ptr[4], float(d.get("radius") or 0), out))
    im = ffi.gc(out[0], lib.fluidsurf_image_free)
    solids = _arrays.image_array(d.get("solid_depth"), (h, w), f"{name}['solid_depth']", required=False)
    if solids is not None:  # a render in a scene with solids: metrics leave out what they hide
        _check(lib.fluidsurf_image_set_solid_depth(im, ffi.from_buffer("float[]", solids)))
    return im


def metrics(image, reference, radius=None):
    """The metrics of image against reference (dicts as render() returns, the
    same size): IoU; depth bias, RMSE and p95 around the bias (in r); the depth
    error's median, the 50th/95th/99th percentiles of its magnitude and the share
    of pixels over 1 r, which a few far outliers do not move; normal error in
    degrees, PSNR, SSIM (docs/DESIGN.md, "Metrics"). Where a dict carries
    "solid_depth" (render() in a scene with solids), the pixels a solid hides are
    left out, as compare leaves them out."""
    a, b = _image_from_dict(image, "image"), _image_from_dict(reference, "reference")
    return _metrics(a, b, 0 if radius is None else _arrays.positive(radius, "radius"))


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
            repeat=3, counters=False, tables=False, out=None, force=False):
    """Each method variant against the reference on a particle set or a sequence,
    through the engine of `fluidsurf compare` (common/study, fluidsurf_compare):
    the same metrics, the same timing protocol (a warm-up, then `repeat` timed
    renders, their median as frame_ms), the same tables.
    positions: an N x 3 array, a list of them (a sequence), or None with scene=
    (the scene file's own particle source, as `fluidsurf compare s.json`).
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
    frames = _frames(positions, colors)
    if not frames and scene is None:
        raise ValueError("positions: give particles, or scene= a scene file with its own particle source")
    s = _scene(scene, radius, up, field)
    if width is not None or height is not None or scene is None:
        _view(s, width or 512, height or 512, camera)
    elif camera is not None:
        raise ValueError("camera: give width and height with it")
    c_sets, nsets, _keep = _c_settings(sets)
    c_refs, nrefs, _keep_refs = _c_settings(refs)
    handles = ffi.new("fluidsurf_particles *[]", [f.handle for f in frames]) if frames else ffi.NULL
    flags = (lib.FLUIDSURF_STUDY_COUNTERS if counters else 0) | (lib.FLUIDSURF_STUDY_FORCE if force else 0)
    made = ffi.new("fluidsurf_study **")
    if out is None:
        _check(lib.fluidsurf_compare(s, handles, len(frames), ",".join(methods).encode(), c_sets, nsets, c_refs, nrefs,
                                     int(repeat), flags, made))
    else:
        _check(lib.fluidsurf_compare_to_dir(s, handles, len(frames), ",".join(methods).encode(), c_sets, nsets, c_refs,
                                            nrefs, int(repeat), flags, os.fspath(out).encode(), made))
    study = ffi.gc(made[0], lib.fluidsurf_study_free)
    texts = {}
    for name in ("metrics", "timings", "temporal", "counters"):
        t = lib.fluidsurf_study_table(study, name.encode())
        if t != ffi.NULL:
            texts[name] = _text(t)
    if "r_source=estimated" in texts["metrics"].splitlines()[0]:
        warnings.warn("no radius given: r estimated from the particle spacing (a few percent low on compressed SPH "
                      "output; pass radius=)", stacklevel=2)
    result = {name: _frame_table(_table(t)) for name, t in texts.items()}
    return result if tables else result["metrics"]


def _frame_table(rows):
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows)


def mesh(positions, radius=None, params=None, scene=None, field=None):
    """The surface of positions (N x 3) as a triangle mesh, as `fluidsurf mesh`
    makes it: marching cubes of the scene's field (the mesh method,
    methods/mesh/README.md), without rendering. Returns (vertices, faces,
    normals): N x 3 float32 in scene units, M x 3 int64 vertex indices wound
    counter-clockwise seen from outside, N x 3 float32 unit outward normals (the
    field's gradient; with smooth=weighted splashsurf's smoothed face normals),
    as pysplashsurf's reconstruction gives them. radius, field and scene as
    render() (a mesh has no up); params: {parameter: value} of the method mesh
    (cube, the voxel size in r; smooth; smooth_iters; field; ...).
    Unlike splashsurf, faces that smoothing leaves with no area are collapsed
    (pieces shrunk to a point or a line are removed) and a normal that comes
    out of length 0 is taken from its faces or the field's gradient, so every
    normal is unit and every face has an area (methods/mesh/README.md,
    "Deviations").
    A library built without OpenVDB refuses (ValueError naming the option)."""
    # without OpenVDB the method is not registered: the library's refusal says why
    settings = _settings("mesh", params) if "mesh" in _registry() else []
    p = _Particles(positions)
    s = _scene(scene, radius, None, field)
    if radius is None and scene is None:  # arrays carry no r: the library estimates it
        warnings.warn("no radius given: r estimated from the particle spacing (a few percent low on compressed "
                      "SPH output; pass radius=)", stacklevel=2)
    arr, n, _keep = _c_settings(settings)
    out = ffi.new("fluidsurf_mesh **")
    _check(lib.fluidsurf_mesh_build(s, p.handle, arr, n, out))
    m = ffi.gc(out[0], lib.fluidsurf_mesh_free)
    nv, nt = lib.fluidsurf_mesh_vertex_count(m), lib.fluidsurf_mesh_triangle_count(m)
    vertices = _arrays.rows(ffi, lib.fluidsurf_mesh_vertices(m), nv, np.float32)
    normals = _arrays.rows(ffi, lib.fluidsurf_mesh_normals(m), nv, np.float32)
    faces = _arrays.rows(ffi, lib.fluidsurf_mesh_triangles(m), nt, np.uint32).astype(np.int64)
    return vertices, faces, normals
