"""The Python module against the real library and the real command line
(tests/python.cmake runs it on the installed prefix). FS_BIN: the fluidsurf
binary; FS_SRC: the source tree."""
import os
import re
import resource
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
    assert "camera" not in cli


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
        assert 0.8 < r["mask_iou"] <= 1 and r["normal_mean_deg"] > 0 and r["total_ms"] > 0
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
    ({"scene": "/nonexistent/scene.json"}, "/nonexistent/scene.json"),
]


@pytest.mark.parametrize("kwargs,words", BAD_ARGS)
def test_bad_arguments(kwargs, words):
    args = {"radius": R, "method": "raycast_pca", "width": 16, "height": 16, **kwargs}
    with pytest.raises(ValueError, match=words):
        fluidsurf.render(np.random.default_rng(1).random((4, 3), dtype=np.float32), **args)


def test_bad_files_and_images(tmp_path):
    with pytest.raises(ValueError, match="missing.ply"):
        fluidsurf.read_particles(str(tmp_path / "missing.ply"))
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
