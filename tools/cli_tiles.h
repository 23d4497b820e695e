/*
 * cli_tiles.h — `hfshade tiles plan | run | merge` (issue 40): a DEM's
 * windows as jobs for GNU parallel or Slurm, and their mosaic
 * (tools/gis/gis_tiles.h; docs/GIS.md "Many machines").  A build without
 * GDAL says so in one line and exits 1.
 */
#ifndef HFS_CLI_TILES_H
#define HFS_CLI_TILES_H

/* argv[0] = "tiles".  The process exit status: 0, 1 (an error: one line on
 * stderr) or 2 (a bad command line). */
int hfs_cli_tiles(int argc, char **argv);

#endif /* HFS_CLI_TILES_H */
