"""Issue 48's calls against the real library and command line: metrics() refuses
what `fluidsurf diff` refuses, in its words; read_gbuffer() gives back all an EXR
holds and its view renders again bit for bit; write_image(), write_mesh(),
info(), estimate_radius(); splashsurf's names of the mesh's settings; every new
call refuses bad input before anything renders."""
import locale
import os
import re
import subprocess
import warnings

import numpy as np
import pytest

import fluidsurf

SRC = os.environ["FS_SRC"]
BIN = os.environ["FS_BIN"]
CUBE = os.path.join(SRC, "experiments/data/splashsurf/cube_2366_particles.vtk")
SIZE = 40


@pytest.fixture(scope="module")
def cube():
    return fluidsurf.read_particles(CUBE)["positions"]


def cli(*args):
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True)


def cli_render(path, *options):
    """`fluidsurf render CUBE -W SIZE -H SIZE OPTIONS -o path`: the EXR's path."""
    done = cli("render", CUBE, "-W", SIZE, "-H", SIZE, "-q", *options, "-o", path)
    assert done.returncode == 0, done.stderr
    return path


def diff_words(a, b, *options):
    """`fluidsurf diff`'s refusal of a against b, with the file names as metrics()
    names its arguments (image, reference)."""
    done = cli("diff", a, b, *options)
    assert done.returncode == 2, done.stdout + done.stderr
    line = done.stderr.strip().removeprefix("fluidsurf: ")
    return line.replace(str(a), "image").replace(str(b), "reference")


def test_metrics_refuses_what_diff_refuses(tmp_path):
    """The same two EXRs: diff's refusal and metrics()'s ValueError say the same."""
    y, z = cli_render(tmp_path / "y.exr", "--up", "y"), cli_render(tmp_path / "z.exr", "--up", "z")
    gy, gz = fluidsurf.read_gbuffer(y), fluidsurf.read_gbuffer(z)
    with pytest.raises(ValueError) as e:
        fluidsurf.metrics(gy, gz)
    assert "were rendered with different cameras (eye" in str(e.value)
    assert str(e.value) == diff_words(y, z)
    # the case: two renders of the library with another up axis
    pos = fluidsurf.read_particles(CUBE)["positions"]
    with pytest.raises(ValueError, match="^image and reference were rendered with different cameras"):
        fluidsurf.metrics(fluidsurf.render(pos, 0.025, up="z", width=SIZE, height=SIZE, method="spheres"),
                          fluidsurf.render(pos, 0.025, up="y", width=SIZE, height=SIZE, method="spheres"))
    small = cli_render(tmp_path / "small.exr", "--up", "y", "-W", 24)
    with pytest.raises(ValueError) as e:
        fluidsurf.metrics(fluidsurf.read_gbuffer(small), gy)
    assert str(e.value) == diff_words(small, y) == \
        f"image is 24x{SIZE} but reference is {SIZE}x{SIZE}: images of different sizes cannot be compared"


def test_metrics_warns_of_another_r_and_strict_refuses(cube):
    ref = fluidsurf.render(cube, 0.025, method="spheres", width=SIZE, height=SIZE)
    other = fluidsurf.render(cube, 0.03, method="spheres", width=SIZE, height=SIZE, camera=ref["camera"])
    with pytest.warns(UserWarning, match=r"^image has r = 0\.03 but reference has r = 0\.025; depth errors are in "
                                         r"the reference's r$"):
        m = fluidsurf.metrics(other, ref)
    assert 0 < m["mask_iou"] < 1
    with pytest.raises(ValueError, match=r"^image has r = 0\.03 but reference has r = 0\.025 \(refused under strict\)$"):
        fluidsurf.metrics(other, ref, strict=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the same image: not a word
        assert fluidsurf.metrics(ref, ref, strict=True)["mask_iou"] == 1
        # arrays of one's own carry no provenance: accepted, only what both carry is checked
        own = {k: ref[k] for k in ("depth", "normal", "coverage")}
        assert fluidsurf.metrics(own, ref, strict=True)["mask_iou"] == 1
    with pytest.raises(ValueError, match="^strict: expected True or False"):
        fluidsurf.metrics(ref, ref, strict="yes")
    with pytest.raises(ValueError, match=r"^image\['provenance'\]: "):
        fluidsurf.metrics({**ref, "provenance": {"camera": "x"}}, ref)


def test_read_gbuffer_returns_all_the_exr_holds_and_renders_again(tmp_path, cube):
    """A `fluidsurf render` EXR: its provenance, camera, size, r and its source;
    render() through them gives the stored image bit for bit."""
    path = cli_render(tmp_path / "view.exr", "--method", "raycast_pca", "--up", "z")
    g = fluidsurf.read_gbuffer(path)
    prov = g["provenance"]
    assert prov["fluidsurf:method"] == "raycast_pca" and prov["fluidsurf:r_source"] == "estimated"
    assert {"fluidsurf:commit", "fluidsurf:camera", "fluidsurf:params", "fluidsurf:scene_hash"} <= set(prov)
    assert (g["width"], g["height"]) == (SIZE, SIZE) and g["r_source"] == "estimated"
    assert g["radius"] == pytest.approx(float(prov["fluidsurf:r"]), rel=1e-7)
    assert set(g["camera"]) == {"eye", "target", "up", "fov"} and g["camera"]["up"] == [0, 0, 1]
    again = fluidsurf.render(cube, g["radius"], method="raycast_pca", camera=g["camera"], width=g["width"],
                             height=g["height"], up="z")
    for name in ("depth", "normal", "thickness", "coverage", "rgb", "alpha"):
        np.testing.assert_array_equal(again[name], g[name], err_msg=name)
    assert again["camera"] == g["camera"]


def test_read_gbuffer_gives_the_solids_depth(tmp_path):
    scene = tmp_path / "s.json"
    scene.write_text('{"particles": "%s", "radius": 0.025, "camera": {"width": 32, "height": 32}, '
                     '"obstacles": [{"min": [0.8, 0, 0.8], "max": [1.5, 0.3, 1.0]}]}' % CUBE)
    done = cli("render", scene, "-o", tmp_path / "s.exr", "-q")
    assert done.returncode == 0, done.stderr
    g = fluidsurf.read_gbuffer(tmp_path / "s.exr")
    assert g["solid_depth"].shape == (32, 32) and np.isfinite(g["solid_depth"]).any()


def test_write_image_round_trip(tmp_path, cube):
    out = fluidsurf.render(cube, 0.025, method="raycast_pca", width=SIZE, height=SIZE)
    fluidsurf.write_image(out, tmp_path / "a.exr")
    back = fluidsurf.read_gbuffer(tmp_path / "a.exr")
    for name in ("depth", "normal", "thickness", "coverage", "rgb", "alpha"):
        np.testing.assert_array_equal(back[name], out[name], err_msg=name)
    assert back["camera"] == out["camera"] and back["radius"] == out["radius"]
    assert {k: v for k, v in back["provenance"].items() if k != "fluidsurf:empty_depth"} == out["provenance"]
    # diff reads what write_image wrote: the same image, no threshold crossed (a scene of
    # the library has no scene_hash: diff says it cannot check the scene)
    done = cli("diff", tmp_path / "a.exr", tmp_path / "a.exr", "--fail-iou", "1")
    assert done.returncode == 0 and "mask_iou 1" in done.stdout, done.stderr
    fluidsurf.write_image(out, tmp_path / "a.png")
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # arrays of one's own with a layer and r: the layer comes back, r is fluidsurf:r
    own = {k: out[k] for k in ("depth", "normal", "coverage", "rgb")}
    own["mine"], own["radius"] = np.full((SIZE, SIZE), 7, np.float32), 0.025
    fluidsurf.write_image(own, tmp_path / "own.exr")
    b = fluidsurf.read_gbuffer(tmp_path / "own.exr")
    assert (b["mine"] == 7).all() and b["radius"] == np.float32(0.025) and "camera" not in b


BAD_WRITES = [
    (lambda d, t: fluidsurf.write_image(d, t / "x.tif"), "^path .*: expected a file ending in .png, .exr"),
    (lambda d, t: fluidsurf.write_image(d, t / "nosuch" / "x.exr"), "no such folder"),
    (lambda d, t: fluidsurf.write_image(d, t), "expected a file ending in"),
    (lambda d, t: fluidsurf.write_image({k: d[k] for k in ("depth", "normal", "coverage")}, t / "x.exr"),
     "no shaded rgba"),
    (lambda d, t: fluidsurf.write_image({**d, "rgb": d["rgb"][:, :3]}, t / "x.exr"), r"^image\['rgb'\]: expected shape"),
    (lambda d, t: fluidsurf.write_image({**d, "odd": np.zeros((3, 3))}, t / "x.exr"), r"^image\['odd'\]: a layer is"),
    (lambda d, t: fluidsurf.write_image({**d, "depth": np.zeros((2, 2, 2))}, t / "x.exr"), r"^image\['depth'\]"),
    (lambda d, t: fluidsurf.write_image("x.exr", t / "x.exr"), "^image: expected a dict"),
    (lambda d, t: fluidsurf.write_mesh(([[0, 0, 0]], [[0, 0, 1]]), t / "m.ply"), "^mesh faces: indices from 0 to 0"),
    (lambda d, t: fluidsurf.write_mesh(([[0, 0, np.nan]], np.zeros((0, 3), int)), t / "m.ply"), "^mesh vertices"),
    (lambda d, t: fluidsurf.write_mesh(([[0, 0, 0]], [[0.5, 0, 0]]), t / "m.ply"), "^mesh faces: expected M x 3 int"),
    (lambda d, t: fluidsurf.write_mesh(([[0, 0, 0]], np.zeros((0, 3), int)), t / "m.stl"), "^path .*ending in .ply"),
    (lambda d, t: fluidsurf.write_mesh(([[0, 0, 0]], np.zeros((0, 3), int)), t / "m.ply", provenance={"r": "1"}),
     "^provenance: 'r'"),
    (lambda d, t: fluidsurf.write_mesh("mesh", t / "m.ply"), "^mesh: expected"),
    (lambda d, t: fluidsurf.info(d["depth"]), "^positions: expected an N x 3 array"),
    (lambda d, t: fluidsurf.info(np.zeros((4, 3)), radius=-1), "^radius: must be positive"),
    (lambda d, t: fluidsurf.info(np.zeros((4, 3)), volume_scale=0), "^volume_scale: must be positive"),
    (lambda d, t: fluidsurf.estimate_radius(np.zeros((9, 3))), "no spacing"),
    (lambda d, t: fluidsurf.estimate_radius([[0, 0, np.inf]]), "^positions: .*NaN or infinite"),
]


@pytest.mark.parametrize("call,words", BAD_WRITES)
def test_bad_input_refused_and_nothing_written(tmp_path, cube, call, words):
    d = fluidsurf.render(cube[:50], 0.025, method="spheres", width=16, height=16)
    before = set(os.listdir(tmp_path))
    with pytest.raises((ValueError, FileNotFoundError), match=words):
        call(d, tmp_path)
    assert set(os.listdir(tmp_path)) == before


def mesh_file_provenance(path):
    """The fluidsurf:NAME=VALUE lines of a PLY or OBJ header as a dict."""
    text = path.read_bytes().split(b"end_header")[0].decode("utf-8", "replace")
    return dict(re.findall(r"^(?:comment|#) (fluidsurf:[a-z_]+)=(.*)$", text, re.M))


def test_write_mesh_with_provenance(tmp_path, cube):
    m = fluidsurf.mesh(cube, 0.025, params={"cube": 1.0})
    vertices, faces, normals = m  # pysplashsurf's triple still
    assert len(faces) > 100 and m.provenance["fluidsurf:method"] == "mesh"
    assert "cube=1;" in m.provenance["fluidsurf:params"] and float(m.provenance["fluidsurf:r"]) == pytest.approx(0.025)
    for ext in ("ply", "obj", "vtk", "vtp"):
        fluidsurf.write_mesh(m, tmp_path / f"m.{ext}", provenance={"fluidsurf:note": "by hand"})
        assert b"fluidsurf:params" in (tmp_path / f"m.{ext}").read_bytes(), ext
    for ext in ("ply", "obj"):
        p = mesh_file_provenance(tmp_path / f"m.{ext}")
        assert p == {**m.provenance, "fluidsurf:note": "by hand"}, ext
    # the file is the mesh: fluidsurf reads the PLY's vertices back (as particles) unchanged
    back = fluidsurf.read_particles(tmp_path / "m.ply")["positions"]
    np.testing.assert_array_equal(back, vertices)
    # a mesh of one's own, without normals: area-weighted normals from its faces
    tet = (np.eye(3, dtype=np.float32).tolist() + [[0, 0, 0]], [[3, 1, 0], [3, 0, 2], [3, 2, 1], [0, 1, 2]])
    fluidsurf.write_mesh(tet, tmp_path / "tet.obj")
    text = (tmp_path / "tet.obj").read_text()
    assert "\nvn -0.57735 -0.57735 -0.57735\n" in text and "fluidsurf:" not in text.replace("# fluidsurf mesh", "")


def test_writing_a_vtk_mesh_leaves_the_locale(tmp_path, cube):
    """VTK 9.1's legacy writer sets the process's locale to "C": the library puts
    the caller's back, or open() would read text as ASCII for the rest of the session."""
    before = locale.setlocale(locale.LC_ALL)
    m = fluidsurf.mesh(cube, 0.025, params={"cube": 1.0})
    for ext in ("vtk", "vtp"):
        fluidsurf.write_mesh(m, tmp_path / f"m.{ext}")
        assert locale.setlocale(locale.LC_ALL) == before, ext


def test_splashsurf_names(cube):
    ours = fluidsurf.mesh(cube, 0.025, params={"cube": 1.0}, field={"support": 4.0, "iso": 0.6})
    theirs = fluidsurf.mesh(cube, 0.025, params={"cube_size": 1.0},
                            field={"smoothing_length": 2.0, "iso_surface_threshold": 0.6})
    for a, b in zip(ours, theirs):
        np.testing.assert_array_equal(a, b)
    with pytest.raises(ValueError, match="'cube_size' and 'cube' are one parameter"):
        fluidsurf.mesh(cube, 0.025, params={"cube": 1.0, "cube_size": 1.0})
    with pytest.raises(ValueError, match="'smoothing_length' and 'support' are one setting"):
        fluidsurf.mesh(cube, 0.025, field={"support": 4.0, "smoothing_length": 2.0})
    with pytest.raises(ValueError, match=r"^field\['smoothing_length'\]: must be positive"):
        fluidsurf.mesh(cube, 0.025, field={"smoothing_length": -2.0})
    for name in ("cube_size", "smoothing length", "iso-surface threshold"):
        assert name in fluidsurf.mesh.__doc__, name


def test_info_and_estimate_radius_are_the_command_lines(cube):
    """info() of the arrays gives `fluidsurf info`'s numbers for the file."""
    text = cli("info", CUBE).stdout
    r_cli = float(re.search(r"^radius r: (\S+) \(estimated", text, re.M).group(1))
    nn_cli = float(re.search(r"^nearest-neighbour distance, median: (\S+)", text, re.M).group(1))
    phi_cli = float(re.search(r"^density phi at centres, median: (\S+)", text, re.M).group(1))
    r = fluidsurf.estimate_radius(cube)
    i = fluidsurf.info(cube)
    assert r == pytest.approx(r_cli, rel=1e-5) and i["radius"] == r and i["radius_source"] == "estimated"
    assert i["count"] == 2366 and i["nn_median"] == pytest.approx(nn_cli, rel=1e-5)
    assert i["density_median"] == pytest.approx(phi_cli, rel=1e-3)
    assert i["bbox_min"] == pytest.approx([0.85, 0.0499902, 0.85], rel=1e-5)
    given = fluidsurf.info(cube, radius=0.03, volume_scale=2)
    assert given["radius"] == pytest.approx(0.03) and given["radius_source"] == "given"
    assert given["estimated_radius"] == r and given["volume_scale"] == 2
    # a render without a radius uses the same estimate
    with pytest.warns(UserWarning, match="no radius given"):
        out = fluidsurf.render(cube, method="spheres", width=16, height=16)
    assert out["radius"] == np.float32(r)
