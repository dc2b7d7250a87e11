/* Fuzz target: LTC with arbitrary matrices and polygons (NaN, Inf, huge,
 * repeated and self-intersecting vertices): mf_ltc_from_matrix,
 * mf_ltc_from_inverse, eval, sample, mf_ltc_integrate, the polygon form
 * factors, the table lookups (anisotropic GGX's and the volumetric sheen's too) and the light
 * shapes (ellipses, disks, lines, tubes, textured quads). */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = { data, size };
    mf_real M[3][3], a, b, x;
    mf_vec3 verts[16], w, F;
    mf_ltc l;
    int i, j, n = (int)(fz_u8(&in) % 17u), two = (int)(fz_u8(&in) & 1u);
    unsigned mode = fz_u8(&in);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) M[i][j] = fz_real(&in);
    if (mode % 3u == 0) l = mf_ltc_from_matrix(M);
    else if (mode % 3u == 1) l = mf_ltc_from_inverse(M[0][0], M[0][1], M[0][2], M[1][0], M[1][1]);
    else l = mf_ltc_ggx(fz_real(&in), fz_real(&in));
    for (i = 0; i < n; ++i) { verts[i].x = fz_real(&in); verts[i].y = fz_real(&in); verts[i].z = fz_real(&in); }
    w = mf_normalize(mf_vec3_make(fz_real(&in), fz_real(&in), fz_real(&in)));
    FZ_NONNEG(mf_ltc_eval(&l, w), "ltc_eval");
    w = mf_ltc_sample(&l, fz_unit(&in), fz_unit(&in));
    FZ_VEC(w, "ltc_sample");
    x = mf_ltc_integrate(&l, verts, n, two);
    FZ_NONNEG(x, "ltc_integrate");
    FZ_NONNEG(mf_polygon_irradiance(verts, n, two), "polygon_irradiance");
    F = mf_polygon_vector_form_factor(verts, n);
    FZ_VEC(F, "vector_form_factor");
    FZ_NONNEG(mf_sphere_form_factor(F), "sphere_form_factor");
    if (n >= 4) {   /* light shapes from the first vertices */
        mf_real uv[2], lod, r = fz_real(&in);
        FZ_NONNEG(mf_ltc_integrate_ellipse(&l, verts[0], verts[1], verts[2], two), "ltc_integrate_ellipse");
        FZ_NONNEG(mf_ltc_integrate_ellipse_clipped(&l, verts[0], verts[1], verts[2], two), "ltc_integrate_ellipse_clipped");
        FZ_NONNEG(mf_ltc_integrate_disk(&l, verts[0], verts[1], r, two), "ltc_integrate_disk");
        FZ_VEC(mf_ellipse_vector_form_factor(verts[0], verts[1], verts[2]), "ellipse_vector_form_factor");
        FZ_NONNEG(mf_ltc_integrate_line(&l, verts[0], verts[3], r), "ltc_integrate_line");
        FZ_NONNEG(mf_ltc_integrate_tube(&l, verts[0], verts[3], r), "ltc_integrate_tube");
        FZ_NONNEG(mf_ltc_integrate_textured(&l, verts, two, r, uv, &lod), "ltc_integrate_textured");
        FZ_FIN(uv[0], "textured u"); FZ_FIN(uv[1], "textured v"); FZ_NONNEG(lod, "textured lod");
    }
    a = fz_real(&in); b = fz_real(&in);
    FZ_NONNEG(mf_ltc_ggx_albedo(a, b), "ggx_albedo");
    FZ_NONNEG(mf_ltc_ggx_fresnel(a, b), "ggx_fresnel");
    l = mf_ltc_ggx(a, b);
    for (i = 0; i < 9; ++i) FZ_FIN(l.Minv[i], "ggx Minv");
    {   /* the anisotropic GGX table: arbitrary view and alphas */
        mf_vec3 wa = mf_vec3_make(fz_real(&in), fz_real(&in), fz_real(&in));
        mf_real c = fz_real(&in);
        mf_ltc la = mf_ltc_ggx_aniso(wa, a, c);
        for (i = 0; i < 9; ++i) { FZ_FIN(la.Minv[i], "ggx_aniso Minv"); FZ_FIN(la.M[i], "ggx_aniso M"); }
        FZ_NONNEG(la.det_inv, "ggx_aniso det");
        FZ_NONNEG(mf_ltc_ggx_aniso_albedo(wa, b, c), "ggx_aniso_albedo");
        if (n >= 3) FZ_NONNEG(mf_ltc_integrate(&la, verts, n, two), "ggx_aniso integrate");
    }
    FZ_NONNEG(mf_ltc_meso_alpha(a), "meso_alpha");
    FZ_NONNEG(mf_ltc_combined_alpha(a, b), "combined_alpha");
    /* the volumetric sheen table: arbitrary view and roughness */
    FZ_NONNEG(mf_sheen_albedo(a, b), "sheen_albedo");
    {
        mf_vec3 wo = mf_normalize(mf_vec3_make(fz_real(&in), fz_real(&in), fz_real(&in)));
        mf_sample r = mf_sheen_sample(wo, a, fz_unit(&in), fz_unit(&in));
        FZ_SAMPLE(r, "sheen_sample");
        FZ_NONNEG(mf_sheen_brdf(wo, w, a), "sheen_brdf");
        FZ_NONNEG(mf_sheen_pdf(wo, w, a), "sheen_pdf");
        if (r.lobe != MF_LOBE_NONE && !(mf_sheen_pdf(wo, r.wi, a) > 0)) FZ_FAIL("%s", "sheen_sample: pdf of the sample is 0");
    }
    return 0;
}
