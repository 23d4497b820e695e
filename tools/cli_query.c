/*
 * cli_query.c — see cli_query.h.
 */
#include "cli_query.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define QUERY_MAX_POINTS (1 << 24)

/* One "x y z" line into p; 0 or an error naming path:line. */
static int parse_line(const char *path, long line, char *s, double p[3], hfs_error *err)
{
    char *end = s;
    for (int k = 0; k < 3; ++k) {
        errno = 0;
        const char *start = end;
        p[k] = strtod(start, &end);
        if (end == start || errno == ERANGE || !isfinite(p[k]))
            return hfs_fail(err, HFS_E_FORMAT, "%s:%ld: expected three finite numbers \"x y z\"",
                            path, line);
    }
    while (isspace((unsigned char)*end))
        ++end;
    if (*end)
        return hfs_fail(err, HFS_E_FORMAT, "%s:%ld: unexpected text after \"x y z\"", path, line);
    return HFS_OK;
}

int cli_query_read_points(const char *path, double **xyz, int *n, hfs_error *err)
{
    *xyz = NULL, *n = 0;
    FILE *fp = fopen(path, "r");
    if (!fp)
        return hfs_fail(err, HFS_E_IO, "%s: %s", path, strerror(errno));
    int cap = 0, rc = HFS_OK;
    long line = 0;
    char buf[512];
    while (!rc && fgets(buf, sizeof buf, fp)) {
        ++line;
        if (!strchr(buf, '\n') && !feof(fp)) {
            rc = hfs_fail(err, HFS_E_FORMAT, "%s:%ld: line longer than %zu bytes", path, line,
                          sizeof buf - 2);
            break;
        }
        char *s = buf;
        while (isspace((unsigned char)*s))
            ++s;
        if (!*s || *s == '#')
            continue;
        if (*n == QUERY_MAX_POINTS) {
            rc = hfs_fail(err, HFS_E_FORMAT, "%s:%ld: more than %d points", path, line,
                          QUERY_MAX_POINTS);
            break;
        }
        if (*n == cap) {
            cap = cap ? 2 * cap : 256;
            double *grown = realloc(*xyz, (size_t)cap * 3 * sizeof *grown);
            if (!grown) {
                rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
                break;
            }
            *xyz = grown;
        }
        if (!(rc = parse_line(path, line, s, *xyz + 3 * (size_t)*n, err)))
            ++*n;
    }
    if (!rc && ferror(fp))
        rc = hfs_fail(err, HFS_E_IO, "%s: read error", path);
    fclose(fp);
    if (!rc && *n == 0)
        rc = hfs_fail(err, HFS_E_FORMAT, "%s: no points", path);
    if (rc) {
        free(*xyz);
        *xyz = NULL, *n = 0;
    }
    return rc;
}

int cli_query_run(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                  const hfs_quality *q, const char *path, hfs_error *err)
{
    double *xyz = NULL;
    int n = 0;
    int rc = cli_query_read_points(path, &xyz, &n, err);
    if (rc)
        return rc;
    if (l->n_key == 0) {
        free(xyz);
        return hfs_fail(err, HFS_E_INVALID, "query: the scene has no key light (--key)");
    }
    float *vis = malloc((size_t)n * (size_t)l->n_key * sizeof *vis);
    if (!vis)
        rc = hfs_fail(err, HFS_E_NOMEM, "query: out of memory for %d points", n);
    if (!rc && (rc = hfs_renderer_query_points(r, f, l, q, xyz, n, vis, err)) == HFS_OK) {
        printf("# x y z");
        for (int k = 0; k < l->n_key; ++k)
            printf(" key%d", k + 1);
        printf("\n");
        for (int i = 0; i < n; ++i) {
            printf("%.9g %.9g %.9g", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
            for (int k = 0; k < l->n_key; ++k)
                printf(" %.6f", vis[(size_t)i * (size_t)l->n_key + (size_t)k]);
            printf("\n");
        }
    }
    free(vis);
    free(xyz);
    return rc;
}
