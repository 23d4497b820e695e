/*
 * cli_render_job.c — see cli_render_job.h.
 */
#include "cli_render_job.h"

#include "tiled_render.h"

#include <stdlib.h>
#include <string.h>

int render_job_halo(const hfs_field *f, const hfs_lighting *l, int tile, int *halo,
                    hfs_error *err)
{
    if (f->width <= tile && f->height <= tile)
        return hfs_fail(err, HFS_E_INVALID, "--tile %d: the %dx%d field fits one tile (no jobs "
                        "to cut)", tile, f->width, f->height);
    *halo = hfs_tile_halo(f, l);
    if (*halo < 0)
        return hfs_fail(err, HFS_E_INVALID, "--tile: this lighting sees terrain at any distance "
                        "(a local light, or a key light at or below its own radius): no halo "
                        "short of the whole field; render it whole");
    return HFS_OK;
}

int render_job_frame(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                     const hfs_quality *q, int tile, int halo, int job, hfs_image *part,
                     int *ix, int *iy, hfs_error *err)
{
    const int nx = (f->width + tile - 1) / tile, ny = (f->height + tile - 1) / tile;
    if (job < 1 || job > nx * ny)
        return hfs_fail(err, HFS_E_INVALID, "--job %d: the field has %d jobs of --tile %d", job,
                        nx * ny, tile);
    /* the GIS commands' windows, with the render's halo */
    const hfs_tile_window v = hfs_tile_window_of(f->width, f->height, tile, halo,
                                                 (job - 1) % nx, (job - 1) / nx);
    const int x0 = v.x0, y0 = v.y0, w = v.w, h = v.h, iw = v.iw, ih = v.ih;
    *ix = v.ix, *iy = v.iy;
    float *z = malloc((size_t)w * (size_t)h * sizeof *z);
    float *alb = l->albedo_map ? malloc((size_t)w * (size_t)h * 3 * sizeof *alb) : NULL;
    hfs_image win = {0};
    int rc = z && (alb || !l->albedo_map) ? HFS_OK
                                          : hfs_fail(err, HFS_E_NOMEM, "--job %d: out of memory "
                                                     "for a window of %dx%d", job, w, h);
    hfs_lighting sl = *l;
    hfs_field sf = *f;
    if (!rc) /* the window's heights (and albedo), its lights moved with it */
        sf = hfs_tile_sub_field(f, l, x0, y0, w, h, z, alb, &sl);
    if (!rc)
        rc = hfs_image_alloc(&win, w, h, err);
    if (!rc)
        rc = hfs_renderer_render(r, &sf, &sl, q, &win, NULL, NULL, err);
    if (!rc)
        rc = hfs_image_alloc(part, iw, ih, err);
    for (int j = 0; !rc && j < ih; ++j)
        memcpy(part->rgb + (size_t)j * iw * 3,
               win.rgb + ((size_t)(*iy - y0 + j) * w + (size_t)(*ix - x0)) * 3,
               (size_t)iw * 3 * sizeof *part->rgb);
    hfs_image_free(&win);
    free(alb);
    free(z);
    return rc;
}
