/* @api */
/* ======================================================================== */
/* == 23. Volumetric sheen: the LTC of a layer of fibres                    */
/* ======================================================================== */
/* Zeltner, Burley & Chiang 2022 ("Practical Multiple-Scattering Sheen Using
 * Linearly Transformed Cosines", Eq. 1), the fuzz of OpenPBR and the sheen
 * of Cycles: the light reflected by a layer of fibre-like SGGX microflakes
 * standing along the normal (unit thickness and density, albedo 1, over a
 * black base, every scattering order) is a linearly transformed cosine,
 *   f(wo, wi) wi.z = R D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3,
 *   M^-1 = [A 0 B; 0 A 0; 0 0 1],
 * w = wi in the frame turned about z so that wo has azimuth 0, D_o the
 * clamped cosine / pi. A, B and the albedo R are read bilinearly from the
 * built-in table (22_sheen_table.h), fitted by tools/sheen_fit.c to our own
 * simulation of the layer, in cos theta_o and alpha (OpenPBR's
 * fuzz_roughness; the fibres' cross-section sigma = alpha^2, SGGX
 * S = diag(1, 1, sigma^2)). alpha is clamped to [0, 1] and cos theta_o to
 * [0, 1]: the table's first row is the layer at alpha = 0.01 (alpha = 0 is
 * an empty layer) and its first column the view at cos theta_o = 0.01, so
 * alpha < 1/31 and cos theta_o < 1/31 blend towards those fits. The last
 * row of M^-1 keeps z, so the lobe lies in the upper hemisphere and
 * integrates to 1 there: the albedo is R exactly, and the sampler's weight
 * f cos / pdf is R. Sampling: a cosine direction moved by M (Heitz et al.
 * 2016). The lobe is reciprocal only approximately (the paper's choice).
 * Directions are unit vectors; below the horizon (either side), NaN or
 * R = 0 give 0 and no sample. Gone with MF_NO_LTC_TABLE. */
#ifndef MF_NO_LTC_TABLE
/* f(wo, wi) without the cosine (divide by nothing more; times wi.z it is the lobe) */
MFDEF mf_real mf_sheen_brdf(mf_vec3 wo, mf_vec3 wi, mf_real alpha);
/* the sampler's density per solid angle (the LTC; 0 where f is 0) */
MFDEF mf_real mf_sheen_pdf(mf_vec3 wo, mf_vec3 wi, mf_real alpha);
/* wi with density mf_sheen_pdf, weight f cos / pdf = R; u in [0, 1] */
MFDEF mf_sample mf_sheen_sample(mf_vec3 wo, mf_real alpha, mf_real u1, mf_real u2);
/* R: the directional albedo of the layer, integral of f cos over wi (for
 * layering: what the sheen takes from the light below it, albedo-scaled) */
MFDEF mf_real mf_sheen_albedo(mf_real cos_theta_o, mf_real alpha);
#endif

/* @impl */
#ifndef MF_NO_LTC_TABLE
/* A, B, R at (cos theta_o, alpha), bilinear in the table (nodes j / (n - 1)
 * in both; inputs clamped to [0, 1], NaN read as 0) */
static void mf__sheen_lookup(mf_real mu, mf_real alpha, mf_real *A, mf_real *B, mf_real *R)
{
    int n, i, j, k;
    const float *t = mf__sheen_data(&n);
    mf_real x = mf_clamp(mu, MF_R(0.0), MF_R(1.0)) * (mf_real)(n - 1), y = mf_clamp(alpha, MF_R(0.0), MF_R(1.0)) * (mf_real)(n - 1);
    mf_real fx, fy, v[3];
    j = (int)x; if (j > n - 2) j = n - 2;
    i = (int)y; if (i > n - 2) i = n - 2;
    fx = x - (mf_real)j; fy = y - (mf_real)i;
    for (k = 0; k < 3; ++k) {
        const float *p = t + 3 * (i * n + j) + k;
        mf_real a0 = (mf_real)p[0] + fx * ((mf_real)p[3] - (mf_real)p[0]);
        mf_real a1 = (mf_real)p[3 * n] + fx * ((mf_real)p[3 * n + 3] - (mf_real)p[3 * n]);
        v[k] = a0 + fy * (a1 - a0);
    }
    *A = mf_max(v[0], MF_R(1e-4));   /* the fitted A are above 1e-2; never singular */
    *B = v[1];
    *R = mf_max(v[2], MF_R(0.0));
}

/* the azimuth of wo: (cos, sin); wo along the normal (or non-finite) gives 0 */
static void mf__sheen_frame(mf_vec3 wo, mf_real *c, mf_real *s)
{
    mf_real r2 = wo.x * wo.x + wo.y * wo.y, r;
    *c = MF_R(1.0); *s = MF_R(0.0);
    if (!(r2 > MF_R(0.0)) || !(r2 < MF_BIG)) return;
    r = MF_SQRT(r2);
    *c = wo.x / r; *s = wo.y / r;
}

/* the LTC density of w (wo's frame): A^2 v.z / (pi |v|^4), v = M^-1 w */
static mf_real mf__sheen_ltc(mf_real A, mf_real B, mf_vec3 w)
{
    mf_real vx = A * w.x + B * w.z, vy = A * w.y, l2 = vx * vx + vy * vy + w.z * w.z;
    if (!(w.z > MF_R(0.0)) || !(l2 > MF_R(0.0))) return MF_R(0.0);
    return mf__cap(A * A * w.z * MF_INV_PI / (l2 * l2));
}

/* R and the LTC density of wi, or 0 (below the horizon, NaN) */
static mf_real mf__sheen_eval(mf_vec3 wo, mf_vec3 wi, mf_real alpha, mf_real *R)
{
    mf_real A, B, c, s;
    *R = MF_R(0.0);
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0)) || !(alpha == alpha) || !(wo.z < MF_BIG) || !(wi.z < MF_BIG))
        return MF_R(0.0);
    mf__sheen_lookup(wo.z, alpha, &A, &B, R);
    mf__sheen_frame(wo, &c, &s);
    return mf__sheen_ltc(A, B, mf_vec3_make(c * wi.x + s * wi.y, c * wi.y - s * wi.x, wi.z));
}

MFDEF mf_real mf_sheen_brdf(mf_vec3 wo, mf_vec3 wi, mf_real alpha)
{
    mf_real R, d = mf__sheen_eval(wo, wi, alpha, &R);
    return d > MF_R(0.0) ? mf__cap(R * d / wi.z) : MF_R(0.0);
}

MFDEF mf_real mf_sheen_pdf(mf_vec3 wo, mf_vec3 wi, mf_real alpha)
{
    mf_real R, d = mf__sheen_eval(wo, wi, alpha, &R);
    return R > MF_R(0.0) ? d : MF_R(0.0);
}

MFDEF mf_sample mf_sheen_sample(mf_vec3 wo, mf_real alpha, mf_real u1, mf_real u2)
{
    mf_real A, B, R, c, s, l, pdf;
    mf_vec3 o, w;
    mf_sample r;
    if (!(wo.z > MF_R(0.0)) || !(wo.z < MF_BIG) || !(alpha == alpha)) return mf__no_sample();
    mf__sheen_lookup(wo.z, alpha, &A, &B, &R);
    if (!(R > MF_R(0.0))) return mf__no_sample();
    mf__sheen_frame(wo, &c, &s);
    /* o.z > 0 (u1 = 1 is read as MF_U_MAX); M o = ((o.x - B o.z) / A, o.y / A, o.z)
     * keeps z, so wi is above the horizon */
    o = mf__sample_cosine(u1, u2);
    w = mf_vec3_make((o.x - B * o.z) / A, o.y / A, o.z);
    l = MF_SQRT(mf_dot(w, w));
    if (!(l > MF_R(0.0)) || !(l < MF_BIG)) return mf__no_sample();
    w = mf_scale(w, MF_R(1.0) / l);
    pdf = mf__sheen_ltc(A, B, w);
    if (!(pdf > MF_R(0.0)) || !(w.z > MF_R(0.0))) return mf__no_sample();
    r.wi = mf_vec3_make(c * w.x - s * w.y, s * w.x + c * w.y, w.z);
    r.pdf = pdf;
    r.weight = R;   /* f cos / pdf: the lobe is R times the LTC */
    r.lobe = MF_LOBE_REFLECTION;
    return r;
}

MFDEF mf_real mf_sheen_albedo(mf_real cos_theta_o, mf_real alpha)
{
    mf_real A, B, R;
    if (!(cos_theta_o > MF_R(0.0)) || !(alpha == alpha)) return MF_R(0.0);
    mf__sheen_lookup(cos_theta_o, alpha, &A, &B, &R);
    return mf_min(R, MF_R(1.0));
}
#endif
