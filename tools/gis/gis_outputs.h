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
 *   - gis_outputs_destroy removes every temporary not committed.
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

int gis_outputs_commit(gis_outputs *g, hfs_error *err);

void gis_outputs_destroy(gis_outputs *g);

#endif /* HFS_GIS_OUTPUTS_H */
