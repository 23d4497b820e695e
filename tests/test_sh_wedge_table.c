/*
 * test_sh_wedge_table.c — SN08 visibility wedges.  The exact wedge
 * projection, the table entries and the interpolated lookups are compared
 * with brute-force 2D quadrature of "visible above the linear horizon" over
 * the wedge, for random horizon pairs (negative ones included), the boundary
 * wedge (and its mirror for the start of a swath), clamping, and the open-sky
 * full swath.  Prints table creation time and the interpolation error at
 * n = 256, the figure quoted in runtime/sh/sh_wedge_table.c.
 */
#include "sh.h"
#include "test_sh_util.h"

#include <stdlib.h>

#define HPI (T_PI / 2)

/* integral over phi in [p0, p1] of integral_{h(phi)}^{pi/2} y(phi, e) cos e de,
 * h linear from wa at phi = p0 to wb at phi = p1 */
static void brute_wedge(double p0, double p1, double wa, double wb, double out[16])
{
    enum { NPAN = 8, NP = 20, NE = 16 };
    /* unit-interval rules, mapped affinely per panel / per elevation range */
    double gx[NP], gw[NP], ex[NE], ew[NE];
    ref_gauss(NP, 0, 1, gx, gw);
    ref_gauss(NE, 0, 1, ex, ew);
    for (int k = 0; k < 16; ++k)
        out[k] = 0;
    const double plen = (p1 - p0) / NPAN;
    for (int p = 0; p < NPAN; ++p) {
        for (int i = 0; i < NP; ++i) {
            const double phi = p0 + plen * (p + gx[i]), wphi = fabs(plen) * gw[i];
            const double h = wa + (wb - wa) * (phi - p0) / (p1 - p0);
            for (int j = 0; j < NE; ++j) {
                const double e = h + (HPI - h) * ex[j], we = (HPI - h) * ew[j];
                double y[16];
                ref_y_dir(phi, e, y);
                for (int k = 0; k < 16; ++k)
                    out[k] += wphi * we * cos(e) * y[k];
            }
        }
    }
}

static double diff16(const double *a, const double *b)
{
    double e = 0;
    for (int k = 0; k < 16; ++k)
        e = ref_max(e, fabs(a[k] - b[k]));
    return e;
}

int main(void)
{
    int fails = 0;
    ref_rng rng = {31337};

    {   /* exact wedge */
        static const double ds[] = {0.05, 2 * T_PI / 32, 2 * T_PI / 3, 2 * T_PI};
        double e = 0;
        for (unsigned d = 0; d < 4; ++d)
            for (int t = 0; t < 40; ++t) {
                double wa = ref_uniform(&rng, -HPI, HPI), wb = ref_uniform(&rng, -HPI, HPI);
                if (t == 0)
                    wa = -HPI, wb = HPI;   /* steepest */
                if (t == 1)
                    wa = wb = -0.7;        /* constant, negative */
                double lib[16], bf[16];
                hfs_wedge_exact(ds[d], wa, wb, lib);
                brute_wedge(0, ds[d], wa, wb, bf);
                e = ref_max(e, diff16(lib, bf));
            }
        ref_check(&fails, "hfs_wedge_exact vs brute force (4 extents x 40 pairs)", e, 1e-13);
    }

    const int n = 256;
    static const double ds[2] = {2 * T_PI / 32, 2 * T_PI / 3};
    static const char *dn[2] = {"2pi/32", "2pi/3"};
    for (int d = 0; d < 2; ++d) {
        const double D = ds[d], Db = D / 2;
        const double t0 = ref_now();
        hfs_wedge_tables *t = hfs_wedge_tables_create_ext(D, Db, n);
        const double dt = ref_now() - t0;
        if (!t) {
            ref_check(&fails, "hfs_wedge_tables_create_ext", INFINITY, 0);
            continue;
        }
        printf("     tables n=%d dphi=%s: interior %d x %d x 16 + boundary %d x 16 doubles"
               " (%.1f MiB), created in %.3f s\n", n, dn[d], n, n, n,
               (double)(n * n + n) * 16 * 8 / 1048576.0, dt);
        char what[96];
        double e;

        e = fabs(hfs_wedge_tables_dphi(t) - D) + fabs(hfs_wedge_tables_dphi_boundary(t) - Db) +
            (hfs_wedge_tables_size(t) != n);
        ref_check(&fails, "table accessors", e, 0);

        /* stored entries (layout [(b*n + a)*16 + k], horizon -pi/2 + pi i/(n-1)) */
        const double *I = hfs_wedge_interior_data(t), *B = hfs_wedge_boundary_data(t);
        e = 0;
        for (int s = 0; s < 60; ++s) {
            int ia = (int)ref_uniform(&rng, 0, n), ib = (int)ref_uniform(&rng, 0, n);
            if (s < 4)
                ia = (s & 1) ? n - 1 : 0, ib = (s & 2) ? n - 1 : 0;
            double bf[16];
            brute_wedge(0, D, -HPI + T_PI * ia / (n - 1), -HPI + T_PI * ib / (n - 1), bf);
            e = ref_max(e, diff16(I + ((size_t)ib * n + ia) * 16, bf));
            brute_wedge(0, Db, -HPI + T_PI * ia / (n - 1), HPI, bf);
            e = ref_max(e, diff16(B + (size_t)ia * 16, bf));
        }
        snprintf(what, sizeof what, "dphi=%s: table entries vs brute force", dn[d]);
        ref_check(&fails, what, e, 1e-13);

        /* interpolated lookups at random horizons: the n = 256 figure */
        double ei = 0, eb = 0, mag = 0;
        for (int s = 0; s < 150; ++s) {
            const double wa = ref_uniform(&rng, -HPI, HPI), wb = ref_uniform(&rng, -HPI, HPI);
            double lib[16], bf[16];
            hfs_wedge_interior(t, wa, wb, lib);
            brute_wedge(0, D, wa, wb, bf);
            ei = ref_max(ei, diff16(lib, bf));
            for (int k = 0; k < 16; ++k)
                mag = ref_max(mag, fabs(bf[k]));
            hfs_wedge_boundary(t, wa, lib);
            brute_wedge(0, Db, wa, HPI, bf);
            eb = ref_max(eb, diff16(lib, bf));
        }
        snprintf(what, sizeof what, "dphi=%s: bilinear interior lookup, n=256 (|coef|<=%.2f)",
                 dn[d], mag);
        ref_check(&fails, what, ei, d == 0 ? 2e-5 : 1e-4);
        snprintf(what, sizeof what, "dphi=%s: linear boundary lookup, n=256", dn[d]);
        ref_check(&fails, what, eb, d == 0 ? 1e-5 : 5e-5);

        /* start of a swath: mirror_y of the boundary wedge is the wedge over
         * [-Db, 0], horizon omega at 0 rising to pi/2 at -Db */
        e = 0;
        for (int s = 0; s < 20; ++s) {
            const double w = -HPI + T_PI * (int)ref_uniform(&rng, 0, n) / (n - 1);
            double lib[16], m[16], bf[16];
            hfs_wedge_boundary(t, w, lib);
            hfs_sh_mirror_y(lib, m);
            brute_wedge(0, -Db, w, HPI, bf);
            e = ref_max(e, diff16(m, bf));
        }
        snprintf(what, sizeof what, "dphi=%s: mirrored boundary = wedge over [-dphi_b, 0]", dn[d]);
        ref_check(&fails, what, e, 1e-13);

        /* clamping: beyond +-pi/2 and NaN read the end entries */
        {
            double a[16], b[16];
            hfs_wedge_interior(t, -5.0, 9.0, a);
            e = diff16(a, I + ((size_t)(n - 1) * n + 0) * 16);
            hfs_wedge_interior(t, NAN, NAN, a);
            e = ref_max(e, diff16(a, I));
            hfs_wedge_boundary(t, 3.0, b);
            e = ref_max(e, diff16(b, B + (size_t)(n - 1) * 16));
            double z[16] = {0};
            e = ref_max(e, diff16(b, z));   /* fully blocked: all zero */
            snprintf(what, sizeof what, "dphi=%s: clamped / NaN lookups", dn[d]);
            ref_check(&fails, what, e, 1e-15);
        }
        hfs_wedge_tables_destroy(t);
    }

    {   /* open sky through a full swath of table wedges: c0 = sqrt(4 pi) */
        const int nw = 16;
        hfs_wedge_tables *t = hfs_wedge_tables_create(2 * T_PI / nw, 16);
        double V[16] = {0}, w[16], r[16];
        double e = INFINITY;
        if (t) {
            for (int j = 0; j < nw; ++j) {
                hfs_wedge_interior(t, -HPI, -HPI, w);
                hfs_sh_rotate_z(w, 2 * T_PI * j / nw, r);
                for (int k = 0; k < 16; ++k)
                    V[k] += r[k];
            }
            e = fabs(V[0] - sqrt(4 * T_PI));
            for (int k = 1; k < 16; ++k)
                e = ref_max(e, fabs(V[k]));
        }
        ref_check(&fails, "16 table wedges at horizon -pi/2 = uniform sky", e, 1e-13);
        hfs_wedge_tables_destroy(t);
        hfs_wedge_tables_destroy(NULL);
        e = (hfs_wedge_tables_create(1.0, 1) == NULL) + (hfs_wedge_tables_create(0.0, 8) == NULL) +
            (hfs_wedge_tables_create(7.0, 8) == NULL);
        ref_check(&fails, "create rejects n < 2 and dphi outside (0, 2pi]", 3 - e, 0);
    }

    {   /* The two visibility paths agree where they must: for a constant
         * horizon, M_lin on the NLP band vector equals the exact wedge in
         * every even-m row (their elevation factors are polynomials of degree
         * <= 3 in z, which the 4-term NLP projection preserves).  Odd-m rows
         * differ by NS09's truncation; the figure is printed, not checked. */
        double M[16 * 8], e_even = 0, e_odd = 0;
        const double D = 2 * T_PI / 32;
        hfs_wedge_mlin(D, M);
        for (int s = 0; s < 50; ++s) {
            const double w = ref_uniform(&rng, -HPI, HPI);
            double v[4], lin[16], ex[16];
            hfs_nlp_visible_band(w, HPI, v);
            for (int r = 0; r < 16; ++r) {
                lin[r] = 0;
                for (int c = 0; c < 8; ++c)
                    lin[r] += M[r * 8 + c] * v[c % 4];
            }
            hfs_wedge_exact(D, w, w, ex);
            for (int r = 0; r < 16; ++r) {
                if (hfs_sh_order(r) % 2 == 0)
                    e_even = ref_max(e_even, fabs(lin[r] - ex[r]));
                else
                    e_odd = ref_max(e_odd, fabs(lin[r] - ex[r]));
            }
        }
        ref_check(&fails, "constant horizon: M_lin(NLP band) = exact wedge, even-m rows", e_even, 1e-14);
        printf("     (odd-m rows differ by up to %.2e: NS09's order-4 NLP truncation)\n", e_odd);
    }

    {   /* costs: exact wedge, lookups */
        hfs_wedge_tables *t = hfs_wedge_tables_create(2 * T_PI / 32, 64);
        double o[16], acc = 0;
        const int reps = 2000;
        const double t0 = ref_now();
        for (int r = 0; r < reps; ++r) {
            hfs_wedge_exact(2 * T_PI / 32, -1.5 + 3.0 * r / reps, 0.3, o);
            acc += o[r & 15];
        }
        const double t1 = ref_now();
        for (int r = 0; r < reps && t; ++r) {
            hfs_wedge_interior(t, -1.5 + 3.0 * r / reps, 0.3, o);
            acc += o[r & 15];
        }
        const double t2 = ref_now();
        printf("     timing: hfs_wedge_exact %.2f us, hfs_wedge_interior %.1f ns (checksum %g)\n",
               1e6 * (t1 - t0) / reps, 1e9 * (t2 - t1) / reps, acc);
        hfs_wedge_tables_destroy(t);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
