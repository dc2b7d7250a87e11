/* ======================================================================== */
/* == 6. Distribution kinds: Student-t                                      */
/* ======================================================================== */
/* Student's t-distribution of slopes (Ribardiere et al. 2017), anisotropic:
 * P22 = (1/(pi ax ay)) (1 + r^2/(gamma-1))^-gamma, r^2 = x^2/ax^2 + y^2/ay^2;
 * gamma = 2 is GGX, gamma -> infinity Beckmann. Exact Lambda through the
 * incomplete beta function (measured against an independent 1D integral,
 * gamma 1.55 to 1000, alpha 1e-4 to 1, to 89.9 deg: 1.4e-10 relative in
 * double; in float the head - tail difference cancels: 4.4e-3 relative where
 * Lambda > 1e-4, 4e-4 on 1 + Lambda); NDF sampling by the closed-form inverse CDF;
 * visible normals by the exact numerical inversion of 07_numeric_vndf.h.
 * Everything but the constructor is cold. */
/* @decl */
typedef struct mf_ndf_student_t {
    mf_real gamma;      /* in [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] */
    mf_real K;          /* marginal slope density constant: P2(x) = K (1 + x^2/(g-1))^(1/2-g) */
    mf_real lbeta;      /* log B(gamma - 1, 1/2) */
    mf_real vndf_p;     /* tail exponent of the numerical VNDF sampler's substitution */
} mf_ndf_student_t;
/* @api */
/* Student's t-distribution of slopes (STD), anisotropic. gamma in
 * [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] (clamped). */
MF_INLINE mf_ndf mf_student_t(mf_real alpha_x, mf_real alpha_y, mf_real gamma)
{
    mf_ndf d;
    mf_real g1, beta;
    if (!(gamma > MF_STUDENT_T_GAMMA_MIN)) gamma = MF_STUDENT_T_GAMMA_MIN;
    if (gamma > MF_STUDENT_T_GAMMA_MAX) gamma = MF_STUDENT_T_GAMMA_MAX;
    d = mf__ndf_init(MF_NDF_STUDENT_T, alpha_x, alpha_y);
    g1 = gamma - MF_R(1.0);
    d.p.student_t.gamma = gamma;
    d.p.student_t.K = MF_SQRT(g1) * MF_EXP(MF_LGAMMA(gamma - MF_R(0.5)) - MF_LGAMMA(gamma)) / MF_SQRT_PI;
    d.p.student_t.lbeta = MF_LGAMMA(g1) + MF_LGAMMA(MF_R(0.5)) - MF_LGAMMA(g1 + MF_R(0.5));
    /* the sampler's tail substitution must cancel tan(theta) ~ q^-beta, beta = 1/(2 gamma - 2) */
    beta = MF_R(0.5) / g1;
    d.p.student_t.vndf_p = MF_R(2.0) / (MF_R(1.0) - beta);
    return d;
}
/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion the numerical visible-normal sampler uses (07_numeric_vndf.h). */
MF_COLD mf_real mf__student_t_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__student_t_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__student_t_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__student_t_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__student_t_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__student_t_tail(const mf_ndf *d, mf_real tan2);
/* @cold */
/* Student-t D in logs, so cos^2 may underflow: log D = -g log1p(s2/(g-1)) - 4 log cos,
 * s2 the squared scaled slope. D ~ cos^(2g-4) grows at the horizon when g < 2;
 * capped at e^60 / (pi ax ay) (reached only for cos < ~1e-25). */
MF_COLD mf_real mf__student_t_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real g1, q, lz2, ls2, l1, lr;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    g1 = d->p.student_t.gamma - MF_R(1.0);
    q = mf__q(d->ax, d->ay, wm);
    lz2 = MF_R(2.0) * MF_LOG(wm.z);
    if (!(q > MF_R(0.0))) l1 = MF_R(0.0);
    else {
        ls2 = MF_LOG(q) - lz2;
        l1 = ls2 > MF_R(30.0) ? ls2 - MF_LOG(g1) : MF_LOG1P(MF_EXP(ls2) / g1);
    }
    lr = mf_min(-d->p.student_t.gamma * l1 - MF_R(2.0) * lz2, MF_R(60.0));
    return MF_EXP(lr) / (MF_PI * d->ax * d->ay);
}

/* Student-t Lambda for unit roughness, as a function of mu = cot(theta) / alpha_w. */
MF_INLINE mf_real mf__student_t_lambda_mu(const mf_ndf *d, mf_real mu)
{
    mf_real g = d->p.student_t.gamma, g1 = g - MF_R(1.0), l1p, head, w, tail;
    if (!(mu < MF_R(1e15))) return MF_R(0.0);
    mu = mf_max(mu, MF_R(1e-15));
    l1p = MF_LOG1P(mu * mu / g1);
    head = d->p.student_t.K * g1 / ((MF_R(2.0) * g - MF_R(3.0)) * mu) * MF_EXP((MF_R(1.5) - g) * l1p);
    w = g1 / (g1 + mu * mu);
    tail = MF_R(0.5) * mf__betainc(g1, MF_R(0.5), w, d->p.student_t.lbeta);
    return mf_max(head - tail, MF_R(0.0));
}

/* Student-t Lambda through the projected roughness. */
MF_COLD mf_real mf__student_t_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(d->ax, d->ay, w);
    if (!(a2t2 > MF_R(0.0))) return MF_R(0.0);
    return mf__student_t_lambda_mu(d, MF_R(1.0) / MF_SQRT(a2t2));
}

/* tan^2(theta) at D-cos mass t from the pole (q = 1 - t beyond), unit alpha:
 * q = (1 + tan^2/(g-1))^(1-g). MF_BIG at q = 0. */
MF_COLD mf_real mf__student_t_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    mf_real g1 = d->p.student_t.gamma - MF_R(1.0), lq;
    if (!(q > MF_R(0.0))) return MF_BIG;
    if (!(t > MF_R(0.0))) return MF_R(0.0);
    lq = q < MF_R(0.5) ? MF_LOG(q) : MF_LOG1P(-t);
    return mf_min(g1 * MF_EXPM1(-lq / g1), MF_BIG);
}

/* D-cos mass beyond the polar angle whose tan^2 is tan2, unit alpha. */
MF_COLD mf_real mf__student_t_tail(const mf_ndf *d, mf_real tan2)
{
    mf_real g1 = d->p.student_t.gamma - MF_R(1.0);
    return MF_EXP(-g1 * MF_LOG1P(tan2 / g1));
}

MF_COLD mf_vec3 mf__student_t_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(d->ax, d->ay, mf__student_t_tan2(d, t, MF_R(1.0) - t), u2);
}

MF_COLD mf_vec3 mf__student_t_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__iso_sample_visible_view(d, d->ax, d->ay, w, u1, u2);
}
