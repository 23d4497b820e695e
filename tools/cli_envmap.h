/*
 * cli_envmap.h — `hfshade envmap decompose MAP [--max-lights N]
 * [--min-share F] [--contrast C] [--picture OUT.png]`: an environment map's
 * lights and residual as scene lines (runtime/envmap/env_decompose.h), and a
 * picture of the map with the lights circled.
 */
#ifndef HFS_CLI_ENVMAP_H
#define HFS_CLI_ENVMAP_H

/* argv[0] = "envmap".  Returns the process exit status (0, 1 error, 2
 * usage); errors are one line on stderr. */
int hfs_cli_envmap(int argc, char **argv);

#endif /* HFS_CLI_ENVMAP_H */
