/*
 * edit_frame.h — a frame after an edit of the heights (issue 38; DESIGN.md
 * "Local edits"): which texels each pass recomputes (edit_region.h's
 * conservative regions, filled as the passes run) and the scissored
 * draws.  The functions that need the renderer are declared in
 * gles_backend.h, "Local edits".
 *
 * A frame takes this path when the heights changed, nothing else did (the
 * planner would otherwise run nothing), every product of the last frame is
 * current, and the edit keeps the field's normalization (base, hscale,
 * vmax: an edit that moves the field's lowest or highest height changes
 * every normalized height, and the frame is cold).  Any pass that cannot
 * bound what the edit reaches runs whole, and so does everything it feeds:
 * exact either way.
 */
#ifndef HFS_GLES_EDIT_FRAME_H
#define HFS_GLES_EDIT_FRAME_H

#include "edit_region.h"

/* A change whose box covers more than this share of the field takes a
 * cold frame. */
#define HFS_EDIT_MAX_SHARE 0.5

typedef struct hfs_gles_edit {
    hfs_edit_box box;        /* the texels whose heights changed */
    double top;              /* hfs_edit_top of the box grown by 3: the highest
                                value a sample reading it can take */
    /* Regions, texels (a grid receiver counts at its texel): */
    hfs_tiles normals;       /* normals, and every per-texel read of the heights */
    hfs_tiles levels;        /* the reconstructed levels: the coarsest one's reach */
    hfs_tiles env;           /* the environment's grid horizons (near part) */
    hfs_tiles far;           /* far-grid receivers that changed, grown by their blend */
    hfs_tiles transfer;      /* the transfer / the map's occlusion */
    hfs_tiles key;           /* one key light's factor (its sweep; the draw's) */
    hfs_tiles local;         /* the local lights' ratios (grid receivers) */
    hfs_tiles shade;         /* the shading: every region above, and the keys' */
    int transfer_made;       /* transfer filled this frame */
    /* Per reconstructed layer (layout.h), for the far grid's test
     * (env_horizons.frag far_edit_changes): how far a read's footprint
     * reaches, and the highest value a read within that of the box can
     * take (the heights within twice that, before or after). */
    double layer_reach[HFS_GLES_MAX_LEVELS], layer_top[HFS_GLES_MAX_LEVELS];
    void *far_old, *far_now; /* the far atlas as the last frame left it, and now */
    size_t far_cap;
    int far_half;            /* far_old holds halves (else floats) */
    hfs_edit_rect *rects;    /* scratch for the scissor rectangles */
    size_t rects_cap;
    char why[96];            /* the planner's reason, "heights edited: ..." */
} hfs_gles_edit;

void hfs_gles_edit_free(hfs_gles_edit *e);

#endif /* HFS_GLES_EDIT_FRAME_H */
