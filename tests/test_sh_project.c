/*
 * test_sh_project.c — equirectangular projection: the discrete definition
 * (sum over texels of L y_k dOmega, exact texel solid angle) by brute force on
 * an odd-sized random map, a constant map (c0 = sqrt(4 pi)), and recovery of
 * a known SH function's coefficients with the midpoint-rule error O(1/h^2).
 */
#include "sh.h"
#include "test_sh_util.h"

#include <stdlib.h>

/* The definition, texel by texel, with the reference basis. */
static void brute_project(const float *rgb, int w, int h, double out[3][16])
{
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 16; ++k)
            out[c][k] = 0;
    for (int j = 0; j < h; ++j) {
        const double e = T_PI / 2 - T_PI * (j + 0.5) / h;
        const double dom = (2 * T_PI / w) *
            (sin(T_PI / 2 - T_PI * j / h) - sin(T_PI / 2 - T_PI * (j + 1.0) / h));
        for (int i = 0; i < w; ++i) {
            double y[16];
            ref_y_dir(2 * T_PI * (i + 0.5) / w, e, y);
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 16; ++k)
                    out[c][k] += rgb[((size_t)j * w + i) * 3 + c] * y[k] * dom;
        }
    }
}

int main(void)
{
    int fails = 0;
    ref_rng rng = {42};

    {   /* random map, width not a multiple of the library's column block */
        const int w = 301, h = 77;
        float *img = malloc(sizeof(float) * 3 * w * h);
        if (!img)
            return 1;
        for (int i = 0; i < 3 * w * h; ++i)
            img[i] = (float)ref_uniform(&rng, 0, 4);
        double lib[3][16], bf[3][16], e = 0;
        hfs_sh_project_equirect(img, w, h, lib);
        brute_project(img, w, h, bf);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 16; ++k)
                e = ref_max(e, fabs(lib[c][k] - bf[c][k]));
        ref_check(&fails, "equirect 301x77 random map vs texel-by-texel sum", e, 1e-11);
        free(img);
    }

    {   /* constant map: c0 = sqrt(4 pi) exactly, m != 0 vanish exactly,
         * m = 0 (l > 0) are midpoint-rule residue O(1/h^2) */
        const int w = 64, h = 32;
        float *img = malloc(sizeof(float) * 3 * w * h);
        if (!img)
            return 1;
        for (int i = 0; i < 3 * w * h; ++i)
            img[i] = 1.0f;
        double lib[3][16], e0 = 0, em = 0, ez = 0;
        hfs_sh_project_equirect(img, w, h, lib);
        for (int c = 0; c < 3; ++c) {
            e0 = ref_max(e0, fabs(lib[c][0] - sqrt(4 * T_PI)));
            for (int k = 1; k < 16; ++k) {
                if (k == 2 || k == 6 || k == 12)
                    ez = ref_max(ez, fabs(lib[c][k]));
                else
                    em = ref_max(em, fabs(lib[c][k]));
            }
        }
        ref_check(&fails, "constant map: c0 = sqrt(4 pi)", e0, 1e-13);
        ref_check(&fails, "constant map: m != 0 coefficients", em, 1e-13);
        ref_check(&fails, "constant map: zonal l > 0 (64x32, O(1/h^2))", ez, 5e-3);
        free(img);
    }

    {   /* a known SH function: recover its coefficients */
        double c[16];
        for (int k = 0; k < 16; ++k)
            c[k] = ref_uniform(&rng, -1, 1);
        double errs[2];
        for (int r = 0; r < 2; ++r) {
            const int h = r ? 256 : 128, w = 2 * h;
            float *img = malloc(sizeof(float) * 3 * w * h);
            if (!img)
                return 1;
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    double y[16], v = 0;
                    ref_y_dir(2 * T_PI * (i + 0.5) / w, T_PI / 2 - T_PI * (j + 0.5) / h, y);
                    for (int k = 0; k < 16; ++k)
                        v += c[k] * y[k];
                    for (int ch = 0; ch < 3; ++ch)
                        img[((size_t)j * w + i) * 3 + ch] = (float)(v * (ch + 1));
                }
            double lib[3][16], e = 0;
            hfs_sh_project_equirect(img, w, h, lib);
            for (int ch = 0; ch < 3; ++ch)
                for (int k = 0; k < 16; ++k)
                    e = ref_max(e, fabs(lib[ch][k] / (ch + 1) - c[k]));
            errs[r] = e;
            free(img);
        }
        ref_check(&fails, "SH function 256x128: recovered coefficients", errs[0], 5e-4);
        ref_check(&fails, "SH function 512x256: recovered coefficients", errs[1], 1.5e-4);
        printf("     (error ratio 128->256 rows: %.2f, expect ~4 for O(1/h^2))\n",
               errs[0] / errs[1]);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
