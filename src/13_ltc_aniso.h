/* @api */
/* ======================================================================== */
/* == 13a. LTC of anisotropic GGX                                           */
/* ======================================================================== */
/* Aakash KT, Heitz, Dupuy, Narayanan 2022 (I3D, "Bringing Linearly
 * Transformed Cosines to Anisotropic GGX"): without a plane of symmetry the
 * LTC's matrix has all nine entries. Stored here as M^-1 up to the two
 * invariances of an LTC (a scale, and a rotation about z applied on the
 * left of M^-1): M^-1 = [p q r; q s t; u v w] with the upper-left 2x2 block
 * symmetric positive definite (the polar factor; unique and smooth) and of
 * determinant 1, so s = (1 + q^2) / p: seven numbers per entry, plus the
 * albedo. Symmetries of GGX cut the domain: x -> -x and y -> -y mirror the
 * view into azimuth [0, pi/2] (conjugating M^-1 by the mirror keeps its
 * orientation, so one-sided lights stay right), and swapping alpha_x and
 * alpha_y is the exchange of x and y (likewise a conjugation), so that the
 * table holds alpha_x >= alpha_y only. Its last slice, alpha_y = alpha_x, is
 * the isotropic table (mf_ltc_ggx) rotated to the view's azimuth. Lookups
 * blend each node's M (not M^-1), as the published table does. */

/* The public functions (mf_ltc_ggx_aniso, mf_ltc_ggx_aniso_albedo,
 * mf_ltc_ggx_aniso_table, mf_ltc_ggx_aniso_export_rgba16f) are declared in
 * 13_ltc.h with the other built-in tables. */
/* @impl */
#ifndef MF_NO_LTC_TABLE
static const unsigned short *mf__ltc_ggx_aniso_data(int dims[4]);   /* 14_ltc_table_aniso.h */

/* IEEE binary16 bits to a real (finite input; the table holds no Inf/NaN) */
static mf_real mf__half_value(unsigned short h)
{
    union { float f; unsigned int u; } v;
    unsigned int e = (h >> 10) & 31u, m = h & 1023u;
    float r;
    if (e == 0u) r = (float)m * 5.9604644775390625e-8f;   /* subnormal: m 2^-24 */
    else { v.u = ((e + 112u) << 23) | (m << 13); r = v.f; }
    return (mf_real)((h & 0x8000u) ? -r : r);
}

/* The isotropic entry in the aniso form: mf_ltc_ggx's M^-1 = [a 0 b; 0 1 0;
 * c 0 d] (wo in the xz plane) rotated to the azimuth (cp, sp) = (cos, sin),
 * R M^-1 R^T, scaled to a block determinant of 1 (divided by sqrt(a)). */
static void mf__ltc_aniso_iso_node(mf_real ct, mf_real alpha, mf_real cp, mf_real sp, mf_real *m, mf_real *alb)
{
    mf_ltc l = mf__ltc_builtin(mf__ltc_ggx_data, ct, alpha, alb, 0);
    mf_real a = l.Minv[0], b = l.Minv[2], c = l.Minv[6], d = l.Minv[8], k, y = l.Minv[4];
    if (y > MF_R(0.0)) { a /= y; b /= y; c /= y; d /= y; }   /* the table form has y = 1 */
    k = a > MF_R(0.0) ? MF_R(1.0) / MF_SQRT(a) : MF_R(1.0);
    /* R diag-block [a 0; 0 1] R^T, R = [cp -sp; sp cp] */
    m[0] = (a * cp * cp + sp * sp) * k; m[1] = (a - MF_R(1.0)) * cp * sp * k; m[2] = b * cp * k;
    m[3] = m[1];                       m[4] = (a * sp * sp + cp * cp) * k; m[5] = b * sp * k;
    m[6] = c * cp * k;                 m[7] = c * sp * k;                  m[8] = d * k;
}

/* M of a node's M^-1, scaled to a last column of unit length (the published
 * table's normalization); 0 if singular */
static int mf__ltc_aniso_node_m(const mf_real *a, mf_real *M)
{
    /* the adjugate: M up to the positive factor 1 / det, which the scaling drops */
    mf_real n, det;
    int k;
    M[0] = a[4] * a[8] - a[5] * a[7]; M[1] = a[2] * a[7] - a[1] * a[8]; M[2] = a[1] * a[5] - a[2] * a[4];
    M[3] = a[5] * a[6] - a[3] * a[8]; M[4] = a[0] * a[8] - a[2] * a[6]; M[5] = a[2] * a[3] - a[0] * a[5];
    M[6] = a[3] * a[7] - a[4] * a[6]; M[7] = a[1] * a[6] - a[0] * a[7]; M[8] = a[0] * a[4] - a[1] * a[3];
    det = a[0] * M[0] + a[1] * M[3] + a[2] * M[6];
    n = MF_SQRT(M[2] * M[2] + M[5] * M[5] + M[8] * M[8]);
    if (!(det > MF_R(0.0)) || !(n > MF_R(0.0)) || !(n < MF_BIG)) return 0;
    n = MF_R(1.0) / n;
    for (k = 0; k < 9; ++k) M[k] *= n;
    return 1;
}

/* M (9 entries) and the albedo for ax >= ay and a view (x, y >= 0):
 * multilinear in (sqrt(1 - cos theta), azimuth, sqrt(ax), sqrt(ay / ax)) of
 * each node's M (mf__ltc_aniso_node_m). Blending M moves the lobe's axis M z
 * linearly between nodes; blending the stored M^-1 instead bends thin lobes
 * (large anisotropy) between near-normal views (docs/ACCURACY.md).
 * snap: the nearest node instead (the fallback below) */
static void mf__ltc_aniso_core(mf_real ct, mf_real cp, mf_real sp, mf_real ax, mf_real v, int snap, mf_real *m, mf_real *alb)
{
    int dims[4], nt, np, na, nv, i[3], c, k, iv;
    const unsigned short *t = mf__ltc_ggx_aniso_data(dims);
    mf_real x[3], f[3], fv, xv, lo[9], loa = MF_R(0.0), hia = MF_R(0.0), ph;
    nt = dims[0]; np = dims[1]; na = dims[2]; nv = dims[3];
    ph = MF_ATAN2(sp, cp) * MF_R(0.63661977236758134308);   /* azimuth / (pi/2) */
    x[0] = MF_SQRT(MF_R(1.0) - ct) * (mf_real)(nt - 1);
    x[1] = mf_clamp(ph, MF_R(0.0), MF_R(1.0)) * (mf_real)(np - 1);
    x[2] = MF_SQRT(ax) * (mf_real)(na - 1);
    xv = MF_SQRT(v) * (mf_real)nv;
    for (k = 0; k < 3; ++k) {
        int n = k == 0 ? nt : (k == 1 ? np : na);
        i[k] = (int)x[k];
        if (i[k] > n - 2) i[k] = n - 2;
        f[k] = mf_clamp(x[k] - (mf_real)i[k], MF_R(0.0), MF_R(1.0));
        if (snap) f[k] = f[k] < MF_R(0.5) ? MF_R(0.0) : MF_R(1.0);
    }
    iv = (int)xv;
    if (iv > nv - 1) iv = nv - 1;
    fv = mf_clamp(xv - (mf_real)iv, MF_R(0.0), MF_R(1.0));
    if (snap) fv = fv < MF_R(0.5) ? MF_R(0.0) : MF_R(1.0);
    for (k = 0; k < 9; ++k) m[k] = lo[k] = MF_R(0.0);
    /* the two v slices: iv from the table, iv + 1 from it or (= nv) the isotropic table */
    for (c = 0; c < 16; ++c) {
        int dt = c & 1, dp = (c >> 1) & 1, da = (c >> 2) & 1, dv = c >> 3, j = iv + dv;
        mf_real w = (dt ? f[0] : MF_R(1.0) - f[0]) * (dp ? f[1] : MF_R(1.0) - f[1]) * (da ? f[2] : MF_R(1.0) - f[2]);
        const unsigned short *e;
        mf_real p, q, mi[9], nm[9], *o = dv ? m : lo;
        if (j >= nv) continue;
        if (w == MF_R(0.0)) continue;
        e = t + 8 * ((((size_t)(i[2] + da) * (size_t)nv + (size_t)j) * (size_t)nt + (size_t)(i[0] + dt)) * (size_t)np + (size_t)(i[1] + dp));
        p = mf__half_value(e[0]); q = mf__half_value(e[1]);
        mi[0] = p; mi[1] = q; mi[2] = mf__half_value(e[2]);
        mi[3] = q; mi[4] = (MF_R(1.0) + q * q) / p; mi[5] = mf__half_value(e[3]);
        mi[6] = mf__half_value(e[4]); mi[7] = mf__half_value(e[5]); mi[8] = mf__half_value(e[6]);
        if (!mf__ltc_aniso_node_m(mi, nm)) continue;   /* not in the built-in table (every node has det > 0) */
        for (k = 0; k < 9; ++k) o[k] += w * nm[k];
        if (dv) hia += w * mf__half_value(e[7]);
        else loa += w * mf__half_value(e[7]);
    }
    if (iv + 1 >= nv) {   /* the isotropic slice at the exact view and alpha */
        mf_real mi[9];
        mf__ltc_aniso_iso_node(ct, ax, cp, sp, mi, &hia);
        if (!mf__ltc_aniso_node_m(mi, m)) for (k = 0; k < 9; ++k) m[k] = (k % 4 == 0) ? MF_R(1.0) : MF_R(0.0);
    }
    for (k = 0; k < 9; ++k) m[k] = (MF_R(1.0) - fv) * lo[k] + fv * m[k];
    if (alb) *alb = (MF_R(1.0) - fv) * loa + fv * hia;
}

static mf_ltc mf__ltc_aniso(mf_vec3 wo, mf_real ax, mf_real ay, mf_real *alb)
{
    mf_real m[9], len, ct, x, y, a, v, sw;
    int k, mx, my, swap;
    if (alb) *alb = MF_R(0.0);
    if (!(wo.x == wo.x) || !(wo.y == wo.y) || !(wo.z == wo.z) || !(ax == ax) || !(ay == ay)) {
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        return mf_ltc_from_matrix9(I9);
    }
    ax = mf_clamp(ax, MF_LTC_ALPHA_MIN, MF_R(1.0)); ay = mf_clamp(ay, MF_LTC_ALPHA_MIN, MF_R(1.0));
    swap = ax < ay;
    if (swap) { sw = ax; ax = ay; ay = sw; x = wo.y; y = wo.x; }
    else { x = wo.x; y = wo.y; }
    mx = x < MF_R(0.0); my = y < MF_R(0.0);
    x = MF_FABS(x); y = MF_FABS(y);
    if (!(x < MF_BIG) || !(y < MF_BIG) || !(MF_FABS(wo.z) < MF_BIG)) { x = mf_min(x, MF_BIG); y = mf_min(y, MF_BIG); }
    len = MF_SQRT(x * x + y * y + wo.z * wo.z);
    ct = len > MF_R(0.0) && len < MF_BIG ? mf_clamp(wo.z / len, MF_R(0.0), MF_R(1.0)) : MF_R(1.0);
    {   /* unit azimuth (1, 0) at normal view */
        mf_real r = MF_SQRT(x * x + y * y);
        if (r > MF_R(0.0) && r < MF_BIG) { x /= r; y /= r; }
        else { x = MF_R(1.0); y = MF_R(0.0); }
    }
    a = ax; v = mf_clamp(ay / ax, MF_R(0.0), MF_R(1.0));
    mf__ltc_aniso_core(ct, x, y, a, v, 0, m, alb);
    {   /* every node preserves orientation (det M > 0), but a blend of
         * two differently sheared fits of a very thin lobe could cross 0:
         * then the nearest node */
        mf_real d = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
        if (!(d > MF_R(0.0))) mf__ltc_aniso_core(ct, x, y, a, v, 1, m, alb);
    }
    /* undo the mirrors (conjugation by diag(-1, 1, 1), diag(1, -1, 1)), then the swap */
    if (mx) { m[1] = -m[1]; m[3] = -m[3]; m[2] = -m[2]; m[6] = -m[6]; }
    if (my) { m[1] = -m[1]; m[3] = -m[3]; m[5] = -m[5]; m[7] = -m[7]; }
    if (swap) {
        mf_real s[9];
        for (k = 0; k < 9; ++k) s[k] = m[k];
        m[0] = s[4]; m[1] = s[3]; m[2] = s[5];
        m[3] = s[1]; m[4] = s[0]; m[5] = s[2];
        m[6] = s[7]; m[7] = s[6]; m[8] = s[8];
    }
    if (alb && !(*alb >= MF_R(0.0))) *alb = MF_R(0.0);
    return mf_ltc_from_matrix9(m);
}

MFDEF mf_ltc mf_ltc_ggx_aniso(mf_vec3 wo, mf_real ax, mf_real ay) { return mf__ltc_aniso(wo, ax, ay, 0); }
MFDEF mf_real mf_ltc_ggx_aniso_albedo(mf_vec3 wo, mf_real ax, mf_real ay)
{
    mf_real a;
    mf__ltc_aniso(wo, ax, ay, &a);
    return a;
}
MFDEF const unsigned short *mf_ltc_ggx_aniso_table(int dims[4])
{
    int d[4];
    const unsigned short *t = mf__ltc_ggx_aniso_data(d);
    if (dims) { dims[0] = d[0]; dims[1] = d[1]; dims[2] = d[2]; dims[3] = d[3]; }
    return t;
}
MFDEF mf_result mf_ltc_ggx_aniso_export_rgba16f(unsigned short *tex1, unsigned short *tex2)
{
    int d[4], ia, iv, it, ip, k;
    const unsigned short *t = mf__ltc_ggx_aniso_data(d);
    size_t width = (size_t)d[1] * (size_t)d[0];
    if (!tex1 || !tex2) return MF_ERROR_INVALID_ARGUMENT;
    for (ia = 0; ia < d[2]; ++ia)
        for (iv = 0; iv < d[3]; ++iv)
            for (it = 0; it < d[0]; ++it)
                for (ip = 0; ip < d[1]; ++ip) {
                    size_t e = 8 * ((((size_t)ia * (size_t)d[3] + (size_t)iv) * (size_t)d[0] + (size_t)it) * (size_t)d[1] + (size_t)ip);
                    size_t o = 4 * (((size_t)ia * (size_t)d[3] + (size_t)iv) * width + (size_t)it * (size_t)d[1] + (size_t)ip);
                    for (k = 0; k < 4; ++k) { tex1[o + (size_t)k] = t[e + (size_t)k]; tex2[o + (size_t)k] = t[e + 4 + (size_t)k]; }
                }
    return MF_SUCCESS;
}
#endif
