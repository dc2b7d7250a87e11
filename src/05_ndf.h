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
 *   Charlie  (Estevez & Kulla 2017, Eq. 2): the sheen distribution
 *            (2 + 1/alpha) sin^{1/alpha}(theta) / (2 pi), isotropic (06_kind_charlie.h).
 * mf_ndf is a small value type; build it once per shading point and pass it by
 * const pointer. Every generic operation (mf_D, mf_lambda, mf_G1, mf_G2,
 * mf_D_visible, mf_sample_D, mf_sample_visible, mf_brdf...) accepts every kind. */

/* The kinds of mf_ndf, in the order of their mf_ndf_type values
 * (MF_NDF_BECKMANN = 0, MF_NDF_GGX, MF_NDF_GTR, MF_NDF_STUDENT_T, MF_NDF_LEADR
 * = the non-centered Beckmann of LEADR moments, MF_NDF_TABULATED,
 * MF_NDF_CHARLIE = the sheen of Estevez & Kulla 2017). Each line
 * X(NAME, name, INL, CEN, ISO, TR, ETAB, AXES, PREP) is one module
 * src/06_kind_<name>.h, which defines
 *   - its parameter struct mf_ndf_<name> (part @decl), stored in mf_ndf.p.<name>,
 *     at most 32 bytes in float (a pointer and six mf_real), so that mf_ndf
 *     stays within 64; anything larger lives in a built object it points to
 *     (mf_tabulated, mf_gtr_table);
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
 *               w.z >= 0; the zero vector when there is none;
 *   - and what its traits promise. The traits are the line's digits; no module
 *     but this one and the kind's own tests a kind by name (tests/kind_names_check.sh):
 *     INL  0: the generic front ends (mf_D, mf_lambda, mf_sample_D,
 *          mf_sample_visible) reach the kind through the cold dispatch (declared
 *          below, defined in 07_ndf_dispatch.h after the kinds);
 *          1: they inline its D, Lambda and NDF sampling, which are then
 *          MF_FORCE_INLINE, with mf__<name>_sample_D_dir (the NDF sample before
 *          normalization); 2: its visible normals too, with
 *          mf__<name>_sample_visible_dir (likewise). The kinds of INL 2 are
 *          tested first.
 *     CEN  1: centred, the mean slope is 0; 0: the kind defines
 *          void mf__<name>_mean_slope(const mf_ndf *d, mf_real *mx, mf_real *my),
 *          MF_FORCE_INLINE (the mean surface is tilted: projected area and BSDF
 *          weights use it).
 *     ISO  visible normals by the numerical inversion of 05_numeric_vndf.h
 *          through the NDF-cos CDF of an isotropic distribution: 0 none; 1 of
 *          the kind's own D; 2 of its unit-roughness form, stretched by (ax, ay).
 *          The kind defines mf__<name>_tan2(d, t, q), mf__<name>_tail(d, tan2)
 *          and mf__<name>_vndf_p(d) (see 05_numeric_vndf.h).
 *     TR   1: Trowbridge-Reitz closed forms hold, 1 + Lambda(w) =
 *          |(ax w.x, ay w.y, w.z)| / (2 w.z) (one-division G2, the bounded
 *          visible-normal sampler of 11_brdf.h).
 *     ETAB the built-in energy table of 17_energy_table.h: 0 none, 1 GGX's,
 *          2 Beckmann's.
 *     AXES 1: untransformed with ax = ay, the distribution is isotropic.
 *     PREP 1: the kind has a built object that speeds it up (mf_<name>_table)
 *          which the library's own long computations (fits, tables, integrals)
 *          build when the distribution lacks it; the kind defines
 *          const mf_ndf *mf__<name>_prepare(const mf_ndf *d, mf_ndf *copy,
 *          mf_<name>_table *t): d itself, or copy, made from d and using t.
 * Adding a kind: write that module (copy 06_kind_ggx.h for the layout, or a
 * cold kind such as 06_kind_student_t.h), add its line here, and test it the
 * way tests/test_ndf.c tests the others. */
#define MF__NDF_KINDS(X) \
    X(BECKMANN,  beckmann,  1, 1, 0, 0, 2, 1, 0) \
    X(GGX,       ggx,       2, 1, 0, 1, 1, 1, 0) \
    X(GTR,       gtr,       0, 1, 1, 0, 0, 1, 1) \
    X(STUDENT_T, student_t, 0, 1, 2, 0, 0, 1, 0) \
    X(LEADR,     leadr,     0, 0, 0, 0, 0, 0, 0) \
    X(TABULATED, tabulated, 0, 1, 0, 0, 0, 0, 0) \
    X(CHARLIE,   charlie,   0, 1, 1, 0, 0, 1, 0)

#define MF__NDF_ENUM(N, n, inl, cen, iso, tr, et, ax, pp) MF_NDF_##N,
typedef enum mf_ndf_type { MF__NDF_KINDS(MF__NDF_ENUM) MF_NDF_KIND_COUNT } mf_ndf_type;
#undef MF__NDF_ENUM

/* A distribution: 64 bytes in float, 128 in double (tests/test_ndf.c checks
 * them). M^-1 is not stored: mf__ndf_Minv derives it from M and 1 / det M
 * (four products), mf__ndf_det |det M| from M. */
#define MF__NDF_PARAMS(N, n, inl, cen, iso, tr, et, ax, pp) mf_ndf_##n n;
typedef struct mf_ndf {
    unsigned char type;         /* mf_ndf_type */
    unsigned char transformed;  /* 1 when M (below) is not the identity */
    unsigned char mode;         /* the kind's own small integer (GTR: how its Lambda and
                                   visible normals are computed), 0 for the others */
    mf_real ax, ay;     /* slope-space roughness along x and y (GTR: ax = ay = alpha;
                           LEADR and tabulated: a characteristic scale, informative) */
    mf_mat2 M;          /* tangential transform of the microsurface */
    mf_real idet;       /* 1 / det M (signed) */
    union { MF__NDF_KINDS(MF__NDF_PARAMS) } p;   /* the kind's own parameters */
} mf_ndf;
#undef MF__NDF_PARAMS

/* Expansion by a trait's digit: MF__IF<d>(s) is s when d is nonzero; the
 * front ends' chains take one level of INL at a time. */
#define MF__IF0(s)
#define MF__IF1(s) s
#define MF__IF2(s) s
#define MF__IFNOT0(s) s
#define MF__IFNOT1(s)
#define MF__INL1_0(s)
#define MF__INL1_1(s) s
#define MF__INL1_2(s)
#define MF__INL2_0(s)
#define MF__INL2_1(s)
#define MF__INL2_2(s) s

/* The traits of kind t (an mf_ndf.type); an unknown kind has none. */
#define MF__NDF_OR_KNOWN(N, n, inl, cen, iso, tr, et, ax, pp) || t == MF_NDF_##N
#define MF__NDF_OR_TILTED(N, n, inl, cen, iso, tr, et, ax, pp) MF__IFNOT##cen(|| t == MF_NDF_##N)
#define MF__NDF_OR_TR(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##tr(|| t == MF_NDF_##N)
#define MF__NDF_OR_AXES(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##ax(|| t == MF_NDF_##N)
#define MF__NDF_IF_ISO(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##iso(if (t == MF_NDF_##N) return iso;)
#define MF__NDF_IF_ETAB(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##et(if (t == MF_NDF_##N) return et;)
/* 1 for the kinds of MF__NDF_KINDS */
MF_FORCE_INLINE int mf__ndf_known(int t) { return 0 MF__NDF_KINDS(MF__NDF_OR_KNOWN); }
/* 1 if the mean slope may be nonzero (CEN 0) */
MF_FORCE_INLINE int mf__ndf_tilted(int t) { return 0 MF__NDF_KINDS(MF__NDF_OR_TILTED); }
/* 1 where the Trowbridge-Reitz closed forms hold (TR) */
MF_FORCE_INLINE int mf__ndf_tr(int t) { return 0 MF__NDF_KINDS(MF__NDF_OR_TR); }
/* 1 if ax = ay makes the untransformed kind isotropic (AXES) */
MF_FORCE_INLINE int mf__ndf_axes(int t) { return 0 MF__NDF_KINDS(MF__NDF_OR_AXES); }
/* the numerical visible-normal inversion of the kind (ISO): 0, 1 or 2 */
MF_FORCE_INLINE int mf__ndf_iso(int t) { MF__NDF_KINDS(MF__NDF_IF_ISO) return 0; }
/* the kind's built-in energy table (ETAB): 0 none, 1 GGX's, 2 Beckmann's */
MF_FORCE_INLINE int mf__ndf_energy_table(int t) { MF__NDF_KINDS(MF__NDF_IF_ETAB) return 0; }
#undef MF__NDF_OR_KNOWN
#undef MF__NDF_OR_TILTED
#undef MF__NDF_OR_TR
#undef MF__NDF_OR_AXES
#undef MF__NDF_IF_ISO
#undef MF__NDF_IF_ETAB

/* M^-1 = adj(M) / det M (the products of mf_mat2_inverse) and |det M| of a
 * transformed distribution (the identity and 1 for the others, whose M is the
 * identity) */
MF_FORCE_INLINE mf_mat2 mf__ndf_Minv(const mf_ndf *d)
{
    return mf_mat2_make(d->M.m11 * d->idet, -d->M.m01 * d->idet, -d->M.m10 * d->idet, d->M.m00 * d->idet);
}
MF_FORCE_INLINE mf_real mf__ndf_det(const mf_ndf *d) { return MF_FABS(mf_mat2_det(d->M)); }

/* A distribution made fast for a long computation (trait PREP): the copy
 * and the built object it refers to; mf__ndf_prepare returns d itself, or
 * p->d. p must outlive the use of the result. */
#define MF__NDF_PREP_MEMBER(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##pp(mf_##n##_table n;)
typedef struct mf__ndf_prep {
    mf_ndf d;
    union { char none; MF__NDF_KINDS(MF__NDF_PREP_MEMBER) } s;
} mf__ndf_prep;
#undef MF__NDF_PREP_MEMBER

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
    d.type = (unsigned char)type;
    d.transformed = 0;
    d.mode = 0;
    d.ax = mf__clamp_alpha(ax);
    d.ay = mf__clamp_alpha(ay);
    d.M = mf_mat2_make(MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0));
    d.idet = MF_R(1.0);
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
 * modules 8-10 inline the kinds of INL > 0 and call these for the others;
 * defined in 07_ndf_dispatch.h, after the kinds).
 * An unknown kind gives 0, and no sample: the zero vector. */
MF_COLD mf_real mf__ndf_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__ndf_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__ndf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__ndf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
/* d, or a copy of it with its built object (trait PREP) in p */
MF_COLD const mf_ndf *mf__ndf_prepare(const mf_ndf *d, mf__ndf_prep *p);

/* The front ends' dispatch: the kinds of INL 2, then those of INL 1, inline,
 * then the cold dispatch. The inline kinds' functions, defined in their
 * modules (06), are declared here. */
#define MF__NDF_INL_DECL(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##inl( \
    MF_FORCE_INLINE mf_real mf__##n##_D(const mf_ndf *d, mf_vec3 wm); \
    MF_FORCE_INLINE mf_real mf__##n##_lambda(const mf_ndf *d, mf_vec3 w); \
    MF_FORCE_INLINE mf_vec3 mf__##n##_sample_D(const mf_ndf *d, mf_real u1, mf_real u2); \
    MF_FORCE_INLINE mf_vec3 mf__##n##_sample_D_dir(const mf_ndf *d, mf_real u1, mf_real u2);) \
    MF__INL2_##inl( \
    MF_FORCE_INLINE mf_vec3 mf__##n##_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2); \
    MF_FORCE_INLINE mf_vec3 mf__##n##_sample_visible_dir(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);)
MF__NDF_KINDS(MF__NDF_INL_DECL)
#undef MF__NDF_INL_DECL
#define MF__NDF_TRY_D2(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL2_##inl(if (d->type == MF_NDF_##N) return mf__##n##_D(d, wm);)
#define MF__NDF_TRY_D1(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL1_##inl(if (d->type == MF_NDF_##N) return mf__##n##_D(d, wm);)
#define MF__NDF_TRY_L2(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL2_##inl(if (d->type == MF_NDF_##N) return mf__##n##_lambda(d, w);)
#define MF__NDF_TRY_L1(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL1_##inl(if (d->type == MF_NDF_##N) return mf__##n##_lambda(d, w);)
#define MF__NDF_TRY_S2(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL2_##inl(if (d->type == MF_NDF_##N) return mf__##n##_sample_D(d, u1, u2);)
#define MF__NDF_TRY_S1(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL1_##inl(if (d->type == MF_NDF_##N) return mf__##n##_sample_D(d, u1, u2);)
#define MF__NDF_TRY_SD2(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL2_##inl(if (d->type == MF_NDF_##N) return mf__##n##_sample_D_dir(d, u1, u2);)
#define MF__NDF_TRY_SD1(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL1_##inl(if (d->type == MF_NDF_##N) return mf__##n##_sample_D_dir(d, u1, u2);)
#define MF__NDF_TRY_V2(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL2_##inl(if (d->type == MF_NDF_##N) return mf__##n##_sample_visible(d, w, u1, u2);)
#define MF__NDF_TRY_VD2(N, n, inl, cen, iso, tr, et, ax, pp) MF__INL2_##inl(if (d->type == MF_NDF_##N) return mf__##n##_sample_visible_dir(d, w, u1, u2);)
/* D of the untransformed distribution (homogeneous of degree -4 in wm) */
MF_FORCE_INLINE mf_real mf__ndf_D_inline(const mf_ndf *d, mf_vec3 wm)
{
    MF__NDF_KINDS(MF__NDF_TRY_D2) MF__NDF_KINDS(MF__NDF_TRY_D1)
    return mf__ndf_D(d, wm);
}
/* Lambda of the untransformed distribution (w of any length) */
MF_FORCE_INLINE mf_real mf__ndf_lambda_inline(const mf_ndf *d, mf_vec3 w)
{
    MF__NDF_KINDS(MF__NDF_TRY_L2) MF__NDF_KINDS(MF__NDF_TRY_L1)
    return mf__ndf_lambda(d, w);
}
/* NDF sampling, unit wm; and a positive multiple of it (the inline kinds skip
 * the normalization that a transform's M^-T would undo); u1, u2 in [0, 1] */
MF_FORCE_INLINE mf_vec3 mf__ndf_sample_D_inline(const mf_ndf *d, mf_real u1, mf_real u2)
{
    MF__NDF_KINDS(MF__NDF_TRY_S2) MF__NDF_KINDS(MF__NDF_TRY_S1)
    return mf__ndf_sample_D(d, u1, u2);
}
MF_FORCE_INLINE mf_vec3 mf__ndf_sample_D_dir_inline(const mf_ndf *d, mf_real u1, mf_real u2)
{
    MF__NDF_KINDS(MF__NDF_TRY_SD2) MF__NDF_KINDS(MF__NDF_TRY_SD1)
    return mf__ndf_sample_D(d, u1, u2);
}
/* visible normals, unit wm; and a positive multiple of it (zero vector: none) */
MF_FORCE_INLINE mf_vec3 mf__ndf_sample_visible_inline(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    MF__NDF_KINDS(MF__NDF_TRY_V2)
    return mf__ndf_sample_visible(d, w, u1, u2);
}
MF_FORCE_INLINE mf_vec3 mf__ndf_sample_visible_dir_inline(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    MF__NDF_KINDS(MF__NDF_TRY_VD2)
    return mf__ndf_sample_visible(d, w, u1, u2);
}
/* The mean slope of the untransformed distribution: (0, 0) for the centred
 * kinds (CEN 1) and unknown ones; inline (the front ends test CEN first). */
#define MF__NDF_MEAN_DECL(N, n, inl, cen, iso, tr, et, ax, pp) \
    MF__IFNOT##cen(MF_FORCE_INLINE void mf__##n##_mean_slope(const mf_ndf *d, mf_real *mx, mf_real *my);)
#define MF__NDF_TRY_MEAN(N, n, inl, cen, iso, tr, et, ax, pp) \
    MF__IFNOT##cen(if (d->type == MF_NDF_##N) { mf__##n##_mean_slope(d, mx, my); return; })
MF__NDF_KINDS(MF__NDF_MEAN_DECL)
MF_FORCE_INLINE void mf__ndf_mean_slope(const mf_ndf *d, mf_real *mx, mf_real *my)
{
    MF__NDF_KINDS(MF__NDF_TRY_MEAN)
    *mx = *my = MF_R(0.0);
}
#undef MF__NDF_MEAN_DECL
#undef MF__NDF_TRY_MEAN
#undef MF__NDF_TRY_D2
#undef MF__NDF_TRY_D1
#undef MF__NDF_TRY_L2
#undef MF__NDF_TRY_L1
#undef MF__NDF_TRY_S2
#undef MF__NDF_TRY_S1
#undef MF__NDF_TRY_SD2
#undef MF__NDF_TRY_SD1
#undef MF__NDF_TRY_V2
#undef MF__NDF_TRY_VD2
/* @cold */
/* The NDF-cos CDF inversion of the kinds of ISO > 0 (05_numeric_vndf.h): tan^2
 * at mass t from the pole (q = 1 - t beyond), the mass beyond tan2, and the
 * exponent p of the sampler's substitution; unknown kinds give 0, 0 and 4.
 * Defined with the dispatch (07_ndf_dispatch.h), after the kinds. */
MF_INLINE mf_real mf__ndf_iso_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_INLINE mf_real mf__ndf_iso_tail(const mf_ndf *d, mf_real tan2);
MF_INLINE mf_real mf__ndf_iso_p(const mf_ndf *d);
