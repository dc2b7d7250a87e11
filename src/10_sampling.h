/* @api */
/* ======================================================================== */
/* == 10. Sampling                                                          */
/* ======================================================================== */
/* mf_sample_D draws wm with density D(wm) wm.z (Walter et al. 2007): the
 * radius of the slope from the inverse CDF, the azimuth uniform, stretched by
 * (ax, ay). mf_sample_visible draws wm with density mf_D_visible(w, wm):
 *   GGX       spherical caps (Dupuy & Benyoub 2023): sample the visible
 *             hemisphere of the stretched configuration as a spherical cap.
 *   Beckmann  slope-space inversion (Heitz & d'Eon 2014, Jakob 2014): the
 *             slope along the view from its CDF (safeguarded Newton on erf),
 *             the other slope from erfinv. The CDF is scaled by tan(theta), so
 *             normal incidence (cot = infinity) and tiny alpha are exact.
 *   GTR, Student-t  exact rejection from GGX's VNDF or from an exact
 *             mixture of GGX lobes (mf__gtr_sample_visible,
 *             mf__student_t_sample_visible), the exact numerical inversion
 *             (05_numeric_vndf.h) as the fallback; their NDF sampling is the
 *             closed-form inverse CDF. */

/* Random numbers: every sampler takes u in [0, 1] inclusive. 1 is read as
 * MF_U_MAX, the largest mf_real below 1 (a double u in [1 - 2^-25, 1) rounds
 * to 1.0f, and the inverse CDFs reach infinite slopes at 1); outside [0, 1]
 * is clamped, NaN becomes 0. */
MF_FORCE_INLINE mf_real mf__u01(mf_real u) { return mf_clamp(u, MF_R(0.0), MF_U_MAX); }

/* wm with density D(wm) wm.z. u1 picks the polar angle, u2 the azimuth.
 * Transformed kinds: M^-T applied to a sample of the base (Eq. 4.17-4.18). */
MF_FORCE_INLINE mf_vec3 mf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_vec3 m;
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    if (!d->transformed) return mf__ndf_sample_D_inline(d, u1, u2);
    /* M^-T is linear and keeps z: GGX and Beckmann samples are normalized
     * once, after it */
    m = mf__ndf_sample_D_dir_inline(d, u1, u2);
    return mf_normalize(mf_mat2_apply_transpose(mf__ndf_Minv(d), m));
}

/* wm with density mf_D_visible(d, w, wm); the zero vector if w.z < 0. GGX
 * inline, the other kinds out of line. Transformed kinds: the base's visible
 * normals for M^-1 w, moved by M^-T (Eq. 4.20-4.21). u2 near 1 reaches the
 * view's visibility horizon, where w.wm is 0 up to rounding: the lobe
 * samplers (mf_brdf_sample ...) reject such normals, so their records never
 * carry a zero pdf. */
MF_FORCE_INLINE mf_vec3 mf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 m;
    mf_mat2 Mi;
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    if (!d->transformed) return mf__ndf_sample_visible_inline(d, w, u1, u2);
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    Mi = mf__ndf_Minv(d);
    w = mf_mat2_apply(Mi, w);   /* the samplers normalize their view themselves */
    m = mf__ndf_sample_visible_dir_inline(d, w, u1, u2);
    return mf_normalize(mf_mat2_apply_transpose(Mi, m));
}

/* Visible normals as a smooth function of (u1, u2), for quadrature over the
 * unit square (albedo tables, LTC fits): the rejection samplers of GTR and
 * Student-t jump with (u1, u2), so those kinds take the exact numerical
 * inversion (05_numeric_vndf.h, microseconds) here; every other kind is
 * mf_sample_visible. */
MF_INLINE mf_vec3 mf__sample_visible_smooth(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 m;
    if (!mf__ndf_iso(d->type)) return mf_sample_visible(d, w, u1, u2);
    if (!(w.z >= MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (d->transformed) w = mf_mat2_apply(mf__ndf_Minv(d), w);
    m = mf__iso_sample_visible_kind(d, w, mf__u01(u1), mf__u01(u2));
    return d->transformed ? mf_normalize(mf_mat2_apply_transpose(mf__ndf_Minv(d), m)) : m;
}
