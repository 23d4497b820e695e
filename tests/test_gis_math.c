/*
 * test_gis_math.c — the arithmetic of the GIS commands (issue 39;
 * tools/gis/gis_math.h, gis_resample.h, gis_products.h), no GDAL, no GL:
 *   conventions  ccw-east 90 = north = SPEC phi -90 deg; compass 90 = east
 *                = phi 0; compass 180 = south = phi +90 (SPEC "Azimuths
 *                for map users"); a south-up or west-running grid turns
 *                the map's azimuths into its own;
 *   flat         every gamma 0 (and rays that leave at once): sky-view
 *                factor 1 of both kinds, openness 90;
 *   V valley     gammas {b, 0, b, 0}: Zaksek 1 - sin(b)/2, Lambertian
 *                (1 + cos^2 b)/2, openness 90 - b/2 degrees; a peak's
 *                negative gammas count 0 in the sky-view factor;
 *   relation     Lambertian >= Zaksek (cos^2 = 1 - sin^2 <= ... ), equal
 *                where every gamma is 0 or 90 degrees;
 *   names        r.horizon's: PREFIX_045.tif, PREFIX_022_5.tif;
 *   nodata       the input's value when no product value can equal it;
 *   sample back  a plane through the non-square resampling is a plane;
 *                holes and NaN become nodata;
 *   renderer     a V valley through gis_product_svf / _openness on the
 *                truth and CPU backends: the exact numbers at its floor
 *                (every ray across the valley rises at the wall's angle).
 */
#include "check.h"
#include "gis_math.h"
#include "gis_products.h"
#include "gis_resample.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

/* a == b modulo 2 pi, within eps. */
static int same_angle(double a, double b, double eps)
{
    return fabs(remainder(a - b, 2.0 * PI)) <= eps;
}

static void test_conventions(void)
{
    CHECK(same_angle(gis_phi_of(90.0, GIS_CCW_EAST), -PI / 2, 1e-15), "ccw-east 90 is north");
    CHECK(gis_phi_of(90.0, GIS_COMPASS) == 0.0, "compass 90 is east, phi 0");
    CHECK(same_angle(gis_phi_of(0.0, GIS_COMPASS), gis_phi_of(90.0, GIS_CCW_EAST), 1e-15),
          "compass 0 = ccw-east 90 (north)");
    CHECK(same_angle(gis_phi_of(180.0, GIS_COMPASS), PI / 2, 1e-15), "compass 180: south, +y");
    CHECK(same_angle(gis_phi_of(270.0, GIS_CCW_EAST), PI / 2, 1e-15), "ccw-east 270: south");
    CHECK(!strcmp(gis_convention_name(GIS_COMPASS), "compass"), "name");
    /* grids: north-up as is; south-up (+y north) mirrors y; west-running x. */
    CHECK(gis_grid_phi(0.3, 1, 1) == 0.3, "north-up: the map's phi");
    CHECK(same_angle(gis_grid_phi(-PI / 2, 1, -1), PI / 2, 1e-15), "south-up: north is +y");
    CHECK(same_angle(gis_grid_phi(0.0, 1, -1), 0.0, 1e-15), "south-up: east is +x");
    CHECK(same_angle(gis_grid_phi(0.0, -1, 1), PI, 1e-15), "west-running: east is -x");
    CHECK(same_angle(gis_grid_phi(PI / 6, -1, -1), PI / 6 + PI, 1e-15), "both: turned half");
    CHECK(gis_horizon_none(HFS_HORIZON_NONE) && !gis_horizon_none(-1.55f) &&
              !gis_horizon_none(0.0f), "HFS_HORIZON_NONE and only it");
}

/* The products of one texel whose n gammas are g[]. */
static void products(const float *g, int n, double *zaksek, double *lambert, double *open)
{
    double acc_z = 0.0, acc_l = 0.0, sum = 0.0;
    int count = 0;
    float out;
    for (int k = 0; k < n; ++k) {
        gis_svf_add(&acc_z, g + k, 1, GIS_SVF_ZAKSEK);
        gis_svf_add(&acc_l, g + k, 1, GIS_SVF_LAMBERTIAN);
        gis_openness_add(&sum, &count, g + k, 1);
    }
    gis_svf_finish(&out, &acc_z, 1, n, GIS_SVF_ZAKSEK);
    *zaksek = out;
    gis_svf_finish(&out, &acc_l, 1, n, GIS_SVF_LAMBERTIAN);
    *lambert = out;
    gis_openness_finish(&out, &sum, &count, 1);
    *open = out;
}

static void test_products(void)
{
    double z, l, o;
    const float flat[4] = {0.0f, 0.0f, HFS_HORIZON_NONE, 0.0f};
    products(flat, 4, &z, &l, &o);
    CHECK(z == 1.0 && l == 1.0 && o == 90.0, "flat: svf %g %g, openness %g", z, l, o);
    const double b = 30.0 * DEG;
    const float valley[4] = {(float)b, 0.0f, (float)b, 0.0f};
    products(valley, 4, &z, &l, &o);
    CHECK(fabs(z - (1.0 - sin(b) / 2.0)) < 1e-7, "valley Zaksek %.9g", z);
    CHECK(fabs(l - (1.0 + cos(b) * cos(b)) / 2.0) < 1e-7, "valley Lambertian %.9g", l);
    CHECK(fabs(o - (90.0 - 15.0)) < 1e-5, "valley openness %.9g", o);
    const float peak[3] = {-0.2f, -0.5f, -1.0f};
    products(peak, 3, &z, &l, &o);
    CHECK(z == 1.0 && l == 1.0, "a peak sees the whole sky: %g %g", z, l);
    CHECK(fabs(o - (90.0 + (0.2 + 0.5 + 1.0) / 3.0 / DEG)) < 1e-4, "peak openness %g", o);
    const float none[2] = {HFS_HORIZON_NONE, HFS_HORIZON_NONE};
    products(none, 2, &z, &l, &o);
    CHECK(z == 1.0 && isnan(o), "no terrain at all: svf 1, openness NaN (nodata)");
    /* Lambertian >= Zaksek; equal at 0 and 90 degrees. */
    srand(7);
    int ok = 1;
    for (int t = 0; t < 1000; ++t) {
        float g[8];
        for (int k = 0; k < 8; ++k)
            g[k] = (float)((rand() / (double)RAND_MAX - 0.3) * PI / 2);
        products(g, 8, &z, &l, &o);
        ok &= l >= z - 1e-6 && z >= 0.0 && l <= 1.0;
    }
    CHECK(ok, "Lambertian >= Zaksek over 1000 random horizons");
    const float ends[4] = {0.0f, (float)(PI / 2), 0.0f, (float)(PI / 2)};
    products(ends, 4, &z, &l, &o);
    CHECK(fabs(z - 0.5) < 1e-7 && fabs(l - 0.5) < 1e-7, "0 and 90 degrees: both 0.5");
    float deg[3];
    gis_horizon_degrees(deg, peak, 3);
    CHECK(deg[0] == 0.0f && deg[2] == 0.0f, "horizon raster: 0 where nothing rises");
    gis_horizon_degrees(deg, valley, 1);
    CHECK(fabs(deg[0] - 30.0) < 1e-5, "horizon raster: degrees");
}

/* The sun's disk under a horizon (gis_disk_visible) and how far terrain
 * can shadow it (gis_shadow_reach). */
static void test_disk(void)
{
    const double phi = 0.7, e = 0.4, a = 0.005;
    const double s[3] = {cos(phi) * cos(e), sin(phi) * cos(e), sin(e)};
    /* facing the sun, the weight is flat: the disk's area above a chord */
    CHECK(gis_disk_visible(s, phi, e, a, (float)(e - a - 1e-4)) == 1.0, "below the disk");
    CHECK(gis_disk_visible(s, phi, e, a, (float)(e + a + 1e-4)) == 0.0, "above the disk");
    CHECK(gis_disk_visible(s, phi, e, a, HFS_HORIZON_NONE) == 1.0, "no terrain");
    /* the disk's share above a chord b0 radii above its centre, exactly
     * (the closed form; b0 from the horizon as a float) */
    const float chords[3] = {(float)e, (float)(e - 0.5 * a), (float)(e + 0.9 * a)};
    for (int c = 0; c < 3; ++c) {
        const double b0 = ((double)chords[c] - e) / a;
        const double seg = (acos(b0) - b0 * sqrt(1.0 - b0 * b0)) / PI;
        const double v = gis_disk_visible(s, phi, e, a, chords[c]);
        CHECK(fabs(v - seg) < 1e-12, "a chord %.3f radii up: %.9f, area %.9f", b0, v, seg);
    }
    /* tilted towards the disk's top (the weight rising with b): more of
     * it above a chord through the centre than its area, as the closed
     * form's moment says: 1/2 + (4/3) alpha n.t_v / (pi n.s) */
    const double tilt[3] = {s[0] * cos(0.3) - cos(phi) * sin(e) * sin(0.3),
                            s[1] * cos(0.3) - sin(phi) * sin(e) * sin(0.3),
                            s[2] * cos(0.3) + cos(e) * sin(0.3)};
    const double b0 = ((double)(float)e - e) / a, ns = cos(0.3), nv = sin(0.3);
    const double want = (ns * (acos(b0) - b0 * sqrt(1.0 - b0 * b0)) +
                         a * nv * (2.0 / 3.0) * pow(1.0 - b0 * b0, 1.5)) / (PI * ns);
    const double tv = gis_disk_visible(tilt, phi, e, a, (float)e);
    CHECK(tv > 0.5 && fabs(tv - want) < 1e-12, "tilted up: %.9f, want %.9f", tv, want);
    /* the tangent plane through the centre, the disk's upper half above
     * it: a horizon through the centre hides none of what lights it */
    const double up[3] = {-sin(e) * cos(phi), -sin(e) * sin(phi), cos(e)};
    const double t = gis_disk_visible(up, phi, e, a, (float)e);
    CHECK(fabs(t - 1.0) < 1e-12, "the lit half above the horizon: %.6f", t);
    /* half a radius up: the weight b over b > 1/2 of the upper half,
     * int b 2 sqrt(1 - b^2) db from 1/2 over from 0 = (3/4)^(3/2) */
    const double low = gis_disk_visible(up, phi, e, a, (float)(e + 0.5 * a));
    CHECK(fabs(low - pow(0.75, 1.5)) < 0.01, "a horizon across the lit half: %.4f", low);
    CHECK(gis_disk_cut(e, a, (float)e) && !gis_disk_cut(e, a, (float)(e - a)) &&
              !gis_disk_cut(e, a, HFS_HORIZON_NONE), "cut");
    CHECK(fabs(gis_shadow_reach(100.0, atan(0.5)) - 200.0) < 1e-9, "reach");
    CHECK(gis_shadow_reach(100.0, 0.0) == HUGE_VAL && gis_shadow_reach(100.0, -0.1) == HUGE_VAL,
          "no reach below the horizontal");
}

/* The isotropic sky's share on a tilted surface (gis_sky_add): its
 * closed form per azimuth against a midpoint sum over the open sky's
 * elevations (above the horizon and the horizontal) of max(0, n.w) cos e,
 * and the cases with known answers. */
static double sky_share(const double n[3], const float *gamma, int n_dirs)
{
    double acc = 0.0;
    const float nf[3] = {(float)n[0], (float)n[1], (float)n[2]};
    for (int k = 0; k < n_dirs; ++k) {
        /* gamma[k] for this texel alone: the term of one azimuth */
        double a = 0.0;
        gis_sky_add(&a, &gamma[k], nf, 1, 2.0 * PI * k / n_dirs);
        acc += a;
    }
    float out;
    gis_sky_finish(&out, &acc, 1, n_dirs);
    return out;
}

static void test_sky(void)
{
    enum { N = 16 };
    float g[N];
    const double flat[3] = {0.0, 0.0, 1.0};
    for (int k = 0; k < N; ++k)
        g[k] = 0.0f;
    CHECK(fabs(sky_share(flat, g, N) - 1.0) < 1e-7, "open flat ground: 1");
    for (int k = 0; k < N; ++k)
        g[k] = (float)(30.0 * PI / 180.0);
    CHECK(fabs(sky_share(flat, g, N) - 0.75) < 1e-6, "flat under 30 degrees all round: cos^2");
    for (int k = 0; k < N; ++k)
        g[k] = k < N / 2 ? (float)(PI / 2) : 0.0f;
    CHECK(fabs(sky_share(flat, g, N) - 0.5) < 1e-6, "a wall over half the circle: 1/2");
    /* a tilted plane with nothing on it: (1 + n_z) / 2 (the upper
     * hemisphere's), whether the horizon is the plane itself (t) or no
     * terrain at all */
    const double s = 35.0 * PI / 180.0, az = 1.1;
    const double n[3] = {sin(s) * cos(az), sin(s) * sin(az), cos(s)};
    float plane[N], none[N];
    for (int k = 0; k < N; ++k) {
        const double ph = 2.0 * PI * k / N, nh = n[0] * cos(ph) + n[1] * sin(ph);
        plane[k] = (float)atan2(-nh, n[2]);
        none[k] = HFS_HORIZON_NONE;
    }
    const double want = 0.5 * (1.0 + cos(s));
    CHECK(fabs(sky_share(n, plane, N) - want) < 1e-6, "tilted open plane: %.7f, (1+nz)/2 %.7f",
          sky_share(n, plane, N), want);
    CHECK(fabs(sky_share(n, none, N) - want) < 1e-6, "tilted, no terrain: %.7f",
          sky_share(n, none, N));
    /* random normals and horizons: each azimuth's closed form against a
     * 20000-point midpoint sum over elevation of max(0, n.w) cos e */
    srand(7);
    double worst = 0.0;
    for (int t = 0; t < 200; ++t) {
        const double ts = (rand() / (double)RAND_MAX) * 1.2, ta = rand() / (double)RAND_MAX * 6.3;
        const double m[3] = {sin(ts) * cos(ta), sin(ts) * sin(ta), cos(ts)};
        const float mf[3] = {(float)m[0], (float)m[1], (float)m[2]};
        const double ph = rand() / (double)RAND_MAX * 6.3;
        const float gam = (float)((rand() / (double)RAND_MAX - 0.4) * PI);
        double a = 0.0, num = 0.0;
        gis_sky_add(&a, &gam, mf, 1, ph);
        for (int i = 0; i < 20000; ++i) {
            const double lo = fmax((double)gam, 0.0);
            const double e = lo + (PI / 2 - lo) * (i + 0.5) / 20000;
            const double d = mf[0] * cos(e) * cos(ph) + mf[1] * cos(e) * sin(ph) + mf[2] * sin(e);
            num += fmax(d, 0.0) * cos(e) * (PI / 2 - lo) / 20000;
        }
        worst = fmax(worst, fabs(a - num));
    }
    CHECK(worst < 1e-6, "closed form against the numeric integral: worst %.2e", worst);
}

static void test_names(void)
{
    char b[64];
    CHECK(!gis_horizon_name(b, sizeof b, "hor", 45.0, 0) && !strcmp(b, "hor_045.tif"), "%s", b);
    CHECK(!gis_horizon_name(b, sizeof b, "hor", 22.5, 1) && !strcmp(b, "hor_022_5.tif"), "%s",
          b);
    CHECK(!gis_horizon_name(b, sizeof b, "d.x/hor", 0.0, 1) && !strcmp(b, "d.x/hor_000_0.tif"),
          "%s", b);
    CHECK(!gis_horizon_name(b, sizeof b, "hor", -90.0, 0) && !strcmp(b, "hor_270.tif"), "%s", b);
    CHECK(!gis_horizon_name(b, sizeof b, "hor", 360.0, 0) && !strcmp(b, "hor_000.tif"), "%s", b);
    CHECK(gis_horizon_name(b, 8, "hor", 45.0, 0) == -1, "too long");
    CHECK(gis_decimals_of("22.5") == 1 && gis_decimals_of("45") == 0 &&
              gis_decimals_of("1.250") == 3 && gis_decimals_of("1e1") == 0,
          "decimals");
    CHECK(gis_nodata_for(1, -32768.0, 0.0, 1.0) == -32768.0f, "SRTM's nodata kept");
    CHECK(gis_nodata_for(1, 0.0, 0.0, 90.0) == GIS_NODATA, "0 would be a horizon: -9999");
    CHECK(gis_nodata_for(0, -32768.0, 0.0, 1.0) == GIS_NODATA, "none declared: -9999");
    CHECK(isnan(gis_nodata_for(1, NAN, 0.0, 1.0)), "NaN kept");
    CHECK(gis_nodata_for(1, 1e300, 0.0, 1.0) == GIS_NODATA, "beyond Float32: -9999");
}

static void test_sample_back(void)
{
    enum { SW = 9, SH = 12, WI = 9, HI = 10 };
    const double sy = 11.0 / 9.0; /* input rows 0..9 -> square rows 0..11 */
    float v[SW * SH], out[WI * HI];
    for (int j = 0; j < SH; ++j)
        for (int i = 0; i < SW; ++i)
            v[j * SW + i] = (float)(3.0 + 2.0 * i - 0.5 * j);
    unsigned char hole[WI * HI] = {0};
    hole[4 * WI + 4] = 1;
    gis_sample_back(v, SW, SH, 1.0, sy, WI, HI, hole, -9999.0f, out);
    double err = 0.0;
    for (int j = 0; j < HI; ++j)
        for (int i = 0; i < WI; ++i)
            if (j * WI + i != 4 * WI + 4)
                err = fmax(err, fabs(out[j * WI + i] - (3.0 + 2.0 * i - 0.5 * j * sy)));
    CHECK(err < 1e-5, "a plane sampled back off by %g", err);
    CHECK(out[4 * WI + 4] == -9999.0f, "a hole is nodata");
    v[5 * SW + 2] = NAN; /* a NaN of the product: nodata around it */
    gis_sample_back(v, SW, SH, 1.0, sy, WI, HI, NULL, -1.0f, out);
    CHECK(out[4 * WI + 2] == -1.0f, "NaN -> nodata");
    float same[SW * SH];
    v[5 * SW + 2] = 1.0f;
    gis_sample_back(v, SW, SH, 1.0, 1.0, SW, SH, NULL, -1.0f, same);
    CHECK(!memcmp(same, v, sizeof v), "a square grid copied as it is");
}

/* A valley along y with walls at angle b, through the products on backend
 * be: at its floor (away from the ends) E and W rise at b, N and S are 0. */
static void test_valley(hfs_backend be)
{
    enum { VW = 21, VH = 17, C = 10 };
    const double b = 25.0 * DEG, dx = 30.0;
    float z[VW * VH];
    for (int j = 0; j < VH; ++j)
        for (int i = 0; i < VW; ++i)
            z[j * VW + i] = (float)(abs(i - C) * dx * tan(b) / 2.0); /* zscale 2 */
    gis_dem dem = {.width = VW, .height = VH, .cx = dx, .cy = dx, .ex = 1, .ey = 1, .sw = VW,
                   .sh = VH, .sz = z, .d = dx};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    const hfs_renderer_desc desc = {.backend = be};
    if (hfs_renderer_create(&desc, &r, &err)) {
        CHECK(0, "renderer: %s", err.msg);
        return;
    }
    gis_compute c = {.r = r, .dem = &dem, .zscale = 2.0, .nodata = -9999.0f};
    float svf[VW * VH], pos[VW * VH], neg[VW * VH];
    const int p = 8 * VW + C;
    CHECK(!gis_product_svf(&c, 4, GIS_SVF_ZAKSEK, svf, &err), "%s", err.msg);
    CHECK(fabs(svf[p] - (1.0 - sin(b) / 2.0)) < 1e-6, "%s: floor svf %.9g, want %.9g",
          hfs_renderer_backend_name(r), svf[p], 1.0 - sin(b) / 2.0);
    CHECK(!gis_product_openness(&c, 4, pos, neg, &err), "%s", err.msg);
    CHECK(fabs(pos[p] - 77.5) < 1e-4 && fabs(neg[p] - 102.5) < 1e-4,
          "%s: floor openness %.7g / %.7g, want 77.5 / 102.5", hfs_renderer_backend_name(r),
          pos[p], neg[p]);
    hfs_renderer_destroy(r);
}

int main(void)
{
    test_conventions();
    test_products();
    test_disk();
    test_sky();
    test_names();
    test_sample_back();
    test_valley(HFS_BACKEND_TRUTH);
    test_valley(HFS_BACKEND_CPU);
    if (failures) {
        fprintf(stderr, "test_gis_math: %d of %ld checks failed\n", failures, checks);
        return 1;
    }
    printf("test_gis_math: %ld checks passed\n", checks);
    return 0;
}
