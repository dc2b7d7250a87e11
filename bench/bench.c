/* bench.c - microbenchmarks of microfacet.h. One line per case:
 *   bench <name> <ns_per_op> [key=value ...]
 * Fixed inputs (4096 directions and random pairs), warm-up, the best of 7
 * repetitions, and a sink so nothing is optimized away. Where a plain
 * implementation of the published algorithm makes sense it runs in the same
 * process and the line carries ratio=<ours / baseline>: the machine is shared
 * and noisy, ratios are what to compare. */
#define _POSIX_C_SOURCE 199309L
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <math.h>
#include <stdlib.h>
#ifdef MF_BENCH_BIG_TU
#include "big_tu.h"
#endif

#define N 4096
#define REPS 7

static mf_vec3 g_wo[N], g_wi[N], g_wm[N], g_wt[N];
static mf_real g_u1[N], g_u2[N];
static volatile double g_sink;

/* the thread's CPU time where there is one: on a shared machine the time
 * the bench is descheduled does not count */
static double now_ns(void)
{
    struct timespec ts;
#ifdef CLOCK_THREAD_CPUTIME_ID
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
#else
    clock_gettime(CLOCK_MONOTONIC, &ts);
#endif
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static unsigned g_state = 12345u;
static mf_real rnd(void)
{
    g_state = g_state * 1664525u + 1013904223u;
    return (mf_real)((double)(g_state >> 8) * (1.0 / 16777216.0));
}

static mf_vec3 rnd_dir(mf_real max_theta)
{
    double t = (double)rnd() * (double)max_theta, p = 6.283185307179586 * (double)rnd();
    return mf_vec3_make((mf_real)(sin(t) * cos(p)), (mf_real)(sin(t) * sin(p)), (mf_real)cos(t));
}

/* ---- baseline: a plain implementation of Heitz 2018, "Sampling the GGX
 * Distribution of Visible Normals", JCGT 7(4), Listing 1 ---- */
static mf_vec3 heitz2018_vndf(mf_vec3 ve, mf_real ax, mf_real ay, mf_real u1, mf_real u2)
{
    mf_vec3 vh = mf_normalize(mf_vec3_make(ax * ve.x, ay * ve.y, ve.z)), t1, t2, nh;
    mf_real lensq = vh.x * vh.x + vh.y * vh.y, r, phi, p1, p2, s;
    t1 = lensq > MF_R(0.0) ? mf_scale(mf_vec3_make(-vh.y, vh.x, MF_R(0.0)), MF_R(1.0) / MF_SQRT(lensq))
                           : mf_vec3_make(MF_R(1.0), MF_R(0.0), MF_R(0.0));
    t2 = mf_cross(vh, t1);
    r = MF_SQRT(u1);
    phi = MF_R(2.0) * MF_PI * u2;
    p1 = r * MF_COS(phi);
    p2 = r * MF_SIN(phi);
    s = MF_R(0.5) * (MF_R(1.0) + vh.z);
    p2 = (MF_R(1.0) - s) * MF_SQRT(MF_R(1.0) - p1 * p1) + s * p2;
    nh = mf_add(mf_add(mf_scale(t1, p1), mf_scale(t2, p2)),
                mf_scale(vh, MF_SQRT(mf_max(MF_R(0.0), MF_R(1.0) - p1 * p1 - p2 * p2))));
    return mf_normalize(mf_vec3_make(ax * nh.x, ay * nh.y, mf_max(MF_R(0.0), nh.z)));
}

/* plain GGX D and Smith G2 (Walter 2007 / Heitz 2014 textbook forms) */
static mf_real plain_ggx_D(mf_real ax, mf_real ay, mf_vec3 m)
{
    mf_real c2 = m.z * m.z, t = (m.x * m.x / (ax * ax) + m.y * m.y / (ay * ay)) / c2;
    mf_real den = MF_PI * ax * ay * c2 * c2 * (MF_R(1.0) + t) * (MF_R(1.0) + t);
    return m.z > MF_R(0.0) ? MF_R(1.0) / den : MF_R(0.0);
}
static mf_real plain_ggx_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / (w.z * w.z);
    return (MF_SQRT(MF_R(1.0) + a2t2) - MF_R(1.0)) * MF_R(0.5);
}

/* ---- baseline: a plain implementation of LTC polygon shading as described
 * by Heitz et al. 2016 (Sec. 3-4): bilinear lookup of the four stored M^-1
 * entries, transform, Sutherland-Hodgman clipping at the horizon into a
 * vertex buffer, normalization, and per edge acos(a.b) times the normalized
 * (a x b).z ---- */
static mf_real plain_ltc_lookup(const float *tab, int n, mf_real ct, mf_real alpha, mf_real *m)
{
    mf_real x = MF_SQRT(MF_R(1.0) - ct) * (mf_real)(n - 1), y = MF_SQRT(alpha) * (mf_real)(n - 1), fx, fy;
    int ix = (int)x, iy = (int)y, k;
    if (ix > n - 2) ix = n - 2;
    if (iy > n - 2) iy = n - 2;
    fx = x - (mf_real)ix; fy = y - (mf_real)iy;
    for (k = 0; k < 4; ++k) {
        const float *e = tab + 6 * (iy * n + ix) + k;
        m[k] = (1 - fy) * ((1 - fx) * (mf_real)e[0] + fx * (mf_real)e[6]) + fy * ((1 - fx) * (mf_real)e[6 * n] + fx * (mf_real)e[6 * n + 6]);
    }
    return m[0];
}
static mf_real plain_ltc_polygon(const mf_real *m4, const mf_vec3 *p, int n)
{
    mf_vec3 in[16], out[17];
    int i, k = 0;
    mf_real sum = MF_R(0.0);
    for (i = 0; i < n; ++i)   /* M^-1 = [m0 0 m1; 0 1 0; m2 0 m3] */
        in[i] = mf_vec3_make(m4[0] * p[i].x + m4[1] * p[i].z, p[i].y, m4[2] * p[i].x + m4[3] * p[i].z);
    for (i = 0; i < n; ++i) {
        mf_vec3 a = in[i], b = in[(i + 1) % n];
        if (a.z > 0) out[k++] = a;
        if ((a.z > 0) != (b.z > 0)) {
            mf_real t = a.z / (a.z - b.z);
            out[k++] = mf_vec3_make(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), MF_R(0.0));
        }
    }
    for (i = 0; i < k; ++i) out[i] = mf_normalize(out[i]);
    for (i = 0; i < k; ++i) {
        mf_vec3 a = out[i], b = out[(i + 1) % k], c = mf_cross(a, b);
        mf_real sl = MF_SQRT(mf_dot(c, c));
        if (sl > MF_R(0.0)) sum += MF_ACOS(mf_clamp(mf_dot(a, b), MF_R(-1.0), MF_R(1.0))) * c.z / sl;
    }
    return MF_FABS(sum) * MF_R(0.15915494309189533577);
}

/* ---- baseline for n-gons: the published shader's algorithm (Heitz et al.
 * 2016, selfshadow/ltc_code ltc_quad.fs) generalized to n vertices: the
 * inverse transform (its sparse 5-product form, as the library), Sutherland-
 * Hodgman clipping to z >= 0 into a vertex buffer (crossing points
 * a.z b - b.z a as in ClipQuadToHorizon), normalization, and per edge its
 * IntegrateEdge: the rational theta / sin theta fit times (a x b).z, with
 * 0.5 / sqrt(1 - d^2) - fit beyond pi/2 ---- */
static mf_real plain_rat_edge(mf_vec3 a, mf_vec3 b)
{
    mf_real x = mf_dot(a, b), y = MF_FABS(x);
    mf_real na = MF_R(0.8543985) + (MF_R(0.4965155) + MF_R(0.0145206) * y) * y;
    mf_real nb = MF_R(3.4175940) + (MF_R(4.1616724) + y) * y, v = na / nb;
    mf_real ts = x > MF_R(0.0) ? v : MF_R(0.5) / MF_SQRT(mf_max(MF_R(1.0) - x * x, MF_R(1e-7))) - v;
    return (a.x * b.y - a.y * b.x) * ts;
}
static mf_real plain_rat_polygon(const mf_real *Mi, const mf_vec3 *p, int n)
{
    mf_vec3 in[64], out[128];
    int i, k = 0;
    mf_real sum = MF_R(0.0);
    for (i = 0; i < n; ++i)   /* M^-1 = [m0 0 m2; 0 m4 0; m6 0 m8] */
        in[i] = mf_vec3_make(Mi[0] * p[i].x + Mi[2] * p[i].z, Mi[4] * p[i].y, Mi[6] * p[i].x + Mi[8] * p[i].z);
    for (i = 0; i < n; ++i) {
        mf_vec3 a = in[i], b = in[i + 1 == n ? 0 : i + 1];
        if (a.z > 0) out[k++] = a;
        if ((a.z > 0) != (b.z > 0))
            out[k++] = mf_vec3_make(a.z * b.x - b.z * a.x, a.z * b.y - b.z * a.y, MF_R(0.0));
    }
    if (k < 3) return MF_R(0.0);
    for (i = 0; i < k; ++i) out[i] = mf_normalize(out[i]);
    for (i = 0; i < k; ++i) sum += plain_rat_edge(out[i], out[i + 1 == k ? 0 : i + 1]);
    return MF_FABS(sum);
}

typedef double (*bench_fn)(const mf_ndf *d);

/* ---- tabulated distributions ---- */
static double b_D(const mf_ndf *d);
static double b_lambda(const mf_ndf *d);
static double b_sample_D(const mf_ndf *d);
static double b_vndf(const mf_ndf *d);
static double b_brdf(const mf_ndf *d);
static double run(bench_fn f, const mf_ndf *d);
static void bench_tabulated(void)
{
    /* a uniform 91-point two-lobe curve, and tabulated copies of GGX 0.3 at
     * 64 and 256 control points, against the analytic GGX in the same run */
    mf_real th[91], dv[91];
    mf_tabulated tabs[3];
    const char *names[3] = { "tab_two_lobe_91u", "tab_ggx_copy_64", "tab_ggx_copy_256" };
    mf_ndf ggx = mf_ggx(MF_R(0.3), MF_R(0.3));
    double t0, t1, tb[3];
    int i, k;
    for (i = 0; i < 91; ++i) {
        double a = 1.5707963267948966 * i / 90.0;
        th[i] = (mf_real)a;
        dv[i] = (mf_real)(exp(-(a / 0.2) * (a / 0.2)) + 0.3 * exp(-((a - 0.8) / 0.15) * ((a - 0.8) / 0.15)));
    }
    t0 = now_ns(); mf_tabulated_build(&tabs[0], th, dv, NULL, 91); t1 = now_ns(); tb[0] = t1 - t0;
    t0 = now_ns(); mf_tabulated_from_ndf(&tabs[1], &ggx, 64); t1 = now_ns(); tb[1] = t1 - t0;
    t0 = now_ns(); mf_tabulated_from_ndf(&tabs[2], &ggx, 256); t1 = now_ns(); tb[2] = t1 - t0;
    {
        double gd = run(b_D, &ggx), gl = run(b_lambda, &ggx), gs = run(b_sample_D, &ggx), gv = run(b_vndf, &ggx), gb = run(b_brdf, &ggx);
        for (k = 0; k < 3; ++k) {
            mf_ndf d = mf_tabulated_ndf(&tabs[k]);
            double td = run(b_D, &d), tl = run(b_lambda, &d), ts = run(b_sample_D, &d), tv = run(b_vndf, &d), tf = run(b_brdf, &d);
            printf("bench %s_build %.0f ms=%.2f points=%d KB=%.1f\n", names[k], tb[k], tb[k] * 1e-6, tabs[k].n,
                   (double)mf_tabulated_memory_bytes(&tabs[k]) / 1024.0);
            printf("bench %s_D %.2f vs_ggx=%.2f\n", names[k], td, td / gd);
            printf("bench %s_lambda %.2f vs_ggx=%.2f\n", names[k], tl, tl / gl);
            printf("bench %s_sample_D %.2f vs_ggx=%.2f\n", names[k], ts, ts / gs);
            printf("bench %s_sample_visible %.2f vs_ggx=%.2f\n", names[k], tv, tv / gv);
            printf("bench %s_brdf_eval %.2f vs_ggx=%.2f\n", names[k], tf, tf / gb);
        }
    }
    for (k = 0; k < 3; ++k) mf_tabulated_release(&tabs[k]);
}

/* GTR with its Lambda rule built once (mf_gtr_table; mf_gtr by value takes
 * it from a per-thread cache of four): a ring of 16 tables */
static mf_ndf gtr_tab(mf_real alpha, mf_real gamma)
{
    static mf_gtr_table t[16];
    static int next = 0;
    mf_gtr_table *p = &t[next++ & 15];
    mf_gtr_table_build(p, alpha, gamma);
    return mf_gtr_table_ndf(p);
}

/* ---- Inverse Bin Map ---- */
/* A car-paint flake map (thesis Sec. 5.5.4, Fig. 5.10): Voronoi flakes around
 * a jittered grid of `cell` texels, tiling, each flake's normal drawn from
 * GTR (alpha `ga`, gamma 1.5), normals below 0.2 clamped up. */
static mf_real *ibm_flake_map(int n, int cell, double ga)
{
    int g = n / cell, x, y, i;
    mf_ndf gtr = mf_gtr((mf_real)ga, MF_R(1.5));
    mf_real *m = (mf_real *)malloc(sizeof(mf_real) * 3 * (size_t)n * (size_t)n);
    float *sx = (float *)malloc(sizeof(float) * (size_t)(g * g)), *sy = (float *)malloc(sizeof(float) * (size_t)(g * g));
    mf_vec3 *fn = (mf_vec3 *)malloc(sizeof(mf_vec3) * (size_t)(g * g));
    if (!m || !sx || !sy || !fn) { free(m); free(sx); free(sy); free(fn); return NULL; }
    for (i = 0; i < g * g; ++i) {
        mf_vec3 t = mf_sample_D(&gtr, rnd(), rnd());
        if (t.z < MF_R(0.2)) t = mf_normalize(mf_vec3_make(t.x, t.y, MF_R(0.2)));
        fn[i] = t;
        sx[i] = (float)((i % g) + (double)rnd()) * (float)cell;
        sy[i] = (float)((i / g) + (double)rnd()) * (float)cell;
    }
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            int cx = x / cell, cy = y / cell, dx, dy, best = 0;
            float bd = 1e30f;
            for (dy = -1; dy <= 1; ++dy)
                for (dx = -1; dx <= 1; ++dx) {
                    int gx = (cx + dx + g) % g, gy = (cy + dy + g) % g, k = gy * g + gx;
                    float ox = sx[k] + (float)((cx + dx) - gx) * (float)cell - ((float)x + 0.5f);
                    float oy = sy[k] + (float)((cy + dy) - gy) * (float)cell - ((float)y + 0.5f);
                    if (ox * ox + oy * oy < bd) { bd = ox * ox + oy * oy; best = k; }
                }
            m[3 * ((size_t)y * n + x)] = fn[best].x;
            m[3 * ((size_t)y * n + x) + 1] = fn[best].y;
            m[3 * ((size_t)y * n + x) + 2] = fn[best].z;
        }
    free(sx); free(sy); free(fn);
    return m;
}

/* A smooth map: a tiling height field of six waves (wave vectors of -4..4
 * periods per side, total amplitude 1), normals from its analytic gradient:
 * nearly every texel has its own normal and bin runs are short. */
static mf_real *ibm_smooth_map(int n)
{
    double kx[6], ky[6], ph[6], amp[6];
    mf_real *m = (mf_real *)malloc(sizeof(mf_real) * 3 * (size_t)n * (size_t)n);
    int x, y, i;
    if (!m) return NULL;
    for (i = 0; i < 6; ++i) {
        kx[i] = (double)(int)(9.0 * (double)rnd()) - 4.0;
        ky[i] = (double)(int)(9.0 * (double)rnd()) - 4.0;
        if (kx[i] == 0.0 && ky[i] == 0.0) kx[i] = 1.0;
        ph[i] = 6.283185307179586 * (double)rnd();
        amp[i] = (0.5 + (double)rnd()) / 6.0;
    }
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            double gx = 0.0, gy = 0.0, l;
            for (i = 0; i < 6; ++i) {
                double c = cos(6.283185307179586 * (kx[i] * (x + 0.5) + ky[i] * (y + 0.5)) / n + ph[i]);
                gx += amp[i] * kx[i] * c;
                gy += amp[i] * ky[i] * c;
            }
            l = sqrt(gx * gx + gy * gy + 1.0);
            m[3 * ((size_t)y * n + x)] = (mf_real)(-gx / l);
            m[3 * ((size_t)y * n + x) + 1] = (mf_real)(-gy / l);
            m[3 * ((size_t)y * n + x) + 2] = (mf_real)(1.0 / l);
        }
    return m;
}

/* the best of 3 builds at flake alpha `alpha`, in ns; the last build stays in *ibm */
static double ibm_build_best(mf_ibm *ibm, const mf_real *nm, int n, double alpha)
{
    double best = 1e30, t0;
    int it;
    for (it = 0; it < 3; ++it) {
        t0 = now_ns();
        if (mf_ibm_build(ibm, nm, n, n, (mf_real)alpha) != MF_SUCCESS) return -1.0;
        t0 = now_ns() - t0;
        if (t0 < best) best = t0;
        if (it < 2) mf_ibm_release(ibm);
    }
    return best;
}

/* |P ∩ texel [x, x+1] x [y, y+1]|, P a convex counterclockwise polygon */
static double ibm_clip_area(const double *px, const double *py, double x0, double y0)
{
    double xa[12], ya[12], xb[12], yb[12], s = 0.0;
    int i, k, e, m = 4;
    for (i = 0; i < 4; ++i) { xa[i] = px[i]; ya[i] = py[i]; }
    for (e = 0; e < 4 && m > 0; ++e) {
        int o = 0;
        for (i = 0; i < m; ++i) {
            int j = (i + 1) % m;
            double di = e == 0 ? xa[i] - x0 : e == 1 ? x0 + 1 - xa[i] : e == 2 ? ya[i] - y0 : y0 + 1 - ya[i];
            double dj = e == 0 ? xa[j] - x0 : e == 1 ? x0 + 1 - xa[j] : e == 2 ? ya[j] - y0 : y0 + 1 - ya[j];
            if (di >= 0) { xb[o] = xa[i]; yb[o] = ya[i]; ++o; }
            if ((di >= 0) != (dj >= 0)) {
                double t = di / (di - dj);
                xb[o] = xa[i] + t * (xa[j] - xa[i]); yb[o] = ya[i] + t * (ya[j] - ya[i]); ++o;
            }
        }
        m = o;
        for (k = 0; k < m; ++k) { xa[k] = xb[k]; ya[k] = yb[k]; }
    }
    for (i = 0; i < m; ++i) s += xa[i] * ya[(i + 1) % m] - xa[(i + 1) % m] * ya[i];
    return 0.5 * fabs(s);
}

/* The baseline: the plain texel sum of Eq. 5.2 - every texel of the
 * footprint's bounding box, its exact overlap, C with its own normal (the
 * same Beckmann flake lobe and G_x as the IBM, G_x computed once). */
static double ibm_brute(const mf_real *nm, int n, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real alpha,
                        const mf_ndf *shadow)
{
    double px[4], py[4], cx = (double)f->u * n, cy = (double)f->v * n, ax = (double)f->ax * n, ay = (double)f->ay * n;
    double bx = (double)f->bx * n, by = (double)f->by * n, x0, x1, y0, y1, sum = 0.0, area = fabs(ax * by - ay * bx), gx;
    mf_vec3 h = mf_normalize(mf_add(wo, wi));
    int x, y;
    px[0] = cx - 0.5 * ax - 0.5 * bx; py[0] = cy - 0.5 * ay - 0.5 * by;
    px[1] = cx + 0.5 * ax - 0.5 * bx; py[1] = cy + 0.5 * ay - 0.5 * by;
    px[2] = cx + 0.5 * ax + 0.5 * bx; py[2] = cy + 0.5 * ay + 0.5 * by;
    px[3] = cx - 0.5 * ax + 0.5 * bx; py[3] = cy - 0.5 * ay + 0.5 * by;
    x0 = fmin(fmin(px[0], px[1]), fmin(px[2], px[3])); x1 = fmax(fmax(px[0], px[1]), fmax(px[2], px[3]));
    y0 = fmin(fmin(py[0], py[1]), fmin(py[2], py[3])); y1 = fmax(fmax(py[0], py[1]), fmax(py[2], py[3]));
    gx = 1.0 / (1.0 + (double)mf_lambda(shadow, wo) + (double)mf_lambda(shadow, wi));
    for (y = (int)floor(y0); y < (int)ceil(y1); ++y)
        for (x = (int)floor(x0); x < (int)ceil(x1); ++x) {
            double a = ibm_clip_area(px, py, x, y);
            const mf_real *t;
            mf_vec3 tn;
            mf_real co, ci, ch, d;
            if (!(a > 0.0)) continue;
            t = nm + 3 * ((size_t)(((y % n) + n) % n) * (size_t)n + (size_t)(((x % n) + n) % n));
            tn = mf_vec3_make(t[0], t[1], t[2]);
            co = mf_dot(wo, tn); ci = mf_dot(wi, tn); ch = mf_dot(h, tn);
            if (!(co > 0) || !(ci > 0) || !(ch > 0)) continue;
            {
                mf_vec3 xh = mf_cross(h, tn), xo = mf_cross(wo, tn), xi = mf_cross(wi, tn);
                d = mf_beckmann_D(alpha, alpha, mf_vec3_make(MF_SQRT(mf_dot(xh, xh)), MF_R(0.0), ch));
                if (!(d > 0)) continue;
                sum += a * (double)d / (1.0 + (double)mf_beckmann_lambda(alpha, alpha, mf_vec3_make(MF_SQRT(mf_dot(xo, xo)), 0, co)) +
                                        (double)mf_beckmann_lambda(alpha, alpha, mf_vec3_make(MF_SQRT(mf_dot(xi, xi)), 0, ci)));
            }
        }
    return sum * gx / (area * 4.0 * (double)wo.z * (double)wi.z);
}

/* IBM on a 2048^2 flake map for the thesis' flake roughnesses (Table 5.5):
 * build time and memory; BRDF eval for footprints of 1, 1e2, 1e4 and 1e6
 * texels against the plain texel sum (ratio = IBM / baseline); pdf and
 * sampling. Directions: wo within 60 degrees, wi the mirror of wo about a
 * GTR flake normal, so that the queries hit glints. */
static void bench_ibm(void)
{
    const int n = 2048, nq = 256;
    const double alphas[4] = { 0.0025, 0.01, 0.04, 0.16 }, texels[4] = { 1.0, 1e2, 1e4, 1e6 };
    mf_real *nm = ibm_flake_map(n, 6, 0.002);
    mf_ndf gtr = gtr_tab(MF_R(0.002), MF_R(1.5));
    mf_footprint fq[nq];
    mf_vec3 wo[nq], wi[nq];
    int a, k, q;
    if (!nm) return;
    for (q = 0; q < nq; ++q) {
        mf_vec3 m = mf_sample_D(&gtr, rnd(), rnd());
        wo[q] = rnd_dir(MF_R(1.05));
        wi[q] = mf_reflect(wo[q], m);
        if (!(wi[q].z > MF_R(0.05))) { wo[q] = mf_vec3_make(0, 0, 1); wi[q] = mf_reflect(wo[q], m); }
    }
    for (a = 0; a < 4; ++a) {
        mf_ibm ibm;
        double t0, t1, best = ibm_build_best(&ibm, nm, n, alphas[a]);
        char name[64];
        if (best < 0.0) { free(nm); return; }
        mf_ibm_set_shadowing(&ibm, &gtr);   /* G_x: the flakes' GTR (Sec. 5.5.4) */
        snprintf(name, sizeof name, "ibm_build_2048_a%g", alphas[a]);
        printf("bench %s %.0f ms=%.1f MB=%.1f bins=%d^2\n", name, best, best * 1e-6,
               (double)mf_ibm_memory_bytes(&ibm) / (1024.0 * 1024.0), ibm.res);
        for (k = 0; k < 4; ++k) {
            double side = sqrt(texels[k]) / n, tib = 1e30, tbr = 1e30, tpdf = 1e30, tsam = 1e30, s = 0.0;
            int nb = texels[k] >= 1e6 ? 2 : (texels[k] >= 1e4 ? 16 : nq), r;
            for (q = 0; q < nq; ++q) {
                double ang = 6.283185307179586 * (double)rnd();
                fq[q].u = rnd(); fq[q].v = rnd();
                fq[q].ax = (mf_real)(side * cos(ang)); fq[q].ay = (mf_real)(side * sin(ang));
                fq[q].bx = (mf_real)(-side * sin(ang)); fq[q].by = (mf_real)(side * cos(ang));
            }
            for (r = 0; r < 3; ++r) {
                t0 = now_ns();
                for (q = 0; q < nq; ++q) s += (double)mf_ibm_brdf(&ibm, &fq[q], wo[q], wi[q]);
                t1 = now_ns(); if ((t1 - t0) / nq < tib) tib = (t1 - t0) / nq;
                for (q = 0; q < nq; ++q) s += (double)mf_ibm_pdf(&ibm, &fq[q], wo[q], wi[q]);
                t0 = now_ns(); if ((t0 - t1) / nq < tpdf) tpdf = (t0 - t1) / nq;
                for (q = 0; q < nq; ++q) s += (double)mf_ibm_sample(&ibm, &fq[q], wo[q], rnd(), rnd(), rnd(), rnd()).wi.z;
                t1 = now_ns(); if ((t1 - t0) / nq < tsam) tsam = (t1 - t0) / nq;
            }
            t0 = now_ns();
            for (q = 0; q < nb; ++q) s += ibm_brute(nm, n, &fq[q], wo[q], wi[q], ibm.alpha, &gtr);
            t1 = now_ns();
            tbr = (t1 - t0) / nb;
            {   /* the same queries through the IBM, for a like-for-like ratio */
                double tsub;
                t0 = now_ns();
                for (q = 0; q < nb; ++q) s += (double)mf_ibm_brdf(&ibm, &fq[q], wo[q], wi[q]);
                tsub = (now_ns() - t0) / nb;
                printf("bench ibm_eval_a%g_texels%g %.0f brute=%.0f ratio=%.4f pdf=%.0f sample=%.0f\n", alphas[a], texels[k],
                       tib, tbr, tsub / tbr, tpdf, tsam);
            }
            g_sink += s;
        }
        mf_ibm_release(&ibm);
    }
    free(nm);
    /* the build on two more maps at alpha 0.01: a smooth one (every texel
     * its own normal) and finer, rougher flakes (Voronoi 4 texels apart, GTR
     * alpha 0.05) */
    for (a = 0; a < 2; ++a) {
        mf_ibm ibm;
        double best;
        nm = a == 0 ? ibm_smooth_map(n) : ibm_flake_map(n, 4, 0.05);
        if (!nm) return;
        best = ibm_build_best(&ibm, nm, n, 0.01);
        free(nm);
        if (best < 0.0) return;
        printf("bench ibm_build_2048_a0.01_%s %.0f ms=%.1f MB=%.1f bins=%d^2\n", a == 0 ? "smooth" : "flakes4", best,
               best * 1e-6, (double)mf_ibm_memory_bytes(&ibm) / (1024.0 * 1024.0), ibm.res);
        mf_ibm_release(&ibm);
    }
}

/* ---- microsurface generation and the gonioreflectometer ---- */
/* Generation: Beckmann alpha 0.5, 500 iterations (the paper's setting), one
 * run each (they take seconds); ns per cell and iteration, and the ratio to
 * the paper's ~15 minutes for 1024^2 (a C++ program on an i7; not this
 * machine, so only indicative). 1024^2 x 500 runs only with MF_BENCH_FULL set
 * (it takes about a minute); otherwise 1024^2 x 100. Tracing: rays per second
 * on a 512^2 Beckmann 0.5 surface at theta_i = 1 rad, mirror and Lambertian
 * facets. Then the first bounce against the Smith model, at alpha 0.5 /
 * theta_i 1 and at the paper's Fig. 9 case (Beckmann sigma 0.75, i.e. alpha
 * 1.06, theta_i 1.5 rad): first-bounce energy (measured and model) and the
 * relative L1 distance of the lobes over a 147-cell sensor; their ns figure
 * is per traced ray. */
static double ms_lobe_l1(const mf_gonio *g, const mf_ndf *d, mf_vec3 wi, double *model_e1)
{
    mf_real *model = (mf_real *)malloc(sizeof(mf_real) * (size_t)g->cells);
    double l1 = 0.0, sm = 0.0;
    int c;
    if (!model) return -1.0;
    mf_gonio_model(g, d, wi, 8, model);
    for (c = 0; c < g->cells; ++c) { l1 += fabs((double)g->first[c] - (double)model[c]); sm += (double)model[c]; }
    free(model);
    *model_e1 = sm;
    return l1 / sm;
}

static void bench_microsurface(void)
{
    mf_ndf d = mf_beckmann(MF_R(0.5), MF_R(0.5)), paper = mf_beckmann(MF_R(1.0606601717798212), MF_R(1.0606601717798212));
    mf_real *h = (mf_real *)malloc(sizeof(mf_real) * 1024 * 1024);
    mf_microsurface_stats st;
    mf_gonio g;
    mf_gonio_config cfg;
    int sizes[2] = { 512, 1024 }, k, f, full = getenv("MF_BENCH_FULL") != NULL;
    double t0, t1, e1m, l1;
    if (!h || mf_gonio_init(&g, 8) != MF_SUCCESS) { free(h); return; }
    for (k = 0; k < 2; ++k) {   /* default options (NULL), seed 1 */
        int n = sizes[k], it = (n == 1024 && !full) ? 100 : 500;
        t0 = now_ns();
        if (mf_microsurface_generate_ex(&d, n, it, 1, NULL, h, &st) != MF_SUCCESS) continue;
        t1 = now_ns();
        printf("bench microsurface_generate_%d_x%d %.1f s=%.2f below=%.3f", n, it, (t1 - t0) / ((double)n * n * it),
               (t1 - t0) * 1e-9, (double)st.below);
        if (n == 1024 && it == 500) printf(" paper_15min_ratio=%.3f", (t1 - t0) * 1e-9 / 900.0);
        printf("\n");
    }
    /* tracing speed on a 512^2 surface */
    mf_microsurface_generate_ex(&d, 512, 200, 2, NULL, h, &st);
    memset(&cfg, 0, sizeof cfg);   /* the defaults: mirror facets, no absorption */
    cfg.seed = 1;
    cfg.wi = mf_vec3_make(MF_R(0.8414709848078965), MF_R(0.0), MF_R(0.5403023058681398));
    for (f = 0; f < 2; ++f) {
        cfg.facet = f ? MF_FACET_LAMBERT : MF_FACET_MIRROR;
        cfg.rays = 1000000;
        t0 = now_ns();
        mf_gonio_measure(&g, h, 512, &cfg);
        t1 = now_ns();
        printf("bench gonio_trace_%s_512 %.1f rays_per_s=%.3g bounces=%.3f lost=%d leaks=%d\n", f ? "lambert" : "mirror",
               (t1 - t0) / cfg.rays, cfg.rays / ((t1 - t0) * 1e-9), (double)g.mean_bounces, g.lost, g.leaks);
        if (!f) {
            l1 = ms_lobe_l1(&g, &d, cfg.wi, &e1m);
            printf("bench gonio_first_bounce_beckmann0.5_theta1 %.1f e1=%.4f e1_model=%.4f l1=%.4f e_multi=%.4f\n",
                   (t1 - t0) / cfg.rays, (double)g.energy_first, e1m, l1, (double)g.energy_multi);
        }
    }
    /* the paper's Fig. 9 case */
    mf_microsurface_generate_ex(&paper, 512, 200, 2, NULL, h, &st);
    cfg.facet = MF_FACET_MIRROR;
    cfg.wi = mf_vec3_make(MF_R(0.9974949866040544), MF_R(0.0), MF_R(0.0707372016677029));
    cfg.rays = 2000000;
    t0 = now_ns();
    mf_gonio_measure(&g, h, 512, &cfg);
    t1 = now_ns();
    l1 = ms_lobe_l1(&g, &paper, cfg.wi, &e1m);
    printf("bench gonio_first_bounce_paper_fig9_sigma0.75_theta1.5 %.1f e1=%.4f e1_model=%.4f l1=%.4f e_multi=%.4f\n",
           (t1 - t0) / cfg.rays, (double)g.energy_first, e1m, l1, (double)g.energy_multi);
    mf_gonio_release(&g);
    free(h);
}

static double run(bench_fn f, const mf_ndf *d)
{
    double best = 1e300;
    int r;
    g_sink += f(d); /* warm-up */
    for (r = 0; r < REPS; ++r) {
        double t0 = now_ns(), s = f(d), t1 = now_ns();
        g_sink += s;
        if ((t1 - t0) / N < best) best = (t1 - t0) / N;
    }
    return best;
}

/* baseline and ours alternately, 15 rounds, best of each: both see the same
 * machine load (run_pair2: each on its own distribution) */
static void run_pair2(bench_fn base, const mf_ndf *db, bench_fn ours, const mf_ndf *d, double *tb, double *to)
{
    int r;
    *tb = *to = 1e300;
    g_sink += base(db) + ours(d);
    for (r = 0; r < 15; ++r) {
        double t0 = now_ns(), s = base(db), t1 = now_ns(), s2 = ours(d), t2 = now_ns();
        g_sink += s + s2;
        if ((t1 - t0) / N < *tb) *tb = (t1 - t0) / N;
        if ((t2 - t1) / N < *to) *to = (t2 - t1) / N;
    }
}
static void run_pair(bench_fn base, bench_fn ours, const mf_ndf *d, double *tb, double *to)
{
    run_pair2(base, d, ours, d, tb, to);
}

#define LOOP(expr) double s = 0.0; int i; for (i = 0; i < N; ++i) { s += (double)(expr); } return s
static double b_D(const mf_ndf *d) { LOOP(mf_D(d, g_wm[i])); }
static double b_lambda(const mf_ndf *d) { LOOP(mf_lambda(d, g_wo[i])); }
static double b_G2(const mf_ndf *d) { LOOP(mf_G2(d, g_wo[i], g_wi[i], g_wm[i])); }
static double b_sample_D(const mf_ndf *d) { LOOP(mf_sample_D(d, g_u1[i], g_u2[i]).z); }
static double b_vndf(const mf_ndf *d) { LOOP(mf_sample_visible(d, g_wo[i], g_u1[i], g_u2[i]).z); }
static double b_brdf(const mf_ndf *d) { LOOP(mf_brdf(d, g_wo[i], g_wi[i])); }
static double b_brdf_pdf(const mf_ndf *d) { LOOP(mf_brdf_pdf(d, g_wo[i], g_wi[i])); }
/* construction, per call: GTR at non-integer gamma builds its Lambda rule */
static double b_make_ggx(const mf_ndf *d) { (void)d; LOOP(mf_ggx(MF_R(0.01) + g_u1[i], MF_R(0.01) + g_u1[i]).ax); }
static double b_make_gtr(const mf_ndf *d) { (void)d; LOOP(mf_gtr(MF_R(0.01) + g_u1[i], MF_R(0.01) + MF_R(3.9) * g_u2[i]).p.gtr.A); }
static double b_brdf_sample(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_brdf_sample(d, g_wo[i], g_u1[i], g_u2[i]);
        s += (double)r.wi.z + (double)r.weight;
    }
    return s;
}
/* Energy compensation: the lobe f_ms (three albedo lookups) against the
 * plain single-scattering mf_brdf; its sample record (cosine direction, pdf,
 * weight) against mf_brdf_sample's record; mf_albedo against a plain bilinear read of a
 * 64 x 64 float array (the baseline of a table lookup). */
static float g_plain_tab[64 * 64];
static mf_real plain_bilinear(mf_real a, mf_real mu)
{
    mf_real x = MF_SQRT(mf_clamp(a, MF_R(0.0), MF_R(1.0))) * MF_R(63.0), y = MF_SQRT(mf_clamp(mu, MF_R(0.0), MF_R(1.0))) * MF_R(63.0);
    int i = (int)x, j = (int)y;
    mf_real fx, fy;
    if (i > 62) i = 62;
    if (j > 62) j = 62;
    fx = x - (mf_real)i; fy = y - (mf_real)j;
    return ((mf_real)g_plain_tab[i * 64 + j] * (MF_R(1.0) - fy) + (mf_real)g_plain_tab[i * 64 + j + 1] * fy) * (MF_R(1.0) - fx) +
           ((mf_real)g_plain_tab[(i + 1) * 64 + j] * (MF_R(1.0) - fy) + (mf_real)g_plain_tab[(i + 1) * 64 + j + 1] * fy) * fx;
}
static double b_brdf_ms(const mf_ndf *d) { LOOP(mf_brdf_ms(d, g_wo[i], g_wi[i])); }
static double b_ms_sample(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_brdf_ms_sample(d, g_wo[i], g_u1[i], g_u2[i]);
        s += (double)r.wi.z + (double)r.weight;
    }
    return s;
}
static double b_ms_pdf(const mf_ndf *d) { LOOP(mf_brdf_ms_pdf(d, g_wo[i], g_wi[i])); }
static double b_albedo(const mf_ndf *d) { LOOP(mf_albedo(d, g_wo[i])); }
static double b_plain_lookup(const mf_ndf *d) { LOOP(plain_bilinear(d->ax, g_wo[i].z)); }
/* rough dielectric compensation lobe (eta 1.5, GGX of the bench), over the
 * same pairs as mf_dielectric_bsdf (half of them transmitted) */
static mf_dielectric_ms_table g_dms;
static double b_dielectric_ms(const mf_ndf *d) { (void)d; LOOP(mf_dielectric_ms_table_bsdf(&g_dms, g_wo[i], g_wt[i], MF_RADIANCE)); }
/* the same lobe from the built-in tables (no build), its sampler, and the
 * importance albedo lookup */
static double b_dielectric_bsdf_ms(const mf_ndf *d) { LOOP(mf_dielectric_bsdf_ms(d, g_wo[i], g_wt[i], MF_R(1.5), MF_RADIANCE)); }
static double b_dielectric_ms_sample(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_dielectric_bsdf_ms_sample(d, g_wo[i], MF_R(1.5), MF_RADIANCE, g_u1[i], g_u2[i], g_u1[(i + 7) % N]);
        s += (double)r.wi.z + (double)r.weight;
    }
    return s;
}
static double b_dielectric_albedo(const mf_ndf *d) { LOOP(mf_dielectric_albedo(d, g_wo[i], MF_R(1.5), MF_IMPORTANCE)); }

/* Rough dielectric, GGX only, written plainly from Walter et al. 2007 (wo
 * above, eta 1.5): the baseline of mf_dielectric_bsdf */
static mf_real plain_walter_ggx(mf_real ax, mf_real ay, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    int refl = wi.z > 0;
    mf_vec3 h = refl ? mf_add(wo, wi) : mf_add(wo, mf_scale(wi, eta));
    mf_real l = MF_SQRT(mf_dot(h, h)), oh, ih, F, G, D, den;
    if (!(l > 0)) return 0;
    h = mf_scale(h, (h.z < 0 ? -1 : 1) / l);
    oh = mf_dot(wo, h); ih = mf_dot(wi, h);
    if (oh <= 0 || (refl ? ih <= 0 : ih >= 0)) return 0;
    F = mf_fresnel_dielectric(oh, eta);
    D = plain_ggx_D(ax, ay, h);
    G = MF_R(1.0) / (MF_R(1.0) + plain_ggx_lambda(ax, ay, wo) + plain_ggx_lambda(ax, ay, mf_vec3_make(wi.x, wi.y, MF_FABS(wi.z))));
    if (refl) return F * D * G / (4 * wo.z * wi.z);
    den = ih + oh / eta;
    return (1 - F) * D * G * MF_FABS(ih) * oh / (den * den * wo.z * -wi.z) / (eta * eta);
}
static double b_walter_plain(const mf_ndf *d) { LOOP(plain_walter_ggx(d->ax, d->ay, g_wo[i], g_wt[i], MF_R(1.5))); }
static double b_dielectric(const mf_ndf *d) { LOOP(mf_dielectric_bsdf(d, g_wo[i], g_wt[i], MF_R(1.5), MF_RADIANCE)); }
static double b_dielectric_pdf(const mf_ndf *d) { LOOP(mf_dielectric_pdf(d, g_wo[i], g_wt[i], MF_R(1.5))); }
static double b_dielectric_sample(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_dielectric_sample(d, g_wo[i], MF_R(1.5), MF_RADIANCE, g_u1[i], g_u2[i], g_u1[(i + 7) % N]);
        s += (double)r.wi.z + (double)r.weight;
    }
    return s;
}

/* The 0.3 bounded sampler, which returned a normal: the cap of Dupuy &
 * Benyoub 2023 shrunk by k (Eto & Tokuyoshi 2023, Eq. 5), u clamped to
 * [0, 1]; other kinds than untransformed GGX take plain visible normals. The
 * baseline of the bounded lines below (0.4 has no such call: it returns the
 * record, mf_brdf_sample_bounded). */
static mf_vec3 bounded_normal_03(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (d->type != MF_NDF_GGX || d->transformed) return mf_sample_visible(d, wo, u1, u2);
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(d->ax, d->ay, wo, mf_clamp(u1, MF_R(0.0), MF_R(1.0)), mf_clamp(u2, MF_R(0.0), MF_R(1.0)),
                                  mf__ggx_bounded_k(d->ax, d->ay, wo));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}

/* sample, reflect, pdf: plain VNDF and bounded VNDF (the same work) */
static double b_vndf_pdf(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_vec3 wi = mf_reflect(g_wo[i], mf_sample_visible(d, g_wo[i], g_u1[i], g_u2[i]));
        s += (double)mf_brdf_pdf(d, g_wo[i], wi);
    }
    return s;
}
static double b_bounded_pdf(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_vec3 wi = mf_reflect(g_wo[i], bounded_normal_03(d, g_wo[i], g_u1[i], g_u2[i]));
        s += (double)mf_brdf_pdf_bounded(d, g_wo[i], wi);
    }
    return s;
}
static double b_heitz2018(const mf_ndf *d) { LOOP(heitz2018_vndf(g_wo[i], d->ax, d->ay, g_u1[i], g_u2[i]).z); }
static double b_ggx_inline(const mf_ndf *d) { LOOP(mf_ggx_sample_visible(d->ax, d->ay, g_wo[i], g_u1[i], g_u2[i]).z); }
static double b_plain_D(const mf_ndf *d) { LOOP(plain_ggx_D(d->ax, d->ay, g_wm[i])); }
static double b_plain_G2(const mf_ndf *d)
{
    LOOP(MF_R(1.0) / (MF_R(1.0) + plain_ggx_lambda(d->ax, d->ay, g_wo[i]) + plain_ggx_lambda(d->ax, d->ay, g_wi[i])));
}
/* the same work as mf_G2 (Heitz 2014 Eq. 99 with its facing tests chi+(wo.wm)
 * chi+(wi.wm) and wo.z, wi.z > 0), written plainly */
static double b_plain_G2_facing(const mf_ndf *d)
{
    LOOP((g_wo[i].z > MF_R(0.0) && g_wi[i].z > MF_R(0.0) && mf_dot(g_wo[i], g_wm[i]) > MF_R(0.0) && mf_dot(g_wi[i], g_wm[i]) > MF_R(0.0))
         ? MF_R(1.0) / (MF_R(1.0) + plain_ggx_lambda(d->ax, d->ay, g_wo[i]) + plain_ggx_lambda(d->ax, d->ay, g_wi[i])) : MF_R(0.0));
}
static double b_fresnel(const mf_ndf *d) { (void)d; LOOP(mf_fresnel_conductor(g_wo[i].z, MF_R(0.2), MF_R(3.9))); }

/* ---- baseline: Beckmann visible normals by slope-space inversion (Heitz &
 * d'Eon 2014) with the plain solve this library used before: safeguarded
 * Newton from erfinv(2u - 1) whatever the view, erfc and exp per step ---- */
static mf_vec3 g_wb[N];
static mf_vec3 newton_beckmann_vndf(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp, tv, mu, inv, k = MF_R(0.5) / MF_SQRT_PI, target, lo, hi, x, y, sx;
    int i;
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    tv = sv / mf_max(cv, MF_R(1e-30));
    mu = tv > MF_R(1.0) / MF_R(12.0) ? MF_R(1.0) / tv : MF_R(12.0);
    inv = MF_R(1.0) / (MF_R(1.0) + tv);
    target = mf_clamp(u1, MF_R(0.0), MF_R(1.0)) * (MF_R(0.5) * MF_ERFC(-mu) + tv * k * MF_EXP(-mu * mu)) * inv;
    lo = MF_R(-12.0); hi = mu;
    x = mf_clamp(mf_erfinv(MF_R(2.0) * u1 - MF_R(1.0)), lo, hi);
    for (i = 0; i < 60; ++i) {
        mf_real e = MF_EXP(-x * x);
        mf_real f = (MF_R(0.5) * MF_ERFC(-x) + tv * k * e) * inv - target;
        mf_real df = e * (MF_R(1.0) - tv * x) * inv / MF_SQRT_PI;
        if (mf__newton_step(&x, f, df, &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + MF_FABS(x)))) break;
    }
    y = mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
    sx = cp * x - sp * y;
    y = sp * x + cp * y;
    return mf_normalize(mf_vec3_make(-ax * sx, -ay * y, MF_R(1.0)));
}
static double b_beck_newton(const mf_ndf *d) { LOOP(newton_beckmann_vndf(d->ax, d->ay, g_wb[i], g_u1[i], g_u2[i]).z); }
static double b_beck_vndf(const mf_ndf *d) { LOOP(mf_beckmann_sample_visible(d->ax, d->ay, g_wb[i], g_u1[i], g_u2[i]).z); }
static void bench_beckmann_vndf(void)
{
    const double views[] = { 0.0, 30.0, 60.0, 80.0, 89.0 };
    mf_ndf d = mf_beckmann(MF_R(0.3), MF_R(0.3));
    int v, i;
    for (v = 0; v < 5; ++v) {
        double t = views[v] * 3.141592653589793 / 180.0, tb, to;
        for (i = 0; i < N; ++i) {
            double p = 6.283185307179586 * (double)rnd();
            g_wb[i] = mf_vec3_make((mf_real)(sin(t) * cos(p)), (mf_real)(sin(t) * sin(p)), (mf_real)cos(t));
        }
        run_pair(b_beck_newton, b_beck_vndf, &d, &tb, &to);
        printf("bench beckmann_vndf_%.0fdeg %.2f ratio=%.3f newton_baseline=%.2f alpha=0.3\n", views[v], to, to / tb, tb);
    }
}

/* ---- The sample record against the 0.3 sequence. A 0.3 sampler returned
 * the direction alone; the caller then asked for the pdf (for MIS) and the
 * weight f cos / pdf in separate calls, which evaluate D and Lambda again.
 * The baselines write that sequence out plainly; both sides sum the
 * direction's z, the pdf and the weight over the same inputs. ---- */
static double b_rec_brdf(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_brdf_sample(d, g_wo[i], g_u1[i], g_u2[i]);
        s += (double)r.wi.z + (double)r.pdf + (double)r.weight;
    }
    return s;
}
/* visible normal, reflection, mf_brdf_pdf, weight G2 / G1 = (1 + Lambda(wo))
 * / (1 + Lambda(wo) + Lambda(wi)) */
static double b_seq03_brdf(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_vec3 wo = g_wo[i], wi = mf_reflect(wo, mf_sample_visible(d, wo, g_u1[i], g_u2[i]));
        if (wi.z > MF_R(0.0)) {
            mf_real pdf = mf_brdf_pdf(d, wo, wi), lo = mf_lambda(d, wo);
            mf_real w = (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(d, wi));
            s += (double)wi.z + (double)pdf + (double)w;
        }
    }
    return s;
}
static double b_rec_dielectric(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_dielectric_sample(d, g_wo[i], MF_R(1.5), MF_RADIANCE, g_u1[i], g_u2[i], g_u1[(i + 7) % N]);
        s += (double)r.wi.z + (double)r.pdf + (double)r.weight;
    }
    return s;
}
/* the 0.3 dielectric sampler's direction (visible normal of wo's side,
 * reflection with probability F(wo.m), refraction otherwise), then
 * mf_dielectric_pdf and the weight mf_dielectric_bsdf |wi.z| / pdf */
static double b_seq03_dielectric(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_vec3 wo = g_wo[i], m, wi;
        mf_real eta = MF_R(1.5), sg = MF_R(1.0), c, pdf;
        if (wo.z < MF_R(0.0)) { wo = mf_scale(wo, MF_R(-1.0)); eta = MF_R(1.0) / eta; sg = MF_R(-1.0); }
        m = mf_sample_visible(d, wo, g_u1[i], g_u2[i]);
        c = mf_dot(wo, m);
        if (!(m.z > MF_R(0.0)) || !(c > MF_R(0.0))) continue;
        if (g_u1[(i + 7) % N] < mf_fresnel_dielectric(c, eta)) {
            wi = mf_reflect(wo, m);
            if (!(wi.z > MF_R(0.0))) continue;
        } else if (!mf_refract(wo, m, eta, &wi) || !(wi.z < MF_R(0.0))) continue;
        wi = mf_scale(wi, sg);
        pdf = mf_dielectric_pdf(d, g_wo[i], wi, MF_R(1.5));
        if (pdf > MF_R(0.0))
            s += (double)wi.z + (double)pdf +
                 (double)(mf_dielectric_bsdf(d, g_wo[i], wi, MF_R(1.5), MF_RADIANCE) * MF_FABS(wi.z) / pdf);
    }
    return s;
}
static double b_rec_bounded(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample r = mf_brdf_sample_bounded(d, g_wo[i], g_u1[i], g_u2[i]);
        s += (double)r.wi.z + (double)r.pdf + (double)r.weight;
    }
    return s;
}
/* the 0.3 bounded normal, reflection, mf_brdf_pdf_bounded, weight mf_brdf cos / pdf */
static double b_seq03_bounded(const mf_ndf *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_vec3 wo = g_wo[i], wi = mf_reflect(wo, bounded_normal_03(d, wo, g_u1[i], g_u2[i]));
        mf_real pdf;
        if (!(wi.z > MF_R(0.0))) continue;
        pdf = mf_brdf_pdf_bounded(d, wo, wi);
        if (pdf > MF_R(0.0)) s += (double)wi.z + (double)pdf + (double)(mf_brdf(d, wo, wi) * wi.z / pdf);
    }
    return s;
}
/* ./build/bench record runs only this */
static void bench_record(void)
{
    struct { const char *name; mf_ndf d; } ks[5];
    struct { const char *name; bench_fn base, rec; } ops[3];
    int k, o;
    ks[0].name = "ggx_a0.3"; ks[0].d = mf_ggx(MF_R(0.3), MF_R(0.3));
    ks[1].name = "ggx_a0.3_0.1"; ks[1].d = mf_ggx(MF_R(0.3), MF_R(0.1));
    ks[2].name = "beckmann_a0.3"; ks[2].d = mf_beckmann(MF_R(0.3), MF_R(0.3));
    ks[3].name = "gtr_a0.3_g1.5"; ks[3].d = mf_gtr(MF_R(0.3), MF_R(1.5));
    ks[4].name = "ggx_a0.3_transformed";
    ks[4].d = mf_transformed(mf_ggx(MF_R(0.3), MF_R(0.3)), mf_mat2_make(MF_R(1.5), MF_R(0.3), MF_R(-0.2), MF_R(0.8)));
    ops[0].name = "brdf_sample"; ops[0].base = b_seq03_brdf; ops[0].rec = b_rec_brdf;
    ops[1].name = "dielectric_sample"; ops[1].base = b_seq03_dielectric; ops[1].rec = b_rec_dielectric;
    ops[2].name = "brdf_sample_bounded"; ops[2].base = b_seq03_bounded; ops[2].rec = b_rec_bounded;
    for (o = 0; o < 3; ++o)
        for (k = 0; k < 5; ++k) {
            double tb, tr;
            run_pair(ops[o].base, ops[o].rec, &ks[k].d, &tb, &tr);
            printf("bench record_%s_%s %.2f ratio=%.3f seq03_baseline=%.2f\n", ops[o].name, ks[k].name, tr, tr / tb, tb);
        }
}

/* GTR Lambda across alpha and gamma (the mixture rule's nodes grow as alpha
 * falls) against isotropic GGX's in the same run */
static void bench_gtr_lambda(void)
{
    const double as[] = { 1e-4, 1e-3, 0.02, 0.3 }, gs[] = { 0.5, 1.5, 2.5, 3.5 };
    mf_ndf giso = mf_ggx(MF_R(0.3), MF_R(0.3));
    double worst = 0.0;
    int i, j, r;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j) {
            mf_gtr_table tab;
            mf_ndf d;
            double t = 1e300, gl = 1e300, x;
            mf_gtr_table_build(&tab, (mf_real)as[i], (mf_real)gs[j]);   /* the rule built once */
            d = mf_gtr_table_ndf(&tab);
            for (r = 0; r < 3; ++r) {   /* interleaved: both see the same machine state */
                x = run(b_lambda, &giso); if (x < gl) gl = x;
                x = run(b_lambda, &d); if (x < t) t = x;
            }
            if (t / gl > worst) worst = t / gl;
            printf("bench gtr_lambda_a%g_g%g %.2f ratio_to_ggx=%.2f nodes=%d ggx=%.2f\n", as[i], gs[j], t, t / gl, tab.nq, gl);
        }
    printf("bench gtr_lambda_worst ratio_to_ggx=%.2f\n", worst);
}

/* GTR and Student-t against isotropic GGX (alpha 0.3) in the same run: the
 * bench inputs (views to 1.5 rad); ./build/bench gtr_student runs only this */
static void bench_gtr_student(void)
{
    int k;
    {
        struct { const char *name; mf_ndf d; } hs[6];
        mf_ndf giso = mf_ggx(MF_R(0.3), MF_R(0.3));
        double gl, gd, gs, gv, mg, mt;
        hs[0].name = "gtr_a0.02_g1.5"; hs[0].d = gtr_tab(MF_R(0.02), MF_R(1.5));
        hs[1].name = "gtr_a0.3_g0.5"; hs[1].d = gtr_tab(MF_R(0.3), MF_R(0.5));
        hs[2].name = "gtr_a0.3_g2.5"; hs[2].d = gtr_tab(MF_R(0.3), MF_R(2.5));
        hs[3].name = "gtr_a0.3_g3"; hs[3].d = mf_gtr(MF_R(0.3), MF_R(3.0));
        hs[4].name = "student_t_a0.3_g1.6"; hs[4].d = mf_student_t(MF_R(0.3), MF_R(0.3), MF_R(1.6));
        hs[5].name = "student_t_a0.3_g3"; hs[5].d = mf_student_t(MF_R(0.3), MF_R(0.3), MF_R(3.0));
        gd = run(b_D, &giso); gl = run(b_lambda, &giso); gs = run(b_sample_D, &giso); gv = run(b_vndf, &giso);
        printf("bench ggx_iso_D %.2f\nbench ggx_iso_lambda %.2f\nbench ggx_iso_sample_D %.2f\nbench ggx_iso_sample_visible %.2f\n", gd, gl, gs, gv);
        for (k = 0; k < 6; ++k) {
            /* each against GGX run alternately with it (15 rounds, best of each) */
            const mf_ndf *d = &hs[k].d;
            bench_fn fs[4];
            const char *ops[4] = { "D", "lambda", "sample_D", "sample_visible" };
            int o;
            fs[0] = b_D; fs[1] = b_lambda; fs[2] = b_sample_D; fs[3] = b_vndf;
            for (o = 0; o < 4; ++o) {
                double tg, t;
                run_pair2(fs[o], &giso, fs[o], d, &tg, &t);
                printf("bench %s_%s %.2f ratio_to_ggx=%.2f ggx=%.2f\n", hs[k].name, ops[o], t, t / tg, tg);
            }
        }
        {   /* mf_gtr by value at a non-integer gamma: the rule and the envelope
             * from the per-thread cache, against the table's */
            mf_ndf bv = mf_gtr(MF_R(0.3), MF_R(1.5)), bt = gtr_tab(MF_R(0.3), MF_R(1.5));
            mf_ndf bv2 = mf_gtr(MF_R(0.02), MF_R(1.5)), bt2 = gtr_tab(MF_R(0.02), MF_R(1.5));
            double tt, t;
            run_pair2(b_lambda, &bt, b_lambda, &bv, &tt, &t);
            printf("bench gtr_a0.3_g1.5_by_value_lambda %.2f ratio_to_table=%.2f table=%.2f\n", t, t / tt, tt);
            run_pair2(b_vndf, &bt2, b_vndf, &bv2, &tt, &t);
            printf("bench gtr_a0.02_g1.5_by_value_sample_visible %.2f ratio_to_table=%.2f table=%.2f\n", t, t / tt, tt);
        }
        run_pair(b_make_ggx, b_make_gtr, &giso, &mg, &mt);
        printf("bench ggx_construct %.2f\nbench gtr_construct_noninteger_gamma %.2f ratio_to_ggx=%.2f\n", mg, mt, mt / mg);
        printf("# sizeof(mf_ndf) = %d bytes\n", (int)sizeof(mf_ndf));
    }
    bench_gtr_lambda();
}

struct bench_kind { const char *name; mf_ndf d; };
/* the core sections, one bit each; "core:<name>" runs one of them alone,
 * "sections" lists them (tools/bench_inline.sh runs the builds one section
 * at a time, in turn) */
static const char *const core_sections[] = { "ggx", "kinds", "transformed", "leadr", "ltc" };
#define CORE_SECTIONS ((int)(sizeof core_sections / sizeof *core_sections))
#define CORE_ALL ((1 << CORE_SECTIONS) - 1)
static void bench_core(const struct bench_kind *ks, int sections);
static void bench_lobes(void);
static void bench_sheen(void);
static void bench_fresnel_avg(void);
/* LTC: table lookup, quad above the horizon, quad crossing it, per vertex,
 * against the plain baseline; fitting */
static void bench_ltc_shapes(void);
static void bench_ltc_ngons(void);
static void bench_ltc(void)
{
    int i, k;
    /* LTC: table lookup, quad above the horizon, quad crossing it, per vertex
     * (32-gon minus quad over 28), against the plain baseline above */
    {
        mf_vec3 qa[4], qc[4], ng[32];
        double t0, t1, s = 0.0;
        int it, reps = 20000, nt = 0, na = 0;
        mf_ltc l = mf_ltc_ggx(MF_R(0.7), MF_R(0.3));
        mf_real m4[4];
        const float *tab = mf_ltc_ggx_table(&nt, &na);
        double best[10];
        mf_ltc_fit_result fr;
        mf_ndf g = mf_ggx(MF_R(0.3), MF_R(0.3));
        plain_ltc_lookup(tab, nt, MF_R(0.7), MF_R(0.3), m4);
        qa[0] = mf_vec3_make(-1, -1, 2); qa[1] = mf_vec3_make(-1, 1, 2); qa[2] = mf_vec3_make(1, 1, 2); qa[3] = mf_vec3_make(1, -1, 2);
        /* a vertical quad beside the lobe, crossing the horizon after M^-1 */
        qc[0] = mf_vec3_make(-1, 2, -1); qc[1] = mf_vec3_make(-1, 2, 1); qc[2] = mf_vec3_make(1, 2, 1); qc[3] = mf_vec3_make(1, 2, -1);
        for (k = 0; k < 32; ++k) {
            double a = -6.283185307179586 * k / 32;
            ng[k] = mf_vec3_make((mf_real)cos(a), (mf_real)sin(a), MF_R(2.0));
        }
        for (k = 0; k < 10; ++k) best[k] = 1e30;
        for (it = 0; it < 150; ++it) {
            double t[11];
            t[0] = now_ns();
            for (i = 0; i < reps; ++i) { mf_ltc m = mf_ltc_ggx(g_u1[i & (N - 1)], g_u2[i & (N - 1)]); s += (double)(m.Minv[0] + m.Minv[8]); }
            t[1] = now_ns();
            for (i = 0; i < reps; ++i) { mf_real mm[4]; plain_ltc_lookup(tab, nt, g_u1[i & (N - 1)], g_u2[i & (N - 1)], mm); s += (double)(mm[0] + mm[3]); }
            t[2] = now_ns();
            for (i = 0; i < reps; ++i) { qa[0].x = (mf_real)(-1.0 - 1e-7 * (i & 7)); s += (double)mf_ltc_integrate(&l, qa, 4, 1); }
            t[3] = now_ns();
            for (i = 0; i < reps; ++i) { qa[0].x = (mf_real)(-1.0 - 1e-7 * (i & 7)); s += (double)plain_ltc_polygon(m4, qa, 4); }
            t[4] = now_ns();
            for (i = 0; i < reps; ++i) { qc[0].y = (mf_real)(2.0 + 1e-7 * (i & 7)); s += (double)mf_ltc_integrate(&l, qc, 4, 1); }
            t[5] = now_ns();
            for (i = 0; i < reps; ++i) { qc[0].y = (mf_real)(2.0 + 1e-7 * (i & 7)); s += (double)plain_ltc_polygon(m4, qc, 4); }
            t[6] = now_ns();
            for (i = 0; i < reps / 4; ++i) { ng[0].x = (mf_real)(1.0 + 1e-7 * (i & 7)); s += (double)mf_ltc_integrate(&l, ng, 32, 1); }
            t[7] = now_ns();
            for (i = 0; i < reps / 4; ++i) { ng[0].x = (mf_real)(1.0 + 1e-7 * (i & 7)); s += (double)plain_ltc_polygon(m4, ng, 16); }
            t[8] = now_ns();
            for (i = 0; i < reps / 4; ++i) { ng[0].x = (mf_real)(1.0 + 1e-7 * (i & 7)); s += (double)mf_ltc_integrate(&l, ng, 16, 1); }
            t[9] = now_ns();
            for (i = 0; i < reps / 4; ++i) { ng[0].x = (mf_real)(1.0 + 1e-7 * (i & 7)); s += (double)plain_ltc_polygon(m4, ng, 4); }
            t[10] = now_ns();
            for (k = 0; k < 10; ++k) {
                double per = (t[k + 1] - t[k]) / (k >= 6 ? reps / 4 : reps);
                if (per < best[k]) best[k] = per;
            }
        }
        /* best: 0 lookup, 1 plain lookup, 2 quad, 3 plain quad, 4 clipped, 5 plain clipped, 6 ours 32-gon, 7 plain 16-gon, 8 ours 16-gon, 9 plain 4-gon */
        printf("bench ltc_ggx_table_lookup %.2f ratio=%.3f plain=%.2f\n", best[0], best[0] / best[1], best[1]);
        printf("bench ltc_quad_integrate %.2f ratio=%.3f plain=%.2f\n", best[2], best[2] / best[3], best[3]);
        printf("bench ltc_quad_clipped %.2f ratio=%.3f plain=%.2f\n", best[4], best[4] / best[5], best[5]);
        printf("bench ltc_per_vertex %.2f ratio=%.3f plain=%.2f ngon32=%.1f ngon16=%.1f plain16=%.1f plain4=%.1f\n",
               (best[6] - best[8]) / 16, (best[6] - best[8]) / 16 / ((best[7] - best[9]) / 12), (best[7] - best[9]) / 12,
               best[6], best[8], best[7], best[9]);
        g_sink += s;
        t0 = now_ns();
        fr.params[0] = fr.params[1] = MF_R(0.3); fr.params[2] = MF_R(0.0);
        for (it = 0; it < 16; ++it) mf_ltc_fit(&fr, &g, NULL, NULL, MF_R(1.0) - MF_R(0.06) * (mf_real)it, fr.params);
        t1 = now_ns();
        printf("bench ltc_fit_one_entry %.0f full_64x64_table_s=%.1f\n", (t1 - t0) / 16, (t1 - t0) / 16 * 4096 * 1e-9);
        g_sink += s + (double)fr.albedo;
        {   /* the anisotropic lookup (view in the shading frame, alpha_y = alpha_x / 3)
             * against the isotropic one at the same views and alpha_x, best of 20 */
            double ba = 1e30, bi = 1e30, sa = 0.0;
            for (it = 0; it < 20; ++it) {
                double u0, u1, u2;
                u0 = now_ns();
                for (i = 0; i < reps; ++i) {
                    mf_ltc m = mf_ltc_ggx_aniso(g_wo[i & (N - 1)], MF_R(0.05) + g_u2[i & (N - 1)], (MF_R(0.05) + g_u2[i & (N - 1)]) / 3);
                    sa += (double)(m.Minv[0] + m.Minv[8]);
                }
                u1 = now_ns();
                for (i = 0; i < reps; ++i) {
                    mf_ltc m = mf_ltc_ggx(g_wo[i & (N - 1)].z, MF_R(0.05) + g_u2[i & (N - 1)]);
                    sa += (double)(m.Minv[0] + m.Minv[8]);
                }
                u2 = now_ns();
                if ((u1 - u0) / reps < ba) ba = (u1 - u0) / reps;
                if ((u2 - u1) / reps < bi) bi = (u2 - u1) / reps;
            }
            printf("bench ltc_ggx_aniso_lookup %.2f ratio_to_isotropic=%.3f isotropic=%.2f\n", ba, ba / bi, bi);
            g_sink += sa;
        }
    }
    bench_ltc_shapes();
    bench_ltc_ngons();
}

/* LTC n-gons, n = 3..32, against plain_rat_polygon in the same run: a
 * regular n-gon given in the LTC's cosine space (moved by M), crossing the
 * horizon with about half its vertices below it (clipped) or all above
 * (unclipped); per extra vertex from n = 16 to 32 */
static void bench_ltc_ngons(void)
{
    static const int ns[] = { 3, 4, 5, 6, 7, 8, 10, 12, 16, 20, 24, 32 };
    mf_ltc l = mf_ltc_ggx(MF_R(0.7), MF_R(0.3));
    mf_vec3 pc[12][32], pu[12][32];
    double best[12][4], s = 0.0;
    int i, j, k, it, reps = 1000;
    for (j = 0; j < 12; ++j) {
        int n = ns[j];
        for (k = 0; k < n; ++k) {
            double a = 6.283185307179586 * (k + 0.3) / n, qc[3], qu[3];
            int r;
            qc[0] = 1.0; qc[1] = 0.8 * cos(a); qc[2] = 0.8 * sin(a);           /* a vertical n-gon across the horizon */
            qu[0] = 0.3 + 0.8 * cos(a); qu[1] = 0.2 - 0.8 * sin(a); qu[2] = 1.0; /* a horizontal one above */
            for (r = 0; r < 3; ++r) {
                mf_real *dc = r == 0 ? &pc[j][k].x : r == 1 ? &pc[j][k].y : &pc[j][k].z;
                mf_real *du = r == 0 ? &pu[j][k].x : r == 1 ? &pu[j][k].y : &pu[j][k].z;
                *dc = (mf_real)((double)l.M[3 * r] * qc[0] + (double)l.M[3 * r + 1] * qc[1] + (double)l.M[3 * r + 2] * qc[2]);
                *du = (mf_real)((double)l.M[3 * r] * qu[0] + (double)l.M[3 * r + 1] * qu[1] + (double)l.M[3 * r + 2] * qu[2]);
            }
        }
        for (k = 0; k < 4; ++k) best[j][k] = 1e30;
    }
    for (it = 0; it < 400; ++it)
        for (j = 0; j < 12; ++j) {
            int n = ns[j];
            mf_vec3 *c = pc[j], *u = pu[j];
            mf_real x0c = c[0].x, x0u = u[0].x;
            double t[5];
            t[0] = now_ns();
            for (i = 0; i < reps; ++i) { c[0].x = x0c + (mf_real)(1e-7 * (i & 7)); s += (double)mf_ltc_integrate(&l, c, n, 1); }
            t[1] = now_ns();
            for (i = 0; i < reps; ++i) { c[0].x = x0c + (mf_real)(1e-7 * (i & 7)); s += (double)plain_rat_polygon(l.Minv, c, n); }
            t[2] = now_ns();
            for (i = 0; i < reps; ++i) { u[0].x = x0u + (mf_real)(1e-7 * (i & 7)); s += (double)mf_ltc_integrate(&l, u, n, 1); }
            t[3] = now_ns();
            for (i = 0; i < reps; ++i) { u[0].x = x0u + (mf_real)(1e-7 * (i & 7)); s += (double)plain_rat_polygon(l.Minv, u, n); }
            t[4] = now_ns();
            c[0].x = x0c; u[0].x = x0u;
            for (k = 0; k < 4; ++k)
                if ((t[k + 1] - t[k]) / reps < best[j][k]) best[j][k] = (t[k + 1] - t[k]) / reps;
        }
    for (j = 0; j < 12; ++j)
        printf("bench ltc_ngon_%d clipped=%.2f ratio=%.3f plain=%.2f unclipped=%.2f ratio=%.3f plain=%.2f\n", ns[j],
               best[j][0], best[j][0] / best[j][1], best[j][1], best[j][2], best[j][2] / best[j][3], best[j][3]);
    printf("bench ltc_ngon_per_vertex clipped=%.2f ratio=%.3f plain=%.2f unclipped=%.2f ratio=%.3f plain=%.2f\n",
           (best[11][0] - best[8][0]) / 16, (best[11][0] - best[8][0]) / (best[11][1] - best[8][1]), (best[11][1] - best[8][1]) / 16,
           (best[11][2] - best[8][2]) / 16, (best[11][2] - best[8][2]) / (best[11][3] - best[8][3]), (best[11][3] - best[8][3]) / 16);
    g_sink += s;
}

/* LTC light shapes: a disk (exact cone form factor) against the plain way,
 * its inscribed 32-gon through mf_ltc_integrate (0.64% low); a line light
 * (closed form) against a camera-facing quad ribbon of the same width
 * through mf_ltc_integrate; a tube (line + half caps) */
static void bench_ltc_shapes(void)
{
    mf_ltc l = mf_ltc_ggx(MF_R(0.7), MF_R(0.3));
    mf_vec3 c = mf_vec3_make(MF_R(0.2), MF_R(0.1), MF_R(2.0)), n = mf_vec3_make(MF_R(0.1), MF_R(0.0), MF_R(-1.0));
    mf_vec3 p1 = mf_vec3_make(MF_R(-1.0), MF_R(0.3), MF_R(1.5)), p2 = mf_vec3_make(MF_R(1.0), MF_R(0.5), MF_R(2.0));
    mf_real cs[32], sn[32], rad = MF_R(0.5), lr = MF_R(0.02);
    mf_vec3 hc = mf_vec3_make(MF_R(0.0), MF_R(1.5), MF_R(0.1)), hu = mf_vec3_make(MF_R(0.8), MF_R(0.0), MF_R(0.0)), hv = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.5));
    double best[7], s = 0.0;
    int i, k, it, reps = 20000;
    for (k = 0; k < 32; ++k) { cs[k] = (mf_real)cos(-6.283185307179586 * k / 32); sn[k] = (mf_real)sin(-6.283185307179586 * k / 32); }
    for (k = 0; k < 7; ++k) best[k] = 1e30;
    for (it = 0; it < 100; ++it) {
        double t[8];
        t[0] = now_ns();
        for (i = 0; i < reps; ++i) { c.x = (mf_real)(0.2 + 1e-7 * (i & 7)); s += (double)mf_ltc_integrate_disk(&l, c, n, rad, 0); }
        t[1] = now_ns();
        for (i = 0; i < reps; ++i) {   /* plain: the disk's frame, 32 vertices, the polygon integral */
            mf_vec3 nn = mf_normalize(n), q[32];
            mf_basis fr = mf_basis_from_normal(nn);
            mf_vec3 tt = fr.t, bb = fr.b;
            c.x = (mf_real)(0.2 + 1e-7 * (i & 7));
            for (k = 0; k < 32; ++k) q[k] = mf_add(c, mf_add(mf_scale(tt, rad * cs[k]), mf_scale(bb, rad * sn[k])));
            s += (double)mf_ltc_integrate(&l, q, 32, 0);
        }
        t[2] = now_ns();
        for (i = 0; i < reps; ++i) { p1.x = (mf_real)(-1.0 - 1e-7 * (i & 7)); s += (double)mf_ltc_integrate_line(&l, p1, p2, lr); }
        t[3] = now_ns();
        for (i = 0; i < reps; ++i) {   /* plain: a ribbon of width 2 lr across the plane of the line and the point */
            mf_vec3 w, q[4];
            p1.x = (mf_real)(-1.0 - 1e-7 * (i & 7));
            w = mf_scale(mf_normalize(mf_cross(p1, p2)), lr);
            q[0] = mf_add(p1, w); q[1] = mf_add(p2, w); q[2] = mf_add(p2, mf_scale(w, MF_R(-1.0))); q[3] = mf_add(p1, mf_scale(w, MF_R(-1.0)));
            s += (double)mf_ltc_integrate(&l, q, 4, 1);
        }
        t[4] = now_ns();
        for (i = 0; i < reps; ++i) { p1.x = (mf_real)(-1.0 - 1e-7 * (i & 7)); s += (double)mf_ltc_integrate_tube(&l, p1, p2, lr); }
        t[5] = now_ns();
        /* an ellipse crossing the horizon: sphere approximation, exact clipping */
        for (i = 0; i < reps; ++i) { hc.x = (mf_real)(1e-7 * (i & 7)); s += (double)mf_ltc_integrate_ellipse(&l, hc, hu, hv, 1); }
        t[6] = now_ns();
        for (i = 0; i < reps; ++i) { hc.x = (mf_real)(1e-7 * (i & 7)); s += (double)mf_ltc_integrate_ellipse_clipped(&l, hc, hu, hv, 1); }
        t[7] = now_ns();
        for (k = 0; k < 7; ++k)
            if ((t[k + 1] - t[k]) / reps < best[k]) best[k] = (t[k + 1] - t[k]) / reps;
    }
    printf("bench ltc_disk %.2f ratio=%.3f plain_32gon=%.2f\n", best[0], best[0] / best[1], best[1]);
    printf("bench ltc_line %.2f ratio=%.3f plain_ribbon_quad=%.2f\n", best[2], best[2] / best[3], best[3]);
    printf("bench ltc_tube %.2f\n", best[4]);
    printf("bench ltc_ellipse_crossing_horizon %.2f exact_clipping=%.2f\n", best[5], best[6]);
    g_sink += s;
}

int main(int argc, char **argv)
{
    struct bench_kind ks[5];
    int i;
    if (argc > 1 && !strcmp(argv[1], "sections")) {
        for (i = 0; i < CORE_SECTIONS; ++i) printf("%s\n", core_sections[i]);
        return 0;
    }
    for (i = 0; i < N; ++i) {
        g_wo[i] = rnd_dir(MF_R(1.5));
        g_wi[i] = rnd_dir(MF_R(1.5));
        g_wm[i] = mf_normalize(mf_add(g_wo[i], g_wi[i]));
        g_wt[i] = i % 2 ? g_wi[i] : mf_vec3_make(g_wi[i].x, g_wi[i].y, -g_wi[i].z);   /* half transmitted */
        g_u1[i] = rnd();
        g_u2[i] = rnd();
    }
    ks[0].name = "beckmann"; ks[0].d = mf_beckmann(MF_R(0.3), MF_R(0.2));
    ks[1].name = "ggx"; ks[1].d = mf_ggx(MF_R(0.3), MF_R(0.2));
    ks[2].name = "gtr1.5"; ks[2].d = gtr_tab(MF_R(0.3), MF_R(1.5));
    ks[3].name = "gtr3"; ks[3].d = mf_gtr(MF_R(0.3), MF_R(3.0));
    ks[4].name = "student_t3"; ks[4].d = mf_student_t(MF_R(0.3), MF_R(0.2), MF_R(3.0));
    printf("# microfacet.h %d.%d.%d bench: compiler %s, flags %s, mf_real %s, %d inputs, best of %d\n",
           MF_VERSION_MAJOR, MF_VERSION_MINOR, MF_VERSION_PATCH,
#if defined(__clang__)
           "clang " __clang_version__,
#elif defined(__GNUC__)
           "gcc " __VERSION__,
#else
           "unknown",
#endif
#ifdef MF_BENCH_FLAGS
           MF_BENCH_FLAGS,
#else
           "(see Makefile: -O2)",
#endif
           sizeof(mf_real) == sizeof(double) ? "double" : "float", N, REPS);
    if (argc > 1 && !strcmp(argv[1], "gtr_student")) {   /* one section only */
        bench_gtr_student();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "beckmann_vndf")) {   /* one section only */
        bench_beckmann_vndf();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "ltc_ngon")) {   /* n-gons only */
        bench_ltc_ngons();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "ltc")) {
        bench_ltc();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "ibm")) {
        bench_ibm();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "record")) {
        bench_record();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "lobes")) {
        bench_lobes();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "sheen")) {
        bench_sheen();
        return 0;
    }
    if (argc > 1 && !strcmp(argv[1], "fresnel_avg")) {
        bench_fresnel_avg();
        return 0;
    }
    if (argc > 1 && !strncmp(argv[1], "core:", 5)) {   /* one core section */
        int sec = 0;
        for (i = 0; i < CORE_SECTIONS; ++i)
            if (!strcmp(argv[1] + 5, core_sections[i])) sec = 1 << i;
        if (!sec) {
            fprintf(stderr, "bench: unknown section %s (bench sections lists them)\n", argv[1] + 5);
            return 2;
        }
        bench_core(ks, sec);
        return g_sink == g_sink ? 0 : 1;
    }
    bench_core(ks, argc > 1 && !strcmp(argv[1], "ggx") ? 1 : CORE_ALL);
    if (argc > 1 && (!strcmp(argv[1], "core") || !strcmp(argv[1], "ggx"))) return g_sink == g_sink ? 0 : 1;
    bench_record();
    bench_beckmann_vndf();
    bench_tabulated();
    bench_ibm();
    bench_microsurface();
    bench_lobes();
    bench_sheen();
    bench_fresnel_avg();
    return g_sink == g_sink ? 0 : 1;
}

/* the analytic kinds, the generic API against plain code, transformed
 * against plain, LEADR and LTC: the hot paths (tools/bench_inline.sh runs
 * this part at -O2, -O3 -march=native and in a large translation unit) */
static void bench_core(const struct bench_kind *ks, int sections)
{
    int k;
    if (sections & 1) {   /* ggx: the generic API against plain code, materials */
        const mf_ndf *g = &ks[1].d;
        double base, ours, inl, pd, od, pg, og;
        run_pair(b_heitz2018, b_vndf, g, &base, &ours);
        run_pair(b_heitz2018, b_ggx_inline, g, &base, &inl);
        run_pair(b_plain_D, b_D, g, &pd, &od);
        run_pair(b_plain_G2, b_G2, g, &pg, &og);
        printf("bench ggx_vndf_heitz2018_baseline %.2f\n", base);
        printf("bench ggx_sample_visible_generic %.2f ratio=%.3f\n", ours, ours / base);
        printf("bench ggx_sample_visible_inline %.2f ratio=%.3f\n", inl, inl / base);
        printf("bench ggx_D_plain_baseline %.2f\n", pd);
        printf("bench ggx_D_generic %.2f ratio=%.3f\n", od, od / pd);
        printf("bench ggx_G2_plain_baseline %.2f\n", pg);
        printf("bench ggx_G2_generic %.2f ratio=%.3f\n", og, og / pg);
        run_pair(b_plain_G2_facing, b_G2, g, &pg, &og);
        printf("bench ggx_G2_plain_facing_baseline %.2f\n", pg);
        printf("bench ggx_G2_generic_vs_facing %.2f ratio=%.3f\n", og, og / pg);
        run_pair(b_vndf_pdf, b_bounded_pdf, g, &base, &ours);
        printf("bench ggx_vndf_sample_pdf_baseline %.2f\n", base);
        printf("bench ggx_bounded_vndf_sample_pdf %.2f ratio=%.3f\n", ours, ours / base);
        run_pair(b_walter_plain, b_dielectric, g, &base, &ours);
        printf("bench ggx_dielectric_walter_plain_baseline %.2f\n", base);
        printf("bench ggx_dielectric_bsdf %.2f ratio=%.3f\n", ours, ours / base);
        run_pair(b_walter_plain, b_dielectric_pdf, g, &base, &ours);
        printf("bench ggx_dielectric_pdf %.2f ratio_to_walter_plain_eval=%.3f\n", ours, ours / base);
        run_pair(b_walter_plain, b_dielectric_sample, g, &base, &ours);
        printf("bench ggx_dielectric_sample_and_weight %.2f ratio_to_walter_plain_eval=%.3f\n", ours, ours / base);
        run_pair(b_brdf, b_brdf_ms, g, &base, &ours);
        printf("bench ggx_brdf_single_scattering_baseline %.2f\n", base);
        printf("bench ggx_brdf_ms_eval %.2f ratio=%.3f\n", ours, ours / base);
        run_pair(b_brdf, b_ms_pdf, g, &base, &ours);
        printf("bench ggx_brdf_ms_pdf %.2f ratio_to_brdf_eval=%.3f\n", ours, ours / base);
        run_pair(b_brdf_sample, b_ms_sample, g, &base, &ours);
        printf("bench ggx_brdf_sample_and_weight_baseline %.2f\n", base);
        printf("bench ggx_brdf_ms_sample_pdf_weight %.2f ratio=%.3f\n", ours, ours / base);
        {
            int q;
            for (q = 0; q < 64 * 64; ++q) g_plain_tab[q] = (float)(q % 97) / 97.0f;
        }
        run_pair(b_plain_lookup, b_albedo, g, &base, &ours);
        printf("bench plain_bilinear_lookup_baseline %.2f\n", base);
        printf("bench ggx_albedo_lookup %.2f ratio=%.3f\n", ours, ours / base);
        if (mf_dielectric_ms_table_build(&g_dms, g, MF_R(1.5), 32, 2) == MF_SUCCESS) {
            run_pair(b_dielectric, b_dielectric_ms, g, &base, &ours);
            printf("bench ggx_dielectric_bsdf_single_baseline %.2f\n", base);
            printf("bench ggx_dielectric_bsdf_ms %.2f ratio=%.3f\n", ours, ours / base);
            mf_dielectric_ms_table_release(&g_dms);
        }
        run_pair(b_dielectric, b_dielectric_bsdf_ms, g, &base, &ours);
        printf("bench ggx_dielectric_bsdf_ms_builtin %.2f ratio_to_single=%.3f\n", ours, ours / base);
        run_pair(b_dielectric_sample, b_dielectric_ms_sample, g, &base, &ours);
        printf("bench ggx_dielectric_sample_baseline %.2f\n", base);
        printf("bench ggx_dielectric_bsdf_ms_sample_builtin %.2f ratio=%.3f\n", ours, ours / base);
        run_pair(b_plain_lookup, b_dielectric_albedo, g, &base, &ours);
        printf("bench ggx_dielectric_albedo_lookup %.2f ratio_to_plain_bilinear=%.3f\n", ours, ours / base);
    }
    for (k = 0; k < 5 && (sections & 2); ++k) {   /* kinds */
        const mf_ndf *d = &ks[k].d;
        double vndf = run(b_vndf, d), base = run(b_heitz2018, &ks[1].d);
        printf("bench %s_D %.2f\n", ks[k].name, run(b_D, d));
        printf("bench %s_lambda %.2f\n", ks[k].name, run(b_lambda, d));
        printf("bench %s_G2 %.2f\n", ks[k].name, run(b_G2, d));
        printf("bench %s_sample_D %.2f\n", ks[k].name, run(b_sample_D, d));
        printf("bench %s_sample_visible %.2f vs_ggx_heitz2018=%.2f\n", ks[k].name, vndf, vndf / base);
        printf("bench %s_brdf_eval %.2f\n", ks[k].name, run(b_brdf, d));
        printf("bench %s_brdf_pdf %.2f\n", ks[k].name, run(b_brdf_pdf, d));
        printf("bench %s_brdf_sample_and_weight %.2f\n", ks[k].name, run(b_brdf_sample, d));
    }
    if (sections & 2) bench_gtr_student();
    /* transformed: linearly transformed microsurfaces against plain, in pairs */
    for (k = 0; k < 5 && (sections & 4); ++k) {
        const mf_ndf *d = &ks[k].d;
        mf_ndf t = mf_transformed(*d, mf_mat2_make(MF_R(1.5), MF_R(0.3), MF_R(-0.2), MF_R(0.8)));
        mf_ndf id = mf_transformed(*d, mf_mat2_make(MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0)));
        bench_fn fns[4];
        const char *names[4];
        int f;
        fns[0] = b_D; names[0] = "D";
        fns[1] = b_G2; names[1] = "G2";
        fns[2] = b_sample_D; names[2] = "sample_D";
        fns[3] = b_vndf; names[3] = "sample_visible";
        for (f = 0; f < 4; ++f) {
            double tp, tt, ti;
            if (k >= 2 && f == 3) continue;   /* numerical samplers: ratio is noise-free enough below */
            run_pair(fns[f], fns[f], d, &tp, &tt);
            run_pair(fns[f], fns[f], &t, &tp, &tt);
            {
                double a, b2;
                run_pair(fns[f], fns[f], d, &a, &b2);
                tp = a < b2 ? a : b2;
            }
            run_pair(fns[f], fns[f], &id, &ti, &ti);
            printf("bench %s_transformed_%s %.2f ratio=%.3f identity_ratio=%.3f\n", ks[k].name, names[f], tt, tt / tp, ti / tp);
        }
    }
    if (sections & 4) printf("bench fresnel_conductor %.2f\n", run(b_fresnel, &ks[0].d));
    /* leadr: point-light specular, 5x5 diffuse and environment grids, pyramid build */
    if (sections & 8) {
        mf_leadr a = mf_leadr_with_roughness(mf_leadr_from_slope(MF_R(0.1), MF_R(-0.05)), MF_R(0.3), MF_R(0.2));
        mf_real sh[9] = { 1, 0.2f, 0.5f, 0.1f, 0, 0, 0.05f, 0, 0 };
        double t0, t1, s = 0.0, ts = 1e30, td = 1e30, te = 1e30, th = 1e30;
        int it, q;
        const int NB = 2048;
        mf_real *h = (mf_real *)malloc(sizeof(mf_real) * NB * NB);
        mf_leadr_map map;
        for (it = 0; it < 5; ++it) {
            t0 = now_ns();
            for (q = 0; q < N; ++q) s += (double)mf_leadr_specular(a, g_wo[q], g_wi[q]);
            t1 = now_ns(); if ((t1 - t0) / N < ts) ts = (t1 - t0) / N;
            for (q = 0; q < N; ++q) s += (double)mf_leadr_diffuse(a, g_wo[q], g_wi[q], 5);
            t0 = now_ns(); if ((t0 - t1) / N < td) td = (t0 - t1) / N;
            for (q = 0; q < N; ++q) s += (double)mf_leadr_specular_env(a, g_wo[q], 5, 1, NULL, NULL).x;
            t1 = now_ns(); if ((t1 - t0) / N < te) te = (t1 - t0) / N;
            for (q = 0; q < N; ++q) s += (double)mf_leadr_diffuse_sh9(a, g_wo[q], sh, 5);
            t0 = now_ns(); if ((t0 - t1) / N < th) th = (t0 - t1) / N;
        }
        printf("bench leadr_specular_point %.2f\n", ts);
        printf("bench leadr_diffuse_5x5 %.2f\n", td);
        printf("bench leadr_specular_env_5x5 %.2f\n", te);
        printf("bench leadr_diffuse_sh9_5x5 %.2f\n", th);
        if (h) {
            for (q = 0; q < NB * NB; ++q) h[q] = (mf_real)(0.001 * sin(0.01 * q) * cos(0.0003 * q));
            t0 = now_ns();
            if (mf_leadr_map_from_heights(&map, h, NB, NB, MF_R(0.05), MF_R(0.05)) == MF_SUCCESS) {
                t1 = now_ns();
                printf("bench leadr_pyramid_build_2048 %.0f ms=%.1f MB=%.1f\n", t1 - t0, (t1 - t0) * 1e-6,
                       (double)mf_leadr_map_memory_bytes(&map) / (1024.0 * 1024.0));
                mf_leadr_map_release(&map);
            }
            free(h);
        }
        g_sink += s;
    }
    if (sections & 16) bench_ltc();   /* ltc: lookup, polygons, fitting */
}

/* ---- the lobes of a whole material (issue 42): each against the simplest
 * peer form of its role (ratio = ours / that form) ---- */
static mf_real plain_lambert(mf_vec3 wo, mf_vec3 wi, mf_real rho)
{
    return wo.z > MF_R(0.0) && wi.z > MF_R(0.0) ? rho * MF_INV_PI : MF_R(0.0);
}
static mf_real plain_schlick(mf_real c, mf_real f0)
{
    mf_real m = MF_R(1.0) - c, m2 = m * m;
    return f0 + (MF_R(1.0) - f0) * m2 * m2 * m;
}
static double b_lambert(const mf_ndf *d) { (void)d; LOOP(plain_lambert(g_wo[i], g_wi[i], g_u1[i])); }
static double b_eon(const mf_ndf *d) { (void)d; LOOP(mf_eon_brdf(g_wo[i], g_wi[i], g_u1[i], g_u2[i])); }
static double b_cos_sample(const mf_ndf *d)
{
    (void)d;
    LOOP(mf__sample_cosine(g_u1[i], g_u2[i]).z * g_u1[i]);   /* weight rho: the Lambert record */
}
static double b_eon_sample(const mf_ndf *d) { (void)d; LOOP(mf_eon_sample(g_wo[i], g_u1[i], MF_R(0.6), g_u1[i], g_u2[i]).weight); }
static double b_cos_pdf(const mf_ndf *d) { (void)d; LOOP(g_wi[i].z > MF_R(0.0) ? g_wi[i].z * MF_INV_PI : MF_R(0.0)); }
static double b_eon_pdf(const mf_ndf *d) { (void)d; LOOP(mf_eon_pdf(g_wo[i], g_wi[i], g_u1[i])); }
static double b_eon_albedo_fast(const mf_ndf *d) { (void)d; LOOP(mf_eon_albedo_fast(g_wo[i].z, g_u1[i], g_u2[i])); }
static double b_eon_albedo(const mf_ndf *d) { (void)d; LOOP(mf_eon_albedo(g_wo[i].z, g_u1[i], g_u2[i])); }
static double b_schlick(const mf_ndf *d) { (void)d; LOOP(plain_schlick(g_wo[i].z, g_u1[i])); }
static double b_f82(const mf_ndf *d) { (void)d; LOOP(mf_fresnel_f82(g_wo[i].z, g_u1[i], g_u2[i])); }
static double b_f82_avg(const mf_ndf *d) { (void)d; LOOP(mf_fresnel_f82_average(g_u1[i], MF_R(0.25) * g_u2[i])); }
static double b_tf_spectral3(const mf_ndf *d)
{
    /* the naive RGB: the exact reflectance at three wavelengths */
    static const mf_real lam[3] = { MF_R(647.4), MF_R(544.0), MF_R(442.6) };
    (void)d;
    LOOP(mf_fresnel_thin_film(g_wo[i].z, MF_R(1.0), MF_R(1.33), MF_R(800.0) * g_u1[i], MF_R(1.0), MF_R(0.0), lam[0])
         + mf_fresnel_thin_film(g_wo[i].z, MF_R(1.0), MF_R(1.33), MF_R(800.0) * g_u1[i], MF_R(1.0), MF_R(0.0), lam[1])
         + mf_fresnel_thin_film(g_wo[i].z, MF_R(1.0), MF_R(1.33), MF_R(800.0) * g_u1[i], MF_R(1.0), MF_R(0.0), lam[2]));
}
static mf_real tf_rgb_sum(mf_real c, mf_real d, const mf_real *eb, const mf_real *kb)
{
    mf_real rgb[3];
    mf_fresnel_thin_film_rgb(c, MF_R(1.0), MF_R(1.33), d, eb, kb, rgb);
    return rgb[0] + rgb[1] + rgb[2];
}
static double b_tf_rgb(const mf_ndf *d)
{
    static const mf_real eb[3] = { MF_R(1.0), MF_R(1.0), MF_R(1.0) }, kb[3] = { MF_R(0.0), MF_R(0.0), MF_R(0.0) };
    (void)d;
    LOOP(tf_rgb_sum(g_wo[i].z, MF_R(800.0) * g_u1[i], eb, kb));
}
static double b_tf_rgb_metal(const mf_ndf *d)
{
    static const mf_real eb[3] = { MF_R(0.18), MF_R(0.42), MF_R(1.37) }, kb[3] = { MF_R(3.4), MF_R(2.35), MF_R(1.77) };
    (void)d;
    LOOP(tf_rgb_sum(g_wo[i].z, MF_R(800.0) * g_u1[i], eb, kb));
}
static double b_charlie_fit(const mf_ndf *d) { (void)d; LOOP(mf_charlie_lambda_fit(MF_R(0.05) + MF_R(0.95) * g_u1[i], g_wo[i])); }
static double b_charlie_exact(const mf_ndf *d) { (void)d; LOOP(mf_charlie_lambda(MF_R(0.05) + MF_R(0.95) * g_u1[i], g_wo[i])); }
static double b_charlie_D(const mf_ndf *d) { (void)d; LOOP(mf_charlie_D(MF_R(0.05) + MF_R(0.95) * g_u1[i], g_wm[i])); }
static double b_charlie_fit03(const mf_ndf *d) { (void)d; LOOP(mf_charlie_lambda_fit(MF_R(0.3), g_wo[i])); }
static void bench_lobes(void)
{
    double tb, to;
    mf_ndf ch = mf_charlie(MF_R(0.3)), gg = mf_ggx(MF_R(0.3), MF_R(0.3));
    run_pair(b_lambert, b_eon, NULL, &tb, &to);
    printf("bench eon_brdf %.2f lambert=%.2f ratio=%.2f\n", to, tb, to / tb);
    run_pair(b_cos_sample, b_eon_sample, NULL, &tb, &to);
    printf("bench eon_sample %.2f cosine=%.2f ratio=%.2f\n", to, tb, to / tb);
    run_pair(b_cos_pdf, b_eon_pdf, NULL, &tb, &to);
    printf("bench eon_pdf %.2f cosine=%.2f ratio=%.2f\n", to, tb, to / tb);
    run_pair(b_eon_albedo_fast, b_eon_albedo, NULL, &tb, &to);
    printf("bench eon_albedo %.2f fast=%.2f ratio=%.2f\n", to, tb, to / tb);
    run_pair(b_schlick, b_f82, NULL, &tb, &to);
    printf("bench fresnel_f82 %.2f schlick=%.2f ratio=%.2f\n", to, tb, to / tb);
    printf("bench fresnel_f82_average %.2f\n", run(b_f82_avg, NULL));
    run_pair(b_tf_spectral3, b_tf_rgb, NULL, &tb, &to);
    printf("bench thin_film_rgb_soap %.1f three_wavelengths=%.1f ratio=%.2f\n", to, tb, to / tb);
    printf("bench thin_film_rgb_oxide_on_gold %.1f\n", run(b_tf_rgb_metal, NULL));
    run_pair(b_charlie_fit, b_charlie_exact, NULL, &tb, &to);
    printf("bench charlie_lambda_exact %.1f published_fit=%.1f ratio=%.2f\n", to, tb, to / tb);
    printf("bench charlie_D %.2f\n", run(b_charlie_D, NULL));
    /* the kind through the generic front ends, alpha 0.3 */
    run_pair2(b_charlie_fit03, &ch, b_lambda, &ch, &tb, &to);
    printf("bench charlie_kind_lambda %.1f published_fit=%.1f ratio=%.2f\n", to, tb, to / tb);
    run_pair2(b_vndf, &gg, b_vndf, &ch, &tb, &to);
    printf("bench charlie_kind_sample_visible %.1f ggx=%.1f ratio=%.2f\n", to, tb, to / tb);
}

/* volumetric sheen (table lookup + LTC) against Lambert eval and cosine sampling */
static double b_sheen(const mf_ndf *d) { (void)d; LOOP(mf_sheen_brdf(g_wo[i], g_wi[i], g_u1[i])); }
static double b_sheen_sample(const mf_ndf *d) { (void)d; LOOP(mf_sheen_sample(g_wo[i], g_u1[i], g_u1[i], g_u2[i]).weight); }
static double b_sheen_pdf(const mf_ndf *d) { (void)d; LOOP(mf_sheen_pdf(g_wo[i], g_wi[i], g_u1[i])); }
static void bench_sheen(void)
{
    double tb, to;
    run_pair(b_lambert, b_sheen, NULL, &tb, &to);
    printf("bench sheen_brdf %.2f lambert=%.2f ratio=%.2f\n", to, tb, to / tb);
    run_pair(b_cos_sample, b_sheen_sample, NULL, &tb, &to);
    printf("bench sheen_sample %.2f cosine=%.2f ratio=%.2f\n", to, tb, to / tb);
    run_pair(b_cos_pdf, b_sheen_pdf, NULL, &tb, &to);
    printf("bench sheen_pdf %.2f cosine=%.2f ratio=%.2f\n", to, tb, to / tb);
}

/* Fresnel averages (per material: 128 Fresnel evaluations each) against one
 * mf_fresnel_conductor evaluation; the albedo of kinds without a built-in
 * table (a quadrature per call) and the per-sample ms lobe. */
static void bench_fresnel_avg(void)
{
    double t0, t1, s = 0.0, base;
    int i, n = 20000;
    t0 = now_ns();
    for (i = 0; i < n; ++i) s += (double)mf_fresnel_conductor(MF_R(0.1) + MF_R(0.9) * (mf_real)(i & 255) / MF_R(255.0), MF_R(0.2), MF_R(3.9));
    t1 = now_ns();
    base = (t1 - t0) / n;
    t0 = now_ns();
    for (i = 0; i < n; ++i) s += (double)mf_fresnel_conductor_average(MF_R(0.2) + MF_R(1e-4) * (mf_real)(i & 255), MF_R(3.9));
    t1 = now_ns();
    printf("bench fresnel_conductor_average %.1f fresnel_conductor=%.2f ratio=%.0f\n", (t1 - t0) / n, base, (t1 - t0) / n / base);
    t0 = now_ns();
    for (i = 0; i < n; ++i) s += (double)mf_fresnel_dielectric_average(MF_R(1.5) + MF_R(1e-4) * (mf_real)(i & 255));
    t1 = now_ns();
    printf("bench fresnel_dielectric_average %.1f fresnel_conductor=%.2f ratio=%.0f\n", (t1 - t0) / n, base, (t1 - t0) / n / base);
    t0 = now_ns();
    for (i = 0; i < n; ++i) s += (double)mf_fresnel_f82_average(MF_R(0.9), MF_R(0.7) + MF_R(1e-4) * (mf_real)(i & 255));
    t1 = now_ns();
    printf("bench fresnel_f82_average %.1f fresnel_conductor=%.2f ratio=%.0f\n", (t1 - t0) / n, base, (t1 - t0) / n / base);
    {
        mf_ndf r = mf_rotated(mf_ggx(MF_R(0.2), MF_R(0.4)), MF_R(0.7)), g = mf_gtr(MF_R(0.2), MF_R(1.5));
        mf_vec3 wo = mf_vec3_make(MF_R(0.6), MF_R(0.0), MF_R(0.8));
        t0 = now_ns(); s += (double)mf_albedo(&r, wo); t1 = now_ns();
        printf("bench albedo_rotated_ggx_us %.0f\n", (t1 - t0) * 1e-3);
        t0 = now_ns(); s += (double)mf_albedo(&g, wo); t1 = now_ns();
        printf("bench albedo_gtr_us %.0f\n", (t1 - t0) * 1e-3);
        t0 = now_ns(); s += (double)mf_albedo_average(&r); t1 = now_ns();
        printf("bench albedo_average_rotated_ggx_us %.0f\n", (t1 - t0) * 1e-3);
        t0 = now_ns(); s += (double)mf_brdf_ms_sample(&g, wo, MF_R(0.3), MF_R(0.6)).weight; t1 = now_ns();
        printf("bench brdf_ms_sample_gtr_us %.0f\n", (t1 - t0) * 1e-3);
    }
    g_sink += s;
}
