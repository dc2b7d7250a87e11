/* @api */
/* ======================================================================== */
/* == 3. Fresnel                                                            */
/* ======================================================================== */
/* Unpolarized reflectance of a smooth interface. cos_theta_i is the cosine
 * between the incident direction and the normal on the incident side. */

/* Dielectric; eta = n_transmitted / n_incident, clamped to [1e-6, 1e6] (<= 0
 * or NaN gives 0). A negative cos_theta_i means the light arrives from the
 * other side: eta is inverted. 1 on total internal reflection. */
MF_INLINE mf_real mf_fresnel_dielectric(mf_real cos_theta_i, mf_real eta)
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
 * outside medium); exact unpolarized form. eta <= 0, k < 0 or NaN give 0;
 * eta and k are capped at 1e6. */
MF_INLINE mf_real mf_fresnel_conductor(mf_real cos_theta_i, mf_real eta, mf_real k)
{
    mf_real c = mf_clamp(MF_FABS(cos_theta_i), MF_R(0.0), MF_R(1.0));
    if (!(eta > MF_R(0.0)) || !(k >= MF_R(0.0)) || !(c == c)) return MF_R(0.0);
    eta = mf_min(eta, MF_R(1e6));
    k = mf_min(k, MF_R(1e6));
    mf_real c2 = c * c, s2 = MF_R(1.0) - c2;
    mf_real e2 = eta * eta, k2 = k * k;
    mf_real t0 = e2 - k2 - s2;
    mf_real a2b2 = MF_SQRT(mf_max(t0 * t0 + MF_R(4.0) * e2 * k2, MF_R(0.0)));
    mf_real a = MF_SQRT(mf_max(MF_R(0.5) * (a2b2 + t0), MF_R(0.0)));
    mf_real t1 = a2b2 + c2, t2 = MF_R(2.0) * a * c;
    mf_real rs = (t1 - t2) / mf_max(t1 + t2, MF_R(1e-30));
    mf_real t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    mf_real rp = rs * (t3 - t4) / mf_max(t3 + t4, MF_R(1e-30));
    return mf_clamp(MF_R(0.5) * (rp + rs), MF_R(0.0), MF_R(1.0));
}

/* Schlick's approximation f0 + (1 - f0)(1 - cos)^5. */
MF_INLINE mf_real mf_fresnel_schlick(mf_real f0, mf_real cos_theta)
{
    mf_real m = MF_R(1.0) - mf_clamp(cos_theta, MF_R(0.0), MF_R(1.0));
    if (!(m == m)) m = MF_R(0.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    mf_real m2 = m * m;
    return f0 + (MF_R(1.0) - f0) * m2 * m2 * m;
}
