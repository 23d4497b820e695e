/*
 * gis_outputs.h — the files of one GIS command, committed together: the
 * library's output sets (hfs_io.h hfs_outputs) hold 8 files each, and
 * `hfshade horizon --step 1` writes 360.  A group holds as many sets as it
 * needs, each told the input DEM, and keeps the sets' promises across
 * them:
 *   - an output that is the same file as the input, or as another output
 *     of the group (paths with their links and directory resolved), is an
 *     error before anything is computed;
 *   - every file is written to a temporary first; gis_outputs_commit
 *     renames them set by set, and when a set fails, the files the group
 *     created in the sets before it are removed again (a file that was
 *     there before stays replaced, as in one set);
 *   - gis_outputs_destroy removes every temporary not committed;
 *   - a file written by name (gis_outputs_temporary) keeps the same
 *     promises: a temporary of the group's, renamed at the commit.
 */
#ifndef HFS_GIS_OUTPUTS_H
#define HFS_GIS_OUTPUTS_H

#include "hfs_io.h"

typedef struct gis_outputs gis_outputs;

/* A group for up to n outputs of a run that reads `input`. */
int gis_outputs_create(gis_outputs **out, const char *input, int n, hfs_error *err);

/* Registers path (kept, not copied: it must outlive the group). */
int gis_outputs_add(gis_outputs *g, const char *path, hfs_error *err);

/* The set that path was added to, for the writers (hfs_bytes_write_to);
 * NULL when it was not added. */
hfs_outputs *gis_outputs_set(gis_outputs *g, const char *path);

/* A temporary for an output that a writer makes itself by name (GDAL's
 * GTiff driver, window by window: gis_raster_stream.h), since an output
 * set takes only complete bytes: "TARGET.tmp-XXXXXX" next to TARGET (path
 * with its links and folder resolved), named as the library's output sets
 * name theirs (runtime/io/io_output.c) and created empty with O_EXCL, so
 * the name is this run's own.  *tmp is its name (the group's, valid until
 * gis_outputs_destroy).  gis_outputs_commit syncs it and renames it over
 * TARGET after the sets' files (undone with them on failure);
 * gis_outputs_destroy removes it when it was not renamed.  An existing
 * path that is not a regular file (a device, a FIFO) is refused: renaming
 * over it would replace it (the sets write those in place). */
int gis_outputs_temporary(gis_outputs *g, const char *path, const char **tmp, hfs_error *err);

int gis_outputs_commit(gis_outputs *g, hfs_error *err);

void gis_outputs_destroy(gis_outputs *g);

#endif /* HFS_GIS_OUTPUTS_H */
