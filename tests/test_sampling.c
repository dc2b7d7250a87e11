/* Sampling: chi-square tests of mf_sample_D against D(m) m.z and of
 * mf_sample_visible against mf_D_visible, for every distribution and view
 * directions from normal incidence to 86 degrees.
 * Bins: 24 x 24 cells in normalized slope space (X, Y) = slope / (b ax, b ay),
 * b the median of |(X, Y)| over pilot samples, radius mapped by
 * a = (2/pi) atan(R), azimuth uniform. Expected counts come from 6 x 6
 * Gauss-Legendre integration of the density over each cell; cells
 * expecting fewer than 5 samples are pooled. Fail when the Wilson-Hilferty z
 * of the statistic exceeds 5 (p ~ 3e-7 per test; the seeds are fixed).
 * Expected counts are never rescaled: D_visible integrates to 1 for every kind
 * (GTR at non-integer gamma included, its Lambda exact; test_ndf), so the
 * counts test the sampler's density against mf_D_visible itself, the pdf that
 * mf_brdf_pdf reports. gtr_student_points adds the GTR and Student-t
 * parameters where the old spline Lambda was worst, views to 89.9 degrees
 * (GTR alpha 1e-4 gamma 1.5 caught the float NDF-CDF tail losing the horizon
 * side); Student-t from gamma 1.6: below, the cells' 6 x 6 rule misses the
 * (1 - a)^-0.9 endpoint of the last ring (test_fuzzfound checks gamma 1.55
 * by the fraction of reflections below the horizon instead). */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

#define NA 24
#define NP 24

typedef struct { const mf_ndf *d; mf_vec3 v; int visible; } dens_ctx;

static double density(mf_vec3 m, void *p)
{
    const dens_ctx *c = (const dens_ctx *)p;
    return c->visible ? (double)mf_D_visible(c->d, c->v, m) : (double)mf_D(c->d, m) * m.z;
}

static double worst_z = -1e9;

/* 1: GTR and Student-t visible normals from the exact numerical inversion
 * (05_numeric_vndf.h) the rejection samplers fall back on */
static int numeric_vndf;

static mf_vec3 draw(const mf_ndf *d, mf_vec3 v, int visible, mft_rng *r)
{
    double u1 = mft_u01(r), u2 = mft_u01(r);
    if (visible && numeric_vndf) {
        int gtr = d->type == MF_NDF_GTR;
        return mf__iso_sample_visible_view(d, gtr ? MF_R(1.0) : d->ax, gtr ? MF_R(1.0) : d->ay, v, (mf_real)u1, (mf_real)u2);
    }
    return visible ? mf_sample_visible(d, v, (mf_real)u1, (mf_real)u2) : mf_sample_D(d, (mf_real)u1, (mf_real)u2);
}

void mft_sampler_check(const char *name, const mf_ndf *d, mf_vec3 v, int visible, int n, int rescale, unsigned long long seed)
{
    static double obs[NA * NP], e[NA * NP], rr[2001];
    dens_ctx c;
    mft_cells cells;
    mft_rng r;
    int i, dof, bad = 0;
    double z, tot = 0.0, med;
    char msg[200];
    c.d = d; c.v = v; c.visible = visible;
    n = MFT_N(n);
    memset(obs, 0, sizeof obs);
    /* cell scale: the median normalized slope of 2001 pilot samples (another seed) */
    mft_seed(&r, seed + 999);
    for (i = 0; i < 2001; ++i) {
        mf_vec3 m = draw(d, v, visible, &r);
        rr[i] = mft_norm_radius(d, m);
    }
    med = mft_median(rr, 2001);
    mft_cells_init(&cells, d, med, NA, NP);
    mft_seed(&r, seed);
    for (i = 0; i < n; ++i) {
        mf_vec3 m = draw(d, v, visible, &r);
        int b = mft_cell_of(&cells, m);
        double len = sqrt((double)mf_dot(m, m));
        if (!(fabs(len - 1.0) < 1e-4)) ++bad;
        if (b >= 0) obs[b] += 1.0;
    }
    mft_cell_probs(&cells, density, &c, 1, e);
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

/* The GTR and Student-t samplers (rejection from GGX, or from GGX mixtures
 * at small alpha) over a grid of alpha, gamma and views, both modes and the
 * switch between them (GTR alpha 0.15 / 0.3 below gamma 2). */
static void gtr_student_grid(void)
{
    const double ag[] = { 1e-3, 0.01, 0.05, 0.15, 0.3, 1.0 }, gg[] = { 0.0, 0.5, 1.0, 1.45, 1.5, 1.9, 2.5, 3.0, 3.7, 4.0 };
    const double as[] = { 1e-3, 0.05, 0.3, 1.0 }, gs[] = { 1.6, 1.75, 1.9, 2.5, 4.0, 30.0, 1000.0 };
    int i, j, n = 0;
    char name[64];
    double worst = 0.0;
    mft_reject_calls = mft_reject_tries = 0;
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 10; ++j, ++n) {
            mf_ndf d = mft_gtr(ag[i], gg[j]);
            snprintf(name, sizeof name, "grid gtr_%g_g%g", ag[i], gg[j]);
            mft_sampler_check(name, &d, mf_vec3_make(0, 0, 1), 0, 20000, 0, 7000 + n);
            mft_sampler_check(name, &d, mft_dir(0.7, 0.2), 1, 20000, 0, 7300 + n);
            mft_sampler_check(name, &d, mft_dir(1.45, 1.1), 1, 20000, 0, 7600 + n);
        }
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 7; ++j, ++n) {
            mf_ndf d = mf_student_t((mf_real)as[i], (mf_real)(as[i] * (j & 1 ? 0.5 : 1.0)), (mf_real)gs[j]);
            snprintf(name, sizeof name, "grid student_%g_g%g", as[i], gs[j]);
            mft_sampler_check(name, &d, mf_vec3_make(0, 0, 1), 0, 20000, 0, 7000 + n);
            mft_sampler_check(name, &d, mft_dir(0.7, 0.2), 1, 20000, 0, 7300 + n);
            mft_sampler_check(name, &d, mft_dir(1.45, 1.1), 1, 20000, 0, 7600 + n);
        }
    /* proposals per sample (pilot samples included), per distribution and overall */
    for (i = 0; i < 6 * 10 + 4 * 7; ++i) {
        mf_ndf d = i < 60 ? mft_gtr(ag[i / 10], gg[i % 10]) : mf_student_t((mf_real)as[(i - 60) / 7], (mf_real)as[(i - 60) / 7], (mf_real)gs[(i - 60) % 7]);
        mft_rng r;
        long c0 = mft_reject_calls, t0 = mft_reject_tries;
        int s, v;
        mft_seed(&r, 91 + i);
        for (v = 0; v < 4; ++v)
            for (s = 0; s < 2000; ++s) {
                mf_vec3 w = mft_dir(v == 3 ? 1.56 : 0.5 * v, 0.3);
                (void)mf_sample_visible(&d, w, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                (void)mf_sample_D(&d, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
            }
        if (mft_reject_calls > c0) {
            double m = (double)(mft_reject_tries - t0) / (double)(mft_reject_calls - c0);
            if (m > worst) worst = m;
        }
    }
    {
        char msg[160];
        snprintf(msg, sizeof msg, "rejection samplers: %.2f proposals per sample on average, worst distribution %.2f",
                 (double)mft_reject_tries / (double)(mft_reject_calls > 0 ? mft_reject_calls : 1), worst);
        if (mft_verbose) printf("    %s\n", msg);
        MFT_CHECK(mft_reject_calls > 0 && worst < 2.1, msg);
    }
}

static void gtr_student_points(void)
{
    const double pg[][2] = { { 0.02, 1.45 }, { 0.02, 1.5 }, { 0.001, 0.5 }, { 0.3, 2.5 }, { 0.0015, 3.7 }, { 1e-4, 1.5 } };
    const double ps[][2] = { { 0.3, 1.6 }, { 0.05, 1.75 }, { 0.2, 30.0 } };
    const double th[] = { 0.0, 1.2, 1.5533430342749532, 1.5690509975429023 };
    int i, j;
    char name[64];
    for (i = 0; i < 9; ++i) {
        mf_ndf d = i < 6 ? mft_gtr(pg[i][0], pg[i][1]) : mf_student_t((mf_real)ps[i - 6][0], (mf_real)ps[i - 6][0], (mf_real)ps[i - 6][1]);
        snprintf(name, sizeof name, "%s_%g_g%g", i < 6 ? "gtr" : "student", i < 6 ? pg[i][0] : ps[i - 6][0], i < 6 ? pg[i][1] : ps[i - 6][1]);
        mft_sampler_check(name, &d, mf_vec3_make(0, 0, 1), 0, 40000, 0, 5000 + i);
        for (j = 0; j < 4; ++j) mft_sampler_check(name, &d, mft_dir(th[j], 0.3 + j), 1, 40000, 0, 5100 + 10 * i + j);
    }
}

/* Power against errors in the GGX-mixture envelopes (GTR at small alpha
 * below gamma 2, Student-t below gamma 2): a piece's weight off by 20% moves
 * D_visible by about 1%, which the grid's 20000 samples miss; 1e6 here catch
 * it for every piece but GTR's third (t/2 sqrt z on [4a^2, 1/4], 0.1-2% of
 * the mass). */
static void gtr_student_mixture_power(void)
{
    const double cfg[][3] = { { 0, 0.02, 1.5 }, { 0, 1e-3, 0.5 }, { 0, 0.05, 1.9 }, { 0, 0.01, 1.0 }, { 0, 1e-3, 1.5 },
                              { 1, 0.3, 1.6 }, { 1, 0.05, 1.75 }, { 1, 0.2, 1.95 } };
    const double th[] = { 0.0, 0.8, 1.4 };
    int i, j;
    char name[64];
    for (i = 0; i < 8; ++i) {
        mf_ndf d = cfg[i][0] == 0.0 ? mft_gtr(cfg[i][1], cfg[i][2])
                                    : mf_student_t((mf_real)cfg[i][1], (mf_real)cfg[i][1], (mf_real)cfg[i][2]);
        snprintf(name, sizeof name, "mixture %s_%g_g%g", cfg[i][0] == 0.0 ? "gtr" : "student", cfg[i][1], cfg[i][2]);
        for (j = 0; j < 3; ++j) mft_sampler_check(name, &d, mft_dir(th[j], 0.4 + j), 1, 1000000, 0, 8100 + 10 * i + j);
    }
}

/* Beckmann visible slopes: the returned slope x along the view inverts the
 * visible-slope CDF F(x) = G(x) / G(1/tv), G(x) = erfc(-x)/2 + tv e^{-x^2}/(2 sqrt(pi))
 * (Heitz & d'Eon 2014 Eq. 9), evaluated here in double, on a dense grid of
 * (u, view) from normal incidence to the horizon, u at 0, 1 and near them.
 * Tolerance: |F(x) - u| <= 8 eps (1 + p(x) (1 + |x|)), p = F', i.e. a few ulps
 * of u plus a few ulps of x. */
static void beckmann_slope_cdf_check(void)
{
    const double k = 0.28209479177387814;
    double worst = 0.0, worst_raw = 0.0, eps = MFT_TOL(2.220446049250313e-16, 1.1920929e-07);
    int iv, iu, n = 0, bad = 0, nonfinite = 0;
    char msg[200];
    for (iv = 0; iv <= 200; ++iv) {
        /* views 0 .. 89.99 deg on a grid denser towards grazing, then 1e3 .. 1e30 */
        double tv = iv <= 180 ? tan((1.0 - pow(1.0 - iv / 180.0, 2.0)) * 89.99 * 3.14159265358979323846 / 180.0)
                              : pow(10.0, 3.0 + 27.0 * (iv - 181) / 19.0);
        double mu = tv > 0.0 ? 1.0 / tv : 1e300;
        double top = tv > 0.0 ? 0.5 * erfc(-mu) + tv * k * exp(-mu * mu) : 1.0;
        for (iu = -6; iu <= 2006; ++iu) {
            double u = iu < 0 ? pow(10.0, -1.0 + iu) : iu > 2000 ? 1.0 - pow(10.0, -8.0 + (iu - 2001)) : iu / 2000.0;
            mf_real sx, sy;
            double x, F, p, err;
            mf__beckmann_visible_slopes((mf_real)tv, (mf_real)u, MF_R(0.5), &sx, &sy);
            x = (double)sx;
            ++n;
            if (!(x == x) || fabs(x) > 1e30) { ++nonfinite; continue; }
            F = x >= mu ? 1.0 : (0.5 * erfc(-x) + tv * k * exp(-x * x)) / top;
            p = x >= mu ? 0.0 : exp(-x * x) * (1.0 - tv * x) / (sqrt(3.14159265358979323846) * top);
            u = (double)(mf_real)u;
            err = fabs(F - u) / (eps * (1.0 + p * (1.0 + fabs(x))));
            if (err > worst) worst = err;
            if (fabs(F - u) > worst_raw) worst_raw = fabs(F - u);
            if (err > 8.0) { ++bad; if (mft_verbose) printf("    off: tv=%.17g u=%.17g x=%.17g err=%.2f\n", tv, u, x, err); }
        }
    }
    printf("    Beckmann visible slope CDF: %d (u, view) points, worst |F(x) - u| = %.3g = %.2f eps-units (fail above 8)\n",
           n, worst_raw, worst);
    snprintf(msg, sizeof msg, "Beckmann visible slope inverts its CDF (%d of %d off, worst %.2f eps units)", bad, n, worst);
    MFT_CHECK(bad == 0, msg);
    MFT_CHECK(nonfinite == 0, "Beckmann visible slopes finite");
}

/* Beckmann visible normals at grazing views (85 to 89.9 degrees), isotropic
 * and anisotropic, alpha 1e-4 to 1: chi-square against D_visible, and every
 * sample finite and in the upper hemisphere even at and past the horizon and
 * for u outside [0, 1]. */
static void beckmann_grazing_check(void)
{
    const double th[] = { 1.4835298641951802, 1.5184364492350666, 1.5533430342749532, 1.5690509975429023 };
    const double al[][2] = { { 0.3, 0.3 }, { 0.05, 0.6 }, { 1.0, 1.0 }, { 1e-4, 1e-4 } };
    const double us[] = { 0.0, 1.0, -0.5, 1.5, 1e-30, 0.5 };
    int a, j, i, i2, bad = 0;
    char name[64];
    for (a = 0; a < 4; ++a) {
        mf_ndf d = mf_beckmann((mf_real)al[a][0], (mf_real)al[a][1]);
        snprintf(name, sizeof name, "beckmann_grazing_%g_%g", al[a][0], al[a][1]);
        for (j = 0; j < 4; ++j)
            if (a < 3) mft_sampler_check(name, &d, mft_dir(th[j], 0.3 + j), 1, 200000, 0, 777 + 5 * a + j);
        for (j = 0; j < 8; ++j) {
            double t = j < 4 ? th[j % 4] : 1.5707963267948966 + 0.1 * (j - 4);
            mf_vec3 w = mf_vec3_make((mf_real)(sin(t) * cos(0.7 * j)), (mf_real)(sin(t) * sin(0.7 * j)), (mf_real)fabs(cos(t)));
            if (j == 4) w = mf_vec3_make(MF_R(1.0), MF_R(0.0), MF_R(0.0));
            for (i = 0; i < 6; ++i)
                for (i2 = 0; i2 < 6; ++i2) {
                    mf_vec3 m = mf_beckmann_sample_visible((mf_real)al[a][0], (mf_real)al[a][1], w, (mf_real)us[i], (mf_real)us[i2]);
                    if (!(m.z >= 0.0 && m.z <= 1.0) || !(m.x == m.x) || !(m.y == m.y)) ++bad;
                }
        }
    }
    MFT_CHECK(bad == 0, "Beckmann visible normals finite, upper hemisphere at grazing, horizon and edge u");
}

/* Beckmann visible normals at exactly normal incidence (the polar closed
 * form, a separate path): the slopes (-m.x / (ax m.z), -m.y / (ay m.z)) of
 * every sample on a (u1, u2) grid, u1 at 0, 1 and near them, must invert
 * the Gaussian's radial CDF 1 - exp(-r^2) at u1 and have azimuth 2 pi u2
 * (evaluated in double); isotropic and anisotropic, alpha 1e-4 to 1e3. */
static void beckmann_normal_check(void)
{
    const double al[][2] = { { 0.3, 0.3 }, { 0.05, 0.6 }, { 1.0, 1.0 }, { 1e-4, 1e-4 }, { 1e3, 2.0 } };
    double eps = MFT_TOL(2.220446049250313e-16, 1.1920929e-07), worst_r = 0.0, worst_a = 0.0;
    int a, i1, i2, n = 0, bad = 0;
    char msg[200];
    for (a = 0; a < 5; ++a)
        for (i1 = -6; i1 <= 206; ++i1)
            for (i2 = 0; i2 <= 200; ++i2) {
                double u1 = i1 < 0 ? pow(10.0, -1.0 + i1) : i1 > 200 ? 1.0 - pow(10.0, -7.0 + (i1 - 201)) : i1 / 200.0;
                double u2 = i2 / 200.0, sx, sy, r2, F, er, ea, d;
                mf_vec3 m = mf_beckmann_sample_visible((mf_real)al[a][0], (mf_real)al[a][1], mf_vec3_make(0, 0, 1), (mf_real)u1, (mf_real)u2);
                u1 = (double)(mf_real)u1; u2 = (double)(mf_real)u2;
                ++n;
                if (!(m.z > 0.0) || !(fabs(sqrt((double)mf_dot(m, m)) - 1.0) < 8 * eps)) { ++bad; continue; }
                sx = -(double)m.x / ((double)(mf_real)al[a][0] * m.z);
                sy = -(double)m.y / ((double)(mf_real)al[a][1] * m.z);
                r2 = sx * sx + sy * sy;
                F = -expm1(-r2);
                er = fabs(F - u1) / (eps * (1.0 + r2 * exp(-r2)));
                if (er > worst_r) worst_r = er;
                if (er > 8.0) ++bad;
                if (r2 > 1e-6 && u1 < 1.0) {   /* azimuth, where defined */
                    d = atan2(sy, sx) - 6.283185307179586 * u2;
                    d -= 6.283185307179586 * floor(d / 6.283185307179586 + 0.5);
                    ea = fabs(d) / eps;
                    if (ea > worst_a) worst_a = ea;
                    if (ea > 16.0) ++bad;
                }
            }
    printf("    Beckmann normal-incidence polar form: %d samples, worst radial CDF %.2f eps-units (fail above 8), azimuth %.2f eps (fail above 16)\n",
           n, worst_r, worst_a);
    snprintf(msg, sizeof msg, "Beckmann normal-incidence visible normals invert the radial CDF and the azimuth (%d of %d off)", bad, n);
    MFT_CHECK(bad == 0, msg);
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
        int slow = cs->kind == MF_NDF_GTR || cs->kind == MF_NDF_STUDENT_T || cs->kind == MF_NDF_CHARLIE;
        int n = slow ? 40000 : 200000;
        mft_sampler_check(cs->name, &d, mf_vec3_make(0, 0, 1), 0, 200000, 0, 11 + i);
        for (j = 0; j < 4; ++j)
            mft_sampler_check(cs->name, &d, mft_dir(thetas[j], 0.4 + j), 1, n, 0, 100 + 7 * i + j);
    }
    if (!only || strstr("gtr_student", only)) {
        gtr_student_points();
        numeric_vndf = 1;   /* the same points through the fallback inversion */
        gtr_student_points();
        numeric_vndf = 0;
        gtr_student_grid();
        gtr_student_mixture_power();
    }
    if (!only || strstr("beckmann_vndf", only)) { beckmann_slope_cdf_check(); beckmann_grazing_check(); beckmann_normal_check(); }
    printf("    worst chi-square z over all sampling tests: %.2f (fail above 5)\n", worst_z);
}
