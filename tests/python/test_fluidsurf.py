"""The Python module against the real library and the real command line
(tests/python.cmake runs it on the installed prefix). FS_BIN: the fluidsurf
binary; FS_SRC: the source tree."""
import os
import re
import resource
import struct
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import fluidsurf

SRC = os.environ["FS_SRC"]
BIN = os.environ["FS_BIN"]
DAM = os.path.join(SRC, "experiments/data/splashsurf/dam_break_frame_23_24389_particles.ply")
BGEO = os.path.join(SRC, "experiments/data/splashsurf/dam_break_frame_9_6859_particles.bgeo")
CROP = os.path.join(SRC, "experiments/data/dualsphysics/dambreak200k_t0.300_crop902.vtk")
R = 0.025
SIZE = 128


@pytest.fixture(scope="module")
def dam():
    return fluidsurf.read_particles(DAM)["positions"]


def cli_render(tmp_path, method):
    out = tmp_path / f"{method}.exr"
    subprocess.run([BIN, "render", DAM, "--method", method, "--radius", str(R), "-W", str(SIZE), "-H", str(SIZE),
                    "-o", str(out), "-q"], check=True)
    return fluidsurf.read_gbuffer(out)


@pytest.mark.parametrize("method", ["raycast_pca", "reference"])
def test_render_equals_cli_exr(tmp_path, dam, method):
    py = fluidsurf.render(dam, R, method=method, width=SIZE, height=SIZE)
    cli = cli_render(tmp_path, method)
    for name in ("depth", "normal", "thickness", "coverage"):
        assert py[name].shape == cli[name].shape, name
        np.testing.assert_array_equal(py[name], cli[name], err_msg=name)
    assert py["coverage"].sum() > 1000  # the dam break fills much of the frame
    m = fluidsurf.metrics(py, cli, radius=R)
    assert m["mask_iou"] == 1.0
    assert m["depth_rmse_r"] == 0.0 and m["depth_bias_r"] == 0.0
    assert m["normal_mean_deg"] == 0.0 and m["normal_p95_deg"] == 0.0
    np.testing.assert_allclose(py["rgb"], cli["rgb"], atol=1e-6)
    assert py["provenance"]["fluidsurf:method"] == method
    assert {t["stage"] for t in py["timings"]} >= {"grid", "shade"}
    # the framing chosen, handed back, renders the same view
    again = fluidsurf.render(dam, R, method=method, width=SIZE, height=SIZE, camera=py["camera"])
    np.testing.assert_array_equal(again["depth"], py["depth"])
    assert cli["camera"] == py["camera"]  # the EXR's fluidsurf:camera, read back exactly


def test_zero_copy_layouts_render_alike(dam):
    f32 = np.asfortranarray(dam, dtype=np.float32)
    p = fluidsurf._Particles(f32)
    assert not p.copied
    for k, axis in enumerate("xyz"):
        assert p.column(axis) == f32[:, k].ctypes.data  # the library reads the caller's memory
    assert fluidsurf._Particles(np.ascontiguousarray(dam)).copied
    assert fluidsurf._Particles(dam.astype(np.float64, order="F")).copied
    ref = fluidsurf.render(f32, R, method="spheres", width=64, height=64)
    for layout in (np.ascontiguousarray(dam), dam.astype(np.float64), dam.astype(np.float64, order="F")):
        out = fluidsurf.render(layout, R, method="spheres", width=64, height=64)
        np.testing.assert_array_equal(out["depth"], ref["depth"])
    # zero-copy means live: the caller's edit is what the next render sees
    f32[:, 0] += 100.0
    moved = fluidsurf.render(f32, R, method="spheres", width=64, height=64,
                             camera={"eye": [0, 1, 5], "target": [0, 1, 0]})
    assert moved["coverage"].sum() == 0


def test_read_particles_attributes():
    d = fluidsurf.read_particles(BGEO)
    assert d["positions"].shape == (6859, 3) and d["positions"].dtype == np.float32
    assert np.isfinite(d["positions"]).all()
    ply = fluidsurf.read_particles(DAM)
    assert ply["positions"].shape == (24389, 3) and ply["velocity"].shape == (24389, 3)
    assert "arrays" not in ply
    crop = fluidsurf.read_particles(CROP)  # the file's other point arrays, as `fluidsurf info` lists them
    assert list(crop["arrays"]) == ["Idp", "Rhop"]
    idp, rhop = crop["arrays"]["Idp"], crop["arrays"]["Rhop"]
    assert idp.dtype == np.uint32 and idp.shape == (902,) and len(np.unique(idp)) == 902
    assert rhop.dtype == np.float32 and rhop.shape == (902,) and ((rhop >= 853) & (rhop <= 1087)).all()


def test_methods_and_compare(dam):
    ms = {m["name"]: m for m in fluidsurf.methods()}
    assert {"reference", "raycast_pca", "aniso_ssf", "surfels", "spheres"} <= set(ms)
    assert ms["raycast_pca"]["needs_gl"] and not ms["reference"]["needs_gl"]
    pca = {p["name"]: p for p in ms["raycast_pca"]["params"]}
    assert pca["min_neighbors"]["default"] == 10 and pca["normals"]["type"] == "enum"
    rows = fluidsurf.compare(dam, R, methods=["spheres", "raycast_pca"], width=96, height=96,
                             params={"raycast_pca": {"normals": "basic"}})
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert [r["method"] for r in rows] == ["spheres", "raycast_pca"]
    for r in rows:
        assert 0.8 < r["mask_iou"] <= 1 and r["normal_mean_deg"] > 0 and r["frame_ms"] > 0
    # the reference against itself is exact
    ref = fluidsurf.render(dam, R, method="reference", width=96, height=96)
    m = fluidsurf.metrics(ref, ref)
    assert m["mask_iou"] == 1 and m["normal_mean_deg"] == 0 and m["psnr_db"] == float("inf")


def test_depth_metrics_see_through_outliers():
    """Issue 32's constructed case: a plane whose errors spread within 0.004 r,
    with 0.2% of its pixels (5 of 2500) moved 50 r. The bias and depth_p95_r
    (around the bias) read the outliers' pull, 0.1 r; the median, the
    percentiles of |error| and the share over 1 r read the plane."""
    yy, xx = np.mgrid[0:50, 0:50]
    plane = (3 + 0.01 * xx + 0.005 * yy).astype(np.float32)
    err = 0.004 * R * np.sin(1.7 * np.arange(2500)).reshape(50, 50)
    err.flat[250::500] = 50 * R
    moved = (plane + err).astype(np.float32)
    normal = np.zeros((50, 50, 3), np.float32)
    normal[..., 2] = 1
    cov = np.ones((50, 50), np.float32)
    a, b = {"depth": moved, "normal": normal, "coverage": cov}, {"depth": plane, "normal": normal, "coverage": cov}
    m = fluidsurf.metrics(a, b, radius=R)
    assert m["n_both"] == 2500
    assert m["depth_bias_r"] == pytest.approx(0.1, abs=1e-3) and m["depth_p95_r"] == pytest.approx(0.1, abs=5e-3)
    assert abs(m["depth_median_r"]) < 0.005
    assert max(m["depth_abs_p50_r"], m["depth_abs_p95_r"], m["depth_abs_p99_r"]) < 0.005
    assert m["depth_over_1r_frac"] == 0.002
    # nearest rank (the ceil(q n)-th smallest) of e in r as the library computes it, r a float
    e = (moved.astype(np.float64) - plane.astype(np.float64)).ravel() / np.float64(np.float32(R))
    rank = lambda v, q: np.sort(v)[int(np.ceil(q * v.size)) - 1]
    assert m["depth_median_r"] == pytest.approx(rank(e, 0.5), rel=1e-12)
    for q in (50, 95, 99):
        assert m[f"depth_abs_p{q}_r"] == pytest.approx(rank(np.abs(e), q / 100), rel=1e-12), q
    # the version-1 function, kept for programs built against it, fills its own fields alike
    old = fluidsurf.ffi.new("fluidsurf_metrics *")
    ia, ib = fluidsurf._image_from_dict(a, "a"), fluidsurf._image_from_dict(b, "b")
    assert fluidsurf.lib.fluidsurf_metrics_compute(ia, ib, R, old) == 0
    assert old.depth_bias_r == m["depth_bias_r"] and old.depth_p95_r == m["depth_p95_r"]
    assert fluidsurf.lib.fluidsurf_api_version() >= 2


BAD_POSITIONS = [
    (np.zeros((5, 2), np.float32), "N x 3"),
    (np.zeros(9, np.float32), "N x 3"),
    (np.zeros((0, 3), np.float32), "N >= 1"),
    (np.zeros((5, 3), np.int32), "float32 or float64"),
    (np.array([[0, 0, np.nan]] * 4, np.float32), "NaN or infinite"),
    (np.array([[0, 0, 0], [np.inf, 0, 0]], np.float64), "the first in row 1"),
    (np.array([[1e40, 0, 0]], np.float64), "NaN or infinite in float32"),
]


@pytest.mark.parametrize("positions,words", BAD_POSITIONS)
def test_bad_positions(positions, words):
    with pytest.raises(ValueError, match="^positions: .*" + words):
        fluidsurf.render(positions, R, method="spheres", width=16, height=16)


BAD_ARGS = [
    ({"radius": -1}, "^radius: must be positive"),
    ({"radius": float("nan")}, "^radius: must be positive"),
    ({"radius": "big"}, "^radius: expected a number"),
    ({"width": 0}, "^width: expected an integer"),
    ({"height": 2.5}, "^height: expected an integer"),
    ({"width": True}, "^width: expected an integer"),
    ({"method": "nosuch"}, "unknown method 'nosuch'"),
    ({"method": 3}, "^method: expected a method name"),
    ({"params": {"nosuch": 1}}, "nosuch"),
    ({"params": {"min_neighbors": -5}}, "min_neighbors"),
    ({"params": [1, 2]}, "^params: expected a dict"),
    ({"camera": {"eye": [0, 0, 1]}}, "^camera: expected a dict with 'eye' and 'target'"),
    ({"camera": {"eye": [0, 0, np.nan], "target": [0, 0, 0]}}, r"^camera\['eye'\]: expected 3 finite"),
    ({"camera": {"eye": [0, 0], "target": [0, 0, 0]}}, r"^camera\['eye'\]: expected 3 finite"),
    ({"camera": {"eye": [1, 1, 1], "target": [1, 1, 1]}}, "^camera: eye equals target"),
    ({"camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "zoom": 2}}, "^camera: unknown keys"),
    ({"colors": np.zeros((3, 3))}, r"^colors: expected shape \(4, 3\)"),
]


@pytest.mark.parametrize("kwargs,words", BAD_ARGS)
def test_bad_arguments(kwargs, words):
    args = {"radius": R, "method": "raycast_pca", "width": 16, "height": 16, **kwargs}
    with pytest.raises(ValueError, match=words):
        fluidsurf.render(np.random.default_rng(1).random((4, 3), dtype=np.float32), **args)


def test_bad_files_and_images(tmp_path):
    junk = tmp_path / "junk.ply"
    junk.write_bytes(b"ply\nformat nonsense\n")
    with pytest.raises(ValueError, match="junk.ply"):
        fluidsurf.read_particles(junk)
    with pytest.raises(ValueError, match="junk.ply"):
        fluidsurf.read_gbuffer(junk)
    small = fluidsurf.render(np.zeros((1, 3), np.float32), R, method="spheres", width=16, height=16)
    big = fluidsurf.render(np.zeros((1, 3), np.float32), R, method="spheres", width=32, height=16)
    with pytest.raises(ValueError):
        fluidsurf.metrics(small, big)
    with pytest.raises(ValueError, match=r"^image\['normal'\]: expected shape"):
        fluidsurf.metrics({**small, "normal": small["normal"][:, :, :2]}, small)
    with pytest.raises(ValueError, match="^methods: expected a list"):
        fluidsurf.compare(np.zeros((1, 3), np.float32), R, methods="spheres")


def test_gil_released_while_rendering(dam):
    done = threading.Event()

    def work():
        fluidsurf.render(dam, R, method="reference", width=160, height=160)
        done.set()

    t = threading.Thread(target=work)
    start = time.perf_counter()
    t.start()
    ticks = 0
    while not done.is_set():
        ticks += 1  # runs only while the render has let go of the GIL
    t.join()
    assert time.perf_counter() - start > 0.05  # a render long enough to tell
    assert ticks > 10000


def peak_rss_kb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def test_renders_do_not_grow_memory(dam):
    sub = np.asfortranarray(dam[::4])
    for _ in range(5):
        fluidsurf.render(sub, R, method="raycast_pca", width=SIZE, height=SIZE)
    before = peak_rss_kb()
    for _ in range(50):
        fluidsurf.render(sub, R, method="raycast_pca", width=SIZE, height=SIZE)
    grown_mb = (peak_rss_kb() - before) / 1024
    assert grown_mb <= 5, f"peak RSS grew {grown_mb:.1f} MB over 50 renders"


def test_require_gpu_reaches_the_library():
    """FLUIDSURF_REQUIRE_GPU=1 is the library's --require-gpu (its context has no option):
    a GL method on a software renderer is a fluidsurf.Error naming it, a CPU method still
    renders. A fresh interpreter, as the library makes its context once per process;
    OSMesa, as it is llvmpipe on every machine."""
    code = ("import numpy as np, fluidsurf\n"
            "p = np.zeros((1, 3), np.float32)\n"
            "fluidsurf.render(p, 0.025, method='reference', width=16, height=16)\n"
            "try:\n"
            "    fluidsurf.render(p, 0.025, method='spheres', width=16, height=16)\n"
            "except fluidsurf.Error as e:\n"
            "    print(e)\n")
    env = {**os.environ, "FLUIDSURF_REQUIRE_GPU": "1", "FLUIDSURF_GL": "osmesa"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout
    assert re.fullmatch(r"FLUIDSURF_REQUIRE_GPU=1: the OpenGL renderer is llvmpipe.*, a software rasterizer\n", out), out


# ---- issue 32, part 7: Python's own errors, typed methods(), mesh() -------------

def test_missing_files_raise_file_not_found(tmp_path):
    """A path that leads nowhere is FileNotFoundError (an OSError, not a ValueError),
    naming the argument and the path, for every function that takes one."""
    missing = str(tmp_path / "missing.ply")
    p = np.zeros((1, 3), np.float32)
    calls = [
        ("path", lambda: fluidsurf.read_particles(missing)),
        ("path", lambda: fluidsurf.read_gbuffer(missing)),
        ("scene", lambda: fluidsurf.render(p, R, method="spheres", width=16, height=16, scene=missing)),
        ("scene", lambda: fluidsurf.compare(p, R, methods=["spheres"], width=16, height=16, scene=missing)),
        ("scene", lambda: fluidsurf.mesh(p, R, scene=missing)),
    ]
    for arg, call in calls:
        with pytest.raises(FileNotFoundError) as e:
            call()
        assert not isinstance(e.value, ValueError)
        assert e.value.errno == 2 and e.value.filename == missing
        assert str(e.value) == f"[Errno 2] {arg}: no such file: '{missing}'"


P4 = np.random.default_rng(1).random((4, 3), dtype=np.float32)
PCA_PARAMS = "its parameters: splat_radius, step, max_steps, refine, step_back, normals,"
UNKNOWN = [
    # compare's params: a key that is no method of the comparison, a method.param the method lacks
    (lambda: fluidsurf.compare(P4, R, methods=["spheres"], params={"radius_scale": 2}),
     r"^params=\{'radius_scale': 2\}: 'radius_scale' is not a method of this comparison \(spheres, reference\)"),
    (lambda: fluidsurf.compare(P4, R, methods=["raycast_pca"], params={"raycast_pca.normal": "pca"}),
     r"^params=\{'raycast_pca.normal': 'pca'\}: raycast_pca has no parameter 'normal' \(" + PCA_PARAMS),
    (lambda: fluidsurf.compare(P4, R, methods=["raycast_pca"], params={"raycast_pca": {"normal": "pca"}}),
     r"^params=\{'raycast_pca': \{'normal': 'pca'\}\}: raycast_pca has no parameter 'normal' \(" + PCA_PARAMS),
    (lambda: fluidsurf.compare(P4, R, methods=["spheres"], params={"reference.nosuch": 1}),
     r"^params=\{'reference.nosuch': 1\}: reference has no parameter 'nosuch' \(its parameters: step_min,"),
    (lambda: fluidsurf.compare(P4, R, methods=["spheres"], params={"spheres": 2}),
     r"^params=\{'spheres': 2\}: expected a dict of parameter values of spheres"),
    (lambda: fluidsurf.compare(P4, R, methods=["spheres", "nosuch"]),
     r"^methods: unknown method 'nosuch' \(methods: .*reference.*raycast_pca"),
    (lambda: fluidsurf.compare(P4, R, methods=["spheres"], reference="nosuch"),
     r"^reference: unknown method 'nosuch' \(methods: .*reference"),
    # render's params: {parameter: value} or {'method.parameter': value} of its method
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"normal": "pca"}),
     r"^params=\{'normal': 'pca'\}: raycast_pca has no parameter 'normal' \(" + PCA_PARAMS),
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"aniso_ssf.kappa": 4}),
     r"^params=\{'aniso_ssf.kappa': 4\}: 'aniso_ssf' is not the method rendered \('raycast_pca'\)"),
    (lambda: fluidsurf.render(P4, R, method="nosuch"), r"^method: unknown method 'nosuch' \(methods: .*spheres"),
    # values, checked against methods()' types and ranges
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"normals": "zz"}),
     r"^params=\{'normals': 'zz'\}: raycast_pca.normals 'zz': expected one of 'basic', 'pca', 'blend'$"),
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"normals": 1}),
     r"^params=\{'normals': 1\}: raycast_pca.normals 1: expected one of"),
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"min_neighbors": 2.5}),
     r"^params=\{'min_neighbors': 2.5\}: raycast_pca.min_neighbors 2.5: expected an integer$"),
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"min_neighbors": -5}),
     r"^params=\{'min_neighbors': -5\}: raycast_pca.min_neighbors -5: outside \[3, 1000000\]$"),
    (lambda: fluidsurf.render(P4, R, method="raycast_pca", params={"step": "far"}),
     r"^params=\{'step': 'far'\}: raycast_pca.step 'far': expected a number$"),
    (lambda: fluidsurf.render(P4, R, method="spheres", params={"thickness": 2}),
     r"^params=\{'thickness': 2\}: spheres.thickness 2: expected True or False$"),
    (lambda: fluidsurf.mesh(P4, R, params={"nosuch": 1}),
     r"^params=\{'nosuch': 1\}: mesh has no parameter 'nosuch' \(its parameters: cube, smooth,"),
]


@pytest.mark.parametrize("call,words", UNKNOWN)
def test_unknown_methods_parameters_and_values(call, words):
    """Each is refused before any render, naming the argument as Python wrote it
    and what is valid; no message speaks of the command line's flags."""
    with pytest.raises(ValueError, match=words) as e:
        call()
    assert "--" not in str(e.value)


def test_library_messages_name_no_flags():
    """A setting the module does not check (a scene's) reaches the library, which
    refuses it when it is set (settings are parsed once, there) with a message that
    names it as written, lists the valid names and quotes no flag."""
    scene = fluidsurf._scene(None, R)
    assert fluidsurf.lib.fluidsurf_scene_set(scene, b"reference.nosuch=1") == 2  # FLUIDSURF_ERR_INPUT
    msg = fluidsurf.ffi.string(fluidsurf.lib.fluidsurf_last_error()).decode()
    assert msg.startswith("reference.nosuch=1: reference has no parameter 'nosuch' (its parameters: step_min,"), msg
    for bad in (["normals=zz"], ["min_neighbors=-5"]):
        with pytest.raises(ValueError) as e:
            fluidsurf._render_handle(fluidsurf._scene(None, R), fluidsurf._Particles(P4), "raycast_pca", bad)
        assert re.match(r"raycast_pca\.(normals: 'zz' is not one of|min_neighbors: -5 is outside)", str(e.value)), e.value
        assert "--" not in str(e.value)


def test_methods_defaults_are_typed():
    """An enum's default is its name, ints are int, floats float, bools bool; and
    every method's defaults, handed back as params, are accepted as they are."""
    ms = {m["name"]: m for m in fluidsurf.methods()}
    kinds = set()
    for m in ms.values():
        for p in m["params"]:
            kinds.add(p["type"])
            want = {"enum": str, "int": int, "float": float, "bool": bool}[p["type"]]
            assert type(p["default"]) is want, (m["name"], p)
            if p["type"] == "enum":
                assert p["default"] in p["choices"] and p["min"] is None and p["max"] is None
            elif p["type"] in ("int", "float"):
                assert type(p["min"]) is want and type(p["max"]) is want and p["min"] <= p["default"] <= p["max"]
        defaults = {p["name"]: p["default"] for p in m["params"]}
        assert len(fluidsurf._settings(m["name"], defaults)) == len(defaults)
    assert kinds == {"enum", "int", "float", "bool"}
    ref = {p["name"]: p["default"] for p in ms["reference"]["params"]}
    assert ref["interior"] == "auto" and ref["thickness"] is True and ref["max_layers"] == 64 and ref["step_min"] == 0.02
    pca = {p["name"]: p for p in ms["raycast_pca"]["params"]}
    assert pca["normals"]["default"] == "blend" and pca["normals"]["choices"] == ["basic", "pca", "blend"]
    # the defaults given back render what no params render
    p = np.random.default_rng(3).random((300, 3), dtype=np.float32) * 0.3
    plain = fluidsurf.render(p, R, method="reference", width=24, height=24)
    again = fluidsurf.render(p, R, method="reference", width=24, height=24, params=ref)
    np.testing.assert_array_equal(plain["depth"], again["depth"])
    # methods() is a copy: changing it changes nothing
    ms["reference"]["params"].clear()
    assert len({m["name"]: m for m in fluidsurf.methods()}["reference"]["params"]) == len(ref)


def ball(radius_in_r=8):
    """A ball of particles on a lattice of spacing 2r, centred at (1, 2, 3)."""
    k = np.arange(-radius_in_r // 2, radius_in_r // 2 + 1)
    g = np.stack(np.meshgrid(k, k, k, indexing="ij"), axis=-1).reshape(-1, 3) * 2 * R
    return (g[np.linalg.norm(g, axis=1) <= radius_in_r * R * 1.0001] + [1, 2, 3]).astype(np.float32)


def test_mesh_of_a_ball():
    """mesh() is pysplashsurf's triple: a closed mesh around the ball, its faces
    indexing its vertices, its normals unit and outward."""
    centre, outer = np.array([1, 2, 3]), 8 * R
    v, f, n = fluidsurf.mesh(ball(), R)
    assert v.dtype == np.float32 and n.dtype == np.float32 and f.dtype == np.int64
    assert v.ndim == 2 and v.shape[1] == 3 and n.shape == v.shape and f.ndim == 2 and f.shape[1] == 3
    assert len(v) > 100 and len(f) > 100
    assert f.min() >= 0 and f.max() < len(v)
    d = np.linalg.norm(v - centre, axis=1)
    # the iso-surface of a lattice ball lies within r of its outer particles' centres
    assert outer - R < d.min() and d.max() < outer + R, (d.min(), d.max())
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1, atol=1e-5)
    assert (np.sum(n * (v - centre), axis=1) / d > 0.5).all()
    # closed and consistently wound: every directed edge once, its reverse once
    edges = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    key = edges[:, 0] * len(v) + edges[:, 1]
    assert len(np.unique(key)) == len(key)
    assert np.isin(edges[:, 1] * len(v) + edges[:, 0], key).all()
    # the enclosed volume is the ball's (wound outward: positive)
    vol = np.einsum("ij,ij->i", v[f[:, 0]] - centre, np.cross(v[f[:, 1]] - centre, v[f[:, 2]] - centre)).sum() / 6
    assert 4 / 3 * np.pi * (outer - R) ** 3 < vol < 4 / 3 * np.pi * (outer + R) ** 3
    # parameters are the mesh method's: a finer cube gives more vertices
    fine, _, _ = fluidsurf.mesh(ball(), R, params={"cube": 0.25})
    assert len(fine) > 3 * len(v)


def test_mesh_equals_the_command_line(tmp_path):
    """mesh() of a file's positions is `fluidsurf mesh`'s mesh: the same counts."""
    out = subprocess.run([BIN, "mesh", BGEO, "-o", str(tmp_path / "m.ply"), "--radius", str(R), "--timings", "-q"],
                         check=True, capture_output=True, text=True).stdout
    total = [line.split(",") for line in out.splitlines() if ",total," in line]
    v, f, _ = fluidsurf.mesh(fluidsurf.read_particles(BGEO)["positions"], R)
    assert (len(v), len(f)) == (int(total[0][3]), int(total[0][4]))


def test_mesh_smoothed_has_no_degenerate_normal_or_face():
    """splashsurf's recipe on the DualSPHysics crop (issue 53: it left 28 normals of
    (0, 0, 0) and 52 faces of zero area): every normal unit, every face an area."""
    crop = os.path.join(SRC, "experiments/data/dualsphysics/dambreak200k_t0.300_crop902.vtk")
    v, f, n = fluidsurf.mesh(fluidsurf.read_particles(crop)["positions"], 0.00365,
                             params={"smooth": "weighted", "smooth_iters": 25})
    np.testing.assert_allclose(np.linalg.norm(n, axis=1), 1, atol=1e-5)
    area2 = np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1)
    assert len(f) > 20000 and (area2 > 0).all(), (len(f), (area2 == 0).sum())


def _lattice(nx, ny, nz, spacing=0.05):
    """A jittered lattice at spacing 2r, as the command line's tests build."""
    rng = np.random.default_rng(7)
    g = np.stack(np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij"), -1).reshape(-1, 3)
    return (g * spacing + 0.002 * rng.random(g.shape)).astype(np.float32)


def test_up_field_and_estimated_radius_warning(tmp_path):
    pool = _lattice(24, 16, 4)  # thin along z: a z-up pool
    with pytest.warns(UserWarning, match="estimated from the particle spacing"):
        auto = fluidsurf.render(pool, method="reference", width=32, height=24)
    assert auto["provenance"]["fluidsurf:up"] == "z;auto"
    assert auto["provenance"]["fluidsurf:r_source"] == "estimated"
    assert auto["camera"]["up"] == pytest.approx([0, 0, 1], abs=1e-6)
    # the same as the command line on the same particles
    path = tmp_path / "pool.ply"
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(pool)}\nproperty float x\nproperty float y\n"
                "property float z\nend_header\n")
        np.savetxt(f, pool, fmt="%.9g")
    out = tmp_path / "pool.exr"
    subprocess.run([BIN, "render", str(path), "--method", "reference", "-W", "32", "-H", "24", "-o", str(out), "-q"],
                   check=True)
    np.testing.assert_array_equal(fluidsurf.read_gbuffer(out)["depth"], auto["depth"])
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a given r: no warning
        given = fluidsurf.render(pool, 0.025, method="reference", width=32, height=24, up="x",
                                 field={"iso": 0.3, "kernel": "poly6", "support": 3, "volume_scale": 1.2})
    prov = given["provenance"]
    assert prov["fluidsurf:up"] == "x;option" and prov["fluidsurf:r_source"] == "option"
    assert prov["fluidsurf:field"] == "kernel=poly6;support=3r;iso=0.300000012;volume_scale=1.20000005"
    assert float(prov["fluidsurf:r"]) == pytest.approx(0.025)
    # field= alone leaves r to the estimate
    with pytest.warns(UserWarning, match="estimated"):
        iso = fluidsurf.render(pool, method="reference", width=32, height=24, field={"iso": 0.3})
    assert iso["provenance"]["fluidsurf:r_source"] == "estimated"
    assert "iso=0.300000012" in iso["provenance"]["fluidsurf:field"]
    with pytest.warns(UserWarning, match="estimated"):
        fluidsurf.compare(pool, methods=["spheres"], width=32, height=24)
    for bad, words in [({"up": "w"}, "up='w'"), ({"field": {"isovalue": 1}}, "isovalue"),
                       ({"field": {"iso": -1}}, "field['iso']"), ({"field": {"kernel": "gauss"}}, "gauss")]:
        with pytest.raises(ValueError, match=re.escape(words)):
            fluidsurf.render(pool, 0.025, method="reference", width=8, height=8, **bad)


def _csv_rows(path):
    import csv
    with open(path) as f:
        lines = f.read().splitlines()
    return list(csv.DictReader(lines[1:]))


def test_compare_is_the_command_lines(dam, tmp_path):
    """Python's compare() and `fluidsurf compare` run one engine: the same metrics
    to the last digit, and the same timing protocol (repeat runs after a warm-up)."""
    out = tmp_path / "cli"
    subprocess.run([BIN, "compare", DAM, "--radius", str(R), "--methods", "spheres,reference", "-W", "64", "-H", "48",
                    "--set", "spheres.radius_scale=0.8,1.2", "--repeat", "2", "--no-cache", "-q", "-o", str(out)],
                   check=True)
    t = fluidsurf.compare(dam, R, methods=["spheres", "reference"], width=64, height=48,
                          sweep={"spheres.radius_scale": [0.8, 1.2]}, repeat=2, tables=True)
    py = t["metrics"].to_dict("records") if hasattr(t["metrics"], "to_dict") else t["metrics"]
    cli = _csv_rows(out / "metrics.csv")
    assert len(py) == len(cli) == 3
    for a, b in zip(py, cli):
        for col, text in b.items():
            if col in ("frame_ms", "frame"):
                continue
            v = a[col]
            if text == "":
                assert v == "" or v != v, (col, v)
            elif isinstance(v, str):
                assert text == v, (col, text, v)
            else:
                assert float(text) == float(v), (col, text, v)
    timings = t["timings"].to_dict("records") if hasattr(t["timings"], "to_dict") else t["timings"]
    assert {r["runs"] for r in timings if r["variant"] != "ground truth"} == {2}
    assert {r["runs"] for r in _csv_rows(out / "timings.csv") if r["variant"] != "ground truth"} == {"2"}


def test_compare_out_writes_the_command_lines_folder(tmp_path):
    """compare(out=DIR) writes the folder `fluidsurf compare -o DIR --no-cache`
    writes (fluidsurf_compare_to_dir): file for file and byte for byte but for
    the times and the command line report.md records (tests/same_study.py), a
    sequence with a sweep, two references and counters; panel.png, whose
    captions hold frame times, has the same height and a width within their
    digits. A second run into the folder is refused unless force=True."""
    sys.path.insert(0, os.path.join(SRC, "tests"))
    import same_study
    scene = tmp_path / "s.json"
    scene.write_text('{"particles": {"synthetic": "slab", "first": 0, "last": 1, "moving": true}, "radius": 0.025, '
                     '"camera": {"width": 40, "height": 32}}')
    cli, py = tmp_path / "cli", tmp_path / "py"
    subprocess.run([BIN, "compare", str(scene), "--methods", "spheres", "--set", "spheres.radius_scale=0.8,1.2",
                    "--reference", "reference", "--reference", "analytic", "--repeat", "1", "--counters",
                    "--no-cache", "-q", "-o", str(cli)], check=True)
    args = dict(scene=str(scene), methods=["spheres"], sweep={"spheres.radius_scale": [0.8, 1.2]},
                reference=["reference", "analytic"], repeat=1, counters=True)
    rows = fluidsurf.compare(out=py, **args)
    assert len(rows) == 8
    assert same_study.main([str(cli), str(py), "--skip", "panel.png"]) == 0
    size = lambda p: struct.unpack(">II", (p / "panel.png").read_bytes()[16:24])  # IHDR: width, height
    (cw, ch), (pw, ph) = size(cli), size(py)
    assert ch == ph and abs(cw - pw) <= 24, (size(cli), size(py))
    assert "fluidsurf_compare_to_dir" in (py / "report.md").read_text()
    with pytest.raises(ValueError, match="holds another run's outputs"):
        fluidsurf.compare(out=py, **args)
    fluidsurf.compare(out=py, force=True, **args)
    assert same_study.main([str(cli), str(py), "--skip", "panel.png"]) == 0


def test_compare_sequence_and_scene(tmp_path):
    """A list of arrays is a sequence (one row per frame, a temporal table); a
    scene file's own frames run as `fluidsurf compare s.json` runs them."""
    x, y, z = np.meshgrid(np.arange(8), np.arange(3), np.arange(8), indexing="ij")
    slab = (np.stack([x, y, z], -1).reshape(-1, 3) * 2 * R).astype(np.float32)
    t = fluidsurf.compare([slab, slab + np.float32(0.3 * R)], R, methods=["spheres"], width=32, height=24, repeat=1,
                          tables=True)
    rows = t["metrics"].to_dict("records") if hasattr(t["metrics"], "to_dict") else t["metrics"]
    assert [r["frame"] for r in rows] == [0, 1] and "temporal" in t
    scene = tmp_path / "s.json"
    scene.write_text('{"particles": {"synthetic": "slab", "first": 0, "last": 1}, "radius": 0.025, '
                     '"camera": {"width": 24, "height": 16}}')
    rows = fluidsurf.compare(scene=str(scene), methods=["spheres"], reference=["analytic", "reference"], repeat=1)
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert sorted((r["reference"], r["frame"]) for r in rows) == [("analytic", 0), ("analytic", 1),
                                                                  ("reference", 0), ("reference", 1)]
    with pytest.raises(ValueError, match="sweep"):
        fluidsurf.compare(slab, R, methods=["spheres"], sweep={"spheres.radius_scale": 0.8})


def test_metrics_leave_out_what_solids_hide(tmp_path):
    """metrics() of two render() dicts in a scene with solids masks as compare
    does (their solid_depth layer): fewer pixels than without it, the same
    numbers as compare() of that scene."""
    x, y, z = np.meshgrid(np.arange(10), np.arange(4), np.arange(10), indexing="ij")
    slab = (np.stack([x, y, z], -1).reshape(-1, 3) * 2 * R).astype(np.float32)
    ply = tmp_path / "slab.ply"
    ply.write_text("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                   "end_header\n%s\n" % (len(slab), "\n".join("%r %r %r" % tuple(map(float, p)) for p in slab)))
    scene = tmp_path / "s.json"
    scene.write_text('{"particles": "%s", "radius": %r, "up": "y", "camera": {"eye": [0.2, 0.6, 1.5], '
                     '"target": [0.2, 0.1, 0.2], "width": 48, "height": 40}, '
                     '"obstacles": [{"min": [-0.1, -0.1, 0.55], "max": [0.2, 0.4, 0.65]}]}' % (ply, R))
    a = fluidsurf.render(slab, R, method="spheres", scene=str(scene), width=48, height=40)
    ref = fluidsurf.render(slab, R, method="reference", scene=str(scene), width=48, height=40)
    assert "solid_depth" in ref and "solid_depth" in a
    masked = fluidsurf.metrics(a, ref)
    bare = fluidsurf.metrics({k: v for k, v in a.items() if k != "solid_depth"},
                             {k: v for k, v in ref.items() if k != "solid_depth"})
    assert 0 < masked["n_both"] < bare["n_both"], (masked["n_both"], bare["n_both"])
    rows = fluidsurf.compare(scene=str(scene), methods=["spheres"], repeat=1)
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert rows[0]["n_both"] == masked["n_both"]
    assert rows[0]["normal_mean_deg"] == pytest.approx(masked["normal_mean_deg"], rel=1e-5)


# ---- the command line's camera and frame options (API version 8, issue 54) ----
# camera= as --camera's text, a dict without 'up' (the scene's up axis) or
# read_gbuffer's camera (--camera-from: the same image); a particle file or a frame
# pattern as positions with frame= and frames= (render and compare); save_scene=
# (render --save-scene), a scene file the command line renders into the same image.
# r is estimated from the spacing on both sides (the command line's and the module's): the same r
estimated_r = pytest.mark.filterwarnings("ignore:no radius given")
CUBE = os.path.join(SRC, "experiments/data/splashsurf/cube_2366_particles.vtk")
COLUMN = os.path.join(SRC, "experiments/data/splashsurf/hilbert2_7954_particles.vtk")  # stands on z = 0: up z


def run_cli(*args):
    subprocess.run([BIN, *map(str, args), "-q"], check=True)


def same_depth(a, b):
    np.testing.assert_array_equal(a["depth"], b["depth"])
    np.testing.assert_array_equal(a["coverage"], b["coverage"])


@estimated_r
def test_camera_from_a_cli_exr_renders_the_same_image(tmp_path):
    run_cli("render", COLUMN, "--method", "reference", "-W", 24, "-H", 18, "-o", tmp_path / "a.exr")
    a = fluidsurf.read_gbuffer(tmp_path / "a.exr")
    assert a["camera"]["up"] == [0, 0, 1]  # the framed camera stands on the floor's axis
    b = fluidsurf.render(COLUMN, method="reference", width=24, height=18, camera=a["camera"])
    same_depth(a, b)
    assert b["camera"] == a["camera"]


@estimated_r
def test_camera_text_and_dict_without_up_follow_the_scene_up(tmp_path):
    # the module requires the library's version of its header, 8 or later for these calls
    assert fluidsurf.lib.fluidsurf_api_version() >= fluidsurf.lib.FLUIDSURF_API_VERSION >= 8
    text = fluidsurf.render(COLUMN, method="reference", width=16, height=16, camera="eye=3,2,1;target=0,0,0.5")
    assert text["camera"]["up"] == [0, 0, 1]
    plain = fluidsurf.render(COLUMN, method="reference", width=16, height=16,
                             camera={"eye": (3, 2, 1), "target": (0, 0, 0.5)})
    assert plain["camera"]["up"] == [0, 0, 1]
    same_depth(text, plain)
    given = fluidsurf.render(COLUMN, method="reference", camera="eye=3,2,1;target=0,0,0.5;up=x;size=20x10")
    assert given["camera"]["up"] == [1, 0, 0] and given["depth"].shape == (10, 20)
    with pytest.raises(ValueError, match="target"):
        fluidsurf.render(COLUMN, method="reference", width=16, height=16, camera="eye=1,2,3")


@estimated_r
def test_frame_patterns_in_render_and_compare(tmp_path):
    for f in (1, 2, 3):
        os.symlink(CUBE, tmp_path / f"f_{f}.vtk")
    pattern = str(tmp_path / "f_{}.vtk")
    one = fluidsurf.render(pattern, frame=2, method="reference", width=16, height=16)
    assert one["coverage"].sum() > 0
    same_depth(one, fluidsurf.render(CUBE, method="reference", width=16, height=16))
    rows = fluidsurf.compare(pattern, frames="1:3:2", methods=["spheres"], width=16, height=16, repeat=1)
    frames = sorted({int(r["frame"]) for r in (rows.to_dict("records") if hasattr(rows, "to_dict") else rows)})
    assert frames == [1, 3]
    with pytest.raises(ValueError, match="frame pattern"):
        fluidsurf.render(pattern, method="reference", width=16, height=16)
    with pytest.raises(ValueError, match="not a frame pattern"):
        fluidsurf.compare(CUBE, frames="1:2", methods=["spheres"], width=16, height=16)
    with pytest.raises(ValueError, match="3..1|first <= last"):
        fluidsurf.compare(pattern, frames="3:1", methods=["spheres"], width=16, height=16)


@estimated_r
def test_save_scene_renders_the_same_image_on_the_command_line(tmp_path):
    a = fluidsurf.render(COLUMN, method="reference", width=24, height=18, save_scene=tmp_path / "s.json")
    run_cli("render", tmp_path / "s.json", "--method", "reference", "-o", tmp_path / "b.exr")
    same_depth(a, fluidsurf.read_gbuffer(tmp_path / "b.exr"))
    with pytest.raises(ValueError, match="save_scene"):
        fluidsurf.render(np.zeros((10, 3)), 0.025, method="reference", save_scene=tmp_path / "t.json")
    assert not (tmp_path / "t.json").exists()
