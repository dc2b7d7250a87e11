/* The specular BRDF: mf_brdf_pdf against the histogram of mf_brdf_sample
 * (chi-square, half-vector cells, plus one cell for "no sample"), the sample
 * weight against f cos / pdf, reciprocity, and the white furnace: the
 * directional albedo integral f cos dwi (numerical quadrature over the half
 * vector) is <= 1 and equals the Monte Carlo mean of the sample weights.
 * Tolerances: weight identity 1e-9 (double) / 2e-4 (float) relative;
 * reciprocity 1e-12 / 1e-5; albedo <= 1 + 1e-6; albedo quadrature vs Monte
 * Carlo within 4 standard errors + 2e-3 (the quadrature crosses the kinks
 * wi.z = 0 and wo.h = 0). */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

#define NA 20
#define NP 20


typedef struct { const mf_ndf *d; mf_vec3 wo; double A[4], jac; } alb_ctx;

/* integrand over normalized half-vector slopes: f cos(wi) |dwi/dwh| dwh/dXdY */
static double f_albedo(double X, double Y, void *p)
{
    alb_ctx *c = (alb_ctx *)p;
    double x = c->A[0] * X + c->A[1] * Y, y = c->A[2] * X + c->A[3] * Y, n = sqrt(1.0 + x * x + y * y), cz = 1.0 / n;
    mf_vec3 h = mf_vec3_make((mf_real)(-x * cz), (mf_real)(-y * cz), (mf_real)cz);
    double oh = mf_dot(c->wo, h);
    mf_vec3 wi;
    if (oh <= 0) return 0.0;
    wi = mf_reflect(c->wo, h);
    if (!(wi.z > 0)) return 0.0;
    return (double)mf_brdf(c->d, c->wo, wi) * wi.z * 4.0 * oh * cz * cz * cz * c->jac;
}

/* density of the half vector of mf_brdf_sample: pdf(wi(h)) |dwi/dh| */
typedef struct { const mf_ndf *d; mf_vec3 wo; } h_ctx;
static double h_density(mf_vec3 h, void *p)
{
    const h_ctx *c = (const h_ctx *)p;
    double oh = mf_dot(c->wo, h);
    if (oh <= 0) return 0.0;
    return (double)mf_brdf_pdf(c->d, c->wo, mf_reflect(c->wo, h)) * 4.0 * oh;
}

void mft_brdf_check(const char *name, mf_ndf d, mf_vec3 wo, int n, unsigned long long seed, int spline)
{
    static double obs[NA * NP + 1], e[NA * NP + 1], rr[2001];
    mft_rng r;
    mft_cells cells;
    h_ctx hc;
    int i, dof, badw = 0, badr = 0;
    double tot = 0.0, sumw = 0.0, sumw2 = 0.0, z, alb, mc, se, norm = 1.0, med;
    char msg[200];
    alb_ctx ac;
    n = MFT_N(n);
    /* cell scale from pilot samples */
    mft_seed(&r, seed + 77);
    for (i = 0; i < 2001; ++i) {
        mf_vec3 wi = mf_brdf_sample(&d, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
        mf_vec3 h = mf_normalize(mf_add(wo, wi));
        rr[i] = wi.z > 0 ? mft_norm_radius(&d, h) : 1e30;
    }
    med = mft_median(rr, 2001);
    if (med >= 1e29) {   /* most views of a sheen (Charlie) reflect below the horizon: the valid ones' median */
        int nv = 0;
        while (nv < 2001 && rr[nv] < 1e29) ++nv;   /* rr is sorted */
        med = nv > 0 ? rr[nv / 2] : 1.0;
    }
    mft_cells_init(&cells, &d, med, NA, NP);
    memset(obs, 0, sizeof obs);
    mft_seed(&r, seed);
    for (i = 0; i < n; ++i) {
        mf_sample smp = mf_brdf_sample(&d, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
        mf_vec3 wi = smp.wi;
        double w;
        if (!(wi.z > 0)) { obs[NA * NP] += 1; if (smp.lobe != MF_LOBE_NONE || smp.pdf != 0 || smp.weight != 0) ++badw; continue; }
        /* the record against the functions: pdf = mf_brdf_pdf, weight = f cos / pdf; reciprocity */
        w = smp.weight;
        {
            double f = mf_brdf(&d, wo, wi), pdf = mf_brdf_pdf(&d, wo, wi), fr = mf_brdf(&d, wi, wo);
            if (!(pdf > 0) || fabs(f * wi.z / pdf - w) > MFT_TOL(1e-9, 2e-4) * w) ++badw;
            if (smp.lobe != MF_LOBE_REFLECTION || fabs((double)smp.pdf - pdf) > MFT_TOL(1e-9, 2e-4) * pdf) ++badw;
            /* LEADR's BRDF normalizes by the mean surface: not reciprocal */
            if (d.type != MF_NDF_LEADR && fabs(f - fr) > MFT_TOL(1e-12, 1e-5) * f) ++badr;
        }
        sumw += w; sumw2 += w * w;
        obs[mft_cell_of(&cells, mf_normalize(mf_add(wo, wi)))] += 1;
    }
    /* expected: 3 x 3 sub-cells, since cells cut by the horizon of wi (where
     * the pdf drops to 0) need the resolution */
    hc.d = &d; hc.wo = wo;
    mft_cell_probs(&cells, h_density, &hc, 3, e);
    for (i = 0; i < NA * NP; ++i) tot += e[i];
    if (spline) norm = mft_visible_integral(&d, wo, 1);   /* integral of D_v with the spline Lambda */
    for (i = 0; i < NA * NP; ++i) e[i] *= n / norm;
    e[NA * NP] = n * (1.0 - tot / norm);
    if (e[NA * NP] < 0) e[NA * NP] = 0;
    z = mft_chi2(obs, e, NA * NP + 1, &dof);
    if (z >= 5.0 || getenv("MFT_DUMP")) {
        double po = 0, pe = 0;
        for (i = 0; i < NA * NP; ++i) if (e[i] < 5.0) { po += obs[i]; pe += e[i];
            if (obs[i] > 0 && getenv("MFT_DUMP")) printf("    pooled cell a=%d psi=%d obs %.0f exp %.3f\n", i / NP, i % NP, obs[i], e[i]); }
        printf("    pooled obs %.0f exp %.1f; no sample obs %.0f exp %.1f\n", po, pe, obs[NA * NP], e[NA * NP]);
    }
    if (z >= 5.0 || getenv("MFT_DUMP"))
        for (i = 0; i <= NA * NP; ++i)
            if (e[i] >= 5.0 && (obs[i] - e[i]) * (obs[i] - e[i]) / e[i] > 12.0)
                printf("    cell %d (a=%d psi=%d) obs %.0f exp %.1f\n", i, i / NP, i % NP, obs[i], e[i]);
    snprintf(msg, sizeof msg, "brdf pdf vs samples %s theta_o=%.2f: z=%.2f dof=%d", name, acos((double)wo.z), z, dof);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(z < 5.0, msg);
    snprintf(msg, sizeof msg, "sample weight = f cos / pdf, %s", name);
    MFT_CHECK(badw == 0, msg);
    snprintf(msg, sizeof msg, "reciprocity f(wo,wi) = f(wi,wo), %s", name);
    MFT_CHECK(badr == 0, msg);
    /* white furnace */
    ac.d = &d; ac.wo = wo;
    mft_slope_map(&d, ac.A);
    ac.jac = fabs(ac.A[0] * ac.A[3] - ac.A[1] * ac.A[2]);
    alb = mft_integrate2(f_albedo, &ac, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, 1.0, 1.0, 48);
    mc = sumw / n;
    se = sqrt(fmax(sumw2 / n - mc * mc, 0.0) / n);   /* the difference rounds below 0 when every weight is ~1 */
    snprintf(msg, sizeof msg, "white furnace albedo <= 1, %s theta_o=%.2f (%.5f)", name, acos((double)wo.z), alb);
    MFT_CHECK(alb <= 1.0 + 1e-6, msg);
    snprintf(msg, sizeof msg, "albedo quadrature vs sampled weights %s theta_o=%.2f", name, acos((double)wo.z));
    MFT_NEAR(mc, alb, 0.0, 4.0 * se + 2e-3 + (spline ? fabs(norm - 1.0) : 0.0), msg);
}

void test_brdf(void)
{
    const double thetas[] = { 0.2, 0.9, 1.45 };
    int i, j;
    const char *only = getenv("MFT_CASE");
    for (i = 0; i < mft_ncases; ++i) {
        const mft_case *cs = &mft_cases[i];
        int slow = cs->kind == MF_NDF_GTR || cs->kind == MF_NDF_STUDENT_T || cs->kind == MF_NDF_CHARLIE;
        int spline = cs->kind == MF_NDF_GTR && fabs(cs->gamma - floor(cs->gamma + 0.5)) > 1e-9 && cs->ax < 1.0;
        if (only && !strstr(cs->name, only)) continue;
        for (j = 0; j < 3; ++j)
            mft_brdf_check(cs->name, mft_make(cs), mft_dir(thetas[j], 1.1 + j), slow ? 30000 : 100000, 500 + 3 * i + j, spline);
    }
    /* below-horizon and degenerate inputs */
    {
        mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
        mf_vec3 up = mft_dir(0.5, 0.0), down = mft_dir(2.0, 0.0);
        MFT_CHECK(mf_brdf(&d, down, up) == 0 && mf_brdf(&d, up, down) == 0, "brdf 0 below the horizon");
        MFT_CHECK(mf_brdf_pdf(&d, down, up) == 0 && mf_brdf_pdf(&d, up, down) == 0, "pdf 0 below the horizon");
        MFT_CHECK(mf_brdf_sample(&d, down, MF_R(0.5), MF_R(0.5)).wi.z == 0, "no sample for wo below the horizon");
        MFT_CHECK(mf_brdf_sample(&d, down, MF_R(0.5), MF_R(0.5)).weight == 0 && mf_brdf_sample(&d, down, MF_R(0.5), MF_R(0.5)).pdf == 0,
                  "no weight, no pdf for wo below the horizon");
    }
}
