/*
 * cli_view.h — hfshade's 3-D view flags (issue 16): --view ortho|perspective,
 * --camera AZ,EL,DIST,FOV[,TX,TY,TZ] (degrees, SPEC's azimuth, or compass
 * with azimuth-convention = compass: hfshade.c converts it; an empty
 * DIST frames the field; without a target the field's centre at mid
 * height), --exaggeration E, --view-size WxH; what the view shows
 * besides the terrain (issue 41): --background sky|studio|#rrggbb|R,G,B
 * (#rrggbb sRGB-encoded bytes, decoded to linear; R,G,B linear radiance in
 * the field's units) and --haze off|auto|DEPTH (hfs_view.haze).  Their
 * defaults follow the scene's use: a terrain gets the sky and the auto
 * haze, a panel (preset = panel) the studio and no haze.  One-line errors
 * name the flag and the problem.
 */
#ifndef HFS_CLI_VIEW_H
#define HFS_CLI_VIEW_H

#include "hfshade.h"

typedef struct cli_view {
    int view;            /* --view: 0 none, 1 + hfs_view_mode */
    double cam[7];       /* --camera numbers (degrees; DIST NAN: frame the field) */
    int n_cam, n_target; /* numbers given (0: none); target given (0 or 3) */
    double exaggeration; /* --exaggeration E (0: not given, 1) */
    int view_w, view_h;  /* --view-size WxH (0: not given, 512 x 512) */
    int background;      /* --background: 0 not given, 1 + hfs_background */
    double bg_rgb[3];    /* its colour, linear */
    int haze_given;      /* --haze given: haze holds it */
    double haze;         /* 0 off, HFS_HAZE_AUTO, or the optical depth */
} cli_view;

/* 1 when name is a view flag (its value parsed into c; *rc says how),
 * else 0. */
int cli_view_flag(cli_view *c, const char *name, const char *v, int *rc, hfs_error *err);
/* A view flag without --view is refused. */
int cli_view_check(const cli_view *c, hfs_error *err);
/* The view the flags ask for (c->view set) of field f, in radians; panel:
 * the scene is a panel's (preset = panel), for the defaults. */
hfs_view cli_view_make(const cli_view *c, const hfs_field *f, int panel);

#endif /* HFS_CLI_VIEW_H */
