/* Fits LTC tables with the library's own fitter (mf_ltc_table_build) and
 * prints them as C data to stdout.
 *   cc -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit.c -o ltc_fit -lm
 *   ./ltc_fit [kind] [gamma] [n] > table.inc     (kind: ggx, beckmann, gtr, student_t)
 *   ./ltc_fit --module > src/14_ltc_table.h      the built-in GGX table module (fit,
 *                                                then refinement on polygons, below)
 *   ./ltc_fit --module beckmann > src/14_ltc_table_beckmann.h
 *                                                the built-in Beckmann table module
 *                                                (`make ltc-table`)
 * stderr shows the progress, the time and the value ranges (for float16
 * packing). */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "print_float.h"

/* ---- Refinement of the GGX table on integrated polygons ----
 * The L3 fit of the lobe (mf_ltc_fit) matches the peak and neglects the
 * tail, which carries the light of lamps away from the mirror direction.
 * Each entry is refitted (Nelder-Mead on the four stored M^-1 entries, from
 * the L3 fit) to minimize the mean relative error of albedo * LTC integral
 * against the integral of the true BRDF cos over 56 training lights at unit
 * distance (lobe width w = min(2 atan(alpha), 1)):
 *   around the mirror direction, 16 squares (half-widths 0.25 to 2 w,
 *   offsets 0 to 1.2 w), 8 small squares (half-widths 0.1 to 0.5 w, offsets
 *   0 and 0.3 w: disks) and 8 thin strips (0.03 w by 0.6 or 1.2 w, both
 *   ways: tubes);
 *   away from it (at least min(3 w, 1.2 rad)), 24 squares (half-widths 0.1
 *   to 0.3 rad);
 * objective: 0.5 (mean error around) + 0.5 (mean error away)
 *   + 3 mean over the lights around (those above the horizon) of
 *     max(0, error - max(error of the L3 fit, 0.06)).
 * The last term keeps round and thin lights near the lobe at the L3 fit's
 * accuracy: without it (16 squares around, weights 0.7 / 0.3) the refit
 * traded them for the tail (disks near the lobe at grazing views 36% off,
 * where the L3 fit is 7%). The references are composite 8-point
 * Gauss-Legendre rules over the rectangle, graded around the mirror
 * direction and cut at the horizon. */
static const double gl8x[8] = { -0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363 };
static const double gl8w[8] = { 0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763 };
#define PI_D 3.14159265358979323846

/* ref: the BRDF integral; e0: the L3 fit's relative error; guard: held to e0 */
typedef struct { mf_vec3 p[4]; double ref, e0; int near, guard; } train_light;
typedef struct { train_light L[56]; int n, nn, ng; double albedo; } train_set;
#define GUARD_WEIGHT 3.0
#define GUARD_TOL 0.06

/* u, v spanning the plane through unit c; u along the steepest ascent of z */
static void plane_frame(const double *c, double *u, double *v)
{
    double n;
    int k;
    u[0] = -c[2] * c[0]; u[1] = -c[2] * c[1]; u[2] = 1.0 - c[2] * c[2];
    n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (n < 1e-9) { u[0] = 1.0; u[1] = u[2] = 0.0; }
    else for (k = 0; k < 3; ++k) u[k] /= n;
    v[0] = c[1] * u[2] - c[2] * u[1]; v[1] = c[2] * u[0] - c[0] * u[2]; v[2] = c[0] * u[1] - c[1] * u[0];
}

/* the rectangle of half-angles hx (along u) and hy (along v) centred on c */
static void rect(train_light *l, const double *c, double hx, double hy)
{
    double u[3], v[3], a = tan(hx), b = tan(hy);
    int k;
    plane_frame(c, u, v);
    for (k = 0; k < 4; ++k) {
        double sx = k < 2 ? -a : a, sy = (k == 1 || k == 2) ? b : -b;
        l->p[k] = mf_vec3_make(c[0] + sx * u[0] + sy * v[0], c[1] + sx * u[1] + sy * v[1], c[2] + sx * u[2] + sy * v[2]);
    }
}

static void square(train_light *l, const double *c, double half) { rect(l, c, half, half); }

/* unit a turned by angle t toward azimuth ph */
static void tilt(const double *a, double t, double ph, double *out)
{
    double u[3], v[3];
    int k;
    plane_frame(a, u, v);
    for (k = 0; k < 3; ++k) out[k] = cos(t) * a[k] + sin(t) * (cos(ph) * u[k] + sin(ph) * v[k]);
}

/* breakpoints on [lo, hi], panels of h at the peak c growing geometrically up to hmax */
static int breaks(double lo, double hi, double c, double h, double hmax, double *b, int max)
{
    int n = 0;
    double x = lo;
    b[n++] = lo;
    while (x < hi && n < max - 1) {
        double step = fmax(h, fmin(hmax, 0.5 * fabs(x - c)));
        if (x < c && x + step > c && c - x > 0.25 * h) step = c - x;
        x = fmin(hi, x + step);
        b[n++] = x;
    }
    return n;
}

/* integral of f cos over the square (corners c -+ h u -+ h v, |c| = 1) */
static double reference(const mf_ndf *d, mf_vec3 wo, const train_light *l)
{
    double c[3], u[3], v[3], h, hv, bx[1024], by[1024], px = 1e9, py = 1e9, xlo, sum = 0.0;
    int nx, ny, i, j, a, b, k;
    for (k = 0; k < 3; ++k) {
        c[k] = 0.25 * ((&l->p[0].x)[k] + (&l->p[1].x)[k] + (&l->p[2].x)[k] + (&l->p[3].x)[k]);
        u[k] = 0.5 * ((&l->p[3].x)[k] - (&l->p[0].x)[k]);
        v[k] = 0.5 * ((&l->p[1].x)[k] - (&l->p[0].x)[k]);
    }
    h = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    hv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (k = 0; k < 3; ++k) { u[k] /= h; v[k] /= hv; }
    {   /* the mirror direction's point on the plane */
        double r[3] = { -wo.x, -wo.y, wo.z }, dn = r[0] * c[0] + r[1] * c[1] + r[2] * c[2];
        if (dn > 1e-3) {
            px = (r[0] * u[0] + r[1] * u[1] + r[2] * u[2]) / dn;
            py = (r[0] * v[0] + r[1] * v[1] + r[2] * v[2]) / dn;
        }
    }
    xlo = -h;
    if (u[2] > 1e-12 && -c[2] / u[2] > xlo) xlo = -c[2] / u[2];   /* the horizon */
    if (xlo >= h) return 0.0;
    nx = breaks(xlo, h, px, 0.25 * fmax((double)d->ax, 1e-3), 0.125 * h, bx, 1024);
    ny = breaks(-hv, hv, py, 0.25 * fmax((double)d->ax, 1e-3), 0.125 * hv, by, 1024);
    for (i = 0; i + 1 < nx; ++i)
        for (a = 0; a < 8; ++a) {
            double x = 0.5 * (bx[i] + bx[i + 1] + (bx[i + 1] - bx[i]) * gl8x[a]), wx = 0.5 * (bx[i + 1] - bx[i]) * gl8w[a];
            for (j = 0; j + 1 < ny; ++j)
                for (b = 0; b < 8; ++b) {
                    double y = 0.5 * (by[j] + by[j + 1] + (by[j + 1] - by[j]) * gl8x[b]), wy = 0.5 * (by[j + 1] - by[j]) * gl8w[b];
                    double q[3], r2, r;
                    for (k = 0; k < 3; ++k) q[k] = c[k] + x * u[k] + y * v[k];
                    if (q[2] <= 0.0) continue;
                    r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2]; r = sqrt(r2);
                    /* d omega = dA / r^3 (plane at unit distance) */
                    sum += wx * wy * (double)mf_brdf(d, wo, mf_vec3_make(q[0] / r, q[1] / r, q[2] / r)) * (q[2] / r) / (r2 * r);
                }
        }
    return sum;
}

/* the centre pushed up to 0.05 above the horizon */
static void lift(double *c)
{
    if (c[2] < 0.05) {
        double f = sqrt((1.0 - 0.0025) / (c[0] * c[0] + c[1] * c[1]));
        c[0] *= f; c[1] *= f; c[2] = 0.05;
    }
}

static void training_set(train_set *s, const mf_ndf *d, double ct, double alpha)
{
    static const double size[4] = { 0.5, 1.0, 2.0, 4.0 }, off[4] = { 0.0, 0.4, 0.8, 1.2 }, small[4] = { 0.1, 0.2, 0.35, 0.5 };
    double st = sqrt(1.0 - ct * ct), w = fmin(2.0 * atan(alpha), 1.0), r[3], c[3];
    mf_vec3 wo = mf_vec3_make(st, 0.0, ct);
    int k, i, n = 0, m = 0;
    r[0] = -st; r[1] = 0.0; r[2] = ct;
    memset(s->L, 0, sizeof s->L);
    for (k = 0; k < 16; ++k) {   /* squares around the mirror direction */
        double h = fmin(0.5 * size[k / 4] * w, 1.2);
        tilt(r, off[k % 4] * w, 2.0 * PI_D * (0.618034 * k + 0.1), c);
        lift(c);
        square(&s->L[n], c, h);
        s->L[n].guard = c[2] > sin(h) + 0.02;   /* above the horizon */
        s->L[n++].near = 1;
    }
    for (k = 0; k < 8; ++k) {   /* thin strips (tubes) across it */
        double len = fmin((k & 1 ? 1.2 : 0.6) * w, 1.0), wd = fmax(0.03 * w, 0.004);
        tilt(r, (k & 4) ? 0.2 * w : 0.0, 2.0 * PI_D * (0.618034 * k + 0.6), c);
        lift(c);
        if (k & 2) rect(&s->L[n], c, len, wd); else rect(&s->L[n], c, wd, len);
        s->L[n].guard = 1;
        s->L[n++].near = 1;
    }
    for (k = 0; k < 8; ++k) {   /* small squares (disks) */
        tilt(r, k < 4 ? 0.0 : 0.3 * w, 2.0 * PI_D * (0.618034 * k + 0.35), c);
        lift(c);
        square(&s->L[n], c, small[k % 4] * w);
        s->L[n].guard = 1;
        s->L[n++].near = 1;
    }
    for (i = 0; i < 200 && n < 56; i += 5) {   /* every 5th of 200 Fibonacci points on z in [0.1, 1] */
        double z = 0.1 + 0.9 * (i + 0.5) / 200.0, ph = 2.0 * PI_D * 0.618034 * i, sn = sqrt(1.0 - z * z), dd;
        c[0] = sn * cos(ph); c[1] = sn * sin(ph); c[2] = z;
        dd = acos(fmax(-1.0, fmin(1.0, c[0] * r[0] + c[1] * r[1] + c[2] * r[2])));
        if (dd < fmin(3.0 * w, 1.2)) continue;
        square(&s->L[n], c, 0.1 + 0.1 * (n % 3));
        s->L[n++].near = 0;
    }
    /* references; lights whose integral underflows say nothing */
    for (k = 0; k < n; ++k) {
        s->L[k].ref = reference(d, wo, &s->L[k]);
        if (s->L[k].ref > 1e-12) s->L[m++] = s->L[k];
    }
    s->n = m;
    for (k = 0, s->nn = 0, s->ng = 0; k < m; ++k) { s->nn += s->L[k].near; s->ng += s->L[k].guard; }
}

static double objective(const train_set *s, const double *x)
{
    mf_ltc l = mf_ltc_from_inverse(x[0], x[1], 1.0, x[2], x[3]);
    double en = 0.0, eo = 0.0, eg = 0.0;
    int i;
    /* keep the orientation of the fit: positive diagonal and determinant
     * (blending entries of both signs would pass through singular matrices) */
    if (!(x[0] > 0.0 && x[3] > 0.0 && x[0] * x[3] - x[1] * x[2] > 0.0)) return 1e30;
    for (i = 0; i < s->n; ++i) {
        double e = fabs(s->albedo * mf_ltc_integrate(&l, s->L[i].p, 4, 1) - s->L[i].ref) / s->L[i].ref;
        if (s->L[i].near) en += e; else eo += e;
        if (s->L[i].guard) eg += fmax(0.0, e - fmax(s->L[i].e0, GUARD_TOL));
    }
    return (s->nn ? 0.5 * en / s->nn : 0.0) + (s->n > s->nn ? 0.5 * eo / (s->n - s->nn) : 0.0) + (s->ng ? GUARD_WEIGHT * eg / s->ng : 0.0);
}

/* Nelder-Mead in 4 dimensions (standard coefficients) */
static double nelder_mead4(const train_set *ts, double *x, double step, int max_iter)
{
    double s[5][4], f[5], xr[4], xe[4], xc[4], cen[4];
    int i, j, it, lo = 0;
    for (i = 0; i < 5; ++i) {
        for (j = 0; j < 4; ++j) s[i][j] = x[j];
        if (i > 0) s[i][i - 1] += step * fmax(fabs(x[i - 1]), 0.05);
        f[i] = objective(ts, s[i]);
    }
    for (it = 0; it < max_iter; ++it) {
        int hi = 0, nh;
        double fr;
        lo = 0;
        for (i = 1; i < 5; ++i) { if (f[i] < f[lo]) lo = i; if (f[i] > f[hi]) hi = i; }
        nh = lo;
        for (i = 0; i < 5; ++i) if (i != hi && f[i] > f[nh]) nh = i;
        if (f[hi] - f[lo] <= 1e-7 * (f[lo] + 1e-12)) break;
        for (j = 0; j < 4; ++j) {
            cen[j] = 0.0;
            for (i = 0; i < 5; ++i) if (i != hi) cen[j] += 0.25 * s[i][j];
            xr[j] = 2.0 * cen[j] - s[hi][j];
        }
        fr = objective(ts, xr);
        if (fr < f[lo]) {
            double fe;
            for (j = 0; j < 4; ++j) xe[j] = cen[j] + 2.0 * (xr[j] - cen[j]);
            fe = objective(ts, xe);
            if (fe < fr) { memcpy(s[hi], xe, sizeof xe); f[hi] = fe; }
            else { memcpy(s[hi], xr, sizeof xr); f[hi] = fr; }
        } else if (fr < f[nh]) {
            memcpy(s[hi], xr, sizeof xr); f[hi] = fr;
        } else {
            double fc;
            for (j = 0; j < 4; ++j) xc[j] = cen[j] + 0.5 * (s[hi][j] - cen[j]);
            fc = objective(ts, xc);
            if (fc < f[hi]) { memcpy(s[hi], xc, sizeof xc); f[hi] = fc; }
            else
                for (i = 0; i < 5; ++i) if (i != lo) {
                    for (j = 0; j < 4; ++j) s[i][j] = s[lo][j] + 0.5 * (s[i][j] - s[lo][j]);
                    f[i] = objective(ts, s[i]);
                }
        }
    }
    lo = 0;
    for (i = 1; i < 5; ++i) if (f[i] < f[lo]) lo = i;
    memcpy(x, s[lo], sizeof s[lo]);
    return f[lo];
}

/* refits every entry of a GGX table in place (same grid as mf_ltc_table_build) */
static void refine_on_polygons(mf_ltc_table *t)
{
    static train_set ts;
    double before = 0.0, after = 0.0;
    int i, j, k, n = t->n_theta, na = t->n_alpha;
    for (j = na - 1; j >= 0; --j) {
        double v = (double)j / (na - 1), alpha = fmax(v * v, 1e-3);
        mf_ndf d = mf_ggx(alpha, alpha);
        for (i = 0; i < n; ++i) {
            double tt = (double)i / (n - 1), ct = fmax(1.0 - tt * tt, 1e-3), x[4];
            float *e = t->data + 6 * (j * n + i);
            for (k = 0; k < 4; ++k) x[k] = e[k];
            training_set(&ts, &d, ct, alpha);
            ts.albedo = e[4];
            if (ts.n == 0) continue;
            {   /* the plain fit's errors */
                mf_ltc l0 = mf_ltc_from_inverse(x[0], x[1], 1.0, x[2], x[3]);
                for (k = 0; k < ts.n; ++k) ts.L[k].e0 = fabs(ts.albedo * mf_ltc_integrate(&l0, ts.L[k].p, 4, 1) - ts.L[k].ref) / ts.L[k].ref;
            }
            before += objective(&ts, x);
            nelder_mead4(&ts, x, 0.1, 2000);
            after += nelder_mead4(&ts, x, 0.02, 2000);   /* restart: Nelder-Mead can stall */
            for (k = 0; k < 4; ++k) e[k] = (float)x[k];
        }
        fprintf(stderr, "\rrefined row %d", j);
    }
    fprintf(stderr, "\nmean training error: L3 fit %.4f, refined %.4f\n", before / (n * na), after / (n * na));
}

/* The opening of a built-in table module, up to the first entry. */
static void print_module_head(int n, const char *name, const char *fn, const char *acc, int refined)
{
    printf("/* Generated by tools/ltc_fit.c (`make ltc-table`): do not edit. */\n"
           "/* ======================================================================== */\n"
           "/* == 14. The built-in LTC table of %-39s */\n"
           "/* ======================================================================== */\n"
           "/* %d x %d LTC fits of the %s BRDF times cos(theta_i) (mf_ltc_table_build,\n"
           " * fitted in double%s), rows sqrt(alpha), columns sqrt(1 - cos theta_o), six\n"
           " * floats per entry: inv0..inv3 with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3],\n"
           " * the albedo and the Fresnel column. Read through mf_ltc_%s, mf_ltc_%s_albedo,\n"
           " * mf_ltc_%s_fresnel and mf_ltc_%s_table (13_ltc.h). */\n"
           "/* @impl */\n"
           "#ifndef MF_NO_LTC_TABLE\n"
           "static const float *%s(int *n)\n"
           "{\n"
           "    static const float data[%d * %d * 6] = {\n", name, n, n, name,
           refined ? ", then each entry refitted on its integrals over 56\n"
                     " * training lights around and away from the mirror direction, see\n"
                     " * tools/ltc_fit.c" : "",
           acc, acc, acc, acc, fn, n, n);
}

static void progress(int done, int total, void *ctx)
{
    (void)ctx;
    if (done % 256 == 0 || done == total) fprintf(stderr, "\r%d / %d", done, total);
}

/* the family of the fitted kind at roughness alpha (gamma: the tail of GTR
 * and Student-t) */
typedef struct { int kind; mf_real gamma; } family_ctx;
static mf_ndf family(mf_real alpha, void *ctx)
{
    const family_ctx *f = (const family_ctx *)ctx;
    if (f->kind == MF_NDF_BECKMANN) return mf_beckmann(alpha, alpha);
    if (f->kind == MF_NDF_GTR) return mf_gtr(alpha, f->gamma);
    if (f->kind == MF_NDF_STUDENT_T) return mf_student_t(alpha, alpha, f->gamma);
    return mf_ggx(alpha, alpha);
}

int main(int argc, char **argv)
{
    mf_ltc_table t;
    int kind = MF_NDF_GGX, n = 64, i, k;
    double gamma = 2.0, lo[6], hi[6];
    family_ctx fc;
    clock_t t0 = clock();
    int module = argc > 1 && !strcmp(argv[1], "--module");
    if (module) {   /* the built-in tables: GGX or Beckmann, n = 64 */
        if (argc > 2 && !strcmp(argv[2], "beckmann")) kind = MF_NDF_BECKMANN;
        argc = 1;
    }
    if (argc > 1) {
        if (!strcmp(argv[1], "beckmann")) kind = MF_NDF_BECKMANN;
        else if (!strcmp(argv[1], "gtr")) kind = MF_NDF_GTR;
        else if (!strcmp(argv[1], "student_t")) kind = MF_NDF_STUDENT_T;
    }
    if (argc > 2) gamma = atof(argv[2]);
    if (argc > 3) n = atoi(argv[3]);
    fc.kind = kind;
    fc.gamma = (mf_real)gamma;
    if (mf_ltc_table_build(&t, family, &fc, n, n, progress, NULL) != MF_SUCCESS) {
        fprintf(stderr, "fit failed\n");
        return 1;
    }
    fprintf(stderr, "\nfitted %d x %d in %.1f s\n", n, n, (double)(clock() - t0) / CLOCKS_PER_SEC);
    if (module && kind == MF_NDF_GGX) {
        refine_on_polygons(&t);
        fprintf(stderr, "refined in %.1f s in all\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    }
    for (k = 0; k < 6; ++k) { lo[k] = 1e30; hi[k] = -1e30; }
    if (module && kind == MF_NDF_BECKMANN) print_module_head(n, "Beckmann", "mf__ltc_beckmann_data", "beckmann", 0);
    else if (module) print_module_head(n, "GGX", "mf__ltc_ggx_data", "ggx", 1);
    else printf("/* %d x %d entries [sqrt(alpha)][sqrt(1 - cos theta)]: inv0 inv1 inv2 inv3 albedo fresnel, M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] */\n", n, n);
    for (i = 0; i < n * n; ++i) {
        for (k = 0; k < 6; ++k) {
            double v = t.data[6 * i + k];
            if (v < lo[k]) lo[k] = v;
            if (v > hi[k]) hi[k] = v;
            print_float(v);
        }
        printf(i % 2 == 1 ? "\n" : " ");
    }
    if (module) printf("    };\n    *n = %d;\n    return data;\n}\n#endif\n", n);
    for (k = 0; k < 6; ++k) fprintf(stderr, "column %d in [%g, %g]\n", k, lo[k], hi[k]);
    mf_ltc_table_release(&t);
    return 0;
}
