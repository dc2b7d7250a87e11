// Compiled by `make cuda-check` with nvcc -c (no GPU needed): every generic
// operation must be callable from device code.
#include "microfacet.h"

__global__ void mf_kernel(const float *u, float *out, int n)
{
    int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    mf_ndf k[4];
    k[0] = mf_beckmann(MF_R(0.2), MF_R(0.3));
    k[1] = mf_ggx(MF_R(0.2), MF_R(0.3));
    k[2] = mf_gtr(MF_R(0.2), MF_R(1.5));
    k[3] = mf_student_t(MF_R(0.2), MF_R(0.3), MF_R(3.0));
    k[i & 3] = (i & 4) ? mf_transformed(k[i & 3], mf_mat2_make(MF_R(1.0), MF_R(2.0), MF_R(0.0), MF_R(1.0))) : k[i & 3];
    const mf_ndf *d = &k[i & 3];
    mf_vec3 wo = mf_normalize(mf_vec3_make((mf_real)u[i], MF_R(0.2), MF_R(0.8)));
    mf_sample s = mf_brdf_sample(d, wo, (mf_real)u[i], (mf_real)u[(i + 1) % n]);
    mf_sample sb = mf_brdf_sample_bounded(d, wo, (mf_real)u[i], (mf_real)u[(i + 1) % n]);
    mf_sample st = mf_dielectric_sample(d, wo, MF_R(1.5), MF_IMPORTANCE, (mf_real)u[i], MF_R(0.3), MF_R(0.6));
    mf_vec3 wi = s.wi;
    mf_vec3 wm = mf_sample_D(d, (mf_real)u[i], MF_R(0.5));
    mf_real r = mf_brdf(d, wo, wi) + mf_brdf_pdf(d, wo, wi) + s.pdf + s.weight;
    r += sb.weight + mf_brdf_pdf_bounded(d, wo, sb.wi) + st.weight + mf_dielectric_pdf(d, wo, st.wi, MF_R(1.5));
    r += mf_dielectric_bsdf(d, wo, st.wi, MF_R(1.5), MF_RADIANCE) + mf_basis_from_normal(wm).t.x;
    r += mf_D(d, wm) + mf_G1(d, wo, wm) + mf_G2_separable(d, wo, wi, wm) + mf_D_visible(d, wo, wm);
    r += mf_fresnel_conductor(wo.z, MF_R(0.2), MF_R(3.9)) + mf_fresnel_dielectric(wo.z, MF_R(1.5));
    r += mf_fresnel_schlick(wo.z, MF_R(0.04)) + mf_beckmann_lambda_approx(MF_R(0.2), MF_R(0.2), wo);
    {
        mf_ltc l = mf_ltc_from_inverse(MF_R(2.0), MF_R(0.3), MF_R(2.5), MF_R(-0.2), MF_R(1.0));
        mf_vec3 q[4];
        q[0] = mf_vec3_make(-1, -1, 2); q[1] = mf_vec3_make(-1, 1, 2); q[2] = mf_vec3_make(1, 1, 2); q[3] = mf_vec3_make(1, -1, 2);
        r += mf_ltc_integrate(&l, q, 4, 0) + mf_ltc_eval(&l, wo) + mf_ltc_sample(&l, (mf_real)u[i], MF_R(0.5)).z;
        r += mf_polygon_irradiance(q, 4, 1) + mf_sphere_form_factor(mf_polygon_vector_form_factor(q, 4));
        r += mf_ltc_combined_alpha(mf_ltc_meso_alpha(MF_R(0.9)), MF_R(0.2));
    }
    {
        mf_leadr la = mf_leadr_with_roughness(mf_leadr_from_slope((mf_real)u[i], MF_R(0.1)), MF_R(0.2), MF_R(0.2));
        mf_ndf ld = mf_leadr_ndf(la);
        r += mf_leadr_specular(la, wo, wi) + mf_sample_visible(&ld, wo, MF_R(0.3), MF_R(0.4)).z + mf_lambda(&ld, wo);
    }
    { /* Inverse Bin Map: the queries only read the map's array, a device
         * pointer in a real kernel (a copy of the host struct pointing at it);
         * compiled here, never run */
        const mf_ibm *ibm_dev = (const mf_ibm *)(const void *)(u + n);
        mf_ibm ibm;
        mf_footprint f;
        mf_real pdf;
        int bins[MF_IBM_MAX_WINDOW];
        mf_real w[MF_IBM_MAX_WINDOW];
        ibm = *ibm_dev;
        f.u = (mf_real)u[i]; f.v = MF_R(0.5); f.ax = MF_R(0.01); f.ay = MF_R(0.0); f.bx = MF_R(0.0); f.by = MF_R(0.01);
        r += mf_ibm_brdf(&ibm, &f, wo, wi) + mf_ibm_pdf(&ibm, &f, wo, wi) + mf_ibm_brdf_and_pdf(&ibm, &f, wo, wi, &pdf);
        r += mf_ibm_sample(&ibm, &f, wo, (mf_real)u[i], MF_R(0.2), MF_R(0.3), MF_R(0.4)).wi.z + pdf;
        r += mf_ibm_bin_weight(&ibm, mf_ibm_bin_of(&ibm, wo), &f) + (mf_real)mf_ibm_bin_count(&ibm);
        r += (mf_real)mf_ibm_neighbourhood_weights(&ibm, &f, mf_ibm_texel_bin(&ibm, 1, 2), bins, w);
        r += mf_ibm_bin_normal(&ibm, 0).z + (mf_real)mf_ibm_bin_texels(&ibm, 0);
    }
    out[i] = (float)r;
}

// Tabulated distributions in device code: the table's block copied to the
// device, the struct rebased onto it (mf_tabulated_rebase) and passed by value.
__global__ void mf_kernel_tabulated(mf_tabulated t, const float *u, float *out, int n)
{
    int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    mf_ndf d = mf_tabulated_ndf(&t);
    mf_ndf dt = mf_transformed(d, mf_mat2_make(MF_R(1.2), MF_R(0.1), MF_R(0.0), MF_R(0.9)));
    mf_vec3 wo = mf_normalize(mf_vec3_make((mf_real)u[i], MF_R(0.2), MF_R(0.8)));
    mf_vec3 wi = mf_brdf_sample(&dt, wo, (mf_real)u[i], (mf_real)u[(i + 1) % n]).wi;
    mf_vec3 wm = mf_sample_D(&d, (mf_real)u[i], MF_R(0.5));
    out[i] = (float)(mf_brdf(&dt, wo, wi) + mf_brdf_pdf(&dt, wo, wi) + mf_D(&d, wm) + mf_lambda(&d, wo));
}
