/* ======================================================================== */
/* == 6. Distribution kinds: Beckmann                                       */
/* ======================================================================== */
/* Anisotropic Beckmann: Gaussian slopes, D = exp(-tan^2/alpha_phi^2) / (pi ax ay cos^4)
 * (thesis Eq. C.1; Heitz 2014 Eq. 83); exact Lambda (Heitz 2014 Eq. 84) and
 * Walter et al. 2007's rational approximation (thesis C.2); NDF sampling by
 * the inverse slope CDF; visible normals by slope-space inversion (Heitz &
 * d'Eon 2014, Jakob 2014) with a safeguarded Newton solve (cold). */
/* @decl */
typedef struct mf_ndf_beckmann { char none; } mf_ndf_beckmann;   /* no parameters beyond mf_ndf.ax, ay */
/* @api */
/* Anisotropic Beckmann. alpha = sqrt(2) sigma of the Gaussian slopes. */
MF_INLINE mf_ndf mf_beckmann(mf_real alpha_x, mf_real alpha_y)
{
    return mf__ndf_init(MF_NDF_BECKMANN, alpha_x, alpha_y);
}

/* Per-distribution fast paths for D, Lambda and sampling (the same clamps as
 * the generic functions). */
MF_INLINE mf_real mf_beckmann_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real z2, e;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    z2 = wm.z * wm.z;
    e = mf__q(ax, ay, wm) / z2;                   /* tan^2 / alpha_projected^2 */
    if (!(e < MF_R(80.0))) return MF_R(0.0);     /* exp underflow (and NaN) */
    return MF_EXP(-e) / (MF_PI * ax * ay * z2 * z2);
}

MF_INLINE mf_real mf_beckmann_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w), a;
    if (!(a2t2 > MF_R(1e-3))) return MF_R(0.0);   /* a > 31.6: Lambda < 1e-400 */
    a = MF_R(1.0) / MF_SQRT(a2t2);
    return mf_max(MF_R(0.5) * (MF_EXP(-a * a) / (a * MF_SQRT_PI) - MF_ERFC(a)), MF_R(0.0));
}

/* Walter et al. 2007 rational approximation of the Beckmann Lambda (thesis
 * Eq. C.2); relative error of G1 below about 0.35%. */
MF_INLINE mf_real mf_beckmann_lambda_approx(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w), a;
    if (!(a2t2 > MF_R(1.0) / (MF_R(1.6) * MF_R(1.6)))) return MF_R(0.0);
    a = MF_R(1.0) / MF_SQRT(a2t2);
    return (MF_R(1.0) - MF_R(1.259) * a + MF_R(0.396) * a * a) / (MF_R(3.535) * a + MF_R(2.181) * a * a);
}

MF_COLD void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy);
MF_INLINE mf_vec3 mf_beckmann_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp, sx, sy, x, y;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    mf__beckmann_visible_slopes(sv / mf_max(cv, MF_R(1e-30)), u1, u2, &sx, &sy);
    x = cp * sx - sp * sy;   /* rotate back to the view azimuth, then unstretch */
    y = sp * sx + cp * sy;
    return mf_normalize(mf_vec3_make(-ax * x, -ay * y, MF_R(1.0)));
}

/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_INLINE mf_real mf__beckmann_D(const mf_ndf *d, mf_vec3 wm) { return mf_beckmann_D(d->ax, d->ay, wm); }
MF_INLINE mf_real mf__beckmann_lambda(const mf_ndf *d, mf_vec3 w) { return mf_beckmann_lambda(d->ax, d->ay, w); }
MF_INLINE mf_vec3 mf__beckmann_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(d->ax, d->ay, -MF_LOG1P(-t), u2);
}
MF_INLINE mf_vec3 mf__beckmann_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf_beckmann_sample_visible(d->ax, d->ay, w, u1, u2);
}
/* @cold */
/* Beckmann visible slopes for unit roughness and view tan(theta) = tv (view
 * along +x): the slope x along the view has density ~ max(0, 1 - tv x) exp(-x^2),
 * CDF F(x) = [erfc(-x)/2 + tv exp(-x^2)/(2 sqrt(pi))] / (1 + tv); y ~ N(0, 1/2). */
MF_COLD void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy)
{
    mf_real mu = tv > MF_R(1.0) / MF_R(12.0) ? MF_R(1.0) / tv : MF_R(12.0);
    mf_real inv = MF_R(1.0) / (MF_R(1.0) + tv), k = MF_R(0.5) / MF_SQRT_PI;
    mf_real target = mf_clamp(u1, MF_R(0.0), MF_R(1.0)) *
                     (MF_R(0.5) * MF_ERFC(-mu) + tv * k * MF_EXP(-mu * mu)) * inv;
    mf_real lo = MF_R(-12.0), hi = mu, x;
    int i;
    x = mf_clamp(mf_erfinv(MF_R(2.0) * u1 - MF_R(1.0)), lo, hi);   /* exact at tv = 0 */
    for (i = 0; i < 60; ++i) {
        mf_real e = MF_EXP(-x * x);
        mf_real f = (MF_R(0.5) * MF_ERFC(-x) + tv * k * e) * inv - target;
        mf_real df = e * (MF_R(1.0) - tv * x) * inv / MF_SQRT_PI;
        if (mf__newton_step(&x, f, df, &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + MF_FABS(x)))) break;
    }
    *sx = x;
    *sy = mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
}
