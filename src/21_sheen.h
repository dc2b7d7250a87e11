/* @api */
/* ======================================================================== */
/* == 21. Sheen: the Charlie distribution with its exact Smith Lambda       */
/* ======================================================================== */
/* Estevez & Kulla 2017 ("Production Friendly Microfacet Sheen BRDF", Eq. 2):
 * D(m) = (2 + 1/alpha) sin^{1/alpha}(theta_m) / (2 pi), the sheen of Filament,
 * glTF KHR_materials_sheen and Falcor. Its Smith Lambda (Heitz 2014 Eq. 16:
 * 1 + Lambda(w) = int D(m) <w.m> dm / w.z) has no elementary closed form; the
 * paper fits it (Sec. 3, L(x) = a/(1 + b x^c) + d x + e). Here it is exact: the
 * azimuthal integral in closed form, the remaining one by Gauss-Legendre
 * (below). The kind's math as standalone functions, ready to be wired in as
 * an mf_ndf kind (D, Lambda, NDF sampling; visible normals numerically). */

/* alpha is clamped to [1e-3, 1] (k = 1/alpha in [1, 1000]) */
#define MF_CHARLIE_ALPHA_MIN MF_R(1e-3)

/* D(wm) = (2 + 1/alpha) (sin theta_m)^{1/alpha} / (2 pi) for wm.z > 0 (unit
 * wm), else 0; normalized: int D(m) m.z dm = 1. NaN alpha gives 0. */
MF_INLINE mf_real mf_charlie_D(mf_real alpha, mf_vec3 wm)
{
    mf_real k, s2;
    if (!(wm.z > MF_R(0.0)) || !(alpha == alpha)) return MF_R(0.0);
    k = MF_R(1.0) / mf_clamp(alpha, MF_CHARLIE_ALPHA_MIN, MF_R(1.0));
    s2 = mf_clamp(wm.x * wm.x + wm.y * wm.y, MF_R(0.0), MF_R(1.0));
    return (MF_R(2.0) + k) * MF_POW(s2, MF_R(0.5) * k) * (MF_R(0.5) * MF_INV_PI);
}

/* The exact Smith Lambda of Charlie. With mu = cos theta_o, s = sin theta_o,
 * k = 1/alpha, c = (2 + k)/(2 pi), integrating <w.m> over the azimuth of m in
 * closed form (the facets with t = m.z > s see w from every azimuth) gives
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
 * relative accuracy. Depends on |w.z| (w need not be unit); MF_BIG at
 * w.z = 0; 0 on NaN. */
MF_COLD mf_real mf_charlie_lambda(mf_real alpha, mf_vec3 w);

/* The published fit of Lambda (Estevez & Kulla 2017 Sec. 3, as in glTF
 * KHR_materials_sheen): Lambda = exp(L(mu)) for mu < 1/2, else
 * exp(2 L(1/2) - L(1 - mu)), L(x) = a/(1 + b x^c) + d x + e, each coefficient
 * interpolated in (1 - alpha)^2 between the paper's two rows. Kept to match
 * renderers that use it and to measure it: the README states how far it is
 * from mf_charlie_lambda. alpha clamped as above; |w.z| used. */
MF_INLINE mf_real mf_charlie_lambda_fit(mf_real alpha, mf_vec3 w)
{
    mf_real l2 = w.x * w.x + w.y * w.y + w.z * w.z, mu, t, a, b, c, d, e, x, lx, lh;
    if (!(l2 > MF_R(0.0)) || !(alpha == alpha)) return MF_R(0.0);
    mu = mf_min(MF_FABS(w.z) / MF_SQRT(l2), MF_R(1.0));
    alpha = mf_clamp(alpha, MF_CHARLIE_ALPHA_MIN, MF_R(1.0));
    t = (MF_R(1.0) - alpha) * (MF_R(1.0) - alpha);
    a = MF_R(21.5473) + t * (MF_R(25.3245) - MF_R(21.5473));
    b = MF_R(3.82987) + t * (MF_R(3.32435) - MF_R(3.82987));
    c = MF_R(0.19823) + t * (MF_R(0.16801) - MF_R(0.19823));
    d = MF_R(-1.97760) + t * (MF_R(-1.27393) + MF_R(1.97760));
    e = MF_R(-4.32054) + t * (MF_R(-4.85967) + MF_R(4.32054));
    x = mu < MF_R(0.5) ? mu : MF_R(1.0) - mu;
    lx = a / (MF_R(1.0) + b * MF_POW(x, c)) + d * x + e;
    if (mu < MF_R(0.5)) return MF_EXP(lx);
    lh = a / (MF_R(1.0) + b * MF_POW(MF_R(0.5), c)) + d * MF_R(0.5) + e;
    return MF_EXP(MF_R(2.0) * lh - lx);
}

/* A normal m with density D(m) m.z (the NDF sampler): the fraction of
 * projected area with sin theta_m <= S is S^{k+2}, so sin theta_m =
 * u1^{1/(k+2)}, phi = 2 pi u2. u in [0, 1] (1 read as the largest value
 * below 1): m.z = sqrt(-expm1(2 log(u1)/(k+2))) > 0 always. */
MF_INLINE mf_vec3 mf_charlie_sample_D(mf_real alpha, mf_real u1, mf_real u2)
{
    mf_real k, umax = MF_R(1.0) - MF_R(0.5) * MF_EPS, lg, s2, z, s, phi;
    if (!(alpha == alpha) || !(u1 == u1) || !(u2 == u2)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    k = MF_R(1.0) / mf_clamp(alpha, MF_CHARLIE_ALPHA_MIN, MF_R(1.0));
    u1 = mf_clamp(u1, MF_R(0.0), umax);
    u2 = mf_clamp(u2, MF_R(0.0), umax);
    if (!(u1 > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    lg = MF_R(2.0) * MF_LOG(u1) / (k + MF_R(2.0));
    s2 = MF_EXP(lg);
    z = MF_SQRT(mf_max(-MF_EXPM1(lg), MF_R(0.0)));
    s = MF_SQRT(mf_min(s2, MF_R(1.0)));
    phi = MF_R(2.0) * MF_PI * u2;
    return mf_vec3_make(s * MF_COS(phi), s * MF_SIN(phi), z);
}

/* @cold */
MF_COLD mf_real mf_charlie_lambda(mf_real alpha, mf_vec3 w)
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
    mf_real xy2 = w.x * w.x + w.y * w.y, z2 = w.z * w.z, l2 = xy2 + z2, k, s2, s, mu, b, sum = MF_R(0.0), head;
    int i;
    if (!(l2 > MF_R(0.0)) || !(l2 < MF_BIG) || !(alpha == alpha)) return MF_R(0.0);
    if (!(z2 > MF_R(0.0))) return MF_BIG;
    if (!(xy2 > MF_R(0.0))) return MF_R(0.0);
    k = MF_R(1.0) / mf_clamp(alpha, MF_CHARLIE_ALPHA_MIN, MF_R(1.0));
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
