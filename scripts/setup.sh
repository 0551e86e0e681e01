#!/usr/bin/env bash
# Installs the Debian packages fluidsurf needs to build, test and run its
# experiments. Idempotent: does nothing (quickly) when everything is present.
set -euo pipefail
PKGS=(build-essential cmake pkg-config git
      libosmesa6-dev libglfw3-dev libegl-dev
      libopenvdb-dev libopenvdb-tools libboost-iostreams-dev libtbb-dev
      libopenimageio-dev openimageio-tools libvtk9-dev libcjson-dev zlib1g-dev
      libopenexr-dev libstb-dev glslang-tools
      clang libclang-rt-14-dev clang-format # the fuzz targets; the C style check (scripts/check_format.sh)
      xvfb xauth fonts-dejavu-core gnuplot-nox python3 python3-vtk9
      slurm-wlm munge
      python3-numpy python3-cffi python3-pytest python3-matplotlib
      python3-venv python3-pip python3-setuptools python3-wheel # pip install . (pyproject.toml) into a venv
      chromium chromium-driver python3-selenium) # the report page's browser test (tests/report.cmake)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
