/*
 * test_validate_once.c — heights are checked once per change
 * (hfs_renderer_set_field_serial, hfshade.h), through the public API on the
 * CPU backend (no GL needed):
 *   - no serial (the default): a height changed to NaN in place, between two
 *     renders of the same field, fails the very render that follows, with
 *     one line naming the texel; so does a NaN in a new array;
 *   - with a serial: the change declared by a new serial fails the next
 *     render the same way; a field at another address is scanned even under
 *     the same serial; while pointer, size and serial stay, the heights are
 *     not scanned again (a NaN slipped in against the contract is not
 *     reported as a height: the scan did not run), and
 *     hfs_renderer_invalidate forgets what was checked;
 *   - the other inputs are still checked on every render.
 */
#include "check.h"
#include "hfshade.h"

#include <math.h>
#include <string.h>

#define W 9
#define H 7

static int render(hfs_renderer *r, const float *z, const hfs_lighting *l, const hfs_quality *q,
                  hfs_image *img, hfs_error *err)
{
    const hfs_field f = {.width = W, .height = H, .z = z, .dx = 1.0, .zscale = 1.0};
    memset(err, 0, sizeof *err);
    return hfs_renderer_render(r, &f, l, q, img, NULL, NULL, err);
}

/* The refusal of a non-finite height at texel k: one line, naming it. */
static int refused_at(int rc, const hfs_error *err, int k)
{
    char want[64];
    snprintf(want, sizeof want, "non-finite height at texel %d", k);
    return rc == HFS_E_INVALID && strstr(err->msg, want) && !strchr(err->msg, '\n');
}

int main(void)
{
    float z[W * H], other[W * H];
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
            z[j * W + i] = other[j * W + i] = (float)(0.3 * sin(0.7 * i) + 0.2 * cos(0.9 * j));
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    l.env_sh[0][0] = l.env_sh[1][0] = l.env_sh[2][0] = 3.5449077;
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.nphi_env = 4;
    q.threads = 1;
    hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_image img = {0};
    hfs_error err = {{0}};
    if (hfs_renderer_create(&d, &r, &err) || hfs_image_alloc(&img, W, H, &err)) {
        fprintf(stderr, "setup: %s\n", err.msg);
        return 1;
    }

    /* No serial: every render scans. */
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "good field: %s", err.msg);
    z[23] = NAN;
    int rc = render(r, z, &l, &q, &img, &err);
    CHECK(refused_at(rc, &err, 23), "NaN set in place, no serial: rc %d '%s'", rc, err.msg);
    z[23] = 0.0f;
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "repaired: %s", err.msg);
    other[5] = INFINITY;
    rc = render(r, other, &l, &q, &img, &err);
    CHECK(refused_at(rc, &err, 5), "Inf in another array: rc %d '%s'", rc, err.msg);
    other[5] = 0.0f;

    /* A serial: the caller declares each change. */
    hfs_renderer_set_field_serial(r, 1);
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "serial 1: %s", err.msg);
    z[40] = NAN;
    hfs_renderer_set_field_serial(r, 2);
    rc = render(r, z, &l, &q, &img, &err);
    CHECK(refused_at(rc, &err, 40), "NaN declared by serial 2: rc %d '%s'", rc, err.msg);
    z[40] = 0.0f;
    hfs_renderer_set_field_serial(r, 3);
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "serial 3: %s", err.msg);
    other[7] = NAN;
    rc = render(r, other, &l, &q, &img, &err);
    CHECK(refused_at(rc, &err, 7), "another address under serial 3: rc %d '%s'", rc, err.msg);
    other[7] = 0.0f;

    /* Same pointer, size and serial: no scan (this NaN breaks the contract:
     * only the backend's output check may still catch it). */
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "serial 3 again: %s", err.msg);
    z[11] = NAN;
    rc = render(r, z, &l, &q, &img, &err);
    CHECK(!strstr(err.msg, "non-finite height"), "heights scanned again under an unchanged "
          "serial: '%s'", err.msg);
    for (size_t i = 0; i < (size_t)W * H * 3; ++i)
        CHECK(isfinite(img.rgb[i]) || rc != 0, "non-finite output %zu written", i);
    hfs_renderer_invalidate(r);
    rc = render(r, z, &l, &q, &img, &err);
    CHECK(refused_at(rc, &err, 11), "after hfs_renderer_invalidate: rc %d '%s'", rc, err.msg);
    z[11] = 0.0f;

    /* The other inputs: checked on every call, whatever the serial. */
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "serial 3, good: %s", err.msg);
    l.albedo = 1.5;
    rc = render(r, z, &l, &q, &img, &err);
    CHECK(rc == HFS_E_INVALID && strstr(err.msg, "albedo") && !strchr(err.msg, '\n'),
          "albedo 1.5 under a serial: rc %d '%s'", rc, err.msg);
    l.albedo = 1.0;
    q.k = 0;
    rc = render(r, z, &l, &q, &img, &err);
    CHECK(rc == HFS_E_INVALID && strstr(err.msg, "k: 0"), "k 0 under a serial: '%s'", err.msg);
    q.k = 2;

    /* Serial 0 again: back to scanning every render. */
    hfs_renderer_set_field_serial(r, 0);
    CHECK(render(r, z, &l, &q, &img, &err) == 0, "serial 0: %s", err.msg);
    z[0] = -INFINITY;
    rc = render(r, z, &l, &q, &img, &err);
    CHECK(refused_at(rc, &err, 0), "-Inf in place, serial 0: rc %d '%s'", rc, err.msg);

    hfs_image_free(&img);
    hfs_renderer_destroy(r);
    printf("%s: %ld checks, %d failure(s)\n", failures ? "FAIL" : "PASS", checks, failures);
    return failures ? 1 : 0;
}
