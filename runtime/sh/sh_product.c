/*
 * sh_product.c — order-4 SH product through the sparse triple-product tensor
 * C_ijk = integral y_i y_j y_k.
 *
 * The nonzero entries are computed once, at build time, by exact quadrature
 * (tools/gen_sh_tables.c) and arrive here as sh_product_gen.inc in the build
 * directory: a const entry table and an unrolled product.  Nothing is
 * initialized at run time, so the product is reentrant and allocation-free;
 * the same generator writes the GLSL twin (sh_product.glsl.inc) so both
 * renderers multiply with identical coefficients.
 *
 * Projection of a*b onto the basis is out_k = sum_ij C_ijk a_i b_j; each
 * unordered pair (i, j) is visited once thanks to symmetry in i and j.
 * The result is the exact order-4 truncation of the order-7 product.
 */
#include "sh.h"

#include <stddef.h>

typedef struct {
    unsigned char i, j, k;
    double c;
} hfs_sh_tensor_entry;

#include "sh_product_gen.inc"

void hfs_sh_product(const double a[HFS_SH_N], const double b[HFS_SH_N],
                    double out[HFS_SH_N])
{
    hfs_sh_product_unrolled(a, b, out);
}

int hfs_sh_product_nonzeros(void)
{
    return HFS_SH_PRODUCT_TERMS;
}

int hfs_sh_product_entry(int idx, int *i, int *j, int *k, double *c)
{
    if (idx < 0 || idx >= HFS_SH_PRODUCT_TERMS)
        return -1;
    const hfs_sh_tensor_entry *e = &hfs_sh_tensor[idx];
    if (i)
        *i = e->i;
    if (j)
        *j = e->j;
    if (k)
        *k = e->k;
    if (c)
        *c = e->c;
    return 0;
}
