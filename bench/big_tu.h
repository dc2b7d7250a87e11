/* big_tu.h - included by bench.c when MF_BENCH_BIG_TU is defined: 48 extern
 * functions that call the hot inline API, so the bench's translation unit
 * holds many more call sites than the bench itself (a renderer's shading
 * file). gcc's inlining budgets are per unit: without forced inlining the
 * hot helpers then move out of line. tools/bench_inline.sh compares the
 * bench lines of this build with the plain -O2 build. */
#define MF_BIG_TU_FN(i)                                                                              \
    double mf_bench_big_tu_##i(const mf_ndf *d, const mf_ltc *l, const mf_vec3 *q, mf_vec3 wo,        \
                               mf_vec3 wi, mf_real u1, mf_real u2);                                    \
    double mf_bench_big_tu_##i(const mf_ndf *d, const mf_ltc *l, const mf_vec3 *q, mf_vec3 wo,        \
                               mf_vec3 wi, mf_real u1, mf_real u2)                                     \
    {                                                                                                  \
        mf_vec3 wm = mf_normalize(mf_add(wo, wi));                                                     \
        mf_sample s = mf_brdf_sample(d, wo, u1, u2);                                                   \
        mf_sample t = mf_dielectric_sample(d, wo, MF_R(1.5), MF_RADIANCE, u1, u2, u1 * u2);            \
        return (double)(mf_D(d, wm) + mf_lambda(d, wo) + mf_G1(d, wo, wm) + mf_G2(d, wo, wi, wm) +   \
                        mf_brdf(d, wo, wi) + mf_brdf_pdf(d, wo, wi) + s.wi.z + s.pdf + s.weight +      \
                        mf_sample_D(d, u1, u2).z + mf_sample_visible(d, wo, u1, u2).z +                \
                        mf_dielectric_bsdf(d, wo, t.wi, MF_R(1.5), MF_RADIANCE) +                      \
                        mf_dielectric_pdf(d, wo, t.wi, MF_R(1.5)) + t.weight +                         \
                        mf_ggx_sample_visible(d->ax, d->ay, wo, u1, u2).x +                            \
                        mf_beckmann_sample_visible(d->ax, d->ay, wo, u1, u2).y +                       \
                        mf_ltc_integrate(l, q, 4, (int)(u1 > u2)) + mf_polygon_irradiance(q, 4, 1));   \
    }
#define MF_BIG_TU_8(a) MF_BIG_TU_FN(a##0) MF_BIG_TU_FN(a##1) MF_BIG_TU_FN(a##2) MF_BIG_TU_FN(a##3) \
                       MF_BIG_TU_FN(a##4) MF_BIG_TU_FN(a##5) MF_BIG_TU_FN(a##6) MF_BIG_TU_FN(a##7)
MF_BIG_TU_8(1) MF_BIG_TU_8(2) MF_BIG_TU_8(3) MF_BIG_TU_8(4) MF_BIG_TU_8(5) MF_BIG_TU_8(6)
