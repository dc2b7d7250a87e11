/* Compiled by tests/warnings.sh with every warning as an error, in many
 * language modes; linked as two translation units (MFT_SECOND_TU). Touches
 * every public function so each one is instantiated. */
#ifndef MFT_SECOND_TU
#define MICROFACET_IMPLEMENTATION
#endif
#include "microfacet.h"
#include "microfacet.h" /* including twice is harmless */

#ifndef MFT_SECOND_TU
static void mft_map(mf_real u, mf_real v, mf_real out[2], void *ctx) { (void)ctx; out[0] = u + v; out[1] = u - v; }
static mf_vec3 mft_env(mf_vec3 wi, mf_real sa, void *ctx) { (void)ctx; (void)sa; return wi; }
static mf_real mft_brdf_cos(mf_vec3 wo, mf_vec3 wi, void *ctx) { (void)ctx; return wo.z * wi.z; }
static mf_ndf mft_family(mf_real a, void *ctx) { (void)ctx; return mf_gtr(a, MF_R(1.5)); }
#endif

#ifdef MFT_SECOND_TU
mf_real mft_second(void);
mf_real mft_second(void)
{
    mf_ndf d = mf_gtr(MF_R(0.3), MF_R(1.5));
    return mf_D(&d, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0))) +
           (mf_real)(mf_result_string(MF_ERROR_OUT_OF_MEMORY)[0] == 'o');
}
#else
mf_real mft_second(void);
int main(void)
{
    mf_ndf k[4];
    mf_vec3 wo = mf_vec3_make(MF_R(0.36), MF_R(0.48), MF_R(0.8)), wi = mf_vec3_make(MF_R(-0.6), MF_R(0.0), MF_R(0.8));
    mf_vec3 t, b;
    mf_real s = MF_R(0.0);
    int i;
    k[0] = mf_beckmann(MF_R(0.2), MF_R(0.3));
    k[1] = mf_ggx(MF_R(0.2), MF_R(0.3));
    k[2] = mf_gtr(MF_R(0.2), MF_R(2.5));
    k[3] = mf_student_t(MF_R(0.2), MF_R(0.3), MF_R(3.0));
    {
        mf_gtr_table gt;
        mf_ndf g;
        s += (mf_real)(mf_gtr_table_build(&gt, MF_R(0.2), MF_R(2.5)) == MF_SUCCESS);
        g = mf_gtr_table_ndf(&gt);
        s += mf_lambda(&g, wo);
    }
    for (i = 0; i < 4; ++i) {
        const mf_ndf *d = &k[i];
        mf_vec3 wm = mf_sample_visible(d, wo, MF_R(0.3), MF_R(0.7)), wd = mf_sample_D(d, MF_R(0.3), MF_R(0.7));
        mf_vec3 ws = mf_brdf_sample(d, wo, MF_R(0.2), MF_R(0.9)).wi;
        s += mf_D(d, wm) + mf_lambda(d, wo) + mf_G1(d, wo, wm) + mf_G2(d, wo, wi, wm) + mf_G2_separable(d, wo, wi, wm);
        s += mf_D_visible(d, wo, wm) + wd.z + ws.z + mf_brdf(d, wo, wi) + mf_brdf_pdf(d, wo, wi);
        s += mf_brdf_sample(d, wo, MF_R(0.2), MF_R(0.9)).weight + mf_projected_area(d, wo) + mf_brdf_pdf_bounded(d, wo, wi);
        s += mf_brdf_sample_bounded(d, wo, MF_R(0.3), MF_R(0.6)).pdf;
        s += mf_albedo(d, wo) + mf_albedo_average(d) + mf_brdf_ms(d, wo, wi) + mf_ms_turquin_scale(d, wo, MF_R(0.5));
        s += mf_albedo_integrate(d, wo, 1) + mf_ms_fresnel(MF_R(0.9), MF_R(0.6));
        s += mf_brdf_ms_sample(d, wo, MF_R(0.3), MF_R(0.6)).wi.z + mf_brdf_ms_pdf(d, wo, wi);
        if (i == 2) {
            mf_albedo_table at;
            if (mf_albedo_table_build(&at, d, 4, 1, 1) == MF_SUCCESS) {
                s += mf_albedo_table_eval(&at, wo) + mf_albedo_table_average(&at) + mf_albedo_table_brdf_ms(&at, wo, wi);
                mf_albedo_table_release(&at);
            }
            {
                mf_dielectric_ms_table dt;
                if (mf_dielectric_ms_table_build(&dt, d, MF_R(1.5), 4, 1) == MF_SUCCESS) {
                    s += mf_dielectric_ms_table_albedo(&dt, wo) + mf_dielectric_ms_table_bsdf(&dt, wo, wi, MF_RADIANCE) + mf_dielectric_ms_table_pdf(&dt, wo, wi);
                    s += mf_dielectric_ms_table_sample(&dt, wo, MF_RADIANCE, MF_R(0.2), MF_R(0.4), MF_R(0.6)).wi.z;
                    mf_dielectric_ms_table_release(&dt);
                }
                s += mf_dielectric_albedo_integrate(d, wo, MF_R(1.5), 1);
                s += mf_dielectric_albedo(d, wo, MF_R(1.5), MF_RADIANCE) + mf_dielectric_bsdf_ms(d, wo, wi, MF_R(1.5), MF_IMPORTANCE) + mf_dielectric_bsdf_ms_pdf(d, wo, wi, MF_R(1.5));
                s += mf_dielectric_bsdf_ms_sample(d, wo, MF_R(1.5), MF_RADIANCE, MF_R(0.2), MF_R(0.4), MF_R(0.6)).weight;
            }
        s += mf_dielectric_bsdf(d, wo, wi, MF_R(1.5), MF_RADIANCE) + mf_dielectric_pdf(d, wo, wi, MF_R(1.5));
        s += mf_dielectric_sample(d, wo, MF_R(1.5), MF_RADIANCE, MF_R(0.2), MF_R(0.7), MF_R(0.5)).weight + mf_dielectric_bsdf(d, wo, wi, MF_R(1.5), MF_IMPORTANCE);
    }
    s += mf_beckmann_lambda_approx(MF_R(0.2), MF_R(0.2), wo) + mf_erfinv(MF_R(0.3));
    s += mf_fresnel_dielectric(MF_R(0.5), MF_R(1.5)) + mf_fresnel_conductor(MF_R(0.5), MF_R(0.2), MF_R(3.0));
    s += mf_fresnel_schlick(MF_R(0.5), MF_R(0.04));
    {   /* materials helpers */
        mf_basis fb = mf_basis_from(wo, mf_vec3_make(MF_R(1.0), MF_R(0.0), MF_R(0.0))), fl = mf_basis_ltc(wo, wo);
        mf_real ce, ck, cr, cg;
        mf_ndf rot = mf_rotated(mf_ggx(MF_R(0.3), MF_R(0.1)), MF_R(0.5));
        mf_conductor_from_artist(MF_R(0.9), MF_R(0.5), &ce, &ck);
        mf_artist_from_conductor(ce, ck, &cr, &cg);
        s += mf_to_local(&fb, wo).z + mf_to_world(&fl, wo).z + rot.ax + cr + cg;
        s += mf_f0_from_ior(MF_R(1.5)) + mf_ior_from_f0(MF_R(0.04)) + mf_fresnel_schlick_f90(MF_R(0.5), MF_R(0.04), MF_R(0.5));
        s += mf_fresnel_dielectric_average(MF_R(1.5)) + mf_fresnel_conductor_average(MF_R(0.2), MF_R(3.0));
        }
        s += mf_alpha_from_roughness(MF_R(0.5)) + mf_roughness_from_alpha(MF_R(0.25));
        {
            mf_vec3 wt;
            s += (mf_real)mf_refract(wo, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0)), MF_R(1.5), &wt) + wt.z;
        }
        s += mf_beckmann_alpha_from_sigma(MF_R(0.2)) + mf_beckmann_sigma_from_alpha(MF_R(0.3));
    }
    {
        mf_mat2 T;
        mf_vec3 tri[3];
        mf_real uv[6] = { MF_R(0.0), MF_R(0.0), MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0) };
        mf_ndf x = mf_stretched(mf_transformed(k[2], mf_mat2_make(MF_R(1.0), MF_R(2.0), MF_R(0.0), MF_R(1.0))), MF_R(0.3));
        mf_ndf a = mf_gtr_anisotropic(MF_R(0.1), MF_R(0.3), MF_R(1.5));
        tri[0] = mf_vec3_make(0, 0, 0); tri[1] = mf_vec3_make(1, 0, 0); tri[2] = mf_vec3_make(0, 1, 0);
        s += mf_D(&x, wo) + mf_lambda(&a, wo) + mf_sample_visible(&x, wo, MF_R(0.5), MF_R(0.5)).z;
        s += (mf_real)(mf_tension_from_triangles(tri, tri, uv, &T) == MF_SUCCESS) + mf_mat2_det(mf_mat2_transpose(T));
        s += (mf_real)mf_transform_is_valid(mf_mat2_inverse(T)) + mf_stretch_matrix(MF_R(0.2)).m00;
    }
    {
        const mf_real m9[9] = { MF_R(1.0), MF_R(0.0), MF_R(0.2), MF_R(0.0), MF_R(1.0), MF_R(0.0), MF_R(0.1), MF_R(0.0), MF_R(1.0) };
        const mf_real m33[3][3] = { { MF_R(1.0), MF_R(0.0), MF_R(0.0) }, { MF_R(0.0), MF_R(1.0), MF_R(0.0) }, { MF_R(0.0), MF_R(0.0), MF_R(1.0) } };
        mf_ltc l = mf_ltc_from_matrix9(m9), l2 = mf_ltc_from_matrix(m33), l3 = mf_ltc_from_inverse(MF_R(2.0), MF_R(0.1), MF_R(2.0), MF_R(0.1), MF_R(1.0));
        mf_vec3 quad[4];
        quad[0] = mf_vec3_make(-1, -1, 1); quad[1] = mf_vec3_make(-1, 1, 1); quad[2] = mf_vec3_make(1, 1, 1); quad[3] = mf_vec3_make(1, -1, 1);
        s += mf_ltc_eval(&l, wo) + mf_ltc_sample(&l2, MF_R(0.3), MF_R(0.6)).z + mf_ltc_integrate(&l3, quad, 4, 1);
        s += mf_polygon_irradiance(quad, 4, 0) + mf_sphere_form_factor(mf_polygon_vector_form_factor(quad, 4));
        s += mf_ltc_meso_alpha(MF_R(0.9)) + mf_ltc_combined_alpha(MF_R(0.2), MF_R(0.3));
    }
    {   /* LTC light shapes */
        const mf_real m9[9] = { MF_R(1.0), MF_R(0.0), MF_R(0.2), MF_R(0.0), MF_R(1.0), MF_R(0.0), MF_R(0.1), MF_R(0.0), MF_R(1.0) };
        mf_ltc l = mf_ltc_from_matrix9(m9);
        mf_vec3 c = mf_vec3_make(MF_R(0.1), MF_R(0.2), MF_R(1.0)), u = mf_vec3_make(MF_R(0.3), MF_R(0.0), MF_R(0.0));
        mf_vec3 v = mf_vec3_make(MF_R(0.0), MF_R(-0.3), MF_R(0.0)), quad[4];
        mf_real uv[2], lod;
        quad[0] = mf_vec3_make(-1, -1, 1); quad[1] = mf_vec3_make(-1, 1, 1); quad[2] = mf_vec3_make(1, 1, 1); quad[3] = mf_vec3_make(1, -1, 1);
        s += mf_ltc_integrate_ellipse_clipped(&l, c, u, v, 1);
        s += mf_ltc_integrate_ellipse(&l, c, u, v, 0) + mf_ltc_integrate_disk(&l, c, mf_vec3_make(0, 0, -1), MF_R(0.3), 1);
        s += mf_ellipse_vector_form_factor(c, u, v).z + mf_ltc_integrate_line(&l, c, mf_add(c, u), MF_R(0.01));
        s += mf_ltc_integrate_tube(&l, c, mf_add(c, u), MF_R(0.01)) + mf_ltc_integrate_textured(&l, quad, 0, MF_R(256.0), uv, &lod);
        s += uv[0] + lod;
    }
    {
        mf_leadr la = mf_leadr_with_roughness(mf_leadr_add(mf_leadr_from_slope(MF_R(0.1), MF_R(0.2)), mf_leadr_from_normal(wo)), MF_R(0.2), MF_R(0.3));
        mf_ndf ld;
        mf_real vx, vy, cxy;
        la = mf_leadr_lerp(mf_leadr_height_scale(mf_leadr_deform(la, mf_mat2_make(1, 0, 0, 1)), MF_R(0.5)), la, MF_R(0.5));
        la = mf_leadr_scale(la, MF_R(1.0));
        ld = mf_leadr_ndf(la);
        s += mf_leadr_specular(la, wo, wi) + mf_D(&ld, wo) + mf_leadr_mean_normal(la).z + (mf_real)mf_leadr_to_covariance(la, &vx, &vy, &cxy);
        s += mf_leadr_map_lookup((const mf_leadr_map *)0, MF_R(0.5), MF_R(0.5), MF_R(0.1)).E_x;
    }
    { /* tabulated distributions */
        mf_real th[3] = { MF_R(0.0), MF_R(0.8), MF_R(1.5707963267948966) }, dv[3] = { MF_R(2.0), MF_R(1.0), MF_R(0.0) };
        mf_tabulated t1, t2, t3;
        mf_ndf d1, d2;
        if (mf_tabulated_build(&t1, th, dv, (const mf_real *)0, 3) == MF_SUCCESS &&
            mf_tabulated_from_ndf(&t2, &k[1], 16) == MF_SUCCESS) {
            t3 = mf_tabulated_rebase(&t1, t1.block);
            d1 = mf_tabulated_ndf(&t3);
            d2 = mf_transformed(mf_tabulated_ndf(&t2), mf_mat2_make(MF_R(1.0), MF_R(0.5), MF_R(0.0), MF_R(1.0)));
            s += mf_D(&d1, wo) + mf_lambda(&d2, wo) + mf_sample_visible(&d2, wo, MF_R(0.2), MF_R(0.4)).z;
            s += mf_sample_D(&d1, MF_R(0.5), MF_R(0.5)).z + (mf_real)mf_tabulated_memory_bytes(&t2);
        }
        mf_tabulated_release(&t1);
        mf_tabulated_release(&t2);
    }
    { /* Inverse Bin Map */
        mf_real nm[4 * 4 * 3];
        mf_ibm ibm, ld;
        mf_footprint f;
        int bins[MF_IBM_MAX_WINDOW], q;
        mf_real w[MF_IBM_MAX_WINDOW], pdf = MF_R(0.0);
        unsigned char buf[4096];
        size_t nb;
        for (q = 0; q < 16; ++q) { nm[3 * q] = MF_R(0.0); nm[3 * q + 1] = MF_R(0.6) * (mf_real)(q & 1); nm[3 * q + 2] = (q & 1) ? MF_R(0.8) : MF_R(1.0); }
        f.u = MF_R(0.5); f.v = MF_R(0.5); f.ax = MF_R(0.5); f.ay = MF_R(0.0); f.bx = MF_R(0.1); f.by = MF_R(0.5);
        if (mf_ibm_build(&ibm, nm, 4, 4, MF_R(0.1)) == MF_SUCCESS &&
            mf_ibm_build_ex(&ld, nm, 4, 4, MF_R(0.1), (const mf_ibm_options *)0) == MF_SUCCESS) {
            mf_ibm_release(&ld);
            mf_ibm_set_shadowing(&ibm, &k[2]);
            s += mf_ibm_brdf(&ibm, &f, wo, wi) + mf_ibm_pdf(&ibm, &f, wo, wi) + mf_ibm_brdf_and_pdf(&ibm, &f, wo, wi, &pdf);
            s += mf_ibm_sample(&ibm, &f, wo, MF_R(0.1), MF_R(0.2), MF_R(0.3), MF_R(0.4)).wi.z + pdf;
            s += mf_ibm_bin_weight(&ibm, mf_ibm_bin_of(&ibm, wo), &f) + (mf_real)mf_ibm_bin_count(&ibm);
            s += (mf_real)mf_ibm_neighbourhood_weights(&ibm, &f, mf_ibm_texel_bin(&ibm, 1, 2), bins, w);
            s += mf_ibm_bin_normal(&ibm, mf_ibm_texel_bin(&ibm, 0, 0)).z + (mf_real)mf_ibm_bin_texels(&ibm, 0);
            s += (mf_real)mf_ibm_memory_bytes(&ibm);
            if (mf_ibm_save(&ibm, buf, sizeof buf, &nb) == MF_SUCCESS && mf_ibm_load(&ld, buf, nb) == MF_SUCCESS) mf_ibm_release(&ld);
            mf_ibm_release(&ibm);
        }
    }
    { /* microsurface generation, gonioreflectometer */
        mf_real hm[8 * 8], gr[2 * 8 * 8], sw[8 * 8], mod[64], zl, zh, pl, ph;
        mf_microsurface_options mo;
        mf_microsurface_stats ms;
        mf_gonio go;
        mf_gonio_config gc;
        memset(&mo, 0, sizeof mo);
        mo.gradients = gr; mo.schwarz = sw;
        s += (mf_real)(mf_microsurface_generate(&k[0], 8, 1, 5u, hm) == MF_SUCCESS);
        s += (mf_real)(mf_microsurface_generate_ex(&k[1], 8, 2, 1u, &mo, hm, &ms) == MF_SUCCESS) + ms.below;
        s += (mf_real)(mf_microsurface_integrate(gr, 8, hm) == MF_SUCCESS);
        memset(&gc, 0, sizeof gc);
        gc.rays = 100; gc.wi = wo;
        if (mf_gonio_init(&go, 2) == MF_SUCCESS) {
            s += (mf_real)(mf_gonio_measure(&go, hm, 8, &gc) == MF_SUCCESS) + go.energy_first;
            if (go.cells <= 64) s += (mf_real)(mf_gonio_model(&go, &k[0], wo, 2, mod) == MF_SUCCESS);
            mf_gonio_cell_bounds(&go, 1, &zl, &zh, &pl, &ph);
            s += zl + zh + pl + ph + mf_gonio_cell_solid_angle(&go) + mf_gonio_cell_center(&go, mf_gonio_cell(&go, wo)).z;
            mf_gonio_release(&go);
        }
    }
    { /* per-kind fast paths, vector helpers, 2x2 matrices */
        mf_mat2 J = mf_jacobian_2d(mft_map, (void *)0, MF_R(0.2), MF_R(0.3), MF_R(1e-3)), T;
        mf_vec3 v = mf_add(mf_scale(wo, MF_R(0.5)), mf_normalize(wi));
        s += mf_beckmann_D(MF_R(0.2), MF_R(0.3), wo) + mf_beckmann_lambda(MF_R(0.2), MF_R(0.3), wo);
        s += mf_beckmann_sample_visible(MF_R(0.2), MF_R(0.3), wo, MF_R(0.3), MF_R(0.6)).z;
        s += mf_ggx_D(MF_R(0.2), MF_R(0.3), wo) + mf_ggx_lambda(MF_R(0.2), MF_R(0.3), wo);
        s += mf_ggx_sample_visible(MF_R(0.2), MF_R(0.3), wo, MF_R(0.3), MF_R(0.6)).z;
        s += mf_clamp(v.x, MF_R(0.0), MF_R(1.0)) + mf_max(v.y, MF_R(0.0)) + mf_min(v.z, MF_R(1.0));
        s += mf_mat2_apply(J, wo).x + mf_mat2_apply_transpose(mf_mat2_mul(J, J), wo).y;
        s += (mf_real)(mf_tension_matrix(J, J, &T) == MF_SUCCESS) + T.m00;
    }
    { /* LEADR shading and maps */
        mf_leadr la = mf_leadr_with_roughness(mf_leadr_from_slope(MF_R(0.1), MF_R(0.2)), MF_R(0.2), MF_R(0.3));
        mf_real sh[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 }, hm[4 * 4], nm[4 * 4 * 3];
        mf_leadr_map m;
        int q;
        mf_sh9_add_directional(sh, wo, MF_R(1.0));
        s += mf_sh9_irradiance(sh, wo) + mf_leadr_diffuse_sh9(la, wo, sh, 5);
        s += mf_leadr_diffuse(la, wo, wi, 5) + mf_leadr_diffuse_noshadow(la, wo, wi, 5);
        s += mf_leadr_specular_env(la, wo, 5, 1, mft_env, (void *)0).z;
        for (q = 0; q < 16; ++q) { hm[q] = MF_R(0.01) * (mf_real)(q & 3); nm[3 * q] = MF_R(0.0); nm[3 * q + 1] = MF_R(0.0); nm[3 * q + 2] = MF_R(1.0); }
        if (mf_leadr_map_from_heights(&m, hm, 4, 4, MF_R(0.1), MF_R(0.1)) == MF_SUCCESS) {
            s += mf_leadr_map_lookup(&m, MF_R(0.3), MF_R(0.6), MF_R(0.1)).E_xx + (mf_real)mf_leadr_map_memory_bytes(&m);
            mf_leadr_map_release(&m);
        }
        if (mf_leadr_map_from_normals(&m, nm, 4, 4, MF_R(0.1), MF_R(0.1)) == MF_SUCCESS) mf_leadr_map_release(&m);
    }
    { /* LTC fitting and tables */
        mf_ltc_fit_result r;
        mf_ltc_table tb;
        int nt = 0, na = 0;
        if (mf_ltc_fit(&r, (const mf_ndf *)0, mft_brdf_cos, (void *)0, MF_R(0.7), (const mf_real *)0) == MF_SUCCESS) s += r.albedo;
        if (mf_ltc_table_build(&tb, mft_family, (void *)0, 2, 2, (mf_progress_fn)0, (void *)0) == MF_SUCCESS) {
            s += mf_ltc_table_lookup(&tb, MF_R(0.5), MF_R(0.3), (mf_real *)0, (mf_real *)0).M[0];
            mf_ltc_table_release(&tb);
        }
        s += mf_ltc_ggx(MF_R(0.5), MF_R(0.3)).M[0] + mf_ltc_ggx_albedo(MF_R(0.5), MF_R(0.3));
        s += mf_ltc_ggx_fresnel(MF_R(0.5), MF_R(0.3)) + (mf_real)mf_ltc_ggx_table(&nt, &na)[0] + (mf_real)(nt + na);
        s += mf_ltc_beckmann(MF_R(0.5), MF_R(0.3)).M[0] + mf_ltc_beckmann_albedo(MF_R(0.5), MF_R(0.3));
        s += mf_ltc_beckmann_fresnel(MF_R(0.5), MF_R(0.3)) + (mf_real)mf_ltc_beckmann_table(&nt, &na)[0] + (mf_real)(nt + na);
        {
            static unsigned short t1[4 * 64 * 64], t2[4 * 64 * 64];
            if (mf_ltc_table_export_rgba16f(mf_ltc_ggx_table(&nt, &na), nt, na, t1, t2) == MF_SUCCESS) s += (mf_real)t1[0];
        }
        {   /* anisotropic GGX */
            static unsigned short a1[4 * 8192], a2[4 * 8192];
            int dm[4];
            const unsigned short *at = mf_ltc_ggx_aniso_table(dm);
            s += mf_ltc_ggx_aniso(wo, MF_R(0.3), MF_R(0.1)).M[0] + mf_ltc_ggx_aniso_albedo(wo, MF_R(0.3), MF_R(0.1)) + (mf_real)at[0];
            if (dm[0] * dm[1] * dm[2] * dm[3] <= 8192 && mf_ltc_ggx_aniso_export_rgba16f(a1, a2) == MF_SUCCESS) s += (mf_real)a1[0];
        }
    }
    { mf_basis fr_ = mf_basis_from_normal(wo); t = fr_.t; b = fr_.b; }
    {   /* the lobes of a whole material */
        mf_real eb[3] = { MF_R(0.2), MF_R(0.9), MF_R(1.5) }, kb[3] = { MF_R(3.0), MF_R(2.5), MF_R(1.9) }, rgb[3];
        s += mf_eon_brdf(wo, wi, MF_R(0.8), MF_R(0.5)) + mf_eon_pdf(wo, wi, MF_R(0.5)) + mf_eon_sample(wo, MF_R(0.8), MF_R(0.5), MF_R(0.3), MF_R(0.6)).weight;
        s += mf_eon_albedo(wo.z, MF_R(0.8), MF_R(0.5)) + mf_eon_albedo_fast(wo.z, MF_R(0.8), MF_R(0.5)) + mf_eon_albedo_average(MF_R(0.8), MF_R(0.5));
        s += mf_fresnel_f82(wo.z, MF_R(0.9), MF_R(0.8)) + mf_fresnel_f82_average(MF_R(0.9), MF_R(0.8));
        s += mf_fresnel_thin_film(wo.z, MF_R(1.0), MF_R(1.33), MF_R(300.0), MF_R(1.5), MF_R(0.0), MF_R(550.0));
        mf_fresnel_thin_film_rgb(wo.z, MF_R(1.0), MF_R(1.33), MF_R(300.0), eb, kb, rgb);
        s += rgb[0] + rgb[1] + rgb[2];
        s += mf_charlie_D(MF_R(0.4), wo) + mf_charlie_lambda(MF_R(0.4), wo) + mf_charlie_lambda_fit(MF_R(0.4), wo);
        s += mf_charlie_sample_D(MF_R(0.4), MF_R(0.3), MF_R(0.6)).z;
        { mf_ndf ch = mf_charlie(MF_R(0.4)); s += mf_lambda(&ch, wo) + mf_sample_visible(&ch, wo, MF_R(0.3), MF_R(0.6)).z; }
        s += mf_sheen_brdf(wo, wi, MF_R(0.5)) + mf_sheen_pdf(wo, wi, MF_R(0.5)) + mf_sheen_sample(wo, MF_R(0.5), MF_R(0.3), MF_R(0.6)).weight;
        s += mf_sheen_albedo(wo.z, MF_R(0.5));
    }
#ifndef MF_NO_DEPRECATED
    /* the deprecated 0.3 names still compile and run (warnings off here only) */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    {
        const mf_ndf *d = &k[1];
        mf_microsurface_options mo;
        mf_gonio_config gc;
        s += mf_brdf_sample_weight(d, wo, wi) + mf_ggx_brdf_pdf_bounded(d, wo, wi);
        s += mf_ggx_sample_visible_bounded(d, wo, MF_R(0.3), MF_R(0.6)).z + mf_dielectric_sample_weight(d, wo, wi, MF_R(1.5));
        s += (mf_real)mf_transform_valid(mf_mat2_make(MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0)));
        s += (mf_real)mf_leadr_covariance(mf_leadr_from_slope(MF_R(0.1), MF_R(0.2)), &t.x, &t.y, &t.z);
        mf_frame(wo, &t, &b);
        mf_microsurface_options_default(&mo);
        mf_gonio_config_default(&gc);
        s += t.x + b.y + mo.threshold + gc.absorption;
        {
            mf_albedo_table at;
            mf_dielectric_ms_table dt;
            at.n_mu = 0; at.n_phi = 0; at.E = 0; at.E_avg = MF_R(0.0);
            s += mf_brdf_ms_table(&at, wo, wi);
            if (mf_dielectric_ms_build(&dt, d, MF_R(1.5), 4, 1) == MF_SUCCESS) {
                s += mf_dielectric_ms_pdf(&dt, wo, wi);
                mf_dielectric_ms_release(&dt);
            }
        }
#ifndef MF_NO_IBM
        s += mf_ibm_brdf_pdf((const mf_ibm *)0, (const mf_footprint *)0, wo, wi, (mf_real *)0);
#endif
    }
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif
    s += mf_dot(mf_cross(t, b), mf_reflect(wo, wi)) + mft_second();
    return s == s ? 0 : 1;
}
#endif
