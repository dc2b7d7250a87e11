/* Measures mf_ltc_ggx_aniso against Monte Carlo of the true anisotropic GGX
 * BRDF over a set of square, disk and tube lights (docs/ACCURACY.md), and
 * optionally a published 8^4 table read at run time (never stored here).
 *   cc -O2 -DMF_USE_DOUBLE -I. tools/ltc_aniso_eval.c -o ltc_aniso_eval -lm
 *   ./ltc_aniso_eval [--quick] [--low] [--off AZ EL] [--xy FILE] [--al FILE]
 * FILE: the C array of Aakash KT et al. 2022 (LTC-Anisotropic, LUT/
 * alphax_alphay_theta_phi.cpp for --xy, LUT/alpha_lambda_theta_phi.cpp for
 * --al): 8^4 matrices M (9 floats, row-major), [alpha_x][alpha_y][theta][phi]
 * or [alpha][lambda = alpha_y / alpha_x][theta][phi], nodes k / 7 (alphas,
 * lambda; alphas clamped below at 1e-4), theta = (k / 7) 0.9999 pi/2 and
 * phi = (k / 7) pi/2, looked up as their shader does (quadrilinear in those
 * coordinates, the view mirrored into phi in [0, pi/2]).
 *
 * The set: alpha_x in {0.2, 0.4, 0.7}, alpha_y = alpha_x / r, r in {1, 2, 5,
 * 10}; view azimuth (k + 1/4) pi/4, k = 0..7; view elevation 0, 20, 40, 60,
 * 80 deg; lights centred on the mirror direction at distance 2, facing the
 * point: a square of half-side 0.4, a disk of radius 0.4, a tube of length 2
 * and radius 0.05 lying horizontally across the mirror direction. Reference:
 * 512 x 512 stratified samples of mf_brdf_sample (the visible normals),
 * each weight counted when its ray hits the light; the same samples give
 * the albedo. Figures: mean relative error of albedo x LTC integral, with
 * the Monte Carlo albedo (the shape of the lobe alone: "shape") and with
 * the table's albedo ("ours"), over the lights holding at least 1e-4 of
 * the albedo. --quick: 128 x 128 samples; --low: views 2, 4, 6, 8, 10 deg
 * instead; --off AZ EL: the lights' direction turned by AZ radians in
 * azimuth and lowered by EL radians (at least 0.05 rad above the horizon):
 * lights beside the lobe. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI_D 3.14159265358979323846

/* ---- the published tables, read from their C source ---- */
static float *pub_load(const char *path)
{
    FILE *f = fopen(path, "rb");
    float *t;
    long n = 0, sz;
    char *buf, *p;
    if (!f) return 0;
    fseek(f, 0, SEEK_END); sz = ftell(f); fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)sz + 1);
    t = (float *)malloc(sizeof(float) * 8 * 8 * 8 * 8 * 9);
    if (!buf || !t || fread(buf, 1, (size_t)sz, f) != (size_t)sz) { fclose(f); return 0; }
    fclose(f);
    buf[sz] = 0;
    p = strchr(buf, '=');
    while (p && *p && n < 8 * 8 * 8 * 8 * 9) {
        char *e;
        double v;
        if (!(*p == '-' || (*p >= '0' && *p <= '9') || *p == '.')) { ++p; continue; }
        v = strtod(p, &e);
        if (e == p) { ++p; continue; }
        t[n++] = (float)v;
        p = e;
    }
    free(buf);
    if (n != 8 * 8 * 8 * 8 * 9) { fprintf(stderr, "%s: %ld numbers\n", path, n); free(t); return 0; }
    return t;
}

/* quadrilinear lookup of M at fractional indices x[0..3] (each in [0, 7]) */
static void pub_lerp(const float *t, const double *x, double *m)
{
    int i[4], k, c;
    double f[4];
    for (k = 0; k < 9; ++k) m[k] = 0;
    for (k = 0; k < 4; ++k) {
        double v = x[k] < 0 ? 0 : (x[k] > 7 ? 7 : x[k]);
        i[k] = (int)v;
        if (i[k] > 6) i[k] = 6;
        f[k] = v - i[k];
    }
    for (c = 0; c < 16; ++c) {
        double w = 1;
        size_t o = 0;
        for (k = 0; k < 4; ++k) {
            int b = (c >> k) & 1;
            w *= b ? f[k] : 1 - f[k];
            o = o * 8 + (size_t)(i[k] + b);
        }
        for (k = 0; k < 9; ++k) m[k] += w * t[9 * o + (size_t)k];
    }
}

/* the published LTC for wo (shading frame) and (ax, ay); al: the
 * alpha-lambda parameterization (ax >= ay, swapping x and y otherwise) */
static mf_ltc pub_ltc(const float *t, int al, mf_vec3 wo, double ax, double ay)
{
    double x[4], m[9], X = wo.x, Y = wo.y, th, ph, det;
    int mx, my, swap = 0, k;
    if (al && ax < ay) { double s = ax; ax = ay; ay = s; s = X; X = Y; Y = s; swap = 1; }
    mx = X < 0; my = Y < 0;
    th = acos(wo.z < 1 ? wo.z : 1); ph = atan2(fabs(Y), fabs(X));
    if (al) { x[0] = (ax - 1e-3) / (1 - 1e-3) * 7; x[1] = ay / ax * 7; }
    else { x[0] = ax * 7; x[1] = ay * 7; }
    x[2] = th / (PI_D / 2) * 7; x[3] = ph / (PI_D / 2) * 7;
    pub_lerp(t, x, m);
    /* conjugate by the mirrors and the swap (keeps the distribution mirrored) */
    if (mx) { m[1] = -m[1]; m[3] = -m[3]; m[2] = -m[2]; m[6] = -m[6]; }
    if (my) { m[1] = -m[1]; m[3] = -m[3]; m[5] = -m[5]; m[7] = -m[7]; }
    if (swap) {
        double s[9];
        for (k = 0; k < 9; ++k) s[k] = m[k];
        m[0] = s[4]; m[1] = s[3]; m[2] = s[5]; m[3] = s[1]; m[4] = s[0]; m[5] = s[2]; m[6] = s[7]; m[7] = s[6]; m[8] = s[8];
    }
    /* an orientation-reversing M is the same distribution as M diag(-1, 1, 1) */
    det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
    if (det < 0) { m[0] = -m[0]; m[3] = -m[3]; m[6] = -m[6]; }
    return mf_ltc_from_matrix9(m);
}

/* ---- lights ---- */
typedef struct { mf_vec3 c, n, e1, e2; double h; } quad_light;   /* square (h half-side) or disk (h radius) */
typedef struct { mf_vec3 p1, p2; double r; } tube_light;

static double dot3(mf_vec3 a, mf_vec3 b) { return (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z; }

static int hit_plane(const quad_light *q, mf_vec3 w, int disk)
{
    double dn = dot3(w, q->n), t, u, v;
    mf_vec3 p;
    if (!(dn < 0)) return 0;   /* front face only: n faces the point */
    t = dot3(q->c, q->n) / dn;
    if (!(t > 0)) return 0;
    p = mf_vec3_make(t * w.x - q->c.x, t * w.y - q->c.y, t * w.z - q->c.z);
    u = dot3(p, q->e1); v = dot3(p, q->e2);
    return disk ? u * u + v * v <= q->h * q->h : fabs(u) <= q->h && fabs(v) <= q->h;
}

static int hit_tube(const tube_light *tb, mf_vec3 w)
{
    mf_vec3 a = mf_normalize(mf__vsub(tb->p2, tb->p1)), o = mf_scale(tb->p1, -1.0);   /* origin - p1 */
    double L = sqrt(dot3(mf__vsub(tb->p2, tb->p1), mf__vsub(tb->p2, tb->p1))), wa = dot3(w, a), oa = dot3(o, a);
    mf_vec3 wp = mf__vsub(w, mf_scale(a, wa)), op = mf__vsub(o, mf_scale(a, oa));
    double A = dot3(wp, wp), B = 2 * dot3(wp, op), C = dot3(op, op) - tb->r * tb->r, D = B * B - 4 * A * C;
    int e;
    if (A > 0 && D >= 0) {
        double s = sqrt(D), t1 = (-B - s) / (2 * A), t2 = (-B + s) / (2 * A), ts[2];
        ts[0] = t1; ts[1] = t2;
        for (e = 0; e < 2; ++e)
            if (ts[e] > 0) { double z = oa + ts[e] * wa; if (z >= 0 && z <= L) return 1; }
    }
    for (e = 0; e < 2; ++e) {   /* caps */
        double zc = e ? L : 0, t;
        if (wa == 0) continue;
        t = (zc - oa) / wa;
        if (t > 0) {
            mf_vec3 p = mf_add(o, mf_scale(w, t));
            mf_vec3 pr = mf__vsub(p, mf_scale(a, dot3(p, a)));
            if (dot3(pr, pr) <= tb->r * tb->r) return 1;
        }
    }
    return 0;
}

/* the LTC under test (and its albedo): the built-in table by default */
static mf_ltc table_ltc(mf_vec3 wo, double ax, double ay, double *alb)
{
    *alb = mf_ltc_ggx_aniso_albedo(wo, (mf_real)ax, (mf_real)ay);
    return mf_ltc_ggx_aniso(wo, (mf_real)ax, (mf_real)ay);
}
#ifndef LTC_UNDER_TEST
#define LTC_UNDER_TEST table_ltc
#endif

int main(int argc, char **argv)
{
    static const double axs[3] = { 0.2, 0.4, 0.7 }, rs[4] = { 1, 2, 5, 10 }, ths_main[5] = { 0, 20, 40, 60, 80 }, ths_low[5] = { 2, 4, 6, 8, 10 };
    const double *ths = ths_main;
    double off_az = 0, off_el = 0;
    float *pub[2] = { 0, 0 };
    int quick = 0, i, N = 512, ia, ir, ip, it, s, n = 0;
    double sum_shape[3] = { 0 }, sum_ours[3] = { 0 }, sum_pub[2][3] = { { 0 } }, sum_r[4][3] = { { 0 } }, sum_rp[4][3] = { { 0 } };
    int cnt[3] = { 0 }, cnt_r[4] = { 0 };
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--low")) ths = ths_low;
        else if (!strcmp(argv[i], "--off") && i + 2 < argc) { off_az = atof(argv[i + 1]); off_el = atof(argv[i + 2]); i += 2; }
        else if (!strcmp(argv[i], "--xy") && i + 1 < argc) pub[0] = pub_load(argv[++i]);
        else if (!strcmp(argv[i], "--al") && i + 1 < argc) pub[1] = pub_load(argv[++i]);
    }
    if (quick) N = 128;
    for (ia = 0; ia < 3; ++ia)
        for (ir = 0; ir < 4; ++ir)
            for (ip = 0; ip < 8; ++ip)
                for (it = 0; it < 5; ++it) {
                    double ax = axs[ia], ay = ax / rs[ir], ph = (ip + 0.25) * PI_D / 4, th = ths[it] * PI_D / 180;
                    mf_vec3 wo = mf_vec3_make(sin(th) * cos(ph), sin(th) * sin(ph), cos(th)), R, hz;
                    mf_ndf d = mf_ggx(ax, ay);
                    quad_light q;
                    tube_light tb;
                    double ref[3] = { 0 }, alb = 0, est[3], albt, ltcv[3];
                    mf_ltc l;
                    int a, b;
                    R = mf_vec3_make(-wo.x, -wo.y, wo.z);
                    if (off_az != 0 || off_el != 0) {   /* beside the lobe */
                        double az = atan2(R.y, R.x) + off_az, el = asin(R.z) - off_el;
                        if (el < 0.05) el = 0.05;
                        R = mf_vec3_make(cos(el) * cos(az), cos(el) * sin(az), sin(el));
                    }
                    q.c = mf_scale(R, 2.0); q.n = mf_scale(R, -1.0);
                    hz = fabs(R.z) > 0.999 ? mf_vec3_make(cos(ph + PI_D / 2), sin(ph + PI_D / 2), 0) : mf_normalize(mf_cross(mf_vec3_make(0, 0, 1), R));
                    q.e1 = hz; q.e2 = mf_cross(q.n, hz); q.h = 0.4;
                    tb.p1 = mf__vsub(q.c, hz); tb.p2 = mf_add(q.c, hz); tb.r = 0.05;
                    for (a = 0; a < N; ++a)
                        for (b = 0; b < N; ++b) {
                            mf_sample r = mf_brdf_sample(&d, wo, (a + 0.5) / N, (b + 0.5) / N);
                            if (!(r.pdf > 0) || !(r.wi.z > 0)) continue;
                            alb += r.weight;
                            if (hit_plane(&q, r.wi, 0)) ref[0] += r.weight;
                            if (hit_plane(&q, r.wi, 1)) ref[1] += r.weight;
                            if (hit_tube(&tb, r.wi)) ref[2] += r.weight;
                        }
                    alb /= (double)N * N;
                    for (s = 0; s < 3; ++s) ref[s] /= (double)N * N;
                    l = LTC_UNDER_TEST(wo, ax, ay, &albt);
                    {
                        mf_vec3 v[4];
                        v[0] = mf_add(q.c, mf_add(mf_scale(q.e1, -q.h), mf_scale(q.e2, -q.h)));
                        v[1] = mf_add(q.c, mf_add(mf_scale(q.e1, q.h), mf_scale(q.e2, -q.h)));
                        v[2] = mf_add(q.c, mf_add(mf_scale(q.e1, q.h), mf_scale(q.e2, q.h)));
                        v[3] = mf_add(q.c, mf_add(mf_scale(q.e1, -q.h), mf_scale(q.e2, q.h)));
                        /* counterclockwise seen from the point: try both windings, the front one is nonzero */
                        ltcv[0] = mf_ltc_integrate(&l, v, 4, 1);
                        ltcv[1] = mf_ltc_integrate_disk(&l, q.c, q.n, q.h, 1);
                        ltcv[2] = mf_ltc_integrate_tube(&l, tb.p1, tb.p2, tb.r);
                        for (s = 0; s < 3; ++s) {
                            double e;
                            if (!(ref[s] > 1e-4 * alb)) continue;
                            est[s] = alb * ltcv[s];
                            e = fabs(est[s] - ref[s]) / ref[s];
                            sum_shape[s] += e; sum_r[ir][s] += e;
                            sum_ours[s] += fabs(albt * ltcv[s] - ref[s]) / ref[s];
                            cnt[s]++; if (s == 0) cnt_r[ir]++;
                            {
                                int k;
                                for (k = 0; k < 2; ++k)
                                    if (pub[k]) {
                                        mf_ltc pl = pub_ltc(pub[k], k, wo, ax, ay);
                                        double pv = s == 0 ? mf_ltc_integrate(&pl, v, 4, 1)
                                                  : (s == 1 ? mf_ltc_integrate_disk(&pl, q.c, q.n, q.h, 1) : mf_ltc_integrate_tube(&pl, tb.p1, tb.p2, tb.r));
                                        double pe = fabs(alb * pv - ref[s]) / ref[s];
                                        sum_pub[k][s] += pe;
                                        if (k == 0) sum_rp[ir][s] += pe;
                                    }
                            }
                            if (getenv("VERBOSE"))
                                printf("ax %.2f ay %.3f ph %.2f th %2.0f shape %d ref %.4g ltc %.4g (%.3f) alb %.4f/%.4f\n", ax, ay, ph, ths[it], s, ref[s], est[s], e, alb, albt);
                        }
                    }
                    ++n;
                }
    printf("configurations %d (N = %d), lights counted: square %d disk %d tube %d\n", n, N, cnt[0], cnt[1], cnt[2]);
    printf("mean relative error       square  disk    tube    all\n");
    printf("ours (MC albedo, shape)   %.4f  %.4f  %.4f  %.4f\n", sum_shape[0] / cnt[0], sum_shape[1] / cnt[1], sum_shape[2] / cnt[2],
           (sum_shape[0] + sum_shape[1] + sum_shape[2]) / (cnt[0] + cnt[1] + cnt[2]));
    printf("ours (table albedo)       %.4f  %.4f  %.4f  %.4f\n", sum_ours[0] / cnt[0], sum_ours[1] / cnt[1], sum_ours[2] / cnt[2],
           (sum_ours[0] + sum_ours[1] + sum_ours[2]) / (cnt[0] + cnt[1] + cnt[2]));
    for (s = 0; s < 2; ++s)
        if (pub[s])
            printf("published %s (MC albedo) %.4f  %.4f  %.4f  %.4f\n", s ? "a-l  " : "ax-ay", sum_pub[s][0] / cnt[0], sum_pub[s][1] / cnt[1],
                   sum_pub[s][2] / cnt[2], (sum_pub[s][0] + sum_pub[s][1] + sum_pub[s][2]) / (cnt[0] + cnt[1] + cnt[2]));
    for (ir = 0; ir < 4; ++ir)
        printf("r = %2.0f: ours %.4f %.4f %.4f%s", rs[ir], sum_r[ir][0] / cnt_r[ir], sum_r[ir][1] / cnt_r[ir], sum_r[ir][2] / cnt_r[ir],
               pub[0] ? "" : "\n"),
            pub[0] ? printf("   published ax-ay %.4f %.4f %.4f\n", sum_rp[ir][0] / cnt_r[ir], sum_rp[ir][1] / cnt_r[ir], sum_rp[ir][2] / cnt_r[ir]) : 0;
    return 0;
}
