#!/usr/bin/env bash
# Live inputs (issue 18): capture-to-photon latency and the capture path's
# CPU per frame in headless replay, and the depth filter's effect
# (BENCHMARKS.md "Live inputs (issue 18)", docs/CAPTURE.md).
#
# Latency: hfs-capture-synth writes a 512x384 Z16 recording at 30 fps
# (FRAMES frames; a hand enters at 30, sweeps until 60, rests until 100,
# leaves; noise 1.5 mm, 0.5% holes); a headless hfshade-kiosk (frames kept
# in memory) replays it through a [capture] section with role = heights,
# grid 256x192 (2x2 depth pixels per height, area-averaged), on a scene
# with the demo's courtyard sky and a key light, default (kiosk) preset.
# Each frame is due at its recorded time (the replay's clock); latency =
# that time to the moment hfs_display_present returned for the frame
# showing its heights (the kiosk's --stats "capture" lines).  CPU = the
# loop thread's CPU time (CLOCK_THREAD_CPUTIME_ID) spent taking the frame:
# read, convert (plane, roi, resample), filter, fill holes; the render is
# not in it.  RUNS runs (the machine is shared: medians of runs).
# Filter: tests/test_depth_heights --report on the same synthetic camera.
#
# usage: tools/bench_capture.sh BUILD_DIR [FRAMES] [RUNS]   (defaults 150, 3)
set -euo pipefail
cd "$(dirname "$0")/.."
B=$(cd "$1" && pwd); N=${2:-150}; RUNS=${3:-3}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT

$B/tools/hfgen flat --size 256x192 -o "$T/flat.pfm" >/dev/null
cat >"$T/scene.ini" <<EOS
height = flat.pfm
dx = 0.002
env-map = $PWD/data/courtyard.exr
key = 95,30,2.5,400
albedo = 0.35
EOS
printf '[capture sandbox]\nreplay = rec\nrole = heights\ngrid = 256x192\n' >"$T/cap.ini"
$B/board/hfs-capture-synth "$T/rec" --frames "$N" --hand 30,60,100
cd "$T"
for r in $(seq "$RUNS"); do
  "$B/board/hfshade-kiosk" scene.ini --input cap.ini --display headless --exit-after-capture \
      --stats "stats-$r.txt" 2>"log-$r.txt"
done
python3 - "$N" stats-*.txt <<'EOS'
import statistics, sys
n = int(sys.argv[1])
print("| run | frames shown of %d | superseded | latency median ms | max ms | capture CPU median ms/frame | max | render median ms |" % n)
print("|---|---|---|---|---|---|---|---|")
meds = []
for i, path in enumerate(sys.argv[2:], 1):
    lat, cpu, render, last, sup = [], [], [], None, 0
    for line in open(path):
        f = line.split()
        if f[0] == "frame": last = float(f[3])
        if f[0] == "capture":
            lat.append(int(f[4]) / 1e6); cpu.append(int(f[5]) / 1e6); render.append(last)
            sup = int(f[7])
    meds.append((statistics.median(lat), max(lat), statistics.median(cpu)))
    print(f"| {i} | {len(lat)} | {sup} | {statistics.median(lat):.1f} | {max(lat):.1f} | "
          f"{statistics.median(cpu):.2f} | {max(cpu):.2f} | {statistics.median(render):.1f} |")
print(f"\nmedian of runs: latency median {statistics.median(m[0] for m in meds):.1f} ms, "
      f"max {statistics.median(m[1] for m in meds):.1f} ms, capture CPU "
      f"{statistics.median(m[2] for m in meds):.2f} ms/frame")
EOS
echo
"$B/tests/test_depth_heights" --report
