/*
 * height_load.c — hfs_height_load(): picks the format, runs its loader, fills
 * the holes; also the raw float32 loader, which is too small for a file.
 *
 * Format choice: a known extension names the format and the content must
 * carry that format's signature (so a mislabelled file gets a precise error,
 * never a silent misread); otherwise the signature decides; raw float32 has
 * no signature, so it needs a raw extension or an explicit size.
 *
 * Invariants: *out is zero unless the whole load (including hole filling)
 * succeeded; every error message starts with the path.
 */
#include "io_internal.h"

#include <stdlib.h>
#include <string.h>

static int ieq_prefix(const unsigned char *p, size_t n, const char *word)
{
    size_t k = 0;
    for (; word[k]; ++k) {
        int c;
        if (k >= n)
            return 0;
        c = p[k];
        if (c >= 'A' && c <= 'Z')
            c += 'a' - 'A';
        if (c != word[k])
            return 0;
    }
    /* The key must end at whitespace, or at the end of a file that ends
     * right there (the loader then reports the truncated header). */
    return k == n || hfs_io_isspace(p[k]);
}

/* Format by signature; *other names a recognised non-height format. */
static hfs_height_format sniff(const unsigned char *p, size_t n, const char **other)
{
    static const char *const asc_keys[] = {"ncols", "nrows", "xllcorner", "xllcenter",
                                           "yllcorner", "yllcenter", "cellsize",
                                           "nodata_value"};
    *other = NULL;
    if (n >= 8 && memcmp(p, "\x89PNG\r\n\x1a\n", 8) == 0)
        return HFS_HEIGHT_PNG;
    if (n >= 3 && p[0] == 'P' && (hfs_io_isspace(p[2]) || p[2] == '#')) {
        switch (p[1]) {
        case '5': case '2': return HFS_HEIGHT_PGM;
        case '1': case '4': *other = "a PBM bitmap"; return HFS_HEIGHT_AUTO;
        case '3': case '6': *other = "a colour PPM image"; return HFS_HEIGHT_AUTO;
        case '7': *other = "a PAM image"; return HFS_HEIGHT_AUTO;
        default: break;
        }
    }
    if (n >= 3 && p[0] == 'P' && p[1] == 'f' && hfs_io_isspace(p[2]))
        return HFS_HEIGHT_PFM;
    if (n >= 3 && p[0] == 'P' && p[1] == 'F' && hfs_io_isspace(p[2])) {
        /* Let the PFM loader give the precise "colour PFM" message. */
        return HFS_HEIGHT_PFM;
    }
    if (n >= 2 && p[0] == '#' && p[1] == '?') {
        *other = "a Radiance HDR image (an environment map format)";
        return HFS_HEIGHT_AUTO;
    }
    if (n >= 4 && memcmp(p, "\x76\x2f\x31\x01", 4) == 0) {
        *other = "an OpenEXR image (an environment map format)";
        return HFS_HEIGHT_AUTO;
    }
    {
        size_t k = 0;
        while (k < n && hfs_io_isspace(p[k]))
            ++k;
        for (size_t i = 0; i < sizeof asc_keys / sizeof asc_keys[0]; ++i)
            if (ieq_prefix(p + k, n - k, asc_keys[i]))
                return HFS_HEIGHT_ASC;
    }
    return HFS_HEIGHT_AUTO;
}

static hfs_height_format from_extension(const char *path)
{
    char ext[8];
    hfs_io_extension(path, ext, sizeof ext);
    if (!strcmp(ext, "png")) return HFS_HEIGHT_PNG;
    if (!strcmp(ext, "pgm") || !strcmp(ext, "pnm")) return HFS_HEIGHT_PGM;
    if (!strcmp(ext, "pfm")) return HFS_HEIGHT_PFM;
    if (!strcmp(ext, "asc")) return HFS_HEIGHT_ASC;
    if (!strcmp(ext, "raw") || !strcmp(ext, "f32") || !strcmp(ext, "r32") ||
        !strcmp(ext, "bin"))
        return HFS_HEIGHT_RAW_F32;
    return HFS_HEIGHT_AUTO;
}

static const char *format_name(hfs_height_format f)
{
    switch (f) {
    case HFS_HEIGHT_PNG: return "PNG";
    case HFS_HEIGHT_PGM: return "PGM";
    case HFS_HEIGHT_PFM: return "PFM";
    case HFS_HEIGHT_ASC: return "ESRI ASCII grid";
    case HFS_HEIGHT_RAW_F32: return "raw float32";
    case HFS_HEIGHT_EXTERNAL: return "GDAL raster";
    default: return "unknown";
    }
}

static int load_raw(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out, hfs_error *err)
{
    size_t n = (size_t)o->raw_w * (size_t)o->raw_h;
    long long bytes = (long long)n * 4;
    unsigned char *b;
    float *z;
    int rc;

    rc = hfs_io_check_size(rd->path, o->raw_w, o->raw_h, 2, o->max_w, o->max_h,
                           o->max_texels, err);
    if (rc)
        return rc;
    /* Check the size before allocating: a wrong --size is the usual mistake
     * and deserves a message with both numbers. */
    if (rd->file_size >= 0 && rd->file_size != bytes)
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: file has %lld bytes but raw float32 %dx%d needs exactly %lld",
                        rd->path, rd->file_size, o->raw_w, o->raw_h, bytes);
    z = malloc(n * sizeof *z);
    if (!z)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for %dx%d heights", rd->path,
                        o->raw_w, o->raw_h);
    b = (unsigned char *)z;
    if (hfs_rd_read(rd, b, n * 4) != n * 4) {
        free(z);
        return hfs_rd_fail_short(rd, err, "raw float32 data");
    }
    rc = hfs_rd_expect_end(rd, 0, err, "raw float32 data");
    if (rc) {
        free(z);
        return rc;
    }
    for (size_t k = 0; k < n; ++k)
        z[k] = hfs_io_f32_le(b + 4 * k); /* reads its 4 bytes before writing them */
    out->width = o->raw_w;
    out->height = o->raw_h;
    out->z = z;
    return HFS_OK;
}

static int resolve_opts(const char *path, const hfs_height_load_opts *opts, hfs_io_hopts *o,
                        hfs_error *err)
{
    hfs_height_load_opts zero;
    memset(&zero, 0, sizeof zero);
    if (!opts)
        opts = &zero;
    if (opts->raw_width < 0 || opts->raw_height < 0 ||
        (opts->raw_width == 0) != (opts->raw_height == 0))
        return hfs_fail(err, HFS_E_INVALID, "%s: invalid raw size %dx%d", path,
                        opts->raw_width, opts->raw_height);
    if (opts->max_width < 0 || opts->max_height < 0 || opts->max_texels < 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: invalid size limit", path);
    o->max_w = opts->max_width ? opts->max_width : HFS_HEIGHT_MAX_DIM;
    o->max_h = opts->max_height ? opts->max_height : HFS_HEIGHT_MAX_DIM;
    o->max_texels = opts->max_texels ? opts->max_texels : HFS_HEIGHT_MAX_TEXELS;
    o->raw_w = opts->raw_width;
    o->raw_h = opts->raw_height;
    return HFS_OK;
}

static hfs_height_loader_fn extra_loader;

void hfs_height_set_extra_loader(hfs_height_loader_fn fn)
{
    extra_loader = fn;
}

int hfs_height_load(const char *path, const hfs_height_load_opts *opts, hfs_heightmap *out,
                    hfs_error *err)
{
    hfs_io_hopts o;
    hfs_rd rd;
    hfs_height_format by_ext, by_content, fmt;
    const unsigned char *head;
    const char *other;
    size_t nhead;
    int rc;

    if (!out)
        return hfs_fail(err, HFS_E_INVALID, "%s: no output", path ? path : "(no file)");
    memset(out, 0, sizeof *out);
    if (!path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): no height field path");
    rc = resolve_opts(path, opts, &o, err);
    if (rc)
        return rc;
    rc = hfs_rd_open(&rd, path, err);
    if (rc)
        return rc;

    nhead = hfs_rd_peek(&rd, 64, &head);
    if (nhead == 0) {
        rc = rd.read_errno ? hfs_rd_fail_short(&rd, err, "file")
                           : hfs_fail(err, HFS_E_FORMAT, "%s: empty file", path);
        goto out;
    }
    by_ext = from_extension(path);
    by_content = sniff(head, nhead, &other);
    if (by_ext == HFS_HEIGHT_RAW_F32) {
        fmt = by_ext; /* no signature to check */
    } else if (by_ext != HFS_HEIGHT_AUTO) {
        if (by_content != by_ext) {
            const char *what = by_content != HFS_HEIGHT_AUTO ? format_name(by_content) : other;
            if (what)
                rc = hfs_fail(err, HFS_E_FORMAT, "%s: not a valid %s file (the content is %s)",
                              path, format_name(by_ext), what);
            else
                rc = hfs_fail(err, HFS_E_FORMAT, "%s: not a valid %s file (bad signature)", path,
                              format_name(by_ext));
            goto out;
        }
        fmt = by_ext;
    } else if (by_content != HFS_HEIGHT_AUTO) {
        fmt = by_content;
    } else if (other) {
        rc = hfs_fail(err, HFS_E_UNSUPPORTED, "%s: this is %s, not a height field", path, other);
        goto out;
    } else if (extra_loader && !o.raw_w &&
               (rc = extra_loader(path, opts, out, err)) != HFS_E_UNSUPPORTED) {
        goto out; /* read (or refused with its own message) by the extra loader */
    } else if (o.raw_w) {
        fmt = HFS_HEIGHT_RAW_F32;
    } else {
        rc = hfs_fail(err, HFS_E_FORMAT,
                      "%s: unrecognised height field format (expected PNG, PGM, PFM, ESRI .asc, "
                      "or raw float32 with a size)", path);
        goto out;
    }
    if (fmt == HFS_HEIGHT_RAW_F32 && !o.raw_w) {
        rc = hfs_fail(err, HFS_E_INVALID, "%s: raw float32 needs its size (--size WxH)", path);
        goto out;
    }
    if (fmt != HFS_HEIGHT_RAW_F32 && o.raw_w) {
        rc = hfs_fail(err, HFS_E_INVALID, "%s: a raw size was given but the file is %s, not raw float32",
                      path, format_name(fmt));
        goto out;
    }

    switch (fmt) {
    case HFS_HEIGHT_PNG: rc = hfs_io_load_png(&rd, &o, out, err); break;
    case HFS_HEIGHT_PGM: rc = hfs_io_load_pgm(&rd, &o, out, err); break;
    case HFS_HEIGHT_PFM: rc = hfs_io_load_pfm(&rd, &o, out, err); break;
    case HFS_HEIGHT_ASC: rc = hfs_io_load_asc(&rd, &o, out, err); break;
    default: rc = load_raw(&rd, &o, out, err); break;
    }
    if (rc)
        goto out;

    {
        hfs_error ferr;
        long holes = 0;
        int frc = hfs_height_fill_holes(out->z, out->width, out->height,
                                        opts ? opts->has_nodata : 0, opts ? opts->nodata : 0.0f,
                                        &holes, &ferr);
        if (frc) {
            rc = hfs_fail(err, frc, "%s: %s", path, ferr.msg);
            goto out;
        }
        out->holes = holes;
        out->format = fmt;
    }

out:
    hfs_rd_close(&rd);
    if (rc)
        hfs_heightmap_free(out);
    return rc;
}

void hfs_heightmap_free(hfs_heightmap *hm)
{
    if (!hm)
        return;
    free(hm->z);
    memset(hm, 0, sizeof *hm);
}
