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

typedef struct { const mf_ndf *d; mf_vec3 v; int visible; } dens_ctx;

static double density(mf_vec3 m, void *p)
{
    const dens_ctx *c = (const dens_ctx *)p;
    return c->visible ? (double)mf_D_visible(c->d, c->v, m) : (double)mf_D(c->d, m) * m.z;
}

static double worst_z = -1e9;

static mf_vec3 draw(const mf_ndf *d, mf_vec3 v, int visible, mft_rng *r)
{
    double u1 = mft_u01(r), u2 = mft_u01(r);
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
        mft_sampler_check(cs->name, &d, mf_vec3_make(0, 0, 1), 0, 200000, 0, 11 + i);
        for (j = 0; j < 4; ++j)
            mft_sampler_check(cs->name, &d, mft_dir(thetas[j], 0.4 + j), 1, n, is_spline(cs), 100 + 7 * i + j);
    }
    printf("    worst chi-square z over all sampling tests: %.2f (fail above 5)\n", worst_z);
}
