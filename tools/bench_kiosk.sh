#!/usr/bin/env bash
# hfshade-kiosk: input-to-photon latency and idle CPU (board/KIOSK.md).
#
# Latency: a headless kiosk (frames kept in memory, not written) on a 256x256
# fractal terrain under the demo sky (courtyard.exr) and a key light, with
# the default quality preset (kiosk), replays EVENTS knob turns SPACING_MS
# apart, cycling environment rotation, key azimuth and key elevation.  For
# each event the --stats file holds the event's timestamp and the
# CLOCK_MONOTONIC time right after hfs_display_present returned for the
# frame showing it; latency = the difference.  The first frame (start-up,
# every pass) is not an event and is excluded.
# Idle CPU: the same kiosk with no input for IDLE_S seconds after its first
# frame; CPU = user + system time of the whole process (getrusage, every
# thread) over that wall time.
#
# Read-back vs texture (issue 20), with COMPARE=x11 in the environment
# instead of the two above: the same replay on an x11 window (one Xvfb,
# xvfb-run; --size 256x256, the field 1:1) run ROUNDS times in turn with
# --readback (render, read back, sRGB on the CPU, upload, draw) and with the
# renderer sharing the window's context (the sRGB picture encoded on the GPU
# into a texture the window draws: no read-back, no upload), side by side:
# latency as above, render = the kiosk's render step (render_texture vs
# render + read-back), CPU per frame = the process's user + system CPU
# between consecutive frames (getrusage: llvmpipe's threads included, so
# on this machine the GPU's work is CPU too).
#
# usage: tools/bench_kiosk.sh BUILD_DIR [EVENTS] [SPACING_MS] [IDLE_S]
#        defaults 100 events, 150 ms, 10 s
#        COMPARE=x11 [ROUNDS=2] tools/bench_kiosk.sh BUILD_DIR [EVENTS] [SPACING_MS]
set -euo pipefail
cd "$(dirname "$0")/.."
B=$(cd "$1" && pwd); N=${2:-100}; SPACING=${3:-150}; IDLE=${4:-10}
K=$B/board/hfshade-kiosk
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT

$B/tools/hfgen fractal --size 256x256 -o "$T/terrain.pfm" >/dev/null
cat >"$T/scene.ini" <<EOS
height = terrain.pfm
env-map = $PWD/data/courtyard.exr
key = 95,30,2.5,400
albedo = 0.35
EOS
cat >"$T/knobs.ini" <<'EOS'
[knob environment]
action = env.rotate
step = 5
[knob azimuth]
action = key.azimuth
step = 2
[knob elevation]
action = key.elevation
step = 1
min = 5
max = 85
EOS
# Events: env, azimuth, elevation in turn; elevation goes up and down so
# every event changes the scene (no clamping).
awk -v n="$N" -v dt="$SPACING" 'BEGIN {
  split("environment azimuth elevation", k, " ");
  for (i = 0; i < n; ++i) {
    c = k[i % 3 + 1]; d = (c == "elevation" && int(i / 3) % 2) ? -1 : 1;
    printf "%d %s turn %d\n", 200 + i * dt, c, d } }' >"$T/events.txt"

if [ "${COMPARE:-}" = x11 ]; then
    ROUNDS=${ROUNDS:-2}
    cat >"$T/runs.sh" <<EOS
set -e
for r in \$(seq $ROUNDS); do
  for mode in readback texture; do
    flag=; [ \$mode = readback ] && flag=--readback
    "$K" "$T/scene.ini" --input "$T/knobs.ini" --replay "$T/events.txt" --display x11 \\
        --size 256x256 --stats "$T/\$mode.\$r.txt" --exit-after-replay \$flag 2>"$T/\$mode.\$r.log"
  done
done
EOS
    xvfb-run -a -s "-screen 0 640x480x24" bash "$T/runs.sh"
    python3 - "$T" "$ROUNDS" <<'EOS'
import glob, statistics, sys
T, rounds = sys.argv[1], int(sys.argv[2])
def pct(v, q): v = sorted(v); return v[int(q * (len(v) - 1))]
print("| path | events | latency median ms | p90 ms | max ms | render median ms | CPU per frame median ms | mean ms |")
print("|---|---|---|---|---|---|---|---|")
for mode in ("readback", "texture"):
    lat, ren, cpu = [], [], []
    for path in sorted(glob.glob(f"{T}/{mode}.*.txt")):
        frames = {}
        for line in open(path):
            f = line.split()
            if f[0] == "frame": frames[int(f[1])] = (float(f[3]), int(f[7]))
            if f[0] == "event" and f[5] == "1": lat.append(int(f[3]) / 1e6)
        ns = sorted(frames)
        ren += [frames[n][0] for n in ns[1:]]
        cpu += [(frames[b][1] - frames[a][1]) / 1e3 for a, b in zip(ns[1:], ns[2:])]
    print(f"| {mode} | {len(lat)} | {statistics.median(lat):.1f} | {pct(lat, 0.9):.1f} | "
          f"{max(lat):.1f} | {statistics.median(ren):.1f} | {statistics.median(cpu):.1f} | "
          f"{statistics.mean(cpu):.1f} |")
EOS
    exit 0
fi

"$K" "$T/scene.ini" --input "$T/knobs.ini" --replay "$T/events.txt" --display headless \
    --stats "$T/latency.txt" --exit-after-replay 2>"$T/latency.log"

# Idle: start, wait for the first frame, leave alone, SIGTERM.
"$K" "$T/scene.ini" --input "$T/knobs.ini" --display headless --stats "$T/idle.txt" \
    2>"$T/idle.log" &
pid=$!
for _ in $(seq 600); do grep -q '^frame 0 ' "$T/idle.txt" 2>/dev/null && break; sleep 0.1; done
sleep "$IDLE"
kill -TERM $pid; wait $pid

python3 - "$T/latency.txt" "$T/idle.txt" <<'EOS'
import statistics, sys
lat = {}; render = {}; frames = {}; passes = {}
for line in open(sys.argv[1]):
    f = line.split()
    if f[0] == "frame":
        frames[int(f[1])] = (float(f[3]), int(f[4]), int(f[5]))
    if f[0] == "event" and f[5] == "1":
        lat.setdefault(f[6], []).append(int(f[3]) / 1e6)
        render.setdefault(f[6], []).append(frames[int(f[4])][0])
        passes.setdefault(f[6], []).append(frames[int(f[4])][1:])
every = sorted(x for v in lat.values() for x in v)
def row(name, v, r, p):
    v = sorted(v)
    ran = statistics.median_low([x[0] for x in p]); tot = p[0][1]
    print(f"| {name} | {len(v)} | {statistics.median(v):.1f} | {v[int(0.9 * (len(v) - 1))]:.1f} | {max(v):.1f} | {statistics.median(r):.1f} | {ran}/{tot} |")
print("| knob | events | latency median ms | p90 ms | max ms | render median ms | passes run (median) |")
print("|---|---|---|---|---|---|---|")
for k in sorted(lat):
    row(k, lat[k], render[k], passes[k])
row("all", every, [x for v in render.values() for x in v], [x for v in passes.values() for x in v])
first = None; last = None
for line in open(sys.argv[2]):
    f = line.split()
    if f[0] == "frame" and f[1] == "0": first = (int(f[2]), int(f[7]))
    if f[0] == "exit": last = (int(f[1]), int(f[2]), int(f[3]))
wall = (last[0] - first[0]) / 1e9; cpu = (last[1] - first[1]) / 1e6
print(f"\nidle: {cpu:.3f} s CPU over {wall:.1f} s = {100 * cpu / wall:.2f}% of one core, "
      f"{last[2] - 1} frame(s) after the first")
EOS
echo; grep -h started "$T/latency.log" | sed 's/^/latency run: /'
