/* Energy compensation (Kulla & Conty 2017). The reference is an independent
 * integral in double of f(wo, wi) wi.z over the half vector wh (dwi =
 * 4 (wo.wh) dwh), in polar coordinates of the normalized slope rho =
 * tan(theta_h) / alpha = u / (1 - u), Gauss-Legendre panels in u and in the
 * azimuth; it uses neither the tables nor the sampler.
 *  - the built-in GGX / Beckmann tables against it (max error printed, held);
 *  - white furnace: E_true(wo) + int f_ms wi.z dwi = 1 within 1e-2 for alpha
 *    in [0.01, 1] and views mu in [1e-3, 1] (worst case printed);
 *  - single-scattering albedo <= 1; Turquin scaling gives 1 at F = 1;
 *  - anisotropic GGX / Beckmann through the equivalent alpha: error printed;
 *  - the table builder on GTR, Student-t, tabulated and transformed GGX
 *    against the reference, and its compensated furnace; bad input;
 *  - mf_ms_fresnel against the geometric series of Kulla & Conty;
 *  - cosine sampling of the lobe: chi-square, pdf integral, weight;
 *  - robustness: no NaN/Inf, pdf >= 0, E in [0, 1]. */
#include "mf_test.h"

/* a check whose message carries a measured figure: printed under -v */
#define CHECKV(cond, msg) do { MFT_CHECK(cond, msg); if (mft_verbose) printf("    %s\n", msg); } while (0)

/* E(wo) = int f cos dwi, in double, over wh; np panels of 8 nodes each way */
static double ref_albedo(const mf_ndf *d, mf_vec3 wo, int np)
{
    static double gx[8], gw[8];
    static int init = 0;
    double a = sqrt((double)d->ax * (double)d->ay), sum = 0.0;
    int p, i, q, j;
    if (!init) { mft_gl(8, gx, gw); init = 1; }
    if (a > 1.0) a = 1.0;
    if (d->transformed) a *= sqrt(fabs((double)d->M.m00 * d->M.m11 - (double)d->M.m01 * d->M.m10));
    for (p = 0; p < np; ++p)
        for (i = 0; i < 8; ++i) {
            double u = ((double)p + gx[i]) / np, rho = u / (1.0 - u), drho = 1.0 / ((1.0 - u) * (1.0 - u));
            double th = atan(a * rho), dth = a / (1.0 + a * a * rho * rho) * drho;
            for (q = 0; q < 2 * np; ++q)
                for (j = 0; j < 8; ++j) {
                    double ph = 2.0 * 3.14159265358979324 * ((double)q + gx[j]) / (2 * np);
                    mf_vec3 wh = mf_vec3_make((mf_real)(sin(th) * cos(ph)), (mf_real)(sin(th) * sin(ph)), (mf_real)cos(th));
                    double c = (double)mf_dot(wo, wh);
                    mf_vec3 wi;
                    if (!(c > 0.0)) continue;
                    wi = mf_vec3_make((mf_real)(2.0 * c * wh.x - wo.x), (mf_real)(2.0 * c * wh.y - wo.y), (mf_real)(2.0 * c * wh.z - wo.z));
                    if (!(wi.z > 0)) continue;
                    sum += gw[i] * gw[j] / np * 2.0 * 3.14159265358979324 / (2 * np) *
                           (double)mf_brdf(d, wo, wi) * (double)wi.z * 4.0 * c * sin(th) * dth;
                }
        }
    return sum;
}

/* int f_ms(wo, wi) wi.z dwi (GL in x = sqrt(mu), 16 azimuths) */
static double ref_ms(const mf_ndf *d, const mf_albedo_table *t, mf_vec3 wo)
{
    double gx[8], gw[8], sum = 0.0;
    int p, i, q;
    mft_gl(8, gx, gw);
    for (p = 0; p < 32; ++p)
        for (i = 0; i < 8; ++i) {
            double x = ((double)p + gx[i]) / 32.0, mu = x * x, s = sqrt(1.0 - mu * mu);
            for (q = 0; q < 16; ++q) {
                double ph = 2.0 * 3.14159265358979324 * (q + 0.5) / 16.0;
                mf_vec3 wi = mf_vec3_make((mf_real)(s * cos(ph)), (mf_real)(s * sin(ph)), (mf_real)mu);
                double f = t ? (double)mf_albedo_table_brdf_ms(t, wo, wi) : (double)mf_brdf_ms(d, wo, wi);
                sum += gw[i] / 32.0 * 2.0 * x * (2.0 * 3.14159265358979324 / 16.0) * f * mu;
            }
        }
    return sum;
}

static mf_vec3 view(double mu, double phi)
{
    double s = sqrt(1.0 - mu * mu);
    return mf_vec3_make((mf_real)(s * cos(phi)), (mf_real)(s * sin(phi)), (mf_real)mu);
}

static void tables_and_furnace(void)
{
    static const double alphas[] = { 0.01, 0.015, 0.02, 0.03, 0.05, 0.07, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0 };
    static const double mus[] = { 1e-3, 0.003, 0.01, 0.02, 0.035, 0.05, 0.08, 0.12, 0.17, 0.25, 0.33, 0.45, 0.6, 0.75, 0.9, 1.0 };
    int k, ia, im;
    char msg[200];
    for (k = 0; k < 2; ++k) {
        double worst_tab = 0.0, worst_f = 0.0, max_ss = 0.0, worst_tq = 0.0, wa = 0, wm = 0, ta = 0, tm = 0;
        for (ia = 0; ia < (int)(sizeof alphas / sizeof alphas[0]); ++ia) {
            mf_ndf d = k ? mf_beckmann((mf_real)alphas[ia], (mf_real)alphas[ia]) : mf_ggx((mf_real)alphas[ia], (mf_real)alphas[ia]);
            for (im = 0; im < (int)(sizeof mus / sizeof mus[0]); ++im) {
                mf_vec3 wo = view(mus[im], 0.4);
                double e = ref_albedo(&d, wo, 24), et = (double)mf_albedo(&d, wo);
                double tot = e + ref_ms(&d, NULL, wo), tq = e * (double)mf_ms_turquin_scale(&d, wo, MF_R(1.0));
                if (fabs(et - e) > worst_tab) { worst_tab = fabs(et - e); ta = alphas[ia]; tm = mus[im]; }
                if (fabs(tot - 1.0) > worst_f) { worst_f = fabs(tot - 1.0); wa = alphas[ia]; wm = mus[im]; }
                if (fabs(tq - 1.0) > worst_tq) worst_tq = fabs(tq - 1.0);
                if (e > max_ss) max_ss = e;
            }
        }
        snprintf(msg, sizeof msg, "%s built-in table vs integral: max |error| %.2e (alpha %g, mu %g) <= 5e-3",
                 k ? "Beckmann" : "GGX", worst_tab, ta, tm);
        CHECKV(worst_tab <= 5e-3, msg);
        snprintf(msg, sizeof msg, "%s white furnace, compensated: worst |1 - albedo| %.2e (alpha %g, mu %g) <= 1e-2",
                 k ? "Beckmann" : "GGX", worst_f, wa, wm);
        CHECKV(worst_f <= 1e-2, msg);
        snprintf(msg, sizeof msg, "%s Turquin scaling at F = 1: worst |1 - albedo| %.2e <= 1e-2", k ? "Beckmann" : "GGX", worst_tq);
        CHECKV(worst_tq <= 1e-2, msg);
        snprintf(msg, sizeof msg, "%s single-scattering albedo <= 1 (max %.6f)", k ? "Beckmann" : "GGX", max_ss);
        CHECKV(max_ss <= 1.0 + 1e-6, msg);
        /* E_avg against 2 int E mu dmu of the reference, at three alphas */
        {
            double worst = 0.0, gx[8], gw[8];
            int p, i;
            mft_gl(8, gx, gw);
            for (ia = 0; ia < 3; ++ia) {
                double a = ia == 0 ? 0.1 : ia == 1 ? 0.5 : 1.0, s = 0.0;
                mf_ndf d = k ? mf_beckmann((mf_real)a, (mf_real)a) : mf_ggx((mf_real)a, (mf_real)a);
                for (p = 0; p < 4; ++p)
                    for (i = 0; i < 8; ++i) {
                        double x = (p + gx[i]) / 4.0, mu = x * x;
                        s += gw[i] / 4.0 * ref_albedo(&d, view(mu, 0.0), 12) * 4.0 * x * x * x;
                    }
                if (fabs(s - (double)mf_albedo_average(&d)) > worst) worst = fabs(s - (double)mf_albedo_average(&d));
            }
            snprintf(msg, sizeof msg, "%s E_avg vs integral at alpha 0.1, 0.5, 1: max |error| %.2e <= 2e-3", k ? "Beckmann" : "GGX", worst);
            CHECKV(worst <= 2e-3, msg);
        }
    }
}

/* anisotropic: the equivalent isotropic alpha sqrt(ax ay), an approximation
 * whose error is measured here per aspect ratio (3 and 10) */
static void anisotropic(void)
{
    static const double ab[][2] = { { 0.1, 0.3 }, { 0.2, 0.6 }, { 0.3, 0.9 }, { 0.05, 0.5 }, { 0.1, 1.0 } };
    int k, c, im, ip;
    char msg[200];
    for (k = 0; k < 2; ++k) {
        double worst[2] = { 0.0, 0.0 }, worst_f[2] = { 0.0, 0.0 };
        for (c = 0; c < 5; ++c) {
            mf_ndf d = k ? mf_beckmann((mf_real)ab[c][0], (mf_real)ab[c][1]) : mf_ggx((mf_real)ab[c][0], (mf_real)ab[c][1]);
            int g = c >= 3;   /* aspect 10 */
            for (im = 0; im < 5; ++im)
                for (ip = 0; ip < 3; ++ip) {
                    mf_vec3 wo = view(im == 0 ? 0.05 : 0.25 * im, 0.785398 * ip);
                    double e = ref_albedo(&d, wo, 16), err = fabs((double)mf_albedo(&d, wo) - e);
                    double f = fabs(e + ref_ms(&d, NULL, wo) - 1.0);
                    if (err > worst[g]) worst[g] = err;
                    if (f > worst_f[g]) worst_f[g] = f;
                }
        }
        snprintf(msg, sizeof msg, "%s anisotropic via sqrt(ax ay): max |E error| %.3f at aspect 3 (<= 0.2), %.3f at aspect 10 (<= 0.4); furnace off by %.3f, %.3f",
                 k ? "Beckmann" : "GGX", worst[0], worst[1], worst_f[0], worst_f[1]);
        CHECKV(worst[0] <= 0.2 && worst[1] <= 0.4 && worst_f[0] <= 0.2 && worst_f[1] <= 0.4, msg);
    }
}

static void builder(void)
{
    mf_tabulated tab;
    mf_ndf base = mf_ggx(MF_R(0.4), MF_R(0.4)), ds[5];
    const char *names[5] = { "GTR gamma 1.5", "Student-t gamma 3", "tabulated GGX 0.4", "transformed GGX", "GGX 0.1 x 1.0" };
    mf_albedo_table t;
    int c, im, ip, nphi;
    char msg[200];
    mf_tabulated_from_ndf(&tab, &base, 64);
    ds[0] = mf_gtr(MF_R(0.5), MF_R(1.5));
    ds[1] = mf_student_t(MF_R(0.3), MF_R(0.3), MF_R(3.0));
    ds[2] = mf_tabulated_ndf(&tab);
    ds[3] = mf_transformed(mf_ggx(MF_R(0.3), MF_R(0.3)), mf_mat2_make(MF_R(1.5), MF_R(0.3), MF_R(0.0), MF_R(0.8)));
    ds[4] = mf_ggx(MF_R(0.1), MF_R(1.0));
    for (c = 0; c < 5; ++c) {
        double worst = 0.0, worst_f = 0.0;
        mf_result r;
        nphi = c == 4 ? 32 : c == 3 ? 16 : 1;
        r = mf_albedo_table_build(&t, &ds[c], 24, nphi, c == 4 ? 8 : 4);
        if (r != MF_SUCCESS) { CHECKV(0, "mf_albedo_table_build succeeds"); continue; }
        for (im = 0; im < 4; ++im)
            for (ip = 0; ip < (c >= 3 ? 3 : 1); ++ip) {
                mf_vec3 wo = view(im == 0 ? 0.1 : 0.3 * im, 1.0 + 2.0 * ip);
                double e = ref_albedo(&ds[c], wo, 16);
                double err = fabs((double)mf_albedo_table_eval(&t, wo) - e);
                double f = fabs(e + ref_ms(NULL, &t, wo) - 1.0);
                if (err > worst) worst = err;
                if (f > worst_f) worst_f = f;
            }
        snprintf(msg, sizeof msg, "albedo table of %s (24 x %d): max |E error| %.2e, furnace |1 - albedo| %.2e <= %g",
                 names[c], nphi, worst, worst_f, c == 4 ? 1.5e-2 : 1e-2);
        CHECKV(worst <= (c == 4 ? 1.5e-2 : 1e-2) && worst_f <= (c == 4 ? 1.5e-2 : 1e-2), msg);
        if (c == 0) {
            double e = ref_albedo(&ds[c], view(0.6, 0.0), 16);
            MFT_NEAR(mf_albedo(&ds[c], view(0.6, 0.0)), e, 0.0, 1e-2, "mf_albedo of GTR integrates (no table)");
            MFT_NEAR(mf_albedo_average(&ds[c]), mf_albedo_table_average(&t), 0.0, 1e-2, "mf_albedo_average of GTR vs its table");
        }
        mf_albedo_table_release(&t);
        CHECKV(t.E == NULL, "released table holds nothing");
    }
    mf_tabulated_release(&tab);
    /* bad input */
    {
        mf_ndf bad = base;
        int ok = 1;
        bad.type = 99;
        ok &= mf_albedo_table_build(NULL, &base, 8, 1, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_albedo_table_build(&t, NULL, 8, 1, 1) == MF_ERROR_INVALID_ARGUMENT && t.E == NULL;
        ok &= mf_albedo_table_build(&t, &bad, 8, 1, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_albedo_table_build(&t, &base, 1, 1, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_albedo_table_build(&t, &base, 8, 0, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_albedo_table_build(&t, &base, 8, 1, 0) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_albedo_table_build(&t, &base, 1 << 20, 1, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_albedo_table_eval(&t, view(0.5, 0.0)) == 0 && mf_albedo_table_average(NULL) == 0;
        ok &= mf_albedo_table_brdf_ms(NULL, view(0.5, 0.0), view(0.5, 0.0)) == 0;
        mf_albedo_table_release(NULL);
        mf_albedo_table_release(&t);
        CHECKV(ok, "mf_albedo_table_build: bad arguments are MF_ERROR_INVALID_ARGUMENT, nothing allocated");
    }
}

static void fresnel_and_sampling(void)
{
    int i, bad = 0;
    char msg[200];
    /* Kulla & Conty: the energy of bounces 2, 3, ... with Fresnel F_avg per
     * bounce, sum_k F^(k+1) E (1 - E)^k, over 1 - E, is the factor */
    for (i = 0; i < 50; ++i) {
        double f = (i % 10) / 9.0, e = 0.05 + 0.9 * (i / 10) / 4.0, s = 0.0, pk = 1.0;
        int k;
        for (k = 1; k < 4000; ++k) { pk *= f * (1.0 - e); s += f * e * pk; }
        if (fabs((double)mf_ms_fresnel((mf_real)f, (mf_real)e) - s / (1.0 - e)) > MFT_TOL(1e-9, 1e-5)) ++bad;
    }
    CHECKV(bad == 0 && fabs((double)mf_ms_fresnel(MF_R(1.0), MF_R(0.4)) - 1.0) < MFT_TOL(1e-12, 1e-6),
              "mf_ms_fresnel equals the geometric series of bounces (Kulla & Conty Eq. 2), 1 at F_avg = 1");
    /* cosine sampling: 10 x 8 equal-probability bins in (1 - z^2, phi) */
    {
        static double obs[80], ex[80];
        mf_ndf d = mf_ggx(MF_R(0.7), MF_R(0.7));
        mf_vec3 wo = view(0.4, 0.0);
        mft_rng r;
        int n = 200000, dof, lost = 0;
        double z, west = 0.0, west2 = 0.0, sig, wref = ref_ms(&d, NULL, wo), pint = 0.0, gx[8], gw[8];
        int p, q;
        mft_seed(&r, 12);
        for (i = 0; i < 80; ++i) { obs[i] = 0; ex[i] = n / 80.0; }
        for (i = 0; i < n; ++i) {
            mf_vec3 wi = mf_brdf_ms_sample(&d, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
            double pdf = mf_brdf_ms_pdf(&d, wo, wi), ph;
            int b0, b1;
            if (!(wi.z > 0) || !(pdf > 0)) { ++lost; continue; }
            { double w = (double)mf_brdf_ms(&d, wo, wi) * wi.z / pdf; west += w; west2 += w * w; }
            ph = atan2((double)wi.y, (double)wi.x); if (ph < 0) ph += 2.0 * 3.14159265358979324;
            b0 = (int)((1.0 - (double)wi.z * wi.z) * 10.0); if (b0 > 9) b0 = 9; if (b0 < 0) b0 = 0;
            b1 = (int)(ph / (2.0 * 3.14159265358979324) * 8.0); if (b1 > 7) b1 = 7;
            obs[b0 * 8 + b1] += 1.0;
        }
        z = mft_chi2(obs, ex, 80, &dof);
        snprintf(msg, sizeof msg, "mf_brdf_ms_sample follows mf_brdf_ms_pdf: chi-square z = %.2f (dof %d), %d lost", z, dof, lost);
        CHECKV(fabs(z) < 5.0 && lost < 5, msg);
        west /= n;
        sig = sqrt((west2 / n - west * west) / n);
        snprintf(msg, sizeof msg, "compensation lobe, %d samples: MC estimate %.5f vs integral %.5f, within 4 sigma (sigma %.1e)", n, west, wref, sig);
        CHECKV(fabs(west - wref) < 4.0 * sig, msg);
        mft_gl(8, gx, gw);
        for (p = 0; p < 16; ++p)
            for (i = 0; i < 8; ++i) {
                double mu = (p + gx[i]) / 16.0;
                for (q = 0; q < 8; ++q) {
                    double ph = 2.0 * 3.14159265358979324 * (q + 0.5) / 8.0, s = sqrt(1.0 - mu * mu);
                    pint += gw[i] / 16.0 * 2.0 * 3.14159265358979324 / 8.0 *
                            (double)mf_brdf_ms_pdf(&d, wo, mf_vec3_make((mf_real)(s * cos(ph)), (mf_real)(s * sin(ph)), (mf_real)mu));
                }
            }
        MFT_NEAR(pint, 1.0, 0.0, 1e-5, "mf_brdf_ms_pdf integrates to 1 over the hemisphere");
    }
}

static void robust(void)
{
    const double inf = HUGE_VAL, nan = inf - inf;
    const double alphas[] = { 0.0, 1e-12, 1e-4, 0.02, 0.5, 1.0, 3.0, 1e6, -1.0, nan, inf };
    const double us[] = { 0.0, 1e-12, 0.5, 1.0 - 1e-7, 1.0, -1.0, nan };
    const double fs[] = { 0.0, 0.5, 1.0, -1.0, 2.0, nan, inf };
    mf_vec3 dirs[8];
    int k, ia, i, j, bad = 0;
    dirs[0] = mf_vec3_make(0, 0, 1);
    dirs[1] = mf_vec3_make(1, 0, 0);
    dirs[2] = mft_dir(1.5707963, 0.3);
    dirs[3] = mft_dir(0.7, 2.0);
    dirs[4] = mf_vec3_make(0, 0, -1);
    dirs[5] = mf_vec3_make((mf_real)nan, 0, 1);
    dirs[6] = mf_vec3_make(0, 0, (mf_real)inf);
    dirs[7] = mf_vec3_make(0, 0, 0);
    for (k = 0; k < 2; ++k)
        for (ia = 0; ia < 11; ++ia) {
            mf_real a = (mf_real)alphas[ia];
            mf_ndf d = k ? mf_beckmann(a, (mf_real)alphas[(ia + 3) % 11]) : mf_ggx(a, (mf_real)alphas[(ia + 3) % 11]);
            double ea = mf_albedo_average(&d);
            if (!(ea >= 0 && ea <= 1)) ++bad;
            for (i = 0; i < 8; ++i) {
                double e = mf_albedo(&d, dirs[i]), tq = mf_ms_turquin_scale(&d, dirs[i], (mf_real)fs[i % 7]);
                if (!(e >= 0 && e <= 1) || !mft_finite(tq) || tq < 1) ++bad;
                for (j = 0; j < 8; ++j) {
                    double f = mf_brdf_ms(&d, dirs[i], dirs[j]), p = mf_brdf_ms_pdf(&d, dirs[i], dirs[j]);
                    if (!mft_finite(f) || f < 0 || !mft_finite(p) || p < 0) ++bad;
                }
                for (j = 0; j < 7; ++j) {
                    mf_vec3 w = mf_brdf_ms_sample(&d, dirs[i], (mf_real)us[j], (mf_real)us[(j + 2) % 7]).wi;
                    double l = (double)w.x * w.x + (double)w.y * w.y + (double)w.z * w.z;
                    if (!mft_finite(l) || !(l == 0.0 || fabs(l - 1.0) < 1e-4)) ++bad;
                }
            }
        }
    for (i = 0; i < 7; ++i)
        for (j = 0; j < 7; ++j) {
            double m = mf_ms_fresnel((mf_real)fs[i], (mf_real)fs[j]);
            if (!mft_finite(m) || m < 0 || m > 1) ++bad;
        }
    /* other kinds through the integrator, a few cases */
    {
        mf_ndf o[3];
        o[0] = mf_gtr(MF_R(0.0), (mf_real)nan);
        o[1] = mf_student_t(MF_R(1e6), MF_R(1e-12), MF_R(1.0));
        o[2] = mf_gtr(MF_R(0.3), MF_R(2.0));
        for (k = 0; k < 3; ++k)
            for (i = 0; i < 8; ++i) {
                double e = mf_albedo(&o[k], dirs[i]), e2 = mf_albedo_integrate(&o[k], dirs[i], 1);
                /* panel counts -80 .. 200: 40 (i = 3, 8 unless --full) is the one in range */
                double e3 = mf_albedo_integrate(&o[k], dirs[i], i == 3 && !mft_full ? 8 : (i - 2) * 40);
                if (!(e >= 0 && e <= 1) || !(e2 >= 0 && e2 <= 1) || !(e3 >= 0 && e3 <= 1)) ++bad;
            }
    }
    CHECKV(bad == 0, "energy compensation functions: finite, E in [0, 1], f_ms and pdf >= 0, unit or zero samples, on extreme input");
}

/* int f_ms |wi.z| dwi over both hemispheres, the transmitted part times e^2
 * (importance transport), GL in x = sqrt(|mu|), 16 azimuths */
static double ref_diel_ms(const mf_dielectric_ms_table *t, mf_vec3 wo)
{
    double gx[8], gw[8], sum = 0.0;
    int p, i, q, side;
    mft_gl(8, gx, gw);
    for (side = 0; side < 2; ++side)
        for (p = 0; p < 32; ++p)
            for (i = 0; i < 8; ++i) {
                double x = ((double)p + gx[i]) / 32.0, mu = x * x, s = sqrt(1.0 - mu * mu);
                for (q = 0; q < 16; ++q) {
                    double ph = 2.0 * 3.14159265358979324 * (q + 0.5) / 16.0, f, e;
                    mf_vec3 wi = mf_vec3_make((mf_real)(s * cos(ph)), (mf_real)(s * sin(ph)), (mf_real)(side ? -mu : mu));
                    f = (double)mf_dielectric_ms_table_bsdf(t, wo, wi, MF_RADIANCE);
                    if ((wo.z > 0) != (wi.z > 0)) { e = wo.z > 0 ? (double)t->eta : 1.0 / (double)t->eta; f *= e * e; }
                    sum += gw[i] / 32.0 * 2.0 * x * (2.0 * 3.14159265358979324 / 16.0) * f * mu;
                }
            }
    return sum;
}

/* dielectric white furnace in importance transport: MC albedo of the single-
 * scattering BSDF (mf_dielectric_sample, weight times e^2) plus the
 * compensation lobe's integral, both sides, GGX and Beckmann */
static void dielectric(void)
{
    static const double alphas[] = { 0.01, 0.03, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0 };
    static const double mus[] = { 0.02, 0.1, 0.3, 0.6, 1.0 };
    const mf_real eta = MF_R(1.5);
    const int n = MFT_N(100000);
    int k, ia, im, side, i;
    char msg[400];
    for (k = 0; k < 2; ++k) {
        double worst_f = 0.0, raw_f = 0.0, worst_e = 0.0, wa = 0, wm = 0, ws = 0, sig_max = 0.0, loss = 0.0, la = 0, lm = 0, ls = 0;
        int bad_recip = 0;
        for (ia = 0; ia < (int)(sizeof alphas / sizeof alphas[0]); ++ia) {
            mf_ndf d = k ? mf_beckmann((mf_real)alphas[ia], (mf_real)alphas[ia]) : mf_ggx((mf_real)alphas[ia], (mf_real)alphas[ia]);
            mf_dielectric_ms_table t;
            mft_rng r;
            if (mf_dielectric_ms_table_build(&t, &d, eta, 32, 8) != MF_SUCCESS) { CHECKV(0, "mf_dielectric_ms_build succeeds"); continue; }
            mft_seed(&r, 99 + ia);
            for (im = 0; im < 5; ++im)
                for (side = 0; side < 2; ++side) {
                    mf_vec3 wo = view(mus[im], 0.3);
                    double s1 = 0.0, s2 = 0.0, e, sig, tot;
                    if (side) wo.z = -wo.z;
                    for (i = 0; i < n; ++i) {
                        /* importance transport: the record's weight conserves */
                        mf_sample smp = mf_dielectric_sample(&d, wo, eta, MF_IMPORTANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                        double w;
                        if (smp.lobe == MF_LOBE_NONE) continue;
                        w = (double)smp.weight;
                        s1 += w; s2 += w * w;
                    }
                    e = s1 / n;
                    sig = sqrt((s2 / n - e * e) / n);
                    if (sig > sig_max) sig_max = sig;
                    tot = e + ref_diel_ms(&t, wo);
                    if (fabs(tot - 1.0) - 4.0 * sig > worst_f) worst_f = fabs(tot - 1.0) - 4.0 * sig;
                    if (fabs(tot - 1.0) > raw_f) { raw_f = fabs(tot - 1.0); wa = alphas[ia]; wm = mus[im]; ws = side; }
                    if (fabs(e - (double)mf_dielectric_ms_table_albedo(&t, wo)) - 4.0 * sig > worst_e) worst_e = fabs(e - (double)mf_dielectric_ms_table_albedo(&t, wo)) - 4.0 * sig;
                    if (1.0 - e > loss) { loss = 1.0 - e; la = alphas[ia]; lm = mus[im]; ls = side; }
                }
            /* generalized reciprocity of the lobe: f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2 */
            for (i = 0; i < 200; ++i) {
                mf_vec3 a = view(0.05 + 0.95 * mft_u01(&r), 6.283 * mft_u01(&r)), b = view(0.05 + 0.95 * mft_u01(&r), 6.283 * mft_u01(&r));
                double na = 1.0, nb = 1.0, f1, f2;
                if (i & 1) { a.z = -a.z; na = 1.5; }
                if (i & 2) { b.z = -b.z; nb = 1.5; }
                f1 = (double)mf_dielectric_ms_table_bsdf(&t, a, b, MF_RADIANCE) / (na * na);
                f2 = (double)mf_dielectric_ms_table_bsdf(&t, b, a, MF_RADIANCE) / (nb * nb);
                if (fabs(f1 - f2) > MFT_TOL(1e-9, 1e-5) * (fabs(f1) + 1e-3)) ++bad_recip;
            }
            mf_dielectric_ms_table_release(&t);
        }
        snprintf(msg, sizeof msg, "%s dielectric eta 1.5 white furnace (importance transport), both sides: worst |1 - albedo| %.2e "
                 "(alpha %g, mu %g, %s; MC sigma <= %.1e, %d samples; %.1e beyond 4 sigma) <= 1e-2; single scattering loses up to %.3f (alpha %g, mu %g, %s)",
                 k ? "Beckmann" : "GGX", raw_f, wa, wm, ws ? "below" : "above", sig_max, n, worst_f, loss, la, lm, ls ? "below" : "above");
        CHECKV(raw_f <= 1e-2, msg);
        snprintf(msg, sizeof msg, "%s dielectric albedo table vs MC: worst |error| %.2e beyond 4 sigma <= 5e-3", k ? "Beckmann" : "GGX", worst_e);
        CHECKV(worst_e <= 5e-3, msg);
        snprintf(msg, sizeof msg, "%s dielectric compensation lobe: generalized reciprocity (%d of 1600 pairs off)", k ? "Beckmann" : "GGX", bad_recip);
        CHECKV(bad_recip == 0, msg);
    }
    /* sampling of the lobe: 2 sides x 10 x 8 bins, from above and below */
    {
        static double obs[160], ex[160];
        mf_ndf d = mf_ggx(MF_R(0.6), MF_R(0.6));
        mf_dielectric_ms_table t;
        mft_rng r;
        int s0, dof, j, bad = 0;
        double z, pint;
        mf_dielectric_ms_table_build(&t, &d, MF_R(1.5), 16, 2);
        for (s0 = 0; s0 < 2; ++s0) {
            mf_vec3 wo = view(0.5, 0.2);
            if (s0) wo.z = -wo.z;
            mft_seed(&r, 5 + s0);
            for (i = 0; i < 160; ++i) obs[i] = 0.0;
            for (i = 0; i < 160; ++i) {
                double share = (double)mf_dielectric_ms_table_pdf(&t, wo, mf_vec3_make(0, 0, i >= 80 ? -1 : 1)) * 3.14159265358979324;
                ex[i] = 200000.0 * share / 80.0;
            }
            for (i = 0; i < 200000; ++i) {
                mf_vec3 wi = mf_dielectric_ms_table_sample(&t, wo, MF_RADIANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
                double ph = atan2((double)wi.y, (double)wi.x), az = fabs((double)wi.z);
                int b0, b1;
                if (wi.z == 0) continue;
                if (ph < 0) ph += 2.0 * 3.14159265358979324;
                b0 = (int)((1.0 - az * az) * 10.0); if (b0 > 9) b0 = 9; if (b0 < 0) b0 = 0;
                b1 = (int)(ph / (2.0 * 3.14159265358979324) * 8.0); if (b1 > 7) b1 = 7;
                obs[(wi.z < 0 ? 80 : 0) + b0 * 8 + b1] += 1.0;
            }
            z = mft_chi2(obs, ex, 160, &dof);
            snprintf(msg, sizeof msg, "mf_dielectric_ms_sample from %s follows mf_dielectric_ms_pdf: chi-square z = %.2f (dof %d)", s0 ? "below" : "above", z, dof);
            CHECKV(fabs(z) < 5.0, msg);
            /* pdf integrates to 1 over the sphere */
            {
                double gx[8], gw[8];
                int p, q, sd;
                mft_gl(8, gx, gw);
                pint = 0.0;
                for (sd = 0; sd < 2; ++sd)
                    for (p = 0; p < 8; ++p)
                        for (j = 0; j < 8; ++j) {
                            double mu = (p + gx[j]) / 8.0, sn = sqrt(1.0 - mu * mu);
                            for (q = 0; q < 8; ++q) {
                                double ph = 6.283185307179586 * (q + 0.5) / 8.0;
                                pint += gw[j] / 8.0 * 6.283185307179586 / 8.0 *
                                        (double)mf_dielectric_ms_table_pdf(&t, wo, mf_vec3_make((mf_real)(sn * cos(ph)), (mf_real)(sn * sin(ph)), (mf_real)(sd ? -mu : mu)));
                            }
                        }
                if (fabs(pint - 1.0) > 1e-5) ++bad;
            }
        }
        CHECKV(bad == 0, "mf_dielectric_ms_pdf integrates to 1 over the sphere from both sides");
        mf_dielectric_ms_table_release(&t);
    }
    /* bad input, degenerate directions */
    {
        mf_dielectric_ms_table t;
        mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
        const double inf = HUGE_VAL, nan = inf - inf;
        int ok = 1, bad = 0, a, b;
        mf_vec3 dirs[6];
        ok &= mf_dielectric_ms_table_build(NULL, &d, MF_R(1.5), 8, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_dielectric_ms_table_build(&t, &d, (mf_real)nan, 8, 1) == MF_ERROR_INVALID_ARGUMENT && t.E == NULL;
        ok &= mf_dielectric_ms_table_build(&t, &d, MF_R(0.0), 8, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_dielectric_ms_table_build(&t, &d, MF_R(1.5), 1, 1) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_dielectric_ms_table_build(&t, &d, MF_R(1.5), 8, 65) == MF_ERROR_INVALID_ARGUMENT;
        ok &= mf_dielectric_ms_table_albedo(&t, view(0.5, 0.0)) == 0 && mf_dielectric_ms_table_bsdf(NULL, view(0.5, 0.0), view(0.5, 0.0), MF_RADIANCE) == 0;
        mf_dielectric_ms_table_release(NULL);
        CHECKV(ok, "mf_dielectric_ms_build: bad arguments are MF_ERROR_INVALID_ARGUMENT, nothing allocated");
        mf_dielectric_ms_table_build(&t, &d, MF_R(1.5), 8, 1);
        dirs[0] = mf_vec3_make(0, 0, 1); dirs[1] = mf_vec3_make(1, 0, 0); dirs[2] = mf_vec3_make(0, 0, -1);
        dirs[3] = mf_vec3_make((mf_real)nan, 0, 1); dirs[4] = mf_vec3_make(0, 0, (mf_real)inf); dirs[5] = mf_vec3_make(0, 0, 0);
        for (a = 0; a < 6; ++a) {
            double e = mf_dielectric_ms_table_albedo(&t, dirs[a]), ei = mf_dielectric_albedo_integrate(&d, dirs[a], (mf_real)(a == 1 ? nan : 1.5), 1);
            mf_vec3 w = mf_dielectric_ms_table_sample(&t, dirs[a], MF_RADIANCE, (mf_real)nan, MF_R(0.5), (mf_real)inf).wi;
            double l = (double)w.x * w.x + (double)w.y * w.y + (double)w.z * w.z;
            if (!(e >= 0 && e <= 1) || !(ei >= 0 && ei <= 1) || !mft_finite(l) || !(l == 0.0 || fabs(l - 1.0) < 1e-4)) ++bad;
            for (b = 0; b < 6; ++b) {
                double f = mf_dielectric_ms_table_bsdf(&t, dirs[a], dirs[b], MF_RADIANCE), p = mf_dielectric_ms_table_pdf(&t, dirs[a], dirs[b]);
                if (!mft_finite(f) || f < 0 || !mft_finite(p) || p < 0) ++bad;
            }
        }
        mf_dielectric_ms_table_release(&t);
        CHECKV(bad == 0, "dielectric compensation functions: finite, E in [0, 1], f and pdf >= 0 on degenerate input");
    }
}


/* ---- the built-in dielectric tables (mf_dielectric_albedo, _bsdf_ms) */

/* int f(wo, wi) |wi.z| dwi over the sphere in double, f = mf_dielectric_bsdf
 * in `mode`, over the half vector m (reflection dwi = 4 |wo.m| dm,
 * refraction dwi = (wi.m + wo.m / e)^2 / |wi.m| dm, Walter 2007 Eqs. 14, 17),
 * polar normalized slope u / (1 - u) x azimuth in [0, pi] (wo in the xz
 * plane: the integrand is even in the azimuth), 16 x 8 panels of 8 GL nodes
 * (8 in the slope left 6e-3 at normal incidence from below: the total
 * internal reflection edge is then a circle of m inside a panel);
 * *tr the transmitted part. Uses neither the tables nor the samplers. */
static double ref_diel_albedo(const mf_ndf *d, mf_vec3 wo, double eta, mf_transport mode, double *tr)
{
    static double gx[8], gw[8];
    static int init = 0;
    const double pi = 3.14159265358979324;
    double a = sqrt((double)d->ax * (double)d->ay), e = wo.z > 0 ? eta : 1.0 / eta, sum = 0.0, st = 0.0;
    double sg = wo.z > 0 ? 1.0 : -1.0;
    mf_vec3 w = mf_vec3_make(wo.x, wo.y, (mf_real)fabs((double)wo.z));
    int p, i, q, j;
    if (!init) { mft_gl(8, gx, gw); init = 1; }
    if (a > 1.0) a = 1.0;
    for (p = 0; p < 16; ++p)
        for (i = 0; i < 8; ++i) {
            double u = ((double)p + gx[i]) / 16.0, rho = u / (1.0 - u), drho = 1.0 / ((1.0 - u) * (1.0 - u));
            double th = atan(a * rho), dth = a / (1.0 + a * a * rho * rho) * drho;
            for (q = 0; q < 8; ++q)
                for (j = 0; j < 8; ++j) {
                    double ph = pi * ((double)q + gx[j]) / 8.0, wt = gw[i] * gw[j] / 128.0 * 2.0 * pi * sin(th) * dth;
                    double mx = sin(th) * cos(ph), my = sin(th) * sin(ph), mz = cos(th);
                    double c = (double)w.x * mx + (double)w.y * my + (double)w.z * mz, ct2, ct, f;
                    mf_vec3 wi;
                    if (!(c > 0.0)) continue;
                    /* reflection */
                    wi = mf_vec3_make((mf_real)(2.0 * c * mx - w.x), (mf_real)(2.0 * c * my - w.y), (mf_real)(2.0 * c * mz - w.z));
                    if (wi.z > 0) {
                        f = (double)mf_dielectric_bsdf(d, wo, mf_vec3_make(wi.x, wi.y, (mf_real)(sg * wi.z)), (mf_real)eta, mode);
                        sum += wt * f * (double)wi.z * 4.0 * c;
                    }
                    /* refraction (Snell: sin t = sin i / e) */
                    ct2 = 1.0 - (1.0 - c * c) / (e * e);
                    if (ct2 <= 0.0) continue;
                    ct = sqrt(ct2);
                    {
                        double tx = -w.x / e + (c / e - ct) * mx, ty = -w.y / e + (c / e - ct) * my, tz = -w.z / e + (c / e - ct) * mz;
                        double im = tx * mx + ty * my + tz * mz, den = (im + c / e) * (im + c / e);
                        if (!(tz < 0.0)) continue;
                        f = (double)mf_dielectric_bsdf(d, wo, mf_vec3_make((mf_real)tx, (mf_real)ty, (mf_real)(sg * tz)), (mf_real)eta, mode);
                        f *= wt * -tz * den / fabs(im);
                        sum += f;
                        st += f;
                    }
                }
        }
    if (tr) *tr = st;
    return sum;
}

/* int mf_dielectric_bsdf_ms |wi.z| dwi over both hemispheres in `mode`: GL
 * in x = sqrt(|mu|), 8 x 8 nodes, 4 azimuths (the lobe depends on |wi.z|) */
static double ref_diel_ms_builtin(const mf_ndf *d, mf_vec3 wo, double eta, mf_transport mode)
{
    double gx[8], gw[8], sum = 0.0;
    int p, i, q, side;
    mft_gl(8, gx, gw);
    for (side = 0; side < 2; ++side)
        for (p = 0; p < 8; ++p)
            for (i = 0; i < 8; ++i) {
                double x = ((double)p + gx[i]) / 8.0, mu = x * x, sn = sqrt(1.0 - mu * mu);
                for (q = 0; q < 4; ++q) {
                    double ph = 2.0 * 3.14159265358979324 * (q + 0.5) / 4.0;
                    mf_vec3 wi = mf_vec3_make((mf_real)(sn * cos(ph)), (mf_real)(sn * sin(ph)), (mf_real)(side ? -mu : mu));
                    sum += gw[i] / 8.0 * 2.0 * x * (2.0 * 3.14159265358979324 / 4.0) * (double)mf_dielectric_bsdf_ms(d, wo, wi, (mf_real)eta, mode) * mu;
                }
            }
    return sum;
}

static void builtin_dielectric(void)
{
    static const double alphas[] = { 0.01, 0.05, 0.2, 0.5, 1.0 };
    static const double etas[] = { 1.05, 1.33, 2.0, 3.0 };
    static const double mus[] = { 1e-3, 0.02, 0.1, 0.4, 0.8, 1.0 };
    char msg[400];
    int k, ia, ie, im, side;
    for (k = 0; k < 2; ++k) {
        double worst = 0.0, wa = 0, we = 0, wm = 0, worst_rel = 0.0, worst_t = 0.0, wta = 0, wte = 0, wtm = 0;
        int ws = 0, wts = 0, n = 0, bad_mode = 0;
        for (ia = 0; ia < 5; ++ia) {
            mf_ndf d = k ? mf_beckmann((mf_real)alphas[ia], (mf_real)alphas[ia]) : mf_ggx((mf_real)alphas[ia], (mf_real)alphas[ia]);
            for (ie = 0; ie < 4; ++ie)
                for (im = 0; im < 6; ++im)
                    for (side = 0; side < 2; ++side) {
                        mf_vec3 wo = view(mus[im], 0.0);
                        double t, e_ref, tot, e_rad, e_tab, e_tab_rad, e2, ms_i, ms_r, x;
                        if (side) wo.z = -wo.z;
                        e_ref = ref_diel_albedo(&d, wo, etas[ie], MF_IMPORTANCE, &t);
                        tot = e_ref + (ms_i = ref_diel_ms_builtin(&d, wo, etas[ie], MF_IMPORTANCE));
                        ++n;
                        if (fabs(tot - 1.0) > worst) { worst = fabs(tot - 1.0); wa = alphas[ia]; we = etas[ie]; wm = mus[im]; ws = side; }
                        /* the radiance albedo: R + T / e^2 (e = eta_i / eta_o) */
                        x = side ? etas[ie] : 1.0 / etas[ie];
                        e_rad = e_ref - t + t * x * x;
                        if (im == 3 && fabs(ref_diel_albedo(&d, wo, etas[ie], MF_RADIANCE, 0) - e_rad) > 1e-6 * (1.0 + e_rad)) ++bad_mode;
                        e_tab = (double)mf_dielectric_albedo(&d, wo, (mf_real)etas[ie], MF_IMPORTANCE);
                        e_tab_rad = (double)mf_dielectric_albedo(&d, wo, (mf_real)etas[ie], MF_RADIANCE);
                        e2 = e_tab_rad - e_rad;
                        if (fabs(e2) > worst_t) { worst_t = fabs(e2); wta = alphas[ia]; wte = etas[ie]; wtm = mus[im]; wts = side; }
                        if (!(e_tab >= 0.0 && e_tab <= 1.0)) ++bad_mode;
                        /* the lobe in radiance: its transmitted part carries 1 / e^2 */
                        ms_r = ref_diel_ms_builtin(&d, wo, etas[ie], MF_RADIANCE);
                        {
                            mf_vec3 wi = view(0.5, 1.0);
                            double fi, fr;
                            wi.z = side ? wi.z : -wi.z;   /* the other side */
                            fi = (double)mf_dielectric_bsdf_ms(&d, wo, wi, (mf_real)etas[ie], MF_IMPORTANCE);
                            fr = (double)mf_dielectric_bsdf_ms(&d, wo, wi, (mf_real)etas[ie], MF_RADIANCE);
                            if (fabs(fr - fi * x * x) > MFT_TOL(1e-12, 1e-5) * (fi * x * x + 1e-6)) ++bad_mode;
                        }
                        if (!(ms_r >= 0.0) || !(ms_i >= 0.0)) ++bad_mode;
                        (void)worst_rel;
                    }
        }
        /* the sampler's record: pdf = mf_dielectric_bsdf_ms_pdf, weight = f |cos| / pdf */
        {
            mf_ndf d = k ? mf_beckmann(MF_R(0.4), MF_R(0.4)) : mf_ggx(MF_R(0.4), MF_R(0.4));
            mft_rng r;
            int i2, bad_rec = 0;
            mft_seed(&r, 17 + k);
            for (i2 = 0; i2 < 200; ++i2) {
                mf_vec3 wo = view(0.05 + 0.95 * mft_u01(&r), 1.0);
                mf_sample sm;
                double p2, f2;
                if (i2 & 1) wo.z = -wo.z;
                sm = mf_dielectric_bsdf_ms_sample(&d, wo, MF_R(1.5), MF_RADIANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                if (sm.lobe == MF_LOBE_NONE) continue;
                p2 = (double)mf_dielectric_bsdf_ms_pdf(&d, wo, sm.wi, MF_R(1.5));
                f2 = (double)mf_dielectric_bsdf_ms(&d, wo, sm.wi, MF_R(1.5), MF_RADIANCE);
                if (fabs(p2 - (double)sm.pdf) > 1e-5 * p2 || fabs(f2 * fabs((double)sm.wi.z) / p2 - (double)sm.weight) > 1e-4 * (double)sm.weight + 1e-9) ++bad_rec;
            }
            snprintf(msg, sizeof msg, "%s mf_dielectric_bsdf_ms_sample's record matches mf_dielectric_bsdf_ms_pdf and f |cos| / pdf (%d of 200 off)", k ? "Beckmann" : "GGX", bad_rec);
            CHECKV(bad_rec == 0, msg);
        }
        /* the sampler follows the pdf: chi-square over 2 sides x 10 x 8 bins */
        {
            static double obs[160], ex[160];
            mf_ndf d = k ? mf_beckmann(MF_R(0.3), MF_R(0.3)) : mf_ggx(MF_R(0.6), MF_R(0.6));
            mft_rng r;
            int s0, i2, dof;
            double z;
            for (s0 = 0; s0 < 2; ++s0) {
                mf_vec3 wo = view(0.5, 0.2);
                if (s0) wo.z = -wo.z;
                mft_seed(&r, 31 + s0 + 2 * k);
                for (i2 = 0; i2 < 160; ++i2) {
                    /* the pdf is the side's share times cos / pi: each of the 80 bins
                     * of equal cos-weighted solid angle holds share / 80 */
                    double share = (double)mf_dielectric_bsdf_ms_pdf(&d, wo, mf_vec3_make(0, 0, i2 >= 80 ? -1 : 1), MF_R(1.5)) * 3.14159265358979324;
                    obs[i2] = 0.0;
                    ex[i2] = 50000.0 * share / 80.0;
                }
                for (i2 = 0; i2 < 50000; ++i2) {
                    mf_sample sm = mf_dielectric_bsdf_ms_sample(&d, wo, MF_R(1.5), MF_RADIANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                    double ph, az;
                    int b0, b1;
                    if (sm.lobe == MF_LOBE_NONE) continue;
                    ph = atan2((double)sm.wi.y, (double)sm.wi.x); az = fabs((double)sm.wi.z);
                    if (ph < 0) ph += 2.0 * 3.14159265358979324;
                    b0 = (int)((1.0 - az * az) * 10.0); if (b0 > 9) b0 = 9; if (b0 < 0) b0 = 0;
                    b1 = (int)(ph / (2.0 * 3.14159265358979324) * 8.0); if (b1 > 7) b1 = 7;
                    obs[(sm.wi.z < 0 ? 80 : 0) + b0 * 8 + b1] += 1.0;
                }
                z = mft_chi2(obs, ex, 160, &dof);
                snprintf(msg, sizeof msg, "%s mf_dielectric_bsdf_ms_sample from %s follows mf_dielectric_bsdf_ms_pdf: chi-square z = %.2f (dof %d)",
                         k ? "Beckmann" : "GGX", s0 ? "below" : "above", z, dof);
                CHECKV(fabs(z) < 5.0, msg);
            }
        }
        snprintf(msg, sizeof msg, "%s built-in dielectric white furnace (importance), %d views (alpha 0.01..1, eta 1.05..3, both sides, mu 1e-3..1): "
                 "worst |1 - albedo| %.2e (alpha %g, eta %g, mu %g, %s) <= 6e-3", k ? "Beckmann" : "GGX", n, worst, wa, we, wm, ws ? "below" : "above");
        CHECKV(worst <= 6e-3, msg);
        snprintf(msg, sizeof msg, "%s mf_dielectric_albedo in radiance transport vs R + T / e^2 of the reference: worst %.2e (alpha %g, eta %g, mu %g, %s) <= 0.15",
                 k ? "Beckmann" : "GGX", worst_t, wta, wte, wtm, wts ? "below" : "above");
        CHECKV(worst_t <= 0.15, msg);
        snprintf(msg, sizeof msg, "%s dielectric transport modes: radiance = importance with T / e^2, lobe's transmission / e^2 (%d off)", k ? "Beckmann" : "GGX", bad_mode);
        CHECKV(bad_mode == 0, msg);
    }
}

void test_energy(void)
{
    tables_and_furnace();
    anisotropic();
    builder();
    fresnel_and_sampling();
    robust();
    dielectric();
    builtin_dielectric();
}
