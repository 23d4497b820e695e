/*
 * cli_tiles.c — `hfshade tiles plan | run | merge` (cli_tiles.h): the
 * command lines of tools/gis/gis_tiles.h.  A job is the streamed product
 * command itself (`--job K`), run through hfs_cli_gis as if typed.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "cli_tiles.h"

#include "cli_usage.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HFS_HAVE_GDAL
#include "cli_gis.h"
#include "gis_tiles.h"
#include "scene_keys.h"

#include <limits.h>

#define MAX_WORDS (GIS_TILES_MAX_ARGS + 16)

static void usage(FILE *f)
{
    fprintf(f,
            "usage: hfshade tiles plan DEM --product render|svf|horizon|openness|sun|insolation\n"
            "                          --tile N -o DIR\n"
            "                          [the product's options: --radius R, --directions N, ...]\n"
            "       hfshade tiles run DIR/manifest LINE\n"
            "       hfshade tiles merge DIR -o OUT.tif [--cog]\n"
            "A DEM's windows (those `hfshade PRODUCT --tile N` streams) as independent jobs for\n"
            "GNU parallel or a Slurm job array (docs/GIS.md \"Many machines\"):\n"
            "  plan   writes DIR/manifest and DIR/jobs (one line a job: K IX IY IW IH HALO "
            "tiles/K);\n"
            "  run    computes job LINE (its number or its line of DIR/jobs) into DIR/tiles/;\n"
            "         a job whose files are there already is not redone;\n"
            "  merge  writes the mosaic: DIR/mosaic.vrt and OUT.tif (horizon: PREFIX_AAA.tif an\n"
            "         azimuth); refused while a job's files are missing.\n"
            "e.g. parallel --joblog DIR/log hfshade tiles run DIR/manifest {} :::: DIR/jobs\n");
}

/* 1 if flag of product takes a file: a render's scene keys of form PATH
 * (--env-map, --albedo-map, --objects, ...), a GIS command's FILE options
 * (--sky-map). */
static int file_option(const char *product, const char *flag)
{
    if (strcmp(product, "render"))
        return hfs_cli_gis_file_option(product, flag);
    const int id = flag[0] == '-' && flag[1] == '-' ? hfs_scene_key_find(flag + 2) : -1;
    const hfs_scene_key *key = id >= 0 ? hfs_scene_key_get((hfs_scene_key_id)id) : NULL;
    return key && key->form == HFS_FORM_PATH;
}

/* The value of each file option in rest made absolute, as the plan makes
 * the DEM's, so that a job finds it from any folder: into abs (n paths),
 * rest[k] pointed there.  A file realpath cannot resolve is left as given,
 * for the product's own check to name. */
static void absolute_paths(const char *product, char **rest, int n, char (*abs)[PATH_MAX])
{
    for (int k = 1; k < n; ++k)
        if (file_option(product, rest[k - 1]) && realpath(rest[k], abs[k]))
            rest[k] = abs[k];
}

/* tiles plan DEM --product render --tile N -o DIR [scene options]: the
 * render's command line checks them (hfs_cli_render_plan); every job
 * replays all but the DEM. */
static int plan_render(const char *tile, char **rest, int n_rest, const char *dir)
{
    char *end;
    const long n = strtol(tile, &end, 10);
    if (end == tile || *end || n < 16 || n > 1L << 20)
        return hfs_usage_error("hfshade tiles plan", "--tile: '%s' is not a tile side in "
                               "[16, 1048576] texels", tile);
    char *words[MAX_WORDS], *args[MAX_WORDS];
    int m = 0, n_args = 0;
    const char *dem = NULL;
    for (int k = 0; k < n_rest; ++k) {
        if (!dem && rest[k][0] != '-' && (k == 0 || rest[k - 1][0] != '-'))
            dem = rest[k];
        else
            args[n_args++] = rest[k];
    }
    if (!dem)
        return hfs_usage_error("hfshade tiles plan", "no DEM given");
    words[m++] = "hfshade", words[m++] = "render", words[m++] = "--height";
    words[m++] = (char *)dem;
    for (int k = 0; k < n_args; ++k)
        words[m++] = args[k];
    return hfs_cli_render_plan(m, words, (int)n, args, n_args, dir);
}

/* tiles plan DEM --product P --tile N -o DIR [options] */
static int plan(int argc, char **argv)
{
    const char *product = NULL, *dir = NULL, *tile = NULL;
    char *words[MAX_WORDS], *rest[MAX_WORDS];
    int n_rest = 0, n = 0;
    for (int i = 1; i < argc; ++i) {
        const char *s = argv[i];
        const char **slot = !strcmp(s, "--product") ? &product : !strcmp(s, "-o") ? &dir
                            : !strcmp(s, "--tile")  ? &tile    : NULL;
        if (slot && i + 1 < argc) {
            *slot = argv[++i];
        } else if (n_rest + 1 >= MAX_WORDS - 8) {
            return hfs_usage_error("hfshade tiles plan", "more than %d options",
                                   GIS_TILES_MAX_ARGS);
        } else {
            rest[n_rest++] = argv[i];
        }
    }
    if (!product || !dir || !tile)
        return hfs_usage_error("hfshade tiles plan", "%s is required",
                               !product ? "--product" : !dir ? "-o DIR" : "--tile N");
    if (!hfs_cli_is_gis(product) && strcmp(product, "render"))
        return hfs_usage_error("hfshade tiles plan", "--product: '%s' is not render, svf, "
                               "horizon, openness, sun or insolation", product);
    static char abs[MAX_WORDS][PATH_MAX];
    absolute_paths(product, rest, n_rest, abs);
    if (!strcmp(product, "render"))
        return plan_render(tile, rest, n_rest, dir);
    /* the product's own parser checks every option: PRODUCT REST --tile N -o DIR/tiles/0 */
    char out[4096];
    snprintf(out, sizeof out, "%s/tiles/0", dir);
    words[n++] = (char *)product;
    for (int k = 0; k < n_rest; ++k)
        words[n++] = rest[k];
    words[n++] = "--tile", words[n++] = (char *)tile, words[n++] = "-o", words[n++] = out;
    gis_args a;
    double azimuth[HFS_MAX_HORIZON_AZIMUTHS];
    int rc = hfs_cli_gis_args(n, words, &a, azimuth);
    if (rc)
        return rc < 0 ? 0 : rc;
    /* the options replayed by every job: all but the DEM */
    char *args[MAX_WORDS];
    int n_args = 0;
    for (int k = 0; k < n_rest; ++k)
        if (rest[k] != a.dem)
            args[n_args++] = rest[k];
    hfs_error err = {{0}};
    if ((rc = gis_tiles_plan(&a, args, n_args, dir, &err)))
        fprintf(stderr, "hfshade: %s\n", err.msg);
    return rc ? 1 : 0;
}

/* tiles run MANIFEST LINE: job K's command (argv for hfs_cli_gis). */
static int run(int argc, char **argv)
{
    if (argc != 3)
        return hfs_usage_error("hfshade tiles run", "needs DIR/manifest and a job's LINE");
    gis_tiles_plan_t m;
    hfs_error err = {{0}};
    if (gis_tiles_read(argv[1], &m, &err)) {
        fprintf(stderr, "hfshade: %s\n", err.msg);
        return 1;
    }
    char *end;
    const long k = strtol(argv[2], &end, 10);
    int rc = 0;
    if (end == argv[2] || (*end && *end != ' ') || k < 1 || k > m.jobs) {
        fprintf(stderr, "hfshade: %s: job '%s' is not one of 1..%d\n", argv[1], argv[2], m.jobs);
        rc = 1;
    } else if (gis_tiles_job_done(&m, (int)k)) {
        fprintf(stderr, "%s: job %ld done already\n", argv[1], k);
    } else {
        char *words[MAX_WORDS], out[PATH_MAX + 64], tile[16], job[16];
        int n = 0;
        gis_tiles_path(&m, (int)k, strcmp(m.product, "horizon") ? 0 : -1, out, sizeof out);
        snprintf(tile, sizeof tile, "%d", m.tile);
        snprintf(job, sizeof job, "%ld", k);
        const int render = !strcmp(m.product, "render");
        if (render) /* hfshade render --height DEM ... --geotiff OUT */
            words[n++] = "hfshade", words[n++] = "render", words[n++] = "--height";
        else
            words[n++] = m.product;
        words[n++] = m.dem;
        for (int j = 0; j < m.n_args; ++j)
            words[n++] = m.args[j];
        words[n++] = "--tile", words[n++] = tile, words[n++] = "--job", words[n++] = job;
        words[n++] = render ? "--geotiff" : "-o", words[n++] = out;
        rc = render ? hfs_cli_scene_main(n, words) : hfs_cli_gis(n, words);
    }
    gis_tiles_plan_free(&m);
    return rc;
}

/* tiles merge DIR -o OUT [--cog] */
static int merge(int argc, char **argv)
{
    const char *dir = NULL, *out = NULL;
    int cog = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(argv[i], "--cog"))
            cog = 1;
        else if (!dir && argv[i][0] != '-')
            dir = argv[i];
        else
            return hfs_usage_error("hfshade tiles merge", "%s: unexpected argument", argv[i]);
    }
    if (!dir || !out)
        return hfs_usage_error("hfshade tiles merge", "needs DIR and -o OUT.tif");
    char manifest[PATH_MAX + 16];
    snprintf(manifest, sizeof manifest, "%s/manifest", dir);
    gis_tiles_plan_t m;
    hfs_error err = {{0}};
    int rc = gis_tiles_read(manifest, &m, &err);
    if (!rc)
        rc = gis_tiles_merge(&m, out, cog, &err);
    if (rc)
        fprintf(stderr, "hfshade: %s\n", err.msg);
    else
        fprintf(stderr, "%s: %s mosaic of %d jobs (%dx%d)\n", out, m.product, m.jobs, m.width,
                m.height);
    gis_tiles_plan_free(&m);
    return rc ? 1 : 0;
}

int hfs_cli_tiles(int argc, char **argv)
{
    (void)usage;
    if (argc >= 2 && hfs_is_help(argv[1])) {
        usage(stdout);
        return 0;
    }
    const char *what = argc >= 2 ? argv[1] : "";
    if (!strcmp(what, "plan"))
        return plan(argc - 1, argv + 1);
    if (!strcmp(what, "run"))
        return run(argc - 1, argv + 1);
    if (!strcmp(what, "merge"))
        return merge(argc - 1, argv + 1);
    usage(stderr);
    return 2;
}
#else
int hfs_cli_tiles(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "hfshade: tiles: this hfshade was built without GDAL (the tiles are "
            "GeoTIFFs)\n");
    return 1;
}
#endif
