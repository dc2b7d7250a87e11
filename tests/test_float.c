/* Float and double builds agree: the same functions compiled in the other
 * precision (tests/ref_other.c) are compared on random inputs.
 * Tolerances (relative): D, 1 + Lambda, pdf and brdf 2e-4 where the value is
 * above 1e-3 of its peak scale (float resolution near steep peaks and the
 * float incomplete beta); samples from the same (u1, u2): angle below 2e-3 rad
 * except within 1e-4 of a branch (u at the edge of the analytic region). */
#include "mf_test.h"
#include "ref_other.h"

void test_float(void)
{
    int c, i, badD = 0, badL = 0, badF = 0, badS = 0, n = 0, ns = 0;
    double worst_s = 0.0;
    mft_rng r;
    char msg[120];
    mft_seed(&r, 99);
    for (c = 0; c < mft_ncases; ++c) {
        const mft_case *cs = &mft_cases[c];
        mf_ndf d = mft_make(cs);
        for (i = 0; i < 300; ++i) {
            mf_vec3 wo = mft_dir(1.5 * mft_u01(&r), 6.283 * mft_u01(&r)), wi = mft_dir(1.5 * mft_u01(&r), 6.283 * mft_u01(&r));
            mf_vec3 wm = mf_sample_D(&d, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
            double vo[3], vi[3], vm[3], sm[3];
            double u1 = mft_u01(&r), u2 = mft_u01(&r), D, Dr, L, Lr, f, fr, p, pr, ang;
            mf_vec3 m;
            vo[0] = wo.x; vo[1] = wo.y; vo[2] = wo.z; vi[0] = wi.x; vi[1] = wi.y; vi[2] = wi.z;
            vm[0] = wm.x; vm[1] = wm.y; vm[2] = wm.z;
            D = mf_D(&d, wm); Dr = ref_D(cs->kind, cs->ax, cs->ay, cs->gamma, vm);
            if (fabs(D - Dr) > 2e-4 * fabs(Dr) + 1e-3 * mf_D(&d, mf_vec3_make(0, 0, 1))) ++badD;
            L = mf_lambda(&d, wo); Lr = ref_lambda(cs->kind, cs->ax, cs->ay, cs->gamma, vo);
            if (fabs(L - Lr) > 2e-4 * (1.0 + Lr)) ++badL;
            f = mf_brdf(&d, wo, wi); fr = ref_brdf(cs->kind, cs->ax, cs->ay, cs->gamma, vo, vi);
            p = mf_brdf_pdf(&d, wo, wi); pr = ref_brdf_pdf(cs->kind, cs->ax, cs->ay, cs->gamma, vo, vi);
            if (fabs(f - fr) > 2e-4 * fr + 1e-6 || fabs(p - pr) > 2e-4 * pr + 1e-6) ++badF;
            m = mf_sample_visible(&d, wo, (mf_real)u1, (mf_real)u2);
            ref_sample_visible(cs->kind, cs->ax, cs->ay, cs->gamma, vo, u1, u2, sm);
            ang = sqrt((m.x - sm[0]) * (m.x - sm[0]) + (m.y - sm[1]) * (m.y - sm[1]) + (m.z - sm[2]) * (m.z - sm[2]));
            if (ang > worst_s) worst_s = ang;
            if (ang > 2e-3) ++badS;
            ++n; ++ns;
        }
    }
    snprintf(msg, sizeof msg, "float/double D agree (%d of %d off)", badD, n);
    MFT_CHECK(badD == 0, msg);
    snprintf(msg, sizeof msg, "float/double Lambda agree (%d of %d off)", badL, n);
    MFT_CHECK(badL == 0, msg);
    snprintf(msg, sizeof msg, "float/double brdf and pdf agree (%d of %d off)", badF, n);
    MFT_CHECK(badF == 0, msg);
    snprintf(msg, sizeof msg, "float/double visible samples agree (%d of %d off, worst %.2g)", badS, ns, worst_s);
    MFT_CHECK(badS == 0, msg);
    if (mft_verbose) printf("    worst sample distance %.3g\n", worst_s);
}
