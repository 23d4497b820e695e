/*
 * gis_horizon_files.c — see gis_horizon_files.h.
 */
#include "gis_horizon_files.h"

#include "parallel.h"

#include <cpl_vsi.h>

#include <stdlib.h>
#include <string.h>

/* One queued file: its angles, strings, and once encoded its bytes. */
typedef struct queued {
    int k;
    float *deg;
    gis_horizon_text t;
    void *bytes;
    size_t len;
    hfs_error err;
    int rc;
} queued;

struct gis_horizon_files {
    const gis_run *r;
    size_t texels;
    int slots, used, workers, failed;
    queued *q;
};

int gis_horizon_files_create(gis_horizon_files **out, const gis_run *r, hfs_error *err)
{
    *out = NULL;
    gis_horizon_files *f = calloc(1, sizeof *f);
    if (!f)
        return hfs_fail(err, HFS_E_NOMEM, "horizon: out of memory");
    f->r = r;
    f->texels = (size_t)r->dem.width * (size_t)r->dem.height;
    f->workers = hfs_parallel_default_threads();
    size_t slots = GIS_HORIZON_FILES_FLOATS / (f->texels ? f->texels : 1);
    slots = slots > (size_t)r->a->n_azimuths ? (size_t)r->a->n_azimuths : slots;
    f->slots = slots < 1 ? 1 : (int)slots;
    f->q = calloc((size_t)f->slots, sizeof *f->q);
    int made = f->q != NULL;
    for (int s = 0; made && s < f->slots; ++s)
        made = (f->q[s].deg = malloc(f->texels * sizeof(float))) != NULL;
    if (!made) {
        const int n = f->slots;
        gis_horizon_files_destroy(f);
        return hfs_fail(err, HFS_E_NOMEM, "horizon: out of memory for %d rasters", n);
    }
    *out = f;
    return HFS_OK;
}

/* Queued file s encoded (on a worker: only its own slot is written). */
static void encode_one(void *ctx, int s, int worker)
{
    gis_horizon_files *f = ctx;
    queued *e = &f->q[s];
    (void)worker;
    const gis_raster g = gis_run_horizon_raster(f->r, e->k, e->deg, &e->t);
    e->rc = gis_raster_encode(f->r->names[e->k], &g, &e->bytes, &e->len, &e->err);
}

/* The queue encoded in parallel, then written in order. */
static int flush(gis_horizon_files *f, hfs_error *err)
{
    const int n = f->used;
    f->used = 0;
    hfs_parallel_rows(n, f->workers < n ? f->workers : n, encode_one, f, NULL, NULL);
    int rc = HFS_OK;
    for (int s = 0; s < n; ++s) {
        queued *e = &f->q[s];
        if (!rc && e->rc)
            rc = e->rc, *err = e->err;
        else if (!rc) {
            const char *name = f->r->names[e->k];
            rc = hfs_bytes_write_to(gis_outputs_set(f->r->outs, name), name, e->bytes, e->len,
                                    err);
        }
        VSIFree(e->bytes);
        e->bytes = NULL;
    }
    return rc;
}

int gis_horizon_files_add(gis_horizon_files *f, int k, const float *deg, hfs_error *err)
{
    if (f->failed)
        return f->failed;
    queued *e = &f->q[f->used++];
    e->k = k;
    memcpy(e->deg, deg, f->texels * sizeof(float));
    int rc = HFS_OK;
    if (f->used == f->slots || k == f->r->a->n_azimuths - 1)
        rc = f->failed = flush(f, err);
    return rc;
}

void gis_horizon_files_destroy(gis_horizon_files *f)
{
    if (!f)
        return;
    for (int s = 0; f->q && s < f->slots; ++s) {
        free(f->q[s].deg);
        VSIFree(f->q[s].bytes);
    }
    free(f->q);
    free(f);
}
