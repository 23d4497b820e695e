#!/bin/bash
# include_rules.sh — the house rules of runtime/ (issue 34), checked on the
# sources.  Every #include in runtime/FOLDER/ must name a header of FOLDER
# itself, of the runtime/ root (hfshade.h, the public header, and its
# generated hfshade_version.h), or of a folder that runtime/FOLDER/README.md
# names on its one "May include:" line; the root's own files include only
# the root.  Nothing in runtime/ includes a header of board/ or tools/.
# runtime/CMakeLists.txt links each folder's library to the same folders,
# so the README line is the one place a rule is written.
#
# A header is found by its name (every header name in runtime/, board/ and
# tools/ is unique; a duplicate is reported, since it would make the rule
# ambiguous) or, for a path with a '/', by the path itself.  Quoted includes
# must resolve; <...> includes are checked when their name is ours.
#   tests/include_rules.sh SOURCE_DIR     (exit 0: all kept; 1: a violation)
set -u
src=${1:?usage: include_rules.sh SOURCE_DIR}
rt="$src/runtime"
[ -d "$rt" ] || { echo "include_rules: $rt: no such folder"; exit 2; }

# Generated at build time, with the folder that owns them.
generated=". hfshade_version.h
sh sh_product_gen.inc"

owners=$(mktemp)
trap 'rm -f "$owners"' EXIT
{
    echo "$generated"
    (cd "$rt" && find . -maxdepth 2 -type f \( -name '*.h' -o -name '*.def' -o -name '*.inc' \) |
        sed -E 's|^\./||; s|^([^/]*)$|. \1|; s|^([^/]*)/(.*)$|\1 \2|')
    for other in board tools; do
        [ -d "$src/$other" ] && (cd "$src/$other" && find . -type f -name '*.h' |
            sed -E "s|^.*/([^/]*)$|$other \\1|")
    done
} | sort -k2 >"$owners"

# owner_of[HEADER]: its folder, the first line of $owners that names it
# (read once: a lookup per #include was a process per #include).
declare -A owner_of
while read -r folder header; do
    [ -n "${owner_of[$header]+x}" ] || owner_of[$header]=$folder
done <"$owners"

rt_real=$(realpath "$rt")
src_real=$(realpath "$src")
fail=0
dups=$(awk '{ n[$2]++; f[$2] = f[$2] " " $1 } END { for (h in n) if (n[h] > 1) print h ":" f[h] }' "$owners")
if [ -n "$dups" ]; then
    echo "include_rules: header names used in more than one folder (rename one):"
    echo "$dups"
    fail=1
fi

# allowed FOLDER: the folders FOLDER may include, one line (in bash alone:
# on a machine where a process costs ~15 ms, a pipeline per folder was
# most of the script's time).
allowed() {
    [ "$1" = . ] && return
    local readme="$rt/$1/README.md" line rule="" n=0 w out=""
    if [ -f "$readme" ]; then
        while IFS= read -r line || [ -n "$line" ]; do
            [[ $line == "May include:"* ]] && rule=${line#May include:} && n=$((n + 1))
        done <"$readme"
    fi
    if [ "$n" != 1 ]; then
        echo "!missing"
        return
    fi
    for w in ${rule//[,.]/ }; do
        [ "$w" = nothing ] || out="${out:+$out }$w"
    done
    echo "$out"
}

for dir in . $(cd "$rt" && find . -mindepth 1 -maxdepth 1 -type d | sed 's|^\./||' | sort); do
    may=$(allowed "$dir")
    if [ "$may" = "!missing" ]; then
        echo "include_rules: runtime/$dir/README.md: needs exactly one 'May include:' line"
        fail=1
        continue
    fi
    # Every #include of the folder's files in one awk: FILE:LINE:QUOTE:NAME
    # (a process per file was most of this script's time).
    files=$(cd "$rt/$dir" && find . -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' \) | sort)
    [ -n "$files" ] || continue
    while IFS=: read -r f line quote name; do
        path="$rt/$dir/$f"
        owner=""
        if [[ $name == */* ]]; then
            # A path: the first place it exists decides (the file's own
            # folder, runtime/, the source root); else a system header.
            for base in "$(dirname "$path")" "$rt" "$src"; do
                [ -e "$base/$name" ] || continue
                real=$(realpath "$base/$name")
                case $real in
                "$rt_real"/*/*) owner=${real#"$rt_real"/}; owner=${owner%%/*} ;;
                "$rt_real"/*) owner=. ;;
                "$src_real"/board/*) owner=board ;;
                "$src_real"/tools/*) owner=tools ;;
                *) owner="?" ;;
                esac
                break
            done
        else
            owner=${owner_of[$name]:-}
        fi
        if [ -z "$owner" ] || [ "$owner" = "?" ]; then
            [ "$quote" = '"' ] || continue # a system header
            echo "runtime/$dir/$f:$line: includes \"$name\", which is no header of runtime/"
            fail=1
            continue
        fi
        [ "$owner" = "$dir" ] || [ "$owner" = . ] && continue
        case " $may " in *" $owner "*) continue ;; esac
        if [ "$owner" = board ] || [ "$owner" = tools ]; then
            echo "runtime/$dir/$f:$line: includes $name from $owner/: runtime/ never includes $owner/"
        else
            echo "runtime/$dir/$f:$line: includes $name from $owner/, which runtime/$dir/README.md does not allow (May include: ${may:-nothing})"
        fi
        fail=1
    done < <(cd "$rt/$dir" && awk '/^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]/ {
                      s = $0; sub(/^[[:space:]]*#[[:space:]]*include[[:space:]]*/, "", s)
                      name = substr(s, 2); sub(/[>"].*/, "", name)
                      f = FILENAME; sub(/^\.\//, "", f)
                      print f ":" FNR ":" substr(s, 1, 1) ":" name }' $files)
done
[ $fail = 0 ] && echo "include_rules: every #include in runtime/ keeps its folder's README rule"
exit $fail
