/*
 * gis_tiles.c — see gis_tiles.h.  The plan's windows are gis_stream.h's
 * (the same halo, the same aligned reads), so a job is `--job K` of the
 * streamed command and the mosaic holds the streamed run's values.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "gis_tiles.h"

#include "gis_run.h"

#include <gdal.h>
#include <gdal_utils.h>
#include <ini.h>

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *const product_names[] = {"svf", "horizon", "openness", "sun", "insolation",
                                            "render"};
#define N_NAMES (sizeof product_names / sizeof product_names[0])

/* ---- the manifest -------------------------------------------------------- */

static int min_i(int a, int b)
{
    return a < b ? a : b;
}

/* Job k's (from 0) inner part, as gis_stream.c's window_of cuts it. */
static void job_part(const gis_tiles_plan_t *m, int k, int *ix, int *iy, int *iw, int *ih)
{
    *ix = (k % m->columns) * m->tile, *iy = (k / m->columns) * m->tile;
    *iw = min_i(m->tile, m->width - *ix), *ih = min_i(m->tile, m->height - *iy);
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    gis_tiles_plan_t *m = user;
    char *end;
    if (!strcmp(section, "outputs") && !strcmp(name, "suffix")) {
        if (m->n_suffix >= HFS_MAX_HORIZON_AZIMUTHS)
            return 0;
        return (m->suffix[m->n_suffix++] = strdup(value)) != NULL;
    }
    if (strcmp(section, "plan"))
        return 0;
    if (!strcmp(name, "dem"))
        return snprintf(m->dem, sizeof m->dem, "%s", value) < (int)sizeof m->dem;
    if (!strcmp(name, "product"))
        return snprintf(m->product, sizeof m->product, "%s", value) < (int)sizeof m->product;
    if (!strcmp(name, "arg")) {
        if (m->n_args >= GIS_TILES_MAX_ARGS)
            return 0;
        return (m->args[m->n_args++] = strdup(value)) != NULL;
    }
    int *field = !strcmp(name, "format")    ? &m->format
                 : !strcmp(name, "tile")    ? &m->tile
                 : !strcmp(name, "halo")    ? &m->halo
                 : !strcmp(name, "columns") ? &m->columns
                 : !strcmp(name, "rows")    ? &m->rows
                 : !strcmp(name, "jobs")    ? &m->jobs
                 : !strcmp(name, "width")   ? &m->width
                 : !strcmp(name, "height")  ? &m->height
                                            : NULL;
    if (!field)
        return 0;
    errno = 0;
    const long v = strtol(value, &end, 10);
    if (end == value || *end || errno || v < 0 || v > INT_MAX)
        return 0;
    *field = (int)v;
    return 1;
}

void gis_tiles_plan_free(gis_tiles_plan_t *m)
{
    for (int k = 0; k < m->n_args; ++k)
        free(m->args[k]);
    for (int k = 0; k < m->n_suffix; ++k)
        free(m->suffix[k]);
    *m = (gis_tiles_plan_t){0};
}

int gis_tiles_read(const char *manifest, gis_tiles_plan_t *m, hfs_error *err)
{
    *m = (gis_tiles_plan_t){0};
    const int line = ini_parse(manifest, on_key, m);
    int known = 0;
    for (size_t p = 0; p < N_NAMES; ++p)
        known |= !strcmp(m->product, product_names[p]);
    const int ok = line == 0 && known && m->format == GIS_TILES_FORMAT && m->dem[0] &&
                   m->tile > 0 && m->columns > 0 && m->rows > 0 &&
                   m->jobs == m->columns * m->rows && m->width > 0 && m->height > 0 &&
                   m->n_suffix > 0;
    if (ok) {
        const char *slash = strrchr(manifest, '/');
        const int n = slash ? (int)(slash - manifest) : 1;
        snprintf(m->dir, sizeof m->dir, "%.*s", n, slash ? manifest : ".");
        return HFS_OK;
    }
    gis_tiles_plan_free(m);
    if (line < 0)
        return hfs_fail(err, HFS_E_IO, "%s: cannot read the manifest (%s)", manifest,
                        strerror(errno));
    if (line > 0)
        return hfs_fail(err, HFS_E_FORMAT, "%s: line %d: not a key of a tiles manifest (or a "
                        "value out of range)", manifest, line);
    return hfs_fail(err, HFS_E_FORMAT, "%s: not a complete manifest of `hfshade tiles plan` "
                    "(format %d)", manifest, GIS_TILES_FORMAT);
}

int gis_tiles_path(const gis_tiles_plan_t *m, int job, int s, char *buf, size_t n)
{
    const int w = s < 0 ? snprintf(buf, n, "%s/tiles/%d", m->dir, job)
                        : snprintf(buf, n, "%s/tiles/%d%s", m->dir, job, m->suffix[s]);
    return w > 0 && (size_t)w < n ? 0 : -1;
}

int gis_tiles_job_done(const gis_tiles_plan_t *m, int job)
{
    char p[PATH_MAX + 64];
    for (int s = 0; s < m->n_suffix; ++s)
        if (gis_tiles_path(m, job, s, p, sizeof p) || access(p, F_OK))
            return 0;
    return 1;
}

/* ---- plan ---------------------------------------------------------------- */

/* The plan's grid: product, the DEM (made absolute), its size, the tile
 * and the halo; no files yet. */
static int grid_of(gis_tiles_plan_t *m, const char *product, const char *dem, int width,
                   int height, int tile, int halo, hfs_error *err)
{
    m->format = GIS_TILES_FORMAT;
    m->tile = tile, m->halo = halo, m->width = width, m->height = height;
    m->columns = (width + tile - 1) / tile;
    m->rows = (height + tile - 1) / tile;
    m->jobs = m->columns * m->rows;
    snprintf(m->product, sizeof m->product, "%s", product);
    if (!realpath(dem, m->dem))
        return hfs_fail(err, HFS_E_IO, "%s: %s", dem, strerror(errno));
    return HFS_OK;
}

/* The plan of run r (opened, not loaded: gis_run_open's windows, the
 * streamed command's): its windows, or why it has none. */
static int plan_of(const gis_run *r, gis_tiles_plan_t *m, hfs_error *err)
{
    const gis_args *a = r->a;
    if (r->mode != GIS_STREAMED)
        return hfs_fail(err, HFS_E_INVALID, "%s: no tiles to plan: %s", a->dem,
                        r->mode == GIS_WHOLE ? "the DEM fits one --tile"
                                             : gis_stream_why(r->mode));
    int rc = grid_of(m, product_names[a->product], a->dem, r->dem.width, r->dem.height, a->tile,
                     r->halo, err);
    const int n = a->product == GIS_HORIZON ? a->n_azimuths : 1;
    for (int k = 0; k < n && !rc; ++k) {
        char s[64] = ".tif";
        if (a->product == GIS_HORIZON && gis_horizon_name(s, sizeof s, "", a->azimuth[k],
                                                          a->decimals))
            return hfs_fail(err, HFS_E_INVALID, "horizon: azimuth %g's name", a->azimuth[k]);
        if (!(m->suffix[m->n_suffix++] = strdup(s)))
            return hfs_fail(err, HFS_E_NOMEM, "tiles plan: out of memory");
    }
    return rc;
}

/* m as the manifest's text into f. */
static void write_manifest(FILE *f, const gis_tiles_plan_t *m, char *const *args, int n_args)
{
    fprintf(f, "; hfshade tiles plan: a DEM's windows as jobs (docs/GIS.md \"Many "
            "machines\").\n; Run each line of ./jobs with `hfshade tiles run %s/manifest "
            "LINE`,\n; then `hfshade tiles merge %s -o OUT.tif`.  Do not edit.\n[plan]\n",
            m->dir, m->dir);
    fprintf(f, "format = %d\ndem = %s\nproduct = %s\ntile = %d\nhalo = %d\ncolumns = %d\n"
            "rows = %d\njobs = %d\nwidth = %d\nheight = %d\n", m->format, m->dem, m->product,
            m->tile, m->halo, m->columns, m->rows, m->jobs, m->width, m->height);
    for (int k = 0; k < n_args; ++k)
        fprintf(f, "arg = %s\n", args[k]);
    fprintf(f, "[outputs]\n");
    for (int k = 0; k < m->n_suffix; ++k)
        fprintf(f, "suffix = %s\n", m->suffix[k]);
}

/* path written whole from m (manifest: 1; jobs: 0), through a temporary
 * renamed into place. */
static int write_file(const char *path, const gis_tiles_plan_t *m, int manifest,
                      char *const *args, int n_args, hfs_error *err)
{
    char tmp[PATH_MAX + 16];
    snprintf(tmp, sizeof tmp, "%s.part", path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return hfs_fail(err, HFS_E_IO, "%s: %s", tmp, strerror(errno));
    if (manifest) {
        write_manifest(f, m, args, n_args);
    } else {
        for (int k = 0; k < m->jobs; ++k) {
            int ix, iy, iw, ih;
            job_part(m, k, &ix, &iy, &iw, &ih);
            fprintf(f, "%d %d %d %d %d %d tiles/%d\n", k + 1, ix, iy, iw, ih, m->halo, k + 1);
        }
    }
    const int bad = ferror(f) | fclose(f);
    if (bad || rename(tmp, path)) {
        remove(tmp);
        return hfs_fail(err, HFS_E_IO, "%s: cannot write it", path);
    }
    return HFS_OK;
}

/* A plan's directory: nothing there yet, at most GIS_TILES_MAX_ARGS
 * words to replay. */
static int check_dir(const char *dir, int n_args, hfs_error *err)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/manifest", dir);
    if (n_args > GIS_TILES_MAX_ARGS)
        return hfs_fail(err, HFS_E_INVALID, "tiles plan: more than %d option words",
                        GIS_TILES_MAX_ARGS);
    if (!access(path, F_OK))
        return hfs_fail(err, HFS_E_INVALID, "%s: a plan is there already (plan into a new "
                        "directory)", path);
    return HFS_OK;
}

/* m (its grid and files made, or rc an error) written into dir: the
 * directories, the jobs, the manifest last; m freed. */
static int write_plan(gis_tiles_plan_t *m, int rc, char *const *args, int n_args,
                      const char *dir, hfs_error *err)
{
    char path[PATH_MAX + 64], tiles[PATH_MAX + 64];
    snprintf(m->dir, sizeof m->dir, "%s", dir);
    snprintf(path, sizeof path, "%s/manifest", dir);
    snprintf(tiles, sizeof tiles, "%s/tiles", dir);
    if (!rc && ((mkdir(dir, 0777) && errno != EEXIST) || (mkdir(tiles, 0777) && errno != EEXIST)))
        rc = hfs_fail(err, HFS_E_IO, "%s: %s", dir, strerror(errno));
    if (!rc) {
        snprintf(tiles, sizeof tiles, "%s/jobs", dir);
        rc = write_file(tiles, m, 0, args, n_args, err);
    }
    if (!rc) /* the manifest last: a plan with a manifest is whole */
        rc = write_file(path, m, 1, args, n_args, err);
    gis_tiles_plan_free(m);
    return rc;
}

int gis_tiles_plan(const gis_args *a, char *const *args, int n_args, const char *dir,
                   hfs_error *err)
{
    int rc = check_dir(dir, n_args + 2, err);
    if (rc)
        return rc;
    gis_tiles_plan_t m = {0};
    gis_run *r = calloc(1, sizeof *r);
    if (!r)
        return hfs_fail(err, HFS_E_NOMEM, "tiles plan: out of memory");
    r->a = a;
    rc = gis_run_open(r, 0, err);
    if (!rc)
        rc = plan_of(r, &m, err);
    /* sun, insolation: the relief the plan read, given to every job, so
     * that no job reads the whole DEM again to find it (the same double:
     * %.17g round-trips) */
    char relief[40], *words[GIS_TILES_MAX_ARGS + 2];
    const int scanned = r->c.has_relief && !a->relief_given;
    for (int k = 0; k < n_args && k < GIS_TILES_MAX_ARGS; ++k)
        words[k] = args[k];
    snprintf(relief, sizeof relief, "%.17g", r->relief);
    words[n_args] = "--relief", words[n_args + 1] = relief;
    gis_sky_map_free(&r->sky);
    gis_dem_free(&r->dem);
    free(r);
    return write_plan(&m, rc, words, n_args + (scanned ? 2 : 0), dir, err);
}

int gis_tiles_plan_grid(const char *product, const char *dem, int width, int height, int tile,
                        int halo, char *const *args, int n_args, const char *dir,
                        hfs_error *err)
{
    int rc = check_dir(dir, n_args, err);
    if (rc)
        return rc;
    gis_tiles_plan_t m = {0};
    rc = grid_of(&m, product, dem, width, height, tile, halo, err);
    if (!rc && !(m.suffix[m.n_suffix++] = strdup(".tif")))
        rc = hfs_fail(err, HFS_E_NOMEM, "tiles plan: out of memory");
    return write_plan(&m, rc, args, n_args, dir, err);
}
