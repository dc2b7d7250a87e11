#ifndef MFT_REF_OTHER_H
#define MFT_REF_OTHER_H
#ifdef __cplusplus
extern "C" {
#endif
double ref_D(int kind, double ax, double ay, double g, const double *wm);
double ref_lambda(int kind, double ax, double ay, double g, const double *w);
double ref_brdf(int kind, double ax, double ay, double g, const double *wo, const double *wi);
double ref_brdf_pdf(int kind, double ax, double ay, double g, const double *wo, const double *wi);
void ref_sample_visible(int kind, double ax, double ay, double g, const double *w, double u1, double u2, double *wm);
void ref_sample_D(int kind, double ax, double ay, double g, double u1, double u2, double *wm);
void ref_ltc_edge_fast(const double *a, const double *b, double *out);
double ref_ltc_shape(int shape, const double *m9, const double *p, double r);
#ifdef __cplusplus
}
#endif
#endif
