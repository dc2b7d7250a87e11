/* @api */
/* ======================================================================== */
/* == 11. Specular microfacet BRDF                                          */
/* ======================================================================== */
/* f(wo, wi) = D(wh) G2(wo, wi, wh) / (4 |wo.z| |wi.z|) (Walter et al. 2007
 * Eq. 20 without Fresnel), sampled through the visible normals of wo
 * (Heitz & d'Eon 2014): pdf(wi) = D_wo(wh) / (4 wo.wh). Reflection only.
 * For LEADR moments wo.z is replaced by the mean surface's projected area
 * wo . (-E_x, -E_y, 1) (LEADR Eq. 16-17), which keeps the energy but is not
 * reciprocal when the mean slope is not 0. */

MF_INLINE mf_real mf_brdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    if (!(wh.z > MF_R(0.0))) return MF_R(0.0);
    /* f grows like 1/cos at grazing retro-reflection: divide in two steps and
     * cap, so float never overflows */
    /* wo below a tilted mean surface (LEADR): fully masked. Without this, in
     * float G2 = 1/(1 + MF_BIG) and the clamped projection 1e-30 cancel. */
    {
        mf_real p = mf__mean_surface_proj(d, wo);
        if (!(p > MF_R(0.0))) return MF_R(0.0);
        return mf_min(mf_D(d, wh) * mf_G2(d, wo, wi, wh) / (MF_R(4.0) * p) / wi.z, MF_BIG);
    }
}

MF_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi);

/* Samples wi for wo; wi.z <= 0 (the zero vector) means no sample. A wi is
 * returned only where mf_brdf_pdf is positive (rounding can put a sampled
 * normal where D underflows to 0, e.g. Beckmann 0.01 at u = (0, 0)). */
MF_INLINE mf_vec3 mf_brdf_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 wm, wi;
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    wm = mf_sample_visible(d, wo, u1, u2);
    wi = mf_reflect(wo, wm);
    if (!(wi.z > MF_R(0.0)) || !(wm.z > MF_R(0.0)) || !(wi.x == wi.x && wi.y == wi.y) ||
        !(mf_brdf_pdf(d, wo, wi) > MF_R(0.0)))
        return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return wi;
}

/* Density of mf_brdf_sample per unit solid angle of wi; capped at MF_BIG
 * (near the horizon D_visible / (4 wo.wh) overflows float). */
MF_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    mf_real c, p;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    c = mf_dot(wo, wh);
    if (!(c > MF_R(0.0))) return MF_R(0.0);
    p = mf_D_visible(d, wo, wh) / (MF_R(4.0) * c);
    return mf__cap(p);
}

/* f(wo, wi) wi.z / pdf(wi) for a wi from mf_brdf_sample: G2 / G1(wo)
 * = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)). */
MF_INLINE mf_real mf_brdf_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_real lo;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    lo = mf_lambda(d, wo);
    return (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(d, wi));
}
