/*
 * bench_truth.c — see bench_truth.h.
 */
#include "bench_truth.h"

#include "hfs_io.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

typedef struct fnv {
    unsigned long long h;
} fnv;

static void fnv_bytes(fnv *s, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i) {
        s->h ^= b[i];
        s->h *= 0x100000001b3ull;
    }
}

static void fnv_double(fnv *s, double v)
{
    fnv_bytes(s, &v, sizeof v);
}

static void fnv_int(fnv *s, long long v)
{
    fnv_bytes(s, &v, sizeof v);
}

unsigned long long bench_truth_hash(const hfs_field *f, const hfs_lighting *l,
                                    const hfs_quality *q)
{
    fnv s = {0xcbf29ce484222325ull};
    fnv_int(&s, 3); /* cache format version (2: bounces and gloss; 3: the truth
                     * integrates env_map itself, and from_env lights) */
    fnv_int(&s, f->width);
    fnv_int(&s, f->height);
    fnv_double(&s, f->dx);
    fnv_double(&s, f->zscale);
    fnv_bytes(&s, f->z, (size_t)f->width * f->height * sizeof *f->z);
    /* Field by field: the struct's padding is not part of the scene. */
    fnv_int(&s, l->has_env);
    if (l->has_env) {
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < HFS_SH_COEFFS; ++k)
                fnv_double(&s, l->env_sh[c][k]);
        fnv_double(&s, l->env_rotate);
        fnv_int(&s, l->env_map != NULL);
        if (l->env_map) { /* its content: a new map file is a new scene */
            fnv_int(&s, l->env_map_width);
            fnv_int(&s, l->env_map_height);
            fnv_bytes(&s, l->env_map,
                      (size_t)l->env_map_width * l->env_map_height * 3 * sizeof *l->env_map);
        }
    }
    fnv_int(&s, l->n_key);
    for (int i = 0; i < l->n_key; ++i) {
        const hfs_key_light *k = &l->key[i];
        fnv_double(&s, k->phi);
        fnv_double(&s, k->elev);
        fnv_double(&s, k->alpha);
        fnv_bytes(&s, k->radiance, sizeof k->radiance);
        fnv_int(&s, k->disabled);
        fnv_int(&s, k->from_env);
    }
    fnv_int(&s, l->n_local);
    for (int i = 0; i < l->n_local; ++i) {
        const hfs_local_light *p = &l->local[i];
        for (int c = 0; c < 3; ++c)
            fnv_double(&s, p->pos[c]);
        fnv_double(&s, p->radius);
        fnv_bytes(&s, p->radiance, sizeof p->radiance);
        fnv_int(&s, p->disabled);
    }
    fnv_double(&s, l->albedo);
    if (l->albedo_map)
        fnv_bytes(&s, l->albedo_map, (size_t)f->width * f->height * 3 * sizeof *l->albedo_map);
    fnv_int(&s, l->bounces);
    fnv_double(&s, l->specular);
    if (l->specular > 0.0) {
        fnv_double(&s, l->gloss);
        for (int c = 0; c < 3; ++c)
            fnv_double(&s, l->view_dir[c]);
    }
    fnv_int(&s, q->truth_azimuths);
    fnv_int(&s, q->truth_elev_order);
    fnv_int(&s, q->truth_light_samples);
    return s.h;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int bench_truth_get(const char *cache_dir, const hfs_field *f, const hfs_lighting *l,
                    const hfs_quality *q, hfs_image *out, int *cached, double *seconds,
                    hfs_error *err)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/truth-%016llx.pfm", cache_dir,
             bench_truth_hash(f, l, q));
    *cached = 0;
    *seconds = 0.0;
    struct stat st;
    if (stat(path, &st) == 0) {
        int rc = hfs_pfm_read_image(path, out, err);
        if (rc)
            return rc;
        if (out->width == f->width && out->height == f->height) {
            *cached = 1;
            return HFS_OK;
        }
        hfs_image_free(out); /* a stale file of another size: render again */
    }
    if (mkdir(cache_dir, 0777) != 0 && errno != EEXIST)
        return hfs_fail(err, HFS_E_IO, "%s: cannot create the truth cache: %s", cache_dir,
                        strerror(errno));
    hfs_renderer_desc d = {.backend = HFS_BACKEND_TRUTH};
    hfs_renderer *r = NULL;
    int rc = hfs_renderer_create(&d, &r, err);
    if (rc)
        return rc;
    if (!(rc = hfs_image_alloc(out, f->width, f->height, err))) {
        const double t0 = now_s();
        rc = hfs_renderer_render(r, f, l, q, out, NULL, NULL, err);
        *seconds = now_s() - t0;
    }
    hfs_renderer_destroy(r);
    if (!rc)
        rc = hfs_pfm_write(path, out, 0, err);
    if (rc)
        hfs_image_free(out);
    return rc;
}
