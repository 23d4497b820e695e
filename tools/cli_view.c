/*
 * cli_view.c — see cli_view.h.
 */
#include "cli_view.h"

#include <math.h>
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
    } else {
        return 0;
    }
    return 1;
}

int cli_view_check(const cli_view *c, hfs_error *err)
{
    if (!c->view && (c->n_cam || c->exaggeration > 0.0 || c->view_w))
        return hfs_fail(err, HFS_E_INVALID, "%s: needs --view ortho|perspective",
                        c->n_cam ? "--camera" : c->view_w ? "--view-size" : "--exaggeration");
    return HFS_OK;
}

hfs_view cli_view_make(const cli_view *c, const hfs_field *f)
{
    const double rad = 3.14159265358979323846 / 180.0;
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.mode = (hfs_view_mode)(c->view - 1);
    if (c->view_w)
        v.width = c->view_w, v.height = c->view_h;
    if (c->exaggeration > 0.0)
        v.exaggeration = c->exaggeration;
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
