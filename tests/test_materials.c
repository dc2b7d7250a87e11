/* Materials: GGX bounded visible-normal sampling (Eto & Tokuyoshi 2023).
 * Checked against integrals in double over the reflected directions wi (cells
 * of the upper hemisphere, Gauss-Legendre in each, as test_sampling; in wi the
 * densities are smooth up to the horizon):
 *  - the reflected directions follow mf_ggx_brdf_pdf_bounded (chi-square), the
 *    lost samples (reflection below the horizon) counted in one extra bin
 *    against 1 - the integral of the pdf over the upper hemisphere;
 *  - the samples lost are never more than with plain VNDF sampling, and none
 *    for isotropic GGX at normal incidence (there the cap is exact);
 *  - the estimator f cos / pdf of the albedo is unbiased (its mean against
 *    the integral of f cos and against plain VNDF sampling's) and its
 *    variance is at most plain VNDF's; the variance ratio at grazing views is
 *    printed. Views 0 to 87 degrees (83 for alpha < 0.3, whose lobe at 87 is
 *    a peak at the horizon finer than the cells' quadrature);
 *  - other kinds fall back to mf_sample_visible / mf_brdf_pdf exactly;
 *  - degenerate input gives the zero vector / 0, never NaN. */
#include "mf_test.h"
#include "quad.h"

#define NA 20
#define NP 20

typedef struct { const mf_ndf *d; mf_vec3 wo; int what; } bctx;

/* over wi: what 0, the bounded sampler's density; what 1, f cos (albedo) */
static double bdens(mf_vec3 wi, void *p)
{
    const bctx *c = (const bctx *)p;
    if (c->what == 0) return (double)mf_ggx_brdf_pdf_bounded(c->d, c->wo, wi);
    return (double)mf_brdf(c->d, c->wo, wi) * (double)wi.z;
}

static void bounded_case(double ax, double ay, double theta, double phi, unsigned long long seed, double *vratio)
{
    static double obs[NA * NP + 1], e[NA * NP + 1], rr[2001];
    mf_ndf d = mf_ggx((mf_real)ax, (mf_real)ay), iso = mf_ggx(MF_R(1.0), MF_R(1.0));
    mf_vec3 wo = mft_dir(theta, phi);
    bctx c;
    mft_cells cells;
    mft_rng r;
    const int n = 200000;
    int i, dof, lost_b = 0, lost_p = 0, nonunit = 0;
    double up = 0.0, alb = 0.0, sb = 0.0, sb2 = 0.0, sp = 0.0, sp2 = 0.0, z, vb, vp, se;
    char msg[200];
    c.d = &d; c.wo = wo;
    mft_seed(&r, seed + 7);
    for (i = 0; i < 2001; ++i) {
        mf_vec3 m = mf_ggx_sample_visible_bounded(&d, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
        rr[i] = mft_norm_radius(&iso, mf_reflect(wo, m));
    }
    /* cells over wi: an isotropic map around the normal, scaled by the samples */
    mft_cells_init(&cells, &iso, mft_median(rr, 2001), NA, NP);
    memset(obs, 0, sizeof obs);
    mft_seed(&r, seed);
    for (i = 0; i < n; ++i) {
        mf_real u1 = (mf_real)mft_u01(&r), u2 = (mf_real)mft_u01(&r);
        mf_vec3 m = mf_ggx_sample_visible_bounded(&d, wo, u1, u2), wi = mf_reflect(wo, m);
        mf_vec3 mp = mf_sample_visible(&d, wo, u1, u2), wp = mf_reflect(wo, mp);
        double w;
        if (!(fabs(sqrt((double)mf_dot(m, m)) - 1.0) < 1e-4)) ++nonunit;
        if (wi.z > 0 && mf_dot(wo, m) > 0) {
            int b = mft_cell_of(&cells, wi);
            if (b >= 0) obs[b] += 1.0;
            w = (double)mf_brdf(&d, wo, wi) * (double)wi.z / (double)mf_ggx_brdf_pdf_bounded(&d, wo, wi);
            sb += w; sb2 += w * w;
        } else { obs[NA * NP] += 1.0; ++lost_b; }
        if (wp.z > 0) { w = (double)mf_brdf_sample_weight(&d, wo, wp); sp += w; sp2 += w * w; }
        else ++lost_p;
    }
    c.what = 0;
    mft_cell_probs(&cells, bdens, &c, 6, e);
    for (i = 0; i < NA * NP; ++i) { up += e[i]; e[i] *= n; }
    e[NA * NP] = n * (1.0 - up);
    if (e[NA * NP] < 0.0) e[NA * NP] = 0.0;
    z = mft_chi2(obs, e, NA * NP + 1, &dof);
    snprintf(msg, sizeof msg, "bounded VNDF chi2 ggx %gx%g theta %.2f: z = %.2f (dof %d), lost %.4f (plain %.4f)",
             ax, ay, theta, z, dof, (double)lost_b / n, (double)lost_p / n);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(z < 5.0, msg);
    snprintf(msg, sizeof msg, "bounded VNDF loses no more than plain: ggx %gx%g theta %.2f (%d vs %d)", ax, ay, theta, lost_b, lost_p);
    MFT_CHECK(lost_b <= lost_p && (theta > 0.0 || ax != ay || lost_b == 0), msg);
    MFT_CHECK(nonunit == 0, "bounded VNDF normals are unit vectors");
    /* unbiased albedo estimator, and its variance against plain VNDF */
    c.what = 1;
    mft_cell_probs(&cells, bdens, &c, 6, e);
    for (i = 0; i < NA * NP; ++i) alb += e[i];
    sb /= n; sp /= n;
    vb = sb2 / n - sb * sb; vp = sp2 / n - sp * sp;
    se = sqrt(vb / n) + sqrt(vp / n);
    snprintf(msg, sizeof msg, "bounded VNDF albedo estimate ggx %gx%g theta %.2f: %.5f vs integral %.5f (plain %.5f)", ax, ay,
             theta, sb, alb, sp);
    MFT_CHECK(fabs(sb - alb) < 5.0 * se + MFT_TOL(2e-4, 1e-3) && fabs(sb - sp) < 5.0 * se, msg);
    snprintf(msg, sizeof msg, "bounded VNDF variance <= plain: ggx %gx%g theta %.2f (%.3g vs %.3g)", ax, ay, theta, vb, vp);
    MFT_CHECK(vb <= vp * 1.0001 + 1e-12, msg);
    if (vratio) *vratio = vb > 0.0 ? vp / vb : 1.0;
}

void test_materials(void)
{
    static const double th[] = { 0.0, 0.6, 1.2, 1.4, 1.52 };
    static const double al[][2] = { { 0.1, 0.1 }, { 0.5, 0.5 }, { 1.0, 1.0 }, { 0.6, 0.15 }, { 0.08, 0.4 } };
    double ratio[3][3];
    int a, t, i;
    for (a = 0; a < 5; ++a)
        for (t = 0; t < 5; ++t) {
            double vr = 1.0;
            /* at 87 deg a lobe of alpha < 0.3 is a thin peak at the horizon,
             * finer than the cells' quadrature: 83 deg there */
            double theta = t == 4 && (al[a][0] < 0.3 || al[a][1] < 0.3) ? 1.45 : th[t];
            bounded_case(al[a][0], al[a][1], theta, 0.3 + 1.1 * a, 100 + 10 * (unsigned long long)a + (unsigned long long)t, &vr);
            if (a < 3 && t >= 2) ratio[a][t - 2] = vr;
        }
    printf("    bounded VNDF: albedo-estimator variance of plain / bounded, GGX alpha 0.1, 0.5, 1 at 69, 80, 87 (0.1: 83) deg: "
           "%.2f %.2f %.2f | %.2f %.2f %.2f | %.2f %.2f %.2f\n", ratio[0][0], ratio[0][1], ratio[0][2], ratio[1][0],
           ratio[1][1], ratio[1][2], ratio[2][0], ratio[2][1], ratio[2][2]);
    {   /* other kinds and transformed GGX: the plain sampler and pdf */
        mf_ndf ds[3];
        mft_rng r;
        int same = 1;
        ds[0] = mf_beckmann(MF_R(0.3), MF_R(0.2));
        ds[1] = mf_transformed(mf_ggx(MF_R(0.3), MF_R(0.3)), mf_mat2_make(MF_R(1.0), MF_R(0.4), MF_R(0.0), MF_R(0.7)));
        ds[2] = mf_student_t(MF_R(0.3), MF_R(0.3), MF_R(3.0));
        mft_seed(&r, 5);
        for (i = 0; i < 300; ++i) {
            mf_ndf *d = &ds[i % 3];
            mf_vec3 wo = mft_dir(1.5 * mft_u01(&r), 6.28 * mft_u01(&r)), wi = mft_dir(1.5 * mft_u01(&r), 6.28 * mft_u01(&r));
            mf_real u1 = (mf_real)mft_u01(&r), u2 = (mf_real)mft_u01(&r);
            mf_vec3 a1 = mf_ggx_sample_visible_bounded(d, wo, u1, u2), a2 = mf_sample_visible(d, wo, u1, u2);
            if (a1.x != a2.x || a1.y != a2.y || a1.z != a2.z) same = 0;
            if (mf_ggx_brdf_pdf_bounded(d, wo, wi) != mf_brdf_pdf(d, wo, wi)) same = 0;
        }
        MFT_CHECK(same, "bounded VNDF: other kinds and transformed GGX use the plain sampler and pdf");
    }
    {   /* degenerate input */
        mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
        mf_real nan = (mf_real)(0.0 * HUGE_VAL), big = (mf_real)1e30;
        mf_vec3 bad[5];
        int ok = 1;
        bad[0] = mf_vec3_make(0, 0, -1); bad[1] = mf_vec3_make(0, 0, 0); bad[2] = mf_vec3_make(nan, 0, 1);
        bad[3] = mf_vec3_make(1, 0, 0); bad[4] = mf_vec3_make(big, big, big);
        for (i = 0; i < 5; ++i) {
            mf_vec3 m = mf_ggx_sample_visible_bounded(&d, bad[i], MF_R(0.5), nan);
            mf_real p = mf_ggx_brdf_pdf_bounded(&d, bad[i], mf_vec3_make(0, 0, 1));
            mf_real q = mf_ggx_brdf_pdf_bounded(&d, mf_vec3_make(0, 0, 1), bad[i]);
            if (!mft_finite(m.x) || !mft_finite(m.y) || !mft_finite(m.z) || !mft_finite(p) || !mft_finite(q) || p < 0 || q < 0) ok = 0;
        }
        MFT_CHECK(ok, "bounded VNDF: degenerate input gives finite results, never NaN");
    }
}
