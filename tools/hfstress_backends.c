/*
 * hfstress_backends.c — the renderers hfstress runs (hfstress.h): one per
 * backend kind, GLES precisions sharing one context per profile, made on
 * first use and probed so that an unusable one is skipped with its reason
 * instead of failing every case.
 */
#include "hfstress.h"
#include "cli_usage.h"
#include "gl_require.h"

#include <stdio.h>
#include <string.h>

typedef struct backend_def {
    const char *name;
    hfs_backend kind;
    const char *profile; /* GLES target profile; NULL: by precision         */
    int fp32;            /* GLES texture precision                          */
    int shares;          /* backend whose renderer this one uses, or -1     */
} backend_def;

static const backend_def defs[BK_COUNT] = {
    [BK_CPU] = {"cpu", HFS_BACKEND_CPU, NULL, 0, -1},
    [BK_GLES16] = {"gles-fp16", HFS_BACKEND_GLES, NULL, 0, -1},
    [BK_GLES32] = {"gles-fp32", HFS_BACKEND_GLES, NULL, 1, BK_GLES16},
    [BK_ES32_16] = {"gles-es32-fp16", HFS_BACKEND_GLES, "es32", 0, -1},
    [BK_ES32_32] = {"gles-es32-fp32", HFS_BACKEND_GLES, "es32", 1, BK_ES32_16},
    [BK_TRUTH] = {"truth", HFS_BACKEND_TRUTH, NULL, 0, -1},
};

const char *stress_backend_name(int b)
{
    return defs[b].name;
}

int stress_backend_is_gles(int b)
{
    return defs[b].kind == HFS_BACKEND_GLES;
}

int stress_backend_fp32(int b)
{
    return defs[b].fp32;
}

int stress_backend_parse(const char *list, int want[BK_COUNT])
{
    memset(want, 0, BK_COUNT * sizeof *want);
    char buf[256];
    snprintf(buf, sizeof buf, "%s", list);
    for (char *save = NULL, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        int found = 0;
        for (int b = 0; b < BK_COUNT; ++b)
            if (!strcmp(t, "all") || !strcmp(t, defs[b].name) ||
                (!strcmp(t, "gles") && defs[b].kind == HFS_BACKEND_GLES))
                want[b] = found = 1;
        if (!found) {
            hfs_usage_error("hfstress", "--backend: unknown backend '%s' (cpu, gles, gles-fp16, "
                            "gles-fp32, gles-es32-fp16, gles-es32-fp32, truth, all)", t);
            return -1;
        }
    }
    for (int b = 0; b < BK_COUNT; ++b)
        if (want[b])
            return 0;
    hfs_usage_error("hfstress", "--backend: '%s' names no backend", list);
    return -1;
}

int stress_render(stress_backends *s, int b, const stress_scene *sc, hfs_image *img,
                  hfs_error *err)
{
    hfs_quality q = sc->q;
    q.precision = defs[b].fp32 ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16;
    if (s->subsample)
        q.subsample = s->subsample;
    if (!img->rgb) {
        const int rc = hfs_image_alloc(img, sc->f.width, sc->f.height, err);
        if (rc)
            return rc;
    }
    return hfs_renderer_render(s->r[b], &sc->f, &sc->l, &q, img, NULL, NULL, err);
}

/* A flat 2x2 field under a uniform sky: what any working renderer draws. */
static int probe(stress_backends *s, int b, hfs_error *err)
{
    static const float z[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    stress_scene p;
    memset(&p, 0, sizeof p);
    p.f = (hfs_field){.width = 2, .height = 2, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting_defaults(&p.l);
    p.l.has_env = 1;
    p.l.env_sh[0][0] = p.l.env_sh[1][0] = p.l.env_sh[2][0] = 1.0;
    hfs_quality_defaults(&p.q);
    hfs_image img = {0};
    const int rc = stress_render(s, b, &p, &img, err);
    hfs_image_free(&img);
    return rc;
}

/* Whether backend b's failure to be created is the machine's, not the
 * product's (runtime/gl/gl_require.h): no GLES context of any kind here, or a
 * driver below ES 3.2 refusing the es32 profile with the capability layer's
 * line.  Anything else counts as a failed check. */
static int excused(int b, int rc, const hfs_error *err)
{
    if (defs[b].kind != HFS_BACKEND_GLES)
        return 0;
    if (defs[b].profile && !strcmp(defs[b].profile, "es32") && rc == HFS_E_UNSUPPORTED &&
        strstr(err->msg, "profile es32: this driver offers"))
        return 1;
    hfs_error why = {""};
    return hfs_gl_missing_device(&why);
}

int stress_backend_ready(stress_backends *s, int b)
{
    if (s->state[b])
        return s->state[b] > 0;
    hfs_error err = {{0}};
    const int sh = defs[b].shares;
    if (sh >= 0 && stress_backend_ready(s, sh)) {
        s->r[b] = s->r[sh]; /* one context serves both precisions */
    } else if (sh >= 0) {
        memcpy(s->why[b], s->why[sh], sizeof s->why[b]);
        s->state[b] = -1;
        return 0;
    } else {
        /* gles-fp16/fp32 stand for the smallest ES 3.0 device (strict
         * limits: 2048 texels, 16 KiB blocks); gles-es32-* for the driver. */
        const hfs_renderer_desc d = {.backend = defs[b].kind, .gl_profile = defs[b].profile,
                                     .gl_strict_limits = defs[b].profile == NULL};
        const int rc = hfs_renderer_create(&d, &s->r[b], &err);
        if (rc) {
            snprintf(s->why[b], sizeof s->why[b], "%s", err.msg);
            s->state[b] = -1;
            s->broken[b] = !excused(b, rc, &err);
            return 0;
        }
    }
    if (defs[b].kind == HFS_BACKEND_GLES && probe(s, b, &err)) {
        snprintf(s->why[b], sizeof s->why[b], "%s", err.msg);
        s->broken[b] = 1; /* a context and a renderer, but not the 2x2 sky */
        if (sh < 0)
            hfs_renderer_destroy(s->r[b]);
        s->r[b] = NULL;
        s->state[b] = -1;
        return 0;
    }
    s->state[b] = 1;
    return 1;
}

void stress_backends_close(stress_backends *s)
{
    for (int b = 0; b < BK_COUNT; ++b)
        if (s->r[b] && defs[b].shares < 0)
            hfs_renderer_destroy(s->r[b]);
    memset(s->r, 0, sizeof s->r);
}
