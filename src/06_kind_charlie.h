/* ======================================================================== */
/* == 6. Distribution kinds: Charlie sheen                                  */
/* ======================================================================== */
/* The Charlie sheen distribution (Estevez & Kulla 2017, "Production Friendly
 * Microfacet Sheen BRDF", Eq. 2): D(m) = (2 + 1/alpha) sin^{1/alpha}(theta_m)
 * / (2 pi), isotropic, its mass near the horizon (fibres seen side-on). Not a
 * slope-scale family: ax = ay = alpha records the parameter, no stretch of a
 * unit-roughness form (trait ISO 1, not 2; anisotropy only through
 * mf_transformed). Exact Smith Lambda (mf__charlie_lambda_k), NDF sampling in
 * closed form, visible normals by the exact numerical inversion of
 * 05_numeric_vndf.h through the closed-form NDF-cos CDF: the D-cos mass of
 * theta_m < theta is sin^{k+2}(theta), k = 1/alpha. The standalone functions
 * of 21_sheen.h (mf_charlie_D, mf_charlie_lambda, mf_charlie_sample_D) call
 * the helpers here. Everything but the constructor and the D and sampling
 * helpers is cold. */
/* @decl */
typedef struct mf_ndf_charlie {
    mf_real k;          /* 1 / alpha, in [1, 1 / MF_CHARLIE_ALPHA_MIN] */
} mf_ndf_charlie;
/* @api */
/* alpha is clamped to [1e-3, 1] (k = 1/alpha in [1, 1000]) */
#define MF_CHARLIE_ALPHA_MIN MF_R(1e-3)
/* k = 1 / alpha, alpha clamped (NaN gives alpha = MF_CHARLIE_ALPHA_MIN) */
MF_INLINE mf_real mf__charlie_k(mf_real alpha)
{
    return MF_R(1.0) / (alpha > MF_CHARLIE_ALPHA_MIN ? mf_min(alpha, MF_R(1.0)) : MF_CHARLIE_ALPHA_MIN);
}
/* The Charlie sheen distribution (Estevez & Kulla 2017) as an mf_ndf: every
 * generic operation accepts it. alpha in [MF_CHARLIE_ALPHA_MIN, 1] (clamped;
 * NaN and below give the minimum); isotropic. */
MF_INLINE mf_ndf mf_charlie(mf_real alpha)
{
    mf_real k = mf__charlie_k(alpha);
    mf_ndf d = mf__ndf_init(MF_NDF_CHARLIE, MF_R(1.0) / k, MF_R(1.0) / k);
    d.p.charlie.k = k;
    return d;
}
/* D for k = 1/alpha (Eq. 2), homogeneous of degree -4 in wm: (2 + k)
 * sin^k / (2 pi |wm|^4) with sin^2 = (x^2 + y^2) / |wm|^2; 0 for wm.z <= 0 and
 * non-finite wm, capped at MF_BIG (a vanishing wm). */
MF_INLINE mf_real mf__charlie_D_k(mf_real k, mf_vec3 wm)
{
    mf_real xy2, l2;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    xy2 = wm.x * wm.x + wm.y * wm.y;
    l2 = xy2 + wm.z * wm.z;
    if (!(l2 > MF_R(0.0)) || !(l2 < MF_BIG)) return MF_R(0.0);
    return mf_min((MF_R(2.0) + k) * MF_POW(xy2 / l2, MF_R(0.5) * k) * (MF_R(0.5) * MF_INV_PI) / (l2 * l2), MF_BIG);
}
/* Normals of density D(m) m.z: the D-cos mass of sin theta_m <= S is
 * S^{k+2}, so sin^2 theta_m = u1^{2/(k+2)}, phi = 2 pi u2. u1 is clamped to
 * [MF__CHARLIE_T_MIN, 1 - eps/2]: at u1 = 0 the pole, where D = 0, is
 * replaced by a normal 1e-12 of the mass away, where D, and the BRDF's pdf
 * at grazing views, stay normal floats; m.z = sqrt(-expm1(2 log(u1)/(k+2)))
 * > 0 at u1 = 1. NaN u gives the pole. */
#define MF__CHARLIE_T_MIN MF_R(1e-12)
MF_INLINE mf_vec3 mf__charlie_sample_D_k(mf_real k, mf_real u1, mf_real u2)
{
    mf_real umax = MF_R(1.0) - MF_R(0.5) * MF_EPS, lg, s2, z, s, cp, sp;
    if (!(u1 == u1) || !(u2 == u2)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    u1 = mf_clamp(u1, MF__CHARLIE_T_MIN, umax);
    u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));
    lg = MF_R(2.0) * MF_LOG(u1) / (k + MF_R(2.0));   /* log sin^2 */
    s2 = MF_EXP(lg);
    z = MF_SQRT(mf_max(-MF_EXPM1(lg), MF_R(0.0)));
    s = MF_SQRT(mf_min(s2, MF_R(1.0)));
    mf__sincos_2pi(u2, &cp, &sp);
    return mf_vec3_make(s * cp, s * sp, z);
}
/* The exact Smith Lambda for k = 1/alpha (see the @cold part); w of any
 * length, |w.z| used, MF_BIG at w.z = 0, 0 for non-finite w. */
MF_COLD mf_real mf__charlie_lambda_k(mf_real k, mf_vec3 w);
/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion of the numerical visible-normal sampler (05_numeric_vndf.h). */
MF_COLD mf_real mf__charlie_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__charlie_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__charlie_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__charlie_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__charlie_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__charlie_tail(const mf_ndf *d, mf_real tan2);
/* Exponent p of the numerical sampler's substitution: near the horizon the
 * mass beyond theta is q ~ (k+2) cos^2 / 2, tan ~ q^-1/2, p = 2 / (1 - 1/2). */
MF_INLINE mf_real mf__charlie_vndf_p(const mf_ndf *d) { (void)d; return MF_R(4.0); }
/* @cold */
MF_COLD mf_real mf__charlie_D(const mf_ndf *d, mf_vec3 wm) { return mf__charlie_D_k(d->p.charlie.k, wm); }
MF_COLD mf_real mf__charlie_lambda(const mf_ndf *d, mf_vec3 w) { return mf__charlie_lambda_k(d->p.charlie.k, w); }
MF_COLD mf_vec3 mf__charlie_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    return mf__charlie_sample_D_k(d->p.charlie.k, u1, u2);
}

/* Visible normals: the exact numerical inversion (05_numeric_vndf.h) of the
 * kind's own D (trait ISO 1, unstretched). */
MF_COLD mf_vec3 mf__charlie_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__iso_sample_visible_kind(d, w, u1, u2);
}

/* tan^2(theta) at D-cos mass t from the pole (q = 1 - t beyond): sin^2 =
 * t^{2/(k+2)}, its log from whichever of t and q is the smaller, cos^2 =
 * -expm1 of it. t is floored at MF__CHARLIE_T_MIN, as in
 * mf__charlie_sample_D_k, so the pole (D = 0) is never returned. MF_BIG at
 * q = 0. */
MF_COLD mf_real mf__charlie_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    mf_real lg, c2;
    if (!(q > MF_R(0.0))) return MF_BIG;
    lg = MF_R(2.0) / (d->p.charlie.k + MF_R(2.0)) * (q < MF_R(0.5) ? MF_LOG1P(-q) : MF_LOG(mf_max(t, MF__CHARLIE_T_MIN)));
    c2 = -MF_EXPM1(lg);
    if (!(c2 > MF_R(0.0))) return MF_BIG;
    return mf_min(MF_EXP(lg) / c2, MF_BIG);
}

/* D-cos mass beyond the polar angle whose tan^2 is tan2: 1 - sin^{k+2} =
 * -expm1((k+2)/2 log sin^2), log sin^2 = -log1p(1/tan2). */
MF_COLD mf_real mf__charlie_tail(const mf_ndf *d, mf_real tan2)
{
    if (!(tan2 > MF_R(0.0))) return MF_R(1.0);
    if (!(tan2 < MF_BIG)) return MF_R(0.0);
    return -MF_EXPM1(-MF_R(0.5) * (d->p.charlie.k + MF_R(2.0)) * MF_LOG1P(MF_R(1.0) / tan2));
}

/* The exact Smith Lambda of Charlie (Heitz 2014 Eq. 16: 1 + Lambda(w) =
 * int D(m) <w.m> dm / w.z). With mu = cos theta_o, s = sin theta_o,
 * c = (2 + k)/(2 pi), integrating <w.m> over the azimuth of m in closed form
 * (the facets with t = m.z > s see w from every azimuth) gives
 *   1 + Lambda = mu^{k+2}
 *     + (2 c s^2 / mu) int_0^{pi/2} (1 - s^2 sin^2 b)^{k/2} cos b
 *                         (mu sin b phi0(b) + cos b) db,
 *   phi0 = pi/2 + asin(mu sin b / sqrt(1 - s^2 sin^2 b))
 * (t = s sin b: the substitution makes the integrand analytic). It is
 * evaluated by 12-point Gauss-Legendre on [0, min(pi/2, 7 / (s sqrt k))]
 * (the factor (1 - s^2 sin^2 b)^{k/2} is below e^{-24} beyond): within 1e-6
 * relative of the integral for alpha in [1e-3, 1] and every direction
 * (tests/test_lobes.c holds 1e-5 against an independent 2D quadrature of
 * 1 + Lambda). mu^{k+2} - 1 is taken as expm1, so small Lambda keeps its
 * relative accuracy. */
MF_COLD mf_real mf__charlie_lambda_k(mf_real k, mf_vec3 w)
{
    /* 12-point Gauss-Legendre on [0, 1] */
    const mf_real x[12] = {
        MF_R(0.0092196828766403782), MF_R(0.047941371814762601), MF_R(0.11504866290284765),
        MF_R(0.20634102285669126), MF_R(0.31608425050090994), MF_R(0.43738329574426554),
        MF_R(0.56261670425573446), MF_R(0.68391574949909006), MF_R(0.79365897714330874),
        MF_R(0.88495133709715235), MF_R(0.95205862818523740), MF_R(0.99078031712335962) };
    const mf_real wt[12] = {
        MF_R(0.023587668193255917), MF_R(0.053469662997659283), MF_R(0.080039164271673166),
        MF_R(0.10158371336153292), MF_R(0.11674626826917739), MF_R(0.12457352290670144),
        MF_R(0.12457352290670144), MF_R(0.11674626826917739), MF_R(0.10158371336153292),
        MF_R(0.080039164271673166), MF_R(0.053469662997659283), MF_R(0.023587668193255917) };
    /* sin(pi/2 x_i) (the nodes are symmetric: cos(pi/2 x_i) = sin(pi/2 x_{11-i})) */
    const mf_real sn[12] = {
        MF_R(0.014481737762297655), MF_R(0.075234973915839734), MF_R(0.17973594380167027),
        MF_R(0.31847446499852328), MF_R(0.47635456854949670), MF_R(0.63425156629817825),
        MF_R(0.77312673647229901), MF_R(0.87925327694699151), MF_R(0.94793144010730246),
        MF_R(0.98371489289616976), MF_R(0.99716583309892992), MF_R(0.99989513413726738) };
    mf_real xy2 = w.x * w.x + w.y * w.y, z2 = w.z * w.z, l2 = xy2 + z2, s2, s, mu, b, sum = MF_R(0.0), head;
    int i;
    if (!(l2 > MF_R(0.0)) || !(l2 < MF_BIG)) return MF_R(0.0);
    if (!(z2 > MF_R(0.0))) return MF_BIG;
    if (!(xy2 > MF_R(0.0))) return MF_R(0.0);
    s2 = xy2 / l2;
    s = MF_SQRT(s2);
    mu = MF_SQRT(z2 / l2);
    /* mu^{k+2} - 1, log mu = log1p(-s^2)/2 */
    head = MF_EXPM1(MF_R(0.5) * (k + MF_R(2.0)) * MF_LOG1P(-mf_min(s2, MF_R(1.0) - MF_EPS)));
    b = MF_R(0.5) * MF_PI;
    if (s * MF_SQRT(k) * b > MF_R(7.0)) b = MF_R(7.0) / (s * MF_SQRT(k));
    for (i = 0; i < 12; ++i) {
        mf_real sb, cb, q, arg, phi0;
        if (b < MF_R(0.5) * MF_PI) { sb = MF_SIN(b * x[i]); cb = MF_COS(b * x[i]); }
        else { sb = sn[i]; cb = sn[11 - i]; }
        q = MF_R(1.0) - s2 * sb * sb;
        arg = mf_min(mu * sb / MF_SQRT(q), MF_R(1.0));
        phi0 = MF_R(0.5) * MF_PI + MF_ASIN(arg);
        sum += wt[i] * MF_EXP(MF_R(0.5) * k * MF_LOG(q)) * cb * (mu * sb * phi0 + cb);
    }
    /* 2 c s^2 / mu = (2 + k) s^2 / (pi mu) */
    return mf_min(mf_max(head + (MF_R(2.0) + k) * s2 / (MF_PI * mu) * b * sum, MF_R(0.0)), MF_BIG);
}
