/* Fits the sensitivities of mf_fresnel_thin_film_rgb (Belcour & Barla 2017,
 * Sec. 4: the colour-matching functions in the frequency domain as sums of
 * Gaussians, whose Fourier transforms are closed-form) and prints the
 * constants of src/19_fresnel_f82_thin_film.h:
 *   cc -O2 tools/thin_film_fit.c -o thin_film_fit -lm && ./thin_film_fit 12 1e-3
 * (12 Gaussians, ridge 1e-3; about a minute)
 * Targets: the linear sRGB sensitivities s_c(nu) = sum_j M_cj cmf_j(1/nu)
 * D65(1/nu) / nu^2 (the D65-weighted CIE 1931 functions taken to linear sRGB
 * by M, as densities in the frequency nu = 1/lambda, in 1/um; the 5 nm
 * tables linearly interpolated in lambda, 0 outside 380-780 nm), fitted
 * together in L2 over nu (each channel relative to its norm) by K Gaussians
 * of shared means and widths and per-channel amplitudes (Levenberg-Marquardt
 * on the means and log widths, numeric Jacobian; the amplitudes by linear
 * least squares with a small ridge, variable projection). Printed: per
 * Gaussian its mean mu (1/um), its variance term 2 pi^2 sigma^2 (um^2) and,
 * per channel c, the weight W_ck = a_ck G_k / sum_k' a_ck' G_k' (G_k =
 * sqrt(2 pi) sigma_k the Gaussian's integral), so that
 *   S_c(x) / S_c(0) = sum_k W_ck exp(2 pi i x mu_k) exp(-2 pi^2 sigma_k^2 x^2)
 * is the normalized Fourier transform of channel c at optical path x (um);
 * and the error of that transform against the tables' own, over x in
 * [0, 40] um. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cie_1931_d65.h"

#define NG 3000            /* fitting grid in nu */
#define NU0 1.1
#define NU1 2.8
static const double PI = 3.14159265358979323846;

static double table(const double *t, double lambda_nm)
{
    double f = (lambda_nm - MF_CIE_LAMBDA0) / MF_CIE_DLAMBDA;
    int i = (int)floor(f);
    if (f < 0.0 || f > MF_CIE_N - 1) return 0.0;
    if (i >= MF_CIE_N - 1) return t[MF_CIE_N - 1];
    f -= i;
    return t[i] * (1.0 - f) + t[i + 1] * f;
}
static const double *cmf(int j) { return j == 0 ? mf_cie_x : j == 1 ? mf_cie_y : mf_cie_z; }
/* the target density in nu (1/um) */
static double target(int j, double nu)
{
    double l = 1000.0 / nu;
    return table(cmf(j), l) * table(mf_cie_d65, l) / (nu * nu);
}

/* The fit: K Gaussians g_k(nu) = exp(-(nu - mu_k)^2 / (2 sigma_k^2)) shared by
 * the three linear sRGB channels s_c = sum_j M_cj target_j, each channel with
 * its own amplitudes a_ck (variable projection: for given means and widths
 * the amplitudes are the linear least-squares solution); the residual is
 * every channel's, relative to its norm. */
#define KMAX 12
static double g_sc[3][NG], g_nsc[3];
static int g_k;
static double g_ridge = 1e-3;
/* solves the normal equations of channel c for p = (mu_k, log sigma_k); amplitudes to a */
static void amplitudes(const double *p, const double *nu, double a[3][KMAX])
{
    double A[KMAX][KMAX + 3];
    int k = g_k, i, b, c, q;
    for (i = 0; i < k; ++i)
        for (b = 0; b < k + 3; ++b) A[i][b] = 0.0;
    for (q = 0; q < NG; ++q) {
        double g[KMAX];
        for (i = 0; i < k; ++i) { double d = (nu[q] - p[2 * i]) / exp(p[2 * i + 1]); g[i] = exp(-0.5 * d * d); }
        for (i = 0; i < k; ++i) {
            for (b = 0; b < k; ++b) A[i][b] += g[i] * g[b];
            for (c = 0; c < 3; ++c) A[i][k + c] += g[i] * g_sc[c][q];
        }
    }
    /* a ridge on the amplitudes: no pairs of near-equal Gaussians with large
     * amplitudes of opposite signs (a derivative in disguise, cancellation in float) */
    {
        double tr = 0.0;
        for (i = 0; i < k; ++i) tr += A[i][i];
        for (i = 0; i < k; ++i) A[i][i] += g_ridge * tr / k;
    }
    for (i = 0; i < k; ++i) {
        int piv = i;
        for (b = i + 1; b < k; ++b) if (fabs(A[b][i]) > fabs(A[piv][i])) piv = b;
        for (b = 0; b < k + 3; ++b) { double t = A[i][b]; A[i][b] = A[piv][b]; A[piv][b] = t; }
        for (b = 0; b < k; ++b)
            if (b != i) {
                double f = A[b][i] / A[i][i];
                int e;
                for (e = i; e < k + 3; ++e) A[b][e] -= f * A[i][e];
            }
    }
    for (c = 0; c < 3; ++c)
        for (i = 0; i < k; ++i) a[c][i] = A[i][k + c] / A[i][i];
}
static double resid(const double *p, const double *nu, double *r)
{
    double a[3][KMAX], e = 0.0;
    int q, c, i;
    amplitudes(p, nu, a);
    for (q = 0; q < NG; ++q) {
        double g[KMAX];
        for (i = 0; i < g_k; ++i) { double d = (nu[q] - p[2 * i]) / exp(p[2 * i + 1]); g[i] = exp(-0.5 * d * d); }
        for (c = 0; c < 3; ++c) {
            double m = 0.0;
            for (i = 0; i < g_k; ++i) m += a[c][i] * g[i];
            r[3 * q + c] = (m - g_sc[c][q]) / g_nsc[c];
            e += r[3 * q + c] * r[3 * q + c];
        }
    }
    return e;
}
/* Levenberg-Marquardt on the 2K nonlinear parameters */
static double fit(double *p, const double *nu)
{
    static double r[3 * NG], r2[3 * NG], J[3 * NG][2 * KMAX];
    double lam = 1e-3, e = resid(p, nu, r);
    int it, n = 2 * g_k, a, b, i;
    for (it = 0; it < 500; ++it) {
        double A[2 * KMAX][2 * KMAX + 1], pn[2 * KMAX], en;
        for (a = 0; a < n; ++a) {
            double h = 1e-6, keep = p[a];
            p[a] = keep + h; resid(p, nu, r2);
            for (i = 0; i < 3 * NG; ++i) J[i][a] = r2[i];
            p[a] = keep - h; resid(p, nu, r2);
            for (i = 0; i < 3 * NG; ++i) J[i][a] = (J[i][a] - r2[i]) / (2.0 * h);
            p[a] = keep;
        }
        for (;;) {
            for (a = 0; a < n; ++a) {
                for (b = 0; b < n; ++b) {
                    double s = 0.0;
                    for (i = 0; i < 3 * NG; ++i) s += J[i][a] * J[i][b];
                    A[a][b] = s * (a == b ? 1.0 + lam : 1.0);
                }
                A[a][n] = 0.0;
                for (i = 0; i < 3 * NG; ++i) A[a][n] -= J[i][a] * r[i];
            }
            for (a = 0; a < n; ++a) {
                int piv = a;
                for (b = a + 1; b < n; ++b) if (fabs(A[b][a]) > fabs(A[piv][a])) piv = b;
                for (b = 0; b <= n; ++b) { double tt = A[a][b]; A[a][b] = A[piv][b]; A[piv][b] = tt; }
                for (b = 0; b < n; ++b)
                    if (b != a) {
                        double f = A[b][a] / A[a][a];
                        for (i = a; i <= n; ++i) A[b][i] -= f * A[a][i];
                    }
            }
            for (a = 0; a < n; ++a) pn[a] = p[a] + A[a][n] / A[a][a];
            en = resid(pn, nu, r2);
            if (en < e) {
                double gain = e - en;
                memcpy(p, pn, sizeof(double) * n);
                memcpy(r, r2, sizeof r);
                e = en;
                lam *= 0.3;
                if (gain < 1e-12 * e) return e;
                break;
            }
            lam *= 10.0;
            if (lam > 1e12) return e;
        }
    }
    return e;
}

int main(int argc, char **argv)
{
    static double nu[NG];
    double p[2 * KMAX], a[3][KMAX], W[3][KMAX], mu[KMAX], v[KMAX], dnu = (NU1 - NU0) / (NG - 1), e;
    int i, j, c, q;
    g_k = argc > 1 ? atoi(argv[1]) : 8;
    if (argc > 2) g_ridge = atof(argv[2]);
    if (g_k < 1 || g_k > KMAX) return 1;
    for (q = 0; q < NG; ++q) nu[q] = NU0 + dnu * q;
    for (c = 0; c < 3; ++c) {
        g_nsc[c] = 0.0;
        for (q = 0; q < NG; ++q) {
            g_sc[c][q] = 0.0;
            for (j = 0; j < 3; ++j) g_sc[c][q] += mf_xyz_to_srgb[c][j] * target(j, nu[q]);
            g_nsc[c] += g_sc[c][q] * g_sc[c][q];
        }
        g_nsc[c] = sqrt(g_nsc[c]);
    }
    /* initial means spread over the visible frequencies, widths 0.1 / um */
    for (i = 0; i < g_k; ++i) {
        p[2 * i] = 1.35 + (2.55 - 1.35) * (i + 0.5) / g_k;
        p[2 * i + 1] = log(0.6 / g_k);
    }
    e = fit(p, nu);
    fprintf(stderr, "fit: %d Gaussians, relative L2 error of the three channels together %.3g\n", g_k, sqrt(e / 3.0));
    amplitudes(p, nu, a);
    for (i = 0; i < g_k; ++i) {
        double sg = exp(p[2 * i + 1]);
        mu[i] = p[2 * i];
        v[i] = 2.0 * PI * PI * sg * sg;
        for (c = 0; c < 3; ++c) W[c][i] = a[c][i] * sqrt(2.0 * PI) * sg;   /* the Gaussian's integral */
    }
    for (c = 0; c < 3; ++c) {
        double norm = 0.0;
        for (i = 0; i < g_k; ++i) norm += W[c][i];
        for (i = 0; i < g_k; ++i) W[c][i] /= norm;
    }
    /* error of the normalized transforms against the tables' (dense quadrature in nu) */
    {
        double worst[3] = { 0, 0, 0 }, norm[3] = { 0, 0, 0 }, cen[3] = { 0, 0, 0 };
        int n = 20000;
        static double sc[3][20000], nq[20000];
        for (q = 0; q < n; ++q) {
            double x = NU0 + (NU1 - NU0) * (q + 0.5) / n;
            nq[q] = x;
            for (c = 0; c < 3; ++c) {
                sc[c][q] = 0.0;
                for (j = 0; j < 3; ++j) sc[c][q] += mf_xyz_to_srgb[c][j] * target(j, x);
                norm[c] += sc[c][q];
                cen[c] += sc[c][q] * x;
            }
        }
        for (i = 0; i <= 400; ++i) {
            double x = 0.1 * i;
            for (c = 0; c < 3; ++c) {
                double re = 0.0, im = 0.0, fr = 0.0, fi = 0.0, er;
                for (q = 0; q < n; ++q) { re += sc[c][q] * cos(2 * PI * x * nq[q]); im += sc[c][q] * sin(2 * PI * x * nq[q]); }
                re /= norm[c]; im /= norm[c];
                for (j = 0; j < g_k; ++j) {
                    double env = W[c][j] * exp(-v[j] * x * x);
                    fr += env * cos(2 * PI * x * mu[j]);
                    fi += env * sin(2 * PI * x * mu[j]);
                }
                er = sqrt((fr - re) * (fr - re) + (fi - im) * (fi - im));
                if (er > worst[c]) worst[c] = er;
            }
        }
        fprintf(stderr, "worst |S_fit - S_table| / S(0) over x in [0, 40] um: R %.3g G %.3g B %.3g\n", worst[0], worst[1], worst[2]);
        printf("    /* Generated by tools/thin_film_fit.c %d %g: the normalized transforms'\n"
               "     * error against the CIE tables' over x in [0, 40] um: R %.2g, G %.2g, B %.2g;\n"
               "     * the channels' mean wavelengths (1 / mean frequency): %.1f, %.1f, %.1f nm */\n",
               g_k, g_ridge, worst[0], worst[1], worst[2], 1000.0 * norm[0] / cen[0], 1000.0 * norm[1] / cen[1],
               1000.0 * norm[2] / cen[2]);
    }
    /* the arrays as they stand in mf_fresnel_thin_film_rgb */
    printf("    const mf_real mu[MF__TF_K] = {");
    for (i = 0; i < g_k; ++i) printf("%s MF_R(%.9g)%s", i % 4 == 0 ? "\n       " : "", mu[i], i + 1 < g_k ? "," : " };\n");
    printf("    const mf_real var[MF__TF_K] = {");
    for (i = 0; i < g_k; ++i) printf("%s MF_R(%.9g)%s", i % 4 == 0 ? "\n       " : "", v[i], i + 1 < g_k ? "," : " };\n");
    printf("    const mf_real w[3][MF__TF_K] = {\n");
    for (c = 0; c < 3; ++c) {
        printf("        {");
        for (i = 0; i < g_k; ++i) printf("%s MF_R(%.9g)%s", i % 4 == 0 && i ? "\n         " : "", W[c][i], i + 1 < g_k ? "," : " }");
        printf("%s\n", c < 2 ? "," : " };");
    }
    return 0;
}
