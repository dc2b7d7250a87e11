/* @optional MF_NO_DEPRECATED */
/* @api */
/* ======================================================================== */
/* == 97. Deprecated 0.3 names (removed in 0.5; MF_NO_DEPRECATED drops them) */
/* ======================================================================== */
/* The 0.3 names of renamed functions, each a thin inline wrapper of its 0.4
 * form, marked deprecated where the compiler can say so. Functions whose
 * signature changed under the same name (the samplers now return mf_sample,
 * the dielectric functions take an mf_transport, the Fresnel functions take
 * the cosine first) have no alias: the README's migration table lists them. */
#if defined(__cplusplus) && __cplusplus >= 201402L
#define MF_DEPRECATED(msg) [[deprecated(msg)]]
#elif defined(__GNUC__) || defined(__clang__)
#define MF_DEPRECATED(msg) __attribute__((deprecated(msg)))
#elif defined(_MSC_VER)
#define MF_DEPRECATED(msg) __declspec(deprecated(msg))
#else
#define MF_DEPRECATED(msg)
#endif

/* 0.3: the sample weight G2 / G1(wo) of mf_brdf_sample's direction */
MF_DEPRECATED("use mf_brdf_sample(...).weight") MF_INLINE mf_real mf_brdf_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_real lo;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    lo = mf_lambda(d, wo);
    return (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(d, wi));
}
/* 0.3: a normal of the bounded cap (reflect wo on it for wi) */
MF_DEPRECATED("use mf_brdf_sample_bounded") MF_INLINE mf_vec3 mf_ggx_sample_visible_bounded(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (!mf__bounded_applies(d)) return mf_sample_visible(d, wo, u1, u2);
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(d->ax, d->ay, wo, mf__u01(u1), mf__u01(u2), mf__ggx_bounded_k(d->ax, d->ay, wo));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}
MF_DEPRECATED("use mf_brdf_pdf_bounded") MF_INLINE mf_real mf_ggx_brdf_pdf_bounded(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    return mf_brdf_pdf_bounded(d, wo, wi);
}
/* 0.3: f |wi.z| / pdf of mf_dielectric_sample's direction, radiance transport */
MF_DEPRECATED("use mf_dielectric_sample(...).weight") MF_INLINE mf_real mf_dielectric_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_real p = mf_dielectric_pdf(d, wo, wi, eta);
    return p > MF_R(0.0) ? mf_min(mf_dielectric_bsdf(d, wo, wi, eta, MF_RADIANCE) * MF_FABS(wi.z) / p, MF_BIG) : MF_R(0.0);
}
MF_DEPRECATED("use mf_albedo_table_brdf_ms") MF_INLINE mf_real mf_brdf_ms_table(const mf_albedo_table *t, mf_vec3 wo, mf_vec3 wi)
{
    return mf_albedo_table_brdf_ms(t, wo, wi);
}
MF_DEPRECATED("use mf_dielectric_ms_table_build") MF_INLINE mf_result mf_dielectric_ms_build(mf_dielectric_ms_table *t, const mf_ndf *d, mf_real eta, int n_mu, int panels)
{
    return mf_dielectric_ms_table_build(t, d, eta, n_mu, panels);
}
MF_DEPRECATED("use mf_dielectric_ms_table_release") MF_INLINE void mf_dielectric_ms_release(mf_dielectric_ms_table *t)
{
    mf_dielectric_ms_table_release(t);
}
MF_DEPRECATED("use mf_dielectric_ms_table_pdf") MF_INLINE mf_real mf_dielectric_ms_pdf(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_vec3 wi)
{
    return mf_dielectric_ms_table_pdf(t, wo, wi);
}
/* 0.3: an orthonormal t, b around n */
MF_DEPRECATED("use mf_basis_from_normal") MF_INLINE void mf_frame(mf_vec3 n, mf_vec3 *t, mf_vec3 *b)
{
    mf_basis f = mf_basis_from_normal(n);
    *t = f.t;
    *b = f.b;
}
MF_DEPRECATED("use mf_transform_is_valid") MF_INLINE int mf_transform_valid(mf_mat2 M)
{
    return mf_transform_is_valid(M);
}
#ifndef MF_NO_LEADR
/* 0.3: 1 when the moments were valid as given */
MF_DEPRECATED("use mf_leadr_to_covariance (mf_result)") MF_INLINE int mf_leadr_covariance(mf_leadr a, mf_real *var_x, mf_real *var_y, mf_real *cov_xy)
{
    return mf_leadr_to_covariance(a, var_x, var_y, cov_xy) == MF_SUCCESS;
}
#endif
#ifndef MF_NO_IBM
MF_DEPRECATED("use mf_ibm_brdf_and_pdf") MF_INLINE mf_real mf_ibm_brdf_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf)
{
    return mf_ibm_brdf_and_pdf(ibm, f, wo, wi, pdf);
}
#endif
#ifndef MF_NO_MICROSURFACE
/* 0.3: options filled with the defaults; in 0.4 all-zero options are the defaults */
MF_DEPRECATED("zero the struct: all-zero options are the defaults") MF_INLINE void mf_microsurface_options_default(mf_microsurface_options *o)
{
    if (o) memset(o, 0, sizeof *o);
}
MF_DEPRECATED("zero the struct: an all-zero configuration is the default") MF_INLINE void mf_gonio_config_default(mf_gonio_config *c)
{
    if (c) memset(c, 0, sizeof *c);
}
#endif
