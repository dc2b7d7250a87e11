/* Linearly Transformed Cosines: normalization by quadrature over the sphere,
 * chi-square of mf_ltc_sample, polygon integrals against Monte Carlo
 * (triangles, quads, pentagons, a concave hexagon; partly and fully below the
 * horizon, one- and two-sided, tiny and huge lights), the analytic form factor
 * of a square, the vector form factor, sphere lights against quadrature, and
 * the multi-scale roughness fits (Tao Eq. 5, 7) against the integrals they
 * approximate.
 * Tolerances: normalization 1e-6 (double) / 1e-4 (float); polygon integrals
 * 1e-3 + 4 standard errors of the Monte Carlo estimate (4M samples); analytic
 * form factors 1e-9 (double) / 2e-5 (float) relative; sphere lights 2e-6
 * absolute; Eq. 5 within 0.05 of the alpha it inverts (measured 0.003); Eq. 7
 * within 0.2 of the alpha whose lobe has the convolution's mean length
 * (measured 0.16; Eq. 7 was fitted to the whole lobe). The built-in GGX
 * table against Monte Carlo of the true BRDF cos over quads near and beside
 * the mirror direction, 5 roughnesses x 4 view angles: mean relative error
 * below 0.06 (measured 0.046), max below 0.35 (measured 0.284 at theta_o = 81
 * degrees, where the LTC lobe spills below the true horizon). The RGBA16F
 * export in ltc_code's layout: every half at its published texel and channel
 * within half precision; the published shader's lookup on it (uv, linear
 * filtering, clamp to edge, its mat3) against the library's lookup within
 * 5e-3 on squares (measured 4.5e-4) and 1e-3 on albedo and Fresnel; the
 * sphere channel against quadrature (see MFT_SPHERE_EXCESS_TOL and
 * MFT_SPHERE_LOOKUP_TOL). */
#include "mf_test.h"
#include "quad.h"
#include "ref_other.h"
#include <stdlib.h>

static const double PI_D = 3.14159265358979323846;
#define MFT_LTC_MEAN_TOL 0.06  /* measured 0.046 */
#define MFT_LTC_MAX_TOL 0.35   /* measured 0.284, at theta_o = 81 deg */

static mf_ltc random_ltc(mft_rng *r, double spread)
{
    mf_real m[9];
    int i;
    for (i = 0; i < 9; ++i) m[i] = (mf_real)((i % 4 == 0 ? 1.0 : 0.0) + spread * (2 * mft_u01(r) - 1));
    return mf_ltc_from_matrix9(m);
}

/* integral over the sphere in (z, phi), which has uniform area */
static double sphere_integral(const mf_ltc *l)
{
    double gx[8], gw[8], sum = 0.0;
    int pz, pp, i, j;
    const int NZ = 200, NPH = 200;
    mft_gl(8, gx, gw);
    for (pz = 0; pz < NZ; ++pz)
        for (i = 0; i < 8; ++i) {
            double z = -1.0 + 2.0 * (pz + gx[i]) / NZ, s = sqrt(1.0 - z * z), row = 0.0;
            for (pp = 0; pp < NPH; ++pp)
                for (j = 0; j < 8; ++j) {
                    double phi = 2.0 * PI_D * (pp + gx[j]) / NPH;
                    row += gw[j] * (double)mf_ltc_eval(l, mf_vec3_make((mf_real)(s * cos(phi)), (mf_real)(s * sin(phi)), (mf_real)z));
                }
            sum += gw[i] * row * (2.0 * PI_D / NPH) * (2.0 / NZ);
        }
    return sum;
}

/* does the ray from the origin along w hit the planar polygon? sides: 1 = front only */
static int hits(const mf_vec3 *p, int n, mf_vec3 w, int two_sided)
{
    mf_vec3 nrm = mf_vec3_make(0, 0, 0), c = mf_vec3_make(0, 0, 0), x, u, v;
    double t, den, px, py;
    int i, j, inside = 0;
    for (i = 0; i < n; ++i) {   /* Newell normal */
        mf_vec3 a = p[i], b = p[(i + 1) % n];
        nrm.x += (a.y - b.y) * (a.z + b.z);
        nrm.y += (a.z - b.z) * (a.x + b.x);
        nrm.z += (a.x - b.x) * (a.y + b.y);
        c = mf_add(c, a);
    }
    c = mf_scale(c, (mf_real)(1.0 / n));
    den = (double)mf_dot(nrm, w);
    if (den == 0.0) return 0;
    t = (double)mf_dot(nrm, c) / den;
    if (t <= 0.0) return 0;
    if (!two_sided && mf_dot(nrm, c) >= 0) return 0;   /* back face: Newell normal points away from the origin */
    x = mf_scale(w, (mf_real)t);
    { mf_basis fr_ = mf_basis_from_normal(mf_normalize(nrm)); u = fr_.t; v = fr_.b; }
    px = mf_dot(x, u); py = mf_dot(x, v);
    for (i = 0, j = n - 1; i < n; j = i++) {   /* crossing number */
        double xi = mf_dot(p[i], u), yi = mf_dot(p[i], v), xj = mf_dot(p[j], u), yj = mf_dot(p[j], v);
        if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
}

static void polygon_case(const char *name, const mf_ltc *l, const mf_vec3 *p, int n, int two_sided, mft_rng *r)
{
    const int N = mft_full ? 4000000 : 500000;   /* the bound grows with se; exact values: test_polygon_exact */
    int i, k = 0;
    double est, se, got = mf_ltc_integrate(l, p, n, two_sided);
    char msg[160];
    for (i = 0; i < N; ++i) k += hits(p, n, mf_ltc_sample(l, (mf_real)mft_u01(r), (mf_real)mft_u01(r)), two_sided);
    est = (double)k / N;
    se = sqrt(est * (1 - est) / N);
    snprintf(msg, sizeof msg, "LTC polygon vs Monte Carlo: %s%s", name, two_sided ? " (two-sided)" : "");
    MFT_NEAR(got, est, 0.0, 1e-3 + 4 * se, msg);
}

/* differential area below the corner of a parallel a x b rectangle at height h */
static double ff_corner(double a, double b, double h)
{
    double x = a / h, y = b / h;
    return (x / sqrt(1 + x * x) * atan(y / sqrt(1 + x * x)) + y / sqrt(1 + y * y) * atan(x / sqrt(1 + y * y))) / (2 * PI_D);
}

static void square(mf_vec3 *p, double h, double half, double cx, double cy)
{
    /* counterclockwise seen from below: facing the origin when h > 0 */
    p[0] = mf_vec3_make((mf_real)(cx - half), (mf_real)(cy - half), (mf_real)h);
    p[1] = mf_vec3_make((mf_real)(cx - half), (mf_real)(cy + half), (mf_real)h);
    p[2] = mf_vec3_make((mf_real)(cx + half), (mf_real)(cy + half), (mf_real)h);
    p[3] = mf_vec3_make((mf_real)(cx + half), (mf_real)(cy - half), (mf_real)h);
}

static double ggx_mean_cos(double a)   /* mean resultant length of the LTC diag(a, a, 1) */
{
    double gx[8], gw[8], s = 0.0;
    int p, i;
    mf_ndf d = mf_ggx((mf_real)a, (mf_real)a);
    mft_gl(8, gx, gw);
    /* integral over theta of D cos^2 sin 2 pi, in the variable t = tan(theta) / a mapped to [0,1) */
    for (p = 0; p < 400; ++p)
        for (i = 0; i < 8; ++i) {
            double v = (p + gx[i]) / 400, t = a * v / (1 - v), dt = a / ((1 - v) * (1 - v));
            double th = atan(t), c = cos(th);
            mf_vec3 m = mf_vec3_make((mf_real)sin(th), 0, (mf_real)c);
            s += gw[i] / 400 * (double)mf_D(&d, m) * c * c * sin(th) * 2 * PI_D * dt / (1 + t * t);
        }
    return s;
}

static double invert_mean_cos(double b)
{
    double lo = 1e-4, hi = 1.0;
    int i;
    for (i = 0; i < 60; ++i) {
        double mid = 0.5 * (lo + hi);
        if (ggx_mean_cos(mid) > b) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static mf_real lambert_cos(mf_vec3 wo, mf_vec3 wi, void *ctx)
{
    (void)wo; (void)ctx;
    return wi.z > 0 ? wi.z * MF_INV_PI : MF_R(0.0);
}

static mf_real ggx_cos(mf_vec3 wo, mf_vec3 wi, void *ctx)
{
    return mf_brdf((const mf_ndf *)ctx, wo, wi) * mf_max(wi.z, MF_R(0.0));
}

/* integral of the true f cos over a polygon, by BRDF importance sampling */
static double brdf_polygon_mc(const mf_ndf *d, mf_vec3 wo, const mf_vec3 *p, int n, int N, mft_rng *r, double *se)
{
    double s = 0, s2 = 0;
    int i;
    for (i = 0; i < N; ++i) {
        mf_sample smp = mf_brdf_sample(d, wo, (mf_real)mft_u01(r), (mf_real)mft_u01(r));
        double w = 0;
        if (smp.lobe && hits(p, n, smp.wi, 1)) w = smp.weight;
        s += w; s2 += w * w;
    }
    *se = sqrt((s2 / N - (s / N) * (s / N)) / N);
    return s / N;
}

/* the built-in GGX table against Monte Carlo of the true BRDF cos over
 * polygons: relative error of the lobe's integral over each polygon */
static void test_ggx_table(mft_rng *r)
{
    const double cosv[] = { 0.95, 0.7, 0.4, 0.15 }, alphas[] = { 0.05, 0.13, 0.3, 0.6, 0.9 };
    double sum = 0, worst = 0;
    int a, c, k, count = 0;
    char msg[200];
    for (a = 0; a < 5; ++a)
        for (c = 0; c < 4; ++c)
            for (k = 0; k < 2; ++k) {
                mf_ndf d = mf_ggx((mf_real)alphas[a], (mf_real)alphas[a]);
                double ct = cosv[c], st = sqrt(1 - ct * ct), se, mc, ltc, rel;
                mf_vec3 wo = mf_vec3_make((mf_real)st, 0, (mf_real)ct), p[4], refl = mf_vec3_make((mf_real)-st, 0, (mf_real)ct);
                mf_ltc l = mf_ltc_ggx((mf_real)ct, (mf_real)alphas[a]);
                /* a quad around the mirror direction (k = 0) or beside it (k = 1), 2 units away */
                mf_vec3 cdir = k == 0 ? refl : mf_normalize(mf_vec3_make((mf_real)(-0.3 * st), 0.5f, (mf_real)ct)), u, v;
                double size = 0.3 + 1.2 * alphas[a];
                { mf_basis fr_ = mf_basis_from_normal(cdir); u = fr_.t; v = fr_.b; }
                p[0] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)-size), mf_scale(v, (mf_real)-size)));
                p[1] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)-size), mf_scale(v, (mf_real)size)));
                p[2] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)size), mf_scale(v, (mf_real)size)));
                p[3] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)size), mf_scale(v, (mf_real)-size)));
                mc = brdf_polygon_mc(&d, wo, p, 4, MFT_N(200000), r, &se);
                ltc = mf_ltc_ggx_albedo((mf_real)ct, (mf_real)alphas[a]) * mf_ltc_integrate(&l, p, 4, 1);
                if (mc < 0.02) continue;   /* relative error of a negligible integral says nothing */
                rel = fabs(ltc - mc) / mc;
                if (mft_verbose) printf("    alpha %.2f cos %.2f quad %d: ltc %.4f mc %.4f (se %.4f) rel %.3f\n", alphas[a], ct, k, ltc, mc, se, rel);
                sum += rel; ++count;
                if (rel > worst) worst = rel;
            }
    /* the albedo column at grid entries against Monte Carlo of the weights */
    {
        const int ents[6][2] = { { 20, 0 }, { 20, 20 }, { 30, 0 }, { 45, 40 }, { 63, 10 }, { 10, 55 } };
        double wa = 0;
        int e, i;
        for (e = 0; e < 6; ++e) {
            double v = ents[e][0] / 63.0, t = ents[e][1] / 63.0, al = v * v, ct = 1 - t * t, s1 = 0, s2 = 0, m, sd;
            mf_ndf d = mf_ggx((mf_real)al, (mf_real)al);
            mf_vec3 wo = mf_vec3_make((mf_real)sqrt(1 - ct * ct), 0, (mf_real)ct);
            const int nw = MFT_N(400000);
            for (i = 0; i < nw; ++i) {
                double w = (double)mf_brdf_sample(&d, wo, (mf_real)mft_u01(r), (mf_real)mft_u01(r)).weight;
                s1 += w; s2 += w * w;
            }
            m = s1 / nw; sd = sqrt((s2 / nw - m * m) / nw);
            if (fabs(mf_ltc_ggx_albedo((mf_real)ct, (mf_real)al) - m) - 4 * sd > wa) wa = fabs(mf_ltc_ggx_albedo((mf_real)ct, (mf_real)al) - m) - 4 * sd;
        }
        snprintf(msg, sizeof msg, "GGX table albedo vs Monte Carlo at grid entries (worst excess over 4 sigma %.4f)", wa);
        MFT_CHECK(wa < 2e-3, msg);
    }
    printf("    GGX table vs Monte Carlo of the BRDF over %d quads: mean relative error %.3f, max %.3f\n", count, sum / count, worst);
    snprintf(msg, sizeof msg, "GGX LTC table: mean relative error %.3f over %d quads", sum / count, count);
    MFT_CHECK(count > 20 && sum / count < MFT_LTC_MEAN_TOL, msg);
    snprintf(msg, sizeof msg, "GGX LTC table: max relative error %.3f", worst);
    MFT_CHECK(worst < MFT_LTC_MAX_TOL, msg);
}

/* The 4 x 4 table of the kind refitted at the shipped table's nodes 0, 21,
 * 42, 63 in both axes (test_ggx_table_data and test_ggx_refined share the GGX
 * one: fitted once); NULL when the fit fails. */
static mf_ltc_table refit_tab[2];
static int refit_state[2];   /* 0 not yet fitted, 1 fitted, -1 failed */
static const mf_ltc_table *refit_table(int kind)
{
    int b = kind == MF_NDF_BECKMANN;
    if (!refit_state[b])
        refit_state[b] = mf_ltc_table_build(&refit_tab[b], b ? mft_family_beckmann : mft_family_ggx, NULL, 4, 4, NULL, NULL) == MF_SUCCESS ? 1 : -1;
    return refit_state[b] > 0 ? &refit_tab[b] : NULL;
}
static void refit_release(void)
{
    int b;
    for (b = 0; b < 2; ++b) if (refit_state[b] > 0) mf_ltc_table_release(&refit_tab[b]);
    refit_state[0] = refit_state[1] = 0;
}

/* Compare the refitted 4 x 4 table with the shipped table s at its nodes:
 * *wm the worst matrix difference relative to the entry's largest matrix
 * element, *wa the worst albedo / Fresnel difference. 0 when the refit fails. */
static int refit_compare(int kind, const float *s, const char *name, double *wm, double *wa)
{
    const mf_ltc_table *t = refit_table(kind);
    int i, j, k;
    *wm = *wa = 0.0;
    if (!t) return 0;
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            const float *a = t->data + 6 * (j * 4 + i), *b = s + 6 * (21 * j * 64 + 21 * i);
            double scale = 0.0;
            for (k = 0; k < 4; ++k) scale = fabs(b[k]) > scale ? fabs(b[k]) : scale;
            for (k = 0; k < 4; ++k) {
                if (fabs(a[k] - b[k]) / scale > *wm) *wm = fabs(a[k] - b[k]) / scale;
                if (mft_verbose && fabs(a[k] - b[k]) / scale > 1e-3) printf("    %s refit node %d %d entry %d: %g vs %g\n", name, j, i, k, a[k], b[k]);
            }
            for (k = 4; k < 6; ++k) if (fabs(a[k] - b[k]) > *wa) *wa = fabs(a[k] - b[k]);
        }
    return 1;
}

/* The built-in table is data generated by tools/ltc_fit.c (make ltc-table):
 * refit a 4 x 4 table whose nodes are the shipped table's nodes 0, 21, 42, 63
 * in both axes and compare; check the raw accessor against the lookup at the
 * nodes; check the albedo and Fresnel columns against quadrature of
 * mf_brdf cos and mf_brdf cos (1 - wo.h)^5 over the hemisphere. */
static void test_ggx_table_data(void)
{
    int n = 0, na = 0, i, j, k;
    const float *s = mf_ltc_ggx_table(&n, &na);
    double wm = 0.0, wa = 0.0, wacc = 0.0, wf = 0.0;
    char msg[200];
    MFT_CHECK(s != NULL && n == 64 && na == 64, "mf_ltc_ggx_table: 64 x 64 entries");
    if (!s || n != 64) return;
    MFT_CHECK(refit_compare(MF_NDF_GGX, s, "GGX", &wm, &wa), "refit 4 x 4 GGX table");
    /* the matrices are the fit refined on polygons (tools/ltc_fit.c; checked
     * in test_ggx_refined): only the albedo and Fresnel columns must match */
    if (mft_verbose) printf("    shipped GGX matrices vs the plain refit: %.2g of their scale\n", wm);
    snprintf(msg, sizeof msg, "refitted albedo and Fresnel columns match the shipped table (%.2g)", wa);
    MFT_CHECK(wa < MFT_TOL(1e-5, 1e-3), msg);
    for (j = 0; j < 64; j += 9)
        for (i = 0; i < 64; i += 7) {
            double tt = i / 63.0, v = j / 63.0, ct = 1.0 - tt * tt, al = v * v;
            mf_real alb, fr;
            const float *e = s + 6 * (j * 64 + i);
            mf_ltc l;
            if (ct < 1e-3 || al < 1e-3) continue;   /* the clamped ends */
            l = mf_ltc_from_inverse((mf_real)e[0], (mf_real)e[1], MF_R(1.0), (mf_real)e[2], (mf_real)e[3]);
            alb = mf_ltc_ggx_albedo((mf_real)ct, (mf_real)al);
            fr = mf_ltc_ggx_fresnel((mf_real)ct, (mf_real)al);
            /* M^-1 up to scale (the lookup rescales it): both over their (2,2) entry */
            {
                mf_ltc g = mf_ltc_ggx((mf_real)ct, (mf_real)al);
                for (k = 0; k < 9; ++k) {
                    double dk = fabs((double)l.Minv[k] / (double)l.Minv[8] - (double)g.Minv[k] / (double)g.Minv[8]);
                    if (dk / (fabs((double)l.Minv[k] / (double)l.Minv[8]) + 1.0) > wacc)
                        wacc = dk / (fabs((double)l.Minv[k] / (double)l.Minv[8]) + 1.0);
                }
            }
            if (fabs((double)alb - e[4]) > wacc) wacc = fabs((double)alb - e[4]);
            if (fabs((double)fr - e[5]) > wacc) wacc = fabs((double)fr - e[5]);
        }
    /* float: the node coordinate sqrt(1 - cos) 63 is off by an ulp or so, which
     * blends in a neighbour by that fraction */
    snprintf(msg, sizeof msg, "raw table entries = lookups at the nodes (matrix, albedo, fresnel; worst %.2g)", wacc);
    MFT_CHECK(wacc < MFT_TOL(1e-5, 2e-3), msg);
    /* albedo and Fresnel columns against a midpoint rule in (cos theta_i, phi) */
    for (j = 21; j < 64; j += 21)
        for (i = 0; i < 63; i += 21) {
            double tt = i / 63.0, v = j / 63.0, ct = 1.0 - tt * tt, al = v * v, alb = 0.0, fr = 0.0;
            int N = 400, p, q;
            mf_ndf d = mf_ggx((mf_real)al, (mf_real)al);
            mf_vec3 wo = mf_vec3_make((mf_real)sqrt(1.0 - ct * ct), 0, (mf_real)ct);
            const float *e = s + 6 * (j * 64 + i);
            for (p = 0; p < N; ++p)
                for (q = 0; q < N; ++q) {
                    double c = (p + 0.5) / N, ph = 2.0 * PI_D * (q + 0.5) / N, sn = sqrt(1.0 - c * c), f, h;
                    mf_vec3 wi = mf_vec3_make((mf_real)(sn * cos(ph)), (mf_real)(sn * sin(ph)), (mf_real)c);
                    mf_vec3 hv = mf_normalize(mf_add(wo, wi));
                    f = (double)mf_brdf(&d, wo, wi) * c * (2.0 * PI_D / N) / N;
                    h = 1.0 - (double)mf_dot(wo, hv);
                    alb += f; fr += f * h * h * h * h * h;
                }
            if (fabs(alb - e[4]) > wf) wf = fabs(alb - e[4]);
            if (fabs(fr - e[5]) > wf) wf = fabs(fr - e[5]);
        }
    snprintf(msg, sizeof msg, "albedo and Fresnel columns vs quadrature of the BRDF (worst %.2g)", wf);
    MFT_CHECK(wf < 5e-3, msg);
}

static void test_fitter(void)
{
    mf_ltc_fit_result r;
    mf_ltc_table t;
    mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
    mf_vec3 wo = mf_vec3_make(MF_R(0.6), 0, MF_R(0.8)), w;
    double worst = 0;
    int i;
    /* a Lambertian callback fits the clamped cosine itself, albedo 1 */
    MFT_CHECK(mf_ltc_fit(&r, NULL, lambert_cos, NULL, MF_R(0.8), NULL) == MF_SUCCESS, "fit a user BRDF callback");
    MFT_NEAR(r.albedo, 1.0, 1e-3, 0, "Lambertian albedo 1");
    for (i = 0; i < 50; ++i) {
        w = mft_dir(1.5 * i / 50.0, 0.3 * i);
        if (fabs((double)mf_ltc_eval(&r.ltc, w) - w.z / PI_D) > worst) worst = fabs((double)mf_ltc_eval(&r.ltc, w) - w.z / PI_D);
    }
    MFT_CHECK(worst < 0.02, "Lambertian fit is the clamped cosine");
    /* the callback form of GGX and the mf_ndf form agree */
    {
        mf_ltc_fit_result a, b;
        mf_vec3 q[4];
        square(q, 1.0, 0.6, -0.8, 0.0);
        mf_ltc_fit(&a, &d, NULL, NULL, wo.z, NULL);
        mf_ltc_fit(&b, NULL, ggx_cos, &d, wo.z, NULL);
        MFT_NEAR(a.albedo, b.albedo, 0.02, 0, "GGX albedo: BRDF sampling vs cosine sampling");
        MFT_NEAR(mf_ltc_integrate(&a.ltc, q, 4, 1), mf_ltc_integrate(&b.ltc, q, 4, 1), 0.05, 0.01, "GGX fit: callback vs mf_ndf");
    }
    /* bad input, and a small Beckmann table (the 4 x 4 refit: refit_compare) */
    MFT_CHECK(mf_ltc_fit(&r, NULL, NULL, NULL, MF_R(0.5), NULL) == MF_ERROR_INVALID_ARGUMENT, "fit without a BRDF rejected");
    MFT_CHECK(mf_ltc_fit(&r, &d, NULL, NULL, MF_R(0.0), NULL) == MF_ERROR_INVALID_ARGUMENT, "fit at cos 0 rejected");
    MFT_CHECK(mf_ltc_table_build(&t, mft_family_beckmann, NULL, 1, 4, NULL, NULL) == MF_ERROR_INVALID_ARGUMENT && t.data == NULL,
              "table of 1 column rejected, nothing allocated");
    MFT_CHECK(mf_ltc_table_build(&t, mft_family_beckmann, NULL, 2, 2, NULL, NULL) == MF_SUCCESS, "Beckmann 2 x 2 table");
    {
        mf_real alb;
        mf_ltc l = mf_ltc_table_lookup(&t, MF_R(0.8), MF_R(0.3), &alb, NULL);
        MFT_CHECK(mft_finite(alb) && alb > 0 && alb <= 1.001 && mft_finite(mf_ltc_eval(&l, wo)), "table lookup finite");
    }
    mf_ltc_table_release(&t);
    MFT_CHECK(t.data == NULL, "table released");
}



/* a square of half-size h at unit distance around direction c */
static void square_at(mf_vec3 *p, mf_vec3 c, double h)
{
    mf_vec3 u, v;
    { mf_basis fr_ = mf_basis_from_normal(c); u = fr_.t; v = fr_.b; }
    p[0] = mf_add(c, mf_add(mf_scale(u, (mf_real)-h), mf_scale(v, (mf_real)-h)));
    p[1] = mf_add(c, mf_add(mf_scale(u, (mf_real)-h), mf_scale(v, (mf_real)h)));
    p[2] = mf_add(c, mf_add(mf_scale(u, (mf_real)h), mf_scale(v, (mf_real)h)));
    p[3] = mf_add(c, mf_add(mf_scale(u, (mf_real)h), mf_scale(v, (mf_real)-h)));
}

/* Off-node accuracy of a table between rows of small alpha (0.003 to 0.04,
 * where the matrix entries grow like 1 / alpha), on the built-in Beckmann
 * table (plain mf_ltc_table_build fits; the GGX entries are refined beyond
 * the direct fit): the integral of the looked-up LTC over squares around and
 * beside the mirror direction (0.5 to 4 lobe widths) against that of a
 * direct fit at the same (cos, alpha), and the same at the nodes. Blending
 * the stored form (middle entry 1) keeps the off-node error near the on-node
 * one; blending the form with a last entry of 1 (reimplemented here) is
 * shown for comparison. */
static void test_off_node(void)
{
    const int rows[] = { 3, 5, 7, 9, 11 }, cols[] = { 4, 20, 36, 50 };
    int n, na, ri, ci, q, half, cnt[2] = { 0, 0 };
    const float *t = mf_ltc_beckmann_table(&n, &na);
    double sum[2] = { 0, 0 }, mx[2] = { 0, 0 }, sum_old = 0, mx_old = 0;
    char msg[200];
    for (half = 0; half < 2; ++half)
        for (ri = 0; ri < 5; ++ri)
            for (ci = 0; ci < 4; ++ci) {
                if (!mft_full && ((ri & 1) || (ci & 1))) continue;   /* make test: 6 of the 20 cells */
                double v = (rows[ri] + 0.5 * half) / 63.0, tt = (cols[ci] + 0.5 * half) / 63.0, al = v * v, ct = 1 - tt * tt;
                double st = sqrt(1 - ct * ct);
                mf_ltc_fit_result fr;
                mf_ndf d = mf_beckmann((mf_real)al, (mf_real)al);
                mf_ltc l = mf_ltc_beckmann((mf_real)ct, (mf_real)al), lo;
                mf_ltc_fit(&fr, &d, NULL, NULL, (mf_real)ct, NULL);
                {   /* the old blend: entries over the last one, i.e. [a/d3 0 b/d3; 0 1/d3 0; c/d3 0 1] */
                    int ix = cols[ci], iy = rows[ri], k, c2;
                    double fx = 0.5 * half, fy = 0.5 * half, w[4], o[5] = { 0, 0, 0, 0, 0 };
                    const float *e[4];
                    e[0] = t + 6 * (iy * 64 + ix); e[1] = e[0] + 6; e[2] = e[0] + 6 * 64; e[3] = e[2] + 6;
                    w[0] = (1 - fx) * (1 - fy); w[1] = fx * (1 - fy); w[2] = (1 - fx) * fy; w[3] = fx * fy;
                    for (c2 = 0; c2 < 4; ++c2) {
                        double r3 = 1.0 / e[c2][3];
                        o[0] += w[c2] * e[c2][0] * r3; o[1] += w[c2] * e[c2][1] * r3;
                        o[2] += w[c2] * r3; o[3] += w[c2] * e[c2][2] * r3; o[4] += w[c2];
                    }
                    lo = mf_ltc_from_inverse((mf_real)o[0], (mf_real)o[1], (mf_real)o[2], (mf_real)o[3], (mf_real)o[4]);
                    (void)k;
                }
                for (q = 0; q < 6; ++q) {
                    double h = (q % 3 == 0 ? 0.5 : q % 3 == 1 ? 1.5 : 4.0) * al, off = q < 3 ? 0.0 : 1.5 * al, ref, e1;
                    mf_vec3 p[4];
                    square_at(p, mf_normalize(mf_vec3_make((mf_real)-st, (mf_real)off, (mf_real)ct)), h);
                    ref = mf_ltc_integrate(&fr.ltc, p, 4, 1);
                    if (ref < 1e-3) continue;
                    e1 = fabs(mf_ltc_integrate(&l, p, 4, 1) - ref) / ref;
                    sum[half] += e1; cnt[half]++;
                    if (e1 > mx[half]) mx[half] = e1;
                    if (half) {
                        double e0 = fabs(mf_ltc_integrate(&lo, p, 4, 1) - ref) / ref;
                        sum_old += e0;
                        if (e0 > mx_old) mx_old = e0;
                    }
                }
            }
    printf("    Beckmann table vs direct fits, alpha 0.003-0.04: on-node mean %.4f max %.4f (%d squares); off-node mean %.4f max %.4f"
           " (blending the last-entry-1 form: mean %.4f max %.4f)\n", sum[0] / cnt[0], mx[0], cnt[0], sum[1] / cnt[1], mx[1],
           sum_old / cnt[1], mx_old);
    snprintf(msg, sizeof msg, "off-node LTC lookup vs direct fit: mean %.4f (on-node %.4f), max %.4f", sum[1] / cnt[1], sum[0] / cnt[0], mx[1]);
    MFT_CHECK(cnt[1] > (mft_full ? 60 : 18) && sum[1] / cnt[1] < 0.01 && mx[1] < 0.06, msg);
}

/* The edge integral (theta / sin theta) (a x b) of unit vectors a, b in long
 * double from the stored (rounded) components: the products of two floats or
 * doubles lose at most 2^-64 of their size, atan2l takes the angle. */
static void edge_exact(mf_vec3 a, mf_vec3 b, long double *out)
{
    long double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
    long double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    long double s = sqrtl(cx * cx + cy * cy + cz * cz), d = ax * bx + ay * by + az * bz, th = atan2l(s, d);
    out[0] = cx * th / s; out[1] = cy * th / s; out[2] = cz * th / s; out[3] = th;
}

/* a unit vector at angle t from a (unit), towards a random perpendicular */
static mf_vec3 at_angle(mf_vec3 a, double t, mft_rng *r)
{
    mf_vec3 u, v;
    double p = 2 * PI_D * mft_u01(r);
    { mf_basis fr_ = mf_basis_from_normal(a); u = fr_.t; v = fr_.b; }
    return mf_normalize(mf_add(mf_scale(a, (mf_real)cos(t)), mf_add(mf_scale(u, (mf_real)(sin(t) * cos(p))), mf_scale(v, (mf_real)(sin(t) * sin(p))))));
}

/* The fast edge (rational theta / sin theta, exact differences) and the edge
 * used by the polygon integrator against the long double edge, relative to
 * the edge's length theta: random edges, nearly antipodal ones (pi - theta
 * from 1e-6 to 0.3) and short ones (1e-7 to 1e-2); and the fast edge of this
 * precision against the other precision's on the same (float) vectors.
 * Tolerance 1e-5 (the rational fit alone is 5.6e-7); with MF_USE_DOUBLE the
 * integrator uses the exact atan2 edge, held to 1e-8. */
static void test_fast_edge(mft_rng *r)
{
    double worst[3] = { 0, 0, 0 }, worst_z = 0, agree = 0;
    const char *sets[3] = { "random", "nearly antipodal", "short" };
    char msg[200];
    int set, i;
    for (set = 0; set < 3; ++set)
        for (i = 0; i < 20000; ++i) {
            mf_vec3 a = mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r)), b, e;
            long double x[4];
            double err, ez, t;
            a = mf_normalize(a);
            if (set == 0) b = mf_normalize(mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r)));
            else if (set == 1) { t = PI_D - exp(log(1e-6) + (log(0.3) - log(1e-6)) * mft_u01(r)); b = at_angle(a, t, r); }
            else { t = exp(log(1e-7) + (log(1e-2) - log(1e-7)) * mft_u01(r)); b = at_angle(a, t, r); }
            edge_exact(a, b, x);
            if (!(x[3] > 0) || !(x[3] < 3.1415926535)) continue;   /* rounded onto the same or the opposite point */
            e = mf__edge_vector_fast(a, b);
            err = sqrt((double)((e.x - x[0]) * (e.x - x[0]) + (e.y - x[1]) * (e.y - x[1]) + (e.z - x[2]) * (e.z - x[2]))) / (double)x[3];
            ez = fabs((double)mf__edge_z(a, b) - (double)x[2]) / (double)x[3];
            if (err > worst[set]) worst[set] = err;
            if (ez > worst_z) worst_z = ez;
            {   /* the same float-representable input in both precisions */
                volatile float fa[6];
                double da[3], db[3], o[3], g;
                fa[0] = (float)a.x; fa[1] = (float)a.y; fa[2] = (float)a.z; fa[3] = (float)b.x; fa[4] = (float)b.y; fa[5] = (float)b.z;
                da[0] = fa[0]; da[1] = fa[1]; da[2] = fa[2]; db[0] = fa[3]; db[1] = fa[4]; db[2] = fa[5];
                mf_vec3 f = mf__edge_vector_fast(mf_vec3_make((mf_real)da[0], (mf_real)da[1], (mf_real)da[2]),
                                                 mf_vec3_make((mf_real)db[0], (mf_real)db[1], (mf_real)db[2]));
                ref_ltc_edge_fast(da, db, o);
                g = sqrt((o[0] - f.x) * (o[0] - f.x) + (o[1] - f.y) * (o[1] - f.y) + (o[2] - f.z) * (o[2] - f.z)) / (double)x[3];
                if (g > agree) agree = g;
            }
        }
    for (set = 0; set < 3; ++set) {
        snprintf(msg, sizeof msg, "fast LTC edge vs long double, %s edges: worst %.2g of theta", sets[set], worst[set]);
        MFT_CHECK(worst[set] < MFT_TOL(1e-6, 1e-5), msg);
        if (mft_verbose) printf("    %s\n", msg);
    }
    snprintf(msg, sizeof msg, "polygon edge (z) vs long double: worst %.2g of theta", worst_z);
    MFT_CHECK(worst_z < MFT_TOL(1e-8, 1e-5), msg);
    snprintf(msg, sizeof msg, "fast LTC edge: float and double agree (worst %.2g of theta)", agree);
    MFT_CHECK(agree < 1e-5, msg);
    printf("    fast edge vs long double: random %.2g, nearly antipodal %.2g, short %.2g; polygon edge %.2g; float vs double %.2g\n",
           worst[0], worst[1], worst[2], worst_z, agree);
}


/* Reference for the polygon integrator: the float vertices transformed by
 * the float matrix, clipped at z = 0 (Sutherland-Hodgman) and summed with
 * the exact edge, all in long double. Returns the signed sum (2 pi times the
 * form factor, the integrator's convention) and in *S the sum of the edge
 * lengths theta (the scale of the fast edge's error, as in test_fast_edge). */
static long double ref_polygon_sum(const mf_real *A, const mf_vec3 *p, int n, long double *S)
{
    long double v[48][3], c[96][3], sum = 0, x[4];
    int i, m = 0;
    for (i = 0; i < n; ++i) {
        long double px = p[i].x, py = p[i].y, pz = p[i].z;
        if (A) {
            v[i][0] = (long double)A[0] * px + (long double)A[1] * py + (long double)A[2] * pz;
            v[i][1] = (long double)A[3] * px + (long double)A[4] * py + (long double)A[5] * pz;
            v[i][2] = (long double)A[6] * px + (long double)A[7] * py + (long double)A[8] * pz;
        } else { v[i][0] = px; v[i][1] = py; v[i][2] = pz; }
    }
    for (i = 0; i < n; ++i) {
        const long double *a = v[i], *b = v[(i + 1) % n];
        if (a[2] > 0) { c[m][0] = a[0]; c[m][1] = a[1]; c[m][2] = a[2]; ++m; }
        if ((a[2] > 0) != (b[2] > 0)) {
            long double t = a[2] / (a[2] - b[2]);
            c[m][0] = a[0] + t * (b[0] - a[0]); c[m][1] = a[1] + t * (b[1] - a[1]); c[m][2] = 0; ++m;
        }
    }
    *S = 0;
    for (i = 0; i < m; ++i) {
        long double la = sqrtl(c[i][0] * c[i][0] + c[i][1] * c[i][1] + c[i][2] * c[i][2]);
        c[i][0] /= la; c[i][1] /= la; c[i][2] /= la;
    }
    for (i = 0; i < m; ++i) {
        const long double *a = c[i], *b = c[(i + 1) % m];
        long double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
        long double sn = sqrtl(cx * cx + cy * cy + cz * cz), d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        x[1] = atan2l(sn, d);
        x[0] = sn > 0 ? cz * x[1] / sn : 0;
        sum += x[0];
        *S += x[1];
    }
    return sum;
}

/* The polygon integrator (quads straight and clipped by each pattern of
 * vertices above the horizon, two-run quads, n-gons, vertices exactly on
 * the horizon; sizes 1e-3 to 1e4 at unit distance, so nearly antipodal edges
 * too) against the long double reference, through identity, sparse (table)
 * and full matrices: error relative to the result where the result is at
 * least 10% of the perimeter (the sum of the edge lengths), and relative to
 * the perimeter everywhere.
 * Tolerance 1e-5 (float: the fast edge) / 1e-10 (double: the exact edge). */
static void test_polygon_exact(mft_rng *r)
{
    double worst_rel = 0, worst_s = 0, worst_tiny = 0, rel_at = 0;
    int i, k, n, cfgs[16] = { 0 }, ncfg = 0, nrel = 0, nzero = 0, bad_zero = 0;
    char msg[240];
    for (i = 0; i < 30000; ++i) {
        mf_vec3 p[40], nrm, u, v, c;
        mf_ltc l;
        const mf_real *A;
        long double ref, S;
        double got, e, size = exp(log(1e-3) + (log(1e4) - log(1e-3)) * mft_u01(r));
        int kind = i % 4, shape = (i / 4) % 4, cfg = 0;
        if (kind == 0) A = 0;
        else {
            if (kind == 1) l = mf_ltc_ggx((mf_real)mft_u01(r), (mf_real)mft_u01(r));
            else if (kind == 2) l = random_ltc(r, 0.5);
            else l = mf_ltc_from_inverse((mf_real)(0.2 + 2 * mft_u01(r)), (mf_real)(mft_u01(r) - 0.5), (mf_real)(0.2 + 2 * mft_u01(r)),
                                         (mf_real)(mft_u01(r) - 0.5), (mf_real)(0.2 + 2 * mft_u01(r)));
            A = l.Minv;
        }
        n = shape == 3 ? 5 + (int)(35 * mft_u01(r)) : 4;
        c = mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r));
        if (shape == 2) {   /* four random points: non-planar, non-convex, two runs */
            for (k = 0; k < 4; ++k)
                p[k] = mf_scale(mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r)), (mf_real)(0.5 + mft_u01(r)));
        } else {           /* convex, planar: a rectangle or a regular n-gon in a random plane */
            nrm = mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r));
            { mf_basis fr_ = mf_basis_from_normal(nrm); u = fr_.t; v = fr_.b; }
            for (k = 0; k < n; ++k) {
                double a = 2 * PI_D * k / n, w = shape == 0 ? 1.0 : 0.5 + mft_u01(r);
                p[k] = mf_add(c, mf_add(mf_scale(u, (mf_real)(size * cos(a))), mf_scale(v, (mf_real)(size * w * sin(a)))));
            }
            if (shape == 1 && kind == 0) p[(int)(4 * mft_u01(r)) & 3].z = 0;   /* a vertex on the horizon */
        }
        if (n == 4) {
            for (k = 0; k < 4; ++k) {
                mf_vec3 t = A ? mf__mat3_apply(A, p[k]) : p[k];
                cfg |= (t.z > 0) << k;
            }
            if (!cfgs[cfg]++) ++ncfg;
        }
        ref = ref_polygon_sum(A, p, n, &S);
        got = (double)mf__polygon_sum(A, p, n);
        if (!(S > 0)) { ++nzero; if (got != 0) ++bad_zero; continue; }
        e = fabs(got - (double)ref);
        if (size < 0.05) { if (e / (double)S > worst_tiny) worst_tiny = e / (double)S; }
        else if (e / (double)S > worst_s) worst_s = e / (double)S;
        if (fabsl(ref) >= 0.1L * S) {
            ++nrel;
            if (e / fabs((double)ref) > worst_rel) { worst_rel = e / fabs((double)ref); rel_at = size; }
        }
    }
    snprintf(msg, sizeof msg, "polygons vs long double clipping and edges: worst %.2g relative (%d cases; at size %.3g), %.2g of the perimeter (sizes >= 0.05), %.2g (tiny lights); %d of 16 quad sign patterns",
             worst_rel, nrel, rel_at, worst_s, worst_tiny, ncfg);
    MFT_CHECK(worst_rel < MFT_TOL(1e-10, 1e-5) && worst_s < MFT_TOL(1e-10, 1e-5) && worst_tiny < MFT_TOL(1e-10, 1e-5) && ncfg == 16, msg);
    printf("    %s\n", msg);
    snprintf(msg, sizeof msg, "polygons entirely below the horizon: 0 (%d of %d wrong)", bad_zero, nzero);
    MFT_CHECK(bad_zero == 0 && nzero > 0, msg);
}

/* Form-factor accuracy of n-gons (n = 3..32) in random planes and random
 * LTC matrices (table, random 3x3, sparse inverse, identity), crossing the
 * horizon or not, one in five of random points within 0.9 of the center
 * (non-convex, several runs above the horizon; farther, an edge passes
 * arbitrarily near the shading point and the rounding of its vertices moves
 * its plane by more than K counts), at sizes 0.02 to 20 at unit distance: against the long
 * double reference, relative error where the form factor |ref| / 2 pi is at
 * least 0.01, and its bound in the condition number K = (sum of the edge
 * lengths theta) / |ref|: the fast edge errs by up to 5.6e-7 theta per edge
 * (the fit) plus rounding, so float holds error <= 1e-6 K, and 1e-5 where
 * K <= 10; double (the exact edge) 1e-12 K and 1e-9 relative. */
static void test_polygon_form_factor(mft_rng *r)
{
    double worst[2] = { 0, 0 }, kap[2] = { 0, 0 }, nat[2] = { 0, 0 }, per_k = 0, kmax = 0, worst10 = 0;
    int i, k, cnt[2] = { 0, 0 }, cnt10 = 0, total = MFT_N(40000);
    char msg[300];
    for (i = 0; i < total; ++i) {
        mf_vec3 p[32], c, u, v, nrm;
        mf_ltc l;
        const mf_real *A = 0;
        long double ref, S;
        double got, e, kappa, size = exp(log(0.02) + (log(20.0) - log(0.02)) * mft_u01(r)), w = 0.3 + 1.4 * mft_u01(r);
        int n = 3 + (int)(30 * mft_u01(r)), kind = i % 4, clipped = 0;
        if (n > 32) n = 32;
        if (kind == 0) { l = mf_ltc_ggx((mf_real)mft_u01(r), (mf_real)mft_u01(r)); A = l.Minv; }
        else if (kind == 1) { l = random_ltc(r, 0.5); A = l.Minv; }
        else if (kind == 2) {
            l = mf_ltc_from_inverse((mf_real)(0.2 + 2 * mft_u01(r)), (mf_real)(mft_u01(r) - 0.5), (mf_real)(0.2 + 2 * mft_u01(r)),
                                    (mf_real)(mft_u01(r) - 0.5), (mf_real)(0.2 + 2 * mft_u01(r)));
            A = l.Minv;
        }
        c = mft_dir(acos(mft_u01(r) * 1.1 - 0.1), 2 * PI_D * mft_u01(r));
        nrm = mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r));
        { mf_basis fr_ = mf_basis_from_normal(nrm); u = fr_.t; v = fr_.b; }
        for (k = 0; k < n; ++k) {
            double a = 2 * PI_D * (k + 0.25) / n;
            if (i % 5 == 4)   /* random points: non-planar, non-convex, several runs above the horizon */
                p[k] = mf_add(c, mf_scale(mft_dir(acos(2 * mft_u01(r) - 1), 2 * PI_D * mft_u01(r)), (mf_real)((size < 0.9 ? size : 0.9) * mft_u01(r))));
            else p[k] = mf_add(c, mf_add(mf_scale(u, (mf_real)(size * cos(a))), mf_scale(v, (mf_real)(size * w * sin(a)))));
            if (!((A ? mf__mat3_apply(A, p[k]) : p[k]).z > 0)) clipped = 1;
        }
        ref = ref_polygon_sum(A, p, n, &S);
        if (!(fabsl(ref) >= 0.02L * PI_D)) continue;
        got = (double)mf__polygon_sum(A, p, n);
        e = fabs(got - (double)ref) / fabs((double)ref);
        kappa = (double)(S / fabsl(ref));
        ++cnt[clipped];
        if (e > worst[clipped]) { worst[clipped] = e; kap[clipped] = kappa; nat[clipped] = n; }
        if (kappa > kmax) kmax = kappa;
        if (e / kappa > per_k) per_k = e / kappa;
        if (kappa <= 10) { ++cnt10; if (e > worst10) worst10 = e; }
    }
    snprintf(msg, sizeof msg, "n-gons 3..32, form factor >= 0.01: worst %.2g relative unclipped (%d; n = %.0f, K = %.3g), %.2g clipped (%d; n = %.0f, K = %.3g); error / K at most %.2g (K up to %.3g); %.2g where K <= 10 (%d)",
             worst[0], cnt[0], nat[0], kap[0], worst[1], cnt[1], nat[1], kap[1], per_k, kmax, worst10, cnt10);
    MFT_CHECK(per_k < MFT_TOL(1e-12, 1e-6) && worst10 < MFT_TOL(1e-9, 1e-5) && worst[0] < MFT_TOL(1e-9, 1e-4) && worst[1] < MFT_TOL(1e-9, 1e-4)
              && cnt[0] > total / 20 && cnt[1] > total / 20 && cnt10 > total / 20, msg);
    printf("    %s\n", msg);
}

/* binary16 bits to double (independent of the encoder) */
static double half_value(unsigned short h)
{
    int e = (h >> 10) & 31, m = h & 1023;
    double v = e == 0 ? ldexp((double)m, -24) : ldexp(1.0 + m / 1024.0, e - 15);
    return (h & 0x8000) ? -v : v;
}

/* The published shaders' texture access (ltc_code, webgl/shaders/ltc/ltc_quad.fs and others),
 * emulated in double: a w x h RGBA texture stored row by row, first row at
 * v = 0, GL linear filtering (texel centres at ((j + 0.5) / w, (i + 0.5) / h))
 * with clamp to edge, at uv = value * LUT_SCALE + LUT_BIAS per axis,
 * LUT_SCALE = (n - 1) / n, LUT_BIAS = 0.5 / n. */
static double lut_coord(double value, int n) { return value * (n - 1.0) / n + 0.5 / n; }
static void tex_linear(const unsigned short *tex, int w, int h, double u, double v, double *out)
{
    double x = u * w - 0.5, y = v * h - 0.5, fx, fy;
    int x0 = (int)floor(x), y0 = (int)floor(y), x1, y1, c;
    fx = x - x0; fy = y - y0;
    x1 = x0 + 1; y1 = y0 + 1;
    x0 = x0 < 0 ? 0 : x0 > w - 1 ? w - 1 : x0; x1 = x1 < 0 ? 0 : x1 > w - 1 ? w - 1 : x1;
    y0 = y0 < 0 ? 0 : y0 > h - 1 ? h - 1 : y0; y1 = y1 < 0 ? 0 : y1 > h - 1 ? h - 1 : y1;
    for (c = 0; c < 4; ++c)
        out[c] = (1 - fy) * ((1 - fx) * half_value(tex[4 * (y0 * w + x0) + c]) + fx * half_value(tex[4 * (y0 * w + x1) + c])) +
                 fy * ((1 - fx) * half_value(tex[4 * (y1 * w + x0) + c]) + fx * half_value(tex[4 * (y1 * w + x1) + c]));
}

/* The exported half holding channel k (inv0 inv1 inv2 inv3 albedo fresnel) of
 * table entry e ([alpha][theta], nt x na), as documented: texel (column
 * alpha, row theta), ltc_1 = (inv0, inv2, inv1, inv3), ltc_2 = (albedo,
 * fresnel, 0, sphere). */
static double exported_entry(const unsigned short *t1, const unsigned short *t2, int nt, int na, int e, int k)
{
    static const int ch[4] = { 0, 2, 1, 3 };
    int texel = (e % nt) * na + e / nt;
    return k < 4 ? half_value(t1[4 * texel + ch[k]]) : half_value(t2[4 * texel + k - 4]);
}

/* Cosine form factor of a uniform sphere light clipped at the horizon,
 * divided by |F| = len = sin^2 sigma, its centre at cos omega = z, by
 * quadrature in double (independent of the library's closed form): in the
 * cap's own polar angle t, each ring integrates max(0, a + b cos p) over p
 * in closed form (a = cos t cos omega, b = sin t sin omega); the ring touches
 * the horizon at t = |pi/2 - omega|, where the integrand has a (t - t_k)^1.5
 * kink: the t-integral is split there and each side substituted
 * t = t_k -+ s^2 (smooth in s), 4 panels x 16-point Gauss-Legendre (16
 * panels agree to 2e-15). len = 0: the limit max(z, 0). */
static double sphere_ring(double t, double om)
{
    double a = cos(t) * cos(om), b = sin(t) * sin(om), p0;
    if (b <= fabs(a)) return a > 0 ? 2 * PI_D * a : 0.0;
    p0 = acos(-a / b);
    return 2 * (a * p0 + sqrt(b * b - a * a));
}
static double sphere_piece(double t0, double sgn, double len_t, double om)
{
    double gx[16], gw[16], sum = 0.0, S = sqrt(len_t);
    int p, i;
    mft_gl(16, gx, gw);
    for (p = 0; p < 4; ++p)
        for (i = 0; i < 16; ++i) {
            double sv = S * (p + gx[i]) / 4, t = t0 + sgn * sv * sv;
            sum += gw[i] * S / 4 * 2 * sv * sphere_ring(t, om) * sin(t);
        }
    return sum;
}
static double sphere_ratio_quad(double z, double len)
{
    double sg, om, tk, ff;
    if (len <= 0) return z > 0 ? z : 0.0;
    sg = asin(sqrt(len)); om = acos(z < -1 ? -1 : z > 1 ? 1 : z); tk = fabs(0.5 * PI_D - om);
    if (tk > 0 && tk < sg) ff = sphere_piece(tk, -1, tk, om) + sphere_piece(tk, 1, sg - tk, om);
    else ff = sphere_piece(sg, -1, sg, om);
    return ff / PI_D / len;
}

/* ltc_2.w at every texel of a w x h export against the quadrature at its
 * node (z = 2 j / (w - 1) - 1, len = i / (h - 1)): the worst error relative
 * to max(value, 2^-14), and (*excess) the worst error beyond half-precision
 * rounding (2^-11 max(value, 2^-14)) */
static double sphere_nodes_worst(const unsigned short *t2, int w, int h, double *excess)
{
    double worst = 0.0, ex = 0.0;
    int i, j;
    for (i = 0; i < h; ++i)
        for (j = 0; j < w; ++j) {
            double want = sphere_ratio_quad(2.0 * j / (w - 1) - 1, (double)i / (h - 1)), got = half_value(t2[4 * (i * w + j) + 3]);
            double den = want > 6.103515625e-05 ? want : 6.103515625e-05, err = fabs(got - want);
            if (err / den > worst) worst = err / den;
            if (err - den / 2048 > ex) ex = err - den / 2048;
        }
    *excess = ex;
    return worst;
}

/* The published shader's lookup on the exported textures (nt x na table:
 * the textures are na wide, nt high): uv = (sqrt(alpha), sqrt(1 - N.V))
 * through LUT_SCALE / LUT_BIAS, linear filtering, clamp to edge, M^-1 =
 * mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w)) (GLSL,
 * column-major), the polygon transformed by it and integrated (two-sided;
 * the shader's sum of IntegrateEdge, here mf_polygon_irradiance of the
 * transformed vertices). Against the library's lookup: worst relative
 * difference of 200 square integrals, and (*alb) the worst difference of
 * t2.x, t2.y from mf_ltc_table_lookup's albedo and Fresnel, relative to
 * max(value, 0.01). */
static double export_convention_worst(const unsigned short *t1, const unsigned short *t2, const float *data, int nt, int na,
                                      mf_ltc (*lookup)(mf_real, mf_real), mft_rng *r, double *alb)
{
    double wq = 0.0, wa = 0.0;
    int i, k, c;
    mf_ltc_table tab;
    tab.n_theta = nt; tab.n_alpha = na; tab.data = (float *)data;
    for (i = 0; i < 200; ++i) {
        double ct = 0.02 + 0.98 * mft_u01(r), al = 0.02 + 0.98 * mft_u01(r), st = sqrt(1 - ct * ct);
        double u = lut_coord(sqrt(al), na), v = lut_coord(sqrt(1 - ct), nt), a1[4], a2[4], col[3][3], A[3][3];
        mf_real la, lf;
        mf_vec3 p[4], q[4];
        mf_ltc b;
        tex_linear(t1, na, nt, u, v, a1);
        tex_linear(t2, na, nt, u, v, a2);
        /* mat3(vec3(x, 0, y), vec3(0, 1, 0), vec3(z, 0, w)): three columns */
        col[0][0] = a1[0]; col[0][1] = 0; col[0][2] = a1[1];
        col[1][0] = 0;     col[1][1] = 1; col[1][2] = 0;
        col[2][0] = a1[2]; col[2][1] = 0; col[2][2] = a1[3];
        for (k = 0; k < 3; ++k)
            for (c = 0; c < 3; ++c) A[k][c] = col[c][k];
        b = lookup((mf_real)ct, (mf_real)al);
        square_at(p, mf_normalize(mf_vec3_make((mf_real)(-st + 0.3 * mft_u01(r)), (mf_real)(0.3 * mft_u01(r)), (mf_real)ct)), 0.2 + al);
        for (k = 0; k < 4; ++k) {
            double x = (double)p[k].x, y = (double)p[k].y, z = (double)p[k].z;
            q[k] = mf_vec3_make((mf_real)(A[0][0] * x + A[0][1] * y + A[0][2] * z), (mf_real)(A[1][0] * x + A[1][1] * y + A[1][2] * z),
                                (mf_real)(A[2][0] * x + A[2][1] * y + A[2][2] * z));
        }
        {
            double ia = mf_polygon_irradiance(q, 4, 1), ib = mf_ltc_integrate(&b, p, 4, 1);
            if (ib > 1e-3 && fabs(ia - ib) / ib > wq) wq = fabs(ia - ib) / ib;
        }
        mf_ltc_table_lookup(&tab, (mf_real)ct, (mf_real)al, &la, &lf);
        if (fabs(a2[0] - la) / (la > 0.01 ? la : 0.01) > wa) wa = fabs(a2[0] - la) / (la > 0.01 ? la : 0.01);
        if (fabs(a2[1] - lf) / (lf > 0.01 ? lf : 0.01) > wa) wa = fabs(a2[1] - lf) / (lf > 0.01 ? lf : 0.01);
    }
    *alb = wa;
    return wq;
}

/* The published clipless lookup on ltc_2.w (w x h): spheres of angular
 * radius sigma in (0, pi/2) at omega in [0, pi] from the normal, F their
 * vector form factor (|F| = sin^2 sigma, F.z / |F| = cos omega), uv =
 * (F.z / |F| * 0.5 + 0.5, |F|) through LUT_SCALE / LUT_BIAS, linear
 * filtering, form factor |F| texture(ltc_2, uv).w; worst difference from the
 * quadrature, relative to |F| (the bilinear interpolation of the table, over
 * 400 random spheres) */
static double sphere_lookup_worst(const unsigned short *t2, int w, int h, mft_rng *r)
{
    double worst = 0.0;
    int i;
    for (i = 0; i < 400; ++i) {
        double sg = 0.5 * PI_D * mft_u01(r), om = PI_D * mft_u01(r), len = sin(sg) * sin(sg), z = cos(om), t[4], got, want;
        if (len < 1e-6) continue;
        tex_linear(t2, w, h, lut_coord(z * 0.5 + 0.5, w), lut_coord(len, h), t);
        got = len * t[3];
        want = len * sphere_ratio_quad(z, len);
        if (fabs(got - want) / len > worst) worst = fabs(got - want) / len;
    }
    return worst;
}

/* The two-RGBA half-float export in ltc_code's layout: every value within
 * half precision of the table at its documented texel and channel, ltc_2.z
 * = 0, ltc_2.w (the horizon-clipped sphere) against quadrature at every
 * node and through the published clipless lookup, the published shader's
 * lookup reproducing mf_ltc_ggx on squares and the table's albedo and
 * Fresnel, a non-square table, known encodings, bad input. */
/* ltc_2.w beyond half-precision rounding: double 0 (quadrature and closed
 * form agree far below a half ulp: measured 0); float 1e-7 absolute, measured 3.9e-8:
 * the float closed form cancels near tangency (terms near 0.1, values near
 * 1e-5 at |F| = 4/63, F.z = -0.24) */
#define MFT_SPHERE_EXCESS_TOL MFT_TOL(1e-12, 1e-7)
#define MFT_SPHERE_LOOKUP_TOL 0.025  /* bilinear interpolation of the 64 x 64 table, linear in |F| where the form
                                        factor has a square-root slope at |F| = 1: measured 0.0198 (|F| near 1, F.z
                                        near 0); the sup over a 2000 x 2000 grid of (z, |F|) is 0.0200, below 0.004
                                        for |F| < 0.25 */
static void test_export(mft_rng *r)
{
    static unsigned short t1[4 * 64 * 64], t2[4 * 64 * 64];
    int n, na, i, k, bad = 0;
    const float *t = mf_ltc_ggx_table(&n, &na);
    double worst = 0, wq = 0, wa = 0, ws, wx;
    char msg[200];
    MFT_CHECK(mf_ltc_table_export_rgba16f(t, n, na, t1, t2) == MF_SUCCESS, "export the GGX table as two RGBA16F textures");
    for (i = 0; i < n * na; ++i) {
        for (k = 0; k < 6; ++k) {
            double h = exported_entry(t1, t2, n, na, i, k), want = t[6 * i + k];
            /* relative 2^-11 for normal halves, absolute 2^-25 below 2^-14 */
            double err = fabs(h - want) / (fabs(want) > 6.103515625e-05 ? fabs(want) : 6.103515625e-05);
            if (err > worst) worst = err;
        }
        if (t2[4 * i + 2] != 0) ++bad;
    }
    snprintf(msg, sizeof msg, "exported halves within half precision of the table at the published texel and channel (worst %.2g relative, B = 0 in %d texels)", worst, n * na - bad);
    MFT_CHECK(worst <= 1.0 / 2048 && bad == 0, msg);
    printf("    %s\n", msg);
    ws = sphere_nodes_worst(t2, na, n, &wx);
    snprintf(msg, sizeof msg, "ltc_2.w: the horizon-clipped sphere at every node against quadrature (worst %.3g relative, floor 2^-14; %.2g beyond half rounding)", ws, wx);
    MFT_CHECK(wx <= MFT_SPHERE_EXCESS_TOL, msg);
    printf("    %s\n", msg);
    {   /* its own generator: the draws of r below stay those of the checks that follow */
        mft_rng rs;
        mft_seed(&rs, 1407);
        ws = sphere_lookup_worst(t2, na, n, &rs);
    }
    snprintf(msg, sizeof msg, "published clipless lookup of ltc_2.w against quadrature over 400 spheres (worst %.3g of |F|)", ws);
    MFT_CHECK(ws < MFT_SPHERE_LOOKUP_TOL, msg);
    printf("    %s\n", msg);
    /* the published shader's lookup */
    wq = export_convention_worst(t1, t2, t, n, na, mf_ltc_ggx, r, &wa);
    snprintf(msg, sizeof msg, "published shader lookup of the export reproduces mf_ltc_ggx on squares (worst %.2g relative)", wq);
    MFT_CHECK(wq < 5e-3, msg);
    printf("    %s\n", msg);
    snprintf(msg, sizeof msg, "published shader lookup: t2.x, t2.y = the table's albedo and Fresnel (worst %.2g relative)", wa);
    MFT_CHECK(wa < 1e-3, msg);
    printf("    %s\n", msg);
    {   /* a non-square table, 3 theta x 5 alpha, entry (alpha j, theta i) channel k holding 100 k + 3 j + i */
        float d[6 * 15];
        unsigned short b1[4 * 15], b2[4 * 15];
        static const int ch[4] = { 0, 2, 1, 3 };
        int j, ok = 1;
        for (j = 0; j < 5; ++j)
            for (i = 0; i < 3; ++i)
                for (k = 0; k < 6; ++k) d[6 * (3 * j + i) + k] = (float)(100 * k + 3 * j + i);
        MFT_CHECK(mf_ltc_table_export_rgba16f(d, 3, 5, b1, b2) == MF_SUCCESS, "export a 3 x 5 table");
        for (j = 0; j < 5; ++j)
            for (i = 0; i < 3; ++i) {
                for (k = 0; k < 4; ++k) ok = ok && half_value(b1[4 * (i * 5 + j) + ch[k]]) == 100 * k + 3 * j + i;
                ok = ok && half_value(b2[4 * (i * 5 + j)]) == 400 + 3 * j + i && half_value(b2[4 * (i * 5 + j) + 1]) == 500 + 3 * j + i &&
                     b2[4 * (i * 5 + j) + 2] == 0;
            }
        MFT_CHECK(ok, "3 theta x 5 alpha: textures 5 wide and 3 high, alpha along u, theta along v, ltc_1 = (inv0, inv2, inv1, inv3)");
        ws = sphere_nodes_worst(b2, 5, 3, &wx);
        snprintf(msg, sizeof msg, "3 x 5: ltc_2.w, z along u and |F| along v, against quadrature (worst %.3g relative, %.2g beyond half rounding)", ws, wx);
        MFT_CHECK(wx <= MFT_SPHERE_EXCESS_TOL, msg);
    }
    {   /* known encodings, through a 2 x 2 table: entries 0 (theta 0, alpha 0: texel 0) and 1 (theta 1, alpha 0: texel 2) */
        float d[24];
        unsigned short a1[16], a2[16];
        const float in[8] = { 1.0f, 65504.0f, 1e6f, 5.9604645e-8f, 1.4e-8f, -2.0f, 0.1f, 3.0517578e-5f };
        const unsigned short want[8] = { 0x3c00, 0x7bff, 0x7bff, 0x0001, 0x0000, 0xc000, 0x2e66, 0x0200 };
        static const int ch[4] = { 0, 2, 1, 3 };
        int ok = 1;
        for (i = 0; i < 24; ++i) d[i] = 0.5f;
        for (i = 0; i < 8; ++i) d[6 * (i / 4) + i % 4] = in[i];
        MFT_CHECK(mf_ltc_table_export_rgba16f(d, 2, 2, a1, a2) == MF_SUCCESS, "export a 2 x 2 table");
        for (i = 0; i < 8; ++i) ok = ok && a1[4 * (2 * (i / 4)) + ch[i % 4]] == want[i];
        MFT_CHECK(ok && a2[0] == 0x3800, "half encodings: 1, 65504, overflow, 2^-24, underflow, -2, 0.1, subnormal 2^-15, 0.5");
        /* sphere corners: (z, |F|) = (-1, 0) 0, (1, 0) 1, (-1, 1) 0, (1, 1) 1 */
        MFT_CHECK(a2[3] == 0 && a2[7] == 0x3c00 && a2[11] == 0 && a2[15] == 0x3c00, "2 x 2: ltc_2.w at the corners 0, 1, 0, 1");
        {
            volatile double zero = 0.0;
            d[7] = (float)(1.0 / zero);   /* inf */
        }
        MFT_CHECK(mf_ltc_table_export_rgba16f(d, 2, 2, a1, a2) == MF_ERROR_INVALID_DATA, "export rejects a non-finite entry");
        MFT_CHECK(mf_ltc_table_export_rgba16f(NULL, 2, 2, a1, a2) == MF_ERROR_INVALID_ARGUMENT &&
                  mf_ltc_table_export_rgba16f(d, 1, 2, a1, a2) == MF_ERROR_INVALID_ARGUMENT &&
                  mf_ltc_table_export_rgba16f(d, 2, 2, NULL, a2) == MF_ERROR_INVALID_ARGUMENT, "export rejects bad arguments");
    }
}

/* Broad-light accuracy of the built-in GGX table: 512 square lights at unit
 * distance, 8 views (cos 0.05 to 1) x 8 roughnesses (alpha 0.01 to 1) x 8
 * lights: 4 around the mirror direction (half-widths 0.25 to 2 lobe widths,
 * offsets 0 to 1.5 widths, lobe width min(2 atan(alpha), 1)) and 4 away from
 * it (centres uniform over z >= 0.1 at least min(3 widths, 1.2 rad) from the
 * mirror direction, half-widths 0.05 to 0.4 rad). The table's albedo times
 * the LTC integral against composite Gauss-Legendre quadrature of the true
 * BRDF cos over each square (graded around the mirror direction, cut at the
 * horizon; halving the panels changes it by < 3e-5): the mean relative
 * error overall, near, away, and per view and roughness band. */
typedef struct { double ct, alpha; mf_vec3 p[4]; int near; } broad_light;
static unsigned long long broad_state;
static double broad_u01(void)
{
    broad_state ^= broad_state << 13; broad_state ^= broad_state >> 7; broad_state ^= broad_state << 17;
    return (double)(broad_state >> 11) * (1.0 / 9007199254740992.0);
}
/* u along the steepest ascent of z in the plane through unit c */
static void broad_frame(const double *c, double *u, double *v)
{
    double n;
    int k;
    u[0] = -c[2] * c[0]; u[1] = -c[2] * c[1]; u[2] = 1.0 - c[2] * c[2];
    n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (n < 1e-9) { u[0] = 1.0; u[1] = u[2] = 0.0; }
    else for (k = 0; k < 3; ++k) u[k] /= n;
    v[0] = c[1] * u[2] - c[2] * u[1]; v[1] = c[2] * u[0] - c[0] * u[2]; v[2] = c[0] * u[1] - c[1] * u[0];
}
static void broad_square(broad_light *l, const double *c, double half)
{
    double u[3], v[3], h = tan(half);
    int k;
    broad_frame(c, u, v);
    for (k = 0; k < 4; ++k) {
        double sx = k < 2 ? -h : h, sy = (k == 1 || k == 2) ? h : -h;
        l->p[k] = mf_vec3_make((mf_real)(c[0] + sx * u[0] + sy * v[0]), (mf_real)(c[1] + sx * u[1] + sy * v[1]),
                               (mf_real)(c[2] + sx * u[2] + sy * v[2]));
    }
}
static void broad_tilt(const double *a, double t, double ph, double *out)
{
    double u[3], v[3];
    int k;
    broad_frame(a, u, v);
    for (k = 0; k < 3; ++k) out[k] = cos(t) * a[k] + sin(t) * (cos(ph) * u[k] + sin(ph) * v[k]);
}
static int broad_lights(broad_light *ls)
{
    static const double cts[8] = { 0.05, 0.12, 0.25, 0.4, 0.55, 0.7, 0.85, 1.0 };
    static const double als[8] = { 0.01, 0.02, 0.05, 0.1, 0.2, 0.35, 0.6, 1.0 };
    int i, j, k, n = 0;
    broad_state = 0x9e3779b97f4a7c15ULL;
    for (j = 0; j < 8; ++j)
        for (i = 0; i < 8; ++i) {
            double ct = cts[i], st = sqrt(1 - ct * ct), w = fmin(2.0 * atan(als[j]), 1.0), r[3];
            r[0] = -st; r[1] = 0; r[2] = ct;
            for (k = 0; k < 8; ++k) {
                broad_light *l = &ls[n++];
                double c[3];
                l->ct = ct; l->alpha = als[j]; l->near = k < 4;
                if (k < 4) {
                    static const double off[4] = { 0.0, 0.5, 1.0, 1.5 }, size[4] = { 0.5, 1.0, 2.0, 4.0 };
                    broad_tilt(r, off[k] * w, 2 * PI_D * broad_u01(), c);
                    if (c[2] < 0.05) { double f = sqrt((1 - 0.0025) / (c[0] * c[0] + c[1] * c[1])); c[0] *= f; c[1] *= f; c[2] = 0.05; }
                    broad_square(l, c, fmin(0.5 * size[k] * w, 1.2));
                } else {
                    double dmin = fmin(3.0 * w, 1.2), dd;
                    do {
                        double z = 0.1 + 0.9 * broad_u01(), ph = 2 * PI_D * broad_u01(), sn = sqrt(1 - z * z);
                        c[0] = sn * cos(ph); c[1] = sn * sin(ph); c[2] = z;
                        dd = acos(fmax(-1.0, fmin(1.0, c[0] * r[0] + c[1] * r[1] + c[2] * r[2])));
                    } while (dd < dmin);
                    broad_square(l, c, 0.05 + 0.35 * broad_u01());
                }
            }
        }
    return n;
}
static int broad_breaks(double lo, double hi, double c, double h, double hmax, double *b, int max)
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
/* integral of f cos over the square: dA / r^3 on the plane at unit distance */
static double broad_reference(const mf_ndf *d, mf_vec3 wo, const broad_light *l)
{
    double c[3], u[3], v[3], h, bx[1024], by[1024], px = 1e9, py = 1e9, xlo, sum = 0.0, gx[8], gw[8];
    int nx, ny, i, j, a, b, k;
    mft_gl(8, gx, gw);
    for (k = 0; k < 3; ++k) {
        double q[4];
        for (i = 0; i < 4; ++i) q[i] = k == 0 ? (double)l->p[i].x : k == 1 ? (double)l->p[i].y : (double)l->p[i].z;
        c[k] = 0.25 * (q[0] + q[1] + q[2] + q[3]); u[k] = 0.5 * (q[3] - q[0]); v[k] = 0.5 * (q[1] - q[0]);
    }
    h = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (k = 0; k < 3; ++k) { u[k] /= h; v[k] /= h; }
    {
        double r[3], dn;
        r[0] = -(double)wo.x; r[1] = -(double)wo.y; r[2] = (double)wo.z;
        dn = r[0] * c[0] + r[1] * c[1] + r[2] * c[2];
        if (dn > 1e-3) { px = (r[0] * u[0] + r[1] * u[1] + r[2] * u[2]) / dn; py = (r[0] * v[0] + r[1] * v[1] + r[2] * v[2]) / dn; }
    }
    xlo = -h;
    if (u[2] > 1e-12 && -c[2] / u[2] > xlo) xlo = -c[2] / u[2];
    if (xlo >= h) return 0.0;
    nx = broad_breaks(xlo, h, px, 0.25 * fmax((double)d->ax, 1e-3), 0.125 * h, bx, 1024);
    ny = broad_breaks(-h, h, py, 0.25 * fmax((double)d->ax, 1e-3), 0.125 * h, by, 1024);
    for (i = 0; i + 1 < nx; ++i)
        for (a = 0; a < 8; ++a) {
            double x = bx[i] + (bx[i + 1] - bx[i]) * gx[a], wx = (bx[i + 1] - bx[i]) * gw[a];   /* nodes on [0, 1] */
            for (j = 0; j + 1 < ny; ++j)
                for (b = 0; b < 8; ++b) {
                    double y = by[j] + (by[j + 1] - by[j]) * gx[b], wy = (by[j + 1] - by[j]) * gw[b];
                    double q[3], r2, r;
                    for (k = 0; k < 3; ++k) q[k] = c[k] + x * u[k] + y * v[k];
                    if (q[2] <= 0.0) continue;
                    r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2]; r = sqrt(r2);
                    sum += wx * wy * (double)mf_brdf(d, wo, mf_vec3_make((mf_real)(q[0] / r), (mf_real)(q[1] / r), (mf_real)(q[2] / r))) *
                           (q[2] / r) / (r2 * r);
                }
        }
    return sum;
}
static void test_broad_lights(void)
{
    static broad_light ls[512];
    /* bounds slightly above the measured values (see the printed lines) */
    /* measured (float and double alike): mean 0.1961, near 0.0310, away 0.3611;
     * bands (views x alpha) 0.428 0.450 0.164 / 0.243 0.192 0.083 / 0.095 0.117 0.028.
     * The published table (Heitz et al. 2016, ltc_code) measured on the same
     * lights outside this project: mean 0.2857, near 0.0609, away 0.5105; the
     * plain fit (mf_ltc_table_build): 0.2858, 0.0619, 0.5097 */
    static const double band_tol[3][3] = { { 0.44, 0.465, 0.17 }, { 0.25, 0.198, 0.086 }, { 0.098, 0.12, 0.03 } };
    const double mean_tol = 0.20, near_tol = 0.033, off_tol = 0.37;
    double sum = 0, sn = 0, so = 0, band[3][3] = { { 0 } };
    int cnt[3][3] = { { 0 } }, n = broad_lights(ls), i, a, v, nn = 0;
    char msg[200];
    for (i = 0; i < n; ++i) {
        broad_light *l = &ls[i];
        mf_ndf d = mf_ggx((mf_real)l->alpha, (mf_real)l->alpha);
        mf_vec3 wo = mf_vec3_make((mf_real)sqrt(1 - l->ct * l->ct), 0, (mf_real)l->ct);
        mf_ltc lt = mf_ltc_ggx((mf_real)l->ct, (mf_real)l->alpha);
        double ref = broad_reference(&d, wo, l);
        double e = fabs((double)mf_ltc_ggx_albedo((mf_real)l->ct, (mf_real)l->alpha) * (double)mf_ltc_integrate(&lt, l->p, 4, 1) - ref) / ref;
        v = l->ct < 0.3 ? 0 : l->ct < 0.7 ? 1 : 2; a = l->alpha < 0.08 ? 0 : l->alpha < 0.3 ? 1 : 2;
        sum += e; band[v][a] += e; ++cnt[v][a];
        if (l->near) { sn += e; ++nn; } else so += e;
    }
    printf("    GGX table, broad lights (%d squares): mean relative error %.4f, around the mirror direction %.4f, away %.4f\n",
           n, sum / n, sn / nn, so / (n - nn));
    for (v = 0; v < 3; ++v)
        printf("    views %s: alpha < 0.08 %.4f, 0.08-0.3 %.4f, >= 0.3 %.4f\n", v == 0 ? "cos < 0.3 " : v == 1 ? "cos 0.3-0.7" : "cos >= 0.7",
               band[v][0] / cnt[v][0], band[v][1] / cnt[v][1], band[v][2] / cnt[v][2]);
    snprintf(msg, sizeof msg, "GGX table over 512 broad lights: mean relative error %.4f (near %.4f, away %.4f)", sum / n, sn / nn, so / (n - nn));
    MFT_CHECK(sum / n < mean_tol && sn / nn < near_tol && so / (n - nn) < off_tol, msg);
    for (v = 0; v < 3; ++v)
        for (a = 0; a < 3; ++a) {
            snprintf(msg, sizeof msg, "GGX table, broad lights, view band %d x roughness band %d: mean relative error %.4f", v, a, band[v][a] / cnt[v][a]);
            MFT_CHECK(band[v][a] / cnt[v][a] < band_tol[v][a], msg);
        }
}

/* The shipped GGX matrices are the plain fit (mf_ltc_table_build) refined on
 * integrated polygons: at the nodes 0, 21, 42, 63 of both axes (a 4 x 4
 * refit) both are compared on 8 squares per node (4 around the mirror
 * direction, 4 away from it, drawn like the broad-light set) against
 * quadrature of the true BRDF cos: the refined entries must be the better
 * ones on the whole and away from the lobe, and stay close around it. */
static void test_ggx_refined(void)
{
    const mf_ltc_table *t = refit_table(MF_NDF_GGX);
    const float *s = mf_ltc_ggx_table(NULL, NULL);
    double e_fit[2] = { 0, 0 }, e_ship[2] = { 0, 0 };
    int i, j, k, cnt[2] = { 0, 0 };
    char msg[220];
    if (!t) { MFT_CHECK(0, "refit 4 x 4 GGX table"); return; }
    broad_state = 0x2545f4914f6cdd1dULL;
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            double tt = i / 3.0, v = j / 3.0, ct = fmax(1.0 - tt * tt, 1e-3), al = fmax(v * v, 1e-3), st = sqrt(1 - ct * ct);
            double w = fmin(2.0 * atan(al), 1.0), r[3];
            const float *a = t->data + 6 * (j * 4 + i), *b = s + 6 * (21 * j * 64 + 21 * i);
            mf_ltc la = mf_ltc_from_inverse((mf_real)a[0], (mf_real)a[1], MF_R(1.0), (mf_real)a[2], (mf_real)a[3]);
            mf_ltc lb = mf_ltc_from_inverse((mf_real)b[0], (mf_real)b[1], MF_R(1.0), (mf_real)b[2], (mf_real)b[3]);
            mf_ndf d = mf_ggx((mf_real)al, (mf_real)al);
            mf_vec3 wo = mf_vec3_make((mf_real)st, 0, (mf_real)ct);
            r[0] = -st; r[1] = 0; r[2] = ct;
            for (k = 0; k < 8; ++k) {
                broad_light l;
                double c[3], ref;
                if (k < 4) {
                    broad_tilt(r, 0.4 * k * w, 2 * PI_D * broad_u01(), c);
                    if (c[2] < 0.05) { double f = sqrt((1 - 0.0025) / (c[0] * c[0] + c[1] * c[1])); c[0] *= f; c[1] *= f; c[2] = 0.05; }
                    broad_square(&l, c, fmin((0.3 + 0.6 * k) * w, 1.2));
                } else {
                    double dd;
                    do {
                        double z = 0.1 + 0.9 * broad_u01(), ph = 2 * PI_D * broad_u01(), sn = sqrt(1 - z * z);
                        c[0] = sn * cos(ph); c[1] = sn * sin(ph); c[2] = z;
                        dd = acos(fmax(-1.0, fmin(1.0, c[0] * r[0] + c[1] * r[1] + c[2] * r[2])));
                    } while (dd < fmin(3.0 * w, 1.2));
                    broad_square(&l, c, 0.05 + 0.35 * broad_u01());
                }
                ref = broad_reference(&d, wo, &l);
                if (!(ref > 1e-12)) continue;
                e_fit[k < 4] += fabs((double)a[4] * (double)mf_ltc_integrate(&la, l.p, 4, 1) - ref) / ref;
                e_ship[k < 4] += fabs((double)b[4] * (double)mf_ltc_integrate(&lb, l.p, 4, 1) - ref) / ref;
                ++cnt[k < 4];
            }
        }
    printf("    GGX shipped (refined) vs plain fit at 16 nodes: around the mirror direction %.4f vs %.4f, away %.4f vs %.4f (%d + %d squares)\n",
           e_ship[1] / cnt[1], e_fit[1] / cnt[1], e_ship[0] / cnt[0], e_fit[0] / cnt[0], cnt[1], cnt[0]);
    snprintf(msg, sizeof msg, "refined GGX entries beat the plain fit on squares (all %.4f vs %.4f, away %.4f vs %.4f)",
             (e_ship[0] + e_ship[1]) / (cnt[0] + cnt[1]), (e_fit[0] + e_fit[1]) / (cnt[0] + cnt[1]), e_ship[0] / cnt[0], e_fit[0] / cnt[0]);
    /* measured: all 0.57 of the plain fit's error (float 0.59), away 0.71 (float 0.75) */
    MFT_CHECK(cnt[0] > 40 && cnt[1] > 50 && e_ship[0] + e_ship[1] < 0.8 * (e_fit[0] + e_fit[1]) && e_ship[0] < 0.8 * e_fit[0], msg);
    snprintf(msg, sizeof msg, "refined GGX entries stay close to the true lobe around the mirror direction (%.4f, plain fit %.4f)",
             e_ship[1] / cnt[1], e_fit[1] / cnt[1]);
    MFT_CHECK(e_ship[1] / cnt[1] < 0.03, msg);   /* measured 0.024 */
}

/* The built-in Beckmann table (tools/ltc_fit.c --module beckmann): the same
 * checks as the GGX table. Refit of a 4 x 4 table at the shipped nodes 0, 21,
 * 42, 63; raw entries = lookups at the nodes; albedo and Fresnel columns
 * against a midpoint rule of mf_brdf cos over the hemisphere; the lookup
 * against Monte Carlo of the true Beckmann BRDF cos over quads around and
 * beside the mirror direction (mean and max relative error asserted); the
 * RGBA16F export of the table and its sampling convention. */
#define MFT_LTC_BECK_MEAN_TOL 0.12   /* measured 0.103: the cosine lobe's tail (power -4) holds */
#define MFT_LTC_BECK_MAX_TOL 0.95    /* 10-15% of the energy outside quads that hold 98% of the
                                        Gaussian-tailed Beckmann lobe; max 0.898 at alpha 0.6,
                                        81 degrees, beside the mirror direction */
static void test_beckmann_table(mft_rng *r)
{
    int n = 0, na = 0, i, j, k, a, c, count = 0;
    const float *s = mf_ltc_beckmann_table(&n, &na);
    double wm = 0.0, wa = 0.0, wacc = 0.0, wf = 0.0, sum = 0.0, worst = 0.0;
    char msg[200];
    MFT_CHECK(s != NULL && n == 64 && na == 64, "mf_ltc_beckmann_table: 64 x 64 entries");
    if (!s || n != 64 || na != 64) return;
    MFT_CHECK(s != mf_ltc_ggx_table(NULL, NULL), "the Beckmann table is its own data");
    MFT_CHECK(refit_compare(MF_NDF_BECKMANN, s, "Beckmann", &wm, &wa), "refit 4 x 4 Beckmann table");
    snprintf(msg, sizeof msg, "refitted Beckmann entries match the shipped table (matrix %.2g of its scale, albedo/fresnel %.2g)", wm, wa);
    /* Nelder-Mead stops within a few 1e-3 of the optimum (measured 4.2e-3;
     * float 0.019 at alpha 1e-3, 90 degrees, where every entry is below 2e-3) */
    MFT_CHECK(wm < MFT_TOL(6e-3, 3e-2) && wa < MFT_TOL(1e-5, 1e-3), msg);
    for (j = 0; j < 64; j += 9)
        for (i = 0; i < 64; i += 7) {
            double tt = i / 63.0, v = j / 63.0, ct = 1.0 - tt * tt, al = v * v;
            const float *e = s + 6 * (j * 64 + i);
            mf_ltc l, g;
            if (ct < 1e-3 || al < 1e-3) continue;   /* the clamped ends */
            l = mf_ltc_from_inverse((mf_real)e[0], (mf_real)e[1], MF_R(1.0), (mf_real)e[2], (mf_real)e[3]);
            g = mf_ltc_beckmann((mf_real)ct, (mf_real)al);
            for (k = 0; k < 9; ++k) {
                double dk = fabs((double)l.Minv[k] / (double)l.Minv[8] - (double)g.Minv[k] / (double)g.Minv[8]);
                if (dk / (fabs((double)l.Minv[k] / (double)l.Minv[8]) + 1.0) > wacc) wacc = dk / (fabs((double)l.Minv[k] / (double)l.Minv[8]) + 1.0);
            }
            if (fabs((double)mf_ltc_beckmann_albedo((mf_real)ct, (mf_real)al) - e[4]) > wacc) wacc = fabs((double)mf_ltc_beckmann_albedo((mf_real)ct, (mf_real)al) - e[4]);
            if (fabs((double)mf_ltc_beckmann_fresnel((mf_real)ct, (mf_real)al) - e[5]) > wacc) wacc = fabs((double)mf_ltc_beckmann_fresnel((mf_real)ct, (mf_real)al) - e[5]);
        }
    snprintf(msg, sizeof msg, "raw Beckmann entries = lookups at the nodes (matrix, albedo, fresnel; worst %.2g)", wacc);
    MFT_CHECK(wacc < MFT_TOL(1e-5, 2e-3), msg);
    for (j = 21; j < 64; j += 21)
        for (i = 0; i < 63; i += 21) {
            double tt = i / 63.0, v = j / 63.0, ct = 1.0 - tt * tt, al = v * v, alb = 0.0, fr = 0.0;
            int N = 400, p, q;
            mf_ndf d = mf_beckmann((mf_real)al, (mf_real)al);
            mf_vec3 wo = mf_vec3_make((mf_real)sqrt(1.0 - ct * ct), 0, (mf_real)ct);
            const float *e = s + 6 * (j * 64 + i);
            for (p = 0; p < N; ++p)
                for (q = 0; q < N; ++q) {
                    double cc = (p + 0.5) / N, ph = 2.0 * PI_D * (q + 0.5) / N, sn = sqrt(1.0 - cc * cc), f, h;
                    mf_vec3 wi = mf_vec3_make((mf_real)(sn * cos(ph)), (mf_real)(sn * sin(ph)), (mf_real)cc);
                    f = (double)mf_brdf(&d, wo, wi) * cc * (2.0 * PI_D / N) / N;
                    h = 1.0 - (double)mf_dot(wo, mf_normalize(mf_add(wo, wi)));
                    alb += f; fr += f * h * h * h * h * h;
                }
            if (fabs(alb - e[4]) > wf) wf = fabs(alb - e[4]);
            if (fabs(fr - e[5]) > wf) wf = fabs(fr - e[5]);
        }
    snprintf(msg, sizeof msg, "Beckmann albedo and Fresnel columns vs quadrature of the BRDF (worst %.2g)", wf);
    MFT_CHECK(wf < 5e-3, msg);
    /* against Monte Carlo of the true Beckmann BRDF cos over quads */
    {
        const double cosv[] = { 0.95, 0.7, 0.4, 0.15 }, alphas[] = { 0.05, 0.13, 0.3, 0.6, 0.9 };
        for (a = 0; a < 5; ++a)
            for (c = 0; c < 4; ++c)
                for (k = 0; k < 2; ++k) {
                    mf_ndf d = mf_beckmann((mf_real)alphas[a], (mf_real)alphas[a]);
                    double ct = cosv[c], st = sqrt(1 - ct * ct), se, mc, lt, rel, size = 0.3 + 1.2 * alphas[a];
                    mf_vec3 wo = mf_vec3_make((mf_real)st, 0, (mf_real)ct), p[4], u, v;
                    mf_vec3 cdir = k == 0 ? mf_vec3_make((mf_real)-st, 0, (mf_real)ct) : mf_normalize(mf_vec3_make((mf_real)(-0.3 * st), 0.5f, (mf_real)ct));
                    mf_ltc l = mf_ltc_beckmann((mf_real)ct, (mf_real)alphas[a]);
                    { mf_basis fr_ = mf_basis_from_normal(cdir); u = fr_.t; v = fr_.b; }
                    p[0] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)-size), mf_scale(v, (mf_real)-size)));
                    p[1] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)-size), mf_scale(v, (mf_real)size)));
                    p[2] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)size), mf_scale(v, (mf_real)size)));
                    p[3] = mf_add(mf_scale(cdir, 2), mf_add(mf_scale(u, (mf_real)size), mf_scale(v, (mf_real)-size)));
                    mc = brdf_polygon_mc(&d, wo, p, 4, MFT_N(200000), r, &se);
                    lt = mf_ltc_beckmann_albedo((mf_real)ct, (mf_real)alphas[a]) * mf_ltc_integrate(&l, p, 4, 1);
                    if (mc < 0.02) continue;
                    rel = fabs(lt - mc) / mc;
                    if (mft_verbose) printf("    Beckmann alpha %.2f cos %.2f quad %d: ltc %.4f mc %.4f (se %.4f) rel %.3f\n", alphas[a], ct, k, lt, mc, se, rel);
                    sum += rel; ++count;
                    if (rel > worst) worst = rel;
                }
        printf("    Beckmann table vs Monte Carlo of the BRDF over %d quads: mean relative error %.3f, max %.3f\n", count, sum / count, worst);
        snprintf(msg, sizeof msg, "Beckmann LTC table: mean relative error %.3f over %d quads", sum / count, count);
        MFT_CHECK(count > 20 && sum / count < MFT_LTC_BECK_MEAN_TOL, msg);
        snprintf(msg, sizeof msg, "Beckmann LTC table: max relative error %.3f", worst);
        MFT_CHECK(worst < MFT_LTC_BECK_MAX_TOL, msg);
    }
    /* RGBA16F export: halves within half precision at the published texel and
     * channel, the published shader's lookup reproducing mf_ltc_beckmann on
     * squares and the table's albedo and Fresnel */
    {
        static unsigned short t1[4 * 64 * 64], t2[4 * 64 * 64];
        double we = 0.0, wq = 0.0, wb = 0.0;
        MFT_CHECK(mf_ltc_table_export_rgba16f(s, n, na, t1, t2) == MF_SUCCESS, "export the Beckmann table as two RGBA16F textures");
        for (i = 0; i < n * na; ++i)
            for (k = 0; k < 6; ++k) {
                double h = exported_entry(t1, t2, n, na, i, k), want = s[6 * i + k];
                double err = fabs(h - want) / (fabs(want) > 6.103515625e-05 ? fabs(want) : 6.103515625e-05);
                if (err > we) we = err;
            }
        snprintf(msg, sizeof msg, "exported Beckmann halves within half precision of the table (worst %.2g relative)", we);
        MFT_CHECK(we <= 1.0 / 2048, msg);
        wq = export_convention_worst(t1, t2, s, n, na, mf_ltc_beckmann, r, &wb);
        snprintf(msg, sizeof msg, "published shader lookup of the export reproduces mf_ltc_beckmann on squares (worst %.2g relative)", wq);
        MFT_CHECK(wq < 5e-3, msg);
        printf("    %s\n", msg);
        snprintf(msg, sizeof msg, "published shader lookup: Beckmann t2.x, t2.y = the table's albedo and Fresnel (worst %.2g relative)", wb);
        MFT_CHECK(wb < 1e-3, msg);
    }
}

void test_ltc(void)
{
    mft_rng r;
    int i;
    char msg[160];
    test_ggx_table_data();
    mft_seed(&r, 31);
    test_fast_edge(&r);
    test_polygon_exact(&r);
    {
        mft_rng r2;
        mft_seed(&r2, 44);
        test_polygon_form_factor(&r2);
    }
    test_off_node();
    test_export(&r);
    test_fitter();
    test_ggx_table(&r);
    test_beckmann_table(&r);
    test_broad_lights();
    test_ggx_refined();
    refit_release();
    /* normalization */
    for (i = 0; i < 6; ++i) {
        mf_ltc l = random_ltc(&r, i < 3 ? 0.4 : 0.9);
        snprintf(msg, sizeof msg, "LTC integrates to 1 over the sphere (matrix %d)", i);
        MFT_NEAR(sphere_integral(&l), 1.0, MFT_TOL(1e-6, 1e-4), 0, msg);
    }
    {
        mf_ltc l = mf_ltc_from_inverse(MF_R(4.0), MF_R(-1.2), MF_R(3.0), MF_R(0.5), MF_R(1.0));
        MFT_NEAR(sphere_integral(&l), 1.0, MFT_TOL(1e-6, 1e-4), 0, "LTC from the 5-coefficient inverse integrates to 1");
    }
    /* sampling chi-square over 32 x 32 equal-area cells */
    {
        static double obs[1024], e[1024];
        mf_ltc l = random_ltc(&r, 0.6);
        double gx[8], gw[8];
        int n = 400000, c, j, a, b, dof;
        double z;
        mft_gl(8, gx, gw);   /* 8 x 8 nodes a cell: the expected counts of a peaked lobe to < 1e-4 */
        memset(obs, 0, sizeof obs);
        for (i = 0; i < n; ++i) {
            mf_vec3 w = mf_ltc_sample(&l, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
            double ph = atan2((double)w.y, (double)w.x);
            int iz = (int)((w.z + 1) * 16), ip;
            if (ph < 0) ph += 2 * PI_D;
            ip = (int)(ph / (2 * PI_D) * 32);
            if (iz > 31) iz = 31;
            if (ip > 31) ip = 31;
            if (iz < 0) iz = 0;
            obs[iz * 32 + ip] += 1;
        }
        for (c = 0; c < 1024; ++c) {
            double s = 0;
            for (a = 0; a < 8; ++a)
                for (b = 0; b < 8; ++b) {
                    double zz = -1 + 2.0 * (c / 32 + gx[a]) / 32, ph = 2 * PI_D * (c % 32 + gx[b]) / 32, sn = sqrt(1 - zz * zz);
                    s += gw[a] * gw[b] * (double)mf_ltc_eval(&l, mf_vec3_make((mf_real)(sn * cos(ph)), (mf_real)(sn * sin(ph)), (mf_real)zz));
                }
            e[c] = s * (2.0 / 32) * (2 * PI_D / 32) * n;
        }
        z = mft_chi2(obs, e, 1024, &dof);
        snprintf(msg, sizeof msg, "LTC sampling chi-square z=%.2f dof=%d", z, dof);
        MFT_CHECK(z < 5.0, msg);
        (void)j;
    }
    /* polygons against Monte Carlo */
    {
        mf_ltc ltcs[3];
        mf_vec3 p[6];
        int k;
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        ltcs[0] = mf_ltc_from_matrix9(I9);
        ltcs[1] = random_ltc(&r, 0.5);
        ltcs[2] = mf_ltc_from_inverse(MF_R(3.0), MF_R(-0.8), MF_R(2.5), MF_R(0.6), MF_R(1.0));
        for (k = 0; k < 3; ++k) {
            const mf_ltc *l = &ltcs[k];
            /* triangle above, counterclockwise seen from below */
            p[0] = mf_vec3_make(-0.5f, -0.4f, 1.0f); p[2] = mf_vec3_make(0.6f, -0.2f, 1.3f); p[1] = mf_vec3_make(0.1f, 0.7f, 0.8f);
            polygon_case("triangle", l, p, 3, 0, &r);
            polygon_case("triangle", l, p, 3, 1, &r);
            /* quad partly below the horizon (vertical, in front) */
            p[0] = mf_vec3_make(1.0f, -1.0f, -0.5f); p[1] = mf_vec3_make(1.0f, 1.0f, -0.5f);
            p[2] = mf_vec3_make(1.0f, 1.0f, 1.0f); p[3] = mf_vec3_make(1.0f, -1.0f, 1.0f);
            polygon_case("vertical quad crossing the horizon", l, p, 4, 0, &r);
            polygon_case("vertical quad crossing the horizon", l, p, 4, 1, &r);
            /* pentagon tilted, crossing the horizon twice */
            for (i = 0; i < 5; ++i) {
                double a = 2 * PI_D * i / 5;
                p[i] = mf_vec3_make((mf_real)(0.8 * cos(a) - 0.3), (mf_real)(0.8 * sin(a)), (mf_real)(0.2 + 0.7 * cos(a)));
            }
            polygon_case("tilted pentagon", l, p, 5, 1, &r);
            /* concave hexagon (an L shape) above */
            p[0] = mf_vec3_make(-1, -1, 1); p[1] = mf_vec3_make(1, -1, 1); p[2] = mf_vec3_make(1, 0, 1);
            p[3] = mf_vec3_make(0, 0, 1); p[4] = mf_vec3_make(0, 1, 1); p[5] = mf_vec3_make(-1, 1, 1);
            polygon_case("concave L hexagon", l, p, 6, 1, &r);
            /* small and large squares */
            square(p, 2.0, 0.02, 0.3, -0.2);
            polygon_case("small square", l, p, 4, 1, &r);
            square(p, 0.3, 50.0, 0.0, 0.0);
            polygon_case("huge square", l, p, 4, 1, &r);
        }
        /* fully below the horizon */
        square(p, -1.0, 0.5, 0.0, 0.0);
        MFT_CHECK(mf_ltc_integrate(&ltcs[0], p, 4, 1) == 0 && mf_polygon_irradiance(p, 4, 1) == 0, "polygon below the horizon: 0");
    }
    /* analytic form factor of squares parallel to the surface */
    {
        mf_vec3 p[4], q[4];
        double h, want;
        for (h = 0.25; h < 5; h *= 2) {
            square(p, h, 0.5, 0.0, 0.0);
            want = 4 * ff_corner(0.5, 0.5, h);
            snprintf(msg, sizeof msg, "form factor of a unit square at height %.2f", h);
            MFT_NEAR(mf_polygon_irradiance(p, 4, 0), want, MFT_TOL(1e-9, 2e-5), 0, msg);
            q[0] = p[0]; q[1] = p[3]; q[2] = p[2]; q[3] = p[1];   /* reversed: back face */
            MFT_CHECK(mf_polygon_irradiance(q, 4, 0) == 0 && fabs(mf_polygon_irradiance(q, 4, 1) - want) < MFT_TOL(1e-9, 2e-5) * want,
                      "reversed square: one-sided 0, two-sided equal");
            snprintf(msg, sizeof msg, "vector form factor z of a unit square at height %.2f", h);
            MFT_NEAR(mf_polygon_vector_form_factor(p, 4).z, want, MFT_TOL(1e-9, 2e-5), 0, msg);
        }
        /* tiny and huge squares: solid angle limit and the full hemisphere */
        square(p, 1.0, 1e-4, 0.0, 0.0);
        MFT_NEAR(mf_polygon_irradiance(p, 4, 0), 4e-8 / PI_D, MFT_TOL(1e-6, 1e-3), 0, "tiny square: cos dA / (pi r^2)");
        square(p, 1.0, 1e5, 0.0, 0.0);
        MFT_NEAR(mf_polygon_irradiance(p, 4, 0), 4 * ff_corner(1e5, 1e5, 1.0), MFT_TOL(1e-9, 1e-5), 0, "huge square (edges nearly antipodal)");
    }
    /* sphere lights: Snyder's clipped form factor against quadrature over the cap */
    {
        double worst = 0;
        int a, b;
        for (a = 1; a < 6; ++a)
            for (b = 0; b < 9; ++b) {
                double sig = 0.15 * a, om = b * 0.25, gx[8], gw[8], num = 0;
                int pz, pp, i2, j2;
                mf_vec3 F = mf_vec3_make((mf_real)(sin(om) * sin(sig) * sin(sig)), 0, (mf_real)(cos(om) * sin(sig) * sin(sig)));
                mft_gl(8, gx, gw);
                for (pz = 0; pz < 40; ++pz)   /* cap around its axis: cos in [cos sig, 1], uniform area */
                    for (i2 = 0; i2 < 8; ++i2) {
                        double cz = cos(sig) + (1 - cos(sig)) * (pz + gx[i2]) / 40, sz = sqrt(1 - cz * cz);
                        for (pp = 0; pp < 40; ++pp)
                            for (j2 = 0; j2 < 8; ++j2) {
                                double ph = 2 * PI_D * (pp + gx[j2]) / 40;
                                /* local (sz cos, sz sin, cz) rotated so the axis is at angle om from z */
                                double wz = cz * cos(om) - sz * cos(ph) * sin(om);
                                if (wz > 0) num += gw[i2] * gw[j2] * wz / PI_D * (1 - cos(sig)) / 40 * 2 * PI_D / 40;
                            }
                    }
                if (fabs(mf_sphere_form_factor(F) - num) > worst) worst = fabs(mf_sphere_form_factor(F) - num);
            }
        snprintf(msg, sizeof msg, "sphere light form factor vs quadrature (worst abs error %.2g)", worst);
        MFT_CHECK(worst < MFT_TOL(2e-6, 2e-5), msg);
    }
    /* multi-scale roughness: Eq. 5 against the mean length it fits (Eq. 4),
     * Eq. 7 against the convolution, whose mean resultant length is the
     * product of the two (Funk-Hecke) */
    {
        double w5 = 0, w7 = 0, a, b;
        for (a = 0.1; a <= 1.0001; a += 0.1) {
            double len = ggx_mean_cos(a), e = fabs(mf_ltc_meso_alpha((mf_real)len) - a);
            if (e > w5) w5 = e;
        }
        for (a = 0.1; a <= 0.9001; a += 0.2)
            for (b = 0.1; b <= 0.9001; b += 0.2) {
                double want = invert_mean_cos(ggx_mean_cos(a) * ggx_mean_cos(b));
                double e = fabs(mf_ltc_combined_alpha((mf_real)a, (mf_real)b) - want);
                if (mft_verbose) printf("    micro %.1f meso %.1f: Eq. 7 %.3f, matched %.3f\n", a, b, (double)mf_ltc_combined_alpha((mf_real)a, (mf_real)b), want);
                if (e > w7) w7 = e;
            }
        printf("    multi-scale: Eq. 5 worst |alpha error| %.3f over alpha 0.1..1; Eq. 7 vs mean-length-matched convolution %.3f\n", w5, w7);
        snprintf(msg, sizeof msg, "Tao Eq. 5 inverts the mean normal length (worst %.3f)", w5);
        MFT_CHECK(w5 < 0.05, msg);
        /* Eq. 7 was fitted to the whole convolved lobe, not to its first moment:
         * measured agreement 0.03 when either roughness is <= 0.1, up to 0.16
         * when both are around 0.5 */
        snprintf(msg, sizeof msg, "Tao Eq. 7 follows the convolution's mean length (worst %.3f)", w7);
        MFT_CHECK(w7 < 0.2, msg);
    }
}
