/* LEADR slope moments and moment maps (Dupuy et al. 2013): linearity,
 * deformation (Eq. 12) against deforming every slope sample, height scaling,
 * roughness, mean normal (Eq. 11), the covariance guard; the mip pyramid of a
 * periodic height map (every coarse texel the exact mean of its children,
 * slopes against the analytic derivative), lookups (texel exactness, wrap,
 * coarsest level = mean of all), and bad input. Tolerances 1e-12 relative in
 * double (1e-5 in float) for identities; 5e-3 for the central-difference
 * slopes of the test's sinusoids (truncation error k^2 h^2 / 6 times the
 * amplitude, 4e-3 in sum for the highest frequency on 32 rows). */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

static int near_m(mf_leadr a, mf_leadr b, double tol)
{
    double s = 1.0 + fabs((double)b.E_xx) + fabs((double)b.E_yy);
    return fabs((double)(a.E_x - b.E_x)) < tol * s && fabs((double)(a.E_y - b.E_y)) < tol * s &&
           fabs((double)(a.E_xx - b.E_xx)) < tol * s && fabs((double)(a.E_yy - b.E_yy)) < tol * s &&
           fabs((double)(a.E_xy - b.E_xy)) < tol * s;
}

static void test_moments(void)
{
    mft_rng r;
    int i, k, bad = 0;
    const double tol = MFT_TOL(1e-12, 1e-5);
    mft_seed(&r, 8);
    for (k = 0; k < 20; ++k) {
        mf_mat2 J = mf_mat2_make((mf_real)(2 * mft_u01(&r) - 1), (mf_real)(2 * mft_u01(&r) - 1),
                                 (mf_real)(2 * mft_u01(&r) - 1), (mf_real)(2 * mft_u01(&r) - 1));
        mf_leadr sum = mf_leadr_scale(mf_leadr_from_slope(0, 0), 0), dsum = sum, hsum = sum, avg;
        mf_real eta = (mf_real)(3 * mft_u01(&r));
        for (i = 0; i < 16; ++i) {
            mf_real su = (mf_real)(2 * mft_u01(&r) - 1), sv = (mf_real)(2 * mft_u01(&r) - 1);
            /* x = du/dx su + dv/dx sv, y = du/dy su + dv/dy sv */
            mf_real x = J.m00 * su + J.m10 * sv, y = J.m01 * su + J.m11 * sv;
            sum = mf_leadr_add(sum, mf_leadr_from_slope(su, sv));
            dsum = mf_leadr_add(dsum, mf_leadr_from_slope(x, y));
            hsum = mf_leadr_add(hsum, mf_leadr_from_slope(eta * su, eta * sv));
        }
        avg = mf_leadr_scale(sum, MF_R(1.0) / 16);
        if (!near_m(mf_leadr_deform(avg, J), mf_leadr_scale(dsum, MF_R(1.0) / 16), tol)) ++bad;
        if (!near_m(mf_leadr_height_scale(avg, eta), mf_leadr_scale(hsum, MF_R(1.0) / 16), tol)) ++bad;
        if (!near_m(mf_leadr_lerp(avg, sum, MF_R(0.25)), mf_leadr_add(mf_leadr_scale(avg, MF_R(0.75)), mf_leadr_scale(sum, MF_R(0.25))), tol)) ++bad;
    }
    MFT_CHECK(bad == 0, "moments: deformation (Eq. 12), height scaling and lerp act like the slope samples");
    {
        mf_leadr a = mf_leadr_from_slope(MF_R(0.3), MF_R(-0.2)), b = mf_leadr_with_roughness(a, MF_R(0.4), MF_R(0.1));
        mf_real vx, vy, c;
        mf_vec3 n = mf_leadr_mean_normal(a);
        int ok = mf_leadr_to_covariance(b, &vx, &vy, &c) == MF_SUCCESS;
        MFT_NEAR(vx, 0.08, tol, tol, "roughness adds alpha_x^2 / 2");
        MFT_NEAR(vy, 0.005, tol, tol, "roughness adds alpha_y^2 / 2");
        MFT_CHECK(ok == 1 && fabs((double)c) < 1e-6, "valid covariance passes the guard");
        MFT_NEAR(n.x, -0.3 / sqrt(1.13), tol, tol, "mean normal (Eq. 11) x");
        MFT_NEAR(n.z, 1.0 / sqrt(1.13), tol, tol, "mean normal (Eq. 11) z");
        ok = mf_leadr_to_covariance(a, &vx, &vy, &c) == MF_SUCCESS;   /* a single slope: zero variance */
        MFT_CHECK(ok == 0 && vx >= MF_LEADR_MIN_VARIANCE && vy >= MF_LEADR_MIN_VARIANCE && fabs((double)c) <= sqrt((double)vx * vy),
                  "degenerate covariance guarded");
        b.E_xy = 10;
        ok = mf_leadr_to_covariance(b, &vx, &vy, &c) == MF_SUCCESS;
        MFT_CHECK(ok == 0 && fabs((double)c) <= 0.9991 * sqrt((double)vx * vy), "correlation clamped below 1");
        b.E_xx = (mf_real)(HUGE_VAL - HUGE_VAL);
        ok = mf_leadr_to_covariance(b, &vx, &vy, &c) == MF_SUCCESS;
        MFT_CHECK(ok == 0 && vx == MF_LEADR_MIN_VARIANCE, "NaN moments guarded");
    }
}

static void test_maps(void)
{
    const int W = 64, H = 32;
    mf_real *h = (mf_real *)malloc(sizeof(mf_real) * W * H), *nrm = (mf_real *)malloc(sizeof(mf_real) * 3 * W * H);
    mf_leadr_map m;
    int x, y, l, bad = 0;
    double worst = 0;
    const double pi = 3.14159265358979323846, tol = MFT_TOL(1e-12, 1e-5);
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            double u = (x + 0.5) / W, v = (y + 0.5) / H;
            h[y * W + x] = (mf_real)(0.01 * sin(2 * pi * u) + 0.005 * cos(4 * pi * v) + 0.002 * sin(2 * pi * (u + 3 * v)));
        }
    MFT_CHECK(mf_leadr_map_from_heights(&m, h, W, H, MF_R(0.1), MF_R(0.2)) == MF_SUCCESS, "moment map from heights");
    MFT_CHECK(m.levels == 7 && mf_leadr_map_memory_bytes(&m) == sizeof(mf_leadr) * (64 * 32 + 32 * 16 + 16 * 8 + 8 * 4 + 4 * 2 + 2 + 1),
              "pyramid levels and memory");
    /* slopes against the analytic gradient (rows top to bottom, v down) */
    for (y = 0; y < H; ++y)
        for (x = 0; x < W; ++x) {
            double u = (x + 0.5) / W, v = (y + 0.5) / H;
            double du = 0.02 * pi * cos(2 * pi * u) + 0.004 * pi * cos(2 * pi * (u + 3 * v));
            double dv = -0.02 * pi * sin(4 * pi * v) + 0.012 * pi * cos(2 * pi * (u + 3 * v));
            const mf_leadr *t = m.texels + y * W + x;
            double e = fabs(t->E_x - du) + fabs(t->E_y - dv);
            if (e > worst) worst = e;
            if (fabs((double)t->E_xx - (double)t->E_x * t->E_x - 0.005) > 1e-6) ++bad;
        }
    MFT_CHECK(worst < 5e-3, "slopes of a periodic height map match the analytic gradient");
    MFT_CHECK(bad == 0, "base roughness in every texel");
    /* each coarse texel is the exact mean of its children */
    bad = 0;
    for (l = 1; l < m.levels; ++l) {
        int w = W >> l > 0 ? W >> l : 1, hh = H >> l > 0 ? H >> l : 1, pw = W >> (l - 1) > 0 ? W >> (l - 1) : 1, ph = H >> (l - 1) > 0 ? H >> (l - 1) : 1;
        int sx = pw > w ? 2 : 1, sy = ph > hh ? 2 : 1;
        for (y = 0; y < hh; ++y)
            for (x = 0; x < w; ++x) {
                mf_leadr acc = mf_leadr_scale(mf_leadr_from_slope(0, 0), 0);
                int a, b;
                for (b = 0; b < sy; ++b)
                    for (a = 0; a < sx; ++a) acc = mf_leadr_add(acc, m.texels[m.offset[l - 1] + (y * sy + b) * pw + x * sx + a]);
                if (!near_m(m.texels[m.offset[l] + y * w + x], mf_leadr_scale(acc, MF_R(1.0) / (mf_real)(sx * sy)), tol)) ++bad;
            }
    }
    MFT_CHECK(bad == 0, "every coarse mip texel is the mean of the finer ones");
    /* lookups */
    {
        mf_leadr t0 = mf_leadr_map_lookup(&m, (mf_real)(5.5 / W), (mf_real)(7.5 / H), MF_R(1e-6));
        mf_leadr tw = mf_leadr_map_lookup(&m, (mf_real)(5.5 / W + 1.0), (mf_real)(7.5 / H - 2.0), MF_R(1e-6));
        mf_leadr top = mf_leadr_map_lookup(&m, MF_R(0.3), MF_R(0.8), MF_R(4.0));
        MFT_CHECK(near_m(t0, m.texels[7 * W + 5], tol), "lookup at a texel center, finest level: the texel");
        MFT_CHECK(near_m(tw, t0, MFT_TOL(1e-9, 1e-4)), "lookup wraps (the texture tiles)");
        MFT_CHECK(near_m(top, m.texels[m.offset[m.levels - 1]], tol), "huge footprint: the mean of the whole map");
        MFT_NEAR(top.E_x, 0.0, 0, 1e-6, "mean slope of a periodic height map is 0");
    }
    mf_leadr_map_release(&m);
    MFT_CHECK(m.texels == NULL && m.levels == 0, "map released");
    /* from normals: the same slopes */
    for (x = 0; x < W * H; ++x) {
        mf_vec3 n = mf_normalize(mf_vec3_make((mf_real)(0.1 * sin(x * 0.3)), (mf_real)(0.05 * cos(x * 0.7)), 1));
        nrm[3 * x] = n.x; nrm[3 * x + 1] = n.y; nrm[3 * x + 2] = n.z;
    }
    MFT_CHECK(mf_leadr_map_from_normals(&m, nrm, W, H, 0, 0) == MF_SUCCESS &&
              fabs((double)m.texels[10].E_x - (-nrm[30] / nrm[32])) < tol, "moment map from normals");
    mf_leadr_map_release(&m);
    /* bad input */
    MFT_CHECK(mf_leadr_map_from_heights(&m, NULL, W, H, 0, 0) == MF_ERROR_INVALID_ARGUMENT && m.texels == NULL, "NULL heights");
    MFT_CHECK(mf_leadr_map_from_heights(&m, h, 0, H, 0, 0) == MF_ERROR_INVALID_ARGUMENT && m.texels == NULL, "zero size");
    MFT_CHECK(mf_leadr_map_from_heights(&m, h, 48, H, 0, 0) == MF_ERROR_INVALID_ARGUMENT && m.texels == NULL, "size not a power of two");
    h[17] = (mf_real)(HUGE_VAL - HUGE_VAL);
    MFT_CHECK(mf_leadr_map_from_heights(&m, h, W, H, 0, 0) == MF_ERROR_INVALID_DATA && m.texels == NULL, "NaN height");
    nrm[5] = -1;
    MFT_CHECK(mf_leadr_map_from_normals(&m, nrm, W, H, 0, 0) == MF_ERROR_INVALID_DATA && m.texels == NULL, "normal below the horizon");
    MFT_CHECK(mf_leadr_map_from_heights(NULL, h, W, H, 0, 0) == MF_ERROR_INVALID_ARGUMENT, "NULL map");
    free(h);
    free(nrm);
}

static mf_leadr moments(double mx, double my, double vx, double vy, double rho)
{
    mf_leadr a;
    double c = rho * sqrt(vx * vy);
    a.E_x = (mf_real)mx; a.E_y = (mf_real)my;
    a.E_xx = (mf_real)(vx + mx * mx); a.E_yy = (mf_real)(vy + my * my); a.E_xy = (mf_real)(c + mx * my);
    return a;
}

/* the non-centered Beckmann distribution through the generic operations */
static void test_ndf_kind(void)
{
    const double thetas[] = { 0.0, 0.4, 0.9, 1.3 };
    char msg[200];
    int k, j;
    for (k = 0; k < 3; ++k) {
        mf_leadr a = k == 0 ? moments(0.15, -0.1, 0.04, 0.09, 0.5) : k == 1 ? moments(-0.3, 0.2, 0.02, 0.01, -0.7)
                                                                      : moments(0.0, 0.0, 0.05, 0.05, 0.0);
        mf_ndf d = mf_leadr_ndf(a), b = mf_beckmann(MF_R(0.31622776601683794), MF_R(0.31622776601683794));
        MFT_NEAR(mft_norm_integral(&d), 1.0, MFT_TOL(1e-7, 2e-4), 0, "LEADR NDF normalized (Eq. 8, 10)");
        for (j = 0; j < 4; ++j) {
            mf_vec3 v = mft_dir(thetas[j], 0.5 + 1.7 * j);
            double proj = (double)v.z - a.E_x * v.x - a.E_y * v.y;
            snprintf(msg, sizeof msg, "LEADR projected-area identity (supplement Eq. 9), moments %d theta %.1f", k, thetas[j]);
            MFT_NEAR(mft_visible_integral(&d, v, 0), proj * (1.0 + mf_lambda(&d, v)), MFT_TOL(1e-7, 2e-4), 0, msg);
            snprintf(msg, sizeof msg, "LEADR integral of D_visible, moments %d theta %.1f", k, thetas[j]);
            MFT_NEAR(mft_visible_integral(&d, v, 1), 1.0, MFT_TOL(1e-7, 2e-4), 0, msg);
            snprintf(msg, sizeof msg, "LEADR moments %d", k);
            mft_sampler_check(msg, &d, v, 1, 100000, 0, 7000 + 10 * k + j);
        }
        mft_sampler_check("LEADR", &d, mf_vec3_make(0, 0, 1), 0, 100000, 0, 7100 + k);
        mft_brdf_check(k == 0 ? "LEADR 0" : k == 1 ? "LEADR 1" : "LEADR 2", d, mft_dir(0.6, 2.5), 60000, 7200 + k, 0);
        if (k == 2) {   /* centered: the Beckmann distribution of alpha = sqrt(2 sigma^2) */
            mf_vec3 m = mft_dir(0.3, 1.0), v = mft_dir(1.0, 2.0);
            MFT_NEAR(mf_D(&d, m), mf_D(&b, m), MFT_TOL(1e-12, 1e-5), 0, "centered LEADR D is Beckmann");
            MFT_NEAR(mf_lambda(&d, v), mf_lambda(&b, v), MFT_TOL(1e-12, 1e-5), 1e-7, "centered LEADR Lambda is Beckmann");
        }
        /* Eq. 17 and Eq. 16 integrating to one without shadowing: with Lambda(wi)
         * dropped the integral over wi is (1 + Lambda(wo)) / (1 + Lambda(wo)) = 1,
         * i.e. the projected-area identity above; here Eq. 17 itself */
        {
            mf_vec3 wo = mft_dir(0.5, 0.3), wi = mft_dir(0.7, 3.0), wh = mf_normalize(mf_add(wo, wi));
            double want = mf_D(&d, wh) / (4.0 * ((double)wo.z - a.E_x * wo.x - a.E_y * wo.y) * (1.0 + mf_lambda(&d, wo) + mf_lambda(&d, wi)));
            MFT_NEAR(mf_leadr_specular(a, wo, wi), want, MFT_TOL(1e-12, 1e-5), 0, "LEADR specular (Eq. 17)");
        }
    }
    {
        mf_ndf d = mf_leadr_ndf(moments(0.8, 0.0, 0.01, 0.01, 0.0));
        mf_vec3 below = mf_normalize(mf_vec3_make(1, 0, MF_R(0.5)));   /* cot = 0.5 < mean slope 0.8 */
        MFT_CHECK(mf_G1(&d, below, mf_vec3_make(0, 0, 1)) < 1e-6 && mft_finite(mf_lambda(&d, below)), "direction below the mean surface: masked");
    }
    {   /* regression: viewer below the mean surface gave D/(4 wi.z) in float */
        mf_leadr a;
        mf_vec3 wo = mf_vec3_make(MF_R(0.5463), MF_R(-0.8347), MF_R(0.0692)), wi = mf_vec3_make(MF_R(-0.5999), MF_R(0.8001), MF_R(0.00225));
        a.E_x = MF_R(0.790454); a.E_y = MF_R(0.279968);
        a.E_xx = MF_R(0.00279) + a.E_x * a.E_x; a.E_yy = MF_R(0.0515) + a.E_y * a.E_y; a.E_xy = a.E_x * a.E_y;
        {
            mf_ndf d = mf_leadr_ndf(a);
            MFT_CHECK(mf_brdf(&d, wo, wi) == 0 && mf_leadr_specular(a, wo, wi) == 0, "viewer below the mean surface: BRDF 0");
        }
    }
}

static mf_vec3 env_smooth(mf_vec3 wi, mf_real solid_angle, void *ctx)
{
    mf_real v = MF_R(1.0) + MF_R(0.5) * wi.x + wi.z;
    (void)solid_angle; (void)ctx;
    return mf_vec3_make(v, v, v);
}

/* dense reference of the grid sums: tensor Gauss-Legendre over slopes within
 * 7 standard deviations of the mean */
static double dense(mf_leadr a, mf_vec3 wo, int mode, mf_vec3 wl)
{
    mf_ndf d = mf_leadr_ndf(a);
    double gx[8], gw[8], sum = 0, sx = sqrt((double)d.p.leadr.vx), sy = sqrt((double)d.p.leadr.vy);
    double lo = mf_lambda(&d, wo), proj = (double)wo.z - a.E_x * wo.x - a.E_y * wo.y;
    int i, j, pi, pj;
    const int P = 60;
    mft_gl(8, gx, gw);
    for (pi = 0; pi < P; ++pi)
        for (i = 0; i < 8; ++i)
            for (pj = 0; pj < P; ++pj)
                for (j = 0; j < 8; ++j) {
                    double x = a.E_x + sx * (-7 + 14.0 * (pi + gx[i]) / P), y = a.E_y + sy * (-7 + 14.0 * (pj + gx[j]) / P);
                    double w = gw[i] * gw[j] * (14.0 * sx / P) * (14.0 * sy / P), n = sqrt(1 + x * x + y * y), on, c2;
                    mf_vec3 wn = mf_vec3_make((mf_real)(-x / n), (mf_real)(-y / n), (mf_real)(1 / n)), wi;
                    on = mf_dot(wn, wo);
                    if (on <= 0) continue;
                    c2 = 1.0 / (n * n);
                    w *= (double)mf_D(&d, wn) * c2 * c2;   /* P22 */
                    if (mode == 0) {
                        wi = mf_reflect(wo, wn);
                        if (wi.z <= 0) continue;
                        sum += w * (double)env_smooth(wi, 0, NULL).x * on / wn.z / (1 + lo + mf_lambda(&d, wi));
                    } else {
                        double ni = mf_dot(wn, wl);
                        if (ni <= 0) continue;
                        sum += w * ni / (1 + lo + mf_lambda(&d, wl)) * on / wn.z / 3.14159265358979323846;
                    }
                }
    return sum / proj;
}

static void test_grid_shading(void)
{
    mf_leadr a = moments(0.15, -0.1, 0.04, 0.09, 0.5);
    mf_vec3 wo = mft_dir(0.6, 0.4), wl = mft_dir(0.9, 2.5);
    double rd = dense(a, wo, 1, wl), re = dense(a, wo, 0, wl), ed[4], ee[4];
    const int ns[4] = { 5, 9, 17, 33 };
    char msg[200];
    int k;
    for (k = 0; k < 4; ++k) {
        ed[k] = fabs(mf_leadr_diffuse(a, wo, wl, ns[k]) / rd - 1);
        ee[k] = fabs(mf_leadr_specular_env(a, wo, ns[k], 1, env_smooth, NULL).x / re - 1);
    }
    printf("    LEADR grids vs dense integrals, N = 5, 9, 17, 33: diffuse %.2g %.2g %.2g %.2g; environment %.2g %.2g %.2g %.2g\n",
           ed[0], ed[1], ed[2], ed[3], ee[0], ee[1], ee[2], ee[3]);
    snprintf(msg, sizeof msg, "LEADR diffuse grid converges (N=33 error %.2g, N=5 %.2g)", ed[3], ed[0]);
    MFT_CHECK(ed[3] < 2e-3 && ed[3] < ed[0], msg);
    snprintf(msg, sizeof msg, "LEADR environment grid converges (N=33 error %.2g, N=5 %.2g)", ee[3], ee[0]);
    MFT_CHECK(ee[3] < 2e-3 && ee[3] < ee[0], msg);
    MFT_CHECK(mf_leadr_diffuse_noshadow(a, wo, wl, 5) >= mf_leadr_diffuse(a, wo, wl, 5), "without shadowing is brighter");
    MFT_CHECK(mf_leadr_diffuse(a, mft_dir(2.0, 0), wl, 5) == 0, "wo below the horizon: 0");
    /* SH9: one directional light against the order-2 clamped-cosine
     * convolution L (1/4 + mu/2 + 5/32 (3 mu^2 - 1)); a constant environment
     * gives albedo-1 diffuse = L exactly; the artificial micronormal keeps a
     * back-facing mesonormal defined */
    {
        mf_real sh[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 }, c[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
        mft_rng rr;
        double worst = 0;
        int i;
        mft_seed(&rr, 3);
        mf_sh9_add_directional(sh, wl, MF_R(2.0));
        for (i = 0; i < 100; ++i) {
            mf_vec3 nn = mft_dir(3.14159 * mft_u01(&rr), 6.283 * mft_u01(&rr));
            double mu = mf_dot(nn, wl), want = 2.0 * (0.25 + mu / 2 + 5.0 / 32 * (3 * mu * mu - 1));
            if (fabs(mf_sh9_irradiance(sh, nn) - want) > worst) worst = fabs(mf_sh9_irradiance(sh, nn) - want);
        }
        MFT_CHECK(worst < 2e-5, "SH9 irradiance of a directional light (order-2 clamped cosine)");
        c[0] = (mf_real)(3.0 * 3.5449077018110318);   /* L00 = L sqrt(4 pi) for constant radiance L = 3 */
        MFT_NEAR(mf_leadr_diffuse_sh9(a, wo, c, 5), 3.0 * 3.5449077018110318 * 0.886227 / 3.14159265358979323846, 1e-5, 0,
                 "SH9 diffuse of a constant environment");
        {
            mf_leadr back = moments(2.5, 0.0, 0.01, 0.01, 0.0);   /* mesonormal tilted away from wo */
            mf_vec3 w2 = mft_dir(1.2, 0.0);
            double v = mf_leadr_diffuse_sh9(back, w2, c, 5);
            MFT_CHECK(mft_finite(v) && v > 0, "artificial micronormal: defined when the mesonormal faces away");
        }
    }
}

void test_leadr(void)
{
    test_moments();
    test_maps();
    test_ndf_kind();
    test_grid_shading();
}
