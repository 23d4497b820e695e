/*
 * envmap_exr.c — OpenEXR environment maps through the OpenEXRCore C API.
 *
 * Reads part 0 (scanline, or level 0 of a tiled part) with the library's own
 * decode pipeline (exr_decoding_initialize / choose_default_routines / run),
 * so every compression OpenEXRCore knows is supported and converted to float
 * by the library.  Channels: R, G, B if all three exist (others such as A are
 * skipped), else Y as grey; partial RGB sets, sub-sampled channels, deep
 * parts and cube-face environment maps are refused.  The data window is the
 * image; its top row is the zenith (SPEC).
 *
 * Invariants: we supply the I/O (pread on our own descriptor, with the file
 * size so the library can validate offsets) and an error handler that
 * records the library's first message instead of printing it; chunk
 * reconstruction is disabled, so a damaged offset table is an error, not a
 * guess.  Nothing large is allocated on a header's word alone: every chunk
 * is checked first (its rectangle against the image, its decoded size
 * against what its stored bytes can expand to) before the image is
 * allocated and decoded.
 */
#include "file_input.h"
#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <openexr.h>

typedef struct exr_src {
    int fd;
    int64_t size;
    char msg[256];          /* first message from the library */
} exr_src;

static void exr_on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    void *ud = NULL;
    (void)code;
    if (exr_get_user_data(ctxt, &ud) == EXR_ERR_SUCCESS && ud) {
        exr_src *s = ud;
        if (!s->msg[0])
            snprintf(s->msg, sizeof s->msg, "%s", msg ? msg : "");
    }
}

static int64_t exr_src_read(exr_const_context_t ctxt, void *ud, void *buffer, uint64_t sz,
                            uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_src *s = ud;
    uint64_t done = 0;

    while (done < sz) {
        ssize_t r = pread(s->fd, (char *)buffer + done, (size_t)(sz - done),
                          (off_t)(offset + done));
        if (r < 0) {
            if (errno == EINTR)
                continue;
            if (error_cb)
                error_cb(ctxt, EXR_ERR_READ_IO, "read error at offset %llu",
                         (unsigned long long)(offset + done));
            return -1;
        }
        if (r == 0)
            break; /* end of file: the library reports the short read */
        done += (uint64_t)r;
    }
    return (int64_t)done;
}

static int64_t exr_src_size(exr_const_context_t ctxt, void *ud)
{
    (void)ctxt;
    return ((exr_src *)ud)->size;
}

/* One-line error from a library result. */
static int exr_fail(const char *path, exr_src *s, exr_result_t rv, const char *step,
                    hfs_error *err)
{
    int code = rv == EXR_ERR_OUT_OF_MEMORY ? HFS_E_NOMEM
             : rv == EXR_ERR_FILE_ACCESS || rv == EXR_ERR_READ_IO ? HFS_E_IO
             : rv == EXR_ERR_FEATURE_NOT_IMPLEMENTED ? HFS_E_UNSUPPORTED
                                                    : HFS_E_FORMAT;
    return hfs_fail(err, code, "%s: OpenEXR %s failed: %s", path, step,
                    s->msg[0] ? s->msg : exr_get_error_code_as_string(rv));
}

typedef struct exr_job {
    const char *path;
    exr_src *src;
    exr_context_t ctxt;
    exr_decode_pipeline_t dec;
    int dec_live;
    int grey;               /* decode Y into component 0 only */
    int w, h;               /* data window size */
    exr_compression_t compression;
    float *rgb;             /* NULL while the chunks are only checked */
} exr_job;


static int component_of(const char *name, int grey)
{
    if (grey)
        return strcmp(name, "Y") == 0 ? 0 : -1;
    if (!strcmp(name, "R")) return 0;
    if (!strcmp(name, "G")) return 1;
    if (!strcmp(name, "B")) return 2;
    return -1;
}

/* The most a codec can expand a chunk's stored bytes, with a margin:
 * deflate (ZIP, ZIPS; PXR24 also widens 24-bit floats to 32) 1032:1, PIZ's
 * Huffman run codes about 410:1, RLE 64:1, B44 about 11:1.  DWA, which this
 * OpenEXRCore cannot decode, and later codecs get a loose bound. */
static uint64_t max_expansion(exr_compression_t c)
{
    switch (c) {
    case EXR_COMPRESSION_NONE: return 1;
    case EXR_COMPRESSION_RLE: return 128;
    case EXR_COMPRESSION_ZIPS:
    case EXR_COMPRESSION_ZIP:
    case EXR_COMPRESSION_PIZ:
    case EXR_COMPRESSION_PXR24:
    case EXR_COMPRESSION_B44:
    case EXR_COMPRESSION_B44A: return 2048;
    default: return 1u << 16;
    }
}

/* Checks one chunk whose top-left pixel is (x0, y0) in data-window space:
 * inside the image, and no larger decoded than its stored bytes allow (the
 * library allocates the decoded size before it decompresses). */
static int check_chunk(exr_job *j, const exr_chunk_info_t *ci, int x0, int y0, hfs_error *err)
{
    if (x0 < 0 || y0 < 0 || ci->width < 1 || ci->height < 1 || ci->width > j->w - x0 ||
        ci->height > j->h - y0)
        return hfs_fail(err, HFS_E_FORMAT, "%s: OpenEXR chunk %d (%dx%d at %d,%d) lies outside the "
                        "%dx%d image", j->path, ci->idx, ci->width, ci->height, x0, y0, j->w, j->h);
    if (ci->unpacked_size / max_expansion(j->compression) > ci->packed_size)
        return hfs_fail(err, HFS_E_FORMAT, "%s: corrupt OpenEXR chunk %d (%llu stored bytes cannot "
                        "decode to %llu)", j->path, ci->idx, (unsigned long long)ci->packed_size,
                        (unsigned long long)ci->unpacked_size);
    return HFS_OK;
}

/* Decodes one chunk that check_chunk() accepted. */
static int decode_chunk(exr_job *j, const exr_chunk_info_t *ci, int x0, int y0, hfs_error *err)
{
    exr_result_t rv;

    if (!j->dec_live) {
        rv = exr_decoding_initialize(j->ctxt, 0, ci, &j->dec);
        if (rv)
            return exr_fail(j->path, j->src, rv, "decoder setup", err);
        j->dec_live = 1;
    } else {
        rv = exr_decoding_update(j->ctxt, 0, ci, &j->dec);
        if (rv)
            return exr_fail(j->path, j->src, rv, "decoder update", err);
    }
    for (int c = 0; c < j->dec.channel_count; ++c) {
        exr_coding_channel_info_t *ch = &j->dec.channels[c];
        int k = component_of(ch->channel_name, j->grey);
        if (k < 0) {
            ch->decode_to_ptr = NULL; /* skipped by the library */
            continue;
        }
        if (ch->width != ci->width || ch->height != ci->height)
            return hfs_fail(err, HFS_E_FORMAT, "%s: OpenEXR channel %s has %dx%d samples in a %dx%d "
                            "chunk", j->path, ch->channel_name, ch->width, ch->height, ci->width,
                            ci->height);
        ch->decode_to_ptr =
            (uint8_t *)(j->rgb + ((size_t)y0 * (size_t)j->w + (size_t)x0) * 3 + (size_t)k);
        ch->user_pixel_stride = 3 * (int32_t)sizeof(float);
        ch->user_line_stride = j->w * 3 * (int32_t)sizeof(float);
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = (int16_t)sizeof(float);
    }
    /* Routines depend on the channel layout we just set, so choose them for
     * every chunk (cheap) rather than trust the first chunk's choice. */
    rv = exr_decoding_choose_default_routines(j->ctxt, 0, &j->dec);
    if (rv)
        return exr_fail(j->path, j->src, rv, "decoder setup", err);
    rv = exr_decoding_run(j->ctxt, 0, &j->dec);
    if (rv)
        return exr_fail(j->path, j->src, rv, "decoding", err);
    return HFS_OK;
}

/* Checks (while j->rgb is NULL) or decodes one chunk. */
static int visit_chunk(exr_job *j, const exr_chunk_info_t *ci, int x0, int y0, hfs_error *err)
{
    int rc = check_chunk(j, ci, x0, y0, err);
    if (rc || !j->rgb)
        return rc;
    return decode_chunk(j, ci, x0, y0, err);
}

static int read_scanlines(exr_job *j, const exr_attr_box2i_t *dw, hfs_error *err)
{
    int32_t lpc = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(j->ctxt, 0, &lpc);

    if (rv || lpc < 1)
        return exr_fail(j->path, j->src, rv ? rv : EXR_ERR_INVALID_ATTR, "scanline layout", err);
    for (int64_t y = dw->min.y; y <= dw->max.y; y += lpc) {
        exr_chunk_info_t ci;
        int rc;
        rv = exr_read_scanline_chunk_info(j->ctxt, 0, (int)y, &ci);
        if (rv)
            return exr_fail(j->path, j->src, rv, "reading a scanline chunk", err);
        if (ci.start_x != dw->min.x || ci.width != j->w)
            return hfs_fail(err, HFS_E_FORMAT, "%s: OpenEXR scanline chunk %d does not span the "
                            "data window", j->path, ci.idx);
        rc = visit_chunk(j, &ci, 0, (int)((int64_t)ci.start_y - dw->min.y), err);
        if (rc)
            return rc;
    }
    return HFS_OK;
}

static int read_tiles(exr_job *j, hfs_error *err)
{
    uint32_t tw = 0, th = 0;
    exr_tile_level_mode_t lmode;
    exr_tile_round_mode_t rmode;
    exr_result_t rv = exr_get_tile_descriptor(j->ctxt, 0, &tw, &th, &lmode, &rmode);
    int32_t lw = 0, lh = 0;

    if (rv || tw < 1 || th < 1)
        return exr_fail(j->path, j->src, rv ? rv : EXR_ERR_INVALID_ATTR, "tile layout", err);
    rv = exr_get_level_sizes(j->ctxt, 0, 0, 0, &lw, &lh);
    if (rv)
        return exr_fail(j->path, j->src, rv, "tile layout", err);
    if (lw != j->w || lh != j->h)
        return hfs_fail(err, HFS_E_FORMAT, "%s: OpenEXR level 0 is %dx%d but the data window is "
                        "%dx%d", j->path, lw, lh, j->w, j->h);
    for (int64_t ty = 0; ty * th < (int64_t)j->h; ++ty) {
        for (int64_t tx = 0; tx * tw < (int64_t)j->w; ++tx) {
            exr_chunk_info_t ci;
            int rc;
            rv = exr_read_tile_chunk_info(j->ctxt, 0, (int)tx, (int)ty, 0, 0, &ci);
            if (rv)
                return exr_fail(j->path, j->src, rv, "reading a tile", err);
            rc = visit_chunk(j, &ci, (int)(tx * tw), (int)(ty * th), err);
            if (rc)
                return rc;
        }
    }
    return HFS_OK;
}

/* Picks R,G,B or Y from the channel list; sets j->grey. */
static int choose_channels(exr_job *j, hfs_error *err)
{
    const exr_attr_chlist_t *cl = NULL;
    int have[4] = {0, 0, 0, 0}; /* R G B Y */
    exr_result_t rv = exr_get_channels(j->ctxt, 0, &cl);

    if (rv || !cl)
        return exr_fail(j->path, j->src, rv ? rv : EXR_ERR_MISSING_REQ_ATTR, "channel list", err);
    for (int c = 0; c < cl->num_channels; ++c) {
        const exr_attr_chlist_entry_t *e = &cl->entries[c];
        const char *nm = e->name.str;
        int k = !strcmp(nm, "R") ? 0 : !strcmp(nm, "G") ? 1 : !strcmp(nm, "B") ? 2
              : !strcmp(nm, "Y") ? 3 : -1;
        if (k < 0)
            continue;
        if (e->x_sampling != 1 || e->y_sampling != 1)
            return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: OpenEXR channel %s is sub-sampled (%d, %d); "
                            "only full-resolution channels are supported", j->path, nm,
                            e->x_sampling, e->y_sampling);
        have[k] = 1;
    }
    if (have[0] && have[1] && have[2]) {
        j->grey = 0;
        return HFS_OK;
    }
    if (have[0] || have[1] || have[2])
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: OpenEXR image has only part of R, G, B", j->path);
    if (have[3]) {
        j->grey = 1;
        return HFS_OK;
    }
    return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: OpenEXR image has no R, G, B or Y channel",
                    j->path);
}

static int load_part0(exr_job *j, hfs_error *err)
{
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    exr_envmap_t em;
    int nparts = 0, rc;
    int64_t w, h;
    exr_result_t rv;

    rv = exr_get_count(j->ctxt, &nparts);
    if (rv || nparts < 1)
        return exr_fail(j->path, j->src, rv ? rv : EXR_ERR_FILE_BAD_HEADER, "part count", err);
    rv = exr_get_storage(j->ctxt, 0, &storage);
    if (rv)
        return exr_fail(j->path, j->src, rv, "storage query", err);
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: deep OpenEXR images are not supported", j->path);
    if (exr_attr_get_envmap(j->ctxt, 0, "envmap", &em) == EXR_ERR_SUCCESS && em == EXR_ENVMAP_CUBE)
        return hfs_fail(err, HFS_E_UNSUPPORTED,
                        "%s: cube-face OpenEXR environment maps are not supported (need lat-long)",
                        j->path);
    j->src->msg[0] = '\0'; /* a missing optional attribute is not an error */
    rv = exr_get_data_window(j->ctxt, 0, &dw);
    if (rv)
        return exr_fail(j->path, j->src, rv, "data window", err);
    w = (int64_t)dw.max.x - dw.min.x + 1;
    h = (int64_t)dw.max.y - dw.min.y + 1;
    rc = hfs_io_check_size(j->path, w, h, 1, HFS_ENVMAP_MAX_DIM, HFS_ENVMAP_MAX_DIM,
                           HFS_ENVMAP_MAX_TEXELS, err);
    if (rc)
        return rc;
    j->w = (int)w;
    j->h = (int)h;
    if ((rc = choose_channels(j, err)))
        return rc;
    rv = exr_get_compression(j->ctxt, 0, &j->compression);
    if (rv)
        return exr_fail(j->path, j->src, rv, "compression query", err);
    /* Every chunk is checked before the image is allocated, so that a
     * header's claim costs memory only when the data to fill it is there
     * (reading the first chunk also checks that the offset table fits in
     * the file). */
    rc = storage == EXR_STORAGE_SCANLINE ? read_scanlines(j, &dw, err) : read_tiles(j, err);
    if (rc)
        return rc;
    j->rgb = calloc((size_t)j->w * (size_t)j->h * 3, sizeof *j->rgb);
    if (!j->rgb)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d map", j->path, j->w, j->h);
    rc = storage == EXR_STORAGE_SCANLINE ? read_scanlines(j, &dw, err) : read_tiles(j, err);
    if (rc)
        return rc;
    if (j->grey) {
        size_t n = (size_t)j->w * (size_t)j->h;
        for (size_t k = 0; k < n; ++k)
            j->rgb[3 * k + 1] = j->rgb[3 * k + 2] = j->rgb[3 * k];
    }
    return HFS_OK;
}

int hfs_io_envmap_load_exr(const char *path, hfs_envmap *out, hfs_error *err)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_src src;
    exr_job job;
    exr_result_t rv;
    int rc;

    memset(&src, 0, sizeof src);
    memset(&job, 0, sizeof job);
    long long size;
    if ((rc = hfs_open_regular(path, "environment map", &src.fd, &size, err)))
        return rc;
    src.size = (int64_t)size;

    init.error_handler_fn = exr_on_error;
    init.user_data = &src;
    init.read_fn = exr_src_read;
    init.size_fn = exr_src_size;
    init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;

    job.path = path;
    job.src = &src;
    rv = exr_start_read(&job.ctxt, path, &init);
    if (rv) {
        rc = exr_fail(path, &src, rv, "header parsing", err);
    } else {
        rc = load_part0(&job, err);
    }
    if (job.dec_live)
        exr_decoding_destroy(job.ctxt, &job.dec);
    if (job.ctxt)
        exr_finish(&job.ctxt);
    close(src.fd);
    if (rc) {
        free(job.rgb);
        return rc;
    }
    out->width = job.w;
    out->height = job.h;
    out->rgb = job.rgb;
    return HFS_OK;
}
