/*
 * cpu_points.c — key-light visibility of points above the field on the
 * CPU reference (hfs_renderer_query_points): each key light's shadow
 * height maps at HFS_SHM_LAYERS elevations across its disk (shm.h), read
 * bilinearly at each point's grid position.
 */
#include "backends.h"
#include "shm.h"

#include <stdlib.h>

int hfs_cpu_query_points(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                         const double *xyz, int n, float *vis, hfs_error *err)
{
    const size_t cells = (size_t)f->width * (size_t)f->height;
    float *maps = malloc((HFS_SHM_LAYERS + 1) * cells * sizeof *maps);
    if (!maps)
        return hfs_fail(err, HFS_E_NOMEM, "query: out of memory for %d shadow height maps",
                        HFS_SHM_LAYERS);
    float *scratch = maps + HFS_SHM_LAYERS * cells;
    for (int k = 0; k < l->n_key; ++k) {
        const hfs_key_light *kl = &l->key[k];
        for (int m = 0; m < HFS_SHM_LAYERS; ++m)
            hfs_shm_build(f, kl->phi, hfs_shm_layer_elevation(kl->elev, kl->alpha, m),
                          maps + (size_t)m * cells, scratch, q->threads);
        for (int i = 0; i < n; ++i) {
            const double *p = xyz + 3 * (size_t)i;
            double s[HFS_SHM_LAYERS];
            for (int m = 0; m < HFS_SHM_LAYERS; ++m)
                s[m] = hfs_shm_sample(maps + (size_t)m * cells, f->width, f->height,
                                      p[0] / f->dx, p[1] / f->dx);
            vis[(size_t)i * (size_t)l->n_key + (size_t)k] = (float)hfs_shm_disk_fraction(s, p[2]);
        }
    }
    free(maps);
    return HFS_OK;
}

int hfs_cpu_shadow_height_map(const hfs_field *f, const hfs_key_light *k, const hfs_quality *q,
                              int layer, float *out, hfs_error *err)
{
    float *scratch = malloc((size_t)f->width * (size_t)f->height * sizeof *scratch);
    if (!scratch)
        return hfs_fail(err, HFS_E_NOMEM, "shadow height map: out of memory");
    hfs_shm_build(f, k->phi, hfs_shm_layer_elevation(k->elev, k->alpha, layer), out, scratch,
                  q->threads);
    free(scratch);
    return HFS_OK;
}
