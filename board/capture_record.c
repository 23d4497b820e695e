/*
 * capture_record.c — recordings (capture_record.h): the writer and the
 * replay source.
 */
#include "capture_record.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "file_input.h"

#define INDEX_NAME "capture.txt"
#define INDEX_MAX (64 << 20)

/* ---- writing -------------------------------------------------------------------- */

struct hfs_capture_recorder {
    char dir[256];
    FILE *index;
    long n;
    hfs_pixfmt format;
    int width, height;
    int failed;
};

int hfs_capture_record_open(const char *dir, hfs_capture_recorder **out, hfs_error *err)
{
    *out = NULL;
    if (strlen(dir) > 200)
        return hfs_fail(err, HFS_E_INVALID, "--capture-record %s: path too long", dir);
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return hfs_fail(err, HFS_E_IO, "--capture-record %s: %s", dir, strerror(errno));
    char path[300];
    snprintf(path, sizeof path, "%s/%s", dir, INDEX_NAME);
    struct stat st;
    if (stat(path, &st) == 0)
        return hfs_fail(err, HFS_E_INVALID, "--capture-record %s: already holds a recording",
                        dir);
    hfs_capture_recorder *r = calloc(1, sizeof *r);
    if (!r)
        return hfs_fail(err, HFS_E_NOMEM, "--capture-record: out of memory");
    snprintf(r->dir, sizeof r->dir, "%s", dir);
    if (!(r->index = fopen(path, "wx"))) {
        free(r);
        return hfs_fail(err, HFS_E_IO, "--capture-record %s: %s", path, strerror(errno));
    }
    *out = r;
    return HFS_OK;
}

static int write_rows(const char *path, const hfs_capture_frame *f)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return -1;
    const size_t row = (size_t)f->width * (size_t)hfs_pixfmt_bytes(f->format);
    int bad = 0;
    for (int y = 0; y < f->height && !bad; ++y)
        bad = fwrite(f->data + (size_t)y * (size_t)f->stride, 1, row, fp) != row;
    return (fclose(fp) != 0 || bad) ? -1 : 0;
}

int hfs_capture_record_frame(hfs_capture_recorder *r, const hfs_capture_frame *f,
                             hfs_error *err)
{
    if (r->failed)
        return hfs_fail(err, HFS_E_IO, "--capture-record %s: stopped after an error", r->dir);
    int rc = hfs_capture_frame_check(f, "--capture-record", err);
    if (rc)
        return rc;
    if (r->n == 0) {
        r->format = f->format, r->width = f->width, r->height = f->height;
        fprintf(r->index, "hfs-capture 1\nformat %s\nsize %d %d\n", hfs_pixfmt_name(f->format),
                f->width, f->height);
    } else if (f->format != r->format || f->width != r->width || f->height != r->height) {
        return hfs_fail(err, HFS_E_INVALID, "--capture-record %s: frame %u is %dx%d %s, the "
                        "recording %dx%d %s", r->dir, f->sequence, f->width, f->height,
                        hfs_pixfmt_name(f->format), r->width, r->height,
                        hfs_pixfmt_name(r->format));
    }
    char name[32], path[300];
    snprintf(name, sizeof name, "frame-%06ld.raw", r->n);
    snprintf(path, sizeof path, "%s/%s", r->dir, name);
    if (write_rows(path, f) ||
        fprintf(r->index, "frame %u %lld %s\n", f->sequence, (long long)f->t_ns, name) < 0 ||
        fflush(r->index) != 0) {
        r->failed = 1;
        return hfs_fail(err, HFS_E_IO, "--capture-record %s: %s", path, strerror(errno));
    }
    r->n++;
    return HFS_OK;
}

int hfs_capture_record_close(hfs_capture_recorder *r, hfs_error *err)
{
    if (!r)
        return HFS_OK;
    const int bad = fclose(r->index) != 0 || r->failed;
    int rc = bad ? hfs_fail(err, HFS_E_IO, "--capture-record %s: incomplete", r->dir) : HFS_OK;
    free(r);
    return rc;
}

/* ---- replay ---------------------------------------------------------------------- */

typedef struct rec_frame {
    uint32_t seq;
    int64_t t_ns;
    char file[64];
} rec_frame;

typedef struct replay_cap {
    hfs_capture base;
    char dir[256];
    hfs_pixfmt format;
    int width, height;
    rec_frame *f;
    int n, next;
    int64_t base_ns;          /* due time of frame 0 in this pass */
    int loop;
    int pace_shown;           /* never skip: the clock waits for next() */
    uint8_t *buf;             /* the frame handed out */
    size_t frame_bytes;
    int have_seq;
    uint32_t last_seq;
} replay_cap;

static int parse_header(replay_cap *c, const char *path, int line, const char *s,
                        hfs_error *err)
{
    char fmt[16];
    int w, h;
    if (line == 1)
        return strcmp(s, "hfs-capture 1") ? hfs_fail(err, HFS_E_FORMAT, "%s:1: not an "
                                                     "hfs-capture 1 index", path)
                                          : HFS_OK;
    if (sscanf(s, "format %15s", fmt) == 1) {
        c->format = hfs_pixfmt_from_name(fmt);
        return c->format ? HFS_OK : hfs_fail(err, HFS_E_FORMAT, "%s:%d: unknown format '%s' "
                                             "(Z16, Y16, GREY, YUYV)", path, line, fmt);
    }
    if (sscanf(s, "size %d %d", &w, &h) == 2) {
        if (w < 1 || h < 1 || w > 16384 || h > 16384)
            return hfs_fail(err, HFS_E_FORMAT, "%s:%d: size %dx%d out of range", path, line,
                            w, h);
        c->width = w, c->height = h;
        return HFS_OK;
    }
    return hfs_fail(err, HFS_E_FORMAT, "%s:%d: expected 'format', 'size' or 'frame'", path,
                    line);
}

static int parse_frame(replay_cap *c, const char *path, int line, const char *s, hfs_error *err)
{
    rec_frame fr;
    unsigned seq;
    long long t;
    char tail[2];
    if (sscanf(s, "frame %u %lld %63s %1s", &seq, &t, fr.file, tail) != 3 ||
        strchr(fr.file, '/'))
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: expected 'frame SEQUENCE T_NS FILE' "
                        "(FILE in the directory)", path, line);
    if (!c->format || !c->width)
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: a frame before format and size", path, line);
    if (c->n > 0 && t < c->f[c->n - 1].t_ns)
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: time goes backwards", path, line);
    if (c->n % 256 == 0) {
        rec_frame *g = realloc(c->f, (size_t)(c->n + 256) * sizeof *g);
        if (!g)
            return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
        c->f = g;
    }
    fr.seq = seq;
    fr.t_ns = t;
    c->f[c->n++] = fr;
    return HFS_OK;
}

static int load_index(replay_cap *c, hfs_error *err)
{
    char path[300];
    snprintf(path, sizeof path, "%s/%s", c->dir, INDEX_NAME);
    char *text = NULL;
    int rc = hfs_read_text_file(path, "capture index", INDEX_MAX, &text, NULL, err);
    if (rc)
        return rc;
    int line = 0;
    for (char *s = text, *nl; !rc && s && *s; s = nl ? nl + 1 : NULL) {
        nl = strchr(s, '\n');
        if (nl)
            *nl = '\0';
        ++line;
        if (*s == '#' || *s == '\0')
            continue;
        rc = strncmp(s, "frame ", 6) ? parse_header(c, path, line, s, err)
                                     : parse_frame(c, path, line, s, err);
    }
    free(text);
    if (!rc && c->n == 0)
        rc = hfs_fail(err, HFS_E_FORMAT, "%s: no frames", path);
    return rc;
}

static int load_frame(replay_cap *c, const rec_frame *fr, hfs_error *err)
{
    char path[340];
    snprintf(path, sizeof path, "%s/%s", c->dir, fr->file);
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return hfs_fail(err, HFS_E_FORMAT, "%s: %s", path, strerror(errno));
    const size_t got = fread(c->buf, 1, c->frame_bytes, fp);
    const int extra = fgetc(fp) != EOF;
    fclose(fp);
    if (got != c->frame_bytes || extra)
        return hfs_fail(err, HFS_E_FORMAT, "%s: %s, a %dx%d %s frame is %zu bytes", path,
                        extra ? "too long" : "too short", c->width, c->height,
                        hfs_pixfmt_name(c->format), c->frame_bytes);
    return HFS_OK;
}

static int64_t due(const replay_cap *c, int i)
{
    return c->base_ns + (c->f[i].t_ns - c->f[0].t_ns);
}

/* When a looping replay starts its next pass: one frame period after the
 * last frame. */
static int64_t next_pass(const replay_cap *c)
{
    const int64_t period = c->n > 1 ? (c->f[c->n - 1].t_ns - c->f[0].t_ns) / (c->n - 1)
                                    : 33333333;
    return due(c, c->n - 1) + period;
}

static int r_next(hfs_capture *base, int64_t now_ns, hfs_capture_frame *out, hfs_error *err)
{
    replay_cap *c = (replay_cap *)base;
    if (c->next >= c->n && c->loop && now_ns >= next_pass(c)) {
        c->base_ns = next_pass(c);
        c->next = 0;
        c->have_seq = 0; /* the sequence starts again: no gap */
    }
    if (c->next >= c->n || due(c, c->next) > now_ns)
        return 0;
    int i = c->next;
    long skipped = 0;
    if (c->pace_shown)
        c->base_ns += now_ns - due(c, i); /* late by that much: the clock waited */
    while (!c->pace_shown && i + 1 < c->n && due(c, i + 1) <= now_ns) {
        skipped++;
        i++;
    }
    base->superseded += skipped;
    c->next = i + 1;
    base->finished = c->next >= c->n && !c->loop;
    int rc = load_frame(c, &c->f[i], err);
    if (rc)
        return rc;
    /* Gaps the recording holds (the device dropped them), not the frames
     * skipped here for a newer one. */
    if (c->have_seq && c->f[i].seq > c->last_seq + 1 + (uint32_t)skipped)
        base->dropped += (long)(c->f[i].seq - c->last_seq - 1) - skipped;
    c->have_seq = 1;
    c->last_seq = c->f[i].seq;
    *out = (hfs_capture_frame){.data = c->buf, .bytes = c->frame_bytes, .width = c->width,
                               .height = c->height, .format = c->format,
                               .stride = c->width * hfs_pixfmt_bytes(c->format),
                               .t_ns = due(c, i), .sequence = c->f[i].seq};
    if (base->tap)
        base->tap(base->tap_user, out);
    base->frames++;
    return 1;
}

static int r_fd(hfs_capture *base)
{
    (void)base;
    return -1;
}

static int64_t r_deadline(hfs_capture *base)
{
    replay_cap *c = (replay_cap *)base;
    if (c->next < c->n)
        return due(c, c->next);
    return c->loop ? next_pass(c) : INT64_MAX;
}

static int r_reopen(hfs_capture *base, hfs_error *err)
{
    (void)base, (void)err;
    return HFS_OK;
}

static void r_close(hfs_capture *base)
{
    (void)base;
}

static void r_destroy(hfs_capture *base)
{
    replay_cap *c = (replay_cap *)base;
    if (!c)
        return;
    free(c->f);
    free(c->buf);
    free(c);
}

static const hfs_capture_vt replay_vt = {r_fd, r_deadline, r_next, r_reopen, r_close, r_destroy};

int hfs_capture_replay_open(const char *dir, int64_t start_ns, int loop, hfs_capture **out,
                            hfs_error *err)
{
    *out = NULL;
    if (strlen(dir) > 200)
        return hfs_fail(err, HFS_E_INVALID, "replay %s: path too long", dir);
    replay_cap *c = calloc(1, sizeof *c);
    if (!c)
        return hfs_fail(err, HFS_E_NOMEM, "replay %s: out of memory", dir);
    c->base.vt = &replay_vt;
    snprintf(c->base.name, sizeof c->base.name, "replay %s", dir);
    snprintf(c->dir, sizeof c->dir, "%s", dir);
    c->base_ns = start_ns;
    c->loop = loop;
    int rc = load_index(c, err);
    if (!rc) {
        c->frame_bytes = (size_t)c->width * (size_t)c->height * (size_t)hfs_pixfmt_bytes(c->format);
        if (!(c->buf = malloc(c->frame_bytes)))
            rc = hfs_fail(err, HFS_E_NOMEM, "replay %s: out of memory", dir);
    }
    if (rc) {
        r_destroy(&c->base);
        return rc;
    }
    *out = &c->base;
    return HFS_OK;
}

void hfs_capture_replay_pace_shown(hfs_capture *base)
{
    ((replay_cap *)base)->pace_shown = 1;
}

int hfs_capture_replay_count(const hfs_capture *base)
{
    return ((const replay_cap *)base)->n;
}

void hfs_capture_replay_format(const hfs_capture *base, hfs_pixfmt *format, int *width,
                               int *height)
{
    const replay_cap *c = (const replay_cap *)base;
    *format = c->format;
    *width = c->width;
    *height = c->height;
}
