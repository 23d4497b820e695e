#!/usr/bin/env bash
# Run time against error (issue 5): hfbench's default sweep on cones, fractal
# terrain and the real DEM at 256x256 under the demo lighting (sky + sun),
# GLES on this machine, against cached ground truth.  Writes the CSV and the
# plots (error against time per scene, Pareto front, defaults, picks) under
# docs/bench/, and prints the Markdown summary that BENCHMARKS.md quotes.
# Takes ~15-25 minutes on the 2-core build machine (truth renders are cached
# in BUILD_DIR/bench-cache).  Run it on an otherwise idle machine.
# usage: tools/bench_pareto.sh [BUILD_DIR] [FRAMES]     (defaults: build 3)
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
F=${2:-3}
mkdir -p docs/bench
"$B/tools/hfbench" -o docs/bench/pareto-256.csv --plots docs/bench --scenes cones,fractal,dem \
  --size 256 --lights sky+sun --frames "$F" --cache "$B/bench-cache" | tee docs/bench/pareto-256.md
rm -f docs/bench/*.dat
