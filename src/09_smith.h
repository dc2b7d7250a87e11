/* @api */
/* ======================================================================== */
/* == 9. Smith masking                                                      */
/* ======================================================================== */
/* Smith: G1(w, m) = chi+(w.m) / (1 + Lambda(w)) (thesis Eq. 3.8 with the
 * average visibility S = 1 / (1 + Lambda)), which satisfies the masking
 * constraint integral G1(w,m) <w.m> D(m) dm = w.z (thesis Eq. 3.9).
 * Shape-invariant kinds (Beckmann, GGX, Student-t) depend only on
 * a = 1 / (alpha_w tan(theta)), alpha_w^2 = ax^2 cos^2(phi) + ay^2 sin^2(phi),
 * the projected roughness (Heitz 2014 Sec. 5.2) - never an averaged alpha.
 *   Beckmann: Lambda = (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi))  (Heitz 2014 Eq. 84)
 *             and Walter et al. 2007's rational approximation (thesis C.2), named apart.
 *   GGX:      Lambda = (sqrt(1 + 1/a^2) - 1)/2  (thesis C.4)
 *   GTR:      Dimov's exact formulas at gamma = 0..4 (thesis C.7-C.11) rewritten in
 *             tan(theta) without cancellation; between them an exact mixture of
 *             the GGX (gamma < 2) or gamma-4 (gamma > 2) Lambdas integrated by
 *             a Gauss-Jacobi rule built at construction (see mf__gtr_lambda):
 *             measured within 2e-6 relative of the true Lambda in double.
 *   Student-t: exact, from the marginal slope density P2(x) = K (1 + x^2/(g-1))^(1/2-g):
 *             Lambda = K (g-1)/((2g-3) mu) (1 + mu^2/(g-1))^(3/2-g) - Q(mu),
 *             Q the upper tail of P2 = I_w(g-1, 1/2)/2, w = (g-1)/(g-1+mu^2)
 *             (the closed form behind Ribardiere et al. 2017 Eq. 13-15; clamped at 0). */

/* Smith Lambda(w). Symmetric in w.z; large but finite at w.z = 0. The inline
 * kinds (GGX, Beckmann) inline, the others out of line; transformed kinds at
 * M^-1 w (Eq. 4.4). */
MF_FORCE_INLINE mf_real mf_lambda(const mf_ndf *d, mf_vec3 w)
{
    /* Lambda depends on w only through tan(theta) and phi: no normalization */
    if (d->transformed) w = mf_mat2_apply(mf__ndf_Minv(d), w);
    return mf__ndf_lambda_inline(d, w);
}

/* Monodirectional masking G1(w, wm) = chi+(w.wm) chi+(w.z) / (1 + Lambda(w)). */
MF_FORCE_INLINE mf_real mf_G1(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
{
    if (!(w.z > MF_R(0.0)) || !(mf_dot(w, wm) > MF_R(0.0))) return MF_R(0.0);
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, w));
}

/* Height-correlated masking-shadowing (Heitz 2014 Eq. 99):
 * G2 = chi+(wo.wm) chi+(wi.wm) / (1 + Lambda(wo) + Lambda(wi)). Reflection only:
 * 0 unless wo.z > 0 and wi.z > 0. */
/* GGX, wo.z, wi.z > 0: 1 + Lambda(w) = |s w| / (2 w.z) with s w = (ax w.x,
 * ay w.y, w.z) (thesis C.4), so G2 = 2 zo zi / (zi |s wo| + zo |s wi|): one
 * division instead of five. */
MF_FORCE_INLINE mf_real mf__ggx_G2(mf_real ax, mf_real ay, mf_vec3 wo, mf_vec3 wi)
{
    mf_real xo = ax * wo.x, yo = ay * wo.y, xi = ax * wi.x, yi = ay * wi.y;
    mf_real so = MF_SQRT(xo * xo + yo * yo + wo.z * wo.z), si = MF_SQRT(xi * xi + yi * yi + wi.z * wi.z);
    mf_real den = wi.z * so + wo.z * si;
    return den > MF_R(0.0) ? MF_R(2.0) * wo.z * wi.z / den : MF_R(0.0);
}
/* 1 / (1 + Lambda(wo) + Lambda(wi)) for wo.z, wi.z > 0 (no facet checks) */
MF_FORCE_INLINE mf_real mf__G2_up(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    /* the Trowbridge-Reitz kinds (trait TR: GGX) as the straight path: with
     * another hardware thread busy on the core, mf_G2 costs 1.24-1.38 instead
     * of 1.36-1.70 times a plain G2 loop without facing tests (bench
     * ggx_G2_generic) */
    if (MF__LIKELY(mf__ndf_tr(d->type))) {
        /* M^-1 fixes z: the transformed directions stay above the horizon */
        if (d->transformed) { mf_mat2 Mi = mf__ndf_Minv(d); wo = mf_mat2_apply(Mi, wo); wi = mf_mat2_apply(Mi, wi); }
        return mf__ggx_G2(d->ax, d->ay, wo, wi);
    }
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, wo) + mf_lambda(d, wi));
}
MF_FORCE_INLINE mf_real mf_G2(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_vec3 wm)
{
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    if (!(mf_dot(wo, wm) > MF_R(0.0)) || !(mf_dot(wi, wm) > MF_R(0.0))) return MF_R(0.0);
    return mf__G2_up(d, wo, wi);
}

/* Separable form G1(wo, wm) G1(wi, wm) (Heitz 2014 Eq. 98). */
MF_FORCE_INLINE mf_real mf_G2_separable(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_vec3 wm)
{
    return mf_G1(d, wo, wm) * mf_G1(d, wi, wm);
}

/* w . (-E_x, -E_y, 1): the projected area of the mean surface (unnormalized
 * mesonormal) toward w; w.z for every centred kind (trait CEN). The mean slope
 * of a transformed distribution is M^-T times the base's (Eq. 4.16). */
MF_FORCE_INLINE mf_real mf__mean_surface_proj(const mf_ndf *d, mf_vec3 w)
{
    mf_real mx, my;
    if (!mf__ndf_tilted(d->type)) return w.z;
    mf__ndf_mean_slope(d, &mx, &my);
    if (d->transformed) {
        mf_mat2 Mi = mf__ndf_Minv(d);
        mf_real tx = Mi.m00 * mx + Mi.m10 * my, ty = Mi.m01 * mx + Mi.m11 * my;
        mx = tx; my = ty;
    }
    return w.z - mx * w.x - my * w.y;
}

/* Projected area of the visible microsurface, w.z (1 + Lambda(w)) =
 * integral <w.m> D(m) dm (thesis Eq. 3.9); finite and positive at w.z = 0.
 * For LEADR moments the mean surface is tilted: (w . (-E_x, -E_y, 1)) (1 +
 * Lambda(w)) (LEADR supplement Eq. 9; trait CEN 0). */
/* the same for a known lo = Lambda(w) (the samplers share it) */
MF_FORCE_INLINE mf_real mf__projected_area_l(const mf_ndf *d, mf_vec3 w, mf_real lo)
{
    mf_real cz;
    if (mf__ndf_tilted(d->type)) return mf__cap(mf_max(mf__mean_surface_proj(d, w), MF_R(1e-15)) * (MF_R(1.0) + lo));
    cz = mf_max(MF_FABS(w.z), MF_R(1e-15));
    return mf__cap(cz + cz * lo);
}
MF_FORCE_INLINE mf_real mf_projected_area(const mf_ndf *d, mf_vec3 w)
{
    return mf__projected_area_l(d, w, mf_lambda(d, w));
}

/* Distribution of visible normals (Heitz & d'Eon 2014 Eq. 2):
 * D_w(wm) = G1(w, wm) max(0, w.wm) D(wm) / w.z; integrates to 1 over wm. 0 if w.z < 0. */
MF_FORCE_INLINE mf_real mf_D_visible(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
{
    mf_real c = mf_dot(w, wm);
    if (w.z < MF_R(0.0) || !(c > MF_R(0.0))) return MF_R(0.0);
    return mf__cap(c * mf_D(d, wm) / mf_projected_area(d, w));
}
