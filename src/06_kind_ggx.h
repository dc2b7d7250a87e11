/* ======================================================================== */
/* == 6. Distribution kinds: GGX                                            */
/* ======================================================================== */
/* Anisotropic GGX (Trowbridge-Reitz): D = 1 / (pi ax ay cos^4 (1 + tan^2/alpha_phi^2)^2)
 * (thesis Eq. C.3, corrected; Heitz 2014 Eq. 85); Lambda (thesis C.4); NDF
 * sampling by inverting the slope CDF (Walter et al. 2007); visible normals by
 * spherical caps (Dupuy & Benyoub 2023). Every function is inline: GGX is the
 * hot path of most renderers. */
/* @decl */
typedef struct mf_ndf_ggx { char none; } mf_ndf_ggx;   /* no parameters beyond mf_ndf.ax, ay */
/* @api */
/* Anisotropic GGX (Trowbridge-Reitz). */
MF_INLINE mf_ndf mf_ggx(mf_real alpha_x, mf_real alpha_y)
{
    return mf__ndf_init(MF_NDF_GGX, alpha_x, alpha_y);
}

MF_FORCE_INLINE mf_real mf_ggx_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real t;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    t = wm.z * wm.z + mf__q(ax, ay, wm);          /* cos^2 (1 + tan^2/alpha^2), no cos^4 underflow */
    return MF_R(1.0) / (MF_PI * ax * ay * t * t);
}

MF_FORCE_INLINE mf_real mf_ggx_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w);
    return a2t2 / (MF_R(2.0) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + a2t2)));
}

/* GGX VNDF by spherical caps (Dupuy & Benyoub 2023, Listing 3), before the
 * final normalization; w need not be unit. (0,0,1) for degenerate input. k
 * scales the cap's lower bound -k v.z: 1 is the whole visible hemisphere, k < 1
 * the bounded cap of Eto & Tokuyoshi 2023 (mf_brdf_sample_bounded). */
MF_FORCE_INLINE mf_vec3 mf__ggx_vndf_unnormalized(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2, mf_real k)
{
    mf_vec3 v, h;
    mf_real cp, sp, z, s, l2, b;
    v = mf_vec3_make(ax * w.x, ay * w.y, w.z);
    l2 = mf_dot(v, v);
    if (!(l2 > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    v = mf_scale(v, MF_R(1.0) / MF_SQRT(l2));
    mf__sincos_2pi(u1, &cp, &sp);                            /* azimuth 2 pi u1 (u1 clamped to [0, 1]) */
    b = k * v.z;
    z = (MF_R(1.0) - u2) * (MF_R(1.0) + b) - b;              /* cap of the visible hemisphere */
    s = MF_SQRT(mf_clamp(MF_R(1.0) - z * z, MF_R(0.0), MF_R(1.0)));
    h = mf_vec3_make(s * cp + v.x, s * sp + v.y, z + v.z);
    /* h.v = c.v + 1 >= 0 exactly; near the cap point c = -v (u2 -> 1, the
     * azimuth opposite v) h vanishes and what rounding leaves may face away
     * from v: a normal of zero density there, so take (0, 0, 1) instead */
    if (!(mf_dot(h, v) > MF_R(0.0)) || !(mf_dot(h, h) > MF_R(16.0) * MF_EPS * MF_EPS))
        return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    h = mf_vec3_make(ax * h.x, ay * h.y, mf_max(h.z, MF_R(0.0)));
    if (!(mf_dot(h, h) > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    return h;
}
MF_FORCE_INLINE mf_vec3 mf_ggx_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(ax, ay, w, u1, u2, MF_R(1.0));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}

/* GGX visible normals for the roughness (ax, ay) / k, k > 0: the VNDF is
 * unchanged when (alpha, w.z) are scaled together, so the huge roughness of a
 * heavy-tailed kind's mixture component never overflows. */
MF_INLINE mf_vec3 mf__ggx_sample_visible_k(mf_real ax, mf_real ay, mf_real k, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 h = mf__ggx_vndf_unnormalized(ax, ay, mf_vec3_make(w.x, w.y, k * w.z), u1, u2, MF_R(1.0));
    h.z *= k;
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}

/* The kind's entries of the generic dispatch (05_ndf.h; INL 2: the front
 * ends inline them). */
MF_FORCE_INLINE mf_real mf__ggx_D(const mf_ndf *d, mf_vec3 wm) { return mf_ggx_D(d->ax, d->ay, wm); }
MF_FORCE_INLINE mf_real mf__ggx_lambda(const mf_ndf *d, mf_vec3 w) { return mf_ggx_lambda(d->ax, d->ay, w); }
/* the NDF sample not normalized (mf_sample_D normalizes a transformed one
 * once, after M^-T), and normalized; u1, u2 in [0, 1] (mf_sample_D clamps
 * them) */
MF_FORCE_INLINE mf_vec3 mf__ggx_sample_D_dir(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real q = MF_R(1.0) - u1;
    return mf__slope_dir_u(d->ax, d->ay, q > MF_R(0.0) ? u1 / q : MF_BIG, u2);
}
MF_FORCE_INLINE mf_vec3 mf__ggx_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    return mf_normalize(mf__ggx_sample_D_dir(d, u1, u2));
}
MF_FORCE_INLINE mf_vec3 mf__ggx_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf_ggx_sample_visible(d->ax, d->ay, w, u1, u2);
}
/* the visible normal before its normalization (a transformed GGX normalizes
 * once, after M^-T); w.z >= 0 */
MF_FORCE_INLINE mf_vec3 mf__ggx_sample_visible_dir(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__ggx_vndf_unnormalized(d->ax, d->ay, w, u1, u2, MF_R(1.0));
}
