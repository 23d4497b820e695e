/*
 * bounds_texture.h — the gap search's max pyramid (runtime/core/ray_bound.h)
 * as a texture of the horizon passes: one channel (R16F, R32F at fp32), the
 * atlas of hfs_ray_bound_layout over the normalized heights v = (z - base) /
 * hscale, each bound rounded up to the texture's precision (a bound may
 * only err high: the search then reads more, never misses) and -2 (below
 * every v) where no level lies.  Built on the CPU with the terrain upload,
 * as the heights arrive from memory: O(W H), well below the upload itself.
 */
#ifndef HFS_GLES_BOUNDS_TEXTURE_H
#define HFS_GLES_BOUNDS_TEXTURE_H

#include "gl_api.h"
#include "gl_caps.h"
#include "hfshade.h"
#include "layout.h"

/* Uploads f's bounds into tex (L->rb.aw x L->rb.ah, allocated by
 * resources.c), built in `work`: hfs_gles_bounds_work_bytes(L) bytes the
 * caller keeps between terrain changes (the renderer's scratch: a fresh
 * allocation of that size each change cost page faults, issue 37). */
size_t hfs_gles_bounds_work_bytes(const hfs_gles_layout *L);
int hfs_gles_bounds_upload(const hfs_gl *gl, const hfs_gl_caps *c, GLuint tex,
                           const hfs_gles_layout *L, const hfs_field *f, void *work,
                           hfs_error *err);

/* The bound nearest above v at the caps' precision (exposed for tests). */
uint16_t hfs_gles_half_up(double v);
float hfs_gles_float_up(double v);

#endif /* HFS_GLES_BOUNDS_TEXTURE_H */
