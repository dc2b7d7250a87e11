/* Volumetric sheen (23_sheen_volume.h), against references written here in
 * double:
 *  - the lobe: int pdf dw = 1 and int f cos dw = mf_sheen_albedo by
 *    quadrature over the hemisphere (in plane coordinates, where the
 *    grazing lobes of low alpha are smooth bumps), nothing below the
 *    horizon;
 *  - the table against the layer itself: the albedo of a slab of unit
 *    thickness and density of fibre-like SGGX microflakes over a black base
 *    (Zeltner et al. 2022), simulated here by random walks that pick
 *    directions uniformly and weight them by the phase function (so no
 *    visible-normal sampler is shared with tools/sheen_fit.c), at table
 *    nodes; tolerance 4 standard deviations of the estimate plus the
 *    table's own noise;
 *  - the sampler by chi-square against mf_sheen_pdf, its record (pdf =
 *    mf_sheen_pdf, weight = f cos / pdf), u in {0, 1} corners and grazing
 *    views, and every function on special values. */
#include "mf_test.h"
#include <stdlib.h>

#define SH_PI 3.14159265358979323846

/* ---- quadrature on the sphere about a pole ---------------------------------- */
typedef double (*sh_fn)(mf_vec3 w, const void *ctx);
typedef struct { mf_vec3 wo; double alpha; int what; } sh_ctx;   /* what: 0 pdf, 1 f cos, 2 pdf below the horizon */
static double sh_g(mf_vec3 w, const void *p)
{
    const sh_ctx *c = (const sh_ctx *)p;
    if (c->what == 2) return w.z <= 0 ? (double)mf_sheen_pdf(c->wo, w, (mf_real)c->alpha) : 0.0;
    if (c->what == 1) return (double)mf_sheen_brdf(c->wo, w, (mf_real)c->alpha) * (double)w.z;
    return (double)mf_sheen_pdf(c->wo, w, (mf_real)c->alpha);
}
/* int g over the upper hemisphere in plane coordinates, w = (x, y, 1) / |.|,
 * dw = dx dy / (1 + x^2 + y^2)^(3/2): polar about (cx, cy), radius
 * r = h t / (1 - t), t in 24 panels, azimuth in 32; 16-point Gauss-Legendre
 * in each. The plane holds the grazing directions that low alpha favours at
 * finite distance, with no kink at the horizon; (cx, cy) and h only place
 * the nodes (any values converge). */
static double sh_plane(sh_fn g, const void *ctx, double cx, double cy, double h)
{
    double x[16], w[16], sum = 0.0;
    int k, i, j, q;
    mft_gl(16, x, w);
    for (k = 0; k < 24; ++k)
        for (i = 0; i < 16; ++i) {
            double t = (k + x[i]) / 24.0, r = h * t / (1.0 - t), dr = h / ((1.0 - t) * (1.0 - t)) / 24.0;
            for (q = 0; q < 32; ++q)
                for (j = 0; j < 16; ++j) {
                    double ph = 2.0 * SH_PI * (q + x[j]) / 32.0, px = cx + r * cos(ph), py = cy + r * sin(ph);
                    double l2 = 1.0 + px * px + py * py, l = sqrt(l2);
                    mf_vec3 d = mf_vec3_make((mf_real)(px / l), (mf_real)(py / l), (mf_real)(1.0 / l));
                    sum += w[i] * dr * w[j] * (2.0 * SH_PI / 32.0) * r * g(d, ctx) / (l2 * l);
                }
        }
    return sum;
}

static void test_sheen_lobe(void)
{
    static const double al[5] = { 0.05, 0.1, 0.3, 0.6, 1.0 };
    static const double th[5] = { 0.0, 40.0, 75.0, 89.0, 89.9 };
    double worst_n = 0.0, worst_a = 0.0;
    int i, j, k, below = 0;
    for (i = 0; i < 5; ++i)
        for (j = 0; j < 5; ++j) {
            sh_ctx c;
            mf_vec3 p0, p1;
            double n, e, alb, cx, cy, h;
            c.wo = mft_dir(th[j] * SH_PI / 180.0, 0.4 + j);
            c.alpha = al[i];
            alb = (double)mf_sheen_albedo(c.wo.z, (mf_real)al[i]);
            /* the nodes' centre and scale from two samples: u1 = 0 (the
             * cosine's pole) and u1 = 1/2 (its 45-degree ring) */
            p0 = mf_sheen_sample(c.wo, (mf_real)al[i], MF_R(0.0), MF_R(0.0)).wi;
            p1 = mf_sheen_sample(c.wo, (mf_real)al[i], MF_R(0.5), MF_R(0.0)).wi;
            if (alb > 0.0 && (!(p0.z > 0) || !(p1.z > 0))) { ++below; continue; }
            cx = alb > 0.0 ? (double)p0.x / (double)p0.z : 0.0;
            cy = alb > 0.0 ? (double)p0.y / (double)p0.z : 0.0;
            h = alb > 0.0 ? hypot((double)p1.x / (double)p1.z - cx, (double)p1.y / (double)p1.z - cy) : 1.0;
            c.what = 0; n = sh_plane(sh_g, &c, cx, cy, h);
            if (mft_verbose) printf("    alpha %g theta %g: albedo %.6f int pdf %.9f\n", al[i], th[j], alb, n);
            e = fabs(n - (alb > 0.0 ? 1.0 : 0.0)); if (!(e <= worst_n)) worst_n = mft_finite(e) ? e : 1.0;
            c.what = 1; n = sh_plane(sh_g, &c, cx, cy, h);
            e = fabs(n - alb); if (!(e <= worst_a)) worst_a = mft_finite(e) ? e : 1.0;
            /* nothing below the horizon */
            for (k = 0; k < 4096; ++k) {
                mf_vec3 d = mft_dir(SH_PI / 2.0 + SH_PI / 2.0 * (k / 64 + 1) / 64.0, 2.0 * SH_PI * (k % 64) / 64.0);
                if (mf_sheen_pdf(c.wo, d, (mf_real)al[i]) != 0 || mf_sheen_brdf(c.wo, d, (mf_real)al[i]) != 0) ++below;
            }
        }
    printf("    sheen lobe: |int pdf - 1| %.3g, |int f cos - mf_sheen_albedo| %.3g (alpha 0.05 .. 1, views 0 .. 89.9 deg); "
           "%d directions below the horizon with pdf or f > 0\n", worst_n, worst_a, below);
    MFT_NEAR(worst_n, 0.0, 0.0, MFT_TOL(1e-6, 1e-4), "sheen: mf_sheen_pdf integrates to 1");
    MFT_NEAR(worst_a, 0.0, 0.0, MFT_TOL(1e-6, 1e-4), "sheen: int f cos = mf_sheen_albedo");
    MFT_CHECK(below == 0, "sheen: nothing below the horizon");
}

/* ---- the layer, simulated here -------------------------------------------- */
/* sigma(w) = sqrt(w^T S w), S = diag(1, 1, s^2); D(m) = 1 / (pi s (m^T S^-1 m)^2) */
static double sh_sigma(double s, const double *w) { return sqrt(w[0] * w[0] + w[1] * w[1] + s * s * w[2] * w[2]); }
static double sh_D(double s, const double *m)
{
    double q = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] / (s * s);
    return 1.0 / (SH_PI * s * q * q);
}
/* one walk entering along -wo; directions uniform on the sphere weighted by
 * 4 pi p(a -> w), p = D(h) / (4 sigma(a)); returns the weight leaving at the top */
static double sh_walk(mft_rng *r, double s, double mu)
{
    double d[3], z = 0.0, wt = 1.0;
    int order;
    d[0] = -sqrt(1.0 - mu * mu); d[1] = 0.0; d[2] = -mu;
    for (order = 0; order < 100000; ++order) {
        double st = sh_sigma(s, d), a[3], w[3], h[3], l, u, ph, sn;
        z += -log(1.0 - mft_u01(r)) / st * -d[2];
        if (z < 0.0) return wt;
        if (z > 1.0) return 0.0;
        a[0] = -d[0]; a[1] = -d[1]; a[2] = -d[2];
        u = 2.0 * mft_u01(r) - 1.0; ph = 2.0 * SH_PI * mft_u01(r); sn = sqrt(1.0 - u * u);
        w[0] = sn * cos(ph); w[1] = sn * sin(ph); w[2] = u;
        h[0] = a[0] + w[0]; h[1] = a[1] + w[1]; h[2] = a[2] + w[2];
        l = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        if (!(l > 1e-12)) return 0.0;
        h[0] /= l; h[1] /= l; h[2] /= l;
        wt *= 4.0 * SH_PI * sh_D(s, h) / (4.0 * st);
        d[0] = w[0]; d[1] = w[1]; d[2] = w[2];
        if (wt < 1e-3) {   /* Russian roulette */
            if (mft_u01(r) < 0.5) return 0.0;
            wt *= 2.0;
        }
    }
    return 0.0;
}

static void test_sheen_layer(void)
{
    /* table nodes: alpha = i / 31, cos theta_o = j / 31 */
    static const int ai[3] = { 31, 24, 18 };
    static const int mj[3] = { 31, 15, 3 };
    double worst = 0.0;
    int i, j, k, n, bad = 0;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            /* the phase-function weights vary more as alpha drops: more walks */
            double alpha = (n = ai[i] < 20 ? 160000 : 40000, ai[i] / 31.0), mu = mj[j] / 31.0, s = alpha * alpha, sum = 0.0, sum2 = 0.0, mean, sd, tab, tol;
            mft_rng r;
            mft_seed(&r, 4242 + 10 * i + j);
            for (k = 0; k < n; ++k) { double v = sh_walk(&r, s, mu); sum += v; sum2 += v * v; }
            mean = sum / n;
            sd = sqrt(fmax(sum2 / n - mean * mean, 0.0) / n);
            tab = (double)mf_sheen_albedo((mf_real)mu, (mf_real)alpha);
            /* 4 sd of ours, 4 sd of the table's 206000 walks, float rounding */
            tol = 4.0 * sd + 4.0 * sqrt(mean * (1.0 - mean) / 206000.0) + 1e-4;
            printf("    sheen layer: alpha %.3f cos theta_o %.3f: simulated R %.4f +- %.4f, table %.4f\n", alpha, mu, mean, sd, tab);
            if (!(fabs(tab - mean) <= tol)) ++bad;
            if (!(fabs(tab - mean) / tol <= worst)) worst = fabs(tab - mean) / tol;
        }
    printf("    sheen layer: worst |table - simulation| / tolerance %.2f\n", worst);
    MFT_CHECK(bad == 0, "sheen: the table's albedo is the simulated layer's (9 nodes, 4 sd)");
}

/* ---- the sampler ----------------------------------------------------------- */
#define SA 16
#define SP 32
static void sh_cell_probs(mf_vec3 wo, double alpha, double *prob)
{
    double x[8], w[8];
    int a, p, sa, sp, i, j;
    mft_gl(8, x, w);
    for (a = 0; a < SA; ++a)
        for (p = 0; p < SP; ++p) {
            double sum = 0.0;
            for (sa = 0; sa < 2; ++sa)
                for (sp = 0; sp < 2; ++sp)
                    for (i = 0; i < 8; ++i)
                        for (j = 0; j < 8; ++j) {
                            double z = (a + (sa + x[i]) / 2.0) / SA, ph = 2.0 * SH_PI * (p + (sp + x[j]) / 2.0) / SP;
                            double st = sqrt(1.0 - z * z);
                            mf_vec3 wi = mf_vec3_make((mf_real)(st * cos(ph)), (mf_real)(st * sin(ph)), (mf_real)z);
                            sum += w[i] * w[j] * (double)mf_sheen_pdf(wo, wi, (mf_real)alpha);
                        }
            prob[a * SP + p] = sum / 4.0 * (1.0 / SA) * (2.0 * SH_PI / SP);
        }
}
static int sh_cell_of(mf_vec3 wi)
{
    double ph = atan2((double)wi.y, (double)wi.x);
    int a = (int)((double)wi.z * SA), p;
    if (ph < 0.0) ph += 2.0 * SH_PI;
    p = (int)(ph / (2.0 * SH_PI) * SP);
    if (a < 0) a = 0;
    if (a >= SA) a = SA - 1;
    if (p >= SP) p = SP - 1;
    return a * SP + p;
}

static void test_sheen_sample(void)
{
    static const double al[3] = { 0.4, 0.7, 1.0 };
    static const double th[3] = { 20.0, 60.0, 85.0 };
    static double obs[SA * SP + 1], ex[SA * SP + 1];
    double worst_z = 0.0, worst_pdf = 0.0, worst_w = 0.0;
    int i, j, k, n = 50000, bad = 0;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            mf_vec3 wo = mft_dir(th[j] * SH_PI / 180.0, 0.9 * j + 0.3);
            double tot = 0.0, z;
            int dof;
            mft_rng r;
            sh_cell_probs(wo, al[i], ex);
            for (k = 0; k < SA * SP; ++k) { tot += ex[k]; ex[k] *= n; obs[k] = 0.0; }
            ex[SA * SP] = n * (tot < 1.0 ? 1.0 - tot : 0.0);
            obs[SA * SP] = 0.0;
            mft_seed(&r, 5200 + 10 * i + j);
            for (k = 0; k < n; ++k) {
                mf_sample s = mf_sheen_sample(wo, (mf_real)al[i], (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                double pdf, f, e;
                if (s.lobe == MF_LOBE_NONE) { obs[SA * SP] += 1.0; continue; }
                if (!(s.wi.z > 0) || !(s.pdf > 0) || s.lobe != MF_LOBE_REFLECTION) { ++bad; continue; }
                obs[sh_cell_of(s.wi)] += 1.0;
                pdf = (double)mf_sheen_pdf(wo, s.wi, (mf_real)al[i]);
                e = fabs((double)s.pdf - pdf) / pdf;
                if (!(e <= worst_pdf)) worst_pdf = mft_finite(e) ? e : 1.0;
                f = (double)mf_sheen_brdf(wo, s.wi, (mf_real)al[i]) * s.wi.z / pdf;
                e = fabs((double)s.weight - f) / (f > 1e-30 ? f : 1e-30);
                if (!(e <= worst_w)) worst_w = mft_finite(e) ? e : 1.0;
            }
            z = mft_chi2(obs, ex, SA * SP + 1, &dof);
            if (!(fabs(z) <= worst_z)) worst_z = mft_finite(z) ? fabs(z) : 1e9;
        }
    printf("    sheen sampling: worst |chi-square z| %.2f (3 alpha x 3 views, 5e4 samples, 513 bins with the lost one); "
           "record pdf vs mf_sheen_pdf %.3g, weight vs f cos / pdf %.3g (relative)\n", worst_z, worst_pdf, worst_w);
    MFT_CHECK(bad == 0, "sheen sampling: every sample above the horizon with pdf > 0");
    MFT_CHECK(worst_z < 4.5, "sheen sampling: chi-square of the samples against mf_sheen_pdf (|z| < 4.5, 9 cases)");
    MFT_NEAR(worst_pdf, 0.0, 0.0, MFT_TOL(1e-9, 1e-3), "sheen sampling: record pdf = mf_sheen_pdf");
    MFT_NEAR(worst_w, 0.0, 0.0, MFT_TOL(1e-9, 1e-3), "sheen sampling: weight = f cos / pdf");
    /* u corners and grazing views give valid samples */
    {
        static const double us[5] = { 0.0, 5.9604644775390625e-08, 0.5, 1.0 - 5.9604644775390625e-08, 1.0 };
        static const double ths[5] = { 0.0, 45.0, 89.0, 89.99, 89.99999 };
        static const double ag[4] = { 0.0, 0.02, 0.5, 1.0 };
        int a, b, bad_c = 0;
        double worst_c = 0.0;
        for (i = 0; i < 5; ++i)
            for (j = 0; j < 4; ++j)
                for (a = 0; a < 5; ++a)
                    for (b = 0; b < 5; ++b) {
                        mf_vec3 wo = mft_dir(ths[i] * SH_PI / 180.0, 1.0);
                        mf_sample s = mf_sheen_sample(wo, (mf_real)ag[j], (mf_real)us[a], (mf_real)us[b]);
                        double len = sqrt((double)mf_dot(s.wi, s.wi)), pdf = (double)mf_sheen_pdf(wo, s.wi, (mf_real)ag[j]);
                        if (s.lobe == MF_LOBE_NONE && (double)mf_sheen_albedo(wo.z, (mf_real)ag[j]) == 0.0) continue;
                        if (s.lobe != MF_LOBE_REFLECTION || !(s.wi.z > 0) || !(s.pdf > 0) || !(s.pdf < MF_BIG)
                            || !(s.weight > 0) || !(s.weight <= 1) || fabs(len - 1.0) > 1e-5 || !(pdf > 0)) {
                            ++bad_c;
                            printf("    sheen corner: theta %g alpha %g u (%g, %g): lobe %d wi.z %g pdf %g weight %g\n",
                                   ths[i], ag[j], us[a], us[b], s.lobe, (double)s.wi.z, (double)s.pdf, (double)s.weight);
                            continue;
                        }
                        if (!(fabs(s.pdf - pdf) / pdf <= worst_c)) worst_c = fabs(s.pdf - pdf) / pdf;
                    }
        printf("    sheen corners: record pdf vs mf_sheen_pdf at u in {0, 2^-24, 1/2, 1 - 2^-24, 1}^2: %.3g (relative)\n", worst_c);
        MFT_CHECK(bad_c == 0, "sheen sampling: u corners give a valid sample (views to 89.99999 deg, alpha 0 .. 1)");
        MFT_NEAR(worst_c, 0.0, 0.0, MFT_TOL(1e-6, 1e-2), "sheen sampling: corners' record pdf = mf_sheen_pdf");
    }
}

/* ---- special values --------------------------------------------------------- */
static int sh_finpos(mf_real v) { return v >= MF_R(0.0) && v <= MF_BIG; }
static void test_sheen_robust(void)
{
    mf_real v[12];
    mf_vec3 d[10];
    int i, j, k, l, bad = 0, n = 0;
    mft_special_values(v, d);
    for (i = 0; i < 12; ++i)
        for (j = 0; j < 12; ++j) {
            mf_real a = mf_sheen_albedo(v[i], v[j]);
            ++n;
            if (!(a >= 0) || !(a <= 1)) ++bad;
        }
    for (i = 0; i < 10; ++i)
        for (j = 0; j < 10; ++j)
            for (k = 0; k < 12; ++k) {
                ++n;
                if (!sh_finpos(mf_sheen_brdf(d[i], d[j], v[k])) || !sh_finpos(mf_sheen_pdf(d[i], d[j], v[k]))) ++bad;
                for (l = 0; l < 12; ++l) {
                    mf_sample r = mf_sheen_sample(d[i], v[k], v[l], v[j % 12]);
                    if (!mft_record_ok(r)) ++bad;
                }
            }
    printf("    sheen robustness: %d special-value combinations, %d out of range\n", n, bad);
    MFT_CHECK(bad == 0, "sheen: every function finite and in range on special values (0, -0, tiny, huge, inf, NaN, negative)");
}

void test_sheen(void)
{
    test_sheen_lobe();
    test_sheen_layer();
    test_sheen_sample();
    test_sheen_robust();
}
