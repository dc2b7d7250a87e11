/* Distributions and Smith masking, checked by numerical integration in slope
 * space (tests/quad.c), never against the code's own closed forms:
 *   normalization   integral D(m) (m.n) dm = 1                  (thesis Eq. 3.5)
 *   masking         integral G1(v,m) <v.m> D(m) dm = v.z         (thesis Eq. 3.9)
 *                   i.e. mf_lambda against the integrated Lambda
 *   visible normals integral D_v(m) dm = 1
 * Tolerances: 1e-7 relative in double where the formula is exact (Beckmann, GGX,
 * Student-t, GTR at integer gamma); measured worst 6e-9 (the quadrature reaches
 * ~1e-15 on GGX). GTR at non-integer gamma (a Gauss-Jacobi rule over an
 * exact mixture, see mf__gtr_lambda): 1e-5 here, and test_lambda_dense checks
 * Lambda itself, relative, against a 1D integral over a dense (alpha, gamma,
 * angle) grid for GTR and Student-t. Float builds: 2e-4 (float math near the
 * D peak and the incomplete beta limit this). */
#include "mf_test.h"
#include "quad.h"

static int gtr_spline_case(const mft_case *c)
{
    return c->kind == MF_NDF_GTR && fabs(c->gamma - floor(c->gamma + 0.5)) > 1e-9 && c->ax < 1.0;
}

static void test_normalization(void)
{
    int i;
    char msg[128];
    for (i = 0; i < mft_ncases; ++i) {
        mf_ndf d = mft_make(&mft_cases[i]);
        snprintf(msg, sizeof msg, "normalization %s", mft_cases[i].name);
        MFT_NEAR(mft_norm_integral(&d), 1.0, MFT_TOL(1e-7, 2e-4), 0.0, msg);
    }
    /* extra GTR tails, including the Berry limit and gamma = 0 */
    {
        double g[] = { 0.0, 0.3, 0.999999, 1.0, 1.000001, 1.5, 2.2, 3.5, 4.0 };
        double a[] = { 0.05, 0.4, 0.9999 };
        int j, k;
        for (j = 0; j < 9; ++j)
            for (k = 0; k < 3; ++k) {
                mf_ndf d = mf_gtr((mf_real)a[k], (mf_real)g[j]);
                snprintf(msg, sizeof msg, "normalization gtr a=%g g=%g", a[k], g[j]);
                MFT_NEAR(mft_norm_integral(&d), 1.0, MFT_TOL(1e-7, 2e-4), 0.0, msg);
            }
    }
}

static void test_masking(void)
{
    const double thetas[] = { 0.0, 0.4, 0.9, 1.25, 1.45, 1.5533 /* 89 deg */ };
    const double phis[] = { 0.0, 0.7, 2.0 };
    int i, j;
    char msg[160];
    double worst_spline = 0.0;
    for (i = 0; i < mft_ncases; ++i) {
        mf_ndf d = mft_make(&mft_cases[i]);
        int spline = gtr_spline_case(&mft_cases[i]);
        for (j = 0; j < 6; ++j) {
            mf_vec3 v = mft_dir(thetas[j], phis[j % 3]);
            double area, lam_num, lam, g1sum, tol, dvis = 1.0;
            if (!mft_full && j % 2 == 1 && j != 5) continue;   /* make test: 0, 52, 83 and 89 deg */
            area = mft_visible_integrals(&d, v, j == 2 || j == 5 ? &dvis : NULL);   /* v.z (1 + Lambda) */
            lam_num = area / v.z - 1.0; lam = mf_lambda(&d, v);
            g1sum = area / (v.z * (1.0 + lam));              /* integral G1 <v.m> D / v.z */
            tol = spline ? MFT_TOL(1e-5, 2e-4) : MFT_TOL(1e-7, 2e-4);
            if (spline && fabs(g1sum - 1.0) > worst_spline) worst_spline = fabs(g1sum - 1.0);
            snprintf(msg, sizeof msg, "masking constraint %s theta=%.4f", mft_cases[i].name, thetas[j]);
            MFT_NEAR(g1sum, 1.0, tol, 0.0, msg);
            snprintf(msg, sizeof msg, "lambda vs integral %s theta=%.4f", mft_cases[i].name, thetas[j]);
            MFT_NEAR(1.0 + lam, 1.0 + lam_num, tol, 0.0, msg);
            if (j == 2 || j == 5) {
                snprintf(msg, sizeof msg, "integral D_visible %s theta=%.4f", mft_cases[i].name, thetas[j]);
                MFT_NEAR(dvis, 1.0, tol, 0.0, msg);
            }
        }
    }
    printf("    GTR non-integer gamma worst masking-constraint error: %.2e\n", worst_spline);
}

/* Smith G2 forms and symmetry of Lambda. */
static void test_smith_forms(void)
{
    int i;
    mft_rng r;
    mft_seed(&r, 7);
    for (i = 0; i < mft_ncases; ++i) {
        mf_ndf d = mft_make(&mft_cases[i]);
        mf_vec3 wo = mft_dir(0.3 + 1.2 * mft_u01(&r), 6.28 * mft_u01(&r));
        mf_vec3 wi = mft_dir(0.1 + 1.4 * mft_u01(&r), 6.28 * mft_u01(&r));
        mf_vec3 wh = mf_normalize(mf_add(wo, wi)), wneg = wo;
        double lo = mf_lambda(&d, wo), li = mf_lambda(&d, wi);
        wneg.z = -wneg.z;
        MFT_NEAR(mf_G2(&d, wo, wi, wh), 1.0 / (1.0 + lo + li), 1e-6, 0.0, "G2 height-correlated form");
        MFT_NEAR(mf_G2_separable(&d, wo, wi, wh), 1.0 / ((1.0 + lo) * (1.0 + li)), 1e-6, 0.0, "G2 separable form");
        MFT_CHECK(mf_G2(&d, wo, wi, wh) >= mf_G2_separable(&d, wo, wi, wh), "height-correlated >= separable");
        MFT_NEAR(mf_lambda(&d, wneg), lo, 1e-6, 0.0, "Lambda symmetric in w.z");
        MFT_CHECK(mf_G1(&d, wneg, wh) == 0, "G1 = 0 below the horizon");
        MFT_CHECK(mf_G1(&d, wo, mf_scale(wh, -1)) == 0, "G1 = 0 for a back-facing microfacet");
    }
}

/* GGX G2 in one division (2 zo zi / (zi |s wo| + zo |s wi|)) against the
 * height-correlated form built in double from the closed-form Lambda (thesis
 * C.4), plain and transformed, from normal incidence to 1e-6 above the
 * horizon and alpha 1e-4..1e4. */
static double ggx_lambda_ref(double ax, double ay, double x, double y, double z)
{
    double a2t2 = (ax * ax * x * x + ay * ay * y * y) / (z * z);
    return 0.5 * (sqrt(1.0 + a2t2) - 1.0);
}
static void test_ggx_G2_one_division(void)
{
    const double alphas[] = { 1e-4, 0.01, 0.3, 1.0, 20.0, 1e4 };
    const double thetas[] = { 0.0, 0.5, 1.2, 1.5, 1.5707, 1.5707953 };
    double worst = 0.0;
    int ia, jo, ji, t, bad = 0;
    for (t = 0; t < 2; ++t)
        for (ia = 0; ia < 6; ++ia)
            for (jo = 0; jo < 6; ++jo)
                for (ji = 0; ji < 6; ++ji) {
                    double ax = alphas[ia], ay = alphas[(ia + 2) % 6], po = 0.3 + jo, pi = 2.0 + 0.7 * ji;
                    double m00 = t ? 1.5 : 1.0, m01 = t ? 0.3 : 0.0, m10 = t ? -0.2 : 0.0, m11 = t ? 0.8 : 1.0;
                    double det = m00 * m11 - m01 * m10, xo, yo, xi, yi, want, got, e;
                    mf_vec3 wo = mf_vec3_make((mf_real)(sin(thetas[jo]) * cos(po)), (mf_real)(sin(thetas[jo]) * sin(po)), (mf_real)cos(thetas[jo]));
                    mf_vec3 wi = mf_vec3_make((mf_real)(sin(thetas[ji]) * cos(pi)), (mf_real)(sin(thetas[ji]) * sin(pi)), (mf_real)cos(thetas[ji]));
                    mf_ndf d = mf_ggx((mf_real)ax, (mf_real)ay);
                    if (t) d = mf_transformed(d, mf_mat2_make((mf_real)m00, (mf_real)m01, (mf_real)m10, (mf_real)m11));
                    /* Lambda of a transformed kind at M^-1 w (Eq. 4.4) */
                    xo = (m11 * wo.x - m01 * wo.y) / det; yo = (-m10 * wo.x + m00 * wo.y) / det;
                    xi = (m11 * wi.x - m01 * wi.y) / det; yi = (-m10 * wi.x + m00 * wi.y) / det;
                    want = 1.0 / (1.0 + ggx_lambda_ref(d.ax, d.ay, xo, yo, wo.z) + ggx_lambda_ref(d.ax, d.ay, xi, yi, wi.z));
                    got = mf_G2(&d, wo, wi, mf_vec3_make(0, 0, 1));
                    e = fabs(got - want) / want;
                    if (!(got >= 0.0 && got <= 1.0) || !(e < 16 * MF_EPS)) ++bad;
                    if (e > worst) worst = e;
                }
    printf("    GGX G2 one-division form: worst relative error %.3g (%.2f eps)\n", worst, worst / MF_EPS);
    MFT_CHECK(bad == 0, "GGX G2 one-division form = 1 / (1 + Lambda(wo) + Lambda(wi)), plain and transformed, to 16 eps");
}

/* Known values and limits. */
static void test_values(void)
{
    mf_vec3 n = mf_vec3_make(0, 0, 1), w = mft_dir(1.0, 0.3);
    mf_ndf g = mf_ggx(MF_R(0.3), MF_R(0.3)), b = mf_beckmann(MF_R(0.3), MF_R(0.3)), gt2 = mf_gtr(MF_R(0.3), 2.0f);
    mf_ndf st2 = mf_student_t(MF_R(0.3), MF_R(0.3), 2.0f), st_big = mf_student_t(MF_R(0.3), MF_R(0.3), 1000.0f);
    mf_vec3 m = mft_dir(0.2, 1.0);
    MFT_NEAR(mf_D(&g, n), 1.0 / (3.14159265358979323846 * (double)MF_R(0.3) * (double)MF_R(0.3)), MFT_TOL(1e-12, 1e-6), 0, "GGX D(n) = 1/(pi a^2)");
    MFT_NEAR(mf_D(&b, n), 1.0 / (3.14159265358979323846 * (double)MF_R(0.3) * (double)MF_R(0.3)), MFT_TOL(1e-12, 1e-6), 0, "Beckmann D(n) = 1/(pi a^2)");
    MFT_NEAR(mf_D(&gt2, m), mf_D(&g, m), MFT_TOL(1e-12, 1e-5), 0, "GTR gamma=2 D equals GGX");
    MFT_NEAR(mf_lambda(&gt2, w), mf_lambda(&g, w), MFT_TOL(1e-12, 1e-5), 0, "GTR gamma=2 Lambda equals GGX");
    MFT_NEAR(mf_D(&st2, m), mf_D(&g, m), MFT_TOL(1e-12, 1e-5), 0, "Student-t gamma=2 D equals GGX");
    MFT_NEAR(mf_lambda(&st2, w), mf_lambda(&g, w), MFT_TOL(1e-9, 1e-4), 0, "Student-t gamma=2 Lambda equals GGX");
    MFT_NEAR(mf_D(&st_big, m), mf_D(&b, m), 2e-3, 0, "Student-t gamma=1000 D near Beckmann");
    MFT_NEAR(1.0 + mf_lambda(&st_big, w), 1.0 + mf_lambda(&b, w), 1e-5, 0, "Student-t gamma=1000 Lambda near Beckmann");
    /* Walter's approximation of the Beckmann Lambda: G1 within 0.4% */
    {
        int i;
        double worst = 0.0;
        for (i = 1; i < 90; ++i) {
            mf_vec3 v = mft_dir(i * 0.01745329, 0.0);
            double e = (1.0 + mf_beckmann_lambda(0.3f, 0.3f, v)) / (1.0 + mf_beckmann_lambda_approx(0.3f, 0.3f, v)) - 1.0;
            if (fabs(e) > worst) worst = fabs(e);
        }
        MFT_CHECK(worst < 4e-3, "Walter Beckmann G1 approximation within 0.4%");
    }
    /* GTR limits: gamma -> 1 is Berry (C.6), alpha -> 1 is uniform 1/pi */
    {
        mf_ndf a = mf_gtr(MF_R(0.3), 1.0f), bb = mf_gtr(MF_R(0.3), MF_R(1.0) + MF_R(1e-6)), u = mf_gtr(1.0f, 3.0f);
        double a2 = (double)MF_R(0.3) * (double)MF_R(0.3), c2 = m.z * m.z;
        double berry = (a2 - 1.0) / (3.14159265358979323846 * log(a2) * (1.0 + (a2 - 1.0) * c2));
        MFT_NEAR(mf_D(&a, m), berry, MFT_TOL(1e-10, 1e-5), 0, "GTR gamma=1 is Berry (C.6)");
        MFT_NEAR(mf_D(&bb, m), berry, MFT_TOL(1e-5, 1e-4), 0, "GTR gamma->1 continuous");
        MFT_NEAR(mf_D(&u, m), 1.0 / 3.14159265358979323846, MFT_TOL(1e-12, 1e-6), 0, "GTR alpha=1 is 1/pi");
        MFT_NEAR(mf_lambda(&u, w), mf_lambda(&a, w) * 0 + (sqrt(1 + tan(1.0) * tan(1.0)) - 1) / 2, MFT_TOL(1e-9, 1e-5), 0,
                 "GTR alpha=1 Lambda is GGX alpha=1");
    }
    /* Fresnel */
    MFT_NEAR(mf_fresnel_dielectric(1.0f, 1.5f), 0.04, 1e-6, 0, "dielectric normal incidence");
    MFT_NEAR(mf_fresnel_dielectric(0.1f, MF_R(1.0) / MF_R(1.5)), 1.0, 0, 0, "total internal reflection");
    MFT_NEAR(mf_fresnel_dielectric(-0.5f, 1.5f), mf_fresnel_dielectric(0.5f, MF_R(1.0) / MF_R(1.5)), 1e-6, 0, "dielectric from inside");
    MFT_NEAR(mf_fresnel_conductor(1.0f, MF_R(0.2), 3.0f), ((double)MF_R(0.8) * MF_R(0.8) + 9.0) / ((double)MF_R(1.2) * MF_R(1.2) + 9.0), MFT_TOL(1e-12, 1e-6), 0,
             "conductor normal incidence |(n-1)/(n+1)|^2");
    MFT_NEAR(mf_fresnel_conductor(0.6f, 1.5f, 0.0f), mf_fresnel_dielectric(0.6f, 1.5f), MFT_TOL(1e-12, 1e-5), 0,
             "conductor with k = 0 is the dielectric");
    MFT_NEAR(mf_fresnel_conductor(0.0f, MF_R(0.2), 3.0f), 1.0, MFT_TOL(1e-9, 1e-5), 0, "conductor grazing -> 1");
    MFT_NEAR(mf_fresnel_schlick(0.5f, 0.04f), 0.04 + 0.96 * 0.03125, 1e-6, 0, "Schlick");
}

/* Slope density P22 at squared slope radius x, written here in double
 * from the papers (GTR: thesis C.5 times cos^4; Student-t: Ribardiere 2017). */
typedef struct { int kind; double a, g, norm; } dense_ctx;
static double dense_p22(const dense_ctx *c, double x)
{
    double a2 = c->a * c->a;
    if (c->kind == MF_NDF_GTR)
        return c->norm * pow(1.0 + x, c->g - 2.0) * pow(a2 + x, -c->g);
    return exp(-c->g * log1p(x / (a2 * (c->g - 1.0)))) / (3.14159265358979323846 * a2);
}
/* Smith Lambda(mu = cot theta) = (1/mu) integral_{x > mu} (x - mu) P22 over the
 * slope plane; in polar coordinates r = mu cosh s the azimuth integrates in
 * closed form: Lambda = 2 mu^2 int_0^inf P22 cosh s sinh s (sinh s - atan sinh s) ds.
 * Composite 8-point Gauss-Legendre on panels of 1/8 in s (s ~ log r resolves
 * every scale of the density), GTR to where the r^-3 tail is below 1e-14;
 * Student-t (tail r^(2 - 2g), slow for g near 1.5) to R = 1e6 max(mu, a sqrt(g-1)),
 * beyond which the power-law asymptotics of P22 and of the azimuth integral
 * (r - mu pi/2, relative error mu^2/R^2) integrate in closed form. */
static double dense_lambda_ref(const dense_ctx *c, double mu)
{
    double gx[8], gw[8], smax, h = 0.125, sum = 0.0, tail = 0.0, R = 0.0;
    int p, i, np;
    if (c->kind == MF_NDF_GTR) smax = log(2.0e14 * (1.0 + c->a) / mu) + 4.0;
    else {
        double g = c->g, B = c->a * c->a * (g - 1.0), A = 1.0 / (3.14159265358979323846 * c->a * c->a);
        R = 1e6 * (mu > sqrt(B) ? mu : sqrt(B));
        smax = acosh(R / mu);
        R = mu * cosh(smax);
        /* P22 = A B^g r^-2g (1 - g B / r^2 + ...), times r (r - mu pi / 2), from R up */
        {   /* in logs: B^g R^(3-2g) over- and underflows at large g */
            double lb = g * log(B), lr = log(R);
            tail = 2.0 / mu * A * (exp(lb + (3.0 - 2.0 * g) * lr) / (2.0 * g - 3.0) -
                                   0.5 * 3.14159265358979323846 * mu * exp(lb + (2.0 - 2.0 * g) * lr) / (2.0 * g - 2.0) -
                                   g * B * exp(lb + (1.0 - 2.0 * g) * lr) / (2.0 * g - 1.0));
        }
    }
    np = (int)(smax / h) + 1;
    h = smax / np;
    mft_gl(8, gx, gw);
    for (p = 0; p < np; ++p)
        for (i = 0; i < 8; ++i) {
            double s = h * (p + gx[i]), z = sinh(s), r = mu * cosh(s);
            double d = z < 1e-3 ? z * z * z * (1.0 / 3.0 - z * z / 5.0) : z - atan(z);
            sum += h * gw[i] * dense_p22(c, r * r) * cosh(s) * z * d;
        }
    return 2.0 * mu * mu * sum + tail;
}
/* the vectorizable sqrt of the GTR mixture loops, over its whole domain
 * [1, 2e16]: every float of [1, 4) (the guess depends on the exponent's
 * parity and the mantissa only) and 2e5 log-spaced points up to 2e16 */
static void test_gtr_sqrt(void)
{
    double worst = 0.0, e;
    float x;
    int i;
    char msg[128];
    for (x = 1.0f; x < 4.0f; x = nextafterf(x, 8.0f)) {
        e = fabs((double)mf__gtr_sqrt(x) - sqrt((double)x)) / sqrt((double)x);
        if (e > worst) worst = e;
    }
    for (i = 0; i <= 200000; ++i) {
        double xd = (double)(mf_real)pow(2e16, i / 200000.0);
        e = fabs((double)mf__gtr_sqrt((mf_real)xd) - sqrt(xd)) / sqrt(xd);
        if (e > worst) worst = e;
    }
    snprintf(msg, sizeof msg, "GTR mixture sqrt on [1, 2e16]: worst relative error %.3g", worst);
    MFT_CHECK(worst <= MFT_TOL(1.2e-16, 4e-7), msg);
    printf("    %s\n", msg);
}
static void test_lambda_dense(void)
{
    const double gg[] = { 0.0, 0.1, 0.25, 0.5, 0.75, 0.99, 1.0, 1.01, 1.25, 1.45, 1.5, 1.75, 1.9, 1.99, 2.0,
                          2.01, 2.25, 2.5, 2.75, 3.0, 3.3, 3.7, 3.9, 3.99, 4.0 };
    const double gs[] = { 1.55, 1.6, 1.75, 2.0, 2.5, 3.0, 5.0, 10.0, 30.0, 100.0, 1000.0 };
    const double th[] = { 1.0, 10.0, 30.0, 45.0, 60.0, 70.0, 80.0, 85.0, 88.0, 89.0, 89.5, 89.9 };
    /* bounds: relative on Lambda, and on 1 + Lambda. Double: 1e-5 both (measured
     * GTR 1.8e-6, Student-t 1.6e-10). Float: GTR 3e-5 where Lambda > 1e-4 and
     * 1e-6 on 1 + Lambda (measured 8.4e-7, 6.0e-7); Student-t's head and
     * incomplete-beta tail cancel about ten to one at large gamma, and the
     * float continued fraction near its switch point keeps ~3e-6 of each:
     * 1e-3 and 1e-5 (measured 3.5e-4, 3.4e-6). */
    const double tr[2] = { MFT_TOL(1e-5, 3e-5), MFT_TOL(1e-5, 1e-3) }, t1[2] = { MFT_TOL(1e-5, 1e-6), MFT_TOL(1e-5, 1e-5) };
    double al[20], worst[2] = { 0.0, 0.0 }, worst1[2] = { 0.0, 0.0 }, wpar[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } };
    int ia, ig, it, k, fails = 0;
    for (ia = 0; ia < 20; ++ia) al[ia] = pow(10.0, -4.0 + 4.0 * ia / 19.0);   /* 1e-4 .. 1 */
    for (k = 0; k < 2; ++k)
        for (ig = 0; ig < (k == 0 ? 25 : 11); ++ig)
            for (ia = 0; ia < 20; ++ia) {
                dense_ctx c;
                mf_ndf d;
                c.kind = k == 0 ? MF_NDF_GTR : MF_NDF_STUDENT_T;
                c.g = k == 0 ? gg[ig] : gs[ig];
                c.a = (double)(mf_real)al[ia];
                if (k == 0) {   /* N = (g-1)(a^2-1) / (pi (1 - a^(2(1-g)))), Berry at g = 1 */
                    double a2 = c.a * c.a;
                    c.norm = a2 == 1.0 ? 1.0 / 3.14159265358979323846 :
                             c.g == 1.0 ? (a2 - 1.0) / (3.14159265358979323846 * log(a2)) :
                             (c.g - 1.0) * (a2 - 1.0) / (3.14159265358979323846 * (1.0 - pow(a2, 1.0 - c.g)));
                    d = mft_gtr(c.a, c.g);
                } else
                    d = mf_student_t((mf_real)c.a, (mf_real)c.a, (mf_real)c.g);
                for (it = 0; it < 12; ++it) {
                    double t = th[it] * 3.14159265358979323846 / 180.0;
                    mf_vec3 v = mf_vec3_make((mf_real)sin(t), 0, (mf_real)cos(t));
                    double mu = (double)v.z / (double)v.x;   /* the direction the library sees */
                    double ref = dense_lambda_ref(&c, mu), got = mf_lambda(&d, v), e, e1;
                    e1 = fabs(got - ref) / (1.0 + ref);
                    if (!(e1 <= worst1[k])) worst1[k] = e1;
                    if (!(ref > MFT_TOL(1e-30, 1e-4))) continue;   /* float: relative only where it shows */
                    e = fabs(got - ref) / ref;
                    if (!(e <= worst[k])) { worst[k] = e; wpar[k][0] = c.a; wpar[k][1] = c.g; wpar[k][2] = th[it]; }
                    if (!(e <= tr[k] && e1 <= t1[k]) && fails++ < 5) {
                        char msg[160];
                        snprintf(msg, sizeof msg, "dense Lambda %s a=%g g=%g theta=%g", k ? "student" : "gtr", c.a, c.g, th[it]);
                        MFT_NEAR(got, ref, tr[k], 0.0, msg);
                    }
                }
            }
    MFT_CHECK(worst[0] <= tr[0] && worst1[0] <= t1[0], "dense GTR Lambda within bound");
    MFT_CHECK(worst[1] <= tr[1] && worst1[1] <= t1[1], "dense Student-t Lambda within bound");
    printf("    dense Lambda vs 1D integral, worst relative error%s: GTR %.2e (a=%g g=%g %g deg), "
           "Student-t %.2e (a=%g g=%g %g deg); on 1 + Lambda: GTR %.2e, Student-t %.2e\n",
           MFT_TOL(1, 0) ? "" : " where Lambda > 1e-4", worst[0], wpar[0][0], wpar[0][1], wpar[0][2],
           worst[1], wpar[1][0], wpar[1][1], wpar[1][2], worst1[0], worst1[1]);
}

/* integral D_visible = 1 at the points of the dense grid where the old
 * approximations were worst: with exact Lambda the pdf of the samplers is
 * their density (mf_brdf_pdf = D_visible / (4 |wo.wm|)). Student-t from
 * gamma 2: below, the r^(2-2 gamma) tail of the integrand defeats the 2D
 * quadrature's tail map (it reads 6e-4 low at gamma 1.55), where the 1D
 * reference of test_lambda_dense, with its closed-form tail, holds 1e-10. */
static void test_visible_dense(void)
{
    const double ag[] = { 1e-3, 0.02, 0.3 }, gg[] = { 0.5, 1.45, 1.5, 2.5, 3.7 }, gs[] = { 2.0, 3.0, 30.0 };
    const double th[] = { 60.0, 89.0, 89.9 };
    double worst = 0.0;
    int ia, ig, it;
    char msg[128];
    for (ia = 0; ia < 3; ++ia)
        for (ig = 0; ig < 8; ++ig) {
            mf_ndf d = ig < 5 ? mft_gtr(ag[ia], gg[ig]) : mf_student_t((mf_real)ag[ia], (mf_real)ag[ia], (mf_real)gs[ig - 5]);
            for (it = 0; it < 3; ++it) {
                double t = th[it] * 3.14159265358979323846 / 180.0, got;
                if (!mft_full && (ia + ig + it) % 3) continue;   /* make test: a third of the grid, every row and column */
                mf_vec3 v = mf_vec3_make((mf_real)sin(t), 0, (mf_real)cos(t));
                got = mft_visible_integral(&d, v, 1);
                if (fabs(got - 1.0) > worst) worst = fabs(got - 1.0);
                snprintf(msg, sizeof msg, "integral D_visible %s a=%g g=%g theta=%g", ig < 5 ? "gtr" : "student",
                         ag[ia], ig < 5 ? gg[ig] : gs[ig - 5], th[it]);
                MFT_NEAR(got, 1.0, MFT_TOL(1e-5, 1e-3), 0.0, msg);
            }
        }
    printf("    integral D_visible, GTR and Student-t at alpha 1e-3..0.3, up to 89.9 deg: worst |1 - I| %.2e\n", worst);
}


/* The mf_ndf value type stays small: 64 bytes in float (128 in double). */
static void test_ndf_size(void)
{
    printf("    sizeof(mf_ndf) = %d bytes (%s)\n", (int)sizeof(mf_ndf), MFT_REAL_NAME);
    MFT_CHECK(sizeof(mf_ndf) <= MFT_TOL(128, 64), "sizeof(mf_ndf) <= 64 bytes in float, 128 in double");
}

static int vec_same(mf_vec3 a, mf_vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* A GTR of an mf_gtr_table and mf_gtr by value (whose Lambda takes the same
 * rule from the per-thread cache, or builds it) agree to the bit, transformed too; the table's builder
 * rejects NULL and mf_gtr_table_ndf(NULL) is no distribution. */
static void test_gtr_table(void)
{
    const double as[] = { 1e-4, 0.02, 0.3, 1.0 }, gs[] = { 0.0, 0.5, 1.0, 1.5, 2.5, 3.0, 3.7, 4.0 };
    int i, j, k, bad = 0, n = 0;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 8; ++j) {
            mf_gtr_table t;
            mf_ndf v = mf_gtr((mf_real)as[i], (mf_real)gs[j]), tb, vt, tt;
            mf_mat2 M = mf_mat2_make(MF_R(1.3), MF_R(0.2), MF_R(-0.1), MF_R(0.8));
            MFT_CHECK(mf_gtr_table_build(&t, (mf_real)as[i], (mf_real)gs[j]) == MF_SUCCESS, "mf_gtr_table_build");
            tb = mf_gtr_table_ndf(&t);
            vt = mf_transformed(v, M); tt = mf_transformed(tb, M);
            for (k = 0; k < 24; ++k) {
                double th = 1.55 * k / 23.0, ph = 0.7 * k;
                mf_vec3 w = mft_dir(th, ph), m = mft_dir(0.9 * th, 2.0 - ph);
                mf_real u1 = (mf_real)((k * 0.61803398875) - floor(k * 0.61803398875)), u2 = (mf_real)(0.13 + 0.031 * k);
                ++n;
                if (mf_lambda(&v, w) != mf_lambda(&tb, w) || mf_D(&v, m) != mf_D(&tb, m) ||
                    mf_lambda(&vt, w) != mf_lambda(&tt, w) || mf_D(&vt, m) != mf_D(&tt, m) ||
                    !vec_same(mf_sample_D(&v, u1, u2), mf_sample_D(&tb, u1, u2)) ||
                    !vec_same(mf_sample_visible(&v, w, u1, u2), mf_sample_visible(&tb, w, u1, u2)) ||
                    !vec_same(mf_sample_visible(&vt, w, u1, u2), mf_sample_visible(&tt, w, u1, u2)))
                    ++bad;
            }
        }
    printf("    GTR by value against its mf_gtr_table: %d of %d points differ\n", bad, n);
    MFT_CHECK(bad == 0, "mf_gtr and mf_gtr_table_ndf: the same bits (Lambda, D, both samplers, transformed)");
    MFT_CHECK(mf_gtr_table_build(NULL, MF_R(0.3), MF_R(1.5)) == MF_ERROR_INVALID_ARGUMENT, "mf_gtr_table_build(NULL)");
    {
        mf_ndf z = mf_gtr_table_ndf(NULL);
        mf_vec3 w = mft_dir(0.5, 0.3), s = mf_sample_visible(&z, w, MF_R(0.3), MF_R(0.6));
        MFT_CHECK(mf_D(&z, w) == 0 && mf_lambda(&z, w) == 0 && s.x == 0 && s.y == 0 && s.z == 0,
                  "mf_gtr_table_ndf(NULL): every function returns 0");
    }
}

/* The envelope of GTR's mixture sampler (mode 1), derived from a^(2(1-g)),
 * a and 4^g, against its definition evaluated in double (mf__gtr_envelope:
 * masses C_j z_e^q k_j, kk_j, s_j of the seven power laws). */
static void test_gtr_envelope(void)
{
    const double as[] = { 1e-4, 1e-3, 0.01, 0.05, 0.15, 0.2499 }, gs[] = { 0.05, 0.5, 0.5001, 0.9999, 1.0, 1.2, 1.5, 1.5003, 1.8, 1.99 };
    double worst = 0.0;
    int i, j, jj, n = 0;
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 10; ++j) {
            mf_ndf d = mf_gtr((mf_real)as[i], (mf_real)gs[j]);
            mf_real vs[19];
            double g, a, L, ln4 = log(4.0), ends[6];
            if ((d.mode & 3) != 1) continue;
            ++n;
            g = (double)d.p.gtr.gamma; a = (double)d.ax; L = 2.0 * log(a);
            ends[0] = -1e300; ends[1] = L - ln4; ends[2] = L + ln4; ends[3] = -ln4; ends[4] = ln4; ends[5] = 1e300;
            mf__gtr_envelope(&d, vs);
            for (jj = 0; jj < 7; ++jj) {
                int pc = jj == 6 ? 4 : (jj + 1) >> 1;
                double c = jj == 0 || jj == 2 ? 2.0 : jj == 1 || jj == 4 ? 1.5 : jj == 3 ? 1.0 : jj == 5 ? 0.5 : 0.0;
                double q = c - g, lo = ends[pc], hi = ends[pc + 1], lc, sj = 1.0, kj, mass, e;
                lc = pc == 0 ? -L : pc == 1 ? -0.5 * L - log(2.0) : pc == 3 ? -log(2.0) : 0.0;
                if (pc == 0 || pc == 4) kj = 1.0 / fabs(q);
                else {
                    sj = -expm1(-fabs(q) * (hi - lo));
                    kj = q != 0.0 ? sj / fabs(q) : hi - lo;
                }
                mass = exp(lc + q * (q > 0.0 ? hi : lo)) * kj;
                e = fabs((double)vs[jj] - mass) / mass;
                if (e > worst) worst = e;
                e = fabs(fabs((double)vs[7 + jj]) - kj) / kj;
                if (e > worst) worst = e;
                if ((vs[7 + jj] < 0) != (q > 0.0)) worst = 1.0;
                if (jj >= 1 && jj <= 5) {
                    e = fabs((double)vs[13 + jj] - sj) / (sj > 0.0 ? sj : 1.0);
                    if (e > worst) worst = e;
                }
            }
        }
    printf("    GTR mixture envelope (%d cases): worst relative error %.2e\n", n, worst);
    MFT_CHECK(n > 20, "the envelope cases are in mode 1");
    MFT_CHECK(worst < MFT_TOL(1e-12, 3e-6), "GTR mixture envelope against its definition");
}

/* Every kind's inline front end agrees with the cold dispatch, and a kind
 * unknown to MF__NDF_KINDS is no distribution: 0, and no sample (05_ndf.h). */
static void test_dispatch(void)
{
    mf_ndf k[7], u;
    int i, j, bad = 0;
    k[0] = mf_beckmann(MF_R(0.3), MF_R(0.2)); k[1] = mf_ggx(MF_R(0.3), MF_R(0.2));
    k[2] = mf_gtr(MF_R(0.3), MF_R(2.5)); k[3] = mf_student_t(MF_R(0.3), MF_R(0.2), MF_R(3.0));
    k[4] = mf_leadr_ndf(mf_leadr_with_roughness(mf_leadr_from_slope(MF_R(0.1), MF_R(-0.05)), MF_R(0.3), MF_R(0.2)));
    k[5] = mf_ggx(MF_R(0.5), MF_R(0.5)); k[6] = mf_charlie(MF_R(0.3));
    for (i = 0; i < 7; ++i) {
        if (i == 5) continue;   /* (tabulated: test_tabulated) */
        MFT_CHECK(k[i].type == (i == 6 ? MF_NDF_CHARLIE : i) && mf__ndf_known(k[i].type), "kinds in the order of MF__NDF_KINDS");
        for (j = 0; j < 16; ++j) {
            mf_vec3 w = mft_dir(1.5 * j / 15.0, 0.4 * j);
            mf_real u1 = (mf_real)(0.05 + 0.06 * j), u2 = (mf_real)(0.9 - 0.05 * j);
            if (mf_D(&k[i], w) != mf__ndf_D(&k[i], w) || mf_lambda(&k[i], w) != mf__ndf_lambda(&k[i], w) ||
                !vec_same(mf_sample_D(&k[i], u1, u2), mf__ndf_sample_D(&k[i], u1, u2)) ||
                !vec_same(mf_sample_visible(&k[i], w, u1, u2), mf__ndf_sample_visible(&k[i], w, u1, u2)))
                ++bad;
        }
    }
    MFT_CHECK(bad == 0, "inline front ends and the cold dispatch agree for every kind");
    MFT_CHECK(mf__ndf_tr(MF_NDF_GGX) && !mf__ndf_tr(MF_NDF_STUDENT_T) && mf__ndf_tilted(MF_NDF_LEADR) &&
              !mf__ndf_tilted(MF_NDF_GGX) && mf__ndf_iso(MF_NDF_GTR) == 1 && mf__ndf_iso(MF_NDF_STUDENT_T) == 2 &&
              mf__ndf_iso(MF_NDF_BECKMANN) == 0 &&
              mf__ndf_energy_table(MF_NDF_GGX) == 1 && mf__ndf_energy_table(MF_NDF_BECKMANN) == 2 &&
              !mf__ndf_axes(MF_NDF_LEADR), "the traits of MF__NDF_KINDS");
    MFT_CHECK(mf__ndf_iso(MF_NDF_CHARLIE) == 1 && !mf__ndf_tr(MF_NDF_CHARLIE) && !mf__ndf_tilted(MF_NDF_CHARLIE) &&
              mf__ndf_axes(MF_NDF_CHARLIE) && mf__ndf_energy_table(MF_NDF_CHARLIE) == 0,
              "the traits of Charlie: numerical visible normals of its own D, isotropic");
    for (i = 0; i < 3; ++i) {
        mf_vec3 w = mft_dir(0.6, 0.2), m = mft_dir(0.3, 1.0), s, sv, z;
        mf_real mx = 1, my = 1;
        u = k[i == 2 ? 5 : i];
        u.type = (unsigned char)(i == 0 ? MF_NDF_KIND_COUNT : 99 + i);
        if (i == 1) u = mf_transformed(u, mf_mat2_make(MF_R(1.2), MF_R(0.3), MF_R(0.0), MF_R(0.9)));
        s = mf_sample_D(&u, MF_R(0.4), MF_R(0.7)); sv = mf_sample_visible(&u, w, MF_R(0.4), MF_R(0.7));
        z = mf__sample_visible_smooth(&u, w, MF_R(0.4), MF_R(0.7));
        mf__ndf_mean_slope(&u, &mx, &my);
        MFT_CHECK(!mf__ndf_known(u.type) && mf_D(&u, m) == 0 && mf_lambda(&u, w) == 0 && mf_brdf(&u, w, m) == 0 &&
                  s.x == 0 && s.y == 0 && s.z == 0 && sv.x == 0 && sv.y == 0 && sv.z == 0 && z.z == 0 &&
                  mx == 0 && my == 0 && !mf__ndf_tilted(u.type),
                  "an unknown kind: D, Lambda, BRDF 0 and no sample");
    }
}

void test_ndf(void)
{
    test_ndf_size();
    test_dispatch();
    test_gtr_table();
    test_gtr_envelope();
    test_gtr_sqrt();
    test_lambda_dense();
    test_visible_dense();
    test_values();
    test_smith_forms();
    test_ggx_G2_one_division();
    test_normalization();
    test_masking();
}
