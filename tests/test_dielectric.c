/* Rough dielectric BSDF (Walter et al. 2007), against integrals in double:
 *  - mf_refract: Snell's law, coplanarity, unit length, total internal
 *    reflection exactly where sin i > eta;
 *  - sampling: chi-square of the sampled directions over both hemispheres
 *    (cells of each, Gauss-Legendre in each cell) against mf_dielectric_pdf,
 *    the lost samples in one more bin against 1 - the pdf's integral, for
 *    several kinds (transformed included), eta 1.5, 1/1.5 and 1.33, wo on
 *    both sides;
 *  - weights: mf_dielectric_sample_weight = f |cos| / pdf on every sample;
 *  - energy: the importance-transport albedo (transmission times e^2) is at
 *    most 1, and the sample mean agrees with its quadrature;
 *  - reciprocity f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2;
 *  - the smooth limit (alpha 1e-3): the reflected fraction is the Fresnel
 *    reflectance at wo, the transmitted direction the refraction of wo;
 *  - degenerate input: finite, pdf >= 0. */
#include "mf_test.h"
#include "quad.h"

#define NA 16
#define NP 16
#define NC (NA * NP)

typedef struct { const mf_ndf *d; mf_vec3 wo; mf_real eta; int lower, what; } dctx;

/* over one hemisphere (lower: z flipped): what 0 the pdf, what 1 the
 * importance-transport f |cos| */
static double ddens(mf_vec3 w, void *p)
{
    const dctx *c = (const dctx *)p;
    mf_vec3 wi = c->lower ? mf_vec3_make(w.x, w.y, -w.z) : w;
    if (c->what == 0) return (double)mf_dielectric_pdf(c->d, c->wo, wi, c->eta);
    {
        double f = (double)mf_dielectric_bsdf(c->d, c->wo, wi, c->eta, MF_RADIANCE) * fabs((double)wi.z);
        /* e = eta_i / eta_o across the interface */
        double e = c->wo.z > 0 ? (double)c->eta : 1.0 / (double)c->eta;
        return wi.z * c->wo.z < 0 ? f * e * e : f;
    }
}

static void dielectric_case(const char *name, const mf_ndf *d, double theta, int below, double eta, int n, unsigned long long seed)
{
    static double obs[2 * NC + 1], e[2 * NC + 1], rr[2][1001];
    mft_cells cells[2];
    mf_ndf iso = mf_ggx(MF_R(1.0), MF_R(1.0));
    mf_vec3 wo = mft_dir(theta, 0.4);
    dctx c;
    mft_rng r, rb;
    int i, h, nr[2] = { 0, 0 }, dof, badw = 0;
    double tot = 0.0, z, alb_q = 0.0, alb_s = 0.0, alb_s2 = 0.0, se;
    char msg[220];
    if (below) wo.z = -wo.z;
    c.d = d; c.wo = wo; c.eta = (mf_real)eta;
    /* cells per hemisphere scaled by pilot samples */
    mft_seed(&r, seed + 3);
    for (i = 0; i < 4000 && (nr[0] < 1001 || nr[1] < 1001); ++i) {
        mf_vec3 wi = mf_dielectric_sample(d, wo, (mf_real)eta, MF_RADIANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
        int lo = wi.z < 0;
        if (wi.z == 0 || nr[lo] >= 1001) continue;
        rr[lo][nr[lo]++] = mft_norm_radius(&iso, mf_vec3_make(wi.x, wi.y, lo ? -wi.z : wi.z));
    }
    for (h = 0; h < 2; ++h) mft_cells_init(&cells[h], &iso, nr[h] > 10 ? mft_median(rr[h], nr[h]) : 1.0, NA, NP);
    memset(obs, 0, sizeof obs);
    mft_seed(&r, seed);
    mft_seed(&rb, seed + 1);
    for (i = 0; i < n; ++i) {
        mf_sample smp = mf_dielectric_sample(d, wo, (mf_real)eta, MF_RADIANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
        mf_vec3 wi = smp.wi;
        double pdf, f, w, ew;
        int lo;
        if (wi.z == 0) { obs[2 * NC] += 1.0; continue; }
        lo = wi.z < 0;
        obs[lo * NC + mft_cell_of(&cells[lo], mf_vec3_make(wi.x, wi.y, lo ? -wi.z : wi.z))] += 1.0;
        pdf = (double)mf_dielectric_pdf(d, wo, wi, (mf_real)eta);
        f = (double)mf_dielectric_bsdf(d, wo, wi, (mf_real)eta, MF_RADIANCE);
        w = (double)smp.weight;
        if (!(pdf > 0.0) || !(fabs(w - f * fabs((double)wi.z) / pdf) <= MFT_TOL(1e-6, 2e-3) * (w + 1e-3))) ++badw;
        if (!(fabs((double)smp.pdf - pdf) <= MFT_TOL(1e-6, 2e-3) * pdf) || smp.lobe != (lo == (wo.z < 0) ? MF_LOBE_REFLECTION : MF_LOBE_TRANSMISSION)) ++badw;
        /* importance transport: the same direction, the weight times e^2 on transmission */
        {
            mf_sample si = mf_dielectric_sample(d, wo, (mf_real)eta, MF_IMPORTANCE, (mf_real)mft_u01(&rb), (mf_real)mft_u01(&rb), (mf_real)mft_u01(&rb));
            if (si.lobe == MF_LOBE_TRANSMISSION) {
                double fi = (double)mf_dielectric_bsdf(d, wo, si.wi, (mf_real)eta, MF_IMPORTANCE), pi = (double)mf_dielectric_pdf(d, wo, si.wi, (mf_real)eta);
                double e2 = si.wi.z < 0 ? eta * eta : 1.0 / (eta * eta), fr = (double)mf_dielectric_bsdf(d, wo, si.wi, (mf_real)eta, MF_RADIANCE);
                if (!(fabs(fi - fr * e2) <= MFT_TOL(1e-9, 1e-4) * fi) || !(fabs((double)si.weight - fi * fabs((double)si.wi.z) / pi) <= MFT_TOL(1e-6, 2e-3) * ((double)si.weight + 1e-3))) ++badw;
            }
        }
        ew = wi.z * wo.z < 0 ? w * (wo.z > 0 ? eta * eta : 1.0 / (eta * eta)) : w;   /* importance transport */
        alb_s += ew; alb_s2 += ew * ew;
    }
    for (h = 0; h < 2; ++h) {
        c.lower = h; c.what = 0;
        mft_cell_probs(&cells[h], ddens, &c, 2, e + h * NC);
        c.what = 1;
        {
            static double q[NC];
            mft_cell_probs(&cells[h], ddens, &c, 2, q);
            for (i = 0; i < NC; ++i) alb_q += q[i];
        }
    }
    for (i = 0; i < 2 * NC; ++i) { tot += e[i]; e[i] *= n; }
    e[2 * NC] = tot < 1.0 ? n * (1.0 - tot) : 0.0;
    z = mft_chi2(obs, e, 2 * NC + 1, &dof);
    snprintf(msg, sizeof msg, "dielectric chi2 %s eta %.3f theta %.2f %s: z = %.2f (dof %d), pdf integral %.5f, lost %.4f", name, eta,
             theta, below ? "below" : "above", z, dof, tot, obs[2 * NC] / n);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(z < 5.0, msg);
    MFT_CHECK(tot <= 1.0 + 2e-3, msg);
    snprintf(msg, sizeof msg, "dielectric weight = f |cos| / pdf on every sample: %s eta %.3f theta %.2f (%d bad)", name, eta, theta, badw);
    MFT_CHECK(badw == 0, msg);
    alb_s /= n;
    se = sqrt((alb_s2 / n - alb_s * alb_s) / n);
    snprintf(msg, sizeof msg, "dielectric importance albedo %s eta %.3f theta %.2f %s: sampled %.5f, quadrature %.5f (<= 1)", name, eta,
             theta, below ? "below" : "above", alb_s, alb_q);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(fabs(alb_s - alb_q) < 5.0 * se + 3e-3 && alb_q <= 1.0 + 2e-3, msg);
}

void test_dielectric(void)
{
    mft_rng r;
    int i, k;
    char msg[200];
    {   /* mf_refract */
        int bad = 0, tir_bad = 0;
        mft_seed(&r, 21);
        for (i = 0; i < 20000; ++i) {
            mf_vec3 n = mft_dir(0.5 * mft_u01(&r), 6.28 * mft_u01(&r)), wi = mft_dir(1.55 * mft_u01(&r), 6.28 * mft_u01(&r)), wt, x;
            double eta = 0.4 + 2.6 * mft_u01(&r), si, st;
            int ok;
            /* wi on n's side */
            if (mf_dot(wi, n) < 0) wi = mf_reflect(mf_scale(wi, MF_R(-1.0)), n), wi = mf_scale(wi, MF_R(1.0));
            if (mf_dot(wi, n) < 0) continue;
            ok = mf_refract(wi, n, (mf_real)eta, &wt);

            x = mf_cross(wi, n);
            si = sqrt((double)x.x * x.x + (double)x.y * x.y + (double)x.z * x.z);   /* well conditioned */
            if (ok != (si < eta * (1.0 - 1e-5)) && fabs(si - eta) > 1e-4) ++tir_bad;
            if (!ok) { if (wt.x != 0 || wt.y != 0 || wt.z != 0) ++bad; continue; }
            {
                mf_vec3 y = mf_cross(wt, n);
                st = sqrt((double)y.x * y.x + (double)y.y * y.y + (double)y.z * y.z);
            }
            if (fabs(st * eta - si) > MFT_TOL(1e-10, 2e-5) || fabs((double)mf_dot(wt, x)) > MFT_TOL(1e-10, 2e-5) ||
                fabs((double)mf_dot(wt, wt) - 1.0) > MFT_TOL(1e-12, 1e-6) || !(mf_dot(wt, n) < 0)) ++bad;
        }
        snprintf(msg, sizeof msg, "mf_refract: Snell, coplanar, unit, other side (%d bad); TIR exactly where sin i > eta (%d bad)", bad, tir_bad);
        MFT_CHECK(bad == 0 && tir_bad == 0, msg);
    }
    {   /* sampling, weights, energy over kinds, eta, sides */
        mf_ndf ds[5];
        const char *names[5] = { "ggx 0.3", "beckmann 0.5x0.2", "ggx 0.8", "student 0.3 g3", "transformed ggx 0.3" };
        static const double etas[3] = { 1.5, 1.0 / 1.5, 1.33 };
        static const double th[3] = { 0.3, 1.0, 1.4 };
        ds[0] = mf_ggx(MF_R(0.3), MF_R(0.3));
        ds[1] = mf_beckmann(MF_R(0.5), MF_R(0.2));
        ds[2] = mf_ggx(MF_R(0.8), MF_R(0.8));
        ds[3] = mf_student_t(MF_R(0.3), MF_R(0.3), MF_R(3.0));
        ds[4] = mf_transformed(mf_ggx(MF_R(0.3), MF_R(0.3)), mf_mat2_make(MF_R(1.2), MF_R(0.4), MF_R(0.0), MF_R(0.8)));
        for (k = 0; k < 5; ++k)
            for (i = 0; i < 6; ++i)
                dielectric_case(names[k], &ds[k], th[i % 3], i >= 3, etas[(i + k) % 3], k == 3 ? 30000 : 100000,
                                1000 + 17 * (unsigned long long)k + (unsigned long long)i);
    }
    {   /* reciprocity */
        mf_ndf d = mf_beckmann(MF_R(0.4), MF_R(0.25));
        double worst = 0.0;
        mft_seed(&r, 31);
        for (i = 0; i < 20000; ++i) {
            mf_vec3 a = mft_dir(1.5 * mft_u01(&r), 6.28 * mft_u01(&r)), b = mft_dir(1.5 * mft_u01(&r), 6.28 * mft_u01(&r));
            double eta = i % 2 ? 1.5 : 0.7, fa, fb, na, nb, e;
            if (i % 3 == 0) a.z = -a.z;
            if (i % 5 < 2) b.z = -b.z;
            na = a.z > 0 ? 1.0 : eta; nb = b.z > 0 ? 1.0 : eta;
            fa = (double)mf_dielectric_bsdf(&d, a, b, (mf_real)eta, MF_RADIANCE) / (na * na);
            fb = (double)mf_dielectric_bsdf(&d, b, a, (mf_real)eta, MF_RADIANCE) / (nb * nb);
            if (fa < 1e-4 && fb < 1e-4) continue;
            e = fabs(fa - fb) / fmax(fa, fb);
            if (e > worst) worst = e;
        }
        snprintf(msg, sizeof msg, "dielectric reciprocity f(wo,wi)/eta_o^2 = f(wi,wo)/eta_i^2: worst relative %.2g", worst);
        MFT_CHECK(worst < MFT_TOL(1e-9, 5e-3), msg);
    }
    {   /* smooth limit */
        mf_ndf d = mf_ggx(MF_R(1e-3), MF_R(1e-3));
        for (k = 0; k < 4; ++k) {
            double theta = 0.2 + 0.4 * k, eta = k % 2 ? 1.5 : 1.0 / 1.5, Fr, frac, near;
            int ntr = 0, nnear = 0;
            mf_vec3 wo = mft_dir(theta, 1.0), wt;
            int nrefl = 0, n = 20000, has_t = mf_refract(wo, mf_vec3_make(0, 0, 1), (mf_real)eta, &wt);
            mft_seed(&r, 40 + (unsigned long long)k);
            for (i = 0; i < n; ++i) {
                mf_vec3 wi = mf_dielectric_sample(&d, wo, (mf_real)eta, MF_RADIANCE, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
                if (wi.z > 0) ++nrefl;
                else if (wi.z < 0 && has_t) { ++ntr; nnear += acos(fmin(1.0, (double)mf_dot(wi, wt))) < 0.01; }
            }
            Fr = (double)mf_fresnel_dielectric(wo.z, (mf_real)eta);
            frac = (double)nrefl / n;
            near = ntr ? (double)nnear / ntr : 1.0;
            snprintf(msg, sizeof msg, "dielectric alpha 1e-3, eta %.3f, theta %.1f: reflected %.4f vs Fresnel %.4f, %.3f of the transmitted within 0.01 rad of the refraction",
                     eta, theta, frac, Fr, near);
            MFT_CHECK(fabs(frac - Fr) < 5.0 * sqrt(Fr * (1.0 - Fr) / n) + 1e-3 && near > 0.95, msg);
        }
    }
    {   /* degenerate input */
        mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
        mf_real nan = (mf_real)(0.0 * HUGE_VAL), etas[5];
        mf_vec3 ws[5];
        int ok = 1, a, b, c;
        etas[0] = 0; etas[1] = nan; etas[2] = (mf_real)1e30; etas[3] = MF_R(1.5); etas[4] = MF_R(-1.0);
        ws[0] = mf_vec3_make(0, 0, 0); ws[1] = mf_vec3_make(nan, 0, 1); ws[2] = mf_vec3_make(1, 0, 0);
        ws[3] = mf_vec3_make(0, 0, -1); ws[4] = mf_vec3_make(0.6f, 0, 0.8f);
        for (a = 0; a < 5; ++a)
            for (b = 0; b < 5; ++b)
                for (c = 0; c < 5; ++c) {
                    mf_real f = mf_dielectric_bsdf(&d, ws[a], ws[b], etas[c], MF_RADIANCE), p = mf_dielectric_pdf(&d, ws[a], ws[b], etas[c]);
                    mf_sample smp = mf_dielectric_sample(&d, ws[a], etas[c], MF_RADIANCE, MF_R(0.5), nan, MF_R(0.5));
                    mf_real w = smp.weight;
                    mf_vec3 s = smp.wi;
                    if (!mft_finite(f) || !mft_finite(p) || !mft_finite(w) || p < 0 || f < 0 || !mft_finite(s.x) || !mft_finite(s.z)) {
                        if (mft_verbose) printf("    degenerate %d %d %d: f %g p %g w %g s %g %g %g\n", a, b, c, (double)f, (double)p, (double)w, (double)s.x, (double)s.y, (double)s.z);
                        ok = 0;
                    }
                }
        MFT_CHECK(ok, "dielectric: degenerate directions and eta give finite values, pdf >= 0");
    }
}
