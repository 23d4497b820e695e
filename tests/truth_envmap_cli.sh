#!/usr/bin/env bash
# truth_envmap_cli.sh HFSHADE HFGEN DATA_DIR — the truth of an --env-map
# end to end (scene layer -> lighting.env_map -> truth): on a flat 8x8
# field under data/courtyard.exr the truth is the map's cosine integral at
# the zenith normal, Lo = (0.599258, 0.668173, 0.993968), computed
# independently of the truth (the map's rows summed with
# Int sin e cos e de; DESIGN.md "Ground truth of an environment map"); with
# truth-env = sh it is the SH projection's, (0.664888, 0.694108, 0.972659).
# Tolerance 1e-5 (the truth's float tables: measured 1e-7).
set -euo pipefail
HFS=$1 GEN=$2 DATA=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$GEN" flat --size 8x8 -o "$tmp/flat.pfm" >/dev/null
texel() { # PFM: the first texel's RGB (after three header lines; little-endian)
    [ "$(sed -n 3p "$1")" = "-1.0" ] || [ "$(sed -n 3p "$1" | cut -c1)" = "-" ] ||
        { echo "FAIL: $1 is not little-endian" >&2; exit 1; }
    od -A n -t f4 -j "$(head -n 3 "$1" | wc -c)" -N 12 "$1"
}
check() { # PFM R G B
    read -r r g b <<<"$(texel "$1")"
    awk -v f="$1" -v r="$r" -v g="$g" -v b="$b" -v R="$2" -v G="$3" -v B="$4" 'BEGIN {
        d = 0; split(r " " g " " b, x, " "); split(R " " G " " B, y, " ");
        for (i = 1; i <= 3; ++i) { e = x[i] - y[i]; if (e < 0) e = -e; if (e > d) d = e }
        printf "%s: (%s, %s, %s), max |diff| %.2e\n", f, r, g, b, d;
        exit !(d < 1e-5) }' || { echo "FAIL: $1 is not ($2, $3, $4)"; exit 1; }
}
L=(--height "$tmp/flat.pfm" --env-map "$DATA/courtyard.exr" --backend truth --quiet)
"$HFS" render "${L[@]}" --pfm "$tmp/map.pfm"
"$HFS" render "${L[@]}" --truth-env sh --pfm "$tmp/sh.pfm"
check "$tmp/map.pfm" 0.599258 0.668173 0.993968
check "$tmp/sh.pfm" 0.664888 0.694108 0.972659
echo "truth_envmap_cli: ok"
