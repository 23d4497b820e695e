#!/usr/bin/env bash
# The pictures in README.md and docs/img/ (issue 16): the demo DEM
# (data/demo.ini) in 3-D on the GLES path, without and with one indirect
# bounce, at the defaults.  Deterministic: the same build gives the same
# files.
# usage: tools/make_pictures.sh [BUILD_DIR]   (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
CAM="--view perspective --camera 250,38,17000,40 --view-size 640x384"
for b in 0 1; do
    # shellcheck disable=SC2086
    "$B/tools/hfshade" render data/demo.ini --bounces $b $CAM -o "docs/img/dem-3d-bounces$b.png" --quiet
done
echo "wrote docs/img/dem-3d-bounces0.png docs/img/dem-3d-bounces1.png"
