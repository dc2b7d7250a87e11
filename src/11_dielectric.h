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
 * factor is radiance transport (MF_RADIANCE: a path tracer following camera
 * paths); importance transport (MF_IMPORTANCE: light tracing, photon
 * mapping) omits it. Reciprocity holds in the generalized
 * form f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2.
 * Sampling draws visible normals of wo's side (Heitz & d'Eon 2014), then
 * reflection with probability F(wo.h) and refraction otherwise (so the weight
 * f |cos| / pdf is G2 / G1(wo), times 1 / e^2 when transmitted radiance).
 * A wo below the surface is handled by inverting every direction (a height
 * field seen from below, mirrored through the origin, has the same slope
 * distribution, so this is exact for every kind, non-centered LEADR
 * included) and using 1 / eta. At the smallest alpha (1e-4 after clamping)
 * the lobes are nearly a mirror and a refraction: sampling is exact and the
 * weights stay near F-free 1, but evaluating a fixed wi gives about 0 unless
 * it is within ~alpha of the specular directions; a renderer wanting the
 * delta limit uses mf_fresnel_dielectric with mf_reflect / mf_refract.
 * Thin-walled sheets (two interfaces) are not modelled here. */

/* Refraction of wi (unit, pointing away from the surface) through the unit
 * normal n; eta = index on the side opposite n over index on n's side (the
 * library's convention with n for +z). wi on either side: below n
 * (wi.n < 0) the function uses -n and 1 / eta. *wt: unit, on the other side
 * from wi. Returns 1 when refracted, 0 on total internal reflection or
 * degenerate input (then *wt is the zero vector). Snell: sin t = sin i / e. */
MF_FORCE_INLINE int mf_refract(mf_vec3 wi, mf_vec3 n, mf_real eta, mf_vec3 *wt)
{
    mf_real ci = mf_dot(wi, n), s2t, ct;
    *wt = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG) || !(MF_FABS(ci) <= MF_R(1.0) + MF_R(1e-3))) return 0;
    if (ci < MF_R(0.0)) { n = mf_scale(n, MF_R(-1.0)); ci = -ci; eta = MF_R(1.0) / eta; }
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

/* f(wo, wi) in the given transport mode: MF_RADIANCE carries the 1 / e^2
 * factor on transmission, MF_IMPORTANCE does not (its transmitted value is
 * the radiance one times e^2; the adjoint BSDF of Veach 1997, Sec. 5.2). */
MF_FORCE_INLINE mf_real mf_dielectric_bsdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta, mf_transport mode)
{
    mf_vec3 h;
    mf_real F, oh, den, g;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return MF_R(0.0);
    g = mf_D(d, h) * mf__dielectric_G2(d, wo, wi) / wo.z;   /* two divisions: no underflow of wo.z wi.z */
    if (wi.z > MF_R(0.0)) return mf_min(F * g / (MF_R(4.0) * wi.z), MF_BIG);
    g = (MF_R(1.0) - F) * g * MF_FABS(mf_dot(wi, h)) * oh / (den * -wi.z);
    return mf_min(mode == MF_IMPORTANCE ? g : g / (eta * eta), MF_BIG);
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

/* The record of a sampled wi: pdf and f as mf_dielectric_pdf and
 * mf_dielectric_bsdf compute them (the same half vector, so the record and
 * the functions agree), with D and the two Lambdas computed once. */
MF_FORCE_INLINE mf_sample mf__dielectric_record(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta, mf_transport mode)
{
    mf_sample s = mf__no_sample();
    mf_vec3 h, wo0 = wo, wi0 = wi;
    mf_real F, oh, den, dm, lo, li, A, dv, p, f;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return s;
    dm = mf_D(d, h);
    lo = mf_lambda(d, wo);
    li = mf_lambda(d, wi.z < MF_R(0.0) ? mf_scale(wi, MF_R(-1.0)) : wi);
    A = mf__projected_area_l(d, wo, lo);
    dv = mf__cap(oh * dm / A);                                 /* mf_D_visible(d, wo, h) */
    f = dm / ((MF_R(1.0) + lo + li) * wo.z);                   /* D G2 / wo.z */
    if (wi.z > MF_R(0.0)) {
        p = mf_min(F * dv / (MF_R(4.0) * oh), MF_BIG);
        f = mf_min(F * f / (MF_R(4.0) * wi.z), MF_BIG);
    } else {
        p = mf_min((MF_R(1.0) - F) * dv * MF_FABS(mf_dot(wi, h)) / den, MF_BIG);
        f = (MF_R(1.0) - F) * f * MF_FABS(mf_dot(wi, h)) * oh / (den * -wi.z);
        f = mf_min(mode == MF_IMPORTANCE ? f : f / (eta * eta), MF_BIG);
    }
    if (!(p > MF_R(0.0))) return s;
    s.wi = wi0;
    s.pdf = p;
    s.weight = mf_min(f * MF_FABS(wi.z) / p, MF_BIG);
    s.lobe = wo0.z * wi0.z > MF_R(0.0) ? MF_LOBE_REFLECTION : MF_LOBE_TRANSMISSION;
    return s;
}

/* Samples wi (reflected or transmitted) for wo on either side from three
 * uniform numbers (u1, u2 the visible normal of wo's side, u3 the choice
 * between reflection, with probability F(wo.m), and refraction) and returns
 * the record: pdf as mf_dielectric_pdf, weight f |wi.z| / pdf = G2 / G1(wo)
 * = (1 + Lambda(wo)) G2 (LEADR's tilted mean surface: A(wo) G2 / wo.z),
 * divided by e^2 when transmitted in radiance transport. No sample where
 * rounding leaves wi without density (a grazing refraction whose half
 * vector no longer faces both directions). */
MF_FORCE_INLINE mf_sample mf_dielectric_sample(const mf_ndf *d, mf_vec3 wo, mf_real eta, mf_transport mode,
                                               mf_real u1, mf_real u2, mf_real u3)
{
    mf_vec3 m, wi, w = wo;
    mf_real e = eta, F, c;
    if (!mf__dielectric_ok(wo, eta)) return mf__no_sample();
    if (w.z < MF_R(0.0)) { w = mf_scale(w, MF_R(-1.0)); e = MF_R(1.0) / e; }
    m = mf_sample_visible(d, w, u1, u2);
    c = mf_dot(w, m);
    if (!(m.z > MF_R(0.0)) || !(c > MF_R(0.0))) return mf__no_sample();
    F = mf_fresnel_dielectric(c, e);
    if (mf__u01(u3) < F) {
        wi = mf_reflect(w, m);
        if (!(wi.z > MF_R(0.0))) return mf__no_sample();
    } else if (!mf_refract(w, m, e, &wi) || !(wi.z < MF_R(0.0))) return mf__no_sample();
    if (wo.z < MF_R(0.0)) wi = mf_scale(wi, MF_R(-1.0));
    return mf__dielectric_record(d, wo, wi, eta, mode);
}
