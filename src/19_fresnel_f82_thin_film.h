/* @api */
/* ======================================================================== */
/* == 19. F82-tint and thin-film Fresnel                                    */
/* ======================================================================== */
/* F82-tint: Hoffman 2023 ("Generalization of Adobe's Fresnel Model", the
 * metal Fresnel of OpenPBR 1.x): Schlick minus a term a mu (1 - mu)^6 whose
 * weight a makes F(1/7) = tint * Schlick(1/7) (the paper's Eq. 1-3 with
 * mu-bar = 1/7, its "82 degrees"); the formula goes negative for small f0 and
 * tint (OpenPBR PR #256), so F is clamped at 0, and its hemispherical average
 * is that of the clamped F, in closed form between the roots.
 * Thin film: Belcour & Barla 2017 ("A Practical Extension to Microfacet
 * Theory for the Modeling of Varying Iridescence"): the exact Airy sum of a
 * film over a (possibly absorbing) base, per wavelength (their Eq. 1-2 with
 * complex amplitudes), and their RGB form: the reflectance as a Fourier
 * series in the phase (Eq. 7-9) integrated in closed form against Gaussian
 * fits of the colour-matching functions in the frequency domain (Sec. 4). */

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
 * back, in closed form between its two roots (found by Newton's method).
 * Per material (a few Fresnel evaluations' worth, bench fresnel_avg):
 * compute it once per f0 and tint. */
MF_COLD mf_real mf_fresnel_f82_average(mf_real f0, mf_real tint);

/* Thin-film interference (Belcour & Barla 2017, Eq. 1-2): the unpolarized
 * reflectance (R_s + R_p)/2 of a film of real index eta_film and thickness
 * thickness_nm between the outside (real index eta_outside, where the light
 * comes from) and a base of complex index eta_base + i k_base, at
 * wavelength_nm: per polarization the exact Airy sum
 *   r = (r12 + r23 e^{i delta}) / (1 + r12 r23 e^{i delta}),
 *   delta = 4 pi thickness q2 / wavelength,  q_j = sqrt(n_j^2 - (n1 sin theta1)^2)
 * with the complex Fresnel amplitudes r12, r23 (their phases included) and
 * R = |r|^2. Zero thickness gives the bare base's Fresnel reflectance (of
 * eta_base + i k_base relative to eta_outside), exactly. Total internal
 * reflection in the film (eta_outside sin theta > eta_film) makes q2
 * imaginary: the film is evanescent and r is the frustrated-TIR reflectance,
 * the base's Fresnel at zero thickness rising to 1 (no interference colours)
 * once the film is thicker than about a wavelength; TIR at the base (real
 * eta_base below eta_outside sin theta) is |r23| = 1 with its phase.
 * cos_theta is used as |cos_theta| (clamped to 1); a negative thickness is
 * read as 0. Returns 0 for non-positive eta_outside, eta_film, eta_base or
 * wavelength, negative k_base or NaN; 1 at grazing incidence. */
MF_COLD mf_real mf_fresnel_thin_film(mf_real cos_theta, mf_real eta_outside, mf_real eta_film,
                                     mf_real thickness_nm, mf_real eta_base, mf_real k_base,
                                     mf_real wavelength_nm);
/* The same film in linear sRGB under D65 (Belcour & Barla 2017, Sec. 4):
 * per polarization and channel c the reflectance is the Fourier series
 *   R(delta) = C0 + 2 sum_{m>=1} C_m cos(m (delta + phi)),
 *   C0 = R12 + T^2 R23 / (1 - R12 R23), C_m = (C0 - R12 - T) (R12 R23)^{m/2},
 *   T = 1 - R12, phi = pi + arg r12 + arg r23 (exact: the Airy sum's own
 * expansion), integrated against channel c's sensitivity in closed form:
 * that sensitivity (the D65-weighted CIE 1931 functions taken to linear
 * sRGB) as 12 Gaussians in frequency (tools/thin_film_fit.c), so each term is
 * Re(e^{i m phi} S_c(m OPD)), OPD = 2 thickness q2, with S_c the Gaussians'
 * Fourier transform normalized to S_c(0) = 1. The series is summed until its
 * remainder is below 1e-7 (at most 256 terms), so a spectrally flat
 * reflectance R gives exactly (R, R, R) and zero thickness the base's
 * Fresnel per channel. eta_base[c], k_base[c] are the base's index for
 * channel c (a dispersive base is read at one index per channel; the film's
 * index is constant over the spectrum). Each channel is clipped to [0, 1]:
 * saturated interference colours lie outside the sRGB gamut (negative
 * components). Against spectral integration of the exact reflectance with
 * the CIE tables (clipped the same way) the result is within 1e-3 (measured
 * by tests/test_lobes.c over 8 film stacks, 0-2000 nm, 0-80 degrees; the
 * fitted transform is within 6e-3 of the tables', so the error is at most
 * 6e-3 times sum 2|C_m|). Under total internal
 * reflection in the film there are no interference colours: each channel is
 * mf_fresnel_thin_film at that channel's mean wavelength (647.4, 544.0, 442.6
 * nm), within 4e-3 of spectral integration. Invalid input (as
 * mf_fresnel_thin_film, NULL arrays) gives (0, 0, 0). */
MF_COLD void mf_fresnel_thin_film_rgb(mf_real cos_theta, mf_real eta_outside, mf_real eta_film,
                                      mf_real thickness_nm, const mf_real eta_base[3],
                                      const mf_real k_base[3], mf_real rgb[3]);

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

/* ---- thin film ----------------------------------------------------------- */
typedef struct mf__cx { mf_real re, im; } mf__cx;
MF_INLINE mf__cx mf__cx_make(mf_real re, mf_real im) { mf__cx z; z.re = re; z.im = im; return z; }
MF_INLINE mf__cx mf__cx_add(mf__cx a, mf__cx b) { return mf__cx_make(a.re + b.re, a.im + b.im); }
MF_INLINE mf__cx mf__cx_sub(mf__cx a, mf__cx b) { return mf__cx_make(a.re - b.re, a.im - b.im); }
MF_INLINE mf__cx mf__cx_mul(mf__cx a, mf__cx b) { return mf__cx_make(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
MF_INLINE mf__cx mf__cx_scale(mf__cx a, mf_real s) { return mf__cx_make(a.re * s, a.im * s); }
MF_INLINE mf_real mf__cx_abs2(mf__cx a) { return a.re * a.re + a.im * a.im; }
/* a / b (Smith's scaling); 0 / 0 gives NaN, which the callers test */
MF_INLINE mf__cx mf__cx_div(mf__cx a, mf__cx b)
{
    mf_real r, d;
    if (MF_FABS(b.re) >= MF_FABS(b.im)) {
        r = b.im / b.re; d = b.re + b.im * r;
        return mf__cx_make((a.re + a.im * r) / d, (a.im - a.re * r) / d);
    }
    r = b.re / b.im; d = b.re * r + b.im;
    return mf__cx_make((a.re * r + a.im) / d, (a.im * r - a.re) / d);
}
/* the principal square root: Re >= 0, and Im >= 0 when a.im >= 0 (so that a
 * wave with q = sqrt(n^2 - a) decays into an absorbing or evanescent medium) */
MF_INLINE mf__cx mf__cx_sqrt(mf__cx a)
{
    mf_real m = MF_SQRT(MF_SQRT(mf__cx_abs2(a))), t;
    if (!(m > MF_R(0.0))) return mf__cx_make(MF_R(0.0), MF_R(0.0));
    t = MF_SQRT(MF_R(0.5) * (MF_SQRT(mf__cx_abs2(a)) + MF_FABS(a.re)));
    if (a.re >= MF_R(0.0)) return mf__cx_make(t, a.im / (MF_R(2.0) * t));
    return mf__cx_make(MF_FABS(a.im) / (MF_R(2.0) * t), a.im >= MF_R(0.0) ? t : -t);
}
/* The two interfaces' amplitudes for one polarization: q_j = n_j cos theta_j,
 * e_j = 1 (s) or n_j^2 (p); r_ij = (e_j q_i - e_i q_j) / (e_j q_i + e_i q_j).
 * The p form has the opposite sign convention to s at normal incidence: the
 * same for both interfaces, so |r| of the film is unchanged. */
MF_INLINE mf__cx mf__tf_amp(mf__cx qi, mf__cx qj, mf__cx ei, mf__cx ej)
{
    mf__cx a = mf__cx_mul(ej, qi), b = mf__cx_mul(ei, qj);
    return mf__cx_div(mf__cx_sub(a, b), mf__cx_add(a, b));
}
/* the film's interfaces for one polarization (p = 0: s, 1: p) */
MF_INLINE void mf__tf_interfaces(mf_real n1, mf_real n2, mf__cx n3sq, mf_real q1, mf__cx q2, mf__cx q3, int p,
                                 mf__cx *r12, mf__cx *r23)
{
    mf__cx one = mf__cx_make(MF_R(1.0), MF_R(0.0));
    mf__cx e1 = p ? mf__cx_make(n1 * n1, MF_R(0.0)) : one, e2 = p ? mf__cx_make(n2 * n2, MF_R(0.0)) : one;
    mf__cx e3 = p ? n3sq : one;
    *r12 = mf__tf_amp(mf__cx_make(q1, MF_R(0.0)), q2, e1, e2);
    *r23 = mf__tf_amp(q2, q3, e2, e3);
}
/* validated inputs: 0 when invalid; c1 = |cos|, a = (n1 sin theta1)^2 */
MF_INLINE int mf__tf_check(mf_real cos_theta, mf_real n1, mf_real n2, mf_real d, mf_real *c1, mf_real *a)
{
    if (!(cos_theta == cos_theta) || !(n1 > MF_R(0.0)) || !(n1 < MF_BIG) || !(n2 > MF_R(0.0)) || !(n2 < MF_BIG)
        || !(d == d) || !(d < MF_BIG))
        return 0;
    *c1 = mf_min(MF_FABS(cos_theta), MF_R(1.0));
    *a = n1 * n1 * (MF_R(1.0) - *c1 * *c1);
    return 1;
}
MF_COLD mf_real mf_fresnel_thin_film(mf_real cos_theta, mf_real eta_outside, mf_real eta_film,
                                     mf_real thickness_nm, mf_real eta_base, mf_real k_base,
                                     mf_real wavelength_nm)
{
    mf_real c1, a, n1 = eta_outside, n2 = eta_film, R = MF_R(0.0), k;
    mf__cx n3sq, q2, q3, ph;
    int p;
    if (!mf__tf_check(cos_theta, n1, n2, thickness_nm, &c1, &a) || !(eta_base > MF_R(0.0)) || !(eta_base < MF_BIG)
        || !(k_base >= MF_R(0.0)) || !(k_base < MF_BIG) || !(wavelength_nm > MF_R(0.0)) || !(wavelength_nm < MF_BIG))
        return MF_R(0.0);
    if (!(c1 > MF_R(0.0))) return MF_R(1.0);
    n3sq = mf__cx_make(eta_base * eta_base - k_base * k_base, MF_R(2.0) * eta_base * k_base);
    q2 = mf__cx_sqrt(mf__cx_make(n2 * n2 - a, MF_R(0.0)));
    q3 = mf__cx_sqrt(mf__cx_make(n3sq.re - a, n3sq.im));
    /* e^{i delta}, delta = 4 pi d q2 / lambda (q2 imaginary: a decay) */
    k = MF_R(4.0) * MF_PI * mf_max(thickness_nm, MF_R(0.0)) / wavelength_nm;
    ph = mf__cx_scale(mf__cx_make(MF_COS(k * q2.re), MF_SIN(k * q2.re)), MF_EXP(-k * q2.im));
    for (p = 0; p < 2; ++p) {
        mf__cx r12, r23, t, r;
        mf__tf_interfaces(n1, n2, n3sq, c1 * n1, q2, q3, p, &r12, &r23);
        t = mf__cx_mul(r23, ph);
        r = mf__cx_div(mf__cx_add(r12, t), mf__cx_add(mf__cx_make(MF_R(1.0), MF_R(0.0)), mf__cx_mul(r12, t)));
        R += MF_R(0.5) * mf__cx_abs2(r);
    }
    return R == R ? mf_clamp(R, MF_R(0.0), MF_R(1.0)) : MF_R(1.0);
}

#define MF__TF_K 12
MF_COLD void mf_fresnel_thin_film_rgb(mf_real cos_theta, mf_real eta_outside, mf_real eta_film,
                                      mf_real thickness_nm, const mf_real eta_base[3],
                                      const mf_real k_base[3], mf_real rgb[3])
{
    /* Generated by tools/thin_film_fit.c 12 0.001: the normalized transforms'
     * error against the CIE tables' over x in [0, 40] um: R 0.0057, G 0.0042, B 0.0044;
     * the channels' mean wavelengths (1 / mean frequency): 647.4, 544.0, 442.6 nm */
    const mf_real mu[MF__TF_K] = {
        MF_R(1.63491337), MF_R(1.5623611), MF_R(1.63580221), MF_R(1.71986526),
        MF_R(1.81065029), MF_R(1.90752231), MF_R(1.98449151), MF_R(2.05640068),
        MF_R(2.14239652), MF_R(2.23470572), MF_R(2.52411769), MF_R(2.41482654) };
    const mf_real var[MF__TF_K] = {
        MF_R(0.101836623), MF_R(0.00201866521), MF_R(0.0234220967), MF_R(0.0554136166),
        MF_R(0.0776334448), MF_R(0.0642109583), MF_R(0.0316081964), MF_R(0.0443507848),
        MF_R(0.0829196455), MF_R(0.177344457), MF_R(0.0203991684), MF_R(0.00836299255) };
    const mf_real w[3][MF__TF_K] = {
        { MF_R(1.05376979), MF_R(0.00428867109), MF_R(0.110719585), MF_R(0.304472295),
          MF_R(-0.0538272755), MF_R(-0.326083004), MF_R(-0.0689420762), MF_R(-0.0831027655),
          MF_R(-0.0664575347), MF_R(0.124588182), MF_R(0.000339882759), MF_R(0.000234252643) },
        { MF_R(-0.106364357), MF_R(-0.00016190555), MF_R(0.0040044925), MF_R(0.160327648),
          MF_R(0.521118213), MF_R(0.380852919), MF_R(0.060984347), MF_R(0.0692308753),
          MF_R(0.023954458), MF_R(-0.113680842), MF_R(-0.000253919149), MF_R(-1.19290977e-05) },
        { MF_R(-0.00826076665), MF_R(-4.45702046e-05), MF_R(-0.0027549846), MF_R(-0.0253166718),
          MF_R(-0.0652040488), MF_R(-0.0253268871), MF_R(0.024264921), MF_R(0.0276954009),
          MF_R(0.216452125), MF_R(0.859531414), MF_R(0.00143286703), MF_R(-0.00246879871) } };
    const mf_real lambda_mean[3] = { MF_R(647.4), MF_R(544.0), MF_R(442.6) };
    mf_real c1, a, n1 = eta_outside, n2 = eta_film, x, rho[3][2], B[3][2], acc[3];
    mf__cx q2, z[MF__TF_K], cur[MF__TF_K], ph[3][2], phm[3][2];
    mf_real env[MF__TF_K], g[MF__TF_K], f2[MF__TF_K], rhom[3][2];
    int c, p, k, m;
    if (!rgb) return;
    rgb[0] = rgb[1] = rgb[2] = MF_R(0.0);
    if (!eta_base || !k_base || !mf__tf_check(cos_theta, n1, n2, thickness_nm, &c1, &a)) return;
    for (c = 0; c < 3; ++c)
        if (!(eta_base[c] > MF_R(0.0)) || !(eta_base[c] < MF_BIG) || !(k_base[c] >= MF_R(0.0)) || !(k_base[c] < MF_BIG)) return;
    if (!(c1 > MF_R(0.0))) { rgb[0] = rgb[1] = rgb[2] = MF_R(1.0); return; }
    if (a >= n2 * n2) {
        /* total internal reflection in the film: evanescent, no interference */
        for (c = 0; c < 3; ++c)
            rgb[c] = mf_fresnel_thin_film(c1, n1, n2, thickness_nm, eta_base[c], k_base[c], lambda_mean[c]);
        return;
    }
    q2 = mf__cx_make(MF_SQRT(n2 * n2 - a), MF_R(0.0));
    /* the optical path difference 2 d q2, in micrometres (the fit's unit) */
    x = MF_R(2e-3) * mf_max(thickness_nm, MF_R(0.0)) * q2.re;
    for (c = 0; c < 3; ++c) {
        mf__cx n3sq = mf__cx_make(eta_base[c] * eta_base[c] - k_base[c] * k_base[c], MF_R(2.0) * eta_base[c] * k_base[c]);
        mf__cx q3 = mf__cx_sqrt(mf__cx_make(n3sq.re - a, n3sq.im));
        acc[c] = MF_R(0.0);
        for (p = 0; p < 2; ++p) {
            mf__cx r12, r23;
            mf_real R12, R23, T, C0, a12, a23, phi;
            mf__tf_interfaces(n1, n2, n3sq, c1 * n1, q2, q3, p, &r12, &r23);
            R12 = mf__cx_abs2(r12); R23 = mf__cx_abs2(r23);
            if (!(R12 == R12) || !(R23 == R23)) { rgb[0] = rgb[1] = rgb[2] = MF_R(1.0); return; }
            R12 = mf_min(R12, MF_R(1.0)); R23 = mf_min(R23, MF_R(1.0));
            T = MF_R(1.0) - R12;
            /* Belcour & Barla Eq. 8-9: C0, and C_m = B rho^m, rho = |r12 r23| */
            C0 = R12 + (T > MF_R(0.0) ? T * T * R23 / (MF_R(1.0) - R12 * R23) : MF_R(0.0));
            B[c][p] = C0 - R12 - T;
            rho[c][p] = MF_SQRT(R12 * R23);
            acc[c] += MF_R(0.5) * C0;
            /* phi = pi + arg r12 + arg r23 (r12 is real here: 0 or pi) */
            a12 = r12.re < MF_R(0.0) ? MF_PI : MF_R(0.0);
            a23 = MF_ATAN2(r23.im, r23.re);
            phi = MF_PI + a12 + a23;
            ph[c][p] = mf__cx_make(MF_COS(phi), MF_SIN(phi));
            phm[c][p] = ph[c][p];
            rhom[c][p] = rho[c][p];
        }
    }
    /* per Gaussian k: e^{2 pi i x mu_k m} and e^{-var_k x^2 m^2} by recurrence */
    for (k = 0; k < MF__TF_K; ++k) {
        mf_real t = MF_R(2.0) * MF_PI * x * mu[k], f = MF_EXP(-var[k] * x * x);
        z[k] = mf__cx_make(MF_COS(t), MF_SIN(t));
        cur[k] = z[k];
        env[k] = f;            /* e^{-var x^2 m^2} at m = 1 */
        g[k] = f;              /* f^{2m - 1}: the factor from m - 1 to m */
        f2[k] = f * f;
    }
    for (m = 1; m <= 256; ++m) {
        mf_real bound = MF_R(0.0), rmax = MF_R(0.0);
        for (c = 0; c < 3; ++c) {
            mf__cx S = mf__cx_make(MF_R(0.0), MF_R(0.0));
            mf_real envmax = MF_R(0.0);
            for (k = 0; k < MF__TF_K; ++k) {
                S = mf__cx_add(S, mf__cx_scale(cur[k], w[c][k] * env[k]));
                envmax = mf_max(envmax, MF_FABS(w[c][k]) * env[k]);
            }
            for (p = 0; p < 2; ++p) {
                mf__cx e = phm[c][p];
                acc[c] += B[c][p] * rhom[c][p] * (e.re * S.re - e.im * S.im);   /* 2 x 1/2 */
                bound = mf_max(bound, MF_FABS(B[c][p]) * rhom[c][p] * envmax * (mf_real)MF__TF_K);
                rmax = mf_max(rmax, rho[c][p]);
                rhom[c][p] *= rho[c][p];
                phm[c][p] = mf__cx_mul(phm[c][p], ph[c][p]);
            }
        }
        /* the remainder: the envelopes do not grow with m, so it is at most
         * bound rho / (1 - rho) */
        if (!(bound > MF_R(0.0)) || (rmax < MF_R(1.0) && bound * rmax <= MF_R(1e-7) * (MF_R(1.0) - rmax))) break;
        for (k = 0; k < MF__TF_K; ++k) {
            cur[k] = mf__cx_mul(cur[k], z[k]);
            g[k] *= f2[k];
            env[k] *= g[k];
        }
    }
    for (c = 0; c < 3; ++c) rgb[c] = acc[c] == acc[c] ? mf_clamp(acc[c], MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
}
