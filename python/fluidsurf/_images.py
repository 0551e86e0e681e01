"""G-buffers as dicts of NumPy arrays: rendered, read from EXRs, made from the
caller's arrays, written, and measured against each other."""
import warnings

import numpy as np

from . import _arrays
from ._lib import check, existing_path, ffi, lib, output_path, provenance_pairs, text

# The keys of an image dict that are not its extra layers (AOVs).
_NOT_LAYERS = {"depth", "normal", "thickness", "coverage", "rgb", "alpha", "timings", "provenance", "radius",
               "r_source", "camera", "width", "height"}


def _provenance(im):
    return {text(lib.fluidsurf_image_provenance_name(im, i)): text(lib.fluidsurf_image_provenance_value(im, i))
            for i in range(lib.fluidsurf_image_provenance_count(im))}


def _camera_dict(im):
    """The camera of im in render()'s camera= form, None when it has none."""
    cam = ffi.new("fluidsurf_camera *")
    if lib.fluidsurf_image_camera(im, cam) != lib.FLUIDSURF_OK:
        return None
    return {"eye": list(cam.eye), "target": list(cam.target), "up": list(cam.up), "fov": cam.fov_deg}


def image_dict(im):
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
        name = text(lib.fluidsurf_image_aov_name(im, i))
        d[name] = layer(name)
    d["timings"] = [{"stage": text(lib.fluidsurf_image_stage_name(im, i)),
                     "ms": lib.fluidsurf_image_stage_ms(im, i),
                     "renderer": text(lib.fluidsurf_image_stage_renderer(im, i))}
                    for i in range(lib.fluidsurf_image_stage_count(im))]
    d["provenance"] = _provenance(im)
    d["width"], d["height"] = w, h
    d["radius"] = lib.fluidsurf_image_radius(im)
    d["r_source"] = d["provenance"].get("fluidsurf:r_source")
    camera = _camera_dict(im)
    if camera is not None:
        d["camera"] = camera
    return d


def read_gbuffer(path):
    """A G-buffer EXR that fluidsurf wrote (render -o OUT.exr, compare,
    write_image) as render()'s dict, with everything the file holds: the layers
    (depth, normal, thickness, coverage, rgb, alpha, the method's AOVs, and
    'solid_depth' where solids hide the fluid), 'width' and 'height', 'radius'
    (fluidsurf:r) and 'r_source' ('option', 'file', 'estimated', ...),
    'provenance' ({'fluidsurf:NAME': text} of every attribute) and 'camera' in
    render()'s camera= form, so that render(positions, radius=g['radius'],
    camera=g['camera'], width=g['width'], height=g['height'], method=...)
    renders the same image again. A file without fluidsurf:camera gives no
    'camera'; 'timings' is empty (a file has none)."""
    out = ffi.new("fluidsurf_image **")
    check(lib.fluidsurf_image_read(existing_path(path, "path"), out))
    return image_dict(ffi.gc(out[0], lib.fluidsurf_image_free))


def _extra_layers(d, h, w, name):
    """The dict's other H x W or H x W x 4 arrays (the AOVs), checked."""
    layers = {}
    for key, value in d.items():
        if key in _NOT_LAYERS or not isinstance(value, np.ndarray):
            continue
        a = np.ascontiguousarray(value, dtype=np.float32)
        if a.shape not in ((h, w), (h, w, 4)):
            raise ValueError(f"{name}[{key!r}]: a layer is H x W or H x W x 4 ({h}, {w}), got shape {a.shape}")
        layers[key] = a
    return layers


def _core_arrays(d, name):
    """The dict's core layers checked: (h, w, depth, normal, coverage, thickness, rgba)."""
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
    return h, w, depth, normal, coverage, thickness, rgba


def image_from_dict(d, name, all_layers=False):
    """An image handle of a dict as render() returns (or the caller's own arrays):
    its core layers, 'solid_depth' (all_layers: every other H x W (x 4) array),
    its provenance and r."""
    h, w, *core = _core_arrays(d, name)
    depth, normal, coverage, thickness, rgba = core
    layers = _extra_layers(d, h, w, name) if all_layers else {}
    solids = _arrays.image_array(d.get("solid_depth"), (h, w), f"{name}['solid_depth']", required=False)
    if solids is not None:  # a render in a scene with solids: metrics leave out what they hide
        layers["solid_depth"] = solids
    r = d.get("radius")
    radius = 0.0 if r is None or r == 0 else _arrays.positive(r, f"{name}['radius']")  # 0: none (a file without r)
    pairs = provenance_pairs(d.get("provenance"), f"{name}['provenance']")
    ptr = [ffi.from_buffer("float[]", a) if a is not None else ffi.NULL for a in core]
    out = ffi.new("fluidsurf_image **")
    check(lib.fluidsurf_image_from_arrays(w, h, ptr[0], ptr[1], ptr[3], ptr[2], ptr[4], radius, out))
    im = ffi.gc(out[0], lib.fluidsurf_image_free)
    for key, a in layers.items():
        ncomp = 1 if a.ndim == 2 else 4
        check(lib.fluidsurf_image_set_layer(im, key.encode(), ncomp, ffi.from_buffer("float[]", a)))
    for k, v in pairs:
        check(lib.fluidsurf_image_set_provenance(im, k, v))
    return im


def write_image(image, path):
    """Writes image (a dict as render() or read_gbuffer() returns) as
    `fluidsurf render -o` writes it, by the extension: .png, the shaded 'rgb'
    (and 'alpha') as sRGB; .exr, RGBA, the G-buffer, every other H x W or
    H x W x 4 array of the dict as a layer by its key, and the provenance as
    attributes ('radius' as fluidsurf:r when the provenance has none), which
    read_gbuffer() and `fluidsurf diff` read back. Atomic: a failure leaves no
    file and no old one replaced. ValueError for another extension, an image
    without 'rgb', or arrays of the wrong shape."""
    p = output_path(path, "path", (".png", ".exr"))
    d = dict(image) if isinstance(image, dict) else image
    if isinstance(d, dict) and d.get("radius") and "fluidsurf:r" not in (d.get("provenance") or {}):
        d["provenance"] = {**(d.get("provenance") or {}), "fluidsurf:r": f"{float(d['radius']):.9g}"}
    im = image_from_dict(d, "image", all_layers=True)
    check(lib.fluidsurf_image_write(im, p))


def _metrics_dict(m, d):
    names = ("mask_iou", "depth_bias_r", "depth_rmse_r", "depth_p95_r", "normal_mean_deg", "normal_p95_deg",
             "interior_normal_mean_deg", "psnr_db", "ssim", "n_both", "n_union", "n_interior")
    depth = ("depth_median_r", "depth_abs_p50_r", "depth_abs_p95_r", "depth_abs_p99_r", "depth_over_1r_frac")
    return {**{k: getattr(m, k) for k in names}, **{k: getattr(d, k) for k in depth}}


def metrics(image, reference, radius=None, strict=False):
    """The metrics of image against reference (dicts as render() and
    read_gbuffer() return, or of your own arrays): IoU; depth bias, RMSE and p95
    around the bias (in r); the depth error's median, the 50th/95th/99th
    percentiles of its magnitude and the share of pixels over 1 r, which a few
    far outliers do not move; normal error in degrees, PSNR, SSIM
    (docs/DESIGN.md, "Metrics"). Where a dict carries "solid_depth" (render() in
    a scene with solids), the pixels a solid hides are left out, as compare
    leaves them out.
    The images must be comparable, by `fluidsurf diff`'s rule: a different size
    or camera (provenance fluidsurf:camera) raises ValueError with diff's
    words; a different scene (fluidsurf:scene_hash) or r warns (UserWarning),
    or with strict=True raises ValueError, as `diff --strict`. Only what both
    dicts carry is checked: your own arrays without 'provenance' pass."""
    if not isinstance(strict, (bool, np.bool_)):
        raise ValueError(f"strict: expected True or False, got {strict!r}")
    a, b = image_from_dict(image, "image"), image_from_dict(reference, "reference")
    r = 0 if radius is None else _arrays.positive(radius, "radius")
    m, d = ffi.new("fluidsurf_metrics *"), ffi.new("fluidsurf_depth_metrics *")
    found = ffi.new("char[]", 2048)
    flags = lib.FLUIDSURF_METRICS_STRICT if strict else 0
    check(lib.fluidsurf_metrics_compute3(a, b, r, flags, m, d, found, len(found)))
    for line in text(found).splitlines():
        warnings.warn(line, UserWarning, stacklevel=2)
    return _metrics_dict(m, d)
