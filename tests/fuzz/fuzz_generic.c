/* Fuzz target: the generic API. Every constructor (transforms included) with
 * arbitrary float bit patterns for parameters and random numbers, unit
 * directions from arbitrary bit patterns (see fz_dir).
 * Asserts: no crash, no NaN/Inf, pdf >= 0, pdf(sample) > 0 for every
 * returned sample, finite weights; each sampler's record keeps the 0.4
 * contract (FZ_SAMPLE). */
#include "fuzz_common.h"

static mf_tabulated fz_tab;
static int fz_tab_ok = 0;

/* a direction: a unit vector normalized (in double) from three arbitrary
 * float bit patterns (the library's contract is unit directions; this reaches
 * the horizon, denormal components and exact axes), or the zero vector when
 * they are not finite or all zero; mode bit 1 mirrors it above the horizon */
static mf_vec3 fz_dir(fz_in *in)
{
    unsigned mode = fz_u8(in);
    double x = (double)fz_real(in), y = (double)fz_real(in), z = (double)fz_real(in), l;
    mf_vec3 w = mf_vec3_make(0, 0, 0);
    if (mode & 4u) { x *= 1e-30; y *= 1e-30; }   /* near the pole */
    if (mode & 8u) z *= 1e-30;                   /* near the horizon */
    l = sqrt(x * x + y * y + z * z);
    if (fz_finite(l) && l > 0.0) { w.x = (mf_real)(x / l); w.y = (mf_real)(y / l); w.z = (mf_real)(z / l); }
    if (mode & 2u) w.z = MF_FABS(w.z);
    return w;
}

static mf_ndf fz_ndf(fz_in *in)
{
    unsigned k = fz_u8(in);
    mf_real a = fz_real(in), b = fz_real(in), g = fz_real(in);
    mf_ndf d;
    switch (k % 8u) {
    case 0: d = mf_beckmann(a, b); break;
    case 1: d = mf_ggx(a, b); break;
    case 2: d = mf_gtr(a, g); break;
    case 3: d = mf_student_t(a, b, g); break;
    case 4: d = mf_gtr_anisotropic(a, b, g); break;
    case 5: {
        mf_leadr m;
        m.E_x = a; m.E_y = b; m.E_xx = g; m.E_yy = fz_real(in); m.E_xy = fz_real(in);
        d = mf_leadr_ndf(m);
        break;
    }
    case 6:
        if (!fz_tab_ok) {
            mf_ndf base = mf_ggx(MF_R(0.3), MF_R(0.3));
            fz_tab_ok = mf_tabulated_from_ndf(&fz_tab, &base, 24) == MF_SUCCESS ? 1 : -1;
        }
        d = fz_tab_ok > 0 ? mf_tabulated_ndf(&fz_tab) : mf_ggx(a, b);
        break;
    case 7: d = mf_charlie(a); break;
    }
    /* transforms: stretch, general matrix, or composed */
    k = fz_u8(in);
    if (k & 1u) d = mf_stretched(d, fz_real(in));
    if (k & 2u) {
        mf_real m00 = fz_real(in), m01 = fz_real(in), m10 = fz_real(in), m11 = fz_real(in);
        d = mf_transformed(d, mf_mat2_make(m00, m01, m10, m11));
    }
    if (k & 4u) d = mf_stretched(d, fz_real(in));
    return d;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = { data, size };
    mf_ndf d = fz_ndf(&in);
    mf_vec3 wo = fz_dir(&in), wi = fz_dir(&in), wm = fz_dir(&in), s;
    mf_real u1 = fz_unit(&in), u2 = fz_unit(&in), v;
    mf_sample r;
    snprintf(fz_ctx, sizeof fz_ctx, "type %d ax %.9g ay %.9g p0 %.9g p1 %.9g p2 %.9g tr %d M %.9g %.9g %.9g %.9g "
             "wo %.9g %.9g %.9g wi %.9g %.9g %.9g wm %.9g %.9g %.9g u %.9g %.9g", (int)d.type, (double)d.ax, (double)d.ay,
             (double)((mf_real *)&d.p)[0], (double)((mf_real *)&d.p)[1], (double)((mf_real *)&d.p)[2], d.transformed,
             (double)d.M.m00, (double)d.M.m01, (double)d.M.m10, (double)d.M.m11, (double)wo.x, (double)wo.y, (double)wo.z,
             (double)wi.x, (double)wi.y, (double)wi.z, (double)wm.x, (double)wm.y, (double)wm.z, (double)u1, (double)u2);

    FZ_NONNEG(mf_D(&d, wm), "D");
    FZ_NONNEG(mf_lambda(&d, wo), "lambda");
    FZ_NONNEG(mf_G1(&d, wo, wm), "G1");
    FZ_NONNEG(mf_G2(&d, wo, wi, wm), "G2");
    FZ_NONNEG(mf_G2_separable(&d, wo, wi, wm), "G2_separable");
    FZ_NONNEG(mf_D_visible(&d, wo, wm), "D_visible");
    v = mf_projected_area(&d, wo);
    FZ_NONNEG(v, "projected_area");
    FZ_NONNEG(mf_brdf(&d, wo, wi), "brdf");
    FZ_NONNEG(mf_brdf_pdf(&d, wo, wi), "brdf_pdf");
    FZ_NONNEG(mf_brdf_pdf_bounded(&d, wo, wi), "brdf_pdf_bounded");
    s = mf_sample_D(&d, u1, u2);
    FZ_VEC(s, "sample_D");
    s = mf_sample_visible(&d, wo, u1, u2);
    FZ_VEC(s, "sample_visible");
    r = mf_brdf_sample(&d, wo, u1, u2);
    FZ_SAMPLE(r, "brdf_sample");
    if (r.lobe != MF_LOBE_NONE) {
        mf_real p = mf_brdf_pdf(&d, wo, r.wi), f = mf_brdf(&d, wo, r.wi);
        if (!(r.wi.z > MF_R(0.0))) FZ_FAIL("brdf_sample below the horizon: z = %g", (double)r.wi.z);
        if (!(p > MF_R(0.0)) || !fz_finite((double)p)) FZ_FAIL("pdf of a returned sample = %g", (double)p);
        FZ_NONNEG(f, "brdf of a returned sample");
    }
    r = mf_brdf_sample_bounded(&d, wo, u1, u2);
    FZ_SAMPLE(r, "brdf_sample_bounded");
    if (r.lobe != MF_LOBE_NONE && !(r.wi.z > MF_R(0.0))) FZ_FAIL("brdf_sample_bounded below the horizon: z = %g", (double)r.wi.z);
    {   /* the lobes of a whole material, parameters from the same bytes:
         * EON (rho x, sigma y), F82-tint, thin film, volumetric sheen */
        mf_real x = fz_real(&in), y = fz_real(&in), eb[3], kb[3], rgb[3];
        int c;
        FZ_NONNEG(mf_eon_brdf(wo, wi, x, y), "eon_brdf");
        FZ_NONNEG(mf_eon_pdf(wo, wi, y), "eon_pdf");
        FZ_NONNEG(mf_eon_albedo(wo.z, x, y), "eon_albedo");
        FZ_NONNEG(mf_eon_albedo_fast(wo.z, x, y), "eon_albedo_fast");
        r = mf_eon_sample(wo, x, y, u1, u2);
        FZ_SAMPLE(r, "eon_sample");
        FZ_NONNEG(mf_fresnel_f82(wo.z, x, y), "fresnel_f82");
        FZ_NONNEG(mf_fresnel_f82_average(x, y), "fresnel_f82_average");
        FZ_NONNEG(mf_fresnel_thin_film(wo.z, u1, x, y * MF_R(1000.0), u2, x, MF_R(380.0) + MF_R(400.0) * u2), "fresnel_thin_film");
        eb[0] = x; eb[1] = y; eb[2] = u1; kb[0] = u2; kb[1] = x; kb[2] = y;
        mf_fresnel_thin_film_rgb(wo.z, MF_R(1.0), u1 + MF_R(1.0), x * MF_R(1000.0), eb, kb, rgb);
        for (c = 0; c < 3; ++c) FZ_NONNEG(rgb[c], "fresnel_thin_film_rgb");
        FZ_NONNEG(mf_sheen_brdf(wo, wi, x), "sheen_brdf");
        FZ_NONNEG(mf_sheen_pdf(wo, wi, x), "sheen_pdf");
        FZ_NONNEG(mf_sheen_albedo(wo.z, x), "sheen_albedo");
        r = mf_sheen_sample(wo, x, u1, u2);
        FZ_SAMPLE(r, "sheen_sample");
    }
    if (d.type == MF_NDF_GGX || d.type == MF_NDF_BECKMANN) {   /* the built-in dielectric tables (other kinds integrate: slow) */
        mf_real eta = fz_real(&in);
        FZ_NONNEG(mf_dielectric_albedo(&d, wo, eta, MF_IMPORTANCE), "dielectric_albedo");
        FZ_NONNEG(mf_dielectric_albedo(&d, wo, eta, MF_RADIANCE), "dielectric_albedo radiance");
        FZ_NONNEG(mf_dielectric_bsdf_ms(&d, wo, wi, eta, MF_RADIANCE), "dielectric_bsdf_ms");
        FZ_NONNEG(mf_dielectric_bsdf_ms_pdf(&d, wo, wi, eta), "dielectric_bsdf_ms_pdf");
        r = mf_dielectric_bsdf_ms_sample(&d, wo, eta, MF_IMPORTANCE, u1, u2, u1 * u2);
        FZ_SAMPLE(r, "dielectric_bsdf_ms_sample");
    }
    return 0;
}
