/* @api */
/* ======================================================================== */
/* == 3. Fresnel                                                            */
/* ======================================================================== */
/* Unpolarized reflectance of a smooth interface whose normal is +z. Every
 * Fresnel function takes the cosine first. One index convention for the
 * whole library: eta = index on the -z side over index on the +z side; the
 * sign of cos_theta (the incident direction's z) says which side the light
 * is on, and the function flips eta itself. */

/* Dielectric: cos_theta > 0 reflects on the +z side (relative index eta
 * across), cos_theta < 0 on the -z side (1 / eta). eta is clamped to
 * [1e-6, 1e6] (<= 0 or NaN gives 0). 1 on total internal reflection. */
MF_FORCE_INLINE mf_real mf_fresnel_dielectric(mf_real cos_theta_i, mf_real eta)
{
    mf_real ci, s2t, ct, rs, rp;
    if (!(eta > MF_R(0.0)) || !(cos_theta_i == cos_theta_i)) return MF_R(0.0);
    eta = mf_clamp(eta, MF_R(1e-6), MF_R(1e6));
    ci = mf_clamp(cos_theta_i, MF_R(-1.0), MF_R(1.0));
    if (ci < MF_R(0.0)) { eta = MF_R(1.0) / eta; ci = -ci; }
    s2t = (MF_R(1.0) - ci * ci) / (eta * eta);           /* Snell */
    if (s2t >= MF_R(1.0)) return MF_R(1.0);
    ct = MF_SQRT(MF_R(1.0) - s2t);
    rs = (ci - eta * ct) / (ci + eta * ct);
    rp = (eta * ci - ct) / (eta * ci + ct);
    return MF_R(0.5) * (rs * rs + rp * rp);
}

/* Conductor with complex index of refraction eta + i k (relative to the
 * outside medium, on the +z side); exact unpolarized form. Light cannot come
 * from inside a conductor: cos_theta is clamped to [0, 1] (grazing, F = 1,
 * for cos_theta <= 0). eta <= 0, k < 0 or NaN give 0; eta and k are capped
 * at 1e6. */
MF_INLINE mf_real mf_fresnel_conductor(mf_real cos_theta_i, mf_real eta, mf_real k)
{
    mf_real c = mf_clamp(cos_theta_i, MF_R(0.0), MF_R(1.0));
    if (!(eta > MF_R(0.0)) || !(k >= MF_R(0.0)) || !(c == c)) return MF_R(0.0);
    eta = mf_min(eta, MF_R(1e6));
    k = mf_min(k, MF_R(1e6));
    mf_real c2 = c * c, s2 = MF_R(1.0) - c2;
    mf_real e2 = eta * eta, k2 = k * k;
    mf_real t0 = e2 - k2 - s2;
    /* every value below is finite (inputs checked and capped): mf__max_num */
    mf_real a2b2 = MF_SQRT(mf__max_num(t0 * t0 + MF_R(4.0) * e2 * k2, MF_R(0.0)));
    mf_real a = MF_SQRT(mf__max_num(MF_R(0.5) * (a2b2 + t0), MF_R(0.0)));
    mf_real t1 = a2b2 + c2, t2 = MF_R(2.0) * a * c;
    mf_real rs = (t1 - t2) / mf__max_num(t1 + t2, MF_R(1e-30));
    mf_real t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    mf_real rp = rs * (t3 - t4) / mf__max_num(t3 + t4, MF_R(1e-30));
    return mf_clamp(MF_R(0.5) * (rp + rs), MF_R(0.0), MF_R(1.0));
}


/* Normal-incidence reflectance of a dielectric of relative index eta,
 * ((eta - 1) / (eta + 1))^2, and the eta > 1 giving f0 (f0 in [0, 1), clamped
 * below 1 - 1e-6). Non-finite or non-positive input gives 0 / 1. */
MF_INLINE mf_real mf_f0_from_ior(mf_real eta)
{
    mf_real r;
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG)) return MF_R(0.0);
    r = (eta - MF_R(1.0)) / (eta + MF_R(1.0));
    return r * r;
}
MF_INLINE mf_real mf_ior_from_f0(mf_real f0)
{
    mf_real s;
    if (!(f0 > MF_R(0.0))) return MF_R(1.0);
    s = MF_SQRT(mf_min(f0, MF_R(1.0) - MF_R(1e-6)));
    return (MF_R(1.0) + s) / (MF_R(1.0) - s);
}

/* Schlick with an edge value: f0 + (f90 - f0)(1 - cos)^5 (f90 = 1 is
 * mf_fresnel_schlick; Burley 2012 and Filament use f90 for specular
 * occlusion). cos_theta is clamped to [0, 1]. */
MF_FORCE_INLINE mf_real mf_fresnel_schlick_f90(mf_real cos_theta, mf_real f0, mf_real f90)
{
    mf_real m = MF_R(1.0) - mf_clamp(cos_theta, MF_R(0.0), MF_R(1.0)), m2;
    if (!(m == m)) m = MF_R(0.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    f90 = mf_clamp(f90, MF_R(0.0), MF_R(1.0));
    m2 = m * m;
    return f0 + (f90 - f0) * m2 * m2 * m;
}
/* Schlick's approximation f0 + (1 - f0)(1 - cos)^5: the f90 = 1 case. */
MF_FORCE_INLINE mf_real mf_fresnel_schlick(mf_real cos_theta, mf_real f0)
{
    return mf_fresnel_schlick_f90(cos_theta, f0, MF_R(1.0));
}

/* Artist-friendly conductor Fresnel (Gulbrandsen 2014, "Artist Friendly
 * Metallic Fresnel", JCGT 3(4)): reflectivity r (the color at normal
 * incidence) and edge tint g, both in [0, 1] per channel, to the complex index
 * eta + i k whose exact Fresnel (mf_fresnel_conductor) has f0 = r (Eqs. 3-4):
 *   eta = g (1 - r) / (1 + r) + (1 - g) (1 + sqrt r) / (1 - sqrt r),
 *   k = sqrt((r (eta + 1)^2 - (eta - 1)^2) / (1 - r)).
 * r is clamped to [0, 0.9999], g to [0, 1]. And back: r from eta and k, g
 * from where eta lies between the two limits. */
MF_INLINE void mf_conductor_from_artist(mf_real r, mf_real g, mf_real *eta, mf_real *k)
{
    mf_real sr, n, k2;
    r = r == r ? mf_clamp(r, MF_R(0.0), MF_R(0.9999)) : MF_R(0.0);
    g = g == g ? mf_clamp(g, MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
    sr = MF_SQRT(r);
    n = g * (MF_R(1.0) - r) / (MF_R(1.0) + r) + (MF_R(1.0) - g) * (MF_R(1.0) + sr) / (MF_R(1.0) - sr);
    k2 = (r * (n + MF_R(1.0)) * (n + MF_R(1.0)) - (n - MF_R(1.0)) * (n - MF_R(1.0))) / (MF_R(1.0) - r);
    *eta = n;
    *k = MF_SQRT(mf_max(k2, MF_R(0.0)));
}
MF_INLINE void mf_artist_from_conductor(mf_real eta, mf_real k, mf_real *r, mf_real *g)
{
    mf_real sr, nmin, nmax, rr;
    if (!(eta > MF_R(0.0)) || !(k >= MF_R(0.0)) || !(eta < MF_BIG) || !(k < MF_BIG)) { *r = *g = MF_R(0.0); return; }
    rr = ((eta - MF_R(1.0)) * (eta - MF_R(1.0)) + k * k) / ((eta + MF_R(1.0)) * (eta + MF_R(1.0)) + k * k);
    rr = mf_clamp(rr, MF_R(0.0), MF_R(0.9999));
    sr = MF_SQRT(rr);
    nmin = (MF_R(1.0) - rr) / (MF_R(1.0) + rr);
    nmax = (MF_R(1.0) + sr) / (MF_R(1.0) - sr);
    *r = rr;
    *g = nmax > nmin ? mf_clamp((nmax - eta) / (nmax - nmin), MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
}
