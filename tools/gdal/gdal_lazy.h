/*
 * gdal_lazy.h — GDAL, loaded when the tools first use it.
 *
 * libgdal brings about 110 other libraries with it (PROJ, HDF5, poppler,
 * database clients, codecs): linked, it made every start of hfshade cost
 * 88 ms instead of about 10, and every start of the kiosk (a reload's
 * admission check is one) a quarter more, whatever the scene read.  So
 * the tools do not link libgdal.  gdal_lazy.c defines each GDAL function
 * they call (gdal_functions.def) as a forwarder: the first call of any
 * loads the library by the soname the build found (dlopen), registers
 * GDAL's drivers (GDALAllRegister) and calls the library's function; the
 * next calls go straight through.  A PFM, PNG or EXR scene never loads
 * GDAL.  HFS_GDAL_LIBRARY, when set, names the library to load instead
 * (a path or a soname: another GDAL build; the tests' missing library).
 *
 * The doors of the GDAL code (the height loader, the GIS commands' DEM,
 * the GeoTIFF writers) call hfs_gdal_need first, so a machine without the
 * library gets a one-line error naming it; a forwarder reached when the
 * library cannot be loaded prints that line and exits with status 1.
 */
#ifndef HFS_GDAL_LAZY_H
#define HFS_GDAL_LAZY_H

#include "hfshade.h"

/* Loads libgdal and registers its drivers, once per process (thread-safe),
 * for a door of the GDAL code: HFS_OK, or HFS_E_IO naming path
 * ("PATH: GDAL (libgdal.so.N) cannot be loaded: ...") in err. */
int hfs_gdal_need(const char *path, hfs_error *err);

#endif
