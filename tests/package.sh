#!/usr/bin/env bash
# package.sh BUILD_DIR VERSION — `cpack -G DEB` on the build (into a
# temporary directory), then each package's contents and control fields
# (cmake/package.cmake, docs/INSTALL.md):
#   - exactly libhfshade0, libhfshade-dev, hfshade-tools, hfshade-kiosk,
#     python3-hfshade (Architecture: all);
#   - each holds its own files and only them, under /usr, /etc/hfshade and
#     /lib/systemd/system (never /usr/local), no file in two packages, every
#     ELF file stripped;
#   - Depends: libhfshade-dev and python3-hfshade on libhfshade0 (= VERSION),
#     python3-hfshade also on python3-numpy and python3-cffi (Suggests
#     python3-gdal); libhfshade0 on
#     libc6 and libegl1 only; the tools and the kiosk on the libraries they
#     link (libpng, OpenEXR, inih; the kiosk also gpiod, evdev, DRM/GBM, X11,
#     adduser); every dependency a package dpkg knows here;
#   - every package has /usr/share/doc/PACKAGE/{copyright,changelog.gz};
#   - libhfshade0 carries a shlibs file and an ldconfig trigger; the kiosk marks
#     /etc/hfshade/*.ini as conffiles, and its unit runs /usr/bin/hfshade-kiosk
#     on /etc/hfshade/; its postinst is valid sh;
#   - lintian, where installed, finds no error.
set -euo pipefail
build=$1 version=$2
major=${version%%.*}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "package: FAIL: $*"; fail=1; }

cpack -G DEB -B "$tmp/out" --config "$build/CPackConfig.cmake" >"$tmp/cpack.log" 2>&1 ||
    { cat "$tmp/cpack.log"; echo "package: FAIL: cpack -G DEB"; exit 1; }
arch=$(dpkg --print-architecture)
names="libhfshade$major libhfshade-dev hfshade-tools hfshade-kiosk python3-hfshade"
debarch() { case $1 in python3-*) echo all ;; *) echo "$arch" ;; esac; }
got=$(cd "$tmp/out" && ls -- *.deb | sort | tr '\n' ' ')
want=$(for n in $names; do echo "${n}_${version}_$(debarch "$n").deb"; done | sort | tr '\n' ' ')
[ "$got" = "$want" ] || { bad "packages: '$got', expected '$want'"; exit 1; }

deb() { echo "$tmp/out/${1}_${version}_$(debarch "$1").deb"; }
files() { dpkg-deb -c "$(deb "$1")" | awk '$1 !~ /^d/ {print $6}' | sed 's|^\./|/|' | sort; }
depends() { dpkg-deb -f "$(deb "$1")" Depends; }
expect_files() { # PACKAGE FILE... : exactly these files (and links), and its doc files
    local p=$1; shift
    printf '%s\n' "$@" "/usr/share/doc/$p/copyright" "/usr/share/doc/$p/changelog.gz" | sort >"$tmp/want"
    files "$p" >"$tmp/got"
    diff "$tmp/want" "$tmp/got" >"$tmp/diff" || { bad "$p: contents (< missing, > unexpected):"; cat "$tmp/diff"; }
}

libdir=$(files libhfshade-dev | sed -n 's|^\(.*\)/pkgconfig/hfshade.pc$|\1|p')
case $libdir in /usr/lib|/usr/lib/*-linux-*) ;; *) bad "libdir '$libdir' is not /usr/lib[/triplet]" ;; esac
expect_files "libhfshade$major" "$libdir/libhfshade.so.$major" "$libdir/libhfshade.so.$version" \
    "$libdir/libhfshade_gis.so.$major" "$libdir/libhfshade_gis.so.$version"
expect_files libhfshade-dev /usr/include/hfshade/hfshade.h /usr/include/hfshade/hfshade_inputs.h \
    /usr/include/hfshade/hfshade_horizons.h \
    /usr/include/hfshade/hfshade_version.h /usr/include/hfshade/hfshade_envmap.h \
    /usr/include/hfshade/hfshade_gis.h "$libdir/libhfshade_gis.so" \
    "$libdir/libhfshade.so" "$libdir/pkgconfig/hfshade.pc" \
    "$libdir/cmake/hfshade/hfshadeConfig.cmake" "$libdir/cmake/hfshade/hfshadeConfigVersion.cmake" \
    "$libdir/cmake/hfshade/hfshadeTargets.cmake" \
    $(files libhfshade-dev | grep "^$libdir/cmake/hfshade/hfshadeTargets-[a-z]*\.cmake$")
expect_files hfshade-tools /usr/bin/hfshade /usr/bin/hfgen /usr/bin/hfbench
expect_files hfshade-kiosk /usr/bin/hfshade-kiosk /usr/bin/hfs-capture-info /usr/bin/hfs-capture-synth \
    /etc/hfshade/kiosk.ini /etc/hfshade/demo.ini /lib/systemd/system/hfshade-kiosk.service \
    /usr/share/hfshade/demo.ini /usr/share/hfshade/demo-objects.txt \
    /usr/share/hfshade/jacksboro.png /usr/share/hfshade/courtyard.exr \
    /usr/share/doc/hfshade-kiosk/KIOSK.md /usr/share/doc/hfshade-kiosk/INPUT.md
py=/usr/lib/python3/dist-packages/hfshade
expect_files python3-hfshade $py/__init__.py $py/_errors.py $py/_ffi.py $py/envmap.py $py/gis.py \
    $py/render.py /usr/share/doc/python3-hfshade/examples/svf_geotiff.py
dups=$(for n in $names; do files "$n"; done | sort | uniq -d)
[ -z "$dups" ] || bad "files in two packages: $dups"

# Depends
dev_dep=$(depends libhfshade-dev)
[ "$dev_dep" = "libhfshade$major (= $version)" ] || bad "libhfshade-dev Depends: '$dev_dep'"
py_dep=$(depends python3-hfshade)
[ "$py_dep" = "libhfshade$major (= $version), python3:any, python3-numpy, python3-cffi" ] ||
    bad "python3-hfshade Depends: '$py_dep'"
[ "$(dpkg-deb -f "$(deb python3-hfshade)" Suggests)" = python3-gdal ] ||
    bad "python3-hfshade Suggests: '$(dpkg-deb -f "$(deb python3-hfshade)" Suggests)'"
lib_dep=$(depends "libhfshade$major")
for d in $(echo "$lib_dep" | tr ',' '\n' | sed 's/(.*//; s/ //g'); do
    case $d in libc6|libegl1) ;; *) bad "libhfshade$major depends on $d (only libc6, libegl1)" ;; esac
done
echo "$lib_dep" | grep -q "libc6 (>=" || bad "libhfshade$major Depends lacks libc6: '$lib_dep'"
echo "$lib_dep" | grep -q "libegl1" || bad "libhfshade$major Depends lacks libegl1: '$lib_dep'"
for need in libpng16-16 libopenexr libinih1 libegl1 libc6; do
    depends hfshade-tools | grep -q "$need" || bad "hfshade-tools does not depend on $need"
    depends hfshade-kiosk | grep -q "$need" || bad "hfshade-kiosk does not depend on $need"
done
# GDAL is loaded at run time (tools/gdal/gdal_lazy.h): named by hand.
if grep -q '^HFS_GDAL_FILE:INTERNAL=.' "$build/CMakeCache.txt"; then
    depends hfshade-tools | grep -q "libgdal[0-9]* (>=" || bad "hfshade-tools does not depend on libgdal"
    depends hfshade-kiosk | grep -q "libgdal[0-9]* (>=" || bad "hfshade-kiosk does not depend on libgdal"
fi
for need in adduser libgpiod libevdev libdrm libgbm libx11; do
    depends hfshade-kiosk | grep -q "$need" || bad "hfshade-kiosk does not depend on $need"
done
for n in $names; do
    for d in $(depends "$n" | tr ',|' '\n\n' | sed 's/(.*//; s/ //g'); do
        case $d in libhfshade$major|python3:any) continue ;; esac
        dpkg-query -W "$d" >/dev/null 2>&1 || bad "$n depends on $d, a package dpkg does not know here"
    done
    echo "package: $n Depends: $(depends "$n")"
done

# Control files, unit, stripping
mkdir -p "$tmp/ctl" "$tmp/data"
for n in $names; do
    dpkg-deb -e "$(deb "$n")" "$tmp/ctl/$n"
    dpkg-deb -x "$(deb "$n")" "$tmp/data"
done
grep -qx "libhfshade $major libhfshade$major (>= $version)" "$tmp/ctl/libhfshade$major/shlibs" 2>/dev/null ||
    bad "libhfshade$major: no shlibs line 'libhfshade $major libhfshade$major (>= $version)'"
grep -qx "activate-noawait ldconfig" "$tmp/ctl/libhfshade$major/triggers" 2>/dev/null ||
    bad "libhfshade$major has no ldconfig trigger"
for n in $names; do
    zcat "$tmp/data/usr/share/doc/$n/changelog.gz" | head -1 | grep -qx "$n ($version) unstable; urgency=medium" ||
        bad "$n: changelog.gz does not start with '$n ($version) unstable; urgency=medium'"
done
printf '/etc/hfshade/demo.ini\n/etc/hfshade/kiosk.ini\n' >"$tmp/conf.want"
sort "$tmp/ctl/hfshade-kiosk/conffiles" 2>/dev/null | diff "$tmp/conf.want" - >/dev/null ||
    bad "hfshade-kiosk conffiles: '$(cat "$tmp/ctl/hfshade-kiosk/conffiles" 2>/dev/null)'"
sh -n "$tmp/ctl/hfshade-kiosk/postinst" || bad "hfshade-kiosk postinst is not valid sh"
[ -x "$tmp/ctl/hfshade-kiosk/postinst" ] || bad "hfshade-kiosk postinst is not executable"
grep -qx "ExecStart=/usr/bin/hfshade-kiosk /etc/hfshade/demo.ini --input /etc/hfshade/kiosk.ini --display kms" \
    "$tmp/data/lib/systemd/system/hfshade-kiosk.service" || bad "the packaged unit's ExecStart"
grep -qx "height = /usr/share/hfshade/jacksboro.png.*" "$tmp/data/etc/hfshade/demo.ini" ||
    bad "/etc/hfshade/demo.ini does not name /usr/share/hfshade/jacksboro.png"
grep -q "^prefix=/usr$" "$tmp/data$libdir/pkgconfig/hfshade.pc" || bad "hfshade.pc prefix is not /usr"
while read -r f; do
    if file -b "$f" | grep -q '^ELF' && ! file -b "$f" | grep -q ', stripped'; then
        bad "not stripped: ${f#"$tmp/data"}"
    fi
done < <(find "$tmp/data" -type f)

if command -v lintian >/dev/null; then
    lintian --fail-on error "$tmp"/out/*.deb >"$tmp/lintian.out" 2>&1 ||
        { grep '^E:' "$tmp/lintian.out"; bad "lintian reports errors"; }
    echo "package: lintian: $(grep -c '^E:' "$tmp/lintian.out") errors, $(grep -c '^W:' "$tmp/lintian.out") warnings"
else
    echo "package: lintian not installed: not run"
fi
[ $fail = 0 ] && echo "package: ok"
exit $fail
