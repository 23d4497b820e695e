/*
 * pass_env_sky_occlusion.c — the SH sky's occluded light at full
 * resolution, for a frame whose sky is not being turned (DESIGN.md "The
 * sky occlusion"): the slice path's exact slices as the transfer finds
 * them (env_slices.frag HFS_ENV_DOT), their T_occ dotted with the sky in
 * the shader: 3 values a texel as fp16 (hi, lo) pairs in an RGBA and an
 * RG target, instead of the transfer's 16 in 4 RGBA ones (3 MiB instead
 * of 8 at 512^2, kept for a turn that never comes).
 * Unlike the transfer it depends on the sky (its rotation and tint), so a
 * renderer whose sky turns keeps the transfer instead from then on
 * (gles_frame.c env_fold): the two give the shading the same bits.
 */
#include "gles_backend.h"

static int present(const hfs_gles_frame *fr)
{
    return fr->env_fold;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    int rc = hfs_gles_skyocc_ensure(&g->r, &g->gl, &g->caps, err);
    if (rc)
        return rc;
    if (fr->edit) /* the region, into the shading's */
        hfs_gles_edit_transfer(g, fr);
    const hfs_gles_layout *L = &fr->L;
    hfs_gles_stage_fetches(g, HFS_PASS_ENV_SKY_OCCLUSION, 0,
                           (double)L->w * L->h * hfs_gles_env_slices_fetches(g, fr));
    return hfs_gles_draw_env_slices(g, fr, HFS_SLICES_SKY, g->r.skyocc_fbo, err);
}

const hfs_gles_pass hfs_pass_env_sky_occlusion = {
    .id = HFS_PASS_ENV_SKY_OCCLUSION,
    .plan_name = "sky occlusion",
    .scope = HFS_SCOPE_FRAME,
    .reads = {"pyramid", "env visibility", "env light"},
    .writes = {"env sky occlusion"},
    .stages = {"sky occlusion"},
    .present = present,
    .run = run,
};
