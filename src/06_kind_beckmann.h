/* ======================================================================== */
/* == 6. Distribution kinds: Beckmann                                       */
/* ======================================================================== */
/* Anisotropic Beckmann: Gaussian slopes, D = exp(-tan^2/alpha_phi^2) / (pi ax ay cos^4)
 * (thesis Eq. C.1; Heitz 2014 Eq. 83); exact Lambda (Heitz 2014 Eq. 84) and
 * Walter et al. 2007's rational approximation (thesis C.2); NDF sampling by
 * the inverse slope CDF; visible normals by slope-space inversion (Heitz &
 * d'Eon 2014, Jakob 2014) with a safeguarded Halley solve (cold). */
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
MF_FORCE_INLINE mf_real mf_beckmann_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real z2, e;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    z2 = wm.z * wm.z;
    e = mf__q(ax, ay, wm) / z2;                   /* tan^2 / alpha_projected^2 */
    if (!(e < MF_R(80.0))) return MF_R(0.0);     /* exp underflow (and NaN) */
    return MF_EXP(-e) / (MF_PI * ax * ay * z2 * z2);
}

MF_FORCE_INLINE mf_real mf_beckmann_lambda(mf_real ax, mf_real ay, mf_vec3 w)
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
MF_FORCE_INLINE mf_vec3 mf_beckmann_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp, sx, sy, x, y;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (w.x == MF_R(0.0) && w.y == MF_R(0.0)) {
        /* exactly normal: the visible slopes are D's, a unit Gaussian of
         * variance 1/2 per axis; polar form, radius^2 = -log(1 - u1) */
        mf_real r2 = -MF_LOG(mf_max(MF_R(1.0) - mf_clamp(u1, MF_R(0.0), MF_R(1.0)), MF_TINY)), inv;
        mf__sincos_2pi(u2, &cp, &sp);
        x = ax * cp; y = ay * sp;
        inv = MF_R(1.0) / MF_SQRT(MF_R(1.0) + r2 * (x * x + y * y));   /* |(-x r, -y r, 1)| from r^2: off the sqrt(r2) path */
        sx = MF_SQRT(r2) * inv;
        return mf_vec3_make(-x * sx, -y * sx, inv);
    }
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    mf__beckmann_visible_slopes(sv / mf_max(cv, MF_R(1e-30)), u1, u2, &sx, &sy);
    x = cp * sx - sp * sy;   /* rotate back to the view azimuth, then unstretch */
    y = sp * sx + cp * sy;
    return mf_normalize(mf_vec3_make(-ax * x, -ay * y, MF_R(1.0)));
}

/* The kind's entries of the generic dispatch (05_ndf.h; INL 1: the front
 * ends inline D, Lambda and the NDF sampling). */
MF_FORCE_INLINE mf_real mf__beckmann_D(const mf_ndf *d, mf_vec3 wm) { return mf_beckmann_D(d->ax, d->ay, wm); }
MF_FORCE_INLINE mf_real mf__beckmann_lambda(const mf_ndf *d, mf_vec3 w) { return mf_beckmann_lambda(d->ax, d->ay, w); }
/* u1, u2 in [0, 1] (mf_sample_D clamps them) */
MF_FORCE_INLINE mf_vec3 mf__beckmann_sample_D_dir(const mf_ndf *d, mf_real u1, mf_real u2)
{
    return mf__slope_dir_u(d->ax, d->ay, -MF_LOG1P(-u1), u2);
}
MF_FORCE_INLINE mf_vec3 mf__beckmann_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    return mf_normalize(mf__beckmann_sample_D_dir(d, u1, u2));
}
MF_FORCE_INLINE mf_vec3 mf__beckmann_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf_beckmann_sample_visible(d->ax, d->ay, w, u1, u2);
}
/* @cold */
/* Beckmann visible slopes for unit roughness and view tan(theta) = tv (view
 * along +x): the slope x along the view has density ~ max(0, 1 - tv x) exp(-x^2),
 * G(x) = erfc(-x)/2 + tv exp(-x^2)/(2 sqrt(pi)) (Heitz & d'Eon 2014 Eq. 9 up to
 * the factor 1 + tv) is solved for G(x) = u1 G(1/tv) by safeguarded Halley
 * steps sharing one erfc and one exp; y ~ N(0, 1/2). The start blends the
 * quantiles of the two limits, erfinv(2u - 1) at tv = 0 and -sqrt(-log u) as
 * tv -> infinity (where G ~ exp(-x^2)); past the top 1/tv it uses the
 * quadratic tail G(1/tv) - G(x) ~ tv exp(-1/tv^2) (1/tv - x)^2 / (2 sqrt(pi)). */
/* Halley converges cubically: after a step s the error is O(s^3) (times
 * 1 / (1/tv - x)^2 near the top, hence the tolerance relative to that gap), so
 * a step below eps^(1/3) / 5 is the last one. */
#ifndef MF__HALLEY_TOL
#ifdef MF_USE_DOUBLE
#define MF__HALLEY_TOL MF_R(1e-6)
#else
#define MF__HALLEY_TOL MF_R(1e-3)
#endif
#endif
MF_COLD void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy)
{
    const mf_real k = MF_R(0.28209479177387814);   /* 1 / (2 sqrt(pi)) */
    mf_real u = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), w = tv / (MF_R(0.5) + tv);
    mf_real mu = tv > MF_R(1.0) / MF_R(12.0) ? MF_R(1.0) / tv : MF_R(12.0), total = MF_R(1.0), top = MF_R(0.0);
    /* lo: x^2 + y^2 stays below mf_beckmann_D's cut of 80 for every u2 (|y| <=
     * 5.9), so u1 = 0 gives a normal of positive density; the mass cut is 1e-20 */
    mf_real lo = MF_R(-6.5), hi = mu, x, target;
    int i;
    *sy = mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
    if (!(tv > MF_EPS) && MF_FABS(u - MF_R(0.5)) < MF_R(0.4999)) {   /* x(tv) = x(0) + O(tv) */
        *sx = mf_erfinv(MF_R(2.0) * u - MF_R(1.0));
        return;
    }
    x = mf__erfinv_giles(mf_clamp(MF_R(2.0) * u - MF_R(1.0), MF_R(-1.0) + MF_EPS, MF_R(1.0) - MF_EPS));
    x = (MF_R(1.0) - w) * x - w * MF_SQRT(-MF_LOG(mf_max(u, MF_R(1e-30))));
    if (tv > MF_R(1.0) / MF_R(6.0)) {   /* else G(mu) = 1 to double precision */
        top = tv * k * MF_EXP(-mu * mu);
        total = MF_R(0.5) * MF_ERFC(-mu) + top;
        if (x >= mu) x = mu - MF_SQRT((MF_R(1.0) - u) * total / mf_max(top, MF_R(1e-30)));
    }
    target = u * total;
    x = mf_clamp(x, lo, hi);
    for (i = 0; i < 60; ++i) {
        mf_real e = MF_EXP(-x * x), s = MF_R(1.0) - tv * x;
        mf_real f = MF_R(0.5) * MF_ERFC(-x) + tv * k * e - target;
        mf_real df = MF_R(2.0) * k * e * s, r = df > MF_R(0.0) ? f / df : MF_R(0.0);
        /* Halley: f / (f' - f f'' / (2 f')), with f''/f' = -2x - tv / (1 - tv x);
         * a non-positive effective slope falls back to bisection */
        df *= MF_R(1.0) + MF_R(0.5) * r * (MF_R(2.0) * x + tv / mf_max(s, MF_R(1e-30)));
        if (mf__newton_step(&x, f, df, &lo, &hi, MF__HALLEY_TOL * mf_min(MF_R(1.0) + MF_FABS(x), mu - x))) break;
    }
    MF__SOLVER_DONE(MF__SITE_BECKMANN, i, 60);
    *sx = x;
}
