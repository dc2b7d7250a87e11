/* The lobes of a whole material (issue 42), against references written here
 * in double:
 *  - F82-tint (Hoffman 2023): F(1) = f0, F(0) = 1, F(1/7) = tint *
 *    Schlick(f0, 1/7), F >= 0, and the average of the clamped F against
 *    quadrature over the whole (f0, tint) square (panels split at the sign
 *    changes of the test's own F, so the quadrature is exact to rounding). */
#include "mf_test.h"
#include <stdlib.h>

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

void test_material_lobes(void)
{
    test_f82();
}
