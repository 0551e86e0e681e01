"""`pip install .` (pyproject.toml): CMake configures and builds libfluidsurf in
build-pip/ (-DFS_TESTS=OFF; an existing build-pip/ keeps its options), installs
its component `python` (the library, its OpenImageIO module, the module's
files) into a staging folder, and the package is packed from there:

    fluidsurf/*.py, fluidsurf/fluidsurf.h     the module and the header cffi reads
    fluidsurf/lib/libfluidsurf.so.0           the library (_paths.py points here)
    fluidsurf/lib/fluidsurf/fluidsurf-oiio.so its OpenImageIO module, found beside it

FLUIDSURF_BUILD_DIR=DIR packs the build in DIR as it is (already built: nothing is
configured or compiled), as the test pip_install does."""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
SONAME = "libfluidsurf.so.0"


def version():
    with open(os.path.join(HERE, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(\s*fluidsurf\s+VERSION\s+([0-9.]+)", f.read()).group(1)


def cmake(*args):
    subprocess.run(["cmake", *args], check=True)


def build_dir():
    """The CMake build to pack: FLUIDSURF_BUILD_DIR as it is, else build-pip/, built here."""
    given = os.environ.get("FLUIDSURF_BUILD_DIR")
    if given:
        if not os.path.isfile(os.path.join(given, "CMakeCache.txt")):
            sys.exit(f"setup.py: FLUIDSURF_BUILD_DIR={given} is not a CMake build folder (no CMakeCache.txt)")
        return os.path.abspath(given)
    build = os.path.join(HERE, "build-pip")
    if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
        cmake("-S", HERE, "-B", build, "-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-DFS_TESTS=OFF")
    cmake("--build", build, "-j", str(os.cpu_count() or 2), "--target", "fluidsurf_lib")
    return build


def one(pattern, what):
    found = glob.glob(pattern, recursive=True)
    if len(found) != 1:
        sys.exit(f"setup.py: expected one {what} in the staged install, found {len(found)} ({pattern})")
    return found[0]


class CMakeBuildPy(build_py):
    """build_py as CMake builds and installs the package (the sources are not copied as they are)."""

    def run(self):
        build = build_dir()
        out = os.path.join(self.build_lib, "fluidsurf")
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(os.path.join(out, "lib", "fluidsurf"))
        with tempfile.TemporaryDirectory() as stage:
            cmake("--install", build, "--component", "python", "--prefix", stage)
            package = os.path.dirname(one(os.path.join(stage, "**", "fluidsurf", "__init__.py"), "module"))
            for f in glob.glob(os.path.join(package, "*.py")) + [os.path.join(package, "fluidsurf.h")]:
                shutil.copy(f, out)
            shutil.copy(one(os.path.join(stage, "**", SONAME), SONAME), os.path.join(out, "lib", SONAME))
            for plugin in glob.glob(os.path.join(stage, "**", "fluidsurf", "fluidsurf-oiio.so"), recursive=True):
                shutil.copy(plugin, os.path.join(out, "lib", "fluidsurf"))
        with open(os.path.join(out, "_paths.py"), "w", encoding="utf-8") as f:
            f.write('# Written by setup.py: where libfluidsurf.so lies, relative to this package.\n'
                    f'LIB_FROM_PACKAGE = "lib"\nSONAME = "{SONAME}"\n')


class BinaryDistribution(Distribution):
    """The package holds a shared library: a platform wheel, not a pure one."""

    def has_ext_modules(self):
        return True


def work_dir():
    """setuptools' own build and egg-info folders: beside the CMake build, not in the tree."""
    base = os.path.join(os.environ.get("FLUIDSURF_BUILD_DIR") or os.path.join(HERE, "build-pip"), "setuptools")
    os.makedirs(base, exist_ok=True)
    return base


setup(version=version(), packages=["fluidsurf"], package_dir={"fluidsurf": "python/fluidsurf"},
      distclass=BinaryDistribution, cmdclass={"build_py": CMakeBuildPy},
      options={"build": {"build_base": work_dir()}, "egg_info": {"egg_base": work_dir()}})
