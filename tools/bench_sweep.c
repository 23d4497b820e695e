/*
 * bench_sweep.c — see bench_sweep.h.
 */
#include "bench_sweep.h"

#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_AXES 12
#define MAX_VALUES 16

typedef struct axis {
    char key[32];
    char values[MAX_VALUES][32];
    int n;
} axis;

void bench_point_label(const hfs_quality *q, hfs_backend backend, char *out, size_t cap)
{
    const int n = snprintf(out, cap, "%s k%d o%d e%d k%d l%d sub%d %s %s %s",
                           backend == HFS_BACKEND_CPU ? "cpu" : "gles", q->k, q->offset,
                           q->nphi_env, q->nphi_key, q->nphi_local, q->subsample,
                           q->precision == HFS_PRECISION_FP32 ? "fp32" : "fp16",
                           q->visibility == HFS_VIS_WEDGE_TABLE ? "wedge"
                           : q->visibility == HFS_VIS_SLICE     ? "slice"
                                                                : "leg",
                           q->local_full_swath ? "full" : "part");
    /* The bounces' settings only where they differ from the defaults (the
     * labels of direct-light sweeps, and the CSVs that hold them, stay). */
    hfs_quality d;
    hfs_quality_defaults(&d);
    if (n > 0 && (size_t)n < cap &&
        (q->nphi_bounce != d.nphi_bounce || q->bounce_refine != d.bounce_refine ||
         q->bounce_subsample != d.bounce_subsample))
        snprintf(out + n, cap - (size_t)n, " b%d/%d/%d", q->nphi_bounce, q->bounce_refine,
                 q->bounce_subsample);
}

/* Splits "key=v1,v2 key=v3" into axes. */
static int parse_grid(const char *grid, axis *ax, int *n_ax, hfs_error *err)
{
    char buf[1024];
    if (strlen(grid) >= sizeof buf)
        return hfs_fail(err, HFS_E_INVALID, "grid '%.40s...': too long", grid);
    snprintf(buf, sizeof buf, "%s", grid);
    *n_ax = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, " \t", &save); tok; tok = strtok_r(NULL, " \t", &save)) {
        char *eq = strchr(tok, '=');
        if (!eq || eq == tok || !eq[1])
            return hfs_fail(err, HFS_E_INVALID, "grid '%s': '%s' is not key=v1,v2,...", grid, tok);
        if (*n_ax == MAX_AXES)
            return hfs_fail(err, HFS_E_INVALID, "grid '%s': more than %d keys", grid, MAX_AXES);
        axis *a = &ax[(*n_ax)++];
        *eq = '\0';
        if (strlen(tok) >= sizeof a->key)
            return hfs_fail(err, HFS_E_INVALID, "grid '%s': key '%s' too long", grid, tok);
        snprintf(a->key, sizeof a->key, "%s", tok);
        if (strcmp(a->key, "backend") != 0 && !hfs_scene_is_key(a->key))
            return hfs_fail(err, HFS_E_INVALID, "grid '%s': '%s' is not a scene key", grid,
                            a->key);
        a->n = 0;
        char *vsave = NULL;
        for (char *v = strtok_r(eq + 1, ",", &vsave); v; v = strtok_r(NULL, ",", &vsave)) {
            if (a->n == MAX_VALUES || strlen(v) >= sizeof a->values[0])
                return hfs_fail(err, HFS_E_INVALID, "grid '%s': too many or too long values "
                                "for %s", grid, a->key);
            snprintf(a->values[a->n++], sizeof a->values[0], "%s", v);
        }
    }
    return HFS_OK;
}

static int point_add(bench_sweep *s, const hfs_quality *q, hfs_backend backend, hfs_error *err)
{
    char label[192];
    bench_point_label(q, backend, label, sizeof label);
    for (int i = 0; i < s->n; ++i)
        if (!strcmp(s->pts[i].label, label))
            return HFS_OK;
    if (s->n == s->cap) {
        const int cap = s->cap ? 2 * s->cap : 64;
        bench_point *p = realloc(s->pts, (size_t)cap * sizeof *p);
        if (!p)
            return hfs_fail(err, HFS_E_NOMEM, "sweep: out of memory");
        s->pts = p;
        s->cap = cap;
    }
    bench_point *p = &s->pts[s->n++];
    memset(p, 0, sizeof *p);
    p->q = *q;
    p->backend = backend;
    hfs_quality d;
    hfs_quality_defaults(&d);
    char dlabel[192];
    bench_point_label(&d, HFS_BACKEND_GLES, dlabel, sizeof dlabel);
    p->is_default = !strcmp(label, dlabel);
    snprintf(p->label, sizeof p->label, "%s", label);
    return HFS_OK;
}

int bench_sweep_add_grid(bench_sweep *s, const char *grid, hfs_error *err)
{
    axis ax[MAX_AXES];
    int n_ax = 0;
    int rc = parse_grid(grid, ax, &n_ax, err);
    if (rc)
        return rc;
    int idx[MAX_AXES] = {0};
    for (;;) {
        hfs_scene sc;
        hfs_scene_init(&sc);
        hfs_backend backend = HFS_BACKEND_GLES;
        for (int a = 0; a < n_ax; ++a) {
            const char *v = ax[a].values[idx[a]];
            char where[80];
            snprintf(where, sizeof where, "grid %s", ax[a].key);
            if (!strcmp(ax[a].key, "backend")) {
                if (!strcmp(v, "gles"))
                    backend = HFS_BACKEND_GLES;
                else if (!strcmp(v, "cpu"))
                    backend = HFS_BACKEND_CPU;
                else
                    return hfs_fail(err, HFS_E_INVALID, "%s: '%s' is not gles or cpu", where, v);
            } else if ((rc = hfs_scene_set(&sc, HFS_SOURCE_FLAG, ax[a].key, v, where, NULL,
                                           err))) {
                return rc;
            }
        }
        hfs_quality q;
        hfs_scene_quality(&sc, &q);
        if ((rc = point_add(s, &q, backend, err)))
            return rc;
        int a = 0;
        while (a < n_ax && ++idx[a] == ax[a].n)
            idx[a++] = 0;
        if (a == n_ax)
            break;
    }
    return HFS_OK;
}

void bench_sweep_free(bench_sweep *s)
{
    free(s->pts);
    memset(s, 0, sizeof *s);
}
