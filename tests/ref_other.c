/* The library in the other precision (this file is compiled with the opposite
 * of the test binary's mf_real), behind a double interface, for test_float.
 * It holds that precision's implementation: every test binary is a program
 * using both precisions, which links because non-inline symbols carry their
 * precision (mf_..._f32 / mf_..._f64). */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "ref_other.h"

static mf_ndf make(int kind, double ax, double ay, double g)
{
    switch (kind) {
    case MF_NDF_BECKMANN: return mf_beckmann((mf_real)ax, (mf_real)ay);
    case MF_NDF_GGX: return mf_ggx((mf_real)ax, (mf_real)ay);
    case MF_NDF_GTR: return mf_gtr((mf_real)ax, (mf_real)g);
    case MF_NDF_CHARLIE: return mf_charlie((mf_real)ax);
    default: return mf_student_t((mf_real)ax, (mf_real)ay, (mf_real)g);
    }
}
static mf_vec3 v3(const double *v) { return mf_vec3_make((mf_real)v[0], (mf_real)v[1], (mf_real)v[2]); }

double ref_D(int kind, double ax, double ay, double g, const double *wm)
{
    mf_ndf d = make(kind, ax, ay, g);
    return (double)mf_D(&d, v3(wm));
}
double ref_lambda(int kind, double ax, double ay, double g, const double *w)
{
    mf_ndf d = make(kind, ax, ay, g);
    return (double)mf_lambda(&d, v3(w));
}
double ref_brdf(int kind, double ax, double ay, double g, const double *wo, const double *wi)
{
    mf_ndf d = make(kind, ax, ay, g);
    return (double)mf_brdf(&d, v3(wo), v3(wi));
}
double ref_brdf_pdf(int kind, double ax, double ay, double g, const double *wo, const double *wi)
{
    mf_ndf d = make(kind, ax, ay, g);
    return (double)mf_brdf_pdf(&d, v3(wo), v3(wi));
}
void ref_sample_visible(int kind, double ax, double ay, double g, const double *w, double u1, double u2, double *wm)
{
    mf_ndf d = make(kind, ax, ay, g);
    mf_vec3 m = mf_sample_visible(&d, v3(w), (mf_real)u1, (mf_real)u2);
    wm[0] = (double)m.x; wm[1] = (double)m.y; wm[2] = (double)m.z;
}
void ref_sample_D(int kind, double ax, double ay, double g, double u1, double u2, double *wm)
{
    mf_ndf d = make(kind, ax, ay, g);
    mf_vec3 m = mf_sample_D(&d, (mf_real)u1, (mf_real)u2);
    wm[0] = (double)m.x; wm[1] = (double)m.y; wm[2] = (double)m.z;
}

/* the fast LTC edge integral (rational theta / sin theta) in this precision */
void ref_ltc_edge_fast(const double *a, const double *b, double *out)
{
    mf_vec3 e = mf__edge_vector_fast(v3(a), v3(b));
    out[0] = (double)e.x; out[1] = (double)e.y; out[2] = (double)e.z;
}

/* an LTC light shape in this precision: shape 0 ellipse (p0 center, p1 p2
 * axes), 1 exactly clipped ellipse, 2 line (p0 p1, radius r), 3 tube;
 * m9: the row-major matrix M */
double ref_ltc_shape(int shape, const double *m9, const double *p, double r)
{
    mf_real m[9];
    mf_ltc l;
    int i;
    for (i = 0; i < 9; ++i) m[i] = (mf_real)m9[i];
    l = mf_ltc_from_matrix9(m);
    switch (shape) {
    case 0: return (double)mf_ltc_integrate_ellipse(&l, v3(p), v3(p + 3), v3(p + 6), 1);
    case 1: return (double)mf_ltc_integrate_ellipse_clipped(&l, v3(p), v3(p + 3), v3(p + 6), 1);
    case 2: return (double)mf_ltc_integrate_line(&l, v3(p), v3(p + 3), (mf_real)r);
    default: return (double)mf_ltc_integrate_tube(&l, v3(p), v3(p + 3), (mf_real)r);
    }
}
