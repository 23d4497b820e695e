/*
 * gis_sweep_blocks.h — the windowed sweep's first test of a line, from
 * bounds kept per block of the field instead of its texels (gis_sweep.c).
 *
 * A sun above the horizontal (a window whose bottom rises) leaves most of
 * a high sun's lines with nothing to do: their relief and their steepest
 * rise along the azimuth cannot reach the disk, and line_bounds proves it
 * from the bands of texels about each line, 12 reads a column.  Here the
 * same bounds come from the field's blocks of GIS_SWEEP_BLOCK^2 texels
 * (their lowest and highest height and their largest rise towards each of
 * the four neighbours), a few blocks per GIS_SWEEP_BLOCK columns: looser,
 * but never below line_bounds' (each band's texels, and each difference
 * it takes, lie in the blocks read), so a line they clear is one
 * line_bounds would clear, and the values do not change.  No GDAL, no GL.
 */
#ifndef HFS_GIS_SWEEP_BLOCKS_H
#define HFS_GIS_SWEEP_BLOCKS_H

#include "hfshade.h"

/* Texels a side of a block: 8 keeps a line's band (6 rows about it, plus
 * the 8 columns' climb of at most 8 rows) within three blocks across. */
#define GIS_SWEEP_BLOCK 8

/* An azimuth's frame as gis_sweep.c walks it: u along the major axis (x
 * when x_major), v across it, each up the field's axis (u_up, v_up) or
 * down it; nu, nv the field's size along them; r the rows climbed a
 * column (0 <= r <= 1). */
typedef struct gis_sweep_frame {
    int x_major, u_up, v_up, nu, nv;
    double r;
} gis_sweep_frame;

/* What a line's bands can hold, world units: the lowest and highest
 * height, the largest rise to the next column (du) and to the next row
 * (dv), none below 0, and the largest |difference| to the next row. */
typedef struct gis_sweep_extent {
    double zmin, zmax, du, dv, dv_abs;
} gis_sweep_extent;

/* The field's blocks: bw x bh of them, 6 values each (zmin, zmax, the
 * largest rise to +x, -x, +y, -y; rises of at least 0). */
typedef struct gis_sweep_blocks {
    int bw, bh;
    double *v;
} gis_sweep_blocks;

/* The blocks of field f (zscale applied), their rows shared among
 * `threads` workers (0: the machine's cores).  HFS_OK, or HFS_E_NOMEM
 * with b empty. */
int gis_sweep_blocks_make(gis_sweep_blocks *b, const hfs_field *f, int threads);
void gis_sweep_blocks_free(gis_sweep_blocks *b);

/* The largest |height| of the field (zscale applied), from its blocks. */
double gis_sweep_blocks_zabs(const gis_sweep_blocks *b);

/* Line k's extent (v = k + r u) over the whole line, from the blocks its
 * bands touch: at least what line_bounds finds from the texels. */
gis_sweep_extent gis_sweep_blocks_line(const gis_sweep_blocks *b, const gis_sweep_frame *fr,
                                       long k);

#endif /* HFS_GIS_SWEEP_BLOCKS_H */
