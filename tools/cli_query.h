/*
 * cli_query.h — `hfshade query [SCENE.ini] [flags] --points FILE` (issue
 * 19): the key-light visibility of points above the field, for scripts and
 * tests.  FILE holds one point a line, "x y z" in world units (x = i dx,
 * y = j dx, z = zscale h); blank lines and lines starting with '#' are
 * skipped.  Output (stdout): a header line "# x y z key1 ... keyN", then
 * per point its coordinates and the visible fraction of each key light's
 * disk (%.6f).  Errors name FILE:LINE and the problem.
 */
#ifndef HFS_CLI_QUERY_H
#define HFS_CLI_QUERY_H

#include "hfshade.h"

/* Reads the points of path into *xyz (3 n doubles, malloc'd; the caller
 * frees) and *n. */
int cli_query_read_points(const char *path, double **xyz, int *n, hfs_error *err);

/* Queries r for the points of path and prints the table. */
int cli_query_run(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                  const hfs_quality *q, const char *path, hfs_error *err);

#endif /* HFS_CLI_QUERY_H */
