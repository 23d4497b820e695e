#!/usr/bin/env bash
# kiosk_reload_soak.sh — issue 13's "a kiosk survives 100 reloads
# alternating good scenes and scenes the renderer refuses, with fds and
# memory flat".  The kiosk runs headless; each SIGHUP swaps the scene file
# between a good scene and one that loads but that the GLES renderer refuses
# (a 2100-texel-wide field with a local light: the kiosk runs under strict
# limits, ES 3.0's 2048-texel textures, and a local light keeps the field
# from tiles, so the refusal exists on any driver).  After every
# reload it must still run; the open descriptors after reload 100 must equal
# those after reload 10, and the resident memory may grow by at most 1 MiB
# between them.  Prints the numbers.
# usage: kiosk_reload_soak.sh KIOSK HFGEN [RELOADS]
set -u
KIOSK=$1 HFGEN=$2 N=${3:-100}
w=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill -KILL $pid 2>/dev/null; rm -rf "$w"' EXIT
"$HFGEN" cones --size 48x40 -o "$w/h.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
sky="3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0"
printf 'height = h.pfm\nenv-sh = %s\nbackend = gles\nkey = 30,20,2,10\n' "$sky" >"$w/good.ini"
"$HFGEN" cones --size 2100x3 -o "$w/wide.pfm" >/dev/null || { echo "FAIL: hfgen"; exit 1; }
printf 'height = wide.pfm\nenv-sh = %s\nbackend = gles\nkey = 30,20,2,10\nlocal = 10,1,5,0.5,100\n' "$sky" >"$w/refused.ini"
cp "$w/good.ini" "$w/scene.ini"
HFS_GL_STRICT_LIMITS=1 "$KIOSK" "$w/scene.ini" --display headless 2>"$w/log" &
pid=$!
for _ in $(seq 100); do grep -q started "$w/log" && break; sleep 0.1; done
if ! grep -q started "$w/log"; then
    if grep -q "GL context\|EGL" "$w/log" && [ "${HFS_REQUIRE_GL:-0}" != 1 ]; then
        echo "SKIP: no GLES context: $(head -1 "$w/log")"; exit 77
    fi
    echo "FAIL: the kiosk did not start"; cat "$w/log"; exit 1
fi
fds() { ls /proc/$pid/fd | wc -l; }
rss() { awk '/VmRSS/ {print $2}' /proc/$pid/status; }
fd10= rss10= ok=0 refused=0
t0=$(date +%s%N)
for i in $(seq 1 "$N"); do
    if [ $((i % 2)) = 1 ]; then cp "$w/refused.ini" "$w/scene.ini"; else cp "$w/good.ini" "$w/scene.ini"; fi
    before=$(grep -c reload "$w/log")
    kill -HUP $pid || { echo "FAIL: the kiosk is gone before reload $i"; tail -3 "$w/log"; exit 1; }
    for _ in $(seq 200); do [ "$(grep -c reload "$w/log")" -gt "$before" ] && break; sleep 0.02; done
    if ! kill -0 $pid 2>/dev/null; then echo "FAIL: the kiosk exited at reload $i"; tail -3 "$w/log"; exit 1; fi
    [ "$(grep -c reload "$w/log")" -gt "$before" ] || { echo "FAIL: no reload line for reload $i"; exit 1; }
    if [ "$i" = 10 ]; then fd10=$(fds); rss10=$(rss); fi
done
t1=$(date +%s%N)
fd100=$(fds) rss100=$(rss)
ok=$(grep -c "reloaded" "$w/log")
refused=$(grep -c "reload failed" "$w/log")
kill -TERM $pid; wait $pid; rc=$?; pid=
echo "reloads $N: $ok swapped in, $refused refused and kept the running scene; $(( (t1 - t0) / 1000000 / N )) ms a reload"
echo "fds after reload 10: $fd10, after reload $N: $fd100; VmRSS $rss10 kB -> $rss100 kB"
fail=0
[ $rc -eq 0 ] || { echo "FAIL: exit status $rc after SIGTERM"; fail=1; }
[ "$ok" -eq $((N / 2)) ] && [ "$refused" -eq $(((N + 1) / 2)) ] || { echo "FAIL: expected $((N / 2)) swaps, $(((N + 1) / 2)) refusals"; fail=1; }
[ "$fd10" = "$fd100" ] || { echo "FAIL: descriptors grew"; fail=1; }
[ $((rss100 - rss10)) -le 1024 ] || { echo "FAIL: memory grew by $((rss100 - rss10)) kB"; fail=1; }
[ $fail = 0 ] && echo PASS
exit $fail
