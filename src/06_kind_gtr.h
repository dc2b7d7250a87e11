/* ======================================================================== */
/* == 6. Distribution kinds: GTR                                            */
/* ======================================================================== */
/* Burley's Generalized Trowbridge-Reitz (Burley 2012; thesis Eq. C.5, Berry
 * limit C.6), isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma. Lambda from
 * Dimov's exact formulas at gamma = 0..4 (thesis C.7-C.11) with a spline in
 * gamma between them; NDF sampling by the closed-form inverse CDF; visible
 * normals by the exact numerical inversion of 07_numeric_vndf.h. Everything
 * but the constructor is cold. */
/* @decl */
typedef struct mf_ndf_gtr {
    mf_real gamma;      /* tail exponent in [0, 4] */
    mf_real norm;       /* N of D = N / (sin^2 + a^2 cos^2)^gamma */
    mf_real L;          /* log(alpha^2) */
    mf_real E, EM;      /* expm1((1 - gamma) L), expm1(-(1 - gamma) L) */
    mf_real RK, RMK;    /* kL / expm1(kL) and -kL / expm1(-kL), k = 1 - gamma */
    mf_real w[5];       /* natural-spline weights of the masking nodes gamma = 0..4 */
} mf_ndf_gtr;
/* @api */
/* Weights w_j(g) of the natural cubic spline through nodes j = 0..4 (unit
 * spacing) evaluated at g: the spline of data y is sum_j w_j y_j. The second
 * derivatives solve [4 1 0; 1 4 1; 0 1 4] M = 6 (second differences), whose
 * inverse is [15 -4 1; -4 16 -4; 1 -4 15] / 56. */
MF_INLINE void mf__spline5_weights(mf_real g, mf_real w[5])
{
    const mf_real inv[3][3] = {
        { MF_R(15.0) / MF_R(56.0), MF_R(-4.0) / MF_R(56.0), MF_R(1.0) / MF_R(56.0) },
        { MF_R(-4.0) / MF_R(56.0), MF_R(16.0) / MF_R(56.0), MF_R(-4.0) / MF_R(56.0) },
        { MF_R(1.0) / MF_R(56.0), MF_R(-4.0) / MF_R(56.0), MF_R(15.0) / MF_R(56.0) } };
    int i = (int)g, j, r, k;
    mf_real t, a, b;
    if (i > 3) i = 3;
    if (i < 0) i = 0;
    t = g - (mf_real)i;
    a = MF_R(1.0) - t;
    for (j = 0; j < 5; ++j) {
        mf_real y[5] = { 0, 0, 0, 0, 0 }, m[5] = { 0, 0, 0, 0, 0 };
        y[j] = MF_R(1.0);
        for (r = 0; r < 3; ++r)
            for (k = 0; k < 3; ++k)
                m[r + 1] += inv[r][k] * MF_R(6.0) * (y[k + 2] - MF_R(2.0) * y[k + 1] + y[k]);
        b = a * y[i] + t * y[i + 1] + ((a * a * a - a) * m[i] + (t * t * t - t) * m[i + 1]) / MF_R(6.0);
        w[j] = b;
    }
}

/* Burley's GTR, isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma.
 * alpha in [MF_ALPHA_MIN, 1], gamma in [0, 4] (clamped; see CLAMPS above).
 * gamma = 2 is GGX, gamma = 1 the Berry distribution (limit C.6), gamma = 0
 * the uniform 1/pi; alpha = 1 gives 1/pi for every gamma. N is written with
 * x/expm1(x) so the limits gamma -> 1 and alpha -> 1 are exact. */
MF_INLINE mf_ndf mf_gtr(mf_real alpha, mf_real gamma)
{
    mf_ndf d;
    mf_ndf_gtr *p;
    mf_real a, L, k;
    a = mf__clamp_alpha(alpha);
    if (a > MF_R(1.0)) a = MF_R(1.0);
    /* the bits: under -ffast-math the comparisons let NaN through, and the
     * spline below indexes by gamma */
    if (!mf__finite_bits(gamma)) gamma = MF_R(0.0);
    gamma = gamma > MF_R(0.0) ? (gamma < MF_R(4.0) ? gamma : MF_R(4.0)) : MF_R(0.0);
    d = mf__ndf_init(MF_NDF_GTR, a, a);
    p = &d.p.gtr;
    L = MF_R(2.0) * MF_LOG(a);
    k = MF_R(1.0) - gamma;
    p->gamma = gamma;
    /* N = (gamma-1)(a^2-1) / (pi (1 - a^(2(1-gamma))))  (C.5) = r(kL) / (pi r(L)) */
    p->norm = mf__x_over_expm1(k * L) / (MF_PI * mf__x_over_expm1(L));
    p->L = L;
    p->E = MF_EXPM1(k * L);
    p->EM = MF_EXPM1(-k * L);
    p->RK = mf__x_over_expm1(k * L);
    p->RMK = mf__x_over_expm1(-k * L);
    mf__spline5_weights(gamma, p->w);
    return d;
}

/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion the numerical visible-normal sampler uses (07_numeric_vndf.h). */
MF_COLD mf_real mf__gtr_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__gtr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__gtr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__gtr_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__gtr_tail(const mf_ndf *d, mf_real tan2);
/* @cold */
/* D, homogeneous of degree -4: N / ((sin^2 + a^2 cos^2)^gamma |wm|^4) */
MF_COLD mf_real mf__gtr_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real s2, l2, den;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    s2 = wm.x * wm.x + wm.y * wm.y;
    l2 = s2 + wm.z * wm.z;
    den = (s2 + d->ax * d->ax * wm.z * wm.z) / l2;  /* 1 + (a^2 - 1) cos^2 */
    return d->p.gtr.norm / (MF_POW(den, d->p.gtr.gamma) * l2 * l2);
}

/* GTR Lambda at the integer tails, in t2 = tan^2(theta) and a2 = alpha^2.
 * Derived from thesis Eq. C.7-C.11 with mu = 1/t; differences such as
 * sqrt(1 + a2 t2) - 1 are written as quotients so nothing cancels. */
MF_INLINE void mf__gtr_lambda_nodes(mf_real a2, mf_real L, mf_real t2, mf_real lam[5])
{
    mf_real qa = MF_SQRT(MF_R(1.0) + a2 * t2), qb = MF_SQRT(MF_R(1.0) + t2);
    mf_real ea = a2 * t2 / (qa + MF_R(1.0));           /* qa - 1 */
    mf_real a4 = a2 * a2, A4, d, y;
    lam[0] = t2 / (MF_R(2.0) * (MF_R(1.0) + qb));       /* C.7: GGX with alpha = 1 */
    lam[2] = MF_R(0.5) * ea;                            /* C.9: GGX */
    /* C.8: Lambda1 = [(qa - qb) - log1p((qa - qb)/(1 + qb))] / L */
    d = t2 / (qa + qb);                                 /* (qa - qb) / (a2 - 1) */
    y = (a2 - MF_R(1.0)) * d / (MF_R(1.0) + qb);
    lam[1] = d * (MF_R(1.0) - mf__log1p_over_x(y) / (MF_R(1.0) + qb)) / mf__x_over_expm1(L);
    /* C.10 */
    lam[3] = a2 * t2 * ((MF_R(3.0) * a2 + MF_R(1.0)) * ea + MF_R(4.0) * a2) /
             (MF_R(4.0) * (a2 + MF_R(1.0)) * qa * (qa + MF_R(1.0)));
    /* C.11 */
    A4 = MF_R(8.0) * (a4 + a2 + MF_R(1.0));
    lam[4] = a2 * t2 * (MF_R(12.0) * a4 - A4 * ea * (qa + MF_R(0.5)) / (qa + MF_R(1.0)) +
                        MF_R(3.0) * a2 * t2 * (MF_R(5.0) * a4 + MF_R(2.0) * a2 + MF_R(1.0))) /
             (MF_R(2.0) * A4 * qa * qa * qa);
}
/* GTR Lambda: Dimov's formulas at the integer tails, spline in gamma.
 * The thesis (C.3) splines S = 1/(1+Lambda) in gamma; at small alpha that
 * misses the masking constraint by up to 17% (alpha 0.02, gamma 0.5), because
 * Lambda scales like alpha^(2 gamma - 2). The spline of log(Lambda) follows
 * that scaling: measured error of the constraint <= 0.6% for gamma >= 1 and
 * <= 5.4% for gamma < 1 (alpha in [0.02, 1], theta_v <= 89 deg). Exact at
 * integer gamma. tan^2 is capped at 1e16 (Lambda ~ 1e8, G1 ~ 1e-8) so float
 * never overflows. */
MF_COLD mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real lam[5], sig = MF_R(0.0), t2 = mf_min(mf__a2t2(MF_R(1.0), MF_R(1.0), w), MF_R(1e16));
    int j;
    if (!(t2 > MF_R(0.0))) return MF_R(0.0);
    mf__gtr_lambda_nodes(d->ax * d->ax, d->p.gtr.L, t2, lam);
    for (j = 0; j < 5; ++j) sig += d->p.gtr.w[j] * MF_LOG(mf_max(lam[j], MF_TINY));
    return MF_EXP(sig);
}

/* tan^2(theta) at D-cos mass t from the pole (q = 1 - t beyond): w = sin^2 +
 * a^2 cos^2 has density ~ w^-gamma on [a^2, 1]; log w = lw. MF_BIG at q = 0. */
MF_COLD mf_real mf__gtr_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real L = p->L, uq, ut, lw, llw, c2, s2;
    if (!(q > MF_R(0.0))) return MF_BIG;
    if (!(t > MF_R(0.0))) return MF_R(0.0);
    /* uq = lw / L and ut = (L - lw) / L add up to 1; the smaller one is
     * computed from its own end (q or t), the other as its complement */
    uq = q * mf__log1p_over_x(q * p->E) / p->RK;
    if (uq < MF_R(0.5)) ut = MF_R(1.0) - uq;
    else { ut = t * mf__log1p_over_x(t * p->EM) / p->RMK; uq = MF_R(1.0) - ut; }
    lw = L * uq; llw = L * ut;
    c2 = uq / mf__x_over_expm1(lw);            /* cos^2 r(L)^-1 */
    s2 = MF_EXP(lw) * ut / mf__x_over_expm1(llw);
    if (!(c2 > MF_R(0.0))) return MF_BIG;
    return mf_min(s2 / c2, MF_BIG);
}

/* D-cos mass beyond the polar angle whose tan^2 is tan2 (inverse of the above). */
MF_COLD mf_real mf__gtr_tail(const mf_ndf *d, mf_real tan2)
{
    mf_real a2m1 = d->ax * d->ax - MF_R(1.0), x = MF_R(1.0) / (MF_R(1.0) + tan2);
    mf_real L = d->p.gtr.L, k = MF_R(1.0) - d->p.gtr.gamma;
    mf_real lwL = x * mf__log1p_over_x(a2m1 * x) / mf__log1p_over_x(a2m1);  /* log w / L */
    return lwL * mf__x_over_expm1(k * L) / mf__x_over_expm1(k * L * lwL);
}

MF_COLD mf_vec3 mf__gtr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(MF_R(1.0), MF_R(1.0), mf__gtr_tan2(d, t, MF_R(1.0) - t), u2);
}

MF_COLD mf_vec3 mf__gtr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__iso_sample_visible_view(d, MF_R(1.0), MF_R(1.0), w, u1, u2);
}
