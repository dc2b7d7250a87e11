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

MF_FORCE_INLINE mf_real mf_brdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
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

MF_FORCE_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi);

/* Samples wi for wo; wi.z <= 0 (the zero vector) means no sample. A wi is
 * returned only where mf_brdf_pdf is positive (rounding can put a sampled
 * normal where D underflows to 0, e.g. Beckmann 0.01 at u = (0, 0)). */
MF_FORCE_INLINE mf_vec3 mf_brdf_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
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
MF_FORCE_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
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
MF_FORCE_INLINE mf_real mf_brdf_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_real lo;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    lo = mf_lambda(d, wo);
    return (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(d, wi));
}

/* GGX bounded visible-normal sampling (Eto & Tokuyoshi 2023, "Bounded VNDF
 * Sampling for Smith-GGX Reflections", Listings 1-2). The spherical cap of
 * Dupuy & Benyoub 2023 is shrunk by k (the paper's Eq. 5, with a = min(ax, ay)
 * for anisotropic GGX, Eq. 6) to a cap that still holds every normal whose
 * reflection of wo is above the horizon but far fewer of the others: fewer
 * samples lost (none for isotropic GGX at normal incidence; at alpha 0.5 and
 * 80 degrees 1.4% instead of 7.5%) and a lower-variance estimator (plain /
 * bounded variance of the albedo estimate 2.2 at alpha 0.5, 2.5 to 4 at alpha
 * 1; test_materials). A reflection below the horizon is still possible and
 * counts as no sample. Returns a normal wm (reflect wo on it for wi, as after
 * mf_sample_visible); the zero vector when wo.z <= 0. Any other kind than untransformed GGX falls back to
 * mf_sample_visible, and mf_ggx_brdf_pdf_bounded to mf_brdf_pdf, so the pair
 * stays consistent for every mf_ndf. */
MF_FORCE_INLINE mf_real mf__ggx_bounded_k(mf_real ax, mf_real ay, mf_vec3 wo)
{
    mf_real a = mf_clamp(mf_min(ax, ay), MF_R(0.0), MF_R(1.0)), a2 = a * a;
    mf_real s = MF_R(1.0) + MF_SQRT(wo.x * wo.x + wo.y * wo.y), s2 = s * s;
    return (MF_R(1.0) - a2) * s2 / (s2 + a2 * wo.z * wo.z);   /* Eq. 5 */
}
MF_FORCE_INLINE mf_vec3 mf_ggx_sample_visible_bounded(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (!mf__ndf_tr(d->type) || d->transformed) return mf_sample_visible(d, wo, u1, u2);
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(d->ax, d->ay, wo, mf_clamp(u1, MF_R(0.0), MF_R(1.0)), mf_clamp(u2, MF_R(0.0), MF_R(1.0)),
                                  mf__ggx_bounded_k(d->ax, d->ay, wo));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}
/* Density per unit solid angle of wi = reflect(wo, wm) for wm from
 * mf_ggx_sample_visible_bounded (paper Listing 2): D(wm) / (2 (k wo.z + t)),
 * t = |(ax wo.x, ay wo.y, wo.z)|; plain VNDF sampling is the case k = 1. */
MF_FORCE_INLINE mf_real mf_ggx_brdf_pdf_bounded(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    mf_real t, k;
    if (!mf__ndf_tr(d->type) || d->transformed) return mf_brdf_pdf(d, wo, wi);
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    if (!(mf_dot(wo, wh) > MF_R(0.0))) return MF_R(0.0);
    t = MF_SQRT(d->ax * d->ax * wo.x * wo.x + d->ay * d->ay * wo.y * wo.y + wo.z * wo.z);
    k = mf__ggx_bounded_k(d->ax, d->ay, wo);
    return mf_min(mf_ggx_D(d->ax, d->ay, wh) / (MF_R(2.0) * (k * wo.z + t)), MF_BIG);
}

/* Hemispherical averages of the Fresnel terms, F_avg = 2 int_0^1 F(mu) mu dmu
 * (Kulla & Conty 2017, the energy-compensation average; 1 - F_avg is the
 * share a cosine-distributed light transmits). Dielectric of relative index
 * eta (eta < 1: seen from the denser side, total internal reflection below
 * the critical cosine mu_c = sqrt(1 - eta^2)), conductor eta + i k. On each
 * side of mu_c (0 when eta >= 1), 8 panels of 8-point Gauss-Legendre in t,
 * mu = mu_c -+ len t^2, which smooths the square root at the critical angle;
 * within 1e-8 of a dense integral in double, 1e-6 in float (test_materials). */
MF_COLD mf_real mf_fresnel_dielectric_average(mf_real eta);
MF_COLD mf_real mf_fresnel_conductor_average(mf_real eta, mf_real k);

/* @cold */
/* Fresnel averages (section 11): the quadrature. */
MF_INLINE mf_real mf__fresnel_average(mf_real eta, mf_real k, int conductor)
{
    mf_real mu_c = MF_R(0.0), sum = MF_R(0.0);
    int side, p, i;
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG) || !(k >= MF_R(0.0)) || !(k < MF_BIG)) return MF_R(0.0);
    if (eta < MF_R(1.0)) mu_c = MF_SQRT(MF_R(1.0) - eta * eta);   /* where F drops from (near) 1 */
    for (side = 0; side < 2; ++side) {
        mf_real len = side ? MF_R(1.0) - mu_c : mu_c;   /* mu = mu_c -+ len t^2 */
        if (!(len > MF_R(0.0))) continue;
        for (p = 0; p < 8; ++p)
            for (i = 0; i < 8; ++i) {
                mf_real t = mf__gl_node01(p, i, 8);
                mf_real mu = side ? mu_c + len * t * t : mu_c - len * t * t;
                mf_real f = conductor ? mf_fresnel_conductor(mu, eta, k) : mf_fresnel_dielectric(mu, eta);
                /* 2 F mu dmu, dmu = 2 len t dt, panel width 1/8 (weights sum to 1) */
                sum += mf__gl_w(i) * MF_R(4.0) * len * f * mu * t / MF_R(8.0);
            }
    }
    return mf_clamp(sum, MF_R(0.0), MF_R(1.0));
}
MF_COLD mf_real mf_fresnel_dielectric_average(mf_real eta) { return mf__fresnel_average(eta, MF_R(0.0), 0); }
MF_COLD mf_real mf_fresnel_conductor_average(mf_real eta, mf_real k) { return mf__fresnel_average(eta, k, 1); }
