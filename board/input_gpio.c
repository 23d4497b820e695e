/*
 * input_gpio.c — the GPIO input source: edges in, detents and presses out.
 *
 * Holds, per chip, the controls wired to it and one decoder each; reads
 * edges through hfs_gpio_ops (libgpiod or a test fake) and feeds them in
 * timestamp order.  Invariants:
 *   - h == NULL exactly when the chip is closed (after a loss); fd is -1
 *     and deadline INT64_MAX then, so the owner only calls reopen;
 *   - edges read but not yet decoded (the caller's event array was full)
 *     wait in `pending`, and the deadline is "now" until they are used, so
 *     nothing is lost when the fd is no longer readable;
 *   - decoders are restarted from the lines' levels at every (re)open.
 */
#include "input_gpio.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "debounce.h"
#include "quadrature.h"

#define GPIO_MAX_LINES (2 * HFS_MAX_CONTROLS)
#define GPIO_EDGE_BATCH 64

typedef struct gpio_control {
    char name[HFS_CONTROL_NAME_MAX];
    hfs_control_kind kind;
    int line[2];            /* indices into offsets[]; [1] knobs only      */
    int active_low;
    int steps_per_detent;
    int64_t settle_ns;
    hfs_quadrature q;
    hfs_debounce d;
} gpio_control;

typedef struct gpio_source {
    hfs_input_source base;
    const hfs_gpio_ops *ops;
    void *h;                                /* NULL = closed              */
    char chip[256];
    int n_lines;
    unsigned offsets[GPIO_MAX_LINES];
    int line_control[GPIO_MAX_LINES];       /* control index per line     */
    int line_role[GPIO_MAX_LINES];          /* 0 = A / button, 1 = B      */
    int n_controls;
    gpio_control ctl[HFS_MAX_CONTROLS];
    hfs_gpio_edge pending[GPIO_EDGE_BATCH]; /* read, not yet decoded      */
    int pending_pos, pending_n;
    int behind;             /* the last read stopped with work left       */
} gpio_source;

static int find_line(const gpio_source *s, unsigned offset)
{
    for (int i = 0; i < s->n_lines; ++i)
        if (s->offsets[i] == offset)
            return i;
    return -1;
}

/* "17,18" for messages. */
static void format_lines(const gpio_source *s, char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < s->n_lines && used + 12 < n; ++i)
        used += (size_t)snprintf(buf + used, n - used, "%s%u", i ? "," : "", s->offsets[i]);
}

static void close_chip(gpio_source *s)
{
    if (s->h)
        s->ops->close(s->h);
    s->h = NULL;
    s->pending_pos = s->pending_n = 0;
    s->behind = 0;
}

/* Opens the chip, requests the lines, starts the decoders.  On failure the
 * source stays closed and err says why, naming the chip. */
static int open_chip(gpio_source *s, hfs_error *err)
{
    errno = 0;
    void *h = s->ops->open_chip(s->ops->ctx, s->chip);
    if (!h) {
        int e = errno;
        switch (e) {
        case ENOSYS:
            return hfs_fail(err, HFS_E_UNSUPPORTED,
                            "gpio %s: not built (libgpiod was not found at build time)", s->chip);
        case ENOENT:
            return hfs_fail(err, HFS_E_IO, "gpio %s: no such chip", s->chip);
        case EACCES: case EPERM:
            return hfs_fail(err, HFS_E_IO, "gpio %s: permission denied", s->chip);
        case ENOTTY: case ENODEV:
            return hfs_fail(err, HFS_E_IO, "gpio %s: not a GPIO chip", s->chip);
        default:
            return hfs_fail(err, HFS_E_IO, "gpio %s: cannot open (%s)", s->chip,
                            strerror(e ? e : EIO));
        }
    }
    char lines[200];
    format_lines(s, lines, sizeof lines);
    int r = s->ops->request(h, s->offsets, s->n_lines, "hfshade");
    if (r < 0) {
        s->ops->close(h);
        switch (-r) {
        case EBUSY:
            return hfs_fail(err, HFS_E_IO, "gpio %s: lines %s busy (requested by another program)",
                            s->chip, lines);
        case EINVAL:
            return hfs_fail(err, HFS_E_IO, "gpio %s: lines %s: no such line on this chip",
                            s->chip, lines);
        case EACCES: case EPERM:
            return hfs_fail(err, HFS_E_IO, "gpio %s: lines %s: permission denied", s->chip, lines);
        default:
            return hfs_fail(err, HFS_E_IO, "gpio %s: cannot request lines %s (%s)", s->chip,
                            lines, strerror(-r));
        }
    }
    int level[GPIO_MAX_LINES];
    r = s->ops->get_values(h, level);
    if (r < 0) {
        s->ops->close(h);
        return hfs_fail(err, HFS_E_IO, "gpio %s: cannot read lines %s (%s)", s->chip, lines,
                        strerror(-r));
    }
    for (int c = 0; c < s->n_controls; ++c) {
        gpio_control *k = &s->ctl[c];
        if (k->kind == HFS_CONTROL_KNOB)
            hfs_quadrature_init(&k->q, k->steps_per_detent, level[k->line[0]] != 0,
                                level[k->line[1]] != 0);
        else
            hfs_debounce_init(&k->d, k->settle_ns, (level[k->line[0]] != 0) != k->active_low);
    }
    s->h = h;
    s->pending_pos = s->pending_n = 0;
    s->behind = 0;
    return HFS_OK;
}

static int gpio_fd(hfs_input_source *src)
{
    gpio_source *s = (gpio_source *)src;
    return s->h ? s->ops->fd(s->h) : -1;
}

static int64_t gpio_deadline(hfs_input_source *src)
{
    gpio_source *s = (gpio_source *)src;
    if (!s->h)
        return INT64_MAX;
    if (s->behind)
        return INT64_MIN;   /* due at once: work is waiting in user space */
    int64_t t = INT64_MAX;
    for (int c = 0; c < s->n_controls; ++c)
        if (s->ctl[c].kind == HFS_CONTROL_BUTTON) {
            int64_t d = hfs_debounce_deadline(&s->ctl[c].d);
            if (d < t)
                t = d;
        }
    return t;
}

static void emit(hfs_input_event *ev, const gpio_control *k, hfs_input_kind kind, int delta,
                 int64_t t_ns)
{
    memset(ev, 0, sizeof *ev);
    ev->t_ns = t_ns;
    ev->kind = kind;
    ev->delta = delta;
    memcpy(ev->control, k->name, sizeof ev->control);
}

static int gpio_read(hfs_input_source *src, int64_t now_ns, hfs_input_event *out, int max,
                     hfs_error *err)
{
    gpio_source *s = (gpio_source *)src;
    if (!s->h)
        return hfs_fail(err, HFS_E_IO, "gpio %s: closed after a loss (reopen first)", s->chip);
    int n = 0;
    s->behind = 0;
    /* Decode edges until the kernel has none left or out is full (a knob
     * edge may complete a detent, so each edge needs a free slot). */
    while (n < max) {
        if (s->pending_pos == s->pending_n) {
            int r = s->ops->read_edges(s->h, s->pending, GPIO_EDGE_BATCH);
            if (r < 0) {
                close_chip(s);
                if (r == -ENODEV)
                    return hfs_fail(err, HFS_E_IO, "gpio %s: device removed (%s)", s->chip,
                                    strerror(-r));
                return hfs_fail(err, HFS_E_IO, "gpio %s: read failed (%s)", s->chip,
                                strerror(-r));
            }
            s->pending_pos = 0;
            s->pending_n = r;
            if (r == 0)
                break;
        }
        const hfs_gpio_edge *e = &s->pending[s->pending_pos++];
        int li = find_line(s, e->offset);
        if (li < 0)
            continue;   /* not ours: the ops reported a line we never asked for */
        gpio_control *k = &s->ctl[s->line_control[li]];
        if (k->kind == HFS_CONTROL_KNOB) {
            int d = hfs_quadrature_edge(&k->q, s->line_role[li], e->level != 0, e->t_ns);
            if (d != 0)
                emit(&out[n++], k, HFS_INPUT_TURN, d, e->t_ns);
        } else {
            hfs_debounce_edge(&k->d, (e->level != 0) != k->active_low, e->t_ns);
        }
    }
    if (s->pending_pos < s->pending_n)
        s->behind = 1;
    /* Presses and releases confirmed by now (or by later edges already
     * fed: the debouncer queues those). */
    for (int c = 0; c < s->n_controls; ++c) {
        gpio_control *k = &s->ctl[c];
        if (k->kind != HFS_CONTROL_BUTTON)
            continue;
        for (;;) {
            if (n == max) {
                if (hfs_debounce_deadline(&k->d) <= now_ns || k->d.n_queued > 0)
                    s->behind = 1;
                break;
            }
            int64_t t;
            int kind = hfs_debounce_poll(&k->d, now_ns, &t);
            if (!kind)
                break;
            emit(&out[n++], k, (hfs_input_kind)kind, 0, t);
        }
    }
    return n;
}

static int gpio_reopen(hfs_input_source *src, hfs_error *err)
{
    gpio_source *s = (gpio_source *)src;
    close_chip(s);
    return open_chip(s, err);
}

static void gpio_destroy(hfs_input_source *src)
{
    gpio_source *s = (gpio_source *)src;
    close_chip(s);
    free(s);
}

static const hfs_input_source_ops gpio_source_ops = {
    .kind = "gpio",
    .fd = gpio_fd,
    .deadline_ns = gpio_deadline,
    .read = gpio_read,
    .reopen = gpio_reopen,
    .destroy = gpio_destroy,
};

static int add_line(gpio_source *s, const hfs_control_config *c, int offset, int control,
                    int role, hfs_error *err)
{
    if (offset < 0)
        return hfs_fail(err, HFS_E_INVALID, "gpio %s: control '%s': line %d is negative",
                        s->chip, c->name, offset);
    int li = find_line(s, (unsigned)offset);
    if (li >= 0)
        return hfs_fail(err, HFS_E_INVALID, "gpio %s: line %d is used by both '%s' and '%s'",
                        s->chip, offset, s->ctl[s->line_control[li]].name, c->name);
    li = s->n_lines++;
    s->offsets[li] = (unsigned)offset;
    s->line_control[li] = control;
    s->line_role[li] = role;
    return li;
}

int hfs_gpio_source_create(const hfs_input_config *cfg, const char *chip,
                           const hfs_gpio_ops *ops, hfs_input_source **out, hfs_error *err)
{
    *out = NULL;
    if (!cfg || !chip || !chip[0])
        return hfs_fail(err, HFS_E_INVALID, "gpio: no chip named");
    if (strlen(chip) >= sizeof(((gpio_source *)0)->chip))
        return hfs_fail(err, HFS_E_INVALID, "gpio: chip name too long");
    gpio_source *s = calloc(1, sizeof *s);
    if (!s)
        return hfs_fail(err, HFS_E_NOMEM, "gpio %s: out of memory", chip);
    s->base.ops = &gpio_source_ops;
    s->ops = ops ? ops : hfs_gpio_ops_libgpiod();
    strcpy(s->chip, chip);
    /* Truncated for display only; messages use s->chip in full. */
    if (snprintf(s->base.name, sizeof s->base.name, "gpio %s", chip) >= (int)sizeof s->base.name)
        s->base.name[sizeof s->base.name - 1] = '\0';

    int r = HFS_OK;
    int n_cfg = cfg->n_controls < HFS_MAX_CONTROLS ? cfg->n_controls : HFS_MAX_CONTROLS;
    for (int i = 0; i < n_cfg && r >= 0; ++i) {
        const hfs_control_config *c = &cfg->control[i];
        if (c->device != HFS_DEVICE_GPIO || strcmp(c->path, chip) != 0)
            continue;
        int ci = s->n_controls++;
        gpio_control *k = &s->ctl[ci];
        memcpy(k->name, c->name, sizeof k->name);
        k->name[sizeof k->name - 1] = '\0';
        k->kind = c->kind;
        k->active_low = c->active_low != 0;
        k->steps_per_detent = c->steps_per_detent > 0 ? c->steps_per_detent : 4;
        k->settle_ns = (int64_t)(c->debounce_ms > 0 ? c->debounce_ms : 10) * 1000000;
        r = add_line(s, c, c->lines[0], ci, 0, err);
        if (r >= 0)
            k->line[0] = r;
        if (r >= 0 && c->kind == HFS_CONTROL_KNOB) {
            r = add_line(s, c, c->lines[1], ci, 1, err);
            if (r >= 0)
                k->line[1] = r;
        }
    }
    if (r >= 0 && s->n_controls == 0)
        r = hfs_fail(err, HFS_E_INVALID, "gpio %s: no control is wired to this chip", chip);
    if (r >= 0)
        r = open_chip(s, err);
    if (r < 0) {
        free(s);
        return r;
    }
    *out = &s->base;
    return HFS_OK;
}
