/*
 * gis_utm_grid.h — the grid the sun and insolation tests write their DEMs
 * on (test_gis_sun.c, test_gis_sky_cli.c): 64 x 48 cells of 30 m in UTM
 * zone 33N, centred on (500000, 5200000), the zone's central meridian
 * (longitude 15, latitude about 47).
 */
#ifndef HFS_TEST_GIS_UTM_GRID_H
#define HFS_TEST_GIS_UTM_GRID_H

#define W 64
#define H 48
#define CELL 30.0
#define EPSG_UTM33 32633

static const double utm_gt[6] = {500000.0 - CELL * W / 2, CELL, 0.0, 5200000.0 + CELL * H / 2,
                                 0.0, -CELL};

#endif /* HFS_TEST_GIS_UTM_GRID_H */
