/* version.c — hfs_version(), hfs_version_number(): the library's version at
 * run time (hfshade_version.h is generated from the CMake project version). */
#include "hfshade.h"

const char *hfs_version(void)
{
    return HFS_VERSION_STRING;
}

int hfs_version_number(void)
{
    return HFS_VERSION_NUMBER;
}
