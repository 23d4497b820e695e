/*
 * cli_render_job.h — the lit render of a DEM as jobs of `hfshade tiles`
 * (issue 40 item 1; docs/GIS.md "Many machines"): `hfshade render --height
 * DEM ... --tile N --job K --geotiff OUT.tif` renders only job K's part of
 * the grid and writes it as a GeoTIFF of its own extent, so that GNU
 * parallel or a Slurm array can render a DEM tile by tile and `hfshade
 * tiles merge` can put the parts back together.
 *
 * The jobs are the tiles of N x N texels of the grid, row by row (the GIS
 * commands' order: tools/gis/gis_stream.h).  Job K renders its part grown
 * by a halo on every side, widened outwards to multiples of
 * HFS_TILE_ALIGN (so that its sub-sampled visibility grid falls on the
 * whole field's), cut to the field, and keeps the part.  The halo is the
 * single process's own tiled render's (runtime/renderer/tiled_render.h,
 * hfs_tile_halo): from the whole field's relief and the lights, far enough
 * that terrain beyond it cannot rise above the lowest elevation the scene
 * sees (a key light's e - a, the sky's 1.27 degrees).  A local light needs
 * the terrain between receiver and light, anywhere: no halo short of the
 * whole field, refused in one line.
 *
 * What a job reads: the whole DEM (the render's loader, which also fills
 * holes and knows the relief); what it renders: its window only.
 */
#ifndef HFS_CLI_RENDER_JOB_H
#define HFS_CLI_RENDER_JOB_H

#include "hfshade.h"

/* The halo (texels) that tiles of `tile` texels of field f need under
 * lighting l.  An error (one line) when no halo short of the whole field
 * is enough (a local light, a key light at or below its own radius) or
 * when the field fits one tile. */
int render_job_halo(const hfs_field *f, const hfs_lighting *l, int tile, int *halo,
                    hfs_error *err);

/* Job `job` (from 1, row by row) of tiles of `tile` texels with `halo`:
 * its window rendered on r with l and q, its part (*iw x *ih texels at
 * *ix, *iy of the grid) into part (allocated here; the caller frees it).
 * An error when the field has fewer jobs. */
int render_job_frame(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                     const hfs_quality *q, int tile, int halo, int job, hfs_image *part,
                     int *ix, int *iy, hfs_error *err);

#endif /* HFS_CLI_RENDER_JOB_H */
