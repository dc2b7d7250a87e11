/* The LTC of anisotropic GGX (mf_ltc_ggx_aniso, 13_ltc_aniso.h): light
 * integrals against Monte Carlo of the true BRDF cos by an independent
 * double-precision sampler of the visible normals (Heitz 2018) written here,
 * over squares, disks and tubes on the mirror direction (a reduced fixed
 * set; the whole set of docs/ACCURACY.md under --full, as
 * tools/ltc_aniso_eval.c); the LTC's own integrals against quadrature (over
 * the sphere: 1; over a square: mf_ltc_integrate, the exact edge integral);
 * the albedo against the same Monte Carlo; the isotropic slice against
 * mf_ltc_ggx (equal at ax = ay, within 1% at ay = 0.99 ax); the mirror and
 * swap symmetries; lookups at the table's edges and corners (finite,
 * orientation-preserving, continuous across node planes); NaN and Inf give
 * finite output.
 * Tolerances: mean relative error over the reduced set (48 views x 3
 * lights) below MFT_ANISO_MEAN_TOL (measured values in the comments there;
 * a broken lookup or table errs by 0.15 and more), Monte Carlo noise (36864
 * stratified samples, lights holding at least 2% of the lobe) about 0.5%;
 * quadrature 1e-4 (double) / 1e-3 (float); albedo MFT_ANISO_ALB_TOL absolute
 * (half-float storage and interpolation); symmetries 1e-9 / 2e-4; ay = 0.99
 * ax within 2.5% of mf_ltc_ggx (measured 1.9%: the table's L3 fits next to
 * the isotropic table's refit on polygons, see docs/ACCURACY.md). */
#include "mf_test.h"
#include <stdlib.h>

static const double PI_A = 3.14159265358979323846;
#define MFT_ANISO_MEAN_TOL 0.04       /* reduced set: measured 0.0311 */
#define MFT_ANISO_MEAN_TOL_FULL 0.055 /* whole set (--full): measured 0.0469 */
#define MFT_ANISO_ALB_TOL 0.035       /* albedo, worst absolute: measured 0.0063 (reduced), 0.0271 (whole) */

/* a check that also prints its measured figure under -v */
#define MFT_CHECK_V(cond, msg) (mft_verbose ? printf("    %s\n", msg) : 0, MFT_CHECK(cond, msg))

#ifndef MF_NO_LTC_TABLE
/* ---- independent reference: anisotropic GGX in double ---- */
static double lam(double ax, double ay, const double *w)
{
    double z2 = w[2] * w[2];
    if (!(z2 > 0)) return 1e30;
    return 0.5 * (-1 + sqrt(1 + (ax * ax * w[0] * w[0] + ay * ay * w[1] * w[1]) / z2));
}
/* a visible normal (Heitz 2018, JCGT 7(4), listing 1), reflected: wi and
 * the weight f cos / pdf = (1 + L(wo)) / (1 + L(wo) + L(wi)); 0 below */
static double vndf_reflect(double ax, double ay, const double *wo, double u1, double u2, double *wi)
{
    double vh[3], l, t1[3], t2[3], r, ph, p1, p2, s, nh[3], n[3], d;
    vh[0] = ax * wo[0]; vh[1] = ay * wo[1]; vh[2] = wo[2];
    l = sqrt(vh[0] * vh[0] + vh[1] * vh[1] + vh[2] * vh[2]);
    vh[0] /= l; vh[1] /= l; vh[2] /= l;
    l = vh[0] * vh[0] + vh[1] * vh[1];
    if (l > 0) { t1[0] = -vh[1] / sqrt(l); t1[1] = vh[0] / sqrt(l); t1[2] = 0; }
    else { t1[0] = 1; t1[1] = 0; t1[2] = 0; }
    t2[0] = vh[1] * t1[2] - vh[2] * t1[1]; t2[1] = vh[2] * t1[0] - vh[0] * t1[2]; t2[2] = vh[0] * t1[1] - vh[1] * t1[0];
    r = sqrt(u1); ph = 2 * PI_A * u2;
    p1 = r * cos(ph); p2 = r * sin(ph);
    s = 0.5 * (1 + vh[2]);
    p2 = (1 - s) * sqrt(1 - p1 * p1) + s * p2;
    d = sqrt(fmax(0.0, 1 - p1 * p1 - p2 * p2));
    nh[0] = p1 * t1[0] + p2 * t2[0] + d * vh[0];
    nh[1] = p1 * t1[1] + p2 * t2[1] + d * vh[1];
    nh[2] = p1 * t1[2] + p2 * t2[2] + d * vh[2];
    n[0] = ax * nh[0]; n[1] = ay * nh[1]; n[2] = fmax(0.0, nh[2]);
    l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    n[0] /= l; n[1] /= l; n[2] /= l;
    d = wo[0] * n[0] + wo[1] * n[1] + wo[2] * n[2];
    wi[0] = 2 * d * n[0] - wo[0]; wi[1] = 2 * d * n[1] - wo[1]; wi[2] = 2 * d * n[2] - wo[2];
    if (!(wi[2] > 0)) return 0;
    return (1 + lam(ax, ay, wo)) / (1 + lam(ax, ay, wo) + lam(ax, ay, wi));
}

static double dt3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static mf_vec3 mv(const double *a) { return mf_vec3_make((mf_real)a[0], (mf_real)a[1], (mf_real)a[2]); }

/* lights on the mirror direction R at distance 2 facing the point: square
 * (half-side 0.4), disk (radius 0.4), tube (length 2, radius 0.05) across R */
typedef struct { double c[3], n[3], e1[3], e2[3], p1[3], p2[3]; } lights;
static void lights_make(lights *L, const double *wo, double ph)
{
    double R[3] = { -wo[0], -wo[1], wo[2] }, h;
    int k;
    for (k = 0; k < 3; ++k) { L->c[k] = 2 * R[k]; L->n[k] = -R[k]; }
    h = sqrt(R[0] * R[0] + R[1] * R[1]);
    if (h < 1e-3) { L->e1[0] = -sin(ph); L->e1[1] = cos(ph); L->e1[2] = 0; }
    else { L->e1[0] = -R[1] / h; L->e1[1] = R[0] / h; L->e1[2] = 0; }
    L->e2[0] = L->n[1] * L->e1[2] - L->n[2] * L->e1[1];
    L->e2[1] = L->n[2] * L->e1[0] - L->n[0] * L->e1[2];
    L->e2[2] = L->n[0] * L->e1[1] - L->n[1] * L->e1[0];
    for (k = 0; k < 3; ++k) { L->p1[k] = L->c[k] - L->e1[k]; L->p2[k] = L->c[k] + L->e1[k]; }
}
/* which lights the ray w hits: bit 0 square, 1 disk, 2 tube */
static int lights_hit(const lights *L, const double *w)
{
    int m = 0, e;
    double dn = dt3(w, L->n);
    if (dn < 0) {
        double t = dt3(L->c, L->n) / dn, p[3], u, v;
        p[0] = t * w[0] - L->c[0]; p[1] = t * w[1] - L->c[1]; p[2] = t * w[2] - L->c[2];
        u = dt3(p, L->e1); v = dt3(p, L->e2);
        if (fabs(u) <= 0.4 && fabs(v) <= 0.4) m |= 1;
        if (u * u + v * v <= 0.16) m |= 2;
    }
    {   /* the closed tube along e1 from p1, length 2, radius 0.05 */
        double o[3] = { -L->p1[0], -L->p1[1], -L->p1[2] }, wa = dt3(w, L->e1), oa = dt3(o, L->e1), wp[3], op[3], A, B, C, D;
        int k, hit = 0;
        for (k = 0; k < 3; ++k) { wp[k] = w[k] - wa * L->e1[k]; op[k] = o[k] - oa * L->e1[k]; }
        A = dt3(wp, wp); B = 2 * dt3(wp, op); C = dt3(op, op) - 0.0025; D = B * B - 4 * A * C;
        if (A > 0 && D >= 0)
            for (e = -1; e <= 1; e += 2) {
                double t = (-B + e * sqrt(D)) / (2 * A), z = oa + t * wa;
                if (t > 0 && z >= 0 && z <= 2) hit = 1;
            }
        for (e = 0; e < 2 && wa != 0; ++e) {
            double t = (2.0 * e - oa) / wa, p[3], q;
            for (k = 0; k < 3; ++k) p[k] = o[k] + t * w[k];
            q = dt3(p, L->e1);
            for (k = 0; k < 3; ++k) p[k] -= q * L->e1[k];
            if (t > 0 && dt3(p, p) <= 0.0025) hit = 1;
        }
        if (hit) m |= 4;
    }
    return m;
}
static void lights_ltc(const lights *L, const mf_ltc *l, double *out)
{
    mf_vec3 v[4];
    double s[4][2] = { { -0.4, -0.4 }, { 0.4, -0.4 }, { 0.4, 0.4 }, { -0.4, 0.4 } }, p[3];
    int i, k;
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 3; ++k) p[k] = L->c[k] + s[i][0] * L->e1[k] + s[i][1] * L->e2[k];
        v[i] = mv(p);
    }
    out[0] = (double)mf_ltc_integrate(l, v, 4, 1);
    out[1] = (double)mf_ltc_integrate_disk(l, mv(L->c), mv(L->n), MF_R(0.4), 1);
    out[2] = (double)mf_ltc_integrate_tube(l, mv(L->p1), mv(L->p2), MF_R(0.05));
}

/* Monte Carlo of the lights and the albedo with N x N stratified samples */
static void mc_lights(double ax, double ay, const double *wo, const lights *L, int N, double *ref, double *alb)
{
    int a, b, s;
    double wi[3], w;
    ref[0] = ref[1] = ref[2] = *alb = 0;
    for (a = 0; a < N; ++a)
        for (b = 0; b < N; ++b) {
            int m;
            w = vndf_reflect(ax, ay, wo, (a + 0.5) / N, (b + 0.5) / N, wi);
            if (!(w > 0)) continue;
            *alb += w;
            m = lights_hit(L, wi);
            for (s = 0; s < 3; ++s) if (m & (1 << s)) ref[s] += w;
        }
    for (s = 0; s < 3; ++s) ref[s] /= (double)N * N;
    *alb /= (double)N * N;
}

static void test_against_mc(void)
{
    static const double axs[3] = { 0.2, 0.4, 0.7 }, rs[4] = { 1, 2, 5, 10 }, ths[5] = { 0, 20, 40, 60, 80 };
    int ia, ir, ip, it, s, n = 0, N = mft_full ? 256 : 192;
    double sum = 0, sumr[4] = { 0 }, worst_alb = 0;
    int cnt[4] = { 0 };
    char msg[200];
    for (ia = 0; ia < 3; ++ia)
        for (ir = 0; ir < 4; ++ir)
            for (ip = 0; ip < 8; ++ip)
                for (it = 0; it < 5; ++it) {
                    double ax = axs[ia], ay = ax / rs[ir], ph = (ip + 0.25) * PI_A / 4, th = ths[it] * PI_A / 180;
                    double wo[3] = { sin(th) * cos(ph), sin(th) * sin(ph), cos(th) }, ref[3], alb, est[3], albt;
                    lights L;
                    mf_ltc l;
                    if (!mft_full && !((ip == 1 || ip == 6) && (it == 1 || it == 3))) continue;
                    lights_make(&L, wo, ph);
                    mc_lights(ax, ay, wo, &L, N, ref, &alb);
                    l = mf_ltc_ggx_aniso(mv(wo), (mf_real)ax, (mf_real)ay);
                    albt = (double)mf_ltc_ggx_aniso_albedo(mv(wo), (mf_real)ax, (mf_real)ay);
                    if (fabs(albt - alb) > worst_alb) worst_alb = fabs(albt - alb);
                    lights_ltc(&L, &l, est);
                    for (s = 0; s < 3; ++s) {
                        double e;
                        if (!(ref[s] > 0.02 * alb)) continue;
                        e = fabs(albt * est[s] - ref[s]) / ref[s];
                        if (mft_verbose) printf("    ax %.2f ay %.3f ph %.2f th %2.0f light %d: %.4g vs %.4g (%.3f)\n", ax, ay, ph, ths[it], s, albt * est[s], ref[s], e);
                        sum += e; sumr[ir] += e; cnt[ir]++; ++n;
                    }
                }
    sum /= n;
    printf("    anisotropic GGX LTC vs Monte Carlo (%s set, %d lights): mean rel error %.4f; by anisotropy 1 2 5 10: %.4f %.4f %.4f %.4f; albedo worst abs %.4f\n",
           mft_full ? "whole" : "reduced", n, sum, sumr[0] / cnt[0], sumr[1] / cnt[1], sumr[2] / cnt[2], sumr[3] / cnt[3], worst_alb);
    snprintf(msg, sizeof msg, "aniso LTC vs MC over squares, disks, tubes: mean rel error %.4f < %.3f", sum, mft_full ? MFT_ANISO_MEAN_TOL_FULL : MFT_ANISO_MEAN_TOL);
    MFT_CHECK_V(sum < (mft_full ? MFT_ANISO_MEAN_TOL_FULL : MFT_ANISO_MEAN_TOL), msg);
    snprintf(msg, sizeof msg, "aniso albedo vs MC: worst abs error %.4f < %.3f", worst_alb, MFT_ANISO_ALB_TOL);
    MFT_CHECK_V(worst_alb < MFT_ANISO_ALB_TOL, msg);
}

/* the LTC over the sphere (1) and over a square (the edge integral) by
 * quadrature of mf_ltc_eval, for lookups in every quadrant and both
 * orders of the alphas */
static double gx[32], gw[32];
static void test_quadrature(void)
{
    static const double cfg[6][4] = { { 0.5, 0.25, 30, 0.4 }, { 0.25, 0.5, 50, 2.0 }, { 0.6, 0.1, 70, 3.5 },
                                      { 0.15, 0.45, 10, 5.0 }, { 0.8, 0.8, 40, 1.0 }, { 0.3, 0.06, 60, 4.4 } };
    int c, worst_c = 0;
    double worst_s = 0, worst_q = 0;
    char msg[160];
    for (c = 0; c < 6; ++c) {
        double th = cfg[c][2] * PI_A / 180, ph = cfg[c][3], wo[3] = { sin(th) * cos(ph), sin(th) * sin(ph), cos(th) };
        mf_ltc l = mf_ltc_ggx_aniso(mv(wo), (mf_real)cfg[c][0], (mf_real)cfg[c][1]);
        lights L;
        double sph = 0, sq = 0, e[3];
        int a, i, b, j;
        /* sphere: z = cos in [-1, 1] x azimuth, 32 x 64 panels of 32 nodes */
        for (a = 0; a < 32; ++a)
            for (i = 0; i < 32; ++i) {
                double z = -1 + 2 * (a + gx[i]) / 32, r = sqrt(fmax(0.0, 1 - z * z));
                for (b = 0; b < 16; ++b)
                    for (j = 0; j < 32; ++j) {
                        double p = 2 * PI_A * (b + gx[j]) / 16;
                        sph += gw[i] * gw[j] * (double)mf_ltc_eval(&l, mf_vec3_make((mf_real)(r * cos(p)), (mf_real)(r * sin(p)), (mf_real)z)) * (2.0 / 32) * (2 * PI_A / 16);
                    }
            }
        /* the square light by area: D(w) cos_l / d^2 dA, 8 x 8 panels */
        lights_make(&L, wo, ph);
        for (a = 0; a < 8; ++a)
            for (i = 0; i < 32; ++i)
                for (b = 0; b < 8; ++b)
                    for (j = 0; j < 32; ++j) {
                        double u = -0.4 + 0.8 * (a + gx[i]) / 8, v = -0.4 + 0.8 * (b + gx[j]) / 8, x[3], d2, d;
                        int k;
                        for (k = 0; k < 3; ++k) x[k] = L.c[k] + u * L.e1[k] + v * L.e2[k];
                        d2 = dt3(x, x); d = sqrt(d2);
                        sq += gw[i] * gw[j] * (double)mf_ltc_eval(&l, mf_vec3_make((mf_real)(x[0] / d), (mf_real)(x[1] / d), (mf_real)(x[2] / d))) *
                              fabs(dt3(x, L.n)) / (d * d2) * (0.8 / 8) * (0.8 / 8);
                    }
        lights_ltc(&L, &l, e);
        if (fabs(sph - 1) > worst_s) { worst_s = fabs(sph - 1); worst_c = c; }
        if (fabs(sq - e[0]) / sq > worst_q) worst_q = fabs(sq - e[0]) / sq;
        if (mft_verbose) printf("    config %d: sphere %.8f, square %.8g vs edges %.8g\n", c, sph, sq, e[0]);
    }
    snprintf(msg, sizeof msg, "aniso LTC integrates to 1 over the sphere: worst |err| %.2g (config %d)", worst_s, worst_c);
    MFT_CHECK_V(worst_s < MFT_TOL(1e-4, 1e-3), msg);
    snprintf(msg, sizeof msg, "aniso LTC over a square: edge integral vs quadrature worst rel %.2g", worst_q);
    MFT_CHECK_V(worst_q < MFT_TOL(1e-4, 1e-3), msg);
}

/* ax = ay: mf_ltc_ggx in mf_basis_ltc's frame (tangent along the view's
 * azimuth; at normal view the tangent itself); ay = 0.99 ax within 1% */
static void test_isotropic_slice(void)
{
    static const double cts[4] = { 1.0, 0.8, 0.45, 0.2 }, als[4] = { 0.05, 0.2, 0.5, 0.9 }, phs[3] = { 0.0, 1.1, 4.0 };
    int ic, ia, ip;
    double worst = 0, worst99 = 0, worst_alb = 0;
    char msg[160];
    for (ic = 0; ic < 4; ++ic)
        for (ia = 0; ia < 4; ++ia)
            for (ip = 0; ip < 3; ++ip) {
                double ct = cts[ic], st = sqrt(1 - ct * ct), ph = phs[ip], a = als[ia];
                double wo[3] = { st * cos(ph), st * sin(ph), ct }, wl[3] = { st, 0, ct }, e1[3], e2[3], e3[3], e4[3];
                lights L, Ll;
                mf_ltc la = mf_ltc_ggx_aniso(mv(wo), (mf_real)a, (mf_real)a), l9 = mf_ltc_ggx_aniso(mv(wo), (mf_real)a, (mf_real)(0.99 * a));
                mf_ltc li = mf_ltc_ggx((mf_real)ct, (mf_real)a);
                int s;
                if (ct == 1.0 && ph != 0.0) continue;   /* normal view: mf_ltc_ggx's frame is any frame */
                lights_make(&L, wo, ph);
                lights_make(&Ll, wl, 0.0);   /* the same lights in the LTC frame */
                lights_ltc(&L, &la, e1); lights_ltc(&Ll, &li, e2); lights_ltc(&L, &l9, e3);
                (void)e4;
                for (s = 0; s < 3; ++s) {
                    if (!(e2[s] > 1e-6)) continue;
                    if (fabs(e1[s] - e2[s]) / e2[s] > worst) worst = fabs(e1[s] - e2[s]) / e2[s];
                    if (fabs(e3[s] - e2[s]) / e2[s] > worst99) worst99 = fabs(e3[s] - e2[s]) / e2[s];
                }
                s = 0;
                {
                    double d = fabs((double)mf_ltc_ggx_aniso_albedo(mv(wo), (mf_real)a, (mf_real)a) - (double)mf_ltc_ggx_albedo((mf_real)ct, (mf_real)a));
                    if (d > worst_alb) worst_alb = d;
                }
            }
    snprintf(msg, sizeof msg, "aniso at ax = ay equals mf_ltc_ggx rotated: worst rel %.2g (albedo %.2g)", worst, worst_alb);
    MFT_CHECK_V(worst < MFT_TOL(1e-9, 1e-4) && worst_alb < MFT_TOL(1e-12, 1e-6), msg);
    snprintf(msg, sizeof msg, "aniso at ay = 0.99 ax within 2.5%% of mf_ltc_ggx: worst rel %.3g", worst99);
    MFT_CHECK_V(worst99 < 0.025, msg);
}

/* x -> -x, y -> -y and the exchange of x and y (with the alphas) */
static void test_symmetries(void)
{
    double worst = 0;
    int k;
    char msg[160];
    for (k = 0; k < 12; ++k) {
        double th = (10 + 6 * k) * PI_A / 180, ph = 0.3 + 0.5 * k, ax = 0.1 + 0.07 * k, ay = 0.5 - 0.03 * k;
        double wo[3] = { sin(th) * cos(ph), sin(th) * sin(ph), cos(th) }, e0[3], e[3];
        double wm[3][3], sg[3][3] = { { -1, 1, 1 }, { 1, -1, 1 }, { 0, 0, 1 } };
        lights L;
        mf_ltc l = mf_ltc_ggx_aniso(mv(wo), (mf_real)ax, (mf_real)ay);
        int t, s, i;
        lights_make(&L, wo, ph);
        lights_ltc(&L, &l, e0);
        for (t = 0; t < 3; ++t) {
            lights M = L;
            mf_ltc lm;
            /* the mirrored (t < 2) or swapped (t = 2) view and lights */
            double *vec[6];
            vec[0] = M.c; vec[1] = M.n; vec[2] = M.e1; vec[3] = M.e2; vec[4] = M.p1; vec[5] = M.p2;
            for (i = 0; i < 3; ++i) wm[t][i] = wo[i];
            if (t < 2) {
                for (i = 0; i < 3; ++i) wm[t][i] *= sg[t][i];
                for (s = 0; s < 6; ++s) for (i = 0; i < 3; ++i) vec[s][i] *= sg[t][i];
                lm = mf_ltc_ggx_aniso(mv(wm[t]), (mf_real)ax, (mf_real)ay);
            } else {
                double q;
                q = wm[t][0]; wm[t][0] = wm[t][1]; wm[t][1] = q;
                for (s = 0; s < 6; ++s) { q = vec[s][0]; vec[s][0] = vec[s][1]; vec[s][1] = q; }
                lm = mf_ltc_ggx_aniso(mv(wm[t]), (mf_real)ay, (mf_real)ax);
            }
            /* a reflection reverses the square's winding: integrate two-sided (as lights_ltc does) */
            lights_ltc(&M, &lm, e);
            for (s = 0; s < 3; ++s)
                if (e0[s] > 1e-6 && fabs(e[s] - e0[s]) / e0[s] > worst) worst = fabs(e[s] - e0[s]) / e0[s];
        }
    }
    snprintf(msg, sizeof msg, "aniso LTC mirrored in x, in y, and with x, y and the alphas exchanged: worst rel %.2g", worst);
    MFT_CHECK_V(worst < MFT_TOL(1e-9, 2e-4), msg);
}

/* the table's edges and corners: finite, det > 0, albedo in [0, 1],
 * continuous across the node planes (1e-4 either side of each) */
static void test_edges(void)
{
    static const double av[7] = { 0.0, 1e-3, 0.0123456790123, 0.111111111111, 0.5, 1.0, 3.0 }, cv[6] = { -0.3, 0.0, 0.03, 0.21, 0.99, 1.0 },
                        pv[6] = { 0.0, 0.5 * 3.14159265358979323846, 3.14159265358979323846, -1e-9, 0.224399475, 1.5 * 3.14159265358979323846 };
    int i, j, k, p, ok = 1, cont = 1, dims[4];
    double worst_jump = 0;
    char msg[200];
    const unsigned short *t = mf_ltc_ggx_aniso_table(dims);
    for (i = 0; i < 7; ++i)
        for (j = 0; j < 7; ++j)
            for (k = 0; k < 6; ++k)
                for (p = 0; p < 6; ++p) {
                    double ct = cv[k], st = sqrt(fmax(0.0, 1 - ct * ct));
                    mf_vec3 wo = mf_vec3_make((mf_real)(st * cos(pv[p])), (mf_real)(st * sin(pv[p])), (mf_real)ct);
                    mf_ltc l = mf_ltc_ggx_aniso(wo, (mf_real)av[i], (mf_real)av[j]);
                    double a = (double)mf_ltc_ggx_aniso_albedo(wo, (mf_real)av[i], (mf_real)av[j]), d;
                    int q;
                    for (q = 0; q < 9; ++q) if (!mft_finite((double)l.Minv[q]) || !mft_finite((double)l.M[q])) ok = 0;
                    d = (double)l.Minv[0] * ((double)l.Minv[4] * l.Minv[8] - (double)l.Minv[5] * l.Minv[7]) -
                        (double)l.Minv[1] * ((double)l.Minv[3] * l.Minv[8] - (double)l.Minv[5] * l.Minv[6]) +
                        (double)l.Minv[2] * ((double)l.Minv[3] * l.Minv[7] - (double)l.Minv[4] * l.Minv[6]);
                    if (!(d > 0) || !mft_finite((double)l.det_inv) || !(a >= 0 && a <= 1.0)) ok = 0;
                }
    /* continuity: a light's integral either side of interior node planes of alpha_x and of the view */
    for (i = 1; i < dims[2] - 1; i += 3)
        for (k = 1; k < dims[0] - 1; k += 3) {
            double ax = (double)i / (dims[2] - 1), tt = (double)k / (dims[0] - 1), e[2][3];
            int s, h;
            ax *= ax;
            for (h = 0; h < 2; ++h) {
                double axh = ax * (h ? 1.0001 : 0.9999), ct = 1 - tt * tt * (h ? 1.0001 : 0.9999), st = sqrt(1 - ct * ct);
                double wo[3] = { st * cos(0.7), st * sin(0.7), ct };
                lights L;
                mf_ltc l = mf_ltc_ggx_aniso(mv(wo), (mf_real)axh, (mf_real)(0.3 * axh));
                lights_make(&L, wo, 0.7);
                lights_ltc(&L, &l, e[h]);
            }
            for (s = 0; s < 3; ++s)
                if (e[0][s] > 1e-6) {
                    double jmp = fabs(e[1][s] - e[0][s]) / e[0][s];
                    if (jmp > worst_jump) worst_jump = jmp;
                }
        }
    if (!(worst_jump < 0.01)) cont = 0;
    snprintf(msg, sizeof msg, "aniso LTC at the table's edges and corners (alphas 0..3, views -0.3..1, azimuths): finite, det > 0, albedo in [0, 1]");
    MFT_CHECK_V(ok && t != 0 && dims[0] >= 2 && dims[1] >= 2 && dims[2] >= 2 && dims[3] >= 1, msg);
    snprintf(msg, sizeof msg, "aniso LTC continuous across node planes: worst jump %.2g < 0.01", worst_jump);
    MFT_CHECK_V(cont, msg);
}

static void test_bad(void)
{
    const mf_real inf = (mf_real)1e30 * (mf_real)1e30, nan = inf - inf;
    const mf_real vals[7] = { 0, 1, -1, (mf_real)0.3, inf, -inf, nan };
    int i, j, k, ok = 1;
    unsigned short *t1, *t2;
    int dims[4];
    for (i = 0; i < 7; ++i)
        for (j = 0; j < 7; ++j)
            for (k = 0; k < 7; ++k) {
                mf_vec3 wo = mf_vec3_make(vals[i], vals[(i + j) % 7], vals[k]);
                mf_ltc l = mf_ltc_ggx_aniso(wo, vals[j], vals[k]);
                mf_real a = mf_ltc_ggx_aniso_albedo(wo, vals[j], vals[(j + k) % 7]);
                int q;
                for (q = 0; q < 9; ++q) if (!mft_finite((double)l.Minv[q]) || !mft_finite((double)l.M[q])) ok = 0;
                if (!mft_finite((double)l.det_inv) || !mft_finite((double)a) || a < 0) ok = 0;
            }
    MFT_CHECK(ok, "aniso LTC and albedo finite for NaN, Inf, zero and negative inputs");
    mf_ltc_ggx_aniso_table(dims);
    t1 = (unsigned short *)malloc(sizeof(unsigned short) * 4 * (size_t)dims[0] * dims[1] * dims[2] * dims[3]);
    t2 = (unsigned short *)malloc(sizeof(unsigned short) * 4 * (size_t)dims[0] * dims[1] * dims[2] * dims[3]);
    if (t1 && t2) {
        const unsigned short *t = mf_ltc_ggx_aniso_table(0);
        size_t n = (size_t)dims[0] * dims[1] * dims[2] * dims[3], e, bad = 0;
        MFT_CHECK(mf_ltc_ggx_aniso_export_rgba16f(t1, t2) == MF_SUCCESS && mf_ltc_ggx_aniso_export_rgba16f(0, t2) == MF_ERROR_INVALID_ARGUMENT,
                  "aniso RGBA export: success, null rejected");
        /* the texel of entry ((ia nv + iv) nt + it) np + ip sits at row ia nv + iv, column it np + ip: the same order */
        for (e = 0; e < n; ++e) {
            int q;
            for (q = 0; q < 4; ++q) if (t1[4 * e + (size_t)q] != t[8 * e + (size_t)q] || t2[4 * e + (size_t)q] != t[8 * e + 4 + (size_t)q]) ++bad;
        }
        MFT_CHECK(bad == 0, "aniso RGBA export: every half at its texel and channel");
    }
    free(t1); free(t2);
}
#endif

void test_ltc_aniso(void)
{
#ifndef MF_NO_LTC_TABLE
    mft_gl(32, gx, gw);
    test_isotropic_slice();
    test_symmetries();
    test_quadrature();
    test_edges();
    test_bad();
    test_against_mc();
#endif
}
