/* Fits the volumetric sheen LTC table (Zeltner, Burley & Chiang 2022,
 * "Practical Multiple-Scattering Sheen Using Linearly Transformed Cosines")
 * from our own Monte Carlo reference of their layer, and prints the built-in
 * table module (`make sheen-table`):
 *   cc -O2 -DMF_USE_DOUBLE -I. tools/sheen_fit.c -o sheen_fit -lm
 *   ./sheen_fit > src/22_sheen_table.h
 *   ./sheen_fit --compare ltc_table_sheen_volume.cpp > /dev/null
 *       also compares with the published table (tizian/ltc-sheen,
 *       fitting/python/data/ltc_table_sheen_volume.cpp, read at run time,
 *       never stored here) and prints the figures on stderr.
 *   ./sheen_fit --truncate --compare ltc_table_sheen_volume.cpp
 *       the same for the authors' truncated reference (below); prints no module.
 *
 * The layer (the talk; the authors' code for the numbers): a slab of unit
 * thickness and unit density over a black base, single-scattering albedo 1,
 * filled with fibre-like SGGX microflakes standing along the normal,
 * S = diag(1, 1, s^2) with s = alpha^2 (their cross-section sigma = alpha^2,
 * Heitz et al. 2015 Sec. 3 "fiber-like": sigma(w) = sqrt(w^T S w) is the
 * projected area, so the extinction along w is sigma(w)), the specular
 * microflake phase function p(a -> w) = D(h) / (4 sigma(a)), h = (a + w)/|.|,
 * D(m) = 1 / (pi sqrt|S| (m^T S^-1 m)^2) (Heitz 2015 Eq. 9). Multiple
 * scattering without a cap on the order (a walk stops when it leaves).
 * --truncate reproduces the authors' reference instead (at most 16 orders,
 * a walk still inside after them counted as reflected when it heads up):
 * the published R follow it; they differ from the complete layer only at
 * low alpha and grazing views, where light climbs out after many orders.
 *
 * Reference lobe: for each cell (cos theta_o, alpha) W random walks enter at
 * the top along -wo; at every scattering vertex (depth z, incoming a) next
 * event estimation adds p(a -> w) exp(-sigma(w) z / w.z) to each of 32 x 32
 * directions w (theta midpoints in [0, pi/2], phi midpoints in [0, pi]: the
 * lobe is symmetric in phi), an estimate of f(wo, w) w.z. The walks sample
 * free paths with sigma(d) and the next direction by reflection on a visible
 * microflake normal (sampled as below). R, the albedo, is the fraction of
 * walks that leave through the top (W + W_R walks), an unbiased estimate
 * independent of the direction grid; the grid integral of the NEE lobe is
 * printed next to it as a check of sampler against phase function.
 *
 * Fit: the published restricted form M^-1 = [A 0 B; 0 A 0; 0 0 1] (D_LTC
 * = A^2 v.z / (pi |v|^4), v = M^-1 w), A and B by Nelder-Mead on the
 * published error measure, the sum over the 32 x 32 directions of
 * |R D_LTC(w) - ref(w)|^3, roughest first with each fit starting from the
 * previous one (as the authors); where R < 1e-3 the lobe estimate is mostly
 * noise and A, B continue from the rougher row. mf_ltc_fit is not used: it fits the general
 * 3-parameter form in a rotated frame from a BRDF callback, while the table
 * blends A, B, R of the restricted form. Table: 32 x 32 nodes at the
 * published points, cos theta_o = max(0.01, j / 31), alpha = max(0.01, i / 31). */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "print_float.h"

#define NT 32          /* table nodes per axis */
#define GT 32          /* direction grid: theta */
#define GP 32          /* direction grid: phi in [0, pi] */
#define W_NEE 6000     /* walks with next event estimation per cell */
#define W_R 200000     /* further walks for the albedo per cell */
#define MAX_ORDER 100000
#define R_FIT_MIN 1e-3  /* below, the lobe estimate is noise: A, B continue from the rougher row */
#define PI 3.14159265358979323846
#ifndef ROW_MIN
#define ROW_MIN 0   /* a quicker partial run for checks: -DROW_MIN=28 */
#endif

/* ---- random numbers: splitmix64, doubles in [0, 1) ---- */
static unsigned long long rng_state;
static double rnd(void)
{
    unsigned long long z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* ---- the fibre SGGX medium, S = diag(1, 1, s^2) ---- */
static double sgm(double s, double x, double y, double z) { return sqrt(x * x + y * y + s * s * z * z); }

/* A visible normal for direction a: the microflakes are the normals of the
 * ellipsoid {x : x^T S x <= 1} = S^-1/2 (unit ball); lines along a map
 * under S^1/2 to lines along a' = S^1/2 a, so a point uniform in projected
 * area on the unit sphere's half facing a' maps to one on the ellipsoid
 * (the map between the line families is linear), whose normal is S x, i.e.
 * normalize(S^1/2 u). */
static void sample_visible(double s, const double *a, double u1, double u2, double *m)
{
    double w[3], t1[3], t2[3], l, r, ph, p1, p2, p3, u[3];
    w[0] = a[0]; w[1] = a[1]; w[2] = s * a[2];
    l = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    w[0] /= l; w[1] /= l; w[2] /= l;
    /* a frame around w (Duff et al. 2017) */
    {
        double sg = w[2] >= 0.0 ? 1.0 : -1.0, aa = -1.0 / (sg + w[2]), b = w[0] * w[1] * aa;
        t1[0] = 1.0 + sg * w[0] * w[0] * aa; t1[1] = sg * b; t1[2] = -sg * w[0];
        t2[0] = b; t2[1] = sg + w[1] * w[1] * aa; t2[2] = -w[1];
    }
    r = sqrt(u1); ph = 2.0 * PI * u2;
    p1 = r * cos(ph); p2 = r * sin(ph); p3 = sqrt(fmax(0.0, 1.0 - p1 * p1 - p2 * p2));
    u[0] = p1 * t1[0] + p2 * t2[0] + p3 * w[0];
    u[1] = p1 * t1[1] + p2 * t2[1] + p3 * w[1];
    u[2] = p1 * t1[2] + p2 * t2[2] + p3 * w[2];
    m[0] = u[0]; m[1] = u[1]; m[2] = s * u[2];
    l = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    m[0] /= l; m[1] /= l; m[2] /= l;
}

/* the direction grid */
static double gw[GT][GP][3], gtau[GT], gsolid[GT];

static void grid_init(double s)
{
    int k, l;
    for (k = 0; k < GT; ++k) {
        double th = (k + 0.5) / GT * 0.5 * PI;
        for (l = 0; l < GP; ++l) {
            double ph = (l + 0.5) / GP * PI;
            gw[k][l][0] = sin(th) * cos(ph); gw[k][l][1] = sin(th) * sin(ph); gw[k][l][2] = cos(th);
        }
        gtau[k] = sgm(s, sin(th), 0.0, cos(th)) / cos(th);
        /* solid angle of one cell, both phi halves: 2 sin(th) dth dphi */
        gsolid[k] = 2.0 * sin(th) * (0.5 * PI / GT) * (PI / GP);
    }
}

/* One walk from wo; with ref, next event estimation into ref. Returns 1 when
 * it leaves through the top. */
static int g_truncate = 0;   /* --truncate: the published reference's 16 orders */
static int walk(double s, double mu, double (*ref)[GP])
{
    double d[3], z = 0.0, inv_s = 1.0 / s;
    int order;
    d[0] = -sqrt(fmax(0.0, 1.0 - mu * mu)); d[1] = 0.0; d[2] = -mu;
    for (order = 0; order < (g_truncate ? 16 : MAX_ORDER); ++order) {
        double st = sgm(s, d[0], d[1], d[2]), a[3], m[3], c;
        if (!(st > 0.0)) return 0;
        z += -log(1.0 - rnd()) / st * -d[2];
        if (z < 0.0) return 1;
        if (z > 1.0) return 0;
        a[0] = -d[0]; a[1] = -d[1]; a[2] = -d[2];
        if (ref) {
            /* p(a -> w) = D(h) / (4 sigma(a)), D(h) = |v|^4 / (pi s q^2) with
             * v = a + w, q = v^T S^-1 v */
            double k0 = 1.0 / (4.0 * PI * s * st);
            int k, l;
            for (k = 0; k < GT; ++k) {
                double tr = exp(-gtau[k] * z) * k0;
                for (l = 0; l < GP; ++l) {
                    double vx = a[0] + gw[k][l][0], vy = a[1] + gw[k][l][1], vz = (a[2] + gw[k][l][2]) * inv_s;
                    double v2 = vx * vx + vy * vy + (a[2] + gw[k][l][2]) * (a[2] + gw[k][l][2]);
                    double q = vx * vx + vy * vy + vz * vz;
                    if (q > 0.0) ref[k][l] += tr * v2 * v2 / (q * q);
                }
            }
        }
        sample_visible(s, a, rnd(), rnd(), m);
        c = m[0] * a[0] + m[1] * a[1] + m[2] * a[2];
        d[0] = 2.0 * c * m[0] - a[0]; d[1] = 2.0 * c * m[1] - a[1]; d[2] = 2.0 * c * m[2] - a[2];
        c = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        d[0] /= c; d[1] /= c; d[2] /= c;
    }
    return g_truncate ? d[2] > 0.0 : 0;
}

/* ---- the LTC of the restricted form ---- */
static double ltc_d(double A, double B, const double *w)
{
    double vx = A * w[0] + B * w[2], vy = A * w[1], vz = w[2], l2 = vx * vx + vy * vy + vz * vz;
    if (!(vz > 0.0) || !(l2 > 0.0)) return 0.0;
    return A * A * vz / (PI * l2 * l2);
}

static double (*fit_ref)[GP];
static double fit_R;
/* the published measure: sum over the grid of |R D_LTC - ref|^3 */
static double l3_error(double A, double B, double R, double (*ref)[GP])
{
    double e = 0.0;
    int k, l;
    for (k = 0; k < GT; ++k)
        for (l = 0; l < GP; ++l) {
            double x = fabs(R * ltc_d(A, B, gw[k][l]) - ref[k][l]);
            e += x * x * x;
        }
    return e;
}
static double objective(const double *p) { return p[0] > 0.0 ? l3_error(p[0], p[1], fit_R, fit_ref) : 1e300; }

/* Nelder-Mead in 2 dimensions (standard coefficients), from x */
static void nelder_mead(double *x)
{
    double s[3][2], f[3], c[2], xr[2], xe[2], xc[2], fr;
    int i, j, it, lo, hi, nh;
    for (i = 0; i < 3; ++i) {
        s[i][0] = x[0]; s[i][1] = x[1];
        if (i == 1) s[i][0] += 0.1 * fmax(fabs(x[0]), 0.1);
        if (i == 2) s[i][1] += 0.05;
        f[i] = objective(s[i]);
    }
    for (it = 0; it < 2000; ++it) {
        lo = hi = 0;
        for (i = 1; i < 3; ++i) { if (f[i] < f[lo]) lo = i; if (f[i] > f[hi]) hi = i; }
        nh = lo;
        for (i = 0; i < 3; ++i) if (i != hi && f[i] > f[nh]) nh = i;
        if (fabs(f[hi] - f[lo]) <= 1e-10 * (fabs(f[lo]) + 1e-300) && it > 10) break;
        for (j = 0; j < 2; ++j) { c[j] = 0.5 * (s[0][j] + s[1][j] + s[2][j] - s[hi][j]); xr[j] = 2.0 * c[j] - s[hi][j]; }
        fr = objective(xr);
        if (fr < f[lo]) {
            double fe;
            for (j = 0; j < 2; ++j) xe[j] = c[j] + 2.0 * (xr[j] - c[j]);
            fe = objective(xe);
            if (fe < fr) { s[hi][0] = xe[0]; s[hi][1] = xe[1]; f[hi] = fe; }
            else { s[hi][0] = xr[0]; s[hi][1] = xr[1]; f[hi] = fr; }
        } else if (fr < f[nh]) {
            s[hi][0] = xr[0]; s[hi][1] = xr[1]; f[hi] = fr;
        } else {
            double fc;
            for (j = 0; j < 2; ++j) xc[j] = c[j] + 0.5 * (s[hi][j] - c[j]);
            fc = objective(xc);
            if (fc < f[hi]) { s[hi][0] = xc[0]; s[hi][1] = xc[1]; f[hi] = fc; }
            else
                for (i = 0; i < 3; ++i) if (i != lo) {
                    for (j = 0; j < 2; ++j) s[i][j] = s[lo][j] + 0.5 * (s[i][j] - s[lo][j]);
                    f[i] = objective(s[i]);
                }
        }
    }
    lo = 0;
    for (i = 1; i < 3; ++i) if (f[i] < f[lo]) lo = i;
    x[0] = s[lo][0]; x[1] = s[lo][1];
}

/* relative L1 distance of two normalized lobes, int |a - b| dw over the
 * hemisphere by the grid (in [0, 2]); ref (not null) stands for b scaled by 1/R */
static double l1_shape(double A1, double B1, double A2, double B2, double (*ref)[GP], double R)
{
    double e = 0.0;
    int k, l;
    for (k = 0; k < GT; ++k)
        for (l = 0; l < GP; ++l) {
            double b = ref ? ref[k][l] / R : ltc_d(A2, B2, gw[k][l]);
            e += fabs(ltc_d(A1, B1, gw[k][l]) - b) * gsolid[k];
        }
    return e;
}

/* reads the published table: 32 x 32 triples (A, B, R), alpha rows, mu
 * columns, as the numbers after each "Vector3f(" */
static int read_published(const char *path, double (*pub)[NT][3])
{
    FILE *f = fopen(path, "r");
    char buf[1 << 16];
    int n = 0;
    if (!f) return 0;
    while (fgets(buf, sizeof buf, f)) {
        char *p = buf;
        while ((p = strstr(p, "Vector3f(")) != 0) {
            double a, b, c;
            p += 9;
            if (sscanf(p, "%lf , %lf , %lf", &a, &b, &c) == 3 && n < NT * NT) {
                pub[n / NT][n % NT][0] = a; pub[n / NT][n % NT][1] = b; pub[n / NT][n % NT][2] = c;
                ++n;
            }
        }
    }
    fclose(f);
    return n == NT * NT;
}

static double node(int i) { double v = (double)i / (NT - 1); return v > 0.01 ? v : 0.01; }

int main(int argc, char **argv)
{
    static double table[NT][NT][3], pub[NT][NT][3], ref[GT][GP], err_mine[NT][NT], l1_mine[NT][NT], l1_pub[NT][NT], l1_mp[NT][NT], l3_pub[NT][NT];
    static double grid_R[NT][NT];
    const char *cmp = 0;
    int i, j, k, l, have_pub = 0;
    clock_t t0 = clock();
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--truncate")) g_truncate = 1;
        else if (!strcmp(argv[i], "--compare") && i + 1 < argc) cmp = argv[++i];
        else { fprintf(stderr, "usage: %s [--truncate] [--compare ltc_table_sheen_volume.cpp]\n", argv[0]); return 2; }
    }
    if (cmp && !(have_pub = read_published(cmp, pub))) { fprintf(stderr, "cannot read 32 x 32 entries from %s\n", cmp); return 1; }
    for (i = NT - 1; i >= ROW_MIN; --i) {       /* alpha rows, roughest first */
        double alpha = node(i), s = alpha * alpha, x[2];
        grid_init(s);
        for (j = 0; j < NT; ++j) {
            double mu = node(j), R, gR = 0.0;
            long up = 0, w;
            rng_state = 0x5EED0000ULL + (unsigned long long)(i * NT + j) * 0x10001ULL;
            memset(ref, 0, sizeof ref);
            for (w = 0; w < W_NEE; ++w) up += walk(s, mu, ref);
            for (k = 0; k < GT; ++k) for (l = 0; l < GP; ++l) { ref[k][l] /= W_NEE; gR += ref[k][l] * gsolid[k]; }
            for (w = 0; w < W_R; ++w) up += walk(s, mu, 0);
            R = (double)up / (W_NEE + W_R);
            grid_R[i][j] = gR;
            /* start: the neighbour in alpha (same mu), else the cosine */
            if (i < NT - 1 && table[i + 1][j][0] > 0.0) { x[0] = table[i + 1][j][0]; x[1] = table[i + 1][j][1]; }
            else { x[0] = 1.0; x[1] = 0.0; }
            if (R >= R_FIT_MIN) {
                fit_ref = ref; fit_R = R;
                nelder_mead(x);
                nelder_mead(x);   /* restart: Nelder-Mead can stall */
            }
            table[i][j][0] = x[0]; table[i][j][1] = x[1]; table[i][j][2] = R;
            err_mine[i][j] = l3_error(x[0], x[1], R, ref);
            l1_mine[i][j] = R >= R_FIT_MIN ? l1_shape(x[0], x[1], 0, 0, ref, gR) : 0.0;
            if (have_pub) {
                double A = pub[i][j][0], B = pub[i][j][1];
                l3_pub[i][j] = A > 0.0 ? l3_error(A, B, pub[i][j][2], ref) : -1.0;
                l1_pub[i][j] = A > 0.0 && R >= R_FIT_MIN ? l1_shape(A, B, 0, 0, ref, gR) : -1.0;
                l1_mp[i][j] = A > 0.0 ? l1_shape(x[0], x[1], A, B, 0, 0) : -1.0;
            }
        }
        fprintf(stderr, "\ralpha row %d / %d", NT - i, NT);
    }
    fprintf(stderr, "\nsimulated and fitted in %.1f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    /* checks and comparison */
    {
        double dmax = 0.0, dsum = 0.0, dsgn = 0.0;
        int n = 0, ai = 0, aj = 0;
        for (i = 0; i < NT; ++i) for (j = 0; j < NT; ++j)
            if (table[i][j][2] > 0.01) {
                double d = fabs(grid_R[i][j] - table[i][j][2]) / table[i][j][2];
                if (i >= 8 && d > dmax) { dmax = d; ai = i; aj = j; }
                dsum += d; ++n;
                dsgn += (grid_R[i][j] - table[i][j][2]) / table[i][j][2];
            }
        fprintf(stderr, "check: R by escapes vs grid integral of the NEE lobe, alpha >= 0.25 and R > 0.01: max rel diff %.4f (alpha %.3f, mu %.3f), mean over all R > 0.01 %.4f (signed %.4f)\n",
                dmax, node(ai), node(aj), dsum / n, dsgn / n);
    }
    if (have_pub) {
        double rmax = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0, ratio_sum = 0.0;
        int ri = 0, rj = 0, n = 0, nb = 0, worse = 0;
        for (i = 0; i < NT; ++i) for (j = 0; j < NT; ++j) {
            double d = fabs(table[i][j][2] - pub[i][j][2]);
            if (d > rmax) { rmax = d; ri = i; rj = j; }
            if (i >= 8 && table[i][j][2] > 0.01 && l1_pub[i][j] >= 0.0) {
                s1 += l1_mine[i][j]; s2 += l1_pub[i][j]; s3 += l1_mp[i][j];
                if (l1_mine[i][j] > m1) m1 = l1_mine[i][j];
                if (l1_pub[i][j] > m2) m2 = l1_pub[i][j];
                if (l1_mp[i][j] > m3) m3 = l1_mp[i][j];
                if (l3_pub[i][j] > 0.0) { ratio_sum += err_mine[i][j] / l3_pub[i][j]; ++nb; if (err_mine[i][j] > l3_pub[i][j]) ++worse; }
                ++n;
            }
        }
        {
            int nbig = 0;
            double amax = 0.0, mmax = 0.0;
            for (i = 0; i < NT; ++i) for (j = 0; j < NT; ++j)
                if (fabs(table[i][j][2] - pub[i][j][2]) > 1e-2) { ++nbig; amax = fmax(amax, node(i)); mmax = fmax(mmax, node(j)); }
            fprintf(stderr, "published table: R max |ours - published| %.4f (alpha %.3f, mu %.3f); %d cells differ by more than 0.01 "
                            "(all with alpha <= %.3f and mu <= %.3f)\n", rmax, node(ri), node(rj), nbig, amax, mmax);
        }
        fprintf(stderr, "lobe shape over the %d cells with alpha >= 0.25 and R > 0.01, L1 distance of normalized lobes (0..2):\n"
                        "  our LTC vs our reference: mean %.4f max %.4f\n"
                        "  published LTC vs our reference: mean %.4f max %.4f\n"
                        "  our LTC vs published LTC: mean %.4f max %.4f\n"
                        "  published L3 measure on our reference: ours / published mean %.3f, ours worse in %d of %d cells\n",
                n, s1 / n, m1, s2 / n, m2, s3 / n, m3, ratio_sum / nb, worse, nb);
        for (i = 0; i < NT; i += 5) {
            fprintf(stderr, "alpha %.3f:", node(i));
            for (j = 0; j < NT; j += 6)
                fprintf(stderr, " mu %.2f R %.4f/%.4f A %.3f/%.3f B %.3f/%.3f;", node(j), table[i][j][2], pub[i][j][2],
                        table[i][j][0], pub[i][j][0], table[i][j][1], pub[i][j][1]);
            fprintf(stderr, "\n");
        }
    }
    if (g_truncate) return 0;   /* a check, not the shipped table */
    /* the module */
    printf("/* Generated by tools/sheen_fit.c (`make sheen-table`): do not edit. */\n"
           "/* ======================================================================== */\n"
           "/* == 22. The built-in volumetric sheen LTC table                          */\n"
           "/* ======================================================================== */\n"
           "/* Zeltner, Burley & Chiang 2022: LTC fits of the light reflected by a\n"
           " * layer of fibre-like SGGX microflakes (unit thickness and density, albedo\n"
           " * 1, black base, every scattering order), simulated by tools/sheen_fit.c\n"
           " * (%d walks per entry with next event estimation for the lobe, %d for\n"
           " * the albedo). %d rows alpha = max(0.01, i / %d), %d columns\n"
           " * cos theta_o = max(0.01, j / %d), three floats per entry: A, B of\n"
           " * M^-1 = [A 0 B; 0 A 0; 0 0 1] and the albedo R. Read through\n"
           " * mf_sheen_brdf, mf_sheen_pdf, mf_sheen_sample, mf_sheen_albedo (23_sheen_volume.h). */\n"
           "/* @impl */\n"
           "#ifndef MF_NO_LTC_TABLE\n"
           "static const float *mf__sheen_data(int *n)\n"
           "{\n"
           "    static const float data[%d * %d * 3] = {\n", W_NEE, W_NEE + W_R, NT, NT - 1, NT, NT - 1, NT, NT);
    for (i = 0; i < NT; ++i) {
        for (j = 0; j < NT; ++j) {
            print_float(table[i][j][0]); print_float(table[i][j][1]); print_float(table[i][j][2]);
            printf(j % 4 == 3 ? "\n" : " ");
        }
    }
    printf("    };\n    *n = %d;\n    return data;\n}\n#endif\n", NT);
    return 0;
}
