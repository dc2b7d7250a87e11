/* @api */
/* ======================================================================== */
/* == 5. Distributions: the mf_ndf value type and its one dispatch point    */
/* ======================================================================== */
/* D(m) per unit solid angle, normalized so that integral D(m) (m.n) dm = 1
 * (thesis Eq. 3.5). Slopes: a microfacet m has slope (-m.x/m.z, -m.y/m.z).
 *   Beckmann (thesis Eq. C.1; anisotropic form Heitz 2014 Eq. 83)
 *   GGX      (thesis Eq. C.3, corrected: 1/(pi a^2 cos^4 (1 + tan^2/a^2)^2); Heitz 2014 Eq. 85)
 *   GTR      (Burley 2012; thesis Eq. C.5, Berry limit C.6), isotropic
 *   Student-t (Ribardiere et al. 2017): slopes follow a 2D Student t law,
 *            P22 = (1/(pi ax ay)) (1 + r^2/(gamma-1))^-gamma, r^2 = x^2/ax^2 + y^2/ay^2;
 *            gamma = 2 is GGX, gamma -> infinity is Beckmann.
 *   Tabulated (Ribardiere et al. 2019, Sec. 3): piecewise linear in theta through
 *            control points (Eq. 11), each curve normalized (Eq. 12); anisotropic
 *            from two curves D_x (phi = 0) and D_y (phi = pi/2) by Eq. 10. Built by
 *            mf_tabulated_build / mf_tabulated_from_ndf; any number
 *            of lobes. Lambda by the split integration of Eq. 13-14 (precomputed
 *            at build time, see mf__tab_lambda), NDF sampling by Eq. 15-18, visible
 *            normals by an exact inversion (mf__tab_sample_visible).
 * mf_ndf is a small value type; build it once per shading point and pass it by
 * const pointer. Every generic operation (mf_D, mf_lambda, mf_G1, mf_G2,
 * mf_D_visible, mf_sample_D, mf_sample_visible, mf_brdf...) accepts every kind. */

/* The kinds of mf_ndf, in the order of their mf_ndf_type values
 * (MF_NDF_BECKMANN = 0, MF_NDF_GGX, MF_NDF_GTR, MF_NDF_STUDENT_T, MF_NDF_LEADR
 * = the non-centered Beckmann of LEADR moments, MF_NDF_TABULATED). Each entry
 * X(NAME, name) is one module src/06_kind_<name>.h, which defines
 *   - its parameter struct mf_ndf_<name> (part @decl), stored in mf_ndf.p.<name>;
 *   - its constructor(s), which fill mf_ndf through mf__ndf_init;
 *   - the four functions the generic operations dispatch to, each for the
 *     untransformed distribution (transforms are applied around them):
 *       mf_real mf__<name>_D(const mf_ndf *d, mf_vec3 wm)     D, homogeneous of
 *               degree -4 in wm (equal to D for a unit wm), 0 for wm.z <= 0
 *       mf_real mf__<name>_lambda(const mf_ndf *d, mf_vec3 w) Smith Lambda, w of
 *               any length, finite
 *       mf_vec3 mf__<name>_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
 *               unit wm with density D(wm) wm.z
 *       mf_vec3 mf__<name>_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
 *               unit wm with density D_w(wm) for a view w of any length with
 *               w.z >= 0; the zero vector when there is none.
 * Adding a kind: write that module (copy 06_kind_ggx.h for the layout), add
 * its line here, and test it the way tests/test_ndf.c tests the others. */
#define MF__NDF_KINDS(X) \
    X(BECKMANN, beckmann) \
    X(GGX, ggx) \
    X(GTR, gtr) \
    X(STUDENT_T, student_t) \
    X(LEADR, leadr) \
    X(TABULATED, tabulated)

#define MF__NDF_ENUM(NAME, name) MF_NDF_##NAME,
typedef enum mf_ndf_type { MF__NDF_KINDS(MF__NDF_ENUM) MF_NDF_KIND_COUNT } mf_ndf_type;
#undef MF__NDF_ENUM

#define MF__NDF_PARAMS(NAME, name) mf_ndf_##name name;
typedef struct mf_ndf {
    int type;           /* mf_ndf_type */
    int transformed;    /* 1 when M (below) is not the identity */
    mf_real ax, ay;     /* slope-space roughness along x and y (GTR: ax = ay = alpha;
                           LEADR and tabulated: a characteristic scale, informative) */
    mf_mat2 M, Minv;    /* tangential transform of the microsurface and its inverse */
    mf_real det;        /* |det M| */
    union { MF__NDF_KINDS(MF__NDF_PARAMS) } p;   /* the kind's own parameters */
} mf_ndf;
#undef MF__NDF_PARAMS

MF_INLINE mf_real mf__clamp_alpha(mf_real a)
{
    return a > MF_ALPHA_MIN ? (a < MF_ALPHA_MAX ? a : MF_ALPHA_MAX) : MF_ALPHA_MIN;
}

/* Roughness conventions. Constructors take alpha, the slope scale of the
 * distribution (GGX, Beckmann: alpha^2 = mean tan^2 of Beckmann normals).
 * Perceptual roughness r (Burley 2012, Disney principled BRDF; glTF 2.0
 * metallic-roughness, Filament, UE4) maps to alpha = r^2; Beckmann written
 * with sigma, the standard deviation of the slope along one axis (a Gaussian
 * height field, LEADR's per-axis variance sigma^2), has alpha = sqrt(2) sigma.
 * Negative or NaN input gives 0 (which constructors clamp to their minimum). */
MF_INLINE mf_real mf_alpha_from_roughness(mf_real r) { return r > MF_R(0.0) ? mf_min(r * r, MF_BIG) : MF_R(0.0); }
MF_INLINE mf_real mf_roughness_from_alpha(mf_real alpha) { return alpha > MF_R(0.0) ? MF_SQRT(mf_min(alpha, MF_BIG)) : MF_R(0.0); }
MF_INLINE mf_real mf_beckmann_alpha_from_sigma(mf_real sigma)
{
    return sigma > MF_R(0.0) ? mf_min(sigma * MF_R(1.41421356237309505), MF_BIG) : MF_R(0.0);
}
MF_INLINE mf_real mf_beckmann_sigma_from_alpha(mf_real alpha)
{
    return alpha > MF_R(0.0) ? mf_min(alpha, MF_BIG) * MF_R(0.70710678118654752) : MF_R(0.0);
}

/* An untransformed distribution of the given kind and (clamped) roughness,
 * its parameters zeroed for the constructor to fill. */
MF_INLINE mf_ndf mf__ndf_init(int type, mf_real ax, mf_real ay)
{
    mf_ndf d;
    unsigned char *b = (unsigned char *)&d.p;
    size_t i;
    for (i = 0; i < sizeof d.p; ++i) b[i] = 0;
    d.type = type;
    d.ax = mf__clamp_alpha(ax);
    d.ay = mf__clamp_alpha(ay);
    d.transformed = 0;
    d.M = d.Minv = mf_mat2_make(MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0));
    d.det = MF_R(1.0);
    return d;
}

/* sum of squared scaled slopes times cos^2: m.x^2/ax^2 + m.y^2/ay^2 */
MF_FORCE_INLINE mf_real mf__q(mf_real ax, mf_real ay, mf_vec3 m)
{
    mf_real x = m.x / ax, y = m.y / ay;
    return x * x + y * y;
}

/* alpha_w^2 tan^2(theta) = 1/a^2, with w.z clamped so the horizon stays
 * finite, capped at MF_A2T2_MAX (alpha 1e4 under a stretch at the horizon
 * overflows float; NaN gives the cap too), so the Lambdas never see inf/inf */
#define MF_A2T2_MAX MF_R(1e30)
MF_FORCE_INLINE mf_real mf__a2t2(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real x = ax * w.x, y = ay * w.y;
    mf_real r = (x * x + y * y) / (w.z * w.z + MF_R(1e-30));   /* + not max: no select on the division's path */
    return r < MF_A2T2_MAX ? r : MF_A2T2_MAX;
}

/* The unstretched slope direction at the azimuth 2 pi u2 and squared unit
 * slope radius r2, stretched by (ax, ay), not normalized: (ax r cos, ay r
 * sin, 1), or (ax cos, ay sin, 0) where r2 overflows; and wm (normalized). */
MF_FORCE_INLINE mf_vec3 mf__slope_dir_u(mf_real ax, mf_real ay, mf_real r2, mf_real u2)
{
    mf_real cp, sp;
    mf__sincos_2pi(u2, &cp, &sp);
    if (!(r2 < MF_R(1e30))) return mf_vec3_make(ax * cp, ay * sp, MF_R(0.0));
    r2 = MF_SQRT(mf_max(r2, MF_R(0.0)));
    return mf_vec3_make(ax * r2 * cp, ay * r2 * sp, MF_R(1.0));
}
MF_FORCE_INLINE mf_vec3 mf__wm_from_slope_u(mf_real ax, mf_real ay, mf_real r2, mf_real u2)
{
    return mf_normalize(mf__slope_dir_u(ax, ay, r2, u2));
}

/* Stretch w into the unit-roughness configuration; returns cos and sin of its
 * polar angle and the cos/sin of its azimuth. */
MF_FORCE_INLINE void mf__stretch_view(mf_real ax, mf_real ay, mf_vec3 w, mf_real *cv, mf_real *sv,
                                mf_real *cp, mf_real *sp)
{
    mf_vec3 v = mf_normalize(mf_vec3_make(ax * w.x, ay * w.y, mf_max(w.z, MF_R(0.0))));
    mf_real s = MF_SQRT(v.x * v.x + v.y * v.y);
    *cv = v.z; *sv = s;
    if (s > MF_R(0.0)) { *cp = v.x / s; *sp = v.y / s; }
    else { *cp = MF_R(1.0); *sp = MF_R(0.0); }
}
/* The generic dispatch of the untransformed kinds (cold: the front ends in
 * modules 8-10 inline GGX and Beckmann and call these for the others). */
MF_COLD mf_real mf__ndf_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__ndf_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__ndf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__ndf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
/* @cold */
#define MF__NDF_CASE_D(NAME, name) case MF_NDF_##NAME: return mf__##name##_D(d, wm);
#define MF__NDF_CASE_LAMBDA(NAME, name) case MF_NDF_##NAME: return mf__##name##_lambda(d, w);
#define MF__NDF_CASE_SAMPLE_D(NAME, name) case MF_NDF_##NAME: return mf__##name##_sample_D(d, u1, u2);
#define MF__NDF_CASE_SAMPLE_VISIBLE(NAME, name) case MF_NDF_##NAME: return mf__##name##_sample_visible(d, w, u1, u2);
MF_COLD mf_real mf__ndf_D(const mf_ndf *d, mf_vec3 wm)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_D)
    default: return MF_R(0.0);
    }
}
MF_COLD mf_real mf__ndf_lambda(const mf_ndf *d, mf_vec3 w)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_LAMBDA)
    default: return MF_R(0.0);
    }
}
MF_COLD mf_vec3 mf__ndf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_SAMPLE_D)
    default: return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    }
}
MF_COLD mf_vec3 mf__ndf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_SAMPLE_VISIBLE)
    default: return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    }
}
#undef MF__NDF_CASE_D
#undef MF__NDF_CASE_LAMBDA
#undef MF__NDF_CASE_SAMPLE_D
#undef MF__NDF_CASE_SAMPLE_VISIBLE
