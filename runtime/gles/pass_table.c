/*
 * pass_table.c — the GLES frame's passes, in order (pass.h).  A new pass
 * is a new pass_*.c and a row here (and its id in pass.h).
 */
#include "pass.h"

const hfs_gles_pass *const hfs_gles_pass_table[HFS_PASS_COUNT] = {
    [HFS_PASS_TERRAIN] = &hfs_pass_terrain,
    [HFS_PASS_ENV_HORIZONS] = &hfs_pass_env_horizons,
    [HFS_PASS_KEY_HORIZONS] = &hfs_pass_key_horizons,
    [HFS_PASS_LOCAL_LIGHTS] = &hfs_pass_local_lights,
    [HFS_PASS_ENV_TRANSFER] = &hfs_pass_env_transfer,
    [HFS_PASS_ENV_MAP_SLICES] = &hfs_pass_env_map_slices,
    [HFS_PASS_ENV_SKY_OCCLUSION] = &hfs_pass_env_sky_occlusion,
    [HFS_PASS_KEY_VISIBILITY] = &hfs_pass_key_visibility,
    [HFS_PASS_SHADE] = &hfs_pass_shade,
    [HFS_PASS_BOUNCE] = &hfs_pass_bounce,
    [HFS_PASS_READBACK] = &hfs_pass_readback,
    [HFS_PASS_LIT_TEXTURE] = &hfs_pass_lit_texture,
    [HFS_PASS_VIEW] = &hfs_pass_view,
};

int hfs_gles_pass_max_instances(const hfs_gles_pass *p)
{
    switch (p->scope) {
    case HFS_SCOPE_KEY:
        return HFS_MAX_KEY_LIGHTS;
    case HFS_SCOPE_LOCAL:
        return HFS_MAX_LOCAL_LIGHTS;
    default:
        return 1;
    }
}
