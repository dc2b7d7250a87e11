/* ======================================================================== */
/* == 6. Distribution kinds: GTR                                            */
/* ======================================================================== */
/* Burley's Generalized Trowbridge-Reitz (Burley 2012; thesis Eq. C.5, Berry
 * limit C.6), isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma. Lambda from
 * Dimov's exact formulas at gamma = 0..4 (thesis C.7-C.11) and, between them,
 * from an exact mixture of those distributions integrated by a Gauss-Jacobi
 * rule (mf__gtr_mix_init): too large for mf_ndf, it lives in an mf_gtr_table
 * (mf_gtr_table_build, mf_gtr_table_ndf), or, for mf_gtr by value, in a
 * per-thread cache of recent tables (mf__gtr_cached). NDF sampling by the
 * closed-form inverse CDF (mf__gtr_sample_D), visible normals by exact rejection from GGX or from a
 * mixture of GGX lobes (mf__gtr_sample_visible), falling back on the exact
 * numerical inversion of 05_numeric_vndf.h. Everything but the constructors
 * is cold. */
/* @decl */
/* most nodes of the Lambda mixture rule (the rule takes fewer at larger
 * alpha: mf__gtr_mix_init); at most MF__GJ_MAX of 04_util.h */
#define MF__GTR_NQ 24
/* What a GTR computes at each call without it: the Lambda rule at a
 * non-integer gamma, and the visible sampler's mixture envelope (gamma below
 * 2, alpha below 1/4). Built by mf_gtr_table_build (no allocation: a plain
 * struct, copied as it is to device memory). Fields are filled by the
 * builder; read them, do not write them. */
typedef struct mf_gtr_table {
    mf_real alpha, gamma;       /* the distribution's, clamped as mf_gtr clamps them */
    int nq;                     /* nodes of the mixture rule, a multiple of 4 (0: integer gamma) */
    mf_real qb[MF__GTR_NQ], qw[MF__GTR_NQ];   /* mixture nodes alpha_b^2 and weights */
    mf_real E, EM;              /* expm1(kL), expm1(-kL), k = 1 - gamma, L = log(alpha^2) */
    mf_real RK, RMK;            /* kL / expm1(kL) and -kL / expm1(-kL) */
    mf_real vs[19];             /* the mixture envelope of the visible sampler (mf__gtr_envelope;
                                   mf_ndf.mode's sampler 1 only) */
} mf_gtr_table;
typedef struct mf_ndf_gtr {
    const mf_gtr_table *tab;    /* the table of mf_gtr_table_ndf, 0 from mf_gtr */
    mf_real gamma;              /* tail exponent in [0, 4] */
    mf_real norm;               /* N of D = N / (sin^2 + a^2 cos^2)^gamma */
    mf_real L;                  /* log(alpha^2) */
    mf_real A;                  /* exp((1 - gamma) L) = alpha^(2 (1 - gamma)) */
    mf_real v0, v1;             /* the visible sampler's constants (mf__gtr_sampler_init) */
} mf_ndf_gtr;
/* @api */
/* mf_ndf.mode of a GTR: the Lambda mixture (0 closed form at integer gamma,
 * mixture of 1 GGX, 2 gamma-3, 3 gamma-4) times 4, plus the visible sampler
 * (0 GGX of alpha v0, 1 GGX mixture, 2 rejection from GGX) */
#define MF__GTR_MIX(d) ((int)(d)->mode >> 2)
#define MF__GTR_VMODE(d) ((int)(d)->mode & 3)
MF_COLD int mf__gtr_sampler_init(mf_ndf_gtr *p, mf_real a);
MF_COLD void mf__gtr_mix_init(mf_gtr_table *t, mf_real a, mf_real gamma);
MF_COLD void mf__gtr_envelope(const mf_ndf *d, mf_real vs[19]);
/* the table of a GTR by value from the per-thread cache, or NULL (see @cold) */
MF_COLD const mf_gtr_table *mf__gtr_cached(const mf_ndf *d);
/* Burley's GTR, isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma.
 * alpha in [MF_ALPHA_MIN, 1], gamma in [0, 4] (clamped; see CLAMPS above).
 * gamma = 2 is GGX, gamma = 1 the Berry distribution (limit C.6), gamma = 0
 * the uniform 1/pi; alpha = 1 gives 1/pi for every gamma. N is written with
 * x/expm1(x) so the limits gamma -> 1 and alpha -> 1 are exact. At a
 * non-integer gamma, Lambda needs a quadrature rule and the visible sampler
 * (below gamma 2 and alpha 1/4) an envelope, too large for mf_ndf: they come
 * from a per-thread cache of the last four (alpha, gamma) used (built on a
 * miss, about a microsecond), or are built at each call where the compiler
 * has no thread-local storage (and in CUDA device code). An mf_gtr_table
 * built once (mf_gtr_table_ndf) needs neither: the same values. */
MF_INLINE mf_ndf mf_gtr(mf_real alpha, mf_real gamma)
{
    mf_ndf d;
    mf_ndf_gtr *p;
    mf_real a, L, k;
    int mix;
    a = mf__clamp_alpha(alpha);
    if (a > MF_R(1.0)) a = MF_R(1.0);
    /* the bits: under -ffast-math the comparisons let NaN through, and the
     * Lambda rule (mf__gtr_mix_init) indexes the closed forms by gamma */
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
    p->A = MF_EXP(k * L);
    mix = gamma == (mf_real)(int)gamma ? 0 : gamma < MF_R(2.0) ? 1 : gamma < MF_R(3.0) ? 2 : 3;
    d.mode = (unsigned char)(4 * mix + mf__gtr_sampler_init(p, a));
    return d;
}

/* The table of mf_gtr(alpha, gamma) into *t (nothing is allocated, nothing
 * to release). MF_ERROR_INVALID_ARGUMENT for a NULL t. */
MF_COLD mf_result mf_gtr_table_build(mf_gtr_table *t, mf_real alpha, mf_real gamma);
/* The GTR of a built table: the values of mf_gtr(t->alpha, t->gamma), to the
 * bit, with Lambda at a non-integer gamma as fast as at an integer one, and
 * the mixture sampler's envelope read, not derived at each sample. The
 * distribution refers to t: keep t alive, in place and unchanged while it is
 * used (for CUDA, copy the struct to device memory and pass its device
 * address). A NULL t gives a distribution whose every function returns 0. */
MF_INLINE mf_ndf mf_gtr_table_ndf(const mf_gtr_table *t)
{
    mf_ndf d;
    if (!t) return mf__ndf_init(MF_NDF_KIND_COUNT, MF_R(1.0), MF_R(1.0));
    d = mf_gtr(t->alpha, t->gamma);
    d.p.gtr.tab = t;
    return d;
}

/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion the numerical visible-normal sampler uses (05_numeric_vndf.h; ISO 1). */
MF_COLD mf_real mf__gtr_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__gtr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__gtr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__gtr_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__gtr_tail(const mf_ndf *d, mf_real tan2);
MF_INLINE mf_real mf__gtr_vndf_p(const mf_ndf *d) { (void)d; return MF_R(4.0); }   /* tan ~ q^-1/2 at every gamma */
/* d with its table built in t (trait PREP), or d itself where it has one or
 * needs none (integer gamma, sampler other than the mixture) */
MF_COLD const mf_ndf *mf__gtr_prepare(const mf_ndf *d, mf_ndf *copy, mf_gtr_table *t);
/* sqrt(x) for x in [1, 2e16] in the mixture loops of mf__gtr_lambda. Float:
 * the bit-level first guess of 1/sqrt(x) (relative error < 3.5%), three
 * Newton steps y (3 - x y^2) / 2 (each squares the error: a few float ulps),
 * times x. Unlike sqrtf, which may set errno, compilers vectorize it across
 * the loops' groups of 4 nodes. Double: MF_SQRT (the same steps gain
 * nothing there; docs/PERFORMANCE.md). */
MF_INLINE mf_real mf__gtr_sqrt(mf_real x)
{
#ifdef MF_USE_DOUBLE
    return MF_SQRT(x);
#else
    union { float f; unsigned int u; } v;
    float y;
    v.f = x;
    v.u = 0x5f3759dfu - (v.u >> 1);
    y = v.f;
    y = y * (1.5f - 0.5f * x * y * y);
    y = y * (1.5f - 0.5f * x * y * y);
    y = y * (1.5f - 0.5f * x * y * y);
    return x * y;
#endif
}

/* @cold */
/* The table of a GTR without one (mf_gtr by value at a non-integer gamma):
 * from a per-thread cache of the last MF__GTR_CACHE tables, keyed by the
 * clamped (alpha, gamma) and refilled in turn, so that Lambda and the
 * visible sampler build the rule and the envelope once per material, not
 * once per call (the table of mf_gtr_table_build: the same bits). NULL
 * without thread-local storage (C99 compilers other than gcc, clang and
 * MSVC; CUDA device code): the caller then builds what it needs. */
#define MF__GTR_CACHE 4
#if defined(__cplusplus) && __cplusplus >= 201103L
#define MF__GTR_TLS thread_local
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L && !defined(__STDC_NO_THREADS__)
#define MF__GTR_TLS _Thread_local
#elif defined(__GNUC__) || defined(__clang__)
#define MF__GTR_TLS __thread
#elif defined(_MSC_VER)
#define MF__GTR_TLS __declspec(thread)
#endif
MF_COLD const mf_gtr_table *mf__gtr_cached(const mf_ndf *d)
{
#if defined(MF__GTR_TLS) && !defined(__CUDA_ARCH__)
    static MF__GTR_TLS mf_gtr_table cache[MF__GTR_CACHE];   /* alpha 0: empty */
    static MF__GTR_TLS unsigned next;
    int i;
    for (i = 0; i < MF__GTR_CACHE; ++i)
        if (cache[i].alpha == d->ax && cache[i].gamma == d->p.gtr.gamma) return &cache[i];
    i = (int)(next++ % MF__GTR_CACHE);
    mf_gtr_table_build(&cache[i], d->ax, d->p.gtr.gamma);
    return &cache[i];
#else
    (void)d;
    return 0;
#endif
}
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

/* Dimov's gamma = 4 Lambda (C.11) times 16 (a2^2 + a2 + 1), in a2 = alpha^2,
 * z = a2 tan^2 and q = sqrt(1 + z) (also the component of the gamma-4 mixture).
 * C.11's bracket, 3 (5 a2^2 + 2 a2 + 1)(q+1)^2 - 8 (a2^2 + a2 + 1)(q + 1/2), is
 * (3q+1)(q-1) + a2 (6q^2 + 4q + 2) + a2^2 (15q^2 + 22q + 11): with q - 1 = e =
 * z / (q+1) every term is positive (the textbook form cancels to -1e-22 in
 * float at small z). One division: E = z / ((q+1) q^3), e = E q^3. */
MF_INLINE mf_real mf__gtr_lambda4s(mf_real a2, mf_real z, mf_real q)
{
    mf_real q1 = q + MF_R(1.0), q3 = q * q * q, E = z / (q1 * q3), e = E * q3;
    mf_real P = a2 * (((MF_R(6.0) + MF_R(15.0) * a2) * q + (MF_R(4.0) + MF_R(22.0) * a2)) * q +
                      (MF_R(2.0) + MF_R(11.0) * a2));
    return E * (MF_R(12.0) * a2 * a2 * q1 + e * ((MF_R(3.0) * q + MF_R(1.0)) * e + P));
}

/* Dimov's gamma = 3 Lambda (C.10) times 4 (1 + a2), in a2 = alpha^2, z = a2 tan^2
 * and q = sqrt(1 + z), with qa - 1 = z / (q + 1) folded into one quotient of
 * positive terms (also the component of the gamma-3 mixture). */
MF_INLINE mf_real mf__gtr_lambda3s(mf_real a2, mf_real z, mf_real q)
{
    mf_real q1 = q + MF_R(1.0);
    return z * ((MF_R(3.0) * a2 + MF_R(1.0)) * z + MF_R(4.0) * a2 * q1) / (q * q1 * q1);
}

/* GTR Lambda at integer gamma g = 0..4 (thesis Eq. C.7-C.11 with mu = 1/t),
 * only the one asked for; differences such as sqrt(1 + a2 t2) - 1 are
 * written as quotients so nothing cancels. */
MF_INLINE mf_real mf__gtr_lambda_int(int g, mf_real a2, mf_real L, mf_real t2)
{
    mf_real qa, qb, ea, d, y;
    if (g == 4)                                                        /* C.11 */
        return mf__gtr_lambda4s(a2, a2 * t2, MF_SQRT(MF_R(1.0) + a2 * t2)) /
               (MF_R(16.0) * (a2 * a2 + a2 + MF_R(1.0)));
    qb = MF_SQRT(MF_R(1.0) + t2);
    if (g == 0) return t2 / (MF_R(2.0) * (MF_R(1.0) + qb));           /* C.7: GGX with alpha = 1 */
    qa = MF_SQRT(MF_R(1.0) + a2 * t2);
    ea = a2 * t2 / (qa + MF_R(1.0));                                   /* qa - 1 */
    if (g == 2) return MF_R(0.5) * ea;                                 /* C.9: GGX */
    if (g == 3) return mf__gtr_lambda3s(a2, a2 * t2, qa) / (MF_R(4.0) * (a2 + MF_R(1.0)));   /* C.10 */
    /* C.8: Lambda1 = [(qa - qb) - log1p((qa - qb)/(1 + qb))] / L */
    d = t2 / (qa + qb);                                                /* (qa - qb) / (a2 - 1) */
    y = (a2 - MF_R(1.0)) * d / (MF_R(1.0) + qb);
    return d * (MF_R(1.0) - mf__log1p_over_x(y) / (MF_R(1.0) + qb)) / mf__x_over_expm1(L);
}

/* GTR Lambda, exact at every gamma. With x = tan^2, the slope density is
 * proportional to (1+x)^(gamma-2) (a^2+x)^-gamma; Feynman's parametrization
 * 1/(A^l B^m) = B(l,m)^-1 int s^(l-1) (1-s)^(m-1) (sA + (1-s)B)^-(l+m) ds with
 * A = 1 + x, B = a^2 + x writes it as a positive mixture over b = a^2 + s(1 - a^2)
 * in [a^2, 1] of GTR slope densities of alpha^2 = b and integer gamma k,
 * (1+x)^(k-2) (b+x)^-k, with l = k - gamma, m = gamma:
 *   gamma in (0, 2): GGX (k = 2);  (2, 3): k = 3;  (3, 4): k = 4
 * (k = 3 needs no (1+x)^2 factor, and its Lambda is the cheaper one).
 * Lambda is linear in the slope density, so it is the same mixture of Dimov's
 * Lambdas (C.9, C.10, C.11). In y = log b the mixing weight is
 * (y - log a^2)^(l-1) (-y)^(m-1) times a smooth positive factor, and the
 * components are analytic in the strip |Im y| < pi: mf__gtr_mix_init builds
 * the Gauss-Jacobi rule of those exponents on [log a^2, 0], its weights times
 * that factor, normalized. Its nodes grow with the interval's length |log a^2|,
 * from 3-4 at alpha near 1 to 19 (k = 2), 24 (k = 3), 24 (k = 4) at alpha 1e-4
 * (then padded with zero weights to a multiple of 4): a line above the least
 * count that met 5e-7 against an independent 1D integral at 60 alphas 1e-4..1
 * (9-18 gammas per k, near the integers included, 12 angles to 89.9 deg);
 * k = 4 below alpha 2e-4 would want 25-27 and keeps 24 (2e-6).
 * Integer gamma: the closed forms C.7-C.11. Measured against an independent
 * 1D integral of the slope density (tests/test_ndf.c, 20 alphas 1e-4..1,
 * 25 gammas in [0, 4], theta 1..89.9 deg): relative error of Lambda <= 1.8e-6
 * in double (test bound 1e-5); float 8.4e-7 where Lambda > 1e-4 and 6.0e-7
 * on 1 + Lambda. Cost: bench lines gtr_lambda_* (docs/PERFORMANCE.md);
 * with the rule of an mf_gtr_table (or of the per-thread cache, for mf_gtr
 * by value) Lambda is a few GGX Lambdas; building the rule (Golub-Welsch)
 * costs about a microsecond (integer gamma needs no rule). The
 * rule's 2 x 24 numbers do not fit in mf_ndf, and no cheaper exact form is
 * known: the per-call work of any rule whose nodes depend on gamma is
 * transcendental per node. tan^2 is capped at 1e16 (Lambda ~ 1e8, G1 ~ 1e-8)
 * so float never overflows. */
/* the mixture sum of kind mix (1, 2, 3: components of gamma 2, 3, 4) at tan^2 t2 */
MF_INLINE mf_real mf__gtr_lambda_mix(const mf_gtr_table *p, int mix, mf_real t2)
{
    mf_real s[4];
    int j, k;
    /* nq is a multiple of 4 (zero-weight padding): four independent sums, one
     * loop per component so that each vectorizes */
    s[0] = s[1] = s[2] = s[3] = MF_R(0.0);
    if (mix == 1) {          /* C.9 (times 2) */
        for (j = 0; j < p->nq; j += 4)
            for (k = 0; k < 4; ++k) {
                mf_real bt = p->qb[j + k] * t2;
                s[k] += p->qw[j + k] * bt / (mf__gtr_sqrt(MF_R(1.0) + bt) + MF_R(1.0));
            }
    } else if (mix == 2) {   /* C.10 */
        for (j = 0; j < p->nq; j += 4)
            for (k = 0; k < 4; ++k) {
                mf_real b = p->qb[j + k], bt = b * t2;
                s[k] += p->qw[j + k] * mf__gtr_lambda3s(b, bt, mf__gtr_sqrt(MF_R(1.0) + bt));
            }
    } else {                 /* C.11 */
        for (j = 0; j < p->nq; j += 4)
            for (k = 0; k < 4; ++k) {
                mf_real b = p->qb[j + k], bt = b * t2;
                s[k] += p->qw[j + k] * mf__gtr_lambda4s(b, bt, mf__gtr_sqrt(MF_R(1.0) + bt));
            }
    }
    return (s[0] + s[1]) + (s[2] + s[3]);
}
MF_COLD mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real t2 = mf_min(mf__a2t2(MF_R(1.0), MF_R(1.0), w), MF_R(1e16));
    int mix = MF__GTR_MIX(d);
    if (!(t2 > MF_R(0.0))) return MF_R(0.0);
    if (mix == 0)   /* integer gamma: C.8 and C.11 can round to -4e-23 in float */
        return mf_max(mf__gtr_lambda_int((int)p->gamma, d->ax * d->ax, p->L, t2), MF_R(0.0));
    if (p->tab) return mf__gtr_lambda_mix(p->tab, mix, t2);
    {
        const mf_gtr_table *c = mf__gtr_cached(d);   /* mf_gtr by value */
        mf_gtr_table t;   /* no thread-local cache: the rule, built here */
        if (c) return mf__gtr_lambda_mix(c, mix, t2);
        mf__gtr_mix_init(&t, d->ax, p->gamma);
        return mf__gtr_lambda_mix(&t, mix, t2);
    }
}

/* The mixture rule of mf__gtr_lambda for gamma and alpha a (see there) into
 * t->nq, qb, qw, built in double in every build. With
 * u = y - log a^2, the smooth factor is, in logs,
 *   (l-1) log(expm1(u)/u) + (m-1) log(expm1(y)/y)      (the exact endpoint factors)
 *   + log of b times the component's normalization N_k(b)^-1 (C.5):
 *     k = 3: (1 + b) / b;  k = 4: (b^2 + b + 1) / b^2  (k = 2: constant).
 * Nodes: ceil(c1 |log a^2| + c0), (c1, c0) = (0.85, 2.5), (1.15, 2.5), (1.3, 3)
 * for k = 2, 3, 4 (see mf__gtr_lambda), at most MF__GTR_NQ. */
MF_COLD void mf__gtr_mix_init(mf_gtr_table *p, mf_real a, mf_real gamma)
{
    double g = (double)gamma, L = 2.0 * log((double)a), el, em = g - 1.0, x[MF__GTR_NQ], w[MF__GTR_NQ], lf[MF__GTR_NQ], qb[MF__GTR_NQ];
    double top = -1e300, sum = 0.0, fn;
    int i, n, k;
    if (g == floor(g)) { p->nq = 0; return; }
    k = g < 2.0 ? 2 : g < 3.0 ? 3 : 4;    /* the components' integer gamma */
    fn = k == 2 ? ceil(2.5 - 0.85 * L) : k == 3 ? ceil(2.5 - 1.15 * L) :
         ceil(3.0 - 1.3 * L);
    n = fn < MF__GTR_NQ ? (int)fn : MF__GTR_NQ;
    el = k - g - 1.0;
    /* x = 1 is b = 1 (exponent m - 1), x = -1 is b = a^2 (exponent l - 1) */
    mf__gauss_jacobi(n, em, el, x, w);
    for (i = 0; i < n; ++i) {
        double y = 0.5 * L * (1.0 - x[i]), u = y - L, b = exp(y), f;
        f = (u > 1e-6 ? el * log(expm1(u) / u) : 0.0) +
            (y < -1e-6 ? em * log(expm1(y) / y) : 0.0);
        if (k == 3) f += log((1.0 + b) / b);
        if (k == 4) f += log((b * b + b + 1.0) / (b * b));
        qb[i] = b;
        lf[i] = f;
        if (f > top) top = f;
    }
    for (i = 0; i < n; ++i) { w[i] *= exp(lf[i] - top); sum += w[i]; }
    for (p->nq = n; p->nq % 4; ++p->nq) { p->qb[p->nq] = MF_R(1.0); p->qw[p->nq] = MF_R(0.0); }
    for (i = 0; i < n; ++i) {
        p->qb[i] = (mf_real)qb[i];
        p->qw[i] = (mf_real)(w[i] / (k == 2 ? sum * 2.0 : k == 3 ? sum * 4.0 * (1.0 + qb[i]) :
                                     sum * 16.0 * (qb[i] * qb[i] + qb[i] + 1.0)));
    }
}

/* expm1(kL), expm1(-kL), kL / expm1(kL), -kL / expm1(-kL) (k = 1 - gamma):
 * the careful inversion's constants (mf_gtr_table holds them) */
MF_INLINE void mf__gtr_expm1s(mf_real gamma, mf_real L, mf_real *E, mf_real *EM, mf_real *RK, mf_real *RMK)
{
    mf_real k = MF_R(1.0) - gamma;
    *E = MF_EXPM1(k * L);
    *EM = MF_EXPM1(-k * L);
    *RK = mf__x_over_expm1(k * L);
    *RMK = mf__x_over_expm1(-k * L);
}

/* tan^2(theta) at D-cos mass t from the pole (q = 1 - t beyond): w = sin^2 +
 * a^2 cos^2 has density ~ w^-gamma on [a^2, 1]; log w = lw. MF_BIG at q = 0. */
MF_COLD mf_real mf__gtr_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real L = p->L, uq, ut, lw, llw, c2, s2, E, EM, RK, RMK;
    if (!(q > MF_R(0.0))) return MF_BIG;
    if (!(t > MF_R(0.0))) return MF_R(0.0);
    if (p->tab) { E = p->tab->E; EM = p->tab->EM; RK = p->tab->RK; RMK = p->tab->RMK; }
    else mf__gtr_expm1s(p->gamma, L, &E, &EM, &RK, &RMK);
    /* uq = lw / L and ut = (L - lw) / L add up to 1. Each is computed from
     * its own end (q or t), starting from the smaller mass, which carries the
     * precision (the other is 1 minus it); the other end takes over when its
     * u is the smaller one and its mass keeps log1p away from -1 (in float,
     * t = 1 - 6e-9 rounds to 1 and t EM to -1 at gamma 4, alpha 0.0015). */
    if (q <= t) {
        uq = q * mf__log1p_over_x(q * E) / RK;
        ut = MF_R(1.0) - uq;
        if (uq > MF_R(0.5) && t * EM > MF_R(-0.5)) { ut = t * mf__log1p_over_x(t * EM) / RMK; uq = MF_R(1.0) - ut; }
    } else {
        ut = t * mf__log1p_over_x(t * EM) / RMK;
        uq = MF_R(1.0) - ut;
        if (ut > MF_R(0.5) && q * E > MF_R(-0.5)) { uq = q * mf__log1p_over_x(q * E) / RK; ut = MF_R(1.0) - uq; }
    }
    lw = L * uq; llw = L * ut;
    c2 = uq / mf__x_over_expm1(lw);            /* cos^2 r(L)^-1 */
    s2 = MF_EXP(lw) * ut / mf__x_over_expm1(llw);
    if (!(c2 > MF_R(0.0))) return MF_BIG;
    return mf_min(s2 / c2, MF_BIG);
}

/* D-cos mass beyond the polar angle whose tan^2 is tan2 (inverse of the above). */
MF_COLD mf_real mf__gtr_tail(const mf_ndf *d, mf_real tan2)
{
    mf_real a2 = d->ax * d->ax, a2m1 = a2 - MF_R(1.0), x = MF_R(1.0) / (MF_R(1.0) + tan2);
    mf_real L = d->p.gtr.L, k = MF_R(1.0) - d->p.gtr.gamma, lwL;
    /* log w / L, w = (tan^2 + a^2) / (1 + tan^2); the log1p form (exact at
     * alpha -> 1) would take log1p(a^2 - 1) = log1p(-1) in float at alpha 1e-4 */
    if (a2 < MF_R(0.25)) lwL = (MF_LOG(tan2 + a2) - MF_LOG1P(tan2)) / L;
    else lwL = x * mf__log1p_over_x(a2m1 * x) / mf__log1p_over_x(a2m1);
    return lwL * mf__x_over_expm1(k * L) / mf__x_over_expm1(k * L * lwL);
}

/* The mixture envelope of mf__gtr_sample_visible (mode 1: gamma in (0, 2),
 * alpha <= 1/4). Term j has the density C_j z^(q_j - 1) on its piece [lo, hi]
 * of the ends 0, a^2/4, 4a^2, 1/4, 4, inf (pieces 0, 1, 1, 2, 2, 3, 4 for j =
 * 0..6; q_j = 2, 3/2, 2, 1, 3/2, 1/2, 0 minus gamma; log C_j = -L, -L/2 -
 * log 2, 0, -log 2, 0 by piece, L = log a^2): vs[j] = its mass C_j z_e^q k_j,
 * vs[7 + j] = kk_j = -k_j (q > 0, z_e = hi) or k_j (q <= 0, z_e = lo), k_j =
 * s_j / |q_j|, vs[13 + j] = s_j = -expm1(-|q_j| log(hi/lo)) (1 on the two
 * unbounded pieces). Each C_j z_e^q_j is a product of A = a^(2 (1 - gamma)),
 * a, 4^gamma and powers of 2, and each 1 - s_j one of 16^gamma, A and a: no
 * exponential but s_j's expm1 where 1 - s_j > 1/2 (there 1 minus the product
 * would lose s_j's relative precision). */
/* s_j and k_j of a bounded piece from P = 1 - s_j = exp(-|q| ll), iaq = 1/|q|
 * (0 at q = 0), ll = log(hi/lo); where P > 1/2, s_j from its own expm1 */
MF_INLINE void mf__gtr_piece(mf_real P, mf_real q, mf_real iaq, mf_real ll, mf_real *sj, mf_real *kj)
{
    if (!(P > MF_R(0.5))) { *sj = MF_R(1.0) - P; *kj = *sj * iaq; return; }
    if (q == MF_R(0.0)) { *sj = MF_R(0.0); *kj = ll; return; }   /* the limit q -> 0 */
    *sj = -MF_EXPM1(-MF_FABS(q) * ll);
    *kj = *sj * iaq;
}
MF_COLD void mf__gtr_envelope(const mf_ndf *d, mf_real vs[19])
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real g = p->gamma, a = d->ax, A = p->A, G4 = p->v0, aA = a * A, r = MF_R(1.0) / (G4 * aA);
    mf_real iG4 = r * aA, iA = r * G4 * a, iaA = r * G4, G16 = G4 * G4, iG16 = iG4 * iG4;
    mf_real ln4 = MF_R(1.3862943611198906), ll16 = MF_R(2.0) * ln4, llm = -ln4 - (p->L + ln4);   /* log(hi/lo) of pieces 1, 3 and 2 */
    mf_real q0 = MF_R(2.0) - g, q1 = MF_R(1.5) - g, q3 = MF_R(1.0) - g, q5 = MF_R(0.5) - g;   /* q_j = c_j - gamma */
    mf_real i0 = MF_R(1.0) / q0, i1 = q1 != MF_R(0.0) ? MF_R(1.0) / MF_FABS(q1) : MF_R(0.0);
    mf_real i3 = q3 != MF_R(0.0) ? MF_R(1.0) / MF_FABS(q3) : MF_R(0.0), i5 = q5 != MF_R(0.0) ? MF_R(1.0) / MF_FABS(q5) : MF_R(0.0);
    mf_real k;
    /* unbounded pieces: s = 1, k = 1 / |q|; vs[j] = C_j z_e^q_j k_j */
    vs[0] = A * G4 * MF_R(0.0625) * i0; vs[7] = -i0;
    k = MF_R(1.0) / g; vs[6] = iG4 * k; vs[13] = k;
    /* bounded pieces: 1 - s_j = 16^-|q| on pieces 1 and 3, (16 a^2)^|q| on piece 2 */
    mf__gtr_piece(G16 * MF_R(0.00390625), q0, i0, ll16, &vs[15], &k);
    vs[2] = MF_R(8.0) * aA * iG4 * k; vs[9] = -k;
    if (q1 > MF_R(0.0)) {
        mf__gtr_piece(G16 * MF_R(0.015625), q1, i1, ll16, &vs[14], &k);
        vs[1] = MF_R(4.0) * A * iG4 * k; vs[8] = -k;
        mf__gtr_piece(MF_R(64.0) * aA * iG16, q1, i1, llm, &vs[17], &k);
        vs[4] = G4 * MF_R(0.125) * k; vs[11] = -k;
    } else {
        mf__gtr_piece(MF_R(64.0) * iG16, q1, i1, ll16, &vs[14], &k);
        vs[1] = A * G4 * MF_R(0.0625) * k; vs[8] = k;
        mf__gtr_piece(G16 * iaA * MF_R(0.015625), q1, i1, llm, &vs[17], &k);
        vs[4] = MF_R(8.0) * aA * iG4 * k; vs[11] = k;
    }
    if (q3 > MF_R(0.0)) {
        mf__gtr_piece(MF_R(16.0) * A * iG16, q3, i3, llm, &vs[16], &k);
        vs[3] = G4 * MF_R(0.25) * k; vs[10] = -k;
    } else {
        mf__gtr_piece(G16 * iA * MF_R(0.0625), q3, i3, llm, &vs[16], &k);
        vs[3] = MF_R(4.0) * A * iG4 * k; vs[10] = k;
    }
    if (q5 > MF_R(0.0)) {
        mf__gtr_piece(G16 * MF_R(0.25), q5, i5, ll16, &vs[18], &k);
        vs[5] = iG4 * k; vs[12] = -k;
    } else {
        mf__gtr_piece(MF_R(4.0) * iG16, q5, i5, ll16, &vs[18], &k);
        vs[5] = G4 * MF_R(0.25) * k; vs[12] = k;
    }
}

/* Visible normals (density D_w), exact, by one of (mf__gtr_sampler_init
 * chooses):
 * - gamma = 2, gamma = 0, alpha = 1: GGX of alpha, 1, 1 (the same D);
 * - gamma in (0, 2), alpha <= 1/4, where the GGX proposal below has K > 1.5
 *   (alpha below about 0.15): the slope density (1+x)^(gamma-2) (a^2+x)^-gamma
 *   is the mixture over z in (0, inf) of GGX densities of alpha_b^2 = b =
 *   (a^2 + z) / (1 + z) with weight f(z) = z^(1-gamma) / ((1 + z)(a^2 + z))
 *   (Feynman's identity of mf__gtr_lambda with z = s / (1 - s)). The visible
 *   normals of a mixture: b with weight f(z) (1 + Lambda_b(w)) (each
 *   component's projected area), then b's GGX VNDF. z is drawn by rejection
 *   from f <= z^(1-g) m1(z) m2(z), m1 = min(1/a^2, 1/(2a sqrt z), 1/z) >=
 *   1/(a^2 + z) and m2 = min(1, 1/(2 sqrt z), 1/z) >= 1/(1 + z) (AM-GM, each
 *   within 4/5 on pieces split at a^2/4, 4a^2 and 1/4, 4), times 1 + Lambda_b
 *   = (1 + sqrt(1 + b t^2))/2 <= its value at b = 5a^2/4 on [0, a^2/4],
 *   1 + Lambda_{a^2} + (t/2) sqrt z up to 1/4 (b <= a^2 + z), 1 + Lambda_1
 *   beyond (t = tan theta_w): seven power laws (mf__gtr_envelope), each
 *   inverted in closed form, log z = log z_e + kk u log1p(-u s) / (-u s);
 * - otherwise (gamma in (2, 4], or below 2 with K <= 1.5): rejection from
 *   GGX's VNDF of alpha_p (mf__gtr_sampler_init), accepting with D / (K D_GGX)
 *   (the max(0, w.m) factor cancels), K = sup D / D_GGX <= 1.27 above gamma 2.
 * Normals facing away from w (float rounding at the cap's edge) are drawn
 * again. The first proposal uses (u1, u2), further draws the stream of
 * mf__stream_next; after 64 rejections (probability below 1e-12) the exact
 * numerical inversion of 05_numeric_vndf.h answers. */
MF_INLINE mf_vec3 mf__gtr_ggx(mf_real a, int vis, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real q = MF_R(1.0) - u1;
    return vis ? mf_ggx_sample_visible(a, a, w, u1, u2) : mf__wm_from_slope_u(a, a, q > MF_R(0.0) ? u1 / q : MF_BIG, u2);
}
MF_INLINE mf_vec3 mf__gtr_sample_vis(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real a2 = d->ax * d->ax, g = p->gamma;
    unsigned int st;
    mf_real v1 = u1, v2 = u2;   /* the current proposal's uniforms */
    int it = 0, fresh = 1, vmode = MF__GTR_VMODE(d);
    mf_vec3 m = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    if (vmode == 0) return mf_ggx_sample_visible(p->v0, p->v0, w, u1, u2);
    if (!(w.z >= MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    st = mf__stream_seed(u1, u2);
    if (vmode == 2) {
        mf_real ap = p->v0, ap2 = ap * ap;
        m = mf_ggx_sample_visible(ap, ap, w, u1, u2);
        for (it = 0; it < 64; ++it) {
            /* D / (K D_GGX) = cK ((1+x)/(a^2+x))^(gamma-2) ((ap^2+x)/(a^2+x))^2, x = s2/c2 */
            mf_real c2 = m.z * m.z, s2 = m.x * m.x + m.y * m.y, den = a2 * c2 + s2, r = (ap2 * c2 + s2) / den;
            r = p->v1 * MF_POW((c2 + s2) / den, g - MF_R(2.0)) * r * r;
            if (mf__stream_next(&st) < r && m.z > MF_R(0.0) && mf_dot(w, m) > MF_R(0.0)) break;
            mf__stream_next2(&st, &v1, &v2);
            m = mf_ggx_sample_visible(ap, ap, w, v1, v2);
        }
    } else {
        mf_real s2 = w.x * w.x + w.y * w.y, th, t4, c0, c0p, c1, W[7], tot, a = d->ax, env[19];
        const mf_real *vs = env;
        const mf_gtr_table *c = p->tab ? p->tab : mf__gtr_cached(d);
        if (c) vs = c->vs;   /* built once, by the same function */
        else mf__gtr_envelope(d, env);
        t4 = s2 < w.z * w.z / (MF_EPS * MF_EPS) ? s2 / (w.z * w.z) : MF_R(1.0) / (MF_EPS * MF_EPS);   /* t^2 */
        th = MF_R(0.5) * MF_SQRT(t4);                                                  /* t/2, off the c0 path */
        /* 1 + Lambda_b at b = a^2, 5a^2/4 and 1 */
        c0 = MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + t4 * a2));
        c0p = MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + MF_R(1.25) * t4 * a2));
        c1 = MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + t4));
        W[0] = c0p * vs[0]; W[1] = c0 * vs[1]; W[2] = th * vs[2]; W[3] = c0 * vs[3]; W[4] = th * vs[4];
        W[5] = c1 * vs[5]; W[6] = c1 * vs[6];
        tot = W[0] + W[1] + W[2] + W[3] + W[4] + W[5] + W[6];
        for (it = 0; it < 64; ++it) {
            /* the term from one uniform, the place in it from the next (in [0, 1)) */
            mf_real x = mf__stream_next(&st) * tot, u = mf__stream_next(&st), kk, us, lz, z, sz, n1, n2, cb, d2, b;
            int k, pc;
            for (k = 0; k < 6 && x >= W[k]; ++k) x -= W[k];
            pc = k == 6 ? 4 : (k + 1) >> 1;   /* piece: [0, a^2/4], [a^2/4, 4a^2], [4a^2, 1/4], [1/4, 4], [4, inf) */
            kk = vs[7 + k];
            us = k == 0 || k == 6 ? u : u * vs[13 + k];
            /* the piece's end z_e: its upper end where the density rises (kk < 0), else its lower one */
            lz = kk < MF_R(0.0) ? (pc == 0 ? p->L - MF_R(1.3862944) : pc == 1 ? p->L + MF_R(1.3862944) : pc == 2 ? MF_R(-1.3862944) : MF_R(1.3862944))
                                : (pc == 1 ? p->L - MF_R(1.3862944) : pc == 2 ? p->L + MF_R(1.3862944) : pc == 3 ? MF_R(-1.3862944) : MF_R(1.3862944));
            lz += kk * u * mf__log1p_over_x_fast(-us);
            z = MF_EXP(mf_min(lz, MF_R(34.5)));          /* z <= 1e15: b within 1e-15 of 1 beyond */
            sz = MF_SQRT(z);
            /* f / (z^(1-g) m1 m2) = n1 n2 / ((a^2 + z)(1 + z)), times 1 + Lambda_b over its bound cb */
            n1 = pc == 0 ? a2 : pc == 1 ? MF_R(2.0) * a * sz : z;
            n2 = pc < 3 ? MF_R(1.0) : pc == 3 ? MF_R(2.0) * sz : z;
            cb = pc == 0 ? c0p : pc < 3 ? c0 + th * sz : c1;
            d2 = MF_R(1.0) + z;
            b = (a2 + z) / d2;
            if (mf__stream_next(&st) * cb * (a2 + z) * d2 < n1 * n2 * MF_R(0.5) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + t4 * b))) {
                mf_real ab = MF_SQRT(b);
                if (!fresh) mf__stream_next2(&st, &v1, &v2);
                m = mf_ggx_sample_visible(ab, ab, w, v1, v2);
                fresh = 0;
                if (m.z > MF_R(0.0) && mf_dot(w, m) > MF_R(0.0)) break;   /* float's cap edge: draw again */
            }
        }
    }
    MF__SOLVER_DONE(MF__SITE_REJECT, it, 64);
    if (it < 64) return m;
    return mf__iso_sample_visible_view(d, MF_R(1.0), MF_R(1.0), w, u1, u2);
}

MF_COLD mf_vec3 mf__gtr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__gtr_sample_vis(d, w, u1, u2);
}

/* Normals of density D cos by the inverse CDF: w = sin^2 + a^2 cos^2 has
 * density ~ w^-gamma on [a^2, 1], so w^k = A q + t (k = 1 - gamma, A = a^(2k),
 * q = 1 - t; a sum of positive terms) and tan^2 = (w - a^2) / (1 - w): one
 * pow. Its relative error is about (2/|k| + 2 + |log a^2|) u (w/(w - a^2) +
 * w/(1 - w)), u the unit roundoff (the roundings of A and of A q + t raised
 * to 1/k, then the two differences cancel); where that exceeds 128 u (t near
 * 0 or 1, gamma near 1, alpha near 1) the careful mf__gtr_tan2 answers.
 * Measured in float against a long double inverse (alpha 1e-4..0.99, gamma
 * 0.1..4): at most 150 u, the careful path's own worst 264 u. */
MF_COLD mf_vec3 mf__gtr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), q = MF_R(1.0) - t, k = MF_R(1.0) - p->gamma;
    mf_real a2 = d->ax * d->ax, w, n, e, tan2;
    if (MF__GTR_VMODE(d) == 0) return mf__gtr_ggx(p->v0, 0, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0)), t, u2);
    /* A = exp(kL), not E + 1: float's E rounds near -1 at small alpha */
    w = k != MF_R(0.0) ? MF_POW(p->A * q + t, MF_R(1.0) / k) : MF_EXP(p->L * q);
    n = w - a2; e = MF_R(1.0) - w;
    /* (2/|k| + 2 + |L|) (w/n + w/e) <= 128, without dividing by k */
    if (n > MF_R(0.0) && e > MF_R(0.0) &&
        (MF_R(2.0) + (MF_R(2.0) - p->L) * MF_FABS(k)) * w * (n + e) <= MF_R(128.0) * MF_FABS(k) * n * e)
        tan2 = n / e;
    else
        tan2 = mf__gtr_tan2(d, t, q);
    return mf__wm_from_slope_u(MF_R(1.0), MF_R(1.0), tan2, u2);
}

/* The visible sampler's mode (returned) and constants (see
 * mf__gtr_sample_visible). Rejection (2): v0 = alpha_p, v1 = N pi /
 * (alpha_p^2 K), K = max of the ratio at x = 0, infinity and its one
 * stationary point. Mixture (1): v0 = 4^gamma, from which mf__gtr_envelope
 * derives the envelope. GGX (0): v0 = its alpha. */
MF_COLD int mf__gtr_sampler_init(mf_ndf_gtr *p, mf_real a)
{
    mf_real g = p->gamma, L = p->L, a2 = a * a, npi = p->norm * MF_PI;
    mf_real ap2, c1, c0, l0, li, lk, x;
    p->v0 = g == MF_R(2.0) ? a : MF_R(1.0);
    p->v1 = MF_R(0.0);
    if (g == MF_R(0.0) || g == MF_R(2.0) || !(a < MF_R(1.0))) return 0;
    /* GGX proposal: alpha_p^2 = a^gamma below gamma 2 (it minimizes K there),
     * a^2 / (1 + (gamma - 2)(1 - a^2)) above; K = the largest of the ratio at
     * x = 0 (npi ap^2 a^(-2g)), infinity (npi / ap^2) and its one stationary
     * point, the root of a linear equation (the x^2 terms cancel) */
    ap2 = g < MF_R(2.0) ? MF_EXP(MF_R(0.5) * g * L) : a2 / (MF_R(1.0) + (g - MF_R(2.0)) * (MF_R(1.0) - a2));
    c1 = (g - MF_R(2.0)) * (ap2 + a2) + MF_R(2.0) * (MF_R(1.0) + a2) - g * (MF_R(1.0) + ap2);
    c0 = (g - MF_R(2.0)) * ap2 * a2 + MF_R(2.0) * a2 - g * ap2;
    l0 = MF_LOG(npi * ap2) - g * L; li = MF_LOG(npi / ap2); lk = mf_max(l0, li);
    x = c1 != MF_R(0.0) ? -c0 / c1 : MF_R(-1.0);
    if (x > MF_R(0.0))
        lk = mf_max(lk, li + (g - MF_R(2.0)) * MF_LOG1P(x) + MF_R(2.0) * MF_LOG1P(x / ap2) - g * MF_LOG(a2 + x) + MF_R(2.0) * MF_LOG(ap2));
    /* K <= 1.5 below gamma 2: alpha >~ 0.15; the mixture's pieces need 4a^2 <= 1/4 */
    if (g > MF_R(2.0) || lk < MF_LOG(MF_R(1.5)) || a > MF_R(0.25)) {
        p->v0 = MF_SQRT(ap2);
        p->v1 = npi / (ap2 * MF_EXP(lk));
        return 2;
    }
    p->v0 = MF_EXP(g * MF_R(1.3862943611198906));
    return 1;
}

MF_COLD mf_result mf_gtr_table_build(mf_gtr_table *t, mf_real alpha, mf_real gamma)
{
    mf_ndf d;
    int i;
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    d = mf_gtr(alpha, gamma);
    t->alpha = d.ax;
    t->gamma = d.p.gtr.gamma;
    mf__gtr_mix_init(t, t->alpha, t->gamma);
    mf__gtr_expm1s(t->gamma, d.p.gtr.L, &t->E, &t->EM, &t->RK, &t->RMK);
    if (MF__GTR_VMODE(&d) == 1) mf__gtr_envelope(&d, t->vs);
    else for (i = 0; i < 19; ++i) t->vs[i] = MF_R(0.0);
    return MF_SUCCESS;
}

MF_COLD const mf_ndf *mf__gtr_prepare(const mf_ndf *d, mf_ndf *copy, mf_gtr_table *t)
{
    if ((MF__GTR_MIX(d) == 0 && MF__GTR_VMODE(d) != 1) || d->p.gtr.tab) return d;
    mf_gtr_table_build(t, d->ax, d->p.gtr.gamma);
    *copy = *d;
    copy->p.gtr.tab = t;
    return copy;
}
