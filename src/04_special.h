/* @api */
/* ======================================================================== */
/* == 4. Special functions                                                  */
/* ======================================================================== */
/* Small, self-contained pieces the distributions need: the inverse error
 * function, the regularized incomplete beta function, and the functions
 * x / expm1(x) and log1p(x) / x, which keep the GTR formulas finite at their
 * removable singularities (gamma = 1, alpha = 1). */

/* x / (e^x - 1), 1 at x = 0. */
MF_INLINE mf_real mf__x_over_expm1(mf_real x)
{
    if (MF_FABS(x) < MF_R(1e-4)) return MF_R(1.0) - MF_R(0.5) * x;
    return x / MF_EXPM1(x);
}
/* log(1 + x) / x, 1 at x = 0. */
MF_INLINE mf_real mf__log1p_over_x(mf_real x)
{
    if (MF_FABS(x) < MF_R(1e-4)) return MF_R(1.0) - MF_R(0.5) * x;
    return MF_LOG1P(x) / x;
}

/* log1p(x) / x for x in (-1, 0], with one log (Goldberg 1991: the rounding
 * of 1 + x cancels in log(1 + x) / ((1 + x) - 1)); the rejection samplers'
 * power-law draws (GTR, Student-t) */
MF_INLINE mf_real mf__log1p_over_x_fast(mf_real x)
{
    mf_real y = MF_R(1.0) + x, e = y - MF_R(1.0);
    return e != MF_R(0.0) ? MF_LOG(y) / e : MF_R(1.0);
}

/* Inverse of erf on (-1, 1): Giles' single-precision approximation (2010),
 * polished by Newton steps on erf/erfc. Finite for every input (clamped). */
MF_INLINE mf_real mf__erfinv_giles(mf_real y)
{
    mf_real w, p;
    w = -MF_LOG((MF_R(1.0) - y) * (MF_R(1.0) + y));
    if (w < MF_R(5.0)) {
        w = w - MF_R(2.5);
        p = MF_R(2.81022636e-08);
        p = MF_R(3.43273939e-07) + p * w;
        p = MF_R(-3.5233877e-06) + p * w;
        p = MF_R(-4.39150654e-06) + p * w;
        p = MF_R(0.00021858087) + p * w;
        p = MF_R(-0.00125372503) + p * w;
        p = MF_R(-0.00417768164) + p * w;
        p = MF_R(0.246640727) + p * w;
        p = MF_R(1.50140941) + p * w;
    } else {
        w = MF_SQRT(w) - MF_R(3.0);
        p = MF_R(-0.000200214257);
        p = MF_R(0.000100950558) + p * w;
        p = MF_R(0.00134934322) + p * w;
        p = MF_R(-0.00367342844) + p * w;
        p = MF_R(0.00573950773) + p * w;
        p = MF_R(-0.0076224613) + p * w;
        p = MF_R(0.00943887047) + p * w;
        p = MF_R(1.00167406) + p * w;
        p = MF_R(2.83297682) + p * w;
    }
    return p * y;
}
MF_INLINE mf_real mf_erfinv(mf_real y)
{
    mf_real x;
    int i;
    y = mf_clamp(y, MF_R(-1.0) + MF_EPS, MF_R(1.0) - MF_EPS);
    x = mf__erfinv_giles(y);
#ifdef MF_USE_DOUBLE
    for (i = 0; i < 2; ++i) { /* Newton on the tail-accurate side */
        mf_real r = x >= 0.0 ? (1.0 - y) - MF_ERFC(x) : MF_ERFC(-x) - (1.0 + y); /* erf(x) - y */
        x -= r / (2.0 / MF_SQRT_PI * MF_EXP(-x * x));
    }
#else
    (void)i;
#endif
    return x;
}

/* cos and sin of 2 pi u, u in [0, 1], without a library call: the nearest
 * quarter turn k = round(4u) is exact (4u - k is exact in binary), the rest
 * t = (4u - k) pi/2 lies in [-pi/4, pi/4] where the Taylor series to t^9 / t^10
 * (float) or t^17 / t^18 (double) is below half an ulp; the quarter turn
 * picks and negates without branches (an index and exact factors +-1). */
MF_FORCE_INLINE void mf__sincos_2pi(mf_real u, mf_real *c, mf_real *s)
{
    u = mf_clamp(u, MF_R(0.0), MF_R(1.0));
#if defined(__CUDA_ARCH__)
    /* device: CUDA's sincospi (documented within 1 ulp in float, 2 in
     * double), faster there than this polynomial: GGX mf_sample_visible in
     * float 111 against 99 G samples/s on an H100 (make cuda-run) */
#ifdef MF_USE_DOUBLE
    sincospi(MF_R(2.0) * u, s, c);
#else
    sincospif(MF_R(2.0) * u, s, c);
#endif
#else
    mf_real q = MF_R(4.0) * u, t, t2, v[2];
    int k = (int)(q + MF_R(0.5));
    t = (q - (mf_real)k) * MF_R(1.57079632679489661923);
    t2 = t * t;
#ifdef MF_USE_DOUBLE
    v[1] = 2.8114572543455207632e-15 - t2 * 8.2206352466243297170e-18;   /* 1/17!, 1/19! */
    v[1] = 7.6471637318198164759e-13 - t2 * v[1];
    v[1] = 1.6059043836821614599e-10 - t2 * v[1];
    v[1] = 2.5052108385441718775e-08 - t2 * v[1];
    v[1] = 2.7557319223985890653e-06 - t2 * v[1];
    v[0] = 1.5619206968586225271e-16;                                 /* 1/18! */
    v[0] = 4.7794773323873852974e-14 - t2 * v[0];
    v[0] = 1.1470745597729724714e-11 - t2 * v[0];
    v[0] = 2.0876756987868098979e-09 - t2 * v[0];
    v[0] = 2.7557319223985890653e-07 - t2 * v[0];
    v[0] = 2.4801587301587301587e-05 - t2 * v[0];
#else
    v[1] = MF_R(2.7557319223985890653e-06);
    v[0] = MF_R(2.4801587301587301587e-05) - t2 * MF_R(2.7557319223985890653e-07);
#endif
    v[1] = MF_R(1.9841269841269841270e-04) - t2 * v[1];
    v[1] = MF_R(8.3333333333333333333e-03) - t2 * v[1];
    v[1] = MF_R(1.6666666666666666667e-01) - t2 * v[1];
    v[1] = t - t * t2 * v[1];                                 /* sin t */
    v[0] = MF_R(1.3888888888888888889e-03) - t2 * v[0];
    v[0] = MF_R(4.1666666666666666667e-02) - t2 * v[0];
    v[0] = MF_R(0.5) - t2 * v[0];
    v[0] = MF_R(1.0) - t2 * v[0];                             /* cos t */
    *c = v[k & 1] * (mf_real)(1 - ((k + 1) & 2));
    *s = v[(k & 1) ^ 1] * (mf_real)(1 - (k & 2));
#endif
}

/* Regularized incomplete beta I_x(a, b) by Lentz's continued fraction
 * (converges fast for x < (a+1)/(a+b+2); the symmetry I_x(a,b) = 1 - I_{1-x}(b,a)
 * covers the rest). lbeta = log B(a, b), precomputed by the caller. */
MF_INLINE mf_real mf__betacf(mf_real a, mf_real b, mf_real x)
{
    const mf_real tiny = MF_R(1e-30);
    mf_real c = MF_R(1.0), d = MF_R(1.0) - (a + b) * x / (a + MF_R(1.0)), h;
    int m;
    if (MF_FABS(d) < tiny) d = tiny;
    d = MF_R(1.0) / d;
    h = d;
    for (m = 1; m <= 300; ++m) {
        mf_real fm = (mf_real)m, m2 = MF_R(2.0) * fm, aa, del;
        aa = fm * (b - fm) * x / ((a + m2 - MF_R(1.0)) * (a + m2));
        d = MF_R(1.0) + aa * d; if (MF_FABS(d) < tiny) d = tiny;
        c = MF_R(1.0) + aa / c; if (MF_FABS(c) < tiny) c = tiny;
        d = MF_R(1.0) / d; h *= d * c;
        aa = -(a + fm) * (a + b + fm) * x / ((a + m2) * (a + m2 + MF_R(1.0)));
        d = MF_R(1.0) + aa * d; if (MF_FABS(d) < tiny) d = tiny;
        c = MF_R(1.0) + aa / c; if (MF_FABS(c) < tiny) c = tiny;
        d = MF_R(1.0) / d; del = d * c; h *= del;
        if (MF_FABS(del - MF_R(1.0)) < MF_R(4.0) * MF_EPS) break;
    }
    MF__SOLVER_DONE(MF__SITE_BETACF, m > 300 ? 300 : m, 300);
    return h;
}
/* I_x(a, b) from x, y = 1 - x and their logs as the caller computes them,
 * so that nothing rounds 1 - x where x is near 1 (Student-t's Lambda:
 * x = (g-1)/(g-1 + mu^2), a = g - 1 up to 999) */
MF_INLINE mf_real mf__betainc_xy(mf_real a, mf_real b, mf_real x, mf_real y, mf_real lx, mf_real ly, mf_real lbeta)
{
    mf_real front;
    if (!(x > MF_R(0.0))) return MF_R(0.0);
    if (!(y > MF_R(0.0))) return MF_R(1.0);
    front = MF_EXP(a * lx + b * ly - lbeta);
    if (x < (a + MF_R(1.0)) / (a + b + MF_R(2.0))) return front * mf__betacf(a, b, x) / a;
    return MF_R(1.0) - front * mf__betacf(b, a, y) / b;
}
MF_INLINE mf_real mf__betainc(mf_real a, mf_real b, mf_real x, mf_real lbeta)
{
    if (!(x > MF_R(0.0))) return MF_R(0.0);
    if (!(x < MF_R(1.0))) return MF_R(1.0);
    return mf__betainc_xy(a, b, x, MF_R(1.0) - x, MF_LOG(x), MF_LOG1P(-x), lbeta);
}
/* @cold */
/* One step of safeguarded Newton for an increasing f on the bracket [lo, hi]:
 * shrinks the bracket with the sign of f, takes the Newton step, falls back to
 * bisection when the step leaves the bracket. Returns 1 when converged. */
MF_INLINE int mf__newton_step(mf_real *x, mf_real f, mf_real df, mf_real *lo, mf_real *hi, mf_real tol)
{
    mf_real step, nx;
    if (f > MF_R(0.0)) *hi = *x; else *lo = *x;
    if (df > MF_R(0.0)) {
        step = f / df;
        nx = *x - step;
        if (MF_FABS(step) <= tol) { *x = mf_clamp(nx, *lo, *hi); return 1; }
        if (nx > *lo && nx < *hi) { *x = nx; return 0; }
    }
    nx = MF_R(0.5) * (*lo + *hi);
    if (!(nx > *lo && nx < *hi)) return 1;   /* bracket exhausted */
    *x = nx;
    return 0;
}

/* Sample phi in (-pi, pi] with density proportional to max(0, c + cos(phi)). */
MF_INLINE mf_real mf__sample_phi_cos(mf_real c, mf_real u)
{
    mf_real phi0, total, lo, hi, phi, sgn = MF_R(1.0);
    int i;
    if (u < MF_R(0.5)) { u = MF_R(1.0) - MF_R(2.0) * u; sgn = MF_R(-1.0); }
    else u = MF_R(2.0) * u - MF_R(1.0);
    /* |phi| has CDF (c phi + sin phi) / (c phi0 + sin phi0) on [0, phi0] */
    phi0 = c >= MF_R(1.0) ? MF_PI : MF_ACOS(mf_max(-c, MF_R(-1.0)));
    total = c * phi0 + MF_SIN(phi0);
    if (c > MF_R(1e6)) return sgn * u * MF_PI;   /* uniform */
    /* keep off the edge phi0, where the density is 0 (u = 0 would land on it):
     * the CDF mass moved is 4 eps */
    if (c < MF_R(1.0)) u = mf_min(u, MF_R(1.0) - MF_R(4.0) * MF_EPS);
    lo = MF_R(0.0); hi = phi0; phi = u * phi0;
    for (i = 0; i < 60; ++i)
        if (mf__newton_step(&phi, c * phi + MF_SIN(phi) - u * total, c + MF_COS(phi), &lo, &hi, MF_R(4.0) * MF_EPS))
            break;
    MF__SOLVER_DONE(MF__SITE_PHI_COS, i, 60);
    return sgn * phi;
}
