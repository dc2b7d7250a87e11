/* Tabulated (piecewise-linear) distributions (Ribardiere et al. 2019, Sec. 3).
 * The integrals run in polar coordinates, split exactly where the integrand
 * has kinks: at every control angle, at theta_c = pi/2 - theta_v (where the
 * visibility cut enters) with a substitution theta = theta_c + L s^2 for the
 * (theta - theta_c)^(3/2) onset, and in phi at the visibility boundary. Only
 * mf_D, mf_lambda and mf_D_visible are evaluated, never the closed forms of the
 * builder, so the checks are independent:
 *   normalization (Eq. 12) and the masking constraint (Eq. 13-14,
 *   integral <v.m> D dm = v.z (1 + Lambda)) for views up to 89 degrees, and
 *   integral D_visible = 1: 1e-8 relative in double (Lambda interpolates the
 *   projected-area table by cubic Hermite with exact derivatives; measured worst
 *   1.0e-9), 1e-5 in float (measured 8.3e-7);
 *   Eq. 10: D equals (cos^2 D_x(theta) D_y(0) + sin^2 D_y(theta) D_x(0)) / c with
 *   the curves normalized by our own quadrature, 1e-9 (float 2e-5);
 *   chi-square of both samplers (24 x 24 cells, z < 5) and the BRDF checks of
 *   test_brdf.c (pdf histogram, weight = f cos / pdf, reciprocity, furnace);
 *   a tabulated copy of GGX and of Beckmann (mf_tabulated_from_ndf, 256 points)
 *   matches the analytic D and 1 + Lambda to the tabulation error: measured
 *   and printed, bounded at 2e-3 (D) and 1e-3 (1 + Lambda);
 *   transformed tabulated distributions (slope-space quadrature of quad.c: its
 *   tensor rule crosses the kinks of the curves, so 2e-5 relative);
 *   bad input gives an error and leaves nothing allocated; a released or NULL
 *   table gives 0 everywhere; mf_tabulated_rebase reproduces every value. */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

#define PI 3.14159265358979323846

static double tol_int(void) { return MFT_TOL(1e-8, 1e-5); }

/* integral over the hemisphere of what(m) (0: D cos, 1: <v.m> D, 2: D_visible)
 * for the tabulated distribution t seen from v */
typedef struct { const mf_ndf *d; mf_vec3 v; int what; } pol_ctx;

static double pol_f(const pol_ctx *c, double th, double ph)
{
    mf_vec3 m = mf_vec3_make((mf_real)(sin(th) * cos(ph)), (mf_real)(sin(th) * sin(ph)), (mf_real)cos(th));
    double vm;
    switch (c->what) {
    case 0: return (double)mf_D(c->d, m) * cos(th);
    case 1: vm = (double)mf_dot(c->v, m); return vm > 0 ? vm * (double)mf_D(c->d, m) : 0.0;
    default: return (double)mf_D_visible(c->d, c->v, m);
    }
}

/* integral over phi at polar angle th of f, only over the visible arc when what > 0 */
static double pol_phi(const pol_ctx *c, double th)
{
    static double gx[24], gw[24];
    static int init = 0;
    double so, co, phio, a, b, lo, hi, s = 0.0;
    int i;
    if (!init) { mft_gl(24, gx, gw); init = 1; }
    if (c->what == 0) { lo = 0.0; hi = 2.0 * PI; phio = 0.0; }
    else {
        double sxy = sqrt((double)c->v.x * c->v.x + (double)c->v.y * c->v.y);
        so = sxy; co = c->v.z; phio = sxy > 0 ? atan2((double)c->v.y, (double)c->v.x) : 0.0;
        a = so * sin(th); b = co * cos(th);
        if (a <= b) { lo = phio - PI; hi = phio + PI; }
        else { double p = acos(-b / a); lo = phio - p; hi = phio + p; }
    }
    /* the integrand is a smooth trigonometric polynomial on [lo, hi]: two 24-point panels */
    for (i = 0; i < 48; ++i) {
        double half = 0.5 * (hi - lo), x = lo + half * ((i / 24) + gx[i % 24]);
        s += half * gw[i % 24] * pol_f(c, th, x);
    }
    return s;
}

static double pol_piece(const pol_ctx *c, double ta, double tb, int subst)
{
    static double gx[16], gw[16];
    static int init = 0;
    double s = 0.0, L = tb - ta;
    int i, p, np = 1 + (int)(L / 0.05);
    if (!init) { mft_gl(16, gx, gw); init = 1; }
    if (!(L > 0)) return 0.0;
    for (p = 0; p < np; ++p)
        for (i = 0; i < 16; ++i) {
            double u = (p + gx[i]) / np, th, jac;
            if (subst) { th = ta + L * u * u; jac = 2.0 * L * u; } else { th = ta + L * u; jac = L; }
            s += gw[i] / np * jac * sin(th) * pol_phi(c, th);
        }
    return s;
}

static double polar_integral(const mf_tabulated *t, const mf_ndf *d, mf_vec3 v, int what)
{
    pol_ctx c;
    double tc = what == 0 ? 10.0 : 0.5 * PI - acos((double)v.z), s = 0.0;
    int i;
    c.d = d; c.v = v; c.what = what;
    for (i = 0; i + 1 < t->n; ++i) {
        double a = (double)t->theta[i], b = fmin((double)t->theta[i + 1], 0.5 * PI);   /* float pi/2 is above pi/2 */
        if (tc > a && tc < b) { s += pol_piece(&c, a, tc, 0) + pol_piece(&c, tc, b, 1); }
        else s += pol_piece(&c, a, b, fabs(tc - a) < 1e-12);
    }
    return s;
}

/* the property battery on one tabulated distribution */
static void integrals(const char *name, const mf_tabulated *t)
{
    const double thetas[] = { 0.0, 0.4, 1.0, 1.3, 1.5533 };
    mf_ndf d = mf_tabulated_ndf(t);
    char msg[300];
    int j;
    snprintf(msg, sizeof msg, "tabulated normalization %s", name);
    MFT_NEAR(polar_integral(t, &d, mf_vec3_make(0, 0, 1), 0), 1.0, tol_int(), 0.0, msg);
    for (j = 0; j < 5; ++j) {
        mf_vec3 v = mft_dir(thetas[j], 0.3 + 1.1 * j);
        snprintf(msg, sizeof msg, "tabulated masking constraint %s theta=%.3f", name, thetas[j]);
        MFT_NEAR(polar_integral(t, &d, v, 1) / ((double)v.z * (1.0 + (double)mf_lambda(&d, v))), 1.0, tol_int(), 0.0, msg);
        snprintf(msg, sizeof msg, "tabulated integral D_visible %s theta=%.3f", name, thetas[j]);
        MFT_NEAR(polar_integral(t, &d, v, 2), 1.0, tol_int(), 0.0, msg);
    }
}

static void samplers(const char *name, const mf_tabulated *t, unsigned long long seed)
{
    mf_ndf d = mf_tabulated_ndf(t);
    mft_sampler_check(name, &d, mf_vec3_make(0, 0, 1), 0, 60000, 0, seed);
    mft_sampler_check(name, &d, mf_vec3_make(0, 0, 1), 1, 40000, 0, seed + 1);
    mft_sampler_check(name, &d, mft_dir(0.8, 0.7), 1, 40000, 0, seed + 2);
    mft_sampler_check(name, &d, mft_dir(1.45, 2.5), 1, 40000, 0, seed + 3);
    mft_brdf_check(name, d, mft_dir(1.1, 0.4), 30000, seed + 4, 0);
}

/* curves on a uniform grid of n points */
static void grid(int n, double *th)
{
    int i;
    for (i = 0; i < n; ++i) th[i] = 0.5 * PI * i / (n - 1);
}

static double ggx_curve(double a, double th)
{
    double c = cos(th), t2 = tan(th) * tan(th);
    if (th >= 0.5 * PI - 1e-12) return 0.0;
    return 1.0 / (PI * a * a * c * c * c * c * (1 + t2 / (a * a)) * (1 + t2 / (a * a)));
}
static double beck_curve(double a, double th)
{
    double c = cos(th), t2 = tan(th) * tan(th);
    if (th >= 0.5 * PI - 1e-12) return 0.0;
    return exp(-t2 / (a * a)) / (PI * a * a * c * c * c * c);
}

/* build from double arrays (converted to mf_real) */
static mf_result build(mf_tabulated *t, const double *th, const double *dx, const double *dy, int n)
{
    mf_real *a = (mf_real *)malloc(sizeof(mf_real) * 3 * n);
    mf_result r;
    int i;
    for (i = 0; i < n; ++i) { a[i] = (mf_real)th[i]; a[n + i] = (mf_real)dx[i]; a[2 * n + i] = dy ? (mf_real)dy[i] : 0; }
    r = mf_tabulated_build(t, a, a + n, dy ? a + 2 * n : NULL, n);
    free(a);
    return r;
}

/* Eq. 10 against curves normalized by our own quadrature */
static void test_eq10(void)
{
    enum { N = 41 };
    double th[N], dx[N], dy[N], nx = 0, ny = 0, worst = 0.0, gx[16], gw[16];
    mf_tabulated t;
    mf_ndf d;
    int i, k;
    mft_rng r;
    grid(N, th);
    for (i = 0; i < N; ++i) { dx[i] = ggx_curve(0.2, th[i]) * 3.0; dy[i] = beck_curve(0.5, th[i]) + 0.2 * exp(-pow((th[i] - 0.8) / 0.1, 2)); }
    MFT_CHECK(build(&t, th, dx, dy, N) == MF_SUCCESS, "anisotropic two-curve build");
    mft_gl(16, gx, gw);
    for (i = 0; i + 1 < N; ++i)
        for (k = 0; k < 16; ++k) {
            double x = th[i] + (th[i + 1] - th[i]) * gx[k], f = (x - th[i]) / (th[i + 1] - th[i]);
            double w = gw[k] * (th[i + 1] - th[i]) * 2.0 * PI * cos(x) * sin(x);
            nx += w * (dx[i] + (dx[i + 1] - dx[i]) * f);
            ny += w * (dy[i] + (dy[i + 1] - dy[i]) * f);
        }
    d = mf_tabulated_ndf(&t);
    mft_seed(&r, 31);
    for (i = 0; i < 400; ++i) {
        double a = 1.5 * mft_u01(&r), p = 2 * PI * mft_u01(&r), ia, fx, fy, want, got, c;
        int j = (int)(a / th[1]);
        ia = (a - th[j]) / (th[j + 1] - th[j]);
        fx = (dx[j] + (dx[j + 1] - dx[j]) * ia) / nx;
        fy = (dy[j] + (dy[j + 1] - dy[j]) * ia) / ny;
        c = 0.5 * (dx[0] / nx + dy[0] / ny);
        want = (cos(p) * cos(p) * fx * dy[0] / ny + sin(p) * sin(p) * fy * dx[0] / nx) / c;
        got = mf_D(&d, mft_dir(a, p));
        if (fabs(got - want) / want > worst) worst = fabs(got - want) / want;
    }
    if (mft_verbose) printf("    Eq. 10 worst relative error %.3g\n", worst);
    MFT_CHECK(worst < MFT_TOL(1e-9, 2e-5), "D follows Eq. 10 with normalized curves");
    integrals("aniso ggx0.2 x beckmann0.5+ring", &t);
    samplers("aniso ggx0.2 x beckmann0.5+ring", &t, 7100);
    mf_tabulated_release(&t);
}

/* isotropic multi-lobe, and an anisotropic ring with zero at the pole (weights 1, 1) */
static void tab_lobes(void)
{
    enum { N = 64 };
    double th[N], dx[N], dy[N];
    mf_tabulated t;
    int i;
    grid(N, th);
    for (i = 0; i < N; ++i) dx[i] = exp(-pow(th[i] / 0.15, 2)) + 0.3 * exp(-pow((th[i] - 0.7) / 0.12, 2));
    MFT_CHECK(build(&t, th, dx, NULL, N) == MF_SUCCESS, "two-lobe build");
    MFT_CHECK(t.aniso == 0 && t.inv_h > 0, "two-lobe: isotropic, uniform control points");
    integrals("two lobes", &t);
    samplers("two lobes", &t, 7200);
    mf_tabulated_release(&t);
    for (i = 0; i < N; ++i) { dx[i] = exp(-pow((th[i] - 0.5) / 0.1, 2)); dy[i] = exp(-pow((th[i] - 0.9) / 0.2, 2)) * (th[i] > 0); }
    dx[0] = 0.0;
    MFT_CHECK(build(&t, th, dx, dy, N) == MF_SUCCESS, "anisotropic rings build");
    MFT_NEAR(t.wx, 1.0, 1e-12, 0, "rings: Eq. 10 weights 1 when both curves vanish at the pole");
    integrals("aniso rings", &t);
    samplers("aniso rings", &t, 7300);
    mf_tabulated_release(&t);
}

/* tabulated copies of GGX and Beckmann against the analytic distributions */
static void test_copies(void)
{
    mft_case cs[3] = { { "ggx 0.3", MF_NDF_GGX, 0.3, 0.3, 0 }, { "beckmann 0.5", MF_NDF_BECKMANN, 0.5, 0.5, 0 },
                       { "ggx 0.05", MF_NDF_GGX, 0.05, 0.05, 0 } };
    int k, i;
    for (k = 0; k < 3; ++k) {
        mf_ndf a = mft_make(&cs[k]), d;
        mf_tabulated t;
        mft_rng r;
        double ed = 0.0, el = 0.0, dmax = (double)mf_D(&a, mf_vec3_make(0, 0, 1));
        char msg[200];
        MFT_CHECK(mf_tabulated_from_ndf(&t, &a, 256) == MF_SUCCESS, "from_ndf builds");
        d = mf_tabulated_ndf(&t);
        mft_seed(&r, 40 + k);
        for (i = 0; i < 2000; ++i) {
            mf_vec3 m = mf_sample_D(&a, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
            mf_vec3 v = mft_dir(1.55 * mft_u01(&r), 6.28 * mft_u01(&r));
            double da = mf_D(&a, m), dt = mf_D(&d, m);
            double la = 1.0 + mf_lambda(&a, v), lt = 1.0 + mf_lambda(&d, v);
            if (da > 1e-3 * dmax && fabs(dt / da - 1.0) > ed) ed = fabs(dt / da - 1.0);
            if (fabs(lt / la - 1.0) > el) el = fabs(lt / la - 1.0);
        }
        printf("    tabulated copy of %s (%d points, %.1f KB): D within %.2e, 1 + Lambda within %.2e\n", cs[k].name, t.n,
               mf_tabulated_memory_bytes(&t) / 1024.0, ed, el);
        snprintf(msg, sizeof msg, "tabulated %s: D matches the analytic one (%.2e)", cs[k].name, ed);
        MFT_CHECK(ed < 2e-3, msg);
        snprintf(msg, sizeof msg, "tabulated %s: Lambda matches the analytic one (%.2e)", cs[k].name, el);
        MFT_CHECK(el < 1e-3, msg);
        if (k == 0) integrals("copy of ggx 0.3", &t);
        if (k == 2) samplers("copy of ggx 0.05 (non-uniform points)", &t, 7500);
        mf_tabulated_release(&t);
    }
}

/* an anisotropic source: the two slices become D_x and D_y of Eq. 10 */
static void test_aniso_copy(void)
{
    mf_ndf a = mf_ggx(MF_R(0.3), MF_R(0.1)), d;
    mf_tabulated t;
    double worst0 = 0.0, worst = 0.0;
    int i;
    mft_rng r;
    MFT_CHECK(mf_tabulated_from_ndf(&t, &a, 128) == MF_SUCCESS && t.aniso == 1, "from_ndf of anisotropic GGX: two curves");
    d = mf_tabulated_ndf(&t);
    mft_seed(&r, 77);
    for (i = 0; i < 500; ++i) {
        double th = 1.4 * mft_u01(&r), p = 6.283 * mft_u01(&r), da, dt;
        mf_vec3 m0 = mft_dir(th, 0.0), m = mft_dir(th, p);
        da = mf_D(&a, m0); dt = mf_D(&d, m0);
        if (da > 1e-3 * mf_D(&a, mf_vec3_make(0, 0, 1)) && fabs(dt / da - 1.0) > worst0) worst0 = fabs(dt / da - 1.0);
        da = mf_D(&a, m); dt = mf_D(&d, m);
        if (da > 1e-2 * mf_D(&a, mf_vec3_make(0, 0, 1)) && fabs(dt / da - 1.0) > worst) worst = fabs(dt / da - 1.0);
    }
    /* on phi = 0 Eq. 10 gives wx D_x: the curve rescaled by its own normalization */
    printf("    tabulated anisotropic GGX 0.3x0.1 (Eq. 10 form): relative D difference on phi = 0 %.3f, anywhere %.3f\n", worst0, worst);
    integrals("copy of ggx 0.3x0.1", &t);
    samplers("copy of ggx 0.3x0.1", &t, 7600);
    mf_tabulated_release(&t);
    /* elliptical anisotropy exactly: the isotropic base tabulated, then stretched (thesis Eq. 4.22) */
    {
        mf_real ab = MF_SQRT(MF_R(0.3) * MF_R(0.1));
        mf_ndf iso = mf_ggx(ab, ab), e;
        double ed = 0.0, el = 0.0;
        MFT_CHECK(mf_tabulated_from_ndf(&t, &iso, 256) == MF_SUCCESS, "from_ndf of the isotropic base");
        e = mf_transformed(mf_tabulated_ndf(&t), mf_mat2_make(ab / MF_R(0.3), 0, 0, ab / MF_R(0.1)));
        for (i = 0; i < 1000; ++i) {
            mf_vec3 m = mf_sample_D(&a, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)), v = mft_dir(1.55 * mft_u01(&r), 6.283 * mft_u01(&r));
            double da = mf_D(&a, m), dt = mf_D(&e, m), la = 1.0 + mf_lambda(&a, v), lt = 1.0 + mf_lambda(&e, v);
            if (da > 1e-3 * mf_D(&a, mf_vec3_make(0, 0, 1)) && fabs(dt / da - 1.0) > ed) ed = fabs(dt / da - 1.0);
            if (fabs(lt / la - 1.0) > el) el = fabs(lt / la - 1.0);
        }
        printf("    tabulated isotropic GGX stretched to 0.3x0.1: D within %.2e, 1 + Lambda within %.2e\n", ed, el);
        MFT_CHECK(ed < 2e-3 && el < 1e-3, "tabulated base + diagonal transform = anisotropic GGX to the tabulation error");
        mf_tabulated_release(&t);
    }
}

/* transformed tabulated distributions through the generic slope-space quadrature */
static void test_transformed(void)
{
    enum { N = 48 };
    double th[N], dx[N];
    mf_tabulated t;
    mf_ndf d;
    int i, j;
    char msg[200];
    grid(N, th);
    for (i = 0; i < N; ++i) dx[i] = ggx_curve(0.4, th[i]) + 0.5 * exp(-pow((th[i] - 0.6) / 0.15, 2));
    MFT_CHECK(build(&t, th, dx, NULL, N) == MF_SUCCESS, "build for transforms");
    d = mf_transformed(mf_tabulated_ndf(&t), mf_mat2_make(MF_R(1.4), MF_R(0.5), MF_R(-0.3), MF_R(0.7)));
    MFT_NEAR(mft_norm_integral(&d), 1.0, MFT_TOL(2e-5, 2e-4), 0.0, "transformed tabulated normalization");
    for (j = 0; j < 3; ++j) {
        mf_vec3 v = mft_dir(0.3 + 0.6 * j, 0.5 + 2.0 * j);
        snprintf(msg, sizeof msg, "transformed tabulated masking constraint theta=%.2f", 0.3 + 0.6 * j);
        MFT_NEAR(mft_visible_integral(&d, v, 0) / ((double)v.z * (1.0 + mf_lambda(&d, v))), 1.0, MFT_TOL(2e-5, 2e-4), 0.0, msg);
    }
    mft_sampler_check("transformed tabulated", &d, mf_vec3_make(0, 0, 1), 0, 60000, 0, 7400);
    mft_sampler_check("transformed tabulated", &d, mft_dir(1.0, 1.0), 1, 40000, 0, 7401);
    mf_tabulated_release(&t);
}

static void test_bad_input(void)
{
    mf_real th[4] = { 0, MF_R(0.5), MF_R(1.0), MF_R(1.5707963267948966) }, v[4] = { 1, 1, 1, 1 };
    mf_real bad[4] = { 1, -1, 1, 1 }, zero[4] = { 0, 0, 0, 0 }, unord[4] = { 0, MF_R(1.0), MF_R(0.5), MF_R(1.5707963267948966) };
    mf_real shortend[4] = { 0, MF_R(0.5), MF_R(1.0), MF_R(1.4) }, nanv[4];
    mf_tabulated t;
    mf_ndf d;
    mf_vec3 w = mft_dir(0.7, 0.3), s;
    nanv[0] = 1; nanv[1] = (mf_real)nan(""); nanv[2] = 1; nanv[3] = 1;
    MFT_CHECK(mf_tabulated_build(NULL, th, v, NULL, 4) == MF_ERROR_INVALID_ARGUMENT, "build: NULL table");
    MFT_CHECK(mf_tabulated_build(&t, NULL, v, NULL, 4) == MF_ERROR_INVALID_ARGUMENT && t.block == NULL, "build: NULL theta");
    MFT_CHECK(mf_tabulated_build(&t, th, v, NULL, 1) == MF_ERROR_INVALID_ARGUMENT && t.block == NULL, "build: n < 2");
    MFT_CHECK(mf_tabulated_build(&t, th, bad, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: negative value");
    MFT_CHECK(mf_tabulated_build(&t, th, v, nanv, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: NaN value");
    MFT_CHECK(mf_tabulated_build(&t, th, zero, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: all zero");
    MFT_CHECK(mf_tabulated_build(&t, th, v, zero, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: all-zero D_y");
    MFT_CHECK(mf_tabulated_build(&t, unord, v, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: unordered angles");
    MFT_CHECK(mf_tabulated_build(&t, shortend, v, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: angles not reaching pi/2");
    MFT_CHECK(mf_tabulated_from_ndf(&t, NULL, 64) == MF_ERROR_INVALID_ARGUMENT && t.block == NULL, "from_ndf: NULL ndf");
    {   /* angles closer than the precision, and ends that snapping would reorder */
        mf_real close[4] = { 0, (mf_real)MFT_TOL(1e-16, 1e-9), MF_R(0.5), MF_R(1.5707963267948966) };
        mf_real near1[4] = { 0, (mf_real)MFT_TOL(1e-12, 1e-5), MF_R(0.5), MF_R(1.5707963267948966) };
        mf_ndf dn;
        mf_real low[4] = { MF_R(-9e-5), MF_R(-1e-5), MF_R(0.5), MF_R(1.5707963267948966) };
        mf_real high[4] = { 0, MF_R(0.5), MF_R(1.5707963267948966) + MF_R(1e-5), MF_R(1.5707963267948966) + MF_R(9e-5) };
        MFT_CHECK(mf_tabulated_build(&t, close, v, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: angles closer than 16 ulps");
        MFT_CHECK(mf_tabulated_build(&t, near1, v, NULL, 4) == MF_SUCCESS, "build: angles a few hundred ulps apart");
        dn = mf_tabulated_ndf(&t);
        MFT_CHECK(mft_finite(mf_lambda(&dn, mf_vec3_make(1, 0, 0))) && mft_finite(mf_lambda(&dn, mft_dir(1.5707963, 0))),
                  "close angles: Lambda finite on the table's nodes");
        mf_tabulated_release(&t);
        MFT_CHECK(mf_tabulated_build(&t, low, v, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: first angles reordered by snapping");
        MFT_CHECK(mf_tabulated_build(&t, high, v, NULL, 4) == MF_ERROR_INVALID_DATA && t.block == NULL, "build: last angles reordered by snapping");
        MFT_CHECK(mf_tabulated_build(&t, th, v, NULL, MF_TABULATED_MAX_POINTS + 1) == MF_ERROR_INVALID_ARGUMENT, "build: n above the maximum");
    }
    MFT_CHECK(mf_tabulated_build(&t, th, v, NULL, 4) == MF_SUCCESS, "build: constant curve");
    d = mf_tabulated_ndf(&t);
    MFT_NEAR(mf_D(&d, w), 1.0 / PI, MFT_TOL(1e-12, 1e-6), 0, "constant curve is the uniform 1/pi");
    mf_tabulated_release(&t);
    MFT_CHECK(t.block == NULL && mf_tabulated_memory_bytes(&t) == 0, "release empties the table");
    d = mf_tabulated_ndf(&t);
    s = mf_sample_visible(&d, w, MF_R(0.3), MF_R(0.6));
    MFT_CHECK(mf_D(&d, w) == 0 && mf_lambda(&d, w) == 0 && mf_brdf(&d, w, w) == 0 && s.z == 0 && mf_sample_D(&d, MF_R(0.3), MF_R(0.2)).z == 0,
              "released table: every function returns 0");
    d = mf_tabulated_ndf(NULL);
    MFT_CHECK(mf_D(&d, w) == 0 && mf_brdf_pdf(&d, w, w) == 0, "NULL table: every function returns 0");
}

static void test_rebase(void)
{
    enum { N = 32 };
    double th[N], dx[N], dy[N];
    mf_tabulated t, c;
    void *copy;
    mf_ndf a, b;
    int i, same = 1;
    mft_rng r;
    grid(N, th);
    for (i = 0; i < N; ++i) { dx[i] = ggx_curve(0.3, th[i]); dy[i] = beck_curve(0.3, th[i]); }
    build(&t, th, dx, dy, N);
    copy = malloc(t.bytes);
    memcpy(copy, t.block, t.bytes);
    c = mf_tabulated_rebase(&t, copy);
    a = mf_tabulated_ndf(&t); b = mf_tabulated_ndf(&c);
    mft_seed(&r, 5);
    for (i = 0; i < 200; ++i) {
        mf_vec3 v = mft_dir(1.5 * mft_u01(&r), 6.28 * mft_u01(&r));
        mf_real u1 = (mf_real)mft_u01(&r), u2 = (mf_real)mft_u01(&r);
        mf_vec3 s1 = mf_sample_visible(&a, v, u1, u2), s2 = mf_sample_visible(&b, v, u1, u2);
        if (mf_D(&a, v) != mf_D(&b, v) || mf_lambda(&a, v) != mf_lambda(&b, v) || s1.x != s2.x || s1.z != s2.z) same = 0;
    }
    {   /* Lambda and visible samples are scale-free in the view (transforms pass M^-1 w) */
        int scale_ok = 1;
        mft_seed(&r, 6);
        for (i = 0; i < 100; ++i) {
            mf_vec3 v = mft_dir(1.55 * mft_u01(&r), 6.28 * mft_u01(&r));
            mf_real u1 = (mf_real)mft_u01(&r), u2 = (mf_real)mft_u01(&r), l = mf_lambda(&a, v);
            mf_vec3 s1 = mf_sample_visible(&a, v, u1, u2);
            int k;
            for (k = 0; k < 2; ++k) {
                mf_vec3 vs = mf_scale(v, k ? MF_R(1e-20) : MF_R(1e20)), s2 = mf_sample_visible(&a, vs, u1, u2);
                if (fabs(mf_lambda(&a, vs) - l) > MFT_TOL(1e-9, 1e-4) * (1.0 + l) || fabs(s2.x - s1.x) + fabs(s2.z - s1.z) > MFT_TOL(1e-9, 1e-4))
                    scale_ok = 0;
            }
        }
        MFT_CHECK(scale_ok, "Lambda and visible samples unchanged when the view is scaled by 1e20 or 1e-20");
    }
    mf_tabulated_release(&t);
    memset(&t, 0, sizeof t);   /* the copy must not refer to the original */
    MFT_CHECK(same && c.block == copy, "rebased table reproduces every value");
    free(copy);
}

void test_tabulated(void)
{
    test_eq10();
    tab_lobes();
    test_copies();
    test_aniso_copy();
    test_transformed();
    test_bad_input();
    test_rebase();
}
