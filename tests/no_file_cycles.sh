#!/bin/bash
# no_file_cycles.sh — the layering rule of issue 34, checked: no two
# translation units of the runtime libraries call each other, directly or
# round a longer circle.  A circle means neither file can be read, tested
# or moved without the other; one-way dependencies keep each file below
# the ones that use it.
#
# Reads every static library under BUILD_DIR/runtime (recursively: the
# libraries live in per-folder build directories; the shared library holds
# the same objects merged, so it is not read), builds the graph object ->
# object (an undefined symbol of one object defined, T/D/B/R or weak, by
# another) and finds its strongly connected components (Tarjan).  Every
# component of more than one object is a cycle; each is named with one
# symbol per edge, so the call to move is plain.
#   tests/no_file_cycles.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: no_file_cycles.sh BUILD_DIR}
mapfile -t libs < <(find "$build/runtime" -name 'lib*.a' | sort)
if [ ${#libs[@]} -eq 0 ]; then
    echo "no_file_cycles: no static libraries under $build/runtime (build first)"
    exit 1
fi
# nm -A: "LIB:MEMBER:ADDR TYPE SYMBOL" (ADDR blank for undefined symbols).
cycles=$(nm -A "${libs[@]}" 2>/dev/null | awk -v prefix="$build/" '
    function node_of(field,   n) {
        n = field
        sub(/:[0-9a-fA-F]*$/, "", n)
        if (index(n, prefix) == 1)
            n = substr(n, length(prefix) + 1)
        if (!(n in known)) {
            known[n] = 1
            order[++n_nodes] = n
        }
        return n
    }
    NF == 3 && $2 == "U" { v = node_of($1); ref_from[++n_refs] = v; ref_sym[n_refs] = $3; next }
    NF == 3 && $2 ~ /^[TDBRWV]$/ { v = node_of($1); if (!($3 in definer)) definer[$3] = v }
    function strong(v,   i, w, size, members) {
        num[v] = low[v] = ++counter
        stack[++sp] = v
        on_stack[v] = 1
        for (i = 1; i <= n_out[v]; i++) {
            w = out[v, i]
            if (!(w in num)) {
                strong(w)
                if (low[w] < low[v]) low[v] = low[w]
            } else if (on_stack[w] && num[w] < low[v])
                low[v] = num[w]
        }
        if (low[v] != num[v])
            return
        size = 0
        do {
            w = stack[sp--]
            on_stack[w] = 0
            member[w] = v
            members = members "\n    " w
            size++
        } while (w != v)
        if (size > 1)
            report(v, members, size)
    }
    function report(root, members, size,   i, j, a, b) {
        printf "cycle of %d files:%s\n  calls inside it:\n", size, members
        for (i = 1; i <= n_nodes; i++) {
            a = order[i]
            if (member[a] != root) continue
            for (j = 1; j <= n_out[a]; j++) {
                b = out[a, j]
                if (member[b] == root)
                    printf "    %s -> %s (%s)\n", a, b, via[a, b]
            }
        }
    }
    END {
        for (i = 1; i <= n_refs; i++) {
            v = ref_from[i]
            if (!(ref_sym[i] in definer)) continue
            w = definer[ref_sym[i]]
            if (w == v || ((v, w) in via)) continue
            via[v, w] = ref_sym[i]
            out[v, ++n_out[v]] = w
        }
        for (i = 1; i <= n_nodes; i++)
            if (!(order[i] in num))
                strong(order[i])
    }')
if [ -n "$cycles" ]; then
    echo "no_file_cycles: translation units of runtime/ that call each other"
    echo "(move what the lower file needs below both):"
    echo "$cycles"
    exit 1
fi
echo "no_file_cycles: the object-file call graph of ${#libs[@]} runtime libraries has no cycle"
