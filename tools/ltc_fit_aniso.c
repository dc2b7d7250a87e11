/* Fits the LTC table of anisotropic GGX (src/14_ltc_table_aniso.h, read by
 * mf_ltc_ggx_aniso in src/13_ltc_aniso.h) and prints it as a module.
 *   cc -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit_aniso.c -o ltc_fit_aniso -lm
 *   ./ltc_fit_aniso --module > src/14_ltc_table_aniso.h   (`make ltc-table-aniso`)
 *   ./ltc_fit_aniso --module NT NP NA NV                   another resolution
 * Deterministic (stratified samples, no random numbers): the same build
 * regenerates the module byte for byte. stderr shows progress and time.
 *
 * Per entry (view (sqrt(1 - cos theta), azimuth), sqrt(alpha_x),
 * sqrt(alpha_y / alpha_x) < 1), Nelder-Mead over the seven free numbers of
 * M^-1 = [p q r; q s t; u v w], s = (1 + q^2) / p (13_ltc_aniso.h), on the
 * L3 error of the LTC against the normalized lobe f cos / albedo, estimated
 * with multiple importance sampling from the LTC and from the BRDF's
 * visible-normal sampler (N x N stratified samples each), as the isotropic
 * fitter (mf_ltc_fit) does. Warm starts walk each (view, alpha_x) from the
 * isotropic entry (mf_ltc_ggx rotated, the table's last slice) down in
 * alpha_y, and also try the previous view elevation's fit: the better
 * start wins, which keeps neighbouring entries on the same branch for
 * interpolation. The albedo is the mean weight of 128 x 128 stratified
 * samples of mf_brdf_sample. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NS 24           /* N: the error estimate's stratified samples per side and technique */
#define NALB 128        /* albedo samples per side */
#define PI_D 3.14159265358979323846

typedef struct {
    mf_ndf d;
    mf_vec3 wo;
    double albedo;
    mf_vec3 bw[NS * NS];
    double bf[NS * NS], bp[NS * NS];
} fit_ctx;

static void minv_from_x(const double *x, double *m)
{
    double p = fabs(x[0]) + 1e-9, q = x[1];
    m[0] = p; m[1] = q; m[2] = x[2];
    m[3] = q; m[4] = (1.0 + q * q) / p; m[5] = x[3];
    m[6] = x[4]; m[7] = x[5]; m[8] = x[6];
}

/* The LTC of a row-major M^-1 (singular or not finite: M = I) */
static mf_ltc ltc_from_minv9(const double *mi)
{
    mf_ltc l;
    mf_real det;
    int i;
    for (i = 0; i < 9; ++i) l.Minv[i] = mi[i];
    det = mf__mat3_inverse(l.Minv, l.M);
    if (!(MF_FABS(det) * MF_BIG > MF_R(1.0)) || !(MF_FABS(det) < MF_BIG)) {
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        return mf_ltc_from_matrix9(I9);
    }
    l.det_inv = MF_FABS(det);
    return l;
}

static double fit_error(const fit_ctx *c, const double *x)
{
    double m[9], err = 0;
    mf_ltc l;
    int i, j;
    double inv[9];
    minv_from_x(x, m);
    /* singular or orientation-reversing (a mirrored branch: one-sided lights
     * would flip, and interpolation across branches is meaningless): rejected.
     * So is w <= 0: thin lobes also fit by strongly sheared matrices with
     * w < 0 (about as well), but blending those with the w > 0 fits of the
     * neighbouring views crosses det 0. */
    if (!(mf__mat3_inverse(m, inv) > 0) || !(m[8] > 0)) return 1e30;
    l = ltc_from_minv9(m);
    for (i = 0; i < NS; ++i)
        for (j = 0; j < NS; ++j) {
            mf_vec3 w = mf_ltc_sample(&l, (i + 0.5) / NS, (j + 0.5) / NS);
            double dl = mf_ltc_eval(&l, w), f = 0, pb = 0, e;
            if (w.z > 0) { f = mf_brdf(&c->d, c->wo, w) * w.z / c->albedo; pb = mf_brdf_pdf(&c->d, c->wo, w); }
            e = fabs(f - dl);
            if (dl + pb > 0) err += e * e * e / (dl + pb);
        }
    for (i = 0; i < NS * NS; ++i) {
        double dl = mf_ltc_eval(&l, c->bw[i]), e = fabs(c->bf[i] - dl);
        if (dl + c->bp[i] > 0) err += e * e * e / (dl + c->bp[i]);
    }
    return err / (2.0 * NS * NS);
}

#define ND 7
static double nelder_mead(const fit_ctx *c, double *x, double step, int max_iter)
{
    double s[ND + 1][ND], f[ND + 1], cen[ND], xr[ND], xe[ND], xc[ND], fr, fe, fc;
    int i, j, it;
    for (i = 0; i <= ND; ++i) {
        for (j = 0; j < ND; ++j) s[i][j] = x[j];
        if (i > 0) s[i][i - 1] += step * (fabs(x[i - 1]) > 0.02 ? fabs(x[i - 1]) : 0.02);
        f[i] = fit_error(c, s[i]);
    }
    for (it = 0; it < max_iter; ++it) {
        int lo = 0, hi = 0, nh;
        for (i = 1; i <= ND; ++i) { if (f[i] < f[lo]) lo = i; if (f[i] > f[hi]) hi = i; }
        nh = lo == 0 ? 1 : 0;
        for (i = 0; i <= ND; ++i) if (i != hi && f[i] > f[nh]) nh = i;
        if (f[hi] - f[lo] <= 1e-9 * (fabs(f[lo]) + 1e-30)) break;
        for (j = 0; j < ND; ++j) {
            cen[j] = 0;
            for (i = 0; i <= ND; ++i) if (i != hi) cen[j] += s[i][j];
            cen[j] /= ND;
        }
        for (j = 0; j < ND; ++j) xr[j] = cen[j] + (cen[j] - s[hi][j]);
        fr = fit_error(c, xr);
        if (fr < f[lo]) {
            for (j = 0; j < ND; ++j) xe[j] = cen[j] + 2.0 * (cen[j] - s[hi][j]);
            fe = fit_error(c, xe);
            if (fe < fr) { memcpy(s[hi], xe, sizeof xe); f[hi] = fe; }
            else { memcpy(s[hi], xr, sizeof xr); f[hi] = fr; }
        } else if (fr < f[nh]) {
            memcpy(s[hi], xr, sizeof xr); f[hi] = fr;
        } else {
            int outside = fr < f[hi];
            for (j = 0; j < ND; ++j) xc[j] = outside ? cen[j] + 0.5 * (xr[j] - cen[j]) : cen[j] + 0.5 * (s[hi][j] - cen[j]);
            fc = fit_error(c, xc);
            if (fc < (outside ? fr : f[hi])) { memcpy(s[hi], xc, sizeof xc); f[hi] = fc; }
            else {
                for (i = 0; i <= ND; ++i) if (i != lo) {
                    for (j = 0; j < ND; ++j) s[i][j] = s[lo][j] + 0.5 * (s[i][j] - s[lo][j]);
                    f[i] = fit_error(c, s[i]);
                }
            }
        }
    }
    {
        int lo = 0;
        for (i = 1; i <= ND; ++i) if (f[i] < f[lo]) lo = i;
        memcpy(x, s[lo], sizeof(double) * ND);
        return f[lo];
    }
}

/* the table's nodes */
static double node_ct(int it, int nt) { double t = (double)it / (nt - 1); double c = 1 - t * t; return c > 0.03 ? c : 0.03; }   /* the last node at 88 deg */
static double node_phi(int ip, int np) { return 0.5 * PI_D * ip / (np - 1); }
static double node_ax(int ia, int na) { double v = (double)ia / (na - 1); v *= v; return v > 1e-3 ? v : 1e-3; }
static double node_v(int iv, int nv) { double s = (double)iv / nv; return s * s; }

static void setup(fit_ctx *c, double ct, double phi, double ax, double ay)
{
    int i, j, k = 0;
    double st = sqrt(1 - ct * ct), sum = 0;
    c->d = mf_ggx(ax, ay);
    c->wo = mf_vec3_make(st * cos(phi), st * sin(phi), ct);
    for (i = 0; i < NALB; ++i)
        for (j = 0; j < NALB; ++j) {
            mf_sample r = mf_brdf_sample(&c->d, c->wo, (i + 0.5) / NALB, (j + 0.5) / NALB);
            if (r.pdf > 0) sum += r.weight;
        }
    c->albedo = sum / (NALB * NALB);
    for (i = 0; i < NS; ++i)
        for (j = 0; j < NS; ++j, ++k) {
            mf_sample r = mf_brdf_sample(&c->d, c->wo, (i + 0.5) / NS, (j + 0.5) / NS);
            c->bw[k] = r.wi;
            c->bf[k] = r.pdf > 0 && r.wi.z > 0 ? mf_brdf(&c->d, c->wo, r.wi) * r.wi.z / c->albedo : 0;
            c->bp[k] = r.pdf > 0 ? r.pdf : 0;
        }
}

static void x_from_minv(const double *m, double *x)
{
    x[0] = m[0]; x[1] = m[1]; x[2] = m[2]; x[3] = m[5]; x[4] = m[6]; x[5] = m[7]; x[6] = m[8];
}

int main(int argc, char **argv)
{
    int nt = 10, np = 8, na = 10, nv = 6, ia, iv, it, ip, done = 0, total, k;
    double *tab, *prev_t, t0 = (double)clock();
    int module = argc > 1 && !strcmp(argv[1], "--module");
    fit_ctx *c = (fit_ctx *)malloc(sizeof(fit_ctx));
    if (argc > 5) { nt = atoi(argv[2]); np = atoi(argv[3]); na = atoi(argv[4]); nv = atoi(argv[5]); }
    if (nt < 2 || np < 2 || na < 2 || nv < 1 || !c) { fprintf(stderr, "bad size\n"); return 1; }
    total = nt * np * na * nv;
    tab = (double *)calloc((size_t)total * 8, sizeof(double));
    prev_t = (double *)calloc((size_t)np * nv * ND, sizeof(double));
    if (!tab || !prev_t) return 1;
    for (ia = na - 1; ia >= 0; --ia) {
        double ax = node_ax(ia, na);
        for (it = 0; it < nt; ++it) {
            double ct = node_ct(it, nt);
            for (ip = 0; ip < np; ++ip) {
                double phi = node_phi(ip, np), m[9], x[ND], xg[ND];
                mf__ltc_aniso_iso_node(ct, ax, cos(phi), sin(phi), m, 0);
                x_from_minv(m, x);
                for (iv = nv - 1; iv >= 0; --iv) {
                    double ay = ax * node_v(iv, nv), e1, e2, err, *o;
                    if (ay < 1e-3) ay = 1e-3;
                    setup(c, ct, phi, ax, ay);
                    if (it > 0) {   /* the better of the two starts */
                        memcpy(xg, prev_t + ((size_t)ip * nv + iv) * ND, sizeof xg);
                        e1 = fit_error(c, x); e2 = fit_error(c, xg);
                        if (e2 < e1) memcpy(x, xg, sizeof xg);
                    }
                    if (!(fit_error(c, x) < 1e30)) {   /* no valid start: the scaled diagonal */
                        memset(x, 0, sizeof x);
                        x[0] = sqrt(ay / ax); x[6] = sqrt(ax * ay);
                    }
                    nelder_mead(c, x, 0.1, 1500);
                    err = nelder_mead(c, x, 0.02, 1500);
                    x[0] = fabs(x[0]);
                    memcpy(prev_t + ((size_t)ip * nv + iv) * ND, x, sizeof x);
                    o = tab + 8 * ((((size_t)ia * nv + iv) * nt + it) * np + ip);
                    for (k = 0; k < ND; ++k) o[k] = x[k];
                    o[7] = c->albedo;
                    ++done;
                    if (!module || done % 50 == 0)
                        fprintf(stderr, "%d/%d ax %.3f ay %.4f ct %.3f phi %.2f err %.3g alb %.4f  x %.4g %.4g %.4g %.4g %.4g %.4g %.4g  %.0fs\n",
                                done, total, ax, ay, ct, phi, err, c->albedo, x[0], x[1], x[2], x[3], x[4], x[5], x[6],
                                ((double)clock() - t0) / CLOCKS_PER_SEC);
                }
            }
        }
    }
    if (module) {
        size_t n = (size_t)total * 8, i;
        printf("/* Generated by tools/ltc_fit_aniso.c (`make ltc-table-aniso`): do not edit. */\n");
        printf("/* ======================================================================== */\n");
        printf("/* == 14a. The built-in LTC table of anisotropic GGX                        */\n");
        printf("/* ======================================================================== */\n");
        printf("/* %d x %d x %d x %d LTC fits of the anisotropic GGX BRDF times cos(theta_i)\n", na, nv, nt, np);
        printf(" * (tools/ltc_fit_aniso.c: Nelder-Mead on the L3 error, as mf_ltc_fit),\n");
        printf(" * nodes sqrt(alpha_x) = ia / %d, sqrt(alpha_y / alpha_x) = iv / %d (the slice\n", na - 1, nv);
        printf(" * iv = %d is mf_ltc_ggx's table), sqrt(1 - cos theta_o) = it / %d, azimuth\n", nv, nt - 1);
        printf(" * (pi/2) ip / %d; eight IEEE binary16 values per entry: p q r t u v w of\n", np - 1);
        printf(" * M^-1 = [p q r; q s t; u v w], s = (1 + q^2) / p, and the albedo. Read\n");
        printf(" * through mf_ltc_ggx_aniso and mf_ltc_ggx_aniso_albedo (13_ltc_aniso.h). */\n");
        printf("/* @impl */\n#ifndef MF_NO_LTC_TABLE\n");
        printf("static const unsigned short *mf__ltc_ggx_aniso_data(int dims[4])\n{\n");
        printf("    static const unsigned short data[%d * %d * %d * %d * 8] = {\n", na, nv, nt, np);
        for (i = 0; i < n; ++i) {
            unsigned short h = mf__half_bits((float)tab[i]);
            printf("%u%s", (unsigned)h, i + 1 == n ? "\n" : (i % 24 == 23 ? ",\n" : ","));
        }
        printf("    };\n");
        printf("    dims[0] = %d; dims[1] = %d; dims[2] = %d; dims[3] = %d;\n", nt, np, na, nv);
        printf("    return data;\n}\n#endif\n");
    }
    fprintf(stderr, "done: %d entries, %.0f s\n", total, ((double)clock() - t0) / CLOCKS_PER_SEC);
    free(tab); free(prev_t); free(c);
    return 0;
}
