/* Robustness sweep: extreme and invalid parameters (alpha 0, 1e-12, huge,
 * negative, NaN, Inf; gamma outside its domain), grazing, normal and
 * below-horizon directions, u = 0 and u -> 1. Every output must be finite;
 * D, Lambda, pdf >= 0; G1, G2 in [0, 1]; samples unit vectors or the zero
 * vector. One check per distribution kind and function family (kind 5:
 * tabulated copies of GGX and anisotropic Beckmann with those parameters;
 * kind 6: Charlie, and Charlie stretched by an alpha of the list). */
#include "mf_test.h"

static int unit_or_zero(mf_vec3 m)
{
    double l = (double)m.x * m.x + (double)m.y * m.y + (double)m.z * m.z;
    if (!mft_finite(l)) return 0;
    return l == 0.0 || fabs(l - 1.0) < 1e-4;
}

void test_robust(void)
{
    const double inf = HUGE_VAL, nan = inf - inf;
    const double alphas[] = { 0.0, 1e-12, 1e-4, 0.02, 0.5, 1.0, 3.0, 1e6, -1.0, nan, inf };
    const double gammas[] = { -1.0, 0.0, 0.5, 1.0, 1.0 + 1e-7, 1.5, 1.55, 2.0, 3.99, 4.0, 7.0, 1e6, nan };
    const double us[] = { 0.0, 1e-12, 1e-7, 0.3, 0.5, 1.0 - 1e-7, 1.0 };
    mf_vec3 dirs[12];
    int kind, ia, ig, i, j, k, l;
    char msg[120];
    dirs[0] = mf_vec3_make(0, 0, 1);
    dirs[1] = mf_vec3_make(1, 0, 0);
    dirs[2] = mf_vec3_make(0, 1, 0);
    dirs[3] = mft_dir(1.5707963, 0.3);            /* z ~ 3e-8 */
    dirs[4] = mf_normalize(mf_vec3_make(1, 1, MF_R(1e-30)));
    dirs[5] = mft_dir(1e-9, 0.0);
    dirs[6] = mft_dir(0.7, 2.0);
    dirs[7] = mft_dir(1.56, -1.0);
    dirs[8] = mf_vec3_make(0, 0, -1);
    dirs[9] = mft_dir(2.0, 0.5);
    dirs[10] = mft_dir(1.5707964, 0.3);           /* just below */
    dirs[11] = mft_dir(0.05, 4.0);
    for (kind = 0; kind < 7; ++kind) {
        int bad_eval = 0, bad_smith = 0, bad_sample = 0, bad_brdf = 0;
        for (ia = 0; ia < 11; ++ia)
            for (ig = 0; ig < (kind >= 2 && kind <= 3 ? 13 : 1); ++ig) {
                mf_real a = (mf_real)alphas[ia], b = (mf_real)alphas[(ia + 3) % 11], g = (mf_real)gammas[ig];
                mf_leadr lm = mf_leadr_with_roughness(mf_leadr_from_slope(a, -b), a, b), l0 = mf_leadr_from_slope(a, b);
                mf_tabulated ta, tb;   /* kind 5: tabulated copies of GGX (a, b) and of anisotropic Beckmann (a, 0) */
                mf_ndf ga = mf_ggx(a, b), gb = mf_beckmann(a, 0);
                mf_ndf d, d0;
                if (kind == 5) {
                    mf_tabulated_from_ndf(&ta, &ga, 24);
                    mf_tabulated_from_ndf(&tb, &gb, 24);
                }
                d = kind == 0 ? mf_beckmann(a, b) : kind == 1 ? mf_ggx(a, b) : kind == 2 ? mf_gtr(a, g)
                  : kind == 3 ? mf_student_t(a, b, g) : kind == 4 ? mf_leadr_ndf(lm) : kind == 5 ? mf_tabulated_ndf(&ta) : mf_charlie(a);
                d0 = kind == 0 ? mf_beckmann(a, 0) : kind == 1 ? mf_ggx(0, a) : kind == 2 ? mf_gtr(0, g)
                   : kind == 3 ? mf_student_t(a, 0, g) : kind == 4 ? mf_leadr_ndf(l0) : kind == 5 ? mf_tabulated_ndf(&tb)
                   : mf_stretched(mf_charlie(b), a);
                for (l = 0; l < 2; ++l) {
                    const mf_ndf *dd = l ? &d0 : &d;
                    for (i = 0; i < 12; ++i) {
                        double D = mf_D(dd, dirs[i]), L = mf_lambda(dd, dirs[i]), A = mf_projected_area(dd, dirs[i]);
                        if (!mft_finite(D) || D < 0 || !mft_finite(L) || L < 0 || !mft_finite(A) || A <= 0) {
                            if (mft_verbose && bad_eval < 5) printf("    eval a=%g b=%g g=%g l=%d dir %d: D=%g L=%g A=%g\n", (double)a, (double)b, (double)g, l, i, D, L, A);
                            ++bad_eval;
                        }
                        for (j = 0; j < 12; ++j) {
                            mf_vec3 wh = mf_normalize(mf_add(dirs[i], dirs[j]));
                            double g1 = mf_G1(dd, dirs[i], dirs[j]), g2 = mf_G2(dd, dirs[i], dirs[j], wh);
                            double g2s = mf_G2_separable(dd, dirs[i], dirs[j], wh), dv = mf_D_visible(dd, dirs[i], dirs[j]);
                            double f = mf_brdf(dd, dirs[i], dirs[j]), p = mf_brdf_pdf(dd, dirs[i], dirs[j]);
                            double w = mf_brdf_sample(dd, dirs[i], (mf_real)j / MF_R(11.0), MF_R(0.37)).weight;
                            if (!(g1 >= 0 && g1 <= 1 && g2 >= 0 && g2 <= 1 && g2s >= 0 && g2s <= 1)) ++bad_smith;
                            if (!mft_finite(dv) || dv < 0) ++bad_smith;
                            if (!mft_finite(f) || f < 0 || !mft_finite(p) || p < 0 || !(w >= 0 && w <= 1)) {
                                if (mft_verbose && bad_brdf < 5) printf("    brdf a=%g b=%g g=%g l=%d dirs %d %d: f=%g p=%g w=%g\n", (double)a, (double)b, (double)g, l, i, j, f, p, w);
                                ++bad_brdf;
                            }
                        }
                        for (j = 0; j < 7; ++j)
                            for (k = 0; k < 7; ++k) {
                                mf_real u1 = (mf_real)us[j], u2 = (mf_real)us[k];
                                mf_vec3 m1 = mf_sample_D(dd, u1, u2), m2 = mf_sample_visible(dd, dirs[i], u1, u2);
                                mf_vec3 wi = mf_brdf_sample(dd, dirs[i], u1, u2).wi;
                                if (!unit_or_zero(m1) || !unit_or_zero(m2) || !unit_or_zero(wi)) ++bad_sample;
                                if (dirs[i].z >= 0 && !(m2.z >= 0)) ++bad_sample;
                            }
                    }
                }
                if (kind == 5) { mf_tabulated_release(&ta); mf_tabulated_release(&tb); }
            }
        snprintf(msg, sizeof msg, "sweep kind %d: D, Lambda, projected area finite and >= 0 (%d bad)", kind, bad_eval);
        MFT_CHECK(bad_eval == 0, msg);
        snprintf(msg, sizeof msg, "sweep kind %d: G1, G2 in [0,1], D_visible finite (%d bad)", kind, bad_smith);
        MFT_CHECK(bad_smith == 0, msg);
        snprintf(msg, sizeof msg, "sweep kind %d: samples unit or zero (%d bad)", kind, bad_sample);
        MFT_CHECK(bad_sample == 0, msg);
        snprintf(msg, sizeof msg, "sweep kind %d: brdf, pdf finite >= 0, weight in [0,1] (%d bad)", kind, bad_brdf);
        MFT_CHECK(bad_brdf == 0, msg);
    }
    /* Fresnel with odd input */
    {
        int bad = 0;
        for (i = 0; i < 11; ++i)
            for (j = 0; j < 11; ++j) {
                double c = i / 5.0 - 1.0, e = alphas[j];
                double fd = mf_fresnel_dielectric((mf_real)c, (mf_real)e), fc = mf_fresnel_conductor((mf_real)c, (mf_real)e, (mf_real)e);
                double fs = mf_fresnel_schlick((mf_real)c, MF_R(0.04));
                if (!(fd >= 0 && fd <= 1) || !(fc >= 0 && fc <= 1) || !(fs >= 0 && fs <= 1)) ++bad;
            }
        MFT_CHECK(bad == 0, "Fresnel in [0,1] for any input");
    }
    /* the lobes of a whole material with odd input: EON, F82-tint, thin film,
     * volumetric sheen. Outputs finite; f, pdf >= 0; reflectances and
     * albedos in [0, 1]; samples a unit direction with positive pdf and
     * finite weight, or the empty record */
    {
        const double vals[] = { -1.0, 0.0, 1e-12, 0.3, 1.0, 1.5, 1e6, nan, inf, -inf };
        int bad_eon = 0, bad_f82 = 0, bad_film = 0, bad_sheen = 0, a, b;
        for (a = 0; a < 10; ++a)
            for (b = 0; b < 10; ++b) {
                mf_real x = (mf_real)vals[a], y = (mf_real)vals[b];
                double f82 = mf_fresnel_f82(x, y, x), f82a = mf_fresnel_f82_average(x, y);
                mf_real eb[3], kb[3], rgb[3];
                double tf, tf2;
                eb[0] = x; eb[1] = y; eb[2] = MF_R(1.5); kb[0] = y; kb[1] = x; kb[2] = MF_R(0.0);
                tf = mf_fresnel_thin_film(x, MF_R(1.0), y, MF_R(300.0), x, y, MF_R(550.0));
                tf2 = mf_fresnel_thin_film(MF_R(0.7), x, MF_R(1.33), y, MF_R(1.5), MF_R(0.0), x);
                mf_fresnel_thin_film_rgb(x, MF_R(1.0), MF_R(1.4), y, eb, kb, rgb);
                if (!(f82 >= 0 && f82 <= 1) || !(f82a >= 0 && f82a <= 1)) ++bad_f82;
                if (!(tf >= 0 && tf <= 1) || !(tf2 >= 0 && tf2 <= 1) || !(rgb[0] >= 0 && rgb[0] <= 1 && rgb[1] >= 0 && rgb[1] <= 1 && rgb[2] >= 0 && rgb[2] <= 1)) ++bad_film;
                for (i = 0; i < 12; ++i) {
                    double ea = mf_eon_albedo(dirs[i].z, x, y), ef = mf_eon_albedo_fast(dirs[i].z, x, y);
                    double eav = mf_eon_albedo_average(x, y), sa = mf_sheen_albedo(dirs[i].z, x);
                    if (!(ea >= 0 && ea <= 1) || !(ef >= 0 && ef <= 1) || !(eav >= 0 && eav <= 1)) ++bad_eon;
                    if (!(sa >= 0 && sa <= 1)) ++bad_sheen;
                    for (j = 0; j < 12; ++j) {
                        double fe = mf_eon_brdf(dirs[i], dirs[j], x, y), pe = mf_eon_pdf(dirs[i], dirs[j], y);
                        double fs = mf_sheen_brdf(dirs[i], dirs[j], x), ps = mf_sheen_pdf(dirs[i], dirs[j], x);
                        if (!mft_finite(fe) || fe < 0 || !mft_finite(pe) || pe < 0) ++bad_eon;
                        if (!mft_finite(fs) || fs < 0 || !mft_finite(ps) || ps < 0) ++bad_sheen;
                    }
                    for (j = 0; j < 7; ++j) {
                        mf_sample se = mf_eon_sample(dirs[i], x, y, (mf_real)us[j], (mf_real)us[(j + 3) % 7]);
                        mf_sample ss = mf_sheen_sample(dirs[i], x, (mf_real)us[j], (mf_real)us[(j + 3) % 7]);
                        if (!mft_record_ok(se) || !unit_or_zero(se.wi)) ++bad_eon;
                        if (!mft_record_ok(ss) || !unit_or_zero(ss.wi)) ++bad_sheen;
                    }
                }
            }
        snprintf(msg, sizeof msg, "odd input: EON brdf, pdf, sample, albedos (%d bad)", bad_eon);
        MFT_CHECK(bad_eon == 0, msg);
        snprintf(msg, sizeof msg, "odd input: F82-tint and its average in [0, 1] (%d bad)", bad_f82);
        MFT_CHECK(bad_f82 == 0, msg);
        snprintf(msg, sizeof msg, "odd input: thin film, exact and RGB, in [0, 1] (%d bad)", bad_film);
        MFT_CHECK(bad_film == 0, msg);
        snprintf(msg, sizeof msg, "odd input: volumetric sheen brdf, pdf, sample, albedo (%d bad)", bad_sheen);
        MFT_CHECK(bad_sheen == 0, msg);
    }
    /* the built-in dielectric compensation with odd eta, alpha and
     * directions: importance albedo in [0, 1], radiance albedo finite >= 0,
     * f and pdf >= 0, samples the record contract */
    {
        const double etas[] = { -1.0, 0.0, 1e-12, 0.5, 1.0, 1.5, 3.0, 1e6, nan, inf };
        const double alph2[] = { 0.0, 1e-6, 0.3, 1.0, 50.0, nan };
        int bad = 0, a, b;
        for (a = 0; a < 10; ++a)
            for (b = 0; b < 6; ++b) {
                mf_ndf d = (b & 1) ? mf_beckmann((mf_real)alph2[b], (mf_real)alph2[b]) : mf_ggx((mf_real)alph2[b], (mf_real)alph2[(b + 2) % 6]);
                mf_real eta = (mf_real)etas[a];
                for (i = 0; i < 12; ++i) {
                    double ei = mf_dielectric_albedo(&d, dirs[i], eta, MF_IMPORTANCE), er = mf_dielectric_albedo(&d, dirs[i], eta, MF_RADIANCE);
                    mf_sample sm = mf_dielectric_bsdf_ms_sample(&d, dirs[i], eta, MF_RADIANCE, (mf_real)us[i % 7], (mf_real)us[(i + 3) % 7], (mf_real)us[(i + 5) % 7]);
                    if (!(ei >= 0 && ei <= 1) || !mft_finite(er) || er < 0) ++bad;
                    /* mft_record_ok wants wi above; transmission goes below */
                    if (sm.lobe == MF_LOBE_NONE ? (sm.pdf != 0 || sm.weight != 0)
                                                : !(sm.pdf > 0 && sm.pdf < MF_BIG && sm.weight >= 0 && sm.weight <= MF_BIG && sm.wi.z != 0)) ++bad;
                    if (!unit_or_zero(sm.wi)) ++bad;
                    for (j = 0; j < 12; j += 3) {
                        double f = mf_dielectric_bsdf_ms(&d, dirs[i], dirs[j], eta, MF_IMPORTANCE), p = mf_dielectric_bsdf_ms_pdf(&d, dirs[i], dirs[j], eta);
                        if (!mft_finite(f) || f < 0 || !mft_finite(p) || p < 0) ++bad;
                    }
                }
            }
        snprintf(msg, sizeof msg, "odd input: built-in dielectric albedo, compensation lobe, pdf, sample (%d bad)", bad);
        MFT_CHECK(bad == 0, msg);
    }
#ifndef MF_NO_LTC_TABLE
    {   /* the anisotropic GGX LTC: every view and pair of alphas */
        int bad_ltc = 0;
        mf_vec3 q[4];
        q[0] = mf_vec3_make(-1, -1, 2); q[1] = mf_vec3_make(1, -1, 2); q[2] = mf_vec3_make(1, 1, 2); q[3] = mf_vec3_make(-1, 1, 2);
        for (i = 0; i < 12; ++i)
            for (ia = 0; ia < 11; ++ia)
                for (j = 0; j < 11; ++j) {
                    mf_ltc lt = mf_ltc_ggx_aniso(dirs[i], (mf_real)alphas[ia], (mf_real)alphas[j]);
                    double al = mf_ltc_ggx_aniso_albedo(dirs[i], (mf_real)alphas[ia], (mf_real)alphas[j]), v = mf_ltc_integrate(&lt, q, 4, 0);
                    for (k = 0; k < 9; ++k) if (!mft_finite(lt.M[k]) || !mft_finite(lt.Minv[k])) ++bad_ltc;
                    if (!(al >= 0 && al <= 1) || !mft_finite(v) || v < 0 || !(lt.det_inv > 0) || !mft_finite(lt.det_inv)) ++bad_ltc;
                }
        snprintf(msg, sizeof msg, "odd input: anisotropic GGX LTC finite, albedo in [0, 1] (%d bad)", bad_ltc);
        MFT_CHECK(bad_ltc == 0, msg);
    }
#endif
    /* tiny alpha: still exact enough to reflect like a mirror */
    {
        mf_ndf d = mf_ggx(0, 0);
        mf_vec3 wo = mft_dir(0.6, 0.2);
        mf_sample smp = mf_brdf_sample(&d, wo, MF_R(0.3), MF_R(0.8));
        MFT_NEAR(smp.wi.z, wo.z, 1e-3, 0, "alpha = 0 (clamped to 1e-4) reflects like a mirror");
        MFT_NEAR(smp.weight, 1.0, 1e-3, 0, "alpha = 0: weight 1");
    }
}
