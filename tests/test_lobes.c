/* The lobes of a whole material (issue 42), against references written here
 * in double:
 *  - F82-tint (Hoffman 2023): F(1) = f0, F(0) = 1, F(1/7) = tint *
 *    Schlick(f0, 1/7), F >= 0, and the average of the clamped F against
 *    quadrature over the whole (f0, tint) square (panels split at the sign
 *    changes of the test's own F, so the quadrature is exact to rounding);
 *  - EON: the white furnace, the albedo functions and the BRDF against
 *    quadrature of FON written here, reciprocity, the sampler by chi-square
 *    (lost samples in their own bin), its record, u corners, its variance;
 *  - thin film: the Airy sum against a transfer-matrix (characteristic
 *    matrix) reference in complex double written here, zero thickness, the
 *    RGB form against spectral integration with the CIE tables;
 *  - Charlie sheen: normalization, the exact Lambda against a 2D quadrature
 *    of 1 + Lambda, the published fit's distance to it, NDF sampling; the
 *    kind mf_charlie through the generic operations (mf_D, mf_lambda, mf_G1,
 *    the projected area int D_visible = 1, NDF and visible-normal sampling
 *    by chi-square, u corners, the BRDF sample record, reciprocity, an LTC
 *    fit). */
#include "mf_test.h"
#include <stdlib.h>
#include "tools/cie_1931_d65.h"

/* ---- F82-tint ------------------------------------------------------------ */

/* The defining form: Schlick minus a mu (1 - mu)^6, a chosen so that F(1/7) = tint S(1/7). */
static double ref_schlick(double f0, double mu) { return f0 + (1.0 - f0) * pow(1.0 - mu, 5.0); }
static double ref_f82_raw(double mu, double f0, double tint)
{
    double mb = 1.0 / 7.0;
    double a = ref_schlick(f0, mb) * (1.0 - tint) / (mb * pow(1.0 - mb, 6.0)), x = 1.0 - mu, x2 = x * x;
    return f0 + (1.0 - f0) * x2 * x2 * x - a * mu * x2 * x2 * x2;
}
/* 2 int_0^1 max(F, 0) mu dmu: 64 panels of 8-point Gauss-Legendre, each split
 * at the sign changes of F found on 64 points inside it (bisection); F is a
 * polynomial of degree 7, so each piece is integrated exactly (two roots
 * closer than 1/4096 could hide a negative sliver of area below 1e-10) */
static double ref_f82_average(double f0, double tint)
{
    double x[8], w[8], sum = 0.0;
    int p, i, k, np = 64, ns = 64;
    mft_gl(8, x, w);
    for (p = 0; p < np; ++p) {
        double cut[66];
        int nc = 0;
        cut[nc++] = (double)p / np;
        for (k = 0; k < ns; ++k) {
            double lo = (p + (double)k / ns) / np, hi = (p + (k + 1.0) / ns) / np;
            int slo = ref_f82_raw(lo, f0, tint) < 0.0, j;
            if (slo == (ref_f82_raw(hi, f0, tint) < 0.0)) continue;
            for (j = 0; j < 200 && hi - lo > 1e-17; ++j) {
                double m = 0.5 * (lo + hi);
                if ((ref_f82_raw(m, f0, tint) < 0.0) == slo) lo = m; else hi = m;
            }
            cut[nc++] = 0.5 * (lo + hi);
        }
        cut[nc++] = (p + 1.0) / np;
        for (k = 0; k + 1 < nc; ++k)
            for (i = 0; i < 8; ++i) {
                double mu = cut[k] + (cut[k + 1] - cut[k]) * x[i];
                double f = ref_f82_raw(mu, f0, tint);
                sum += 2.0 * (cut[k + 1] - cut[k]) * w[i] * (f > 0.0 ? f : 0.0) * mu;
            }
    }
    return sum;
}

static void test_f82(void)
{
    double worst_avg = 0.0, worst_f = 0.0, mb = 1.0 / 7.0;
    int i, j, k, bad_id = 0, bad_range = 0, n_neg = 0;
    for (i = 0; i <= 40; ++i)
        for (j = 0; j <= 40; ++j) {
            double f0 = i / 40.0, tint = j / 40.0, want, got;
            /* identities: F(1) = f0, F(0) = 1, F(1/7) = tint * Schlick(f0, 1/7) */
            if (fabs((double)mf_fresnel_f82(MF_R(1.0), (mf_real)f0, (mf_real)tint) - f0) > MFT_TOL(1e-14, 1e-6)) ++bad_id;
            if (fabs((double)mf_fresnel_f82(MF_R(0.0), (mf_real)f0, (mf_real)tint) - 1.0) > MFT_TOL(1e-14, 1e-6)) ++bad_id;
            if (fabs((double)mf_fresnel_f82((mf_real)mb, (mf_real)f0, (mf_real)tint) - tint * ref_schlick(f0, mb))
                > MFT_TOL(1e-13, 2e-6)) ++bad_id;
            /* the clamped F against the defining form */
            for (k = 0; k <= 200; ++k) {
                double mu = k / 200.0, r = ref_f82_raw(mu, f0, tint);
                double g = (double)mf_fresnel_f82((mf_real)mu, (mf_real)f0, (mf_real)tint);
                if (!(g >= 0.0 && g <= 1.0)) ++bad_range;
                if (r < 0.0) { r = 0.0; ++n_neg; }
                if (fabs(g - r) > worst_f) worst_f = fabs(g - r);
            }
            want = ref_f82_average(f0, tint);
            got = (double)mf_fresnel_f82_average((mf_real)f0, (mf_real)tint);
            if (!(fabs(got - want) <= worst_avg)) worst_avg = mft_finite(got) ? fabs(got - want) : 1.0;
        }
    printf("    f82: %d of 41^2 x 201 values of the formula negative; worst |F - ref| %.3g, "
           "worst |average - quadrature| %.3g over the (f0, tint) grid\n", n_neg, worst_f, worst_avg);
    MFT_CHECK(n_neg > 1000, "f82: the formula does go negative on the grid (the clamp is exercised)");
    MFT_CHECK(bad_id == 0, "f82: F(1) = f0, F(0) = 1, F(1/7) = tint Schlick(f0, 1/7)");
    MFT_CHECK(bad_range == 0, "f82: F in [0, 1]");
    MFT_NEAR(worst_f, 0.0, 0.0, MFT_TOL(1e-13, 2e-6), "f82: F = max(formula, 0)");
    MFT_NEAR(worst_avg, 0.0, 0.0, MFT_TOL(1e-12, 1e-6), "f82: average of the clamped F = quadrature, 41^2 grid");
    /* random points off the grid, and the corners where the clamp starts */
    {
        mft_rng r;
        double worst = 0.0;
        mft_seed(&r, 82);
        for (i = 0; i < 2000; ++i) {
            double f0 = mft_u01(&r), tint = mft_u01(&r) * (i & 1 ? 1.0 : 0.1);
            double e = fabs((double)mf_fresnel_f82_average((mf_real)f0, (mf_real)tint) - ref_f82_average(f0, tint));
            if (!(e <= worst)) worst = mft_finite(e) ? e : 1.0;
        }
        MFT_NEAR(worst, 0.0, 0.0, MFT_TOL(1e-12, 1e-6), "f82: average = quadrature, 2000 random (f0, tint)");
    }
    /* tint = 1 is Schlick, whose average is f0 + (1 - f0)/21 */
    MFT_NEAR(mf_fresnel_f82_average(MF_R(0.3), MF_R(1.0)), 0.3 + 0.7 / 21.0, MFT_TOL(1e-14, 1e-6), 0.0, "f82: tint 1 is Schlick's average");
    /* out of the domain: clamps, NaN gives 0 */
    MFT_CHECK(mf_fresnel_f82(MF_R(-0.5), MF_R(0.2), MF_R(0.7)) == mf_fresnel_f82(MF_R(0.5), MF_R(0.2), MF_R(0.7)),
              "f82: |cos| used");
    MFT_CHECK(mf_fresnel_f82(MF_R(0.3), MF_R(2.0), MF_R(-1.0)) == mf_fresnel_f82(MF_R(0.3), MF_R(1.0), MF_R(0.0)),
              "f82: f0 and tint clamped to [0, 1]");
    {
        volatile double z = 0.0;
        mf_real nan_ = (mf_real)(z / z);
        MFT_CHECK(mf_fresnel_f82(nan_, MF_R(0.5), MF_R(0.5)) == 0 && mf_fresnel_f82(MF_R(0.5), nan_, MF_R(0.5)) == 0
                  && mf_fresnel_f82_average(nan_, MF_R(0.5)) == 0 && mf_fresnel_f82_average(MF_R(0.5), nan_) == 0,
                  "f82: NaN gives 0");
    }
}

/* ---- EON ------------------------------------------------------------------ */

typedef double (*hemi_fn)(mf_vec3 wi, void *ctx);
/* int g(wi) dwi over the upper hemisphere, wo in the xz plane at theta_o:
 * theta split at theta_o (FON's max(mu_o, mu_i)), phi at pi/2 (the sign of s),
 * g symmetric in y; panels x 16-point Gauss-Legendre in each piece */
static double hemi_int(hemi_fn g, void *ctx, double theta_o, int panels)
{
    double x[16], w[16], th[3] = { 0.0, theta_o, 1.5707963267948966 }, ph[3] = { 0.0, 1.5707963267948966, 3.141592653589793 };
    double sum = 0.0;
    int a, b, pa, pb, i, j;
    mft_gl(16, x, w);
    for (a = 0; a < 2; ++a) {
        double t0 = th[a], t1 = th[a + 1];
        if (!(t1 > t0)) continue;
        for (b = 0; b < 2; ++b)
            for (pa = 0; pa < panels; ++pa)
                for (pb = 0; pb < panels; ++pb)
                    for (i = 0; i < 16; ++i) {
                        double ht = (t1 - t0) / panels, t = t0 + ht * (pa + x[i]);
                        for (j = 0; j < 16; ++j) {
                            double hp = (ph[b + 1] - ph[b]) / panels, p = ph[b] + hp * (pb + x[j]);
                            mf_vec3 wi = mft_dir(t, p);
                            sum += 2.0 * ht * hp * w[i] * w[j] * sin(t) * g(wi, ctx);
                        }
                    }
    }
    return sum;
}
static double rad(double deg) { return deg * 3.14159265358979323846 / 180.0; }

/* FON single scattering at rho = 1 (Fujii; EON Eq. 3-4), written here */
static double ref_fon(mf_vec3 wo, mf_vec3 wi, double sigma)
{
    double mo = wo.z, mi = wi.z, s = (double)wo.x * wi.x + (double)wo.y * wi.y + (double)wo.z * wi.z - mo * mi;
    double A = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * 3.14159265358979323846)) * sigma), B = sigma * A;
    double t = s > 0.0 ? (mo > mi ? mo : mi) : 1.0;
    if (!(mo > 0.0) || !(mi > 0.0)) return 0.0;
    return (A + B * s / t) / 3.14159265358979323846;
}
typedef struct { mf_vec3 wo; double rho, sigma; int what; } eon_ctx;
static double eon_g(mf_vec3 wi, void *p)
{
    const eon_ctx *c = (const eon_ctx *)p;
    double f;
    switch (c->what) {
    case 0: return ref_fon(c->wo, wi, c->sigma) * wi.z;                                   /* E_F */
    case 1: return (double)mf_eon_brdf(c->wo, wi, (mf_real)c->rho, (mf_real)c->sigma) * wi.z;   /* E */
    case 3: f = (double)mf_eon_brdf(c->wo, wi, MF_R(1.0), (mf_real)c->sigma) * wi.z;       /* second moment */
            return f > 0.0 ? f * f / (double)mf_eon_pdf(c->wo, wi, (mf_real)c->sigma) : 0.0;
    default: f = (double)mf_eon_brdf(c->wo, wi, MF_R(1.0), (mf_real)c->sigma);            /* same, cosine pdf */
             return f * f * wi.z * 3.14159265358979323846;
    }
}
/* FON's directional albedo by quadrature (independent of the closed form) */
static double ref_ef(double mu, double sigma)
{
    eon_ctx c;
    c.wo = mf_vec3_make((mf_real)sqrt(1.0 - mu * mu), MF_R(0.0), (mf_real)mu);
    c.sigma = sigma; c.rho = 1.0; c.what = 0;
    return hemi_int(eon_g, &c, acos(mu), 2);
}
static double ref_ef_avg(double sigma)
{
    double x[16], w[16], sum = 0.0;
    int p, i;
    mft_gl(16, x, w);
    for (p = 0; p < 4; ++p)
        for (i = 0; i < 16; ++i) {
            double mu = (p + x[i]) / 4.0;
            sum += 2.0 * mu * ref_ef(mu, sigma) * w[i] / 4.0;
        }
    return sum;
}

static void test_eon_eval(void)
{
    static const double sig[6] = { 0.0, 0.05, 0.25, 0.5, 0.75, 1.0 };
    static const double th[9] = { 0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.99 };
    static const double rhos[3] = { 1.0, 0.8, 0.3 };
    double worst_furnace = 0.0, worst_alb = 0.0, worst_f = 0.0, worst_ef = 0.0, worst_avg = 0.0, worst_rec = 0.0;
    int i, j, k;
    mft_rng r;
    /* white furnace and albedo: quadrature of mf_eon_brdf cos against 1 and mf_eon_albedo */
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 9; ++j)
            for (k = 0; k < 3; ++k) {
                eon_ctx c;
                double e, a;
                c.wo = mft_dir(rad(th[j]), 0.0); c.rho = rhos[k]; c.sigma = sig[i]; c.what = 1;
                e = hemi_int(eon_g, &c, rad(th[j]), 4);
                a = (double)mf_eon_albedo(c.wo.z, (mf_real)rhos[k], (mf_real)sig[i]);
                if (k == 0 && !(fabs(e - 1.0) <= worst_furnace)) worst_furnace = mft_finite(e) ? fabs(e - 1.0) : 1.0;
                if (!(fabs(e - a) <= worst_alb)) worst_alb = mft_finite(a) ? fabs(e - a) : 1.0;
            }
    /* the closed-form FON albedo against quadrature of FON, and its average */
    for (i = 0; i < 6; ++i) {
        double avg_q = ref_ef_avg(sig[i]), avg_c = 0.0, x[16], w[16];
        int p;
        mft_gl(16, x, w);
        for (j = 0; j < 9; ++j) {
            double mu = cos(rad(th[j])), ef = ref_ef(mu, sig[i]);
            /* E_F from mf_eon_albedo at rho = 1/2 ... through E = rho E_F + rho_ms (1 - E_F) */
            double rho = 0.5, A = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * 3.14159265358979323846)) * sig[i]);
            double eavg = avg_q, rms = rho * rho * eavg / (1.0 - rho * (1.0 - eavg));
            double want = rho * ef + rms * (1.0 - ef);
            double got = (double)mf_eon_albedo((mf_real)mu, (mf_real)rho, (mf_real)sig[i]);
            (void)A;
            if (!(fabs(got - want) <= worst_ef)) worst_ef = mft_finite(got) ? fabs(got - want) : 1.0;
        }
        /* mf_eon_albedo_average against 2 int E mu dmu of mf_eon_albedo */
        for (k = 1; k < 3; ++k) {
            avg_c = 0.0;
            for (p = 0; p < 8; ++p)
                for (j = 0; j < 16; ++j) {
                    double mu = (p + x[j]) / 8.0;
                    avg_c += 2.0 * mu * (double)mf_eon_albedo((mf_real)mu, (mf_real)rhos[k], (mf_real)sig[i]) * w[j] / 8.0;
                }
            if (!(fabs(avg_c - (double)mf_eon_albedo_average((mf_real)rhos[k], (mf_real)sig[i])) <= worst_avg))
                worst_avg = fabs(avg_c - (double)mf_eon_albedo_average((mf_real)rhos[k], (mf_real)sig[i]));
        }
        /* mf_eon_brdf pointwise against the paper's definition built on the quadrature E_F */
        mft_seed(&r, 100 + i);
        for (k = 0; k < 12; ++k) {
            mf_vec3 wo = mft_dir(acos(mft_u01(&r)), 0.0), wi = mft_dir(acos(mft_u01(&r)), 6.283185307179586 * mft_u01(&r));
            double rho = mft_u01(&r), efo = ref_ef(wo.z, sig[i]), efi = ref_ef(wi.z, sig[i]);
            double rms = rho * rho * avg_q / (1.0 - rho * (1.0 - avg_q));
            double want = rho * ref_fon(wo, wi, sig[i])
                        + (sig[i] > 0.0 ? rms / 3.14159265358979323846 * (1.0 - efo) * (1.0 - efi) / (1.0 - avg_q) : 0.0);
            double got = (double)mf_eon_brdf(wo, wi, (mf_real)rho, (mf_real)sig[i]);
            if (!(fabs(got - want) <= worst_f * want)) worst_f = mft_finite(got) ? fabs(got - want) / want : 1.0;
            /* reciprocity */
            got = fabs((double)mf_eon_brdf(wi, wo, (mf_real)rho, (mf_real)sig[i]) - got) / want;
            if (!(got <= worst_rec)) worst_rec = mft_finite(got) ? got : 1.0;
        }
    }
    printf("    eon: |furnace - 1| %.3g, |quadrature - mf_eon_albedo| %.3g (6 sigma x 9 views x 3 rho); "
           "albedo vs quadrature E_F %.3g, average %.3g; f vs definition (rel) %.3g, reciprocity %.3g\n",
           worst_furnace, worst_alb, worst_ef, worst_avg, worst_f, worst_rec);
    MFT_NEAR(worst_furnace, 0.0, 0.0, 1e-3, "eon: white furnace (rho 1) = 1 within 1e-3, sigma in [0, 1], views to 89.99 deg");
    MFT_NEAR(worst_furnace, 0.0, 0.0, MFT_TOL(1e-9, 2e-6), "eon: white furnace, to the quadrature's accuracy");
    MFT_NEAR(worst_alb, 0.0, 0.0, MFT_TOL(1e-9, 2e-6), "eon: mf_eon_albedo = quadrature of f cos");
    MFT_NEAR(worst_ef, 0.0, 0.0, MFT_TOL(1e-9, 2e-6), "eon: closed-form E_F and E_F_avg = quadrature of FON");
    MFT_NEAR(worst_avg, 0.0, 0.0, MFT_TOL(1e-9, 2e-6), "eon: mf_eon_albedo_average = 2 int E mu dmu");
    MFT_NEAR(worst_f, 0.0, 0.0, MFT_TOL(1e-8, 2e-6), "eon: f = FON + the multiple-scattering lobe of quadrature E_F (relative)");
    MFT_NEAR(worst_rec, 0.0, 0.0, MFT_TOL(1e-14, 1e-6), "eon: reciprocity f(wo, wi) = f(wi, wo)");
    /* sigma = 0 is Lambert */
    MFT_NEAR(mf_eon_brdf(mft_dir(0.3, 0.0), mft_dir(1.2, 2.0), MF_R(0.7), MF_R(0.0)), 0.7 / 3.14159265358979323846,
             MFT_TOL(1e-15, 1e-7), 0.0, "eon: sigma 0 is Lambert rho/pi");
    /* the fast albedo: its largest distance to the exact one over mu, sigma, rho in [0, 1] */
    {
        double worst = 0.0, wmu = 0, ws = 0, wr = 0;
        for (i = 0; i <= 1000; ++i)
            for (j = 0; j <= 50; ++j)
                for (k = 0; k <= 10; ++k) {
                    double mu = i / 1000.0, sg = j / 50.0, rho = k / 10.0;
                    double e = fabs((double)mf_eon_albedo_fast((mf_real)mu, (mf_real)rho, (mf_real)sg)
                                    - (double)mf_eon_albedo((mf_real)mu, (mf_real)rho, (mf_real)sg));
                    if (!(e <= worst)) { worst = mft_finite(e) ? e : 1.0; wmu = mu; ws = sg; wr = rho; }
                }
        printf("    eon: fast albedo within %.3g of the exact one (worst at mu %g, sigma %g, rho %g)\n", worst, wmu, ws, wr);
        MFT_NEAR(worst, 0.0, 0.0, 1.5e-4, "eon: mf_eon_albedo_fast within 1.5e-4 of mf_eon_albedo");
    }
    /* out of the domain */
    MFT_CHECK(mf_eon_brdf(mft_dir(0.3, 0.0), mf_vec3_make(0, 0, -1), 1, 1) == 0 && mf_eon_brdf(mf_vec3_make(0, 0, -1), mft_dir(0.3, 0.0), 1, 1) == 0
              && mf_eon_pdf(mft_dir(0.3, 0.0), mf_vec3_make(0, 0, -1), 1) == 0 && mf_eon_albedo(MF_R(-0.5), 1, 1) == 0
              && mf_eon_sample(mf_vec3_make(0, 0, -1), 1, 1, MF_R(0.5), MF_R(0.5)).lobe == MF_LOBE_NONE,
              "eon: below the horizon gives 0 / no sample");
}

#define EA 16
#define EP 32
/* probability of each (z ring, phi sector) cell under the pdf, 4 x 4 sub-cells of 8 x 8 nodes */
static void eon_cell_probs(mf_vec3 wo, double sigma, double *prob)
{
    double x[8], w[8];
    int a, p, sa, sp, i, j;
    mft_gl(8, x, w);
    for (a = 0; a < EA; ++a)
        for (p = 0; p < EP; ++p) {
            double sum = 0.0;
            for (sa = 0; sa < 4; ++sa)
                for (sp = 0; sp < 4; ++sp)
                    for (i = 0; i < 8; ++i)
                        for (j = 0; j < 8; ++j) {
                            double z = (a + (sa + x[i]) / 4.0) / EA, ph = 6.283185307179586 * (p + (sp + x[j]) / 4.0) / EP;
                            double st = sqrt(1.0 - z * z);
                            mf_vec3 wi = mf_vec3_make((mf_real)(st * cos(ph)), (mf_real)(st * sin(ph)), (mf_real)z);
                            sum += w[i] * w[j] * (double)mf_eon_pdf(wo, wi, (mf_real)sigma);
                        }
            prob[a * EP + p] = sum / 16.0 * (1.0 / EA) * (6.283185307179586 / EP);
        }
}
static int eon_cell_of(mf_vec3 wi)
{
    double ph = atan2((double)wi.y, (double)wi.x);
    int a = (int)((double)wi.z * EA), p;
    if (ph < 0.0) ph += 6.283185307179586;
    p = (int)(ph / 6.283185307179586 * EP);
    if (a < 0) a = 0;
    if (a >= EA) a = EA - 1;
    if (p >= EP) p = EP - 1;
    return a * EP + p;
}

static void test_eon_sample(void)
{
    static const double sig[4] = { 0.0, 0.3, 0.7, 1.0 };
    static const double th[6] = { 0.0, 30.0, 60.0, 80.0, 88.0, 89.99 };
    static double obs[EA * EP + 1], ex[EA * EP + 1];
    double worst_z = 0.0, worst_pdf = 0.0, worst_w = 0.0, worst_int = 0.0;
    int i, j, k, n = 100000, bad = 0;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 6; ++j) {
            mf_vec3 wo = mft_dir(rad(th[j]), 0.7 * j);
            double tot = 0.0, z;
            int dof;
            mft_rng r;
            eon_cell_probs(wo, sig[i], ex);
            for (k = 0; k < EA * EP; ++k) { tot += ex[k]; ex[k] *= n; obs[k] = 0.0; }
            z = fabs(tot - 1.0);
            if (!(z <= worst_int)) worst_int = mft_finite(z) ? z : 1.0;
            ex[EA * EP] = n * (tot < 1.0 ? 1.0 - tot : 0.0);
            obs[EA * EP] = 0.0;
            mft_seed(&r, 4200 + 10 * i + j);
            for (k = 0; k < n; ++k) {
                double rho = mft_u01(&r);
                mf_sample s = mf_eon_sample(wo, (mf_real)rho, (mf_real)sig[i], (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                double pdf, f, e;
                if (s.lobe == MF_LOBE_NONE) { obs[EA * EP] += 1.0; continue; }
                if (!(s.wi.z > 0) || !(s.pdf > 0) || s.lobe != MF_LOBE_REFLECTION) { ++bad; continue; }
                obs[eon_cell_of(s.wi)] += 1.0;
                pdf = (double)mf_eon_pdf(wo, s.wi, (mf_real)sig[i]);
                e = fabs((double)s.pdf - pdf) / pdf;
                if (!(e <= worst_pdf)) worst_pdf = mft_finite(e) ? e : 1.0;
                f = (double)mf_eon_brdf(wo, s.wi, (mf_real)rho, (mf_real)sig[i]) * s.wi.z / pdf;
                e = fabs((double)s.weight - f) / (f > 1e-30 ? f : 1e-30);
                if (!(e <= worst_w)) worst_w = mft_finite(e) ? e : 1.0;
            }
            z = mft_chi2(obs, ex, EA * EP + 1, &dof);
            if (!(fabs(z) <= worst_z)) worst_z = mft_finite(z) ? fabs(z) : 1e9;
        }
    printf("    eon sampling: worst |chi-square z| %.2f (4 sigma x 6 views, 1e5 samples, 513 bins with the lost one); "
           "|int pdf - 1| %.3g; record pdf vs mf_eon_pdf %.3g, weight vs f cos / pdf %.3g (relative)\n",
           worst_z, worst_int, worst_pdf, worst_w);
    MFT_CHECK(bad == 0, "eon sampling: every sample above the horizon with pdf > 0");
    MFT_CHECK(worst_z < 4.5, "eon sampling: chi-square of the samples against mf_eon_pdf (|z| < 4.5, 24 cases)");
    MFT_NEAR(worst_int, 0.0, 0.0, MFT_TOL(1e-6, 1e-5), "eon sampling: mf_eon_pdf integrates to 1 (nothing lost)");
    MFT_NEAR(worst_pdf, 0.0, 0.0, MFT_TOL(1e-9, 1e-3), "eon sampling: record pdf = mf_eon_pdf");
    MFT_NEAR(worst_w, 0.0, 0.0, MFT_TOL(1e-9, 1e-3), "eon sampling: weight = f cos / pdf");
    /* u corners give valid samples */
    {
        static const double us[5] = { 0.0, 5.9604644775390625e-08, 0.5, 1.0 - 5.9604644775390625e-08, 1.0 };
        static const double ths[4] = { 0.0, 45.0, 89.0, 89.99 };
        static const double sg[3] = { 0.0, 0.5, 1.0 };
        int a, b, bad_c = 0;
        double worst_c = 0.0;
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 3; ++j)
                for (a = 0; a < 5; ++a)
                    for (b = 0; b < 5; ++b) {
                        mf_vec3 wo = mft_dir(rad(ths[i]), 1.0);
                        mf_sample s = mf_eon_sample(wo, MF_R(0.8), (mf_real)sg[j], (mf_real)us[a], (mf_real)us[b]);
                        double len = sqrt((double)mf_dot(s.wi, s.wi)), pdf = (double)mf_eon_pdf(wo, s.wi, (mf_real)sg[j]);
                        if (s.lobe != MF_LOBE_REFLECTION || !(s.wi.z > 0) || !(s.pdf > 0) || !(s.pdf < MF_BIG)
                            || !(s.weight >= 0) || !(s.weight < MF_BIG) || fabs(len - 1.0) > 1e-5 || !(pdf > 0)) {
                            ++bad_c;
                            printf("    eon corner: theta %g sigma %g u (%g, %g): lobe %d wi.z %g pdf %g weight %g\n",
                                   ths[i], sg[j], us[a], us[b], s.lobe, (double)s.wi.z, (double)s.pdf, (double)s.weight);
                            continue;
                        }
                        if (!(fabs(s.pdf - pdf) / pdf <= worst_c)) worst_c = fabs(s.pdf - pdf) / pdf;
                    }
        printf("    eon corners: record pdf vs mf_eon_pdf at u in {0, 2^-24, 1/2, 1 - 2^-24, 1}^2: %.3g (relative)\n", worst_c);
        MFT_CHECK(bad_c == 0, "eon sampling: u corners give a valid sample (views to 89.99 deg, sigma 0, 1/2, 1)");
        MFT_NEAR(worst_c, 0.0, 0.0, MFT_TOL(1e-6, 1e-2), "eon sampling: corners' record pdf = mf_eon_pdf");
    }
    /* the variance of the albedo estimate (rho = 1, sigma = 1) against cosine sampling */
    {
        static const double tv[6] = { 0.0, 30.0, 60.0, 75.0, 85.0, 89.0 };
        double worse = 0.0;
        printf("    eon variance at sigma 1 (rho 1), clipped LTC / cosine:");
        for (j = 0; j < 6; ++j) {
            eon_ctx c;
            double v1, v2;
            c.wo = mft_dir(rad(tv[j]), 0.0); c.sigma = 1.0; c.rho = 1.0;
            c.what = 3; v1 = hemi_int(eon_g, &c, rad(tv[j]), 4) - 1.0;
            c.what = 4; v2 = hemi_int(eon_g, &c, rad(tv[j]), 4) - 1.0;
            printf(" %g deg %.3g/%.3g;", tv[j], v1, v2);
            if (v1 / v2 > worse) worse = v1 / v2;
        }
        printf("\n");
        MFT_CHECK(worse < 1.0, "eon sampling: lower variance than cosine sampling at sigma 1, every view");
    }
}


/* ---- thin film -------------------------------------------------------------- */

typedef struct { double re, im; } tcx;
static tcx tc(double re, double im) { tcx z; z.re = re; z.im = im; return z; }
static tcx tadd(tcx a, tcx b) { return tc(a.re + b.re, a.im + b.im); }
static tcx tsub(tcx a, tcx b) { return tc(a.re - b.re, a.im - b.im); }
static tcx tmul(tcx a, tcx b) { return tc(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
static tcx tdiv(tcx a, tcx b)
{
    double d = b.re * b.re + b.im * b.im;
    return tc((a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d);
}
/* polar form, angle in (-pi, pi]: Re >= 0, Im >= 0 for Im(a) >= 0 */
static tcx tsqrt(tcx a)
{
    double r = sqrt(sqrt(a.re * a.re + a.im * a.im)), t = 0.5 * atan2(a.im, a.re);
    return tc(r * cos(t), r * sin(t));
}
static tcx tcos(tcx z) { return tc(cos(z.re) * cosh(z.im), -sin(z.re) * sinh(z.im)); }
static tcx tsin(tcx z) { return tc(sin(z.re) * cosh(z.im), cos(z.re) * sinh(z.im)); }
/* Characteristic-matrix reflectance of one film (Born & Wolf 1.6.2-1.6.3, time
 * factor e^{-i omega t}, N = n + i k absorbing for k > 0): tilted admittances
 * eta_j = N_j cos theta_j (s) or N_j / cos theta_j (p),
 * [B; C] = [cos b, -i sin b / eta2; -i eta2 sin b, cos b] [1; eta3],
 * b = 2 pi d N2 cos theta2 / lambda, r = (eta1 B - C) / (eta1 B + C). */
static double ref_tmm(double c1, double n1, double n2, double d, double n3r, double n3i, double lambda)
{
    double s2 = n1 * n1 * (1.0 - c1 * c1), R = 0.0;
    tcx N1 = tc(n1, 0.0), N2 = tc(n2, 0.0), N3 = tc(n3r, n3i);
    tcx Q1 = tc(n1 * c1, 0.0), Q2 = tsqrt(tsub(tmul(N2, N2), tc(s2, 0.0))), Q3 = tsqrt(tsub(tmul(N3, N3), tc(s2, 0.0)));
    tcx b = tmul(tc(2.0 * 3.14159265358979323846 * d / lambda, 0.0), Q2), i1 = tc(0.0, -1.0);
    int p;
    for (p = 0; p < 2; ++p) {
        tcx e1 = p ? tdiv(tmul(N1, N1), Q1) : Q1, e2 = p ? tdiv(tmul(N2, N2), Q2) : Q2, e3 = p ? tdiv(tmul(N3, N3), Q3) : Q3;
        tcx cb = tcos(b), sb = tsin(b);
        tcx B = tadd(cb, tmul(tdiv(tmul(i1, sb), e2), e3));
        tcx C = tadd(tmul(tmul(i1, e2), sb), tmul(cb, e3));
        tcx r = tdiv(tsub(tmul(e1, B), C), tadd(tmul(e1, B), C));
        R += 0.5 * (r.re * r.re + r.im * r.im);
    }
    return R;
}

typedef struct { const char *name; double n1, n2, n3, k3; } tf_case;
static const tf_case tf_cases[] = {
    { "soap bubble", 1.0, 1.33, 1.0, 0.0 },
    { "oil on water", 1.0, 1.47, 1.33, 0.0 },
    { "TiO2 on glass", 1.0, 2.4, 1.5, 0.0 },
    { "oxide on gold", 1.0, 1.5, 0.18, 3.4 },
    { "oxide on aluminium", 1.0, 1.6, 1.2, 7.0 },
    { "film on copper, under water", 1.33, 1.45, 0.6, 2.6 },
    { "film over air, under glass (base TIR)", 1.5, 1.7, 1.0, 0.0 },
    { "low film over metal", 1.0, 1.2, 2.5, 0.5 },
};
#define TF_NCASES ((int)(sizeof(tf_cases) / sizeof(tf_cases[0])))

/* linear sRGB of the film by spectral integration, int R s_c / int s_c over
 * 380-780 nm in 0.5 nm trapezoids, s_c = M (x, y, z) D65 (tables interpolated
 * linearly), R from the characteristic matrix */
static void ref_tf_rgb(double c1, double n1, double n2, double d, double n3, double k3, double rgb[3])
{
    double num[3] = { 0, 0, 0 }, den[3] = { 0, 0, 0 };
    int i, c, n = 800;
    for (i = 0; i <= n; ++i) {
        double l = 380.0 + 400.0 * i / n, f = (l - 380.0) / 5.0, wt = (i == 0 || i == n) ? 0.5 : 1.0, xyz[3], R;
        int j = (int)f;
        if (j >= MF_CIE_N - 1) j = MF_CIE_N - 2;
        f -= j;
        xyz[0] = (mf_cie_x[j] * (1 - f) + mf_cie_x[j + 1] * f);
        xyz[1] = (mf_cie_y[j] * (1 - f) + mf_cie_y[j + 1] * f);
        xyz[2] = (mf_cie_z[j] * (1 - f) + mf_cie_z[j + 1] * f);
        wt *= mf_cie_d65[j] * (1 - f) + mf_cie_d65[j + 1] * f;
        R = ref_tmm(c1, n1, n2, d, n3, k3, l);
        for (c = 0; c < 3; ++c) {
            double sc = wt * (mf_xyz_to_srgb[c][0] * xyz[0] + mf_xyz_to_srgb[c][1] * xyz[1] + mf_xyz_to_srgb[c][2] * xyz[2]);
            num[c] += R * sc;
            den[c] += sc;
        }
    }
    /* clipped to [0, 1] as the library does (saturated interference colours
     * lie outside the sRGB gamut: negative components) */
    for (c = 0; c < 3; ++c) rgb[c] = num[c] / den[c] < 0.0 ? 0.0 : num[c] / den[c] > 1.0 ? 1.0 : num[c] / den[c];
}

static void test_thin_film(void)
{
    static const double thick[12] = { 0.0, 10.0, 50.0, 100.0, 200.0, 300.0, 400.0, 550.0, 700.0, 1000.0, 1500.0, 2000.0 };
    static const double ang[6] = { 0.0, 30.0, 50.0, 70.0, 80.0, 89.0 };
    double worst = 0.0, worst0 = 0.0, worst0_rgb = 0.0, worst_rgb = 0.0, worst_tir = 0.0, worst_flat = 0.0;
    const char *wname = "", *wrgb = "";
    double wd = 0, wa = 0;
    int i, j, k, l;
    /* the Airy sum against the characteristic matrix, every case, thickness, angle, wavelength */
    for (i = 0; i < TF_NCASES; ++i)
        for (j = 0; j < 12; ++j)
            for (k = 0; k < 6; ++k)
                for (l = 0; l <= 8; ++l) {
                    const tf_case *t = &tf_cases[i];
                    double c1 = cos(rad(ang[k])), lam = 380.0 + 50.0 * l;
                    double want = ref_tmm(c1, t->n1, t->n2, thick[j], t->n3, t->k3, lam);
                    double got = (double)mf_fresnel_thin_film((mf_real)c1, (mf_real)t->n1, (mf_real)t->n2, (mf_real)thick[j],
                                                              (mf_real)t->n3, (mf_real)t->k3, (mf_real)lam);
                    if (!(fabs(got - want) <= worst)) { worst = mft_finite(got) ? fabs(got - want) : 1.0; wname = t->name; }
                }
    /* zero thickness: the bare base, against the library's conductor and dielectric Fresnel */
    for (i = 0; i < TF_NCASES; ++i)
        for (k = 0; k < 6; ++k) {
            const tf_case *t = &tf_cases[i];
            double c1 = cos(rad(ang[k]));
            double base = t->k3 > 0.0 ? (double)mf_fresnel_conductor((mf_real)c1, (mf_real)(t->n3 / t->n1), (mf_real)(t->k3 / t->n1))
                                      : (double)mf_fresnel_dielectric((mf_real)c1, (mf_real)(t->n3 / t->n1));
            double got = (double)mf_fresnel_thin_film((mf_real)c1, (mf_real)t->n1, (mf_real)t->n2, MF_R(0.0), (mf_real)t->n3,
                                                      (mf_real)t->k3, MF_R(550.0));
            mf_real eb[3], kb[3], rgb[3];
            if (!(fabs(got - base) <= worst0)) worst0 = mft_finite(got) ? fabs(got - base) : 1.0;
            eb[0] = eb[1] = eb[2] = (mf_real)t->n3; kb[0] = kb[1] = kb[2] = (mf_real)t->k3;
            mf_fresnel_thin_film_rgb((mf_real)c1, (mf_real)t->n1, (mf_real)t->n2, MF_R(0.0), eb, kb, rgb);
            for (l = 0; l < 3; ++l)
                if (!(fabs((double)rgb[l] - base) <= worst0_rgb)) worst0_rgb = mft_finite((double)rgb[l]) ? fabs((double)rgb[l] - base) : 1.0;
            /* a film of the outside's index is no film: a flat spectrum, (R, R, R) at any thickness */
            mf_fresnel_thin_film_rgb((mf_real)c1, (mf_real)t->n1, (mf_real)t->n1, MF_R(420.0), eb, kb, rgb);
            for (l = 0; l < 3; ++l)
                if (!(fabs((double)rgb[l] - base) <= worst_flat)) worst_flat = mft_finite((double)rgb[l]) ? fabs((double)rgb[l] - base) : 1.0;
        }
    /* the RGB form against spectral integration of the exact reflectance */
    for (i = 0; i < TF_NCASES; ++i)
        for (j = 0; j < 12; ++j)
            for (k = 0; k < 5; ++k) {
                const tf_case *t = &tf_cases[i];
                double c1 = cos(rad(ang[k])), want[3], e;
                mf_real eb[3], kb[3], rgb[3];
                int tir = t->n1 * t->n1 * (1.0 - c1 * c1) >= t->n2 * t->n2;
                eb[0] = eb[1] = eb[2] = (mf_real)t->n3; kb[0] = kb[1] = kb[2] = (mf_real)t->k3;
                ref_tf_rgb(c1, t->n1, t->n2, thick[j], t->n3, t->k3, want);
                mf_fresnel_thin_film_rgb((mf_real)c1, (mf_real)t->n1, (mf_real)t->n2, (mf_real)thick[j], eb, kb, rgb);
                for (l = 0; l < 3; ++l) {
                    e = mft_finite((double)rgb[l]) ? fabs((double)rgb[l] - want[l]) : 1.0;
                    if (tir) { if (!(e <= worst_tir)) worst_tir = e; }
                    else if (!(e <= worst_rgb)) { worst_rgb = e; wrgb = t->name; wd = thick[j]; wa = ang[k]; }
                }
            }
    /* total internal reflection in the film: glass over an air gap over glass (frustrated TIR) */
    for (j = 0; j < 12; ++j)
        for (k = 0; k < 3; ++k) {
            static const double tang[3] = { 45.0, 60.0, 80.0 };
            double c1 = cos(rad(tang[k])), want[3], e;
            mf_real eb[3] = { MF_R(1.5), MF_R(1.5), MF_R(1.5) }, kb[3] = { 0, 0, 0 }, rgb[3];
            ref_tf_rgb(c1, 1.5, 1.0, thick[j], 1.5, 0.0, want);
            mf_fresnel_thin_film_rgb((mf_real)c1, MF_R(1.5), MF_R(1.0), (mf_real)thick[j], eb, kb, rgb);
            for (l = 0; l < 3; ++l) {
                e = mft_finite((double)rgb[l]) ? fabs((double)rgb[l] - want[l]) : 1.0;
                if (!(e <= worst_tir)) worst_tir = e;
            }
            /* the per-wavelength value against the reference (the TMM's evanescent film) */
            e = fabs((double)mf_fresnel_thin_film((mf_real)c1, MF_R(1.5), MF_R(1.0), (mf_real)thick[j], MF_R(1.5), MF_R(0.0), MF_R(500.0))
                     - ref_tmm(c1, 1.5, 1.0, thick[j], 1.5, 0.0, 500.0));
            if (!(e <= worst)) { worst = e; wname = "glass / air gap / glass (TIR)"; }
        }
    printf("    thin film: Airy vs characteristic matrix %.3g (worst: %s); zero thickness vs bare Fresnel %.3g; "
           "(rgb %.3g); index-matched film flat %.3g\n", worst, wname, worst0, worst0_rgb, worst_flat);
    printf("    thin film rgb vs spectral integration (CIE 1931 x D65 -> linear sRGB): %.3g (worst: %s, %g nm, %g deg); "
           "under TIR in the film %.3g\n", worst_rgb, wrgb, wd, wa, worst_tir);
    /* float: the phase delta reaches 90 rad at 2000 nm, rounded to about 90 x 6e-8 */
    MFT_NEAR(worst, 0.0, 0.0, MFT_TOL(1e-12, 5e-5), "thin film: Airy sum = characteristic matrix (8 stacks, 12 thicknesses, 6 angles, 9 wavelengths)");
    MFT_NEAR(worst0, 0.0, 0.0, MFT_TOL(1e-12, 2e-6), "thin film: zero thickness = the base's Fresnel");
    MFT_NEAR(worst0_rgb, 0.0, 0.0, MFT_TOL(2e-7, 2e-6), "thin film rgb: zero thickness = the base's Fresnel (the series' remainder below 1e-7)");
    MFT_NEAR(worst_flat, 0.0, 0.0, MFT_TOL(1e-12, 2e-6), "thin film rgb: a flat reflectance R gives (R, R, R)");
    MFT_NEAR(worst_rgb, 0.0, 0.0, 2e-3, "thin film rgb: within 2e-3 of spectral integration (8 stacks, 0-2000 nm, 0-80 deg)");
    MFT_NEAR(worst_tir, 0.0, 0.0, 5e-3, "thin film rgb: under TIR in the film within 5e-3 of spectral integration");
    {
        mf_real eb[3] = { 1, 1, 1 }, kb[3] = { 0, 0, 0 }, rgb[3] = { 5, 5, 5 };
        volatile double zz = 0.0;
        mf_real nan_ = (mf_real)(zz / zz);
        mf_fresnel_thin_film_rgb(MF_R(0.5), MF_R(-1.0), MF_R(1.3), MF_R(100.0), eb, kb, rgb);
        MFT_CHECK(rgb[0] == 0 && rgb[1] == 0 && rgb[2] == 0 && mf_fresnel_thin_film(nan_, 1, 1.3f, 100, 1.5f, 0, 500) == 0
                  && mf_fresnel_thin_film(MF_R(0.5), 1, MF_R(1.3), 100, MF_R(1.5), MF_R(-1.0), 500) == 0
                  && mf_fresnel_thin_film(MF_R(0.5), 1, MF_R(1.3), 100, MF_R(1.5), 0, 0) == 0,
                  "thin film: invalid input gives 0");
    }
}

/* ---- Charlie sheen -------------------------------------------------------- */

/* 1 + Lambda = (1/mu) int D(m) <w.m> dm, by 2D quadrature over m = (theta_m,
 * phi) written here: t = m.z in [s, 1] (w sees every azimuth: GL in t and a
 * 32-point rule in phi over [0, pi]) and t in [0, s] with t = s (1 - u^2)
 * (GL in u), phi over [0, phi0(t)] where w.m > 0 (GL in phi): the kinks on
 * panel edges, D as the paper's formula */
static double ref_charlie_onep(double alpha, double mu)
{
    double k = 1.0 / alpha, c = (2.0 + k) / (2.0 * 3.14159265358979323846), s = sqrt(1.0 - mu * mu);
    double x[16], w[16], sum = 0.0;
    int P = 48, p, i, j;
    mft_gl(16, x, w);
    if (!(s > 0.0)) return 1.0;
    for (p = 0; p < P; ++p)
        for (i = 0; i < 16; ++i) {
            /* upper part: t in [s, 1] */
            double t = s + (1.0 - s) * (p + x[i]) / P, st = sqrt(1.0 - t * t), D = c * pow(st, k), in = 0.0;
            for (j = 0; j < 16; ++j) {
                double ph = 3.14159265358979323846 * x[j];
                in += w[j] * 3.14159265358979323846 * (s * st * cos(ph) + mu * t);
            }
            sum += 2.0 * (1.0 - s) / P * w[i] * D * in;
            /* lower part: t = s (1 - u^2), dt = 2 s u du */
            {
                double u = (p + x[i]) / P, tl = s * (1.0 - u * u), sl = sqrt(1.0 - tl * tl), Dl = c * pow(sl, k), in2 = 0.0;
                double cphi = -mu * tl / (s * sl), ph0 = acos(cphi < -1.0 ? -1.0 : cphi > 1.0 ? 1.0 : cphi);
                for (j = 0; j < 16; ++j) {
                    double ph = ph0 * x[j];
                    in2 += w[j] * ph0 * (s * sl * cos(ph) + mu * tl);
                }
                sum += 2.0 * 2.0 * s * u / P * w[i] * Dl * in2;
            }
        }
    return sum / mu;
}

static void test_charlie(void)
{
    static const double al[10] = { 1.0, 0.7, 0.5, 0.3, 0.15, 0.07, 0.03, 0.01, 0.003, 0.001 };
    static const double th[10] = { 0.0, 10.0, 30.0, 45.0, 60.0, 70.0, 80.0, 85.0, 89.0, 89.99 };
    double worst = 0.0, wa = 0, wt = 0, worst_norm = 0.0, fit_l = 0.0, fit_g = 0.0, fl_a = 0, fl_m = 0, fg_a = 0, fg_m = 0;
    double fit_ga = 0.0, fa_a = 0, fa_m = 0;
    int i, j, k;
    for (i = 0; i < 10; ++i) {
        /* normalization int D m.z dm = 1 (t = m.z, 1024 panels of 16 nodes: D is
         * as narrow as 1/sqrt(1000) in t) */
        double x[16], w[16], nsum = 0.0;
        int p;
        mft_gl(16, x, w);
        for (p = 0; p < 1024; ++p)
            for (k = 0; k < 16; ++k) {
                double t = (p + x[k]) / 1024.0;
                mf_vec3 m = mf_vec3_make((mf_real)sqrt(1.0 - t * t), MF_R(0.0), (mf_real)t);
                nsum += 2.0 * 3.14159265358979323846 * w[k] / 1024.0 * (double)mf_charlie_D((mf_real)al[i], m) * t;
            }
        if (!(fabs(nsum - 1.0) <= worst_norm)) worst_norm = mft_finite(nsum) ? fabs(nsum - 1.0) : 1.0;
        for (j = 0; j < 10; ++j) {
            double mu = cos(rad(th[j])), want = ref_charlie_onep(al[i], mu);
            double got = 1.0 + (double)mf_charlie_lambda((mf_real)al[i], mft_dir(rad(th[j]), 0.3 * j));
            double e = fabs(got - want) / want;
            if (!(e <= worst)) { worst = mft_finite(e) ? e : 1.0; wa = al[i]; wt = th[j]; }
        }
    }
    /* the published fit against the exact Lambda: view cosines 0.05-0.6 and 0-1 */
    for (i = 0; i <= 40; ++i)
        for (j = 0; j <= 110; ++j) {
            double a = 0.07 + 0.93 * i / 40.0, mu = 0.05 + 0.005 * j;
            mf_vec3 v = mf_vec3_make((mf_real)sqrt(1.0 - mu * mu), MF_R(0.0), (mf_real)mu);
            double le = (double)mf_charlie_lambda((mf_real)a, v), lf = (double)mf_charlie_lambda_fit((mf_real)a, v);
            double el = fabs(lf - le) / le, eg = fabs(1.0 / (1.0 + lf) - 1.0 / (1.0 + le));
            if (el > fit_l) { fit_l = el; fl_a = a; fl_m = mu; }
            if (eg > fit_g) { fit_g = eg; fg_a = a; fg_m = mu; }
        }
    /* and G1 over the whole domain: alpha 1e-3..1 (log-spaced), view cosines 0.02..1 */
    for (i = 0; i <= 30; ++i)
        for (j = 0; j <= 49; ++j) {
            double a = pow(10.0, -3.0 * i / 30.0), mu = 0.02 + 0.02 * j, le, lf, eg;
            mf_vec3 v = mf_vec3_make((mf_real)sqrt(1.0 - mu * mu), MF_R(0.0), (mf_real)mu);
            le = (double)mf_charlie_lambda((mf_real)a, v); lf = (double)mf_charlie_lambda_fit((mf_real)a, v);
            eg = fabs(1.0 / (1.0 + lf) - 1.0 / (1.0 + le));
            if (eg > fit_ga) { fit_ga = eg; fa_a = a; fa_m = mu; }
        }
    printf("    charlie: |int D cos - 1| %.3g; exact Lambda vs 2D quadrature of 1 + Lambda %.3g relative (worst alpha %g, %g deg);\n"
           "      the published fit (alpha 0.07-1, mu 0.05-0.6): Lambda up to %.3g relative (alpha %.3g, mu %.3g), G1 up to %.3g (alpha %.3g, mu %.3g);\n"
           "      G1 of the fit over alpha 1e-3..1, mu 0.02..1: up to %.3g (alpha %.3g, mu %.3g)\n",
           worst_norm, worst, wa, wt, fit_l, fl_a, fl_m, fit_g, fg_a, fg_m, fit_ga, fa_a, fa_m);
    /* the quadrature of sqrt(1 - t^2) at alpha 1 converges slowly at t = 1 */
    MFT_NEAR(worst_norm, 0.0, 0.0, MFT_TOL(1e-8, 1e-5), "charlie: D normalized, alpha 1e-3..1");
    MFT_NEAR(worst, 0.0, 0.0, MFT_TOL(1e-5, 3e-5), "charlie: exact Lambda within 1e-5 of quadrature of 1 + Lambda (alpha 1e-3..1, views to 89.99 deg)");
    /* the figures README.md and docs/ACCURACY.md state: G1 of the fit 0.045 off (alpha 0.07-1), 0.63 over the whole domain */
    MFT_CHECK(fit_g > 0.04 && fit_g < 0.05, "charlie: G1 of the published fit is 0.04-0.05 off the exact one (alpha 0.07-1, mu 0.05-0.6)");
    MFT_CHECK(fit_ga > 0.6 && fit_ga < 0.67, "charlie: G1 of the published fit is 0.6-0.67 off at worst over alpha 1e-3..1, mu 0.02..1 (alpha 1e-3)");
    MFT_CHECK(mf_charlie_lambda(MF_R(0.3), mf_vec3_make(0, 0, 1)) == 0 && mf_charlie_lambda(MF_R(0.3), mf_vec3_make(1, 0, 0)) >= MF_R(1e20)
              && mf_charlie_lambda(MF_R(0.3), mf_vec3_make(0.6f, 0, -0.8f)) == mf_charlie_lambda(MF_R(0.3), mf_vec3_make(0.6f, 0, 0.8f)),
              "charlie: Lambda 0 at the normal, huge at grazing, symmetric in w.z");
    /* NDF sampling: chi-square of m.z^2 (uniform bins of sin^{k+2}) and phi */
    {
        static const double as[3] = { 1.0, 0.3, 0.02 };
        double worst_z = 0.0;
        int bad = 0;
        for (i = 0; i < 3; ++i) {
            double obs[64], ex[64], z;
            int dof, n = 64000;
            mft_rng r;
            mft_seed(&r, 777 + i);
            for (k = 0; k < 64; ++k) { obs[k] = 0.0; ex[k] = n / 64.0; }
            for (k = 0; k < n; ++k) {
                mf_vec3 m = mf_charlie_sample_D((mf_real)as[i], (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                double st = sqrt((double)m.x * m.x + (double)m.y * m.y), ph = atan2((double)m.y, (double)m.x);
                /* the fraction of projected area below sin theta is sin^{k+2}: 8 bins of it x 8 of phi */
                int b1 = (int)(pow(st, 1.0 / as[i] + 2.0) * 8.0), b2;
                if (ph < 0) ph += 6.283185307179586;
                b2 = (int)(ph / 6.283185307179586 * 8.0);
                if (!(m.z > 0)) ++bad;
                if (b1 > 7) b1 = 7;
                if (b2 > 7) b2 = 7;
                obs[b1 * 8 + b2] += 1.0;
            }
            z = mft_chi2(obs, ex, 64, &dof);
            if (fabs(z) > worst_z) worst_z = fabs(z);
        }
        {
            mf_vec3 m0 = mf_charlie_sample_D(MF_R(0.3), MF_R(1.0), MF_R(1.0)), m1 = mf_charlie_sample_D(MF_R(0.3), MF_R(0.0), MF_R(0.0));
            if (!(m0.z > 0) || !(m1.z > 0)) ++bad;
        }
        MFT_CHECK(bad == 0, "charlie: sampled normals above the horizon, u corners included");
        MFT_CHECK(worst_z < 4.5, "charlie: NDF sampling chi-square (alpha 1, 0.3, 0.02)");
    }
}

/* Charlie as an mf_ndf kind (mf_charlie): the generic operations against
 * the same references. Cells for the visible-normal chi-square: 8 bins of
 * the NDF-cos CDF u = sin^{k+2}(theta) by 8 of phi; expected counts by GL
 * quadrature of mf_D_visible over theta (2 x 8 nodes) and phi (8 nodes on
 * each piece between the cell's edges and the visibility edges). */
typedef struct { mf_ndf d; mf_vec3 w; double k, cv, sv, pv; } ch_ctx;
/* the visibility edges phi_v +- phi_c at theta, as many as lie in (lo, hi) */
static int ch_edges(const ch_ctx *c, double th, double lo, double hi, double *e)
{
    double a = c->sv * sin(th), b = c->cv * cos(th), pc, cand[4];
    int n = 0, j;
    if (!(a > b)) return 0;
    pc = acos(-b / a);
    cand[0] = c->pv + pc; cand[1] = c->pv - pc; cand[2] = cand[0] - 6.283185307179586; cand[3] = cand[1] + 6.283185307179586;
    for (j = 0; j < 4; ++j) if (cand[j] > lo && cand[j] < hi) e[n++] = cand[j];
    if (n == 2 && e[0] > e[1]) { double t = e[0]; e[0] = e[1]; e[1] = t; }
    return n;
}
/* The azimuthal integral of D_visible over [p0, p1] at polar angle th
 * (sin st, cos ct), split at the cell's visibility edges (ch_edges), by the
 * 8-point rule x, w on each piece */
static double ch_row(const ch_ctx *c, double th, double st, double ct, double p0, double p1, const double *x, const double *w)
{
    double e[4], pts[6], row = 0.0;
    int ne = ch_edges(c, th, p0, p1, e), np = 0, q, j;
    pts[np++] = p0;
    for (q = 0; q < ne; ++q) pts[np++] = e[q];
    pts[np++] = p1;
    for (q = 0; q + 1 < np; ++q)
        for (j = 0; j < 8; ++j) {
            double ph = pts[q] + (pts[q + 1] - pts[q]) * x[j];
            mf_vec3 m = mf_vec3_make((mf_real)(st * cos(ph)), (mf_real)(st * sin(ph)), (mf_real)ct);
            row += (pts[q + 1] - pts[q]) * w[j] * (double)mf_D_visible(&c->d, c->w, m);
        }
    return row;
}
/* integral of mf_D_visible over theta in [t0, t1], phi in [p0, p1] (solid angle) */
static double ch_cell(const ch_ctx *c, double t0, double t1, double p0, double p1)
{
    double x[8], w[8], sum = 0.0;
    int h, i;
    mft_gl(8, x, w);
    for (h = 0; h < 2; ++h)
        for (i = 0; i < 8; ++i) {
            double th = t0 + (t1 - t0) * (h + x[i]) / 2.0;
            sum += (t1 - t0) / 2.0 * w[i] * ch_row(c, th, sin(th), cos(th), p0, p1, x, w) * sin(th);
        }
    return sum;
}
/* The same over the cell u in [u0, u1] (u = sin^{k+2} theta), phi in [p0,
 * p1], in the variable s of u = u1 - (u1 - u0)(1 - s)^2, where dw / du =
 * 1 / ((k+2) sin^k cos) and its cos ~ sqrt(1 - u) at the horizon are smooth */
static double ch_cell_u(const ch_ctx *c, double u0, double u1, double p0, double p1)
{
    double x[8], w[8], sum = 0.0, k = c->k;
    int h, i;
    mft_gl(8, x, w);
    for (h = 0; h < 2; ++h)
        for (i = 0; i < 8; ++i) {
            double sv = (h + x[i]) / 2.0, om = (1.0 - u1) + (u1 - u0) * (1.0 - sv) * (1.0 - sv), u = 1.0 - om;
            double lg = 2.0 * log1p(-om) / (k + 2.0), st = exp(0.5 * lg), ct = sqrt(-expm1(lg)), th = atan2(st, ct);
            double dw = 2.0 * (u1 - u0) * (1.0 - sv) / ((k + 2.0) * pow(u, k / (k + 2.0)) * ct);
            double row = ch_row(c, th, st, ct, p0, p1, x, w);
            sum += w[i] / 2.0 * row * dw;
        }
    return sum;
}
static int ch_bin(double k, mf_vec3 m, double pv)
{
    double st = sqrt((double)m.x * m.x + (double)m.y * m.y), ph = atan2((double)m.y, (double)m.x) - pv;
    int b1 = (int)(pow(st / sqrt(st * st + (double)m.z * m.z), k + 2.0) * 8.0), b2;
    ph -= 6.283185307179586 * floor(ph / 6.283185307179586);
    b2 = (int)(ph / 6.283185307179586 * 8.0);
    return (b1 > 7 ? 7 : b1) * 8 + (b2 > 7 ? 7 : b2);
}
/* panel p of 2 h over theta in [0, pi/2]: h on [pi/2 - c, pi/2], h below */
static void ch_panel(double c, int p, int h, double *lo, double *hi)
{
    double e = 1.5707963267948966 - c;
    if (p < h) { *lo = e + c * p / h; *hi = e + c * (p + 1) / h; }
    else { *lo = e * (p - h) / h; *hi = e * (p - h + 1) / h; }
}
static void test_charlie_kind(void)
{
    static const double al[6] = { 1.0, 0.5, 0.1, 0.02, 0.005, 0.001 };
    static const double th[6] = { 0.0, 20.0, 50.0, 70.0, 85.0, 89.9 };
    static const double vis[4][2] = { { 1.0, 60.0 }, { 0.001, 0.0 }, { 0.001, 75.0 }, { 0.1, 89.0 } };
    double x[16], w[16], worst_norm = 0.0, worst_lam = 0.0, worst_vis = 0.0, worst_z = 0.0, worst_g1 = 0.0, worst_cells = 0.0;
    int i, j, k, p, bad = 0, badrec = 0, nrec = 0;
    char msg[200];
    mft_rng r;
    mft_gl(16, x, w);
    for (i = 0; i < 6; ++i) {
        mf_ndf d = mf_charlie((mf_real)al[i]);
        double kk = 1.0 / al[i], c = kk > 64.0 ? 8.0 / sqrt(kk) : 1.5707963267948966, nsum = 0.0;
        /* int D m.z dm over theta: 64 panels on [pi/2 - c, pi/2] (D ~ exp(-k (pi/2 - theta)^2 / 2)), 64 below */
        for (p = 0; p < 128; ++p)
            for (k = 0; k < 16; ++k) {
                double lo, hi, t;
                mf_vec3 m;
                ch_panel(c, p, 64, &lo, &hi);
                t = lo + (hi - lo) * x[k];
                m = mf_vec3_make((mf_real)sin(t), MF_R(0.0), (mf_real)cos(t));
                nsum += 2.0 * 3.14159265358979323846 * (hi - lo) * w[k] * (double)mf_D(&d, m) * cos(t) * sin(t);
            }
        if (!(fabs(nsum - 1.0) <= worst_norm)) worst_norm = mft_finite(nsum) ? fabs(nsum - 1.0) : 1.0;
        for (j = 0; j < 6; ++j) {
            mf_vec3 v = mft_dir(rad(th[j]), 0.7 * j), m = mft_dir(rad(th[j]) * 0.5, 0.7 * j);
            double mu = cos(rad(th[j])), want = ref_charlie_onep(al[i], mu), lam = (double)mf_lambda(&d, v);
            double e = fabs(1.0 + lam - want) / want, g1 = (double)mf_G1(&d, v, m);
            if (!(e <= worst_lam)) worst_lam = mft_finite(e) ? e : 1.0;
            e = fabs(g1 - 1.0 / want);
            if (!(e <= worst_g1)) worst_g1 = mft_finite(e) ? e : 1.0;
            /* int D_visible dm = 1: theta panels as above, phi split at the visibility edges */
            if (j % 2 == 1) {
                ch_ctx cx;
                double tot = 0.0;
                cx.d = d; cx.w = v; cx.k = kk; cx.cv = mu; cx.sv = sin(rad(th[j])); cx.pv = 0.7 * j;
                cx.pv -= 6.283185307179586 * floor(cx.pv / 6.283185307179586);
                for (p = 0; p < 32; ++p) {
                    double lo, hi;
                    ch_panel(c, p, 16, &lo, &hi);
                    tot += ch_cell(&cx, lo, hi, 0.0, 6.283185307179586);
                }
                e = fabs(tot - 1.0);
                if (!(e <= worst_vis)) worst_vis = mft_finite(e) ? e : 1.0;
            }
        }
    }
    printf("    charlie kind: |int D cos - 1| %.3g; mf_lambda vs 2D quadrature of 1 + Lambda %.3g relative; G1 %.3g; |int D_visible - 1| %.3g\n",
           worst_norm, worst_lam, worst_g1, worst_vis);
    MFT_NEAR(worst_norm, 0.0, 0.0, MFT_TOL(1e-9, 1e-5), "charlie kind: mf_D normalized, alpha 1e-3..1");
    MFT_NEAR(worst_lam, 0.0, 0.0, MFT_TOL(1e-5, 3e-5), "charlie kind: mf_lambda within 1e-5 of quadrature of 1 + Lambda (alpha 1e-3..1, to 89.9 deg)");
    MFT_NEAR(worst_g1, 0.0, 0.0, MFT_TOL(1e-5, 3e-5), "charlie kind: mf_G1 = 1 / (1 + Lambda) of the quadrature");
    MFT_NEAR(worst_vis, 0.0, 0.0, MFT_TOL(2e-5, 5e-5), "charlie kind: int mf_D_visible dm = 1 (projected area)");
    /* NDF and visible-normal sampling, chi-square */
    for (i = 0; i < 6; ++i) {
        double obs[64], ex[64], z, kk, tot = 0.0;
        int dof, n = 16000;
        ch_ctx cx;
        mft_seed(&r, 4242 + i);
        if (i < 2) {   /* mf_sample_D against D cos: uniform in u and phi */
            mf_ndf d = mf_charlie(MF_R(i == 0 ? 1.0 : 0.001));
            kk = i == 0 ? 1.0 : 1000.0;
            for (k = 0; k < 64; ++k) { obs[k] = 0.0; ex[k] = n / 64.0; }
            for (k = 0; k < n; ++k) {
                mf_vec3 m = mf_sample_D(&d, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                if (!(m.z > 0)) ++bad;
                obs[ch_bin(kk, m, 0.0)] += 1.0;
            }
        } else {       /* mf_sample_visible against mf_D_visible */
            const double *cf = vis[i - 2];
            cx.d = mf_charlie((mf_real)cf[0]); kk = 1.0 / cf[0];
            cx.w = mft_dir(rad(cf[1]), 0.4); cx.cv = cos(rad(cf[1])); cx.sv = sin(rad(cf[1])); cx.pv = 0.4; cx.k = kk;
            for (j = 0; j < 8; ++j)
                for (k = 0; k < 8; ++k) {
                    ex[j * 8 + k] = ch_cell_u(&cx, j / 8.0, (j + 1) / 8.0, 0.4 + 6.283185307179586 * k / 8.0, 0.4 + 6.283185307179586 * (k + 1) / 8.0);
                    tot += ex[j * 8 + k];
                }
            for (k = 0; k < 64; ++k) { obs[k] = 0.0; ex[k] *= n / tot; }
            for (k = 0; k < n; ++k) {
                mf_vec3 m = mf_sample_visible(&cx.d, cx.w, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                if (!(m.z > 0) || !(mf_dot(m, cx.w) > -MFT_TOL(1e-12, 1e-5))) ++bad;
                obs[ch_bin(kk, m, 0.4)] += 1.0;
            }
            if (!(fabs(tot - 1.0) <= worst_cells)) worst_cells = mft_finite(tot) ? fabs(tot - 1.0) : 1.0;
        }
        z = mft_chi2(obs, ex, 64, &dof);
        if (!(fabs(z) <= worst_z)) worst_z = mft_finite(z) ? fabs(z) : 1e3;
    }
    /* u corners: unit normals of positive density, visible ones facing the view */
    for (i = 0; i < 2; ++i) {
        mf_ndf d = mf_charlie(MF_R(i == 0 ? 1.0 : 0.001));
        for (j = 0; j < 4; ++j) {
            mf_vec3 v = mft_dir(rad(j == 3 ? 89.99 : 30.0 * j), 1.0);
            for (k = 0; k < 4; ++k) {
                mf_real u1 = (mf_real)(k & 1), u2 = (mf_real)(k >> 1);
                mf_vec3 m = mf_sample_D(&d, u1, u2), mv = mf_sample_visible(&d, v, u1, u2);
                mf_sample s = mf_brdf_sample(&d, v, u1, u2);
                if (!(fabs((double)mf_dot(m, m) - 1.0) < 1e-5) || !(mf_D(&d, m) > 0)) ++bad;
                if (!(fabs((double)mf_dot(mv, mv) - 1.0) < 1e-5) || !(mf_D(&d, mv) > 0) || !(mf_dot(v, mv) > -MFT_TOL(1e-12, 1e-5))) ++bad;
                if (s.lobe == MF_LOBE_NONE ? (s.pdf != 0 || s.weight != 0) : (!(s.pdf > 0) || !(s.pdf < MF_BIG) || !(s.weight >= 0))) ++bad;
            }
        }
    }
    /* mf_brdf_sample's record: pdf = mf_brdf_pdf, weight = f cos / pdf; reciprocity */
    mft_seed(&r, 99);
    for (i = 0; i < 3; ++i) {
        mf_ndf d = mf_charlie(MF_R(i == 0 ? 1.0 : i == 1 ? 0.1 : 0.001));
        for (j = 0; j < 300; ++j) {
            mf_vec3 v = mft_dir(1.55 * mft_u01(&r), 6.28 * mft_u01(&r));
            mf_sample s = mf_brdf_sample(&d, v, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
            double f, pdf, fr;
            if (s.lobe == MF_LOBE_NONE) continue;
            ++nrec;
            f = mf_brdf(&d, v, s.wi); fr = mf_brdf(&d, s.wi, v); pdf = mf_brdf_pdf(&d, v, s.wi);
            if (!(fabs((double)s.pdf - pdf) <= MFT_TOL(1e-9, 2e-4) * pdf) || !(fabs((double)s.weight - f * s.wi.z / pdf) <= MFT_TOL(1e-9, 2e-4) * s.weight)
                || !(fabs(f - fr) <= MFT_TOL(1e-12, 1e-5) * f))
                ++badrec;
        }
    }
    printf("    charlie kind: sampling chi-square worst |z| %.2f; the visible cells' expected mass sums to 1 within %.2g\n", worst_z, worst_cells);
    MFT_NEAR(worst_cells, 0.0, 0.0, 1e-4, "charlie kind: the chi-square cells of mf_D_visible sum to 1");
    snprintf(msg, sizeof msg, "charlie kind: mf_sample_D and mf_sample_visible chi-square (worst |z| %.2f, fail above 4.5)", worst_z);
    MFT_CHECK(worst_z < 4.5, msg);
    MFT_CHECK(bad == 0, "charlie kind: samples above the horizon, facing the view, u in {0, 1} included");
    snprintf(msg, sizeof msg, "charlie kind: mf_brdf_sample record (pdf, weight) and reciprocity (%d of %d off)", badrec, nrec);
    MFT_CHECK(badrec == 0 && nrec > 100, msg);
    /* LTC fitting of the Charlie BRDF (one view): its albedo against mf_albedo;
     * in the float build only (a fit samples the numerical visible normals
     * 2^16 times: about 1.5 s) */
#ifndef MF_USE_DOUBLE
    {
        mf_ndf d = mf_charlie(MF_R(0.3));
        mf_ltc_fit_result fr;
        mf_result res = mf_ltc_fit(&fr, &d, 0, 0, MF_R(0.8), 0);
        double a = (double)mf_albedo(&d, mf_vec3_make(MF_R(0.6), MF_R(0.0), MF_R(0.8)));
        printf("    charlie kind: LTC fit at cos 0.8, alpha 0.3: albedo %.5f (mf_albedo %.5f), error %.3g\n", (double)fr.albedo, a, (double)fr.error);
        MFT_CHECK(res == MF_SUCCESS && fabs((double)fr.albedo - a) < 0.03 * a && mft_finite(fr.error), "charlie kind: mf_ltc_fit succeeds, its albedo within 3% of mf_albedo");
    }
#endif
}

/* ---- robustness: every new function on special values ---------------------- */
static int fin01(mf_real v) { return v >= MF_R(0.0) && v <= MF_R(1.0); }
static int finpos(mf_real v) { return v >= MF_R(0.0) && v <= MF_BIG; }
static void test_lobes_robust(void)
{
    mf_real v[12];
    mf_vec3 d[10];
    int i, j, k, l, bad = 0, n = 0;
    mft_special_values(v, d);
    for (i = 0; i < 12; ++i)
        for (j = 0; j < 12; ++j) {
            mf_real rgb[3], eb[3], kb[3];
            for (k = 0; k < 12; ++k) {
                mf_vec3 m;
                ++n;
                if (!fin01(mf_fresnel_f82(v[i], v[j], v[k]))) ++bad;
                if (!fin01(mf_eon_albedo(v[i], v[j], v[k])) || !fin01(mf_eon_albedo_fast(v[i], v[j], v[k]))) ++bad;
                if (!fin01(mf_fresnel_thin_film(v[i], v[j], v[k], MF_R(300.0), MF_R(1.5), MF_R(0.1), MF_R(550.0)))) ++bad;
                if (!fin01(mf_fresnel_thin_film(MF_R(0.7), MF_R(1.0), v[i], v[j], v[k], MF_R(0.5), MF_R(550.0)))) ++bad;
                if (!fin01(mf_fresnel_thin_film(MF_R(0.7), MF_R(1.0), MF_R(1.4), MF_R(200.0), v[i], v[j], v[k]))) ++bad;
                m = mf_charlie_sample_D(v[i], v[j], v[k]);
                if (!(m.z > 0) || !(m.z <= 1) || !mft_finite(m.x) || !mft_finite(m.y)) ++bad;
            }
            if (!fin01(mf_fresnel_f82_average(v[i], v[j])) || !fin01(mf_eon_albedo_average(v[i], v[j]))) ++bad;
            eb[0] = v[i]; eb[1] = MF_R(1.5); eb[2] = v[j]; kb[0] = v[j]; kb[1] = 0; kb[2] = v[i];
            mf_fresnel_thin_film_rgb(MF_R(0.6), MF_R(1.0), MF_R(1.33), MF_R(400.0), eb, kb, rgb);
            for (l = 0; l < 3; ++l) if (!fin01(rgb[l])) ++bad;
            mf_fresnel_thin_film_rgb(v[i], v[j], MF_R(1.33), v[(i + j) % 12], eb, kb, rgb);
            for (l = 0; l < 3; ++l) if (!fin01(rgb[l])) ++bad;
        }
    for (i = 0; i < 10; ++i)
        for (j = 0; j < 10; ++j)
            for (k = 0; k < 12; ++k) {
                mf_sample r;
                ++n;
                if (!finpos(mf_eon_brdf(d[i], d[j], v[k], MF_R(0.5))) || !finpos(mf_eon_brdf(d[i], d[j], MF_R(0.5), v[k]))) ++bad;
                if (!finpos(mf_eon_pdf(d[i], d[j], v[k]))) ++bad;
                if (!finpos(mf_charlie_D(v[k], d[i])) || !finpos(mf_charlie_lambda(v[k], d[i])) || !finpos(mf_charlie_lambda_fit(v[k], d[i]))) ++bad;
                for (l = 0; l < 12; ++l) {
                    r = mf_eon_sample(d[i], v[k], MF_R(0.7), v[l], v[j]);
                    if (!mft_record_ok(r)) ++bad;
                    r = mf_eon_sample(d[i], MF_R(0.7), v[k], v[l], MF_R(0.3));
                    if (!mft_record_ok(r)) ++bad;
                }
            }
    printf("    robustness: %d special-value combinations, %d out of range\n", n, bad);
    MFT_CHECK(bad == 0, "lobes: every new function finite and in range on special values (0, -0, tiny, huge, inf, NaN, negative)");
}

void test_lobes(void)
{
    test_f82();
    test_eon_eval();
    test_eon_sample();
    test_thin_film();
    test_charlie();
    test_charlie_kind();
    test_lobes_robust();
}
