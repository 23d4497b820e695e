/*
 * cli_frames.c — see cli_frames.h.
 */
#include "cli_frames.h"

#include "median.h"

#include <stdio.h>
#include <stdlib.h>

int cli_render_once(hfs_renderer *r, const hfs_scene_inputs *in, const hfs_view *v,
                       hfs_image *img, hfs_image *vimg, hfs_progress_fn progress, void *user,
                       hfs_error *err)
{
    if (v)
        return hfs_renderer_render_view(r, &in->field, &in->lighting, &in->quality, v, img, vimg,
                                        err);
    return hfs_renderer_render(r, &in->field, &in->lighting, &in->quality, img, progress, user,
                               err);
}

int cli_time_frames(int n, hfs_renderer *r, const hfs_scene_inputs *in, const hfs_view *v,
                    hfs_image *img, hfs_image *vimg, hfs_error *err)
{
    double *ms = calloc((size_t)n * (HFS_MAX_PASSES + 2), sizeof *ms);
    if (!ms)
        return hfs_fail(err, HFS_E_NOMEM, "--time: out of memory");
    hfs_timings t = {0};
    int rc = hfs_renderer_set_timing(r, 1);
    for (int f = -1; f < n && !rc; ++f) {
        hfs_renderer_invalidate(r);
        rc = cli_render_once(r, in, v, img, vimg, NULL, NULL, err);
        if (rc || f < 0)
            continue;
        hfs_renderer_timings(r, &t);
        for (int p = 0; p < t.n_passes; ++p)
            ms[(size_t)p * n + f] = t.pass[p].ms;
        ms[(size_t)HFS_MAX_PASSES * n + f] = t.gpu_ms;
        ms[(size_t)(HFS_MAX_PASSES + 1) * n + f] = t.frame_ms;
    }
    if (!rc) {
        printf("timing: %s, %dx%d, %d frames after 1 warm-up, method %s\n", t.device,
               in->field.width, in->field.height, n, t.method);
        printf("%-12s %10s\n", "pass", "median ms");
        for (int p = 0; p < t.n_passes; ++p)
            printf("%-12s %10.3f\n", t.pass[p].name, hfs_median(ms + (size_t)p * n, n));
        printf("%-12s %10.3f\n", "passes", hfs_median(ms + (size_t)HFS_MAX_PASSES * n, n));
        printf("%-12s %10.3f\n", "frame", hfs_median(ms + (size_t)(HFS_MAX_PASSES + 1) * n, n));
        printf("texture memory: %.2f MiB (%zu bytes)\n", t.texture_bytes / 1048576.0, t.texture_bytes);
    }
    free(ms);
    return rc;
}
