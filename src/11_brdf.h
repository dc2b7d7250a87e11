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

/* Samples wi for wo through the visible normals of wo (Heitz & d'Eon 2014)
 * and returns the record: pdf = D_wo(wh) / (4 wo.wh) (mf_brdf_pdf, at the
 * half vector of (wo, wi) as mf_brdf_pdf computes it, so the two agree to
 * the last bit), weight f wi.z / pdf = G2 / G1(wo) = (1 + Lambda(wo)) /
 * (1 + Lambda(wo) + Lambda(wi)). D and the two Lambdas are computed once for
 * the three. No sample (MF_LOBE_NONE) when wo.z <= 0, when the reflection
 * falls below the horizon, or where rounding puts the normal where D
 * underflows or wo.wh vanishes (pdf 0). */
MF_FORCE_INLINE mf_sample mf_brdf_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_sample s = mf__no_sample();
    mf_vec3 wm, wi, wh;
    mf_real lo, li, pdf, c;
    if (!(wo.z > MF_R(0.0))) return s;
    wm = mf_sample_visible(d, wo, u1, u2);
    wi = mf_reflect(wo, wm);
    if (!(wi.z > MF_R(0.0)) || !(wm.z > MF_R(0.0)) || !(wi.x == wi.x && wi.y == wi.y)) return s;
    wh = mf_normalize(mf_add(wo, wi));
    c = mf_dot(wo, wh);
    if (!(c > MF_R(0.0))) return s;
    lo = mf_lambda(d, wo);
    li = mf_lambda(d, wi);
    pdf = mf__cap(mf__cap(c * mf_D(d, wh) / mf__projected_area_l(d, wo, lo)) / (MF_R(4.0) * c));
    if (!(pdf > MF_R(0.0))) return s;
    s.wi = wi;
    s.pdf = pdf;
    s.weight = (MF_R(1.0) + lo) / (MF_R(1.0) + lo + li);
    s.lobe = MF_LOBE_REFLECTION;
    return s;
}

/* GGX bounded visible-normal sampling (Eto & Tokuyoshi 2023, "Bounded VNDF
 * Sampling for Smith-GGX Reflections", Listings 1-2). The spherical cap of
 * Dupuy & Benyoub 2023 is shrunk by k (the paper's Eq. 5, with a = min(ax, ay)
 * for anisotropic GGX, Eq. 6) to a cap that still holds every normal whose
 * reflection of wo is above the horizon but far fewer of the others: fewer
 * samples lost and a lower-variance estimator (test_materials). A reflection
 * below the horizon is still possible and counts as no sample. Kinds other
 * than untransformed GGX take mf_brdf_sample, and mf_brdf_pdf_bounded
 * mf_brdf_pdf, so the pair stays consistent for every mf_ndf. */
MF_FORCE_INLINE mf_real mf__ggx_bounded_k(mf_real ax, mf_real ay, mf_vec3 wo)
{
    mf_real a = mf_clamp(mf_min(ax, ay), MF_R(0.0), MF_R(1.0)), a2 = a * a;
    mf_real s = MF_R(1.0) + MF_SQRT(wo.x * wo.x + wo.y * wo.y), s2 = s * s;
    return (MF_R(1.0) - a2) * s2 / (s2 + a2 * wo.z * wo.z);   /* Eq. 5 */
}
/* 1 when the bounded sampler applies to d (untransformed GGX) */
MF_FORCE_INLINE int mf__bounded_applies(const mf_ndf *d) { return mf__ndf_tr(d->type) && !d->transformed; }
/* The bounded pdf's denominator 2 (k wo.z + t), t = |(ax wo.x, ay wo.y, wo.z)|
 * (Listing 2): pdf(wi) = D(wm) / that. */
MF_FORCE_INLINE mf_real mf__ggx_bounded_den(const mf_ndf *d, mf_vec3 wo)
{
    mf_real t = MF_SQRT(d->ax * d->ax * wo.x * wo.x + d->ay * d->ay * wo.y * wo.y + wo.z * wo.z);
    return MF_R(2.0) * (mf__ggx_bounded_k(d->ax, d->ay, wo) * wo.z + t);
}
/* The record of a bounded sample: pdf = D(wm) / (2 (k wo.z + t)), weight
 * f wi.z / pdf = G2 (k wo.z + t) / (2 wo.z). */
MF_FORCE_INLINE mf_sample mf_brdf_sample_bounded(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_sample s = mf__no_sample();
    mf_vec3 h, wi;
    mf_real den, pdf;
    if (!mf__bounded_applies(d)) return mf_brdf_sample(d, wo, u1, u2);
    if (!(wo.z > MF_R(0.0))) return s;
    h = mf__ggx_vndf_unnormalized(d->ax, d->ay, wo, mf__u01(u1), mf__u01(u2), mf__ggx_bounded_k(d->ax, d->ay, wo));
    h = mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
    wi = mf_reflect(wo, h);
    if (!(wi.z > MF_R(0.0)) || !(mf_dot(wo, h) > MF_R(0.0))) return s;
    h = mf_normalize(mf_add(wo, wi));   /* as mf_brdf_pdf_bounded: the two agree exactly */
    if (!(mf_dot(wo, h) > MF_R(0.0))) return s;
    den = mf__ggx_bounded_den(d, wo);
    pdf = mf_min(mf_ggx_D(d->ax, d->ay, h) / den, MF_BIG);
    if (!(pdf > MF_R(0.0))) return s;
    s.wi = wi;
    s.pdf = pdf;
    s.weight = mf_min(mf__ggx_G2(d->ax, d->ay, wo, wi) * den / (MF_R(4.0) * wo.z), MF_BIG);
    s.lobe = MF_LOBE_REFLECTION;
    return s;
}
/* Density of mf_brdf_sample_bounded per unit solid angle of wi. */
MF_FORCE_INLINE mf_real mf_brdf_pdf_bounded(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    if (!mf__bounded_applies(d)) return mf_brdf_pdf(d, wo, wi);
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    if (!(mf_dot(wo, wh) > MF_R(0.0))) return MF_R(0.0);
    return mf_min(mf_ggx_D(d->ax, d->ay, wh) / mf__ggx_bounded_den(d, wo), MF_BIG);
}

/* Hemispherical averages of the Fresnel terms, F_avg = 2 int_0^1 F(mu) mu dmu
 * (Kulla & Conty 2017, the energy-compensation average; 1 - F_avg is the
 * share a cosine-distributed light transmits). Dielectric of relative index
 * eta (eta < 1: seen from the denser side, total internal reflection below
 * the critical cosine mu_c = sqrt(1 - eta^2)), conductor eta + i k. On each
 * side of mu_c (0 when eta >= 1), 8 panels of 8-point Gauss-Legendre in t,
 * mu = mu_c -+ len t^2, which smooths the square root at the critical angle;
 * within 1e-8 of a dense integral in double, 1e-6 in float (test_materials).
 * Per material: 128 Fresnel evaluations a call (bench fresnel_avg), so
 * compute F_avg once with the material's eta and k, never per sample. */
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
