#!/usr/bin/env bash
# install.sh BUILD_DIR SOURCE_DIR VERSION — `cmake --install` into a fresh
# prefix, then use what was installed as someone else would
# (docs/INSTALL.md):
#   1. the files land in their conventional places (lib, include/hfshade,
#      lib/pkgconfig, lib/cmake/hfshade, bin, etc/hfshade, lib/systemd/system,
#      share/hfshade), the unit's ExecStart names the installed kiosk and
#      configuration, `hfshade --version` prints VERSION, and the installed
#      demo scene passes `hfshade --check`;
#   2. libhfshade.so.VERSION has the SONAME libhfshade.so.MAJOR, needs only
#      libc/libm/libEGL (no libpng, OpenEXR, inih, gpiod...), and exports
#      exactly the functions the installed headers declare HFS_API;
#   3. tests/install/consumer.c built with `pkg-config --cflags --libs
#      hfshade` and, as a CMake project, with find_package(hfshade) +
#      hfshade::hfshade, each run against the installed library (not the
#      build tree's): versions agree, CPU render, GLES render or skip;
#   4. tools/examples/embed_mesh built both ways too (it also links
#      libEGL/libGLESv2 itself) and run: its PPM, or a skip without GLES;
#   5. libhfshade_gis.so.VERSION (SONAME, needs libhfshade, exports exactly
#      hfshade_gis.h's HFS_GIS_API functions) and the Python module
#      (lib/python3/dist-packages/hfshade) imported by /usr/bin/python3 from
#      the prefix, the libraries found by their SONAMEs, rendering and
#      computing an SVF (skipped, said so, without numpy/cffi).
set -euo pipefail
build=$1 src=$2 version=$3
major=${version%%.*}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "install: FAIL: $*"; fail=1; }

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; exit 1; }
pc=$(find "$prefix" -path '*/pkgconfig/hfshade.pc' | head -1)
[ -n "$pc" ] || { bad "no LIBDIR/pkgconfig/hfshade.pc installed"; exit 1; }
libdir=$(sed -n 's/^libdir=${prefix}\///p' "$pc")   # lib or lib/<triplet>
[ -n "$libdir" ] || { bad "$pc: no libdir=\${prefix}/..."; exit 1; }

# 1. places
for f in "$libdir/libhfshade.so.$version" "$libdir/libhfshade.so.$major" "$libdir/libhfshade.so" \
         include/hfshade/hfshade.h include/hfshade/hfshade_inputs.h include/hfshade/hfshade_version.h \
         include/hfshade/hfshade_horizons.h \
         include/hfshade/hfshade_envmap.h include/hfshade/hfshade_gis.h \
         "$libdir/libhfshade_gis.so.$version" "$libdir/libhfshade_gis.so.$major" "$libdir/libhfshade_gis.so" \
         lib/python3/dist-packages/hfshade/__init__.py lib/python3/dist-packages/hfshade/_ffi.py \
         share/doc/python3-hfshade/examples/svf_geotiff.py \
         "$libdir/pkgconfig/hfshade.pc" "$libdir/cmake/hfshade/hfshadeConfig.cmake" \
         "$libdir/cmake/hfshade/hfshadeConfigVersion.cmake" "$libdir/cmake/hfshade/hfshadeTargets.cmake" \
         bin/hfshade bin/hfgen bin/hfbench bin/hfshade-kiosk bin/hfs-capture-info bin/hfs-capture-synth \
         etc/hfshade/kiosk.ini etc/hfshade/demo.ini lib/systemd/system/hfshade-kiosk.service \
         share/hfshade/jacksboro.png share/hfshade/courtyard.exr share/doc/hfshade-kiosk/KIOSK.md; do
    [ -e "$prefix/$f" ] || bad "not installed: $f"
done
[ "$(readlink "$prefix/$libdir/libhfshade.so.$major")" = "libhfshade.so.$version" ] ||
    bad "libhfshade.so.$major does not point at libhfshade.so.$version"
# Only what a consumer needs: no test programs, no static internals.
extra=$(cd "$prefix" && find . -type f -name '*.a' -o -type f -name 'test_*' | head -3)
[ -z "$extra" ] || bad "installed internals: $extra"
grep -q "^ExecStart=$prefix/bin/hfshade-kiosk $prefix/etc/hfshade/demo.ini --input $prefix/etc/hfshade/kiosk.ini" \
    "$prefix/lib/systemd/system/hfshade-kiosk.service" || bad "the unit's ExecStart is not the installed kiosk"
[ "$("$prefix/bin/hfshade" --version)" = "hfshade $version" ] ||
    bad "installed hfshade --version: '$("$prefix/bin/hfshade" --version 2>&1)', expected 'hfshade $version'"
"$prefix/bin/hfshade" render "$prefix/etc/hfshade/demo.ini" --backend cpu --check >"$tmp/check.out" 2>&1 ||
    bad "installed demo scene: $(cat "$tmp/check.out")"

# 2. the shared library
so=$prefix/$libdir/libhfshade.so.$version
readelf -d "$so" | grep -q "SONAME.*\[libhfshade.so.$major\]" || bad "SONAME is not libhfshade.so.$major"
needed=$(readelf -d "$so" | sed -n 's/.*NEEDED.*\[\(.*\)\]/\1/p' | sort | tr '\n' ' ')
for n in $needed; do
    case $n in
        libc.so.*|libm.so.*|libEGL.so.*|libdl.so.*|libpthread.so.*|ld-linux*) ;;
        *) bad "libhfshade needs $n (only libc, libm, libEGL allowed)" ;;
    esac
done
nm -D --defined-only "$so" | awk '{print $3}' | grep -vE '^(_init|_fini|_edata|_end|__bss_start)$' |
    sort -u >"$tmp/exported"
cat "$prefix"/include/hfshade/*.h | tr '\n' ' ' |
    grep -oE 'HFS_API[^;{(]*[( ]' | grep -oE 'hfs_[a-z0-9_]+ *\($' | tr -d ' (' | sort -u >"$tmp/declared"
[ -s "$tmp/declared" ] || bad "no HFS_API declarations found in the installed headers"
if ! diff "$tmp/declared" "$tmp/exported" >"$tmp/symdiff"; then
    bad "exported symbols differ from the headers' HFS_API functions (< declared only, > exported only):"
    cat "$tmp/symdiff"
fi
echo "install: libhfshade.so.$major needs: $needed; exports $(wc -l <"$tmp/exported") functions"

# 3. consumers, run against the installed library
export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
cc -std=c11 -Wall -Wextra -Werror -pedantic "$src/tests/install/consumer.c" -o "$tmp/consumer-pc" \
    $(pkg-config --cflags --libs hfshade) -lm || bad "pkg-config build"
cmake -S "$src/tests/install" -B "$tmp/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release >"$tmp/cmake.log" 2>&1 &&
    cmake --build "$tmp/cmake-build" >>"$tmp/cmake.log" 2>&1 || { cat "$tmp/cmake.log"; bad "find_package build"; }
for exe in "$tmp/consumer-pc" "$tmp/cmake-build/consumer"; do
    [ -x "$exe" ] || continue
    lib=$(LD_LIBRARY_PATH=$prefix/$libdir ldd "$exe" | sed -n 's/.*libhfshade.so.[0-9]* => \([^ ]*\).*/\1/p')
    case $lib in
        "$prefix"/*) ;;
        *) bad "$(basename "$(dirname "$exe")")/consumer resolves libhfshade to '$lib', not the installed one" ;;
    esac
    LD_LIBRARY_PATH=$prefix/$libdir "$exe" "$version" || bad "$exe failed"
done
# 4. tools/examples/embed_mesh: an application drawing its own GL scene with
#    the lit texture (issue 20), built both ways against the installed
#    package, run against it: a 640x400 PPM, or a skip without EGL/GLES.
ex=$src/tools/examples/embed_mesh
cc -std=c11 -Wall -Wextra -Werror -pedantic "$ex/embed_mesh.c" -o "$tmp/embed-pc" \
    $(pkg-config --cflags --libs hfshade egl glesv2) -lm || bad "embed_mesh: pkg-config build"
cmake -S "$ex" -B "$tmp/embed-build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
      >"$tmp/embed.log" 2>&1 && cmake --build "$tmp/embed-build" >>"$tmp/embed.log" 2>&1 ||
    { cat "$tmp/embed.log"; bad "embed_mesh: find_package build"; }
for exe in "$tmp/embed-pc" "$tmp/embed-build/embed_mesh"; do
    [ -x "$exe" ] || continue
    rc=0
    LD_LIBRARY_PATH=$prefix/$libdir "$exe" "$tmp/embed.ppm" 3 || rc=$?
    if [ $rc = 77 ]; then
        [ "${HFS_REQUIRE_GL:-0}" = 1 ] && bad "$exe: no GLES context (HFS_REQUIRE_GL=1)"
        continue
    fi
    [ $rc = 0 ] || { bad "$exe failed ($rc)"; continue; }
    [ "$(head -c 15 "$tmp/embed.ppm" | tr '\n' ' ')" = "P6 640 400 255 " ] ||
        bad "$exe: $tmp/embed.ppm is not a 640x400 PPM"
done
# 5. libhfshade_gis and the Python module
gso=$prefix/$libdir/libhfshade_gis.so.$version
readelf -d "$gso" | grep -q "SONAME.*\[libhfshade_gis.so.$major\]" || bad "libhfshade_gis: SONAME is not libhfshade_gis.so.$major"
gneeded=$(readelf -d "$gso" | sed -n 's/.*NEEDED.*\[\(.*\)\]/\1/p' | sort | tr '\n' ' ')
for n in $gneeded; do
    case $n in
        "libhfshade.so.$major"|libc.so.*|libm.so.*) ;;
        *) bad "libhfshade_gis needs $n (only libhfshade, libc, libm allowed)" ;;
    esac
done
nm -D --defined-only "$gso" | awk '{print $3}' | grep -vE '^(_init|_fini|_edata|_end|__bss_start)$' |
    sort -u >"$tmp/gis_exported"
tr '\n' ' ' <"$prefix/include/hfshade/hfshade_gis.h" | grep -oE 'HFS_GIS_API[^;{(]*[( ]' |
    grep -oE 'hfs_[a-z0-9_]+ *\($' | tr -d ' (' | sort -u >"$tmp/gis_declared"
[ -s "$tmp/gis_declared" ] || bad "no HFS_GIS_API declarations in hfshade_gis.h"
diff "$tmp/gis_declared" "$tmp/gis_exported" >"$tmp/gis_symdiff" ||
    { bad "libhfshade_gis exports differ from hfshade_gis.h (< declared only, > exported only):"; cat "$tmp/gis_symdiff"; }
py=/usr/bin/python3
if [ -x $py ] && $py -c 'import numpy, cffi' 2>/dev/null; then
    (cd "$tmp" && env -u HFSHADE_LIBRARY -u HFSHADE_GIS_LIBRARY PYTHONDONTWRITEBYTECODE=1 \
        PYTHONPATH="$prefix/lib/python3/dist-packages" LD_LIBRARY_PATH="$prefix/$libdir" $py -c "
import numpy as np, hfshade
assert hfshade.__file__.startswith('$prefix/'), hfshade.__file__
assert hfshade.library_version() == '$version', hfshade.library_version()
z = np.add.outer(np.sin(np.arange(24) / 3.0), np.cos(np.arange(32) / 4.0)).astype(np.float32)
img = hfshade.render(z, backend='cpu', dx=2.0, key=[(30, 40, 2, 3.0)], env=np.ones(16))
assert img.shape == (24, 32, 3) and np.isfinite(img).all() and img.max() > 0
v = hfshade.svf(z, 2.0, backend='cpu')
assert v.shape == (24, 32) and 0 < v.min() and v.max() <= 1
print('install: python3-hfshade: render and svf from', hfshade.__file__)
") || bad "the installed Python module"
else
    echo "install: python3-hfshade: not checked ($py without numpy or cffi)"
fi
[ $fail = 0 ] && echo "install: ok"
exit $fail
