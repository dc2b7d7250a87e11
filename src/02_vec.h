/* @decl */
typedef struct mf_vec3 { mf_real x, y, z; } mf_vec3;
typedef struct mf_mat2 { mf_real m00, m01, m10, m11; } mf_mat2; /* row-major */
/* An orthonormal, right-handed shading frame: t (tangent, the x axis of the
 * local frame, along which alpha_x applies), b = n x t, n (the z axis). */
typedef struct mf_basis { mf_vec3 t, b, n; } mf_basis;
/* What a sampler returns (0.4): the direction wi, its density per unit solid
 * angle, the weight f |wi.z| / pdf with the lobe's own f (Fresnel where the
 * lobe includes it) and the side it went to. No sample: lobe MF_LOBE_NONE,
 * wi = 0, pdf = 0, weight = 0. */
typedef enum mf_lobe { MF_LOBE_NONE = 0, MF_LOBE_REFLECTION = 1, MF_LOBE_TRANSMISSION = 2 } mf_lobe;
typedef struct mf_sample { mf_vec3 wi; mf_real pdf; mf_real weight; int lobe; } mf_sample;
/* Which quantity a path carries through a refraction: radiance (the
 * transmitted value carries 1/eta^2 of the solid-angle compression) or
 * importance (adjoint transport: no such factor). */
typedef enum mf_transport { MF_RADIANCE = 0, MF_IMPORTANCE = 1 } mf_transport;
/* @api */
/* ======================================================================== */
/* == 2. Vectors and frames                                                 */
/* ======================================================================== */

MF_FORCE_INLINE mf_vec3 mf_vec3_make(mf_real x, mf_real y, mf_real z)
{
    mf_vec3 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}
/* The empty record: no sample. */
MF_FORCE_INLINE mf_sample mf__no_sample(void)
{
    mf_sample s;
    s.wi = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    s.pdf = s.weight = MF_R(0.0);
    s.lobe = MF_LOBE_NONE;
    return s;
}
MF_FORCE_INLINE mf_real mf_dot(mf_vec3 a, mf_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
MF_FORCE_INLINE mf_vec3 mf_add(mf_vec3 a, mf_vec3 b) { return mf_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
MF_FORCE_INLINE mf_vec3 mf_scale(mf_vec3 a, mf_real s) { return mf_vec3_make(a.x * s, a.y * s, a.z * s); }
MF_FORCE_INLINE mf_vec3 mf_cross(mf_vec3 a, mf_vec3 b)
{
    return mf_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* x clamped to [lo, hi] (lo <= hi); NaN gives lo. A max, then a min: on
 * x86 a compare and branch and a minss (constant bounds), where a nested
 * test compiles to a compare and blends at -march=native (4-7% of GGX
 * mf_brdf and both visible-normal samplers there) */
MF_FORCE_INLINE mf_real mf_clamp(mf_real x, mf_real lo, mf_real hi)
{
    x = x > lo ? x : lo;
    return x < hi ? x : hi;
}
MF_FORCE_INLINE mf_real mf_max(mf_real a, mf_real b) { return a > b ? a : b; }
MF_FORCE_INLINE mf_real mf_min(mf_real a, mf_real b) { return a < b ? a : b; }
/* mf_max for an a that is never NaN (a NaN a would be returned; a -0 a stays
 * -0 against b = +0): against a constant b gcc compiles this form to maxss,
 * mf_max's to a compare and blend at -march=native */
MF_FORCE_INLINE mf_real mf__max_num(mf_real a, mf_real b) { return a < b ? b : a; }
/* 1 if x is finite, read from its bits: -ffast-math (__FAST_MATH__) lets the
 * compiler assume that no value is NaN or Inf and fold x == x, x - x == 0 or
 * isnan(x) to true; the validation of data that may index memory uses this. */
MF_INLINE int mf__finite_bits(mf_real x)
{
#ifdef MF_USE_DOUBLE
    union { double d; unsigned char c[8]; } v;
    union { unsigned int i; unsigned char c[4]; } e;
    unsigned int hi;
    v.d = x;
    e.i = 1u;
    hi = e.c[0] == 1u ? ((unsigned int)v.c[7] << 8 | v.c[6]) : ((unsigned int)v.c[0] << 8 | v.c[1]);
    return (hi & 0x7ff0u) != 0x7ff0u;
#else
    union { float f; unsigned int u; } v;
    v.f = x;
    return (v.u & 0x7f800000u) != 0x7f800000u;
#endif
}
/* x capped at MF_BIG; NaN becomes 0 (the results that may overflow float) */
MF_FORCE_INLINE mf_real mf__cap(mf_real x) { return x < MF_BIG ? x : (x == x ? MF_BIG : MF_R(0.0)); }

/* Unit vector along v; the zero vector when v is zero (or not finite). */
MF_FORCE_INLINE mf_vec3 mf_normalize(mf_vec3 v)
{
    mf_real l2 = mf_dot(v, v);
    if (!(l2 > MF_R(0.0)) || !(l2 < MF_BIG)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return mf_scale(v, MF_R(1.0) / MF_SQRT(l2));
}

/* Mirror reflection of w about the unit normal m: 2 (w.m) m - w. */
MF_FORCE_INLINE mf_vec3 mf_reflect(mf_vec3 w, mf_vec3 m)
{
    return mf_add(mf_scale(m, MF_R(2.0) * mf_dot(w, m)), mf_scale(w, MF_R(-1.0)));
}

/* 2x2 matrices, row-major: M = [m00 m01; m10 m11] acts on column vectors. */
MF_FORCE_INLINE mf_mat2 mf_mat2_make(mf_real m00, mf_real m01, mf_real m10, mf_real m11)
{
    mf_mat2 m;
    m.m00 = m00; m.m01 = m01; m.m10 = m10; m.m11 = m11;
    return m;
}
MF_INLINE mf_mat2 mf_mat2_mul(mf_mat2 a, mf_mat2 b)
{
    return mf_mat2_make(a.m00 * b.m00 + a.m01 * b.m10, a.m00 * b.m01 + a.m01 * b.m11,
                        a.m10 * b.m00 + a.m11 * b.m10, a.m10 * b.m01 + a.m11 * b.m11);
}
MF_INLINE mf_real mf_mat2_det(mf_mat2 a) { return a.m00 * a.m11 - a.m01 * a.m10; }
MF_INLINE mf_mat2 mf_mat2_transpose(mf_mat2 a) { return mf_mat2_make(a.m00, a.m10, a.m01, a.m11); }
/* The inverse; the zero matrix when a is singular or not finite. */
MF_INLINE mf_mat2 mf_mat2_inverse(mf_mat2 a)
{
    mf_real det = mf_mat2_det(a), inv;
    if (!(det != MF_R(0.0)) || !(MF_FABS(det) < MF_BIG)) return mf_mat2_make(0, 0, 0, 0);
    inv = MF_R(1.0) / det;
    return mf_mat2_make(a.m11 * inv, -a.m01 * inv, -a.m10 * inv, a.m00 * inv);
}
/* (M v.xy, v.z) and (M^T v.xy, v.z) */
MF_FORCE_INLINE mf_vec3 mf_mat2_apply(mf_mat2 a, mf_vec3 v)
{
    return mf_vec3_make(a.m00 * v.x + a.m01 * v.y, a.m10 * v.x + a.m11 * v.y, v.z);
}
MF_FORCE_INLINE mf_vec3 mf_mat2_apply_transpose(mf_mat2 a, mf_vec3 v)
{
    return mf_vec3_make(a.m00 * v.x + a.m10 * v.y, a.m01 * v.x + a.m11 * v.y, v.z);
}

/* A direction with density max(0, w.z) / pi (cosine-weighted hemisphere,
 * Malley's method) from u1, u2 in [0, 1] (u1 = 1 read as MF_U_MAX, so
 * z > 0; NaN reads as 0). */
MF_INLINE mf_vec3 mf__sample_cosine(mf_real u1, mf_real u2)
{
    mf_real r, phi;
    u1 = mf_clamp(u1, MF_R(0.0), MF_U_MAX);
    u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));   /* NaN: 0 */
    r = MF_SQRT(u1);
    phi = MF_R(2.0) * MF_PI * u2;
    return mf_vec3_make(r * MF_COS(phi), r * MF_SIN(phi), MF_SQRT(mf_max(MF_R(1.0) - u1, MF_R(0.0))));
}

/* A shading frame around a unit normal n (t, b = n x t, n), branchless and
 * singularity-free (Duff et al. 2017, "Building an Orthonormal Basis,
 * Revisited", Listing 3). */
MF_INLINE mf_basis mf_basis_from_normal(mf_vec3 n)
{
    mf_basis f;
    mf_real s = n.z >= MF_R(0.0) ? MF_R(1.0) : MF_R(-1.0);
    mf_real a = MF_R(-1.0) / (s + n.z);
    mf_real c = n.x * n.y * a;
    f.t = mf_vec3_make(MF_R(1.0) + s * n.x * n.x * a, s * c, -s * n.x);
    f.b = mf_vec3_make(c, s + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

/* The shading frame of the normal n and a tangent: n normalized, the tangent
 * made orthogonal to it (Gram-Schmidt). When the tangent is zero, not finite
 * or parallel to n (its orthogonal part below 1e-4 of its length), any
 * orthonormal frame around n (mf_basis_from_normal); a zero or non-finite n gives the
 * identity frame. Orthonormal to float precision for every input. */
MF_INLINE mf_basis mf_basis_from(mf_vec3 n, mf_vec3 tangent)
{
    mf_basis f;
    mf_real tl2, pl2;
    mf_vec3 p;
    n = mf_normalize(n);
    if (!(n.x * n.x + n.y * n.y + n.z * n.z > MF_R(0.5))) n = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    f.n = n;
    tl2 = mf_dot(tangent, tangent);
    p = mf_add(tangent, mf_scale(n, -mf_dot(tangent, n)));
    pl2 = mf_dot(p, p);
    if (tl2 < MF_BIG && pl2 > MF_R(1e-8) * tl2 && pl2 > MF_R(0.0)) {
        f.t = mf_scale(p, MF_R(1.0) / MF_SQRT(pl2));
        f.t = mf_normalize(mf_add(f.t, mf_scale(n, -mf_dot(f.t, n))));   /* second pass: float */
        f.b = mf_cross(n, f.t);
    } else f = mf_basis_from_normal(n);
    return f;
}
/* The frame's coordinates of a world direction, and back. */
MF_INLINE mf_vec3 mf_to_local(const mf_basis *f, mf_vec3 w)
{
    return mf_vec3_make(mf_dot(w, f->t), mf_dot(w, f->b), mf_dot(w, f->n));
}
MF_INLINE mf_vec3 mf_to_world(const mf_basis *f, mf_vec3 w)
{
    return mf_add(mf_add(mf_scale(f->t, w.x), mf_scale(f->b, w.y)), mf_scale(f->n, w.z));
}
/* The frame the LTC functions expect (Heitz et al. 2016): n and the tangent
 * in the plane of n and wo (world), so that wo is (sin, 0, cos) locally with
 * a non-negative x. Any frame around n when wo is parallel to n. */
MF_INLINE mf_basis mf_basis_ltc(mf_vec3 n, mf_vec3 wo)
{
    return mf_basis_from(n, wo);
}
