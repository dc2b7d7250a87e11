/* @api */
/* ======================================================================== */
/* == 11b. Rough dielectric BSDF                                            */
/* ======================================================================== */
/* Walter et al. 2007 ("Microfacet Models for Refraction through Rough
 * Surfaces") for every mf_ndf, transforms included. eta = index below the
 * surface (-z) over the index above it (+z); wo and wi on either side:
 * reflection when wo.z wi.z > 0, transmission otherwise. With eta_o the index
 * on wo's side and e = eta_i / eta_o the relative index across:
 *   reflection   f = F(wo.h) D(h) G2 / (4 |wo.z| |wi.z|),   h = normalize(wo + wi)  (Eq. 20)
 *   transmission f = (1 - F(wo.h)) D(h) G2 |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / e)^2) / e^2
 *                h = normalize(wo + e wi), facing wo's side  (Eqs. 16, 21)
 * with G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (the height-correlated form,
 * each direction's masking on its own side). The 1 / e^2 = (eta_o / eta_i)^2
 * factor is radiance transport: a path tracer following camera paths uses f
 * as it is. Importance transport (light tracing, photon mapping) omits it:
 * multiply the transmitted value by e^2. Reciprocity holds in the generalized
 * form f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2.
 * Sampling draws visible normals of wo's side (Heitz & d'Eon 2014), then
 * reflection with probability F(wo.h) and refraction otherwise (so the weight
 * f |cos| / pdf is G2 / G1(wo), times 1 / e^2 when transmitted).
 * A wo below the surface is handled by inverting every direction (a height
 * field seen from below, mirrored through the origin, has the same slope
 * distribution, so this is exact for every kind, non-centered LEADR
 * included) and using 1 / eta. At the smallest alpha (1e-4 after clamping)
 * the lobes are nearly a mirror and a refraction: sampling is exact and the
 * weights stay near F-free 1, but evaluating a fixed wi gives about 0 unless
 * it is within ~alpha of the specular directions; a renderer wanting the
 * delta limit uses mf_fresnel_dielectric with mf_reflect / mf_refract.
 * Thin-walled sheets (two interfaces) are not modelled here. */

/* Refraction of wi (pointing away, on n's side) through the unit normal n;
 * eta = n_transmitted / n_incident (as mf_fresnel_dielectric). *wt: unit, on
 * the other side. Returns 0 on total internal reflection or degenerate input
 * (then *wt is the zero vector). Snell: sin t = sin i / eta. */
MF_FORCE_INLINE int mf_refract(mf_vec3 wi, mf_vec3 n, mf_real eta, mf_vec3 *wt)
{
    mf_real ci = mf_dot(wi, n), s2t, ct;
    *wt = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG) || !(ci >= MF_R(0.0)) || !(ci <= MF_R(1.0) + MF_R(1e-3))) return 0;
    ci = mf_min(ci, MF_R(1.0));
    s2t = (MF_R(1.0) - ci * ci) / (eta * eta);
    if (!(s2t < MF_R(1.0))) return 0;
    ct = MF_SQRT(MF_R(1.0) - s2t);
    *wt = mf_normalize(mf_add(mf_scale(wi, MF_R(-1.0) / eta), mf_scale(n, ci / eta - ct)));
    return wt->z == wt->z && mf_dot(*wt, *wt) > MF_R(0.5);
}

/* wo above (after the inversion), e relative index across: the generalized
 * half vector of (wo, wi) facing up, and 1 when the configuration is valid
 * (wo and wi on the facet's correct sides). */
MF_FORCE_INLINE int mf__dielectric_half(mf_vec3 wo, mf_vec3 wi, mf_real e, mf_vec3 *h)
{
    mf_vec3 m = wi.z > MF_R(0.0) ? mf_add(wo, wi) : mf_add(wo, mf_scale(wi, e));
    mf_real l2 = mf_dot(m, m);
    if (!(l2 > MF_R(1e-30)) || !(l2 < MF_BIG)) return 0;
    m = mf_scale(m, MF_R(1.0) / MF_SQRT(l2));
    if (m.z < MF_R(0.0)) m = mf_scale(m, MF_R(-1.0));
    *h = m;
    if (!(mf_dot(m, wo) > MF_R(0.0))) return 0;
    return wi.z > MF_R(0.0) ? mf_dot(m, wi) > MF_R(0.0) : mf_dot(m, wi) < MF_R(0.0);
}

/* 1 when eta is a usable index and w a finite direction off the horizon */
MF_FORCE_INLINE int mf__dielectric_ok(mf_vec3 w, mf_real eta)
{
    return eta > MF_R(0.0) && eta < MF_BIG && MF_FABS(w.x) + MF_FABS(w.y) + MF_FABS(w.z) < MF_BIG && w.z != MF_R(0.0);
}

/* Prepares (wo, wi, eta) for the evaluation: inverts both when wo is below;
 * 0 when there is nothing to evaluate. */
MF_FORCE_INLINE int mf__dielectric_setup(mf_vec3 *wo, mf_vec3 *wi, mf_real *eta)
{
    if (!mf__dielectric_ok(*wo, *eta) || !mf__dielectric_ok(*wi, *eta)) return 0;   /* NaN, infinite, horizon */
    if (wo->z < MF_R(0.0)) {
        *wo = mf_scale(*wo, MF_R(-1.0));
        *wi = mf_scale(*wi, MF_R(-1.0));
        *eta = MF_R(1.0) / *eta;
    }
    return 1;
}

MF_FORCE_INLINE mf_real mf__dielectric_G2(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    /* wi below: its masking on the lower side is Lambda(-wi) (see above) */
    return mf__G2_up(d, wo, wi.z < MF_R(0.0) ? mf_scale(wi, MF_R(-1.0)) : wi);
}

/* The common part of eval and pdf: after the setup, the half vector h, wo.h,
 * the Fresnel reflectance there and, for transmission, the Jacobian's
 * denominator (wi.h + wo.h / e)^2 (Walter Eq. 17). 0 when nothing to do. */
MF_FORCE_INLINE int mf__dielectric_prep(mf_vec3 *wo, mf_vec3 *wi, mf_real *eta, mf_vec3 *h, mf_real *oh, mf_real *F, mf_real *den)
{
    mf_real x;
    if (!mf__dielectric_setup(wo, wi, eta) || !mf__dielectric_half(*wo, *wi, *eta, h)) return 0;
    *oh = mf_dot(*wo, *h);
    *F = mf_fresnel_dielectric(*oh, *eta);
    *den = MF_R(1.0);
    if (wi->z > MF_R(0.0)) return 1;   /* reflection: no Jacobian denominator */
    x = mf_dot(*wi, *h) + *oh / *eta;
    *den = x * x;
    return *den > MF_R(0.0);
}

MF_FORCE_INLINE mf_real mf_dielectric_bsdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_vec3 h;
    mf_real F, oh, den, g;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return MF_R(0.0);
    g = mf_D(d, h) * mf__dielectric_G2(d, wo, wi) / wo.z;   /* two divisions: no underflow of wo.z wi.z */
    if (wi.z > MF_R(0.0)) return mf_min(F * g / (MF_R(4.0) * wi.z), MF_BIG);
    return mf_min((MF_R(1.0) - F) * g * MF_FABS(mf_dot(wi, h)) * oh / (den * -wi.z * eta * eta), MF_BIG);
}

/* Density of mf_dielectric_sample per unit solid angle of wi (either side). */
MF_FORCE_INLINE mf_real mf_dielectric_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_vec3 h;
    mf_real F, oh, den, dv;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return MF_R(0.0);
    dv = mf_D_visible(d, wo, h);
    if (wi.z > MF_R(0.0)) return mf_min(F * dv / (MF_R(4.0) * oh), MF_BIG);
    return mf_min((MF_R(1.0) - F) * dv * MF_FABS(mf_dot(wi, h)) / den, MF_BIG);   /* Jacobian |wi.h| / (wi.h + wo.h / e)^2 */
}

/* Samples wi (reflected or transmitted) for wo on either side from three
 * uniform numbers; the zero vector means no sample. */
MF_FORCE_INLINE mf_vec3 mf_dielectric_sample(const mf_ndf *d, mf_vec3 wo, mf_real eta, mf_real u1, mf_real u2, mf_real u3)
{
    mf_vec3 m, wi, zero = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    mf_real s = MF_R(1.0), F;
    if (!mf__dielectric_ok(wo, eta)) return zero;
    if (wo.z < MF_R(0.0)) { wo = mf_scale(wo, MF_R(-1.0)); eta = MF_R(1.0) / eta; s = MF_R(-1.0); }
    m = mf_sample_visible(d, wo, u1, u2);
    if (!(m.z > MF_R(0.0)) || !(mf_dot(wo, m) > MF_R(0.0))) return zero;
    F = mf_fresnel_dielectric(mf_dot(wo, m), eta);
    if (u3 < F) {
        wi = mf_reflect(wo, m);
        if (!(wi.z > MF_R(0.0))) return zero;
    } else {
        if (!mf_refract(wo, m, eta, &wi) || !(wi.z < MF_R(0.0))) return zero;
    }
    return mf_scale(wi, s);
}

/* f |wi.z| / pdf for a wi from mf_dielectric_sample: G2 / G1(wo) = (1 +
 * Lambda(wo)) G2, divided by e^2 when transmitted (radiance transport);
 * for LEADR moments (a tilted mean surface) the ratio itself. */
MF_FORCE_INLINE mf_real mf_dielectric_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_real w;
    if (mf__ndf_tilted(d->type)) {   /* visible normals of a tilted mean surface: the ratio itself */
        w = mf_dielectric_pdf(d, wo, wi, eta);
        return w > MF_R(0.0) ? mf_min(mf_dielectric_bsdf(d, wo, wi, eta) * MF_FABS(wi.z) / w, MF_BIG) : MF_R(0.0);
    }
    if (!mf__dielectric_setup(&wo, &wi, &eta)) return MF_R(0.0);
    w = (MF_R(1.0) + mf_lambda(d, wo)) * mf__dielectric_G2(d, wo, wi);
    return wi.z > MF_R(0.0) ? w : w / (eta * eta);
}
