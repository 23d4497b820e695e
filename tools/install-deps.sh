#!/bin/sh
# Installs hfshade's build and test dependencies from Debian 12's archive.
# Idempotent: does nothing when everything is already installed.
set -eu
# clang, libclang-rt-14-dev (libFuzzer and the sanitizer runtimes of
# Debian 12's clang 14, only recommended by clang) and llvm (llvm-symbolizer
# for readable reports) are for tools/fuzz.sh; gnuplot-nox draws hfbench's
# plots.
PKGS="build-essential cmake pkg-config libpng-dev libinih-dev libstb-dev
      libopenexr-dev libegl-dev libgles-dev libosmesa6-dev libegl-mesa0
      libgl1-mesa-dri glslang-tools clang libclang-rt-14-dev llvm gnuplot-nox"
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
