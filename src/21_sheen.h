/* @api */
/* ======================================================================== */
/* == 21. Sheen: the Charlie distribution with its exact Smith Lambda       */
/* ======================================================================== */
/* Estevez & Kulla 2017 ("Production Friendly Microfacet Sheen BRDF", Eq. 2):
 * D(m) = (2 + 1/alpha) sin^{1/alpha}(theta_m) / (2 pi), the sheen of Filament,
 * glTF KHR_materials_sheen and Falcor. Its Smith Lambda (Heitz 2014 Eq. 16:
 * 1 + Lambda(w) = int D(m) <w.m> dm / w.z) has no elementary closed form; the
 * paper fits it (Sec. 3, L(x) = a/(1 + b x^c) + d x + e). The distribution is
 * the mf_ndf kind mf_charlie (06_kind_charlie.h: exact Lambda, sampling,
 * every generic operation); these are its functions by alpha, for callers
 * without an mf_ndf, and the published fit. alpha is clamped to
 * [MF_CHARLIE_ALPHA_MIN, 1] = [1e-3, 1] (k = 1/alpha in [1, 1000]). */

/* D(wm) = (2 + 1/alpha) (sin theta_m)^{1/alpha} / (2 pi) for wm.z > 0 (unit
 * wm; any length: homogeneous of degree -4), else 0; normalized: int D(m)
 * m.z dm = 1. NaN alpha gives 0. */
MF_INLINE mf_real mf_charlie_D(mf_real alpha, mf_vec3 wm)
{
    if (!(alpha == alpha)) return MF_R(0.0);
    return mf__charlie_D_k(mf__charlie_k(alpha), wm);
}

/* The exact Smith Lambda of Charlie (mf__charlie_lambda_k, 06_kind_charlie.h:
 * the azimuthal integral in closed form, 12-point Gauss-Legendre over the
 * rest; within 1e-5 of an independent 2D quadrature, tests/test_lobes.c).
 * Depends on |w.z| (w need not be unit); MF_BIG at w.z = 0; 0 on NaN. */
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

/* A normal m with density D(m) m.z (the NDF sampler): sin theta_m =
 * u1^{1/(k+2)}, phi = 2 pi u2 (mf__charlie_sample_D_k). u in [0, 1]; m.z > 0
 * and D(m) > 0 always (u1 below 1e-12 is read as 1e-12). NaN gives the pole. */
MF_INLINE mf_vec3 mf_charlie_sample_D(mf_real alpha, mf_real u1, mf_real u2)
{
    if (!(alpha == alpha)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    return mf__charlie_sample_D_k(mf__charlie_k(alpha), u1, u2);
}

/* @cold */
MF_COLD mf_real mf_charlie_lambda(mf_real alpha, mf_vec3 w)
{
    if (!(alpha == alpha)) return MF_R(0.0);
    return mf__charlie_lambda_k(mf__charlie_k(alpha), w);
}
