/*
 * pass_env_map_slices.c — an environment map's occluded light at full
 * resolution (env-shade = map on the slice path; DESIGN.md "Shading from
 * the map itself"): per texel and slice, the horizon exactly as the
 * transfer finds it (env_slices.frag, HFS_ENV_MAP 1), then the map's
 * integral between the tangent plane and it from the slice's F, G table
 * (env_map_slices.h).  Writes each texel's occluded irradiance (<= 0) to
 * the occlusion target the shading pass adds to the map's open sky.
 * Unlike the transfer it depends on the sky's rotation (the slices' wedges
 * turn over the map): a turned sky reruns this pass and the shading, not
 * the horizons.  Its prepare also keeps the open-sky table the shading
 * reads on every path with env-shade = map, and a glossy frame's table of
 * the map's lobe (env_gloss.h).
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <math.h>

static int present(const hfs_gles_frame *fr)
{
    return fr->has_env && fr->env_map > 0;
}

static int prepare(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    int rc = hfs_gles_env_open_follow(&g->envmap, &g->gl, &g->caps, fr->l, err);
    if (!rc && fr->env_map == 2)
        rc = hfs_gles_env_slices_follow(&g->envmap, &g->gl, &g->caps, fr->l, &g->env_slices,
                                        err);
    if (!rc && fr->gloss_map) /* the shading's glossy table (env_gloss.h) */
        rc = hfs_gles_env_gloss_follow(&g->envmap, &g->gl, &g->caps, fr->l, fr->gloss.s, err);
    fr->gloss_map_max = fr->gloss_map ? g->envmap.gmax : 0.0;
    return rc;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    if (fr->env_map != 2)
        return HFS_OK;
    const hfs_gles_layout *L = &fr->L;
    /* As the transfer, and per slice the F and G rows at two elevations
     * (all slices counted: an open one skips them). */
    hfs_gles_stage_fetches(g, HFS_PASS_ENV_MAP_SLICES, 0,
                           (double)L->w * L->h *
                               (hfs_gles_env_slices_fetches(g, fr) + 4.0 * g->env_vis_n));
    return hfs_gles_draw_env_slices(g, fr, HFS_SLICES_MAP, g->envmap.occ_fbo, err);
}

const hfs_gles_pass hfs_pass_env_map_slices = {
    .id = HFS_PASS_ENV_MAP_SLICES,
    .plan_name = "map occlusion",
    .scope = HFS_SCOPE_FRAME,
    .reads = {"pyramid", "env visibility", "env light"},
    .writes = {"env map occlusion"},
    .stages = {"map occlusion"},
    .present = present,
    .prepare = prepare,
    .run = run,
};
