/* @decl */
#define MF_VERSION_MAJOR 0
#define MF_VERSION_MINOR 4
#define MF_VERSION_PATCH 0

/* ======================================================================== */
/* == 1. Configuration and portability                                      */
/* ======================================================================== */
/* mf_real and its literals, the math-call macros, storage classes (MF_INLINE
 * hot paths, MF_COLD device-callable cold paths, MFDEF builders), the
 * allocator pair, the module opt-outs and the precision-tagged symbol names. */

#if defined(MF_MALLOC) && !defined(MF_FREE)
#error "microfacet.h: MF_MALLOC is defined but MF_FREE is not; define both or neither"
#endif
#if defined(MF_FREE) && !defined(MF_MALLOC)
#error "microfacet.h: MF_FREE is defined but MF_MALLOC is not; define both or neither"
#endif

#include <math.h>
#include <stddef.h>
#include <string.h>   /* memcpy: the IBM's packed 8-byte reads */

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
#ifndef MF_FLOOR
#define MF_FLOOR(x) floor(x)
#endif
#ifndef MF_CEIL
#define MF_CEIL(x) ceil(x)
#endif
#ifndef MF_TAN
#define MF_TAN(x) tan(x)
#endif
#ifndef MF_ATAN
#define MF_ATAN(x) atan(x)
#endif
#ifndef MF_ASIN
#define MF_ASIN(x) asin(x)
#endif
#define MF_EPS 2.220446049250313e-16
#define MF_U_MAX 0.99999999999999989   /* 1 - 2^-53: the largest double below 1 */
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
#ifndef MF_FLOOR
#define MF_FLOOR(x) floorf(x)
#endif
#ifndef MF_CEIL
#define MF_CEIL(x) ceilf(x)
#endif
#ifndef MF_TAN
#define MF_TAN(x) tanf(x)
#endif
#ifndef MF_ATAN
#define MF_ATAN(x) atanf(x)
#endif
#ifndef MF_ASIN
#define MF_ASIN(x) asinf(x)
#endif
#define MF_EPS 1.1920929e-7f
#define MF_U_MAX 0.99999994f            /* 1 - 2^-24: the largest float below 1 */
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
#define MF__INLINE_DEFAULT
#endif
/* MF_FORCE_INLINE: the small hot helpers (vector algebra, GGX and Beckmann D
 * and Lambda, the generic front ends, BRDF and dielectric evaluation, the LTC
 * edge term). At -O3 and in a translation unit holding the whole library,
 * gcc's unit-growth limits otherwise move some of them out of line, which
 * costs their callers more than the call saves (docs/PERFORMANCE.md). Unoptimized builds (gcc and clang without
 * __OPTIMIZE__) get plain MF_INLINE: forcing there only copies each front
 * end's whole dispatch into every caller, unfolded, and hides the calls from
 * debuggers. A user-defined MF_INLINE is kept as it is. */
#ifndef MF_FORCE_INLINE
#if !defined(MF__INLINE_DEFAULT)
#define MF_FORCE_INLINE MF_INLINE
#elif defined(__CUDACC__)
#define MF_FORCE_INLINE static __forceinline__ MF_HD
#elif (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE__)
#define MF_FORCE_INLINE MF_INLINE
#elif defined(__GNUC__) || defined(__clang__)
#define MF_FORCE_INLINE static inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define MF_FORCE_INLINE static __forceinline
#else
#define MF_FORCE_INLINE MF_INLINE
#endif
#endif
#ifndef MFDEF
#define MFDEF extern
#endif
/* MF__LIKELY(c): c is expected true; the compiler lays out its branch as
 * the straight path (fewer taken jumps in loops over the generic front
 * ends: they run faster when a second hardware thread shares the core). */
#if defined(__GNUC__) || defined(__clang__)
#define MF__LIKELY(c) __builtin_expect(!!(c), 1)
#else
#define MF__LIKELY(c) (c)
#endif
/* MF__PREFETCH(p): a hint that memory at p is read soon; no-op where the
 * compiler has no builtin for it and in device code. */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDA_ARCH__)
#define MF__PREFETCH(p) __builtin_prefetch((const void *)(p))
#else
#define MF__PREFETCH(p) ((void)(p))
#endif
/* MF__NOINLINE: keeps a rarely taken path out of its caller's code (where
 * inlining it cost the caller's hot loop: the IBM's few-texel path) */
#if defined(__CUDACC__)
#define MF__NOINLINE __noinline__
#elif defined(__GNUC__) || defined(__clang__)
#define MF__NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define MF__NOINLINE __declspec(noinline)
#else
#define MF__NOINLINE
#endif
/* MF__CLZ32(v), MF__CTZ32(v): leading and trailing zero bits of a nonzero
 * 32-bit unsigned, where the compiler has an instruction for them (undefined
 * here: portable code). */
#if defined(__CUDA_ARCH__)
#define MF__CLZ32(v) __clz((int)(v))
#define MF__CTZ32(v) (__ffs((int)(v)) - 1)
#elif defined(__GNUC__) || defined(__clang__)
#define MF__CLZ32(v) __builtin_clz(v)
#define MF__CTZ32(v) __builtin_ctz(v)
#endif
/* MF_COLD: functions that device code may call but that host includers need
 * not compile (numerical samplers, tabulated and IBM queries, the generic
 * dispatch of the rarer kinds). Host builds declare them here and define them
 * once, in the implementation; nvcc compiles them into every translation unit
 * as static device functions. */
#ifndef MF_COLD
#if defined(__CUDACC__)
#define MF_COLD static __noinline__ MF_HD
#else
#define MF_COLD MFDEF
#endif
#endif
#if !defined(MF_MALLOC)
#include <stdlib.h>
#define MF_MALLOC(n) malloc(n)
#define MF_FREE(p) free(p)
#endif

/* MF_FAST_MATH is 1 where the compiler may assume that no value is NaN or
 * Inf (gcc and clang -ffast-math or -ffinite-math-only), else 0: see FAST
 * MATH at the top for what then still holds. */
#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)
#define MF_FAST_MATH 1
#else
#define MF_FAST_MATH 0
#endif

/* Iterative solvers: every Newton, Halley, bisection, continued-fraction and
 * Nelder-Mead loop has a fixed iteration cap. MF__SOLVER_DONE(site, it, cap)
 * runs when such a loop ends, it = iterations taken (it == cap: stopped at the
 * cap without converging). Empty by default; the tests define it to record
 * the iterations each site takes on adversarial input. Sites: */
#define MF__SITE_BETACF 0      /* incomplete-beta continued fraction, 300 */
#define MF__SITE_PHI_COS 1     /* azimuth of the visible-normal samplers, 60 */
#define MF__SITE_NUM_VNDF 2    /* numerical visible-normal inversion, 50 */
#define MF__SITE_TAB_THETA 3   /* tabulated theta inversion, 60 */
#define MF__SITE_TAB_PHI 4     /* tabulated anisotropic azimuth, 60 */
#define MF__SITE_BECKMANN 5    /* Beckmann visible slope (Halley), 60 */
#define MF__SITE_LTC_FIT 6     /* Nelder-Mead of the LTC fit, 400 per restart */
#define MF__SITE_REJECT 7      /* GTR and Student-t visible-normal rejection, 64 */
#define MF__SITE_COUNT 8
#ifndef MF__SOLVER_DONE
#define MF__SOLVER_DONE(site, it, cap) ((void)0)
#endif

/* Module opt-outs (define before including, the same in every file):
 *   MF_NO_LEADR        LEADR moments and maps (the non-centered Beckmann kind
 *                      of mf_ndf stays)
 *   MF_NO_LTC_TABLE    the built-in LTC tables (GGX, Beckmann, volumetric
 *                      sheen) and their accessors
 *   MF_NO_IBM          the Inverse Bin Map
 *   MF_NO_MICROSURFACE microsurface generation and the gonioreflectometer
 *   MF_NO_ENERGY_TABLES the built-in rough-dielectric albedo tables
 *                      (mf_dielectric_albedo and mf_dielectric_bsdf_ms then
 *                      integrate for every kind) */

/* Precision-tagged symbols: every non-inline function is emitted as
 * <name>_f32 (float) or <name>_f64 (MF_USE_DOUBLE), so a program may hold
 * both precisions (in different translation units), and an implementation
 * compiled in one precision never satisfies calls made in the other: the
 * link fails naming mf_..._f32 or mf_..._f64. The list below is generated
 * from every MFDEF / MF_COLD declaration by tools/amalgamate.sh. */
#ifdef MF_USE_DOUBLE
#define MF__SYM(name) name##_f64
#else
#define MF__SYM(name) name##_f32
#endif
/* @symbols */

/* Precision guard: every file that includes the header references a symbol
 * named after its precision, mf_precision_is_float_... or
 * mf_precision_is_double_..., that only an implementation of that precision
 * defines. A program whose files disagree on MF_USE_DOUBLE, or that lacks an
 * implementation file of a precision it uses, then fails to link naming the
 * precision, even when it calls only inline functions (an mf_ndf made in a
 * float file and read in a double one would otherwise be misread silently).
 * So every program defines MICROFACET_IMPLEMENTATION in one file per
 * precision it uses, as it had to already for anything but the kind-specific
 * functions: the generic front ends call the cold paths of the rarer kinds,
 * which only an optimizer that sees the kind folds away. The reference is a
 * static pointer kept by the attribute used (gcc, clang; on ELF also retain,
 * where the compiler has it, so that --gc-sections keeps it too) or a /include
 * linker directive (MSVC); other compilers check nothing. */
#ifdef MF_USE_DOUBLE
#define MF__PRECISION_GUARD mf_precision_is_double_define_MICROFACET_IMPLEMENTATION_in_a_double_file
#else
#define MF__PRECISION_GUARD mf_precision_is_float_define_MICROFACET_IMPLEMENTATION_in_a_float_file
#endif
#ifdef __cplusplus
extern "C" {
#endif
extern const int MF__PRECISION_GUARD;
#ifdef __cplusplus
}
#endif
#if !defined(__CUDACC_RTC__)
#if defined(__GNUC__) || defined(__clang__)
#if defined(__ELF__) && !defined(__CUDACC__) && defined(__has_attribute)
#if __has_attribute(retain)
#define MF__KEEP __attribute__((used, retain))
#endif
#endif
#ifndef MF__KEEP
#define MF__KEEP __attribute__((used))
#endif
static const int *const mf__precision_ref MF__KEEP = &MF__PRECISION_GUARD;
#elif defined(_MSC_VER)
#define MF__STR2(x) #x
#define MF__STR(x) MF__STR2(x)
#if defined(_M_IX86)
#pragma comment(linker, "/include:_" MF__STR(MF__PRECISION_GUARD))
#else
#pragma comment(linker, "/include:" MF__STR(MF__PRECISION_GUARD))
#endif
#endif
#endif

/* Result codes of builders. */
typedef enum mf_result {
    MF_SUCCESS = 0,
    MF_ERROR_INVALID_ARGUMENT = -1,
    MF_ERROR_OUT_OF_MEMORY = -2,
    MF_ERROR_INVALID_DATA = -3,
    MF_ERROR_BUFFER_TOO_SMALL = -4
} mf_result;
/* @api */
/* A short English name of a result code. */
MFDEF const char *mf_result_string(mf_result r);
/* @impl */
/* the precision guard's one definition (see MF__PRECISION_GUARD above) */
const int MF__PRECISION_GUARD = 1;

MFDEF const char *mf_result_string(mf_result r)
{
    switch (r) {
    case MF_SUCCESS: return "success";
    case MF_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case MF_ERROR_OUT_OF_MEMORY: return "out of memory";
    case MF_ERROR_INVALID_DATA: return "invalid data";
    case MF_ERROR_BUFFER_TOO_SMALL: return "buffer too small";
    default: return "unknown result";
    }
}

/* 1 if n is a positive power of two (the map builders' sizes). */
MF_INLINE int mf__pow2(int n) { return n > 0 && (n & (n - 1)) == 0; }
