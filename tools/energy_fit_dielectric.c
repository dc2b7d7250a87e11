/* Tabulates the rough-dielectric albedo of isotropic GGX and Beckmann for
 * the built-in tables of mf_dielectric_albedo / mf_dielectric_bsdf_ms and
 * prints src/17_energy_table_dielectric.h (`make energy-table`, after the
 * conductor table, which this one is relative to):
 *   cc -O2 -DMF_USE_DOUBLE -I. tools/energy_fit_dielectric.c -o fit -lm
 *   ./fit > src/17_energy_table_dielectric.h
 * For wo above a relative index e (index across over index of wo's side),
 * in importance transport: E = R + T, the reflected plus transmitted albedo
 * of mf_dielectric_bsdf, by Gauss-Legendre quadrature over the visible
 * normals (PANELS^2 panels of 8 x 8 nodes). Stored per node:
 * dE = E - E_cond(mu, alpha), E_cond the built-in F = 1 table (mf_albedo),
 * which carries the grazing dip at mu ~ alpha so that dE is smooth enough
 * for a coarse grid, as an integer in units of 1e-4. Axes: kind (GGX,
 * Beckmann), side (0: e >= 1, entering the denser medium; 1: e < 1,
 * leaving it), s = |e - 1| / (e + 1) (e and 1 / e share s) at NS nodes
 * equally spaced in log(s + SOFF) from e = 1.05 to e = 3, r = sqrt(alpha)
 * = i / (NR - 1), u(mu) = c / (NX - 1) (ucoord below; mu = 1e-4 at c = 0). Then
 * per (kind, side, s, r) the exact average 2 int dE mu dmu of the node
 * row's interpolant (float), and per (side, s) the Fresnel average F_avg(e). */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <string.h>
#include <time.h>

#ifndef NX
#define NX 28
#endif
#ifndef NR
#define NR 16
#endif
#ifndef NS
#define NS 14
#endif
#define SMAX 0.5
#define SMIN (0.05 / 2.05)   /* e = 1.05 */
#ifndef SOFF
#define SOFF 0.015
#endif
#ifndef PANELS
#define PANELS 16
#endif

#include "print_float.h"

/* E and T for wo = (sqrt(1 - mu^2), 0, mu), relative index e */
static void albedo(const mf_ndf *d, double mu, double e, double *E, double *T)
{
    mf_vec3 wo = mf_vec3_make(sqrt(1.0 - mu * mu), 0.0, mu);
    double lo = mf_lambda(d, wo), sr = 0.0, st = 0.0, h = 1.0 / PANELS;
    int p1, p2, i, j;
    for (p1 = 0; p1 < PANELS; ++p1)
        for (i = 0; i < 8; ++i)
            for (p2 = 0; p2 < PANELS; ++p2)
                for (j = 0; j < 8; ++j) {
                    double w = mf__gl_w(i) * mf__gl_w(j), F;
                    mf_vec3 m = mf__sample_visible_smooth(d, wo, mf__gl_node01(p1, i, PANELS), mf__gl_node01(p2, j, PANELS)), wr, wt;
                    if (!(m.z > 0.0) || !(mf_dot(wo, m) > 0.0)) continue;
                    F = mf_fresnel_dielectric(mf_dot(wo, m), e);
                    wr = mf_reflect(wo, m);
                    if (wr.z > 0.0) sr += w * F * (1.0 + lo) * mf__dielectric_G2(d, wo, wr);
                    if (F < 1.0 && mf_refract(wo, m, e, &wt) && wt.z < 0.0) st += w * (1.0 - F) * (1.0 + lo) * mf__dielectric_G2(d, wo, wt);
                }
    *E = (sr + st) * h * h;
    *T = st * h * h;
    if (*E > 1.0) { *T *= 1.0 / *E; *E = 1.0; }
}

static void print_int(long v, int *col)
{
    *col += printf("%ld,", v);
    if (*col > 100) { printf("\n"); *col = 0; }
}


/* the column coordinate u(mu) = (mu^(1/4) + 1 - sqrt(1 - mu)) / 2: dense
 * at grazing (near e = 1 a grazing refraction stays grazing and E has a
 * second dip at mu << alpha), linear in the angle at normal incidence
 * (where the exiting side's total internal reflection moves fast); its
 * inverse by bisection */
static double ucoord(double mu) { return 0.5 * (sqrt(sqrt(mu)) + 1.0 - sqrt(1.0 - mu)); }
static double umu(double u)
{
    double lo = 0.0, hi = 1.0;
    int it;
    for (it = 0; it < 200; ++it) {
        double m = 0.5 * (lo + hi);
        if (ucoord(m) < u) lo = m; else hi = m;
    }
    return 0.5 * (lo + hi);
}
/* 2 int e(u(mu)) mu dmu for e piecewise linear on n nodes u = c / (n - 1):
 * per segment 8-point Gauss-Legendre in mu (the integrand is smooth there) */
static double avg_u(const double *e, int n)
{
    double sum = 0.0;
    int c, g;
    for (c = 0; c + 1 < n; ++c) {
        double m0 = umu((double)c / (n - 1)), m1 = umu((double)(c + 1) / (n - 1));
        for (g = 0; g < 8; ++g) {
            double t = 0.5 + 0.5 * (double)mf__gl_xi(g), mu = m0 + (m1 - m0) * t;
            double f = (ucoord(mu) * (n - 1)) - (double)c, v = e[c] + (e[c + 1] - e[c]) * f;
            sum += (double)mf__gl_w(g) * (m1 - m0) * 2.0 * v * mu;
        }
    }
    return sum;
}

static short dq[2][2][NS][NR][NX];

int main(void)
{
    static const char *kinds[2] = { "GGX", "Beckmann" };
    double row[NX];
    int k, sd, j, i, c, col;
    clock_t t0 = clock();
    for (k = 0; k < 2; ++k)
        for (sd = 0; sd < 2; ++sd)
            for (j = 0; j < NS; ++j) {
                double s = (SMIN + SOFF) * pow((SMAX + SOFF) / (SMIN + SOFF), (double)j / (NS - 1)) - SOFF, eta = (1.0 + s) / (1.0 - s), e = sd ? 1.0 / eta : eta;
                for (i = 0; i < NR; ++i) {
                    double r = (double)i / (NR - 1), alpha = r * r;
                    mf_ndf d = k == 0 ? mf_ggx(alpha, alpha) : mf_beckmann(alpha, alpha);
                    for (c = 0; c < NX; ++c) {
                        double mu = c == 0 ? 1e-4 : umu((double)c / (NX - 1)), E, T;
                        double ec = (double)mf_albedo(&d, mf_vec3_make(sqrt(1.0 - mu * mu), 0.0, mu));
                        if (i == 0) { E = 1.0; T = 0.0; }
                        else albedo(&d, mu, e, &E, &T);
                        dq[k][sd][j][i][c] = (short)floor((E - ec) * 1e4 + 0.5);
                    }
                }
                fprintf(stderr, "\r%s side %d s %d / %d", kinds[k], sd, j + 1, NS);
            }
    printf("/* Generated by tools/energy_fit_dielectric.c (`make energy-table`): do not\n"
           " * edit. */\n"
           "/* ======================================================================== */\n"
           "/* == 17b. The built-in rough-dielectric albedo tables of GGX and Beckmann   */\n"
           "/* ======================================================================== */\n"
           "/* For wo above a relative index e (across over wo's side), importance\n"
           " * transport, the albedo E = R + T of mf_dielectric_bsdf (quadrature over the\n"
           " * visible normals in double, %d panels) as dE = E - mf_albedo (the F = 1\n"
           " * table of 17_energy_table.h carries the grazing dip at mu ~ alpha), in\n"
           " * units of 1e-4: [kind GGX, Beckmann][side e >= 1, e < 1][s = |e - 1| /\n"
           " * (e + 1), %d nodes equally spaced in log(s + %g) from e = 1.05 to %g]\n"
           " * [sqrt(alpha) = i / %d][(mu^(1/4) + 1 - sqrt(1 - mu)) / 2 = c / %d]\n"
           " * (mu = 1e-4 at c = 0). Then\n"
           " * the exact average 2 int dE mu dmu of each (kind, side, s, alpha) row's\n"
           " * interpolant, and F_avg(e) per (side, s). Read through\n"
           " * mf_dielectric_albedo (18_energy.h); gone with MF_NO_ENERGY_TABLES. */\n"
           "/* @impl */\n"
           "#ifndef MF_NO_ENERGY_TABLES\n"
           "#define MF__DIEL_NX %d\n#define MF__DIEL_NR %d\n#define MF__DIEL_NS %d\n#define MF__DIEL_SMIN %.17g\n#define MF__DIEL_SMAX %g\n#define MF__DIEL_SOFF %.17g\n#define MF__DIEL_LOGR %.17g /* log((SMAX + SOFF) / (SMIN + SOFF)) */\n"
           "static const short *mf__energy_diel_data(void)\n"
           "{\n"
           "    static const short dE[2 * 2 * %d * %d * %d] = {\n", PANELS, NS, SOFF, (1.0 + SMAX) / (1.0 - SMAX), NR - 1, NX - 1, NX, NR, NS, SMIN, SMAX, SOFF, log((SMAX + SOFF) / (SMIN + SOFF)), NS, NR, NX);
    col = 0;
    for (k = 0; k < 2; ++k) for (sd = 0; sd < 2; ++sd) for (j = 0; j < NS; ++j) for (i = 0; i < NR; ++i) for (c = 0; c < NX; ++c) print_int(dq[k][sd][j][i][c], &col);
    printf("\n    };\n    return dE;\n}\n");
    printf("static const float *mf__energy_diel_avg(void)\n{\n    static const float avg[2 * 2 * %d * %d + 2 * %d] = {\n", NS, NR, NS);
    col = 0;
    for (k = 0; k < 2; ++k) for (sd = 0; sd < 2; ++sd) for (j = 0; j < NS; ++j) {
        for (i = 0; i < NR; ++i) {
            for (c = 0; c < NX; ++c) row[c] = (double)dq[k][sd][j][i][c] * 1e-4;
            print_float(avg_u(row, NX));
        }
        printf("\n");
    }
    for (sd = 0; sd < 2; ++sd) {
        for (j = 0; j < NS; ++j) {
            double s = (SMIN + SOFF) * pow((SMAX + SOFF) / (SMIN + SOFF), (double)j / (NS - 1)) - SOFF, eta = (1.0 + s) / (1.0 - s);
            print_float((double)mf_fresnel_dielectric_average(sd ? 1.0 / eta : eta));
        }
        printf("\n");
    }
    printf("    };\n    return avg;\n}\n#endif\n");
    fprintf(stderr, "\ntabulated in %.1f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    return 0;
}
