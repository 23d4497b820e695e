/*
 * hfshade — the command-line front end (SPEC.md "Command-line contract").
 *
 *   hfshade render  [SCENE.ini] [flags] -o OUT.png [--pfm OUT.pfm]
 *   hfshade compare [SCENE.ini] [flags] RESULT.pfm REFERENCE.pfm   (cli_compare.h)
 *   hfshade query   [SCENE.ini] [flags] --points FILE   (cli_query.h)
 *   hfshade keys                      (lists every scene key / flag)
 *   hfshade info [--context NAME]     (makes a GL context and describes it)
 *   hfshade envmap decompose MAP [...] (lights + residual as scene lines;
 *                                     cli_envmap.h)
 *   hfshade svf | horizon | openness | sun | insolation DEM -o OUT [...]
 *                                     (GIS rasters on the DEM's own grid,
 *                                     through GDAL; cli_gis.h)
 *   hfshade tiles plan | run | merge  (a DEM's windows as jobs; cli_tiles.h;
 *                                     the render's jobs: cli_render_job.h)
 *
 * Every scene key is also a flag (--KEY VALUE); flags override the file.
 * Errors: one line on stderr naming the input and the problem, exit 1 (2 for
 * usage errors); no output file is left behind on failure.
 */
#include "gl_context.h"
#include "hfs_io.h"
#include "hfshade.h"
#include "scene.h"
#include "scene_load.h"
#include "cli_compare.h"
#include "cli_query.h"
#include "cli_usage.h"
#include "cli_frames.h"
#include "cli_help.h"
#include "cli_picture.h"
#include "cli_render_job.h"
#include "cli_view.h"
#ifdef HFS_HAVE_GDAL
#include "geotiff_write.h"
#include "gis_lit.h"
#include "gis_tiles.h"
#include "height_gdal.h"
#endif
#include "cli_envmap.h"
#include "cli_gis.h"
#include "cli_tiles.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>


typedef struct cli {
    const char *command;
    const char *scene_file;
    const char *out_png;
    const char *out_pfm;
    const char *out_tif;     /* --geotiff: the lit radiance, georeferenced */
    const char *points;   /* query: --points FILE */
    const char *positional[2];
    int n_positional;
    int exposure_set; /* --exposure EV given: 2^EV, else metered (auto) */
    double exposure_ev;
    int time_frames; /* --time N: timed frames after one warm-up, 0 = off */
    int colormap; /* 0 none, 1 terrain */
    int quiet;
    int check;    /* --check: everything a render does but write the outputs */
    int tile, job; /* --tile N --job K: render job K only (cli_render_job.h)   */
    cli_view v;   /* --view, --camera, --exaggeration, --view-size, --background, --haze */
    hfs_scene scene;
} cli;

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Progress on a terminal only: a single rewritten line on stderr. */
static void progress_bar(void *user, double fraction)
{
    int *last = user;
    const int pct = (int)(fraction * 100.0);
    if (pct == *last)
        return;
    *last = pct;
    fprintf(stderr, "\rrendering %3d%%", pct);
    if (pct >= 100)
        fputc('\n', stderr);
    fflush(stderr);
}

/* The flag name of argv[i] ("o" for -o, "pfm" for --pfm), or NULL. */
static const char *flag_name(const char *a)
{
    if (a[0] != '-' || a[1] == '\0')
        return NULL;
    return a[1] == '-' ? a + 2 : a + 1;
}

/* Flags that take no value. */
static int is_switch(const char *name)
{
    return !strcmp(name, "quiet") || !strcmp(name, "help") || !strcmp(name, "h") ||
           !strcmp(name, "check");
}

/* A tool option (-o, --pfm, --exposure, --time, --colormap) given twice is
 * an error, like a repeated scene key: the last one silently winning hides a
 * typo in a long command line.  Scene keys are the scene layer's to judge
 * (hfs_scene_set: key and local are repeatable, the others are not). */
static int check_repeats(int argc, char **argv, hfs_error *err)
{
    for (int i = 2; i < argc; ++i) {
        const char *name = flag_name(argv[i]);
        if (!name)
            continue;
        const int takes_value = !is_switch(name);
        if (hfs_scene_is_key(name)) {
            i += takes_value;
            continue;
        }
        for (int j = 2; j < i; ++j) {
            const char *prev = flag_name(argv[j]);
            if (prev && !strcmp(prev, name))
                return hfs_fail(err, HFS_E_INVALID, "%s: given twice (once is allowed)", argv[i]);
            if (prev && !is_switch(prev))
                ++j; /* skip its value */
        }
        i += takes_value;
    }
    return HFS_OK;
}

/* 1 if --NAME is a flag with a value: the tool's own, the view's, a scene key. */
static int takes_value(const char *name)
{
    static const char *const own[] = {"o",    "pfm",      "geotiff",  "points",       "time",
                                      "colormap", "exposure", "view", "camera", "exaggeration",
                                      "view-size", "background", "haze", "tile", "job"};
    for (size_t k = 0; k < sizeof own / sizeof own[0]; ++k)
        if (!strcmp(name, own[k]))
            return 1;
    return hfs_scene_is_key(name);
}

/* Two passes over argv: the scene file first, then flags, so flags always
 * override the file whatever their position. */
static int parse_args(cli *c, int argc, char **argv, hfs_error *err)
{
    int rc = check_repeats(argc, argv, err);
    if (rc)
        return rc;
    for (int i = 2; i < argc; ++i) {
        const char *a = argv[i];
        if (a[0] == '-' && a[1] != '\0') {
            const char *name = a[1] == '-' ? a + 2 : a + 1;
            if (is_switch(name))
                continue;
            ++i; /* every other flag takes a value */
            continue;
        }
        const size_t len = strlen(a);
        if (!c->scene_file && c->n_positional == 0 && len > 4 && !strcmp(a + len - 4, ".ini")) {
            c->scene_file = a;
        } else {
            if (c->n_positional >= 2)
                return hfs_fail(err, HFS_E_INVALID, "%s: unexpected argument", a);
            c->positional[c->n_positional++] = a;
        }
    }
    if (c->scene_file && (rc = hfs_scene_load_file(&c->scene, c->scene_file, err)))
        return rc;
    for (int i = 2; i < argc; ++i) {
        const char *a = argv[i];
        if (!(a[0] == '-' && a[1] != '\0'))
            continue;
        const char *name = a[1] == '-' ? a + 2 : a + 1;
        if (!strcmp(name, "quiet")) {
            c->quiet = 1;
            continue;
        }
        if (!strcmp(name, "check")) {
            c->check = 1;
            continue;
        }
        if (!strcmp(name, "help") || !strcmp(name, "h")) {
            hfshade_usage(stdout);
            exit(0);
        }
        if (i + 1 >= argc)
            return hfs_fail(err, HFS_E_INVALID, takes_value(name) ? "%s: missing value"
                                                : "%s: unknown flag (see 'hfshade keys')", a);
        const char *v = argv[++i];
        if (cli_view_flag(&c->v, name, v, &rc, err)) {
            if (rc)
                return rc;
        } else if (!strcmp(name, "o")) {
            c->out_png = v;
        } else if (!strcmp(name, "pfm")) {
            c->out_pfm = v;
        } else if (!strcmp(name, "geotiff")) {
            c->out_tif = v;
        } else if (!strcmp(name, "points")) {
            c->points = v;
        } else if (!strcmp(name, "time")) {
            char *end;
            long n = strtol(v, &end, 10);
            if (end == v || *end || n < 1 || n > 10000)
                return hfs_fail(err, HFS_E_INVALID, "--time: '%s' is not a frame count in [1, 10000]", v);
            c->time_frames = (int)n;
        } else if (!strcmp(name, "tile") || !strcmp(name, "job")) {
            char *end;
            const long n = strtol(v, &end, 10);
            const int tile = !strcmp(name, "tile");
            if (end == v || *end || n < (tile ? 16 : 1) || n > (tile ? 1L << 20 : 1L << 30))
                return hfs_fail(err, HFS_E_INVALID, "--%s: '%s' is not %s", name, v,
                                tile ? "a tile side in [16, 1048576] texels"
                                     : "a job number (1, 2, ...)");
            *(tile ? &c->tile : &c->job) = (int)n;
        } else if (!strcmp(name, "colormap")) {
            if (!strcmp(v, "terrain"))
                c->colormap = 1;
            else if (!strcmp(v, "none"))
                c->colormap = 0;
            else
                return hfs_fail(err, HFS_E_INVALID, "--colormap: '%s' is not none or terrain", v);
        } else if (!strcmp(name, "exposure")) {
            char *end;
            c->exposure_set = strcmp(v, "auto") != 0;
            c->exposure_ev = c->exposure_set ? strtod(v, &end) : 0.0;
            if (c->exposure_set && (end == v || *end || !(fabs(c->exposure_ev) <= 40.0)))
                return hfs_fail(err, HFS_E_INVALID, "--exposure: '%s' is not auto or stops "
                                "(EV) in [-40, 40]", v);
        } else {
            if (!hfs_scene_is_key(name))
                return hfs_fail(err, HFS_E_INVALID, "%s: unknown flag (see 'hfshade keys')", a);
            char where[80];
            snprintf(where, sizeof where, "--%s", name);
            if ((rc = hfs_scene_set(&c->scene, HFS_SOURCE_FLAG, name, v, where, NULL, err)))
                return rc;
        }
    }
    return HFS_OK;
}

/* Everything a render needs (scene_load.h), plus the tool's one message
 * about filled holes. */
typedef hfs_scene_inputs scene_inputs;

static void scene_inputs_free(scene_inputs *in)
{
    hfs_scene_inputs_free(in);
}

static int load_inputs(const cli *c, scene_inputs *in, hfs_error *err)
{
    int rc = hfs_scene_inputs_load(&c->scene, in, err);
    if (rc)
        return rc;
    if (in->hm.note[0] && !c->quiet)
        fprintf(stderr, "%s\n", in->hm.note);
    if (in->hm.holes > 0 && !c->quiet)
        fprintf(stderr, "%s: filled %ld hole%s (nodata)\n", c->scene.height, in->hm.holes,
                in->hm.holes == 1 ? "" : "s");
    return HFS_OK;
}

/* The run's output set: every output checked against every input and the
 * other output before anything is read or rendered. */
static int plan_outputs(const cli *c, hfs_outputs **o, hfs_error *err)
{
    int rc = hfs_outputs_create(o, err);
    if (!rc)
        rc = hfs_outputs_input(*o, c->scene_file, err);
    if (!rc)
        rc = hfs_outputs_input(*o, c->scene.height, err);
    if (!rc)
        rc = hfs_outputs_input(*o, c->scene.env_map, err);
    if (!rc)
        rc = hfs_outputs_input(*o, c->scene.albedo_map, err);
    if (!rc && c->out_pfm)
        rc = hfs_outputs_add(*o, c->out_pfm, err);
    if (!rc && c->out_tif)
        rc = hfs_outputs_add(*o, c->out_tif, err);
    if (!rc && c->out_png)
        rc = hfs_outputs_add(*o, c->out_png, err);
    return rc;
}

#ifdef HFS_HAVE_GDAL
/* --tile N --job K: job K's part of the lit grid, as a GeoTIFF of its own
 * extent (cli_render_job.h). */
static int cmd_render_job(const cli *c, hfs_error *err)
{
    if (!c->tile || !c->job || !c->out_tif || c->out_png || c->out_pfm || c->v.view ||
        c->time_frames || c->check)
        return hfs_fail(err, HFS_E_INVALID, "--tile and --job: together, with --geotiff OUT.tif "
                        "only (a render job of `hfshade tiles`; no -o, --pfm, --view, --time, "
                        "--check)");
    const hfs_height_load_opts lo = {.has_nodata = c->scene.has_nodata,
                                     .nodata = (float)c->scene.nodata};
    scene_inputs in = {0};
    hfs_renderer *r = NULL;
    hfs_image part = {0};
    hfs_outputs *outs = NULL;
    int halo = 0, ix = 0, iy = 0;
    int rc = plan_outputs(c, &outs, err);
    if (!rc)
        rc = gis_lit_check_grid(c->scene.height, &lo, err);
    if (!rc)
        rc = load_inputs(c, &in, err);
    if (!rc)
        rc = render_job_halo(&in.field, &in.lighting, c->tile, &halo, err);
    const hfs_renderer_desc desc = {.backend = c->scene.backend,
                                    .context = c->scene.context[0] ? c->scene.context : NULL};
    if (!rc)
        rc = hfs_renderer_create(&desc, &r, err);
    const double t0 = now_seconds();
    if (!rc)
        rc = render_job_frame(r, &in.field, &in.lighting, &in.quality, c->tile, halo, c->job,
                              &part, &ix, &iy, err);
    if (!rc)
        rc = gis_lit_write_part(outs, c->out_tif, c->scene.height, &lo, &part, ix, iy, err);
    if (!rc)
        rc = hfs_outputs_commit(outs, err);
    if (!rc && !c->quiet)
        fprintf(stderr, "%s: job %d of --tile %d (%dx%d at %d,%d, halo %d), backend %s, "
                "%.3f s\n", c->out_tif, c->job, c->tile, part.width, part.height, ix, iy, halo,
                hfs_renderer_backend_name(r), now_seconds() - t0);
    hfs_outputs_destroy(outs);
    hfs_image_free(&part);
    hfs_renderer_destroy(r);
    scene_inputs_free(&in);
    return rc;
}

int hfs_cli_render_plan(int argc, char **argv, int tile, char *const *args, int n_args,
                        const char *dir)
{
    cli c;
    memset(&c, 0, sizeof c);
    hfs_scene_init(&c.scene);
    c.command = argv[1];
    c.quiet = 1;
    hfs_error err = {{0}};
    scene_inputs in = {0};
    int halo = 0, rc = parse_args(&c, argc, argv, &err);
    if (rc) {
        fprintf(stderr, "hfshade: %s\n", err.msg);
        return HFS_EXIT_USAGE;
    }
    const hfs_height_load_opts lo = {.has_nodata = c.scene.has_nodata,
                                     .nodata = (float)c.scene.nodata};
    rc = gis_lit_check_grid(c.scene.height, &lo, &err);
    if (!rc)
        rc = load_inputs(&c, &in, &err);
    if (!rc)
        rc = render_job_halo(&in.field, &in.lighting, tile, &halo, &err);
    if (!rc)
        rc = gis_tiles_plan_grid("render", c.scene.height, in.field.width, in.field.height,
                                 tile, halo, args, n_args, dir, &err);
    scene_inputs_free(&in);
    if (rc)
        fprintf(stderr, "hfshade: %s\n", err.msg);
    return rc ? 1 : 0;
}
#endif

static int cmd_render(const cli *c, hfs_error *err)
{
#ifdef HFS_HAVE_GDAL
    if (c->tile || c->job)
        return cmd_render_job(c, err);
#else
    if (c->tile || c->job)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "--tile, --job: this hfshade was built without "
                        "GDAL (a job writes a GeoTIFF)");
#endif
    int rc = cli_view_check(&c->v, err);
    if (rc)
        return rc;
    if (c->v.view && c->colormap)
        return hfs_fail(err, HFS_E_INVALID, "--colormap: colours the grid, not the 3-D view "
                        "(--view)");
#ifndef HFS_HAVE_GDAL
    if (c->out_tif)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "--geotiff: this hfshade was built without GDAL");
#endif
    if (c->out_tif && c->v.view)
        return hfs_fail(err, HFS_E_INVALID, "--geotiff: a 3-D view has no georeferencing (the "
                        "lit grid has: drop --view)");
    if (!c->out_png && !c->out_pfm && !c->out_tif && !c->check)
        return hfs_fail(err, HFS_E_INVALID, "render: no output (give -o OUT.png and/or --pfm OUT.pfm)");
    if (c->n_positional)
        return hfs_fail(err, HFS_E_INVALID, "%s: unexpected argument", c->positional[0]);

    scene_inputs in = {0};
    hfs_renderer *r = NULL;
    hfs_image img = {0}, vimg = {0};
    hfs_view view;
    hfs_outputs *outs = NULL;
    rc = plan_outputs(c, &outs, err);
    if (rc || (rc = load_inputs(c, &in, err)))
        goto out;
    hfs_renderer_desc desc = {.backend = c->scene.backend,
                              .context = c->scene.context[0] ? c->scene.context : NULL};
    if ((rc = hfs_renderer_create(&desc, &r, err)))
        goto out;
    if ((rc = hfs_image_alloc(&img, in.field.width, in.field.height, err)))
        goto out;
    if (c->v.view) {
        cli_view v = c->v; /* --camera's azimuth as the scene reads azimuths */
        v.cam[0] = hfs_scene_spec_azimuth(&c->scene, v.cam[0]);
        view = cli_view_make(&v, &in.field, !strcmp(c->scene.preset, "panel"));
        view.objects = c->scene.objects; /* drawn lit in the view */
        view.n_objects = c->scene.n_objects;
        if ((rc = hfs_image_alloc(&vimg, view.width, view.height, err)))
            goto out;
    }
    const hfs_view *vp = c->v.view ? &view : NULL;
    hfs_image *shown = c->v.view ? &vimg : &img; /* what the outputs hold */
    int last_pct = -1;
    const int show = !c->quiet && isatty(STDERR_FILENO);
    const double t0 = now_seconds();
    if (c->time_frames)
        rc = cli_time_frames(c->time_frames, r, &in, vp, &img, &vimg, err);
    else
        rc = cli_render_once(r, &in, vp, &img, &vimg, show ? progress_bar : NULL, &last_pct, err);
    const double t1 = now_seconds();
    if (rc)
        goto out;
    if (c->check) { /* the outputs were checked against the inputs; none is written */
        if (!c->quiet)
            printf("%s: ok (%dx%d, backend %s, one frame in %.3f s; nothing written)\n",
                   c->scene_file ? c->scene_file : "scene", in.field.width, in.field.height,
                   hfs_renderer_backend_name(r), t1 - t0);
        goto out;
    }
    /* Both files are written to temporaries first and renamed together:
     * a failure leaves neither, and removes nothing that was there. */
    if (c->out_pfm && (rc = hfs_pfm_write_to(outs, c->out_pfm, shown, 0, err)))
        goto out;
#ifdef HFS_HAVE_GDAL
    const hfs_height_load_opts lo = {.has_nodata = c->scene.has_nodata,
                                     .nodata = (float)c->scene.nodata};
    if (c->out_tif &&
        (rc = gis_lit_write(outs, c->out_tif, c->scene.height, &lo, shown, &in.hm, err)))
        goto out;
    /* The grid's PNG and PFM keep a GDAL-read DEM's place: world files. */
    if (!c->v.view && c->out_pfm && (rc = hfs_gdal_write_world_file(outs, c->out_pfm, &in.hm, err)))
        goto out;
    if (!c->v.view && c->out_png && (rc = hfs_gdal_write_world_file(outs, c->out_png, &in.hm, err)))
        goto out;
#endif
    if (c->out_png) {
        if (c->colormap)
            cli_terrain_colormap(&img, &in.hm); /* after the PFM: display only */
        /* Metered on the lit grid, also for a 3-D view (which render_once
         * filled too): terrain only, never the sky or the objects, and the
         * same exposure for the grid and any view of the scene. */
        const hfs_png_opts po = {.exposure = c->exposure_set ? exp2(c->exposure_ev)
                                                             : hfs_exposure_auto(&img),
                                 .tonemap = HFS_TONEMAP_HUE};
        if ((rc = hfs_png_write_to(outs, c->out_png, shown, &po, err)))
            goto out;
    }
    if ((rc = hfs_outputs_commit(outs, err)))
        goto out;
    if (!c->quiet && !c->time_frames) /* the size of the picture written: the view's */
        fprintf(stderr, "%s: %dx%d, backend %s, %.3f s\n",
                c->out_png ? c->out_png : c->out_pfm ? c->out_pfm : c->out_tif, shown->width,
                shown->height, hfs_renderer_backend_name(r), t1 - t0);
out:
    hfs_outputs_destroy(outs);
    hfs_image_free(&img);
    hfs_image_free(&vimg);
    hfs_renderer_destroy(r);
    scene_inputs_free(&in);
    return rc;
}

static int cmd_compare(const cli *c, hfs_error *err)
{
    if (c->n_positional != 2)
        return hfs_fail(err, HFS_E_INVALID, "compare: give RESULT.pfm and REFERENCE.pfm");
    scene_inputs in;
    int rc = load_inputs(c, &in, err);
    if (!rc)
        rc = cli_compare_run(&in.field, &in.lighting, &in.quality, c->positional[0],
                             c->positional[1], err);
    scene_inputs_free(&in);
    return rc;
}

static int cmd_query(const cli *c, hfs_error *err)
{
    if (!c->points)
        return hfs_fail(err, HFS_E_INVALID, "query: give --points FILE (x y z a line)");
    if (c->n_positional)
        return hfs_fail(err, HFS_E_INVALID, "%s: unexpected argument", c->positional[0]);
    scene_inputs in;
    hfs_renderer *r = NULL;
    int rc = load_inputs(c, &in, err);
    if (rc)
        return rc;
    hfs_renderer_desc desc = {.backend = c->scene.backend,
                              .context = c->scene.context[0] ? c->scene.context : NULL};
    if (!(rc = hfs_renderer_create(&desc, &r, err)))
        rc = cli_query_run(r, &in.field, &in.lighting, &in.quality, c->points, err);
    hfs_renderer_destroy(r);
    scene_inputs_free(&in);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return hfs_usage_error("hfshade", "no command given (render, compare, query, envmap, "
                                          "svf, horizon, openness, sun, insolation, info, "
                                          "keys)");
#ifdef HFS_HAVE_GDAL
    hfs_gdal_register(); /* GeoTIFF, SRTM .hgt, VRT ... as height fields */
#endif
    cli c;
    memset(&c, 0, sizeof c);
    hfs_scene_init(&c.scene);
    c.command = argv[1];
    if (!strcmp(c.command, "--help") || !strcmp(c.command, "-h") || !strcmp(c.command, "help")) {
        hfshade_usage(stdout);
        return 0;
    }
    if (!strcmp(c.command, "keys")) {
        hfshade_print_keys();
        return 0;
    }
    if (!strcmp(c.command, "--version") || !strcmp(c.command, "version")) {
        printf("hfshade %s\n", hfs_version());
        return 0;
    }
    if (!strcmp(c.command, "envmap"))
        return hfs_cli_envmap(argc - 1, argv + 1);
    if (hfs_cli_is_gis(c.command))
        return hfs_cli_gis(argc - 1, argv + 1);
    if (!strcmp(c.command, "tiles"))
        return hfs_cli_tiles(argc - 1, argv + 1);
    if (!strcmp(c.command, "info")) {
        /* Proves --context end to end until the GLES backend uses it. */
        const char *name = NULL;
        for (int i = 2; i < argc; ++i) {
            if (!strcmp(argv[i], "--context") && i + 1 < argc)
                name = argv[++i];
            else
                return hfs_usage_error("hfshade", "info: %s: %s", argv[i],
                                       !strcmp(argv[i], "--context") ? "missing value"
                                                                     : "unexpected argument");
        }
        hfs_error e = {{0}};
        hfs_gl_context *ctx = NULL;
        if (hfs_gl_context_create(name, &ctx, &e)) {
            fprintf(stderr, "hfshade: %s\n", e.msg);
            return 1;
        }
        printf("%s\n", hfs_gl_context_describe(ctx));
        hfs_gl_context_destroy(ctx);
        return 0;
    }
    if (strcmp(c.command, "render") && strcmp(c.command, "compare") && strcmp(c.command, "query")) {
        return hfs_usage_error("hfshade", "unknown command '%s'", c.command);
    }
    return hfs_cli_scene_main(argc, argv);
}

int hfs_cli_scene_main(int argc, char **argv)
{
    cli c;
    memset(&c, 0, sizeof c);
    hfs_scene_init(&c.scene);
    c.command = argv[1];
    hfs_error err = {{0}};
    int rc = parse_args(&c, argc, argv, &err);
    if (rc) {
        fprintf(stderr, "hfshade: %s\n", err.msg);
        return HFS_EXIT_USAGE;
    }
    rc = !strcmp(c.command, "render")    ? cmd_render(&c, &err)
         : !strcmp(c.command, "compare") ? cmd_compare(&c, &err)
                                         : cmd_query(&c, &err);
    if (rc) {
        fprintf(stderr, "hfshade: %s\n", err.msg);
        return 1;
    }
    return 0;
}
