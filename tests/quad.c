/* Numerical integration over slope space for the tests: tensor Gauss-Legendre
 * rules on the real line split into a fine core [-R c, R c] and compressed
 * tails (power map for infinite ends, exponential map for finite ones). */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

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
typedef struct { const mf_ndf *d; double A[4], jac, cp, sp, vz, s, area, worst; mf_vec3 v; int what; long k; } vis_ctx;

/* slopes = A (X, Y): A = M^-T diag(ax, ay) (Eq. 4.16: the transformed slope is
 * M^-T times the base slope), row-major */
void mft_slope_map(const mf_ndf *d, double A[4])
{
    double i00 = 1, i01 = 0, i10 = 0, i11 = 1;
    if (d->transformed) {   /* M^-1 in double */
        double m00 = d->M.m00, m01 = d->M.m01, m10 = d->M.m10, m11 = d->M.m11, det = m00 * m11 - m01 * m10;
        i00 = m11 / det; i01 = -m01 / det; i10 = -m10 / det; i11 = m00 / det;
    }
    /* (Minv)^T = [i00 i10; i01 i11] */
    A[0] = i00 * d->ax; A[1] = i10 * d->ay;
    A[2] = i01 * d->ax; A[3] = i11 * d->ay;
}

static double f_norm(double X, double Y, void *p)
{
    const vis_ctx *c = (const vis_ctx *)p;
    double x = c->A[0] * X + c->A[1] * Y, y = c->A[2] * X + c->A[3] * Y;
    double c2 = 1.0 / (1.0 + x * x + y * y);
    return (double)mf_D(c->d, m_of_slope(x, y)) * c2 * c2 * c->jac;   /* D cos^4 = P22 */
}

double mft_scale(const mf_ndf *d) { return d->ax > d->ay ? d->ax : d->ay; }

double mft_norm_integral(const mf_ndf *d)
{
    vis_ctx c;
    c.d = d;
    mft_slope_map(d, c.A);
    c.jac = fabs(c.A[0] * c.A[3] - c.A[1] * c.A[2]);
    return mft_integrate2(f_norm, &c, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, 1.0, 1.0, 48);
}

static double f_vis(double Xt, double Yt, void *p)
{
    vis_ctx *c = (vis_ctx *)p;
    double X = c->cp * Xt - c->sp * Yt, Y = c->sp * Xt + c->cp * Yt;
    double x = c->A[0] * X + c->A[1] * Y, y = c->A[2] * X + c->A[3] * Y;
    double c2 = 1.0 / (1.0 + x * x + y * y), jac = c->jac;
    mf_vec3 m = m_of_slope(x, y);
    double proj = c->vz - Xt * c->s;             /* (v.m) / cos(theta_m) */
    double D;
    if (proj <= 0.0) return 0.0;
    D = (double)mf_D(c->d, m);
    /* D_visible = max(0, v.m) D(m) / A(v) (Heitz 2014, Eq. 2; A = v.z (1 +
     * Lambda) for a centred kind) per solid angle, dm = cos^3 dslope: the
     * integrand of the area, over A (mf_projected_area, once per integral:
     * the numerical Lambdas cost microseconds); mf_D_visible itself is
     * compared with it at every 61st node, its error measured against D / A
     * (the v.m factor's scale) */
    if (c->what == 1 && ++c->k % 61 == 0 && D > 1e-30 * c->area) {   /* float: no subnormal values */
        double want = proj * sqrt(c2) * D / c->area, got = (double)mf_D_visible(c->d, c->v, m);
        double e = fabs(got - want) / (D / c->area + 1e-300);
        if (!(e <= c->worst)) c->worst = e;
    }
    return D * c2 * c2 * proj * jac;
}

double mft_visible_integrals(const mf_ndf *d, mf_vec3 v, double *dvis)
{
    vis_ctx c;
    double nx, ny, s, r;
    mft_slope_map(d, c.A);
    c.jac = fabs(c.A[0] * c.A[3] - c.A[1] * c.A[2]);
    /* slope . v_xy = X . (A^T v_xy): the visibility bound is straight along A^T v_xy */
    nx = c.A[0] * v.x + c.A[2] * v.y; ny = c.A[1] * v.x + c.A[3] * v.y; s = sqrt(nx * nx + ny * ny);
    c.d = d; c.v = v; c.vz = v.z; c.s = s; c.what = dvis != NULL; c.k = 0; c.worst = 0.0;
    c.area = dvis ? (double)mf_projected_area(d, v) : 1.0;
    if (s > 0.0) { c.cp = nx / s; c.sp = ny / s; } else { c.cp = 1.0; c.sp = 0.0; }
    r = mft_integrate2(f_vis, &c, -HUGE_VAL, s > 0.0 ? c.vz / s : HUGE_VAL, -HUGE_VAL, HUGE_VAL, 1.0, 1.0, 48);
    if (dvis) {
        *dvis = r / c.area;
        /* an mf_D_visible that disagrees with D and the area fails the caller's check */
        if (!(c.worst <= MFT_TOL(1e-9, 2e-5))) {
            printf("    mf_D_visible differs from max(0, v.m) D / mf_projected_area by %.3g (scale D / area)\n", c.worst);
            *dvis = HUGE_VAL;
        }
    }
    return r;
}

double mft_visible_integral(const mf_ndf *d, mf_vec3 v, int what)
{
    double dvis, area = mft_visible_integrals(d, v, what == 1 ? &dvis : NULL);
    return what == 1 ? dvis : area;
}

/* ---- cells over the hemisphere for chi-square tests ---- */

void mft_cells_init(mft_cells *c, const mf_ndf *d, double median, int na, int np)
{
    int i;
    mft_slope_map(d, c->A);
    for (i = 0; i < 4; ++i) c->A[i] *= median;
    c->na = na; c->np = np;
}

/* normalized slope radius of m for d */
double mft_norm_radius(const mf_ndf *d, mf_vec3 m)
{
    double A[4], sx, sy, det, X, Y;
    if (!(m.z > 0)) return 1e30;
    mft_slope_map(d, A);
    sx = -m.x / m.z; sy = -m.y / m.z; det = A[0] * A[3] - A[1] * A[2];
    X = (A[3] * sx - A[1] * sy) / det;
    Y = (-A[2] * sx + A[0] * sy) / det;
    return sqrt(X * X + Y * Y);
}

int mft_cell_of(const mft_cells *c, mf_vec3 m)
{
    const double pi = 3.14159265358979323846;
    double X, Y, a, p;
    int ia, ip;
    if (!(m.z > 0)) return -1;
    {
        double sx = -m.x / m.z, sy = -m.y / m.z, det = c->A[0] * c->A[3] - c->A[1] * c->A[2];
        X = (c->A[3] * sx - c->A[1] * sy) / det;
        Y = (-c->A[2] * sx + c->A[0] * sy) / det;
    }
    a = atan(sqrt(X * X + Y * Y)) * 2.0 / pi;
    p = atan2(Y, X); if (p < 0) p += 2.0 * pi;
    ia = (int)(a * c->na); ip = (int)(p / (2.0 * pi) * c->np);
    if (ia >= c->na) ia = c->na - 1;
    if (ip >= c->np) ip = c->np - 1;
    return ia * c->np + ip;
}

void mft_cell_probs(const mft_cells *c, double (*dens)(mf_vec3, void *), void *ctx, int sub, double *prob)
{
    const double pi = 3.14159265358979323846;
    double gx[6], gw[6];
    int ia, ip, i, j, na = c->na, np = c->np;
    mft_gl(6, gx, gw);
    for (ia = 0; ia < na; ++ia)
        for (ip = 0; ip < np; ++ip) {
            double s = 0.0;
            for (i = 0; i < 6 * sub; ++i)
                for (j = 0; j < 6 * sub; ++j) {
                    /* the outer ring reaches the horizon, where D may diverge
                     * (Student-t, gamma < 2): a = 1 - (1 - s)^4 / na there */
                    double sa = (i / 6 + gx[i % 6]) / sub, da = 1.0 / na;
                    double a = ia < na - 1 ? (ia + sa) / na : 1.0 - pow(1.0 - sa, 4.0) / na;
                    double psi = (ip + (j / 6 + gx[j % 6]) / sub) / np * 2.0 * pi;
                    double R = tan(0.5 * pi * a), dR = 0.5 * pi / (cos(0.5 * pi * a) * cos(0.5 * pi * a));
                    double X = R * cos(psi), Y = R * sin(psi);
                    double x = c->A[0] * X + c->A[1] * Y, y = c->A[2] * X + c->A[3] * Y;
                    double cz = 1.0 / sqrt(1.0 + x * x + y * y);
                    mf_vec3 m = mf_vec3_make((mf_real)(-x * cz), (mf_real)(-y * cz), (mf_real)cz);
                    if (ia == na - 1) da = 4.0 * pow(1.0 - sa, 3.0) / na;
                    /* dm = cos^3 dslope, dslope = bx by R dR dpsi */
                    s += gw[i % 6] * gw[j % 6] / (sub * sub) * dens(m, ctx) *
                         cz * cz * cz * fabs(c->A[0] * c->A[3] - c->A[1] * c->A[2]) * R * dR * (2.0 * pi / np) * da;
                }
            prob[ia * np + ip] = s;
        }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

double mft_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof(double), cmp_double);
    return v[n / 2];
}

void mft_special_values(mf_real v[12], mf_vec3 d[10])
{
    volatile double zero = 0.0;
    mf_real inf_ = (mf_real)(1.0 / zero), nan_ = (mf_real)(zero / zero);
    v[0] = 0; v[1] = -v[0]; v[2] = MF_R(1e-30); v[3] = MF_R(1e-7); v[4] = MF_R(0.5); v[5] = 1; v[6] = MF_R(1.5);
    v[7] = MF_R(1e30); v[8] = inf_; v[9] = -1; v[10] = nan_; v[11] = -inf_;
    d[0] = mf_vec3_make(0, 0, 1); d[1] = mft_dir(1.0, 0.5); d[2] = mft_dir(1.5706, 2.0); d[3] = mf_vec3_make(1, 0, 0);
    d[4] = mf_vec3_make(0, 0, -1); d[5] = mf_vec3_make(0, 0, 0); d[6] = mf_vec3_make(3, 4, 5); d[7] = mf_vec3_make(nan_, 0, 1);
    d[8] = mf_vec3_make(inf_, 0, 1); d[9] = mft_dir(1e-7, 0.0);
}

int mft_record_ok(mf_sample r)
{
    if (r.lobe == MF_LOBE_NONE) return r.pdf == 0 && r.weight == 0;
    return r.pdf > 0 && r.pdf < MF_BIG && r.weight >= 0 && r.weight <= MF_BIG && r.wi.z > 0 &&
           mft_finite((double)r.wi.x) && mft_finite((double)r.wi.y);
}
