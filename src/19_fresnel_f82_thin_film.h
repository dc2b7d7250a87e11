/* @api */
/* ======================================================================== */
/* == 19. F82-tint and thin-film Fresnel                                    */
/* ======================================================================== */
/* F82-tint: Hoffman 2023 ("Generalization of Adobe's Fresnel Model", the
 * metal Fresnel of OpenPBR 1.x): Schlick minus a term a mu (1 - mu)^6 whose
 * weight a makes F(1/7) = tint * Schlick(1/7) (the paper's Eq. 1-3 with
 * mu-bar = 1/7, its "82 degrees"); the formula goes negative for small f0 and
 * tint (OpenPBR PR #256), so F is clamped at 0, and its hemispherical average
 * is that of the clamped F, in closed form between the roots. */

/* F82-tint Fresnel, per channel: f0 the reflectance at normal incidence, tint
 * the colour at mu = 1/7 relative to Schlick's there, so that
 *   F(mu) = f0 + (1 - f0)(1 - mu)^5 - a mu (1 - mu)^6,
 *   a = (1 - tint) (f0 + (1 - f0)(6/7)^5) / ((1/7)(6/7)^6)
 * and F(1) = f0, F(0) = 1, F(1/7) = tint * Schlick(f0, 1/7). Returns F clamped
 * to [0, 1]. cos_theta is used as |cos_theta| (a conductor reflects the same
 * from either side) and clamped to 1; f0 and tint are clamped to [0, 1]
 * (tint > 1 would let F exceed 1); NaN inputs give 0. */
MF_INLINE mf_real mf_fresnel_f82(mf_real cos_theta, mf_real f0, mf_real tint)
{
    mf_real mu, x, x2, x5, a, f;
    if (!(cos_theta == cos_theta) || !(f0 == f0) || !(tint == tint)) return MF_R(0.0);
    mu = mf_min(MF_FABS(cos_theta), MF_R(1.0));
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    tint = mf_clamp(tint, MF_R(0.0), MF_R(1.0));
    /* a = (1 - tint) (7 (7/6)^6 f0 + (49/6)(1 - f0)): S(1/7) over (1/7)(6/7)^6 */
    a = (MF_R(1.0) - tint) * (MF_R(17.651384602194787) * f0 + MF_R(8.1666666666666667) * (MF_R(1.0) - f0));
    x = MF_R(1.0) - mu;
    x2 = x * x;
    x5 = x2 * x2 * x;
    f = f0 + (MF_R(1.0) - f0) * x5 - a * mu * x5 * x;
    return mf_clamp(f, MF_R(0.0), MF_R(1.0));
}

/* The hemispherical average 2 int_0^1 F(mu) mu dmu of the clamped F82-tint
 * Fresnel (the F_avg of mf_ms_fresnel for a coloured conductor), per channel,
 * f0 and tint clamped to [0, 1] (NaN gives 0). Unclamped it is
 * f0 + (1 - f0)/21 - a/126; where the formula is negative (one interval of mu
 * at most: F/(1 - mu)^5 is convex in 1 - mu) that interval's part is taken
 * back, in closed form between its two roots (found by Newton's method). */
MF_COLD mf_real mf_fresnel_f82_average(mf_real f0, mf_real tint);

/* @cold */
/* Antiderivative in x = 1 - mu of F(mu) mu for F(x) = f0 + (1 - f0) x^5 - a (1 - x) x^6:
 * f0 (x - x^2/2) + (1 - f0)(x^6/6 - x^7/7) - a (x^7/7 - x^8/4 + x^9/9) */
MF_INLINE mf_real mf__f82_antideriv(mf_real x, mf_real f0, mf_real a)
{
    mf_real x2 = x * x, x6 = x2 * x2 * x2, x7 = x6 * x;
    return f0 * (x - MF_R(0.5) * x2) + (MF_R(1.0) - f0) * x6 * (MF_R(1.0) / MF_R(6.0) - x / MF_R(7.0))
         - a * x7 * (MF_R(1.0) / MF_R(7.0) - MF_R(0.25) * x + x2 / MF_R(9.0));
}
/* p(x) = F / x^5 = f0 x^-5 + (1 - f0) - a x (1 - x) and p'(x), x = 1 - mu in (0, 1];
 * p'' = 30 f0 x^-7 + 2 a >= 0: p is convex, so F < 0 on one interval at most */
MF_INLINE mf_real mf__f82_p(mf_real x, mf_real f0, mf_real a, mf_real *dp)
{
    mf_real xi = MF_R(1.0) / x, xi2 = xi * xi, xi5 = xi2 * xi2 * xi;
    *dp = MF_R(-5.0) * f0 * xi5 * xi - a * (MF_R(1.0) - MF_R(2.0) * x);
    return f0 * xi5 + (MF_R(1.0) - f0) - a * x * (MF_R(1.0) - x);
}
/* The root of p in [lo, hi] (p(lo) and p(hi) of opposite signs, or one of
 * them 0): Newton's method kept inside the shrinking bracket, bisection when a
 * step would leave it (rtsafe) */
MF_INLINE mf_real mf__f82_root(mf_real lo, mf_real hi, mf_real f0, mf_real a)
{
    mf_real dp, plo = mf__f82_p(lo, f0, a, &dp), x = MF_R(0.5) * (lo + hi);
    int it;
    for (it = 0; it < 100; ++it) {
        mf_real p = mf__f82_p(x, f0, a, &dp), xn;
        if (p == MF_R(0.0)) return x;
        if ((p > MF_R(0.0)) == (plo > MF_R(0.0))) lo = x; else hi = x;
        xn = dp != MF_R(0.0) ? x - p / dp : lo;
        if (!(xn > lo && xn < hi)) xn = MF_R(0.5) * (lo + hi);
        if (MF_FABS(xn - x) <= MF_R(2.0) * MF_EPS * x || hi - lo <= MF_R(2.0) * MF_EPS * hi) return xn;
        x = xn;
    }
    return x;
}
MF_COLD mf_real mf_fresnel_f82_average(mf_real f0, mf_real tint)
{
    mf_real a, avg, xm, x1, x2;
    if (!(f0 == f0) || !(tint == tint)) return MF_R(0.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    tint = mf_clamp(tint, MF_R(0.0), MF_R(1.0));
    a = (MF_R(1.0) - tint) * (MF_R(17.651384602194787) * f0 + MF_R(8.1666666666666667) * (MF_R(1.0) - f0));
    avg = f0 + (MF_R(1.0) - f0) / MF_R(21.0) - a / MF_R(126.0);
    /* p has its minimum where p' = 0, i.e. x^6 (2x - 1) = 5 f0 / a (increasing
     * in x on [1/2, 1], no solution below 1/2): bisection and Newton there */
    if (!(a > MF_R(0.0))) return mf_clamp(avg, MF_R(0.0), MF_R(1.0));
    {
        mf_real t = MF_R(5.0) * f0 / a, lo = MF_R(0.5), hi = MF_R(1.0), dp;
        int it;
        if (t >= MF_R(1.0)) return mf_clamp(avg, MF_R(0.0), MF_R(1.0));   /* p decreasing, p(1) = 1 */
        xm = MF_R(0.75);
        for (it = 0; it < 100; ++it) {
            mf_real x2m = xm * xm, x5 = x2m * x2m * xm, h = x5 * xm * (MF_R(2.0) * xm - MF_R(1.0)) - t;
            mf_real dh = x5 * (MF_R(14.0) * xm - MF_R(6.0)), xn;
            if (h > MF_R(0.0)) hi = xm; else lo = xm;
            xn = dh > MF_R(0.0) ? xm - h / dh : lo;
            if (!(xn > lo && xn < hi)) xn = MF_R(0.5) * (lo + hi);
            if (MF_FABS(xn - xm) <= MF_R(2.0) * MF_EPS || hi - lo <= MF_R(2.0) * MF_EPS) { xm = xn; break; }
            xm = xn;
        }
        if (!(mf__f82_p(xm, f0, a, &dp) < MF_R(0.0))) return mf_clamp(avg, MF_R(0.0), MF_R(1.0));
    }
    /* p(1) = 1 > 0 and p(0+) = +inf (or 1 - f0 = 1 > 0 at f0 = 0): a root each side of xm */
    x1 = mf__f82_root(MF_R(1e-3) * xm, xm, f0, a);
    x2 = mf__f82_root(xm, MF_R(1.0), f0, a);
    /* the clamped average: avg - 2 int_{x1}^{x2} F(x) (1 - x) dx, the integral negative */
    avg -= MF_R(2.0) * (mf__f82_antideriv(x2, f0, a) - mf__f82_antideriv(x1, f0, a));
    return mf_clamp(avg, MF_R(0.0), MF_R(1.0));
}
