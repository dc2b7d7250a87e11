/* @api */
/* ======================================================================== */
/* == 20. EON: energy-preserving Oren-Nayar diffuse                         */
/* ======================================================================== */
/* Portsmouth, Kutz, Hill 2025, "EON: A practical energy-preserving rough
 * diffuse BRDF" (JCGT 14(1); OpenPBR 1.x's diffuse): Fujii's Oren-Nayar (FON,
 * Eq. 3-4: f_ss = rho/pi A (1 + sigma s/t), A = 1/(1 + c1 sigma)) plus the
 * analytic multiple-scattering lobe (Eq. 7-10) built from FON's exact
 * directional albedo E_F (Eq. 5) and its average (Eq. 6), so that the white
 * furnace (rho = 1) is exactly 1. Sampling: the paper's clipped LTC (Sec. 5,
 * Listings 2-4) mixed with a uniform lobe. */

/* c1 = 1/2 - 2/(3 pi), c2 = 2/3 - 28/(15 pi) (EON Eq. 4, 6) */
#define MF__EON_C1 MF_R(0.2877934092108062)
#define MF__EON_C2 MF_R(0.07248821245692394)
#define MF__EON_INV_C1_C2 MF_R(4.6445697320678745)   /* 1 / (c1 - c2) */

/* G(mu)/pi of FON's albedo E_F = (1 + sigma G/pi) / (1 + c1 sigma) (EON Eq. 5):
 *   G = S (acos mu - S mu) + (2/3) ((S/mu)(1 - S^3) - S),  S = sin theta,
 * with (S/mu)(1 - S^3) = S mu (1 + S + S^2)/(1 + S) (no division by mu, no
 * cancellation at grazing). G/pi falls from c1 at mu = 0 to 0 at mu = 1. */
MF_INLINE mf_real mf__eon_gpi(mf_real mu)
{
    mf_real s;
    mu = mf_clamp(mu, MF_R(0.0), MF_R(1.0));
    s = MF_SQRT(mf_max(MF_R(1.0) - mu * mu, MF_R(0.0)));
    return s * (MF_ACOS(mu) - s * mu
                + MF_R(2.0) / MF_R(3.0) * (mu * (MF_R(1.0) + s + s * s) / (MF_R(1.0) + s) - MF_R(1.0))) * MF_INV_PI;
}
/* The paper's fit of G/pi (Listing 1, E_FON_approx): a quartic in 1 - mu */
MF_INLINE mf_real mf__eon_gpi_fast(mf_real mu)
{
    mf_real m = MF_R(1.0) - mf_clamp(mu, MF_R(0.0), MF_R(1.0));
    return m * (MF_R(0.0571085289) + m * (MF_R(0.491881867) + m * (MF_R(-0.332181442) + m * MF_R(0.0714429953))));
}

/* EON, f without the cosine: single scattering (FON) plus multiple
 * scattering,
 *   f = rho/pi A (1 + sigma s/t)
 *     + rho_ms/pi (1 - E_F(mu_o)) (1 - E_F(mu_i)) / (1 - E_F_avg),
 *   s = wo.wi - mu_o mu_i, s/t = s / max(mu_o, mu_i) where s > 0, else s,
 *   E_F_avg = A (1 + c2 sigma), rho_ms = rho^2 E_F_avg / (1 - rho (1 - E_F_avg)).
 * Since 1 - E_F(mu) = sigma (c1 - G(mu)/pi) A and 1 - E_F_avg = sigma (c1 - c2) A,
 * the second line is rho_ms/pi sigma A (c1 - G_o/pi)(c1 - G_i/pi) / (c1 - c2):
 * no 0/0 at sigma = 0 (Lambert) and no epsilon. With the exact E_F the white
 * furnace (rho = 1) integrates to 1 for every view and sigma.
 * rho: albedo in [0, 1] per channel (clamped); sigma: OpenPBR's diffuse
 * roughness in [0, 1] (clamped; not Oren-Nayar's angle). 0 when wo.z <= 0 or
 * wi.z <= 0 or on NaN or infinite input. Reciprocal. */
MF_INLINE mf_real mf_eon_brdf(mf_vec3 wo, mf_vec3 wi, mf_real rho, mf_real sigma)
{
    mf_real mo = wo.z, mi = wi.z, s, st, A, eavg, rho_ms, fss, fms;
    if (!(mo > MF_R(0.0)) || !(mi > MF_R(0.0)) || !(rho == rho) || !(sigma == sigma)) return MF_R(0.0);
    rho = mf_clamp(rho, MF_R(0.0), MF_R(1.0));
    sigma = mf_clamp(sigma, MF_R(0.0), MF_R(1.0));
    mo = mf_min(mo, MF_R(1.0));
    mi = mf_min(mi, MF_R(1.0));
    s = mf_dot(wo, wi) - mo * mi;
    st = s > MF_R(0.0) ? s / mf_max(mo, mi) : s;
    A = MF_R(1.0) / (MF_R(1.0) + MF__EON_C1 * sigma);
    fss = A * (MF_R(1.0) + sigma * st);
    eavg = A * (MF_R(1.0) + MF__EON_C2 * sigma);
    rho_ms = rho * rho * eavg / (MF_R(1.0) - rho * (MF_R(1.0) - eavg));
    fms = rho_ms * sigma * A * (MF__EON_C1 - mf__eon_gpi(mo)) * (MF__EON_C1 - mf__eon_gpi(mi)) * MF__EON_INV_C1_C2;
    if (!(MF_FABS(fss) < MF_BIG) || !(fms < MF_BIG)) return MF_R(0.0);   /* NaN or infinite directions */
    return mf_max(rho * fss + fms, MF_R(0.0)) * MF_INV_PI;
}

/* The directional albedo int f wi.z dwi of mf_eon_brdf, exact (EON Eq. 11):
 * rho E_F(mu) + rho_ms (1 - E_F(mu)); 1 at rho = 1. cos_theta_o <= 0 or NaN
 * gives 0; rho, sigma clamped as mf_eon_brdf. */
MF_INLINE mf_real mf__eon_albedo(mf_real mu, mf_real rho, mf_real sigma, int fast)
{
    mf_real A, ef, eavg, rho_ms;
    if (!(mu > MF_R(0.0)) || !(rho == rho) || !(sigma == sigma)) return MF_R(0.0);
    rho = mf_clamp(rho, MF_R(0.0), MF_R(1.0));
    sigma = mf_clamp(sigma, MF_R(0.0), MF_R(1.0));
    A = MF_R(1.0) / (MF_R(1.0) + MF__EON_C1 * sigma);
    ef = A * (MF_R(1.0) + sigma * (fast ? mf__eon_gpi_fast(mu) : mf__eon_gpi(mu)));
    eavg = A * (MF_R(1.0) + MF__EON_C2 * sigma);
    rho_ms = rho * rho * eavg / (MF_R(1.0) - rho * (MF_R(1.0) - eavg));
    return mf_clamp(rho * ef + rho_ms * (MF_R(1.0) - ef), MF_R(0.0), MF_R(1.0));
}
MF_INLINE mf_real mf_eon_albedo(mf_real cos_theta_o, mf_real rho, mf_real sigma)
{
    return mf__eon_albedo(cos_theta_o, rho, sigma, 0);
}
/* The same with the paper's polynomial fit of G/pi (no acos; Listing 1's
 * E_FON_approx, within 4.7e-4 of the exact E_F): within 1.3e-4 of
 * mf_eon_albedo over mu, rho, sigma in [0, 1]
 * (tests/test_lobes.c holds the bound). */
MF_INLINE mf_real mf_eon_albedo_fast(mf_real cos_theta_o, mf_real rho, mf_real sigma)
{
    return mf__eon_albedo(cos_theta_o, rho, sigma, 1);
}
/* Its hemispherical average 2 int_0^1 E(mu) mu dmu = rho E_F_avg + rho_ms (1 - E_F_avg)
 * (what a layer below or above EON needs); rho, sigma clamped, NaN gives 0. */
MF_INLINE mf_real mf_eon_albedo_average(mf_real rho, mf_real sigma)
{
    mf_real A, eavg, rho_ms;
    if (!(rho == rho) || !(sigma == sigma)) return MF_R(0.0);
    rho = mf_clamp(rho, MF_R(0.0), MF_R(1.0));
    sigma = mf_clamp(sigma, MF_R(0.0), MF_R(1.0));
    A = MF_R(1.0) / (MF_R(1.0) + MF__EON_C1 * sigma);
    eavg = A * (MF_R(1.0) + MF__EON_C2 * sigma);
    rho_ms = rho * rho * eavg / (MF_R(1.0) - rho * (MF_R(1.0) - eavg));
    return mf_clamp(rho * eavg + rho_ms * (MF_R(1.0) - eavg), MF_R(0.0), MF_R(1.0));
}

/* ---- sampling: clipped LTC (EON Sec. 5) + a uniform lobe --------------- */
/* The LTC M = [a 0 b; 0 c 0; d 0 1] fitted to FON at (mu, sigma) (EON Listing
 * 2's rational fits), in the frame whose x axis is wo's azimuth. d <= 0 over
 * the domain except for mu > 0.99992, where the fit gives d < 4e-3 sigma > 0;
 * it is clamped to 0 there, so that the clip below is always on the +x side
 * (the sampler and the pdf both use the clamped matrix). */
typedef struct mf__eon_ltc { mf_real a, b, c, d, vz, s, det, pu, tx, ty; } mf__eon_ltc;
MF_INLINE mf__eon_ltc mf__eon_ltc_make(mf_vec3 wo, mf_real sigma)
{
    mf__eon_ltc L;
    mf_real mu = mf_clamp(wo.z, MF_R(0.0), MF_R(1.0)), r = sigma, l2 = wo.x * wo.x + wo.y * wo.y;
    L.a = MF_R(1.0) + r * (MF_R(0.303392) + (MF_R(-0.518982) + MF_R(0.111709) * mu) * mu
                           + (MF_R(-0.276266) + MF_R(0.335918) * mu) * r);
    L.b = r * (MF_R(-1.16407) + MF_R(1.15859) * mu + (MF_R(0.150815) - MF_R(0.150105) * mu) * r)
        / (mu * mu * mu - MF_R(1.43545));
    L.c = MF_R(1.0) + (MF_R(0.20013) + (MF_R(-0.506373) + MF_R(0.261777) * mu) * mu) * r;
    L.d = r * (MF_R(0.540852) + (MF_R(-1.01625) + MF_R(0.475392) * mu) * mu)
        / (MF_R(-1.0743) + mu * (MF_R(0.0725628) + mu));
    L.d = mf_min(L.d, MF_R(0.0));
    /* the clipped disk (cosine lobe's projection where (M w).z > 0): the unit
     * disk's x < 0 half and, for x > 0, the inside of the ellipse of x
     * semi-axis vz = 1/sqrt(1 + d^2); its area is pi s, s = (1 + vz)/2 */
    L.vz = MF_R(1.0) / MF_SQRT(MF_R(1.0) + L.d * L.d);
    L.s = MF_R(0.5) * (MF_R(1.0) + L.vz);
    L.det = L.c * (L.a - L.b * L.d);
    /* the uniform lobe's probability (EON Listing 4) */
    L.pu = r > MF_R(0.0) ? MF_POW(r, MF_R(0.1)) * (MF_R(0.162925) + mu * (MF_R(-0.372058) + (MF_R(0.538233) - MF_R(0.290822) * mu) * mu))
                         : MF_R(0.0);
    /* the frame: x along wo's azimuth (any, fixed, at normal incidence) */
    if (l2 > MF_R(1e-30) && l2 < MF_BIG) {
        mf_real il = MF_R(1.0) / MF_SQRT(l2);
        L.tx = wo.x * il; L.ty = wo.y * il;
    } else { L.tx = MF_R(1.0); L.ty = MF_R(0.0); }
    return L;
}
/* The clipped LTC's density at a direction w of the LTC frame (w.z > 0):
 * D_o(M^-1 w / |M^-1 w|) |M^-1| / |M^-1 w|^3 with D_o = cos/(pi s) on the
 * clipped disk; with v = adj(M) w = |M| M^-1 w this is |M|^2 v.z / (pi s |v|^4). */
MF_INLINE mf_real mf__eon_cltc_pdf(const mf__eon_ltc *L, mf_vec3 w)
{
    mf_real vx = L->c * (w.x - L->b * w.z), vy = (L->a - L->b * L->d) * w.y, vz = L->c * (L->a * w.z - L->d * w.x);
    mf_real l2 = vx * vx + vy * vy + vz * vz;
    if (!(vz > MF_R(0.0)) || !(l2 > MF_R(0.0))) return MF_R(0.0);
    return L->det * L->det * vz / (MF_PI * L->s * l2 * l2);
}

/* The density (per solid angle) of mf_eon_sample: P_u / (2 pi) + (1 - P_u)
 * D_cltc(wi), P_u = sigma^0.1 (0.162925 - 0.372058 mu + 0.538233 mu^2
 * - 0.290822 mu^3) (EON Listing 4). sigma clamped to [0, 1] (sigma = 0:
 * cosine sampling). 0 when wo.z <= 0, wi.z <= 0 or on NaN. */
MF_INLINE mf_real mf_eon_pdf(mf_vec3 wo, mf_vec3 wi, mf_real sigma)
{
    mf__eon_ltc L;
    mf_vec3 w;
    mf_real p;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0)) || !(sigma == sigma)) return MF_R(0.0);
    L = mf__eon_ltc_make(wo, mf_clamp(sigma, MF_R(0.0), MF_R(1.0)));
    w = mf_vec3_make(L.tx * wi.x + L.ty * wi.y, L.tx * wi.y - L.ty * wi.x, wi.z);
    p = L.pu * (MF_R(0.5) * MF_INV_PI) + (MF_R(1.0) - L.pu) * mf__eon_cltc_pdf(&L, w);
    return p == p ? p : MF_R(0.0);
}

/* Samples wi for EON (EON Sec. 5): with probability P_u uniformly over the
 * hemisphere, else from the clipped LTC: a uniform point of the clipped disk
 * (the unit disk's chord at height y, [-h, h], h = sqrt(1 - y^2), mapped
 * affinely onto the region's chord [-h, vz h]: Jacobian s), lifted to the
 * hemisphere (wh) and transformed by M. The record: wi, pdf = mf_eon_pdf(wo,
 * wi, sigma), weight = mf_eon_brdf(wo, wi, rho, sigma) wi.z / pdf (the
 * direction does not depend on rho: per-channel weights are
 * mf_eon_brdf(.., rho_c, ..) wi.z / pdf), lobe MF_LOBE_REFLECTION. u1, u2 in
 * [0, 1] (1 is read as the largest value below 1); every u gives a sample
 * with wi.z > 0 and pdf > 0 (the lifted height and wi.z are computed without
 * cancellation near the disk's rim and the clip). No sample when wo.z <= 0
 * or wo is not finite. */
MF_INLINE mf_sample mf_eon_sample(mf_vec3 wo, mf_real rho, mf_real sigma, mf_real u1, mf_real u2)
{
    mf__eon_ltc L;
    mf_sample r;
    mf_vec3 w;
    mf_real umax = MF_R(1.0) - MF_R(0.5) * MF_EPS, pc, f, l;
    if (!(wo.z > MF_R(0.0)) || !(wo.z < MF_BIG) || !(wo.x * wo.x + wo.y * wo.y < MF_BIG) || !(sigma == sigma)
        || !(u1 == u1) || !(u2 == u2))
        return mf__no_sample();
    sigma = mf_clamp(sigma, MF_R(0.0), MF_R(1.0));
    L = mf__eon_ltc_make(wo, sigma);
    u1 = mf_clamp(u1, MF_R(0.0), umax);
    u2 = mf_clamp(u2, MF_R(0.0), umax);
    if (u1 < L.pu) {
        /* uniform: z = 1 - u in (0, 1] */
        mf_real z = MF_R(1.0) - mf_min(u1 / L.pu, umax), sz = MF_SQRT(mf_max(MF_R(1.0) - z * z, MF_R(0.0)));
        mf_real phi = MF_R(2.0) * MF_PI * u2;
        w = mf_vec3_make(sz * MF_COS(phi), sz * MF_SIN(phi), z);
        pc = mf__eon_cltc_pdf(&L, w);
    } else {
        mf_real u = L.pu > MF_R(0.0) ? mf_min((u1 - L.pu) / (MF_R(1.0) - L.pu), umax) : u1;
        mf_real R = MF_SQRT(u), phi = MF_R(2.0) * MF_PI * u2, x = R * MF_COS(phi), y = R * MF_SIN(phi);
        mf_real h = MF_SQRT(mf_max(MF_R(1.0) - y * y, MF_R(0.0))), hpx, hmx, xc, zc2, zc, wz;
        /* (h + x)(h - x) = 1 - u: the small factor from the large one */
        if (x >= MF_R(0.0)) { hpx = h + x; hmx = (MF_R(1.0) - u) / hpx; }
        else { hmx = h - x; hpx = (MF_R(1.0) - u) / hmx; }
        xc = L.s * x - (MF_R(1.0) - L.s) * h;                 /* [-h, h] -> [-h, vz h] */
        /* z^2 = h^2 - xc^2 = (h + xc)(h - xc), h + xc = s (h + x), h - xc = s (h - x) + 2 h (1 - s) */
        zc2 = L.s * hpx * (L.s * hmx + MF_R(2.0) * h * (MF_R(1.0) - L.s));
        zc = MF_SQRT(mf_max(zc2, MF_R(0.0)));
        /* (M wh).z = d xc + z; for xc > 0 (d <= 0) it is
         * (1 + d^2) s (h - x) (vz h + xc) / (z - d xc): no cancellation at the clip */
        wz = xc > MF_R(0.0) ? (MF_R(1.0) + L.d * L.d) * L.s * hmx * (L.vz * h + xc) / (zc - L.d * xc)
                            : L.d * xc + zc;
        w = mf_vec3_make(L.a * xc + L.b * zc, L.c * y, wz);
        l = MF_SQRT(mf_dot(w, w));
        if (!(l > MF_R(0.0)) || !(zc > MF_R(0.0))) return mf__no_sample();
        /* D_cltc(w) = (zc / (pi s)) |M wh|^3 / |M| (the LTC's change of measure) */
        pc = zc * l * l * l / (MF_PI * L.s * L.det);
        w = mf_scale(w, MF_R(1.0) / l);
    }
    if (!(w.z > MF_R(0.0))) return mf__no_sample();
    r.pdf = L.pu * (MF_R(0.5) * MF_INV_PI) + (MF_R(1.0) - L.pu) * pc;
    r.wi = mf_vec3_make(L.tx * w.x - L.ty * w.y, L.ty * w.x + L.tx * w.y, w.z);
    if (!(r.pdf > MF_R(0.0)) || !(r.pdf < MF_BIG)) return mf__no_sample();
    f = mf_eon_brdf(wo, r.wi, rho, sigma);
    r.weight = f * r.wi.z / r.pdf;
    r.lobe = MF_LOBE_REFLECTION;
    return r;
}
