/*
 * cli_compare.h — `hfshade compare [SCENE.ini] [flags] RESULT.pfm
 * REFERENCE.pfm`: SPEC's error metrics of a render against a reference
 * (fractions of the scene's largest unshadowed value), and how much of the
 * reference's umbra the result renders lit (issue 36).  Output (stdout),
 * one line:
 *   mean_abs M rmse R p99_abs P max_abs X nonfinite N norm V umbra_lit L/U
 * where U counts the texels the reference holds in umbra (below 1% of
 * their unshadowed value, where that is above 1% of the norm) and L those
 * of them the result renders at half their unshadowed value or more (first
 * channel).  Errors name the file and the problem.
 */
#ifndef HFS_CLI_COMPARE_H
#define HFS_CLI_COMPARE_H

#include "hfshade.h"

/* Reads result and reference (PFM, f's size), prints the line above. */
int cli_compare_run(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                    const char *result, const char *reference, hfs_error *err);

#endif /* HFS_CLI_COMPARE_H */
