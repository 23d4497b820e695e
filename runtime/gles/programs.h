/*
 * programs.h — the GLES backend's program cache (weston renderer-gl's
 * shape): a program is its row of programs.def plus a typed variant key;
 * the "#define" prefix is built from the key in one place
 * (hfs_gles_variant_defines), so no pass spells a define.
 *
 * Texture units and block bindings come from the program's row: a pass
 * binds a texture by sampler name (hfs_gles_program_texture), and the name
 * must be in the row (an error otherwise, so a shader and its row cannot
 * drift apart: the cache also refuses a program whose linked samplers or
 * blocks are not listed).
 */
#ifndef HFS_GLES_PROGRAMS_H
#define HFS_GLES_PROGRAMS_H

#include "gl_api.h"
#include "hfshade.h"

typedef enum hfs_gles_program_id {
#define HFS_PROGRAM(id, shader, product, samplers, blocks) id,
#include "programs.def"
#undef HFS_PROGRAM
    HFS_PROG_COUNT
} hfs_gles_program_id;

/* Uniform blocks: fixed binding points (the names of programs.def). */
enum hfs_gles_block { HFS_BLOCK_SCALES, HFS_BLOCK_SWATH, HFS_BLOCK_SHADE, HFS_BLOCK_KEYS,
                      HFS_BLOCK_LOCAL, HFS_BLOCK_BOUNCE, HFS_BLOCK_VIEW,
                      HFS_BLOCK_COUNT };

/* The variant of a program: each field is one #define of the shaders
 * (0 = not defined; the shaders' defaults then apply). */
typedef struct hfs_gles_variant {
    int fp32;       /* HFS_FP32 1: fp32 targets instead of fp16 hi+lo pairs  */
    int count;      /* HFS_COUNT 1: the fetch-counting twin of a grid pass   */
    int tables;     /* HFS_TABLES 1 and HFS_TABLE_N: the wedge-table path    */
    int n_layers;   /* HFS_NLAYERS: reconstructed layers                     */
    int n_out;      /* HFS_NOUT: render targets of a grid pass               */
    int n_dir;      /* HFS_NDIR: directions of the swath                     */
    int recon_v;    /* HFS_RECON_V: levels per reconstruction y pass         */
    int key_vec4;   /* HFS_KEY_VEC4: declared size of the key records        */
    int n_keys;     /* HFS_NKEYS: key lights shaded                          */
    int env;        /* HFS_ENV 1: the environment is shaded                  */
    int local;      /* HFS_LOCAL 1: local lights are shaded                  */
    int local_dirs; /* HFS_LOCAL_DIRS: the local lights' full swath          */
    int n_local;    /* HFS_NLOCAL: local lights shaded                       */
    int swath_tex;  /* HFS_SWATH_TEX 1: HfsSwath from a texture (block_texture.h) */
    int keys_tex;   /* HFS_KEYS_TEX 1: HfsKeys from a texture                */
    int local_tex;  /* HFS_LOCAL_TEX 1: HfsLocal's swath from a texture      */
    int albedo_map; /* HFS_ALBEDO_MAP 1: the shading reads u_albedo          */
    int slice;      /* HFS_SLICE 1: exact slice lighting (slice_light.h)     */
    int n_bdir;     /* HFS_NBDIR: the bounces' directions                    */
    int glossy;     /* HFS_GLOSSY 1: the shading adds the Phong lobe (gloss.h);
                       2: for a viewer at a point (each texel's own V)       */
    int env_dot;    /* HFS_ENV_DOT 1: env_slices.frag dots T_occ with the sky
                       (the sky occlusion, pass_env_sky_occlusion.c)          */
    int env_occ;    /* HFS_ENV_OCC 1: shade.frag reads that sky occlusion     */
    int env_map;    /* HFS_ENV_MAP (env-shade = map): env_slices.frag 1, the
                       map's occluded light; shade.frag 1, the open-sky
                       table, 2, and the map's occluded light (pass_shade.c) */
    int pairs;      /* HFS_PAIRS 1: the slice path's grid horizons come with
                       their occluders' distances (hor_pairs)                */
    int far_k;      /* HFS_FARK K: split horizons' sub-directions a slice    */
    int far_h;      /* HFS_FARH: the far occluders' heights (split_horizon.h
                       HFS_SPLIT_HEIGHTS; 0 or 1: one), layers of u_far       */
    int far_atlas;  /* HFS_FAR_ATLAS 1: env_horizons.frag's far pass          */
    int gloss_map;  /* HFS_GLOSS_MAP 1: shade.frag's glossy lobe adds the map's
                       beyond order 4 (u_egloss, env_gloss.h)                */
    int near;       /* HFS_NEAR 1: the bounces' near part at every texel
                       (bounce_gather.frag) and its use (bounce_light.frag)  */
    int cells;      /* HFS_CELLS 1: gles_ray.frag's search of every cell,
                       hfs_gap_search_cells (key lights, GIS horizons)       */
    int src_layers; /* HFS_SRC_LAYERS N: terrain_decimate.frag reads the level
                       array of N layers, its last (the heights)             */
} hfs_gles_variant;

#define HFS_GLES_MAX_PROGRAMS 64
#define HFS_GLES_MAX_SAMPLERS 8

typedef struct hfs_gles_program {
    hfs_gles_program_id id;
    hfs_gles_variant variant;
    GLuint name;
} hfs_gles_program;

typedef struct hfs_gles_programs {
    hfs_gles_program prog[HFS_GLES_MAX_PROGRAMS];
    int n;
    int pair_fetch; /* HFS_PAIR_FETCH 1 in every program (gl_probe.h): a
                       property of the context's driver, set before the
                       first program is made */
} hfs_gles_programs;

/* The program (id, variant), compiled and linked on first use, made
 * current.  *out points into the cache (valid until the next get). */
int hfs_gles_program_use(hfs_gles_programs *c, const hfs_gl *gl, hfs_gles_program_id id,
                         const hfs_gles_variant *v, const hfs_gles_program **out,
                         hfs_error *err);
void hfs_gles_programs_free(hfs_gles_programs *c, const hfs_gl *gl);

/* Binds texture t (target) to the unit of sampler `sampler` of program p. */
int hfs_gles_program_texture(const hfs_gl *gl, const hfs_gles_program *p, const char *sampler,
                             GLenum target, GLuint t, hfs_error *err);

/* Uniforms by name (absent from a variant: ignored). */
void hfs_gles_set_i1(const hfs_gl *gl, const hfs_gles_program *p, const char *name, int a);
void hfs_gles_set_i2(const hfs_gl *gl, const hfs_gles_program *p, const char *name, int a,
                     int b);
void hfs_gles_set_f1(const hfs_gl *gl, const hfs_gles_program *p, const char *name, float a);
void hfs_gles_set_f2(const hfs_gl *gl, const hfs_gles_program *p, const char *name, float a,
                     float b);
void hfs_gles_set_f4(const hfs_gl *gl, const hfs_gles_program *p, const char *name,
                     const double v[4]);

/* The "#define NAME VALUE" strings of variant v, and HFS_PAIR_FETCH when
 * pair_fetch (the cache's, a property of the driver: gl_probe.h)
 * (NULL-terminated; bufs holds their text).  Exposed for tests. */
#define HFS_GLES_MAX_DEFINES 40
void hfs_gles_variant_defines(const hfs_gles_variant *v, int pair_fetch, char bufs[][32],
                              const char *defs[HFS_GLES_MAX_DEFINES + 1]);

/* The shader file of program id ("env_horizons.frag"), whether it gets the
 * SH product. */
const char *hfs_gles_program_shader(hfs_gles_program_id id);
int hfs_gles_program_has_product(hfs_gles_program_id id);

#endif /* HFS_GLES_PROGRAMS_H */
