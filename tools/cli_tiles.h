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

/* The scene commands' side (tools/hfshade.c), for the render's jobs
 * (cli_render_job.h): */
/* `hfshade render|compare|query ...` as main runs it, argv[0] the
 * program, argv[1] the command: the exit status. */
int hfs_cli_scene_main(int argc, char **argv);
/* `tiles plan DEM --product render`: argv a render's command line
 * (`hfshade render --height DEM OPTIONS`), checked and its inputs loaded;
 * the plan of tiles of `tile` texels written into dir, with args the
 * options each job replays.  The exit status (0, 1, 2), the error's one
 * line printed. */
int hfs_cli_render_plan(int argc, char **argv, int tile, char *const *args, int n_args,
                        const char *dir);

#endif /* HFS_CLI_TILES_H */
