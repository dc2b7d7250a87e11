/* ======================================================================== */
/* == 6. Distribution kinds: Student-t                                      */
/* ======================================================================== */
/* Student's t-distribution of slopes (Ribardiere et al. 2017), anisotropic:
 * P22 = (1/(pi ax ay)) (1 + r^2/(gamma-1))^-gamma, r^2 = x^2/ax^2 + y^2/ay^2;
 * gamma = 2 is GGX, gamma -> infinity Beckmann. Exact Lambda through the
 * incomplete beta function (measured against an independent 1D integral,
 * gamma 1.55 to 1000, alpha 1e-4 to 1, to 89.9 deg: 1.6e-10 relative in
 * double; in float 3.5e-4 relative where Lambda > 1e-4, 3.4e-6 on 1 + Lambda:
 * the head and the tail cancel about ten to one at large gamma, so K and
 * log B(g-1, 1/2) come from double log-gamma at construction and the tail is
 * given 1 - x unrounded); NDF sampling by the closed-form inverse CDF;
 * visible normals by exact rejection from GGX or from an exact GGX mixture
 * (mf__student_t_sample_visible), falling back on the exact numerical
 * inversion of 05_numeric_vndf.h. Everything but the constructor is cold. */
/* @decl */
typedef struct mf_ndf_student_t {
    mf_real gamma;      /* in [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] */
    mf_real K;          /* marginal slope density constant: P2(x) = K (1 + x^2/(g-1))^(1/2-g) */
    mf_real lbeta;      /* log B(gamma - 1, 1/2) */
    mf_real vs[5];      /* the visible sampler's constants: gamma > 2, vs[0] = 1/K of its
                           rejection from GGX; gamma < 2, the masses of its mixture
                           envelope (mf__student_t_sampler_init) */
} mf_ndf_student_t;
/* @api */
MF_COLD void mf__student_t_sampler_init(mf_ndf_student_t *p);
/* Student's t-distribution of slopes (STD), anisotropic. gamma in
 * [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] (clamped). */
MF_INLINE mf_ndf mf_student_t(mf_real alpha_x, mf_real alpha_y, mf_real gamma)
{
    mf_ndf d;
    if (!(gamma > MF_STUDENT_T_GAMMA_MIN)) gamma = MF_STUDENT_T_GAMMA_MIN;
    if (gamma > MF_STUDENT_T_GAMMA_MAX) gamma = MF_STUDENT_T_GAMMA_MAX;
    d = mf__ndf_init(MF_NDF_STUDENT_T, alpha_x, alpha_y);
    d.p.student_t.gamma = gamma;
    {
        /* in double in every build: the log-gamma values reach 5900 at gamma 1000,
         * and their float differences would lose 3.5e-4 of K and B (the float
         * Lambda's head and tail, which cancel ten to one, 4e-3) */
        double gd = (double)gamma, lg = lgamma(gd - 0.5);
        d.p.student_t.K = (mf_real)(sqrt(gd - 1.0) * exp(lg - lgamma(gd)) / 1.7724538509055160273);
        d.p.student_t.lbeta = (mf_real)(lgamma(gd - 1.0) + 0.57236494292470008708 - lg);
    }
    mf__student_t_sampler_init(&d.p.student_t);
    return d;
}
/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion the numerical visible-normal sampler uses (05_numeric_vndf.h). */
MF_COLD mf_real mf__student_t_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__student_t_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__student_t_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__student_t_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__student_t_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__student_t_tail(const mf_ndf *d, mf_real tan2);
/* Exponent p of the numerical sampler's substitution (05_numeric_vndf.h): it
 * must cancel the tail tan(theta) ~ q^-beta, beta = 1/(2 gamma - 2), p = 2 / (1 - beta). */
MF_INLINE mf_real mf__student_t_vndf_p(const mf_ndf *d)
{
    mf_real beta = MF_R(0.5) / (d->p.student_t.gamma - MF_R(1.0));
    return MF_R(2.0) / (MF_R(1.0) - beta);
}
/* Term j of the visible sampler's mixture envelope (gamma < 2, see
 * mf__student_t_sampler_init): its k_j, with *kk = -k_j (q_j > 0) or k_j, and
 * *s = s_j (1 on the unbounded pieces); returns q_j. */
MF_INLINE mf_real mf__student_t_term(mf_real g, int j, mf_real *kj, mf_real *kk, mf_real *s)
{
    mf_real ln4 = MF_R(1.3862943611198906), q = g - (j == 0 ? MF_R(1.0) : j < 3 ? MF_R(1.5) : MF_R(2.0)), aq = MF_FABS(q);
    *s = MF_R(1.0);
    if (j == 2 || j == 3) {                 /* [1/4, 4]: log(hi/lo) = log 16 */
        *s = -MF_EXPM1(-aq * MF_R(2.0) * ln4);
        *kj = MF_R(2.0) * ln4 / mf__x_over_expm1(-aq * MF_R(2.0) * ln4);
    } else *kj = MF_R(1.0) / aq;
    *kk = q > MF_R(0.0) ? -*kj : *kj;
    return q;
}
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
    mf_real g = d->p.student_t.gamma, g1 = g - MF_R(1.0), m2, l1p, head, w, tail;
    if (!(mu < MF_R(1e15))) return MF_R(0.0);
    mu = mf_max(mu, MF_R(1e-15));
    m2 = mu * mu;
    l1p = MF_LOG1P(m2 / g1);
    head = d->p.student_t.K * g1 / ((MF_R(2.0) * g - MF_R(3.0)) * mu) * MF_EXP((MF_R(1.5) - g) * l1p);
    w = g1 / (g1 + m2);
    /* x = w, 1 - x = mu^2 / (g1 + mu^2), log x = -l1p: no rounding of 1 - w */
    tail = MF_R(0.5) * mf__betainc_xy(g1, MF_R(0.5), w, m2 / (g1 + m2), -l1p, MF_LOG(m2 / g1) - l1p, d->p.student_t.lbeta);
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

/* Normals of density D cos: tan^2 = (g-1)(q^(-1/(g-1)) - 1), q = 1 - t, one
 * pow where its relative error, about (1 + 1/(g-1)) u w / (w - 1) with
 * w = q^(-1/(g-1)) (u the unit roundoff), is below 128 u; mf__student_t_tan2
 * (log1p, expm1) near the pole and at large gamma. */
MF_COLD mf_vec3 mf__student_t_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), q = MF_R(1.0) - t, g1 = d->p.student_t.gamma - MF_R(1.0), w, tan2;
    w = MF_POW(q, MF_R(-1.0) / g1);
    if (q > MF_R(0.0) && (g1 + MF_R(1.0)) * w <= MF_R(128.0) * g1 * (w - MF_R(1.0)))
        tan2 = mf_min(g1 * (w - MF_R(1.0)), MF_BIG);
    else
        tan2 = mf__student_t_tan2(d, t, q);
    return mf__wm_from_slope_u(d->ax, d->ay, tan2, u2);
}

/* Visible normals, exact, in the space stretched to unit roughness, where
 * the slope density is (1/pi)(1 + v/(g-1))^-g, v the squared slope:
 * - gamma = 2: GGX;
 * - gamma > 2: rejection from GGX's VNDF (unit roughness), accepting with
 *   D / (K D_GGX) = (1 + v)^2 (1 + v/(g-1))^-g / K (the max(0, w.m) factor
 *   cancels), K = 4 ((g-1)/g)^g <= 4/e: accepted >= 68% of the time;
 * - gamma in [1.55, 2): the Gamma(g) = Gamma(2) Beta(g, 2-g) identity makes
 *   (1 + v/(g-1))^-g the mean of (1 + B v/(g-1))^-2 over B ~ Beta(g, 2 - g):
 *   the density is the mixture over z = B/(1-B) in (0, inf) of GGX densities
 *   of alpha_b^2 = b = (g-1)(1 + z)/z with weight f(z) = z^(g-2) / (1 + z).
 *   As for GTR (mf__gtr_sample_visible), b with weight f (1 + Lambda_b(w)),
 *   then b's GGX VNDF; z by rejection from f <= z^(g-2) m(z), m = min(1,
 *   1/(2 sqrt z), 1/z) >= 1/(1 + z) (AM-GM, within 4/5; pieces split at 1/4
 *   and 4), times 1 + Lambda_b <= 1 + Lambda_{g-1} + (t/2) sqrt(g-1) z^-1/2
 *   (sqrt(x + y) <= sqrt x + sqrt y) up to 4, its value at b = 5(g-1)/4
 *   beyond: five power laws (integrable because g > 3/2), each inverted in
 *   closed form (mf__student_t_sampler_init). Components beyond
 *   b = (g-1)/eps^2 (normals within ~eps alpha of the horizon) are drawn at
 *   that b.
 * Further draws come from mf__stream_next; after 64 rejections (probability
 * below 1e-10) the exact numerical inversion of 05_numeric_vndf.h answers. */
MF_COLD mf_vec3 mf__student_t_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real g = d->p.student_t.gamma, g1 = g - MF_R(1.0), ax = d->ax, ay = d->ay;
    unsigned int st;
    mf_real v1 = u1, v2 = u2;   /* the current proposal's uniforms */
    int it = 0, fresh = 1;
    mf_vec3 m = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    if (g == MF_R(2.0)) return mf_ggx_sample_visible(ax, ay, w, u1, u2);
    if (!(w.z >= MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    st = mf__stream_seed(u1, u2);
    if (g > MF_R(2.0)) {
        for (it = 0; it < 64; ++it) {
            mf_real c2, q, gc, r;
            if (!fresh) mf__stream_next2(&st, &v1, &v2);
            m = mf_ggx_sample_visible(ax, ay, w, v1, v2);
            c2 = m.z * m.z; q = mf__q(ax, ay, m); gc = g1 * c2;
            fresh = 0;
            if (!(m.z > MF_R(0.0)) || !(mf_dot(w, m) > MF_R(0.0))) continue;
            /* (1+v)^2 (1+v/g1)^-g = (g1 (c2+q)/(gc+q))^2 (gc/(gc+q))^(g-2), v = q/c2 */
            r = g1 * (c2 + q) / (gc + q);
            r = d->p.student_t.vs[0] * r * r * MF_POW(gc / (gc + q), g - MF_R(2.0));
            if (mf__stream_next(&st) < r) break;
        }
    } else {
        const mf_real *vs = d->p.student_t.vs;
        mf_real a2t2 = mf__a2t2(ax, ay, w), sg = MF_SQRT(g1), th, t4, c0, c0p, W[5], tot, lzmin = MF_R(2.0) * MF_LOG(MF_EPS);
        a2t2 = mf_min(a2t2, MF_R(1.0) / (MF_EPS * MF_EPS));
        th = MF_R(0.5) * MF_SQRT(a2t2);                                        /* t/2 */
        t4 = a2t2 * g1;                                                        /* (t/2)^2 4 (g-1), not through th */
        c0 = MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + t4));                /* 1 + Lambda at b = g - 1 */
        c0p = MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + MF_R(1.25) * t4));  /* at b = 5(g - 1)/4 */
        W[0] = c0 * vs[0]; W[1] = th * sg * vs[1]; W[2] = c0 * vs[2]; W[3] = th * sg * vs[3]; W[4] = c0p * vs[4];
        tot = W[0] + W[1] + W[2] + W[3] + W[4];
        for (it = 0; it < 64; ++it) {
            /* the term from one uniform, the place in it from the next (in [0, 1)) */
            mf_real x = mf__stream_next(&st) * tot, u = mf__stream_next(&st), lz, iz, rho, b1, n, kj, kk, sj;
            int k;
            for (k = 0; k < 4 && x >= W[k]; ++k) x -= W[k];
            mf__student_t_term(g, k, &kj, &kk, &sj);
            /* log z = log z_e + kk u log1p(-u s)/(-u s); z_e = 1/4 (terms 0, 1, 3), 4 (2, 4) */
            lz = (k == 2 || k == 4 ? MF_R(1.3862944) : MF_R(-1.3862944)) +
                 kk * u * mf__log1p_over_x_fast(k == 2 || k == 3 ? -u * sj : -u);
            lz = mf_max(lz, lzmin);
            iz = MF_EXP(-lz);                       /* 1/z */
            rho = MF_SQRT(iz);
            b1 = MF_R(1.0) + iz;                    /* b / (g-1) */
            /* f / (z^(g-2) m) = (1/z, 2/sqrt z, 1) / b1 on the three pieces, times
             * 1 + Lambda_b = (1 + sqrt(1 + b t^2)) / 2 over its bound */
            n = k < 2 ? iz : k < 4 ? MF_R(2.0) * rho : MF_R(1.0);
            if (mf__stream_next(&st) * (k < 4 ? c0 + th * sg * rho : c0p) * b1 <
                n * MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + t4 * b1))) {
                mf_real k1 = MF_R(1.0) / (sg * MF_SQRT(b1));
                if (!fresh) mf__stream_next2(&st, &v1, &v2);
                m = mf__ggx_sample_visible_k(ax, ay, k1, w, v1, v2);
                fresh = 0;
                if (m.z > MF_R(0.0) && mf_dot(w, m) > MF_R(0.0)) break;   /* float's cap edge: draw again */
            }
        }
    }
    MF__SOLVER_DONE(MF__SITE_REJECT, it, 64);
    if (it < 64) return m;
    return mf__iso_sample_visible_view(d, ax, ay, w, u1, u2);
}

/* The visible sampler's constants (see mf__student_t_sample_visible). gamma
 * > 2: vs[0] = 1/K, K = sup (1 + v)^2 (1 + v/(g-1))^-g = 4 ((g-1)/g)^g, at v
 * = 1. gamma < 2, the mixture envelope: term j has the density C_j z^(q_j -
 * 1) on its piece [lo, hi] ((0, 1/4] twice, [1/4, 4] twice, [4, inf); q =
 * g-1, g-3/2, g-3/2, g-2, g-2; C = 1, 1, 1/2, 1/2, 1); vs[j] = its mass C_j
 * z_e^q k_j (z_e = hi where q > 0, else lo), k_j = s_j / |q_j|, s_j =
 * -expm1(-|q_j| log 16) on [1/4, 4] (1 on the others); the sampler takes k_j
 * and s_j of the term it draws from mf__student_t_term. */
MF_COLD void mf__student_t_sampler_init(mf_ndf_student_t *p)
{
    mf_real g = p->gamma, ln4 = MF_R(1.3862943611198906);
    int j;
    for (j = 0; j < 5; ++j) p->vs[j] = MF_R(0.0);
    if (g > MF_R(2.0)) p->vs[0] = MF_R(0.25) * MF_EXP(-g * MF_LOG((g - MF_R(1.0)) / g));
    if (!(g < MF_R(2.0))) return;
    for (j = 0; j < 5; ++j) {
        mf_real kj, kk, sj, q = mf__student_t_term(g, j, &kj, &kk, &sj), le, lc;
        lc = j == 2 || j == 3 ? -MF_LOG(MF_R(2.0)) : MF_R(0.0);
        le = j == 2 || j == 4 ? ln4 : -ln4;
        p->vs[j] = MF_EXP(lc + q * le) * kj;
    }
}
