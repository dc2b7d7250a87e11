/* @optional MF_NO_IBM */
/* @api */
/* ======================================================================== */
/* == 15d. Inverse Bin Map: the filtered glint BRDF, its pdf, sampling      */
/* ======================================================================== */
/* The binned, truncated filtered BRDF of Eq. 5.13 over the bin weights of
 * 15_ibm_3_traverse.h, each bin a Beckmann flake lobe around its mean
 * normal; its pdf (Eq. 5.16) and the sampler whose density it is. */
/* ---- the filtered BRDF (Eq. 5.13), its pdf (Eq. 5.16) and sampling ---- */

/* Filtered glint BRDF over the footprint (Eq. 5.13 with F = 1, no cosine):
 * sum over the bins around the half vector's bin of W_j C(wo, wi, t_j). Each
 * bin is represented by its mean normal t_j (mf_ibm_bin_normal). Reciprocal.
 * Truncated like Eq. 5.13 (measured truncation: docs/ACCURACY.md); for
 * small footprints the same sum is taken texel by texel (Eq. 5.2). 0 below
 * the horizon and for degenerate input. */
MF_COLD mf_real mf_ibm_brdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi);

/* Density of mf_ibm_sample per unit solid angle of wi (Eq. 5.16 with the
 * visible-normal density of each bin's lobe): sum of W_j D_wo(h; t_j) /
 * (4 wo.h) over the same bins as mf_ibm_brdf. It integrates to 1 minus the
 * no-sample mass of mf_ibm_sample. */
MF_COLD mf_real mf_ibm_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi);

/* mf_ibm_brdf and (in *pdf) mf_ibm_pdf from one weight query (MIS needs both). */
MF_COLD mf_real mf_ibm_brdf_and_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf);

/* Samples wi (Sec. 5.4.3): (u1, u2) a point of the footprint, uniform by
 * area, whose texel's bin j gives the normal t_j; (u3, u4) a visible normal m
 * of the flake Beckmann around t_j for wo; wi = reflect(wo, m). The zero vector
 * (no sample) when wo.t_j <= 0, wi is below the horizon, or the bin j is not
 * in the neighbourhood of beta(h) that mf_ibm_pdf sums (the truncation of Eq.
 * 5.13) - so the density of the returned wi is exactly mf_ibm_pdf. */
MF_COLD mf_sample mf_ibm_sample(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                mf_real u3, mf_real u4);
/* @cold */
/* The flake Beckmann Lambda of a direction at sin^2 s2 and cosine c from a
 * bin normal; 0 where it is below 3e-19 (a = cot / alpha > 6), which adds
 * nothing to 1 + Lambda in float or double (Eq. 84 ~ exp(-a^2) / (2 a^3
 * sqrt(pi))): its exp and erfc spared, the sums bit for bit the same. */
MF_INLINE mf_real mf__ibm_flake_lambda(mf_real alpha, mf_real s2, mf_real c)
{
    if (MF_R(36.0) * alpha * alpha * s2 < c * c) return MF_R(0.0);
    return mf_beckmann_lambda(alpha, alpha, mf_vec3_make(MF_SQRT(s2), MF_R(0.0), c));
}

/* mean normals the BRDF keeps from its facing test: the 21 bins of the
 * default radius, without a window-sized array on a GPU thread's stack */
#define MF__IBM_KEPT_NORMALS 32
/* The lobes of the bins around beta(h): for each non-empty bin j of the
 * neighbourhood with wo.t_j > 0, the texel contribution C (Eq. 3.29, no
 * Fresnel) and the sampling density of wi through j,
 *   C_j   = D(h; t_j) G2(wo, wi; t_j) G_x(wo, wi, t_j) / (4 wo.z wi.z),
 *   pdf_j = D_wo(h; t_j) / (4 wo.h) = D(h; t_j) / (4 (wo.t_j) (1 + Lambda(wo; t_j))),
 * with D, Lambda the flake Beckmann measured from t_j (angles through |a x t|
 * so that tiny alpha stays exact in float) and G_x the Smith G2 of the map's
 * distribution (mf_ibm_set_shadowing). Returns the weighted sums. */
MF_INLINE mf_real mf__ibm_lobes(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, int want_f,
                                mf_real *pdf)
{
    mf__ibm_set s;
    mf__ibm_fp p;
    mf_real gx = MF_R(-1.0), a = ibm->alpha, sf = MF_R(0.0), spdf = MF_R(0.0);
    mf_vec3 h;
    int r = ibm->radius, b = ibm->res, cx, cy, i, small, nb = 0, known = 0;
    int near[MF_IBM_MAX_WINDOW], ndx[MF_IBM_MAX_WINDOW], ndy[MF_IBM_MAX_WINDOW];
    mf_vec3 tn[MF__IBM_KEPT_NORMALS];   /* the set's first mean normals, where the facing test read them (known) */
    h = mf_normalize(mf_add(wo, wi));
    if (!(h.z > MF_R(0.0))) return MF_R(0.0);
    cx = mf__ibm_cell(h.x, b); cy = mf__ibm_cell(h.y, b);
    /* the bins that may hold texels of the footprint, found before any
     * footprint work (none: 0) - but for footprints of at most 16 texels,
     * which read their texels' bins for less (mf__ibm_direct_any) */
    small = f && (mf_real)ibm->width * (mf_real)ibm->height * (MF_FABS(f->ax) + MF_FABS(f->bx)) * (MF_FABS(f->ay) + MF_FABS(f->by)) <= MF_R(16.0);
    if (!small && (nb = mf__ibm_near_bins(ibm, f, cx, cy, near, ndx, ndy)) == 0) return MF_R(0.0);
    mf__ibm_footprint(ibm, f, &p);
    if (p.mode == MF__IBM_NONE) return MF_R(0.0);
    mf__ibm_set_init(&s, cx, cy, r);
    /* a footprint of a few texels: the bins of its texels */
    if (p.mode == MF__IBM_EXACT && p.few) { if (!mf__ibm_direct_any(ibm, &p, &s, 1)) return MF_R(0.0); }
    else {   /* those bins; for a footprint of many texels only those that
         * face wo (and wi when only f is wanted), which spares their
         * traversal (small ones are checked after their weights) */
        if (small && (nb = mf__ibm_near_bins(ibm, f, cx, cy, near, ndx, ndy)) == 0) return MF_R(0.0);
        known = p.mode == MF__IBM_EXACT && !p.direct;
        for (i = 0; i < nb; ++i) {
            if (known) {
                mf_vec3 t = mf_ibm_bin_normal(ibm, near[i]);
                if (!(mf_dot(wo, t) > MF_R(0.0)) || !(mf_dot(h, t) > MF_R(0.0))) continue;
                if (!pdf && !(mf_dot(wi, t) > MF_R(0.0))) continue;
                if (s.n < MF__IBM_KEPT_NORMALS) tn[s.n] = t;
            }
            mf__ibm_set_add(&s, ndx[i], ndy[i], near[i]);
        }
    }
    if (s.n == 0) return MF_R(0.0);
    /* the bins' mean normals, read below unless the facing test has: their
     * loads start now, under the weights' work */
    for (i = known ? MF__IBM_KEPT_NORMALS : 0; i < s.n; ++i) MF__PREFETCH(ibm->data + ibm->mean_at + (size_t)s.bin[i]);
    mf__ibm_weights(ibm, &p, &s);
    for (i = 0; i < s.n; ++i) {
        mf_vec3 t, xh, xo;
        mf_real co, ci, ch, d, lo;
        if (!(s.w[i] > MF_R(0.0))) continue;
        t = known && i < MF__IBM_KEPT_NORMALS ? tn[i] : mf_ibm_bin_normal(ibm, s.bin[i]);
        co = mf_dot(wo, t); ci = mf_dot(wi, t); ch = mf_dot(h, t);
        if (!(co > MF_R(0.0)) || !(ch > MF_R(0.0))) continue;
        xh = mf_cross(h, t); xo = mf_cross(wo, t);
        d = mf_beckmann_D(a, a, mf_vec3_make(MF_SQRT(mf_dot(xh, xh)), MF_R(0.0), ch));
        if (!(d > MF_R(0.0))) continue;
        lo = mf__ibm_flake_lambda(a, mf_dot(xo, xo), co);
        spdf += s.w[i] * d / (MF_R(4.0) * co * (MF_R(1.0) + lo));
        if (want_f && ci > MF_R(0.0)) {
            mf_vec3 xi = mf_cross(wi, t);
            mf_real li = mf__ibm_flake_lambda(a, mf_dot(xi, xi), ci);
            if (gx < MF_R(0.0))
                gx = ibm->has_shadow ? MF_R(1.0) / (MF_R(1.0) + mf_lambda(&ibm->shadow, wo) + mf_lambda(&ibm->shadow, wi)) : MF_R(1.0);
            sf += s.w[i] * d * gx / ((MF_R(1.0) + lo + li) * MF_R(4.0) * wo.z * wi.z);
        }
    }
    if (pdf) *pdf = mf_min(spdf, MF_BIG);
    return mf_min(sf, MF_BIG);
}

MF_COLD mf_real mf_ibm_brdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi)
{
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ibm_lobes(ibm, f, wo, wi, 1, (mf_real *)0);
}

MF_COLD mf_real mf_ibm_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi)
{
    mf_real pdf = MF_R(0.0);
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    mf__ibm_lobes(ibm, f, wo, wi, 0, &pdf);
    return pdf;
}

MF_COLD mf_real mf_ibm_brdf_and_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf)
{
    mf_real tmp = MF_R(0.0);
    if (!pdf) pdf = &tmp;
    *pdf = MF_R(0.0);
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ibm_lobes(ibm, f, wo, wi, 1, pdf);
}

/* the direction of mf_ibm_sample (the zero vector: none) */
MF_INLINE mf_vec3 mf__ibm_sample_dir(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                     mf_real u3, mf_real u4)
{
    mf_vec3 none = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), t, tt, tb, o, m, wi, h;
    mf__ibm_fp p;
    int tx, ty, j, dx, dy, r;
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0))) return none;
    mf__ibm_footprint(ibm, f, &p);
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    if (p.mode == MF__IBM_NONE) return none;
    if (p.mode == MF__IBM_POINT) { tx = p.tx; ty = p.ty; }
    else if (p.mode == MF__IBM_GLOBAL) {
        tx = (int)(u1 * (mf_real)ibm->width); ty = (int)(u2 * (mf_real)ibm->height);
    } else {
        mf_real x = p.cx + (u1 - MF_R(0.5)) * p.ax + (u2 - MF_R(0.5)) * p.bx;
        mf_real y = p.cy + (u1 - MF_R(0.5)) * p.ay + (u2 - MF_R(0.5)) * p.by;
        tx = (int)MF_FLOOR(x - (mf_real)ibm->width * MF_FLOOR(x / (mf_real)ibm->width));
        ty = (int)MF_FLOOR(y - (mf_real)ibm->height * MF_FLOOR(y / (mf_real)ibm->height));
    }
    if (tx < 0 || tx >= ibm->width) tx = 0;
    if (ty < 0 || ty >= ibm->height) ty = 0;
    j = mf_ibm_texel_bin(ibm, tx, ty);
    t = mf_ibm_bin_normal(ibm, j);
    if (!(mf_dot(wo, t) > MF_R(0.0))) return none;
    { mf_basis fr_ = mf_basis_from_normal(t); tt = fr_.t; tb = fr_.b; }
    o = mf_vec3_make(mf_dot(wo, tt), mf_dot(wo, tb), mf_dot(wo, t));
    m = mf_beckmann_sample_visible(ibm->alpha, ibm->alpha, o, u3, u4);
    m = mf_add(mf_add(mf_scale(tt, m.x), mf_scale(tb, m.y)), mf_scale(t, m.z));
    wi = mf_reflect(wo, m);
    if (!(wi.z > MF_R(0.0))) return none;
    h = mf_normalize(mf_add(wo, wi));
    if (!(h.z > MF_R(0.0))) return none;
    /* the pdf sums the bins around beta(h) only: outside, no sample */
    r = ibm->radius;
    dx = j % ibm->res - mf__ibm_cell(h.x, ibm->res);
    dy = j / ibm->res - mf__ibm_cell(h.y, ibm->res);
    if (dx * dx + dy * dy > r * (r + 1)) return none;
    {
        mf_real ch = mf_dot(h, t);
        mf_vec3 xh = mf_cross(h, t);
        if (!(ch > MF_R(0.0)) || !(mf_beckmann_D(ibm->alpha, ibm->alpha, mf_vec3_make(MF_SQRT(mf_dot(xh, xh)), MF_R(0.0), ch)) > MF_R(0.0)))
            return none;
    }
    return wi;
}
MF_COLD mf_sample mf_ibm_sample(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                mf_real u3, mf_real u4)
{
    mf_sample s = mf__no_sample();
    mf_real fv, pdf = MF_R(0.0);
    mf_vec3 wi = mf__ibm_sample_dir(ibm, f, wo, u1, u2, u3, u4);
    if (!(wi.z > MF_R(0.0))) return s;
    fv = mf_ibm_brdf_and_pdf(ibm, f, wo, wi, &pdf);
    if (!(pdf > MF_R(0.0))) return s;
    s.wi = wi;
    s.pdf = pdf;
    s.weight = mf_min(fv * wi.z / pdf, MF_BIG);
    s.lobe = MF_LOBE_REFLECTION;
    return s;
}
