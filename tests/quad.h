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
#ifdef __cplusplus
}
#endif
#endif
