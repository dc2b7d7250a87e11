#ifndef MFT_QUAD_H
#define MFT_QUAD_H
#ifdef __cplusplus
extern "C" {
#endif
#define MFT_MAXN 2048
int mft_nodes(double lo, double hi, double cmin, double c, int core_panels, double *x, double *w, int max);
double mft_integrate2(double (*f)(double, double, void *), void *ctx,
                      double xlo, double xhi, double ylo, double yhi, double cmin, double c, int core_panels);
double mft_scale(const mf_ndf *d);
/* integral D(m) (m.n) dm */
double mft_norm_integral(const mf_ndf *d);
/* what = 0: integral D(m) max(0, v.m) dm = v.z (1 + Lambda); what = 1: integral D_v(m) dm */
double mft_visible_integral(const mf_ndf *d, mf_vec3 v, int what);
/* both at once: returns the first, *dvis the second (mf_D_visible checked on the way) */
double mft_visible_integrals(const mf_ndf *d, mf_vec3 v, double *dvis);
/* Cells over the hemisphere: (X, Y) = A^-1 slope, radius mapped by
 * a = (2/pi) atan(|(X, Y)|) into na rings, azimuth into np sectors. */
typedef struct { int na, np; double A[4]; } mft_cells;   /* slope = A (X, Y), row-major */
void mft_slope_map(const mf_ndf *d, double A[4]);         /* normalized coordinates of d */
/* cells scaled by the median normalized slope radius of a sample set */
void mft_cells_init(mft_cells *c, const mf_ndf *d, double median, int na, int np);
int mft_cell_of(const mft_cells *c, mf_vec3 m);   /* -1 below the horizon */
/* probability of each cell under dens (per solid angle), sub x sub sub-cells of 6 x 6 nodes */
void mft_cell_probs(const mft_cells *c, double (*dens)(mf_vec3, void *), void *ctx, int sub, double *prob);
double mft_median(double *v, int n);   /* sorts v */
double mft_norm_radius(const mf_ndf *d, mf_vec3 m);   /* |A^-1 slope(m)|, 1e30 below the horizon */
#ifdef __cplusplus
}
#endif
#endif
