/*
 * test_presets.c — the quality presets (hfshade.h hfs_quality_preset) are
 * the settings the last measurement picked: for each use, the rows of
 * docs/bench/pareto-256.csv whose "use" column names it (tools/
 * bench_pareto.sh writes it) must have the preset's k, offset, directions,
 * sub-sampling, precision and visibility path; the defaults are the kiosk
 * preset; an unknown use is refused and leaves the defaults.
 *
 *   test_presets CSV
 */
#include "hfshade.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define NCOL 40

/* Splits a CSV line (no quoting in hfbench's output) in place. */
static int split(char *line, char **col)
{
    int n = 0;
    for (char *p = line; n < NCOL;) {
        col[n++] = p;
        char *c = strchr(p, ',');
        if (!c)
            break;
        *c = '\0';
        p = c + 1;
    }
    char *nl = strpbrk(col[n - 1], "\r\n");
    if (nl)
        *nl = '\0';
    return n;
}

static int column(char **head, int n, const char *name)
{
    for (int i = 0; i < n; ++i)
        if (!strcmp(head[i], name))
            return i;
    return -1;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_presets CSV\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "r");
    if (!f) {
        printf("FAIL: %s: cannot open\n", argv[1]);
        return 1;
    }
    char header[1024], line[1024];
    char *head[NCOL], *col[NCOL];
    if (!fgets(header, sizeof header, f)) {
        fclose(f);
        printf("FAIL: %s: empty\n", argv[1]);
        return 1;
    }
    const int nh = split(header, head);
    const int c_use = column(head, nh, "use"), c_k = column(head, nh, "k"),
              c_o = column(head, nh, "offset"), c_e = column(head, nh, "nphi_env"),
              c_key = column(head, nh, "nphi_key"), c_sub = column(head, nh, "subsample"),
              c_prec = column(head, nh, "precision"), c_vis = column(head, nh, "visibility");
    CHECK(c_use >= 0 && c_k >= 0 && c_o >= 0 && c_e >= 0 && c_key >= 0 && c_sub >= 0 &&
              c_prec >= 0 && c_vis >= 0, "%s: missing columns", argv[1]);
    static const char *const uses[] = {"kiosk", "panel", "headless"};
    int rows[3] = {0};
    while (!failures && fgets(line, sizeof line, f)) {
        const int n = split(line, col);
        if (n < nh)
            continue;
        for (int u = 0; u < 3; ++u) {
            if (!strstr(col[c_use], uses[u]))
                continue;
            hfs_quality q;
            CHECK(hfs_quality_preset(&q, uses[u]) == 0, "preset %s", uses[u]);
            const int prec_fp32 = !strcmp(col[c_prec], "fp32");
            const hfs_visibility_path vis = !strcmp(col[c_vis], "wedge")   ? HFS_VIS_WEDGE_TABLE
                                            : !strcmp(col[c_vis], "slice") ? HFS_VIS_SLICE
                                                                           : HFS_VIS_LEGENDRE;
            CHECK(q.k == atoi(col[c_k]) && q.offset == atoi(col[c_o]) &&
                      q.nphi_env == atoi(col[c_e]) && q.nphi_key == atoi(col[c_key]) &&
                      q.subsample == atoi(col[c_sub]) &&
                      (q.precision == HFS_PRECISION_FP32) == prec_fp32 &&
                      q.visibility == vis,
                  "preset %s (k%d o%d e%d k%d sub%d) is not the measured pick (k%s o%s e%s k%s "
                  "sub%s %s %s)", uses[u], q.k, q.offset, q.nphi_env, q.nphi_key, q.subsample,
                  col[c_k], col[c_o], col[c_e], col[c_key], col[c_sub], col[c_prec], col[c_vis]);
            ++rows[u];
        }
    }
    fclose(f);
    for (int u = 0; u < 3; ++u)
        CHECK(rows[u] > 0, "no row of %s picks %s", argv[1], uses[u]);
    hfs_quality d, k;
    hfs_quality_defaults(&d);
    hfs_quality_preset(&k, "kiosk");
    CHECK(!memcmp(&d, &k, sizeof d), "defaults differ from the kiosk preset");
    CHECK(hfs_quality_preset(&k, "museum") == HFS_E_INVALID && !memcmp(&d, &k, sizeof d),
          "unknown preset");
    printf("presets = measured picks (%d, %d, %d rows): %s\n", rows[0], rows[1], rows[2],
           failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
