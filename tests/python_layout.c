/*
 * python_layout.c — the layout of every struct the Python module's cdef
 * mirrors by hand (tools/python/hfshade/_ffi.py), as this compiler lays
 * it out from the installed headers: "STRUCT SIZE" and "STRUCT.FIELD
 * OFFSET SIZE" lines.  tests/python/test_layout.py compares them with
 * cffi's ffi.sizeof/ffi.offsetof, so a header change that is not
 * mirrored in the cdef fails the suite.
 */
#include "hfshade.h"
#include "hfshade_envmap.h"
#include "hfshade_gis.h"

#include <stddef.h>
#include <stdio.h>

#define S(type) printf("%s %zu\n", #type, sizeof(type))
#define F(type, field)                                                                       \
    printf("%s.%s %zu %zu\n", #type, #field, offsetof(type, field),                         \
           sizeof(((type *)0)->field))

static void inputs(void)
{
    S(hfs_error), F(hfs_error, msg);
    S(hfs_field), F(hfs_field, width), F(hfs_field, height), F(hfs_field, z), F(hfs_field, dx),
        F(hfs_field, zscale);
    S(hfs_key_light), F(hfs_key_light, phi), F(hfs_key_light, elev), F(hfs_key_light, alpha),
        F(hfs_key_light, radiance), F(hfs_key_light, disabled), F(hfs_key_light, from_env);
    S(hfs_local_light), F(hfs_local_light, pos), F(hfs_local_light, radius),
        F(hfs_local_light, radiance), F(hfs_local_light, disabled);
    S(hfs_lighting), F(hfs_lighting, has_env), F(hfs_lighting, env_sh),
        F(hfs_lighting, env_rotate), F(hfs_lighting, env_map), F(hfs_lighting, env_map_width),
        F(hfs_lighting, env_map_height), F(hfs_lighting, env_open),
        F(hfs_lighting, env_shade_map), F(hfs_lighting, n_key), F(hfs_lighting, key),
        F(hfs_lighting, n_local), F(hfs_lighting, local), F(hfs_lighting, albedo),
        F(hfs_lighting, albedo_map), F(hfs_lighting, bounces), F(hfs_lighting, specular),
        F(hfs_lighting, gloss), F(hfs_lighting, view_dir), F(hfs_lighting, view_from_eye),
        F(hfs_lighting, view_eye);
}

static void quality(void)
{
    S(hfs_quality), F(hfs_quality, k), F(hfs_quality, offset), F(hfs_quality, nphi_env),
        F(hfs_quality, nphi_key), F(hfs_quality, refine), F(hfs_quality, split),
        F(hfs_quality, far_from), F(hfs_quality, far_dirs), F(hfs_quality, far_step),
        F(hfs_quality, nphi_bounce), F(hfs_quality, bounce_refine),
        F(hfs_quality, bounce_subsample), F(hfs_quality, bounce_near),
        F(hfs_quality, nphi_local), F(hfs_quality, local_full_swath),
        F(hfs_quality, subsample), F(hfs_quality, precision), F(hfs_quality, visibility),
        F(hfs_quality, threads), F(hfs_quality, truth_azimuths),
        F(hfs_quality, truth_elev_order), F(hfs_quality, truth_light_samples);
    S(hfs_image), F(hfs_image, width), F(hfs_image, height), F(hfs_image, rgb);
    S(hfs_renderer_desc), F(hfs_renderer_desc, backend), F(hfs_renderer_desc, context),
        F(hfs_renderer_desc, gl_profile), F(hfs_renderer_desc, gl_strict_limits),
        F(hfs_renderer_desc, egl_display), F(hfs_renderer_desc, egl_share_context);
}

static void envmap(void)
{
    S(hfs_env_decompose_opts), F(hfs_env_decompose_opts, max_lights),
        F(hfs_env_decompose_opts, min_share), F(hfs_env_decompose_opts, contrast),
        F(hfs_env_decompose_opts, max_radius), F(hfs_env_decompose_opts, threads);
    S(hfs_env_light), F(hfs_env_light, phi), F(hfs_env_light, elev), F(hfs_env_light, alpha),
        F(hfs_env_light, radiance), F(hfs_env_light, energy), F(hfs_env_light, share),
        F(hfs_env_light, id);
    S(hfs_env_decomp), F(hfs_env_decomp, n_lights), F(hfs_env_decomp, light),
        F(hfs_env_decomp, residual_sh), F(hfs_env_decomp, total_energy),
        F(hfs_env_decomp, residual_energy);
    S(hfs_env_lighting_opts), F(hfs_env_lighting_opts, lights),
        F(hfs_env_lighting_opts, n_scene_keys), F(hfs_env_lighting_opts, shade_sh),
        F(hfs_env_lighting_opts, truth_sh), F(hfs_env_lighting_opts, nphi_env);
    S(hfs_env_lighting), F(hfs_env_lighting, sh), F(hfs_env_lighting, n_keys),
        F(hfs_env_lighting, keys), F(hfs_env_lighting, residual), F(hfs_env_lighting, open);
    S(hfs_gis_dem), F(hfs_gis_dem, width), F(hfs_gis_dem, height), F(hfs_gis_dem, z),
        F(hfs_gis_dem, hole), F(hfs_gis_dem, has_nodata), F(hfs_gis_dem, nodata),
        F(hfs_gis_dem, cell), F(hfs_gis_dem, zscale);
    S(hfs_gis_site), F(hfs_gis_site, lat), F(hfs_gis_site, lon), F(hfs_gis_site, elevation_m),
        F(hfs_gis_site, linke), F(hfs_gis_site, convergence_deg);
}

/* The constants the cdef spells as numbers. */
static void constants(void)
{
    printf("#HFS_SH_COEFFS %d\n#HFS_MAX_KEY_LIGHTS %d\n#HFS_MAX_LOCAL_LIGHTS %d\n",
           HFS_SH_COEFFS, HFS_MAX_KEY_LIGHTS, HFS_MAX_LOCAL_LIGHTS);
    printf("#HFS_ENV_MAX_LIGHTS %d\n#HFS_VERSION_MAJOR %d\n", HFS_ENV_MAX_LIGHTS,
           HFS_VERSION_MAJOR);
    printf("#HFS_BACKEND_GLES %d\n#HFS_BACKEND_CPU %d\n#HFS_BACKEND_TRUTH %d\n",
           HFS_BACKEND_GLES, HFS_BACKEND_CPU, HFS_BACKEND_TRUTH);
    printf("#HFS_VIS_LEGENDRE %d\n#HFS_VIS_WEDGE_TABLE %d\n#HFS_VIS_SLICE %d\n",
           HFS_VIS_LEGENDRE, HFS_VIS_WEDGE_TABLE, HFS_VIS_SLICE);
    printf("#HFS_PRECISION_FP16 %d\n#HFS_PRECISION_FP32 %d\n", HFS_PRECISION_FP16,
           HFS_PRECISION_FP32);
    printf("#HFS_GIS_SVF %d\n#HFS_GIS_HORIZON %d\n#HFS_GIS_OPENNESS %d\n", HFS_GIS_SVF,
           HFS_GIS_HORIZON, HFS_GIS_OPENNESS);
    printf("#HFS_GIS_SUN %d\n#HFS_GIS_INSOLATION %d\n", HFS_GIS_SUN, HFS_GIS_INSOLATION);
}

int main(void)
{
    inputs();
    quality();
    envmap();
    constants();
    return 0;
}
