/*
 * visibility.h — azimuth swaths and horizons -> SH visibility (DESIGN.md
 * "Azimuth swaths" and "Visibility to SH"), shared by every backend: the CPU
 * reference evaluates it in double, the GLES path packs the same swaths and
 * folded matrices into its uniform blocks (runtime/gles/uniform_blocks.h).
 *
 * Swath layout.
 *   Full swath (environment, and a key light whose disk covers a pole):
 *     n samples phi_j = phi0 + j*dphi, dphi = 2 pi/n; n wedges [phi_j, phi_j+1]
 *     (the last wraps to sample 0).
 *   Partial swath (key light at (phi_L, e_L), angular radius alpha):
 *     half-width h = asin(sin(alpha)/cos(e_L)); the samples are the run of
 *     a circle lattice, phi_j = phi0 + j*dphi with dphi = 2 pi / N and
 *     phi0 = k0 dphi (hfs_swath_key), whose wedges +- dphi/2 cover
 *     [phi_L - h, phi_L + h]; wedges in order:
 *       0        start boundary [phi_0 - dphi/2, phi_0], width dphi/2,
 *                blocked at its outer end, sample 0 at its inner end;
 *       1..n-1   interior [phi_{w-1}, phi_w];
 *       n        end boundary [phi_{n-1}, phi_{n-1} + dphi/2], sample n-1,
 *                then blocked.
 *   A key light needs the full swath when its disk covers the zenith OR the
 *   nadir, |e_L| + alpha >= pi/2 (exactly when sin(alpha)/cos(e_L) >= 1 and h
 *   would be undefined); it then uses max(nphi_key, nphi_env) samples from
 *   phi0 = 0.  (DESIGN.md names only the zenith case; a light that far below
 *   the horizon contributes nothing to an upward-facing receiver anyway, but
 *   a steep receiver still sees it, so the swath must stay well-defined.)
 *
 * Visibility (both paths z-rotate canonical wedges to their start and sum):
 *   HFS_VIS_LEGENDRE  (NS09) v_j = NLP vector of the visible band
 *       (omega_j, pi/2]; wedge SH = M_lin(extent) [v_a; v_b], a blocked end
 *       using the zero vector.  Since everything after v_j is linear, the
 *       object folds each wedge's rotation and matrix half into one 16x4
 *       matrix per sample: V = sum_j C_j v_j (the same linear map).
 *   HFS_VIS_WEDGE_TABLE (SN08) interior wedge = 2D table(omega_a, omega_b)
 *       of extent dphi, boundary wedge = 1D table(omega) of extent dphi/2
 *       (horizon rising linearly to pi/2 at the swath edge), mirrored
 *       (y -> -y) at the start of the swath.  Tables have
 *       HFS_VIS_TABLE_SIZE entries per horizon axis over [-pi/2, pi/2]; the
 *       size is odd so that horizon 0 (a flat receiver) is a table node.
 * The two paths differ inside boundary wedges by construction: Legendre fades
 * the visible band's NLP vector linearly to zero, the tables raise the
 * horizon linearly to pi/2.
 *
 * hfs_visibility_eval is the fast form the renderer uses;
 * hfs_visibility_eval_reference computes the same sum wedge by wedge with
 * the library's own rotation (the literal definition, for tests and for the
 * GLES author to compare against).
 *
 * Ownership: create/destroy; destroy(NULL) is a no-op.  Immutable after
 * create: any number of threads may evaluate one object at once.
 */
#ifndef HFS_VISIBILITY_H
#define HFS_VISIBILITY_H

#include "hfshade.h"
#include "sh.h"

#define HFS_VIS_TABLE_SIZE 257

/* ---- swath layout ---------------------------------------------------------- */

typedef struct hfs_swath {
    int n;         /* azimuth samples (>= 1)                                  */
    int full;      /* 1: complete circle; 0: partial with boundary wedges      */
    double phi0;   /* azimuth of sample 0                                      */
    double dphi;   /* sample spacing (wedge extent; boundary wedges dphi/2)    */
    /* Elevation window of the light (NS09 section 6): the Legendre path counts
     * only the visible band (max(omega, elev_lo), elev_hi].  [-pi/2, pi/2] for
     * the environment; the light's [e - alpha, e + alpha] for a key light.  The
     * wedge-table path cannot restrict elevation and ignores it (SN08). */
    double elev_lo, elev_hi;
} hfs_swath;

typedef struct hfs_swath_wedge {
    double start;  /* azimuth where the wedge begins                           */
    double extent; /* azimuthal width                                          */
    int a, b;      /* sample index at its start / end; -1 = fully blocked      */
} hfs_swath_wedge;

/* Full swath of n samples starting at phi0 = 0. */
void hfs_swath_full(int n, hfs_swath *s);

/* Swath of a key light (phi, elev, alpha in radians; alpha in [0, pi/2),
 * lifted to HFS_MIN_VIS_ALPHA, lights.h, before anything else): the full
 * swath of max(nphi_key, nphi_env) samples where the disk covers the zenith
 * or the nadir; otherwise a partial swath covering the disk's azimuths
 * phi +- h (h = asin(sin alpha / cos elev)) with samples on a lattice of the
 * circle (spacing 2 pi / N >= 2h / nphi_key, N the largest round count
 * 1..4, 4..7 x 2^k not finer: within 1.25x for nphi_key >= 2, 1.5x for
 * nphi_key = 1; 0.8 nphi_key to nphi_key + 1 samples), which a light moving
 * within the sampled swath keeps.  The window is [e - alpha, e + alpha]
 * clamped to [-pi/2, pi/2]. */
void hfs_swath_key(double phi, double elev, double alpha, int nphi_key,
                   int nphi_env, hfs_swath *s);

/* Azimuth of sample j: phi0 + j*dphi. */
double hfs_swath_phi(const hfs_swath *s, int j);

/* n wedges for a full swath, n + 1 for a partial one (order above). */
int hfs_swath_wedge_count(const hfs_swath *s);
void hfs_swath_get_wedge(const hfs_swath *s, int w, hfs_swath_wedge *out);

/* ---- horizons -> SH visibility ----------------------------------------------- */

typedef struct hfs_visibility hfs_visibility;

/* path: HFS_VIS_WEDGE_TABLE; any other value means HFS_VIS_LEGENDRE.  Building the
 * tables takes a few tens of milliseconds per swath.  Returns HFS_OK,
 * HFS_E_INVALID or HFS_E_NOMEM. */
int hfs_visibility_create(const hfs_swath *s, hfs_visibility_path path,
                          hfs_visibility **out, hfs_error *err);
void hfs_visibility_destroy(hfs_visibility *v);

const hfs_swath *hfs_visibility_swath(const hfs_visibility *v);
hfs_visibility_path hfs_visibility_get_path(const hfs_visibility *v);

/* V = SH visibility of the swath given the horizons omega[0..n-1] at its
 * samples (each in [-pi/2, pi/2]). */
void hfs_visibility_eval(const hfs_visibility *v, const double *omega,
                         double V[HFS_SH_N]);

/* The same, wedge by wedge (slow, literal). */
void hfs_visibility_eval_reference(const hfs_visibility *v, const double *omega,
                                   double V[HFS_SH_N]);

/* Legendre path only: the per-sample matrix C_j (16x4 row-major) of the
 * folded form, for upload (NULL for the table path). */
const double *hfs_visibility_sample_matrix(const hfs_visibility *v, int j);

#endif /* HFS_VISIBILITY_H */
