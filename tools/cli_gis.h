/*
 * cli_gis.h — `hfshade svf | horizon | openness | sun | insolation DEM -o
 * OUT [options]`: the GIS rasters terrain analysts use (issue 39; SPEC.md
 * "Terrain rasters"; docs/GIS.md), on the DEM's own grid, through GDAL
 * (tools/gis/).  This
 * file parses the command line and prints the usage; a build without GDAL
 * says so in one line and exits 1.
 */
#ifndef HFS_CLI_GIS_H
#define HFS_CLI_GIS_H

/* 1 if name is one of the GIS commands. */
int hfs_cli_is_gis(const char *name);

/* 1 if option flag of GIS command `command` takes a file (its value a
 * path, as --sky-map's): `hfshade tiles plan` makes those absolute. */
int hfs_cli_gis_file_option(const char *command, const char *flag);

/* argv[0] = the command ("svf", "horizon", "openness", "sun", "insolation").  Returns the
 * process exit status: 0, 1 (an error: one line on stderr naming the input
 * and the problem, nothing written) or 2 (a bad command line: one line). */
int hfs_cli_gis(int argc, char **argv);

/* The parsing alone, into a (azimuth: HFS_MAX_HORIZON_AZIMUTHS doubles,
 * a->azimuth's storage): 0, -1 (--help printed) or a usage error's exit
 * status (its line printed).  `hfshade tiles plan` parses the product's
 * options with it. */
struct gis_args;
int hfs_cli_gis_args(int argc, char **argv, struct gis_args *a, double *azimuth);

#endif /* HFS_CLI_GIS_H */
