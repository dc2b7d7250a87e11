/* Numerical integration over slope space for the tests: tensor Gauss-Legendre
 * rules on the real line split into a fine core [-R c, R c] and compressed
 * tails (power map for infinite ends, exponential map for finite ones). */
#include "mf_test.h"
#include "quad.h"

#define MFT_R 10.0

/* core [a, b]: x = cmin sinh(s), uniform panels in s, so the scale cmin is
 * resolved near 0 and the scale cmax further out */
static int push_core(double a, double b, double cmin, int panels, double *x, double *w, int n, int max)
{
    double gx[8], gw[8], sa = asinh(a / cmin), sb = asinh(b / cmin);
    int p, i;
    mft_gl(8, gx, gw);
    for (p = 0; p < panels; ++p) {
        double pa = sa + (sb - sa) * p / panels, pb = sa + (sb - sa) * (p + 1) / panels;
        for (i = 0; i < 8 && n < max; ++i) {
            double s = pa + (pb - pa) * gx[i];
            x[n] = cmin * sinh(s);
            w[n] = cmin * cosh(s) * (pb - pa) * gw[i];
            ++n;
        }
    }
    return n;
}

/* tail beyond edge e > 0 outward to bound b (b = HUGE_VAL for infinity), sign s */
static int push_tail(double e, double b, double s, int panels, double *x, double *w, int n, int max)
{
    double gx[8], gw[8];
    int p, i;
    const double m = 30.0;
    mft_gl(8, gx, gw);
    if (b <= e) return n;
    for (p = 0; p < panels; ++p) {
        for (i = 0; i < 8 && n < max; ++i) {
            double a = (p + gx[i]) / panels, xx, jac;
            if (b == HUGE_VAL) { xx = e * pow(1.0 - a, -m); jac = e * m * pow(1.0 - a, -m - 1.0); }
            else { double L = log(b / e); xx = e * exp(a * L); jac = xx * L; }
            x[n] = s * xx;
            w[n] = jac * gw[i] / panels;
            ++n;
        }
    }
    return n;
}

int mft_nodes(double lo, double hi, double cmin, double c, int core_panels, double *x, double *w, int max)
{
    double e = MFT_R * c;
    int n = 0;
    if (lo < -e) n = push_tail(e, -lo, -1.0, 48, x, w, n, max);
    {
        double a = lo > -e ? lo : -e, b = hi < e ? hi : e;
        if (b > a) n = push_core(a, b, cmin, core_panels, x, w, n, max);
    }
    if (hi > e) n = push_tail(e, hi, 1.0, 48, x, w, n, max);
    return n;
}

double mft_integrate2(double (*f)(double, double, void *), void *ctx,
                      double xlo, double xhi, double ylo, double yhi, double cmin, double c, int core_panels)
{
    static double x[MFT_MAXN], wx[MFT_MAXN], y[MFT_MAXN], wy[MFT_MAXN];
    int nx = mft_nodes(xlo, xhi, cmin, c, core_panels, x, wx, MFT_MAXN);
    int ny = mft_nodes(ylo, yhi, cmin, c, core_panels, y, wy, MFT_MAXN);
    double sum = 0.0;
    int i, j;
    for (i = 0; i < nx; ++i) {
        double row = 0.0;
        for (j = 0; j < ny; ++j) row += wy[j] * f(x[i], y[j], ctx);
        sum += wx[i] * row;
    }
    return sum;
}

/* ---- integrals of a distribution ---- */

static mf_vec3 m_of_slope(double x, double y)
{
    double n = sqrt(1.0 + x * x + y * y);
    return mf_vec3_make((mf_real)(-x / n), (mf_real)(-y / n), (mf_real)(1.0 / n));
}

/* Integrals run in normalized slopes (X, Y) = (x/ax, y/ay), where every
 * distribution here is isotropic at unit scale; the visible-normal integrals
 * rotate (X, Y) so that X lies along (ax v.x, ay v.y), which turns the
 * visibility kink v.m = 0 into the straight bound X = v.z / |(ax v.x, ay v.y)|. */
typedef struct { const mf_ndf *d; double cp, sp, vz, s; mf_vec3 v; int what; } vis_ctx;

static double f_norm(double X, double Y, void *p)
{
    const mf_ndf *d = (const mf_ndf *)p;
    double x = d->ax * X, y = d->ay * Y;
    double c2 = 1.0 / (1.0 + x * x + y * y);
    return (double)mf_D(d, m_of_slope(x, y)) * c2 * c2 * d->ax * d->ay;   /* D cos^4 = P22 */
}

double mft_scale(const mf_ndf *d) { return d->ax > d->ay ? d->ax : d->ay; }

double mft_norm_integral(const mf_ndf *d)
{
    return mft_integrate2(f_norm, (void *)d, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, 1.0, 1.0, 48);
}

static double f_vis(double Xt, double Yt, void *p)
{
    vis_ctx *c = (vis_ctx *)p;
    double x = c->d->ax * (c->cp * Xt - c->sp * Yt), y = c->d->ay * (c->sp * Xt + c->cp * Yt);
    double c2 = 1.0 / (1.0 + x * x + y * y), jac = c->d->ax * c->d->ay;
    mf_vec3 m = m_of_slope(x, y);
    double proj = c->vz - Xt * c->s;             /* (v.m) / cos(theta_m) */
    if (proj <= 0.0) return 0.0;
    if (c->what == 0) return (double)mf_D(c->d, m) * c2 * c2 * proj * jac;
    /* D_visible per solid angle; dm = cos^3 dslope */
    return (double)mf_D_visible(c->d, c->v, m) * c2 * sqrt(c2) * jac;
}

double mft_visible_integral(const mf_ndf *d, mf_vec3 v, int what)
{
    vis_ctx c;
    double nx = d->ax * v.x, ny = d->ay * v.y, s = sqrt(nx * nx + ny * ny);
    c.d = d; c.v = v; c.vz = v.z; c.s = s; c.what = what;
    if (s > 0.0) { c.cp = nx / s; c.sp = ny / s; } else { c.cp = 1.0; c.sp = 0.0; }
    return mft_integrate2(f_vis, &c, -HUGE_VAL, s > 0.0 ? c.vz / s : HUGE_VAL, -HUGE_VAL, HUGE_VAL, 1.0, 1.0, 48);
}
