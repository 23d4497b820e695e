/*
 * cpu_grid.h — the CPU reference on a sub-sampled visibility grid
 * (hfs_quality.subsample 2 or 4; DESIGN.md "GLES path", "Visibility
 * grid", "Key lights on the 2x2 grid"): what the GLES passes compute at
 * that subsample, in double.  Receiver a of the grid sits on grid point
 * min(a sub, W-1); a texel reads the receivers around it with its
 * bilinear weights (hfs_grid_axis).
 *
 *   slice path   the grid's near occluders (env_horizons.frag HFS_PAIRS:
 *                the scales from distance 2^(1/k) to far-from, unseeded,
 *                refined; an occluder grid of cpu_far_grid.h), blended and
 *                moved to each texel's height (env_slices.frag,
 *                hfs_split_far_slope), the texel's own cell searched per
 *                texel; split horizons' far grid as at subsample 1, with
 *                the subsample's settings (split_horizon.h);
 *   Legendre, tables   V_env - hemisphere(N_receiver) per receiver
 *                (env_horizons.frag), read bilinearly and given back the
 *                hemisphere of the texel's own normal (env_transfer.frag);
 *   key lights   per receiver and direction the occluder (tan of the
 *                horizon and its distance; key_horizons.frag, the
 *                texels' scales left out, hfs_key_near_make), and per
 *                texel the near search along the swath's centre (scales,
 *                refinement, the ray's crossings to `to`), the four
 *                neighbours' occluders moved to it and each direction's
 *                own crossings from `to` to `edge` (key_visibility.frag
 *                near_horizon, key_horizon; hfs_cpu_grid_key_near and
 *                hfs_cpu_grid_key_horizon are those two functions).
 *
 * Where the CPU still differs from GLES at these subsamples (fp16 storage
 * of the occluders, float grid coordinates and filtering, ties of the
 * occluders' distances): DESIGN.md "One reference at every subsample".
 * Local lights' grid is cpu_local_grid.c's; the bounces stay per texel
 * (GLES gathers them on its bounce_subsample grid).  Private to the CPU
 * renderer (cpu_render.c, cpu_render_setup.c).
 */
#ifndef HFS_CPU_GRID_H
#define HFS_CPU_GRID_H

#include "cpu_render_ctx.h"

/* Builds the frame's grids when c->sub > 1 (nothing at subsample 1): the
 * environment's (slice path: near occluders; Legendre and tables: V) and
 * each key light's.  Needs the jobs, plans, visibility objects, the slice
 * path's far grid and the workers' scratch. */
int hfs_cpu_grid_build(render_ctx *c, const hfs_quality *q, const hfs_cpu_pyramid *pyr,
                       int threads, hfs_error *err);
void hfs_cpu_grid_free(render_ctx *c);

/* Slice path: the places of row j's texels on the grid (s->grid_pl), once
 * per row; then direction d's horizons om[0..W-1] of row j above the
 * floors fl (the grid's near occluders and the texel's own cell). */
void hfs_cpu_grid_env_places(const render_ctx *c, worker_scratch *s, int j);
void hfs_cpu_grid_env_row(const render_ctx *c, const worker_scratch *s, int d, int j,
                          const double *fl, double *om);

/* Legendre and tables: V_env at texel (i, j) of unit normal n. */
void hfs_cpu_grid_env_v(const render_ctx *c, int i, int j, const double n[3],
                        double v[HFS_SH_N]);

/* A key light's near search at texel (i, j) along its swath's centre (one
 * for all its directions, key_visibility.frag near_horizon): the slope of
 * its finest scales, refined, and every crossing of the ray to `to`, not
 * below the slope where the light's window starts (tables: -1e30); that
 * start where there is none (a full swath searches per direction). */
double hfs_cpu_grid_key_near(const render_ctx *c, const swath_job *job, int i, int j);

/* A key light's horizon at texel (i, j) (unit normal n, floor fl) in
 * direction d of its swath, from the grid's four receivers around it, its
 * near search `near` and its own ray's crossings from `to` to `edge`
 * (key_visibility.frag key_horizon). */
double hfs_cpu_grid_key_horizon(const render_ctx *c, const swath_job *job, int d, int i, int j,
                                const double n[3], double fl, double near);

#endif /* HFS_CPU_GRID_H */
