#!/usr/bin/env bash
# The pictures in README.md and docs/img/ (issue 16): the demo DEM
# (data/demo.ini) in 3-D on the GLES path, without and with one indirect
# bounce, at the defaults; and a panel (hfgen panel) under a local light,
# Lambertian and glossy, seen from straight above (SPEC's view-dir), and
# glossy in perspective (each texel lit for its own view vector towards
# the eye); the demo DEM under a synthetic sky with a sun, its SH alone,
# decomposed into lights, and the truth of the map (issue 17).
# Issue 41: the demo DEM and the panel, top-down and in 3-D, as the
# current code draws them (docs/img/{dem,panel}-{top,3d}.png: the
# automatic exposure, the hue-keeping curve, the environment map behind
# the DEM through the automatic haze, the panel (preset = panel) in the
# studio), and the same four commands run once by the code before issue
# 41 (commit cd90b19), kept as docs/img/*-before.png:
#   git worktree add /tmp/h41-before cd90b19
#   cmake -S /tmp/h41-before -B /tmp/h41-before/build-before
#   cmake --build /tmp/h41-before/build-before --target hfshade hfgen -j2
#   tools/make_pictures.sh build --before /tmp/h41-before/build-before   # -before only
#   git worktree remove --force /tmp/h41-before
# Deterministic: the same build gives the same files.
# usage: tools/make_pictures.sh [BUILD_DIR] [--before OLD_BUILD_DIR]   (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
# The issue-41 pair: SUFFIX "" with this build, "-before" with cd90b19's.
# The same commands for both (only flags cd90b19 knows): what changed is
# the defaults.
pictures41() { # BUILD SUFFIX
    local b=$1 s=$2 t
    t=$(mktemp -d)
    "$b/tools/hfgen" panel --size 256x256 -o "$t/panel.pfm" >/dev/null
    local panel="--height $t/panel.pfm --local 110,90,40,6,60 --albedo 0.85 --preset panel"
    panel="$panel --env-sh 0.6,0,0.3,0,0,0,0,0,0,0,0,0,0,0,0,0"
    "$b/tools/hfshade" render data/demo.ini -o "docs/img/dem-top$s.png" --quiet
    "$b/tools/hfshade" render data/demo.ini --view perspective --camera 300,12,34000,40 \
        --view-size 640x384 -o "docs/img/dem-3d$s.png" --quiet
    # shellcheck disable=SC2086
    "$b/tools/hfshade" render $panel -o "docs/img/panel-top$s.png" --quiet
    # shellcheck disable=SC2086
    "$b/tools/hfshade" render $panel --view perspective --camera 235,32,330,40 \
        --view-size 640x384 -o "docs/img/panel-3d$s.png" --quiet
    rm -rf "$t"
    echo "wrote docs/img/dem-{top,3d}$s.png docs/img/panel-{top,3d}$s.png"
}
if [ "${2:-}" = "--before" ]; then
    pictures41 "${3:?--before needs the old build directory}" -before
    exit 0
fi
pictures41 "$B" ""
CAM="--view perspective --camera 250,38,17000,40 --view-size 640x384"
for b in 0 1; do
    # shellcheck disable=SC2086
    "$B/tools/hfshade" render data/demo.ini --bounces $b $CAM -o "docs/img/dem-3d-bounces$b.png" --quiet
done
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
"$B/tools/hfgen" panel --size 256x256 -o "$T/panel.pfm"
PANEL="--height $T/panel.pfm --local 110,90,40,6,60 --env-sh 0.6,0,0.3,0,0,0,0,0,0,0,0,0,0,0,0,0"
# shellcheck disable=SC2086
"$B/tools/hfshade" render $PANEL --albedo 0.85 -o docs/img/panel-diffuse.png --quiet
# shellcheck disable=SC2086
"$B/tools/hfshade" render $PANEL --albedo 0.45 --specular 0.4 --gloss 48 -o docs/img/panel-glossy.png --quiet
# shellcheck disable=SC2086
"$B/tools/hfshade" render $PANEL --albedo 0.45 --specular 0.4 --gloss 48 --view perspective \
    --camera 235,32,330,40 --view-size 640x384 -o docs/img/panel-glossy-3d.png --quiet
# Issue 17: the demo DEM under a synthetic sky whose 0.5-degree sun (at the
# demo sun's 336/15 degrees) holds 80% of the energy: the map's SH alone
# (--env-shade sh), the map decomposed into lights + residual shaded from
# the map itself (--env-lights auto), and the truth of the map itself (a
# minute or two on two cores); then the same for the demo's courtyard map
# (no sun disk: no light is extracted; the map's own shading does it).
"$B/tools/hfgen" sky --sun 336,15 --size 1024x512 -o "$T/sky.pfm"
SKY="--height data/jacksboro.png --dx 83 --zscale 2 --albedo 0.35 --env-map $T/sky.pfm --exposure -1.74"  # x 0.3
# shellcheck disable=SC2086
"$B/tools/hfshade" render $SKY --env-shade sh -o docs/img/sky-sh-only.png --quiet
# shellcheck disable=SC2086
"$B/tools/hfshade" render $SKY --env-lights auto -o docs/img/sky-env-lights.png --quiet
# shellcheck disable=SC2086
"$B/tools/hfshade" render $SKY --backend truth -o docs/img/sky-truth.png --quiet
YARD="--height data/jacksboro.png --dx 83 --zscale 2 --albedo 0.6 --env-map data/courtyard.exr"
# shellcheck disable=SC2086
"$B/tools/hfshade" render $YARD --env-shade sh -o docs/img/courtyard-sh-only.png --quiet
# shellcheck disable=SC2086
"$B/tools/hfshade" render $YARD --env-lights auto -o docs/img/courtyard-map.png --quiet
# shellcheck disable=SC2086
"$B/tools/hfshade" render $YARD --backend truth -o docs/img/courtyard-truth.png --quiet
# Issue 19: pins and boxes (data/demo-objects.txt) across the shadow of the
# demo DEM's straight ridge at a 10-degree sun, under a dim sky so the
# shadow reads: the two pins in the shadow band stay dark, the others lit.
OBJ="--height data/jacksboro.png --dx 83 --zscale 2 --albedo 0.35 --key 336,10,2,6000"
OBJ="$OBJ --env-sh 1.1,0,0.6,0,0,0,0,0,0,0,0,0,0,0,0,0 --objects data/demo-objects.txt"
# shellcheck disable=SC2086
"$B/tools/hfshade" render $OBJ --view perspective --camera 290,35,8000,40,16300,10400,1100 \
    --view-size 640x384 --exposure -1 -o docs/img/dem-objects.png --quiet
echo "wrote docs/img/dem-objects.png"
echo "wrote docs/img/dem-3d-bounces{0,1}.png docs/img/panel-{diffuse,glossy,glossy-3d}.png"
echo "wrote docs/img/sky-{sh-only,env-lights,truth}.png docs/img/courtyard-{sh-only,map,truth}.png"
