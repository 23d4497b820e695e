/*
 * gis_horizon_files.h — the horizon command's GeoTIFFs (one an azimuth,
 * the DEM computed whole), encoded a few at a time on worker threads and
 * written in azimuth order.
 *
 * Why: a file's DEFLATE and floating-point prediction cost about as much
 * as its azimuth's sweep (docs/GIS.md "The sweep"), and on one thread the
 * 16 files of the Jacksboro DEM took a third of the command.  Each queued
 * raster is GDAL-encoded into memory on its own (hfs_parallel_rows: the
 * bytes do not depend on the thread count), then written through the
 * run's output set on the calling thread, in order: the output group's
 * promises (temporaries, all or nothing) are unchanged.  Our own threads,
 * created and joined here, not GDAL's NUM_THREADS pool (which outlives
 * the command: valgrind then reports its stacks).  The queue holds as
 * many rasters as GIS_HORIZON_FILES_FLOATS floats allow (all 16 of a
 * small DEM, one at a time near the whole-DEM limit): each flush's new
 * thread opens PROJ's database again (GDAL's PROJ context is per thread,
 * and writing a CRS reads it), so fewer flushes open it fewer times (the
 * Jacksboro DEM's 16 files: proj.db opened 5 times at 2 rasters a
 * worker, twice now; `strace -f -e trace=openat`).
 */
#ifndef HFS_GIS_HORIZON_FILES_H
#define HFS_GIS_HORIZON_FILES_H

#include "gis_run.h"

#define GIS_HORIZON_FILES_FLOATS (1 << 24) /* 64 MiB of queued angles */

typedef struct gis_horizon_files gis_horizon_files;

/* A queue for run r's horizon files (r->names, the input's grid). */
int gis_horizon_files_create(gis_horizon_files **out, const gis_run *r, hfs_error *err);

/* Azimuth k's angles (degrees, the input's grid) copied into the queue;
 * the queue encoded and written when it is full or k is the last
 * azimuth.  The first failure, in azimuth order, is returned (and every
 * later call returns it too: nothing after it is written). */
int gis_horizon_files_add(gis_horizon_files *q, int k, const float *deg, hfs_error *err);

void gis_horizon_files_destroy(gis_horizon_files *q);

#endif /* HFS_GIS_HORIZON_FILES_H */
