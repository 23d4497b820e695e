/*
 * wedge_textures.h — the wedge tables of the table visibility path
 * (visibility.h, HFS_VIS_WEDGE_TABLE) as GL textures: the CPU tables cached
 * by azimuth step dphi, and the textures of the environment swath, the key
 * lights' swaths (a set of 4 layers per distinct dphi, interior and
 * boundary) and the local lights' full swath, each uploaded only when its
 * dphi (or the precision) changes.
 */
#ifndef HFS_GLES_WEDGE_TEXTURES_H
#define HFS_GLES_WEDGE_TEXTURES_H

#include "gl_api.h"
#include "gl_caps.h"
#include "sh.h"

#define HFS_GLES_TABLE_CACHE 12

typedef struct hfs_gles_wedge_textures {
    struct {
        double dphi;
        hfs_wedge_tables *t;
        unsigned long used;
    } cache[HFS_GLES_TABLE_CACHE];
    unsigned long clock;
    GLuint env, keys, keys_boundary, local;
    double env_dphi, local_dphi, key_dphi[HFS_MAX_KEY_LIGHTS];
    int key_sets;
    size_t bytes;
    int fp32;              /* format of the textures */
} hfs_gles_wedge_textures;

/* Drops the textures when the precision changed (called once a frame). */
void hfs_gles_wedge_textures_follow(hfs_gles_wedge_textures *w, const hfs_gl *gl,
                                    const hfs_gl_caps *c);
/* The environment's (or the local lights') table texture for step dphi. */
int hfs_gles_wedge_env(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                       double dphi, void *scratch, hfs_error *err);
int hfs_gles_wedge_local(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                         double dphi, void *scratch, hfs_error *err);
/* The key lights' sets: set s for step dphi[s], s < n_sets. */
int hfs_gles_wedge_keys(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                        const double *dphi, int n_sets, void *scratch, hfs_error *err);
void hfs_gles_wedge_textures_free(hfs_gles_wedge_textures *w, const hfs_gl *gl);

/* Scratch bytes the uploads need (caller-owned). */
size_t hfs_gles_wedge_scratch_bytes(void);

#endif /* HFS_GLES_WEDGE_TEXTURES_H */
