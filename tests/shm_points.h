/*
 * shm_points.h — points that test shadow height maps (test_shm.c,
 * bench_shm.c): n random points over field f, each within `spread` world
 * units of the key light's centre shadow height (its SHM, shm.h) where
 * that height is at least `spread` above the ground: in or near a
 * penumbra, not in plain sun.  Deterministic (seed).  Header-only.
 */
#ifndef HFS_TEST_SHM_POINTS_H
#define HFS_TEST_SHM_POINTS_H

#include "field_geom.h"
#include "shm.h"

#include <stdlib.h>

/* 0, or -1 when no such point turns up in 1000 n tries (a scene in full
 * sun) or memory runs out. */
static inline int shm_edge_points(const hfs_field *f, const hfs_key_light *k, int n,
                                  double spread, unsigned seed, double *xyz)
{
    const int w = f->width, h = f->height;
    float *sc = malloc(sizeof(float) * (size_t)w * h), *tmp = malloc(sizeof(float) * (size_t)w * h);
    int got = 0;
    if (sc && tmp) {
        hfs_shm_build(f, k->phi, k->elev, sc, tmp, 1);
        for (long tries = 0; got < n && tries < 1000L * n; ++tries) {
            double u[3];
            for (int c = 0; c < 3; ++c) {
                seed = seed * 1103515245u + 12345u;
                u[c] = ((seed >> 8) & 0xffff) / 65535.0;
            }
            const double x = (w - 1) * u[0], y = (h - 1) * u[1];
            const double top = hfs_shm_sample(sc, w, h, x, y);
            double ground;
            hfs_field_bilinear(f, x, y, &ground);
            if (top - ground < spread)
                continue; /* in the sun down to the ground: no edge to test */
            xyz[3 * got] = x * f->dx, xyz[3 * got + 1] = y * f->dx;
            xyz[3 * got + 2] = top + spread * (2.0 * u[2] - 1.0);
            ++got;
        }
    }
    free(sc), free(tmp);
    return got == n ? 0 : -1;
}

#endif /* HFS_TEST_SHM_POINTS_H */
