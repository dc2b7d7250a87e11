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
    if (c->what == 0) return (double)mf_brdf_pdf_bounded(c->d, c->wo, wi);
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
        mf_sample sb0 = mf_brdf_sample_bounded(&d, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
        rr[i] = sb0.lobe ? mft_norm_radius(&iso, sb0.wi) : 1e30;
    }
    /* cells over wi: an isotropic map around the normal, scaled by the samples */
    mft_cells_init(&cells, &iso, mft_median(rr, 2001), NA, NP);
    memset(obs, 0, sizeof obs);
    mft_seed(&r, seed);
    for (i = 0; i < n; ++i) {
        mf_real u1 = (mf_real)mft_u01(&r), u2 = (mf_real)mft_u01(&r);
        mf_sample sbd = mf_brdf_sample_bounded(&d, wo, u1, u2), spl = mf_brdf_sample(&d, wo, u1, u2);
        mf_vec3 wi = sbd.wi;
        double w;
        if (sbd.lobe != MF_LOBE_NONE && !(fabs(sqrt((double)mf_dot(wi, wi)) - 1.0) < 1e-4)) ++nonunit;
        if (sbd.lobe == MF_LOBE_REFLECTION) {
            int b = mft_cell_of(&cells, wi);
            double pdf = (double)mf_brdf_pdf_bounded(&d, wo, wi);
            if (b >= 0) obs[b] += 1.0;
            w = (double)mf_brdf(&d, wo, wi) * (double)wi.z / pdf;
            /* the record: pdf = mf_brdf_pdf_bounded, weight = f cos / pdf */
            if (!(fabs((double)sbd.pdf - pdf) <= MFT_TOL(1e-9, 2e-4) * pdf) || !(fabs((double)sbd.weight - w) <= MFT_TOL(1e-9, 2e-4) * w)) ++nonunit;
            sb += w; sb2 += w * w;
        } else { obs[NA * NP] += 1.0; ++lost_b; if (sbd.pdf != 0 || sbd.weight != 0) ++nonunit; }
        if (spl.lobe == MF_LOBE_REFLECTION) { w = (double)spl.weight; sp += w; sp2 += w * w; }
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
    MFT_CHECK(nonunit == 0, "bounded samples: unit directions, record pdf and weight = the functions'");
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

static void test_materials_helpers(void);
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
            mf_sample a1 = mf_brdf_sample_bounded(d, wo, u1, u2), a2 = mf_brdf_sample(d, wo, u1, u2);
            if (a1.wi.x != a2.wi.x || a1.wi.y != a2.wi.y || a1.wi.z != a2.wi.z || a1.pdf != a2.pdf || a1.weight != a2.weight) same = 0;
            if (mf_brdf_pdf_bounded(d, wo, wi) != mf_brdf_pdf(d, wo, wi)) same = 0;
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
            mf_vec3 m = mf_brdf_sample_bounded(&d, bad[i], MF_R(0.5), nan).wi;
            mf_real p = mf_brdf_pdf_bounded(&d, bad[i], mf_vec3_make(0, 0, 1));
            mf_real q = mf_brdf_pdf_bounded(&d, mf_vec3_make(0, 0, 1), bad[i]);
            if (!mft_finite(m.x) || !mft_finite(m.y) || !mft_finite(m.z) || !mft_finite(p) || !mft_finite(q) || p < 0 || q < 0) ok = 0;
        }
        MFT_CHECK(ok, "bounded VNDF: degenerate input gives finite results, never NaN");
    }
    test_materials_helpers();
}

/* ---- frames, roughness conventions, Fresnel helpers ---- */

static double orth_err(const mf_basis *f)
{
    mf_vec3 c = mf_cross(f->n, f->t);
    double e = 0.0, v[9];
    int i;
    v[0] = fabs((double)mf_dot(f->t, f->t) - 1.0); v[1] = fabs((double)mf_dot(f->b, f->b) - 1.0);
    v[2] = fabs((double)mf_dot(f->n, f->n) - 1.0); v[3] = fabs((double)mf_dot(f->t, f->b));
    v[4] = fabs((double)mf_dot(f->t, f->n)); v[5] = fabs((double)mf_dot(f->b, f->n));
    v[6] = fabs((double)(c.x - f->b.x)); v[7] = fabs((double)(c.y - f->b.y)); v[8] = fabs((double)(c.z - f->b.z));
    for (i = 0; i < 9; ++i) e = v[i] > e || !(v[i] == v[i]) ? (v[i] == v[i] ? v[i] : 1e30) : e;
    return e;
}

/* independent dense integral of 2 F(mu) mu over [0, 1]: Simpson, split at the
 * critical cosine, with F from the textbook Fresnel equations in double */
static double fresnel_avg_ref(double eta, double k, int conductor)
{
    const int n = 200000;
    double a = 0.0, mc = 0.0, sum = 0.0, h;
    int i;
    if (!conductor && eta < 1.0) { mc = sqrt(1.0 - eta * eta); a = mc * mc; }
    h = (1.0 - mc) / n;
    for (i = 0; i <= n; ++i) {
        double mu = mc + i * h, f;
        if (conductor) {   /* |r_s|^2, |r_p|^2 with the complex cosine of transmission */
            double s2 = 1.0 - mu * mu, er = eta * eta - k * k - s2, ei = 2.0 * eta * k, m = sqrt(er * er + ei * ei);
            double cr = sqrt(0.5 * (m + er)), ci = sqrt(0.5 * (m - er)); /* sqrt(n^2 - s2) = cr + i ci */
            double rs = ((mu - cr) * (mu - cr) + ci * ci) / ((mu + cr) * (mu + cr) + ci * ci);
            /* r_p = (N^2 mu - c) / (N^2 mu + c), N^2 = er' + i ei with er' = eta^2 - k^2 */
            double nr = eta * eta - k * k, pr = nr * mu - cr, pi_ = ei * mu - ci, qr = nr * mu + cr, qi = ei * mu + ci;
            double rp = (pr * pr + pi_ * pi_) / (qr * qr + qi * qi);
            f = 0.5 * (rs + rp);
        } else {
            double s2t = (1.0 - mu * mu) / (eta * eta), ct, rs, rp;
            if (s2t >= 1.0) f = 1.0;
            else {
                ct = sqrt(1.0 - s2t);
                rs = (mu - eta * ct) / (mu + eta * ct); rp = (eta * mu - ct) / (eta * mu + ct);
                f = 0.5 * (rs * rs + rp * rp);
            }
        }
        sum += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * 2.0 * f * mu;
    }
    return a + sum * h / 3.0;
}

static void test_materials_helpers(void)
{
    mft_rng r;
    int i, ok;
    double worst = 0.0, e;
    char msg[200];
    mft_seed(&r, 77);
    /* frames from random normals and tangents, and degenerate tangents */
    for (i = 0; i < 20000; ++i) {
        mf_vec3 n = mft_dir(3.14159 * mft_u01(&r), 6.2832 * mft_u01(&r)), tg;
        mf_basis f;
        int kind = i % 5;
        double s = 0.1 + 10.0 * mft_u01(&r);
        n = mf_scale(n, (mf_real)s);   /* not unit */
        if (kind == 0) tg = mft_dir(3.14159 * mft_u01(&r), 6.2832 * mft_u01(&r));
        else if (kind == 1) tg = mf_scale(n, (mf_real)-2.0);                       /* parallel */
        else if (kind == 2) tg = mf_add(n, mf_vec3_make((mf_real)1e-9, 0, 0));    /* nearly parallel */
        else if (kind == 3) tg = mf_vec3_make(0, 0, 0);
        else tg = mf_vec3_make((mf_real)(0.0 * HUGE_VAL), 1, 0);                    /* NaN */
        f = mf_basis_from(n, tg);
        e = orth_err(&f);
        if (e > worst) worst = e;
        if (kind == 0) {
            mf_vec3 lt = mf_to_local(&f, tg), ln = mf_to_local(&f, mf_normalize(n));
            mf_vec3 v = mft_dir(3.0 * mft_u01(&r), 6.28 * mft_u01(&r)), back = mf_to_world(&f, mf_to_local(&f, v));
            e = fabs((double)lt.y) + (lt.x < 0 ? 1.0 : 0.0) + fabs((double)ln.z - 1.0) +
                fabs((double)(back.x - v.x)) + fabs((double)(back.y - v.y)) + fabs((double)(back.z - v.z));
            if (e > worst) worst = e;
        }
    }
    snprintf(msg, sizeof msg, "mf_basis_from: orthonormal, right-handed, tangent in the t-n half plane, round trip: worst %.2g", worst);
    MFT_CHECK(worst < MFT_TOL(1e-12, 2e-6), msg);
    {   /* the LTC frame: wo in the xz half plane with x >= 0; zero / NaN n: identity */
        mf_basis f;
        double w2 = 0.0;
        for (i = 0; i < 2000; ++i) {
            mf_vec3 n = mft_dir(3.14159 * mft_u01(&r), 6.2832 * mft_u01(&r)), wo = mft_dir(3.14159 * mft_u01(&r), 6.2832 * mft_u01(&r));
            mf_vec3 l;
            f = mf_basis_ltc(n, wo);
            l = mf_to_local(&f, wo);
            e = fabs((double)l.y) + (l.x < 0 ? 1.0 : 0.0) + orth_err(&f);
            if (e > w2) w2 = e;
        }
        f = mf_basis_from(mf_vec3_make(0, 0, 0), mf_vec3_make(1, 0, 0));
        MFT_CHECK(w2 < MFT_TOL(1e-12, 2e-6) && f.n.z == MF_R(1.0) && f.t.x == MF_R(1.0), "mf_basis_ltc: wo = (sin, 0, cos); zero normal: identity frame");
    }
    {   /* rotation: D and Lambda of the rotated distribution at R m are the base's at m */
        mf_ndf base = mf_ggx(MF_R(0.5), MF_R(0.1)), bk = mf_beckmann(MF_R(0.4), MF_R(0.15));
        double wd = 0.0;
        for (i = 0; i < 2000; ++i) {
            const mf_ndf *b = i % 2 ? &base : &bk;
            double ang = 6.2832 * mft_u01(&r) - 3.1416, c = cos(ang), s = sin(ang);
            mf_ndf rot = mf_rotated(*b, (mf_real)ang);
            mf_vec3 m = mft_dir(1.4 * mft_u01(&r), 6.28 * mft_u01(&r));
            mf_vec3 rm = mf_vec3_make((mf_real)(c * m.x - s * m.y), (mf_real)(s * m.x + c * m.y), m.z);
            double d0 = (double)mf_D(b, m), d1 = (double)mf_D(&rot, rm), l0 = (double)mf_lambda(b, m), l1 = (double)mf_lambda(&rot, rm);
            e = fabs(d1 - d0) / (d0 + 1e-3) + fabs(l1 - l0) / (l0 + 1e-3);
            if (e > wd) wd = e;
        }
        snprintf(msg, sizeof msg, "mf_rotated: D(R m) and Lambda(R m) of the rotation are the base's at m: worst %.2g", wd);
        MFT_CHECK(wd < MFT_TOL(1e-10, 2e-4), msg);
    }
    {   /* roughness conventions: known points, round trips; sigma is the per-axis
         * slope standard deviation of Beckmann (integrated over slope space) */
        double ex2 = 0.0, sig = 0.21, a = (double)mf_beckmann_alpha_from_sigma((mf_real)sig), hs = a / 30.0;
        mf_ndf bk = mf_beckmann((mf_real)a, (mf_real)a);
        int ix, iy;
        for (ix = -300; ix <= 300; ++ix)
            for (iy = -300; iy <= 300; ++iy) {   /* slope space, P22 = D cos^4 */
                double x = ix * hs, y = iy * hs, c2 = 1.0 / (1.0 + x * x + y * y);
                mf_vec3 m = mf_vec3_make((mf_real)(-x * sqrt(c2)), (mf_real)(-y * sqrt(c2)), (mf_real)sqrt(c2));
                double dA = hs * hs;
                ex2 += x * x * (double)mf_D(&bk, m) * c2 * c2 * dA;
            }
        snprintf(msg, sizeof msg, "Beckmann alpha from sigma: per-axis slope variance %.6f, sigma^2 %.6f", ex2, sig * sig);
        MFT_NEAR(ex2, sig * sig, MFT_TOL(1e-4, 1e-3), 0.0, msg);
        ok = fabs((double)mf_alpha_from_roughness(MF_R(0.5)) - 0.25) < 1e-7 &&
             fabs((double)mf_roughness_from_alpha(mf_alpha_from_roughness(MF_R(0.7))) - 0.7) < 1e-6 &&
             fabs((double)mf_beckmann_sigma_from_alpha(mf_beckmann_alpha_from_sigma(MF_R(0.3))) - 0.3) < 1e-6 &&
             mf_alpha_from_roughness((mf_real)(0.0 * HUGE_VAL)) == MF_R(0.0) && mf_roughness_from_alpha(MF_R(-1.0)) == MF_R(0.0);
        MFT_CHECK(ok, "roughness remaps: r = 0.5 gives alpha 0.25, round trips, NaN and negative give 0");
    }
    {   /* f0 and the index of refraction */
        double w3 = 0.0;
        for (i = 1; i <= 400; ++i) {
            double eta = 1.0 + i * 0.01;
            double f0 = (double)mf_f0_from_ior((mf_real)eta);
            e = fabs(f0 - (double)mf_fresnel_dielectric(MF_R(1.0), (mf_real)eta)) + fabs((double)mf_ior_from_f0((mf_real)f0) - eta) / eta;
            if (e > w3) w3 = e;
        }
        snprintf(msg, sizeof msg, "f0 from ior = Fresnel at normal incidence, ior from f0 round trip (eta 1.01..5): worst %.2g", w3);
        MFT_CHECK(w3 < MFT_TOL(1e-9, 2e-5) && fabs((double)mf_f0_from_ior(MF_R(1.5)) - 0.04) < 1e-7, msg);
        ok = mf_fresnel_schlick_f90(MF_R(1.0), MF_R(0.04), MF_R(0.5)) == MF_R(0.04) &&
             fabs((double)mf_fresnel_schlick_f90(MF_R(0.0), MF_R(0.04), MF_R(0.5)) - 0.5) < 1e-7 &&
             fabs((double)(mf_fresnel_schlick_f90(MF_R(0.3), MF_R(0.2), MF_R(1.0)) - mf_fresnel_schlick(MF_R(0.3), MF_R(0.2)))) < 1e-7;
        MFT_CHECK(ok, "Schlick with f90: f0 at normal incidence, f90 at grazing, f90 = 1 is mf_fresnel_schlick");
    }
    {   /* Gulbrandsen 2014: f0 of the exact Fresnel is r; round trip of r and g */
        double w4 = 0.0;
        int ir, ig;
        for (ir = 0; ir <= 40; ++ir)
            for (ig = 0; ig <= 20; ++ig) {
                double rr = 0.02 + 0.96 * ir / 40.0, gg = ig / 20.0;
                mf_real eta, k, r2, g2;
                mf_conductor_from_artist((mf_real)rr, (mf_real)gg, &eta, &k);
                mf_artist_from_conductor(eta, k, &r2, &g2);
                e = fabs((double)mf_fresnel_conductor(MF_R(1.0), eta, k) - rr) + fabs((double)r2 - rr) + fabs((double)g2 - gg) * (rr < 0.9 ? 1.0 : 0.01);
                if (e > w4) w4 = e;
            }
        snprintf(msg, sizeof msg, "artist conductor (Gulbrandsen): f0 = r, r and g round trip (r 0.02..0.98): worst %.2g", w4);
        MFT_CHECK(w4 < MFT_TOL(1e-8, 2e-3), msg);
    }
    {   /* hemispherical Fresnel averages against a dense independent integral */
        static const double etas[] = { 0.5, 0.67, 0.9, 1.05, 1.33, 1.5, 2.4, 4.0 };
        static const double cond[][2] = { { 0.143, 3.983 }, { 0.2, 3.9 }, { 1.5, 0.5 }, { 2.9, 3.0 }, { 0.05, 0.1 } };
        double w5 = 0.0;
        for (i = 0; i < 8; ++i) {
            e = fabs((double)mf_fresnel_dielectric_average((mf_real)etas[i]) - fresnel_avg_ref(etas[i], 0.0, 0));
            if (mft_verbose) printf("    dielectric %g: %.3g\n", etas[i], e);
            if (e > w5) w5 = e;
        }
        for (i = 0; i < 5; ++i) {
            e = fabs((double)mf_fresnel_conductor_average((mf_real)cond[i][0], (mf_real)cond[i][1]) - fresnel_avg_ref(cond[i][0], cond[i][1], 1));
            if (mft_verbose) printf("    conductor %g %g: %.3g\n", cond[i][0], cond[i][1], e);
            if (e > w5) w5 = e;
        }
        snprintf(msg, sizeof msg, "Fresnel hemispherical averages (dielectric eta 0.5..4, conductors) vs dense integral: worst %.2g (eta 1.5: %.5f)",
                 w5, (double)mf_fresnel_dielectric_average(MF_R(1.5)));
        printf("    %s\n", msg);
        MFT_CHECK(w5 < MFT_TOL(1e-7, 2e-6), msg);
        ok = mft_finite(mf_fresnel_dielectric_average((mf_real)(0.0 * HUGE_VAL))) && mf_fresnel_conductor_average(MF_R(-1.0), MF_R(1.0)) == MF_R(0.0);
        MFT_CHECK(ok, "Fresnel averages: bad input gives 0");
    }
}
