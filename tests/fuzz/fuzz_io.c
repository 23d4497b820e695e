/*
 * fuzz_io.c — the height-field and environment-map checks shared by the
 * loader fuzz targets (see fuzz.h): load, then check the contract of
 * hfs_io.h on success (sizes within the guards, finite values, the expected
 * format) and on failure (one-line message, zeroed output).
 */
#include "fuzz.h"
#include "hfs_io.h"

#include <math.h>

static void check_finite(const float *v, size_t n, const char *what, const char *path)
{
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(v[k]))
            fuzz_fail(what, path);
}

void fuzz_height(const char *name, const uint8_t *data, size_t size,
                 const hfs_height_load_opts *opts, int expect)
{
    const char *path = fuzz_write(name, data, size);
    hfs_heightmap hm;
    hfs_error err;
    int rc;

    if (!path)
        return;
    err.msg[0] = '\0';
    rc = hfs_height_load(path, opts, &hm, &err);
    if (rc == 0) {
        size_t n = (size_t)hm.width * (size_t)hm.height;
        fuzz_check_size(path, hm.width, hm.height, 2, HFS_HEIGHT_MAX_DIM, hm.z);
        if (hm.holes < 0 || (size_t)hm.holes >= n)
            fuzz_fail("impossible hole count", path);
        if ((int)hm.format != expect)
            fuzz_fail("height field loaded as an unexpected format", path);
        check_finite(hm.z, n, "non-finite height after hole filling", path);
        hfs_heightmap_free(&hm);
    } else {
        fuzz_check_failure(path, rc, &err, !hm.z && !hm.width && !hm.height && !hm.holes);
    }
    fuzz_remove(path);
}

void fuzz_envmap(const char *name, const uint8_t *data, size_t size)
{
    const char *path = fuzz_write(name, data, size);
    hfs_envmap em;
    hfs_error err;
    int rc;

    if (!path)
        return;
    err.msg[0] = '\0';
    rc = hfs_envmap_load(path, &em, &err);
    if (rc == 0) {
        size_t n = (size_t)em.width * (size_t)em.height * 3;
        fuzz_check_size(path, em.width, em.height, 1, HFS_ENVMAP_MAX_DIM, em.rgb);
        check_finite(em.rgb, n, "non-finite environment map value", path);
        hfs_envmap_free(&em);
    } else {
        fuzz_check_failure(path, rc, &err, !em.rgb && !em.width && !em.height);
    }
    fuzz_remove(path);
}
