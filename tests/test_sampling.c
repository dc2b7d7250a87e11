/* Sampling: chi-square tests of mf_sample_D against D(m) m.z and of
 * mf_sample_visible against mf_D_visible, for every distribution and view
 * directions from normal incidence to 86 degrees.
 * Bins: 24 x 24 cells in normalized slope space (X, Y) = slope / (b ax, b ay),
 * b the median of |(X, Y)| over pilot samples, radius mapped by
 * a = (2/pi) atan(R), azimuth uniform. Expected counts come from 6 x 6
 * Gauss-Legendre integration of the density over each cell; cells
 * expecting fewer than 5 samples are pooled. Fail when the Wilson-Hilferty z
 * of the statistic exceeds 5 (p ~ 3e-7 per test; the seeds are fixed).
 * For GTR at non-integer gamma D_visible is normalized by the spline Lambda, so
 * its integral differs from 1 by the spline error (test_ndf); there the
 * expected counts are rescaled to the sample count and the shape is tested. */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

#define NA 24
#define NP 24

typedef struct { const mf_ndf *d; mf_vec3 v; int visible; double bx, by; } dens_ctx;

static double density(const dens_ctx *c, mf_vec3 m)
{
    return c->visible ? (double)mf_D_visible(c->d, c->v, m) : (double)mf_D(c->d, m) * m.z;
}

static int bin_of(const dens_ctx *c, mf_vec3 m)
{
    double X, Y, a, p;
    int ia, ip;
    if (!(m.z > 0)) return -1;
    X = -m.x / (m.z * c->bx); Y = -m.y / (m.z * c->by);
    a = atan(sqrt(X * X + Y * Y)) * 2.0 / 3.14159265358979323846;
    p = atan2(Y, X); if (p < 0) p += 2.0 * 3.14159265358979323846;
    ia = (int)(a * NA); ip = (int)(p / (2.0 * 3.14159265358979323846) * NP);
    if (ia >= NA) ia = NA - 1;
    if (ip >= NP) ip = NP - 1;
    return ia * NP + ip;
}

/* probability of every cell, integrated in (a, psi) */
static void expected(const dens_ctx *c, double *e)
{
    double gx[6], gw[6];
    int ia, ip, i, j;
    const double pi = 3.14159265358979323846;
    mft_gl(6, gx, gw);
    for (ia = 0; ia < NA; ++ia)
        for (ip = 0; ip < NP; ++ip) {
            double s = 0.0;
            for (i = 0; i < 6; ++i)
                for (j = 0; j < 6; ++j) {
                    /* the outer ring reaches the horizon, where D may diverge
                     * (Student-t, gamma < 2): a = 1 - (1 - s)^4 / NA there */
                    double sa = gx[i], da = 1.0 / NA;
                    double a = ia < NA - 1 ? (ia + sa) / NA : 1.0 - pow(1.0 - sa, 4.0) / NA;
                    double psi = (ip + gx[j]) / NP * 2.0 * pi;
                    double R = tan(0.5 * pi * a), dR = 0.5 * pi / (cos(0.5 * pi * a) * cos(0.5 * pi * a));
                    double x = c->bx * R * cos(psi), y = c->by * R * sin(psi);
                    double n2 = 1.0 + x * x + y * y, cz = 1.0 / sqrt(n2);
                    mf_vec3 m = mf_vec3_make((mf_real)(-x * cz), (mf_real)(-y * cz), (mf_real)cz);
                    double jac;
                    if (ia == NA - 1) da = 4.0 * pow(1.0 - sa, 3.0) / NA;
                    jac = cz * cz * cz * c->bx * c->by * R * dR * (2.0 * pi / NP) * da;
                    s += gw[i] * gw[j] * density(c, m) * jac;
                }
            e[ia * NP + ip] = s;
        }
}

static double worst_z = -1e9;

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static void chi2_test(const char *name, const mf_ndf *d, mf_vec3 v, int visible, int n, int rescale, unsigned long long seed)
{
    static double obs[NA * NP], e[NA * NP];
    dens_ctx c;
    mft_rng r;
    int i, dof, bad = 0;
    double z, tot = 0.0;
    char msg[200];
    c.d = d; c.v = v; c.visible = visible;
    memset(obs, 0, sizeof obs);
    /* bin scale: the median normalized slope of 2001 pilot samples (another seed) */
    {
        static double rr[2001];
        int k;
        mft_seed(&r, seed + 999);
        for (k = 0; k < 2001; ++k) {
            double u1 = mft_u01(&r), u2 = mft_u01(&r);
            mf_vec3 m = visible ? mf_sample_visible(d, v, (mf_real)u1, (mf_real)u2) : mf_sample_D(d, (mf_real)u1, (mf_real)u2);
            double X = m.x / (d->ax * m.z), Y = m.y / (d->ay * m.z);
            rr[k] = m.z > 0 ? sqrt(X * X + Y * Y) : 1e30;
        }
        qsort(rr, 2001, sizeof(double), cmp_double);
        c.bx = d->ax * rr[1000]; c.by = d->ay * rr[1000];
    }
    mft_seed(&r, seed);
    for (i = 0; i < n; ++i) {
        double u1 = mft_u01(&r), u2 = mft_u01(&r);
        mf_vec3 m = visible ? mf_sample_visible(d, v, (mf_real)u1, (mf_real)u2) : mf_sample_D(d, (mf_real)u1, (mf_real)u2);
        int b = bin_of(&c, m);
        double len = sqrt((double)mf_dot(m, m));
        if (!(fabs(len - 1.0) < 1e-4)) ++bad;
        if (b >= 0) obs[b] += 1.0;
    }
    expected(&c, e);
    for (i = 0; i < NA * NP; ++i) tot += e[i];
    for (i = 0; i < NA * NP; ++i) e[i] *= rescale ? n / tot : n;
    z = mft_chi2(obs, e, NA * NP, &dof);
    if (z > worst_z) worst_z = z;
    if (z >= 5.0 || getenv("MFT_DUMP")) {
        for (i = 0; i < NA * NP; ++i)
            if (e[i] >= 5.0 && (obs[i] - e[i]) * (obs[i] - e[i]) / e[i] > 12.0)
                printf("    cell a=%d psi=%d obs %.0f exp %.1f\n", i / NP, i % NP, obs[i], e[i]);
    }
    snprintf(msg, sizeof msg, "chi2 %s %s theta_v=%.3f: z=%.2f dof=%d", visible ? "VNDF" : "NDF", name, acos((double)v.z), z, dof);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(z < 5.0, msg);
    snprintf(msg, sizeof msg, "samples are unit vectors %s", name);
    MFT_CHECK(bad == 0, msg);
}

static int is_spline(const mft_case *c)
{
    return c->kind == MF_NDF_GTR && fabs(c->gamma - floor(c->gamma + 0.5)) > 1e-9 && c->ax < 1.0;
}

void test_sampling(void)
{
    const double thetas[] = { 0.0, 0.6, 1.2, 1.5 };
    int i, j;
    const char *only = getenv("MFT_CASE");
    for (i = 0; i < mft_ncases; ++i) {
        const mft_case *cs = &mft_cases[i];
        if (only && !strstr(cs->name, only)) continue;
        mf_ndf d = mft_make(cs);
        int slow = cs->kind == MF_NDF_GTR || cs->kind == MF_NDF_STUDENT_T;
        int n = slow ? 40000 : 200000;
        chi2_test(cs->name, &d, mf_vec3_make(0, 0, 1), 0, 200000, 0, 11 + i);
        for (j = 0; j < 4; ++j)
            chi2_test(cs->name, &d, mft_dir(thetas[j], 0.4 + j), 1, n, is_spline(cs), 100 + 7 * i + j);
    }
    printf("    worst chi-square z over all sampling tests: %.2f (fail above 5)\n", worst_z);
}
