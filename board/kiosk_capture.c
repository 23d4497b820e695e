/*
 * kiosk_capture.c — a [capture NAME] section with role = heights in the
 * kiosk (docs/CAPTURE.md "In the kiosk"): its frames become the heights.
 *
 * The live source (capture_live.h) is polled with the knobs; when a frame
 * changed the heights, the world's field points at them under their new
 * serial, so the next frame renders them (the GLES planner compares the
 * heights themselves, so it reruns the terrain passes for new heights at
 * the same address).  Loss and bad frames are the live source's business:
 * logged, never fatal; the last good heights stay on screen.
 */
#include "kiosk.h"

#include <stdlib.h>
#include <string.h>

static void capture_log(void *user, int warning, const char *line)
{
    (void)user;
    kiosk_log(warning ? KIOSK_WARNING : KIOSK_INFO, "%s", line);
}

static const hfs_capture_config *heights_config(const hfs_input_config *cfg)
{
    for (int i = 0; i < cfg->captures.n; ++i)
        if (cfg->captures.c[i].role == HFS_ROLE_HEIGHTS)
            return &cfg->captures.c[i];
    return NULL;
}

int kiosk_capture_open(kiosk *k, const kiosk_world *w, hfs_error *err)
{
    const hfs_capture_config *c = heights_config(&w->cfg);
    if (!c)
        return k->opt.capture_record
                   ? hfs_fail(err, HFS_E_INVALID, "--capture-record: %s has no [capture NAME] "
                              "section", k->opt.input_path ? k->opt.input_path : "no --input")
                   : HFS_OK;
    if (k->opt.no_devices && !c->replay[0])
        return HFS_OK; /* --no-devices: the camera is not opened either */
    hfs_capture_live_desc d = {.config = c, .config_path = k->opt.input_path,
                               .grid_w = w->in.field.width, .grid_h = w->in.field.height,
                               .record_dir = k->opt.capture_record,
                               .start_ns = hfs_input_now_ns(), .log = capture_log};
    const int rc = hfs_capture_live_open(&d, &k->capture, err);
    if (!rc)
        kiosk_log(KIOSK_INFO, "capture %s: %s %s -> %dx%d heights%s%s", c->name,
                  c->replay[0] ? "replay" : "device", c->replay[0] ? c->replay : c->device,
                  c->depth.grid_w ? c->depth.grid_w : d.grid_w,
                  c->depth.grid_h ? c->depth.grid_h : d.grid_h,
                  k->opt.capture_record ? ", recording to " : "",
                  k->opt.capture_record ? k->opt.capture_record : "");
    return rc;
}

void kiosk_capture_apply(hfs_capture_live *live, kiosk_world *w)
{
    if (!live)
        return;
    int gw, gh;
    uint64_t serial;
    const float *z = hfs_capture_live_heights(live, &gw, &gh, &serial);
    if (!z)
        return;
    w->in.field.z = z;
    w->in.field.width = gw;
    w->in.field.height = gh;
    w->in.serial = serial;
}

int kiosk_capture_drain(hfs_capture_live *live, kiosk_world *w)
{
    if (!hfs_capture_live_drain(live, hfs_input_now_ns()))
        return 0;
    kiosk_capture_apply(live, w);
    return 1;
}
