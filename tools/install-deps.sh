#!/bin/sh
# Installs hfshade's build and test dependencies from Debian 12's archive.
# Idempotent: does nothing when everything is already installed.
set -eu
# dpkg-dev (dpkg-shlibdeps) and file are what `cpack -G DEB` runs to work
# out the packages' dependencies (docs/INSTALL.md; tests/package.sh).
# clang, libclang-rt-14-dev (libFuzzer and the sanitizer runtimes of
# Debian 12's clang 14, only recommended by clang) and llvm (llvm-symbolizer
# for readable reports) are for tools/fuzz.sh; gnuplot-nox draws hfbench's
# plots.  libx11-dev, libgbm-dev and libdrm-dev build the x11 and kms
# displays (board/DISPLAY.md); xvfb and xauth run the window test.
# libgpiod-dev and libevdev-dev are the input sources (board/DEVICES.md);
# umockdev emulates an evdev node for their test.  linux-libc-dev: the
# kernel headers (linux/videodev2.h) the V4L2 capture source is written
# against (docs/CAPTURE.md; build-essential pulls it in already).  GNU
# parallel runs the jobs of `hfshade tiles` (docs/GIS.md "Many machines";
# tests/test_gis_tiles.c); slurm-wlm and munge a single-node Slurm for
# tests/slurm_tiles.sh (started by the test, in a folder of its own).
# python3-numpy, python3-cffi and python3-gdal are the Python module's
# (tools/python/hfshade, docs/PYTHON.md) and its tests' (tests/python.cmake).
PKGS="build-essential cmake pkg-config libpng-dev libinih-dev libstb-dev
      libopenexr-dev libegl-dev libgles-dev libosmesa6-dev libegl-mesa0
      libgl1-mesa-dri glslang-tools clang libclang-rt-14-dev llvm gnuplot-nox
      libx11-dev libgbm-dev libdrm-dev xvfb xauth libgpiod-dev libevdev-dev umockdev
      linux-libc-dev libgdal-dev dpkg-dev file parallel slurm-wlm munge
      python3-numpy python3-cffi python3-gdal"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "installing:$missing"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
