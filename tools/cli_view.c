/*
 * cli_view.c — see cli_view.h.
 */
#include "cli_view.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* --camera AZ,EL,DIST,FOV[,TX,TY,TZ]: degrees, SPEC's azimuth; an empty
 * DIST frames the field; without TX,TY,TZ the target is the field's centre
 * at mid height. */
static int parse_camera(cli_view *c, const char *v, hfs_error *err)
{
    const char *p = v;
    int n = 0;
    for (; n < 7; ++n) {
        char *end;
        if (n == 2 && *p == ',') {
            c->cam[n] = NAN, end = (char *)p;
        } else {
            c->cam[n] = strtod(p, &end);
            if (end == p || !isfinite(c->cam[n]))
                return hfs_fail(err, HFS_E_INVALID, "--camera: '%s': number %d is not a finite "
                                "number (AZ,EL,DIST,FOV[,TX,TY,TZ])", v, n + 1);
        }
        p = end;
        if (*p != ',')
            break;
        ++p;
    }
    if (*p || (n + 1 != 4 && n + 1 != 7))
        return hfs_fail(err, HFS_E_INVALID, "--camera: '%s' is not AZ,EL,DIST,FOV or "
                        "AZ,EL,DIST,FOV,TX,TY,TZ", v);
    if (fabs(c->cam[1]) > 90.0)
        return hfs_fail(err, HFS_E_INVALID, "--camera: elevation %g is out of range [-90, 90] "
                        "(degrees)", c->cam[1]);
    if (!(c->cam[2] > 0.0) && !isnan(c->cam[2]))
        return hfs_fail(err, HFS_E_INVALID, "--camera: distance %g is not positive", c->cam[2]);
    if (!(c->cam[3] > 0.0 && c->cam[3] < 179.0))
        return hfs_fail(err, HFS_E_INVALID, "--camera: field of view %g is out of range (0, "
                        "179) (degrees)", c->cam[3]);
    c->n_cam = n + 1;
    c->n_target = n + 1 == 7 ? 3 : 0;
    return HFS_OK;
}

/* The sRGB EOTF (IEC 61966-2-1), a byte to linear. */
static double srgb_decode(int b)
{
    const double x = b / 255.0;
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

/* --background sky|studio|#rrggbb|R,G,B. */
static int parse_background(cli_view *c, const char *v, hfs_error *err)
{
    if (!strcmp(v, "sky") || !strcmp(v, "studio")) {
        c->background = 1 + (!strcmp(v, "sky") ? HFS_BACKGROUND_SKY : HFS_BACKGROUND_STUDIO);
        return HFS_OK;
    }
    c->background = 1 + HFS_BACKGROUND_COLOR;
    if (v[0] == '#') {
        unsigned rgb[3];
        int used = 0;
        if (strlen(v) != 7 || strspn(v + 1, "0123456789abcdefABCDEF") != 6 ||
            sscanf(v + 1, "%2x%2x%2x%n", &rgb[0], &rgb[1], &rgb[2], &used) != 3 || used != 6)
            return hfs_fail(err, HFS_E_INVALID, "--background: '%s' is not #rrggbb (six hex "
                            "digits)", v);
        for (int k = 0; k < 3; ++k)
            c->bg_rgb[k] = srgb_decode((int)rgb[k]);
        return HFS_OK;
    }
    const char *p = v;
    for (int k = 0; k < 3; ++k) {
        char *end;
        c->bg_rgb[k] = strtod(p, &end);
        if (end == p || !(c->bg_rgb[k] >= 0.0 && c->bg_rgb[k] <= 1e30) ||
            *end != (k < 2 ? ',' : '\0'))
            return hfs_fail(err, HFS_E_INVALID, "--background: '%s' is not sky, studio, "
                            "#rrggbb or R,G,B (linear, each in [0, 1e30])", v);
        p = end + 1;
    }
    return HFS_OK;
}

/* --haze off|auto|DEPTH. */
static int parse_haze(cli_view *c, const char *v, hfs_error *err)
{
    char *end;
    c->haze_given = 1;
    if (!strcmp(v, "off") || !strcmp(v, "auto")) {
        c->haze = !strcmp(v, "off") ? 0.0 : HFS_HAZE_AUTO;
        return HFS_OK;
    }
    c->haze = strtod(v, &end);
    if (end == v || *end || !(c->haze > 0.0 && c->haze <= 50.0))
        return hfs_fail(err, HFS_E_INVALID, "--haze: '%s' is not off, auto or an optical depth "
                        "in (0, 50]", v);
    return HFS_OK;
}

int cli_view_flag(cli_view *c, const char *name, const char *v, int *rc, hfs_error *err)
{
    char *end;
    *rc = HFS_OK;
    if (!strcmp(name, "view")) {
        if (!strcmp(v, "ortho") || !strcmp(v, "perspective"))
            c->view = 1 + (!strcmp(v, "ortho") ? HFS_VIEW_ORTHO : HFS_VIEW_PERSPECTIVE);
        else
            *rc = hfs_fail(err, HFS_E_INVALID, "--view: '%s' is not ortho or perspective", v);
    } else if (!strcmp(name, "camera")) {
        *rc = parse_camera(c, v, err);
    } else if (!strcmp(name, "exaggeration")) {
        c->exaggeration = strtod(v, &end);
        if (end == v || *end || !(c->exaggeration > 0.0) || c->exaggeration > 1e6)
            *rc = hfs_fail(err, HFS_E_INVALID, "--exaggeration: '%s' is not a number in (0, "
                           "1e6]", v);
    } else if (!strcmp(name, "view-size")) {
        long w = strtol(v, &end, 10), h = *end == 'x' ? strtol(end + 1, &end, 10) : 0;
        if (*end || w < 1 || h < 1 || w > 8192 || h > 8192)
            *rc = hfs_fail(err, HFS_E_INVALID, "--view-size: '%s' is not WxH with sides in "
                           "[1, 8192]", v);
        c->view_w = (int)w, c->view_h = (int)h;
    } else if (!strcmp(name, "background")) {
        *rc = parse_background(c, v, err);
    } else if (!strcmp(name, "haze")) {
        *rc = parse_haze(c, v, err);
    } else {
        return 0;
    }
    return 1;
}

int cli_view_check(const cli_view *c, hfs_error *err)
{
    if (!c->view && (c->n_cam || c->exaggeration > 0.0 || c->view_w || c->background ||
                     c->haze_given))
        return hfs_fail(err, HFS_E_INVALID, "%s: needs --view ortho|perspective",
                        c->n_cam          ? "--camera"
                        : c->view_w       ? "--view-size"
                        : c->background   ? "--background"
                        : c->haze_given   ? "--haze"
                                          : "--exaggeration");
    return HFS_OK;
}

hfs_view cli_view_make(const cli_view *c, const hfs_field *f, int panel)
{
    const double rad = 3.14159265358979323846 / 180.0;
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.mode = (hfs_view_mode)(c->view - 1);
    if (c->view_w)
        v.width = c->view_w, v.height = c->view_h;
    if (c->exaggeration > 0.0)
        v.exaggeration = c->exaggeration;
    /* A terrain is seen against its sky through air; a panel in a studio. */
    v.background = c->background ? (hfs_background)(c->background - 1)
                                 : panel ? HFS_BACKGROUND_STUDIO : HFS_BACKGROUND_SKY;
    for (int k = 0; k < 3; ++k)
        v.background_rgb[k] = c->bg_rgb[k];
    v.haze = c->haze_given ? c->haze : panel ? 0.0 : HFS_HAZE_AUTO;
    if (c->n_cam) {
        v.azimuth = c->cam[0] * rad, v.elevation = c->cam[1] * rad, v.fov = c->cam[3] * rad;
        for (int k = 0; k < c->n_target; ++k)
            v.target[k] = c->cam[4 + k];
    }
    if (!c->n_target) /* the centre at mid height, of the exaggerated field */
        v.target[2] *= v.exaggeration;
    if (c->n_cam && !isnan(c->cam[2]))
        v.distance = c->cam[2];
    else
        hfs_view_frame(&v, f);
    return v;
}
