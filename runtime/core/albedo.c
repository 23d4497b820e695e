/*
 * albedo.c — see albedo.h.
 */
#include "albedo.h"

#include <stddef.h>

void hfs_albedo_map_apply(const float *map, hfs_image *out)
{
    if (!map)
        return;
    const size_t n = (size_t)out->width * (size_t)out->height * 3;
    for (size_t i = 0; i < n; ++i)
        out->rgb[i] *= map[i];
}

int hfs_albedo_map_check(const float *map, int width, int height, hfs_error *err)
{
    if (!map)
        return HFS_OK;
    static const char *const channel[3] = {"R", "G", "B"};
    const size_t n = (size_t)width * (size_t)height * 3;
    for (size_t i = 0; i < n; ++i)
        if (!(map[i] >= 0.0f && map[i] <= 1.0f)) { /* NaN fails both */
            const size_t t = i / 3;
            return hfs_fail(err, HFS_E_INVALID,
                            "albedo map: texel (%zu, %zu) %s is %g, outside [0, 1]",
                            t % (size_t)width, t / (size_t)width, channel[i % 3],
                            (double)map[i]);
        }
    return HFS_OK;
}
