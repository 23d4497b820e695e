/*
 * cli_picture.c — hfshade render's display-only treatment of its PNG
 * (cli_picture.h); the PFM and GeoTIFF never see it.
 */
#include "cli_picture.h"

/* Display option: multiplies the (linear) output by a colour of the
 * normalized height — lowland green, hills tan, summits grey-white — like a
 * hypsometric map.  Only the PNG sees it; the PFM keeps SPEC's Lo. */
void cli_terrain_colormap(hfs_image *img, const hfs_heightmap *hm)
{
    static const double stops[][4] = {/* t, r, g, b */
                                      {0.00, 0.28, 0.50, 0.24}, {0.30, 0.55, 0.62, 0.32},
                                      {0.60, 0.62, 0.52, 0.38}, {0.85, 0.78, 0.76, 0.72},
                                      {1.00, 0.97, 0.97, 0.97}};
    const size_t n = (size_t)hm->width * (size_t)hm->height;
    float lo = hm->z[0], hi = hm->z[0];
    for (size_t k = 1; k < n; ++k) {
        lo = hm->z[k] < lo ? hm->z[k] : lo;
        hi = hm->z[k] > hi ? hm->z[k] : hi;
    }
    const double span = hi > lo ? (double)hi - (double)lo : 1.0;
    for (size_t k = 0; k < n; ++k) {
        const double t = ((double)hm->z[k] - lo) / span;
        int s = 0;
        while (s < 3 && t > stops[s + 1][0])
            ++s;
        const double u = (t - stops[s][0]) / (stops[s + 1][0] - stops[s][0]);
        for (int ch = 0; ch < 3; ++ch)
            img->rgb[3 * k + ch] *= (float)(stops[s][1 + ch] + u * (stops[s + 1][1 + ch] - stops[s][1 + ch]));
    }
}
