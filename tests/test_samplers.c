/* Every sampler at the corners of its random numbers (0.4 rule): u in
 * {0, 2^-24, 0.5, 1 - 2^-24, 1} in every coordinate combination, views from
 * normal incidence to 89.99 degrees, every kind. A sample is either none
 * (lobe MF_LOBE_NONE, wi = 0, pdf = 0, weight = 0) or a unit direction on
 * the side its lobe names whose record pdf is positive, finite and equal to
 * the lobe's pdf function, and whose weight is finite and equal to
 * f |wi.z| / pdf from the lobe's evaluation. */
#include "mf_test.h"

static const double mfs_u[5] = { 0.0, 5.9604644775390625e-8, 0.5, 0.99999994039535522, 1.0 };

typedef struct { int none_bad, unit_bad, side_bad, pdf_bad, weight_bad, count, some; } mfs_tally;

/* record checks against the pdf and f |wi.z| / pdf computed by the caller */
static void mfs_check(mfs_tally *t, mf_sample s, mf_vec3 wo, int two_sided, double pdf, double fcos)
{
    double l, rel = MFT_TOL(1e-6, 2e-3);
    ++t->count;
    if (s.lobe == MF_LOBE_NONE) {
        if (s.pdf != 0 || s.weight != 0 || s.wi.x != 0 || s.wi.y != 0 || s.wi.z != 0) ++t->none_bad;
        return;
    }
    ++t->some;
    l = (double)s.wi.x * s.wi.x + (double)s.wi.y * s.wi.y + (double)s.wi.z * s.wi.z;
    if (!(fabs(l - 1.0) < 1e-4)) ++t->unit_bad;
    if (s.lobe == MF_LOBE_REFLECTION ? !(s.wi.z * wo.z > 0) : (!two_sided || !(s.wi.z * wo.z < 0))) ++t->side_bad;
    if (!(s.pdf > 0) || !mft_finite(s.pdf) || !(fabs((double)s.pdf - pdf) <= rel * pdf)) ++t->pdf_bad;
    if (!mft_finite(s.weight) || !(s.weight >= 0) || !(fabs((double)s.weight - fcos / pdf) <= rel * ((double)s.weight + 1e-6))) ++t->weight_bad;
}

static void mfs_report_min(const char *name, const mfs_tally *t, int min_some)
{
    char msg[200];
    snprintf(msg, sizeof msg, "%s: %d corner samples (%d directions): none records empty %d, unit %d, side %d, pdf %d, weight %d bad",
             name, t->count, t->some, t->none_bad, t->unit_bad, t->side_bad, t->pdf_bad, t->weight_bad);
    MFT_CHECK(t->count > 0 && t->some >= min_some && !t->none_bad && !t->unit_bad && !t->side_bad && !t->pdf_bad && !t->weight_bad, msg);
}

static void mfs_report(const char *name, const mfs_tally *t) { mfs_report_min(name, t, t->count / 4 + 1); }

/* views: theta in {0, 30, 60, 80, 89, 89.99} degrees at two azimuths */
#define MFS_NV 12
static mf_vec3 mfs_view(int k)
{
    static const double th[6] = { 0.0, 30.0, 60.0, 80.0, 89.0, 89.99 };
    return mft_dir(th[k % 6] * 3.14159265358979323846 / 180.0, k < 6 ? 0.0 : 2.2);
}

void test_samplers(void)
{
    mf_ndf ds[32];
    const char *names[32];
    int nd = 0, k, v, a, b, c;
    mf_tabulated tab;
    mf_ndf g3 = mf_ggx(MF_R(0.3), MF_R(0.3));
    mfs_tally tb, tbb, tdr, tdi, tms, tdm, tnd;
    memset(&tb, 0, sizeof tb); tbb = tdr = tdi = tms = tdm = tnd = tb;
    for (k = 0; k < mft_ncases; ++k) { names[nd] = mft_cases[k].name; ds[nd++] = mft_make(&mft_cases[k]); }
    names[nd] = "transformed ggx"; ds[nd++] = mf_transformed(mf_ggx(MF_R(0.3), MF_R(0.3)), mf_mat2_make(MF_R(1.0), MF_R(0.4), MF_R(0.0), MF_R(0.7)));
    names[nd] = "leadr"; ds[nd++] = mf_leadr_ndf(mf_leadr_with_roughness(mf_leadr_from_slope(MF_R(0.1), MF_R(-0.05)), MF_R(0.2), MF_R(0.3)));
    if (mf_tabulated_from_ndf(&tab, &g3, 32) == MF_SUCCESS) { names[nd] = "tabulated"; ds[nd++] = mf_tabulated_ndf(&tab); }
    for (k = 0; k < nd; ++k) {
        const mf_ndf *d = &ds[k];
        for (v = 0; v < MFS_NV; ++v) {
            mf_vec3 wo = mfs_view(v);
            for (a = 0; a < 5; ++a)
                for (b = 0; b < 5; ++b) {
                    mf_real u1 = (mf_real)mfs_u[a], u2 = (mf_real)mfs_u[b];
                    mf_sample s = mf_brdf_sample(d, wo, u1, u2);
                    mf_vec3 m = mf_sample_D(d, u1, u2), mv = mf_sample_visible(d, wo, u1, u2);
                    mfs_check(&tb, s, wo, 0, mf_brdf_pdf(d, wo, s.wi), (double)mf_brdf(d, wo, s.wi) * s.wi.z);
                    s = mf_brdf_sample_bounded(d, wo, u1, u2);
                    mfs_check(&tbb, s, wo, 0, mf_brdf_pdf_bounded(d, wo, s.wi), (double)mf_brdf(d, wo, s.wi) * s.wi.z);
                    /* the compensation lobe at a quarter of the kinds; a kind without a
                     * built-in albedo table integrates its albedo at each call (the
                     * normal view; every view under --full) */
                    if (k % 4 == 0 && (d->type == MF_NDF_GGX || d->type == MF_NDF_BECKMANN || v == 0 || mft_full)) {
                        s = mf_brdf_ms_sample(d, wo, u1, u2);
                        mfs_check(&tms, s, wo, 0, mf_brdf_ms_pdf(d, wo, s.wi), (double)mf_brdf_ms(d, wo, s.wi) * s.wi.z);
                    }
                    /* the distribution samplers: unit normals where D is positive; a
                     * visible normal at u2 = 1 lies on the view's visibility horizon
                     * (wo.m = 0 up to rounding), which the lobe samplers reject */
                    ++tnd.count;
                    if (!(fabs((double)mf_dot(m, m) - 1.0) < 1e-4) || !(mf_D(d, m) > 0)) ++tnd.unit_bad;
                    if (mv.x != 0 || mv.y != 0 || mv.z != 0) {
                        ++tnd.some;
                        if (!(fabs((double)mf_dot(mv, mv) - 1.0) < 1e-4) || !(mf_D(d, mv) > 0) || !(mf_dot(wo, mv) > -MFT_TOL(1e-12, 1e-5))) ++tnd.pdf_bad;
                    }
                    for (c = 0; c < 5; ++c) {
                        int side;
                        for (side = 0; side < 2; ++side) {
                            mf_vec3 w = side ? mf_vec3_make(wo.x, wo.y, -wo.z) : wo;
                            mf_real eta = MF_R(1.5);
                            mf_sample sr = mf_dielectric_sample(d, w, eta, MF_RADIANCE, u1, u2, (mf_real)mfs_u[c]);
                            mf_sample si = mf_dielectric_sample(d, w, eta, MF_IMPORTANCE, u1, u2, (mf_real)mfs_u[c]);
                            mfs_check(&tdr, sr, w, 1, mf_dielectric_pdf(d, w, sr.wi, eta),
                                      (double)mf_dielectric_bsdf(d, w, sr.wi, eta, MF_RADIANCE) * fabs((double)sr.wi.z));
                            mfs_check(&tdi, si, w, 1, mf_dielectric_pdf(d, w, si.wi, eta),
                                      (double)mf_dielectric_bsdf(d, w, si.wi, eta, MF_IMPORTANCE) * fabs((double)si.wi.z));
                        }
                    }
                }
        }
    }
    mfs_report("mf_brdf_sample", &tb);
    mfs_report("mf_brdf_sample_bounded", &tbb);
    mfs_report("mf_brdf_ms_sample", &tms);
    mfs_report("mf_dielectric_sample (radiance)", &tdr);
    mfs_report("mf_dielectric_sample (importance)", &tdi);
    {
        char msg[160];
        snprintf(msg, sizeof msg, "mf_sample_D / mf_sample_visible at corner u: unit normals of positive density (%d, %d bad)",
                 tnd.unit_bad, tnd.pdf_bad);
        MFT_CHECK(tnd.count > 0 && tnd.some > tnd.count / 2 && !tnd.unit_bad && !tnd.pdf_bad, msg);
    }
    {   /* the compensation lobe of a rough dielectric, from its table */
        mf_dielectric_ms_table t;
        mf_ndf g = mf_ggx(MF_R(0.5), MF_R(0.5));
        if (mf_dielectric_ms_table_build(&t, &g, MF_R(1.5), 16, 2) == MF_SUCCESS) {
            int mode;
            for (mode = 0; mode < 2; ++mode)
                for (v = 0; v < MFS_NV; ++v)
                    for (a = 0; a < 125; ++a) {
                        int side;
                        for (side = 0; side < 2; ++side) {
                            mf_vec3 wo = mfs_view(v), w = side ? mf_vec3_make(wo.x, wo.y, -wo.z) : wo;
                            mf_sample s = mf_dielectric_ms_table_sample(&t, w, (mf_transport)mode, (mf_real)mfs_u[a % 5],
                                                                        (mf_real)mfs_u[(a / 5) % 5], (mf_real)mfs_u[a / 25]);
                            mfs_check(&tdm, s, w, 1, mf_dielectric_ms_table_pdf(&t, w, s.wi),
                                      (double)mf_dielectric_ms_table_bsdf(&t, w, s.wi, (mf_transport)mode) * fabs((double)s.wi.z));
                        }
                    }
            mf_dielectric_ms_table_release(&t);
        }
        mfs_report("mf_dielectric_ms_table_sample", &tdm);
    }
#ifndef MF_NO_IBM
    {   /* glints: a small bumpy normal map, footprints of 1 and 30 texels */
        mf_ibm ibm;
        mf_real nrm[16 * 16 * 3];
        mfs_tally ti;
        int i;
        memset(&ti, 0, sizeof ti);
        for (i = 0; i < 256; ++i) {
            mf_vec3 n = mf_normalize(mf_vec3_make(MF_R(0.3) * (mf_real)sin(0.7 * i), MF_R(0.3) * (mf_real)cos(1.3 * i), MF_R(1.0)));
            nrm[3 * i] = n.x; nrm[3 * i + 1] = n.y; nrm[3 * i + 2] = n.z;
        }
        if (mf_ibm_build(&ibm, nrm, 16, 16, MF_R(0.1)) == MF_SUCCESS) {
            mf_footprint f[2];
            int q;
            f[0].u = MF_R(0.3); f[0].v = MF_R(0.6); f[0].ax = (mf_real)(1.0 / 16); f[0].ay = 0; f[0].bx = 0; f[0].by = (mf_real)(1.0 / 16);
            f[1].u = MF_R(0.5); f[1].v = MF_R(0.5); f[1].ax = MF_R(0.3); f[1].ay = MF_R(0.1); f[1].bx = MF_R(-0.05); f[1].by = MF_R(0.4);
            for (q = 0; q < 2; ++q)
                for (v = 0; v < MFS_NV; v += 2)
                    for (a = 0; a < 625; ++a) {
                        mf_vec3 wo = mfs_view(v);
                        mf_sample s = mf_ibm_sample(&ibm, &f[q], wo, (mf_real)mfs_u[a % 5], (mf_real)mfs_u[(a / 5) % 5],
                                                    (mf_real)mfs_u[(a / 25) % 5], (mf_real)mfs_u[a / 125]);
                        mf_real p = MF_R(0.0), fv = mf_ibm_brdf_and_pdf(&ibm, &f[q], wo, s.wi, &p);
                        mfs_check(&ti, s, wo, 0, p, (double)fv * s.wi.z);
                    }
            mf_ibm_release(&ibm);
        }
        mfs_report_min("mf_ibm_sample", &ti, 100);   /* most corner footprint points see no lobe near h */
    }
#endif
    if (nd > 0 && !strcmp(names[nd - 1], "tabulated")) mf_tabulated_release(&tab);
}
