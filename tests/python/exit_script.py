"""A session as issue 48 found it crashing at exit: a particle file read, a
dozen bad calls (each refused), mesh() without a radius, compare() with one
method, render(), methods(), then the interpreter exits. Run by
tests/python_exit.sh many times with the CPU kept busy; it must exit 0 each time.
Not a pytest file: python3 exit_script.py PARTICLES SIZE."""
import sys
import warnings

import numpy as np

import fluidsurf


def bad_calls(pos):
    """Calls the module must refuse with a ValueError before anything renders."""
    return [lambda: fluidsurf.render(pos[:, :2]), lambda: fluidsurf.render(pos, -1.0),
            lambda: fluidsurf.render(pos, method="nope"), lambda: fluidsurf.render(pos, width=0),
            lambda: fluidsurf.render(pos, params={"nope": 1}), lambda: fluidsurf.render(np.full((3, 3), np.nan)),
            lambda: fluidsurf.compare(pos, methods=["nope"]), lambda: fluidsurf.mesh(pos, params={"cube": -1}),
            lambda: fluidsurf.render(pos, up="w"), lambda: fluidsurf.render(pos, field={"bad": 1}),
            lambda: fluidsurf.render(pos, camera={"eye": (0, 0, 0)}), lambda: fluidsurf.metrics({}, {})]


def main(path, size):
    warnings.simplefilter("ignore")  # the estimated radius's warning
    pos = fluidsurf.read_particles(path)["positions"]
    for i, call in enumerate(bad_calls(pos)):
        try:
            call()
            sys.exit(f"bad call {i} was accepted")
        except ValueError:
            pass
    meshes = any(m["name"] == "mesh" for m in fluidsurf.methods())  # not without OpenVDB
    vertices = fluidsurf.mesh(pos)[0] if meshes else [0]
    rows = fluidsurf.compare(pos, methods=["raycast_pca"], width=size, height=size, repeat=1)
    out = fluidsurf.render(pos, width=size, height=size)
    print(len(vertices) > 0, len(rows), out["depth"].shape, len(fluidsurf.methods()) > 0)


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]))
