/*
 * capture.c — pixel formats and frame checks shared by the capture sources
 * (capture.h).
 */
#include "capture.h"

#include <linux/videodev2.h>
#include <string.h>

static const struct {
    hfs_pixfmt f;
    const char *name;
    uint32_t fourcc;
    int bytes;
} formats[] = {
    {HFS_PIX_Z16, "Z16", V4L2_PIX_FMT_Z16, 2},
    {HFS_PIX_Y16, "Y16", V4L2_PIX_FMT_Y16, 2},
    {HFS_PIX_GREY, "GREY", V4L2_PIX_FMT_GREY, 1},
    {HFS_PIX_YUYV, "YUYV", V4L2_PIX_FMT_YUYV, 2},
};
#define N_FORMATS (sizeof formats / sizeof formats[0])

const char *hfs_pixfmt_name(hfs_pixfmt f)
{
    for (size_t i = 0; i < N_FORMATS; ++i)
        if (formats[i].f == f)
            return formats[i].name;
    return NULL;
}

hfs_pixfmt hfs_pixfmt_from_name(const char *name)
{
    for (size_t i = 0; i < N_FORMATS; ++i)
        if (!strcmp(formats[i].name, name))
            return formats[i].f;
    return HFS_PIX_NONE;
}

uint32_t hfs_pixfmt_fourcc(hfs_pixfmt f)
{
    for (size_t i = 0; i < N_FORMATS; ++i)
        if (formats[i].f == f)
            return formats[i].fourcc;
    return 0;
}

hfs_pixfmt hfs_pixfmt_from_fourcc(uint32_t fourcc)
{
    for (size_t i = 0; i < N_FORMATS; ++i)
        if (formats[i].fourcc == fourcc)
            return formats[i].f;
    return HFS_PIX_NONE;
}

int hfs_pixfmt_bytes(hfs_pixfmt f)
{
    for (size_t i = 0; i < N_FORMATS; ++i)
        if (formats[i].f == f)
            return formats[i].bytes;
    return 0;
}

const char *hfs_fourcc_text(uint32_t fourcc, char buf[5])
{
    for (int i = 0; i < 4; ++i) {
        const char ch = (char)((fourcc >> (8 * i)) & 0xff);
        buf[i] = ch >= 32 && ch < 127 ? ch : '?';
    }
    buf[4] = '\0';
    return buf;
}

int hfs_capture_frame_check(const hfs_capture_frame *f, const char *who, hfs_error *err)
{
    const int bpp = hfs_pixfmt_bytes(f->format);
    if (!f->data || bpp == 0 || f->width < 1 || f->height < 1 ||
        f->stride < f->width * bpp)
        return hfs_fail(err, HFS_E_FORMAT, "%s: frame %u: bad geometry %dx%d stride %d",
                        who, f->sequence, f->width, f->height, f->stride);
    const size_t need = (size_t)(f->height - 1) * (size_t)f->stride + (size_t)f->width * bpp;
    if (f->bytes < need)
        return hfs_fail(err, HFS_E_FORMAT, "%s: frame %u: %zu bytes, %dx%d %s needs %zu", who,
                        f->sequence, f->bytes, f->width, f->height, hfs_pixfmt_name(f->format),
                        need);
    return HFS_OK;
}
