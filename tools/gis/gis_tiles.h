/*
 * gis_tiles.h — `hfshade tiles plan | run | merge` (issue 40; docs/GIS.md
 * "Many machines"): a DEM's streamed windows (gis_stream.h) as jobs that
 * existing engines run (GNU parallel on local cores or over ssh, a Slurm
 * job array), and the mosaic of their rasters.  No scheduler here: a plan
 * is two files, a job is one process, the merge one more.
 *
 *   DIR/manifest   INI (libinih reads it back): [plan] format, dem (the
 *                  absolute path), product, tile, halo, columns, rows,
 *                  jobs, width, height, and `arg` once per word of the
 *                  product's options; [outputs] `suffix` once per file a
 *                  job writes (".tif"; horizon: "_045.tif", ... as
 *                  r.horizon names them).  Written once by plan.
 *   DIR/jobs       one line a job: "K IX IY IW IH HALO tiles/K": its number
 *                  (from 1, row by row), the part of the DEM it computes
 *                  (columns IX.. IX+IW-1, rows IY.. IY+IH-1), the halo it
 *                  reads around it (texels), its files' prefix in DIR.
 *   DIR/tiles/     K + suffix: job K's GeoTIFFs, each its own part of the
 *                  DEM's grid (`hfshade PRODUCT ... --tile N --job K`).
 *
 * A job's files are renamed into place only when all are written
 * (gis_outputs.h), so a killed job leaves no file that looks finished;
 * `run` of a job whose files are all there does nothing (idempotent:
 * GNU parallel's --resume-failed, a Slurm requeue).  The same plan gives
 * the same tiles on any machine (each window's search reads only its own
 * heights), and merge the same mosaic, byte for byte.
 */
#ifndef HFS_GIS_TILES_H
#define HFS_GIS_TILES_H

#include "gis_command.h"
#include "hfshade.h"

#define GIS_TILES_FORMAT 1
#define GIS_TILES_MAX_ARGS 64

#include <limits.h>
#include <stddef.h>

/* A plan, as its manifest says. */
typedef struct gis_tiles_plan_t {
    int format;
    char dir[PATH_MAX];       /* the plan's directory (the manifest's)       */
    char dem[PATH_MAX];       /* absolute                                    */
    char product[16];         /* svf | horizon | openness | sun | insolation |
                                 render                                      */
    int tile, halo, columns, rows, jobs, width, height;
    int n_args;               /* the product's option words, replayed        */
    char *args[GIS_TILES_MAX_ARGS];
    int n_suffix;             /* the files a job writes: K + suffix          */
    char *suffix[HFS_MAX_HORIZON_AZIMUTHS];
} gis_tiles_plan_t;

/* Reads manifest (libinih) into *m (freed with gis_tiles_plan_free).  0,
 * or an error naming the manifest (and the line of a bad key). */
int gis_tiles_read(const char *manifest, gis_tiles_plan_t *m, hfs_error *err);
void gis_tiles_plan_free(gis_tiles_plan_t *m);

/* Job `job`'s file of suffix s into buf[n]: DIR/tiles/JOB + suffix (s < 0:
 * the prefix DIR/tiles/JOB, the job's -o).  0, or -1 when it does not fit. */
int gis_tiles_path(const gis_tiles_plan_t *m, int job, int s, char *buf, size_t n);

/* 1 when every file of job `job` is there (renamed into place: finished). */
int gis_tiles_job_done(const gis_tiles_plan_t *m, int job);

/* plan: the product's parsed arguments `a` (with a->tile the tile's side,
 * a->dem the DEM, a->out unused), its option words args[0..n_args-1] as
 * the user gave them (replayed by run), into directory dir (created; an
 * existing manifest there is refused).  run (tools/cli_tiles.c): job K's
 * command, `hfshade PRODUCT DEM ARGS --tile N --job K -o DIR/tiles/K...`,
 * nothing when gis_tiles_job_done.  Refused too when the DEM would not
 * stream (no radius, non-square cells, one window): the one line says why.
 * 0, or an error. */
int gis_tiles_plan(const gis_args *a, char *const *args, int n_args, const char *dir,
                   hfs_error *err);

/* plan for a product whose windows its own command lays out (the lit
 * render: tools/cli_render_job.h): the DEM (made absolute), its width x
 * height grid cut into tiles of `tile` texels, each read with `halo`
 * texels around it, one file a job (".tif"); args and dir as above. */
int gis_tiles_plan_grid(const char *product, const char *dem, int width, int height, int tile,
                        int halo, char *const *args, int n_args, const char *dir,
                        hfs_error *err);

/* merge (gis_tiles_merge.c): the mosaic of every job's files: a VRT of the
 * tiles in the plan's directory (mosaic + suffix, ".vrt" for ".tif") and
 * a GeoTIFF made from it (tiled and compressed as the commands write
 * theirs; a COG with cog): out for svf and openness, out + suffix for
 * each horizon azimuth (out a PREFIX), all renamed into place together.
 * Refused when a job's file is missing, naming the first missing jobs.
 * 0, or an error. */
int gis_tiles_merge(const gis_tiles_plan_t *m, const char *out, int cog, hfs_error *err);

#endif /* HFS_GIS_TILES_H */
