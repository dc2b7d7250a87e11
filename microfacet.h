/* microfacet.h - microfacet BRDF/NDF math in one dependency-free C header.
 * Version 0.1.0.  MIT licensed (see the end of this file).
 *
 * QUICK START
 *
 *     #include "microfacet.h"     // in every file that uses it
 *     // in exactly one C or C++ file, before the include:
 *     #define MICROFACET_IMPLEMENTATION
 *
 *     mf_ndf  d   = mf_ggx(0.3f, 0.1f);                    // anisotropic GGX
 *     mf_vec3 wo  = mf_vec3_make(0.3f, 0.2f, 0.93f);       // unit, local frame
 *     mf_vec3 wi  = mf_brdf_sample(&d, wo, u1, u2);        // wi.z <= 0: no sample
 *     mf_real f   = mf_brdf(&d, wo, wi);                   // D G2 / (4 |wo.z| |wi.z|)
 *     mf_real pdf = mf_brdf_pdf(&d, wo, wi);               // per solid angle of wi
 *     // or directly the sample weight f * wi.z / pdf = G2 / G1(wo):
 *     mf_real w   = mf_brdf_sample_weight(&d, wo, wi);
 *
 * TABLE OF CONTENTS  (modules in dependency order; search for "== n.")
 *
 *   == 1. Configuration and portability (mf_real, MF_HD, MF_INLINE, MFDEF, ...)
 *   == 2. Vectors and frames
 *   == 3. Fresnel
 *   == 4. Special functions (erf inverse, incomplete beta, stable helpers)
 *   == 5. Distributions: Beckmann, GGX, GTR, Student-t; the value type mf_ndf
 *   == 6. Linearly transformed microsurfaces: any 2x2 transform of any
 *         distribution, stretch anisotropy, deformation tracking; mf_D
 *   == 7. Smith masking: Lambda, G1, G2 (height-correlated, separable), D_visible
 *   == 8. Sampling: NDF (D cos) and visible normals (VNDF) for every distribution
 *   == 9. Specular microfacet BRDF: eval, sample, pdf
 *   == 10. Linearly Transformed Cosines: eval, sample, polygon integration with
 *          horizon clipping, vector form factor, sphere lights, multi-scale
 *          roughness
 *   == 11. Declarations of non-inline functions; implementation section
 *
 * CONVENTIONS
 *
 *   - Local shading frame: z is the macro normal n = (0,0,1); x is the tangent
 *     along which alpha_x is measured. Directions are unit vectors pointing away
 *     from the surface: wo toward the viewer, wi toward the light, wm a
 *     microfacet normal, wh the half vector.
 *   - Roughness alpha is the slope-space scale (GGX alpha; Beckmann alpha =
 *     sqrt(2) sigma). The core never squares or remaps it.
 *   - pdfs are per unit solid angle. Angles are radians.
 *   - Below the horizon, on back-facing microfacets and at degenerate inputs,
 *     functions return 0 (pdf 0, weight 0), never NaN or Inf. Samplers that
 *     cannot produce a sample return the zero vector (z = 0).
 *   - BRDF functions exclude Fresnel and the cosine unless the name says so.
 *
 * CLAMPS (documented domain of every parameter)
 *
 *   - alpha (every distribution) is clamped to [MF_ALPHA_MIN, MF_ALPHA_MAX]
 *     = [1e-4, 1e4]; NaN becomes MF_ALPHA_MIN. GTR alpha is clamped to
 *     [MF_ALPHA_MIN, 1] (the domain of Burley's distribution).
 *   - GTR gamma is clamped to [0, 4], the range of Dimov's exact masking
 *     formulas (thesis app. C.3). Student-t gamma is clamped to
 *     [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] = [1.55, 1000]
 *     (the mean slope, hence Lambda, exists only for gamma > 1.5).
 *   - Lambda(w) is symmetric in w.z (it uses |w.z|); at w.z = 0 it is large
 *     but finite (w.z is clamped to 1e-15 inside the slope).
 *
 * CONFIGURATION MACROS (define before including)
 *
 *   MF_USE_DOUBLE           mf_real is double (default float)
 *   MICROFACET_IMPLEMENTATION  emit the non-inline functions in this file
 *   MFDEF                   storage of non-inline functions (default extern)
 *   MF_MALLOC(n) / MF_FREE(p)  allocator pair (default malloc/free)
 *   MF_ASSERT(x)            internal assertions (default: nothing)
 *   MF_SQRT, MF_EXP, ...    every math call goes through a macro of this form
 *
 * ERROR MODEL
 *
 *   Hot-path functions never allocate, log or abort; outside their domain they
 *   return 0. Builders (later modules) validate input and return an mf_result
 *   (MF_SUCCESS = 0, negative codes for errors; mf_result_string() names them)
 *   and leave nothing allocated on failure. There is no global error state.
 *
 * REVISIONS
 *
 *   0.1.0  first release: Beckmann, GGX, GTR, Student-t; Smith Lambda, G1, G2;
 *          NDF and VNDF sampling; specular BRDF; Fresnel; linearly transformed
 *          microsurfaces for every distribution.
 */
#ifndef MICROFACET_H
#define MICROFACET_H

#define MF_VERSION_MAJOR 0
#define MF_VERSION_MINOR 1
#define MF_VERSION_PATCH 0

/* ======================================================================== */
/* == 1. Configuration and portability                                      */
/* ======================================================================== */

#include <math.h>
#include <stddef.h>

#ifdef MF_USE_DOUBLE
typedef double mf_real;
#define MF_R(x) (x)
#define MF_SQRT(x) sqrt(x)
#define MF_EXP(x) exp(x)
#define MF_EXPM1(x) expm1(x)
#define MF_LOG(x) log(x)
#define MF_LOG1P(x) log1p(x)
#define MF_POW(x, y) pow(x, y)
#define MF_SIN(x) sin(x)
#define MF_COS(x) cos(x)
#define MF_ACOS(x) acos(x)
#define MF_ATAN2(y, x) atan2(y, x)
#define MF_ERF(x) erf(x)
#define MF_ERFC(x) erfc(x)
#define MF_LGAMMA(x) lgamma(x)
#define MF_FABS(x) fabs(x)
#define MF_EPS 2.220446049250313e-16
#define MF_BIG 1e300
#define MF_TINY 1e-300
#else
typedef float mf_real;
#define MF_R(x) (x##f)
#define MF_SQRT(x) sqrtf(x)
#define MF_EXP(x) expf(x)
#define MF_EXPM1(x) expm1f(x)
#define MF_LOG(x) logf(x)
#define MF_LOG1P(x) log1pf(x)
#define MF_POW(x, y) powf(x, y)
#define MF_SIN(x) sinf(x)
#define MF_COS(x) cosf(x)
#define MF_ACOS(x) acosf(x)
#define MF_ATAN2(y, x) atan2f(y, x)
#define MF_ERF(x) erff(x)
#define MF_ERFC(x) erfcf(x)
#define MF_LGAMMA(x) lgammaf(x)
#define MF_FABS(x) fabsf(x)
#define MF_EPS 1.1920929e-7f
#define MF_BIG 1e30f
#define MF_TINY 1e-37f
#endif

#define MF_PI MF_R(3.14159265358979323846)
#define MF_INV_PI MF_R(0.31830988618379067154)
#define MF_SQRT_PI MF_R(1.77245385090551602730)
#define MF_ALPHA_MIN MF_R(1e-4)
#define MF_ALPHA_MAX MF_R(1e4)
#define MF_STUDENT_T_GAMMA_MIN MF_R(1.55)
#define MF_STUDENT_T_GAMMA_MAX MF_R(1000.0)

#if defined(__CUDACC__)
#define MF_HD __host__ __device__
#else
#define MF_HD
#endif
#ifndef MF_INLINE
#define MF_INLINE static inline MF_HD
#endif
/* MF_SLOW marks the heavy branches of the generic dispatch (numerical
 * samplers, special functions) as not to be inlined, so that mf_D, mf_G2,
 * mf_sample_visible... stay small and the common kinds (GGX) inline fully. */
#ifndef MF_SLOW
#if defined(__CUDACC__)
#define MF_SLOW static __noinline__ MF_HD
#elif defined(__GNUC__) || defined(__clang__)
#define MF_SLOW static __attribute__((noinline, unused))
#elif defined(_MSC_VER)
#define MF_SLOW static __declspec(noinline)
#else
#define MF_SLOW static inline
#endif
#endif
#ifndef MFDEF
#define MFDEF extern
#endif
#ifndef MF_ASSERT
#define MF_ASSERT(x) ((void)0)
#endif
#if !defined(MF_MALLOC) && !defined(MF_FREE)
#include <stdlib.h>
#define MF_MALLOC(n) malloc(n)
#define MF_FREE(p) free(p)
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Result codes of builders. */
typedef enum mf_result {
    MF_SUCCESS = 0,
    MF_ERROR_INVALID_ARGUMENT = -1,
    MF_ERROR_OUT_OF_MEMORY = -2,
    MF_ERROR_INVALID_DATA = -3
} mf_result;

/* ======================================================================== */
/* == 2. Vectors and frames                                                 */
/* ======================================================================== */

typedef struct mf_vec3 { mf_real x, y, z; } mf_vec3;
typedef struct mf_mat2 { mf_real m00, m01, m10, m11; } mf_mat2; /* row-major */

MF_INLINE mf_vec3 mf_vec3_make(mf_real x, mf_real y, mf_real z)
{
    mf_vec3 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}
MF_INLINE mf_real mf_dot(mf_vec3 a, mf_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
MF_INLINE mf_vec3 mf_add(mf_vec3 a, mf_vec3 b) { return mf_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
MF_INLINE mf_vec3 mf_scale(mf_vec3 a, mf_real s) { return mf_vec3_make(a.x * s, a.y * s, a.z * s); }
MF_INLINE mf_vec3 mf_cross(mf_vec3 a, mf_vec3 b)
{
    return mf_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
MF_INLINE mf_real mf_clamp(mf_real x, mf_real lo, mf_real hi) { return x < lo ? lo : (x > hi ? hi : x); }
MF_INLINE mf_real mf_max(mf_real a, mf_real b) { return a > b ? a : b; }
MF_INLINE mf_real mf_min(mf_real a, mf_real b) { return a < b ? a : b; }

/* Unit vector along v; the zero vector when v is zero (or not finite). */
MF_INLINE mf_vec3 mf_normalize(mf_vec3 v)
{
    mf_real l2 = mf_dot(v, v);
    if (!(l2 > MF_R(0.0)) || !(l2 < MF_BIG)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return mf_scale(v, MF_R(1.0) / MF_SQRT(l2));
}

/* Mirror reflection of w about the unit normal m: 2 (w.m) m - w. */
MF_INLINE mf_vec3 mf_reflect(mf_vec3 w, mf_vec3 m)
{
    return mf_add(mf_scale(m, MF_R(2.0) * mf_dot(w, m)), mf_scale(w, MF_R(-1.0)));
}

/* 2x2 matrices, row-major: M = [m00 m01; m10 m11] acts on column vectors. */
MF_INLINE mf_mat2 mf_mat2_make(mf_real m00, mf_real m01, mf_real m10, mf_real m11)
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
MF_INLINE mf_vec3 mf_mat2_apply(mf_mat2 a, mf_vec3 v)
{
    return mf_vec3_make(a.m00 * v.x + a.m01 * v.y, a.m10 * v.x + a.m11 * v.y, v.z);
}
MF_INLINE mf_vec3 mf_mat2_apply_transpose(mf_mat2 a, mf_vec3 v)
{
    return mf_vec3_make(a.m00 * v.x + a.m10 * v.y, a.m01 * v.x + a.m11 * v.y, v.z);
}

/* Tangent frame (t, b) around a unit normal n, branchless and singularity-free
 * (Duff et al. 2017, "Building an Orthonormal Basis, Revisited"). */
MF_INLINE void mf_frame(mf_vec3 n, mf_vec3 *t, mf_vec3 *b)
{
    mf_real s = n.z >= MF_R(0.0) ? MF_R(1.0) : MF_R(-1.0);
    mf_real a = MF_R(-1.0) / (s + n.z);
    mf_real c = n.x * n.y * a;
    *t = mf_vec3_make(MF_R(1.0) + s * n.x * n.x * a, s * c, -s * n.x);
    *b = mf_vec3_make(c, s + n.y * n.y * a, -n.y);
}

/* ======================================================================== */
/* == 3. Fresnel                                                            */
/* ======================================================================== */
/* Unpolarized reflectance of a smooth interface. cos_theta_i is the cosine
 * between the incident direction and the normal on the incident side. */

/* Dielectric; eta = n_transmitted / n_incident, clamped to [1e-6, 1e6] (<= 0
 * or NaN gives 0). A negative cos_theta_i means the light arrives from the
 * other side: eta is inverted. 1 on total internal reflection. */
MF_INLINE mf_real mf_fresnel_dielectric(mf_real cos_theta_i, mf_real eta)
{
    mf_real ci, s2t, ct, rs, rp;
    if (!(eta > MF_R(0.0)) || !(cos_theta_i == cos_theta_i)) return MF_R(0.0);
    eta = mf_clamp(eta, MF_R(1e-6), MF_R(1e6));
    ci = mf_clamp(cos_theta_i, MF_R(-1.0), MF_R(1.0));
    if (ci < MF_R(0.0)) { eta = MF_R(1.0) / eta; ci = -ci; }
    s2t = (MF_R(1.0) - ci * ci) / (eta * eta);           /* Snell */
    if (s2t >= MF_R(1.0)) return MF_R(1.0);
    ct = MF_SQRT(MF_R(1.0) - s2t);
    rs = (ci - eta * ct) / (ci + eta * ct);
    rp = (eta * ci - ct) / (eta * ci + ct);
    return MF_R(0.5) * (rs * rs + rp * rp);
}

/* Conductor with complex index of refraction eta + i k (relative to the
 * outside medium); exact unpolarized form. eta <= 0, k < 0 or NaN give 0;
 * eta and k are capped at 1e6. */
MF_INLINE mf_real mf_fresnel_conductor(mf_real cos_theta_i, mf_real eta, mf_real k)
{
    mf_real c = mf_clamp(MF_FABS(cos_theta_i), MF_R(0.0), MF_R(1.0));
    if (!(eta > MF_R(0.0)) || !(k >= MF_R(0.0)) || !(c == c)) return MF_R(0.0);
    eta = mf_min(eta, MF_R(1e6));
    k = mf_min(k, MF_R(1e6));
    mf_real c2 = c * c, s2 = MF_R(1.0) - c2;
    mf_real e2 = eta * eta, k2 = k * k;
    mf_real t0 = e2 - k2 - s2;
    mf_real a2b2 = MF_SQRT(mf_max(t0 * t0 + MF_R(4.0) * e2 * k2, MF_R(0.0)));
    mf_real a = MF_SQRT(mf_max(MF_R(0.5) * (a2b2 + t0), MF_R(0.0)));
    mf_real t1 = a2b2 + c2, t2 = MF_R(2.0) * a * c;
    mf_real rs = (t1 - t2) / mf_max(t1 + t2, MF_R(1e-30));
    mf_real t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    mf_real rp = rs * (t3 - t4) / mf_max(t3 + t4, MF_R(1e-30));
    return mf_clamp(MF_R(0.5) * (rp + rs), MF_R(0.0), MF_R(1.0));
}

/* Schlick's approximation f0 + (1 - f0)(1 - cos)^5. */
MF_INLINE mf_real mf_fresnel_schlick(mf_real f0, mf_real cos_theta)
{
    mf_real m = MF_R(1.0) - mf_clamp(cos_theta, MF_R(0.0), MF_R(1.0));
    if (!(m == m)) m = MF_R(0.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    mf_real m2 = m * m;
    return f0 + (MF_R(1.0) - f0) * m2 * m2 * m;
}

/* ======================================================================== */
/* == 4. Special functions                                                  */
/* ======================================================================== */
/* Small, self-contained pieces the distributions need: the inverse error
 * function, the regularized incomplete beta function, and the functions
 * x / expm1(x) and log1p(x) / x, which keep the GTR formulas finite at their
 * removable singularities (gamma = 1, alpha = 1). */

/* x / (e^x - 1), 1 at x = 0. */
MF_INLINE mf_real mf__x_over_expm1(mf_real x)
{
    if (MF_FABS(x) < MF_R(1e-4)) return MF_R(1.0) - MF_R(0.5) * x;
    return x / MF_EXPM1(x);
}
/* log(1 + x) / x, 1 at x = 0. */
MF_INLINE mf_real mf__log1p_over_x(mf_real x)
{
    if (MF_FABS(x) < MF_R(1e-4)) return MF_R(1.0) - MF_R(0.5) * x;
    return MF_LOG1P(x) / x;
}

/* Inverse of erf on (-1, 1): Giles' single-precision approximation (2010),
 * polished by Newton steps on erf/erfc. Finite for every input (clamped). */
MF_INLINE mf_real mf_erfinv(mf_real y)
{
    mf_real w, p, x;
    int i;
    y = mf_clamp(y, MF_R(-1.0) + MF_EPS, MF_R(1.0) - MF_EPS);
    w = -MF_LOG((MF_R(1.0) - y) * (MF_R(1.0) + y));
    if (w < MF_R(5.0)) {
        w = w - MF_R(2.5);
        p = MF_R(2.81022636e-08);
        p = MF_R(3.43273939e-07) + p * w;
        p = MF_R(-3.5233877e-06) + p * w;
        p = MF_R(-4.39150654e-06) + p * w;
        p = MF_R(0.00021858087) + p * w;
        p = MF_R(-0.00125372503) + p * w;
        p = MF_R(-0.00417768164) + p * w;
        p = MF_R(0.246640727) + p * w;
        p = MF_R(1.50140941) + p * w;
    } else {
        w = MF_SQRT(w) - MF_R(3.0);
        p = MF_R(-0.000200214257);
        p = MF_R(0.000100950558) + p * w;
        p = MF_R(0.00134934322) + p * w;
        p = MF_R(-0.00367342844) + p * w;
        p = MF_R(0.00573950773) + p * w;
        p = MF_R(-0.0076224613) + p * w;
        p = MF_R(0.00943887047) + p * w;
        p = MF_R(1.00167406) + p * w;
        p = MF_R(2.83297682) + p * w;
    }
    x = p * y;
#ifdef MF_USE_DOUBLE
    for (i = 0; i < 2; ++i) { /* Newton on the tail-accurate side */
        mf_real r = x >= 0.0 ? (1.0 - y) - MF_ERFC(x) : MF_ERFC(-x) - (1.0 + y); /* erf(x) - y */
        x -= r / (2.0 / MF_SQRT_PI * MF_EXP(-x * x));
    }
#else
    (void)i;
#endif
    return x;
}

/* Regularized incomplete beta I_x(a, b) by Lentz's continued fraction
 * (converges fast for x < (a+1)/(a+b+2); the symmetry I_x(a,b) = 1 - I_{1-x}(b,a)
 * covers the rest). lbeta = log B(a, b), precomputed by the caller. */
MF_INLINE mf_real mf__betacf(mf_real a, mf_real b, mf_real x)
{
    const mf_real tiny = MF_R(1e-30);
    mf_real c = MF_R(1.0), d = MF_R(1.0) - (a + b) * x / (a + MF_R(1.0)), h;
    int m;
    if (MF_FABS(d) < tiny) d = tiny;
    d = MF_R(1.0) / d;
    h = d;
    for (m = 1; m <= 300; ++m) {
        mf_real fm = (mf_real)m, m2 = MF_R(2.0) * fm, aa, del;
        aa = fm * (b - fm) * x / ((a + m2 - MF_R(1.0)) * (a + m2));
        d = MF_R(1.0) + aa * d; if (MF_FABS(d) < tiny) d = tiny;
        c = MF_R(1.0) + aa / c; if (MF_FABS(c) < tiny) c = tiny;
        d = MF_R(1.0) / d; h *= d * c;
        aa = -(a + fm) * (a + b + fm) * x / ((a + m2) * (a + m2 + MF_R(1.0)));
        d = MF_R(1.0) + aa * d; if (MF_FABS(d) < tiny) d = tiny;
        c = MF_R(1.0) + aa / c; if (MF_FABS(c) < tiny) c = tiny;
        d = MF_R(1.0) / d; del = d * c; h *= del;
        if (MF_FABS(del - MF_R(1.0)) < MF_R(4.0) * MF_EPS) break;
    }
    return h;
}
MF_INLINE mf_real mf__betainc(mf_real a, mf_real b, mf_real x, mf_real lbeta)
{
    mf_real front;
    if (!(x > MF_R(0.0))) return MF_R(0.0);
    if (!(x < MF_R(1.0))) return MF_R(1.0);
    front = MF_EXP(a * MF_LOG(x) + b * MF_LOG1P(-x) - lbeta);
    if (x < (a + MF_R(1.0)) / (a + b + MF_R(2.0))) return front * mf__betacf(a, b, x) / a;
    return MF_R(1.0) - front * mf__betacf(b, a, MF_R(1.0) - x) / b;
}

/* ======================================================================== */
/* == 5. Distributions                                                      */
/* ======================================================================== */
/* D(m) per unit solid angle, normalized so that integral D(m) (m.n) dm = 1
 * (thesis Eq. 3.5). Slopes: a microfacet m has slope (-m.x/m.z, -m.y/m.z).
 *   Beckmann (thesis Eq. C.1; anisotropic form Heitz 2014 Eq. 83)
 *   GGX      (thesis Eq. C.3, corrected: 1/(pi a^2 cos^4 (1 + tan^2/a^2)^2); Heitz 2014 Eq. 85)
 *   GTR      (Burley 2012; thesis Eq. C.5, Berry limit C.6), isotropic
 *   Student-t (Ribardiere et al. 2017): slopes follow a 2D Student t law,
 *            P22 = (1/(pi ax ay)) (1 + r^2/(gamma-1))^-gamma, r^2 = x^2/ax^2 + y^2/ay^2;
 *            gamma = 2 is GGX, gamma -> infinity is Beckmann.
 * mf_ndf is a small value type; build it once per shading point and pass it by
 * const pointer. Every generic operation (mf_D, mf_lambda, mf_G1, mf_G2,
 * mf_D_visible, mf_sample_D, mf_sample_visible, mf_brdf...) accepts every kind. */

typedef enum mf_ndf_type {
    MF_NDF_BECKMANN = 0,
    MF_NDF_GGX = 1,
    MF_NDF_GTR = 2,
    MF_NDF_STUDENT_T = 3
} mf_ndf_type;

typedef struct mf_ndf {
    int type;           /* mf_ndf_type */
    int transformed;    /* 1 when M (below) is not the identity */
    mf_real ax, ay;     /* slope-space roughness along x and y (GTR: ax = ay = alpha) */
    mf_real gamma;      /* tail exponent (GTR, Student-t); 0 otherwise */
    mf_real c[13];      /* per-kind constants precomputed by the constructor */
    mf_mat2 M, Minv;    /* tangential transform of the microsurface and its inverse */
    mf_real det;        /* |det M| */
} mf_ndf;

/* Layout of mf_ndf.c[] */
#define MF__GTR_NORM 0   /* normalization N of D = N / (sin^2 + a^2 cos^2)^gamma */
#define MF__GTR_L 1      /* L = log(alpha^2) */
#define MF__GTR_KL 2     /* (1 - gamma) L */
#define MF__GTR_E 3      /* expm1((1 - gamma) L) */
#define MF__GTR_EM 4     /* expm1(-(1 - gamma) L) */
#define MF__GTR_W 5      /* 5 natural-spline weights for the masking nodes gamma = 0..4 */
#define MF__ST_K 0       /* marginal slope density constant: P2(x) = K (1 + x^2/(g-1))^(1/2-g) */
#define MF__ST_LBETA 1   /* log B(gamma - 1, 1/2) */
#define MF__GTR_RK 10    /* kL / expm1(kL) */
#define MF__GTR_RMK 11   /* -kL / expm1(-kL) */
#define MF__VNDF_P 12    /* tail exponent of the numerical VNDF sampler (GTR, Student-t) */

MF_INLINE mf_real mf__clamp_alpha(mf_real a)
{
    return a > MF_ALPHA_MIN ? (a < MF_ALPHA_MAX ? a : MF_ALPHA_MAX) : MF_ALPHA_MIN;
}

MF_INLINE mf_ndf mf__ndf_init(int type, mf_real ax, mf_real ay, mf_real gamma)
{
    mf_ndf d;
    int i;
    d.type = type;
    d.ax = mf__clamp_alpha(ax);
    d.ay = mf__clamp_alpha(ay);
    d.gamma = gamma;
    for (i = 0; i < 13; ++i) d.c[i] = MF_R(0.0);
    d.transformed = 0;
    d.M = d.Minv = mf_mat2_make(MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0));
    d.det = MF_R(1.0);
    return d;
}

/* Anisotropic Beckmann. alpha = sqrt(2) sigma of the Gaussian slopes. */
MF_INLINE mf_ndf mf_beckmann(mf_real alpha_x, mf_real alpha_y)
{
    return mf__ndf_init(MF_NDF_BECKMANN, alpha_x, alpha_y, MF_R(0.0));
}

/* Anisotropic GGX (Trowbridge-Reitz). */
MF_INLINE mf_ndf mf_ggx(mf_real alpha_x, mf_real alpha_y)
{
    return mf__ndf_init(MF_NDF_GGX, alpha_x, alpha_y, MF_R(0.0));
}

/* Weights w_j(g) of the natural cubic spline through nodes j = 0..4 (unit
 * spacing) evaluated at g: the spline of data y is sum_j w_j y_j. The second
 * derivatives solve [4 1 0; 1 4 1; 0 1 4] M = 6 (second differences), whose
 * inverse is [15 -4 1; -4 16 -4; 1 -4 15] / 56. */
MF_INLINE void mf__spline5_weights(mf_real g, mf_real w[5])
{
    const mf_real inv[3][3] = {
        { MF_R(15.0) / MF_R(56.0), MF_R(-4.0) / MF_R(56.0), MF_R(1.0) / MF_R(56.0) },
        { MF_R(-4.0) / MF_R(56.0), MF_R(16.0) / MF_R(56.0), MF_R(-4.0) / MF_R(56.0) },
        { MF_R(1.0) / MF_R(56.0), MF_R(-4.0) / MF_R(56.0), MF_R(15.0) / MF_R(56.0) } };
    int i = (int)g, j, r, k;
    mf_real t, a, b;
    if (i > 3) i = 3;
    if (i < 0) i = 0;
    t = g - (mf_real)i;
    a = MF_R(1.0) - t;
    for (j = 0; j < 5; ++j) {
        mf_real y[5] = { 0, 0, 0, 0, 0 }, m[5] = { 0, 0, 0, 0, 0 };
        y[j] = MF_R(1.0);
        for (r = 0; r < 3; ++r)
            for (k = 0; k < 3; ++k)
                m[r + 1] += inv[r][k] * MF_R(6.0) * (y[k + 2] - MF_R(2.0) * y[k + 1] + y[k]);
        b = a * y[i] + t * y[i + 1] + ((a * a * a - a) * m[i] + (t * t * t - t) * m[i + 1]) / MF_R(6.0);
        w[j] = b;
    }
}

/* Burley's GTR, isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma.
 * alpha in [MF_ALPHA_MIN, 1], gamma in [0, 4] (clamped; see CLAMPS above).
 * gamma = 2 is GGX, gamma = 1 the Berry distribution (limit C.6), gamma = 0
 * the uniform 1/pi; alpha = 1 gives 1/pi for every gamma. N is written with
 * x/expm1(x) so the limits gamma -> 1 and alpha -> 1 are exact. */
MF_INLINE mf_ndf mf_gtr(mf_real alpha, mf_real gamma)
{
    mf_ndf d;
    mf_real a, L, k;
    a = mf__clamp_alpha(alpha);
    if (a > MF_R(1.0)) a = MF_R(1.0);
    gamma = gamma > MF_R(0.0) ? (gamma < MF_R(4.0) ? gamma : MF_R(4.0)) : MF_R(0.0);
    d = mf__ndf_init(MF_NDF_GTR, a, a, gamma);
    L = MF_R(2.0) * MF_LOG(a);
    k = MF_R(1.0) - gamma;
    /* N = (gamma-1)(a^2-1) / (pi (1 - a^(2(1-gamma))))  (C.5) = r(kL) / (pi r(L)) */
    d.c[MF__GTR_NORM] = mf__x_over_expm1(k * L) / (MF_PI * mf__x_over_expm1(L));
    d.c[MF__GTR_L] = L;
    d.c[MF__GTR_KL] = k * L;
    d.c[MF__GTR_E] = MF_EXPM1(k * L);
    d.c[MF__GTR_EM] = MF_EXPM1(-k * L);
    d.c[MF__GTR_RK] = mf__x_over_expm1(k * L);
    d.c[MF__GTR_RMK] = mf__x_over_expm1(-k * L);
    mf__spline5_weights(gamma, d.c + MF__GTR_W);
    d.c[MF__VNDF_P] = MF_R(4.0);
    return d;
}

/* Student's t-distribution of slopes (STD), anisotropic. gamma in
 * [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] (clamped). */
MF_INLINE mf_ndf mf_student_t(mf_real alpha_x, mf_real alpha_y, mf_real gamma)
{
    mf_ndf d;
    mf_real g1, beta;
    if (!(gamma > MF_STUDENT_T_GAMMA_MIN)) gamma = MF_STUDENT_T_GAMMA_MIN;
    if (gamma > MF_STUDENT_T_GAMMA_MAX) gamma = MF_STUDENT_T_GAMMA_MAX;
    d = mf__ndf_init(MF_NDF_STUDENT_T, alpha_x, alpha_y, gamma);
    g1 = gamma - MF_R(1.0);
    d.c[MF__ST_K] = MF_SQRT(g1) * MF_EXP(MF_LGAMMA(gamma - MF_R(0.5)) - MF_LGAMMA(gamma)) / MF_SQRT_PI;
    d.c[MF__ST_LBETA] = MF_LGAMMA(g1) + MF_LGAMMA(MF_R(0.5)) - MF_LGAMMA(g1 + MF_R(0.5));
    /* the sampler's tail substitution must cancel tan(theta) ~ q^-beta, beta = 1/(2 gamma - 2) */
    beta = MF_R(0.5) / g1;
    d.c[MF__VNDF_P] = MF_R(2.0) / (MF_R(1.0) - beta);
    return d;
}

/* sum of squared scaled slopes times cos^2: m.x^2/ax^2 + m.y^2/ay^2 */
MF_INLINE mf_real mf__q(mf_real ax, mf_real ay, mf_vec3 m)
{
    mf_real x = m.x / ax, y = m.y / ay;
    return x * x + y * y;
}

/* Per-distribution fast paths for D (same clamps as the generic mf_D). */
MF_INLINE mf_real mf_beckmann_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real z2, e;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    z2 = wm.z * wm.z;
    e = mf__q(ax, ay, wm) / z2;                   /* tan^2 / alpha_projected^2 */
    if (!(e < MF_R(80.0))) return MF_R(0.0);     /* exp underflow (and NaN) */
    return MF_EXP(-e) / (MF_PI * ax * ay * z2 * z2);
}
MF_INLINE mf_real mf_ggx_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real t;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    t = wm.z * wm.z + mf__q(ax, ay, wm);          /* cos^2 (1 + tan^2/alpha^2), no cos^4 underflow */
    return MF_R(1.0) / (MF_PI * ax * ay * t * t);
}

/* Student-t D in logs, so cos^2 may underflow: log D = -g log1p(s2/(g-1)) - 4 log cos,
 * s2 the squared scaled slope. D ~ cos^(2g-4) grows at the horizon when g < 2;
 * capped at e^60 / (pi ax ay) (reached only for cos < ~1e-25). */
MF_SLOW mf_real mf__student_t_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real g1, q, lz2, ls2, l1, lr;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    g1 = d->gamma - MF_R(1.0);
    q = mf__q(d->ax, d->ay, wm);
    lz2 = MF_R(2.0) * MF_LOG(wm.z);
    if (!(q > MF_R(0.0))) l1 = MF_R(0.0);
    else {
        ls2 = MF_LOG(q) - lz2;
        l1 = ls2 > MF_R(30.0) ? ls2 - MF_LOG(g1) : MF_LOG1P(MF_EXP(ls2) / g1);
    }
    lr = mf_min(-d->gamma * l1 - MF_R(2.0) * lz2, MF_R(60.0));
    return MF_EXP(lr) / (MF_PI * d->ax * d->ay);
}

/* D of the untransformed distribution at the direction of wm, times |wm|^-4:
 * equal to D(wm) for a unit wm, and homogeneous of degree -4 so that the
 * transformed D (Eq. 4.14) needs no normalization. The Beckmann, GGX and
 * Student-t formulas have this form already. */
MF_INLINE mf_real mf__D_base(const mf_ndf *d, mf_vec3 wm)
{
    switch (d->type) {
    case MF_NDF_BECKMANN: return mf_beckmann_D(d->ax, d->ay, wm);
    case MF_NDF_GGX: return mf_ggx_D(d->ax, d->ay, wm);
    case MF_NDF_GTR: {
        mf_real s2, l2, den;
        if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
        s2 = wm.x * wm.x + wm.y * wm.y;
        l2 = s2 + wm.z * wm.z;
        den = (s2 + d->ax * d->ax * wm.z * wm.z) / l2;  /* 1 + (a^2 - 1) cos^2 */
        return d->c[MF__GTR_NORM] / (MF_POW(den, d->gamma) * l2 * l2);
    }
    case MF_NDF_STUDENT_T: return mf__student_t_D(d, wm);
    default: return MF_R(0.0);
    }
}

/* ======================================================================== */
/* == 6. Linearly transformed microsurfaces                                 */
/* ======================================================================== */
/* Atanasov et al. 2022 (thesis ch. 4): the microsurface is transformed by a
 * tangential matrix M (Eq. 4.1: M acts on the xy plane, z is kept). Normals
 * transform by M^-T, so the statistics of the new surface are those of the old
 * one at transformed arguments:
 *   D_M(m)     = |det M| / |M^T m|^4 D(M^T m / |M^T m|)        (Eq. 4.14)
 *   G1_M(v, m) = G1(M^-1 v / |M^-1 v|, M^T m / |M^T m|)         (Eq. 4.4)
 *   sampling   u' ~ D cos or D_w with w = M^-1 v / |.|, then m' = M^-T u' / |.|
 *                                                              (Eq. 4.17-4.21)
 * This holds for every distribution, shape-invariant or not; mf_transformed
 * works on any mf_ndf and every generic operation honours it. A diagonal M on a
 * shape-invariant distribution equals elliptical anisotropy (Eq. 4.22-4.23). */

/* M with |det M| <= MF_TRANSFORM_MIN_DET times the squared Frobenius norm of
 * M (or with a non-finite entry) is not invertible enough to define a surface. */
#define MF_TRANSFORM_MIN_DET MF_R(1e-9)

/* 1 if M can transform a microsurface (finite, |det| above the threshold). */
MF_INLINE int mf_transform_valid(mf_mat2 M)
{
    mf_real n2 = M.m00 * M.m00 + M.m01 * M.m01 + M.m10 * M.m10 + M.m11 * M.m11;
    mf_real det = MF_FABS(mf_mat2_det(M));
    return n2 < MF_BIG && det < MF_BIG && det > MF_TRANSFORM_MIN_DET * n2;
}

/* The distribution of the microsurface transformed by M (row-major, acting
 * on the tangent-plane coordinates (x, y) of the shading frame). Transforming
 * a transformed distribution composes: mf_transformed(mf_transformed(b, M1), M2)
 * is b transformed by M2 M1. An M that fails mf_transform_valid is rejected:
 * base is returned unchanged. The identity gives back base itself, at no cost. */
MF_INLINE mf_ndf mf_transformed(mf_ndf base, mf_mat2 M)
{
    mf_ndf d = base;
    mf_mat2 P = base.transformed ? mf_mat2_mul(M, base.M) : M;
    if (!mf_transform_valid(M) || !mf_transform_valid(P)) return base;
    if (P.m00 == MF_R(1.0) && P.m01 == MF_R(0.0) && P.m10 == MF_R(0.0) && P.m11 == MF_R(1.0)) {
        d.transformed = 0;
        d.M = d.Minv = P;
        d.det = MF_R(1.0);
        return d;
    }
    d.transformed = 1;
    d.M = P;
    d.Minv = mf_mat2_inverse(P);
    d.det = MF_FABS(mf_mat2_det(P));
    return d;
}

/* Stretch matrix M_s (Eq. 4.24): diag(1/(1-s), 1-s) for s in [0,1),
 * diag(1+s, 1/(1+s)) for s in (-1,0); det M_s = 1, M_s^-1 = M_-s (Eq. 4.25).
 * s is clamped to [-0.999, 0.999]. */
MF_INLINE mf_mat2 mf_stretch_matrix(mf_real s)
{
    s = s == s ? mf_clamp(s, MF_R(-0.999), MF_R(0.999)) : MF_R(0.0);
    if (s >= MF_R(0.0)) return mf_mat2_make(MF_R(1.0) / (MF_R(1.0) - s), MF_R(0.0), MF_R(0.0), MF_R(1.0) - s);
    return mf_mat2_make(MF_R(1.0) + s, MF_R(0.0), MF_R(0.0), MF_R(1.0) / (MF_R(1.0) + s));
}

/* Stretch anisotropy: s > 0 stretches along x (smoother in x), s < 0 along y. */
MF_INLINE mf_ndf mf_stretched(mf_ndf base, mf_real s)
{
    return mf_transformed(base, mf_stretch_matrix(s));
}

/* Anisotropic GTR by scaling the microsurface (Eq. 4.22 with alpha =
 * sqrt(alpha_x alpha_y)): exactly elliptical anisotropy for shape-invariant
 * kinds; for GTR (shape-variant) the closest analogue, which keeps the area
 * of the highlight of the isotropic GTR of roughness sqrt(alpha_x alpha_y). */
MF_INLINE mf_ndf mf_gtr_anisotropic(mf_real alpha_x, mf_real alpha_y, mf_real gamma)
{
    mf_real ax = mf_min(mf__clamp_alpha(alpha_x), MF_R(1.0)), ay = mf_min(mf__clamp_alpha(alpha_y), MF_R(1.0));
    mf_real a = MF_SQRT(ax * ay);
    return mf_transformed(mf_gtr(a, gamma), mf_mat2_make(a / ax, MF_R(0.0), MF_R(0.0), a / ay));
}

/* D(wm), 1/sr; 0 if wm.z <= 0. Transformed kinds by Eq. 4.14. */
MF_INLINE mf_real mf_D(const mf_ndf *d, mf_vec3 wm)
{
    if (!d->transformed) return mf__D_base(d, wm);
    /* |det M| |M^T m|^-4 D(M^T m / |M^T m|) = |det M| mf__D_base(M^T m) */
    return d->det * mf__D_base(d, mf_mat2_apply_transpose(d->M, wm));
}

/* Deformation tracking (thesis Sec. 4.4.1). The tension matrix T = D R^-1 maps
 * the edges of a rest triangle to those of its deformed state, both expressed
 * in the triangle's orthonormal tangent frame (U along the texture u axis,
 * V along the orthogonalized texture v axis);
 * use it as M in mf_transformed with the shading frame's x axis along U.
 * rest_edges and deformed_edges hold the two edge vectors as columns. */
MF_INLINE mf_result mf_tension_matrix(mf_mat2 rest_edges, mf_mat2 deformed_edges, mf_mat2 *T)
{
    mf_mat2 Ri;
    if (!T) return MF_ERROR_INVALID_ARGUMENT;
    if (!mf_transform_valid(rest_edges) || !mf_transform_valid(deformed_edges)) return MF_ERROR_INVALID_DATA;
    Ri = mf_mat2_inverse(rest_edges);
    *T = mf_mat2_mul(deformed_edges, Ri);
    return MF_SUCCESS;
}

/* Edges p1 - p0 and p2 - p0 of a triangle in its orthonormal tangent frame
 * (U, V): U along dP/du, V the part of dP/dv orthogonal to U (texture
 * coordinates uv = {u0, v0, u1, v1, u2, v2}), so the frame follows the
 * texture, not the winding. */
MF_INLINE mf_result mf__triangle_edges(const mf_vec3 p[3], const mf_real uv[6], mf_mat2 *E)
{
    mf_vec3 e1 = mf_add(p[1], mf_scale(p[0], MF_R(-1.0))), e2 = mf_add(p[2], mf_scale(p[0], MF_R(-1.0)));
    mf_real du1 = uv[2] - uv[0], dv1 = uv[3] - uv[1], du2 = uv[4] - uv[0], dv2 = uv[5] - uv[1];
    mf_real det = du1 * dv2 - du2 * dv1;
    mf_vec3 U, V;
    if (!(MF_FABS(det) > MF_R(0.0)) || !(MF_FABS(det) < MF_BIG)) return MF_ERROR_INVALID_DATA;
    /* [e1 e2] = [dP/du dP/dv] [du1 du2; dv1 dv2] */
    /* dP/du and dP/dv up to the factor 1/det, whose sign matters */
    U = mf_add(mf_scale(e1, dv2), mf_scale(e2, -dv1));
    V = mf_add(mf_scale(e2, du1), mf_scale(e1, -du2));
    if (det < MF_R(0.0)) { U = mf_scale(U, MF_R(-1.0)); V = mf_scale(V, MF_R(-1.0)); }
    U = mf_normalize(U);
    V = mf_normalize(mf_add(V, mf_scale(U, -mf_dot(V, U))));
    if (mf_dot(U, U) == MF_R(0.0) || mf_dot(V, V) == MF_R(0.0)) return MF_ERROR_INVALID_DATA;
    *E = mf_mat2_make(mf_dot(e1, U), mf_dot(e2, U), mf_dot(e1, V), mf_dot(e2, V));
    return MF_SUCCESS;
}

/* Tension matrix of a triangle from its rest and deformed vertex positions
 * and its texture coordinates (shared by both states). */
MF_INLINE mf_result mf_tension_from_triangles(const mf_vec3 rest[3], const mf_vec3 deformed[3],
                                              const mf_real uv[6], mf_mat2 *T)
{
    mf_mat2 R, D;
    mf_result r;
    if (!rest || !deformed || !uv || !T) return MF_ERROR_INVALID_ARGUMENT;
    r = mf__triangle_edges(rest, uv, &R);
    if (r != MF_SUCCESS) return r;
    r = mf__triangle_edges(deformed, uv, &D);
    if (r != MF_SUCCESS) return r;
    return mf_tension_matrix(R, D, T);
}

/* Jacobian of a nonlinear map (u, v) -> map(u, v) by central differences of
 * step h: the local linear transform of Fig. 4.2 (bottom right). */
typedef void (*mf_map2_fn)(mf_real u, mf_real v, mf_real out[2], void *ctx);
MF_INLINE mf_mat2 mf_jacobian_2d(mf_map2_fn map, void *ctx, mf_real u, mf_real v, mf_real h)
{
    mf_real a[2], b[2], c[2], e[2];
    map(u + h, v, a, ctx); map(u - h, v, b, ctx);
    map(u, v + h, c, ctx); map(u, v - h, e, ctx);
    return mf_mat2_make((a[0] - b[0]) / (MF_R(2.0) * h), (c[0] - e[0]) / (MF_R(2.0) * h),
                        (a[1] - b[1]) / (MF_R(2.0) * h), (c[1] - e[1]) / (MF_R(2.0) * h));
}

/* ======================================================================== */
/* == 7. Smith masking                                                      */
/* ======================================================================== */
/* Smith: G1(w, m) = chi+(w.m) / (1 + Lambda(w)) (thesis Eq. 3.8 with the
 * average visibility S = 1 / (1 + Lambda)), which satisfies the masking
 * constraint integral G1(w,m) <w.m> D(m) dm = w.z (thesis Eq. 3.9).
 * Shape-invariant kinds (Beckmann, GGX, Student-t) depend only on
 * a = 1 / (alpha_w tan(theta)), alpha_w^2 = ax^2 cos^2(phi) + ay^2 sin^2(phi),
 * the projected roughness (Heitz 2014 Sec. 5.2) - never an averaged alpha.
 *   Beckmann: Lambda = (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi))  (Heitz 2014 Eq. 84)
 *             and Walter et al. 2007's rational approximation (thesis C.2), named apart.
 *   GGX:      Lambda = (sqrt(1 + 1/a^2) - 1)/2  (thesis C.4)
 *   GTR:      Dimov's exact formulas at gamma = 0..4 (thesis C.7-C.11) rewritten in
 *             tan(theta) without cancellation, natural cubic spline in gamma between
 *             (of log Lambda, not of S as in the thesis: see mf_lambda).
 *   Student-t: exact, from the marginal slope density P2(x) = K (1 + x^2/(g-1))^(1/2-g):
 *             Lambda = K (g-1)/((2g-3) mu) (1 + mu^2/(g-1))^(3/2-g) - Q(mu),
 *             Q the upper tail of P2 = I_w(g-1, 1/2)/2, w = (g-1)/(g-1+mu^2)
 *             (the closed form behind Ribardiere et al. 2017 Eq. 13-15; clamped at 0). */

/* alpha_w^2 tan^2(theta) = 1/a^2, with w.z clamped so the horizon stays finite */
MF_INLINE mf_real mf__a2t2(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real x = ax * w.x, y = ay * w.y;
    return (x * x + y * y) / mf_max(w.z * w.z, MF_R(1e-30));
}

MF_INLINE mf_real mf_ggx_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w);
    return a2t2 / (MF_R(2.0) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + a2t2)));
}

MF_INLINE mf_real mf_beckmann_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w), a;
    if (!(a2t2 > MF_R(1e-3))) return MF_R(0.0);   /* a > 31.6: Lambda < 1e-400 */
    a = MF_R(1.0) / MF_SQRT(a2t2);
    return mf_max(MF_R(0.5) * (MF_EXP(-a * a) / (a * MF_SQRT_PI) - MF_ERFC(a)), MF_R(0.0));
}

/* Walter et al. 2007 rational approximation of the Beckmann Lambda (thesis
 * Eq. C.2); relative error of G1 below about 0.35%. */
MF_INLINE mf_real mf_beckmann_lambda_approx(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w), a;
    if (!(a2t2 > MF_R(1.0) / (MF_R(1.6) * MF_R(1.6)))) return MF_R(0.0);
    a = MF_R(1.0) / MF_SQRT(a2t2);
    return (MF_R(1.0) - MF_R(1.259) * a + MF_R(0.396) * a * a) / (MF_R(3.535) * a + MF_R(2.181) * a * a);
}

/* GTR Lambda at the integer tails, in t2 = tan^2(theta) and a2 = alpha^2.
 * Derived from thesis Eq. C.7-C.11 with mu = 1/t; differences such as
 * sqrt(1 + a2 t2) - 1 are written as quotients so nothing cancels. */
MF_INLINE void mf__gtr_lambda_nodes(mf_real a2, mf_real L, mf_real t2, mf_real lam[5])
{
    mf_real qa = MF_SQRT(MF_R(1.0) + a2 * t2), qb = MF_SQRT(MF_R(1.0) + t2);
    mf_real ea = a2 * t2 / (qa + MF_R(1.0));           /* qa - 1 */
    mf_real a4 = a2 * a2, A4, d, y;
    lam[0] = t2 / (MF_R(2.0) * (MF_R(1.0) + qb));       /* C.7: GGX with alpha = 1 */
    lam[2] = MF_R(0.5) * ea;                            /* C.9: GGX */
    /* C.8: Lambda1 = [(qa - qb) - log1p((qa - qb)/(1 + qb))] / L */
    d = t2 / (qa + qb);                                 /* (qa - qb) / (a2 - 1) */
    y = (a2 - MF_R(1.0)) * d / (MF_R(1.0) + qb);
    lam[1] = d * (MF_R(1.0) - mf__log1p_over_x(y) / (MF_R(1.0) + qb)) / mf__x_over_expm1(L);
    /* C.10 */
    lam[3] = a2 * t2 * ((MF_R(3.0) * a2 + MF_R(1.0)) * ea + MF_R(4.0) * a2) /
             (MF_R(4.0) * (a2 + MF_R(1.0)) * qa * (qa + MF_R(1.0)));
    /* C.11 */
    A4 = MF_R(8.0) * (a4 + a2 + MF_R(1.0));
    lam[4] = a2 * t2 * (MF_R(12.0) * a4 - A4 * ea * (qa + MF_R(0.5)) / (qa + MF_R(1.0)) +
                        MF_R(3.0) * a2 * t2 * (MF_R(5.0) * a4 + MF_R(2.0) * a2 + MF_R(1.0))) /
             (MF_R(2.0) * A4 * qa * qa * qa);
}

/* Student-t Lambda for unit roughness, as a function of mu = cot(theta) / alpha_w. */
MF_INLINE mf_real mf__student_t_lambda_mu(const mf_ndf *d, mf_real mu)
{
    mf_real g = d->gamma, g1 = g - MF_R(1.0), l1p, head, w, tail;
    if (!(mu < MF_R(1e15))) return MF_R(0.0);
    mu = mf_max(mu, MF_R(1e-15));
    l1p = MF_LOG1P(mu * mu / g1);
    head = d->c[MF__ST_K] * g1 / ((MF_R(2.0) * g - MF_R(3.0)) * mu) * MF_EXP((MF_R(1.5) - g) * l1p);
    w = g1 / (g1 + mu * mu);
    tail = MF_R(0.5) * mf__betainc(g1, MF_R(0.5), w, d->c[MF__ST_LBETA]);
    return mf_max(head - tail, MF_R(0.0));
}

/* GTR Lambda: Dimov's formulas at the integer tails, spline in gamma.
 * The thesis (C.3) splines S = 1/(1+Lambda) in gamma; at small alpha that
 * misses the masking constraint by up to 17% (alpha 0.02, gamma 0.5), because
 * Lambda scales like alpha^(2 gamma - 2). The spline of log(Lambda) follows
 * that scaling: measured error of the constraint <= 0.6% for gamma >= 1 and
 * <= 5.4% for gamma < 1 (alpha in [0.02, 1], theta_v <= 89 deg). Exact at
 * integer gamma. tan^2 is capped at 1e16 (Lambda ~ 1e8, G1 ~ 1e-8) so float
 * never overflows. */
MF_SLOW mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real lam[5], sig = MF_R(0.0), t2 = mf_min(mf__a2t2(MF_R(1.0), MF_R(1.0), w), MF_R(1e16));
    int j;
    if (!(t2 > MF_R(0.0))) return MF_R(0.0);
    mf__gtr_lambda_nodes(d->ax * d->ax, d->c[MF__GTR_L], t2, lam);
    for (j = 0; j < 5; ++j) sig += d->c[MF__GTR_W + j] * MF_LOG(mf_max(lam[j], MF_TINY));
    return MF_EXP(sig);
}

/* Student-t Lambda through the projected roughness. */
MF_SLOW mf_real mf__student_t_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(d->ax, d->ay, w);
    if (!(a2t2 > MF_R(0.0))) return MF_R(0.0);
    return mf__student_t_lambda_mu(d, MF_R(1.0) / MF_SQRT(a2t2));
}

MF_SLOW mf_real mf__lambda_other(const mf_ndf *d, mf_vec3 w)
{
    switch (d->type) {
    case MF_NDF_BECKMANN: return mf_beckmann_lambda(d->ax, d->ay, w);
    case MF_NDF_GTR: return mf__gtr_lambda(d, w);
    case MF_NDF_STUDENT_T: return mf__student_t_lambda(d, w);
    default: return MF_R(0.0);
    }
}

/* Smith Lambda(w). Symmetric in w.z; large but finite at w.z = 0. GGX inline,
 * the other kinds out of line; transformed kinds at M^-1 w (Eq. 4.4). */
MF_INLINE mf_real mf_lambda(const mf_ndf *d, mf_vec3 w)
{
    /* Lambda depends on w only through tan(theta) and phi: no normalization */
    if (d->transformed) w = mf_mat2_apply(d->Minv, w);
    if (d->type == MF_NDF_GGX) return mf_ggx_lambda(d->ax, d->ay, w);
    return mf__lambda_other(d, w);
}

/* Monodirectional masking G1(w, wm) = chi+(w.wm) chi+(w.z) / (1 + Lambda(w)). */
MF_INLINE mf_real mf_G1(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
{
    if (!(w.z > MF_R(0.0)) || !(mf_dot(w, wm) > MF_R(0.0))) return MF_R(0.0);
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, w));
}

/* Height-correlated masking-shadowing (Heitz 2014 Eq. 99):
 * G2 = chi+(wo.wm) chi+(wi.wm) / (1 + Lambda(wo) + Lambda(wi)). Reflection only:
 * 0 unless wo.z > 0 and wi.z > 0. */
MF_INLINE mf_real mf_G2(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_vec3 wm)
{
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    if (!(mf_dot(wo, wm) > MF_R(0.0)) || !(mf_dot(wi, wm) > MF_R(0.0))) return MF_R(0.0);
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, wo) + mf_lambda(d, wi));
}

/* Separable form G1(wo, wm) G1(wi, wm) (Heitz 2014 Eq. 98). */
MF_INLINE mf_real mf_G2_separable(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_vec3 wm)
{
    return mf_G1(d, wo, wm) * mf_G1(d, wi, wm);
}

/* Projected area of the visible microsurface, w.z (1 + Lambda(w)) =
 * integral <w.m> D(m) dm (thesis Eq. 3.9); finite and positive at w.z = 0. */
MF_INLINE mf_real mf_projected_area(const mf_ndf *d, mf_vec3 w)
{
    mf_real cz = mf_max(MF_FABS(w.z), MF_R(1e-15));
    return cz + cz * mf_lambda(d, w);
}

/* Distribution of visible normals (Heitz & d'Eon 2014 Eq. 2):
 * D_w(wm) = G1(w, wm) max(0, w.wm) D(wm) / w.z; integrates to 1 over wm. 0 if w.z < 0. */
MF_INLINE mf_real mf_D_visible(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
{
    mf_real c = mf_dot(w, wm);
    if (w.z < MF_R(0.0) || !(c > MF_R(0.0))) return MF_R(0.0);
    return c * mf_D(d, wm) / mf_projected_area(d, w);
}

/* ======================================================================== */
/* == 8. Sampling                                                           */
/* ======================================================================== */
/* mf_sample_D draws wm with density D(wm) wm.z (Walter et al. 2007): the
 * radius of the slope from the inverse CDF, the azimuth uniform, stretched by
 * (ax, ay). mf_sample_visible draws wm with density mf_D_visible(w, wm):
 *   GGX       spherical caps (Dupuy & Benyoub 2023): sample the visible
 *             hemisphere of the stretched configuration as a spherical cap.
 *   Beckmann  slope-space inversion (Heitz & d'Eon 2014, Jakob 2014): the
 *             slope along the view from its CDF (safeguarded Newton on erf),
 *             the other slope from erfinv. The CDF is scaled by tan(theta), so
 *             normal incidence (cot = infinity) and tiny alpha are exact.
 *   GTR, Student-t  exact numerical inversion (see mf__iso_sample_visible):
 *             64 evaluations (32 in float builds) of the inverse NDF CDF per
 *             sample, no rejection, deterministic; about 50-100x the cost of
 *             GGX (see make bench). */

/* wm from an unstretched slope direction (cos phi, sin phi) and squared unit
 * slope radius r2, stretched by (ax, ay): wm ~ (ax r cos, ay r sin, 1). */
MF_INLINE mf_vec3 mf__wm_from_slope(mf_real ax, mf_real ay, mf_real r2, mf_real cp, mf_real sp)
{
    if (!(r2 < MF_R(1e30))) return mf_normalize(mf_vec3_make(ax * cp, ay * sp, MF_R(0.0)));
    r2 = MF_SQRT(mf_max(r2, MF_R(0.0)));
    return mf_normalize(mf_vec3_make(ax * r2 * cp, ay * r2 * sp, MF_R(1.0)));
}

/* Isotropic kinds sampled numerically (GTR with its alpha; Student-t with unit
 * roughness, stretched by the caller). t is the CDF of D cos measured from the
 * pole (theta = 0), q = 1 - t the mass beyond theta; both are passed so each
 * end stays accurate. Returns tan^2(theta) (MF_BIG at q = 0). */
MF_SLOW mf_real mf__iso_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    if (!(q > MF_R(0.0))) return MF_BIG;
    if (!(t > MF_R(0.0))) return MF_R(0.0);
    if (d->type == MF_NDF_GTR) {
        /* w = sin^2 + a^2 cos^2 has density ~ w^-gamma on [a^2, 1]; log w = lw. */
        mf_real L = d->c[MF__GTR_L], uq, ut, lw, llw;
        /* uq = lw / L and ut = (L - lw) / L add up to 1; the smaller one is
         * computed from its own end (q or t), the other as its complement */
        uq = q * mf__log1p_over_x(q * d->c[MF__GTR_E]) / d->c[MF__GTR_RK];
        if (uq < MF_R(0.5)) ut = MF_R(1.0) - uq;
        else { ut = t * mf__log1p_over_x(t * d->c[MF__GTR_EM]) / d->c[MF__GTR_RMK]; uq = MF_R(1.0) - ut; }
        lw = L * uq; llw = L * ut;
        mf_real c2 = uq / mf__x_over_expm1(lw);            /* cos^2 r(L)^-1 */
        mf_real s2 = MF_EXP(lw) * ut / mf__x_over_expm1(llw);
        if (!(c2 > MF_R(0.0))) return MF_BIG;
        return mf_min(s2 / c2, MF_BIG);
    } else {
        /* Student-t, unit alpha: q = (1 + tan^2/(g-1))^(1-g) */
        mf_real g1 = d->gamma - MF_R(1.0);
        mf_real lq = q < MF_R(0.5) ? MF_LOG(q) : MF_LOG1P(-t);
        return mf_min(g1 * MF_EXPM1(-lq / g1), MF_BIG);
    }
}

/* Mass of D cos beyond the polar angle whose tan^2 is tan2 (inverse of the above). */
MF_INLINE mf_real mf__iso_tail(const mf_ndf *d, mf_real tan2)
{
    if (d->type == MF_NDF_GTR) {
        mf_real a2m1 = d->ax * d->ax - MF_R(1.0), x = MF_R(1.0) / (MF_R(1.0) + tan2);
        mf_real L = d->c[MF__GTR_L], k = MF_R(1.0) - d->gamma;
        mf_real lwL = x * mf__log1p_over_x(a2m1 * x) / mf__log1p_over_x(a2m1);  /* log w / L */
        return lwL * mf__x_over_expm1(k * L) / mf__x_over_expm1(k * L * lwL);
    } else {
        mf_real g1 = d->gamma - MF_R(1.0);
        return MF_EXP(-g1 * MF_LOG1P(tan2 / g1));
    }
}

/* One step of safeguarded Newton for an increasing f on the bracket [lo, hi]:
 * shrinks the bracket with the sign of f, takes the Newton step, falls back to
 * bisection when the step leaves the bracket. Returns 1 when converged. */
MF_INLINE int mf__newton_step(mf_real *x, mf_real f, mf_real df, mf_real *lo, mf_real *hi, mf_real tol)
{
    mf_real step, nx;
    if (f > MF_R(0.0)) *hi = *x; else *lo = *x;
    if (df > MF_R(0.0)) {
        step = f / df;
        nx = *x - step;
        if (MF_FABS(step) <= tol) { *x = mf_clamp(nx, *lo, *hi); return 1; }
        if (nx > *lo && nx < *hi) { *x = nx; return 0; }
    }
    nx = MF_R(0.5) * (*lo + *hi);
    if (!(nx > *lo && nx < *hi)) return 1;   /* bracket exhausted */
    *x = nx;
    return 0;
}

/* Sample phi in (-pi, pi] with density proportional to max(0, c + cos(phi)). */
MF_INLINE mf_real mf__sample_phi_cos(mf_real c, mf_real u)
{
    mf_real phi0, total, lo, hi, phi, sgn = MF_R(1.0);
    int i;
    if (u < MF_R(0.5)) { u = MF_R(1.0) - MF_R(2.0) * u; sgn = MF_R(-1.0); }
    else u = MF_R(2.0) * u - MF_R(1.0);
    /* |phi| has CDF (c phi + sin phi) / (c phi0 + sin phi0) on [0, phi0] */
    phi0 = c >= MF_R(1.0) ? MF_PI : MF_ACOS(mf_max(-c, MF_R(-1.0)));
    total = c * phi0 + MF_SIN(phi0);
    if (c > MF_R(1e6)) return sgn * u * MF_PI;   /* uniform */
    lo = MF_R(0.0); hi = phi0; phi = u * phi0;
    for (i = 0; i < 60; ++i)
        if (mf__newton_step(&phi, c * phi + MF_SIN(phi) - u * total, c + MF_COS(phi), &lo, &hi, MF_R(4.0) * MF_EPS))
            break;
    return sgn * phi;
}

/* 8-point Gauss-Legendre rule: nodes xi on [-1, 1], weights normalized to sum 1. */
#define MF__GL_N 8
MF_INLINE mf_real mf__gl_xi(int i)
{
    const mf_real x[MF__GL_N] = {
        MF_R(-0.96028985649753623), MF_R(-0.79666647741362674), MF_R(-0.52553240991632899),
        MF_R(-0.18343464249564980), MF_R(0.18343464249564980), MF_R(0.52553240991632899),
        MF_R(0.79666647741362674), MF_R(0.96028985649753623) };
    return x[i];
}
MF_INLINE mf_real mf__gl_w(int i)
{
    const mf_real w[MF__GL_N] = {
        MF_R(0.050614268145188130), MF_R(0.11119051722668724), MF_R(0.15685332293894364),
        MF_R(0.18134189168918100), MF_R(0.18134189168918100), MF_R(0.15685332293894364),
        MF_R(0.11119051722668724), MF_R(0.050614268145188130) };
    return w[i];
}

/* Legendre polynomials P_0..P_(MF__GL_N) at x. */
MF_INLINE void mf__legendre(mf_real x, mf_real *p)
{
    int n;
    p[0] = MF_R(1.0);
    p[1] = x;
    for (n = 1; n < MF__GL_N; ++n)
        p[n + 1] = ((mf_real)(2 * n + 1) * x * p[n] - (mf_real)n * p[n - 1]) / (mf_real)(n + 1);
}

/* State of the numerical VNDF sampler for one view (see mf__iso_sample_visible). */
typedef struct mf__iso_vis {
    const mf_ndf *d;
    mf_real tv;        /* tan(theta_v) */
    mf_real tc, qc;    /* D-cos mass inside / beyond theta_c = pi/2 - theta_v */
} mf__iso_vis;

/* Visible-normal weight over the D-cos CDF coordinate beyond theta_c, in the
 * variable s in [0,1] with q = qc (1 - s^2)^p: per unit of D-cos mass, D_w
 * integrated over phi is cos(theta_v) psi(theta), psi = (phi0 + sqrt(T^2-1))/pi,
 * T = tan(theta_v) tan(theta), phi0 = acos(-1/T) (psi = 1 for T <= 1); this
 * returns psi dt/ds. The substitution makes it smooth at both ends: ~s^3 at
 * theta_c, and tan(theta) ~ q^-beta is cancelled at the horizon. */
MF_INLINE mf_real mf__iso_vis_h(const mf__iso_vis *v, mf_real s, mf_real *t_out, mf_real *q_out)
{
    const mf_ndf *d = v->d;
    mf_real p = d->c[MF__VNDF_P], s2 = s * s, l = MF_LOG1P(-s2);
    mf_real q = v->qc * MF_EXP(p * l), t = v->tc - v->qc * MF_EXPM1(p * l);   /* each accurate at its end */
    mf_real T2, psi = MF_R(1.0);
    *t_out = t; *q_out = q;
    if (!(q > MF_R(0.0)) || !(s2 < MF_R(1.0))) return MF_R(0.0);
    T2 = v->tv * v->tv * mf__iso_tan2(d, t, q);
    if (T2 > MF_R(1.0)) {
        mf_real T = MF_SQRT(T2);
        psi = (MF_ACOS(-MF_R(1.0) / T) + MF_SQRT(T2 - MF_R(1.0))) * MF_INV_PI;
    }
    /* -dq/ds = p q 2 s / (1 - s^2) */
    return psi * p * q * MF_R(2.0) * s / (MF_R(1.0) - s2);
}

/* Exact visible-normal sampling for an isotropic distribution known through its
 * NDF-sampling CDF (mf__iso_tan2 / mf__iso_tail). The visible density over
 * (D-cos mass t, phi) factors into a marginal in t and phi given t:
 *   - inside theta_c = pi/2 - theta_v every azimuth faces the viewer and the
 *     marginal is the constant cos(theta_v): t is linear there (analytic);
 *   - beyond it the marginal cos(theta_v) psi is integrated on 8 panels (4 in
 *     float builds) of 8 Gauss-Legendre nodes: 64 (32) evaluations, relative
 *     error of the total measured below 2e-6 (6e-6) over GTR and Student-t
 *     parameters, typically 1e-9 (1e-7); inside the chosen panel the CDF of the Legendre
 *     interpolant through the same nodes is inverted by safeguarded Newton, so
 *     no further evaluation is needed;
 *   - phi given theta has density max(0, cot(theta_v) cot(theta) + cos(phi)).
 * cv, sv: cos and sin of the view's polar angle, the view along +x. Returns wm
 * in that frame. */
#ifdef MF_USE_DOUBLE
#define MF__ISO_PANELS 8   /* total mass to ~1e-8 relative */
#else
#define MF__ISO_PANELS 4   /* total mass to ~1e-5 relative, below float's sampling resolution */
#endif
MF_INLINE mf_vec3 mf__iso_sample_visible(const mf_ndf *d, mf_real cv, mf_real sv, mf_real u1, mf_real u2)
{
    mf_real hv[MF__ISO_PANELS][MF__GL_N], cum[MF__ISO_PANELS + 1];
    mf_real target, t, q, tan2, cphi, c2, ct, st, phi, tan2c;
    mf__iso_vis v;
    int k, i;
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    if (!(sv > MF_R(1e-7) * cv)) {            /* normal incidence: the NDF-cos sampler */
        tan2 = mf__iso_tan2(d, u1, MF_R(1.0) - u1);
        cphi = MF_R(1e30);
    } else {
        v.d = d;
        v.tv = sv / mf_max(cv, MF_R(1e-30));
        tan2c = cv / sv; tan2c *= tan2c;
        v.qc = mf__iso_tail(d, tan2c);
        v.tc = MF_R(1.0) - v.qc;
        cum[0] = v.tc;                        /* masses in units of cos(theta_v) */
        for (k = 0; k < MF__ISO_PANELS; ++k) {
            mf_real sum = MF_R(0.0);
            for (i = 0; i < MF__GL_N; ++i) {
                mf_real s = ((mf_real)k + MF_R(0.5) + MF_R(0.5) * mf__gl_xi(i)) / (mf_real)MF__ISO_PANELS;
                hv[k][i] = mf__iso_vis_h(&v, s, &t, &q);
                sum += mf__gl_w(i) * hv[k][i];
            }
            cum[k + 1] = cum[k] + sum / (mf_real)MF__ISO_PANELS;
        }
        target = u1 * cum[MF__ISO_PANELS];
        if (target <= v.tc) {
            t = target;
            q = MF_R(1.0) - t;
        } else {
            mf_real a[MF__GL_N], P[MF__GL_N + 1], lo = MF_R(-1.0), hi = MF_R(1.0), x, rem, width;
            int n;
            for (k = 0; k < MF__ISO_PANELS - 1 && cum[k + 1] < target; ++k) {}
            width = MF_R(1.0) / (mf_real)MF__ISO_PANELS;
            rem = (target - cum[k]) / width;     /* in units of the panel's own variable */
            /* Legendre coefficients of the interpolant: a_n = (2n+1) sum_i w_i h_i P_n(xi_i) */
            for (n = 0; n < MF__GL_N; ++n) a[n] = MF_R(0.0);
            for (i = 0; i < MF__GL_N; ++i) {
                mf__legendre(mf__gl_xi(i), P);
                for (n = 0; n < MF__GL_N; ++n) a[n] += mf__gl_w(i) * hv[k][i] * P[n];
            }
            for (n = 0; n < MF__GL_N; ++n) a[n] *= (mf_real)(2 * n + 1);
            x = MF_R(2.0) * mf_clamp(rem / mf_max((cum[k + 1] - cum[k]) / width, MF_R(1e-30)), MF_R(0.0), MF_R(1.0)) - MF_R(1.0);
            for (i = 0; i < 50; ++i) {
                /* F(x) = integral over [-1, x] of the interpolant / 2; F' = h(x) / 2 */
                mf_real F, dF = MF_R(0.0);
                mf__legendre(x, P);
                F = a[0] * (x + MF_R(1.0));
                for (n = 1; n < MF__GL_N; ++n) F += a[n] * (P[n + 1] - P[n - 1]) / (mf_real)(2 * n + 1);
                for (n = 0; n < MF__GL_N; ++n) dF += a[n] * P[n];
                if (mf__newton_step(&x, MF_R(0.5) * F - rem, MF_R(0.5) * dF, &lo, &hi, MF_R(8.0) * MF_EPS)) break;
            }
            mf__iso_vis_h(&v, ((mf_real)k + MF_R(0.5) + MF_R(0.5) * x) * width, &t, &q);
        }
        tan2 = mf__iso_tan2(d, t, q);
        /* phi | theta: max(0, cv cos(theta) + sv sin(theta) cos(phi)) -> c = 1/(tv tan) */
        cphi = tan2 > MF_R(0.0) ? MF_R(1.0) / (v.tv * MF_SQRT(tan2)) : MF_R(1e30);
    }
    if (!(tan2 < MF_R(1e30))) { ct = MF_R(0.0); st = MF_R(1.0); }
    else { c2 = MF_R(1.0) / (MF_R(1.0) + tan2); ct = MF_SQRT(c2); st = MF_SQRT(tan2) * ct; }
    phi = mf__sample_phi_cos(cphi, u2);
    return mf_vec3_make(st * MF_COS(phi), st * MF_SIN(phi), ct);
}

/* Beckmann visible slopes for unit roughness and view tan(theta) = tv (view
 * along +x): the slope x along the view has density ~ max(0, 1 - tv x) exp(-x^2),
 * CDF F(x) = [erfc(-x)/2 + tv exp(-x^2)/(2 sqrt(pi))] / (1 + tv); y ~ N(0, 1/2). */
MF_SLOW void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy)
{
    mf_real mu = tv > MF_R(1.0) / MF_R(12.0) ? MF_R(1.0) / tv : MF_R(12.0);
    mf_real inv = MF_R(1.0) / (MF_R(1.0) + tv), k = MF_R(0.5) / MF_SQRT_PI;
    mf_real target = mf_clamp(u1, MF_R(0.0), MF_R(1.0)) *
                     (MF_R(0.5) * MF_ERFC(-mu) + tv * k * MF_EXP(-mu * mu)) * inv;
    mf_real lo = MF_R(-12.0), hi = mu, x;
    int i;
    x = mf_clamp(mf_erfinv(MF_R(2.0) * u1 - MF_R(1.0)), lo, hi);   /* exact at tv = 0 */
    for (i = 0; i < 60; ++i) {
        mf_real e = MF_EXP(-x * x);
        mf_real f = (MF_R(0.5) * MF_ERFC(-x) + tv * k * e) * inv - target;
        mf_real df = e * (MF_R(1.0) - tv * x) * inv / MF_SQRT_PI;
        if (mf__newton_step(&x, f, df, &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + MF_FABS(x)))) break;
    }
    *sx = x;
    *sy = mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
}

/* Stretch w into the unit-roughness configuration; returns cos and sin of its
 * polar angle and the cos/sin of its azimuth. */
MF_INLINE void mf__stretch_view(mf_real ax, mf_real ay, mf_vec3 w, mf_real *cv, mf_real *sv,
                                mf_real *cp, mf_real *sp)
{
    mf_vec3 v = mf_normalize(mf_vec3_make(ax * w.x, ay * w.y, mf_max(w.z, MF_R(0.0))));
    mf_real s = MF_SQRT(v.x * v.x + v.y * v.y);
    *cv = v.z; *sv = s;
    if (s > MF_R(0.0)) { *cp = v.x / s; *sp = v.y / s; }
    else { *cp = MF_R(1.0); *sp = MF_R(0.0); }
}

MF_INLINE mf_vec3 mf_beckmann_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp, sx, sy, x, y;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    mf__beckmann_visible_slopes(sv / mf_max(cv, MF_R(1e-30)), u1, u2, &sx, &sy);
    x = cp * sx - sp * sy;   /* rotate back to the view azimuth, then unstretch */
    y = sp * sx + cp * sy;
    return mf_normalize(mf_vec3_make(-ax * x, -ay * y, MF_R(1.0)));
}

/* GGX VNDF by spherical caps (Dupuy & Benyoub 2023, Listing 3), before the
 * final normalization; w need not be unit. (0,0,1) for degenerate input. */
MF_INLINE mf_vec3 mf__ggx_vndf_unnormalized(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 v, h;
    mf_real phi, z, s, l2;
    v = mf_vec3_make(ax * w.x, ay * w.y, w.z);
    l2 = mf_dot(v, v);
    if (!(l2 > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    v = mf_scale(v, MF_R(1.0) / MF_SQRT(l2));
    phi = MF_R(2.0) * MF_PI * u1;
    z = (MF_R(1.0) - u2) * (MF_R(1.0) + v.z) - v.z;          /* cap of the visible hemisphere */
    s = MF_SQRT(mf_clamp(MF_R(1.0) - z * z, MF_R(0.0), MF_R(1.0)));
    h = mf_vec3_make(s * MF_COS(phi) + v.x, s * MF_SIN(phi) + v.y, z + v.z);
    h = mf_vec3_make(ax * h.x, ay * h.y, mf_max(h.z, MF_R(0.0)));
    if (!(mf_dot(h, h) > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    return h;
}
MF_INLINE mf_vec3 mf_ggx_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(ax, ay, w, u1, u2);
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}

/* wm with density D(wm) wm.z of the untransformed distribution. */
MF_INLINE mf_vec3 mf__sample_D_base(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real phi = MF_R(2.0) * MF_PI * u2, cp = MF_COS(phi), sp = MF_SIN(phi), r2;
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), q = MF_R(1.0) - t;
    switch (d->type) {
    case MF_NDF_BECKMANN: r2 = -MF_LOG1P(-t); break;
    case MF_NDF_GGX: r2 = q > MF_R(0.0) ? t / q : MF_BIG; break;
    case MF_NDF_GTR: r2 = mf__iso_tan2(d, t, q); return mf__wm_from_slope(MF_R(1.0), MF_R(1.0), r2, cp, sp);
    case MF_NDF_STUDENT_T: r2 = mf__iso_tan2(d, t, q); break;
    default: return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    }
    return mf__wm_from_slope(d->ax, d->ay, r2, cp, sp);
}

MF_SLOW mf_vec3 mf__sample_visible_other(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    switch (d->type) {
    case MF_NDF_BECKMANN: return mf_beckmann_sample_visible(d->ax, d->ay, w, u1, u2);
    case MF_NDF_GTR:
    case MF_NDF_STUDENT_T: {
        mf_real cv, sv, cp, sp, ax = d->type == MF_NDF_GTR ? MF_R(1.0) : d->ax;
        mf_real ay = d->type == MF_NDF_GTR ? MF_R(1.0) : d->ay;
        mf_vec3 m;
        if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
        mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
        m = mf__iso_sample_visible(d, cv, sv, u1, u2);
        return mf_normalize(mf_vec3_make(ax * (cp * m.x - sp * m.y), ay * (sp * m.x + cp * m.y), m.z));
    }
    default: return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    }
}

/* wm with density D(wm) wm.z. u1 picks the polar angle, u2 the azimuth.
 * Transformed kinds: M^-T applied to a sample of the base (Eq. 4.17-4.18). */
MF_INLINE mf_vec3 mf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_vec3 m = mf__sample_D_base(d, u1, u2);
    if (!d->transformed) return m;
    return mf_normalize(mf_mat2_apply_transpose(d->Minv, m));
}

/* wm with density mf_D_visible(d, w, wm); the zero vector if w.z < 0. GGX
 * inline, the other kinds out of line. Transformed kinds: the base's visible
 * normals for M^-1 w, moved by M^-T (Eq. 4.20-4.21). */
MF_INLINE mf_vec3 mf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 m;
    if (!d->transformed) {
        if (d->type == MF_NDF_GGX) return mf_ggx_sample_visible(d->ax, d->ay, w, u1, u2);
        return mf__sample_visible_other(d, w, u1, u2);
    }
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    w = mf_mat2_apply(d->Minv, w);   /* the samplers normalize their view themselves */
    if (d->type == MF_NDF_GGX) m = mf__ggx_vndf_unnormalized(d->ax, d->ay, w, u1, u2);
    else m = mf__sample_visible_other(d, w, u1, u2);
    return mf_normalize(mf_mat2_apply_transpose(d->Minv, m));
}

/* ======================================================================== */
/* == 9. Specular microfacet BRDF                                           */
/* ======================================================================== */
/* f(wo, wi) = D(wh) G2(wo, wi, wh) / (4 |wo.z| |wi.z|) (Walter et al. 2007
 * Eq. 20 without Fresnel), sampled through the visible normals of wo
 * (Heitz & d'Eon 2014): pdf(wi) = D_wo(wh) / (4 wo.wh). Reflection only. */

MF_INLINE mf_real mf_brdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    if (!(wh.z > MF_R(0.0))) return MF_R(0.0);
    /* f grows like 1/cos at grazing retro-reflection: divide in two steps and
     * cap, so float never overflows */
    return mf_min(mf_D(d, wh) * mf_G2(d, wo, wi, wh) / (MF_R(4.0) * wo.z) / wi.z, MF_BIG);
}

/* Samples wi for wo; wi.z <= 0 (the zero vector) means no sample. */
MF_INLINE mf_vec3 mf_brdf_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 wm, wi;
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    wm = mf_sample_visible(d, wo, u1, u2);
    wi = mf_reflect(wo, wm);
    if (!(wi.z > MF_R(0.0)) || !(wm.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return wi;
}

/* Density of mf_brdf_sample per unit solid angle of wi. */
MF_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    mf_real c;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    c = mf_dot(wo, wh);
    if (!(c > MF_R(0.0))) return MF_R(0.0);
    return mf_D_visible(d, wo, wh) / (MF_R(4.0) * c);
}

/* f(wo, wi) wi.z / pdf(wi) for a wi from mf_brdf_sample: G2 / G1(wo)
 * = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)). */
MF_INLINE mf_real mf_brdf_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_real lo;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    lo = mf_lambda(d, wo);
    return (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(d, wi));
}

/* ======================================================================== */
/* == 10. Linearly Transformed Cosines                                      */
/* ======================================================================== */
/* Heitz, Dupuy, Hill, Neubelt 2016; Tao et al. 2021 Eq. 1: a clamped cosine
 * D_o(w) = max(0, w.z)/pi transformed by a 3x3 matrix M,
 *   D(w) = D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3,
 * integrates to 1 over the sphere, and its integral over a polygon is the
 * cosine form factor of the polygon transformed by M^-1 (Heitz 2017), clipped
 * exactly at the horizon. Polygons are given by their vertices relative to the
 * shading point (any length); the front face is the one whose vertices run
 * counterclockwise seen from the shading point. */

typedef struct mf_ltc {
    mf_real M[9];       /* row-major */
    mf_real Minv[9];
    mf_real det_inv;    /* |det M^-1| */
} mf_ltc;

MF_INLINE mf_vec3 mf__mat3_apply(const mf_real *a, mf_vec3 v)
{
    return mf_vec3_make(a[0] * v.x + a[1] * v.y + a[2] * v.z, a[3] * v.x + a[4] * v.y + a[5] * v.z,
                        a[6] * v.x + a[7] * v.y + a[8] * v.z);
}

/* Inverse of a row-major 3x3 matrix; returns its determinant (0: singular). */
MF_INLINE mf_real mf__mat3_inverse(const mf_real *a, mf_real *inv)
{
    mf_real c0 = a[4] * a[8] - a[5] * a[7], c1 = a[5] * a[6] - a[3] * a[8], c2 = a[3] * a[7] - a[4] * a[6];
    mf_real det = a[0] * c0 + a[1] * c1 + a[2] * c2, r;
    if (!(det != MF_R(0.0)) || !(MF_FABS(det) < MF_BIG)) return MF_R(0.0);
    r = MF_R(1.0) / det;
    inv[0] = c0 * r; inv[1] = (a[2] * a[7] - a[1] * a[8]) * r; inv[2] = (a[1] * a[5] - a[2] * a[4]) * r;
    inv[3] = c1 * r; inv[4] = (a[0] * a[8] - a[2] * a[6]) * r; inv[5] = (a[2] * a[3] - a[0] * a[5]) * r;
    inv[6] = c2 * r; inv[7] = (a[1] * a[6] - a[0] * a[7]) * r; inv[8] = (a[0] * a[4] - a[1] * a[3]) * r;
    return det;
}

/* The LTC of the row-major matrix m[9]. A singular or non-finite M gives the
 * clamped cosine itself (M = I). */
MF_INLINE mf_ltc mf_ltc_from_matrix9(const mf_real m[9])
{
    mf_ltc l;
    mf_real det;
    int i;
    for (i = 0; i < 9; ++i) l.M[i] = m[i];
    det = mf__mat3_inverse(l.M, l.Minv);
    if (!(MF_FABS(det) > MF_R(1e-20))) {
        for (i = 0; i < 9; ++i) l.M[i] = l.Minv[i] = (i % 4 == 0) ? MF_R(1.0) : MF_R(0.0);
        det = MF_R(1.0);
    }
    l.det_inv = MF_R(1.0) / MF_FABS(det);
    return l;
}

/* The same from M[row][col] (the API form; in C, passing a non-const array
 * to a const 2D-array parameter draws a -Wpedantic warning before C23:
 * mf_ltc_from_matrix9 avoids it). */
MF_INLINE mf_ltc mf_ltc_from_matrix(const mf_real M[3][3])
{
    mf_real m[9];
    int i;
    for (i = 0; i < 9; ++i) m[i] = M[i / 3][i % 3];
    return mf_ltc_from_matrix9(m);
}

/* The LTC of the usual 4/5-coefficient tables, which store the inverse
 * M^-1 = [a 0 b; 0 c 0; d 0 e] (e = 1 in 4-coefficient tables). */
MF_INLINE mf_ltc mf_ltc_from_inverse(mf_real a, mf_real b, mf_real c, mf_real d, mf_real e)
{
    mf_real inv[3][3], m[9], det;
    mf_ltc l;
    int i;
    inv[0][0] = a; inv[0][1] = 0; inv[0][2] = b;
    inv[1][0] = 0; inv[1][1] = c; inv[1][2] = 0;
    inv[2][0] = d; inv[2][1] = 0; inv[2][2] = e;
    for (i = 0; i < 9; ++i) m[i] = inv[i / 3][i % 3];
    det = mf__mat3_inverse(m, l.M);
    if (!(MF_FABS(det) > MF_R(1e-20))) {
        const mf_real I[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        return mf_ltc_from_matrix9(I);
    }
    for (i = 0; i < 9; ++i) l.Minv[i] = m[i];
    l.det_inv = MF_FABS(det);
    return l;
}

/* D(w), per steradian: |det M^-1| (M^-1 w).z / (pi |M^-1 w|^4) where positive. */
MF_INLINE mf_real mf_ltc_eval(const mf_ltc *l, mf_vec3 w)
{
    mf_vec3 v = mf__mat3_apply(l->Minv, w);
    mf_real l2 = mf_dot(v, v);
    if (!(v.z > MF_R(0.0)) || !(l2 > MF_R(0.0))) return MF_R(0.0);
    return l->det_inv * v.z / (MF_PI * l2 * l2);
}

/* A direction with density mf_ltc_eval: a cosine-distributed direction moved by M. */
MF_INLINE mf_vec3 mf_ltc_sample(const mf_ltc *l, mf_real u1, mf_real u2)
{
    mf_real r = MF_SQRT(mf_clamp(u1, MF_R(0.0), MF_R(1.0))), phi = MF_R(2.0) * MF_PI * u2;
    mf_vec3 w = mf_vec3_make(r * MF_COS(phi), r * MF_SIN(phi), MF_SQRT(mf_max(MF_R(1.0) - u1, MF_R(0.0))));
    return mf_normalize(mf__mat3_apply(l->M, w));
}

/* Integral of the cosine lobe's vector irradiance over the great arc from a to
 * b (unit vectors): (theta / sin theta) (a x b), theta = atan2(|a x b|, a.b),
 * accurate for tiny and for nearly antipodal arcs (no acos, no 1 - x^2). */
MF_INLINE mf_vec3 mf__edge_vector(mf_vec3 a, mf_vec3 b)
{
    mf_vec3 c = mf_cross(a, b);
    mf_real s = MF_SQRT(mf_dot(c, c)), d = mf_dot(a, b);
    if (!(s > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return mf_scale(c, MF_ATAN2(s, d) / s);
}

/* Signed cosine form factor (z component of the vector form factor, over
 * 2 pi) of the polygon p[0..n-1] transformed by A (NULL: identity), clipped
 * to z >= 0 on the fly: every edge is cut where it crosses the horizon and the
 * exit and entry points are joined along the horizon, so no vertex buffer is
 * needed and any n works. */
MF_INLINE mf_real mf__polygon_form_factor(const mf_real *A, const mf_vec3 *p, int n)
{
    int i, s = -1;
    mf_real sum = MF_R(0.0);
    mf_vec3 exit_pt = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), a, b;
    if (!p || n < 3) return MF_R(0.0);
    for (i = 0; i < n; ++i) {
        a = A ? mf__mat3_apply(A, p[i]) : p[i];
        if (a.z > MF_R(0.0)) { s = i; break; }
    }
    if (s < 0) return MF_R(0.0);   /* entirely below the horizon */
    a = A ? mf__mat3_apply(A, p[s]) : p[s];
    for (i = 1; i <= n; ++i) {
        int above_a = a.z > MF_R(0.0), above_b;
        b = A ? mf__mat3_apply(A, p[(s + i) % n]) : p[(s + i) % n];
        above_b = b.z > MF_R(0.0);
        if (above_a && above_b) {
            sum += mf__edge_vector(mf_normalize(a), mf_normalize(b)).z;
        } else if (above_a || above_b) {
            mf_real t = a.z / (a.z - b.z);
            mf_vec3 x = mf_add(a, mf_scale(mf_add(b, mf_scale(a, MF_R(-1.0))), t));
            x.z = MF_R(0.0);
            x = mf_normalize(x);
            if (above_a) {
                sum += mf__edge_vector(mf_normalize(a), x).z;
                exit_pt = x;
            } else {
                sum += mf__edge_vector(exit_pt, x).z;     /* along the horizon */
                sum += mf__edge_vector(x, mf_normalize(b)).z;
            }
        }
        a = b;
    }
    return sum * MF_R(0.15915494309189533577);   /* 1 / (2 pi) */
}

MF_INLINE mf_real mf__sided(mf_real ff, int two_sided)
{
    /* counterclockwise seen from the shading point is the front */
    ff = -ff;
    if (two_sided) return MF_FABS(ff);
    return mf_max(ff, MF_R(0.0));
}

/* Integral of D over the spherical polygon seen through verts[0..n-1]
 * (positions relative to the shading point, any length, n >= 3), clipped at
 * the horizon; two_sided counts both faces of the polygon. */
MF_INLINE mf_real mf_ltc_integrate(const mf_ltc *l, const mf_vec3 *verts, int n, int two_sided)
{
    return mf__sided(mf__polygon_form_factor(l->Minv, verts, n), two_sided);
}

/* Cosine form factor of a polygon: integral over it of max(0, w.z)/pi,
 * clipped at the horizon (the irradiance of a unit-radiance light, / pi). */
MF_INLINE mf_real mf_polygon_irradiance(const mf_vec3 *verts, int n, int two_sided)
{
    return mf__sided(mf__polygon_form_factor((const mf_real *)0, verts, n), two_sided);
}

/* Vector form factor F of a polygon (not clipped; Heitz 2017): F.z is its
 * unclipped cosine form factor, |F| and F / |F| feed mf_sphere_form_factor. */
MF_INLINE mf_vec3 mf_polygon_vector_form_factor(const mf_vec3 *verts, int n)
{
    mf_vec3 f = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    int i;
    if (!verts || n < 3) return f;
    for (i = 0; i < n; ++i) f = mf_add(f, mf__edge_vector(mf_normalize(verts[i]), mf_normalize(verts[(i + 1) % n])));
    return mf_scale(f, MF_R(-0.15915494309189533577));
}

/* Cosine form factor of a uniform sphere light of angular radius sigma whose
 * center lies at angle omega from the normal, clipped at the horizon
 * (Snyder 1996), from F = its vector form factor: |F| = sin^2 sigma,
 * F.z / |F| = cos omega. Applied to the vector form factor of a polygon or a
 * disk, it is the sphere approximation of their horizon-clipped form factor
 * (Hill & Heitz 2016). */
MF_INLINE mf_real mf_sphere_form_factor(mf_vec3 F)
{
    mf_real len = MF_SQRT(mf_dot(F, F)), s2, co, so, x, y, z;
    if (!(len > MF_R(0.0))) return MF_R(0.0);
    s2 = mf_min(len, MF_R(1.0));                 /* sin^2 sigma */
    co = mf_clamp(F.z / len, MF_R(-1.0), MF_R(1.0));
    so = MF_SQRT(MF_R(1.0) - co * co);
    x = MF_SQRT(mf_max(MF_R(1.0) / s2 - MF_R(1.0), MF_R(0.0)));  /* cot sigma */
    if (co >= MF_SQRT(s2)) return co * s2;      /* omega <= pi/2 - sigma: fully above */
    if (co <= -MF_SQRT(s2)) return MF_R(0.0);    /* omega >= pi/2 + sigma: fully below */
    y = so > MF_R(0.0) ? -x * co / so : MF_R(0.0);
    y = mf_clamp(y, MF_R(-1.0), MF_R(1.0));
    z = so * MF_SQRT(MF_R(1.0) - y * y);
    return mf_max(((co * MF_ACOS(y) - x * z) * s2 + MF_ATAN2(z, x)) * MF_INV_PI, MF_R(0.0));
}

/* Multi-scale roughness (Tao et al. 2021). The meso-scale normals of a
 * footprint, summarized by the length of their mean (an unnormalized mip-mapped
 * normal), are an LTC with M = diag(a, a, 1), i.e. a GGX lobe of roughness a;
 * Eq. 5 fits a from the mean length (result clamped to [0, 1]; a mean length
 * below about 0.65 gives 1). */
MF_INLINE mf_real mf_ltc_meso_alpha(mf_real mean_normal_length)
{
    mf_real b = mf_clamp(mean_normal_length, MF_R(0.0), MF_R(1.0)), b2 = b * b, b3 = b2 * b, b4 = b2 * b2;
    mf_real num = MF_R(1.629) * b4 + MF_R(17.05) * b3 - MF_R(18.96) * b2 - MF_R(23.37) * b + MF_R(23.65);
    mf_real den = b3 - MF_R(28.07) * b2 + MF_R(31.1) * b - MF_R(3.545);
    if (!(den > MF_R(0.0))) return MF_R(1.0);
    return mf_clamp(num / den, MF_R(0.0), MF_R(1.0));
}

/* Roughness of the convolution of micro- and meso-scale lobes (Tao Eq. 7),
 * clamped to [0, 1]. */
MF_INLINE mf_real mf_ltc_combined_alpha(mf_real alpha_micro, mf_real alpha_meso)
{
    mf_real a = mf_clamp(alpha_micro, MF_R(0.0), MF_R(1.0)), m = mf_clamp(alpha_meso, MF_R(0.0), MF_R(1.0));
    return mf_clamp(MF_R(0.07) * a * a + MF_R(0.94) * a + m - MF_R(0.83) * a * m, MF_R(0.0), MF_R(1.0));
}

/* ======================================================================== */
/* == 11. Non-inline functions                                              */
/* ======================================================================== */

/* A short English name of a result code. */
MFDEF const char *mf_result_string(mf_result r);

#ifdef __cplusplus
}
#endif

#endif /* MICROFACET_H */

#ifdef MICROFACET_IMPLEMENTATION
#ifndef MICROFACET_IMPLEMENTATION_DONE
#define MICROFACET_IMPLEMENTATION_DONE
#ifdef __cplusplus
extern "C" {
#endif

MFDEF const char *mf_result_string(mf_result r)
{
    switch (r) {
    case MF_SUCCESS: return "success";
    case MF_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case MF_ERROR_OUT_OF_MEMORY: return "out of memory";
    case MF_ERROR_INVALID_DATA: return "invalid data";
    default: return "unknown result";
    }
}

#ifdef __cplusplus
}
#endif
#endif /* MICROFACET_IMPLEMENTATION_DONE */
#endif /* MICROFACET_IMPLEMENTATION */

/*
 * LICENSE (MIT)
 *
 * Copyright (c) 2026 the microfacet.h authors
 *
 * Permission is hereby granted, free of charge, to any person obtaining a copy
 * of this software and associated documentation files (the "Software"), to deal
 * in the Software without restriction, including without limitation the rights
 * to use, copy, modify, merge, publish, distribute, sublicense, and/or sell
 * copies of the Software, and to permit persons to whom the Software is
 * furnished to do so, subject to the following conditions:
 *
 * The above copyright notice and this permission notice shall be included in
 * all copies or substantial portions of the Software.
 *
 * THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
 * IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
 * FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
 * AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
 * LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
 * OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
 * SOFTWARE.
 */
