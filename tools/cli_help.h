/*
 * cli_help.h — what `hfshade --help` and `hfshade keys` print: the tool's
 * commands and options, and one line a scene key (its form, help, range
 * and default, from the scene layer's table of keys).
 */
#ifndef HFS_CLI_HELP_H
#define HFS_CLI_HELP_H

#include <stdio.h>

/* The commands and the render's own options, into f. */
void hfshade_usage(FILE *f);

/* Every scene key, one line each, on stdout. */
void hfshade_print_keys(void);

#endif /* HFS_CLI_HELP_H */
