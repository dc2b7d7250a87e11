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
 *     but finite (w.z^2 is clamped to 1e-30 inside the slope).
 *
 * CONFIGURATION MACROS (define before including)
 *
 *   MF_USE_DOUBLE           mf_real is double (default float)
 *   MICROFACET_IMPLEMENTATION  emit the non-inline functions in this file
 *   MFDEF                   storage of non-inline functions (default extern)
 *   MF_MALLOC(n) / MF_FREE(p)  allocator pair (default malloc/free)
 *   MF_ASSERT(x)            internal assertions (default: nothing)
 *   MF_SQRT, MF_EXP, ...    every math call goes through a macro of this form;
 *                           define one to replace it (e.g. with an intrinsic)
 *
 * ERROR MODEL
 *
 *   Hot-path functions never allocate, log or abort; outside their domain they
 *   return 0. Builders (LTC fitting and tables) validate input and return an mf_result
 *   (MF_SUCCESS = 0, negative codes for errors; mf_result_string() names them)
 *   and leave nothing allocated on failure. There is no global error state.
 *
 * REVISIONS
 *
 *   0.1.0  first release: Beckmann, GGX, GTR, Student-t; Smith Lambda, G1, G2;
 *          NDF and VNDF sampling; specular BRDF; Fresnel; linearly transformed
 *          microsurfaces for every distribution; Linearly Transformed Cosines
 *          (polygon integration, fitter, tables, built-in GGX table).
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
#ifndef MF_SQRT
#define MF_SQRT(x) sqrt(x)
#endif
#ifndef MF_EXP
#define MF_EXP(x) exp(x)
#endif
#ifndef MF_EXPM1
#define MF_EXPM1(x) expm1(x)
#endif
#ifndef MF_LOG
#define MF_LOG(x) log(x)
#endif
#ifndef MF_LOG1P
#define MF_LOG1P(x) log1p(x)
#endif
#ifndef MF_POW
#define MF_POW(x, y) pow(x, y)
#endif
#ifndef MF_SIN
#define MF_SIN(x) sin(x)
#endif
#ifndef MF_COS
#define MF_COS(x) cos(x)
#endif
#ifndef MF_ACOS
#define MF_ACOS(x) acos(x)
#endif
#ifndef MF_ATAN2
#define MF_ATAN2(y, x) atan2(y, x)
#endif
#ifndef MF_ERF
#define MF_ERF(x) erf(x)
#endif
#ifndef MF_ERFC
#define MF_ERFC(x) erfc(x)
#endif
#ifndef MF_LGAMMA
#define MF_LGAMMA(x) lgamma(x)
#endif
#ifndef MF_FABS
#define MF_FABS(x) fabs(x)
#endif
#define MF_EPS 2.220446049250313e-16
#define MF_BIG 1e300
#define MF_TINY 1e-300
#else
typedef float mf_real;
#define MF_R(x) (x##f)
#ifndef MF_SQRT
#define MF_SQRT(x) sqrtf(x)
#endif
#ifndef MF_EXP
#define MF_EXP(x) expf(x)
#endif
#ifndef MF_EXPM1
#define MF_EXPM1(x) expm1f(x)
#endif
#ifndef MF_LOG
#define MF_LOG(x) logf(x)
#endif
#ifndef MF_LOG1P
#define MF_LOG1P(x) log1pf(x)
#endif
#ifndef MF_POW
#define MF_POW(x, y) powf(x, y)
#endif
#ifndef MF_SIN
#define MF_SIN(x) sinf(x)
#endif
#ifndef MF_COS
#define MF_COS(x) cosf(x)
#endif
#ifndef MF_ACOS
#define MF_ACOS(x) acosf(x)
#endif
#ifndef MF_ATAN2
#define MF_ATAN2(y, x) atan2f(y, x)
#endif
#ifndef MF_ERF
#define MF_ERF(x) erff(x)
#endif
#ifndef MF_ERFC
#define MF_ERFC(x) erfcf(x)
#endif
#ifndef MF_LGAMMA
#define MF_LGAMMA(x) lgammaf(x)
#endif
#ifndef MF_FABS
#define MF_FABS(x) fabsf(x)
#endif
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
 * counterclockwise seen from the shading point. The fitter, the tables and the
 * built-in GGX table are non-inline (section 11, MICROFACET_IMPLEMENTATION). */

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

/* ---- LTC fitting and tables (Heitz et al. 2016, Sec. 4; Hill & Heitz 2016) ----
 * mf_ltc_fit fits, for one view direction wo = (sin t, 0, cos t), the LTC that
 * best matches the normalized lobe f(wo, wi) wi.z / albedo: M = B L with B the
 * frame whose z is the lobe's average direction and L = [m11 0 m13; 0 m22 0;
 * 0 0 1], found by Nelder-Mead on the cubed error estimated with multiple
 * importance sampling from the LTC and the BRDF (32 x 32 stratified samples
 * each, deterministic). The BRDF is either the specular microfacet BRDF of d
 * (brdf = NULL) or a callback returning f(wo, wi) wi.z (d = NULL; its side of
 * the estimate samples the cosine). Also returned: the albedo, integral of
 * f cos, and the Fresnel term, integral of f cos (1 - wo.h)^5, so that with
 * Schlick's F the lobe integrates to f0 albedo + (1 - f0) fresnel... written
 * out: (albedo - fresnel) f0 + fresnel. */
typedef mf_real (*mf_brdf_cos_fn)(mf_vec3 wo, mf_vec3 wi, void *ctx);
typedef struct mf_ltc_fit_result {
    mf_ltc ltc;          /* the fitted distribution */
    mf_real inv[4];      /* M^-1 = [inv0 0 inv1; 0 inv2 0; inv3 0 1] (normalized, table form) */
    mf_real albedo;      /* integral of f cos */
    mf_real fresnel;     /* integral of f cos (1 - wo.h)^5 */
    mf_real error;       /* the fitted L3 error estimate */
    mf_real params[3];   /* m11, m22, m13: pass as guess to the next fit */
} mf_ltc_fit_result;
MFDEF mf_result mf_ltc_fit(const mf_ndf *d, mf_brdf_cos_fn brdf, void *ctx, mf_real cos_theta_o,
                           const mf_real *guess, mf_ltc_fit_result *out);

/* A table of fits over view angle and roughness for a distribution family:
 * kind (mf_ndf_type) with tail gamma (GTR, Student-t; ignored otherwise),
 * n_theta points in t = sqrt(1 - cos theta_o) and n_alpha points in
 * sqrt(alpha) (alpha clamped below at MF_LTC_ALPHA_MIN). data holds, per
 * entry [alpha][theta], the six floats inv0 inv1 inv2 inv3 albedo fresnel. */
#define MF_LTC_ALPHA_MIN MF_R(1e-3)
typedef struct mf_ltc_table { int n_theta, n_alpha; float *data; } mf_ltc_table;
typedef void (*mf_progress_fn)(int done, int total, void *ctx);
MFDEF mf_result mf_ltc_table_build(mf_ltc_table *t, int kind, mf_real gamma, int n_theta, int n_alpha,
                                   mf_progress_fn progress, void *ctx);
MFDEF void mf_ltc_table_release(mf_ltc_table *t);
/* Bilinear lookup (of the normalized M^-1 entries, albedo and fresnel). */
MFDEF mf_ltc mf_ltc_table_lookup(const mf_ltc_table *t, mf_real cos_theta_o, mf_real alpha,
                                 mf_real *albedo, mf_real *fresnel);

/* Built-in table (tools/ltc_fit.c): the LTC of the GGX BRDF cos for
 * wo = (sin theta_o, 0, cos theta_o), isotropic alpha in [0, 1] (clamped below
 * at MF_LTC_ALPHA_MIN), normalized: f cos ~= mf_ltc_ggx_albedo mf_ltc_eval.
 * mf_ltc_ggx_fresnel is the integral of f cos (1 - wo.h)^5 (Schlick split).
 * mf_ltc_ggx_table exposes the raw 64 x 64 x 6 floats for GPU textures: rows
 * sqrt(alpha), columns sqrt(1 - cos theta_o), entries inv0 inv1 inv2 inv3
 * albedo fresnel with M^-1 = [inv0 0 inv1; 0 inv2 0; inv3 0 1]. Float16
 * packing: the LTC does not change when M^-1 is scaled, so divide inv0..inv3
 * and the implicit 1 by the largest of |inv0..inv3| and store those five
 * values (all in [-1, 1]; mf_ltc_from_inverse takes the fifth as e). Only the
 * 15 entries with alpha < 0.01 and theta_o > 85 deg need values below float16's
 * smallest normal (6e-5) for e. Not available in CUDA device code (upload the
 * table instead). Fitted in 150 s (double, one core). */
MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha);
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha);

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

/* ---- LTC fitting ---- */

typedef struct mf__fit_ctx {
    const mf_ndf *d;
    mf_brdf_cos_fn brdf;
    void *ctx;
    mf_vec3 wo, X, Z;          /* view; frame of the lobe (Y = (0,1,0)) */
    mf_real albedo;
    int n;                     /* samples per technique */
    mf_vec3 *bw;               /* BRDF-side samples: directions, f/albedo, pdf */
    mf_real *bf, *bp;
} mf__fit_ctx;

static mf_real mf__fit_f(const mf__fit_ctx *c, mf_vec3 wi)
{
    if (c->brdf) return wi.z > MF_R(0.0) ? c->brdf(c->wo, wi, c->ctx) : MF_R(0.0);
    return mf_brdf(c->d, c->wo, wi) * mf_max(wi.z, MF_R(0.0));
}

static mf_real mf__fit_pdf(const mf__fit_ctx *c, mf_vec3 wi)
{
    if (c->brdf) return mf_max(wi.z, MF_R(0.0)) * MF_INV_PI;
    return mf_brdf_pdf(c->d, c->wo, wi);
}

static mf_ltc mf__fit_ltc(const mf__fit_ctx *c, const mf_real *p)
{
    /* M = [X Y Z] [m11 0 m13; 0 m22 0; 0 0 1] */
    mf_real m11 = MF_FABS(p[0]) + MF_R(1e-7), m22 = MF_FABS(p[1]) + MF_R(1e-7), m13 = p[2], m[9];
    m[0] = c->X.x * m11; m[1] = MF_R(0.0); m[2] = c->X.x * m13 + c->Z.x;
    m[3] = MF_R(0.0);    m[4] = m22;       m[5] = MF_R(0.0);
    m[6] = c->X.z * m11; m[7] = MF_R(0.0); m[8] = c->X.z * m13 + c->Z.z;
    return mf_ltc_from_matrix9(m);
}

static mf_real mf__fit_error(const mf__fit_ctx *c, const mf_real *p)
{
    mf_ltc l = mf__fit_ltc(c, p);
    mf_real err = MF_R(0.0);
    int i, j, k = 0, n1 = 1;
    while (n1 * n1 < c->n) ++n1;
    /* LTC side: stratified samples of the current LTC */
    for (i = 0; i < n1; ++i)
        for (j = 0; j < n1; ++j) {
            mf_vec3 w = mf_ltc_sample(&l, ((mf_real)i + MF_R(0.5)) / (mf_real)n1, ((mf_real)j + MF_R(0.5)) / (mf_real)n1);
            mf_real dl = mf_ltc_eval(&l, w), f = mf__fit_f(c, w) / c->albedo, pb = mf__fit_pdf(c, w), e = MF_FABS(f - dl);
            if (dl + pb > MF_R(0.0)) err += e * e * e / (dl + pb);
            ++k;
        }
    /* BRDF side: fixed samples */
    for (i = 0; i < c->n; ++i) {
        mf_real dl = mf_ltc_eval(&l, c->bw[i]), e = MF_FABS(c->bf[i] - dl);
        if (dl + c->bp[i] > MF_R(0.0)) err += e * e * e / (dl + c->bp[i]);
    }
    return err / (mf_real)(k + c->n);
}

/* Nelder-Mead in 3 dimensions (standard coefficients). */
static mf_real mf__nelder_mead(const mf__fit_ctx *c, mf_real *x, mf_real step, int max_iter)
{
    mf_real s[4][3], f[4], xr[3], xe[3], xc[3], cen[3];
    int i, j, it;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 3; ++j) s[i][j] = x[j];
        if (i > 0) s[i][i - 1] += step * (MF_FABS(x[i - 1]) > MF_R(0.1) ? MF_FABS(x[i - 1]) : MF_R(0.1));
        f[i] = mf__fit_error(c, s[i]);
    }
    for (it = 0; it < max_iter; ++it) {
        int lo = 0, hi = 0, nh = 0;
        mf_real fr;
        for (i = 1; i < 4; ++i) { if (f[i] < f[lo]) lo = i; if (f[i] > f[hi]) hi = i; }
        nh = lo;
        for (i = 0; i < 4; ++i) if (i != hi && f[i] > f[nh]) nh = i;
        /* converged: relative spread 1e-7 (double) or 1.2e-5 (float) */
        if (MF_FABS(f[hi] - f[lo]) <= mf_max(MF_R(1e-7), MF_R(100.0) * MF_EPS) * (MF_FABS(f[lo]) + MF_R(1e-12))) break;
        for (j = 0; j < 3; ++j) {
            cen[j] = MF_R(0.0);
            for (i = 0; i < 4; ++i) if (i != hi) cen[j] += s[i][j] / MF_R(3.0);
            xr[j] = cen[j] + (cen[j] - s[hi][j]);
        }
        fr = mf__fit_error(c, xr);
        if (fr < f[lo]) {
            mf_real fe;
            for (j = 0; j < 3; ++j) xe[j] = cen[j] + MF_R(2.0) * (xr[j] - cen[j]);
            fe = mf__fit_error(c, xe);
            if (fe < fr) { for (j = 0; j < 3; ++j) s[hi][j] = xe[j]; f[hi] = fe; }
            else { for (j = 0; j < 3; ++j) s[hi][j] = xr[j]; f[hi] = fr; }
        } else if (fr < f[nh]) {
            for (j = 0; j < 3; ++j) s[hi][j] = xr[j];
            f[hi] = fr;
        } else {
            mf_real fc;
            for (j = 0; j < 3; ++j) xc[j] = cen[j] + MF_R(0.5) * (s[hi][j] - cen[j]);
            fc = mf__fit_error(c, xc);
            if (fc < f[hi]) { for (j = 0; j < 3; ++j) s[hi][j] = xc[j]; f[hi] = fc; }
            else {
                for (i = 0; i < 4; ++i) if (i != lo) {
                    for (j = 0; j < 3; ++j) s[i][j] = s[lo][j] + MF_R(0.5) * (s[i][j] - s[lo][j]);
                    f[i] = mf__fit_error(c, s[i]);
                }
            }
        }
    }
    {
        int lo = 0;
        for (i = 1; i < 4; ++i) if (f[i] < f[lo]) lo = i;
        for (j = 0; j < 3; ++j) x[j] = s[lo][j];
        return f[lo];
    }
}

MFDEF mf_result mf_ltc_fit(const mf_ndf *d, mf_brdf_cos_fn brdf, void *ctx, mf_real cos_theta_o,
                           const mf_real *guess, mf_ltc_fit_result *out)
{
    mf__fit_ctx c;
    mf_real ct, st, sum = MF_R(0.0), fres = MF_R(0.0), p[3];
    mf_vec3 avg = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    int i, j, n1 = 32, k;
    if (!out || (!d && !brdf) || !(cos_theta_o > MF_R(0.0)) || !(cos_theta_o <= MF_R(1.0)))
        return MF_ERROR_INVALID_ARGUMENT;
    ct = cos_theta_o; st = MF_SQRT(mf_max(MF_R(1.0) - ct * ct, MF_R(0.0)));
    c.d = d; c.brdf = brdf; c.ctx = ctx; c.wo = mf_vec3_make(st, MF_R(0.0), ct);
    c.n = n1 * n1;
    c.bw = (mf_vec3 *)MF_MALLOC(sizeof(mf_vec3) * (size_t)c.n);
    c.bf = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)c.n);
    c.bp = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)c.n);
    if (!c.bw || !c.bf || !c.bp) { MF_FREE(c.bw); MF_FREE(c.bf); MF_FREE(c.bp); return MF_ERROR_OUT_OF_MEMORY; }
    /* BRDF-side samples; albedo, Fresnel term and average direction by
     * importance sampling (the BRDF's own sampler, or the cosine) */
    for (i = 0, k = 0; i < n1; ++i)
        for (j = 0; j < n1; ++j, ++k) {
            mf_real u1 = ((mf_real)i + MF_R(0.5)) / (mf_real)n1, u2 = ((mf_real)j + MF_R(0.5)) / (mf_real)n1, f, pdf, w;
            mf_vec3 wi, h;
            if (brdf) {
                mf_real r = MF_SQRT(u1), phi = MF_R(2.0) * MF_PI * u2;
                wi = mf_vec3_make(r * MF_COS(phi), r * MF_SIN(phi), MF_SQRT(MF_R(1.0) - u1));
            } else wi = mf_brdf_sample(d, c.wo, u1, u2);
            f = mf__fit_f(&c, wi);
            pdf = mf__fit_pdf(&c, wi);
            w = pdf > MF_R(0.0) ? f / pdf : MF_R(0.0);
            c.bw[k] = wi; c.bf[k] = f; c.bp[k] = pdf;
            sum += w;
            h = mf_normalize(mf_add(c.wo, wi));
            {
                mf_real q = MF_R(1.0) - mf_clamp(mf_dot(c.wo, h), MF_R(0.0), MF_R(1.0)), q2 = q * q;
                fres += w * q2 * q2 * q;
            }
            avg = mf_add(avg, mf_scale(wi, w));
        }
    c.albedo = sum / (mf_real)c.n;
    out->albedo = c.albedo;
    out->fresnel = fres / (mf_real)c.n;
    if (!(c.albedo > MF_R(1e-12))) {   /* no lobe: the clamped cosine, zero albedo */
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        out->ltc = mf_ltc_from_matrix9(I9);
        out->inv[0] = out->inv[2] = MF_R(1.0); out->inv[1] = out->inv[3] = MF_R(0.0);
        out->error = MF_R(0.0);
        out->params[0] = out->params[1] = MF_R(1.0); out->params[2] = MF_R(0.0);
        MF_FREE(c.bw); MF_FREE(c.bf); MF_FREE(c.bp);
        return MF_SUCCESS;
    }
    for (k = 0; k < c.n; ++k) c.bf[k] /= c.albedo;
    avg.y = MF_R(0.0);
    c.Z = mf_normalize(avg);
    if (!(c.Z.z > MF_R(0.0))) c.Z = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    c.X = mf_vec3_make(c.Z.z, MF_R(0.0), -c.Z.x);
    if (guess) { p[0] = guess[0]; p[1] = guess[1]; p[2] = guess[2]; }
    else { p[0] = p[1] = MF_R(0.5); p[2] = MF_R(0.0); }
    out->error = mf__nelder_mead(&c, p, MF_R(0.1), 400);
    out->error = mf__nelder_mead(&c, p, MF_R(0.02), 400);   /* restart: Nelder-Mead can stall */
    out->params[0] = MF_FABS(p[0]); out->params[1] = MF_FABS(p[1]); out->params[2] = p[2];
    out->ltc = mf__fit_ltc(&c, p);
    /* normalized inverse, table form (the LTC is invariant to scaling M) */
    {
        const mf_real *iv = out->ltc.Minv;
        out->inv[0] = iv[0] / iv[8]; out->inv[1] = iv[2] / iv[8];
        out->inv[2] = iv[4] / iv[8]; out->inv[3] = iv[6] / iv[8];
    }
    MF_FREE(c.bw); MF_FREE(c.bf); MF_FREE(c.bp);
    return MF_SUCCESS;
}

static mf_ndf mf__family(int kind, mf_real alpha, mf_real gamma)
{
    switch (kind) {
    case MF_NDF_BECKMANN: return mf_beckmann(alpha, alpha);
    case MF_NDF_GTR: return mf_gtr(alpha, gamma);
    case MF_NDF_STUDENT_T: return mf_student_t(alpha, alpha, gamma);
    default: return mf_ggx(alpha, alpha);
    }
}

/* grid: t = sqrt(1 - cos theta) in [0, 1], v = sqrt(alpha) in [0, 1] */
static mf_real mf__ltc_grid_cos(int i, int n)
{
    mf_real t = (mf_real)i / (mf_real)(n - 1);
    return mf_max(MF_R(1.0) - t * t, MF_R(1e-3));
}
static mf_real mf__ltc_grid_alpha(int j, int n)
{
    mf_real v = (mf_real)j / (mf_real)(n - 1);
    return mf_max(v * v, MF_LTC_ALPHA_MIN);
}

MFDEF mf_result mf_ltc_table_build(mf_ltc_table *t, int kind, mf_real gamma, int n_theta, int n_alpha,
                                   mf_progress_fn progress, void *ctx)
{
    int i, j, done = 0;
    mf_real prev0[3], prev[3];
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    t->data = 0; t->n_theta = t->n_alpha = 0;
    if (n_theta < 2 || n_alpha < 2 || n_theta > 4096 || n_alpha > 4096 || kind < 0 || kind > MF_NDF_STUDENT_T)
        return MF_ERROR_INVALID_ARGUMENT;
    t->data = (float *)MF_MALLOC(sizeof(float) * 6 * (size_t)n_theta * (size_t)n_alpha);
    if (!t->data) return MF_ERROR_OUT_OF_MEMORY;
    t->n_theta = n_theta; t->n_alpha = n_alpha;
    /* roughest first, each view angle warm-started from its neighbour */
    prev0[0] = prev0[1] = MF_R(1.0); prev0[2] = MF_R(0.0);
    for (j = n_alpha - 1; j >= 0; --j) {
        mf_ndf d = mf__family(kind, mf__ltc_grid_alpha(j, n_alpha), gamma);
        prev[0] = prev0[0]; prev[1] = prev0[1]; prev[2] = prev0[2];
        for (i = 0; i < n_theta; ++i) {
            mf_ltc_fit_result r;
            float *e = t->data + 6 * ((size_t)j * (size_t)n_theta + (size_t)i);
            mf_result res = mf_ltc_fit(&d, 0, 0, mf__ltc_grid_cos(i, n_theta), prev, &r);
            if (res != MF_SUCCESS) { mf_ltc_table_release(t); return res; }
            e[0] = (float)r.inv[0]; e[1] = (float)r.inv[1]; e[2] = (float)r.inv[2]; e[3] = (float)r.inv[3];
            e[4] = (float)r.albedo; e[5] = (float)r.fresnel;
            prev[0] = r.params[0]; prev[1] = r.params[1]; prev[2] = r.params[2];
            if (i == 0) { prev0[0] = r.params[0]; prev0[1] = r.params[1]; prev0[2] = r.params[2]; }
            if (progress) progress(++done, n_theta * n_alpha, ctx);
        }
    }
    return MF_SUCCESS;
}

MFDEF void mf_ltc_table_release(mf_ltc_table *t)
{
    if (!t) return;
    MF_FREE(t->data);
    t->data = 0;
    t->n_theta = t->n_alpha = 0;
}

static mf_ltc mf__ltc_lookup(const float *data, int nt, int na, mf_real cos_theta_o, mf_real alpha,
                             mf_real *albedo, mf_real *fresnel)
{
    mf_real ct = mf_clamp(cos_theta_o, MF_R(0.0), MF_R(1.0)), a = mf_clamp(alpha, MF_R(0.0), MF_R(1.0));
    mf_real x = MF_SQRT(MF_R(1.0) - ct) * (mf_real)(nt - 1), y = MF_SQRT(a) * (mf_real)(na - 1), fx, fy, v[6];
    int ix = (int)x, iy = (int)y, k;
    if (ix > nt - 2) ix = nt - 2;
    if (iy > na - 2) iy = na - 2;
    if (ix < 0) ix = 0;
    if (iy < 0) iy = 0;
    fx = mf_clamp(x - (mf_real)ix, MF_R(0.0), MF_R(1.0)); fy = mf_clamp(y - (mf_real)iy, MF_R(0.0), MF_R(1.0));
    for (k = 0; k < 6; ++k) {
        const float *e00 = data + 6 * (iy * nt + ix), *e10 = e00 + 6, *e01 = e00 + 6 * nt, *e11 = e01 + 6;
        v[k] = (MF_R(1.0) - fy) * ((MF_R(1.0) - fx) * (mf_real)e00[k] + fx * (mf_real)e10[k]) +
               fy * ((MF_R(1.0) - fx) * (mf_real)e01[k] + fx * (mf_real)e11[k]);
    }
    if (albedo) *albedo = v[4];
    if (fresnel) *fresnel = v[5];
    return mf_ltc_from_inverse(v[0], v[1], v[2], v[3], MF_R(1.0));
}

MFDEF mf_ltc mf_ltc_table_lookup(const mf_ltc_table *t, mf_real cos_theta_o, mf_real alpha,
                                 mf_real *albedo, mf_real *fresnel)
{
    if (!t || !t->data || t->n_theta < 2 || t->n_alpha < 2) {
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        if (albedo) *albedo = MF_R(0.0);
        if (fresnel) *fresnel = MF_R(0.0);
        return mf_ltc_from_matrix9(I9);
    }
    return mf__ltc_lookup(t->data, t->n_theta, t->n_alpha, cos_theta_o, alpha, albedo, fresnel);
}

/* ---- built-in GGX table, generated by tools/ltc_fit.c (do not edit) ---- */
#define MF__LTC_GGX_N 64
static const float mf__ltc_ggx_data[MF__LTC_GGX_N * MF__LTC_GGX_N * 6] = {
/* MF_LTC_GGX_TABLE_BEGIN */
/* 64 x 64 entries [sqrt(alpha)][sqrt(1 - cos theta)]: inv0 inv1 inv2 inv3 albedo fresnel */
500.0f,-1.60923e-11f,500.0f,-2.13454e-19f,1.0f,9.72612e-25f, 500.0f,11.226f,500.252f,-0.0224521f,1.0f,1.30374e-18f,
500.0f,22.4648f,501.009f,-0.0449296f,1.0f,1.10057e-15f, 500.0f,33.7291f,502.275f,-0.0674582f,1.0f,6.14557e-14f,
500.0f,45.0319f,504.056f,-0.0900638f,1.0f,1.07942e-12f, 500.0f,56.3863f,506.359f,-0.112773f,1.0f,1.00025e-11f,
500.0f,67.8056f,509.195f,-0.135611f,1.0f,6.1765e-11f, 500.0f,79.3036f,512.578f,-0.158607f,1.0f,2.88073e-10f,
500.0f,90.8943f,516.523f,-0.181788f,1.0f,1.09386e-09f, 500.0f,102.592f,521.05f,-0.205184f,1.0f,3.54955e-09f,
500.0f,114.413f,526.18f,-0.228825f,1.0f,1.01747e-08f, 500.0f,126.371f,531.939f,-0.252742f,1.0f,2.63806e-08f,
500.0f,138.484f,538.356f,-0.276968f,1.0f,6.2957e-08f, 500.0f,150.769f,545.462f,-0.301538f,1.0f,1.40141e-07f,
500.0f,163.244f,553.297f,-0.326488f,1.0f,2.93992e-07f, 500.0f,175.929f,561.902f,-0.351857f,1.0f,5.8601e-07f,
500.0f,188.843f,571.324f,-0.377686f,1.0f,1.11722e-06f, 500.0f,202.01f,581.616f,-0.40402f,1.0f,2.04827e-06f,
500.0f,215.452f,592.839f,-0.430904f,1.0f,3.62733e-06f, 500.0f,229.195f,605.061f,-0.45839f,1.0f,6.22828e-06f,
500.0f,243.266f,618.356f,-0.486531f,1.0f,1.04017e-05f, 500.0f,257.694f,632.812f,-0.515387f,1.0f,1.69425e-05f,
500.0f,272.511f,648.524f,-0.545021f,1.0f,2.69769e-05f, 500.0f,287.752f,665.602f,-0.575504f,1.0f,4.20752e-05f,
499.999f,303.455f,684.17f,-0.60691f,1.0f,6.4394e-05f, 499.999f,319.662f,704.367f,-0.639323f,1.0f,9.68545e-05f,
499.999f,336.418f,726.354f,-0.672834f,1.0f,0.000143365f, 499.999f,353.774f,750.311f,-0.707546f,1.0f,0.000209091f,
499.999f,371.785f,776.448f,-0.743569f,1.0f,0.000300794f, 499.999f,390.515f,805.004f,-0.781028f,1.0f,0.000427228f,
499.999f,410.032f,836.252f,-0.820063f,1.0f,0.000599632f, 499.999f,430.415f,870.513f,-0.860827f,1.0f,0.000832305f,
499.999f,451.75f,908.156f,-0.903498f,1.0f,0.0011433f, 499.999f,474.137f,949.611f,-0.948271f,1.0f,0.00155522f,
499.998f,497.687f,995.385f,-0.995372f,1.0f,0.00209622f, 499.998f,522.529f,1046.07f,-1.04506f,1.0f,0.00280107f,
499.998f,548.809f,1102.38f,-1.09761f,1.0f,0.00371248f, 499.998f,576.695f,1165.15f,-1.15339f,1.0f,0.00488261f,
499.997f,606.382f,1235.4f,-1.21276f,1.0f,0.0063748f, 499.997f,638.097f,1314.34f,-1.27619f,1.0f,0.00826558f,
499.997f,672.106f,1403.46f,-1.34421f,1.0f,0.0106469f, 499.996f,708.724f,1504.58f,-1.41744f,1.0f,0.0136288f,
499.996f,748.325f,1619.98f,-1.49664f,0.999999f,0.0173424f, 499.995f,791.354f,1752.49f,-1.5827f,0.999999f,0.0219432f,
499.994f,838.355f,1905.69f,-1.6767f,0.999999f,0.0276146f, 499.994f,889.988f,2084.17f,-1.77997f,0.999999f,0.0345728f,
499.993f,947.069f,2293.9f,-1.89413f,0.999999f,0.043071f, 499.991f,1010.62f,2542.72f,-2.02122f,0.999999f,0.053405f,
499.99f,1081.92f,2841.15f,-2.16383f,0.999999f,0.0659194f, 499.988f,1162.64f,3203.52f,-2.32527f,0.999999f,0.0810138f,
499.986f,1254.94f,3649.85f,-2.50988f,0.999998f,0.0991507f, 499.983f,1361.72f,4208.65f,-2.72342f,0.999998f,0.120863f,
499.979f,1486.9f,4921.88f,-2.97378f,0.999998f,0.146765f, 499.975f,1635.99f,5853.17f,-3.27196f,0.999997f,0.17756f,
499.968f,1816.96f,7103.04f,-3.63389f,0.999997f,0.214053f, 499.959f,2041.72f,8837.89f,-4.08342f,0.999996f,0.257162f,
499.946f,2329.03f,11349.9f,-4.65803f,0.999995f,0.307932f, 499.926f,2710.09f,15191.4f,-5.42017f,0.999993f,0.36755f,
499.893f,3241.1f,21513.9f,-6.48218f,0.99999f,0.43736f, 499.834f,4034.32f,33062.4f,-8.06862f,0.999984f,0.51888f,
499.706f,5351.41f,57809.5f,-10.7028f,0.999971f,0.613815f, 499.343f,7975.23f,127880.0f,-15.9506f,0.999936f,0.724063f,
497.41f,15780.8f,501237.0f,-31.5635f,0.999744f,0.851565f, 152.429f,93556.4f,5.30655e+07f,-164.346f,0.891749f,0.876408f,
500.0f,-1.60923e-11f,500.0f,-2.13454e-19f,1.0f,9.72612e-25f, 500.0f,11.226f,500.252f,-0.0224521f,1.0f,1.30374e-18f,
500.0f,22.4648f,501.009f,-0.0449296f,1.0f,1.10057e-15f, 500.0f,33.7291f,502.275f,-0.0674582f,1.0f,6.14557e-14f,
500.0f,45.0319f,504.056f,-0.0900638f,1.0f,1.07942e-12f, 500.0f,56.3863f,506.359f,-0.112773f,1.0f,1.00025e-11f,
500.0f,67.8056f,509.195f,-0.135611f,1.0f,6.1765e-11f, 500.0f,79.3036f,512.578f,-0.158607f,1.0f,2.88073e-10f,
500.0f,90.8943f,516.523f,-0.181788f,1.0f,1.09386e-09f, 500.0f,102.592f,521.05f,-0.205184f,1.0f,3.54955e-09f,
500.0f,114.413f,526.18f,-0.228825f,1.0f,1.01747e-08f, 500.0f,126.371f,531.939f,-0.252742f,1.0f,2.63806e-08f,
500.0f,138.484f,538.356f,-0.276968f,1.0f,6.2957e-08f, 500.0f,150.769f,545.462f,-0.301538f,1.0f,1.40141e-07f,
500.0f,163.244f,553.297f,-0.326488f,1.0f,2.93992e-07f, 500.0f,175.929f,561.902f,-0.351857f,1.0f,5.8601e-07f,
500.0f,188.843f,571.324f,-0.377686f,1.0f,1.11722e-06f, 500.0f,202.01f,581.616f,-0.40402f,1.0f,2.04827e-06f,
500.0f,215.452f,592.839f,-0.430904f,1.0f,3.62733e-06f, 500.0f,229.195f,605.061f,-0.45839f,1.0f,6.22828e-06f,
500.0f,243.266f,618.356f,-0.486531f,1.0f,1.04017e-05f, 500.0f,257.694f,632.812f,-0.515387f,1.0f,1.69425e-05f,
500.0f,272.511f,648.524f,-0.545021f,1.0f,2.69769e-05f, 500.0f,287.752f,665.602f,-0.575504f,1.0f,4.20752e-05f,
499.999f,303.455f,684.17f,-0.60691f,1.0f,6.4394e-05f, 499.999f,319.662f,704.367f,-0.639323f,1.0f,9.68545e-05f,
499.999f,336.418f,726.354f,-0.672834f,1.0f,0.000143365f, 499.999f,353.774f,750.311f,-0.707546f,1.0f,0.000209091f,
499.999f,371.785f,776.448f,-0.743569f,1.0f,0.000300794f, 499.999f,390.515f,805.004f,-0.781028f,1.0f,0.000427228f,
499.999f,410.032f,836.252f,-0.820063f,1.0f,0.000599632f, 499.999f,430.415f,870.513f,-0.860827f,1.0f,0.000832305f,
499.999f,451.75f,908.156f,-0.903498f,1.0f,0.0011433f, 499.999f,474.137f,949.611f,-0.948271f,1.0f,0.00155522f,
499.998f,497.687f,995.385f,-0.995372f,1.0f,0.00209622f, 499.998f,522.529f,1046.07f,-1.04506f,1.0f,0.00280107f,
499.998f,548.809f,1102.38f,-1.09761f,1.0f,0.00371248f, 499.998f,576.695f,1165.15f,-1.15339f,1.0f,0.00488261f,
499.997f,606.382f,1235.4f,-1.21276f,1.0f,0.0063748f, 499.997f,638.097f,1314.34f,-1.27619f,1.0f,0.00826558f,
499.997f,672.106f,1403.46f,-1.34421f,1.0f,0.0106469f, 499.996f,708.724f,1504.58f,-1.41744f,1.0f,0.0136288f,
499.996f,748.325f,1619.98f,-1.49664f,0.999999f,0.0173424f, 499.995f,791.354f,1752.49f,-1.5827f,0.999999f,0.0219432f,
499.994f,838.355f,1905.69f,-1.6767f,0.999999f,0.0276146f, 499.994f,889.988f,2084.17f,-1.77997f,0.999999f,0.0345728f,
499.993f,947.069f,2293.9f,-1.89413f,0.999999f,0.043071f, 499.991f,1010.62f,2542.72f,-2.02122f,0.999999f,0.053405f,
499.99f,1081.92f,2841.15f,-2.16383f,0.999999f,0.0659194f, 499.988f,1162.64f,3203.52f,-2.32527f,0.999999f,0.0810138f,
499.986f,1254.94f,3649.85f,-2.50988f,0.999998f,0.0991507f, 499.983f,1361.72f,4208.65f,-2.72342f,0.999998f,0.120863f,
499.979f,1486.9f,4921.88f,-2.97378f,0.999998f,0.146765f, 499.975f,1635.99f,5853.17f,-3.27196f,0.999997f,0.17756f,
499.968f,1816.96f,7103.04f,-3.63389f,0.999997f,0.214053f, 499.959f,2041.72f,8837.89f,-4.08342f,0.999996f,0.257162f,
499.946f,2329.03f,11349.9f,-4.65803f,0.999995f,0.307932f, 499.926f,2710.09f,15191.4f,-5.42017f,0.999993f,0.36755f,
499.893f,3241.1f,21513.9f,-6.48218f,0.99999f,0.43736f, 499.834f,4034.32f,33062.4f,-8.06862f,0.999984f,0.51888f,
499.706f,5351.41f,57809.5f,-10.7028f,0.999971f,0.613815f, 499.343f,7975.23f,127880.0f,-15.9506f,0.999936f,0.724063f,
497.41f,15780.8f,501237.0f,-31.5635f,0.999744f,0.851565f, 152.429f,93556.4f,5.30655e+07f,-164.346f,0.891749f,0.876408f,
496.125f,-5.27282e-12f,496.125f,-2.43948e-19f,1.0f,1.0513e-24f, 496.125f,11.139f,496.375f,-0.0224521f,1.0f,1.30942e-18f,
496.125f,22.2907f,497.126f,-0.0449296f,1.0f,1.10159e-15f, 496.125f,33.4677f,498.383f,-0.0674582f,1.0f,6.14799e-14f,
496.125f,44.6829f,500.149f,-0.0900638f,1.0f,1.07965e-12f, 496.125f,55.9493f,502.434f,-0.112773f,1.0f,1.00039e-11f,
496.125f,67.2801f,505.249f,-0.135611f,1.0f,6.17709e-11f, 496.125f,78.689f,508.606f,-0.158607f,1.0f,2.88093e-10f,
496.125f,90.1898f,512.52f,-0.181788f,1.0f,1.09392e-09f, 496.125f,101.797f,517.012f,-0.205184f,1.0f,3.5497e-09f,
496.125f,113.526f,522.102f,-0.228825f,1.0f,1.01751e-08f, 496.125f,125.392f,527.817f,-0.252742f,1.0f,2.63813e-08f,
496.125f,137.411f,534.183f,-0.276968f,1.0f,6.29584e-08f, 496.125f,149.601f,541.235f,-0.301538f,1.0f,1.40144e-07f,
496.125f,161.979f,549.009f,-0.326488f,1.0f,2.93997e-07f, 496.125f,174.565f,557.547f,-0.351857f,1.0f,5.86018e-07f,
496.125f,187.38f,566.896f,-0.377686f,1.0f,1.11724e-06f, 496.125f,200.445f,577.108f,-0.40402f,1.0f,2.04829e-06f,
496.125f,213.783f,588.245f,-0.430904f,1.0f,3.62737e-06f, 496.125f,227.419f,600.371f,-0.45839f,1.0f,6.22833e-06f,
496.125f,241.381f,613.564f,-0.486531f,1.0f,1.04018e-05f, 496.125f,255.697f,627.908f,-0.515387f,1.0f,1.69426e-05f,
496.125f,270.399f,643.498f,-0.545021f,1.0f,2.6977e-05f, 496.125f,285.522f,660.444f,-0.575503f,1.0f,4.20754e-05f,
496.124f,301.104f,678.868f,-0.60691f,1.0f,6.43943e-05f, 496.124f,317.185f,698.908f,-0.639323f,1.0f,9.6855e-05f,
496.124f,333.811f,720.724f,-0.672834f,1.0f,0.000143365f, 496.124f,351.032f,744.496f,-0.707546f,1.0f,0.000209092f,
496.124f,368.904f,770.431f,-0.743569f,1.0f,0.000300795f, 496.124f,387.489f,798.765f,-0.781028f,1.0f,0.00042723f,
496.124f,406.855f,829.771f,-0.820062f,1.0f,0.000599634f, 496.124f,427.079f,863.767f,-0.860827f,1.0f,0.000832307f,
496.124f,448.249f,901.117f,-0.903498f,1.0f,0.0011433f, 496.124f,470.462f,942.251f,-0.948271f,1.0f,0.00155523f,
496.123f,493.83f,987.671f,-0.995372f,1.0f,0.00209623f, 496.123f,518.48f,1037.97f,-1.04506f,1.0f,0.00280107f,
496.123f,544.556f,1093.84f,-1.09761f,1.0f,0.00371248f, 496.123f,572.225f,1156.12f,-1.15339f,1.0f,0.00488262f,
496.122f,601.682f,1225.82f,-1.21276f,1.0f,0.00637481f, 496.122f,633.151f,1304.15f,-1.27619f,1.0f,0.00826559f,
496.122f,666.897f,1392.58f,-1.34421f,1.0f,0.0106469f, 496.121f,703.232f,1492.92f,-1.41744f,0.999999f,0.0136289f,
496.121f,742.525f,1607.43f,-1.49664f,0.999999f,0.0173425f, 496.12f,785.221f,1738.91f,-1.5827f,0.999999f,0.0219432f,
496.119f,831.858f,1890.92f,-1.6767f,0.999999f,0.0276146f, 496.118f,883.09f,2068.02f,-1.77997f,0.999999f,0.0345728f,
496.117f,939.729f,2276.12f,-1.89413f,0.999999f,0.043071f, 496.116f,1002.78f,2523.01f,-2.02122f,0.999999f,0.0534051f,
496.115f,1073.54f,2819.13f,-2.16383f,0.999999f,0.0659194f, 496.113f,1153.63f,3178.7f,-2.32527f,0.999999f,0.0810139f,
496.111f,1245.22f,3621.56f,-2.50988f,0.999998f,0.0991507f, 496.108f,1351.16f,4176.03f,-2.72342f,0.999998f,0.120863f,
496.104f,1475.37f,4883.73f,-2.97377f,0.999998f,0.146765f, 496.099f,1623.31f,5807.81f,-3.27196f,0.999997f,0.17756f,
496.093f,1802.87f,7047.99f,-3.63389f,0.999997f,0.214053f, 496.084f,2025.89f,8769.39f,-4.08342f,0.999996f,0.257161f,
496.071f,2310.97f,11261.9f,-4.65802f,0.999995f,0.307932f, 496.051f,2689.08f,15073.6f,-5.42015f,0.999993f,0.36755f,
496.018f,3215.97f,21347.1f,-6.48216f,0.999989f,0.43736f, 495.957f,4003.03f,32805.9f,-8.06858f,0.999983f,0.518879f,
495.829f,5309.88f,57360.9f,-10.7027f,0.999971f,0.613813f, 495.463f,7913.26f,126886.0f,-15.9503f,0.999935f,0.724059f,
493.515f,15657.2f,497308.0f,-31.5608f,0.99974f,0.851556f, 157.519f,95799.5f,5.09109e+07f,-162.58f,0.891839f,0.87636f,
220.5f,-1.1599e-12f,220.5f,-6.77657e-21f,1.0f,3.49245e-21f, 220.5f,4.95068f,220.611f,-0.022452f,1.0f,4.73196e-18f,
220.5f,9.90697f,220.945f,-0.0449294f,1.0f,1.44657e-15f, 220.5f,14.8745f,221.503f,-0.0674579f,1.0f,6.86544e-14f,
220.5f,19.8591f,222.288f,-0.0900634f,1.0f,1.14596e-12f, 220.5f,24.8663f,223.304f,-0.112772f,1.0f,1.03843e-11f,
220.5f,29.9022f,224.555f,-0.135611f,1.0f,6.33701e-11f, 220.5f,34.9728f,226.047f,-0.158606f,1.0f,2.93497e-10f,
220.5f,40.0843f,227.787f,-0.181788f,1.0f,1.10946e-09f, 220.5f,45.2431f,229.783f,-0.205183f,1.0f,3.58918e-09f,
220.5f,50.4558f,232.045f,-0.228824f,1.0f,1.0266e-08f, 220.499f,55.7295f,234.585f,-0.25274f,1.0f,2.65744e-08f,
220.499f,61.0713f,237.415f,-0.276966f,1.0f,6.33423e-08f, 220.499f,66.489f,240.549f,-0.301536f,1.0f,1.40866e-07f,
220.499f,71.9905f,244.004f,-0.326486f,1.0f,2.95291e-07f, 220.499f,77.5844f,247.798f,-0.351855f,1.0f,5.88243e-07f,
220.499f,83.2797f,251.953f,-0.377684f,1.0f,1.12093e-06f, 220.499f,89.0862f,256.492f,-0.404017f,1.0f,2.05422e-06f,
220.499f,95.0142f,261.441f,-0.4309f,1.0f,3.63663e-06f, 220.499f,101.075f,266.831f,-0.458386f,1.0f,6.24243e-06f,
220.499f,107.28f,272.694f,-0.486526f,1.0f,1.04228e-05f, 220.499f,113.643f,279.069f,-0.515382f,1.0f,1.69731e-05f,
220.499f,120.177f,285.998f,-0.545015f,1.0f,2.70207e-05f, 220.499f,126.898f,293.529f,-0.575497f,1.0f,4.21368e-05f,
220.499f,133.823f,301.717f,-0.606902f,1.0f,6.44791e-05f, 220.499f,140.97f,310.624f,-0.639314f,0.999999f,9.69704e-05f,
220.499f,148.359f,320.32f,-0.672825f,0.999999f,0.00014352f, 220.498f,156.013f,330.885f,-0.707535f,0.999999f,0.000209297f,
220.498f,163.956f,342.411f,-0.743557f,0.999999f,0.000301064f, 220.498f,172.216f,355.003f,-0.781014f,0.999999f,0.000427577f,
220.498f,180.823f,368.784f,-0.820047f,0.999999f,0.000600079f, 220.498f,189.811f,383.892f,-0.860809f,0.999999f,0.00083287f,
220.497f,199.22f,400.492f,-0.903477f,0.999999f,0.001144f, 220.497f,209.092f,418.773f,-0.948248f,0.999999f,0.0015561f,
220.497f,219.477f,438.958f,-0.995345f,0.999999f,0.0020973f, 220.496f,230.432f,461.31f,-1.04503f,0.999999f,0.00280238f,
220.496f,242.02f,486.141f,-1.09758f,0.999998f,0.00371405f, 220.495f,254.317f,513.821f,-1.15335f,0.999998f,0.00488448f,
220.494f,267.408f,544.796f,-1.21271f,0.999998f,0.00637701f, 220.494f,281.393f,579.605f,-1.27614f,0.999998f,0.00826815f,
220.493f,296.39f,618.904f,-1.34415f,0.999998f,0.0106499f, 220.492f,312.537f,663.497f,-1.41737f,0.999997f,0.0136322f,
220.49f,329.999f,714.383f,-1.49656f,0.999997f,0.0173462f, 220.489f,348.972f,772.811f,-1.58261f,0.999997f,0.0219473f,
220.487f,369.696f,840.362f,-1.67659f,0.999996f,0.0276191f, 220.485f,392.462f,919.061f,-1.77983f,0.999996f,0.0345775f,
220.483f,417.63f,1011.54f,-1.89397f,0.999995f,0.0430758f, 220.48f,445.647f,1121.24f,-2.02103f,0.999995f,0.0534097f,
220.477f,477.085f,1252.82f,-2.1636f,0.999994f,0.0659235f, 220.473f,512.67f,1412.59f,-2.32498f,0.999993f,0.0810169f,
220.468f,553.361f,1609.36f,-2.50951f,0.999992f,0.0991519f, 220.461f,600.426f,1855.72f,-2.72296f,0.99999f,0.120862f,
220.453f,655.6f,2170.13f,-2.97317f,0.999989f,0.146759f, 220.442f,721.309f,2580.64f,-3.27116f,0.999986f,0.177547f,
220.428f,801.051f,3131.52f,-3.6328f,0.999983f,0.21403f, 220.407f,900.074f,3896.04f,-4.08188f,0.999979f,0.257124f,
220.378f,1026.61f,5002.81f,-4.65574f,0.999972f,0.307872f, 220.333f,1194.38f,6694.88f,-5.41657f,0.999962f,0.367457f,
220.259f,1427.99f,9478.45f,-6.47603f,0.999946f,0.437214f, 220.124f,1776.53f,14558.5f,-8.05679f,0.999916f,0.518643f,
219.834f,2353.87f,25426.1f,-10.6753f,0.999851f,0.613407f, 219.019f,3496.86f,56060.9f,-15.8597f,0.999665f,0.723253f,
214.759f,6804.17f,215951.0f,-30.8616f,0.998456f,0.848983f, 43.9668f,13542.8f,4.24721e+06f,-55.1269f,0.925309f,0.885475f,
124.031f,2.85536e-10f,124.031f,-1.2199e-19f,1.0f,1.09842e-18f, 124.031f,2.78475f,124.093f,-0.0224517f,1.0f,6.24449e-17f,
124.031f,5.57265f,124.281f,-0.0449289f,1.0f,3.44937e-15f, 124.031f,8.36689f,124.595f,-0.0674572f,1.0f,9.72039e-14f,
124.031f,11.1707f,125.037f,-0.0900623f,1.0f,1.37074e-12f, 124.031f,13.9873f,125.608f,-0.112771f,1.0f,1.15746e-11f,
124.031f,16.82f,126.312f,-0.135609f,1.0f,6.81521e-11f, 124.031f,19.6721f,127.151f,-0.158604f,1.0f,3.09213e-10f,
124.031f,22.5473f,128.129f,-0.181785f,1.0f,1.15383e-09f, 124.031f,25.4492f,129.252f,-0.20518f,1.0f,3.70046e-09f,
124.031f,28.3813f,130.525f,-0.22882f,1.0f,1.05198e-08f, 124.03f,31.3477f,131.953f,-0.252737f,1.0f,2.711e-08f,
124.03f,34.3525f,133.545f,-0.276962f,1.0f,6.44017e-08f, 124.03f,37.3998f,135.308f,-0.301531f,1.0f,1.4285e-07f,
124.03f,40.4944f,137.252f,-0.32648f,1.0f,2.98835e-07f, 124.03f,43.6409f,139.386f,-0.351848f,1.0f,5.94323e-07f,
124.03f,46.8445f,141.723f,-0.377676f,0.999999f,1.13099e-06f, 124.03f,50.1106f,144.276f,-0.404008f,0.999999f,2.07036e-06f,
124.03f,53.445f,147.06f,-0.430891f,0.999999f,3.66179e-06f, 124.03f,56.8541f,150.091f,-0.458375f,0.999999f,6.28068e-06f,
124.03f,60.3444f,153.389f,-0.486514f,0.999999f,1.04796e-05f, 124.03f,63.9233f,156.975f,-0.515368f,0.999999f,1.70559e-05f,
124.03f,67.5988f,160.872f,-0.545f,0.999999f,2.71389e-05f, 124.029f,71.3794f,165.108f,-0.575479f,0.999999f,4.23027e-05f,
124.029f,75.2746f,169.714f,-0.606882f,0.999999f,6.47083e-05f, 124.029f,79.2946f,174.724f,-0.639291f,0.999998f,9.72823e-05f,
124.029f,83.4509f,180.177f,-0.672799f,0.999998f,0.000143939f, 124.028f,87.756f,186.119f,-0.707506f,0.999998f,0.000209852f,
124.028f,92.2236f,192.602f,-0.743524f,0.999998f,0.000301789f, 124.028f,96.8694f,199.685f,-0.780977f,0.999997f,0.000428515f,
124.027f,101.71f,207.435f,-0.820004f,0.999997f,0.000601277f, 124.027f,106.766f,215.933f,-0.860761f,0.999997f,0.000834386f,
124.026f,112.058f,225.269f,-0.903423f,0.999997f,0.0011459f, 124.026f,117.61f,235.551f,-0.948186f,0.999996f,0.00155845f,
124.025f,123.451f,246.903f,-0.995275f,0.999996f,0.00210018f, 124.024f,129.612f,259.475f,-1.04494f,0.999996f,0.00280588f,
124.023f,136.13f,273.439f,-1.09749f,0.999995f,0.00371827f, 124.022f,143.046f,289.007f,-1.15324f,0.999995f,0.00488951f,
124.021f,150.408f,306.427f,-1.21259f,0.999994f,0.00638293f, 124.02f,158.273f,326.003f,-1.276f,0.999993f,0.00827506f,
124.018f,166.706f,348.103f,-1.34399f,0.999993f,0.0106578f, 124.016f,175.786f,373.18f,-1.41719f,0.999992f,0.0136413f,
124.014f,185.605f,401.795f,-1.49634f,0.999991f,0.0173564f, 124.012f,196.274f,434.65f,-1.58235f,0.99999f,0.0219585f,
124.009f,207.926f,472.634f,-1.67629f,0.999989f,0.0276312f, 124.005f,220.726f,516.885f,-1.77947f,0.999987f,0.0345902f,
124.001f,234.875f,568.878f,-1.89354f,0.999985f,0.0430887f, 123.996f,250.625f,630.558f,-2.02051f,0.999983f,0.0534221f,
123.99f,268.295f,704.529f,-2.16296f,0.999981f,0.0659345f, 123.983f,288.295f,794.341f,-2.3242f,0.999978f,0.0810249f,
123.974f,311.16f,904.941f,-2.50853f,0.999974f,0.099155f, 123.962f,337.602f,1043.39f,-2.72171f,0.99997f,0.120857f,
123.948f,368.594f,1220.06f,-2.97156f,0.999964f,0.146742f, 123.929f,405.491f,1450.69f,-3.26902f,0.999956f,0.177512f,
123.903f,450.251f,1760.08f,-3.62987f,0.999946f,0.213968f, 123.867f,505.802f,2189.31f,-4.07773f,0.999932f,0.257023f,
123.815f,576.736f,2810.36f,-4.64961f,0.999911f,0.307712f, 123.735f,670.67f,3759.07f,-5.40694f,0.99988f,0.367207f,
123.604f,801.232f,5317.8f,-6.45961f,0.999827f,0.436821f, 123.366f,995.404f,8156.11f,-8.02523f,0.99973f,0.518009f,
122.857f,1314.95f,14200.6f,-10.602f,0.999518f,0.612312f, 121.441f,1937.14f,31039.7f,-15.6196f,0.998842f,0.721025f,
114.21f,3604.91f,114026.0f,-28.9549f,0.989895f,0.837383f, 20.9997f,3761.1f,747207.0f,-28.1732f,0.952079f,0.880491f,
79.3791f,-8.03531e-10f,79.3791f,-1.0168e-18f,1.0f,9.47492e-17f, 79.3791f,1.78222f,79.4191f,-0.0224512f,1.0f,1.07641e-15f,
79.3791f,3.56647f,79.5393f,-0.0449278f,1.0f,1.75364e-14f, 79.3791f,5.35477f,79.7402f,-0.0674556f,1.0f,2.20657e-13f,
79.379f,7.14918f,80.0229f,-0.0900602f,1.0f,2.12041e-12f, 79.379f,8.95178f,80.3885f,-0.112768f,1.0f,1.50025e-11f,
79.379f,10.7647f,80.8388f,-0.135605f,1.0f,8.07563e-11f, 79.379f,12.5901f,81.3758f,-0.1586f,1.0f,3.48345e-10f,
79.379f,14.4302f,82.0021f,-0.18178f,1.0f,1.26016e-09f, 79.379f,16.2873f,82.7207f,-0.205175f,1.0f,3.95999e-09f,
79.3789f,18.1639f,83.5352f,-0.228814f,0.999999f,1.11001e-08f, 79.3789f,20.0624f,84.4494f,-0.252729f,0.999999f,2.83168e-08f,
79.3788f,21.9854f,85.4681f,-0.276953f,0.999999f,6.67617e-08f, 79.3786f,23.9357f,86.5963f,-0.30152f,0.999999f,1.4723e-07f,
79.3785f,25.9161f,87.8401f,-0.326468f,0.999999f,3.06604e-07f, 79.3784f,27.9298f,89.2061f,-0.351834f,0.999999f,6.07573e-07f,
79.3782f,29.9801f,90.7017f,-0.377661f,0.999999f,1.15282e-06f, 79.3781f,32.0703f,92.3356f,-0.40399f,0.999998f,2.10522e-06f,
79.378f,34.2043f,94.1171f,-0.430871f,0.999998f,3.71597e-06f, 79.3778f,36.386f,96.0571f,-0.458352f,0.999998f,6.36283e-06f,
79.3777f,38.6197f,98.1675f,-0.486488f,0.999998f,1.06014e-05f, 79.3775f,40.9101f,100.462f,-0.515338f,0.999997f,1.72328e-05f,
79.3773f,43.2623f,102.956f,-0.544966f,0.999997f,2.73912e-05f, 79.3771f,45.6817f,105.667f,-0.575441f,0.999997f,4.26562e-05f,
79.3768f,48.1745f,108.614f,-0.606839f,0.999996f,6.51959e-05f, 79.3765f,50.7471f,111.82f,-0.639243f,0.999996f,9.7945e-05f,
79.3761f,53.4069f,115.309f,-0.672745f,0.999995f,0.000144827f, 79.3757f,56.1618f,119.112f,-0.707445f,0.999995f,0.000211027f,
79.3752f,59.0208f,123.26f,-0.743454f,0.999995f,0.000303325f, 79.3747f,61.9936f,127.792f,-0.780898f,0.999994f,0.000430499f,
79.374f,65.0914f,132.751f,-0.819915f,0.999993f,0.000603813f, 79.3733f,68.3264f,138.188f,-0.860661f,0.999993f,0.000837591f,
79.3725f,71.7125f,144.162f,-0.903308f,0.999992f,0.00114991f, 79.3716f,75.2653f,150.741f,-0.948056f,0.999991f,0.00156342f,
79.3705f,79.0026f,158.004f,-0.995127f,0.99999f,0.00210627f, 79.3692f,82.9446f,166.047f,-1.04478f,0.999989f,0.00281328f,
79.3678f,87.1145f,174.981f,-1.09729f,0.999988f,0.00372716f, 79.3662f,91.539f,184.941f,-1.15302f,0.999987f,0.00490009f,
79.3643f,96.2489f,196.085f,-1.21234f,0.999985f,0.0063954f, 79.3622f,101.28f,208.608f,-1.2757f,0.999984f,0.00828959f,
79.3596f,106.675f,222.745f,-1.34365f,0.999982f,0.0106746f, 79.3568f,112.482f,238.785f,-1.41679f,0.99998f,0.0136603f,
79.3534f,118.762f,257.088f,-1.49588f,0.999978f,0.0173777f, 79.3495f,125.584f,278.101f,-1.58181f,0.999975f,0.021982f,
79.345f,133.035f,302.392f,-1.67565f,0.999972f,0.0276566f, 79.3395f,141.219f,330.689f,-1.77872f,0.999968f,0.034617f,
79.3331f,150.263f,363.933f,-1.89263f,0.999964f,0.0431158f, 79.3253f,160.33f,403.367f,-2.01942f,0.999959f,0.0534482f,
79.316f,171.621f,450.651f,-2.16163f,0.999953f,0.0659575f, 79.3047f,184.398f,508.051f,-2.32255f,0.999946f,0.0810418f,
79.2905f,199.0f,578.723f,-2.50647f,0.999937f,0.0991614f, 79.2726f,215.881f,667.167f,-2.71909f,0.999926f,0.120847f,
79.2498f,235.656f,779.988f,-2.96816f,0.999912f,0.146707f, 79.22f,259.185f,927.198f,-3.26451f,0.999893f,0.177439f,
79.1796f,287.703f,1124.58f,-3.62372f,0.999868f,0.213839f, 79.1237f,323.056f,1398.19f,-4.06904f,0.999833f,0.256811f,
79.0428f,368.126f,1793.64f,-4.63676f,0.999781f,0.307378f, 78.9197f,427.666f,2396.71f,-5.38677f,0.999702f,0.366684f,
78.7173f,510.102f,3384.9f,-6.42528f,0.99957f,0.435998f, 78.3505f,631.877f,5175.94f,-7.95947f,0.999318f,0.516673f,
77.5756f,829.569f,8954.03f,-10.45f,0.998699f,0.60995f, 75.3816f,1200.06f,19191.6f,-15.0735f,0.993063f,0.712947f,
65.862f,2060.92f,64537.9f,-25.6658f,0.975667f,0.816885f, 12.7463f,1484.67f,204042.0f,-17.9755f,0.968791f,0.862674f,
55.1236f,2.0542e-09f,55.1236f,-5.96745e-19f,1.0f,3.59631e-15f, 55.1236f,1.23764f,55.1514f,-0.0224502f,1.0f,1.6311e-14f,
55.1236f,2.47668f,55.2349f,-0.0449259f,1.0f,1.25435e-13f, 55.1236f,3.71854f,55.3744f,-0.0674527f,1.0f,8.27317e-13f,
55.1236f,4.96465f,55.5707f,-0.0900562f,1.0f,4.86716e-12f, 55.1236f,6.21643f,55.8246f,-0.112763f,1.0f,2.53555e-11f,
55.1236f,7.47538f,56.1372f,-0.135599f,1.0f,1.14209e-10f, 55.1236f,8.74299f,56.5101f,-0.158593f,0.999999f,4.43392e-10f,
55.1236f,10.0208f,56.945f,-0.181771f,0.999999f,1.50271e-09f, 55.1236f,11.3105f,57.444f,-0.205164f,0.999999f,4.52566e-09f,
55.1235f,12.6136f,58.0095f,-0.228801f,0.999999f,1.23228e-08f, 55.1235f,13.932f,58.6444f,-0.252714f,0.999999f,3.07939e-08f,
55.1234f,15.2674f,59.3517f,-0.276936f,0.999998f,7.15092e-08f, 55.1232f,16.6217f,60.1352f,-0.301501f,0.999998f,1.559e-07f,
55.1231f,17.997f,60.9988f,-0.326446f,0.999998f,3.21788e-07f, 55.1229f,19.3953f,61.9474f,-0.35181f,0.999997f,6.33195e-07f,
55.1226f,20.819f,62.986f,-0.377632f,0.999997f,1.19466e-06f, 55.1224f,22.2705f,64.1205f,-0.403958f,0.999997f,2.17158e-06f,
55.1222f,23.7523f,65.3575f,-0.430834f,0.999996f,3.81846e-06f, 55.122f,25.2673f,66.7045f,-0.458311f,0.999996f,6.5174e-06f,
55.1217f,26.8183f,68.1698f,-0.486441f,0.999995f,1.08296e-05f, 55.1215f,28.4088f,69.763f,-0.515285f,0.999995f,1.75629e-05f,
55.1212f,30.042f,71.4945f,-0.544906f,0.999994f,2.78602e-05f, 55.1208f,31.722f,73.3766f,-0.575374f,0.999993f,4.33116e-05f,
55.1204f,33.4529f,75.4227f,-0.606763f,0.999992f,6.60975e-05f, 55.12f,35.2392f,77.6483f,-0.639157f,0.999992f,9.91675e-05f,
55.1194f,37.0859f,80.0709f,-0.672647f,0.999991f,0.000146462f, 55.1189f,38.9987f,82.7107f,-0.707334f,0.99999f,0.000213186f,
55.1182f,40.9837f,85.5904f,-0.743329f,0.999989f,0.000306142f, 55.1174f,43.0477f,88.7365f,-0.780756f,0.999987f,0.000434134f,
55.1165f,45.1984f,92.1791f,-0.819754f,0.999986f,0.000608449f, 55.1154f,47.4442f,95.9533f,-0.860478f,0.999985f,0.000843444f,
55.1142f,49.7948f,100.1f,-0.903101f,0.999983f,0.00115723f, 55.1129f,52.261f,104.666f,-0.94782f,0.999981f,0.00157247f,
55.1113f,54.8552f,109.707f,-0.994859f,0.999979f,0.00211736f, 55.1096f,57.5913f,115.289f,-1.04447f,0.999977f,0.00282672f,
55.1075f,60.4853f,121.49f,-1.09695f,0.999975f,0.00374331f, 55.1052f,63.5558f,128.401f,-1.15262f,0.999972f,0.0049193f,
55.1025f,66.824f,136.134f,-1.21188f,0.99997f,0.00641802f, 55.0994f,70.3149f,144.824f,-1.27517f,0.999966f,0.00831593f,
55.0958f,74.0574f,154.632f,-1.34303f,0.999963f,0.0107049f, 55.0916f,78.0861f,165.76f,-1.41608f,0.999958f,0.0136948f,
55.0868f,82.4415f,178.456f,-1.49505f,0.999954f,0.0174163f, 55.0813f,87.1727f,193.031f,-1.58084f,0.999948f,0.0220245f,
55.0746f,92.3385f,209.877f,-1.6745f,0.999942f,0.0277024f, 55.0669f,98.011f,229.498f,-1.77735f,0.999934f,0.0346651f,
55.0577f,104.279f,252.545f,-1.891f,0.999926f,0.0431646f, 55.0466f,111.252f,279.876f,-2.01744f,0.999915f,0.0534952f,
55.0333f,119.071f,312.641f,-2.15922f,0.999903f,0.0659987f, 55.0168f,127.915f,352.403f,-2.31958f,0.999888f,0.0810719f,
54.9965f,138.016f,401.338f,-2.50275f,0.999869f,0.0991726f, 54.9711f,149.686f,462.551f,-2.71435f,0.999845f,0.120828f,
54.9383f,163.344f,540.589f,-2.96203f,0.999815f,0.146642f, 54.8956f,179.576f,642.332f,-3.25638f,0.999776f,0.177306f,
54.8382f,199.221f,778.61f,-3.61263f,0.999722f,0.213606f, 54.7587f,223.525f,967.253f,-4.05337f,0.999648f,0.256429f,
54.6436f,254.415f,1239.34f,-4.61362f,0.999537f,0.306773f, 54.4686f,295.045f,1653.04f,-5.35054f,0.999364f,0.365739f,
54.1829f,350.909f,2327.67f,-6.36378f,0.999059f,0.434502f, 53.6679f,432.423f,3540.03f,-7.84159f,0.998362f,0.514153f,
52.5543f,561.089f,6046.28f,-10.1505f,0.993898f,0.603144f, 49.7044f,788.312f,12564.6f,-14.22f,0.986867f,0.702153f,
39.4521f,1211.34f,36744.1f,-21.3165f,0.954899f,0.785624f, 9.23487f,750.048f,72740.9f,-13.0226f,0.978507f,0.836259f,
40.4981f,-7.0808e-09f,40.4981f,-2.2256e-18f,1.0f,7.7208e-14f, 40.4981f,0.909267f,40.5186f,-0.0224487f,1.0f,2.02076e-13f,
40.4981f,1.81957f,40.5799f,-0.0449229f,1.0f,9.26449e-13f, 40.4981f,2.73193f,40.6824f,-0.067448f,1.0f,3.98504e-12f,
40.4981f,3.64742f,40.8266f,-0.0900498f,1.0f,1.58214e-11f, 40.4981f,4.56708f,41.013f,-0.112755f,0.999999f,5.9179e-11f,
40.4981f,5.492f,41.2427f,-0.135589f,0.999999f,2.08424e-10f, 40.4981f,6.42328f,41.5166f,-0.15858f,0.999999f,6.83033e-10f,
40.4981f,7.36207f,41.8361f,-0.181757f,0.999999f,2.06541e-09f, 40.498f,8.30955f,42.2027f,-0.205147f,0.999998f,5.75736e-09f,
40.498f,9.26694f,42.6181f,-0.228781f,0.999998f,1.48578e-08f, 40.4979f,10.2355f,43.0844f,-0.252691f,0.999997f,3.57364e-08f,
40.4978f,11.2166f,43.6039f,-0.27691f,0.999997f,8.06964e-08f, 40.4977f,12.2116f,44.1794f,-0.301471f,0.999996f,1.72272e-07f,
40.4976f,13.2219f,44.8139f,-0.326411f,0.999996f,3.49887e-07f, 40.4973f,14.2492f,45.5107f,-0.351769f,0.999995f,6.79831e-07f,
40.497f,15.2951f,46.2736f,-0.377587f,0.999994f,1.26977e-06f, 40.4967f,16.3614f,47.107f,-0.403906f,0.999994f,2.2893e-06f,
40.4964f,17.4499f,48.0157f,-0.430775f,0.999993f,3.9985e-06f, 40.496f,18.5628f,49.0051f,-0.458243f,0.999992f,6.78664e-06f,
40.4957f,19.7022f,50.0814f,-0.486365f,0.999991f,1.1224e-05f, 40.4953f,20.8705f,51.2515f,-0.515199f,0.99999f,1.81301e-05f,
40.4949f,22.0703f,52.5232f,-0.544809f,0.999988f,2.86616e-05f, 40.4944f,23.3043f,53.9054f,-0.575263f,0.999987f,4.44259e-05f,
40.4938f,24.5757f,55.4081f,-0.606637f,0.999986f,6.76238e-05f, 40.4932f,25.8878f,57.0425f,-0.639015f,0.999984f,0.000101229f,
40.4925f,27.2442f,58.8216f,-0.672486f,0.999983f,0.00014921f, 40.4917f,28.6491f,60.76f,-0.707152f,0.999981f,0.000216804f,
40.4907f,30.107f,62.8746f,-0.743124f,0.999979f,0.00031085f, 40.4897f,31.6228f,65.1846f,-0.780524f,0.999977f,0.00044019f,
40.4884f,33.2021f,67.7122f,-0.819492f,0.999974f,0.000616158f, 40.487f,34.8512f,70.4832f,-0.86018f,0.999971f,0.000853154f,
40.4854f,36.5772f,73.5273f,-0.902763f,0.999969f,0.00116933f, 40.4836f,38.3879f,76.8793f,-0.947436f,0.999965f,0.00158742f,
40.4815f,40.2924f,80.5799f,-0.994421f,0.999962f,0.00213564f, 40.4791f,42.3009f,84.6771f,-1.04397f,0.999958f,0.00284887f,
40.4763f,44.4251f,89.2279f,-1.09637f,0.999954f,0.00376988f, 40.4731f,46.6785f,94.2999f,-1.15196f,0.999949f,0.00495085f,
40.4695f,49.0766f,99.9744f,-1.21113f,0.999943f,0.00645511f, 40.4653f,51.6378f,106.35f,-1.27431f,0.999937f,0.00835906f,
40.4605f,54.3831f,113.545f,-1.34203f,0.99993f,0.0107545f, 40.4549f,57.3375f,121.707f,-1.41491f,0.999923f,0.013751f,
40.4484f,60.5309f,131.018f,-1.49369f,0.999914f,0.0174792f, 40.4408f,63.9987f,141.705f,-1.57924f,0.999903f,0.0220938f,
40.4319f,67.784f,154.054f,-1.67262f,0.999891f,0.027777f, 40.4214f,71.9389f,168.434f,-1.77512f,0.999878f,0.0347433f,
40.4089f,76.5278f,185.319f,-1.88832f,0.999861f,0.0432437f, 40.394f,81.6307f,205.336f,-2.01421f,0.999842f,0.053571f,
40.3759f,87.3489f,229.322f,-2.15528f,0.999818f,0.0660651f, 40.3538f,93.8114f,258.416f,-2.31472f,0.99979f,0.0811199f,
40.3265f,101.187f,294.199f,-2.49667f,0.999755f,0.0991895f, 40.292f,109.697f,338.925f,-2.70663f,0.99971f,0.120796f,
40.248f,119.642f,395.887f,-2.95203f,0.999653f,0.146536f, 40.1906f,131.441f,470.058f,-3.24313f,0.999577f,0.177089f,
40.1135f,145.684f,569.236f,-3.59459f,0.999474f,0.213225f, 40.0068f,163.245f,706.207f,-4.02794f,0.999326f,0.255805f,
39.8533f,185.46f,903.117f,-4.57613f,0.999101f,0.305783f, 39.6202f,214.468f,1201.05f,-5.29187f,0.998712f,0.364168f,
39.2406f,253.888f,1682.9f,-6.2627f,0.997716f,0.431786f, 38.5328f,310.0f,2533.46f,-7.62646f,0.99312f,0.507436f,
37.1501f,395.531f,4252.11f,-9.71721f,0.989056f,0.594533f, 33.8258f,532.908f,8428.82f,-13.0048f,0.9762f,0.684761f,
24.7682f,730.928f,20462.8f,-16.8182f,0.931491f,0.746895f, 7.20845f,430.898f,30962.4f,-10.1444f,0.984306f,0.80489f,
31.0054f,2.24926e-08f,31.0054f,-2.33637e-18f,1.0f,1.08798e-12f, 31.0054f,0.696135f,31.021f,-0.0224464f,1.0f,2.03354e-12f,
31.0054f,1.39306f,31.068f,-0.0449183f,1.0f,6.36576e-12f, 31.0054f,2.09157f,31.1464f,-0.0674409f,0.999999f,2.02107e-11f,
31.0054f,2.79246f,31.2568f,-0.0900403f,0.999999f,6.09424e-11f, 31.0054f,3.49655f,31.3995f,-0.112742f,0.999999f,1.7569e-10f,
31.0054f,4.20467f,31.5753f,-0.135574f,0.999999f,4.89303e-10f, 31.0053f,4.91766f,31.785f,-0.158562f,0.999998f,1.31906e-09f,
31.0053f,5.63639f,32.0295f,-0.181735f,0.999998f,3.42582e-09f, 31.0053f,6.36178f,32.3101f,-0.205121f,0.999997f,8.52014e-09f,
31.0052f,7.09474f,32.6281f,-0.228751f,0.999996f,2.02103e-08f, 31.0051f,7.83626f,32.985f,-0.252656f,0.999996f,4.56719e-08f,
31.005f,8.58735f,33.3827f,-0.276869f,0.999995f,9.84373e-08f, 31.0049f,9.34909f,33.8231f,-0.301424f,0.999994f,2.02855e-07f,
31.0047f,10.1226f,34.3087f,-0.326358f,0.999993f,4.00951e-07f, 31.0045f,10.9091f,34.842f,-0.351709f,0.999992f,7.62648e-07f,
31.0042f,11.7097f,35.426f,-0.377517f,0.99999f,1.40057e-06f, 31.0038f,12.526f,36.0639f,-0.403827f,0.999989f,2.49094e-06f,
31.0034f,13.3593f,36.7594f,-0.430685f,0.999987f,4.3025e-06f, 31.0029f,14.2112f,37.5167f,-0.458142f,0.999986f,7.2357e-06f,
31.0024f,15.0834f,38.3404f,-0.48625f,0.999984f,1.1875e-05f, 31.0018f,15.9776f,39.2359f,-0.515068f,0.999982f,1.90573e-05f,
31.0013f,16.896f,40.2091f,-0.544661f,0.99998f,2.9961e-05f, 31.0006f,17.8405f,41.2668f,-0.575096f,0.999978f,4.62195e-05f,
30.9999f,18.8136f,42.4166f,-0.606448f,0.999976f,7.00647e-05f, 30.9991f,19.8178f,43.6671f,-0.638801f,0.999973f,0.000104507f,
30.9981f,20.8559f,45.0283f,-0.672244f,0.99997f,0.000153557f, 30.9971f,21.931f,46.5112f,-0.706878f,0.999967f,0.0002225f,
30.9959f,23.0466f,48.1288f,-0.742814f,0.999963f,0.000318229f, 30.9945f,24.2064f,49.8959f,-0.780173f,0.99996f,0.000449647f,
30.9929f,25.4148f,51.8292f,-0.819094f,0.999955f,0.000628152f, 30.991f,26.6764f,53.9485f,-0.859729f,0.999951f,0.000868214f,
30.989f,27.9967f,56.2765f,-0.90225f,0.999946f,0.00118806f, 30.9866f,29.3816f,58.8397f,-0.946853f,0.999941f,0.00161048f,
30.9839f,30.8381f,61.6692f,-0.993757f,0.999934f,0.00216377f, 30.9807f,32.3738f,64.8016f,-1.04321f,0.999928f,0.00288285f,
30.9772f,33.9978f,68.2803f,-1.09551f,0.99992f,0.00381054f, 30.9731f,35.7202f,72.1568f,-1.15097f,0.999912f,0.00499904f,
30.9684f,37.5528f,76.4932f,-1.20999f,0.999903f,0.00651163f, 30.9629f,39.5095f,81.3642f,-1.27299f,0.999892f,0.00842465f,
30.9567f,41.6063f,86.8609f,-1.34051f,0.99988f,0.0108297f, 30.9494f,43.8621f,93.0946f,-1.41315f,0.999867f,0.0138362f,
30.9411f,46.2996f,100.204f,-1.49163f,0.999851f,0.0175744f, 30.9312f,48.9453f,108.361f,-1.57683f,0.999834f,0.0221981f,
30.9197f,51.8317f,117.784f,-1.66977f,0.999813f,0.0278891f, 30.9061f,54.9981f,128.752f,-1.77173f,0.999789f,0.0348606f,
30.89f,58.4931f,141.625f,-1.88427f,0.999761f,0.043362f, 30.8706f,62.3763f,156.878f,-2.00933f,0.999727f,0.0536838f,
30.8473f,66.7238f,175.143f,-2.14932f,0.999686f,0.0661631f, 30.8189f,71.6316f,197.28f,-2.30737f,0.999636f,0.0811895f,
30.7835f,77.2244f,224.481f,-2.48749f,0.999573f,0.0992116f, 30.7393f,83.6668f,258.44f,-2.69498f,0.999494f,0.120743f,
30.6829f,91.1802f,301.624f,-2.93695f,0.999391f,0.14637f, 30.6092f,100.067f,357.746f,-3.22318f,0.999252f,0.176754f,
30.5105f,110.755f,432.599f,-3.56744f,0.999056f,0.212638f, 30.3745f,123.867f,535.607f,-3.98965f,0.998753f,0.254837f,
30.1788f,140.33f,682.941f,-4.51931f,0.998179f,0.304178f, 29.876f,161.551f,903.731f,-5.19663f,0.996062f,0.360834f,
29.3825f,189.816f,1256.0f,-6.0947f,0.992666f,0.425681f, 28.5481f,229.114f,1868.63f,-7.34775f,0.989311f,0.500417f,
26.9459f,285.604f,3055.3f,-9.12173f,0.981092f,0.581565f, 23.5217f,366.272f,5685.27f,-11.5301f,0.961786f,0.661202f,
16.6375f,458.056f,11251.6f,-13.0219f,0.911425f,0.706698f, 5.86884f,268.793f,14875.3f,-8.24348f,0.988036f,0.770993f,
24.4969f,2.42112e-09f,24.4969f,-2.666e-18f,0.999999f,1.10653e-11f, 24.4969f,0.550007f,24.5093f,-0.0224432f,0.999999f,1.67722e-11f,
24.4969f,1.10064f,24.5464f,-0.0449118f,0.999999f,3.93982e-11f, 24.4969f,1.65252f,24.6083f,-0.0674311f,0.999999f,9.91341e-11f,
24.4969f,2.20628f,24.6955f,-0.0900269f,0.999998f,2.44171e-10f, 24.4969f,2.76257f,24.8083f,-0.112725f,0.999998f,5.82311e-10f,
24.4969f,3.32205f,24.9471f,-0.135552f,0.999997f,1.3513e-09f, 24.4969f,3.88537f,25.1127f,-0.158536f,0.999997f,3.06904e-09f,
24.4968f,4.45322f,25.3059f,-0.181704f,0.999996f,6.83823e-09f, 24.4968f,5.02633f,25.5275f,-0.205085f,0.999995f,1.49294e-08f,
24.4967f,5.60543f,25.7786f,-0.228709f,0.999994f,3.18358e-08f, 24.4967f,6.19128f,26.0605f,-0.252607f,0.999992f,6.60854e-08f,
24.4965f,6.78469f,26.3746f,-0.276812f,0.999991f,1.33216e-07f, 24.4964f,7.3865f,26.7225f,-0.301359f,0.99999f,2.60471e-07f,
24.4962f,7.9976f,27.106f,-0.326283f,0.999988f,4.93947e-07f, 24.496f,8.61894f,27.5271f,-0.351623f,0.999986f,9.09167e-07f,
24.4957f,9.2515f,27.9883f,-0.37742f,0.999984f,1.62629e-06f, 24.4952f,9.89635f,28.4921f,-0.403716f,0.999982f,2.83151e-06f,
24.4947f,10.5546f,29.0414f,-0.430559f,0.99998f,4.80648e-06f, 24.4942f,11.2276f,29.6395f,-0.457998f,0.999977f,7.96813e-06f,
24.4935f,11.9165f,30.29f,-0.486086f,0.999974f,1.29216e-05f, 24.4928f,12.6228f,30.9971f,-0.514883f,0.999971f,2.05294e-05f,
24.492f,13.3482f,31.7656f,-0.544451f,0.999968f,3.20013e-05f, 24.4911f,14.0941f,32.6006f,-0.574858f,0.999964f,4.9008e-05f,
24.4902f,14.8626f,33.5083f,-0.606179f,0.99996f,7.38261e-05f, 24.4892f,15.6557f,34.4955f,-0.638496f,0.999956f,0.000109518f,
24.488f,16.4754f,35.5699f,-0.671899f,0.999951f,0.000160154f, 24.4866f,17.3243f,36.7403f,-0.706488f,0.999946f,0.000231089f,
24.4851f,18.2051f,38.017f,-0.742371f,0.999941f,0.000329291f, 24.4833f,19.1207f,39.4113f,-0.779672f,0.999934f,0.000463748f,
24.4814f,20.0745f,40.9368f,-0.818526f,0.999928f,0.000645947f, 24.4791f,21.0702f,42.6088f,-0.859084f,0.99992f,0.000890454f,
24.4764f,22.1121f,44.4452f,-0.901519f,0.999912f,0.00121559f, 24.4735f,23.2048f,46.4668f,-0.946021f,0.999904f,0.00164425f,
24.4701f,24.3537f,48.6982f,-0.99281f,0.999894f,0.00220481f, 24.4662f,25.5649f,51.1681f,-1.04213f,0.999883f,0.00293226f,
24.4617f,26.8453f,53.9104f,-1.09427f,0.999871f,0.00386947f, 24.4566f,28.203f,56.9659f,-1.14956f,0.999857f,0.00506864f,
24.4507f,29.6471f,60.3829f,-1.20836f,0.999842f,0.00659302f, 24.4439f,31.1885f,64.2203f,-1.27112f,0.999825f,0.00851882f,
24.4361f,32.8395f,68.5493f,-1.33834f,0.999806f,0.0109374f, 24.4271f,34.6149f,73.4572f,-1.41063f,0.999784f,0.0139578f,
24.4166f,36.5322f,79.0522f,-1.48869f,0.999758f,0.0177096f, 24.4043f,38.6121f,85.4693f,-1.57338f,0.999729f,0.0223461f,
24.39f,40.8797f,92.8788f,-1.6657f,0.999696f,0.0280475f, 24.373f,43.3652f,101.498f,-1.7669f,0.999656f,0.0350255f,
24.353f,46.106f,111.608f,-1.8785f,0.999609f,0.0435273f, 24.3289f,49.1479f,123.578f,-2.00236f,0.999553f,0.0538402f,
24.2999f,52.5486f,137.898f,-2.14083f,0.999484f,0.0662971f, 24.2644f,56.3812f,155.234f,-2.29691f,0.999399f,0.0812816f,
24.2207f,60.7406f,176.508f,-2.47442f,0.999293f,0.099234f, 24.166f,65.75f,203.021f,-2.67839f,0.999153f,0.120656f,
24.0959f,71.5724f,236.665f,-2.9155f,0.998965f,0.146115f, 24.005f,78.4324f,280.267f,-3.19476f,0.998689f,0.176242f,
23.8836f,86.6388f,338.197f,-3.5285f,0.998216f,0.211707f, 23.7138f,96.6189f,417.429f,-3.93246f,0.996994f,0.253004f,
23.4627f,108.974f,529.572f,-4.42711f,0.99403f,0.300293f, 23.0999f,124.712f,696.482f,-5.06217f,0.991985f,0.355864f,
22.5328f,145.229f,958.991f,-5.88752f,0.988765f,0.419367f, 21.5858f,172.596f,1402.14f,-6.97591f,0.982566f,0.489926f,
19.9019f,209.441f,2217.55f,-8.39888f,0.970873f,0.564843f, 16.7576f,255.73f,3822.94f,-9.98099f,0.945704f,0.633295f,
11.453f,287.313f,6431.34f,-10.2239f,0.898976f,0.669543f, 4.67985f,171.212f,7939.0f,-6.88497f,0.990575f,0.735915f,
19.8412f,-4.60924e-08f,19.8412f,1.14472e-18f,0.999998f,8.65815e-11f, 19.8412f,0.445476f,19.8512f,-0.022439f,0.999998f,1.14918e-10f,
19.8412f,0.891458f,19.8812f,-0.0449032f,0.999998f,2.17544e-10f, 19.8412f,1.33845f,19.9314f,-0.0674181f,0.999997f,4.54914e-10f,
19.8412f,1.78697f,20.002f,-0.0900091f,0.999997f,9.56147e-10f, 19.8412f,2.23754f,20.0933f,-0.112702f,0.999996f,1.97398e-09f,
19.8412f,2.69067f,20.2057f,-0.135524f,0.999995f,3.99288e-09f, 19.8412f,3.14693f,20.3398f,-0.158502f,0.999994f,7.93642e-09f,
19.8411f,3.60686f,20.4962f,-0.181663f,0.999993f,1.55546e-08f, 19.8411f,4.07104f,20.6756f,-0.205036f,0.999991f,3.01219e-08f,
19.841f,4.54006f,20.8789f,-0.228652f,0.99999f,5.76475e-08f, 19.8409f,5.01456f,21.1071f,-0.252541f,0.999988f,1.08891e-07f,
19.8408f,5.49517f,21.3614f,-0.276736f,0.999986f,2.026e-07f, 19.8406f,5.98258f,21.643f,-0.301272f,0.999983f,3.70523e-07f,
19.8404f,6.47751f,21.9534f,-0.326183f,0.999981f,6.64965e-07f, 19.8402f,6.98071f,22.2943f,-0.351508f,0.999978f,1.16982e-06f,
19.8398f,7.493f,22.6676f,-0.377288f,0.999975f,2.01636e-06f, 19.8394f,8.01523f,23.0754f,-0.403566f,0.999972f,3.40522e-06f,
19.8389f,8.54831f,23.52f,-0.430388f,0.999968f,5.6366e-06f, 19.8382f,9.09322f,24.0041f,-0.457803f,0.999964f,9.15083e-06f,
19.8374f,9.65104f,24.5306f,-0.485866f,0.99996f,1.45821e-05f, 19.8365f,10.2229f,25.103f,-0.514633f,0.999955f,2.28288e-05f,
19.8355f,10.8101f,25.7249f,-0.544167f,0.99995f,3.51437e-05f, 19.8345f,11.414f,26.4006f,-0.574536f,0.999944f,5.32493e-05f,
19.8333f,12.0361f,27.135f,-0.605814f,0.999938f,7.94829e-05f, 19.832f,12.678f,27.9336f,-0.638083f,0.999931f,0.000116977f,
19.8305f,13.3414f,28.8027f,-0.671431f,0.999924f,0.000169885f, 19.8289f,14.0284f,29.7494f,-0.705958f,0.999916f,0.000243651f,
19.827f,14.7411f,30.7818f,-0.741771f,0.999908f,0.000345345f, 19.8249f,15.4819f,31.9092f,-0.778992f,0.999898f,0.000484068f,
19.8224f,16.2534f,33.1425f,-0.817754f,0.999888f,0.000671425f, 19.8197f,17.0587f,34.494f,-0.858209f,0.999877f,0.000922105f,
19.8165f,17.9012f,35.9782f,-0.900524f,0.999864f,0.00125456f, 19.8129f,18.7845f,37.6118f,-0.94489f,0.999851f,0.00169179f,
19.8087f,19.713f,39.4145f,-0.991521f,0.999835f,0.00226229f, 19.804f,20.6916f,41.4095f,-1.04066f,0.999819f,0.00300114f,
19.7986f,21.7258f,43.6239f,-1.09259f,0.9998f,0.00395126f, 19.7924f,22.822f,46.0904f,-1.14763f,0.999779f,0.00516483f,
19.7852f,23.9875f,48.8481f,-1.20614f,0.999755f,0.00670503f, 19.777f,25.2308f,51.9438f,-1.26856f,0.999728f,0.00864787f,
19.7675f,26.5618f,55.4349f,-1.33539f,0.999698f,0.0110844f, 19.7566f,27.9923f,59.391f,-1.4072f,0.999664f,0.0141231f,
19.7438f,29.5359f,63.8987f,-1.48469f,0.999624f,0.0178927f, 19.729f,31.2092f,69.0657f,-1.56869f,0.999578f,0.0225452f,
19.7116f,33.0315f,75.0278f,-1.66017f,0.999524f,0.0282595f, 19.6912f,35.0269f,81.9582f,-1.76034f,0.99946f,0.0352447f,
19.6669f,37.2243f,90.08f,-1.87065f,0.999384f,0.043745f, 19.6378f,39.6592f,99.6852f,-1.99289f,0.999292f,0.0540431f,
19.6029f,42.3765f,111.162f,-2.1293f,0.999177f,0.0664659f, 19.5603f,45.4324f,125.036f,-2.2827f,0.999031f,0.081388f,
19.5077f,48.8985f,142.027f,-2.45666f,0.998835f,0.099236f, 19.4418f,52.8672f,163.155f,-2.65578f,0.998555f,0.120488f,
19.358f,57.4611f,189.879f,-2.88593f,0.998084f,0.145653f, 19.2473f,62.8366f,224.341f,-3.15388f,0.996993f,0.17515f,
19.0948f,69.1981f,269.757f,-3.46755f,0.994577f,0.209226f, 18.8907f,76.8704f,331.581f,-3.84825f,0.992697f,0.249436f,
18.6289f,86.3778f,418.54f,-4.31716f,0.991002f,0.296484f, 18.1973f,98.0177f,546.224f,-4.89755f,0.987921f,0.350228f,
17.5703f,112.861f,742.554f,-5.62478f,0.982719f,0.410664f, 16.5815f,131.841f,1063.02f,-6.53726f,0.974598f,0.477166f,
14.9883f,155.939f,1614.08f,-7.60388f,0.958518f,0.544494f, 12.5661f,185.332f,2546.19f,-8.53269f,0.929179f,0.60224f,
8.51345f,190.654f,3797.74f,-8.24626f,0.892694f,0.634654f, 4.00124f,118.458f,4463.6f,-5.86747f,0.992381f,0.700473f,
16.3963f,3.94977e-09f,16.3963f,-4.91823e-18f,0.999996f,5.45034e-10f, 16.3963f,0.36813f,16.4045f,-0.0224337f,0.999996f,6.63839e-10f,
16.3963f,0.736677f,16.4293f,-0.0448925f,0.999995f,1.06991e-09f, 16.3963f,1.10606f,16.4708f,-0.0674016f,0.999995f,1.92663e-09f,
16.3963f,1.4767f,16.5291f,-0.0899867f,0.999994f,3.55848e-09f, 16.3963f,1.84904f,16.6045f,-0.112673f,0.999993f,6.54459e-09f,
16.3962f,2.2235f,16.6973f,-0.135488f,0.999991f,1.18873e-08f, 16.3962f,2.60053f,16.8081f,-0.158458f,0.99999f,2.13072e-08f,
16.3962f,2.9806f,16.9373f,-0.181611f,0.999988f,3.7753e-08f, 16.3961f,3.36417f,17.0854f,-0.204975f,0.999986f,6.62651e-08f,
16.396f,3.75175f,17.2533f,-0.22858f,0.999983f,1.15403e-07f, 16.3959f,4.14385f,17.4418f,-0.252458f,0.999981f,1.99542e-07f,
16.3958f,4.54099f,17.6518f,-0.27664f,0.999977f,3.42456e-07f, 16.3956f,4.94375f,17.8843f,-0.30116f,0.999974f,5.82769e-07f,
16.3954f,5.35271f,18.1407f,-0.326054f,0.99997f,9.82018e-07f, 16.3951f,5.7685f,18.4222f,-0.35136f,0.999966f,1.63631e-06f,
16.3948f,6.19178f,18.7304f,-0.377119f,0.999962f,2.69279e-06f, 16.3943f,6.62326f,19.067f,-0.403373f,0.999957f,4.37248e-06f,
16.3937f,7.0637f,19.4341f,-0.430168f,0.999951f,7.00133e-06f, 16.393f,7.51388f,19.8338f,-0.457553f,0.999945f,1.10518e-05f,
16.3921f,7.97469f,20.2685f,-0.485581f,0.999939f,1.71975e-05f, 16.3911f,8.44708f,20.741f,-0.514309f,0.999932f,2.63849e-05f,
16.39f,8.93206f,21.2543f,-0.543799f,0.999924f,3.99242e-05f, 16.3887f,9.43078f,21.8121f,-0.574118f,0.999916f,5.96061e-05f,
16.3872f,9.94444f,22.4182f,-0.605341f,0.999907f,8.78475e-05f, 16.3856f,10.4744f,23.0772f,-0.637547f,0.999897f,0.000127873f,
16.3839f,11.0221f,23.7942f,-0.670824f,0.999886f,0.000183939f, 16.3819f,11.5892f,24.575f,-0.705269f,0.999874f,0.000261608f,
16.3797f,12.1774f,25.4264f,-0.74099f,0.999862f,0.00036808f, 16.3771f,12.7886f,26.3561f,-0.778106f,0.999848f,0.000512593f,
16.3742f,13.4251f,27.3728f,-0.81675f,0.999832f,0.000706901f, 16.3709f,14.0894f,28.4868f,-0.857068f,0.999815f,0.000965847f,
16.3672f,14.784f,29.7098f,-0.899227f,0.999797f,0.00130803f, 16.3629f,15.5122f,31.0557f,-0.943414f,0.999776f,0.0017566f,
16.358f,16.2773f,32.5404f,-0.989839f,0.999753f,0.00234017f, 16.3524f,17.0834f,34.1829f,-1.03874f,0.999728f,0.00309391f,
16.346f,17.935f,36.0056f,-1.0904f,0.999699f,0.00406077f, 16.3386f,18.837f,38.0351f,-1.14511f,0.999667f,0.00529292f,
16.3302f,19.7956f,40.3031f,-1.20325f,0.999631f,0.00685336f, 16.3205f,20.8176f,42.848f,-1.26523f,0.999591f,0.00881782f,
16.3093f,21.9109f,45.7164f,-1.33153f,0.999544f,0.0112768f, 16.2963f,23.0849f,48.9653f,-1.40272f,0.999491f,0.0143382f,
16.2814f,24.3506f,52.6645f,-1.47946f,0.999429f,0.0181293f, 16.2638f,25.721f,56.9017f,-1.56256f,0.999357f,0.0228008f,
16.2434f,27.2118f,61.7866f,-1.65295f,0.999271f,0.028529f, 16.2193f,28.8416f,67.4589f,-1.75176f,0.999167f,0.0355199f,
16.1907f,30.6334f,74.0985f,-1.86039f,0.99904f,0.0440127f, 16.1567f,32.6152f,81.94f,-1.9805f,0.998877f,0.0542833f,
16.1156f,34.8211f,91.2937f,-2.11417f,0.99866f,0.0666468f, 16.0657f,37.2947f,102.576f,-2.26391f,0.998341f,0.0814559f,
16.0037f,40.0889f,116.355f,-2.43271f,0.997789f,0.0990801f, 15.9246f,43.2696f,133.405f,-2.62339f,0.996535f,0.119796f,
15.8217f,46.9209f,154.841f,-2.84058f,0.994491f,0.144007f, 15.691f,51.1693f,182.405f,-3.0949f,0.992887f,0.172768f,
15.5234f,56.1772f,218.673f,-3.39629f,0.99169f,0.20679f, 15.2961f,62.1325f,267.543f,-3.75295f,0.989618f,0.246152f,
14.9851f,69.3193f,335.537f,-4.18246f,0.987009f,0.29166f, 14.5387f,78.0546f,433.405f,-4.69805f,0.98224f,0.342912f,
13.8878f,88.768f,580.506f,-5.32314f,0.975737f,0.400348f, 12.9077f,101.777f,810.47f,-6.0476f,0.963792f,0.460989f,
11.4617f,117.173f,1178.99f,-6.81008f,0.945316f,0.521534f, 9.38415f,132.159f,1732.16f,-7.2963f,0.914668f,0.570262f,
6.38203f,126.938f,2361.85f,-6.82417f,0.891257f,0.601666f, 3.47557f,84.9034f,2653.16f,-5.08099f,0.993711f,0.665208f,
13.7759f,5.99626e-08f,13.7759f,-2.74119e-18f,0.999992f,2.85095e-09f, 13.7759f,0.309295f,13.7828f,-0.0224273f,0.999991f,3.28035e-09f,
13.7759f,0.618941f,13.8036f,-0.0448795f,0.999991f,4.69319e-09f, 13.7759f,0.92929f,13.8384f,-0.0673819f,0.99999f,7.48882e-09f,
13.7759f,1.2407f,13.8874f,-0.0899598f,0.999989f,1.24223e-08f, 13.7759f,1.55352f,13.9507f,-0.112639f,0.999987f,2.07574e-08f,
13.7758f,1.86813f,14.0287f,-0.135445f,0.999985f,3.45258e-08f, 13.7758f,2.18491f,14.1217f,-0.158406f,0.999983f,5.69489e-08f,
13.7758f,2.50423f,14.2301f,-0.181548f,0.99998f,9.31212e-08f, 13.7757f,2.82649f,14.3545f,-0.204901f,0.999977f,1.511e-07f,
13.7756f,3.15212f,14.4955f,-0.228493f,0.999973f,2.43628e-07f, 13.7755f,3.48153f,14.6537f,-0.252356f,0.999969f,3.90791e-07f,
13.7754f,3.81519f,14.83f,-0.276521f,0.999965f,6.24057e-07f, 13.7752f,4.15355f,15.0252f,-0.301023f,0.99996f,9.92273e-07f,
13.775f,4.49711f,15.2403f,-0.325896f,0.999955f,1.57037e-06f, 13.7746f,4.84641f,15.4766f,-0.351179f,0.999949f,2.47179e-06f,
13.7743f,5.20198f,15.7353f,-0.376911f,0.999942f,3.86579e-06f, 13.7738f,5.56443f,16.0178f,-0.403135f,0.999935f,6.00127e-06f,
13.7731f,5.93437f,16.3258f,-0.429895f,0.999927f,9.23887e-06f, 13.7724f,6.31249f,16.6612f,-0.457242f,0.999918f,1.40937e-05f,
13.7715f,6.6995f,17.026f,-0.485227f,0.999909f,2.12914e-05f, 13.7704f,7.0962f,17.4224f,-0.513906f,0.999899f,3.18404e-05f,
13.7691f,7.50341f,17.8531f,-0.543341f,0.999888f,4.71249e-05f, 13.7675f,7.92209f,18.321f,-0.573598f,0.999876f,6.90221e-05f,
13.7659f,8.35326f,18.8294f,-0.60475f,0.999863f,0.000100049f, 13.764f,8.79803f,19.382f,-0.636876f,0.999848f,0.000143545f,
13.7619f,9.25762f,19.9832f,-0.670063f,0.999833f,0.000203894f, 13.7596f,9.73337f,20.6378f,-0.704406f,0.999816f,0.000286804f,
13.757f,10.2268f,21.3513f,-0.740011f,0.999797f,0.000399629f, 13.754f,10.7394f,22.1302f,-0.776995f,0.999776f,0.000551774f,
13.7507f,11.273f,22.9819f,-0.815488f,0.999754f,0.00075517f, 13.7469f,11.8298f,23.9148f,-0.855635f,0.999729f,0.00102483f,
13.7425f,12.4118f,24.9387f,-0.897597f,0.999702f,0.00137953f, 13.7375f,13.0217f,26.065f,-0.941558f,0.999671f,0.00184257f,
13.7319f,13.6623f,27.3072f,-0.987723f,0.999637f,0.0024427f, 13.7254f,14.3368f,28.6808f,-1.03633f,0.9996f,0.00321515f,
13.718f,15.049f,30.2045f,-1.08763f,0.999557f,0.00420288f, 13.7095f,15.8029f,31.9003f,-1.14194f,0.999509f,0.00545796f,
13.6998f,16.6036f,33.7944f,-1.1996f,0.999455f,0.00704313f, 13.6885f,17.4565f,35.9186f,-1.26102f,0.999393f,0.00903366f,
13.6756f,18.368f,38.3112f,-1.32666f,0.999321f,0.0115193f, 13.6607f,19.3459f,41.0191f,-1.39706f,0.999237f,0.0146068f,
13.6434f,20.3989f,44.0998f,-1.47286f,0.999138f,0.0184218f, 13.6233f,21.5375f,47.6251f,-1.55481f,0.999017f,0.0231122f,
13.5998f,22.7741f,51.6847f,-1.64379f,0.998868f,0.0288505f, 13.572f,24.1235f,56.3926f,-1.74086f,0.998674f,0.0358363f,
13.5392f,25.6039f,61.8946f,-1.84724f,0.998406f,0.0442969f, 13.4999f,27.2365f,68.3786f,-1.96436f,0.997988f,0.0544821f,
13.4522f,29.0472f,76.0895f,-2.09363f,0.997216f,0.0666346f, 13.3917f,31.0638f,85.3385f,-2.23581f,0.995498f,0.0808845f,
13.3181f,33.3321f,96.6063f,-2.39638f,0.993982f,0.0979424f, 13.228f,35.9049f,110.535f,-2.57963f,0.992835f,0.118346f,
13.1165f,38.8497f,128.024f,-2.78997f,0.991819f,0.142564f, 12.9734f,42.242f,150.344f,-3.03128f,0.990213f,0.170851f,
12.7886f,46.1917f,179.46f,-3.31209f,0.98833f,0.203906f, 12.5478f,50.8433f,218.32f,-3.64063f,0.985741f,0.242123f,
12.214f,56.3159f,271.558f,-4.02336f,0.981317f,0.285374f, 11.7571f,62.8296f,346.898f,-4.47493f,0.975761f,0.334385f,
11.1313f,70.6444f,456.397f,-4.99034f,0.966367f,0.387454f, 10.2371f,79.7122f,620.144f,-5.55475f,0.952903f,0.44336f,
9.01896f,89.8022f,861.76f,-6.06686f,0.931512f,0.496193f, 7.50925f,99.2579f,1177.19f,-6.28275f,0.903496f,0.538733f,
5.34738f,93.0214f,1485.73f,-5.76543f,0.894006f,0.570918f, 3.05867f,62.6631f,1652.09f,-4.45806f,0.994719f,0.630497f,
11.7363f,3.90724e-07f,11.7363f,-1.98168e-18f,0.999983f,1.2693e-08f, 11.7363f,0.263502f,11.7422f,-0.02242f,0.999983f,1.40527e-08f,
11.7363f,0.527304f,11.76f,-0.0448648f,0.999982f,1.84135e-08f, 11.7363f,0.791703f,11.7896f,-0.0673593f,0.999981f,2.66614e-08f,
11.7363f,1.057f,11.8313f,-0.0899289f,0.999979f,4.04168e-08f, 11.7363f,1.32351f,11.8852f,-0.112599f,0.999977f,6.22715e-08f,
11.7363f,1.59154f,11.9516f,-0.135395f,0.999974f,9.61737e-08f, 11.7363f,1.86141f,12.0307f,-0.158345f,0.999971f,1.48024e-07f,
11.7363f,2.13345f,12.123f,-0.181475f,0.999967f,2.26587e-07f, 11.7362f,2.408f,12.2289f,-0.204814f,0.999963f,3.44883e-07f,
11.7361f,2.6854f,12.3489f,-0.228391f,0.999958f,5.22274e-07f, 11.736f,2.96603f,12.4836f,-0.252236f,0.999952f,7.8759e-07f,
11.7359f,3.25027f,12.6336f,-0.276382f,0.999946f,1.18372e-06f, 11.7357f,3.53851f,12.7997f,-0.300861f,0.999939f,1.77428e-06f,
11.7354f,3.83117f,12.9828f,-0.325709f,0.999931f,2.65306e-06f, 11.7351f,4.1287f,13.1839f,-0.350964f,0.999923f,3.95739e-06f,
11.7347f,4.43157f,13.404f,-0.376664f,0.999913f,5.8864e-06f, 11.7341f,4.74028f,13.6443f,-0.402851f,0.999903f,8.726e-06f,
11.7335f,5.05536f,13.9063f,-0.42957f,0.999892f,1.28821e-05f, 11.7327f,5.37738f,14.1916f,-0.45687f,0.99988f,1.89248e-05f,
11.7317f,5.70694f,14.5018f,-0.484802f,0.999867f,2.76454e-05f, 11.7306f,6.0447f,14.8389f,-0.513422f,0.999852f,4.01304e-05f,
11.7291f,6.39139f,15.2052f,-0.54279f,0.999836f,5.78554e-05f, 11.7275f,6.74777f,15.6031f,-0.572971f,0.999819f,8.28035e-05f,
11.7256f,7.1147f,16.0353f,-0.604037f,0.999801f,0.000117613f, 11.7235f,7.49312f,16.5051f,-0.636066f,0.99978f,0.00016576f,
11.7211f,7.88408f,17.016f,-0.669142f,0.999758f,0.000231781f, 11.7184f,8.28868f,17.5721f,-0.70336f,0.999733f,0.000321551f,
11.7154f,8.70817f,18.1781f,-0.738823f,0.999706f,0.000442603f, 11.712f,9.1439f,18.8395f,-0.775645f,0.999676f,0.000604533f,
11.7082f,9.59739f,19.5624f,-0.813953f,0.999644f,0.000819462f, 11.7039f,10.0703f,20.354f,-0.853889f,0.999607f,0.0011026f,
11.6989f,10.5645f,21.2225f,-0.89561f,0.999567f,0.00147289f, 11.6933f,11.0821f,22.1774f,-0.939293f,0.999522f,0.00195378f,
11.6869f,11.6255f,23.2302f,-0.985139f,0.999472f,0.00257411f, 11.6796f,12.1974f,24.3939f,-1.03337f,0.999415f,0.00336916f,
11.6712f,12.8007f,25.684f,-1.08425f,0.999351f,0.00438179f, 11.6616f,13.439f,27.1189f,-1.13806f,0.999277f,0.00566379f,
11.6506f,14.1162f,28.7208f,-1.19513f,0.999191f,0.00727744f, 11.6379f,14.8369f,30.5158f,-1.25586f,0.99909f,0.00929714f,
11.6233f,15.6064f,32.536f,-1.32067f,0.99897f,0.0118113f, 11.6065f,16.4307f,34.8202f,-1.39007f,0.998821f,0.0149241f,
11.5871f,17.3172f,37.4161f,-1.46466f,0.99863f,0.0187574f, 11.5643f,18.2738f,40.3828f,-1.54508f,0.99837f,0.0234515f,
11.5376f,19.3107f,43.7936f,-1.63206f,0.997983f,0.0291628f, 11.5059f,20.4391f,47.7392f,-1.72629f,0.997326f,0.0360509f,
11.4675f,21.6715f,52.3317f,-1.82817f,0.996059f,0.0442391f, 11.421f,23.0245f,57.7275f,-1.93978f,0.994593f,0.0540478f,
11.3657f,24.5203f,64.135f,-2.06359f,0.993266f,0.0658656f, 11.3006f,26.1865f,71.8402f,-2.20306f,0.992593f,0.0802185f,
11.2212f,28.0508f,81.1862f,-2.35865f,0.991609f,0.0972204f, 11.1234f,30.1498f,92.6672f,-2.53304f,0.990163f,0.117224f,
11.0022f,32.5322f,107.01f,-2.73169f,0.98881f,0.140898f, 10.8505f,35.2566f,125.21f,-2.95828f,0.987081f,0.168587f,
10.6558f,38.3882f,148.685f,-3.2154f,0.984024f,0.200344f, 10.4007f,42.0026f,179.659f,-3.51026f,0.979993f,0.236741f,
10.0664f,46.204f,221.541f,-3.85061f,0.975133f,0.278285f, 9.62505f,51.1037f,279.274f,-4.23208f,0.967194f,0.32385f,
9.16809f,57.5992f,357.451f,-4.65117f,0.956245f,0.37304f, 8.39794f,64.1557f,473.037f,-5.0751f,0.940999f,0.423588f,
7.40069f,70.9626f,628.402f,-5.40459f,0.919015f,0.470083f, 6.11354f,74.999f,814.88f,-5.45744f,0.896602f,0.508831f,
4.50392f,68.5966f,968.41f,-4.94977f,0.899091f,0.541559f, 2.72141f,47.392f,1069.85f,-3.95451f,0.995499f,0.596608f,
10.1178f,-1.10834e-07f,10.1178f,-1.77028e-18f,0.999968f,4.89937e-08f, 10.1178f,0.227162f,10.1229f,-0.022412f,0.999968f,5.28151e-08f,
10.1178f,0.454581f,10.1381f,-0.0448486f,0.999967f,6.48566e-08f, 10.1178f,0.682517f,10.1637f,-0.0673345f,0.999965f,8.69126e-08f,
10.1178f,0.911229f,10.1996f,-0.0898949f,0.999963f,1.22188e-07f, 10.1178f,1.14098f,10.246f,-0.112555f,0.99996f,1.75648e-07f,
10.1178f,1.37204f,10.3032f,-0.13534f,0.999956f,2.54561e-07f, 10.1178f,1.60469f,10.3714f,-0.158278f,0.999951f,3.6932e-07f,
10.1178f,1.83921f,10.4509f,-0.181394f,0.999946f,5.34642e-07f, 10.1177f,2.07589f,10.5421f,-0.204717f,0.99994f,7.71319e-07f,
10.1176f,2.31503f,10.6454f,-0.228276f,0.999933f,1.10876e-06f, 10.1175f,2.55694f,10.7614f,-0.252101f,0.999925f,1.58866e-06f,
10.1174f,2.80196f,10.8906f,-0.276224f,0.999916f,2.27025e-06f, 10.1172f,3.05042f,11.0336f,-0.300678f,0.999906f,3.23772e-06f,
10.1169f,3.30269f,11.1912f,-0.325496f,0.999895f,4.61055e-06f, 10.1166f,3.55914f,11.3643f,-0.350717f,0.999884f,6.55787e-06f,
10.1162f,3.82019f,11.5537f,-0.376379f,0.99987f,9.31783e-06f, 10.1156f,4.08624f,11.7606f,-0.402523f,0.999856f,1.32238e-05f,
10.1149f,4.35778f,11.986f,-0.429194f,0.999841f,1.87387e-05f, 10.1141f,4.63526f,12.2315f,-0.456439f,0.999823f,2.6501e-05f,
10.1131f,4.91922f,12.4983f,-0.484308f,0.999805f,3.73824e-05f, 10.1119f,5.21022f,12.7883f,-0.512857f,0.999784f,5.25636e-05f,
10.1104f,5.50886f,13.1034f,-0.542145f,0.999762f,7.36291e-05f, 10.1086f,5.81579f,13.4456f,-0.572236f,0.999738f,0.000102686f,
10.1066f,6.13173f,13.8173f,-0.603199f,0.999711f,0.000142514f, 10.1042f,6.45748f,14.2212f,-0.635111f,0.999681f,0.000196745f,
10.1015f,6.79393f,14.6603f,-0.668056f,0.999649f,0.000270088f, 10.0985f,7.14202f,15.1381f,-0.702124f,0.999614f,0.000368601f,
10.0952f,7.50281f,15.6587f,-0.737416f,0.999574f,0.000500013f, 10.0914f,7.87745f,16.2266f,-0.774044f,0.999531f,0.000674116f,
10.0871f,8.2672f,16.8471f,-0.812131f,0.999483f,0.000903226f, 10.0823f,8.6735f,17.5262f,-0.851813f,0.999429f,0.00120273f,
10.0768f,9.09788f,18.271f,-0.893242f,0.999368f,0.00159171f, 10.0706f,9.5421f,19.0896f,-0.93659f,0.999299f,0.00209371f,
10.0635f,10.0082f,19.9916f,-0.982047f,0.99922f,0.00273756f, 10.0553f,10.4983f,20.9879f,-1.02983f,0.999128f,0.00355836f,
10.046f,11.015f,22.0919f,-1.08017f,0.99902f,0.00459856f, 10.0354f,11.5612f,23.3189f,-1.13336f,0.998891f,0.00590914f,
10.0232f,12.14f,24.6874f,-1.18969f,0.99873f,0.00755082f, 10.0091f,12.7554f,26.2197f,-1.2495f,0.998524f,0.00959507f,
9.99302f,13.4114f,27.9419f,-1.31317f,0.99824f,0.0121245f, 9.97415f,14.1129f,29.8865f,-1.38107f,0.997821f,0.0152307f,
9.9521f,14.8655f,32.0916f,-1.45352f,0.997137f,0.0190069f, 9.92591f,15.6752f,34.6026f,-1.53061f,0.995926f,0.0235277f,
9.89479f,16.5497f,37.4831f,-1.61386f,0.994644f,0.0290178f, 9.8584f,17.4988f,40.8116f,-1.70439f,0.993414f,0.0356946f,
9.81669f,18.5354f,44.6961f,-1.80464f,0.992867f,0.0439429f, 9.76722f,19.6707f,49.2525f,-1.91419f,0.992111f,0.0538265f,
9.70829f,20.9204f,54.6428f,-2.0343f,0.991056f,0.0655967f, 9.63764f,22.3031f,61.0859f,-2.16714f,0.989859f,0.0796103f,
9.55322f,23.8435f,68.8871f,-2.31599f,0.988919f,0.0963756f, 9.4502f,25.5669f,78.4297f,-2.48191f,0.987554f,0.116081f,
9.32461f,27.5096f,90.2467f,-2.66693f,0.985397f,0.138992f, 9.16305f,29.6915f,105.105f,-2.87357f,0.982183f,0.165376f,
8.96685f,32.1914f,124.121f,-3.10802f,0.978633f,0.195972f, 8.71305f,35.0273f,148.913f,-3.37232f,0.974015f,0.230864f,
8.38879f,38.2659f,181.725f,-3.66439f,0.967008f,0.269556f, 7.98321f,42.0038f,225.848f,-3.98306f,0.957576f,0.311913f,
7.46913f,46.2446f,285.742f,-4.3185f,0.945789f,0.357366f, 6.82528f,50.8752f,365.489f,-4.62425f,0.928951f,0.402382f,
6.16077f,56.3206f,461.731f,-4.82194f,0.908442f,0.443892f, 5.01713f,56.7125f,574.847f,-4.77239f,0.892473f,0.479785f,
3.75583f,50.4231f,656.822f,-4.31177f,0.906099f,0.513909f, 2.44396f,36.5878f,716.226f,-3.54028f,0.996116f,0.563736f,
8.81183f,-3.17108e-07f,8.81184f,-1.7809e-18f,0.999941f,1.66347e-07f, 8.81184f,0.197839f,8.81626f,-0.0224035f,0.999941f,1.7598e-07f,
8.81185f,0.395902f,8.82954f,-0.0448314f,0.999939f,2.05961e-07f, 8.81186f,0.594414f,8.85176f,-0.0673082f,0.999937f,2.59623e-07f,
8.81187f,0.793604f,8.883f,-0.0898587f,0.999933f,3.42822e-07f, 8.81188f,0.993699f,8.92339f,-0.112508f,0.999929f,4.64416e-07f,
8.81189f,1.19493f,8.97314f,-0.135281f,0.999924f,6.3701e-07f, 8.81189f,1.39755f,9.03247f,-0.158205f,0.999917f,8.7803e-07f,
8.81188f,1.60179f,9.10163f,-0.181306f,0.99991f,1.21126e-06f, 8.81185f,1.80792f,9.18097f,-0.204611f,0.999901f,1.66902e-06f,
8.81178f,2.01618f,9.27086f,-0.228151f,0.999892f,2.29521e-06f, 8.81169f,2.22685f,9.37173f,-0.251953f,0.99988f,3.14958e-06f,
8.81155f,2.44022f,9.48408f,-0.27605f,0.999868f,4.31375e-06f, 8.81135f,2.65659f,9.60847f,-0.300474f,0.999855f,5.89937e-06f,
8.81109f,2.87627f,9.74554f,-0.325258f,0.999839f,8.05953e-06f, 8.81075f,3.09958f,9.896f,-0.350441f,0.999823f,1.1004e-05f,
8.81032f,3.32687f,10.0607f,-0.376059f,0.999804f,1.502e-05f, 8.80977f,3.55852f,10.2405f,-0.402153f,0.999784f,2.04991e-05f,
8.80907f,3.79491f,10.4364f,-0.428767f,0.999762f,2.79738e-05f, 8.80822f,4.03646f,10.6497f,-0.455948f,0.999738f,3.81634e-05f,
8.80718f,4.28363f,10.8815f,-0.483744f,0.999711f,5.20342e-05f, 8.8059f,4.53688f,11.1335f,-0.512211f,0.999682f,7.08755e-05f,
8.80437f,4.79674f,11.4071f,-0.541405f,0.99965f,9.63952e-05f, 8.80253f,5.06377f,11.7042f,-0.571389f,0.999614f,0.00013084f,
8.80036f,5.33857f,12.027f,-0.602231f,0.999575f,0.000177141f, 8.79782f,5.62182f,12.3776f,-0.634006f,0.999532f,0.000239099f,
8.79494f,5.91427f,12.7587f,-0.666795f,0.999484f,0.000321601f, 8.79165f,6.21673f,13.1733f,-0.700685f,0.999431f,0.000430887f,
8.78798f,6.53012f,13.6248f,-0.735774f,0.999371f,0.000574868f, 8.78383f,6.8554f,14.1171f,-0.772169f,0.999303f,0.000763504f,
8.77917f,7.19367f,14.6548f,-0.809987f,0.999226f,0.00100924f, 8.77388f,7.5461f,15.2429f,-0.84936f,0.999137f,0.00132754f,
8.76789f,7.91403f,15.8876f,-0.89043f,0.999033f,0.00173743f, 8.76105f,8.29892f,16.5958f,-0.933357f,0.99891f,0.0022622f,
8.7533f,8.70247f,17.3755f,-0.978314f,0.998759f,0.00293005f, 8.74441f,9.12647f,18.2362f,-1.02549f,0.998569f,0.00377476f,
8.73429f,9.57308f,19.189f,-1.07509f,0.998318f,0.00483606f, 8.72267f,10.0446f,20.2467f,-1.12732f,0.997968f,0.00615933f,
8.70915f,10.5435f,21.4248f,-1.18234f,0.997445f,0.00779344f, 8.69351f,11.0729f,22.7406f,-1.24026f,0.996612f,0.00978483f,
8.67488f,11.6356f,24.2144f,-1.301f,0.995236f,0.0121668f, 8.65355f,12.2363f,25.8788f,-1.36662f,0.994306f,0.0151764f,
8.62868f,12.8793f,27.7647f,-1.43692f,0.993372f,0.0188696f, 8.6004f,13.571f,29.9173f,-1.5133f,0.992854f,0.023471f,
8.5674f,14.3166f,32.3831f,-1.59544f,0.992162f,0.0290413f, 8.52889f,15.1235f,35.2246f,-1.684f,0.991238f,0.0357445f,
8.48396f,16.0006f,38.5255f,-1.78038f,0.990315f,0.0438377f, 8.43178f,16.9589f,42.3931f,-1.88634f,0.989652f,0.053644f,
8.36988f,18.009f,46.958f,-2.00228f,0.988785f,0.0653325f, 8.29636f,19.1654f,52.3939f,-2.12949f,0.98759f,0.0791703f,
8.2085f,20.445f,58.9272f,-2.26919f,0.985839f,0.0954054f, 8.10138f,21.8641f,66.8566f,-2.42223f,0.983126f,0.114214f,
7.97016f,23.4442f,76.6356f,-2.59307f,0.98029f,0.136261f, 7.81056f,25.2163f,88.8473f,-2.78393f,0.977104f,0.161887f,
7.61826f,27.2226f,104.259f,-2.99405f,0.972462f,0.190965f, 7.37196f,29.4552f,124.036f,-3.22416f,0.966139f,0.22359f,
7.07375f,31.9943f,149.679f,-3.4741f,0.958109f,0.259829f, 6.72651f,34.9449f,183.084f,-3.7386f,0.948151f,0.299343f,
6.36985f,38.6198f,225.316f,-3.9962f,0.934808f,0.340351f, 5.76486f,41.5432f,280.852f,-4.20997f,0.918117f,0.380856f,
5.07746f,43.966f,345.255f,-4.3121f,0.900422f,0.418393f, 4.14822f,43.0147f,412.579f,-4.20146f,0.890787f,0.451864f,
3.22975f,38.2879f,455.585f,-3.79913f,0.913091f,0.486731f, 2.21264f,28.7547f,493.722f,-3.19429f,0.99661f,0.532022f,
7.74284f,-2.29507e-08f,7.74285f,-5.60474e-19f,0.999891f,5.02692e-07f, 7.74284f,0.173836f,7.74672f,-0.0223947f,0.999891f,5.24668e-07f,
7.74286f,0.347869f,7.75839f,-0.0448134f,0.999889f,5.92459e-07f, 7.74287f,0.522296f,7.77788f,-0.0672806f,0.999885f,7.11769e-07f,
7.7429f,0.697319f,7.8053f,-0.0898205f,0.999881f,8.92503e-07f, 7.74292f,0.873137f,7.84077f,-0.112458f,0.999875f,1.1494e-06f,
7.74295f,1.04996f,7.88443f,-0.135218f,0.999867f,1.50296e-06f, 7.74296f,1.22799f,7.93649f,-0.158127f,0.999858f,1.98085e-06f,
7.74297f,1.40745f,7.99721f,-0.181211f,0.999848f,2.61977e-06f, 7.74295f,1.58856f,8.06683f,-0.204497f,0.999836f,3.46806e-06f,
7.74292f,1.77155f,8.1457f,-0.228014f,0.999822f,4.58932e-06f, 7.74284f,1.95666f,8.2342f,-0.251791f,0.999806f,6.06733e-06f,
7.74273f,2.14413f,8.33277f,-0.275858f,0.999789f,8.01271e-06f, 7.74255f,2.33423f,8.44189f,-0.300248f,0.999769f,1.0572e-05f,
7.7423f,2.52723f,8.56212f,-0.324995f,0.999748f,1.39401e-05f, 7.74198f,2.72341f,8.69407f,-0.350133f,0.999724f,1.83762e-05f,
7.74155f,2.92308f,8.83847f,-0.3757f,0.999697f,2.42257e-05f, 7.741f,3.12656f,8.99611f,-0.401737f,0.999668f,3.19487e-05f,
7.74029f,3.33418f,9.16788f,-0.428285f,0.999635f,4.21567e-05f, 7.73945f,3.54632f,9.35477f,-0.45539f,0.999599f,5.566e-05f,
7.73838f,3.76336f,9.55793f,-0.483101f,0.99956f,7.35282e-05f, 7.73709f,3.98572f,9.77863f,-0.51147f,0.999516f,9.71664e-05f,
7.73552f,4.21384f,10.0183f,-0.540553f,0.999467f,0.00012841f, 7.73364f,4.4482f,10.2785f,-0.57041f,0.999412f,0.000169644f,
7.7314f,4.68933f,10.5611f,-0.601107f,0.99935f,0.000223943f, 7.72875f,4.93779f,10.868f,-0.632715f,0.99928f,0.000295253f,
7.7257f,5.19422f,11.2016f,-0.665312f,0.9992f,0.000388591f, 7.72221f,5.45934f,11.5643f,-0.69898f,0.999109f,0.000510299f,
7.71825f,5.73388f,11.9591f,-0.73381f,0.999001f,0.000668326f, 7.71381f,6.01874f,12.3894f,-0.769901f,0.998873f,0.000872542f,
7.70879f,6.31481f,12.859f,-0.807357f,0.998716f,0.00113508f, 7.70312f,6.62312f,13.3724f,-0.84629f,0.99852f,0.00147062f,
7.69668f,6.94476f,13.9347f,-0.886812f,0.998264f,0.00189661f, 7.68933f,7.28097f,14.5519f,-0.929032f,0.997916f,0.00243304f,
7.68098f,7.63317f,15.2304f,-0.973034f,0.997419f,0.00310154f, 7.67131f,8.00274f,15.9782f,-1.01886f,0.996676f,0.00392296f,
7.66007f,8.39132f,16.8036f,-1.06646f,0.995536f,0.00491328f, 7.64691f,8.80074f,17.7193f,-1.11684f,0.994533f,0.00616787f,
7.6317f,9.23328f,18.7381f,-1.17012f,0.993546f,0.00773562f, 7.61445f,9.69181f,19.8785f,-1.22748f,0.993108f,0.00976032f,
7.59464f,10.1789f,21.1571f,-1.28825f,0.992543f,0.0122483f, 7.57179f,10.6977f,22.5965f,-1.35276f,0.991811f,0.0152871f,
7.54539f,11.2519f,24.2244f,-1.42147f,0.990918f,0.0189846f, 7.51544f,11.8467f,26.0795f,-1.49602f,0.99047f,0.0235844f,
7.48098f,12.4866f,28.2013f,-1.57614f,0.989928f,0.0291599f, 7.44106f,13.1772f,30.6428f,-1.6625f,0.98926f,0.0358833f,
7.39436f,13.9248f,33.4715f,-1.75585f,0.988411f,0.0439453f, 7.3397f,14.7373f,36.77f,-1.85695f,0.987288f,0.0535492f,
7.27571f,15.6241f,40.6448f,-1.96654f,0.985728f,0.0648967f, 7.20128f,16.5978f,45.2275f,-2.08515f,0.983466f,0.0781621f,
7.10782f,17.6563f,50.7237f,-2.2154f,0.981042f,0.093799f, 7.00075f,18.8334f,57.3664f,-2.35888f,0.978406f,0.112141f,
6.8739f,20.1409f,65.4769f,-2.5165f,0.97521f,0.133421f, 6.72078f,21.5932f,75.466f,-2.68692f,0.970472f,0.157522f,
6.53048f,23.1919f,87.9608f,-2.87264f,0.964724f,0.184901f, 6.30242f,24.975f,103.706f,-3.07334f,0.957794f,0.215663f,
6.03422f,26.9797f,123.645f,-3.28389f,0.94886f,0.249363f, 5.78746f,29.5428f,148.129f,-3.49752f,0.938229f,0.285725f,
5.43391f,32.0961f,178.556f,-3.68976f,0.924262f,0.32273f, 4.92398f,33.9967f,216.649f,-3.83095f,0.908756f,0.359361f,
4.33277f,35.209f,257.977f,-3.86778f,0.895171f,0.39404f, 3.67835f,34.6052f,295.291f,-3.72557f,0.891241f,0.425315f,
2.76401f,29.2277f,326.461f,-3.3807f,0.919621f,0.46003f, 2.13318f,23.9543f,343.017f,-2.90145f,0.99701f,0.50156f,
6.85679f,7.64664e-07f,6.8568f,7.91117e-19f,0.999799f,1.36532e-06f, 6.85681f,0.15394f,6.86022f,-0.022385f,0.999798f,1.41102e-06f,
6.85681f,0.308054f,6.87055f,-0.0447937f,0.999795f,1.55109e-06f, 6.85685f,0.462518f,6.8878f,-0.0672502f,0.999791f,1.79456e-06f,
6.85688f,0.617509f,6.91204f,-0.0897784f,0.999784f,2.15698e-06f, 6.85692f,0.773205f,6.94342f,-0.112403f,0.999775f,2.66118e-06f,
6.85697f,0.92979f,6.98204f,-0.135148f,0.999764f,3.33844e-06f, 6.85701f,1.08745f,7.02809f,-0.15804f,0.999751f,4.23012e-06f,
6.85705f,1.24637f,7.08177f,-0.181105f,0.999735f,5.38991e-06f, 6.85706f,1.40675f,7.14336f,-0.204369f,0.999717f,6.88683e-06f,
6.85704f,1.56879f,7.2131f,-0.22786f,0.999697f,8.80938e-06f, 6.857f,1.73271f,7.29136f,-0.251607f,0.999674f,1.1271e-05f,
6.85692f,1.89872f,7.37849f,-0.275639f,0.999647f,1.44172e-05f, 6.85678f,2.06705f,7.47494f,-0.299989f,0.999618f,1.84358e-05f,
6.85655f,2.23793f,7.5812f,-0.324689f,0.999585f,2.35694e-05f, 6.85625f,2.41163f,7.69781f,-0.349774f,0.999548f,3.01325e-05f,
6.85585f,2.5884f,7.82539f,-0.375281f,0.999506f,3.85336e-05f, 6.85532f,2.76854f,7.96466f,-0.401247f,0.99946f,4.93041e-05f,
6.85466f,2.95233f,8.11636f,-0.427714f,0.999408f,6.31347e-05f, 6.8538f,3.14009f,8.28141f,-0.454726f,0.999349f,8.09218e-05f,
6.85276f,3.33218f,8.46078f,-0.482329f,0.999282f,0.000103826f, 6.85147f,3.52893f,8.65557f,-0.510572f,0.999205f,0.000133341f,
6.84991f,3.73074f,8.86706f,-0.539509f,0.999117f,0.000171386f, 6.84801f,3.93804f,9.09664f,-0.569195f,0.999014f,0.000220402f,
6.84574f,4.15125f,9.34588f,-0.599691f,0.998892f,0.00028347f, 6.84303f,4.37088f,9.61653f,-0.631057f,0.998746f,0.000364442f,
6.83988f,4.59747f,9.91057f,-0.66336f,0.998566f,0.000468057f, 6.83623f,4.8316f,10.2302f,-0.696663f,0.998338f,0.00060003f,
6.83208f,5.07396f,10.5779f,-0.731029f,0.998041f,0.000767035f, 6.82737f,5.32526f,10.9565f,-0.766508f,0.99764f,0.000976467f,
6.82209f,5.58631f,11.3692f,-0.80313f,0.997082f,0.00123579f, 6.81615f,5.85798f,11.8196f,-0.840888f,0.996283f,0.0015513f,
6.80932f,6.14112f,12.3118f,-0.879729f,0.995127f,0.00192626f, 6.80116f,6.43654f,12.8515f,-0.920667f,0.99426f,0.00242576f,
6.79184f,6.74565f,13.4446f,-0.963574f,0.993457f,0.00306412f, 6.78103f,7.06958f,14.0989f,-1.00908f,0.993014f,0.00390605f,
6.76876f,7.40994f,14.8217f,-1.05672f,0.992457f,0.00495344f, 6.75467f,7.76817f,15.6223f,-1.10667f,0.991757f,0.00624855f,
6.73852f,8.14613f,16.5127f,-1.15954f,0.99115f,0.0078724f, 6.7203f,8.5462f,17.5073f,-1.21589f,0.990784f,0.00991969f,
6.69952f,8.9705f,18.6214f,-1.2756f,0.990359f,0.0124402f, 6.6758f,9.42174f,19.8744f,-1.33903f,0.989862f,0.015528f,
6.64886f,9.9032f,21.29f,-1.40659f,0.989273f,0.0192919f, 6.61775f,10.4178f,22.8967f,-1.47871f,0.988566f,0.023856f,
6.58173f,10.9692f,24.7307f,-1.55586f,0.987695f,0.0293592f, 6.54049f,11.563f,26.8341f,-1.63854f,0.986583f,0.0359515f,
6.49209f,12.2024f,29.2619f,-1.72717f,0.985106f,0.0437865f, 6.43694f,12.8965f,32.0771f,-1.82209f,0.983074f,0.0530089f,
6.37088f,13.6466f,35.3773f,-1.9252f,0.980986f,0.0639739f, 6.29292f,14.4618f,39.2753f,-2.03738f,0.978739f,0.0769301f,
6.20683f,15.3647f,43.9073f,-2.15975f,0.976303f,0.0921701f, 6.09724f,16.3348f,49.4705f,-2.29142f,0.972876f,0.109702f,
5.98557f,17.4487f,56.1487f,-2.433f,0.968392f,0.129733f, 5.82587f,18.5996f,64.3876f,-2.5862f,0.963226f,0.152664f,
5.64577f,19.8868f,74.4916f,-2.74981f,0.956908f,0.178505f, 5.43945f,21.3206f,86.9306f,-2.92062f,0.948891f,0.207052f,
5.20917f,22.9352f,102.224f,-3.09605f,0.939706f,0.238398f, 4.99618f,24.9413f,120.309f,-3.26216f,0.928176f,0.271351f,
4.65857f,26.6293f,142.497f,-3.40207f,0.914858f,0.305085f, 4.18392f,27.5911f,168.713f,-3.48694f,0.901171f,0.33832f,
3.80375f,28.758f,193.349f,-3.47915f,0.891749f,0.370449f, 3.22446f,27.5482f,216.38f,-3.32807f,0.893413f,0.400223f,
2.4806f,23.3245f,235.855f,-3.03453f,0.925586f,0.434007f, 1.95739f,19.3776f,248.129f,-2.65065f,0.997339f,0.472415f,
6.11434f,7.74337e-07f,6.11434f,-1.38039e-17f,0.999619f,3.35897e-06f, 6.11435f,0.137267f,6.11739f,-0.0223723f,0.999618f,3.44607e-06f,
6.11438f,0.27469f,6.12658f,-0.0447679f,0.999613f,3.7117e-06f, 6.11441f,0.412423f,6.14196f,-0.0672104f,0.999606f,4.16909e-06f,
6.11447f,0.550628f,6.16356f,-0.0897234f,0.999595f,4.84082e-06f, 6.11454f,0.689463f,6.1915f,-0.112331f,0.99958f,5.75973e-06f,
6.11461f,0.829091f,6.22589f,-0.135057f,0.999563f,6.97022e-06f, 6.11469f,0.969674f,6.2669f,-0.157927f,0.999541f,8.53004e-06f,
6.11475f,1.11138f,6.31473f,-0.180966f,0.999516f,1.05128e-05f, 6.11481f,1.2544f,6.36956f,-0.2042f,0.999487f,1.3011e-05f,
6.11485f,1.39889f,6.43166f,-0.227656f,0.999453f,1.61409e-05f, 6.11486f,1.54506f,6.50132f,-0.251363f,0.999413f,2.00474e-05f,
6.11481f,1.69308f,6.57889f,-0.275348f,0.999368f,2.49118e-05f, 6.11472f,1.84317f,6.66474f,-0.299643f,0.999317f,3.09616e-05f,
6.11456f,1.99554f,6.7593f,-0.324279f,0.999257f,3.84821e-05f, 6.11432f,2.15041f,6.86307f,-0.349288f,0.999189f,4.78322e-05f,
6.11397f,2.30801f,6.97659f,-0.374705f,0.99911f,5.94639e-05f, 6.11351f,2.4686f,7.10046f,-0.400566f,0.999019f,7.39454e-05f,
6.11289f,2.63243f,7.23538f,-0.426908f,0.998911f,9.19892e-05f, 6.11212f,2.79979f,7.38213f,-0.453768f,0.998783f,0.000114482f,
6.11113f,2.97097f,7.54159f,-0.481187f,0.998629f,0.000142516f, 6.10991f,3.14629f,7.71474f,-0.509204f,0.99844f,0.000177413f,
6.10841f,3.32609f,7.90268f,-0.537855f,0.998204f,0.000220724f, 6.10658f,3.51072f,8.10668f,-0.567176f,0.997902f,0.000274187f,
6.10434f,3.70056f,8.32809f,-0.59719f,0.997507f,0.000339591f, 6.10162f,3.89603f,8.56846f,-0.627911f,0.996978f,0.000418483f,
6.09839f,4.09757f,8.82939f,-0.65933f,0.996256f,0.000511662f, 6.09466f,4.30571f,9.11256f,-0.691411f,0.995267f,0.00061844f,
6.09038f,4.52101f,9.4198f,-0.724548f,0.994264f,0.000754008f, 6.08551f,4.74416f,9.75365f,-0.75905f,0.993413f,0.000937048f,
6.07962f,4.97557f,10.1176f,-0.795392f,0.992986f,0.00119814f, 6.07284f,5.21608f,10.5149f,-0.833018f,0.992459f,0.00152648f,
6.06519f,5.46659f,10.9492f,-0.872017f,0.991814f,0.00193717f, 6.05635f,5.72783f,11.4253f,-0.912929f,0.991348f,0.00247226f,
6.0463f,6.00088f,11.9486f,-0.955899f,0.991036f,0.00316295f, 6.0349f,6.28681f,12.5248f,-1.00084f,0.990683f,0.0040298f,
6.02202f,6.58688f,13.1609f,-1.04793f,0.990284f,0.00511258f, 6.00735f,6.90236f,13.8653f,-1.09737f,0.989831f,0.00645873f,
5.99073f,7.23483f,14.6474f,-1.1494f,0.989319f,0.00812453f, 5.97188f,7.58599f,15.519f,-1.20428f,0.988737f,0.0101762f,
5.95057f,7.95788f,16.4934f,-1.26228f,0.988072f,0.0126907f, 5.94014f,8.37205f,17.5751f,-1.3237f,0.9873f,0.0157566f,
5.89788f,8.77135f,18.821f,-1.38885f,0.986379f,0.0194732f, 5.86595f,9.21865f,20.2174f,-1.45804f,0.985246f,0.0239484f,
5.82882f,9.69599f,21.8059f,-1.53153f,0.983797f,0.0292948f, 5.78682f,10.2086f,23.6194f,-1.60951f,0.981891f,0.0356233f,
5.73731f,10.7575f,25.7105f,-1.69379f,0.980152f,0.0432498f, 5.67969f,11.3477f,28.1343f,-1.7845f,0.978276f,0.0523176f,
5.61577f,11.9905f,30.9578f,-1.88252f,0.976312f,0.0630768f, 5.54108f,12.686f,34.266f,-1.98726f,0.973651f,0.0755869f,
5.4539f,13.4408f,38.1651f,-2.09859f,0.970006f,0.089964f, 5.34987f,14.2559f,42.8145f,-2.21865f,0.966009f,0.106653f,
5.23743f,15.1675f,48.3653f,-2.34734f,0.961404f,0.125823f, 5.09195f,16.1219f,55.0789f,-2.4829f,0.955564f,0.147417f,
4.97308f,17.3233f,62.9693f,-2.62378f,0.948321f,0.171453f, 4.78699f,18.4881f,72.6816f,-2.76774f,0.939825f,0.197964f,
4.53327f,19.5723f,84.6124f,-2.90944f,0.930183f,0.226717f, 4.32299f,21.0009f,98.109f,-3.03568f,0.918602f,0.256687f,
4.02747f,22.1519f,113.912f,-3.13345f,0.906598f,0.287554f, 3.70186f,23.0856f,130.743f,-3.17758f,0.89549f,0.318049f,
3.3019f,23.1969f,147.654f,-3.14083f,0.88991f,0.347781f, 2.9004f,22.4389f,160.717f,-2.9936f,0.896611f,0.376391f,
2.33322f,19.4409f,171.605f,-2.74455f,0.930998f,0.408875f, 1.80536f,15.8586f,182.973f,-2.43362f,0.997609f,0.444623f,
5.48643f,7.2132e-07f,5.48644f,-1.47583e-17f,0.999233f,7.52126e-06f, 5.48645f,0.123163f,5.48919f,-0.0223486f,0.99923f,7.67319e-06f,
5.48649f,0.246468f,5.49742f,-0.0447199f,0.999222f,8.13473e-06f, 5.48656f,0.370053f,5.5112f,-0.0671365f,0.999207f,8.92331e-06f,
5.48663f,0.49406f,5.53058f,-0.0896212f,0.999186f,1.00685e-05f, 5.48674f,0.618634f,5.55563f,-0.112197f,0.999158f,1.16127e-05f,
5.48686f,0.743919f,5.58647f,-0.134888f,0.999123f,1.36123e-05f, 5.487f,0.870068f,5.62323f,-0.157717f,0.99908f,1.61394e-05f,
5.48712f,0.997227f,5.6661f,-0.180708f,0.999028f,1.9283e-05f, 5.48726f,1.12556f,5.71524f,-0.203887f,0.998966f,2.31523e-05f,
5.48738f,1.25522f,5.77093f,-0.227277f,0.998892f,2.78783e-05f, 5.48749f,1.38638f,5.83338f,-0.250905f,0.998805f,3.36176e-05f,
5.48755f,1.51921f,5.90291f,-0.274797f,0.9987f,4.05551e-05f, 5.48759f,1.6539f,5.97987f,-0.298977f,0.998575f,4.89059e-05f,
5.48756f,1.79064f,6.06461f,-0.323472f,0.998424f,5.8916e-05f, 5.48748f,1.92961f,6.15762f,-0.348308f,0.998241f,7.0857e-05f,
5.48732f,2.07105f,6.25936f,-0.373507f,0.998015f,8.50127e-05f, 5.48706f,2.21516f,6.37038f,-0.399089f,0.997732f,0.000101647f,
5.4867f,2.36218f,6.49131f,-0.425071f,0.997373f,0.00012094f, 5.48618f,2.51237f,6.62286f,-0.451461f,0.996911f,0.000142877f,
5.48551f,2.66597f,6.76583f,-0.478254f,0.996309f,0.000167063f, 5.48462f,2.82328f,6.92108f,-0.505435f,0.995519f,0.000192448f,
5.48341f,2.98454f,7.08961f,-0.532972f,0.994482f,0.000216975f, 5.48149f,3.14993f,7.27206f,-0.561312f,0.993535f,0.000250188f,
5.47877f,3.31973f,7.46938f,-0.590732f,0.992852f,0.000301707f, 5.47547f,3.49443f,7.68292f,-0.621209f,0.992353f,0.000375527f,
5.47181f,3.67455f,7.91442f,-0.652467f,0.991753f,0.000467149f, 5.46769f,3.86055f,8.16534f,-0.684904f,0.991322f,0.000592532f,
5.46279f,4.05272f,8.43801f,-0.71858f,0.991026f,0.000761098f, 5.45708f,4.25159f,8.73475f,-0.753374f,0.990694f,0.000976451f,
5.45074f,4.45792f,9.05798f,-0.78938f,0.990324f,0.00125067f, 5.44361f,4.67227f,9.41064f,-0.826703f,0.989913f,0.00159867f,
5.43556f,4.89533f,9.7961f,-0.865458f,0.989461f,0.00203874f, 5.42634f,5.12772f,10.2182f,-0.905772f,0.988966f,0.00259323f,
5.4159f,5.37034f,10.6815f,-0.94792f,0.988523f,0.00329614f, 5.40407f,5.6241f,11.1913f,-0.992123f,0.988168f,0.00418548f,
5.39077f,5.8901f,11.7535f,-1.03837f,0.987758f,0.00529182f, 5.37574f,6.16941f,12.3752f,-1.08683f,0.987277f,0.00666077f,
5.35893f,6.46352f,13.0646f,-1.13769f,0.986702f,0.0083452f, 5.34525f,6.7803f,13.8275f,-1.19113f,0.985999f,0.0104054f,
5.31732f,7.09995f,14.6875f,-1.24734f,0.985117f,0.0129085f, 5.29241f,7.44628f,15.6459f,-1.30648f,0.983988f,0.0159274f,
5.26344f,7.81279f,16.723f,-1.36869f,0.982519f,0.0195389f, 5.23066f,8.20266f,17.9385f,-1.43436f,0.98076f,0.0238535f,
5.19524f,8.62123f,19.317f,-1.50462f,0.979098f,0.0290802f, 5.14938f,9.0595f,20.8959f,-1.57973f,0.977403f,0.0353538f,
5.10214f,9.53703f,22.7013f,-1.65986f,0.975501f,0.0428147f, 5.04906f,10.0519f,24.7783f,-1.74498f,0.973128f,0.0515747f,
4.98176f,10.5932f,27.1901f,-1.83548f,0.970279f,0.0618021f, 4.91169f,11.1911f,29.9945f,-1.93203f,0.967046f,0.0737311f,
4.82671f,11.8274f,33.2874f,-2.0351f,0.963423f,0.0875911f, 4.73929f,12.5409f,37.1394f,-2.14428f,0.959125f,0.103507f,
4.61929f,13.2637f,41.7388f,-2.25835f,0.953734f,0.121495f, 4.50379f,14.106f,47.1095f,-2.37618f,0.947125f,0.141621f,
4.36045f,14.9826f,53.5161f,-2.49625f,0.939398f,0.16396f, 4.18886f,15.8893f,61.1252f,-2.6157f,0.930754f,0.188493f,
4.01648f,16.911f,69.7857f,-2.72729f,0.920913f,0.214749f, 3.86373f,18.1262f,79.3319f,-2.82161f,0.910198f,0.242258f,
3.58671f,18.8335f,90.5932f,-2.88556f,0.899721f,0.27046f, 3.25032f,19.0872f,102.657f,-2.9015f,0.89164f,0.29872f,
2.9392f,19.0924f,113.092f,-2.84696f,0.889356f,0.326141f, 2.51483f,17.7741f,122.324f,-2.71144f,0.900768f,0.354086f,
2.12459f,15.8982f,128.787f,-2.49914f,0.936003f,0.384893f, 1.67416f,13.1214f,137.314f,-2.24403f,0.997833f,0.418201f,
4.95191f,6.74986e-07f,4.95192f,-8.98451e-18f,0.998258f,1.52586e-05f, 4.95194f,0.111151f,4.9544f,-0.02228f,0.99825f,1.54938e-05f,
4.95201f,0.222429f,4.96185f,-0.0445803f,0.998226f,1.62053e-05f, 4.95213f,0.333965f,4.97431f,-0.0669212f,0.998185f,1.74095e-05f,
4.9523f,0.445885f,4.99183f,-0.0893231f,0.998126f,1.91338e-05f, 4.9525f,0.558319f,5.01447f,-0.111806f,0.998047f,2.1415e-05f,
4.95275f,0.671402f,5.04239f,-0.134389f,0.997945f,2.4298e-05f, 4.95305f,0.78527f,5.07564f,-0.157092f,0.997816f,2.78324e-05f,
4.95336f,0.90006f,5.11443f,-0.179932f,0.997654f,3.20676e-05f, 4.95375f,1.01592f,5.15892f,-0.202927f,0.997453f,3.70433e-05f,
4.95415f,1.133f,5.20934f,-0.226091f,0.997202f,4.27746e-05f, 4.95461f,1.25145f,5.2659f,-0.249436f,0.996889f,4.92269e-05f,
4.95508f,1.37143f,5.32892f,-0.272969f,0.996496f,5.62766e-05f, 4.95562f,1.49311f,5.3987f,-0.296693f,0.996f,6.36489e-05f,
4.95619f,1.61668f,5.47563f,-0.320601f,0.995372f,7.08276e-05f, 4.95678f,1.7423f,5.56008f,-0.344681f,0.994576f,7.69287e-05f,
4.95741f,1.87018f,5.65252f,-0.368909f,0.993568f,8.05402e-05f, 4.95774f,2.00043f,5.75313f,-0.393495f,0.992507f,8.30421e-05f,
4.95722f,2.13307f,5.86186f,-0.418957f,0.991814f,9.22197e-05f, 4.95625f,2.26841f,5.97972f,-0.445053f,0.991236f,0.000106139f,
4.95479f,2.40667f,6.10748f,-0.471797f,0.990755f,0.000125782f, 4.95283f,2.54809f,6.24581f,-0.499314f,0.990434f,0.000154934f,
4.9505f,2.69297f,6.39586f,-0.527432f,0.990075f,0.000191904f, 4.94778f,2.84162f,6.55849f,-0.5562f,0.989677f,0.00023895f,
4.94468f,2.99433f,6.73467f,-0.585673f,0.989237f,0.000298994f, 4.94114f,3.15145f,6.92517f,-0.616216f,0.989029f,0.00038383f,
4.93701f,3.31325f,7.13178f,-0.647642f,0.988816f,0.000493588f, 4.93222f,3.48008f,7.35609f,-0.680009f,0.988588f,0.000634691f,
4.92694f,3.65252f,7.59969f,-0.713395f,0.988342f,0.000815478f, 4.92108f,3.831f,7.86459f,-0.747883f,0.988076f,0.00104625f,
4.91451f,4.016f,8.153f,-0.783563f,0.987789f,0.00133963f, 4.90699f,4.20791f,8.46757f,-0.820531f,0.987475f,0.00171098f,
4.89862f,4.40749f,8.81113f,-0.858892f,0.987128f,0.00217889f, 4.88919f,4.6153f,9.18704f,-0.898756f,0.98674f,0.00276558f,
4.87856f,4.83206f,9.59917f,-0.940241f,0.986298f,0.00349741f, 4.8666f,5.0585f,10.052f,-0.983465f,0.985784f,0.0044053f,
4.8534f,5.29581f,10.5504f,-1.02855f,0.985171f,0.00552493f, 4.83914f,5.54537f,11.1002f,-1.07562f,0.984424f,0.00689682f,
4.82032f,5.80447f,11.7101f,-1.12477f,0.983492f,0.00856601f, 4.80079f,6.0789f,12.3859f,-1.1761f,0.982313f,0.0105813f,
4.77807f,6.36734f,13.138f,-1.22968f,0.980808f,0.0129946f, 4.75249f,6.67206f,13.9798f,-1.28649f,0.979411f,0.0159499f,
4.72466f,6.99604f,14.9232f,-1.34643f,0.97789f,0.0195137f, 4.69154f,7.33734f,15.9883f,-1.41033f,0.976515f,0.0238518f,
4.65356f,7.69898f,17.1931f,-1.47763f,0.974785f,0.0290024f, 4.61253f,8.08713f,18.5582f,-1.54844f,0.9726f,0.0350724f,
4.56492f,8.49953f,20.1129f,-1.62281f,0.969832f,0.0421678f, 4.50789f,8.93451f,21.9018f,-1.70175f,0.96684f,0.0505271f,
4.45254f,9.41846f,23.9479f,-1.78586f,0.963712f,0.0603628f, 4.37646f,9.91077f,26.3406f,-1.8755f,0.960479f,0.0718691f,
4.31344f,10.4916f,29.0635f,-1.96879f,0.956265f,0.0849791f, 4.21336f,11.051f,32.2965f,-2.06619f,0.951341f,0.0999371f,
4.11499f,11.6867f,36.0195f,-2.16611f,0.945309f,0.116724f, 3.99739f,12.3497f,40.3839f,-2.26791f,0.938409f,0.13551f,
3.91904f,13.2411f,45.2581f,-2.36838f,0.930303f,0.156134f, 3.77699f,13.9922f,50.9571f,-2.46611f,0.921877f,0.178818f,
3.63451f,14.8562f,57.1638f,-2.55221f,0.912319f,0.202821f, 3.36837f,15.222f,65.1829f,-2.62065f,0.902864f,0.228128f,
3.17769f,15.8472f,72.7979f,-2.65867f,0.894145f,0.253938f, 2.92445f,16.0817f,80.5634f,-2.65493f,0.888952f,0.280133f,
2.55938f,15.4039f,88.6567f,-2.59223f,0.889936f,0.305723f, 2.29168f,14.7252f,93.7393f,-2.47084f,0.905313f,0.333082f,
1.87374f,12.7057f,99.7622f,-2.2882f,0.9403f,0.361861f, 1.56197f,10.9735f,104.595f,-2.07703f,0.998018f,0.393147f,
4.4981f,-6.19084e-07f,4.49809f,-1.71456e-17f,0.995043f,2.66207e-05f, 4.49817f,0.100919f,4.50038f,-0.0219788f,0.995008f,2.6864e-05f,
4.49839f,0.201962f,4.50729f,-0.0439656f,0.994904f,2.75842e-05f, 4.49875f,0.303241f,4.51883f,-0.0659675f,0.994726f,2.87495e-05f,
4.49929f,0.404892f,4.53506f,-0.0879899f,0.994464f,3.02978e-05f, 4.49998f,0.50703f,4.55608f,-0.110036f,0.994107f,3.212e-05f,
4.50084f,0.609789f,4.58198f,-0.132105f,0.99364f,3.40365e-05f, 4.5019f,0.713298f,4.6129f,-0.154192f,0.99304f,3.57604e-05f,
4.50316f,0.817697f,4.64901f,-0.176288f,0.992283f,3.68486e-05f, 4.50465f,0.923125f,4.69045f,-0.198379f,0.991339f,3.66373e-05f,
4.50631f,1.02972f,4.73746f,-0.220447f,0.990175f,3.41634e-05f, 4.5072f,1.13746f,4.78922f,-0.243077f,0.989303f,3.28576e-05f,
4.50737f,1.24645f,4.84603f,-0.26628f,0.988715f,3.35859e-05f, 4.50701f,1.35684f,4.90835f,-0.289998f,0.988342f,3.65341e-05f,
4.50658f,1.46887f,4.97698f,-0.313988f,0.98792f,3.98309e-05f, 4.5056f,1.58256f,5.0518f,-0.338535f,0.987714f,4.63734e-05f,
4.50446f,1.69817f,5.13358f,-0.363479f,0.987518f,5.50412e-05f, 4.50315f,1.81587f,5.22277f,-0.388827f,0.987307f,6.61814e-05f,
4.50164f,1.93584f,5.31989f,-0.414619f,0.987083f,8.05664e-05f, 4.49989f,2.05828f,5.42545f,-0.440892f,0.986848f,9.9211e-05f,
4.49784f,2.18335f,5.54002f,-0.467711f,0.986625f,0.000123764f, 4.49534f,2.31124f,5.66411f,-0.495216f,0.986514f,0.000157583f,
4.49253f,2.44224f,5.79866f,-0.523341f,0.986392f,0.000201392f, 4.48952f,2.57665f,5.9444f,-0.552136f,0.986259f,0.000258013f,
4.48601f,2.71462f,6.10232f,-0.581654f,0.986113f,0.00033099f, 4.48194f,2.85641f,6.2735f,-0.611951f,0.985951f,0.000424759f,
4.47749f,3.00244f,6.45901f,-0.643086f,0.98577f,0.000544824f, 4.47263f,3.1531f,6.66025f,-0.675124f,0.985565f,0.000697981f,
4.46725f,3.30869f,6.87867f,-0.70813f,0.985331f,0.000892555f, 4.46107f,3.46948f,7.11612f,-0.742176f,0.98506f,0.00113867f,
4.45423f,3.63602f,7.37445f,-0.777335f,0.984742f,0.00144854f, 4.44659f,3.80877f,7.65587f,-0.813686f,0.984365f,0.00183674f,
4.43807f,3.98821f,7.96292f,-0.851305f,0.98391f,0.00232051f, 4.4285f,4.17486f,8.29842f,-0.890271f,0.983356f,0.00291995f,
4.41804f,4.36958f,8.66558f,-0.930658f,0.982673f,0.00365811f, 4.40688f,4.57341f,9.0679f,-0.972534f,0.981824f,0.00456103f,
4.39274f,4.78489f,9.51062f,-1.01596f,0.980762f,0.00565756f, 4.37627f,5.00553f,9.99846f,-1.06098f,0.979432f,0.00697908f,
4.35773f,5.23664f,10.5378f,-1.10816f,0.978091f,0.00860102f, 4.33811f,5.48066f,11.135f,-1.1578f,0.97682f,0.0105926f,
4.31627f,5.73772f,11.8001f,-1.21047f,0.975812f,0.0130564f, 4.29051f,6.00703f,12.5417f,-1.26565f,0.974602f,0.0160201f,
4.26113f,6.29058f,13.3717f,-1.32336f,0.973071f,0.0195518f, 4.23069f,6.59415f,14.3003f,-1.38365f,0.97114f,0.0237314f,
4.19625f,6.91584f,15.3451f,-1.44693f,0.968902f,0.0286806f, 4.15376f,7.25138f,16.5303f,-1.51344f,0.966368f,0.0345234f,
4.10727f,7.6098f,17.8747f,-1.58367f,0.963649f,0.0414312f, 4.07761f,8.03506f,19.372f,-1.65746f,0.960557f,0.0495115f,
3.99694f,8.39916f,21.1528f,-1.73453f,0.956886f,0.0588648f, 3.96542f,8.9084f,23.0903f,-1.81528f,0.952837f,0.0696696f,
3.86297f,9.30946f,25.4442f,-1.89912f,0.948212f,0.0820267f, 3.79326f,9.83669f,28.0484f,-1.98503f,0.942764f,0.0959986f,
3.72809f,10.439f,30.9981f,-2.07267f,0.936706f,0.11177f, 3.58752f,10.895f,34.5897f,-2.15896f,0.929465f,0.129146f,
3.47121f,11.4705f,38.5126f,-2.24228f,0.921417f,0.14822f, 3.41701f,12.3091f,42.6071f,-2.32023f,0.913196f,0.169027f,
3.17929f,12.556f,47.9924f,-2.38559f,0.904423f,0.191063f, 3.02451f,13.079f,53.2234f,-2.43326f,0.896403f,0.214345f,
2.85691f,13.4987f,58.5718f,-2.4523f,0.889671f,0.238081f, 2.66252f,13.6633f,63.6903f,-2.43531f,0.887116f,0.26235f,
2.34064f,12.9714f,69.2175f,-2.37069f,0.891238f,0.286484f, 2.09853f,12.2806f,72.8105f,-2.26259f,0.909503f,0.312956f,
1.732f,10.6149f,77.2933f,-2.1052f,0.943993f,0.339909f, 1.53083f,9.58929f,79.8722f,-1.92881f,0.998171f,0.369446f,
4.13386f,-4.50171e-07f,4.13386f,-1.23558e-17f,0.980818f,2.36802e-05f, 4.13412f,0.0925185f,4.13615f,-0.0204001f,0.980663f,2.30558e-05f,
4.1349f,0.185169f,4.14303f,-0.0407692f,0.980195f,2.10756e-05f, 4.13606f,0.278081f,4.15439f,-0.0611311f,0.979458f,1.75688e-05f,
4.13525f,0.371309f,4.16793f,-0.082501f,0.979441f,1.5797e-05f, 4.13377f,0.464889f,4.18499f,-0.104309f,0.979662f,1.4897e-05f,
4.13203f,0.558918f,4.2061f,-0.126393f,0.979964f,1.45807e-05f, 4.13037f,0.653521f,4.23167f,-0.148659f,0.980213f,1.44963e-05f,
4.1285f,0.748777f,4.26153f,-0.171192f,0.980535f,1.51791e-05f, 4.12668f,0.844826f,4.29609f,-0.193939f,0.980818f,1.6347e-05f,
4.12488f,0.941788f,4.33551f,-0.216919f,0.981068f,1.81256e-05f, 4.12311f,1.03979f,4.37993f,-0.240152f,0.981289f,2.06742e-05f,
4.12132f,1.13895f,4.42959f,-0.263662f,0.981485f,2.41975e-05f, 4.1195f,1.2394f,4.48471f,-0.287471f,0.981659f,2.8959e-05f,
4.11764f,1.34127f,4.54554f,-0.311607f,0.981812f,3.52992e-05f, 4.1157f,1.44471f,4.61241f,-0.336096f,0.981946f,4.3656e-05f,
4.11368f,1.54987f,4.68563f,-0.360968f,0.982063f,5.45921e-05f, 4.11152f,1.65688f,4.76559f,-0.386254f,0.982161f,6.88273e-05f,
4.10922f,1.76593f,4.85272f,-0.411987f,0.98224f,8.72797e-05f, 4.10674f,1.87718f,4.94751f,-0.438201f,0.9823f,0.000111115f,
4.10408f,1.99082f,5.05049f,-0.464932f,0.982338f,0.000141809f, 4.10127f,2.10707f,5.16219f,-0.492221f,0.982353f,0.000181219f,
4.09814f,2.22609f,5.2833f,-0.520107f,0.982341f,0.00023167f, 4.09455f,2.34803f,5.4146f,-0.548633f,0.982298f,0.000296062f,
4.09084f,2.47331f,5.55681f,-0.577846f,0.98222f,0.000377985f, 4.08643f,2.6019f,5.71098f,-0.607791f,0.9821f,0.000481858f,
4.08184f,2.73439f,5.87797f,-0.63852f,0.981931f,0.000613074f, 4.07664f,2.87085f,6.05906f,-0.670081f,0.981703f,0.000778169f,
4.071f,3.01174f,6.25553f,-0.702528f,0.981405f,0.000984978f, 4.06472f,3.15731f,6.46887f,-0.735911f,0.98102f,0.0012428f,
4.0578f,3.30799f,6.70072f,-0.770282f,0.980531f,0.00156252f, 4.05008f,3.46412f,6.95302f,-0.805688f,0.979911f,0.00195671f,
4.04175f,3.62637f,7.22771f,-0.842173f,0.979133f,0.00243966f, 4.03288f,3.79541f,7.52697f,-0.879947f,0.978325f,0.00303237f,
4.02149f,3.97003f,7.85436f,-0.918878f,0.977285f,0.00374819f, 4.00765f,4.15084f,8.21399f,-0.959428f,0.976254f,0.00463523f,
3.99408f,4.34127f,8.60783f,-1.00168f,0.975191f,0.00572873f, 3.97719f,4.53845f,9.04293f,-1.0461f,0.974302f,0.00709599f,
3.9604f,4.74705f,9.52138f,-1.0923f,0.973235f,0.00875338f, 3.94268f,4.96711f,10.0492f,-1.14033f,0.971919f,0.0107465f,
3.91961f,5.19434f,10.6356f,-1.19023f,0.970305f,0.0131291f, 3.8927f,5.43149f,11.2893f,-1.24245f,0.968556f,0.0159944f,
3.86601f,5.6856f,12.0144f,-1.29689f,0.96651f,0.0194006f, 3.84514f,5.96763f,12.817f,-1.35401f,0.964369f,0.0234527f,
3.79793f,6.22966f,13.74f,-1.4141f,0.962161f,0.0282799f, 3.76216f,6.53229f,14.7634f,-1.47691f,0.959646f,0.0339633f,
3.71704f,6.84438f,15.9193f,-1.5423f,0.956678f,0.0405961f, 3.67119f,7.18333f,17.2184f,-1.6097f,0.952974f,0.0482245f,
3.6698f,7.64537f,18.5988f,-1.67995f,0.948948f,0.057085f, 3.5554f,7.91138f,20.3763f,-1.75203f,0.944201f,0.0671929f,
3.49171f,8.31801f,22.2774f,-1.82723f,0.939492f,0.0788568f, 3.4257f,8.76064f,24.4138f,-1.90315f,0.934025f,0.0919913f,
3.32633f,9.16194f,26.9046f,-1.97814f,0.927608f,0.106575f, 3.26908f,9.71595f,29.5241f,-2.05089f,0.92044f,0.122683f,
3.13193f,10.0879f,32.7172f,-2.11857f,0.912499f,0.140201f, 3.00765f,10.5129f,36.127f,-2.17932f,0.904606f,0.159213f,
2.87315f,10.9062f,39.8265f,-2.22893f,0.897267f,0.179677f, 2.71164f,11.1786f,43.8051f,-2.26014f,0.890721f,0.201072f,
2.5379f,11.326f,47.7716f,-2.26553f,0.886021f,0.222965f, 2.35486f,11.299f,51.4656f,-2.23998f,0.885825f,0.245439f,
2.14921f,10.9682f,54.7407f,-2.1768f,0.89276f,0.268298f, 1.93008f,10.3128f,57.4095f,-2.08098f,0.913199f,0.293752f,
1.66255f,9.19223f,60.0368f,-1.945f,0.94714f,0.31909f, 1.43828f,8.14334f,62.6005f,-1.79632f,0.998296f,0.347073f,
3.81222f,1.83671e-07f,3.81222f,-2.11471e-17f,0.967556f,2.07684e-06f, 3.81223f,0.0855194f,3.8141f,-0.0221286f,0.967552f,2.14635e-06f,
3.81224f,0.171134f,3.81973f,-0.0442784f,0.967541f,2.3598e-06f, 3.81225f,0.25694f,3.82914f,-0.0664707f,0.967522f,2.7321e-06f,
3.81226f,0.343032f,3.84237f,-0.0887271f,0.967496f,3.2891e-06f, 3.81227f,0.429509f,3.85947f,-0.111069f,0.967461f,4.06901e-06f,
3.81147f,0.516315f,3.8797f,-0.133218f,0.967691f,5.37094e-06f, 3.80893f,0.603306f,3.90213f,-0.154923f,0.968475f,7.38713e-06f,
3.80593f,0.690778f,3.92822f,-0.176726f,0.969342f,9.71781e-06f, 3.80265f,0.778847f,3.95824f,-0.198711f,0.970246f,1.24997e-05f,
3.7994f,0.867689f,3.99269f,-0.22098f,0.971083f,1.5848e-05f, 3.79606f,0.95738f,4.03159f,-0.243527f,0.971902f,2.00549e-05f,
3.79292f,1.04813f,4.07547f,-0.266418f,0.972593f,2.52702e-05f, 3.78974f,1.13998f,4.12428f,-0.289647f,0.973252f,3.19847e-05f,
3.78649f,1.23306f,4.17825f,-0.313232f,0.973887f,4.06036e-05f, 3.78335f,1.32756f,4.23788f,-0.337207f,0.974418f,5.1511e-05f,
3.7803f,1.42363f,4.30347f,-0.361591f,0.974854f,6.53554e-05f, 3.77729f,1.5214f,4.37534f,-0.386407f,0.975201f,8.2941e-05f,
3.77395f,1.6209f,4.45344f,-0.41169f,0.975608f,0.000105619f, 3.77064f,1.72241f,4.53854f,-0.437456f,0.975943f,0.000134293f,
3.76745f,1.82618f,4.6311f,-0.463732f,0.976194f,0.000170463f, 3.76396f,1.93221f,4.73165f,-0.490549f,0.976361f,0.000216021f,
3.76002f,2.04063f,4.84094f,-0.517936f,0.976443f,0.000273286f, 3.75593f,2.15178f,4.95942f,-0.545927f,0.976438f,0.000345082f,
3.75165f,2.26588f,5.08764f,-0.574584f,0.976408f,0.000435191f, 3.74698f,2.38306f,5.22631f,-0.603952f,0.976374f,0.000547867f,
3.74164f,2.50344f,5.37672f,-0.634023f,0.97622f,0.000687367f, 3.73614f,2.62758f,5.53971f,-0.664829f,0.975932f,0.000859302f,
3.73018f,2.75564f,5.71643f,-0.696398f,0.975493f,0.00107013f, 3.72379f,2.88798f,5.90808f,-0.728756f,0.974879f,0.0013272f,
3.71683f,3.02491f,6.11608f,-0.761926f,0.974066f,0.00163875f, 3.70975f,3.16719f,6.34171f,-0.795927f,0.973025f,0.00201395f,
3.69973f,3.31298f,6.58807f,-0.831481f,0.972288f,0.00249553f, 3.68815f,3.46374f,6.85701f,-0.868331f,0.971537f,0.00309345f,
3.67708f,3.62189f,7.15026f,-0.906756f,0.970872f,0.00384584f, 3.66382f,3.78551f,7.47146f,-0.946449f,0.970015f,0.00476094f,
3.65034f,3.95719f,7.82283f,-0.987468f,0.968939f,0.00586848f, 3.636f,4.13715f,8.20814f,-1.02998f,0.967689f,0.00721017f,
3.6175f,4.32239f,8.63329f,-1.07431f,0.966388f,0.00884604f, 3.5968f,4.5158f,9.10236f,-1.12036f,0.964944f,0.0108065f,
3.57717f,4.72251f,9.61801f,-1.16807f,0.963242f,0.0131359f, 3.55328f,4.93703f,10.1914f,-1.21772f,0.961334f,0.0159185f,
3.52568f,5.16084f,10.8276f,-1.26942f,0.959213f,0.0192334f, 3.49277f,5.39263f,11.5398f,-1.3234f,0.956935f,0.0231797f,
3.47125f,5.66005f,12.3177f,-1.37933f,0.954252f,0.0278085f, 3.4276f,5.91161f,13.2061f,-1.43711f,0.951117f,0.0331881f,
3.38655f,6.18824f,14.1977f,-1.49736f,0.947863f,0.0394821f, 3.33638f,6.47128f,15.3122f,-1.55916f,0.944001f,0.0467227f,
3.29039f,6.78743f,16.553f,-1.6232f,0.939932f,0.0551312f, 3.23256f,7.10741f,17.9568f,-1.68833f,0.935244f,0.0647094f,
3.18143f,7.47134f,19.5006f,-1.7538f,0.929862f,0.0755124f, 3.14762f,7.90883f,21.2099f,-1.81989f,0.924311f,0.0877362f,
3.03227f,8.18239f,23.2281f,-1.88392f,0.917955f,0.101262f, 2.97786f,8.63733f,25.3131f,-1.94433f,0.91095f,0.116108f,
2.8546f,8.92325f,27.7601f,-1.99856f,0.903363f,0.132181f, 2.80171f,9.43614f,30.1026f,-2.04604f,0.896423f,0.149759f,
2.66036f,9.65483f,32.9802f,-2.08222f,0.890354f,0.168631f, 2.51114f,9.81153f,35.9059f,-2.10099f,0.885427f,0.188348f,
2.34878f,9.84101f,38.7444f,-2.09671f,0.882725f,0.208573f, 2.17207f,9.69223f,41.4397f,-2.06611f,0.884708f,0.229419f,
1.98145f,9.31246f,43.7411f,-2.00688f,0.894417f,0.251312f, 1.78191f,8.71084f,45.761f,-1.92122f,0.916252f,0.275442f,
1.55156f,7.80261f,47.7642f,-1.80343f,0.949735f,0.29937f, 1.36378f,6.9988f,49.5248f,-1.67716f,0.998398f,0.325993f,
3.49954f,3.33378e-07f,3.49954f,-2.53904e-17f,0.966875f,4.03733e-06f, 3.49955f,0.078478f,3.50126f,-0.0220642f,0.96687f,4.14929e-06f,
3.49957f,0.157043f,3.50641f,-0.0441486f,0.966854f,4.49167e-06f, 3.4996f,0.235783f,3.51502f,-0.0662738f,0.966827f,5.0843e-06f,
3.49964f,0.314786f,3.52712f,-0.0884602f,0.966789f,5.96127e-06f, 3.49969f,0.394142f,3.54277f,-0.110729f,0.96674f,7.17249e-06f,
3.49974f,0.473941f,3.56202f,-0.1331f,0.96668f,8.78608e-06f, 3.49978f,0.554273f,3.58496f,-0.155595f,0.966606f,1.08915e-05f,
3.49981f,0.635234f,3.6117f,-0.178236f,0.96652f,1.36038e-05f, 3.49982f,0.716919f,3.64233f,-0.201045f,0.96642f,1.70689e-05f,
3.49979f,0.799425f,3.67701f,-0.224044f,0.966304f,2.14701e-05f, 3.49973f,0.882853f,3.71588f,-0.247256f,0.966172f,2.70368e-05f,
3.4996f,0.967306f,3.75912f,-0.270705f,0.966022f,3.40545e-05f, 3.49939f,1.05289f,3.80695f,-0.294415f,0.965852f,4.28777e-05f,
3.49909f,1.13972f,3.85957f,-0.318411f,0.96566f,5.39445e-05f, 3.49869f,1.22791f,3.91724f,-0.342719f,0.965442f,6.77952e-05f,
3.49704f,1.31708f,3.97882f,-0.366975f,0.965525f,8.51525e-05f, 3.49445f,1.40742f,4.04481f,-0.391319f,0.965823f,0.000106793f,
3.49162f,1.49933f,4.11609f,-0.415967f,0.966175f,0.000133676f, 3.48909f,1.59318f,4.19322f,-0.44102f,0.966497f,0.000166976f,
3.4842f,1.68804f,4.27716f,-0.466483f,0.966838f,0.000208175f, 3.48037f,1.78547f,4.36808f,-0.492456f,0.967073f,0.00025892f,
3.47548f,1.88474f,4.46685f,-0.518958f,0.96722f,0.000321259f, 3.4707f,1.98654f,4.57344f,-0.545979f,0.967328f,0.000397559f,
3.46549f,2.09083f,4.68915f,-0.573596f,0.967248f,0.000490399f, 3.46028f,2.19808f,4.81438f,-0.601814f,0.967013f,0.000602889f,
3.45449f,2.30818f,4.94954f,-0.630624f,0.966724f,0.00073859f, 3.44855f,2.42167f,5.09595f,-0.660062f,0.966197f,0.000901051f,
3.44149f,2.53819f,5.25511f,-0.690363f,0.96558f,0.00110295f, 3.4349f,2.65919f,5.42701f,-0.721711f,0.965032f,0.00135956f,
3.42753f,2.78413f,5.61352f,-0.754367f,0.96475f,0.00169265f, 3.41792f,2.91209f,5.81661f,-0.787963f,0.964291f,0.00210139f,
3.40679f,3.04392f,6.03808f,-0.822524f,0.963635f,0.00260012f, 3.41294f,3.19725f,6.26816f,-0.858213f,0.96285f,0.00321236f,
3.38367f,3.32416f,6.54162f,-0.895347f,0.962233f,0.00397194f, 3.37195f,3.47397f,6.82747f,-0.93362f,0.961393f,0.00489014f,
3.36008f,3.63116f,7.13916f,-0.973051f,0.960279f,0.00599382f, 3.34326f,3.79106f,7.48237f,-1.01366f,0.958859f,0.00731288f,
3.3243f,3.95715f,7.85907f,-1.05548f,0.957139f,0.00888079f, 3.30419f,4.13126f,8.27419f,-1.09932f,0.95562f,0.0107919f,
3.28602f,4.3184f,8.72832f,-1.14462f,0.953805f,0.0130656f, 3.26119f,4.50828f,9.23254f,-1.19182f,0.951897f,0.0157966f,
3.23384f,4.70698f,9.78986f,-1.24041f,0.949562f,0.0190043f, 3.21045f,4.92537f,10.3993f,-1.2905f,0.946884f,0.0227524f,
3.17616f,5.14223f,11.0861f,-1.34236f,0.944004f,0.0271469f, 3.14222f,5.37578f,11.8436f,-1.39586f,0.940793f,0.0322804f,
3.09861f,5.61019f,12.6945f,-1.45115f,0.937347f,0.0382739f, 3.05769f,5.86803f,13.6357f,-1.50739f,0.933337f,0.0451447f,
3.0301f,6.17166f,14.6433f,-1.56526f,0.929253f,0.0530665f, 2.96489f,6.42532f,15.8336f,-1.62298f,0.924412f,0.0619954f,
2.90668f,6.71233f,17.1272f,-1.68058f,0.919123f,0.0720938f, 2.87346f,7.07983f,18.4735f,-1.73651f,0.913131f,0.0833206f,
2.76993f,7.30159f,20.1376f,-1.79106f,0.90719f,0.0958806f, 2.71097f,7.64741f,21.7853f,-1.84081f,0.900616f,0.109558f,
2.59986f,7.86349f,23.717f,-1.88423f,0.89386f,0.124402f, 2.55118f,8.25406f,25.5229f,-1.92004f,0.887781f,0.140542f,
2.41863f,8.38015f,27.672f,-1.94582f,0.883242f,0.158012f, 2.33694f,8.57165f,29.6451f,-1.95524f,0.880058f,0.176216f,
2.17791f,8.55575f,31.7028f,-1.94417f,0.87934f,0.194908f, 2.00949f,8.33541f,33.7091f,-1.91146f,0.883611f,0.214411f,
1.83403f,7.94429f,35.3472f,-1.85758f,0.896134f,0.235607f, 1.65089f,7.39681f,36.9014f,-1.77995f,0.918738f,0.258133f,
1.51971f,6.92928f,37.8452f,-1.67761f,0.951937f,0.28085f, 1.33774f,6.19946f,39.3794f,-1.56934f,0.998479f,0.306166f,
3.22418f,1.66745e-07f,3.22418f,-1.64002e-17f,0.965754f,7.41174e-06f, 3.22419f,0.0722649f,3.22576f,-0.0219742f,0.965746f,7.58212e-06f,
3.22423f,0.144611f,3.23049f,-0.0439673f,0.965722f,8.10133e-06f, 3.22427f,0.217118f,3.23839f,-0.0659985f,0.965681f,8.99392e-06f,
3.22434f,0.289867f,3.2495f,-0.0880868f,0.965624f,1.03018e-05f, 3.22442f,0.362939f,3.26385f,-0.110251f,0.965549f,1.20857e-05f,
3.22451f,0.436416f,3.28151f,-0.132512f,0.965456f,1.44274e-05f, 3.22459f,0.510386f,3.30256f,-0.154887f,0.965343f,1.74326e-05f,
3.22467f,0.584931f,3.32708f,-0.177398f,0.965209f,2.12345e-05f, 3.22474f,0.660141f,3.35518f,-0.200063f,0.965052f,2.59983e-05f,
3.22479f,0.736104f,3.38698f,-0.222903f,0.964871f,3.19268e-05f, 3.22479f,0.81291f,3.4226f,-0.245937f,0.964661f,3.92664e-05f,
3.22475f,0.890654f,3.46223f,-0.269187f,0.964422f,4.83146e-05f, 3.22463f,0.969431f,3.50603f,-0.292672f,0.964147f,5.94282e-05f,
3.22445f,1.04935f,3.5542f,-0.316412f,0.963834f,7.30321e-05f, 3.22422f,1.13052f,3.60697f,-0.340429f,0.963475f,8.96281e-05f,
3.22397f,1.21307f,3.66456f,-0.36474f,0.963066f,0.000109804f, 3.22387f,1.29719f,3.72719f,-0.389366f,0.962598f,0.000134243f,
3.22359f,1.38289f,3.79508f,-0.414324f,0.962062f,0.000163727f, 3.22286f,1.47019f,3.86875f,-0.439632f,0.961447f,0.000199141f,
3.2219f,1.55935f,3.94857f,-0.465306f,0.960741f,0.000241474f, 3.22101f,1.65066f,4.03489f,-0.491361f,0.959931f,0.000291814f,
3.21995f,1.74421f,4.12808f,-0.51781f,0.959002f,0.000351344f, 3.21794f,1.83975f,4.22877f,-0.544666f,0.957937f,0.000421334f,
3.21518f,1.93752f,4.33771f,-0.57208f,0.956826f,0.000506823f, 3.21199f,2.03789f,4.4552f,-0.600304f,0.955823f,0.000618042f,
3.20901f,2.14152f,4.58175f,-0.629496f,0.955008f,0.000765274f, 3.20537f,2.24805f,4.71818f,-0.659273f,0.954142f,0.000945836f,
3.20085f,2.35749f,4.86361f,-0.68935f,0.953452f,0.00116667f, 3.19281f,2.46803f,5.02093f,-0.720275f,0.952994f,0.0014474f,
3.18339f,2.58139f,5.19091f,-0.751915f,0.952563f,0.00179253f, 3.1748f,2.69976f,5.37459f,-0.78437f,0.952016f,0.00221303f,
3.1639f,2.82079f,5.57405f,-0.817648f,0.951356f,0.00272301f, 3.1537f,2.94752f,5.78997f,-0.851815f,0.950531f,0.00333854f,
3.14355f,3.07995f,6.02364f,-0.886874f,0.949534f,0.00407771f, 3.12908f,3.21408f,6.27928f,-0.922883f,0.948254f,0.00496066f,
3.11135f,3.35105f,6.56003f,-0.960098f,0.946984f,0.00602955f, 3.09702f,3.49878f,6.86415f,-0.998659f,0.945572f,0.00732354f,
3.07866f,3.64961f,7.19897f,-1.03877f,0.944186f,0.00889388f, 3.06767f,3.81802f,7.5582f,-1.08023f,0.942665f,0.0107707f,
3.03674f,3.97025f,7.96596f,-1.1228f,0.940738f,0.0129817f, 3.0173f,4.14715f,8.40337f,-1.16646f,0.938479f,0.0155708f,
2.99355f,4.32919f,8.88759f,-1.21147f,0.935995f,0.0186192f, 2.97627f,4.53286f,9.40973f,-1.25814f,0.933375f,0.0222312f,
2.93433f,4.71164f,10.0138f,-1.30616f,0.930533f,0.0264518f, 2.89829f,4.91189f,10.6648f,-1.35532f,0.927373f,0.031345f,
2.86241f,5.12673f,11.3863f,-1.40544f,0.923828f,0.0369985f, 2.87024f,5.43778f,12.1008f,-1.45614f,0.919861f,0.0434605f,
2.78107f,5.58539f,13.0469f,-1.50717f,0.915545f,0.0508222f, 2.73459f,5.82781f,14.0097f,-1.55809f,0.910843f,0.0591803f,
2.68526f,6.08092f,15.0521f,-1.6079f,0.90568f,0.0685336f, 2.64021f,6.35982f,16.1891f,-1.65637f,0.900402f,0.0790229f,
2.60529f,6.67883f,17.3492f,-1.70107f,0.894536f,0.0905127f, 2.48473f,6.79558f,18.8311f,-1.74154f,0.888695f,0.103131f,
2.43103f,7.08089f,20.1892f,-1.77534f,0.882897f,0.116744f, 2.3169f,7.18868f,21.7827f,-1.80259f,0.878423f,0.131758f,
2.26152f,7.44668f,23.1753f,-1.81943f,0.875375f,0.147835f, 2.12239f,7.41206f,24.8068f,-1.82181f,0.874131f,0.164657f,
2.02349f,7.44199f,26.1915f,-1.80633f,0.875596f,0.182f, 1.86404f,7.18767f,27.6652f,-1.77311f,0.882202f,0.200312f,
1.70243f,6.809f,28.9129f,-1.72425f,0.897245f,0.220726f, 1.54073f,6.33757f,30.0583f,-1.6539f,0.920565f,0.241741f,
1.42867f,5.95107f,30.6779f,-1.56515f,0.953856f,0.263568f, 1.27253f,5.37832f,31.8775f,-1.47127f,0.998544f,0.287545f,
2.98128f,-2.41134e-07f,2.98128f,-1.40107e-17f,0.963822f,1.27745e-05f, 2.98129f,0.0667659f,2.98272f,-0.0218312f,0.963809f,1.30152e-05f,
2.98134f,0.133607f,2.98708f,-0.0436792f,0.963769f,1.37461e-05f, 2.98141f,0.200595f,2.99436f,-0.0655607f,0.963702f,1.49936e-05f,
2.98152f,0.26781f,3.00459f,-0.0874925f,0.963606f,1.68027e-05f, 2.98164f,0.33532f,3.01782f,-0.109491f,0.963481f,1.92371e-05f,
2.98179f,0.403206f,3.0341f,-0.131574f,0.963325f,2.23809e-05f, 2.98195f,0.471543f,3.05349f,-0.153756f,0.963136f,2.63394e-05f,
2.9821f,0.54041f,3.07608f,-0.176054f,0.962909f,3.12407e-05f, 2.98225f,0.609887f,3.10195f,-0.198485f,0.962643f,3.72369e-05f,
2.9824f,0.680057f,3.13121f,-0.221064f,0.962333f,4.4505e-05f, 2.9825f,0.751f,3.16399f,-0.243807f,0.961974f,5.3247e-05f,
2.98257f,0.8228f,3.20044f,-0.266728f,0.96156f,6.36896e-05f, 2.98261f,0.895556f,3.2407f,-0.28984f,0.961084f,7.60817e-05f,
2.9826f,0.969358f,3.28494f,-0.313159f,0.960539f,9.06903e-05f, 2.98262f,1.04432f,3.33336f,-0.336696f,0.959916f,0.000107794f,
2.98275f,1.1206f,3.38613f,-0.360463f,0.959205f,0.000127673f, 2.98276f,1.1982f,3.4434f,-0.384471f,0.958395f,0.0001506f,
2.98243f,1.27717f,3.50561f,-0.40873f,0.957476f,0.000176822f, 2.98209f,1.35772f,3.57282f,-0.43325f,0.956434f,0.000206549f,
2.9812f,1.43987f,3.64573f,-0.458258f,0.955428f,0.000243916f, 2.97975f,1.52375f,3.72455f,-0.483956f,0.954588f,0.000294635f,
2.97756f,1.60937f,3.80955f,-0.51024f,0.953801f,0.000359811f, 2.97566f,1.69735f,3.90111f,-0.536972f,0.952931f,0.000439194f,
2.97281f,1.78726f,4.00001f,-0.564468f,0.952199f,0.000542923f, 2.97019f,1.87987f,4.10637f,-0.59251f,0.951395f,0.000670554f,
2.96794f,1.97555f,4.22084f,-0.621117f,0.950503f,0.000826892f, 2.96615f,2.07468f,4.34392f,-0.650315f,0.949512f,0.00101781f,
2.96101f,2.17475f,4.47755f,-0.680128f,0.948409f,0.00125015f, 2.95436f,2.27707f,4.62244f,-0.71058f,0.94718f,0.00153189f,
2.95011f,2.38509f,4.77789f,-0.74183f,0.945911f,0.00187718f, 2.94194f,2.49391f,4.94737f,-0.773793f,0.944502f,0.00229386f,
2.93608f,2.60913f,5.12931f,-0.806446f,0.942904f,0.00279269f, 2.92909f,2.72823f,5.32704f,-0.839932f,0.941183f,0.00339431f,
2.91767f,2.84818f,5.54241f,-0.874536f,0.939485f,0.00413319f, 2.90372f,2.97089f,5.77839f,-0.910212f,0.93774f,0.0050304f,
2.89413f,3.10413f,6.03166f,-0.946947f,0.935899f,0.00611285f, 2.88225f,3.24148f,6.30724f,-0.984554f,0.933812f,0.00739759f,
2.8664f,3.38129f,6.60826f,-1.02301f,0.931444f,0.00891401f, 2.84817f,3.52568f,6.9379f,-1.06231f,0.928781f,0.0106967f,
2.8313f,3.6799f,7.29806f,-1.10304f,0.926152f,0.0128362f, 2.8164f,3.84581f,7.68594f,-1.1448f,0.923295f,0.0153549f,
2.80924f,4.03299f,8.09996f,-1.18753f,0.920349f,0.018319f, 2.76553f,4.17741f,8.58438f,-1.23062f,0.91729f,0.021762f,
2.7835f,4.4183f,9.04526f,-1.27422f,0.913988f,0.0257432f, 2.70084f,4.52868f,9.65578f,-1.31843f,0.910484f,0.0303473f,
2.68634f,4.75254f,10.2405f,-1.36284f,0.906634f,0.035613f, 2.62179f,4.90027f,10.9458f,-1.40781f,0.902728f,0.0416771f,
2.61318f,5.16234f,11.6227f,-1.45283f,0.898688f,0.0486025f, 2.53954f,5.3119f,12.459f,-1.49667f,0.894215f,0.05635f,
2.54733f,5.63878f,13.2117f,-1.53942f,0.889646f,0.0650781f, 2.44093f,5.73363f,14.2316f,-1.57927f,0.884655f,0.0746862f,
2.37991f,5.9297f,15.2419f,-1.61602f,0.879765f,0.085316f, 2.34626f,6.19729f,16.1737f,-1.64759f,0.874802f,0.0968614f,
2.2297f,6.24678f,17.4258f,-1.67337f,0.870482f,0.109448f, 2.17627f,6.44595f,18.5099f,-1.69318f,0.867853f,0.123362f,
2.11651f,6.61101f,19.5481f,-1.70277f,0.866641f,0.138166f, 2.03139f,6.66913f,20.621f,-1.6996f,0.867489f,0.153694f,
1.88354f,6.48535f,21.8302f,-1.6814f,0.871349f,0.169831f, 1.80236f,6.44659f,22.5779f,-1.64856f,0.8803f,0.187032f,
1.65654f,6.09359f,23.542f,-1.60455f,0.897743f,0.206667f, 1.49288f,5.62656f,24.4619f,-1.54085f,0.921835f,0.226315f,
1.35884f,5.1795f,25.0896f,-1.46395f,0.955507f,0.247464f, 1.25425f,4.81954f,25.8459f,-1.38161f,0.998592f,0.270082f,
2.76743f,-1.50446e-06f,2.76742f,-1.29811e-17f,0.960304f,2.02792e-05f, 2.76745f,0.0618908f,2.76877f,-0.021573f,0.96028f,2.05776e-05f,
2.76752f,0.123848f,2.77281f,-0.0431589f,0.960209f,2.14792e-05f, 2.76765f,0.185946f,2.77955f,-0.0647702f,0.960089f,2.30028e-05f,
2.7678f,0.248248f,2.78903f,-0.0864196f,0.959918f,2.5179e-05f, 2.76799f,0.310826f,2.80128f,-0.108119f,0.959695f,2.80491e-05f,
2.76822f,0.373752f,2.81635f,-0.129882f,0.959416f,3.16631e-05f, 2.76848f,0.437093f,2.83429f,-0.151718f,0.959077f,3.6077e-05f,
2.76875f,0.500923f,2.85519f,-0.173639f,0.958673f,4.13484e-05f, 2.76903f,0.565315f,2.87911f,-0.195655f,0.9582f,4.75318e-05f,
2.76929f,0.630339f,2.90616f,-0.217778f,0.957651f,5.46705e-05f, 2.76956f,0.696077f,2.93643f,-0.240016f,0.957018f,6.27884e-05f,
2.7698f,0.762604f,2.97005f,-0.262378f,0.956295f,7.18779e-05f, 2.77005f,0.830015f,3.00714f,-0.284872f,0.955474f,8.18868e-05f,
2.77033f,0.898399f,3.04785f,-0.307508f,0.954547f,9.27032e-05f, 2.7705f,0.967816f,3.09233f,-0.330357f,0.953556f,0.000104836f,
2.7702f,1.0383f,3.14045f,-0.353792f,0.95278f,0.000122817f, 2.76956f,1.10993f,3.19266f,-0.377655f,0.952074f,0.000146396f,
2.76833f,1.18272f,3.24933f,-0.401952f,0.951421f,0.000176764f, 2.7674f,1.25706f,3.31058f,-0.426678f,0.950795f,0.000215433f,
2.7718f,1.33512f,3.3754f,-0.451758f,0.950107f,0.000262755f, 2.76497f,1.41034f,3.44818f,-0.477211f,0.949351f,0.000320599f,
2.76328f,1.48954f,3.52537f,-0.503157f,0.948606f,0.000392997f, 2.76175f,1.57088f,3.60853f,-0.529601f,0.947844f,0.000482908f,
2.75988f,1.65427f,3.69813f,-0.556491f,0.946996f,0.000592469f, 2.75861f,1.74043f,3.79427f,-0.583845f,0.94605f,0.000725522f,
2.75796f,1.82969f,3.89727f,-0.611678f,0.944994f,0.000886516f, 2.76168f,1.92496f,4.00561f,-0.640006f,0.943812f,0.00108056f,
2.7474f,2.01046f,4.13038f,-0.668838f,0.942489f,0.0013135f, 2.74207f,2.10532f,4.26044f,-0.698183f,0.941008f,0.00159193f,
2.73599f,2.20292f,4.40162f,-0.728172f,0.939434f,0.00192856f, 2.73162f,2.30565f,4.55222f,-0.759039f,0.937897f,0.00234488f,
2.72553f,2.41096f,4.71577f,-0.790791f,0.936366f,0.00285583f, 2.71579f,2.51713f,4.89335f,-0.823336f,0.934746f,0.00347436f,
2.70472f,2.62639f,5.08605f,-0.856554f,0.932934f,0.00421211f, 2.69758f,2.74452f,5.2919f,-0.890437f,0.930904f,0.00508783f,
2.68679f,2.86426f,5.5164f,-0.925134f,0.928735f,0.00613247f, 2.67308f,2.9864f,5.75992f,-0.960615f,0.926388f,0.00737166f,
2.65583f,3.11037f,6.02848f,-0.997165f,0.924016f,0.00885892f, 2.64208f,3.24495f,6.31676f,-1.03442f,0.921387f,0.0106064f,
2.63906f,3.40046f,6.61814f,-1.07272f,0.918701f,0.0126843f, 2.62951f,3.55631f,6.9479f,-1.11155f,0.915671f,0.0150992f,
2.587f,3.67506f,7.34106f,-1.15088f,0.912308f,0.0178974f, 2.60162f,3.88327f,7.70247f,-1.19096f,0.908794f,0.0211653f,
2.53372f,3.9789f,8.18839f,-1.23127f,0.904907f,0.0249176f, 2.51667f,4.15976f,8.6561f,-1.27207f,0.900876f,0.0292599f,
2.48877f,4.3331f,9.17237f,-1.31307f,0.89666f,0.0342501f, 2.45162f,4.49983f,9.74048f,-1.35349f,0.89204f,0.0398933f,
2.43443f,4.71266f,10.3275f,-1.39365f,0.887401f,0.0463218f, 2.3732f,4.85126f,11.0184f,-1.43278f,0.882633f,0.053574f,
2.3423f,5.05561f,11.6967f,-1.46947f,0.877458f,0.0615826f, 2.30322f,5.25112f,12.4419f,-1.50384f,0.872376f,0.0705164f,
2.25932f,5.44026f,13.2107f,-1.53413f,0.867179f,0.0802718f, 2.22111f,5.64397f,14.0045f,-1.5597f,0.862281f,0.090932f,
2.09897f,5.63325f,15.0072f,-1.5797f,0.858218f,0.102584f, 2.03459f,5.7445f,15.8628f,-1.59245f,0.856882f,0.115453f,
1.98335f,5.86918f,16.6167f,-1.59564f,0.857454f,0.129072f, 1.89792f,5.85967f,17.4311f,-1.58793f,0.860431f,0.143395f,
1.75625f,5.65919f,18.3094f,-1.56777f,0.866629f,0.158381f, 1.67979f,5.57924f,18.9066f,-1.53644f,0.878138f,0.174704f,
1.54486f,5.26319f,19.6389f,-1.49637f,0.897606f,0.193381f, 1.42055f,4.92722f,20.2405f,-1.43879f,0.922569f,0.211816f,
1.32927f,4.63724f,20.5965f,-1.37198f,0.956761f,0.232351f, 1.20016f,4.22442f,21.3177f,-1.29927f,0.998627f,0.253725f,
2.58112f,1.34726e-06f,2.58112f,-2.34566e-17f,0.953621f,2.80232e-05f, 2.58115f,0.0575715f,2.58237f,-0.021077f,0.953579f,2.82873e-05f,
2.58124f,0.115204f,2.58613f,-0.042161f,0.953452f,2.90758e-05f, 2.5814f,0.172966f,2.5924f,-0.0632589f,0.953239f,3.03767e-05f,
2.58163f,0.230918f,2.6012f,-0.0843774f,0.952938f,3.21673e-05f, 2.5819f,0.289123f,2.6126f,-0.105523f,0.952547f,3.44096e-05f,
2.58221f,0.347649f,2.6266f,-0.126703f,0.952062f,3.7045e-05f, 2.58256f,0.406557f,2.64324f,-0.147924f,0.95148f,3.99856e-05f,
2.58294f,0.465912f,2.66261f,-0.169192f,0.950796f,4.31052e-05f, 2.58333f,0.525784f,2.68476f,-0.190513f,0.950005f,4.62274e-05f,
2.5836f,0.586232f,2.7097f,-0.211979f,0.949172f,4.96377e-05f, 2.58343f,0.647307f,2.73723f,-0.233971f,0.948594f,5.59789e-05f,
2.58303f,0.709085f,2.76762f,-0.256322f,0.948128f,6.50086e-05f, 2.58264f,0.771664f,2.80112f,-0.278923f,0.947663f,7.65263e-05f,
2.58219f,0.835108f,2.83781f,-0.301807f,0.947217f,9.12547e-05f, 2.58195f,0.899574f,2.87787f,-0.325003f,0.946797f,0.000110133f,
2.58077f,0.964775f,2.92149f,-0.348448f,0.946323f,0.000133298f, 2.57967f,1.0311f,2.96906f,-0.372159f,0.945793f,0.000161651f,
2.57869f,1.09867f,3.02071f,-0.396152f,0.945201f,0.00019627f, 2.57966f,1.16829f,3.07629f,-0.420443f,0.944541f,0.00023843f,
2.57623f,1.2376f,3.13665f,-0.445113f,0.943872f,0.000290542f, 2.57542f,1.30944f,3.20142f,-0.47012f,0.943128f,0.00035378f,
2.57485f,1.38314f,3.27122f,-0.495466f,0.942289f,0.000430054f, 2.57398f,1.45866f,3.34656f,-0.521162f,0.941344f,0.000521718f,
2.57371f,1.53663f,3.42733f,-0.547216f,0.940281f,0.000631465f, 2.57421f,1.61744f,3.51359f,-0.573636f,0.939088f,0.000762357f,
2.5909f,1.70701f,3.59581f,-0.600428f,0.937749f,0.000917863f, 2.56346f,1.7789f,3.71022f,-0.627805f,0.936395f,0.00110876f,
2.55709f,1.8626f,3.82033f,-0.655809f,0.935031f,0.00134374f, 2.55355f,1.95113f,3.93727f,-0.684599f,0.93374f,0.00163719f,
2.55056f,2.04326f,4.06232f,-0.713889f,0.932299f,0.00198909f, 2.54732f,2.13865f,4.19629f,-0.743679f,0.930691f,0.00240939f,
2.54451f,2.23808f,4.33946f,-0.774065f,0.92896f,0.00291366f, 2.52821f,2.32907f,4.50249f,-0.805136f,0.927148f,0.00352084f,
2.52059f,2.4318f,4.67187f,-0.836707f,0.925115f,0.00423875f, 2.51287f,2.53885f,4.8557f,-0.868889f,0.922923f,0.00509182f,
2.50069f,2.64586f,5.05451f,-0.901868f,0.920671f,0.00611535f, 2.48581f,2.75466f,5.27231f,-0.935517f,0.91827f,0.00732926f,
2.47653f,2.87492f,5.50263f,-0.969956f,0.915796f,0.0087718f, 2.47216f,3.0071f,5.74506f,-1.00488f,0.913067f,0.0104564f,
2.46069f,3.13728f,6.01355f,-1.04019f,0.910049f,0.012414f, 2.42956f,3.24825f,6.31953f,-1.0762f,0.90694f,0.0147161f,
2.43025f,3.40837f,6.62042f,-1.11251f,0.903558f,0.0173792f, 2.38175f,3.50662f,6.98948f,-1.14943f,0.900117f,0.0204906f,
2.36565f,3.65745f,7.35999f,-1.18638f,0.896387f,0.0240612f, 2.3681f,3.84221f,7.73023f,-1.22329f,0.892432f,0.0281554f,
2.30896f,3.94344f,8.2f,-1.25963f,0.88813f,0.0327915f, 2.27619f,4.08898f,8.67405f,-1.29552f,0.883715f,0.0380726f,
2.25758f,4.26646f,9.15117f,-1.33051f,0.879189f,0.0440387f, 2.25695f,4.48566f,9.63291f,-1.36393f,0.874538f,0.0507045f,
2.16069f,4.52672f,10.2983f,-1.39569f,0.870044f,0.0581974f, 2.11729f,4.66881f,10.8959f,-1.4241f,0.865379f,0.0664039f,
2.06715f,4.79609f,11.5427f,-1.44887f,0.860939f,0.0754255f, 2.0128f,4.90878f,12.1984f,-1.46895f,0.856902f,0.0852626f,
1.97238f,5.04391f,12.8444f,-1.48443f,0.854052f,0.0961216f, 1.90894f,5.11161f,13.5285f,-1.4941f,0.852791f,0.108005f,
1.80275f,5.04787f,14.2896f,-1.49509f,0.852936f,0.120591f, 1.77634f,5.16442f,14.8332f,-1.48621f,0.855116f,0.133845f,
1.64076f,4.9449f,15.5402f,-1.46468f,0.861788f,0.147726f, 1.58156f,4.88257f,15.8985f,-1.4358f,0.876028f,0.163451f,
1.46978f,4.63214f,16.4412f,-1.39808f,0.896851f,0.180838f, 1.38213f,4.40789f,16.7809f,-1.34607f,0.922785f,0.198203f,
1.27151f,4.07806f,17.1797f,-1.28783f,0.957607f,0.218145f, 1.18588f,3.81789f,17.5903f,-1.2233f,0.99865f,0.238422f,
2.42264f,5.04659e-07f,2.42265f,-6.36672e-18f,0.941103f,2.78816e-05f, 2.42267f,0.0537697f,2.4238f,-0.0201957f,0.941039f,2.7847e-05f,
2.42276f,0.107597f,2.42727f,-0.0403944f,0.940846f,2.7719e-05f, 2.4229f,0.161541f,2.43306f,-0.0605993f,0.940525f,2.74242e-05f,
2.42312f,0.215661f,2.4412f,-0.0808135f,0.940074f,2.68364e-05f, 2.42281f,0.270055f,2.45119f,-0.101527f,0.939893f,2.74666e-05f,
2.42214f,0.324747f,2.4632f,-0.12263f,0.939908f,2.95605e-05f, 2.42141f,0.379767f,2.47756f,-0.143917f,0.939931f,3.27038e-05f,
2.42052f,0.435155f,2.49427f,-0.165419f,0.939996f,3.72812e-05f, 2.41963f,0.490975f,2.51354f,-0.187061f,0.940002f,4.31419e-05f,
2.41874f,0.547289f,2.53546f,-0.208855f,0.939949f,5.05393e-05f, 2.41786f,0.604171f,2.56009f,-0.230812f,0.939836f,5.97766e-05f,
2.41693f,0.661676f,2.58745f,-0.252981f,0.939713f,7.14824e-05f, 2.41612f,0.719907f,2.61773f,-0.275335f,0.939521f,8.58486e-05f,
2.41554f,0.778973f,2.65102f,-0.297885f,0.939259f,0.000103376f, 2.41434f,0.838704f,2.68734f,-0.320642f,0.938922f,0.000124651f,
2.41352f,0.899469f,2.72716f,-0.343615f,0.938503f,0.000150356f, 2.41212f,0.96103f,2.77047f,-0.366814f,0.937998f,0.000181279f,
2.41124f,1.02383f,2.81738f,-0.390248f,0.9374f,0.000218324f, 2.40996f,1.08763f,2.8681f,-0.413924f,0.936699f,0.000262526f,
2.40952f,1.15296f,2.92251f,-0.43785f,0.935889f,0.000315059f, 2.40975f,1.21995f,2.98085f,-0.462032f,0.934959f,0.000377251f,
2.40987f,1.28861f,3.04392f,-0.486475f,0.9339f,0.000450597f, 2.40897f,1.3587f,3.11265f,-0.511203f,0.932715f,0.000537256f,
2.40976f,1.43171f,3.18523f,-0.536529f,0.931612f,0.000647242f, 2.40237f,1.50203f,3.26558f,-0.562421f,0.930548f,0.00078472f,
2.40037f,1.57754f,3.35055f,-0.58874f,0.929401f,0.000951554f, 2.39637f,1.654f,3.44195f,-0.615427f,0.928115f,0.00115123f,
2.39267f,1.73304f,3.54025f,-0.64263f,0.92678f,0.00139412f, 2.39077f,1.81601f,3.64436f,-0.670351f,0.925383f,0.00168803f,
2.38857f,1.90166f,3.75549f,-0.698509f,0.923858f,0.00203857f, 2.38998f,1.99367f,3.87169f,-0.727057f,0.92215f,0.00245381f,
2.37349f,2.07307f,4.00758f,-0.75598f,0.92024f,0.0029436f, 2.36473f,2.16233f,4.14961f,-0.785639f,0.918349f,0.00353898f,
2.35864f,2.2576f,4.30056f,-0.815771f,0.916296f,0.00424504f, 2.34806f,2.3522f,4.46342f,-0.846589f,0.914207f,0.00509317f,
2.33733f,2.45047f,4.63852f,-0.877779f,0.911881f,0.00608829f, 2.32979f,2.5564f,4.82451f,-0.909288f,0.909299f,0.0072503f,
2.31888f,2.66333f,5.02727f,-0.941136f,0.906485f,0.00860677f, 2.30328f,2.76957f,5.24703f,-0.973649f,0.903644f,0.0102149f,
2.28472f,2.87678f,5.48688f,-1.00656f,0.900643f,0.0120944f, 2.27594f,3.00139f,5.73439f,-1.03987f,0.897521f,0.0142897f,
2.25472f,3.11519f,6.01139f,-1.07341f,0.894247f,0.016826f, 2.23336f,3.2339f,6.30704f,-1.10718f,0.890869f,0.0197673f,
2.24821f,3.411f,6.58335f,-1.14056f,0.887154f,0.0231121f, 2.18424f,3.47759f,6.96291f,-1.17367f,0.883281f,0.0269368f,
2.16984f,3.62344f,7.31892f,-1.20635f,0.879307f,0.0313006f, 2.16246f,3.78761f,7.67762f,-1.23796f,0.875105f,0.0362114f,
2.09997f,3.86274f,8.13768f,-1.26826f,0.870789f,0.0417277f, 2.06816f,3.9917f,8.57192f,-1.29749f,0.866749f,0.0479708f,
2.03166f,4.11405f,9.02712f,-1.32411f,0.862606f,0.0548497f, 1.985f,4.21627f,9.53141f,-1.34786f,0.858648f,0.0624534f,
1.94787f,4.33376f,10.013f,-1.36783f,0.854943f,0.0707711f, 1.89436f,4.41207f,10.5423f,-1.38342f,0.851807f,0.0798537f,
1.85377f,4.50613f,11.0448f,-1.39516f,0.850144f,0.089966f, 1.79028f,4.53454f,11.6007f,-1.40123f,0.849968f,0.100956f,
1.73967f,4.55907f,12.1105f,-1.39959f,0.851286f,0.112626f, 1.66047f,4.5252f,12.5963f,-1.38926f,0.854618f,0.12493f,
1.59588f,4.48054f,13.041f,-1.36987f,0.860783f,0.137947f, 1.50574f,4.32193f,13.474f,-1.34415f,0.873543f,0.152909f,
1.43059f,4.16055f,13.7575f,-1.30851f,0.895584f,0.169077f, 1.30563f,3.84843f,14.1788f,-1.26156f,0.922589f,0.185502f,
1.2429f,3.66619f,14.3551f,-1.21047f,0.958085f,0.204814f, 1.14386f,3.38555f,14.7305f,-1.15295f,0.998662f,0.224117f,
2.28205f,-1.01416e-06f,2.28204f,-1.85576e-17f,0.926616f,1.60221e-05f, 2.28206f,0.0507955f,2.28312f,-0.0211901f,0.926594f,1.63233e-05f,
2.28212f,0.101645f,2.28633f,-0.0423924f,0.926527f,1.72376e-05f, 2.2815f,0.152436f,2.29101f,-0.0631308f,0.926825f,1.9371e-05f,
2.28041f,0.203248f,2.29732f,-0.0836346f,0.927353f,2.23699e-05f, 2.27918f,0.254198f,2.30565f,-0.104178f,0.927891f,2.59995e-05f,
2.27795f,0.305367f,2.31621f,-0.124827f,0.928347f,3.02869e-05f, 2.27664f,0.356791f,2.32891f,-0.145579f,0.928775f,3.55291e-05f,
2.27536f,0.408542f,2.34396f,-0.166463f,0.929101f,4.18074e-05f, 2.27411f,0.460677f,2.36138f,-0.187485f,0.929324f,4.93569e-05f,
2.27289f,0.513257f,2.38122f,-0.208651f,0.929459f,5.84697e-05f, 2.27168f,0.566336f,2.40352f,-0.229968f,0.929534f,6.94939e-05f,
2.27061f,0.620003f,2.4284f,-0.251444f,0.929502f,8.26508e-05f, 2.2698f,0.674362f,2.45593f,-0.273082f,0.929361f,9.82933e-05f,
2.26892f,0.72939f,2.48613f,-0.294887f,0.929105f,0.000116814f, 2.26776f,0.785094f,2.51929f,-0.316866f,0.928731f,0.000138649f,
2.26649f,0.841567f,2.55551f,-0.339021f,0.928234f,0.00016428f, 2.26579f,0.89911f,2.59487f,-0.361356f,0.927609f,0.000194244f,
2.26481f,0.957476f,2.63729f,-0.383898f,0.926912f,0.000229371f, 2.26487f,1.01718f,2.6827f,-0.406629f,0.926076f,0.000270069f,
2.2639f,1.07777f,2.73232f,-0.429821f,0.925289f,0.000321732f, 2.26258f,1.13961f,2.78596f,-0.453509f,0.924563f,0.000387537f,
2.26316f,1.20378f,2.84299f,-0.477505f,0.923746f,0.0004671f, 2.26328f,1.26955f,2.90445f,-0.501827f,0.92284f,0.000563198f,
2.27231f,1.34197f,2.96914f,-0.526598f,0.921922f,0.000681736f, 2.25676f,1.40265f,3.04218f,-0.551664f,0.920865f,0.000823401f,
2.25356f,1.47194f,3.11878f,-0.577028f,0.919661f,0.000992157f, 2.25512f,1.5465f,3.19896f,-0.602717f,0.918338f,0.00119298f,
2.25076f,1.61929f,3.28683f,-0.628737f,0.916896f,0.00143116f, 2.24926f,1.69646f,3.37891f,-0.65504f,0.915272f,0.00171191f,
2.24176f,1.77152f,3.4813f,-0.681967f,0.913684f,0.00205542f, 2.23147f,1.84651f,3.59252f,-0.709343f,0.912002f,0.00246702f,
2.23368f,1.93477f,3.70428f,-0.73731f,0.910307f,0.00296565f, 2.22304f,2.01481f,3.83073f,-0.765576f,0.908404f,0.00355293f,
2.2143f,2.09939f,3.96389f,-0.79411f,0.906277f,0.00424163f, 2.20537f,2.18693f,4.10656f,-0.822871f,0.90391f,0.00504575f,
2.19482f,2.27619f,4.26354f,-0.852202f,0.901535f,0.00600244f, 2.1879f,2.37277f,4.4258f,-0.882105f,0.899162f,0.00713831f,
2.17284f,2.4643f,4.60595f,-0.912277f,0.896606f,0.00846556f, 2.16044f,2.56244f,4.79518f,-0.942699f,0.893878f,0.0100143f,
2.15408f,2.67198f,4.99285f,-0.973078f,0.890855f,0.0117962f, 2.13347f,2.76844f,5.21504f,-1.00368f,0.887734f,0.013872f,
2.11526f,2.87159f,5.44871f,-1.03406f,0.884329f,0.0162473f, 2.10361f,2.98793f,5.69533f,-1.06427f,0.880761f,0.0189749f,
2.09158f,3.10955f,5.95399f,-1.09453f,0.877264f,0.0221192f, 2.05495f,3.19721f,6.25453f,-1.1244f,0.873692f,0.0257145f,
2.07451f,3.37531f,6.50723f,-1.15335f,0.869938f,0.0297676f, 2.00462f,3.41698f,6.88137f,-1.18142f,0.866206f,0.0343645f,
1.99888f,3.56076f,7.17781f,-1.20798f,0.862397f,0.0395094f, 1.9645f,3.66457f,7.54832f,-1.23245f,0.858526f,0.0452103f,
1.92251f,3.75137f,7.9389f,-1.25526f,0.855124f,0.0516138f, 1.87762f,3.82889f,8.33389f,-1.27495f,0.851875f,0.0586396f,
1.83834f,3.91239f,8.72958f,-1.29092f,0.848957f,0.0663075f, 1.78425f,3.95767f,9.14968f,-1.303f,0.846817f,0.0747282f,
1.74285f,4.01964f,9.56031f,-1.31168f,0.846265f,0.0841308f, 1.68013f,4.02175f,9.99392f,-1.31501f,0.84716f,0.0943126f,
1.6302f,4.03646f,10.3804f,-1.31152f,0.8496f,0.105151f, 1.55413f,3.9682f,10.7964f,-1.30029f,0.853986f,0.116581f,
1.50918f,3.94882f,11.0994f,-1.28169f,0.86128f,0.12883f, 1.46732f,3.90795f,11.3596f,-1.25951f,0.874008f,0.143147f,
1.37393f,3.71169f,11.6983f,-1.22648f,0.893808f,0.158052f, 1.29441f,3.52018f,11.9065f,-1.18395f,0.921911f,0.173596f,
1.19744f,3.25766f,12.1476f,-1.13903f,0.958231f,0.192324f, 1.12683f,3.06556f,12.3706f,-1.08753f,0.998664f,0.210759f,
2.14152f,-8.97151e-07f,2.14151f,-3.11903e-18f,0.920984f,2.35164e-05f, 2.14153f,0.047491f,2.14251f,-0.0208031f,0.920952f,2.38741e-05f,
2.14159f,0.09503f,2.1455f,-0.0416149f,0.920857f,2.49562e-05f, 2.14169f,0.142666f,2.15047f,-0.0624439f,0.920697f,2.67896e-05f,
2.1418f,0.190449f,2.15747f,-0.0832987f,0.920471f,2.94191e-05f, 2.14194f,0.238427f,2.16651f,-0.104188f,0.920178f,3.29072e-05f,
2.14208f,0.286651f,2.17763f,-0.125119f,0.919816f,3.73339e-05f, 2.14223f,0.335166f,2.19085f,-0.1461f,0.919382f,4.2796e-05f,
2.1424f,0.384029f,2.2062f,-0.16714f,0.918873f,4.94069e-05f, 2.14261f,0.43329f,2.22374f,-0.188245f,0.918285f,5.7295e-05f,
2.14248f,0.482846f,2.24305f,-0.20914f,0.917832f,6.67081e-05f, 2.14205f,0.532751f,2.26417f,-0.229871f,0.917494f,7.77494e-05f,
2.14169f,0.58316f,2.28738f,-0.250598f,0.917158f,9.05228e-05f, 2.14381f,0.634774f,2.3129f,-0.271401f,0.916755f,0.000105178f,
2.14062f,0.685631f,2.34046f,-0.292298f,0.916265f,0.000121886f, 2.13915f,0.737589f,2.37106f,-0.313324f,0.915678f,0.000140969f,
2.13761f,0.790294f,2.40428f,-0.334778f,0.915245f,0.00016622f, 2.13635f,0.843875f,2.43997f,-0.356602f,0.914814f,0.000198124f,
2.13504f,0.898273f,2.47861f,-0.378689f,0.914329f,0.000236905f, 2.135f,0.953974f,2.51976f,-0.401106f,0.913897f,0.000285111f,
2.13566f,1.01113f,2.56422f,-0.423751f,0.913331f,0.000342693f, 2.13605f,1.06959f,2.61227f,-0.446624f,0.912628f,0.00041132f,
2.13684f,1.12978f,2.66362f,-0.469734f,0.911786f,0.000493007f, 2.13493f,1.19014f,2.71866f,-0.493212f,0.910991f,0.000592455f,
2.13193f,1.25142f,2.77838f,-0.516923f,0.910043f,0.000710201f, 2.12948f,1.31461f,2.8422f,-0.540863f,0.908927f,0.000849145f,
2.12852f,1.38051f,2.91015f,-0.565025f,0.907634f,0.00101256f, 2.12535f,1.44683f,2.98455f,-0.589652f,0.906322f,0.00121207f,
2.12221f,1.51504f,3.06336f,-0.614692f,0.904992f,0.00145259f, 2.11697f,1.58364f,3.14719f,-0.640208f,0.903665f,0.00174428f,
2.11093f,1.65361f,3.23749f,-0.66597f,0.902149f,0.00208842f, 2.10853f,1.72874f,3.33252f,-0.691956f,0.900435f,0.00249296f,
2.10264f,1.80344f,3.43544f,-0.718215f,0.898557f,0.0029698f, 2.11509f,1.89675f,3.5346f,-0.744796f,0.896549f,0.0035335f,
2.10779f,1.97224f,3.64725f,-0.771889f,0.894568f,0.0042073f, 2.07957f,2.0377f,3.79007f,-0.799229f,0.892443f,0.00499687f,
2.08111f,2.13067f,3.91998f,-0.826947f,0.890242f,0.00593117f, 2.06052f,2.20416f,4.06893f,-0.854752f,0.887812f,0.00701614f,
2.05002f,2.29085f,4.22164f,-0.882539f,0.885122f,0.00826813f, 2.04126f,2.38272f,4.38684f,-0.910552f,0.882348f,0.00973287f,
2.05031f,2.49911f,4.54468f,-0.938588f,0.879455f,0.0114223f, 2.0305f,2.58541f,4.74107f,-0.966664f,0.876487f,0.0133774f,
1.99481f,2.65424f,4.95344f,-0.994577f,0.873385f,0.0156269f, 2.01507f,2.79857f,5.13218f,-1.02229f,0.870206f,0.018216f,
1.98874f,2.88539f,5.35938f,-1.04925f,0.866775f,0.0211426f, 1.94256f,2.94525f,5.6237f,-1.07552f,0.86326f,0.02446f,
1.92383f,3.04553f,5.87495f,-1.10135f,0.859954f,0.0282527f, 1.89081f,3.12562f,6.1456f,-1.12601f,0.856656f,0.0325195f,
1.90108f,3.27705f,6.38488f,-1.14887f,0.853264f,0.0372567f, 1.8652f,3.35601f,6.68342f,-1.17015f,0.850148f,0.0425833f,
1.82118f,3.41456f,6.9996f,-1.1891f,0.847258f,0.0484711f, 1.77509f,3.46679f,7.32835f,-1.20533f,0.844777f,0.0549574f,
1.73479f,3.52309f,7.64418f,-1.2182f,0.842801f,0.062068f, 1.68346f,3.55005f,7.98788f,-1.22756f,0.841727f,0.0699004f,
1.68921f,3.68998f,8.21334f,-1.2336f,0.842185f,0.0786131f, 1.58725f,3.58336f,8.65797f,-1.23491f,0.84416f,0.0880685f,
1.5716f,3.65037f,8.90271f,-1.23006f,0.847661f,0.0981369f, 1.51456f,3.61216f,9.17653f,-1.21848f,0.8531f,0.108798f,
1.43544f,3.49874f,9.5043f,-1.20099f,0.861516f,0.120385f, 1.37602f,3.40945f,9.76862f,-1.18081f,0.875114f,0.133985f,
1.29068f,3.24022f,10.0804f,-1.15153f,0.891783f,0.147809f, 1.23061f,3.09904f,10.185f,-1.11253f,0.920867f,0.162524f,
1.1745f,2.94903f,10.3059f,-1.07277f,0.958075f,0.180637f, 1.09466f,2.74594f,10.4986f,-1.02649f,0.998657f,0.198295f,
2.01782f,8.35421e-08f,2.01782f,-2.80643e-17f,0.912291f,3.11923e-05f, 2.01783f,0.0444942f,2.01873f,-0.0202304f,0.912248f,3.15462e-05f,
2.01788f,0.0890325f,2.02148f,-0.0404659f,0.912117f,3.26111e-05f, 2.01795f,0.133659f,2.0261f,-0.0607115f,0.911898f,3.43967e-05f,
2.01805f,0.178414f,2.03258f,-0.0809723f,0.911591f,3.69181e-05f, 2.01817f,0.223348f,2.04093f,-0.101253f,0.911193f,4.01945e-05f,
2.01833f,0.268503f,2.05118f,-0.121559f,0.910703f,4.42472e-05f, 2.01849f,0.313925f,2.06337f,-0.141894f,0.910119f,4.90965e-05f,
2.01872f,0.35966f,2.07752f,-0.162263f,0.909438f,5.47589e-05f, 2.01903f,0.405772f,2.09365f,-0.182671f,0.908659f,6.12429e-05f,
2.01948f,0.452314f,2.11181f,-0.203121f,0.907777f,6.85443e-05f, 2.01946f,0.499256f,2.13213f,-0.223775f,0.906905f,7.76478e-05f,
2.02003f,0.546898f,2.1543f,-0.244807f,0.906166f,9.02696e-05f, 2.02111f,0.59527f,2.17845f,-0.266094f,0.905463f,0.00010641f,
2.02015f,0.643725f,2.20497f,-0.287528f,0.904702f,0.000125965f, 2.01971f,0.692938f,2.23381f,-0.309129f,0.903892f,0.000149686f,
2.03058f,0.746262f,2.26547f,-0.330952f,0.903069f,0.000178844f, 2.02065f,0.793925f,2.2987f,-0.352919f,0.902155f,0.000213626f,
2.02213f,0.845715f,2.33414f,-0.374768f,0.901338f,0.000255003f, 2.02377f,0.89862f,2.37219f,-0.396585f,0.900559f,0.000304045f,
2.02488f,0.952604f,2.41318f,-0.418477f,0.899741f,0.000361976f, 2.02668f,1.00828f,2.45674f,-0.440497f,0.898829f,0.000430182f,
2.02567f,1.06398f,2.50267f,-0.462618f,0.897866f,0.000510285f, 2.02167f,1.1194f,2.5542f,-0.484969f,0.896808f,0.000605153f,
2.02138f,1.17826f,2.60775f,-0.507724f,0.895818f,0.000722326f, 2.01676f,1.23594f,2.6668f,-0.53084f,0.894837f,0.00086515f,
2.01597f,1.29745f,2.72793f,-0.554227f,0.893729f,0.00103569f, 2.01577f,1.36104f,2.79235f,-0.577798f,0.892521f,0.0012369f,
2.00932f,1.422f,2.86312f,-0.601621f,0.891215f,0.00147568f, 2.00432f,1.48555f,2.93813f,-0.625746f,0.889796f,0.00175998f,
2.00237f,1.55322f,3.01731f,-0.650034f,0.888195f,0.00209287f, 1.99591f,1.6193f,3.10434f,-0.674597f,0.886558f,0.0024867f,
2.00094f,1.69688f,3.19026f,-0.699474f,0.88482f,0.00295485f, 1.98451f,1.75874f,3.29297f,-0.72462f,0.882961f,0.00350816f,
1.99149f,1.84338f,3.38818f,-0.749982f,0.880977f,0.00415863f, 1.97263f,1.90656f,3.50566f,-0.775487f,0.878901f,0.00491593f,
1.97063f,1.98798f,3.61882f,-0.801016f,0.87661f,0.00579258f, 1.95593f,2.05948f,3.74819f,-0.826814f,0.874268f,0.00682502f,
1.94256f,2.13452f,3.88347f,-0.852593f,0.871746f,0.00801963f, 1.93816f,2.22167f,4.02301f,-0.878651f,0.869317f,0.00941829f,
1.92261f,2.29884f,4.17296f,-0.904484f,0.866683f,0.0110228f, 1.90252f,2.3731f,4.33948f,-0.93019f,0.863954f,0.0128752f,
1.89572f,2.46555f,4.50392f,-0.955458f,0.861038f,0.0149876f, 1.87361f,2.54113f,4.68671f,-0.980293f,0.85807f,0.0173916f,
1.85321f,2.62041f,4.8803f,-1.00465f,0.855115f,0.020136f, 1.84943f,2.72475f,5.06709f,-1.02821f,0.852106f,0.0232468f,
1.83502f,2.81593f,5.26708f,-1.0505f,0.84897f,0.0267283f, 1.79059f,2.86295f,5.51251f,-1.07182f,0.846051f,0.0306586f,
1.76269f,2.93363f,5.74537f,-1.09209f,0.843524f,0.0351077f, 1.76963f,3.06027f,5.94329f,-1.11019f,0.84106f,0.0400216f,
1.72436f,3.09974f,6.20663f,-1.12589f,0.838829f,0.0454427f, 1.67773f,3.13165f,6.47794f,-1.13922f,0.837199f,0.0514526f,
1.64099f,3.17407f,6.72998f,-1.14956f,0.836236f,0.0580574f, 1.64716f,3.28969f,6.92963f,-1.15667f,0.83624f,0.0653384f,
1.58928f,3.26384f,7.21864f,-1.16062f,0.837735f,0.0734227f, 1.54173f,3.28184f,7.42598f,-1.16032f,0.840755f,0.0821992f,
1.48395f,3.23657f,7.73815f,-1.15454f,0.845309f,0.0915628f, 1.46032f,3.25075f,7.91785f,-1.14297f,0.851814f,0.101542f,
1.40091f,3.17752f,8.12421f,-1.12706f,0.8615f,0.112639f, 1.32447f,3.04903f,8.3944f,-1.10814f,0.875653f,0.125382f,
1.26018f,2.93129f,8.60852f,-1.0814f,0.892511f,0.138371f, 1.2194f,2.83614f,8.6929f,-1.04641f,0.919415f,0.152193f,
1.13661f,2.63976f,8.83791f,-1.01108f,0.957641f,0.169712f, 1.07754f,2.49398f,8.94819f,-0.969334f,0.998641f,0.186671f,
1.91038f,7.79182e-07f,1.91039f,-6.36336e-17f,0.89927f,3.48117e-05f, 1.9104f,0.0417737f,1.91123f,-0.0194277f,0.899216f,3.50313e-05f,
1.91041f,0.0835865f,1.91377f,-0.0388579f,0.899052f,3.56833e-05f, 1.91046f,0.12548f,1.91799f,-0.058293f,0.898779f,3.67479e-05f,
1.91053f,0.167487f,1.92392f,-0.0777352f,0.898395f,3.81903e-05f, 1.91063f,0.209651f,1.93158f,-0.0971872f,0.897901f,3.99582e-05f,
1.91051f,0.252036f,1.94086f,-0.116838f,0.897431f,4.26307e-05f, 1.91014f,0.294715f,1.95167f,-0.136882f,0.897135f,4.72634e-05f,
1.90967f,0.337679f,1.96418f,-0.157113f,0.89686f,5.35729e-05f, 1.90925f,0.380965f,1.97849f,-0.177458f,0.896539f,6.15624e-05f,
1.90892f,0.424627f,1.99462f,-0.197916f,0.896168f,7.1492e-05f, 1.90879f,0.468726f,2.01269f,-0.218502f,0.895754f,8.37754e-05f,
1.90913f,0.513378f,2.03268f,-0.23918f,0.895254f,9.8552e-05f, 1.90875f,0.558337f,2.05439f,-0.259952f,0.894662f,0.000116216f,
1.90853f,0.603852f,2.07848f,-0.280822f,0.893977f,0.000137215f, 1.9089f,0.650088f,2.10476f,-0.301791f,0.893194f,0.00016206f,
1.9093f,0.696874f,2.13308f,-0.322863f,0.892308f,0.000191323f, 1.91101f,0.744623f,2.16334f,-0.344037f,0.891315f,0.000225649f,
1.91385f,0.793408f,2.19554f,-0.365314f,0.89021f,0.000265756f, 1.91658f,0.843376f,2.23059f,-0.386692f,0.888988f,0.000312444f,
1.91787f,0.894211f,2.26923f,-0.408334f,0.887752f,0.000369203f, 1.93103f,0.951568f,2.30809f,-0.43031f,0.886544f,0.000439376f,
1.91686f,0.997885f,2.35346f,-0.452527f,0.885294f,0.000524178f, 1.91808f,1.05259f,2.40019f,-0.474881f,0.883924f,0.000624242f,
1.91607f,1.10685f,2.45076f,-0.497514f,0.882531f,0.000745081f, 1.91683f,1.16406f,2.50372f,-0.52032f,0.881034f,0.000888229f,
1.91812f,1.22305f,2.5596f,-0.543253f,0.879401f,0.00105632f, 1.91498f,1.28055f,2.61885f,-0.566076f,0.877768f,0.00125304f,
1.90912f,1.33746f,2.68426f,-0.588862f,0.876142f,0.00148412f, 1.90773f,1.39891f,2.75142f,-0.61188f,0.874577f,0.00176185f,
1.92397f,1.4784f,2.81016f,-0.635077f,0.872963f,0.00209078f, 1.90051f,1.52356f,2.89981f,-0.65844f,0.871333f,0.00248034f,
1.89418f,1.58622f,2.9801f,-0.681922f,0.86959f,0.00293647f, 1.88797f,1.65071f,3.06541f,-0.705394f,0.867707f,0.00346559f,
1.88139f,1.71663f,3.15849f,-0.728921f,0.865662f,0.00408077f, 1.89444f,1.80249f,3.24561f,-0.752769f,0.863725f,0.00481254f,
1.86361f,1.84995f,3.36013f,-0.776586f,0.861596f,0.0056596f, 1.85471f,1.9193f,3.46848f,-0.80049f,0.859442f,0.00664842f,
1.85033f,1.9953f,3.58148f,-0.824181f,0.857108f,0.00778241f, 1.85193f,2.08036f,3.69759f,-0.847774f,0.85466f,0.00909357f,
1.83023f,2.14172f,3.83149f,-0.871323f,0.852273f,0.010607f, 1.81192f,2.20828f,3.97273f,-0.894442f,0.84973f,0.0123308f,
1.80783f,2.29331f,4.10992f,-0.91715f,0.847101f,0.0143013f, 1.79543f,2.37019f,4.26076f,-0.939556f,0.844599f,0.0165613f,
1.76564f,2.42552f,4.42842f,-0.961292f,0.842085f,0.019127f, 1.76619f,2.52215f,4.57995f,-0.98193f,0.839457f,0.0220033f,
1.74998f,2.59735f,4.75463f,-1.00182f,0.837087f,0.0252689f, 1.70498f,2.63033f,4.95316f,-1.02034f,0.834796f,0.0289226f,
1.7166f,2.74609f,5.10884f,-1.03738f,0.83273f,0.0330058f, 1.67803f,2.78502f,5.31682f,-1.05273f,0.831041f,0.0375467f,
1.63265f,2.80845f,5.53362f,-1.06601f,0.829787f,0.0425873f, 1.64901f,2.93078f,5.68125f,-1.07669f,0.829003f,0.0481389f,
1.59744f,2.93348f,5.90487f,-1.0847f,0.829011f,0.0542531f, 1.55234f,2.93897f,6.1274f,-1.09008f,0.830193f,0.0610455f,
1.49595f,2.90767f,6.34148f,-1.09246f,0.832812f,0.0685654f, 1.4503f,2.90008f,6.55902f,-1.09072f,0.836809f,0.0766916f,
1.44079f,2.94485f,6.70519f,-1.08435f,0.842435f,0.0854134f, 1.37914f,2.87605f,6.9026f,-1.073f,0.850016f,0.0947736f,
1.35257f,2.85786f,7.03469f,-1.05864f,0.860958f,0.10542f, 1.29373f,2.76849f,7.22268f,-1.04082f,0.875634f,0.117332f,
1.21467f,2.62141f,7.43992f,-1.01625f,0.892862f,0.129554f, 1.16276f,2.51415f,7.55273f,-0.984923f,0.917564f,0.142554f,
1.12265f,2.41276f,7.59226f,-0.953422f,0.95695f,0.159507f, 1.05499f,2.25736f,7.68561f,-0.915648f,0.998618f,0.175839f,
1.81837f,1.89847e-06f,1.81836f,-9.67573e-18f,0.880881f,2.6041e-05f, 1.81758f,0.0395348f,1.81837f,-0.0192471f,0.881482f,2.76236e-05f,
1.81675f,0.0790577f,1.81987f,-0.0384929f,0.882039f,2.97343e-05f, 1.81593f,0.118635f,1.82294f,-0.057789f,0.882496f,3.23895e-05f,
1.81509f,0.158285f,1.82763f,-0.0771382f,0.882853f,3.57228e-05f, 1.81425f,0.198062f,1.8339f,-0.096543f,0.883109f,3.98726e-05f,
1.81339f,0.237981f,1.8418f,-0.116006f,0.883262f,4.49856e-05f, 1.81258f,0.278087f,1.85134f,-0.135528f,0.883312f,5.12202e-05f,
1.81184f,0.318435f,1.86253f,-0.155113f,0.883256f,5.87491e-05f, 1.81123f,0.359058f,1.87541f,-0.174764f,0.883108f,6.78032e-05f,
1.81085f,0.400025f,1.89f,-0.194482f,0.882854f,7.85658e-05f, 1.81086f,0.441414f,1.9063f,-0.214266f,0.882492f,9.12635e-05f,
1.81103f,0.48323f,1.92418f,-0.234118f,0.882017f,0.000106149f, 1.81104f,0.525421f,1.94393f,-0.254036f,0.881427f,0.000123498f,
1.81108f,0.568061f,1.96561f,-0.27402f,0.880719f,0.00014361f, 1.81218f,0.611449f,1.98925f,-0.294069f,0.879888f,0.000166812f,
1.8117f,0.654942f,2.01511f,-0.314299f,0.879011f,0.000194673f, 1.81225f,0.699256f,2.04277f,-0.334856f,0.878184f,0.000229856f,
1.8151f,0.744892f,2.07198f,-0.355578f,0.877289f,0.000272116f, 1.81644f,0.791182f,2.10397f,-0.376494f,0.876347f,0.000323115f,
1.81966f,0.83936f,2.1379f,-0.397576f,0.875334f,0.000384182f, 1.82041f,0.887665f,2.17371f,-0.418756f,0.874197f,0.000456041f,
1.82014f,0.936626f,2.21279f,-0.440035f,0.872943f,0.000540442f, 1.835f,0.99518f,2.25039f,-0.461426f,0.871593f,0.000639494f,
1.82098f,1.03905f,2.29855f,-0.482971f,0.87016f,0.000756434f, 1.82018f,1.09138f,2.34724f,-0.504658f,0.868633f,0.000894236f,
1.83569f,1.1549f,2.39176f,-0.52662f,0.867093f,0.00106039f, 1.81695f,1.19862f,2.45183f,-0.548803f,0.865506f,0.00125876f,
1.81402f,1.25325f,2.50927f,-0.571122f,0.863821f,0.0014929f, 1.81408f,1.31126f,2.56981f,-0.593485f,0.861985f,0.00176588f,
1.81226f,1.36941f,2.63392f,-0.615866f,0.859992f,0.00208312f, 1.81282f,1.43101f,2.70168f,-0.638355f,0.857909f,0.00245494f,
1.80511f,1.48775f,2.77694f,-0.661045f,0.8558f,0.00289521f, 1.79731f,1.54561f,2.85534f,-0.683789f,0.853594f,0.00340945f,
1.79389f,1.60876f,2.93845f,-0.706704f,0.851395f,0.00401366f, 1.79487f,1.67761f,3.02166f,-0.729575f,0.849078f,0.00471429f,
1.78315f,1.73665f,3.11486f,-0.752268f,0.846596f,0.00551914f, 1.77279f,1.79815f,3.21412f,-0.774729f,0.84416f,0.00645307f,
1.76943f,1.86799f,3.3124f,-0.796724f,0.841777f,0.00752753f, 1.78756f,1.96205f,3.4032f,-0.818303f,0.839354f,0.00875699f,
1.76359f,2.01432f,3.52077f,-0.839598f,0.836975f,0.0101734f, 1.73074f,2.0564f,3.65174f,-0.860516f,0.834627f,0.0117985f,
1.7366f,2.14326f,3.76255f,-0.881015f,0.832393f,0.0136559f, 1.72134f,2.20691f,3.88708f,-0.900786f,0.830137f,0.0157527f,
1.68748f,2.2474f,4.0335f,-0.919743f,0.827922f,0.0181212f, 1.68738f,2.33076f,4.16549f,-0.938118f,0.825995f,0.0208263f,
1.66869f,2.39014f,4.30644f,-0.955284f,0.824135f,0.0238537f, 1.63132f,2.42237f,4.46502f,-0.971049f,0.822457f,0.0272231f,
1.63042f,2.50524f,4.60976f,-0.985307f,0.821035f,0.0309849f, 1.59131f,2.52991f,4.77949f,-0.998328f,0.820271f,0.0352152f,
1.55847f,2.55934f,4.94097f,-1.00905f,0.819831f,0.039866f, 1.55859f,2.63838f,5.07712f,-1.01765f,0.820104f,0.0450123f,
1.50755f,2.62902f,5.26409f,-1.02366f,0.821141f,0.0506823f, 1.46707f,2.62952f,5.43575f,-1.0274f,0.823438f,0.0570027f,
1.46466f,2.68921f,5.56654f,-1.02851f,0.827215f,0.0639962f, 1.40442f,2.63881f,5.74868f,-1.02562f,0.83222f,0.0715254f,
1.35699f,2.60192f,5.90139f,-1.01896f,0.838991f,0.079682f, 1.33938f,2.61002f,6.01932f,-1.00803f,0.8477f,0.0884932f,
1.27887f,2.52195f,6.16695f,-0.994982f,0.859808f,0.098666f, 1.2499f,2.48829f,6.28878f,-0.978276f,0.875082f,0.109831f,
1.18832f,2.38071f,6.44697f,-0.955573f,0.892716f,0.121315f, 1.1531f,2.31333f,6.54109f,-0.927682f,0.915408f,0.13363f,
1.08816f,2.16833f,6.59236f,-0.899347f,0.956019f,0.149982f, 1.04116f,2.06112f,6.63516f,-0.865066f,0.998588f,0.165749f,
1.72473f,1.04204e-06f,1.72473f,-1.97615e-17f,0.870399f,3.38726e-05f, 1.72472f,0.0373457f,1.72546f,-0.0192977f,0.870353f,3.42878e-05f,
1.72474f,0.0747235f,1.72767f,-0.0385977f,0.870216f,3.55404e-05f, 1.72474f,0.112164f,1.73135f,-0.0579022f,0.869987f,3.76508e-05f,
1.72473f,0.149701f,1.7365f,-0.0772133f,0.869666f,4.06529e-05f, 1.72472f,0.187361f,1.74316f,-0.096533f,0.869251f,4.45934e-05f,
1.72476f,0.225184f,1.7513f,-0.115863f,0.868741f,4.9531e-05f, 1.72457f,0.26307f,1.76065f,-0.134911f,0.868343f,5.56985e-05f,
1.72427f,0.301078f,1.77122f,-0.153757f,0.868017f,6.30806e-05f, 1.72409f,0.33932f,1.78319f,-0.172563f,0.867649f,7.16635e-05f,
1.7242f,0.377867f,1.7966f,-0.191359f,0.867216f,8.15356e-05f, 1.72484f,0.416825f,1.81151f,-0.210175f,0.866695f,9.28037e-05f,
1.74083f,0.459524f,1.83035f,-0.229193f,0.866205f,0.000106783f, 1.73946f,0.499443f,1.84473f,-0.248493f,0.86574f,0.000124565f,
1.72311f,0.535322f,1.86557f,-0.267971f,0.865294f,0.000146442f, 1.72335f,0.575781f,1.88687f,-0.287557f,0.864778f,0.000172569f,
1.72489f,0.616937f,1.90978f,-0.30722f,0.864141f,0.000203306f, 1.72685f,0.658648f,1.93391f,-0.327047f,0.863449f,0.000240254f,
1.72938f,0.701421f,1.9605f,-0.346967f,0.862674f,0.000283865f, 1.73247f,0.745471f,1.98899f,-0.36696f,0.86181f,0.000334974f,
1.73675f,0.791242f,2.01912f,-0.387017f,0.860814f,0.000394561f, 1.73456f,0.834999f,2.05074f,-0.40713f,0.85968f,0.000463831f,
1.7342f,0.880808f,2.08706f,-0.42739f,0.858469f,0.000545933f, 1.73234f,0.926721f,2.12544f,-0.447863f,0.857222f,0.000644682f,
1.73344f,0.97525f,2.1653f,-0.468593f,0.856001f,0.000764073f, 1.73512f,1.02528f,2.20702f,-0.489387f,0.854672f,0.000903797f,
1.74421f,1.08099f,2.24857f,-0.510217f,0.853202f,0.00106666f, 1.74615f,1.13371f,2.29471f,-0.531196f,0.85167f,0.00125936f,
1.73011f,1.17586f,2.34973f,-0.552212f,0.850011f,0.00148408f, 1.73676f,1.23398f,2.40199f,-0.573283f,0.848243f,0.00174676f,
1.72666f,1.2818f,2.46163f,-0.594502f,0.846432f,0.0020576f, 1.72046f,1.33328f,2.52351f,-0.615837f,0.844607f,0.00242226f,
1.7401f,1.40581f,2.57851f,-0.637237f,0.84272f,0.00284933f, 1.71425f,1.44452f,2.65419f,-0.65853f,0.840685f,0.00334206f,
1.71354f,1.50422f,2.72401f,-0.679673f,0.8385f,0.00390867f, 1.72418f,1.57531f,2.79341f,-0.70084f,0.836291f,0.00457056f,
1.70755f,1.62425f,2.87731f,-0.72182f,0.833967f,0.00533208f, 1.68966f,1.67228f,2.9673f,-0.742762f,0.831652f,0.00621778f,
1.68735f,1.73613f,3.05305f,-0.763599f,0.829378f,0.00723967f, 1.67142f,1.78753f,3.14827f,-0.784099f,0.827033f,0.00840914f,
1.68933f,1.87454f,3.22701f,-0.804247f,0.824667f,0.00974926f, 1.65704f,1.91096f,3.3439f,-0.823785f,0.82221f,0.011266f,
1.6611f,1.98718f,3.44313f,-0.842713f,0.81974f,0.0129866f, 1.64536f,2.04173f,3.55492f,-0.861026f,0.817342f,0.0149441f,
1.61539f,2.07854f,3.67918f,-0.878745f,0.815149f,0.0171678f, 1.6105f,2.14567f,3.79269f,-0.895374f,0.813004f,0.0196566f,
1.59094f,2.19391f,3.91532f,-0.910772f,0.811137f,0.0224506f, 1.56874f,2.23721f,4.04565f,-0.924536f,0.809907f,0.0255994f,
1.5498f,2.28265f,4.17205f,-0.936588f,0.809116f,0.0291032f, 1.52054f,2.3102f,4.30441f,-0.946982f,0.808911f,0.0329972f,
1.52303f,2.38249f,4.41224f,-0.955488f,0.809328f,0.0373007f, 1.47338f,2.37184f,4.56392f,-0.962016f,0.810526f,0.0420732f,
1.43928f,2.37886f,4.69716f,-0.966342f,0.812649f,0.0473517f, 1.42645f,2.41458f,4.81588f,-0.968593f,0.816059f,0.0532222f,
1.37987f,2.38879f,4.96112f,-0.968382f,0.820883f,0.0597028f, 1.37405f,2.42476f,5.05527f,-0.964882f,0.827089f,0.0667285f,
1.31168f,2.35563f,5.19816f,-0.957892f,0.834931f,0.0743464f, 1.29736f,2.36197f,5.28143f,-0.947439f,0.844796f,0.0826531f,
1.24424f,2.28796f,5.40208f,-0.935456f,0.857993f,0.092325f, 1.22219f,2.26395f,5.49423f,-0.919827f,0.873944f,0.102808f,
1.19454f,2.21989f,5.51392f,-0.899022f,0.892175f,0.11369f, 1.11698f,2.08236f,5.728f,-0.874244f,0.913459f,0.12538f,
1.07487f,1.98665f,5.73739f,-0.848466f,0.954864f,0.141096f, 1.03356f,1.89606f,5.75305f,-0.81727f,0.99855f,0.156355f,
1.64281f,-4.20288e-06f,1.64281f,-3.99406e-17f,0.856141f,3.92906e-05f, 1.64279f,0.0351064f,1.64348f,-0.0184525f,0.856088f,3.96356e-05f,
1.64276f,0.070241f,1.64548f,-0.0369051f,0.85593f,4.06708e-05f, 1.64271f,0.105427f,1.64883f,-0.0553576f,0.855666f,4.23977e-05f,
1.64267f,0.140695f,1.65353f,-0.0738099f,0.855296f,4.48174e-05f, 1.64264f,0.176076f,1.65957f,-0.092262f,0.854819f,4.79299e-05f,
1.64268f,0.211597f,1.66697f,-0.110713f,0.854235f,5.17324e-05f, 1.64245f,0.247278f,1.67579f,-0.129235f,0.85359f,5.64691e-05f,
1.64226f,0.283247f,1.6858f,-0.148107f,0.853075f,6.34386e-05f, 1.6424f,0.319522f,1.69713f,-0.167109f,0.85254f,7.23053e-05f,
1.64268f,0.356099f,1.70979f,-0.186236f,0.851988f,8.34184e-05f, 1.64369f,0.393096f,1.72396f,-0.20541f,0.851353f,9.67725e-05f,
1.64417f,0.430264f,1.73905f,-0.22462f,0.850623f,0.00011263f, 1.64472f,0.467775f,1.7558f,-0.243889f,0.849846f,0.00013162f,
1.64597f,0.50566f,1.77395f,-0.262941f,0.849162f,0.000154102f, 1.64726f,0.543728f,1.79317f,-0.281885f,0.848475f,0.000180406f,
1.65f,0.58242f,1.8136f,-0.30077f,0.847757f,0.000211048f, 1.65325f,0.622066f,1.83603f,-0.319668f,0.846945f,0.000246588f,
1.65605f,0.662536f,1.86021f,-0.338553f,0.846059f,0.000287682f, 1.65729f,0.7035f,1.88683f,-0.357675f,0.845175f,0.00033782f,
1.65664f,0.744391f,1.91423f,-0.37698f,0.844356f,0.000398859f, 1.65681f,0.786393f,1.94332f,-0.396351f,0.843416f,0.000470485f,
1.6572f,0.829534f,1.97531f,-0.4158f,0.842379f,0.000554679f, 1.65716f,0.873219f,2.00848f,-0.435372f,0.841354f,0.000654821f,
1.6585f,0.918602f,2.04376f,-0.454965f,0.840189f,0.000771353f, 1.66048f,0.965344f,2.08062f,-0.474565f,0.838882f,0.000906579f,
1.6564f,1.00939f,2.12131f,-0.494186f,0.837475f,0.00106381f, 1.65456f,1.05563f,2.16319f,-0.513995f,0.836102f,0.00125146f,
1.65279f,1.10287f,2.20957f,-0.533865f,0.83464f,0.00147148f, 1.65147f,1.1513f,2.25659f,-0.553799f,0.833102f,0.00172984f,
1.65124f,1.20172f,2.30613f,-0.57371f,0.831451f,0.00202996f, 1.6474f,1.25042f,2.35827f,-0.593575f,0.829747f,0.00237685f,
1.64131f,1.29844f,2.41575f,-0.613344f,0.827928f,0.00277716f, 1.63763f,1.34928f,2.47548f,-0.63325f,0.826137f,0.00325029f,
1.64329f,1.40875f,2.5341f,-0.652975f,0.824219f,0.0037944f, 1.65483f,1.47744f,2.57769f,-0.672651f,0.822277f,0.00442771f,
1.63732f,1.51736f,2.66571f,-0.69213f,0.820311f,0.00515342f, 1.61586f,1.55616f,2.74567f,-0.711354f,0.818278f,0.00598602f,
1.61356f,1.61332f,2.81928f,-0.730415f,0.816277f,0.00694771f, 1.63615f,1.69584f,2.88281f,-0.748994f,0.814179f,0.00803919f,
1.61137f,1.73496f,2.9691f,-0.767129f,0.812066f,0.00928278f, 1.58261f,1.76525f,3.06999f,-0.784889f,0.810076f,0.0107011f,
1.58126f,1.82662f,3.15524f,-0.802208f,0.808209f,0.0123245f, 1.58487f,1.89469f,3.23809f,-0.818697f,0.806348f,0.014151f,
1.58124f,1.95815f,3.29969f,-0.834257f,0.804541f,0.0162017f, 1.53672f,1.96611f,3.44973f,-0.848882f,0.802905f,0.0185064f,
1.55172f,2.04882f,3.53181f,-0.862693f,0.801632f,0.0211151f, 1.52921f,2.08321f,3.63845f,-0.875433f,0.800721f,0.0240465f,
1.48284f,2.08383f,3.76233f,-0.886618f,0.800082f,0.0272968f, 1.48273f,2.14443f,3.85861f,-0.896053f,0.799797f,0.0308886f,
1.4409f,2.14347f,3.98808f,-0.903963f,0.800182f,0.03489f, 1.45059f,2.21351f,4.07278f,-0.910042f,0.801288f,0.0393347f,
1.39817f,2.18615f,4.19806f,-0.912907f,0.803922f,0.0442471f, 1.36073f,2.17455f,4.31079f,-0.913559f,0.808167f,0.0496998f,
1.34324f,2.18844f,4.40302f,-0.912095f,0.813982f,0.0557099f, 1.33705f,2.21515f,4.47715f,-0.90789f,0.821281f,0.0622532f,
1.28254f,2.15189f,4.59709f,-0.900624f,0.830202f,0.0693633f, 1.26854f,2.15776f,4.64669f,-0.890791f,0.841303f,0.0772338f,
1.2059f,2.06849f,4.76377f,-0.879651f,0.855543f,0.0863879f, 1.18449f,2.04278f,4.84026f,-0.865012f,0.872232f,0.096238f,
1.1316f,1.9577f,4.93722f,-0.845977f,0.891178f,0.106582f, 1.09763f,1.90004f,5.01215f,-0.823561f,0.913071f,0.117803f,
1.06355f,1.82582f,5.01974f,-0.800437f,0.953497f,0.132808f, 1.00574f,1.71075f,5.03952f,-0.771983f,0.998506f,0.147611f,
1.57192f,2.48433e-06f,1.57193f,-8.14052e-17f,0.837434f,3.72874e-05f, 1.5719f,0.0330142f,1.57253f,-0.0174221f,0.837377f,3.74319e-05f,
1.57174f,0.066096f,1.57425f,-0.034998f,0.83731f,3.81525e-05f, 1.57121f,0.0993502f,1.57687f,-0.0530345f,0.837468f,4.03433e-05f,
1.57055f,0.132676f,1.58069f,-0.0711582f,0.83759f,4.35488e-05f, 1.56983f,0.166091f,1.58572f,-0.0893321f,0.837644f,4.78153e-05f,
1.56915f,0.199605f,1.59201f,-0.107533f,0.8376f,5.31912e-05f, 1.56855f,0.233262f,1.59956f,-0.12576f,0.837456f,5.98153e-05f,
1.56819f,0.267089f,1.60837f,-0.144012f,0.837212f,6.78434e-05f, 1.56816f,0.301152f,1.61843f,-0.162288f,0.836868f,7.74568e-05f,
1.56861f,0.335498f,1.62975f,-0.180588f,0.836423f,8.88523e-05f, 1.57115f,0.370477f,1.64257f,-0.198904f,0.835871f,0.000102223f,
1.57045f,0.405058f,1.65573f,-0.217234f,0.835208f,0.000117803f, 1.57158f,0.44024f,1.67079f,-0.235575f,0.834433f,0.000135847f,
1.57393f,0.475893f,1.6874f,-0.253925f,0.83355f,0.00015666f, 1.57294f,0.511198f,1.70589f,-0.27244f,0.832655f,0.000181922f,
1.57635f,0.547706f,1.72497f,-0.291189f,0.831793f,0.000213285f, 1.57892f,0.584869f,1.74602f,-0.309969f,0.830834f,0.000250052f,
1.58236f,0.623212f,1.76877f,-0.328895f,0.829855f,0.000294352f, 1.58644f,0.662783f,1.79271f,-0.347834f,0.828769f,0.000346074f,
1.5884f,0.702309f,1.81734f,-0.366778f,0.827574f,0.000406283f, 1.58942f,0.742286f,1.84393f,-0.385613f,0.826332f,0.000476176f,
1.60765f,0.791362f,1.86923f,-0.404257f,0.825153f,0.000557778f, 1.58942f,0.823441f,1.90344f,-0.422863f,0.823966f,0.00065335f,
1.5911f,0.865975f,1.93517f,-0.441548f,0.822812f,0.000767391f, 1.60445f,0.918309f,1.96673f,-0.460295f,0.821667f,0.000902549f,
1.5892f,0.950444f,2.00435f,-0.479034f,0.820446f,0.00106044f, 1.58746f,0.993247f,2.04152f,-0.497692f,0.819143f,0.00124313f,
1.58803f,1.03829f,2.08089f,-0.516257f,0.817736f,0.00145394f, 1.58546f,1.08224f,2.12306f,-0.534842f,0.816267f,0.00169995f,
1.58373f,1.12737f,2.16898f,-0.553472f,0.814849f,0.00198906f, 1.57987f,1.17185f,2.21468f,-0.572094f,0.813384f,0.00232542f,
1.57405f,1.21566f,2.26487f,-0.59068f,0.81187f,0.00271674f, 1.57214f,1.2631f,2.3158f,-0.609146f,0.810353f,0.00316868f,
1.57887f,1.31829f,2.36615f,-0.627375f,0.808712f,0.00368577f, 1.58782f,1.3767f,2.41815f,-0.645414f,0.807007f,0.00428077f,
1.56911f,1.41312f,2.48109f,-0.663296f,0.805343f,0.00496684f, 1.55314f,1.45152f,2.54558f,-0.680809f,0.803606f,0.00574752f,
1.54838f,1.50045f,2.61119f,-0.698019f,0.801859f,0.00664248f, 1.56158f,1.56111f,2.64829f,-0.714857f,0.800126f,0.0076645f,
1.53647f,1.59749f,2.7478f,-0.731471f,0.798583f,0.00883973f, 1.51788f,1.63354f,2.82363f,-0.747542f,0.797081f,0.0101721f,
1.5129f,1.68352f,2.89715f,-0.762855f,0.795575f,0.0116706f, 1.53243f,1.76035f,2.96139f,-0.777436f,0.794184f,0.0133575f,
1.50027f,1.77983f,3.05264f,-0.791535f,0.793129f,0.0152845f, 1.47123f,1.80229f,3.14265f,-0.804627f,0.792221f,0.0174449f,
1.46865f,1.85401f,3.22148f,-0.81651f,0.791475f,0.0198512f, 1.48817f,1.93204f,3.28672f,-0.827364f,0.791141f,0.0225449f,
1.46217f,1.95023f,3.37566f,-0.837056f,0.791284f,0.0255596f, 1.40772f,1.93337f,3.49135f,-0.845253f,0.791882f,0.0289134f,
1.40932f,1.98491f,3.56933f,-0.851688f,0.792985f,0.0326163f, 1.36767f,1.973f,3.67264f,-0.856726f,0.794976f,0.0367583f,
1.37059f,2.02065f,3.74603f,-0.859854f,0.797804f,0.0413421f, 1.32146f,1.98892f,3.85628f,-0.861058f,0.801692f,0.0464217f,
1.31676f,2.01743f,3.92821f,-0.859753f,0.806919f,0.0520053f, 1.26598f,1.9691f,4.01557f,-0.854558f,0.814936f,0.0580986f,
1.24762f,1.96382f,4.08209f,-0.847162f,0.824986f,0.0647755f, 1.23379f,1.96056f,4.127f,-0.837774f,0.837264f,0.0722392f,
1.18114f,1.88969f,4.21316f,-0.827293f,0.852525f,0.0808671f, 1.1586f,1.86106f,4.27683f,-0.813592f,0.870043f,0.0901526f,
1.13359f,1.82424f,4.33619f,-0.796028f,0.889729f,0.0999523f, 1.06842f,1.7185f,4.42303f,-0.775826f,0.912397f,0.110781f,
1.03843f,1.65633f,4.42977f,-0.754968f,0.95193f,0.125081f, 1.00205f,1.58245f,4.41968f,-0.728961f,0.998456f,0.139476f,
1.50429f,1.91429e-06f,1.50429f,-2.627e-17f,0.820973f,3.92558e-05f, 1.50426f,0.03146f,1.50486f,-0.0178594f,0.820925f,3.96961e-05f,
1.50416f,0.0629355f,1.50659f,-0.0357175f,0.820779f,4.10235e-05f, 1.504f,0.0944477f,1.50946f,-0.053573f,0.820535f,4.32575e-05f,
1.5038f,0.126017f,1.5135f,-0.0714244f,0.820194f,4.64301e-05f, 1.50336f,0.157523f,1.51838f,-0.0889136f,0.819986f,5.08299e-05f,
1.50286f,0.189044f,1.52422f,-0.106226f,0.819814f,5.63224e-05f, 1.50249f,0.220671f,1.53114f,-0.123492f,0.819588f,6.28692e-05f,
1.50239f,0.252441f,1.53911f,-0.140737f,0.819291f,7.0557e-05f, 1.50269f,0.284412f,1.5482f,-0.157981f,0.818892f,7.94466e-05f,
1.50361f,0.316664f,1.55839f,-0.175221f,0.818394f,8.96683e-05f, 1.52223f,0.352394f,1.57367f,-0.192711f,0.817971f,0.000102762f,
1.50344f,0.381569f,1.58188f,-0.210341f,0.817517f,0.000118744f, 1.50427f,0.414504f,1.5954f,-0.228088f,0.81702f,0.000138088f,
1.50844f,0.44828f,1.61057f,-0.245851f,0.816434f,0.000160775f, 1.50782f,0.481155f,1.62566f,-0.263687f,0.815813f,0.000187764f,
1.51138f,0.515405f,1.64283f,-0.281559f,0.815102f,0.000219437f, 1.51526f,0.550607f,1.66173f,-0.29943f,0.814279f,0.000256224f,
1.51861f,0.586509f,1.68203f,-0.317293f,0.813342f,0.000298819f, 1.52255f,0.623494f,1.70324f,-0.33514f,0.81229f,0.000347996f,
1.52353f,0.660027f,1.72608f,-0.353071f,0.8112f,0.000406088f, 1.5216f,0.695913f,1.7508f,-0.371142f,0.810121f,0.000475607f,
1.52274f,0.733839f,1.77641f,-0.389304f,0.809004f,0.000558114f, 1.52503f,0.773137f,1.80374f,-0.407431f,0.807778f,0.00065377f,
1.52562f,0.812436f,1.83274f,-0.425539f,0.806462f,0.000764946f, 1.52745f,0.852913f,1.86282f,-0.443696f,0.805106f,0.000895543f,
1.52721f,0.892974f,1.89415f,-0.461768f,0.803636f,0.00104608f, 1.5241f,0.931941f,1.92952f,-0.479823f,0.802101f,0.00122143f,
1.52541f,0.974247f,1.96571f,-0.497929f,0.800579f,0.0014272f, 1.52325f,1.01494f,2.00512f,-0.515988f,0.799039f,0.00166716f,
1.5268f,1.06015f,2.04326f,-0.533728f,0.797597f,0.0019458f, 1.52093f,1.0995f,2.08411f,-0.55117f,0.79614f,0.00226565f,
1.51779f,1.14129f,2.1263f,-0.568341f,0.794639f,0.00263187f, 1.51352f,1.18282f,2.17307f,-0.585355f,0.793186f,0.00305662f,
1.51537f,1.22975f,2.21902f,-0.602142f,0.791721f,0.00354484f, 1.52229f,1.2814f,2.26499f,-0.618778f,0.790309f,0.00410888f,
1.5028f,1.31225f,2.31979f,-0.635266f,0.789014f,0.00476023f, 1.49352f,1.35136f,2.37286f,-0.651348f,0.787675f,0.00550009f,
1.48834f,1.3944f,2.42989f,-0.667135f,0.786417f,0.00634865f, 1.50539f,1.45818f,2.47765f,-0.682457f,0.785182f,0.00731242f,
1.47217f,1.47552f,2.54383f,-0.697211f,0.783957f,0.00840083f, 1.49428f,1.53811f,2.59905f,-0.711389f,0.782838f,0.00963095f,
1.4526f,1.55288f,2.6734f,-0.725056f,0.781878f,0.0110294f, 1.45513f,1.6042f,2.73346f,-0.738217f,0.781204f,0.0126182f,
1.45279f,1.64993f,2.79401f,-0.750467f,0.780658f,0.0143964f, 1.44406f,1.68871f,2.85991f,-0.761882f,0.780367f,0.0163976f,
1.40745f,1.6941f,2.94068f,-0.772346f,0.780424f,0.0186341f, 1.40576f,1.73841f,3.00875f,-0.781544f,0.780744f,0.0211199f,
1.37951f,1.75091f,3.08641f,-0.789734f,0.7816f,0.0239128f, 1.39193f,1.80948f,3.14156f,-0.796845f,0.783121f,0.0270428f,
1.34006f,1.78484f,3.23361f,-0.802234f,0.785122f,0.0304907f, 1.33396f,1.81512f,3.30136f,-0.806146f,0.787901f,0.0343329f,
1.29984f,1.8047f,3.38218f,-0.808593f,0.791665f,0.0386146f, 1.28988f,1.82346f,3.45168f,-0.809219f,0.796437f,0.0433493f,
1.28755f,1.84966f,3.50861f,-0.80776f,0.802307f,0.0485493f, 1.23408f,1.79912f,3.59551f,-0.804283f,0.80954f,0.0542804f,
1.22075f,1.79981f,3.64942f,-0.797067f,0.819251f,0.0605253f, 1.20677f,1.79244f,3.68286f,-0.787934f,0.832636f,0.0676025f,
1.14962f,1.71548f,3.75672f,-0.77798f,0.848927f,0.0757297f, 1.1267f,1.68548f,3.80777f,-0.765061f,0.867314f,0.0844684f,
1.103f,1.65141f,3.8041f,-0.748964f,0.887911f,0.0938189f, 1.05617f,1.57934f,3.9082f,-0.730664f,0.911418f,0.104249f,
1.02542f,1.52081f,3.92102f,-0.711801f,0.950174f,0.117876f, 0.984767f,1.44412f,3.90535f,-0.687988f,0.9984f,0.131908f,
1.44277f,-1.52221e-06f,1.44277f,-1.25177e-17f,0.803584f,4.34658e-05f, 1.44272f,0.0295295f,1.44329f,-0.0168704f,0.803533f,4.38244e-05f,
1.44259f,0.0590712f,1.44482f,-0.0337381f,0.803378f,4.4901e-05f, 1.44239f,0.0886477f,1.4474f,-0.0506001f,0.80312f,4.66987e-05f,
1.44215f,0.118266f,1.45101f,-0.0674536f,0.802759f,4.92217e-05f, 1.44198f,0.147957f,1.45563f,-0.0842957f,0.802295f,5.24751e-05f,
1.44151f,0.177747f,1.46131f,-0.101271f,0.801817f,5.68906e-05f, 1.44119f,0.207736f,1.46788f,-0.118513f,0.801414f,6.31676e-05f,
1.44118f,0.237891f,1.47538f,-0.135848f,0.800984f,7.11437e-05f, 1.44166f,0.268247f,1.48395f,-0.153219f,0.800488f,8.08867e-05f,
1.44266f,0.298815f,1.49344f,-0.1706f,0.79991f,9.25482e-05f, 1.44406f,0.329521f,1.50347f,-0.187825f,0.799389f,0.000106574f,
1.44526f,0.360249f,1.51446f,-0.204844f,0.7989f,0.000123051f, 1.44671f,0.391053f,1.52647f,-0.221761f,0.798384f,0.000142254f,
1.46417f,0.425588f,1.54181f,-0.238636f,0.797798f,0.000164505f, 1.45219f,0.453501f,1.55367f,-0.255462f,0.797139f,0.000190186f,
1.45383f,0.485325f,1.57005f,-0.272285f,0.796406f,0.000219955f, 1.45648f,0.518135f,1.58782f,-0.289252f,0.795719f,0.000256085f,
1.45872f,0.551352f,1.60601f,-0.30633f,0.794996f,0.00029927f, 1.46236f,0.585809f,1.62511f,-0.32338f,0.794195f,0.000349397f,
1.4693f,0.622458f,1.64457f,-0.340504f,0.793394f,0.000408861f, 1.46354f,0.654014f,1.66586f,-0.357604f,0.792491f,0.000477853f,
1.46475f,0.689283f,1.68843f,-0.374655f,0.79148f,0.000557515f, 1.46705f,0.725757f,1.71245f,-0.391648f,0.7904f,0.000649379f,
1.46711f,0.761713f,1.73929f,-0.408642f,0.789282f,0.000756443f, 1.48374f,0.807282f,1.7631f,-0.425667f,0.788124f,0.000882066f,
1.46576f,0.834487f,1.79447f,-0.44276f,0.78696f,0.0010303f, 1.46498f,0.87154f,1.82393f,-0.459798f,0.785729f,0.00120234f,
1.4662f,0.910387f,1.85535f,-0.476733f,0.784464f,0.00140038f, 1.46591f,0.948884f,1.88778f,-0.493513f,0.783111f,0.0016274f,
1.46351f,0.986678f,1.92473f,-0.510163f,0.781696f,0.00188875f, 1.46072f,1.02457f,1.9601f,-0.526848f,0.780325f,0.002196f,
1.4582f,1.06316f,1.99737f,-0.543295f,0.778872f,0.00254717f, 1.45463f,1.10133f,2.03919f,-0.559658f,0.777467f,0.00295419f,
1.45457f,1.14266f,2.08024f,-0.575773f,0.776041f,0.00341936f, 1.45529f,1.18507f,2.12171f,-0.59154f,0.774558f,0.00394805f,
1.44468f,1.21902f,2.16896f,-0.607073f,0.773106f,0.00455615f, 1.43961f,1.25729f,2.21551f,-0.622318f,0.771708f,0.00525144f,
1.43712f,1.29791f,2.26357f,-0.636904f,0.770423f,0.0060388f, 1.4358f,1.33989f,2.3129f,-0.65091f,0.769421f,0.00693644f,
1.45107f,1.3968f,2.35472f,-0.664269f,0.768563f,0.00795234f, 1.42236f,1.41338f,2.41419f,-0.677148f,0.767955f,0.00911316f,
1.40314f,1.43749f,2.47011f,-0.689301f,0.767508f,0.0104199f, 1.39686f,1.47362f,2.52396f,-0.700659f,0.767234f,0.0118858f,
1.40217f,1.52107f,2.57392f,-0.711351f,0.767279f,0.0135366f, 1.39599f,1.55607f,2.62622f,-0.721124f,0.767607f,0.0153813f,
1.38399f,1.58335f,2.68396f,-0.730187f,0.768395f,0.0174657f, 1.34359f,1.57826f,2.75829f,-0.73815f,0.769547f,0.0197896f,
1.33989f,1.61171f,2.81453f,-0.744923f,0.771152f,0.0223698f, 1.35039f,1.66374f,2.85037f,-0.750764f,0.773454f,0.0252726f,
1.31927f,1.64855f,2.92772f,-0.755252f,0.776397f,0.0284899f, 1.28675f,1.64989f,2.98848f,-0.758344f,0.780103f,0.0320711f,
1.263f,1.64869f,3.05402f,-0.760003f,0.784723f,0.0360546f, 1.25785f,1.66868f,3.10455f,-0.760155f,0.790417f,0.0404711f,
1.25505f,1.68968f,3.15035f,-0.758459f,0.7972f,0.0453402f, 1.2034f,1.64051f,3.22642f,-0.754965f,0.805304f,0.050717f,
1.1943f,1.64552f,3.26964f,-0.749259f,0.81473f,0.056593f, 1.15204f,1.59838f,3.32123f,-0.741087f,0.8275f,0.0632984f,
1.1273f,1.56898f,3.36432f,-0.73131f,0.844715f,0.0709202f, 1.10137f,1.53487f,3.4065f,-0.719107f,0.864058f,0.0791564f,
1.07886f,1.50309f,3.44073f,-0.704421f,0.885704f,0.0881227f, 1.05358f,1.46574f,3.47336f,-0.687917f,0.910205f,0.0982213f,
1.00479f,1.38601f,3.49124f,-0.67071f,0.948238f,0.111159f, 0.96625f,1.31629f,3.46684f,-0.648874f,0.998339f,0.124869f,
1.38959f,-1.74981e-06f,1.38958f,-3.58506e-17f,0.782169f,4.0256e-05f, 1.38932f,0.0277968f,1.38984f,-0.0160737f,0.782347f,4.09977e-05f,
1.38874f,0.0557032f,1.39085f,-0.0324428f,0.782646f,4.29102e-05f, 1.38801f,0.0836242f,1.39279f,-0.0488304f,0.782857f,4.56375e-05f,
1.38721f,0.11157f,1.39566f,-0.0652289f,0.782972f,4.9248e-05f, 1.38642f,0.139559f,1.39948f,-0.0816348f,0.78299f,5.38364e-05f,
1.38576f,0.167601f,1.40422f,-0.0980444f,0.782911f,5.95072e-05f, 1.38537f,0.195729f,1.40988f,-0.114454f,0.782733f,6.63758e-05f,
1.38539f,0.223977f,1.41648f,-0.130858f,0.782457f,7.45695e-05f, 1.38592f,0.252376f,1.424f,-0.147254f,0.782081f,8.42285e-05f,
1.38717f,0.280968f,1.43244f,-0.163635f,0.781606f,9.55067e-05f, 1.38912f,0.309738f,1.44136f,-0.179997f,0.78103f,0.000108573f,
1.3899f,0.33843f,1.45159f,-0.196356f,0.780366f,0.000123727f, 1.39056f,0.367239f,1.4628f,-0.212909f,0.77973f,0.000142517f,
1.39315f,0.396295f,1.47479f,-0.22952f,0.779046f,0.00016488f, 1.39537f,0.425723f,1.48809f,-0.246216f,0.778337f,0.000191664f,
1.39934f,0.456144f,1.50294f,-0.262892f,0.77754f,0.000222868f, 1.40753f,0.488866f,1.51967f,-0.27953f,0.77665f,0.000259017f,
1.40626f,0.51881f,1.53554f,-0.295936f,0.775804f,0.000301027f, 1.41014f,0.551226f,1.55307f,-0.312195f,0.775002f,0.00035003f,
1.41675f,0.585445f,1.57018f,-0.328325f,0.774176f,0.00040649f, 1.41116f,0.614756f,1.58995f,-0.34447f,0.773339f,0.000472863f,
1.43403f,0.658143f,1.60131f,-0.360599f,0.772525f,0.000550979f, 1.41257f,0.68038f,1.63254f,-0.376762f,0.771678f,0.00064282f,
1.41455f,0.714553f,1.65513f,-0.392794f,0.770801f,0.000748658f, 1.42469f,0.753653f,1.67737f,-0.408726f,0.769828f,0.000870292f,
1.4145f,0.782193f,1.70292f,-0.424606f,0.768836f,0.00101142f, 1.41384f,0.816275f,1.72838f,-0.440372f,0.767811f,0.0011739f,
1.41261f,0.850528f,1.75758f,-0.456133f,0.766777f,0.00136391f, 1.42918f,0.896092f,1.78322f,-0.471753f,0.765695f,0.00158238f,
1.41102f,0.920564f,1.81783f,-0.487309f,0.76466f,0.00183616f, 1.42771f,0.969578f,1.84463f,-0.502744f,0.763619f,0.0021284f,
1.41432f,0.995632f,1.8797f,-0.517933f,0.762514f,0.00246172f, 1.41501f,1.03327f,1.91371f,-0.532886f,0.761414f,0.00284185f,
1.40185f,1.06113f,1.95179f,-0.547712f,0.760383f,0.00328157f, 1.41483f,1.10864f,1.98471f,-0.562194f,0.759318f,0.00378109f,
1.4178f,1.14645f,2.00429f,-0.576302f,0.758237f,0.0043479f, 1.39615f,1.17071f,2.06603f,-0.590183f,0.757285f,0.00499817f,
1.38309f,1.19822f,2.10831f,-0.603657f,0.756392f,0.00573578f, 1.37823f,1.2322f,2.15384f,-0.616748f,0.755603f,0.00657684f,
1.38837f,1.27967f,2.19293f,-0.629407f,0.754951f,0.00753179f, 1.36361f,1.29543f,2.24083f,-0.641504f,0.754435f,0.00860738f,
1.37156f,1.34089f,2.28282f,-0.652961f,0.754077f,0.00981608f, 1.34912f,1.35712f,2.33375f,-0.663782f,0.75393f,0.0111793f,
1.33855f,1.38399f,2.38786f,-0.673786f,0.753977f,0.0127063f, 1.34569f,1.42725f,2.42939f,-0.682695f,0.754612f,0.0144332f,
1.31944f,1.4346f,2.48107f,-0.690469f,0.755888f,0.0163712f, 1.32153f,1.47112f,2.52356f,-0.697233f,0.757731f,0.0185394f,
1.28831f,1.46654f,2.57999f,-0.702763f,0.760061f,0.0209395f, 1.28033f,1.48773f,2.62671f,-0.707255f,0.763062f,0.0236186f,
1.27843f,1.51851f,2.65815f,-0.710754f,0.766867f,0.0266149f, 1.28255f,1.54663f,2.70564f,-0.713048f,0.771484f,0.0299563f,
1.24729f,1.54039f,2.74708f,-0.714044f,0.777027f,0.0336663f, 1.23433f,1.53511f,2.80581f,-0.713667f,0.783612f,0.0377836f,
1.18899f,1.49798f,2.86565f,-0.71186f,0.791387f,0.0423561f, 1.17197f,1.49255f,2.91238f,-0.708254f,0.800345f,0.047386f,
1.1634f,1.4973f,2.93731f,-0.703074f,0.810787f,0.0529815f, 1.15264f,1.49293f,2.98113f,-0.696571f,0.823027f,0.0593051f,
1.10159f,1.42982f,3.02782f,-0.687027f,0.839906f,0.0664189f, 1.07708f,1.39765f,3.05673f,-0.675533f,0.860325f,0.0742151f,
1.05535f,1.36816f,3.08613f,-0.662087f,0.883094f,0.0828113f, 1.03164f,1.33456f,3.11071f,-0.647212f,0.908697f,0.0926038f,
1.00659f,1.29223f,3.11736f,-0.631496f,0.946128f,0.104897f, 0.951087f,1.20376f,3.08961f,-0.61145f,0.998272f,0.118323f,
1.33755f,-1.83749e-06f,1.33755f,-9.44506e-17f,0.764108f,4.48159e-05f, 1.33747f,0.0263382f,1.33798f,-0.0159494f,0.764062f,4.52408e-05f,
1.33722f,0.0526813f,1.33926f,-0.0318949f,0.763922f,4.65203e-05f, 1.33685f,0.0790426f,1.3414f,-0.0478322f,0.763689f,4.86677e-05f,
1.33642f,0.105423f,1.3444f,-0.0637575f,0.763363f,5.17052e-05f, 1.33607f,0.131844f,1.34827f,-0.0796664f,0.762945f,5.56636e-05f,
1.33581f,0.158219f,1.35282f,-0.095331f,0.762563f,6.06998e-05f, 1.33579f,0.184568f,1.35801f,-0.110755f,0.762226f,6.6817e-05f,
1.33525f,0.210933f,1.36412f,-0.126183f,0.761905f,7.42971e-05f, 1.33539f,0.237489f,1.37084f,-0.141811f,0.761646f,8.3928e-05f,
1.33644f,0.264258f,1.37831f,-0.157481f,0.7614f,9.5668e-05f, 1.33781f,0.291076f,1.38595f,-0.173178f,0.761086f,0.000109587f,
1.33948f,0.317984f,1.39466f,-0.188895f,0.760729f,0.000126081f, 1.34152f,0.344874f,1.40424f,-0.20458f,0.760303f,0.000145295f,
1.35128f,0.373477f,1.41666f,-0.220236f,0.759783f,0.000167542f, 1.34774f,0.399624f,1.42697f,-0.235857f,0.759169f,0.000193214f,
1.35111f,0.427934f,1.43979f,-0.25147f,0.758513f,0.000223039f, 1.35297f,0.456473f,1.45457f,-0.267061f,0.757799f,0.000257552f,
1.35456f,0.485376f,1.47028f,-0.28275f,0.757078f,0.000298715f, 1.35832f,0.515531f,1.48608f,-0.298508f,0.75634f,0.000347552f,
1.36048f,0.545494f,1.50174f,-0.314196f,0.755515f,0.000403877f, 1.36056f,0.575107f,1.51905f,-0.329854f,0.754638f,0.000469314f,
1.37401f,0.611565f,1.53721f,-0.345507f,0.753756f,0.000545612f, 1.36469f,0.637428f,1.55698f,-0.361056f,0.752793f,0.000633199f,
1.3671f,0.669455f,1.57758f,-0.376489f,0.751751f,0.000733527f, 1.36771f,0.701016f,1.60015f,-0.391832f,0.750747f,0.000850868f,
1.39085f,0.747543f,1.60446f,-0.406851f,0.749814f,0.000986147f, 1.36463f,0.762414f,1.64483f,-0.421757f,0.748951f,0.0011443f,
1.36551f,0.794905f,1.66946f,-0.43647f,0.748094f,0.00132575f, 1.36656f,0.827865f,1.69442f,-0.450958f,0.747258f,0.00153336f,
1.36587f,0.860059f,1.72004f,-0.465218f,0.746391f,0.0017701f, 1.3711f,0.896374f,1.74758f,-0.479297f,0.745552f,0.00204238f,
1.35907f,0.921768f,1.77755f,-0.493235f,0.744757f,0.00235669f, 1.3844f,0.966108f,1.78731f,-0.506978f,0.74403f,0.00271741f,
1.35317f,0.984493f,1.83823f,-0.520508f,0.743325f,0.00313133f, 1.35229f,1.01748f,1.87009f,-0.533812f,0.742755f,0.00360438f,
1.34959f,1.04936f,1.90199f,-0.546766f,0.74221f,0.0041408f, 1.34171f,1.07726f,1.93689f,-0.559429f,0.74176f,0.00475397f,
1.35241f,1.11989f,1.96826f,-0.571696f,0.741422f,0.00544904f, 1.3328f,1.13787f,2.00662f,-0.583449f,0.741134f,0.00623271f,
1.32945f,1.16883f,2.04335f,-0.594674f,0.740954f,0.00711532f, 1.33543f,1.2082f,2.07976f,-0.605409f,0.740976f,0.00811101f,
1.34488f,1.24968f,2.11279f,-0.615656f,0.741228f,0.00923842f, 1.3134f,1.24408f,2.16614f,-0.625274f,0.741702f,0.0105086f,
1.29327f,1.26708f,2.20358f,-0.634371f,0.742546f,0.0119442f, 1.28626f,1.29176f,2.24484f,-0.642591f,0.743628f,0.0135457f,
1.28102f,1.31697f,2.2849f,-0.649886f,0.745007f,0.0153326f, 1.29425f,1.36033f,2.31895f,-0.6566f,0.746972f,0.0173497f,
1.28204f,1.3766f,2.35976f,-0.662265f,0.749367f,0.0195916f, 1.26314f,1.38388f,2.40252f,-0.666427f,0.752415f,0.0220793f,
1.22697f,1.36827f,2.44919f,-0.668876f,0.756757f,0.0248664f, 1.21384f,1.37555f,2.48891f,-0.670313f,0.762182f,0.0279855f,
1.20611f,1.38694f,2.52544f,-0.670547f,0.76857f,0.0314399f, 1.20442f,1.4031f,2.5534f,-0.669608f,0.776044f,0.0352747f,
1.20089f,1.41517f,2.58341f,-0.667645f,0.784812f,0.0395715f, 1.15978f,1.37947f,2.63021f,-0.663944f,0.794675f,0.0442821f,
1.14018f,1.36728f,2.66381f,-0.659227f,0.806161f,0.0496066f, 1.1084f,1.33681f,2.69839f,-0.653238f,0.819322f,0.0556009f,
1.08344f,1.31132f,2.73493f,-0.645333f,0.834762f,0.0622764f, 1.05859f,1.27973f,2.75927f,-0.634157f,0.85616f,0.0696371f,
1.03549f,1.24868f,2.77821f,-0.621754f,0.880102f,0.0778621f, 1.0105f,1.21514f,2.80055f,-0.608353f,0.90691f,0.0873689f,
0.985102f,1.17653f,2.80275f,-0.593983f,0.943852f,0.099056f, 0.955946f,1.12511f,2.76578f,-0.575564f,0.9982f,0.112235f,
1.29199f,1.81987e-06f,1.29199f,-1.62093e-17f,0.743092f,4.57627e-05f, 1.2919f,0.0245933f,1.29236f,-0.0148048f,0.743047f,4.60711e-05f,
1.29164f,0.0491901f,1.2935f,-0.0296051f,0.742912f,4.69959e-05f, 1.29116f,0.0738206f,1.29536f,-0.0444641f,0.742725f,4.86554e-05f,
1.29038f,0.0985891f,1.29783f,-0.0596744f,0.74266f,5.17542e-05f, 1.2896f,0.123412f,1.30099f,-0.0749673f,0.742573f,5.60538e-05f,
1.28901f,0.148263f,1.30493f,-0.0902827f,0.742428f,6.15677e-05f, 1.28876f,0.173153f,1.30956f,-0.105589f,0.742202f,6.83439e-05f,
1.28894f,0.198117f,1.31496f,-0.120899f,0.741915f,7.65876e-05f, 1.28971f,0.223171f,1.32108f,-0.136188f,0.741544f,8.63718e-05f,
1.29125f,0.248337f,1.32797f,-0.151448f,0.741088f,9.78615e-05f, 1.29361f,0.273529f,1.33498f,-0.166673f,0.740549f,0.000111241f,
1.29607f,0.298577f,1.34268f,-0.18173f,0.739996f,0.000126741f, 1.2971f,0.323395f,1.35156f,-0.196539f,0.739483f,0.000144638f,
1.29858f,0.348568f,1.36158f,-0.2114f,0.73905f,0.000166392f, 1.30124f,0.374218f,1.37244f,-0.226277f,0.738618f,0.000192193f,
1.30329f,0.400283f,1.38436f,-0.241106f,0.738177f,0.000222378f, 1.3069f,0.427235f,1.39731f,-0.255936f,0.737695f,0.00025769f,
1.31003f,0.454499f,1.41099f,-0.27067f,0.73718f,0.000298409f, 1.31366f,0.482459f,1.42502f,-0.285336f,0.736581f,0.000345196f,
1.31591f,0.510229f,1.43849f,-0.299914f,0.735925f,0.000398872f, 1.31666f,0.537857f,1.45298f,-0.314442f,0.735256f,0.000460902f,
1.31711f,0.565764f,1.4704f,-0.329031f,0.734593f,0.000534166f, 1.31642f,0.593349f,1.48817f,-0.343581f,0.733893f,0.00061925f,
1.31844f,0.622572f,1.50638f,-0.358084f,0.73321f,0.000718128f, 1.32097f,0.652365f,1.52558f,-0.372457f,0.732473f,0.000831433f,
1.32263f,0.682087f,1.54494f,-0.386711f,0.7317f,0.000961355f, 1.32119f,0.71057f,1.5649f,-0.400819f,0.730882f,0.00111005f,
1.31844f,0.738391f,1.5873f,-0.414858f,0.730099f,0.00128197f, 1.31968f,0.768789f,1.60981f,-0.428841f,0.729366f,0.00148165f,
1.31938f,0.798483f,1.63267f,-0.442602f,0.728595f,0.00170916f, 1.31839f,0.828094f,1.65827f,-0.456212f,0.727841f,0.00197104f,
1.33353f,0.868039f,1.68118f,-0.469581f,0.727081f,0.00226978f, 1.3176f,0.888185f,1.7083f,-0.482515f,0.72646f,0.00260959f,
1.31422f,0.916247f,1.73394f,-0.494929f,0.725976f,0.00299483f, 1.30836f,0.942538f,1.76324f,-0.507037f,0.725635f,0.0034374f,
1.30705f,0.971973f,1.79097f,-0.5187f,0.725369f,0.00393798f, 1.30401f,0.999794f,1.81965f,-0.530006f,0.725246f,0.00450663f,
1.2979f,1.02511f,1.84819f,-0.540936f,0.725314f,0.00515051f, 1.3046f,1.06065f,1.8777f,-0.551483f,0.725548f,0.00588127f,
1.28666f,1.07573f,1.91039f,-0.56158f,0.72598f,0.006708f, 1.2803f,1.09997f,1.9444f,-0.571199f,0.726613f,0.00764321f,
1.27989f,1.12879f,1.97552f,-0.58023f,0.727458f,0.00869503f, 1.28606f,1.16268f,2.00523f,-0.588731f,0.728595f,0.00987888f,
1.25588f,1.1635f,2.04219f,-0.596569f,0.730035f,0.0112042f, 1.26826f,1.20189f,2.07144f,-0.603784f,0.731831f,0.0126965f,
1.23761f,1.19955f,2.11094f,-0.610229f,0.734024f,0.0143604f, 1.23066f,1.21799f,2.14434f,-0.615815f,0.736609f,0.0162222f,
1.2236f,1.23487f,2.18047f,-0.620757f,0.739809f,0.018315f, 1.23136f,1.26598f,2.20841f,-0.624695f,0.743537f,0.0206398f,
1.23709f,1.29409f,2.23454f,-0.627603f,0.747868f,0.0232336f, 1.19357f,1.2685f,2.27987f,-0.629724f,0.753048f,0.026149f,
1.16447f,1.25416f,2.31711f,-0.629631f,0.759603f,0.0293694f, 1.15146f,1.2547f,2.34364f,-0.62809f,0.767875f,0.0329669f,
1.13657f,1.25053f,2.37374f,-0.625682f,0.77751f,0.0369833f, 1.12611f,1.24967f,2.40081f,-0.62206f,0.788418f,0.0414248f,
1.11066f,1.24072f,2.42788f,-0.617484f,0.800853f,0.0464492f, 1.1008f,1.23687f,2.44767f,-0.611999f,0.815012f,0.0521465f,
1.08836f,1.22683f,2.47368f,-0.605087f,0.830816f,0.0584587f, 1.03907f,1.16907f,2.50146f,-0.594844f,0.851614f,0.065403f,
1.01902f,1.14277f,2.51313f,-0.583366f,0.876816f,0.0733055f, 0.997722f,1.11567f,2.52045f,-0.571171f,0.904859f,0.0824931f,
0.974739f,1.08294f,2.52852f,-0.558014f,0.941417f,0.0936076f, 0.947688f,1.03639f,2.48916f,-0.541082f,0.998123f,0.106573f,
1.25032f,-1.31046e-06f,1.25032f,-1.07992e-16f,0.721626f,4.55313e-05f, 1.25019f,0.0233397f,1.25067f,-0.0147943f,0.721585f,4.59754e-05f,
1.24982f,0.0466774f,1.25171f,-0.0295837f,0.721464f,4.73136e-05f, 1.24922f,0.0699718f,1.25339f,-0.044257f,0.721319f,4.96438e-05f,
1.2484f,0.0931316f,1.25557f,-0.0585786f,0.721289f,5.31314e-05f, 1.24766f,0.116263f,1.25839f,-0.072814f,0.721237f,5.75768e-05f,
1.24715f,0.139386f,1.26179f,-0.0870062f,0.721136f,6.30075e-05f, 1.24705f,0.162538f,1.26586f,-0.101176f,0.720958f,6.94662e-05f,
1.24743f,0.185721f,1.27055f,-0.115313f,0.72072f,7.70696e-05f, 1.2477f,0.208922f,1.27604f,-0.129469f,0.720422f,8.60458e-05f,
1.24839f,0.232247f,1.28216f,-0.143812f,0.720155f,9.72928e-05f, 1.24985f,0.255671f,1.28881f,-0.158228f,0.719896f,0.00011091f,
1.25192f,0.278896f,1.29503f,-0.17263f,0.719575f,0.000126868f, 1.25376f,0.302108f,1.3024f,-0.18703f,0.719202f,0.000145566f,
1.25687f,0.325699f,1.31125f,-0.201417f,0.718775f,0.00016738f, 1.25991f,0.349723f,1.3212f,-0.215749f,0.718274f,0.000192531f,
1.26368f,0.374499f,1.33233f,-0.23002f,0.717707f,0.000221461f, 1.26757f,0.39979f,1.34413f,-0.244232f,0.717095f,0.000254706f,
1.26903f,0.424819f,1.35723f,-0.25844f,0.716452f,0.000293413f, 1.27088f,0.450291f,1.37056f,-0.272503f,0.7159f,0.000339003f,
1.28526f,0.481226f,1.3842f,-0.286407f,0.715418f,0.000392333f, 1.27469f,0.501697f,1.3957f,-0.300131f,0.71493f,0.00045355f,
1.27516f,0.527509f,1.41014f,-0.313738f,0.714424f,0.000523986f, 1.27628f,0.553611f,1.42492f,-0.327255f,0.713941f,0.000605622f,
1.27829f,0.580452f,1.44105f,-0.34065f,0.713446f,0.000699112f, 1.27801f,0.60641f,1.45883f,-0.353898f,0.712956f,0.000806131f,
1.2805f,0.633893f,1.4763f,-0.367137f,0.712488f,0.000931004f, 1.29973f,0.673508f,1.47905f,-0.380197f,0.712042f,0.00107372f,
1.2925f,0.693794f,1.51132f,-0.393192f,0.711621f,0.00123919f, 1.27801f,0.712588f,1.53125f,-0.405989f,0.711172f,0.0014278f,
1.27878f,0.740071f,1.55127f,-0.418575f,0.710767f,0.00164258f, 1.27805f,0.766724f,1.57153f,-0.43092f,0.710347f,0.00188658f,
1.2765f,0.793012f,1.59516f,-0.443125f,0.709995f,0.00216659f, 1.29261f,0.831226f,1.61326f,-0.455174f,0.709756f,0.00248776f,
1.27503f,0.846784f,1.6391f,-0.466925f,0.709556f,0.00285184f, 1.27017f,0.870905f,1.6621f,-0.47834f,0.709389f,0.00326385f,
1.26416f,0.894219f,1.68954f,-0.48948f,0.709315f,0.00373366f, 1.26289f,0.920685f,1.71453f,-0.500318f,0.709392f,0.00426638f,
1.25959f,0.945422f,1.73967f,-0.510704f,0.709541f,0.00486625f, 1.25165f,0.966145f,1.76779f,-0.520749f,0.709858f,0.0055482f,
1.25391f,0.994433f,1.79413f,-0.530055f,0.710533f,0.0063195f, 1.24262f,1.01125f,1.81974f,-0.538677f,0.711583f,0.00718897f,
1.23853f,1.03307f,1.84716f,-0.54673f,0.712986f,0.00817218f, 1.23311f,1.05356f,1.87435f,-0.554092f,0.714669f,0.00927264f,
1.23701f,1.08134f,1.90028f,-0.56079f,0.71668f,0.0105044f, 1.23844f,1.0963f,1.92169f,-0.566929f,0.719146f,0.011887f,
1.20499f,1.09842f,1.95782f,-0.572479f,0.722083f,0.0134408f, 1.21248f,1.12705f,1.98166f,-0.577231f,0.725441f,0.0151751f,
1.18489f,1.12144f,2.01473f,-0.581267f,0.729364f,0.0171146f, 1.17608f,1.13218f,2.04355f,-0.584535f,0.733891f,0.019282f,
1.16688f,1.14157f,2.07066f,-0.587082f,0.739145f,0.0217172f, 1.16024f,1.15149f,2.09919f,-0.588613f,0.745067f,0.0244264f,
1.16144f,1.1683f,2.12191f,-0.589221f,0.751832f,0.0274369f, 1.161f,1.18465f,2.13955f,-0.589f,0.75958f,0.0308312f,
1.11981f,1.1498f,2.17451f,-0.586004f,0.769626f,0.0345832f, 1.10354f,1.14105f,2.1952f,-0.582226f,0.781487f,0.0387769f,
1.0949f,1.13858f,2.21311f,-0.577666f,0.794882f,0.0434983f, 1.0605f,1.10647f,2.23738f,-0.572611f,0.810088f,0.0489116f,
1.04304f,1.0913f,2.25914f,-0.566158f,0.826818f,0.0548891f, 1.02188f,1.06913f,2.28015f,-0.557244f,0.846613f,0.061448f,
1.00102f,1.04302f,2.28615f,-0.546595f,0.873168f,0.069053f, 0.981323f,1.01904f,2.28795f,-0.535523f,0.902565f,0.0779565f,
0.957078f,0.987978f,2.29215f,-0.523451f,0.938829f,0.0885232f, 0.922068f,0.935526f,2.24778f,-0.507883f,0.998041f,0.101308f,
1.21175f,2.39508e-06f,1.21174f,-3.32834e-18f,0.700376f,4.77335e-05f, 1.21161f,0.0216814f,1.21204f,-0.0136228f,0.700339f,4.80922e-05f,
1.21123f,0.0433562f,1.21293f,-0.0272405f,0.700229f,4.91705e-05f, 1.21068f,0.0650283f,1.21443f,-0.0408483f,0.700045f,5.09745e-05f,
1.20999f,0.0866985f,1.21655f,-0.0544482f,0.699791f,5.35272e-05f, 1.20911f,0.108471f,1.21917f,-0.0683231f,0.699617f,5.7474e-05f,
1.20853f,0.130272f,1.22231f,-0.0823091f,0.699448f,6.27676e-05f, 1.20838f,0.152088f,1.22597f,-0.096304f,0.699229f,6.93531e-05f,
1.20869f,0.173936f,1.23028f,-0.110318f,0.698975f,7.74299e-05f, 1.20951f,0.19574f,1.23509f,-0.124191f,0.69871f,8.70576e-05f,
1.21089f,0.217459f,1.24037f,-0.137804f,0.698497f,9.8417e-05f, 1.21304f,0.239154f,1.24615f,-0.151279f,0.69828f,0.000111649f,
1.2156f,0.260515f,1.25131f,-0.164667f,0.698031f,0.000126947f, 1.21822f,0.281986f,1.25798f,-0.177989f,0.697731f,0.000144531f,
1.21934f,0.303718f,1.26596f,-0.191283f,0.69743f,0.000165026f, 1.22029f,0.325649f,1.27493f,-0.204673f,0.697154f,0.000189564f,
1.22339f,0.348325f,1.28476f,-0.218057f,0.696848f,0.000218196f, 1.22532f,0.371107f,1.29516f,-0.231398f,0.696543f,0.000251476f,
1.23223f,0.395937f,1.30749f,-0.244716f,0.696206f,0.000290121f, 1.2318f,0.418422f,1.31836f,-0.257955f,0.695816f,0.000334474f,
1.23515f,0.442705f,1.33023f,-0.271103f,0.695399f,0.000385304f, 1.23726f,0.466647f,1.34147f,-0.28415f,0.694954f,0.000443422f,
1.23674f,0.489845f,1.35457f,-0.297131f,0.694484f,0.000510324f, 1.23822f,0.514281f,1.36812f,-0.3101f,0.694027f,0.000588262f,
1.23747f,0.537728f,1.38296f,-0.323034f,0.693581f,0.00067878f, 1.23934f,0.562638f,1.39811f,-0.33589f,0.693173f,0.000783108f,
1.24148f,0.587874f,1.41339f,-0.34844f,0.692805f,0.000902061f, 1.25703f,0.617252f,1.42822f,-0.360625f,0.692508f,0.00103748f,
1.24234f,0.636707f,1.44372f,-0.372517f,0.692255f,0.00119143f, 1.26287f,0.666995f,1.44564f,-0.384177f,0.692046f,0.00136699f,
1.23823f,0.683263f,1.4793f,-0.395791f,0.691977f,0.00157119f, 1.23866f,0.708003f,1.49716f,-0.407133f,0.691973f,0.00180306f,
1.23544f,0.730554f,1.5163f,-0.418214f,0.691999f,0.0020661f, 1.23542f,0.755073f,1.53526f,-0.429072f,0.692126f,0.00236687f,
1.24857f,0.78418f,1.55421f,-0.439663f,0.692313f,0.00270813f, 1.23157f,0.801057f,1.57479f,-0.449979f,0.692638f,0.00309505f,
1.22673f,0.821908f,1.59624f,-0.460051f,0.693095f,0.00353446f, 1.22383f,0.843987f,1.61749f,-0.469894f,0.693739f,0.00403649f,
1.22175f,0.866523f,1.63932f,-0.479329f,0.694499f,0.00460204f, 1.22888f,0.895622f,1.66016f,-0.488304f,0.695366f,0.00523803f,
1.22238f,0.914398f,1.68257f,-0.496868f,0.696448f,0.0059535f, 1.20794f,0.926313f,1.70622f,-0.505005f,0.697745f,0.00675979f,
1.21266f,0.951317f,1.72943f,-0.512619f,0.699253f,0.00766453f, 1.19839f,0.963181f,1.75246f,-0.51991f,0.701146f,0.0086898f,
1.19278f,0.980372f,1.77711f,-0.526632f,0.703326f,0.00984226f, 1.18618f,0.995657f,1.80125f,-0.532158f,0.706011f,0.0111268f,
1.18408f,1.01306f,1.82487f,-0.536792f,0.709451f,0.0125712f, 1.18122f,1.02919f,1.84573f,-0.540737f,0.713513f,0.0141902f,
1.15627f,1.02445f,1.8694f,-0.54396f,0.718161f,0.0160001f, 1.14779f,1.03273f,1.89335f,-0.54643f,0.723429f,0.0180126f,
1.15195f,1.05218f,1.91233f,-0.548413f,0.729505f,0.0202922f, 1.12341f,1.0393f,1.93825f,-0.549589f,0.736331f,0.0228263f,
1.11443f,1.04352f,1.95852f,-0.549811f,0.743908f,0.0256404f, 1.10173f,1.0427f,1.98349f,-0.549529f,0.752569f,0.0288352f,
1.08986f,1.04123f,2.00608f,-0.548006f,0.762059f,0.0323513f, 1.0765f,1.0357f,2.02247f,-0.544405f,0.773983f,0.036317f,
1.06423f,1.02846f,2.03424f,-0.539777f,0.788354f,0.0407675f, 1.05437f,1.02249f,2.05057f,-0.534902f,0.804568f,0.045881f,
1.04246f,1.0134f,2.06492f,-0.528862f,0.822303f,0.0515498f, 1.02803f,1.00138f,2.07881f,-0.521543f,0.841651f,0.0578167f,
1.00783f,0.976856f,2.08399f,-0.511293f,0.869173f,0.0650829f, 0.970327f,0.935325f,2.08186f,-0.501241f,0.900021f,0.0737224f,
0.948928f,0.910134f,2.09064f,-0.490187f,0.936101f,0.0837844f, 0.923681f,0.869965f,2.04004f,-0.475858f,0.997955f,0.0964113f,
1.17759f,-1.52531e-06f,1.1776f,-6.76034e-17f,0.677333f,4.61072e-05f, 1.17743f,0.0204738f,1.17787f,-0.0134668f,0.677301f,4.6549e-05f,
1.17685f,0.0408379f,1.17856f,-0.0266612f,0.677341f,4.81056e-05f, 1.17595f,0.0610983f,1.17968f,-0.0396131f,0.677462f,5.07153e-05f,
1.17496f,0.0813319f,1.18129f,-0.0525372f,0.677541f,5.41885e-05f, 1.17412f,0.101543f,1.18342f,-0.0654403f,0.67757f,5.85769e-05f,
1.17359f,0.121727f,1.18605f,-0.0783261f,0.677532f,6.39255e-05f, 1.17345f,0.141885f,1.18921f,-0.0911881f,0.677442f,7.035e-05f,
1.17379f,0.162035f,1.19286f,-0.104022f,0.677295f,7.79321e-05f, 1.17468f,0.182181f,1.19703f,-0.116822f,0.677085f,8.67672e-05f,
1.17464f,0.202255f,1.20203f,-0.129697f,0.676867f,9.73962e-05f, 1.17659f,0.222399f,1.20722f,-0.142675f,0.67666f,0.000110295f,
1.18263f,0.242698f,1.21302f,-0.155702f,0.676446f,0.000125671f, 1.18106f,0.262266f,1.218f,-0.168691f,0.676197f,0.000143553f,
1.18292f,0.282377f,1.22457f,-0.181638f,0.675905f,0.000164255f, 1.19368f,0.304888f,1.23517f,-0.19455f,0.675597f,0.000188336f,
1.18869f,0.323916f,1.24138f,-0.207169f,0.675347f,0.000215988f, 1.19192f,0.345267f,1.25077f,-0.219593f,0.675111f,0.000247638f,
1.19516f,0.366991f,1.26061f,-0.231862f,0.674873f,0.000283775f, 1.19596f,0.388174f,1.27139f,-0.24412f,0.674682f,0.000326169f,
1.19725f,0.409773f,1.28242f,-0.256346f,0.674503f,0.000375478f, 1.20494f,0.434117f,1.29414f,-0.268507f,0.674371f,0.000432585f,
1.2106f,0.45793f,1.3045f,-0.280551f,0.674221f,0.000497869f, 1.20284f,0.475939f,1.31479f,-0.29247f,0.674053f,0.000572371f,
1.21018f,0.501143f,1.32786f,-0.30431f,0.673931f,0.000658246f, 1.20417f,0.520018f,1.33982f,-0.316012f,0.673789f,0.00075614f,
1.20359f,0.541654f,1.35449f,-0.327577f,0.673651f,0.000867836f, 1.20527f,0.56452f,1.36828f,-0.339082f,0.673594f,0.000997129f,
1.22139f,0.595183f,1.38199f,-0.350401f,0.673531f,0.0011441f, 1.20392f,0.607883f,1.39759f,-0.361598f,0.673512f,0.00131271f,
1.22508f,0.641707f,1.39514f,-0.372683f,0.673593f,0.00150587f, 1.20336f,0.651955f,1.42811f,-0.383545f,0.673714f,0.00172496f,
1.20375f,0.674496f,1.44452f,-0.394153f,0.673865f,0.00197302f, 1.20243f,0.69576f,1.46055f,-0.404326f,0.67413f,0.00225357f,
1.19985f,0.716148f,1.4792f,-0.41406f,0.674649f,0.00257341f, 1.2113f,0.743838f,1.49226f,-0.423437f,0.675339f,0.00293668f,
1.19474f,0.756247f,1.51246f,-0.432404f,0.676163f,0.00334638f, 1.20433f,0.783827f,1.52989f,-0.441033f,0.677159f,0.00380989f,
1.1932f,0.797468f,1.54833f,-0.449353f,0.678376f,0.00433431f, 1.18555f,0.812787f,1.56715f,-0.457367f,0.67985f,0.00492769f,
1.18234f,0.831155f,1.58598f,-0.464981f,0.681518f,0.00559655f, 1.18818f,0.855721f,1.60394f,-0.472134f,0.683422f,0.00634702f,
1.17788f,0.867713f,1.6243f,-0.478783f,0.685542f,0.00718828f, 1.19338f,0.898609f,1.63784f,-0.485082f,0.688041f,0.00813619f,
1.16207f,0.893286f,1.66286f,-0.490952f,0.690879f,0.00920723f, 1.17432f,0.92133f,1.68044f,-0.496412f,0.694154f,0.0104143f,
1.1459f,0.916118f,1.70312f,-0.501128f,0.697728f,0.0117561f, 1.13904f,0.926769f,1.72568f,-0.505344f,0.701799f,0.0132623f,
1.13243f,0.936967f,1.74543f,-0.508807f,0.706567f,0.0149613f, 1.12601f,0.945821f,1.76411f,-0.510469f,0.712325f,0.0168324f,
1.12898f,0.961088f,1.77883f,-0.511815f,0.719159f,0.0189663f, 1.11927f,0.953148f,1.80143f,-0.512375f,0.726758f,0.0213272f,
1.08917f,0.948015f,1.81275f,-0.512393f,0.735284f,0.0239837f, 1.07647f,0.945669f,1.83354f,-0.51178f,0.744772f,0.0269642f,
1.0718f,0.950523f,1.84737f,-0.510254f,0.755181f,0.0302748f, 1.06741f,0.954126f,1.86408f,-0.508165f,0.766784f,0.0340342f,
1.03816f,0.930824f,1.87399f,-0.503679f,0.781293f,0.0382488f, 1.02379f,0.919693f,1.8851f,-0.498765f,0.79849f,0.0430539f,
1.00802f,0.906854f,1.89556f,-0.493093f,0.81731f,0.0484388f, 0.989586f,0.891266f,1.90825f,-0.486518f,0.837816f,0.0544787f,
0.969633f,0.869343f,1.91276f,-0.477329f,0.864845f,0.0613748f, 0.951563f,0.849555f,1.90524f,-0.468203f,0.897239f,0.0697689f,
0.927014f,0.823838f,1.90969f,-0.458222f,0.933301f,0.0794136f, 0.889008f,0.774642f,1.85089f,-0.444909f,0.997864f,0.0918561f,
1.14518f,2.53754e-07f,1.14518f,-5.9599e-17f,0.655699f,4.84393e-05f, 1.14501f,0.0188899f,1.14541f,-0.0122664f,0.655672f,4.88106e-05f,
1.14455f,0.037769f,1.14608f,-0.0245279f,0.65559f,4.99277e-05f, 1.14385f,0.0566471f,1.14723f,-0.0367796f,0.655454f,5.18004e-05f,
1.14311f,0.0754988f,1.14884f,-0.0490166f,0.655265f,5.44448e-05f, 1.14221f,0.09435f,1.15093f,-0.0613233f,0.655064f,5.80562e-05f,
1.14158f,0.113237f,1.15339f,-0.0738417f,0.654924f,6.30899e-05f, 1.1413f,0.132118f,1.15623f,-0.0864172f,0.654779f,6.94643e-05f,
1.14148f,0.150878f,1.15945f,-0.0987462f,0.654704f,7.72495e-05f, 1.14204f,0.169543f,1.16294f,-0.11092f,0.654679f,8.65884e-05f,
1.14319f,0.188149f,1.16689f,-0.12301f,0.654652f,9.75633e-05f, 1.14499f,0.206657f,1.1713f,-0.135025f,0.654602f,0.00011031f,
1.16092f,0.226905f,1.18014f,-0.14697f,0.654533f,0.000125041f, 1.15033f,0.243147f,1.1803f,-0.158852f,0.65443f,0.000141966f,
1.15282f,0.261733f,1.18631f,-0.170675f,0.654289f,0.000161345f, 1.15379f,0.280488f,1.19363f,-0.182536f,0.65419f,0.000184217f,
1.15456f,0.299345f,1.20143f,-0.194455f,0.654108f,0.00021123f, 1.15734f,0.318851f,1.20989f,-0.206304f,0.653989f,0.000242224f,
1.15898f,0.338388f,1.21864f,-0.218121f,0.65389f,0.000278135f, 1.16196f,0.358497f,1.22801f,-0.229885f,0.653786f,0.000319516f,
1.16458f,0.3787f,1.23782f,-0.241552f,0.653654f,0.000366774f, 1.16754f,0.399266f,1.24772f,-0.253112f,0.653498f,0.000420659f,
1.18705f,0.426467f,1.24441f,-0.264522f,0.653351f,0.000482065f, 1.18944f,0.44748f,1.25236f,-0.275646f,0.653356f,0.000552851f,
1.17041f,0.459218f,1.27803f,-0.286599f,0.653433f,0.000634342f, 1.1827f,0.484776f,1.29068f,-0.297399f,0.65356f,0.000727801f,
1.17051f,0.498787f,1.30113f,-0.308038f,0.653752f,0.000835037f, 1.17148f,0.519047f,1.31332f,-0.31849f,0.653974f,0.000956953f,
1.17268f,0.539452f,1.32589f,-0.328791f,0.654279f,0.00109586f, 1.18128f,0.563822f,1.33839f,-0.338895f,0.654631f,0.00125346f,
1.19234f,0.589076f,1.34242f,-0.348782f,0.655036f,0.00143206f, 1.17849f,0.599291f,1.36554f,-0.358508f,0.655509f,0.00163576f,
1.16931f,0.616798f,1.3778f,-0.368111f,0.656132f,0.00186933f, 1.16908f,0.636312f,1.39265f,-0.377481f,0.656822f,0.00213395f,
1.17141f,0.657472f,1.40714f,-0.386669f,0.657658f,0.00243443f, 1.16661f,0.674105f,1.42156f,-0.395588f,0.658611f,0.00277392f,
1.16378f,0.691899f,1.43808f,-0.404201f,0.659661f,0.00315726f, 1.17153f,0.716044f,1.45345f,-0.412537f,0.660865f,0.00359106f,
1.15778f,0.726286f,1.46858f,-0.420541f,0.662231f,0.00407953f, 1.16871f,0.752078f,1.48434f,-0.42799f,0.663865f,0.00463022f,
1.1544f,0.760601f,1.50045f,-0.434739f,0.665903f,0.00525089f, 1.14603f,0.772219f,1.51669f,-0.441129f,0.668355f,0.00595449f,
1.1416f,0.786399f,1.5328f,-0.446985f,0.671103f,0.00674244f, 1.13823f,0.800732f,1.54895f,-0.452285f,0.674138f,0.00762216f,
1.1321f,0.812167f,1.56379f,-0.457162f,0.677571f,0.00860886f, 1.13632f,0.830629f,1.57847f,-0.461888f,0.681554f,0.00973735f,
1.11825f,0.831833f,1.59546f,-0.466026f,0.685908f,0.010997f, 1.11073f,0.840428f,1.61255f,-0.469522f,0.69068f,0.0123955f,
1.11827f,0.85972f,1.62833f,-0.472716f,0.696071f,0.0139823f, 1.09513f,0.854061f,1.6442f,-0.475205f,0.701966f,0.0157408f,
1.08732f,0.859339f,1.66223f,-0.477151f,0.708502f,0.0177273f, 1.07735f,0.861091f,1.67697f,-0.477136f,0.716561f,0.019931f,
1.0686f,0.862679f,1.68841f,-0.476756f,0.725931f,0.0224407f, 1.0589f,0.862176f,1.70155f,-0.475713f,0.736244f,0.0252223f,
1.04735f,0.859476f,1.71548f,-0.47426f,0.747673f,0.0283636f, 1.04147f,0.860716f,1.72658f,-0.472144f,0.760173f,0.0318996f,
1.03553f,0.86141f,1.73682f,-0.469448f,0.773948f,0.0359113f, 1.02379f,0.853642f,1.74279f,-0.464126f,0.791903f,0.0404318f,
1.00225f,0.835165f,1.75165f,-0.458807f,0.811901f,0.0455665f, 0.989105f,0.826976f,1.75358f,-0.45279f,0.833584f,0.0513598f,
0.971291f,0.80735f,1.75868f,-0.444635f,0.860223f,0.0579298f, 0.953081f,0.788497f,1.7508f,-0.436299f,0.894228f,0.0660757f,
0.909994f,0.749159f,1.74503f,-0.427325f,0.930817f,0.0753701f, 0.909894f,0.734529f,1.70104f,-0.414947f,0.997769f,0.0876181f,
1.11689f,-3.92878e-06f,1.11689f,-3.71428e-17f,0.632061f,4.64583e-05f, 1.11668f,0.0176969f,1.11707f,-0.0119442f,0.632068f,4.69423e-05f,
1.11598f,0.0352225f,1.11749f,-0.0234878f,0.632236f,4.86087e-05f, 1.115f,0.0527279f,1.11828f,-0.0349931f,0.632392f,5.11022e-05f,
1.11394f,0.070207f,1.11947f,-0.0464849f,0.63251f,5.44195e-05f, 1.11306f,0.0876393f,1.12103f,-0.0579612f,0.632591f,5.86294e-05f,
1.11247f,0.105014f,1.12301f,-0.0694176f,0.632634f,6.37984e-05f, 1.11224f,0.122341f,1.12536f,-0.08085f,0.632634f,6.99987e-05f,
1.11244f,0.139614f,1.12813f,-0.0922532f,0.632593f,7.73242e-05f, 1.11312f,0.156818f,1.13128f,-0.103622f,0.63251f,8.58809e-05f,
1.11358f,0.173951f,1.13501f,-0.114994f,0.632411f,9.59395e-05f, 1.11439f,0.191023f,1.13909f,-0.126497f,0.632359f,0.000108212f,
1.11589f,0.208005f,1.14338f,-0.138015f,0.632303f,0.000122665f, 1.11863f,0.224694f,1.14689f,-0.149531f,0.632238f,0.00013957f,
1.12611f,0.242436f,1.15389f,-0.160873f,0.632194f,0.000159052f, 1.12242f,0.258839f,1.1579f,-0.171972f,0.632216f,0.000181488f,
1.12489f,0.276342f,1.16464f,-0.182953f,0.63228f,0.000207401f, 1.12709f,0.29394f,1.17184f,-0.193816f,0.632345f,0.00023701f,
1.12973f,0.311902f,1.17979f,-0.204562f,0.632417f,0.000270786f, 1.13046f,0.329617f,1.18822f,-0.215244f,0.632523f,0.00030959f,
1.13752f,0.349621f,1.1978f,-0.225907f,0.632674f,0.000354676f, 1.13346f,0.36577f,1.20585f,-0.236537f,0.632847f,0.000406778f,
1.13598f,0.38444f,1.21478f,-0.24707f,0.633066f,0.000466547f, 1.15548f,0.409689f,1.21001f,-0.257487f,0.633279f,0.000534596f,
1.15548f,0.427879f,1.21925f,-0.267778f,0.633498f,0.000612f, 1.13999f,0.439435f,1.24124f,-0.277935f,0.633765f,0.000700037f,
1.14524f,0.460169f,1.25247f,-0.287981f,0.634059f,0.00080052f, 1.14052f,0.475632f,1.2624f,-0.297902f,0.634391f,0.000914936f,
1.1394f,0.493134f,1.27475f,-0.307752f,0.634821f,0.0010462f, 1.14046f,0.511681f,1.28589f,-0.317381f,0.635362f,0.00119606f,
1.14129f,0.529984f,1.29713f,-0.326564f,0.636053f,0.00136571f, 1.14663f,0.550533f,1.30848f,-0.335412f,0.636857f,0.00155758f,
1.13741f,0.563224f,1.31995f,-0.34405f,0.63782f,0.00177622f, 1.15849f,0.58877f,1.3138f,-0.352425f,0.638927f,0.00202368f,
1.13426f,0.59633f,1.34312f,-0.360511f,0.640137f,0.00230267f, 1.13355f,0.61305f,1.35626f,-0.368352f,0.641493f,0.00261831f,
1.1391f,0.633217f,1.36958f,-0.376003f,0.64306f,0.00297666f, 1.13032f,0.644786f,1.38201f,-0.383441f,0.644822f,0.00338231f,
1.12836f,0.660254f,1.39521f,-0.390559f,0.646771f,0.00383832f, 1.1366f,0.682091f,1.40953f,-0.397324f,0.648884f,0.00435117f,
1.11999f,0.687333f,1.4217f,-0.403774f,0.651225f,0.00492927f, 1.11948f,0.702715f,1.43631f,-0.409963f,0.653854f,0.00558237f,
1.13551f,0.726235f,1.43912f,-0.415831f,0.656761f,0.00631891f, 1.11981f,0.725973f,1.46758f,-0.421324f,0.660011f,0.00714583f,
1.10095f,0.734479f,1.47823f,-0.425598f,0.66382f,0.00806513f, 1.10126f,0.747515f,1.4886f,-0.429238f,0.668194f,0.00909801f,
1.09451f,0.755621f,1.50222f,-0.432774f,0.673277f,0.010283f, 1.09642f,0.770139f,1.51175f,-0.435671f,0.678797f,0.0115955f,
1.08027f,0.768579f,1.52888f,-0.438121f,0.684872f,0.013066f, 1.08288f,0.781593f,1.54084f,-0.440166f,0.691566f,0.0147163f,
1.06249f,0.776078f,1.55265f,-0.441824f,0.698945f,0.0165773f, 1.05456f,0.779468f,1.5657f,-0.442766f,0.70691f,0.0186399f,
1.04801f,0.782763f,1.57715f,-0.443015f,0.716086f,0.0210053f, 1.04408f,0.786224f,1.58599f,-0.441356f,0.727088f,0.0236058f,
1.04028f,0.788861f,1.59419f,-0.439748f,0.739476f,0.0265802f, 1.03508f,0.778771f,1.59482f,-0.437551f,0.752922f,0.0299047f,
1.00267f,0.768038f,1.61075f,-0.435176f,0.767711f,0.0337275f, 0.988948f,0.759553f,1.61678f,-0.430967f,0.784884f,0.0379992f,
0.973215f,0.747268f,1.62128f,-0.425843f,0.806073f,0.042898f, 0.957999f,0.735672f,1.62335f,-0.420245f,0.828969f,0.048444f,
0.941217f,0.721643f,1.6238f,-0.413157f,0.855345f,0.0547425f, 0.923776f,0.704228f,1.61061f,-0.405433f,0.890999f,0.0626238f,
0.899782f,0.683741f,1.60461f,-0.39724f,0.929204f,0.0716511f, 0.861363f,0.64032f,1.54474f,-0.385892f,0.997669f,0.0836745f,
1.08981f,-1.6601e-06f,1.08981f,-1.68339e-17f,0.610128f,4.83924e-05f, 1.08962f,0.0161996f,1.08997f,-0.0107911f,0.610112f,4.87571e-05f,
1.08911f,0.0323967f,1.09046f,-0.0215781f,0.610063f,4.98551e-05f, 1.08834f,0.0485742f,1.09129f,-0.0323565f,0.609983f,5.16978e-05f,
1.0875f,0.06473f,1.09248f,-0.0431222f,0.609871f,5.43045e-05f, 1.08653f,0.0808476f,1.09403f,-0.0539133f,0.609747f,5.77764e-05f,
1.08583f,0.0969857f,1.09583f,-0.0649179f,0.609695f,6.25835e-05f, 1.08541f,0.113058f,1.09792f,-0.075911f,0.609676f,6.86535e-05f,
1.08536f,0.128986f,1.10028f,-0.0866676f,0.609754f,7.60872e-05f, 1.08562f,0.144804f,1.10284f,-0.0973003f,0.60986f,8.48966e-05f,
1.08637f,0.16052f,1.10575f,-0.107874f,0.609993f,9.52943e-05f, 1.08762f,0.176121f,1.10901f,-0.118393f,0.610115f,0.00010735f,
1.08951f,0.191588f,1.11258f,-0.128846f,0.610235f,0.000121265f, 1.09994f,0.207585f,1.11879f,-0.139251f,0.610333f,0.000137235f,
1.09471f,0.222209f,1.11993f,-0.149584f,0.610444f,0.00015555f, 1.09531f,0.237782f,1.12517f,-0.159905f,0.610554f,0.000176695f,
1.09593f,0.253528f,1.13109f,-0.170265f,0.610692f,0.000201465f, 1.1082f,0.272188f,1.14108f,-0.180618f,0.610872f,0.000230255f,
1.10016f,0.285809f,1.14439f,-0.190896f,0.611049f,0.000263155f, 1.10123f,0.302038f,1.15154f,-0.201123f,0.611234f,0.000300935f,
1.10367f,0.318726f,1.15913f,-0.211292f,0.61143f,0.00034427f, 1.11371f,0.338293f,1.16897f,-0.221179f,0.61173f,0.000393695f,
1.10781f,0.352056f,1.17502f,-0.230819f,0.61212f,0.000449954f, 1.10989f,0.368884f,1.18299f,-0.240272f,0.612559f,0.000513844f,
1.1199f,0.389088f,1.19325f,-0.249557f,0.613058f,0.000586491f, 1.11666f,0.403876f,1.20002f,-0.25878f,0.613627f,0.000670242f,
1.11065f,0.417192f,1.20705f,-0.267853f,0.614275f,0.000765465f, 1.10976f,0.432953f,1.21674f,-0.27682f,0.614998f,0.000874069f,
1.11002f,0.448932f,1.22598f,-0.285661f,0.615814f,0.000998103f, 1.11053f,0.465193f,1.23553f,-0.294373f,0.616693f,0.00113916f,
1.11071f,0.481173f,1.24554f,-0.302908f,0.617676f,0.00129892f, 1.1111f,0.497315f,1.25547f,-0.311248f,0.61872f,0.00147953f,
1.11353f,0.51441f,1.26648f,-0.319458f,0.619892f,0.0016846f, 1.11951f,0.53331f,1.27687f,-0.327478f,0.621194f,0.00191636f,
1.10873f,0.543172f,1.28573f,-0.335255f,0.622584f,0.00217762f, 1.12661f,0.568359f,1.29834f,-0.342725f,0.624123f,0.00247266f,
1.10251f,0.570374f,1.30779f,-0.349646f,0.626001f,0.00280675f, 1.10087f,0.58414f,1.31937f,-0.356129f,0.628107f,0.00318269f,
1.09959f,0.597825f,1.33041f,-0.362333f,0.630487f,0.0036083f, 1.09573f,0.609665f,1.34133f,-0.368341f,0.633181f,0.00409072f,
1.09269f,0.621886f,1.35249f,-0.373978f,0.636122f,0.00463105f, 1.09098f,0.634453f,1.36303f,-0.379228f,0.639296f,0.00523535f,
1.09904f,0.652806f,1.37509f,-0.384192f,0.642769f,0.00591767f, 1.0812f,0.654019f,1.38546f,-0.388997f,0.646665f,0.00668963f,
1.07639f,0.663496f,1.3977f,-0.393374f,0.650853f,0.00755191f, 1.08487f,0.681561f,1.40781f,-0.397288f,0.655377f,0.00851128f,
1.06912f,0.682072f,1.41772f,-0.401026f,0.66038f,0.00960995f, 1.07196f,0.693861f,1.42856f,-0.403692f,0.666302f,0.0108456f,
1.05444f,0.692475f,1.43869f,-0.405412f,0.672977f,0.0122157f, 1.04829f,0.697139f,1.44874f,-0.406851f,0.680401f,0.0137602f,
1.0408f,0.700205f,1.45945f,-0.407981f,0.68855f,0.0154967f, 1.03485f,0.704169f,1.46675f,-0.408717f,0.697416f,0.0174443f,
1.02985f,0.707945f,1.47783f,-0.409221f,0.707123f,0.0196615f, 1.02896f,0.714695f,1.48532f,-0.408864f,0.717605f,0.0221154f,
1.02358f,0.715626f,1.49183f,-0.406727f,0.730677f,0.0249195f, 0.998091f,0.699634f,1.49626f,-0.404483f,0.745154f,0.028074f,
0.98919f,0.696779f,1.50252f,-0.402083f,0.760923f,0.0316776f, 0.982014f,0.695172f,1.50747f,-0.399166f,0.777904f,0.0357413f,
0.969325f,0.685774f,1.50964f,-0.394009f,0.7998f,0.0403984f, 0.956458f,0.676651f,1.50856f,-0.388778f,0.823986f,0.0457164f,
0.941908f,0.666485f,1.508f,-0.382864f,0.850257f,0.0517967f, 0.923826f,0.64579f,1.48779f,-0.375514f,0.887558f,0.0593953f,
0.882733f,0.617174f,1.47483f,-0.368055f,0.927487f,0.0681834f, 0.852843f,0.583256f,1.41901f,-0.357671f,0.997566f,0.0800038f,
1.06624f,-1.30141e-06f,1.06624f,-5.69819e-17f,0.586529f,4.64342e-05f, 1.06603f,0.0150588f,1.06637f,-0.0104218f,0.586534f,4.68713e-05f,
1.06534f,0.0299512f,1.06665f,-0.0204601f,0.586693f,4.84063e-05f, 1.06437f,0.0448206f,1.06719f,-0.0304513f,0.586863f,5.07428e-05f,
1.06329f,0.0596577f,1.06802f,-0.0404264f,0.587019f,5.38742e-05f, 1.06236f,0.0744346f,1.06913f,-0.050386f,0.587161f,5.78566e-05f,
1.06168f,0.0891442f,1.07052f,-0.0603264f,0.587288f,6.27559e-05f, 1.06132f,0.103787f,1.07222f,-0.0702445f,0.587396f,6.86387e-05f,
1.06128f,0.118343f,1.07422f,-0.0801362f,0.587487f,7.55944e-05f, 1.06162f,0.132821f,1.07654f,-0.0899974f,0.58756f,8.3726e-05f,
1.06172f,0.147205f,1.07929f,-0.0998401f,0.587632f,9.3214e-05f, 1.06207f,0.161525f,1.08228f,-0.109795f,0.587755f,0.000104675f,
1.06289f,0.175709f,1.08545f,-0.119759f,0.587888f,0.000118096f, 1.06479f,0.189784f,1.0889f,-0.129748f,0.588044f,0.00013385f,
1.06721f,0.203637f,1.09202f,-0.139482f,0.588275f,0.000151983f, 1.06914f,0.217685f,1.09591f,-0.149025f,0.588563f,0.000172776f,
1.07019f,0.23184f,1.1002f,-0.158449f,0.588882f,0.000196566f, 1.07199f,0.246229f,1.10571f,-0.16779f,0.589258f,0.000223932f,
1.08638f,0.264126f,1.11592f,-0.177062f,0.589659f,0.000255179f, 1.07561f,0.275398f,1.11758f,-0.186224f,0.5901f,0.000290742f,
1.07567f,0.289794f,1.12425f,-0.195317f,0.590554f,0.00033125f, 1.07764f,0.304726f,1.13094f,-0.204388f,0.59109f,0.000378139f,
1.0778f,0.319217f,1.13809f,-0.213376f,0.591652f,0.000431581f, 1.07933f,0.334146f,1.14548f,-0.222321f,0.592263f,0.000492997f,
1.08113f,0.349258f,1.15281f,-0.231154f,0.592936f,0.000562815f, 1.08304f,0.364441f,1.16081f,-0.239875f,0.593644f,0.000642082f,
1.08367f,0.379031f,1.16716f,-0.248503f,0.59441f,0.000732236f, 1.0838f,0.393447f,1.17411f,-0.25697f,0.595273f,0.000834511f,
1.08434f,0.408056f,1.18208f,-0.265034f,0.596305f,0.000950288f, 1.08493f,0.422561f,1.1902f,-0.272815f,0.597454f,0.00108119f,
1.08397f,0.436183f,1.19782f,-0.280346f,0.598718f,0.00122911f, 1.08184f,0.449298f,1.2073f,-0.287718f,0.600148f,0.00139692f,
1.08224f,0.463285f,1.21628f,-0.294955f,0.601717f,0.00158834f, 1.08226f,0.477023f,1.22549f,-0.302043f,0.603452f,0.00180589f,
1.08167f,0.490439f,1.23421f,-0.308948f,0.605336f,0.00205192f, 1.08029f,0.503195f,1.24348f,-0.315692f,0.607401f,0.00233025f,
1.07738f,0.514987f,1.25107f,-0.322226f,0.609638f,0.00264389f, 1.07983f,0.529672f,1.26071f,-0.328496f,0.612033f,0.00299638f,
1.07193f,0.538238f,1.26885f,-0.334487f,0.614591f,0.00339213f, 1.06982f,0.54982f,1.27923f,-0.340252f,0.617379f,0.00383748f,
1.06793f,0.561115f,1.28909f,-0.345699f,0.620499f,0.00434248f, 1.06441f,0.571013f,1.29884f,-0.3504f,0.624134f,0.00491013f,
1.07425f,0.588561f,1.30779f,-0.354597f,0.628135f,0.00554471f, 1.05619f,0.588687f,1.3159f,-0.358433f,0.632502f,0.00625842f,
1.05245f,0.596848f,1.32609f,-0.362127f,0.637358f,0.00706516f, 1.04732f,0.604142f,1.3354f,-0.365432f,0.64259f,0.00796304f,
1.05429f,0.61848f,1.34227f,-0.36855f,0.648295f,0.00898573f, 1.05475f,0.628462f,1.35218f,-0.371413f,0.654488f,0.0101391f,
1.03308f,0.623263f,1.35957f,-0.373891f,0.661165f,0.0114232f, 1.02696f,0.627679f,1.36697f,-0.375348f,0.668695f,0.0128691f,
1.0262f,0.63413f,1.3737f,-0.375803f,0.677481f,0.0144888f, 1.02727f,0.641869f,1.38109f,-0.376193f,0.687202f,0.0163339f,
1.02737f,0.648157f,1.38894f,-0.376231f,0.697701f,0.0183976f, 0.998779f,0.634408f,1.3922f,-0.376135f,0.709122f,0.0207425f,
0.996555f,0.638389f,1.39891f,-0.375297f,0.721485f,0.0233742f, 0.976554f,0.627137f,1.40069f,-0.372656f,0.736796f,0.0263641f,
0.967173f,0.623472f,1.40204f,-0.37016f,0.753594f,0.0297624f, 0.952586f,0.616428f,1.40613f,-0.367487f,0.771701f,0.033642f,
0.94056f,0.609f,1.40618f,-0.363211f,0.793097f,0.0380554f, 0.927637f,0.600231f,1.39955f,-0.358322f,0.818662f,0.0431711f,
0.910214f,0.589257f,1.39586f,-0.353277f,0.846044f,0.0490829f, 0.891804f,0.573399f,1.38195f,-0.346481f,0.883923f,0.0563804f,
0.870265f,0.557828f,1.36419f,-0.339696f,0.925669f,0.0649485f, 0.836862f,0.524354f,1.30638f,-0.330217f,0.997458f,0.0765864f,
1.04372f,1.24089e-06f,1.04373f,-3.29055e-17f,0.564507f,4.77033e-05f, 1.04355f,0.0136122f,1.04383f,-0.00924355f,0.564502f,4.80513e-05f,
1.04304f,0.02722f,1.04417f,-0.018484f,0.56449f,4.90994e-05f, 1.04226f,0.0408181f,1.04475f,-0.0277184f,0.56447f,5.086e-05f,
1.04139f,0.0543872f,1.04556f,-0.0369435f,0.564443f,5.3354e-05f, 1.04037f,0.0679244f,1.04664f,-0.0462183f,0.564433f,5.67101e-05f,
1.03955f,0.0814687f,1.0479f,-0.0556744f,0.564496f,6.12704e-05f, 1.03898f,0.0949599f,1.04938f,-0.0651662f,0.564584f,6.69759e-05f,
1.03869f,0.108286f,1.05104f,-0.0744221f,0.564772f,7.39324e-05f, 1.03862f,0.121459f,1.05285f,-0.0835352f,0.565012f,8.21727e-05f,
1.03892f,0.134555f,1.05495f,-0.0925868f,0.565297f,9.18741e-05f, 1.03953f,0.147515f,1.05727f,-0.101583f,0.565595f,0.000103113f,
1.04057f,0.160344f,1.05984f,-0.11051f,0.56592f,0.000116083f, 1.04205f,0.172993f,1.06262f,-0.119397f,0.566246f,0.000130956f,
1.04403f,0.185547f,1.06574f,-0.128222f,0.566606f,0.000148005f, 1.04641f,0.198134f,1.06862f,-0.136997f,0.566972f,0.000167449f,
1.04681f,0.210858f,1.07242f,-0.145784f,0.567372f,0.000189965f, 1.04695f,0.223631f,1.07668f,-0.154579f,0.56784f,0.000216102f,
1.04858f,0.236733f,1.08165f,-0.163354f,0.568339f,0.000246182f, 1.05568f,0.251173f,1.08906f,-0.172058f,0.568855f,0.000280441f,
1.0517f,0.263093f,1.09266f,-0.180648f,0.569412f,0.000319432f, 1.05189f,0.276057f,1.09818f,-0.188962f,0.570125f,0.000364067f,
1.05342f,0.289308f,1.10417f,-0.197102f,0.570924f,0.000414922f, 1.05486f,0.302591f,1.11025f,-0.205083f,0.571789f,0.000472602f,
1.0559f,0.315705f,1.1167f,-0.212924f,0.572713f,0.000537965f, 1.05762f,0.329097f,1.12383f,-0.220634f,0.573739f,0.00061216f,
1.05881f,0.34232f,1.1302f,-0.22828f,0.574855f,0.000696643f, 1.0582f,0.354993f,1.13742f,-0.235808f,0.576074f,0.000792673f,
1.05781f,0.367425f,1.14264f,-0.243248f,0.577368f,0.000902079f, 1.0572f,0.379705f,1.14848f,-0.250547f,0.578772f,0.00102584f,
1.05738f,0.392405f,1.15627f,-0.257715f,0.580265f,0.00116586f, 1.05728f,0.404906f,1.16358f,-0.264778f,0.581886f,0.00132449f,
1.05611f,0.41677f,1.17041f,-0.271682f,0.583628f,0.00150349f, 1.05555f,0.428855f,1.17789f,-0.278332f,0.585488f,0.00170505f,
1.06431f,0.445979f,1.18543f,-0.284454f,0.587626f,0.00193218f, 1.05405f,0.451971f,1.19344f,-0.29024f,0.589994f,0.00218793f,
1.05301f,0.463024f,1.20142f,-0.295899f,0.592646f,0.00247996f, 1.05279f,0.474253f,1.20899f,-0.301369f,0.595546f,0.00281086f,
1.0689f,0.490629f,1.21834f,-0.306653f,0.598702f,0.00318363f, 1.06542f,0.503361f,1.22522f,-0.311656f,0.602062f,0.00360135f,
1.04297f,0.50224f,1.22994f,-0.316357f,0.605635f,0.00406866f, 1.05508f,0.519347f,1.24001f,-0.320966f,0.609551f,0.00459784f,
1.03558f,0.518818f,1.24547f,-0.325335f,0.613745f,0.00519237f, 1.03307f,0.527402f,1.25357f,-0.329476f,0.618263f,0.00586033f,
1.02819f,0.534185f,1.26111f,-0.332706f,0.623311f,0.00660685f, 1.02369f,0.540223f,1.26916f,-0.335337f,0.629078f,0.00744736f,
1.02335f,0.548343f,1.2736f,-0.337796f,0.635432f,0.00840417f, 1.03002f,0.56071f,1.28216f,-0.339995f,0.642307f,0.00947967f,
1.00902f,0.555541f,1.28777f,-0.341951f,0.649726f,0.0106802f, 1.0053f,0.560526f,1.29388f,-0.343769f,0.65775f,0.0120419f,
0.999875f,0.564267f,1.30034f,-0.345137f,0.666278f,0.0135606f, 0.993879f,0.566285f,1.30453f,-0.345234f,0.676388f,0.0152986f,
0.986052f,0.566413f,1.31006f,-0.344697f,0.687657f,0.017223f, 0.985326f,0.571016f,1.31385f,-0.344443f,0.70003f,0.0194515f,
0.9832f,0.574455f,1.31808f,-0.3437f,0.713181f,0.0219272f, 0.97169f,0.571063f,1.31976f,-0.342165f,0.727985f,0.0247723f,
0.963752f,0.56687f,1.32035f,-0.33937f,0.74577f,0.0279848f, 0.956724f,0.566017f,1.32077f,-0.336895f,0.765065f,0.0316941f,
0.947322f,0.56217f,1.32003f,-0.333584f,0.786096f,0.0358902f, 0.911603f,0.538036f,1.30585f,-0.328862f,0.813044f,0.0408185f,
0.894137f,0.527849f,1.29841f,-0.324311f,0.841896f,0.0465467f, 0.876303f,0.5143f,1.28317f,-0.318264f,0.880103f,0.0535651f,
0.855563f,0.500478f,1.26272f,-0.312095f,0.923754f,0.0619291f, 0.832825f,0.476155f,1.21276f,-0.30347f,0.997346f,0.0734038f,
1.02402f,-2.91197e-07f,1.02403f,-7.23551e-17f,0.541403f,4.59263e-05f, 1.02383f,0.0125295f,1.02412f,-0.00886448f,0.541403f,4.63039e-05f,
1.02325f,0.0249715f,1.02434f,-0.0175324f,0.541477f,4.75654e-05f, 1.02235f,0.0373228f,1.02469f,-0.0259794f,0.54165f,4.97162e-05f,
1.02133f,0.0496294f,1.02524f,-0.0343964f,0.541843f,5.26344e-05f, 1.02035f,0.0618869f,1.02597f,-0.0427926f,0.54205f,5.63575e-05f,
1.01959f,0.0740693f,1.0269f,-0.0511731f,0.542262f,6.09299e-05f, 1.01903f,0.0861773f,1.02804f,-0.0595335f,0.54249f,6.64468e-05f,
1.01873f,0.0982136f,1.02943f,-0.0678732f,0.542725f,7.29698e-05f, 1.01867f,0.110154f,1.03101f,-0.0761896f,0.542968f,8.05974e-05f,
1.01891f,0.122006f,1.03283f,-0.0844796f,0.543219f,8.94438e-05f, 1.01826f,0.133795f,1.03505f,-0.0928461f,0.543529f,9.99879e-05f,
1.0189f,0.145484f,1.03728f,-0.101261f,0.543884f,0.000112416f, 1.01932f,0.157045f,1.0397f,-0.10967f,0.544266f,0.000126826f,
1.02059f,0.168448f,1.04232f,-0.117991f,0.544705f,0.000143489f, 1.02216f,0.179692f,1.04515f,-0.126065f,0.545239f,0.000162579f,
1.02404f,0.190921f,1.04763f,-0.133997f,0.545837f,0.000184386f, 1.02544f,0.202269f,1.05084f,-0.141837f,0.546499f,0.000209307f,
1.02666f,0.213711f,1.05455f,-0.149607f,0.547209f,0.00023771f, 1.02712f,0.225196f,1.0584f,-0.157287f,0.54799f,0.000270082f,
1.02836f,0.236803f,1.06294f,-0.164908f,0.548805f,0.000306867f, 1.02934f,0.248367f,1.06772f,-0.172437f,0.54969f,0.000348622f,
1.02865f,0.259683f,1.07287f,-0.179892f,0.550617f,0.000395963f, 1.02979f,0.271384f,1.07807f,-0.18733f,0.551626f,0.00045037f,
1.03106f,0.28317f,1.08398f,-0.194704f,0.552721f,0.00051224f, 1.03215f,0.294935f,1.08955f,-0.201998f,0.553878f,0.000582393f,
1.03196f,0.306271f,1.09611f,-0.209242f,0.555124f,0.000662437f, 1.03276f,0.317836f,1.1018f,-0.216221f,0.556539f,0.000753346f,
1.03334f,0.329246f,1.10745f,-0.22287f,0.55811f,0.00085609f, 1.03378f,0.340542f,1.11319f,-0.229295f,0.559807f,0.000972117f,
1.03298f,0.351085f,1.11771f,-0.235577f,0.561672f,0.00110346f, 1.04311f,0.366303f,1.12633f,-0.241735f,0.563684f,0.0012523f,
1.03156f,0.37211f,1.12897f,-0.247738f,0.565845f,0.00142038f, 1.03084f,0.382504f,1.13559f,-0.253574f,0.568144f,0.00160966f,
1.03122f,0.393345f,1.14206f,-0.259309f,0.570627f,0.00182358f, 1.02757f,0.402052f,1.14735f,-0.264865f,0.573272f,0.00206396f,
1.02603f,0.411778f,1.15371f,-0.270208f,0.57606f,0.00233354f, 1.03027f,0.423981f,1.16162f,-0.275356f,0.579023f,0.00263603f,
1.02499f,0.431149f,1.16778f,-0.280362f,0.582326f,0.00298105f, 1.02428f,0.440326f,1.1737f,-0.284762f,0.586069f,0.00337252f,
1.02126f,0.448224f,1.1796f,-0.288862f,0.590201f,0.00381358f, 1.01996f,0.456642f,1.18604f,-0.292612f,0.594609f,0.00430562f,
1.01491f,0.462658f,1.19221f,-0.296167f,0.599361f,0.00485862f, 1.02425f,0.476348f,1.19995f,-0.299612f,0.604503f,0.00548131f,
1.00623f,0.474811f,1.20251f,-0.302862f,0.609995f,0.00618296f, 1.00522f,0.482537f,1.20932f,-0.305798f,0.615827f,0.00696233f,
1.01476f,0.495642f,1.21572f,-0.308702f,0.622186f,0.00785919f, 0.993664f,0.490515f,1.21699f,-0.31043f,0.629563f,0.00887153f,
0.987074f,0.493235f,1.2223f,-0.311621f,0.637589f,0.00998886f, 0.982926f,0.496945f,1.22614f,-0.312885f,0.646355f,0.0112627f,
0.976852f,0.499513f,1.23036f,-0.314016f,0.655763f,0.0127018f, 0.972309f,0.502428f,1.23459f,-0.314998f,0.665832f,0.0143294f,
0.964561f,0.502989f,1.2369f,-0.314711f,0.677118f,0.0161439f, 0.957144f,0.502363f,1.23902f,-0.313951f,0.690315f,0.0182421f,
0.950234f,0.502125f,1.23954f,-0.313104f,0.704478f,0.0205917f, 0.946048f,0.503523f,1.24202f,-0.312279f,0.719667f,0.023288f,
0.938392f,0.501299f,1.24273f,-0.309752f,0.737531f,0.0263407f, 0.93097f,0.499021f,1.23891f,-0.307302f,0.758011f,0.0298864f,
0.907969f,0.487104f,1.23132f,-0.30469f,0.77977f,0.0339147f, 0.894777f,0.478972f,1.22376f,-0.300226f,0.807095f,0.0386111f,
0.87744f,0.469579f,1.21286f,-0.296128f,0.837495f,0.0441724f, 0.859865f,0.457851f,1.19616f,-0.290785f,0.876098f,0.0509293f,
0.836502f,0.44366f,1.17002f,-0.285189f,0.921745f,0.0591092f, 0.79845f,0.413609f,1.10713f,-0.277375f,0.997231f,0.0704389f,
1.0054f,-1.11742e-06f,1.0054f,5.62487e-18f,0.519557f,4.64119e-05f, 1.00524f,0.0111324f,1.00547f,-0.00766654f,0.519565f,4.67384e-05f,
1.0048f,0.0222645f,1.00568f,-0.0153315f,0.51959f,4.77221e-05f, 1.0041f,0.0333808f,1.00604f,-0.0229934f,0.519632f,4.93761e-05f,
1.00325f,0.0444837f,1.00657f,-0.0306505f,0.519691f,5.17221e-05f, 1.00217f,0.055595f,1.00726f,-0.0384147f,0.519807f,5.49575e-05f,
1.00125f,0.0667038f,1.00806f,-0.0463086f,0.519993f,5.92476e-05f, 1.00052f,0.0777476f,1.00903f,-0.0542377f,0.520219f,6.45794e-05f,
1.00001f,0.0887058f,1.01019f,-0.0621342f,0.520469f,7.09706e-05f, 0.999649f,0.0994966f,1.0114f,-0.0697961f,0.520827f,7.85946e-05f,
0.999463f,0.110163f,1.01279f,-0.0773422f,0.521255f,8.75399e-05f, 0.999514f,0.120725f,1.01436f,-0.0848078f,0.521734f,9.79103e-05f,
0.99977f,0.131164f,1.01609f,-0.0922226f,0.522252f,0.000109857f, 1.00028f,0.141486f,1.01796f,-0.0995808f,0.522816f,0.000123572f,
1.00109f,0.151661f,1.02002f,-0.106901f,0.523413f,0.000139258f, 1.00221f,0.161687f,1.02225f,-0.114172f,0.524062f,0.000157173f,
1.00358f,0.171645f,1.02474f,-0.121403f,0.524742f,0.000177564f, 1.01596f,0.182978f,1.03205f,-0.128618f,0.525482f,0.000200933f,
1.00533f,0.191694f,1.02966f,-0.135834f,0.526287f,0.000227819f, 1.00499f,0.201837f,1.03317f,-0.143034f,0.527145f,0.000258617f,
1.00577f,0.211997f,1.03665f,-0.150201f,0.528058f,0.000293769f, 1.00659f,0.222189f,1.04059f,-0.157171f,0.529093f,0.000333751f,
1.00777f,0.232392f,1.04515f,-0.163878f,0.530256f,0.000379104f, 1.00815f,0.24241f,1.04935f,-0.170459f,0.531523f,0.000430669f,
1.00877f,0.25254f,1.05393f,-0.176918f,0.532885f,0.000489111f, 1.00929f,0.262625f,1.05837f,-0.183289f,0.534376f,0.000555483f,
1.00975f,0.272639f,1.06297f,-0.189562f,0.53595f,0.000630543f, 1.01015f,0.282622f,1.06766f,-0.195724f,0.537629f,0.000715388f,
1.01605f,0.294493f,1.07411f,-0.201785f,0.539398f,0.000811215f, 1.01041f,0.302223f,1.07791f,-0.207775f,0.541305f,0.000919775f,
1.01049f,0.311991f,1.08284f,-0.213676f,0.543319f,0.00104244f, 1.0104f,0.321639f,1.08781f,-0.219477f,0.545477f,0.00118086f,
1.01115f,0.331432f,1.09329f,-0.225153f,0.547749f,0.00133707f, 1.00959f,0.340034f,1.09694f,-0.230396f,0.550311f,0.00151404f,
1.01573f,0.351791f,1.1041f,-0.23539f,0.553151f,0.00171448f, 1.00629f,0.356763f,1.10602f,-0.240151f,0.556205f,0.00194012f,
1.00451f,0.364866f,1.11136f,-0.244728f,0.559483f,0.0021938f, 1.00235f,0.372674f,1.11623f,-0.249146f,0.562993f,0.00247869f,
1.00752f,0.383749f,1.12298f,-0.25335f,0.566698f,0.00279727f, 0.997862f,0.387421f,1.12663f,-0.257421f,0.570639f,0.00315624f,
0.998269f,0.395776f,1.13093f,-0.261604f,0.57496f,0.00356808f, 0.995192f,0.402509f,1.1365f,-0.265598f,0.579512f,0.00403162f,
0.991234f,0.408427f,1.14143f,-0.268936f,0.584516f,0.00454886f, 0.987789f,0.414005f,1.14606f,-0.271552f,0.590064f,0.00512706f,
0.985001f,0.419558f,1.15063f,-0.274117f,0.596168f,0.00578255f, 0.981972f,0.424801f,1.15401f,-0.276455f,0.602671f,0.00651513f,
0.979194f,0.429914f,1.15835f,-0.278797f,0.609668f,0.00735206f, 0.979787f,0.436675f,1.16394f,-0.281088f,0.617158f,0.00829824f,
0.968583f,0.437077f,1.16664f,-0.28298f,0.625103f,0.00934778f, 0.969281f,0.442396f,1.16874f,-0.283534f,0.63434f,0.0105374f,
0.971512f,0.448733f,1.1738f,-0.284187f,0.644539f,0.0118968f, 0.973279f,0.454463f,1.17666f,-0.284704f,0.655415f,0.0134183f,
0.945301f,0.443749f,1.17261f,-0.285259f,0.667058f,0.0151484f, 0.938376f,0.443868f,1.17314f,-0.284746f,0.680093f,0.0171152f,
0.932278f,0.443449f,1.17279f,-0.283609f,0.695226f,0.0193517f, 0.928916f,0.444944f,1.17315f,-0.282586f,0.711414f,0.0218913f,
0.924572f,0.445838f,1.1734f,-0.281265f,0.728931f,0.0248118f, 0.915677f,0.442012f,1.16919f,-0.278559f,0.750519f,0.0281874f,
0.88846f,0.428615f,1.15467f,-0.276145f,0.77357f,0.0320623f, 0.87559f,0.422012f,1.14625f,-0.272347f,0.800828f,0.0365379f,
0.85735f,0.412839f,1.1315f,-0.268665f,0.83285f,0.0419479f, 0.839105f,0.402364f,1.11262f,-0.263985f,0.871914f,0.0484596f,
0.813433f,0.388297f,1.08168f,-0.258923f,0.919644f,0.056474f, 0.775226f,0.361559f,1.01881f,-0.25188f,0.997112f,0.0676759f,
0.988899f,1.86624e-06f,0.988902f,-7.20196e-17f,0.497291f,4.48913e-05f, 0.98875f,0.0100998f,0.988961f,-0.00725111f,0.497302f,4.52395e-05f,
0.988285f,0.0201941f,0.98913f,-0.0145005f,0.497336f,4.62892e-05f, 0.987554f,0.0302008f,0.989384f,-0.0215658f,0.497455f,4.81459e-05f,
0.986639f,0.0401185f,0.989716f,-0.0284512f,0.497668f,5.08108e-05f, 0.98568f,0.0499913f,0.990163f,-0.03529f,0.497932f,5.42457e-05f,
0.984824f,0.0597971f,0.990733f,-0.0421079f,0.498233f,5.8484e-05f, 0.984101f,0.0695371f,0.991439f,-0.0489075f,0.49857f,6.35869e-05f,
0.983544f,0.0792099f,0.992314f,-0.0556926f,0.498939f,6.96289e-05f, 0.983117f,0.0888127f,0.993311f,-0.062461f,0.499351f,7.67207e-05f,
0.982871f,0.0983322f,0.994467f,-0.0692131f,0.499795f,8.49486e-05f, 0.982375f,0.107789f,0.995861f,-0.0759776f,0.500283f,9.45232e-05f,
0.98193f,0.117191f,0.997375f,-0.0828148f,0.500844f,0.000105835f, 0.982063f,0.126488f,0.998945f,-0.0896585f,0.501458f,0.000118935f,
0.98194f,0.135685f,1.00064f,-0.096494f,0.502117f,0.000134007f, 0.982444f,0.144746f,1.00252f,-0.103288f,0.502837f,0.000151341f,
0.983086f,0.153609f,1.00443f,-0.109825f,0.503676f,0.000171128f, 0.98392f,0.162369f,1.00657f,-0.116237f,0.504612f,0.000193716f,
0.98491f,0.17109f,1.00884f,-0.122558f,0.505634f,0.000219444f, 0.986084f,0.179721f,1.01063f,-0.128808f,0.506726f,0.000248666f,
0.986824f,0.188455f,1.01286f,-0.134978f,0.507898f,0.000281828f, 0.987633f,0.197281f,1.01591f,-0.14109f,0.50914f,0.000319425f,
0.987702f,0.205969f,1.01865f,-0.147135f,0.510462f,0.00036202f, 0.988201f,0.214806f,1.02235f,-0.153156f,0.511874f,0.000410443f,
0.988604f,0.223603f,1.02586f,-0.159124f,0.513388f,0.000465319f, 0.98869f,0.232267f,1.02947f,-0.165026f,0.514972f,0.000527338f,
0.988919f,0.241024f,1.03329f,-0.170869f,0.516657f,0.00059749f, 0.989009f,0.249664f,1.03707f,-0.176555f,0.518467f,0.00067673f,
0.988855f,0.258117f,1.04081f,-0.181861f,0.520471f,0.000766102f, 0.989103f,0.266562f,1.04545f,-0.187034f,0.522675f,0.000867665f,
0.98677f,0.274275f,1.04948f,-0.192086f,0.525054f,0.000982664f, 0.991909f,0.28428f,1.05545f,-0.196989f,0.527573f,0.00111204f,
0.985256f,0.290073f,1.05787f,-0.201765f,0.530236f,0.00125758f, 0.985769f,0.298242f,1.06193f,-0.206489f,0.533108f,0.00142224f,
0.986565f,0.306411f,1.06552f,-0.211115f,0.536137f,0.00160796f, 0.98618f,0.31415f,1.06994f,-0.215694f,0.539363f,0.00181863f,
0.988255f,0.322833f,1.07575f,-0.220222f,0.542796f,0.00205678f, 0.982445f,0.328026f,1.07703f,-0.224525f,0.546491f,0.00232494f,
0.984471f,0.336284f,1.08267f,-0.228147f,0.550572f,0.00262486f, 0.998861f,0.349524f,1.09012f,-0.231481f,0.55499f,0.00296057f,
0.973791f,0.345667f,1.08721f,-0.2346f,0.559692f,0.00333629f, 0.973906f,0.352309f,1.09099f,-0.237899f,0.564832f,0.00377088f,
0.970097f,0.357446f,1.09452f,-0.241073f,0.570285f,0.004258f, 0.970311f,0.364018f,1.09614f,-0.243993f,0.575998f,0.00479861f,
0.981439f,0.375714f,1.10661f,-0.246791f,0.582047f,0.00540438f, 0.960357f,0.371618f,1.10402f,-0.248814f,0.588923f,0.00609617f,
0.956295f,0.375204f,1.10583f,-0.250453f,0.596504f,0.00688073f, 0.952516f,0.378607f,1.10907f,-0.25203f,0.604646f,0.00776042f,
0.948683f,0.382101f,1.11244f,-0.25355f,0.613311f,0.00874629f, 0.944297f,0.384754f,1.11285f,-0.255027f,0.622508f,0.00986602f,
0.937144f,0.385831f,1.11456f,-0.255811f,0.632787f,0.0111458f, 0.930377f,0.38637f,1.11449f,-0.25566f,0.644384f,0.0125686f,
0.925441f,0.387596f,1.11528f,-0.255929f,0.656943f,0.0142105f, 0.919352f,0.388362f,1.11471f,-0.25612f,0.670226f,0.0160624f,
0.912188f,0.387655f,1.11262f,-0.255168f,0.685466f,0.018191f, 0.905659f,0.38661f,1.10932f,-0.25381f,0.702656f,0.0205846f,
0.893643f,0.383598f,1.10559f,-0.252969f,0.721073f,0.0233879f, 0.884854f,0.380563f,1.10035f,-0.250602f,0.742609f,0.0265891f,
0.873188f,0.376193f,1.09113f,-0.248341f,0.767011f,0.0303216f, 0.859579f,0.370575f,1.08196f,-0.245296f,0.794319f,0.0346174f,
0.843944f,0.363213f,1.06534f,-0.241861f,0.827971f,0.0398618f, 0.828923f,0.355584f,1.04787f,-0.237807f,0.867557f,0.0461433f,
0.81302f,0.34743f,1.02343f,-0.233245f,0.917456f,0.0540096f, 0.779627f,0.324631f,0.968708f,-0.226939f,0.996989f,0.0651001f,
0.973575f,-2.02496e-06f,0.973573f,-4.31626e-17f,0.475898f,4.4579e-05f, 0.973454f,0.00877073f,0.973611f,-0.00610012f,0.475918f,4.48827e-05f,
0.973109f,0.0175424f,0.973737f,-0.0122003f,0.475978f,4.57983e-05f, 0.972542f,0.0263094f,0.973952f,-0.0183005f,0.476079f,4.73392e-05f,
0.971772f,0.0350694f,0.97426f,-0.0244149f,0.476226f,4.95438e-05f, 0.970795f,0.0438944f,0.974631f,-0.0307f,0.476469f,5.26631e-05f,
0.969811f,0.0526964f,0.975082f,-0.0370352f,0.476773f,5.66613e-05f, 0.968948f,0.0614457f,0.97565f,-0.0433792f,0.477123f,6.15644e-05f,
0.968177f,0.0701331f,0.976291f,-0.0497185f,0.477516f,6.7437e-05f, 0.967549f,0.0787507f,0.977084f,-0.0560609f,0.477957f,7.43951e-05f,
0.967032f,0.0872553f,0.977972f,-0.0622753f,0.478476f,8.25396e-05f, 0.966609f,0.0956226f,0.978932f,-0.0682908f,0.479102f,9.20036e-05f,
0.966293f,0.103877f,0.979989f,-0.074225f,0.479801f,0.00010291f, 0.966071f,0.11204f,0.981128f,-0.0801032f,0.480565f,0.00011542f,
0.965969f,0.120113f,0.98238f,-0.0859257f,0.481403f,0.000129735f, 0.96601f,0.128063f,0.983742f,-0.0917211f,0.482296f,0.000146055f,
0.966164f,0.13591f,0.98518f,-0.0974743f,0.483265f,0.000164654f, 0.966521f,0.143615f,0.98674f,-0.103201f,0.484288f,0.000185781f,
0.966994f,0.151203f,0.988399f,-0.108897f,0.48539f,0.000209802f, 0.967833f,0.158779f,0.990475f,-0.114571f,0.486562f,0.00023709f,
0.967314f,0.166385f,0.992714f,-0.120225f,0.487801f,0.000268078f, 0.968191f,0.17384f,0.994223f,-0.125903f,0.489147f,0.000303615f,
0.968601f,0.181307f,0.996049f,-0.131438f,0.490597f,0.000343849f, 0.968643f,0.188774f,0.998491f,-0.136684f,0.492203f,0.000389363f,
0.968546f,0.196104f,1.00086f,-0.141802f,0.493949f,0.000440936f, 0.968299f,0.203457f,1.00349f,-0.146823f,0.495823f,0.000499281f,
0.96801f,0.210755f,1.00623f,-0.151747f,0.497807f,0.000565126f, 0.967629f,0.217958f,1.00898f,-0.156577f,0.499916f,0.000639399f,
0.967885f,0.225152f,1.01264f,-0.161391f,0.502163f,0.000723634f, 0.96731f,0.232245f,1.01556f,-0.166185f,0.504564f,0.000819257f,
0.966631f,0.239277f,1.01862f,-0.170905f,0.507085f,0.000926945f, 0.965831f,0.246175f,1.02168f,-0.175546f,0.509743f,0.00104814f,
0.965417f,0.253102f,1.02553f,-0.180128f,0.51254f,0.00118486f, 0.964159f,0.259609f,1.02843f,-0.184302f,0.515664f,0.00133934f,
0.962715f,0.26587f,1.03124f,-0.188125f,0.519021f,0.00151236f, 0.965683f,0.273372f,1.03602f,-0.191781f,0.522614f,0.00170665f,
0.96036f,0.278051f,1.03757f,-0.19539f,0.526463f,0.00192689f, 0.961124f,0.284575f,1.04057f,-0.198976f,0.530562f,0.00217651f,
0.959234f,0.290273f,1.04387f,-0.202534f,0.534915f,0.00245884f, 0.956715f,0.295687f,1.04678f,-0.206016f,0.539522f,0.00277512f,
0.953996f,0.300795f,1.0499f,-0.20931f,0.544325f,0.00312717f, 0.954745f,0.306643f,1.05267f,-0.212034f,0.549634f,0.00352493f,
0.962491f,0.315336f,1.05909f,-0.214481f,0.55555f,0.0039823f, 0.945922f,0.31397f,1.05526f,-0.216758f,0.561868f,0.00449162f,
0.944119f,0.318608f,1.05816f,-0.218795f,0.568507f,0.00505413f, 0.953879f,0.323444f,1.06105f,-0.221057f,0.575646f,0.00570169f,
0.936606f,0.325287f,1.05988f,-0.223402f,0.58323f,0.00644205f, 0.93033f,0.327301f,1.0605f,-0.224538f,0.59157f,0.00725758f,
0.925981f,0.32954f,1.06156f,-0.225388f,0.600891f,0.00818226f, 0.922613f,0.332005f,1.06198f,-0.226494f,0.610918f,0.00924791f,
0.917162f,0.333658f,1.06262f,-0.227551f,0.6215f,0.0104402f, 0.912463f,0.335274f,1.06119f,-0.228129f,0.632967f,0.0117923f,
0.905534f,0.335168f,1.0606f,-0.227704f,0.646263f,0.013333f, 0.905296f,0.338069f,1.06062f,-0.227644f,0.660517f,0.015088f,
0.905932f,0.341613f,1.05671f,-0.227804f,0.675629f,0.017111f, 0.899059f,0.34044f,1.05825f,-0.226076f,0.6935f,0.0193858f,
0.871495f,0.329905f,1.04333f,-0.225087f,0.713035f,0.0220481f, 0.861707f,0.327448f,1.03676f,-0.223517f,0.734365f,0.0251009f,
0.850114f,0.323166f,1.0257f,-0.22122f,0.760107f,0.0286842f, 0.834397f,0.31802f,1.01304f,-0.218975f,0.78756f,0.0328239f,
0.818668f,0.311094f,0.995269f,-0.215665f,0.822867f,0.0379037f, 0.800378f,0.303538f,0.974321f,-0.212203f,0.863032f,0.043969f,
0.77865f,0.29392f,0.944563f,-0.208106f,0.915183f,0.0517034f, 0.737264f,0.272393f,0.885445f,-0.202509f,0.996862f,0.0626979f,
0.959764f,-2.90247e-07f,0.959768f,-4.36676e-17f,0.454721f,4.33495e-05f, 0.959655f,0.00778873f,0.959799f,-0.00565817f,0.454743f,4.36683e-05f,
0.959308f,0.0155767f,0.959886f,-0.0113162f,0.45481f,4.46292e-05f, 0.958767f,0.0233588f,0.960049f,-0.0169739f,0.454921f,4.62467e-05f,
0.958043f,0.0311062f,0.960272f,-0.0225765f,0.455094f,4.85655e-05f, 0.957211f,0.0387369f,0.960521f,-0.0279583f,0.455384f,5.16729e-05f,
0.956347f,0.0463254f,0.960838f,-0.0332713f,0.455751f,5.55473e-05f, 0.955513f,0.05385f,0.961221f,-0.038549f,0.456186f,6.02356e-05f,
0.954758f,0.0613216f,0.961683f,-0.0438122f,0.456679f,6.57978e-05f, 0.954071f,0.0687345f,0.96222f,-0.0490614f,0.457233f,7.232e-05f,
0.953469f,0.0760926f,0.962866f,-0.0543027f,0.457846f,7.99019e-05f, 0.952961f,0.0833972f,0.963579f,-0.0595351f,0.458524f,8.86731e-05f,
0.952183f,0.0906487f,0.964444f,-0.0647696f,0.459261f,9.87756e-05f, 0.951431f,0.0978385f,0.965392f,-0.0700457f,0.460074f,0.000110513f,
0.951036f,0.104985f,0.966372f,-0.0753598f,0.460971f,0.000124117f, 0.95073f,0.112055f,0.967425f,-0.0806598f,0.461927f,0.000139641f,
0.950537f,0.119007f,0.968569f,-0.0859438f,0.462945f,0.000157322f, 0.950407f,0.125867f,0.96983f,-0.0911335f,0.46406f,0.000177473f,
0.950318f,0.132558f,0.971023f,-0.0961017f,0.465323f,0.000200418f, 0.949699f,0.139147f,0.972258f,-0.10096f,0.466695f,0.000226486f,
0.949657f,0.145591f,0.973529f,-0.10574f,0.468163f,0.000256016f, 0.949679f,0.151939f,0.974909f,-0.110444f,0.469734f,0.000289425f,
0.949781f,0.158233f,0.976548f,-0.115135f,0.47142f,0.000327382f, 0.950686f,0.164461f,0.97823f,-0.119786f,0.473203f,0.000370311f,
0.950906f,0.170593f,0.97923f,-0.124402f,0.475097f,0.000418872f, 0.950714f,0.17675f,0.980515f,-0.128974f,0.477085f,0.000473668f,
0.950188f,0.182945f,0.982505f,-0.133512f,0.479186f,0.000535516f, 0.966462f,0.191986f,0.99181f,-0.138065f,0.481421f,0.000605744f,
0.948995f,0.195097f,0.98681f,-0.142446f,0.483799f,0.000684837f, 0.947961f,0.200948f,0.988815f,-0.146483f,0.486429f,0.00077404f,
0.946704f,0.206629f,0.990727f,-0.150312f,0.489235f,0.000874203f, 0.945507f,0.21222f,0.993051f,-0.154024f,0.492212f,0.000986763f,
0.944609f,0.217719f,0.995457f,-0.157748f,0.495404f,0.00111456f, 0.942932f,0.223089f,0.997323f,-0.161386f,0.498766f,0.001258f,
0.94326f,0.228707f,0.999916f,-0.164999f,0.50232f,0.00142012f, 0.941431f,0.233889f,1.00206f,-0.16862f,0.506079f,0.00160324f,
0.939379f,0.238933f,1.00398f,-0.172158f,0.510023f,0.00180799f, 0.938567f,0.243968f,1.00645f,-0.1753f,0.514282f,0.00203875f,
0.938646f,0.248993f,1.00845f,-0.17808f,0.519004f,0.00230134f, 0.936019f,0.253286f,1.01043f,-0.180732f,0.524047f,0.00259755f,
0.932798f,0.25732f,1.01165f,-0.183355f,0.529416f,0.00292977f, 0.935697f,0.262964f,1.01506f,-0.185826f,0.535039f,0.00329838f,
0.929459f,0.265651f,1.01568f,-0.188487f,0.541041f,0.00372357f, 0.925266f,0.269079f,1.01661f,-0.19109f,0.547365f,0.00420107f,
0.920874f,0.271842f,1.0176f,-0.192615f,0.554436f,0.00473123f, 0.919838f,0.275267f,1.01864f,-0.193973f,0.562084f,0.00533144f,
0.916254f,0.278061f,1.01886f,-0.195737f,0.57036f,0.00602873f, 0.911041f,0.280229f,1.01921f,-0.197313f,0.579005f,0.00679708f,
0.910846f,0.283695f,1.01962f,-0.19877f,0.588128f,0.00766058f, 0.903569f,0.284363f,1.01802f,-0.199244f,0.598728f,0.00866886f,
0.897684f,0.285254f,1.01735f,-0.199655f,0.610061f,0.00978043f, 0.899799f,0.289104f,1.01869f,-0.200511f,0.622161f,0.0110722f,
0.900569f,0.289748f,1.02002f,-0.200682f,0.635141f,0.0125146f, 0.898176f,0.293728f,1.01891f,-0.200149f,0.65029f,0.0141866f,
0.897591f,0.295529f,1.01672f,-0.200019f,0.666393f,0.0160948f, 0.862376f,0.284136f,0.997692f,-0.199265f,0.683937f,0.0182691f,
0.854943f,0.28257f,0.990696f,-0.197989f,0.704597f,0.0208009f, 0.850591f,0.282792f,0.986361f,-0.19712f,0.726393f,0.023723f,
0.840275f,0.279339f,0.976484f,-0.19473f,0.752874f,0.0271424f, 0.832965f,0.27855f,0.967784f,-0.193036f,0.781521f,0.031171f,
0.798805f,0.265322f,0.937457f,-0.190026f,0.817545f,0.0360639f, 0.780842f,0.259324f,0.916511f,-0.187127f,0.858345f,0.0419257f,
0.754519f,0.249455f,0.883886f,-0.183465f,0.912827f,0.0495435f, 0.720399f,0.233235f,0.83238f,-0.178551f,0.996732f,0.0604566f,
0.947215f,2.4158e-06f,0.947214f,-1.79587e-17f,0.434041f,4.23054e-05f, 0.947127f,0.00654787f,0.947234f,-0.00458049f,0.434072f,4.25875e-05f,
0.946891f,0.0130947f,0.947295f,-0.00916243f,0.434165f,4.34382e-05f, 0.946485f,0.0196391f,0.9474f,-0.0137473f,0.43432f,4.4871e-05f,
0.945879f,0.0262214f,0.947532f,-0.018426f,0.434563f,4.70031e-05f, 0.945104f,0.0328431f,0.947683f,-0.0232021f,0.434897f,4.9915e-05f,
0.944236f,0.0394568f,0.947888f,-0.0279972f,0.435298f,5.3591e-05f, 0.943325f,0.0460398f,0.948138f,-0.0327917f,0.435761f,5.80685e-05f,
0.942429f,0.0525937f,0.948455f,-0.037594f,0.436289f,6.34348e-05f, 0.941583f,0.0590968f,0.948825f,-0.0423922f,0.436877f,6.97549e-05f,
0.940795f,0.0655439f,0.94927f,-0.0471862f,0.437526f,7.71264e-05f, 0.940071f,0.0719445f,0.949778f,-0.0519758f,0.438237f,8.56618e-05f,
0.939369f,0.0782476f,0.950345f,-0.0566596f,0.439039f,9.55015e-05f, 0.938703f,0.0844195f,0.950914f,-0.0611459f,0.439966f,0.000106801f,
0.938058f,0.0905205f,0.951547f,-0.0655533f,0.440987f,0.000119715f, 0.937473f,0.0965311f,0.952296f,-0.0699124f,0.442098f,0.000134441f,
0.936888f,0.10248f,0.953027f,-0.0742429f,0.443303f,0.000151235f, 0.936329f,0.108355f,0.953802f,-0.0785473f,0.4446f,0.000170325f,
0.935799f,0.114156f,0.954637f,-0.0828337f,0.445979f,0.000191974f, 0.935316f,0.11988f,0.955516f,-0.0871035f,0.447456f,0.000216534f,
0.934861f,0.125508f,0.956462f,-0.0913567f,0.449017f,0.000244319f, 0.934453f,0.131047f,0.957433f,-0.0956005f,0.450673f,0.000275771f,
0.934074f,0.136494f,0.958441f,-0.0998299f,0.452425f,0.000311319f, 0.933768f,0.141816f,0.959478f,-0.104034f,0.454262f,0.000351412f,
0.933812f,0.147009f,0.960768f,-0.108055f,0.4563f,0.000397091f, 0.933382f,0.152109f,0.961809f,-0.11184f,0.45851f,0.000448605f,
0.932852f,0.157125f,0.962874f,-0.115501f,0.460863f,0.000506612f, 0.940999f,0.161372f,0.9669f,-0.119128f,0.46338f,0.000572218f,
0.931944f,0.166903f,0.964665f,-0.122697f,0.466034f,0.000646023f, 0.930925f,0.171645f,0.965179f,-0.126207f,0.468837f,0.000728926f,
0.930922f,0.176477f,0.966937f,-0.129735f,0.471796f,0.000822806f, 0.9331f,0.181593f,0.969457f,-0.133299f,0.474928f,0.000929251f,
0.928073f,0.185858f,0.969237f,-0.13683f,0.478213f,0.0010487f, 0.926213f,0.190377f,0.97044f,-0.140109f,0.481698f,0.00118235f,
0.924768f,0.194638f,0.972078f,-0.142967f,0.485539f,0.00133327f, 0.923853f,0.198801f,0.973031f,-0.145709f,0.489654f,0.00150346f,
0.921696f,0.202812f,0.974398f,-0.148393f,0.494009f,0.00169537f, 0.926999f,0.206649f,0.978366f,-0.151086f,0.498627f,0.00191096f,
0.918939f,0.210658f,0.976195f,-0.153776f,0.503483f,0.00215359f, 0.916824f,0.214486f,0.977709f,-0.156572f,0.508613f,0.002431f,
0.913514f,0.21796f,0.978187f,-0.159185f,0.51408f,0.00274271f, 0.910146f,0.220981f,0.978814f,-0.160968f,0.520103f,0.00308926f,
0.908935f,0.224157f,0.979011f,-0.162722f,0.52658f,0.0034822f, 0.905392f,0.226975f,0.979468f,-0.164618f,0.533471f,0.00392873f,
0.902387f,0.229709f,0.979315f,-0.166543f,0.540725f,0.00442825f, 0.897713f,0.232069f,0.9793f,-0.168481f,0.548326f,0.00499077f,
0.895692f,0.234405f,0.97911f,-0.16958f,0.556915f,0.00564138f, 0.889818f,0.23581f,0.977868f,-0.17047f,0.566222f,0.00636312f,
0.888544f,0.238043f,0.976971f,-0.171508f,0.576063f,0.00717839f, 0.88257f,0.239448f,0.975491f,-0.172962f,0.58652f,0.00812695f,
0.876001f,0.239843f,0.972841f,-0.172944f,0.598082f,0.0091627f, 0.872751f,0.240936f,0.970845f,-0.173325f,0.611035f,0.0103918f,
0.874644f,0.24378f,0.972348f,-0.173701f,0.624589f,0.0117494f, 0.874515f,0.244972f,0.971044f,-0.173675f,0.639624f,0.0133453f,
0.850154f,0.239896f,0.957273f,-0.173f,0.656662f,0.0151351f, 0.841795f,0.239194f,0.950755f,-0.173014f,0.674736f,0.0172335f,
0.834357f,0.237654f,0.943749f,-0.171619f,0.695771f,0.0196371f, 0.822373f,0.235307f,0.933669f,-0.170677f,0.718818f,0.0224289f,
0.810411f,0.232302f,0.922863f,-0.168875f,0.745346f,0.025699f, 0.796461f,0.228847f,0.908277f,-0.167379f,0.775535f,0.0296184f,
0.78149f,0.224275f,0.891258f,-0.164902f,0.812014f,0.0343333f, 0.763765f,0.219301f,0.870551f,-0.162538f,0.8535f,0.0400037f,
0.738715f,0.21123f,0.839066f,-0.15928f,0.91039f,0.0475191f, 0.703926f,0.197658f,0.789919f,-0.155028f,0.996598f,0.0583647f,
0.935675f,-1.11905e-06f,0.935672f,2.94663e-18f,0.414128f,4.13738e-05f, 0.935591f,0.00561706f,0.935681f,-0.00411651f,0.41416f,4.16643e-05f,
0.93537f,0.0112282f,0.935725f,-0.00823413f,0.414255f,4.25403e-05f, 0.935004f,0.0168451f,0.935789f,-0.0123539f,0.414415f,4.40153e-05f,
0.934507f,0.0224511f,0.935885f,-0.016477f,0.414639f,4.61116e-05f, 0.933892f,0.028052f,0.936013f,-0.0206043f,0.414927f,4.88614e-05f,
0.93318f,0.0336214f,0.936177f,-0.0246787f,0.415297f,5.23214e-05f, 0.932409f,0.0390904f,0.936333f,-0.0285682f,0.415788f,5.65731e-05f,
0.931607f,0.0445075f,0.936524f,-0.0323978f,0.416371f,6.16438e-05f, 0.930797f,0.0498814f,0.936734f,-0.0361957f,0.417041f,6.76052e-05f,
0.929997f,0.0552225f,0.936967f,-0.0399808f,0.417792f,7.45423e-05f, 0.929219f,0.0605143f,0.93725f,-0.0437566f,0.418625f,8.25622e-05f,
0.928452f,0.0657745f,0.937566f,-0.0475311f,0.419541f,9.17926e-05f, 0.92771f,0.0709992f,0.93792f,-0.0513055f,0.420539f,0.00010237f,
0.926976f,0.0761785f,0.938307f,-0.0550837f,0.421618f,0.000114455f, 0.926252f,0.0813135f,0.938729f,-0.058871f,0.422786f,0.000128256f,
0.925557f,0.0864013f,0.939179f,-0.0626602f,0.424034f,0.000143946f, 0.92488f,0.0914424f,0.939703f,-0.0664598f,0.425369f,0.000161792f,
0.923772f,0.0964362f,0.940286f,-0.0702847f,0.4268f,0.000182131f, 0.923039f,0.101364f,0.94083f,-0.0740657f,0.428328f,0.000205173f,
0.922277f,0.106114f,0.941431f,-0.0775802f,0.430018f,0.00023124f, 0.921398f,0.110798f,0.941926f,-0.0810014f,0.431863f,0.000260853f,
0.920456f,0.115379f,0.942456f,-0.0843477f,0.433831f,0.000294276f, 0.919491f,0.119892f,0.943004f,-0.0876446f,0.435921f,0.000331962f,
0.919417f,0.124249f,0.943564f,-0.0909232f,0.438133f,0.00037452f, 0.918449f,0.128604f,0.944107f,-0.0942339f,0.440496f,0.000422909f,
0.917506f,0.132855f,0.944697f,-0.0975331f,0.442979f,0.000477418f, 0.916519f,0.137056f,0.945241f,-0.100817f,0.445585f,0.000538754f,
0.915931f,0.141099f,0.946069f,-0.104115f,0.448328f,0.000607968f, 0.914907f,0.14513f,0.946635f,-0.107399f,0.451235f,0.00068637f,
0.913734f,0.148967f,0.947313f,-0.110239f,0.454413f,0.000774427f, 0.912339f,0.152694f,0.947721f,-0.112919f,0.457817f,0.000873368f,
0.912244f,0.156264f,0.948332f,-0.115488f,0.461413f,0.000984133f, 0.910489f,0.159731f,0.948047f,-0.118155f,0.465249f,0.00111051f,
0.917477f,0.163704f,0.951426f,-0.120793f,0.469277f,0.00125187f, 0.906672f,0.166606f,0.94824f,-0.123392f,0.473484f,0.00140958f,
0.906143f,0.169985f,0.94896f,-0.126091f,0.477917f,0.00158867f, 0.903357f,0.173203f,0.949112f,-0.128514f,0.482681f,0.00179098f,
0.912433f,0.176188f,0.952526f,-0.130347f,0.487868f,0.00201624f, 0.899531f,0.178873f,0.948858f,-0.132307f,0.493458f,0.00227553f,
0.89672f,0.181653f,0.948972f,-0.134277f,0.49934f,0.00256616f, 0.893209f,0.184316f,0.948793f,-0.136317f,0.505527f,0.00289201f,
0.891084f,0.186976f,0.948609f,-0.138394f,0.511996f,0.00325882f, 0.887918f,0.18919f,0.947878f,-0.13987f,0.51909f,0.0036746f,
0.88519f,0.19117f,0.946931f,-0.141011f,0.526875f,0.00414543f, 0.8801f,0.192952f,0.945735f,-0.142255f,0.535112f,0.00467345f,
0.882372f,0.19551f,0.946742f,-0.143812f,0.543826f,0.00528061f, 0.872326f,0.196384f,0.94316f,-0.145118f,0.553024f,0.0059572f,
0.868922f,0.197439f,0.940671f,-0.145381f,0.563451f,0.00672642f, 0.863525f,0.198453f,0.938279f,-0.146216f,0.574662f,0.00761609f,
0.858303f,0.199316f,0.935323f,-0.147057f,0.586346f,0.00860014f, 0.852744f,0.199712f,0.931836f,-0.147268f,0.599441f,0.00975827f,
0.845314f,0.199648f,0.927652f,-0.147112f,0.613878f,0.011037f, 0.840004f,0.199947f,0.922708f,-0.147761f,0.629216f,0.0125609f,
0.833155f,0.199164f,0.917047f,-0.146903f,0.646544f,0.0142507f, 0.823494f,0.198294f,0.909834f,-0.146703f,0.665732f,0.0162575f,
0.814841f,0.197054f,0.902074f,-0.14599f,0.686603f,0.0185496f, 0.805057f,0.195139f,0.891833f,-0.144901f,0.710936f,0.0212307f,
0.792163f,0.19288f,0.88077f,-0.143641f,0.73755f,0.0243521f, 0.777807f,0.189797f,0.865873f,-0.142228f,0.769301f,0.028157f,
0.762544f,0.186112f,0.848768f,-0.140252f,0.806281f,0.0327038f, 0.741948f,0.181787f,0.826346f,-0.138432f,0.848973f,0.0382364f,
0.718093f,0.175085f,0.796512f,-0.135515f,0.907875f,0.0456201f, 0.685209f,0.164437f,0.749404f,-0.131906f,0.996461f,0.0564113f,
0.92545f,5.62373e-07f,0.925453f,-1.47497e-16f,0.394387f,3.97265e-05f, 0.9254f,0.00447193f,0.925452f,-0.00313834f,0.394427f,3.99892e-05f,
0.925246f,0.00894983f,0.925472f,-0.00627901f,0.394547f,4.07816e-05f, 0.924974f,0.0134367f,0.925497f,-0.00945128f,0.394754f,4.21391e-05f,
0.924566f,0.017965f,0.92551f,-0.0127295f,0.395068f,4.41644e-05f, 0.924049f,0.022504f,0.925528f,-0.0160288f,0.395466f,4.68357e-05f,
0.923435f,0.0270344f,0.925566f,-0.0193274f,0.395942f,5.01738e-05f, 0.922719f,0.03156f,0.925611f,-0.0226314f,0.396497f,5.42379e-05f,
0.921947f,0.0360706f,0.925664f,-0.0259341f,0.397129f,5.90794e-05f, 0.921112f,0.0405561f,0.92575f,-0.0292365f,0.397838f,6.47708e-05f,
0.920241f,0.0450282f,0.925853f,-0.0325396f,0.398624f,7.13965e-05f, 0.919349f,0.0494759f,0.925984f,-0.0358483f,0.399489f,7.90633e-05f,
0.91846f,0.0538948f,0.926137f,-0.0391651f,0.400435f,8.78889e-05f, 0.917566f,0.0582661f,0.926317f,-0.042487f,0.401461f,9.79962e-05f,
0.916659f,0.0626168f,0.92651f,-0.0458106f,0.402568f,0.000109531f, 0.915746f,0.0668504f,0.926688f,-0.0489277f,0.403814f,0.000122671f,
0.914809f,0.0709865f,0.926872f,-0.051906f,0.405189f,0.000137596f, 0.913839f,0.0750567f,0.927046f,-0.0548244f,0.406676f,0.000154511f,
0.912939f,0.079093f,0.927269f,-0.057726f,0.408278f,0.000173728f, 0.91194f,0.0830765f,0.927472f,-0.060613f,0.409993f,0.000195492f,
0.910893f,0.0870161f,0.927677f,-0.0634916f,0.411821f,0.000220084f, 0.909838f,0.0909094f,0.927906f,-0.0663654f,0.413751f,0.000247814f,
0.908749f,0.0947685f,0.928113f,-0.069244f,0.415799f,0.000279092f, 0.907931f,0.0985703f,0.92841f,-0.0721443f,0.417957f,0.000314455f,
0.906796f,0.102332f,0.928623f,-0.0750834f,0.420243f,0.000354477f, 0.90567f,0.106037f,0.928857f,-0.0780097f,0.422631f,0.000399406f,
0.904422f,0.109572f,0.929066f,-0.0806478f,0.425248f,0.000450115f, 0.903563f,0.11296f,0.929077f,-0.0830685f,0.428064f,0.000507183f,
0.902144f,0.116313f,0.929256f,-0.0854545f,0.43107f,0.000571813f, 0.90049f,0.119586f,0.929273f,-0.0878361f,0.434254f,0.000644575f,
0.899528f,0.122714f,0.929148f,-0.0902472f,0.43761f,0.000726933f, 0.898079f,0.125886f,0.929309f,-0.0927085f,0.441141f,0.000819986f,
0.896315f,0.12897f,0.929258f,-0.095217f,0.444853f,0.000924719f, 0.894549f,0.132009f,0.9293f,-0.0977235f,0.448722f,0.00104184f,
0.89313f,0.134783f,0.929095f,-0.0998762f,0.452893f,0.0011738f, 0.891069f,0.137454f,0.928944f,-0.101704f,0.457437f,0.00132269f,
0.888752f,0.140001f,0.928443f,-0.103441f,0.462238f,0.00148844f, 0.887605f,0.142361f,0.927996f,-0.105304f,0.467321f,0.00167685f,
0.885029f,0.144856f,0.927528f,-0.107251f,0.472656f,0.0018888f, 0.883908f,0.147024f,0.926723f,-0.10929f,0.478239f,0.00212862f,
0.880911f,0.149304f,0.926112f,-0.111135f,0.484258f,0.00240258f, 0.886703f,0.151982f,0.928027f,-0.112255f,0.490835f,0.00270597f,
0.875495f,0.152855f,0.923149f,-0.113543f,0.497845f,0.00305005f, 0.873019f,0.154655f,0.922313f,-0.114939f,0.505197f,0.00343582f,
0.886168f,0.156983f,0.924646f,-0.116671f,0.512957f,0.00388087f, 0.865472f,0.157767f,0.918193f,-0.117585f,0.521385f,0.00437682f,
0.862076f,0.158883f,0.916178f,-0.118251f,0.53067f,0.00494153f, 0.858058f,0.160092f,0.913781f,-0.119241f,0.540479f,0.00558091f,
0.854031f,0.161259f,0.911197f,-0.120501f,0.550756f,0.00631055f, 0.848544f,0.161874f,0.908004f,-0.120661f,0.562294f,0.00713948f,
0.846862f,0.162526f,0.90568f,-0.12098f,0.574809f,0.00807589f, 0.837885f,0.162867f,0.900127f,-0.121866f,0.588002f,0.00916614f,
0.831372f,0.162771f,0.895235f,-0.121487f,0.602716f,0.0103801f, 0.824705f,0.162658f,0.889853f,-0.121676f,0.619008f,0.0118197f,
0.817632f,0.162359f,0.883289f,-0.121792f,0.636118f,0.0134379f, 0.8087f,0.161467f,0.876164f,-0.121026f,0.656318f,0.0153352f,
0.799338f,0.160648f,0.86745f,-0.121034f,0.677554f,0.0175429f, 0.789964f,0.158894f,0.857508f,-0.119679f,0.702728f,0.0201024f,
0.776183f,0.157333f,0.84552f,-0.119115f,0.729573f,0.0230986f, 0.763128f,0.154745f,0.831303f,-0.117544f,0.762828f,0.0267797f,
0.74756f,0.151809f,0.814223f,-0.116038f,0.800353f,0.0311675f, 0.727574f,0.148169f,0.79186f,-0.114521f,0.845029f,0.0366019f,
0.704282f,0.142839f,0.762697f,-0.112136f,0.905284f,0.0438372f, 0.672705f,0.134955f,0.718325f,-0.109154f,0.996321f,0.0545865f,
0.915824f,4.01228e-07f,0.915821f,-2.70086e-17f,0.375841f,3.90709e-05f, 0.915777f,0.00359055f,0.915826f,-0.00265071f,0.375881f,3.93352e-05f,
0.91564f,0.00718401f,0.91582f,-0.00530318f,0.376f,4.01318e-05f, 0.915426f,0.0107725f,0.915828f,-0.00795913f,0.376199f,4.14731e-05f,
0.915123f,0.0143594f,0.915831f,-0.0106202f,0.376478f,4.33795e-05f, 0.914735f,0.0179506f,0.915836f,-0.0132881f,0.376836f,4.58798e-05f,
0.914276f,0.02153f,0.915848f,-0.0159644f,0.377275f,4.9012e-05f, 0.91374f,0.0251152f,0.915865f,-0.0186503f,0.377794f,5.28234e-05f,
0.913121f,0.0286875f,0.915884f,-0.0213472f,0.378394f,5.73713e-05f, 0.912452f,0.0321965f,0.915893f,-0.0239278f,0.379107f,6.27432e-05f,
0.911717f,0.0356334f,0.915886f,-0.0263777f,0.379943f,6.90193e-05f, 0.91094f,0.0390459f,0.915867f,-0.0287817f,0.380885f,7.62787e-05f,
0.910112f,0.0424268f,0.915833f,-0.0311645f,0.381929f,8.4625e-05f, 0.909254f,0.0457768f,0.915809f,-0.0335387f,0.383072f,9.4176e-05f,
0.908364f,0.0491123f,0.915772f,-0.0359122f,0.384321f,0.000105086f, 0.907435f,0.0524366f,0.915734f,-0.0382936f,0.385667f,0.000117498f,
0.906483f,0.0557302f,0.915697f,-0.0406858f,0.387114f,0.000131596f, 0.905508f,0.0590025f,0.915639f,-0.0430949f,0.388663f,0.000147588f,
0.904454f,0.0622476f,0.915583f,-0.0455219f,0.390315f,0.000165695f, 0.903359f,0.0654769f,0.915551f,-0.0479655f,0.392066f,0.000186162f,
0.902222f,0.0686846f,0.915501f,-0.0504419f,0.393928f,0.000209324f, 0.901049f,0.0718455f,0.915449f,-0.0529222f,0.395887f,0.000235387f,
0.899847f,0.0749202f,0.915412f,-0.0552291f,0.39802f,0.000264898f, 0.898554f,0.0778532f,0.915274f,-0.0573f,0.400338f,0.000298094f,
0.897302f,0.0807258f,0.915156f,-0.0592837f,0.402813f,0.000335398f, 0.895899f,0.0835567f,0.914941f,-0.0612923f,0.40545f,0.000377648f,
0.894437f,0.0863554f,0.914735f,-0.0632895f,0.408228f,0.000424999f, 0.893141f,0.0891202f,0.914528f,-0.0653129f,0.411151f,0.00047828f,
0.891594f,0.0918716f,0.914278f,-0.0674171f,0.414239f,0.000538577f, 0.889998f,0.0945882f,0.91403f,-0.069534f,0.417463f,0.000606049f,
0.888711f,0.0972789f,0.913681f,-0.0717428f,0.420848f,0.000682611f, 0.887435f,0.0997528f,0.913231f,-0.0735946f,0.424523f,0.000769116f,
0.885392f,0.102127f,0.912637f,-0.0752131f,0.428498f,0.000867168f, 0.883344f,0.104445f,0.912119f,-0.0768307f,0.432714f,0.000977415f,
0.881081f,0.106718f,0.91148f,-0.078486f,0.437146f,0.00110082f, 0.879107f,0.108951f,0.910874f,-0.0802074f,0.441785f,0.00123926f,
0.876712f,0.111173f,0.910093f,-0.0820279f,0.446638f,0.00139507f, 0.874891f,0.113256f,0.909291f,-0.0838103f,0.45174f,0.00156998f,
0.872362f,0.115086f,0.908225f,-0.0849014f,0.457374f,0.00176796f, 0.870095f,0.11682f,0.906836f,-0.0860952f,0.463411f,0.00199382f,
0.867258f,0.118578f,0.905594f,-0.0874351f,0.469763f,0.00224803f, 0.86399f,0.120323f,0.904264f,-0.0889145f,0.476403f,0.00253318f,
0.861456f,0.121913f,0.902753f,-0.0904346f,0.483341f,0.00285398f, 0.858415f,0.123057f,0.900602f,-0.0909834f,0.491088f,0.00321559f,
0.854901f,0.124341f,0.898547f,-0.0918875f,0.499418f,0.00363361f, 0.851432f,0.125492f,0.896217f,-0.0929163f,0.508108f,0.0040971f,
0.847073f,0.126743f,0.893793f,-0.0942523f,0.517221f,0.00462814f, 0.84328f,0.127344f,0.890751f,-0.0944118f,0.527526f,0.00523246f,
0.839153f,0.128031f,0.887549f,-0.0949658f,0.538518f,0.00591638f, 0.834152f,0.128765f,0.883909f,-0.0958903f,0.55002f,0.00669418f,
0.828512f,0.129034f,0.879643f,-0.0959323f,0.562784f,0.00758453f, 0.822927f,0.129247f,0.875038f,-0.0961859f,0.576813f,0.00860666f,
0.817334f,0.129438f,0.869718f,-0.0968678f,0.591458f,0.00977411f, 0.810115f,0.129088f,0.863863f,-0.0963321f,0.608358f,0.0111206f,
0.80361f,0.128738f,0.856961f,-0.0965284f,0.626398f,0.0126786f, 0.794897f,0.128085f,0.849502f,-0.0959507f,0.646513f,0.0144625f,
0.785786f,0.127309f,0.840313f,-0.0958675f,0.669004f,0.0165972f, 0.775606f,0.126024f,0.830106f,-0.0949859f,0.694213f,0.0190393f,
0.763918f,0.124577f,0.817793f,-0.0945087f,0.722506f,0.0219576f, 0.750117f,0.122588f,0.803423f,-0.0932922f,0.756126f,0.0254802f,
0.734965f,0.120229f,0.786147f,-0.0922283f,0.794237f,0.0297175f, 0.718696f,0.117337f,0.765486f,-0.0909853f,0.840956f,0.035064f,
0.690062f,0.11293f,0.733499f,-0.0891108f,0.902619f,0.0421618f, 0.660641f,0.107382f,0.691607f,-0.0867433f,0.996177f,0.052881f,
0.907564f,-4.82425e-08f,0.90756f,-5.66464e-17f,0.357219f,3.69938e-05f, 0.907532f,0.00256222f,0.90756f,-0.00179691f,0.357266f,3.72394e-05f,
0.907435f,0.00512538f,0.907541f,-0.00359691f,0.357407f,3.79805e-05f, 0.907256f,0.00772049f,0.907491f,-0.00546696f,0.357657f,3.92788e-05f,
0.907009f,0.0103146f,0.907436f,-0.00735296f,0.358004f,4.11277e-05f, 0.906697f,0.0129096f,0.907363f,-0.00923361f,0.358442f,4.35372e-05f,
0.906328f,0.0155007f,0.907284f,-0.0111107f,0.358969f,4.65424e-05f, 0.90589f,0.0180801f,0.907187f,-0.0129859f,0.359588f,5.01864e-05f,
0.905387f,0.0206556f,0.907091f,-0.0148607f,0.360296f,5.45216e-05f, 0.904822f,0.023231f,0.90697f,-0.0167366f,0.361096f,5.96093e-05f,
0.904194f,0.0257911f,0.906845f,-0.0186147f,0.361986f,6.55207e-05f, 0.903514f,0.0283493f,0.906711f,-0.0205063f,0.36297f,7.23567e-05f,
0.90277f,0.0309028f,0.906567f,-0.0224099f,0.364048f,8.02107e-05f, 0.901973f,0.033448f,0.906415f,-0.0243221f,0.365218f,8.91832e-05f,
0.901148f,0.0359904f,0.906249f,-0.0262531f,0.366484f,9.94213e-05f, 0.900243f,0.038524f,0.906073f,-0.0282098f,0.367847f,0.000111087f,
0.899291f,0.0410486f,0.90589f,-0.0301795f,0.369305f,0.000124306f, 0.898347f,0.0435729f,0.905697f,-0.0321899f,0.370865f,0.000139365f,
0.897386f,0.0459763f,0.905437f,-0.0339655f,0.372596f,0.000156482f, 0.896315f,0.048304f,0.905139f,-0.035611f,0.374486f,0.000175898f,
0.895193f,0.0505902f,0.904816f,-0.0372117f,0.376513f,0.000197817f, 0.894027f,0.0528595f,0.904449f,-0.0388026f,0.378673f,0.000222532f,
0.892801f,0.0551017f,0.904074f,-0.0404072f,0.380966f,0.000250377f, 0.891538f,0.0573402f,0.903647f,-0.0420391f,0.383388f,0.00028172f,
0.890197f,0.0595567f,0.903222f,-0.0436996f,0.385937f,0.000316946f, 0.888769f,0.0617667f,0.902749f,-0.0454057f,0.388619f,0.000356562f,
0.887278f,0.0639737f,0.902294f,-0.0471595f,0.391432f,0.00040111f, 0.885709f,0.066149f,0.9018f,-0.0489371f,0.39437f,0.000450982f,
0.884128f,0.0681258f,0.901216f,-0.0503158f,0.397586f,0.000507283f, 0.882535f,0.0699887f,0.900537f,-0.0514801f,0.401035f,0.000570156f,
0.880738f,0.0718504f,0.899779f,-0.0527081f,0.404706f,0.000641389f, 0.87909f,0.0736852f,0.898978f,-0.0540048f,0.408566f,0.000721492f,
0.877393f,0.0755717f,0.898097f,-0.0554592f,0.412631f,0.000812776f, 0.875418f,0.0774665f,0.89721f,-0.0570486f,0.416889f,0.000916367f,
0.873386f,0.0793427f,0.896289f,-0.058676f,0.421312f,0.00103188f, 0.870995f,0.0809528f,0.895137f,-0.0597568f,0.426135f,0.00116173f,
0.868654f,0.0824109f,0.893871f,-0.0605921f,0.431327f,0.00130684f, 0.866104f,0.0838803f,0.892553f,-0.0615479f,0.436803f,0.00146949f,
0.863722f,0.0854073f,0.891143f,-0.0627412f,0.442557f,0.0016548f, 0.861395f,0.0869652f,0.889615f,-0.0641694f,0.448577f,0.00186686f,
0.858472f,0.0883373f,0.887884f,-0.0652654f,0.454972f,0.0021041f, 0.855345f,0.0894119f,0.885892f,-0.0657732f,0.462034f,0.00237057f,
0.852201f,0.0905253f,0.883838f,-0.0665207f,0.469487f,0.00267005f, 0.849125f,0.0917135f,0.881607f,-0.0676121f,0.4773f,0.00301307f,
0.845654f,0.0928686f,0.879186f,-0.0687615f,0.485493f,0.00340307f, 0.841956f,0.0934971f,0.876302f,-0.0688385f,0.494677f,0.0038369f,
0.837591f,0.0943133f,0.87334f,-0.0694323f,0.504432f,0.00433356f, 0.833576f,0.0951887f,0.87005f,-0.0704744f,0.514641f,0.00490754f,
0.829072f,0.0956164f,0.866291f,-0.0706159f,0.525798f,0.00554793f, 0.824187f,0.0959994f,0.86216f,-0.0708542f,0.538064f,0.00628084f,
0.818627f,0.0965421f,0.8577f,-0.0716495f,0.550895f,0.00712896f, 0.813014f,0.0965426f,0.85272f,-0.071426f,0.565181f,0.00808459f,
0.80678f,0.096653f,0.846962f,-0.071725f,0.580793f,0.00920357f, 0.799808f,0.0965956f,0.840699f,-0.0718456f,0.597346f,0.0104703f,
0.792852f,0.0961924f,0.833481f,-0.0715961f,0.616435f,0.0119585f, 0.784233f,0.0958757f,0.825462f,-0.0717111f,0.636451f,0.0136623f,
0.775003f,0.0951173f,0.816124f,-0.0712117f,0.660119f,0.0157022f, 0.764484f,0.0942513f,0.805635f,-0.0708518f,0.68543f,0.0180467f,
0.75259f,0.0930459f,0.792963f,-0.0703101f,0.715192f,0.0208797f, 0.738436f,0.0914793f,0.77816f,-0.0694399f,0.749202f,0.0242526f,
0.722209f,0.0896861f,0.76025f,-0.0687904f,0.787938f,0.0283471f, 0.701504f,0.0873403f,0.737164f,-0.0677928f,0.836759f,0.0336156f,
0.674735f,0.0841031f,0.706429f,-0.0664109f,0.899883f,0.0405859f, 0.631163f,0.0794825f,0.657097f,-0.0646468f,0.99603f,0.0512862f,
0.899568f,1.60695e-06f,0.899569f,-1.20856e-17f,0.340083f,3.65618e-05f, 0.899538f,0.00172146f,0.89956f,-0.00127682f,0.340128f,3.68013e-05f,
0.899463f,0.00343796f,0.899532f,-0.00255513f,0.340265f,3.75235e-05f, 0.899343f,0.00515956f,0.899481f,-0.00383636f,0.340492f,3.87388e-05f,
0.899169f,0.00687854f,0.899419f,-0.00512196f,0.34081f,4.0465e-05f, 0.898939f,0.00860064f,0.899331f,-0.00641329f,0.341219f,4.27269e-05f,
0.898662f,0.0103197f,0.899226f,-0.00771164f,0.341719f,4.5557e-05f, 0.898335f,0.0120415f,0.89911f,-0.00901823f,0.34231f,4.89956e-05f,
0.89796f,0.0137596f,0.898977f,-0.0103342f,0.342992f,5.30913e-05f, 0.897537f,0.0154776f,0.898812f,-0.0116604f,0.343766f,5.79013e-05f,
0.897069f,0.0171967f,0.898647f,-0.0129978f,0.344631f,6.34918e-05f, 0.896546f,0.0189149f,0.898448f,-0.0143471f,0.345587f,6.9939e-05f,
0.89598f,0.0206048f,0.89824f,-0.0156532f,0.346648f,7.7334e-05f, 0.895355f,0.0221902f,0.897978f,-0.0167475f,0.347859f,8.57916e-05f,
0.894687f,0.0237395f,0.897678f,-0.0177647f,0.349199f,9.54194e-05f, 0.893958f,0.0252629f,0.897341f,-0.01876f,0.35066f,0.000106343f,
0.893183f,0.0267879f,0.896974f,-0.0197573f,0.35224f,0.000118714f, 0.892333f,0.0283073f,0.896568f,-0.0207749f,0.35394f,0.000132707f,
0.891421f,0.0298313f,0.89614f,-0.0218255f,0.355759f,0.000148524f, 0.890452f,0.0313584f,0.895677f,-0.0229164f,0.357695f,0.000166392f,
0.889424f,0.0329018f,0.895194f,-0.0240524f,0.359751f,0.000186565f, 0.888355f,0.0344518f,0.894677f,-0.0252422f,0.361926f,0.000209355f,
0.887201f,0.0360247f,0.894116f,-0.0265077f,0.364226f,0.000235215f, 0.886051f,0.0376308f,0.893527f,-0.0278881f,0.36666f,0.000264846f,
0.884775f,0.0392131f,0.892902f,-0.0292622f,0.369234f,0.000298406f, 0.883459f,0.0405766f,0.892169f,-0.0301723f,0.372059f,0.000335955f,
0.882076f,0.0418839f,0.891385f,-0.0309796f,0.375081f,0.000377937f, 0.880637f,0.0431775f,0.890534f,-0.0318116f,0.37828f,0.000424904f,
0.879122f,0.0444876f,0.889653f,-0.0327066f,0.381641f,0.000477475f, 0.877477f,0.0458192f,0.888703f,-0.0336862f,0.385165f,0.000536428f,
0.875768f,0.0471586f,0.887716f,-0.034759f,0.388849f,0.00060267f, 0.87401f,0.0485261f,0.886697f,-0.0359296f,0.392692f,0.000677265f,
0.872223f,0.0497788f,0.885582f,-0.0369132f,0.396787f,0.000761727f, 0.870331f,0.0508475f,0.884269f,-0.037521f,0.401312f,0.000858817f,
0.868271f,0.0519302f,0.882889f,-0.0382051f,0.406097f,0.000967367f, 0.866114f,0.0530441f,0.881432f,-0.0390153f,0.411105f,0.00108847f,
0.86382f,0.0541922f,0.879895f,-0.0399582f,0.41632f,0.00122405f, 0.861432f,0.0553611f,0.878316f,-0.0410362f,0.421739f,0.00137648f,
0.858973f,0.0562408f,0.876523f,-0.0415258f,0.427637f,0.00154892f, 0.856358f,0.0570681f,0.874506f,-0.0419872f,0.434089f,0.00174793f,
0.853567f,0.0579823f,0.872416f,-0.0426635f,0.440842f,0.00196986f, 0.850649f,0.058948f,0.870206f,-0.0435365f,0.447861f,0.00221867f,
0.847519f,0.0597983f,0.86782f,-0.0443115f,0.455231f,0.00249908f, 0.844202f,0.0603348f,0.865113f,-0.0444193f,0.463523f,0.00282196f,
0.840618f,0.0610282f,0.862231f,-0.0449481f,0.472262f,0.00318628f, 0.836922f,0.0617799f,0.859161f,-0.0457137f,0.481325f,0.00359469f,
0.833007f,0.0622282f,0.855793f,-0.0459605f,0.491182f,0.00406346f, 0.828562f,0.0626423f,0.852034f,-0.0461694f,0.502061f,0.00459964f,
0.824114f,0.0631733f,0.848042f,-0.04679f,0.513382f,0.00520569f, 0.819156f,0.0634216f,0.843637f,-0.0469179f,0.525669f,0.00590027f,
0.81368f,0.0636276f,0.838698f,-0.0470417f,0.539316f,0.00669762f, 0.808097f,0.0639506f,0.833397f,-0.047626f,0.553478f,0.00760635f,
0.801577f,0.0638101f,0.82735f,-0.0472851f,0.569691f,0.00866194f, 0.794769f,0.0638755f,0.820719f,-0.0475757f,0.586882f,0.00987269f,
0.787025f,0.0636019f,0.813256f,-0.0473082f,0.606112f,0.0112828f, 0.778575f,0.0634198f,0.804856f,-0.04747f,0.627142f,0.0129329f,
0.769027f,0.0628584f,0.795256f,-0.0470397f,0.650913f,0.014854f, 0.758207f,0.0624632f,0.784321f,-0.0471611f,0.67684f,0.0171299f,
0.745758f,0.0615202f,0.771388f,-0.0465096f,0.707627f,0.0198596f, 0.731305f,0.0604713f,0.756163f,-0.0459584f,0.742066f,0.0230914f,
0.713615f,0.0593758f,0.737594f,-0.0457061f,0.781981f,0.0270921f, 0.691527f,0.0577267f,0.713967f,-0.0449151f,0.832441f,0.0322498f,
0.661862f,0.0555934f,0.681961f,-0.044009f,0.897076f,0.0391021f, 0.614875f,0.0524805f,0.631022f,-0.0428393f,0.99588f,0.0497943f,
0.892954f,-1.10047e-06f,0.892955f,-8.10327e-17f,0.322714f,3.42533e-05f, 0.892938f,0.000816623f,0.892943f,-0.000569737f,0.322765f,3.44831e-05f,
0.892868f,0.00163189f,0.892889f,-0.00114697f,0.322921f,3.51795e-05f, 0.892748f,0.0024491f,0.892806f,-0.00172441f,0.323179f,3.63492e-05f,
0.892595f,0.00325902f,0.89269f,-0.00229519f,0.323537f,3.80034e-05f, 0.892384f,0.004074f,0.892544f,-0.00287118f,0.323999f,4.01738e-05f,
0.892135f,0.00489295f,0.892359f,-0.00345756f,0.324565f,4.28969e-05f, 0.891837f,0.00571197f,0.892145f,-0.00405035f,0.325233f,4.62092e-05f,
0.8915f,0.00652976f,0.891898f,-0.00465043f,0.326004f,5.0159e-05f, 0.891119f,0.00735456f,0.891617f,-0.0052586f,0.326878f,5.48029e-05f,
0.890693f,0.00817755f,0.891312f,-0.00587559f,0.327855f,6.02063e-05f, 0.89022f,0.00900491f,0.890971f,-0.00650199f,0.328936f,6.64437e-05f,
0.889702f,0.00983332f,0.890598f,-0.00713831f,0.330119f,7.35994e-05f, 0.889142f,0.010663f,0.890201f,-0.00778493f,0.331405f,8.17677e-05f,
0.888545f,0.0114929f,0.889774f,-0.00844208f,0.332795f,9.1054e-05f, 0.887899f,0.0123214f,0.88931f,-0.00910987f,0.334288f,0.000101575f,
0.887216f,0.0131553f,0.888817f,-0.00978828f,0.335884f,0.00011346f, 0.886496f,0.0139824f,0.888313f,-0.0104771f,0.337583f,0.00012685f,
0.885733f,0.0148096f,0.887772f,-0.011176f,0.339386f,0.000141901f, 0.884941f,0.0156388f,0.887209f,-0.0118845f,0.341293f,0.000158784f,
0.884104f,0.016457f,0.886616f,-0.0126018f,0.343303f,0.000177683f, 0.883213f,0.0171089f,0.885951f,-0.0129451f,0.345518f,0.00019882f,
0.882245f,0.017671f,0.885195f,-0.0131162f,0.347945f,0.000222502f, 0.881191f,0.0182562f,0.88437f,-0.0133561f,0.350543f,0.000249168f,
0.88006f,0.0189041f,0.883485f,-0.0137285f,0.353304f,0.000279442f, 0.878841f,0.0196423f,0.882539f,-0.0143169f,0.356237f,0.000314572f,
0.877534f,0.0204507f,0.881533f,-0.0150655f,0.359328f,0.000354987f, 0.876183f,0.0212411f,0.880499f,-0.0158206f,0.36254f,0.000399937f,
0.874802f,0.0220239f,0.879441f,-0.0165797f,0.365875f,0.000449838f, 0.873372f,0.0227702f,0.878355f,-0.0172768f,0.369349f,0.000505135f,
0.871861f,0.0231849f,0.877101f,-0.017265f,0.373211f,0.000566427f, 0.870234f,0.0236387f,0.875738f,-0.0173587f,0.377344f,0.000635036f,
0.868472f,0.0241876f,0.874284f,-0.0176909f,0.381697f,0.000713044f, 0.866604f,0.0248834f,0.872749f,-0.0183535f,0.386278f,0.000804369f,
0.864644f,0.0256214f,0.871159f,-0.019138f,0.391034f,0.000907525f, 0.862634f,0.0263341f,0.869537f,-0.0199062f,0.395936f,0.00102106f,
0.860523f,0.026609f,0.867697f,-0.0197284f,0.401398f,0.00114622f, 0.858245f,0.0269827f,0.865695f,-0.0198013f,0.407233f,0.00128686f,
0.855804f,0.0275168f,0.863579f,-0.020272f,0.413355f,0.00144987f, 0.853194f,0.0281982f,0.861364f,-0.0210494f,0.41973f,0.00163867f,
0.85053f,0.0286785f,0.85907f,-0.0214907f,0.426385f,0.0018451f, 0.847657f,0.0288511f,0.856462f,-0.0212565f,0.433852f,0.00207416f,
0.844562f,0.029245f,0.853661f,-0.0215499f,0.441707f,0.00233805f, 0.841253f,0.0298357f,0.850729f,-0.0222807f,0.44989f,0.00264697f,
0.837825f,0.0300967f,0.847628f,-0.0223832f,0.45859f,0.00298377f, 0.83408f,0.0302574f,0.844129f,-0.0222787f,0.468279f,0.00336441f,
0.830035f,0.0306958f,0.840408f,-0.0228491f,0.478417f,0.0038158f, 0.82578f,0.030973f,0.836479f,-0.0230988f,0.489036f,0.00431371f,
0.821134f,0.0310027f,0.832038f,-0.0228976f,0.50108f,0.00488017f, 0.816077f,0.0313667f,0.827276f,-0.0234377f,0.51365f,0.00555023f,
0.810687f,0.0313572f,0.822117f,-0.0232517f,0.52728f,0.0062871f, 0.804719f,0.0314983f,0.816343f,-0.0234512f,0.542393f,0.0071661f,
0.79826f,0.0315731f,0.810134f,-0.0235965f,0.558198f,0.00815105f, 0.791088f,0.0315012f,0.803038f,-0.0234896f,0.576438f,0.00931921f,
0.783216f,0.0315096f,0.795354f,-0.0236359f,0.595443f,0.0106448f, 0.774365f,0.0313364f,0.786502f,-0.0234943f,0.617663f,0.0122412f,
0.764446f,0.0310817f,0.776613f,-0.0233286f,0.641403f,0.0140491f, 0.75308f,0.0309015f,0.765185f,-0.0233881f,0.668729f,0.0162737f,
0.739982f,0.030448f,0.751943f,-0.0230807f,0.699824f,0.018893f, 0.724573f,0.0299369f,0.736256f,-0.0228215f,0.734726f,0.0219915f,
0.705893f,0.0294128f,0.717116f,-0.0227105f,0.776492f,0.0259283f, 0.68246f,0.0286025f,0.692966f,-0.0223257f,0.828007f,0.0309606f,
0.650681f,0.027543f,0.660148f,-0.0218799f,0.8942f,0.0377038f, 0.600304f,0.0260509f,0.607784f,-0.0212976f,0.995727f,0.0483979f,
0.886377f,-3.5386e-06f,0.886374f,-9.35213e-17f,0.306975f,3.39596e-05f, 0.886353f,6.56987e-07f,0.886355f,-6.41635e-17f,0.307023f,3.41753e-05f,
0.886302f,1.8705e-06f,0.886306f,-4.42418e-17f,0.307169f,3.48252e-05f, 0.886209f,2.95529e-06f,0.886214f,5.93542e-17f,0.307412f,3.59176e-05f,
0.886088f,-9.82378e-07f,0.886088f,-1.06467e-17f,0.307753f,3.74669e-05f, 0.885921f,2.54209e-06f,0.885924f,-1.34304e-17f,0.308191f,3.94929e-05f,
0.885729f,1.03131e-06f,0.885732f,-4.08536e-17f,0.308726f,4.20213e-05f, 0.88549f,2.60765e-07f,0.885488f,-1.70276e-16f,0.309358f,4.50841e-05f,
0.88522f,-1.53851e-06f,0.885226f,-1.25038e-16f,0.310087f,4.87193e-05f, 0.884921f,3.9097e-06f,0.884923f,-1.40742e-16f,0.310914f,5.29714e-05f,
0.884589f,3.28111e-06f,0.884592f,-8.9917e-17f,0.311838f,5.78914e-05f, 0.88422f,4.80263e-07f,0.884221f,-2.14427e-17f,0.312859f,6.35375e-05f,
0.883816f,-1.25744e-06f,0.883812f,-3.6209e-17f,0.313978f,6.9975e-05f, 0.883376f,-9.40653e-08f,0.883377f,1.84807e-18f,0.315194f,7.72768e-05f,
0.882915f,-2.20915e-06f,0.882911f,-6.5916e-17f,0.316507f,8.55239e-05f, 0.882415f,-3.6352e-06f,0.882419f,-2.15126e-17f,0.317917f,9.48058e-05f,
0.881804f,-1.10868e-06f,0.881808f,-3.28542e-17f,0.319554f,0.000105825f, 0.881062f,2.99561e-06f,0.881066f,-6.52392e-17f,0.321436f,0.000118881f,
0.880289f,-9.36414e-07f,0.880289f,-3.51698e-17f,0.323431f,0.000133544f, 0.879472f,-3.77515e-06f,0.879474f,-1.30497e-16f,0.325541f,0.000149972f,
0.878618f,6.96653e-07f,0.878619f,-1.09489e-16f,0.327765f,0.000168336f, 0.87773f,-9.06647e-07f,0.877736f,5.0485e-17f,0.330102f,0.000188821f,
0.876811f,2.83727e-06f,0.876813f,-6.92623e-17f,0.332554f,0.000211626f, 0.875858f,-2.24807e-06f,0.875862f,-3.01438e-17f,0.335119f,0.000236968f,
0.874873f,-3.58641e-06f,0.874874f,-7.2026e-17f,0.337799f,0.000265079f, 0.873857f,-4.96958e-07f,0.873856f,-4.50866e-17f,0.340593f,0.000296208f,
0.872804f,1.00835e-06f,0.872807f,-2.19631e-16f,0.343501f,0.000330624f, 0.871458f,-2.06213e-06f,0.871453f,-1.60008e-16f,0.346984f,0.000373673f,
0.870047f,5.14851e-07f,0.870053f,1.73962e-17f,0.350643f,0.000421808f, 0.868611f,-1.11743e-06f,0.868605f,6.35704e-18f,0.354434f,0.000474986f,
0.867134f,-5.49233e-06f,0.867121f,2.64486e-17f,0.358359f,0.000533632f, 0.865612f,-5.39612e-06f,0.865612f,5.69723e-17f,0.362416f,0.000598198f,
0.864052f,7.64782e-07f,0.864048f,9.23434e-17f,0.366607f,0.000669167f, 0.862365f,-3.59203e-06f,0.862372f,6.16634e-17f,0.371106f,0.000750186f,
0.860371f,2.67642e-06f,0.86037f,-1.0696e-16f,0.376286f,0.000849071f, 0.858343f,2.40487e-06f,0.858345f,-7.28257e-17f,0.38162f,0.000957529f,
0.85627f,-2.13488e-06f,0.856264f,-7.52183e-17f,0.387109f,0.00107629f, 0.854139f,7.12966e-07f,0.854135f,-7.82196e-17f,0.392752f,0.00120613f,
0.851853f,-4.87597e-06f,0.851856f,-4.99694e-17f,0.398786f,0.001354f, 0.849205f,2.18178e-06f,0.84921f,-1.67828e-16f,0.405685f,0.00153405f,
0.846493f,2.61363e-06f,0.846498f,-8.41589e-17f,0.412762f,0.00173025f, 0.843725f,4.18888e-06f,0.84373f,-1.20612e-16f,0.420019f,0.00194376f,
0.840762f,-2.08612e-06f,0.840769f,-8.19631e-17f,0.427757f,0.00218621f, 0.837393f,2.63247e-06f,0.837395f,-1.99257e-16f,0.436565f,0.00248065f,
0.833922f,-1.49727e-06f,0.833914f,-1.24834e-16f,0.44558f,0.0027998f, 0.830334f,2.75708e-06f,0.830334f,-4.472e-17f,0.454803f,0.00314534f,
0.826185f,-3.60292e-06f,0.826193f,-2.21666e-16f,0.465609f,0.00357958f, 0.821863f,-3.558e-06f,0.821863f,-1.77811e-16f,0.476745f,0.00405243f,
0.817299f,9.23404e-07f,0.8173f,-9.55122e-17f,0.488323f,0.00457276f, 0.812117f,2.21251e-08f,0.812118f,-1.83679e-17f,0.501747f,0.00521825f,
0.806672f,4.75991e-06f,0.806663f,-9.54486e-17f,0.515448f,0.00591182f, 0.800589f,4.36852e-07f,0.800591f,-1.01587e-16f,0.530897f,0.00674682f,
0.793991f,-5.29667e-06f,0.794003f,3.50187e-17f,0.547394f,0.00768753f, 0.786685f,-2.1082e-06f,0.78669f,-9.68323e-17f,0.565626f,0.00879262f,
0.778612f,9.39181e-07f,0.778617f,-8.35349e-17f,0.585515f,0.0100651f, 0.769518f,5.89981e-06f,0.769525f,-8.57981e-18f,0.607868f,0.0115841f,
0.759351f,-5.25346e-06f,0.759365f,-5.3143e-17f,0.63193f,0.0133018f, 0.747605f,5.43646e-06f,0.747606f,-1.01234e-17f,0.660361f,0.0154622f,
0.734092f,7.59281e-06f,0.734086f,-9.11714e-17f,0.691792f,0.0179758f, 0.718114f,3.34762e-06f,0.718127f,-2.1529e-17f,0.727222f,0.0209504f,
0.698665f,4.81805e-06f,0.698655f,-1.06006e-16f,0.770851f,0.024828f, 0.674176f,1.11358e-05f,0.674148f,-8.54475e-17f,0.823459f,0.0297422f,
0.640838f,-1.39626e-05f,0.640835f,1.50478e-17f,0.891258f,0.0363846f, 0.586854f,3.86233e-05f,0.586875f,-1.0516e-16f,0.995571f,0.0470903f,
/* MF_LTC_GGX_TABLE_END */
};

MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha)
{
    return mf__ltc_lookup(mf__ltc_ggx_data, MF__LTC_GGX_N, MF__LTC_GGX_N, cos_theta_o, alpha, 0, 0);
}
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha)
{
    mf_real a;
    mf__ltc_lookup(mf__ltc_ggx_data, MF__LTC_GGX_N, MF__LTC_GGX_N, cos_theta_o, alpha, &a, 0);
    return a;
}
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha)
{
    mf_real f;
    mf__ltc_lookup(mf__ltc_ggx_data, MF__LTC_GGX_N, MF__LTC_GGX_N, cos_theta_o, alpha, 0, &f);
    return f;
}
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha)
{
    if (n_theta) *n_theta = MF__LTC_GGX_N;
    if (n_alpha) *n_alpha = MF__LTC_GGX_N;
    return mf__ltc_ggx_data;
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
