/* microfacet.h - GENERATED FILE, do not edit: edit the module sources in
 * src/ and run `make header` (tools/amalgamate.sh). Assembled from:
 *   00_intro.h 01_config.h 02_vec.h 03_fresnel.h 04_special.h 05_ndf.h
 *   06_kind_beckmann.h 06_kind_ggx.h 06_kind_gtr.h 06_kind_leadr.h
 *   06_kind_student_t.h 06_kind_tabulated.h 07_numeric_vndf.h 08_transform.h
 *   09_smith.h 10_sampling.h 11_brdf.h 11_dielectric.h 12_leadr.h 13_ltc.h
 *   14_ltc_table.h 14_ltc_table_beckmann.h 15_ibm.h 16_microsurface.h
 *   17_energy_table.h 18_energy.h 99_outro.h
 */
/* microfacet.h - microfacet BRDF/NDF math in one dependency-free C header.
 * Version 0.3.0.  MIT licensed (see the end of this file).
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
 *   This file is generated from one source file per module, src/NN_name.h
 *   (tools/amalgamate.sh). Each module contributes its declarations and hot
 *   inline paths below, its cold paths and its implementation further down.
 *
 *   == 1. Configuration and portability (mf_real, MF_HD, MF_INLINE, MF_COLD,
 *         MFDEF, allocators, opt-outs, precision-tagged symbols)
 *   == 2. Vectors, 2x2 matrices and frames
 *   == 3. Fresnel
 *   == 4. Special functions (erf inverse, incomplete beta, stable helpers,
 *         Newton steps and Gauss-Legendre nodes for the numerical samplers)
 *   == 5. Distributions: the mf_ndf value type, its kinds and the one
 *         dispatch point
 *   == 6. Distribution kinds, one module each: Beckmann, GGX, GTR, LEADR
 *         (non-centered Beckmann), Student-t, tabulated (piecewise-linear)
 *   == 7. Numerical visible-normal sampling of the heavy-tailed kinds
 *   == 8. Linearly transformed microsurfaces: any 2x2 transform of any
 *         distribution, stretch anisotropy, deformation tracking; mf_D
 *   == 9. Smith masking: Lambda, G1, G2 (height-correlated, separable), D_visible
 *   == 10. Sampling: NDF (D cos) and visible normals (VNDF) for every kind
 *   == 11. Specular microfacet BRDF: eval, sample, pdf; GGX bounded VNDF
 *         sampling; Fresnel averages
 *   == 11b. Rough dielectric BSDF (reflection and transmission), refraction
 *   == 12. LEADR slope moments: the linear type, deformation, height scaling,
 *          mean normal, covariance; moment mip maps
 *   == 13. Linearly Transformed Cosines: eval, sample, polygon integration with
 *          horizon clipping, vector form factor, sphere lights, multi-scale
 *          roughness, fitting and tables
 *   == 14. The built-in GGX LTC table (generated data)
 *   == 15. Inverse Bin Map: compact integral histograms of normal maps,
 *          footprint queries, the filtered glint BRDF, sampling and pdf
 *   == 16. Microsurface generation from any distribution and a virtual
 *          gonioreflectometer
 *   == 17. The built-in GGX and Beckmann albedo tables (generated data)
 *   == 18. Energy compensation (Kulla & Conty 2017): albedo, the multiple-
 *          scattering lobe and its sampling, Turquin scaling, table builders
 *          for any kind, rough dielectrics of a given eta
 *
 * ADDING A DISTRIBUTION KIND
 *
 *   1. Write src/06_kind_<name>.h (06_kind_ggx.h shows the layout): its
 *      parameter struct mf_ndf_<name> in the @decl part, a constructor that
 *      fills mf_ndf through mf__ndf_init, and mf__<name>_D, _lambda,
 *      _sample_D and _sample_visible (contract in 05_ndf.h).
 *   2. Add the line X(NAME, name) to MF__NDF_KINDS in src/05_ndf.h.
 *   3. Add the kind to the test cases of tests/main.c (normalization, masking,
 *      sampling chi-square, BRDF battery and robustness sweep then cover it),
 *      run `make header` and `make test`.
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
 *     but finite (w.z^2 is clamped to 1e-30 inside the slope, alpha^2 tan^2
 *     to 1e30). D, D_visible, the projected area, mf_brdf and mf_brdf_pdf are
 *     capped at MF_BIG (1e30 in float): grazing retro-reflection and
 *     transforms with tiny entries reach it. Random numbers outside [0, 1]
 *     are clamped to it (NaN: 0). mf_brdf_sample returns a direction only
 *     where mf_brdf_pdf is positive.
 *   - Transforms: mf_transform_valid also requires |det M| > 1/MF_BIG, so
 *     that M^-1 is finite in mf_real.
 *   - LEADR moments: variances are clamped to [1e-8, 5e7] (alpha up to
 *     MF_ALPHA_MAX); map builders reject normals with z < 1e-4.
 *   - Microsurface generation: at most MF_MICROSURFACE_MAX_ITERATIONS =
 *     100000 iterations (more is an invalid argument).
 *   - Iterative solvers: every Newton, Halley, bisection, continued-fraction
 *     and Nelder-Mead loop has a fixed cap (50 to 400 iterations; the sites
 *     are listed with MF__SOLVER_DONE in the configuration section). A loop
 *     stopped by its cap returns its bracketed or best point, never NaN;
 *     the tests drive each site with adversarial input (u at 0, 1, NaN and
 *     out of range; alpha 1e-4 and 1e4; grazing views; noise BRDFs for the
 *     LTC fit) and reach the caps that can be reached.
 *   - Tabulated distributions: control angles span [0, pi/2] (the ends are
 *     snapped within 1e-4 rad), at most MF_TABULATED_MAX_POINTS = 4096; D is
 *     linear in theta between them; Lambda interpolates a projected-area table
 *     built by exact integration (relative error ~1e-9 in double).
 *   - Inverse Bin Map: flake alpha is clamped like every alpha and rounded to
 *     float; at most MF_IBM_MAX_RES = 1024 bins per axis (alpha below about
 *     0.0023 gets coarser bins than Eq. 5.14); footprints under
 *     MF_IBM_MIN_AREA = 1e-6 texel^2 are point lookups, slivers thinner than
 *     64 ulps of the map size (float: 0.002 texel at 256^2) are widened to
 *     that; footprints whose boundary cuts more than MF_IBM_MAX_PIECES = 64
 *     period cells use the whole map's histogram.
 *
 * CONFIGURATION MACROS (define before including)
 *
 *   MF_USE_DOUBLE           mf_real is double (default float)
 *   MICROFACET_IMPLEMENTATION  emit the non-inline functions in this file
 *   MFDEF                   storage of non-inline functions (default extern)
 *   MF_MALLOC(n) / MF_FREE(p)  allocator pair (default malloc/free); define
 *                           both or neither (one alone is an #error)
 *   MF_NO_LEADR, MF_NO_LTC_TABLE, MF_NO_IBM, MF_NO_MICROSURFACE
 *                           leave out a module (see section 1)
 *   MF_SQRT, MF_EXP, ...    every math call goes through a macro of this form;
 *                           define one to replace it (e.g. with an intrinsic)
 *
 * FAST MATH (-ffast-math, __FAST_MATH__)
 *
 *   Detected: MF_FAST_MATH is 1 under gcc and clang -ffast-math or
 *   -ffinite-math-only (MSVC /fp:fast is not detectable), so a renderer can
 *   test it, e.g. to add its own NaN guards; the header itself emits no
 *   warning.
 *   The compiler may then assume that no value is NaN or Inf and fold the
 *   comparisons this header uses to catch them. What still holds: builders
 *   and loaders never let NaN or Inf data index memory (the IBM builder and
 *   footprint queries test the bits of their floats, bin and texel indices
 *   are clamped after conversion; tests/fastmath_check.c, run by make test,
 *   checks this in float and double). What does not: the promise "0, never
 *   NaN or Inf" for NaN or Inf arguments of the math functions (they may
 *   propagate NaN), and results at the edges of the documented domains may
 *   differ by more than the tested tolerances (the full test suite built
 *   with -ffast-math is not expected to pass).
 *
 * ERROR MODEL
 *
 *   Hot-path functions never allocate, log or abort; outside their domain they
 *   return 0. Builders (LEADR moment maps, LTC fitting and tables, tabulated
 *   distributions, the Inverse Bin Map, microsurface generation) validate input
 *   and return an mf_result (MF_SUCCESS = 0, negative codes for errors;
 *   mf_result_string() names them) and leave nothing allocated on failure.
 *   There is no global error state.
 *
 * REVISIONS
 *
 *   0.1.0  first release: Beckmann, GGX, GTR, Student-t; Smith Lambda, G1, G2;
 *          NDF and VNDF sampling; specular BRDF; Fresnel; linearly transformed
 *          microsurfaces for every distribution; LEADR mapping; Linearly
 *          Transformed Cosines (polygon integration, fitter, tables, built-in
 *          GGX table).
 *   0.2.0  Tabulated (piecewise-linear) distributions as a kind of mf_ndf
 *          (mf_tabulated_build, mf_tabulated_from_ndf): every generic operation,
 *          transforms included; mf_ndf gains the field tab.
 *          Microsurface generation: height fields from any distribution
 *          (Ribardiere et al. 2019, Alg. 1) and a virtual gonioreflectometer.
 *          IBM: Inverse Bin Map (thesis ch. 5): builder, save/load, exact
 *          footprint bin weights, filtered glint BRDF, sampling and pdf.
 *   0.3.0  One source file per module under src/, this header generated from
 *          them. Per-kind parameters are typed structs in mf_ndf.p (the
 *          fields gamma, c[] and tab are gone: mf_ndf.p.gtr.gamma, ...,
 *          mf_ndf.p.tabulated.tab); kinds dispatch through MF__NDF_KINDS.
 *          Cold paths (numerical samplers, tabulated and IBM queries) are
 *          compiled once, in the implementation (every unit under nvcc).
 *          Non-inline symbols carry their precision (mf_..._f32/_f64).
 *          Opt-outs MF_NO_LEADR, MF_NO_LTC_TABLE, MF_NO_IBM,
 *          MF_NO_MICROSURFACE; MF_ASSERT removed (it was never used).
 *          Shading frames (mf_basis: mf_basis_from, mf_to_local, mf_to_world,
 *          mf_basis_ltc), mf_rotated, roughness conventions
 *          (mf_alpha_from_roughness, mf_beckmann_alpha_from_sigma and
 *          inverses), Fresnel helpers (f0 and ior, Schlick with f90,
 *          Gulbrandsen's artist conductor, hemispherical averages), GGX
 *          bounded visible-normal sampling (Eto & Tokuyoshi 2023). Rough
 *          dielectric BSDF (Walter et al. 2007) for every kind, both sides,
 *          eval / pdf / sample / weight, and mf_refract. Beckmann visible
 *          normals by safeguarded Halley steps from a view-dependent start.
 *          Fuzz-found fixes: capped Lambda, D, pdf and LEADR variances, rejected
 *          transforms with an overflowing inverse, LEADR map and LTC input
 *          validation, exact IBM weights of sub-texel footprints, a sample
 *          only where its pdf is positive, mf_clamp maps NaN to the lower
 *          bound, MF_MICROSURFACE_MAX_ITERATIONS; bit-level checks that hold
 *          under -ffast-math. Energy compensation for conductors and
 *          rough dielectrics (Kulla & Conty 2017; Turquin 2019 scaling).
 *          GTR Lambda exact at every gamma (a Gauss-Jacobi rule over an exact
 *          mixture, built by mf_gtr: mf_ndf is larger, 288 bytes in float);
 *          no lost samples at grazing views for any kind. LTC: rational
 *          edge, one normalization per vertex; tables store M^-1 with a unit
 *          middle entry (the published texture layout: the raw data of
 *          mf_ltc_ggx_table, mf_ltc_table and mf_ltc_fit_result.inv changed
 *          meaning), mf_ltc_table_export_rgba16f. MF_FORCE_INLINE on the hot
 *          paths; Beckmann visible normals in closed form at normal
 *          incidence; faster IBM queries; MF_FAST_MATH; solver iteration
 *          caps reported to tests (MF__SOLVER_DONE).
 */
#ifndef MICROFACET_H
#define MICROFACET_H

#define MF_VERSION_MAJOR 0
#define MF_VERSION_MINOR 3
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
 * gcc's unit-growth limits otherwise move some of them out of line and the
 * callers get up to 2x slower. A user-defined MF_INLINE is kept as it is. */
#ifndef MF_FORCE_INLINE
#if !defined(MF__INLINE_DEFAULT)
#define MF_FORCE_INLINE MF_INLINE
#elif defined(__CUDACC__)
#define MF_FORCE_INLINE static __forceinline__ MF_HD
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
#define MF__SITE_COUNT 7
#ifndef MF__SOLVER_DONE
#define MF__SOLVER_DONE(site, it, cap) ((void)0)
#endif

/* Module opt-outs (define before including, the same in every file):
 *   MF_NO_LEADR        LEADR moments and maps (the non-centered Beckmann kind
 *                      of mf_ndf stays)
 *   MF_NO_LTC_TABLE    the built-in GGX LTC table and its accessors
 *   MF_NO_IBM          the Inverse Bin Map
 *   MF_NO_MICROSURFACE microsurface generation and the gonioreflectometer */

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
#define mf_result_string MF__SYM(mf_result_string)
#define mf__ndf_D MF__SYM(mf__ndf_D)
#define mf__ndf_lambda MF__SYM(mf__ndf_lambda)
#define mf__ndf_sample_D MF__SYM(mf__ndf_sample_D)
#define mf__ndf_sample_visible MF__SYM(mf__ndf_sample_visible)
#define mf__beckmann_visible_slopes MF__SYM(mf__beckmann_visible_slopes)
#define mf__gtr_mix_init MF__SYM(mf__gtr_mix_init)
#define mf__gtr_D MF__SYM(mf__gtr_D)
#define mf__gtr_lambda MF__SYM(mf__gtr_lambda)
#define mf__gtr_sample_D MF__SYM(mf__gtr_sample_D)
#define mf__gtr_sample_visible MF__SYM(mf__gtr_sample_visible)
#define mf__gtr_tan2 MF__SYM(mf__gtr_tan2)
#define mf__gtr_tail MF__SYM(mf__gtr_tail)
#define mf__leadr_D MF__SYM(mf__leadr_D)
#define mf__leadr_lambda MF__SYM(mf__leadr_lambda)
#define mf__leadr_sample_D MF__SYM(mf__leadr_sample_D)
#define mf__leadr_sample_visible MF__SYM(mf__leadr_sample_visible)
#define mf__student_t_D MF__SYM(mf__student_t_D)
#define mf__student_t_lambda MF__SYM(mf__student_t_lambda)
#define mf__student_t_sample_D MF__SYM(mf__student_t_sample_D)
#define mf__student_t_sample_visible MF__SYM(mf__student_t_sample_visible)
#define mf__student_t_tan2 MF__SYM(mf__student_t_tan2)
#define mf__student_t_tail MF__SYM(mf__student_t_tail)
#define mf_tabulated_build MF__SYM(mf_tabulated_build)
#define mf_tabulated_from_ndf MF__SYM(mf_tabulated_from_ndf)
#define mf_tabulated_release MF__SYM(mf_tabulated_release)
#define mf_tabulated_memory_bytes MF__SYM(mf_tabulated_memory_bytes)
#define mf__tabulated_D MF__SYM(mf__tabulated_D)
#define mf__tabulated_lambda MF__SYM(mf__tabulated_lambda)
#define mf__tabulated_sample_D MF__SYM(mf__tabulated_sample_D)
#define mf__tabulated_sample_visible MF__SYM(mf__tabulated_sample_visible)
#define mf__iso_sample_visible_view MF__SYM(mf__iso_sample_visible_view)
#define mf_fresnel_dielectric_average MF__SYM(mf_fresnel_dielectric_average)
#define mf_fresnel_conductor_average MF__SYM(mf_fresnel_conductor_average)
#define mf_leadr_map_from_heights MF__SYM(mf_leadr_map_from_heights)
#define mf_leadr_map_from_normals MF__SYM(mf_leadr_map_from_normals)
#define mf_leadr_map_release MF__SYM(mf_leadr_map_release)
#define mf_leadr_map_memory_bytes MF__SYM(mf_leadr_map_memory_bytes)
#define mf_ltc_fit MF__SYM(mf_ltc_fit)
#define mf_ltc_table_build MF__SYM(mf_ltc_table_build)
#define mf_ltc_table_release MF__SYM(mf_ltc_table_release)
#define mf_ltc_table_lookup MF__SYM(mf_ltc_table_lookup)
#define mf_ltc_table_export_rgba16f MF__SYM(mf_ltc_table_export_rgba16f)
#define mf_ltc_ggx MF__SYM(mf_ltc_ggx)
#define mf_ltc_ggx_albedo MF__SYM(mf_ltc_ggx_albedo)
#define mf_ltc_ggx_fresnel MF__SYM(mf_ltc_ggx_fresnel)
#define mf_ltc_ggx_table MF__SYM(mf_ltc_ggx_table)
#define mf_ltc_beckmann MF__SYM(mf_ltc_beckmann)
#define mf_ltc_beckmann_albedo MF__SYM(mf_ltc_beckmann_albedo)
#define mf_ltc_beckmann_fresnel MF__SYM(mf_ltc_beckmann_fresnel)
#define mf_ltc_beckmann_table MF__SYM(mf_ltc_beckmann_table)
#define mf_ibm_bin_texels MF__SYM(mf_ibm_bin_texels)
#define mf_ibm_bin_normal MF__SYM(mf_ibm_bin_normal)
#define mf_ibm_texel_bin MF__SYM(mf_ibm_texel_bin)
#define mf_ibm_set_shadowing MF__SYM(mf_ibm_set_shadowing)
#define mf_ibm_bin_weight MF__SYM(mf_ibm_bin_weight)
#define mf_ibm_neighbourhood_weights MF__SYM(mf_ibm_neighbourhood_weights)
#define mf_ibm_brdf MF__SYM(mf_ibm_brdf)
#define mf_ibm_pdf MF__SYM(mf_ibm_pdf)
#define mf_ibm_brdf_pdf MF__SYM(mf_ibm_brdf_pdf)
#define mf_ibm_sample MF__SYM(mf_ibm_sample)
#define mf_ibm_build MF__SYM(mf_ibm_build)
#define mf_ibm_build_ex MF__SYM(mf_ibm_build_ex)
#define mf_ibm_release MF__SYM(mf_ibm_release)
#define mf_ibm_memory_bytes MF__SYM(mf_ibm_memory_bytes)
#define mf_ibm_save MF__SYM(mf_ibm_save)
#define mf_ibm_load MF__SYM(mf_ibm_load)
#define mf_microsurface_options_default MF__SYM(mf_microsurface_options_default)
#define mf_microsurface_generate MF__SYM(mf_microsurface_generate)
#define mf_microsurface_generate_ex MF__SYM(mf_microsurface_generate_ex)
#define mf_microsurface_integrate MF__SYM(mf_microsurface_integrate)
#define mf_gonio_config_default MF__SYM(mf_gonio_config_default)
#define mf_gonio_init MF__SYM(mf_gonio_init)
#define mf_gonio_release MF__SYM(mf_gonio_release)
#define mf_gonio_cell MF__SYM(mf_gonio_cell)
#define mf_gonio_cell_center MF__SYM(mf_gonio_cell_center)
#define mf_gonio_cell_solid_angle MF__SYM(mf_gonio_cell_solid_angle)
#define mf_gonio_cell_bounds MF__SYM(mf_gonio_cell_bounds)
#define mf_gonio_measure MF__SYM(mf_gonio_measure)
#define mf_gonio_model MF__SYM(mf_gonio_model)
#define mf_albedo MF__SYM(mf_albedo)
#define mf_albedo_average MF__SYM(mf_albedo_average)
#define mf_brdf_ms MF__SYM(mf_brdf_ms)
#define mf_ms_turquin_scale MF__SYM(mf_ms_turquin_scale)
#define mf_albedo_integrate MF__SYM(mf_albedo_integrate)
#define mf_albedo_table_build MF__SYM(mf_albedo_table_build)
#define mf_albedo_table_release MF__SYM(mf_albedo_table_release)
#define mf_albedo_table_eval MF__SYM(mf_albedo_table_eval)
#define mf_albedo_table_average MF__SYM(mf_albedo_table_average)
#define mf_brdf_ms_table MF__SYM(mf_brdf_ms_table)
#define mf_dielectric_ms_build MF__SYM(mf_dielectric_ms_build)
#define mf_dielectric_ms_release MF__SYM(mf_dielectric_ms_release)
#define mf_dielectric_albedo MF__SYM(mf_dielectric_albedo)
#define mf_dielectric_albedo_integrate MF__SYM(mf_dielectric_albedo_integrate)
#define mf_dielectric_bsdf_ms MF__SYM(mf_dielectric_bsdf_ms)
#define mf_dielectric_ms_sample MF__SYM(mf_dielectric_ms_sample)
#define mf_dielectric_ms_pdf MF__SYM(mf_dielectric_ms_pdf)

/* Result codes of builders. */
typedef enum mf_result {
    MF_SUCCESS = 0,
    MF_ERROR_INVALID_ARGUMENT = -1,
    MF_ERROR_OUT_OF_MEMORY = -2,
    MF_ERROR_INVALID_DATA = -3
} mf_result;
typedef struct mf_vec3 { mf_real x, y, z; } mf_vec3;
typedef struct mf_mat2 { mf_real m00, m01, m10, m11; } mf_mat2; /* row-major */
/* An orthonormal, right-handed shading frame: t (tangent, the x axis of the
 * local frame, along which alpha_x applies), b = n x t, n (the z axis). */
typedef struct mf_basis { mf_vec3 t, b, n; } mf_basis;
typedef struct mf_ndf_beckmann { char none; } mf_ndf_beckmann;   /* no parameters beyond mf_ndf.ax, ay */
typedef struct mf_ndf_ggx { char none; } mf_ndf_ggx;   /* no parameters beyond mf_ndf.ax, ay */
/* nodes of the Lambda mixture rule: 16 for gamma < 2, 24 for gamma > 2
 * (measured accuracy in mf__gtr_lambda) */
#define MF__GTR_NQ 24
typedef struct mf_ndf_gtr {
    mf_real gamma;      /* tail exponent in [0, 4] */
    mf_real norm;       /* N of D = N / (sin^2 + a^2 cos^2)^gamma */
    mf_real L;          /* log(alpha^2) */
    mf_real E, EM;      /* expm1((1 - gamma) L), expm1(-(1 - gamma) L) */
    mf_real RK, RMK;    /* kL / expm1(kL) and -kL / expm1(-kL), k = 1 - gamma */
    int mix;            /* Lambda: 0 closed form (integer gamma), 1 GGX mixture, 2 gamma-4 mixture */
    int nq;             /* nodes of the mixture rule */
    mf_real qb[MF__GTR_NQ], qw[MF__GTR_NQ];   /* mixture nodes alpha_b^2 and weights */
} mf_ndf_gtr;
typedef struct mf_ndf_leadr {
    mf_real mx, my;            /* mean slope */
    mf_real vx, vy, cxy;       /* covariance */
    mf_real ixx, iyy, ixy;     /* inverse covariance */
    mf_real norm;              /* 1 / (2 pi sqrt(det)) (Eq. 8) */
    mf_real l00, l10, l11;     /* Cholesky factor, L L^T = covariance */
} mf_ndf_leadr;
typedef struct mf_ndf_student_t {
    mf_real gamma;      /* in [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] */
    mf_real K;          /* marginal slope density constant: P2(x) = K (1 + x^2/(g-1))^(1/2-g) */
    mf_real lbeta;      /* log B(gamma - 1, 1/2) */
    mf_real vndf_p;     /* tail exponent of the numerical VNDF sampler's substitution */
} mf_ndf_student_t;
/* A tabulated (piecewise-linear) distribution: the arrays of one built NDF, all
 * in one allocation (block, bytes) owned until mf_tabulated_release. Fields are
 * filled by the builders; read them, do not write them. For CUDA, copy block to
 * the device and use mf_tabulated_rebase (below) to point a copy of the
 * struct at it; pass that struct by value to the kernel and take its address. */
typedef struct mf_tabulated {
    int n;              /* control points, theta[0] = 0 < ... < theta[n-1] = pi/2 */
    int aniso;          /* 0: one curve (dy == dx, cy == cx) */
    int n_lam;          /* nodes of the projected-area table */
    mf_real inv_h;      /* 1 / spacing when the control points are uniform, else 0 */
    mf_real inv_hl;     /* the same for the projected-area nodes */
    mf_real wx, wy;     /* Eq. 10 weights D_y(0)/c and D_x(0)/c, c = (D_x(0) + D_y(0))/2; 1, 1 if c = 0 */
    mf_real scale;      /* median tan(theta) of D cos: a characteristic slope (used by no formula) */
    mf_real *theta;     /* n control angles */
    mf_real *dx, *dy;   /* the normalized curves at the control points (Eq. 11-12) */
    mf_real *cx, *cy;   /* cumulative D cos mass 2 pi int_0^theta D cos sin, 0 .. 1 */
    mf_real *lt;        /* n_lam view angles theta_o of the table, 0 .. pi/2 */
    mf_real *li;        /* per node: I0, dI0/dtheta_o, I2, dI2/dtheta_o (mf__tabulated_lambda) */
    void *block;        /* the allocation holding every array above */
    size_t bytes;
} mf_tabulated;
typedef struct mf_ndf_tabulated {
    const mf_tabulated *tab;   /* the tables of a built distribution; 0: every function returns 0 */
} mf_ndf_tabulated;

#ifdef __cplusplus
extern "C" {
#endif

/* A short English name of a result code. */
MFDEF const char *mf_result_string(mf_result r);
/* ======================================================================== */
/* == 2. Vectors and frames                                                 */
/* ======================================================================== */

MF_FORCE_INLINE mf_vec3 mf_vec3_make(mf_real x, mf_real y, mf_real z)
{
    mf_vec3 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}
MF_FORCE_INLINE mf_real mf_dot(mf_vec3 a, mf_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
MF_FORCE_INLINE mf_vec3 mf_add(mf_vec3 a, mf_vec3 b) { return mf_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
MF_FORCE_INLINE mf_vec3 mf_scale(mf_vec3 a, mf_real s) { return mf_vec3_make(a.x * s, a.y * s, a.z * s); }
MF_FORCE_INLINE mf_vec3 mf_cross(mf_vec3 a, mf_vec3 b)
{
    return mf_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* x clamped to [lo, hi]; NaN gives lo */
MF_FORCE_INLINE mf_real mf_clamp(mf_real x, mf_real lo, mf_real hi) { return x >= lo ? (x <= hi ? x : hi) : lo; }
MF_FORCE_INLINE mf_real mf_max(mf_real a, mf_real b) { return a > b ? a : b; }
MF_FORCE_INLINE mf_real mf_min(mf_real a, mf_real b) { return a < b ? a : b; }
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
 * Malley's method) from u1, u2 in [0, 1]. */
MF_INLINE mf_vec3 mf__sample_cosine(mf_real u1, mf_real u2)
{
    mf_real r, phi;
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    r = MF_SQRT(u1);
    phi = MF_R(2.0) * MF_PI * u2;
    return mf_vec3_make(r * MF_COS(phi), r * MF_SIN(phi), MF_SQRT(mf_max(MF_R(1.0) - u1, MF_R(0.0))));
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

/* The shading frame of the normal n and a tangent: n normalized, the tangent
 * made orthogonal to it (Gram-Schmidt). When the tangent is zero, not finite
 * or parallel to n (its orthogonal part below 1e-4 of its length), any
 * orthonormal frame around n (mf_frame); a zero or non-finite n gives the
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
    } else mf_frame(n, &f.t, &f.b);
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
/* ======================================================================== */
/* == 3. Fresnel                                                            */
/* ======================================================================== */
/* Unpolarized reflectance of a smooth interface. cos_theta_i is the cosine
 * between the incident direction and the normal on the incident side. */

/* Dielectric; eta = n_transmitted / n_incident, clamped to [1e-6, 1e6] (<= 0
 * or NaN gives 0). A negative cos_theta_i means the light arrives from the
 * other side: eta is inverted. 1 on total internal reflection. */
MF_FORCE_INLINE mf_real mf_fresnel_dielectric(mf_real cos_theta_i, mf_real eta)
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


/* Normal-incidence reflectance of a dielectric of relative index eta,
 * ((eta - 1) / (eta + 1))^2, and the eta > 1 giving f0 (f0 in [0, 1), clamped
 * below 1 - 1e-6). Non-finite or non-positive input gives 0 / 1. */
MF_INLINE mf_real mf_f0_from_ior(mf_real eta)
{
    mf_real r;
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG)) return MF_R(0.0);
    r = (eta - MF_R(1.0)) / (eta + MF_R(1.0));
    return r * r;
}
MF_INLINE mf_real mf_ior_from_f0(mf_real f0)
{
    mf_real s;
    if (!(f0 > MF_R(0.0))) return MF_R(1.0);
    s = MF_SQRT(mf_min(f0, MF_R(1.0) - MF_R(1e-6)));
    return (MF_R(1.0) + s) / (MF_R(1.0) - s);
}

/* Schlick with an edge value: f0 + (f90 - f0)(1 - cos)^5 (f90 = 1 is
 * mf_fresnel_schlick; Burley 2012 and Filament use f90 for specular occlusion). */
MF_FORCE_INLINE mf_real mf_fresnel_schlick_f90(mf_real f0, mf_real f90, mf_real cos_theta)
{
    mf_real m = MF_R(1.0) - mf_clamp(cos_theta, MF_R(0.0), MF_R(1.0)), m2;
    if (!(m == m)) m = MF_R(0.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    f90 = mf_clamp(f90, MF_R(0.0), MF_R(1.0));
    m2 = m * m;
    return f0 + (f90 - f0) * m2 * m2 * m;
}
/* Schlick's approximation f0 + (1 - f0)(1 - cos)^5: the f90 = 1 case. */
MF_FORCE_INLINE mf_real mf_fresnel_schlick(mf_real f0, mf_real cos_theta)
{
    return mf_fresnel_schlick_f90(f0, MF_R(1.0), cos_theta);
}

/* Artist-friendly conductor Fresnel (Gulbrandsen 2014, "Artist Friendly
 * Metallic Fresnel", JCGT 3(4)): reflectivity r (the color at normal
 * incidence) and edge tint g, both in [0, 1] per channel, to the complex index
 * eta + i k whose exact Fresnel (mf_fresnel_conductor) has f0 = r (Eqs. 3-4):
 *   eta = g (1 - r) / (1 + r) + (1 - g) (1 + sqrt r) / (1 - sqrt r),
 *   k = sqrt((r (eta + 1)^2 - (eta - 1)^2) / (1 - r)).
 * r is clamped to [0, 0.9999], g to [0, 1]. And back: r from eta and k, g
 * from where eta lies between the two limits. */
MF_INLINE void mf_conductor_from_artist(mf_real r, mf_real g, mf_real *eta, mf_real *k)
{
    mf_real sr, n, k2;
    r = r == r ? mf_clamp(r, MF_R(0.0), MF_R(0.9999)) : MF_R(0.0);
    g = g == g ? mf_clamp(g, MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
    sr = MF_SQRT(r);
    n = g * (MF_R(1.0) - r) / (MF_R(1.0) + r) + (MF_R(1.0) - g) * (MF_R(1.0) + sr) / (MF_R(1.0) - sr);
    k2 = (r * (n + MF_R(1.0)) * (n + MF_R(1.0)) - (n - MF_R(1.0)) * (n - MF_R(1.0))) / (MF_R(1.0) - r);
    *eta = n;
    *k = MF_SQRT(mf_max(k2, MF_R(0.0)));
}
MF_INLINE void mf_artist_from_conductor(mf_real eta, mf_real k, mf_real *r, mf_real *g)
{
    mf_real sr, nmin, nmax, rr;
    if (!(eta > MF_R(0.0)) || !(k >= MF_R(0.0)) || !(eta < MF_BIG) || !(k < MF_BIG)) { *r = *g = MF_R(0.0); return; }
    rr = ((eta - MF_R(1.0)) * (eta - MF_R(1.0)) + k * k) / ((eta + MF_R(1.0)) * (eta + MF_R(1.0)) + k * k);
    rr = mf_clamp(rr, MF_R(0.0), MF_R(0.9999));
    sr = MF_SQRT(rr);
    nmin = (MF_R(1.0) - rr) / (MF_R(1.0) + rr);
    nmax = (MF_R(1.0) + sr) / (MF_R(1.0) - sr);
    *r = rr;
    *g = nmax > nmin ? mf_clamp((nmax - eta) / (nmax - nmin), MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
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
MF_INLINE mf_real mf__erfinv_giles(mf_real y)
{
    mf_real w, p;
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
    return p * y;
}
MF_INLINE mf_real mf_erfinv(mf_real y)
{
    mf_real x;
    int i;
    y = mf_clamp(y, MF_R(-1.0) + MF_EPS, MF_R(1.0) - MF_EPS);
    x = mf__erfinv_giles(y);
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

/* cos and sin of 2 pi u, u in [0, 1], without a library call: the nearest
 * quarter turn k = round(4u) is exact (4u - k is exact in binary), the rest
 * t = (4u - k) pi/2 lies in [-pi/4, pi/4] where the Taylor series to t^9 / t^10
 * (float) or t^17 / t^18 (double) is below half an ulp; the quarter turn
 * picks and negates without branches (an index and exact factors +-1). */
MF_FORCE_INLINE void mf__sincos_2pi(mf_real u, mf_real *c, mf_real *s)
{
    mf_real q = MF_R(4.0) * mf_clamp(u, MF_R(0.0), MF_R(1.0)), t, t2, v[2];
    int k = (int)(q + MF_R(0.5));
    t = (q - (mf_real)k) * MF_R(1.57079632679489661923);
    t2 = t * t;
#ifdef MF_USE_DOUBLE
    v[1] = 2.8114572543455207632e-15 - t2 * 8.2206352466243297170e-18;   /* 1/17!, 1/19! */
    v[1] = 7.6471637318198164759e-13 - t2 * v[1];
    v[1] = 1.6059043836821614599e-10 - t2 * v[1];
    v[1] = 2.5052108385441718775e-08 - t2 * v[1];
    v[1] = 2.7557319223985890653e-06 - t2 * v[1];
    v[0] = 1.5619206968586225271e-16;                                 /* 1/18! */
    v[0] = 4.7794773323873852974e-14 - t2 * v[0];
    v[0] = 1.1470745597729724714e-11 - t2 * v[0];
    v[0] = 2.0876756987868098979e-09 - t2 * v[0];
    v[0] = 2.7557319223985890653e-07 - t2 * v[0];
    v[0] = 2.4801587301587301587e-05 - t2 * v[0];
#else
    v[1] = MF_R(2.7557319223985890653e-06);
    v[0] = MF_R(2.4801587301587301587e-05) - t2 * MF_R(2.7557319223985890653e-07);
#endif
    v[1] = MF_R(1.9841269841269841270e-04) - t2 * v[1];
    v[1] = MF_R(8.3333333333333333333e-03) - t2 * v[1];
    v[1] = MF_R(1.6666666666666666667e-01) - t2 * v[1];
    v[1] = t - t * t2 * v[1];                                 /* sin t */
    v[0] = MF_R(1.3888888888888888889e-03) - t2 * v[0];
    v[0] = MF_R(4.1666666666666666667e-02) - t2 * v[0];
    v[0] = MF_R(0.5) - t2 * v[0];
    v[0] = MF_R(1.0) - t2 * v[0];                             /* cos t */
    *c = v[k & 1] * (mf_real)(1 - ((k + 1) & 2));
    *s = v[(k & 1) ^ 1] * (mf_real)(1 - (k & 2));
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
    MF__SOLVER_DONE(MF__SITE_BETACF, m > 300 ? 300 : m, 300);
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
    mf_real r = (x * x + y * y) / mf_max(w.z * w.z, MF_R(1e-30));
    return r < MF_A2T2_MAX ? r : MF_A2T2_MAX;
}

/* wm from an unstretched slope direction (cos phi, sin phi) and squared unit
 * slope radius r2, stretched by (ax, ay): wm ~ (ax r cos, ay r sin, 1). */
MF_FORCE_INLINE mf_vec3 mf__wm_from_slope(mf_real ax, mf_real ay, mf_real r2, mf_real cp, mf_real sp)
{
    if (!(r2 < MF_R(1e30))) return mf_normalize(mf_vec3_make(ax * cp, ay * sp, MF_R(0.0)));
    r2 = MF_SQRT(mf_max(r2, MF_R(0.0)));
    return mf_normalize(mf_vec3_make(ax * r2 * cp, ay * r2 * sp, MF_R(1.0)));
}

/* wm for the squared unit slope radius r2 at the azimuth 2 pi u2 (mf__wm_from_slope). */
MF_FORCE_INLINE mf_vec3 mf__wm_from_slope_u(mf_real ax, mf_real ay, mf_real r2, mf_real u2)
{
    mf_real phi = MF_R(2.0) * MF_PI * u2;
    return mf__wm_from_slope(ax, ay, r2, MF_COS(phi), MF_SIN(phi));
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
/* ======================================================================== */
/* == 6. Distribution kinds: Beckmann                                       */
/* ======================================================================== */
/* Anisotropic Beckmann: Gaussian slopes, D = exp(-tan^2/alpha_phi^2) / (pi ax ay cos^4)
 * (thesis Eq. C.1; Heitz 2014 Eq. 83); exact Lambda (Heitz 2014 Eq. 84) and
 * Walter et al. 2007's rational approximation (thesis C.2); NDF sampling by
 * the inverse slope CDF; visible normals by slope-space inversion (Heitz &
 * d'Eon 2014, Jakob 2014) with a safeguarded Halley solve (cold). */
/* Anisotropic Beckmann. alpha = sqrt(2) sigma of the Gaussian slopes. */
MF_INLINE mf_ndf mf_beckmann(mf_real alpha_x, mf_real alpha_y)
{
    return mf__ndf_init(MF_NDF_BECKMANN, alpha_x, alpha_y);
}

/* Per-distribution fast paths for D, Lambda and sampling (the same clamps as
 * the generic functions). */
MF_FORCE_INLINE mf_real mf_beckmann_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real z2, e;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    z2 = wm.z * wm.z;
    e = mf__q(ax, ay, wm) / z2;                   /* tan^2 / alpha_projected^2 */
    if (!(e < MF_R(80.0))) return MF_R(0.0);     /* exp underflow (and NaN) */
    return MF_EXP(-e) / (MF_PI * ax * ay * z2 * z2);
}

MF_FORCE_INLINE mf_real mf_beckmann_lambda(mf_real ax, mf_real ay, mf_vec3 w)
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

MF_COLD void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy);
MF_FORCE_INLINE mf_vec3 mf_beckmann_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp, sx, sy, x, y;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (w.x == MF_R(0.0) && w.y == MF_R(0.0)) {
        /* exactly normal: the visible slopes are D's, a unit Gaussian of
         * variance 1/2 per axis; polar form, radius^2 = -log(1 - u1) */
        mf_real r2 = -MF_LOG(mf_max(MF_R(1.0) - mf_clamp(u1, MF_R(0.0), MF_R(1.0)), MF_TINY)), inv;
        mf__sincos_2pi(u2, &cp, &sp);
        x = ax * cp; y = ay * sp;
        inv = MF_R(1.0) / MF_SQRT(MF_R(1.0) + r2 * (x * x + y * y));   /* |(-x r, -y r, 1)| from r^2: off the sqrt(r2) path */
        sx = MF_SQRT(r2) * inv;
        return mf_vec3_make(-x * sx, -y * sx, inv);
    }
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    mf__beckmann_visible_slopes(sv / mf_max(cv, MF_R(1e-30)), u1, u2, &sx, &sy);
    x = cp * sx - sp * sy;   /* rotate back to the view azimuth, then unstretch */
    y = sp * sx + cp * sy;
    return mf_normalize(mf_vec3_make(-ax * x, -ay * y, MF_R(1.0)));
}

/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_FORCE_INLINE mf_real mf__beckmann_D(const mf_ndf *d, mf_vec3 wm) { return mf_beckmann_D(d->ax, d->ay, wm); }
MF_FORCE_INLINE mf_real mf__beckmann_lambda(const mf_ndf *d, mf_vec3 w) { return mf_beckmann_lambda(d->ax, d->ay, w); }
MF_FORCE_INLINE mf_vec3 mf__beckmann_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(d->ax, d->ay, -MF_LOG1P(-t), u2);
}
MF_FORCE_INLINE mf_vec3 mf__beckmann_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf_beckmann_sample_visible(d->ax, d->ay, w, u1, u2);
}
/* ======================================================================== */
/* == 6. Distribution kinds: GGX                                            */
/* ======================================================================== */
/* Anisotropic GGX (Trowbridge-Reitz): D = 1 / (pi ax ay cos^4 (1 + tan^2/alpha_phi^2)^2)
 * (thesis Eq. C.3, corrected; Heitz 2014 Eq. 85); Lambda (thesis C.4); NDF
 * sampling by inverting the slope CDF (Walter et al. 2007); visible normals by
 * spherical caps (Dupuy & Benyoub 2023). Every function is inline: GGX is the
 * hot path of most renderers. */
/* Anisotropic GGX (Trowbridge-Reitz). */
MF_INLINE mf_ndf mf_ggx(mf_real alpha_x, mf_real alpha_y)
{
    return mf__ndf_init(MF_NDF_GGX, alpha_x, alpha_y);
}

MF_FORCE_INLINE mf_real mf_ggx_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real t;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    t = wm.z * wm.z + mf__q(ax, ay, wm);          /* cos^2 (1 + tan^2/alpha^2), no cos^4 underflow */
    return MF_R(1.0) / (MF_PI * ax * ay * t * t);
}

MF_FORCE_INLINE mf_real mf_ggx_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w);
    return a2t2 / (MF_R(2.0) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + a2t2)));
}

/* GGX VNDF by spherical caps (Dupuy & Benyoub 2023, Listing 3), before the
 * final normalization; w need not be unit. (0,0,1) for degenerate input. k
 * scales the cap's lower bound -k v.z: 1 is the whole visible hemisphere, k < 1
 * the bounded cap of Eto & Tokuyoshi 2023 (mf_ggx_sample_visible_bounded). */
MF_FORCE_INLINE mf_vec3 mf__ggx_vndf_unnormalized(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2, mf_real k)
{
    mf_vec3 v, h;
    mf_real phi, z, s, l2, b;
    v = mf_vec3_make(ax * w.x, ay * w.y, w.z);
    l2 = mf_dot(v, v);
    if (!(l2 > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    v = mf_scale(v, MF_R(1.0) / MF_SQRT(l2));
    phi = MF_R(2.0) * MF_PI * u1;
    b = k * v.z;
    z = (MF_R(1.0) - u2) * (MF_R(1.0) + b) - b;              /* cap of the visible hemisphere */
    s = MF_SQRT(mf_clamp(MF_R(1.0) - z * z, MF_R(0.0), MF_R(1.0)));
    h = mf_vec3_make(s * MF_COS(phi) + v.x, s * MF_SIN(phi) + v.y, z + v.z);
    h = mf_vec3_make(ax * h.x, ay * h.y, mf_max(h.z, MF_R(0.0)));
    if (!(mf_dot(h, h) > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    return h;
}
MF_FORCE_INLINE mf_vec3 mf_ggx_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(ax, ay, w, u1, u2, MF_R(1.0));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}

/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_FORCE_INLINE mf_real mf__ggx_D(const mf_ndf *d, mf_vec3 wm) { return mf_ggx_D(d->ax, d->ay, wm); }
MF_FORCE_INLINE mf_real mf__ggx_lambda(const mf_ndf *d, mf_vec3 w) { return mf_ggx_lambda(d->ax, d->ay, w); }
MF_FORCE_INLINE mf_vec3 mf__ggx_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), q = MF_R(1.0) - t;
    return mf__wm_from_slope_u(d->ax, d->ay, q > MF_R(0.0) ? t / q : MF_BIG, u2);
}
MF_FORCE_INLINE mf_vec3 mf__ggx_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf_ggx_sample_visible(d->ax, d->ay, w, u1, u2);
}
/* ======================================================================== */
/* == 6. Distribution kinds: GTR                                            */
/* ======================================================================== */
/* Burley's Generalized Trowbridge-Reitz (Burley 2012; thesis Eq. C.5, Berry
 * limit C.6), isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma. Lambda from
 * Dimov's exact formulas at gamma = 0..4 (thesis C.7-C.11) and, between them,
 * from an exact mixture of those distributions integrated by a Gauss-Jacobi
 * rule built at construction (mf__gtr_mix_init); NDF sampling by the
 * closed-form inverse CDF; visible normals by the exact numerical inversion
 * of 07_numeric_vndf.h. Everything but the constructor is cold. */
MF_COLD void mf__gtr_mix_init(mf_ndf_gtr *p);
/* Burley's GTR, isotropic: D = N / (1 + (alpha^2 - 1) cos^2)^gamma.
 * alpha in [MF_ALPHA_MIN, 1], gamma in [0, 4] (clamped; see CLAMPS above).
 * gamma = 2 is GGX, gamma = 1 the Berry distribution (limit C.6), gamma = 0
 * the uniform 1/pi; alpha = 1 gives 1/pi for every gamma. N is written with
 * x/expm1(x) so the limits gamma -> 1 and alpha -> 1 are exact. */
MF_INLINE mf_ndf mf_gtr(mf_real alpha, mf_real gamma)
{
    mf_ndf d;
    mf_ndf_gtr *p;
    mf_real a, L, k;
    a = mf__clamp_alpha(alpha);
    if (a > MF_R(1.0)) a = MF_R(1.0);
    /* the bits: under -ffast-math the comparisons let NaN through, and the
     * Lambda rule (mf__gtr_mix_init) indexes the closed forms by gamma */
    if (!mf__finite_bits(gamma)) gamma = MF_R(0.0);
    gamma = gamma > MF_R(0.0) ? (gamma < MF_R(4.0) ? gamma : MF_R(4.0)) : MF_R(0.0);
    d = mf__ndf_init(MF_NDF_GTR, a, a);
    p = &d.p.gtr;
    L = MF_R(2.0) * MF_LOG(a);
    k = MF_R(1.0) - gamma;
    p->gamma = gamma;
    /* N = (gamma-1)(a^2-1) / (pi (1 - a^(2(1-gamma))))  (C.5) = r(kL) / (pi r(L)) */
    p->norm = mf__x_over_expm1(k * L) / (MF_PI * mf__x_over_expm1(L));
    p->L = L;
    p->E = MF_EXPM1(k * L);
    p->EM = MF_EXPM1(-k * L);
    p->RK = mf__x_over_expm1(k * L);
    p->RMK = mf__x_over_expm1(-k * L);
    mf__gtr_mix_init(p);
    return d;
}

/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion the numerical visible-normal sampler uses (07_numeric_vndf.h). */
MF_COLD mf_real mf__gtr_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__gtr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__gtr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__gtr_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__gtr_tail(const mf_ndf *d, mf_real tan2);
/* ======================================================================== */
/* == 6. Distribution kinds: LEADR (non-centered anisotropic Beckmann)      */
/* ======================================================================== */
/* The distribution of LEADR slope moments (Dupuy et al. 2013): Gaussian
 * slopes with a mean and a covariance, D = exp(-q/2) / (2 pi sqrt(det) cos^4)
 * (Eq. 8 and 10); the exact Smith Lambda of the shifted Gaussian (Eq. 13-15);
 * NDF sampling through the Cholesky factor; visible normals by a half-plane
 * inversion. Built from moments by mf_leadr_ndf (module 12). Cold. */
/* The distribution of slopes with mean (mx, my) (finite) and covariance
 * [vx c; c vy] (positive definite; mf_leadr_ndf ensures both). */
MF_INLINE mf_ndf mf__leadr_ndf_make(mf_real mx, mf_real my, mf_real vx, mf_real vy, mf_real c)
{
    mf_real det, l00, l10;
    mf_ndf d = mf__ndf_init(MF_NDF_LEADR, MF_SQRT(MF_R(2.0) * vx), MF_SQRT(MF_R(2.0) * vy));
    mf_ndf_leadr *p = &d.p.leadr;
    p->mx = mx; p->my = my;
    p->vx = vx; p->vy = vy; p->cxy = c;
    det = vx * vy - c * c;
    p->ixx = vy / det; p->iyy = vx / det; p->ixy = -c / det;
    p->norm = MF_R(1.0) / (MF_R(2.0) * MF_PI * MF_SQRT(det));
    l00 = MF_SQRT(vx); l10 = c / l00;
    p->l00 = l00; p->l10 = l10;
    p->l11 = MF_SQRT(mf_max(vy - l10 * l10, MF_R(1e-30)));
    return d;
}

/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_COLD mf_real mf__leadr_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__leadr_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__leadr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__leadr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
/* ======================================================================== */
/* == 6. Distribution kinds: Student-t                                      */
/* ======================================================================== */
/* Student's t-distribution of slopes (Ribardiere et al. 2017), anisotropic:
 * P22 = (1/(pi ax ay)) (1 + r^2/(gamma-1))^-gamma, r^2 = x^2/ax^2 + y^2/ay^2;
 * gamma = 2 is GGX, gamma -> infinity Beckmann. Exact Lambda through the
 * incomplete beta function (measured against an independent 1D integral,
 * gamma 1.55 to 1000, alpha 1e-4 to 1, to 89.9 deg: 1.4e-10 relative in
 * double; in float the head - tail difference cancels: 4.4e-3 relative where
 * Lambda > 1e-4, 4e-4 on 1 + Lambda); NDF sampling by the closed-form inverse CDF;
 * visible normals by the exact numerical inversion of 07_numeric_vndf.h.
 * Everything but the constructor is cold. */
/* Student's t-distribution of slopes (STD), anisotropic. gamma in
 * [MF_STUDENT_T_GAMMA_MIN, MF_STUDENT_T_GAMMA_MAX] (clamped). */
MF_INLINE mf_ndf mf_student_t(mf_real alpha_x, mf_real alpha_y, mf_real gamma)
{
    mf_ndf d;
    mf_real g1, beta;
    if (!(gamma > MF_STUDENT_T_GAMMA_MIN)) gamma = MF_STUDENT_T_GAMMA_MIN;
    if (gamma > MF_STUDENT_T_GAMMA_MAX) gamma = MF_STUDENT_T_GAMMA_MAX;
    d = mf__ndf_init(MF_NDF_STUDENT_T, alpha_x, alpha_y);
    g1 = gamma - MF_R(1.0);
    d.p.student_t.gamma = gamma;
    d.p.student_t.K = MF_SQRT(g1) * MF_EXP(MF_LGAMMA(gamma - MF_R(0.5)) - MF_LGAMMA(gamma)) / MF_SQRT_PI;
    d.p.student_t.lbeta = MF_LGAMMA(g1) + MF_LGAMMA(MF_R(0.5)) - MF_LGAMMA(g1 + MF_R(0.5));
    /* the sampler's tail substitution must cancel tan(theta) ~ q^-beta, beta = 1/(2 gamma - 2) */
    beta = MF_R(0.5) / g1;
    d.p.student_t.vndf_p = MF_R(2.0) / (MF_R(1.0) - beta);
    return d;
}
/* The kind's entries of the generic dispatch (05_ndf.h), and the NDF-CDF
 * inversion the numerical visible-normal sampler uses (07_numeric_vndf.h). */
MF_COLD mf_real mf__student_t_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__student_t_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__student_t_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__student_t_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_COLD mf_real mf__student_t_tan2(const mf_ndf *d, mf_real t, mf_real q);
MF_COLD mf_real mf__student_t_tail(const mf_ndf *d, mf_real tan2);
/* ======================================================================== */
/* == 6. Distribution kinds: tabulated (piecewise-linear)                   */
/* ======================================================================== */
/* Ribardiere et al. 2019, Sec. 3: D piecewise linear in theta through control
 * points (Eq. 11), each curve normalized (Eq. 12); anisotropic from two curves
 * by Eq. 10. Lambda by the split integration of Eq. 13-14 (precomputed at
 * build time), NDF sampling by Eq. 15-18, visible normals by an exact
 * inversion. Builders: mf_tabulated_build, mf_tabulated_from_ndf. Cold. */
/* The distribution of a built mf_tabulated (builders below); a
 * NULL or released table gives a distribution whose every function returns 0.
 * ax = ay = the table's characteristic slope (informative only). */
MF_INLINE mf_ndf mf_tabulated_ndf(const mf_tabulated *t)
{
    mf_real s = t && t->block ? t->scale : MF_R(1.0);
    mf_ndf d = mf__ndf_init(MF_NDF_TABULATED, s, s);
    d.p.tabulated.tab = t && t->block && t->n >= 2 ? t : (const mf_tabulated *)0;
    return d;
}

/* ---- Tabulated (piecewise-linear) distributions: builders ----
 * (Ribardiere et al. 2019, Sec. 3.) mf_tabulated_build takes n control points
 * theta[0] = 0 < theta[1] < ... < theta[n-1] = pi/2 (the ends may be off by up
 * to 1e-4 rad; they are snapped) and the curve D_x at them (per steradian,
 * >= 0, finite, not all 0; any scale: each curve is normalized by Eq. 12).
 * D_y = NULL (or equal to D_x) gives an isotropic distribution; otherwise D_x
 * is the curve at phi = 0 and D_y at phi = pi/2, combined by Eq. 10 (whose
 * weights D_y(0)/c, D_x(0)/c become 1, 1 when both curves vanish at the pole).
 * Any number of lobes. 2 <= n <= MF_TABULATED_MAX_POINTS = 4096; consecutive
 * angles at least 16 ulps apart. Build cost grows as n^2: the projected-area
 * table integrates over the control segments for 1 to 8 view angles per
 * segment (n = 91: 2 ms, 256: 9 ms, 1024: 0.07 s, 4096: about 1 s). Errors:
 * NULL or bad n (MF_ERROR_INVALID_ARGUMENT), unordered, too close or
 * non-finite angles, negative, non-finite or all-zero values
 * (MF_ERROR_INVALID_DATA), allocation
 * (MF_ERROR_OUT_OF_MEMORY); nothing stays allocated on failure.
 * mf_tabulated_from_ndf tabulates any distribution at about n control points
 * placed to equidistribute the linear-interpolation error relative to D
 * (density sqrt(|D''| / D) over 8 n candidate angles that cover both uniform
 * theta and tan(theta) scaled by the median slope), so narrow lobes and long
 * tails are both resolved; D_x and D_y are the means of the slices phi = 0, pi and
 * phi = pi/2, 3 pi/2 (so a general transformed or non-centered distribution is
 * approximated by its Eq. 10 form, which is not elliptical anisotropy: for GGX
 * 0.3 x 0.1 D differs by up to 40% on the x axis and 3x elsewhere; for
 * elliptical anisotropy tabulate the isotropic base of roughness
 * sqrt(ax ay) and apply mf_transformed with M = diag(a/ax, a/ay), exact to the
 * tabulation error). The distribution refers to t: keep t alive and unchanged
 * while it is used. */
#define MF_TABULATED_MAX_POINTS 4096
MFDEF mf_result mf_tabulated_build(mf_tabulated *t, const mf_real *theta, const mf_real *D_x,
                                   const mf_real *D_y, int n);
MFDEF mf_result mf_tabulated_from_ndf(mf_tabulated *t, const mf_ndf *d, int n);
MFDEF void mf_tabulated_release(mf_tabulated *t);
MFDEF size_t mf_tabulated_memory_bytes(const mf_tabulated *t);

/* A copy of t whose arrays live in block (a copy of t->block, e.g. in device
 * memory): every array keeps its offset. */
MF_INLINE mf_tabulated mf_tabulated_rebase(const mf_tabulated *t, void *block)
{
    mf_tabulated r = *t;
    mf_real *ob = (mf_real *)t->block, *nb = (mf_real *)block;
    r.theta = nb + (t->theta - ob); r.dx = nb + (t->dx - ob); r.dy = nb + (t->dy - ob);
    r.cx = nb + (t->cx - ob); r.cy = nb + (t->cy - ob); r.lt = nb + (t->lt - ob); r.li = nb + (t->li - ob);
    r.block = block;
    return r;
}
/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_COLD mf_real mf__tabulated_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__tabulated_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__tabulated_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__tabulated_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
/* ======================================================================== */
/* == 7. Numerical visible-normal sampling of the heavy-tailed kinds        */
/* ======================================================================== */
/* An exact inversion of the distribution of visible normals for isotropic
 * kinds known through their NDF-sampling CDF (GTR, Student-t): the marginal
 * of the D-cos mass by Gauss-Legendre panels, the azimuth given theta in
 * closed form (see mf__iso_sample_visible). Cold. */
/* wm with density D_w(wm) for the view w of any length (w.z >= 0), of the
 * kind d stretched by (ax, ay) (GTR: 1, 1; Student-t: its roughness). */
MF_COLD mf_vec3 mf__iso_sample_visible_view(const mf_ndf *d, mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2);
/* ======================================================================== */
/* == 8. Linearly transformed microsurfaces                                 */
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

/* 1 if M can transform a microsurface (finite, |det| above the threshold,
 * and |det| > 1/MF_BIG so that 1/det and with it M^-1 stay finite in mf_real:
 * diag(1e-20, 1e-20) passes the relative test but not this one in float). */
MF_INLINE int mf_transform_valid(mf_mat2 M)
{
    mf_real n2 = M.m00 * M.m00 + M.m01 * M.m01 + M.m10 * M.m10 + M.m11 * M.m11;
    mf_real det = MF_FABS(mf_mat2_det(M));
    return n2 < MF_BIG && det < MF_BIG && det > MF_TRANSFORM_MIN_DET * n2 && det * MF_BIG > MF_R(1.0);
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

/* d rotated by angle (radians, counterclockwise about the normal): the
 * transform by the rotation R (thesis ch. 4; for a rotation M^-T = M), so
 * D_rotated(m) = D(R^-1 m). Turns an anisotropic lobe, e.g. to follow a
 * brushing direction, without rebuilding the frame. */
MF_INLINE mf_ndf mf_rotated(mf_ndf d, mf_real angle)
{
    mf_real c, s;
    if (!(angle == angle) || !(MF_FABS(angle) < MF_R(1e6))) return d;
    c = MF_COS(angle); s = MF_SIN(angle);
    return mf_transformed(d, mf_mat2_make(c, -s, s, c));
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

/* D of the untransformed distribution, homogeneous of degree -4 in wm: GGX
 * and Beckmann inline, the other kinds through the dispatch (05_ndf.h). */
MF_FORCE_INLINE mf_real mf__D_base(const mf_ndf *d, mf_vec3 wm)
{
    if (d->type == MF_NDF_GGX) return mf_ggx_D(d->ax, d->ay, wm);
    if (d->type == MF_NDF_BECKMANN) return mf_beckmann_D(d->ax, d->ay, wm);
    return mf__ndf_D(d, wm);
}

/* D(wm), 1/sr; 0 if wm.z <= 0. Transformed kinds by Eq. 4.14. */
MF_FORCE_INLINE mf_real mf_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real r;
    if (!d->transformed) return mf__D_base(d, wm);
    /* |det M| |M^T m|^-4 D(M^T m / |M^T m|) = |det M| mf__D_base(M^T m),
     * capped at MF_BIG (a small M makes |M^T m|^-4 overflow) */
    r = d->det * mf__D_base(d, mf_mat2_apply_transpose(d->M, wm));
    return mf__cap(r);
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
/* == 9. Smith masking                                                      */
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
 *             tan(theta) without cancellation; between them an exact mixture of
 *             the GGX (gamma < 2) or gamma-4 (gamma > 2) Lambdas integrated by
 *             a Gauss-Jacobi rule built at construction (see mf__gtr_lambda):
 *             measured within 2e-6 relative of the true Lambda in double.
 *   Student-t: exact, from the marginal slope density P2(x) = K (1 + x^2/(g-1))^(1/2-g):
 *             Lambda = K (g-1)/((2g-3) mu) (1 + mu^2/(g-1))^(3/2-g) - Q(mu),
 *             Q the upper tail of P2 = I_w(g-1, 1/2)/2, w = (g-1)/(g-1+mu^2)
 *             (the closed form behind Ribardiere et al. 2017 Eq. 13-15; clamped at 0). */

/* Smith Lambda(w). Symmetric in w.z; large but finite at w.z = 0. GGX and Beckmann
 * inline, the other kinds out of line; transformed kinds at M^-1 w (Eq. 4.4). */
MF_FORCE_INLINE mf_real mf_lambda(const mf_ndf *d, mf_vec3 w)
{
    /* Lambda depends on w only through tan(theta) and phi: no normalization */
    if (d->transformed) w = mf_mat2_apply(d->Minv, w);
    if (d->type == MF_NDF_GGX) return mf_ggx_lambda(d->ax, d->ay, w);
    if (d->type == MF_NDF_BECKMANN) return mf_beckmann_lambda(d->ax, d->ay, w);
    return mf__ndf_lambda(d, w);
}

/* Monodirectional masking G1(w, wm) = chi+(w.wm) chi+(w.z) / (1 + Lambda(w)). */
MF_FORCE_INLINE mf_real mf_G1(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
{
    if (!(w.z > MF_R(0.0)) || !(mf_dot(w, wm) > MF_R(0.0))) return MF_R(0.0);
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, w));
}

/* Height-correlated masking-shadowing (Heitz 2014 Eq. 99):
 * G2 = chi+(wo.wm) chi+(wi.wm) / (1 + Lambda(wo) + Lambda(wi)). Reflection only:
 * 0 unless wo.z > 0 and wi.z > 0. */
/* GGX, wo.z, wi.z > 0: 1 + Lambda(w) = |s w| / (2 w.z) with s w = (ax w.x,
 * ay w.y, w.z) (thesis C.4), so G2 = 2 zo zi / (zi |s wo| + zo |s wi|): one
 * division instead of five. */
MF_FORCE_INLINE mf_real mf__ggx_G2(mf_real ax, mf_real ay, mf_vec3 wo, mf_vec3 wi)
{
    mf_real xo = ax * wo.x, yo = ay * wo.y, xi = ax * wi.x, yi = ay * wi.y;
    mf_real so = MF_SQRT(xo * xo + yo * yo + wo.z * wo.z), si = MF_SQRT(xi * xi + yi * yi + wi.z * wi.z);
    mf_real den = wi.z * so + wo.z * si;
    return den > MF_R(0.0) ? MF_R(2.0) * wo.z * wi.z / den : MF_R(0.0);
}
/* 1 / (1 + Lambda(wo) + Lambda(wi)) for wo.z, wi.z > 0 (no facet checks) */
MF_FORCE_INLINE mf_real mf__G2_up(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    if (d->type == MF_NDF_GGX) {
        /* M^-1 fixes z: the transformed directions stay above the horizon */
        if (d->transformed) { wo = mf_mat2_apply(d->Minv, wo); wi = mf_mat2_apply(d->Minv, wi); }
        return mf__ggx_G2(d->ax, d->ay, wo, wi);
    }
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, wo) + mf_lambda(d, wi));
}
MF_FORCE_INLINE mf_real mf_G2(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_vec3 wm)
{
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    if (!(mf_dot(wo, wm) > MF_R(0.0)) || !(mf_dot(wi, wm) > MF_R(0.0))) return MF_R(0.0);
    return mf__G2_up(d, wo, wi);
}

/* Separable form G1(wo, wm) G1(wi, wm) (Heitz 2014 Eq. 98). */
MF_FORCE_INLINE mf_real mf_G2_separable(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_vec3 wm)
{
    return mf_G1(d, wo, wm) * mf_G1(d, wi, wm);
}

/* w . (-E_x, -E_y, 1): the projected area of the mean surface (unnormalized
 * mesonormal) toward w; w.z for every centered distribution. The mean slope of
 * a transformed distribution is M^-T times the base's (Eq. 4.16). */
MF_FORCE_INLINE mf_real mf__mean_surface_proj(const mf_ndf *d, mf_vec3 w)
{
    mf_real mx, my;
    if (d->type != MF_NDF_LEADR) return w.z;
    mx = d->p.leadr.mx; my = d->p.leadr.my;
    if (d->transformed) {
        mf_real tx = d->Minv.m00 * mx + d->Minv.m10 * my, ty = d->Minv.m01 * mx + d->Minv.m11 * my;
        mx = tx; my = ty;
    }
    return w.z - mx * w.x - my * w.y;
}

/* Projected area of the visible microsurface, w.z (1 + Lambda(w)) =
 * integral <w.m> D(m) dm (thesis Eq. 3.9); finite and positive at w.z = 0.
 * For LEADR moments the mean surface is tilted: (w . (-E_x, -E_y, 1)) (1 +
 * Lambda(w)) (LEADR supplement Eq. 9). */
MF_FORCE_INLINE mf_real mf_projected_area(const mf_ndf *d, mf_vec3 w)
{
    mf_real cz;
    if (d->type == MF_NDF_LEADR) return mf__cap(mf_max(mf__mean_surface_proj(d, w), MF_R(1e-15)) * (MF_R(1.0) + mf_lambda(d, w)));
    cz = mf_max(MF_FABS(w.z), MF_R(1e-15));
    return mf__cap(cz + cz * mf_lambda(d, w));
}

/* Distribution of visible normals (Heitz & d'Eon 2014 Eq. 2):
 * D_w(wm) = G1(w, wm) max(0, w.wm) D(wm) / w.z; integrates to 1 over wm. 0 if w.z < 0. */
MF_FORCE_INLINE mf_real mf_D_visible(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
{
    mf_real c = mf_dot(w, wm);
    if (w.z < MF_R(0.0) || !(c > MF_R(0.0))) return MF_R(0.0);
    return mf__cap(c * mf_D(d, wm) / mf_projected_area(d, w));
}
/* ======================================================================== */
/* == 10. Sampling                                                          */
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

/* random numbers outside [0, 1] are clamped to it, NaN becomes 0 */
MF_FORCE_INLINE mf_real mf__u01(mf_real u) { return u >= MF_R(0.0) ? (u <= MF_R(1.0) ? u : MF_R(1.0)) : MF_R(0.0); }

/* wm with density D(wm) wm.z. u1 picks the polar angle, u2 the azimuth.
 * Transformed kinds: M^-T applied to a sample of the base (Eq. 4.17-4.18). */
MF_FORCE_INLINE mf_vec3 mf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_vec3 m;
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    m = d->type == MF_NDF_GGX ? mf__ggx_sample_D(d, u1, u2)
              : d->type == MF_NDF_BECKMANN ? mf__beckmann_sample_D(d, u1, u2) : mf__ndf_sample_D(d, u1, u2);
    if (!d->transformed) return m;
    return mf_normalize(mf_mat2_apply_transpose(d->Minv, m));
}

/* wm with density mf_D_visible(d, w, wm); the zero vector if w.z < 0. GGX
 * inline, the other kinds out of line. Transformed kinds: the base's visible
 * normals for M^-1 w, moved by M^-T (Eq. 4.20-4.21). */
MF_FORCE_INLINE mf_vec3 mf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 m;
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    if (!d->transformed) {
        if (d->type == MF_NDF_GGX) return mf_ggx_sample_visible(d->ax, d->ay, w, u1, u2);
        return mf__ndf_sample_visible(d, w, u1, u2);
    }
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    w = mf_mat2_apply(d->Minv, w);   /* the samplers normalize their view themselves */
    if (d->type == MF_NDF_GGX) m = mf__ggx_vndf_unnormalized(d->ax, d->ay, w, u1, u2, MF_R(1.0));
    else m = mf__ndf_sample_visible(d, w, u1, u2);
    return mf_normalize(mf_mat2_apply_transpose(d->Minv, m));
}
/* ======================================================================== */
/* == 11. Specular microfacet BRDF                                          */
/* ======================================================================== */
/* f(wo, wi) = D(wh) G2(wo, wi, wh) / (4 |wo.z| |wi.z|) (Walter et al. 2007
 * Eq. 20 without Fresnel), sampled through the visible normals of wo
 * (Heitz & d'Eon 2014): pdf(wi) = D_wo(wh) / (4 wo.wh). Reflection only.
 * For LEADR moments wo.z is replaced by the mean surface's projected area
 * wo . (-E_x, -E_y, 1) (LEADR Eq. 16-17), which keeps the energy but is not
 * reciprocal when the mean slope is not 0. */

MF_FORCE_INLINE mf_real mf_brdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    if (!(wh.z > MF_R(0.0))) return MF_R(0.0);
    /* f grows like 1/cos at grazing retro-reflection: divide in two steps and
     * cap, so float never overflows */
    /* wo below a tilted mean surface (LEADR): fully masked. Without this, in
     * float G2 = 1/(1 + MF_BIG) and the clamped projection 1e-30 cancel. */
    {
        mf_real p = mf__mean_surface_proj(d, wo);
        if (!(p > MF_R(0.0))) return MF_R(0.0);
        return mf_min(mf_D(d, wh) * mf_G2(d, wo, wi, wh) / (MF_R(4.0) * p) / wi.z, MF_BIG);
    }
}

MF_FORCE_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi);

/* Samples wi for wo; wi.z <= 0 (the zero vector) means no sample. A wi is
 * returned only where mf_brdf_pdf is positive (rounding can put a sampled
 * normal where D underflows to 0, e.g. Beckmann 0.01 at u = (0, 0)). */
MF_FORCE_INLINE mf_vec3 mf_brdf_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 wm, wi;
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    wm = mf_sample_visible(d, wo, u1, u2);
    wi = mf_reflect(wo, wm);
    if (!(wi.z > MF_R(0.0)) || !(wm.z > MF_R(0.0)) || !(wi.x == wi.x && wi.y == wi.y) ||
        !(mf_brdf_pdf(d, wo, wi) > MF_R(0.0)))
        return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return wi;
}

/* Density of mf_brdf_sample per unit solid angle of wi; capped at MF_BIG
 * (near the horizon D_visible / (4 wo.wh) overflows float). */
MF_FORCE_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    mf_real c, p;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    c = mf_dot(wo, wh);
    if (!(c > MF_R(0.0))) return MF_R(0.0);
    p = mf_D_visible(d, wo, wh) / (MF_R(4.0) * c);
    return mf__cap(p);
}

/* f(wo, wi) wi.z / pdf(wi) for a wi from mf_brdf_sample: G2 / G1(wo)
 * = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)). */
MF_FORCE_INLINE mf_real mf_brdf_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_real lo;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    lo = mf_lambda(d, wo);
    return (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(d, wi));
}

/* GGX bounded visible-normal sampling (Eto & Tokuyoshi 2023, "Bounded VNDF
 * Sampling for Smith-GGX Reflections", Listings 1-2). The spherical cap of
 * Dupuy & Benyoub 2023 is shrunk by k (the paper's Eq. 5, with a = min(ax, ay)
 * for anisotropic GGX, Eq. 6) to a cap that still holds every normal whose
 * reflection of wo is above the horizon but far fewer of the others: fewer
 * samples lost (none for isotropic GGX at normal incidence; at alpha 0.5 and
 * 80 degrees 1.4% instead of 7.5%) and a lower-variance estimator (plain /
 * bounded variance of the albedo estimate 2.2 at alpha 0.5, 2.5 to 4 at alpha
 * 1; test_materials). A reflection below the horizon is still possible and
 * counts as no sample. Returns a normal wm (reflect wo on it for wi, as after
 * mf_sample_visible); the zero vector when wo.z <= 0. Any other kind than untransformed GGX falls back to
 * mf_sample_visible, and mf_ggx_brdf_pdf_bounded to mf_brdf_pdf, so the pair
 * stays consistent for every mf_ndf. */
MF_FORCE_INLINE mf_real mf__ggx_bounded_k(mf_real ax, mf_real ay, mf_vec3 wo)
{
    mf_real a = mf_clamp(mf_min(ax, ay), MF_R(0.0), MF_R(1.0)), a2 = a * a;
    mf_real s = MF_R(1.0) + MF_SQRT(wo.x * wo.x + wo.y * wo.y), s2 = s * s;
    return (MF_R(1.0) - a2) * s2 / (s2 + a2 * wo.z * wo.z);   /* Eq. 5 */
}
MF_FORCE_INLINE mf_vec3 mf_ggx_sample_visible_bounded(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (d->type != MF_NDF_GGX || d->transformed) return mf_sample_visible(d, wo, u1, u2);
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(d->ax, d->ay, wo, mf_clamp(u1, MF_R(0.0), MF_R(1.0)), mf_clamp(u2, MF_R(0.0), MF_R(1.0)),
                                  mf__ggx_bounded_k(d->ax, d->ay, wo));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}
/* Density per unit solid angle of wi = reflect(wo, wm) for wm from
 * mf_ggx_sample_visible_bounded (paper Listing 2): D(wm) / (2 (k wo.z + t)),
 * t = |(ax wo.x, ay wo.y, wo.z)|; plain VNDF sampling is the case k = 1. */
MF_FORCE_INLINE mf_real mf_ggx_brdf_pdf_bounded(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 wh;
    mf_real t, k;
    if (d->type != MF_NDF_GGX || d->transformed) return mf_brdf_pdf(d, wo, wi);
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    wh = mf_normalize(mf_add(wo, wi));
    if (!(mf_dot(wo, wh) > MF_R(0.0))) return MF_R(0.0);
    t = MF_SQRT(d->ax * d->ax * wo.x * wo.x + d->ay * d->ay * wo.y * wo.y + wo.z * wo.z);
    k = mf__ggx_bounded_k(d->ax, d->ay, wo);
    return mf_min(mf_ggx_D(d->ax, d->ay, wh) / (MF_R(2.0) * (k * wo.z + t)), MF_BIG);
}

/* Hemispherical averages of the Fresnel terms, F_avg = 2 int_0^1 F(mu) mu dmu
 * (Kulla & Conty 2017, the energy-compensation average; 1 - F_avg is the
 * share a cosine-distributed light transmits). Dielectric of relative index
 * eta (eta < 1: seen from the denser side, total internal reflection below
 * the critical cosine mu_c = sqrt(1 - eta^2)), conductor eta + i k. On each
 * side of mu_c (0 when eta >= 1), 8 panels of 8-point Gauss-Legendre in t,
 * mu = mu_c -+ len t^2, which smooths the square root at the critical angle;
 * within 1e-8 of a dense integral in double, 1e-6 in float (test_materials). */
MF_COLD mf_real mf_fresnel_dielectric_average(mf_real eta);
MF_COLD mf_real mf_fresnel_conductor_average(mf_real eta, mf_real k);

/* ======================================================================== */
/* == 11b. Rough dielectric BSDF                                            */
/* ======================================================================== */
/* Walter et al. 2007 ("Microfacet Models for Refraction through Rough
 * Surfaces") for every mf_ndf, transforms included. eta = index below the
 * surface (-z) over the index above it (+z); wo and wi on either side:
 * reflection when wo.z wi.z > 0, transmission otherwise. With eta_o the index
 * on wo's side and e = eta_i / eta_o the relative index across:
 *   reflection   f = F(wo.h) D(h) G2 / (4 |wo.z| |wi.z|),   h = normalize(wo + wi)  (Eq. 20)
 *   transmission f = (1 - F(wo.h)) D(h) G2 |wi.h| |wo.h| / (|wi.z| |wo.z| (wi.h + wo.h / e)^2) / e^2
 *                h = normalize(wo + e wi), facing wo's side  (Eqs. 16, 21)
 * with G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (the height-correlated form,
 * each direction's masking on its own side). The 1 / e^2 = (eta_o / eta_i)^2
 * factor is radiance transport: a path tracer following camera paths uses f
 * as it is. Importance transport (light tracing, photon mapping) omits it:
 * multiply the transmitted value by e^2. Reciprocity holds in the generalized
 * form f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2.
 * Sampling draws visible normals of wo's side (Heitz & d'Eon 2014), then
 * reflection with probability F(wo.h) and refraction otherwise (so the weight
 * f |cos| / pdf is G2 / G1(wo), times 1 / e^2 when transmitted).
 * A wo below the surface is handled by inverting every direction (a height
 * field seen from below, mirrored through the origin, has the same slope
 * distribution, so this is exact for every kind, non-centered LEADR
 * included) and using 1 / eta. At the smallest alpha (1e-4 after clamping)
 * the lobes are nearly a mirror and a refraction: sampling is exact and the
 * weights stay near F-free 1, but evaluating a fixed wi gives about 0 unless
 * it is within ~alpha of the specular directions; a renderer wanting the
 * delta limit uses mf_fresnel_dielectric with mf_reflect / mf_refract.
 * Thin-walled sheets (two interfaces) are not modelled here. */

/* Refraction of wi (pointing away, on n's side) through the unit normal n;
 * eta = n_transmitted / n_incident (as mf_fresnel_dielectric). *wt: unit, on
 * the other side. Returns 0 on total internal reflection or degenerate input
 * (then *wt is the zero vector). Snell: sin t = sin i / eta. */
MF_FORCE_INLINE int mf_refract(mf_vec3 wi, mf_vec3 n, mf_real eta, mf_vec3 *wt)
{
    mf_real ci = mf_dot(wi, n), s2t, ct;
    *wt = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG) || !(ci >= MF_R(0.0)) || !(ci <= MF_R(1.0) + MF_R(1e-3))) return 0;
    ci = mf_min(ci, MF_R(1.0));
    s2t = (MF_R(1.0) - ci * ci) / (eta * eta);
    if (!(s2t < MF_R(1.0))) return 0;
    ct = MF_SQRT(MF_R(1.0) - s2t);
    *wt = mf_normalize(mf_add(mf_scale(wi, MF_R(-1.0) / eta), mf_scale(n, ci / eta - ct)));
    return wt->z == wt->z && mf_dot(*wt, *wt) > MF_R(0.5);
}

/* wo above (after the inversion), e relative index across: the generalized
 * half vector of (wo, wi) facing up, and 1 when the configuration is valid
 * (wo and wi on the facet's correct sides). */
MF_FORCE_INLINE int mf__dielectric_half(mf_vec3 wo, mf_vec3 wi, mf_real e, mf_vec3 *h)
{
    mf_vec3 m = wi.z > MF_R(0.0) ? mf_add(wo, wi) : mf_add(wo, mf_scale(wi, e));
    mf_real l2 = mf_dot(m, m);
    if (!(l2 > MF_R(1e-30)) || !(l2 < MF_BIG)) return 0;
    m = mf_scale(m, MF_R(1.0) / MF_SQRT(l2));
    if (m.z < MF_R(0.0)) m = mf_scale(m, MF_R(-1.0));
    *h = m;
    if (!(mf_dot(m, wo) > MF_R(0.0))) return 0;
    return wi.z > MF_R(0.0) ? mf_dot(m, wi) > MF_R(0.0) : mf_dot(m, wi) < MF_R(0.0);
}

/* 1 when eta is a usable index and w a finite direction off the horizon */
MF_FORCE_INLINE int mf__dielectric_ok(mf_vec3 w, mf_real eta)
{
    return eta > MF_R(0.0) && eta < MF_BIG && MF_FABS(w.x) + MF_FABS(w.y) + MF_FABS(w.z) < MF_BIG && w.z != MF_R(0.0);
}

/* Prepares (wo, wi, eta) for the evaluation: inverts both when wo is below;
 * 0 when there is nothing to evaluate. */
MF_FORCE_INLINE int mf__dielectric_setup(mf_vec3 *wo, mf_vec3 *wi, mf_real *eta)
{
    if (!mf__dielectric_ok(*wo, *eta) || !mf__dielectric_ok(*wi, *eta)) return 0;   /* NaN, infinite, horizon */
    if (wo->z < MF_R(0.0)) {
        *wo = mf_scale(*wo, MF_R(-1.0));
        *wi = mf_scale(*wi, MF_R(-1.0));
        *eta = MF_R(1.0) / *eta;
    }
    return 1;
}

MF_FORCE_INLINE mf_real mf__dielectric_G2(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    /* wi below: its masking on the lower side is Lambda(-wi) (see above) */
    return mf__G2_up(d, wo, wi.z < MF_R(0.0) ? mf_scale(wi, MF_R(-1.0)) : wi);
}

/* The common part of eval and pdf: after the setup, the half vector h, wo.h,
 * the Fresnel reflectance there and, for transmission, the Jacobian's
 * denominator (wi.h + wo.h / e)^2 (Walter Eq. 17). 0 when nothing to do. */
MF_FORCE_INLINE int mf__dielectric_prep(mf_vec3 *wo, mf_vec3 *wi, mf_real *eta, mf_vec3 *h, mf_real *oh, mf_real *F, mf_real *den)
{
    mf_real x;
    if (!mf__dielectric_setup(wo, wi, eta) || !mf__dielectric_half(*wo, *wi, *eta, h)) return 0;
    *oh = mf_dot(*wo, *h);
    *F = mf_fresnel_dielectric(*oh, *eta);
    *den = MF_R(1.0);
    if (wi->z > MF_R(0.0)) return 1;   /* reflection: no Jacobian denominator */
    x = mf_dot(*wi, *h) + *oh / *eta;
    *den = x * x;
    return *den > MF_R(0.0);
}

MF_FORCE_INLINE mf_real mf_dielectric_bsdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_vec3 h;
    mf_real F, oh, den, g;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return MF_R(0.0);
    g = mf_D(d, h) * mf__dielectric_G2(d, wo, wi) / wo.z;   /* two divisions: no underflow of wo.z wi.z */
    if (wi.z > MF_R(0.0)) return mf_min(F * g / (MF_R(4.0) * wi.z), MF_BIG);
    return mf_min((MF_R(1.0) - F) * g * MF_FABS(mf_dot(wi, h)) * oh / (den * -wi.z * eta * eta), MF_BIG);
}

/* Density of mf_dielectric_sample per unit solid angle of wi (either side). */
MF_FORCE_INLINE mf_real mf_dielectric_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_vec3 h;
    mf_real F, oh, den, dv;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return MF_R(0.0);
    dv = mf_D_visible(d, wo, h);
    if (wi.z > MF_R(0.0)) return mf_min(F * dv / (MF_R(4.0) * oh), MF_BIG);
    return mf_min((MF_R(1.0) - F) * dv * MF_FABS(mf_dot(wi, h)) / den, MF_BIG);   /* Jacobian |wi.h| / (wi.h + wo.h / e)^2 */
}

/* Samples wi (reflected or transmitted) for wo on either side from three
 * uniform numbers; the zero vector means no sample. */
MF_FORCE_INLINE mf_vec3 mf_dielectric_sample(const mf_ndf *d, mf_vec3 wo, mf_real eta, mf_real u1, mf_real u2, mf_real u3)
{
    mf_vec3 m, wi, zero = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    mf_real s = MF_R(1.0), F;
    if (!mf__dielectric_ok(wo, eta)) return zero;
    if (wo.z < MF_R(0.0)) { wo = mf_scale(wo, MF_R(-1.0)); eta = MF_R(1.0) / eta; s = MF_R(-1.0); }
    m = mf_sample_visible(d, wo, u1, u2);
    if (!(m.z > MF_R(0.0)) || !(mf_dot(wo, m) > MF_R(0.0))) return zero;
    F = mf_fresnel_dielectric(mf_dot(wo, m), eta);
    if (u3 < F) {
        wi = mf_reflect(wo, m);
        if (!(wi.z > MF_R(0.0))) return zero;
    } else {
        if (!mf_refract(wo, m, eta, &wi) || !(wi.z < MF_R(0.0))) return zero;
    }
    return mf_scale(wi, s);
}

/* f |wi.z| / pdf for a wi from mf_dielectric_sample: G2 / G1(wo) = (1 +
 * Lambda(wo)) G2, divided by e^2 when transmitted (radiance transport);
 * for LEADR moments (a tilted mean surface) the ratio itself. */
MF_FORCE_INLINE mf_real mf_dielectric_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_real w;
    if (d->type == MF_NDF_LEADR) {   /* visible normals of a tilted mean surface: the ratio itself */
        w = mf_dielectric_pdf(d, wo, wi, eta);
        return w > MF_R(0.0) ? mf_min(mf_dielectric_bsdf(d, wo, wi, eta) * MF_FABS(wi.z) / w, MF_BIG) : MF_R(0.0);
    }
    if (!mf__dielectric_setup(&wo, &wi, &eta)) return MF_R(0.0);
    w = (MF_R(1.0) + mf_lambda(d, wo)) * mf__dielectric_G2(d, wo, wi);
    return wi.z > MF_R(0.0) ? w : w / (eta * eta);
}
#ifndef MF_NO_LEADR
/* ======================================================================== */
/* == 12. LEADR slope moments                                               */
/* ======================================================================== */
/* Dupuy, Heitz et al. 2013 (LEADR mapping). A surface patch is summarized by
 * the first and second moments of its slopes (Eq. 9), which filter linearly
 * (mip maps, bilinear lookups) and define a Gaussian slope distribution
 * (Eq. 8): the mean gives the mesonormal (Eq. 11), the centered second
 * moments the covariance. A roughness alpha of the microsurface adds
 * alpha^2 / 2 to the variances (alpha = sqrt(2) sigma). Texture-space moments
 * move to the surface's tangent frame by the texture Jacobian (Eq. 12). */

typedef struct mf_leadr { mf_real E_x, E_y, E_xx, E_yy, E_xy; } mf_leadr;

MF_INLINE mf_leadr mf__leadr_make(mf_real ex, mf_real ey, mf_real exx, mf_real eyy, mf_real exy)
{
    mf_leadr m;
    m.E_x = ex; m.E_y = ey; m.E_xx = exx; m.E_yy = eyy; m.E_xy = exy;
    return m;
}

/* Moments of a single slope (x, y) = (-n.x/n.z, -n.y/n.z). */
MF_INLINE mf_leadr mf_leadr_from_slope(mf_real x, mf_real y)
{
    return mf__leadr_make(x, y, x * x, y * y, x * y);
}
/* Moments of a unit normal (0 for normals at or below the horizon). */
MF_INLINE mf_leadr mf_leadr_from_normal(mf_vec3 n)
{
    if (!(n.z > MF_R(0.0))) return mf__leadr_make(0, 0, 0, 0, 0);
    return mf_leadr_from_slope(-n.x / n.z, -n.y / n.z);
}
MF_INLINE mf_leadr mf_leadr_add(mf_leadr a, mf_leadr b)
{
    return mf__leadr_make(a.E_x + b.E_x, a.E_y + b.E_y, a.E_xx + b.E_xx, a.E_yy + b.E_yy, a.E_xy + b.E_xy);
}
MF_INLINE mf_leadr mf_leadr_scale(mf_leadr a, mf_real s)
{
    return mf__leadr_make(a.E_x * s, a.E_y * s, a.E_xx * s, a.E_yy * s, a.E_xy * s);
}
/* (1 - t) a + t b */
MF_INLINE mf_leadr mf_leadr_lerp(mf_leadr a, mf_leadr b, mf_real t)
{
    return mf_leadr_add(mf_leadr_scale(a, MF_R(1.0) - t), mf_leadr_scale(b, t));
}
/* Adds the microsurface roughness: alpha^2 / 2 to each variance. */
MF_INLINE mf_leadr mf_leadr_with_roughness(mf_leadr a, mf_real alpha_x, mf_real alpha_y)
{
    a.E_xx += MF_R(0.5) * alpha_x * alpha_x;
    a.E_yy += MF_R(0.5) * alpha_y * alpha_y;
    return a;
}
/* Eq. 12: texture-space moments (slopes along u, v) to the tangent frame
 * (x, y) with the Jacobian duv_dxy = [du/dx du/dy; dv/dx dv/dy]: the slopes
 * move by A = duv_dxy^T, first moments by A, second moments by A E A^T. */
MF_INLINE mf_leadr mf_leadr_deform(mf_leadr a, mf_mat2 duv_dxy)
{
    mf_real a00 = duv_dxy.m00, a01 = duv_dxy.m10, a10 = duv_dxy.m01, a11 = duv_dxy.m11;   /* A */
    mf_leadr r;
    r.E_x = a00 * a.E_x + a01 * a.E_y;
    r.E_y = a10 * a.E_x + a11 * a.E_y;
    r.E_xx = a00 * a00 * a.E_xx + MF_R(2.0) * a00 * a01 * a.E_xy + a01 * a01 * a.E_yy;
    r.E_yy = a10 * a10 * a.E_xx + MF_R(2.0) * a10 * a11 * a.E_xy + a11 * a11 * a.E_yy;
    r.E_xy = a00 * a10 * a.E_xx + (a00 * a11 + a01 * a10) * a.E_xy + a01 * a11 * a.E_yy;
    return r;
}
/* Scaling the displacement by eta scales first moments by eta, second by eta^2. */
MF_INLINE mf_leadr mf_leadr_height_scale(mf_leadr a, mf_real eta)
{
    mf_real e2 = eta * eta;
    return mf__leadr_make(a.E_x * eta, a.E_y * eta, a.E_xx * e2, a.E_yy * e2, a.E_xy * e2);
}
/* The mesonormal (Eq. 11): (-E_x, -E_y, 1) normalized. */
MF_INLINE mf_vec3 mf_leadr_mean_normal(mf_leadr a)
{
    mf_vec3 n = mf_normalize(mf_vec3_make(-a.E_x, -a.E_y, MF_R(1.0)));
    return n.z > MF_R(0.0) ? n : mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
}
/* forward declaration: defined below */
MF_INLINE int mf_leadr_covariance(mf_leadr a, mf_real *var_x, mf_real *var_y, mf_real *cov_xy);

/* The non-centered anisotropic Beckmann distribution of the moments (Eq. 8,
 * 10) as an mf_ndf: every generic operation works (D, Lambda of Eq. 13-15
 * exact, G1, G2, D_visible, both samplers exact, the BRDF of Eq. 16-17). The
 * covariance goes through mf_leadr_covariance's guard. */
MF_INLINE mf_ndf mf_leadr_ndf(mf_leadr a)
{
    mf_real vx, vy, c;
    mf_leadr_covariance(a, &vx, &vy, &c);
    return mf__leadr_ndf_make(a.E_x == a.E_x && MF_FABS(a.E_x) < MF_BIG ? a.E_x : MF_R(0.0),
                              a.E_y == a.E_y && MF_FABS(a.E_y) < MF_BIG ? a.E_y : MF_R(0.0), vx, vy, c);
}

/* Eq. 17 with L = F = 1: the radiance reflected toward wo from a directional
 * light along wi, (w_nbar . w_g)/(w_nbar . wo) D(wh) / (4 (1 + Lambda(wo) +
 * Lambda(wi))) (supplement Sec. 3.3); = mf_brdf(mf_leadr_ndf(a)) wi.z. */
MF_INLINE mf_real mf_leadr_specular(mf_leadr a, mf_vec3 wo, mf_vec3 wi)
{
    mf_ndf d = mf_leadr_ndf(a);
    return mf_brdf(&d, wo, wi) * mf_max(wi.z, MF_R(0.0));
}

/* The slope sample grid of Sec. 5.1: n x n points p_j uniform in [-l, l]
 * with Gaussian weights, warped by the Cholesky factor of the covariance
 * and shifted by the mean. l = 0.45 (n - 1) (the paper's 1.8 at n = 5),
 * at most 4.5; the sums converge to the integrals as n grows (test_leadr). */
#define MF_LEADR_GRID_MAX 33
MF_INLINE mf_real mf__leadr_grid_l(int n) { return mf_min(MF_R(0.45) * (mf_real)(n - 1), MF_R(4.5)); }

typedef mf_vec3 (*mf_env_fn)(mf_vec3 wi, mf_real solid_angle, void *ctx);

/* The 1D points and Gaussian weights of the grid; returns the weight sum. */
MF_INLINE mf_real mf__leadr_grid_points(int n, mf_real *p1, mf_real *w1)
{
    mf_real lim = mf__leadr_grid_l(n), wsum = MF_R(0.0);
    int j;
    for (j = 0; j < n; ++j) {
        p1[j] = n > 1 ? -lim + MF_R(2.0) * lim * (mf_real)j / (mf_real)(n - 1) : MF_R(0.0);
        w1[j] = MF_EXP(MF_R(-0.5) * p1[j] * p1[j]);
        wsum += w1[j];
    }
    return wsum;
}

/* The micronormal of grid point (pj, pk): the sample scaled, correlated and
 * shifted to the slope distribution (Sec. 5.1, Cholesky of the covariance). */
MF_INLINE mf_vec3 mf__leadr_grid_normal(const mf_ndf *d, mf_real pj, mf_real pk)
{
    mf_real sy2 = MF_SQRT(d->p.leadr.vy), r = d->p.leadr.cxy / (d->p.leadr.l00 * sy2);
    mf_real sx = pj * d->p.leadr.l00 + d->p.leadr.mx;
    mf_real sy = (r * pj + MF_SQRT(mf_max(MF_R(1.0) - r * r, MF_R(0.0))) * pk) * sy2 + d->p.leadr.my;
    return mf_normalize(mf_vec3_make(-sx, -sy, MF_R(1.0)));
}

/* Sum over the grid of g(wn) <wn, wo> / (wn . wg) W, where g is the
 * lighting term of the shading mode (0: environment specular, Eq. 22;
 * 1: diffuse under one directional light, Eq. 20-21), divided by the mean
 * surface's projected area wo . (-E_x, -E_y, 1). */
MF_INLINE mf_vec3 mf__leadr_grid(mf_leadr a, mf_vec3 wo, int n, int mode, mf_vec3 wl, int shadowing,
                                 mf_env_fn env, void *ctx)
{
    mf_ndf d = mf_leadr_ndf(a);
    mf_real lam_o, w1[MF_LEADR_GRID_MAX], p1[MF_LEADR_GRID_MAX], wsum, proj, area;
    mf_vec3 acc = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    int j, k;
    n = n < 1 ? 1 : (n > MF_LEADR_GRID_MAX ? MF_LEADR_GRID_MAX : n);
    proj = mf__mean_surface_proj(&d, wo);
    if (!(wo.z > MF_R(0.0)) || !(proj > MF_R(0.0))) return acc;
    wsum = mf__leadr_grid_points(n, p1, w1);
    lam_o = mf_lambda(&d, wo);
    if (mode == 1 && shadowing) lam_o += mf_lambda(&d, wl);   /* the light is fixed: once */
    /* slope-space area of one sample, overestimated along the longest axis */
    area = MF_R(2.0) * (n > 1 ? mf__leadr_grid_l(n) : MF_R(1.0)) * MF_SQRT(mf_max(d.p.leadr.vx, d.p.leadr.vy)) / (mf_real)n;
    area *= area;
    for (j = 0; j < n; ++j)
        for (k = 0; k < n; ++k) {
            mf_real W = w1[j] * w1[k] / (wsum * wsum), on, g;
            mf_vec3 wn = mf__leadr_grid_normal(&d, p1[j], p1[k]), wi;
            on = mf_dot(wn, wo);
            if (!(on > MF_R(0.0))) continue;
            if (mode == 0) {
                mf_vec3 L;
                mf_real sa;
                wi = mf_reflect(wo, wn);
                if (!(wi.z > MF_R(0.0))) continue;
                /* solid angle of the sample: |d wi / d slope| A = 4 (wo.wn) cos^3 A */
                sa = MF_R(4.0) * on * wn.z * wn.z * wn.z * area;
                L = env ? env(wi, sa, ctx) : mf_vec3_make(MF_R(1.0), MF_R(1.0), MF_R(1.0));
                g = MF_R(1.0) / (MF_R(1.0) + lam_o + (shadowing ? mf_lambda(&d, wi) : MF_R(0.0)));
                acc = mf_add(acc, mf_scale(L, g * on / wn.z * W));
            } else {
                mf_real ni = mf_dot(wn, wl);
                if (!(ni > MF_R(0.0))) continue;
                g = ni / (MF_R(1.0) + lam_o);
                acc = mf_add(acc, mf_scale(mf_vec3_make(MF_R(1.0), MF_R(1.0), MF_R(1.0)), g * on / wn.z * W * MF_INV_PI));
            }
        }
    return mf_scale(acc, MF_R(1.0) / proj);
}

/* Specular microfacets under environment lighting (Eq. 19, 22; Algorithm 1):
 * env(wi, solid_angle, ctx) returns the prefiltered radiance for a direction
 * and the solid angle one sample covers, alpha = |d wi / d slope| A with
 * A = (2 l max(sigma_x, sigma_y) / n)^2; a cube map of size s would use
 * LOD = log2(sqrt(alpha / (4 pi)) s) (supplement, Algorithm 1).
 * n x n slope samples (5 is the paper's default); no Fresnel (F = 1);
 * self_shadowing = 0 drops Lambda(wi) (supplement Sec. 1.5). */
MF_INLINE mf_vec3 mf_leadr_specular_env(mf_leadr a, mf_vec3 wo, int n, int self_shadowing, mf_env_fn env, void *ctx)
{
    return mf__leadr_grid(a, wo, n, 0, wo, self_shadowing, env, ctx);
}

/* Diffuse microfacets (albedo 1) under one directional light along wi of
 * radiance 1 (Eq. 20-21, Algorithm 2), n x n slope samples (5 by default). */
MF_INLINE mf_real mf_leadr_diffuse(mf_leadr a, mf_vec3 wo, mf_vec3 wi, int grid_n)
{
    return mf__leadr_grid(a, wo, grid_n > 0 ? grid_n : 5, 1, wi, 1, (mf_env_fn)0, (void *)0).x;
}
/* The same without self-shadowing (1 / (1 + Lambda(wo)), supplement Sec. 1.5). */
MF_INLINE mf_real mf_leadr_diffuse_noshadow(mf_leadr a, mf_vec3 wo, mf_vec3 wi, int grid_n)
{
    return mf__leadr_grid(a, wo, grid_n > 0 ? grid_n : 5, 1, wi, 0, (mf_env_fn)0, (void *)0).x;
}

/* Second-order spherical harmonics of a radiance environment (Ramamoorthi &
 * Hanrahan 2001; LEADR Algorithm 2), coefficients ordered L00, L1-1, L10,
 * L11, L2-2, L2-1, L20, L21, L22. Adds a directional light of radiance L. */
MF_INLINE void mf_sh9_add_directional(mf_real sh[9], mf_vec3 dir, mf_real L)
{
    mf_real x = dir.x, y = dir.y, z = dir.z;
    sh[0] += MF_R(0.282095) * L;
    sh[1] += MF_R(0.488603) * y * L; sh[2] += MF_R(0.488603) * z * L; sh[3] += MF_R(0.488603) * x * L;
    sh[4] += MF_R(1.092548) * x * y * L; sh[5] += MF_R(1.092548) * y * z * L;
    sh[6] += MF_R(0.315392) * (MF_R(3.0) * z * z - MF_R(1.0)) * L;
    sh[7] += MF_R(1.092548) * x * z * L; sh[8] += MF_R(0.546274) * (x * x - y * y) * L;
}
/* Irradiance E(n) of the SH9 environment (Ramamoorthi & Hanrahan Eq. 13). */
MF_INLINE mf_real mf_sh9_irradiance(const mf_real sh[9], mf_vec3 n)
{
    const mf_real c1 = MF_R(0.429043), c2 = MF_R(0.511664), c3 = MF_R(0.743125), c4 = MF_R(0.886227), c5 = MF_R(0.247708);
    mf_real x = n.x, y = n.y, z = n.z;
    return c1 * sh[8] * (x * x - y * y) + c3 * sh[6] * z * z + c4 * sh[0] - c5 * sh[6] +
           MF_R(2.0) * c1 * (sh[4] * x * y + sh[7] * x * z + sh[5] * y * z) +
           MF_R(2.0) * c2 * (sh[3] * x + sh[1] * y + sh[2] * z);
}

/* Diffuse microfacets (albedo 1) under an SH9 environment, without
 * self-shadowing (supplement, Simplified Algorithm 3): the ratio
 * sum E(wn) S W / (pi sum S W), S = <wn, wo> / (wn . wg), over n x n slope
 * samples plus the artificial micronormal of supplement Sec. 3.7 (the
 * mesonormal bent toward wo, weight 1e-5), which keeps the result defined
 * when the mesonormal faces away from wo (low tessellation silhouettes). */
MF_INLINE mf_real mf_leadr_diffuse_sh9(mf_leadr a, mf_vec3 wo, const mf_real sh[9], int n)
{
    mf_ndf d = mf_leadr_ndf(a);
    mf_real w1[MF_LEADR_GRID_MAX], p1[MF_LEADR_GRID_MAX], wsum, num, den, on;
    mf_vec3 nb = mf_leadr_mean_normal(a), nt;
    int j, k;
    n = n < 1 ? 5 : (n > MF_LEADR_GRID_MAX ? MF_LEADR_GRID_MAX : n);
    if (!(wo.z > MF_R(0.0)) || !sh) return MF_R(0.0);
    wsum = mf__leadr_grid_points(n, p1, w1);
    /* the artificial micronormal */
    nt = mf_normalize(mf_add(nb, mf_scale(wo, -mf_dot(nb, wo) * MF_R(1.01))));
    on = mf_max(mf_dot(nt, wo), MF_R(0.0));
    den = MF_R(1e-5) * on / mf_max(nt.z, MF_R(1e-6));
    num = den * mf_sh9_irradiance(sh, nt);
    for (j = 0; j < n; ++j)
        for (k = 0; k < n; ++k) {
            mf_vec3 wn = mf__leadr_grid_normal(&d, p1[j], p1[k]);
            mf_real S = mf_max(mf_dot(wn, wo), MF_R(0.0)) / wn.z * w1[j] * w1[k] / (wsum * wsum);
            num += S * mf_sh9_irradiance(sh, wn);
            den += S;
        }
    return den > MF_R(0.0) ? num / (MF_PI * den) : MF_R(0.0);
}

/* Covariance (Eq. 9) with its validity guard: variances in
 * [MF_LEADR_MIN_VARIANCE, MF_LEADR_MAX_VARIANCE] and |correlation| at most
 * MF_LEADR_MAX_CORRELATION (filtering and float round-off can break the
 * first and last; the upper bound, alpha = sqrt(2 var) = MF_ALPHA_MAX, keeps
 * the determinant and D finite in float). Returns 1 if the moments were valid
 * as given, 0 if the guard changed them (non-finite moments give an isotropic
 * variance of MF_LEADR_MIN_VARIANCE). */
#define MF_LEADR_MIN_VARIANCE MF_R(1e-8)
#define MF_LEADR_MAX_VARIANCE MF_R(5e7)
#define MF_LEADR_MAX_CORRELATION MF_R(0.999)
MF_INLINE int mf_leadr_covariance(mf_leadr a, mf_real *var_x, mf_real *var_y, mf_real *cov_xy)
{
    mf_real sx = a.E_xx - a.E_x * a.E_x, sy = a.E_yy - a.E_y * a.E_y, c = a.E_xy - a.E_x * a.E_y, lim;
    int ok = 1;
    if (!(sx < MF_BIG) || !(sy < MF_BIG) || !(MF_FABS(c) < MF_BIG)) { sx = sy = MF_LEADR_MIN_VARIANCE; c = MF_R(0.0); ok = 0; }
    if (!(sx >= MF_LEADR_MIN_VARIANCE)) { sx = MF_LEADR_MIN_VARIANCE; ok = 0; }
    if (!(sy >= MF_LEADR_MIN_VARIANCE)) { sy = MF_LEADR_MIN_VARIANCE; ok = 0; }
    if (sx > MF_LEADR_MAX_VARIANCE) { sx = MF_LEADR_MAX_VARIANCE; ok = 0; }
    if (sy > MF_LEADR_MAX_VARIANCE) { sy = MF_LEADR_MAX_VARIANCE; ok = 0; }
    lim = MF_LEADR_MAX_CORRELATION * MF_SQRT(sx * sy);
    if (MF_FABS(c) > lim) { c = c > MF_R(0.0) ? lim : -lim; ok = 0; }
    if (var_x) *var_x = sx;
    if (var_y) *var_y = sy;
    if (cov_xy) *cov_xy = c;
    return ok;
}

/* A mip pyramid of moments over a periodic (tiling) texture. Level 0 holds
 * width x height texels; each next level halves both sizes (down to 1) and
 * holds exactly the mean of its 2x2 children. Sizes must be powers of two.
 * Built by mf_leadr_map_from_heights / mf_leadr_map_from_normals (implementation section). */
typedef struct mf_leadr_map {
    int width, height, levels;
    mf_leadr *texels;      /* all levels, level 0 first, rows top to bottom */
    size_t offset[32];     /* first texel of each level */
} mf_leadr_map;

MF_INLINE int mf__leadr_level_w(const mf_leadr_map *m, int l) { int w = m->width >> l; return w > 0 ? w : 1; }
MF_INLINE int mf__leadr_level_h(const mf_leadr_map *m, int l) { int h = m->height >> l; return h > 0 ? h : 1; }

/* Bilinear lookup at (u, v) in level l, wrapping (texel centers at (i + 1/2) / size). */
MF_INLINE mf_leadr mf__leadr_bilinear(const mf_leadr_map *m, int l, mf_real u, mf_real v)
{
    int w = mf__leadr_level_w(m, l), h = mf__leadr_level_h(m, l), x0, y0, x1, y1;
    mf_real x = u * (mf_real)w - MF_R(0.5), y = v * (mf_real)h - MF_R(0.5), fx, fy, fl;
    const mf_leadr *t = m->texels + m->offset[l];
    fl = (mf_real)(int)x; if (fl > x) fl -= MF_R(1.0);
    fx = x - fl; x0 = (int)fl;
    fl = (mf_real)(int)y; if (fl > y) fl -= MF_R(1.0);
    fy = y - fl; y0 = (int)fl;
    x0 %= w; if (x0 < 0) x0 += w;
    y0 %= h; if (y0 < 0) y0 += h;
    x1 = (x0 + 1) % w; y1 = (y0 + 1) % h;
    return mf_leadr_lerp(mf_leadr_lerp(t[y0 * w + x0], t[y0 * w + x1], fx),
                         mf_leadr_lerp(t[y1 * w + x0], t[y1 * w + x1], fx), fy);
}

/* Trilinear lookup for a footprint of width `footprint` in texture units (the
 * texture spans [0,1]^2 and tiles): the level where a texel has that width,
 * bilinear within the two nearest levels, linear between them. */
MF_INLINE mf_leadr mf_leadr_map_lookup(const mf_leadr_map *m, mf_real u, mf_real v, mf_real footprint)
{
    mf_real lod, f;
    int l0;
    if (!m || !m->texels || m->levels < 1 || !(u == u) || !(v == v)) return mf__leadr_make(0, 0, 0, 0, 0);
    /* keep the coordinates small (wrap happens per texel); beyond 2^23 every
     * float is an integer, and an infinite coordinate goes to the edge 0:
     * no out-of-range conversion to int */
    u = MF_FABS(u) < MF_R(8388608.0) ? u - (mf_real)(int)u : MF_R(0.0);
    v = MF_FABS(v) < MF_R(8388608.0) ? v - (mf_real)(int)v : MF_R(0.0);
    lod = footprint > MF_R(0.0) ? MF_LOG(footprint * (mf_real)(m->width > m->height ? m->width : m->height)) * MF_R(1.4426950408889634) : MF_R(0.0);
    lod = mf_clamp(lod, MF_R(0.0), (mf_real)(m->levels - 1));
    l0 = (int)lod;
    if (l0 >= m->levels - 1) return mf__leadr_bilinear(m, m->levels - 1, u, v);
    f = lod - (mf_real)l0;
    return mf_leadr_lerp(mf__leadr_bilinear(m, l0, u, v), mf__leadr_bilinear(m, l0 + 1, u, v), f);
}

/* ---- LEADR moment maps ----
 * From a height map (heights in texture units: the texture spans [0,1]^2, so
 * the slope along u is (h[x+1] - h[x-1]) width / 2, periodic) or from a normal
 * map (unit normals, 3 per texel, z > 0), plus a base microsurface roughness
 * (alpha_x, alpha_y added as alpha^2/2 to the variances). Row-major, rows top
 * to bottom. width and height must be powers of two, at most 2^15. Errors:
 * NULL or zero size or non-power-of-two, alpha NaN, negative or above
 * MF_ALPHA_MAX (MF_ERROR_INVALID_ARGUMENT); non-finite heights or slopes
 * whose square exceeds MF_BIG / 4, invalid normals - not unit within 1e-3,
 * or z below MF_LEADR_MIN_NORMAL_Z, whose slope variance would overflow -
 * (MF_ERROR_INVALID_DATA); allocation (MF_ERROR_OUT_OF_MEMORY); nothing
 * stays allocated on failure. */
#define MF_LEADR_MIN_NORMAL_Z MF_R(1e-4)
MFDEF mf_result mf_leadr_map_from_heights(mf_leadr_map *m, const mf_real *heights, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y);
MFDEF mf_result mf_leadr_map_from_normals(mf_leadr_map *m, const mf_real *normals_xyz, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y);
MFDEF void mf_leadr_map_release(mf_leadr_map *m);
MFDEF size_t mf_leadr_map_memory_bytes(const mf_leadr_map *m);
#endif /* MF_NO_LEADR */
/* ======================================================================== */
/* == 13. Linearly Transformed Cosines                                      */
/* ======================================================================== */
/* Heitz, Dupuy, Hill, Neubelt 2016; Tao et al. 2021 Eq. 1: a clamped cosine
 * D_o(w) = max(0, w.z)/pi transformed by a 3x3 matrix M,
 *   D(w) = D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3,
 * integrates to 1 over the sphere, and its integral over a polygon is the
 * cosine form factor of the polygon transformed by M^-1 (Heitz 2017), clipped
 * exactly at the horizon. Polygons are given by their vertices relative to the
 * shading point (any length); the front face is the one whose vertices run
 * counterclockwise seen from the shading point. The fitter, the tables and the
 * built-in GGX table are non-inline (implementation section). */

typedef struct mf_ltc {
    mf_real M[9];       /* row-major */
    mf_real Minv[9];
    mf_real det_inv;    /* |det M^-1| */
} mf_ltc;

MF_FORCE_INLINE mf_vec3 mf__mat3_apply(const mf_real *a, mf_vec3 v)
{
    return mf_vec3_make(a[0] * v.x + a[1] * v.y + a[2] * v.z, a[3] * v.x + a[4] * v.y + a[5] * v.z,
                        a[6] * v.x + a[7] * v.y + a[8] * v.z);
}

/* A 3x3 matrix is singular for the LTC code when |det| is at most
 * MF_LTC_MIN_DET_REL times the product of its row lengths (Hadamard's bound:
 * the ratio is 1 for orthogonal rows, scale-free, and a rounding-level
 * remainder for parallel rows: float gives 4e-7 for two equal rows of
 * 4.9609375, which an absolute test accepted). */
#ifdef MF_USE_DOUBLE
#define MF_LTC_MIN_DET_REL 1e-12
#else
#define MF_LTC_MIN_DET_REL 1e-5f
#endif

/* Inverse of a row-major 3x3 matrix; returns its determinant (0: singular,
 * not finite, or an inverse that is not finite). */
MF_INLINE mf_real mf__mat3_inverse(const mf_real *a, mf_real *inv)
{
    mf_real c0 = a[4] * a[8] - a[5] * a[7], c1 = a[5] * a[6] - a[3] * a[8], c2 = a[3] * a[7] - a[4] * a[6];
    mf_real det = a[0] * c0 + a[1] * c1 + a[2] * c2, r, rel, s = MF_R(0.0);
    int i;
    if (!(det != MF_R(0.0)) || !(MF_FABS(det) < MF_BIG)) return MF_R(0.0);
    rel = MF_FABS(det) / MF_SQRT(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) / MF_SQRT(a[3] * a[3] + a[4] * a[4] + a[5] * a[5]) /
          MF_SQRT(a[6] * a[6] + a[7] * a[7] + a[8] * a[8]);
    if (!(rel > MF_LTC_MIN_DET_REL)) return MF_R(0.0);
    r = MF_R(1.0) / det;
    inv[0] = c0 * r; inv[1] = (a[2] * a[7] - a[1] * a[8]) * r; inv[2] = (a[1] * a[5] - a[2] * a[4]) * r;
    inv[3] = c1 * r; inv[4] = (a[0] * a[8] - a[2] * a[6]) * r; inv[5] = (a[2] * a[3] - a[0] * a[5]) * r;
    inv[6] = c2 * r; inv[7] = (a[1] * a[6] - a[0] * a[7]) * r; inv[8] = (a[0] * a[4] - a[1] * a[3]) * r;
    for (i = 0; i < 9; ++i) s += MF_FABS(inv[i]);
    if (!(s < MF_BIG)) return MF_R(0.0);
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
    if (!(MF_FABS(det) * MF_BIG > MF_R(1.0))) {   /* singular, or 1/det overflows */
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
 * M^-1 = [a 0 b; 0 c 0; d 0 e] (e = 1 in 4-coefficient tables). Its inverse
 * in closed form, k = ae - bd: M = [e/k 0 -b/k; 0 1/c 0; -d/k 0 a/k],
 * |det M^-1| = |c k|; singular (the Hadamard test above), non-finite or
 * overflowing input gives M = I. */
MF_INLINE mf_ltc mf_ltc_from_inverse(mf_real a, mf_real b, mf_real c, mf_real d, mf_real e)
{
    mf_ltc l;
    mf_real k = a * e - b * d, rk, rc, h = MF_LTC_MIN_DET_REL * MF_LTC_MIN_DET_REL;
    if (!(k * k > h * (a * a + b * b) * (d * d + e * e)) || !(c * c > MF_R(0.0)) ||
        !(MF_FABS(k) < MF_BIG) || !(MF_FABS(c * k) < MF_BIG) || !(MF_FABS(c * k) * MF_BIG > MF_R(1.0)) ||
        !(MF_FABS(a) + MF_FABS(b) + MF_FABS(d) + MF_FABS(e) < MF_BIG)) {
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        return mf_ltc_from_matrix9(I9);
    }
    rk = MF_R(1.0) / k; rc = MF_R(1.0) / c;
    l.Minv[0] = a; l.Minv[1] = MF_R(0.0); l.Minv[2] = b;
    l.Minv[3] = MF_R(0.0); l.Minv[4] = c; l.Minv[5] = MF_R(0.0);
    l.Minv[6] = d; l.Minv[7] = MF_R(0.0); l.Minv[8] = e;
    l.M[0] = e * rk; l.M[1] = MF_R(0.0); l.M[2] = -b * rk;
    l.M[3] = MF_R(0.0); l.M[4] = rc; l.M[5] = MF_R(0.0);
    l.M[6] = -d * rk; l.M[7] = MF_R(0.0); l.M[8] = a * rk;
    l.det_inv = MF_FABS(c * k);
    return l;
}

/* D(w), per steradian: |det M^-1| (M^-1 w).z / (pi |M^-1 w|^4) where positive. */
MF_FORCE_INLINE mf_real mf_ltc_eval(const mf_ltc *l, mf_vec3 w)
{
    mf_vec3 v = mf__mat3_apply(l->Minv, w);
    mf_real l2 = mf_dot(v, v);
    if (!(v.z > MF_R(0.0)) || !(l2 > MF_R(0.0))) return MF_R(0.0);
    return mf__cap(l->det_inv * v.z / (MF_PI * l2 * l2));
}

/* A direction with density mf_ltc_eval: a cosine-distributed direction moved by M. */
MF_INLINE mf_vec3 mf_ltc_sample(const mf_ltc *l, mf_real u1, mf_real u2)
{
    return mf_normalize(mf__mat3_apply(l->M, mf__sample_cosine(u1, u2)));
}

/* the per-edge and per-vertex helpers must inline into the polygon loops;
 * the rare ones stay out of line */
#define MF__LTC_HOT MF_FORCE_INLINE
#if defined(__CUDACC__)
#define MF__LTC_RARE static __noinline__ MF_HD
#elif defined(__GNUC__) || defined(__clang__)
#define MF__LTC_RARE static __attribute__((noinline, cold, unused))
#else
#define MF__LTC_RARE MF_INLINE
#endif

/* theta / sin theta for d = cos theta in [0, 1]: a (2, 2) rational fit,
 * relative error 5.6e-7 (minimax in the relative error, fitted in long
 * double; a (3, 3) fit reaches 1.1e-9 at two more multiply-adds). */
MF__LTC_HOT mf_real mf__theta_sin(mf_real d)
{
    mf_real p = MF_R(1.5707954524054327) + d * (MF_R(0.90581169693094948) + d * MF_R(0.026032047669933955));
    mf_real q = MF_R(1.0) + d * (MF_R(1.2132377142117774) + d * MF_R(0.28940008969878159));
    return p / q;
}

/* Integral of the cosine lobe's vector irradiance over the great arc from a to
 * b (unit vectors): (theta / sin theta) (a x b). a x b is formed as
 * a x (b - a) for theta <= pi/2 and a x (a + b) beyond, where the
 * differences are exact, so short and nearly antipodal arcs keep their
 * relative accuracy; theta / sin theta is the rational fit for theta <= pi/2
 * and pi / sin theta - (pi - theta) / sin(pi - theta) beyond, with sin theta
 * = |a x b| (no 1 - d^2). The exact atan2 form is used with MF_USE_DOUBLE or
 * MF_LTC_EXACT_EDGE. A zero or exactly antipodal arc gives 0. */
#if defined(MF_USE_DOUBLE) && !defined(MF_LTC_EXACT_EDGE)
#define MF_LTC_EXACT_EDGE
#endif
MF__LTC_HOT mf_vec3 mf__vsub(mf_vec3 a, mf_vec3 b) { return mf_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
MF_INLINE mf_vec3 mf__edge_vector_fast(mf_vec3 a, mf_vec3 b)
{
    mf_real d = mf_dot(a, b), s2, f;
    mf_vec3 c;
    if (d >= MF_R(0.0)) return mf_scale(mf_cross(a, mf__vsub(b, a)), mf__theta_sin(d));
    c = mf_cross(a, mf_add(a, b));
    s2 = mf_dot(c, c);
    if (!(s2 > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    f = MF_SQRT(s2);
    return mf_scale(c, MF_PI / f - mf__theta_sin(-d));
}
MF_INLINE mf_vec3 mf__edge_vector_exact(mf_vec3 a, mf_vec3 b)
{
    mf_real d = mf_dot(a, b), s;
    mf_vec3 c = d >= MF_R(0.0) ? mf_cross(a, mf__vsub(b, a)) : mf_cross(a, mf_add(a, b));
    s = MF_SQRT(mf_dot(c, c));
    if (!(s > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return mf_scale(c, MF_ATAN2(s, d) / s);
}
/* the z component beyond pi/2 (out of line: rare in small lights) */
MF__LTC_RARE mf_real mf__edge_z_obtuse(mf_vec3 a, mf_vec3 b, mf_real d)
{
    mf_real cx = a.y * (a.z + b.z) - a.z * (a.y + b.y), cy = a.z * (a.x + b.x) - a.x * (a.z + b.z);
    mf_real cz = a.x * (a.y + b.y) - a.y * (a.x + b.x), s2 = cx * cx + cy * cy + cz * cz;
    if (!(s2 > MF_R(1e-30))) return MF_R(0.0);
    return cz * (MF_PI / MF_SQRT(s2) - mf__theta_sin(-d));
}
/* its z component only */
MF__LTC_HOT mf_real mf__edge_z(mf_vec3 a, mf_vec3 b)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_vector_exact(a, b).z;
#else
    mf_real d = a.x * b.x + a.y * b.y + a.z * b.z;
    if (d >= MF_R(0.0)) return (a.x * (b.y - a.y) - a.y * (b.x - a.x)) * mf__theta_sin(d);
    return mf__edge_z_obtuse(a, b, d);
#endif
}
MF_INLINE mf_vec3 mf__edge_vector(mf_vec3 a, mf_vec3 b)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_vector_exact(a, b);
#else
    return mf__edge_vector_fast(a, b);
#endif
}

#define MF__LTC_T(A, v) ((A) ? mf__mat3_apply((A), (v)) : (v))
MF__LTC_HOT mf_vec3 mf__unit_or_zero(mf_vec3 v)
{
    mf_real l2 = v.x * v.x + v.y * v.y + v.z * v.z, r = l2 > MF_R(0.0) ? MF_R(1.0) / MF_SQRT(l2) : MF_R(0.0);
    return mf_vec3_make(v.x * r, v.y * r, v.z * r);
}

/* Signed cosine form factor (z component of the vector form factor, times
 * 2 pi) of the polygon p[0..n-1] transformed by A (NULL: identity), clipped
 * to z >= 0 on the fly: every edge is cut where it crosses the horizon and the
 * exit and entry points are joined along the horizon, so no vertex buffer is
 * needed and any n works. Each vertex is transformed and normalized once. */
MF_INLINE mf_real mf__polygon_clipped(const mf_real *A, const mf_vec3 *p, int n)
{
    int i, j, s = -1;
    mf_real sum = MF_R(0.0);
    mf_vec3 exit_pt = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), a, an, b, bn, first, first_n;
    for (i = 0; i < n; ++i) {
        a = A ? mf__mat3_apply(A, p[i]) : p[i];
        if (a.z > MF_R(0.0)) { s = i; break; }
    }
    if (s < 0) return MF_R(0.0);   /* entirely below the horizon */
    first = a;
    first_n = an = mf__unit_or_zero(a);
    for (i = 1, j = s; i <= n; ++i) {
        if (++j == n) j = 0;
        if (i == n) { b = first; bn = first_n; }
        else {
            b = A ? mf__mat3_apply(A, p[j]) : p[j];
            bn = b.z > MF_R(0.0) ? mf__unit_or_zero(b) : b;
        }
        if (a.z > MF_R(0.0)) {
            if (b.z > MF_R(0.0)) sum += mf__edge_z(an, bn);
            else {   /* leaves: a.z b - b.z a is on the segment and on the horizon */
                mf_vec3 x = mf__vsub(mf_scale(b, a.z), mf_scale(a, b.z));
                x.z = MF_R(0.0);
                x = mf__unit_or_zero(x);
                sum += mf__edge_z(an, x);
                exit_pt = x;
            }
        } else if (b.z > MF_R(0.0)) {   /* enters: along the horizon, then up */
            mf_vec3 x = mf__vsub(mf_scale(a, b.z), mf_scale(b, a.z));
            x.z = MF_R(0.0);
            x = mf__unit_or_zero(x);
            sum += mf__edge_z(exit_pt, x) + mf__edge_z(x, bn);
        }
        a = b; an = bn;
    }
    return sum;
}

/* The same, by a faster path for polygons above the horizon: quads
 * straight-line, other polygons in blocks of 16 vertices (transform and
 * normalize into a buffer, then the edges); the first vertex below the
 * horizon hands over to the clipping loop. */
MF_INLINE mf_real mf__polygon_sum(const mf_real *A, const mf_vec3 *p, int n)
{
    mf_vec3 u[16], u0 = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), prev = u0;
    mf_real s0 = MF_R(0.0), s1 = MF_R(0.0);
    int base, k, m;
    if (!p || n < 3) return MF_R(0.0);
    if (n == 4) {
        mf_vec3 b0 = MF__LTC_T(A, p[0]), b1 = MF__LTC_T(A, p[1]), b2 = MF__LTC_T(A, p[2]), b3 = MF__LTC_T(A, p[3]);
        if (!(b0.z > MF_R(0.0) && b1.z > MF_R(0.0) && b2.z > MF_R(0.0) && b3.z > MF_R(0.0))) {
            u[0] = b0; u[1] = b1; u[2] = b2; u[3] = b3;   /* clip the transformed quad */
            return mf__polygon_clipped((const mf_real *)0, u, 4);
        }
        b0 = mf__unit_or_zero(b0); b1 = mf__unit_or_zero(b1); b2 = mf__unit_or_zero(b2); b3 = mf__unit_or_zero(b3);
        s0 = mf__edge_z(b0, b1) + mf__edge_z(b1, b2);
        s1 = mf__edge_z(b2, b3) + mf__edge_z(b3, b0);
        return s0 + s1;
    }
    for (base = 0; base < n; base += 16) {
        m = n - base < 16 ? n - base : 16;
        for (k = 0; k < m; ++k) {
            mf_vec3 w = MF__LTC_T(A, p[base + k]);
            if (!(w.z > MF_R(0.0))) goto clip;
            u[k] = mf__unit_or_zero(w);
        }
        if (base == 0) u0 = u[0];
        else s0 += mf__edge_z(prev, u[0]);
        for (k = 0; k + 1 < m; ++k) s1 += mf__edge_z(u[k], u[k + 1]);
        prev = u[m - 1];
    }
    s0 += mf__edge_z(prev, u0);
    return s0 + s1;
clip:
    return mf__polygon_clipped(A, p, n);
}

/* the cosine form factor: the sum over 2 pi */
MF_INLINE mf_real mf__polygon_form_factor(const mf_real *A, const mf_vec3 *p, int n)
{
    return mf__polygon_sum(A, p, n) * MF_R(0.15915494309189533577);
}

MF_INLINE mf_real mf__sided(mf_real ff, int two_sided)
{
    /* counterclockwise seen from the shading point is the front */
    ff = -ff;
    if (!(ff == ff)) return MF_R(0.0);
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

/* ---- LTC fitting and tables (Heitz et al. 2016, Sec. 4; Hill & Heitz 2016) ----
 * mf_ltc_fit fits, for one view direction wo = (sin t, 0, cos t), the LTC that
 * best matches the normalized lobe f(wo, wi) wi.z / albedo: M = B L with B the
 * frame whose z is the lobe's average direction and L = [m11 0 m13; 0 m22 0;
 * 0 0 1], found by Nelder-Mead on the cubed error estimated with multiple
 * importance sampling from the LTC and the BRDF (32 x 32 stratified samples
 * each, deterministic; the albedo from 256 x 256). The BRDF is either the specular microfacet BRDF of d
 * (brdf = NULL) or a callback returning f(wo, wi) wi.z (d = NULL; its side of
 * the estimate samples the cosine). Also returned: the albedo, integral of
 * f cos, and the Fresnel term, integral of f cos (1 - wo.h)^5, so that with
 * Schlick's F the lobe integrates to f0 albedo + (1 - f0) fresnel... written
 * out: (albedo - fresnel) f0 + fresnel. */
typedef mf_real (*mf_brdf_cos_fn)(mf_vec3 wo, mf_vec3 wi, void *ctx);
typedef struct mf_ltc_fit_result {
    mf_ltc ltc;          /* the fitted distribution */
    mf_real inv[4];      /* M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (normalized, table form) */
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
 * entry [alpha][theta], the six floats inv0 inv1 inv2 inv3 albedo fresnel
 * with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (middle entry 1: blending
 * this form between entries keeps the lobe; the form with a last entry of 1
 * has entries growing like 1 / alpha and bends it between rows). */
#define MF_LTC_ALPHA_MIN MF_R(1e-3)
typedef struct mf_ltc_table { int n_theta, n_alpha; float *data; } mf_ltc_table;
typedef void (*mf_progress_fn)(int done, int total, void *ctx);
MFDEF mf_result mf_ltc_table_build(mf_ltc_table *t, int kind, mf_real gamma, int n_theta, int n_alpha,
                                   mf_progress_fn progress, void *ctx);
MFDEF void mf_ltc_table_release(mf_ltc_table *t);
/* Bilinear lookup of the four M^-1 entries (and of the albedo and Fresnel
 * columns when asked for); M follows in closed form. */
MFDEF mf_ltc mf_ltc_table_lookup(const mf_ltc_table *t, mf_real cos_theta_o, mf_real alpha,
                                 mf_real *albedo, mf_real *fresnel);

/* Export of a table (mf_ltc_table.data, mf_ltc_ggx_table, n_theta x n_alpha
 * entries of six floats) as the two RGBA half-float (IEEE binary16) textures
 * of the published shaders: texel (column i = theta index, row j = alpha
 * index) at [4 (j n_theta + i)], tex1 = (inv0, inv1, inv2, inv3) with
 * M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (GLSL: mat3(vec3(r, 0, b),
 * vec3(0, 1, 0), vec3(g, 0, a)) is the same matrix, column-major), tex2 =
 * (albedo, fresnel, 0, 1). Sampling convention, linear filtering, clamp to
 * edge: uv = (sqrt(1 - cos theta_o), sqrt(alpha)) (n - 1) / n + 0.5 / n
 * (per axis), which puts the texel centres on the fitted nodes and equals
 * mf_ltc_table_lookup. Rounding is to nearest even; magnitudes below 2^-24
 * flush to 0, above 65504 give the largest finite half. Returns
 * MF_ERROR_INVALID_ARGUMENT on null pointers or sizes below 2, and
 * MF_ERROR_INVALID_DATA (textures untouched) when an entry is not finite. */
MFDEF mf_result mf_ltc_table_export_rgba16f(const float *data, int n_theta, int n_alpha, unsigned short *tex1,
                                            unsigned short *tex2);

/* Built-in table (tools/ltc_fit.c): the LTC of the GGX BRDF cos for
 * wo = (sin theta_o, 0, cos theta_o), isotropic alpha in [0, 1] (clamped below
 * at MF_LTC_ALPHA_MIN), normalized: f cos ~= mf_ltc_ggx_albedo mf_ltc_eval.
 * mf_ltc_ggx_fresnel is the integral of f cos (1 - wo.h)^5 (Schlick split).
 * mf_ltc_ggx_table exposes the raw 64 x 64 x 6 floats for GPU textures: rows
 * sqrt(alpha), columns sqrt(1 - cos theta_o), entries inv0 inv1 inv2 inv3
 * albedo fresnel with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (the layout
 * of the published shader textures). Not available in CUDA device code
 * (upload the table instead). The entries are the mf_ltc_table_build fit
 * refined on integrated polygons (tools/ltc_fit.c: per entry, the mean
 * relative error of the lobe's integral over 40 squares around and away
 * from the mirror direction): over 512 square lights near and away from
 * the lobe the mean relative error is 0.19 where the plain fit (and the
 * published table) give 0.29, at the same integration cost. About 5 min to
 * refit (double, one core). */
#ifndef MF_NO_LTC_TABLE
MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha);
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha);
/* The same for the Beckmann BRDF (table 14_ltc_table_beckmann.h, same layout,
 * 64 x 64, the plain mf_ltc_table_build fit: about 4 min). */
MFDEF mf_ltc mf_ltc_beckmann(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_beckmann_albedo(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_beckmann_fresnel(mf_real cos_theta_o, mf_real alpha);
MFDEF const float *mf_ltc_beckmann_table(int *n_theta, int *n_alpha);
#endif
/* Generated by tools/ltc_fit.c (`make ltc-table`): do not edit. */
/* ======================================================================== */
/* == 14. The built-in LTC table of GGX                                     */
/* ======================================================================== */
/* 64 x 64 LTC fits of the GGX BRDF times cos(theta_i) (mf_ltc_table_build,
 * fitted in double, then each entry refitted on its integrals over 40
 * training squares around and away from the mirror direction, see
 * tools/ltc_fit.c), rows sqrt(alpha), columns sqrt(1 - cos theta_o), six
 * floats per entry: inv0..inv3 with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3],
 * the albedo and the Fresnel column. Read through mf_ltc_ggx, mf_ltc_ggx_albedo,
 * mf_ltc_ggx_fresnel and mf_ltc_ggx_table (13_ltc.h). */
/* Generated by tools/ltc_fit.c (`make ltc-table`): do not edit. */
/* ======================================================================== */
/* == 14. The built-in LTC table of Beckmann                                */
/* ======================================================================== */
/* 64 x 64 LTC fits of the Beckmann BRDF times cos(theta_i) (mf_ltc_table_build,
 * fitted in double), rows sqrt(alpha), columns sqrt(1 - cos theta_o), six
 * floats per entry: inv0..inv3 with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3],
 * the albedo and the Fresnel column. Read through mf_ltc_beckmann, mf_ltc_beckmann_albedo,
 * mf_ltc_beckmann_fresnel and mf_ltc_beckmann_table (13_ltc.h). */
#ifndef MF_NO_IBM
/* ======================================================================== */
/* == 15. Inverse Bin Map                                                   */
/* ======================================================================== */
/* Atanasov et al. 2021 (thesis ch. 5): the filtered BRDF of a normal map over a
 * pixel footprint A (Eq. 5.1-5.3) grouped by directional bins (binned BRDF,
 * Eq. 5.7-5.8), truncated to the 21 bins around the half vector's bin (Eq.
 * 5.13, bin resolution Eq. 5.14), each texel a Beckmann flake lobe with Smith
 * shadowing (texel contribution C, Eq. 3.29); bin weights from the Inverse Bin
 * Map (Eq. 5.15, 5.17) with node-level prefiltering; sampling and pdf Eq. 5.16. */

/* Use: build once per normal map and flake roughness (mf_ibm_build, section
 * 14; about 0.05-0.1 s and 16-28 MB for a 2048^2 map), then per shading point
 * pass the pixel footprint in texture space (e.g. from ray differentials):
 *
 *     mf_ibm ibm;
 *     mf_ibm_build(&ibm, normals_xyz, 2048, 2048, 0.01f);   // check the mf_result
 *     mf_footprint fp = { u, v, dudx, dvdx, dudy, dvdy };
 *     mf_real f = mf_ibm_brdf(&ibm, &fp, wo, wi);           // no Fresnel, no cosine
 *     mf_vec3 wi2 = mf_ibm_sample(&ibm, &fp, wo, u1, u2, u3, u4);   // z <= 0: none
 *     mf_real pdf, f2 = mf_ibm_brdf_pdf(&ibm, &fp, wo, wi2, &pdf);  // both, one query
 *     mf_ibm_release(&ibm);
 *
 * The map's normals and wo, wi share the shading frame: x along u (texel
 * columns), y along v (rows), z the macro normal. The model (thesis Eq. 3.27-
 * 3.29, 5.2): each texel is a flat facet of normal t_k carrying a Beckmann
 * microsurface of roughness alpha around t_k; its contribution
 *     C(wo, wi, t) = D(h; t) G2(wo, wi; t) G_x(wo, wi, t) / (4 wo.z wi.z)
 * has D and the Smith G2 measured from t (height-correlated) and G_x the
 * Smith G2 of the normal map's own distribution (mf_ibm_set_shadowing). The
 * filtered BRDF is sum_k w_k C(t_k), w_k the texel's share of the footprint
 * (Eq. 5.2-5.3); the IBM groups texels by bin (Eq. 5.7), represents each bin by
 * its texels' mean normal, and keeps the bins around the half vector's bin
 * (Eq. 5.13): measured loss about 1% of the albedo (tests). Sampling picks a
 * texel by area, then a visible normal of its lobe, and returns no sample when
 * the truncation would not count it, so mf_ibm_pdf is its exact density and
 * integrates to 1 minus the no-sample mass (truncation, wi below the horizon,
 * wo behind the bin normal). Queries cost the footprint's perimeter in texels
 * (exact areas at the boundary, whole kd nodes inside), not its area. */

/* Layout of the single integer array (32-bit words), built by mf_ibm_build:
 *   header   MF__IBM_HEADER words: magic, version, sizes, parameters, checksum
 *   index    b*b + 1 packed fields: start of bin j's block in the lists (the
 *            index I of Sec. 5.4.4)
 *   means    b*b words: mean normal of each bin, 16 + 16 bits inside the bin
 *   lists    packed fields, one block per bin: the inverse bin map B^-1 (Eq.
 *            5.17), the bin's texel positions as Morton codes, sorted; a bin of
 *            n >= MF_IBM_TREE_MIN texels puts first n and the top k levels of
 *            its kd-tree (forest F): the 2^k + 1 boundaries of its level-k nodes
 *            in its list, k = floor(log2(n / 16))
 *   bin map  N packed fields (row-major): the bin of each texel (Eq. 5.15),
 *            stored as ix | iy << s (s bits per axis)
 * The kd-trees split the larger side of the power-of-two box holding the map
 * in the middle (x first on ties). The Morton code interleaves the bits in
 * exactly that order, so sorting a bin's positions by it makes every node a
 * contiguous range (Sec. 5.4.4): nodes down to level k are read from the
 * stored boundaries, deeper splits are found by binary search on the node's
 * bit, so no pointers are stored at all. */
#define MF_IBM_MAGIC 0x4d464942u          /* "BIFM" in little-endian bytes */
#define MF_IBM_VERSION 1u
#define MF_IBM_LEAF 10                    /* leaf size L of Sec. 5.4.4 */
#define MF_IBM_TREE_MIN 32                /* bins this large store the top of their kd-tree */
#define MF_IBM_MAX_RES 1024               /* bins per axis at most (index memory b^2) */
#define MF_IBM_MAX_RADIUS 8               /* neighbourhood radius in bins at most */
#define MF_IBM_MAX_WINDOW 289             /* (2 MF_IBM_MAX_RADIUS + 1)^2 */
#define MF_IBM_BATCH 21                   /* bins per kd traversal (the 21 of Sec. 5.4.2) */
#define MF_IBM_MAX_PIECES 64              /* period cells cut by the footprint, exact up to this */
#define MF_IBM_MIN_AREA MF_R(1e-6)        /* footprints smaller than this (texel^2): point lookup */
#ifndef MF_IBM_DIRECT_TEXELS
#define MF_IBM_DIRECT_TEXELS 2048         /* direct texel sum (Eq. 5.2) up to this bounding box (bench) */
#endif
#define MF__IBM_HEADER 16
#define MF__IBM_STACK 32

/* Parallelogram footprint in texture space, tiled with period 1: center
 * (u, v), edges a = (ax, ay), b = (bx, by); corners (u,v) +- a/2 +- b/2. Texel
 * (x, y) of a width x height map covers [x/width, (x+1)/width) x [y/height,
 * (y+1)/height). */
typedef struct mf_footprint { mf_real u, v, ax, ay, bx, by; } mf_footprint;

/* A built Inverse Bin Map (mf_ibm_build, mf_ibm_load). Everything it holds is
 * `data` (one allocation, `words` 32-bit words); the other fields are derived
 * from its header. The queries below only read `data`: copy it to the GPU and
 * point a copy of this struct at the copy to use them in device code. */
typedef struct mf_ibm {
    unsigned int *data;         /* the single integer array (layout above) */
    size_t words;               /* its length in 32-bit words */
    int width, height;          /* map size in texels */
    int res;                    /* b, bins per axis: b*b bins over [-1,1]^2 (Sec. 5.4.2) */
    int radius;                 /* neighbourhood radius: bins with dx^2+dy^2 <= r(r+1); 2 -> 21 bins */
    int kx, ky;                 /* log2 of the power-of-two box holding the map */
    int off_bits, pos_bits, list_bits, bin_bits, axis_bits;   /* widths of the packed fields */
    unsigned int list_len;      /* fields in the lists section */
    size_t off_at, mean_at, pos_at, bin_at;       /* word offsets of the sections */
    mf_real alpha;              /* Beckmann flake roughness */
    mf_real cut;                /* cut of the flake lobe in sigmas (3, Sec. 5.4.1) */
    mf_real shadow_ax, shadow_ay;   /* Beckmann roughness fitted to the map's slopes */
    int has_shadow;             /* 1: G_x is the Smith G2 of `shadow`; 0: G_x = 1 */
    mf_ndf shadow;              /* distribution of the normal map for G_x (Sec. 3.2.3) */
} mf_ibm;

/* The checksum of a map's array (mf_ibm_load checks it): a 4-lane
 * multiplicative hash of the words, the checksum word itself (word 15, lane 3)
 * taken as 0. */
MF_INLINE unsigned int mf__ibm_checksum(const unsigned int *w, size_t n)
{
    unsigned int h0 = 0x811c9dc5u, h1 = 0x01000193u, h2 = 0x9e3779b9u, h3 = 0x7f4a7c15u;
    size_t i;
    for (i = 0; i + 4u <= n; i += 4u) {
        unsigned int v3 = i + 3u == MF__IBM_HEADER - 1 ? 0u : w[i + 3u];
        h0 = (h0 ^ w[i]) * 0x01000193u + 1u;
        h1 = (h1 ^ w[i + 1u]) * 0x01000193u + 3u;
        h2 = (h2 ^ w[i + 2u]) * 0x01000193u + 5u;
        h3 = (h3 ^ v3) * 0x01000193u + 7u;
    }
    for (; i < n; ++i) h0 = (h0 ^ w[i]) * 0x01000193u + 11u;
    return h0 ^ (h1 * 0x9e3779b1u) ^ (h2 * 0x85ebca77u) ^ (h3 * 0xc2b2ae3du);
}

/* ---- bins (Sec. 5.4.2): b x b squares over [-1,1]^2 of (n.x, n.y) ---- */

MF_INLINE int mf__ibm_cell(mf_real v, int b)
{
    mf_real f = (mf_real)b * (MF_R(0.5) * v + MF_R(0.5));
    int c;
    if (!(f > MF_R(0.0))) return 0;              /* also NaN */
    if (f >= (mf_real)b) return b - 1;
    c = (int)f;                                  /* truncation = floor for f > 0 */
    return c >= 0 && c < b ? c : 0;              /* in range even where -ffast-math let NaN through */
}

/* b*b: the number of bins (those outside the unit disk stay empty). */
MF_INLINE int mf_ibm_bin_count(const mf_ibm *ibm)
{
    return ibm && ibm->data ? ibm->res * ibm->res : 0;
}

/* beta(n) = floor(b (n.x/2 + 1/2)) + b floor(b (n.y/2 + 1/2)) for the
 * normalized n; -1 for n below the horizon, zero or not finite. */
MF_INLINE int mf_ibm_bin_of(const mf_ibm *ibm, mf_vec3 n)
{
    if (!ibm || !ibm->data) return -1;
    n = mf_normalize(n);
    if (!(n.z >= MF_R(0.0)) || mf_dot(n, n) == MF_R(0.0)) return -1;
    return mf__ibm_cell(n.x, ibm->res) + ibm->res * mf__ibm_cell(n.y, ibm->res);
}

/* Number of texels in bin `bin`. */
MF_COLD int mf_ibm_bin_texels(const mf_ibm *ibm, int bin);

/* The normal that represents bin `bin` in C and in sampling: the mean of the
 * bin's texel normals (their (x, y) averaged, rounded to a multiple of 1/65536
 * of the bin - exact for the normal (0,0,1) - lifted to the hemisphere); the
 * bin center beta^-1(j, 1/2, 1/2) for an empty bin. The thesis uses the center; the mean is exact for a bin whose texels
 * share one normal (flat regions, flakes) and never farther from them. */
MF_COLD mf_vec3 mf_ibm_bin_normal(const mf_ibm *ibm, int bin);

/* The bin of texel (x, y) (wrapped into the map) from the bin map. */
MF_COLD int mf_ibm_texel_bin(const mf_ibm *ibm, int x, int y);

/* Sets the distribution whose Smith G2 is the normal map's shadowing G_x of
 * Eq. 3.29 (e.g. the GTR the flakes were drawn from, as in Sec. 5.5.4); NULL:
 * G_x = 1. mf_ibm_build and mf_ibm_load set mf_beckmann(shadow_ax, shadow_ay),
 * the Beckmann roughness of the map's RMS slopes (sqrt(2 E[s^2]) per axis). */
MF_COLD void mf_ibm_set_shadowing(mf_ibm *ibm, const mf_ndf *d);

/* ---- footprints: periods, pieces, exact areas ---- */

#define MF__IBM_NONE 0     /* no texel (center not finite) */
#define MF__IBM_POINT 1    /* degenerate footprint: the texel at the center */
#define MF__IBM_EXACT 2    /* full periods plus exact pieces */
#define MF__IBM_GLOBAL 3   /* too many periods: the whole map's histogram */

/* ---- bin weights: a window of bins around a center bin ---- */

/* Fraction of the footprint's area whose texels fall in `bin` (texels are
 * constant squares; Eq. 5.3, 5.8). Exact (polygon clipping) for any
 * parallelogram, rectangles through a fast path, wrapping across the border.
 * Footprints covering whole periods count them from the bin sizes; if the
 * footprint's boundary cuts more than MF_IBM_MAX_PIECES period cells the
 * weight is that of the whole map (n_bin / N) - exact when the footprint is a
 * union of whole periods, otherwise off by at most the cut cells' share of
 * the area. Zero area (< MF_IBM_MIN_AREA texels) or a non-finite edge: 1 for
 * the bin of the texel at the center, else 0; non-finite center: 0.
 * Cost: an empty bin (or, for the queries below, an empty neighbourhood)
 * returns before any footprint work; footprints of up to
 * MF_IBM_DIRECT_TEXELS bounding-box texels visit the box, reading each
 * texel's bin before clipping it, unless the wanted bins hold fewer texels
 * than half the box (then their lists are walked); larger ones traverse the
 * kd-trees. A texel cut by one footprint edge gets its area in closed form. */
MF_COLD mf_real mf_ibm_bin_weight(const mf_ibm *ibm, int bin, const mf_footprint *f);

/* The neighbourhood of `center_bin` (bins with dx^2 + dy^2 <= r(r+1), r =
 * ibm->radius: the 21 bins of Sec. 5.4.2 for r = 2) that hold texels, with
 * their weights, in one traversal. bins and weights must hold
 * MF_IBM_MAX_WINDOW entries; returns how many were written. */
MF_COLD int mf_ibm_neighbourhood_weights(const mf_ibm *ibm, const mf_footprint *f, int center_bin, int *bins,
                                           mf_real *weights);

/* ---- the filtered BRDF (Eq. 5.13), its pdf (Eq. 5.16) and sampling ---- */

/* Filtered glint BRDF over the footprint (Eq. 5.13 with F = 1, no cosine):
 * sum over the bins around the half vector's bin of W_j C(wo, wi, t_j). Each
 * bin is represented by its mean normal t_j (mf_ibm_bin_normal). Reciprocal.
 * Truncated like Eq. 5.13 (see the README for the measured truncation); for
 * small footprints the same sum is taken texel by texel (Eq. 5.2). 0 below
 * the horizon and for degenerate input. */
MF_COLD mf_real mf_ibm_brdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi);

/* Density of mf_ibm_sample per unit solid angle of wi (Eq. 5.16 with the
 * visible-normal density of each bin's lobe): sum of W_j D_wo(h; t_j) /
 * (4 wo.h) over the same bins as mf_ibm_brdf. It integrates to 1 minus the
 * no-sample mass of mf_ibm_sample. */
MF_COLD mf_real mf_ibm_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi);

/* mf_ibm_brdf and (in *pdf) mf_ibm_pdf from one weight query (MIS needs both). */
MF_COLD mf_real mf_ibm_brdf_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf);

/* Samples wi (Sec. 5.4.3): (u1, u2) a point of the footprint, uniform by
 * area, whose texel's bin j gives the normal t_j; (u3, u4) a visible normal m
 * of the flake Beckmann around t_j for wo; wi = reflect(wo, m). The zero vector
 * (no sample) when wo.t_j <= 0, wi is below the horizon, or the bin j is not
 * in the neighbourhood of beta(h) that mf_ibm_pdf sums (the truncation of Eq.
 * 5.13) - so the density of the returned wi is exactly mf_ibm_pdf. */
MF_COLD mf_vec3 mf_ibm_sample(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                mf_real u3, mf_real u4);

/* ---- Inverse Bin Map: builder, queries, filtered BRDF ---- */
#define MF_IBM_MIN_CUT MF_R(0.1)
/* Builds the Inverse Bin Map of a normal map (Sec. 5.4): normals_xyz holds
 * width*height unit normals (x, y, z; z > 0, length within 1e-3 of 1;
 * normalized before binning), row-major, texel (x, y) at index y*width + x.
 * flake_alpha is the Beckmann flake roughness (clamped to [MF_ALPHA_MIN,
 * MF_ALPHA_MAX] and rounded to float, so that a saved map reloads
 * bit-identically); the bin resolution is b = floor(5 / sin(theta0)),
 * theta0 = atan(3 sigma), sigma = alpha / sqrt(2) (Eq. 5.14), at most
 * MF_IBM_MAX_RES. mf_ibm_build_ex also takes the resolution b (0: Eq. 5.14)
 * and the cut in sigmas (0: 3, else in [MF_IBM_MIN_CUT, 10]: a cut that
 * rounds to 0 in float would not reload); the neighbourhood radius r grows with b so
 * that the bins around h cover the cut cone: r = max(2, ceil(b sin(theta0)/2
 * - 1/2)), at most MF_IBM_MAX_RADIUS (r = 2, the 21 bins, at the default b).
 * width and height in [1, 16384]; powers of two build fastest. Errors: NULL,
 * sizes, alpha <= 0 or NaN, resolution or cut out of range
 * (MF_ERROR_INVALID_ARGUMENT); a NaN, non-unit or below-horizon normal
 * (MF_ERROR_INVALID_DATA); allocation (MF_ERROR_OUT_OF_MEMORY). Nothing stays
 * allocated on failure, and *ibm is zeroed. */
MFDEF mf_result mf_ibm_build(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha);
MFDEF mf_result mf_ibm_build_ex(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha,
                                int resolution, mf_real cut_sigmas);
MFDEF void mf_ibm_release(mf_ibm *ibm);
/* Bytes held: the single integer array (ibm->words * 4). */
MFDEF size_t mf_ibm_memory_bytes(const mf_ibm *ibm);
/* Save and load (no stdio): mf_ibm_save copies the integer array (native
 * byte order) to buf when cap is large enough and returns the bytes it needs
 * (0 for an empty map). mf_ibm_load copies such a buffer (any alignment) into
 * a new map after validating everything a query reads: magic, version, sizes,
 * a checksum, the index, every texel position (in range, sorted, each texel
 * exactly once, in the bin the bin map gives it) and the bin map; a corrupted
 * or foreign buffer gives MF_ERROR_INVALID_DATA and nothing allocated.
 * mf_ibm_set_shadowing is not saved: set it again after loading. */
MFDEF size_t mf_ibm_save(const mf_ibm *ibm, void *buf, size_t cap);
MFDEF mf_result mf_ibm_load(mf_ibm *ibm, const void *buf, size_t bytes);
/* Area of the unit square where a linear function is >= 0, from its values
 * v[0..3] at the corners (0,0), (1,0), (1,1), (0,1): the triangle, trapezoid
 * or pentagon that one line cuts, each from crossing fractions v_i / (v_i -
 * v_j) of opposite-signed values (no cancellation). */
MF_INLINE mf_real mf__ibm_square_cut(const mf_real *v)
{
    int i, neg = 0, m = 0;
    for (i = 0; i < 4; ++i) if (v[i] < MF_R(0.0)) { ++neg; m |= 1 << i; }
    if (neg == 0) return MF_R(1.0);
    if (neg == 4) return MF_R(0.0);
    for (i = 0; i < 4; ++i) {
        int p = (i + 3) & 3, n = (i + 1) & 3, o = (i + 2) & 3;
        mf_real a = v[i], tp = a / (a - v[p]), tn = a / (a - v[n]);
        if (neg == 1 && (m >> i & 1)) return MF_R(1.0) - MF_R(0.5) * tp * tn;   /* corner i cut off */
        if (neg == 3 && !(m >> i & 1)) return MF_R(0.5) * tp * tn;              /* only corner i kept */
        if (neg == 2 && (m >> i & 1) && (m >> n & 1))                          /* edge i..n below */
            return MF_R(1.0) - MF_R(0.5) * (tp + v[n] / (v[n] - v[o]));
    }
    return MF_R(-1.0);   /* opposite corners below: not a single line */
}

#endif /* MF_NO_IBM */
#ifndef MF_NO_MICROSURFACE
/* ======================================================================== */
/* == 16. Microsurface generation and a virtual gonioreflectometer          */
/* ======================================================================== */
/* Ribardiere, Bringier, Meneveaux, Simonot 2019, "Microfacet BSDFs Generated
 * from NDFs and Explicit Microgeometry", Sec. 2 and 4: periodic height fields
 * whose normals follow any mf_ndf (Algorithm 1: slopes Q_m sampled from D,
 * Schwarz error Eq. 19, least-squares integration Eq. 20-21 with the discrete
 * derivatives of Eq. 22, re-matching), and a virtual gonioreflectometer that
 * traces them. Everything is in the implementation section (no inline part). */

/* ---- Microsurface generation and the virtual gonioreflectometer ---- */
/* mf_microsurface_generate (Ribardiere et al. 2019, Algorithm 1): a periodic
 * size x size height field whose normals follow d. Row-major (x along a row,
 * y down the rows), heights in units of the grid spacing, mean 0: the central
 * difference (h[x+1] - h[x-1]) / 2 is the slope dh/dx (and likewise in y), and
 * the normal (-dh/dx, -dh/dy, 1)/|.| follows d's distribution. The surface is
 * also consistent as a triangle mesh (each grid square split by the diagonal
 * from (x+1, y) to (x, y+1), the geometry mf_gonio_measure traces): every
 * triangle's slope is a one-sided difference at one of its corners, and the
 * generator targets one-sided and central differences alike (see the
 * implementation). The surface converges toward one that is smooth over a
 * few cells (slopes of neighbours correlated, as they must be for the two
 * readings to agree): histograms match D to a few percent (total variation
 * over the slope plane 0.02 to 0.03 for Beckmann, 0.04 to 0.05 for the heavier
 * tails of GGX and Student-t, at 128^2 and 150 iterations; a random sample of
 * the same size scores 0.04). size must be a power of two in [MF_MICROSURFACE_MIN_SIZE,
 * MF_MICROSURFACE_MAX_SIZE]; memory about 100 bytes per cell; time about
 * 0.15 us per cell and iteration (1024^2 x 500 in 73 s, one core).
 * Deterministic for a seed (within one build: float and double builds draw
 * different samples). d must be centered
 * (every periodic surface has mean slope 0): a LEADR distribution with a
 * non-zero mean slope is rejected. Errors: NULL pointers, bad size, negative
 * iterations or more than MF_MICROSURFACE_MAX_ITERATIONS, an invalid distribution (MF_ERROR_INVALID_ARGUMENT); allocation
 * (MF_ERROR_OUT_OF_MEMORY); nothing stays allocated on failure. */
/* 64-bit seeds: unsigned long long (C99, C++11; C++98 compilers accept it
 * as an extension, quietly here) */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wlong-long"
#endif
typedef unsigned long long mf_u64;
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif
#define MF_MICROSURFACE_MIN_SIZE 8
#define MF_MICROSURFACE_MAX_SIZE 4096
#define MF_MICROSURFACE_THRESHOLD MF_R(0.02)
/* the most re-matching iterations a call accepts (the paper uses 500; at
 * 4096^2 this cap is about 5 days of one core): more is an invalid argument */
#define MF_MICROSURFACE_MAX_ITERATIONS 100000
/* slopes drawn beyond this magnitude (heavy tails, u -> 1) are shortened to it */
#define MF_MICROSURFACE_MAX_SLOPE MF_R(1e3)

typedef struct mf_microsurface_options {
    int iterations;          /* re-matching iterations (the paper uses 500) */
    mf_u64 seed;
    mf_real threshold;       /* Schwarz threshold on eps(x, y), default MF_MICROSURFACE_THRESHOLD */
    mf_real max_rematch;     /* at most this fraction of the cells, those of largest eps, is */
                             /* re-matched per iteration; 1: all above the threshold, as in */
                             /* the paper; 0 (default): 0.5 for light tails down to 0.25 for */
                             /* heavy ones (see the implementation) */
    int stratified;          /* 1: jittered stratified random numbers for Q_m (default); 0: independent */
    mf_progress_fn progress; /* called after each iteration with (done, iterations, ctx); may be NULL */
    void *ctx;
    mf_real *gradients;      /* optional output, size*size*2: the final target gradient field, */
                             /* a permutation of the sampled slopes Q_m (x, y interleaved) */
    mf_real *schwarz;        /* optional output, size*size: the final eps(x, y) */
} mf_microsurface_options;

typedef struct mf_microsurface_stats {
    int iterations;          /* iterations done */
    mf_real below;           /* fraction of cells with eps <= threshold at the end */
    mf_real eps_mean;        /* mean of eps over the cells at the end */
    mf_real eps_median;
    int rematched;           /* cells above the threshold at the end (0 without iterations) */
    mf_real rms_target;      /* RMS of the sampled slopes |Q_m| (both components) */
    mf_real rms_central;     /* RMS of the central-difference slopes of the result */
    mf_real rms_triangle;    /* RMS of the triangle slopes of the result */
} mf_microsurface_stats;

MFDEF void mf_microsurface_options_default(mf_microsurface_options *o);
MFDEF mf_result mf_microsurface_generate(const mf_ndf *d, int size, int iterations, mf_u64 seed,
                                         mf_real *heights);
MFDEF mf_result mf_microsurface_generate_ex(const mf_ndf *d, int size, const mf_microsurface_options *o,
                                            mf_real *heights, mf_microsurface_stats *stats);
/* Step 3 alone: the periodic height field (mean 0) whose triangles and
 * central differences best fit per-point slopes gradients_xy (size*size*2,
 * x and y interleaved) in the least-squares sense; the discrete Poisson
 * equation, solved by FFT in double. A field that is the central difference
 * of a smooth surface gives that surface back up to O(w^2) per Fourier mode w
 * (the mode's amplitude times cos^2(w/2)). Same size rules and errors as the
 * generator; non-finite input: MF_ERROR_INVALID_DATA. */
MFDEF mf_result mf_microsurface_integrate(const mf_real *gradients_xy, int size, mf_real *heights);

/* The virtual gonioreflectometer (Ribardiere et al. 2019, Sec. 2): a
 * collimated beam from wi lights a periodic height field (heights in units of
 * the grid spacing, as above) traced as a triangle mesh with mirror or
 * Lambertian facets; every bounce is followed and the light leaving the
 * surface is recorded in a hemispherical sensor of equal-solid-angle cells
 * (rings of equal area whose sector counts keep the cells near square,
 * after Beckers and Beckers 2012), separately for the first bounce and for
 * the rest. A cell holds the fraction of the incident power it receives, an
 * estimate of the integral over the cell of f(wi, wo) cos(theta_o) dwo.
 * Rays start uniformly over one period, wrap around it and march the cells
 * with a 2D DDA; intersections are exact (the height above the surface is
 * linear on each triangle piece of the path). Rays still bouncing after
 * max_bounces, or still crossing the surface after 64 size + 65536 squares in
 * one flight, are counted as lost, with their power: at incidence within
 * about 0.001 rad of the horizon most rays are (a flight from the top of the
 * surface then spans more squares than that). */
#define MF_FACET_MIRROR 0
#define MF_FACET_LAMBERT 1
typedef struct mf_gonio_config {
    mf_vec3 wi;              /* unit, toward the light, wi.z > 0 */
    int facet;               /* MF_FACET_MIRROR or MF_FACET_LAMBERT */
    mf_real albedo;          /* power kept at each bounce, [0, 1] (default 1) */
    int rays;                /* default 1000000 */
    int max_bounces;         /* default 100 */
    mf_u64 seed;
    mf_progress_fn progress; /* called about 100 times with (rays done, rays, ctx); may be NULL */
    void *ctx;
} mf_gonio_config;

typedef struct mf_gonio {
    int rings, cells;        /* rings of the sensor (the first is the polar cap), cells in all */
    int *ring_first;         /* rings + 1 entries: index of the first cell of each ring */
    mf_real *ring_z;         /* rings + 1 entries: cos(theta) of the ring boundaries, 1 down to 0 */
    mf_real *first;          /* per cell: power fraction leaving after exactly one bounce */
    mf_real *multi;          /* per cell: after two bounces or more */
    int rays;                /* rays traced by the last measurement */
    int lost;                /* rays still on the surface after max_bounces or the step budget */
    int leaks;               /* rays found below the surface and put back (rounding; should be 0) */
    mf_real energy_first, energy_multi, energy_lost;   /* totals, fractions of the incident power */
    mf_real mean_bounces;    /* mean number of bounces per ray */
} mf_gonio;

MFDEF void mf_gonio_config_default(mf_gonio_config *c);
/* Allocates a sensor of `rings` rings (1..1024) with zero readings. */
MFDEF mf_result mf_gonio_init(mf_gonio *g, int rings);
MFDEF void mf_gonio_release(mf_gonio *g);
/* Cell of a direction (w.z > 0), -1 below the horizon or for NaN. */
MFDEF int mf_gonio_cell(const mf_gonio *g, mf_vec3 w);
/* Center of a cell: middle of its cos(theta) range and of its azimuth range. */
MFDEF mf_vec3 mf_gonio_cell_center(const mf_gonio *g, int cell);
/* Every cell has the solid angle 2 pi / cells. */
MFDEF mf_real mf_gonio_cell_solid_angle(const mf_gonio *g);
/* The cell is cos(theta) in [z_lo, z_hi], phi in [phi_lo, phi_hi) (radians, 0 to 2 pi). */
MFDEF void mf_gonio_cell_bounds(const mf_gonio *g, int cell, mf_real *z_lo, mf_real *z_hi,
                                mf_real *phi_lo, mf_real *phi_hi);
/* Traces c->rays rays over the height field (size x size, power of two,
 * 4..MF_MICROSURFACE_MAX_SIZE) and replaces the readings of g. Errors: NULL,
 * uninitialized g, bad size or configuration (MF_ERROR_INVALID_ARGUMENT),
 * non-finite heights (MF_ERROR_INVALID_DATA), allocation. */
MFDEF mf_result mf_gonio_measure(mf_gonio *g, const mf_real *heights, int size, const mf_gonio_config *c);
/* The single-scattering model for comparison: out[cell] = integral over the
 * cell of mf_brdf(d, wo, wi) wo.z dwo, by an n x n midpoint rule in
 * (cos theta, phi) per cell (n in 1..64). */
MFDEF mf_result mf_gonio_model(const mf_gonio *g, const mf_ndf *d, mf_vec3 wi, int n, mf_real *out);
#endif /* MF_NO_MICROSURFACE */
/* Generated by tools/energy_fit.c (`make energy-table`): do not edit. */
/* ======================================================================== */
/* == 17. The built-in directional-albedo tables of GGX and Beckmann        */
/* ======================================================================== */
/* E(mu, alpha), F = 1, of isotropic GGX then Beckmann (mf_albedo_integrate
 * in double, 16 panels): 64 rows sqrt(alpha) = i / 63, 64 columns
 * sqrt(mu) = j / 63 (mu = 1e-4 at j = 0), then E_avg, the exact average of
 * the row's interpolant. Read through mf_albedo (18_energy.h). */
/* ======================================================================== */
/* == 18. Energy compensation (multiple scattering)                         */
/* ======================================================================== */
/* Kulla & Conty 2017 ("Revisiting physically based shading at Imageworks",
 * section 2.1): single scattering (mf_brdf, F = 1) loses the energy 1 - E(wo),
 * E(wo) = int mf_brdf(wo, wi) wi.z dwi the directional albedo. The lobe
 *   f_ms(wo, wi) = (1 - E(wo)) (1 - E(wi)) / (pi (1 - E_avg)),
 *   E_avg = (1/pi) int E(w) w.z dw   (= 2 int_0^1 E(mu) mu dmu, isotropic)
 * puts it back: int (mf_brdf + f_ms) wi.z dwi = 1 for every wo, and f_ms is
 * reciprocal. Coloured conductors multiply f_ms by mf_ms_fresnel(F_avg, E_avg)
 * per channel (Kulla & Conty Eq. 2: F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
 * F_avg from mf_fresnel_conductor_average). The scaling form of Turquin 2019
 * ("Practical multiple scattering compensation for microfacet models",
 * Eq. 12-13) multiplies the single-scattering lobe by mf_ms_turquin_scale
 * (1 + F0 (1 - E) / E) instead: cheaper, energy-conserving at F = 1, but not
 * reciprocal and it changes the lobe's shape.
 *
 * E comes from built-in tables for isotropic GGX and Beckmann
 * (17_energy_table.h, generated by tools/energy_fit.c, `make energy-table`):
 * 64 x 64 entries, rows sqrt(alpha) in [0, 1], columns sqrt(mu) in [0, 1],
 * bilinear; alpha > 1 reads the last row. Anisotropic GGX and Beckmann use
 * the equivalent isotropic alpha sqrt(ax ay) (an approximation, its error is
 * measured in test_energy and stated in the README). Every other mf_ndf
 * (transformed, GTR, Student-t, tabulated, LEADR) is integrated on each call
 * by mf_albedo_integrate: exact but slow (4096 BRDF evaluations for E, about
 * 130 times more for E_avg); build an mf_albedo_table for it once instead.
 * Rough dielectrics: mf_dielectric_ms_table below. */
MFDEF mf_real mf_albedo(const mf_ndf *d, mf_vec3 wo);
MFDEF mf_real mf_albedo_average(const mf_ndf *d);
MFDEF mf_real mf_brdf_ms(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi);
MFDEF mf_real mf_ms_turquin_scale(const mf_ndf *d, mf_vec3 wo, mf_real f0);
/* E(wo) by quadrature of f cos / pdf over the visible-normal sampler's unit
 * square ((8 panels)^2 of 8 x 8 Gauss-Legendre nodes, panels = 8), exact for
 * every mf_ndf; panels in [1, 64]. 0 when wo.z <= 0 or on bad input. */
MFDEF mf_real mf_albedo_integrate(const mf_ndf *d, mf_vec3 wo, int panels);

/* Kulla & Conty Eq. 2: the per-channel factor of f_ms for a Fresnel average
 * F_avg in [0, 1] (1 at F_avg = 1). */
MF_INLINE mf_real mf_ms_fresnel(mf_real f_avg, mf_real e_avg)
{
    mf_real den;
    f_avg = mf_clamp(f_avg, MF_R(0.0), MF_R(1.0));
    e_avg = mf_clamp(e_avg, MF_R(0.0), MF_R(1.0));
    if (!(f_avg == f_avg) || !(e_avg == e_avg)) return MF_R(0.0);
    den = MF_R(1.0) - f_avg * (MF_R(1.0) - e_avg);
    return den > MF_R(1e-12) ? f_avg * f_avg * e_avg / den : MF_R(0.0);
}

/* The compensation lobe is sampled with the cosine distribution (its shape
 * in wi is (1 - E(wi)) wi.z, close to cosine): pdf = wi.z / pi. The weight
 * f_ms wi.z / pdf = pi f_ms. d and wo are unused (kept for symmetry with
 * mf_brdf_sample). The zero vector when wo.z <= 0. */
MF_INLINE mf_vec3 mf_brdf_ms_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
{
    mf_real r, phi, z;
    (void)d;
    if (!(wo.z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    r = MF_SQRT(u1);
    phi = MF_R(2.0) * MF_PI * u2;
    z = MF_SQRT(mf_max(MF_R(1.0) - u1, MF_R(0.0)));
    if (!(z > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return mf_vec3_make(r * MF_COS(phi), r * MF_SIN(phi), z);
}
MF_INLINE mf_real mf_brdf_ms_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    (void)d;
    if (!(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf_min(wi.z, MF_R(1.0)) / MF_PI;
}

/* A table of E(wo) for one mf_ndf (any kind, transforms included):
 * n_mu x n_phi entries at mu = x^2, x = i / (n_mu - 1) (mu = 1e-4 at x = 0),
 * azimuth phi = 2 pi j / n_phi (n_phi = 1 for an isotropic distribution),
 * each by mf_albedo_integrate; bilinear in (x, phi), periodic in phi. E_avg
 * is the exact hemispherical average of that interpolant, so the table's
 * compensated lobe conserves energy to the table's own accuracy.
 * n_mu in [2, 1024], n_phi in [1, 1024], panels as mf_albedo_integrate.
 * Returns MF_ERROR_INVALID_ARGUMENT (t zeroed when not NULL),
 * MF_ERROR_OUT_OF_MEMORY or MF_ERROR_INVALID_DATA (an entry not finite); on
 * failure nothing is left allocated. Release with mf_albedo_table_release. */
typedef struct mf_albedo_table {
    int n_mu, n_phi;
    mf_real *E;        /* [j * n_mu + i] */
    mf_real E_avg;
} mf_albedo_table;
MFDEF mf_result mf_albedo_table_build(mf_albedo_table *t, const mf_ndf *d, int n_mu, int n_phi, int panels);
MFDEF void mf_albedo_table_release(mf_albedo_table *t);
MFDEF mf_real mf_albedo_table_eval(const mf_albedo_table *t, mf_vec3 wo);
MFDEF mf_real mf_albedo_table_average(const mf_albedo_table *t);
MFDEF mf_real mf_brdf_ms_table(const mf_albedo_table *t, mf_vec3 wo, mf_vec3 wi);

/* Rough dielectrics (Kulla & Conty 2017, section 2.2), for one mf_ndf and
 * one eta (index below over index above, as mf_dielectric_bsdf). E1(mu) and
 * E2(mu) are the albedos of reflection plus transmission seen from above
 * (entering, relative index eta) and from below (exiting, 1 / eta), in
 * importance (flux) transport, i.e. without the 1 / e^2 factor of
 * transmitted radiance: that is the transport in which a non-absorbing
 * interface must conserve, E + compensation = 1 from either side. The
 * compensation is split between reflection and transmission so that it is
 * reciprocal (generalized: f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2 in
 * radiance form) and conserves on both sides: from above a share
 * x = 1 - F_avg(eta) (mf_fresnel_dielectric_average) is transmitted, from
 * below the share y = x (1 - E1_avg) / (eta^2 (1 - E2_avg)), which
 * reciprocity dictates; the lobes are
 *   reflection above    (1 - x) (1 - E1(mu_o)) (1 - E1(mu_i)) / (pi (1 - E1_avg))
 *   reflection below    (1 - y) (1 - E2(mu_o)) (1 - E2(mu_i)) / (pi (1 - E2_avg))
 *   transmission down   x (1 - E1(mu_o)) (1 - E2(mu_i)) / (pi (1 - E2_avg))
 *   transmission up     y (1 - E2(mu_o)) (1 - E1(mu_i)) / (pi (1 - E1_avg))
 * (importance form; mf_dielectric_bsdf_ms returns the radiance form, the
 * transmitted lobes divided by e^2 = (eta_i / eta_o)^2 like
 * mf_dielectric_bsdf). x is clamped to keep y <= 1. E1 and E2 are
 * tabulated at n_mu nodes mu = x^2 as mf_albedo_table, by quadrature over
 * the visible normals of the side of wo (panels as mf_albedo_integrate).
 * There are no built-in dielectric tables: build one per material. */
typedef struct mf_dielectric_ms_table {
    int n_mu;
    mf_real eta;
    mf_real *E;              /* E1 at [i], E2 at [n_mu + i] */
    mf_real E1_avg, E2_avg;  /* hemispherical averages of the interpolants */
    mf_real x, y;            /* shares transmitted from above and from below */
} mf_dielectric_ms_table;
MFDEF mf_result mf_dielectric_ms_build(mf_dielectric_ms_table *t, const mf_ndf *d, mf_real eta, int n_mu, int panels);
MFDEF void mf_dielectric_ms_release(mf_dielectric_ms_table *t);
/* E(wo) of the side of wo (importance transport, reflection + transmission) */
MFDEF mf_real mf_dielectric_albedo(const mf_dielectric_ms_table *t, mf_vec3 wo);
/* the same by quadrature, for any mf_ndf (0 on bad input) */
MFDEF mf_real mf_dielectric_albedo_integrate(const mf_ndf *d, mf_vec3 wo, mf_real eta, int panels);
/* the compensation lobe (radiance form), its sampling (u3 picks the side:
 * transmission with the share of wo's side; cosine on that side) and pdf */
MFDEF mf_real mf_dielectric_bsdf_ms(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_vec3 wi);
MFDEF mf_vec3 mf_dielectric_ms_sample(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_real u1, mf_real u2, mf_real u3);
MFDEF mf_real mf_dielectric_ms_pdf(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_vec3 wi);


#ifdef __cplusplus
}
#endif

#endif /* MICROFACET_H */

/* ======================================================================== */
/* == Cold paths: compiled once, in the implementation, on host builds;    */
/* == in every translation unit under nvcc (device code calls them).       */
/* ======================================================================== */
#if (defined(MICROFACET_IMPLEMENTATION) || defined(__CUDACC__)) && !defined(MICROFACET_COLD_DONE)
#define MICROFACET_COLD_DONE
#ifdef __cplusplus
extern "C" {
#endif

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
    /* keep off the edge phi0, where the density is 0 (u = 0 would land on it):
     * the CDF mass moved is 4 eps */
    if (c < MF_R(1.0)) u = mf_min(u, MF_R(1.0) - MF_R(4.0) * MF_EPS);
    lo = MF_R(0.0); hi = phi0; phi = u * phi0;
    for (i = 0; i < 60; ++i)
        if (mf__newton_step(&phi, c * phi + MF_SIN(phi) - u * total, c + MF_COS(phi), &lo, &hi, MF_R(4.0) * MF_EPS))
            break;
    MF__SOLVER_DONE(MF__SITE_PHI_COS, i, 60);
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

/* node i of the 8-point rule in panel p of `panels` equal panels of [0, 1] */
MF_INLINE mf_real mf__gl_node01(int p, int i, int panels)
{
    return ((mf_real)p + MF_R(0.5) + MF_R(0.5) * mf__gl_xi(i)) / (mf_real)panels;
}

/* 4-point Gauss-Legendre rule on [-1, 1], weights normalized to sum 1. */
MF_INLINE mf_real mf__gl4_xi(int i)
{
    const mf_real x[4] = { MF_R(-0.86113631159405258), MF_R(-0.33998104358485626), MF_R(0.33998104358485626),
                           MF_R(0.86113631159405258) };
    return x[i];
}
MF_INLINE mf_real mf__gl4_w(int i)
{
    const mf_real w[4] = { MF_R(0.17392742256872693), MF_R(0.32607257743127307), MF_R(0.32607257743127307),
                           MF_R(0.17392742256872693) };
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
/* Beckmann visible slopes for unit roughness and view tan(theta) = tv (view
 * along +x): the slope x along the view has density ~ max(0, 1 - tv x) exp(-x^2),
 * G(x) = erfc(-x)/2 + tv exp(-x^2)/(2 sqrt(pi)) (Heitz & d'Eon 2014 Eq. 9 up to
 * the factor 1 + tv) is solved for G(x) = u1 G(1/tv) by safeguarded Halley
 * steps sharing one erfc and one exp; y ~ N(0, 1/2). The start blends the
 * quantiles of the two limits, erfinv(2u - 1) at tv = 0 and -sqrt(-log u) as
 * tv -> infinity (where G ~ exp(-x^2)); past the top 1/tv it uses the
 * quadratic tail G(1/tv) - G(x) ~ tv exp(-1/tv^2) (1/tv - x)^2 / (2 sqrt(pi)). */
/* Halley converges cubically: after a step s the error is O(s^3) (times
 * 1 / (1/tv - x)^2 near the top, hence the tolerance relative to that gap), so
 * a step below eps^(1/3) / 5 is the last one. */
#ifndef MF__HALLEY_TOL
#ifdef MF_USE_DOUBLE
#define MF__HALLEY_TOL MF_R(1e-6)
#else
#define MF__HALLEY_TOL MF_R(1e-3)
#endif
#endif
MF_COLD void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy)
{
    const mf_real k = MF_R(0.28209479177387814);   /* 1 / (2 sqrt(pi)) */
    mf_real u = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), w = tv / (MF_R(0.5) + tv);
    mf_real mu = tv > MF_R(1.0) / MF_R(12.0) ? MF_R(1.0) / tv : MF_R(12.0), total = MF_R(1.0), top = MF_R(0.0);
    /* lo: x^2 + y^2 stays below mf_beckmann_D's cut of 80 for every u2 (|y| <=
     * 5.9), so u1 = 0 gives a normal of positive density; the mass cut is 1e-20 */
    mf_real lo = MF_R(-6.5), hi = mu, x, target;
    int i;
    *sy = mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
    if (!(tv > MF_EPS) && MF_FABS(u - MF_R(0.5)) < MF_R(0.4999)) {   /* x(tv) = x(0) + O(tv) */
        *sx = mf_erfinv(MF_R(2.0) * u - MF_R(1.0));
        return;
    }
    x = mf__erfinv_giles(mf_clamp(MF_R(2.0) * u - MF_R(1.0), MF_R(-1.0) + MF_EPS, MF_R(1.0) - MF_EPS));
    x = (MF_R(1.0) - w) * x - w * MF_SQRT(-MF_LOG(mf_max(u, MF_R(1e-30))));
    if (tv > MF_R(1.0) / MF_R(6.0)) {   /* else G(mu) = 1 to double precision */
        top = tv * k * MF_EXP(-mu * mu);
        total = MF_R(0.5) * MF_ERFC(-mu) + top;
        if (x >= mu) x = mu - MF_SQRT((MF_R(1.0) - u) * total / mf_max(top, MF_R(1e-30)));
    }
    target = u * total;
    x = mf_clamp(x, lo, hi);
    for (i = 0; i < 60; ++i) {
        mf_real e = MF_EXP(-x * x), s = MF_R(1.0) - tv * x;
        mf_real f = MF_R(0.5) * MF_ERFC(-x) + tv * k * e - target;
        mf_real df = MF_R(2.0) * k * e * s, r = df > MF_R(0.0) ? f / df : MF_R(0.0);
        /* Halley: f / (f' - f f'' / (2 f')), with f''/f' = -2x - tv / (1 - tv x);
         * a non-positive effective slope falls back to bisection */
        df *= MF_R(1.0) + MF_R(0.5) * r * (MF_R(2.0) * x + tv / mf_max(s, MF_R(1e-30)));
        if (mf__newton_step(&x, f, df, &lo, &hi, MF__HALLEY_TOL * mf_min(MF_R(1.0) + MF_FABS(x), mu - x))) break;
    }
    MF__SOLVER_DONE(MF__SITE_BECKMANN, i, 60);
    *sx = x;
}
/* D, homogeneous of degree -4: N / ((sin^2 + a^2 cos^2)^gamma |wm|^4) */
MF_COLD mf_real mf__gtr_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real s2, l2, den;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    s2 = wm.x * wm.x + wm.y * wm.y;
    l2 = s2 + wm.z * wm.z;
    den = (s2 + d->ax * d->ax * wm.z * wm.z) / l2;  /* 1 + (a^2 - 1) cos^2 */
    return d->p.gtr.norm / (MF_POW(den, d->p.gtr.gamma) * l2 * l2);
}

/* Dimov's gamma = 4 Lambda (C.11), in t2 = tan^2(theta) and a2 = alpha^2
 * (also the component of the gamma-4 mixture). */
MF_INLINE mf_real mf__gtr_lambda4(mf_real a2, mf_real t2)
{
    mf_real a2t2 = a2 * t2, qa = MF_SQRT(MF_R(1.0) + a2t2), ea = a2t2 / (qa + MF_R(1.0));
    mf_real a4 = a2 * a2, A4 = MF_R(8.0) * (a4 + a2 + MF_R(1.0));
    return a2t2 * (MF_R(12.0) * a4 - A4 * ea * (qa + MF_R(0.5)) / (qa + MF_R(1.0)) +
                   MF_R(3.0) * a2t2 * (MF_R(5.0) * a4 + MF_R(2.0) * a2 + MF_R(1.0))) /
           (MF_R(2.0) * A4 * qa * qa * qa);
}

/* GTR Lambda at integer gamma g = 0..4 (thesis Eq. C.7-C.11 with mu = 1/t),
 * only the one asked for; differences such as sqrt(1 + a2 t2) - 1 are
 * written as quotients so nothing cancels. */
MF_INLINE mf_real mf__gtr_lambda_int(int g, mf_real a2, mf_real L, mf_real t2)
{
    mf_real qa, qb, ea, d, y;
    if (g == 4) return mf__gtr_lambda4(a2, t2);                       /* C.11 */
    qb = MF_SQRT(MF_R(1.0) + t2);
    if (g == 0) return t2 / (MF_R(2.0) * (MF_R(1.0) + qb));           /* C.7: GGX with alpha = 1 */
    qa = MF_SQRT(MF_R(1.0) + a2 * t2);
    ea = a2 * t2 / (qa + MF_R(1.0));                                   /* qa - 1 */
    if (g == 2) return MF_R(0.5) * ea;                                 /* C.9: GGX */
    if (g == 3)                                                        /* C.10 */
        return a2 * t2 * ((MF_R(3.0) * a2 + MF_R(1.0)) * ea + MF_R(4.0) * a2) /
               (MF_R(4.0) * (a2 + MF_R(1.0)) * qa * (qa + MF_R(1.0)));
    /* C.8: Lambda1 = [(qa - qb) - log1p((qa - qb)/(1 + qb))] / L */
    d = t2 / (qa + qb);                                                /* (qa - qb) / (a2 - 1) */
    y = (a2 - MF_R(1.0)) * d / (MF_R(1.0) + qb);
    return d * (MF_R(1.0) - mf__log1p_over_x(y) / (MF_R(1.0) + qb)) / mf__x_over_expm1(L);
}

/* GTR Lambda, exact at every gamma. With x = tan^2, the slope density is
 * proportional to (1+x)^(gamma-2) (a^2+x)^-gamma; Feynman's parametrization
 * 1/(A^l B^m) = B(l,m)^-1 int s^(l-1) (1-s)^(m-1) (sA + (1-s)B)^-(l+m) ds with
 * A = 1 + x, B = a^2 + x writes it as a positive mixture over b = a^2 + s(1 - a^2)
 * in [a^2, 1] of
 *   gamma in (0, 2): GGX slope densities of alpha^2 = b (l = 2 - gamma, m = gamma);
 *   gamma in (2, 4): gamma = 4 GTR densities of alpha^2 = b (l = 4 - gamma, m = gamma).
 * Lambda is linear in the slope density, so it is the same mixture of Dimov's
 * Lambdas (C.9, C.11). In y = log b the mixing weight is
 * (y - log a^2)^(l-1) (-y)^(m-1) times a smooth positive factor, and the
 * components are analytic in the strip |Im y| < pi: mf__gtr_mix_init builds
 * the Gauss-Jacobi rule of those exponents on [log a^2, 0], its weights times
 * that factor, normalized. Integer gamma: the closed forms C.7-C.11.
 * 16 nodes for gamma < 2, 24 for gamma > 2. Measured against an independent
 * 1D integral of the slope density (tests/test_ndf.c, alpha 1e-4 and 1e-3..1,
 * 25 gammas in [0, 4], theta 1..89.9 deg): relative error of Lambda <= 2.0e-6
 * in double (test bound 1e-5); float 6.8e-6 where Lambda > 1e-4 and 8.1e-7
 * on 1 + Lambda. Cost (make bench, float): 12x GGX's Lambda for gamma < 2,
 * 35x for gamma in (2, 4) (the gamma-4 components are dearer); building the
 * rule makes mf_gtr at non-integer gamma cost 5-15 us (Golub-Welsch; integer
 * gamma costs nothing), and the rule makes mf_ndf 544 bytes in double (192
 * before), 288 in float (104). tan^2 is capped at 1e16
 * (Lambda ~ 1e8, G1 ~ 1e-8) so float never overflows. */
MF_COLD mf_real mf__gtr_lambda(const mf_ndf *d, mf_vec3 w)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real t2 = mf_min(mf__a2t2(MF_R(1.0), MF_R(1.0), w), MF_R(1e16)), sum = MF_R(0.0);
    int j;
    if (!(t2 > MF_R(0.0))) return MF_R(0.0);
    if (p->mix == 1) {
        for (j = 0; j < p->nq; ++j) {
            mf_real bt = p->qb[j] * t2;
            sum += p->qw[j] * bt / (MF_SQRT(MF_R(1.0) + bt) + MF_R(1.0));
        }
        return MF_R(0.5) * sum;
    }
    if (p->mix == 2) {   /* C.11 cancels to -1e-22 in float at small a^2 t^2 */
        for (j = 0; j < p->nq; ++j) sum += p->qw[j] * mf__gtr_lambda4(p->qb[j], t2);
        return mf_max(sum, MF_R(0.0));
    }
    /* integer gamma: C.11 can round to -4e-23 in float */
    return mf_max(mf__gtr_lambda_int((int)p->gamma, d->ax * d->ax, p->L, t2), MF_R(0.0));
}

/* Gauss-Jacobi rule for the weight (1-x)^ea (1+x)^eb on [-1, 1] by Golub and
 * Welsch (1969): nodes are the eigenvalues of the Jacobi matrix of the
 * polynomials' recurrence, weights the squared first components of its unit
 * eigenvectors (unnormalized: the caller normalizes). Implicit QL with Wilkinson
 * shifts, at most 60 sweeps per eigenvalue. */
MF_INLINE void mf__gauss_jacobi(int n, mf_real ea, mf_real eb, mf_real *x, mf_real *w)
{
    mf_real e[MF__GTR_NQ];
    int i, l, m, it;
    for (i = 0; i < n; ++i) {
        mf_real s = MF_R(2.0) * (mf_real)i + ea + eb, k = (mf_real)(i + 1), t = MF_R(2.0) * k + ea + eb;
        x[i] = i == 0 ? (eb - ea) / (ea + eb + MF_R(2.0)) : (eb - ea) * (eb + ea) / (s * (s + MF_R(2.0)));
        e[i] = i + 1 < n ? MF_SQRT(MF_R(4.0) * k * (k + ea) * (k + eb) * (k + ea + eb) /
                                   (t * t * (t + MF_R(1.0)) * (t - MF_R(1.0)))) : MF_R(0.0);
        w[i] = i == 0 ? MF_R(1.0) : MF_R(0.0);   /* first row of the eigenvector matrix */
    }
    for (l = 0; l < n; ++l) {
        for (it = 0; it < 60; ++it) {
            mf_real g, r, s, c, pp, f, bb;
            for (m = l; m < n - 1; ++m)
                if (MF_FABS(e[m]) <= MF_EPS * (MF_FABS(x[m]) + MF_FABS(x[m + 1]))) break;
            if (m == l) break;
            g = (x[l + 1] - x[l]) / (MF_R(2.0) * e[l]);
            r = MF_SQRT(g * g + MF_R(1.0));
            g = x[m] - x[l] + e[l] / (g + (g >= MF_R(0.0) ? r : -r));
            s = c = MF_R(1.0); pp = MF_R(0.0);
            for (i = m - 1; i >= l; --i) {
                f = s * e[i]; bb = c * e[i];
                r = MF_SQRT(f * f + g * g); e[i + 1] = r;
                if (r == MF_R(0.0)) { x[i + 1] -= pp; e[m] = MF_R(0.0); break; }
                s = f / r; c = g / r; g = x[i + 1] - pp;
                r = (x[i] - g) * s + MF_R(2.0) * c * bb;
                pp = s * r; x[i + 1] = g + pp; g = c * r - bb;
                f = w[i + 1]; w[i + 1] = s * w[i] + c * f; w[i] = c * w[i] - s * f;
            }
            if (r == MF_R(0.0) && i >= l) continue;
            x[l] -= pp; e[l] = g; e[m] = MF_R(0.0);
        }
    }
    for (i = 0; i < n; ++i) w[i] *= w[i];
}

/* The mixture rule of mf__gtr_lambda for p->gamma and p->L (see there). With
 * u = y - log a^2, the smooth factor is, in logs,
 *   (l-1) log(expm1(u)/u) + (m-1) log(expm1(y)/y)      (the exact endpoint factors)
 *   + gamma-4 only: log of b times the component's normalization,
 *     1 + c/b + c^2/(3 b^2), c = 1 - b. */
MF_COLD void mf__gtr_mix_init(mf_ndf_gtr *p)
{
    mf_real g = p->gamma, L = p->L, el, em = g - MF_R(1.0), x[MF__GTR_NQ], w[MF__GTR_NQ], lf[MF__GTR_NQ];
    mf_real top = -MF_BIG, sum = MF_R(0.0);
    int i, n;
    if (g == MF_FLOOR(g)) { p->mix = 0; p->nq = 0; return; }
    p->mix = g < MF_R(2.0) ? 1 : 2;
    n = p->nq = g < MF_R(2.0) ? 16 : MF__GTR_NQ;
    el = (g < MF_R(2.0) ? MF_R(2.0) : MF_R(4.0)) - g - MF_R(1.0);
    /* x = 1 is b = 1 (exponent m - 1), x = -1 is b = a^2 (exponent l - 1) */
    mf__gauss_jacobi(n, em, el, x, w);
    for (i = 0; i < n; ++i) {
        mf_real y = MF_R(0.5) * L * (MF_R(1.0) - x[i]), u = y - L, b = MF_EXP(y), f;
        f = (u > MF_R(1e-6) ? el * MF_LOG(MF_EXPM1(u) / u) : MF_R(0.0)) +
            (y < MF_R(-1e-6) ? em * MF_LOG(MF_EXPM1(y) / y) : MF_R(0.0));
        if (p->mix == 2) {
            mf_real c = MF_R(1.0) - b, cb = c / b;
            f += MF_LOG(MF_R(1.0) + cb + cb * cb / MF_R(3.0));
        }
        p->qb[i] = b;
        lf[i] = f;
        if (f > top) top = f;
    }
    for (i = 0; i < n; ++i) { p->qw[i] = w[i] * MF_EXP(lf[i] - top); sum += p->qw[i]; }
    for (i = 0; i < n; ++i) p->qw[i] /= sum;
}

/* tan^2(theta) at D-cos mass t from the pole (q = 1 - t beyond): w = sin^2 +
 * a^2 cos^2 has density ~ w^-gamma on [a^2, 1]; log w = lw. MF_BIG at q = 0. */
MF_COLD mf_real mf__gtr_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    const mf_ndf_gtr *p = &d->p.gtr;
    mf_real L = p->L, uq, ut, lw, llw, c2, s2;
    if (!(q > MF_R(0.0))) return MF_BIG;
    if (!(t > MF_R(0.0))) return MF_R(0.0);
    /* uq = lw / L and ut = (L - lw) / L add up to 1. Each is computed from
     * its own end (q or t), starting from the smaller mass, which carries the
     * precision (the other is 1 minus it); the other end takes over when its
     * u is the smaller one and its mass keeps log1p away from -1 (in float,
     * t = 1 - 6e-9 rounds to 1 and t EM to -1 at gamma 4, alpha 0.0015). */
    if (q <= t) {
        uq = q * mf__log1p_over_x(q * p->E) / p->RK;
        ut = MF_R(1.0) - uq;
        if (uq > MF_R(0.5) && t * p->EM > MF_R(-0.5)) { ut = t * mf__log1p_over_x(t * p->EM) / p->RMK; uq = MF_R(1.0) - ut; }
    } else {
        ut = t * mf__log1p_over_x(t * p->EM) / p->RMK;
        uq = MF_R(1.0) - ut;
        if (ut > MF_R(0.5) && q * p->E > MF_R(-0.5)) { uq = q * mf__log1p_over_x(q * p->E) / p->RK; ut = MF_R(1.0) - uq; }
    }
    lw = L * uq; llw = L * ut;
    c2 = uq / mf__x_over_expm1(lw);            /* cos^2 r(L)^-1 */
    s2 = MF_EXP(lw) * ut / mf__x_over_expm1(llw);
    if (!(c2 > MF_R(0.0))) return MF_BIG;
    return mf_min(s2 / c2, MF_BIG);
}

/* D-cos mass beyond the polar angle whose tan^2 is tan2 (inverse of the above). */
MF_COLD mf_real mf__gtr_tail(const mf_ndf *d, mf_real tan2)
{
    mf_real a2 = d->ax * d->ax, a2m1 = a2 - MF_R(1.0), x = MF_R(1.0) / (MF_R(1.0) + tan2);
    mf_real L = d->p.gtr.L, k = MF_R(1.0) - d->p.gtr.gamma, lwL;
    /* log w / L, w = (tan^2 + a^2) / (1 + tan^2); the log1p form (exact at
     * alpha -> 1) would take log1p(a^2 - 1) = log1p(-1) in float at alpha 1e-4 */
    if (a2 < MF_R(0.25)) lwL = (MF_LOG(tan2 + a2) - MF_LOG1P(tan2)) / L;
    else lwL = x * mf__log1p_over_x(a2m1 * x) / mf__log1p_over_x(a2m1);
    return lwL * mf__x_over_expm1(k * L) / mf__x_over_expm1(k * L * lwL);
}

MF_COLD mf_vec3 mf__gtr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(MF_R(1.0), MF_R(1.0), mf__gtr_tan2(d, t, MF_R(1.0) - t), u2);
}

MF_COLD mf_vec3 mf__gtr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__iso_sample_visible_view(d, MF_R(1.0), MF_R(1.0), w, u1, u2);
}
/* Eq. 8 and 10: Gaussian slopes with mean and covariance, / cos^4 */
MF_COLD mf_real mf__leadr_D(const mf_ndf *d, mf_vec3 wm)
{
    const mf_ndf_leadr *p = &d->p.leadr;
    mf_real sx, sy, q, z2;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    sx = -wm.x / wm.z - p->mx;
    sy = -wm.y / wm.z - p->my;
    q = p->ixx * sx * sx + MF_R(2.0) * p->ixy * sx * sy + p->iyy * sy * sy;
    if (!(q >= MF_R(0.0) && q < MF_R(160.0))) return MF_R(0.0);   /* q < 0: float overflow */
    z2 = wm.z * wm.z;
    return p->norm * MF_EXP(MF_R(-0.5) * q) / (z2 * z2);
}

/* slope = mean + L n, n two standard normals */
MF_COLD mf_vec3 mf__leadr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    const mf_ndf_leadr *p = &d->p.leadr;
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    mf_real n1 = MF_R(1.4142135623730951) * mf_erfinv(MF_R(2.0) * t - MF_R(1.0));
    mf_real n2 = MF_R(1.4142135623730951) * mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
    mf_real sx = p->mx + p->l00 * n1;
    mf_real sy = p->my + p->l10 * n1 + p->l11 * n2;
    return mf_normalize(mf_vec3_make(-sx, -sy, MF_R(1.0)));
}

/* LEADR Lambda (Eq. 13-15 and the supplement, Sec. 1.5): the exact Smith
 * Lambda of the shifted Gaussian relative to the mesonormal's projected area,
 * Lambda = exp(-nu^2) / (2 nu sqrt(pi)) - erfc(nu) / 2 with
 * nu = (cot theta - mu(phi)) / (sigma(phi) sqrt 2); +infinity (MF_BIG) for
 * nu <= 0, a direction below the mean surface. Not symmetric in w.z. */
MF_COLD mf_real mf__leadr_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real sxy = MF_SQRT(w.x * w.x + w.y * w.y), cp, sp, mu, var, nu;
    if (!(sxy > MF_R(0.0))) return w.z > MF_R(0.0) ? MF_R(0.0) : MF_BIG;
    cp = w.x / sxy; sp = w.y / sxy;
    mu = cp * d->p.leadr.mx + sp * d->p.leadr.my;
    var = cp * cp * d->p.leadr.vx + sp * sp * d->p.leadr.vy + MF_R(2.0) * cp * sp * d->p.leadr.cxy;
    nu = (w.z / sxy - mu) / MF_SQRT(MF_R(2.0) * mf_max(var, MF_R(1e-30)));
    if (!(nu > MF_R(0.0))) return MF_BIG;
    if (nu > MF_R(30.0)) return MF_R(0.0);
    return mf_min(mf_max(MF_R(0.5) * (MF_EXP(-nu * nu) / (nu * MF_SQRT_PI) - MF_ERFC(nu)), MF_R(0.0)), MF_BIG);
}

/* LEADR visible normals: with slopes s = mean + L z (z standard normal), the
 * visibility weight max(0, w.z - s . w.xy) is a half-plane in z along
 * n = L^T w.xy, so z along n has the Beckmann-like visible density
 * max(0, c - z1) N(z1) (the inversion of mf__beckmann_visible_slopes) and z
 * across n stays standard normal. */
MF_COLD mf_vec3 mf__leadr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real l00 = d->p.leadr.l00, l10 = d->p.leadr.l10, l11 = d->p.leadr.l11;
    mf_real nx = l00 * w.x + l10 * w.y, ny = l11 * w.y, k = MF_SQRT(nx * nx + ny * ny);
    mf_real cnum = w.z - d->p.leadr.mx * w.x - d->p.leadr.my * w.y, x, y, ex = MF_R(1.0), ey = MF_R(0.0), z1, z2, sx, sy;
    if (w.z < MF_R(0.0) || !(cnum > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (k > MF_R(1e-30) * cnum) { ex = nx / k; ey = ny / k; }
    /* unit-Beckmann units (exp(-x^2)): z = sqrt(2) x, bound c = cnum / k */
    mf__beckmann_visible_slopes(k > MF_R(1e-30) * cnum ? MF_R(1.4142135623730951) * k / cnum : MF_R(0.0), u1, u2, &x, &y);
    z1 = MF_R(1.4142135623730951) * x; z2 = MF_R(1.4142135623730951) * y;
    /* z = z1 e + z2 e_perp, s = mean + L z */
    x = z1 * ex - z2 * ey; y = z1 * ey + z2 * ex;
    sx = d->p.leadr.mx + l00 * x;
    sy = d->p.leadr.my + l10 * x + l11 * y;
    return mf_normalize(mf_vec3_make(-sx, -sy, MF_R(1.0)));
}
/* Student-t D in logs, so cos^2 may underflow: log D = -g log1p(s2/(g-1)) - 4 log cos,
 * s2 the squared scaled slope. D ~ cos^(2g-4) grows at the horizon when g < 2;
 * capped at e^60 / (pi ax ay) (reached only for cos < ~1e-25). */
MF_COLD mf_real mf__student_t_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real g1, q, lz2, ls2, l1, lr;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    g1 = d->p.student_t.gamma - MF_R(1.0);
    q = mf__q(d->ax, d->ay, wm);
    lz2 = MF_R(2.0) * MF_LOG(wm.z);
    if (!(q > MF_R(0.0))) l1 = MF_R(0.0);
    else {
        ls2 = MF_LOG(q) - lz2;
        l1 = ls2 > MF_R(30.0) ? ls2 - MF_LOG(g1) : MF_LOG1P(MF_EXP(ls2) / g1);
    }
    lr = mf_min(-d->p.student_t.gamma * l1 - MF_R(2.0) * lz2, MF_R(60.0));
    return MF_EXP(lr) / (MF_PI * d->ax * d->ay);
}

/* Student-t Lambda for unit roughness, as a function of mu = cot(theta) / alpha_w. */
MF_INLINE mf_real mf__student_t_lambda_mu(const mf_ndf *d, mf_real mu)
{
    mf_real g = d->p.student_t.gamma, g1 = g - MF_R(1.0), l1p, head, w, tail;
    if (!(mu < MF_R(1e15))) return MF_R(0.0);
    mu = mf_max(mu, MF_R(1e-15));
    l1p = MF_LOG1P(mu * mu / g1);
    head = d->p.student_t.K * g1 / ((MF_R(2.0) * g - MF_R(3.0)) * mu) * MF_EXP((MF_R(1.5) - g) * l1p);
    w = g1 / (g1 + mu * mu);
    tail = MF_R(0.5) * mf__betainc(g1, MF_R(0.5), w, d->p.student_t.lbeta);
    return mf_max(head - tail, MF_R(0.0));
}

/* Student-t Lambda through the projected roughness. */
MF_COLD mf_real mf__student_t_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(d->ax, d->ay, w);
    if (!(a2t2 > MF_R(0.0))) return MF_R(0.0);
    return mf__student_t_lambda_mu(d, MF_R(1.0) / MF_SQRT(a2t2));
}

/* tan^2(theta) at D-cos mass t from the pole (q = 1 - t beyond), unit alpha:
 * q = (1 + tan^2/(g-1))^(1-g). MF_BIG at q = 0. */
MF_COLD mf_real mf__student_t_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    mf_real g1 = d->p.student_t.gamma - MF_R(1.0), lq;
    if (!(q > MF_R(0.0))) return MF_BIG;
    if (!(t > MF_R(0.0))) return MF_R(0.0);
    lq = q < MF_R(0.5) ? MF_LOG(q) : MF_LOG1P(-t);
    return mf_min(g1 * MF_EXPM1(-lq / g1), MF_BIG);
}

/* D-cos mass beyond the polar angle whose tan^2 is tan2, unit alpha. */
MF_COLD mf_real mf__student_t_tail(const mf_ndf *d, mf_real tan2)
{
    mf_real g1 = d->p.student_t.gamma - MF_R(1.0);
    return MF_EXP(-g1 * MF_LOG1P(tan2 / g1));
}

MF_COLD mf_vec3 mf__student_t_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(d->ax, d->ay, mf__student_t_tan2(d, t, MF_R(1.0) - t), u2);
}

MF_COLD mf_vec3 mf__student_t_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    return mf__iso_sample_visible_view(d, d->ax, d->ay, w, u1, u2);
}
/* Index i of the interval [x[i], x[i+1]] holding v (clamped to 0 .. n-2): direct
 * when the nodes are uniform (inv_h > 0), else by bisection. */
MF_INLINE int mf__tab_find(const mf_real *x, int n, mf_real inv_h, mf_real v)
{
    int lo = 0, hi = n - 1;
    if (!(v > x[0])) return 0;   /* also NaN */
    if (inv_h > MF_R(0.0)) {
        int i = (int)mf_clamp(v * inv_h, MF_R(0.0), (mf_real)(n - 2));
        /* round-off may put v one interval off */
        if (i > 0 && v < x[i]) --i;
        else if (i < n - 2 && v >= x[i + 1]) ++i;
        return i;
    }
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (v < x[mid]) hi = mid; else lo = mid;
    }
    return lo;
}

/* 1 if the control angles a < b are far enough apart to be told apart
 * (16 ulps): the builders reject (or, from an ndf, merge) closer ones. */
MF_INLINE int mf__tab_gap_ok(mf_real a, mf_real b)
{
    return b - a > MF_R(16.0) * MF_EPS * (MF_R(1.0) + MF_FABS(b));
}

/* The curve c (dx or dy) at theta in interval i (Eq. 11). */
MF_INLINE mf_real mf__tab_curve(const mf_tabulated *t, const mf_real *c, int i, mf_real theta)
{
    mf_real f = (theta - t->theta[i]) / (t->theta[i + 1] - t->theta[i]);
    f = mf_clamp(f, MF_R(0.0), MF_R(1.0));
    return c[i] + (c[i + 1] - c[i]) * f;
}

/* Eq. 10 at polar angle theta and cos^2(phi) = c2, per solid angle. */
MF_INLINE mf_real mf__tab_D_angles(const mf_tabulated *t, mf_real theta, mf_real c2)
{
    int i = mf__tab_find(t->theta, t->n, t->inv_h, theta);
    mf_real vx = mf__tab_curve(t, t->dx, i, theta);
    if (!t->aniso) return vx;
    return c2 * t->wx * vx + (MF_R(1.0) - c2) * t->wy * mf__tab_curve(t, t->dy, i, theta);
}

/* Eq. 10 as P + Q cos(2 phi) at theta in control segment i (mf__tabulated_lambda):
 * P = (wx D_x + wy D_y) / 2, Q = (wx D_x - wy D_y) / 2; one curve: P = D_x, Q = 0. */
MF_INLINE void mf__tab_PQ(const mf_tabulated *t, int i, mf_real theta, mf_real *P, mf_real *Q)
{
    mf_real vx = mf__tab_curve(t, t->dx, i, theta), vy;
    if (!t->aniso) { *P = vx; *Q = MF_R(0.0); return; }
    vy = mf__tab_curve(t, t->dy, i, theta);
    *P = MF_R(0.5) * (t->wx * vx + t->wy * vy);
    *Q = MF_R(0.5) * (t->wx * vx - t->wy * vy);
}

/* Tabulated D, homogeneous of degree -4 in wm. */
MF_COLD mf_real mf__tabulated_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real s2, l2, c2;
    if (!d->p.tabulated.tab || !(wm.z > MF_R(0.0))) return MF_R(0.0);
    s2 = wm.x * wm.x + wm.y * wm.y;
    l2 = s2 + wm.z * wm.z;
    if (!(l2 < MF_BIG)) return MF_R(0.0);
    c2 = s2 > MF_R(0.0) ? wm.x * wm.x / s2 : MF_R(0.5);   /* any phi at the pole */
    return mf__tab_D_angles(d->p.tabulated.tab, MF_ATAN2(MF_SQRT(s2), wm.z), c2) / (l2 * l2);
}

/* Tabulated Lambda (Ribardiere et al. 2019, Eq. 13-14). Write Eq. 10 as
 * D = P(theta) + Q(theta) cos(2 phi), P = (wx D_x + wy D_y)/2, Q = (wx D_x - wy D_y)/2.
 * For a view at (theta_o, phi_o), the azimuthal integral of the clamped
 * <o.m> = max(0, a cos(psi) + b), a = sin theta_o sin theta, b = cos theta_o cos theta,
 * psi = phi - phi_o, against 1 and cos(2 psi) is (mf__tab_J)
 *   J0 = 2 pi b, J2 = 0                               where a <= b (I1 + I2 of Eq. 14),
 *   J0 = 2 (a sin p + b p), J2 = (2/3) a sin^3 p, p = acos(-b/a)  beyond (I3),
 * so the projected area I = integral <o.m> D dm = I0(theta_o) + cos(2 phi_o) I2(theta_o),
 *   I0 = int sin theta P J0 dtheta,  I2 = int sin theta Q J2 dtheta,
 * and Lambda = I / cos theta_o - 1. The part theta <= pi/2 - theta_o is the
 * closed-form cumulative mass of the curves; the rest is integrated once, at
 * build time, on nodes theta_o mirrored from the control points (where I has
 * its kinks) and subdivided; Lambda interpolates I0 and I2 by cubic Hermite
 * with their exact theta_o-derivatives. */
MF_INLINE void mf__tab_J(mf_real a, mf_real b, mf_real *j0, mf_real *j2)
{
    mf_real c, sp;
    if (!(a > b)) { *j0 = MF_R(2.0) * MF_PI * b; *j2 = MF_R(0.0); return; }
    c = mf_clamp(-b / a, MF_R(-1.0), MF_R(1.0));
    sp = MF_SQRT(mf_max(MF_R(1.0) - c * c, MF_R(0.0)));
    *j0 = MF_R(2.0) * (a * sp + b * MF_ACOS(c));
    *j2 = MF_R(2.0) / MF_R(3.0) * a * sp * sp * sp;
}

/* Cubic Hermite interpolation of column k (0: I0, 2: I2) of the table at theta_o. */
MF_INLINE mf_real mf__tab_I(const mf_tabulated *t, int j, int k, mf_real to)
{
    const mf_real *a = t->li + 4 * j, *b = a + 4;
    mf_real h = t->lt[j + 1] - t->lt[j], s = h > MF_R(0.0) ? mf_clamp((to - t->lt[j]) / h, MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
    mf_real s2 = s * s, s3 = s2 * s;
    return (MF_R(2.0) * s3 - MF_R(3.0) * s2 + MF_R(1.0)) * a[k] + (s3 - MF_R(2.0) * s2 + s) * h * a[k + 1] +
           (MF_R(3.0) * s2 - MF_R(2.0) * s3) * b[k] + (s3 - s2) * h * b[k + 1];
}

/* The projected area I0 + cos(2 phi_o) I2 of the table at theta_o (k2 = cos 2 phi_o). */
MF_INLINE mf_real mf__tab_area(const mf_tabulated *t, mf_real to, mf_real k2)
{
    int j = mf__tab_find(t->lt, t->n_lam, t->inv_hl, to);
    mf_real I = mf__tab_I(t, j, 0, to);
    return t->aniso ? I + k2 * mf__tab_I(t, j, 2, to) : I;
}

/* Symmetric in w.z like the other kinds; scale-free in w (transforms pass M^-1 w). */
MF_COLD mf_real mf__tabulated_lambda(const mf_ndf *d, mf_vec3 w)
{
    const mf_tabulated *t = d->p.tabulated.tab;
    mf_real s2, z, to, I, co;
    if (!t) return MF_R(0.0);
    z = mf_max(mf_max(MF_FABS(w.x), MF_FABS(w.y)), MF_FABS(w.z));   /* scale-free: bring w near unit length */
    if (!(z > MF_R(0.0)) || !(z < MF_BIG)) return MF_R(0.0);
    w = mf_scale(w, MF_R(1.0) / z);
    s2 = w.x * w.x + w.y * w.y;
    z = MF_FABS(w.z);
    if (!(s2 > MF_R(0.0))) return MF_R(0.0);
    to = MF_ATAN2(MF_SQRT(s2), z);
    I = mf__tab_area(t, to, (w.x * w.x - w.y * w.y) / s2);
    co = mf_max(z / MF_SQRT(s2 + z * z), MF_R(1e-15));
    return mf_clamp(I / co - MF_R(1.0), MF_R(0.0), MF_BIG);
}

/* ---- Tabulated kinds (Ribardiere et al. 2019, Sec. 3.2) ---- */

/* sin(h) cos(h) - h without cancellation at small h */
MF_INLINE mf_real mf__sincos_minus_h(mf_real h)
{
    mf_real h2 = h * h;
    if (MF_FABS(h) < MF_R(0.1))
        return h * h2 * (MF_R(-2.0) / MF_R(3.0) + h2 * (MF_R(2.0) / MF_R(15.0) - h2 * (MF_R(4.0) / MF_R(315.0))));
    return MF_SIN(h) * MF_COS(h) - h;
}

/* D cos mass 2 pi int_{ta}^{x} (da + s (t - ta)) cos t sin t dt of a linear
 * piece (Eq. 12, 17-18): 2 pi [da sin(h) sin(ta + x) / 2 + s (cos 2x (sin h cos h - h)
 * + sin 2x sin^2 h) / 4], h = x - ta, written so that short pieces keep their digits. */
MF_INLINE mf_real mf__tab_piece_mass(mf_real ta, mf_real da, mf_real s, mf_real x)
{
    mf_real h = x - ta, sh = MF_SIN(h);
    return MF_R(2.0) * MF_PI * (MF_R(0.5) * da * sh * MF_SIN(ta + x) +
                                MF_R(0.25) * s * (MF_COS(MF_R(2.0) * x) * mf__sincos_minus_h(h) + MF_SIN(MF_R(2.0) * x) * sh * sh));
}

/* The curve mixture ax D_x + ay D_y on control segment i: its value at theta[i] and slope. */
MF_INLINE void mf__tab_mix(const mf_tabulated *t, int i, mf_real ax, mf_real ay, mf_real *da, mf_real *s)
{
    const mf_real *dy = t->aniso ? t->dy : t->dx;
    mf_real a = ax * t->dx[i] + ay * dy[i], b = ax * t->dx[i + 1] + ay * dy[i + 1];
    *da = a;
    *s = (b - a) / (t->theta[i + 1] - t->theta[i]);
}

/* theta whose cumulative mass of the mixture ax C_x + ay C_y is target (Eq. 17-18):
 * the control segment by bisection of the cumulative masses, then safeguarded
 * Newton on the closed-form mass of the linear piece. */
MF_INLINE mf_real mf__tab_invert(const mf_tabulated *t, mf_real ax, mf_real ay, mf_real target)
{
    const mf_real *cy = t->aniso ? t->cy : t->cx;
    int lo = 0, hi = t->n - 1, it;
    mf_real ta, tb, da, sl, rem, seg, x, blo, bhi;
    if (!(target > MF_R(0.0))) return MF_R(0.0);
    if (!(target < ax * t->cx[hi] + ay * cy[hi])) return t->theta[hi];
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (ax * t->cx[mid] + ay * cy[mid] <= target) lo = mid; else hi = mid;
    }
    ta = t->theta[lo]; tb = t->theta[hi];
    rem = target - (ax * t->cx[lo] + ay * cy[lo]);
    seg = (ax * t->cx[hi] + ay * cy[hi]) - (ax * t->cx[lo] + ay * cy[lo]);
    mf__tab_mix(t, lo, ax, ay, &da, &sl);
    x = ta + (tb - ta) * mf_clamp(rem / mf_max(seg, MF_TINY), MF_R(0.0), MF_R(1.0));
    blo = ta; bhi = tb;
    for (it = 0; it < 60; ++it) {
        mf_real f = mf__tab_piece_mass(ta, da, sl, x) - rem;
        mf_real df = MF_R(2.0) * MF_PI * mf_max(da + sl * (x - ta), MF_R(0.0)) * MF_COS(x) * MF_SIN(x);
        if (mf__newton_step(&x, f, df, &blo, &bhi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + x))) break;
    }
    MF__SOLVER_DONE(MF__SITE_TAB_THETA, it, 60);
    return x;
}

/* Cumulative mass of the mixture ax C_x + ay C_y up to theta. */
MF_INLINE mf_real mf__tab_mass_to(const mf_tabulated *t, mf_real ax, mf_real ay, mf_real theta)
{
    const mf_real *cy = t->aniso ? t->cy : t->cx;
    int k = mf__tab_find(t->theta, t->n, t->inv_h, theta);
    mf_real da, sl;
    mf__tab_mix(t, k, ax, ay, &da, &sl);
    return ax * t->cx[k] + ay * cy[k] + mf__tab_piece_mass(t->theta[k], da, sl, mf_clamp(theta, t->theta[k], t->theta[k + 1]));
}

/* NDF sampling (Eq. 15-18): phi from its marginal (1 + k cos 2 phi) / (2 pi),
 * k = (wx - wy)/2, whose CDF (phi + k sin(2 phi)/2) / (2 pi) (Eq. 16) is
 * inverted by safeguarded Newton; theta given phi from the mixture
 * cos^2(phi) wx C_x + sin^2(phi) wy C_y (Eq. 17-18). */
MF_COLD mf_vec3 mf__tabulated_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    const mf_tabulated *t = d->p.tabulated.tab;
    mf_real phi, cp, sp, th, ax = MF_R(1.0), ay = MF_R(0.0), st;
    if (!t) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));
    phi = MF_R(2.0) * MF_PI * u2;
    if (t->aniso) {
        mf_real k = MF_R(0.5) * (t->wx - t->wy), lo = MF_R(0.0), hi = MF_R(2.0) * MF_PI, target = phi;
        int i;
        for (i = 0; i < 60; ++i)
            if (mf__newton_step(&phi, phi + MF_R(0.5) * k * MF_SIN(MF_R(2.0) * phi) - target,
                                MF_R(1.0) + k * MF_COS(MF_R(2.0) * phi), &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + phi)))
                break;
        MF__SOLVER_DONE(MF__SITE_TAB_PHI, i, 60);
    }
    cp = MF_COS(phi); sp = MF_SIN(phi);
    if (t->aniso) { ax = cp * cp * t->wx; ay = sp * sp * t->wy; }
    th = mf__tab_invert(t, ax, ay, u1 * (ax + ay));
    st = MF_SIN(th);
    return mf_vec3_make(st * cp, st * sp, mf_max(MF_COS(th), MF_R(0.0)));   /* float pi/2 is above pi/2 */
}

/* Integrals over theta in [ta, tb], inside control segment i, of sin(theta) P J0
 * and sin(theta) Q J2 (out[0], out[1]; mf__tab_lambda) for the view (so, co) =
 * (sin, cos theta_o) and, when deriv, of their theta_o-derivatives (out[2],
 * out[3]). Gauss-Legendre panels of at most 0.1 rad, 8 points (4 on pieces
 * under 0.05 rad: the integrand is smooth within a segment); with subst the
 * variable is theta = ta + (tb - ta) s^2, which smooths the (theta -
 * theta_c)^(3/2) onset of J0 at theta_c = pi/2 - theta_o. */
MF_INLINE void mf__tab_outer(const mf_tabulated *t, int i, mf_real ta, mf_real tb, mf_real so, mf_real co,
                             int subst, int deriv, mf_real out[4])
{
    mf_real L = tb - ta;
    int np, p, g, k, ng;
    for (k = 0; k < 4; ++k) out[k] = MF_R(0.0);
    if (!(L > MF_R(0.0))) return;
    np = 1 + (int)(L * MF_R(10.0));
    ng = subst || L >= MF_R(0.05) ? MF__GL_N : 4;
    for (p = 0; p < np; ++p)
        for (g = 0; g < ng; ++g) {
            mf_real xi = ng == 4 ? mf__gl4_xi(g) : mf__gl_xi(g), gw = ng == 4 ? mf__gl4_w(g) : mf__gl_w(g);
            mf_real u = ((mf_real)p + MF_R(0.5) + MF_R(0.5) * xi) / (mf_real)np;
            mf_real th = subst ? ta + L * u * u : ta + L * u, wgt = gw / (mf_real)np * (subst ? MF_R(2.0) * L * u : L);
            mf_real sn = MF_SIN(th), cs = MF_COS(th), a = so * sn, b = co * cs, j0, j2, P, Q;
            mf__tab_PQ(t, i, th, &P, &Q);
            mf__tab_J(a, b, &j0, &j2);
            wgt *= sn;
            out[0] += wgt * P * j0;
            if (t->aniso) out[1] += wgt * Q * j2;
            if (deriv) {
                /* d/dtheta_o under the integral; the clamp's boundary terms vanish */
                mf_real ad = co * sn, bd = -so * cs, dj0, dj2;
                if (a > b) {
                    mf_real c = mf_clamp(-b / a, MF_R(-1.0), MF_R(1.0)), spp = MF_SQRT(mf_max(MF_R(1.0) - c * c, MF_R(0.0)));
                    dj0 = MF_R(2.0) * (ad * spp + bd * MF_ACOS(c));
                    dj2 = MF_R(2.0) * spp * (ad * (MF_R(1.0) - MF_R(2.0) / MF_R(3.0) * spp * spp) + bd * c);
                } else { dj0 = MF_R(2.0) * MF_PI * bd; dj2 = MF_R(0.0); }
                out[2] += wgt * P * dj0;
                if (t->aniso) out[3] += wgt * Q * dj2;
            }
        }
}

/* Antiderivative in psi = phi - phi_o of (a cos psi + b)(P + Qc cos 2psi - Qs sin 2psi),
 * the azimuthal visible density of Eq. 10 (Qc = Q cos 2phi_o, Qs = Q sin 2phi_o). */
MF_INLINE mf_real mf__tab_G(mf_real psi, mf_real a, mf_real b, mf_real P, mf_real Qc, mf_real Qs)
{
    mf_real sn = MF_SIN(psi), cs = MF_COS(psi);
    mf_real s2 = MF_R(2.0) * sn * cs, c2 = cs * cs - sn * sn;
    mf_real s3 = sn * (MF_R(3.0) - MF_R(4.0) * sn * sn), c3 = cs * (MF_R(4.0) * cs * cs - MF_R(3.0));
    return P * (a * sn + b * psi) + Qc * (a * (MF_R(0.5) * sn + s3 / MF_R(6.0)) + MF_R(0.5) * b * s2) +
           Qs * (a * (c3 / MF_R(6.0) + MF_R(0.5) * cs) + MF_R(0.5) * b * c2);
}

/* Exact visible-normal sampling of a tabulated kind. The visible density
 * max(0, w.m) D(m) / I factors into a marginal in theta, sin(theta) [P J0 +
 * cos(2 phi_o) Q J2] (see mf__tab_lambda), and phi given theta. Its total is the
 * projected area of the table. Inside theta_c = pi/2 - theta_o the marginal is
 * cos(theta_o) times the D cos mass of the curve mixture (closed form,
 * inverted as in NDF sampling); beyond it the control segments' masses are
 * integrated by Gauss-Legendre (substitution at theta_c) from theta_c on until
 * the target is reached, and that segment is inverted by safeguarded Newton on
 * its partial integral. phi given theta: the cosine-clamped density of mf__sample_phi_cos
 * for one curve; for two, Newton on the closed-form CDF mf__tab_G. No rejection;
 * deterministic in (u1, u2). Cost grows with the number of control segments
 * beyond theta_c (see make bench). */
MF_COLD mf_vec3 mf__tabulated_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    const mf_tabulated *t = d->p.tabulated.tab;
    mf_real s2, len, so, co, cp = MF_R(1.0), sp = MF_R(0.0), k2, tc, mxw, myw, cin, inner, outer, target;
    mf_real o[4], th, sn, a, b, P, Q, psi, cps, sps, lastm = MF_R(0.0);
    int k, j, i, nseg, last = 0;
    if (!t || !(w.z >= MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    len = mf_max(mf_max(MF_FABS(w.x), MF_FABS(w.y)), w.z);   /* scale-free: bring w near unit length */
    if (!(len > MF_R(0.0)) || !(len < MF_BIG)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    w = mf_scale(w, MF_R(1.0) / len);
    s2 = w.x * w.x + w.y * w.y;
    len = MF_SQRT(s2 + w.z * w.z);   /* in [1, sqrt 3] */
    so = MF_SQRT(s2) / len; co = w.z / len;
    if (s2 > MF_R(0.0)) { cp = w.x / MF_SQRT(s2); sp = w.y / MF_SQRT(s2); }
    k2 = cp * cp - sp * sp;   /* cos(2 phi_o) */
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));
    tc = MF_R(0.5) * MF_PI - MF_ATAN2(MF_SQRT(s2), w.z);
    k = mf__tab_find(t->theta, t->n, t->inv_h, tc);
    mxw = t->aniso ? MF_R(0.5) * t->wx : MF_R(1.0);
    myw = t->aniso ? MF_R(0.5) * t->wy : MF_R(0.0);
    cin = mf__tab_mass_to(t, mxw, myw, tc);
    inner = co * cin;
    /* the total from the projected-area table (what D_visible divides by, to
     * its interpolation error ~1e-9); the outer segments are integrated one by
     * one from theta_c until the target is reached */
    outer = mf__tab_area(t, MF_R(0.5) * MF_PI - tc, k2) - inner;
    target = u1 * (inner + mf_max(outer, MF_R(0.0)));
    nseg = t->n - 1 - k;
    if (target <= inner || !(outer > MF_R(0.0))) {
        th = co > MF_R(0.0) ? mf__tab_invert(t, mxw, myw, mf_min(target / co, cin)) : tc;
        th = mf_min(th, tc);
    } else {
        mf_real rem = target - inner, lo, hi, ta, m = MF_R(0.0);
        for (j = 0; j < nseg; ++j) {
            mf__tab_outer(t, k + j, j == 0 ? tc : t->theta[k + j], t->theta[k + j + 1], so, co, j == 0, 0, o);
            m = o[0] + k2 * o[1];
            if (rem <= m) break;
            if (m > MF_R(0.0)) { last = j; lastm = m; }
            rem -= m;
        }
        if (j == nseg) { j = last; m = lastm; rem = m; }   /* the table's total was a hair above the sum */
        ta = j == 0 ? tc : t->theta[k + j];
        lo = ta; hi = t->theta[k + j + 1];
        th = ta + (hi - ta) * mf_clamp(rem / mf_max(m, MF_TINY), MF_R(0.0), MF_R(1.0));
        for (i = 0; i < 60; ++i) {
            mf_real f, ss = MF_SIN(th), jj0, jj2;
            mf__tab_outer(t, k + j, ta, th, so, co, j == 0, 0, o);
            f = o[0] + k2 * o[1] - rem;
            mf__tab_PQ(t, k + j, th, &P, &Q);
            mf__tab_J(so * ss, co * MF_COS(th), &jj0, &jj2);   /* the derivative: the integrand at th */
            if (mf__newton_step(&th, f, ss * (P * jj0 + k2 * Q * jj2), &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + th))) break;
        }
    }
    /* phi given theta */
    sn = MF_SIN(th);
    a = so * sn; b = co * MF_COS(th);
    mf__tab_PQ(t, mf__tab_find(t->theta, t->n, t->inv_h, th), th, &P, &Q);
    if (!t->aniso || !(P > MF_R(0.0))) {
        psi = mf__sample_phi_cos(a > MF_R(1e-30) * b ? b / a : MF_R(1e30), u2);
    } else {
        mf_real pmax = a > b ? MF_ACOS(-b / a) : MF_PI, lo = -pmax, hi = pmax, g0, g1, tg, s2o = MF_R(2.0) * cp * sp;
        g0 = mf__tab_G(-pmax, a, b, P, Q * k2, Q * s2o);
        g1 = mf__tab_G(pmax, a, b, P, Q * k2, Q * s2o);
        tg = g0 + u2 * (g1 - g0);
        psi = -pmax + MF_R(2.0) * pmax * u2;
        for (i = 0; i < 60; ++i) {
            mf_real f = mf__tab_G(psi, a, b, P, Q * k2, Q * s2o) - tg;
            mf_real df = (a * MF_COS(psi) + b) * (P + Q * (k2 * MF_COS(MF_R(2.0) * psi) - s2o * MF_SIN(MF_R(2.0) * psi)));
            if (mf__newton_step(&psi, f, mf_max(df, MF_R(0.0)), &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + MF_FABS(psi)))) break;
        }
    }
    cps = MF_COS(psi); sps = MF_SIN(psi);
    /* z >= 8 eps: theta = pi/2 rounds to cos < 0 in float (u1 = 1 - 2^-24),
     * and atan2 must give the D lookup an angle below the last node */
    return mf_normalize(mf_vec3_make(sn * (cp * cps - sp * sps), sn * (sp * cps + cp * sps), mf_max(MF_COS(th), MF_R(8.0) * MF_EPS)));
}
/* The NDF-CDF inversion of an isotropic kind sampled numerically (GTR with
 * its alpha; Student-t with unit roughness, stretched by the caller): t is the
 * D-cos mass from the pole (theta = 0) to theta, q = 1 - t the mass beyond;
 * both are passed so each end stays accurate. Returns tan^2(theta). */
MF_INLINE mf_real mf__iso_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    return d->type == MF_NDF_GTR ? mf__gtr_tan2(d, t, q) : mf__student_t_tan2(d, t, q);
}
/* Mass of D cos beyond the polar angle whose tan^2 is tan2 (inverse of the above). */
MF_INLINE mf_real mf__iso_tail(const mf_ndf *d, mf_real tan2)
{
    return d->type == MF_NDF_GTR ? mf__gtr_tail(d, tan2) : mf__student_t_tail(d, tan2);
}
/* Exponent p of the substitution q = qc (1 - s^2)^p: it must cancel the tail
 * tan(theta) ~ q^-beta (GTR: beta = 1/2 at every gamma; Student-t:
 * beta = 1/(2 gamma - 2)), p = 2 / (1 - beta). */
MF_INLINE mf_real mf__iso_p(const mf_ndf *d)
{
    return d->type == MF_NDF_GTR ? MF_R(4.0) : d->p.student_t.vndf_p;
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
    mf_real p = mf__iso_p(d), s2 = s * s, l = MF_LOG1P(-s2);
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
                mf_real s = mf__gl_node01(k, i, MF__ISO_PANELS);
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
            MF__SOLVER_DONE(MF__SITE_NUM_VNDF, i, 50);
            mf__iso_vis_h(&v, ((mf_real)k + MF_R(0.5) + MF_R(0.5) * x) * width, &t, &q);
        }
        tan2 = mf__iso_tan2(d, t, q);
        /* phi | theta: max(0, cv cos(theta) + sv sin(theta) cos(phi)) -> c = 1/(tv tan) */
        cphi = tan2 > MF_R(0.0) ? MF_R(1.0) / (v.tv * MF_SQRT(tan2)) : MF_R(1e30);
    }
    /* the heaviest tails put visible mass beyond tan = 1e15 (Student-t gamma
     * 1.55: ~10%): those normals keep tan = 1e15, so none is horizontal (z = 0,
     * density 0); every reflection about them points below the horizon anyway */
    tan2 = mf_min(tan2, MF_R(1e30));
    c2 = MF_R(1.0) / (MF_R(1.0) + tan2); ct = MF_SQRT(c2); st = MF_SQRT(tan2) * ct;
    phi = mf__sample_phi_cos(cphi, u2);
    return mf_vec3_make(st * MF_COS(phi), st * MF_SIN(phi), ct);
}

MF_COLD mf_vec3 mf__iso_sample_visible_view(const mf_ndf *d, mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp;
    mf_vec3 m;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    m = mf__iso_sample_visible(d, cv, sv, u1, u2);
    return mf_normalize(mf_vec3_make(ax * (cp * m.x - sp * m.y), ay * (sp * m.x + cp * m.y), m.z));
}
/* Fresnel averages (section 11): the quadrature. */
MF_INLINE mf_real mf__fresnel_average(mf_real eta, mf_real k, int conductor)
{
    mf_real mu_c = MF_R(0.0), sum = MF_R(0.0);
    int side, p, i;
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG) || !(k >= MF_R(0.0)) || !(k < MF_BIG)) return MF_R(0.0);
    if (eta < MF_R(1.0)) mu_c = MF_SQRT(MF_R(1.0) - eta * eta);   /* where F drops from (near) 1 */
    for (side = 0; side < 2; ++side) {
        mf_real len = side ? MF_R(1.0) - mu_c : mu_c;   /* mu = mu_c -+ len t^2 */
        if (!(len > MF_R(0.0))) continue;
        for (p = 0; p < 8; ++p)
            for (i = 0; i < 8; ++i) {
                mf_real t = mf__gl_node01(p, i, 8);
                mf_real mu = side ? mu_c + len * t * t : mu_c - len * t * t;
                mf_real f = conductor ? mf_fresnel_conductor(mu, eta, k) : mf_fresnel_dielectric(mu, eta);
                /* 2 F mu dmu, dmu = 2 len t dt, panel width 1/8 (weights sum to 1) */
                sum += mf__gl_w(i) * MF_R(4.0) * len * f * mu * t / MF_R(8.0);
            }
    }
    return mf_clamp(sum, MF_R(0.0), MF_R(1.0));
}
MF_COLD mf_real mf_fresnel_dielectric_average(mf_real eta) { return mf__fresnel_average(eta, MF_R(0.0), 0); }
MF_COLD mf_real mf_fresnel_conductor_average(mf_real eta, mf_real k) { return mf__fresnel_average(eta, k, 1); }
#ifndef MF_NO_IBM
/* one field of `w` bits (w <= 32) of a packed array */
MF_INLINE unsigned int mf__ibm_get(const unsigned int *base, size_t i, int w)
{
    size_t bit = i * (size_t)w;
    const unsigned int *p = base + (bit >> 5);
    unsigned int s = (unsigned int)(bit & 31u), v = p[0] >> s;
    if (s + (unsigned int)w > 32u) v |= p[1] << (32u - s);
    return w >= 32 ? v : v & ((1u << w) - 1u);
}

/* bits of x spread to the even positions (x < 2^16) and back */
MF_INLINE unsigned int mf__ibm_spread(unsigned int x)
{
    x &= 0xffffu;
    x = (x | (x << 8)) & 0x00ff00ffu;
    x = (x | (x << 4)) & 0x0f0f0f0fu;
    x = (x | (x << 2)) & 0x33333333u;
    return (x | (x << 1)) & 0x55555555u;
}
MF_INLINE unsigned int mf__ibm_compact(unsigned int x)
{
    x &= 0x55555555u;
    x = (x | (x >> 1)) & 0x33333333u;
    x = (x | (x >> 2)) & 0x0f0f0f0fu;
    x = (x | (x >> 4)) & 0x00ff00ffu;
    return (x | (x >> 8)) & 0xffffu;
}

/* Morton code in the kd split order: the larger side of the box splits first
 * (x on ties), so the code's bits from the top are the kd-tree's decisions. */
MF_INLINE unsigned int mf__ibm_morton(int kx, int ky, unsigned int x, unsigned int y)
{
    int k = kx < ky ? kx : ky;
    unsigned int m = (1u << k) - 1u, lo = (mf__ibm_spread(x & m) << 1) | mf__ibm_spread(y & m);
    unsigned int hi = kx > ky ? x >> k : y >> k;
    return (hi << (2 * k)) | lo;
}
MF_INLINE void mf__ibm_unmorton(int kx, int ky, unsigned int c, int *x, int *y)
{
    int k = kx < ky ? kx : ky;
    unsigned int lo = k > 0 ? c & ((1u << (2 * k)) - 1u) : 0u, hi = c >> (2 * k);
    unsigned int ux = mf__ibm_compact(lo >> 1), uy = mf__ibm_compact(lo);
    if (kx > ky) ux |= hi << k;
    else uy |= hi << k;
    *x = (int)ux;
    *y = (int)uy;
}

/* start of bin j's block in the lists section */
MF_INLINE unsigned int mf__ibm_off(const mf_ibm *ibm, int j)
{
    return mf__ibm_get(ibm->data + ibm->off_at, (size_t)j, ibm->off_bits);
}

/* stored kd-tree levels of a bin of n texels: floor(log2(n / 16)), within the tree's depth */
MF_INLINE int mf__ibm_tree_levels(const mf_ibm *ibm, unsigned int n)
{
    int k = 0;
    while (k < 24 && (n >> (k + 5)) != 0u) ++k;
    return k < ibm->kx + ibm->ky ? k : ibm->kx + ibm->ky;
}

/* Bin j's texel count; *base: the first of its positions, *tab: its level-k
 * node boundaries (relative to base), *k: the stored levels (0: none). */
MF_INLINE unsigned int mf__ibm_bin_info(const mf_ibm *ibm, int j, unsigned int *base, unsigned int *tab, int *k)
{
    unsigned int s = mf__ibm_off(ibm, j), len = mf__ibm_off(ibm, j + 1) - s, n;
    if (len < (unsigned int)MF_IBM_TREE_MIN) { *base = s; *tab = s; *k = 0; return len; }
    n = mf__ibm_get(ibm->data + ibm->pos_at, s, ibm->list_bits);
    *k = mf__ibm_tree_levels(ibm, n);
    *tab = s + 1u;
    *base = s + 2u + (1u << *k);
    return n;
}

MF_COLD int mf_ibm_bin_texels(const mf_ibm *ibm, int bin)
{
    unsigned int base, tab;
    int k;
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return 0;
    return (int)mf__ibm_bin_info(ibm, bin, &base, &tab, &k);
}

MF_COLD mf_vec3 mf_ibm_bin_normal(const mf_ibm *ibm, int bin)
{
    unsigned int q;
    mf_real b, x, y, r2;
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    q = ibm->data[ibm->mean_at + (size_t)bin];
    b = (mf_real)ibm->res;
    x = MF_R(2.0) * ((mf_real)(bin % ibm->res) + (mf_real)(q >> 16) * MF_R(1.52587890625e-5)) / b - MF_R(1.0);
    y = MF_R(2.0) * ((mf_real)(bin / ibm->res) + (mf_real)(q & 0xffffu) * MF_R(1.52587890625e-5)) / b - MF_R(1.0);
    r2 = x * x + y * y;
    if (r2 > MF_R(1.0)) { mf_real s = MF_R(1.0) / MF_SQRT(r2); x *= s; y *= s; r2 = MF_R(1.0); }
    return mf_vec3_make(x, y, MF_SQRT(MF_R(1.0) - r2));
}

MF_COLD int mf_ibm_texel_bin(const mf_ibm *ibm, int x, int y)
{
    unsigned int v;
    if (!ibm || !ibm->data) return -1;
    x %= ibm->width; if (x < 0) x += ibm->width;
    y %= ibm->height; if (y < 0) y += ibm->height;
    v = mf__ibm_get(ibm->data + ibm->bin_at, (size_t)y * (size_t)ibm->width + (size_t)x, ibm->bin_bits);
    return (int)(v & ((1u << ibm->axis_bits) - 1u)) + ibm->res * (int)(v >> ibm->axis_bits);
}

MF_COLD void mf_ibm_set_shadowing(mf_ibm *ibm, const mf_ndf *d)
{
    if (!ibm) return;
    ibm->has_shadow = d ? 1 : 0;
    if (d) ibm->shadow = *d;
}

typedef struct mf__ibm_fp {
    int mode, tx, ty;          /* POINT: the texel */
    int direct;                /* sum the covered texels directly (Eq. 5.2) */
    int few;                   /* direct, and A is small (bounding box <= 16 texels) or thin */
    int bx0, by0, bx1, by1;    /* direct: texels [bx0, bx1) x [by0, by1) (unwrapped) hold A */
    int rect;                  /* axis-aligned: every piece is a rectangle */
    int row0, row1;            /* period rows touched */
    mf_real x[4], y[4];        /* corners in texels, counterclockwise, center in the first period */
    mf_real cx, cy, ax, ay, bx, by;   /* center and edges in texels */
    mf_real area;              /* |A| in texels */
    mf_real full;              /* periods entirely inside A */
} mf__ibm_fp;

/* A convex piece of the footprint inside one period, shifted to the first. */
typedef struct mf__ibm_piece {
    int ox, oy;                     /* integer origin of the relative coordinates */
    int bx0, by0, bx1, by1;         /* texels [bx0,bx1) x [by0,by1) it can touch */
    int n, rect;
    mf_real x[12], y[12];           /* vertices relative to the origin, counterclockwise */
    mf_real ea[12], eb[12], ec[12]; /* unit half-planes ea x + eb y + ec >= 0 */
    mf_real elo[12], ehi[12];       /* least and largest of ea x + eb y over the unit square */
    mf_real rx0, ry0, rx1, ry1;     /* the rectangle (rect) */
} mf__ibm_piece;

/* Clips a convex polygon to coord >= value (sgn = 1) or <= value (sgn = -1)
 * along axis 0 (x) or 1 (y); crossing points get the exact value. */
MF_INLINE int mf__ibm_clip_axis(const mf_real *xi, const mf_real *yi, int n, int axis, mf_real value, mf_real sgn,
                                mf_real *xo, mf_real *yo)
{
    int i, m = 0;
    for (i = 0; i < n; ++i) {
        int k = i + 1 == n ? 0 : i + 1;
        mf_real di = sgn * ((axis ? yi[i] : xi[i]) - value), dk = sgn * ((axis ? yi[k] : xi[k]) - value);
        if (di >= MF_R(0.0)) { xo[m] = xi[i]; yo[m] = yi[i]; ++m; }
        if ((di >= MF_R(0.0)) != (dk >= MF_R(0.0))) {
            mf_real t = di / (di - dk);
            if (axis) { xo[m] = xi[i] + t * (xi[k] - xi[i]); yo[m] = value; }
            else { xo[m] = value; yo[m] = yi[i] + t * (yi[k] - yi[i]); }
            ++m;
        }
    }
    return m;
}

/* Clips a convex polygon to a x + b y + c >= 0. */
MF_INLINE int mf__ibm_clip_line(const mf_real *xi, const mf_real *yi, int n, mf_real a, mf_real b, mf_real c,
                                mf_real *xo, mf_real *yo)
{
    int i, m = 0;
    for (i = 0; i < n; ++i) {
        int k = i + 1 == n ? 0 : i + 1;
        mf_real di = a * xi[i] + b * yi[i] + c, dk = a * xi[k] + b * yi[k] + c;
        if (di >= MF_R(0.0)) { xo[m] = xi[i]; yo[m] = yi[i]; ++m; }
        if ((di >= MF_R(0.0)) != (dk >= MF_R(0.0))) {
            mf_real t = di / (di - dk);
            xo[m] = xi[i] + t * (xi[k] - xi[i]);
            yo[m] = yi[i] + t * (yi[k] - yi[i]);
            ++m;
        }
    }
    return m;
}

/* Shoelace area of a polygon (counterclockwise: positive). */
MF_INLINE mf_real mf__ibm_shoelace(const mf_real *x, const mf_real *y, int n)
{
    mf_real s = MF_R(0.0);
    int i;
    for (i = 0; i < n; ++i) {
        int k = i + 1 == n ? 0 : i + 1;
        s += x[i] * y[k] - x[k] * y[i];
    }
    return MF_R(0.5) * s;
}

/* The footprint clipped to period row `row` (y in [row H, (row+1) H]). */
MF_INLINE int mf__ibm_slab(const mf_ibm *ibm, const mf__ibm_fp *p, int row, mf_real *xo, mf_real *yo)
{
    mf_real tx[12], ty[12], H = (mf_real)ibm->height;
    int n = mf__ibm_clip_axis(p->x, p->y, 4, 1, (mf_real)row * H, MF_R(1.0), tx, ty);
    return mf__ibm_clip_axis(tx, ty, n, 1, (mf_real)(row + 1) * H, MF_R(-1.0), xo, yo);
}

/* Columns of a slab: all cells [*c0, *c1] it touches and the full ones
 * [*f0, *f1] (empty when *f1 < *f0): cells whose whole square lies inside A,
 * i.e. inside both chords of A at the slab's bottom and top (A is convex). */
MF_INLINE void mf__ibm_slab_columns(const mf_ibm *ibm, int row, const mf_real *x, const mf_real *y, int n, mf_real *c0,
                                    mf_real *c1, mf_real *f0, mf_real *f1)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, y0 = (mf_real)row * H, y1 = (mf_real)(row + 1) * H;
    mf_real lo = x[0], hi = x[0], l0 = MF_BIG, r0 = -MF_BIG, l1 = MF_BIG, r1 = -MF_BIG;
    int i;
    for (i = 0; i < n; ++i) {
        lo = mf_min(lo, x[i]); hi = mf_max(hi, x[i]);
        if (y[i] == y0) { l0 = mf_min(l0, x[i]); r0 = mf_max(r0, x[i]); }
        if (y[i] == y1) { l1 = mf_min(l1, x[i]); r1 = mf_max(r1, x[i]); }
    }
    *c0 = MF_FLOOR(lo / W);
    *c1 = MF_FLOOR(hi / W);
    if (*c1 > *c0 && hi == *c1 * W) *c1 -= MF_R(1.0);   /* touches the next column only on its edge */
    *f0 = MF_R(1.0); *f1 = MF_R(0.0);
    if (l0 <= r0 && l1 <= r1) {
        *f0 = MF_CEIL(mf_max(l0, l1) / W);
        *f1 = MF_FLOOR(mf_min(r0, r1) / W) - MF_R(1.0);
    }
}

/* Classifies a footprint: wraps the center into the first period, finds the
 * periods it covers entirely and the cells its boundary cuts. More than
 * MF_IBM_MAX_PIECES cut cells (or rows): the whole map's histogram
 * (MF__IBM_GLOBAL, see mf_ibm_bin_weight). Zero area or a non-finite edge:
 * the texel at the center; a non-finite center: nothing. */
MF_INLINE void mf__ibm_footprint(const mf_ibm *ibm, const mf_footprint *f, mf__ibm_fp *p)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, cross, ex, ey, xs[12], ys[12];
    int row, pieces = 0, edges_ok;
    p->mode = MF__IBM_NONE;
    p->direct = p->few = 0;
    p->full = MF_R(0.0);
    if (!f) return;
    /* bits, not comparisons, so that -ffast-math keeps NaN from the indices */
    if (!mf__finite_bits(f->u) || !mf__finite_bits(f->v)) return;
    edges_ok = mf__finite_bits(f->ax) && mf__finite_bits(f->ay) && mf__finite_bits(f->bx) && mf__finite_bits(f->by);
    p->cx = f->u * W; p->cy = f->v * H;
    if (!(MF_FABS(p->cx) < MF_BIG) || !(MF_FABS(p->cy) < MF_BIG)) return;
    p->cx -= W * MF_FLOOR(p->cx / W);
    p->cy -= H * MF_FLOOR(p->cy / H);
    if (!(p->cx >= MF_R(0.0)) || !(p->cx < W)) p->cx = MF_R(0.0);   /* rounding at the period edge */
    if (!(p->cy >= MF_R(0.0)) || !(p->cy < H)) p->cy = MF_R(0.0);
    p->tx = (int)p->cx; if (p->tx >= ibm->width || p->tx < 0) p->tx = p->tx < 0 ? 0 : ibm->width - 1;
    p->ty = (int)p->cy; if (p->ty >= ibm->height || p->ty < 0) p->ty = p->ty < 0 ? 0 : ibm->height - 1;
    if (!edges_ok) { p->mode = MF__IBM_POINT; return; }
    p->ax = f->ax * W; p->ay = f->ay * H; p->bx = f->bx * W; p->by = f->by * H;
    cross = p->ax * p->by - p->ay * p->bx;
    p->area = MF_FABS(cross);
    if (!(p->area >= MF_IBM_MIN_AREA)) { p->mode = MF__IBM_POINT; return; }
    {   /* a sliver thinner than 64 ulps of its coordinates would turn the
         * clipped areas into round-off (float): widen it across its longer
         * edge to that thickness (the sampler uses these same edges). 64
         * measured best against double: L1 of the weights <= 4e-3 for any
         * thickness (none: up to 1, as round-off; 1024: 0.65, as widening) */
        mf_real la2 = p->ax * p->ax + p->ay * p->ay, lb2 = p->bx * p->bx + p->by * p->by;
        mf_real lm = MF_SQRT(mf_max(la2, lb2)), tmin = MF_R(64.0) * MF_EPS * (mf_max(W, H) + lm), grow;
        if (lm < MF_BIG && p->area < tmin * lm) {
            grow = (tmin * lm - p->area) / lm * (cross > MF_R(0.0) ? MF_R(1.0) : MF_R(-1.0));
            if (la2 >= lb2) { p->bx -= grow * p->ay / lm; p->by += grow * p->ax / lm; }   /* b moves along a's normal */
            else { p->ax += grow * p->by / lm; p->ay -= grow * p->bx / lm; }              /* a along b's */
            cross = p->ax * p->by - p->ay * p->bx;
            p->area = MF_FABS(cross);
        }
    }
    ex = MF_R(0.5) * (MF_FABS(p->ax) + MF_FABS(p->bx));
    ey = MF_R(0.5) * (MF_FABS(p->ay) + MF_FABS(p->by));
    p->mode = MF__IBM_GLOBAL;
    if (!(p->area < MF_BIG) || !(ex < (mf_real)MF_IBM_MAX_PIECES * W) || !(ey < (mf_real)MF_IBM_MAX_PIECES * H)) return;
    {
        mf_real sa = cross > MF_R(0.0) ? MF_R(0.5) : MF_R(-0.5);   /* counterclockwise corners */
        p->x[0] = p->cx - MF_R(0.5) * p->ax - sa * p->bx; p->y[0] = p->cy - MF_R(0.5) * p->ay - sa * p->by;
        p->x[1] = p->cx + MF_R(0.5) * p->ax - sa * p->bx; p->y[1] = p->cy + MF_R(0.5) * p->ay - sa * p->by;
        p->x[2] = p->cx + MF_R(0.5) * p->ax + sa * p->bx; p->y[2] = p->cy + MF_R(0.5) * p->ay + sa * p->by;
        p->x[3] = p->cx - MF_R(0.5) * p->ax + sa * p->bx; p->y[3] = p->cy - MF_R(0.5) * p->ay + sa * p->by;
    }
    p->rect = (p->ay == MF_R(0.0) && p->bx == MF_R(0.0)) || (p->ax == MF_R(0.0) && p->by == MF_R(0.0));
    p->row0 = (int)MF_FLOOR((p->cy - ey) / H);
    p->row1 = (int)MF_FLOOR((p->cy + ey) / H);
    if (p->row1 > p->row0 && p->cy + ey == (mf_real)p->row1 * H) --p->row1;
    /* narrower than a period both ways: no full period and at most 4 cut
     * cells, so the count is only needed for wider footprints */
    if (!(MF_R(2.0) * ex < W && MF_R(2.0) * ey < H))
        for (row = p->row0; row <= p->row1; ++row) {
            mf_real c0, c1, f0, f1, nf = MF_R(0.0);
            int n = mf__ibm_slab(ibm, p, row, xs, ys);
            if (n < 3) continue;
            mf__ibm_slab_columns(ibm, row, xs, ys, n, &c0, &c1, &f0, &f1);
            if (f1 >= f0) { nf = f1 - f0 + MF_R(1.0); p->full += nf; }
            pieces += (int)(c1 - c0 + MF_R(1.0) - nf);
            if (pieces > MF_IBM_MAX_PIECES) { p->full = MF_R(0.0); return; }
        }
    p->mode = MF__IBM_EXACT;
    p->direct = p->full == MF_R(0.0) && MF_R(4.0) * ex * ey <= (mf_real)MF_IBM_DIRECT_TEXELS;
    /* a few texels, or thin: their clipped areas give |A| (see mf__ibm_weights) */
    p->few = p->direct && (MF_R(4.0) * ex * ey <= MF_R(16.0) || MF_R(32.0) * p->area <= MF_R(4.0) * ex * ey);
    if (p->direct) {
        p->bx0 = (int)MF_FLOOR(p->cx - ex); p->bx1 = (int)MF_CEIL(p->cx + ex);
        p->by0 = (int)MF_FLOOR(p->cy - ey); p->by1 = (int)MF_CEIL(p->cy + ey);
    }
}

/* The piece of slab (x, y, n) in column `col`, shifted to the first period;
 * 0 if it has no area. */
MF_INLINE int mf__ibm_piece_make(const mf_ibm *ibm, const mf__ibm_fp *p, int row, int col, const mf_real *x,
                                 const mf_real *y, int n, mf__ibm_piece *pc)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, tx[12], ty[12], lx, ly, hx, hy, sx, sy;
    int i, m = mf__ibm_clip_axis(x, y, n, 0, (mf_real)col * W, MF_R(1.0), tx, ty);
    m = mf__ibm_clip_axis(tx, ty, m, 0, (mf_real)(col + 1) * W, MF_R(-1.0), pc->x, pc->y);
    if (m < 3) return 0;
    sx = (mf_real)col * W; sy = (mf_real)row * H;
    lx = hx = pc->x[0] - sx; ly = hy = pc->y[0] - sy;
    for (i = 0; i < m; ++i) {
        pc->x[i] -= sx; pc->y[i] -= sy;
        lx = mf_min(lx, pc->x[i]); hx = mf_max(hx, pc->x[i]);
        ly = mf_min(ly, pc->y[i]); hy = mf_max(hy, pc->y[i]);
    }
    pc->ox = (int)MF_FLOOR(lx); pc->oy = (int)MF_FLOOR(ly);
    if (pc->ox < 0) pc->ox = 0;
    if (pc->oy < 0) pc->oy = 0;
    pc->bx0 = pc->ox; pc->by0 = pc->oy;
    pc->bx1 = (int)MF_CEIL(hx); pc->by1 = (int)MF_CEIL(hy);
    if (pc->bx1 > ibm->width) pc->bx1 = ibm->width;
    if (pc->by1 > ibm->height) pc->by1 = ibm->height;
    if (pc->bx1 <= pc->bx0 || pc->by1 <= pc->by0) return 0;
    /* relative coordinates, without repeated vertices (clipping a corner that
     * lies on a period edge repeats it; a zero-length edge has no half-plane) */
    {
        int k = 0;
        for (i = 0; i < m; ++i) {
            mf_real vx = pc->x[i] - (mf_real)pc->ox, vy = pc->y[i] - (mf_real)pc->oy;
            if (k > 0 && vx == pc->x[k - 1] && vy == pc->y[k - 1]) continue;
            pc->x[k] = vx; pc->y[k] = vy; ++k;
        }
        while (k > 1 && pc->x[k - 1] == pc->x[0] && pc->y[k - 1] == pc->y[0]) --k;
        m = k;
    }
    if (m < 3 || !(mf__ibm_shoelace(pc->x, pc->y, m) > MF_R(0.0))) return 0;
    pc->n = m;
    pc->rect = p->rect;
    pc->rx0 = lx - (mf_real)pc->ox; pc->rx1 = hx - (mf_real)pc->ox;
    pc->ry0 = ly - (mf_real)pc->oy; pc->ry1 = hy - (mf_real)pc->oy;
    for (i = 0; i < m; ++i) {
        int k = i + 1 == m ? 0 : i + 1;
        mf_real a = pc->y[i] - pc->y[k], b = pc->x[k] - pc->x[i], l = MF_SQRT(a * a + b * b);
        if (l > MF_R(0.0)) { a /= l; b /= l; }
        pc->ea[i] = a; pc->eb[i] = b;
        pc->elo[i] = mf_min(a, MF_R(0.0)) + mf_min(b, MF_R(0.0));
        pc->ehi[i] = mf_max(a, MF_R(0.0)) + mf_max(b, MF_R(0.0));
        pc->ec[i] = l > MF_R(0.0) ? -(a * pc->x[i] + b * pc->y[i]) : MF_R(1.0);
    }
    return 1;
}

/* Box [x0,x1) x [y0,y1) (texels) against a piece: -1 outside, 1 inside, 0
 * cut (separating axes: the box's and the piece's edges, exact for convex). */
MF_INLINE int mf__ibm_classify(const mf__ibm_piece *pc, int x0, int y0, int x1, int y1)
{
    mf_real X0, Y0, X1, Y1;
    int i, in = 1;
    if (x1 <= pc->bx0 || x0 >= pc->bx1 || y1 <= pc->by0 || y0 >= pc->by1) return -1;
    X0 = (mf_real)(x0 - pc->ox); X1 = (mf_real)(x1 - pc->ox);
    Y0 = (mf_real)(y0 - pc->oy); Y1 = (mf_real)(y1 - pc->oy);
    if (pc->rect) {
        if (X1 <= pc->rx0 || X0 >= pc->rx1 || Y1 <= pc->ry0 || Y0 >= pc->ry1) return -1;
        return X0 >= pc->rx0 && X1 <= pc->rx1 && Y0 >= pc->ry0 && Y1 <= pc->ry1 ? 1 : 0;
    }
    for (i = 0; i < pc->n; ++i) {
        mf_real a = pc->ea[i], b = pc->eb[i];
        mf_real lo = pc->ec[i] + (a > MF_R(0.0) ? a * X0 : a * X1) + (b > MF_R(0.0) ? b * Y0 : b * Y1);
        mf_real hi = pc->ec[i] + (a > MF_R(0.0) ? a * X1 : a * X0) + (b > MF_R(0.0) ? b * Y1 : b * Y0);
        if (hi <= MF_R(0.0)) return -1;
        if (lo < MF_R(0.0)) in = 0;
    }
    return in;
}

/* |piece ∩ texel (tx, ty)| in texels: 1 inside, 0 outside, otherwise the unit
 * square clipped by the cutting edges (Sutherland-Hodgman) and its shoelace
 * area, in coordinates relative to the texel corner. */
MF_INLINE mf_real mf__ibm_texel_area(const mf__ibm_piece *pc, int tx, int ty)
{
    mf_real X = (mf_real)(tx - pc->ox), Y = (mf_real)(ty - pc->oy), xa[16], ya[16], xb[16], yb[16];
    mf_real cv[12];
    int i, cut[12], nc = 0, n = 4;
    if (pc->rect) {
        mf_real w = mf_min(X + MF_R(1.0), pc->rx1) - mf_max(X, pc->rx0);
        mf_real h = mf_min(Y + MF_R(1.0), pc->ry1) - mf_max(Y, pc->ry0);
        return w > MF_R(0.0) && h > MF_R(0.0) ? w * h : MF_R(0.0);
    }
    for (i = 0; i < pc->n; ++i) {
        mf_real v = pc->ea[i] * X + pc->eb[i] * Y + pc->ec[i];
        if (v + pc->ehi[i] <= MF_R(0.0)) return MF_R(0.0);
        if (v + pc->elo[i] < MF_R(0.0)) { cut[nc] = i; cv[nc] = v; ++nc; }
    }
    if (nc == 0) return MF_R(1.0);
    if (nc == 1) {   /* one edge cuts the texel (most boundary texels): closed form */
        mf_real a = pc->ea[cut[0]], b = pc->eb[cut[0]], v[4], r;
        v[0] = cv[0]; v[1] = cv[0] + a; v[2] = cv[0] + a + b; v[3] = cv[0] + b;
        r = mf__ibm_square_cut(v);
        if (r >= MF_R(0.0)) return r;
    }
    xa[0] = MF_R(0.0); ya[0] = MF_R(0.0); xa[1] = MF_R(1.0); ya[1] = MF_R(0.0);
    xa[2] = MF_R(1.0); ya[2] = MF_R(1.0); xa[3] = MF_R(0.0); ya[3] = MF_R(1.0);
    for (i = 0; i < nc && n >= 3; ++i) {
        int k;
        n = mf__ibm_clip_line(xa, ya, n, pc->ea[cut[i]], pc->eb[cut[i]], cv[i], xb, yb);
        for (k = 0; k < n; ++k) { xa[k] = xb[k]; ya[k] = yb[k]; }
    }
    return n >= 3 ? mf_max(mf__ibm_shoelace(xa, ya, n), MF_R(0.0)) : MF_R(0.0);
}

/* The bins whose weights a query needs: those of the window (cx + dx, cy + dy),
 * |dx|, |dy| <= r, that are listed; slot maps a window cell to its list entry. */
typedef struct mf__ibm_set {
    int cx, cy, r, side, n;
    int bin[MF_IBM_MAX_WINDOW];
    short slot[MF_IBM_MAX_WINDOW];
    mf_real w[MF_IBM_MAX_WINDOW];    /* accumulated area, then weight */
} mf__ibm_set;

MF_INLINE void mf__ibm_set_init(mf__ibm_set *s, int cx, int cy, int r)
{
    int i;
    s->cx = cx; s->cy = cy; s->r = r; s->side = 2 * r + 1; s->n = 0;
    for (i = 0; i < s->side * s->side; ++i) s->slot[i] = -1;
}

/* adds window cell (dx, dy) (bin j) to the list */
MF_INLINE void mf__ibm_set_add(mf__ibm_set *s, int dx, int dy, int j)
{
    s->slot[(dy + s->r) * s->side + dx + s->r] = (short)s->n;
    s->bin[s->n] = j;
    s->w[s->n] = MF_R(0.0);
    ++s->n;
}

/* list entry of a bin map value (ix | iy << s), or -1 */
MF_INLINE int mf__ibm_set_find(const mf_ibm *ibm, const mf__ibm_set *s, unsigned int v)
{
    int ix = (int)(v & ((1u << ibm->axis_bits) - 1u)), iy = (int)(v >> ibm->axis_bits);
    int dx = ix - s->cx, dy = iy - s->cy;
    if (dx < -s->r || dx > s->r || dy < -s->r || dy > s->r) return -1;
    return s->slot[(dy + s->r) * s->side + dx + s->r];
}

/* Direct texel sum over a piece (Eq. 5.2-5.3 grouped by bin): a texel's bin
 * is read first and its area clipped only when the bin is wanted. With
 * `all`, every texel's area is clipped and their sum returned (the piece's
 * area as the texel areas add up); otherwise 0. */
MF_INLINE mf_real mf__ibm_direct(const mf_ibm *ibm, const mf__ibm_piece *pc, mf__ibm_set *s, int all)
{
    mf_real tot = MF_R(0.0);
    int x, y;
    for (y = pc->by0; y < pc->by1; ++y)
        for (x = pc->bx0; x < pc->bx1; ++x) {
            int k = mf__ibm_set_find(ibm, s, mf__ibm_get(ibm->data + ibm->bin_at, (size_t)y * (size_t)ibm->width + (size_t)x, ibm->bin_bits));
            mf_real a;
            if (k < 0 && !all) continue;
            a = mf__ibm_texel_area(pc, x, y);
            if (!(a > MF_R(0.0))) continue;
            tot += a;
            if (k >= 0) s->w[k] += a;
        }
    return tot;
}

/* 1 if a texel of the direct footprint's bounding box (wrapped) is wanted:
 * its bin listed in s, or (s NULL) within the neighbourhood of radius r
 * around bin (cx, cy). An index-only test that spares the clipping (and,
 * for footprints of a few texels, listing the bins) when no texel is. */
MF_INLINE int mf__ibm_direct_any(const mf_ibm *ibm, const mf__ibm_fp *p, const mf__ibm_set *s, int cx, int cy, int r)
{
    int x, y, W = ibm->width, H = ibm->height;
    unsigned int m = (1u << ibm->axis_bits) - 1u;
    for (y = p->by0; y < p->by1; ++y) {
        int ty = y % H;
        if (ty < 0) ty += H;
        for (x = p->bx0; x < p->bx1; ++x) {
            int tx = x % W, dx, dy;
            unsigned int v;
            if (tx < 0) tx += W;
            v = mf__ibm_get(ibm->data + ibm->bin_at, (size_t)ty * (size_t)W + (size_t)tx, ibm->bin_bits);
            if (s) {
                if (mf__ibm_set_find(ibm, s, v) >= 0) return 1;
                continue;
            }
            dx = (int)(v & m) - cx; dy = (int)(v >> ibm->axis_bits) - cy;
            if (dx * dx + dy * dy <= r * (r + 1)) return 1;
        }
    }
    return 0;
}

/* first index in [s, e) whose Morton code has bit `bit` set: a linear scan
 * of short ranges (predictable, one cache line), else binary search */
MF_INLINE unsigned int mf__ibm_split(const mf_ibm *ibm, unsigned int s, unsigned int e, int bit)
{
    const unsigned int *pos = ibm->data + ibm->pos_at;
    /* all on one side (common where a bin's texels cluster): two reads */
    if (s >= e || ((mf__ibm_get(pos, s, ibm->list_bits) >> bit) & 1u)) return s;
    if (!((mf__ibm_get(pos, e - 1u, ibm->list_bits) >> bit) & 1u)) return e;
    if (e - s <= 24u) {
        while (s < e && !((mf__ibm_get(pos, s, ibm->list_bits) >> bit) & 1u)) ++s;
        return s;
    }
    while (s < e) {
        unsigned int m = s + (e - s) / 2u;
        if ((mf__ibm_get(pos, m, ibm->list_bits) >> bit) & 1u) e = m;
        else s = m + 1u;
    }
    return s;
}

typedef struct mf__ibm_frame {
    int x0, y0, lx, ly;
    unsigned int pre;               /* the node's index in its level (its code prefix) */
    unsigned int s[MF_IBM_BATCH], e[MF_IBM_BATCH];
} mf__ibm_frame;

/* kd traversal of Sec. 5.4.4 for up to MF_IBM_BATCH bins at once (their trees
 * share the splits): each node is classified against the piece once; inside
 * nodes add their texel count (prefiltering, Fig. 5.4), outside nodes are
 * skipped, cut nodes descend down to leaves of at most MF_IBM_LEAF texels,
 * whose texels get exact areas. */
MF_INLINE void mf__ibm_traverse(const mf_ibm *ibm, const mf__ibm_piece *pc, const int *bins, int nb, mf_real *acc)
{
    mf__ibm_frame st[MF__IBM_STACK], cur;
    unsigned int cnt[MF_IBM_BATCH], base[MF_IBM_BATCH], tab[MF_IBM_BATCH];
    int lev[MF_IBM_BATCH];
    mf_real frac[MF_IBM_BATCH];
    const unsigned int *pos = ibm->data + ibm->pos_at;
    int sp = 0, i, depth = ibm->kx + ibm->ky;
    cur.x0 = 0; cur.y0 = 0; cur.lx = ibm->kx; cur.ly = ibm->ky; cur.pre = 0u;
    for (i = 0; i < nb; ++i) {
        unsigned int nt = mf__ibm_bin_info(ibm, bins[i], &base[i], &tab[i], &lev[i]);
        cur.s[i] = base[i];
        cur.e[i] = base[i] + nt;
        cnt[i] = 0u;
        frac[i] = MF_R(0.0);
    }
    for (;;) {
        int x1 = cur.x0 + (1 << cur.lx), y1 = cur.y0 + (1 << cur.ly), c, any = 0;
        if (x1 > ibm->width) x1 = ibm->width;
        if (y1 > ibm->height) y1 = ibm->height;
        c = mf__ibm_classify(pc, cur.x0, cur.y0, x1, y1);
        if (c > 0) {
            for (i = 0; i < nb; ++i) cnt[i] += cur.e[i] - cur.s[i];
        } else if (c == 0) {
            mf__ibm_frame right;
            int bit = cur.lx + cur.ly - 1, rany = 0;
            for (i = 0; i < nb; ++i) {
                unsigned int s = cur.s[i], e = cur.e[i];
                right.s[i] = right.e[i] = 0u;
                if (s >= e) continue;
                if (e - s <= (unsigned int)MF_IBM_LEAF || bit < 0) {
                    for (; s < e; ++s) {
                        int x, y;
                        mf_real a;
                        mf__ibm_unmorton(ibm->kx, ibm->ky, mf__ibm_get(pos, s, ibm->list_bits), &x, &y);
                        a = mf__ibm_texel_area(pc, x, y);
                        if (a >= MF_R(1.0)) ++cnt[i];
                        else frac[i] += a;
                    }
                    cur.e[i] = cur.s[i];
                } else {
                    /* the split: stored down to level k, else binary search */
                    int l = depth - cur.lx - cur.ly, kk = lev[i];
                    unsigned int m = l < kk ? base[i] + mf__ibm_get(pos, (size_t)tab[i] + (size_t)((2u * cur.pre + 1u) << (kk - l - 1)), ibm->list_bits)
                                            : mf__ibm_split(ibm, s, e, bit);
                    right.s[i] = m; right.e[i] = e;
                    cur.e[i] = m;
                    if (m > s) any = 1;
                    if (e > m) rany = 1;
                }
            }
            if (bit >= 0) {
                if (cur.lx >= cur.ly) { --cur.lx; right.x0 = cur.x0 + (1 << cur.lx); right.y0 = cur.y0; }
                else { --cur.ly; right.x0 = cur.x0; right.y0 = cur.y0 + (1 << cur.ly); }
                right.lx = cur.lx; right.ly = cur.ly;
                cur.pre *= 2u;
                right.pre = cur.pre + 1u;
                if (rany) {
                    if (any) { if (sp < MF__IBM_STACK) st[sp++] = right; }
                    else { cur = right; continue; }
                }
                if (any) continue;
            }
        }
        if (sp == 0) break;
        cur = st[--sp];
    }
    for (i = 0; i < nb; ++i) acc[i] += (mf_real)cnt[i] + frac[i];
}

/* W_j for every bin of the set (Eq. 5.8): full periods count each texel of the
 * bin once, the pieces by direct sum or kd traversal, all divided by |A|. */
MF_INLINE void mf__ibm_weights(const mf_ibm *ibm, const mf__ibm_fp *p, mf__ibm_set *s)
{
    mf_real tot, dtot = MF_R(0.0);
    int i, direct = p->direct;
    if (p->mode == MF__IBM_NONE) { for (i = 0; i < s->n; ++i) s->w[i] = MF_R(0.0); return; }
    if (p->mode == MF__IBM_POINT) {
        int k = mf__ibm_set_find(ibm, s, mf__ibm_get(ibm->data + ibm->bin_at, (size_t)p->ty * (size_t)ibm->width + (size_t)p->tx, ibm->bin_bits));
        for (i = 0; i < s->n; ++i) s->w[i] = i == k ? MF_R(1.0) : MF_R(0.0);
        return;
    }
    if (p->mode == MF__IBM_GLOBAL) {
        mf_real inv = MF_R(1.0) / ((mf_real)ibm->width * (mf_real)ibm->height);
        for (i = 0; i < s->n; ++i) s->w[i] = (mf_real)mf_ibm_bin_texels(ibm, s->bin[i]) * inv;
        return;
    }
    for (i = 0; i < s->n; ++i) s->w[i] = p->full * (mf_real)mf_ibm_bin_texels(ibm, s->bin[i]);
    if (direct && !p->few) {
        /* wanted bins with fewer texels than half the bounding box: their
         * lists (kd traversal) cost less than visiting the box */
        double texels = 0.0;
        for (i = 0; i < s->n; ++i) texels += (double)mf_ibm_bin_texels(ibm, s->bin[i]);
        if (2.0 * texels < (double)(p->bx1 - p->bx0) * (double)(p->by1 - p->by0)) direct = 0;
    }
    if (direct && !mf__ibm_direct_any(ibm, p, s, 0, 0, 0)) return;   /* no wanted texel: all 0 */
    tot = p->full * (mf_real)ibm->width * (mf_real)ibm->height;
    {
        mf_real xs[12], ys[12], c0, c1, f0, f1, col;
        mf__ibm_piece pc;
        int row;
        for (row = p->row0; row <= p->row1; ++row) {
            int n = mf__ibm_slab(ibm, p, row, xs, ys);
            if (n < 3) continue;
            mf__ibm_slab_columns(ibm, row, xs, ys, n, &c0, &c1, &f0, &f1);
            for (col = c0; col <= c1; col += MF_R(1.0)) {
                if (col >= f0 && col <= f1) continue;
                if (!mf__ibm_piece_make(ibm, p, row, (int)col, xs, ys, n, &pc)) continue;
                tot += mf__ibm_shoelace(pc.x, pc.y, pc.n);
                if (direct) dtot += mf__ibm_direct(ibm, &pc, s, p->few);
                else
                    for (i = 0; i < s->n; i += MF_IBM_BATCH)
                        mf__ibm_traverse(ibm, &pc, s->bin + i, s->n - i < MF_IBM_BATCH ? s->n - i : MF_IBM_BATCH, s->w + i);
            }
        }
    }
    /* |A| as the pieces add up, so that the weights of all bins sum to 1 even
     * where float round-off moves the corners of a thin footprint; for
     * small or thin footprints (few), as the texel areas themselves add up
     * (the clipped texels and the shoelace of the pieces round differently:
     * on a flat map, where one bin holds every texel, the weight of a
     * sub-texel footprint is then exactly 1) */
    if (direct && p->few && dtot > MF_R(0.0)) tot = dtot;
    if (!(tot > MF_R(0.0))) tot = p->area;
    for (i = 0; i < s->n; ++i) s->w[i] = mf_clamp(s->w[i] / tot, MF_R(0.0), MF_R(1.0));
}

MF_COLD mf_real mf_ibm_bin_weight(const mf_ibm *ibm, int bin, const mf_footprint *f)
{
    mf__ibm_fp p;
    mf__ibm_set s;
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return MF_R(0.0);
    if (mf_ibm_bin_texels(ibm, bin) == 0) return MF_R(0.0);   /* empty bin: no footprint work */
    mf__ibm_footprint(ibm, f, &p);
    mf__ibm_set_init(&s, bin % ibm->res, bin / ibm->res, 0);
    mf__ibm_set_add(&s, 0, 0, bin);
    mf__ibm_weights(ibm, &p, &s);
    return s.w[0];
}

MF_COLD int mf_ibm_neighbourhood_weights(const mf_ibm *ibm, const mf_footprint *f, int center_bin, int *bins,
                                           mf_real *weights)
{
    mf__ibm_fp p;
    mf__ibm_set s;
    int dx, dy, r, b, cx, cy, i;
    if (!ibm || !ibm->data || center_bin < 0 || center_bin >= ibm->res * ibm->res) return 0;
    r = ibm->radius; b = ibm->res; cx = center_bin % b; cy = center_bin / b;
    mf__ibm_set_init(&s, cx, cy, r);
    for (dy = -r; dy <= r; ++dy)
        for (dx = -r; dx <= r; ++dx) {
            int j = (cx + dx) + b * (cy + dy);
            if (dx * dx + dy * dy > r * (r + 1) || cx + dx < 0 || cx + dx >= b || cy + dy < 0 || cy + dy >= b) continue;
            if (mf_ibm_bin_texels(ibm, j) > 0) mf__ibm_set_add(&s, dx, dy, j);
        }
    if (s.n == 0) return 0;   /* an empty neighbourhood: no footprint work */
    mf__ibm_footprint(ibm, f, &p);
    mf__ibm_weights(ibm, &p, &s);
    for (i = 0; i < s.n; ++i) { bins[i] = s.bin[i]; weights[i] = s.w[i]; }
    return s.n;
}

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
    int dx, dy, r = ibm->radius, b = ibm->res, cx, cy, i;
    h = mf_normalize(mf_add(wo, wi));
    if (!(h.z > MF_R(0.0))) return MF_R(0.0);
    mf__ibm_footprint(ibm, f, &p);
    if (p.mode == MF__IBM_NONE) return MF_R(0.0);
    cx = mf__ibm_cell(h.x, b); cy = mf__ibm_cell(h.y, b);
    if (p.mode == MF__IBM_EXACT && p.few && !mf__ibm_direct_any(ibm, &p, (const mf__ibm_set *)0, cx, cy, r)) return MF_R(0.0);
    mf__ibm_set_init(&s, cx, cy, r);
    /* the non-empty bins of the neighbourhood; for a footprint of many
     * texels only those that face wo (and wi when only f is wanted), which
     * spares their traversal (small ones are checked after their weights) */
    for (dy = -r; dy <= r; ++dy)
        for (dx = -r; dx <= r; ++dx) {
            int j = (cx + dx) + b * (cy + dy);
            mf_vec3 t;
            if (dx * dx + dy * dy > r * (r + 1) || cx + dx < 0 || cx + dx >= b || cy + dy < 0 || cy + dy >= b) continue;
            if (mf_ibm_bin_texels(ibm, j) == 0) continue;
            if (p.mode == MF__IBM_EXACT && !p.direct) {
                t = mf_ibm_bin_normal(ibm, j);
                if (!(mf_dot(wo, t) > MF_R(0.0)) || !(mf_dot(h, t) > MF_R(0.0))) continue;
                if (!pdf && !(mf_dot(wi, t) > MF_R(0.0))) continue;
            }
            mf__ibm_set_add(&s, dx, dy, j);
        }
    if (s.n == 0) return MF_R(0.0);
    mf__ibm_weights(ibm, &p, &s);
    for (i = 0; i < s.n; ++i) {
        mf_vec3 t, xh, xo;
        mf_real co, ci, ch, d, lo;
        if (!(s.w[i] > MF_R(0.0))) continue;
        t = mf_ibm_bin_normal(ibm, s.bin[i]);
        co = mf_dot(wo, t); ci = mf_dot(wi, t); ch = mf_dot(h, t);
        if (!(co > MF_R(0.0)) || !(ch > MF_R(0.0))) continue;
        xh = mf_cross(h, t); xo = mf_cross(wo, t);
        d = mf_beckmann_D(a, a, mf_vec3_make(MF_SQRT(mf_dot(xh, xh)), MF_R(0.0), ch));
        if (!(d > MF_R(0.0))) continue;
        lo = mf_beckmann_lambda(a, a, mf_vec3_make(MF_SQRT(mf_dot(xo, xo)), MF_R(0.0), co));
        spdf += s.w[i] * d / (MF_R(4.0) * co * (MF_R(1.0) + lo));
        if (want_f && ci > MF_R(0.0)) {
            mf_vec3 xi = mf_cross(wi, t);
            mf_real li = mf_beckmann_lambda(a, a, mf_vec3_make(MF_SQRT(mf_dot(xi, xi)), MF_R(0.0), ci));
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

MF_COLD mf_real mf_ibm_brdf_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf)
{
    mf_real tmp = MF_R(0.0);
    if (!pdf) pdf = &tmp;
    *pdf = MF_R(0.0);
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ibm_lobes(ibm, f, wo, wi, 1, pdf);
}

MF_COLD mf_vec3 mf_ibm_sample(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                mf_real u3, mf_real u4)
{
    mf_vec3 none = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), t, tt, tb, o, m, wi, h;
    mf__ibm_fp p;
    int tx, ty, j, dx, dy, r;
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0))) return none;
    mf__ibm_footprint(ibm, f, &p);
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0)); u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));
    if (!(u1 == u1)) u1 = MF_R(0.5);
    if (!(u2 == u2)) u2 = MF_R(0.5);
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
    mf_frame(t, &tt, &tb);
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
#endif /* MF_NO_IBM */

#ifdef __cplusplus
}
#endif
#endif /* cold paths */

/* ======================================================================== */
/* == Implementation: builders, loaders, fitters, generators, data tables  */
/* ======================================================================== */
#if defined(MICROFACET_IMPLEMENTATION) && !defined(MICROFACET_IMPLEMENTATION_DONE)
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

/* 1 if n is a positive power of two (the map builders' sizes). */
MF_INLINE int mf__pow2(int n) { return n > 0 && (n & (n - 1)) == 0; }
/* ---- Tabulated (piecewise-linear) distributions ---- */

static void mf__tab_zero(mf_tabulated *t)
{
    t->n = t->aniso = t->n_lam = 0;
    t->inv_h = t->inv_hl = t->wx = t->wy = t->scale = MF_R(0.0);
    t->theta = t->dx = t->dy = t->cx = t->cy = t->lt = t->li = (mf_real *)0;
    t->block = (void *)0;
    t->bytes = 0;
}

/* normalizes curve c in place (Eq. 12) and fills its cumulative mass; 0 if its mass is not positive */
static int mf__tab_normalize(const mf_real *th, mf_real *c, mf_real *cum, int n)
{
    mf_real total = MF_R(0.0);
    int i;
    cum[0] = MF_R(0.0);
    for (i = 0; i + 1 < n; ++i) {
        total += mf__tab_piece_mass(th[i], c[i], (c[i + 1] - c[i]) / (th[i + 1] - th[i]), th[i + 1]);
        cum[i + 1] = total;
    }
    if (!(total > MF_R(0.0)) || !(total < MF_BIG)) return 0;
    for (i = 0; i < n; ++i) { c[i] /= total; cum[i] /= total; }
    cum[n - 1] = MF_R(1.0);
    return 1;
}

/* I0, dI0, I2, dI2 at theta_o (mf__tabulated_lambda): the closed-form part inside
 * theta_c = pi/2 - theta_o, the integrated part beyond. */
static void mf__tab_node(const mf_tabulated *t, mf_real to, mf_real *out)
{
    mf_real so = MF_SIN(to), co = mf_max(MF_COS(to), MF_R(0.0)), tc = mf_max(MF_R(0.5) * MF_PI - to, MF_R(0.0)), o[4];
    mf_real mxw = t->aniso ? MF_R(0.5) * t->wx : MF_R(1.0), myw = t->aniso ? MF_R(0.5) * t->wy : MF_R(0.0);
    mf_real cin = mf__tab_mass_to(t, mxw, myw, tc);
    int k = mf__tab_find(t->theta, t->n, t->inv_h, tc), j;
    out[0] = co * cin; out[1] = -so * cin; out[2] = out[3] = MF_R(0.0);
    for (j = k; j < t->n - 1; ++j) {
        mf__tab_outer(t, j, j == k ? mf_min(tc, t->theta[k + 1]) : t->theta[j], t->theta[j + 1], so, co, j == k, 1, o);
        out[0] += o[0]; out[2] += o[1]; out[1] += o[2]; out[3] += o[3];
    }
}

MFDEF mf_result mf_tabulated_build(mf_tabulated *t, const mf_real *theta, const mf_real *D_x,
                                   const mf_real *D_y, int n)
{
    const mf_real hpi = MF_R(0.5) * MF_PI;
    mf_real *blk, h, c0;
    int i, j, q, aniso = 0, sub, nl, uniform = 1;
    size_t count;
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    mf__tab_zero(t);
    if (!theta || !D_x || n < 2 || n > MF_TABULATED_MAX_POINTS) return MF_ERROR_INVALID_ARGUMENT;
    h = hpi / (mf_real)(n - 1);
    for (i = 0; i < n; ++i) {
        if (!mf__finite_bits(theta[i]) || !(MF_FABS(theta[i]) < MF_R(10.0))) return MF_ERROR_INVALID_DATA;
        if (i > 0 && !mf__tab_gap_ok(i == 1 ? MF_R(0.0) : theta[i - 1], i == n - 1 ? hpi : theta[i]))
            return MF_ERROR_INVALID_DATA;   /* unordered, or too close once the ends are snapped */
        if (!mf__finite_bits(D_x[i]) || !(D_x[i] >= MF_R(0.0) && D_x[i] < MF_BIG)) return MF_ERROR_INVALID_DATA;
        if (D_y && (!mf__finite_bits(D_y[i]) || !(D_y[i] >= MF_R(0.0) && D_y[i] < MF_BIG))) return MF_ERROR_INVALID_DATA;
        if (D_y && D_y[i] != D_x[i]) aniso = 1;
        if (!(MF_FABS(theta[i] - h * (mf_real)i) <= MF_R(1e-4) * h)) uniform = 0;
    }
    if (!(MF_FABS(theta[0]) <= MF_R(1e-4)) || !(MF_FABS(theta[n - 1] - hpi) <= MF_R(1e-4))) return MF_ERROR_INVALID_DATA;
    /* projected-area nodes: the mirrored control points, each interval cut in sub */
    sub = n - 1 >= 512 ? 1 : n - 1 >= 128 ? 2 : n - 1 >= 32 ? 4 : 8;
    nl = (n - 1) * sub + 1;
    count = (size_t)n * (aniso ? 5u : 3u) + (size_t)nl * 5u;
    blk = (mf_real *)MF_MALLOC(sizeof(mf_real) * count);
    if (!blk) return MF_ERROR_OUT_OF_MEMORY;
    t->block = blk; t->bytes = sizeof(mf_real) * count;
    t->n = n; t->aniso = aniso; t->n_lam = nl;
    t->theta = blk; t->dx = blk + n; t->cx = blk + 2 * n;
    t->dy = aniso ? blk + 3 * n : t->dx;
    t->cy = aniso ? blk + 4 * n : t->cx;
    t->lt = blk + (size_t)n * (aniso ? 5u : 3u);
    t->li = t->lt + nl;
    for (i = 0; i < n; ++i) {
        t->theta[i] = theta[i];
        t->dx[i] = D_x[i];
        if (aniso) t->dy[i] = D_y[i];
    }
    t->theta[0] = MF_R(0.0); t->theta[n - 1] = hpi;
    if (!mf__tab_normalize(t->theta, t->dx, t->cx, n) || (aniso && !mf__tab_normalize(t->theta, t->dy, t->cy, n))) {
        mf_tabulated_release(t);
        return MF_ERROR_INVALID_DATA;
    }
    c0 = MF_R(0.5) * (t->dx[0] + t->dy[0]);   /* Eq. 10 */
    t->wx = c0 > MF_R(0.0) ? t->dy[0] / c0 : MF_R(1.0);
    t->wy = c0 > MF_R(0.0) ? t->dx[0] / c0 : MF_R(1.0);
    t->inv_h = uniform ? MF_R(1.0) / h : MF_R(0.0);
    t->inv_hl = uniform ? (mf_real)sub / h : MF_R(0.0);
    for (j = 0; j + 1 < n; ++j) {
        mf_real a = hpi - t->theta[n - 1 - j], b = hpi - t->theta[n - 2 - j];
        for (q = 0; q < sub; ++q) t->lt[j * sub + q] = a + (b - a) * (mf_real)q / (mf_real)sub;
    }
    t->lt[0] = MF_R(0.0); t->lt[nl - 1] = hpi;
    for (j = 0; j < nl; ++j) mf__tab_node(t, t->lt[j], t->li + 4 * j);
    {   /* characteristic slope: the median of D cos */
        mf_real mxw = aniso ? MF_R(0.5) * t->wx : MF_R(1.0), myw = aniso ? MF_R(0.5) * t->wy : MF_R(0.0);
        t->scale = mf_clamp(MF_TAN(mf_min(mf__tab_invert(t, mxw, myw, MF_R(0.5)), MF_R(1.5706))), MF_R(1e-4), MF_R(1e4));
    }
    return MF_SUCCESS;
}

/* D of d averaged over the azimuths phi0 and phi0 + pi, at polar angle th */
static mf_real mf__tab_slice(const mf_ndf *d, mf_real th, mf_real phi0)
{
    mf_real st = MF_SIN(th), ct = MF_COS(th), c = MF_COS(phi0), s = MF_SIN(phi0);
    return MF_R(0.5) * (mf_D(d, mf_vec3_make(st * c, st * s, ct)) + mf_D(d, mf_vec3_make(-st * c, -st * s, ct)));
}

MFDEF mf_result mf_tabulated_from_ndf(mf_tabulated *t, const mf_ndf *d, int n)
{
    const mf_real hpi = MF_R(0.5) * MF_PI;
    mf_real *th, *dx, *dy, *cth, *cx, *cy, *cum, *err, scale = MF_R(1.0), total = MF_R(0.0), fmax = MF_R(0.0);
    int i, j, m, M, iso = 1, K = 800, *best;
    char *sel;
    mf_result r;
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    mf__tab_zero(t);
    if (!d || n < 4 || n > MF_TABULATED_MAX_POINTS) return MF_ERROR_INVALID_ARGUMENT;
    M = 8 * n;   /* candidate angles */
    th = (mf_real *)MF_MALLOC(sizeof(mf_real) * (3 * (size_t)n + 5 * (size_t)M) + (sizeof(int) + 1) * (size_t)M);
    if (!th) return MF_ERROR_OUT_OF_MEMORY;
    dx = th + n; dy = th + 2 * n; cth = th + 3 * n; cx = cth + M; cy = cx + M; cum = cy + M; err = cum + M;
    best = (int *)(void *)(err + M);
    sel = (char *)(void *)(best + M);
    /* the median tan(theta) of D cos over a log grid of tan(theta) in [1e-5, 1e5]
     * (two passes: the total, then the median) */
    for (j = 0; j < 2; ++j) {
        mf_real acc = MF_R(0.0), prev_t = MF_R(0.0), prev_f = MF_R(0.0);
        for (i = 0; i <= K; ++i) {
            mf_real tt = MF_ATAN(MF_R(1e-5) * MF_POW(MF_R(10.0), MF_R(10.0) * (mf_real)i / (mf_real)K));
            mf_real f = MF_R(0.5) * (mf__tab_slice(d, tt, MF_R(0.0)) + mf__tab_slice(d, tt, hpi)) * MF_COS(tt) * MF_SIN(tt);
            acc += MF_R(0.5) * (f + prev_f) * (tt - prev_t);
            prev_t = tt; prev_f = f;
            if (j == 1 && acc >= MF_R(0.5) * total) { scale = MF_TAN(tt); break; }
        }
        total = acc;
    }
    if (!(total > MF_R(0.0)) || !(total < MF_BIG)) { MF_FREE(th); return MF_ERROR_INVALID_DATA; }
    /* candidates: half uniform in theta, half at tan(theta) = s tan(pi q / 2), merged */
    for (i = 0; i < M / 2; ++i) cth[i] = hpi * (mf_real)i / (mf_real)(M / 2 - 1);
    for (i = M / 2; i < M; ++i) cth[i] = MF_ATAN(scale * MF_TAN(hpi * (mf_real)(i - M / 2 + 1) / (mf_real)(M - M / 2 + 1)));
    {   /* merge the two sorted halves (through err, free until phase 2) */
        int a = 0, b = M / 2, k = 0;
        while (a < M / 2 || b < M) err[k++] = b >= M || (a < M / 2 && cth[a] <= cth[b]) ? cth[a++] : cth[b++];
        for (i = 0; i < M; ++i) cth[i] = err[i];
    }
    for (i = 1, m = 1; i < M; ++i)
        if (mf__tab_gap_ok(cth[m - 1], cth[i])) cth[m++] = cth[i];
    cth[m - 1] = hpi;
    M = m;
    for (i = 0; i < M; ++i) {
        cx[i] = mf__tab_slice(d, cth[i], MF_R(0.0));
        cy[i] = mf__tab_slice(d, cth[i], hpi);
        fmax = mf_max(fmax, mf_max(cx[i], cy[i]));
    }
    /* Control points are candidates. Phase 1 (3/4 of them) equidistributes the
     * error of linear interpolation relative to D (floored at 1e-4 of its
     * peak): density sqrt(|D''| / D) plus a floor so flat parts keep points.
     * Phase 2 adds the rest to the segments whose interpolated D cos mass is
     * most wrong (e.g. a wide segment from a small value to zero beyond the end
     * of a lobe, which no curvature sees), a quarter of them per pass. */
    cum[0] = MF_R(0.0);
    for (i = 1; i < M; ++i) {
        mf_real rho = MF_R(0.0), h = cth[i] - cth[i - 1];
        int a = i > 1 ? i - 1 : 1, k;
        for (k = 0; k < 2; ++k) {
            const mf_real *f = k ? cy : cx;
            mf_real h0 = cth[a] - cth[a - 1], h1 = cth[a + 1 < M ? a + 1 : a] - cth[a];
            mf_real d2 = a + 1 < M ? MF_R(2.0) * ((f[a + 1] - f[a]) / h1 - (f[a] - f[a - 1]) / h0) / (h0 + h1) : MF_R(0.0);
            rho = mf_max(rho, MF_SQRT(MF_FABS(d2) / (MF_R(0.5) * (f[i] + f[i - 1]) + MF_R(1e-4) * fmax)));
        }
        cum[i] = cum[i - 1] + h * (rho + MF_R(2.0) / hpi);
    }
    for (i = 0; i < M; ++i) sel[i] = (char)(i == 0 || i == M - 1);
    for (i = 1, j = 1, m = 2; i < (3 * n) / 4 - 1; ++i) {
        mf_real target = cum[M - 1] * (mf_real)i / (mf_real)((3 * n) / 4 - 1);
        while (j < M - 1 && cum[j] < target) ++j;
        if (!sel[j]) { sel[j] = 1; ++m; }
    }
    while (m < n) {
        /* mass error of each segment, in units of the total */
        mf_real emax = MF_R(0.0), thr;
        int a = 0, nseg = 0, added = 0, want;
        for (i = 1; i < M; ++i) {
            if (!sel[i]) continue;
            err[nseg] = MF_R(0.0); best[nseg] = -1;
            {
                mf_real be = -MF_R(1.0);
                int k, c2;
                for (k = a + 1; k < i; ++k)
                    for (c2 = 0; c2 < 2; ++c2) {
                        const mf_real *f = c2 ? cy : cx;
                        mf_real fr = (cth[k] - cth[a]) / (cth[i] - cth[a]), lin = f[a] + (f[i] - f[a]) * fr;
                        mf_real dev = MF_FABS(lin - f[k]);
                        err[nseg] += dev * MF_COS(cth[k]) * MF_SIN(cth[k]) * (cth[k + 1] - cth[k - 1]) * MF_R(0.5) / total;
                        /* split where the interpolant is furthest off: right after the end of a lobe,
                         * mid-way inside one */
                        if (dev > be) { be = dev; best[nseg] = k; }
                    }
            }
            emax = mf_max(emax, err[nseg]);
            ++nseg; a = i;
        }
        want = n - m < nseg / 4 + 1 ? n - m : nseg / 4 + 1;
        if (!(emax > MF_R(0.0)) || want <= 0) break;
        /* threshold: bisect for about `want` segments above it */
        {
            mf_real lo = MF_R(0.0), hi = emax;
            int it, cnt;
            for (it = 0; it < 40; ++it) {
                thr = MF_R(0.5) * (lo + hi);
                for (cnt = 0, i = 0; i < nseg; ++i) cnt += err[i] > thr;
                if (cnt > want) lo = thr; else hi = thr;
            }
            thr = hi;
        }
        for (i = 0; i < nseg && m < n; ++i)
            if ((err[i] >= thr || (added == 0 && err[i] == emax)) && best[i] > 0 && !sel[best[i]]) { sel[best[i]] = 1; ++m; ++added; }
        if (!added) break;
    }
    for (i = 0, m = 0; i < M; ++i)
        if (sel[i]) {
            th[m] = cth[i]; dx[m] = cx[i]; dy[m] = cy[i];
            if (MF_FABS(dx[m] - dy[m]) > MF_R(1e-6) * mf_max(dx[m], dy[m])) iso = 0;
            ++m;
        }
    r = mf_tabulated_build(t, th, dx, iso ? (const mf_real *)0 : dy, m);
    MF_FREE(th);
    return r;
}

MFDEF void mf_tabulated_release(mf_tabulated *t)
{
    if (!t) return;
    MF_FREE(t->block);
    mf__tab_zero(t);
}

MFDEF size_t mf_tabulated_memory_bytes(const mf_tabulated *t)
{
    return t && t->block ? t->bytes : 0;
}
#ifndef MF_NO_LEADR
/* ---- LEADR moment maps ---- */


/* allocates the pyramid for level 0 already filled in m->texels[0..w*h) */
static mf_result mf__leadr_alloc(mf_leadr_map *m, int w, int h)
{
    size_t total = 0;
    int l, ww = w, hh = h;
    m->width = w; m->height = h; m->levels = 0;
    for (l = 0; l < 32; ++l) {
        m->offset[l] = total;
        total += (size_t)ww * (size_t)hh;
        ++m->levels;
        if (ww == 1 && hh == 1) break;
        ww = ww > 1 ? ww / 2 : 1; hh = hh > 1 ? hh / 2 : 1;
    }
    /* at most 2^30 * 4/3 texels (sizes up to 2^15): check the bytes anyway */
    if (total > (size_t)-1 / sizeof(mf_leadr)) return MF_ERROR_OUT_OF_MEMORY;
    m->texels = (mf_leadr *)MF_MALLOC(sizeof(mf_leadr) * total);
    return m->texels ? MF_SUCCESS : MF_ERROR_OUT_OF_MEMORY;
}

/* coarser levels: the mean of the 2x2 children (a 2x1 or 1x2 pair once one
 * side has reached 1) */
static void mf__leadr_reduce(mf_leadr_map *m)
{
    int l;
    for (l = 1; l < m->levels; ++l) {
        size_t pw = (size_t)mf__leadr_level_w(m, l - 1), ph = (size_t)mf__leadr_level_h(m, l - 1);
        size_t w = (size_t)mf__leadr_level_w(m, l), h = (size_t)mf__leadr_level_h(m, l), x, y;
        const mf_leadr *src = m->texels + m->offset[l - 1];
        mf_leadr *dst = m->texels + m->offset[l];
        size_t sx = pw > w ? 2 : 1, sy = ph > h ? 2 : 1;
        for (y = 0; y < h; ++y)
            for (x = 0; x < w; ++x) {
                mf_leadr acc = src[(y * sy) * pw + x * sx];
                if (sx == 2) acc = mf_leadr_add(acc, src[(y * sy) * pw + x * sx + 1]);
                if (sy == 2) {
                    acc = mf_leadr_add(acc, src[(y * sy + 1) * pw + x * sx]);
                    if (sx == 2) acc = mf_leadr_add(acc, src[(y * sy + 1) * pw + x * sx + 1]);
                }
                dst[y * w + x] = mf_leadr_scale(acc, MF_R(1.0) / (mf_real)(sx * sy));
            }
    }
}

/* the base roughness: finite, 0 to MF_ALPHA_MAX */
MF_INLINE int mf__leadr_alpha_ok(mf_real a) { return a >= MF_R(0.0) && a <= MF_ALPHA_MAX; }

MFDEF mf_result mf_leadr_map_from_heights(mf_leadr_map *m, const mf_real *heights, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y)
{
    size_t x, y, w = (size_t)width, h = (size_t)height, i;
    mf_result r;
    if (!m) return MF_ERROR_INVALID_ARGUMENT;
    m->texels = 0; m->width = m->height = m->levels = 0;
    if (!heights || !mf__pow2(width) || !mf__pow2(height) || width > (1 << 15) || height > (1 << 15) ||
        !mf__leadr_alpha_ok(alpha_x) || !mf__leadr_alpha_ok(alpha_y))
        return MF_ERROR_INVALID_ARGUMENT;
    /* allocation first: a size the allocator refuses never reads the data */
    r = mf__leadr_alloc(m, width, height);
    if (r != MF_SUCCESS) { m->width = m->height = m->levels = 0; return r; }
    for (i = 0; i < w * h; ++i)
        if (!mf__finite_bits(heights[i]) || !(MF_FABS(heights[i]) < MF_BIG)) { mf_leadr_map_release(m); return MF_ERROR_INVALID_DATA; }
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            size_t xp = (x + 1) % w, xm = (x + w - 1) % w, yp = (y + 1) % h, ym = (y + h - 1) % h;
            /* rows run top to bottom, v grows downward with the row index */
            mf_real su = (heights[y * w + xp] - heights[y * w + xm]) * (mf_real)width * MF_R(0.5);
            mf_real sv = (heights[yp * w + x] - heights[ym * w + x]) * (mf_real)height * MF_R(0.5);
            if (!(su * su < MF_R(0.25) * MF_BIG) || !(sv * sv < MF_R(0.25) * MF_BIG)) {
                mf_leadr_map_release(m);
                return MF_ERROR_INVALID_DATA;
            }
            m->texels[y * w + x] = mf_leadr_with_roughness(mf_leadr_from_slope(su, sv), alpha_x, alpha_y);
        }
    mf__leadr_reduce(m);
    return MF_SUCCESS;
}

MFDEF mf_result mf_leadr_map_from_normals(mf_leadr_map *m, const mf_real *normals_xyz, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y)
{
    size_t i, n_texels = (size_t)width * (size_t)height;
    mf_result r;
    if (!m) return MF_ERROR_INVALID_ARGUMENT;
    m->texels = 0; m->width = m->height = m->levels = 0;
    if (!normals_xyz || !mf__pow2(width) || !mf__pow2(height) || width > (1 << 15) || height > (1 << 15) ||
        !mf__leadr_alpha_ok(alpha_x) || !mf__leadr_alpha_ok(alpha_y))
        return MF_ERROR_INVALID_ARGUMENT;
    r = mf__leadr_alloc(m, width, height);
    if (r != MF_SUCCESS) { m->width = m->height = m->levels = 0; return r; }
    for (i = 0; i < n_texels; ++i) {
        const mf_real *n = normals_xyz + 3 * i;
        mf_real l2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (!(n[2] >= MF_LEADR_MIN_NORMAL_Z) || !(MF_FABS(l2 - MF_R(1.0)) < MF_R(1e-3))) {
            mf_leadr_map_release(m);
            return MF_ERROR_INVALID_DATA;
        }
    }
    for (i = 0; i < n_texels; ++i) {
        const mf_real *n = normals_xyz + 3 * i;
        m->texels[i] = mf_leadr_with_roughness(mf_leadr_from_normal(mf_vec3_make(n[0], n[1], n[2])), alpha_x, alpha_y);
    }
    mf__leadr_reduce(m);
    return MF_SUCCESS;
}

MFDEF void mf_leadr_map_release(mf_leadr_map *m)
{
    if (!m) return;
    MF_FREE(m->texels);
    m->texels = 0;
    m->width = m->height = m->levels = 0;
}

MFDEF size_t mf_leadr_map_memory_bytes(const mf_leadr_map *m)
{
    if (!m || !m->texels || m->levels < 1) return 0;
    return sizeof(mf_leadr) * (m->offset[m->levels - 1] + 1);
}
#endif /* MF_NO_LEADR */
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
    MF__SOLVER_DONE(MF__SITE_LTC_FIT, it, max_iter);
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
    /* Albedo, Fresnel term and average direction by importance sampling (the
     * BRDF's own sampler, or the cosine) on a 256 x 256 grid, fine enough for
     * the heavy GGX tail (1% of the lobe beyond 45 degrees at alpha 0.1) that a
     * 32 x 32 midpoint grid misses; the error estimate uses every 8th point. */
    for (i = 0, k = 0; i < 8 * n1; ++i)
        for (j = 0; j < 8 * n1; ++j) {
            mf_real u1 = ((mf_real)i + MF_R(0.5)) / (mf_real)(8 * n1), u2 = ((mf_real)j + MF_R(0.5)) / (mf_real)(8 * n1), f, pdf, w;
            mf_vec3 wi, h;
            wi = brdf ? mf__sample_cosine(u1, u2) : mf_brdf_sample(d, c.wo, u1, u2);
            f = mf__fit_f(&c, wi);
            pdf = mf__fit_pdf(&c, wi);
            w = pdf > MF_R(0.0) ? f / pdf : MF_R(0.0);
            if (i % 8 == 4 && j % 8 == 4) { c.bw[k] = wi; c.bf[k] = f; c.bp[k] = pdf; ++k; }
            sum += w;
            h = mf_normalize(mf_add(c.wo, wi));
            {
                mf_real q = MF_R(1.0) - mf_clamp(mf_dot(c.wo, h), MF_R(0.0), MF_R(1.0)), q2 = q * q;
                fres += w * q2 * q2 * q;
            }
            avg = mf_add(avg, mf_scale(wi, w));
        }
    c.albedo = sum / (mf_real)(64 * c.n);
    out->albedo = c.albedo;
    out->fresnel = fres / (mf_real)(64 * c.n);
    if (!(c.albedo > MF_R(1e-12))) {   /* no lobe: the clamped cosine, zero albedo */
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        out->ltc = mf_ltc_from_matrix9(I9);
        out->inv[0] = out->inv[3] = MF_R(1.0); out->inv[1] = out->inv[2] = MF_R(0.0);
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
        out->inv[0] = iv[0] / iv[4]; out->inv[1] = iv[2] / iv[4];
        out->inv[2] = iv[6] / iv[4]; out->inv[3] = iv[8] / iv[4];
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

/* Bilinear lookup in (sqrt(1 - cos theta_o), sqrt(alpha)) of the four
 * stored M^-1 entries (middle entry 1); the albedo and Fresnel columns only
 * when asked for; M in closed form (mf_ltc_from_inverse). */
static mf_ltc mf__ltc_lookup(const float *data, int nt, int na, mf_real cos_theta_o, mf_real alpha,
                             mf_real *albedo, mf_real *fresnel)
{
    mf_real ct, a, x, y, fx, fy, w00, w10, w01, w11, v[4];
    const float *e00, *e10, *e01, *e11;
    int ix, iy, k;
    if (!(cos_theta_o == cos_theta_o) || !(alpha == alpha)) {
        /* NaN: no lookup (its conversion to int is undefined) */
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        if (albedo) *albedo = MF_R(0.0);
        if (fresnel) *fresnel = MF_R(0.0);
        return mf_ltc_from_matrix9(I9);
    }
    ct = mf_clamp(cos_theta_o, MF_R(0.0), MF_R(1.0)); a = mf_clamp(alpha, MF_R(0.0), MF_R(1.0));
    x = MF_SQRT(MF_R(1.0) - ct) * (mf_real)(nt - 1); y = MF_SQRT(a) * (mf_real)(na - 1);
    ix = (int)x; iy = (int)y;
    if (ix > nt - 2) ix = nt - 2;
    if (iy > na - 2) iy = na - 2;
    fx = mf_clamp(x - (mf_real)ix, MF_R(0.0), MF_R(1.0)); fy = mf_clamp(y - (mf_real)iy, MF_R(0.0), MF_R(1.0));
    e00 = data + 6 * (iy * nt + ix); e10 = e00 + 6; e01 = e00 + 6 * nt; e11 = e01 + 6;
    w00 = (MF_R(1.0) - fx) * (MF_R(1.0) - fy); w10 = fx * (MF_R(1.0) - fy);
    w01 = (MF_R(1.0) - fx) * fy; w11 = fx * fy;
    for (k = 0; k < 4; ++k)
        v[k] = w00 * (mf_real)e00[k] + w10 * (mf_real)e10[k] + w01 * (mf_real)e01[k] + w11 * (mf_real)e11[k];
    if (albedo) *albedo = w00 * (mf_real)e00[4] + w10 * (mf_real)e10[4] + w01 * (mf_real)e01[4] + w11 * (mf_real)e11[4];
    if (fresnel) *fresnel = w00 * (mf_real)e00[5] + w10 * (mf_real)e10[5] + w01 * (mf_real)e01[5] + w11 * (mf_real)e11[5];
    return mf_ltc_from_inverse(v[0], v[1], MF_R(1.0), v[2], v[3]);
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

/* float to IEEE binary16, round to nearest even (finite input) */
static unsigned short mf__half_bits(float f)
{
    union { float f; unsigned int u; } v;
    unsigned int sign, e, m, h;
    v.f = f;
    sign = (v.u >> 16) & 0x8000u;
    e = (v.u >> 23) & 0xffu;
    m = v.u & 0x7fffffu;
    if (e >= 143u) return (unsigned short)(sign | 0x7bffu);   /* >= 65536: the largest finite */
    if (e >= 113u) {                                           /* normal half */
        h = ((e - 112u) << 10) | (m >> 13);
        m &= 0x1fffu;
        if (m > 0x1000u || (m == 0x1000u && (h & 1u))) ++h;   /* may carry into the exponent: still right */
        if (h > 0x7bffu) h = 0x7bffu;
        return (unsigned short)(sign | h);
    }
    if (e < 102u) return (unsigned short)sign;                 /* below half the smallest subnormal */
    {   /* subnormal half: value = m' 2^-24 */
        unsigned int full = m | 0x800000u, shift = 126u - e, rem, half;
        h = full >> shift;
        rem = full & ((1u << shift) - 1u);
        half = 1u << (shift - 1u);
        if (rem > half || (rem == half && (h & 1u))) ++h;
        return (unsigned short)(sign | h);
    }
}

MFDEF mf_result mf_ltc_table_export_rgba16f(const float *data, int n_theta, int n_alpha, unsigned short *tex1,
                                            unsigned short *tex2)
{
    size_t i, n;
    int k;
    if (!data || !tex1 || !tex2 || n_theta < 2 || n_alpha < 2 || n_theta > 4096 || n_alpha > 4096)
        return MF_ERROR_INVALID_ARGUMENT;
    n = (size_t)n_theta * (size_t)n_alpha;
    for (i = 0; i < 6 * n; ++i)
        if (!mf__finite_bits((mf_real)data[i])) return MF_ERROR_INVALID_DATA;
    for (i = 0; i < n; ++i) {
        for (k = 0; k < 4; ++k) tex1[4 * i + (size_t)k] = mf__half_bits(data[6 * i + (size_t)k]);
        tex2[4 * i] = mf__half_bits(data[6 * i + 4]);
        tex2[4 * i + 1] = mf__half_bits(data[6 * i + 5]);
        tex2[4 * i + 2] = 0;
        tex2[4 * i + 3] = 0x3c00u;   /* 1.0 */
    }
    return MF_SUCCESS;
}

#ifndef MF_NO_LTC_TABLE
static const float *mf__ltc_ggx_data(int *n);   /* the built-in table: 14_ltc_table.h */
MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha)
{
    int n;
    const float *t = mf__ltc_ggx_data(&n);
    return mf__ltc_lookup(t, n, n, cos_theta_o, alpha, 0, 0);
}
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha)
{
    int n;
    const float *t = mf__ltc_ggx_data(&n);
    mf_real a;
    mf__ltc_lookup(t, n, n, cos_theta_o, alpha, &a, 0);
    return a;
}
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha)
{
    int n;
    const float *t = mf__ltc_ggx_data(&n);
    mf_real f;
    mf__ltc_lookup(t, n, n, cos_theta_o, alpha, 0, &f);
    return f;
}
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha)
{
    int n;
    const float *t = mf__ltc_ggx_data(&n);
    if (n_theta) *n_theta = n;
    if (n_alpha) *n_alpha = n;
    return t;
}
static const float *mf__ltc_beckmann_data(int *n);   /* 14_ltc_table_beckmann.h */
MFDEF mf_ltc mf_ltc_beckmann(mf_real cos_theta_o, mf_real alpha)
{
    int n;
    const float *t = mf__ltc_beckmann_data(&n);
    return mf__ltc_lookup(t, n, n, cos_theta_o, alpha, 0, 0);
}
MFDEF mf_real mf_ltc_beckmann_albedo(mf_real cos_theta_o, mf_real alpha)
{
    int n;
    const float *t = mf__ltc_beckmann_data(&n);
    mf_real a;
    mf__ltc_lookup(t, n, n, cos_theta_o, alpha, &a, 0);
    return a;
}
MFDEF mf_real mf_ltc_beckmann_fresnel(mf_real cos_theta_o, mf_real alpha)
{
    int n;
    const float *t = mf__ltc_beckmann_data(&n);
    mf_real f;
    mf__ltc_lookup(t, n, n, cos_theta_o, alpha, 0, &f);
    return f;
}
MFDEF const float *mf_ltc_beckmann_table(int *n_theta, int *n_alpha)
{
    int n;
    const float *t = mf__ltc_beckmann_data(&n);
    if (n_theta) *n_theta = n;
    if (n_alpha) *n_alpha = n;
    return t;
}
#endif
#ifndef MF_NO_LTC_TABLE
static const float *mf__ltc_ggx_data(int *n)
{
    static const float data[64 * 64 * 6] = {
1.00003f,-1.03307e-07f,0.000102365f,0.00200004f,1.0f,4.26386e-21f, 1.00091f,0.0224718f,0.000101101f,0.00200401f,1.0f,2.3843e-18f,
0.998023f,0.0448406f,6.27917e-05f,0.00200288f,1.0f,1.16261e-15f, 0.995508f,0.0671551f,2.57039e-05f,0.00200179f,1.0f,6.24941e-14f,
1.00102f,0.0901528f,0.000114675f,0.00202159f,1.0f,1.08813e-12f, 0.987625f,0.111377f,7.07283e-05f,0.00200823f,1.0f,1.00501e-11f,
0.987731f,0.133945f,4.87595e-05f,0.00201387f,1.0f,6.19597e-11f, 0.979506f,0.155355f,1.68967e-05f,0.00200783f,1.0f,2.88719e-10f,
0.9692f,0.176189f,-8.42079e-06f,0.00199992f,1.0f,1.0957e-09f, 0.960215f,0.197021f,-4.38914e-05f,0.00199182f,1.0f,3.55419e-09f,
0.952519f,0.217959f,-6.91942e-05f,0.00198718f,1.0f,1.01854e-08f, 0.944517f,0.238717f,-9.31453e-05f,0.0019823f,1.0f,2.6403e-08f,
0.931732f,0.258059f,-0.000120486f,0.00197049f,1.0f,6.30015e-08f, 0.918872f,0.277074f,-0.000146022f,0.00195888f,1.0f,1.40225e-07f,
0.907718f,0.296358f,-0.000168391f,0.00195044f,1.0f,2.94142e-07f, 0.893384f,0.314342f,-0.00019193f,0.0019373f,1.0f,5.86267e-07f,
0.881067f,0.332765f,-0.000212394f,0.00192801f,1.0f,1.11765e-06f, 0.889165f,0.359231f,-0.000210925f,0.00195489f,1.0f,2.04896e-06f,
0.870621f,0.375141f,-0.000240958f,0.00193636f,1.0f,3.6284e-06f, 0.852918f,0.39096f,-0.000261626f,0.00191943f,1.0f,6.22991e-06f,
0.834496f,0.405999f,-0.000281623f,0.00190236f,1.0f,1.04042e-05f, 0.815798f,0.420443f,-0.000300305f,0.00188532f,1.0f,1.6946e-05f,
0.774216f,0.421963f,-0.000327002f,0.00182698f,1.0f,2.69819e-05f, 0.796867f,0.458582f,-0.00032529f,0.00188776f,1.0f,4.20823e-05f,
0.771443f,0.468183f,-0.000336557f,0.00185959f,1.0f,6.44038e-05f, 0.71354f,0.456181f,-0.000351606f,0.00178223f,1.0f,9.68679e-05f,
0.67948f,0.457191f,-0.000385026f,0.00172769f,1.0f,0.000143383f, 0.696799f,0.49297f,-0.000375931f,0.00179519f,1.0f,0.000209115f,
0.679558f,0.505284f,-0.000398881f,0.00177099f,1.0f,0.000300825f, 0.65387f,0.510664f,-0.000402351f,0.001756f,1.0f,0.000427269f,
0.617212f,0.506144f,-0.0004022f,0.00171188f,1.0f,0.000599685f, 0.614175f,0.528679f,-0.000433753f,0.00171572f,1.0f,0.000832372f,
0.558948f,0.505015f,-0.000441735f,0.0016438f,1.0f,0.00114338f, 0.492374f,0.466919f,-0.000433881f,0.00151153f,1.0f,0.00155533f,
0.489792f,0.487531f,-0.000441069f,0.00153273f,1.0f,0.00209635f, 0.496991f,0.519373f,-0.000427177f,0.00160666f,1.0f,0.00280123f,
0.479991f,0.52683f,-0.000458076f,0.00157518f,1.0f,0.00371267f, 0.468431f,0.540264f,-0.000461957f,0.00157558f,1.0f,0.00488284f,
0.399189f,0.484126f,-0.000451602f,0.00143532f,1.0f,0.00637507f, 0.369829f,0.471981f,-0.000449788f,0.00139067f,1.0f,0.0082659f,
0.3563f,0.478945f,-0.000445213f,0.00140184f,1.0f,0.0106473f, 0.323889f,0.459105f,-0.000448427f,0.00133115f,1.0f,0.0136293f,
0.299804f,0.448709f,-0.00059716f,0.00107017f,0.999999f,0.0173429f, 0.274718f,0.434811f,-0.000440218f,0.0012526f,0.999999f,0.0219437f,
0.262796f,0.440636f,-0.000445115f,0.00125576f,0.999999f,0.0276152f, 0.240252f,0.427646f,-0.000563882f,0.000998409f,0.999999f,0.0345734f,
0.220304f,0.417287f,-0.000550119f,0.000973672f,0.999999f,0.0430717f, 0.200653f,0.405566f,-0.000431075f,0.00115677f,0.999999f,0.0534058f,
0.179259f,0.387888f,-0.000512912f,0.000917666f,0.999999f,0.0659202f, 0.157897f,0.367158f,-0.000486986f,0.000885473f,0.999999f,0.0810146f,
0.136708f,0.343129f,-0.000456341f,0.000851548f,0.999998f,0.0991513f, 0.118839f,0.323658f,-0.000456992f,0.000755872f,0.999998f,0.120864f,
0.102212f,0.303966f,-0.000455822f,0.00065378f,0.999998f,0.146765f, 0.0859353f,0.281189f,-0.000427978f,0.000607521f,0.999997f,0.17756f,
0.0704446f,0.256001f,-0.000397173f,0.000558313f,0.999997f,0.214052f, 0.0566235f,0.231232f,-0.000363953f,0.000515693f,0.999996f,0.257159f,
0.0440571f,0.205236f,-0.000330336f,0.000461407f,0.999995f,0.307928f, 0.0329437f,0.178579f,-0.000293398f,0.000411391f,0.999993f,0.367544f,
0.023385f,0.151606f,-0.000254479f,0.000360876f,0.999989f,0.43735f, 0.0151616f,0.122359f,-0.000235396f,0.000104845f,0.999984f,0.518862f,
0.0086389f,0.0924944f,-0.000185053f,1.634e-05f,0.999971f,0.613786f, 0.00393588f,0.0628204f,-0.000114507f,0.000184635f,0.999936f,0.724008f,
0.00086454f,0.0322501f,-9.85516e-05f,0.000142378f,0.999515f,0.851221f, 0.00178672f,0.0117216f,-0.000345678f,0.000202852f,0.892067f,0.874534f,
1.00003f,-1.03379e-07f,0.000102366f,0.00200004f,1.0f,4.26386e-21f, 1.00091f,0.0224718f,0.000101101f,0.00200401f,1.0f,2.3843e-18f,
0.998023f,0.0448406f,6.27917e-05f,0.00200288f,1.0f,1.16261e-15f, 0.995508f,0.0671551f,2.57039e-05f,0.00200179f,1.0f,6.24941e-14f,
1.00102f,0.0901528f,0.000114675f,0.00202159f,1.0f,1.08813e-12f, 0.987625f,0.111377f,7.07283e-05f,0.00200823f,1.0f,1.00501e-11f,
0.987731f,0.133945f,4.87595e-05f,0.00201387f,1.0f,6.19597e-11f, 0.979506f,0.155355f,1.68967e-05f,0.00200783f,1.0f,2.88719e-10f,
0.9692f,0.176189f,-8.42079e-06f,0.00199992f,1.0f,1.0957e-09f, 0.960215f,0.197021f,-4.38914e-05f,0.00199182f,1.0f,3.55419e-09f,
0.952519f,0.217959f,-6.91942e-05f,0.00198718f,1.0f,1.01854e-08f, 0.944517f,0.238717f,-9.31453e-05f,0.0019823f,1.0f,2.6403e-08f,
0.931732f,0.258059f,-0.000120486f,0.00197049f,1.0f,6.30015e-08f, 0.918872f,0.277074f,-0.000146022f,0.00195888f,1.0f,1.40225e-07f,
0.907718f,0.296358f,-0.000168391f,0.00195044f,1.0f,2.94142e-07f, 0.893384f,0.314342f,-0.00019193f,0.0019373f,1.0f,5.86267e-07f,
0.881067f,0.332765f,-0.000212394f,0.00192801f,1.0f,1.11765e-06f, 0.889165f,0.359231f,-0.000210925f,0.00195489f,1.0f,2.04896e-06f,
0.870621f,0.375141f,-0.000240958f,0.00193636f,1.0f,3.6284e-06f, 0.852918f,0.39096f,-0.000261626f,0.00191943f,1.0f,6.22991e-06f,
0.83449f,0.405996f,-0.000281608f,0.00190237f,1.0f,1.04042e-05f, 0.815798f,0.420443f,-0.000300305f,0.00188532f,1.0f,1.6946e-05f,
0.797384f,0.434582f,-0.000317514f,0.00186935f,1.0f,2.69819e-05f, 0.797863f,0.459156f,-0.00032506f,0.00188756f,1.0f,4.20823e-05f,
0.731037f,0.443674f,-0.000343185f,0.00179213f,1.0f,6.44038e-05f, 0.71354f,0.456181f,-0.000351606f,0.00178223f,1.0f,9.68679e-05f,
0.680336f,0.457756f,-0.000384602f,0.00172882f,1.0f,0.000143383f, 0.696799f,0.49297f,-0.000375931f,0.00179519f,1.0f,0.000209115f,
0.679734f,0.505416f,-0.000398782f,0.00177085f,1.0f,0.000300825f, 0.654027f,0.510798f,-0.000413846f,0.00174456f,1.0f,0.000427269f,
0.629392f,0.516127f,-0.000420612f,0.0017227f,1.0f,0.000599685f, 0.61081f,0.525785f,-0.000429362f,0.00171211f,1.0f,0.000832372f,
0.590858f,0.533818f,-0.00043726f,0.00169879f,1.0f,0.00114338f, 0.492477f,0.467017f,-0.000433896f,0.00151176f,1.0f,0.00155533f,
0.489574f,0.48732f,-0.000441034f,0.00153224f,1.0f,0.00209635f, 0.502232f,0.524819f,-0.00043252f,0.00161134f,1.0f,0.00280123f,
0.492797f,0.540882f,-0.000458716f,0.00160179f,1.0f,0.00371267f, 0.468308f,0.540121f,-0.000462078f,0.00157558f,1.0f,0.00488284f,
0.399189f,0.484126f,-0.000451602f,0.00143532f,1.0f,0.00637507f, 0.369829f,0.471981f,-0.000449788f,0.00139067f,1.0f,0.0082659f,
0.348069f,0.467886f,-0.0004502f,0.00136524f,1.0f,0.0106473f, 0.374166f,0.530332f,-0.000474219f,0.00148625f,1.0f,0.0136293f,
0.299804f,0.448709f,-0.000597161f,0.00107017f,0.999999f,0.0173429f, 0.280266f,0.443576f,-0.000454902f,0.00125687f,0.999999f,0.0219437f,
0.262796f,0.440635f,-0.000445115f,0.00125576f,0.999999f,0.0276152f, 0.240049f,0.427285f,-0.000563515f,0.000997825f,0.999999f,0.0345734f,
0.220306f,0.41729f,-0.000550125f,0.00097368f,0.999999f,0.0430717f, 0.200656f,0.405572f,-0.000431079f,0.00115678f,0.999999f,0.0534058f,
0.179259f,0.387889f,-0.000512907f,0.000917664f,0.999999f,0.0659202f, 0.156597f,0.364138f,-0.000480477f,0.000888551f,0.999999f,0.0810146f,
0.136739f,0.343207f,-0.000456591f,0.00085176f,0.999998f,0.0991513f, 0.11882f,0.323607f,-0.000457356f,0.000754646f,0.999998f,0.120864f,
0.102212f,0.303965f,-0.000455821f,0.000653779f,0.999998f,0.146765f, 0.0859353f,0.281189f,-0.000427978f,0.000607521f,0.999997f,0.17756f,
0.0704468f,0.256009f,-0.000397158f,0.000558311f,0.999997f,0.214052f, 0.0566249f,0.231237f,-0.000365132f,0.000510688f,0.999996f,0.257159f,
0.0440571f,0.205236f,-0.000330334f,0.000461406f,0.999995f,0.307928f, 0.0329438f,0.178579f,-0.000293396f,0.000411389f,0.999993f,0.367544f,
0.0233851f,0.151607f,-0.000254475f,0.000360912f,0.999989f,0.43735f, 0.0151615f,0.122359f,-0.000235405f,0.000104766f,0.999984f,0.518862f,
0.00863882f,0.0924935f,-0.000185043f,1.64266e-05f,0.999971f,0.613786f, 0.00388788f,0.0621012f,-0.000113459f,0.000182707f,0.999936f,0.724008f,
0.00086462f,0.0322543f,-9.85556e-05f,0.000142391f,0.999515f,0.851221f, 0.00183056f,0.0124785f,-0.000320799f,0.000352326f,0.892067f,0.874534f,
1.00003f,-1.052e-07f,0.000103166f,0.00201566f,1.0f,4.6087e-21f, 0.999531f,0.0224414f,0.000101115f,0.00201795f,1.0f,2.433e-18f,
0.998157f,0.0448466f,6.3364e-05f,0.00201869f,1.0f,1.16528e-15f, 0.998078f,0.0673277f,2.74533e-05f,0.00202074f,1.0f,6.25409e-14f,
0.999247f,0.0899934f,0.000112795f,0.00203492f,1.0f,1.08854e-12f, 0.987786f,0.111395f,7.15158e-05f,0.00202414f,1.0f,1.00524e-11f,
0.984578f,0.133519f,4.47155e-05f,0.00202505f,1.0f,6.19689e-11f, 0.979509f,0.155355f,1.70398e-05f,0.00202351f,1.0f,2.8875e-10f,
0.970517f,0.176427f,-1.48503e-05f,0.00201613f,1.0f,1.09579e-09f, 0.960053f,0.196987f,-4.29143e-05f,0.00200734f,1.0f,3.55441e-09f,
0.950578f,0.217516f,-7.18302e-05f,0.00199961f,1.0f,1.01859e-08f, 0.941236f,0.237889f,-9.76085e-05f,0.00199314f,1.0f,2.64041e-08f,
0.932701f,0.258327f,-0.000120468f,0.00198742f,1.0f,6.30037e-08f, 0.918812f,0.277056f,-0.000147217f,0.00197408f,1.0f,1.40229e-07f,
0.90882f,0.296717f,-0.000168756f,0.00196748f,1.0f,2.94149e-07f, 0.893435f,0.31436f,-0.000193387f,0.00195252f,1.0f,5.86279e-07f,
0.881065f,0.332765f,-0.000214054f,0.00194306f,1.0f,1.11767e-06f, 0.860332f,0.347591f,-0.00023913f,0.00191986f,1.0f,2.04899e-06f,
0.871276f,0.37543f,-0.000244451f,0.00195018f,1.0f,3.62845e-06f, 0.852922f,0.390961f,-0.000263664f,0.00193443f,1.0f,6.22999e-06f,
0.81202f,0.395072f,-0.000295638f,0.00187704f,1.0f,1.04043e-05f, 0.815244f,0.420152f,-0.000301932f,0.00190076f,1.0f,1.69462e-05f,
0.796681f,0.434194f,-0.00032077f,0.00188341f,1.0f,2.69822e-05f, 0.798538f,0.459544f,-0.00032748f,0.00190386f,1.0f,4.20826e-05f,
0.769165f,0.466799f,-0.000338599f,0.00187581f,1.0f,6.44043e-05f, 0.74f,0.473087f,-0.00036578f,0.00183535f,1.0f,9.68686e-05f,
0.717876f,0.483001f,-0.00037989f,0.0018116f,1.0f,0.000143383f, 0.699365f,0.494837f,-0.000386287f,0.00180224f,1.0f,0.000209116f,
0.679537f,0.505268f,-0.000402134f,0.00178468f,1.0f,0.000300827f, 0.635827f,0.496591f,-0.0004161f,0.00172421f,1.0f,0.000427271f,
0.612731f,0.502472f,-0.000423757f,0.00170046f,1.0f,0.000599687f, 0.612692f,0.527404f,-0.000432662f,0.00172937f,1.0f,0.000832375f,
0.590657f,0.533637f,-0.000439221f,0.00171271f,1.0f,0.00114338f, 0.538392f,0.510532f,-0.000555361f,0.00152044f,1.0f,0.00155533f,
0.491295f,0.489032f,-0.000444692f,0.00154795f,1.0f,0.00209636f, 0.475949f,0.497399f,-0.000449679f,0.00154122f,1.0f,0.00280123f,
0.493576f,0.541738f,-0.000461561f,0.00161436f,1.0f,0.00371268f, 0.452615f,0.522026f,-0.000464518f,0.00155434f,1.0f,0.00488285f,
0.399181f,0.484116f,-0.000455127f,0.00144651f,1.0f,0.00637509f, 0.369837f,0.471991f,-0.000453305f,0.00140156f,1.0f,0.00826591f,
0.349601f,0.469954f,-0.000453706f,0.00137726f,1.0f,0.0106473f, 0.325809f,0.461812f,-0.000457145f,0.0013397f,0.999999f,0.0136293f,
0.29562f,0.442453f,-0.00044549f,0.00129027f,0.999999f,0.017343f, 0.274644f,0.434694f,-0.000443595f,0.00126212f,0.999999f,0.0219437f,
0.282002f,0.472822f,-0.000463415f,0.00133349f,0.999999f,0.0276152f, 0.240048f,0.427283f,-0.000567937f,0.00100558f,0.999999f,0.0345735f,
0.220323f,0.417323f,-0.000554459f,0.000981344f,0.999999f,0.0430717f, 0.200674f,0.405608f,-0.000434468f,0.0011659f,0.999999f,0.0534058f,
0.178908f,0.38713f,-0.000515721f,0.000923347f,0.999999f,0.0659202f, 0.155903f,0.362527f,-0.000485501f,0.000884999f,0.999999f,0.0810146f,
0.137014f,0.343897f,-0.000460793f,0.000859323f,0.999998f,0.0991514f, 0.118884f,0.32378f,-0.000454931f,0.000777713f,0.999998f,0.120864f,
0.102217f,0.303979f,-0.000459396f,0.000658913f,0.999998f,0.146765f, 0.0863655f,0.282595f,-0.000433499f,0.000615576f,0.999997f,0.17756f,
0.0704501f,0.25602f,-0.000399856f,0.00056408f,0.999997f,0.214052f, 0.0575238f,0.234908f,-0.000372042f,0.000521958f,0.999996f,0.257159f,
0.0440537f,0.205219f,-0.000332521f,0.000466698f,0.999994f,0.307928f, 0.0329438f,0.178579f,-0.000295703f,0.000414614f,0.999993f,0.367543f,
0.0233853f,0.151614f,-0.000256352f,0.000363618f,0.999989f,0.437349f, 0.0151644f,0.122371f,-0.000230409f,0.000159734f,0.999983f,0.518861f,
0.00863887f,0.0924937f,-0.000186447f,1.69975e-05f,0.999971f,0.613784f, 0.00390317f,0.0622963f,-0.0001255f,7.70317e-06f,0.999935f,0.724004f,
0.000982422f,0.0346281f,-9.55023e-05f,0.00014598f,0.999487f,0.851188f, 0.00183963f,0.0126595f,-0.000316764f,0.000393184f,0.892164f,0.874482f,
1.00001f,-4.82423e-07f,0.0002317f,0.00453537f,1.0f,1.5205e-17f, 0.999736f,0.0224452f,0.000227633f,0.00454099f,1.0f,1.62772e-16f,
0.998154f,0.0448458f,0.000142424f,0.00454208f,1.0f,3.54341e-15f, 0.995555f,0.0671576f,5.82258e-05f,0.00453939f,1.0f,8.57956e-14f,
0.998194f,0.0898952f,0.000250032f,0.00457531f,1.0f,1.24324e-12f, 0.987735f,0.111388f,0.000160659f,0.00455421f,1.0f,1.08059e-11f,
0.987627f,0.133928f,0.000110078f,0.0045664f,1.0f,6.48598e-11f, 0.979491f,0.155349f,3.81947e-05f,0.00455291f,1.0f,2.9799e-10f,
0.970306f,0.176387f,-3.18616e-05f,0.00453616f,1.0f,1.12141e-09f, 0.960197f,0.197015f,-9.96777e-05f,0.00451659f,1.0f,3.61788e-09f,
0.950551f,0.217508f,-0.000162194f,0.00449917f,1.0f,1.03294e-08f, 0.940216f,0.23763f,-0.000221514f,0.00447998f,1.0f,2.67051e-08f,
0.933856f,0.258643f,-0.00026844f,0.00447574f,1.0f,6.35961e-08f, 0.921721f,0.277928f,-0.000325145f,0.00445216f,1.0f,1.41334e-07f,
0.909002f,0.296772f,-0.000379302f,0.00442741f,1.0f,2.96118e-07f, 0.8952f,0.314977f,-0.000431891f,0.00439968f,1.0f,5.8965e-07f,
0.880499f,0.332546f,-0.000482518f,0.00436964f,1.0f,1.12324e-06f, 0.865143f,0.349529f,-0.000530741f,0.00433822f,1.0f,2.05791e-06f,
0.871279f,0.375425f,-0.00054346f,0.00439054f,1.0f,3.64235e-06f, 0.83241f,0.381561f,-0.000620308f,0.00427108f,1.0f,6.25109e-06f,
0.828173f,0.402885f,-0.000621347f,0.00429746f,1.0f,1.04356e-05f, 0.815893f,0.420476f,-0.000680802f,0.00427534f,1.0f,1.69918e-05f,
0.77777f,0.423893f,-0.000738308f,0.00415745f,1.0f,2.70473e-05f, 0.758992f,0.436793f,-0.000772569f,0.0041198f,1.0f,4.21741e-05f,
0.76787f,0.465964f,-0.00076423f,0.00422021f,1.0f,6.45306e-05f, 0.743161f,0.47509f,-0.000802077f,0.00414536f,0.999999f,9.70404e-05f,
0.717823f,0.482944f,-0.000854129f,0.00408234f,0.999999f,0.000143614f, 0.672216f,0.475604f,-0.00089124f,0.00393228f,0.999999f,0.000209422f,
0.648255f,0.482009f,-0.000914101f,0.00387601f,0.999999f,0.000301227f, 0.625518f,0.488538f,-0.000935135f,0.00382777f,0.999999f,0.000427789f,
0.630496f,0.517007f,-0.000952959f,0.00391009f,0.999999f,0.000600349f, 0.607016f,0.522494f,-0.000973188f,0.00386347f,0.999999f,0.000833213f,
0.562769f,0.508476f,-0.0010128f,0.00370168f,0.999999f,0.00114443f, 0.527013f,0.499749f,-0.000993149f,0.00359609f,0.999999f,0.00155664f,
0.513067f,0.510672f,-0.0010103f,0.00359779f,0.999999f,0.00209796f, 0.516f,0.53919f,-0.00103461f,0.00369159f,0.999999f,0.00280318f,
0.454931f,0.499332f,-0.00102106f,0.00342561f,0.999998f,0.00371503f, 0.468268f,0.540042f,-0.00104735f,0.0035716f,0.999998f,0.00488565f,
0.431083f,0.52275f,-0.00101776f,0.00350091f,0.999998f,0.0063784f, 0.415334f,0.529895f,-0.00106574f,0.00340979f,0.999998f,0.00826979f,
0.3944f,0.530094f,-0.00106794f,0.00339492f,0.999998f,0.0106518f, 0.373857f,0.529824f,-0.00107538f,0.00337193f,0.999997f,0.0136344f,
0.311157f,0.465682f,-0.00102744f,0.00302058f,0.999997f,0.0173487f, 0.285899f,0.452487f,-0.00101841f,0.00292925f,0.999997f,0.0219502f,
0.262731f,0.440519f,-0.00131436f,0.00233544f,0.999996f,0.0276222f, 0.241378f,0.429637f,-0.00128272f,0.00227162f,0.999996f,0.034581f,
0.218081f,0.413069f,-0.00123813f,0.00219184f,0.999995f,0.0430795f, 0.196851f,0.397876f,-0.00119486f,0.00212356f,0.999995f,0.0534136f,
0.176187f,0.381235f,-0.00114712f,0.00205685f,0.999994f,0.0659274f, 0.155689f,0.362017f,-0.00109149f,0.00198867f,0.999993f,0.0810206f,
0.136602f,0.34285f,-0.00103412f,0.00193006f,0.999992f,0.0991551f, 0.118771f,0.323456f,-0.0010368f,0.00171036f,0.99999f,0.120864f,
0.101287f,0.301197f,-0.00102747f,0.00147025f,0.999989f,0.14676f, 0.0860192f,0.281441f,-0.000972512f,0.0013798f,0.999986f,0.177546f,
0.0705313f,0.25629f,-0.000900247f,0.00127171f,0.999983f,0.214024f, 0.0569044f,0.232329f,-0.000830208f,0.00116256f,0.999978f,0.257113f,
0.0441408f,0.20559f,-0.00075028f,0.00104811f,0.999972f,0.307853f, 0.0328956f,0.178277f,-0.000664267f,0.000931315f,0.999962f,0.367424f,
0.0233409f,0.151266f,-0.000576255f,0.000816823f,0.999946f,0.437161f, 0.0150951f,0.121754f,-0.000475448f,0.000688403f,0.999915f,0.518557f,
0.00875221f,0.0935742f,-0.000376038f,0.000564712f,0.999849f,0.613261f, 0.00399166f,0.0634632f,-0.000260757f,0.000421918f,0.999201f,0.722591f,
0.00122025f,0.0393157f,-0.00021251f,3.9676e-05f,0.997003f,0.847012f, 0.00170134f,0.0123574f,-0.00059287f,0.00072273f,0.925506f,0.883569f,
1.00013f,-1.61871e-06f,0.000413867f,0.00806348f,1.0f,4.69449e-15f, 0.999651f,0.0224419f,0.000403705f,0.00807268f,1.0f,1.37807e-14f,
0.998194f,0.0448459f,0.000253917f,0.00807518f,1.0f,7.24701e-14f, 0.995652f,0.0671623f,0.00010317f,0.00807064f,1.0f,4.00409e-13f,
0.994866f,0.089593f,0.000423532f,0.00811558f,1.0f,2.49961e-12f, 0.991647f,0.11182f,0.000308205f,0.00811879f,1.0f,1.52112e-11f,
0.987665f,0.133926f,0.000195608f,0.0081184f,1.0f,7.85234e-11f, 0.979455f,0.155338f,6.74126e-05f,0.00809401f,1.0f,3.35911e-10f,
0.972435f,0.176766f,-4.63732e-05f,0.00807732f,1.0f,1.21686e-09f, 0.963006f,0.197584f,-0.0001634f,0.00804573f,1.0f,3.83863e-09f,
0.950732f,0.217545f,-0.00028706f,0.00799969f,1.0f,1.08041e-08f, 0.944377f,0.238672f,-0.000375977f,0.00798987f,1.0f,2.76636e-08f,
0.933275f,0.258475f,-0.000479472f,0.00795292f,1.0f,6.54292e-08f, 0.921406f,0.277826f,-0.000579148f,0.00791266f,1.0f,1.44678e-07f,
0.908133f,0.296482f,-0.000677248f,0.00786499f,1.0f,3.01968e-07f, 0.894345f,0.314668f,-0.000770484f,0.00781569f,1.0f,5.99515e-07f,
0.87943f,0.332135f,-0.000860888f,0.00776075f,0.999999f,1.13935e-06f, 0.885017f,0.357502f,-0.000904515f,0.00787546f,0.999999f,2.08344e-06f,
0.870986f,0.375263f,-0.000968537f,0.00780546f,0.999999f,3.68179e-06f, 0.83673f,0.383525f,-0.00104408f,0.00764346f,0.999999f,6.31058e-06f,
0.835937f,0.406659f,-0.00113192f,0.00767854f,0.999999f,1.05235e-05f, 0.815987f,0.420488f,-0.00120904f,0.00759932f,0.999999f,1.71189e-05f,
0.800094f,0.436012f,-0.00127499f,0.00755509f,0.999999f,2.7228e-05f, 0.798899f,0.459683f,-0.00130567f,0.00761179f,0.999999f,4.24266e-05f,
0.759042f,0.46067f,-0.00140003f,0.00739183f,0.999999f,6.48782e-05f, 0.740678f,0.473468f,-0.00145548f,0.00735002f,0.999998f,9.75121e-05f,
0.717441f,0.482656f,-0.00151865f,0.00725404f,0.999998f,0.000144245f, 0.689461f,0.487771f,-0.00157292f,0.00712567f,0.999998f,0.000210256f,
0.678619f,0.504416f,-0.00161358f,0.00713891f,0.999998f,0.000302316f, 0.65709f,0.51312f,-0.00164803f,0.00705171f,0.999997f,0.000429195f,
0.63034f,0.516837f,-0.00169497f,0.00695134f,0.999997f,0.000602146f, 0.60747f,0.52284f,-0.00167338f,0.00692051f,0.999997f,0.000835483f,
0.589761f,0.532744f,-0.00176306f,0.00683957f,0.999997f,0.00114728f, 0.532166f,0.504602f,-0.0017724f,0.00644713f,0.999996f,0.00156016f,
0.528208f,0.525678f,-0.00180874f,0.00654137f,0.999996f,0.00210228f, 0.471096f,0.492312f,-0.0017952f,0.00612028f,0.999996f,0.00280843f,
0.493942f,0.542056f,-0.00184442f,0.00645638f,0.999995f,0.00372135f, 0.423745f,0.488698f,-0.00181634f,0.00590082f,0.999995f,0.00489319f,
0.416075f,0.504542f,-0.00184831f,0.00597241f,0.999994f,0.0063873f, 0.413526f,0.527646f,-0.00188486f,0.00609094f,0.999993f,0.00828019f,
0.392112f,0.52679f,-0.00190944f,0.00603872f,0.999993f,0.0106638f, 0.372242f,0.527368f,-0.001928f,0.00598996f,0.999992f,0.0136482f,
0.351741f,0.526096f,-0.00190958f,0.00586024f,0.999991f,0.0173642f, 0.286819f,0.453912f,-0.00181336f,0.00522055f,0.99999f,0.0219674f,
0.2629f,0.440778f,-0.00179425f,0.00506276f,0.999989f,0.027641f, 0.240376f,0.427834f,-0.0022735f,0.00402591f,0.999987f,0.034601f,
0.218481f,0.4138f,-0.0022038f,0.00390141f,0.999985f,0.0431002f, 0.197879f,0.399905f,-0.00171994f,0.0046037f,0.999983f,0.0534341f,
0.176359f,0.381573f,-0.00204063f,0.0036587f,0.999981f,0.0659466f, 0.156419f,0.363673f,-0.0019477f,0.00354563f,0.999978f,0.0810365f,
0.138169f,0.346736f,-0.00185642f,0.00345413f,0.999974f,0.0991651f, 0.118817f,0.323536f,-0.00183967f,0.0030518f,0.99997f,0.120864f,
0.101814f,0.302713f,-0.00183263f,0.00262578f,0.999964f,0.146745f, 0.0863478f,0.282457f,-0.00173377f,0.00246154f,0.999956f,0.177508f,
0.0712519f,0.258839f,-0.00161507f,0.00227453f,0.999946f,0.213952f, 0.0568252f,0.231945f,-0.00147607f,0.00206515f,0.999932f,0.25699f,
0.044042f,0.205039f,-0.00133058f,0.00185773f,0.999911f,0.307654f, 0.033552f,0.181704f,-0.00120084f,0.00168645f,0.999878f,0.367111f,
0.0232337f,0.15043f,-0.00101868f,0.00144394f,0.999822f,0.436664f, 0.0153311f,0.123411f,-0.000863065f,0.00124493f,0.999421f,0.517535f,
0.00882335f,0.094075f,-0.000668343f,0.00100684f,0.99891f,0.61141f, 0.00397123f,0.062784f,-0.00045785f,0.000741755f,0.997643f,0.719257f,
0.00135426f,0.0419062f,-0.000346264f,0.000623578f,0.990212f,0.836244f, 1.293e-09f,0.0083316f,-0.00114259f,0.0010922f,0.952901f,0.880247f,
1.0003f,-4.18422e-06f,0.000642744f,0.012602f,1.0f,3.89588e-13f, 0.999816f,0.0224422f,0.000628142f,0.0126159f,1.0f,6.56917e-13f,
0.998228f,0.0448444f,0.000392943f,0.0126182f,1.0f,1.80124e-12f, 1.00594f,0.0678255f,0.000933491f,0.0127427f,1.0f,5.22028e-12f,
0.992534f,0.0893795f,0.000638452f,0.0126607f,1.0f,1.53391e-11f, 0.991588f,0.111804f,0.000480176f,0.0126854f,1.0f,4.75984e-11f,
0.984651f,0.133512f,0.000278593f,0.012658f,1.0f,1.55939e-10f, 0.979397f,0.155318f,0.00010406f,0.0126467f,1.0f,5.11501e-10f,
0.970324f,0.176376f,-8.94066e-05f,0.0125998f,1.0f,1.59536e-09f, 0.96353f,0.19768f,-0.000252551f,0.0125772f,1.0f,4.61574e-09f,
0.951587f,0.21773f,-0.000443021f,0.0125078f,0.999999f,1.23279e-08f, 0.94213f,0.238095f,-0.000604363f,0.0124644f,0.999999f,3.05268e-08f,
0.933127f,0.258421f,-0.000751232f,0.0124259f,0.999999f,7.06011e-08f, 0.921138f,0.277731f,-0.000907641f,0.0123619f,0.999999f,1.53689e-07f,
0.909551f,0.296928f,-0.00105089f,0.0123036f,0.999999f,3.17161e-07f, 0.896049f,0.315244f,-0.00119611f,0.0122302f,0.999999f,6.24373e-07f,
0.884831f,0.334132f,-0.0013191f,0.0121868f,0.999999f,1.17892e-06f, 0.889331f,0.359221f,-0.00136704f,0.0123079f,0.999998f,2.14488e-06f,
0.872135f,0.375738f,-0.0014712f,0.0122056f,0.999998f,3.775e-06f, 0.834824f,0.382633f,-0.00171429f,0.0118896f,0.999998f,6.44906e-06f,
0.834496f,0.405918f,-0.00177409f,0.0119818f,0.999998f,1.07252e-05f, 0.816516f,0.420741f,-0.00184364f,0.0118905f,0.999997f,1.74077e-05f,
0.82715f,0.450647f,-0.00191216f,0.0121142f,0.999997f,2.76344e-05f, 0.796954f,0.458505f,-0.0020549f,0.0118857f,0.999997f,4.29899e-05f,
0.768191f,0.466096f,-0.00217786f,0.0116738f,0.999996f,6.56476e-05f, 0.71594f,0.457652f,-0.00229919f,0.0111981f,0.999996f,9.85488e-05f,
0.719061f,0.483697f,-0.00236623f,0.0113461f,0.999995f,0.000145625f, 0.699174f,0.494574f,-0.0024439f,0.0112483f,0.999995f,0.000212069f,
0.679377f,0.505028f,-0.00251492f,0.0111538f,0.999995f,0.000304672f, 0.654493f,0.511037f,-0.00258594f,0.0110049f,0.999994f,0.000432223f,
0.637348f,0.522499f,-0.00264454f,0.010956f,0.999993f,0.000605998f, 0.606867f,0.522198f,-0.00260251f,0.0108265f,0.999993f,0.000840334f,
0.58953f,0.532457f,-0.00275427f,0.0106823f,0.999992f,0.00115332f, 0.56061f,0.531437f,-0.00279312f,0.0104775f,0.999991f,0.00156763f,
0.538265f,0.535584f,-0.00283478f,0.0103636f,0.99999f,0.00211142f, 0.516802f,0.539885f,-0.00286791f,0.0102514f,0.999989f,0.00281951f,
0.496551f,0.544827f,-0.00288442f,0.0101255f,0.999988f,0.00373465f, 0.463673f,0.534588f,-0.00291841f,0.00988162f,0.999987f,0.00490902f,
0.433115f,0.525146f,-0.00292576f,0.0096174f,0.999985f,0.00640594f, 0.414025f,0.528173f,-0.00294116f,0.0095148f,0.999984f,0.00830193f,
0.354734f,0.47677f,-0.00285759f,0.00872267f,0.999982f,0.0106889f, 0.37409f,0.529961f,-0.00304468f,0.00928731f,0.99998f,0.0136767f,
0.355198f,0.531271f,-0.0030197f,0.00927421f,0.999978f,0.0173964f, 0.28997f,0.458828f,-0.00284626f,0.00822109f,0.999975f,0.022003f,
0.263119f,0.441085f,-0.00280434f,0.00791461f,0.999972f,0.0276798f, 0.240693f,0.428345f,-0.00355507f,0.00629587f,0.999968f,0.0346422f,
0.218607f,0.413982f,-0.0034243f,0.00613497f,0.999964f,0.0431428f, 0.197265f,0.398621f,-0.00332387f,0.00590656f,0.999959f,0.0534763f,
0.176587f,0.381998f,-0.00319177f,0.00572134f,0.999953f,0.0659857f, 0.156655f,0.364146f,-0.00304685f,0.00554485f,0.999946f,0.0810687f,
0.137044f,0.343797f,-0.00287907f,0.0053698f,0.999937f,0.099185f, 0.119134f,0.324303f,-0.00287226f,0.00479762f,0.999926f,0.120864f,
0.101829f,0.30265f,-0.00286268f,0.00410187f,0.999911f,0.146713f, 0.0858594f,0.280732f,-0.0026984f,0.00382579f,0.999892f,0.177429f,
0.0707977f,0.25704f,-0.00251315f,0.00353312f,0.999866f,0.213804f, 0.0569855f,0.232428f,-0.00231155f,0.00323431f,0.999827f,0.256738f,
0.0442557f,0.205833f,-0.00208585f,0.00291477f,0.999744f,0.307232f, 0.0329558f,0.17826f,-0.00184307f,0.00258588f,0.999292f,0.36622f,
0.023276f,0.15042f,-0.00158932f,0.00225488f,0.998989f,0.435266f, 0.0157488f,0.126345f,-0.00135886f,0.00197648f,0.998597f,0.51561f,
0.00895382f,0.0948002f,-0.00104657f,0.00158189f,0.997413f,0.608093f, 0.00415992f,0.0644392f,-0.000717651f,0.00117871f,0.994035f,0.712457f,
0.00297226f,0.0445263f,-0.000565843f,6.43351e-08f,0.976238f,0.815451f, 0.000274696f,0.0135892f,-0.00114329f,0.00138284f,0.96849f,0.861776f,
1.00056f,-8.84004e-06f,0.000921145f,0.018153f,1.0f,1.37998e-11f, 1.00019f,0.0224435f,0.000897009f,0.0181744f,1.0f,1.80909e-11f,
0.998522f,0.044851f,0.000558375f,0.0181765f,1.0f,3.3518e-11f, 0.996171f,0.0671785f,0.00119632f,0.0182333f,1.0f,6.8905e-11f,
0.993025f,0.0894105f,0.000923667f,0.0182387f,1.0f,1.43925e-10f, 0.991914f,0.111823f,0.000693671f,0.0182719f,1.0f,3.02215e-10f,
0.987509f,0.133875f,0.000434957f,0.0182655f,1.0f,6.47656e-10f, 0.979303f,0.155286f,0.000146808f,0.0182106f,0.999999f,1.4371e-09f,
0.970127f,0.176323f,-0.000132901f,0.0181435f,0.999999f,3.29428e-09f, 0.960729f,0.197094f,-0.000396394f,0.018075f,0.999999f,7.65765e-09f,
0.95147f,0.217686f,-0.000641596f,0.0180112f,0.999999f,1.76428e-08f, 0.946196f,0.239095f,-0.000829162f,0.0180012f,0.999999f,3.9592e-08f,
0.930744f,0.257744f,-0.00110466f,0.0178617f,0.999998f,8.5703e-08f, 0.922037f,0.277976f,-0.00130279f,0.0178171f,0.999998f,1.78279e-07f,
0.914183f,0.298396f,-0.00148298f,0.0177921f,0.999998f,3.56325e-07f, 0.922167f,0.324331f,-0.00152525f,0.0179989f,0.999997f,6.85448e-07f,
0.905678f,0.341925f,-0.00175504f,0.0178577f,0.999997f,1.27227e-06f, 0.888933f,0.359009f,-0.00197135f,0.017716f,0.999997f,2.28488e-06f,
0.849317f,0.365911f,-0.00230579f,0.0172228f,0.999996f,3.98121e-06f, 0.853009f,0.390875f,-0.00237196f,0.0174073f,0.999996f,6.74769e-06f,
0.834339f,0.405791f,-0.00255746f,0.017253f,0.999995f,1.11508e-05f, 0.812085f,0.418393f,-0.00275016f,0.0170528f,0.999994f,1.80051e-05f,
0.786278f,0.428426f,-0.00280274f,0.0168327f,0.999994f,2.84612e-05f, 0.798447f,0.459287f,-0.00294383f,0.0171235f,0.999993f,4.41188e-05f,
0.769071f,0.466526f,-0.00305557f,0.0168756f,0.999992f,6.71693e-05f, 0.739845f,0.472818f,-0.00329125f,0.0165109f,0.999991f,0.000100575f,
0.718862f,0.483505f,-0.00341468f,0.0163356f,0.999991f,0.000148293f, 0.689593f,0.48775f,-0.00353815f,0.0160321f,0.99999f,0.000215543f,
0.656033f,0.487669f,-0.00365451f,0.015652f,0.999988f,0.000309149f, 0.654492f,0.510946f,-0.00372272f,0.0158474f,0.999987f,0.000437933f,
0.630417f,0.516744f,-0.00381318f,0.0156393f,0.999986f,0.000613209f, 0.612969f,0.527385f,-0.00389077f,0.015562f,0.999985f,0.000849355f,
0.58941f,0.532256f,-0.00396383f,0.0153747f,0.999983f,0.00116451f, 0.560616f,0.531332f,-0.00404164f,0.0150662f,0.999981f,0.00158136f,
0.519311f,0.516906f,-0.00404412f,0.0145072f,0.999979f,0.00212814f, 0.503606f,0.52603f,-0.00410975f,0.0144835f,0.999977f,0.00283968f,
0.465184f,0.510387f,-0.00411855f,0.0139498f,0.999975f,0.00375877f, 0.45528f,0.525229f,-0.00418767f,0.0140508f,0.999972f,0.00493758f,
0.435609f,0.528126f,-0.00421062f,0.013888f,0.999969f,0.00643946f, 0.414175f,0.528228f,-0.00423383f,0.0137001f,0.999966f,0.00834085f,
0.395661f,0.531205f,-0.00425267f,0.0135648f,0.999962f,0.0107336f, 0.365369f,0.517782f,-0.00430421f,0.0132824f,0.999958f,0.0137275f,
0.355159f,0.531011f,-0.00434473f,0.0133455f,0.999953f,0.0174533f, 0.32843f,0.519286f,-0.00432421f,0.01297f,0.999948f,0.0220658f,
0.265944f,0.445689f,-0.00405386f,0.0114748f,0.999941f,0.0277479f, 0.244862f,0.435577f,-0.00517183f,0.00917342f,0.999934f,0.0347144f,
0.219747f,0.415991f,-0.00394824f,0.0107543f,0.999925f,0.043217f, 0.197839f,0.399665f,-0.0047964f,0.00852137f,0.999915f,0.0535493f,
0.176886f,0.382522f,-0.00460394f,0.00824112f,0.999902f,0.0660529f, 0.156947f,0.364685f,-0.00441218f,0.00794593f,0.999886f,0.0811234f,
0.13714f,0.343928f,-0.00414779f,0.00773434f,0.999866f,0.0992173f, 0.11901f,0.3238f,-0.00413425f,0.00689168f,0.999841f,0.12086f,
0.10187f,0.302577f,-0.00411994f,0.00590457f,0.999803f,0.146652f, 0.0866077f,0.282949f,-0.00390862f,0.00555027f,0.99969f,0.177254f,
0.0711176f,0.257946f,-0.00362315f,0.00510135f,0.999336f,0.213356f, 0.0569829f,0.232157f,-0.00331632f,0.00464649f,0.999123f,0.256017f,
0.0445565f,0.206878f,-0.00301227f,0.00421565f,0.99892f,0.306181f, 0.0330655f,0.178428f,-0.00265291f,0.00372541f,0.99866f,0.364922f,
0.0233601f,0.150434f,-0.00228418f,0.00324496f,0.997957f,0.433186f, 0.0152805f,0.12197f,-0.00188903f,0.00275833f,0.996853f,0.512201f,
0.00885984f,0.0928291f,-0.00146518f,0.00222435f,0.994412f,0.602332f, 0.00426508f,0.0645943f,-0.00101077f,0.00168589f,0.98734f,0.700967f,
0.00318424f,0.0482932f,-0.000685188f,0.00172865f,0.955301f,0.784166f, 0.00294783f,0.0368137f,-0.000762247f,0.00219601f,0.977647f,0.834944f,
1.00095f,-1.66414e-05f,0.0012433f,0.0247215f,1.0f,2.65246e-10f, 1.00044f,0.0224396f,0.00120703f,0.0247456f,1.0f,3.08067e-10f,
0.998908f,0.0448576f,0.000745101f,0.0247518f,1.0f,4.49918e-10f, 0.997155f,0.0672197f,0.00163882f,0.0248412f,1.0f,7.34082e-10f,
0.996198f,0.0896643f,0.00131297f,0.0248797f,1.0f,1.24455e-09f, 0.99456f,0.112086f,0.000987318f,0.0249174f,0.999999f,2.13064e-09f,
0.987369f,0.13383f,0.000585406f,0.0248601f,0.999999f,3.66172e-09f, 0.978783f,0.15518f,0.000216176f,0.0247831f,0.999999f,6.34752e-09f,
0.969973f,0.176272f,-0.000187259f,0.0246939f,0.999999f,1.11916e-08f, 0.961208f,0.197165f,-0.000536665f,0.0246126f,0.999998f,2.01939e-08f,
0.951978f,0.217773f,-0.000863313f,0.0245277f,0.999998f,3.72864e-08f, 0.941807f,0.237967f,-0.00118658f,0.0244281f,0.999997f,6.99786e-08f,
0.936243f,0.259213f,-0.00144346f,0.0244219f,0.999997f,1.32108e-07f, 0.924388f,0.278636f,-0.00175079f,0.0243001f,0.999996f,2.48241e-07f,
0.913024f,0.297979f,-0.00203227f,0.0241924f,0.999996f,4.60457e-07f, 0.922127f,0.324247f,-0.00207766f,0.0244956f,0.999995f,8.38466e-07f,
0.904756f,0.341496f,-0.00241313f,0.0243046f,0.999994f,1.49428e-06f, 0.888356f,0.358704f,-0.00268918f,0.0241051f,0.999994f,2.60295e-06f,
0.871079f,0.37514f,-0.00296652f,0.0239014f,0.999993f,4.43131e-06f, 0.853019f,0.390809f,-0.00322852f,0.0236907f,0.999992f,7.37696e-06f,
0.834473f,0.405782f,-0.00347822f,0.0234804f,0.999991f,1.20202e-05f, 0.815986f,0.420312f,-0.00370522f,0.0232755f,0.99999f,1.91926e-05f,
0.79619f,0.433703f,-0.00393457f,0.0230583f,0.999988f,3.00652e-05f, 0.762157f,0.438461f,-0.00419211f,0.0224964f,0.999987f,4.62622e-05f,
0.744965f,0.45192f,-0.0043753f,0.0223609f,0.999986f,7.00037e-05f, 0.740662f,0.473236f,-0.00447675f,0.0224895f,0.999984f,0.000104286f,
0.718244f,0.482965f,-0.00454924f,0.0222935f,0.999982f,0.000153103f, 0.698828f,0.494132f,-0.00479667f,0.0220447f,0.999981f,0.000221719f,
0.679779f,0.505123f,-0.00492349f,0.0218582f,0.999979f,0.000317006f, 0.654822f,0.511083f,-0.00506563f,0.0215644f,0.999976f,0.00044784f,
0.631532f,0.517523f,-0.00518762f,0.0213091f,0.999974f,0.000625591f, 0.612835f,0.527118f,-0.00529818f,0.021179f,0.999971f,0.000864698f,
0.566992f,0.511983f,-0.00536684f,0.0203116f,0.999968f,0.00118336f, 0.544436f,0.51592f,-0.00546337f,0.0201091f,0.999965f,0.00160433f,
0.539654f,0.536699f,-0.00547541f,0.0203628f,0.999962f,0.00215588f, 0.502948f,0.525185f,-0.00559123f,0.0196905f,0.999958f,0.00287291f,
0.474918f,0.52087f,-0.00572447f,0.0191709f,0.999953f,0.00379822f, 0.466955f,0.538081f,-0.00569596f,0.0193957f,0.999948f,0.00498401f,
0.443042f,0.536764f,-0.00573921f,0.0190976f,0.999943f,0.0064936f, 0.415466f,0.529369f,-0.00574349f,0.0186354f,0.999937f,0.00840337f,
0.377673f,0.507147f,-0.00575678f,0.0179546f,0.99993f,0.010805f, 0.374653f,0.530327f,-0.00583642f,0.018359f,0.999922f,0.0138082f,
0.353649f,0.528588f,-0.00591475f,0.0181274f,0.999913f,0.0175432f, 0.296349f,0.468572f,-0.00563135f,0.0163698f,0.999902f,0.0221644f,
0.264091f,0.442444f,-0.00550568f,0.0155509f,0.999889f,0.027854f, 0.241656f,0.429809f,-0.00698429f,0.0123712f,0.999875f,0.0348259f,
0.219778f,0.41592f,-0.00678049f,0.0119799f,0.999857f,0.0433305f, 0.19796f,0.399731f,-0.00652804f,0.0115994f,0.999834f,0.0536592f,
0.177267f,0.383143f,-0.00630453f,0.0111659f,0.9998f,0.0661498f, 0.157322f,0.365328f,-0.00600491f,0.010857f,0.999708f,0.0811791f,
0.138232f,0.346381f,-0.00567724f,0.0105717f,0.999419f,0.0991439f, 0.119846f,0.325762f,-0.00560355f,0.00954491f,0.999246f,0.120665f,
0.101957f,0.302512f,-0.00560323f,0.00803451f,0.9991f,0.146315f, 0.0865476f,0.28239f,-0.00530359f,0.00753601f,0.998959f,0.176763f,
0.0715004f,0.258915f,-0.00493984f,0.00696532f,0.998798f,0.212771f, 0.0575825f,0.234062f,-0.00454648f,0.00637726f,0.998565f,0.255178f,
0.0444113f,0.205498f,-0.00406698f,0.00569609f,0.998003f,0.304793f, 0.0334303f,0.179681f,-0.0036259f,0.00510185f,0.997394f,0.362805f,
0.0235128f,0.15055f,-0.00310044f,0.00441452f,0.996232f,0.43f, 0.015455f,0.122204f,-0.00256219f,0.00374023f,0.994078f,0.507083f,
0.00908623f,0.0934863f,-0.00197779f,0.00303097f,0.98944f,0.593548f, 0.00411734f,0.0623083f,-0.00136817f,0.00224756f,0.976768f,0.683747f,
0.0017867f,0.0492541f,-0.00098161f,0.0024385f,0.931933f,0.746048f, 0.00273009f,0.0349359f,-0.000952911f,0.0026587f,0.983365f,0.803594f,
1.00154f,-2.91672e-05f,0.0016031f,0.0323162f,1.0f,3.17746e-09f, 1.00106f,0.022437f,0.00154252f,0.0323465f,0.999999f,3.46814e-09f,
0.999731f,0.0448745f,0.000938432f,0.0323599f,0.999999f,4.39192e-09f, 0.997408f,0.0672108f,0.00213368f,0.0324588f,0.999999f,6.11107e-09f,
0.994682f,0.0895022f,0.00165991f,0.0324751f,0.999999f,8.92097e-09f, 0.994357f,0.112028f,0.00127563f,0.0325427f,0.999999f,1.3296e-08f,
0.989479f,0.134068f,0.000803512f,0.0325214f,0.999998f,1.99771e-08f, 0.978938f,0.155169f,0.000240075f,0.0323698f,0.999998f,3.0139e-08f,
0.970538f,0.176336f,-0.000240838f,0.032269f,0.999997f,4.57085e-08f, 0.962125f,0.197311f,-0.000690936f,0.0321717f,0.999997f,6.99542e-08f,
0.952817f,0.217921f,-0.00112841f,0.0320571f,0.999996f,1.08536e-07f, 0.943682f,0.238386f,-0.0015351f,0.0319522f,0.999995f,1.71292e-07f,
0.949287f,0.262708f,-0.00166786f,0.0322141f,0.999994f,2.75175e-07f, 0.926919f,0.279327f,-0.00225577f,0.0318069f,0.999994f,4.48865e-07f,
0.937448f,0.305611f,-0.00231767f,0.0322271f,0.999992f,7.39825e-07f, 0.922245f,0.324194f,-0.00270665f,0.0319968f,0.999991f,1.22472e-06f,
0.905546f,0.341711f,-0.00312339f,0.0317379f,0.99999f,2.02446e-06f, 0.888497f,0.358669f,-0.00351266f,0.0314767f,0.999989f,3.32533e-06f,
0.870945f,0.37499f,-0.0038721f,0.0312119f,0.999987f,5.40818e-06f, 0.852945f,0.390673f,-0.00421967f,0.0309381f,0.999986f,8.68793e-06f,
0.836635f,0.40672f,-0.00452282f,0.0307225f,0.999984f,1.3766e-05f, 0.815885f,0.42017f,-0.00484165f,0.0303889f,0.999982f,2.14994e-05f,
0.797081f,0.434081f,-0.00498414f,0.030194f,0.99998f,3.30896e-05f, 0.777491f,0.44709f,-0.00538591f,0.029836f,0.999978f,5.01964e-05f,
0.76818f,0.465764f,-0.00557521f,0.0298729f,0.999975f,7.50818e-05f, 0.739202f,0.47235f,-0.00583605f,0.029296f,0.999972f,0.00011079f,
0.718641f,0.483088f,-0.00606734f,0.0290404f,0.999969f,0.000161369f, 0.698862f,0.494002f,-0.00626465f,0.0287891f,0.999966f,0.000232145f,
0.673565f,0.500367f,-0.00645749f,0.0283693f,0.999963f,0.000330055f, 0.647887f,0.505543f,-0.006608f,0.0279562f,0.999959f,0.00046405f,
0.630668f,0.51664f,-0.00677482f,0.0277966f,0.999955f,0.000645576f, 0.600043f,0.515713f,-0.00692837f,0.0272591f,0.99995f,0.000889153f,
0.587097f,0.529801f,-0.00704016f,0.027237f,0.999945f,0.00121306f, 0.562393f,0.532675f,-0.0071245f,0.0268115f,0.999939f,0.00164012f,
0.538566f,0.535362f,-0.00725051f,0.0265185f,0.999933f,0.00219869f, 0.516038f,0.538552f,-0.00732355f,0.0261756f,0.999926f,0.0029237f,
0.491668f,0.538944f,-0.00737083f,0.0257293f,0.999919f,0.003858f, 0.464601f,0.535064f,-0.00746655f,0.0253087f,0.99991f,0.00505377f,
0.435018f,0.526842f,-0.0074503f,0.0246314f,0.9999f,0.00657426f, 0.414371f,0.527996f,-0.00752541f,0.0243527f,0.999889f,0.00849574f,
0.392913f,0.52716f,-0.00762391f,0.0241433f,0.999875f,0.0109097f, 0.375173f,0.530722f,-0.0076527f,0.0239203f,0.99986f,0.0139252f,
0.330131f,0.493478f,-0.00751787f,0.0224849f,0.99984f,0.017672f, 0.326244f,0.515552f,-0.00770945f,0.0230716f,0.999811f,0.0223027f,
0.264608f,0.443057f,-0.0071951f,0.0203333f,0.999746f,0.0279928f, 0.243738f,0.433107f,-0.00713584f,0.0198532f,0.999512f,0.0349208f,
0.225635f,0.426613f,-0.00901076f,0.0159551f,0.999354f,0.0433853f, 0.19851f,0.400541f,-0.00853209f,0.0151695f,0.99923f,0.0536697f,
0.177825f,0.384017f,-0.00819679f,0.0146966f,0.999123f,0.0661075f, 0.157871f,0.366233f,-0.00785937f,0.014174f,0.999018f,0.081084f,
0.142286f,0.35604f,-0.0076292f,0.0140637f,0.99891f,0.0990459f, 0.120633f,0.327441f,-0.0072328f,0.0128266f,0.998789f,0.120503f,
0.102478f,0.303557f,-0.00730414f,0.0106085f,0.998638f,0.146034f, 0.0879297f,0.286284f,-0.00700531f,0.00997942f,0.998287f,0.176227f,
0.071982f,0.260005f,-0.00646664f,0.00913234f,0.99788f,0.211875f, 0.0581173f,0.235468f,-0.00595929f,0.00837494f,0.997415f,0.253812f,
0.0444708f,0.205036f,-0.00529626f,0.00742294f,0.9966f,0.302791f, 0.0333779f,0.178353f,-0.00468929f,0.00660874f,0.9954f,0.359735f,
0.0237663f,0.150852f,-0.00403411f,0.00576539f,0.993394f,0.425324f, 0.0157476f,0.122755f,-0.00332749f,0.00487874f,0.989702f,0.499693f,
0.00945576f,0.0946672f,-0.00255264f,0.00397141f,0.981913f,0.581053f, 0.00425901f,0.0623356f,-0.00177395f,0.00293595f,0.962525f,0.660666f,
0.00201835f,0.0437585f,-0.00140667f,0.00261222f,0.911906f,0.706376f, 0.00171458f,0.0261026f,-0.00141452f,0.000804493f,0.987183f,0.769869f,
1.00238f,-4.74366e-05f,0.00198578f,0.0409488f,0.999999f,2.58836e-08f, 1.0018f,0.0224311f,0.00189355f,0.0409789f,0.999999f,2.7311e-08f,
1.00118f,0.0449001f,0.00114894f,0.0410077f,0.999998f,3.17469e-08f, 0.997713f,0.0671969f,0.00267917f,0.0410997f,0.999998f,3.96654e-08f,
1.00004f,0.0899194f,0.00226024f,0.0412468f,0.999998f,5.19018e-08f, 0.993998f,0.111946f,0.00158713f,0.0411833f,0.999997f,6.97301e-08f,
0.986797f,0.133675f,0.000926814f,0.0410854f,0.999997f,9.49996e-08f, 0.978643f,0.155078f,0.000282358f,0.0409625f,0.999996f,1.3037e-07f,
0.970462f,0.176275f,-0.000319917f,0.0408416f,0.999995f,1.79721e-07f, 0.962208f,0.197277f,-0.000885176f,0.0407232f,0.999994f,2.48866e-07f,
0.952965f,0.217899f,-0.00143535f,0.040578f,0.999993f,3.46751e-07f, 0.954728f,0.24103f,-0.00172184f,0.0407983f,0.999992f,4.87443e-07f,
0.958618f,0.265107f,-0.00195077f,0.0411036f,0.99999f,6.93294e-07f, 0.952852f,0.286894f,-0.00235579f,0.0410596f,0.999989f,9.99856e-07f,
0.937729f,0.305726f,-0.00289608f,0.0407834f,0.999987f,1.46326e-06f, 0.921608f,0.323855f,-0.00341122f,0.0404801f,0.999985f,2.17105e-06f,
0.901354f,0.340022f,-0.00395704f,0.0400807f,0.999983f,3.25766e-06f, 0.888382f,0.358501f,-0.00443108f,0.0398364f,0.999981f,4.92607e-06f,
0.870856f,0.374828f,-0.00491158f,0.0394911f,0.999979f,7.47753e-06f, 0.852818f,0.390485f,-0.00528432f,0.0391734f,0.999976f,1.13517e-05f,
0.834476f,0.405549f,-0.00575092f,0.0387994f,0.999973f,1.71796e-05f, 0.815743f,0.419957f,-0.00613136f,0.0384496f,0.99997f,2.58536e-05f,
0.797217f,0.434009f,-0.00648243f,0.0381187f,0.999967f,3.86165e-05f, 0.797085f,0.458036f,-0.00665086f,0.0384966f,0.999963f,5.71764e-05f,
0.76829f,0.465644f,-0.00705641f,0.0378044f,0.999959f,8.38508e-05f, 0.74064f,0.472903f,-0.00740101f,0.0371626f,0.999954f,0.000121747f,
0.718653f,0.482907f,-0.00768045f,0.0367464f,0.999949f,0.000174983f, 0.698864f,0.493798f,-0.00792944f,0.0364292f,0.999944f,0.000248964f,
0.678774f,0.504041f,-0.00794856f,0.0362529f,0.999938f,0.000350712f, 0.654704f,0.510588f,-0.00837773f,0.035636f,0.999932f,0.000489268f,
0.629203f,0.515153f,-0.00857975f,0.0352129f,0.999925f,0.000676172f, 0.612966f,0.526761f,-0.00875535f,0.0349972f,0.999917f,0.000926036f,
0.588297f,0.530599f,-0.00890799f,0.034509f,0.999908f,0.00125723f, 0.554056f,0.524489f,-0.00905359f,0.0336627f,0.999898f,0.00169265f,
0.53076f,0.527357f,-0.00916227f,0.0332115f,0.999886f,0.0022607f, 0.518164f,0.540489f,-0.00911798f,0.0332638f,0.999872f,0.00299631f,
0.491117f,0.538014f,-0.00931674f,0.0325417f,0.999854f,0.00394217f, 0.45722f,0.526343f,-0.0093777f,0.0315824f,0.999829f,0.00514992f,
0.436345f,0.528086f,-0.00944958f,0.0312122f,0.999779f,0.00668049f, 0.413575f,0.526989f,-0.00957955f,0.0307923f,0.999613f,0.00859625f,
0.383621f,0.514441f,-0.00952254f,0.0299209f,0.999439f,0.0109987f, 0.375716f,0.531011f,-0.00967553f,0.030271f,0.999325f,0.0140077f,
0.346731f,0.517357f,-0.00986978f,0.0291055f,0.999229f,0.0177473f, 0.329132f,0.518603f,-0.0096866f,0.0291421f,0.999143f,0.0223693f,
0.265129f,0.443547f,-0.00911459f,0.0257269f,0.999064f,0.0280535f, 0.244284f,0.433837f,-0.0116072f,0.0205885f,0.998982f,0.0350093f,
0.223571f,0.422135f,-0.00894734f,0.0244687f,0.998902f,0.043484f, 0.19919f,0.401498f,-0.0108144f,0.0192311f,0.998815f,0.0537627f,
0.178428f,0.384847f,-0.0103882f,0.0186275f,0.998719f,0.0661773f, 0.158436f,0.367025f,-0.0099224f,0.0180541f,0.998588f,0.0811024f,
0.143341f,0.357926f,-0.00963655f,0.0178209f,0.998318f,0.0989399f, 0.121422f,0.328915f,-0.00925919f,0.0161291f,0.997978f,0.120204f,
0.104323f,0.308239f,-0.0093753f,0.0135182f,0.997675f,0.145508f, 0.0876411f,0.284644f,-0.00880874f,0.0125524f,0.997237f,0.175428f,
0.0725912f,0.261248f,-0.00820629f,0.0116103f,0.996588f,0.210635f, 0.0587691f,0.237006f,-0.00756094f,0.0106566f,0.995708f,0.251899f,
0.0449768f,0.206097f,-0.00670673f,0.00942941f,0.994441f,0.299971f, 0.0341954f,0.181139f,-0.00598502f,0.0084755f,0.992494f,0.355527f,
0.0241542f,0.151401f,-0.00507959f,0.0073005f,0.989237f,0.418918f, 0.0161986f,0.123707f,-0.00417523f,0.00619706f,0.983393f,0.489654f,
0.0100233f,0.0965928f,-0.00317648f,0.00505667f,0.971718f,0.564595f, 0.00448106f,0.0623172f,-0.0022255f,0.00371429f,0.946075f,0.632811f,
0.00233153f,0.0465402f,-0.00174911f,0.00339896f,0.898569f,0.668629f, 0.00246016f,0.0325509f,-0.00129785f,0.00350971f,0.989821f,0.734956f,
1.00352f,-7.34806e-05f,0.00237868f,0.0506372f,0.999996f,1.52281e-07f, 1.00286f,0.0224224f,0.00224012f,0.0506597f,0.999996f,1.5759e-07f,
1.00143f,0.0448944f,0.00130053f,0.0506753f,0.999996f,1.73878e-07f, 1.00478f,0.0676427f,0.000531661f,0.0507995f,0.999996f,2.02254e-07f,
0.998921f,0.0897647f,0.0026808f,0.0509363f,0.999995f,2.44634e-07f, 0.993595f,0.111856f,0.00191933f,0.0508355f,0.999994f,3.03861e-07f,
0.986424f,0.133574f,0.00110549f,0.0507163f,0.999993f,3.83902e-07f, 0.978205f,0.154956f,0.000309686f,0.0505622f,0.999992f,4.90164e-07f,
0.970944f,0.176297f,-0.000402376f,0.0504454f,0.999991f,6.30022e-07f, 0.962855f,0.197336f,-0.0010951f,0.0503052f,0.999989f,8.13672e-07f,
0.960527f,0.219481f,-0.00158608f,0.0503986f,0.999987f,1.05552e-06f, 0.957137f,0.241512f,-0.00208182f,0.0504676f,0.999985f,1.37642e-06f,
0.958388f,0.264916f,-0.00242267f,0.0507248f,0.999983f,1.80708e-06f, 0.948348f,0.285396f,-0.00304081f,0.0505642f,0.999981f,2.39337e-06f,
0.936432f,0.305142f,-0.00366033f,0.0503334f,0.999978f,3.20405e-06f, 0.921458f,0.323651f,-0.00428093f,0.0499533f,0.999975f,4.34211e-06f,
0.904831f,0.341165f,-0.0049253f,0.0495615f,0.999972f,5.96073e-06f, 0.887684f,0.358054f,-0.00553325f,0.0491574f,0.999968f,8.28553e-06f,
0.870635f,0.374572f,-0.00594446f,0.0487918f,0.999964f,1.16449e-05f, 0.852403f,0.390124f,-0.00662143f,0.0483162f,0.99996f,1.65109e-05f,
0.834341f,0.405313f,-0.00709614f,0.0478906f,0.999955f,2.35526e-05f, 0.822495f,0.423185f,-0.00749017f,0.0477635f,0.99995f,3.37068e-05f,
0.800817f,0.435741f,-0.00796734f,0.0472151f,0.999944f,4.82679e-05f, 0.782663f,0.449652f,-0.00837077f,0.0468409f,0.999938f,6.90026e-05f,
0.768151f,0.465322f,-0.00871574f,0.0466549f,0.999931f,9.82941e-05f, 0.741887f,0.473452f,-0.00913085f,0.0459282f,0.999923f,0.000139321f,
0.718758f,0.482736f,-0.00947997f,0.045353f,0.999914f,0.000196279f, 0.698912f,0.493572f,-0.00978838f,0.0449629f,0.999903f,0.000274647f,
0.679029f,0.503879f,-0.0100732f,0.0445817f,0.99989f,0.000381504f, 0.654651f,0.510243f,-0.0103437f,0.043985f,0.999873f,0.000525894f,
0.630672f,0.516086f,-0.010587f,0.0434139f,0.999847f,0.000719178f, 0.613475f,0.526856f,-0.0107965f,0.043197f,0.999801f,0.000975074f,
0.587474f,0.529485f,-0.011f,0.0425561f,0.999681f,0.0013078f, 0.561353f,0.530977f,-0.0111608f,0.0418821f,0.99949f,0.00173815f,
0.540088f,0.536187f,-0.0112876f,0.0414116f,0.999378f,0.00230606f, 0.515517f,0.537279f,-0.011416f,0.0407994f,0.999288f,0.0030429f,
0.482845f,0.52852f,-0.0115137f,0.0397418f,0.999211f,0.00399096f, 0.463774f,0.533266f,-0.0116503f,0.0394557f,0.999141f,0.00520182f,
0.442103f,0.534508f,-0.0116844f,0.0388498f,0.999076f,0.00673846f, 0.415442f,0.528447f,-0.011744f,0.0380602f,0.999013f,0.00867622f,
0.393226f,0.526491f,-0.0119147f,0.0377273f,0.998952f,0.0111062f, 0.375628f,0.530262f,-0.0119308f,0.0373278f,0.998891f,0.0141361f,
0.347683f,0.518109f,-0.011916f,0.0363512f,0.99883f,0.0178945f, 0.32926f,0.518677f,-0.0118835f,0.0360545f,0.998763f,0.0225321f,
0.284058f,0.474184f,-0.0115862f,0.0334114f,0.998687f,0.0282263f, 0.243384f,0.431564f,-0.011118f,0.0308942f,0.998594f,0.0351841f,
0.221515f,0.418024f,-0.0138532f,0.02456f,0.99845f,0.04364f, 0.199919f,0.402377f,-0.0133657f,0.0237786f,0.998155f,0.0538453f,
0.179227f,0.385915f,-0.0128432f,0.0230393f,0.997914f,0.0661761f, 0.159277f,0.368226f,-0.0122699f,0.0223336f,0.997679f,0.0809989f,
0.140128f,0.349289f,-0.0116482f,0.0216821f,0.997387f,0.0987248f, 0.121021f,0.32697f,-0.0116556f,0.0188882f,0.996902f,0.119789f,
0.102725f,0.302609f,-0.0114067f,0.0163984f,0.996395f,0.144799f, 0.0884558f,0.286069f,-0.0108861f,0.0155589f,0.995654f,0.174285f,
0.0734168f,0.262908f,-0.0101518f,0.014409f,0.994712f,0.208931f, 0.0596094f,0.23886f,-0.00935683f,0.013239f,0.993355f,0.24936f,
0.0455021f,0.206731f,-0.00826164f,0.0116587f,0.991386f,0.296209f, 0.0342397f,0.179274f,-0.00726902f,0.0103344f,0.988382f,0.349939f,
0.0247238f,0.152295f,-0.0062295f,0.0090258f,0.983509f,0.410539f, 0.0168789f,0.125271f,-0.00509607f,0.00767784f,0.975048f,0.476797f,
0.0105321f,0.0975418f,-0.00387588f,0.00626439f,0.959302f,0.54442f, 0.0047688f,0.0618711f,-0.00272609f,0.00456719f,0.929574f,0.602007f,
0.00272774f,0.0474912f,-0.00212069f,0.00519494f,0.892223f,0.633824f, 0.00206141f,0.030647f,-0.00194002f,0.00484611f,0.991712f,0.699651f,
1.00503f,-0.000109032f,0.00276123f,0.0614055f,0.999989f,6.77482e-07f, 1.00489f,0.0224142f,0.00248144f,0.0614715f,0.999989f,6.93002e-07f,
1.00287f,0.0449133f,0.00141426f,0.0614313f,0.999989f,7.40263e-07f, 1.00082f,0.0673462f,0.00032215f,0.061402f,0.999988f,8.21385e-07f,
0.997453f,0.0895588f,0.00307217f,0.0616526f,0.999987f,9.40004e-07f, 0.992103f,0.111618f,0.00215629f,0.0615273f,0.999986f,1.10142e-06f,
0.985594f,0.133399f,0.00124381f,0.0613642f,0.999984f,1.31287e-06f, 0.978939f,0.154992f,0.000356402f,0.0612343f,0.999982f,1.58393e-06f,
0.971666f,0.176342f,-0.000500705f,0.0610866f,0.99998f,1.92712e-06f, 0.96331f,0.197343f,-0.0013432f,0.0608988f,0.999978f,2.35898e-06f,
0.954493f,0.218067f,-0.00215402f,0.0607066f,0.999975f,2.90158e-06f, 0.966459f,0.243621f,-0.00224028f,0.0615191f,0.999971f,3.585e-06f,
0.957407f,0.264475f,-0.0030083f,0.0613538f,0.999967f,4.45107e-06f, 0.950631f,0.285867f,-0.0036511f,0.0613101f,0.999963f,5.55885e-06f,
0.935798f,0.30475f,-0.00447159f,0.0608789f,0.999958f,6.99279e-06f, 0.919744f,0.322832f,-0.00529554f,0.0604223f,0.999952f,8.87423e-06f,
0.903165f,0.340313f,-0.0060653f,0.0599508f,0.999946f,1.13776e-05f, 0.887117f,0.357627f,-0.00673134f,0.0594553f,0.999938f,1.47522e-05f,
0.870047f,0.374116f,-0.00738819f,0.0589508f,0.999929f,1.93519e-05f, 0.852161f,0.389809f,-0.00801875f,0.0584426f,0.999918f,2.5672e-05f,
0.842789f,0.409099f,-0.00846589f,0.0583809f,0.999904f,3.43945e-05f, 0.829067f,0.426241f,-0.00896884f,0.0581365f,0.999884f,4.64333e-05f,
0.811642f,0.441243f,-0.00949757f,0.0577123f,0.999852f,6.29465e-05f, 0.796729f,0.457282f,-0.00995963f,0.0574483f,0.999793f,8.51855e-05f,
0.771276f,0.466869f,-0.0105121f,0.0566084f,0.999661f,0.000113708f, 0.747064f,0.476372f,-0.0109971f,0.0558463f,0.999471f,0.000151258f,
0.719004f,0.482563f,-0.0114644f,0.0548692f,0.999361f,0.000206968f, 0.699335f,0.493504f,-0.0118313f,0.0543976f,0.999274f,0.000284824f,
0.679838f,0.504235f,-0.0121595f,0.0539375f,0.999201f,0.000391692f, 0.655306f,0.510341f,-0.0125022f,0.053224f,0.999138f,0.000536753f,
0.632038f,0.516852f,-0.0127638f,0.0525213f,0.999081f,0.000731625f, 0.613976f,0.526807f,-0.0130528f,0.0522681f,0.999028f,0.000991008f,
0.588865f,0.530313f,-0.0132552f,0.0514589f,0.998978f,0.0013334f, 0.561837f,0.53093f,-0.0134924f,0.0506688f,0.99893f,0.00178191f,
0.540457f,0.536021f,-0.0136498f,0.0500997f,0.998885f,0.00236503f, 0.514409f,0.535558f,-0.0138163f,0.0492921f,0.99884f,0.00311766f,
0.488441f,0.534113f,-0.0138933f,0.0483318f,0.998793f,0.00408236f, 0.465141f,0.534349f,-0.0140175f,0.0476486f,0.998748f,0.00531161f,
0.442278f,0.534295f,-0.0141043f,0.0469379f,0.998697f,0.00686731f, 0.417489f,0.530349f,-0.0142187f,0.0461773f,0.998643f,0.00882527f,
0.395835f,0.529408f,-0.0143176f,0.0455924f,0.998582f,0.011275f, 0.375447f,0.529209f,-0.0144194f,0.045104f,0.998502f,0.0143221f,
0.354734f,0.527584f,-0.0145269f,0.0446196f,0.998376f,0.0180884f, 0.32738f,0.515115f,-0.014556f,0.0434058f,0.998131f,0.0227067f,
0.280133f,0.467235f,-0.0181928f,0.0329954f,0.997927f,0.02838f, 0.299074f,0.527411f,-0.0148095f,0.0435575f,0.997744f,0.0353127f,
0.232867f,0.438295f,-0.0173688f,0.0306658f,0.997554f,0.0437396f, 0.200865f,0.403496f,-0.016212f,0.0287958f,0.997315f,0.0539271f,
0.180181f,0.387074f,-0.0155606f,0.0279322f,0.996924f,0.0661624f, 0.16024f,0.369459f,-0.0148743f,0.0270831f,0.996528f,0.0808483f,
0.140989f,0.350327f,-0.0141122f,0.0262812f,0.996061f,0.0983838f, 0.121728f,0.327598f,-0.0136214f,0.0242072f,0.995399f,0.119192f,
0.103785f,0.304354f,-0.0138212f,0.0199373f,0.994607f,0.143819f, 0.0893911f,0.287558f,-0.0131873f,0.0189089f,0.993544f,0.172786f,
0.0739369f,0.262995f,-0.0122243f,0.0174996f,0.992111f,0.206673f, 0.0607845f,0.240792f,-0.0113196f,0.0161102f,0.990106f,0.246034f,
0.0460059f,0.20665f,-0.00993036f,0.0140758f,0.987235f,0.291354f, 0.0349551f,0.180167f,-0.00874371f,0.0125213f,0.982916f,0.342833f,
0.0255486f,0.153704f,-0.00747149f,0.0109512f,0.9761f,0.400057f, 0.0183484f,0.130775f,-0.00618351f,0.00955118f,0.964836f,0.461186f,
0.0109516f,0.0971058f,-0.00467209f,0.00757539f,0.945631f,0.521258f, 0.005136f,0.0604004f,-0.00329423f,0.0054654f,0.915043f,0.570139f,
0.0033042f,0.0446602f,-0.00277568f,0.00500228f,0.891472f,0.601605f, 0.00202066f,0.0289794f,-0.00254146f,0.00464988f,0.993115f,0.6645f,
1.00696f,-0.000158313f,0.00318205f,0.0732816f,0.999959f,2.36031e-06f, 1.00684f,0.0223996f,0.00266669f,0.0733544f,0.999959f,2.39674e-06f,
1.0046f,0.0449351f,0.00143919f,0.0732736f,0.999958f,2.50711e-06f, 1.00575f,0.0674983f,0.000231301f,0.0733683f,0.999956f,2.69458e-06f,
0.997628f,0.0894914f,0.00366275f,0.0733221f,0.999953f,2.96449e-06f, 0.992535f,0.11158f,0.00253088f,0.0732541f,0.999949f,3.32442e-06f,
0.987263f,0.133521f,0.0014701f,0.0731702f,0.999943f,3.78427e-06f, 0.980595f,0.155145f,0.000438209f,0.0729839f,0.999937f,4.35629e-06f,
0.972627f,0.176397f,-0.000615661f,0.0727728f,0.999928f,5.05492e-06f, 0.96437f,0.197438f,-0.00161662f,0.072559f,0.999916f,5.89614e-06f,
0.97317f,0.221957f,-0.00185329f,0.0733002f,0.9999f,6.89509e-06f, 0.966433f,0.24344f,-0.00271906f,0.0732099f,0.999876f,8.05914e-06f,
0.956674f,0.264086f,-0.00364842f,0.0729769f,0.999838f,9.36695e-06f, 0.940638f,0.282765f,-0.00465169f,0.0724113f,0.999774f,1.07066e-05f,
0.934836f,0.304193f,-0.0054078f,0.0724155f,0.999652f,1.16987e-05f, 0.920775f,0.322989f,-0.00625928f,0.071862f,0.999427f,1.15148e-05f,
0.903239f,0.340077f,-0.00722229f,0.071323f,0.99928f,1.24464e-05f, 0.887304f,0.35743f,-0.00800331f,0.0707383f,0.999178f,1.45536e-05f,
0.869261f,0.373355f,-0.00885788f,0.0701473f,0.999098f,1.79895e-05f, 0.852664f,0.389753f,-0.0095252f,0.0695329f,0.999033f,2.31997e-05f,
0.835153f,0.405171f,-0.010219f,0.0689576f,0.998977f,3.08717e-05f, 0.852997f,0.437828f,-0.0101815f,0.0706848f,0.998927f,4.19919e-05f,
0.828332f,0.44968f,-0.0108892f,0.0697815f,0.998884f,5.79666e-05f, 0.797826f,0.457491f,-0.0118059f,0.0683861f,0.998845f,8.06251e-05f,
0.768909f,0.465062f,-0.012524f,0.0671607f,0.998808f,0.000112483f, 0.7413f,0.472374f,-0.0131354f,0.0660216f,0.998774f,0.000156854f,
0.719361f,0.482383f,-0.0136307f,0.0652829f,0.998741f,0.000218071f, 0.69966f,0.493286f,-0.0140695f,0.064721f,0.998712f,0.000301907f,
0.679832f,0.503603f,-0.0144777f,0.0641731f,0.998681f,0.000415522f, 0.660279f,0.513641f,-0.0148539f,0.0636684f,0.998652f,0.000568426f,
0.631703f,0.515989f,-0.0152346f,0.0624668f,0.998622f,0.000772331f, 0.616684f,0.528492f,-0.0155209f,0.0624041f,0.99859f,0.00104217f,
0.587812f,0.528805f,-0.0157551f,0.0610993f,0.998558f,0.00139667f, 0.5629f,0.531376f,-0.0160085f,0.0602554f,0.998523f,0.0018589f,
0.54068f,0.535574f,-0.0162407f,0.0596071f,0.998484f,0.00245732f, 0.513541f,0.533971f,-0.0164306f,0.0585522f,0.998438f,0.0032267f,
0.489576f,0.534622f,-0.0165126f,0.0575976f,0.998378f,0.0042091f, 0.463155f,0.530797f,-0.0167379f,0.0566432f,0.998292f,0.00545452f,
0.449037f,0.541316f,-0.0168578f,0.0564647f,0.998141f,0.00701961f, 0.419975f,0.532629f,-0.0169106f,0.0550892f,0.997927f,0.00897647f,
0.396035f,0.52876f,-0.0172072f,0.0539367f,0.99777f,0.0114306f, 0.376106f,0.529109f,-0.0171358f,0.0536521f,0.99763f,0.0144837f,
0.364526f,0.540964f,-0.0173605f,0.0539463f,0.997482f,0.0182585f, 0.346209f,0.542677f,-0.0175322f,0.053662f,0.997313f,0.0229008f,
0.321021f,0.530484f,-0.0173146f,0.0520277f,0.997082f,0.0285746f, 0.246622f,0.43609f,-0.0203762f,0.037259f,0.996738f,0.0354665f,
0.223358f,0.419863f,-0.0201232f,0.035185f,0.996423f,0.0438409f, 0.202008f,0.404771f,-0.0195505f,0.0338757f,0.996061f,0.0539525f,
0.181344f,0.388467f,-0.0189031f,0.0325424f,0.995547f,0.0660796f, 0.161106f,0.370232f,-0.0181729f,0.0311408f,0.994991f,0.0806041f,
0.142348f,0.352278f,-0.0168428f,0.0313788f,0.994255f,0.0978828f, 0.122407f,0.327786f,-0.0160122f,0.0292719f,0.99337f,0.118371f,
0.103723f,0.302391f,-0.0163529f,0.0235196f,0.992207f,0.142516f, 0.0894141f,0.285604f,-0.0155568f,0.0223419f,0.990686f,0.170819f,
0.0757314f,0.267046f,-0.014666f,0.0210965f,0.988645f,0.203776f, 0.0617812f,0.242645f,-0.013525f,0.0193179f,0.985845f,0.241841f,
0.0469472f,0.207748f,-0.0117613f,0.0167883f,0.981869f,0.285309f, 0.0359684f,0.181554f,-0.0103266f,0.0149385f,0.97602f,0.334131f,
0.0267622f,0.155966f,-0.00878513f,0.0130959f,0.967137f,0.387522f, 0.0192887f,0.130972f,-0.00710232f,0.0112342f,0.953279f,0.443179f,
0.0111815f,0.0946687f,-0.0056029f,0.00895043f,0.931917f,0.496116f, 0.00569503f,0.0598387f,-0.00367161f,0.00872552f,0.903705f,0.538581f,
0.00435642f,0.046321f,-0.00320259f,0.00776814f,0.894446f,0.571213f, 0.002471f,0.0248441f,-0.00235467f,0.00571963f,0.994186f,0.629887f,
1.00765f,-0.000212989f,0.00371753f,0.0860524f,0.999203f,5.47751e-06f, 1.00739f,0.0223463f,0.00305556f,0.0861185f,0.99916f,5.40512e-06f,
1.00473f,0.0448755f,0.00169691f,0.0859638f,0.999018f,5.11695e-06f, 1.0009f,0.0672564f,0.000351663f,0.0857376f,0.998736f,4.36723e-06f,
0.998418f,0.0893662f,0.00440923f,0.0859942f,0.998465f,3.47317e-06f, 0.992896f,0.111458f,0.00309857f,0.0858408f,0.998367f,3.08984e-06f,
0.985844f,0.133194f,0.00174833f,0.0856372f,0.998315f,2.88129e-06f, 0.979373f,0.154814f,0.000515938f,0.0854749f,0.998284f,2.78983e-06f,
0.971737f,0.176094f,-0.000700472f,0.0852553f,0.998265f,2.80277e-06f, 0.964709f,0.197322f,-0.0018216f,0.085086f,0.998252f,2.92072e-06f,
0.955791f,0.218011f,-0.00295561f,0.0848054f,0.998244f,3.15799e-06f, 0.966944f,0.243286f,-0.00313246f,0.0858883f,0.998239f,3.54433e-06f,
0.961077f,0.26494f,-0.00411441f,0.0858525f,0.998236f,4.12061e-06f, 0.951656f,0.285656f,-0.00501563f,0.0855687f,0.998234f,4.95356e-06f,
0.936507f,0.304439f,-0.00619922f,0.0849661f,0.998232f,6.13588e-06f, 0.921269f,0.322837f,-0.00727142f,0.0843292f,0.998231f,7.81625e-06f,
0.904897f,0.340424f,-0.00833654f,0.0836691f,0.998231f,1.01901e-05f, 0.888102f,0.357422f,-0.00915584f,0.0830553f,0.99823f,1.35461e-05f,
0.87065f,0.373745f,-0.0100319f,0.0823914f,0.998229f,1.82912e-05f, 0.851741f,0.388918f,-0.0112391f,0.0815939f,0.998227f,2.49942e-05f,
0.8663f,0.419398f,-0.0112022f,0.0831867f,0.998225f,3.44421e-05f, 0.853187f,0.437431f,-0.0119358f,0.0829176f,0.998223f,4.77272e-05f,
0.828143f,0.44909f,-0.0128866f,0.08177f,0.998219f,6.63028e-05f, 0.798218f,0.457224f,-0.0138444f,0.0802216f,0.998214f,9.21307e-05f,
0.769078f,0.464687f,-0.0146911f,0.0787832f,0.998207f,0.000127818f, 0.741461f,0.471998f,-0.0154087f,0.0774469f,0.9982f,0.000176842f,
0.719639f,0.482064f,-0.0159889f,0.0765895f,0.99819f,0.000243645f, 0.69992f,0.492928f,-0.0165039f,0.0759279f,0.998176f,0.000334031f,
0.680062f,0.503191f,-0.0169829f,0.0752814f,0.99816f,0.000455455f, 0.655726f,0.509569f,-0.0174419f,0.0742717f,0.998136f,0.000617262f,
0.631799f,0.51541f,-0.0178506f,0.0733114f,0.998105f,0.000831346f, 0.615991f,0.527324f,-0.0181513f,0.0729626f,0.998057f,0.00111214f,
0.587643f,0.52792f,-0.0184959f,0.0716527f,0.99798f,0.00147723f, 0.563567f,0.531214f,-0.0187773f,0.0707187f,0.997838f,0.00194631f,
0.540303f,0.534376f,-0.0190382f,0.0698476f,0.997661f,0.00254853f, 0.512803f,0.533428f,-0.0192505f,0.0685853f,0.997539f,0.00332677f,
0.489209f,0.533332f,-0.0193718f,0.067445f,0.997429f,0.00432059f, 0.464704f,0.532151f,-0.0195303f,0.066359f,0.997322f,0.00558108f,
0.442256f,0.532245f,-0.0196802f,0.0654539f,0.997208f,0.00716916f, 0.421864f,0.533872f,-0.0198531f,0.0647913f,0.997076f,0.00915786f,
0.402473f,0.536029f,-0.0200238f,0.0642325f,0.9969f,0.0116315f, 0.377323f,0.529534f,-0.0200857f,0.0629841f,0.996634f,0.0146854f,
0.356139f,0.527204f,-0.0201916f,0.0621766f,0.996366f,0.0184548f, 0.347816f,0.54291f,-0.0205143f,0.0629317f,0.996109f,0.0230887f,
0.318386f,0.526221f,-0.0204184f,0.0610265f,0.995801f,0.028746f, 0.246666f,0.435018f,-0.0242613f,0.0429471f,0.995376f,0.0356067f,
0.275845f,0.513529f,-0.0205221f,0.0592607f,0.994929f,0.0439176f, 0.203373f,0.406174f,-0.0229566f,0.0398828f,0.994392f,0.053925f,
0.182598f,0.389682f,-0.0221984f,0.0383074f,0.993716f,0.0659121f, 0.162293f,0.371324f,-0.0213351f,0.0366524f,0.992909f,0.080218f,
0.142441f,0.350904f,-0.0210998f,0.03292f,0.991922f,0.0972065f, 0.124789f,0.332342f,-0.0205592f,0.0303939f,0.990664f,0.117268f,
0.106603f,0.308625f,-0.0193735f,0.0281895f,0.989061f,0.140832f, 0.0894749f,0.283214f,-0.0180577f,0.0259736f,0.986976f,0.168332f,
0.0743838f,0.259301f,-0.0167395f,0.0238668f,0.984212f,0.200181f, 0.0619374f,0.239417f,-0.0155563f,0.022129f,0.980457f,0.236705f,
0.0500539f,0.21718f,-0.0142183f,0.0202263f,0.975229f,0.278029f, 0.0374097f,0.183669f,-0.0119548f,0.0178399f,0.967762f,0.323861f,
0.0286633f,0.159965f,-0.0101298f,0.0155015f,0.956913f,0.37313f, 0.0205185f,0.13231f,-0.00826893f,0.0132724f,0.941099f,0.423342f,
0.011943f,0.0913729f,-0.00614275f,0.0100376f,0.91926f,0.470027f, 0.0064437f,0.0595704f,-0.00433968f,0.0103171f,0.895925f,0.508123f,
0.00526974f,0.046844f,-0.00377032f,0.00915551f,0.899549f,0.54208f, 0.00315385f,0.0257643f,-0.00273111f,0.00664288f,0.995023f,0.596087f,
1.00239f,-0.000231996f,0.00492045f,0.0988585f,0.996055f,4.61736e-07f, 1.00277f,0.0221689f,0.00461226f,0.0990529f,0.996055f,4.75647e-07f,
1.00102f,0.0446188f,0.00283824f,0.0990321f,0.996054f,5.18299e-07f, 1.00005f,0.0667807f,0.00663375f,0.0994134f,0.996052f,5.92504e-07f,
1.00029f,0.0892791f,0.00541863f,0.0996485f,0.996049f,7.0315e-07f, 0.994219f,0.111314f,0.00379605f,0.0994928f,0.996046f,8.57529e-07f,
0.987096f,0.133076f,0.0022088f,0.0992654f,0.996042f,1.06585e-06f, 0.979483f,0.154566f,0.000689596f,0.0990113f,0.996037f,1.342e-06f,
0.972302f,0.175926f,-0.00070489f,0.0987956f,0.996031f,1.70468e-06f, 0.963986f,0.196918f,-0.00207643f,0.0985066f,0.996025f,2.17907e-06f,
0.955027f,0.217595f,-0.00339545f,0.0981827f,0.996017f,2.79924e-06f, 0.958435f,0.240967f,-0.00400522f,0.0988386f,0.996008f,3.61163e-06f,
0.960939f,0.264628f,-0.00452078f,0.0993186f,0.99612f,4.72315e-06f, 0.953225f,0.28574f,-0.00565526f,0.0992181f,0.996292f,6.18657e-06f,
0.938329f,0.304664f,-0.00699918f,0.0985117f,0.996459f,8.10406e-06f, 0.922348f,0.32282f,-0.00826622f,0.0977947f,0.996607f,1.06488e-05f,
0.905631f,0.340294f,-0.00960679f,0.0970034f,0.996735f,1.40641e-05f, 0.888724f,0.357276f,-0.0107234f,0.0962289f,0.996845f,1.86839e-05f,
0.871201f,0.373567f,-0.0118755f,0.095401f,0.996938f,2.49674e-05f, 0.853502f,0.389399f,-0.0125944f,0.0946988f,0.997017f,3.35414e-05f,
0.867189f,0.419246f,-0.012959f,0.0964647f,0.997085f,4.5259e-05f, 0.853548f,0.437017f,-0.0138257f,0.0961054f,0.997141f,6.12649e-05f,
0.828803f,0.448836f,-0.0148923f,0.0948199f,0.997186f,8.30855e-05f, 0.798317f,0.456692f,-0.0160537f,0.0929885f,0.997218f,0.000112728f,
0.769849f,0.464553f,-0.0170048f,0.0913633f,0.997236f,0.000152787f, 0.741352f,0.471305f,-0.0178813f,0.0897728f,0.997235f,0.000206542f,
0.72012f,0.481753f,-0.0185194f,0.0887889f,0.997202f,0.000277957f, 0.700521f,0.492664f,-0.0191127f,0.0880282f,0.997115f,0.000371515f,
0.680764f,0.502989f,-0.0196614f,0.0872783f,0.996978f,0.000493948f, 0.657486f,0.510216f,-0.0201307f,0.0861049f,0.996895f,0.000659869f,
0.632602f,0.515234f,-0.0206677f,0.0850008f,0.996829f,0.00088006f, 0.616765f,0.527079f,-0.0210244f,0.0846058f,0.996768f,0.00116927f,
0.587417f,0.526796f,-0.0214186f,0.0829909f,0.996707f,0.00154616f, 0.563726f,0.530335f,-0.0217783f,0.0819919f,0.99664f,0.00203372f,
0.539273f,0.532724f,-0.0220546f,0.080823f,0.996561f,0.00266014f, 0.512311f,0.531198f,-0.0223079f,0.079394f,0.99646f,0.00345916f,
0.488896f,0.531897f,-0.0224269f,0.078064f,0.996316f,0.00447059f, 0.464669f,0.530946f,-0.022604f,0.0768204f,0.996092f,0.00573995f,
0.442832f,0.531676f,-0.0227804f,0.0758347f,0.995889f,0.00733842f, 0.423028f,0.533975f,-0.0229874f,0.0751097f,0.995695f,0.00933947f,
0.403692f,0.53616f,-0.0231746f,0.0744694f,0.995478f,0.0118261f, 0.379002f,0.530288f,-0.023257f,0.073087f,0.995199f,0.0148952f,
0.366117f,0.539888f,-0.0235837f,0.0734322f,0.994831f,0.0186606f, 0.333779f,0.521981f,-0.0239022f,0.0707726f,0.994468f,0.0232799f,
0.319799f,0.52647f,-0.0235706f,0.0706396f,0.994038f,0.0289054f, 0.249698f,0.438748f,-0.0281883f,0.0501695f,0.993491f,0.0357158f,
0.226392f,0.422754f,-0.0273897f,0.0481857f,0.992891f,0.0439448f, 0.205124f,0.407951f,-0.026633f,0.0464379f,0.992137f,0.0538183f,
0.183477f,0.389722f,-0.0256555f,0.0444288f,0.991249f,0.0656265f, 0.164712f,0.374855f,-0.0244381f,0.0437225f,0.990162f,0.0796707f,
0.144037f,0.352654f,-0.0247928f,0.0377257f,0.988815f,0.0962886f, 0.124893f,0.330149f,-0.0234919f,0.0352826f,0.987135f,0.115845f,
0.106558f,0.305543f,-0.0220931f,0.0327536f,0.985004f,0.138717f, 0.097302f,0.304928f,-0.021949f,0.0325546f,0.982254f,0.16527f,
0.0785169f,0.269759f,-0.0198793f,0.0286626f,0.978655f,0.195831f, 0.0651402f,0.247658f,-0.0183896f,0.0264258f,0.973843f,0.230597f,
0.0498178f,0.210868f,-0.0158074f,0.0226071f,0.96731f,0.269537f, 0.0396121f,0.187452f,-0.0138284f,0.020071f,0.958296f,0.312163f,
0.0315795f,0.166283f,-0.0116752f,0.0175623f,0.945825f,0.357228f, 0.0220167f,0.132567f,-0.00962233f,0.0155618f,0.928968f,0.402321f,
0.00966444f,0.0713997f,-0.00643319f,0.00923395f,0.908323f,0.443836f, 0.00689406f,0.0566718f,-0.0056079f,0.00875668f,0.891322f,0.479062f,
0.00619512f,0.0469713f,-0.00434287f,0.0105565f,0.905551f,0.513838f, 0.00378322f,0.0262037f,-0.00318354f,0.00771144f,0.995685f,0.563292f,
1.00683f,-0.00034808f,0.00516301f,0.114222f,0.99601f,1.32041e-06f, 1.00664f,0.0221526f,0.00437327f,0.114334f,0.99601f,1.35011e-06f,
1.00419f,0.0446735f,0.0024887f,0.114182f,0.996008f,1.4407e-06f, 1.00226f,0.0670898f,0.00089485f,0.114183f,0.996005f,1.59669e-06f,
0.99863f,0.089029f,0.00583806f,0.114354f,0.996001f,1.82584e-06f, 0.992611f,0.111072f,0.00400638f,0.114168f,0.995995f,2.13959e-06f,
0.986739f,0.132923f,0.00229861f,0.113987f,0.995989f,2.55367e-06f, 0.980088f,0.15452f,0.000660919f,0.113753f,0.995981f,3.08901e-06f,
0.972912f,0.175869f,-0.000926912f,0.113494f,0.995971f,3.77303e-06f, 0.964572f,0.196866f,-0.00249822f,0.113161f,0.99596f,4.64151e-06f,
0.969202f,0.22037f,-0.00316789f,0.113981f,0.995947f,5.74117e-06f, 0.975562f,0.244685f,-0.00371167f,0.11501f,0.995931f,7.13327e-06f,
0.956587f,0.263132f,-0.00571314f,0.113819f,0.995913f,8.8985e-06f, 0.951406f,0.284868f,-0.00673793f,0.113782f,0.995892f,1.11437e-05f,
0.936293f,0.303608f,-0.0083079f,0.112988f,0.995868f,1.40101e-05f, 0.920577f,0.321765f,-0.00979486f,0.112151f,0.995838f,1.76843e-05f,
0.905228f,0.339719f,-0.0110038f,0.111303f,0.995801f,2.24093e-05f, 0.888496f,0.356722f,-0.0122957f,0.110414f,0.995754f,2.84938e-05f,
0.871246f,0.373093f,-0.0136563f,0.109446f,0.995691f,3.6312e-05f, 0.853606f,0.388845f,-0.014591f,0.108604f,0.995604f,4.62771e-05f,
0.867681f,0.418809f,-0.0148225f,0.110656f,0.995476f,5.8764e-05f, 0.854193f,0.436597f,-0.0157931f,0.110247f,0.995287f,7.40408e-05f,
0.831195f,0.449304f,-0.0168547f,0.108996f,0.995142f,9.60688e-05f, 0.800373f,0.45705f,-0.0183099f,0.106799f,0.995028f,0.000126991f,
0.771582f,0.464779f,-0.0194161f,0.104893f,0.994927f,0.000169288f, 0.74508f,0.472789f,-0.0197777f,0.103597f,0.994832f,0.000226511f,
0.722053f,0.482466f,-0.0211251f,0.101925f,0.99474f,0.00030338f, 0.702302f,0.49419f,-0.0209237f,0.101573f,0.994647f,0.000405869f,
0.683885f,0.504389f,-0.022371f,0.100192f,0.994548f,0.000541604f, 0.659718f,0.510959f,-0.0229808f,0.098847f,0.99444f,0.000720092f,
0.636183f,0.517187f,-0.023525f,0.0975955f,0.994313f,0.000953084f, 0.619793f,0.528561f,-0.0239903f,0.097171f,0.994183f,0.00125473f,
0.592994f,0.530571f,-0.0244547f,0.0956148f,0.994074f,0.00164159f, 0.566575f,0.53183f,-0.0248455f,0.0940969f,0.993962f,0.0021378f,
0.542398f,0.534269f,-0.0251205f,0.0926859f,0.993893f,0.00277718f, 0.515736f,0.533134f,-0.0253925f,0.0910366f,0.993822f,0.00359193f,
0.49021f,0.531939f,-0.0256326f,0.0894935f,0.993726f,0.00462238f, 0.465681f,0.530622f,-0.0258503f,0.0880556f,0.99358f,0.00591614f,
0.45456f,0.543911f,-0.0261627f,0.0883431f,0.993352f,0.00752854f, 0.424966f,0.53469f,-0.0262891f,0.0862175f,0.993121f,0.00954026f,
0.405733f,0.537012f,-0.0265064f,0.0854675f,0.992866f,0.0120351f, 0.377657f,0.526544f,-0.0265239f,0.08334f,0.992535f,0.0151055f,
0.357916f,0.526066f,-0.0266682f,0.0824307f,0.99212f,0.0188664f, 0.33604f,0.521626f,-0.0284091f,0.0787063f,0.99167f,0.0234638f,
0.324709f,0.527969f,-0.0267741f,0.0808948f,0.991094f,0.0290399f, 0.302715f,0.520677f,-0.0272229f,0.0804019f,0.990442f,0.0357877f,
0.228546f,0.424694f,-0.0312526f,0.0558928f,0.989637f,0.043901f, 0.266368f,0.52316f,-0.0295969f,0.0757367f,0.988683f,0.0536195f,
0.209131f,0.439097f,-0.027401f,0.0648137f,0.987525f,0.065199f, 0.166941f,0.377168f,-0.0277938f,0.0511019f,0.986109f,0.0789247f,
0.158365f,0.382763f,-0.024788f,0.0591589f,0.984362f,0.0951051f, 0.12999f,0.340051f,-0.023035f,0.0533682f,0.982195f,0.114068f,
0.107609f,0.304413f,-0.0214224f,0.0485551f,0.979457f,0.136133f, 0.0958613f,0.296133f,-0.0245104f,0.0360294f,0.975969f,0.161604f,
0.0773309f,0.26111f,-0.0219679f,0.0319531f,0.97146f,0.19071f, 0.0610745f,0.228202f,-0.0194785f,0.028212f,0.965561f,0.223541f,
0.0523102f,0.214364f,-0.0179289f,0.0262041f,0.957767f,0.259925f, 0.0434527f,0.193923f,-0.0158992f,0.0234786f,0.947441f,0.299253f,
0.0337418f,0.168762f,-0.0133976f,0.0200901f,0.933924f,0.340233f, 0.0224546f,0.126736f,-0.010627f,0.0158236f,0.917099f,0.380738f,
0.0104391f,0.0699593f,-0.00731229f,0.0103516f,0.89912f,0.418134f, 0.00831649f,0.0585191f,-0.00657646f,0.00968528f,0.889126f,0.451439f,
0.00435876f,0.0353539f,-0.00557015f,0.00770825f,0.911692f,0.486366f, 0.00446478f,0.0265563f,-0.00369579f,0.00891162f,0.996209f,0.531638f,
1.01135f,-0.000471486f,0.00541106f,0.130819f,0.995874f,3.2778e-06f, 1.01114f,0.0221441f,0.00374262f,0.130918f,0.995873f,3.33257e-06f,
1.00781f,0.0447509f,0.0018098f,0.130564f,0.995868f,3.49869e-06f, 1.00595f,0.0672565f,-0.000482967f,0.130524f,0.99586f,3.78162e-06f,
0.999735f,0.088999f,0.00635552f,0.13036f,0.995848f,4.19042e-06f, 0.995135f,0.111124f,0.00446948f,0.130259f,0.995832f,4.73771e-06f,
0.98955f,0.133036f,0.002571f,0.130072f,0.995811f,5.43925e-06f, 0.98302f,0.154696f,0.000712053f,0.129811f,0.995783f,6.31308e-06f,
0.975527f,0.176061f,-0.0011055f,0.129472f,0.995747f,7.37733e-06f, 0.982136f,0.19986f,-0.00172628f,0.130501f,0.995699f,8.64551e-06f,
0.973358f,0.220997f,-0.00348216f,0.130128f,0.995634f,1.01167e-05f, 0.964951f,0.241986f,-0.00513585f,0.129805f,0.995544f,1.17564e-05f,
0.958307f,0.263268f,-0.00654239f,0.129683f,0.995418f,1.34623e-05f, 0.948919f,0.283753f,-0.00804518f,0.129314f,0.995239f,1.50122e-05f,
0.93423f,0.302518f,-0.00975886f,0.128423f,0.995056f,1.6868e-05f, 0.918776f,0.320668f,-0.0113867f,0.127488f,0.994938f,2.01208e-05f,
0.904253f,0.338885f,-0.0126575f,0.126518f,0.994842f,2.47146e-05f, 0.887684f,0.3559f,-0.0142257f,0.125465f,0.994757f,3.0987e-05f,
0.870591f,0.37228f,-0.0156345f,0.124415f,0.99468f,3.94575e-05f, 0.852777f,0.387882f,-0.0167902f,0.123433f,0.994606f,5.08546e-05f,
0.866861f,0.417725f,-0.0169407f,0.125727f,0.994533f,6.61344e-05f, 0.854198f,0.435869f,-0.0180007f,0.125317f,0.994459f,8.6604e-05f,
0.830419f,0.448159f,-0.0192219f,0.123811f,0.994381f,0.000113926f, 0.799695f,0.455919f,-0.020871f,0.121327f,0.994295f,0.000150271f,
0.771088f,0.463746f,-0.0221149f,0.119176f,0.994195f,0.000198399f, 0.744657f,0.471767f,-0.02318f,0.117296f,0.994076f,0.000261764f,
0.721822f,0.481147f,-0.0235529f,0.116157f,0.993922f,0.000344465f, 0.702606f,0.492328f,-0.024236f,0.115216f,0.993718f,0.000451455f,
0.683839f,0.503319f,-0.0254654f,0.113902f,0.993515f,0.000592323f, 0.659823f,0.509959f,-0.0261475f,0.112379f,0.993343f,0.000778846f,
0.636451f,0.516315f,-0.0267612f,0.110973f,0.993175f,0.00102226f, 0.619116f,0.526735f,-0.0272875f,0.110352f,0.992995f,0.00133728f,
0.595436f,0.531371f,-0.0277953f,0.10896f,0.992791f,0.0017419f, 0.568216f,0.532069f,-0.0281645f,0.106976f,0.992545f,0.00225764f,
0.542186f,0.532625f,-0.0285094f,0.105201f,0.992235f,0.00290998f, 0.515791f,0.531657f,-0.0288126f,0.103349f,0.991943f,0.00373991f,
0.49029f,0.530358f,-0.0290894f,0.101614f,0.991642f,0.00478714f, 0.483624f,0.54885f,-0.0294948f,0.102561f,0.991297f,0.00609809f,
0.464319f,0.553367f,-0.0297937f,0.101742f,0.990873f,0.00772691f, 0.435362f,0.545415f,-0.0299557f,0.0994383f,0.990433f,0.00975113f,
0.448499f,0.590276f,-0.0306385f,0.103757f,0.989951f,0.0122512f, 0.378898f,0.525845f,-0.0300672f,0.0946765f,0.989368f,0.0153157f,
0.360066f,0.526095f,-0.0303014f,0.0935699f,0.988744f,0.0190676f, 0.351995f,0.537231f,-0.0303841f,0.0940575f,0.988002f,0.023627f,
0.337313f,0.543009f,-0.0324235f,0.0903443f,0.987178f,0.0291528f, 0.321917f,0.547234f,-0.0325217f,0.0898504f,0.9862f,0.0358071f,
0.305977f,0.549746f,-0.0325221f,0.0891556f,0.985067f,0.043789f, 0.288332f,0.554807f,-0.0332699f,0.092664f,0.983737f,0.0533153f,
0.190658f,0.399571f,-0.0336882f,0.0592956f,0.982157f,0.0646246f, 0.169775f,0.380757f,-0.0323922f,0.0567474f,0.980269f,0.0779805f,
0.150746f,0.362976f,-0.0310971f,0.0544484f,0.977982f,0.0936578f, 0.128489f,0.332913f,-0.0306822f,0.0459237f,0.975184f,0.11194f,
0.11691f,0.322592f,-0.0290693f,0.0438238f,0.971722f,0.133097f, 0.0939189f,0.284988f,-0.026844f,0.0392751f,0.967402f,0.157366f,
0.0796237f,0.263003f,-0.0247401f,0.036459f,0.961943f,0.18489f, 0.0654443f,0.238237f,-0.0225675f,0.0333098f,0.955003f,0.215665f,
0.051714f,0.202165f,-0.0186007f,0.0281718f,0.946146f,0.249418f, 0.0478058f,0.203097f,-0.0172644f,0.0282193f,0.934929f,0.285482f,
0.0311288f,0.146841f,-0.0135796f,0.0201926f,0.92112f,0.322647f, 0.0189551f,0.10132f,-0.0103155f,0.0150278f,0.905388f,0.359167f,
0.0117179f,0.0710086f,-0.00845f,0.0119944f,0.891349f,0.393299f, 0.0100465f,0.0610469f,-0.00761544f,0.0110015f,0.888598f,0.425177f,
0.00411536f,0.0327236f,-0.00666392f,0.00880898f,0.917545f,0.459656f, 0.00262626f,0.0213505f,-0.00541117f,0.00706554f,0.99663f,0.501226f,
1.01462f,-0.000599219f,0.00574748f,0.148318f,0.994898f,6.03928e-06f, 1.01436f,0.0221051f,0.00324459f,0.148404f,0.994875f,6.04634e-06f,
1.0132f,0.0447645f,0.000796516f,0.148369f,0.994806f,6.04972e-06f, 1.00824f,0.0672908f,-0.00118927f,0.147718f,0.994684f,5.99203e-06f,
1.00139f,0.0888597f,0.00718574f,0.147334f,0.994498f,5.76462e-06f, 0.996465f,0.110976f,0.00500773f,0.147152f,0.994295f,5.44194e-06f,
0.990733f,0.132884f,0.00286962f,0.146911f,0.994205f,5.60613e-06f, 0.984111f,0.15454f,0.000774916f,0.146596f,0.994151f,6.06107e-06f,
0.976959f,0.175944f,-0.00124084f,0.146246f,0.994113f,6.78954e-06f, 0.968219f,0.196941f,-0.0032676f,0.145749f,0.994082f,7.81827e-06f,
0.97301f,0.220521f,-0.00408177f,0.146784f,0.994055f,9.20411e-06f, 0.963967f,0.241377f,-0.00595682f,0.146337f,0.994029f,1.10238e-05f,
0.961829f,0.263747f,-0.00723688f,0.146738f,0.994002f,1.33853e-05f, 0.947866f,0.283049f,-0.0092706f,0.145802f,0.993972f,1.64291e-05f,
0.933072f,0.301738f,-0.0112169f,0.144794f,0.993939f,2.03474e-05f, 0.917624f,0.319824f,-0.0129766f,0.143766f,0.993899f,2.53776e-05f,
0.901583f,0.337323f,-0.0148206f,0.142629f,0.993853f,3.18436e-05f, 0.885271f,0.35433f,-0.0164436f,0.141481f,0.993795f,4.01431e-05f,
0.868481f,0.370712f,-0.017576f,0.140464f,0.993722f,5.07817e-05f, 0.851877f,0.386852f,-0.0189666f,0.139242f,0.993627f,6.43721e-05f,
0.86506f,0.416072f,-0.019327f,0.141686f,0.993501f,8.16277e-05f, 0.853168f,0.434464f,-0.0204539f,0.141278f,0.993331f,0.000103341f,
0.828785f,0.446385f,-0.0219359f,0.139403f,0.99315f,0.000131774f, 0.798935f,0.454585f,-0.0236144f,0.136746f,0.993009f,0.000170856f,
0.77038f,0.462351f,-0.0250197f,0.134343f,0.992877f,0.00022298f, 0.743555f,0.470147f,-0.0261864f,0.132108f,0.992743f,0.000291827f,
0.722196f,0.480481f,-0.0271744f,0.13072f,0.992599f,0.000382185f, 0.703036f,0.491541f,-0.0280101f,0.129596f,0.992435f,0.000499968f,
0.683402f,0.501931f,-0.0287895f,0.128453f,0.992239f,0.000652359f, 0.659885f,0.508788f,-0.0295223f,0.126749f,0.991996f,0.000848045f,
0.636667f,0.515076f,-0.0301802f,0.125119f,0.991733f,0.00110043f, 0.613573f,0.520731f,-0.0307824f,0.123563f,0.991492f,0.00142758f,
0.591206f,0.52625f,-0.0312125f,0.122159f,0.991237f,0.00184646f, 0.569086f,0.531237f,-0.0317509f,0.120682f,0.990942f,0.00237844f,
0.547508f,0.535979f,-0.0321606f,0.119358f,0.990589f,0.00304918f, 0.526391f,0.540462f,-0.0325408f,0.118099f,0.990212f,0.00389514f,
0.505745f,0.544742f,-0.0328957f,0.116912f,0.989825f,0.00495873f, 0.485706f,0.548963f,-0.0332133f,0.115808f,0.989377f,0.00628365f,
0.444158f,0.527513f,-0.0332934f,0.111139f,0.98886f,0.00792618f, 0.44645f,0.556523f,-0.0338842f,0.113879f,0.988313f,0.0099598f,
0.400439f,0.525496f,-0.0336161f,0.107933f,0.987672f,0.0124567f, 0.379459f,0.523789f,-0.0338553f,0.106663f,0.986972f,0.0155163f,
0.394797f,0.573626f,-0.0368625f,0.109512f,0.986158f,0.01924f, 0.489725f,0.70739f,-0.0239775f,0.127694f,0.985247f,0.023758f,
0.352185f,0.562452f,-0.0360089f,0.107242f,0.984189f,0.0292076f, 0.323847f,0.5539f,-0.0364954f,0.105292f,0.982968f,0.0357521f,
0.31054f,0.56159f,-0.0387679f,0.100799f,0.981549f,0.0435733f, 0.299056f,0.561983f,-0.0364011f,0.104225f,0.97989f,0.052873f,
0.276493f,0.560442f,-0.0377126f,0.104746f,0.977928f,0.0638699f, 0.172545f,0.383761f,-0.0379506f,0.0613284f,0.975593f,0.0767999f,
0.154313f,0.365666f,-0.0349105f,0.0619138f,0.97279f,0.091907f, 0.135593f,0.346884f,-0.0350648f,0.0547341f,0.969396f,0.109432f,
0.112309f,0.311005f,-0.0325647f,0.0483482f,0.965257f,0.129598f, 0.0974222f,0.289134f,-0.0302041f,0.0447116f,0.960169f,0.152573f,
0.0832123f,0.266847f,-0.0277668f,0.0410733f,0.953872f,0.178431f, 0.0716912f,0.247827f,-0.0251177f,0.0379681f,0.946083f,0.207098f,
0.0617533f,0.230153f,-0.0223818f,0.0343587f,0.93648f,0.238241f, 0.0510563f,0.205924f,-0.0195551f,0.0320667f,0.924866f,0.2712f,
0.0362733f,0.159726f,-0.0160176f,0.0261049f,0.911461f,0.304924f, 0.0198215f,0.0969277f,-0.0111311f,0.0174478f,0.897613f,0.338079f,
0.0133037f,0.0717749f,-0.00974914f,0.0138442f,0.887338f,0.369637f, 0.0116401f,0.0622563f,-0.00876781f,0.0126824f,0.889922f,0.400258f,
0.00449583f,0.0317587f,-0.00773262f,0.0100862f,0.922905f,0.43377f, 0.00348553f,0.0219016f,-0.00624151f,0.00812652f,0.996969f,0.472122f,
1.01377f,-0.000730008f,0.00673887f,0.165799f,0.991797f,3.49105e-06f, 1.01349f,0.0219339f,0.00408649f,0.165903f,0.991795f,3.55751e-06f,
1.01081f,0.0445755f,0.00158037f,0.165573f,0.991789f,3.75958e-06f, 1.00502f,0.0662411f,0.0104549f,0.165043f,0.991779f,4.10547e-06f,
1.00133f,0.0885402f,0.00800989f,0.164958f,0.991763f,4.6091e-06f, 0.996733f,0.110671f,0.00557366f,0.164824f,0.991743f,5.29042e-06f,
0.991131f,0.132581f,0.0031839f,0.164581f,0.991723f,6.18149e-06f, 0.98474f,0.154259f,0.000837567f,0.164278f,0.991817f,7.40228e-06f,
0.977445f,0.175656f,-0.001453f,0.163885f,0.991939f,8.89735e-06f, 0.97105f,0.19694f,-0.00351958f,0.163617f,0.992051f,1.06912e-05f,
0.972057f,0.219796f,-0.0048072f,0.164337f,0.992138f,1.28399e-05f, 0.97291f,0.242878f,-0.00603706f,0.165082f,0.992195f,1.54047e-05f,
0.961076f,0.26306f,-0.008295f,0.164295f,0.992217f,1.84405e-05f, 0.947007f,0.282315f,-0.0105725f,0.163236f,0.992199f,2.1981e-05f,
0.932323f,0.300991f,-0.0127326f,0.162115f,0.992131f,2.60196e-05f, 0.917049f,0.319075f,-0.0147233f,0.160959f,0.992017f,3.0631e-05f,
0.901096f,0.336523f,-0.0165158f,0.159791f,0.991945f,3.73089e-05f, 0.884789f,0.35348f,-0.018539f,0.158436f,0.991888f,4.63347e-05f,
0.868375f,0.370317f,-0.02017f,0.157126f,0.991831f,5.82402e-05f, 0.852004f,0.386138f,-0.0217263f,0.155869f,0.991768f,7.38179e-05f,
0.847803f,0.407342f,-0.0223657f,0.156452f,0.991694f,9.41174e-05f, 0.851993f,0.432871f,-0.0230655f,0.15811f,0.991603f,0.000120464f,
0.827388f,0.444593f,-0.0245776f,0.156049f,0.991488f,0.000154528f, 0.798472f,0.453185f,-0.0260696f,0.153413f,0.991339f,0.000198325f,
0.76967f,0.460831f,-0.0281057f,0.150365f,0.991145f,0.000254292f, 0.742901f,0.468557f,-0.0294015f,0.147906f,0.990945f,0.000327467f,
0.722919f,0.479641f,-0.0304125f,0.14641f,0.990765f,0.000424153f, 0.70822f,0.493627f,-0.0312771f,0.145847f,0.990576f,0.000549925f,
0.684153f,0.500914f,-0.0322209f,0.143862f,0.990362f,0.000712135f, 0.671458f,0.515764f,-0.0329205f,0.143663f,0.99011f,0.000919964f,
0.637374f,0.514048f,-0.0337892f,0.140143f,0.989803f,0.00118438f, 0.617852f,0.522563f,-0.0344291f,0.138936f,0.989502f,0.00152417f,
0.596601f,0.529084f,-0.0349002f,0.137573f,0.989184f,0.00195709f, 0.57033f,0.530459f,-0.0355096f,0.135202f,0.988822f,0.00250402f,
0.548911f,0.535279f,-0.0359696f,0.133712f,0.988395f,0.00319036f, 0.545263f,0.55719f,-0.0364285f,0.135203f,0.987957f,0.004054f,
0.507366f,0.544006f,-0.036437f,0.131384f,0.987467f,0.00513153f, 0.487151f,0.548008f,-0.0371738f,0.129758f,0.986901f,0.00646743f,
0.467509f,0.551943f,-0.0375353f,0.128625f,0.986296f,0.00812244f, 0.461897f,0.564929f,-0.0363062f,0.129904f,0.985594f,0.0101561f,
0.443535f,0.569043f,-0.0363728f,0.128955f,0.984826f,0.0126504f, 0.414342f,0.568058f,-0.0394138f,0.124996f,0.983943f,0.0156892f,
0.384969f,0.555499f,-0.0398054f,0.121722f,0.98295f,0.0193789f, 0.368344f,0.560275f,-0.0401057f,0.121004f,0.981819f,0.023836f,
0.351963f,0.56492f,-0.0404513f,0.120487f,0.980518f,0.0291939f, 0.341752f,0.566647f,-0.0397427f,0.118856f,0.97902f,0.0356039f,
0.319965f,0.561029f,-0.0401135f,0.11727f,0.977287f,0.0432351f, 0.295352f,0.56203f,-0.041333f,0.117287f,0.975261f,0.0522702f,
0.29052f,0.570066f,-0.0406231f,0.116983f,0.972891f,0.0629112f, 0.17607f,0.386404f,-0.0408789f,0.0728768f,0.970086f,0.0753639f,
0.157175f,0.368982f,-0.0392546f,0.0699451f,0.96675f,0.0898405f, 0.139229f,0.350172f,-0.0395313f,0.0609394f,0.962759f,0.106543f,
0.120436f,0.324351f,-0.0369926f,0.0560635f,0.957962f,0.125644f, 0.103829f,0.295971f,-0.0326006f,0.0498605f,0.952174f,0.147261f,
0.0868872f,0.270246f,-0.0307821f,0.0462134f,0.945179f,0.171412f, 0.0741442f,0.242713f,-0.0261131f,0.0402075f,0.93676f,0.197967f,
0.0675055f,0.239635f,-0.0245061f,0.0390024f,0.926776f,0.226589f, 0.0522309f,0.197466f,-0.0216448f,0.0335955f,0.915286f,0.25667f,
0.0312239f,0.129235f,-0.0153645f,0.0230829f,0.902912f,0.287345f, 0.0203276f,0.0913322f,-0.0121138f,0.0187287f,0.891521f,0.317671f,
0.0153802f,0.072924f,-0.0110611f,0.0167456f,0.885438f,0.347132f, 0.0135373f,0.0622358f,-0.00871636f,0.0199291f,0.893105f,0.376585f,
0.00522325f,0.0313362f,-0.00884106f,0.0114493f,0.927674f,0.408787f, 0.00370982f,0.0200123f,-0.00657154f,0.00847491f,0.997244f,0.444364f,
1.01598f,-0.000599721f,0.00608925f,0.185409f,0.991047f,6.70898e-06f, 1.01531f,0.022087f,0.00342158f,0.185395f,0.991037f,6.7876e-06f,
1.01409f,0.0447417f,0.00029365f,0.185337f,0.991006f,7.02133e-06f, 1.01218f,0.0673149f,-0.00277819f,0.185198f,0.990952f,7.40279e-06f,
1.00647f,0.089402f,-0.00191707f,0.184181f,0.990872f,7.91609e-06f, 1.00064f,0.110667f,0.00612657f,0.184313f,0.990762f,8.53111e-06f,
0.994793f,0.132614f,0.00346598f,0.183985f,0.990615f,9.19498e-06f, 0.987874f,0.154276f,0.000859305f,0.18352f,0.990424f,9.8209e-06f,
0.982167f,0.175757f,-0.00127922f,0.183006f,0.99025f,1.07004e-05f, 0.973985f,0.196923f,-0.00389058f,0.182643f,0.990139f,1.22398e-05f,
0.970764f,0.218896f,-0.00570426f,0.18281f,0.990046f,1.43466e-05f, 0.972255f,0.242038f,-0.00697434f,0.183704f,0.989959f,1.70945e-05f,
0.960424f,0.262237f,-0.00941957f,0.18277f,0.989873f,2.06105e-05f, 0.946517f,0.28153f,-0.0119139f,0.181607f,0.989781f,2.50559e-05f,
0.93191f,0.300212f,-0.0142977f,0.180371f,0.98968f,3.06417e-05f, 0.916706f,0.318286f,-0.0165156f,0.179089f,0.989564f,3.76198e-05f,
0.90091f,0.335743f,-0.0186058f,0.177757f,0.989428f,4.62961e-05f, 0.884589f,0.352598f,-0.0207199f,0.176326f,0.989264f,5.70215e-05f,
0.868195f,0.369025f,-0.0225005f,0.174905f,0.989063f,7.01901e-05f, 0.852383f,0.385423f,-0.0241103f,0.173384f,0.988862f,8.67563e-05f,
0.835504f,0.400787f,-0.0251389f,0.172293f,0.98876f,0.000109138f, 0.853217f,0.432265f,-0.0255937f,0.176051f,0.988681f,0.000138424f,
0.828039f,0.443681f,-0.0273128f,0.173656f,0.9886f,0.00017638f, 0.799665f,0.452621f,-0.0290074f,0.170669f,0.988498f,0.000225259f,
0.773727f,0.46199f,-0.0309894f,0.167679f,0.988362f,0.000287879f, 0.75227f,0.473275f,-0.0323167f,0.165833f,0.988178f,0.000367621f,
0.728852f,0.481962f,-0.0336409f,0.163743f,0.987981f,0.000470735f, 0.709866f,0.493233f,-0.0346776f,0.162338f,0.987787f,0.000604685f,
0.685775f,0.50046f,-0.0357425f,0.160135f,0.987563f,0.000776427f, 0.661983f,0.507042f,-0.0367029f,0.158027f,0.987294f,0.000995007f,
0.63882f,0.513388f,-0.0375275f,0.156009f,0.986971f,0.00127193f, 0.618134f,0.520829f,-0.0382329f,0.154419f,0.986643f,0.00162535f,
0.596103f,0.526564f,-0.0388449f,0.152646f,0.986276f,0.00207211f, 0.571979f,0.529734f,-0.039464f,0.150522f,0.985841f,0.00263219f,
0.55108f,0.534983f,-0.039915f,0.14886f,0.985373f,0.00333541f, 0.529841f,0.539093f,-0.0404212f,0.147319f,0.984854f,0.0042131f,
0.509344f,0.543301f,-0.0408651f,0.145857f,0.984256f,0.00530135f, 0.497465f,0.557121f,-0.0404692f,0.147211f,0.983608f,0.00664946f,
0.478612f,0.561727f,-0.0405008f,0.145909f,0.982863f,0.00830678f, 0.443845f,0.546972f,-0.0428869f,0.139363f,0.982042f,0.0103402f,
0.42372f,0.54856f,-0.0433008f,0.137715f,0.981104f,0.0128194f, 0.407479f,0.551967f,-0.0435017f,0.136468f,0.980045f,0.0158304f,
0.388456f,0.556094f,-0.0440633f,0.135603f,0.97885f,0.0194715f, 0.371629f,0.560393f,-0.044434f,0.134824f,0.977487f,0.0238527f,
0.355455f,0.565179f,-0.0447922f,0.134247f,0.975924f,0.0290983f, 0.352149f,0.575389f,-0.0435464f,0.133216f,0.974131f,0.0353495f,
0.312253f,0.552771f,-0.0459658f,0.130302f,0.972064f,0.0427609f, 0.305597f,0.567346f,-0.0447786f,0.130308f,0.969662f,0.0514978f,
0.199778f,0.405786f,-0.0471415f,0.0848894f,0.966865f,0.0617399f, 0.194145f,0.418378f,-0.0475058f,0.0868741f,0.963586f,0.073668f,
0.161325f,0.372175f,-0.0435444f,0.0785399f,0.959731f,0.0874638f, 0.143764f,0.353328f,-0.0413398f,0.0751083f,0.955178f,0.10329f,
0.12779f,0.335746f,-0.0410807f,0.0640445f,0.94979f,0.121279f, 0.10784f,0.299071f,-0.0368759f,0.05663f,0.94342f,0.141505f,
0.0973658f,0.285984f,-0.0335364f,0.0527266f,0.935913f,0.163947f, 0.0853722f,0.265506f,-0.0269809f,0.0600411f,0.927156f,0.188449f,
0.0626418f,0.211116f,-0.0258376f,0.0397249f,0.917176f,0.214689f, 0.0542475f,0.193107f,-0.0234136f,0.0366065f,0.906291f,0.242149f,
0.0358124f,0.136732f,-0.0178713f,0.0271984f,0.895462f,0.27016f, 0.0197556f,0.0831755f,-0.013785f,0.0193844f,0.886873f,0.298095f,
0.0174663f,0.0742834f,-0.0127498f,0.0182963f,0.884838f,0.325776f, 0.00916496f,0.0440276f,-0.0107734f,0.014084f,0.896711f,0.354053f,
0.0062993f,0.0297421f,-0.00896836f,0.0114503f,0.932076f,0.384816f, 0.00537655f,0.0217234f,-0.00712822f,0.00934273f,0.997466f,0.41797f,
1.01618f,-0.000733193f,0.00684421f,0.205113f,0.987368f,5.50221e-06f, 1.01541f,0.0219294f,0.00400727f,0.20507f,0.987364f,5.59934e-06f,
1.01415f,0.044588f,0.000490212f,0.205023f,0.987444f,6.04501e-06f, 1.012f,0.0671802f,-0.00300551f,0.204854f,0.987615f,6.79391e-06f,
1.00752f,0.0893179f,-0.00339545f,0.203979f,0.987768f,7.68475e-06f, 1.0025f,0.110422f,0.00671224f,0.204389f,0.987889f,8.75194e-06f,
0.996663f,0.132362f,0.00376469f,0.204008f,0.987977f,1.00457e-05f, 0.990173f,0.1541f,0.000879953f,0.203607f,0.988031f,1.1617e-05f,
0.982635f,0.175525f,-0.00193953f,0.203061f,0.988052f,1.35144e-05f, 0.974098f,0.1966f,-0.00469506f,0.202392f,0.988037f,1.57804e-05f,
0.968817f,0.217818f,-0.00689312f,0.202182f,0.987985f,1.8449e-05f, 0.960512f,0.238731f,-0.0093092f,0.201643f,0.98789f,2.15379e-05f,
0.957587f,0.260821f,-0.010948f,0.201855f,0.987749f,2.50396e-05f, 0.945189f,0.280457f,-0.013533f,0.200821f,0.987617f,2.95987e-05f,
0.930666f,0.299141f,-0.0161443f,0.199471f,0.987511f,3.57695e-05f, 0.915517f,0.317201f,-0.0186066f,0.198055f,0.987403f,4.36918e-05f,
0.899788f,0.334609f,-0.0207307f,0.196658f,0.987283f,5.37391e-05f, 0.883534f,0.351422f,-0.0230399f,0.195094f,0.987145f,6.64014e-05f,
0.867997f,0.368156f,-0.024556f,0.193629f,0.986981f,8.22744e-05f, 0.851173f,0.383919f,-0.0263789f,0.19206f,0.986782f,0.000102084f,
0.862402f,0.411731f,-0.0271322f,0.195038f,0.98654f,0.00012669f, 0.85064f,0.4298f,-0.028636f,0.194447f,0.986312f,0.000158897f,
0.831453f,0.444459f,-0.0301422f,0.192192f,0.986085f,0.000200729f, 0.801983f,0.452739f,-0.0323587f,0.188685f,0.985839f,0.000254369f,
0.769366f,0.458114f,-0.0344897f,0.184687f,0.985562f,0.000322735f, 0.751321f,0.47086f,-0.0357875f,0.183173f,0.98524f,0.000409339f,
0.732771f,0.482777f,-0.037069f,0.181718f,0.984899f,0.000520227f, 0.710936f,0.492127f,-0.0383147f,0.179663f,0.984554f,0.000662825f,
0.687414f,0.499712f,-0.0394348f,0.177247f,0.984174f,0.000844036f, 0.663966f,0.506484f,-0.040472f,0.174933f,0.983739f,0.00107273f,
0.641167f,0.513008f,-0.0413582f,0.17271f,0.983283f,0.00136286f, 0.61965f,0.519783f,-0.0421321f,0.170752f,0.982795f,0.00172928f,
0.600835f,0.527922f,-0.0414645f,0.170552f,0.982242f,0.00218801f, 0.575437f,0.530105f,-0.0434861f,0.166773f,0.981654f,0.00276317f,
0.559276f,0.539573f,-0.0433266f,0.166689f,0.981008f,0.00347992f, 0.537793f,0.543634f,-0.0437499f,0.16502f,0.98029f,0.00436871f,
0.518761f,0.549721f,-0.0440737f,0.163657f,0.979541f,0.00546842f, 0.49155f,0.546274f,-0.0461587f,0.159045f,0.978738f,0.00682114f,
0.489693f,0.570082f,-0.0458985f,0.162579f,0.977856f,0.00847888f, 0.446758f,0.546442f,-0.0472094f,0.154286f,0.976882f,0.0105029f,
0.435365f,0.551182f,-0.044927f,0.155703f,0.975783f,0.0129607f, 0.450288f,0.591658f,-0.0458268f,0.156972f,0.974545f,0.0159337f,
0.392548f,0.556734f,-0.0484325f,0.15036f,0.973142f,0.0195127f, 0.375997f,0.561211f,-0.0488415f,0.149454f,0.971547f,0.0238014f,
0.366863f,0.563311f,-0.0476854f,0.147069f,0.969729f,0.0289163f, 0.35866f,0.577311f,-0.047527f,0.147619f,0.967642f,0.0349843f,
0.337772f,0.573322f,-0.0475288f,0.145107f,0.965248f,0.0421472f, 0.314573f,0.564633f,-0.0487675f,0.14409f,0.962482f,0.0505535f,
0.204472f,0.409329f,-0.0519985f,0.0948278f,0.959286f,0.0603614f, 0.284445f,0.570688f,-0.0501484f,0.144942f,0.955573f,0.0717265f,
0.166375f,0.375087f,-0.0480073f,0.0877528f,0.951257f,0.0848013f, 0.149717f,0.358289f,-0.0450067f,0.0840878f,0.946231f,0.0997166f,
0.134396f,0.339005f,-0.0446032f,0.0722327f,0.94039f,0.116571f, 0.121272f,0.321871f,-0.0379107f,0.0767333f,0.933627f,0.135403f,
0.109331f,0.304078f,-0.0335026f,0.0732177f,0.925867f,0.15617f, 0.0905652f,0.270723f,-0.0292836f,0.0674934f,0.917121f,0.178717f,
0.0642121f,0.205232f,-0.0285143f,0.0435667f,0.907571f,0.202752f, 0.0504644f,0.16834f,-0.0231064f,0.0357121f,0.897767f,0.227857f,
0.0325115f,0.116305f,-0.0180037f,0.0266336f,0.888911f,0.253549f, 0.0217601f,0.0834019f,-0.0156919f,0.0219461f,0.883322f,0.279435f,
0.0201592f,0.0767926f,-0.0146136f,0.021013f,0.885085f,0.305543f, 0.00960481f,0.0405312f,-0.0112685f,0.0145983f,0.900394f,0.33262f,
0.00736127f,0.0294103f,-0.00976931f,0.0124319f,0.93638f,0.361924f, 0.00602961f,0.0216764f,-0.00832757f,0.0105449f,0.997646f,0.39294f,
1.02106f,-0.000641418f,0.0050116f,0.227524f,0.985766f,9.01426e-06f, 1.02042f,0.0221161f,0.00156124f,0.227448f,0.985747f,9.0919e-06f,
1.01933f,0.0446529f,-0.000248244f,0.227468f,0.985691f,9.31917e-06f, 1.01651f,0.0672999f,-0.00398368f,0.227045f,0.985595f,9.67816e-06f,
1.01185f,0.0896695f,-0.0070145f,0.225835f,0.985457f,1.01359e-05f, 1.00515f,0.110165f,0.00702683f,0.225624f,0.985275f,1.06462e-05f,
0.999408f,0.132174f,0.00387427f,0.225229f,0.985154f,1.16639e-05f, 0.992317f,0.15383f,0.000826211f,0.224566f,0.985062f,1.31974e-05f,
0.984433f,0.175208f,-0.00215534f,0.223825f,0.984972f,1.52328e-05f, 0.975835f,0.196279f,-0.00519037f,0.223133f,0.984875f,1.78243e-05f,
0.967652f,0.217099f,-0.00799915f,0.2225f,0.984763f,2.10484e-05f, 0.959155f,0.237606f,-0.0105803f,0.221726f,0.984631f,2.49996e-05f,
0.95852f,0.26006f,-0.0121061f,0.222339f,0.984501f,2.97912e-05f, 0.944695f,0.279349f,-0.0151046f,0.220953f,0.984401f,3.5543e-05f,
0.930231f,0.298045f,-0.0179579f,0.219482f,0.98428f,4.23523e-05f, 0.915143f,0.316105f,-0.0205596f,0.217974f,0.984168f,5.10193e-05f,
0.899446f,0.333516f,-0.022999f,0.216411f,0.984074f,6.23499e-05f, 0.883221f,0.350281f,-0.0253024f,0.214796f,0.983969f,7.67064e-05f,
0.866747f,0.366509f,-0.02743f,0.213136f,0.983837f,9.47344e-05f, 0.873313f,0.392034f,-0.0282982f,0.215264f,0.983671f,0.000117262f,
0.87026f,0.414252f,-0.0290731f,0.215637f,0.983461f,0.000145277f, 0.844486f,0.425991f,-0.0315582f,0.212215f,0.983229f,0.000180869f,
0.827083f,0.440918f,-0.0330243f,0.210756f,0.983f,0.000226882f, 0.796739f,0.448448f,-0.0359705f,0.20666f,0.982742f,0.000285378f,
0.769842f,0.4568f,-0.0379979f,0.203318f,0.982443f,0.000359261f, 0.75224f,0.46975f,-0.039355f,0.201649f,0.982094f,0.000452346f,
0.733863f,0.481676f,-0.0407488f,0.200056f,0.981741f,0.000571614f, 0.71191f,0.490859f,-0.0421118f,0.197742f,0.981354f,0.000722695f,
0.688273f,0.498195f,-0.0433836f,0.195111f,0.98091f,0.000912669f, 0.665083f,0.505049f,-0.0445062f,0.192585f,0.980433f,0.00115256f,
0.642574f,0.511691f,-0.0454586f,0.190154f,0.979919f,0.00145464f, 0.626416f,0.522542f,-0.0457507f,0.189532f,0.979337f,0.00183182f,
0.602767f,0.526864f,-0.0464185f,0.187107f,0.978718f,0.00230424f, 0.591911f,0.541556f,-0.0462684f,0.188022f,0.978026f,0.00289103f,
0.571777f,0.548f,-0.0469504f,0.186257f,0.977275f,0.00361923f, 0.546138f,0.548503f,-0.0475066f,0.183211f,0.976438f,0.00451761f,
0.523889f,0.548212f,-0.0485421f,0.179491f,0.975526f,0.00562369f, 0.499213f,0.551082f,-0.0503353f,0.1761f,0.974509f,0.00697768f,
0.483079f,0.559019f,-0.0508529f,0.175056f,0.973385f,0.00862974f, 0.465031f,0.563645f,-0.0517179f,0.174084f,0.972139f,0.0106371f,
0.45012f,0.569738f,-0.0520967f,0.1731f,0.970749f,0.0130648f, 0.432755f,0.577495f,-0.0528102f,0.17255f,0.969195f,0.0159881f,
0.404983f,0.55729f,-0.051876f,0.165184f,0.967454f,0.0194923f, 0.38063f,0.561586f,-0.0534f,0.164803f,0.965497f,0.0236733f,
0.545627f,0.778122f,-0.0357393f,0.203174f,0.963292f,0.0286379f, 0.342452f,0.557444f,-0.0534604f,0.160067f,0.960795f,0.0345021f,
0.354235f,0.588473f,-0.0514366f,0.162434f,0.957962f,0.0413925f, 0.331215f,0.580647f,-0.0513096f,0.159009f,0.954739f,0.0494419f,
0.318819f,0.588278f,-0.0512996f,0.159028f,0.951063f,0.0587872f, 0.194273f,0.405324f,-0.0556078f,0.103436f,0.946863f,0.0695631f,
0.177431f,0.389556f,-0.0532357f,0.0998926f,0.94206f,0.081894f, 0.156765f,0.360901f,-0.0483236f,0.0930823f,0.936576f,0.0958856f,
0.144083f,0.346717f,-0.0447285f,0.0897855f,0.930336f,0.111607f, 0.13019f,0.328413f,-0.0373577f,0.0934759f,0.92329f,0.129076f,
0.117521f,0.313405f,-0.0364979f,0.0827249f,0.915445f,0.14824f, 0.0768505f,0.221283f,-0.0335918f,0.0514069f,0.906921f,0.168953f,
0.0638561f,0.188024f,-0.0280571f,0.0434642f,0.898046f,0.190975f, 0.0486257f,0.151634f,-0.0233814f,0.0358713f,0.889655f,0.213982f,
0.0329724f,0.109266f,-0.0192696f,0.028225f,0.883075f,0.237637f, 0.0245168f,0.0850094f,-0.0176729f,0.0247942f,0.880582f,0.26174f,
0.0228565f,0.0782755f,-0.0164271f,0.0236672f,0.885828f,0.286405f, 0.0116188f,0.0429718f,-0.0135723f,0.0174197f,0.903917f,0.312258f,
0.0096713f,0.0310865f,-0.0105265f,0.0137452f,0.940079f,0.340099f, 0.00744192f,0.0223353f,-0.0094934f,0.0119773f,0.99779f,0.36926f,
1.01892f,-0.000445168f,0.00476833f,0.249114f,0.982009f,9.25071e-06f, 1.01975f,0.022228f,0.00161338f,0.248997f,0.981997f,9.37778e-06f,
1.01899f,0.0446404f,-0.000200422f,0.24902f,0.981959f,9.76e-06f, 1.01793f,0.0670288f,-0.00334841f,0.248595f,0.981896f,1.04001e-05f,
1.01427f,0.0894633f,-0.00650469f,0.248122f,0.981866f,1.13753e-05f, 1.01045f,0.110346f,0.00756174f,0.248357f,0.981878f,1.26663e-05f,
1.00341f,0.132159f,0.00392718f,0.247725f,0.981865f,1.41855e-05f, 0.995347f,0.153638f,0.000406835f,0.246907f,0.98181f,1.59158e-05f,
0.987574f,0.175066f,-0.00290078f,0.246179f,0.981718f,1.79244e-05f, 0.978255f,0.196003f,-0.00579904f,0.244842f,0.98166f,2.07534e-05f,
0.968415f,0.216621f,-0.0088189f,0.243715f,0.981599f,2.43898e-05f, 0.958271f,0.23696f,-0.0120726f,0.242936f,0.981519f,2.89209e-05f,
0.954355f,0.258125f,-0.014072f,0.242852f,0.981412f,3.4487e-05f, 0.943403f,0.277972f,-0.0169867f,0.241872f,0.981271f,4.12535e-05f,
0.929144f,0.296666f,-0.0200496f,0.240286f,0.98109f,4.9412e-05f, 0.914287f,0.314742f,-0.0228415f,0.238663f,0.980868f,5.92385e-05f,
0.901505f,0.333106f,-0.0253909f,0.237406f,0.980659f,7.19873e-05f, 0.886024f,0.350217f,-0.0279632f,0.235592f,0.980441f,8.81323e-05f,
0.871782f,0.367318f,-0.0298151f,0.23424f,0.980197f,0.000108315f, 0.856246f,0.383656f,-0.0317274f,0.232417f,0.979917f,0.000133398f,
0.840514f,0.3996f,-0.0339197f,0.230386f,0.979591f,0.000164425f, 0.851157f,0.427534f,-0.0340287f,0.233746f,0.979264f,0.00020413f,
0.827209f,0.439207f,-0.0362677f,0.230777f,0.978919f,0.000254486f, 0.783633f,0.439837f,-0.0400671f,0.223441f,0.978535f,0.00031774f,
0.766098f,0.452977f,-0.0416435f,0.221544f,0.978108f,0.000396858f, 0.74791f,0.465298f,-0.0431587f,0.219609f,0.977717f,0.000497486f,
0.72922f,0.476734f,-0.0446722f,0.217771f,0.977313f,0.000624284f, 0.71051f,0.487662f,-0.0460753f,0.21599f,0.97686f,0.000782864f,
0.694674f,0.500212f,-0.0466574f,0.214952f,0.976386f,0.000982777f, 0.677231f,0.511344f,-0.0479757f,0.213274f,0.975864f,0.00123299f,
0.664936f,0.525795f,-0.0478663f,0.21375f,0.975282f,0.00154492f, 0.648554f,0.537457f,-0.0487709f,0.212317f,0.974653f,0.00193425f,
0.630801f,0.547481f,-0.0498195f,0.210825f,0.973949f,0.00241672f, 0.600623f,0.546096f,-0.0511047f,0.206479f,0.973182f,0.00301457f,
0.576744f,0.548932f,-0.0511175f,0.20447f,0.972328f,0.00375106f, 0.563868f,0.562014f,-0.0525192f,0.203514f,0.971385f,0.00465605f,
0.550762f,0.574795f,-0.053685f,0.202881f,0.970347f,0.00576411f, 0.564054f,0.598239f,-0.0518077f,0.204863f,0.969193f,0.00711458f,
0.52412f,0.599859f,-0.0550995f,0.202837f,0.967912f,0.00875426f, 0.499358f,0.584078f,-0.0539272f,0.194797f,0.966488f,0.010737f,
0.444969f,0.559907f,-0.0569189f,0.187584f,0.964904f,0.0131245f, 0.446871f,0.575312f,-0.0555968f,0.188252f,0.963136f,0.0159869f,
0.422785f,0.571179f,-0.0560724f,0.184399f,0.961159f,0.0194027f, 0.409282f,0.578457f,-0.0566339f,0.184358f,0.958943f,0.0234601f,
0.416289f,0.613713f,-0.0556281f,0.188603f,0.956458f,0.0282566f, 0.533411f,0.784183f,-0.0366266f,0.221001f,0.953662f,0.0338971f,
0.512784f,0.792609f,-0.0407304f,0.226425f,0.950507f,0.0404933f, 0.35435f,0.604334f,-0.0548834f,0.178767f,0.946951f,0.0481635f,
0.335202f,0.602249f,-0.0563087f,0.179193f,0.942932f,0.057025f, 0.445543f,0.800391f,-0.0283152f,0.223916f,0.938396f,0.0671927f,
0.311094f,0.619369f,-0.0575161f,0.182133f,0.933286f,0.0787703f, 0.165645f,0.363313f,-0.055273f,0.0893195f,0.927547f,0.0918397f,
0.152356f,0.348084f,-0.0429412f,0.109122f,0.921151f,0.106452f, 0.139246f,0.336009f,-0.0423344f,0.096222f,0.9141f,0.122612f,
0.120422f,0.305706f,-0.0377492f,0.0954062f,0.906484f,0.140265f, 0.0731233f,0.199194f,-0.0346761f,0.0520461f,0.898521f,0.159288f,
0.0666542f,0.184451f,-0.0297507f,0.0466293f,0.890663f,0.179493f, 0.0493834f,0.143314f,-0.0245802f,0.0376222f,0.883729f,0.200645f,
0.033331f,0.102078f,-0.0204618f,0.0296421f,0.879109f,0.222528f, 0.027706f,0.0869505f,-0.0198738f,0.027978f,0.878995f,0.245038f,
0.0258197f,0.0802724f,-0.0184735f,0.0266688f,0.886824f,0.268339f, 0.0125699f,0.0396394f,-0.0136753f,0.0176116f,0.907131f,0.292948f,
0.012116f,0.0337005f,-0.0112503f,0.015195f,0.943237f,0.319388f, 0.00974918f,0.0245723f,-0.0102067f,0.0133195f,0.997905f,0.346904f,
1.01858f,-0.000194722f,0.00442947f,0.271868f,0.977872f,1.03025e-05f, 1.02063f,0.022068f,0.00381861f,0.272062f,0.977954f,1.05668e-05f,
1.01993f,0.044738f,-0.000572794f,0.272098f,0.978077f,1.11908e-05f, 1.01998f,0.0666199f,-0.00167646f,0.270989f,0.978161f,1.20489e-05f,
1.01787f,0.0875644f,0.00990276f,0.273448f,0.978203f,1.31773e-05f, 1.0151f,0.110311f,0.00782474f,0.272146f,0.978202f,1.46127e-05f,
1.00802f,0.132174f,0.00388237f,0.27144f,0.978158f,1.63886e-05f, 0.999492f,0.153606f,3.19899e-05f,0.27044f,0.978069f,1.85331e-05f,
0.990694f,0.174828f,-0.00362286f,0.269408f,0.977932f,2.10673e-05f, 0.980749f,0.195627f,-0.00625542f,0.267654f,0.977755f,2.40734e-05f,
0.970629f,0.216205f,-0.00957168f,0.266283f,0.977602f,2.81163e-05f, 0.959998f,0.236433f,-0.0130228f,0.265094f,0.97744f,3.3226e-05f,
0.952795f,0.257711f,-0.0158613f,0.264804f,0.977256f,3.95301e-05f, 0.945103f,0.277138f,-0.0185555f,0.264142f,0.977041f,4.72086e-05f,
0.93102f,0.295847f,-0.0218695f,0.262446f,0.976843f,5.64956e-05f, 0.917789f,0.31443f,-0.0248763f,0.260989f,0.976636f,6.77817e-05f,
0.902451f,0.331988f,-0.0278737f,0.259157f,0.976448f,8.22356e-05f, 0.885055f,0.348542f,-0.0300008f,0.256418f,0.976246f,0.000100295f,
0.868894f,0.364858f,-0.0324881f,0.254485f,0.97601f,0.000122633f, 0.852367f,0.380564f,-0.0348128f,0.252513f,0.975728f,0.000150116f,
0.835569f,0.395829f,-0.0378781f,0.250113f,0.975426f,0.000184695f, 0.818414f,0.41036f,-0.0400493f,0.248013f,0.975106f,0.000228352f,
0.80096f,0.424281f,-0.0420737f,0.245894f,0.974742f,0.000282774f, 0.804368f,0.44893f,-0.0423336f,0.248008f,0.974328f,0.000350524f,
0.76678f,0.451319f,-0.0454572f,0.241691f,0.973895f,0.000436147f, 0.768796f,0.475345f,-0.0442846f,0.244943f,0.973414f,0.00054317f,
0.74335f,0.483689f,-0.046736f,0.241284f,0.972877f,0.000676575f, 0.751969f,0.512085f,-0.046083f,0.245773f,0.972308f,0.000844022f,
0.73588f,0.52582f,-0.0473502f,0.244269f,0.971673f,0.00105211f, 0.719047f,0.538569f,-0.048747f,0.242888f,0.970993f,0.00131173f,
0.700605f,0.549802f,-0.0501217f,0.241192f,0.970242f,0.00163353f, 0.664226f,0.54633f,-0.0523929f,0.235017f,0.96943f,0.00203239f,
0.631591f,0.544177f,-0.0542077f,0.229627f,0.968538f,0.00252425f, 0.602792f,0.543688f,-0.0551104f,0.225585f,0.96757f,0.00313011f,
0.587934f,0.55474f,-0.055275f,0.225327f,0.966508f,0.00387278f, 0.574248f,0.566926f,-0.055907f,0.224958f,0.965345f,0.00478048f,
0.555862f,0.574776f,-0.0581081f,0.221795f,0.964072f,0.00588595f, 0.543077f,0.587764f,-0.0587678f,0.221695f,0.962675f,0.00722732f,
0.530978f,0.601675f,-0.0593753f,0.22192f,0.961138f,0.00884807f, 0.551471f,0.626437f,-0.0554038f,0.22292f,0.959443f,0.0107986f,
0.546677f,0.645957f,-0.0543924f,0.223025f,0.957573f,0.0131366f, 0.592109f,0.715985f,-0.044191f,0.236525f,0.955541f,0.0159271f,
0.436331f,0.578449f,-0.0589814f,0.20137f,0.953302f,0.0192419f, 0.416386f,0.578107f,-0.0588305f,0.197861f,0.950824f,0.0231619f,
0.553178f,0.76114f,-0.0406899f,0.240606f,0.948067f,0.0277741f, 0.539656f,0.776343f,-0.0396777f,0.241286f,0.944996f,0.0331738f,
0.516767f,0.778179f,-0.0326814f,0.247352f,0.941567f,0.0394596f, 0.531746f,0.841764f,-0.0290343f,0.260804f,0.937741f,0.0467347f,
0.491711f,0.820738f,-0.02936f,0.25092f,0.933469f,0.0551003f, 0.223273f,0.437658f,-0.0663016f,0.132531f,0.92871f,0.0646532f,
0.204894f,0.41711f,-0.0531913f,0.149438f,0.92343f,0.075479f, 0.175636f,0.368536f,-0.0467323f,0.12984f,0.917611f,0.0876433f,
0.161626f,0.35388f,-0.0443481f,0.12308f,0.911265f,0.101185f, 0.146197f,0.337979f,-0.0426195f,0.117455f,0.904455f,0.116101f,
0.10646f,0.258606f,-0.0336447f,0.0899665f,0.897343f,0.132348f, 0.117004f,0.297841f,-0.0462302f,0.0772825f,0.89023f,0.149825f,
0.0689851f,0.178688f,-0.0319194f,0.0492756f,0.883652f,0.168396f, 0.0486076f,0.13165f,-0.0264551f,0.0394339f,0.878488f,0.187898f,
0.034732f,0.0986414f,-0.0232004f,0.0328289f,0.876114f,0.208201f, 0.0369438f,0.102062f,-0.0185098f,0.0428276f,0.878568f,0.22929f,
0.035f,0.0946236f,-0.0173309f,0.0419836f,0.888608f,0.25133f, 0.0158441f,0.0431616f,-0.0160574f,0.0208191f,0.909962f,0.274688f,
0.0176731f,0.0452099f,-0.013127f,0.0191603f,0.945868f,0.299771f, 0.0137909f,0.0323273f,-0.0100826f,0.0148769f,0.997993f,0.32584f,
1.02211f,0.00015427f,0.00206312f,0.297335f,0.973936f,1.28874e-05f, 1.0213f,0.0223476f,0.00171401f,0.296952f,0.973906f,1.29553e-05f,
1.01673f,0.045159f,-0.000860755f,0.294487f,0.973824f,1.31705e-05f, 1.01783f,0.0669375f,-0.00321101f,0.293877f,0.973804f,1.38992e-05f,
1.01963f,0.0869729f,0.011235f,0.296542f,0.973777f,1.50519e-05f, 1.01526f,0.109383f,0.00757049f,0.295927f,0.973721f,1.66102e-05f,
1.00887f,0.13135f,0.00343608f,0.295296f,0.973627f,1.85976e-05f, 1.00155f,0.153034f,-0.000560155f,0.294467f,0.973491f,2.10448e-05f,
0.993461f,0.174409f,-0.00400783f,0.293515f,0.97331f,2.3983e-05f, 0.984441f,0.195391f,-0.00716888f,0.292496f,0.973137f,2.75145e-05f,
0.9744f,0.216126f,-0.0101517f,0.290126f,0.973019f,3.2162e-05f, 0.970786f,0.237267f,-0.012935f,0.29036f,0.972899f,3.79679e-05f,
0.954719f,0.256132f,-0.0172729f,0.2879f,0.972753f,4.50608e-05f, 0.942546f,0.27543f,-0.0206201f,0.286138f,0.97257f,5.36333e-05f,
0.929035f,0.294141f,-0.0240255f,0.284301f,0.972339f,6.39182e-05f, 0.91473f,0.312249f,-0.0272065f,0.282411f,0.972104f,7.69058e-05f,
0.899871f,0.329781f,-0.0303903f,0.280376f,0.971848f,9.30809e-05f, 0.884539f,0.346684f,-0.0329336f,0.278449f,0.971552f,0.000112965f,
0.868761f,0.36307f,-0.0356463f,0.276339f,0.971205f,0.000137255f, 0.852564f,0.378827f,-0.0380856f,0.274233f,0.970843f,0.000167748f,
0.836021f,0.393992f,-0.0404338f,0.272067f,0.97045f,0.000205792f, 0.81931f,0.408768f,-0.0434975f,0.269471f,0.970007f,0.000252803f,
0.832581f,0.437571f,-0.0405679f,0.275024f,0.969526f,0.000311301f, 0.821771f,0.4555f,-0.0425175f,0.273979f,0.969014f,0.000384533f,
0.810412f,0.473173f,-0.044066f,0.273543f,0.968446f,0.00047524f, 0.795723f,0.489634f,-0.0458203f,0.272562f,0.967856f,0.000588466f,
0.779756f,0.508486f,-0.0476516f,0.271951f,0.967251f,0.000729174f, 0.766508f,0.521739f,-0.0490601f,0.270762f,0.966602f,0.000903643f,
0.737848f,0.523661f,-0.0512646f,0.265412f,0.965909f,0.00112022f, 0.721704f,0.536711f,-0.0527322f,0.264046f,0.96515f,0.00138777f,
0.704847f,0.548967f,-0.0541639f,0.262549f,0.964329f,0.00171819f, 0.688712f,0.561505f,-0.0554769f,0.261292f,0.963434f,0.00212501f,
0.668785f,0.571697f,-0.0563932f,0.258036f,0.962451f,0.00262411f, 0.613317f,0.548421f,-0.0598233f,0.246683f,0.96138f,0.00323524f,
0.642239f,0.599671f,-0.0588818f,0.258429f,0.960208f,0.00398089f, 0.632792f,0.618425f,-0.0613389f,0.257676f,0.958923f,0.00488741f,
0.618474f,0.632342f,-0.0621839f,0.257325f,0.957512f,0.00598579f, 0.670625f,0.672518f,-0.054557f,0.260118f,0.955964f,0.00731191f,
0.591242f,0.662117f,-0.063689f,0.257346f,0.954265f,0.00890691f, 0.634742f,0.693112f,-0.0546682f,0.254334f,0.952392f,0.0108174f,
0.625146f,0.712838f,-0.0539448f,0.253527f,0.95033f,0.0130966f, 0.614082f,0.730354f,-0.050031f,0.257372f,0.948061f,0.0158047f,
0.601902f,0.745322f,-0.0494448f,0.259747f,0.945553f,0.0190071f, 0.580955f,0.749656f,-0.0493036f,0.257936f,0.942785f,0.0227769f,
0.561387f,0.755706f,-0.0454029f,0.260277f,0.939726f,0.027193f, 0.557796f,0.781954f,-0.0395715f,0.273157f,0.936345f,0.032339f,
0.544136f,0.799396f,-0.0335193f,0.279351f,0.932611f,0.0383029f, 0.298113f,0.517614f,-0.0808153f,0.168887f,0.928491f,0.0451741f,
0.252844f,0.458528f,-0.0743965f,0.149618f,0.923956f,0.0530398f, 0.503483f,0.850981f,-0.0377701f,0.301909f,0.918983f,0.0619825f,
0.244304f,0.481741f,-0.0709375f,0.1538f,0.913561f,0.0720721f, 0.191928f,0.384812f,-0.0559595f,0.127649f,0.907707f,0.083364f,
0.171457f,0.362108f,-0.0517153f,0.122714f,0.901474f,0.0958868f, 0.156351f,0.345018f,-0.0502625f,0.117029f,0.894976f,0.10964f,
0.141686f,0.324617f,-0.0480311f,0.113323f,0.888436f,0.124589f, 0.0754404f,0.187776f,-0.0441107f,0.0399384f,0.882211f,0.140661f,
0.0775838f,0.189666f,-0.0302736f,0.073335f,0.87694f,0.15776f, 0.0508883f,0.126713f,-0.0274715f,0.0413243f,0.873625f,0.175786f,
0.0407044f,0.104841f,-0.0252372f,0.0368251f,0.873491f,0.19468f, 0.0409404f,0.102868f,-0.0203036f,0.0508218f,0.878338f,0.214466f,
0.0399926f,0.0983195f,-0.0190991f,0.0486568f,0.890479f,0.235301f, 0.042296f,0.104109f,-0.0167851f,0.0454372f,0.912484f,0.257461f,
0.024935f,0.056388f,-0.0165716f,0.0244021f,0.948031f,0.281256f, 0.0146399f,0.0290247f,-0.0122755f,0.0167912f,0.99806f,0.306025f,
1.02914f,0.000530068f,-0.00327621f,0.325466f,0.96892f,1.46664e-05f, 1.02693f,0.0222938f,0.00290582f,0.323154f,0.96889f,1.47723e-05f,
1.02585f,0.0449636f,-0.00192156f,0.322874f,0.968801f,1.50841e-05f, 1.02167f,0.0644566f,0.0155328f,0.320805f,0.968722f,1.58154e-05f,
1.01806f,0.0868482f,0.0112134f,0.320752f,0.968659f,1.70819e-05f, 1.01485f,0.108857f,0.00736989f,0.320302f,0.968566f,1.88097e-05f,
1.01102f,0.130761f,0.00375591f,0.319643f,0.968435f,2.10178e-05f, 1.0076f,0.153497f,0.00103172f,0.318693f,0.968322f,2.3784e-05f,
0.99759f,0.174317f,-0.00221991f,0.317575f,0.968188f,2.70959e-05f, 0.990184f,0.195886f,-0.00624456f,0.316845f,0.96805f,3.12541e-05f,
0.978232f,0.215989f,-0.0108513f,0.315046f,0.967911f,3.65408e-05f, 0.965147f,0.235468f,-0.0153339f,0.31302f,0.96774f,4.30086e-05f,
0.9534f,0.255167f,-0.0192746f,0.311388f,0.967526f,5.08111e-05f, 0.940667f,0.274309f,-0.0230522f,0.309538f,0.967262f,6.01654e-05f,
0.927197f,0.292902f,-0.0267108f,0.30756f,0.966991f,7.19257e-05f, 0.916406f,0.311416f,-0.0296491f,0.306034f,0.96669f,8.64302e-05f,
0.904317f,0.329371f,-0.0325425f,0.304407f,0.966344f,0.000104112f, 0.910087f,0.353697f,-0.0330113f,0.306892f,0.965952f,0.000125689f,
0.898813f,0.372453f,-0.0354645f,0.305461f,0.965545f,0.000152676f, 0.883426f,0.389082f,-0.0354839f,0.30385f,0.965135f,0.000185916f,
0.871613f,0.407174f,-0.0388862f,0.302493f,0.964695f,0.00022669f, 0.855006f,0.422729f,-0.0415606f,0.300458f,0.964242f,0.000277568f,
0.840283f,0.440905f,-0.043609f,0.298944f,0.963743f,0.000340353f, 0.825453f,0.454569f,-0.0457378f,0.297106f,0.963197f,0.000417948f,
0.811729f,0.47135f,-0.0476297f,0.296119f,0.96261f,0.000514269f, 0.796847f,0.487993f,-0.0495385f,0.295065f,0.961961f,0.000633024f,
0.782188f,0.504126f,-0.051346f,0.294078f,0.961265f,0.000780197f, 0.76919f,0.51727f,-0.0526394f,0.292494f,0.960497f,0.000961423f,
0.744629f,0.524865f,-0.0572772f,0.286908f,0.95967f,0.00118509f, 0.728382f,0.537779f,-0.0588402f,0.28532f,0.958765f,0.00145988f,
0.712446f,0.550639f,-0.0602765f,0.283883f,0.957781f,0.00179708f, 0.696731f,0.563428f,-0.0616006f,0.282577f,0.956716f,0.00221017f,
0.681315f,0.576252f,-0.0628013f,0.28144f,0.955554f,0.00271425f, 0.66624f,0.589222f,-0.0639359f,0.280448f,0.954289f,0.00332789f,
0.651517f,0.602405f,-0.0649634f,0.279652f,0.952914f,0.00407273f, 0.637188f,0.615924f,-0.0659064f,0.27906f,0.951417f,0.00497387f,
0.62574f,0.632422f,-0.0669195f,0.279208f,0.949785f,0.0060603f, 0.610601f,0.645295f,-0.0676156f,0.27872f,0.948007f,0.00736573f,
0.652835f,0.672877f,-0.058068f,0.277773f,0.946067f,0.00892832f, 0.635065f,0.682573f,-0.0575107f,0.275263f,0.943947f,0.0107912f,
0.62689f,0.701955f,-0.0539063f,0.278833f,0.94165f,0.0130035f, 0.612794f,0.715672f,-0.0531899f,0.277461f,0.939161f,0.0156197f,
0.600409f,0.728468f,-0.0539654f,0.27869f,0.936446f,0.0187f, 0.592995f,0.750838f,-0.0502825f,0.282718f,0.933476f,0.0223095f,
0.580881f,0.766564f,-0.0437146f,0.291057f,0.930225f,0.0265189f, 0.570487f,0.782447f,-0.0434988f,0.293914f,0.926668f,0.0314029f,
0.559012f,0.802757f,-0.03439f,0.307749f,0.922782f,0.0370383f, 0.284103f,0.477729f,-0.0824734f,0.169037f,0.918543f,0.0435029f,
0.52295f,0.830139f,-0.0394316f,0.321532f,0.91394f,0.050872f, 0.50475f,0.843136f,-0.041939f,0.328833f,0.908968f,0.0592157f,
0.495799f,0.853888f,-0.0430598f,0.335293f,0.903644f,0.068594f, 0.198015f,0.382362f,-0.0563645f,0.146659f,0.898016f,0.0790526f,
0.438772f,0.838604f,-0.0473046f,0.337214f,0.892174f,0.0906174f, 0.165001f,0.351961f,-0.0505669f,0.134666f,0.886278f,0.103291f,
0.108764f,0.229685f,-0.0454843f,0.0728766f,0.880597f,0.117052f, 0.0892556f,0.197204f,-0.0396073f,0.0627114f,0.875533f,0.131853f,
0.0737261f,0.166159f,-0.0354155f,0.0549698f,0.871693f,0.147637f, 0.0529872f,0.122884f,-0.0284557f,0.0428065f,0.869949f,0.164346f,
0.047293f,0.110787f,-0.0278402f,0.0415662f,0.871519f,0.181962f, 0.0406399f,0.095394f,-0.0282521f,0.0402822f,0.878129f,0.200534f,
0.038847f,0.0893135f,-0.0266142f,0.0387473f,0.892098f,0.220226f, 0.0207267f,0.0439774f,-0.0174483f,0.0234874f,0.91503f,0.241247f,
0.0186211f,0.0371098f,-0.015059f,0.0206955f,0.949764f,0.263822f, 0.0183874f,0.0347907f,-0.012818f,0.0187867f,0.998107f,0.287416f,
1.02742f,-0.00153731f,0.00722072f,0.354998f,0.963091f,1.63917e-05f, 1.0258f,0.0207162f,0.00398163f,0.355029f,0.963059f,1.65121e-05f,
1.03637f,0.0415876f,0.0164357f,0.3544f,0.962973f,1.68986e-05f, 1.0353f,0.0640688f,0.0141585f,0.354108f,0.962926f,1.78571e-05f,
1.02442f,0.0855118f,0.0150708f,0.346732f,0.962853f,1.92947e-05f, 1.01843f,0.107653f,0.0109649f,0.345349f,0.962735f,2.12039e-05f,
1.02234f,0.131934f,0.00886878f,0.346853f,0.962609f,2.36449e-05f, 1.01509f,0.153876f,0.00388025f,0.346035f,0.962472f,2.66302e-05f,
1.00557f,0.175128f,-0.00132255f,0.344691f,0.962332f,3.04162e-05f, 0.994754f,0.195841f,-0.00641811f,0.342999f,0.962183f,3.52149e-05f,
0.982543f,0.215904f,-0.0114611f,0.341018f,0.961996f,4.10647e-05f, 0.971444f,0.235691f,-0.0159567f,0.339332f,0.96176f,4.80897e-05f,
0.962544f,0.255685f,-0.0195742f,0.337997f,0.961484f,5.66137e-05f, 0.952889f,0.27532f,-0.0231388f,0.336609f,0.961194f,6.72618e-05f,
0.942794f,0.294724f,-0.0265196f,0.335163f,0.960862f,8.02322e-05f, 0.939594f,0.315615f,-0.0266992f,0.33606f,0.960477f,9.58812e-05f,
0.9261f,0.333938f,-0.0299012f,0.333995f,0.96011f,0.000115266f, 0.916799f,0.353646f,-0.0332776f,0.332508f,0.959728f,0.000139099f,
0.903509f,0.371734f,-0.0358789f,0.330264f,0.959301f,0.000168089f, 0.887664f,0.388276f,-0.0391276f,0.328138f,0.958848f,0.00020396f,
0.920179f,0.428167f,-0.0360247f,0.339427f,0.958352f,0.000248061f, 0.926525f,0.452416f,-0.0372958f,0.340972f,0.957801f,0.000302108f,
0.908107f,0.469457f,-0.040867f,0.33852f,0.957213f,0.000368961f, 0.883317f,0.492344f,-0.0450507f,0.336205f,0.95656f,0.000450908f,
0.863725f,0.5072f,-0.0484188f,0.333514f,0.955861f,0.000552123f, 0.850142f,0.515976f,-0.0503786f,0.330616f,0.955092f,0.000676242f,
0.833035f,0.52799f,-0.0528274f,0.328007f,0.954266f,0.000829062f, 0.81437f,0.541579f,-0.0553322f,0.325641f,0.953365f,0.00101631f,
0.795937f,0.554855f,-0.0576316f,0.323394f,0.952392f,0.00124585f, 0.749636f,0.547462f,-0.0594065f,0.314945f,0.951341f,0.00152663f,
0.722599f,0.562958f,-0.0651041f,0.310083f,0.950202f,0.00186912f, 0.704152f,0.57541f,-0.0672205f,0.307942f,0.948999f,0.00228607f,
0.693689f,0.580695f,-0.0675669f,0.305609f,0.947716f,0.00279254f, 0.677479f,0.592865f,-0.0685822f,0.304113f,0.946333f,0.00340597f,
0.661199f,0.604589f,-0.0696241f,0.302838f,0.944836f,0.00414659f, 0.644939f,0.61585f,-0.0706886f,0.301797f,0.943212f,0.00503806f,
0.629716f,0.628344f,-0.0714333f,0.301036f,0.941451f,0.00610781f, 0.662089f,0.645571f,-0.0619272f,0.297539f,0.939538f,0.00738684f,
0.65251f,0.66245f,-0.061318f,0.297197f,0.937457f,0.00891061f, 0.642057f,0.678385f,-0.0610173f,0.297205f,0.93519f,0.0107188f,
0.636091f,0.700627f,-0.0592281f,0.297908f,0.932726f,0.0128566f, 0.625835f,0.717366f,-0.0557459f,0.30171f,0.930043f,0.0153731f,
0.60972f,0.72559f,-0.0563793f,0.301447f,0.927125f,0.018323f, 0.551309f,0.688814f,-0.0627663f,0.287054f,0.923953f,0.0217648f,
0.583916f,0.750295f,-0.0475055f,0.313178f,0.920505f,0.025761f, 0.580524f,0.777816f,-0.0446621f,0.318859f,0.916772f,0.0303783f,
0.565773f,0.79306f,-0.0368376f,0.331558f,0.912735f,0.0356838f, 0.54773f,0.806382f,-0.0394331f,0.338349f,0.908388f,0.0417453f,
0.52588f,0.813033f,-0.0437462f,0.341921f,0.903736f,0.0486284f, 0.509389f,0.82617f,-0.0445276f,0.351067f,0.898796f,0.0563938f,
0.498114f,0.847911f,-0.0471635f,0.36304f,0.893607f,0.0650929f, 0.488113f,0.871844f,-0.0492249f,0.374523f,0.888246f,0.0747661f,
0.484982f,0.891225f,-0.0498152f,0.384392f,0.882835f,0.0854383f, 0.175514f,0.357459f,-0.0537146f,0.147285f,0.877574f,0.0971194f,
0.168135f,0.352969f,-0.0469578f,0.138802f,0.872774f,0.109797f, 0.0919794f,0.191301f,-0.041199f,0.0656989f,0.868949f,0.123447f,
0.0794915f,0.172427f,-0.0372934f,0.0572773f,0.866646f,0.138039f, 0.0586646f,0.125687f,-0.0312541f,0.047529f,0.86669f,0.153557f,
0.0523359f,0.113417f,-0.0314304f,0.046733f,0.870178f,0.170014f, 0.0487394f,0.104661f,-0.0297873f,0.0444818f,0.878488f,0.187475f,
0.0458314f,0.0964671f,-0.0292294f,0.043516f,0.893375f,0.206069f, 0.0419138f,0.0839965f,-0.027476f,0.0407134f,0.917093f,0.226003f,
0.0319217f,0.0628427f,-0.0186999f,0.0286765f,0.951087f,0.247424f, 0.0277498f,0.0526257f,-0.0161795f,0.024933f,0.998136f,0.269963f,
1.03617f,-0.00353551f,0.0259092f,0.38016f,0.956404f,1.80415e-05f, 1.04181f,0.0178989f,0.0245579f,0.379466f,0.956379f,1.81861e-05f,
1.03836f,0.04046f,0.0212242f,0.377799f,0.956396f,1.8899e-05f, 1.03357f,0.0628266f,0.0181545f,0.37577f,0.95637f,2.00498e-05f,
1.02961f,0.0850204f,0.0154984f,0.375799f,0.956287f,2.16349e-05f, 1.0329f,0.10897f,0.0124772f,0.377956f,0.956142f,2.36746e-05f,
1.02545f,0.13093f,0.00657717f,0.377127f,0.955964f,2.62434e-05f, 1.01712f,0.152633f,0.00130284f,0.37556f,0.955834f,2.96977e-05f,
1.01619f,0.175488f,0.000286989f,0.373455f,0.955684f,3.40089e-05f, 1.01066f,0.196924f,-0.00421976f,0.373159f,0.955491f,3.92332e-05f,
1.00061f,0.217533f,-0.0093179f,0.37167f,0.955245f,4.5493e-05f, 0.989102f,0.237734f,-0.0144468f,0.369846f,0.954984f,5.3324e-05f,
0.975189f,0.25698f,-0.0181192f,0.366757f,0.954684f,6.28824e-05f, 0.993009f,0.283011f,-0.0162815f,0.371829f,0.95433f,7.43849e-05f,
0.982082f,0.302916f,-0.0203443f,0.370139f,0.953945f,8.84472e-05f, 0.988298f,0.327644f,-0.0214839f,0.37247f,0.953568f,0.000105735f,
0.978678f,0.348155f,-0.0250092f,0.371354f,0.953152f,0.000126647f, 0.921185f,0.353251f,-0.0360452f,0.357116f,0.952708f,0.000152293f,
0.906023f,0.37028f,-0.0397972f,0.354733f,0.952224f,0.000183696f, 0.900864f,0.390695f,-0.0420559f,0.355407f,0.951685f,0.000221913f,
0.876162f,0.403477f,-0.046499f,0.350334f,0.951108f,0.000268949f, 0.863661f,0.42066f,-0.0491803f,0.348882f,0.950468f,0.000326282f,
0.875502f,0.448578f,-0.0449428f,0.355691f,0.949781f,0.000396756f, 0.82924f,0.449219f,-0.0521366f,0.344739f,0.949028f,0.0004828f,
0.838658f,0.477255f,-0.0511595f,0.349939f,0.948219f,0.000588383f, 0.819962f,0.490608f,-0.0541246f,0.347135f,0.947337f,0.000717268f,
0.801406f,0.503513f,-0.0568942f,0.344391f,0.946396f,0.00087491f, 0.779052f,0.521092f,-0.0599602f,0.342193f,0.94541f,0.00106726f,
0.765796f,0.52897f,-0.0615587f,0.339225f,0.944356f,0.00130154f, 0.748633f,0.552995f,-0.0640769f,0.34012f,0.943222f,0.0015865f,
0.74192f,0.561165f,-0.0643202f,0.338123f,0.942004f,0.00193257f, 0.748346f,0.592305f,-0.0691862f,0.340386f,0.940688f,0.00235162f,
0.799036f,0.620153f,-0.0613967f,0.346267f,0.939266f,0.00285787f, 0.786393f,0.636491f,-0.0622434f,0.345433f,0.937728f,0.00346781f,
0.773734f,0.652927f,-0.0626285f,0.344363f,0.936066f,0.00420073f, 0.707991f,0.667567f,-0.0731179f,0.34271f,0.934268f,0.00507852f,
0.63604f,0.626496f,-0.0754107f,0.323463f,0.932325f,0.00612677f, 0.71711f,0.684807f,-0.0608359f,0.338412f,0.930224f,0.00737426f,
0.606971f,0.65164f,-0.0793872f,0.320656f,0.92795f,0.00885338f, 0.688374f,0.713388f,-0.0568477f,0.338088f,0.925493f,0.0106011f,
0.643754f,0.695419f,-0.0595484f,0.324416f,0.922836f,0.0126576f, 0.633478f,0.712522f,-0.0584327f,0.324324f,0.919969f,0.0150683f,
0.618453f,0.721093f,-0.0573235f,0.326504f,0.916876f,0.0178819f, 0.603202f,0.731954f,-0.0499503f,0.332907f,0.913543f,0.0211506f,
0.591385f,0.740885f,-0.0503368f,0.336448f,0.909961f,0.0249308f, 0.586348f,0.765851f,-0.0441744f,0.345027f,0.906126f,0.0292805f,
0.573763f,0.784202f,-0.0393693f,0.355697f,0.902064f,0.0342592f, 0.555892f,0.796753f,-0.0417474f,0.362771f,0.897765f,0.0399263f,
0.535543f,0.804396f,-0.0441295f,0.367473f,0.893244f,0.0463391f, 0.518668f,0.815871f,-0.0470429f,0.376272f,0.888537f,0.0535508f,
0.506077f,0.833094f,-0.0499236f,0.388031f,0.883702f,0.0616073f, 0.492879f,0.847273f,-0.0529368f,0.400194f,0.87884f,0.0705458f,
0.49823f,0.902634f,-0.0512257f,0.41151f,0.874101f,0.0803926f, 0.188322f,0.371905f,-0.0627295f,0.139037f,0.869705f,0.0911617f,
0.179741f,0.358472f,-0.0495991f,0.15153f,0.865954f,0.102852f, 0.0941327f,0.183924f,-0.0426286f,0.0682989f,0.86329f,0.115462f,
0.082712f,0.167559f,-0.038489f,0.0618273f,0.8623f,0.128985f, 0.0727255f,0.151815f,-0.0345719f,0.0558185f,0.863752f,0.143425f,
0.0700257f,0.140092f,-0.0354301f,0.0561473f,0.868768f,0.158815f, 0.0606214f,0.121289f,-0.0312488f,0.0495803f,0.878734f,0.175235f,
0.0618727f,0.122716f,-0.0294302f,0.0486869f,0.894706f,0.192804f, 0.0510762f,0.0920202f,-0.0323886f,0.0484197f,0.918662f,0.211688f,
0.0267148f,0.0454752f,-0.0171566f,0.0250639f,0.952043f,0.232037f, 0.0224101f,0.0361274f,-0.0186986f,0.0165689f,0.998151f,0.253614f,
1.04962f,-0.00444595f,0.0260148f,0.413538f,0.948961f,1.98939e-05f, 1.0413f,0.0169716f,0.0282604f,0.403318f,0.948965f,2.01815e-05f,
1.03992f,0.0397697f,0.0226707f,0.403863f,0.948988f,2.10226e-05f, 1.03709f,0.0618134f,0.0217033f,0.404353f,0.948947f,2.22572e-05f,
1.03325f,0.0843221f,0.0164491f,0.404296f,0.948836f,2.38938e-05f, 1.02835f,0.106699f,0.0107916f,0.403885f,0.948704f,2.61715e-05f,
1.02212f,0.128794f,0.00531812f,0.402925f,0.948543f,2.91743e-05f, 1.01521f,0.150647f,-0.000245877f,0.402075f,0.948355f,3.2927e-05f,
1.03315f,0.176275f,0.00268665f,0.404983f,0.948147f,3.7489e-05f, 1.0162f,0.196383f,-0.00258129f,0.401905f,0.94793f,4.32268e-05f,
1.02483f,0.220246f,-0.00385636f,0.403868f,0.947679f,5.02624e-05f, 1.08369f,0.252665f,0.0102784f,0.419129f,0.947374f,5.87179e-05f,
1.02035f,0.264641f,-0.00985245f,0.404221f,0.947029f,6.90219e-05f, 1.0602f,0.297528f,-0.00183176f,0.415985f,0.946648f,8.16482e-05f,
1.0433f,0.31811f,-0.00857851f,0.413035f,0.946216f,9.68464e-05f, 0.994394f,0.326732f,-0.0202445f,0.40104f,0.945782f,0.000115424f,
0.977565f,0.344773f,-0.0250498f,0.398179f,0.945318f,0.000138038f, 0.965737f,0.364636f,-0.0276234f,0.395534f,0.944804f,0.000165416f,
0.954108f,0.383695f,-0.0311113f,0.394318f,0.944253f,0.00019893f, 0.941458f,0.402267f,-0.0345621f,0.392877f,0.943641f,0.000239548f,
0.92988f,0.421083f,-0.037521f,0.391902f,0.942985f,0.000289254f, 0.917706f,0.439657f,-0.0400671f,0.390579f,0.942262f,0.000349625f,
0.875839f,0.444489f,-0.0479863f,0.38028f,0.941485f,0.000423403f, 0.890391f,0.474861f,-0.0463714f,0.387631f,0.940638f,0.000513094f,
0.838855f,0.472479f,-0.0548522f,0.374263f,0.93973f,0.000622417f, 0.810391f,0.480225f,-0.0593211f,0.367961f,0.93878f,0.000755437f,
0.802413f,0.49873f,-0.0608064f,0.368444f,0.937767f,0.000917043f, 0.784422f,0.511222f,-0.0634964f,0.365659f,0.936682f,0.00111324f,
0.768406f,0.524501f,-0.065772f,0.363584f,0.935516f,0.00135115f, 0.756285f,0.540079f,-0.0674353f,0.362946f,0.934262f,0.00163901f,
0.747181f,0.558662f,-0.067705f,0.362415f,0.932909f,0.00198652f, 0.818648f,0.598518f,-0.0544021f,0.378105f,0.931454f,0.0024053f,
0.771706f,0.592207f,-0.0666429f,0.360943f,0.929886f,0.0029087f, 0.790281f,0.630162f,-0.0650258f,0.369094f,0.928198f,0.00351223f,
0.703842f,0.626093f,-0.0717787f,0.363246f,0.926381f,0.00423388f, 0.708861f,0.657713f,-0.0774678f,0.366944f,0.924426f,0.00509417f,
0.754938f,0.680001f,-0.0573947f,0.373379f,0.922324f,0.00611671f, 0.730412f,0.685527f,-0.0647489f,0.363714f,0.920061f,0.00732783f,
0.709325f,0.692679f,-0.0611322f,0.363674f,0.917631f,0.0087576f, 0.683525f,0.695138f,-0.0612691f,0.357771f,0.915027f,0.0104393f,
0.654873f,0.693626f,-0.0620608f,0.349527f,0.91226f,0.0124098f, 0.636155f,0.698451f,-0.0632522f,0.347074f,0.909307f,0.0147099f,
0.627895f,0.716699f,-0.0592288f,0.350866f,0.906153f,0.0173831f, 0.611543f,0.725641f,-0.0508921f,0.35788f,0.902791f,0.0204766f,
0.605692f,0.741953f,-0.0517942f,0.361757f,0.899213f,0.0240398f, 0.593113f,0.754208f,-0.0440362f,0.371327f,0.895423f,0.0281248f,
0.576102f,0.766024f,-0.0419947f,0.379336f,0.891427f,0.0327839f, 0.565136f,0.787378f,-0.0439154f,0.387806f,0.887245f,0.0380693f,
0.543303f,0.791239f,-0.0477937f,0.396009f,0.882909f,0.044032f, 0.526962f,0.80221f,-0.0496547f,0.401431f,0.878476f,0.0507195f,
0.511947f,0.812857f,-0.052719f,0.411866f,0.874023f,0.0581736f, 0.480727f,0.794449f,-0.052676f,0.401124f,0.869672f,0.06643f,
0.504238f,0.874199f,-0.0546558f,0.437344f,0.865589f,0.0755162f, 0.203089f,0.371545f,-0.0575763f,0.173261f,0.862006f,0.0854511f,
0.147331f,0.281026f,-0.0567966f,0.100817f,0.859239f,0.0962458f, 0.0960831f,0.176183f,-0.0440467f,0.0707935f,0.857781f,0.107915f,
0.0851642f,0.161099f,-0.0399515f,0.0643738f,0.858261f,0.120464f, 0.0840737f,0.161541f,-0.0393395f,0.0644175f,0.861308f,0.133921f,
0.0805435f,0.149373f,-0.0393431f,0.0636181f,0.867771f,0.148333f, 0.069095f,0.127677f,-0.0344329f,0.055544f,0.878669f,0.163776f,
0.0712637f,0.13071f,-0.0325023f,0.0548986f,0.895751f,0.180384f, 0.0776806f,0.141738f,-0.0302509f,0.0560166f,0.919753f,0.198271f,
0.0321026f,0.0531212f,-0.0180534f,0.027678f,0.952675f,0.217634f, 0.0314075f,0.047868f,-0.0197304f,0.0255909f,0.998152f,0.238317f,
1.04649f,-0.0033996f,0.0221031f,0.442913f,0.940817f,2.22747e-05f, 1.04768f,0.0189019f,0.0212302f,0.441362f,0.940779f,2.24804e-05f,
1.04523f,0.038481f,0.0282714f,0.435494f,0.940667f,2.30959e-05f, 1.04672f,0.0636449f,0.0106054f,0.442252f,0.940576f,2.43626e-05f,
1.03688f,0.0836349f,0.0170298f,0.433639f,0.940506f,2.63182e-05f, 1.03197f,0.105993f,0.0111009f,0.433184f,0.940385f,2.88616e-05f,
1.02588f,0.128105f,0.00520199f,0.432368f,0.9402f,3.20228e-05f, 1.03552f,0.153439f,0.00637883f,0.432173f,0.939992f,3.61137e-05f,
1.02429f,0.174009f,0.00870517f,0.43057f,0.939744f,4.11888e-05f, 1.01012f,0.193f,0.00682823f,0.428905f,0.939477f,4.73404e-05f,
1.07712f,0.22594f,0.0113477f,0.445071f,0.93919f,5.49143e-05f, 1.01515f,0.239746f,-0.0101796f,0.429839f,0.938868f,6.4161e-05f,
1.07188f,0.271929f,0.00588922f,0.44629f,0.938487f,7.52463e-05f, 1.02249f,0.28631f,-0.0109024f,0.432623f,0.938071f,8.88196e-05f,
1.00699f,0.3053f,-0.016775f,0.429849f,0.937602f,0.000105217f, 0.991088f,0.323657f,-0.0222681f,0.426999f,0.937091f,0.000125033f,
0.974805f,0.341594f,-0.0273764f,0.424083f,0.936565f,0.000149157f, 0.964419f,0.361222f,-0.0300134f,0.421816f,0.93599f,0.000178267f,
0.953129f,0.37997f,-0.0336126f,0.420503f,0.935374f,0.000213712f, 0.941558f,0.398497f,-0.0370626f,0.419211f,0.934696f,0.000256565f,
0.929672f,0.416829f,-0.0401158f,0.417862f,0.933965f,0.000308676f, 0.917648f,0.43502f,-0.0428399f,0.416495f,0.933169f,0.000371805f,
0.904403f,0.452386f,-0.0457456f,0.415193f,0.932306f,0.000448367f, 0.857541f,0.453784f,-0.0550229f,0.402247f,0.931378f,0.000541309f,
0.83958f,0.467477f,-0.0584426f,0.399133f,0.930389f,0.000653807f, 0.821659f,0.480708f,-0.0616719f,0.396064f,0.929347f,0.000790014f,
0.803905f,0.493545f,-0.0646676f,0.393071f,0.928237f,0.000954842f, 0.786338f,0.506001f,-0.0674531f,0.390172f,0.927047f,0.00115388f,
0.832134f,0.558201f,-0.0611208f,0.410774f,0.925768f,0.00139387f, 0.814511f,0.571819f,-0.0638867f,0.40841f,0.924397f,0.00168282f,
0.797557f,0.585477f,-0.0663752f,0.406335f,0.922925f,0.00203003f, 0.729048f,0.586581f,-0.0760675f,0.391012f,0.921345f,0.00244632f,
0.729869f,0.58659f,-0.073788f,0.387177f,0.919651f,0.00294438f, 0.732494f,0.614385f,-0.0796078f,0.390115f,0.917835f,0.00353864f,
0.713316f,0.623496f,-0.0784637f,0.389359f,0.915888f,0.00424576f, 0.771433f,0.656223f,-0.0593718f,0.398123f,0.913805f,0.00508503f,
0.748778f,0.664197f,-0.0679604f,0.387509f,0.911579f,0.00607784f, 0.73674f,0.67916f,-0.0612947f,0.392796f,0.909226f,0.0072487f,
0.714954f,0.6854f,-0.0628256f,0.38847f,0.906722f,0.00862475f, 0.68681f,0.684511f,-0.0646729f,0.38086f,0.904057f,0.0102365f,
0.658602f,0.683029f,-0.0654464f,0.372103f,0.901223f,0.0121173f, 0.643554f,0.691053f,-0.0661277f,0.370804f,0.898212f,0.0143038f,
0.636893f,0.710703f,-0.0601383f,0.376808f,0.895016f,0.0168347f, 0.625522f,0.722467f,-0.0544537f,0.384304f,0.891639f,0.0197527f,
0.613804f,0.730382f,-0.0545923f,0.386295f,0.888083f,0.0231016f, 0.599953f,0.741902f,-0.0445538f,0.396457f,0.884358f,0.0269275f,
0.58967f,0.762485f,-0.0435481f,0.405753f,0.880483f,0.0312772f, 0.573913f,0.775983f,-0.0461531f,0.413252f,0.87649f,0.0361972f,
0.556561f,0.785649f,-0.049308f,0.421694f,0.872424f,0.041733f, 0.53777f,0.790543f,-0.0530228f,0.431082f,0.868354f,0.0479277f,
0.53008f,0.812935f,-0.0542914f,0.44085f,0.864376f,0.0548204f, 0.521116f,0.831895f,-0.0558444f,0.451359f,0.860622f,0.0624461f,
0.526635f,0.829942f,-0.0547382f,0.45842f,0.857337f,0.070834f, 0.550001f,0.877831f,-0.0485314f,0.467717f,0.85474f,0.080008f,
0.142884f,0.243797f,-0.0595216f,0.101911f,0.85314f,0.0899924f, 0.251072f,0.468457f,-0.0347081f,0.238876f,0.852925f,0.100802f,
0.08738f,0.154276f,-0.0416114f,0.0670355f,0.85462f,0.112469f, 0.119654f,0.225247f,-0.0379463f,0.115543f,0.858856f,0.125028f,
0.084862f,0.145685f,-0.0414713f,0.0672485f,0.866623f,0.138535f, 0.0788284f,0.134861f,-0.0378049f,0.0622388f,0.878794f,0.153078f,
0.0816781f,0.138751f,-0.0358791f,0.061884f,0.896312f,0.168757f, 0.0846386f,0.141584f,-0.0348992f,0.0628561f,0.920488f,0.185731f,
0.0848957f,0.140957f,-0.0257385f,0.0663374f,0.952993f,0.204157f, 0.0406355f,0.0598899f,-0.0215156f,0.033997f,0.99814f,0.224019f,
1.04337f,-0.0025716f,0.021205f,0.471153f,0.931403f,2.39764e-05f, 1.04526f,0.0194551f,0.0220192f,0.468497f,0.931467f,2.44222e-05f,
1.04407f,0.0418482f,0.0151113f,0.469865f,0.931463f,2.53489e-05f, 1.04557f,0.0631678f,0.0121571f,0.46858f,0.931379f,2.67503e-05f,
1.03996f,0.0828634f,0.0178019f,0.463272f,0.931227f,2.87004e-05f, 1.0354f,0.105273f,0.0111654f,0.463211f,0.931074f,3.14543e-05f,
1.02906f,0.127317f,0.00515614f,0.462098f,0.930904f,3.49938e-05f, 1.03776f,0.152707f,0.00652997f,0.461261f,0.930679f,3.93447e-05f,
1.02764f,0.173553f,0.00245193f,0.459774f,0.930427f,4.48307e-05f, 1.04358f,0.196541f,0.00962362f,0.464841f,0.930119f,5.15154e-05f,
1.07403f,0.22361f,0.0100604f,0.473656f,0.929763f,5.95923e-05f, 1.0161f,0.238191f,-0.0114737f,0.458595f,0.929404f,6.95181e-05f,
1.06483f,0.26826f,0.00417125f,0.473536f,0.928995f,8.14331e-05f, 1.01887f,0.283678f,-0.0125322f,0.459236f,0.928547f,9.59043e-05f,
1.00382f,0.302528f,-0.0185747f,0.456376f,0.928045f,0.000113364f, 0.988354f,0.32075f,-0.0242623f,0.453427f,0.927487f,0.000134428f,
0.974152f,0.338949f,-0.0287689f,0.45043f,0.926877f,0.000159906f, 0.963123f,0.357729f,-0.0323837f,0.448552f,0.926237f,0.000190648f,
0.952115f,0.376112f,-0.0361362f,0.447167f,0.925554f,0.000227802f, 0.940866f,0.394279f,-0.0397112f,0.445794f,0.924817f,0.000272707f,
0.929423f,0.412339f,-0.0427513f,0.444315f,0.924016f,0.000326876f, 0.917614f,0.430099f,-0.0456523f,0.442915f,0.923155f,0.000392428f,
0.90512f,0.447314f,-0.0486424f,0.441672f,0.922221f,0.00047149f, 0.85936f,0.449176f,-0.0582642f,0.428228f,0.921215f,0.000566887f,
0.840547f,0.46209f,-0.0620348f,0.424514f,0.920134f,0.000682008f, 0.823143f,0.475219f,-0.0653506f,0.421335f,0.918998f,0.000820717f,
0.805864f,0.487958f,-0.0684421f,0.418233f,0.917792f,0.000987623f, 0.788895f,0.500207f,-0.0712918f,0.41521f,0.916505f,0.00118826f,
0.832536f,0.550176f,-0.0647299f,0.436049f,0.915129f,0.00142905f, 0.81541f,0.56371f,-0.067522f,0.433564f,0.913659f,0.00171756f,
0.797524f,0.576308f,-0.0702429f,0.430812f,0.912085f,0.00206257f, 0.744088f,0.562968f,-0.0772251f,0.412627f,0.910405f,0.00247432f,
0.734622f,0.579948f,-0.078324f,0.412808f,0.908608f,0.00296454f, 0.724594f,0.596573f,-0.078832f,0.413109f,0.906691f,0.00354675f,
0.714908f,0.613766f,-0.0796217f,0.413913f,0.904647f,0.00423662f, 0.723912f,0.648893f,-0.0851456f,0.418464f,0.902472f,0.00505148f,
0.756043f,0.658255f,-0.0628049f,0.418754f,0.900184f,0.00601138f, 0.732834f,0.66407f,-0.0643783f,0.412954f,0.89776f,0.00713841f,
0.720234f,0.675719f,-0.0663731f,0.414024f,0.895195f,0.00845775f, 0.690127f,0.673208f,-0.0680558f,0.404273f,0.892479f,0.00999649f,
0.662432f,0.671782f,-0.0687941f,0.395014f,0.889612f,0.0117852f, 0.652145f,0.684468f,-0.06842f,0.395355f,0.886587f,0.0138563f,
0.644199f,0.701669f,-0.0598869f,0.404052f,0.88341f,0.0162455f, 0.634066f,0.7148f,-0.0559087f,0.408621f,0.880085f,0.0189899f,
0.620599f,0.71749f,-0.0566254f,0.410002f,0.876622f,0.0221293f, 0.608665f,0.730645f,-0.0440957f,0.424191f,0.873043f,0.0257046f,
0.597741f,0.750029f,-0.0457879f,0.431401f,0.869373f,0.0297576f, 0.580246f,0.759619f,-0.0489541f,0.439165f,0.865656f,0.0343304f,
0.560837f,0.764168f,-0.0527899f,0.447834f,0.861948f,0.0394641f, 0.546606f,0.774309f,-0.0556579f,0.457277f,0.85836f,0.0451984f,
0.539653f,0.795515f,-0.0567046f,0.46684f,0.855005f,0.0515707f, 0.528515f,0.806758f,-0.0589931f,0.477459f,0.852011f,0.0586157f,
0.550918f,0.852696f,-0.052603f,0.484859f,0.849557f,0.0663644f, 0.231132f,0.380448f,-0.0632377f,0.205029f,0.847882f,0.0748461f,
0.570012f,0.892896f,-0.0375783f,0.518365f,0.847291f,0.0840894f, 0.213268f,0.392279f,-0.0332782f,0.208467f,0.848161f,0.0941208f,
0.211042f,0.368368f,-0.0285067f,0.210585f,0.851028f,0.104982f, 0.1283f,0.224388f,-0.039596f,0.123559f,0.856631f,0.116714f,
0.097427f,0.162315f,-0.0341095f,0.098154f,0.865475f,0.129384f, 0.0877103f,0.137773f,-0.0421624f,0.0694976f,0.878476f,0.143076f,
0.0887372f,0.138438f,-0.0408506f,0.0692578f,0.896622f,0.15791f, 0.0885178f,0.137105f,-0.0360844f,0.0652159f,0.921095f,0.174012f,
0.0688612f,0.101579f,-0.0309727f,0.0529575f,0.953287f,0.191577f, 0.0894565f,0.13472f,-0.024073f,0.0688633f,0.998117f,0.210666f,
1.05134f,-0.00247356f,0.00814502f,0.516072f,0.921331f,2.63956e-05f, 1.04294f,0.0200524f,0.0228864f,0.495818f,0.921288f,2.66227e-05f,
1.04264f,0.0422508f,0.0167343f,0.496656f,0.92122f,2.74826e-05f, 1.04462f,0.061321f,0.0167468f,0.493426f,0.921124f,2.90129e-05f,
1.04443f,0.0834516f,0.0101006f,0.493957f,0.921002f,3.12006e-05f, 1.03554f,0.104223f,0.0124192f,0.49052f,0.920838f,3.41166e-05f,
1.03086f,0.126379f,0.00525189f,0.491247f,0.920633f,3.79097e-05f, 1.0314f,0.151403f,0.00356877f,0.488702f,0.920365f,4.25888e-05f,
1.0143f,0.168953f,0.007953f,0.485558f,0.92009f,4.84396e-05f, 1.06753f,0.198063f,0.0110105f,0.500652f,0.919777f,5.56078e-05f,
1.01573f,0.214796f,-0.0102455f,0.486578f,0.919406f,6.42479e-05f, 1.06893f,0.243803f,0.00597624f,0.502906f,0.918993f,7.47975e-05f,
1.01354f,0.257764f,-0.016207f,0.487437f,0.91852f,8.74413e-05f, 1.01908f,0.279597f,-0.00330794f,0.490053f,0.918031f,0.000102796f,
1.00077f,0.299542f,-0.020374f,0.483247f,0.91749f,0.000121199f, 0.985779f,0.317574f,-0.026197f,0.480233f,0.916904f,0.000143451f,
0.972234f,0.335713f,-0.0307244f,0.477141f,0.916254f,0.000170141f, 0.96179f,0.354051f,-0.0347798f,0.4757f,0.91555f,0.000202363f,
0.951108f,0.372094f,-0.0386447f,0.474244f,0.91478f,0.00024106f, 0.940198f,0.389895f,-0.0423299f,0.472795f,0.913974f,0.000287663f,
0.929503f,0.407869f,-0.0451749f,0.471116f,0.913115f,0.000343763f, 0.91761f,0.424934f,-0.0484383f,0.469743f,0.912189f,0.000411184f,
0.905215f,0.441644f,-0.0515291f,0.468335f,0.911193f,0.000492236f, 0.858728f,0.443048f,-0.0618763f,0.453735f,0.910126f,0.000589697f,
0.841812f,0.456407f,-0.0655418f,0.450374f,0.908978f,0.000706661f, 0.824974f,0.469376f,-0.0689401f,0.447092f,0.907748f,0.000846946f,
0.808419f,0.482106f,-0.0720156f,0.443892f,0.906446f,0.00101501f, 0.792145f,0.494564f,-0.0748923f,0.440898f,0.905073f,0.0012161f,
0.833158f,0.54151f,-0.0682016f,0.461522f,0.903615f,0.00145633f, 0.816686f,0.554969f,-0.0709952f,0.45898f,0.902062f,0.0017428f,
0.799997f,0.567905f,-0.0736314f,0.456394f,0.900412f,0.00208387f, 0.751393f,0.558467f,-0.0797943f,0.438523f,0.898654f,0.00248901f,
0.744232f,0.576702f,-0.0804073f,0.439859f,0.896784f,0.00296916f, 0.73239f,0.591689f,-0.0814528f,0.439139f,0.894799f,0.00353708f,
0.725153f,0.611038f,-0.0810304f,0.440004f,0.892691f,0.00420682f, 0.777052f,0.637967f,-0.064296f,0.447025f,0.890458f,0.00499473f,
0.753686f,0.644364f,-0.0660122f,0.440594f,0.888115f,0.00591884f, 0.736186f,0.653138f,-0.0678449f,0.437993f,0.885656f,0.00699977f,
0.727111f,0.667276f,-0.069135f,0.440243f,0.883068f,0.00825971f, 0.693541f,0.661247f,-0.0713928f,0.427967f,0.88035f,0.00972371f,
0.668025f,0.661338f,-0.0718214f,0.419193f,0.877503f,0.0114192f, 0.66269f,0.678969f,-0.0700164f,0.421669f,0.874528f,0.0133752f,
0.651603f,0.691754f,-0.0591393f,0.432177f,0.871432f,0.0156237f, 0.64204f,0.702364f,-0.0584881f,0.43391f,0.868229f,0.0181986f,
0.629486f,0.706184f,-0.0564195f,0.437634f,0.864936f,0.0211351f, 0.621589f,0.72424f,-0.0452904f,0.450394f,0.861579f,0.0244701f,
0.604268f,0.734212f,-0.0484171f,0.457511f,0.858195f,0.0282411f, 0.584593f,0.739028f,-0.0523203f,0.465532f,0.85484f,0.0324862f,
0.569726f,0.748447f,-0.0552748f,0.474139f,0.851614f,0.0372435f, 0.560616f,0.765137f,-0.0569605f,0.483516f,0.848587f,0.0425501f,
0.549883f,0.777435f,-0.0589459f,0.49288f,0.845868f,0.0484419f, 0.538202f,0.784424f,-0.0615432f,0.503511f,0.843599f,0.0549534f,
0.564609f,0.829234f,-0.0536502f,0.509654f,0.841967f,0.062118f, 0.587391f,0.841626f,-0.0385024f,0.525718f,0.841203f,0.0699678f,
0.590958f,0.873396f,-0.0260365f,0.552917f,0.841597f,0.0785356f, 0.591159f,0.896492f,-0.00558527f,0.595818f,0.843624f,0.0878617f,
0.21799f,0.362707f,-0.0346562f,0.221336f,0.84771f,0.09798f, 0.131841f,0.206994f,-0.0430184f,0.129105f,0.854309f,0.108957f,
0.0999072f,0.147778f,-0.0471148f,0.0799043f,0.86414f,0.120853f, 0.0984227f,0.1441f,-0.0463134f,0.0774842f,0.877973f,0.133759f,
0.114028f,0.169909f,-0.033563f,0.112423f,0.896683f,0.147784f, 0.117712f,0.170736f,-0.0376542f,0.0961896f,0.921275f,0.16307f,
0.0930141f,0.130275f,-0.0247352f,0.0915779f,0.953381f,0.179833f, 0.0921045f,0.126476f,-0.0218059f,0.0900249f,0.998083f,0.198205f,
1.03507f,-6.20242e-06f,0.00173496f,0.545202f,0.910113f,2.85119e-05f, 1.04079f,0.0205535f,0.0239682f,0.523169f,0.910068f,2.87747e-05f,
1.04047f,0.0425286f,0.0175576f,0.524055f,0.909969f,2.96409e-05f, 1.04125f,0.0631938f,0.0134216f,0.523183f,0.909896f,3.132e-05f,
1.04273f,0.0823036f,0.0126783f,0.520089f,0.909759f,3.36604e-05f, 1.03426f,0.103178f,0.0135444f,0.517093f,0.909558f,3.67432e-05f,
1.02992f,0.125238f,0.00612273f,0.518144f,0.909339f,4.07877e-05f, 1.03238f,0.150381f,0.00302489f,0.518538f,0.909076f,4.57908e-05f,
1.01765f,0.168798f,0.00720935f,0.515684f,0.908774f,5.20188e-05f, 1.04143f,0.192992f,0.00690689f,0.523433f,0.908412f,5.959e-05f,
1.01197f,0.212685f,-0.0128566f,0.514583f,0.908007f,6.87729e-05f, 1.06203f,0.240952f,0.00422649f,0.530729f,0.907574f,7.99013e-05f,
0.999894f,0.253365f,-0.0220519f,0.512227f,0.907088f,9.32726e-05f, 1.01538f,0.277282f,-0.00780738f,0.516051f,0.906549f,0.000109385f,
0.997892f,0.296293f,-0.0221506f,0.510411f,0.905949f,0.000128715f, 0.983966f,0.31438f,-0.0277684f,0.507337f,0.905303f,0.00015192f,
0.970703f,0.33206f,-0.0329455f,0.50467f,0.904619f,0.000179806f, 0.960523f,0.350118f,-0.0371343f,0.50318f,0.903875f,0.000213194f,
0.950127f,0.367848f,-0.0411236f,0.501666f,0.903072f,0.000253291f, 0.939665f,0.385377f,-0.0448072f,0.50011f,0.902201f,0.000301348f,
0.92928f,0.402909f,-0.0477951f,0.498394f,0.901259f,0.000358907f, 0.917739f,0.419552f,-0.0511532f,0.496952f,0.900264f,0.000427869f,
0.905942f,0.436291f,-0.0543202f,0.495632f,0.899212f,0.000510484f, 0.859732f,0.437339f,-0.0652065f,0.480117f,0.898089f,0.000609302f,
0.843395f,0.450453f,-0.0689334f,0.476672f,0.896889f,0.000727413f, 0.827125f,0.463206f,-0.0724082f,0.473291f,0.895608f,0.000868457f,
0.811399f,0.475936f,-0.0754044f,0.469999f,0.89424f,0.0010367f, 0.79678f,0.488847f,-0.0781238f,0.46736f,0.892783f,0.00123711f,
0.834102f,0.532316f,-0.0715294f,0.487245f,0.891246f,0.00147546f, 0.818589f,0.545804f,-0.0742516f,0.484761f,0.88963f,0.00175846f,
0.804168f,0.559889f,-0.0762447f,0.482442f,0.887921f,0.00209383f, 0.759222f,0.553186f,-0.0819589f,0.464839f,0.886114f,0.00249056f,
0.749811f,0.56934f,-0.0828668f,0.464933f,0.884202f,0.00295877f, 0.740942f,0.585989f,-0.0835844f,0.465573f,0.882181f,0.00351006f,
0.732133f,0.602842f,-0.0842343f,0.466517f,0.880048f,0.00415766f, 0.774625f,0.624141f,-0.0675497f,0.469536f,0.8778f,0.00491628f,
0.756555f,0.632337f,-0.0742562f,0.463663f,0.875436f,0.00580267f, 0.741331f,0.642443f,-0.0713857f,0.464534f,0.87297f,0.00683525f,
0.734481f,0.65851f,-0.0715844f,0.466992f,0.870407f,0.00803455f, 0.697148f,0.648637f,-0.0746511f,0.451897f,0.867737f,0.0094229f,
0.674855f,0.650374f,-0.0752034f,0.444342f,0.864968f,0.0110251f, 0.66876f,0.667389f,-0.0701232f,0.448534f,0.862103f,0.0128676f,
0.657971f,0.679877f,-0.0608345f,0.456569f,0.859156f,0.014979f, 0.650997f,0.689276f,-0.0610205f,0.459821f,0.856142f,0.0173894f,
0.638152f,0.693592f,-0.0563865f,0.464485f,0.853089f,0.0201311f, 0.628518f,0.709085f,-0.0476846f,0.476687f,0.850026f,0.0232371f,
0.608733f,0.714388f,-0.0516441f,0.484116f,0.846997f,0.0267416f, 0.593687f,0.723873f,-0.054581f,0.491983f,0.844083f,0.0306797f,
0.579598f,0.732631f,-0.0574727f,0.500603f,0.841365f,0.0350864f, 0.573304f,0.752033f,-0.0583228f,0.509413f,0.838925f,0.0399971f,
0.562215f,0.758033f,-0.0606159f,0.518545f,0.836873f,0.0454462f, 0.565311f,0.762093f,-0.0594002f,0.525198f,0.835357f,0.0514687f,
0.587944f,0.814591f,-0.0517067f,0.533015f,0.834557f,0.058099f, 0.613244f,0.83267f,-0.0341285f,0.552834f,0.834698f,0.0653723f,
0.608067f,0.847645f,-0.020689f,0.580694f,0.836148f,0.0733262f, 0.603691f,0.86288f,-0.00939554f,0.61318f,0.83924f,0.082002f,
0.232771f,0.382453f,-0.0335132f,0.231468f,0.844309f,0.0914496f, 0.166547f,0.242809f,-0.0326634f,0.185042f,0.851885f,0.10172f,
0.225954f,0.360867f,-0.0211815f,0.234363f,0.862655f,0.112898f, 0.129626f,0.194402f,-0.036139f,0.126279f,0.877174f,0.125065f,
0.129924f,0.179984f,-0.0364022f,0.126714f,0.896252f,0.138335f, 0.21637f,0.319365f,-0.0144996f,0.225789f,0.921055f,0.152868f,
0.119067f,0.15565f,-0.0282049f,0.113931f,0.953229f,0.168876f, 0.0964795f,0.121243f,-0.0249314f,0.0963129f,0.998039f,0.186585f,
1.02665f,0.00186649f,-0.00109475f,0.573694f,0.897842f,3.05806e-05f, 1.03803f,0.0210562f,0.0235441f,0.551544f,0.897795f,3.08646e-05f,
1.03782f,0.0427864f,0.0172703f,0.552255f,0.89771f,3.1826e-05f, 1.03738f,0.0644338f,0.0121275f,0.552041f,0.897625f,3.35925e-05f,
1.03911f,0.0834081f,0.00992119f,0.549502f,0.897465f,3.60488e-05f, 1.03119f,0.103551f,0.0120105f,0.546016f,0.897261f,3.93474e-05f,
1.02838f,0.124327f,0.00630507f,0.545586f,0.897034f,4.36208e-05f, 1.02993f,0.148454f,0.00116262f,0.547404f,0.896747f,4.89122e-05f,
1.01671f,0.167245f,0.00578757f,0.544925f,0.896411f,5.54783e-05f, 1.04555f,0.1916f,0.00594256f,0.554875f,0.89603f,6.34329e-05f,
1.06316f,0.216001f,0.00600169f,0.559708f,0.895617f,7.31339e-05f, 1.02211f,0.233025f,-0.0135403f,0.548015f,0.895143f,8.47627e-05f,
1.04081f,0.257176f,-0.00908027f,0.554583f,0.894615f,9.87965e-05f, 1.01226f,0.272707f,-0.00578836f,0.544972f,0.894036f,0.000115584f,
0.995134f,0.292698f,-0.023918f,0.537775f,0.893418f,0.000135728f, 0.980952f,0.310353f,-0.0300699f,0.534655f,0.892744f,0.000159836f,
0.969262f,0.328056f,-0.0351219f,0.532443f,0.892005f,0.000188637f, 0.959375f,0.345837f,-0.0394113f,0.530912f,0.891204f,0.00022312f,
0.949261f,0.363262f,-0.043507f,0.529344f,0.890352f,0.000264313f, 0.939032f,0.380392f,-0.0473836f,0.527788f,0.889445f,0.000313491f,
0.929135f,0.397664f,-0.0503467f,0.525958f,0.888474f,0.000372215f, 0.917974f,0.413903f,-0.0537933f,0.524469f,0.887433f,0.000442321f,
0.907444f,0.430914f,-0.0575489f,0.523134f,0.886318f,0.000525921f, 0.86101f,0.431368f,-0.0683621f,0.506897f,0.885126f,0.000625523f,
0.845379f,0.444256f,-0.0721442f,0.503406f,0.883875f,0.000744082f, 0.828984f,0.457809f,-0.0757568f,0.500024f,0.882553f,0.000885071f,
0.814588f,0.469289f,-0.0786846f,0.496519f,0.88115f,0.00105253f, 0.801704f,0.482647f,-0.081141f,0.494243f,0.879663f,0.00125116f,
0.836313f,0.523292f,-0.0744011f,0.513509f,0.878086f,0.00148639f, 0.822705f,0.537614f,-0.0763334f,0.510943f,0.876416f,0.00176451f,
0.809258f,0.551802f,-0.0781034f,0.508612f,0.874656f,0.00209278f, 0.767315f,0.547058f,-0.0838313f,0.491565f,0.872818f,0.00247945f,
0.758407f,0.562967f,-0.0847004f,0.491778f,0.870891f,0.00293388f, 0.749651f,0.579077f,-0.0854908f,0.492376f,0.868869f,0.00346691f,
0.741128f,0.595464f,-0.0862099f,0.493437f,0.866748f,0.00409046f, 0.773331f,0.610518f,-0.0708875f,0.492884f,0.864527f,0.00481814f,
0.756426f,0.619346f,-0.0728138f,0.489661f,0.862209f,0.00566528f, 0.746746f,0.630943f,-0.0748589f,0.491479f,0.859791f,0.00664836f,
0.742648f,0.649847f,-0.0734661f,0.494248f,0.85728f,0.00778623f, 0.701052f,0.635391f,-0.0777869f,0.476021f,0.854702f,0.00909903f,
0.68359f,0.641224f,-0.0773869f,0.470263f,0.852062f,0.0106093f, 0.675828f,0.656995f,-0.0645472f,0.48161f,0.849364f,0.0123406f,
0.667094f,0.66831f,-0.0628798f,0.482739f,0.846625f,0.0143189f, 0.660008f,0.675408f,-0.0627301f,0.486333f,0.843865f,0.0165716f,
0.64674f,0.679358f,-0.0551998f,0.493025f,0.841114f,0.0191275f, 0.635074f,0.692264f,-0.0502242f,0.503356f,0.838409f,0.022017f,
0.618474f,0.700207f,-0.0535511f,0.510662f,0.835799f,0.0252714f, 0.603168f,0.707794f,-0.0566568f,0.518402f,0.833354f,0.0289226f,
0.590627f,0.716973f,-0.0593172f,0.527113f,0.831183f,0.0330041f, 0.585081f,0.735598f,-0.0598612f,0.535481f,0.829365f,0.0375492f,
0.575639f,0.738024f,-0.061864f,0.543975f,0.828011f,0.0425915f, 0.576911f,0.752f,-0.0607172f,0.551927f,0.827264f,0.0481661f,
0.611707f,0.797491f,-0.0404168f,0.565229f,0.827299f,0.0543081f, 0.617133f,0.790726f,-0.0376488f,0.574179f,0.828364f,0.0610551f,
0.621967f,0.818564f,-0.0232065f,0.600744f,0.830796f,0.0684474f, 0.61613f,0.829363f,-0.0142127f,0.629374f,0.834825f,0.076529f,
0.609613f,0.839403f,-0.00550391f,0.660183f,0.840814f,0.0853554f, 0.250177f,0.361878f,-0.030094f,0.259697f,0.849394f,0.0949859f,
0.548269f,0.829035f,-0.0086953f,0.675115f,0.860857f,0.105493f, 0.222883f,0.341891f,-0.0260629f,0.233947f,0.876026f,0.116975f,
0.610364f,0.818963f,0.0220315f,0.770557f,0.89559f,0.129547f, 0.607637f,0.817782f,0.0130536f,0.795427f,0.920468f,0.143357f,
0.655757f,0.683745f,0.00589548f,0.737739f,0.952847f,0.158664f, 0.142104f,0.158735f,-0.0653916f,0.11532f,0.997986f,0.175755f,
1.02922f,0.00243977f,0.00144722f,0.601335f,0.88453f,3.26268e-05f, 1.02825f,0.0226935f,0.0107794f,0.587037f,0.884481f,3.29211e-05f,
1.03395f,0.0430291f,0.0148546f,0.581508f,0.884401f,3.39622e-05f, 1.03571f,0.0640798f,0.013392f,0.579179f,0.884304f,3.58062e-05f,
1.03556f,0.082958f,0.0120014f,0.576432f,0.884131f,3.83792e-05f, 1.02705f,0.104671f,0.0094313f,0.575541f,0.883927f,4.18835e-05f,
1.02438f,0.125012f,0.00371952f,0.57499f,0.883676f,4.63298e-05f, 1.02666f,0.146362f,-0.00109569f,0.576101f,0.883379f,5.19307e-05f,
1.01743f,0.165994f,0.00436847f,0.574867f,0.883018f,5.8763e-05f, 1.05712f,0.19108f,0.00688811f,0.587224f,0.882632f,6.71434e-05f,
0.996083f,0.203744f,-0.00414767f,0.570691f,0.882185f,7.72153e-05f, 1.04735f,0.23257f,-0.000207252f,0.586713f,0.881684f,8.93799e-05f,
1.03675f,0.252021f,-0.00437988f,0.584835f,0.881131f,0.000103924f, 1.00815f,0.268496f,-0.00754857f,0.572681f,0.880536f,0.000121354f,
0.991672f,0.288439f,-0.0262157f,0.565279f,0.879884f,0.000142179f, 0.978041f,0.305877f,-0.0324199f,0.562142f,0.879167f,0.000167002f,
0.968345f,0.323808f,-0.0368283f,0.560207f,0.878394f,0.000196631f, 0.958487f,0.341198f,-0.0414749f,0.558764f,0.877574f,0.000231947f,
0.948575f,0.358282f,-0.0457783f,0.557229f,0.876693f,0.000273983f, 0.938556f,0.375213f,-0.0497231f,0.555648f,0.875744f,0.000324014f,
0.929173f,0.392008f,-0.0527541f,0.553743f,0.874724f,0.000383539f, 0.918406f,0.407885f,-0.0562954f,0.552221f,0.873644f,0.000454328f,
0.907527f,0.423487f,-0.0596014f,0.55075f,0.872506f,0.000538417f, 0.862505f,0.425099f,-0.071366f,0.53399f,0.871297f,0.000638205f,
0.84664f,0.438716f,-0.0753539f,0.530525f,0.870013f,0.000756526f, 0.830163f,0.453155f,-0.0791377f,0.527277f,0.868649f,0.000896673f,
0.818352f,0.462465f,-0.0815966f,0.523408f,0.867204f,0.00106245f, 0.806931f,0.475958f,-0.0838957f,0.521505f,0.865694f,0.00125829f,
0.840317f,0.515006f,-0.0761198f,0.540029f,0.86411f,0.00148931f, 0.827288f,0.52903f,-0.0780469f,0.537422f,0.862445f,0.00176138f,
0.813993f,0.542559f,-0.0800565f,0.535033f,0.860693f,0.00208114f, 0.757208f,0.550242f,-0.0938782f,0.523911f,0.858854f,0.00245634f,
0.766688f,0.555215f,-0.0865157f,0.518899f,0.856926f,0.00289562f, 0.758147f,0.570691f,-0.0873958f,0.519526f,0.854915f,0.00340884f,
0.749672f,0.586262f,-0.0883138f,0.520589f,0.852836f,0.00400706f, 0.769801f,0.59428f,-0.0751312f,0.515513f,0.850679f,0.00470256f,
0.761507f,0.607561f,-0.0762884f,0.516985f,0.848447f,0.00550941f, 0.753351f,0.619856f,-0.0776254f,0.518852f,0.84614f,0.00644261f,
0.743039f,0.633461f,-0.0766002f,0.51733f,0.843765f,0.00751909f, 0.704324f,0.620965f,-0.0807015f,0.499512f,0.841332f,0.00875738f,
0.692659f,0.631434f,-0.078148f,0.497542f,0.838852f,0.0101774f, 0.684085f,0.644203f,-0.0665162f,0.508114f,0.83636f,0.0118011f,
0.676093f,0.653973f,-0.0651921f,0.509112f,0.833878f,0.0136515f, 0.670112f,0.659947f,-0.0652514f,0.511911f,0.831425f,0.0157537f,
0.656117f,0.66503f,-0.0537745f,0.521608f,0.82903f,0.0181336f, 0.645803f,0.679227f,-0.0516158f,0.529913f,0.826737f,0.0208194f,
0.630526f,0.687628f,-0.0547068f,0.537075f,0.824595f,0.0238397f, 0.61532f,0.693872f,-0.058032f,0.54512f,0.82267f,0.0272246f,
0.601836f,0.699952f,-0.0610272f,0.553635f,0.821062f,0.0310051f, 0.596208f,0.716305f,-0.0615509f,0.561658f,0.81989f,0.0352133f,
0.590528f,0.71661f,-0.0624941f,0.568735f,0.819251f,0.0398823f, 0.601401f,0.738519f,-0.0584498f,0.575832f,0.819281f,0.0450465f,
0.634406f,0.764742f,-0.0376552f,0.586813f,0.820145f,0.0507423f, 0.628477f,0.789124f,-0.0365712f,0.602673f,0.822106f,0.0570082f,
0.632081f,0.784437f,-0.0311551f,0.616863f,0.825435f,0.0638864f, 0.628019f,0.795704f,-0.0219707f,0.643296f,0.830345f,0.071425f,
0.622373f,0.804407f,-0.0149972f,0.671068f,0.837284f,0.0796768f, 0.630386f,0.785911f,-0.0211384f,0.675231f,0.846614f,0.0887112f,
0.609206f,0.817606f,-0.00228102f,0.7342f,0.858895f,0.0986023f, 0.603913f,0.805695f,-0.00869432f,0.752608f,0.874626f,0.109444f,
0.618608f,0.776913f,-0.00667089f,0.760324f,0.894596f,0.121357f, 0.22712f,0.286901f,-0.0297666f,0.246403f,0.919802f,0.134501f,
0.648103f,0.689968f,-0.000784097f,0.773416f,0.952255f,0.149154f, 0.654245f,0.622626f,-0.00380803f,0.747495f,0.997924f,0.165667f,
1.02994f,0.00283353f,0.00319494f,0.628836f,0.870148f,3.4561e-05f, 1.03092f,0.0222206f,0.018696f,0.61019f,0.87012f,3.49124e-05f,
1.03054f,0.0427593f,0.0125864f,0.610587f,0.870045f,3.603e-05f, 1.03455f,0.0633554f,0.0147736f,0.606369f,0.869926f,3.79115e-05f,
1.03274f,0.0842495f,0.00852574f,0.606269f,0.869768f,4.06627e-05f, 1.02842f,0.105023f,0.00399428f,0.60566f,0.86954f,4.42749e-05f,
1.02377f,0.125405f,-0.000643899f,0.604839f,0.869288f,4.89619e-05f, 1.02338f,0.144376f,-0.00337888f,0.604856f,0.868972f,5.47588e-05f,
1.02476f,0.164348f,0.00388135f,0.607252f,0.868606f,6.19164e-05f, 1.03513f,0.18592f,0.00203208f,0.611795f,0.868197f,7.05795e-05f,
1.02266f,0.204958f,-0.00218521f,0.60829f,0.867738f,8.10655e-05f, 0.998533f,0.224779f,-0.0248963f,0.598728f,0.867213f,9.36191e-05f,
0.998402f,0.244824f,-0.027322f,0.599154f,0.866647f,0.000108641f, 1.00442f,0.263951f,-0.00926373f,0.600421f,0.866032f,0.000126604f,
0.988577f,0.283765f,-0.0284138f,0.592856f,0.865353f,0.00014797f, 0.97638f,0.30124f,-0.0340706f,0.589704f,0.864612f,0.000173392f,
0.967562f,0.319007f,-0.038441f,0.588048f,0.863828f,0.000203655f, 0.958027f,0.336151f,-0.043149f,0.586586f,0.862984f,0.000239582f,
0.948276f,0.35286f,-0.047702f,0.585113f,0.862075f,0.000282222f, 0.938386f,0.369543f,-0.0519248f,0.583631f,0.861096f,0.000332803f,
0.929201f,0.385701f,-0.0552536f,0.581763f,0.860067f,0.000392768f, 0.919033f,0.401398f,-0.0586565f,0.580121f,0.858976f,0.000463807f,
0.89747f,0.411988f,-0.0631696f,0.57447f,0.857817f,0.000547881f, 0.864546f,0.417853f,-0.0705643f,0.5633f,0.856585f,0.000647298f,
0.848853f,0.433657f,-0.0778718f,0.558024f,0.85528f,0.000764737f, 0.834205f,0.445218f,-0.0817266f,0.554412f,0.853918f,0.00090331f,
0.822255f,0.455043f,-0.0843659f,0.550582f,0.852486f,0.00106659f, 0.812412f,0.468758f,-0.0863843f,0.549093f,0.850981f,0.00125876f,
0.842546f,0.50457f,-0.0787036f,0.566769f,0.849399f,0.00148454f, 0.828581f,0.516931f,-0.0817272f,0.563954f,0.847738f,0.00174941f,
0.816454f,0.530484f,-0.08336f,0.561548f,0.846007f,0.0020596f, 0.764231f,0.543287f,-0.0966189f,0.552415f,0.844215f,0.00242215f,
0.77437f,0.545849f,-0.088575f,0.54633f,0.842352f,0.00284509f, 0.765863f,0.560408f,-0.0896926f,0.546964f,0.840417f,0.00333742f,
0.757291f,0.574857f,-0.0908894f,0.548019f,0.838414f,0.00390938f, 0.74874f,0.589258f,-0.0921219f,0.549517f,0.836341f,0.00457199f,
0.742627f,0.603418f,-0.0920755f,0.550962f,0.834211f,0.00533802f, 0.761795f,0.610251f,-0.0790516f,0.546705f,0.832049f,0.00622147f,
0.743273f,0.616089f,-0.0797249f,0.540051f,0.829852f,0.00723743f, 0.709788f,0.606788f,-0.0834347f,0.524325f,0.827629f,0.00840265f,
0.700304f,0.618368f,-0.0758206f,0.528204f,0.825396f,0.00973547f, 0.692975f,0.63039f,-0.0684571f,0.534621f,0.823169f,0.0112553f,
0.685405f,0.63852f,-0.0671344f,0.535357f,0.820974f,0.0129837f, 0.680127f,0.644089f,-0.0658201f,0.538838f,0.818849f,0.0149429f,
0.665373f,0.648828f,-0.0517552f,0.550796f,0.81685f,0.0171574f, 0.657847f,0.666434f,-0.052514f,0.556467f,0.815008f,0.0196523f,
0.640164f,0.670404f,-0.0566107f,0.564177f,0.813374f,0.0224546f, 0.624016f,0.67359f,-0.0603119f,0.571968f,0.812014f,0.0255924f,
0.615468f,0.684948f,-0.0618655f,0.579917f,0.811005f,0.0290951f, 0.608253f,0.696866f,-0.0626027f,0.587967f,0.810473f,0.0329934f,
0.606203f,0.696187f,-0.0628064f,0.593906f,0.810553f,0.0373198f, 0.625005f,0.721203f,-0.0484409f,0.604845f,0.811356f,0.0421084f,
0.640681f,0.746631f,-0.0395354f,0.613783f,0.813035f,0.0473957f, 0.632105f,0.751672f,-0.0407704f,0.627153f,0.815839f,0.0532211f,
0.640694f,0.746515f,-0.0358685f,0.63618f,0.820018f,0.0596285f, 0.631984f,0.748556f,-0.0361786f,0.654778f,0.825761f,0.0666672f,
0.633407f,0.768185f,-0.0272267f,0.679699f,0.833558f,0.0743935f, 0.267387f,0.335372f,-0.0517866f,0.285561f,0.843624f,0.082873f,
0.626568f,0.784251f,0.00497276f,0.754719f,0.856535f,0.0921883f, 0.62499f,0.777864f,-0.0103372f,0.770583f,0.872833f,0.102435f,
0.634019f,0.742224f,-0.00837316f,0.770537f,0.89316f,0.113732f, 0.621511f,0.695874f,-0.000375444f,0.732898f,0.918782f,0.126254f,
0.652448f,0.75413f,-0.00311337f,0.794966f,0.951457f,0.140296f, 0.69155f,0.632869f,0.00886468f,0.789467f,0.997854f,0.156274f,
1.02623f,0.00347136f,0.00227129f,0.656594f,0.854743f,3.64287e-05f, 1.01899f,0.024199f,0.000160927f,0.649054f,0.854729f,3.68396e-05f,
1.02732f,0.0428602f,0.0104733f,0.639529f,0.854653f,3.7986e-05f, 1.03064f,0.0626703f,0.0121157f,0.635216f,0.854529f,3.99625e-05f,
1.03016f,0.083232f,0.00775392f,0.634269f,0.85436f,4.2789e-05f, 1.02748f,0.103768f,0.00217138f,0.633948f,0.854142f,4.65852e-05f,
1.02624f,0.12402f,-0.00257604f,0.634065f,0.853866f,5.14008e-05f, 1.02132f,0.143266f,-0.00426079f,0.6335f,0.853554f,5.74457e-05f,
1.02351f,0.161847f,0.00246737f,0.636434f,0.853176f,6.48172e-05f, 1.00808f,0.180155f,-0.00277312f,0.632457f,0.852756f,7.37787e-05f,
0.99862f,0.198603f,-0.0069432f,0.630326f,0.852287f,8.45707e-05f, 0.989567f,0.216737f,-0.0108495f,0.628291f,0.851755f,9.74723e-05f,
0.996305f,0.24078f,-0.0296328f,0.627514f,0.851176f,0.000112899f, 1.00107f,0.258973f,-0.0109235f,0.628117f,0.850549f,0.00013126f,
0.985878f,0.278588f,-0.0304878f,0.620421f,0.849859f,0.000153061f, 0.975839f,0.296227f,-0.0351161f,0.617358f,0.849109f,0.000178934f,
0.966947f,0.313548f,-0.0399564f,0.61589f,0.848315f,0.000209627f, 0.957752f,0.330427f,-0.0447017f,0.61442f,0.847461f,0.000245967f,
0.948297f,0.347615f,-0.0490746f,0.612969f,0.846541f,0.00028896f, 0.938721f,0.363339f,-0.0536163f,0.611492f,0.845562f,0.000339793f,
0.928508f,0.382637f,-0.0570675f,0.610317f,0.844531f,0.000399843f, 0.918285f,0.39874f,-0.0609566f,0.608998f,0.843437f,0.000470742f,
0.890886f,0.401741f,-0.0662232f,0.599291f,0.842276f,0.000554355f, 0.867585f,0.411647f,-0.0701256f,0.59211f,0.841047f,0.000652869f,
0.85227f,0.427184f,-0.0790002f,0.586077f,0.839765f,0.000768822f, 0.838596f,0.436849f,-0.0840127f,0.581781f,0.838421f,0.000905136f,
0.825485f,0.450973f,-0.0871696f,0.579398f,0.837007f,0.00106517f, 0.81484f,0.46721f,-0.089645f,0.578915f,0.835524f,0.00125279f,
0.80368f,0.48764f,-0.0917076f,0.579683f,0.833977f,0.0014725f, 0.800832f,0.488187f,-0.0915947f,0.574878f,0.832376f,0.00172928f,
0.818731f,0.517382f,-0.0869022f,0.588234f,0.830715f,0.0020289f, 0.774798f,0.529499f,-0.0976861f,0.578929f,0.828991f,0.00237793f,
0.781079f,0.534486f,-0.0912506f,0.574031f,0.827204f,0.00278362f, 0.772695f,0.548101f,-0.0925562f,0.574637f,0.825359f,0.00325433f,
0.763027f,0.560836f,-0.0939957f,0.574722f,0.823477f,0.00379934f, 0.757331f,0.576673f,-0.0942337f,0.577138f,0.821557f,0.00442877f,
0.772875f,0.581371f,-0.0827393f,0.572351f,0.819604f,0.00515435f, 0.768453f,0.59804f,-0.080636f,0.573583f,0.817623f,0.00598846f,
0.745294f,0.599018f,-0.082533f,0.563508f,0.815627f,0.0069451f, 0.71576f,0.591849f,-0.0858332f,0.549113f,0.813629f,0.00803951f,
0.708526f,0.604081f,-0.0752196f,0.557244f,0.81167f,0.00928814f, 0.70117f,0.614625f,-0.0700524f,0.560414f,0.809763f,0.010709f,
0.696744f,0.622518f,-0.0689578f,0.562441f,0.80793f,0.0123213f, 0.689367f,0.627709f,-0.0636554f,0.567487f,0.806202f,0.0141459f,
0.679726f,0.638327f,-0.0517406f,0.577127f,0.804617f,0.0162048f, 0.663493f,0.644631f,-0.0553483f,0.583871f,0.803229f,0.0185217f,
0.647196f,0.64846f,-0.0591668f,0.591203f,0.802121f,0.0211216f, 0.63972f,0.661749f,-0.0602314f,0.598132f,0.801346f,0.0240308f,
0.629264f,0.668891f,-0.0624596f,0.606094f,0.800975f,0.0272774f, 0.620649f,0.676493f,-0.0639551f,0.613688f,0.801101f,0.030891f,
0.627736f,0.679057f,-0.0607994f,0.617371f,0.801874f,0.034903f, 0.643096f,0.699606f,-0.0463295f,0.628244f,0.803437f,0.0393474f,
0.65531f,0.720728f,-0.0387139f,0.637632f,0.805912f,0.0442605f, 0.647491f,0.725396f,-0.0397361f,0.650833f,0.80951f,0.0496826f,
0.639812f,0.72882f,-0.0408566f,0.665446f,0.814499f,0.0556579f, 0.648344f,0.730551f,-0.0350404f,0.676743f,0.821054f,0.0622369f,
0.646028f,0.732481f,-0.0298296f,0.696607f,0.829599f,0.0694777f, 0.632619f,0.724463f,-0.0350444f,0.711971f,0.840413f,0.0774475f,
0.634414f,0.737427f,-0.0275496f,0.743011f,0.853944f,0.0862266f, 0.640747f,0.729487f,-0.0175899f,0.765222f,0.870766f,0.0959159f,
0.645334f,0.699578f,-0.0107974f,0.752811f,0.891587f,0.106643f, 0.651214f,0.683528f,0.0179534f,0.782157f,0.917434f,0.118585f,
0.625251f,0.565973f,0.00358909f,0.719655f,0.950464f,0.132047f, 0.69529f,0.617807f,0.00783774f,0.812413f,0.997777f,0.147532f,
1.01671f,0.00450128f,-0.000117565f,0.682295f,0.838358f,3.82686e-05f, 1.02492f,0.0219841f,0.0150415f,0.667429f,0.838325f,3.86419e-05f,
1.03034f,0.041237f,0.0165932f,0.664495f,0.838251f,3.98469e-05f, 1.02965f,0.0615662f,0.0103943f,0.664677f,0.838129f,4.18782e-05f,
1.02667f,0.0817796f,0.00474953f,0.663222f,0.837952f,4.48083e-05f, 1.02376f,0.101756f,-0.00051952f,0.662725f,0.837734f,4.871e-05f,
1.02814f,0.122778f,-0.0036828f,0.664804f,0.837459f,5.36903e-05f, 1.01877f,0.142381f,-0.00485471f,0.661537f,0.837137f,5.9896e-05f,
1.0188f,0.158587f,0.000725778f,0.663904f,0.836765f,6.74766e-05f, 1.01153f,0.17752f,-0.0037532f,0.663107f,0.836336f,7.66738e-05f,
1.00154f,0.196225f,-0.00793799f,0.660603f,0.835864f,8.77152e-05f, 0.994195f,0.213621f,-0.0113846f,0.658265f,0.835336f,0.000100901f,
0.988678f,0.235102f,-0.0319697f,0.653219f,0.834751f,0.000116622f, 0.998136f,0.253476f,-0.0124941f,0.655685f,0.834122f,0.000135291f,
0.983621f,0.272801f,-0.0324105f,0.647889f,0.833436f,0.000157404f, 0.975118f,0.290325f,-0.0364822f,0.645102f,0.832689f,0.000183571f,
0.966515f,0.307402f,-0.041362f,0.64366f,0.831894f,0.000214508f, 0.957685f,0.323928f,-0.0461324f,0.642181f,0.831047f,0.000251047f,
0.948455f,0.341894f,-0.0502391f,0.640809f,0.830137f,0.000294145f, 0.93917f,0.357958f,-0.054656f,0.63938f,0.829169f,0.000344937f,
0.929735f,0.373745f,-0.0588831f,0.637985f,0.828152f,0.00040475f, 0.920025f,0.389468f,-0.0628547f,0.636674f,0.827076f,0.000475117f,
0.898178f,0.395739f,-0.0677604f,0.629107f,0.825937f,0.000557829f, 0.870789f,0.40456f,-0.0716943f,0.619779f,0.82474f,0.000654944f,
0.856131f,0.419432f,-0.0803073f,0.613952f,0.823494f,0.000768852f, 0.841776f,0.433381f,-0.0853558f,0.609896f,0.822189f,0.000902299f,
0.831352f,0.442151f,-0.088979f,0.607246f,0.820823f,0.00105845f, 0.821099f,0.458138f,-0.0914687f,0.606824f,0.819397f,0.0012409f,
0.810395f,0.476793f,-0.0937093f,0.60734f,0.817926f,0.00145373f, 0.800378f,0.490677f,-0.0962428f,0.607033f,0.816405f,0.00170169f,
0.804209f,0.494658f,-0.0933419f,0.60442f,0.814832f,0.00199005f, 0.79297f,0.510053f,-0.0942302f,0.602621f,0.813207f,0.0023248f,
0.785193f,0.522976f,-0.0953924f,0.6027f,0.81154f,0.00271271f, 0.779912f,0.53514f,-0.0950719f,0.602442f,0.809845f,0.00316125f,
0.77319f,0.549377f,-0.095396f,0.603417f,0.808124f,0.00367912f, 0.768073f,0.56443f,-0.0946292f,0.604686f,0.806379f,0.00427556f,
0.781371f,0.570208f,-0.0837633f,0.600487f,0.804615f,0.00496091f, 0.770596f,0.58068f,-0.0832118f,0.597804f,0.802851f,0.00574682f,
0.749738f,0.582237f,-0.0849575f,0.58816f,0.801115f,0.00664589f, 0.726105f,0.579443f,-0.0869079f,0.576204f,0.799415f,0.00767201f,
0.717621f,0.589314f,-0.0740123f,0.58656f,0.797768f,0.00884014f, 0.711287f,0.599135f,-0.0711306f,0.58677f,0.796197f,0.0101669f,
0.707867f,0.605255f,-0.0698728f,0.589045f,0.794728f,0.0116696f, 0.693466f,0.611111f,-0.0544181f,0.600901f,0.793423f,0.0133676f,
0.687368f,0.619196f,-0.0537591f,0.604451f,0.792315f,0.0152813f, 0.670511f,0.62312f,-0.0578728f,0.611485f,0.791442f,0.0174324f,
0.658845f,0.631051f,-0.0602234f,0.617882f,0.790861f,0.0198447f, 0.653386f,0.645582f,-0.0605992f,0.624368f,0.790649f,0.0225428f,
0.644123f,0.651695f,-0.0624627f,0.631701f,0.790915f,0.0255535f, 0.639701f,0.666529f,-0.0622007f,0.638316f,0.791729f,0.0289055f,
0.643933f,0.674795f,-0.0533575f,0.649184f,0.793188f,0.0326293f, 0.662492f,0.678364f,-0.0432558f,0.651106f,0.795473f,0.0367582f,
0.663866f,0.689455f,-0.040103f,0.661298f,0.79872f,0.0413285f, 0.662192f,0.698033f,-0.0383559f,0.673464f,0.803074f,0.0463803f,
0.654785f,0.700209f,-0.0385952f,0.686177f,0.808833f,0.0519586f, 0.649142f,0.703262f,-0.0388941f,0.701909f,0.81615f,0.0581144f,
0.589276f,0.621078f,-0.0459153f,0.667296f,0.825392f,0.0649063f, 0.640759f,0.701731f,-0.0366682f,0.734013f,0.836887f,0.0724036f,
0.647265f,0.705964f,-0.0278322f,0.753719f,0.851034f,0.0806882f, 0.661477f,0.680417f,-0.0223449f,0.766818f,0.868361f,0.089862f,
0.658204f,0.662943f,-0.0038537f,0.7599f,0.889601f,0.100055f, 0.644589f,0.621396f,0.00348676f,0.764256f,0.915889f,0.111457f,
0.626095f,0.55897f,-0.00127435f,0.744952f,0.949359f,0.124376f, 0.616932f,0.550831f,0.0063763f,0.764618f,0.997692f,0.139397f,
1.0113f,0.00499188f,-0.000242729f,0.707403f,0.820992f,3.9958e-05f, 1.02257f,0.0218734f,0.0136435f,0.695314f,0.820945f,4.03186e-05f,
1.0367f,0.0399955f,0.0178049f,0.69627f,0.820883f,4.15743e-05f, 1.03986f,0.059673f,0.013177f,0.697642f,0.82075f,4.36435e-05f,
1.02318f,0.0800159f,0.00189774f,0.691931f,0.820588f,4.66711e-05f, 1.01985f,0.104214f,-0.00153513f,0.69189f,0.820362f,5.06585e-05f,
1.02405f,0.123156f,-0.0052982f,0.693726f,0.820095f,5.57721e-05f, 1.01839f,0.141612f,-0.00588675f,0.692122f,0.819776f,6.21168e-05f,
1.01083f,0.158833f,-0.00126076f,0.690738f,0.819402f,6.98578e-05f, 1.00814f,0.17667f,-0.00551366f,0.691884f,0.818988f,7.92395e-05f,
0.986807f,0.19785f,-0.0112943f,0.686326f,0.818514f,9.04739e-05f, 0.999362f,0.210067f,-0.0127041f,0.687742f,0.817994f,0.000103868f,
0.989137f,0.226987f,-0.0152448f,0.684673f,0.817424f,0.000119787f, 0.995643f,0.247368f,-0.0139505f,0.683041f,0.816797f,0.000138659f,
0.981866f,0.266299f,-0.034146f,0.675172f,0.816127f,0.000160961f, 0.974071f,0.283407f,-0.0374808f,0.672582f,0.815402f,0.000187277f,
0.966398f,0.300279f,-0.0426879f,0.671284f,0.814618f,0.000218295f, 0.957825f,0.31688f,-0.0473421f,0.669802f,0.813792f,0.000254817f,
0.949046f,0.333615f,-0.0517021f,0.668394f,0.812911f,0.000297769f, 0.940197f,0.349036f,-0.0561816f,0.666941f,0.811971f,0.000348241f,
0.931188f,0.364339f,-0.0604335f,0.665543f,0.810985f,0.000407495f, 0.922032f,0.379551f,-0.0644655f,0.664221f,0.80995f,0.000476985f,
0.904178f,0.388475f,-0.0690365f,0.658394f,0.808859f,0.000558401f, 0.874527f,0.39582f,-0.0732073f,0.647278f,0.807712f,0.000653688f,
0.860666f,0.409774f,-0.0815768f,0.641604f,0.806524f,0.000765084f, 0.847067f,0.422847f,-0.0870115f,0.637341f,0.805287f,0.000895155f,
0.837031f,0.436628f,-0.0899744f,0.636113f,0.803997f,0.00104682f, 0.827592f,0.448619f,-0.0928763f,0.634853f,0.802659f,0.00122348f,
0.81769f,0.464212f,-0.0953402f,0.63478f,0.801287f,0.00142891f, 0.811159f,0.474666f,-0.0962599f,0.633018f,0.799875f,0.00166744f,
0.80783f,0.481814f,-0.09548f,0.630066f,0.798423f,0.00194398f, 0.798647f,0.497977f,-0.0972076f,0.630989f,0.796934f,0.00226402f,
0.794489f,0.508754f,-0.0963831f,0.629851f,0.79543f,0.00263375f, 0.788555f,0.522606f,-0.0962917f,0.630281f,0.793908f,0.00306006f,
0.782979f,0.537031f,-0.0959092f,0.631223f,0.792376f,0.00355081f, 0.777521f,0.548336f,-0.09455f,0.630003f,0.790837f,0.00411445f,
0.780315f,0.550899f,-0.0869544f,0.622493f,0.789309f,0.00476059f, 0.774959f,0.564111f,-0.0803954f,0.627241f,0.787818f,0.00549965f,
0.757347f,0.567632f,-0.0773927f,0.623321f,0.786369f,0.00634322f, 0.737638f,0.565918f,-0.0843373f,0.607751f,0.784979f,0.0073039f,
0.728691f,0.574961f,-0.0742288f,0.613866f,0.783666f,0.00839547f, 0.722687f,0.581679f,-0.0722228f,0.613502f,0.782473f,0.00963304f,
0.71527f,0.587351f,-0.0652161f,0.618342f,0.781434f,0.0110327f, 0.706496f,0.591456f,-0.0562292f,0.625462f,0.780574f,0.0126123f,
0.694732f,0.59853f,-0.0558967f,0.631955f,0.779933f,0.0143905f, 0.682885f,0.606453f,-0.0587889f,0.63929f,0.779566f,0.0163879f,
0.674594f,0.617631f,-0.0596247f,0.643871f,0.779557f,0.0186266f, 0.667296f,0.62839f,-0.0606637f,0.650384f,0.779951f,0.02113f,
0.657075f,0.632445f,-0.0629329f,0.657727f,0.780818f,0.0239237f, 0.654333f,0.646714f,-0.0572157f,0.668266f,0.782288f,0.0270352f,
0.660218f,0.633791f,-0.0527273f,0.669462f,0.78446f,0.0304943f, 0.665483f,0.645304f,-0.0476091f,0.676681f,0.787427f,0.0343337f,
0.661477f,0.649747f,-0.0461633f,0.685411f,0.791409f,0.0385895f, 0.645854f,0.640867f,-0.0457255f,0.687615f,0.7965f,0.0433014f,
0.642544f,0.645172f,-0.0456587f,0.70189f,0.802983f,0.0485146f, 0.666656f,0.680341f,-0.0369618f,0.727889f,0.811015f,0.0542803f,
0.63871f,0.652216f,-0.0419347f,0.730619f,0.820922f,0.0606576f, 0.647167f,0.660928f,-0.0347014f,0.746407f,0.833048f,0.0677163f,
0.667651f,0.673653f,-0.0184177f,0.780317f,0.847761f,0.0755405f, 0.648212f,0.609816f,-0.0167652f,0.749842f,0.865634f,0.0842329f,
0.653777f,0.612753f,-0.00507148f,0.766797f,0.887387f,0.0939303f, 0.64535f,0.600696f,0.000541524f,0.787842f,0.91418f,0.104824f,
0.634303f,0.544366f,0.000851846f,0.765724f,0.948251f,0.117244f, 0.627162f,0.528655f,0.00529074f,0.782141f,0.9976f,0.131829f,
1.0108f,0.00534672f,0.000293495f,0.733722f,0.80269f,4.14761e-05f, 1.02054f,0.0219491f,0.0128417f,0.722559f,0.80266f,4.18812e-05f,
1.02219f,0.0404901f,0.0104078f,0.720604f,0.802591f,4.31452e-05f, 1.02142f,0.0608324f,0.00492169f,0.720773f,0.802466f,4.52697e-05f,
1.01847f,0.0838633f,0.00125077f,0.720615f,0.802305f,4.8352e-05f, 1.01535f,0.104901f,-0.00321636f,0.720248f,0.802085f,5.2421e-05f,
1.01875f,0.122483f,-0.00494028f,0.719257f,0.801827f,5.76265e-05f, 1.01333f,0.140587f,-0.00619781f,0.717157f,0.801513f,6.40793e-05f,
1.0041f,0.159301f,-0.00305485f,0.717671f,0.801157f,7.19485e-05f, 0.995881f,0.178026f,-0.00787696f,0.716823f,0.800746f,8.14429e-05f,
0.988133f,0.195818f,-0.012322f,0.715837f,0.800295f,9.28216e-05f, 0.981059f,0.212379f,-0.0162789f,0.713784f,0.799792f,0.000106351f,
0.973232f,0.228313f,-0.0195443f,0.711339f,0.799237f,0.000122385f, 0.993619f,0.24059f,-0.0152633f,0.710098f,0.79864f,0.00014134f,
0.980713f,0.25892f,-0.0353892f,0.702282f,0.797989f,0.0001637f, 0.974133f,0.277663f,-0.0384909f,0.700097f,0.797294f,0.000190024f,
0.966385f,0.292254f,-0.0439643f,0.698594f,0.796552f,0.000220964f, 0.957569f,0.311379f,-0.0480646f,0.697575f,0.795755f,0.000257286f,
0.949893f,0.324678f,-0.0529263f,0.695753f,0.794918f,0.000299885f, 0.941482f,0.339527f,-0.0574298f,0.694293f,0.794033f,0.000349787f,
0.932932f,0.354247f,-0.0616909f,0.692879f,0.793095f,0.000408193f, 0.924248f,0.368884f,-0.0657239f,0.691542f,0.792117f,0.000476481f,
0.894964f,0.374298f,-0.0718888f,0.680643f,0.791097f,0.00055624f, 0.871082f,0.390719f,-0.0771339f,0.676125f,0.790028f,0.000649298f,
0.866077f,0.397632f,-0.0829735f,0.668808f,0.788917f,0.000757748f, 0.853308f,0.409978f,-0.0881052f,0.66469f,0.787773f,0.000883991f,
0.843696f,0.423314f,-0.0912938f,0.663231f,0.78659f,0.00103076f, 0.833241f,0.43608f,-0.0933301f,0.662139f,0.785366f,0.00120114f,
0.825668f,0.451798f,-0.0960546f,0.662214f,0.784118f,0.0013987f, 0.818048f,0.463752f,-0.0972641f,0.661143f,0.782846f,0.00162739f,
0.814403f,0.47221f,-0.0969449f,0.658764f,0.781549f,0.00189172f, 0.805755f,0.487713f,-0.0985971f,0.659652f,0.780231f,0.00219679f,
0.803501f,0.496288f,-0.0968339f,0.657634f,0.778912f,0.00254818f, 0.797972f,0.509768f,-0.0966072f,0.658076f,0.777596f,0.00295239f,
0.792894f,0.523695f,-0.0960234f,0.658986f,0.776286f,0.00341633f, 0.783332f,0.530101f,-0.0952889f,0.653695f,0.774991f,0.00394793f,
0.794594f,0.541016f,-0.0837796f,0.655866f,0.773736f,0.00455586f, 0.778442f,0.54555f,-0.0806976f,0.652548f,0.772536f,0.00524975f,
0.761262f,0.548461f,-0.07832f,0.64725f,0.771402f,0.00604012f, 0.750937f,0.552998f,-0.0788493f,0.642351f,0.77035f,0.00693851f,
0.740024f,0.557956f,-0.0747562f,0.640497f,0.769415f,0.00795754f, 0.735446f,0.564201f,-0.0724054f,0.640194f,0.768632f,0.00911118f,
0.724819f,0.568164f,-0.0620274f,0.646533f,0.768021f,0.0104143f, 0.718814f,0.573306f,-0.0537444f,0.653285f,0.767614f,0.0118831f,
0.705208f,0.579517f,-0.0568639f,0.658856f,0.767473f,0.0135354f, 0.696898f,0.590979f,-0.0580711f,0.664107f,0.767652f,0.0153903f,
0.689841f,0.602329f,-0.0589125f,0.669719f,0.768192f,0.0174685f, 0.678709f,0.606285f,-0.0614961f,0.676551f,0.769163f,0.0197925f,
0.670846f,0.612284f,-0.0629427f,0.683412f,0.770675f,0.0223865f, 0.668255f,0.62494f,-0.0567925f,0.693841f,0.772784f,0.025277f,
0.670004f,0.636568f,-0.0529626f,0.700768f,0.775611f,0.0284932f, 0.672392f,0.615765f,-0.0503525f,0.701943f,0.779293f,0.032067f,
0.658172f,0.617985f,-0.0548591f,0.715529f,0.783941f,0.0360338f, 0.63894f,0.596177f,-0.0523978f,0.707713f,0.78976f,0.0404331f,
0.63167f,0.594346f,-0.0531743f,0.719194f,0.796916f,0.04531f, 0.639421f,0.605323f,-0.046754f,0.731254f,0.805627f,0.0507157f,
0.648946f,0.618605f,-0.0395127f,0.74617f,0.816181f,0.0567095f, 0.62527f,0.585646f,-0.0316827f,0.727909f,0.828906f,0.0633618f,
0.686872f,0.638784f,-0.0126439f,0.795896f,0.844219f,0.0707574f, 0.698131f,0.618202f,-0.0111931f,0.799833f,0.862635f,0.0790023f,
0.650058f,0.565576f,-0.0138409f,0.769107f,0.884872f,0.0882337f, 0.632858f,0.543224f,-0.00221169f,0.765764f,0.912176f,0.098652f,
0.633818f,0.525814f,0.00439995f,0.779613f,0.946978f,0.110606f, 0.659847f,0.53701f,0.00487379f,0.829639f,0.997501f,0.12479f,
1.00966f,0.00578323f,0.000417732f,0.759944f,0.783539f,4.28626e-05f, 1.01696f,0.0225662f,0.00421984f,0.754926f,0.78351f,4.3274e-05f,
1.01868f,0.0424086f,0.00825937f,0.748909f,0.783445f,4.45594e-05f, 1.01999f,0.0628299f,0.00384167f,0.750201f,0.783327f,4.67187e-05f,
1.01505f,0.082626f,-0.0012308f,0.74863f,0.783171f,4.98426e-05f, 1.01252f,0.100644f,-0.00645482f,0.747965f,0.782966f,5.39777e-05f,
1.01544f,0.117879f,-0.0029567f,0.746986f,0.782714f,5.92364e-05f, 1.01158f,0.139426f,-0.0067312f,0.745402f,0.782421f,6.5771e-05f,
1.01164f,0.15583f,-0.00355495f,0.749729f,0.782081f,7.37229e-05f, 1.00473f,0.173992f,-0.00828944f,0.749372f,0.781693f,8.32925e-05f,
0.998379f,0.1908f,-0.0120318f,0.747498f,0.781264f,9.47297e-05f, 0.991325f,0.206709f,-0.0151977f,0.744236f,0.780786f,0.000108323f,
0.982918f,0.222974f,-0.0190591f,0.741975f,0.78027f,0.0001244f, 0.992088f,0.233106f,-0.0163995f,0.73678f,0.779702f,0.00014335f,
0.980532f,0.251044f,-0.0363053f,0.728873f,0.779095f,0.000165644f, 0.97248f,0.267271f,-0.0387905f,0.726614f,0.778443f,0.000191823f,
0.966534f,0.283958f,-0.0447696f,0.725612f,0.777744f,0.000222515f, 0.9589f,0.299957f,-0.0493613f,0.724235f,0.777009f,0.000258456f,
0.950148f,0.31422f,-0.0533195f,0.722556f,0.776229f,0.000300487f, 0.942364f,0.331153f,-0.0583573f,0.721763f,0.775406f,0.000349591f,
0.934936f,0.343543f,-0.0626302f,0.719934f,0.77455f,0.000406896f, 0.926733f,0.357577f,-0.0666489f,0.718586f,0.773651f,0.000473708f,
0.889947f,0.364893f,-0.0743099f,0.705651f,0.772714f,0.000551512f, 0.878072f,0.377056f,-0.0776238f,0.702765f,0.771749f,0.000642014f,
0.866498f,0.388779f,-0.0806093f,0.699825f,0.770748f,0.000747181f, 0.858497f,0.397944f,-0.0887605f,0.692453f,0.769713f,0.000869213f,
0.850188f,0.41055f,-0.0918585f,0.690457f,0.768661f,0.0010107f, 0.838886f,0.422679f,-0.0931371f,0.6892f,0.767584f,0.00117448f,
0.834921f,0.436976f,-0.0958035f,0.688793f,0.766483f,0.00136382f, 0.828149f,0.448899f,-0.0969604f,0.687797f,0.765376f,0.00158238f,
0.822098f,0.460455f,-0.0975841f,0.68687f,0.764265f,0.00183434f, 0.816299f,0.472431f,-0.0979008f,0.686354f,0.763149f,0.0021243f,
0.812637f,0.482911f,-0.096879f,0.685319f,0.762039f,0.00245747f, 0.807562f,0.495898f,-0.096486f,0.685728f,0.760957f,0.00283978f,
0.799656f,0.505381f,-0.0948987f,0.684521f,0.759901f,0.00327753f, 0.793618f,0.51488f,-0.0933689f,0.682293f,0.758881f,0.00377796f,
0.798447f,0.522269f,-0.082529f,0.682691f,0.75792f,0.00434906f, 0.783007f,0.526419f,-0.0801448f,0.67818f,0.757038f,0.00499956f,
0.768771f,0.529628f,-0.0789552f,0.672507f,0.756246f,0.00573919f, 0.764047f,0.537035f,-0.0771419f,0.672064f,0.75556f,0.00657852f,
0.752357f,0.541186f,-0.0740408f,0.666923f,0.755025f,0.00752922f, 0.744545f,0.544496f,-0.0687761f,0.667725f,0.754661f,0.00860393f,
0.734974f,0.550766f,-0.0555528f,0.678032f,0.754494f,0.00981666f, 0.736772f,0.561992f,-0.052229f,0.681155f,0.754567f,0.0111825f,
0.720229f,0.565236f,-0.0558617f,0.684872f,0.75494f,0.0127179f, 0.714144f,0.577937f,-0.0563002f,0.689753f,0.755644f,0.0144409f,
0.702566f,0.582488f,-0.058942f,0.695754f,0.756739f,0.0163709f, 0.692535f,0.586464f,-0.0611848f,0.702171f,0.758317f,0.0185295f,
0.68483f,0.590957f,-0.0626125f,0.708658f,0.760423f,0.0209396f, 0.685726f,0.604683f,-0.0572506f,0.716187f,0.763169f,0.0236272f,
0.680055f,0.612646f,-0.0541868f,0.7267f,0.766653f,0.0266201f, 0.670674f,0.603032f,-0.0570346f,0.734853f,0.770986f,0.0299498f,
0.654613f,0.586861f,-0.0556301f,0.730215f,0.776313f,0.0336509f, 0.651085f,0.574612f,-0.0614376f,0.722854f,0.7828f,0.0377625f,
0.650273f,0.572549f,-0.0594326f,0.728397f,0.790608f,0.0423293f, 0.652237f,0.576712f,-0.0453878f,0.747947f,0.79997f,0.0474025f,
0.655911f,0.577443f,-0.039714f,0.75628f,0.811156f,0.0530416f, 0.666453f,0.579834f,-0.0263252f,0.765674f,0.824489f,0.059317f,
0.694917f,0.603343f,-0.0219628f,0.808825f,0.840374f,0.0663145f, 0.662031f,0.566977f,-0.0163174f,0.792638f,0.859274f,0.0741413f,
0.648882f,0.523238f,-0.01084f,0.78289f,0.882088f,0.0829397f, 0.652841f,0.522309f,-0.0048926f,0.787626f,0.909935f,0.0929133f,
0.646462f,0.505281f,0.00396442f,0.800833f,0.945548f,0.104428f, 0.68916f,0.52795f,0.00421807f,0.87821f,0.997395f,0.118244f,
1.00894f,0.00609444f,0.000727361f,0.785446f,0.763609f,4.40974e-05f, 1.01552f,0.0259442f,0.0123655f,0.776346f,0.763571f,4.44887e-05f,
1.01558f,0.0437522f,0.00613244f,0.776595f,0.763517f,4.58032e-05f, 1.02161f,0.0619779f,0.00322355f,0.779515f,0.763408f,4.79864e-05f,
1.01353f,0.0780467f,-0.0032626f,0.774891f,0.76326f,5.11276e-05f, 1.01253f,0.0940167f,-0.00458078f,0.771831f,0.763072f,5.53085e-05f,
1.02176f,0.11905f,-0.00101313f,0.781869f,0.762839f,6.06097e-05f, 1.01012f,0.137485f,-0.007299f,0.773243f,0.762566f,6.71712e-05f,
1.01391f,0.15287f,-0.00441596f,0.779275f,0.762251f,7.5162e-05f, 1.01591f,0.167661f,-0.00766212f,0.780962f,0.761896f,8.47691e-05f,
0.998672f,0.188186f,-0.0128935f,0.775981f,0.761499f,9.62181e-05f, 1.00265f,0.200516f,-0.0148395f,0.776387f,0.76106f,0.000109788f,
0.996997f,0.213168f,-0.0153882f,0.768447f,0.760584f,0.000125808f, 0.989987f,0.227141f,-0.0174008f,0.763232f,0.760065f,0.000144658f,
0.983209f,0.242542f,-0.0243804f,0.759339f,0.759512f,0.000166787f, 0.972388f,0.260114f,-0.0388433f,0.753259f,0.758914f,0.000192704f,
0.964492f,0.274694f,-0.0430835f,0.75166f,0.758286f,0.000223013f, 0.959688f,0.289219f,-0.0501755f,0.750761f,0.757619f,0.000258408f,
0.952913f,0.303536f,-0.0545229f,0.749138f,0.756915f,0.000299693f, 0.944948f,0.318251f,-0.0590546f,0.747975f,0.756182f,0.00034779f,
0.936951f,0.332814f,-0.0632429f,0.746786f,0.755412f,0.000403767f, 0.929347f,0.34621f,-0.0671148f,0.745368f,0.754615f,0.00046884f,
0.905172f,0.353712f,-0.0730717f,0.735939f,0.753793f,0.000544413f, 0.888835f,0.364675f,-0.0771947f,0.730989f,0.75294f,0.000632089f,
0.874561f,0.374682f,-0.0804546f,0.726218f,0.752071f,0.000733689f, 0.864883f,0.385711f,-0.0876996f,0.720296f,0.751183f,0.000851261f,
0.855819f,0.397021f,-0.0913304f,0.717325f,0.750276f,0.000987172f, 0.843835f,0.407064f,-0.0918347f,0.715466f,0.749364f,0.00114408f,
0.843995f,0.421791f,-0.0952074f,0.715262f,0.748449f,0.001325f, 0.837725f,0.433518f,-0.0961659f,0.714303f,0.747529f,0.0015333f,
0.831918f,0.445147f,-0.0967476f,0.713549f,0.746622f,0.0017728f, 0.826647f,0.45675f,-0.096855f,0.713011f,0.745734f,0.00204776f,
0.822005f,0.468425f,-0.0964373f,0.712729f,0.744868f,0.00236295f, 0.81552f,0.47945f,-0.0953383f,0.712672f,0.744037f,0.00272378f,
0.804872f,0.486724f,-0.0924161f,0.711858f,0.74326f,0.00313604f, 0.814847f,0.496403f,-0.0856277f,0.709617f,0.742543f,0.0036064f,
0.80314f,0.502807f,-0.0814436f,0.708507f,0.741896f,0.00414212f, 0.788172f,0.506346f,-0.0802908f,0.70189f,0.741353f,0.00475126f,
0.779341f,0.510688f,-0.0790308f,0.698689f,0.740925f,0.00544272f, 0.771613f,0.515914f,-0.0765989f,0.695493f,0.740628f,0.00622624f,
0.760828f,0.520727f,-0.0708456f,0.69287f,0.7405f,0.00711257f, 0.752483f,0.524754f,-0.0601438f,0.700501f,0.740572f,0.00811349f,
0.749112f,0.532804f,-0.0531066f,0.704225f,0.740864f,0.00924195f, 0.752984f,0.547714f,-0.0510323f,0.709188f,0.741426f,0.010512f,
0.737182f,0.551563f,-0.0537559f,0.710232f,0.742307f,0.011939f, 0.725477f,0.556714f,-0.0564977f,0.715785f,0.74354f,0.01354f,
0.715209f,0.561308f,-0.0588622f,0.721763f,0.745204f,0.0153333f, 0.711392f,0.561396f,-0.0586149f,0.724457f,0.747354f,0.0173395f,
0.704835f,0.572016f,-0.0597685f,0.732607f,0.750059f,0.0195806f, 0.69701f,0.579831f,-0.0581648f,0.741449f,0.753427f,0.0220814f,
0.69281f,0.584621f,-0.0543366f,0.750993f,0.757532f,0.024869f, 0.68827f,0.581958f,-0.0604664f,0.753895f,0.762509f,0.0279741f,
0.678466f,0.575164f,-0.0526751f,0.759787f,0.768486f,0.0314308f, 0.667314f,0.556798f,-0.0601491f,0.745094f,0.7756f,0.0352773f,
0.666149f,0.550131f,-0.0575755f,0.746981f,0.784045f,0.0395581f, 0.670779f,0.554441f,-0.052293f,0.753826f,0.794041f,0.0443239f,
0.656726f,0.538608f,-0.0402996f,0.740433f,0.805835f,0.0496341f, 0.685842f,0.562574f,-0.0191663f,0.784088f,0.819763f,0.0555598f,
0.69919f,0.571334f,-0.0133967f,0.810517f,0.836205f,0.062187f, 0.661512f,0.518667f,-0.0159724f,0.798517f,0.855713f,0.0696247f,
0.658821f,0.506451f,-0.00708853f,0.808766f,0.87908f,0.0780177f, 0.66763f,0.497105f,-0.00626865f,0.809071f,0.907619f,0.0875785f,
0.653251f,0.48117f,0.004009f,0.81691f,0.94397f,0.0986777f, 0.714416f,0.527049f,0.00778851f,0.932559f,0.997283f,0.112155f,
1.00816f,0.00650955f,0.00113085f,0.810369f,0.742966f,4.51329e-05f, 1.01325f,0.0244548f,0.00754336f,0.803806f,0.742943f,4.55536e-05f,
1.01572f,0.0403096f,0.00471287f,0.802524f,0.742885f,4.68516e-05f, 1.03086f,0.0592324f,0.00597639f,0.810918f,0.74279f,4.90581e-05f,
1.01347f,0.0727784f,-0.00352583f,0.799347f,0.74266f,5.22172e-05f, 1.01f,0.094767f,-0.000413107f,0.796483f,0.742486f,5.6397e-05f,
1.01378f,0.117403f,-0.00118461f,0.80094f,0.74228f,6.17202e-05f, 1.00716f,0.133142f,-0.00912244f,0.798681f,0.742035f,6.82936e-05f,
1.01062f,0.151885f,-0.00567201f,0.806306f,0.741753f,7.62747e-05f, 1.00156f,0.170666f,-0.0104719f,0.805038f,0.741434f,8.58523e-05f,
1.01808f,0.175142f,-0.00844476f,0.803779f,0.74108f,9.72565e-05f, 1.00358f,0.196473f,-0.0152749f,0.804201f,0.740691f,0.000110755f,
1.00691f,0.204843f,-0.013839f,0.79711f,0.740268f,0.000126651f, 0.992634f,0.220219f,-0.0161867f,0.788212f,0.739809f,0.000145311f,
0.984116f,0.235539f,-0.0201326f,0.786529f,0.739321f,0.000167161f, 0.97198f,0.254121f,-0.0382933f,0.779796f,0.738796f,0.000192693f,
0.961398f,0.26883f,-0.041474f,0.778476f,0.738247f,0.000222482f, 0.960553f,0.282209f,-0.049993f,0.777428f,0.737663f,0.000257184f,
0.953504f,0.295569f,-0.0547597f,0.776049f,0.737057f,0.000297557f, 0.946506f,0.308354f,-0.0592586f,0.774564f,0.736423f,0.000344474f,
0.939608f,0.320575f,-0.0634638f,0.772984f,0.735765f,0.000398936f, 0.932406f,0.332704f,-0.0674621f,0.771335f,0.73509f,0.000462083f,
0.919549f,0.343964f,-0.0717385f,0.766968f,0.734392f,0.000535219f, 0.905346f,0.354767f,-0.075369f,0.762122f,0.733684f,0.000619838f,
0.89285f,0.364825f,-0.078713f,0.75808f,0.732964f,0.000717627f, 0.879317f,0.374241f,-0.0819854f,0.753467f,0.732233f,0.000830519f,
0.86519f,0.383021f,-0.0852556f,0.748453f,0.731507f,0.000960684f, 0.852081f,0.392224f,-0.0909614f,0.741877f,0.730781f,0.00111057f,
0.85295f,0.406488f,-0.0941733f,0.741632f,0.73006f,0.00128295f, 0.848903f,0.418728f,-0.0944722f,0.741926f,0.729362f,0.00148096f,
0.845999f,0.431464f,-0.0941101f,0.742971f,0.728684f,0.00170809f, 0.8364f,0.440972f,-0.0957005f,0.739732f,0.728035f,0.00196822f,
0.831675f,0.452738f,-0.0954302f,0.739718f,0.727436f,0.00226583f, 0.821967f,0.460194f,-0.0929429f,0.738611f,0.726888f,0.00260575f,
0.811084f,0.467092f,-0.0899816f,0.737915f,0.726402f,0.00299341f, 0.821752f,0.477967f,-0.0839232f,0.736216f,0.726004f,0.00343484f,
0.808552f,0.482455f,-0.0812221f,0.732165f,0.7257f,0.00393679f, 0.799009f,0.486956f,-0.0799706f,0.728078f,0.725506f,0.00450659f,
0.791618f,0.49105f,-0.0782663f,0.724834f,0.725458f,0.00515254f, 0.783074f,0.496439f,-0.0748236f,0.720145f,0.725566f,0.00588358f,
0.770572f,0.499798f,-0.0636013f,0.724355f,0.725855f,0.00670962f, 0.764271f,0.508221f,-0.0535765f,0.730668f,0.726371f,0.00764156f,
0.762028f,0.508516f,-0.0525468f,0.7293f,0.727132f,0.00869151f, 0.766559f,0.530078f,-0.0499152f,0.735402f,0.728181f,0.00987251f,
0.748391f,0.530468f,-0.0537181f,0.736375f,0.729572f,0.0111992f, 0.737599f,0.53529f,-0.0562597f,0.741718f,0.731335f,0.0126874f,
0.73014f,0.541402f,-0.0581427f,0.7489f,0.733553f,0.0143547f, 0.72089f,0.542363f,-0.0597232f,0.752644f,0.736263f,0.0162204f,
0.713473f,0.546186f,-0.0613265f,0.759567f,0.739566f,0.0183058f, 0.711808f,0.55644f,-0.0596433f,0.763769f,0.743517f,0.0206347f,
0.709206f,0.563862f,-0.0517835f,0.774979f,0.748248f,0.0232335f, 0.705643f,0.562059f,-0.0576177f,0.777174f,0.753836f,0.0261319f,
0.687502f,0.54334f,-0.058715f,0.764046f,0.76042f,0.0293632f, 0.703109f,0.562283f,-0.0462431f,0.79741f,0.768169f,0.0329653f,
0.683166f,0.531896f,-0.0542692f,0.767907f,0.77724f,0.0369819f, 0.670355f,0.513903f,-0.0475209f,0.753921f,0.787839f,0.0414632f,
0.684761f,0.524926f,-0.0322433f,0.768452f,0.800218f,0.0464689f, 0.69392f,0.52915f,-0.0166367f,0.798027f,0.814733f,0.0520695f,
0.676475f,0.509172f,-0.023788f,0.805217f,0.831729f,0.0583523f, 0.672507f,0.498758f,-0.0145387f,0.817421f,0.851834f,0.0654274f,
0.671727f,0.489851f,-0.00796568f,0.823093f,0.875802f,0.0734423f, 0.668743f,0.477255f,-0.00105155f,0.830499f,0.905046f,0.0826134f,
0.665513f,0.462349f,0.00361186f,0.839176f,0.942248f,0.0933248f, 0.719082f,0.492408f,0.00754948f,0.952367f,0.997165f,0.106493f,
1.00748f,0.00661853f,0.00137493f,0.834644f,0.72171f,4.59825e-05f, 1.01082f,0.0224802f,0.00295836f,0.830467f,0.7217f,4.64288e-05f,
1.02255f,0.0372438f,0.00739033f,0.830632f,0.721647f,4.77241e-05f, 1.02788f,0.0586745f,0.00606729f,0.83541f,0.721566f,4.99264e-05f,
1.01186f,0.0711019f,-0.00364755f,0.824392f,0.721451f,5.30824e-05f, 1.00897f,0.0942346f,0.000872666f,0.821415f,0.721304f,5.7266e-05f,
1.01429f,0.114906f,-0.00113211f,0.828587f,0.721126f,6.2568e-05f, 1.00519f,0.128632f,-0.00999002f,0.823503f,0.720912f,6.91092e-05f,
1.00894f,0.150101f,-0.00660765f,0.833248f,0.720672f,7.70512e-05f, 1.00435f,0.16668f,-0.0106777f,0.833118f,0.720398f,8.65697e-05f,
0.996053f,0.183317f,-0.0144772f,0.83026f,0.720098f,9.78774e-05f, 1.01093f,0.186214f,-0.011809f,0.826879f,0.719764f,0.000111226f,
1.0135f,0.195835f,-0.011935f,0.822858f,0.719406f,0.00012692f, 0.991778f,0.214664f,-0.0161227f,0.813438f,0.719017f,0.000145304f,
0.982203f,0.23048f,-0.020568f,0.812225f,0.718607f,0.000166787f, 0.97129f,0.247101f,-0.0318056f,0.808314f,0.718168f,0.000191834f,
0.960571f,0.262623f,-0.0406213f,0.805001f,0.717711f,0.000220988f, 0.951816f,0.276174f,-0.0447992f,0.803921f,0.717228f,0.000254868f,
0.953896f,0.288172f,-0.0546373f,0.802814f,0.716731f,0.000294189f, 0.947174f,0.30053f,-0.0592153f,0.801465f,0.716215f,0.000339774f,
0.940557f,0.312305f,-0.0635101f,0.800012f,0.715686f,0.000392557f, 0.934542f,0.323226f,-0.0670617f,0.798155f,0.715147f,0.000453607f,
0.925433f,0.334139f,-0.0710597f,0.794833f,0.714596f,0.000524138f, 0.913806f,0.344648f,-0.0746573f,0.791029f,0.714046f,0.000605539f,
0.901579f,0.354509f,-0.0780463f,0.786916f,0.713493f,0.000699384f, 0.888773f,0.363704f,-0.0812254f,0.782501f,0.712946f,0.000807436f,
0.875415f,0.372205f,-0.0841793f,0.777795f,0.712411f,0.000931723f, 0.86256f,0.379919f,-0.0866568f,0.773004f,0.711887f,0.00107452f,
0.872998f,0.395378f,-0.0884874f,0.775477f,0.711392f,0.00123837f, 0.856129f,0.401994f,-0.0936617f,0.767009f,0.710924f,0.00142615f,
0.865402f,0.419583f,-0.0889534f,0.776004f,0.710493f,0.00164107f, 0.846106f,0.424382f,-0.0941433f,0.766106f,0.710115f,0.00188674f,
0.838286f,0.433376f,-0.0927622f,0.76538f,0.709791f,0.0021672f, 0.828191f,0.440364f,-0.0902054f,0.764365f,0.709539f,0.00248694f,
0.822037f,0.44964f,-0.0881252f,0.76436f,0.709373f,0.00285095f, 0.82762f,0.457366f,-0.0815115f,0.761745f,0.7093f,0.00326476f,
0.817549f,0.462083f,-0.0802938f,0.756885f,0.709348f,0.00373459f, 0.811035f,0.466783f,-0.0786484f,0.753789f,0.709531f,0.00426724f,
0.807859f,0.47257f,-0.0760775f,0.752246f,0.709863f,0.00487023f, 0.794087f,0.474868f,-0.0712877f,0.745049f,0.710383f,0.00555191f,
0.783114f,0.479561f,-0.05982f,0.751217f,0.711104f,0.00632153f, 0.777847f,0.48901f,-0.0522074f,0.756082f,0.712062f,0.00718923f,
0.775149f,0.490108f,-0.0512928f,0.755064f,0.713295f,0.00816611f, 0.777579f,0.508845f,-0.0495811f,0.761691f,0.714829f,0.00926469f,
0.762874f,0.511686f,-0.0524116f,0.762849f,0.716727f,0.0104985f, 0.75413f,0.517116f,-0.0548523f,0.769741f,0.719015f,0.0118825f,
0.744454f,0.520335f,-0.0568902f,0.774356f,0.721774f,0.0134334f, 0.736642f,0.523766f,-0.0581572f,0.779069f,0.72504f,0.0151696f,
0.730419f,0.527207f,-0.0588117f,0.783747f,0.728914f,0.0171116f, 0.725423f,0.530641f,-0.0586522f,0.787876f,0.733452f,0.0192824f,
0.724281f,0.538808f,-0.0536996f,0.795627f,0.738759f,0.0217072f, 0.723289f,0.54211f,-0.0555641f,0.799217f,0.744955f,0.0244151f,
0.706038f,0.526933f,-0.0549158f,0.786217f,0.752148f,0.0274386f, 0.702572f,0.520899f,-0.0531369f,0.787689f,0.760488f,0.0308151f,
0.689684f,0.498746f,-0.0507286f,0.773246f,0.770153f,0.0345872f, 0.686721f,0.490241f,-0.0404232f,0.772154f,0.781348f,0.0388054f,
0.711613f,0.508282f,-0.024037f,0.795983f,0.794312f,0.0435282f, 0.687754f,0.48596f,-0.0357507f,0.798487f,0.809408f,0.0488269f,
0.685069f,0.478882f,-0.0237497f,0.818464f,0.826992f,0.0547886f, 0.684701f,0.472939f,-0.0186452f,0.822875f,0.847679f,0.0615252f,
0.689491f,0.467902f,-0.0125424f,0.836443f,0.872336f,0.0691868f, 0.684745f,0.454463f,-0.0045817f,0.847233f,0.902262f,0.0779953f,
0.696402f,0.452599f,0.000614053f,0.879648f,0.940413f,0.0883459f, 0.726332f,0.478283f,0.00987708f,0.977052f,0.997041f,0.101227f,
1.00689f,0.00660999f,0.00156484f,0.858201f,0.699955f,4.66878e-05f, 1.01571f,0.0209869f,0.0017096f,0.859095f,0.699937f,4.7105e-05f,
1.01844f,0.0355245f,0.00471396f,0.853756f,0.699897f,4.8401e-05f, 1.02484f,0.0574336f,0.00574967f,0.858982f,0.69983f,5.05965e-05f,
1.01043f,0.0690355f,-0.00374179f,0.848719f,0.699737f,5.37363e-05f, 1.00756f,0.0906508f,-0.000838222f,0.846429f,0.699616f,5.78887e-05f,
1.01475f,0.11196f,-0.00102352f,0.855499f,0.699468f,6.31485e-05f, 1.00549f,0.128989f,-0.00507167f,0.84823f,0.6993f,6.96452e-05f,
1.00878f,0.146363f,-0.00651918f,0.858302f,0.699103f,7.75079e-05f, 1.00356f,0.162771f,-0.0103659f,0.857497f,0.698883f,8.6914e-05f,
0.997571f,0.178749f,-0.0142287f,0.85636f,0.69864f,9.80688e-05f, 1.01243f,0.178801f,-0.010404f,0.850254f,0.698374f,0.000111218f,
0.982895f,0.208422f,-0.0210979f,0.850855f,0.698089f,0.000126647f, 0.990046f,0.20949f,-0.0162263f,0.838333f,0.697783f,0.000144688f,
0.980459f,0.225219f,-0.0207718f,0.837372f,0.69746f,0.000165724f, 0.970276f,0.240896f,-0.0253036f,0.8364f,0.69712f,0.000190197f,
0.959218f,0.257107f,-0.0299896f,0.835448f,0.696767f,0.000218615f, 0.951778f,0.269425f,-0.0439481f,0.830277f,0.6964f,0.000251567f,
0.954447f,0.280438f,-0.0541559f,0.829167f,0.696023f,0.000289721f, 0.947951f,0.292405f,-0.0588289f,0.827981f,0.69564f,0.000333847f,
0.941584f,0.303776f,-0.0632175f,0.826691f,0.695251f,0.00038482f, 0.935754f,0.31426f,-0.0669534f,0.825025f,0.694864f,0.000443638f,
0.930723f,0.323809f,-0.0697651f,0.822849f,0.694476f,0.000511428f, 0.92181f,0.333794f,-0.0735282f,0.819364f,0.694099f,0.000589487f,
0.910285f,0.343444f,-0.076943f,0.815423f,0.69373f,0.000679274f, 0.898192f,0.35246f,-0.0801586f,0.811179f,0.693381f,0.000782426f,
0.885558f,0.360812f,-0.0831612f,0.806632f,0.693054f,0.000900808f, 0.873909f,0.3683f,-0.0855408f,0.802056f,0.692753f,0.00103651f,
0.888793f,0.381857f,-0.0819737f,0.807976f,0.692493f,0.00119188f, 0.880979f,0.391805f,-0.0832777f,0.805927f,0.692271f,0.00136957f,
0.874905f,0.401029f,-0.08353f,0.803928f,0.692108f,0.00157257f, 0.854085f,0.405315f,-0.091334f,0.791406f,0.692006f,0.00180418f,
0.84549f,0.413219f,-0.0895548f,0.790495f,0.691976f,0.00206807f, 0.836816f,0.420683f,-0.0872832f,0.789786f,0.692037f,0.00236842f,
0.83689f,0.430211f,-0.0842752f,0.789183f,0.692192f,0.00270981f, 0.835035f,0.436274f,-0.0799574f,0.785035f,0.692468f,0.00309734f,
0.82717f,0.440876f,-0.0783213f,0.780675f,0.692875f,0.00353674f, 0.825116f,0.446284f,-0.0761035f,0.7795f,0.693431f,0.00403425f,
0.816469f,0.448572f,-0.0734982f,0.773716f,0.694166f,0.00459694f, 0.805062f,0.452686f,-0.0643646f,0.776262f,0.69509f,0.00523242f,
0.795107f,0.459246f,-0.0572286f,0.777842f,0.696248f,0.00594937f, 0.78999f,0.469007f,-0.0511605f,0.781853f,0.697653f,0.00675714f,
0.787889f,0.472308f,-0.0499034f,0.780905f,0.699351f,0.00766629f, 0.78909f,0.48714f,-0.048836f,0.7877f,0.701372f,0.00868832f,
0.776063f,0.490418f,-0.05143f,0.789402f,0.703765f,0.00983616f, 0.768458f,0.496359f,-0.0531695f,0.795097f,0.706572f,0.0111239f,
0.758392f,0.499274f,-0.0546274f,0.797074f,0.709858f,0.0125675f, 0.753544f,0.50483f,-0.0553627f,0.803427f,0.713669f,0.0141844f,
0.746579f,0.507378f,-0.0558013f,0.806446f,0.718094f,0.0159942f, 0.739143f,0.504332f,-0.0573259f,0.811767f,0.723201f,0.0180191f,
0.73912f,0.51258f,-0.0551081f,0.816574f,0.729079f,0.0202836f, 0.740103f,0.520825f,-0.0523147f,0.821936f,0.735841f,0.0228158f,
0.723324f,0.508635f,-0.0510327f,0.807611f,0.743613f,0.0256475f, 0.701435f,0.480462f,-0.0506287f,0.786375f,0.752535f,0.0288154f,
0.71236f,0.474959f,-0.0463126f,0.79762f,0.762782f,0.0323616f, 0.704326f,0.466767f,-0.0339169f,0.792113f,0.774566f,0.0363355f,
0.7171f,0.474364f,-0.0250231f,0.810741f,0.788122f,0.0407959f, 0.704069f,0.463057f,-0.0302246f,0.81876f,0.803797f,0.0458137f,
0.698679f,0.459597f,-0.0253838f,0.831658f,0.821993f,0.0514766f, 0.692672f,0.452434f,-0.0142903f,0.848686f,0.843322f,0.0578975f,
0.710203f,0.448378f,-0.0080302f,0.885574f,0.868625f,0.0652293f, 0.71206f,0.440778f,-0.00433129f,0.892933f,0.89942f,0.0736998f,
0.718239f,0.444485f,0.000602447f,0.915629f,0.938622f,0.0837189f, 0.730969f,0.462357f,0.0113502f,0.999461f,0.996912f,0.0963293f,
1.00632f,0.00668733f,0.00176669f,0.881052f,0.677779f,4.71913e-05f, 1.01395f,0.0206409f,-0.000208529f,0.883631f,0.67776f,4.7598e-05f,
1.01543f,0.0342884f,0.00299511f,0.87655f,0.677732f,4.88886e-05f, 1.0123f,0.0494218f,-0.00151625f,0.874554f,0.677684f,5.10644e-05f,
1.00928f,0.0679921f,-0.00251811f,0.872053f,0.677611f,5.41673e-05f, 1.00642f,0.0874348f,-0.00171873f,0.870507f,0.677521f,5.82762e-05f,
1.00436f,0.10204f,-0.00861487f,0.870723f,0.677415f,6.34842e-05f, 1.00397f,0.125716f,-0.00413063f,0.871847f,0.677287f,6.98917e-05f,
1.00744f,0.142325f,-0.00611796f,0.881395f,0.677144f,7.76418e-05f, 1.00261f,0.158278f,-0.0097607f,0.880646f,0.676982f,8.68981e-05f,
0.997256f,0.173807f,-0.0134702f,0.879795f,0.676806f,9.78604e-05f, 0.990457f,0.1889f,-0.0170489f,0.877814f,0.676616f,0.000110762f,
0.984347f,0.202665f,-0.020279f,0.875559f,0.676411f,0.000125873f, 0.988244f,0.20418f,-0.0161991f,0.862648f,0.676197f,0.000143504f,
0.978861f,0.219763f,-0.0207404f,0.861912f,0.675971f,0.000164018f, 0.969164f,0.234651f,-0.025562f,0.860982f,0.67574f,0.000187835f,
0.959244f,0.248725f,-0.0297744f,0.860204f,0.675499f,0.000215432f, 0.94885f,0.263156f,-0.0408946f,0.856274f,0.67526f,0.000247364f,
0.955072f,0.272395f,-0.0533447f,0.855035f,0.675015f,0.000284254f, 0.948823f,0.283984f,-0.0580952f,0.854057f,0.674777f,0.000326825f,
0.942701f,0.294941f,-0.0625833f,0.852957f,0.674542f,0.000375894f, 0.936884f,0.305139f,-0.0665707f,0.851595f,0.674319f,0.000432391f,
0.932234f,0.314098f,-0.0694329f,0.849488f,0.674107f,0.000497359f, 0.92469f,0.32299f,-0.0724659f,0.845163f,0.673915f,0.000572005f,
0.918914f,0.331629f,-0.0754079f,0.84352f,0.673745f,0.000657671f, 0.907565f,0.340457f,-0.0786511f,0.839498f,0.673604f,0.000755879f,
0.91181f,0.345368f,-0.0768736f,0.837546f,0.673499f,0.000868358f, 0.900537f,0.353062f,-0.079202f,0.832909f,0.673433f,0.000997027f,
0.896324f,0.363733f,-0.0799642f,0.832331f,0.67342f,0.00114408f, 0.888463f,0.373038f,-0.0812282f,0.830038f,0.67346f,0.00131193f,
0.880836f,0.381747f,-0.082038f,0.82753f,0.673572f,0.00150333f, 0.861802f,0.386013f,-0.0883359f,0.816516f,0.673758f,0.00172133f,
0.851567f,0.392331f,-0.0853746f,0.815091f,0.674034f,0.0019693f, 0.848181f,0.402353f,-0.0849344f,0.815407f,0.674412f,0.00225113f,
0.852283f,0.40944f,-0.079142f,0.812973f,0.674903f,0.00257095f, 0.844253f,0.41468f,-0.0773478f,0.808073f,0.675529f,0.0029336f,
0.841889f,0.419546f,-0.0753688f,0.806362f,0.676298f,0.00334422f, 0.836763f,0.423652f,-0.0730124f,0.803031f,0.677241f,0.00380875f,
0.828516f,0.427532f,-0.0704722f,0.798134f,0.678367f,0.00433354f, 0.814918f,0.430626f,-0.0622779f,0.800881f,0.679713f,0.00492586f,
0.805827f,0.437952f,-0.0556503f,0.803711f,0.681293f,0.00559369f, 0.801658f,0.448081f,-0.0500421f,0.807481f,0.68315f,0.00634578f,
0.799691f,0.451378f,-0.0487181f,0.806474f,0.685302f,0.00719196f, 0.801195f,0.465283f,-0.0474634f,0.813001f,0.687805f,0.00814318f,
0.788034f,0.46758f,-0.0501298f,0.814064f,0.690684f,0.00921152f, 0.781766f,0.473555f,-0.0516308f,0.820255f,0.694001f,0.0104104f,
0.774365f,0.477692f,-0.0527888f,0.824142f,0.697798f,0.0117548f, 0.767031f,0.480808f,-0.0534462f,0.826822f,0.702138f,0.0132616f,
0.763477f,0.485553f,-0.0533961f,0.832479f,0.707103f,0.0149496f, 0.752838f,0.477466f,-0.0558487f,0.835419f,0.712756f,0.0168399f,
0.752613f,0.484209f,-0.0535844f,0.839791f,0.719191f,0.0189565f, 0.754099f,0.491245f,-0.0503745f,0.844281f,0.726516f,0.0213265f,
0.736892f,0.478836f,-0.0472938f,0.822848f,0.734853f,0.023981f, 0.722184f,0.45517f,-0.0468274f,0.810041f,0.744346f,0.026956f,
0.727771f,0.450557f,-0.0402582f,0.814769f,0.755161f,0.0302926f, 0.720853f,0.442675f,-0.0276879f,0.811917f,0.767501f,0.0340402f,
0.722112f,0.441557f,-0.0260464f,0.825623f,0.781651f,0.0382569f, 0.716393f,0.438372f,-0.024874f,0.836195f,0.797912f,0.0430131f,
0.711025f,0.43889f,-0.0266991f,0.845353f,0.816728f,0.0483974f, 0.705668f,0.43416f,-0.0164935f,0.860855f,0.838699f,0.0545234f,
0.698831f,0.427515f,-0.00487708f,0.878523f,0.864737f,0.0615457f, 0.693173f,0.421058f,0.00572916f,0.89878f,0.896352f,0.0696981f,
0.74716f,0.441895f,0.00107598f,0.962422f,0.936707f,0.0794079f, 0.718146f,0.428038f,0.0101959f,0.988726f,0.996776f,0.0917728f,
1.00686f,0.0066517f,0.00211621f,0.903737f,0.655279f,4.74888e-05f, 1.00818f,0.0197604f,0.00192993f,0.89991f,0.655277f,4.79182e-05f,
1.01397f,0.0328374f,0.00260174f,0.898868f,0.655257f,4.91844e-05f, 1.00938f,0.047011f,-0.00219344f,0.896064f,0.655225f,5.13265e-05f,
1.00796f,0.0648935f,-0.00334807f,0.895144f,0.655181f,5.43893e-05f, 1.00539f,0.0836786f,-0.00284502f,0.893867f,0.655124f,5.84409e-05f,
1.00399f,0.0975461f,-0.00945401f,0.894508f,0.655058f,6.35643e-05f, 1.0026f,0.121905f,-0.00326342f,0.894719f,0.65498f,6.98627e-05f,
1.00571f,0.13799f,-0.00556108f,0.903308f,0.654891f,7.74687e-05f, 1.00168f,0.153429f,-0.00907422f,0.903105f,0.654796f,8.65447e-05f,
0.996732f,0.168487f,-0.0125861f,0.902326f,0.654691f,9.72774e-05f, 0.991299f,0.183088f,-0.0161487f,0.901456f,0.654582f,0.000109887f,
0.986206f,0.196538f,-0.0194678f,0.90026f,0.654468f,0.000124624f, 0.982195f,0.202196f,-0.0176131f,0.887516f,0.654349f,0.000141787f,
0.977399f,0.214125f,-0.0204755f,0.885801f,0.654232f,0.00016172f, 0.967852f,0.228902f,-0.0250175f,0.885261f,0.654113f,0.000184814f,
0.960037f,0.242105f,-0.0292818f,0.88523f,0.654001f,0.000211522f, 0.95276f,0.255102f,-0.0409912f,0.88187f,0.653892f,0.00024236f,
0.948492f,0.266008f,-0.046735f,0.881525f,0.653794f,0.000277913f, 0.949785f,0.275276f,-0.0570147f,0.879646f,0.653707f,0.000318855f,
0.94386f,0.285888f,-0.0616165f,0.878786f,0.653638f,0.000365946f, 0.942016f,0.293745f,-0.0635852f,0.877503f,0.653587f,0.000420053f,
0.936109f,0.302319f,-0.0664822f,0.873973f,0.653562f,0.000482148f, 0.931547f,0.310561f,-0.0693227f,0.872088f,0.653564f,0.00055334f,
0.923571f,0.319571f,-0.0734842f,0.869304f,0.653604f,0.000634884f, 0.91567f,0.327842f,-0.0767777f,0.866818f,0.65368f,0.000728182f,
0.910885f,0.334374f,-0.0781178f,0.863925f,0.653808f,0.000834827f, 0.912658f,0.338276f,-0.0757116f,0.859999f,0.653985f,0.000956605f,
0.902027f,0.345451f,-0.0782039f,0.855993f,0.654229f,0.00109551f, 0.894181f,0.353472f,-0.0793171f,0.852973f,0.654539f,0.0012538f,
0.886616f,0.361889f,-0.080257f,0.850539f,0.654933f,0.00143399f, 0.866033f,0.364737f,-0.0828634f,0.84034f,0.655415f,0.0016389f,
0.861998f,0.373198f,-0.0831608f,0.840135f,0.656001f,0.00187164f, 0.859799f,0.382837f,-0.0819139f,0.840206f,0.656702f,0.00213579f,
0.861946f,0.387473f,-0.0759157f,0.835696f,0.657533f,0.00243521f, 0.853891f,0.392239f,-0.0725648f,0.832103f,0.65851f,0.00277426f,
0.849365f,0.397088f,-0.0719712f,0.82748f,0.659649f,0.00315785f, 0.847943f,0.401279f,-0.0705756f,0.827175f,0.660971f,0.00359135f,
0.837982f,0.405156f,-0.0659439f,0.826887f,0.662496f,0.00408073f, 0.824748f,0.408598f,-0.0606831f,0.825732f,0.66425f,0.00463274f,
0.817298f,0.416678f,-0.0539833f,0.830039f,0.666259f,0.00525478f, 0.813056f,0.426661f,-0.0487566f,0.832942f,0.66855f,0.00595515f,
0.813217f,0.433784f,-0.0467916f,0.833332f,0.671163f,0.006743f, 0.813343f,0.442867f,-0.0456472f,0.83757f,0.674125f,0.00762861f,
0.803764f,0.446515f,-0.0481621f,0.842025f,0.67749f,0.0086234f, 0.795597f,0.450544f,-0.0496675f,0.845393f,0.681294f,0.00974009f,
0.788689f,0.45437f,-0.0506385f,0.848972f,0.685591f,0.0109931f, 0.783086f,0.458075f,-0.0510542f,0.852821f,0.69045f,0.0123982f,
0.778789f,0.461709f,-0.0508889f,0.856967f,0.695933f,0.0139737f, 0.767675f,0.452636f,-0.0533644f,0.858695f,0.702117f,0.0157399f,
0.766112f,0.455572f,-0.0518203f,0.862892f,0.709091f,0.0177199f, 0.772292f,0.464166f,-0.045787f,0.864553f,0.71696f,0.01994f,
0.750348f,0.450194f,-0.0433495f,0.838395f,0.725846f,0.0224307f, 0.742054f,0.431275f,-0.0416787f,0.833292f,0.735885f,0.0252268f,
0.743547f,0.427445f,-0.036605f,0.829128f,0.747265f,0.0283695f, 0.738351f,0.419672f,-0.0222106f,0.832387f,0.760182f,0.0319067f,
0.736159f,0.424781f,-0.031942f,0.840059f,0.774907f,0.0358965f, 0.721742f,0.41498f,-0.0339444f,0.845448f,0.791765f,0.0404094f,
0.719204f,0.410711f,-0.0272217f,0.86f,0.811209f,0.0455337f, 0.712772f,0.404393f,-0.0177862f,0.873638f,0.833832f,0.051384f,
0.708161f,0.403906f,-0.00750164f,0.889396f,0.860645f,0.0581182f, 0.723028f,0.399551f,-0.00217378f,0.926796f,0.893133f,0.0659736f,
0.746794f,0.408787f,0.000341623f,0.973442f,0.93467f,0.07539f, 0.716538f,0.405077f,0.010827f,0.997756f,0.996635f,0.0875332f,
1.00471f,0.00658994f,0.00266048f,0.924276f,0.632572f,4.76118e-05f, 1.00815f,0.0186717f,0.00314662f,0.920543f,0.632582f,4.80501e-05f,
1.01142f,0.0312314f,0.00185712f,0.919796f,0.632572f,4.92933e-05f, 1.00852f,0.0448699f,-0.00212601f,0.917807f,0.632558f,5.13951e-05f,
1.00714f,0.0618892f,-0.00316599f,0.916976f,0.632544f,5.44062e-05f, 1.00537f,0.0794425f,-0.00383152f,0.916087f,0.632524f,5.83834e-05f,
1.00362f,0.0926193f,-0.00932671f,0.916716f,0.6325f,6.3403e-05f, 1.0018f,0.116578f,-0.00262696f,0.916643f,0.632475f,6.95711e-05f,
1.00529f,0.131708f,-0.00525493f,0.925317f,0.632447f,7.70102e-05f, 1.00124f,0.146375f,-0.00883429f,0.924582f,0.63242f,8.58749e-05f,
0.996381f,0.160952f,-0.0117667f,0.923793f,0.632394f,9.63434e-05f, 0.992392f,0.174101f,-0.0149084f,0.923008f,0.632369f,0.000108617f,
0.987083f,0.187497f,-0.0183094f,0.9221f,0.63235f,0.00012294f, 0.978898f,0.196459f,-0.0181861f,0.910994f,0.632336f,0.00013959f,
0.977408f,0.205265f,-0.0198613f,0.908609f,0.63233f,0.00015889f, 0.96833f,0.219596f,-0.0243601f,0.908331f,0.632334f,0.000181211f,
0.963305f,0.231271f,-0.028227f,0.909243f,0.632351f,0.000206976f, 0.956556f,0.243608f,-0.0392397f,0.90636f,0.632385f,0.000236666f,
0.950507f,0.254814f,-0.0450166f,0.905764f,0.632436f,0.000270831f, 0.951537f,0.263478f,-0.0553137f,0.903789f,0.632512f,0.000310097f,
0.947898f,0.272882f,-0.0595763f,0.903591f,0.632612f,0.000355169f, 0.950477f,0.27762f,-0.058423f,0.90211f,0.632745f,0.000406848f,
0.939642f,0.288494f,-0.0645964f,0.898141f,0.63291f,0.00046605f, 0.935795f,0.29598f,-0.0670857f,0.896174f,0.633118f,0.000533791f,
0.928415f,0.304595f,-0.0712438f,0.89373f,0.633369f,0.000611235f, 0.920941f,0.312581f,-0.0748181f,0.891273f,0.633675f,0.000699684f,
0.926249f,0.314448f,-0.0703865f,0.886924f,0.634036f,0.000800606f, 0.919941f,0.321445f,-0.0729921f,0.88445f,0.634467f,0.000915641f,
0.911892f,0.328207f,-0.0754204f,0.881676f,0.634968f,0.00104665f, 0.90133f,0.334367f,-0.0771769f,0.876779f,0.635556f,0.0011957f,
0.894335f,0.341273f,-0.0776702f,0.873505f,0.636233f,0.0013651f, 0.875581f,0.345367f,-0.0806381f,0.864945f,0.637017f,0.00155749f,
0.872482f,0.353044f,-0.0803104f,0.864347f,0.637914f,0.00177571f, 0.871725f,0.361242f,-0.0780104f,0.863647f,0.638942f,0.00202309f,
0.870919f,0.36556f,-0.0732061f,0.858809f,0.640111f,0.00230318f, 0.862376f,0.370215f,-0.0694821f,0.856514f,0.64144f,0.00262005f,
0.859596f,0.374675f,-0.0681655f,0.855756f,0.642944f,0.0029782f, 0.858248f,0.37943f,-0.0690333f,0.852396f,0.644644f,0.00338261f,
0.847659f,0.383222f,-0.0635455f,0.853684f,0.646563f,0.00383893f, 0.834845f,0.386496f,-0.0594737f,0.850745f,0.648719f,0.00435335f,
0.827958f,0.394256f,-0.0528571f,0.855391f,0.651149f,0.00493286f, 0.823444f,0.403756f,-0.0477318f,0.858457f,0.65387f,0.00558512f,
0.821963f,0.40951f,-0.0460437f,0.857609f,0.656924f,0.00631883f, 0.823296f,0.418706f,-0.0443147f,0.861526f,0.660346f,0.00714366f,
0.815058f,0.422746f,-0.0465221f,0.866282f,0.664172f,0.00807044f, 0.8047f,0.424234f,-0.0485771f,0.867877f,0.668453f,0.00911129f,
0.800855f,0.429252f,-0.049302f,0.874376f,0.673244f,0.0102797f, 0.795565f,0.432598f,-0.0496286f,0.87807f,0.678599f,0.011591f,
0.789629f,0.432281f,-0.0505359f,0.882441f,0.684586f,0.0130626f, 0.781685f,0.429552f,-0.0508731f,0.88255f,0.691283f,0.0147141f,
0.780932f,0.429148f,-0.0489436f,0.885495f,0.698779f,0.0165678f, 0.787079f,0.436912f,-0.0426489f,0.88658f,0.707178f,0.0186494f,
0.75983f,0.419939f,-0.0415897f,0.856412f,0.716594f,0.0209882f, 0.755398f,0.408794f,-0.0387527f,0.852215f,0.727186f,0.0236188f,
0.756138f,0.405518f,-0.0332726f,0.848586f,0.739117f,0.0265812f, 0.753478f,0.398388f,-0.0194442f,0.855012f,0.752603f,0.0299231f,
0.743123f,0.39642f,-0.0316413f,0.859456f,0.767902f,0.0337017f, 0.730146f,0.395532f,-0.0329264f,0.867732f,0.785368f,0.0379877f,
0.728005f,0.393226f,-0.0282683f,0.873856f,0.805453f,0.0428692f, 0.724444f,0.388199f,-0.0200519f,0.889682f,0.828797f,0.0484616f,
0.71649f,0.382207f,-0.0103664f,0.903536f,0.85637f,0.0549251f, 0.746941f,0.391253f,-0.00816637f,0.951733f,0.889832f,0.0625035f,
0.743241f,0.391046f,0.00102426f,0.982452f,0.932518f,0.0716441f, 0.719259f,0.38612f,0.0108475f,1.01886f,0.996489f,0.0835878f,
1.00391f,0.00630319f,0.00201426f,0.944431f,0.609762f,4.75738e-05f, 1.00792f,0.0174562f,0.00385712f,0.940625f,0.609776f,4.80046e-05f,
1.01088f,0.0294036f,0.000433797f,0.940799f,0.60978f,4.92222e-05f, 1.00953f,0.0426271f,-0.00149626f,0.939652f,0.609787f,5.12797e-05f,
1.00677f,0.0577093f,-0.0032324f,0.937723f,0.609801f,5.42262e-05f, 1.00464f,0.0749169f,-0.00241359f,0.936585f,0.609819f,5.81142e-05f,
1.00388f,0.0874314f,-0.00817405f,0.937718f,0.609841f,6.30162e-05f, 1.00181f,0.109361f,-0.00221028f,0.937475f,0.609871f,6.9034e-05f,
1.00513f,0.123439f,-0.00479572f,0.945926f,0.609907f,7.62836e-05f, 1.0013f,0.137317f,-0.00793217f,0.945406f,0.609951f,8.4912e-05f,
0.997031f,0.150807f,-0.0111552f,0.944806f,0.610006f,9.50838e-05f, 0.992358f,0.163869f,-0.0144511f,0.94413f,0.610071f,0.000106991f,
0.987702f,0.176135f,-0.0176451f,0.943253f,0.61015f,0.000120863f, 0.979506f,0.18398f,-0.0180193f,0.932757f,0.610244f,0.000136963f,
0.97743f,0.193818f,-0.019647f,0.930696f,0.610354f,0.000155594f, 0.970698f,0.205788f,-0.0232821f,0.929889f,0.610486f,0.000177105f,
0.965201f,0.21708f,-0.0271649f,0.930613f,0.610639f,0.000201888f, 0.960206f,0.227495f,-0.0309053f,0.931404f,0.610818f,0.000230392f,
0.954434f,0.238047f,-0.0373372f,0.930633f,0.611026f,0.000263128f, 0.952191f,0.247698f,-0.0482403f,0.927969f,0.611265f,0.000300681f,
0.952506f,0.256021f,-0.0573859f,0.925883f,0.611542f,0.000343707f, 0.955571f,0.260187f,-0.056392f,0.924353f,0.611858f,0.000392951f,
0.943784f,0.271458f,-0.0632148f,0.921192f,0.612223f,0.000449261f, 0.94081f,0.278035f,-0.0650394f,0.918889f,0.612635f,0.000513583f,
0.934869f,0.285876f,-0.0687582f,0.916979f,0.613108f,0.000586992f, 0.927984f,0.293494f,-0.0724918f,0.914549f,0.61364f,0.000670688f,
0.927456f,0.297759f,-0.0717962f,0.911293f,0.614245f,0.000766025f, 0.926285f,0.302219f,-0.0712876f,0.908287f,0.614925f,0.000874528f,
0.917175f,0.308704f,-0.073633f,0.904609f,0.615692f,0.000997903f, 0.907281f,0.314556f,-0.0754035f,0.899939f,0.616553f,0.00113807f,
0.900937f,0.32109f,-0.0758607f,0.896897f,0.61752f,0.00129719f, 0.884934f,0.324944f,-0.0786479f,0.889383f,0.618602f,0.00147763f,
0.881992f,0.331861f,-0.0776877f,0.887965f,0.61981f,0.00168206f, 0.883371f,0.338536f,-0.0735835f,0.886146f,0.621162f,0.00191358f,
0.879236f,0.344237f,-0.0715818f,0.883103f,0.622666f,0.00217545f, 0.87154f,0.348532f,-0.0680649f,0.881266f,0.624344f,0.00247141f,
0.869933f,0.352935f,-0.067337f,0.88062f,0.626208f,0.00280568f, 0.868101f,0.357581f,-0.0677917f,0.877856f,0.628281f,0.00318291f,
0.857632f,0.361306f,-0.0624232f,0.879016f,0.630585f,0.00360835f, 0.845301f,0.364327f,-0.0586467f,0.875988f,0.633138f,0.00408774f,
0.838391f,0.371314f,-0.0524446f,0.880169f,0.635975f,0.00462766f, 0.832916f,0.379297f,-0.0469915f,0.884023f,0.639119f,0.00523536f,
0.831229f,0.384532f,-0.045433f,0.883242f,0.642601f,0.00591891f, 0.832435f,0.394135f,-0.0430533f,0.885221f,0.646464f,0.00668754f,
0.82543f,0.398876f,-0.0448643f,0.89013f,0.650746f,0.00755134f, 0.817568f,0.401696f,-0.0466861f,0.894003f,0.655491f,0.00852186f,
0.807798f,0.401917f,-0.0484474f,0.895132f,0.660751f,0.00961214f, 0.801722f,0.403101f,-0.0494949f,0.899331f,0.666586f,0.0108368f,
0.799714f,0.406845f,-0.0492389f,0.905869f,0.673063f,0.0122123f, 0.794381f,0.407245f,-0.0488596f,0.907614f,0.680259f,0.0137578f,
0.794375f,0.406391f,-0.046312f,0.909445f,0.688263f,0.0154947f, 0.797829f,0.409027f,-0.0415725f,0.910947f,0.697176f,0.0174479f,
0.768199f,0.392325f,-0.0411244f,0.878575f,0.707119f,0.0196462f, 0.766243f,0.387401f,-0.0371722f,0.875196f,0.718248f,0.0221232f,
0.766172f,0.384818f,-0.0317822f,0.872041f,0.730722f,0.0249182f, 0.763924f,0.383378f,-0.0279125f,0.873337f,0.744763f,0.0280783f,
0.755008f,0.377947f,-0.0286267f,0.881197f,0.760649f,0.0316604f, 0.74326f,0.375475f,-0.0320708f,0.89842f,0.778734f,0.0357345f,
0.736542f,0.373905f,-0.027638f,0.89848f,0.799475f,0.0403891f, 0.734124f,0.371832f,-0.0225169f,0.907739f,0.823548f,0.0457407f,
0.726457f,0.366542f,-0.0133135f,0.922197f,0.851942f,0.0519511f, 0.758369f,0.37396f,-0.00803078f,0.98695f,0.886333f,0.0592672f,
0.750052f,0.371767f,0.000475036f,1.01232f,0.930255f,0.0681505f, 0.719459f,0.364267f,0.00908032f,1.03924f,0.996337f,0.0799151f,
1.0042f,0.00597715f,0.00212451f,0.964455f,0.586948f,4.73801e-05f, 1.00495f,0.0171242f,-0.00172095f,0.963869f,0.586961f,4.77912e-05f,
1.01164f,0.0273553f,0.00181997f,0.9613f,0.586978f,4.89799e-05f, 1.01081f,0.0405393f,-0.00061192f,0.960873f,0.587007f,5.09877e-05f,
1.00656f,0.0547186f,-0.00176605f,0.957268f,0.587051f,5.38591e-05f, 1.00453f,0.0703077f,-0.00153535f,0.956375f,0.587108f,5.76467e-05f,
1.00812f,0.0849893f,-0.00335016f,0.962636f,0.587177f,6.24182e-05f, 1.00189f,0.102166f,-0.00161874f,0.957467f,0.587263f,6.82691e-05f,
1.00507f,0.115178f,-0.00419657f,0.965709f,0.587364f,7.53097e-05f, 1.00148f,0.127985f,-0.00726714f,0.96529f,0.587482f,8.36796e-05f,
0.997557f,0.140688f,-0.0103134f,0.964776f,0.58762f,9.35309e-05f, 0.993219f,0.152867f,-0.013489f,0.964208f,0.587777f,0.000105046f,
0.988542f,0.164623f,-0.016716f,0.963564f,0.587956f,0.00011844f, 0.980855f,0.172615f,-0.0168871f,0.953443f,0.588161f,0.000133962f,
0.980743f,0.179644f,-0.0178939f,0.950996f,0.58839f,0.000151898f, 0.971774f,0.192999f,-0.0225413f,0.951183f,0.588651f,0.000172566f,
0.967108f,0.202786f,-0.0258073f,0.951077f,0.588942f,0.000196334f, 0.962524f,0.212421f,-0.0294186f,0.95194f,0.589269f,0.000223622f,
0.957628f,0.221608f,-0.0330499f,0.95258f,0.589635f,0.000254911f, 0.955459f,0.231281f,-0.0454051f,0.94931f,0.590042f,0.000290744f,
0.962614f,0.236056f,-0.0508646f,0.949842f,0.590497f,0.00033173f, 0.959661f,0.243138f,-0.0543228f,0.946352f,0.591002f,0.000378559f,
0.948325f,0.253962f,-0.0610616f,0.943225f,0.591563f,0.000432007f, 0.945407f,0.260222f,-0.063106f,0.941255f,0.592186f,0.000492962f,
0.941646f,0.266636f,-0.0654156f,0.939751f,0.592875f,0.000562415f, 0.935298f,0.273937f,-0.0693854f,0.937343f,0.593639f,0.000641482f,
0.933306f,0.278619f,-0.0697472f,0.934591f,0.594482f,0.000731405f, 0.932425f,0.282645f,-0.0690663f,0.931199f,0.595416f,0.000833603f,
0.922898f,0.288842f,-0.0713555f,0.927033f,0.596444f,0.000949652f, 0.913651f,0.294382f,-0.0731508f,0.922621f,0.59758f,0.00108133f,
0.907786f,0.300557f,-0.0736508f,0.919809f,0.59883f,0.0012306f, 0.894101f,0.304071f,-0.0760581f,0.912959f,0.600207f,0.00139969f,
0.891162f,0.310128f,-0.0747631f,0.9109f,0.601726f,0.00159111f, 0.891332f,0.316669f,-0.0717241f,0.909666f,0.603392f,0.00180758f,
0.889282f,0.32235f,-0.069729f,0.908063f,0.605229f,0.00205231f, 0.885828f,0.326807f,-0.0684227f,0.906053f,0.607247f,0.00232867f,
0.882317f,0.331118f,-0.0673179f,0.904572f,0.609463f,0.0026406f, 0.878128f,0.335332f,-0.0662094f,0.903038f,0.611902f,0.00299245f,
0.867738f,0.338838f,-0.0611631f,0.903798f,0.614578f,0.00338907f, 0.859837f,0.344322f,-0.0564287f,0.904955f,0.617518f,0.00383592f,
0.849419f,0.348174f,-0.0519148f,0.904674f,0.620752f,0.00433902f, 0.842396f,0.35442f,-0.0460073f,0.909278f,0.624303f,0.00490534f,
0.84055f,0.359171f,-0.044589f,0.90863f,0.628204f,0.0055424f, 0.839313f,0.366461f,-0.0426128f,0.908358f,0.632493f,0.00625887f,
0.834231f,0.373116f,-0.0431867f,0.912043f,0.63721f,0.00706449f, 0.82652f,0.375786f,-0.0449596f,0.915618f,0.642403f,0.00797009f,
0.819674f,0.377649f,-0.0464351f,0.919637f,0.648121f,0.00898808f, 0.813791f,0.378896f,-0.0474622f,0.923859f,0.654421f,0.0101325f,
0.808672f,0.379215f,-0.0480927f,0.92817f,0.661372f,0.0114192f, 0.805794f,0.380306f,-0.0472891f,0.931775f,0.669052f,0.0128665f,
0.807732f,0.383444f,-0.0433728f,0.933225f,0.677551f,0.0144952f, 0.809263f,0.382535f,-0.0398236f,0.935171f,0.686967f,0.0163296f,
0.781566f,0.366628f,-0.0398522f,0.905779f,0.697427f,0.0183975f, 0.776704f,0.365233f,-0.0346416f,0.899153f,0.709075f,0.0207318f,
0.77622f,0.363746f,-0.0300972f,0.895454f,0.722099f,0.0233711f, 0.774477f,0.362422f,-0.025497f,0.895261f,0.736707f,0.026362f,
0.757515f,0.367178f,-0.0329477f,0.917465f,0.753178f,0.0297607f, 0.752146f,0.355123f,-0.031145f,0.921707f,0.771876f,0.033637f,
0.744947f,0.354058f,-0.0268883f,0.922889f,0.793288f,0.0380796f, 0.740238f,0.352554f,-0.022033f,0.930123f,0.818097f,0.0432052f,
0.740289f,0.350313f,-0.0161874f,0.94782f,0.847318f,0.049178f, 0.769933f,0.35267f,-0.0083883f,1.02308f,0.882762f,0.0562522f,
0.75784f,0.3525f,-0.000927769f,1.04122f,0.928002f,0.0648997f, 0.731858f,0.337653f,0.00705815f,1.08261f,0.996181f,0.0764954f,
1.00404f,0.00571588f,0.00200689f,0.983167f,0.564219f,4.70336e-05f, 1.00532f,0.0158317f,-0.000293601f,0.981759f,0.564229f,4.7418e-05f,
1.01144f,0.0254978f,0.00196088f,0.980596f,0.56426f,4.85764e-05f, 1.0129f,0.0389374f,0.000846458f,0.9819f,0.564312f,5.05312e-05f,
1.00654f,0.0531982f,0.00160955f,0.975602f,0.564385f,5.33184e-05f, 1.0063f,0.0670544f,0.00138083f,0.977543f,0.564481f,5.69953e-05f,
1.00435f,0.0768432f,-0.00545333f,0.977048f,0.5646f,6.1626e-05f, 1.00203f,0.095009f,-0.00085402f,0.976612f,0.564742f,6.72957e-05f,
1.0051f,0.106955f,-0.00343001f,0.984657f,0.564908f,7.41115e-05f, 1.00181f,0.118952f,-0.00631101f,0.984315f,0.565102f,8.22053e-05f,
0.998151f,0.130606f,-0.00928288f,0.983917f,0.565323f,9.17168e-05f, 0.994142f,0.141892f,-0.0123275f,0.98346f,0.565571f,0.000102819f,
0.9898f,0.152791f,-0.0154251f,0.98292f,0.565853f,0.000115716f, 0.982418f,0.160712f,-0.0155421f,0.973241f,0.566168f,0.000130643f,
0.977981f,0.170469f,-0.0184704f,0.972417f,0.566518f,0.000147857f, 0.973578f,0.179619f,-0.0213006f,0.971436f,0.566908f,0.00016766f,
0.968996f,0.188446f,-0.0241627f,0.970612f,0.567338f,0.000190398f, 0.964812f,0.197304f,-0.0276451f,0.971553f,0.567813f,0.000216468f,
0.960346f,0.205713f,-0.0310709f,0.972279f,0.568337f,0.000246309f, 0.955278f,0.214565f,-0.0371314f,0.971599f,0.568911f,0.000280419f,
0.966341f,0.218855f,-0.0476307f,0.970297f,0.569544f,0.000319371f, 0.962812f,0.226757f,-0.0529323f,0.968369f,0.570235f,0.000363812f,
0.956422f,0.234929f,-0.057307f,0.966364f,0.570994f,0.00041446f, 0.949225f,0.242862f,-0.0617438f,0.963594f,0.571824f,0.000472125f,
0.947506f,0.247667f,-0.0625539f,0.961046f,0.572729f,0.000537728f, 0.942914f,0.253849f,-0.0654127f,0.959035f,0.573722f,0.000612314f,
0.943809f,0.257073f,-0.0641164f,0.956559f,0.574802f,0.000697018f, 0.937849f,0.26283f,-0.0662889f,0.952795f,0.575983f,0.000793159f,
0.928984f,0.268663f,-0.0685952f,0.948919f,0.577271f,0.000902198f, 0.920343f,0.273884f,-0.0704247f,0.944782f,0.578673f,0.00102576f,
0.914882f,0.279673f,-0.0709783f,0.942208f,0.580205f,0.0011657f, 0.903662f,0.282696f,-0.0725805f,0.93569f,0.581872f,0.00132404f,
0.899947f,0.287962f,-0.071581f,0.933162f,0.583688f,0.00150313f, 0.899236f,0.294605f,-0.0693739f,0.932553f,0.585669f,0.00170551f,
0.898413f,0.300191f,-0.0673961f,0.931904f,0.587825f,0.00193405f, 0.89477f,0.304509f,-0.0661603f,0.929846f,0.590174f,0.00219209f,
0.892597f,0.308852f,-0.0651797f,0.92949f,0.592735f,0.00248312f, 0.887787f,0.312575f,-0.0641477f,0.927847f,0.595525f,0.00281128f,
0.878022f,0.315939f,-0.0598326f,0.927917f,0.598563f,0.00318104f, 0.871781f,0.32184f,-0.0549671f,0.930588f,0.601878f,0.00359759f,
0.860137f,0.324211f,-0.0514037f,0.928246f,0.605494f,0.00406657f, 0.853489f,0.329449f,-0.0461818f,0.93223f,0.609439f,0.00459446f,
0.849827f,0.333424f,-0.0435196f,0.933689f,0.613743f,0.00518843f, 0.848231f,0.338972f,-0.0418713f,0.933496f,0.618445f,0.00585668f,
0.847251f,0.347558f,-0.0396067f,0.933802f,0.623584f,0.00660832f, 0.840028f,0.349987f,-0.0414876f,0.938017f,0.629207f,0.00745382f,
0.832744f,0.352167f,-0.0434192f,0.942855f,0.635366f,0.00840496f, 0.826052f,0.35422f,-0.0449967f,0.947938f,0.642118f,0.00947512f,
0.821102f,0.354612f,-0.0455912f,0.952249f,0.649529f,0.0106796f, 0.81872f,0.352628f,-0.0446886f,0.95507f,0.657676f,0.0120361f,
0.819479f,0.356066f,-0.041362f,0.957248f,0.666652f,0.0135645f, 0.821398f,0.357784f,-0.0372718f,0.959171f,0.676561f,0.0152886f,
0.798518f,0.342783f,-0.0376627f,0.936537f,0.687526f,0.0172353f, 0.790539f,0.342936f,-0.0331278f,0.925232f,0.699693f,0.0194369f,
0.786244f,0.342276f,-0.0282335f,0.918844f,0.713248f,0.0219315f, 0.778063f,0.344225f,-0.0300946f,0.931877f,0.728418f,0.0247646f,
0.77055f,0.342259f,-0.0301879f,0.940664f,0.745489f,0.0279924f, 0.761727f,0.334377f,-0.0299173f,0.946475f,0.764808f,0.0316837f,
0.755236f,0.333345f,-0.0261238f,0.950365f,0.786906f,0.0359277f, 0.750359f,0.332147f,-0.0216109f,0.958926f,0.812462f,0.0408419f,
0.754272f,0.330115f,-0.0160363f,0.984831f,0.842594f,0.0465919f, 0.77521f,0.333018f,-0.00927366f,1.04605f,0.879062f,0.0534365f,
0.760939f,0.325999f,-0.00173627f,1.06792f,0.925698f,0.0618661f, 0.740676f,0.313349f,0.0044211f,1.11746f,0.996019f,0.0733101f,
1.0039f,0.00549816f,0.00190493f,1.00101f,0.54166f,4.65373e-05f, 1.00555f,0.0146264f,0.000824966f,0.999003f,0.541669f,4.68967e-05f,
1.01128f,0.0235378f,0.00202309f,0.998938f,0.541715f,4.80242e-05f, 1.01056f,0.0344504f,-0.000283295f,0.998329f,0.54179f,4.99203e-05f,
1.00601f,0.0514235f,0.00560267f,0.992957f,0.541892f,5.2618e-05f, 1.00438f,0.0610868f,0.00065498f,0.99332f,0.542027f,5.61763e-05f,
1.00969f,0.0753483f,0.00133496f,1.00192f,0.542194f,6.06564e-05f, 1.00216f,0.0880487f,0.000442091f,0.99501f,0.542392f,6.6134e-05f,
1.00521f,0.0987934f,-0.00249947f,1.00276f,0.542624f,7.27131e-05f, 1.00217f,0.109855f,-0.00522884f,1.00251f,0.542892f,8.05169e-05f,
0.9988f,0.120587f,-0.0080698f,1.00222f,0.543195f,8.96741e-05f, 0.995435f,0.13067f,-0.0108408f,1.00177f,0.543537f,0.00010035f,
0.991122f,0.14101f,-0.0139381f,1.00148f,0.54392f,0.000112739f, 0.984815f,0.147772f,-0.0137192f,0.991924f,0.544344f,0.00012705f,
0.979444f,0.157844f,-0.0170848f,0.991678f,0.544814f,0.000143529f, 0.975398f,0.166229f,-0.0197928f,0.990864f,0.545331f,0.00016246f,
0.972018f,0.173916f,-0.0220152f,0.989694f,0.545898f,0.000184171f, 0.967041f,0.1822f,-0.0255901f,0.990237f,0.54652f,0.000209013f,
0.963005f,0.189861f,-0.0288918f,0.991082f,0.547199f,0.000237405f, 0.959117f,0.198083f,-0.0360957f,0.989309f,0.547939f,0.000269822f,
0.970339f,0.20149f,-0.04412f,0.98987f,0.548746f,0.000306777f, 0.969771f,0.207691f,-0.0482653f,0.98879f,0.549621f,0.000348868f,
0.95799f,0.21804f,-0.055087f,0.985906f,0.550573f,0.00039678f, 0.9534f,0.22427f,-0.0579577f,0.984035f,0.551606f,0.000451246f,
0.952999f,0.228546f,-0.0591273f,0.981506f,0.552724f,0.000513133f, 0.950291f,0.233569f,-0.0609505f,0.979822f,0.553938f,0.000583396f,
0.949829f,0.237062f,-0.0605181f,0.977273f,0.555252f,0.000663089f, 0.943705f,0.242761f,-0.062994f,0.973854f,0.556673f,0.00075344f,
0.935221f,0.24815f,-0.0652356f,0.970283f,0.558213f,0.000855781f, 0.927292f,0.253103f,-0.0672336f,0.966395f,0.559878f,0.000971649f,
0.922163f,0.258489f,-0.0678751f,0.964048f,0.561678f,0.00110272f, 0.912047f,0.261305f,-0.0693534f,0.957938f,0.563628f,0.00125093f,
0.907706f,0.265987f,-0.0687796f,0.955234f,0.565736f,0.00141839f, 0.90694f,0.27206f,-0.0667508f,0.954699f,0.568015f,0.0016075f,
0.906319f,0.277894f,-0.064545f,0.954339f,0.570484f,0.00182096f, 0.904664f,0.281763f,-0.0636539f,0.953868f,0.573154f,0.00206179f,
0.901703f,0.285717f,-0.0628843f,0.953089f,0.576043f,0.0023333f, 0.898393f,0.289927f,-0.0615202f,0.953174f,0.579171f,0.00263932f,
0.889352f,0.293167f,-0.0578816f,0.952844f,0.582562f,0.00298416f, 0.882802f,0.298198f,-0.0537475f,0.954527f,0.586236f,0.00337252f,
0.874144f,0.301965f,-0.0497517f,0.955033f,0.590219f,0.00380976f, 0.864818f,0.304207f,-0.0464259f,0.954406f,0.59454f,0.00430197f,
0.859723f,0.307593f,-0.0426909f,0.957738f,0.599232f,0.00485602f, 0.85772f,0.311298f,-0.0408536f,0.958962f,0.60433f,0.00547956f,
0.856021f,0.320009f,-0.0387139f,0.958882f,0.609876f,0.0061813f, 0.854489f,0.324091f,-0.0370308f,0.959548f,0.615915f,0.0069711f,
0.846315f,0.325563f,-0.0397459f,0.965185f,0.622497f,0.00786031f, 0.840114f,0.32756f,-0.0411386f,0.97012f,0.629681f,0.00886175f,
0.835642f,0.329916f,-0.041359f,0.974501f,0.637536f,0.00999008f, 0.833783f,0.325754f,-0.040247f,0.976553f,0.646142f,0.0112622f,
0.830456f,0.326277f,-0.0397696f,0.981433f,0.655581f,0.0126977f, 0.832889f,0.33112f,-0.034973f,0.983258f,0.665972f,0.0143193f,
0.818435f,0.320149f,-0.0345726f,0.970477f,0.677432f,0.0161536f, 0.80812f,0.31871f,-0.0309325f,0.957964f,0.690113f,0.0182318f,
0.799954f,0.319549f,-0.0261764f,0.947249f,0.704205f,0.0205914f, 0.790131f,0.317799f,-0.0250189f,0.946489f,0.719933f,0.0232775f,
0.783018f,0.316273f,-0.0221861f,0.956833f,0.737587f,0.0263452f, 0.775513f,0.311832f,-0.0266299f,0.971066f,0.757552f,0.0298636f,
0.772005f,0.310168f,-0.025655f,0.988839f,0.780342f,0.0339215f, 0.766405f,0.309188f,-0.0214136f,0.998006f,0.806688f,0.0386371f,
0.768921f,0.309635f,-0.0157363f,1.02359f,0.837685f,0.0441788f, 0.789514f,0.313374f,-0.0127155f,1.07678f,0.875215f,0.0508085f,
0.760615f,0.297395f,-0.00414134f,1.08492f,0.923292f,0.0590311f, 0.770847f,0.293192f,-0.00557202f,1.16812f,0.995852f,0.0703424f,
1.00383f,0.00529707f,0.00177268f,1.01799f,0.519353f,4.58963e-05f, 1.00545f,0.0135576f,0.00126248f,1.01582f,0.519367f,4.62466e-05f,
1.01113f,0.0216572f,0.00211271f,1.0164f,0.519425f,4.73343e-05f, 1.01253f,0.0330409f,0.00134601f,1.01764f,0.519521f,4.91669e-05f,
1.00587f,0.0476976f,0.00666494f,1.01004f,0.519653f,5.17732e-05f, 1.00425f,0.0569371f,0.0020812f,1.01058f,0.519827f,5.52063e-05f,
1.00892f,0.0693735f,0.00235188f,1.01825f,0.52004f,5.95271e-05f, 1.00242f,0.0808855f,0.0011765f,1.01229f,0.520294f,6.48055e-05f,
1.00543f,0.0906725f,-0.00139732f,1.01999f,0.520591f,7.11393e-05f, 1.0026f,0.100838f,-0.00400286f,1.01986f,0.52093f,7.86419e-05f,
0.999492f,0.110658f,-0.00668249f,1.01967f,0.521315f,8.74357e-05f, 0.996096f,0.120164f,-0.00943982f,1.01944f,0.521747f,9.7677e-05f,
0.992443f,0.129325f,-0.0122557f,1.01917f,0.522228f,0.000109545f, 0.987296f,0.134818f,-0.0116325f,1.0097f,0.52276f,0.000123232f,
0.981326f,0.144919f,-0.0152971f,1.00994f,0.523346f,0.000138975f, 0.977203f,0.152889f,-0.0180813f,1.00944f,0.523988f,0.000157038f,
0.97428f,0.159452f,-0.0202207f,1.00841f,0.52469f,0.000177711f, 0.969286f,0.167116f,-0.0232466f,1.00801f,0.525454f,0.000201345f,
0.965554f,0.174073f,-0.0264227f,1.00894f,0.526284f,0.000228313f, 0.961569f,0.181077f,-0.030764f,1.00917f,0.527185f,0.000259049f,
0.970518f,0.184841f,-0.0389185f,1.0088f,0.52816f,0.000294056f, 0.976116f,0.188708f,-0.0433315f,1.00815f,0.529214f,0.000333865f,
0.961193f,0.199391f,-0.0495915f,1.00578f,0.530355f,0.000379118f, 0.956719f,0.205113f,-0.0525011f,1.00329f,0.531583f,0.000430496f,
0.958067f,0.20962f,-0.055792f,1.00152f,0.532908f,0.000488801f, 0.956078f,0.213693f,-0.0566901f,0.999813f,0.534337f,0.000554904f,
0.955652f,0.217081f,-0.0566855f,0.997357f,0.535874f,0.00062982f, 0.949761f,0.222422f,-0.0592811f,0.994292f,0.537529f,0.000714634f,
0.942226f,0.227486f,-0.0616965f,0.991179f,0.539311f,0.000810629f, 0.934404f,0.232081f,-0.0635949f,0.987424f,0.541228f,0.000919193f,
0.930246f,0.236932f,-0.0644464f,0.985841f,0.543289f,0.0010419f, 0.920222f,0.239711f,-0.0658743f,0.979651f,0.545509f,0.00118053f,
0.916398f,0.24413f,-0.0653739f,0.977384f,0.547896f,0.00133707f, 0.914218f,0.248676f,-0.0640917f,0.975952f,0.550464f,0.00151374f,
0.913336f,0.254601f,-0.0614598f,0.975877f,0.553229f,0.00171304f, 0.91238f,0.259051f,-0.0605564f,0.975823f,0.556206f,0.00193778f,
0.910446f,0.262693f,-0.0600952f,0.975987f,0.559413f,0.00219111f, 0.90786f,0.266234f,-0.0595206f,0.975948f,0.562867f,0.00247656f,
0.901005f,0.270155f,-0.055807f,0.977336f,0.56659f,0.00279812f, 0.893473f,0.273902f,-0.0525983f,0.977355f,0.570606f,0.00316027f,
0.883414f,0.276117f,-0.0498172f,0.975154f,0.574941f,0.00356809f, 0.876222f,0.278716f,-0.046612f,0.975986f,0.579624f,0.00402727f,
0.871563f,0.281729f,-0.0433409f,0.978996f,0.584686f,0.00454423f, 0.867733f,0.284701f,-0.0399088f,0.983353f,0.590165f,0.00512629f,
0.86474f,0.291364f,-0.0377296f,0.983728f,0.5961f,0.00578179f, 0.863235f,0.295915f,-0.0360301f,0.984532f,0.602537f,0.00652003f,
0.860363f,0.298976f,-0.0352944f,0.986721f,0.609526f,0.00735185f, 0.854618f,0.300302f,-0.0365636f,0.991471f,0.617129f,0.00828955f,
0.849231f,0.302479f,-0.0374169f,0.996479f,0.625416f,0.00934724f, 0.848874f,0.298836f,-0.0353998f,0.997954f,0.634458f,0.0105412f,
0.846007f,0.300282f,-0.0345026f,1.00253f,0.644356f,0.0118903f, 0.843014f,0.301426f,-0.0333177f,1.00705f,0.655214f,0.0134167f,
0.836239f,0.295263f,-0.0316844f,1.00286f,0.667159f,0.0151463f, 0.825353f,0.293369f,-0.0285971f,0.990846f,0.680347f,0.0171097f,
0.818235f,0.294713f,-0.0239641f,0.982357f,0.694966f,0.0193434f, 0.812406f,0.29578f,-0.0211163f,0.984673f,0.71125f,0.021892f,
0.801391f,0.290054f,-0.0237353f,0.993455f,0.729505f,0.0248104f, 0.796798f,0.289781f,-0.0217738f,1.00386f,0.750119f,0.0281668f,
0.78916f,0.287016f,-0.0198406f,1.01202f,0.773609f,0.0320502f, 0.785385f,0.28489f,-0.0175992f,1.03079f,0.800756f,0.0365795f,
0.783938f,0.28183f,-0.0175405f,1.06078f,0.83267f,0.0419246f, 0.783934f,0.281693f,-0.0144212f,1.0845f,0.871332f,0.0483541f,
0.795975f,0.281364f,-0.0077263f,1.15497f,0.92079f,0.0563805f, 0.788524f,0.270273f,-0.0239949f,1.17437f,0.99568f,0.0675761f,
1.00369f,0.0051558f,0.00170794f,1.03411f,0.497368f,4.51182e-05f, 1.00452f,0.0127759f,-0.000245225f,1.03304f,0.497398f,4.54794e-05f,
1.01105f,0.0197942f,0.00229874f,1.03298f,0.497465f,4.65206e-05f, 1.01274f,0.0300614f,0.00228303f,1.03428f,0.497581f,4.82862e-05f,
1.00578f,0.0440195f,0.00784887f,1.02623f,0.497744f,5.08001e-05f, 1.00432f,0.0519987f,0.00345453f,1.02671f,0.497953f,5.41013e-05f,
1.0081f,0.0635937f,0.00346598f,1.03366f,0.498212f,5.82584e-05f, 1.00266f,0.0739571f,0.00243492f,1.02882f,0.49852f,6.33318e-05f,
1.00563f,0.0827438f,-0.00017833f,1.0364f,0.498877f,6.94128e-05f, 1.00306f,0.0919358f,-0.00260894f,1.03635f,0.499288f,7.66089e-05f,
1.00021f,0.100851f,-0.00513139f,1.03627f,0.499752f,8.50329e-05f, 0.997102f,0.109469f,-0.00773183f,1.03616f,0.50027f,9.48368e-05f,
0.993756f,0.117773f,-0.0103947f,1.03602f,0.500847f,0.000106176f, 0.98985f,0.121881f,-0.00928933f,1.02657f,0.501482f,0.000119242f,
0.984335f,0.13113f,-0.0127712f,1.02693f,0.502179f,0.000134251f, 0.978972f,0.139639f,-0.0161626f,1.02716f,0.502942f,0.000151441f,
0.980037f,0.142716f,-0.0164226f,1.02499f,0.503772f,0.000171102f, 0.973725f,0.151004f,-0.02014f,1.02539f,0.504673f,0.000193533f,
0.967956f,0.158408f,-0.0236849f,1.02581f,0.50565f,0.000219108f, 0.964561f,0.164192f,-0.0266491f,1.02675f,0.506704f,0.000248211f,
0.970902f,0.168072f,-0.0336807f,1.02671f,0.507842f,0.000281314f, 0.980717f,0.170576f,-0.0389457f,1.02638f,0.509069f,0.000318911f,
0.964211f,0.180741f,-0.0441053f,1.02265f,0.510387f,0.000361597f, 0.961523f,0.186194f,-0.0481751f,1.02196f,0.511804f,0.00041f,
0.961894f,0.189932f,-0.0501712f,1.02013f,0.513327f,0.00046487f, 0.959485f,0.193959f,-0.0518573f,1.01924f,0.51496f,0.000527011f,
0.961289f,0.197033f,-0.0525542f,1.01667f,0.516711f,0.000597347f, 0.955837f,0.201924f,-0.0551017f,1.01397f,0.51859f,0.000676921f,
0.950616f,0.206381f,-0.0577513f,1.01263f,0.520603f,0.000766889f, 0.941593f,0.210859f,-0.059525f,1.00784f,0.522759f,0.000868547f,
0.939168f,0.21499f,-0.0607442f,1.00769f,0.52507f,0.000983368f, 0.928411f,0.217887f,-0.0620055f,1.00079f,0.527547f,0.00111299f,
0.92529f,0.222117f,-0.0615381f,0.999153f,0.5302f,0.00125926f, 0.92311f,0.226192f,-0.060606f,0.998003f,0.533043f,0.00142427f,
0.921364f,0.230348f,-0.0590077f,0.996919f,0.53609f,0.00161032f, 0.920439f,0.235761f,-0.0573028f,0.997595f,0.539358f,0.00182006f,
0.918666f,0.239494f,-0.0569279f,0.998081f,0.542865f,0.00205641f, 0.916615f,0.242781f,-0.0565626f,0.998551f,0.546629f,0.00232267f,
0.910852f,0.24571f,-0.0542891f,0.99907f,0.55067f,0.00262259f, 0.903554f,0.248901f,-0.0516028f,0.998766f,0.555014f,0.00296045f,
0.894109f,0.25078f,-0.0490896f,0.996835f,0.559684f,0.00334094f, 0.887743f,0.253028f,-0.0468065f,0.996866f,0.564711f,0.00376941f,
0.889547f,0.257272f,-0.0443817f,1.00315f,0.570125f,0.00425203f, 0.880809f,0.258649f,-0.0408623f,1.00448f,0.575965f,0.00479564f,
0.873712f,0.260689f,-0.0370822f,1.00787f,0.582273f,0.00540825f, 0.871411f,0.267298f,-0.0349672f,1.00894f,0.589092f,0.00609871f,
0.870292f,0.270686f,-0.0333373f,1.01085f,0.596471f,0.00687731f, 0.868176f,0.273491f,-0.0320967f,1.01315f,0.60448f,0.00775587f,
0.863797f,0.275269f,-0.0324589f,1.01778f,0.613176f,0.008748f, 0.863581f,0.271734f,-0.0302694f,1.01905f,0.622651f,0.00986941f,
0.859035f,0.272145f,-0.0306978f,1.02504f,0.632989f,0.0111383f, 0.85429f,0.272023f,-0.0310772f,1.03148f,0.644303f,0.0125762f,
0.843313f,0.266868f,-0.0299896f,1.02279f,0.656725f,0.0142082f, 0.842171f,0.266894f,-0.0261518f,1.02383f,0.670412f,0.0160644f,
0.836293f,0.268378f,-0.0222061f,1.01958f,0.685551f,0.0181807f, 0.832121f,0.269398f,-0.0202777f,1.02643f,0.702402f,0.020601f,
0.821861f,0.265768f,-0.0198882f,1.02878f,0.721253f,0.0233793f, 0.817931f,0.265249f,-0.0182223f,1.04167f,0.742515f,0.026584f,
0.815102f,0.263993f,-0.0165772f,1.06026f,0.76672f,0.0303036f, 0.80862f,0.259184f,-0.0185329f,1.07464f,0.794673f,0.0346579f,
0.802568f,0.25776f,-0.0246843f,1.08644f,0.827528f,0.0398189f, 0.825181f,0.265552f,-0.0209868f,1.15256f,0.867287f,0.0460576f,
0.81781f,0.258641f,-0.0217428f,1.17542f,0.918196f,0.0539013f, 0.797866f,0.243973f,-0.033716f,1.19372f,0.995504f,0.0649967f,
1.00371f,0.00504703f,0.00157694f,1.04933f,0.475796f,4.42616e-05f, 1.00399f,0.0119402f,-0.00121468f,1.04915f,0.475822f,4.45946e-05f,
1.01103f,0.017962f,0.00252178f,1.04869f,0.475903f,4.55994e-05f, 1.01258f,0.0267593f,0.00205237f,1.04963f,0.476038f,4.72939e-05f,
1.00538f,0.0404361f,0.0096718f,1.04144f,0.476228f,4.97095e-05f, 1.00694f,0.0496268f,0.00846889f,1.04564f,0.476474f,5.28808e-05f,
1.00739f,0.0574927f,0.0045684f,1.04802f,0.476776f,5.68687e-05f, 1.00282f,0.0673671f,0.00456113f,1.04473f,0.477133f,6.1732e-05f,
1.00591f,0.0748926f,0.00119802f,1.05195f,0.477551f,6.75593e-05f, 1.00356f,0.0831663f,-0.00106625f,1.05198f,0.478028f,7.44435e-05f,
1.00095f,0.0911815f,-0.00342329f,1.05202f,0.478566f,8.24972e-05f, 0.998111f,0.0989251f,-0.00586124f,1.05203f,0.479168f,9.18592e-05f,
0.995074f,0.106359f,-0.00835625f,1.05202f,0.479833f,0.000102672f, 0.992457f,0.109003f,-0.0067022f,1.04252f,0.480568f,0.000115123f,
0.987367f,0.117417f,-0.00999475f,1.04301f,0.481372f,0.000129398f, 0.982191f,0.125355f,-0.0133156f,1.04348f,0.482248f,0.000145739f,
0.978389f,0.131638f,-0.0159592f,1.04337f,0.483201f,0.000164392f, 0.978208f,0.134926f,-0.0167114f,1.04184f,0.484233f,0.00018566f,
0.972402f,0.141892f,-0.0202291f,1.04235f,0.485346f,0.000209867f, 0.967358f,0.147937f,-0.0235208f,1.04293f,0.486548f,0.000237386f,
0.972319f,0.151258f,-0.0289973f,1.04345f,0.487841f,0.000268647f, 0.984978f,0.15256f,-0.0342805f,1.04369f,0.489228f,0.000304109f,
0.969096f,0.162758f,-0.0406818f,1.04142f,0.490717f,0.000344323f, 0.963167f,0.164249f,-0.035952f,1.03694f,0.492314f,0.000389886f,
0.966795f,0.17016f,-0.0445807f,1.03781f,0.494021f,0.000441464f, 0.965233f,0.174254f,-0.047525f,1.03751f,0.495849f,0.000499822f,
0.966709f,0.177014f,-0.0482041f,1.03535f,0.497804f,0.000565824f, 0.962406f,0.181249f,-0.0505323f,1.03331f,0.499892f,0.000640423f,
0.95658f,0.185449f,-0.053129f,1.03146f,0.502123f,0.000724687f, 0.948781f,0.189492f,-0.0550508f,1.02759f,0.504506f,0.000819842f,
0.947612f,0.192926f,-0.0566152f,1.02859f,0.507053f,0.000927236f, 0.936537f,0.195874f,-0.0577712f,1.02133f,0.509772f,0.0010484f,
0.933868f,0.198911f,-0.0580201f,1.02021f,0.512676f,0.00118507f, 0.932064f,0.203522f,-0.056519f,1.01937f,0.515778f,0.00133915f,
0.930296f,0.206899f,-0.0554879f,1.01857f,0.519093f,0.00151282f, 0.927943f,0.210695f,-0.0546743f,1.01813f,0.522637f,0.00170855f,
0.925073f,0.214888f,-0.0540167f,1.01805f,0.526426f,0.00192906f, 0.925128f,0.219127f,-0.0532802f,1.02059f,0.530482f,0.00217749f,
0.921453f,0.221602f,-0.0529943f,1.01987f,0.534823f,0.00245733f, 0.915092f,0.224502f,-0.0500479f,1.02125f,0.539475f,0.00277252f,
0.907789f,0.22708f,-0.0475718f,1.02113f,0.544464f,0.00312763f, 0.899121f,0.228819f,-0.0451235f,1.0202f,0.549818f,0.00352766f,
0.895804f,0.230532f,-0.0435768f,1.02184f,0.555568f,0.00397834f, 0.891248f,0.231949f,-0.0415622f,1.02345f,0.561752f,0.00448637f,
0.885911f,0.23444f,-0.0379796f,1.0282f,0.568413f,0.00505917f, 0.880576f,0.236573f,-0.0340401f,1.03394f,0.575596f,0.00570528f,
0.870167f,0.239672f,-0.03343f,1.02623f,0.583352f,0.00643451f, 0.865595f,0.241674f,-0.0323653f,1.02498f,0.591747f,0.00725826f,
0.869735f,0.245515f,-0.0299739f,1.03417f,0.600845f,0.00818946f, 0.871464f,0.24618f,-0.0280688f,1.04107f,0.610729f,0.00924336f,
0.866346f,0.243154f,-0.0273744f,1.04093f,0.621495f,0.0104377f, 0.869716f,0.244975f,-0.0251933f,1.05248f,0.633256f,0.0117931f,
0.852685f,0.24214f,-0.0269049f,1.04385f,0.646147f,0.0133343f, 0.852512f,0.241894f,-0.0234374f,1.04761f,0.660325f,0.0150904f,
0.854118f,0.240159f,-0.0212961f,1.05996f,0.675988f,0.017097f, 0.844716f,0.239471f,-0.0205312f,1.06135f,0.693384f,0.0193971f,
0.840715f,0.239168f,-0.0189457f,1.0717f,0.712832f,0.0220443f, 0.830858f,0.238851f,-0.0188384f,1.07718f,0.734751f,0.0251066f,
0.824617f,0.23642f,-0.0214266f,1.08422f,0.759685f,0.0286724f, 0.808744f,0.228829f,-0.0235166f,1.09395f,0.788452f,0.0328621f,
0.822312f,0.232324f,-0.0325565f,1.11311f,0.82224f,0.0378492f, 0.841996f,0.240227f,-0.0342613f,1.16298f,0.863203f,0.0439122f,
0.834628f,0.233803f,-0.0374304f,1.18386f,0.915638f,0.0515899f, 0.805904f,0.217521f,-0.0414376f,1.21716f,0.995323f,0.0625906f,
1.0037f,0.00497607f,0.00148962f,1.0637f,0.454678f,4.33032e-05f, 1.00382f,0.0109948f,-0.000935656f,1.06342f,0.454704f,4.36116e-05f,
1.01104f,0.016529f,0.00322229f,1.06373f,0.454799f,4.45829e-05f, 1.01272f,0.0239247f,0.00266997f,1.0644f,0.45495f,4.6204e-05f,
1.00523f,0.0368441f,0.0111941f,1.05584f,0.455168f,4.85214e-05f, 1.00584f,0.0443929f,0.00894756f,1.05867f,0.455445f,5.15585e-05f,
1.00719f,0.0521119f,0.00650898f,1.06233f,0.455788f,5.5376e-05f, 1.0031f,0.0606495f,0.00608193f,1.05952f,0.456195f,6.00291e-05f,
1.00624f,0.06718f,0.00270425f,1.06665f,0.456667f,6.55991e-05f, 1.00408f,0.074548f,0.000611896f,1.06679f,0.457207f,7.21718e-05f,
1.0017f,0.081679f,-0.0015739f,1.06693f,0.457815f,7.9859e-05f, 0.999113f,0.0885546f,-0.00384061f,1.06706f,0.458493f,8.87757e-05f,
0.996334f,0.0951673f,-0.00617343f,1.06719f,0.459245f,9.90754e-05f, 0.99511f,0.096211f,-0.00388134f,1.05756f,0.460071f,0.000110908f,
0.990423f,0.103805f,-0.00697621f,1.05819f,0.460975f,0.000124473f, 0.985402f,0.111365f,-0.0101718f,1.05888f,0.461959f,0.000139972f,
0.986559f,0.113256f,-0.01039f,1.05723f,0.463025f,0.000157647f, 0.982723f,0.11892f,-0.0129718f,1.05737f,0.464179f,0.000177778f,
0.977402f,0.125177f,-0.0163041f,1.05804f,0.465423f,0.00020066f, 0.972165f,0.130866f,-0.0195866f,1.05866f,0.46676f,0.000226646f,
0.969163f,0.135022f,-0.022179f,1.05958f,0.468197f,0.000256131f, 0.982301f,0.136523f,-0.029138f,1.05783f,0.469738f,0.000289549f,
0.974304f,0.143421f,-0.0343985f,1.05888f,0.471386f,0.000327393f, 0.966932f,0.147795f,-0.0358742f,1.05673f,0.473148f,0.000370227f,
0.971728f,0.150926f,-0.039825f,1.0553f,0.475031f,0.00041868f, 0.970849f,0.154653f,-0.0429809f,1.05502f,0.477041f,0.000473453f,
0.971712f,0.157024f,-0.0435408f,1.0533f,0.479184f,0.000535339f, 0.968839f,0.160505f,-0.0455536f,1.05186f,0.481469f,0.000605225f,
0.964063f,0.164191f,-0.0483046f,1.05088f,0.483905f,0.000684122f, 0.961455f,0.167116f,-0.050898f,1.05133f,0.486501f,0.00077314f,
0.955942f,0.17072f,-0.0521571f,1.04885f,0.489266f,0.000873554f, 0.944582f,0.173709f,-0.0532058f,1.04127f,0.492212f,0.000986786f,
0.942303f,0.176062f,-0.0538507f,1.04062f,0.495351f,0.00111445f, 0.940653f,0.180578f,-0.0523204f,1.04013f,0.498696f,0.00125832f,
0.93901f,0.183769f,-0.0514028f,1.03966f,0.502261f,0.00142044f, 0.936761f,0.186735f,-0.0511263f,1.03949f,0.506063f,0.00160311f,
0.934123f,0.189599f,-0.0511886f,1.03959f,0.510119f,0.00180888f, 0.931506f,0.193156f,-0.0507006f,1.03999f,0.514449f,0.00204071f,
0.932913f,0.197398f,-0.0500304f,1.04361f,0.519073f,0.00230185f, 0.92613f,0.199724f,-0.0489966f,1.04166f,0.524016f,0.00259605f,
0.920831f,0.202625f,-0.0461445f,1.04419f,0.529303f,0.00292755f, 0.915901f,0.204937f,-0.044146f,1.04574f,0.534964f,0.00330115f,
0.90873f,0.20616f,-0.0422914f,1.04553f,0.541031f,0.0037223f, 0.905653f,0.207544f,-0.0408726f,1.04778f,0.547544f,0.00419724f,
0.900591f,0.210383f,-0.0393285f,1.04798f,0.554539f,0.00473306f, 0.894642f,0.212013f,-0.0362573f,1.05181f,0.56207f,0.00533798f,
0.889094f,0.213016f,-0.0322766f,1.05859f,0.570185f,0.00602145f, 0.880842f,0.213902f,-0.0302874f,1.05793f,0.578949f,0.00679416f,
0.876559f,0.215712f,-0.0292704f,1.05795f,0.588433f,0.0076688f, 0.870878f,0.216873f,-0.0293585f,1.0544f,0.598718f,0.00866f,
0.868056f,0.216829f,-0.0272569f,1.05987f,0.609901f,0.00978474f, 0.86814f,0.21662f,-0.0256392f,1.06718f,0.622096f,0.0110634f,
0.868215f,0.214686f,-0.0254257f,1.07229f,0.635442f,0.0125198f, 0.871544f,0.215661f,-0.0245302f,1.08181f,0.650104f,0.0141825f,
0.870598f,0.216263f,-0.0235933f,1.08941f,0.666284f,0.0160865f, 0.863954f,0.213759f,-0.0211535f,1.09939f,0.684235f,0.018274f,
0.848953f,0.211173f,-0.0228321f,1.09462f,0.704284f,0.0207983f, 0.845208f,0.207948f,-0.0212325f,1.11149f,0.726843f,0.0237266f,
0.822696f,0.202343f,-0.0257413f,1.1036f,0.752518f,0.0271478f, 0.823812f,0.207315f,-0.0335516f,1.10842f,0.782104f,0.0311826f,
0.842345f,0.204962f,-0.0392128f,1.14543f,0.816891f,0.0360063f, 0.866256f,0.214794f,-0.0429611f,1.20199f,0.859002f,0.0419014f,
0.856698f,0.206459f,-0.0498169f,1.21508f,0.913017f,0.0494248f, 0.831369f,0.196517f,-0.0543121f,1.25902f,0.995137f,0.0603451f,
1.0036f,0.00490127f,0.00147415f,1.07724f,0.434062f,4.22428e-05f, 1.00605f,0.00967612f,0.00247648f,1.07585f,0.4341f,4.2557e-05f,
1.01108f,0.014401f,0.00310621f,1.07747f,0.4342f,4.34774e-05f, 1.0126f,0.0212825f,0.00356292f,1.07797f,0.434372f,4.50347e-05f,
1.00543f,0.0330772f,0.0120222f,1.06953f,0.434611f,4.72468e-05f, 1.00558f,0.0399256f,0.0106281f,1.07196f,0.434921f,5.01524e-05f,
1.00674f,0.046613f,0.00822385f,1.07536f,0.435301f,5.3799e-05f, 1.00342f,0.0540111f,0.00751652f,1.07338f,0.435751f,5.82402e-05f,
1.00606f,0.0597566f,0.00455474f,1.07983f,0.436275f,6.35557e-05f, 1.00462f,0.0661018f,0.00241695f,1.08075f,0.436871f,6.98181e-05f,
1.00245f,0.0723611f,0.000409055f,1.081f,0.437546f,7.71389e-05f, 1.0001f,0.0783853f,-0.00168254f,1.08126f,0.438296f,8.56249e-05f,
0.997573f,0.0841596f,-0.00384541f,1.08152f,0.439125f,9.5407e-05f, 0.997781f,0.0835528f,-0.000846578f,1.07171f,0.440037f,0.000106647f,
0.993481f,0.0903331f,-0.00373223f,1.07247f,0.441033f,0.000119508f, 0.984959f,0.103188f,-0.00776303f,1.07465f,0.442116f,0.000134186f,
0.991853f,0.0971767f,-0.00594796f,1.07123f,0.443289f,0.000150916f, 0.987198f,0.103067f,-0.00896525f,1.07201f,0.444555f,0.000169942f,
0.982378f,0.108599f,-0.0120802f,1.07283f,0.445919f,0.000191548f, 0.977651f,0.113602f,-0.0151638f,1.07363f,0.447383f,0.000216054f,
0.973939f,0.117645f,-0.0178845f,1.07445f,0.448953f,0.000243833f, 0.988783f,0.118367f,-0.0246784f,1.07482f,0.450633f,0.000275289f,
0.971064f,0.123861f,-0.0231386f,1.07127f,0.452429f,0.000310879f, 0.970952f,0.129076f,-0.0307967f,1.07313f,0.454346f,0.000351124f,
0.976001f,0.131637f,-0.0342368f,1.07139f,0.456389f,0.000396602f, 0.975746f,0.134946f,-0.0376393f,1.07166f,0.458567f,0.000447971f,
0.976512f,0.13712f,-0.0386623f,1.07051f,0.460886f,0.000505965f, 0.974783f,0.140047f,-0.039873f,1.06925f,0.463354f,0.000571409f,
0.96949f,0.143224f,-0.0428655f,1.06795f,0.465978f,0.000645236f, 0.96602f,0.14592f,-0.0454397f,1.06777f,0.46877f,0.000728498f,
0.963255f,0.148618f,-0.0472247f,1.06772f,0.471738f,0.000822374f, 0.952591f,0.151408f,-0.0483601f,1.06069f,0.474895f,0.000928174f,
0.950502f,0.153343f,-0.0492385f,1.06039f,0.478251f,0.00104739f, 0.948968f,0.156699f,-0.0483844f,1.06017f,0.481822f,0.00118174f,
0.947453f,0.160552f,-0.0470295f,1.06013f,0.48562f,0.00133308f, 0.945308f,0.163141f,-0.0470663f,1.06031f,0.489662f,0.00150357f,
0.942864f,0.165628f,-0.0473712f,1.06073f,0.493966f,0.00169563f, 0.941044f,0.168022f,-0.0481561f,1.06066f,0.498552f,0.00191199f,
0.940454f,0.170915f,-0.0485229f,1.06172f,0.50344f,0.00215575f, 0.936616f,0.174188f,-0.0473138f,1.06236f,0.508655f,0.00243044f,
0.932891f,0.17739f,-0.045051f,1.06532f,0.514221f,0.00274003f, 0.928614f,0.180745f,-0.0432408f,1.06697f,0.520172f,0.00308907f,
0.925491f,0.182416f,-0.0422304f,1.06878f,0.526539f,0.00348273f, 0.92295f,0.183747f,-0.0411429f,1.07135f,0.533357f,0.00392698f,
0.916747f,0.183946f,-0.0387736f,1.07439f,0.540674f,0.00442855f, 0.909883f,0.184667f,-0.0363137f,1.07691f,0.548533f,0.00499522f,
0.902125f,0.185427f,-0.0343108f,1.07748f,0.556989f,0.00563613f, 0.897167f,0.186181f,-0.0308792f,1.08438f,0.566108f,0.0063615f,
0.891942f,0.186251f,-0.0272799f,1.09197f,0.57596f,0.00718342f, 0.89084f,0.192234f,-0.0307326f,1.08279f,0.586629f,0.00811621f,
0.894234f,0.192617f,-0.030323f,1.09036f,0.598216f,0.00917619f, 0.892577f,0.19249f,-0.0287949f,1.09715f,0.610838f,0.0103832f,
0.890628f,0.191264f,-0.0280712f,1.10292f,0.624628f,0.0117604f, 0.891264f,0.188229f,-0.030147f,1.10564f,0.639767f,0.0133358f,
0.889446f,0.188428f,-0.0297238f,1.11284f,0.656455f,0.0151436f, 0.860804f,0.183035f,-0.023725f,1.11577f,0.674953f,0.0172257f,
0.863401f,0.182053f,-0.0236096f,1.13129f,0.695593f,0.0196345f, 0.85974f,0.179971f,-0.0229667f,1.14698f,0.718823f,0.0224372f,
0.854646f,0.177045f,-0.0231225f,1.16474f,0.745227f,0.0257221f, 0.851708f,0.174302f,-0.0240234f,1.18921f,0.775644f,0.0296109f,
0.85857f,0.169925f,-0.0365335f,1.20314f,0.811419f,0.034281f, 0.872394f,0.174852f,-0.0519359f,1.21448f,0.854728f,0.0400192f,
0.857019f,0.178741f,-0.0522426f,1.23325f,0.910311f,0.0473943f, 0.860973f,0.171635f,-0.0678154f,1.31273f,0.994946f,0.0582485f,
1.00362f,0.00491813f,0.00139277f,1.08996f,0.414009f,4.11325e-05f, 1.00375f,0.00923597f,-0.00043545f,1.08972f,0.414046f,4.14258e-05f,
1.01123f,0.0126784f,0.00348287f,1.09063f,0.414157f,4.23057e-05f, 1.01262f,0.0187297f,0.004923f,1.09078f,0.414343f,4.37925e-05f,
1.00552f,0.0293234f,0.0130023f,1.08236f,0.414605f,4.59046e-05f, 1.00464f,0.034979f,0.0113958f,1.08336f,0.414942f,4.8676e-05f,
1.00631f,0.0412795f,0.0101612f,1.0876f,0.415356f,5.21546e-05f, 1.00376f,0.047526f,0.00905897f,1.0864f,0.415846f,5.63856e-05f,
1.00697f,0.05224f,0.00606836f,1.09356f,0.416417f,6.14468e-05f, 1.00516f,0.0578467f,0.00433937f,1.09389f,0.417068f,6.74097e-05f,
1.0032f,0.0632529f,0.00251378f,1.09426f,0.417799f,7.43635e-05f, 1.00106f,0.0684351f,0.000599916f,1.09464f,0.418615f,8.24244e-05f,
0.998771f,0.0733914f,-0.00138545f,1.09504f,0.419516f,9.17109e-05f, 1.00047f,0.0710438f,0.00239292f,1.08498f,0.420506f,0.000102362f,
0.995952f,0.0773959f,-0.000424112f,1.08575f,0.421585f,0.000114538f, 0.988279f,0.0891536f,-0.00418305f,1.08826f,0.422758f,0.000128428f,
0.988635f,0.0876839f,-0.00571313f,1.08762f,0.424028f,0.000144237f, 0.991754f,0.0873067f,-0.0046369f,1.0857f,0.425397f,0.000162199f,
0.987316f,0.0921898f,-0.00757619f,1.08672f,0.426869f,0.000182578f, 0.984439f,0.0958418f,-0.0100474f,1.08794f,0.42845f,0.000205672f,
0.979544f,0.100367f,-0.0136388f,1.08857f,0.430141f,0.00023182f, 0.990434f,0.101333f,-0.0191108f,1.08862f,0.431949f,0.0002614f,
0.97459f,0.106854f,-0.0199298f,1.08743f,0.433879f,0.000294841f, 0.974583f,0.110527f,-0.0254081f,1.08878f,0.435937f,0.000332622f,
0.980621f,0.112508f,-0.0289113f,1.08709f,0.438128f,0.000375284f, 0.981712f,0.115162f,-0.032111f,1.08798f,0.440459f,0.000423434f,
0.978057f,0.116711f,-0.0323595f,1.08731f,0.442937f,0.000477751f, 0.98014f,0.119016f,-0.0334453f,1.0864f,0.445572f,0.000539013f,
0.974827f,0.12229f,-0.0371101f,1.08434f,0.44837f,0.000608092f, 0.96968f,0.124944f,-0.0395301f,1.08279f,0.451342f,0.000685944f,
0.969128f,0.126831f,-0.0417255f,1.0848f,0.454497f,0.000773668f, 0.960306f,0.129027f,-0.0432245f,1.07943f,0.457847f,0.000872525f,
0.958442f,0.130544f,-0.0443497f,1.07946f,0.461404f,0.000983871f, 0.957031f,0.134114f,-0.0433011f,1.07967f,0.465182f,0.00110931f,
0.955804f,0.13728f,-0.0427136f,1.07973f,0.469194f,0.00125061f, 0.954284f,0.139474f,-0.0437322f,1.07967f,0.473458f,0.00140975f,
0.952134f,0.141592f,-0.0442849f,1.08036f,0.47799f,0.00158903f, 0.952146f,0.14419f,-0.0449844f,1.08218f,0.482812f,0.00179102f,
0.95295f,0.147261f,-0.0459701f,1.08366f,0.487945f,0.00201862f, 0.949524f,0.149962f,-0.045084f,1.08483f,0.493412f,0.00227516f,
0.944254f,0.151583f,-0.0440524f,1.08519f,0.49924f,0.00256442f, 0.940734f,0.154273f,-0.0422187f,1.08833f,0.505462f,0.00289065f,
0.935688f,0.155806f,-0.0417846f,1.08767f,0.512107f,0.00325882f, 0.934414f,0.158164f,-0.0410108f,1.09079f,0.519218f,0.00367451f,
0.932973f,0.160254f,-0.0401553f,1.09418f,0.526834f,0.00414423f, 0.929591f,0.163207f,-0.0380439f,1.0988f,0.535004f,0.00467541f,
0.92309f,0.163097f,-0.0355698f,1.10289f,0.543785f,0.00527663f, 0.915728f,0.162304f,-0.0332603f,1.10624f,0.553243f,0.00595794f,
0.908792f,0.159715f,-0.0308132f,1.11139f,0.563448f,0.00673092f, 0.908989f,0.165566f,-0.0330642f,1.10775f,0.574489f,0.0076091f,
0.906812f,0.166023f,-0.0321724f,1.11284f,0.586467f,0.00860888f, 0.905386f,0.164881f,-0.0322596f,1.11748f,0.599496f,0.00974897f,
0.901641f,0.165166f,-0.0301583f,1.126f,0.613728f,0.0110521f, 0.901946f,0.162363f,-0.0323724f,1.12961f,0.629331f,0.0125458f,
0.899999f,0.163505f,-0.0322348f,1.13721f,0.646519f,0.0142636f, 0.890163f,0.162887f,-0.0256235f,1.15726f,0.665556f,0.0162467f,
0.876972f,0.15787f,-0.0266593f,1.15957f,0.686799f,0.0185468f, 0.886305f,0.160669f,-0.0294344f,1.17767f,0.710683f,0.0212311f,
0.871353f,0.153647f,-0.0274339f,1.19598f,0.737825f,0.0243878f, 0.868969f,0.149792f,-0.0317728f,1.21489f,0.769091f,0.0281387f,
0.885568f,0.152398f,-0.0512815f,1.21973f,0.805835f,0.0326635f, 0.877669f,0.150836f,-0.0545055f,1.23417f,0.850386f,0.0382537f,
0.863063f,0.149451f,-0.0561181f,1.2595f,0.907524f,0.0454894f, 0.891193f,0.145509f,-0.0842868f,1.36515f,0.994752f,0.05629f,
1.00358f,0.00495354f,0.00138557f,1.10186f,0.394545f,3.99652e-05f, 1.00466f,0.00816218f,0.00206014f,1.10027f,0.394583f,4.02378e-05f,
1.01131f,0.0110087f,0.00386826f,1.10291f,0.394702f,4.1077e-05f, 1.01261f,0.0158468f,0.00525946f,1.10261f,0.394903f,4.24961e-05f,
1.00562f,0.025657f,0.0140513f,1.09435f,0.395183f,4.45052e-05f, 1.00472f,0.03074f,0.0128415f,1.09502f,0.395546f,4.71469e-05f,
1.00589f,0.0359752f,0.0118298f,1.09883f,0.395989f,5.0457e-05f, 1.00404f,0.0410827f,0.0104953f,1.0986f,0.396517f,5.44856e-05f,
1.00751f,0.0454771f,0.00816447f,1.10573f,0.397128f,5.9292e-05f, 1.00572f,0.0497932f,0.00636136f,1.10624f,0.397827f,6.49579e-05f,
1.00393f,0.0543578f,0.00472104f,1.10672f,0.398611f,7.15627e-05f, 1.00199f,0.058724f,0.00299419f,1.10722f,0.399486f,7.92064e-05f,
0.999918f,0.062878f,0.00118965f,1.10775f,0.40045f,8.80022e-05f, 1.00318f,0.0587089f,0.00582299f,1.09737f,0.401509f,9.80832e-05f,
0.999549f,0.0639434f,0.0033624f,1.09841f,0.402664f,0.000109602f, 0.991316f,0.075515f,-0.000491848f,1.10102f,0.403918f,0.000122727f,
0.99235f,0.0731334f,-0.001655f,1.10047f,0.405274f,0.00013765f, 0.996153f,0.0718357f,-0.00012509f,1.09856f,0.406736f,0.000154589f,
0.992183f,0.0760021f,-0.00281891f,1.09973f,0.408305f,0.000173789f, 0.988242f,0.0797454f,-0.00553142f,1.1009f,0.409989f,0.000195529f,
0.98738f,0.0819347f,-0.00762903f,1.10034f,0.411791f,0.000220121f, 0.982778f,0.0866882f,-0.0131778f,1.10254f,0.413713f,0.000247918f,
0.978395f,0.0901176f,-0.0169033f,1.10314f,0.415764f,0.000279318f, 0.978444f,0.0922341f,-0.0202968f,1.10372f,0.417949f,0.00031477f,
0.984634f,0.0936662f,-0.0229927f,1.10184f,0.420273f,0.000354769f, 0.985083f,0.0960559f,-0.0264519f,1.10264f,0.422743f,0.000399878f,
0.983808f,0.097211f,-0.0274561f,1.10287f,0.425366f,0.000450738f, 0.986059f,0.0985566f,-0.0283218f,1.10191f,0.42815f,0.000508078f,
0.982695f,0.100832f,-0.0314454f,1.10238f,0.431105f,0.000572672f, 0.977532f,0.103149f,-0.0339567f,1.10092f,0.434239f,0.000645464f,
0.974692f,0.105093f,-0.0360076f,1.10113f,0.437564f,0.000727444f, 0.967755f,0.106673f,-0.0378907f,1.09743f,0.441089f,0.000819793f,
0.966068f,0.107754f,-0.0392241f,1.09787f,0.444829f,0.000923792f, 0.964855f,0.111368f,-0.038237f,1.09839f,0.448795f,0.00104092f,
0.963905f,0.113745f,-0.0383923f,1.09862f,0.453004f,0.00117284f, 0.962538f,0.11581f,-0.0395522f,1.09897f,0.457471f,0.00132144f,
0.963202f,0.118145f,-0.0409013f,1.10094f,0.462214f,0.00148883f, 0.964301f,0.120567f,-0.0420108f,1.10345f,0.467252f,0.00167744f,
0.963741f,0.122503f,-0.0424756f,1.10571f,0.472611f,0.00189001f, 0.962212f,0.125225f,-0.0423263f,1.10767f,0.478312f,0.0021297f,
0.958583f,0.12732f,-0.0421824f,1.10802f,0.484382f,0.00240004f, 0.952538f,0.127832f,-0.0417933f,1.1074f,0.490854f,0.00270509f,
0.949601f,0.130193f,-0.0403201f,1.11117f,0.497762f,0.00304955f, 0.946154f,0.132293f,-0.0385974f,1.11558f,0.505141f,0.00343876f,
0.939014f,0.130941f,-0.0391969f,1.11233f,0.51304f,0.00387886f, 0.937642f,0.131846f,-0.0389319f,1.11573f,0.521506f,0.00437699f,
0.936409f,0.13505f,-0.0377903f,1.12076f,0.530596f,0.00494136f, 0.934191f,0.136612f,-0.0351433f,1.12972f,0.540374f,0.00558162f,
0.933406f,0.139828f,-0.0356738f,1.1315f,0.550917f,0.00630891f, 0.924592f,0.13665f,-0.036708f,1.12767f,0.562315f,0.00713643f,
0.92164f,0.137467f,-0.0361853f,1.13227f,0.574664f,0.00807972f, 0.918087f,0.137409f,-0.0353507f,1.13828f,0.588098f,0.00915726f,
0.914953f,0.137392f,-0.0343559f,1.14613f,0.602754f,0.0103912f, 0.91176f,0.137065f,-0.0334927f,1.15506f,0.618813f,0.0118085f,
0.908504f,0.136288f,-0.0329937f,1.16493f,0.636492f,0.0134417f, 0.905849f,0.135606f,-0.0323594f,1.17791f,0.656072f,0.0153318f,
0.903067f,0.134255f,-0.0325724f,1.19185f,0.677894f,0.0175298f, 0.898017f,0.130827f,-0.0355578f,1.2015f,0.702433f,0.0201026f,
0.894349f,0.127819f,-0.0401376f,1.21347f,0.730321f,0.0231382f, 0.894193f,0.127062f,-0.048399f,1.22567f,0.762442f,0.0267591f,
0.905125f,0.130809f,-0.0549883f,1.25741f,0.800203f,0.0311466f, 0.927636f,0.125509f,-0.0690565f,1.31003f,0.84595f,0.0365974f,
0.919611f,0.125878f,-0.0787384f,1.33387f,0.904712f,0.0437056f, 0.915182f,0.119172f,-0.10377f,1.39258f,0.994552f,0.0544597f,
1.00355f,0.0049973f,0.00138443f,1.11299f,0.375695f,3.87386e-05f, 1.00818f,0.00704379f,0.00347579f,1.11359f,0.375738f,3.90032e-05f,
1.01094f,0.00943771f,0.00405673f,1.11415f,0.375866f,3.98054e-05f, 1.01263f,0.0130952f,0.00594733f,1.11375f,0.376078f,4.1153e-05f,
1.00578f,0.0221111f,0.0151459f,1.10554f,0.376376f,4.30665e-05f, 1.00506f,0.0266053f,0.0142386f,1.10614f,0.376759f,4.55753e-05f,
1.00468f,0.030429f,0.0129651f,1.1083f,0.377231f,4.87231e-05f, 1.00432f,0.0345608f,0.0119412f,1.11001f,0.37779f,5.25504e-05f,
1.00701f,0.0385408f,0.0102457f,1.116f,0.378438f,5.71162e-05f, 1.00627f,0.0419548f,0.0084737f,1.11781f,0.379177f,6.24875e-05f,
1.00464f,0.0457031f,0.00702428f,1.11839f,0.380008f,6.87451e-05f, 1.00288f,0.049268f,0.00548532f,1.11901f,0.380933f,7.59838e-05f,
1.00101f,0.0526373f,0.00386537f,1.11968f,0.381955f,8.43098e-05f, 1.00588f,0.0465794f,0.00942437f,1.10892f,0.383075f,9.38438e-05f,
1.00255f,0.0510764f,0.00718167f,1.1101f,0.384297f,0.000104726f, 0.994598f,0.0619622f,0.00347176f,1.11296f,0.385621f,0.000117113f,
0.99582f,0.0590843f,0.00253388f,1.11255f,0.387054f,0.000131185f, 0.993063f,0.0619254f,0.000421892f,1.11358f,0.388597f,0.000147144f,
0.996831f,0.0601607f,0.00209131f,1.11194f,0.390253f,0.000165222f, 0.993261f,0.0634241f,-0.00058403f,1.11324f,0.392029f,0.000185674f,
0.989694f,0.066675f,-0.00409797f,1.11427f,0.393927f,0.000208789f, 0.988193f,0.0672419f,-0.00431182f,1.1153f,0.395951f,0.000234893f,
0.982968f,0.0721786f,-0.0110476f,1.11626f,0.398109f,0.000264356f, 0.982179f,0.0736786f,-0.0139294f,1.1173f,0.400406f,0.000297604f,
0.989037f,0.0751755f,-0.0175086f,1.11601f,0.402848f,0.000335087f, 0.989522f,0.076945f,-0.0206695f,1.11701f,0.405441f,0.000377333f,
0.989416f,0.0781083f,-0.0226475f,1.11774f,0.408193f,0.000424953f, 0.986409f,0.0772897f,-0.0210758f,1.11745f,0.411112f,0.00047858f,
0.988687f,0.0798006f,-0.0253063f,1.11829f,0.414207f,0.000539001f, 0.983182f,0.0818392f,-0.0278699f,1.11665f,0.417487f,0.000607033f,
0.98013f,0.0834377f,-0.0300398f,1.11685f,0.420963f,0.000683642f, 0.974876f,0.0844405f,-0.0322403f,1.11477f,0.424647f,0.000769916f,
0.973374f,0.0858002f,-0.0332734f,1.11566f,0.42855f,0.000867058f, 0.972506f,0.0882455f,-0.0334904f,1.11624f,0.432687f,0.00097644f,
0.971787f,0.090127f,-0.0340759f,1.11678f,0.437071f,0.00109963f, 0.970534f,0.0921823f,-0.0351938f,1.11763f,0.441721f,0.00123839f,
0.972291f,0.0942735f,-0.0367801f,1.12057f,0.446656f,0.00139472f, 0.972491f,0.0959798f,-0.0376774f,1.12341f,0.451894f,0.0015709f,
0.971871f,0.0973974f,-0.0382287f,1.1262f,0.457457f,0.0017695f, 0.968045f,0.0976067f,-0.0402851f,1.12381f,0.463373f,0.00199352f,
0.967098f,0.0990939f,-0.0405741f,1.12643f,0.469666f,0.00224626f, 0.964868f,0.101311f,-0.0407165f,1.12777f,0.47637f,0.00253165f,
0.962255f,0.103501f,-0.0406363f,1.12929f,0.48352f,0.00285407f, 0.959614f,0.105203f,-0.0394779f,1.13372f,0.491153f,0.00321861f,
0.95533f,0.106068f,-0.0385108f,1.13682f,0.499316f,0.00363119f, 0.951221f,0.106393f,-0.0374826f,1.13958f,0.508058f,0.00409857f,
0.950327f,0.106808f,-0.0371797f,1.14426f,0.517438f,0.00462862f, 0.948283f,0.10709f,-0.0353816f,1.14966f,0.527521f,0.00523064f,
0.945871f,0.107271f,-0.0368888f,1.15473f,0.538385f,0.00591536f, 0.943912f,0.107997f,-0.0368098f,1.1598f,0.550124f,0.0066955f,
0.941921f,0.108656f,-0.03675f,1.16553f,0.562837f,0.00758611f, 0.939922f,0.109253f,-0.0367687f,1.172f,0.576652f,0.00860516f,
0.932496f,0.105755f,-0.0384584f,1.17197f,0.591721f,0.0097743f, 0.930401f,0.106244f,-0.0392674f,1.17901f,0.608228f,0.0111197f,
0.928272f,0.106527f,-0.0399256f,1.18757f,0.62639f,0.0126736f, 0.926764f,0.106082f,-0.0408077f,1.20042f,0.646502f,0.0144762f,
0.919882f,0.101225f,-0.044569f,1.20516f,0.668914f,0.0165783f, 0.919756f,0.102918f,-0.0486326f,1.21668f,0.694103f,0.0190459f,
0.916615f,0.0998991f,-0.0546173f,1.22813f,0.722726f,0.0219672f, 0.921793f,0.100651f,-0.0564954f,1.26369f,0.755705f,0.0254653f,
0.913964f,0.0947715f,-0.0614273f,1.27465f,0.794476f,0.0297235f, 0.932387f,0.097088f,-0.0730366f,1.32732f,0.841482f,0.0350427f,
0.927839f,0.0946887f,-0.0843749f,1.36237f,0.901908f,0.0420336f, 0.940935f,0.0854119f,-0.126429f,1.43154f,0.994349f,0.0527482f,
1.0045f,0.00497066f,0.00155635f,1.12404f,0.357486f,3.74763e-05f, 1.00707f,0.00659254f,0.00101298f,1.12568f,0.357534f,3.77347e-05f,
1.01062f,0.00791961f,0.00429889f,1.1246f,0.357669f,3.84999e-05f, 1.01269f,0.0105207f,0.00676386f,1.12413f,0.357892f,3.97801e-05f,
1.00596f,0.0186507f,0.0162622f,1.11596f,0.358203f,4.15961e-05f, 1.00533f,0.0222903f,0.0155254f,1.11664f,0.358606f,4.39791e-05f,
1.00492f,0.0255109f,0.0146f,1.11833f,0.3591f,4.69639e-05f, 1.00457f,0.0282638f,0.0134397f,1.12067f,0.359686f,5.05942e-05f,
1.00666f,0.0318771f,0.0124222f,1.12562f,0.360367f,5.49235e-05f, 1.00679f,0.0344503f,0.0107317f,1.12853f,0.361141f,6.00133e-05f,
1.00532f,0.0372991f,0.00940953f,1.1293f,0.362013f,6.594e-05f, 1.00373f,0.0400815f,0.00805669f,1.13005f,0.362982f,7.27878e-05f,
1.00205f,0.0426641f,0.00662562f,1.13085f,0.364053f,8.06577e-05f, 1.00857f,0.0346747f,0.013182f,1.11965f,0.365225f,8.96618e-05f,
1.00551f,0.0384546f,0.0111612f,1.12097f,0.366504f,9.99306e-05f, 1.00132f,0.0435089f,0.00871472f,1.12274f,0.36789f,0.000111612f,
0.99942f,0.0449188f,0.00695237f,1.12369f,0.369388f,0.000124875f, 0.996657f,0.0474536f,0.00488478f,1.12507f,0.371002f,0.000139902f,
0.999819f,0.0456579f,0.00628537f,1.12397f,0.372732f,0.000156904f, 0.997822f,0.0476324f,0.00480456f,1.12502f,0.374587f,0.000176122f,
0.994871f,0.0502224f,0.000966337f,1.12595f,0.376569f,0.000197839f, 0.996231f,0.051969f,-0.00306037f,1.12726f,0.378683f,0.000222343f,
0.988637f,0.054773f,-0.00577079f,1.12849f,0.380933f,0.000249976f, 0.986343f,0.0554307f,-0.00758084f,1.12995f,0.383328f,0.000281144f,
0.991407f,0.0559197f,-0.0096726f,1.12888f,0.385873f,0.000316252f, 0.989809f,0.0557345f,-0.0100412f,1.12945f,0.388574f,0.000355821f,
0.994789f,0.0587038f,-0.0168254f,1.13196f,0.391439f,0.000400367f, 0.9924f,0.0581632f,-0.0164904f,1.13198f,0.394476f,0.000450545f,
0.993599f,0.0591056f,-0.0188195f,1.13274f,0.397694f,0.000507037f, 0.988835f,0.0605899f,-0.02162f,1.13191f,0.401102f,0.000570623f,
0.9853f,0.0619148f,-0.0238777f,1.13188f,0.404713f,0.000642209f, 0.981655f,0.0626545f,-0.0260956f,1.13144f,0.408536f,0.000722805f,
0.980301f,0.0637909f,-0.0272291f,1.13278f,0.412584f,0.000813544f, 0.979885f,0.0652077f,-0.0286691f,1.13338f,0.416872f,0.000915708f,
0.979407f,0.0665741f,-0.0296844f,1.13426f,0.421416f,0.00103076f, 0.979327f,0.068562f,-0.0309208f,1.13625f,0.426232f,0.00116036f,
0.980209f,0.0702277f,-0.0322629f,1.13931f,0.431337f,0.00130641f, 0.979902f,0.0712713f,-0.0330758f,1.14255f,0.436755f,0.00147102f,
0.97963f,0.0722277f,-0.0338445f,1.14599f,0.442504f,0.00165663f, 0.975088f,0.0717335f,-0.0367694f,1.14201f,0.448616f,0.00186607f,
0.974036f,0.0723004f,-0.0377074f,1.1445f,0.455113f,0.00210249f, 0.973163f,0.0728195f,-0.0385016f,1.14719f,0.462029f,0.00236954f,
0.978606f,0.0757092f,-0.0362142f,1.16174f,0.469402f,0.00267146f, 0.971125f,0.0753551f,-0.0390195f,1.15369f,0.47727f,0.00301308f,
0.970337f,0.0779169f,-0.0381187f,1.15735f,0.485678f,0.00340003f, 0.969277f,0.0805032f,-0.0363777f,1.16192f,0.494677f,0.00383879f,
0.968478f,0.0808091f,-0.036391f,1.16662f,0.50433f,0.00433688f, 0.964758f,0.0781038f,-0.0323532f,1.1761f,0.514703f,0.00490326f,
0.965515f,0.0811631f,-0.0338155f,1.17876f,0.525872f,0.00554823f, 0.962879f,0.0807104f,-0.0322047f,1.18451f,0.537935f,0.00628413f,
0.959444f,0.0797795f,-0.0309108f,1.18975f,0.550996f,0.00712551f, 0.960858f,0.0803169f,-0.036105f,1.203f,0.565185f,0.0080898f,
0.953041f,0.0770051f,-0.0441028f,1.19541f,0.580653f,0.00919815f, 0.950898f,0.0758776f,-0.0451326f,1.20451f,0.597593f,0.0104762f,
0.949928f,0.0756604f,-0.0464899f,1.21498f,0.61623f,0.0119556f, 0.949507f,0.0735503f,-0.0461043f,1.23469f,0.636861f,0.0136758f,
0.948917f,0.0724741f,-0.0482559f,1.25016f,0.659846f,0.0156874f, 0.946898f,0.0748683f,-0.0573254f,1.2494f,0.685693f,0.0180557f,
0.947322f,0.073412f,-0.0621361f,1.26935f,0.715048f,0.0208689f, 0.949465f,0.0678782f,-0.0641357f,1.30753f,0.748888f,0.0242508f,
0.948861f,0.0663478f,-0.071014f,1.33036f,0.788659f,0.028386f, 0.948815f,0.064423f,-0.081732f,1.35785f,0.836911f,0.0335805f,
0.958062f,0.0638132f,-0.10084f,1.40845f,0.899029f,0.0404605f, 0.963913f,0.0541402f,-0.144537f,1.47391f,0.994141f,0.0511471f,
1.00358f,0.00516474f,0.0013822f,1.13296f,0.339943f,3.62082e-05f, 1.00694f,0.00575198f,0.00319493f,1.13325f,0.339989f,3.64465e-05f,
1.01046f,0.00640271f,0.00519731f,1.13383f,0.340127f,3.71681e-05f, 1.01282f,0.00785183f,0.00748784f,1.13376f,0.340359f,3.83845e-05f,
1.00693f,0.0114917f,0.0103739f,1.1269f,0.340685f,4.01102e-05f, 1.00559f,0.0181348f,0.0169255f,1.12639f,0.341102f,4.23698e-05f,
1.00489f,0.0208478f,0.0162105f,1.1274f,0.341615f,4.51988e-05f, 1.00511f,0.0228951f,0.0153446f,1.13033f,0.342225f,4.86385e-05f,
1.00603f,0.0253101f,0.0146503f,1.13425f,0.34293f,5.27365e-05f, 1.007f,0.0274416f,0.0132521f,1.13799f,0.343735f,5.75537e-05f,
1.00598f,0.0291553f,0.0118636f,1.13947f,0.34464f,6.31582e-05f, 1.00454f,0.0311779f,0.0107061f,1.14034f,0.345646f,6.96293e-05f,
1.00301f,0.0330352f,0.00946301f,1.14128f,0.346758f,7.70599e-05f, 1.0081f,0.0248779f,0.0161941f,1.12888f,0.347974f,8.55547e-05f,
1.00844f,0.0261017f,0.0152834f,1.13105f,0.349301f,9.52396e-05f, 1.00082f,0.035683f,0.0118302f,1.13432f,0.350739f,0.00010625f,
1.00291f,0.031211f,0.0115113f,1.13412f,0.352293f,0.000118732f, 1.00047f,0.0330575f,0.00969996f,1.13562f,0.353965f,0.000132863f,
1.00264f,0.0315363f,0.0106051f,1.13524f,0.355759f,0.000148856f, 1.00069f,0.0332896f,0.00925321f,1.13659f,0.357682f,0.000166912f,
0.999173f,0.0342646f,0.00725601f,1.13761f,0.359734f,0.000187294f, 0.998025f,0.0335355f,0.00654728f,1.13908f,0.361923f,0.000210285f,
0.994057f,0.037713f,-0.000283712f,1.14f,0.364253f,0.000236199f, 0.992005f,0.0379278f,-0.00207794f,1.14174f,0.366732f,0.000265398f,
0.994095f,0.0371574f,-0.00228671f,1.14113f,0.369365f,0.00029829f, 0.993922f,0.0370845f,-0.00398086f,1.14229f,0.372158f,0.000335312f,
0.999632f,0.0360247f,-0.00554869f,1.14539f,0.37512f,0.000377007f, 0.997775f,0.0358813f,-0.00663745f,1.14567f,0.378259f,0.000423938f,
0.998071f,0.0386448f,-0.0121271f,1.14634f,0.381583f,0.000476752f, 0.993924f,0.0395732f,-0.0151719f,1.14625f,0.385104f,0.000536188f,
0.991021f,0.0402892f,-0.0177386f,1.147f,0.38883f,0.000603084f, 0.98807f,0.0406251f,-0.0201139f,1.14741f,0.392775f,0.000678384f,
0.987259f,0.0414749f,-0.022098f,1.14871f,0.396951f,0.000763153f, 0.98724f,0.0423982f,-0.0237136f,1.15006f,0.401374f,0.000858597f,
0.987543f,0.0434587f,-0.0250168f,1.15182f,0.406058f,0.000966077f, 0.988046f,0.044754f,-0.0260751f,1.15454f,0.411018f,0.00108715f,
0.987765f,0.0455239f,-0.0265862f,1.15732f,0.416278f,0.00122362f, 0.987411f,0.0462994f,-0.0270615f,1.16017f,0.421854f,0.00137746f,
0.987321f,0.0468783f,-0.0276011f,1.16359f,0.427774f,0.00155101f, 0.984249f,0.0463453f,-0.0297652f,1.16169f,0.43406f,0.00174685f,
0.983632f,0.0464819f,-0.0305769f,1.1647f,0.440741f,0.00196808f, 0.983135f,0.0465885f,-0.0316443f,1.16771f,0.447852f,0.00221813f,
0.984354f,0.0472902f,-0.0354595f,1.16878f,0.455428f,0.00250098f, 0.983738f,0.0472687f,-0.0361254f,1.17269f,0.463511f,0.00282126f,
0.983213f,0.0475961f,-0.036655f,1.17681f,0.472146f,0.00318432f, 0.982896f,0.0496489f,-0.0363212f,1.18107f,0.481389f,0.00359642f,
0.98107f,0.0497772f,-0.034145f,1.18795f,0.491294f,0.0040647f, 0.982001f,0.0525296f,-0.0304389f,1.19829f,0.501938f,0.00459781f,
0.977423f,0.0507591f,-0.0287543f,1.20352f,0.513396f,0.00520568f, 0.97893f,0.0543006f,-0.0300713f,1.20769f,0.525767f,0.0059002f,
0.976253f,0.0493327f,-0.0286098f,1.21875f,0.539159f,0.00669546f, 0.979162f,0.0528512f,-0.0321885f,1.22261f,0.553705f,0.00760855f,
0.973451f,0.0504642f,-0.0368076f,1.22087f,0.569566f,0.0086599f, 0.973665f,0.0505979f,-0.0381113f,1.23251f,0.586923f,0.00987466f,
0.97187f,0.0493028f,-0.0418869f,1.24154f,0.606026f,0.0112839f, 0.974143f,0.0434994f,-0.0540137f,1.26348f,0.627164f,0.0129266f,
0.972238f,0.0412577f,-0.0584321f,1.27422f,0.65073f,0.0148525f, 0.974413f,0.0400697f,-0.0622884f,1.2965f,0.677206f,0.0171272f,
0.974966f,0.0377132f,-0.0677368f,1.31732f,0.707298f,0.0198382f, 0.975971f,0.0350102f,-0.0741743f,1.34241f,0.742001f,0.02311f,
0.975124f,0.0373737f,-0.0797376f,1.37225f,0.782797f,0.0271286f, 0.973593f,0.0331809f,-0.0919335f,1.40139f,0.83233f,0.0322067f,
0.966868f,0.0285259f,-0.111376f,1.42747f,0.896078f,0.038979f, 0.977922f,0.0281548f,-0.153974f,1.51646f,0.993928f,0.0496483f,
1.00361f,0.00528589f,0.00140363f,1.14186f,0.323064f,3.49186e-05f, 1.00713f,0.00521761f,0.00174676f,1.14414f,0.323111f,3.51452e-05f,
1.01024f,0.0050386f,0.00492618f,1.14339f,0.323253f,3.58281e-05f, 1.0125f,0.00635686f,0.00862547f,1.14293f,0.32349f,3.69769e-05f,
1.00531f,0.010558f,0.0178814f,1.1347f,0.323825f,3.86113e-05f, 1.00586f,0.0141167f,0.0183483f,1.13541f,0.324257f,4.07534e-05f,
1.00298f,0.0206716f,0.0137605f,1.14078f,0.324786f,4.3432e-05f, 1.00549f,0.0176615f,0.0172635f,1.1391f,0.325412f,4.66843e-05f,
1.00589f,0.0190697f,0.01659f,1.14239f,0.326139f,5.05583e-05f, 1.00624f,0.0202887f,0.0158293f,1.14585f,0.326968f,5.51121e-05f,
1.0066f,0.0212794f,0.0143739f,1.14894f,0.3279f,6.04111e-05f, 1.0053f,0.0226094f,0.0134356f,1.14992f,0.328937f,6.65223e-05f,
1.00392f,0.0237414f,0.0123807f,1.151f,0.330081f,7.35309e-05f, 1.00747f,0.0170257f,0.0176331f,1.14092f,0.331333f,8.15399e-05f,
1.00732f,0.0168528f,0.0180072f,1.13967f,0.3327f,9.06715e-05f, 1.00705f,0.0184659f,0.0172973f,1.14266f,0.334179f,0.000101029f,
1.00658f,0.0176154f,0.016374f,1.14364f,0.335779f,0.000112777f, 1.00663f,0.0172611f,0.0161186f,1.14438f,0.3375f,0.00012607f,
1.00524f,0.0179342f,0.015021f,1.14579f,0.339345f,0.000141085f, 1.00395f,0.0182908f,0.0139171f,1.14722f,0.341324f,0.000158047f,
1.00227f,0.0192216f,0.0127118f,1.14887f,0.343435f,0.000177174f, 1.00146f,0.0186481f,0.0117287f,1.15028f,0.345685f,0.00019873f,
0.99923f,0.02092f,0.00553133f,1.15084f,0.348083f,0.000223029f, 0.997299f,0.0208345f,0.00355694f,1.15285f,0.350631f,0.000250377f,
0.998451f,0.0198199f,0.00296308f,1.15322f,0.353337f,0.000281165f, 0.998668f,0.0193492f,0.00109479f,1.15475f,0.356207f,0.000315832f,
1.00424f,0.0153271f,0.00324346f,1.15791f,0.359251f,0.00035484f, 1.00307f,0.0162356f,-0.000194894f,1.1587f,0.362475f,0.000398728f,
1.00212f,0.0180725f,-0.00511502f,1.15959f,0.36589f,0.000448107f, 0.999117f,0.0186406f,-0.00867675f,1.16029f,0.369506f,0.000503667f,
0.99645f,0.0188325f,-0.0114959f,1.16149f,0.373332f,0.000566187f, 0.994238f,0.0188769f,-0.0141529f,1.16258f,0.377381f,0.000636543f,
0.9964f,0.0202275f,-0.0161216f,1.16628f,0.381668f,0.000715731f, 0.996396f,0.0202319f,-0.0177625f,1.16743f,0.386207f,0.000804902f,
0.995574f,0.0198645f,-0.0190354f,1.16846f,0.39101f,0.000905351f, 0.99587f,0.0199619f,-0.0195823f,1.17184f,0.3961f,0.00101848f,
0.996092f,0.0200839f,-0.0201114f,1.17528f,0.401492f,0.00114605f, 0.996272f,0.0202197f,-0.0206243f,1.17883f,0.407212f,0.00128985f,
0.996394f,0.0203701f,-0.0211235f,1.1825f,0.413279f,0.00145217f, 0.9973f,0.0208296f,-0.0210965f,1.18793f,0.419722f,0.00163544f,
0.997129f,0.0209197f,-0.021697f,1.19151f,0.426569f,0.00184252f, 0.996432f,0.0211611f,-0.0234763f,1.1928f,0.433856f,0.00207671f,
0.993213f,0.0201148f,-0.026061f,1.19099f,0.441618f,0.00234182f, 0.99528f,0.0206405f,-0.0307085f,1.19228f,0.449898f,0.00264223f,
0.995077f,0.0201845f,-0.0316964f,1.19692f,0.458743f,0.00298303f, 0.994963f,0.0196917f,-0.0326125f,1.20194f,0.468204f,0.00337027f,
0.994318f,0.0189227f,-0.0330955f,1.20802f,0.47835f,0.00381074f, 1.00265f,0.0233808f,-0.0289694f,1.22755f,0.489244f,0.00431279f,
0.998635f,0.0190554f,-0.0274802f,1.23586f,0.500975f,0.00488598f, 0.99675f,0.0231258f,-0.0277239f,1.23744f,0.513638f,0.00554178f,
0.99098f,0.0233118f,-0.0274012f,1.23927f,0.527348f,0.00629395f, 0.991026f,0.0228655f,-0.0283984f,1.24795f,0.54224f,0.0071589f,
0.99132f,0.0199577f,-0.0319209f,1.25672f,0.558466f,0.00815678f, 0.987006f,0.017531f,-0.0371323f,1.25859f,0.576239f,0.00931205f,
0.987857f,0.016432f,-0.0388683f,1.27135f,0.595792f,0.0106552f, 0.988657f,0.0139251f,-0.0506868f,1.294f,0.617433f,0.0122248f,
0.988681f,0.0115445f,-0.0560207f,1.30944f,0.641558f,0.0140701f, 0.988861f,0.00884653f,-0.0620376f,1.32721f,0.66868f,0.016256f,
0.988752f,0.00719693f,-0.0683266f,1.34817f,0.699499f,0.0188703f, 0.989066f,0.0047672f,-0.0759908f,1.37283f,0.73505f,0.0220376f,
0.986622f,0.00585977f,-0.0837205f,1.39911f,0.776877f,0.0259465f, 0.981288f,0.00388629f,-0.0968474f,1.42221f,0.827646f,0.0309116f,
0.974002f,0.000438646f,-0.118154f,1.44857f,0.893089f,0.037586f, 0.99235f,0.00118281f,-0.164095f,1.56007f,0.993712f,0.0482446f,
1.00365f,0.00542201f,0.00143413f,1.15008f,0.306855f,3.36198e-05f, 1.00692f,0.0045073f,0.00351926f,1.15073f,0.306903f,3.38347e-05f,
1.01004f,0.00369082f,0.00524729f,1.1517f,0.307049f,3.44822e-05f, 1.01316f,0.00326712f,0.0101805f,1.15112f,0.307293f,3.55708e-05f,
1.00655f,0.00902136f,0.020064f,1.14274f,0.307633f,3.71148e-05f, 1.00619f,0.0102012f,0.019668f,1.14376f,0.308071f,3.9134e-05f,
1.00557f,0.0113095f,0.0194357f,1.14483f,0.308612f,4.16669e-05f, 1.00595f,0.0122142f,0.0190535f,1.14768f,0.309257f,4.47539e-05f,
1.0058f,0.0130645f,0.0185772f,1.1499f,0.310002f,4.84203e-05f, 1.00622f,0.0135535f,0.0179935f,1.15343f,0.310846f,5.27121e-05f,
1.00653f,0.0138615f,0.0172882f,1.15698f,0.311798f,5.77068e-05f, 1.00599f,0.0142577f,0.0161672f,1.15881f,0.312862f,6.34842e-05f,
1.00467f,0.0147155f,0.0153246f,1.15992f,0.314027f,7.00812e-05f, 1.00896f,0.00555624f,0.0203564f,1.15034f,0.315311f,7.76399e-05f,
1.00569f,0.00895955f,0.019573f,1.14955f,0.316706f,8.62294e-05f, 1.00701f,0.00716785f,0.0202562f,1.15006f,0.31822f,9.59793e-05f,
1.00943f,0.00493451f,0.0208754f,1.15271f,0.319854f,0.000107024f, 1.00897f,0.0044404f,0.0204484f,1.15396f,0.321614f,0.000119522f,
1.0079f,0.00431948f,0.0195644f,1.15555f,0.323497f,0.0001336f, 1.00696f,0.00381856f,0.0186609f,1.15716f,0.325523f,0.000149549f,
1.00473f,0.0054156f,0.0174196f,1.15933f,0.32768f,0.000167487f, 1.00331f,0.00552607f,0.0163186f,1.16134f,0.329976f,0.000187663f,
1.00296f,0.0050737f,0.0119657f,1.16187f,0.332429f,0.000210451f, 1.00222f,0.00417075f,0.00929242f,1.16331f,0.335035f,0.000236091f,
1.00181f,0.00293452f,0.00804828f,1.16506f,0.337801f,0.000264929f, 1.00242f,0.00148996f,0.00714074f,1.16627f,0.340734f,0.000297365f,
1.00546f,-0.00271588f,0.00930699f,1.16876f,0.343844f,0.000333854f, 1.0082f,-0.00304039f,0.00625427f,1.17109f,0.347139f,0.0003749f,
1.00675f,-0.00178306f,0.00153402f,1.17212f,0.350628f,0.000421071f, 1.00393f,-0.00204922f,-0.00209006f,1.17361f,0.354322f,0.000472998f,
1.0015f,-0.00239245f,-0.00516637f,1.17527f,0.358228f,0.000531385f, 1.00025f,-0.00258066f,-0.00846509f,1.17684f,0.362366f,0.000597138f,
1.00292f,-0.00207815f,-0.0100441f,1.18104f,0.36675f,0.000671218f, 1.0018f,-0.0034831f,-0.0118986f,1.18088f,0.371382f,0.000754486f,
1.00245f,-0.00414821f,-0.0125347f,1.18444f,0.376293f,0.000848403f, 1.00321f,-0.00473399f,-0.0130753f,1.18841f,0.381489f,0.000954111f,
1.00396f,-0.00530189f,-0.0136164f,1.19256f,0.387002f,0.00107344f, 1.00464f,-0.00584894f,-0.0141744f,1.1968f,0.392841f,0.00120789f,
1.00528f,-0.00637732f,-0.0147454f,1.2012f,0.399035f,0.00135963f, 1.00634f,-0.00697022f,-0.0152465f,1.20656f,0.40562f,0.00153124f,
1.00311f,-0.00806044f,-0.0190822f,1.20211f,0.412616f,0.00172517f, 1.00963f,-0.00370472f,-0.0230903f,1.20599f,0.420058f,0.00194455f,
1.0112f,-0.00446374f,-0.0213465f,1.21632f,0.427986f,0.00219308f, 1.0096f,-0.00524719f,-0.02596f,1.21379f,0.436448f,0.00247518f,
1.01156f,-0.00563098f,-0.0274822f,1.22046f,0.445481f,0.0027952f, 1.01098f,-0.00668162f,-0.0288658f,1.22505f,0.45515f,0.00315929f,
1.01601f,-0.00563919f,-0.0304101f,1.23536f,0.465506f,0.00357354f, 1.01765f,-0.00679581f,-0.0295601f,1.24708f,0.476642f,0.00404671f,
1.01019f,-0.0119376f,-0.0268946f,1.25396f,0.488629f,0.00458747f, 1.0187f,-0.0065416f,-0.0343404f,1.25837f,0.501563f,0.00520679f,
1.01718f,-0.00756515f,-0.0324947f,1.2695f,0.51558f,0.00591896f, 1.01392f,-0.00864701f,-0.0315022f,1.27844f,0.530792f,0.00673851f,
1.00781f,-0.00936725f,-0.0360424f,1.27753f,0.547387f,0.00768639f, 1.00422f,-0.0110701f,-0.0309848f,1.2939f,0.565554f,0.00878571f,
1.00149f,-0.0132113f,-0.0359791f,1.30214f,0.585542f,0.0100664f, 1.00405f,-0.0147049f,-0.0392853f,1.32122f,0.607676f,0.0115672f,
1.00427f,-0.0169831f,-0.0449706f,1.33728f,0.632343f,0.0133356f, 1.00403f,-0.0197505f,-0.052365f,1.35484f,0.660095f,0.0154377f,
1.00288f,-0.0230698f,-0.0610545f,1.37254f,0.691648f,0.0179607f, 1.00118f,-0.0268301f,-0.0713203f,1.39208f,0.728045f,0.0210292f,
0.996784f,-0.0245277f,-0.0797963f,1.4153f,0.770889f,0.0248329f, 0.991574f,-0.0238479f,-0.0936499f,1.44135f,0.822965f,0.0296947f,
0.991703f,-0.025592f,-0.11534f,1.48971f,0.89013f,0.0362789f, 0.989549f,-0.0311581f,-0.15395f,1.57805f,0.993491f,0.0469292f,
    };
    *n = 64;
    return data;
}
#endif
#ifndef MF_NO_LTC_TABLE
static const float *mf__ltc_beckmann_data(int *n)
{
    static const float data[64 * 64 * 6] = {
0.999969f,-6.32889e-08f,7.5921e-25f,0.00185046f,1.0f,2.92714e-30f, 0.999531f,0.0224415f,-4.15587e-05f,0.001851f,1.0f,1.06618e-18f,
0.997962f,0.0448381f,-8.30385e-05f,0.00184819f,1.0f,1.05253e-15f, 0.995473f,0.0671529f,-0.000124359f,0.0018435f,1.0f,6.02811e-14f,
0.99194f,0.0893379f,-0.00016545f,0.00183703f,1.0f,1.06789e-12f, 0.98747f,0.11136f,-0.000206221f,0.00182864f,1.0f,9.93451e-12f,
0.981883f,0.133154f,-0.0002466f,0.00181843f,1.0f,6.14748e-11f, 0.975469f,0.154717f,-0.000286521f,0.00180648f,1.0f,2.87083e-10f,
0.967974f,0.175967f,-0.000325883f,0.00179265f,1.0f,1.091e-09f, 0.959558f,0.196886f,-0.000364624f,0.00177705f,1.0f,3.54225e-09f,
0.95024f,0.217439f,-0.000402682f,0.00175978f,1.0f,1.01579e-08f, 0.939994f,0.237576f,-0.000439957f,0.00174073f,1.0f,2.63447e-08f,
0.928771f,0.25724f,-0.000476389f,0.00172001f,1.0f,6.28855e-08f, 0.916632f,0.276399f,-0.00051186f,0.0016975f,1.0f,1.40007e-07f,
0.903684f,0.295042f,-0.000546389f,0.00167353f,1.0f,2.93751e-07f, 0.889885f,0.313113f,-0.000579832f,0.00164792f,1.0f,5.85594e-07f,
0.875161f,0.330537f,-0.000612131f,0.00162073f,1.0f,1.11654e-06f, 0.85973f,0.347348f,-0.000643241f,0.0015921f,1.0f,2.04716e-06f,
0.843423f,0.363435f,-0.000673038f,0.00156192f,1.0f,3.6256e-06f, 0.826333f,0.378783f,-0.000701464f,0.00153028f,1.0f,6.22565e-06f,
0.80858f,0.3934f,-0.000728544f,0.00149742f,1.0f,1.03978e-05f, 0.790102f,0.407209f,-0.000754138f,0.00146324f,1.0f,1.69368e-05f,
0.770943f,0.420182f,-0.000778152f,0.00142774f,1.0f,2.69687e-05f, 0.751194f,0.432316f,-0.000800615f,0.00139115f,1.0f,4.20637e-05f,
0.730819f,0.443542f,-0.000821379f,0.00135338f,1.0f,6.43782e-05f, 0.709874f,0.45384f,-0.000840447f,0.00131459f,1.0f,9.6833e-05f,
0.688388f,0.463173f,-0.000857729f,0.0012748f,1.0f,0.000143336f, 0.666357f,0.47148f,-0.00087316f,0.00123406f,1.0f,0.000209053f,
0.643981f,0.478846f,-0.000886758f,0.00119257f,1.0f,0.000300744f, 0.621133f,0.485125f,-0.000898405f,0.00115028f,1.0f,0.000427164f,
0.59787f,0.490293f,-0.000908f,0.00110723f,1.0f,0.00059955f, 0.574383f,0.494447f,-0.000915658f,0.00106369f,1.0f,0.000832201f,
0.550547f,0.49742f,-0.000921212f,0.0010196f,1.0f,0.00114317f, 0.526519f,0.499285f,-0.000924668f,0.000975104f,1.0f,0.00155506f,
0.502312f,0.49999f,-0.000925971f,0.000930271f,1.0f,0.00209602f, 0.477948f,0.499486f,-0.00092501f,0.000885125f,1.0f,0.00280083f,
0.453589f,0.497869f,-0.000921959f,0.000839961f,1.0f,0.00371219f, 0.429121f,0.494945f,-0.000916615f,0.000794712f,1.0f,0.00488227f,
0.404705f,0.490814f,-0.000908974f,0.000749504f,1.0f,0.0063744f, 0.380439f,0.485516f,-0.000899112f,0.000704523f,1.0f,0.00826511f,
0.35627f,0.478906f,-0.000886901f,0.000659789f,1.0f,0.0106464f, 0.332304f,0.471028f,-0.000872322f,0.000615413f,1.0f,0.0136282f,
0.308626f,0.461909f,-0.00085544f,0.000571566f,1.0f,0.0173418f, 0.285306f,0.451561f,-0.000836233f,0.000528351f,1.0f,0.0219424f,
0.262373f,0.439928f,-0.000814687f,0.00048588f,1.0f,0.0276138f, 0.239894f,0.427011f,-0.000790786f,0.000444263f,1.0f,0.0345719f,
0.217973f,0.412876f,-0.000764601f,0.000403662f,1.0f,0.0430701f, 0.196637f,0.397457f,-0.000736044f,0.000364151f,1.0f,0.0534043f,
0.175978f,0.380796f,-0.000705203f,0.000325897f,1.0f,0.0659188f, 0.15608f,0.362939f,-0.000672124f,0.000289044f,1.0f,0.0810135f,
0.136981f,0.343818f,-0.000636723f,0.00025368f,1.0f,0.0991507f, 0.118799f,0.323553f,-0.000599177f,0.000220002f,1.0f,0.120864f,
0.101585f,0.302105f,-0.000559474f,0.000188128f,1.0f,0.146767f, 0.0854187f,0.279503f,-0.000517606f,0.000158187f,1.0f,0.177563f,
0.0703914f,0.255812f,-0.000473729f,0.000130356f,1.0f,0.214058f, 0.0565662f,0.231003f,-0.000427805f,0.000104758f,1.0f,0.25717f,
0.0440489f,0.205204f,-0.000380014f,8.15747e-05f,1.0f,0.307944f, 0.0329074f,0.17839f,-0.000330368f,6.09436e-05f,1.0f,0.367569f,
0.0232359f,0.150651f,-0.000278996f,4.30324e-05f,1.0f,0.437391f, 0.0151178f,0.12202f,-0.000225975f,2.79986e-05f,1.0f,0.518929f,
0.00864424f,0.0925719f,-0.000171431f,1.60092e-05f,1.0f,0.613899f, 0.00390488f,0.0623663f,-0.00011549f,7.23231e-06f,1.0f,0.724231f,
0.000992577f,0.0314899f,-5.83082e-05f,1.83913e-06f,1.0f,0.852076f, 2.64116e-06f,0.00171878f,-2.3977e-06f,4.97547e-09f,0.914293f,0.907288f,
0.999969f,-6.32889e-08f,7.5921e-25f,0.00185046f,1.0f,2.92714e-30f, 0.999531f,0.0224415f,-4.15587e-05f,0.001851f,1.0f,1.06618e-18f,
0.997962f,0.0448381f,-8.30385e-05f,0.00184819f,1.0f,1.05253e-15f, 0.995473f,0.0671529f,-0.000124359f,0.0018435f,1.0f,6.02811e-14f,
0.99194f,0.0893379f,-0.00016545f,0.00183703f,1.0f,1.06789e-12f, 0.98747f,0.11136f,-0.000206221f,0.00182864f,1.0f,9.93451e-12f,
0.981883f,0.133154f,-0.0002466f,0.00181843f,1.0f,6.14748e-11f, 0.975469f,0.154717f,-0.000286521f,0.00180648f,1.0f,2.87083e-10f,
0.967974f,0.175967f,-0.000325883f,0.00179265f,1.0f,1.091e-09f, 0.959558f,0.196886f,-0.000364624f,0.00177705f,1.0f,3.54225e-09f,
0.95024f,0.217439f,-0.000402682f,0.00175978f,1.0f,1.01579e-08f, 0.939994f,0.237576f,-0.000439957f,0.00174073f,1.0f,2.63447e-08f,
0.928771f,0.25724f,-0.000476389f,0.00172001f,1.0f,6.28855e-08f, 0.916632f,0.276399f,-0.00051186f,0.0016975f,1.0f,1.40007e-07f,
0.903684f,0.295042f,-0.000546389f,0.00167353f,1.0f,2.93751e-07f, 0.889885f,0.313113f,-0.000579832f,0.00164792f,1.0f,5.85594e-07f,
0.875161f,0.330537f,-0.000612131f,0.00162073f,1.0f,1.11654e-06f, 0.85973f,0.347348f,-0.000643241f,0.0015921f,1.0f,2.04716e-06f,
0.843423f,0.363435f,-0.000673038f,0.00156192f,1.0f,3.6256e-06f, 0.826333f,0.378783f,-0.000701464f,0.00153028f,1.0f,6.22565e-06f,
0.80858f,0.3934f,-0.000728544f,0.00149742f,1.0f,1.03978e-05f, 0.790102f,0.407209f,-0.000754138f,0.00146324f,1.0f,1.69368e-05f,
0.770943f,0.420182f,-0.000778152f,0.00142774f,1.0f,2.69687e-05f, 0.751194f,0.432316f,-0.000800615f,0.00139115f,1.0f,4.20637e-05f,
0.730819f,0.443542f,-0.000821379f,0.00135338f,1.0f,6.43782e-05f, 0.709874f,0.45384f,-0.000840447f,0.00131459f,1.0f,9.6833e-05f,
0.688388f,0.463173f,-0.000857729f,0.0012748f,1.0f,0.000143336f, 0.666357f,0.47148f,-0.00087316f,0.00123406f,1.0f,0.000209053f,
0.643981f,0.478846f,-0.000886758f,0.00119257f,1.0f,0.000300744f, 0.621133f,0.485125f,-0.000898405f,0.00115028f,1.0f,0.000427164f,
0.59787f,0.490293f,-0.000908f,0.00110723f,1.0f,0.00059955f, 0.574383f,0.494447f,-0.000915658f,0.00106369f,1.0f,0.000832201f,
0.550547f,0.49742f,-0.000921212f,0.0010196f,1.0f,0.00114317f, 0.526519f,0.499285f,-0.000924668f,0.000975104f,1.0f,0.00155506f,
0.502312f,0.49999f,-0.000925971f,0.000930271f,1.0f,0.00209602f, 0.477948f,0.499486f,-0.00092501f,0.000885125f,1.0f,0.00280083f,
0.453589f,0.497869f,-0.000921959f,0.000839961f,1.0f,0.00371219f, 0.429121f,0.494945f,-0.000916615f,0.000794712f,1.0f,0.00488227f,
0.404705f,0.490814f,-0.000908974f,0.000749504f,1.0f,0.0063744f, 0.380439f,0.485516f,-0.000899112f,0.000704523f,1.0f,0.00826511f,
0.35627f,0.478906f,-0.000886901f,0.000659789f,1.0f,0.0106464f, 0.332304f,0.471028f,-0.000872322f,0.000615413f,1.0f,0.0136282f,
0.308626f,0.461909f,-0.00085544f,0.000571566f,1.0f,0.0173418f, 0.285306f,0.451561f,-0.000836233f,0.000528351f,1.0f,0.0219424f,
0.262373f,0.439928f,-0.000814687f,0.00048588f,1.0f,0.0276138f, 0.239894f,0.427011f,-0.000790786f,0.000444263f,1.0f,0.0345719f,
0.217973f,0.412876f,-0.000764601f,0.000403662f,1.0f,0.0430701f, 0.196637f,0.397457f,-0.000736044f,0.000364151f,1.0f,0.0534043f,
0.175978f,0.380796f,-0.000705203f,0.000325897f,1.0f,0.0659188f, 0.15608f,0.362939f,-0.000672124f,0.000289044f,1.0f,0.0810135f,
0.136981f,0.343818f,-0.000636723f,0.00025368f,1.0f,0.0991507f, 0.118799f,0.323553f,-0.000599177f,0.000220002f,1.0f,0.120864f,
0.101585f,0.302105f,-0.000559474f,0.000188128f,1.0f,0.146767f, 0.0854187f,0.279503f,-0.000517606f,0.000158187f,1.0f,0.177563f,
0.0703914f,0.255812f,-0.000473729f,0.000130356f,1.0f,0.214058f, 0.0565662f,0.231003f,-0.000427805f,0.000104758f,1.0f,0.25717f,
0.0440489f,0.205204f,-0.000380014f,8.15747e-05f,1.0f,0.307944f, 0.0329074f,0.17839f,-0.000330368f,6.09436e-05f,1.0f,0.367569f,
0.0232359f,0.150651f,-0.000278996f,4.30324e-05f,1.0f,0.437391f, 0.0151178f,0.12202f,-0.000225975f,2.79986e-05f,1.0f,0.518929f,
0.00864424f,0.0925719f,-0.000171431f,1.60092e-05f,1.0f,0.613899f, 0.00390488f,0.0623663f,-0.00011549f,7.23231e-06f,1.0f,0.724231f,
0.000992577f,0.0314899f,-5.83082e-05f,1.83913e-06f,1.0f,0.852076f, 2.64116e-06f,0.00171878f,-2.3977e-06f,4.97547e-09f,0.914293f,0.907288f,
0.99998f,2.56205e-08f,-5.1339e-24f,0.00186493f,1.0f,3.16396e-30f, 0.99952f,0.0224413f,-4.18844e-05f,0.0018655f,1.0f,1.06699e-18f,
0.997988f,0.0448392f,-8.36861e-05f,0.0018626f,1.0f,1.05274e-15f, 0.995494f,0.0671543f,-0.00012534f,0.00185803f,1.0f,6.02863e-14f,
0.992004f,0.0893437f,-0.000166743f,0.00185138f,1.0f,1.06795e-12f, 0.987467f,0.111359f,-0.000207832f,0.00184293f,1.0f,9.93481e-12f,
0.981929f,0.133161f,-0.00024853f,0.00183266f,1.0f,6.14761e-11f, 0.975453f,0.154714f,-0.000288761f,0.0018206f,1.0f,2.87087e-10f,
0.968022f,0.175975f,-0.000328433f,0.00180667f,1.0f,1.09101e-09f, 0.959671f,0.19691f,-0.000367488f,0.00179101f,1.0f,3.54228e-09f,
0.950292f,0.217451f,-0.000405826f,0.00177352f,1.0f,1.0158e-08f, 0.939985f,0.237574f,-0.000443403f,0.00175437f,1.0f,2.63449e-08f,
0.92873f,0.257229f,-0.000480089f,0.00173337f,1.0f,6.28858e-08f, 0.916606f,0.276392f,-0.000515857f,0.00171075f,1.0f,1.40008e-07f,
0.903642f,0.295029f,-0.000550642f,0.00168656f,1.0f,2.93752e-07f, 0.889826f,0.313092f,-0.000584355f,0.00166077f,1.0f,5.85596e-07f,
0.875125f,0.330524f,-0.000616879f,0.00163331f,1.0f,1.11654e-06f, 0.85964f,0.347312f,-0.000648215f,0.00160441f,1.0f,2.04717e-06f,
0.843435f,0.36344f,-0.000678296f,0.00157412f,1.0f,3.62561e-06f, 0.826328f,0.378781f,-0.000706961f,0.00154227f,1.0f,6.22566e-06f,
0.808608f,0.393414f,-0.000734241f,0.00150913f,1.0f,1.03978e-05f, 0.790104f,0.40721f,-0.000759997f,0.00147461f,1.0f,1.69368e-05f,
0.770991f,0.420208f,-0.00078425f,0.00143893f,1.0f,2.69687e-05f, 0.751185f,0.432311f,-0.000806846f,0.00140198f,1.0f,4.20638e-05f,
0.730813f,0.443539f,-0.000827798f,0.00136395f,1.0f,6.43782e-05f, 0.709881f,0.453845f,-0.000847009f,0.00132485f,1.0f,9.68331e-05f,
0.688335f,0.463137f,-0.000864404f,0.00128472f,1.0f,0.000143336f, 0.666351f,0.471476f,-0.000879975f,0.0012437f,1.0f,0.000209053f,
0.644011f,0.478869f,-0.000893694f,0.00120189f,1.0f,0.000300744f, 0.62111f,0.485107f,-0.000905418f,0.00115926f,1.0f,0.000427164f,
0.597896f,0.490314f,-0.000915133f,0.00111593f,1.0f,0.00059955f, 0.57436f,0.494427f,-0.000922786f,0.00107197f,1.0f,0.000832201f,
0.550561f,0.497433f,-0.000928419f,0.00102758f,1.0f,0.00114317f, 0.526532f,0.499298f,-0.000931894f,0.000982725f,1.0f,0.00155506f,
0.502339f,0.500017f,-0.000933195f,0.00093753f,1.0f,0.00209603f, 0.477936f,0.499473f,-0.000932254f,0.000892057f,1.0f,0.00280083f,
0.453558f,0.497836f,-0.000929176f,0.000846536f,1.0f,0.00371219f, 0.429145f,0.494974f,-0.000923782f,0.000800925f,1.0f,0.00488227f,
0.404709f,0.490819f,-0.000916043f,0.000755333f,1.0f,0.0063744f, 0.380405f,0.485473f,-0.000906097f,0.000709996f,1.0f,0.00826511f,
0.356238f,0.478862f,-0.000893758f,0.00066489f,1.0f,0.0106464f, 0.33232f,0.47105f,-0.00087916f,0.000620237f,1.0f,0.0136282f,
0.308634f,0.46192f,-0.000862114f,0.000576025f,1.0f,0.0173418f, 0.285321f,0.451585f,-0.000842798f,0.000532499f,1.0f,0.0219424f,
0.262366f,0.439916f,-0.000821033f,0.000489665f,1.0f,0.0276138f, 0.239894f,0.427012f,-0.000796954f,0.000447728f,1.0f,0.0345719f,
0.217958f,0.412848f,-0.000770528f,0.000406791f,1.0f,0.0430701f, 0.196643f,0.397468f,-0.000741825f,0.00036701f,1.0f,0.0534043f,
0.175985f,0.380812f,-0.000710751f,0.000328461f,1.0f,0.0659188f, 0.156071f,0.362919f,-0.000677332f,0.000291284f,1.0f,0.0810135f,
0.136984f,0.343825f,-0.0006417f,0.000255662f,1.0f,0.0991507f, 0.118797f,0.323547f,-0.000603855f,0.000221719f,1.0f,0.120864f,
0.101579f,0.302088f,-0.000563826f,0.000189592f,1.0f,0.146767f, 0.0854166f,0.279496f,-0.000521651f,0.000159423f,1.0f,0.177563f,
0.0703909f,0.255811f,-0.000477429f,0.000131374f,1.0f,0.214058f, 0.056565f,0.230998f,-0.000431143f,0.000105576f,1.0f,0.25717f,
0.0440509f,0.205213f,-0.000382999f,8.22153e-05f,1.0f,0.307944f, 0.0329085f,0.178396f,-0.000332953f,6.14205e-05f,1.0f,0.367569f,
0.0232346f,0.150643f,-0.000281166f,4.33672e-05f,1.0f,0.43739f, 0.0151185f,0.122026f,-0.000227735f,2.82166e-05f,1.0f,0.518928f,
0.00864414f,0.0925709f,-0.000172767f,1.6134e-05f,1.0f,0.613899f, 0.00390478f,0.0623646f,-0.000116395f,7.28897e-06f,1.0f,0.72423f,
0.000992546f,0.0314887f,-5.87609e-05f,1.85343e-06f,1.0f,0.852075f, 2.64765e-06f,0.00171703f,-2.42171e-06f,5.05626e-09f,0.914253f,0.90722f,
0.999972f,1.23588e-07f,7.77492e-24f,0.00419607f,1.0f,1.05202e-26f, 0.999426f,0.0224392f,-9.42336e-05f,0.0041971f,1.0f,1.29397e-18f,
0.998041f,0.0448416f,-0.000188299f,0.00419097f,1.0f,1.10689e-15f, 0.995513f,0.0671557f,-0.000282004f,0.00418041f,1.0f,6.16543e-14f,
0.991937f,0.0893376f,-0.000375156f,0.00416545f,1.0f,1.08152e-12f, 0.987413f,0.111353f,-0.000467614f,0.00414652f,1.0f,1.00154e-11f,
0.982006f,0.133171f,-0.000559214f,0.00412365f,1.0f,6.18212e-11f, 0.975513f,0.154723f,-0.000649727f,0.00409646f,1.0f,2.88267e-10f,
0.968049f,0.17598f,-0.000738998f,0.00406515f,1.0f,1.09443e-09f, 0.959619f,0.196899f,-0.000826804f,0.00402956f,1.0f,3.55101e-09f,
0.950265f,0.217445f,-0.000913125f,0.00399049f,1.0f,1.01781e-08f, 0.939951f,0.237565f,-0.000997647f,0.00394729f,1.0f,2.63879e-08f,
0.928754f,0.257235f,-0.00108022f,0.00390016f,1.0f,6.29715e-08f, 0.916649f,0.276405f,-0.00116077f,0.00384948f,1.0f,1.40169e-07f,
0.903697f,0.295047f,-0.00123898f,0.00379488f,1.0f,2.94042e-07f, 0.8898f,0.313083f,-0.00131476f,0.00373664f,1.0f,5.86096e-07f,
0.875178f,0.330543f,-0.00138809f,0.00367524f,1.0f,1.11737e-06f, 0.859703f,0.347338f,-0.00145859f,0.0036102f,1.0f,2.0485e-06f,
0.843405f,0.363427f,-0.00152618f,0.00354181f,1.0f,3.6277e-06f, 0.826383f,0.378806f,-0.00159069f,0.00347016f,1.0f,6.22884e-06f,
0.808628f,0.393423f,-0.00165209f,0.00339564f,1.0f,1.04026e-05f, 0.790074f,0.407195f,-0.00170999f,0.00331787f,1.0f,1.69437e-05f,
0.770987f,0.420205f,-0.00176461f,0.00323769f,1.0f,2.69787e-05f, 0.751249f,0.432347f,-0.00181547f,0.00315457f,1.0f,4.20778e-05f,
0.730856f,0.443565f,-0.00186265f,0.00306907f,1.0f,6.43976e-05f, 0.709905f,0.45386f,-0.0019058f,0.00298096f,1.0f,9.68595e-05f,
0.688379f,0.463166f,-0.00194503f,0.0028908f,1.0f,0.000143371f, 0.666373f,0.471491f,-0.00197997f,0.00279836f,1.0f,0.0002091f,
0.643987f,0.47885f,-0.00201081f,0.00270427f,1.0f,0.000300806f, 0.621151f,0.485138f,-0.00203726f,0.00260842f,1.0f,0.000427244f,
0.597869f,0.490292f,-0.00205892f,0.00251069f,1.0f,0.000599653f, 0.574371f,0.494436f,-0.00207634f,0.00241202f,1.0f,0.000832332f,
0.550585f,0.497454f,-0.00208895f,0.00231206f,1.0f,0.00114333f, 0.526554f,0.499318f,-0.00209683f,0.00221121f,1.0f,0.00155527f,
0.502298f,0.499976f,-0.00209957f,0.00210933f,1.0f,0.00209628f, 0.47799f,0.499529f,-0.00209772f,0.00200728f,1.0f,0.00280114f,
0.453553f,0.497829f,-0.0020906f,0.00190468f,1.0f,0.00371256f, 0.429143f,0.494971f,-0.00207847f,0.00180205f,1.0f,0.00488272f,
0.404744f,0.49086f,-0.00206123f,0.00169962f,1.0f,0.00637494f, 0.380396f,0.485461f,-0.00203867f,0.00159746f,1.0f,0.00826574f,
0.356258f,0.478888f,-0.00201103f,0.00149607f,1.0f,0.0106471f, 0.332319f,0.471047f,-0.00197804f,0.00139549f,1.0f,0.0136291f,
0.308636f,0.461922f,-0.00193976f,0.00129607f,1.0f,0.0173427f, 0.28531f,0.451566f,-0.00189629f,0.00119813f,1.0f,0.0219435f,
0.262384f,0.439944f,-0.00184745f,0.00110183f,1.0f,0.027615f, 0.239904f,0.427027f,-0.00179325f,0.00100746f,1.0f,0.0345733f,
0.21796f,0.412851f,-0.00173372f,0.000915308f,1.0f,0.0430716f, 0.196639f,0.397458f,-0.00166908f,0.000825775f,1.0f,0.0534058f,
0.175984f,0.380807f,-0.00159915f,0.000739032f,1.0f,0.0659203f, 0.156088f,0.362955f,-0.0015241f,0.00065545f,1.0f,0.0810149f,
0.136983f,0.343819f,-0.00144386f,0.000575269f,1.0f,0.099152f, 0.118794f,0.323536f,-0.00135867f,0.000498881f,1.0f,0.120865f,
0.101588f,0.30211f,-0.00126864f,0.000426609f,1.0f,0.146767f, 0.0854276f,0.279527f,-0.00117378f,0.000358737f,1.0f,0.177562f,
0.0703926f,0.255812f,-0.00107422f,0.000295611f,1.0f,0.214056f, 0.0565711f,0.231018f,-0.000970111f,0.000237572f,1.0f,0.257165f,
0.04405f,0.205203f,-0.000861729f,0.000184997f,1.0f,0.307936f, 0.0329125f,0.178411f,-0.000749178f,0.000138219f,1.0f,0.367556f,
0.0232374f,0.150652f,-0.000632641f,9.75956e-05f,1.0f,0.437369f, 0.0151209f,0.122034f,-0.000512428f,6.35075e-05f,1.0f,0.518894f,
0.00864614f,0.0925772f,-0.000388746f,3.63205e-05f,1.0f,0.61384f, 0.00390742f,0.0623845f,-0.000261926f,1.64198e-05f,1.0f,0.724121f,
0.000995283f,0.0315311f,-0.000132308f,4.19059e-06f,1.0f,0.851806f, 8.71269e-06f,0.00301574f,-8.4854e-06f,3.59973e-08f,0.935095f,0.922916f,
0.99998f,-1.82125e-07f,2.01413e-23f,0.00745972f,1.0f,3.31673e-24f, 0.999524f,0.0224414f,-0.00016753f,0.00746167f,1.0f,2.05268e-18f,
0.997956f,0.0448379f,-0.000334735f,0.0074502f,1.0f,1.2613e-15f, 0.995555f,0.0671587f,-0.000501358f,0.00743212f,1.0f,6.54336e-14f,
0.991927f,0.0893368f,-0.000666947f,0.00740527f,1.0f,1.11861e-12f, 0.987373f,0.111349f,-0.000831295f,0.00737143f,1.0f,1.02343e-11f,
0.981922f,0.13316f,-0.000994136f,0.00733078f,1.0f,6.27562e-11f, 0.975464f,0.154716f,-0.00115504f,0.00728242f,1.0f,2.91457e-10f,
0.968026f,0.175976f,-0.00131377f,0.0072269f,1.0f,1.10366e-09f, 0.959537f,0.196882f,-0.00146987f,0.00716363f,1.0f,3.57458e-09f,
0.950318f,0.217457f,-0.00162338f,0.00709442f,1.0f,1.02326e-08f, 0.939974f,0.237571f,-0.00177357f,0.0070173f,1.0f,2.65038e-08f,
0.928771f,0.25724f,-0.0019204f,0.00693367f,1.0f,6.32026e-08f, 0.916641f,0.276402f,-0.00206356f,0.00684347f,1.0f,1.40604e-07f,
0.903599f,0.295015f,-0.00220249f,0.006746f,1.0f,2.94824e-07f, 0.889844f,0.313098f,-0.00233736f,0.00664294f,1.0f,5.87443e-07f,
0.875142f,0.33053f,-0.00246767f,0.00653364f,1.0f,1.11961e-06f, 0.859602f,0.347297f,-0.00259286f,0.00641767f,1.0f,2.0521e-06f,
0.843411f,0.363429f,-0.0027131f,0.00629632f,1.0f,3.63333e-06f, 0.826374f,0.378802f,-0.00282792f,0.00616926f,1.0f,6.23743e-06f,
0.808561f,0.39339f,-0.00293693f,0.00603647f,1.0f,1.04154e-05f, 0.790153f,0.407235f,-0.00304017f,0.00589881f,1.0f,1.69624e-05f,
0.771014f,0.420219f,-0.00313714f,0.00575601f,1.0f,2.70054e-05f, 0.751202f,0.43232f,-0.00322757f,0.00560826f,1.0f,4.21154e-05f,
0.730789f,0.443524f,-0.00331113f,0.00545574f,1.0f,6.44497e-05f, 0.709843f,0.453819f,-0.00338808f,0.0052995f,1.0f,9.69305e-05f,
0.688372f,0.463161f,-0.00345767f,0.00513899f,1.0f,0.000143467f, 0.666355f,0.471477f,-0.00351992f,0.00497485f,1.0f,0.000209227f,
0.643969f,0.478836f,-0.00357464f,0.00480743f,1.0f,0.000300973f, 0.621118f,0.485112f,-0.00362166f,0.00463706f,1.0f,0.000427461f,
0.597892f,0.490309f,-0.00366048f,0.00446369f,1.0f,0.000599931f, 0.57435f,0.494417f,-0.00369107f,0.00428784f,1.0f,0.000832684f,
0.550583f,0.497451f,-0.00371361f,0.0041103f,1.0f,0.00114377f, 0.526533f,0.499297f,-0.0037274f,0.00393077f,1.0f,0.00155582f,
0.502306f,0.499981f,-0.00373269f,0.00375008f,1.0f,0.00209696f, 0.478022f,0.49956f,-0.00372925f,0.00356852f,1.0f,0.00280197f,
0.453564f,0.497838f,-0.00371667f,0.00338618f,1.0f,0.00371357f, 0.429144f,0.494968f,-0.00369506f,0.00320371f,1.0f,0.00488392f,
0.40475f,0.490865f,-0.00366444f,0.00302162f,1.0f,0.00637637f, 0.380435f,0.485507f,-0.00362453f,0.00284017f,1.0f,0.00826743f,
0.35627f,0.478902f,-0.00357524f,0.00265979f,1.0f,0.0106491f, 0.332314f,0.471037f,-0.00351655f,0.00248096f,1.0f,0.0136314f,
0.308666f,0.461963f,-0.00344858f,0.00230426f,1.0f,0.0173453f, 0.285303f,0.45155f,-0.00337106f,0.00213f,1.0f,0.0219464f,
0.262383f,0.439939f,-0.0032842f,0.00195878f,1.0f,0.0276183f, 0.239922f,0.427054f,-0.00318798f,0.00179109f,1.0f,0.0345768f,
0.217958f,0.412841f,-0.00308217f,0.00162728f,1.0f,0.0430754f, 0.196657f,0.397488f,-0.00296727f,0.00146812f,1.0f,0.0534098f,
0.175993f,0.380819f,-0.00284297f,0.00131392f,1.0f,0.0659243f, 0.156075f,0.362918f,-0.00270935f,0.00116524f,1.0f,0.0810187f,
0.137002f,0.343859f,-0.00256695f,0.00102281f,1.0f,0.0991553f, 0.118813f,0.323579f,-0.00241555f,0.000887024f,1.0f,0.120867f,
0.101597f,0.302126f,-0.00225536f,0.000758489f,1.0f,0.146768f, 0.0854327f,0.279533f,-0.0020867f,0.000637824f,1.0f,0.177561f,
0.0704009f,0.25583f,-0.00190975f,0.000525613f,1.0f,0.21405f, 0.0565782f,0.231033f,-0.00172472f,0.000422448f,1.0f,0.257153f,
0.0440569f,0.205218f,-0.00153199f,0.000328968f,1.0f,0.307915f, 0.0329174f,0.178418f,-0.00133187f,0.000245802f,1.0f,0.367521f,
0.0232456f,0.150682f,-0.00112482f,0.000173604f,1.0f,0.437313f, 0.0151275f,0.122057f,-0.00091109f,0.000112997f,1.0f,0.518801f,
0.00865433f,0.0926247f,-0.0006913f,6.46704e-05f,1.0f,0.613682f, 0.00391485f,0.0624431f,-0.000465885f,2.92884e-05f,1.0f,0.723825f,
0.00100249f,0.0316396f,-0.000235662f,7.54719e-06f,1.0f,0.851081f, 2.24449e-05f,0.00464971f,-2.2733e-05f,1.66837e-07f,0.957017f,0.937267f,
0.999998f,3.17615e-07f,-2.04876e-22f,0.0116557f,1.0f,2.87557e-22f, 0.9995f,0.0224408f,-0.000261776f,0.0116593f,1.0f,4.50646e-18f,
0.997927f,0.0448365f,-0.00052303f,0.0116411f,1.0f,1.63026e-15f, 0.995498f,0.0671544f,-0.000783349f,0.0116123f,1.0f,7.38728e-14f,
0.991924f,0.0893363f,-0.00104212f,0.0115709f,1.0f,1.19941e-12f, 0.987422f,0.111355f,-0.00129896f,0.0115184f,1.0f,1.07057e-11f,
0.982013f,0.133172f,-0.00155335f,0.0114545f,1.0f,6.47564e-11f, 0.975518f,0.154724f,-0.00180478f,0.0113789f,1.0f,2.98257e-10f,
0.968006f,0.175972f,-0.00205271f,0.0112917f,1.0f,1.1233e-09f, 0.959568f,0.196888f,-0.00229671f,0.0111934f,1.0f,3.62458e-09f,
0.950189f,0.217427f,-0.00253635f,0.0110842f,1.0f,1.03479e-08f, 0.940017f,0.237582f,-0.00277132f,0.010965f,1.0f,2.67494e-08f,
0.928818f,0.257253f,-0.00300076f,0.0108344f,1.0f,6.36917e-08f, 0.916713f,0.276424f,-0.00322439f,0.0106932f,1.0f,1.41525e-07f,
0.903691f,0.295045f,-0.00344164f,0.0105414f,1.0f,2.96476e-07f, 0.889881f,0.313111f,-0.00365222f,0.0103799f,1.0f,5.90288e-07f,
0.875187f,0.330546f,-0.0038557f,0.0102088f,1.0f,1.12433e-06f, 0.859653f,0.347317f,-0.00405139f,0.0100277f,1.0f,2.05971e-06f,
0.843422f,0.363434f,-0.0042393f,0.00983822f,1.0f,3.64522e-06f, 0.826334f,0.378783f,-0.00441859f,0.00963943f,1.0f,6.25555e-06f,
0.808567f,0.393393f,-0.00458891f,0.00943196f,1.0f,1.04424e-05f, 0.790124f,0.407219f,-0.00475009f,0.00921662f,1.0f,1.70018e-05f,
0.771012f,0.420217f,-0.0049016f,0.00899349f,1.0f,2.70618e-05f, 0.751256f,0.43235f,-0.00504301f,0.00876288f,1.0f,4.21947e-05f,
0.730816f,0.443538f,-0.0051739f,0.00852509f,1.0f,6.45596e-05f, 0.709853f,0.453824f,-0.00529375f,0.00828035f,1.0f,9.70805e-05f,
0.688388f,0.46317f,-0.00540284f,0.00803009f,1.0f,0.000143669f, 0.666419f,0.471521f,-0.00550002f,0.0077735f,1.0f,0.000209495f,
0.643936f,0.47881f,-0.00558533f,0.00751165f,1.0f,0.000301324f, 0.621103f,0.485097f,-0.00565857f,0.00724517f,1.0f,0.000427917f,
0.597922f,0.490331f,-0.00571966f,0.00697482f,1.0f,0.000600516f, 0.574362f,0.494424f,-0.00576733f,0.00669992f,1.0f,0.000833427f,
0.550623f,0.497483f,-0.00580263f,0.00642259f,1.0f,0.00114471f, 0.526536f,0.499296f,-0.00582416f,0.00614205f,1.0f,0.00155698f,
0.502345f,0.500017f,-0.00583238f,0.00585969f,1.0f,0.00209839f, 0.477976f,0.499507f,-0.00582654f,0.00557554f,1.0f,0.00280372f,
0.453572f,0.497843f,-0.00580731f,0.00529106f,1.0f,0.00371569f, 0.429148f,0.494968f,-0.00577341f,0.00500585f,1.0f,0.00488647f,
0.404748f,0.490856f,-0.00572564f,0.00472141f,1.0f,0.0063794f, 0.380443f,0.485511f,-0.00566332f,0.00443792f,1.0f,0.008271f,
0.356299f,0.478933f,-0.00558634f,0.00415611f,1.0f,0.0106532f, 0.33235f,0.47108f,-0.00549464f,0.00387671f,1.0f,0.0136362f,
0.308641f,0.461918f,-0.00538825f,0.0036005f,1.0f,0.0173508f, 0.285316f,0.451562f,-0.00526726f,0.0033283f,1.0f,0.0219526f,
0.262369f,0.439905f,-0.00513132f,0.00306065f,1.0f,0.0276252f, 0.239929f,0.427055f,-0.00498131f,0.00279884f,1.0f,0.0345844f,
0.217997f,0.412903f,-0.0048162f,0.00254301f,1.0f,0.0430835f, 0.196648f,0.397456f,-0.00463614f,0.00229405f,1.0f,0.0534182f,
0.176011f,0.380844f,-0.00444221f,0.00205326f,1.0f,0.0659328f, 0.156106f,0.362974f,-0.00423361f,0.00182103f,1.0f,0.0810268f,
0.137015f,0.343874f,-0.00401088f,0.00159838f,1.0f,0.0991623f, 0.118825f,0.32359f,-0.0037744f,0.00138626f,1.0f,0.120872f,
0.101609f,0.30214f,-0.00352415f,0.00118543f,1.0f,0.146769f, 0.0854473f,0.279557f,-0.00326061f,0.000996896f,1.0f,0.177557f,
0.0704151f,0.255854f,-0.00298412f,0.000821562f,1.0f,0.214037f, 0.0565911f,0.231054f,-0.00269493f,0.000660344f,1.0f,0.257128f,
0.0440772f,0.205277f,-0.00239408f,0.000514349f,1.0f,0.307871f, 0.0329328f,0.178459f,-0.00208127f,0.000384372f,1.0f,0.367448f,
0.0232613f,0.150733f,-0.0017578f,0.000271565f,1.0f,0.437193f, 0.0151434f,0.122122f,-0.00142391f,0.000176869f,1.0f,0.518605f,
0.0086686f,0.0926931f,-0.00108058f,0.000101358f,1.0f,0.61335f, 0.00392987f,0.0625554f,-0.000728662f,4.60808e-05f,1.0f,0.723202f,
0.00101765f,0.0318658f,-0.000369651f,1.21135e-05f,0.999946f,0.849505f, 4.94451e-05f,0.00674588f,-5.07807e-05f,5.75963e-07f,0.970575f,0.94108f,
1.00001f,1.59762e-07f,-3.50148e-22f,0.0167843f,1.0f,1.10157e-20f, 0.999445f,0.02244f,-0.000376945f,0.0167889f,1.0f,1.31052e-17f,
0.998009f,0.0448402f,-0.000753179f,0.0167635f,1.0f,2.46763e-15f, 0.995494f,0.0671543f,-0.00112803f,0.0167219f,1.0f,9.09298e-14f,
0.991979f,0.0893418f,-0.00150074f,0.0166631f,1.0f,1.35555e-12f, 0.987394f,0.111351f,-0.00187048f,0.0165863f,1.0f,1.15973e-11f,
0.982007f,0.133171f,-0.00223694f,0.0164952f,1.0f,6.84946e-11f, 0.97552f,0.154725f,-0.00259892f,0.0163859f,1.0f,3.10872e-10f,
0.967986f,0.175969f,-0.00295592f,0.0162602f,1.0f,1.15954e-09f, 0.959565f,0.196887f,-0.00330736f,0.016119f,1.0f,3.71662e-09f,
0.950273f,0.217446f,-0.00365259f,0.0159625f,1.0f,1.05597e-08f, 0.939996f,0.237576f,-0.00399057f,0.0157892f,1.0f,2.71995e-08f,
0.92872f,0.257225f,-0.00432078f,0.0156004f,1.0f,6.45868e-08f, 0.916682f,0.276414f,-0.0046431f,0.0153982f,1.0f,1.43209e-07f,
0.9037f,0.295047f,-0.004956f,0.0151798f,1.0f,2.99495e-07f, 0.889784f,0.313076f,-0.00525917f,0.014947f,1.0f,5.95483e-07f,
0.875201f,0.330551f,-0.00555237f,0.0147011f,1.0f,1.13296e-06f, 0.859629f,0.347306f,-0.00583404f,0.0144402f,1.0f,2.07357e-06f,
0.843425f,0.363435f,-0.00610475f,0.0141675f,1.0f,3.66689e-06f, 0.826402f,0.378813f,-0.00636308f,0.0138816f,1.0f,6.28857e-06f,
0.808648f,0.393431f,-0.00660841f,0.0135829f,1.0f,1.04916e-05f, 0.790154f,0.407233f,-0.00684022f,0.0132723f,1.0f,1.70736e-05f,
0.771039f,0.420231f,-0.00705855f,0.0129512f,1.0f,2.71645e-05f, 0.751216f,0.432325f,-0.00726193f,0.0126187f,1.0f,4.23393e-05f,
0.730843f,0.443552f,-0.00745037f,0.0122763f,1.0f,6.47597e-05f, 0.709893f,0.453847f,-0.00762338f,0.0119245f,1.0f,9.73535e-05f,
0.688416f,0.463185f,-0.00778002f,0.0115635f,1.0f,0.000144036f, 0.666412f,0.471513f,-0.00791991f,0.0111939f,1.0f,0.000209983f,
0.643978f,0.478837f,-0.00804317f,0.0108174f,1.0f,0.000301964f, 0.621159f,0.485137f,-0.0081487f,0.0104338f,1.0f,0.000428747f,
0.597938f,0.490339f,-0.00823627f,0.010044f,1.0f,0.000601581f, 0.574383f,0.494437f,-0.00830503f,0.00964827f,1.0f,0.000834779f,
0.550569f,0.497429f,-0.00835535f,0.00924836f,1.0f,0.00114641f, 0.526535f,0.499289f,-0.00838651f,0.00884461f,1.0f,0.0015591f,
0.502321f,0.499985f,-0.00839836f,0.00843805f,1.0f,0.002101f, 0.478014f,0.499539f,-0.00839063f,0.00802955f,1.0f,0.00280691f,
0.453617f,0.497883f,-0.00836258f,0.00761958f,1.0f,0.00371956f, 0.42916f,0.494972f,-0.00831379f,0.00720889f,1.0f,0.00489111f,
0.404786f,0.490892f,-0.00824499f,0.0067993f,1.0f,0.00638491f, 0.380441f,0.485497f,-0.00815484f,0.00639079f,1.0f,0.0082775f,
0.356287f,0.478904f,-0.008044f,0.00598502f,1.0f,0.0106608f, 0.332353f,0.471071f,-0.0079123f,0.00558295f,1.0f,0.0136449f,
0.308665f,0.461938f,-0.00775913f,0.00518524f,1.0f,0.0173608f, 0.285356f,0.451608f,-0.00758507f,0.0047934f,1.0f,0.0219639f,
0.262422f,0.439977f,-0.00738962f,0.00440818f,1.0f,0.0276377f, 0.239948f,0.42707f,-0.00717289f,0.00403077f,1.0f,0.0345981f,
0.21802f,0.412925f,-0.00693512f,0.00366238f,1.0f,0.0430982f, 0.196682f,0.397503f,-0.00667637f,0.00330417f,1.0f,0.0534335f,
0.17603f,0.380859f,-0.00639659f,0.0029572f,1.0f,0.0659483f, 0.156131f,0.363004f,-0.00609648f,0.00262292f,1.0f,0.0810415f,
0.137037f,0.343897f,-0.00577564f,0.00230228f,1.0f,0.0991751f, 0.118854f,0.323637f,-0.00543504f,0.0019968f,1.0f,0.120881f,
0.101635f,0.302179f,-0.00507486f,0.0017077f,1.0f,0.146772f, 0.0854754f,0.279605f,-0.00469553f,0.00143626f,1.0f,0.177549f,
0.0704431f,0.255907f,-0.00429745f,0.0011838f,1.0f,0.214015f, 0.0566224f,0.231127f,-0.00388118f,0.000951689f,1.0f,0.257083f,
0.0441031f,0.205333f,-0.00344784f,0.000741427f,1.0f,0.307791f, 0.03296f,0.17853f,-0.00299762f,0.000554297f,1.0f,0.367314f,
0.0232876f,0.150811f,-0.00253191f,0.000391857f,1.0f,0.436975f, 0.0151715f,0.122234f,-0.00205144f,0.000255521f,1.0f,0.518249f,
0.00869668f,0.0928388f,-0.00155732f,0.000146786f,1.0f,0.612744f, 0.0039574f,0.0627633f,-0.00105117f,6.71914e-05f,1.0f,0.72207f,
0.00104672f,0.032313f,-0.000534293f,1.83486e-05f,0.99335f,0.840651f, 9.67922e-05f,0.00932183f,-9.98108e-05f,1.62174e-06f,0.978635f,0.937334f,
0.999986f,7.65073e-07f,2.56484e-22f,0.0228461f,1.0f,2.40099e-19f, 0.999462f,0.0224404f,-0.000513078f,0.0228521f,1.0f,4.59916e-17f,
0.99803f,0.0448412f,-0.00102524f,0.0228188f,1.0f,4.39726e-15f, 0.995449f,0.0671511f,-0.00153538f,0.0227605f,1.0f,1.24218e-13f,
0.991908f,0.0893351f,-0.00204261f,0.0226796f,1.0f,1.63981e-12f, 0.987427f,0.111354f,-0.00254598f,0.0225763f,1.0f,1.3165e-11f,
0.98196f,0.133164f,-0.00304465f,0.0224514f,1.0f,7.494e-11f, 0.97547f,0.154717f,-0.00353743f,0.0223032f,1.0f,3.3236e-10f,
0.967982f,0.175968f,-0.00402344f,0.0221326f,1.0f,1.2208e-09f, 0.959594f,0.196894f,-0.00450173f,0.0219401f,1.0f,3.87129e-09f,
0.950259f,0.217442f,-0.00497164f,0.021727f,1.0f,1.09143e-08f, 0.939912f,0.237555f,-0.00543162f,0.021491f,1.0f,2.79506e-08f,
0.92877f,0.257239f,-0.00588131f,0.0212349f,1.0f,6.60773e-08f, 0.916643f,0.276402f,-0.00631959f,0.0209581f,1.0f,1.46007e-07f,
0.90365f,0.29503f,-0.00674565f,0.0206616f,1.0f,3.04507e-07f, 0.88982f,0.313088f,-0.00715857f,0.0203455f,1.0f,6.04098e-07f,
0.875216f,0.330556f,-0.00755755f,0.0200105f,1.0f,1.14724e-06f, 0.85968f,0.347326f,-0.00794104f,0.0196555f,1.0f,2.09652e-06f,
0.843434f,0.363437f,-0.00830928f,0.0192839f,1.0f,3.70274e-06f, 0.826384f,0.378803f,-0.00866054f,0.018894f,1.0f,6.34318e-06f,
0.808611f,0.39341f,-0.0089948f,0.0184883f,1.0f,1.05729e-05f, 0.790094f,0.4072f,-0.00931014f,0.0180651f,1.0f,1.71921e-05f,
0.770977f,0.420194f,-0.00960693f,0.0176275f,1.0f,2.73342e-05f, 0.751197f,0.43231f,-0.00988386f,0.0171751f,1.0f,4.25779e-05f,
0.730862f,0.443559f,-0.010141f,0.0167102f,1.0f,6.509e-05f, 0.709871f,0.453829f,-0.0103759f,0.0162305f,1.0f,9.78039e-05f,
0.688431f,0.463191f,-0.0105897f,0.01574f,1.0f,0.000144642f, 0.666459f,0.47154f,-0.0107799f,0.0152367f,1.0f,0.000210787f,
0.644032f,0.478871f,-0.0109481f,0.0147249f,1.0f,0.000303019f, 0.621165f,0.485135f,-0.0110914f,0.0142023f,1.0f,0.000430115f,
0.597925f,0.490321f,-0.01121f,0.0136711f,1.0f,0.000603336f, 0.574399f,0.494441f,-0.0113042f,0.0131332f,1.0f,0.000837008f,
0.550655f,0.497497f,-0.0113733f,0.0125896f,1.0f,0.00114921f, 0.526558f,0.4993f,-0.0114152f,0.0120395f,1.0f,0.00156258f,
0.502413f,0.500065f,-0.0114318f,0.0114866f,1.0f,0.0021053f, 0.478066f,0.499582f,-0.0114206f,0.01093f,1.0f,0.00281217f,
0.453618f,0.497869f,-0.011382f,0.0103716f,1.0f,0.00372592f, 0.429172f,0.494971f,-0.0113156f,0.00981269f,1.0f,0.00489874f,
0.404785f,0.490874f,-0.0112221f,0.00925534f,1.0f,0.00639399f, 0.380482f,0.485531f,-0.0110995f,0.00869946f,1.0f,0.00828819f,
0.356326f,0.478937f,-0.0109487f,0.00814729f,1.0f,0.0106733f, 0.332409f,0.471128f,-0.0107698f,0.00760027f,1.0f,0.0136593f,
0.308713f,0.461985f,-0.010561f,0.00705875f,1.0f,0.0173773f, 0.285379f,0.451617f,-0.0103241f,0.00652548f,1.0f,0.0219824f,
0.262441f,0.439978f,-0.0100579f,0.00600108f,1.0f,0.0276583f, 0.239975f,0.427084f,-0.00976298f,0.00548747f,1.0f,0.0346206f,
0.218058f,0.412961f,-0.00943963f,0.00498625f,1.0f,0.0431223f, 0.196741f,0.397583f,-0.00908761f,0.00449879f,1.0f,0.0534588f,
0.176065f,0.380893f,-0.00870668f,0.0040265f,1.0f,0.0659736f, 0.156162f,0.363028f,-0.00829815f,0.00357151f,1.0f,0.0810657f,
0.137085f,0.343966f,-0.00786203f,0.00313533f,1.0f,0.0991961f, 0.118888f,0.32367f,-0.00739825f,0.00271949f,1.0f,0.120896f,
0.101682f,0.302256f,-0.00690818f,0.00232605f,1.0f,0.146777f, 0.0855109f,0.279649f,-0.00639147f,0.00195648f,1.0f,0.177538f,
0.0704858f,0.255981f,-0.00584987f,0.00161293f,1.0f,0.213978f, 0.056668f,0.231221f,-0.0052837f,0.00129711f,1.0f,0.257007f,
0.0441447f,0.205421f,-0.00469371f,0.00101087f,1.0f,0.307658f, 0.0330082f,0.178666f,-0.00408161f,0.000756292f,1.0f,0.367093f,
0.0233324f,0.15095f,-0.00344773f,0.000535164f,1.0f,0.436616f, 0.0152163f,0.122405f,-0.0027943f,0.000349632f,1.0f,0.517661f,
0.0087426f,0.0930754f,-0.00212256f,0.000201659f,1.0f,0.611747f, 0.00400319f,0.0631112f,-0.00143499f,9.33361e-05f,0.999958f,0.720169f,
0.00112363f,0.0337485f,-0.000733655f,2.73954e-05f,0.973632f,0.817822f, 0.000165487f,0.0119166f,-0.000177148f,3.90529e-06f,0.984043f,0.928964f,
1.00001f,8.68905e-07f,5.37397e-22f,0.0298408f,1.0f,3.46239e-18f, 0.999508f,0.022442f,-0.000670183f,0.0298495f,1.0f,1.78479e-16f,
0.997904f,0.0448356f,-0.001339f,0.0298022f,1.0f,9.04308e-15f, 0.995454f,0.0671515f,-0.00200551f,0.0297297f,1.0f,1.89432e-13f,
0.991907f,0.0893349f,-0.00266796f,0.0296231f,1.0f,2.14615e-12f, 0.987424f,0.111355f,-0.00332553f,0.029489f,1.0f,1.58213e-11f,
0.981929f,0.133161f,-0.00397662f,0.0293238f,1.0f,8.55485e-11f, 0.975522f,0.154725f,-0.00462054f,0.0291322f,1.0f,3.6709e-10f,
0.967975f,0.175966f,-0.00525523f,0.0289087f,1.0f,1.31861e-09f, 0.959564f,0.196887f,-0.0058798f,0.0286565f,1.0f,4.11617e-09f,
0.950241f,0.217439f,-0.00649357f,0.0283783f,1.0f,1.14722e-08f, 0.93996f,0.237567f,-0.0070945f,0.0280706f,1.0f,2.91273e-08f,
0.928846f,0.257259f,-0.00768228f,0.0277376f,1.0f,6.84039e-08f, 0.916744f,0.276431f,-0.00825479f,0.0273763f,1.0f,1.50364e-07f,
0.90371f,0.295048f,-0.00881082f,0.0269874f,1.0f,3.12291e-07f, 0.889919f,0.313122f,-0.00935033f,0.0265751f,1.0f,6.17454e-07f,
0.875238f,0.330562f,-0.00987149f,0.0261377f,1.0f,1.16936e-06f, 0.859737f,0.347347f,-0.0103726f,0.0256745f,1.0f,2.13201e-06f,
0.843434f,0.363435f,-0.0108531f,0.0251881f,1.0f,3.75812e-06f, 0.826373f,0.378795f,-0.0113115f,0.024678f,1.0f,6.42746e-06f,
0.808663f,0.393432f,-0.0117485f,0.0241489f,1.0f,1.06982e-05f, 0.790179f,0.407239f,-0.0121607f,0.0235969f,1.0f,1.73748e-05f,
0.770996f,0.420199f,-0.0125482f,0.023025f,1.0f,2.75955e-05f, 0.751228f,0.432324f,-0.01291f,0.0224345f,1.0f,4.29453e-05f,
0.730779f,0.443503f,-0.0132439f,0.0218239f,1.0f,6.55982e-05f, 0.709906f,0.453844f,-0.0135523f,0.0212002f,1.0f,9.84968e-05f,
0.688427f,0.463182f,-0.0138307f,0.0205583f,1.0f,0.000145573f, 0.666449f,0.471525f,-0.01408f,0.0199023f,1.0f,0.000212024f,
0.644057f,0.47888f,-0.0142992f,0.0192331f,1.0f,0.000304641f, 0.62117f,0.485128f,-0.0144861f,0.0185504f,1.0f,0.000432218f,
0.597988f,0.49036f,-0.0146417f,0.0178574f,1.0f,0.000606033f, 0.574455f,0.494476f,-0.014765f,0.0171554f,1.0f,0.000840431f,
0.550669f,0.497495f,-0.0148542f,0.0164442f,1.0f,0.00115351f, 0.526625f,0.499347f,-0.0149098f,0.0157267f,1.0f,0.00156794f,
0.502403f,0.500038f,-0.0149306f,0.0150038f,1.0f,0.0021119f, 0.478095f,0.499591f,-0.0149167f,0.0142776f,1.0f,0.00282023f,
0.453697f,0.497935f,-0.0148669f,0.0135489f,1.0f,0.00373568f, 0.429271f,0.495061f,-0.0147807f,0.0128194f,1.0f,0.00491046f,
0.404825f,0.490895f,-0.0146571f,0.0120903f,1.0f,0.00640792f, 0.380536f,0.485571f,-0.0144977f,0.0113649f,1.0f,0.00830459f,
0.356401f,0.479005f,-0.0143005f,0.0106435f,1.0f,0.0106924f, 0.332425f,0.471116f,-0.0140657f,0.00992835f,1.0f,0.0136814f,
0.308768f,0.462029f,-0.0137941f,0.00922193f,1.0f,0.0174025f, 0.285438f,0.451669f,-0.0134846f,0.00852542f,1.0f,0.0220109f,
0.262517f,0.440062f,-0.0131376f,0.00784098f,1.0f,0.0276899f, 0.240041f,0.427153f,-0.0127523f,0.0071701f,1.0f,0.0346552f,
0.218106f,0.412997f,-0.0123291f,0.00651507f,1.0f,0.0431594f, 0.196793f,0.397628f,-0.0118698f,0.00587866f,1.0f,0.0534974f,
0.176133f,0.380975f,-0.0113724f,0.00526193f,1.0f,0.0660125f, 0.156231f,0.363116f,-0.0108387f,0.0046677f,1.0f,0.0811027f,
0.137144f,0.344034f,-0.010269f,0.00409799f,1.0f,0.0992281f, 0.118955f,0.323766f,-0.00966341f,0.00355496f,1.0f,0.120919f,
0.101741f,0.302333f,-0.0090236f,0.00304122f,1.0f,0.146783f, 0.0855849f,0.279782f,-0.00834943f,0.00255877f,1.0f,0.177519f,
0.0705511f,0.256094f,-0.00764191f,0.00211003f,1.0f,0.213921f, 0.0567308f,0.231335f,-0.00690251f,0.00169755f,1.0f,0.256892f,
0.044215f,0.205583f,-0.00613272f,0.00132386f,1.0f,0.307454f, 0.0330768f,0.178844f,-0.00533352f,0.000991375f,1.0f,0.366754f,
0.023402f,0.151169f,-0.00450632f,0.000702624f,1.0f,0.436064f, 0.0152859f,0.122673f,-0.00365371f,0.000460337f,1.0f,0.51676f,
0.00881104f,0.0934164f,-0.00277759f,0.000267092f,0.999998f,0.610215f, 0.00407401f,0.0636476f,-0.0018796f,0.000125828f,0.997023f,0.714834f,
0.00127265f,0.036324f,-0.000984111f,4.12535e-05f,0.949288f,0.78826f, 0.000275652f,0.0152999f,-0.000295322f,8.48499e-06f,0.987879f,0.917152f,
1.00008f,2.65753e-07f,-7.44446e-22f,0.0377701f,1.0f,3.64071e-17f, 0.999562f,0.0224419f,-0.000848251f,0.0377806f,1.0f,7.19265e-16f,
0.998065f,0.0448418f,-0.00169489f,0.0377233f,1.0f,2.07651e-14f, 0.995494f,0.0671535f,-0.0025383f,0.0376278f,1.0f,3.20367e-13f,
0.991889f,0.089333f,-0.00337668f,0.0374923f,1.0f,3.05044e-12f, 0.987518f,0.111365f,-0.00420909f,0.037324f,1.0f,2.02651e-11f,
0.982004f,0.133171f,-0.00503356f,0.0371179f,1.0f,1.02609e-10f, 0.975516f,0.154724f,-0.00584815f,0.0368724f,1.0f,4.21547e-10f,
0.968013f,0.175973f,-0.00665121f,0.0365882f,1.0f,1.46937e-09f, 0.959593f,0.196892f,-0.00744219f,0.0362714f,1.0f,4.4891e-09f,
0.950312f,0.217454f,-0.00821907f,0.0359194f,1.0f,1.23144e-08f, 0.940042f,0.237586f,-0.00897967f,0.03553f,1.0f,3.08917e-08f,
0.928772f,0.257238f,-0.00972271f,0.0351053f,1.0f,7.18752e-08f, 0.916696f,0.276416f,-0.0104476f,0.0346491f,1.0f,1.56837e-07f,
0.903743f,0.295058f,-0.0111518f,0.0341583f,1.0f,3.23822e-07f, 0.889855f,0.313098f,-0.0118337f,0.0336338f,1.0f,6.37187e-07f,
0.875252f,0.330564f,-0.0124936f,0.0330812f,1.0f,1.20196e-06f, 0.859728f,0.34734f,-0.0131282f,0.0324961f,1.0f,2.18425e-06f,
0.843507f,0.363461f,-0.0137366f,0.031881f,1.0f,3.83951e-06f, 0.826398f,0.378801f,-0.0143168f,0.0312356f,1.0f,6.55115e-06f,
0.808662f,0.393426f,-0.014869f,0.0305643f,1.0f,1.08821e-05f, 0.790209f,0.407249f,-0.0153917f,0.0298676f,1.0f,1.76425e-05f,
0.771105f,0.420252f,-0.0158823f,0.0291442f,1.0f,2.7978e-05f, 0.751296f,0.432355f,-0.0163395f,0.0283956f,1.0f,4.34825e-05f,
0.730926f,0.443585f,-0.0167638f,0.0276258f,1.0f,6.63411e-05f, 0.709944f,0.453856f,-0.0171524f,0.0268336f,1.0f,9.95089e-05f,
0.688494f,0.463213f,-0.0175054f,0.0260223f,1.0f,0.000146934f, 0.666479f,0.471533f,-0.0178201f,0.025191f,1.0f,0.000213829f,
0.644133f,0.478922f,-0.0180978f,0.0243446f,1.0f,0.000307007f, 0.621223f,0.485153f,-0.0183338f,0.0234799f,1.0f,0.000435284f,
0.598027f,0.490376f,-0.0185312f,0.0226036f,1.0f,0.000609964f, 0.574553f,0.494541f,-0.0186876f,0.0217155f,1.0f,0.000845418f,
0.550719f,0.497517f,-0.0188001f,0.0208151f,1.0f,0.00115978f, 0.526687f,0.499382f,-0.0188699f,0.0199067f,1.0f,0.00157574f,
0.502468f,0.500075f,-0.0188959f,0.0189916f,1.0f,0.00212151f, 0.478184f,0.499655f,-0.0188792f,0.0180734f,1.0f,0.00283197f,
0.453741f,0.49795f,-0.0188151f,0.0171503f,1.0f,0.00374989f, 0.429308f,0.495068f,-0.0187054f,0.0162267f,1.0f,0.0049275f,
0.404897f,0.490944f,-0.0185502f,0.0153051f,1.0f,0.00642818f, 0.380626f,0.485642f,-0.0183484f,0.0143871f,1.0f,0.00832844f,
0.356478f,0.479063f,-0.0180992f,0.0134746f,1.0f,0.0107202f, 0.332526f,0.471208f,-0.0178027f,0.0125701f,1.0f,0.0137135f,
0.308865f,0.462119f,-0.0174586f,0.0116759f,1.0f,0.0174391f, 0.285531f,0.451758f,-0.0170671f,0.0107947f,1.0f,0.0220522f,
0.262602f,0.440137f,-0.016627f,0.00992794f,1.0f,0.0277358f, 0.240123f,0.427227f,-0.0161394f,0.00907904f,1.0f,0.0347054f,
0.218191f,0.41308f,-0.0156045f,0.00825052f,1.0f,0.0432132f, 0.196876f,0.397708f,-0.0150228f,0.00744502f,1.0f,0.0535535f,
0.176228f,0.381085f,-0.0143939f,0.00666487f,1.0f,0.0660689f, 0.156314f,0.363204f,-0.0137185f,0.00591287f,1.0f,0.0811564f,
0.137231f,0.344137f,-0.0129976f,0.00519199f,1.0f,0.0992745f, 0.119052f,0.323902f,-0.0122322f,0.00450517f,1.0f,0.120951f,
0.101833f,0.302463f,-0.0114218f,0.00385479f,1.0f,0.146793f, 0.0856796f,0.279932f,-0.0105692f,0.00324444f,1.0f,0.177492f,
0.0706465f,0.25626f,-0.00967431f,0.0026767f,1.0f,0.213837f, 0.0568339f,0.231549f,-0.00873924f,0.00215485f,1.0f,0.256723f,
0.0443152f,0.205811f,-0.0077655f,0.00168199f,1.0f,0.307156f, 0.0331738f,0.17909f,-0.00675447f,0.00126123f,1.0f,0.366259f,
0.0235029f,0.151483f,-0.00570912f,0.000895958f,1.0f,0.435261f, 0.0153852f,0.123048f,-0.00463138f,0.000589366f,1.0f,0.515447f,
0.00891358f,0.0939396f,-0.0035252f,0.000344971f,0.99971f,0.607769f, 0.00419929f,0.0647087f,-0.0023851f,0.000167348f,0.986985f,0.702088f,
0.00157062f,0.0411894f,-0.00131409f,6.30055e-05f,0.930072f,0.760682f, 0.000435576f,0.019181f,-0.000465713f,1.69118e-05f,0.990474f,0.902337f,
0.999992f,6.49608e-07f,4.62725e-21f,0.0466323f,1.0f,2.98268e-16f, 0.999461f,0.0224412f,-0.00104723f,0.0466433f,1.0f,2.89203e-15f,
0.997919f,0.0448348f,-0.00209242f,0.0465711f,1.0f,5.14373e-14f, 0.9955f,0.0671544f,-0.00313391f,0.0464573f,1.0f,5.91714e-13f,
0.991969f,0.0893391f,-0.0041692f,0.046292f,1.0f,4.69267e-12f, 0.987432f,0.111355f,-0.00519671f,0.0460818f,1.0f,2.77239e-11f,
0.981926f,0.13316f,-0.00621417f,0.0458241f,1.0f,1.29861e-10f, 0.975495f,0.154719f,-0.00722029f,0.0455239f,1.0f,5.05724e-10f,
0.968059f,0.175981f,-0.00821225f,0.0451758f,1.0f,1.6972e-09f, 0.959678f,0.196911f,-0.00918854f,0.0447832f,1.0f,5.04362e-09f,
0.950286f,0.217449f,-0.0101471f,0.044346f,1.0f,1.35519e-08f, 0.940029f,0.237582f,-0.0110867f,0.0438677f,1.0f,3.34609e-08f,
0.928834f,0.257254f,-0.0120043f,0.043344f,1.0f,7.68945e-08f, 0.916648f,0.276398f,-0.0128981f,0.0427771f,1.0f,1.66147e-07f,
0.903748f,0.295056f,-0.013768f,0.0421728f,1.0f,3.40329e-07f, 0.889906f,0.313111f,-0.0146104f,0.0415271f,1.0f,6.65337e-07f,
0.875166f,0.330529f,-0.0154234f,0.0408404f,1.0f,1.24834e-06f, 0.859698f,0.347324f,-0.016207f,0.0401185f,1.0f,2.25835e-06f,
0.843568f,0.363483f,-0.0169597f,0.0393631f,1.0f,3.95473e-06f, 0.826488f,0.378837f,-0.0176769f,0.0385681f,1.0f,6.72595e-06f,
0.808705f,0.39344f,-0.0183579f,0.0377379f,1.0f,1.11414e-05f, 0.790267f,0.407271f,-0.0190021f,0.0368758f,1.0f,1.80196e-05f,
0.771118f,0.420248f,-0.0196078f,0.0359831f,1.0f,2.85164e-05f, 0.751363f,0.432381f,-0.0201735f,0.035061f,1.0f,4.4238e-05f,
0.731007f,0.443621f,-0.0206971f,0.0341104f,1.0f,6.73848e-05f, 0.710067f,0.453923f,-0.0211763f,0.0331316f,1.0f,0.00010093f,
0.688519f,0.463215f,-0.0216111f,0.0321287f,1.0f,0.000148842f, 0.666585f,0.47159f,-0.0220006f,0.0311041f,1.0f,0.000216359f,
0.644138f,0.478905f,-0.0223425f,0.0300582f,1.0f,0.000310322f, 0.621293f,0.485184f,-0.0226347f,0.0289919f,1.0f,0.000439578f,
0.59809f,0.490401f,-0.0228777f,0.0279094f,1.0f,0.000615466f, 0.574597f,0.494551f,-0.02307f,0.0268124f,1.0f,0.000852397f,
0.550798f,0.497558f,-0.0232094f,0.0257016f,1.0f,0.00116854f, 0.526797f,0.499453f,-0.023297f,0.0245818f,1.0f,0.00158664f,
0.502597f,0.500167f,-0.0233299f,0.0234531f,1.0f,0.00213495f, 0.47826f,0.499693f,-0.0233067f,0.0223173f,1.0f,0.00284837f,
0.45383f,0.498002f,-0.0232284f,0.0211788f,1.0f,0.00376974f, 0.429392f,0.495116f,-0.0230933f,0.020039f,1.0f,0.0049513f,
0.405032f,0.491053f,-0.0229022f,0.0189019f,1.0f,0.00645645f, 0.380723f,0.485708f,-0.022653f,0.0177688f,1.0f,0.00836173f,
0.356569f,0.479118f,-0.0223443f,0.0166416f,1.0f,0.0107591f, 0.332632f,0.471288f,-0.0219786f,0.0155254f,1.0f,0.0137583f,
0.308968f,0.462196f,-0.0215537f,0.0144217f,1.0f,0.0174902f, 0.285652f,0.451865f,-0.0210704f,0.0133339f,1.0f,0.0221098f,
0.262717f,0.440239f,-0.0205275f,0.0122645f,1.0f,0.0277998f, 0.240253f,0.427357f,-0.0199258f,0.0112168f,1.0f,0.0347753f,
0.218323f,0.413219f,-0.0192663f,0.0101946f,1.0f,0.043288f, 0.197007f,0.397852f,-0.0185484f,0.00920045f,1.0f,0.0536315f,
0.176355f,0.381228f,-0.017772f,0.00823742f,1.0f,0.0661473f, 0.156446f,0.363367f,-0.0169383f,0.00730923f,1.0f,0.0812308f,
0.137379f,0.344348f,-0.0160495f,0.0064199f,1.0f,0.0993387f, 0.119197f,0.324114f,-0.0151044f,0.00557203f,1.0f,0.120996f,
0.101967f,0.302663f,-0.0141039f,0.00476917f,1.0f,0.146805f, 0.0858116f,0.28014f,-0.0130517f,0.00401583f,1.0f,0.177453f,
0.0707893f,0.256526f,-0.0119483f,0.00331535f,1.0f,0.213719f, 0.0569746f,0.231835f,-0.0107949f,0.00267135f,1.0f,0.256486f,
0.0444535f,0.206123f,-0.00959342f,0.00208768f,1.0f,0.306739f, 0.0333151f,0.179462f,-0.00834687f,0.00156845f,1.0f,0.365567f,
0.0236448f,0.151925f,-0.0070582f,0.00111767f,1.0f,0.434137f, 0.0155274f,0.123593f,-0.00573042f,0.000739369f,0.999917f,0.513556f,
0.00905966f,0.0946888f,-0.00435751f,0.000438707f,0.994771f,0.600802f, 0.0044329f,0.0668203f,-0.00296598f,0.000222218f,0.971372f,0.68286f,
0.00194871f,0.0461843f,-0.00173345f,9.57883e-05f,0.918884f,0.737832f, 0.000658452f,0.023547f,-0.000701968f,3.14423e-05f,0.992313f,0.885122f,
1.00005f,4.00119e-08f,-5.50697e-21f,0.0564299f,1.0f,1.99587e-15f, 0.99946f,0.0224403f,-0.00126725f,0.0564427f,1.0f,1.13295e-14f,
0.997965f,0.0448384f,-0.00253217f,0.056359f,1.0f,1.33443e-13f, 0.99547f,0.0671537f,-0.00379215f,0.0562152f,1.0f,1.17102e-12f,
0.991927f,0.0893378f,-0.00504506f,0.0560171f,1.0f,7.7438e-12f, 0.987488f,0.111361f,-0.00628865f,0.0557649f,1.0f,4.04079e-11f,
0.981991f,0.133169f,-0.0075198f,0.0554523f,1.0f,1.73574e-10f, 0.975457f,0.154714f,-0.0087365f,0.0550842f,1.0f,6.35466e-10f,
0.968058f,0.175978f,-0.00993727f,0.0546658f,1.0f,2.03858e-09f, 0.959609f,0.196893f,-0.0111185f,0.0541901f,1.0f,5.85763e-09f,
0.95033f,0.217456f,-0.012279f,0.0536638f,1.0f,1.53407e-08f, 0.93996f,0.237563f,-0.013415f,0.0530812f,1.0f,3.71316e-08f,
0.928817f,0.257245f,-0.014526f,0.0524503f,1.0f,8.40001e-08f, 0.916673f,0.276405f,-0.0156081f,0.0517662f,1.0f,1.7923e-07f,
0.903756f,0.295057f,-0.0166606f,0.051035f,1.0f,3.63394e-07f, 0.889887f,0.313101f,-0.0176789f,0.0502505f,1.0f,7.04479e-07f,
0.875196f,0.330535f,-0.0186637f,0.0494226f,1.0f,1.31257e-06f, 0.859735f,0.347333f,-0.0196116f,0.0485487f,1.0f,2.36064e-06f,
0.843588f,0.363484f,-0.0205221f,0.0476339f,1.0f,4.11334e-06f, 0.82648f,0.378824f,-0.0213884f,0.046669f,1.0f,6.96601e-06f,
0.808758f,0.393456f,-0.0222138f,0.0456677f,1.0f,1.14969e-05f, 0.790293f,0.407272f,-0.0229937f,0.0446255f,1.0f,1.85356e-05f,
0.77117f,0.420264f,-0.0237259f,0.0435442f,1.0f,2.92517e-05f, 0.751369f,0.432371f,-0.0244098f,0.0424279f,1.0f,4.52686e-05f,
0.730981f,0.443587f,-0.0250414f,0.0412748f,1.0f,6.88067e-05f, 0.710049f,0.453892f,-0.0256229f,0.0400934f,1.0f,0.000102864f,
0.688619f,0.463262f,-0.0261509f,0.0388831f,1.0f,0.000151436f, 0.666668f,0.471623f,-0.0266218f,0.037643f,1.0f,0.000219796f,
0.644255f,0.478967f,-0.0270349f,0.036377f,1.0f,0.000314822f, 0.621445f,0.485272f,-0.0273899f,0.0350889f,1.0f,0.000445403f,
0.598208f,0.490467f,-0.0276827f,0.0337779f,1.0f,0.000622925f, 0.574721f,0.494622f,-0.0279156f,0.0324511f,1.0f,0.000861852f,
0.550913f,0.497621f,-0.0280836f,0.0311068f,1.0f,0.00118041f, 0.526883f,0.499486f,-0.0281881f,0.0297506f,1.0f,0.00160139f,
0.502682f,0.5002f,-0.0282272f,0.0283845f,1.0f,0.00215312f, 0.478356f,0.499739f,-0.0282014f,0.0270129f,1.0f,0.00287055f,
0.453953f,0.498077f,-0.028106f,0.025635f,1.0f,0.00379656f, 0.429524f,0.4952f,-0.0279426f,0.0242564f,1.0f,0.00498345f,
0.40513f,0.4911f,-0.02771f,0.0228798f,1.0f,0.00649464f, 0.380875f,0.485821f,-0.0274097f,0.0215102f,1.0f,0.00840667f,
0.356721f,0.479237f,-0.0270375f,0.0201477f,1.0f,0.0108114f, 0.332781f,0.471402f,-0.0265934f,0.0187964f,1.0f,0.0138187f,
0.309135f,0.462342f,-0.0260805f,0.0174621f,1.0f,0.0175591f, 0.285807f,0.451993f,-0.0254949f,0.0161458f,1.0f,0.0221874f,
0.262884f,0.440391f,-0.0248392f,0.0148528f,1.0f,0.027886f, 0.240418f,0.427514f,-0.0241114f,0.0135857f,1.0f,0.0348695f,
0.218489f,0.413382f,-0.0233133f,0.012349f,1.0f,0.0433887f, 0.197167f,0.39801f,-0.022444f,0.0111461f,1.0f,0.0537364f,
0.176532f,0.381428f,-0.0215059f,0.00998184f,1.0f,0.0662525f, 0.156621f,0.363572f,-0.0204972f,0.00885902f,1.0f,0.0813306f,
0.137549f,0.344552f,-0.0194224f,0.00778347f,1.0f,0.0994245f, 0.11937f,0.324346f,-0.0182796f,0.00675802f,1.0f,0.121056f,
0.102162f,0.302971f,-0.0170714f,0.00578758f,1.0f,0.14682f, 0.0860008f,0.280453f,-0.0157993f,0.00487646f,1.0f,0.177398f,
0.0709742f,0.256854f,-0.0144647f,0.00402908f,1.0f,0.213558f, 0.0571596f,0.232202f,-0.0130704f,0.00325016f,1.0f,0.256163f,
0.0446409f,0.206544f,-0.0116185f,0.00254432f,1.0f,0.306173f, 0.0335045f,0.179954f,-0.0101127f,0.00191642f,0.999999f,0.364629f,
0.0238325f,0.152497f,-0.00855589f,0.00137122f,0.99995f,0.432586f, 0.0157224f,0.124347f,-0.0069481f,0.000914381f,0.998259f,0.509909f,
0.00930347f,0.0960935f,-0.00528654f,0.000553514f,0.986808f,0.590294f, 0.00487209f,0.070814f,-0.00365799f,0.000297393f,0.953635f,0.659757f,
0.00249335f,0.0526343f,-0.00226356f,0.000144278f,0.914408f,0.718754f, 0.000958785f,0.0283928f,-0.00101927f,5.52075e-05f,0.993664f,0.865906f,
1.00004f,4.0563e-07f,1.08371e-21f,0.0671614f,1.0f,1.12941e-14f, 0.999484f,0.0224413f,-0.00150834f,0.0671809f,1.0f,4.26719e-14f,
0.997974f,0.0448405f,-0.00301377f,0.0670782f,1.0f,3.54308e-13f, 0.9955f,0.0671556f,-0.00451347f,0.0669085f,1.0f,2.43668e-12f,
0.991949f,0.089336f,-0.00600466f,0.0666723f,1.0f,1.35447e-11f, 0.987437f,0.111356f,-0.00748457f,0.0663703f,1.0f,6.23598e-11f,
0.982002f,0.133168f,-0.00895042f,0.0660026f,1.0f,2.44468e-10f, 0.975541f,0.154728f,-0.0103988f,0.0655656f,1.0f,8.36419e-10f,
0.968071f,0.175982f,-0.0118273f,0.0650638f,1.0f,2.54995e-09f, 0.959701f,0.19691f,-0.0132336f,0.0644999f,1.0f,7.04708e-09f,
0.95032f,0.217453f,-0.0146144f,0.0638718f,1.0f,1.79058e-08f, 0.940038f,0.237578f,-0.0159666f,0.0631791f,1.0f,4.23188e-08f,
0.928819f,0.257243f,-0.0172886f,0.0624274f,1.0f,9.39268e-08f, 0.916737f,0.276419f,-0.0185761f,0.0616124f,1.0f,1.9734e-07f,
0.903768f,0.295055f,-0.0198287f,0.0607422f,1.0f,3.95084e-07f, 0.889906f,0.313104f,-0.0210414f,0.0598109f,1.0f,7.5793e-07f,
0.875349f,0.330588f,-0.0222153f,0.0588309f,1.0f,1.39983e-06f, 0.85989f,0.347386f,-0.0233423f,0.0577879f,1.0f,2.49903e-06f,
0.843603f,0.363483f,-0.0244236f,0.056694f,1.0f,4.32712e-06f, 0.82651f,0.378827f,-0.0254552f,0.0555474f,1.0f,7.28858e-06f,
0.808744f,0.393437f,-0.0264355f,0.0543518f,1.0f,1.19733e-05f, 0.790384f,0.407305f,-0.027365f,0.0531147f,1.0f,1.92254e-05f,
0.771195f,0.420261f,-0.0282366f,0.0518286f,1.0f,3.02329e-05f, 0.751436f,0.432389f,-0.0290495f,0.0504988f,1.0f,4.66412e-05f,
0.731062f,0.443618f,-0.0298034f,0.0491309f,1.0f,7.06976e-05f, 0.710162f,0.453939f,-0.0304954f,0.0477254f,1.0f,0.000105431f,
0.688689f,0.463282f,-0.0311212f,0.0462815f,1.0f,0.000154877f, 0.666743f,0.471646f,-0.031682f,0.044807f,1.0f,0.00022435f,
0.644343f,0.478997f,-0.032174f,0.0433012f,1.0f,0.000320777f, 0.621533f,0.485306f,-0.0325948f,0.0417668f,1.0f,0.000453104f,
0.598356f,0.490544f,-0.0329459f,0.0402105f,1.0f,0.000632779f, 0.574837f,0.494672f,-0.0332219f,0.0386307f,1.0f,0.000874333f,
0.551013f,0.49766f,-0.0334216f,0.0370311f,1.0f,0.00119606f, 0.527003f,0.499541f,-0.0335456f,0.0354174f,1.0f,0.00162083f,
0.502825f,0.500276f,-0.0335926f,0.0337928f,1.0f,0.00217705f, 0.478501f,0.499816f,-0.0335606f,0.0321598f,1.0f,0.00289974f,
0.45411f,0.49817f,-0.0334477f,0.0305214f,1.0f,0.00383186f, 0.429743f,0.495367f,-0.0332553f,0.0288832f,1.0f,0.00502573f,
0.405332f,0.491249f,-0.0329785f,0.0272455f,1.0f,0.00654484f, 0.381029f,0.485912f,-0.0326181f,0.0256137f,1.0f,0.00846571f,
0.356911f,0.479378f,-0.0321763f,0.0239938f,1.0f,0.0108802f, 0.333012f,0.471603f,-0.0316505f,0.0223882f,1.0f,0.013898f,
0.309317f,0.462476f,-0.0310379f,0.0207994f,1.0f,0.0176495f, 0.286019f,0.452178f,-0.0303426f,0.0192345f,1.0f,0.0222891f,
0.26308f,0.440553f,-0.0295605f,0.0176952f,1.0f,0.0279989f, 0.240626f,0.427705f,-0.0286949f,0.0161881f,1.0f,0.0349927f,
0.218723f,0.41363f,-0.0277468f,0.0147178f,1.0f,0.0435204f, 0.197403f,0.398271f,-0.0267128f,0.013287f,1.0f,0.0538734f,
0.17675f,0.38166f,-0.0255969f,0.0119021f,1.0f,0.0663898f, 0.156852f,0.363849f,-0.0243982f,0.0105671f,1.0f,0.0814605f,
0.137774f,0.34483f,-0.0231181f,0.00928695f,1.0f,0.0995357f, 0.119606f,0.324668f,-0.0217608f,0.00806799f,1.0f,0.121132f,
0.102392f,0.303296f,-0.0203224f,0.00691313f,1.0f,0.146838f, 0.0862378f,0.280831f,-0.0188108f,0.00582982f,1.0f,0.177324f,
0.0712164f,0.257282f,-0.0172246f,0.00482206f,1.0f,0.213342f, 0.0574032f,0.23268f,-0.0155676f,0.00389576f,1.0f,0.255735f,
0.0448844f,0.207079f,-0.0138428f,0.00305636f,0.999999f,0.305424f, 0.0337525f,0.180593f,-0.0120547f,0.00230981f,0.999951f,0.363365f,
0.024085f,0.153275f,-0.0102021f,0.00166201f,0.999027f,0.429994f, 0.0160018f,0.125484f,-0.00827875f,0.00112181f,0.992577f,0.502509f,
0.0097775f,0.0991555f,-0.00633766f,0.000699611f,0.973977f,0.574544f, 0.00559066f,0.0770055f,-0.00449777f,0.000400943f,0.938208f,0.636412f,
0.00305711f,0.0576935f,-0.00289327f,0.000212105f,0.914442f,0.701728f, 0.00135224f,0.0336854f,-0.00143396f,9.239e-05f,0.994686f,0.844985f,
0.999949f,-1.16385e-06f,-1.9769e-21f,0.0788302f,1.0f,5.54862e-14f, 0.999529f,0.0224414f,-0.00177042f,0.0788539f,1.0f,1.53452e-13f,
0.998026f,0.04484f,-0.00353758f,0.0787369f,1.0f,9.46614e-13f, 0.995459f,0.0671502f,-0.00529777f,0.0785353f,1.0f,5.24275e-12f,
0.992004f,0.0893427f,-0.00704825f,0.0782602f,1.0f,2.47925e-11f, 0.987479f,0.11136f,-0.00878491f,0.0779018f,1.0f,1.01048e-10f,
0.981988f,0.133166f,-0.0105051f,0.0774684f,1.0f,3.61088e-10f, 0.975464f,0.154716f,-0.012205f,0.0769552f,1.0f,1.15067e-09f,
0.968067f,0.175981f,-0.0138825f,0.0763717f,1.0f,3.31999e-09f, 0.959631f,0.196896f,-0.0155326f,0.0757072f,1.0f,8.78749e-09f,
0.950373f,0.21746f,-0.0171536f,0.0749716f,1.0f,2.15767e-08f, 0.940052f,0.237584f,-0.0187407f,0.0741587f,1.0f,4.96139e-08f,
0.92883f,0.257244f,-0.0202912f,0.0732727f,1.0f,1.07695e-07f, 0.916751f,0.276418f,-0.0218037f,0.0723209f,1.0f,2.22178e-07f,
0.903819f,0.295069f,-0.0232735f,0.0712987f,1.0f,4.38149e-07f, 0.889958f,0.313114f,-0.0246967f,0.0702059f,1.0f,8.30019e-07f,
0.875333f,0.330571f,-0.026072f,0.0690491f,1.0f,1.51678e-06f, 0.859915f,0.347387f,-0.0273964f,0.0678301f,1.0f,2.6835e-06f,
0.843675f,0.363503f,-0.0286661f,0.0665482f,1.0f,4.61082e-06f, 0.826593f,0.378852f,-0.0298764f,0.0652021f,1.0f,7.71496e-06f,
0.808859f,0.393482f,-0.031029f,0.0638038f,1.0f,1.26008e-05f, 0.79042f,0.407305f,-0.0321172f,0.0623471f,1.0f,2.01315e-05f,
0.771342f,0.420323f,-0.0331408f,0.0608395f,1.0f,3.15184e-05f, 0.751554f,0.432432f,-0.0340953f,0.0592802f,1.0f,4.84354e-05f,
0.731155f,0.443647f,-0.0349785f,0.0576727f,1.0f,7.31643e-05f, 0.710295f,0.453995f,-0.0357911f,0.0560247f,1.0f,0.000108775f,
0.688818f,0.46333f,-0.0365244f,0.0543293f,1.0f,0.000159351f, 0.666876f,0.471699f,-0.0371812f,0.0525975f,1.0f,0.000230262f,
0.644486f,0.479059f,-0.0377591f,0.050832f,1.0f,0.000328498f, 0.621702f,0.485387f,-0.0382554f,0.0490352f,1.0f,0.000463078f,
0.598483f,0.490588f,-0.0386637f,0.0472049f,1.0f,0.000645527f, 0.574982f,0.494732f,-0.0389877f,0.0453519f,1.0f,0.000890461f,
0.551262f,0.497813f,-0.0392256f,0.0434796f,1.0f,0.00121627f, 0.527225f,0.499674f,-0.0393696f,0.0415851f,1.0f,0.00164592f,
0.503014f,0.50038f,-0.0394234f,0.0396779f,1.0f,0.00220791f, 0.478744f,0.499976f,-0.0393883f,0.0377649f,1.0f,0.00293735f,
0.454325f,0.498304f,-0.0392532f,0.0358404f,1.0f,0.00387728f, 0.429955f,0.495496f,-0.0390281f,0.0339195f,1.0f,0.00508012f,
0.405568f,0.491411f,-0.038704f,0.0319991f,1.0f,0.00660936f, 0.38127f,0.486082f,-0.0382806f,0.0300846f,1.0f,0.00854154f,
0.35714f,0.479537f,-0.0377618f,0.0281842f,1.0f,0.0109684f, 0.333207f,0.471718f,-0.0371421f,0.0262989f,1.0f,0.0139996f,
0.309593f,0.46271f,-0.0364277f,0.0244383f,1.0f,0.0177653f, 0.286271f,0.452384f,-0.0356095f,0.0226013f,1.0f,0.0224194f,
0.263371f,0.440829f,-0.0346954f,0.020798f,1.0f,0.0281434f, 0.240918f,0.427989f,-0.0336802f,0.0190303f,1.0f,0.0351502f,
0.218991f,0.413879f,-0.0325655f,0.0173045f,1.0f,0.0436886f, 0.197675f,0.398541f,-0.0313542f,0.0156272f,1.0f,0.0540481f,
0.17704f,0.381981f,-0.0300444f,0.0140024f,1.0f,0.0665645f, 0.157158f,0.364219f,-0.0286406f,0.0124376f,1.0f,0.0816252f,
0.138086f,0.345237f,-0.0271402f,0.0109366f,1.0f,0.0996759f, 0.119904f,0.325062f,-0.0255461f,0.00950598f,1.0f,0.121226f,
0.102701f,0.303756f,-0.0238624f,0.0081526f,1.0f,0.146857f, 0.0865493f,0.281331f,-0.0220902f,0.00688206f,1.0f,0.177223f,
0.0715287f,0.25783f,-0.0202312f,0.00570031f,1.0f,0.21306f, 0.0577142f,0.23328f,-0.0182894f,0.00461399f,0.999997f,0.255177f,
0.0452079f,0.207809f,-0.01627f,0.00363011f,0.999937f,0.304424f, 0.0340746f,0.181424f,-0.0141712f,0.00275529f,0.999222f,0.361344f,
0.0244336f,0.154401f,-0.0119803f,0.00199989f,0.994223f,0.424204f, 0.0164548f,0.127516f,-0.00973853f,0.00137182f,0.983514f,0.491651f,
0.0103887f,0.102698f,-0.00751324f,0.000884089f,0.959574f,0.55591f, 0.00659016f,0.084754f,-0.00551378f,0.000542329f,0.926551f,0.614108f,
0.00386548f,0.0646934f,-0.00367692f,0.000308571f,0.917107f,0.685327f, 0.0018567f,0.0394444f,-0.00196456f,0.000148501f,0.995479f,0.822603f,
1.00003f,2.60209e-06f,-3.03549e-21f,0.0914437f,1.0f,2.41531e-13f, 0.999538f,0.0224423f,-0.00205363f,0.0914684f,1.0f,5.25139e-13f,
0.998005f,0.044841f,-0.00410326f,0.0913278f,1.0f,2.51445e-12f, 0.995552f,0.0671587f,-0.00614517f,0.0910979f,1.0f,1.15045e-11f,
0.991961f,0.0893386f,-0.00817527f,0.0907748f,1.0f,4.69206e-11f, 0.987468f,0.111361f,-0.0101904f,0.0903658f,1.0f,1.70345e-10f,
0.981973f,0.133163f,-0.0121856f,0.0898621f,1.0f,5.55761e-10f, 0.975528f,0.15472f,-0.0141575f,0.0892681f,1.0f,1.64794e-09f,
0.968104f,0.175984f,-0.0161026f,0.0885867f,1.0f,4.48946e-09f, 0.95976f,0.19692f,-0.0180169f,0.0878185f,1.0f,1.13476e-08f,
0.950294f,0.21744f,-0.0198957f,0.0869593f,1.0f,2.68424e-08f, 0.940053f,0.237576f,-0.0217367f,0.086018f,1.0f,5.98706e-08f,
0.928931f,0.257264f,-0.0235375f,0.0849997f,1.0f,1.26741e-07f, 0.916887f,0.276455f,-0.0252907f,0.0838919f,1.0f,2.56088e-07f,
0.903846f,0.295067f,-0.0269936f,0.082701f,1.0f,4.96305e-07f, 0.890115f,0.31316f,-0.0286466f,0.0814407f,1.0f,9.26488e-07f,
0.875464f,0.33061f,-0.0302416f,0.0800994f,1.0f,1.67209e-06f, 0.859962f,0.347397f,-0.0317756f,0.0786808f,1.0f,2.92689e-06f,
0.84377f,0.363528f,-0.0332482f,0.077195f,1.0f,4.98306e-06f, 0.826728f,0.3789f,-0.034653f,0.0756367f,1.0f,8.27176e-06f,
0.80897f,0.393513f,-0.035989f,0.074014f,1.0f,1.34169e-05f, 0.790586f,0.407369f,-0.037252f,0.0723272f,1.0f,2.13057e-05f,
0.771491f,0.420376f,-0.0384392f,0.0705797f,1.0f,3.31788e-05f, 0.751701f,0.432487f,-0.0395433f,0.0687669f,1.0f,5.07465e-05f,
0.731317f,0.443708f,-0.0405687f,0.0669054f,1.0f,7.63338e-05f, 0.710437f,0.454041f,-0.0415092f,0.0649921f,1.0f,0.000113062f,
0.689022f,0.463422f,-0.0423626f,0.0630314f,1.0f,0.000165075f, 0.667074f,0.471789f,-0.0431238f,0.0610234f,1.0f,0.000237812f,
0.644678f,0.47914f,-0.0437938f,0.0589767f,1.0f,0.000338344f, 0.621836f,0.485426f,-0.0443651f,0.0568884f,1.0f,0.000475776f,
0.598675f,0.490675f,-0.04484f,0.0547689f,1.0f,0.000661734f, 0.575246f,0.494882f,-0.0452189f,0.0526249f,1.0f,0.000910943f,
0.55146f,0.497904f,-0.0454894f,0.0504487f,1.0f,0.0012419f, 0.527432f,0.499774f,-0.0456589f,0.0482556f,1.0f,0.0016777f,
0.503309f,0.500566f,-0.0457235f,0.0460474f,1.0f,0.00224696f, 0.478991f,0.500116f,-0.0456795f,0.0438268f,1.0f,0.0029849f,
0.454614f,0.498491f,-0.0455242f,0.0415977f,1.0f,0.00393467f, 0.4302f,0.495637f,-0.0452594f,0.039368f,1.0f,0.00514876f,
0.405832f,0.491574f,-0.0448834f,0.0371422f,1.0f,0.00669072f, 0.381585f,0.486314f,-0.0443958f,0.034926f,1.0f,0.00863708f,
0.357452f,0.479765f,-0.0437935f,0.032723f,1.0f,0.0110796f, 0.333534f,0.471976f,-0.0430774f,0.0305398f,1.0f,0.0141275f,
0.309936f,0.463002f,-0.0422497f,0.0283838f,1.0f,0.0179108f, 0.286615f,0.452678f,-0.0413009f,0.0262546f,1.0f,0.022583f,
0.263707f,0.441122f,-0.0402391f,0.0241634f,1.0f,0.0283246f, 0.241247f,0.428279f,-0.0390628f,0.0221152f,1.0f,0.0353476f,
0.21936f,0.414257f,-0.0377728f,0.0201164f,1.0f,0.043899f, 0.198048f,0.398943f,-0.0363688f,0.0181725f,1.0f,0.0542663f,
0.177402f,0.382374f,-0.034851f,0.0162898f,1.0f,0.066782f, 0.157519f,0.364631f,-0.0332235f,0.0144761f,1.0f,0.0818295f,
0.138467f,0.34572f,-0.031488f,0.0127381f,1.0f,0.0998485f, 0.120299f,0.325613f,-0.0296421f,0.0110807f,1.0f,0.121341f,
0.103094f,0.304335f,-0.0276915f,0.00951237f,1.0f,0.146875f, 0.0869436f,0.281967f,-0.0256393f,0.00804029f,1.0f,0.177089f,
0.0719258f,0.258533f,-0.0234873f,0.0066712f,0.999992f,0.212692f, 0.0581176f,0.23408f,-0.0212402f,0.0054131f,0.999906f,0.254424f,
0.0456113f,0.208704f,-0.0188959f,0.00427381f,0.999215f,0.302808f, 0.0345305f,0.182695f,-0.016439f,0.00326653f,0.994748f,0.356578f,
0.0250418f,0.156713f,-0.0139222f,0.00239761f,0.987442f,0.416342f, 0.0174335f,0.132556f,-0.0113829f,0.00168308f,0.971696f,0.477581f,
0.0114419f,0.108899f,-0.00890199f,0.00112608f,0.945743f,0.53596f, 0.00755152f,0.090619f,-0.00668314f,0.000727269f,0.919076f,0.593367f,
0.00485249f,0.0724348f,-0.00461578f,0.000440986f,0.921162f,0.668688f, 0.00249069f,0.0456477f,-0.00263029f,0.000230528f,0.996105f,0.798978f,
0.99999f,3.94984e-06f,1.8348e-20f,0.104992f,1.0f,9.46645e-13f, 0.99952f,0.0224426f,-0.00235793f,0.105022f,1.0f,1.70819e-12f,
0.998065f,0.0448451f,-0.00471153f,0.104867f,1.0f,6.58528e-12f, 0.995519f,0.0671542f,-0.00705596f,0.104601f,1.0f,2.54677e-11f,
0.991946f,0.0893357f,-0.00938699f,0.10423f,1.0f,9.0839e-11f, 0.987449f,0.111352f,-0.0116999f,0.103754f,1.0f,2.96048e-10f,
0.981967f,0.133166f,-0.0139909f,0.103177f,1.0f,8.85052e-10f, 0.975469f,0.154714f,-0.016255f,0.102496f,1.0f,2.4443e-09f,
0.968126f,0.17599f,-0.0184892f,0.101719f,1.0f,6.2833e-09f, 0.95978f,0.196923f,-0.0206865f,0.100834f,1.0f,1.51421e-08f,
0.950335f,0.217446f,-0.0228435f,0.099848f,1.0f,3.44348e-08f, 0.940111f,0.237588f,-0.0249574f,0.0987684f,1.0f,7.43327e-08f,
0.928987f,0.257279f,-0.0270241f,0.0975967f,1.0f,1.53111e-07f, 0.916904f,0.276455f,-0.0290375f,0.0963277f,1.0f,3.02331e-07f,
0.903913f,0.295081f,-0.0309935f,0.0949638f,1.0f,5.74622e-07f, 0.890178f,0.313171f,-0.0328894f,0.0935123f,1.0f,1.05503e-06f,
0.875421f,0.330584f,-0.0347185f,0.0919675f,1.0f,1.8772e-06f, 0.860096f,0.347432f,-0.0364837f,0.0903503f,1.0f,3.24587e-06f,
0.843864f,0.363549f,-0.0381719f,0.0886398f,1.0f,5.4677e-06f, 0.826888f,0.378946f,-0.0397857f,0.0868543f,1.0f,8.99257e-06f,
0.809082f,0.393543f,-0.0413164f,0.0849861f,1.0f,1.44682e-05f, 0.790655f,0.407375f,-0.0427647f,0.0830478f,1.0f,2.28116e-05f,
0.771601f,0.420403f,-0.0441295f,0.0810467f,1.0f,3.53003e-05f, 0.751887f,0.432553f,-0.0453988f,0.0789704f,1.0f,5.36893e-05f,
0.731512f,0.443783f,-0.0465741f,0.0768317f,1.0f,8.03575e-05f, 0.710631f,0.454114f,-0.0476547f,0.0746381f,1.0f,0.00011849f,
0.689187f,0.463477f,-0.0486321f,0.0723854f,1.0f,0.000172305f, 0.66728f,0.471869f,-0.0495052f,0.0700809f,1.0f,0.000247328f,
0.644893f,0.479228f,-0.0502736f,0.0677322f,1.0f,0.000350726f, 0.62207f,0.485525f,-0.0509293f,0.0653366f,1.0f,0.000491718f,
0.598982f,0.490836f,-0.0514766f,0.0629079f,1.0f,0.000682049f, 0.57548f,0.494983f,-0.0519081f,0.0604446f,1.0f,0.000936574f,
0.551781f,0.498081f,-0.0522233f,0.0579535f,1.0f,0.00127394f, 0.527767f,0.499967f,-0.0524154f,0.055435f,1.0f,0.00171737f,
0.503617f,0.500737f,-0.0524888f,0.0529013f,1.0f,0.00229563f, 0.479294f,0.500287f,-0.0524349f,0.0503508f,1.0f,0.0030441f,
0.454923f,0.498666f,-0.0522582f,0.0477955f,1.0f,0.00400603f, 0.430555f,0.495866f,-0.0519555f,0.045239f,1.0f,0.00523403f,
0.406212f,0.491834f,-0.0515247f,0.0426866f,1.0f,0.00679168f, 0.381967f,0.486584f,-0.050964f,0.0401438f,1.0f,0.00875552f,
0.357824f,0.480029f,-0.0502713f,0.0376158f,1.0f,0.0112171f, 0.33393f,0.472278f,-0.0494492f,0.0351116f,1.0f,0.0142857f,
0.310312f,0.463278f,-0.0484978f,0.0326377f,1.0f,0.0180907f, 0.287013f,0.453004f,-0.0474125f,0.0301979f,1.0f,0.0227848f,
0.26411f,0.441464f,-0.0461941f,0.0277994f,1.0f,0.028548f, 0.241702f,0.428719f,-0.0448472f,0.025452f,1.0f,0.0355904f,
0.21979f,0.414669f,-0.0433669f,0.0231593f,1.0f,0.0441574f, 0.198505f,0.399414f,-0.0417567f,0.0209302f,1.0f,0.0545335f,
0.177863f,0.382887f,-0.0400178f,0.018772f,1.0f,0.0670476f, 0.157988f,0.365182f,-0.0381509f,0.0166919f,1.0f,0.0820776f,
0.138928f,0.346285f,-0.0361596f,0.0146983f,1.0f,0.100056f, 0.120773f,0.326248f,-0.034047f,0.0127992f,1.0f,0.121474f,
0.103576f,0.305037f,-0.0318122f,0.0110013f,0.999998f,0.146886f, 0.0874347f,0.282749f,-0.0294602f,0.00931337f,0.999979f,0.176904f,
0.0724141f,0.259377f,-0.0269924f,0.00774375f,0.999847f,0.212166f, 0.0586182f,0.235059f,-0.024411f,0.00630318f,0.999081f,0.253125f,
0.046137f,0.209902f,-0.0216916f,0.00500441f,0.995225f,0.299018f, 0.0351127f,0.184299f,-0.0188933f,0.0038534f,0.98989f,0.351001f,
0.0258074f,0.15945f,-0.0160339f,0.00287106f,0.978196f,0.405929f, 0.0182294f,0.135613f,-0.0131731f,0.00206119f,0.958902f,0.461449f,
0.0126931f,0.115411f,-0.010493f,0.00143509f,0.93403f,0.515918f, 0.00905286f,0.100021f,-0.00808131f,0.000973574f,0.914988f,0.573752f,
0.00591418f,0.0789266f,-0.00572856f,0.000619467f,0.925846f,0.651362f, 0.00327371f,0.0522749f,-0.00345107f,0.000347147f,0.996609f,0.774309f,
0.999939f,1.16138e-06f,-1.12255e-20f,0.119486f,1.0f,3.38384e-12f, 0.999435f,0.0224376f,-0.00268338f,0.119518f,1.0f,5.28175e-12f,
0.998f,0.0448402f,-0.00536197f,0.119345f,1.0f,1.69093e-11f, 0.995508f,0.0671579f,-0.00803014f,0.119043f,1.0f,5.63982e-11f,
0.991988f,0.0893401f,-0.0106828f,0.11862f,1.0f,1.78297e-10f, 0.987432f,0.111354f,-0.0133151f,0.118079f,1.0f,5.26025e-10f,
0.98193f,0.133158f,-0.015922f,0.11742f,1.0f,1.448e-09f, 0.975562f,0.154729f,-0.0184996f,0.116652f,1.0f,3.73353e-09f,
0.96807f,0.175977f,-0.02104f,0.115757f,1.0f,9.06221e-09f, 0.959689f,0.196903f,-0.0235411f,0.114754f,1.0f,2.08135e-08f,
0.950405f,0.217459f,-0.0259966f,0.113636f,1.0f,4.54551e-08f, 0.940222f,0.237612f,-0.0284037f,0.112414f,1.0f,9.48234e-08f,
0.928978f,0.257266f,-0.0307532f,0.111073f,1.0f,1.8973e-07f, 0.916942f,0.276458f,-0.0330433f,0.109626f,1.0f,3.65481e-07f,
0.904004f,0.295102f,-0.0352696f,0.108077f,1.0f,6.80071e-07f, 0.890235f,0.313181f,-0.0374264f,0.106425f,1.0f,1.22605e-06f,
0.875602f,0.330637f,-0.0395109f,0.104677f,1.0f,2.14729e-06f, 0.860132f,0.347425f,-0.0415142f,0.102825f,1.0f,3.66224e-06f,
0.844009f,0.363589f,-0.0434389f,0.100889f,1.0f,6.09552e-06f, 0.826967f,0.378956f,-0.0452715f,0.0988502f,1.0f,9.92018e-06f,
0.809311f,0.393619f,-0.0470164f,0.0967328f,1.0f,1.58134e-05f, 0.79089f,0.407457f,-0.0486658f,0.0945318f,1.0f,2.47286e-05f,
0.771809f,0.420471f,-0.0502131f,0.092246f,1.0f,3.79888e-05f, 0.752092f,0.432627f,-0.0516589f,0.0898881f,1.0f,5.74038e-05f,
0.73174f,0.443869f,-0.0529964f,0.087457f,1.0f,8.5418e-05f, 0.710805f,0.454164f,-0.0542214f,0.0849564f,1.0f,0.000125295f,
0.689476f,0.4636f,-0.055337f,0.0824008f,1.0f,0.000181342f, 0.667547f,0.471979f,-0.0563286f,0.0797783f,1.0f,0.000259191f,
0.645157f,0.479336f,-0.0572007f,0.0771054f,1.0f,0.000366128f, 0.622421f,0.485702f,-0.0579506f,0.0743873f,1.0f,0.000511503f,
0.599241f,0.490941f,-0.0585668f,0.0716185f,1.0f,0.000707209f, 0.575814f,0.495146f,-0.059059f,0.0688198f,1.0f,0.000968261f,
0.55208f,0.498214f,-0.0594156f,0.0659861f,1.0f,0.00131347f, 0.528114f,0.500146f,-0.0596359f,0.0631252f,1.0f,0.00176624f,
0.503933f,0.500883f,-0.0597143f,0.0602401f,1.0f,0.00235552f, 0.479705f,0.500532f,-0.0596577f,0.0573458f,1.0f,0.00311683f,
0.455351f,0.498929f,-0.0594577f,0.0544422f,1.0f,0.00409358f, 0.430972f,0.496125f,-0.0591109f,0.0515342f,1.0f,0.00533849f,
0.406638f,0.49211f,-0.0586207f,0.048633f,1.0f,0.00691522f, 0.382384f,0.486851f,-0.0579831f,0.0457429f,1.0f,0.00890025f,
0.358311f,0.480394f,-0.0571993f,0.0428727f,1.0f,0.0113851f, 0.334427f,0.472665f,-0.0562635f,0.0400258f,1.0f,0.0144785f,
0.310798f,0.46366f,-0.055179f,0.0372123f,1.0f,0.0183095f, 0.287522f,0.453428f,-0.0539468f,0.0344407f,1.0f,0.0230302f,
0.26465f,0.441953f,-0.0525639f,0.0317164f,1.0f,0.028819f, 0.24221f,0.42917f,-0.0510292f,0.0290466f,1.0f,0.0358845f,
0.220323f,0.415178f,-0.0493469f,0.0264414f,1.0f,0.0444696f, 0.199061f,0.399997f,-0.0475211f,0.0239106f,1.0f,0.0548554f,
0.178443f,0.38354f,-0.0455456f,0.0214585f,1.0f,0.0673661f, 0.158569f,0.365873f,-0.0434253f,0.0190953f,1.0f,0.0823733f,
0.139509f,0.347012f,-0.0411626f,0.0168299f,0.999999f,0.1003f, 0.121354f,0.327013f,-0.0387616f,0.0146717f,0.999992f,0.121624f,
0.104165f,0.305883f,-0.0362243f,0.0126296f,0.999951f,0.146872f, 0.0880388f,0.283706f,-0.0335528f,0.0107134f,0.999743f,0.17658f,
0.0730346f,0.260473f,-0.0307399f,0.00893319f,0.99882f,0.211118f, 0.059263f,0.236352f,-0.027766f,0.00730607f,0.995121f,0.249953f,
0.0468822f,0.211732f,-0.0247038f,0.00583515f,0.990904f,0.294597f, 0.0360628f,0.18724f,-0.0215355f,0.00454425f,0.981522f,0.342581f,
0.0270176f,0.163956f,-0.0183456f,0.00344255f,0.966834f,0.393065f, 0.0197228f,0.142095f,-0.015244f,0.00253999f,0.946664f,0.444299f,
0.0145843f,0.125103f,-0.0123859f,0.00183755f,0.925164f,0.496466f, 0.0109503f,0.110158f,-0.00977514f,0.0013024f,0.913608f,0.554952f,
0.00723754f,0.0866646f,-0.00704873f,0.000857793f,0.930715f,0.633174f, 0.0042284f,0.0593517f,-0.00445039f,0.000509271f,0.99702f,0.748787f,
1.00002f,-2.21494e-06f,-1.40918e-20f,0.134937f,1.0f,1.11475e-11f, 0.999537f,0.0224418f,-0.00303043f,0.134977f,1.0f,1.55366e-11f,
0.998f,0.0448402f,-0.00605475f,0.134766f,1.0f,4.24109e-11f, 0.995457f,0.0671506f,-0.0090676f,0.134424f,1.0f,1.24145e-10f,
0.991987f,0.0893423f,-0.0120638f,0.133956f,1.0f,3.52189e-10f, 0.987467f,0.111357f,-0.0150361f,0.133344f,1.0f,9.48597e-10f,
0.981988f,0.133166f,-0.0179798f,0.132599f,1.0f,2.4176e-09f, 0.975557f,0.154723f,-0.02089f,0.13173f,1.0f,5.83895e-09f,
0.968203f,0.175994f,-0.02376f,0.130727f,1.0f,1.34052e-08f, 0.959759f,0.196909f,-0.0265831f,0.129589f,1.0f,2.93597e-08f,
0.950469f,0.217472f,-0.0293559f,0.128328f,1.0f,6.15645e-08f, 0.940224f,0.237606f,-0.0320715f,0.12694f,1.0f,1.24024e-07f,
0.929125f,0.257303f,-0.034727f,0.125437f,1.0f,2.40808e-07f, 0.917042f,0.27648f,-0.037313f,0.123805f,1.0f,4.51981e-07f,
0.904059f,0.295106f,-0.039824f,0.122049f,1.0f,8.22293e-07f, 0.890328f,0.313197f,-0.0422608f,0.12019f,1.0f,1.45367e-06f,
0.87575f,0.330669f,-0.0446119f,0.118211f,1.0f,2.5027e-06f, 0.860312f,0.347476f,-0.0468749f,0.116125f,1.0f,4.20475e-06f,
0.844125f,0.363612f,-0.0490443f,0.113932f,1.0f,6.90653e-06f, 0.827149f,0.379009f,-0.0511176f,0.111643f,1.0f,1.11094e-05f,
0.809491f,0.393671f,-0.0530847f,0.109248f,1.0f,1.75265e-05f, 0.791061f,0.407504f,-0.0549449f,0.106762f,1.0f,2.71559e-05f,
0.772001f,0.420522f,-0.0566919f,0.104184f,1.0f,4.13752e-05f, 0.752332f,0.432706f,-0.0583236f,0.101524f,1.0f,6.20608e-05f,
0.732003f,0.44396f,-0.0598331f,0.0987812f,1.0f,9.17364e-05f, 0.711141f,0.454308f,-0.0612176f,0.0959635f,1.0f,0.000133759f,
0.68973f,0.463686f,-0.0624717f,0.0930734f,1.0f,0.000192546f, 0.667812f,0.472072f,-0.0635914f,0.0901165f,1.0f,0.000273853f,
0.6455f,0.479482f,-0.064576f,0.0871025f,1.0f,0.000385109f, 0.622771f,0.485852f,-0.0654222f,0.0840369f,1.0f,0.000535823f,
0.599646f,0.491141f,-0.0661195f,0.0809166f,1.0f,0.000738064f, 0.576245f,0.495368f,-0.066672f,0.077757f,1.0f,0.00100704f,
0.552462f,0.498397f,-0.0670705f,0.0745571f,1.0f,0.00136175f, 0.528556f,0.500381f,-0.0673224f,0.0713347f,1.0f,0.00182581f,
0.504431f,0.501177f,-0.0674117f,0.0680822f,1.0f,0.00242837f, 0.48016f,0.500784f,-0.0673438f,0.0648148f,1.0f,0.00320516f,
0.455845f,0.499228f,-0.0671174f,0.0615401f,1.0f,0.00419974f, 0.431533f,0.496504f,-0.0667317f,0.0582664f,1.0f,0.00546496f,
0.407184f,0.492474f,-0.0661767f,0.0549935f,1.0f,0.00706454f, 0.38293f,0.487223f,-0.0654548f,0.051733f,1.0f,0.00907493f,
0.358858f,0.480773f,-0.064568f,0.0484952f,1.0f,0.0115874f, 0.335004f,0.473088f,-0.0635141f,0.0452869f,1.0f,0.0147105f,
0.311416f,0.464159f,-0.0622956f,0.0421184f,1.0f,0.0185724f, 0.288148f,0.45395f,-0.0609038f,0.0389924f,1.0f,0.0233243f,
0.265258f,0.442461f,-0.0593419f,0.0359199f,1.0f,0.0291432f, 0.242878f,0.429807f,-0.0576193f,0.032915f,1.0f,0.0362355f,
0.220991f,0.415833f,-0.0557209f,0.0299775f,1.0f,0.0448412f, 0.199716f,0.400648f,-0.0536589f,0.0271229f,1.0f,0.0552372f,
0.179129f,0.384288f,-0.0514346f,0.0243603f,0.999999f,0.0677418f, 0.159265f,0.36668f,-0.0490464f,0.0216974f,0.999996f,0.0827183f,
0.140217f,0.347896f,-0.0464975f,0.0191448f,0.999977f,0.100576f, 0.122062f,0.327949f,-0.0437896f,0.0167125f,0.999893f,0.121761f,
0.104901f,0.306961f,-0.0409264f,0.014413f,0.999567f,0.146716f, 0.0887771f,0.284871f,-0.037897f,0.0122578f,0.998405f,0.175721f,
0.0738113f,0.261853f,-0.0346763f,0.0102647f,0.994691f,0.208398f, 0.0601482f,0.238243f,-0.0313661f,0.00843549f,0.991175f,0.246452f,
0.0479044f,0.214318f,-0.0279129f,0.00679635f,0.983529f,0.287934f, 0.037384f,0.191312f,-0.0244003f,0.00535974f,0.971735f,0.332494f,
0.02867f,0.169856f,-0.0209372f,0.00414134f,0.955383f,0.379026f, 0.0219093f,0.151398f,-0.0176263f,0.00314117f,0.936112f,0.426976f,
0.0165086f,0.133358f,-0.0145169f,0.00234025f,0.919003f,0.47767f, 0.0126531f,0.11819f,-0.0115733f,0.00170224f,0.914072f,0.536493f,
0.00882437f,0.0950745f,-0.00859417f,0.00117051f,0.935518f,0.614108f, 0.00537493f,0.0668182f,-0.00564891f,0.000729662f,0.99736f,0.722594f,
0.999951f,2.59507e-08f,3.7927e-20f,0.151329f,1.0f,3.41362e-11f, 0.999529f,0.0224431f,-0.00339853f,0.151374f,1.0f,4.35343e-11f,
0.998017f,0.0448354f,-0.00679052f,0.151144f,1.0f,1.03653e-10f, 0.995498f,0.067159f,-0.0101695f,0.150763f,1.0f,2.70344e-10f,
0.992035f,0.0893454f,-0.0135298f,0.150238f,1.0f,6.95975e-10f, 0.987517f,0.111363f,-0.0168635f,0.149553f,1.0f,1.72533e-09f,
0.981949f,0.133158f,-0.0201637f,0.148711f,1.0f,4.09444e-09f, 0.975664f,0.15474f,-0.0234284f,0.147743f,1.0f,9.29845e-09f,
0.968185f,0.175992f,-0.0266461f,0.146614f,1.0f,2.02405e-08f, 0.959841f,0.196927f,-0.0298125f,0.145342f,1.0f,4.23295e-08f,
0.95053f,0.217481f,-0.0329212f,0.143925f,1.0f,8.52698e-08f, 0.940314f,0.237624f,-0.0359675f,0.142374f,1.0f,1.6588e-07f,
0.929134f,0.257296f,-0.0389417f,0.140676f,1.0f,3.12404e-07f, 0.917163f,0.276497f,-0.0418422f,0.138851f,1.0f,5.70919e-07f,
0.904219f,0.295146f,-0.0446595f,0.136889f,1.0f,1.01464e-06f, 0.89049f,0.313235f,-0.0473916f,0.134805f,1.0f,1.75714e-06f,
0.875859f,0.330692f,-0.0500265f,0.132585f,1.0f,2.97068e-06f, 0.860484f,0.347522f,-0.0525638f,0.130248f,1.0f,4.91137e-06f,
0.844258f,0.363635f,-0.0549938f,0.127786f,1.0f,7.95285e-06f, 0.827314f,0.379046f,-0.0573153f,0.125215f,1.0f,1.2631e-05f,
0.809645f,0.393695f,-0.0595225f,0.122537f,1.0f,1.9702e-05f, 0.79133f,0.407585f,-0.061609f,0.119754f,1.0f,3.0218e-05f,
0.772259f,0.420605f,-0.0635679f,0.116868f,1.0f,4.56223e-05f, 0.752636f,0.432808f,-0.0653954f,0.113886f,1.0f,6.78706e-05f,
0.732344f,0.444083f,-0.0670866f,0.110813f,1.0f,9.95815e-05f, 0.711458f,0.454412f,-0.0686355f,0.107652f,1.0f,0.000144223f,
0.690115f,0.463841f,-0.0700433f,0.104419f,1.0f,0.000206343f, 0.668231f,0.472246f,-0.0712971f,0.101106f,1.0f,0.000291844f,
0.645891f,0.479648f,-0.0723989f,0.0977282f,1.0f,0.000408326f, 0.623205f,0.48605f,-0.0733471f,0.0942953f,1.0f,0.000565483f,
0.600114f,0.491354f,-0.074129f,0.0908019f,1.0f,0.000775589f, 0.576682f,0.49556f,-0.0747442f,0.0872595f,1.0f,0.00105407f,
0.553016f,0.498693f,-0.0751959f,0.0836825f,1.0f,0.00142017f, 0.529046f,0.500628f,-0.0754702f,0.0800662f,1.0f,0.00189774f,
0.504992f,0.501493f,-0.0755768f,0.0764315f,1.0f,0.00251615f, 0.48073f,0.501106f,-0.0754953f,0.0727681f,1.0f,0.00331137f,
0.456452f,0.499601f,-0.0752463f,0.0691065f,1.0f,0.00432715f, 0.432107f,0.496837f,-0.074806f,0.0654343f,1.0f,0.00561646f,
0.407836f,0.492911f,-0.0741882f,0.0617741f,1.0f,0.00724309f, 0.383609f,0.487704f,-0.0733823f,0.0581266f,1.0f,0.0092834f,
0.359564f,0.481294f,-0.072388f,0.0545015f,1.0f,0.0118285f, 0.335721f,0.473636f,-0.0712097f,0.0509118f,1.0f,0.0149863f,
0.312131f,0.464716f,-0.0698382f,0.0473607f,1.0f,0.0188844f, 0.288894f,0.454568f,-0.0682834f,0.0438646f,1.0f,0.0236726f,
0.266028f,0.443137f,-0.0665361f,0.0404268f,1.0f,0.0295261f, 0.243642f,0.43049f,-0.0646041f,0.037062f,1.0f,0.036649f,
0.221792f,0.416612f,-0.0624824f,0.0337765f,0.999999f,0.0452772f, 0.200524f,0.401476f,-0.060176f,0.030583f,0.999997f,0.0556827f,
0.179932f,0.385135f,-0.0576851f,0.0274911f,0.999985f,0.0681752f, 0.160086f,0.367614f,-0.0550104f,0.0245114f,0.999939f,0.0831021f,
0.141062f,0.348926f,-0.0521589f,0.021658f,0.999781f,0.100837f, 0.122939f,0.329133f,-0.04912f,0.0189401f,0.99928f,0.121734f,
0.105778f,0.308212f,-0.0458837f,0.0163737f,0.997783f,0.145979f, 0.0897249f,0.286418f,-0.0424502f,0.0139788f,0.994394f,0.173536f,
0.0748598f,0.263842f,-0.0388939f,0.011753f,0.990999f,0.205648f, 0.0614689f,0.241313f,-0.0351894f,0.00973243f,0.984356f,0.241065f,
0.0501737f,0.221209f,-0.0314771f,0.00794676f,0.974371f,0.279645f, 0.0392795f,0.197105f,-0.0275593f,0.00633872f,0.96098f,0.320937f,
0.0307813f,0.176951f,-0.023831f,0.00499227f,0.944599f,0.364296f, 0.0242737f,0.160086f,-0.0203035f,0.00388156f,0.927538f,0.409786f,
0.0189039f,0.143079f,-0.0168751f,0.00295755f,0.915174f,0.459449f, 0.0143212f,0.123719f,-0.0135893f,0.00220111f,0.91582f,0.51815f,
0.0106701f,0.103849f,-0.0103918f,0.00157581f,0.940096f,0.59422f, 0.00673886f,0.0746919f,-0.00707173f,0.00102398f,0.997644f,0.695907f,
1.00003f,-2.44545e-07f,-1.743e-21f,0.168693f,1.0f,9.78632e-11f, 0.999486f,0.0224411f,-0.00378825f,0.168734f,1.0f,1.16384e-10f,
0.998001f,0.044841f,-0.00756927f,0.168479f,1.0f,2.46478e-10f, 0.995519f,0.0671528f,-0.0113356f,0.168051f,1.0f,5.80364e-10f,
0.991967f,0.0893412f,-0.0150801f,0.167455f,1.0f,1.36947e-09f, 0.987565f,0.111365f,-0.0187971f,0.166705f,1.0f,3.14851e-09f,
0.982049f,0.133167f,-0.0224764f,0.165773f,1.0f,6.99684e-09f, 0.975595f,0.154725f,-0.0261125f,0.164677f,1.0f,1.50022e-08f,
0.968262f,0.176004f,-0.0297f,0.163428f,1.0f,3.10503e-08f, 0.95988f,0.196929f,-0.0332298f,0.162014f,1.0f,6.21211e-08f,
0.950577f,0.217484f,-0.0366935f,0.160432f,1.0f,1.20348e-07f, 0.940404f,0.237634f,-0.0400897f,0.158709f,1.0f,2.26197e-07f,
0.929273f,0.257324f,-0.0434035f,0.156815f,1.0f,4.13236e-07f, 0.917258f,0.276511f,-0.0466363f,0.154784f,1.0f,7.35123e-07f,
0.904395f,0.295183f,-0.0497756f,0.152598f,1.0f,1.27563e-06f, 0.890589f,0.31324f,-0.0528164f,0.150267f,1.0f,2.1627e-06f,
0.876085f,0.330744f,-0.0557565f,0.147806f,1.0f,3.58784e-06f, 0.860687f,0.347565f,-0.0585823f,0.1452f,1.0f,5.8324e-06f,
0.844484f,0.36369f,-0.0612906f,0.142461f,1.0f,9.30263e-06f, 0.827603f,0.379133f,-0.0638787f,0.139602f,1.0f,1.45758e-05f,
0.809926f,0.393783f,-0.0663324f,0.136609f,1.0f,2.24602e-05f, 0.791583f,0.407649f,-0.0686554f,0.133509f,1.0f,3.4072e-05f,
0.772631f,0.420734f,-0.0708407f,0.130302f,1.0f,5.09328e-05f, 0.752913f,0.432883f,-0.072873f,0.126976f,1.0f,7.50924e-05f,
0.732684f,0.444191f,-0.0747548f,0.123553f,1.0f,0.000109281f, 0.711893f,0.454583f,-0.0764849f,0.120043f,1.0f,0.000157099f,
0.690537f,0.463999f,-0.0780465f,0.116435f,1.0f,0.000223245f, 0.668667f,0.472417f,-0.0794432f,0.112749f,1.0f,0.000313797f,
0.6464f,0.479867f,-0.080672f,0.108993f,1.0f,0.000436549f, 0.623711f,0.48627f,-0.0817242f,0.105168f,1.0f,0.000601415f,
0.600639f,0.491595f,-0.0825951f,0.101282f,1.0f,0.000820908f, 0.577269f,0.495849f,-0.0832801f,0.0973407f,1.0f,0.00111071f,
0.553586f,0.498965f,-0.0837796f,0.0933574f,1.0f,0.00149033f, 0.529716f,0.500998f,-0.0840895f,0.0893394f,1.0f,0.00198389f,
0.505634f,0.501835f,-0.0842037f,0.0852915f,1.0f,0.00262104f, 0.481411f,0.501497f,-0.0841168f,0.0812202f,1.0f,0.00343798f,
0.457136f,0.49999f,-0.083831f,0.0771393f,1.0f,0.00447868f, 0.432842f,0.497292f,-0.0833471f,0.0730606f,1.0f,0.00579626f,
0.408566f,0.493362f,-0.0826539f,0.0689851f,1.0f,0.00745452f, 0.384423f,0.488267f,-0.0817603f,0.0649312f,1.0f,0.00952976f,
0.360366f,0.481855f,-0.0806511f,0.0608977f,1.0f,0.0121127f, 0.336566f,0.474273f,-0.0793407f,0.0569066f,1.0f,0.0153108f,
0.312975f,0.465364f,-0.0778142f,0.0529575f,1.0f,0.0192505f, 0.289743f,0.455243f,-0.0760836f,0.0490695f,1.0f,0.0240803f,
0.266935f,0.443921f,-0.0741408f,0.0452478f,0.999999f,0.0299731f, 0.244565f,0.431327f,-0.0719921f,0.0415069f,0.999997f,0.0371295f,
0.222723f,0.417486f,-0.0696327f,0.0378548f,0.999987f,0.0457805f, 0.201487f,0.40245f,-0.0670695f,0.0343061f,0.999955f,0.0561886f,
0.180902f,0.386168f,-0.0642933f,0.0308681f,0.999857f,0.0686452f, 0.161082f,0.368742f,-0.0613151f,0.0275596f,0.999579f,0.0834557f,
0.14208f,0.350166f,-0.0581244f,0.0243928f,0.998828f,0.100891f, 0.123999f,0.330545f,-0.0547031f,0.0213855f,0.996883f,0.121047f,
0.106898f,0.309874f,-0.0510782f,0.0185486f,0.993951f,0.144293f, 0.0909802f,0.288557f,-0.0472995f,0.0158932f,0.990479f,0.171232f,
0.0763354f,0.266786f,-0.0433389f,0.0134468f,0.984504f,0.201254f, 0.0634177f,0.245985f,-0.0393188f,0.0112409f,0.975966f,0.234386f,
0.0517649f,0.224723f,-0.0351497f,0.00924547f,0.964613f,0.270333f, 0.0426608f,0.208326f,-0.0311544f,0.00753592f,0.950584f,0.308693f,
0.0336859f,0.186469f,-0.0271008f,0.00603374f,0.935115f,0.349343f, 0.0275496f,0.172007f,-0.0233969f,0.00480642f,0.921125f,0.393008f,
0.0220575f,0.155344f,-0.0196903f,0.00375013f,0.91328f,0.441718f, 0.0168088f,0.133493f,-0.0159889f,0.00284433f,0.918349f,0.499725f,
0.0127934f,0.112937f,-0.0124597f,0.0020935f,0.944329f,0.573584f, 0.00834353f,0.0829625f,-0.00874314f,0.00141048f,0.997884f,0.668895f,
1.00001f,1.55698e-06f,5.88272e-20f,0.187004f,1.0f,2.64232e-10f, 0.99949f,0.022438f,-0.00419944f,0.18705f,1.0f,2.97379e-10f,
0.998018f,0.0448375f,-0.0083913f,0.186778f,1.0f,5.69732e-10f, 0.995505f,0.0671573f,-0.0125665f,0.186303f,1.0f,1.22508e-09f,
0.991993f,0.0893381f,-0.0167175f,0.185642f,1.0f,2.67327e-09f, 0.98755f,0.111359f,-0.0208373f,0.184806f,1.0f,5.73994e-09f,
0.982106f,0.13318f,-0.0249165f,0.183777f,1.0f,1.20096e-08f, 0.975674f,0.15473f,-0.0289477f,0.182567f,1.0f,2.44123e-08f,
0.968253f,0.176006f,-0.0329228f,0.181174f,1.0f,4.81887e-08f, 0.959949f,0.196941f,-0.0368358f,0.17961f,1.0f,9.24314e-08f,
0.950715f,0.217505f,-0.0406771f,0.177868f,1.0f,1.72472e-07f, 0.940551f,0.23766f,-0.044439f,0.17595f,1.0f,3.13489e-07f,
0.929323f,0.257321f,-0.0481108f,0.173849f,1.0f,5.55825e-07f, 0.917388f,0.276531f,-0.0516929f,0.171597f,1.0f,9.62663e-07f,
0.904462f,0.29518f,-0.0551703f,0.169172f,1.0f,1.63088e-06f, 0.890808f,0.313296f,-0.0585421f,0.166597f,1.0f,2.70611e-06f,
0.876268f,0.330786f,-0.0617989f,0.16387f,1.0f,4.40331e-06f, 0.860923f,0.347628f,-0.0649298f,0.160983f,1.0f,7.03439e-06f,
0.844746f,0.363759f,-0.0679306f,0.157951f,1.0f,1.10448e-05f, 0.827833f,0.379182f,-0.0707964f,0.154782f,1.0f,1.70615e-05f,
0.810244f,0.393863f,-0.0735171f,0.151475f,1.0f,2.59544e-05f, 0.791963f,0.407768f,-0.0760902f,0.148042f,1.0f,3.89158e-05f,
0.772963f,0.420823f,-0.0785041f,0.14448f,1.0f,5.75595e-05f, 0.753352f,0.433038f,-0.080761f,0.140809f,1.0f,8.4046e-05f,
0.733115f,0.444344f,-0.0828436f,0.137018f,1.0f,0.000121237f, 0.712378f,0.454761f,-0.0847584f,0.133132f,1.0f,0.000172885f,
0.691065f,0.464211f,-0.0864891f,0.129141f,1.0f,0.000243865f, 0.669203f,0.472633f,-0.0880326f,0.125058f,1.0f,0.000340458f,
0.646995f,0.48012f,-0.089395f,0.120905f,1.0f,0.000470684f, 0.624279f,0.486497f,-0.0905547f,0.116666f,1.0f,0.000644708f,
0.601258f,0.49187f,-0.0915167f,0.112364f,1.0f,0.000875316f, 0.577888f,0.496127f,-0.0922752f,0.108005f,1.0f,0.00117848f,
0.554257f,0.49929f,-0.0928261f,0.103597f,1.0f,0.00157401f, 0.530431f,0.501354f,-0.0931686f,0.0991526f,1.0f,0.00208635f,
0.506389f,0.502235f,-0.0932948f,0.0946758f,1.0f,0.00274544f, 0.482223f,0.501951f,-0.0931984f,0.0901734f,1.0f,0.00358774f,
0.45796f,0.50047f,-0.0928818f,0.0856606f,1.0f,0.00465746f, 0.433717f,0.497832f,-0.0923461f,0.0811504f,1.0f,0.00600785f,
0.409496f,0.493983f,-0.0915783f,0.0766435f,1.0f,0.00770273f, 0.385317f,0.488846f,-0.0905841f,0.0721573f,1.0f,0.00981823f,
0.361327f,0.482528f,-0.0893632f,0.0677029f,1.0f,0.0124447f, 0.337552f,0.474999f,-0.0879116f,0.0632894f,1.0f,0.0156888f,
0.313984f,0.46614f,-0.0862231f,0.058924f,0.999999f,0.0196758f, 0.290797f,0.456107f,-0.084309f,0.0546265f,0.999996f,0.0245521f,
0.267986f,0.444795f,-0.0821582f,0.0504014f,0.999986f,0.0304874f, 0.245647f,0.432291f,-0.0797817f,0.0462677f,0.999959f,0.0376767f,
0.223835f,0.418538f,-0.0771715f,0.0422329f,0.999886f,0.0463403f, 0.2026f,0.403534f,-0.0743254f,0.0383104f,0.999697f,0.056718f,
0.182071f,0.387407f,-0.0712458f,0.0345181f,0.999233f,0.0690519f, 0.162286f,0.370119f,-0.0679204f,0.030872f,0.998137f,0.0835342f,
0.143368f,0.35179f,-0.0643256f,0.0273932f,0.995635f,0.100183f, 0.125321f,0.332331f,-0.0605546f,0.0240788f,0.993329f,0.119837f,
0.108421f,0.312268f,-0.0565707f,0.0209607f,0.989642f,0.142313f, 0.0927132f,0.29167f,-0.052395f,0.0180569f,0.984186f,0.167645f,
0.0785984f,0.271613f,-0.0481244f,0.0154023f,0.976593f,0.195813f, 0.065412f,0.250148f,-0.0436411f,0.0129582f,0.966584f,0.226649f,
0.0543376f,0.231011f,-0.0392538f,0.0108059f,0.95454f,0.260119f, 0.0448907f,0.21303f,-0.0349226f,0.00891684f,0.940889f,0.295985f,
0.0370577f,0.196521f,-0.0307548f,0.00729412f,0.927317f,0.334517f, 0.0312077f,0.183998f,-0.0267879f,0.00591845f,0.916585f,0.376608f,
0.025576f,0.167533f,-0.0228312f,0.00472044f,0.912883f,0.424354f, 0.0196625f,0.143642f,-0.0187033f,0.00364381f,0.921354f,0.481173f,
0.015178f,0.121011f,-0.014782f,0.00273968f,0.948222f,0.55238f, 0.0102126f,0.0915743f,-0.0106874f,0.00191034f,0.998088f,0.641721f,
0.999994f,-6.6974e-06f,-1.57563e-20f,0.206294f,1.0f,6.75322e-10f, 0.999544f,0.0224447f,-0.00463283f,0.206356f,1.0f,7.27594e-10f,
0.997992f,0.0448425f,-0.00925636f,0.206036f,1.0f,1.27952e-09f, 0.995528f,0.0671592f,-0.0138626f,0.205522f,1.0f,2.53809e-09f,
0.992039f,0.0893432f,-0.0184422f,0.2048f,1.0f,5.16198e-09f, 0.987538f,0.111356f,-0.0229854f,0.203864f,1.0f,1.04171e-08f,
0.982134f,0.133177f,-0.027485f,0.202732f,1.0f,2.06256e-08f, 0.975709f,0.154734f,-0.0319323f,0.201403f,1.0f,3.99074e-08f,
0.968387f,0.176016f,-0.0363183f,0.199876f,1.0f,7.53656e-08f, 0.960031f,0.196951f,-0.0406313f,0.198137f,1.0f,1.38924e-07f,
0.950768f,0.217501f,-0.0448664f,0.196211f,1.0f,2.50113e-07f, 0.940583f,0.237658f,-0.0490157f,0.1941f,1.0f,4.40185e-07f,
0.929503f,0.257351f,-0.0530675f,0.191794f,1.0f,7.58082e-07f, 0.917547f,0.276561f,-0.0570183f,0.189314f,1.0f,1.27891e-06f,
0.904732f,0.295243f,-0.0608534f,0.186643f,1.0f,2.11576e-06f, 0.890988f,0.313326f,-0.0645681f,0.183797f,1.0f,3.43593e-06f,
0.876509f,0.330829f,-0.0681571f,0.180787f,1.0f,5.48284e-06f, 0.861128f,0.347655f,-0.0716082f,0.177606f,1.0f,8.60521e-06f,
0.845061f,0.363842f,-0.0749174f,0.174269f,1.0f,1.32954e-05f, 0.828164f,0.379265f,-0.0780735f,0.170772f,1.0f,2.02392e-05f,
0.810616f,0.393974f,-0.081077f,0.167139f,1.0f,3.03797e-05f, 0.792395f,0.407907f,-0.0839132f,0.163359f,1.0f,4.49984e-05f,
0.773397f,0.420963f,-0.0865725f,0.159434f,1.0f,6.58173e-05f, 0.753822f,0.433189f,-0.0890543f,0.155383f,1.0f,9.51255e-05f,
0.733627f,0.444518f,-0.0913504f,0.15121f,1.0f,0.000135936f, 0.712897f,0.454942f,-0.0934581f,0.146929f,1.0f,0.00019218f,
0.691607f,0.464397f,-0.0953652f,0.142536f,1.0f,0.000268935f, 0.669824f,0.472869f,-0.0970651f,0.138041f,1.0f,0.000372713f,
0.647624f,0.480357f,-0.0985584f,0.13346f,1.0f,0.000511793f, 0.625031f,0.486842f,-0.0998445f,0.128807f,1.0f,0.000696624f,
0.602054f,0.492241f,-0.100904f,0.124073f,1.0f,0.000940302f, 0.578677f,0.496496f,-0.101735f,0.119271f,1.0f,0.00125913f,
0.555127f,0.499732f,-0.102342f,0.114421f,1.0f,0.00167325f, 0.531303f,0.501801f,-0.102714f,0.109525f,1.0f,0.00220746f,
0.507352f,0.502779f,-0.102854f,0.104602f,1.0f,0.00289201f, 0.483169f,0.50249f,-0.102748f,0.0996491f,1.0f,0.00376366f,
0.458958f,0.501064f,-0.1024f,0.0946863f,1.0f,0.00486685f, 0.434731f,0.498453f,-0.101801f,0.0897172f,1.0f,0.00625495f,
0.410508f,0.494605f,-0.100954f,0.0847595f,1.0f,0.00799176f, 0.38639f,0.489549f,-0.0998641f,0.0798294f,0.999999f,0.0101532f,
0.362429f,0.483282f,-0.0985162f,0.0749283f,0.999998f,0.012829f, 0.3387f,0.475828f,-0.096922f,0.070078f,0.999994f,0.0161247f,
0.315153f,0.467021f,-0.0950605f,0.0652765f,0.999984f,0.0201637f, 0.292016f,0.457075f,-0.092953f,0.0605522f,0.999958f,0.0250888f,
0.269234f,0.445853f,-0.0905856f,0.0559096f,0.999893f,0.0310632f, 0.246893f,0.43336f,-0.0879585f,0.0513639f,0.999743f,0.0382684f,
0.225127f,0.419721f,-0.0850736f,0.0469334f,0.999407f,0.0468974f, 0.20401f,0.404985f,-0.0819247f,0.0426356f,0.998673f,0.0571325f,
0.183456f,0.388856f,-0.0784726f,0.0384789f,0.997115f,0.0690921f, 0.163833f,0.37195f,-0.0747517f,0.0344992f,0.994447f,0.0828962f,
0.144944f,0.353779f,-0.0708626f,0.0306768f,0.992484f,0.0994358f, 0.127161f,0.335024f,-0.0666955f,0.0270662f,0.988501f,0.118093f,
0.110459f,0.315582f,-0.0623328f,0.0236692f,0.983491f,0.139403f, 0.0957976f,0.29794f,-0.057893f,0.0205503f,0.976569f,0.163191f,
0.0814061f,0.277356f,-0.0531525f,0.0176242f,0.967701f,0.189478f, 0.0690393f,0.258681f,-0.0484806f,0.0150072f,0.957154f,0.218314f,
0.0582294f,0.240806f,-0.0438238f,0.0126683f,0.945071f,0.249524f, 0.0488221f,0.2234f,-0.039238f,0.0106023f,0.932506f,0.283249f,
0.0417236f,0.21038f,-0.0349087f,0.00883222f,0.921254f,0.31998f, 0.0339162f,0.189872f,-0.0302763f,0.00719443f,0.913756f,0.360655f,
0.0288542f,0.176588f,-0.0261949f,0.00587149f,0.913524f,0.407205f, 0.0228924f,0.154115f,-0.0217756f,0.00463232f,0.924666f,0.462545f,
0.0181304f,0.132768f,-0.0176188f,0.0035866f,0.95186f,0.530851f, 0.0123743f,0.100545f,-0.0129298f,0.00254803f,0.998264f,0.614539f,
0.999997f,6.30478e-07f,4.66352e-20f,0.22656f,1.0f,1.64086e-09f, 0.999544f,0.0224454f,-0.00508789f,0.226628f,1.0f,1.70782e-09f,
0.998006f,0.0448434f,-0.010166f,0.226287f,1.0f,2.79141e-09f, 0.995488f,0.0671544f,-0.0152237f,0.225706f,1.0f,5.15401e-09f,
0.992036f,0.0893378f,-0.0202535f,0.224921f,1.0f,9.838e-09f, 0.987634f,0.11137f,-0.0252432f,0.223899f,1.0f,1.87667e-08f,
0.982179f,0.133181f,-0.0301842f,0.222655f,1.0f,3.53286e-08f, 0.975835f,0.154756f,-0.0350682f,0.221198f,1.0f,6.53146e-08f,
0.968404f,0.176004f,-0.0398814f,0.219506f,1.0f,1.18373e-07f, 0.960161f,0.196965f,-0.0446212f,0.217619f,1.0f,2.10208e-07f,
0.950859f,0.21752f,-0.0492699f,0.215499f,1.0f,3.65841e-07f, 0.940724f,0.23768f,-0.0538234f,0.213174f,1.0f,6.24331e-07f,
0.929662f,0.257376f,-0.0582725f,0.210648f,1.0f,1.0455e-06f, 0.917737f,0.276591f,-0.0626098f,0.207929f,1.0f,1.71932e-06f,
0.904876f,0.295261f,-0.066818f,0.204995f,1.0f,2.77887e-06f, 0.891305f,0.313406f,-0.0709006f,0.201888f,1.0f,4.41788e-06f,
0.876735f,0.330872f,-0.074836f,0.198577f,1.0f,6.91416e-06f, 0.861497f,0.347756f,-0.0786259f,0.195094f,1.0f,1.06605e-05f,
0.84545f,0.363939f,-0.0822575f,0.191435f,1.0f,1.62051e-05f, 0.828671f,0.379414f,-0.0857211f,0.187601f,1.0f,2.43033e-05f,
0.810993f,0.394065f,-0.0890072f,0.183599f,1.0f,3.59839e-05f, 0.792842f,0.408026f,-0.0921209f,0.179459f,1.0f,5.26328e-05f,
0.773856f,0.421089f,-0.0950354f,0.175152f,1.0f,7.60973e-05f, 0.75438f,0.433366f,-0.0977615f,0.170719f,1.0f,0.000108815f,
0.734179f,0.444686f,-0.100276f,0.16614f,1.0f,0.000153976f, 0.713531f,0.455168f,-0.102586f,0.161447f,1.0f,0.00021571f,
0.692253f,0.464624f,-0.104671f,0.156625f,1.0f,0.000299331f, 0.670544f,0.473147f,-0.106541f,0.151708f,1.0f,0.000411609f,
0.648361f,0.480653f,-0.108176f,0.146687f,1.0f,0.000561119f, 0.625834f,0.487173f,-0.10958f,0.141584f,1.0f,0.000758628f,
0.60286f,0.492574f,-0.110742f,0.1364f,1.0f,0.00101758f, 0.579573f,0.496904f,-0.111652f,0.13114f,1.0f,0.00135463f,
0.556033f,0.500149f,-0.112315f,0.125828f,1.0f,0.00179033f, 0.532261f,0.502265f,-0.112721f,0.120468f,1.0f,0.0023498f,
0.508313f,0.503246f,-0.11287f,0.115073f,1.0f,0.00306366f, 0.484269f,0.503097f,-0.112758f,0.109656f,1.0f,0.003969f,
0.460102f,0.501732f,-0.112377f,0.104224f,1.0f,0.00511044f, 0.435885f,0.499136f,-0.111714f,0.0987803f,0.999999f,0.00654144f,
0.411753f,0.495398f,-0.110795f,0.0933625f,0.999997f,0.0083257f, 0.38766f,0.49039f,-0.109591f,0.0879597f,0.999992f,0.0105386f,
0.363757f,0.484216f,-0.108119f,0.0826015f,0.999979f,0.0132688f, 0.340005f,0.476735f,-0.106357f,0.0772853f,0.999951f,0.0166198f,
0.316561f,0.468093f,-0.104327f,0.0720418f,0.999888f,0.0207106f, 0.293436f,0.458189f,-0.102005f,0.0668716f,0.999754f,0.0256756f,
0.2707f,0.447061f,-0.0994005f,0.0617987f,0.999476f,0.0316615f, 0.248457f,0.434764f,-0.096499f,0.0568357f,0.998915f,0.038817f,
0.226691f,0.421174f,-0.0932846f,0.0520008f,0.997806f,0.0472685f, 0.205606f,0.406522f,-0.089744f,0.0473217f,0.995692f,0.0570772f,
0.185221f,0.390781f,-0.0859829f,0.0427988f,0.993725f,0.0687526f, 0.165717f,0.37418f,-0.0819714f,0.0384509f,0.991361f,0.0824474f,
0.147198f,0.356887f,-0.0776609f,0.0343232f,0.987157f,0.0979005f, 0.12954f,0.338535f,-0.0731348f,0.0303987f,0.982456f,0.115756f,
0.113831f,0.321624f,-0.0685147f,0.0267693f,0.976057f,0.135752f, 0.0981695f,0.301551f,-0.0635249f,0.0233183f,0.968052f,0.158003f,
0.0845983f,0.283326f,-0.0585954f,0.0202009f,0.958587f,0.182578f, 0.0736102f,0.268921f,-0.0537562f,0.0174084f,0.947846f,0.209457f,
0.0627183f,0.251154f,-0.048796f,0.0148524f,0.936501f,0.238748f, 0.0549374f,0.240016f,-0.0441979f,0.0126612f,0.925534f,0.270634f,
0.0463228f,0.2221f,-0.0393402f,0.0106271f,0.916723f,0.30574f, 0.038704f,0.203348f,-0.0345503f,0.00882682f,0.912261f,0.345062f,
0.0330498f,0.188145f,-0.0299837f,0.00727378f,0.914975f,0.390288f, 0.0264851f,0.164643f,-0.0251931f,0.00583526f,0.928062f,0.44383f,
0.0211986f,0.142367f,-0.0206127f,0.00459117f,0.955124f,0.509037f, 0.0148528f,0.109831f,-0.0154957f,0.00335149f,0.998415f,0.587494f,
0.999995f,-2.85521e-06f,1.73895e-21f,0.247823f,1.0f,3.80437e-09f, 0.999453f,0.0224423f,-0.0055648f,0.247874f,1.0f,3.85279e-09f,
0.998038f,0.0448359f,-0.0111197f,0.24752f,1.0f,5.91594e-09f, 0.995491f,0.0671523f,-0.0166521f,0.24689f,1.0f,1.02489e-08f,
0.992107f,0.0893452f,-0.0221533f,0.246028f,1.0f,1.84746e-08f, 0.987651f,0.111376f,-0.0276105f,0.244907f,1.0f,3.34838e-08f,
0.98222f,0.133188f,-0.0330149f,0.243551f,1.0f,6.01906e-08f, 0.975887f,0.154761f,-0.0383557f,0.241955f,1.0f,1.06712e-07f,
0.968485f,0.176023f,-0.0436208f,0.240113f,1.0f,1.86152e-07f, 0.96025f,0.196965f,-0.0488018f,0.23804f,1.0f,3.1924e-07f,
0.951003f,0.217537f,-0.0538846f,0.235721f,1.0f,5.38147e-07f, 0.94094f,0.23771f,-0.0588676f,0.233198f,1.0f,8.91921e-07f,
0.929915f,0.257427f,-0.063733f,0.230441f,1.0f,1.45408e-06f, 0.917982f,0.276642f,-0.0684696f,0.227452f,1.0f,2.33311e-06f,
0.90514f,0.295309f,-0.0730696f,0.224246f,1.0f,3.68661e-06f, 0.89157f,0.31344f,-0.0775317f,0.220851f,1.0f,5.7404e-06f,
0.877053f,0.330938f,-0.0818339f,0.217237f,1.0f,8.81365e-06f, 0.861853f,0.347826f,-0.0859734f,0.213429f,1.0f,1.33517e-05f,
0.845817f,0.364022f,-0.0899412f,0.209431f,1.0f,1.99688e-05f, 0.829063f,0.379503f,-0.0937279f,0.205251f,1.0f,2.9502e-05f,
0.811498f,0.3942f,-0.0973206f,0.200886f,1.0f,4.30801e-05f, 0.793328f,0.408149f,-0.100715f,0.196354f,1.0f,6.22099e-05f,
0.77449f,0.42128f,-0.103904f,0.191662f,1.0f,8.88834e-05f, 0.755001f,0.433561f,-0.106881f,0.186824f,1.0f,0.000125709f,
0.734891f,0.444925f,-0.109624f,0.181823f,1.0f,0.000176076f, 0.714278f,0.455419f,-0.112146f,0.176702f,1.0f,0.000244345f,
0.693047f,0.464917f,-0.114429f,0.171451f,1.0f,0.00033609f, 0.671399f,0.47348f,-0.116465f,0.166082f,1.0f,0.00045838f,
0.649268f,0.481023f,-0.11825f,0.160606f,1.0f,0.000620111f, 0.626789f,0.48758f,-0.119781f,0.155037f,1.0f,0.00083241f,
0.603855f,0.493015f,-0.121038f,0.149372f,1.0f,0.0011091f, 0.580673f,0.497425f,-0.122036f,0.143644f,1.0f,0.00146724f,
0.557141f,0.500679f,-0.122755f,0.137848f,1.0f,0.00192777f, 0.533414f,0.50284f,-0.123194f,0.132f,1.0f,0.00251623f,
0.509565f,0.503916f,-0.12336f,0.126125f,0.999999f,0.00326358f, 0.485541f,0.503788f,-0.12323f,0.120215f,0.999998f,0.00420719f,
0.461376f,0.502428f,-0.122802f,0.114285f,0.999995f,0.00539185f, 0.43727f,0.49996f,-0.122096f,0.108371f,0.999987f,0.00687091f,
0.413163f,0.496266f,-0.121083f,0.102461f,0.999972f,0.00870753f, 0.389123f,0.491329f,-0.119765f,0.0965754f,0.999939f,0.0109758f,
0.365263f,0.485219f,-0.118146f,0.0907339f,0.999872f,0.0137617f, 0.341599f,0.47788f,-0.116224f,0.0849526f,0.99974f,0.0171631f,
0.318143f,0.469237f,-0.11398f,0.0792374f,0.999488f,0.0212885f, 0.295076f,0.459443f,-0.111422f,0.0736171f,0.999011f,0.0262519f,
0.272448f,0.448503f,-0.108534f,0.0681075f,0.998129f,0.0321606f, 0.250251f,0.4363f,-0.105288f,0.0627264f,0.996532f,0.0390923f,
0.228652f,0.423025f,-0.101718f,0.0574951f,0.994316f,0.0472044f, 0.207668f,0.40863f,-0.0979474f,0.0524057f,0.992736f,0.0570353f,
0.187601f,0.393537f,-0.0938423f,0.0475127f,0.989917f,0.0683203f, 0.168118f,0.377063f,-0.0894172f,0.0428196f,0.98596f,0.0812277f,
0.149956f,0.36058f,-0.0847802f,0.0383652f,0.981113f,0.0960198f, 0.133481f,0.344989f,-0.0800367f,0.0342042f,0.975145f,0.112771f,
0.116628f,0.325553f,-0.0748295f,0.0301923f,0.967803f,0.1315f, 0.102715f,0.309953f,-0.0697462f,0.0265659f,0.959192f,0.152296f,
0.0892604f,0.29233f,-0.0645301f,0.0232037f,0.949613f,0.175273f, 0.0791059f,0.280407f,-0.0595357f,0.0202228f,0.939258f,0.20041f,
0.0686218f,0.264465f,-0.054376f,0.0174619f,0.929076f,0.227992f, 0.0590036f,0.247633f,-0.0492556f,0.0149763f,0.920018f,0.258278f,
0.0496623f,0.227506f,-0.0438822f,0.0126587f,0.913642f,0.291897f, 0.0439213f,0.216487f,-0.0392077f,0.0107606f,0.911867f,0.329836f,
0.0376621f,0.200096f,-0.034191f,0.00896134f,0.916913f,0.373527f, 0.0304769f,0.175295f,-0.0289902f,0.00729108f,0.931402f,0.425067f,
0.0247119f,0.152563f,-0.0239971f,0.00582741f,0.958066f,0.487125f, 0.0176761f,0.119438f,-0.0184097f,0.00435218f,0.998547f,0.560722f,
0.999985f,-6.62888e-06f,2.62237e-20f,0.270077f,1.0f,8.44405e-09f, 0.999543f,0.0224355f,-0.00606492f,0.270155f,1.0f,8.36886e-09f,
0.997988f,0.0448374f,-0.0121174f,0.269732f,1.0f,1.21826e-08f, 0.995504f,0.0671498f,-0.0181469f,0.26906f,1.0f,1.99448e-08f,
0.992182f,0.089353f,-0.0241428f,0.268133f,1.0f,3.41397e-08f, 0.987722f,0.111374f,-0.0300894f,0.26691f,1.0f,5.90607e-08f,
0.982262f,0.133181f,-0.0359781f,0.26543f,1.0f,1.01778e-07f, 0.975939f,0.15476f,-0.0417959f,0.263682f,1.0f,1.73617e-07f,
0.968603f,0.176031f,-0.047535f,0.261691f,1.0f,2.92342e-07f, 0.960321f,0.196975f,-0.053177f,0.25942f,1.0f,4.85313e-07f,
0.951172f,0.217555f,-0.0587184f,0.256914f,1.0f,7.93965e-07f, 0.941052f,0.237724f,-0.0641425f,0.254151f,1.0f,1.28007e-06f,
0.930105f,0.257441f,-0.0694421f,0.25115f,1.0f,2.03434e-06f, 0.918209f,0.27668f,-0.0746037f,0.247907f,1.0f,3.18813e-06f,
0.905456f,0.29537f,-0.0796138f,0.244419f,1.0f,4.92904e-06f, 0.891835f,0.313482f,-0.0844672f,0.240709f,1.0f,7.5217e-06f,
0.87745f,0.331024f,-0.0891529f,0.236781f,1.0f,1.13348e-05f, 0.862237f,0.347904f,-0.0936594f,0.232637f,1.0f,1.6876e-05f,
0.846247f,0.364108f,-0.0979796f,0.228291f,1.0f,2.48371e-05f, 0.82957f,0.379627f,-0.102103f,0.223748f,1.0f,3.61507e-05f,
0.81209f,0.394369f,-0.106014f,0.219004f,1.0f,5.20616e-05f, 0.793935f,0.408317f,-0.109707f,0.214073f,1.0f,7.42159e-05f,
0.77513f,0.421469f,-0.113174f,0.208969f,1.0f,0.000104771f, 0.755692f,0.433767f,-0.116405f,0.203697f,1.0f,0.00014653f,
0.735694f,0.4452f,-0.119401f,0.19828f,1.0f,0.000203107f, 0.71506f,0.455677f,-0.122134f,0.192699f,1.0f,0.000279123f,
0.693996f,0.465265f,-0.124618f,0.186997f,1.0f,0.000380445f, 0.672338f,0.473828f,-0.126825f,0.181153f,1.0f,0.000514468f,
0.650279f,0.481411f,-0.128769f,0.17521f,1.0f,0.00069045f, 0.627812f,0.487983f,-0.130422f,0.169149f,1.0f,0.00091991f,
0.605011f,0.493505f,-0.131799f,0.163011f,1.0f,0.00121708f, 0.581822f,0.497919f,-0.132876f,0.156783f,0.999999f,0.00159945f,
0.558424f,0.501282f,-0.133657f,0.150491f,0.999998f,0.00208838f, 0.534747f,0.503492f,-0.134134f,0.144145f,0.999996f,0.00270979f,
0.510917f,0.504591f,-0.134302f,0.137757f,0.99999f,0.00349496f, 0.486968f,0.504532f,-0.134161f,0.131346f,0.99998f,0.00448138f,
0.462894f,0.503267f,-0.133696f,0.124915f,0.999959f,0.00571367f, 0.438843f,0.500876f,-0.132917f,0.118492f,0.999919f,0.00724446f,
0.414789f,0.49725f,-0.131808f,0.112082f,0.999844f,0.00913512f, 0.390801f,0.492379f,-0.130361f,0.105698f,0.999706f,0.0114561f,
0.367014f,0.486374f,-0.128587f,0.0993706f,0.999459f,0.0142861f, 0.343398f,0.479112f,-0.126462f,0.0931054f,0.99902f,0.0177098f,
0.320082f,0.470678f,-0.123977f,0.086925f,0.998253f,0.0218104f, 0.297064f,0.460968f,-0.121112f,0.0808496f,0.996943f,0.026659f,
0.274488f,0.450119f,-0.117862f,0.0749055f,0.994889f,0.0323207f, 0.252599f,0.438447f,-0.114406f,0.0690929f,0.993427f,0.0392256f,
0.230977f,0.425192f,-0.110588f,0.0634258f,0.991416f,0.0473287f, 0.210574f,0.411841f,-0.106427f,0.0579738f,0.988149f,0.0565914f,
0.190386f,0.396607f,-0.101951f,0.052695f,0.984489f,0.067383f, 0.171684f,0.381721f,-0.0972393f,0.0476875f,0.979558f,0.0796178f,
0.154446f,0.367274f,-0.0923924f,0.0429636f,0.973891f,0.0935929f, 0.136556f,0.348754f,-0.0870196f,0.0383654f,0.967081f,0.109291f,
0.121477f,0.333444f,-0.0817398f,0.0341681f,0.9592f,0.12681f, 0.108981f,0.321485f,-0.0765282f,0.0303327f,0.950501f,0.146282f,
0.094839f,0.302529f,-0.0709494f,0.0266789f,0.94112f,0.167736f, 0.0838525f,0.288518f,-0.0655687f,0.023408f,0.931648f,0.191351f,
0.0750895f,0.277934f,-0.0604106f,0.0204963f,0.922883f,0.217389f, 0.0655264f,0.261764f,-0.0548238f,0.0177054f,0.915773f,0.246188f,
0.0553754f,0.240011f,-0.049184f,0.0151493f,0.911721f,0.278406f, 0.0495394f,0.229199f,-0.0442228f,0.0130255f,0.912276f,0.314925f,
0.0423792f,0.210389f,-0.0387627f,0.0109552f,0.919254f,0.357014f, 0.034893f,0.18606f,-0.0331909f,0.00903948f,0.934692f,0.406404f,
0.0287018f,0.163261f,-0.0277995f,0.00733442f,0.960874f,0.465411f, 0.0208729f,0.129311f,-0.0216969f,0.0055855f,0.998663f,0.534346f,
0.999958f,-1.85165e-06f,1.04314e-21f,0.293333f,1.0f,1.79932e-08f, 0.999536f,0.0224386f,-0.00658709f,0.293418f,1.0f,1.75334e-08f,
0.998007f,0.0448325f,-0.0131612f,0.292973f,1.0f,2.43855e-08f, 0.99561f,0.0671529f,-0.0197106f,0.292252f,1.0f,3.79688e-08f,
0.992106f,0.0893409f,-0.0262194f,0.291209f,1.0f,6.2022e-08f, 0.987704f,0.111374f,-0.0326787f,0.289896f,1.0f,1.02839e-07f,
0.982299f,0.13319f,-0.0390737f,0.288291f,1.0f,1.705e-07f, 0.975978f,0.15476f,-0.0453938f,0.286411f,1.0f,2.80709e-07f,
0.968703f,0.176043f,-0.0516234f,0.284237f,1.0f,4.57458e-07f, 0.960538f,0.197005f,-0.0577541f,0.281797f,1.0f,7.36801e-07f,
0.951299f,0.217574f,-0.0637654f,0.279055f,1.0f,1.1721e-06f, 0.941283f,0.237748f,-0.0696566f,0.276069f,1.0f,1.84124e-06f,
0.930292f,0.257469f,-0.0754066f,0.272804f,1.0f,2.85639e-06f, 0.918491f,0.276719f,-0.0810081f,0.269284f,1.0f,4.37707e-06f,
0.905813f,0.295431f,-0.0864521f,0.265522f,1.0f,6.62738e-06f, 0.892251f,0.313573f,-0.0917194f,0.2615f,1.0f,9.9186e-06f,
0.877855f,0.331107f,-0.0968004f,0.257232f,1.0f,1.46784e-05f, 0.862678f,0.347993f,-0.101687f,0.252734f,1.0f,2.1488e-05f,
0.84673f,0.364212f,-0.106371f,0.248018f,1.0f,3.113e-05f, 0.8301f,0.37975f,-0.11084f,0.243089f,1.0f,4.46477e-05f,
0.812745f,0.394533f,-0.115084f,0.237953f,1.0f,6.34196e-05f, 0.794619f,0.408499f,-0.119089f,0.232614f,1.0f,8.92512e-05f,
0.775895f,0.42169f,-0.122846f,0.227081f,1.0f,0.000124488f, 0.756569f,0.434037f,-0.126354f,0.221381f,1.0f,0.000172153f,
0.736584f,0.445482f,-0.129592f,0.215502f,1.0f,0.000236113f, 0.716058f,0.456015f,-0.132562f,0.209472f,1.0f,0.000321277f,
0.695002f,0.465607f,-0.135242f,0.203283f,1.0f,0.000433838f, 0.673446f,0.47424f,-0.137637f,0.196965f,1.0f,0.00058155f,
0.651445f,0.481854f,-0.139736f,0.190524f,0.999999f,0.000774063f, 0.629052f,0.488477f,-0.141527f,0.183968f,0.999998f,0.00102331f,
0.606318f,0.494065f,-0.14301f,0.177319f,0.999996f,0.00134396f, 0.583224f,0.498544f,-0.144179f,0.170588f,0.999991f,0.00175393f,
0.559884f,0.501954f,-0.145022f,0.163784f,0.999983f,0.00227493f, 0.53628f,0.504235f,-0.14553f,0.156916f,0.999968f,0.00293317f,
0.512506f,0.50538f,-0.145707f,0.150009f,0.99994f,0.00375994f, 0.488631f,0.505409f,-0.145545f,0.143078f,0.99989f,0.00479237f,
0.464662f,0.504248f,-0.145032f,0.13613f,0.999802f,0.00607391f, 0.440662f,0.501909f,-0.144168f,0.129188f,0.999651f,0.00765465f,
0.416704f,0.498379f,-0.142938f,0.122263f,0.999394f,0.009591f, 0.392777f,0.493607f,-0.141331f,0.115373f,0.998964f,0.0119441f,
0.369061f,0.487695f,-0.139344f,0.108545f,0.998251f,0.0147759f, 0.345636f,0.48068f,-0.136966f,0.101807f,0.9971f,0.0181442f,
0.322338f,0.472266f,-0.134156f,0.0951586f,0.995336f,0.0221005f, 0.299542f,0.462906f,-0.131065f,0.0886247f,0.993769f,0.0268885f,
0.277103f,0.452316f,-0.127651f,0.0822082f,0.992203f,0.032636f, 0.255285f,0.440774f,-0.123836f,0.075964f,0.989719f,0.0392837f,
0.236176f,0.431629f,-0.119817f,0.0700125f,0.986312f,0.046929f, 0.21383f,0.415182f,-0.115201f,0.0640642f,0.982693f,0.0558921f,
0.194684f,0.401863f,-0.110475f,0.0584773f,0.977973f,0.0660726f, 0.17628f,0.387684f,-0.105443f,0.0531188f,0.972368f,0.0776468f,
0.159714f,0.374636f,-0.100198f,0.0480319f,0.965975f,0.090754f, 0.141998f,0.356729f,-0.0946431f,0.043176f,0.958698f,0.10545f,
0.127511f,0.342919f,-0.08915f,0.0387112f,0.950712f,0.121855f, 0.114454f,0.329729f,-0.0835835f,0.0345618f,0.942161f,0.140043f,
0.103829f,0.319876f,-0.0781427f,0.03079f,0.933424f,0.160148f, 0.0926876f,0.306188f,-0.0725452f,0.0272612f,0.925087f,0.182378f,
0.0804249f,0.286283f,-0.0666533f,0.0239149f,0.917892f,0.207016f, 0.0716102f,0.272618f,-0.0608159f,0.0208658f,0.912748f,0.234459f,
0.0623042f,0.254624f,-0.0551873f,0.018142f,0.910757f,0.265277f, 0.0556f,0.241575f,-0.049633f,0.015671f,0.913283f,0.300329f,
0.0478952f,0.221929f,-0.043808f,0.0133257f,0.921778f,0.340718f, 0.0397463f,0.196852f,-0.0378074f,0.0111216f,0.937867f,0.387914f,
0.0331591f,0.174224f,-0.0320137f,0.00914914f,0.963334f,0.443812f, 0.0244795f,0.139495f,-0.025383f,0.00709123f,0.998764f,0.508477f,
1.0f,-8.772e-06f,5.69319e-22f,0.317629f,1.0f,3.69019e-08f, 0.999504f,0.0224451f,-0.00713251f,0.317719f,1.0f,3.54888e-08f,
0.998046f,0.0448406f,-0.0142511f,0.317242f,1.0f,4.7468e-08f, 0.995547f,0.0671542f,-0.0213407f,0.316432f,1.0f,7.06933e-08f,
0.992139f,0.0893518f,-0.0283902f,0.315335f,1.0f,1.10695e-07f, 0.987732f,0.111369f,-0.0353834f,0.313911f,1.0f,1.76576e-07f,
0.982448f,0.133205f,-0.0423077f,0.312181f,1.0f,2.82558e-07f, 0.976095f,0.154762f,-0.0491467f,0.310127f,1.0f,4.50259e-07f,
0.968852f,0.176066f,-0.0558909f,0.307781f,1.0f,7.11916e-07f, 0.960651f,0.197017f,-0.0625246f,0.305132f,1.0f,1.11488e-06f,
0.951537f,0.217598f,-0.0690343f,0.302184f,1.0f,1.72777e-06f, 0.941475f,0.237778f,-0.0754067f,0.298943f,1.0f,2.64874e-06f,
0.930571f,0.257506f,-0.0816302f,0.295419f,1.0f,4.01659e-06f, 0.918812f,0.276771f,-0.0876923f,0.291619f,1.0f,6.0253e-06f,
0.906143f,0.295486f,-0.0935776f,0.28754f,1.0f,8.94315e-06f, 0.892646f,0.313633f,-0.0992762f,0.283197f,1.0f,1.31372e-05f,
0.87834f,0.331196f,-0.104773f,0.278589f,1.0f,1.9105e-05f, 0.863264f,0.348126f,-0.110066f,0.273751f,1.0f,2.75141e-05f,
0.847398f,0.364379f,-0.115125f,0.268644f,1.0f,3.92526e-05f, 0.830763f,0.379896f,-0.119956f,0.263317f,1.0f,5.54916e-05f,
0.813469f,0.394721f,-0.12454f,0.257766f,1.0f,7.77623e-05f, 0.795429f,0.408719f,-0.128869f,0.252001f,1.0f,0.000108052f,
0.776719f,0.421915f,-0.132926f,0.246025f,1.0f,0.000148917f, 0.757478f,0.434293f,-0.136716f,0.239873f,1.0f,0.000203627f,
0.737578f,0.445784f,-0.140211f,0.233523f,0.999999f,0.000276329f, 0.717109f,0.456338f,-0.14341f,0.227006f,0.999999f,0.00037225f,
0.696174f,0.466022f,-0.146313f,0.220344f,0.999998f,0.000497934f, 0.674699f,0.47468f,-0.148892f,0.21352f,0.999995f,0.00066152f,
0.652803f,0.482374f,-0.151155f,0.206574f,0.999991f,0.000873063f, 0.630507f,0.489062f,-0.153092f,0.199514f,0.999984f,0.00114491f,
0.607817f,0.494685f,-0.154686f,0.192342f,0.999971f,0.00149211f, 0.584832f,0.49925f,-0.155936f,0.18508f,0.999949f,0.00193289f,
0.561532f,0.502691f,-0.156831f,0.177739f,0.999911f,0.00248911f, 0.538073f,0.505091f,-0.157381f,0.170353f,0.999847f,0.00318679f,
0.514361f,0.506297f,-0.157546f,0.162905f,0.999741f,0.00405646f, 0.490528f,0.506355f,-0.15734f,0.155433f,0.999569f,0.00513344f,
0.466687f,0.505332f,-0.156758f,0.147961f,0.999293f,0.0064576f, 0.442796f,0.503106f,-0.15577f,0.140488f,0.998851f,0.00807239f,
0.418873f,0.499622f,-0.154375f,0.133049f,0.998157f,0.010023f, 0.395155f,0.495082f,-0.152553f,0.125659f,0.997087f,0.0123525f,
0.371665f,0.489426f,-0.150295f,0.118349f,0.995516f,0.015103f, 0.349592f,0.484154f,-0.14778f,0.111193f,0.993906f,0.0184135f,
0.32525f,0.474455f,-0.144758f,0.103968f,0.992593f,0.0224596f, 0.302575f,0.465298f,-0.141421f,0.0969726f,0.990583f,0.0271813f,
0.280501f,0.455234f,-0.137634f,0.0901351f,0.987669f,0.0326201f, 0.259055f,0.444306f,-0.133544f,0.0834786f,0.98455f,0.0390212f,
0.238423f,0.432708f,-0.129098f,0.0770388f,0.980594f,0.0463698f, 0.219016f,0.421143f,-0.124436f,0.0708724f,0.976088f,0.0548386f,
0.199179f,0.406776f,-0.119192f,0.0648023f,0.970706f,0.0644528f, 0.18159f,0.394067f,-0.113923f,0.0591284f,0.964585f,0.0753461f,
0.166634f,0.383869f,-0.108801f,0.0539155f,0.957786f,0.0876237f, 0.148585f,0.365954f,-0.102771f,0.0486364f,0.95038f,0.101378f,
0.134309f,0.35274f,-0.0970156f,0.043866f,0.942517f,0.116706f, 0.121405f,0.340099f,-0.0912322f,0.0394348f,0.934474f,0.133732f,
0.109848f,0.328033f,-0.0854641f,0.0353411f,0.926665f,0.152621f, 0.0990081f,0.315356f,-0.0796533f,0.0315405f,0.919637f,0.173596f,
0.0876034f,0.298273f,-0.0732949f,0.0278247f,0.914037f,0.196936f, 0.0784991f,0.284514f,-0.0673817f,0.0245601f,0.91071f,0.223066f,
0.0695692f,0.268214f,-0.061551f,0.0215802f,0.910588f,0.252532f, 0.0621871f,0.253785f,-0.0555132f,0.0187643f,0.914753f,0.286083f,
0.0539659f,0.234123f,-0.0493606f,0.0161303f,0.924382f,0.324682f, 0.0451269f,0.207911f,-0.0428666f,0.0135875f,0.940845f,0.369635f,
0.0381054f,0.185391f,-0.0366539f,0.0113153f,0.965494f,0.422471f, 0.0285426f,0.150052f,-0.0295015f,0.0089159f,0.998854f,0.483214f,
1.00001f,4.42574e-06f,1.91651e-19f,0.342955f,1.0f,7.30044e-08f, 0.999516f,0.0224345f,-0.00770115f,0.343055f,1.0f,6.95063e-08f,
0.998067f,0.044838f,-0.0153874f,0.342546f,1.0f,8.9907e-08f, 0.995605f,0.0671538f,-0.0230421f,0.341673f,1.0f,1.28724e-07f,
0.992151f,0.0893466f,-0.0306519f,0.340474f,1.0f,1.93999e-07f, 0.987831f,0.111384f,-0.0382033f,0.338955f,1.0f,2.98712e-07f,
0.982459f,0.1332f,-0.0456765f,0.337073f,1.0f,4.6271e-07f, 0.976174f,0.154766f,-0.0530611f,0.334873f,1.0f,7.15494e-07f,
0.968983f,0.176063f,-0.0603412f,0.332345f,1.0f,1.10011e-06f, 0.960775f,0.197016f,-0.0674986f,0.329477f,1.0f,1.67847e-06f,
0.951762f,0.217629f,-0.0745255f,0.326307f,1.0f,2.53853e-06f, 0.941751f,0.237807f,-0.081401f,0.322809f,1.0f,3.80378e-06f,
0.930862f,0.257555f,-0.0881157f,0.319011f,1.0f,5.64582e-06f, 0.919171f,0.276816f,-0.0946582f,0.314924f,1.0f,8.3006e-06f,
0.906531f,0.295548f,-0.101003f,0.310517f,1.0f,1.20895e-05f, 0.893139f,0.313729f,-0.107155f,0.305855f,1.0f,1.74459e-05f,
0.878872f,0.331293f,-0.113079f,0.300882f,1.0f,2.49495e-05f, 0.863862f,0.348257f,-0.118782f,0.295661f,1.0f,3.53686e-05f,
0.848046f,0.364517f,-0.124238f,0.290168f,1.0f,4.97131e-05f, 0.831574f,0.380109f,-0.129449f,0.284443f,1.0f,6.93003e-05f,
0.814213f,0.394877f,-0.134377f,0.278439f,1.0f,9.58351e-05f, 0.796362f,0.408968f,-0.139052f,0.272259f,0.999999f,0.000131508f,
0.777771f,0.422209f,-0.143419f,0.265822f,0.999998f,0.000179112f, 0.758561f,0.434617f,-0.147496f,0.259195f,0.999997f,0.000242186f,
0.738755f,0.446145f,-0.151259f,0.252366f,0.999995f,0.000325182f, 0.718392f,0.456768f,-0.154707f,0.245365f,0.99999f,0.000433664f,
0.697492f,0.466458f,-0.15782f,0.238186f,0.999983f,0.000574537f, 0.676145f,0.475195f,-0.160597f,0.230858f,0.999971f,0.000756313f,
0.6543f,0.482928f,-0.163021f,0.223382f,0.999951f,0.000989411f, 0.632083f,0.489643f,-0.165093f,0.21579f,0.999919f,0.00128648f,
0.609506f,0.495353f,-0.166797f,0.208084f,0.999867f,0.00166275f, 0.586634f,0.499993f,-0.168126f,0.200283f,0.999785f,0.00213637f,
0.563457f,0.503537f,-0.169071f,0.192406f,0.999656f,0.00272867f, 0.540037f,0.505956f,-0.169612f,0.184458f,0.999456f,0.00346433f,
0.516492f,0.507313f,-0.169758f,0.176479f,0.999148f,0.00437123f, 0.492833f,0.507539f,-0.169479f,0.168471f,0.998679f,0.00547978f,
0.46902f,0.506532f,-0.168761f,0.160456f,0.997979f,0.0068224f, 0.445228f,0.504383f,-0.167587f,0.152458f,0.996947f,0.00843029f,
0.421627f,0.50122f,-0.165968f,0.144518f,0.995493f,0.0103361f, 0.39794f,0.49671f,-0.16394f,0.136625f,0.993904f,0.0126252f,
0.374493f,0.491138f,-0.161608f,0.128777f,0.992734f,0.0154615f, 0.351706f,0.484937f,-0.158854f,0.121068f,0.991007f,0.0187928f,
0.328806f,0.477085f,-0.155589f,0.113463f,0.988549f,0.0226568f, 0.306628f,0.468602f,-0.151938f,0.106028f,0.985587f,0.0271615f,
0.284869f,0.459045f,-0.147955f,0.0987635f,0.982418f,0.032467f, 0.264206f,0.449278f,-0.143598f,0.0917352f,0.978352f,0.0385208f,
0.244522f,0.439247f,-0.139016f,0.0849734f,0.973901f,0.0455301f, 0.223881f,0.425788f,-0.133735f,0.0782331f,0.968751f,0.0535145f,
0.205564f,0.414006f,-0.128443f,0.0719259f,0.962923f,0.0625652f, 0.188526f,0.402393f,-0.122967f,0.0659323f,0.956507f,0.0727875f,
0.172788f,0.391077f,-0.117327f,0.0602528f,0.949591f,0.0842781f, 0.158961f,0.381353f,-0.111626f,0.0549278f,0.942309f,0.0971376f,
0.14465f,0.368553f,-0.105635f,0.0498333f,0.934875f,0.111482f, 0.132631f,0.358429f,-0.0998189f,0.0451738f,0.927596f,0.127452f,
0.119621f,0.343612f,-0.0936257f,0.0406799f,0.920872f,0.145226f, 0.108526f,0.330752f,-0.0873104f,0.0364583f,0.915177f,0.165019f,
0.0965282f,0.31302f,-0.080762f,0.0324469f,0.911181f,0.187168f, 0.0867981f,0.298185f,-0.0745053f,0.0288423f,0.9095f,0.212024f,
0.0799831f,0.288848f,-0.0686555f,0.0256524f,0.910998f,0.240146f, 0.0692351f,0.265537f,-0.0618048f,0.0223353f,0.916523f,0.272185f,
0.0604212f,0.244977f,-0.0552651f,0.0193644f,0.92708f,0.309024f, 0.0533426f,0.227227f,-0.0487905f,0.016625f,0.943715f,0.35174f,
0.0435893f,0.196796f,-0.0417506f,0.0138841f,0.96752f,0.401626f, 0.0350094f,0.168449f,-0.0343609f,0.0112013f,0.998933f,0.458643f,
1.00001f,3.90939e-06f,1.05911e-19f,0.369336f,1.0f,1.39603e-07f, 0.999512f,0.0224331f,-0.0082933f,0.369439f,1.0f,1.31921e-07f,
0.998082f,0.0448444f,-0.0165706f,0.368897f,1.0f,1.65801e-07f, 0.99567f,0.0671539f,-0.0248154f,0.367982f,1.0f,2.29247e-07f,
0.992219f,0.0893532f,-0.0330089f,0.366676f,1.0f,3.33753e-07f, 0.987845f,0.111384f,-0.0411387f,0.365029f,1.0f,4.97567e-07f,
0.982586f,0.133211f,-0.0491875f,0.363024f,1.0f,7.48063e-07f, 0.976332f,0.15479f,-0.0571362f,0.360645f,1.0f,1.12512e-06f,
0.969148f,0.176087f,-0.0649716f,0.357917f,1.0f,1.68581e-06f, 0.961013f,0.197054f,-0.0726821f,0.354864f,1.0f,2.5106e-06f,
0.951957f,0.21765f,-0.0802415f,0.351438f,1.0f,3.71177e-06f, 0.942033f,0.237838f,-0.0876412f,0.347679f,1.0f,5.44422e-06f,
0.931171f,0.257589f,-0.0948658f,0.343594f,1.0f,7.91966e-06f, 0.919558f,0.27688f,-0.101906f,0.339205f,1.0f,1.14247e-05f,
0.90704f,0.295631f,-0.108735f,0.334481f,1.0f,1.63441e-05f, 0.893696f,0.313835f,-0.115347f,0.32946f,1.0f,2.31897e-05f,
0.879468f,0.331398f,-0.121717f,0.324117f,1.0f,3.2637e-05f, 0.864563f,0.348384f,-0.127851f,0.318515f,0.999999f,4.55707e-05f,
0.848838f,0.364679f,-0.133719f,0.312623f,0.999999f,6.314e-05f, 0.832363f,0.380268f,-0.139306f,0.306446f,0.999998f,8.68277e-05f,
0.815197f,0.395117f,-0.144618f,0.300041f,0.999996f,0.000118532f, 0.797338f,0.409197f,-0.149619f,0.293366f,0.999993f,0.000160668f,
0.778853f,0.422495f,-0.15432f,0.286483f,0.999988f,0.000216283f, 0.759688f,0.434912f,-0.15869f,0.279364f,0.999981f,0.000289201f,
0.74004f,0.446505f,-0.16273f,0.272045f,0.999969f,0.000384183f, 0.719767f,0.457191f,-0.166421f,0.26453f,0.999949f,0.000507114f,
0.698985f,0.466923f,-0.169754f,0.256834f,0.99992f,0.000665215f, 0.677714f,0.475717f,-0.172715f,0.248969f,0.999874f,0.000867272f,
0.656028f,0.483528f,-0.175309f,0.240972f,0.999803f,0.00112387f, 0.633972f,0.49037f,-0.17751f,0.232838f,0.999697f,0.00144763f,
0.611455f,0.496096f,-0.179308f,0.224585f,0.999539f,0.00185337f, 0.588665f,0.500791f,-0.180685f,0.216227f,0.999302f,0.00235822f,
0.565633f,0.504443f,-0.181638f,0.207795f,0.998953f,0.00298144f, 0.542435f,0.507046f,-0.182162f,0.199317f,0.99845f,0.0037446f,
0.519086f,0.508545f,-0.182218f,0.190789f,0.997723f,0.00466963f, 0.49659f,0.509811f,-0.181855f,0.182303f,0.996697f,0.00577922f,
0.471836f,0.507903f,-0.18088f,0.173697f,0.995315f,0.0070983f, 0.448411f,0.506118f,-0.179561f,0.165197f,0.993794f,0.00868566f,
0.424824f,0.503024f,-0.177926f,0.156703f,0.9927f,0.0106704f, 0.401493f,0.498896f,-0.175803f,0.148283f,0.991139f,0.0130123f,
0.378809f,0.494201f,-0.173214f,0.139992f,0.98898f,0.0157441f, 0.35757f,0.489838f,-0.170229f,0.13189f,0.986211f,0.0189136f,
0.333642f,0.480834f,-0.166684f,0.123748f,0.983464f,0.0226964f, 0.311758f,0.472772f,-0.162815f,0.11589f,0.979944f,0.0270364f,
0.291182f,0.464862f,-0.158665f,0.108279f,0.976057f,0.0320777f, 0.270552f,0.455245f,-0.154019f,0.100816f,0.971473f,0.0378346f,
0.249759f,0.443583f,-0.14886f,0.0934627f,0.966504f,0.0444536f, 0.231077f,0.433222f,-0.143637f,0.0865321f,0.960951f,0.0519671f,
0.213408f,0.422616f,-0.138187f,0.0799057f,0.954885f,0.0604648f, 0.196643f,0.411569f,-0.132488f,0.0735612f,0.9484f,0.0700406f,
0.180981f,0.400521f,-0.126628f,0.0675382f,0.941621f,0.0807918f, 0.16606f,0.388775f,-0.120577f,0.0618094f,0.934723f,0.092826f,
0.15748f,0.387521f,-0.115005f,0.056694f,0.927941f,0.106268f, 0.139923f,0.366212f,-0.108356f,0.0514056f,0.921576f,0.121266f,
0.130562f,0.359784f,-0.102189f,0.0466942f,0.916001f,0.138002f, 0.118741f,0.345893f,-0.0955288f,0.0420824f,0.911708f,0.156729f,
0.106015f,0.32714f,-0.0886996f,0.0377142f,0.90917f,0.177721f, 0.0959536f,0.312313f,-0.0823641f,0.033848f,0.908989f,0.201357f,
0.0856348f,0.294004f,-0.0755609f,0.0300602f,0.911857f,0.228136f, 0.076922f,0.277433f,-0.0686668f,0.0264948f,0.918491f,0.25866f,
0.0694089f,0.2622f,-0.06196f,0.0232386f,0.929695f,0.293695f, 0.0598937f,0.238213f,-0.0547826f,0.0200237f,0.946385f,0.334229f,
0.0522356f,0.217551f,-0.047778f,0.017071f,0.969478f,0.381409f, 0.0402219f,0.179464f,-0.0393794f,0.01381f,0.999004f,0.434836f,
0.999995f,5.49125e-06f,-8.57281e-20f,0.396798f,1.0f,2.58519e-07f, 0.999563f,0.0224404f,-0.00891015f,0.396926f,1.0f,2.42982e-07f,
0.998087f,0.044834f,-0.0178018f,0.396317f,1.0f,2.97911e-07f, 0.995676f,0.0671605f,-0.0266588f,0.395335f,1.0f,3.99381e-07f,
0.992235f,0.0893423f,-0.0354606f,0.393936f,1.0f,5.63556e-07f, 0.987897f,0.111369f,-0.0441928f,0.392164f,1.0f,8.15717e-07f,
0.982663f,0.133207f,-0.0528383f,0.390017f,1.0f,1.19316e-06f, 0.976449f,0.154787f,-0.0613761f,0.387471f,1.0f,1.74927e-06f,
0.969306f,0.176096f,-0.0697914f,0.384549f,1.0f,2.55904e-06f, 0.961197f,0.197056f,-0.0780658f,0.38125f,1.0f,3.72644e-06f,
0.952237f,0.217678f,-0.0861876f,0.377603f,1.0f,5.39397e-06f, 0.942371f,0.23788f,-0.0941333f,0.373581f,1.0f,7.75511e-06f,
0.931635f,0.257662f,-0.101891f,0.369212f,0.999999f,1.10702e-05f, 0.920005f,0.276927f,-0.109438f,0.364478f,0.999999f,1.56866e-05f,
0.907504f,0.295691f,-0.116762f,0.359408f,0.999999f,2.20637e-05f, 0.894255f,0.313917f,-0.123858f,0.354036f,0.999998f,3.08051e-05f,
0.880111f,0.331513f,-0.130691f,0.348313f,0.999996f,4.26967e-05f, 0.86527f,0.348502f,-0.137265f,0.342306f,0.999994f,5.87555e-05f,
0.849624f,0.364825f,-0.143552f,0.335989f,0.99999f,8.02869e-05f, 0.833295f,0.380464f,-0.149553f,0.32941f,0.999985f,0.000108955f,
0.816252f,0.395363f,-0.155237f,0.322539f,0.999976f,0.000146867f, 0.798446f,0.409453f,-0.160594f,0.315399f,0.999963f,0.00019667f,
0.780101f,0.422795f,-0.165617f,0.308019f,0.999944f,0.000261666f, 0.761069f,0.435282f,-0.170293f,0.300411f,0.999914f,0.000345946f,
0.741451f,0.446896f,-0.174597f,0.292568f,0.99987f,0.000454529f, 0.721348f,0.457647f,-0.178541f,0.284547f,0.999806f,0.000593525f,
0.700705f,0.467461f,-0.182085f,0.276318f,0.999712f,0.000770292f, 0.679587f,0.476339f,-0.185235f,0.267928f,0.999575f,0.000993582f,
0.658035f,0.484219f,-0.187959f,0.25937f,0.999379f,0.00127365f, 0.636044f,0.491091f,-0.190259f,0.250684f,0.999097f,0.00162226f,
0.613719f,0.496924f,-0.192111f,0.241875f,0.998704f,0.00205307f, 0.5911f,0.501732f,-0.1935f,0.232969f,0.998151f,0.00258031f,
0.568328f,0.505555f,-0.194422f,0.224003f,0.997385f,0.00321943f, 0.545121f,0.508106f,-0.194816f,0.214948f,0.996347f,0.00398647f,
0.521839f,0.509608f,-0.194729f,0.205887f,0.995006f,0.0049004f, 0.498694f,0.51027f,-0.19421f,0.196818f,0.993585f,0.0060071f,
0.475772f,0.510087f,-0.19339f,0.187757f,0.992519f,0.0073964f, 0.45189f,0.50788f,-0.191999f,0.178679f,0.991056f,0.0090414f,
0.428964f,0.505423f,-0.190118f,0.169699f,0.989083f,0.0109675f, 0.405835f,0.501491f,-0.187717f,0.16081f,0.986568f,0.0132076f,
0.383144f,0.496771f,-0.18492f,0.152017f,0.983982f,0.0158767f, 0.361541f,0.491949f,-0.181717f,0.143405f,0.980932f,0.0189845f,
0.340378f,0.486273f,-0.178121f,0.135006f,0.97732f,0.0225662f, 0.319214f,0.479224f,-0.17413f,0.126768f,0.973419f,0.0267361f,
0.296853f,0.468997f,-0.169327f,0.118452f,0.96897f,0.0315104f, 0.276871f,0.460244f,-0.164515f,0.110629f,0.964008f,0.0369609f,
0.257896f,0.451267f,-0.159403f,0.103064f,0.958688f,0.0431893f, 0.239689f,0.44171f,-0.154016f,0.0957847f,0.952941f,0.0502457f,
0.222433f,0.431836f,-0.148368f,0.0887924f,0.946844f,0.0582119f, 0.210391f,0.428781f,-0.142861f,0.0823101f,0.94051f,0.0671778f,
0.194835f,0.418387f,-0.136817f,0.0759283f,0.934088f,0.0772418f, 0.178698f,0.40499f,-0.1305f,0.0697983f,0.927765f,0.0885142f,
0.165119f,0.394255f,-0.12427f,0.0640994f,0.921772f,0.101121f, 0.15118f,0.380695f,-0.117621f,0.0585514f,0.91642f,0.115225f,
0.137483f,0.365357f,-0.110607f,0.0531807f,0.912057f,0.131015f, 0.125053f,0.350253f,-0.103766f,0.0482348f,0.909059f,0.148714f,
0.116079f,0.340655f,-0.0971199f,0.0436954f,0.907876f,0.168607f, 0.108582f,0.332824f,-0.0908466f,0.0396097f,0.909035f,0.191068f,
0.0974057f,0.313834f,-0.0836107f,0.0353806f,0.913071f,0.216529f, 0.0851384f,0.289056f,-0.075984f,0.0312592f,0.920604f,0.245555f,
0.0771424f,0.273353f,-0.0688636f,0.0275968f,0.932303f,0.278832f, 0.0675826f,0.250867f,-0.0615919f,0.0241006f,0.94885f,0.317168f,
0.0587867f,0.228293f,-0.05377f,0.0205954f,0.971228f,0.36175f, 0.0459519f,0.190556f,-0.044868f,0.0168853f,0.999067f,0.411853f,
1.00003f,-5.56838e-06f,2.00324e-19f,0.425348f,1.0f,4.64392e-07f, 0.999516f,0.0224354f,-0.00955083f,0.425475f,1.0f,4.34907e-07f,
0.998057f,0.0448302f,-0.0190816f,0.424821f,1.0f,5.21925e-07f, 0.99572f,0.0671579f,-0.0285758f,0.423783f,1.0f,6.80814e-07f,
0.992319f,0.0893434f,-0.0380106f,0.422294f,1.0f,9.33924e-07f, 0.988019f,0.111379f,-0.0473696f,0.420397f,1.0f,1.31578e-06f,
0.982734f,0.133219f,-0.0566328f,0.418084f,1.0f,1.87655e-06f, 0.976564f,0.154802f,-0.0657825f,0.415365f,1.0f,2.68693e-06f,
0.969479f,0.1761f,-0.0748007f,0.412248f,0.999999f,3.8446e-06f, 0.961461f,0.19708f,-0.0836659f,0.408721f,0.999999f,5.48276e-06f,
0.95252f,0.217702f,-0.0923661f,0.40482f,0.999998f,7.78113e-06f, 0.942656f,0.237902f,-0.100871f,0.400499f,0.999997f,1.098e-05f,
0.932022f,0.257698f,-0.109176f,0.39582f,0.999996f,1.53977e-05f, 0.920443f,0.276988f,-0.117257f,0.390765f,0.999994f,2.14532e-05f,
0.908043f,0.295766f,-0.125102f,0.385362f,0.999991f,2.96929e-05f, 0.894826f,0.313981f,-0.132686f,0.379594f,0.999986f,4.08246e-05f,
0.880878f,0.331633f,-0.140005f,0.373506f,0.99998f,5.57582e-05f, 0.866045f,0.348634f,-0.147027f,0.367069f,0.99997f,7.56553e-05f,
0.850595f,0.365012f,-0.153755f,0.360341f,0.999955f,0.000101987f, 0.834344f,0.380671f,-0.160156f,0.353292f,0.999934f,0.000136605f,
0.81737f,0.395596f,-0.166223f,0.345956f,0.999903f,0.000181818f, 0.799755f,0.409756f,-0.17194f,0.338343f,0.999859f,0.000240484f,
0.781472f,0.423115f,-0.177292f,0.330471f,0.999796f,0.000316109f, 0.762627f,0.435679f,-0.182267f,0.322356f,0.999707f,0.000412952f,
0.743157f,0.447348f,-0.186843f,0.314007f,0.999582f,0.000536126f, 0.723185f,0.45816f,-0.190999f,0.30543f,0.999408f,0.000691688f,
0.702692f,0.46804f,-0.194735f,0.296667f,0.999166f,0.00088673f, 0.681728f,0.476983f,-0.19803f,0.287729f,0.998837f,0.00112956f,
0.660318f,0.48494f,-0.20086f,0.27863f,0.998386f,0.00142908f, 0.638515f,0.491894f,-0.203203f,0.269383f,0.997776f,0.00179528f,
0.61641f,0.497861f,-0.205052f,0.260028f,0.996961f,0.00223871f, 0.594131f,0.50287f,-0.206386f,0.250578f,0.995898f,0.00277071f,
0.571366f,0.506647f,-0.207203f,0.241056f,0.994585f,0.00340613f, 0.548458f,0.50943f,-0.207587f,0.231478f,0.993274f,0.0041835f,
0.525744f,0.511442f,-0.207625f,0.22187f,0.992209f,0.00515836f, 0.502563f,0.512048f,-0.207111f,0.212246f,0.990789f,0.00631469f,
0.479465f,0.511649f,-0.206033f,0.202636f,0.988932f,0.00767238f, 0.456952f,0.510716f,-0.204445f,0.193115f,0.986601f,0.00925516f,
0.434038f,0.508254f,-0.202409f,0.183659f,0.98412f,0.0111354f, 0.411547f,0.504995f,-0.199908f,0.174287f,0.981398f,0.0133535f,
0.390582f,0.502133f,-0.196987f,0.165138f,0.97807f,0.0159021f, 0.368959f,0.497359f,-0.193673f,0.156129f,0.974584f,0.018894f,
0.347509f,0.491402f,-0.189757f,0.147198f,0.970505f,0.0223145f, 0.325354f,0.483082f,-0.185224f,0.138282f,0.966181f,0.0262755f,
0.305164f,0.475674f,-0.180604f,0.129833f,0.961379f,0.0307911f, 0.285992f,0.468056f,-0.175637f,0.121634f,0.956174f,0.0359307f,
0.272096f,0.466276f,-0.170703f,0.113922f,0.950697f,0.0417811f, 0.25275f,0.455415f,-0.165028f,0.106182f,0.944949f,0.0483998f,
0.234302f,0.444078f,-0.159097f,0.0987393f,0.939016f,0.0558636f, 0.218318f,0.434715f,-0.153118f,0.0917089f,0.933022f,0.0642598f,
0.203134f,0.424923f,-0.146985f,0.085007f,0.927121f,0.0736855f, 0.193131f,0.422398f,-0.14104f,0.0788116f,0.921496f,0.0842494f,
0.178577f,0.410382f,-0.134398f,0.0726069f,0.916412f,0.0960961f, 0.162353f,0.393055f,-0.127071f,0.0664184f,0.912112f,0.109371f,
0.155268f,0.391051f,-0.121526f,0.0615065f,0.908905f,0.124263f, 0.141135f,0.374151f,-0.113545f,0.0556972f,0.907134f,0.140994f,
0.126995f,0.354066f,-0.106253f,0.0505688f,0.907171f,0.159833f, 0.118805f,0.345017f,-0.0994007f,0.0459527f,0.909482f,0.181139f,
0.107426f,0.327123f,-0.0922121f,0.0414647f,0.914505f,0.205313f, 0.0945408f,0.30187f,-0.0838826f,0.0367461f,0.922741f,0.232852f,
0.0854147f,0.28424f,-0.076248f,0.0325973f,0.934772f,0.264393f, 0.0771504f,0.26693f,-0.0688707f,0.0287917f,0.951234f,0.300711f,
0.0658537f,0.238947f,-0.0602339f,0.0246808f,0.972788f,0.342713f, 0.0522637f,0.201874f,-0.050867f,0.0204957f,0.999124f,0.38974f,
1.00004f,3.13622e-06f,-2.84338e-19f,0.455008f,1.0f,8.10503e-07f, 0.999501f,0.0224376f,-0.0102166f,0.455147f,1.0f,7.57388e-07f,
0.998073f,0.0448318f,-0.0204128f,0.454475f,0.999999f,8.92207e-07f, 0.995699f,0.0671458f,-0.0305678f,0.45335f,0.999999f,1.13592e-06f,
0.992371f,0.0893562f,-0.04066f,0.451765f,0.999999f,1.51892e-06f, 0.988039f,0.11137f,-0.0506682f,0.449725f,0.999999f,2.08766e-06f,
0.982879f,0.133205f,-0.0605752f,0.44726f,0.999998f,2.90873e-06f, 0.976693f,0.154796f,-0.0703583f,0.444353f,0.999997f,4.0746e-06f,
0.96968f,0.176123f,-0.080003f,0.44104f,0.999996f,5.71115e-06f, 0.961688f,0.197098f,-0.089477f,0.43726f,0.999994f,7.9874e-06f,
0.952766f,0.21772f,-0.0987708f,0.433075f,0.999991f,1.1128e-05f, 0.943093f,0.237954f,-0.107868f,0.428503f,0.999986f,1.54285e-05f,
0.932483f,0.257737f,-0.11674f,0.423508f,0.999981f,2.12754e-05f, 0.921023f,0.277065f,-0.125372f,0.418122f,0.999972f,2.91689e-05f,
0.90871f,0.295854f,-0.133742f,0.412338f,0.99996f,3.97525e-05f, 0.895614f,0.3141f,-0.141843f,0.40621f,0.999943f,5.38474e-05f,
0.881712f,0.33177f,-0.149646f,0.399709f,0.999919f,7.24936e-05f, 0.866993f,0.348792f,-0.157129f,0.392842f,0.999885f,9.69975e-05f,
0.851638f,0.365201f,-0.164296f,0.385673f,0.999839f,0.000128987f, 0.835441f,0.380856f,-0.171098f,0.378142f,0.999775f,0.000170474f,
0.818651f,0.395835f,-0.177548f,0.370336f,0.999687f,0.000223916f, 0.801145f,0.410033f,-0.183615f,0.362238f,0.999567f,0.000292288f,
0.783071f,0.423473f,-0.189278f,0.353856f,0.999403f,0.000379143f, 0.764319f,0.436048f,-0.194523f,0.345214f,0.999185f,0.000488763f,
0.74507f,0.44781f,-0.199333f,0.336333f,0.998894f,0.000626033f, 0.7253f,0.458689f,-0.203691f,0.327239f,0.998504f,0.000796457f,
0.704929f,0.468593f,-0.207562f,0.317923f,0.997989f,0.00100626f, 0.684104f,0.477569f,-0.210936f,0.308428f,0.997314f,0.00126217f,
0.662995f,0.485671f,-0.213803f,0.298783f,0.996444f,0.00157148f, 0.641535f,0.492801f,-0.216146f,0.289008f,0.995353f,0.00194237f,
0.619851f,0.499001f,-0.217964f,0.279117f,0.994052f,0.00238623f, 0.599209f,0.505214f,-0.219435f,0.269204f,0.992855f,0.00293766f,
0.57515f,0.508045f,-0.220348f,0.259036f,0.991767f,0.00362416f, 0.552851f,0.51129f,-0.220782f,0.248924f,0.990358f,0.00443916f,
0.530182f,0.513279f,-0.220635f,0.238789f,0.988562f,0.00539742f, 0.507487f,0.514252f,-0.219917f,0.228667f,0.986358f,0.00651696f,
0.48555f,0.514884f,-0.218737f,0.218605f,0.983962f,0.00784355f, 0.46284f,0.513765f,-0.217106f,0.208596f,0.981455f,0.00942415f,
0.441012f,0.512325f,-0.214946f,0.198715f,0.978408f,0.0112438f, 0.420418f,0.511036f,-0.2124f,0.189002f,0.975137f,0.013374f,
0.39872f,0.507448f,-0.209335f,0.17939f,0.971479f,0.0158368f, 0.375532f,0.500927f,-0.205365f,0.169557f,0.967496f,0.0186808f,
0.354896f,0.49582f,-0.201358f,0.160262f,0.963107f,0.0219385f, 0.334645f,0.489812f,-0.196984f,0.151185f,0.958471f,0.0256834f,
0.31836f,0.487128f,-0.192394f,0.142467f,0.95348f,0.0299444f, 0.298449f,0.478962f,-0.187235f,0.133837f,0.948197f,0.0347814f,
0.279991f,0.470985f,-0.181837f,0.125522f,0.94274f,0.04027f, 0.262486f,0.462746f,-0.176156f,0.117488f,0.937165f,0.0464746f,
0.251265f,0.462188f,-0.170615f,0.110001f,0.931561f,0.0534672f, 0.23419f,0.451663f,-0.164452f,0.102551f,0.92605f,0.061332f,
0.217022f,0.439125f,-0.157993f,0.0953484f,0.920781f,0.0701624f, 0.208917f,0.441409f,-0.152568f,0.0891596f,0.915978f,0.0800842f,
0.192173f,0.424625f,-0.144631f,0.0818998f,0.911821f,0.0912169f, 0.175422f,0.407031f,-0.1373f,0.0753916f,0.908561f,0.103717f,
0.164568f,0.398304f,-0.130404f,0.0694896f,0.90646f,0.117764f, 0.153147f,0.38678f,-0.123209f,0.0637719f,0.905821f,0.133577f,
0.139211f,0.368247f,-0.115868f,0.0583088f,0.906972f,0.151418f, 0.129324f,0.354199f,-0.108201f,0.0529986f,0.910274f,0.171606f,
0.120508f,0.344555f,-0.100825f,0.0481281f,0.916122f,0.194524f, 0.108019f,0.322604f,-0.0927205f,0.0431928f,0.924938f,0.220635f,
0.0944577f,0.295393f,-0.084152f,0.0383172f,0.937194f,0.250498f, 0.0854569f,0.277325f,-0.0762857f,0.0340138f,0.953396f,0.284781f,
0.0739587f,0.250839f,-0.0672519f,0.0294213f,0.974182f,0.324355f, 0.0592136f,0.213401f,-0.0573801f,0.0247016f,0.999175f,0.368533f,
1.00005f,-7.08535e-06f,-3.82637e-19f,0.485811f,0.999996f,1.37617e-06f, 0.999538f,0.0224205f,-0.0109081f,0.485977f,0.999997f,1.28466e-06f,
0.998045f,0.0448207f,-0.0217927f,0.485228f,0.999996f,1.48902e-06f, 0.995722f,0.0671501f,-0.0326339f,0.484033f,0.999995f,1.85523e-06f,
0.992411f,0.0893423f,-0.0434085f,0.482361f,0.999994f,2.42392e-06f, 0.988139f,0.111376f,-0.0540927f,0.480198f,0.999992f,3.25653e-06f,
0.982983f,0.133209f,-0.064666f,0.477568f,0.999989f,4.44012e-06f, 0.976838f,0.154804f,-0.0751049f,0.474464f,0.999985f,6.0939e-06f,
0.969895f,0.176124f,-0.0853939f,0.470929f,0.999979f,8.37783e-06f, 0.961922f,0.197113f,-0.095499f,0.466899f,0.999971f,1.15035e-05f,
0.953154f,0.217737f,-0.105414f,0.462462f,0.999961f,1.57477e-05f, 0.943428f,0.237968f,-0.115102f,0.457549f,0.999946f,2.14691e-05f,
0.932913f,0.257762f,-0.124559f,0.452244f,0.999925f,2.91291e-05f, 0.921548f,0.277101f,-0.133749f,0.446497f,0.999898f,3.93152e-05f,
0.909394f,0.295915f,-0.142668f,0.440373f,0.99986f,5.27705e-05f, 0.89637f,0.31418f,-0.151282f,0.43384f,0.99981f,7.0426e-05f,
0.882623f,0.331869f,-0.159573f,0.426921f,0.999742f,9.34383e-05f, 0.868038f,0.348917f,-0.16752f,0.419624f,0.999651f,0.00012323f,
0.852738f,0.365331f,-0.175104f,0.411971f,0.99953f,0.000161531f, 0.836812f,0.381079f,-0.182322f,0.404015f,0.999371f,0.000210433f,
0.820167f,0.396092f,-0.18913f,0.395713f,0.999166f,0.000272516f, 0.802789f,0.410309f,-0.195509f,0.387093f,0.998895f,0.000350599f,
0.784911f,0.423797f,-0.201452f,0.3782f,0.998542f,0.000448083f, 0.766404f,0.436447f,-0.206924f,0.369031f,0.998086f,0.000568751f,
0.747455f,0.448318f,-0.211926f,0.359641f,0.997499f,0.0007168f, 0.727778f,0.459202f,-0.216405f,0.349996f,0.996758f,0.000896941f,
0.707619f,0.469184f,-0.220356f,0.340146f,0.995829f,0.00111404f, 0.687218f,0.478336f,-0.223776f,0.330125f,0.994699f,0.00137401f,
0.666384f,0.486539f,-0.226667f,0.319935f,0.993416f,0.00168666f, 0.645076f,0.493742f,-0.229185f,0.309617f,0.992315f,0.00208164f,
0.623475f,0.500011f,-0.231225f,0.299176f,0.991187f,0.00256743f, 0.601891f,0.505443f,-0.232668f,0.288632f,0.989761f,0.00314401f,
0.580266f,0.51003f,-0.233543f,0.278061f,0.987993f,0.00382236f, 0.558067f,0.513277f,-0.233814f,0.267446f,0.985866f,0.00461583f,
0.53589f,0.515625f,-0.233572f,0.256828f,0.983549f,0.00555561f, 0.514645f,0.517801f,-0.232892f,0.246248f,0.981179f,0.00668222f,
0.492513f,0.518217f,-0.231646f,0.235748f,0.978338f,0.00798195f, 0.471076f,0.518237f,-0.229908f,0.22534f,0.975218f,0.00949743f,
0.451276f,0.518772f,-0.227794f,0.215119f,0.971884f,0.0112693f, 0.426731f,0.513575f,-0.224548f,0.204464f,0.968129f,0.0133025f,
0.405882f,0.510723f,-0.221291f,0.194361f,0.964179f,0.0156624f, 0.385449f,0.507117f,-0.217623f,0.184478f,0.95988f,0.0183636f,
0.369748f,0.507581f,-0.213781f,0.175003f,0.955282f,0.0214514f, 0.347421f,0.499375f,-0.209135f,0.165394f,0.950491f,0.0249848f,
0.32841f,0.493605f,-0.204276f,0.156159f,0.945463f,0.0289977f, 0.309918f,0.487113f,-0.199115f,0.14721f,0.940258f,0.033544f,
0.296952f,0.486374f,-0.193889f,0.138703f,0.934982f,0.0386912f, 0.277253f,0.475534f,-0.18796f,0.13017f,0.92973f,0.0445073f,
0.261201f,0.468091f,-0.182078f,0.122138f,0.924582f,0.0510596f, 0.250923f,0.4677f,-0.176203f,0.114553f,0.919654f,0.0584273f,
0.231882f,0.452848f,-0.169339f,0.106755f,0.91513f,0.0667168f, 0.215327f,0.439931f,-0.162056f,0.0991296f,0.911163f,0.0760326f,
0.200453f,0.427828f,-0.154997f,0.0920552f,0.907948f,0.0865033f, 0.189056f,0.419954f,-0.147972f,0.0853883f,0.905688f,0.0982747f,
0.177662f,0.410445f,-0.140779f,0.0789915f,0.904631f,0.111529f, 0.165707f,0.398754f,-0.133314f,0.0727963f,0.90501f,0.126462f,
0.157106f,0.391637f,-0.126394f,0.0672255f,0.907147f,0.143346f, 0.140864f,0.367396f,-0.117857f,0.0611205f,0.911303f,0.162455f,
0.131421f,0.355154f,-0.109956f,0.0556629f,0.917822f,0.18415f, 0.118212f,0.332859f,-0.10147f,0.0502062f,0.927062f,0.208852f,
0.104933f,0.308188f,-0.0926546f,0.0448713f,0.939432f,0.237078f, 0.0951231f,0.289474f,-0.0843338f,0.0400397f,0.95535f,0.26942f,
0.0828024f,0.262853f,-0.0747705f,0.0348609f,0.975431f,0.306718f, 0.0671263f,0.225903f,-0.0644707f,0.0295947f,0.99922f,0.348254f,
0.999972f,1.071e-05f,-1.1719e-19f,0.517747f,0.999979f,2.27494e-06f, 0.999532f,0.0224252f,-0.0116246f,0.517968f,0.999984f,2.12355e-06f,
0.998102f,0.0448174f,-0.0232239f,0.517176f,0.999982f,2.4265e-06f, 0.995758f,0.0671407f,-0.0347767f,0.515916f,0.999979f,2.96519e-06f,
0.992435f,0.0893427f,-0.0462541f,0.514104f,0.999974f,3.79279e-06f, 0.988255f,0.111377f,-0.0576367f,0.511812f,0.999966f,4.98899e-06f,
0.983096f,0.133201f,-0.068899f,0.509019f,0.999956f,6.66534e-06f, 0.977073f,0.154815f,-0.0800148f,0.505716f,0.999943f,8.97251e-06f,
0.970063f,0.176112f,-0.0909653f,0.501942f,0.999924f,1.21097e-05f, 0.962276f,0.197114f,-0.101723f,0.49768f,0.9999f,1.63361e-05f,
0.953547f,0.217756f,-0.112268f,0.49295f,0.999867f,2.19852e-05f, 0.943932f,0.238002f,-0.12257f,0.48774f,0.999824f,2.94816e-05f,
0.93347f,0.257799f,-0.132613f,0.482085f,0.999768f,3.93606e-05f, 0.922256f,0.27714f,-0.142373f,0.475992f,0.999694f,5.22905e-05f,
0.910104f,0.295954f,-0.15182f,0.46945f,0.999598f,6.90973e-05f, 0.897275f,0.314252f,-0.160948f,0.462528f,0.999473f,9.07906e-05f,
0.883698f,0.331979f,-0.16972f,0.455186f,0.999315f,0.00011865f, 0.869295f,0.34905f,-0.178114f,0.447451f,0.999113f,0.000154125f,
0.854183f,0.365484f,-0.186104f,0.439335f,0.998851f,0.000198921f, 0.838385f,0.381238f,-0.193677f,0.430877f,0.998519f,0.000255125f,
0.821867f,0.396267f,-0.200797f,0.42207f,0.998097f,0.000324992f, 0.804769f,0.410546f,-0.207454f,0.41296f,0.997568f,0.000411182f,
0.787158f,0.424091f,-0.213621f,0.40356f,0.996909f,0.000516549f, 0.769019f,0.436866f,-0.21927f,0.393882f,0.996091f,0.000644129f,
0.750088f,0.448674f,-0.224379f,0.38394f,0.995101f,0.000797519f, 0.730739f,0.459659f,-0.228949f,0.373772f,0.993938f,0.00098125f,
0.711095f,0.469855f,-0.233014f,0.363407f,0.992674f,0.00120373f, 0.69108f,0.479234f,-0.236723f,0.352857f,0.991639f,0.00148923f,
0.67043f,0.487538f,-0.239881f,0.342137f,0.990454f,0.00183483f, 0.649538f,0.494956f,-0.242444f,0.331292f,0.988993f,0.00224465f,
0.62872f,0.501649f,-0.244391f,0.320338f,0.987225f,0.00272672f, 0.607794f,0.507465f,-0.245745f,0.309326f,0.985143f,0.00329104f,
0.586179f,0.511995f,-0.246554f,0.298254f,0.982894f,0.00396038f, 0.564863f,0.51587f,-0.246906f,0.287176f,0.980609f,0.00476508f,
0.544447f,0.519573f,-0.246689f,0.276164f,0.977909f,0.00569463f, 0.522935f,0.521493f,-0.245934f,0.265208f,0.974905f,0.00677444f,
0.502102f,0.523023f,-0.2447f,0.254291f,0.971803f,0.00804869f, 0.481686f,0.523953f,-0.242784f,0.243357f,0.968272f,0.00950746f,
0.458746f,0.521506f,-0.240064f,0.232198f,0.964607f,0.0112089f, 0.437195f,0.519168f,-0.237176f,0.22154f,0.960565f,0.013152f,
0.420966f,0.520935f,-0.23404f,0.211205f,0.956373f,0.0153967f, 0.402806f,0.520237f,-0.230597f,0.201177f,0.951905f,0.0179569f,
0.378912f,0.511558f,-0.22604f,0.190753f,0.947218f,0.0208745f, 0.367159f,0.515328f,-0.221884f,0.181207f,0.942419f,0.0242029f,
0.345522f,0.506849f,-0.216767f,0.171415f,0.937493f,0.027977f, 0.325415f,0.498641f,-0.211406f,0.161965f,0.932498f,0.0322459f,
0.308099f,0.492419f,-0.205919f,0.152921f,0.927548f,0.0370746f, 0.295017f,0.490387f,-0.200324f,0.144276f,0.922736f,0.0425275f,
0.277677f,0.481542f,-0.194229f,0.135741f,0.918134f,0.0486672f, 0.268326f,0.481807f,-0.188423f,0.127852f,0.913884f,0.05558f,
0.24734f,0.465393f,-0.180628f,0.119063f,0.910133f,0.0633621f, 0.239743f,0.46401f,-0.17508f,0.11218f,0.907021f,0.0721157f,
0.22171f,0.450652f,-0.16686f,0.10399f,0.904716f,0.0819638f, 0.204552f,0.433944f,-0.159145f,0.0965347f,0.903417f,0.0930557f,
0.193981f,0.42658f,-0.151826f,0.0897015f,0.90332f,0.105559f, 0.185032f,0.420895f,-0.144822f,0.0834061f,0.904631f,0.119664f,
0.169809f,0.402086f,-0.136614f,0.07676f,0.907601f,0.135614f, 0.153905f,0.379816f,-0.127924f,0.0701892f,0.912498f,0.153691f,
0.142889f,0.36522f,-0.11955f,0.0641195f,0.919592f,0.17422f, 0.132828f,0.351049f,-0.111133f,0.0583315f,0.929185f,0.197589f,
0.118772f,0.326562f,-0.101951f,0.0524357f,0.941617f,0.224261f, 0.108675f,0.308899f,-0.0932843f,0.0470806f,0.957262f,0.254787f,
0.0924532f,0.275022f,-0.0828107f,0.0410783f,0.976551f,0.289834f, 0.0789577f,0.246425f,-0.0723661f,0.035358f,0.999262f,0.328918f,
1.00002f,4.07381e-06f,-1.2901e-19f,0.55091f,0.999915f,3.66031e-06f, 0.99955f,0.0224126f,-0.0123636f,0.551136f,0.999938f,3.42038e-06f,
0.998144f,0.0448086f,-0.0247013f,0.550329f,0.999932f,3.85872e-06f, 0.995774f,0.0671309f,-0.0369848f,0.548951f,0.999922f,4.63262e-06f,
0.99256f,0.0893321f,-0.0491913f,0.547065f,0.999906f,5.80986e-06f, 0.98835f,0.111357f,-0.0612891f,0.544607f,0.999885f,7.49091e-06f,
0.983262f,0.133192f,-0.0732568f,0.541636f,0.999856f,9.8147e-06f, 0.977239f,0.154796f,-0.085066f,0.538137f,0.999819f,1.29661e-05f,
0.970346f,0.17611f,-0.0966882f,0.534103f,0.99977f,1.71854e-05f, 0.96256f,0.197098f,-0.108104f,0.52958f,0.999706f,2.27793e-05f,
0.953903f,0.21773f,-0.11928f,0.524544f,0.999625f,3.01345e-05f, 0.944444f,0.237973f,-0.130196f,0.519022f,0.999521f,3.97316e-05f,
0.934118f,0.257793f,-0.140823f,0.513016f,0.999391f,5.21843e-05f, 0.922984f,0.277129f,-0.151139f,0.50655f,0.999228f,6.82288e-05f,
0.911077f,0.295974f,-0.161119f,0.499647f,0.999022f,8.87158e-05f, 0.898369f,0.314273f,-0.170722f,0.492271f,0.998763f,0.00011469f,
0.884921f,0.331997f,-0.17994f,0.484498f,0.998439f,0.000147376f, 0.870768f,0.349111f,-0.188734f,0.476301f,0.998038f,0.000188193f,
0.855791f,0.365539f,-0.197086f,0.467725f,0.997544f,0.000238767f, 0.840259f,0.381338f,-0.204969f,0.458788f,0.996935f,0.000300806f,
0.82401f,0.396388f,-0.212348f,0.44949f,0.996192f,0.00037625f, 0.807298f,0.410751f,-0.219223f,0.439894f,0.995302f,0.000467345f,
0.790051f,0.424394f,-0.225558f,0.429986f,0.994248f,0.000576511f, 0.771953f,0.437091f,-0.231349f,0.419785f,0.993051f,0.000707457f,
0.753407f,0.449021f,-0.236674f,0.409341f,0.991835f,0.000868613f, 0.73468f,0.460319f,-0.241629f,0.398671f,0.990802f,0.00107563f,
0.715551f,0.470779f,-0.24599f,0.387797f,0.989549f,0.00132297f, 0.695683f,0.480143f,-0.249724f,0.376724f,0.988039f,0.00161576f,
0.675548f,0.488651f,-0.252842f,0.365515f,0.986251f,0.00195993f, 0.655552f,0.496542f,-0.255348f,0.354193f,0.984186f,0.00236296f,
0.63563f,0.503728f,-0.257327f,0.342791f,0.982002f,0.00284302f, 0.615004f,0.509712f,-0.258823f,0.331343f,0.979758f,0.00341935f,
0.594343f,0.514872f,-0.259666f,0.319843f,0.977148f,0.00408563f, 0.575005f,0.520137f,-0.259989f,0.308419f,0.974254f,0.00485895f,
0.55403f,0.523388f,-0.25983f,0.297f,0.971299f,0.00577507f, 0.532959f,0.525636f,-0.258936f,0.285483f,0.967966f,0.00682537f,
0.51068f,0.525883f,-0.257091f,0.273556f,0.964486f,0.00804924f, 0.494358f,0.530233f,-0.25537f,0.262451f,0.960709f,0.00945388f,
0.46925f,0.525901f,-0.252823f,0.251105f,0.956773f,0.0110763f, 0.451097f,0.526707f,-0.249944f,0.240085f,0.952562f,0.0129275f,
0.431331f,0.525034f,-0.246634f,0.229232f,0.948239f,0.0150549f, 0.412204f,0.522878f,-0.242932f,0.218616f,0.943729f,0.0174762f,
0.395091f,0.521661f,-0.238764f,0.208162f,0.939082f,0.0202279f, 0.376106f,0.517391f,-0.234159f,0.197876f,0.934406f,0.0233599f,
0.366055f,0.521981f,-0.229649f,0.18821f,0.929704f,0.0269063f, 0.343292f,0.51116f,-0.224146f,0.17826f,0.925032f,0.0309126f,
0.32594f,0.505092f,-0.218635f,0.168812f,0.920524f,0.0354454f, 0.313588f,0.504086f,-0.212934f,0.159706f,0.916233f,0.0405575f,
0.294385f,0.493215f,-0.206421f,0.150477f,0.91225f,0.0463148f, 0.276097f,0.481871f,-0.199347f,0.141316f,0.908727f,0.052807f,
0.2639f,0.477445f,-0.192721f,0.132932f,0.905757f,0.0601139f, 0.254756f,0.476421f,-0.186044f,0.124937f,0.903483f,0.0683409f,
0.23716f,0.461626f,-0.178489f,0.116768f,0.902065f,0.0776111f, 0.219502f,0.444931f,-0.170615f,0.108803f,0.901664f,0.0880636f,
0.208231f,0.436706f,-0.162979f,0.101385f,0.902435f,0.099852f, 0.199031f,0.430764f,-0.155778f,0.0945961f,0.904588f,0.113175f,
0.189041f,0.422429f,-0.14796f,0.0877772f,0.908307f,0.128246f, 0.172526f,0.400044f,-0.1388f,0.0805141f,0.913819f,0.145326f,
0.162158f,0.388796f,-0.130459f,0.0740647f,0.921356f,0.164717f, 0.14433f,0.360253f,-0.120756f,0.0671653f,0.9312f,0.186792f,
0.130487f,0.337831f,-0.111359f,0.0607492f,0.943657f,0.211992f, 0.119773f,0.320029f,-0.102276f,0.0547926f,0.959031f,0.240808f,
0.103039f,0.287524f,-0.0913715f,0.0481477f,0.977558f,0.27372f, 0.0881035f,0.257784f,-0.08039f,0.0417378f,0.999299f,0.310526f,
1.00003f,-2.16597e-07f,3.59622e-19f,0.585272f,0.999729f,5.72188e-06f, 0.999538f,0.0223956f,-0.0131206f,0.585543f,0.999798f,5.36124e-06f,
0.998144f,0.0447845f,-0.0262113f,0.584661f,0.999783f,5.97773e-06f, 0.995847f,0.067108f,-0.0392447f,0.583228f,0.999758f,7.05873e-06f,
0.992593f,0.0893018f,-0.0521885f,0.581193f,0.99972f,8.68725e-06f, 0.988484f,0.111335f,-0.0650162f,0.578601f,0.999668f,1.09849e-05f,
0.983427f,0.133146f,-0.0776961f,0.575434f,0.9996f,1.41174e-05f, 0.977517f,0.154747f,-0.0902033f,0.571731f,0.999512f,1.8301e-05f,
0.970703f,0.176053f,-0.102503f,0.56746f,0.999401f,2.3818e-05f, 0.963012f,0.197058f,-0.11457f,0.562642f,0.999265f,3.10334e-05f,
0.954462f,0.217672f,-0.126376f,0.55731f,0.999095f,4.03583e-05f, 0.945093f,0.237918f,-0.137886f,0.551452f,0.998881f,5.23055e-05f,
0.934922f,0.257713f,-0.149073f,0.545078f,0.998619f,6.75208e-05f, 0.923928f,0.277043f,-0.159912f,0.53823f,0.998297f,8.6724e-05f,
0.912216f,0.295904f,-0.170372f,0.530908f,0.997907f,0.000110811f, 0.899722f,0.314205f,-0.18042f,0.523121f,0.99743f,0.00014072f,
0.886538f,0.331929f,-0.19003f,0.514901f,0.996851f,0.000177547f, 0.872534f,0.349026f,-0.199174f,0.506262f,0.996159f,0.000222534f,
0.857841f,0.365469f,-0.207815f,0.497201f,0.995333f,0.000276988f, 0.842588f,0.381269f,-0.21595f,0.487786f,0.994363f,0.000342439f,
0.826791f,0.396401f,-0.223551f,0.478012f,0.993248f,0.000420761f, 0.81056f,0.410895f,-0.230649f,0.467938f,0.992023f,0.000515139f,
0.793395f,0.42452f,-0.237338f,0.457546f,0.990896f,0.000634805f, 0.775767f,0.43742f,-0.243563f,0.446875f,0.989778f,0.000784231f,
0.758024f,0.449673f,-0.249164f,0.43592f,0.988445f,0.000962194f, 0.739699f,0.461065f,-0.25415f,0.424751f,0.986875f,0.00117257f,
0.720738f,0.471491f,-0.258518f,0.413412f,0.985052f,0.00141951f, 0.701561f,0.48113f,-0.26226f,0.401899f,0.982988f,0.00170886f,
0.682751f,0.49032f,-0.265481f,0.390255f,0.980855f,0.0020556f, 0.663739f,0.498751f,-0.268171f,0.37851f,0.978621f,0.00246983f,
0.644177f,0.506097f,-0.270236f,0.366722f,0.976067f,0.00294896f, 0.624622f,0.512693f,-0.27172f,0.354915f,0.973259f,0.00350523f,
0.605987f,0.519217f,-0.272659f,0.343012f,0.970403f,0.00416532f, 0.584989f,0.523294f,-0.272966f,0.331108f,0.967218f,0.00492309f,
0.56125f,0.524375f,-0.272143f,0.318532f,0.963875f,0.00580463f, 0.542532f,0.528233f,-0.271249f,0.306602f,0.960314f,0.00682181f,
0.522674f,0.530389f,-0.269922f,0.294861f,0.956563f,0.00799333f, 0.508359f,0.536306f,-0.268208f,0.283361f,0.952618f,0.00933794f,
0.484213f,0.532951f,-0.265657f,0.271614f,0.948537f,0.0108816f, 0.464988f,0.532752f,-0.26281f,0.260227f,0.944264f,0.0126393f,
0.453724f,0.539177f,-0.259746f,0.249213f,0.93993f,0.0146515f, 0.428394f,0.531151f,-0.25576f,0.237925f,0.935498f,0.0169374f,
0.416707f,0.535376f,-0.251827f,0.227282f,0.93101f,0.0195298f, 0.394586f,0.528185f,-0.247123f,0.216496f,0.926575f,0.0224753f,
0.377015f,0.524465f,-0.242366f,0.20622f,0.922199f,0.025806f, 0.363244f,0.523858f,-0.237173f,0.196106f,0.917954f,0.029568f,
0.34489f,0.517029f,-0.231546f,0.186143f,0.913957f,0.0338222f, 0.331862f,0.515256f,-0.225343f,0.176232f,0.910237f,0.0386137f,
0.3112f,0.503003f,-0.21853f,0.166341f,0.906948f,0.0440245f, 0.302368f,0.504764f,-0.212328f,0.157394f,0.904142f,0.0501165f,
0.280726f,0.487833f,-0.204966f,0.148045f,0.901951f,0.0569813f, 0.271305f,0.48645f,-0.198129f,0.13952f,0.900501f,0.0647203f,
0.253055f,0.471366f,-0.190451f,0.130826f,0.89992f,0.0734487f, 0.243237f,0.467192f,-0.183062f,0.122744f,0.900345f,0.0832976f,
0.225481f,0.449732f,-0.175112f,0.114682f,0.901904f,0.094411f, 0.213455f,0.439585f,-0.167068f,0.10694f,0.904786f,0.106981f,
0.202763f,0.430439f,-0.1587f,0.0993596f,0.90915f,0.121208f, 0.187065f,0.411694f,-0.150496f,0.0922321f,0.915192f,0.13734f,
0.175028f,0.397026f,-0.140813f,0.0845446f,0.923126f,0.155669f, 0.157702f,0.371425f,-0.131016f,0.0771383f,0.933151f,0.176509f,
0.145492f,0.353628f,-0.121651f,0.0703098f,0.945522f,0.200255f, 0.132265f,0.332254f,-0.11183f,0.0635117f,0.960635f,0.227463f,
0.117902f,0.307337f,-0.100814f,0.0563499f,0.978465f,0.258385f, 0.0981689f,0.269595f,-0.0889951f,0.0490227f,0.999333f,0.293076f,
0.999995f,1.06917e-05f,5.08104e-19f,0.620802f,0.999281f,8.65872e-06f, 0.999541f,0.0223699f,-0.0138819f,0.621147f,0.999445f,8.15562e-06f,
0.998145f,0.0447584f,-0.0277297f,0.620199f,0.999412f,8.99237e-06f, 0.995895f,0.0670622f,-0.0415126f,0.61867f,0.999356f,1.04493e-05f,
0.992703f,0.0892416f,-0.0551956f,0.61652f,0.999275f,1.26221e-05f, 0.988641f,0.111253f,-0.0687489f,0.613762f,0.999171f,1.56691e-05f,
0.983667f,0.133064f,-0.082139f,0.610421f,0.999035f,1.97663e-05f, 0.977788f,0.154634f,-0.0953268f,0.606462f,0.998861f,2.51532e-05f,
0.971112f,0.175923f,-0.108287f,0.601946f,0.998644f,3.21325e-05f, 0.963577f,0.196893f,-0.120982f,0.596849f,0.998379f,4.10858e-05f,
0.955132f,0.217495f,-0.133382f,0.591192f,0.998059f,5.24653e-05f, 0.945902f,0.237706f,-0.145448f,0.584982f,0.997671f,6.6773e-05f,
0.935909f,0.257502f,-0.157151f,0.578243f,0.997203f,8.46068e-05f, 0.925186f,0.276833f,-0.168465f,0.571014f,0.996644f,0.000106656f,
0.913714f,0.295657f,-0.179348f,0.563275f,0.995982f,0.000133685f, 0.901471f,0.313938f,-0.189769f,0.55505f,0.9952f,0.000166503f,
0.888478f,0.331625f,-0.199719f,0.546412f,0.994288f,0.000206043f, 0.874775f,0.348714f,-0.209153f,0.537312f,0.993241f,0.000253414f,
0.860483f,0.365185f,-0.218081f,0.52783f,0.992066f,0.000310113f, 0.845747f,0.38109f,-0.226511f,0.517941f,0.990827f,0.000379107f,
0.830491f,0.396397f,-0.2346f,0.507721f,0.989738f,0.000468482f, 0.814345f,0.410877f,-0.242149f,0.497189f,0.988525f,0.000576931f,
0.797632f,0.424607f,-0.249073f,0.486325f,0.987107f,0.000705763f, 0.78087f,0.437755f,-0.25536f,0.475168f,0.985468f,0.0008577f,
0.763777f,0.450192f,-0.261037f,0.463815f,0.983598f,0.00103579f, 0.745981f,0.461702f,-0.266092f,0.45224f,0.981525f,0.00124474f,
0.727998f,0.472529f,-0.270647f,0.440495f,0.979425f,0.00149688f, 0.710107f,0.48279f,-0.274594f,0.428548f,0.97718f,0.00179583f,
0.69219f,0.49241f,-0.27791f,0.416525f,0.974653f,0.00214162f, 0.673564f,0.50094f,-0.280637f,0.404442f,0.971909f,0.00254353f,
0.655198f,0.508993f,-0.28288f,0.392318f,0.969122f,0.00302086f, 0.636564f,0.516161f,-0.284281f,0.379885f,0.966043f,0.00356896f,
0.622084f,0.525363f,-0.284776f,0.367006f,0.962808f,0.00420584f, 0.598778f,0.527875f,-0.285062f,0.354614f,0.959411f,0.00494361f,
0.574778f,0.528775f,-0.284677f,0.342149f,0.955804f,0.00579063f, 0.559643f,0.5353f,-0.283919f,0.329929f,0.952078f,0.00676879f,
0.540185f,0.537832f,-0.282681f,0.317863f,0.94818f,0.00788802f, 0.5182f,0.537371f,-0.280807f,0.305758f,0.944153f,0.00916927f,
0.501625f,0.540356f,-0.278444f,0.293779f,0.940041f,0.0106347f, 0.482511f,0.540362f,-0.27562f,0.281982f,0.935811f,0.0122996f,
0.471508f,0.546715f,-0.272616f,0.270602f,0.931582f,0.0141998f, 0.447569f,0.540385f,-0.26874f,0.258973f,0.927331f,0.0163549f,
0.442374f,0.551334f,-0.267339f,0.25026f,0.923108f,0.0187959f, 0.415004f,0.538913f,-0.260304f,0.236834f,0.919008f,0.0215651f,
0.397071f,0.53509f,-0.255482f,0.226055f,0.915038f,0.0246915f, 0.383022f,0.534242f,-0.250086f,0.215305f,0.911307f,0.0282279f,
0.361645f,0.524294f,-0.243698f,0.204253f,0.907855f,0.0322167f, 0.350249f,0.524324f,-0.237828f,0.194155f,0.90479f,0.0367211f,
0.330518f,0.513751f,-0.231342f,0.184054f,0.902166f,0.0417962f, 0.32027f,0.513336f,-0.224899f,0.174467f,0.900094f,0.04752f,
0.300055f,0.499406f,-0.217645f,0.164716f,0.898674f,0.0539759f, 0.28818f,0.494781f,-0.210453f,0.155468f,0.898005f,0.0612573f,
0.27828f,0.492022f,-0.203223f,0.146619f,0.898205f,0.0694765f, 0.259183f,0.475221f,-0.195063f,0.137526f,0.899381f,0.0787537f,
0.249366f,0.470264f,-0.187675f,0.12938f,0.901667f,0.0892377f, 0.238643f,0.463502f,-0.179605f,0.121145f,0.905195f,0.101094f,
0.217283f,0.438082f,-0.170064f,0.11231f,0.910125f,0.114524f, 0.205953f,0.427272f,-0.161196f,0.104301f,0.916616f,0.129755f,
0.188714f,0.40531f,-0.151649f,0.0962169f,0.924825f,0.147039f, 0.17669f,0.390691f,-0.14215f,0.0885069f,0.935013f,0.166729f,
0.165088f,0.375623f,-0.132816f,0.0812296f,0.94733f,0.189145f, 0.146387f,0.34567f,-0.12189f,0.0732975f,0.962084f,0.214757f,
0.130261f,0.319187f,-0.110273f,0.0652933f,0.979281f,0.24383f, 0.114355f,0.292135f,-0.0985166f,0.0574945f,0.999363f,0.276555f,
0.999994f,-2.92845e-06f,-3.78045e-19f,0.657499f,0.998335f,1.26103e-05f, 0.999556f,0.0223323f,-0.0146268f,0.65791f,0.99867f,1.19956e-05f,
0.998202f,0.0446799f,-0.0292168f,0.656929f,0.998612f,1.30976e-05f, 0.995967f,0.0669604f,-0.0437312f,0.655296f,0.998511f,1.49979e-05f,
0.992804f,0.0890906f,-0.0581296f,0.652991f,0.998363f,1.78003e-05f, 0.988833f,0.111084f,-0.0723803f,0.650072f,0.998168f,2.16657e-05f,
0.983981f,0.132865f,-0.0864468f,0.646538f,0.997921f,2.68017e-05f, 0.978199f,0.154377f,-0.10028f,0.642322f,0.997613f,3.34545e-05f,
0.971692f,0.175641f,-0.11386f,0.637563f,0.997236f,4.19266e-05f, 0.96586f,0.196918f,-0.127163f,0.632303f,0.996783f,5.25822e-05f,
0.956044f,0.217138f,-0.140075f,0.626195f,0.996243f,6.58381e-05f, 0.947036f,0.237302f,-0.152635f,0.619619f,0.995606f,8.21644e-05f,
0.937267f,0.257049f,-0.164796f,0.612531f,0.994858f,0.000102071f, 0.926786f,0.276319f,-0.176508f,0.604883f,0.99399f,0.000126138f,
0.915662f,0.295134f,-0.187764f,0.596763f,0.992995f,0.000155023f, 0.903921f,0.313425f,-0.198531f,0.58815f,0.991872f,0.000189541f,
0.891103f,0.331056f,-0.20882f,0.579104f,0.990646f,0.000231001f, 0.877957f,0.348245f,-0.218676f,0.569581f,0.989432f,0.000282718f,
0.864158f,0.364859f,-0.228163f,0.559678f,0.988299f,0.000349011f, 0.849958f,0.380873f,-0.237042f,0.549345f,0.986987f,0.000428153f,
0.838709f,0.397563f,-0.245339f,0.538725f,0.985481f,0.000521914f, 0.81933f,0.410692f,-0.253015f,0.527791f,0.983765f,0.000632173f,
0.803926f,0.42479f,-0.260023f,0.516487f,0.981843f,0.000761311f, 0.787993f,0.438151f,-0.266441f,0.504957f,0.979753f,0.000913153f,
0.773358f,0.451611f,-0.272326f,0.493116f,0.97767f,0.00109765f, 0.75773f,0.464194f,-0.277486f,0.480905f,0.975399f,0.00131428f,
0.73784f,0.473975f,-0.28235f,0.469155f,0.972878f,0.0015648f, 0.721684f,0.485027f,-0.286369f,0.456865f,0.970178f,0.00185658f,
0.703417f,0.494393f,-0.289919f,0.444542f,0.967438f,0.00220313f, 0.692197f,0.50714f,-0.292607f,0.431834f,0.964431f,0.0026007f,
0.662942f,0.508637f,-0.294184f,0.418323f,0.961285f,0.00306264f, 0.64606f,0.516651f,-0.295748f,0.405611f,0.958006f,0.00359876f,
0.626184f,0.522109f,-0.296779f,0.392996f,0.95452f,0.00421292f, 0.607497f,0.527448f,-0.29717f,0.380249f,0.950962f,0.00492529f,
0.590893f,0.533456f,-0.296946f,0.367516f,0.947212f,0.00573773f, 0.573644f,0.538328f,-0.296327f,0.354991f,0.943396f,0.00667315f,
0.559463f,0.544764f,-0.29517f,0.342549f,0.939458f,0.00773967f, 0.536249f,0.543496f,-0.293315f,0.329993f,0.935447f,0.00895678f,
0.523546f,0.549579f,-0.291071f,0.317671f,0.931408f,0.0103451f, 0.503802f,0.549236f,-0.288414f,0.305573f,0.927324f,0.0119194f,
0.497171f,0.558398f,-0.287454f,0.295823f,0.923299f,0.0137122f, 0.468579f,0.549295f,-0.281794f,0.281863f,0.919322f,0.0157419f,
0.45997f,0.556305f,-0.277972f,0.270398f,0.915455f,0.0180402f, 0.436418f,0.548434f,-0.273393f,0.258774f,0.911765f,0.0206424f,
0.417134f,0.543476f,-0.268285f,0.247236f,0.90828f,0.02358f, 0.401947f,0.541458f,-0.262443f,0.235586f,0.905094f,0.0269016f,
0.382799f,0.534335f,-0.256741f,0.224617f,0.902249f,0.0306487f, 0.369224f,0.532065f,-0.250712f,0.213887f,0.899818f,0.0348753f,
0.3603f,0.534256f,-0.244652f,0.203626f,0.897896f,0.0396467f, 0.338388f,0.520494f,-0.237622f,0.193049f,0.896551f,0.0450293f,
0.3288f,0.520145f,-0.230889f,0.183192f,0.895862f,0.0511001f, 0.306797f,0.503501f,-0.223124f,0.172981f,0.895925f,0.0579517f,
0.295171f,0.498521f,-0.215558f,0.163376f,0.896849f,0.0656922f, 0.285004f,0.494633f,-0.208133f,0.154307f,0.898703f,0.0744285f,
0.265935f,0.477534f,-0.199898f,0.145045f,0.901637f,0.0843151f, 0.254225f,0.46937f,-0.191331f,0.135954f,0.905745f,0.0955007f,
0.23497f,0.448833f,-0.181942f,0.126685f,0.911157f,0.108169f, 0.220975f,0.434696f,-0.172654f,0.117881f,0.918012f,0.122535f,
0.20859f,0.421742f,-0.163261f,0.109373f,0.926502f,0.138868f, 0.191426f,0.399957f,-0.153117f,0.100732f,0.936733f,0.157417f,
0.179255f,0.384943f,-0.143497f,0.0927743f,0.94901f,0.1786f, 0.164948f,0.364995f,-0.132703f,0.0844014f,0.963388f,0.20269f,
0.143635f,0.331105f,-0.120224f,0.0753065f,0.98011f,0.230132f, 0.12604f,0.302971f,-0.107986f,0.0666805f,0.999391f,0.260945f,
1.0f,7.75253e-06f,4.13573e-19f,0.695277f,0.996536f,1.75189e-05f, 0.999565f,0.0222618f,-0.0153218f,0.695747f,0.997176f,1.70283e-05f,
0.998241f,0.0445601f,-0.0306049f,0.694711f,0.997077f,1.84044e-05f, 0.996071f,0.0667558f,-0.0458007f,0.692989f,0.996905f,2.076e-05f,
0.992992f,0.0888222f,-0.0608643f,0.69056f,0.996663f,2.42174e-05f, 0.989124f,0.110741f,-0.0757557f,0.687466f,0.996344f,2.89203e-05f,
0.9844f,0.132456f,-0.0904321f,0.683703f,0.995941f,3.50623e-05f, 0.978842f,0.153919f,-0.104852f,0.679283f,0.995448f,4.28882e-05f,
0.972484f,0.175097f,-0.118974f,0.674227f,0.994855f,5.26632e-05f, 0.965252f,0.195943f,-0.132758f,0.668547f,0.994154f,6.47106e-05f,
0.957265f,0.216433f,-0.146163f,0.662245f,0.993338f,7.93851e-05f, 0.948549f,0.236538f,-0.159159f,0.65537f,0.992396f,9.70641e-05f,
0.939153f,0.256217f,-0.17171f,0.6479f,0.991331f,0.000118256f, 0.929109f,0.275476f,-0.183803f,0.639897f,0.990146f,0.000143574f,
0.918424f,0.294256f,-0.195451f,0.631378f,0.988885f,0.000174233f, 0.907016f,0.312591f,-0.206804f,0.622463f,0.987715f,0.000213762f,
0.894734f,0.33032f,-0.217661f,0.613011f,0.986482f,0.000262522f, 0.881969f,0.34751f,-0.227943f,0.603139f,0.985073f,0.000320533f,
0.869013f,0.364225f,-0.237592f,0.592784f,0.983478f,0.000389075f, 0.861981f,0.382725f,-0.247291f,0.583639f,0.981689f,0.000469496f,
0.8416f,0.395799f,-0.255083f,0.571119f,0.979713f,0.000563604f, 0.826542f,0.410416f,-0.262916f,0.559761f,0.97761f,0.000674789f,
0.818548f,0.42705f,-0.270193f,0.547965f,0.975521f,0.00081033f, 0.797326f,0.438546f,-0.276944f,0.536198f,0.973215f,0.000967937f,
0.781873f,0.451495f,-0.283044f,0.524226f,0.970689f,0.00115019f, 0.765977f,0.463737f,-0.288462f,0.511904f,0.968031f,0.00136342f,
0.750524f,0.475592f,-0.293351f,0.499454f,0.96531f,0.00161567f, 0.733664f,0.486212f,-0.29744f,0.486664f,0.962351f,0.00190492f,
0.710983f,0.493076f,-0.300373f,0.472879f,0.959279f,0.00224146f, 0.693255f,0.501824f,-0.303283f,0.459945f,0.956086f,0.00263192f,
0.67732f,0.510865f,-0.305448f,0.446796f,0.952705f,0.00307898f, 0.671066f,0.525151f,-0.307199f,0.433807f,0.949272f,0.00359841f,
0.65063f,0.532242f,-0.309747f,0.422746f,0.945656f,0.00419014f, 0.624718f,0.53117f,-0.308883f,0.407764f,0.942f,0.00487321f,
0.608899f,0.537647f,-0.308736f,0.394609f,0.938209f,0.00565025f, 0.596782f,0.545773f,-0.308279f,0.381777f,0.934391f,0.00654137f,
0.57167f,0.54459f,-0.30727f,0.368997f,0.930512f,0.00755521f, 0.556411f,0.54925f,-0.30561f,0.356146f,0.926613f,0.00870889f,
0.545949f,0.556997f,-0.303526f,0.343479f,0.922745f,0.0100222f, 0.525833f,0.556481f,-0.301027f,0.331025f,0.918898f,0.0115091f,
0.515788f,0.563425f,-0.298218f,0.318853f,0.915167f,0.0131992f, 0.491001f,0.55714f,-0.294641f,0.306501f,0.911537f,0.015109f,
0.480991f,0.562692f,-0.290676f,0.29435f,0.908103f,0.0172736f, 0.455796f,0.553671f,-0.285562f,0.281664f,0.90487f,0.0197166f,
0.447601f,0.5595f,-0.280807f,0.269916f,0.901937f,0.0224815f, 0.422859f,0.548541f,-0.275378f,0.258097f,0.899316f,0.0255992f,
0.416442f,0.554221f,-0.271908f,0.248614f,0.897093f,0.0291199f, 0.390776f,0.540418f,-0.263699f,0.235328f,0.895334f,0.0330955f,
0.379113f,0.539543f,-0.257427f,0.224337f,0.894091f,0.0375805f, 0.369663f,0.540479f,-0.251011f,0.213716f,0.893436f,0.0426409f,
0.346857f,0.52526f,-0.243569f,0.202713f,0.893441f,0.0483514f, 0.336641f,0.523518f,-0.236395f,0.192407f,0.894198f,0.0548027f,
0.314162f,0.505955f,-0.228246f,0.181772f,0.895782f,0.0620912f, 0.302313f,0.500179f,-0.220773f,0.172122f,0.898272f,0.0703271f,
0.291072f,0.494117f,-0.212565f,0.162323f,0.901767f,0.0796413f, 0.27165f,0.476453f,-0.203576f,0.152353f,0.906378f,0.090188f,
0.258279f,0.465506f,-0.194382f,0.142646f,0.912218f,0.102143f, 0.248673f,0.460569f,-0.187153f,0.134752f,0.919412f,0.115708f,
0.225241f,0.43078f,-0.174883f,0.123627f,0.928075f,0.131105f, 0.210374f,0.413943f,-0.164657f,0.114356f,0.938398f,0.14863f,
0.197833f,0.399779f,-0.154838f,0.105729f,0.95054f,0.168594f, 0.18019f,0.37576f,-0.143424f,0.0963748f,0.964623f,0.191307f,
0.162933f,0.351577f,-0.131082f,0.0867579f,0.980917f,0.217237f, 0.138783f,0.314159f,-0.118008f,0.0770084f,0.999416f,0.246223f,
1.00001f,-7.48646e-06f,-1.97011e-19f,0.733962f,0.993399f,2.28938e-05f, 0.999606f,0.0221449f,-0.0159315f,0.734551f,0.994561f,2.3239e-05f,
0.998333f,0.0443189f,-0.0318138f,0.733442f,0.994407f,2.48692e-05f, 0.996205f,0.0664011f,-0.0475971f,0.731607f,0.99415f,2.76579e-05f,
0.993302f,0.0883696f,-0.0632316f,0.72906f,0.993787f,3.16978e-05f, 0.989544f,0.11016f,-0.0786713f,0.725809f,0.993309f,3.7112e-05f,
0.984982f,0.131755f,-0.0938694f,0.721845f,0.992714f,4.4083e-05f, 0.979691f,0.153108f,-0.108779f,0.717203f,0.991995f,5.27948e-05f,
0.974451f,0.174159f,-0.123363f,0.711926f,0.99115f,6.34859e-05f, 0.966685f,0.194907f,-0.13757f,0.705939f,0.990174f,7.64162e-05f,
0.959028f,0.215294f,-0.15138f,0.699337f,0.989071f,9.19404e-05f, 0.950703f,0.235315f,-0.164783f,0.692144f,0.987859f,0.000110601f,
0.94169f,0.254951f,-0.177812f,0.684384f,0.986606f,0.000133603f, 0.932124f,0.274234f,-0.190567f,0.676103f,0.985442f,0.000163589f,
0.922103f,0.293106f,-0.202776f,0.667231f,0.984125f,0.000199568f, 0.911023f,0.311343f,-0.214476f,0.658045f,0.982634f,0.000242247f,
0.899829f,0.329181f,-0.225521f,0.648186f,0.980963f,0.000292524f, 0.887966f,0.34642f,-0.235974f,0.637942f,0.97911f,0.000351419f,
0.8757f,0.363162f,-0.245793f,0.627221f,0.977093f,0.000420374f, 0.862919f,0.379344f,-0.255171f,0.616365f,0.975003f,0.000502756f,
0.849576f,0.394904f,-0.263997f,0.605072f,0.972875f,0.000602195f, 0.83659f,0.410145f,-0.272088f,0.593329f,0.970532f,0.000717285f,
0.822882f,0.424643f,-0.279553f,0.581389f,0.967998f,0.000850399f, 0.813198f,0.440413f,-0.286355f,0.569023f,0.965379f,0.00100715f,
0.79911f,0.453888f,-0.29264f,0.556592f,0.962663f,0.00119124f, 0.777142f,0.463348f,-0.298262f,0.544f,0.959741f,0.0014024f,
0.761163f,0.474737f,-0.302454f,0.529764f,0.956733f,0.00164866f, 0.740303f,0.483192f,-0.306975f,0.517088f,0.953604f,0.00193374f,
0.734299f,0.49839f,-0.310405f,0.503558f,0.950313f,0.00226025f, 0.708709f,0.50296f,-0.313608f,0.490489f,0.94698f,0.00263986f,
0.696882f,0.514135f,-0.315926f,0.476987f,0.943484f,0.00307223f, 0.676064f,0.519777f,-0.318051f,0.463984f,0.939956f,0.00357165f,
0.658462f,0.52641f,-0.319357f,0.450658f,0.936304f,0.00413957f, 0.643471f,0.533929f,-0.319951f,0.437095f,0.932641f,0.00479214f,
0.630759f,0.54238f,-0.319997f,0.423618f,0.928902f,0.00553319f, 0.618995f,0.550864f,-0.319754f,0.410497f,0.925174f,0.00637987f,
0.593321f,0.549261f,-0.319068f,0.397549f,0.921444f,0.00734152f, 0.578707f,0.554359f,-0.317541f,0.38427f,0.917749f,0.00843363f,
0.567561f,0.561276f,-0.315542f,0.37112f,0.914136f,0.00967416f, 0.548008f,0.561522f,-0.313383f,0.358472f,0.910606f,0.0110775f,
0.542354f,0.571766f,-0.310484f,0.345614f,0.90724f,0.0126698f, 0.513463f,0.562607f,-0.306894f,0.332652f,0.904034f,0.014468f,
0.50033f,0.565336f,-0.302363f,0.31931f,0.901072f,0.0165042f, 0.478247f,0.55963f,-0.298021f,0.306806f,0.898367f,0.0188028f,
0.46749f,0.562868f,-0.293285f,0.29449f,0.895978f,0.0213982f, 0.446049f,0.555681f,-0.288201f,0.28239f,0.893974f,0.0243323f,
0.432787f,0.555036f,-0.28258f,0.270329f,0.892383f,0.0276427f, 0.41433f,0.548499f,-0.276705f,0.258572f,0.891266f,0.0313788f,
0.399861f,0.544925f,-0.270248f,0.246801f,0.890685f,0.0355964f, 0.388745f,0.544506f,-0.263968f,0.235702f,0.890695f,0.0403571f,
0.378188f,0.543075f,-0.256799f,0.224307f,0.891356f,0.0457305f, 0.354662f,0.526868f,-0.249049f,0.212896f,0.892758f,0.051807f,
0.344114f,0.52415f,-0.241643f,0.202258f,0.894939f,0.0586675f, 0.324901f,0.510314f,-0.233796f,0.191697f,0.89801f,0.0664337f,
0.310076f,0.500443f,-0.225137f,0.180922f,0.902027f,0.0752178f, 0.295868f,0.490472f,-0.216067f,0.170264f,0.907088f,0.0851659f,
0.283559f,0.480594f,-0.207078f,0.160098f,0.913293f,0.0964424f, 0.270627f,0.471593f,-0.197634f,0.149996f,0.920739f,0.109231f,
0.24876f,0.447735f,-0.187219f,0.139565f,0.929577f,0.123769f, 0.236181f,0.435675f,-0.177751f,0.13023f,0.939943f,0.140314f,
0.221555f,0.41993f,-0.166744f,0.120156f,0.951922f,0.159113f, 0.197588f,0.388114f,-0.154649f,0.109678f,0.965806f,0.180605f,
0.178371f,0.362608f,-0.141772f,0.0990436f,0.981663f,0.205086f, 0.159531f,0.336796f,-0.128834f,0.0887512f,0.999439f,0.23236f,
0.999986f,2.18352e-06f,-2.75462e-19f,0.773385f,0.988544f,2.79955e-05f, 0.999594f,0.0219452f,-0.0164021f,0.774053f,0.990354f,3.03786e-05f,
0.998424f,0.0439368f,-0.0327489f,0.772913f,0.990143f,3.22148e-05f, 0.996432f,0.0658365f,-0.0489851f,0.770998f,0.989787f,3.53194e-05f,
0.993667f,0.0875962f,-0.0650595f,0.768334f,0.989286f,3.97704e-05f, 0.990129f,0.109217f,-0.0809183f,0.764909f,0.988639f,4.56698e-05f,
0.985835f,0.130612f,-0.0965169f,0.760776f,0.987843f,5.31415e-05f, 0.980877f,0.151806f,-0.111812f,0.755924f,0.986906f,6.23739e-05f,
0.975192f,0.17272f,-0.12678f,0.750428f,0.985833f,7.35994e-05f, 0.968583f,0.193317f,-0.141417f,0.744289f,0.984656f,8.73066e-05f,
0.961385f,0.213645f,-0.155799f,0.737475f,0.983501f,0.000104932f, 0.953545f,0.233637f,-0.169834f,0.730026f,0.982313f,0.000127152f,
0.945298f,0.253278f,-0.183361f,0.72197f,0.980954f,0.000153698f, 0.936527f,0.272485f,-0.196345f,0.713341f,0.979418f,0.000185134f,
0.92719f,0.291281f,-0.208805f,0.704322f,0.977705f,0.000222103f, 0.916928f,0.309492f,-0.220671f,0.694751f,0.975819f,0.00026536f,
0.906238f,0.327251f,-0.23195f,0.684664f,0.973787f,0.000316126f, 0.895804f,0.344739f,-0.242736f,0.674089f,0.971731f,0.000377613f,
0.884864f,0.361742f,-0.252948f,0.663108f,0.969564f,0.000450557f, 0.872645f,0.377912f,-0.262591f,0.651997f,0.967201f,0.000534892f,
0.860478f,0.393693f,-0.271584f,0.640523f,0.964669f,0.000632514f, 0.848202f,0.40903f,-0.279891f,0.628404f,0.962091f,0.000748247f,
0.834715f,0.423512f,-0.287622f,0.616135f,0.959382f,0.000882971f, 0.819123f,0.436629f,-0.294583f,0.603425f,0.956495f,0.00103762f,
0.799213f,0.447378f,-0.300531f,0.589653f,0.95355f,0.00121857f, 0.785286f,0.459964f,-0.306226f,0.576503f,0.950476f,0.00142723f,
0.771185f,0.471906f,-0.311304f,0.56326f,0.947267f,0.00166651f, 0.755885f,0.4828f,-0.315898f,0.550035f,0.944021f,0.00194465f,
0.73976f,0.492739f,-0.31982f,0.536674f,0.94063f,0.00226131f, 0.725827f,0.503127f,-0.322956f,0.52286f,0.937216f,0.00262731f,
0.711978f,0.513068f,-0.325602f,0.509228f,0.933691f,0.00304345f, 0.694066f,0.520212f,-0.327912f,0.495887f,0.930161f,0.00352187f,
0.678144f,0.527714f,-0.329462f,0.482283f,0.926559f,0.00406492f, 0.663808f,0.535533f,-0.330233f,0.468334f,0.92298f,0.00468658f,
0.651539f,0.543981f,-0.330539f,0.454571f,0.919381f,0.00539152f, 0.639842f,0.552826f,-0.330523f,0.441123f,0.915833f,0.00619447f,
0.625332f,0.558417f,-0.329923f,0.427655f,0.912335f,0.00710503f, 0.603094f,0.558527f,-0.328992f,0.41448f,0.908926f,0.0081378f,
0.588641f,0.563199f,-0.327101f,0.400806f,0.905639f,0.00930816f, 0.58401f,0.574446f,-0.324687f,0.3872f,0.902501f,0.0106326f,
0.560192f,0.564387f,-0.320696f,0.372436f,0.899552f,0.012131f, 0.534241f,0.564527f,-0.318223f,0.360106f,0.896834f,0.0138259f,
0.52021f,0.566458f,-0.314377f,0.346853f,0.894368f,0.0157388f, 0.513441f,0.573803f,-0.310286f,0.333946f,0.892225f,0.0179026f,
0.488675f,0.565312f,-0.305648f,0.321058f,0.890427f,0.0203452f, 0.478861f,0.566911f,-0.300419f,0.308149f,0.889018f,0.0231021f,
0.456488f,0.560357f,-0.295267f,0.295892f,0.88805f,0.0262146f, 0.443108f,0.559057f,-0.289318f,0.283389f,0.88757f,0.029729f,
0.439148f,0.568181f,-0.286732f,0.274646f,0.887628f,0.0336972f, 0.409923f,0.547867f,-0.276377f,0.258995f,0.88827f,0.0381773f,
0.396657f,0.544223f,-0.26934f,0.247048f,0.889552f,0.0432374f, 0.385963f,0.542626f,-0.262079f,0.235392f,0.891546f,0.04896f,
0.375519f,0.540662f,-0.254987f,0.224368f,0.894292f,0.0554259f, 0.351159f,0.522237f,-0.24659f,0.212668f,0.897863f,0.0627392f,
0.338981f,0.51636f,-0.238038f,0.201304f,0.902342f,0.0710214f, 0.327989f,0.512532f,-0.23032f,0.191083f,0.907798f,0.080403f,
0.301582f,0.486198f,-0.219341f,0.178612f,0.914322f,0.0910406f, 0.286956f,0.4745f,-0.209558f,0.167575f,0.922021f,0.10312f,
0.273354f,0.463219f,-0.199625f,0.156842f,0.930997f,0.116846f, 0.251768f,0.44013f,-0.188683f,0.145742f,0.941346f,0.132441f,
0.237253f,0.425383f,-0.178149f,0.135362f,0.953245f,0.150211f, 0.221286f,0.407692f,-0.166541f,0.124553f,0.966891f,0.170519f,
0.194899f,0.373501f,-0.152882f,0.112631f,0.982343f,0.193646f, 0.174009f,0.346609f,-0.139556f,0.101386f,0.999459f,0.219327f,
0.999997f,-5.76298e-06f,-1.09224e-19f,0.813825f,0.982848f,3.5679e-05f, 0.999662f,0.0216601f,-0.0166899f,0.814086f,0.98408f,3.79345e-05f,
0.998565f,0.0433493f,-0.0333246f,0.812877f,0.98381f,3.98682e-05f, 0.996711f,0.0649529f,-0.0498431f,0.810895f,0.983365f,4.31294e-05f,
0.994173f,0.0864513f,-0.0661993f,0.808137f,0.982745f,4.77678e-05f, 0.99093f,0.107788f,-0.0823463f,0.804622f,0.981959f,5.38842e-05f,
0.986996f,0.128955f,-0.0982488f,0.800328f,0.981026f,6.16594e-05f, 0.982442f,0.149926f,-0.113927f,0.795368f,0.979996f,7.15323e-05f,
0.982896f,0.171415f,-0.129405f,0.789293f,0.978997f,8.47397e-05f, 0.971261f,0.191226f,-0.144665f,0.783444f,0.977856f,0.000100992f,
0.964646f,0.211397f,-0.159382f,0.776401f,0.976531f,0.000120465f, 0.957683f,0.231257f,-0.173604f,0.768718f,0.975022f,0.000143547f,
0.950157f,0.25074f,-0.187303f,0.760419f,0.973331f,0.000170701f, 0.942227f,0.269871f,-0.200475f,0.751589f,0.97147f,0.000202526f,
0.933994f,0.288633f,-0.213178f,0.742407f,0.969484f,0.000240083f, 0.924485f,0.306855f,-0.225444f,0.732636f,0.967488f,0.00028597f,
0.915279f,0.324796f,-0.23713f,0.722458f,0.965324f,0.000339584f, 0.905537f,0.342234f,-0.248101f,0.711612f,0.962976f,0.000401545f,
0.899874f,0.360641f,-0.258162f,0.699571f,0.960483f,0.000473457f, 0.884955f,0.37582f,-0.268481f,0.68923f,0.957961f,0.000559111f,
0.872451f,0.391302f,-0.277682f,0.677297f,0.955279f,0.000657974f, 0.865273f,0.408182f,-0.285616f,0.66365f,0.952444f,0.000771597f,
0.840471f,0.418342f,-0.293369f,0.650681f,0.949572f,0.000905f, 0.827204f,0.431973f,-0.300707f,0.63803f,0.94656f,0.00105808f,
0.815958f,0.445954f,-0.307285f,0.624886f,0.943446f,0.00123419f, 0.80019f,0.457667f,-0.313343f,0.611692f,0.940283f,0.00143832f,
0.785901f,0.469094f,-0.318194f,0.59731f,0.936996f,0.00167084f, 0.772661f,0.480996f,-0.32358f,0.584854f,0.933694f,0.00193973f,
0.757782f,0.491328f,-0.327737f,0.571194f,0.93029f,0.00224526f, 0.74463f,0.501932f,-0.331112f,0.557073f,0.926886f,0.00259672f,
0.736318f,0.514444f,-0.333804f,0.54281f,0.923418f,0.00299557f, 0.715692f,0.520257f,-0.336694f,0.529705f,0.919975f,0.00345247f,
0.710346f,0.533238f,-0.338176f,0.51529f,0.916509f,0.00397018f, 0.687329f,0.536483f,-0.339743f,0.501811f,0.913102f,0.00456104f,
0.674647f,0.544645f,-0.340315f,0.487701f,0.909724f,0.00523007f, 0.67859f,0.563682f,-0.344263f,0.479053f,0.90644f,0.00599065f,
0.649734f,0.559823f,-0.340009f,0.45978f,0.903248f,0.00685142f, 0.626354f,0.559518f,-0.3393f,0.446186f,0.900197f,0.0078274f,
0.609657f,0.562535f,-0.336774f,0.430974f,0.897297f,0.00893039f, 0.60193f,0.571042f,-0.334649f,0.417012f,0.894607f,0.0101802f,
0.58044f,0.569517f,-0.332288f,0.403463f,0.892127f,0.0115904f, 0.575153f,0.578938f,-0.329261f,0.389764f,0.889922f,0.0131861f,
0.545629f,0.569607f,-0.325988f,0.376427f,0.888012f,0.0149882f, 0.532706f,0.571938f,-0.321928f,0.362822f,0.886428f,0.0170222f,
0.514309f,0.569219f,-0.317603f,0.349541f,0.885215f,0.0193188f, 0.500183f,0.569076f,-0.312654f,0.336178f,0.884413f,0.0219123f,
0.489884f,0.57165f,-0.307334f,0.323009f,0.88406f,0.0248408f, 0.467961f,0.563333f,-0.301801f,0.310186f,0.884199f,0.0281483f,
0.453373f,0.560496f,-0.295528f,0.297165f,0.884868f,0.0318836f, 0.442551f,0.560222f,-0.288955f,0.284397f,0.886103f,0.0361f,
0.432223f,0.560454f,-0.282212f,0.271986f,0.887972f,0.0408685f, 0.405988f,0.543777f,-0.274611f,0.259276f,0.890503f,0.0462553f,
0.393991f,0.540359f,-0.26753f,0.247551f,0.893773f,0.0523533f, 0.38201f,0.536305f,-0.259394f,0.235341f,0.897818f,0.0592503f,
0.359287f,0.519765f,-0.250573f,0.223f,0.90271f,0.0670602f, 0.343913f,0.510096f,-0.241501f,0.210918f,0.908523f,0.0759123f,
0.33068f,0.502054f,-0.232209f,0.19911f,0.915335f,0.085954f, 0.316902f,0.492615f,-0.222534f,0.187428f,0.923228f,0.097353f,
0.29143f,0.467748f,-0.211699f,0.175228f,0.93229f,0.110298f, 0.276381f,0.454652f,-0.201539f,0.164025f,0.942654f,0.12503f,
0.260724f,0.439911f,-0.190402f,0.152443f,0.954472f,0.141837f, 0.23903f,0.415785f,-0.178046f,0.140313f,0.967873f,0.161019f,
0.218901f,0.393415f,-0.164746f,0.127886f,0.98296f,0.182889f, 0.189965f,0.357047f,-0.150789f,0.115422f,0.999478f,0.207089f,
1.00001f,-7.37437e-06f,-8.35803e-19f,0.854517f,0.974495f,4.26037e-05f, 0.999712f,0.0212535f,-0.0167762f,0.854317f,0.975335f,4.51403e-05f,
0.998746f,0.0425228f,-0.0335032f,0.853098f,0.975036f,4.70854e-05f, 0.99711f,0.0637377f,-0.0501383f,0.851076f,0.974546f,5.03768e-05f,
0.994846f,0.0848566f,-0.0666573f,0.848263f,0.973896f,5.51586e-05f, 0.991967f,0.105892f,-0.0831057f,0.844679f,0.973164f,6.18981e-05f,
0.988556f,0.126835f,-0.0994733f,0.840343f,0.972391f,7.12012e-05f, 0.984665f,0.14758f,-0.115521f,0.835275f,0.971418f,8.27526e-05f,
0.980225f,0.1681f,-0.13122f,0.82963f,0.970242f,9.67772e-05f, 0.974853f,0.188304f,-0.146483f,0.82315f,0.968869f,0.000113538f,
0.968924f,0.208202f,-0.161294f,0.815976f,0.967304f,0.000133361f, 0.962908f,0.227862f,-0.175631f,0.80812f,0.965568f,0.000156715f,
0.95617f,0.247193f,-0.189576f,0.79979f,0.96373f,0.000184676f, 0.949721f,0.266356f,-0.203105f,0.790798f,0.961838f,0.000218679f,
0.942125f,0.28501f,-0.21614f,0.78162f,0.959752f,0.00025811f, 0.93376f,0.303178f,-0.228538f,0.771745f,0.957487f,0.000303714f,
0.925022f,0.320946f,-0.240363f,0.761324f,0.9551f,0.000356953f, 0.916535f,0.338466f,-0.251641f,0.750282f,0.952673f,0.00042035f,
0.913214f,0.357141f,-0.261989f,0.738073f,0.950069f,0.000493067f, 0.893931f,0.370911f,-0.271943f,0.726194f,0.947332f,0.000576857f,
0.876028f,0.384343f,-0.281215f,0.713606f,0.944561f,0.000675388f, 0.864916f,0.399345f,-0.289951f,0.701075f,0.94164f,0.00078795f,
0.85395f,0.414096f,-0.298018f,0.688117f,0.938646f,0.000918f, 0.84164f,0.427813f,-0.30568f,0.675369f,0.935583f,0.00106805f,
0.829987f,0.441312f,-0.312568f,0.662114f,0.932418f,0.00123925f, 0.817255f,0.453931f,-0.318818f,0.648525f,0.929238f,0.00143721f,
0.815289f,0.470598f,-0.323961f,0.633893f,0.925965f,0.00166203f, 0.791386f,0.477633f,-0.329715f,0.621408f,0.922696f,0.00192078f,
0.789055f,0.493471f,-0.333551f,0.606379f,0.919368f,0.00221426f, 0.765843f,0.49939f,-0.337955f,0.593309f,0.916066f,0.00255061f,
0.753964f,0.510014f,-0.341094f,0.578992f,0.912741f,0.0029316f, 0.750523f,0.524541f,-0.343573f,0.564448f,0.909474f,0.00336676f,
0.727431f,0.528426f,-0.34631f,0.551238f,0.906228f,0.00385912f, 0.711287f,0.5352f,-0.348044f,0.537225f,0.903074f,0.00441968f,
0.698411f,0.543206f,-0.348793f,0.522563f,0.899993f,0.00505338f, 0.687592f,0.551842f,-0.34883f,0.507654f,0.897047f,0.0057731f,
0.674395f,0.558595f,-0.348372f,0.492873f,0.894224f,0.00658579f, 0.658542f,0.563264f,-0.347444f,0.478198f,0.891593f,0.00750762f,
0.633571f,0.561399f,-0.346508f,0.464283f,0.889142f,0.00854769f, 0.623613f,0.568294f,-0.344483f,0.449628f,0.886931f,0.00972473f,
0.615461f,0.57601f,-0.342172f,0.435324f,0.884976f,0.0110546f, 0.593307f,0.573651f,-0.339653f,0.421452f,0.883301f,0.0125555f,
0.588011f,0.581966f,-0.336622f,0.407605f,0.881945f,0.0142504f, 0.575334f,0.57782f,-0.332646f,0.393271f,0.880943f,0.0161648f,
0.544343f,0.57388f,-0.328727f,0.379644f,0.880324f,0.0183265f, 0.536141f,0.578832f,-0.324005f,0.36571f,0.88012f,0.0207671f,
0.512539f,0.570922f,-0.319028f,0.352097f,0.880366f,0.0235235f, 0.499624f,0.570764f,-0.313445f,0.338405f,0.881099f,0.0266374f,
0.4902f,0.573043f,-0.307532f,0.324941f,0.882349f,0.0301542f, 0.46514f,0.561008f,-0.301177f,0.311579f,0.884147f,0.0341248f,
0.450657f,0.557273f,-0.294248f,0.298169f,0.886559f,0.0386185f, 0.440707f,0.556808f,-0.287751f,0.285733f,0.889599f,0.0436951f,
0.429127f,0.554815f,-0.28019f,0.272752f,0.893329f,0.0494395f, 0.403473f,0.537886f,-0.271781f,0.259465f,0.89781f,0.055947f,
0.387306f,0.529239f,-0.26299f,0.246334f,0.903082f,0.0633165f, 0.374266f,0.523028f,-0.254136f,0.233646f,0.909211f,0.0716698f,
0.351846f,0.506043f,-0.24465f,0.220868f,0.916266f,0.0811453f, 0.335053f,0.493945f,-0.234647f,0.208109f,0.924323f,0.0919011f,
0.319403f,0.482309f,-0.22429f,0.195506f,0.933494f,0.104138f, 0.30492f,0.471321f,-0.21412f,0.183519f,0.943876f,0.118072f,
0.280513f,0.447042f,-0.202369f,0.17063f,0.95558f,0.133951f, 0.259351f,0.425584f,-0.189945f,0.157633f,0.968754f,0.152082f,
0.237661f,0.402725f,-0.176194f,0.144007f,0.983516f,0.172784f, 0.215211f,0.377994f,-0.162351f,0.130831f,0.999494f,0.195612f,
1.0f,5.98685e-06f,-3.35467e-19f,0.895368f,0.964005f,5.00354e-05f, 0.999773f,0.0207327f,-0.0167041f,0.89456f,0.963955f,5.13149e-05f,
0.998952f,0.0414975f,-0.0334146f,0.893335f,0.963707f,5.3376e-05f, 0.997597f,0.0622871f,-0.0502313f,0.891323f,0.963407f,5.73105e-05f,
0.995741f,0.0830141f,-0.0669849f,0.888523f,0.962956f,6.31507e-05f, 0.993394f,0.103623f,-0.0835183f,0.88489f,0.962285f,7.08358e-05f,
0.990586f,0.124097f,-0.0997867f,0.880503f,0.961391f,8.05026e-05f, 0.987388f,0.14439f,-0.115738f,0.875353f,0.960282f,9.23219e-05f,
0.983965f,0.164534f,-0.131392f,0.869797f,0.958968f,0.000106525f, 0.979453f,0.184386f,-0.14665f,0.863267f,0.95748f,0.000123495f,
0.974502f,0.204037f,-0.161645f,0.856147f,0.955915f,0.000144305f, 0.969428f,0.223505f,-0.176219f,0.848257f,0.954211f,0.000169222f,
0.96423f,0.242695f,-0.190276f,0.839765f,0.952308f,0.000198177f, 0.958344f,0.261551f,-0.203808f,0.830688f,0.950229f,0.000231758f,
0.952229f,0.28016f,-0.216992f,0.821463f,0.948056f,0.000271445f, 0.943811f,0.298028f,-0.229644f,0.811542f,0.945782f,0.000318148f,
0.93454f,0.315323f,-0.241585f,0.800782f,0.943334f,0.000371717f, 0.917454f,0.330291f,-0.25247f,0.788019f,0.94078f,0.000433872f,
0.916545f,0.349005f,-0.262945f,0.775372f,0.938158f,0.000506576f, 0.899376f,0.362884f,-0.2736f,0.764771f,0.935389f,0.000589533f,
0.888738f,0.37816f,-0.283301f,0.75263f,0.932567f,0.000685834f, 0.884566f,0.395043f,-0.291984f,0.739139f,0.929651f,0.000796342f,
0.869453f,0.408099f,-0.300632f,0.726842f,0.926654f,0.000922849f, 0.87409f,0.427474f,-0.307797f,0.712133f,0.923623f,0.00106869f,
0.846346f,0.435159f,-0.315927f,0.700883f,0.920512f,0.00123448f, 0.835106f,0.448145f,-0.322512f,0.687166f,0.917403f,0.00142529f,
0.8261f,0.461549f,-0.328257f,0.672859f,0.914237f,0.00164165f, 0.820311f,0.475884f,-0.333438f,0.658424f,0.911095f,0.00188969f,
0.801441f,0.484407f,-0.338787f,0.645393f,0.907932f,0.00217057f, 0.787919f,0.494737f,-0.343262f,0.631591f,0.904821f,0.00249146f,
0.7769f,0.505534f,-0.34672f,0.616929f,0.901726f,0.00285444f, 0.770824f,0.518173f,-0.349447f,0.601898f,0.898716f,0.00326789f,
0.750597f,0.523814f,-0.352762f,0.5888f,0.895769f,0.00373518f, 0.743615f,0.535334f,-0.354015f,0.573108f,0.892945f,0.0042662f,
0.719806f,0.537686f,-0.355358f,0.558486f,0.890229f,0.0048657f, 0.704718f,0.543918f,-0.355531f,0.542863f,0.887685f,0.00554597f,
0.700488f,0.555814f,-0.355372f,0.527615f,0.885299f,0.00631351f, 0.687568f,0.561967f,-0.355177f,0.513102f,0.883125f,0.00718225f,
0.671943f,0.566267f,-0.354515f,0.498674f,0.881177f,0.00816399f, 0.646913f,0.564109f,-0.353558f,0.484571f,0.879475f,0.00927185f,
0.636191f,0.570028f,-0.351431f,0.469585f,0.878054f,0.0105233f, 0.627444f,0.576836f,-0.348834f,0.454691f,0.876946f,0.0119378f,
0.604876f,0.573882f,-0.346276f,0.440542f,0.876169f,0.0135343f, 0.598636f,0.581386f,-0.342704f,0.425778f,0.875749f,0.0153366f,
0.586346f,0.584572f,-0.339013f,0.411527f,0.875715f,0.0173713f, 0.55787f,0.574606f,-0.334869f,0.397364f,0.876091f,0.0196681f,
0.545894f,0.576237f,-0.329898f,0.382847f,0.876915f,0.0222627f, 0.536343f,0.573595f,-0.324126f,0.368027f,0.878217f,0.0251953f,
0.511502f,0.569451f,-0.318999f,0.354543f,0.880016f,0.0285068f, 0.498385f,0.568245f,-0.312668f,0.340299f,0.882352f,0.0322499f,
0.48783f,0.568646f,-0.306046f,0.326318f,0.885259f,0.0364818f, 0.477882f,0.569132f,-0.299804f,0.313284f,0.888782f,0.0412716f,
0.449992f,0.552736f,-0.292188f,0.299356f,0.892948f,0.0466894f, 0.43487f,0.546958f,-0.28394f,0.285331f,0.89781f,0.0528243f,
0.421987f,0.542601f,-0.275528f,0.271677f,0.903421f,0.0597774f, 0.396955f,0.525419f,-0.266448f,0.257892f,0.909837f,0.0676629f,
0.379708f,0.514982f,-0.25698f,0.244249f,0.917123f,0.0766145f, 0.363902f,0.50524f,-0.247098f,0.23072f,0.925352f,0.0867852f,
0.34875f,0.495442f,-0.23681f,0.21731f,0.934605f,0.098352f, 0.326243f,0.476667f,-0.226356f,0.204233f,0.944974f,0.111519f,
0.30722f,0.460557f,-0.214647f,0.190506f,0.956568f,0.126529f, 0.288021f,0.443512f,-0.202253f,0.176655f,0.96954f,0.143682f,
0.257505f,0.411865f,-0.188014f,0.16169f,0.984015f,0.163304f, 0.232676f,0.38627f,-0.17398f,0.147495f,0.999509f,0.18486f,
0.999999f,1.9715e-06f,4.62823e-19f,0.935894f,0.951167f,5.75826e-05f, 0.999866f,0.0202504f,-0.0168696f,0.93477f,0.950473f,5.7295e-05f,
0.999286f,0.0404751f,-0.0336142f,0.933553f,0.950377f,6.00703e-05f, 0.99827f,0.0606261f,-0.050211f,0.931508f,0.950072f,6.44443e-05f,
0.996882f,0.0806973f,-0.0666349f,0.928672f,0.949542f,7.04696e-05f, 0.995174f,0.100679f,-0.0828486f,0.924996f,0.948788f,7.82572e-05f,
0.993269f,0.12057f,-0.0988357f,0.920612f,0.947825f,8.79753e-05f, 0.990851f,0.140351f,-0.114596f,0.915482f,0.946688f,9.99546e-05f,
0.989174f,0.160167f,-0.130232f,0.90976f,0.945475f,0.000115069f, 0.985193f,0.179569f,-0.145555f,0.903582f,0.944063f,0.00013308f,
0.983779f,0.199281f,-0.16034f,0.89599f,0.942447f,0.00015416f, 0.97656f,0.217809f,-0.174857f,0.88856f,0.940658f,0.000178808f,
0.972054f,0.236651f,-0.188954f,0.880038f,0.938791f,0.000208307f, 0.966489f,0.255125f,-0.202584f,0.870959f,0.936768f,0.000242659f,
0.966307f,0.274482f,-0.215331f,0.859915f,0.934575f,0.000282157f, 0.943241f,0.288644f,-0.228033f,0.850041f,0.932298f,0.00032841f,
0.935469f,0.305672f,-0.240211f,0.839619f,0.929907f,0.000382007f, 0.928061f,0.322392f,-0.251606f,0.828045f,0.927377f,0.00044329f,
0.921238f,0.339f,-0.262522f,0.816132f,0.924799f,0.000514698f, 0.931179f,0.359875f,-0.272388f,0.802542f,0.922102f,0.000596218f,
0.902768f,0.369994f,-0.283192f,0.792932f,0.919343f,0.000689989f, 0.894661f,0.385232f,-0.292339f,0.779839f,0.916521f,0.000797549f,
0.885753f,0.399892f,-0.301118f,0.767071f,0.913636f,0.000920224f, 0.883283f,0.416381f,-0.308771f,0.752631f,0.910731f,0.00106103f,
0.866783f,0.427783f,-0.316917f,0.740623f,0.907776f,0.00122089f, 0.859705f,0.442078f,-0.32376f,0.7266f,0.904833f,0.00140401f,
0.845583f,0.453339f,-0.330388f,0.713255f,0.901869f,0.00161146f, 0.844725f,0.46931f,-0.335658f,0.698026f,0.898945f,0.00184834f,
0.851161f,0.489365f,-0.345978f,0.694054f,0.896038f,0.00211644f, 0.818487f,0.490597f,-0.345993f,0.670351f,0.893201f,0.0024217f,
0.801865f,0.499007f,-0.350518f,0.6567f,0.890419f,0.00276675f, 0.789128f,0.508632f,-0.353631f,0.641323f,0.887746f,0.00315884f,
0.78414f,0.521217f,-0.355484f,0.624708f,0.88517f,0.00360155f, 0.780463f,0.534295f,-0.357278f,0.608952f,0.882745f,0.00410395f,
0.754972f,0.534117f,-0.359422f,0.594707f,0.880461f,0.00467077f, 0.730567f,0.537968f,-0.361435f,0.58103f,0.878368f,0.00531261f,
0.718289f,0.54523f,-0.361844f,0.565589f,0.876473f,0.00603758f, 0.712495f,0.555442f,-0.361464f,0.549772f,0.874796f,0.00685582f,
0.699361f,0.561307f,-0.361268f,0.53503f,0.873375f,0.00778077f, 0.688507f,0.567916f,-0.360299f,0.519902f,0.872227f,0.00882569f,
0.660993f,0.564196f,-0.35951f,0.50577f,0.871369f,0.0100049f, 0.64786f,0.568268f,-0.357317f,0.490382f,0.870826f,0.011336f,
0.637806f,0.573735f,-0.354595f,0.475001f,0.870622f,0.0128389f, 0.618436f,0.572729f,-0.351989f,0.460469f,0.870782f,0.0145359f,
0.608253f,0.577069f,-0.34821f,0.445085f,0.871324f,0.0164517f, 0.601165f,0.583174f,-0.344152f,0.430027f,0.872272f,0.0186145f,
0.587756f,0.584534f,-0.339828f,0.415285f,0.873654f,0.0210583f, 0.557646f,0.572893f,-0.335077f,0.400646f,0.875501f,0.0238209f,
0.545306f,0.573334f,-0.329543f,0.385705f,0.877819f,0.0269394f, 0.534522f,0.569917f,-0.323026f,0.370233f,0.880664f,0.0304698f,
0.512185f,0.566321f,-0.317901f,0.356952f,0.88404f,0.0344585f, 0.497184f,0.562854f,-0.311087f,0.342331f,0.887999f,0.0389742f,
0.483923f,0.560117f,-0.303595f,0.327544f,0.892576f,0.0440888f, 0.47115f,0.554939f,-0.295581f,0.312776f,0.897804f,0.0498813f,
0.443987f,0.541083f,-0.287361f,0.298352f,0.903732f,0.0564473f, 0.427136f,0.532964f,-0.278485f,0.283799f,0.910412f,0.0638967f,
0.412462f,0.526155f,-0.269309f,0.269484f,0.917903f,0.0723553f, 0.402384f,0.526032f,-0.262729f,0.258244f,0.92627f,0.0819676f,
0.369636f,0.497037f,-0.248836f,0.240352f,0.935588f,0.0929011f, 0.352663f,0.485551f,-0.238484f,0.226457f,0.945942f,0.10535f,
0.33095f,0.468181f,-0.22685f,0.211854f,0.95744f,0.119549f, 0.309182f,0.449661f,-0.214077f,0.1967f,0.970235f,0.135796f,
0.285843f,0.428879f,-0.20011f,0.180975f,0.984461f,0.154418f, 0.262388f,0.407128f,-0.185959f,0.165747f,0.999523f,0.174795f,
0.999986f,6.01992e-07f,-1.13117e-18f,0.975892f,0.935653f,6.4438e-05f, 0.999977f,0.0195205f,-0.0166005f,0.974926f,0.935647f,6.53418e-05f,
0.999729f,0.039046f,-0.0331506f,0.973591f,0.935273f,6.77587e-05f, 0.999232f,0.0584645f,-0.0493955f,0.971455f,0.934799f,7.19987e-05f,
0.998437f,0.0777884f,-0.0653835f,0.968575f,0.934201f,7.79865e-05f, 0.997612f,0.0970845f,-0.0812396f,0.964912f,0.933471f,8.59213e-05f,
0.996462f,0.116366f,-0.0970325f,0.960629f,0.932637f,9.62763e-05f, 0.995634f,0.135615f,-0.112537f,0.955566f,0.931571f,0.000108783f,
0.99448f,0.15477f,-0.127792f,0.950166f,0.930288f,0.000123663f, 0.998487f,0.174633f,-0.14264f,0.943153f,0.928827f,0.00014136f,
0.988482f,0.192389f,-0.157499f,0.936882f,0.927266f,0.000162815f, 0.983983f,0.210763f,-0.171801f,0.929017f,0.925501f,0.000187716f,
0.975966f,0.22837f,-0.185594f,0.920069f,0.923559f,0.000216547f, 0.963438f,0.244751f,-0.19879f,0.909393f,0.921546f,0.000250664f,
0.95914f,0.262391f,-0.211822f,0.899699f,0.919425f,0.000290051f, 0.966953f,0.28236f,-0.224087f,0.888359f,0.917195f,0.000335353f,
0.947528f,0.296356f,-0.236778f,0.879792f,0.914918f,0.000388244f, 0.939841f,0.312538f,-0.248448f,0.868873f,0.912516f,0.000448452f,
0.933682f,0.32873f,-0.259475f,0.856927f,0.910066f,0.000518051f, 0.939529f,0.347813f,-0.269538f,0.84331f,0.90753f,0.000597488f,
0.921208f,0.360442f,-0.280241f,0.832946f,0.904944f,0.000688477f, 0.911002f,0.374735f,-0.290178f,0.821417f,0.902311f,0.000792458f,
0.905479f,0.390075f,-0.298888f,0.807645f,0.89964f,0.000910923f, 0.895722f,0.403814f,-0.307682f,0.795274f,0.896954f,0.00104615f,
0.901147f,0.42212f,-0.315016f,0.780352f,0.894254f,0.00119977f, 0.881752f,0.432026f,-0.322904f,0.767921f,0.891572f,0.00137474f,
0.875272f,0.44389f,-0.329622f,0.753796f,0.888906f,0.00157314f, 0.858785f,0.455799f,-0.33624f,0.740475f,0.886289f,0.00179862f,
0.858404f,0.471281f,-0.341094f,0.724379f,0.883723f,0.00205388f, 0.851202f,0.483979f,-0.345994f,0.709461f,0.881244f,0.00234359f,
0.828288f,0.489625f,-0.350136f,0.694052f,0.878851f,0.00267089f, 0.806666f,0.495892f,-0.354819f,0.680635f,0.876589f,0.00304222f,
0.795851f,0.505787f,-0.358012f,0.665306f,0.874451f,0.00346112f, 0.794431f,0.51929f,-0.360149f,0.648964f,0.872486f,0.00393576f,
0.791153f,0.531778f,-0.362172f,0.633386f,0.870691f,0.00447139f, 0.765675f,0.531467f,-0.364517f,0.619235f,0.869094f,0.00507613f,
0.744513f,0.536712f,-0.366481f,0.605203f,0.867729f,0.0057603f, 0.732971f,0.543877f,-0.366881f,0.589411f,0.866601f,0.0065323f,
0.722545f,0.551126f,-0.366562f,0.573312f,0.865731f,0.00740349f, 0.720825f,0.562631f,-0.365689f,0.557177f,0.865143f,0.00838696f,
0.706721f,0.567664f,-0.36507f,0.542208f,0.864856f,0.00949731f, 0.676264f,0.562221f,-0.36449f,0.528008f,0.86489f,0.0107508f,
0.663208f,0.566084f,-0.362268f,0.512146f,0.865265f,0.0121663f, 0.650748f,0.569764f,-0.359473f,0.496215f,0.865998f,0.0137646f,
0.640642f,0.574454f,-0.356172f,0.480314f,0.867108f,0.0155694f, 0.619636f,0.571757f,-0.353016f,0.465308f,0.868608f,0.0176062f,
0.609241f,0.575221f,-0.348776f,0.449538f,0.870533f,0.0199093f, 0.600967f,0.579787f,-0.344039f,0.433806f,0.872899f,0.0225121f,
0.586432f,0.579632f,-0.339063f,0.418436f,0.87572f,0.0254526f, 0.5574f,0.568324f,-0.333863f,0.403415f,0.879034f,0.0287798f,
0.544769f,0.568055f,-0.328263f,0.38852f,0.882863f,0.0325446f, 0.532281f,0.567337f,-0.321671f,0.373067f,0.88723f,0.0368038f,
0.521234f,0.566834f,-0.314996f,0.358119f,0.892175f,0.0416281f, 0.492694f,0.552414f,-0.306847f,0.342097f,0.897739f,0.0470978f,
0.476011f,0.546321f,-0.298631f,0.326607f,0.903961f,0.0533016f, 0.46235f,0.542127f,-0.29006f,0.311318f,0.910885f,0.0603417f,
0.43725f,0.527231f,-0.281013f,0.296092f,0.918564f,0.0683371f, 0.41868f,0.517133f,-0.271146f,0.280578f,0.927057f,0.0774252f,
0.400421f,0.506542f,-0.260935f,0.265274f,0.936435f,0.0877657f, 0.383585f,0.496593f,-0.250454f,0.250248f,0.946781f,0.099546f,
0.369262f,0.488065f,-0.241103f,0.236859f,0.958199f,0.112991f, 0.333455f,0.457422f,-0.226063f,0.218425f,0.970845f,0.128398f,
0.308381f,0.436649f,-0.211913f,0.201446f,0.984857f,0.146095f, 0.281676f,0.413279f,-0.197636f,0.185098f,0.999534f,0.165382f,
0.999998f,7.68279e-07f,1.92756e-19f,1.01528f,0.917774f,7.09676e-05f, 1.00013f,0.0185525f,-0.0157989f,1.01423f,0.917853f,7.21485e-05f,
1.00028f,0.0371193f,-0.0315986f,1.01286f,0.917539f,7.44997e-05f, 1.00046f,0.0557526f,-0.0474795f,1.0107f,0.91709f,7.87243e-05f,
1.00071f,0.0744201f,-0.0633437f,1.00781f,0.91647f,8.49103e-05f, 1.00067f,0.0930012f,-0.0788977f,1.00423f,0.915708f,9.30376e-05f,
1.00044f,0.111455f,-0.0940909f,1.00008f,0.914857f,0.00010322f, 1.00001f,0.129877f,-0.109098f,0.995208f,0.913897f,0.000115778f,
0.999374f,0.148265f,-0.123951f,0.989727f,0.91282f,0.000131099f, 0.997058f,0.166399f,-0.138592f,0.984236f,0.911542f,0.000149027f,
0.988221f,0.183395f,-0.152695f,0.976235f,0.910102f,0.000170047f, 0.979943f,0.200108f,-0.166533f,0.967465f,0.908562f,0.000195062f,
0.976111f,0.217368f,-0.180087f,0.958814f,0.906838f,0.000223814f, 0.973126f,0.234612f,-0.193259f,0.949368f,0.904992f,0.000257222f,
0.967661f,0.251306f,-0.206174f,0.939878f,0.903036f,0.000295997f, 0.979879f,0.271798f,-0.218356f,0.928622f,0.900939f,0.000340271f,
0.959284f,0.284651f,-0.231208f,0.921145f,0.898776f,0.000391664f, 0.963922f,0.303036f,-0.242386f,0.90838f,0.896495f,0.000450127f,
0.950184f,0.316991f,-0.253952f,0.898245f,0.894162f,0.000517423f, 0.942044f,0.331895f,-0.264742f,0.886623f,0.891815f,0.000594157f,
0.939519f,0.347975f,-0.274828f,0.873839f,0.88947f,0.000682019f, 0.93595f,0.363646f,-0.284726f,0.861716f,0.887099f,0.000781951f,
0.92306f,0.376509f,-0.29463f,0.850656f,0.884728f,0.000895881f, 0.918673f,0.391571f,-0.303242f,0.836996f,0.882353f,0.00102523f,
0.907866f,0.404425f,-0.311774f,0.824224f,0.879997f,0.00117228f, 0.914211f,0.422109f,-0.319583f,0.810642f,0.877663f,0.00133897f,
0.892468f,0.43102f,-0.326828f,0.796703f,0.875379f,0.00152809f, 0.884876f,0.443933f,-0.333239f,0.781835f,0.873156f,0.00174228f,
0.862951f,0.451445f,-0.339009f,0.76657f,0.871011f,0.00198468f, 0.864876f,0.46695f,-0.343665f,0.749908f,0.868968f,0.00225922f,
0.857643f,0.478898f,-0.348612f,0.734985f,0.867035f,0.00256909f, 0.836976f,0.48545f,-0.353808f,0.721486f,0.865253f,0.00292033f,
0.820485f,0.49302f,-0.358298f,0.707456f,0.863616f,0.00331632f, 0.810183f,0.502583f,-0.361429f,0.691653f,0.862161f,0.00376394f,
0.802447f,0.512845f,-0.363783f,0.675316f,0.860907f,0.0042699f, 0.798856f,0.524617f,-0.365699f,0.659128f,0.859861f,0.00484051f,
0.774319f,0.526783f,-0.368632f,0.645613f,0.859047f,0.00548447f, 0.775086f,0.54004f,-0.368997f,0.628438f,0.858486f,0.00621157f,
0.748385f,0.539707f,-0.370519f,0.614068f,0.858197f,0.00703259f, 0.736621f,0.54607f,-0.370352f,0.597698f,0.858193f,0.00795936f,
0.72838f,0.553844f,-0.369522f,0.581097f,0.858488f,0.00900504f, 0.713998f,0.558068f,-0.368829f,0.565506f,0.8591f,0.0101854f,
0.701892f,0.562918f,-0.367303f,0.549398f,0.860048f,0.0115184f, 0.692246f,0.568851f,-0.365227f,0.533223f,0.861348f,0.0130243f,
0.665591f,0.564556f,-0.363364f,0.518085f,0.863012f,0.0147244f, 0.651962f,0.5669f,-0.360082f,0.501644f,0.865049f,0.0166432f,
0.640921f,0.570415f,-0.356327f,0.485256f,0.8675f,0.0188146f, 0.641686f,0.582552f,-0.356752f,0.475142f,0.870358f,0.0212662f,
0.607428f,0.568757f,-0.347738f,0.453129f,0.873666f,0.0240416f, 0.59905f,0.572594f,-0.342941f,0.437416f,0.877423f,0.0271779f,
0.589035f,0.573264f,-0.337208f,0.421156f,0.881675f,0.0307308f, 0.573096f,0.5729f,-0.331352f,0.405393f,0.886439f,0.0347543f,
0.542697f,0.559311f,-0.324735f,0.389336f,0.89174f,0.0393114f, 0.525199f,0.554326f,-0.317198f,0.372819f,0.897617f,0.0444778f,
0.512012f,0.551923f,-0.309422f,0.356655f,0.904109f,0.0503397f, 0.498048f,0.545724f,-0.300984f,0.340348f,0.91126f,0.0569965f,
0.46862f,0.531748f,-0.2921f,0.324154f,0.919119f,0.0645614f, 0.45033f,0.523248f,-0.282519f,0.307796f,0.927743f,0.0731664f,
0.434486f,0.516288f,-0.273065f,0.292169f,0.937195f,0.0829635f, 0.40946f,0.500195f,-0.262247f,0.275674f,0.947546f,0.094126f,
0.388211f,0.486475f,-0.250588f,0.258908f,0.958865f,0.106847f, 0.364787f,0.47007f,-0.237918f,0.241664f,0.971373f,0.121463f,
0.331692f,0.443407f,-0.223845f,0.223579f,0.985205f,0.138306f, 0.302948f,0.420222f,-0.209647f,0.206219f,0.999545f,0.156583f,
0.999999f,2.30042e-06f,-1.05861e-19f,1.05401f,0.897553f,7.68071e-05f, 1.00041f,0.0176521f,-0.0151205f,1.05268f,0.897375f,7.74375e-05f,
1.00129f,0.0352282f,-0.030181f,1.05121f,0.897225f,8.01226e-05f, 1.00228f,0.0527643f,-0.0451536f,1.04912f,0.896875f,8.44199e-05f,
1.00302f,0.0702785f,-0.0600633f,1.04638f,0.896335f,9.04296e-05f, 1.00375f,0.0878615f,-0.0750236f,1.04317f,0.895676f,9.85407e-05f,
1.00319f,0.105361f,-0.0898759f,1.03898f,0.894847f,0.000108785f, 1.00169f,0.12269f,-0.10442f,1.03377f,0.893881f,0.000121216f,
0.993525f,0.139034f,-0.118458f,1.02659f,0.892918f,0.000136329f, 1.00495f,0.148438f,-0.132309f,1.01942f,0.891872f,0.000154352f,
0.990769f,0.172956f,-0.146292f,1.01477f,0.890674f,0.000175244f, 0.987377f,0.189493f,-0.159748f,1.00695f,0.889387f,0.000199837f,
0.983879f,0.2058f,-0.172907f,0.998512f,0.887964f,0.000228251f, 0.981121f,0.222273f,-0.18586f,0.990016f,0.886419f,0.000260965f,
0.976923f,0.238332f,-0.198568f,0.981024f,0.884787f,0.000298911f, 0.974667f,0.254548f,-0.210843f,0.97118f,0.88303f,0.000342122f,
0.972418f,0.270695f,-0.223064f,0.961898f,0.881212f,0.000392035f, 0.967357f,0.28615f,-0.234818f,0.951792f,0.879289f,0.000448686f,
0.97656f,0.304418f,-0.245564f,0.93865f,0.877326f,0.000513758f, 0.960737f,0.317167f,-0.256772f,0.928544f,0.875287f,0.000587515f,
0.952701f,0.331467f,-0.267312f,0.916939f,0.873229f,0.000671869f, 0.948985f,0.346542f,-0.277466f,0.905175f,0.871128f,0.000767353f,
0.944481f,0.361442f,-0.287321f,0.893399f,0.869041f,0.000876218f, 0.93561f,0.37478f,-0.296718f,0.881282f,0.867017f,0.000999467f,
0.927204f,0.387967f,-0.305067f,0.867073f,0.865063f,0.00113968f, 0.916598f,0.400235f,-0.313067f,0.853047f,0.863156f,0.00129813f,
0.914032f,0.417582f,-0.31952f,0.835968f,0.861326f,0.00147787f, 0.894576f,0.423433f,-0.327464f,0.823899f,0.859572f,0.00168094f,
0.887295f,0.43566f,-0.33415f,0.809598f,0.857918f,0.00191064f, 0.876497f,0.446403f,-0.340346f,0.795101f,0.856384f,0.00217046f,
0.869485f,0.458246f,-0.345497f,0.779219f,0.854976f,0.00246346f, 0.862219f,0.469663f,-0.350472f,0.763928f,0.853733f,0.00279514f,
0.847399f,0.478011f,-0.355708f,0.750145f,0.852654f,0.00316925f, 0.848742f,0.492074f,-0.358782f,0.732777f,0.851761f,0.00359125f,
0.826105f,0.49673f,-0.363231f,0.719139f,0.851077f,0.00406782f, 0.81567f,0.505517f,-0.365844f,0.702729f,0.850623f,0.00460623f,
0.81082f,0.516318f,-0.367579f,0.685595f,0.850404f,0.00521349f, 0.805552f,0.521457f,-0.368764f,0.668391f,0.850439f,0.00589867f,
0.780641f,0.528241f,-0.371642f,0.655075f,0.850743f,0.00667198f, 0.780575f,0.54034f,-0.371611f,0.637442f,0.85133f,0.00754467f,
0.753483f,0.539614f,-0.372835f,0.62279f,0.852214f,0.00852962f, 0.740997f,0.545174f,-0.372269f,0.605938f,0.853405f,0.00964112f,
0.731277f,0.551625f,-0.370992f,0.588759f,0.85492f,0.0108962f, 0.727461f,0.560798f,-0.369057f,0.571351f,0.856778f,0.0123149f,
0.71142f,0.562973f,-0.367498f,0.555314f,0.858983f,0.0139166f, 0.692485f,0.563669f,-0.365353f,0.539133f,0.861548f,0.0157256f,
0.667979f,0.560201f,-0.362909f,0.523217f,0.864502f,0.0177724f, 0.654243f,0.562116f,-0.359259f,0.506296f,0.867842f,0.0200842f,
0.639402f,0.562902f,-0.354982f,0.489214f,0.871606f,0.0227019f, 0.63113f,0.567285f,-0.350883f,0.473085f,0.875801f,0.0256636f,
0.621269f,0.570337f,-0.345401f,0.455794f,0.880447f,0.0290151f, 0.593889f,0.561397f,-0.339986f,0.439282f,0.885577f,0.0328135f,
0.584499f,0.564205f,-0.334611f,0.423467f,0.891222f,0.0371221f, 0.566512f,0.558784f,-0.327546f,0.406176f,0.897405f,0.0420085f,
0.537792f,0.547283f,-0.319443f,0.388293f,0.904161f,0.0475547f, 0.520215f,0.541878f,-0.311371f,0.371128f,0.911533f,0.0538552f,
0.50161f,0.535062f,-0.302644f,0.353844f,0.919567f,0.0610193f, 0.485307f,0.529499f,-0.293284f,0.336478f,0.928318f,0.0691731f,
0.469689f,0.521255f,-0.283846f,0.319665f,0.937844f,0.0784618f, 0.439616f,0.505374f,-0.273433f,0.30239f,0.948212f,0.0890519f,
0.41701f,0.492132f,-0.262082f,0.284734f,0.959477f,0.101121f, 0.390404f,0.474571f,-0.249341f,0.266196f,0.971824f,0.114967f,
0.365f,0.457475f,-0.235368f,0.246936f,0.985509f,0.13102f, 0.336704f,0.436806f,-0.22107f,0.228302f,0.999554f,0.148364f,
1.0f,-1.68786e-07f,1.27076e-18f,1.09136f,0.875147f,8.1752e-05f, 1.00064f,0.0160253f,-0.0141933f,1.09083f,0.875133f,8.2677e-05f,
1.00155f,0.0322227f,-0.0284059f,1.08952f,0.874886f,8.50612e-05f, 1.00251f,0.0485115f,-0.0425338f,1.08746f,0.874656f,8.947e-05f,
1.00312f,0.0647867f,-0.0565199f,1.08468f,0.874294f,9.56204e-05f, 1.00217f,0.0808824f,-0.0703822f,1.08085f,0.873777f,0.000103552f,
0.997037f,0.0963032f,-0.0841837f,1.07541f,0.87316f,0.000113668f, 0.99661f,0.112482f,-0.0979444f,1.07025f,0.872386f,0.000125969f,
0.996363f,0.128703f,-0.111599f,1.06472f,0.871454f,0.000140599f, 0.996341f,0.144901f,-0.125139f,1.05855f,0.870464f,0.000158195f,
0.997262f,0.161271f,-0.138513f,1.05392f,0.869455f,0.00017867f, 0.994428f,0.176871f,-0.151431f,1.04671f,0.868391f,0.000202589f,
1.00473f,0.193987f,-0.163754f,1.0366f,0.867246f,0.00023026f, 0.990192f,0.207826f,-0.176503f,1.0301f,0.866039f,0.00026213f,
0.987349f,0.223137f,-0.188728f,1.02106f,0.864778f,0.000298934f, 0.985502f,0.238373f,-0.200653f,1.01141f,0.863429f,0.000340846f,
0.983157f,0.253828f,-0.212555f,1.00224f,0.862036f,0.000389067f, 0.982225f,0.269463f,-0.224415f,0.993748f,0.860563f,0.000443718f,
0.978325f,0.284266f,-0.235788f,0.983659f,0.859061f,0.000506315f, 0.979041f,0.297421f,-0.246188f,0.97063f,0.857502f,0.000577111f,
0.969599f,0.313363f,-0.257227f,0.960921f,0.855933f,0.000657924f, 0.964743f,0.327484f,-0.2672f,0.948228f,0.854334f,0.000749188f,
0.963841f,0.342522f,-0.276513f,0.93418f,0.852752f,0.000853092f, 0.947694f,0.353679f,-0.286204f,0.922508f,0.851169f,0.000970296f,
0.936245f,0.365621f,-0.295026f,0.908922f,0.849635f,0.00110345f, 0.930386f,0.378812f,-0.303407f,0.895085f,0.84814f,0.00125356f,
0.940229f,0.393819f,-0.310358f,0.878117f,0.846794f,0.00142391f, 0.91586f,0.403693f,-0.318997f,0.866968f,0.845563f,0.0016161f,
0.92351f,0.420053f,-0.325199f,0.850149f,0.844456f,0.00183328f, 0.908051f,0.429614f,-0.332535f,0.837273f,0.84349f,0.00207889f,
0.899669f,0.441086f,-0.33881f,0.822656f,0.842665f,0.00235566f, 0.881219f,0.448811f,-0.345141f,0.809065f,0.842007f,0.00266818f,
0.879841f,0.461812f,-0.349612f,0.792049f,0.841536f,0.00302141f, 0.871431f,0.472178f,-0.354217f,0.776364f,0.841256f,0.00341957f,
0.853112f,0.47878f,-0.359278f,0.76256f,0.841186f,0.00386868f, 0.858846f,0.497732f,-0.363053f,0.746881f,0.841342f,0.00437541f,
0.831394f,0.496244f,-0.366063f,0.73054f,0.841737f,0.00494718f, 0.821047f,0.504663f,-0.36841f,0.713795f,0.842386f,0.00559245f,
0.815685f,0.514724f,-0.369784f,0.696102f,0.8433f,0.00632076f, 0.810142f,0.524494f,-0.370865f,0.678792f,0.84449f,0.00714274f,
0.783937f,0.525119f,-0.373211f,0.66461f,0.845968f,0.00807064f, 0.782845f,0.536092f,-0.372691f,0.646158f,0.847741f,0.00911768f,
0.757775f,0.536115f,-0.373475f,0.630808f,0.849821f,0.0102997f, 0.744574f,0.540982f,-0.372541f,0.613337f,0.85223f,0.0116365f,
0.73205f,0.545672f,-0.371084f,0.59585f,0.854965f,0.0131455f, 0.726814f,0.553572f,-0.368728f,0.577743f,0.858048f,0.0148518f,
0.70978f,0.555225f,-0.36665f,0.560876f,0.861488f,0.0167807f, 0.697824f,0.556701f,-0.365174f,0.545642f,0.865304f,0.0189633f,
0.683684f,0.560916f,-0.360709f,0.526703f,0.869501f,0.0214311f, 0.659581f,0.557213f,-0.357705f,0.510641f,0.874116f,0.0242285f,
0.643615f,0.557129f,-0.352849f,0.492664f,0.879155f,0.0273961f, 0.626883f,0.556103f,-0.347419f,0.474645f,0.88464f,0.0309851f,
0.613935f,0.556762f,-0.341324f,0.456466f,0.8906f,0.0350552f, 0.589971f,0.549922f,-0.335274f,0.439071f,0.897067f,0.0396753f,
0.573208f,0.546965f,-0.328147f,0.420971f,0.904079f,0.0449258f, 0.554757f,0.542306f,-0.320749f,0.403235f,0.911667f,0.050894f,
0.540415f,0.540472f,-0.312457f,0.385079f,0.919876f,0.0576842f, 0.511729f,0.526519f,-0.30357f,0.366893f,0.928755f,0.0654175f,
0.494478f,0.520646f,-0.294603f,0.349297f,0.938364f,0.0742337f, 0.472597f,0.510534f,-0.284101f,0.330571f,0.948763f,0.0842938f,
0.451617f,0.500321f,-0.272924f,0.31178f,0.960004f,0.0957655f, 0.418631f,0.479459f,-0.260565f,0.292348f,0.972201f,0.108885f,
0.38977f,0.461267f,-0.246748f,0.271863f,0.98577f,0.124207f, 0.358651f,0.440325f,-0.232692f,0.252214f,0.999562f,0.140688f,
1.0f,4.15533e-07f,1.96802e-20f,1.12588f,0.85083f,8.57942e-05f, 0.99995f,0.0144001f,-0.0131232f,1.12552f,0.850761f,8.65636e-05f,
0.999832f,0.0286971f,-0.0261504f,1.12467f,0.850653f,8.90807e-05f, 0.998989f,0.042966f,-0.03918f,1.12298f,0.850422f,9.32022e-05f,
0.997282f,0.0572284f,-0.052331f,1.12038f,0.850116f,9.92129e-05f, 0.996833f,0.0714602f,-0.0652462f,1.11731f,0.849764f,0.000107103f,
0.996768f,0.0858823f,-0.0780219f,1.11322f,0.84936f,0.000117002f, 0.997124f,0.100651f,-0.0907422f,1.10793f,0.84889f,0.000129178f,
0.997861f,0.115856f,-0.103384f,1.10242f,0.848295f,0.000143574f, 0.998754f,0.131206f,-0.116038f,1.09641f,0.847629f,0.000160746f,
1.02777f,0.151177f,-0.130114f,1.10278f,0.846844f,0.000180688f, 1.00162f,0.162122f,-0.141407f,1.08566f,0.846008f,0.000203963f,
1.00106f,0.176825f,-0.153526f,1.07823f,0.845212f,0.000230821f, 0.998576f,0.191273f,-0.165473f,1.07049f,0.84439f,0.000261716f,
0.997866f,0.20596f,-0.17724f,1.06221f,0.843516f,0.000297098f, 0.995975f,0.220383f,-0.188774f,1.05307f,0.842584f,0.000337504f,
1.00597f,0.23605f,-0.199781f,1.04165f,0.841598f,0.000383601f, 0.994036f,0.24945f,-0.211357f,1.03376f,0.840559f,0.000436024f,
0.996863f,0.264661f,-0.22214f,1.02248f,0.839534f,0.000495771f, 1.00372f,0.272937f,-0.232608f,1.01053f,0.838511f,0.000563593f,
0.982685f,0.291623f,-0.2439f,1.00268f,0.837492f,0.000640587f, 0.968545f,0.303232f,-0.253636f,0.989105f,0.836476f,0.000727698f,
0.963945f,0.316609f,-0.263403f,0.97651f,0.83548f,0.000826429f, 0.958991f,0.329857f,-0.272849f,0.963615f,0.834506f,0.000937875f,
0.962612f,0.344745f,-0.281583f,0.949081f,0.833586f,0.0010642f, 0.955942f,0.357405f,-0.290807f,0.937151f,0.832711f,0.00120648f,
0.942063f,0.36818f,-0.300027f,0.925871f,0.831924f,0.00136762f, 0.935946f,0.380545f,-0.30793f,0.911403f,0.831222f,0.00154919f,
0.929395f,0.392564f,-0.315724f,0.897556f,0.830654f,0.00175404f, 0.923765f,0.404678f,-0.322833f,0.882637f,0.830288f,0.00198586f,
0.939213f,0.422521f,-0.328323f,0.864387f,0.830088f,0.00224712f, 0.916688f,0.428584f,-0.335697f,0.852058f,0.830062f,0.00254168f,
0.906489f,0.436659f,-0.341378f,0.83627f,0.830226f,0.00287403f, 0.88918f,0.447552f,-0.347486f,0.822396f,0.830592f,0.0032492f,
0.885393f,0.459334f,-0.351818f,0.80523f,0.831171f,0.00367247f, 0.87638f,0.469106f,-0.356229f,0.789216f,0.831971f,0.00414982f,
0.859664f,0.476116f,-0.360947f,0.774747f,0.833005f,0.00468825f, 0.859333f,0.488443f,-0.363259f,0.756045f,0.834283f,0.00529559f,
0.837623f,0.492667f,-0.36706f,0.741353f,0.835817f,0.0059811f, 0.827011f,0.500658f,-0.369149f,0.724049f,0.837618f,0.00675521f,
0.817316f,0.50875f,-0.370524f,0.706272f,0.839693f,0.00762916f, 0.817807f,0.520549f,-0.370746f,0.687261f,0.842048f,0.00861544f,
0.813065f,0.525158f,-0.372203f,0.671424f,0.844693f,0.0097291f, 0.786017f,0.531565f,-0.374202f,0.657281f,0.847648f,0.0109888f,
0.761404f,0.530006f,-0.372722f,0.637861f,0.850905f,0.0124104f, 0.748734f,0.534778f,-0.371489f,0.619742f,0.854497f,0.0140205f,
0.735034f,0.538753f,-0.369644f,0.601478f,0.858413f,0.0158387f, 0.723873f,0.543458f,-0.367236f,0.583121f,0.862688f,0.0178991f,
0.71865f,0.550865f,-0.364586f,0.565211f,0.867322f,0.0202301f, 0.7004f,0.55124f,-0.361805f,0.547886f,0.872331f,0.0228693f,
0.678928f,0.549487f,-0.3582f,0.530067f,0.877748f,0.0258632f, 0.669243f,0.553487f,-0.35309f,0.510821f,0.883586f,0.0292589f,
0.641347f,0.546487f,-0.348433f,0.493021f,0.889866f,0.0331111f, 0.623865f,0.544815f,-0.342454f,0.474121f,0.896616f,0.0374848f,
0.605997f,0.542335f,-0.335905f,0.455212f,0.903868f,0.042455f, 0.591369f,0.541363f,-0.328778f,0.436294f,0.911661f,0.0481079f,
0.577343f,0.540305f,-0.32098f,0.417248f,0.920035f,0.054544f, 0.546346f,0.527285f,-0.31277f,0.398415f,0.929046f,0.0618832f,
0.527111f,0.521347f,-0.30424f,0.379905f,0.938748f,0.0702606f, 0.502277f,0.510717f,-0.294332f,0.360412f,0.949197f,0.0798297f,
0.47889f,0.500107f,-0.283306f,0.340333f,0.960437f,0.090752f, 0.452399f,0.486594f,-0.271095f,0.31965f,0.972507f,0.103192f,
0.417049f,0.465494f,-0.257912f,0.298383f,0.98599f,0.11784f, 0.385926f,0.446785f,-0.244203f,0.277748f,0.999568f,0.133523f,
1.0f,1.44176e-06f,-2.11742e-18f,1.15895f,0.824905f,8.89538e-05f, 0.999698f,0.0127958f,-0.0118041f,1.15857f,0.824894f,8.97816e-05f,
0.999032f,0.0256417f,-0.0237525f,1.15781f,0.824828f,9.22357e-05f, 0.998236f,0.0383922f,-0.035567f,1.15647f,0.82471f,9.63229e-05f,
0.997542f,0.0510913f,-0.047365f,1.15449f,0.82459f,0.000102218f, 0.997043f,0.0637518f,-0.0591905f,1.15186f,0.8244f,0.000109906f,
0.996996f,0.0763998f,-0.0710354f,1.1485f,0.824118f,0.000119453f, 0.997683f,0.0891457f,-0.0828044f,1.14436f,0.823859f,0.000131281f,
0.998217f,0.10211f,-0.0943747f,1.13937f,0.823569f,0.000145281f, 1.00014f,0.115791f,-0.105989f,1.13402f,0.823251f,0.000161919f,
1.00224f,0.130133f,-0.11756f,1.12816f,0.822847f,0.000181179f, 1.03259f,0.149596f,-0.130724f,1.13526f,0.822395f,0.000203639f,
1.00747f,0.159199f,-0.141082f,1.1176f,0.821857f,0.000229377f, 1.00853f,0.173136f,-0.152633f,1.11023f,0.821313f,0.000259105f,
1.00802f,0.186844f,-0.163837f,1.10235f,0.820866f,0.00029306f, 1.00595f,0.200294f,-0.174898f,1.09392f,0.820451f,0.000331974f,
1.00476f,0.213932f,-0.185831f,1.08513f,0.820017f,0.00037609f, 1.00325f,0.227431f,-0.196579f,1.07534f,0.81958f,0.000426399f,
0.997557f,0.240152f,-0.206955f,1.06399f,0.819116f,0.000483281f, 0.987332f,0.252093f,-0.216971f,1.05119f,0.81865f,0.000547936f,
0.985514f,0.26554f,-0.227602f,1.04186f,0.818168f,0.000620909f, 0.982681f,0.278674f,-0.237951f,1.03146f,0.817704f,0.000703648f,
0.984334f,0.292509f,-0.247519f,1.01824f,0.817317f,0.000797181f, 0.97434f,0.304351f,-0.257657f,1.0079f,0.816998f,0.000902911f,
0.970585f,0.317022f,-0.266961f,0.994807f,0.816748f,0.00102246f, 0.967635f,0.329944f,-0.276052f,0.981682f,0.816561f,0.00115707f,
0.972139f,0.344236f,-0.28437f,0.966545f,0.816471f,0.00130938f, 0.963728f,0.355938f,-0.293176f,0.953896f,0.816474f,0.00148097f,
0.950498f,0.366444f,-0.302175f,0.942535f,0.816588f,0.0016743f, 0.94513f,0.378481f,-0.30986f,0.927786f,0.816836f,0.00189256f,
0.937853f,0.389826f,-0.317331f,0.913253f,0.817242f,0.00213884f, 0.931829f,0.401465f,-0.324223f,0.897945f,0.817872f,0.0024165f,
0.942135f,0.417207f,-0.329344f,0.87877f,0.818704f,0.00272959f, 0.919323f,0.423998f,-0.336663f,0.866368f,0.81974f,0.00308269f,
0.909765f,0.434252f,-0.342612f,0.851202f,0.820987f,0.00348101f, 0.89689f,0.442974f,-0.348129f,0.835812f,0.822453f,0.00393038f,
0.888555f,0.452827f,-0.3525f,0.818589f,0.824143f,0.00443728f, 0.894478f,0.467372f,-0.355428f,0.799054f,0.826069f,0.00500921f,
0.883524f,0.475972f,-0.359132f,0.782285f,0.828232f,0.00565423f, 0.859615f,0.4802f,-0.363378f,0.767527f,0.830648f,0.00638275f,
0.844457f,0.486649f,-0.366508f,0.751216f,0.833326f,0.00720588f, 0.831931f,0.493898f,-0.368419f,0.733316f,0.836263f,0.00813474f,
0.820241f,0.501022f,-0.369676f,0.715047f,0.839474f,0.00918432f, 0.817498f,0.51265f,-0.370606f,0.69706f,0.84297f,0.0103711f,
0.808493f,0.519319f,-0.37011f,0.677349f,0.846751f,0.0117118f, 0.781208f,0.518507f,-0.371381f,0.661723f,0.850838f,0.0132296f,
0.776608f,0.527141f,-0.369722f,0.641741f,0.855234f,0.0149463f, 0.754591f,0.527919f,-0.369529f,0.625177f,0.85995f,0.0168888f,
0.742023f,0.532332f,-0.367625f,0.606516f,0.865014f,0.0190921f, 0.7273f,0.535331f,-0.364901f,0.587385f,0.870426f,0.0215874f,
0.712565f,0.537937f,-0.361499f,0.568038f,0.876206f,0.024416f, 0.703868f,0.543173f,-0.357087f,0.547985f,0.882379f,0.027626f,
0.683439f,0.542337f,-0.353043f,0.529335f,0.888975f,0.0312746f, 0.660411f,0.538698f,-0.34843f,0.510643f,0.896011f,0.0354201f,
0.648559f,0.54036f,-0.342177f,0.490384f,0.903515f,0.0401334f, 0.61937f,0.532629f,-0.33623f,0.471394f,0.911523f,0.0454973f,
0.60023f,0.529369f,-0.328995f,0.451415f,0.920073f,0.0516067f, 0.58196f,0.526115f,-0.321374f,0.431727f,0.929209f,0.0585711f,
0.562714f,0.521649f,-0.312847f,0.411625f,0.938994f,0.0665264f, 0.545626f,0.518003f,-0.303346f,0.391038f,0.94951f,0.075641f,
0.510024f,0.500876f,-0.293071f,0.370295f,0.960775f,0.0860573f, 0.481359f,0.48762f,-0.281169f,0.348438f,0.972744f,0.0978653f,
0.453177f,0.474023f,-0.267937f,0.325479f,0.986172f,0.111891f, 0.420138f,0.455969f,-0.254328f,0.303492f,0.999574f,0.126837f,
1.0f,-2.50186e-06f,3.07711e-19f,1.19026f,0.797687f,9.12658e-05f, 0.999897f,0.0111503f,-0.0104947f,1.18987f,0.797683f,9.20431e-05f,
0.999526f,0.022332f,-0.0210472f,1.18921f,0.797687f,9.44419e-05f, 0.998979f,0.0334715f,-0.0315228f,1.18809f,0.797688f,9.84356e-05f,
0.998384f,0.0446414f,-0.0420923f,1.1864f,0.797661f,0.00010408f, 0.997881f,0.0557947f,-0.0526702f,1.18419f,0.797637f,0.000111524f,
0.997748f,0.0668524f,-0.0631638f,1.18147f,0.79763f,0.000120827f, 0.998388f,0.0779111f,-0.0737552f,1.17815f,0.797612f,0.000132206f,
0.999227f,0.0890842f,-0.0843916f,1.17411f,0.797536f,0.000145666f, 1.00141f,0.100619f,-0.0950033f,1.16935f,0.797498f,0.000161668f,
1.00325f,0.112606f,-0.105446f,1.16365f,0.797486f,0.000180228f, 1.00561f,0.125406f,-0.116013f,1.1581f,0.797498f,0.000201878f,
1.00883f,0.13883f,-0.126601f,1.15202f,0.79748f,0.000226654f, 1.01349f,0.152633f,-0.137643f,1.14843f,0.797454f,0.000255197f,
1.01329f,0.16538f,-0.148383f,1.14137f,0.797389f,0.00028764f, 1.0128f,0.178219f,-0.159084f,1.13359f,0.797347f,0.000324755f,
1.00131f,0.189029f,-0.16904f,1.12224f,0.797396f,0.000366786f, 1.00008f,0.201409f,-0.179198f,1.11254f,0.797487f,0.000414634f,
0.99925f,0.213887f,-0.189323f,1.10279f,0.797603f,0.000468683f, 1.00331f,0.227074f,-0.199255f,1.09175f,0.797788f,0.000530172f,
0.995824f,0.238695f,-0.209463f,1.08231f,0.797995f,0.000599462f, 0.995289f,0.251351f,-0.219391f,1.07127f,0.798246f,0.000678032f,
0.99467f,0.264267f,-0.229656f,1.06199f,0.798522f,0.000766476f, 0.990833f,0.276578f,-0.239618f,1.05129f,0.798847f,0.000866466f,
0.989809f,0.289245f,-0.248896f,1.03791f,0.799228f,0.000979225f, 0.983507f,0.301004f,-0.258547f,1.02653f,0.799739f,0.00110634f,
0.979889f,0.313204f,-0.267603f,1.01315f,0.800378f,0.00125002f, 0.974896f,0.325242f,-0.276404f,0.99939f,0.80113f,0.00141197f,
0.973658f,0.337894f,-0.284814f,0.984895f,0.802002f,0.00159437f, 0.965707f,0.349211f,-0.293693f,0.972637f,0.803003f,0.00179994f,
0.959415f,0.36074f,-0.301921f,0.958841f,0.804148f,0.00203167f, 0.953484f,0.372375f,-0.309478f,0.943651f,0.805447f,0.00229298f,
0.956542f,0.385814f,-0.315743f,0.925469f,0.806925f,0.00258762f, 0.939226f,0.394576f,-0.323539f,0.912624f,0.808641f,0.00291984f,
0.94134f,0.407828f,-0.329066f,0.894218f,0.810573f,0.00329457f, 0.922795f,0.41569f,-0.336163f,0.880925f,0.812721f,0.00371743f,
0.929111f,0.429812f,-0.340247f,0.860657f,0.815084f,0.00419455f, 0.903359f,0.435176f,-0.347f,0.84803f,0.817668f,0.00473296f,
0.894908f,0.444997f,-0.351388f,0.830433f,0.820476f,0.00534027f, 0.892202f,0.456211f,-0.354523f,0.8109f,0.823515f,0.0060258f,
0.881153f,0.464715f,-0.358169f,0.793514f,0.826799f,0.00680092f, 0.861718f,0.470737f,-0.362199f,0.77787f,0.830321f,0.00767544f,
0.859989f,0.482029f,-0.363537f,0.757377f,0.834101f,0.00866488f, 0.837581f,0.485605f,-0.366559f,0.741357f,0.838136f,0.00978261f,
0.826185f,0.492735f,-0.367651f,0.722313f,0.842442f,0.0110479f, 0.814446f,0.499453f,-0.368257f,0.703299f,0.847019f,0.0124779f,
0.810799f,0.509046f,-0.36757f,0.682783f,0.851893f,0.0140995f, 0.802907f,0.516811f,-0.367553f,0.664487f,0.857059f,0.0159344f,
0.775316f,0.51616f,-0.367892f,0.64768f,0.862535f,0.0180133f, 0.767719f,0.523205f,-0.36549f,0.626927f,0.868347f,0.0203739f,
0.742806f,0.522438f,-0.363792f,0.608315f,0.874501f,0.0230513f, 0.726332f,0.524754f,-0.360569f,0.588061f,0.881015f,0.0260902f,
0.710441f,0.52682f,-0.356845f,0.567921f,0.887913f,0.0295427f, 0.69452f,0.528374f,-0.352344f,0.547458f,0.895225f,0.0334698f,
0.684027f,0.532393f,-0.347021f,0.526627f,0.902987f,0.0379441f, 0.653663f,0.525392f,-0.342065f,0.507242f,0.91122f,0.0430396f,
0.635836f,0.52426f,-0.335464f,0.486299f,0.919959f,0.0488478f, 0.622488f,0.525225f,-0.328423f,0.465619f,0.929247f,0.0554728f,
0.592845f,0.516093f,-0.320756f,0.444943f,0.939125f,0.0630338f, 0.570256f,0.510168f,-0.311767f,0.423283f,0.949703f,0.0717105f,
0.545753f,0.502401f,-0.301664f,0.401015f,0.961018f,0.0816602f, 0.521277f,0.488944f,-0.28981f,0.377531f,0.972915f,0.0928837f,
0.480121f,0.473841f,-0.278022f,0.354636f,0.986315f,0.106332f, 0.447116f,0.458032f,-0.264907f,0.331647f,0.999578f,0.120598f,
0.999999f,-2.06961e-07f,2.17255e-18f,1.21954f,0.769437f,9.26701e-05f, 1.00004f,0.00941079f,-0.00909102f,1.21924f,0.769456f,9.34296e-05f,
1.00006f,0.0188291f,-0.0181666f,1.21868f,0.769532f,9.5758e-05f, 0.999926f,0.0282741f,-0.0272709f,1.21771f,0.769615f,9.95827e-05f,
0.999672f,0.0377825f,-0.0364483f,1.21628f,0.769734f,0.000105042f, 0.99931f,0.0472788f,-0.0455843f,1.21439f,0.769909f,0.000112214f,
0.999302f,0.0568154f,-0.0548371f,1.21199f,0.770095f,0.000121168f, 0.999504f,0.0663522f,-0.0641535f,1.2091f,0.770306f,0.000132058f,
1.00062f,0.075878f,-0.073443f,1.20578f,0.770589f,0.000145081f, 1.0019f,0.0855975f,-0.0828441f,1.20209f,0.770901f,0.000160405f,
1.0037f,0.0956374f,-0.0923955f,1.19773f,0.771224f,0.000178271f, 1.00584f,0.106161f,-0.101936f,1.19269f,0.771601f,0.000198914f,
1.00842f,0.117433f,-0.111448f,1.18707f,0.772059f,0.000222697f, 1.0084f,0.12871f,-0.121014f,1.18079f,0.772535f,0.000249838f,
1.00686f,0.139853f,-0.130778f,1.1746f,0.773026f,0.000280857f, 1.00968f,0.152301f,-0.140718f,1.16842f,0.77351f,0.000316038f,
1.0101f,0.164083f,-0.15068f,1.16076f,0.774021f,0.000356101f, 1.00987f,0.175832f,-0.160585f,1.15245f,0.774618f,0.000401479f,
1.009f,0.187303f,-0.17032f,1.14365f,0.77536f,0.000452951f, 1.0086f,0.198993f,-0.180012f,1.13433f,0.776168f,0.000511087f,
1.00657f,0.210565f,-0.189723f,1.12468f,0.777021f,0.000576694f, 1.00643f,0.222441f,-0.19941f,1.11435f,0.777922f,0.000650873f,
1.00493f,0.233918f,-0.208897f,1.10268f,0.778915f,0.000734447f, 1.00292f,0.245758f,-0.218517f,1.09141f,0.780008f,0.00082897f,
1.00316f,0.258131f,-0.228513f,1.08181f,0.781177f,0.000935461f, 1.00124f,0.270084f,-0.238225f,1.07072f,0.782424f,0.00105534f,
0.997617f,0.281959f,-0.247524f,1.05783f,0.783762f,0.00119048f, 0.99246f,0.29336f,-0.256676f,1.04455f,0.785228f,0.00134302f,
0.992646f,0.305955f,-0.2653f,1.02956f,0.786868f,0.00151491f, 0.983936f,0.317011f,-0.274392f,1.01684f,0.788654f,0.00170857f,
0.984355f,0.32952f,-0.282398f,1.00065f,0.790585f,0.00192681f, 0.992597f,0.342014f,-0.290354f,0.985002f,0.792665f,0.00217277f,
0.980529f,0.352001f,-0.298287f,0.969983f,0.794902f,0.00245006f, 0.960848f,0.362825f,-0.307084f,0.958352f,0.7973f,0.00276259f,
0.953728f,0.37393f,-0.314136f,0.941936f,0.799896f,0.00311498f, 0.946012f,0.384691f,-0.321084f,0.926042f,0.802724f,0.00351234f,
0.939145f,0.395671f,-0.327405f,0.909169f,0.805766f,0.00396097f, 0.943297f,0.407405f,-0.332167f,0.888963f,0.809018f,0.00446763f,
0.924798f,0.416896f,-0.338667f,0.874353f,0.812478f,0.00503919f, 0.913786f,0.426411f,-0.344127f,0.857862f,0.816149f,0.00568438f,
0.900649f,0.434996f,-0.348857f,0.840426f,0.820046f,0.00641419f, 0.891067f,0.444391f,-0.352699f,0.821849f,0.824158f,0.00723761f,
0.893266f,0.455611f,-0.354946f,0.800607f,0.828509f,0.00817022f, 0.880806f,0.464969f,-0.358028f,0.782344f,0.833088f,0.00922324f,
0.856001f,0.469086f,-0.361698f,0.766231f,0.837919f,0.0104168f, 0.85729f,0.480772f,-0.362395f,0.744818f,0.842997f,0.0117666f,
0.831618f,0.483538f,-0.364844f,0.727995f,0.848337f,0.0132954f, 0.822087f,0.491207f,-0.365584f,0.708659f,0.853959f,0.0150304f,
0.80905f,0.497332f,-0.365412f,0.68857f,0.859861f,0.016996f, 0.795981f,0.503142f,-0.364382f,0.667889f,0.866062f,0.0192258f,
0.79142f,0.512069f,-0.362295f,0.646304f,0.872587f,0.0217602f, 0.759768f,0.509476f,-0.361513f,0.628016f,0.879451f,0.0246408f,
0.752331f,0.517334f,-0.358164f,0.606238f,0.886669f,0.0279149f, 0.725095f,0.514182f,-0.355434f,0.586495f,0.894267f,0.0316399f,
0.706997f,0.515435f,-0.351116f,0.565097f,0.902274f,0.035882f, 0.68836f,0.515839f,-0.346066f,0.543505f,0.910732f,0.0407228f,
0.670794f,0.51624f,-0.340308f,0.521781f,0.919677f,0.0462514f, 0.658436f,0.518792f,-0.334038f,0.500257f,0.929134f,0.0525634f,
0.626718f,0.510606f,-0.327155f,0.478792f,0.939142f,0.0597703f, 0.604534f,0.506594f,-0.31895f,0.456354f,0.949774f,0.068022f,
0.576007f,0.498201f,-0.309637f,0.433252f,0.961164f,0.077541f, 0.547264f,0.488972f,-0.298867f,0.409347f,0.973057f,0.0882546f,
0.518228f,0.478867f,-0.286782f,0.384178f,0.986421f,0.101139f, 0.486613f,0.46592f,-0.273694f,0.359493f,0.999581f,0.114777f,
0.999998f,1.60523e-06f,1.05901e-18f,1.24673f,0.740493f,9.33075e-05f, 1.00007f,0.00759883f,-0.00759198f,1.24651f,0.740527f,9.40282e-05f,
1.00019f,0.0152144f,-0.0151862f,1.24601f,0.740661f,9.62621e-05f, 1.00033f,0.0228837f,-0.0228303f,1.24514f,0.740833f,9.99153e-05f,
1.00049f,0.0306094f,-0.0305096f,1.24391f,0.741112f,0.000105191f, 1.00073f,0.0383998f,-0.0382279f,1.24231f,0.741446f,0.000112033f,
1.00093f,0.0463004f,-0.0461036f,1.24035f,0.74185f,0.00012064f, 1.00119f,0.0542006f,-0.0539475f,1.23796f,0.74234f,0.000131057f,
1.00183f,0.0622309f,-0.0619819f,1.23507f,0.742902f,0.000143544f, 1.00226f,0.0703785f,-0.0701227f,1.23181f,0.74352f,0.000158152f,
1.00296f,0.0786611f,-0.0783138f,1.22807f,0.744264f,0.000175268f, 1.00163f,0.0870788f,-0.0866094f,1.22345f,0.745052f,0.000194922f,
1.00158f,0.0956901f,-0.0951363f,1.21823f,0.745886f,0.000217572f, 1.00263f,0.10468f,-0.103756f,1.21314f,0.746797f,0.000243369f,
1.00447f,0.114193f,-0.112418f,1.20739f,0.747815f,0.000272857f, 1.00746f,0.124659f,-0.121206f,1.20102f,0.748893f,0.000306272f,
1.02164f,0.137323f,-0.129337f,1.18618f,0.750048f,0.000344338f, 1.01585f,0.148008f,-0.139793f,1.19033f,0.751242f,0.000387297f,
1.01781f,0.159048f,-0.14923f,1.18266f,0.752485f,0.000436029f, 1.01843f,0.169983f,-0.158617f,1.17442f,0.753832f,0.000490893f,
1.02625f,0.182321f,-0.167263f,1.16095f,0.755344f,0.000552984f, 1.01792f,0.191613f,-0.177179f,1.15555f,0.756985f,0.000623042f,
1.01572f,0.202486f,-0.186544f,1.14544f,0.758714f,0.000701913f, 1.01525f,0.213615f,-0.195926f,1.1345f,0.760529f,0.000790996f,
1.01377f,0.224647f,-0.205281f,1.12278f,0.762421f,0.000891279f, 1.01286f,0.23608f,-0.21469f,1.1109f,0.764455f,0.00100426f,
1.00993f,0.247399f,-0.22402f,1.09827f,0.766616f,0.00113156f, 1.00865f,0.259159f,-0.23374f,1.08726f,0.768891f,0.00127499f,
1.00537f,0.270693f,-0.243252f,1.0751f,0.77128f,0.00143661f, 1.003f,0.28248f,-0.252213f,1.06059f,0.773798f,0.0016187f,
0.996658f,0.29376f,-0.261538f,1.04785f,0.77651f,0.00182393f, 0.990954f,0.305005f,-0.270113f,1.03242f,0.779384f,0.00205522f,
0.986156f,0.316766f,-0.27869f,1.01749f,0.782412f,0.00231601f, 0.996484f,0.330871f,-0.285878f,0.998216f,0.785593f,0.0026101f,
0.975886f,0.339775f,-0.295295f,0.987329f,0.788928f,0.00294171f, 0.968455f,0.350927f,-0.30321f,0.971924f,0.792421f,0.00331548f,
0.961466f,0.362197f,-0.310439f,0.9551f,0.796131f,0.003737f, 0.95944f,0.374278f,-0.316699f,0.936163f,0.800056f,0.00421365f,
0.944719f,0.383792f,-0.32381f,0.920631f,0.804173f,0.00475141f, 0.941983f,0.395725f,-0.329291f,0.90137f,0.808485f,0.0053587f,
0.927393f,0.404697f,-0.335625f,0.885351f,0.813f,0.00604557f, 0.927927f,0.417128f,-0.339814f,0.864681f,0.817711f,0.00682127f,
0.914964f,0.426248f,-0.34457f,0.846499f,0.822636f,0.00769958f, 0.896248f,0.433609f,-0.349482f,0.829643f,0.827771f,0.00869288f,
0.887091f,0.442997f,-0.352492f,0.809282f,0.833123f,0.00981702f, 0.874971f,0.451333f,-0.355656f,0.790316f,0.838712f,0.0110922f,
0.878533f,0.464052f,-0.357104f,0.768661f,0.844532f,0.0125358f, 0.85306f,0.467863f,-0.3602f,0.751583f,0.850601f,0.014173f,
0.851721f,0.478698f,-0.360041f,0.728747f,0.856939f,0.0160335f, 0.82396f,0.480824f,-0.36161f,0.710502f,0.863548f,0.0181445f,
0.808823f,0.486476f,-0.361103f,0.689207f,0.870444f,0.0205422f, 0.793795f,0.491829f,-0.35986f,0.66761f,0.877653f,0.0232696f,
0.781859f,0.497861f,-0.357918f,0.645797f,0.885203f,0.0263779f, 0.758604f,0.499044f,-0.356321f,0.625668f,0.893104f,0.0299167f,
0.741284f,0.502025f,-0.352905f,0.6034f,0.901382f,0.033949f, 0.73177f,0.507804f,-0.348376f,0.580345f,0.91007f,0.038548f,
0.701008f,0.503718f,-0.344246f,0.559012f,0.919214f,0.0438062f, 0.683009f,0.504725f,-0.338935f,0.536778f,0.928862f,0.0498284f,
0.661244f,0.50328f,-0.332321f,0.513573f,0.939025f,0.0567104f, 0.64017f,0.501456f,-0.324771f,0.490054f,0.949735f,0.0645685f,
0.609014f,0.493736f,-0.316587f,0.466522f,0.961214f,0.0736815f, 0.578611f,0.48542f,-0.306428f,0.441442f,0.97315f,0.08394f,
0.547318f,0.475905f,-0.294952f,0.415065f,0.986492f,0.0962878f, 0.511211f,0.462624f,-0.282921f,0.389927f,0.999583f,0.109346f,
0.999997f,-2.04062e-06f,2.28997e-18f,1.2718f,0.711124f,9.32231e-05f, 1.00007f,0.00575818f,-0.00605809f,1.27157f,0.711174f,9.39037e-05f,
1.00023f,0.0115448f,-0.0121286f,1.27112f,0.711361f,9.60375e-05f, 1.00044f,0.017394f,-0.0182558f,1.27037f,0.711632f,9.95355e-05f,
1.00069f,0.0233112f,-0.0244209f,1.26932f,0.712045f,0.00010458f, 1.00107f,0.0293149f,-0.0306822f,1.26792f,0.712549f,0.000111127f,
1.00164f,0.0354448f,-0.0370351f,1.26621f,0.713173f,0.000119344f, 1.00238f,0.0416809f,-0.043488f,1.26417f,0.713907f,0.00012931f,
1.00279f,0.0481079f,-0.0501263f,1.26178f,0.714729f,0.000141158f, 1.00233f,0.0546301f,-0.0568301f,1.25892f,0.715705f,0.000155143f,
1.00235f,0.0613304f,-0.0637392f,1.25583f,0.716769f,0.000171355f, 1.00267f,0.0682199f,-0.0708692f,1.25218f,0.717935f,0.000190107f,
1.00333f,0.0752459f,-0.0780524f,1.24803f,0.719232f,0.000211563f, 1.00402f,0.0825524f,-0.0855066f,1.24366f,0.72062f,0.00023612f,
1.0057f,0.0902188f,-0.093217f,1.2386f,0.722062f,0.000263971f, 1.00811f,0.0983772f,-0.101057f,1.23304f,0.723666f,0.000295744f,
1.01018f,0.107094f,-0.109013f,1.22708f,0.725404f,0.000331691f, 1.01352f,0.116919f,-0.117259f,1.22109f,0.727233f,0.000372378f,
1.01806f,0.12782f,-0.125795f,1.21473f,0.729132f,0.000418345f, 1.02294f,0.138615f,-0.134678f,1.20861f,0.731103f,0.000470126f,
1.02583f,0.149005f,-0.143914f,1.20243f,0.733193f,0.000528784f, 1.027f,0.159107f,-0.152927f,1.19427f,0.735472f,0.000594797f,
1.02676f,0.169341f,-0.161988f,1.18553f,0.737892f,0.0006691f, 1.02668f,0.179618f,-0.171105f,1.17566f,0.740442f,0.000752924f,
1.02536f,0.190043f,-0.18031f,1.16499f,0.743147f,0.000847453f, 1.02333f,0.200617f,-0.189582f,1.15356f,0.745967f,0.000953826f,
1.02213f,0.211541f,-0.198999f,1.14198f,0.748892f,0.00107357f, 1.01944f,0.222294f,-0.208326f,1.1291f,0.751947f,0.00120843f,
1.01796f,0.233583f,-0.217812f,1.11649f,0.755171f,0.00136046f, 1.01824f,0.245191f,-0.226905f,1.10156f,0.758527f,0.00153169f,
1.01969f,0.257395f,-0.236308f,1.08801f,0.762005f,0.00172462f, 1.01014f,0.268118f,-0.246376f,1.07733f,0.765619f,0.00194199f,
1.01312f,0.280585f,-0.254758f,1.05942f,0.769427f,0.002187f, 0.999838f,0.29114f,-0.264547f,1.04765f,0.773389f,0.0024631f,
0.994078f,0.30264f,-0.273142f,1.03139f,0.777503f,0.00277495f, 0.988911f,0.314529f,-0.281679f,1.01548f,0.781758f,0.00312666f,
0.98844f,0.326865f,-0.289138f,0.996497f,0.78615f,0.00352289f, 0.978521f,0.337908f,-0.297676f,0.98193f,0.790724f,0.00397103f,
0.967797f,0.348921f,-0.305728f,0.966396f,0.795499f,0.00447677f, 0.960796f,0.360296f,-0.312655f,0.948103f,0.800458f,0.00504844f,
0.963898f,0.373645f,-0.318171f,0.926602f,0.805597f,0.0056946f, 0.944377f,0.382339f,-0.325507f,0.911363f,0.810918f,0.00642566f,
0.944587f,0.395043f,-0.330202f,0.889738f,0.81642f,0.00725216f, 0.924472f,0.403205f,-0.33666f,0.873854f,0.822121f,0.00818948f,
0.928309f,0.416574f,-0.339953f,0.850866f,0.828011f,0.00924979f, 0.918481f,0.42734f,-0.345895f,0.835556f,0.834108f,0.0104523f,
0.894658f,0.432784f,-0.349256f,0.814976f,0.840423f,0.0118171f, 0.885181f,0.442289f,-0.351734f,0.793537f,0.846956f,0.0133645f,
0.871237f,0.45035f,-0.354138f,0.773104f,0.853725f,0.0151216f, 0.854739f,0.457258f,-0.356007f,0.752603f,0.860754f,0.0171216f,
0.843083f,0.465225f,-0.35639f,0.730155f,0.868045f,0.0193951f, 0.823049f,0.470193f,-0.356957f,0.709274f,0.875617f,0.0219813f,
0.807591f,0.476091f,-0.356239f,0.687004f,0.883492f,0.0249268f, 0.791529f,0.481315f,-0.354834f,0.664576f,0.891706f,0.02829f,
0.774128f,0.485595f,-0.352619f,0.641821f,0.900276f,0.0321284f, 0.762707f,0.491747f,-0.34915f,0.618013f,0.909223f,0.036509f,
0.737621f,0.491974f,-0.34658f,0.596957f,0.918581f,0.0415129f, 0.71785f,0.493632f,-0.341749f,0.573103f,0.92842f,0.0472553f,
0.692907f,0.492486f,-0.33646f,0.549663f,0.938763f,0.0538376f, 0.669429f,0.491059f,-0.329752f,0.525161f,0.949603f,0.0613498f,
0.643955f,0.488047f,-0.321855f,0.499839f,0.961167f,0.0700649f, 0.616219f,0.483342f,-0.31262f,0.473919f,0.973185f,0.0799113f,
0.576261f,0.471547f,-0.302604f,0.447481f,0.986526f,0.0917551f, 0.540554f,0.4609f,-0.291425f,0.421531f,0.999584f,0.104279f,
1.0f,2.4432e-06f,2.72183e-19f,1.29475f,0.681588f,9.24926e-05f, 1.00005f,0.00392785f,-0.00451381f,1.29436f,0.681664f,9.31574e-05f,
1.00018f,0.00788658f,-0.00903184f,1.29399f,0.681888f,9.51568e-05f, 1.00038f,0.0119103f,-0.0136336f,1.29334f,0.682264f,9.8529e-05f,
1.00067f,0.0159973f,-0.0182546f,1.29245f,0.682788f,0.000103298f, 1.00115f,0.0202091f,-0.0230243f,1.29127f,0.683461f,0.000109565f,
1.00166f,0.0245148f,-0.0278518f,1.28982f,0.684279f,0.000117364f, 1.00224f,0.0290036f,-0.0328614f,1.28808f,0.685247f,0.000126871f,
1.00301f,0.0336568f,-0.0380068f,1.28605f,0.686347f,0.000138133f, 1.00388f,0.0385148f,-0.0433189f,1.2837f,0.687605f,0.000151391f,
1.00451f,0.0436127f,-0.0488823f,1.28104f,0.688991f,0.000166778f, 1.00509f,0.0488774f,-0.0545736f,1.27806f,0.690555f,0.000184558f,
1.00572f,0.0544051f,-0.0605441f,1.27469f,0.692238f,0.000204909f, 1.00629f,0.060225f,-0.0667969f,1.27104f,0.694046f,0.000228138f,
1.0076f,0.0662828f,-0.0731936f,1.2669f,0.696014f,0.000254527f, 1.0089f,0.0727425f,-0.0799322f,1.26252f,0.698117f,0.000284538f,
1.01114f,0.0796827f,-0.0870198f,1.25761f,0.700327f,0.000318452f, 1.01396f,0.0872009f,-0.0942955f,1.25254f,0.702723f,0.00035692f,
1.01635f,0.0952873f,-0.101785f,1.24687f,0.70525f,0.000400217f, 1.02005f,0.104392f,-0.109639f,1.24105f,0.707912f,0.000449105f,
1.02285f,0.113881f,-0.117828f,1.23436f,0.710706f,0.000504357f, 1.02647f,0.12384f,-0.126367f,1.22725f,0.713596f,0.000566481f,
1.03063f,0.133864f,-0.1353f,1.22082f,0.716611f,0.000636408f, 1.03238f,0.14353f,-0.144174f,1.21307f,0.719889f,0.00071526f,
1.03326f,0.153315f,-0.15316f,1.20416f,0.723334f,0.000804141f, 1.03275f,0.163258f,-0.162199f,1.19356f,0.726907f,0.000904134f,
1.04623f,0.176174f,-0.170518f,1.17618f,0.730638f,0.00101673f, 1.02957f,0.183745f,-0.180851f,1.17097f,0.734523f,0.00114356f,
1.02775f,0.194518f,-0.190439f,1.15913f,0.738528f,0.00128633f, 1.02535f,0.205452f,-0.2f,1.14603f,0.742659f,0.00144705f,
1.02186f,0.216441f,-0.209593f,1.1323f,0.746968f,0.00162829f, 1.0218f,0.22824f,-0.219384f,1.11902f,0.751411f,0.00183265f,
1.02522f,0.240426f,-0.228459f,1.10189f,0.755971f,0.00206296f, 1.02686f,0.252702f,-0.23797f,1.08697f,0.760673f,0.00232238f,
1.01253f,0.26346f,-0.248288f,1.07559f,0.765553f,0.00261514f, 1.02041f,0.276905f,-0.25659f,1.05569f,0.770574f,0.00294586f,
1.00114f,0.287328f,-0.266736f,1.04384f,0.775718f,0.00331839f, 0.996043f,0.299428f,-0.275488f,1.02682f,0.780996f,0.00373991f,
0.989815f,0.311527f,-0.283894f,1.00928f,0.786405f,0.00421519f, 0.994843f,0.324964f,-0.291011f,0.988068f,0.79201f,0.00475339f,
0.98381f,0.33625f,-0.299285f,0.971745f,0.797778f,0.00536105f, 0.967553f,0.347068f,-0.307727f,0.956609f,0.803716f,0.00604996f,
0.958895f,0.358591f,-0.314464f,0.937075f,0.809812f,0.00682878f, 0.94916f,0.369817f,-0.32106f,0.918162f,0.81608f,0.00771162f,
0.939691f,0.380907f,-0.326802f,0.897901f,0.822524f,0.00871288f, 0.941662f,0.393978f,-0.331591f,0.876272f,0.829144f,0.00984727f,
0.924055f,0.403013f,-0.337345f,0.858317f,0.835957f,0.0111357f, 0.911167f,0.412765f,-0.341693f,0.837869f,0.842975f,0.0126003f,
0.897514f,0.422071f,-0.345141f,0.816461f,0.850199f,0.0142634f, 0.883685f,0.430969f,-0.347713f,0.794267f,0.857647f,0.0161544f,
0.878367f,0.441634f,-0.349026f,0.770527f,0.865344f,0.01831f, 0.862306f,0.449328f,-0.350508f,0.748493f,0.873302f,0.0207662f,
0.8383f,0.454229f,-0.351925f,0.727564f,0.881532f,0.0235646f, 0.830687f,0.463304f,-0.35115f,0.703388f,0.890063f,0.0267572f,
0.804313f,0.466271f,-0.350909f,0.681549f,0.898934f,0.0304104f, 0.785654f,0.470984f,-0.348974f,0.657686f,0.908164f,0.034589f,
0.770583f,0.476442f,-0.346629f,0.634368f,0.917772f,0.039365f, 0.749774f,0.479282f,-0.342887f,0.609799f,0.927803f,0.0448335f,
0.73822f,0.485197f,-0.337941f,0.584349f,0.938352f,0.0511389f, 0.702473f,0.48066f,-0.333069f,0.560423f,0.949358f,0.0583376f,
0.674525f,0.478444f,-0.32636f,0.534587f,0.961021f,0.066675f, 0.64459f,0.474511f,-0.318088f,0.507746f,0.973157f,0.0761461f,
0.616569f,0.470704f,-0.308098f,0.478984f,0.986525f,0.0875193f, 0.57949f,0.461337f,-0.297243f,0.451365f,0.999584f,0.0995504f,
0.999995f,4.17963e-06f,1.25967e-18f,1.31561f,0.652121f,9.1202e-05f, 0.999991f,0.00211951f,-0.00296106f,1.31503f,0.652215f,9.18382e-05f,
1.00007f,0.00427217f,-0.0059578f,1.31472f,0.65248f,9.3723e-05f, 1.00026f,0.00647162f,-0.00899125f,1.31419f,0.652942f,9.69341e-05f,
1.00059f,0.00876555f,-0.0121221f,1.31343f,0.653579f,0.000101474f, 1.00107f,0.0111544f,-0.0153311f,1.31245f,0.654398f,0.000107409f,
1.00171f,0.0136851f,-0.0186916f,1.31124f,0.655401f,0.000114848f, 1.00247f,0.0163789f,-0.0221804f,1.30979f,0.656576f,0.000123833f,
1.00339f,0.0192784f,-0.0258717f,1.30809f,0.657937f,0.000134565f, 1.00439f,0.0224047f,-0.0297324f,1.30616f,0.659463f,0.000147089f,
1.00544f,0.0257957f,-0.0338575f,1.30395f,0.661164f,0.000161676f, 1.00657f,0.029437f,-0.038166f,1.30147f,0.663052f,0.000178446f,
1.00746f,0.0334142f,-0.042833f,1.29871f,0.665107f,0.000197733f, 1.00844f,0.037627f,-0.0476693f,1.29565f,0.667353f,0.00021966f,
1.00953f,0.0422178f,-0.052894f,1.29227f,0.669749f,0.000244641f, 1.011f,0.0471804f,-0.058427f,1.28859f,0.672303f,0.000272888f,
1.01274f,0.052537f,-0.0642199f,1.28455f,0.675072f,0.000304944f, 1.01473f,0.0583814f,-0.0704251f,1.28016f,0.677989f,0.000341158f,
1.0167f,0.064764f,-0.07705f,1.27534f,0.681031f,0.000381932f, 1.01939f,0.0716654f,-0.0838916f,1.27024f,0.684305f,0.000428004f,
1.02137f,0.0790465f,-0.0910781f,1.26445f,0.687764f,0.000479971f, 1.02435f,0.0871532f,-0.0986899f,1.25834f,0.691357f,0.000538415f,
1.02606f,0.0956149f,-0.106708f,1.25141f,0.69509f,0.000604206f, 1.02889f,0.104731f,-0.115143f,1.24383f,0.698983f,0.000678321f,
1.03156f,0.114137f,-0.123766f,1.23566f,0.703075f,0.000761743f, 1.04271f,0.12495f,-0.132004f,1.22204f,0.707389f,0.000855659f,
1.03735f,0.13354f,-0.141785f,1.21951f,0.711902f,0.000961462f, 1.05145f,0.144805f,-0.150207f,1.20235f,0.716553f,0.00108054f,
1.03799f,0.153885f,-0.160562f,1.19801f,0.721353f,0.0012147f, 1.04239f,0.163034f,-0.169893f,1.18354f,0.726319f,0.00136584f,
1.03548f,0.175426f,-0.180152f,1.17373f,0.731402f,0.00153597f, 1.03277f,0.186681f,-0.190164f,1.16072f,0.736612f,0.00172754f,
1.03153f,0.198332f,-0.20032f,1.14738f,0.741991f,0.00194396f, 1.02795f,0.209962f,-0.21031f,1.13237f,0.747484f,0.00218786f,
1.02652f,0.222082f,-0.220329f,1.11719f,0.753075f,0.0024626f, 1.03125f,0.235072f,-0.229803f,1.09917f,0.758839f,0.00277333f,
1.03281f,0.247701f,-0.23935f,1.08183f,0.764731f,0.0031235f, 1.01448f,0.259154f,-0.250299f,1.07078f,0.770746f,0.00351986f,
1.00899f,0.271614f,-0.259842f,1.05393f,0.776862f,0.00396682f, 1.00559f,0.284472f,-0.268759f,1.03516f,0.783097f,0.00447314f,
0.995716f,0.296772f,-0.277813f,1.01774f,0.789497f,0.00504523f, 0.995849f,0.310149f,-0.285696f,0.996929f,0.796052f,0.00569329f,
0.982151f,0.321842f,-0.294778f,0.981176f,0.802757f,0.00642785f, 0.973524f,0.334067f,-0.302621f,0.962197f,0.809603f,0.00725937f,
0.9642f,0.34625f,-0.309807f,0.94218f,0.816609f,0.00820387f, 0.959002f,0.358642f,-0.316536f,0.921958f,0.823774f,0.00927593f,
0.950033f,0.370354f,-0.322789f,0.901582f,0.831101f,0.0104926f, 0.938508f,0.381551f,-0.328076f,0.879791f,0.838607f,0.0118761f,
0.925606f,0.392163f,-0.333138f,0.858693f,0.846309f,0.0134521f, 0.918911f,0.403802f,-0.336512f,0.834682f,0.854207f,0.0152446f,
0.903548f,0.413292f,-0.340271f,0.813061f,0.862319f,0.0172862f, 0.883313f,0.421335f,-0.343418f,0.791288f,0.870673f,0.0196172f,
0.86878f,0.430165f,-0.345216f,0.767785f,0.879285f,0.0222799f, 0.853299f,0.43828f,-0.346445f,0.74447f,0.888166f,0.0253189f,
0.851692f,0.450745f,-0.346193f,0.719446f,0.897346f,0.0287921f, 0.818828f,0.452155f,-0.346136f,0.696221f,0.906876f,0.032779f,
0.814541f,0.462381f,-0.344325f,0.670912f,0.916764f,0.0373451f, 0.779834f,0.462418f,-0.342773f,0.647569f,0.927029f,0.0425694f,
0.758138f,0.465874f,-0.339301f,0.621908f,0.937785f,0.0486021f, 0.735951f,0.468494f,-0.334739f,0.595782f,0.948991f,0.0555143f,
0.71793f,0.471017f,-0.328652f,0.568378f,0.960776f,0.0634965f, 0.676516f,0.465718f,-0.322137f,0.541852f,0.973063f,0.0726252f,
0.642877f,0.461529f,-0.313475f,0.512642f,0.986489f,0.0835602f, 0.606198f,0.454725f,-0.303794f,0.484486f,0.999583f,0.0951378f,
0.999996f,-3.29781e-06f,-1.6082e-18f,1.33446f,0.622935f,8.94553e-05f, 0.999986f,0.000343142f,-0.00143152f,1.33391f,0.623047f,9.00665e-05f,
1.00008f,0.000726022f,-0.00291519f,1.33365f,0.623368f,9.18782e-05f, 1.00029f,0.00113281f,-0.00441695f,1.33321f,0.623893f,9.48978e-05f,
1.00063f,0.00166017f,-0.00604824f,1.33259f,0.624626f,9.91925e-05f, 1.00113f,0.00226847f,-0.00774182f,1.3318f,0.625576f,0.000104816f,
1.00177f,0.00304316f,-0.00960402f,1.33081f,0.626725f,0.000111826f, 1.00254f,0.00397771f,-0.0116128f,1.32961f,0.628102f,0.000120369f,
1.00346f,0.00514396f,-0.0138173f,1.32822f,0.629674f,0.000130487f, 1.00449f,0.00655123f,-0.0162445f,1.32664f,0.631465f,0.000142388f,
1.00563f,0.00824109f,-0.0189003f,1.32483f,0.63345f,0.00015614f, 1.00684f,0.0102322f,-0.0218379f,1.3228f,0.635644f,0.000172019f,
1.00815f,0.0125352f,-0.0250616f,1.32052f,0.638035f,0.000190153f, 1.00952f,0.015183f,-0.0285838f,1.31797f,0.640653f,0.000210891f,
1.01104f,0.0182424f,-0.0324938f,1.31515f,0.643451f,0.00023442f, 1.01269f,0.0216645f,-0.0366697f,1.31205f,0.646466f,0.000261044f,
1.0145f,0.0255836f,-0.0413193f,1.30862f,0.649669f,0.000291244f, 1.01648f,0.0299668f,-0.0463139f,1.30491f,0.653087f,0.000325304f,
1.01828f,0.0348145f,-0.0516648f,1.30085f,0.656714f,0.000363695f, 1.02013f,0.0402255f,-0.05753f,1.29635f,0.660513f,0.000407027f,
1.02219f,0.0461491f,-0.0638445f,1.29145f,0.664522f,0.000455874f, 1.0243f,0.0525607f,-0.0704465f,1.28612f,0.668762f,0.000510818f,
1.02642f,0.0595227f,-0.0775075f,1.28022f,0.673188f,0.000572657f, 1.02854f,0.0670459f,-0.0850698f,1.27372f,0.677802f,0.000642296f,
1.03063f,0.0751385f,-0.0931453f,1.26668f,0.682562f,0.000720648f, 1.03255f,0.0837521f,-0.10166f,1.25891f,0.687506f,0.000808863f,
1.03441f,0.0927569f,-0.110305f,1.25037f,0.692719f,0.000908188f, 1.03618f,0.102194f,-0.119236f,1.24103f,0.69811f,0.00101993f,
1.03784f,0.112047f,-0.128497f,1.23096f,0.703696f,0.00114571f, 1.04816f,0.122768f,-0.137998f,1.21932f,0.709423f,0.00128751f,
1.04534f,0.133081f,-0.148284f,1.21107f,0.715291f,0.00144735f, 1.04546f,0.144017f,-0.158472f,1.19901f,0.72131f,0.00162733f,
1.04393f,0.155421f,-0.168881f,1.18635f,0.727431f,0.0018302f, 1.04151f,0.167082f,-0.179439f,1.17289f,0.733696f,0.00205929f,
1.03985f,0.17918f,-0.190055f,1.15858f,0.740085f,0.00231736f, 1.03642f,0.191505f,-0.200686f,1.1434f,0.746571f,0.00260921f,
1.03392f,0.204051f,-0.211259f,1.12751f,0.753166f,0.00293816f, 1.03041f,0.216928f,-0.221824f,1.11131f,0.75991f,0.00331067f,
1.03766f,0.230469f,-0.231233f,1.08975f,0.76675f,0.00373119f, 1.02198f,0.243079f,-0.242813f,1.07864f,0.773685f,0.00420715f,
1.01593f,0.256402f,-0.252827f,1.06076f,0.780713f,0.00474604f, 1.00956f,0.269661f,-0.262629f,1.04273f,0.787885f,0.00535564f,
1.00297f,0.282922f,-0.271954f,1.02358f,0.795203f,0.00604784f, 0.995947f,0.29624f,-0.280925f,1.0041f,0.802649f,0.00683251f,
1.00494f,0.310758f,-0.288304f,0.980245f,0.810225f,0.0077224f, 0.983812f,0.322682f,-0.297879f,0.96494f,0.817946f,0.00873474f,
0.97422f,0.335358f,-0.305516f,0.944372f,0.825813f,0.00988569f, 0.96314f,0.347733f,-0.31227f,0.922451f,0.833831f,0.0111939f,
0.962129f,0.361374f,-0.317587f,0.897835f,0.842015f,0.0126838f, 0.938587f,0.37152f,-0.324112f,0.878055f,0.850388f,0.0143849f,
0.932435f,0.38394f,-0.328342f,0.853548f,0.858948f,0.0163233f, 0.911796f,0.393508f,-0.333169f,0.832129f,0.867715f,0.0185349f,
0.896414f,0.403474f,-0.336646f,0.808781f,0.876721f,0.0210655f, 0.881501f,0.413173f,-0.339199f,0.784754f,0.885983f,0.0239628f,
0.864945f,0.421995f,-0.340715f,0.759951f,0.895512f,0.0272753f, 0.847207f,0.430027f,-0.341545f,0.735221f,0.905344f,0.0310713f,
0.839354f,0.440085f,-0.341178f,0.709454f,0.915541f,0.035443f, 0.810796f,0.444113f,-0.34054f,0.684776f,0.92608f,0.0404471f,
0.799211f,0.452421f,-0.337844f,0.657521f,0.937055f,0.0462161f, 0.764618f,0.452854f,-0.335328f,0.632206f,0.948494f,0.0528651f,
0.739114f,0.455359f,-0.330602f,0.604344f,0.960431f,0.060516f, 0.711325f,0.456428f,-0.324617f,0.575892f,0.972903f,0.0693308f,
0.672371f,0.452478f,-0.317732f,0.546951f,0.986417f,0.0798587f, 0.63399f,0.447558f,-0.309352f,0.518392f,0.99958f,0.0910188f,
0.999993f,2.3805e-06f,4.3722e-18f,1.35137f,0.594206f,8.73305e-05f, 1.00005f,-0.00138945f,4.38133e-05f,1.35109f,0.594327f,8.79031e-05f,
1.0002f,-0.00276539f,9.13011e-05f,1.3509f,0.594681f,8.9604e-05f, 1.00045f,-0.00407176f,2.93168e-05f,1.35056f,0.595272f,9.24755e-05f,
1.0008f,-0.00529688f,-6.66592e-05f,1.35009f,0.596102f,9.65406e-05f, 1.00128f,-0.00639981f,-0.000307255f,1.34948f,0.597165f,0.000101861f,
1.00187f,-0.00733298f,-0.000696007f,1.34871f,0.598461f,0.000108501f, 1.00256f,-0.0081114f,-0.0012191f,1.3478f,0.599996f,0.000116543f,
1.00338f,-0.0086283f,-0.00199466f,1.34672f,0.601755f,0.000126103f, 1.00433f,-0.0089079f,-0.00293803f,1.34547f,0.603761f,0.0001373f,
1.00542f,-0.00888936f,-0.00418924f,1.34401f,0.606001f,0.000150318f, 1.00664f,-0.00855203f,-0.00568883f,1.34238f,0.608477f,0.000165279f,
1.00806f,-0.0078619f,-0.00751336f,1.3405f,0.611178f,0.00018239f, 1.00968f,-0.00677615f,-0.00967412f,1.3384f,0.614112f,0.0002019f,
1.01149f,-0.00528968f,-0.0121879f,1.33607f,0.617284f,0.000224032f, 1.01352f,-0.00333769f,-0.0150892f,1.33347f,0.620698f,0.000249165f,
1.01572f,-0.000914866f,-0.0184307f,1.3306f,0.62432f,0.000277529f, 1.01808f,0.00198969f,-0.0221311f,1.32742f,0.628199f,0.000309539f,
1.02056f,0.0054476f,-0.0263819f,1.32389f,0.632288f,0.000345645f, 1.02313f,0.00942593f,-0.0310114f,1.32f,0.636626f,0.000386361f,
1.0258f,0.0139518f,-0.0361312f,1.31574f,0.641206f,0.000432236f, 1.02853f,0.0191114f,-0.0418487f,1.31105f,0.645982f,0.000483854f,
1.03125f,0.0248088f,-0.0479838f,1.30585f,0.650997f,0.000541914f, 1.03393f,0.0310585f,-0.0545551f,1.30013f,0.656273f,0.000607289f,
1.03662f,0.0379149f,-0.0616907f,1.2939f,0.661733f,0.000680807f, 1.03908f,0.045346f,-0.0694119f,1.28705f,0.667389f,0.000763545f,
1.04125f,0.053365f,-0.0777097f,1.27943f,0.673211f,0.000856663f, 1.04315f,0.0618795f,-0.0863512f,1.27116f,0.679265f,0.000961618f,
1.04485f,0.0708624f,-0.0952808f,1.26224f,0.685569f,0.00107978f, 1.04619f,0.0803514f,-0.104626f,1.25276f,0.692026f,0.00121264f,
1.0491f,0.0903397f,-0.114409f,1.24262f,0.698669f,0.00136262f, 1.05143f,0.100801f,-0.12458f,1.2317f,0.705429f,0.0015316f,
1.06316f,0.11169f,-0.134594f,1.21558f,0.712328f,0.0017219f, 1.05424f,0.123199f,-0.146046f,1.20874f,0.719353f,0.001937f,
1.05327f,0.135123f,-0.157128f,1.19578f,0.726463f,0.00217921f, 1.05079f,0.147551f,-0.168351f,1.18171f,0.733718f,0.00245331f,
1.04839f,0.160251f,-0.179654f,1.16681f,0.741054f,0.00276244f, 1.04569f,0.173348f,-0.191022f,1.15134f,0.748473f,0.00311215f,
1.04196f,0.186719f,-0.202342f,1.13504f,0.756027f,0.00350782f, 1.03811f,0.200256f,-0.213529f,1.11791f,0.763667f,0.00395503f,
1.03342f,0.214125f,-0.224658f,1.10056f,0.771391f,0.00446255f, 1.02892f,0.228145f,-0.235724f,1.08336f,0.779186f,0.00503694f,
1.02327f,0.242192f,-0.246473f,1.06531f,0.787112f,0.00568799f, 1.02007f,0.256401f,-0.256505f,1.04497f,0.795169f,0.00642841f,
1.01282f,0.270471f,-0.266795f,1.02668f,0.80334f,0.00726882f, 1.00535f,0.284466f,-0.276232f,1.00621f,0.811629f,0.00822352f,
0.997681f,0.298462f,-0.285139f,0.98506f,0.820049f,0.00931127f, 1.0001f,0.313131f,-0.292548f,0.960308f,0.828606f,0.0105505f,
0.98793f,0.326631f,-0.300538f,0.939095f,0.837303f,0.0119616f, 0.964333f,0.338534f,-0.308649f,0.919627f,0.846156f,0.0135712f,
0.953664f,0.351517f,-0.314793f,0.895754f,0.855193f,0.0154136f, 0.937976f,0.363353f,-0.320656f,0.872786f,0.86441f,0.0175171f,
0.924312f,0.375128f,-0.325371f,0.848401f,0.873829f,0.0199217f, 0.909845f,0.386274f,-0.329562f,0.824325f,0.883489f,0.0226817f,
0.892682f,0.396527f,-0.33285f,0.799711f,0.8934f,0.0258463f, 0.877838f,0.40665f,-0.335127f,0.774451f,0.903577f,0.0294707f,
0.86051f,0.415797f,-0.336406f,0.748577f,0.91409f,0.0336499f, 0.839836f,0.423646f,-0.336609f,0.722118f,0.92494f,0.0384524f,
0.824983f,0.432328f,-0.335337f,0.694353f,0.936158f,0.0439712f, 0.79527f,0.436384f,-0.334017f,0.668148f,0.947861f,0.0503773f,
0.767963f,0.440205f,-0.33087f,0.640171f,0.959982f,0.0577194f, 0.738088f,0.442469f,-0.326193f,0.61099f,0.972672f,0.0662463f,
0.710555f,0.444588f,-0.319371f,0.57918f,0.986308f,0.0763969f, 0.671289f,0.441383f,-0.311638f,0.54906f,0.999577f,0.087173f,
1.0f,4.51612e-06f,2.67754e-19f,1.36648f,0.566078f,8.48961e-05f, 1.00007f,-0.00308112f,0.00150932f,1.36633f,0.566206f,8.54293e-05f,
1.00023f,-0.00611832f,0.00295861f,1.36619f,0.566592f,8.70396e-05f, 1.00048f,-0.00912556f,0.00440212f,1.36599f,0.567236f,8.97377e-05f,
1.00081f,-0.0120212f,0.00571387f,1.36569f,0.568135f,9.35729e-05f, 1.0012f,-0.0147821f,0.00691903f,1.36529f,0.569293f,9.85866e-05f,
1.00168f,-0.0174031f,0.00800287f,1.3648f,0.570716f,0.000104856f, 1.00225f,-0.0198002f,0.00887875f,1.36421f,0.572393f,0.000112455f,
1.00293f,-0.0219955f,0.00957481f,1.36345f,0.57433f,0.000121473f, 1.00377f,-0.0238994f,0.0100325f,1.36257f,0.576527f,0.000132043f,
1.00484f,-0.0254849f,0.0102015f,1.36147f,0.578969f,0.000144276f, 1.00617f,-0.0267469f,0.0101291f,1.3602f,0.581683f,0.000158349f,
1.00776f,-0.0275966f,0.00968062f,1.35872f,0.584658f,0.000174496f, 1.00961f,-0.0280426f,0.00892126f,1.357f,0.587891f,0.000192836f,
1.01171f,-0.028057f,0.0077658f,1.35504f,0.591375f,0.000213657f, 1.01404f,-0.0275948f,0.00619142f,1.35283f,0.59513f,0.000237282f,
1.01657f,-0.026648f,0.00420952f,1.35035f,0.59915f,0.000263948f, 1.01929f,-0.0251813f,0.00175533f,1.34758f,0.603416f,0.000294005f,
1.02219f,-0.0231568f,-0.0011828f,1.34452f,0.607957f,0.000327922f, 1.02526f,-0.0205792f,-0.00460852f,1.34111f,0.612767f,0.000366156f,
1.02846f,-0.0174079f,-0.00863886f,1.33731f,0.617807f,0.000409181f, 1.03182f,-0.0136476f,-0.0130999f,1.33314f,0.623151f,0.000457627f,
1.03525f,-0.00927494f,-0.0181787f,1.32852f,0.628716f,0.00051208f, 1.0387f,-0.00425339f,-0.0239159f,1.3234f,0.634524f,0.000573405f,
1.04215f,0.00134438f,-0.0300761f,1.31777f,0.64061f,0.000642402f, 1.04548f,0.00754936f,-0.036841f,1.31158f,0.64693f,0.000720107f,
1.0486f,0.0143961f,-0.0442617f,1.3048f,0.653449f,0.000807497f, 1.05137f,0.0218939f,-0.052342f,1.29732f,0.660142f,0.000905742f,
1.05376f,0.0300099f,-0.0610012f,1.28921f,0.66704f,0.00101659f, 1.05573f,0.0386554f,-0.0699609f,1.28047f,0.67419f,0.00114138f,
1.05793f,0.0478485f,-0.0793992f,1.27121f,0.681534f,0.00128183f, 1.05959f,0.0576605f,-0.0893639f,1.26134f,0.689025f,0.00144043f,
1.06139f,0.0680146f,-0.0997994f,1.25075f,0.696664f,0.00161895f, 1.06235f,0.0790179f,-0.110716f,1.23964f,0.704408f,0.00182075f,
1.06293f,0.0906065f,-0.122011f,1.22777f,0.712285f,0.00204819f, 1.06244f,0.1028f,-0.13363f,1.21496f,0.720241f,0.00230538f,
1.06322f,0.115373f,-0.145589f,1.2021f,0.728311f,0.00259592f, 1.06119f,0.128562f,-0.157659f,1.18782f,0.736466f,0.00292413f,
1.05831f,0.142214f,-0.169794f,1.17233f,0.744688f,0.00329629f, 1.05492f,0.156181f,-0.181954f,1.15617f,0.753023f,0.00371706f,
1.05088f,0.170485f,-0.194102f,1.13943f,0.76144f,0.00419386f, 1.04623f,0.185124f,-0.206167f,1.12208f,0.769925f,0.00473545f,
1.04097f,0.19985f,-0.218013f,1.10394f,0.778469f,0.00534919f, 1.03804f,0.214687f,-0.229587f,1.08506f,0.787132f,0.00604601f,
1.0386f,0.229604f,-0.240691f,1.06479f,0.795912f,0.00683973f, 1.02724f,0.244684f,-0.25205f,1.04666f,0.804795f,0.00774221f,
1.01867f,0.259673f,-0.262572f,1.02617f,0.813784f,0.00876925f, 1.00919f,0.274564f,-0.272468f,1.00459f,0.822894f,0.00994143f,
0.999975f,0.289333f,-0.281732f,0.982225f,0.832133f,0.0112799f, 0.991947f,0.303943f,-0.290164f,0.958706f,0.841503f,0.0128071f,
0.980247f,0.318143f,-0.298201f,0.935658f,0.851022f,0.0145527f, 0.963468f,0.331475f,-0.305864f,0.9131f,0.860721f,0.0165557f,
0.949671f,0.344623f,-0.312191f,0.888411f,0.870594f,0.018847f, 0.935096f,0.357274f,-0.317831f,0.863699f,0.880667f,0.0214723f,
0.919664f,0.369341f,-0.322419f,0.837978f,0.890991f,0.0244976f, 0.906424f,0.381199f,-0.326488f,0.812899f,0.901553f,0.0279669f,
0.897252f,0.393343f,-0.32858f,0.784895f,0.912401f,0.0319586f, 0.866609f,0.401186f,-0.331028f,0.759638f,0.923594f,0.0365744f,
0.845862f,0.409911f,-0.331574f,0.732085f,0.935091f,0.0418611f, 0.824826f,0.417965f,-0.33101f,0.703836f,0.947089f,0.0480399f,
0.808488f,0.426701f,-0.328632f,0.674027f,0.959427f,0.0550941f, 0.768153f,0.428286f,-0.326046f,0.645594f,0.972369f,0.0633566f,
0.733677f,0.430387f,-0.321148f,0.614142f,0.986164f,0.0731581f, 0.695264f,0.430007f,-0.314938f,0.583813f,0.999573f,0.0835813f,
0.999994f,-2.23424e-06f,1.61338e-18f,1.37982f,0.538667f,8.22162e-05f, 1.00006f,-0.00469672f,0.0028904f,1.37955f,0.538802f,8.27139e-05f,
1.00016f,-0.00935423f,0.00577815f,1.3795f,0.539214f,8.42275e-05f, 1.00032f,-0.0139367f,0.00856941f,1.37944f,0.539904f,8.67825e-05f,
1.00048f,-0.0184565f,0.0113059f,1.37933f,0.540871f,9.04005e-05f, 1.00072f,-0.0228378f,0.0139174f,1.37918f,0.542114f,9.51321e-05f,
1.00103f,-0.0270414f,0.0163686f,1.37894f,0.54363f,0.000101032f, 1.00142f,-0.03107f,0.0186707f,1.37864f,0.545426f,0.000108178f,
1.00203f,-0.0348433f,0.0207588f,1.37822f,0.547498f,0.000116662f, 1.00294f,-0.0382966f,0.0225911f,1.37761f,0.54985f,0.000126611f,
1.0042f,-0.0414399f,0.0241953f,1.37686f,0.552488f,0.000138126f, 1.00577f,-0.0441842f,0.0254701f,1.37588f,0.555409f,0.000151404f,
1.00762f,-0.0465363f,0.0264137f,1.37471f,0.558596f,0.000166532f, 1.00972f,-0.0484915f,0.0270363f,1.37329f,0.562083f,0.000183776f,
1.01208f,-0.0499568f,0.0272216f,1.37165f,0.565855f,0.000203394f, 1.01465f,-0.0509452f,0.0270063f,1.36974f,0.569905f,0.000225551f,
1.01745f,-0.0514489f,0.0263564f,1.3676f,0.574248f,0.000250579f, 1.02042f,-0.0513936f,0.0251877f,1.36514f,0.578877f,0.000278825f,
1.02376f,-0.050813f,0.0235672f,1.36243f,0.583801f,0.000310646f, 1.0272f,-0.0496332f,0.0213421f,1.35935f,0.589011f,0.000346516f,
1.03084f,-0.0478801f,0.0186235f,1.35597f,0.594522f,0.000386887f, 1.03463f,-0.0454813f,0.015274f,1.35224f,0.600309f,0.000432321f,
1.03854f,-0.0424532f,0.0113116f,1.34808f,0.606381f,0.000483451f, 1.04257f,-0.0388082f,0.00678197f,1.34348f,0.61274f,0.000540981f,
1.04663f,-0.0344916f,0.0015136f,1.33844f,0.619346f,0.000605688f, 1.05066f,-0.0295254f,-0.00435548f,1.33285f,0.62621f,0.00067838f,
1.05461f,-0.0239259f,-0.0108094f,1.32672f,0.633356f,0.000760361f, 1.05834f,-0.0176386f,-0.0179874f,1.32001f,0.64071f,0.000852629f,
1.06178f,-0.0106171f,-0.0259057f,1.31268f,0.648254f,0.000956346f, 1.06484f,-0.00289404f,-0.0345806f,1.30472f,0.655973f,0.00107346f,
1.06751f,0.0054292f,-0.0436255f,1.29611f,0.663946f,0.00120509f, 1.0698f,0.0144344f,-0.0532192f,1.28697f,0.672126f,0.00135388f,
1.07157f,0.0241627f,-0.0633855f,1.2772f,0.680449f,0.00152128f, 1.07303f,0.0345704f,-0.0741562f,1.26694f,0.68892f,0.00171063f,
1.07402f,0.045697f,-0.0854731f,1.25623f,0.697492f,0.00192408f, 1.07434f,0.0575293f,-0.0972815f,1.2448f,0.706177f,0.00216527f,
1.07449f,0.0699847f,-0.10952f,1.23253f,0.714954f,0.00243833f, 1.07387f,0.0830868f,-0.122084f,1.21942f,0.723807f,0.00274665f,
1.07267f,0.0967435f,-0.134908f,1.20533f,0.732757f,0.00309611f, 1.07165f,0.110832f,-0.147971f,1.19088f,0.741754f,0.00349218f,
1.06888f,0.125455f,-0.161046f,1.175f,0.750853f,0.00394078f, 1.06757f,0.140427f,-0.173997f,1.15739f,0.760023f,0.00444992f,
1.05982f,0.156035f,-0.187213f,1.14114f,0.769251f,0.00502905f, 1.05715f,0.171531f,-0.200105f,1.12311f,0.778528f,0.00568642f,
1.05269f,0.187235f,-0.212718f,1.10408f,0.787917f,0.00643401f, 1.04601f,0.203284f,-0.225079f,1.08451f,0.79741f,0.00728718f,
1.03936f,0.219354f,-0.237142f,1.06461f,0.806995f,0.00825924f, 1.03078f,0.235435f,-0.248702f,1.04377f,0.816678f,0.00936756f,
1.02993f,0.251368f,-0.258985f,1.01925f,0.826475f,0.0106352f, 1.01056f,0.267188f,-0.270027f,0.999392f,0.836393f,0.0120861f,
0.99941f,0.282717f,-0.279611f,0.975885f,0.846434f,0.0137446f, 0.98772f,0.297798f,-0.288504f,0.951911f,0.856624f,0.0156463f,
0.975203f,0.31263f,-0.296667f,0.927494f,0.866987f,0.0178327f, 0.96028f,0.32675f,-0.304005f,0.902631f,0.87752f,0.0203383f,
0.944642f,0.340329f,-0.310239f,0.876581f,0.888266f,0.0232235f, 0.931674f,0.353691f,-0.315841f,0.850869f,0.899252f,0.0265495f,
0.914267f,0.366034f,-0.320055f,0.823683f,0.910471f,0.0303677f, 0.894368f,0.377406f,-0.323437f,0.796395f,0.922035f,0.0348051f,
0.872236f,0.387814f,-0.325825f,0.769028f,0.933866f,0.0398889f, 0.850186f,0.39733f,-0.326782f,0.740202f,0.946171f,0.0458418f,
0.825812f,0.405695f,-0.326179f,0.710429f,0.958761f,0.0526285f, 0.798954f,0.412938f,-0.324356f,0.679888f,0.971991f,0.0606479f,
0.760451f,0.416496f,-0.321581f,0.649202f,0.985982f,0.0701265f, 0.721452f,0.4184f,-0.316731f,0.618279f,0.999567f,0.0802257f,
1.00001f,4.58877e-06f,-3.71279e-18f,1.39154f,0.51207f,7.93519e-05f, 0.999988f,-0.00621868f,0.00423819f,1.39104f,0.512212f,7.98203e-05f,
0.999982f,-0.0123886f,0.00843259f,1.39107f,0.512648f,8.12524e-05f, 0.999962f,-0.0185203f,0.0125954f,1.39115f,0.513374f,8.36541e-05f,
0.999902f,-0.024574f,0.0166535f,1.39122f,0.514387f,8.70537e-05f, 0.999864f,-0.0305068f,0.0206031f,1.39129f,0.515691f,9.14988e-05f,
0.999949f,-0.0362973f,0.0244288f,1.39133f,0.517292f,9.70511e-05f, 1.0004f,-0.0418392f,0.0280595f,1.39124f,0.519187f,0.000103784f,
1.00117f,-0.0470891f,0.0314832f,1.39101f,0.521376f,0.000111778f, 1.00238f,-0.0520551f,0.0347076f,1.3906f,0.523863f,0.000121118f,
1.00392f,-0.0566297f,0.0376266f,1.39f,0.526647f,0.000131963f, 1.00575f,-0.0608475f,0.0402533f,1.38923f,0.529724f,0.000144403f,
1.00785f,-0.06465f,0.0425774f,1.38821f,0.533116f,0.000158634f, 1.01026f,-0.0679922f,0.0445067f,1.38694f,0.536812f,0.000174866f,
1.0129f,-0.0708944f,0.0460323f,1.38547f,0.540802f,0.000193243f, 1.01571f,-0.0733128f,0.047168f,1.3838f,0.545119f,0.000214056f,
1.01876f,-0.0751987f,0.0478234f,1.38186f,0.54974f,0.000237549f, 1.02194f,-0.0765871f,0.0479679f,1.37967f,0.554669f,0.000264044f,
1.02531f,-0.077418f,0.0476344f,1.37723f,0.559934f,0.000293928f, 1.02921f,-0.0776596f,0.0466856f,1.37447f,0.565492f,0.000327555f,
1.03345f,-0.0773409f,0.045215f,1.37145f,0.571394f,0.000365434f, 1.03758f,-0.0763213f,0.0430548f,1.36801f,0.577581f,0.000408035f,
1.04195f,-0.0747189f,0.0403333f,1.36424f,0.584107f,0.000455974f, 1.04632f,-0.0724448f,0.0368552f,1.36008f,0.590896f,0.000509802f,
1.05078f,-0.0694762f,0.0327836f,1.35554f,0.598021f,0.000570478f, 1.05528f,-0.0658504f,0.0279537f,1.35056f,0.605403f,0.000638744f,
1.05972f,-0.0614781f,0.02233f,1.34509f,0.61304f,0.000715432f, 1.06416f,-0.0564349f,0.0161074f,1.33912f,0.620965f,0.000801939f,
1.06841f,-0.0506581f,0.00912443f,1.33259f,0.629129f,0.000899202f, 1.07238f,-0.0440771f,0.00129661f,1.32546f,0.637485f,0.00100892f,
1.076f,-0.0367222f,-0.00735869f,1.31777f,0.646008f,0.00113233f, 1.07922f,-0.02861f,-0.0166065f,1.30943f,0.654773f,0.00127182f,
1.08197f,-0.0197699f,-0.0263858f,1.30052f,0.663737f,0.00142881f, 1.08422f,-0.0101106f,-0.036849f,1.29101f,0.67288f,0.00160636f,
1.08595f,0.000376794f,-0.0479792f,1.28098f,0.682135f,0.00180673f, 1.08711f,0.0117015f,-0.0597434f,1.27046f,0.691512f,0.00203294f,
1.08785f,0.0238205f,-0.072114f,1.25939f,0.700979f,0.00228928f, 1.08799f,0.0366841f,-0.0849942f,1.24761f,0.71054f,0.00257916f,
1.08739f,0.0503193f,-0.0983047f,1.23503f,0.720163f,0.00290717f, 1.08619f,0.0646231f,-0.111955f,1.22137f,0.729881f,0.00327958f,
1.08431f,0.0794928f,-0.125849f,1.20674f,0.739635f,0.00370206f, 1.08236f,0.0948244f,-0.13991f,1.19143f,0.749481f,0.00418128f,
1.07886f,0.11076f,-0.15403f,1.17511f,0.759389f,0.0047261f, 1.07609f,0.126901f,-0.168142f,1.158f,0.769345f,0.00534694f,
1.07131f,0.143498f,-0.18208f,1.13981f,0.779349f,0.00605293f, 1.06463f,0.16051f,-0.195859f,1.12112f,0.789455f,0.00685729f,
1.05793f,0.177618f,-0.20932f,1.10134f,0.799655f,0.00777724f, 1.05012f,0.19481f,-0.222382f,1.0807f,0.809942f,0.00882767f,
1.05149f,0.211485f,-0.234313f,1.05634f,0.820316f,0.0100277f, 1.03286f,0.229046f,-0.247099f,1.03746f,0.8308f,0.0114042f,
1.02653f,0.245909f,-0.258129f,1.01299f,0.841399f,0.0129827f, 1.00996f,0.262587f,-0.26913f,0.990547f,0.852116f,0.0147911f,
0.997264f,0.278801f,-0.278905f,0.965645f,0.862986f,0.0168736f, 0.984616f,0.294631f,-0.287884f,0.940302f,0.874017f,0.0192691f,
0.972664f,0.310056f,-0.295895f,0.914223f,0.885218f,0.0220215f, 0.955852f,0.324675f,-0.303233f,0.888291f,0.896657f,0.0252114f,
0.93825f,0.33867f,-0.309227f,0.860954f,0.908302f,0.0288769f, 0.919236f,0.351945f,-0.314248f,0.833207f,0.920254f,0.033137f,
0.902091f,0.364712f,-0.317657f,0.803842f,0.932464f,0.0380376f, 0.877012f,0.375766f,-0.320693f,0.775738f,0.945103f,0.043774f,
0.850845f,0.385744f,-0.321871f,0.745978f,0.957984f,0.0503118f, 0.822076f,0.394565f,-0.321802f,0.715226f,0.971537f,0.0581076f,
0.795527f,0.40261f,-0.319049f,0.680812f,0.985761f,0.0672876f, 0.756378f,0.406447f,-0.315116f,0.648388f,0.99956f,0.0770897f,
0.999993f,-2.23287e-06f,1.21114e-19f,1.40172f,0.486359f,7.63599e-05f, 0.999928f,-0.00765277f,0.00550952f,1.40125f,0.486506f,7.67985e-05f,
0.999765f,-0.0152895f,0.0109819f,1.40139f,0.486956f,7.81392e-05f, 0.999559f,-0.0228896f,0.0164079f,1.40156f,0.487708f,8.03962e-05f,
0.999345f,-0.0304257f,0.0217608f,1.40179f,0.488767f,8.36056e-05f, 0.999162f,-0.0378476f,0.0269976f,1.40202f,0.490125f,8.77887e-05f,
0.999195f,-0.045096f,0.0320833f,1.40216f,0.491788f,9.30148e-05f, 0.999637f,-0.0520737f,0.0370283f,1.40219f,0.493761f,9.93413e-05f,
1.00048f,-0.0587621f,0.0417618f,1.40206f,0.496036f,0.000106837f, 1.00203f,-0.0650813f,0.0462387f,1.4017f,0.498622f,0.000115626f,
1.00401f,-0.0710566f,0.0504742f,1.40111f,0.501526f,0.0001258f, 1.00629f,-0.076648f,0.0544229f,1.40036f,0.504748f,0.000137491f,
1.00882f,-0.0818244f,0.0580081f,1.39927f,0.508286f,0.000150869f, 1.01151f,-0.0865276f,0.0612355f,1.39817f,0.512144f,0.000166084f,
1.0144f,-0.0907762f,0.0640946f,1.39683f,0.516338f,0.000183342f, 1.01753f,-0.0945755f,0.0665042f,1.39504f,0.520854f,0.000202854f,
1.02079f,-0.097826f,0.0684399f,1.39324f,0.525704f,0.000224897f, 1.02425f,-0.100585f,0.0698977f,1.3912f,0.530899f,0.000249764f,
1.02781f,-0.102791f,0.0708179f,1.3888f,0.536428f,0.000277771f, 1.03146f,-0.10449f,0.0711445f,1.38625f,0.5423f,0.000309326f,
1.03524f,-0.105592f,0.0709108f,1.38334f,0.548514f,0.000344815f, 1.04065f,-0.106133f,0.0700254f,1.38032f,0.555067f,0.000384722f,
1.04561f,-0.105966f,0.0684864f,1.37695f,0.561947f,0.000429596f, 1.05052f,-0.105156f,0.0662243f,1.37302f,0.569164f,0.000480168f,
1.05526f,-0.103619f,0.0632617f,1.36894f,0.576689f,0.00053696f, 1.06007f,-0.101359f,0.0595171f,1.36448f,0.584519f,0.000600893f,
1.06485f,-0.0983549f,0.0550572f,1.35955f,0.592658f,0.000672874f, 1.06967f,-0.0945849f,0.0497036f,1.3543f,0.601038f,0.000753798f,
1.07437f,-0.0900332f,0.0436239f,1.34861f,0.609717f,0.000845045f, 1.07902f,-0.084678f,0.0367642f,1.34235f,0.618641f,0.000947778f,
1.08344f,-0.0784895f,0.0290039f,1.33565f,0.62777f,0.00106346f, 1.08758f,-0.0713936f,0.0202942f,1.32836f,0.637085f,0.00119422f,
1.09122f,-0.0634666f,0.0108461f,1.32044f,0.646589f,0.00134143f, 1.09446f,-0.0547034f,0.000804281f,1.31191f,0.656336f,0.00150776f,
1.0971f,-0.044998f,-0.00999799f,1.30277f,0.666243f,0.00169588f, 1.09918f,-0.0343381f,-0.0215486f,1.29302f,0.676265f,0.00190818f,
1.10078f,-0.0227711f,-0.033833f,1.28284f,0.686415f,0.00214844f, 1.10181f,-0.0102745f,-0.0468054f,1.27203f,0.696643f,0.00242094f,
1.10213f,0.00310499f,-0.060377f,1.26059f,0.706968f,0.00272941f, 1.10173f,0.0173346f,-0.074464f,1.24835f,0.717342f,0.00307894f,
1.10043f,0.0323818f,-0.088986f,1.23515f,0.72781f,0.0034765f, 1.09847f,0.0481238f,-0.103831f,1.221f,0.738309f,0.00392818f,
1.09603f,0.0644146f,-0.118874f,1.20579f,0.748892f,0.00444137f, 1.09283f,0.0812315f,-0.13404f,1.18963f,0.759527f,0.00502583f,
1.08993f,0.0983769f,-0.149255f,1.17274f,0.770201f,0.00569332f, 1.08437f,0.116207f,-0.164345f,1.1548f,0.780931f,0.00645382f,
1.07795f,0.13431f,-0.179237f,1.13589f,0.791752f,0.00732206f, 1.07022f,0.152679f,-0.193862f,1.11606f,0.80266f,0.00831746f,
1.06174f,0.171139f,-0.208109f,1.0954f,0.813647f,0.00945655f, 1.05293f,0.18948f,-0.221813f,1.07362f,0.824717f,0.0107609f,
1.05171f,0.207221f,-0.234362f,1.04831f,0.835896f,0.0122624f, 1.03226f,0.225853f,-0.247449f,1.02762f,0.847179f,0.0139863f,
1.02803f,0.24343f,-0.258507f,1.00087f,0.85858f,0.0159673f, 1.00609f,0.26101f,-0.269881f,0.977715f,0.870144f,0.0182594f,
0.994354f,0.277905f,-0.279743f,0.951654f,0.881849f,0.0208942f, 0.985311f,0.294448f,-0.288223f,0.923516f,0.89376f,0.0239478f,
0.972252f,0.310389f,-0.295769f,0.895273f,0.905871f,0.027473f, 0.94266f,0.325088f,-0.303293f,0.869529f,0.918241f,0.0315629f,
0.921863f,0.339248f,-0.308802f,0.840683f,0.930873f,0.0362962f, 0.902194f,0.352655f,-0.312932f,0.810665f,0.943879f,0.0418271f,
0.87625f,0.364757f,-0.315999f,0.781121f,0.95709f,0.0481337f, 0.848436f,0.375579f,-0.317301f,0.749147f,0.971006f,0.0557241f,
0.814642f,0.384632f,-0.316976f,0.715989f,0.985502f,0.064628f, 0.774999f,0.39103f,-0.315057f,0.684091f,0.999552f,0.0741578f,
0.999997f,9.53235e-06f,3.57373e-18f,1.41048f,0.46159f,7.32905e-05f, 0.999922f,-0.0090297f,0.00670453f,1.41032f,0.461743f,7.3707e-05f,
0.999719f,-0.0180643f,0.0134079f,1.41051f,0.462207f,7.49705e-05f, 0.999432f,-0.0270538f,0.0200294f,1.4108f,0.46298f,7.7095e-05f,
0.999138f,-0.0359882f,0.0265998f,1.41114f,0.464063f,8.00993e-05f, 0.998943f,-0.0448081f,0.033058f,1.4115f,0.465462f,8.40396e-05f,
0.999077f,-0.0534143f,0.039383f,1.41177f,0.467169f,8.89376e-05f, 0.999724f,-0.0617383f,0.0455322f,1.41181f,0.469191f,9.48684e-05f,
1.00076f,-0.0697198f,0.0514973f,1.41168f,0.471539f,0.000101927f, 1.00222f,-0.0773745f,0.0572348f,1.41129f,0.474208f,0.000110175f,
1.00397f,-0.0846267f,0.0626995f,1.41065f,0.4772f,0.000119721f, 1.00649f,-0.0915296f,0.0678573f,1.40983f,0.480519f,0.000130702f,
1.00976f,-0.0979899f,0.0726954f,1.40857f,0.484177f,0.000143254f, 1.01267f,-0.103962f,0.0771798f,1.40721f,0.488174f,0.000157528f,
1.01602f,-0.109516f,0.0812493f,1.40545f,0.492506f,0.0001737f, 1.01941f,-0.114568f,0.0848984f,1.40377f,0.49719f,0.000192008f,
1.02288f,-0.119178f,0.0881028f,1.40195f,0.502231f,0.000212683f, 1.02663f,-0.123283f,0.0907854f,1.39952f,0.507625f,0.00023599f,
1.0305f,-0.126882f,0.0929281f,1.39712f,0.513383f,0.000262267f, 1.03441f,-0.129976f,0.0945157f,1.39475f,0.519494f,0.000291811f,
1.03856f,-0.132587f,0.0955259f,1.39191f,0.525982f,0.000325032f, 1.04273f,-0.134574f,0.0958625f,1.38904f,0.53282f,0.000362467f,
1.04683f,-0.13594f,0.095505f,1.38577f,0.540018f,0.000404582f, 1.05446f,-0.136765f,0.0945048f,1.38242f,0.547565f,0.000451829f,
1.06002f,-0.136755f,0.0926624f,1.37861f,0.555444f,0.000505132f, 1.06529f,-0.13599f,0.0901312f,1.37441f,0.56367f,0.00056495f,
1.07046f,-0.134432f,0.0866897f,1.37007f,0.572187f,0.000632431f, 1.0755f,-0.132072f,0.0825374f,1.36543f,0.581034f,0.000708214f,
1.08042f,-0.128797f,0.0774394f,1.36049f,0.590152f,0.000793744f, 1.08543f,-0.124721f,0.0714472f,1.35512f,0.599525f,0.000889957f,
1.09037f,-0.119757f,0.0646756f,1.34937f,0.609186f,0.000998362f, 1.09519f,-0.113903f,0.0569103f,1.34319f,0.619064f,0.00112091f,
1.09969f,-0.107038f,0.0481289f,1.33638f,0.629113f,0.00125897f, 1.1037f,-0.0991596f,0.038452f,1.32905f,0.639357f,0.00141477f,
1.10717f,-0.0902945f,0.0281007f,1.32105f,0.649851f,0.00159123f, 1.11017f,-0.0804065f,0.0169165f,1.31248f,0.660496f,0.00179059f,
1.11253f,-0.0694525f,0.00488076f,1.30319f,0.671276f,0.00201606f, 1.11431f,-0.0574882f,-0.00797904f,1.29333f,0.682169f,0.00227155f,
1.1156f,-0.0445032f,-0.021618f,1.28292f,0.693143f,0.0025617f, 1.11621f,-0.0305056f,-0.0359406f,1.27185f,0.704213f,0.0028906f,
1.116f,-0.0155542f,-0.0508615f,1.25996f,0.71533f,0.00326388f, 1.1149f,0.000273022f,-0.0663009f,1.24713f,0.726534f,0.00368916f,
1.11298f,0.0169069f,-0.0821327f,1.23329f,0.737769f,0.00417331f, 1.11005f,0.0343083f,-0.0982368f,1.21845f,0.749084f,0.00472444f,
1.10633f,0.0523106f,-0.114511f,1.20257f,0.760441f,0.0053532f, 1.10179f,0.0708464f,-0.130839f,1.1856f,0.771828f,0.006073f,
1.09695f,0.089721f,-0.14712f,1.16791f,0.783289f,0.00689495f, 1.09029f,0.109054f,-0.163198f,1.14896f,0.794827f,0.00783551f,
1.08207f,0.128703f,-0.179025f,1.12905f,0.806448f,0.00891713f, 1.0733f,0.148477f,-0.194437f,1.10812f,0.818141f,0.0101569f,
1.06351f,0.168176f,-0.20932f,1.08611f,0.829914f,0.0115811f, 1.05307f,0.187737f,-0.223584f,1.06299f,0.841798f,0.0132264f,
1.04163f,0.207045f,-0.237092f,1.03892f,0.853774f,0.015117f, 1.02834f,0.226046f,-0.249802f,1.01393f,0.865886f,0.0173045f,
1.01625f,0.244517f,-0.261598f,0.98808f,0.878137f,0.0198314f, 1.00093f,0.26268f,-0.272358f,0.961264f,0.890549f,0.0227529f,
0.983901f,0.280162f,-0.281945f,0.933235f,0.903168f,0.0261488f, 0.966133f,0.297018f,-0.290485f,0.904884f,0.91599f,0.0300766f,
0.944707f,0.312979f,-0.297986f,0.876223f,0.929086f,0.0346557f, 0.923646f,0.328239f,-0.304038f,0.846269f,0.942496f,0.0399929f,
0.900633f,0.34239f,-0.308279f,0.81489f,0.956091f,0.0460953f, 0.883587f,0.348889f,-0.311141f,0.782016f,0.970393f,0.0534855f,
0.836805f,0.36667f,-0.313544f,0.750953f,0.985202f,0.0621353f, 0.796933f,0.37547f,-0.313198f,0.718562f,0.999543f,0.0714155f,
    };
    *n = 64;
    return data;
}
#endif
#ifndef MF_NO_IBM
/* ---- Inverse Bin Map ---- */

/* mf_real <-> float bits, without a header for memcpy */
static unsigned int mf__ibm_fbits(mf_real v)
{
    float f = (float)v;
    unsigned int u = 0u;
    const unsigned char *s = (const unsigned char *)&f;
    unsigned char *d = (unsigned char *)&u;
    size_t i;
    for (i = 0; i < sizeof(float) && i < sizeof(unsigned int); ++i) d[i] = s[i];
    return u;
}
static mf_real mf__ibm_bitsf(unsigned int u)
{
    float f = 0.0f;
    const unsigned char *s = (const unsigned char *)&u;
    unsigned char *d = (unsigned char *)&f;
    size_t i;
    for (i = 0; i < sizeof(float) && i < sizeof(unsigned int); ++i) d[i] = s[i];
    return (mf_real)f;
}

static int mf__ibm_bitlen(size_t v)
{
    int n = 0;
    while (v) { ++n; v >>= 1; }
    return n;
}

/* ORs v into field i (w bits) of a zeroed packed array */
MF_INLINE void mf__ibm_put(unsigned int *base, size_t i, int w, unsigned int v)
{
    size_t bit = i * (size_t)w;
    unsigned int *p = base + (bit >> 5), s = (unsigned int)(bit & 31u);
    p[0] |= v << s;
    if (s + (unsigned int)w > 32u) p[1] |= v >> (32u - s);
}

/* The derived fields of a map from its header values; returns the word count
 * (0 if the sizes are out of range). */
static size_t mf__ibm_layout(mf_ibm *ibm, int width, int height, int res, int radius, unsigned int list_len)
{
    size_t n, bins, words;
    if (width < 1 || width > 16384 || height < 1 || height > 16384 || res < 1 || res > MF_IBM_MAX_RES ||
        radius < 0 || radius > MF_IBM_MAX_RADIUS || list_len < (unsigned int)width * (unsigned int)height ||
        list_len > 0x7fffffffu)
        return 0;
    n = (size_t)width * (size_t)height;
    bins = (size_t)res * (size_t)res;
    ibm->width = width; ibm->height = height; ibm->res = res; ibm->radius = radius;
    ibm->kx = mf__ibm_bitlen((size_t)width - 1u);
    ibm->ky = mf__ibm_bitlen((size_t)height - 1u);
    ibm->list_len = list_len;
    ibm->off_bits = mf__ibm_bitlen(list_len);
    ibm->pos_bits = ibm->kx + ibm->ky > 0 ? ibm->kx + ibm->ky : 1;
    ibm->list_bits = ibm->pos_bits > ibm->off_bits ? ibm->pos_bits : ibm->off_bits;
    ibm->axis_bits = res > 1 ? mf__ibm_bitlen((size_t)res - 1u) : 1;
    ibm->bin_bits = 2 * ibm->axis_bits;
    ibm->off_at = MF__IBM_HEADER;
    ibm->mean_at = ibm->off_at + ((bins + 1u) * (size_t)ibm->off_bits + 31u) / 32u + 1u;
    ibm->pos_at = ibm->mean_at + bins;
    ibm->bin_at = ibm->pos_at + ((size_t)list_len * (size_t)ibm->list_bits + 31u) / 32u + 1u;
    words = ibm->bin_at + (n * (size_t)ibm->bin_bits + 31u) / 32u + 1u;
    if (words >= (size_t)0xffffffffu) return 0;
    return words;
}

static void mf__ibm_set_fields(mf_ibm *ibm)
{
    const unsigned int *h = ibm->data;
    ibm->alpha = mf__ibm_bitsf(h[7]);
    ibm->cut = mf__ibm_bitsf(h[8]);
    ibm->shadow_ax = mf__ibm_bitsf(h[9]);
    ibm->shadow_ay = mf__ibm_bitsf(h[10]);
    ibm->shadow = mf_beckmann(ibm->shadow_ax, ibm->shadow_ay);
    ibm->has_shadow = 1;
}

static void mf__ibm_zero(mf_ibm *ibm)
{
    ibm->data = 0; ibm->words = 0;
    ibm->width = ibm->height = ibm->res = ibm->radius = ibm->kx = ibm->ky = 0;
    ibm->off_bits = ibm->pos_bits = ibm->list_bits = ibm->bin_bits = ibm->axis_bits = 0;
    ibm->list_len = 0u;
    ibm->off_at = ibm->mean_at = ibm->pos_at = ibm->bin_at = 0;
    ibm->alpha = ibm->cut = ibm->shadow_ax = ibm->shadow_ay = MF_R(0.0);
    ibm->has_shadow = 0;
    ibm->shadow = mf_beckmann(MF_R(1.0), MF_R(1.0));
}

/* the resolution (Eq. 5.14) and the neighbourhood radius for a cut */
static void mf__ibm_resolution(mf_real alpha, mf_real cut, int resolution, int *res, int *radius)
{
    mf_real cs = cut * alpha / MF_SQRT(MF_R(2.0));              /* tan(theta0), theta0 = atan(cut sigma) */
    mf_real s0 = cs / MF_SQRT(MF_R(1.0) + cs * cs), r;          /* sin(theta0) */
    if (resolution > 0) *res = resolution;
    else {
        mf_real b = MF_FLOOR(MF_R(5.0) / s0);                   /* Eq. 5.14 */
        *res = !(b < (mf_real)MF_IBM_MAX_RES) ? MF_IBM_MAX_RES : (b < MF_R(1.0) ? 1 : (int)b);
    }
    r = MF_CEIL((mf_real)*res * s0 * MF_R(0.5) - MF_R(0.5));
    *radius = r > MF_R(2.0) ? (r < (mf_real)MF_IBM_MAX_RADIUS ? (int)r : MF_IBM_MAX_RADIUS) : 2;
}

MFDEF mf_result mf_ibm_build_ex(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha,
                                int resolution, mf_real cut_sigmas)
{
    mf_ibm L;
    size_t n, bins, words, i, ncodes, bmw;
    unsigned int *data = 0, *tmp = 0, *cur = 0, *list, *bmap = 0, *mx = 0, *my = 0, start = 0u, amask;
    double *sums = 0, sxx = 0.0, syy = 0.0;
    unsigned char tile[64];
    mf_real alpha, cut;
    int res, radius, x, y;
    if (!ibm) return MF_ERROR_INVALID_ARGUMENT;
    mf__ibm_zero(ibm);
    mf__ibm_zero(&L);
    if (!normals_xyz || width < 1 || width > 16384 || height < 1 || height > 16384 || !(flake_alpha > MF_R(0.0)) ||
        resolution < 0 || resolution > MF_IBM_MAX_RES || !(cut_sigmas >= MF_R(0.0)) || !(cut_sigmas <= MF_R(10.0)) ||
        (cut_sigmas > MF_R(0.0) && cut_sigmas < MF_IBM_MIN_CUT))
        return MF_ERROR_INVALID_ARGUMENT;
    alpha = mf__ibm_bitsf(mf__ibm_fbits(mf__clamp_alpha(flake_alpha)));
    cut = mf__ibm_bitsf(mf__ibm_fbits(cut_sigmas > MF_R(0.0) ? cut_sigmas : MF_R(3.0)));
    mf__ibm_resolution(alpha, cut, resolution, &res, &radius);
    n = (size_t)width * (size_t)height;
    bins = (size_t)res * (size_t)res;
    if (!mf__ibm_layout(&L, width, height, res, radius, (unsigned int)n)) return MF_ERROR_INVALID_ARGUMENT;
    ncodes = (size_t)1 << (L.kx + L.ky);
    amask = (1u << L.axis_bits) - 1u;
    bmw = (n * (size_t)L.bin_bits + 31u) / 32u + 1u;
    tmp = (unsigned int *)MF_MALLOC(ncodes * sizeof(unsigned int));
    cur = (unsigned int *)MF_MALLOC((bins + 1u) * sizeof(unsigned int));
    sums = (double *)MF_MALLOC(2u * bins * sizeof(double));
    bmap = (unsigned int *)MF_MALLOC(bmw * sizeof(unsigned int));
    mx = (unsigned int *)MF_MALLOC(((size_t)width + (size_t)height) * sizeof(unsigned int));
    my = mx ? mx + width : 0;
    if (!tmp || !cur || !sums || !bmap || !mx) {
        MF_FREE(tmp); MF_FREE(cur); MF_FREE(sums); MF_FREE(bmap); MF_FREE(mx);
        return MF_ERROR_OUT_OF_MEMORY;
    }
    for (i = 0; i <= bins; ++i) cur[i] = 0u;   /* sums: set by the first texel of a bin */
    for (i = 0; i < bmw; ++i) bmap[i] = 0u;
    for (x = 0; x < width; ++x) mx[x] = mf__ibm_morton(L.kx, L.ky, (unsigned int)x, 0u);
    if (ncodes != n)
        for (i = 0; i < ncodes; ++i) tmp[i] = 0xffffffffu;
    /* pass 1, in 8 x 8 tiles: validate, bin (Eq. 5.15), count, per-bin sums,
     * the bin map (bins as ix | iy << s); every texel's bin also goes to its
     * Morton code (the x and y bits of the code are disjoint: OR them). Runs
     * of one bin (flakes) add up in registers before they reach memory. */
    for (i = 0; i < (size_t)height; ++i) my[i] = mf__ibm_morton(L.kx, L.ky, 0u, (unsigned int)i);
    for (i = 0; i < 64u; ++i) tile[i] = (unsigned char)(mf__ibm_compact((unsigned int)i >> 1) | (mf__ibm_compact((unsigned int)i) << 3));
    for (y = 0; y < height; y += 8)
        for (x = 0; x < width; x += 8) {
            unsigned int rj = 0xffffffffu, rc = 0u, q;
            double rx = 0.0, ry = 0.0;
            for (q = 0; q <= 64u; ++q) {
                int tx = x + (int)(tile[q & 63u] & 7u), ty = y + (int)(tile[q & 63u] >> 3);
                unsigned int ix, iy, j = 0xfffffffeu;
                mf_real nx = MF_R(0.0), ny = MF_R(0.0);
                if (q < 64u) {
                    size_t k = (size_t)ty * (size_t)width + (size_t)tx;
                    const mf_real *nv = normals_xyz + 3u * k;
                    mf_real nz, l2, il;
                    if (tx >= width || ty >= height) continue;
                    nx = nv[0]; ny = nv[1]; nz = nv[2]; l2 = nx * nx + ny * ny + nz * nz;
                    if (!mf__finite_bits(nx) || !mf__finite_bits(ny) || !mf__finite_bits(nz) ||
                        !(nz > MF_R(0.0)) || !(MF_FABS(l2 - MF_R(1.0)) < MF_R(1e-3))) {
                        MF_FREE(tmp); MF_FREE(cur); MF_FREE(sums); MF_FREE(bmap); MF_FREE(mx);
                        return MF_ERROR_INVALID_DATA;
                    }
                    /* 1/sqrt(l2) by two Newton steps from 1 (|l2 - 1| < 1e-3:
                     * error < 1e-12, no sqrt or division in the hot loop) */
                    il = MF_R(1.5) - MF_R(0.5) * l2;
                    il *= MF_R(1.5) - MF_R(0.5) * l2 * il * il;
                    nx *= il; ny *= il;
                    ix = (unsigned int)mf__ibm_cell(nx, res); iy = (unsigned int)mf__ibm_cell(ny, res);
                    j = ix + (unsigned int)res * iy;
                    mf__ibm_put(bmap, k, L.bin_bits, ix | (iy << L.axis_bits));
                    tmp[mx[tx] | my[ty]] = ix | (iy << L.axis_bits);
                }
                if (j != rj) {
                    if (rc) {
                        if (cur[rj]) { sums[2u * rj] += rx; sums[2u * rj + 1u] += ry; }
                        else { sums[2u * rj] = rx; sums[2u * rj + 1u] = ry; }
                        cur[rj] += rc;
                    }
                    rj = j; rc = 0u; rx = ry = 0.0;
                }
                ++rc; rx += (double)nx; ry += (double)ny;
            }
        }
    MF_FREE(mx);
    /* block sizes: n, or n + 2 + 2^k with the top k levels of the kd-tree */
    for (i = 0; i < bins; ++i) {
        unsigned int c = cur[i];
        start += c < (unsigned int)MF_IBM_TREE_MIN ? c : c + 2u + (1u << mf__ibm_tree_levels(&L, c));
    }
    words = mf__ibm_layout(&L, width, height, res, radius, start);
    data = words ? (unsigned int *)MF_MALLOC(words * sizeof(unsigned int)) : 0;
    if (!data) {
        MF_FREE(tmp); MF_FREE(cur); MF_FREE(sums); MF_FREE(bmap);
        return words ? MF_ERROR_OUT_OF_MEMORY : MF_ERROR_INVALID_ARGUMENT;
    }
    for (i = 0; i < L.bin_at; ++i) data[i] = 0u;
    for (i = 0; i < bmw; ++i) data[L.bin_at + i] = bmap[i];
    MF_FREE(bmap);
    list = data + L.pos_at;
    /* means, quantized inside their bin; the index (Sec. 5.4.4); cur becomes
     * the write cursor of each bin's positions */
    start = 0u;
    for (i = 0; i < bins; ++i) {
        unsigned int c = cur[i], q = 0x80008000u;
        if (c) {
            double fx = (sums[2u * i] / c + 1.0) * 0.5 * res - (double)(i % (size_t)res);
            double fy = (sums[2u * i + 1u] / c + 1.0) * 0.5 * res - (double)(i / (size_t)res);
            unsigned int qx, qy;
            fx = fx < 0.0 ? 0.0 : (fx > 1.0 ? 1.0 : fx);
            fy = fy < 0.0 ? 0.0 : (fy > 1.0 ? 1.0 : fy);
            qx = (unsigned int)(fx * 65536.0 + 0.5); qy = (unsigned int)(fy * 65536.0 + 0.5);
            q = ((qx > 65535u ? 65535u : qx) << 16) | (qy > 65535u ? 65535u : qy);
            {   /* slope moments of the map from the bins' mean normals */
                double ax = sums[2u * i] / c, ay = sums[2u * i + 1u] / c, z2 = 1.0 - ax * ax - ay * ay;
                z2 = z2 > 1e-12 ? z2 : 1e-12;
                sxx += c * ax * ax / z2;
                syy += c * ay * ay / z2;
            }
        }
        data[L.mean_at + i] = q;
        mf__ibm_put(data + L.off_at, i, L.off_bits, start);
        if (c < (unsigned int)MF_IBM_TREE_MIN) { cur[i] = start; start += c; }
        else {
            unsigned int kn = 1u << mf__ibm_tree_levels(&L, c);
            mf__ibm_put(list, start, L.list_bits, c);
            cur[i] = start + 2u + kn;
            start += c + 2u + kn;
        }
    }
    mf__ibm_put(data + L.off_at, bins, L.off_bits, start);
    MF_FREE(sums);
    /* pass 2, in Morton order: the inverse bin map (Eq. 5.17) - positions
     * grouped by bin, each group sorted because the codes come in order */
    {
        unsigned int rv = 0xffffffffu, rj = 0u, c = 0u;
        for (i = 0; i < ncodes; ++i) {
            unsigned int v = tmp[i];
            if (v == 0xffffffffu) continue;
            if (v != rv) {   /* runs of one bin keep their cursor in a register */
                if (rv != 0xffffffffu) cur[rj] = c;
                rv = v;
                rj = (v & amask) + (unsigned int)res * (v >> L.axis_bits);
                c = cur[rj];
            }
            mf__ibm_put(list, c++, L.list_bits, (unsigned int)i);
        }
    }
    MF_FREE(tmp); MF_FREE(cur);
    /* the forest (Sec. 5.4.4): level-k node boundaries of the large bins */
    for (i = 0; i < bins; ++i) {
        unsigned int s, e, c, base, tab, q, node = 0u;
        int k, shift;
        L.data = data;
        s = mf__ibm_off(&L, (int)i);
        e = mf__ibm_off(&L, (int)i + 1);
        if (e - s < (unsigned int)MF_IBM_TREE_MIN) continue;
        c = mf__ibm_bin_info(&L, (int)i, &base, &tab, &k);
        shift = L.kx + L.ky - k;
        for (q = 0; q < c; ++q) {
            unsigned int idx = mf__ibm_get(list, base + q, L.list_bits) >> shift;
            while (node <= idx) mf__ibm_put(list, tab + node++, L.list_bits, q);
        }
        while (node <= (1u << k)) mf__ibm_put(list, tab + node++, L.list_bits, c);
    }
    data[0] = MF_IBM_MAGIC;
    data[1] = MF_IBM_VERSION;
    data[2] = (unsigned int)words;
    data[3] = (unsigned int)width;
    data[4] = (unsigned int)height;
    data[5] = (unsigned int)res;
    data[6] = (unsigned int)radius;
    data[7] = mf__ibm_fbits(alpha);
    data[8] = mf__ibm_fbits(cut);
    data[9] = mf__ibm_fbits(MF_SQRT((mf_real)(2.0 * sxx / (double)n)));
    data[10] = mf__ibm_fbits(MF_SQRT((mf_real)(2.0 * syy / (double)n)));
    data[11] = L.list_len;
    data[MF__IBM_HEADER - 1] = mf__ibm_checksum(data, words);
    *ibm = L;
    ibm->data = data;
    ibm->words = words;
    mf__ibm_set_fields(ibm);
    return MF_SUCCESS;
}

MFDEF mf_result mf_ibm_build(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha)
{
    return mf_ibm_build_ex(ibm, normals_xyz, width, height, flake_alpha, 0, MF_R(0.0));
}

MFDEF void mf_ibm_release(mf_ibm *ibm)
{
    if (!ibm) return;
    MF_FREE(ibm->data);
    mf__ibm_zero(ibm);
}

MFDEF size_t mf_ibm_memory_bytes(const mf_ibm *ibm)
{
    return ibm && ibm->data ? ibm->words * sizeof(unsigned int) : 0u;
}

MFDEF size_t mf_ibm_save(const mf_ibm *ibm, void *buf, size_t cap)
{
    size_t bytes, i;
    if (!ibm || !ibm->data) return 0u;
    bytes = ibm->words * sizeof(unsigned int);
    if (buf && cap >= bytes) {
        const unsigned char *s = (const unsigned char *)ibm->data;
        unsigned char *d = (unsigned char *)buf;
        for (i = 0; i < bytes; ++i) d[i] = s[i];
    }
    return bytes;
}

/* every check a query relies on; 1 if the array is a valid map */
static int mf__ibm_valid(mf_ibm *L, const unsigned int *w, size_t words)
{
    size_t n, bins, j, total = 0;
    mf_real a, c, sx, sy;
    unsigned int prev_end = 0u, amask;
    const unsigned int *list;
    if (words < MF__IBM_HEADER || w[0] != MF_IBM_MAGIC || w[1] != MF_IBM_VERSION || (size_t)w[2] != words) return 0;
    if (w[3] > 16384u || w[4] > 16384u || w[5] > (unsigned int)MF_IBM_MAX_RES || w[6] > (unsigned int)MF_IBM_MAX_RADIUS) return 0;
    if (mf__ibm_layout(L, (int)w[3], (int)w[4], (int)w[5], (int)w[6], w[11]) != words) return 0;
    for (j = 12; j < MF__IBM_HEADER - 1; ++j) if (w[j] != 0u) return 0;
    a = mf__ibm_bitsf(w[7]); c = mf__ibm_bitsf(w[8]); sx = mf__ibm_bitsf(w[9]); sy = mf__ibm_bitsf(w[10]);
    /* alpha as the builder stores it: clamped like every alpha, rounded to float */
    if (!(a > MF_R(0.0)) || a != mf__ibm_bitsf(mf__ibm_fbits(mf__clamp_alpha(a))) || !(c > MF_R(0.0)) || !(c <= MF_R(10.0)) || !(sx >= MF_R(0.0)) ||
        !(sx < MF_BIG) || !(sy >= MF_R(0.0)) || !(sy < MF_BIG))
        return 0;
    if (mf__ibm_checksum(w, words) != w[MF__IBM_HEADER - 1]) return 0;
    L->data = (unsigned int *)0;
    n = (size_t)L->width * (size_t)L->height;
    bins = (size_t)L->res * (size_t)L->res;
    list = w + L->pos_at;
    amask = (1u << L->axis_bits) - 1u;
    /* the bin map: both bin coordinates in range */
    for (j = 0; j < n; ++j) {
        unsigned int v = mf__ibm_get(w + L->bin_at, j, L->bin_bits);
        if ((v & amask) >= (unsigned int)L->res || (v >> L->axis_bits) >= (unsigned int)L->res) return 0;
    }
    /* the index and the blocks: contiguous and in range; the kd-tree tops
     * monotone from 0 to n; the positions in the map, sorted, each in the
     * level-k node its boundaries give and in the bin the bin map gives it -
     * with N positions in all, every texel appears exactly once */
    if (mf__ibm_get(w + L->off_at, 0, L->off_bits) != 0u) return 0;
    for (j = 0; j < bins; ++j) {
        unsigned int s = mf__ibm_get(w + L->off_at, j, L->off_bits), e = mf__ibm_get(w + L->off_at, j + 1u, L->off_bits);
        unsigned int want = (unsigned int)(j % (size_t)L->res) | ((unsigned int)(j / (size_t)L->res) << L->axis_bits);
        unsigned int cnt, base, tab = 0u, q, t;
        int k = 0, shift;
        if (s != prev_end || e < s || e > L->list_len) return 0;
        prev_end = e;
        if (e - s < (unsigned int)MF_IBM_TREE_MIN) { cnt = e - s; base = s; }
        else {
            cnt = mf__ibm_get(list, s, L->list_bits);
            if (cnt < (unsigned int)MF_IBM_TREE_MIN || (size_t)cnt > n) return 0;
            k = mf__ibm_tree_levels(L, cnt);
            if ((size_t)e - s != (size_t)cnt + 2u + ((size_t)1 << k)) return 0;
            tab = s + 1u;
            base = tab + 1u + (1u << k);
            if (mf__ibm_get(list, tab, L->list_bits) != 0u || mf__ibm_get(list, tab + (1u << k), L->list_bits) != cnt) return 0;
            for (t = 0; t < (1u << k); ++t)
                if (mf__ibm_get(list, tab + t, L->list_bits) > mf__ibm_get(list, tab + t + 1u, L->list_bits)) return 0;
        }
        total += cnt;
        shift = L->kx + L->ky - k;
        for (q = 0; q < cnt; ++q) {
            unsigned int code = mf__ibm_get(list, base + q, L->list_bits);
            int x, y;
            if (code >> L->pos_bits) return 0;
            if (q > 0 && code <= mf__ibm_get(list, base + q - 1u, L->list_bits)) return 0;
            mf__ibm_unmorton(L->kx, L->ky, code, &x, &y);
            if (x >= L->width || y >= L->height || mf__ibm_morton(L->kx, L->ky, (unsigned int)x, (unsigned int)y) != code) return 0;
            if (mf__ibm_get(w + L->bin_at, (size_t)y * (size_t)L->width + (size_t)x, L->bin_bits) != want) return 0;
            if (k > 0) {
                unsigned int idx = code >> shift;
                if (q < mf__ibm_get(list, tab + idx, L->list_bits) || q >= mf__ibm_get(list, tab + idx + 1u, L->list_bits)) return 0;
            }
        }
    }
    return prev_end == L->list_len && total == n;
}

MFDEF mf_result mf_ibm_load(mf_ibm *ibm, const void *buf, size_t bytes)
{
    mf_ibm L;
    unsigned int *data;
    size_t words, i;
    if (!ibm) return MF_ERROR_INVALID_ARGUMENT;
    mf__ibm_zero(ibm);
    if (!buf) return MF_ERROR_INVALID_ARGUMENT;
    if (bytes % sizeof(unsigned int) != 0u || bytes < MF__IBM_HEADER * sizeof(unsigned int)) return MF_ERROR_INVALID_DATA;
    words = bytes / sizeof(unsigned int);
    data = (unsigned int *)MF_MALLOC(bytes);
    if (!data) return MF_ERROR_OUT_OF_MEMORY;
    {
        const unsigned char *s = (const unsigned char *)buf;
        unsigned char *d = (unsigned char *)data;
        for (i = 0; i < bytes; ++i) d[i] = s[i];
    }
    mf__ibm_zero(&L);
    if (!mf__ibm_valid(&L, data, words)) {
        MF_FREE(data);
        return MF_ERROR_INVALID_DATA;
    }
    *ibm = L;
    ibm->data = data;
    ibm->words = words;
    mf__ibm_set_fields(ibm);
    return MF_SUCCESS;
}
#endif /* MF_NO_IBM */
#ifndef MF_NO_MICROSURFACE
/* ---- Microsurface generation and the virtual gonioreflectometer ---- */

/* PCG32 (O'Neill 2014), the generator's and the tracer's own: deterministic
 * for a seed, no global state. The multiplier is built from 32-bit halves so
 * that C++98 sees no long long literal. */
typedef struct mf__pcg { mf_u64 s, inc; } mf__pcg;
static unsigned mf__pcg_next(mf__pcg *r)
{
    mf_u64 old = r->s;
    unsigned xs, rot;
    r->s = old * (((mf_u64)0x5851F42Du << 32) | (mf_u64)0x4C957F2Du) + r->inc;
    xs = (unsigned)(((old >> 18) ^ old) >> 27);
    rot = (unsigned)(old >> 59);
    return (xs >> rot) | (xs << ((32u - rot) & 31u));
}
static void mf__pcg_seed(mf__pcg *r, mf_u64 seed, unsigned stream)
{
    r->s = 0;
    r->inc = ((mf_u64)stream << 1) | 1u;
    mf__pcg_next(r);
    r->s += seed;
    mf__pcg_next(r);
}
/* uniform in [0, 1), 53 bits */
static double mf__pcg_u01(mf__pcg *r)
{
    double a = (double)(mf__pcg_next(r) >> 5), b = (double)(mf__pcg_next(r) >> 6);
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
}
/* uniform integer in [0, n) */
static unsigned mf__pcg_below(mf__pcg *r, unsigned n)
{
    return (unsigned)(((mf_u64)mf__pcg_next(r) * (mf_u64)n) >> 32);
}
/* a double in [0, 1) as an mf_real strictly below 1 (float rounds 1 - 2^-30 up) */
static mf_real mf__u01_real(double u)
{
    mf_real r = (mf_real)u;
    return r < MF_R(1.0) ? r : MF_R(1.0) - MF_EPS;
}

/* sqrt in double through MF_SQRT (float in float builds) and two Newton steps */
static double mf__sqrt_d(double x)
{
    double y;
    if (!(x > 0.0)) return 0.0;
    if (x < 1e-30) return 1e-30 * mf__sqrt_d(x * 1e60);   /* below float's range */
    if (x > 1e30) return 1e30 * mf__sqrt_d(x * 1e-60);
    y = (double)MF_SQRT((mf_real)x);
    if (!(y > 0.0)) y = x;
    y = 0.5 * (y + x / y);
    return 0.5 * (y + x / y);
}

/* In-place heapsort of doubles (no qsort: stdlib.h is optional here). */
static void mf__sort_d(double *a, size_t n)
{
    size_t start, end, root, child;
    double t;
    if (n < 2) return;
    for (start = n / 2; start-- > 0;) {
        for (root = start; (child = 2 * root + 1) < n; root = child) {
            if (child + 1 < n && a[child] < a[child + 1]) ++child;
            if (!(a[root] < a[child])) break;
            t = a[root]; a[root] = a[child]; a[child] = t;
        }
    }
    for (end = n - 1; end > 0; --end) {
        t = a[0]; a[0] = a[end]; a[end] = t;
        for (root = 0; (child = 2 * root + 1) < end; root = child) {
            if (child + 1 < end && a[child] < a[child + 1]) ++child;
            if (!(a[root] < a[child])) break;
            t = a[root]; a[root] = a[child]; a[child] = t;
        }
    }
}

/* The k-th smallest of a[0..n) (Hoare's selection; reorders a). */
static double mf__select_d(double *a, size_t n, size_t k)
{
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        double p = a[lo + (hi - lo) / 2], t;
        size_t i = lo, j = hi;
        while (i <= j) {
            while (a[i] < p) ++i;
            while (p < a[j]) --j;
            if (i <= j) {
                t = a[i]; a[i] = a[j]; a[j] = t;
                ++i;
                if (j == 0) break;
                --j;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else break;
    }
    return a[k];
}

/* ---- FFT: radix-2, complex, double precision (interleaved re, im), for
 * power-of-two sizes. Twiddles cos/sin(2 pi k / n), k < n/2, from the
 * half-angle recursion cos(a/2) = sqrt((1 + cos a)/2), sin(a/2) = sin a /
 * (2 cos(a/2)) and products over the bits of k: accurate to a few ulps of
 * double without a double-precision libm call. */
static void mf__fft_twiddles(double *c, double *s, int n)
{
    double bc[32], bs[32];
    int logn = 0, j, k;
    while ((1 << logn) < n) ++logn;
    bc[0] = 1.0; bs[0] = 0.0;       /* angle 2 pi / 2^j for j = 0, 1, 2 ... */
    bc[1] = -1.0; bs[1] = 0.0;
    bc[2] = 0.0; bs[2] = 1.0;
    for (j = 3; j <= logn && j < 32; ++j) {
        bc[j] = mf__sqrt_d(0.5 * (1.0 + bc[j - 1]));
        bs[j] = bs[j - 1] / (2.0 * bc[j]);
    }
    for (k = 0; k < n / 2; ++k) {
        double cr = 1.0, ci = 0.0;
        for (j = 0; j < logn; ++j)
            if (k & (1 << j)) {          /* rotate by 2 pi 2^j / n = 2 pi / 2^(logn - j) */
                double ar = bc[logn - j], ai = bs[logn - j], t = cr * ar - ci * ai;
                ci = cr * ai + ci * ar;
                cr = t;
            }
        c[k] = cr; s[k] = ci;
    }
}

/* forward: sum a_k e^{-2 pi i jk/n}; inverse: e^{+...}, unscaled */
static void mf__fft1(double *a, int n, const double *c, const double *s, int inverse)
{
    int i, j, len, k;
    for (i = 1, j = 0; i < n; ++i) {
        int bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) {
            double t = a[2 * i]; a[2 * i] = a[2 * j]; a[2 * j] = t;
            t = a[2 * i + 1]; a[2 * i + 1] = a[2 * j + 1]; a[2 * j + 1] = t;
        }
    }
    for (i = 0; i < n; i += 2) {   /* first stage: twiddle 1 */
        double *p = a + 2 * i, tr = p[2], ti = p[3];
        p[2] = p[0] - tr; p[3] = p[1] - ti;
        p[0] += tr; p[1] += ti;
    }
    for (len = 4; len <= n; len <<= 1) {   /* one twiddle per k, all blocks */
        int half = len >> 1, step = n / len;
        for (k = 0; k < half; ++k) {
            double wr = c[k * step], wi = inverse ? s[k * step] : -s[k * step];
            for (i = k; i < n; i += len) {
                double *p = a + 2 * i, *q = a + 2 * (i + half);
                double tr = q[0] * wr - q[1] * wi, ti = q[0] * wi + q[1] * wr;
                q[0] = p[0] - tr; q[1] = p[1] - ti;
                p[0] += tr; p[1] += ti;
            }
        }
    }
}

/* Transform of the columns of an n x n row-major array, 8 at a time
 * through tmp (16 n doubles) to stay in cache. */
static void mf__fft_columns(double *a, int n, const double *c, const double *s, int inverse, double *tmp)
{
    int x, y, b, nb;
    nb = n < 8 ? n : 8;
    for (x = 0; x < n; x += nb) {
        for (y = 0; y < n; ++y)
            for (b = 0; b < nb; ++b) {
                const double *p = a + 2 * ((size_t)y * (size_t)n + (size_t)(x + b));
                tmp[2 * ((size_t)b * (size_t)n + (size_t)y)] = p[0];
                tmp[2 * ((size_t)b * (size_t)n + (size_t)y) + 1] = p[1];
            }
        for (b = 0; b < nb; ++b) mf__fft1(tmp + 2 * (size_t)b * (size_t)n, n, c, s, inverse);
        for (y = 0; y < n; ++y)
            for (b = 0; b < nb; ++b) {
                double *p = a + 2 * ((size_t)y * (size_t)n + (size_t)(x + b));
                p[0] = tmp[2 * ((size_t)b * (size_t)n + (size_t)y)];
                p[1] = tmp[2 * ((size_t)b * (size_t)n + (size_t)y) + 1];
            }
    }
}

/* forward 2D transform: rows, then columns */
static void mf__fft2(double *a, int n, const double *c, const double *s, double *tmp)
{
    int y;
    for (y = 0; y < n; ++y) mf__fft1(a + 2 * (size_t)y * (size_t)n, n, c, s, 0);
    mf__fft_columns(a, n, c, s, 0, tmp);
}

/* inverse 2D transform of a Hermitian spectrum (a real result, unscaled, into
 * out): columns, then the rows two at a time (rows A, B with real inverses a,
 * b: the inverse of A + iB is a + ib), a quarter less work */
static void mf__ifft2_real(double *a, int n, const double *c, const double *s, double *tmp, double *out)
{
    int x, y;
    mf__fft_columns(a, n, c, s, 1, tmp);
    for (y = 0; y < n; y += 2) {
        const double *ra = a + 2 * (size_t)y * (size_t)n, *rb = a + 2 * (size_t)(y + 1) * (size_t)n;
        for (x = 0; x < n; ++x) {
            tmp[2 * x] = ra[2 * x] - rb[2 * x + 1];
            tmp[2 * x + 1] = ra[2 * x + 1] + rb[2 * x];
        }
        mf__fft1(tmp, n, c, s, 1);
        for (x = 0; x < n; ++x) {
            out[(size_t)y * (size_t)n + (size_t)x] = tmp[2 * x];
            out[(size_t)(y + 1) * (size_t)n + (size_t)x] = tmp[2 * x + 1];
        }
    }
}

/* ---- Generation (Ribardiere et al. 2019, Sec. 4.2, Algorithm 1) ----
 *
 * Discretization. A grid point (x, y) carries one target slope t = (tx, ty),
 * a sample of Q_m. The surface is the triangle mesh of the grid (squares cut
 * by the diagonal (x+1, y)-(x, y+1)); the triangle below-left of the
 * diagonal has the forward differences F = (h[x+1] - h[x], h[y+1] - h[y]) of
 * its corner (x, y) as slope, the one above-right the backward differences
 * B = (h[x] - h[x-1], h[y] - h[y-1]) of its corner (x+1, y+1). Integration
 * (Step 3) is the least-squares fit of both triangles of every point to its
 * target, sum |F - t|^2 + |B - t|^2: in Fourier, with the discrete symbols
 * (not the continuous ones of Eq. 21, which bias the discrete slopes),
 *     H = -i (sin wx Tx + sin wy Ty) / (2 (2 - cos wx - cos wy)),
 * the discrete Poisson equation "5-point Laplacian h = central divergence t".
 * Since (F + B) / 2 is the central difference of Eq. 22, a point whose two
 * triangles match t has its central difference at t as well: the API's
 * central differences and the traced triangles follow the same targets. The
 * Laplacian vanishes only at w = 0, so nothing is amplified (the central
 * symbol sin w alone vanishes at the Nyquist frequency and decouples the two
 * checkerboard sub-lattices).
 *
 * Schwarz error. Eq. 19, the discrete Schwarz condition, on the target
 * field around the grid square of corner (x, y), relative to the mean
 * cumulative slope of Q_m:
 *     eps(x, y) = |tx(x,y) + ty(x+1,y) - ty(x,y) - tx(x,y+1)| / mean(|tx| + |ty|);
 * threshold 0.02 is the paper's "2% of a cumulative dx and dy error". (The
 * residual of the fit, |F - t| + |B - t|, as the error instead re-matches
 * ~98% of the points every iteration for the same final histogram.)
 *
 * Re-matching (Step 2). Points with eps > threshold release their targets
 * into a pool; in a random order, each takes the unused pool value nearest
 * (Euclidean, slope space) to its central difference, found in a grid over
 * slope space by a spiral search of rings of cells; the search stops when
 * the next ring cannot hold anything nearer, so the match is exact. The grid
 * lines sit at quantiles of Q_m (a uniform grid in the marginal CDFs), so
 * heavy tails (GGX, Student-t) do not pile every sample into one cell: about
 * sixteen pool values per cell and O(1) work per query on average. The
 * targets stay a permutation of Q_m at every step. Before the search the
 * queries' spread is matched to the pool's (see mf__ms_rematch).
 *
 * At most a fraction max_rematch of the points, those of largest eps, are
 * re-matched per iteration. With every point above the threshold (the
 * paper), heavy tails never settle: on GGX 0.4 (128^2, 150 iterations) 90% of
 * the points exceed 0.02 every iteration and the surface ends with 35% too
 * few near-normal facets, its median slope 12% high. Measured over six seeds
 * (median slope length relative to D's, and the deficit at the normal):
 *     max_rematch   GGX 0.4            Beckmann 0.5
 *     1 (paper)     +12%, 35% too few  -0.5%
 *     0.5           +3..+10%, 7..27%   -0.7 .. -0.1%
 *     0.25          -1.5..+2.8%, 2..5% -3.2 .. -2.6%
 * so the default picks it from the tail weight of Q_m, w = r99 / r50 (the
 * 99th and 50th percentiles of |slope|; Beckmann 2.6, Student-t gamma 3 4.7,
 * GGX 10): 0.5 for w <= 3, 0.25 for w >= 6, linear between. It also makes
 * the iterations cheaper.
 *
 * Measured alternatives (Beckmann 0.5, 256^2, 200 iterations; total variation
 * of the central / triangle slope histograms against D, fraction of cells
 * below the threshold): the paper's continuous symbol with Eq. 19, 0.029 /
 * 0.027, 47%; the central symbol sin w alone, 0.011 / 0.54 (the triangles,
 * i.e. the traced surface, are 2.4 times too rough: checkerboard), 87%;
 * forward differences only, 0.035 / 0.027, 11%; this scheme, 0.033 / 0.030,
 * 51%, then 0.03 / 0.03 and 67% with the spread matching. All schemes that
 * keep the triangles right converge to surfaces whose neighbouring slopes are
 * correlated (0.97 to 0.99 at lag 1). */

static double mf__absd(double x) { return x < 0.0 ? -x : x; }
static double mf__mind(double a, double b) { return a < b ? a : b; }

typedef struct mf__ms {
    int n;
    size_t n2;
    double *tx, *ty, *h, *eps, *z, *tmp, *fc, *fs;
    double *px, *py, *qx, *qy, *sx, *sy, *ex, *ey;   /* pool (binned), queries, sorted Q_m, grid lines */
    int *cell, *start, *count, *bin;
    double sbar;          /* mean |tx| + |ty| of Q_m */
} mf__ms;

static void mf__ms_zero(mf__ms *m)
{
    m->tx = m->ty = m->h = m->eps = m->z = m->tmp = m->fc = m->fs = 0;
    m->px = m->py = m->qx = m->qy = m->sx = m->sy = m->ex = m->ey = 0;
    m->cell = m->start = m->count = m->bin = 0;
    m->n = 0; m->n2 = 0; m->sbar = 0.0;
}

static void mf__ms_free(mf__ms *m)
{
    MF_FREE(m->tx); MF_FREE(m->ty); MF_FREE(m->h); MF_FREE(m->eps); MF_FREE(m->z); MF_FREE(m->tmp);
    MF_FREE(m->fc); MF_FREE(m->fs); MF_FREE(m->px); MF_FREE(m->py); MF_FREE(m->qx); MF_FREE(m->qy);
    MF_FREE(m->sx); MF_FREE(m->sy); MF_FREE(m->ex); MF_FREE(m->ey); MF_FREE(m->cell); MF_FREE(m->start);
    MF_FREE(m->count); MF_FREE(m->bin);
}

static int mf__ms_alloc(mf__ms *m, int n)
{
    size_t n2 = (size_t)n * (size_t)n, nb = n2 / 16 + 2, ne = (size_t)n + 2;
    m->n = n; m->n2 = n2;
#define MF__MS_A(p, T, cnt) (m->p = (T *)MF_MALLOC(sizeof(T) * (cnt)))
    MF__MS_A(tx, double, n2); MF__MS_A(ty, double, n2); MF__MS_A(h, double, n2); MF__MS_A(eps, double, n2);
    MF__MS_A(z, double, 2 * n2); MF__MS_A(tmp, double, 16 * (size_t)n); MF__MS_A(fc, double, (size_t)n);
    MF__MS_A(fs, double, (size_t)n); MF__MS_A(px, double, n2); MF__MS_A(py, double, n2);
    MF__MS_A(qx, double, n2); MF__MS_A(qy, double, n2); MF__MS_A(sx, double, n2); MF__MS_A(sy, double, n2);
    MF__MS_A(ex, double, ne); MF__MS_A(ey, double, ne); MF__MS_A(cell, int, n2); MF__MS_A(start, int, nb + 1);
    MF__MS_A(count, int, nb); MF__MS_A(bin, int, n2);
#undef MF__MS_A
    return m->tx && m->ty && m->h && m->eps && m->z && m->tmp && m->fc && m->fs && m->px && m->py &&
           m->qx && m->qy && m->sx && m->sy && m->ex && m->ey && m->cell && m->start && m->count && m->bin;
}

/* cos and sin of 2 pi k / n for any k in [0, n) from the half table */
static void mf__ms_cs(const mf__ms *m, int k, double *c, double *s)
{
    int half = m->n / 2;
    if (k < half) { *c = m->fc[k]; *s = m->fs[k]; }
    else { *c = -m->fc[k - half]; *s = -m->fs[k - half]; }
}

/* Step 3: h from the targets (least squares over both triangles of every point) */
static void mf__ms_integrate(mf__ms *m)
{
    int n = m->n, kx, ky;
    size_t i, n2 = m->n2;
    double *z = m->z, inv = 1.0 / (double)n2;
    for (i = 0; i < n2; ++i) { z[2 * i] = m->tx[i]; z[2 * i + 1] = m->ty[i]; }
    mf__fft2(z, n, m->fc, m->fs, m->tmp);
    /* Z = FFT(tx + i ty): Tx(k) = (Z(k) + conj Z(-k)) / 2, Ty(k) = (Z(k) - conj Z(-k)) / 2i.
     * h is real: H(-k) = conj H(k), so each pair (k, -k) is solved once. */
    for (ky = 0; ky < n; ++ky)
        for (kx = 0; kx < n; ++kx) {
            size_t i0 = (size_t)ky * (size_t)n + (size_t)kx;
            size_t i1 = (size_t)((n - ky) & (n - 1)) * (size_t)n + (size_t)((n - kx) & (n - 1));
            double cx, sx, cy, sy, xr, xi, yr, yi, den, hr, hi;
            if (i1 < i0) continue;
            mf__ms_cs(m, kx, &cx, &sx);
            mf__ms_cs(m, ky, &cy, &sy);
            den = 2.0 * (2.0 - cx - cy);
            if (!(den > 1e-300)) { z[2 * i0] = z[2 * i0 + 1] = 0.0; continue; }   /* mean height 0 */
            xr = 0.5 * (z[2 * i0] + z[2 * i1]); xi = 0.5 * (z[2 * i0 + 1] - z[2 * i1 + 1]);
            yr = 0.5 * (z[2 * i0 + 1] + z[2 * i1 + 1]); yi = -0.5 * (z[2 * i0] - z[2 * i1]);
            /* H = -i (sx X + sy Y) / den */
            hr = (sx * xi + sy * yi) / den;
            hi = -(sx * xr + sy * yr) / den;
            z[2 * i0] = hr; z[2 * i0 + 1] = hi;
            z[2 * i1] = hr; z[2 * i1 + 1] = -hi;
        }
    mf__ifft2_real(z, n, m->fc, m->fs, m->tmp, m->h);
    for (i = 0; i < n2; ++i) m->h[i] *= inv;
}

/* one-sided differences of h at point i = (x, y) */
static void mf__ms_diff(const mf__ms *m, int x, int y, double *fx, double *fy, double *bx, double *by)
{
    int n = m->n, mk = n - 1;
    const double *h = m->h;
    double c = h[(size_t)y * (size_t)n + (size_t)x];
    *fx = h[(size_t)y * (size_t)n + (size_t)((x + 1) & mk)] - c;
    *bx = c - h[(size_t)y * (size_t)n + (size_t)((x - 1) & mk)];
    *fy = h[(size_t)((y + 1) & mk) * (size_t)n + (size_t)x] - c;
    *by = c - h[(size_t)((y - 1) & mk) * (size_t)n + (size_t)x];
}

/* the points with eps above the threshold, listed in m->cell with their
 * central differences (the queries); returns how many */
static int mf__ms_list(mf__ms *m, double threshold)
{
    int n = m->n, x, y, k = 0;
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            size_t i = (size_t)y * (size_t)n + (size_t)x;
            if (m->eps[i] > threshold) {
                double fx, fy, bx, by;
                mf__ms_diff(m, x, y, &fx, &fy, &bx, &by);
                m->cell[k] = (int)i;
                m->qx[k] = 0.5 * (fx + bx);   /* the central difference, Eq. 22 */
                m->qy[k] = 0.5 * (fy + by);
                ++k;
            }
        }
    return k;
}

/* eps of every point (Eq. 19 on the target field), then the list of the
 * points above the threshold; at most max_fraction of all points (those of
 * largest eps) when that is below 1 */
static int mf__ms_errors(mf__ms *m, double threshold, double max_fraction)
{
    int n = m->n, mk = n - 1, x, y, above = 0;
    double inv = 1.0 / m->sbar;
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            size_t i = (size_t)y * (size_t)n + (size_t)x;
            size_t ix = (size_t)y * (size_t)n + (size_t)((x + 1) & mk), iy = (size_t)((y + 1) & mk) * (size_t)n + (size_t)x;
            double e = mf__absd(m->tx[i] + m->ty[ix] - m->ty[i] - m->tx[iy]) * inv;
            m->eps[i] = e;
            if (e > threshold) ++above;
        }
    if ((double)above > max_fraction * (double)m->n2) {
        size_t i, r = (size_t)((1.0 - max_fraction) * (double)m->n2);
        double q;
        for (i = 0; i < m->n2; ++i) m->z[i] = m->eps[i];
        q = mf__select_d(m->z, m->n2, r < m->n2 ? r : m->n2 - 1);
        if (q > threshold) threshold = q;
    }
    return mf__ms_list(m, threshold);
}

/* bin of v among edges e[0..g] (grid cell index in [0, g)) */
static int mf__ms_bin(const double *e, int g, double v)
{
    int lo = 0, hi = g;   /* find the last j in [0, g) with e[j] <= v */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (e[mid] <= v) lo = mid; else hi = mid;
    }
    return lo;
}

/* Step 2: re-match the k points in m->cell (their targets form the pool;
 * m->qx, m->qy hold their central differences) */
static void mf__ms_rematch(mf__ms *m, int k, mf__pcg *rng)
{
    int n = m->n, g, j, q, nb;
    size_t m2 = m->n2;
    if (k <= 0) return;
    /* g x g cells, about sixteen pool values each (fewer, larger cells visit
     * fewer empty cells once the pool thins out: 25% faster than eight at
     * 1024^2); lines at quantiles of Q_m */
    g = 1;
    while ((g + 1) * (g + 1) * 16 <= k && g < n / 2) ++g;
    for (j = 0; j <= g; ++j) {
        size_t r = (size_t)((double)(m2 - 1) * (double)j / (double)g);
        m->ex[j] = m->sx[r]; m->ey[j] = m->sy[r];
    }
    nb = g * g;
    for (j = 0; j <= nb; ++j) m->start[j] = 0;
    for (j = 0; j < k; ++j) {
        int i = m->cell[j];
        m->bin[j] = mf__ms_bin(m->ey, g, m->ty[i]) * g + mf__ms_bin(m->ex, g, m->tx[i]);
        ++m->start[m->bin[j] + 1];
    }
    for (j = 0; j < nb; ++j) { m->start[j + 1] += m->start[j]; m->count[j] = 0; }
    for (j = 0; j < k; ++j) {   /* counting sort of the pool values into the cells */
        int i = m->cell[j], b = m->bin[j], p = m->start[b] + m->count[b]++;
        m->px[p] = m->tx[i]; m->py[p] = m->ty[i];
    }
    /* the queries' spread matched to the pool's, per axis, when they are
     * narrower (the median of |slope|, which heavy tails do not sway): early
     * on the integrated field is much smoother than its targets, and nearest
     * values to the shrunken queries would empty the middle of the pool
     * first. Measured on Beckmann 0.5, 128^2, 150 iterations: the density of
     * the smallest slopes 0.83 of D without, 0.93 with. Queries broader than
     * the pool (heavy tails later on) are left alone: shrinking them hurts. */
    {
        double f[2];
        int ax;
        for (ax = 0; ax < 2; ++ax) {
            const double *qa = ax ? m->qy : m->qx, *pa = ax ? m->py : m->px;
            double mq, mp;
            for (j = 0; j < k; ++j) { m->z[j] = mf__absd(qa[j]); m->z[k + j] = mf__absd(pa[j]); }
            mq = mf__select_d(m->z, (size_t)k, (size_t)k / 2);
            mp = mf__select_d(m->z + k, (size_t)k, (size_t)k / 2);
            f[ax] = mq > 0.0 && mp > 0.0 && mp > mq ? mp / mq : 1.0;
        }
        for (j = 0; j < k; ++j) { m->qx[j] *= f[0]; m->qy[j] *= f[1]; }
    }
    /* serve the points in a random order */
    for (j = k - 1; j > 0; --j) {
        int r = (int)mf__pcg_below(rng, (unsigned)(j + 1)), t = m->cell[j];
        double v;
        m->cell[j] = m->cell[r]; m->cell[r] = t;
        v = m->qx[j]; m->qx[j] = m->qx[r]; m->qx[r] = v;
        v = m->qy[j]; m->qy[j] = m->qy[r]; m->qy[r] = v;
    }
    for (q = 0; q < k; ++q) {
        int i = m->cell[q], bx, by, r, bestpos = -1, bestbin = -1, last;
        double cx = m->qx[q], cy = m->qy[q], bd = 1e300;
        bx = mf__ms_bin(m->ex, g, cx);
        by = mf__ms_bin(m->ey, g, cy);
        for (r = 0;; ++r) {   /* spiral: ring r is the border of the (2r+1)^2 square of cells */
            int yy, more = 0;
            double lb = 1e300;
            for (yy = by - r; yy <= by + r; ++yy) {
                int xx, step = (yy == by - r || yy == by + r || r == 0) ? 1 : 2 * r;
                if (yy < 0 || yy >= g) continue;
                for (xx = bx - r; xx <= bx + r; xx += step) {
                    int b, p, e;
                    if (xx < 0 || xx >= g) continue;
                    b = yy * g + xx;
                    for (p = m->start[b], e = p + m->count[b]; p < e; ++p) {
                        double dx = m->px[p] - cx, dy = m->py[p] - cy, d2 = dx * dx + dy * dy;
                        if (d2 < bd) { bd = d2; bestpos = p; bestbin = b; }
                    }
                }
            }
            /* anything beyond ring r is at least lb away */
            if (bx - r - 1 >= 0) { lb = mf__mind(lb, cx - m->ex[bx - r]); more = 1; }
            if (bx + r + 1 < g) { lb = mf__mind(lb, m->ex[bx + r + 1] - cx); more = 1; }
            if (by - r - 1 >= 0) { lb = mf__mind(lb, cy - m->ey[by - r]); more = 1; }
            if (by + r + 1 < g) { lb = mf__mind(lb, m->ey[by + r + 1] - cy); more = 1; }
            if (!more || (bestpos >= 0 && lb > 0.0 && bd <= lb * lb)) break;
        }
        /* take it; the last value of its cell moves into its place */
        m->tx[i] = m->px[bestpos]; m->ty[i] = m->py[bestpos];
        last = m->start[bestbin] + --m->count[bestbin];
        m->px[bestpos] = m->px[last]; m->py[bestpos] = m->py[last];
    }
}

MFDEF void mf_microsurface_options_default(mf_microsurface_options *o)
{
    if (!o) return;
    o->iterations = 100;
    o->seed = 1;
    o->threshold = MF_MICROSURFACE_THRESHOLD;
    o->max_rematch = MF_R(0.0);
    o->stratified = 1;
    o->progress = 0;
    o->ctx = 0;
    o->gradients = 0;
    o->schwarz = 0;
}

/* 1 if d can be sampled and evaluated: finite roughness, a finite unit
 * sample with z > 0 and D > 0 there, and no mean slope (LEADR) */
static int mf__ms_ndf_ok(const mf_ndf *d)
{
    mf_vec3 m;
    mf_real v;
    if (!(d->ax > MF_R(0.0) && d->ax < MF_BIG) || !(d->ay > MF_R(0.0) && d->ay < MF_BIG)) return 0;
    if (d->transformed && !mf_transform_valid(d->M)) return 0;
    if (d->type == MF_NDF_LEADR && (d->p.leadr.mx != MF_R(0.0) || d->p.leadr.my != MF_R(0.0))) return 0;
    m = mf_sample_D(d, MF_R(0.3), MF_R(0.2));
    v = mf_D(d, m);
    return m.z > MF_R(0.0) && m.z <= MF_R(1.0) && MF_FABS(m.x) <= MF_R(1.0) && MF_FABS(m.y) <= MF_R(1.0) &&
           v > MF_R(0.0) && v < MF_BIG;
}

MFDEF mf_result mf_microsurface_generate_ex(const mf_ndf *d, int size, const mf_microsurface_options *o,
                                            mf_real *heights, mf_microsurface_stats *stats)
{
    mf__ms m;
    mf__pcg rng;
    int n = size, it, k = 0, x, y;
    size_t i, n2;
    double thr, cap, smax = (double)MF_MICROSURFACE_MAX_SLOPE, acc[4];
    if (stats) {
        stats->iterations = stats->rematched = 0;
        stats->below = stats->eps_mean = stats->eps_median = MF_R(0.0);
        stats->rms_target = stats->rms_central = stats->rms_triangle = MF_R(0.0);
    }
    if (!d || !o || !heights || !mf__pow2(size) || size < MF_MICROSURFACE_MIN_SIZE || size > MF_MICROSURFACE_MAX_SIZE ||
        o->iterations < 0 || o->iterations > MF_MICROSURFACE_MAX_ITERATIONS || !(o->threshold >= MF_R(0.0) && o->threshold < MF_BIG) ||
        !(o->max_rematch >= MF_R(0.0) && o->max_rematch <= MF_R(1.0)) || !mf__ms_ndf_ok(d))
        return MF_ERROR_INVALID_ARGUMENT;
    thr = (double)o->threshold;
    mf__ms_zero(&m);
    if (!mf__ms_alloc(&m, n)) { mf__ms_free(&m); return MF_ERROR_OUT_OF_MEMORY; }
    n2 = m.n2;
    mf__fft_twiddles(m.fc, m.fs, n);
    /* Q_m: n^2 slopes drawn with density D cos (= the slope density P22),
     * stratified on an n x n grid of (u1, u2) when asked; then shuffled onto the grid */
    mf__pcg_seed(&rng, o->seed, 0x6d66u);
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            double u1 = mf__pcg_u01(&rng), u2 = mf__pcg_u01(&rng), sxv, syv, l;
            mf_vec3 w;
            if (o->stratified) { u1 = ((double)x + u1) / (double)n; u2 = ((double)y + u2) / (double)n; }
            w = mf_sample_D(d, mf__u01_real(u1), mf__u01_real(u2));
            i = (size_t)y * (size_t)n + (size_t)x;
            if (w.z > MF_R(0.0)) {
                sxv = -(double)w.x / (double)w.z; syv = -(double)w.y / (double)w.z;
                l = mf__sqrt_d(sxv * sxv + syv * syv);
                if (l > smax) { sxv *= smax / l; syv *= smax / l; }
            } else {   /* a horizontal normal: the steepest slope allowed, along it */
                l = mf__sqrt_d((double)w.x * (double)w.x + (double)w.y * (double)w.y);
                sxv = l > 0.0 ? -(double)w.x / l * smax : 0.0;
                syv = l > 0.0 ? -(double)w.y / l * smax : 0.0;
            }
            m.tx[i] = sxv; m.ty[i] = syv;
        }
    for (i = n2 - 1; i > 0; --i) {
        size_t r = (size_t)mf__pcg_below(&rng, (unsigned)(i + 1));
        double t = m.tx[i]; m.tx[i] = m.tx[r]; m.tx[r] = t;
        t = m.ty[i]; m.ty[i] = m.ty[r]; m.ty[r] = t;
    }
    m.sbar = 0.0;
    for (i = 0; i < n2; ++i) {
        m.sx[i] = m.tx[i]; m.sy[i] = m.ty[i];
        m.sbar += mf__absd(m.tx[i]) + mf__absd(m.ty[i]);
    }
    m.sbar = m.sbar / (double)n2 + 1e-300;
    mf__sort_d(m.sx, n2);
    mf__sort_d(m.sy, n2);
    cap = (double)o->max_rematch;
    if (!(cap > 0.0)) {   /* automatic: from the tail weight of Q_m, r99 / r50 of |slope| */
        double r50, r99, w;
        for (i = 0; i < n2; ++i) m.z[i] = m.tx[i] * m.tx[i] + m.ty[i] * m.ty[i];
        r50 = mf__select_d(m.z, n2, n2 / 2);
        r99 = mf__select_d(m.z, n2, n2 - 1 - n2 / 100);
        w = r50 > 0.0 ? mf__sqrt_d(r99 / r50) : 10.0;
        w = (w - 3.0) / 3.0;
        cap = 0.5 - 0.25 * (w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w));
    }
    /* Algorithm 1: integrate, then (compute errors, re-match, integrate) per iteration */
    mf__ms_integrate(&m);
    for (it = 0; it < o->iterations; ++it) {
        k = mf__ms_errors(&m, thr, cap);
        mf__ms_rematch(&m, k, &rng);
        mf__ms_integrate(&m);
        if (o->progress) o->progress(it + 1, o->iterations, o->ctx);
    }
    k = mf__ms_errors(&m, thr, 1.0);
    for (i = 0; i < n2; ++i) heights[i] = (mf_real)m.h[i];
    if (o->gradients)
        for (i = 0; i < n2; ++i) { o->gradients[2 * i] = (mf_real)m.tx[i]; o->gradients[2 * i + 1] = (mf_real)m.ty[i]; }
    if (o->schwarz)
        for (i = 0; i < n2; ++i) o->schwarz[i] = (mf_real)m.eps[i];
    if (stats) {
        acc[0] = acc[1] = acc[2] = acc[3] = 0.0;
        for (y = 0; y < n; ++y)
            for (x = 0; x < n; ++x) {
                double fx, fy, bx, by, cx, cy;
                i = (size_t)y * (size_t)n + (size_t)x;
                mf__ms_diff(&m, x, y, &fx, &fy, &bx, &by);
                cx = 0.5 * (fx + bx); cy = 0.5 * (fy + by);
                acc[0] += m.tx[i] * m.tx[i] + m.ty[i] * m.ty[i];
                acc[1] += cx * cx + cy * cy;
                acc[2] += 0.5 * (fx * fx + fy * fy + bx * bx + by * by);
                acc[3] += m.eps[i];
            }
        stats->iterations = o->iterations;
        stats->rematched = o->iterations > 0 ? k : 0;
        stats->below = (mf_real)(1.0 - (double)k / (double)n2);
        stats->eps_mean = (mf_real)(acc[3] / (double)n2);
        stats->rms_target = (mf_real)mf__sqrt_d(acc[0] / (2.0 * (double)n2));
        stats->rms_central = (mf_real)mf__sqrt_d(acc[1] / (2.0 * (double)n2));
        stats->rms_triangle = (mf_real)mf__sqrt_d(acc[2] / (2.0 * (double)n2));
        mf__sort_d(m.eps, n2);
        stats->eps_median = (mf_real)m.eps[n2 / 2];
    }
    mf__ms_free(&m);
    return MF_SUCCESS;
}

MFDEF mf_result mf_microsurface_generate(const mf_ndf *d, int size, int iterations, mf_u64 seed, mf_real *heights)
{
    mf_microsurface_options o;
    mf_microsurface_options_default(&o);
    o.iterations = iterations;
    o.seed = seed;
    return mf_microsurface_generate_ex(d, size, &o, heights, 0);
}

MFDEF mf_result mf_microsurface_integrate(const mf_real *gradients_xy, int size, mf_real *heights)
{
    mf__ms m;
    size_t i, n2;
    if (!gradients_xy || !heights || !mf__pow2(size) || size < MF_MICROSURFACE_MIN_SIZE || size > MF_MICROSURFACE_MAX_SIZE)
        return MF_ERROR_INVALID_ARGUMENT;
    n2 = (size_t)size * (size_t)size;
    for (i = 0; i < 2 * n2; ++i)
        if (!mf__finite_bits(gradients_xy[i]) || !(MF_FABS(gradients_xy[i]) < MF_BIG)) return MF_ERROR_INVALID_DATA;
    mf__ms_zero(&m);
    m.n = size; m.n2 = n2;
    m.tx = (double *)MF_MALLOC(sizeof(double) * n2);
    m.ty = (double *)MF_MALLOC(sizeof(double) * n2);
    m.h = (double *)MF_MALLOC(sizeof(double) * n2);
    m.z = (double *)MF_MALLOC(sizeof(double) * 2 * n2);
    m.tmp = (double *)MF_MALLOC(sizeof(double) * 16 * (size_t)size);
    m.fc = (double *)MF_MALLOC(sizeof(double) * (size_t)size);
    m.fs = (double *)MF_MALLOC(sizeof(double) * (size_t)size);
    if (!m.tx || !m.ty || !m.h || !m.z || !m.tmp || !m.fc || !m.fs) { mf__ms_free(&m); return MF_ERROR_OUT_OF_MEMORY; }
    mf__fft_twiddles(m.fc, m.fs, size);
    for (i = 0; i < n2; ++i) { m.tx[i] = (double)gradients_xy[2 * i]; m.ty[i] = (double)gradients_xy[2 * i + 1]; }
    mf__ms_integrate(&m);
    for (i = 0; i < n2; ++i) heights[i] = (mf_real)m.h[i];
    mf__ms_free(&m);
    return MF_SUCCESS;
}

/* ---- The virtual gonioreflectometer ---- */

MFDEF void mf_gonio_config_default(mf_gonio_config *c)
{
    if (!c) return;
    c->wi = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    c->facet = MF_FACET_MIRROR;
    c->albedo = MF_R(1.0);
    c->rays = 1000000;
    c->max_bounces = 100;
    c->seed = 1;
    c->progress = 0;
    c->ctx = 0;
}

MFDEF void mf_gonio_release(mf_gonio *g)
{
    if (!g) return;
    MF_FREE(g->ring_first); MF_FREE(g->ring_z); MF_FREE(g->first); MF_FREE(g->multi);
    g->ring_first = 0; g->ring_z = 0; g->first = g->multi = 0;
    g->rings = g->cells = 0;
}

static void mf__gonio_clear(mf_gonio *g)
{
    int i;
    for (i = 0; i < g->cells; ++i) g->first[i] = g->multi[i] = MF_R(0.0);
    g->rays = g->lost = g->leaks = 0;
    g->energy_first = g->energy_multi = g->energy_lost = g->mean_bounces = MF_R(0.0);
}

/* Equal-area sensor (after Beckers and Beckers 2012): a polar cap and rings
 * of width delta in theta, ring k cut into round(2 pi sin(theta_k) / delta)
 * sectors so the cells are near square; the ring boundaries are then placed
 * so that every cell has exactly the solid angle 2 pi / cells:
 * cos(theta) at the end of ring k is 1 - (cells in rings 0..k) / cells. The
 * cap's angular radius delta / sqrt(pi) gives it the area of a square cell. */
MFDEF mf_result mf_gonio_init(mf_gonio *g, int rings)
{
    int k, total = 0;
    double c = 0.5641895835477563, delta;   /* 1/sqrt(pi) */
    if (!g) return MF_ERROR_INVALID_ARGUMENT;
    g->ring_first = 0; g->ring_z = 0; g->first = g->multi = 0; g->rings = g->cells = 0;
    if (rings < 1 || rings > 1024) return MF_ERROR_INVALID_ARGUMENT;
    g->ring_first = (int *)MF_MALLOC(sizeof(int) * (size_t)(rings + 1));
    g->ring_z = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)(rings + 1));
    if (!g->ring_first || !g->ring_z) { mf_gonio_release(g); return MF_ERROR_OUT_OF_MEMORY; }
    delta = 1.5707963267948966 / ((double)(rings - 1) + c);
    g->ring_first[0] = 0;
    for (k = 0; k < rings; ++k) {
        int cnt = 1;
        if (k > 0) {
            double mid = c * delta + ((double)k - 0.5) * delta;
            cnt = (int)((double)MF_SIN((mf_real)mid) * 6.283185307179586 / delta + 0.5);
            if (cnt < 1) cnt = 1;
        }
        total += cnt;
        g->ring_first[k + 1] = total;
    }
    g->rings = rings;
    g->cells = total;
    for (k = 0; k <= rings; ++k) g->ring_z[k] = (mf_real)(1.0 - (double)g->ring_first[k] / (double)total);
    g->ring_z[rings] = MF_R(0.0);
    g->first = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)total);
    g->multi = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)total);
    if (!g->first || !g->multi) { mf_gonio_release(g); return MF_ERROR_OUT_OF_MEMORY; }
    mf__gonio_clear(g);
    return MF_SUCCESS;
}

/* ring holding cos(theta) = z: ring_z[k] >= z > ring_z[k + 1] */
static int mf__gonio_ring(const mf_gonio *g, mf_real z)
{
    int lo = 0, hi = g->rings - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (z > g->ring_z[mid + 1]) hi = mid; else lo = mid + 1;
    }
    return lo;
}

MFDEF int mf_gonio_cell(const mf_gonio *g, mf_vec3 w)
{
    int k, n, j;
    mf_real phi;
    if (!g || !g->ring_z || !(w.z > MF_R(0.0)) || !(MF_FABS(w.x) < MF_BIG) || !(MF_FABS(w.y) < MF_BIG)) return -1;
    k = mf__gonio_ring(g, mf_min(w.z, MF_R(1.0)));
    n = g->ring_first[k + 1] - g->ring_first[k];
    if (n == 1) return g->ring_first[k];
    phi = MF_ATAN2(w.y, w.x);
    if (phi < MF_R(0.0)) phi += MF_R(2.0) * MF_PI;
    j = (int)(phi * (mf_real)n / (MF_R(2.0) * MF_PI));
    if (j >= n) j = n - 1;
    if (j < 0) j = 0;
    return g->ring_first[k] + j;
}

static int mf__gonio_ring_of_cell(const mf_gonio *g, int cell)
{
    int lo = 0, hi = g->rings - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (g->ring_first[mid] <= cell) lo = mid; else hi = mid - 1;
    }
    return lo;
}

MFDEF void mf_gonio_cell_bounds(const mf_gonio *g, int cell, mf_real *z_lo, mf_real *z_hi,
                                mf_real *phi_lo, mf_real *phi_hi)
{
    int k, n;
    mf_real a = MF_R(0.0), b = MF_R(0.0), p0 = MF_R(0.0), p1 = MF_R(0.0);
    if (g && g->ring_z && cell >= 0 && cell < g->cells) {
        k = mf__gonio_ring_of_cell(g, cell);
        n = g->ring_first[k + 1] - g->ring_first[k];
        a = g->ring_z[k + 1]; b = g->ring_z[k];
        p0 = MF_R(2.0) * MF_PI * (mf_real)(cell - g->ring_first[k]) / (mf_real)n;
        p1 = MF_R(2.0) * MF_PI * (mf_real)(cell - g->ring_first[k] + 1) / (mf_real)n;
    }
    if (z_lo) *z_lo = a;
    if (z_hi) *z_hi = b;
    if (phi_lo) *phi_lo = p0;
    if (phi_hi) *phi_hi = p1;
}

MFDEF mf_vec3 mf_gonio_cell_center(const mf_gonio *g, int cell)
{
    mf_real z0, z1, p0, p1, z, s, p;
    if (!g || !g->ring_z || cell < 0 || cell >= g->cells) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (cell == 0) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));   /* the polar cap */
    mf_gonio_cell_bounds(g, cell, &z0, &z1, &p0, &p1);
    z = MF_R(0.5) * (z0 + z1);
    s = MF_SQRT(mf_max(MF_R(1.0) - z * z, MF_R(0.0)));
    p = MF_R(0.5) * (p0 + p1);
    return mf_vec3_make(s * MF_COS(p), s * MF_SIN(p), z);
}

MFDEF mf_real mf_gonio_cell_solid_angle(const mf_gonio *g)
{
    if (!g || g->cells < 1) return MF_R(0.0);
    return MF_R(2.0) * MF_PI / (mf_real)g->cells;
}

MFDEF mf_result mf_gonio_model(const mf_gonio *g, const mf_ndf *d, mf_vec3 wi, int n, mf_real *out)
{
    int c, i, j;
    if (!g || !g->ring_z || !d || !out || n < 1 || n > 64 || !(wi.z > MF_R(0.0))) return MF_ERROR_INVALID_ARGUMENT;
    wi = mf_normalize(wi);
    for (c = 0; c < g->cells; ++c) {
        mf_real z0, z1, p0, p1;
        double sum = 0.0;
        mf_gonio_cell_bounds(g, c, &z0, &z1, &p0, &p1);
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                mf_real z = z0 + (z1 - z0) * ((mf_real)i + MF_R(0.5)) / (mf_real)n;
                mf_real p = p0 + (p1 - p0) * ((mf_real)j + MF_R(0.5)) / (mf_real)n;
                mf_real s = MF_SQRT(mf_max(MF_R(1.0) - z * z, MF_R(0.0)));
                mf_vec3 wo = mf_vec3_make(s * MF_COS(p), s * MF_SIN(p), z);
                sum += (double)(mf_brdf(d, wo, wi) * z);
            }
        out[c] = (mf_real)(sum * (double)mf_gonio_cell_solid_angle(g) / (double)(n * n));
    }
    return MF_SUCCESS;
}

/* The height field as traced: double heights, the top of every grid square
 * (for skipping squares the ray passes over) and of the whole field. */
typedef struct mf__tracer {
    const double *h;
    const double *top;
    int n;
    double zmax;
    long max_steps;
} mf__tracer;

/* height above the triangle tri (0: below-left of the diagonal u + v = 1, 1:
 * above-right) of square corners h00 h10 h01 h11, at local (u, v) and height z */
static double mf__tri_gap(const double *c, int tri, double u, double v, double z)
{
    if (!tri) return z - (c[0] + (c[1] - c[0]) * u + (c[2] - c[0]) * v);
    return z - (c[3] + (c[3] - c[2]) * (u - 1.0) + (c[3] - c[1]) * (v - 1.0));
}

/* March from o along d (unit) over the periodic field: 1 with the hit
 * parameter, the facet (square << 1 | triangle) and its slope; 0 when the ray
 * rises above every vertex; -1 after max_steps squares. skip: the facet the
 * ray leaves (a plane cannot be hit twice in a row). The height above the
 * surface is linear along the ray on each triangle piece, so the first
 * crossing is exact; a piece that starts below the surface (rounding at an
 * edge) is a hit at its start, counted in *leak. */
static int mf__trace(const mf__tracer *T, const double o[3], const double d[3], long skip, double *thit,
                     long *facet, double *slope, int *leak)
{
    int n = T->n, mk = T->n - 1, ix = (int)o[0], iy = (int)o[1], stx = d[0] > 0.0 ? 1 : -1, sty = d[1] > 0.0 ? 1 : -1;
    double inf = 1e300, tdx = d[0] != 0.0 ? 1.0 / mf__absd(d[0]) : inf, tdy = d[1] != 0.0 ? 1.0 / mf__absd(d[1]) : inf;
    double tmx = d[0] > 0.0 ? ((double)ix + 1.0 - o[0]) * tdx : (d[0] < 0.0 ? (o[0] - (double)ix) * tdx : inf);
    double tmy = d[1] > 0.0 ? ((double)iy + 1.0 - o[1]) * tdy : (d[1] < 0.0 ? (o[1] - (double)iy) * tdy : inf);
    double tesc = d[2] > 0.0 ? (T->zmax - o[2]) / d[2] : inf, t0 = 0.0, dsum = d[0] + d[1];
    long step;
    for (step = 0; step < T->max_steps; ++step) {
        double t1 = tmx < tmy ? tmx : tmy, za, zb;
        size_t sq;
        if (t0 >= tesc) return 0;
        if (t1 > tesc) t1 = tesc;
        za = o[2] + t0 * d[2];
        zb = o[2] + t1 * d[2];
        sq = (size_t)(iy & mk) * (size_t)n + (size_t)(ix & mk);
        if (!((za < zb ? za : zb) > T->top[sq])) {
            double c[4], ta[2], tb[2], s0 = o[0] - (double)ix + o[1] - (double)iy;
            int np = 1, p;
            c[0] = T->h[sq];
            c[1] = T->h[(size_t)(iy & mk) * (size_t)n + (size_t)((ix + 1) & mk)];
            c[2] = T->h[(size_t)((iy + 1) & mk) * (size_t)n + (size_t)(ix & mk)];
            c[3] = T->h[(size_t)((iy + 1) & mk) * (size_t)n + (size_t)((ix + 1) & mk)];
            ta[0] = t0; tb[0] = t1;
            if (dsum != 0.0) {   /* the diagonal u + v = 1 splits the path in two pieces */
                double td = (1.0 - s0) / dsum;
                if (td > t0 && td < t1) { tb[0] = td; ta[1] = td; tb[1] = t1; np = 2; }
            }
            for (p = 0; p < np; ++p) {
                double tm = 0.5 * (ta[p] + tb[p]), fa, fb, tol;
                int tri = s0 + tm * dsum > 1.0 ? 1 : 0;
                long id = ((long)sq << 1) | tri;
                if (id == skip) continue;
                fa = mf__tri_gap(c, tri, o[0] + ta[p] * d[0] - (double)ix, o[1] + ta[p] * d[1] - (double)iy, o[2] + ta[p] * d[2]);
                fb = mf__tri_gap(c, tri, o[0] + tb[p] * d[0] - (double)ix, o[1] + tb[p] * d[1] - (double)iy, o[2] + tb[p] * d[2]);
                tol = 1e-9 * (1.0 + mf__absd(za));
                if (fb > 0.0 && fa > -tol) continue;   /* stays above (or starts on it and rises) */
                if (fa > 0.0) *thit = ta[p] + (tb[p] - ta[p]) * fa / (fa - fb);
                else { *thit = ta[p]; if (fa < -tol) ++*leak; }
                *facet = id;
                if (!tri) { slope[0] = c[1] - c[0]; slope[1] = c[2] - c[0]; }
                else { slope[0] = c[3] - c[2]; slope[1] = c[3] - c[1]; }
                return 1;
            }
        }
        if (tmx < tmy) { ix += stx; t0 = tmx; tmx += tdx; }
        else { iy += sty; t0 = tmy; tmy += tdy; }
    }
    return -1;
}

/* wrap a coordinate into [0, n) */
static double mf__wrap(double x, int n)
{
    double f = (double)n;
    if (x >= 0.0 && x < f) return x;
    x -= f * (double)(long)(x / f);
    if (x < 0.0) x += f;
    if (x >= f) x -= f;
    return x;
}

MFDEF mf_result mf_gonio_measure(mf_gonio *g, const mf_real *heights, int size, const mf_gonio_config *c)
{
    mf__tracer T;
    mf__pcg rng;
    double *h, *top, *acc, e1 = 0.0, em = 0.0, el = 0.0, bounces = 0.0, zmax = -1e300;
    size_t i, n2;
    int n = size, r, x, y, leak = 0, lost = 0, every;
    mf_vec3 wi;
    if (!g || !g->ring_z || !g->first || !heights || !c || !mf__pow2(size) || size < 4 || size > MF_MICROSURFACE_MAX_SIZE)
        return MF_ERROR_INVALID_ARGUMENT;
    wi = mf_normalize(c->wi);
    if (!(wi.z > MF_R(0.0)) || (c->facet != MF_FACET_MIRROR && c->facet != MF_FACET_LAMBERT) ||
        !(c->albedo >= MF_R(0.0) && c->albedo <= MF_R(1.0)) || c->rays < 1 || c->max_bounces < 1)
        return MF_ERROR_INVALID_ARGUMENT;
    n2 = (size_t)n * (size_t)n;
    for (i = 0; i < n2; ++i)
        if (!mf__finite_bits(heights[i]) || !(MF_FABS(heights[i]) < MF_BIG)) return MF_ERROR_INVALID_DATA;
    h = (double *)MF_MALLOC(sizeof(double) * n2);
    top = (double *)MF_MALLOC(sizeof(double) * n2);
    acc = (double *)MF_MALLOC(sizeof(double) * 2 * (size_t)g->cells);
    if (!h || !top || !acc) { MF_FREE(h); MF_FREE(top); MF_FREE(acc); return MF_ERROR_OUT_OF_MEMORY; }
    for (i = 0; i < n2; ++i) { h[i] = (double)heights[i]; if (h[i] > zmax) zmax = h[i]; }
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            double a = h[(size_t)y * (size_t)n + (size_t)x], b = h[(size_t)y * (size_t)n + (size_t)((x + 1) & (n - 1))];
            double cc = h[(size_t)((y + 1) & (n - 1)) * (size_t)n + (size_t)x];
            double dd = h[(size_t)((y + 1) & (n - 1)) * (size_t)n + (size_t)((x + 1) & (n - 1))];
            double mx = a > b ? a : b;
            if (cc > mx) mx = cc;
            if (dd > mx) mx = dd;
            top[(size_t)y * (size_t)n + (size_t)x] = mx;
        }
    for (i = 0; i < 2 * (size_t)g->cells; ++i) acc[i] = 0.0;
    T.h = h; T.top = top; T.n = n; T.zmax = zmax; T.max_steps = 64L * n + 65536L;
    mf__pcg_seed(&rng, c->seed, 0x676fu);
    every = c->rays / 100 > 0 ? c->rays / 100 : 1;
    for (r = 0; r < c->rays; ++r) {
        double o[3], d[3], w = 1.0;
        long skip = -1;
        int hits = 0, done = 0;
        mf_vec3 dir = mf_scale(wi, MF_R(-1.0));
        o[0] = mf__pcg_u01(&rng) * (double)n;
        o[1] = mf__pcg_u01(&rng) * (double)n;
        o[2] = zmax;
        while (!done) {
            double t, sl[2];
            long facet;
            int res;
            d[0] = (double)dir.x; d[1] = (double)dir.y; d[2] = (double)dir.z;
            res = mf__trace(&T, o, d, skip, &t, &facet, sl, &leak);
            if (res == 0) {   /* leaves the surface: record */
                int cell = mf_gonio_cell(g, dir);
                if (cell >= 0) acc[2 * cell + (hits > 1 ? 1 : 0)] += w;
                if (hits > 1) em += w; else e1 += w;
                bounces += (double)hits;
                done = 1;
            } else if (res < 0 || hits >= c->max_bounces) {
                ++lost; el += w; bounces += (double)hits; done = 1;
            } else {
                mf_vec3 m = mf_normalize(mf_vec3_make((mf_real)-sl[0], (mf_real)-sl[1], MF_R(1.0)));
                ++hits;
                o[0] = mf__wrap(o[0] + t * d[0], n);
                o[1] = mf__wrap(o[1] + t * d[1], n);
                o[2] = o[2] + t * d[2];
                skip = facet;
                w *= (double)c->albedo;
                if (c->facet == MF_FACET_MIRROR) dir = mf_normalize(mf_reflect(mf_scale(dir, MF_R(-1.0)), m));
                else {   /* cosine-distributed about the facet normal */
                    mf_vec3 tt, bb, l;
                    mf_real u1 = mf__u01_real(mf__pcg_u01(&rng)), u2 = mf__u01_real(mf__pcg_u01(&rng));
                    l = mf__sample_cosine(u1, u2);
                    mf_frame(m, &tt, &bb);
                    dir = mf_normalize(mf_add(mf_add(mf_scale(tt, l.x), mf_scale(bb, l.y)), mf_scale(m, l.z)));
                }
                if (!(w > 0.0)) { bounces += (double)hits; done = 1; }   /* absorbed */
            }
        }
        if (c->progress && ((r + 1) % every == 0 || r + 1 == c->rays)) c->progress(r + 1, c->rays, c->ctx);
    }
    for (i = 0; i < (size_t)g->cells; ++i) {
        g->first[i] = (mf_real)(acc[2 * i] / (double)c->rays);
        g->multi[i] = (mf_real)(acc[2 * i + 1] / (double)c->rays);
    }
    g->rays = c->rays; g->lost = lost; g->leaks = leak;
    g->energy_first = (mf_real)(e1 / (double)c->rays);
    g->energy_multi = (mf_real)(em / (double)c->rays);
    g->energy_lost = (mf_real)(el / (double)c->rays);
    g->mean_bounces = (mf_real)(bounces / (double)c->rays);
    MF_FREE(h); MF_FREE(top); MF_FREE(acc);
    return MF_SUCCESS;
}
#endif /* MF_NO_MICROSURFACE */
static const float *mf__energy_data(int *n)
{
    static const float data[2 * 64 * 65] = {
/* GGX */
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
0.930986f,0.892072f,0.964554f,0.992819f,0.997676f,0.999057f,0.999474f,0.999893f,0.999938f,0.999962f,0.999975f,
0.999983f,0.999988f,0.999991f,0.999994f,0.999995f,0.999996f,0.999997f,0.999998f,0.999998f,0.999998f,0.999999f,
0.999999f,0.999999f,0.999999f,0.999999f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
0.979766f,0.952605f,0.892072f,0.922227f,0.964554f,0.984644f,0.992819f,0.996329f,0.997676f,0.998796f,0.999058f,
0.999254f,0.999474f,0.999841f,0.999893f,0.99992f,0.999939f,0.999952f,0.999962f,0.999969f,0.999975f,0.99998f,
0.999983f,0.999986f,0.999988f,0.99999f,0.999991f,0.999993f,0.999994f,0.999995f,0.999995f,0.999996f,0.999996f,
0.999997f,0.999997f,0.999998f,0.999998f,0.999998f,0.999998f,0.999999f,0.999999f,0.999999f,0.999999f,0.999999f,
0.999999f,0.999999f,0.999999f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999995f,
0.990845f,0.977474f,0.925152f,0.892071f,0.906018f,0.938689f,0.964553f,0.979833f,0.98816f,0.992818f,0.995201f,
0.996895f,0.997676f,0.998613f,0.998906f,0.999058f,0.999204f,0.999328f,0.999475f,0.999728f,0.999867f,0.999894f,
0.999913f,0.999928f,0.99994f,0.999949f,0.999957f,0.999963f,0.999968f,0.999973f,0.999976f,0.999979f,0.999982f,
0.999984f,0.999986f,0.999988f,0.999989f,0.99999f,0.999992f,0.999993f,0.999993f,0.999994f,0.999995f,0.999995f,
0.999996f,0.999996f,0.999997f,0.999997f,0.999997f,0.999998f,0.999998f,0.999998f,0.999999f,0.999999f,0.999999f,
0.999999f,0.999999f,0.999999f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999975f,
0.994801f,0.9871f,0.952604f,0.912812f,0.892069f,0.899241f,0.922223f,0.946198f,0.964552f,0.97681f,0.984641f,
0.989615f,0.992818f,0.994717f,0.99633f,0.997087f,0.997678f,0.99843f,0.998797f,0.998952f,0.99906f,0.999164f,
0.999257f,0.999365f,0.999476f,0.99964f,0.999846f,0.999878f,0.999897f,0.999912f,0.999924f,0.999934f,0.999942f,
0.99995f,0.999956f,0.999961f,0.999966f,0.99997f,0.999973f,0.999976f,0.999979f,0.999981f,0.999983f,0.999985f,
0.999987f,0.999988f,0.99999f,0.999991f,0.999992f,0.999993f,0.999994f,0.999995f,0.999995f,0.999996f,0.999997f,
0.999997f,0.999998f,0.999998f,0.999998f,0.999999f,0.999999f,0.999999f,1.0f,1.0f,0.999927f,
0.996652f,0.99168f,0.968297f,0.935874f,0.906512f,0.892064f,0.895944f,0.912226f,0.932258f,0.950342f,0.964548f,
0.974768f,0.981964f,0.986851f,0.990339f,0.992816f,0.994404f,0.995702f,0.996705f,0.997214f,0.997681f,0.998244f,
0.998705f,0.998868f,0.998979f,0.999064f,0.999131f,0.999229f,0.999304f,0.999388f,0.99948f,0.99961f,0.999823f,
0.999869f,0.999889f,0.999903f,0.999915f,0.999925f,0.999934f,0.999942f,0.999948f,0.999954f,0.999959f,0.999964f,
0.999968f,0.999972f,0.999975f,0.999978f,0.99998f,0.999983f,0.999985f,0.999987f,0.999988f,0.99999f,0.999992f,
0.999993f,0.999994f,0.999995f,0.999996f,0.999997f,0.999998f,0.999999f,0.999999f,1.0f,0.999832f,
0.997678f,0.994186f,0.977471f,0.952599f,0.925142f,0.902813f,0.892055f,0.894199f,0.905991f,0.922206f,0.938667f,
0.95301f,0.96454f,0.973313f,0.97983f,0.984627f,0.988165f,0.990751f,0.992814f,0.994192f,0.995214f,0.99633f,
0.996871f,0.997299f,0.997686f,0.998119f,0.998616f,0.99879f,0.998902f,0.998993f,0.999068f,0.999129f,0.999187f,
0.999266f,0.999333f,0.999405f,0.999488f,0.999606f,0.999804f,0.999867f,0.999888f,0.999902f,0.999914f,0.999924f,
0.999933f,0.999941f,0.999947f,0.999954f,0.999959f,0.999964f,0.999968f,0.999972f,0.999976f,0.999979f,0.999982f,
0.999985f,0.999987f,0.99999f,0.999992f,0.999994f,0.999995f,0.999997f,0.999999f,1.0f,0.999667f,
0.998295f,0.995707f,0.983214f,0.963932f,0.94067f,0.917832f,0.900408f,0.892039f,0.89321f,0.901944f,0.915005f,
0.929399f,0.943002f,0.95482f,0.964528f,0.972187f,0.978157f,0.98276f,0.986263f,0.989035f,0.991059f,0.992812f,
0.99403f,0.994928f,0.995922f,0.99659f,0.997014f,0.997356f,0.997685f,0.998036f,0.998509f,0.99871f,0.998822f,
0.998905f,0.998973f,0.999058f,0.999125f,0.999175f,0.99922f,0.999294f,0.999356f,0.999423f,0.999505f,0.999618f,
0.999814f,0.999876f,0.999896f,0.99991f,0.999922f,0.999932f,0.99994f,0.999948f,0.999955f,0.999961f,0.999967f,
0.999972f,0.999977f,0.999981f,0.999985f,0.999988f,0.999992f,0.999995f,0.999997f,1.0f,0.999404f,
0.998695f,0.996703f,0.987091f,0.971884f,0.952578f,0.931758f,0.912766f,0.898807f,0.892012f,0.892572f,0.899167f,
0.909754f,0.922159f,0.934642f,0.946118f,0.956132f,0.964506f,0.971311f,0.976803f,0.981171f,0.984606f,0.987347f,
0.98958f,0.991264f,0.992806f,0.99388f,0.994712f,0.995522f,0.9963f,0.996773f,0.997104f,0.99737f,0.997658f,
0.997983f,0.998457f,0.998675f,0.99879f,0.998872f,0.998939f,0.998996f,0.999046f,0.99909f,0.999145f,0.99921f,
0.999251f,0.999316f,0.999376f,0.999446f,0.999541f,0.99967f,0.99986f,0.999899f,0.999917f,0.99993f,0.999941f,
0.99995f,0.999959f,0.999966f,0.999973f,0.999979f,0.999985f,0.99999f,0.999995f,0.999999f,0.999014f,
0.998968f,0.997395f,0.989753f,0.977445f,0.961399f,0.943319f,0.925077f,0.909121f,0.897648f,0.891966f,0.892132f,
0.897198f,0.905886f,0.916483f,0.927729f,0.938553f,0.948435f,0.957123f,0.964471f,0.970586f,0.975663f,0.979797f,
0.983127f,0.985919f,0.988145f,0.989979f,0.991406f,0.992786f,0.993765f,0.994528f,0.995212f,0.99603f,0.996535f,
0.996848f,0.997139f,0.997402f,0.997673f,0.997953f,0.998378f,0.9986f,0.99872f,0.998803f,0.998868f,0.998924f,
0.998972f,0.999014f,0.999062f,0.999123f,0.99917f,0.999205f,0.999273f,0.999319f,0.999398f,0.999492f,0.999627f,
0.999862f,0.999918f,0.999939f,0.999953f,0.999964f,0.999974f,0.999983f,0.999991f,0.999998f,0.998456f,
0.999163f,0.997888f,0.991657f,0.981516f,0.968222f,0.952502f,0.935748f,0.919862f,0.906352f,0.896735f,0.891886f,
0.891792f,0.895748f,0.902941f,0.912039f,0.92204f,0.932066f,0.941558f,0.950216f,0.957875f,0.964404f,0.969993f,
0.974708f,0.97861f,0.981839f,0.984591f,0.986816f,0.988739f,0.990251f,0.991499f,0.992753f,0.99363f,0.994334f,
0.994992f,0.995722f,0.996285f,0.996656f,0.996929f,0.997152f,0.997395f,0.997647f,0.997915f,0.998321f,0.998548f,
0.998664f,0.998741f,0.9988f,0.998849f,0.998893f,0.998935f,0.998976f,0.999015f,0.999052f,0.999087f,0.999147f,
0.999189f,0.999265f,0.99935f,0.999482f,0.999786f,0.999933f,0.999964f,0.999981f,0.999994f,0.997688f,
0.999307f,0.998251f,0.993068f,0.984611f,0.973351f,0.959683f,0.944858f,0.929696f,0.915657f,0.904146f,0.895946f,
0.891738f,0.891467f,0.894598f,0.900609f,0.908428f,0.9173f,0.926505f,0.935471f,0.943933f,0.951608f,0.958412f,
0.964323f,0.969463f,0.973847f,0.977542f,0.980659f,0.983334f,0.985612f,0.987465f,0.989128f,0.990417f,0.991559f,
0.992715f,0.993527f,0.994148f,0.994731f,0.995401f,0.996033f,0.996423f,0.996688f,0.996928f,0.997144f,0.997351f,
0.997585f,0.997859f,0.998265f,0.998458f,0.998563f,0.998626f,0.998664f,0.998712f,0.998751f,0.998783f,0.998811f,
0.998837f,0.998864f,0.998894f,0.998927f,0.998968f,0.999037f,0.999159f,0.999599f,0.999962f,0.99664f,
0.999415f,0.998525f,0.994132f,0.986984f,0.97728f,0.965508f,0.952243f,0.938209f,0.924642f,0.912246f,0.902234f,
0.895145f,0.891438f,0.891046f,0.893565f,0.898629f,0.905407f,0.913266f,0.921656f,0.93007f,0.938174f,0.945731f,
0.952622f,0.958766f,0.964187f,0.968908f,0.973025f,0.976544f,0.979545f,0.982157f,0.98441f,0.986285f,0.987943f,
0.989389f,0.990496f,0.991593f,0.992618f,0.993361f,0.993962f,0.994482f,0.995045f,0.995689f,0.996114f,0.996401f,
0.996613f,0.996824f,0.997016f,0.997206f,0.997436f,0.997729f,0.998109f,0.998249f,0.998327f,0.998366f,0.998389f,
0.998402f,0.9984f,0.9984f,0.998381f,0.998349f,0.998306f,0.998226f,0.998054f,0.996827f,0.995199f,
0.999499f,0.998736f,0.994959f,0.988813f,0.980368f,0.970122f,0.9582f,0.945548f,0.932517f,0.920223f,0.909228f,
0.90038f,0.894162f,0.890809f,0.890319f,0.892349f,0.896622f,0.902527f,0.90952f,0.91716f,0.924974f,0.93266f,
0.940049f,0.94688f,0.95315f,0.958742f,0.96376f,0.968166f,0.972009f,0.975361f,0.978297f,0.980832f,0.983003f,
0.984942f,0.986574f,0.988103f,0.989322f,0.99033f,0.991334f,0.992241f,0.992916f,0.993463f,0.993965f,0.994475f,
0.995108f,0.995522f,0.995779f,0.995994f,0.996163f,0.996316f,0.996464f,0.996629f,0.996834f,0.997201f,0.997385f,
0.997406f,0.997349f,0.997231f,0.997038f,0.996756f,0.996706f,0.996747f,0.996784f,0.996817f,0.993227f,
0.999564f,0.998901f,0.995604f,0.990246f,0.982828f,0.973771f,0.963138f,0.95158f,0.93942f,0.927421f,0.916139f,
0.906299f,0.898334f,0.89275f,0.889599f,0.888928f,0.890455f,0.893986f,0.899044f,0.905144f,0.911987f,0.919129f,
0.926284f,0.933296f,0.939927f,0.946134f,0.951782f,0.956899f,0.961487f,0.965578f,0.96914f,0.97233f,0.975148f,
0.9776f,0.979734f,0.981698f,0.983361f,0.984833f,0.986195f,0.987321f,0.988293f,0.989298f,0.990175f,0.990837f,
0.991389f,0.991908f,0.992435f,0.993107f,0.993582f,0.993915f,0.994191f,0.99441f,0.994634f,0.994848f,0.995088f,
0.99538f,0.995859f,0.996258f,0.996438f,0.996547f,0.996626f,0.996691f,0.996747f,0.996796f,0.990617f,
0.999616f,0.999032f,0.99612f,0.991382f,0.984836f,0.976694f,0.967215f,0.956542f,0.945346f,0.933747f,0.922661f,
0.912216f,0.903255f,0.895945f,0.890944f,0.888179f,0.887571f,0.888899f,0.892006f,0.896498f,0.901994f,0.908268f,
0.914902f,0.921655f,0.928382f,0.934884f,0.941017f,0.946739f,0.951977f,0.95677f,0.961092f,0.964938f,0.968385f,
0.971489f,0.974237f,0.976676f,0.978858f,0.980746f,0.982442f,0.983898f,0.985311f,0.986485f,0.987472f,0.988387f,
0.989366f,0.99016f,0.990773f,0.991299f,0.991794f,0.992318f,0.992998f,0.993479f,0.993803f,0.99407f,0.994297f,
0.99451f,0.994725f,0.994989f,0.995323f,0.995955f,0.996372f,0.996555f,0.996666f,0.996748f,0.988755f,
0.999657f,0.999136f,0.996535f,0.992297f,0.986444f,0.979071f,0.970503f,0.960684f,0.950283f,0.93936f,0.928407f,
0.918011f,0.908824f,0.901054f,0.894772f,0.890401f,0.887854f,0.887202f,0.888297f,0.890971f,0.894917f,0.899816f,
0.905527f,0.91163f,0.917925f,0.924316f,0.930569f,0.936554f,0.942231f,0.947486f,0.952368f,0.956827f,0.960837f,
0.964491f,0.967812f,0.970762f,0.973429f,0.975807f,0.97792f,0.979803f,0.981513f,0.982978f,0.984331f,0.98562f,
0.986657f,0.987554f,0.988437f,0.989384f,0.99008f,0.990655f,0.991153f,0.991634f,0.992179f,0.992871f,0.993326f,
0.993644f,0.993889f,0.994104f,0.994318f,0.994556f,0.994872f,0.995528f,0.996342f,0.99661f,0.986516f,
0.999691f,0.99922f,0.996873f,0.993031f,0.987739f,0.981005f,0.973169f,0.964204f,0.954378f,0.944133f,0.933715f,
0.924036f,0.914787f,0.906448f,0.899404f,0.893707f,0.889739f,0.887376f,0.88671f,0.887605f,0.889913f,0.893385f,
0.897799f,0.902989f,0.908587f,0.914477f,0.920504f,0.926486f,0.932286f,0.937881f,0.9431f,0.948026f,0.952543f,
0.956713f,0.960535f,0.964002f,0.967189f,0.970017f,0.972556f,0.974861f,0.976919f,0.978813f,0.980518f,0.982018f,
0.983328f,0.984622f,0.985726f,0.986668f,0.987519f,0.988449f,0.989265f,0.989898f,0.990418f,0.990895f,0.99138f,
0.992006f,0.992646f,0.993031f,0.993291f,0.993488f,0.993662f,0.993838f,0.994141f,0.995881f,0.983814f,
0.999717f,0.999288f,0.997146f,0.993623f,0.988782f,0.982605f,0.975332f,0.967064f,0.957798f,0.948311f,0.938906f,
0.929414f,0.920378f,0.91175f,0.904173f,0.897699f,0.892512f,0.888864f,0.886658f,0.885987f,0.886713f,0.888709f,
0.891782f,0.895771f,0.900487f,0.905644f,0.911142f,0.916814f,0.922533f,0.928138f,0.933583f,0.938759f,0.94365f,
0.948224f,0.952464f,0.956428f,0.960061f,0.963344f,0.966361f,0.969107f,0.971599f,0.973833f,0.975872f,0.977703f,
0.979349f,0.980882f,0.982203f,0.983441f,0.98463f,0.985595f,0.986443f,0.987258f,0.988171f,0.988876f,0.989411f,
0.989867f,0.990305f,0.990804f,0.991544f,0.991979f,0.992153f,0.992142f,0.991851f,0.989633f,0.980463f,
0.999739f,0.999342f,0.997365f,0.994104f,0.989622f,0.983912f,0.977097f,0.969376f,0.960694f,0.952158f,0.943346f,
0.934213f,0.925339f,0.916819f,0.908807f,0.901829f,0.8958f,0.891057f,0.887642f,0.885591f,0.884872f,0.885438f,
0.887169f,0.889907f,0.893495f,0.897794f,0.902549f,0.907668f,0.913021f,0.918456f,0.923861f,0.929146f,0.934232f,
0.939069f,0.943663f,0.947978f,0.952028f,0.955743f,0.959164f,0.962307f,0.965184f,0.967835f,0.970218f,0.972422f,
0.974402f,0.976228f,0.977833f,0.979336f,0.980648f,0.981837f,0.983024f,0.983998f,0.984818f,0.985576f,0.986435f,
0.987153f,0.987647f,0.988002f,0.988265f,0.988536f,0.989065f,0.989082f,0.989109f,0.989409f,0.976428f,
0.999756f,0.999386f,0.997541f,0.994488f,0.990293f,0.984958f,0.978521f,0.971232f,0.963483f,0.955433f,0.947124f,
0.938485f,0.929707f,0.921313f,0.913216f,0.905762f,0.899239f,0.893574f,0.88917f,0.885933f,0.883944f,0.88314f,
0.883548f,0.885008f,0.88739f,0.890621f,0.894503f,0.898869f,0.903603f,0.908619f,0.913767f,0.918932f,0.924013f,
0.928976f,0.93372f,0.938291f,0.942647f,0.946707f,0.950466f,0.953985f,0.957262f,0.960244f,0.963007f,0.965521f,
0.967797f,0.969911f,0.971804f,0.973529f,0.975054f,0.976503f,0.977749f,0.978822f,0.979912f,0.980809f,0.981514f,
0.982124f,0.982855f,0.983776f,0.984544f,0.985176f,0.985785f,0.986577f,0.988046f,0.98888f,0.971446f,
0.99977f,0.999421f,0.997681f,0.994792f,0.990828f,0.985785f,0.979662f,0.972705f,0.96582f,0.958243f,0.950297f,
0.942081f,0.933585f,0.92523f,0.917189f,0.909441f,0.902445f,0.89624f,0.890896f,0.886698f,0.883524f,0.881516f,
0.880606f,0.880757f,0.881897f,0.883902f,0.886709f,0.890128f,0.894047f,0.89834f,0.902961f,0.907745f,0.912579f,
0.917408f,0.922124f,0.926728f,0.931228f,0.935496f,0.939527f,0.943366f,0.94698f,0.950412f,0.95362f,0.95658f,
0.959353f,0.961899f,0.964244f,0.966425f,0.968435f,0.970306f,0.972009f,0.973622f,0.975066f,0.976362f,0.977701f,
0.978908f,0.979921f,0.98084f,0.981878f,0.982971f,0.983748f,0.984347f,0.984967f,0.987182f,0.966216f,
0.999781f,0.999448f,0.99779f,0.995029f,0.991242f,0.986426f,0.980578f,0.97419f,0.967747f,0.960621f,0.952969f,
0.945097f,0.936937f,0.928605f,0.920597f,0.912807f,0.905363f,0.898694f,0.892717f,0.887577f,0.883473f,0.880315f,
0.878238f,0.877256f,0.877485f,0.878604f,0.88054f,0.883213f,0.886483f,0.890216f,0.894352f,0.898808f,0.903435f,
0.908186f,0.912907f,0.91759f,0.922267f,0.926764f,0.93109f,0.935227f,0.93916f,0.942899f,0.946389f,0.949688f,
0.952777f,0.955635f,0.958299f,0.960784f,0.963061f,0.965221f,0.967195f,0.969016f,0.970701f,0.972288f,0.973748f,
0.975026f,0.976339f,0.977545f,0.978531f,0.979401f,0.980496f,0.98144f,0.981771f,0.979725f,0.96129f,
0.999789f,0.999468f,0.997872f,0.995212f,0.991554f,0.986911f,0.98127f,0.975441f,0.969322f,0.962564f,0.9552f,
0.94758f,0.939691f,0.931538f,0.923471f,0.915648f,0.908022f,0.900848f,0.89439f,0.888775f,0.884326f,0.880793f,
0.878146f,0.876484f,0.875721f,0.875859f,0.876823f,0.878541f,0.880965f,0.883946f,0.887371f,0.891246f,0.895422f,
0.899822f,0.904291f,0.908805f,0.913393f,0.917918f,0.922317f,0.926594f,0.93071f,0.934661f,0.938403f,0.94197f,
0.945312f,0.948454f,0.951423f,0.95418f,0.956755f,0.959145f,0.961371f,0.963434f,0.965342f,0.967132f,0.968741f,
0.970279f,0.971651f,0.972846f,0.974078f,0.975115f,0.975825f,0.976345f,0.977037f,0.977725f,0.95573f,
0.999795f,0.999483f,0.997931f,0.995343f,0.991778f,0.987256f,0.981767f,0.976455f,0.970589f,0.964124f,0.957073f,
0.949599f,0.941915f,0.933965f,0.925847f,0.917959f,0.910238f,0.903057f,0.89683f,0.891221f,0.886182f,0.881981f,
0.878608f,0.876066f,0.874405f,0.873594f,0.873628f,0.874405f,0.875932f,0.878096f,0.880799f,0.883955f,0.887551f,
0.891464f,0.895577f,0.899783f,0.904169f,0.908574f,0.912921f,0.917209f,0.921403f,0.925471f,0.929396f,0.933135f,
0.936699f,0.940087f,0.943282f,0.946264f,0.94909f,0.951699f,0.954151f,0.956442f,0.958527f,0.960468f,0.962245f,
0.963893f,0.965331f,0.966698f,0.967846f,0.968797f,0.969955f,0.971309f,0.972579f,0.975195f,0.949167f,
0.999799f,0.999493f,0.997971f,0.995433f,0.991927f,0.987479f,0.982376f,0.977271f,0.97159f,0.965351f,0.958546f,
0.951207f,0.94366f,0.935853f,0.927808f,0.919793f,0.912701f,0.905851f,0.899278f,0.893348f,0.887927f,0.883069f,
0.879044f,0.875765f,0.873239f,0.871554f,0.870664f,0.870541f,0.871126f,0.872418f,0.874313f,0.876708f,0.879575f,
0.882889f,0.886491f,0.890274f,0.89428f,0.898418f,0.902583f,0.906756f,0.910889f,0.91497f,0.91892f,0.922764f,
0.926448f,0.929973f,0.933336f,0.936502f,0.939517f,0.942322f,0.944988f,0.947477f,0.949769f,0.951964f,0.954017f,
0.956072f,0.95811f,0.960045f,0.96182f,0.963604f,0.965144f,0.966736f,0.968167f,0.968605f,0.941738f,
0.999801f,0.999498f,0.997993f,0.995482f,0.992006f,0.987598f,0.98285f,0.977914f,0.972358f,0.966283f,0.959657f,
0.952472f,0.944962f,0.937245f,0.929305f,0.922041f,0.915004f,0.908114f,0.901391f,0.895088f,0.889311f,0.884f,
0.879297f,0.875353f,0.872063f,0.869526f,0.867759f,0.866713f,0.8664f,0.866749f,0.867768f,0.869353f,0.871399f,
0.873988f,0.87696f,0.880203f,0.883705f,0.887449f,0.891333f,0.895289f,0.899323f,0.903358f,0.90743f,0.911472f,
0.91542f,0.919262f,0.92297f,0.92652f,0.929935f,0.933193f,0.936299f,0.939251f,0.942025f,0.944689f,0.947167f,
0.949519f,0.951736f,0.953798f,0.955718f,0.957512f,0.959161f,0.960578f,0.961605f,0.962668f,0.9341f,
0.999801f,0.9995f,0.997999f,0.995496f,0.992023f,0.98762f,0.983196f,0.978383f,0.972918f,0.966946f,0.960443f,
0.953387f,0.945882f,0.938198f,0.931099f,0.923968f,0.916819f,0.909867f,0.903046f,0.896425f,0.890275f,0.884575f,
0.879312f,0.874707f,0.870744f,0.867395f,0.864819f,0.862913f,0.861753f,0.861316f,0.861749f,0.862828f,0.864398f,
0.866474f,0.869042f,0.871941f,0.875121f,0.878628f,0.882308f,0.886138f,0.890073f,0.894068f,0.898081f,0.902069f,
0.906011f,0.909883f,0.913657f,0.91732f,0.920862f,0.924268f,0.927513f,0.93061f,0.933575f,0.936384f,0.938997f,
0.941502f,0.94382f,0.945973f,0.947965f,0.949775f,0.951406f,0.952792f,0.9547f,0.957356f,0.926232f,
0.999801f,0.999498f,0.99799f,0.995478f,0.991982f,0.987553f,0.983427f,0.978694f,0.973286f,0.96737f,0.960936f,
0.953952f,0.946451f,0.939319f,0.932458f,0.92541f,0.918179f,0.911108f,0.904175f,0.897379f,0.890808f,0.884708f,
0.879015f,0.873798f,0.869254f,0.865658f,0.862796f,0.860586f,0.859021f,0.858104f,0.857788f,0.85811f,0.85898f,
0.860305f,0.862217f,0.864492f,0.867115f,0.870092f,0.873329f,0.87677f,0.880365f,0.884102f,0.887893f,0.891733f,
0.895569f,0.899384f,0.903127f,0.906807f,0.91038f,0.913844f,0.917171f,0.920374f,0.923446f,0.926355f,0.929095f,
0.931708f,0.934156f,0.936458f,0.938696f,0.941034f,0.943371f,0.945578f,0.947508f,0.947937f,0.917439f,
0.999798f,0.999492f,0.997969f,0.99543f,0.99189f,0.98755f,0.983553f,0.978863f,0.973488f,0.967577f,0.961165f,
0.954197f,0.946905f,0.940212f,0.933388f,0.926373f,0.919139f,0.911866f,0.904777f,0.897808f,0.890928f,0.884421f,
0.878625f,0.873607f,0.869007f,0.865006f,0.861548f,0.858669f,0.856408f,0.854753f,0.853704f,0.853229f,0.85336f,
0.853956f,0.855111f,0.856716f,0.858698f,0.86106f,0.863758f,0.8667f,0.869877f,0.873227f,0.876711f,0.880284f,
0.88392f,0.887582f,0.891224f,0.894855f,0.898416f,0.901929f,0.905353f,0.908715f,0.912015f,0.915312f,0.918507f,
0.921585f,0.924524f,0.927301f,0.929973f,0.932457f,0.93476f,0.93686f,0.93864f,0.941275f,0.908029f,
0.999795f,0.999484f,0.997935f,0.995355f,0.991755f,0.987575f,0.983583f,0.978904f,0.973539f,0.967587f,0.961146f,
0.954158f,0.94748f,0.940766f,0.933918f,0.92689f,0.919625f,0.91218f,0.904883f,0.897725f,0.890807f,0.884641f,
0.878909f,0.87356f,0.8685f,0.863951f,0.859959f,0.856423f,0.853491f,0.851113f,0.849324f,0.84807f,0.847437f,
0.847295f,0.847671f,0.84857f,0.849874f,0.851614f,0.853724f,0.856175f,0.858925f,0.861972f,0.865289f,0.868762f,
0.872342f,0.876009f,0.879708f,0.883433f,0.887132f,0.890804f,0.894421f,0.897969f,0.90142f,0.904772f,0.908008f,
0.911128f,0.914097f,0.916919f,0.919611f,0.922121f,0.92445f,0.926832f,0.929424f,0.931186f,0.898155f,
0.999791f,0.999473f,0.997891f,0.995255f,0.991576f,0.987541f,0.98353f,0.978825f,0.973434f,0.967413f,0.960904f,
0.954052f,0.947747f,0.941009f,0.934077f,0.926987f,0.919643f,0.912094f,0.904532f,0.897629f,0.891192f,0.884798f,
0.878691f,0.87299f,0.867564f,0.862449f,0.857914f,0.853805f,0.85019f,0.84714f,0.844642f,0.842712f,0.841419f,
0.840849f,0.840818f,0.841289f,0.842207f,0.843534f,0.845262f,0.847325f,0.849707f,0.852358f,0.855242f,0.858317f,
0.861557f,0.864907f,0.868343f,0.871852f,0.87538f,0.878915f,0.882425f,0.885891f,0.889303f,0.892631f,0.895874f,
0.899018f,0.902072f,0.905042f,0.908077f,0.911082f,0.913882f,0.916523f,0.918873f,0.921211f,0.887781f,
0.999785f,0.999459f,0.997836f,0.995132f,0.991355f,0.98745f,0.983396f,0.978639f,0.973187f,0.967074f,0.960452f,
0.954058f,0.947728f,0.940962f,0.933894f,0.926691f,0.919236f,0.911566f,0.904315f,0.897654f,0.891046f,0.884456f,
0.877962f,0.871892f,0.866084f,0.860509f,0.855406f,0.850799f,0.84674f,0.843548f,0.840819f,0.838606f,0.836885f,
0.83569f,0.834963f,0.834742f,0.83497f,0.835627f,0.836697f,0.83814f,0.839929f,0.842028f,0.844398f,0.847003f,
0.849814f,0.852793f,0.855917f,0.859143f,0.862466f,0.865832f,0.869262f,0.87272f,0.876263f,0.879795f,0.883259f,
0.886658f,0.88997f,0.893169f,0.896244f,0.899189f,0.901969f,0.904677f,0.907523f,0.910071f,0.876756f,
0.999779f,0.999443f,0.997771f,0.994987f,0.991096f,0.987307f,0.983186f,0.97835f,0.972807f,0.966576f,0.959818f,
0.953836f,0.947445f,0.940605f,0.933386f,0.926023f,0.918422f,0.911091f,0.904103f,0.897196f,0.890377f,0.883564f,
0.876766f,0.870263f,0.864082f,0.858183f,0.853075f,0.848517f,0.844287f,0.840505f,0.837175f,0.834321f,0.831934f,
0.830049f,0.828633f,0.827692f,0.82723f,0.8272f,0.827611f,0.828429f,0.829636f,0.831213f,0.833145f,0.835452f,
0.838008f,0.840764f,0.843706f,0.846773f,0.84997f,0.853243f,0.856597f,0.859964f,0.863354f,0.866724f,0.870071f,
0.873376f,0.876628f,0.879815f,0.882991f,0.886212f,0.889296f,0.892186f,0.895024f,0.897776f,0.865228f,
0.999772f,0.999424f,0.997698f,0.994822f,0.990801f,0.987116f,0.982906f,0.977966f,0.972303f,0.965937f,0.959437f,
0.953408f,0.946911f,0.939958f,0.932586f,0.925017f,0.917489f,0.910578f,0.903463f,0.896272f,0.889211f,0.882135f,
0.875067f,0.868181f,0.862195f,0.856525f,0.851048f,0.845994f,0.841274f,0.836918f,0.832999f,0.829515f,0.826493f,
0.823957f,0.821916f,0.820452f,0.819597f,0.819172f,0.819163f,0.819558f,0.820327f,0.821453f,0.822902f,0.82465f,
0.826671f,0.828935f,0.831412f,0.834063f,0.836892f,0.839837f,0.842904f,0.846054f,0.849291f,0.85263f,0.856017f,
0.859392f,0.862722f,0.865999f,0.869216f,0.872368f,0.875533f,0.878591f,0.881592f,0.884291f,0.853175f,
0.999763f,0.999404f,0.997615f,0.994636f,0.990473f,0.986878f,0.98256f,0.977492f,0.971682f,0.965153f,0.958938f,
0.952782f,0.946147f,0.939039f,0.931503f,0.923699f,0.916731f,0.909658f,0.902372f,0.894904f,0.887561f,0.880207f,
0.873098f,0.86659f,0.860377f,0.854333f,0.848466f,0.842897f,0.837683f,0.832798f,0.828351f,0.824514f,0.821275f,
0.818453f,0.816064f,0.814097f,0.812573f,0.811477f,0.810791f,0.810516f,0.810637f,0.811132f,0.811983f,0.813177f,
0.8147f,0.816554f,0.818704f,0.821066f,0.823617f,0.826334f,0.829179f,0.832136f,0.835188f,0.838306f,0.841462f,
0.844678f,0.847965f,0.851242f,0.854483f,0.857701f,0.860895f,0.86402f,0.867146f,0.869937f,0.840614f,
0.999754f,0.999381f,0.997525f,0.994433f,0.990265f,0.986597f,0.982154f,0.976938f,0.970953f,0.964233f,0.958285f,
0.951971f,0.94516f,0.937871f,0.93013f,0.92265f,0.915627f,0.90835f,0.900852f,0.893147f,0.885467f,0.878211f,
0.871421f,0.864625f,0.857996f,0.851565f,0.84529f,0.839264f,0.833704f,0.828814f,0.824252f,0.820047f,0.816219f,
0.812783f,0.809758f,0.807153f,0.804988f,0.803271f,0.802049f,0.801333f,0.800998f,0.801031f,0.80142f,0.802145f,
0.803187f,0.80452f,0.80613f,0.807994f,0.810088f,0.812419f,0.814963f,0.817652f,0.820468f,0.823382f,0.826379f,
0.829463f,0.832601f,0.835784f,0.838964f,0.842155f,0.845384f,0.848499f,0.851689f,0.854848f,0.82758f,
0.999745f,0.999357f,0.997427f,0.994212f,0.990063f,0.986276f,0.98169f,0.976303f,0.970119f,0.963507f,0.957489f,
0.950986f,0.943969f,0.936457f,0.928507f,0.921444f,0.914192f,0.906678f,0.898922f,0.890964f,0.883356f,0.876305f,
0.869216f,0.862107f,0.855077f,0.84825f,0.841703f,0.83581f,0.830174f,0.824798f,0.81971f,0.814958f,0.810566f,
0.806593f,0.803192f,0.800236f,0.797677f,0.795508f,0.793735f,0.792362f,0.791378f,0.790793f,0.790617f,0.790834f,
0.791379f,0.792235f,0.793382f,0.794802f,0.796487f,0.798414f,0.800557f,0.802886f,0.805387f,0.808022f,0.810767f,
0.813643f,0.816635f,0.819665f,0.82271f,0.825791f,0.828991f,0.832126f,0.835213f,0.83848f,0.814071f,
0.999734f,0.99933f,0.997321f,0.993973f,0.989835f,0.985918f,0.981171f,0.975591f,0.96919f,0.962762f,0.956555f,
0.949833f,0.942577f,0.934815f,0.927231f,0.919964f,0.912443f,0.904658f,0.896615f,0.888652f,0.881299f,0.873931f,
0.866507f,0.859059f,0.851669f,0.844896f,0.838447f,0.832132f,0.826021f,0.820162f,0.814605f,0.809583f,0.804985f,
0.800708f,0.796781f,0.793227f,0.790066f,0.787373f,0.785121f,0.783241f,0.781749f,0.780637f,0.779916f,0.77956f,
0.779561f,0.779899f,0.780536f,0.781469f,0.78268f,0.784159f,0.785916f,0.787865f,0.790001f,0.792289f,0.794731f,
0.797299f,0.800055f,0.80292f,0.805822f,0.808746f,0.811727f,0.814864f,0.81786f,0.821008f,0.800124f,
0.999723f,0.999302f,0.997208f,0.993719f,0.989583f,0.985523f,0.980598f,0.974807f,0.968166f,0.961906f,0.955489f,
0.948524f,0.940999f,0.932965f,0.925727f,0.918216f,0.910392f,0.902301f,0.893987f,0.886482f,0.87882f,0.871098f,
0.863321f,0.855555f,0.848447f,0.841471f,0.834602f,0.827857f,0.821323f,0.815337f,0.809656f,0.804229f,0.799088f,
0.7943f,0.789997f,0.786041f,0.782442f,0.779245f,0.776441f,0.774046f,0.772027f,0.770371f,0.769091f,0.768207f,
0.767697f,0.767511f,0.767632f,0.768052f,0.768753f,0.769735f,0.770992f,0.772546f,0.774312f,0.776252f,0.778342f,
0.780599f,0.782985f,0.785535f,0.788269f,0.791033f,0.79382f,0.796749f,0.79969f,0.802709f,0.785775f,
0.999711f,0.999272f,0.997087f,0.993448f,0.989309f,0.985092f,0.979974f,0.973953f,0.967051f,0.960945f,0.954298f,
0.94706f,0.939249f,0.931363f,0.923989f,0.916204f,0.908059f,0.899639f,0.891705f,0.883921f,0.875935f,0.867836f,
0.859733f,0.852311f,0.844888f,0.837498f,0.83021f,0.823283f,0.816735f,0.810358f,0.804193f,0.798394f,0.792974f,
0.787838f,0.783061f,0.778655f,0.774618f,0.770924f,0.767616f,0.76475f,0.762225f,0.760054f,0.758231f,0.756764f,
0.755663f,0.754976f,0.754607f,0.754545f,0.754755f,0.755247f,0.755994f,0.757006f,0.758274f,0.759834f,0.761575f,
0.763494f,0.76555f,0.76774f,0.770104f,0.772654f,0.775239f,0.77792f,0.780693f,0.78337f,0.771043f,
0.999698f,0.99924f,0.99696f,0.993163f,0.989012f,0.984627f,0.9793f,0.973032f,0.966104f,0.959885f,0.952985f,
0.945455f,0.937325f,0.929687f,0.922034f,0.913937f,0.905454f,0.89698f,0.889116f,0.880988f,0.872647f,0.864192f,
0.856411f,0.848639f,0.840817f,0.833032f,0.825748f,0.818637f,0.811635f,0.804908f,0.798538f,0.792386f,0.786567f,
0.781081f,0.775881f,0.77105f,0.766613f,0.762486f,0.758677f,0.755227f,0.752215f,0.749595f,0.747297f,0.745327f,
0.743687f,0.742372f,0.741401f,0.740798f,0.740548f,0.740575f,0.74085f,0.741387f,0.742163f,0.743178f,0.744448f,
0.745987f,0.747687f,0.749528f,0.751518f,0.75372f,0.756019f,0.758453f,0.760975f,0.763539f,0.755976f,
0.999685f,0.999207f,0.996827f,0.992863f,0.988694f,0.984129f,0.978579f,0.972048f,0.965194f,0.958729f,0.951553f,
0.943707f,0.935295f,0.927831f,0.919864f,0.911428f,0.902593f,0.894415f,0.886203f,0.877706f,0.868992f,0.860767f,
0.852681f,0.844499f,0.8363f,0.828619f,0.820994f,0.813454f,0.80628f,0.799275f,0.792545f,0.7861f,0.779887f,
0.774068f,0.76852f,0.763238f,0.758279f,0.753784f,0.749599f,0.745717f,0.742146f,0.738915f,0.736072f,0.733661f,
0.731556f,0.72976f,0.728266f,0.727078f,0.726203f,0.72568f,0.725481f,0.725541f,0.72584f,0.726378f,0.727155f,
0.728207f,0.729469f,0.730903f,0.73253f,0.73433f,0.736287f,0.738388f,0.740621f,0.742981f,0.740598f,
0.999671f,0.999172f,0.996687f,0.992548f,0.988355f,0.983598f,0.977812f,0.971003f,0.964211f,0.957479f,0.950007f,
0.941823f,0.933577f,0.925797f,0.917495f,0.908691f,0.899845f,0.891571f,0.882978f,0.87409f,0.865384f,0.857033f,
0.84853f,0.839951f,0.831878f,0.823801f,0.8158f,0.80814f,0.800611f,0.793338f,0.78626f,0.77952f,0.773014f,
0.766719f,0.760799f,0.755241f,0.74992f,0.744871f,0.740147f,0.735878f,0.731926f,0.728265f,0.724908f,0.72187f,
0.719187f,0.716914f,0.71494f,0.713257f,0.71186f,0.710769f,0.709992f,0.709538f,0.709325f,0.709361f,0.709661f,
0.710217f,0.710986f,0.711972f,0.71316f,0.714556f,0.716093f,0.717839f,0.719715f,0.721753f,0.724945f,
0.999657f,0.999135f,0.996541f,0.992219f,0.987997f,0.983037f,0.977001f,0.969899f,0.963157f,0.956141f,0.948352f,
0.939817f,0.931714f,0.923593f,0.914926f,0.905741f,0.897117f,0.888456f,0.879455f,0.870227f,0.861685f,0.852918f,
0.843991f,0.8355f,0.827031f,0.818615f,0.810474f,0.802461f,0.794676f,0.787074f,0.779772f,0.772604f,0.765762f,
0.759256f,0.752927f,0.746837f,0.741157f,0.735818f,0.730722f,0.725896f,0.721384f,0.717303f,0.713532f,0.710038f,
0.706842f,0.703969f,0.701476f,0.699276f,0.697363f,0.695744f,0.694443f,0.693427f,0.692681f,0.692205f,0.691992f,
0.692029f,0.692307f,0.69279f,0.693527f,0.694448f,0.695545f,0.696865f,0.698331f,0.69995f,0.709053f,
0.999642f,0.999097f,0.996389f,0.991877f,0.98762f,0.982446f,0.976148f,0.968739f,0.962035f,0.954716f,0.946592f,
0.93769f,0.929709f,0.921226f,0.912168f,0.902801f,0.894154f,0.885089f,0.875659f,0.866615f,0.85765f,0.848443f,
0.839489f,0.830676f,0.821839f,0.813274f,0.804804f,0.796526f,0.788469f,0.780587f,0.772838f,0.765528f,0.758337f,
0.75132f,0.744723f,0.738393f,0.732265f,0.726385f,0.720923f,0.715758f,0.710835f,0.706199f,0.70194f,0.697992f,
0.694319f,0.690951f,0.68793f,0.685191f,0.682763f,0.68063f,0.678778f,0.67723f,0.675952f,0.674925f,0.674189f,
0.673713f,0.673454f,0.673421f,0.673671f,0.674091f,0.674728f,0.675555f,0.67658f,0.677826f,0.692962f,
0.999626f,0.999058f,0.996231f,0.991522f,0.987224f,0.981827f,0.975254f,0.967612f,0.960848f,0.953211f,0.94473f,
0.935806f,0.927573f,0.918702f,0.909235f,0.900018f,0.890964f,0.881467f,0.8718f,0.8627f,0.853287f,0.843845f,
0.834738f,0.825483f,0.816533f,0.807631f,0.798891f,0.790373f,0.781954f,0.773767f,0.765867f,0.758047f,0.750534f,
0.743352f,0.736304f,0.72948f,0.723091f,0.716905f,0.710944f,0.70533f,0.700023f,0.694965f,0.69023f,0.685794f,
0.681653f,0.677817f,0.674268f,0.671038f,0.668085f,0.665406f,0.663043f,0.660964f,0.659141f,0.657567f,0.656305f,
0.655288f,0.65449f,0.653939f,0.653655f,0.653554f,0.653699f,0.654032f,0.654558f,0.655309f,0.676709f,
0.99961f,0.999017f,0.996067f,0.991195f,0.98681f,0.981179f,0.97432f,0.966657f,0.959596f,0.951625f,0.942769f,
0.93391f,0.925306f,0.916028f,0.906137f,0.897042f,0.887558f,0.877615f,0.868059f,0.858501f,0.848632f,0.839212f,
0.829631f,0.820252f,0.810931f,0.80176f,0.792783f,0.783875f,0.775235f,0.766782f,0.758389f,0.75043f,0.742603f,
0.734907f,0.727627f,0.720537f,0.713633f,0.7071f,0.700793f,0.694742f,0.689005f,0.683537f,0.678359f,0.673456f,
0.66887f,0.664537f,0.660506f,0.656791f,0.65332f,0.650119f,0.64724f,0.644637f,0.642275f,0.640166f,0.638367f,
0.6368f,0.635458f,0.634394f,0.633542f,0.632928f,0.63253f,0.632348f,0.632372f,0.632554f,0.660331f,
0.999593f,0.998974f,0.995898f,0.990952f,0.986378f,0.980503f,0.973347f,0.965656f,0.958284f,0.949962f,0.940712f,
0.931906f,0.922911f,0.913211f,0.903269f,0.893878f,0.883944f,0.873705f,0.864065f,0.854027f,0.844077f,0.834255f,
0.82443f,0.814722f,0.805139f,0.795702f,0.786346f,0.777234f,0.768271f,0.759367f,0.750911f,0.742481f,0.734292f,
0.726426f,0.718671f,0.711246f,0.704039f,0.69708f,0.690391f,0.683975f,0.677807f,0.671945f,0.666316f,0.660987f,
0.655953f,0.651151f,0.646628f,0.64244f,0.638487f,0.634784f,0.63139f,0.628264f,0.625374f,0.622755f,0.620408f,
0.618284f,0.616428f,0.614805f,0.613414f,0.61226f,0.611327f,0.610587f,0.610075f,0.609777f,0.643867f,
0.999576f,0.998931f,0.995723f,0.9907f,0.98593f,0.979801f,0.972335f,0.964608f,0.956914f,0.948222f,0.938568f,
0.9298f,0.920394f,0.910251f,0.900372f,0.890538f,0.880132f,0.869942f,0.859823f,0.849324f,0.839315f,0.829051f,
0.819001f,0.809026f,0.799133f,0.789374f,0.779773f,0.770339f,0.760965f,0.751982f,0.742994f,0.734346f,0.725862f,
0.717551f,0.709555f,0.701734f,0.694178f,0.686872f,0.679803f,0.673009f,0.666428f,0.660184f,0.654141f,0.648358f,
0.64291f,0.63767f,0.632676f,0.628021f,0.62359f,0.619401f,0.615518f,0.611867f,0.608477f,0.605343f,0.602457f,
0.599812f,0.597419f,0.595249f,0.593328f,0.591611f,0.590136f,0.588872f,0.587811f,0.586977f,0.627358f,
0.999558f,0.998885f,0.995542f,0.990438f,0.985464f,0.979073f,0.971286f,0.963516f,0.955486f,0.94641f,0.936625f,
0.927594f,0.917758f,0.90716f,0.897322f,0.887024f,0.876149f,0.865968f,0.855351f,0.84479f,0.834281f,0.823823f,
0.81341f,0.80307f,0.792955f,0.782852f,0.772995f,0.763123f,0.753659f,0.744144f,0.735007f,0.72595f,0.717157f,
0.708546f,0.700185f,0.692041f,0.684117f,0.676469f,0.669009f,0.661874f,0.654901f,0.648251f,0.641832f,0.635621f,
0.629741f,0.624083f,0.618655f,0.613539f,0.608634f,0.604005f,0.599621f,0.595483f,0.591604f,0.587956f,0.584563f,
0.581402f,0.578461f,0.575787f,0.573302f,0.571074f,0.569032f,0.567222f,0.56562f,0.564233f,0.610835f,
0.999539f,0.998839f,0.995356f,0.990167f,0.984982f,0.97832f,0.9702f,0.962381f,0.954001f,0.944528f,0.934726f,
0.925291f,0.915007f,0.904246f,0.894126f,0.883341f,0.872416f,0.86179f,0.850674f,0.840018f,0.829113f,0.818357f,
0.807654f,0.797085f,0.786467f,0.776233f,0.765865f,0.755936f,0.745929f,0.736289f,0.726696f,0.717399f,0.708229f,
0.699319f,0.690615f,0.682149f,0.673858f,0.665884f,0.658062f,0.65055f,0.643242f,0.636152f,0.629378f,0.622785f,
0.616482f,0.610402f,0.604578f,0.598999f,0.593664f,0.588585f,0.583722f,0.579136f,0.574761f,0.570629f,0.56675f,
0.563065f,0.559647f,0.556425f,0.553442f,0.550661f,0.548103f,0.545754f,0.543604f,0.541664f,0.594338f,
0.99952f,0.998791f,0.995165f,0.989887f,0.984484f,0.977541f,0.969078f,0.961203f,0.952461f,0.942577f,0.932751f,
0.922893f,0.912145f,0.901381f,0.890787f,0.879505f,0.868554f,0.857416f,0.846165f,0.835012f,0.823873f,0.812777f,
0.801752f,0.790796f,0.780056f,0.769272f,0.758825f,0.748361f,0.738203f,0.728106f,0.718295f,0.708609f,0.699153f,
0.689889f,0.680875f,0.672061f,0.663468f,0.655098f,0.646982f,0.639045f,0.631425f,0.623963f,0.6168f,0.609843f,
0.603132f,0.596664f,0.590437f,0.584429f,0.57869f,0.573155f,0.567872f,0.562826f,0.557982f,0.553405f,0.549026f,
0.544885f,0.540951f,0.537243f,0.533747f,0.530462f,0.527389f,0.52451f,0.521834f,0.519351f,0.5779f,
0.999501f,0.998742f,0.994969f,0.989598f,0.983971f,0.976739f,0.967924f,0.959984f,0.950867f,0.940558f,0.930699f,
0.920404f,0.909181f,0.898396f,0.887316f,0.875578f,0.864524f,0.85286f,0.841483f,0.829898f,0.818449f,0.807013f,
0.795723f,0.784441f,0.773321f,0.762319f,0.751445f,0.740749f,0.730178f,0.719849f,0.709652f,0.699668f,0.689885f,
0.680303f,0.670975f,0.661778f,0.652911f,0.64416f,0.635733f,0.627454f,0.619465f,0.611672f,0.604125f,0.596803f,
0.589725f,0.582869f,0.576257f,0.569844f,0.563708f,0.557752f,0.552066f,0.546573f,0.54132f,0.536272f,0.531454f,
0.526847f,0.522455f,0.518261f,0.514289f,0.510515f,0.50693f,0.503557f,0.500365f,0.497399f,0.561553f,
0.999481f,0.998692f,0.994767f,0.989301f,0.983442f,0.975912f,0.966984f,0.958725f,0.949221f,0.938474f,0.928573f,
0.917825f,0.906119f,0.895296f,0.883712f,0.871903f,0.860327f,0.848333f,0.8366f,0.824748f,0.812938f,0.801194f,
0.789436f,0.777981f,0.766401f,0.755179f,0.743926f,0.732927f,0.722074f,0.711368f,0.70087f,0.690572f,0.680444f,
0.670595f,0.66086f,0.651432f,0.642158f,0.633143f,0.624339f,0.615742f,0.607397f,0.599267f,0.591377f,0.583709f,
0.576254f,0.569048f,0.562051f,0.555285f,0.548742f,0.542418f,0.536312f,0.530426f,0.524755f,0.5193f,0.514039f,
0.50901f,0.50416f,0.499538f,0.495098f,0.490857f,0.486811f,0.482954f,0.479284f,0.475763f,0.545331f,
0.99946f,0.99864f,0.994561f,0.988996f,0.982899f,0.975062f,0.966033f,0.957429f,0.947524f,0.936545f,0.926375f,
0.915159f,0.903344f,0.892084f,0.879978f,0.868086f,0.855972f,0.843818f,0.831545f,0.81943f,0.80727f,0.795228f,
0.783218f,0.771247f,0.759546f,0.747753f,0.736356f,0.724963f,0.713756f,0.702768f,0.691949f,0.6813f,0.670925f,
0.660685f,0.650684f,0.64091f,0.631303f,0.621979f,0.612845f,0.603937f,0.59526f,0.586797f,0.578559f,0.570563f,
0.562759f,0.555211f,0.54785f,0.540738f,0.533828f,0.527134f,0.520656f,0.514385f,0.508338f,0.502468f,0.496836f,
0.491372f,0.486138f,0.481079f,0.476213f,0.47154f,0.467054f,0.462754f,0.458627f,0.454674f,0.529264f,
0.999439f,0.998587f,0.994349f,0.988682f,0.98234f,0.974189f,0.965053f,0.956094f,0.945777f,0.934713f,0.924107f,
0.91241f,0.900523f,0.888762f,0.876128f,0.864133f,0.85147f,0.839136f,0.826564f,0.814038f,0.801562f,0.789042f,
0.776818f,0.764513f,0.752401f,0.74044f,0.728509f,0.716878f,0.705369f,0.694025f,0.682883f,0.671982f,0.661221f,
0.650675f,0.640388f,0.630251f,0.620366f,0.610706f,0.601258f,0.592023f,0.583047f,0.57426f,0.565702f,0.557381f,
0.549245f,0.541367f,0.533688f,0.526226f,0.518979f,0.511939f,0.505108f,0.498496f,0.492064f,0.485858f,0.479826f,
0.474008f,0.468373f,0.462929f,0.457672f,0.452601f,0.447701f,0.44298f,0.438433f,0.43408f,0.513377f,
0.999418f,0.998533f,0.994133f,0.98836f,0.981768f,0.973294f,0.964046f,0.954722f,0.943981f,0.932825f,0.92177f,
0.90958f,0.89761f,0.885333f,0.872508f,0.860049f,0.847087f,0.834294f,0.821412f,0.808542f,0.795742f,0.782962f,
0.770185f,0.757713f,0.745159f,0.73287f,0.720717f,0.70869f,0.696845f,0.685195f,0.673765f,0.662474f,0.651413f,
0.640602f,0.62995f,0.619531f,0.60934f,0.599373f,0.589617f,0.580065f,0.570789f,0.561686f,0.552822f,0.544188f,
0.53576f,0.527553f,0.519563f,0.511789f,0.504202f,0.496861f,0.48969f,0.482748f,0.475996f,0.469438f,0.463076f,
0.456906f,0.450919f,0.445119f,0.439507f,0.434055f,0.42879f,0.423698f,0.418773f,0.413973f,0.497698f,
0.999396f,0.998478f,0.993912f,0.98803f,0.981181f,0.972376f,0.963012f,0.953313f,0.942138f,0.930883f,0.919367f,
0.90667f,0.894609f,0.881802f,0.868847f,0.855836f,0.84267f,0.82939f,0.816186f,0.802948f,0.789727f,0.776708f,
0.763623f,0.750671f,0.737935f,0.725234f,0.712723f,0.700393f,0.688243f,0.676279f,0.664444f,0.652902f,0.641559f,
0.630387f,0.619448f,0.608732f,0.598239f,0.587976f,0.577903f,0.568076f,0.558494f,0.549104f,0.539943f,0.531008f,
0.522292f,0.513792f,0.505484f,0.497428f,0.489558f,0.481889f,0.474441f,0.467184f,0.460122f,0.453259f,0.446589f,
0.440096f,0.433794f,0.427679f,0.421727f,0.415955f,0.410357f,0.404923f,0.399651f,0.394566f,0.482252f,
0.999373f,0.998421f,0.993686f,0.987692f,0.98058f,0.971437f,0.961952f,0.951868f,0.940247f,0.928889f,0.916899f,
0.903835f,0.891522f,0.878173f,0.865077f,0.851499f,0.838115f,0.824502f,0.810907f,0.797351f,0.78377f,0.770251f,
0.756969f,0.743628f,0.730463f,0.717503f,0.704663f,0.692007f,0.679508f,0.667187f,0.655152f,0.643268f,0.631569f,
0.620117f,0.608881f,0.597866f,0.58709f,0.576524f,0.566148f,0.55606f,0.54618f,0.536514f,0.527076f,0.517852f,
0.508857f,0.500095f,0.491521f,0.48316f,0.475025f,0.467088f,0.459354f,0.451815f,0.444482f,0.437344f,0.430373f,
0.42361f,0.417025f,0.410612f,0.404375f,0.398309f,0.392416f,0.386687f,0.381115f,0.375701f,0.467056f,
0.999351f,0.998364f,0.993455f,0.987346f,0.979965f,0.970477f,0.960865f,0.950389f,0.938311f,0.926843f,0.914367f,
0.901177f,0.888351f,0.874453f,0.861201f,0.847201f,0.833429f,0.819473f,0.805501f,0.791582f,0.777743f,0.763836f,
0.750105f,0.736552f,0.723043f,0.7097f,0.696517f,0.683509f,0.670738f,0.658153f,0.645719f,0.633499f,0.621543f,
0.609798f,0.598263f,0.586973f,0.575905f,0.565034f,0.554404f,0.544028f,0.533881f,0.523953f,0.514256f,0.504772f,
0.495489f,0.48647f,0.477652f,0.46904f,0.460643f,0.452447f,0.444458f,0.436687f,0.429094f,0.421683f,0.414483f,
0.407461f,0.400622f,0.393957f,0.387458f,0.381148f,0.374996f,0.369001f,0.363169f,0.357473f,0.452132f,
0.999327f,0.998305f,0.99322f,0.986993f,0.979337f,0.969495f,0.959753f,0.948874f,0.936357f,0.924746f,0.911774f,
0.89845f,0.885099f,0.871006f,0.85722f,0.84298f,0.828675f,0.81441f,0.800103f,0.785712f,0.771538f,0.757411f,
0.743243f,0.729262f,0.71547f,0.70181f,0.688336f,0.675029f,0.66188f,0.648899f,0.636231f,0.62374f,0.611478f,
0.599436f,0.587629f,0.576049f,0.564678f,0.553546f,0.542674f,0.532022f,0.521595f,0.511417f,0.50148f,0.491754f,
0.482244f,0.472964f,0.463897f,0.455047f,0.446422f,0.438014f,0.429797f,0.421775f,0.413962f,0.406341f,0.398912f,
0.391673f,0.384608f,0.377713f,0.371014f,0.364475f,0.358102f,0.351888f,0.345845f,0.339965f,0.437499f,
0.999303f,0.998245f,0.99298f,0.986632f,0.978696f,0.968493f,0.958617f,0.947326f,0.934663f,0.922601f,0.90912f,
0.895657f,0.881768f,0.867496f,0.853139f,0.83865f,0.823983f,0.80931f,0.794646f,0.779976f,0.765222f,0.750798f,
0.736396f,0.72206f,0.707885f,0.693849f,0.68001f,0.666368f,0.652981f,0.639767f,0.626741f,0.613935f,0.601387f,
0.589064f,0.576964f,0.565085f,0.553457f,0.54209f,0.530938f,0.520039f,0.509355f,0.498943f,0.488768f,0.478807f,
0.469078f,0.459579f,0.450305f,0.44125f,0.432396f,0.423756f,0.415346f,0.407135f,0.399117f,0.391304f,0.383688f,
0.376242f,0.368984f,0.36192f,0.355027f,0.348313f,0.341763f,0.335361f,0.329128f,0.323051f,0.423167f,
0.999279f,0.998184f,0.992735f,0.986265f,0.978042f,0.96747f,0.957456f,0.945745f,0.932932f,0.920407f,0.906408f,
0.892798f,0.878361f,0.863901f,0.848961f,0.834212f,0.819174f,0.804099f,0.789049f,0.774087f,0.759086f,0.744067f,
0.729359f,0.714716f,0.70022f,0.685908f,0.671771f,0.657814f,0.644035f,0.630488f,0.617183f,0.60409f,0.591259f,
0.578634f,0.566239f,0.554119f,0.542274f,0.53062f,0.519253f,0.508098f,0.497174f,0.486531f,0.476152f,0.465973f,
0.456014f,0.446288f,0.436843f,0.427608f,0.418569f,0.409754f,0.401161f,0.392779f,0.384595f,0.376589f,0.368783f,
0.361202f,0.3538f,0.346573f,0.339545f,0.332678f,0.325941f,0.319422f,0.313066f,0.306853f,0.409151f,
/* Beckmann */
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
0.939529f,0.914427f,0.997015f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
0.980735f,0.957037f,0.914427f,0.962919f,0.997015f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999999f,
0.991169f,0.978736f,0.934837f,0.914426f,0.941228f,0.981021f,0.997015f,0.999985f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999997f,
0.995074f,0.987383f,0.957037f,0.925831f,0.914425f,0.93079f,0.962918f,0.986124f,0.997016f,0.999927f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999992f,
0.99686f,0.992004f,0.970359f,0.943237f,0.921389f,0.914422f,0.925868f,0.949586f,0.973742f,0.990515f,0.997019f,
0.999831f,0.999996f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999981f,
0.997824f,0.994477f,0.978735f,0.957034f,0.934831f,0.918671f,0.914416f,0.922857f,0.941219f,0.962916f,0.981023f,
0.992484f,0.997023f,0.999714f,0.999985f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999961f,
0.998403f,0.995955f,0.983665f,0.966212f,0.946637f,0.929152f,0.917214f,0.914406f,0.920906f,0.934718f,0.952717f,
0.970325f,0.984363f,0.99354f,0.99703f,0.99959f,0.999962f,0.999998f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999927f,
0.998778f,0.996909f,0.98738f,0.973703f,0.957028f,0.940141f,0.925812f,0.916436f,0.914391f,0.91957f,0.930761f,
0.946579f,0.962908f,0.976887f,0.986146f,0.994179f,0.997041f,0.999468f,0.999929f,0.999994f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999876f,
0.999035f,0.997561f,0.990085f,0.978729f,0.964157f,0.948957f,0.934808f,0.923285f,0.915891f,0.914369f,0.91861f,
0.927962f,0.941179f,0.954976f,0.968932f,0.981031f,0.988839f,0.994601f,0.997057f,0.999354f,0.999886f,0.999985f,
0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999802f,
0.999219f,0.998026f,0.992f,0.982268f,0.970344f,0.957014f,0.943207f,0.930471f,0.921331f,0.915491f,0.914338f,
0.917888f,0.925786f,0.936613f,0.94954f,0.962892f,0.973747f,0.983509f,0.990558f,0.994898f,0.997079f,0.999249f,
0.999838f,0.999972f,0.999997f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999699f,
0.999354f,0.99837f,0.993407f,0.984895f,0.975129f,0.962914f,0.950468f,0.93867f,0.927874f,0.919785f,0.915182f,
0.914296f,0.91732f,0.924064f,0.932994f,0.945088f,0.956518f,0.967963f,0.978158f,0.985084f,0.991724f,0.995119f,
0.997108f,0.999157f,0.999787f,0.999955f,0.999993f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999559f,
0.999457f,0.99863f,0.994471f,0.98737f,0.978715f,0.967948f,0.956989f,0.94518f,0.934746f,0.925727f,0.918534f,
0.91493f,0.914242f,0.916855f,0.922675f,0.930633f,0.941071f,0.951369f,0.962864f,0.971357f,0.981054f,0.986247f,
0.992556f,0.995291f,0.997147f,0.999077f,0.999735f,0.999935f,0.999987f,0.999998f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999373f,
0.999538f,0.998833f,0.995296f,0.989277f,0.981472f,0.972409f,0.962019f,0.951474f,0.941254f,0.931338f,0.923927f,
0.917575f,0.914712f,0.914172f,0.916457f,0.921528f,0.928628f,0.937509f,0.947619f,0.957519f,0.967244f,0.975764f,
0.98303f,0.988201f,0.993176f,0.99543f,0.997196f,0.999012f,0.999686f,0.999912f,0.999979f,0.999996f,0.999999f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.999141f,
0.999601f,0.998994f,0.995948f,0.99078f,0.983639f,0.9759f,0.966144f,0.956947f,0.946537f,0.937751f,0.928993f,
0.922397f,0.91699f,0.914512f,0.914083f,0.9161f,0.920559f,0.926912f,0.93438f,0.944097f,0.952578f,0.962817f,
0.970304f,0.978867f,0.984426f,0.989644f,0.993656f,0.995547f,0.997257f,0.998962f,0.999641f,0.999889f,0.99997f,
0.999993f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.998843f,
0.999652f,0.999123f,0.996472f,0.991984f,0.985553f,0.978683f,0.970279f,0.961328f,0.952171f,0.943077f,0.934615f,
0.927134f,0.921076f,0.916482f,0.914319f,0.913973f,0.915767f,0.919717f,0.925424f,0.932113f,0.940841f,0.94934f,
0.958192f,0.966676f,0.973773f,0.981103f,0.985445f,0.990742f,0.994038f,0.995648f,0.997331f,0.998928f,0.999602f,
0.999866f,0.99996f,0.99999f,0.999998f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.998477f,
0.999694f,0.999229f,0.9969f,0.992964f,0.987341f,0.980939f,0.973619f,0.964885f,0.956884f,0.947694f,0.939919f,
0.931796f,0.925496f,0.919916f,0.916029f,0.914121f,0.913837f,0.915444f,0.918968f,0.924114f,0.930282f,0.937853f,
0.946214f,0.953581f,0.962744f,0.969513f,0.976958f,0.982757f,0.986522f,0.991604f,0.994353f,0.995739f,0.997421f,
0.99891f,0.999571f,0.999845f,0.99995f,0.999986f,0.999997f,0.999999f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.998028f,
0.999729f,0.999317f,0.997254f,0.993773f,0.988811f,0.982792f,0.976356f,0.968552f,0.960761f,0.952657f,0.944404f,
0.93703f,0.929599f,0.924035f,0.918879f,0.915609f,0.91391f,0.913673f,0.915118f,0.91828f,0.922941f,0.92863f,
0.935135f,0.943235f,0.950543f,0.958638f,0.966199f,0.972133f,0.979356f,0.98401f,0.988079f,0.992298f,0.99462f,
0.995823f,0.997526f,0.998909f,0.999549f,0.999828f,0.99994f,0.999981f,0.999995f,0.999999f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.99749f,
0.999758f,0.99939f,0.997549f,0.994448f,0.990035f,0.984334f,0.978627f,0.971723f,0.963986f,0.956791f,0.948648f,
0.941524f,0.934375f,0.927933f,0.922716f,0.917949f,0.915206f,0.913681f,0.913476f,0.914782f,0.917633f,0.921869f,
0.927121f,0.932867f,0.940415f,0.947719f,0.954506f,0.962638f,0.968842f,0.975302f,0.981196f,0.984981f,0.989341f,
0.992872f,0.994852f,0.995902f,0.997649f,0.998926f,0.999538f,0.999815f,0.999932f,0.999978f,0.999994f,0.999998f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.996848f,
0.999783f,0.999452f,0.997799f,0.995017f,0.991065f,0.985884f,0.980531f,0.974376f,0.967103f,0.960265f,0.952982f,
0.945382f,0.938841f,0.931924f,0.92641f,0.921505f,0.917164f,0.914809f,0.913424f,0.913243f,0.914425f,0.917007f,
0.92087f,0.925726f,0.931143f,0.93776f,0.944964f,0.951385f,0.958915f,0.965775f,0.970938f,0.977795f,0.982635f,
0.98575f,0.990376f,0.993358f,0.995058f,0.995979f,0.997789f,0.99896f,0.999538f,0.999808f,0.999927f,0.999975f,
0.999992f,0.999998f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.996085f,
0.999803f,0.999505f,0.998012f,0.995501f,0.991939f,0.987279f,0.982144f,0.976619f,0.970103f,0.963209f,0.95666f,
0.949335f,0.942722f,0.936333f,0.92984f,0.925001f,0.920378f,0.916571f,0.914404f,0.913135f,0.912968f,0.914042f,
0.916389f,0.919922f,0.924416f,0.929519f,0.935298f,0.94229f,0.948784f,0.955157f,0.96249f,0.96825f,0.973887f,
0.97977f,0.983782f,0.98711f,0.991243f,0.993779f,0.995246f,0.996087f,0.997947f,0.999012f,0.99955f,0.999808f,
0.999924f,0.999973f,0.999991f,0.999998f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.995201f,
0.999821f,0.99955f,0.998194f,0.995916f,0.992688f,0.988471f,0.983522f,0.978532f,0.972656f,0.965854f,0.959802f,
0.953175f,0.946095f,0.940207f,0.933974f,0.92829f,0.92368f,0.919315f,0.91599f,0.91398f,0.912808f,0.912649f,
0.913625f,0.915765f,0.919004f,0.92317f,0.927973f,0.933111f,0.939709f,0.946194f,0.951954f,0.959054f,0.965372f,
0.970221f,0.97642f,0.981359f,0.984713f,0.988455f,0.991982f,0.994151f,0.995421f,0.996413f,0.998122f,0.99908f,
0.999573f,0.999814f,0.999925f,0.999973f,0.999991f,0.999998f,0.999999f,1.0f,1.0f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.994173f,
0.999837f,0.999589f,0.998352f,0.996274f,0.993334f,0.989497f,0.984731f,0.980175f,0.974846f,0.96868f,0.962507f,
0.956481f,0.949808f,0.943607f,0.937819f,0.931756f,0.926827f,0.922425f,0.918309f,0.915406f,0.913529f,0.912435f,
0.91228f,0.913169f,0.915124f,0.9181f,0.921965f,0.926485f,0.93135f,0.937241f,0.943631f,0.949508f,0.955588f,
0.962295f,0.967707f,0.972739f,0.978493f,0.982657f,0.985482f,0.989618f,0.992627f,0.994487f,0.995585f,0.996795f,
0.998314f,0.999164f,0.999608f,0.999828f,0.99993f,0.999974f,0.999992f,0.999998f,0.999999f,1.0f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.99299f,
0.999851f,0.999623f,0.998489f,0.996586f,0.993894f,0.990387f,0.986028f,0.981598f,0.976739f,0.971124f,0.964848f,
0.959346f,0.953247f,0.946635f,0.941224f,0.935538f,0.929773f,0.925428f,0.921218f,0.917357f,0.914808f,0.913043f,
0.912012f,0.911857f,0.912665f,0.914456f,0.917195f,0.920783f,0.925035f,0.929689f,0.934917f,0.941106f,0.947033f,
0.95238f,0.95908f,0.964969f,0.969614f,0.975251f,0.980203f,0.983734f,0.986806f,0.99063f,0.993198f,0.994794f,
0.995742f,0.997195f,0.998519f,0.999262f,0.999652f,0.999847f,0.999938f,0.999978f,0.999993f,0.999998f,1.0f,
1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.991637f,
0.999862f,0.999653f,0.998609f,0.996858f,0.994384f,0.991163f,0.987165f,0.982836f,0.978385f,0.973247f,0.967392f,
0.96184f,0.956244f,0.950096f,0.944237f,0.938929f,0.933355f,0.928252f,0.924076f,0.920044f,0.916461f,0.914182f,
0.912511f,0.911533f,0.911373f,0.912108f,0.913751f,0.916275f,0.919608f,0.923607f,0.92805f,0.932778f,0.938638f,
0.94454f,0.949951f,0.955837f,0.962052f,0.967188f,0.971854f,0.97739f,0.981633f,0.984641f,0.9882f,0.99152f,
0.993712f,0.995079f,0.995928f,0.997601f,0.998735f,0.999371f,0.999706f,0.999872f,0.999949f,0.999982f,0.999995f,
0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.9901f,
0.999873f,0.999679f,0.998715f,0.997098f,0.994814f,0.991844f,0.988161f,0.98392f,0.979824f,0.975101f,0.969724f,
0.964023f,0.958869f,0.953201f,0.947081f,0.94195f,0.936706f,0.93128f,0.926791f,0.922753f,0.918894f,0.915638f,
0.913519f,0.911926f,0.910991f,0.910826f,0.91149f,0.912998f,0.915327f,0.918428f,0.922186f,0.926421f,0.930904f,
0.936247f,0.942042f,0.94754f,0.952739f,0.959011f,0.96456f,0.969042f,0.974313f,0.979204f,0.982847f,0.985641f,
0.989468f,0.992315f,0.994182f,0.995347f,0.99647f,0.998006f,0.998956f,0.999487f,0.999764f,0.9999f,0.999962f,
0.999987f,0.999996f,0.999999f,1.0f,1.0f,1.0f,1.0f,1.0f,1.0f,0.988363f,
0.999882f,0.999703f,0.998808f,0.997309f,0.995193f,0.992444f,0.989038f,0.984958f,0.981089f,0.97673f,0.971771f,
0.966204f,0.961178f,0.955935f,0.950216f,0.944645f,0.93972f,0.934548f,0.929379f,0.925353f,0.921445f,0.917761f,
0.914841f,0.912808f,0.911281f,0.910382f,0.910204f,0.910802f,0.912186f,0.914339f,0.917223f,0.920756f,0.924789f,
0.929123f,0.933948f,0.939559f,0.945079f,0.950148f,0.955935f,0.961768f,0.966691f,0.971187f,0.976497f,0.98076f,
0.983891f,0.98716f,0.990607f,0.993035f,0.994615f,0.995599f,0.997097f,0.998401f,0.999178f,0.999606f,0.999825f,
0.99993f,0.999975f,0.999993f,0.999998f,1.0f,1.0f,1.0f,1.0f,1.0f,0.986416f,
0.99989f,0.999723f,0.998891f,0.997496f,0.995529f,0.992975f,0.989814f,0.986023f,0.982206f,0.978166f,0.973574f,
0.968408f,0.963216f,0.958351f,0.953034f,0.947335f,0.942422f,0.937533f,0.932453f,0.927802f,0.923927f,0.920141f,
0.916639f,0.913999f,0.912039f,0.910569f,0.909693f,0.909502f,0.910038f,0.911307f,0.913298f,0.915984f,0.919302f,
0.923137f,0.927321f,0.931757f,0.937098f,0.942583f,0.947761f,0.952934f,0.958863f,0.964149f,0.968511f,0.973616f,
0.978409f,0.982111f,0.984906f,0.98865f,0.99164f,0.993691f,0.995018f,0.996124f,0.997721f,0.998782f,0.999392f,
0.999721f,0.999884f,0.999957f,0.999987f,0.999997f,0.999999f,1.0f,1.0f,1.0f,0.984233f,
0.999897f,0.999742f,0.998964f,0.997663f,0.995828f,0.993447f,0.990502f,0.986973f,0.983197f,0.979438f,0.97517f,
0.970371f,0.965106f,0.960492f,0.955538f,0.950172f,0.944846f,0.940228f,0.935381f,0.930444f,0.926282f,0.922496f,
0.918832f,0.915519f,0.913102f,0.911204f,0.909777f,0.908923f,0.908712f,0.909186f,0.910349f,0.912189f,0.91469f,
0.917808f,0.921454f,0.92548f,0.929719f,0.934674f,0.940053f,0.945298f,0.950144f,0.955911f,0.96146f,0.966216f,
0.970725f,0.975853f,0.980087f,0.983298f,0.986565f,0.990032f,0.992578f,0.994295f,0.995392f,0.996964f,0.998311f,
0.999134f,0.99959f,0.999826f,0.999935f,0.99998f,0.999995f,0.999999f,1.0f,1.0f,0.981812f,
0.999904f,0.999758f,0.99903f,0.997812f,0.996095f,0.993867f,0.991116f,0.98782f,0.984078f,0.98057f,0.976588f,
0.972115f,0.967147f,0.962396f,0.957766f,0.952738f,0.947392f,0.942657f,0.938052f,0.933263f,0.928554f,0.92475f,
0.921049f,0.917511f,0.91439f,0.912139f,0.91029f,0.908901f,0.908055f,0.907826f,0.908239f,0.909301f,0.911002f,
0.913331f,0.916262f,0.919721f,0.923596f,0.927728f,0.932282f,0.937511f,0.942762f,0.947727f,0.952975f,0.95866f,
0.963754f,0.968038f,0.973184f,0.977869f,0.981581f,0.984547f,0.988283f,0.991306f,0.993438f,0.994851f,0.996203f,
0.997798f,0.998844f,0.999444f,0.999762f,0.999912f,0.999974f,0.999994f,0.999999f,1.0f,0.979127f,
0.99991f,0.999773f,0.999089f,0.997945f,0.996333f,0.994244f,0.991664f,0.988577f,0.984984f,0.981579f,0.977852f,
0.973668f,0.969013f,0.964093f,0.959753f,0.955036f,0.949962f,0.944845f,0.940472f,0.935885f,0.931186f,0.926876f,
0.923196f,0.919579f,0.916163f,0.913259f,0.911097f,0.90929f,0.907925f,0.907088f,0.906831f,0.907183f,0.90815f,
0.90972f,0.911889f,0.914642f,0.917924f,0.921644f,0.925669f,0.929927f,0.934947f,0.940171f,0.945221f,0.950116f,
0.955799f,0.961149f,0.965793f,0.970484f,0.975506f,0.979689f,0.982921f,0.986481f,0.989917f,0.992474f,0.994228f,
0.995512f,0.997291f,0.998556f,0.999306f,0.999704f,0.999895f,0.999972f,0.999996f,1.0f,0.97617f,
0.999915f,0.999786f,0.999142f,0.998065f,0.996548f,0.994582f,0.992156f,0.989255f,0.985869f,0.982481f,0.978982f,
0.975055f,0.970687f,0.965918f,0.96153f,0.957091f,0.952301f,0.947248f,0.94266f,0.93828f,0.933726f,0.929164f,
0.925233f,0.921606f,0.918072f,0.914784f,0.912091f,0.909966f,0.908188f,0.906845f,0.906004f,0.905718f,0.906012f,
0.906886f,0.908333f,0.910351f,0.912935f,0.916047f,0.919616f,0.92353f,0.927638f,0.932365f,0.937513f,0.942628f,
0.947454f,0.952904f,0.958443f,0.963404f,0.96786f,0.973055f,0.977656f,0.981345f,0.984693f,0.988476f,0.991437f,
0.993542f,0.994951f,0.996832f,0.998303f,0.999195f,0.99967f,0.999894f,0.999978f,0.999999f,0.972921f,
0.99992f,0.999798f,0.99919f,0.998172f,0.99674f,0.994886f,0.992598f,0.989864f,0.986671f,0.983291f,0.979994f,
0.976298f,0.972186f,0.967668f,0.963121f,0.958933f,0.954407f,0.949577f,0.944682f,0.940455f,0.936075f,0.931577f,
0.927205f,0.923545f,0.919971f,0.91652f,0.913355f,0.91083f,0.908733f,0.906978f,0.905644f,0.904794f,0.904475f,
0.904709f,0.905494f,0.906821f,0.908696f,0.911121f,0.914073f,0.917494f,0.921289f,0.925333f,0.929754f,0.934795f,
0.939934f,0.944892f,0.950008f,0.955647f,0.960896f,0.965458f,0.970568f,0.975529f,0.979649f,0.983015f,0.987014f,
0.990383f,0.992833f,0.994512f,0.996476f,0.99813f,0.999144f,0.999679f,0.999919f,0.999994f,0.969369f,
0.999924f,0.999808f,0.999233f,0.998269f,0.996914f,0.995159f,0.992995f,0.990411f,0.987394f,0.984029f,0.980903f,
0.977413f,0.973531f,0.969257f,0.9647f,0.960587f,0.956302f,0.951706f,0.946894f,0.942426f,0.93822f,0.933852f,
0.929439f,0.925368f,0.921801f,0.918276f,0.914906f,0.911865f,0.909463f,0.907385f,0.905644f,0.904311f,0.903445f,
0.903086f,0.903262f,0.903965f,0.90518f,0.906916f,0.909186f,0.911977f,0.91525f,0.91893f,0.922908f,0.927109f,
0.932005f,0.937139f,0.942208f,0.947133f,0.952792f,0.958266f,0.963179f,0.968089f,0.973347f,0.977877f,0.981512f,
0.985629f,0.989343f,0.992159f,0.994103f,0.996262f,0.998081f,0.999192f,0.999755f,0.99997f,0.965503f,
0.999928f,0.999818f,0.999271f,0.998357f,0.997071f,0.995406f,0.993354f,0.990905f,0.988047f,0.984808f,0.981721f,
0.978415f,0.97474f,0.970692f,0.966312f,0.962072f,0.958005f,0.953631f,0.949f,0.944308f,0.940171f,0.935947f,
0.931611f,0.927312f,0.923531f,0.919985f,0.916512f,0.913219f,0.910308f,0.907977f,0.905906f,0.904172f,0.902829f,
0.901941f,0.901548f,0.901663f,0.902286f,0.903388f,0.904979f,0.907098f,0.909741f,0.912879f,0.916443f,0.92034f,
0.924457f,0.929129f,0.934242f,0.93939f,0.944345f,0.94988f,0.955558f,0.960763f,0.965657f,0.971143f,0.97607f,
0.980105f,0.984313f,0.988401f,0.99155f,0.993778f,0.996248f,0.998215f,0.999376f,0.99989f,0.961305f,
0.999931f,0.999827f,0.999307f,0.998437f,0.997213f,0.995629f,0.993679f,0.991351f,0.988636f,0.985543f,0.982457f,
0.979317f,0.975828f,0.971983f,0.967801f,0.963458f,0.959536f,0.955369f,0.95093f,0.946315f,0.941937f,0.937862f,
0.933637f,0.929346f,0.925201f,0.92161f,0.918091f,0.914662f,0.911445f,0.908681f,0.90635f,0.904286f,0.902539f,
0.901189f,0.90027f,0.899827f,0.899893f,0.90043f,0.901431f,0.902899f,0.904858f,0.907348f,0.910342f,0.913786f,
0.917612f,0.921703f,0.926158f,0.931221f,0.936438f,0.941548f,0.946928f,0.952758f,0.958268f,0.963251f,0.968955f,
0.974244f,0.978709f,0.983145f,0.987602f,0.991086f,0.99363f,0.996521f,0.998598f,0.999672f,0.956763f,
0.999934f,0.999835f,0.999338f,0.998508f,0.997341f,0.995831f,0.993972f,0.991754f,0.989168f,0.986217f,0.983121f,
0.980129f,0.976807f,0.973147f,0.969155f,0.964915f,0.960912f,0.956932f,0.95268f,0.948209f,0.943678f,0.939598f,
0.935495f,0.931274f,0.927053f,0.923134f,0.9196f,0.916097f,0.912713f,0.909569f,0.90691f,0.904576f,0.902497f,
0.900744f,0.899359f,0.898409f,0.897932f,0.89793f,0.898365f,0.899255f,0.900612f,0.902427f,0.904762f,0.907619f,
0.910956f,0.914703f,0.918757f,0.923076f,0.928062f,0.93334f,0.938598f,0.94391f,0.949885f,0.955672f,0.960939f,
0.966782f,0.972473f,0.977339f,0.982158f,0.987011f,0.990834f,0.993941f,0.997197f,0.999165f,0.951869f,
0.999937f,0.999842f,0.999367f,0.998573f,0.997457f,0.996014f,0.994237f,0.992119f,0.989649f,0.986828f,0.983754f,
0.980861f,0.977689f,0.974195f,0.97038f,0.966288f,0.962151f,0.958339f,0.954261f,0.949946f,0.945482f,0.941171f,
0.937189f,0.933057f,0.928862f,0.924723f,0.921017f,0.917476f,0.913992f,0.910646f,0.907569f,0.904978f,0.902627f,
0.900532f,0.898746f,0.89734f,0.896346f,0.895819f,0.895728f,0.89607f,0.896859f,0.898103f,0.899807f,0.901975f,
0.904688f,0.907905f,0.911571f,0.915606f,0.919883f,0.924744f,0.930071f,0.935475f,0.940828f,0.946917f,0.952999f,
0.958615f,0.964677f,0.970755f,0.976066f,0.981434f,0.986719f,0.990889f,0.994903f,0.998124f,0.946603f,
0.99994f,0.999848f,0.999393f,0.998632f,0.997563f,0.99618f,0.994477f,0.992448f,0.990084f,0.987383f,0.984398f,
0.981521f,0.978483f,0.975138f,0.971483f,0.967546f,0.963438f,0.959603f,0.955682f,0.951521f,0.947172f,0.942766f,
0.93872f,0.934687f,0.930551f,0.926382f,0.922358f,0.918772f,0.915228f,0.911754f,0.908441f,0.905443f,0.902866f,
0.900484f,0.89836f,0.896545f,0.895088f,0.894056f,0.893473f,0.893282f,0.893516f,0.894189f,0.895318f,0.89691f,
0.898957f,0.901508f,0.904614f,0.908205f,0.912201f,0.916496f,0.921249f,0.926612f,0.932162f,0.937667f,0.943869f,
0.950237f,0.956248f,0.962633f,0.969161f,0.974939f,0.981058f,0.986837f,0.991554f,0.996184f,0.940943f,
0.999942f,0.999854f,0.999417f,0.998686f,0.997658f,0.996329f,0.994694f,0.992746f,0.990477f,0.987885f,0.985001f,
0.982114f,0.979198f,0.975987f,0.972478f,0.968688f,0.96468f,0.960736f,0.95696f,0.952942f,0.948718f,0.944364f,
0.940098f,0.936162f,0.932099f,0.927952f,0.923828f,0.919967f,0.916392f,0.912834f,0.909367f,0.90608f,0.903165f,
0.900546f,0.898131f,0.895959f,0.894096f,0.892598f,0.891526f,0.89084f,0.890543f,0.89067f,0.891231f,0.892245f,
0.893723f,0.895663f,0.898063f,0.901039f,0.90454f,0.908505f,0.912841f,0.917521f,0.922929f,0.928641f,0.934376f,
0.940704f,0.947407f,0.953808f,0.960668f,0.967726f,0.974053f,0.981159f,0.987453f,0.992846f,0.934885f,
0.999944f,0.99986f,0.999438f,0.998734f,0.997744f,0.996464f,0.99489f,0.993016f,0.990832f,0.988338f,0.985554f,
0.982648f,0.97984f,0.976749f,0.973372f,0.969717f,0.965827f,0.961836f,0.958103f,0.954215f,0.950116f,0.945849f,
0.941531f,0.937485f,0.933498f,0.929397f,0.925254f,0.921176f,0.917462f,0.91385f,0.910276f,0.906807f,0.903541f,
0.900664f,0.898001f,0.895527f,0.893307f,0.891392f,0.889832f,0.888694f,0.88791f,0.887498f,0.887494f,0.887928f,
0.888818f,0.890176f,0.892009f,0.894311f,0.897135f,0.90056f,0.904494f,0.908847f,0.913534f,0.918983f,0.924866f,
0.930857f,0.937397f,0.944464f,0.951309f,0.958837f,0.966466f,0.973804f,0.981824f,0.988889f,0.92844f,
0.999946f,0.999864f,0.999457f,0.998777f,0.997822f,0.996586f,0.995067f,0.993258f,0.991152f,0.988746f,0.986056f,
0.983177f,0.980415f,0.977432f,0.974172f,0.970641f,0.966869f,0.962937f,0.95912f,0.955354f,0.951369f,0.947199f,
0.942918f,0.93868f,0.93475f,0.930702f,0.926575f,0.922434f,0.918436f,0.914777f,0.911127f,0.907528f,0.904047f,
0.900802f,0.897924f,0.895186f,0.89266f,0.890368f,0.888384f,0.886784f,0.88553f,0.884619f,0.884089f,0.88396f,
0.884261f,0.885018f,0.886248f,0.887964f,0.890174f,0.892867f,0.896187f,0.900082f,0.904478f,0.909249f,0.914705f,
0.920788f,0.927055f,0.933897f,0.9414f,0.948722f,0.957105f,0.965345f,0.974171f,0.98297f,0.921542f,
0.999948f,0.999869f,0.999475f,0.998816f,0.997891f,0.996696f,0.995227f,0.993477f,0.99144f,0.989114f,0.98651f,
0.983691f,0.980929f,0.978042f,0.974887f,0.971469f,0.967806f,0.963957f,0.960051f,0.956363f,0.952486f,0.948411f,
0.944193f,0.939917f,0.935857f,0.931864f,0.927767f,0.923609f,0.919485f,0.915598f,0.911892f,0.908197f,0.904563f,
0.901062f,0.89786f,0.894898f,0.892096f,0.889476f,0.887115f,0.885053f,0.883368f,0.881994f,0.880952f,0.880277f,
0.879998f,0.880157f,0.880773f,0.881866f,0.883459f,0.885563f,0.888174f,0.891364f,0.89523f,0.899657f,0.904521f,
0.910053f,0.916326f,0.922896f,0.930147f,0.938112f,0.946137f,0.955367f,0.964443f,0.974073f,0.914169f,
0.999949f,0.999873f,0.99949f,0.998852f,0.997954f,0.996795f,0.995369f,0.993673f,0.991698f,0.989443f,0.986918f,
0.984166f,0.981386f,0.978584f,0.975522f,0.972205f,0.968644f,0.964882f,0.960995f,0.957252f,0.953469f,0.949487f,
0.945339f,0.941085f,0.936858f,0.932882f,0.928819f,0.924665f,0.920488f,0.916376f,0.912556f,0.908784f,0.905031f,
0.901348f,0.897827f,0.89462f,0.891569f,0.888666f,0.885961f,0.883495f,0.881366f,0.879555f,0.878029f,0.876839f,
0.876012f,0.875575f,0.875571f,0.876023f,0.876962f,0.878415f,0.880404f,0.882939f,0.886022f,0.889832f,0.89428f,
0.899255f,0.904879f,0.911381f,0.918244f,0.925991f,0.934414f,0.94337f,0.953167f,0.964321f,0.906408f,
0.999951f,0.999876f,0.999504f,0.998883f,0.99801f,0.996883f,0.995497f,0.993848f,0.991929f,0.989738f,0.987283f,
0.984597f,0.981795f,0.979063f,0.976084f,0.972856f,0.969387f,0.96571f,0.961873f,0.958028f,0.954331f,0.95043f,
0.946353f,0.942141f,0.937876f,0.933757f,0.92973f,0.925589f,0.921388f,0.917179f,0.913103f,0.909268f,0.905419f,
0.901596f,0.897855f,0.894311f,0.89104f,0.887888f,0.884873f,0.882049f,0.879487f,0.877248f,0.875279f,0.873591f,
0.872226f,0.871219f,0.870611f,0.870427f,0.870699f,0.871468f,0.872764f,0.874617f,0.877052f,0.880055f,0.883762f,
0.888234f,0.893298f,0.899037f,0.905744f,0.912868f,0.921173f,0.929949f,0.940275f,0.950713f,0.898177f,
0.999952f,0.999879f,0.999517f,0.998911f,0.99806f,0.996961f,0.99561f,0.994003f,0.992133f,0.989999f,0.987607f,
0.984983f,0.982203f,0.979483f,0.976576f,0.973427f,0.97004f,0.966441f,0.962663f,0.958797f,0.955073f,0.951245f,
0.947233f,0.94307f,0.938809f,0.934542f,0.930498f,0.926371f,0.922157f,0.917894f,0.913657f,0.909635f,0.905703f,
0.901763f,0.897854f,0.894054f,0.890477f,0.887092f,0.883801f,0.880662f,0.877708f,0.875035f,0.872639f,0.870479f,
0.868606f,0.867047f,0.865839f,0.865024f,0.864637f,0.864707f,0.86527f,0.866376f,0.868064f,0.870364f,0.873277f,
0.876876f,0.881325f,0.88643f,0.892274f,0.899161f,0.90658f,0.915628f,0.92524f,0.935881f,0.88957f,
0.999953f,0.999882f,0.999528f,0.998936f,0.998104f,0.99703f,0.99571f,0.99414f,0.992314f,0.99023f,0.987893f,
0.985325f,0.982582f,0.979847f,0.977003f,0.973922f,0.970607f,0.967078f,0.96336f,0.959515f,0.955701f,0.951937f,
0.947982f,0.943866f,0.939627f,0.935318f,0.931121f,0.927009f,0.922787f,0.918488f,0.91416f,0.909899f,0.905863f,
0.901822f,0.897772f,0.893772f,0.889884f,0.886253f,0.882708f,0.879273f,0.875972f,0.872875f,0.870059f,0.867463f,
0.86509f,0.86299f,0.861212f,0.859777f,0.858737f,0.858114f,0.857939f,0.858251f,0.859112f,0.860584f,0.862706f,
0.86548f,0.86893f,0.873288f,0.878375f,0.884333f,0.891502f,0.899362f,0.908023f,0.917917f,0.880488f,
0.999954f,0.999884f,0.999537f,0.998957f,0.998142f,0.99709f,0.995797f,0.994259f,0.992471f,0.990431f,0.988143f,
0.985626f,0.982921f,0.980158f,0.977368f,0.974344f,0.971093f,0.967625f,0.963962f,0.96015f,0.956267f,0.95251f,
0.948606f,0.94453f,0.940316f,0.935994f,0.93166f,0.927498f,0.92327f,0.91894f,0.914548f,0.910154f,0.905893f,
0.901754f,0.897579f,0.89341f,0.889293f,0.885328f,0.881557f,0.877842f,0.874225f,0.87075f,0.867495f,0.864469f,
0.861627f,0.859016f,0.856658f,0.854625f,0.852935f,0.851607f,0.850688f,0.850215f,0.850242f,0.850807f,0.851979f,
0.853841f,0.856394f,0.859629f,0.863905f,0.868965f,0.874887f,0.881483f,0.888925f,0.897543f,0.870947f,
0.999955f,0.999886f,0.999545f,0.998975f,0.998175f,0.997142f,0.995872f,0.994362f,0.992606f,0.990604f,0.988359f,
0.985886f,0.983218f,0.980435f,0.977674f,0.974699f,0.971501f,0.968085f,0.96447f,0.960693f,0.956801f,0.952969f,
0.949103f,0.945063f,0.940869f,0.936547f,0.932158f,0.927836f,0.923599f,0.919244f,0.914794f,0.910305f,0.905834f,
0.901541f,0.897252f,0.892931f,0.88862f,0.884363f,0.880311f,0.876336f,0.872421f,0.86859f,0.864912f,0.861461f,
0.858171f,0.855046f,0.852144f,0.8495f,0.847163f,0.845132f,0.843451f,0.842168f,0.841331f,0.840987f,0.841192f,
0.841982f,0.843476f,0.845785f,0.84877f,0.852608f,0.856957f,0.862136f,0.86779f,0.875188f,0.860924f,
0.999956f,0.999888f,0.999552f,0.998991f,0.998203f,0.997186f,0.995936f,0.994449f,0.992721f,0.99075f,0.988542f,
0.986106f,0.983472f,0.980696f,0.977923f,0.974988f,0.971833f,0.96846f,0.964887f,0.961141f,0.957256f,0.953328f,
0.949477f,0.945466f,0.941287f,0.936967f,0.932546f,0.928093f,0.923771f,0.919389f,0.914889f,0.910318f,0.905712f,
0.90117f,0.896768f,0.892303f,0.887819f,0.88333f,0.878937f,0.874714f,0.870515f,0.866357f,0.862287f,0.858388f,
0.854652f,0.851041f,0.847592f,0.844349f,0.841364f,0.838631f,0.836181f,0.834069f,0.83234f,0.831041f,0.830223f,
0.82996f,0.830356f,0.831364f,0.833022f,0.835176f,0.838046f,0.841367f,0.846069f,0.85085f,0.850491f,
0.999956f,0.99989f,0.999558f,0.999004f,0.998226f,0.997222f,0.995988f,0.994521f,0.992815f,0.990871f,0.988693f,
0.986289f,0.983683f,0.98092f,0.978116f,0.975213f,0.972092f,0.968753f,0.965214f,0.961493f,0.957617f,0.953652f,
0.949732f,0.945737f,0.941567f,0.937246f,0.932798f,0.928278f,0.923782f,0.919366f,0.914818f,0.910169f,0.905453f,
0.90072f,0.896113f,0.891508f,0.886855f,0.882164f,0.877489f,0.872942f,0.868466f,0.863996f,0.859556f,0.855205f,
0.851031f,0.846939f,0.842949f,0.83911f,0.835478f,0.832035f,0.828819f,0.825866f,0.823226f,0.82094f,0.819066f,
0.817705f,0.816811f,0.816395f,0.816445f,0.817031f,0.818201f,0.820119f,0.822592f,0.824952f,0.839625f,
0.999957f,0.999891f,0.999562f,0.999014f,0.998244f,0.997251f,0.99603f,0.994578f,0.99289f,0.990968f,0.988813f,
0.986435f,0.983852f,0.981101f,0.978257f,0.975375f,0.97228f,0.968965f,0.965452f,0.961749f,0.95788f,0.953895f,
0.949867f,0.94588f,0.941708f,0.937379f,0.932904f,0.928331f,0.923699f,0.91917f,0.91457f,0.909845f,0.905024f,
0.900145f,0.895279f,0.890528f,0.885704f,0.880818f,0.875895f,0.871003f,0.866232f,0.861454f,0.856663f,0.851896f,
0.847239f,0.842673f,0.838156f,0.833721f,0.829429f,0.825287f,0.821285f,0.817492f,0.813921f,0.810632f,0.8077f,
0.805073f,0.802772f,0.800827f,0.799271f,0.798296f,0.797781f,0.797517f,0.797329f,0.797668f,0.828277f,
0.999957f,0.999892f,0.999566f,0.999022f,0.998258f,0.997272f,0.996061f,0.99462f,0.992947f,0.99104f,0.988904f,
0.986544f,0.983979f,0.981239f,0.978368f,0.975478f,0.972399f,0.969099f,0.965602f,0.961909f,0.958042f,0.954041f,
0.94994f,0.945893f,0.941711f,0.937366f,0.93286f,0.928236f,0.923514f,0.918799f,0.914134f,0.909329f,0.904409f,
0.899394f,0.894334f,0.889335f,0.884342f,0.879261f,0.874102f,0.868917f,0.863788f,0.8587f,0.853561f,0.848391f,
0.843246f,0.838198f,0.833145f,0.828119f,0.823175f,0.818308f,0.813526f,0.808867f,0.804366f,0.800075f,0.795942f,
0.791986f,0.78823f,0.784734f,0.781723f,0.778953f,0.776215f,0.773872f,0.77166f,0.769465f,0.816513f,
0.999957f,0.999892f,0.999568f,0.999027f,0.998267f,0.997286f,0.996081f,0.994649f,0.992985f,0.991089f,0.988965f,
0.986619f,0.984066f,0.981331f,0.978447f,0.975521f,0.972448f,0.969154f,0.965665f,0.961973f,0.958103f,0.954082f,
0.949933f,0.945775f,0.941575f,0.937203f,0.932658f,0.92798f,0.923179f,0.918313f,0.913506f,0.908614f,0.903587f,
0.898439f,0.893203f,0.887939f,0.882743f,0.877466f,0.872078f,0.866608f,0.861112f,0.855682f,0.850192f,0.844627f,
0.839018f,0.833445f,0.827868f,0.822247f,0.816618f,0.811043f,0.805467f,0.799943f,0.794512f,0.789096f,0.783735f,
0.778421f,0.773216f,0.768344f,0.76355f,0.758717f,0.754066f,0.749843f,0.745252f,0.740517f,0.804341f,
0.999957f,0.999892f,0.999569f,0.99903f,0.998272f,0.997294f,0.996092f,0.994663f,0.993004f,0.991115f,0.988997f,
0.986658f,0.984111f,0.981377f,0.97848f,0.975504f,0.97243f,0.969132f,0.965641f,0.961942f,0.958059f,0.954013f,
0.949822f,0.945549f,0.941294f,0.936886f,0.932295f,0.927552f,0.922673f,0.917687f,0.912672f,0.907684f,0.902542f,
0.897259f,0.891858f,0.886371f,0.88089f,0.875401f,0.869777f,0.864033f,0.858207f,0.852369f,0.846521f,0.840554f,
0.834489f,0.828369f,0.82225f,0.816031f,0.809737f,0.803422f,0.797047f,0.790663f,0.784205f,0.777659f,0.771039f,
0.764416f,0.757934f,0.751366f,0.744641f,0.737894f,0.731715f,0.725017f,0.71815f,0.711165f,0.791751f,
0.999957f,0.999892f,0.999569f,0.99903f,0.998272f,0.997294f,0.996093f,0.994664f,0.993006f,0.991117f,0.989001f,
0.986663f,0.984116f,0.981376f,0.978464f,0.975431f,0.972343f,0.969035f,0.965529f,0.961813f,0.957909f,0.95383f,
0.949595f,0.945239f,0.940871f,0.936411f,0.931764f,0.926947f,0.921981f,0.916881f,0.911697f,0.906527f,0.901258f,
0.895832f,0.890257f,0.884564f,0.87879f,0.87304f,0.867174f,0.86115f,0.854994f,0.848749f,0.842503f,0.836126f,
0.829598f,0.822943f,0.816248f,0.80942f,0.802449f,0.795381f,0.788219f,0.780892f,0.773392f,0.765707f,0.757877f,
0.75007f,0.742025f,0.733689f,0.725202f,0.717093f,0.708577f,0.699565f,0.690879f,0.681602f,0.778761f,
0.999957f,0.999892f,0.999568f,0.999027f,0.998268f,0.997288f,0.996083f,0.994651f,0.992989f,0.991097f,0.988976f,
0.986634f,0.98408f,0.981328f,0.978397f,0.975322f,0.972186f,0.96886f,0.965328f,0.961587f,0.957652f,0.95353f,
0.949245f,0.944813f,0.940302f,0.935772f,0.931059f,0.926159f,0.921096f,0.915878f,0.910541f,0.90514f,0.899728f,
0.894141f,0.888388f,0.882482f,0.876453f,0.870364f,0.864234f,0.857926f,0.851442f,0.844808f,0.838093f,0.831296f,
0.8243f,0.817115f,0.809797f,0.802357f,0.7947f,0.786888f,0.778866f,0.770583f,0.762045f,0.753241f,0.744345f,
0.735102f,0.725449f,0.715508f,0.705687f,0.695549f,0.684887f,0.67445f,0.663363f,0.652093f,0.765406f,
0.999957f,0.999892f,0.999566f,0.999023f,0.998259f,0.997274f,0.996064f,0.994625f,0.992955f,0.991053f,0.988923f,
0.986569f,0.984003f,0.981232f,0.978276f,0.975161f,0.97196f,0.968605f,0.965037f,0.96126f,0.957284f,0.953108f,
0.948765f,0.944255f,0.939625f,0.934967f,0.930171f,0.925175f,0.920004f,0.914658f,0.909168f,0.903559f,0.897933f,
0.892172f,0.886223f,0.880093f,0.873807f,0.86739f,0.860935f,0.854319f,0.847493f,0.840477f,0.833288f,0.826021f,
0.818543f,0.810818f,0.80288f,0.794794f,0.78646f,0.777837f,0.768945f,0.759702f,0.750139f,0.740353f,0.730174f,
0.719489f,0.708376f,0.697172f,0.685622f,0.673509f,0.661306f,0.648908f,0.636052f,0.622884f,0.7517f,
0.999957f,0.999891f,0.999563f,0.999015f,0.998246f,0.997253f,0.996034f,0.994584f,0.992902f,0.990986f,0.98884f,
0.986469f,0.983884f,0.981088f,0.9781f,0.974942f,0.971662f,0.968269f,0.964655f,0.96083f,0.956801f,0.952561f,
0.94815f,0.943554f,0.938816f,0.933988f,0.929093f,0.923988f,0.918694f,0.913211f,0.907554f,0.901752f,0.895854f,
0.889904f,0.883745f,0.877381f,0.870822f,0.864096f,0.857248f,0.850307f,0.843125f,0.835709f,0.828068f,0.820263f,
0.812289f,0.804018f,0.79546f,0.786693f,0.777645f,0.768205f,0.758414f,0.748234f,0.737762f,0.726823f,0.715346f,
0.703334f,0.691073f,0.678343f,0.665048f,0.651509f,0.637636f,0.623285f,0.608988f,0.594206f,0.737674f,
0.999956f,0.99989f,0.999558f,0.999005f,0.998228f,0.997226f,0.995994f,0.994529f,0.99283f,0.990896f,0.988729f,
0.986334f,0.983722f,0.980894f,0.977868f,0.974662f,0.971299f,0.967851f,0.964179f,0.960296f,0.956202f,0.95189f,
0.947395f,0.942704f,0.937852f,0.932857f,0.927823f,0.922592f,0.91716f,0.911524f,0.905692f,0.899688f,0.893535f,
0.887321f,0.880935f,0.874318f,0.867479f,0.860431f,0.853198f,0.845865f,0.838307f,0.830474f,0.822373f,0.814021f,
0.8055f,0.796672f,0.787502f,0.778016f,0.76821f,0.757952f,0.747278f,0.736242f,0.724744f,0.712622f,0.699938f,
0.686888f,0.673208f,0.659007f,0.644411f,0.629202f,0.6138f,0.598171f,0.582135f,0.566085f,0.723342f,
0.999956f,0.999888f,0.999553f,0.998993f,0.998206f,0.997191f,0.995943f,0.994459f,0.992739f,0.990781f,0.988587f,
0.986162f,0.983516f,0.980649f,0.977578f,0.974317f,0.970878f,0.967347f,0.96361f,0.959655f,0.955483f,0.951088f,
0.946494f,0.941697f,0.936722f,0.931578f,0.92635f,0.92098f,0.915387f,0.909583f,0.903565f,0.897347f,0.890944f,
0.884412f,0.877772f,0.870886f,0.863749f,0.856368f,0.848758f,0.840969f,0.833013f,0.824748f,0.816166f,0.807288f,
0.798161f,0.78875f,0.778958f,0.768739f,0.758145f,0.747075f,0.735573f,0.723635f,0.71103f,0.697804f,0.68418f,
0.669825f,0.654899f,0.639542f,0.623368f,0.606949f,0.590104f,0.573112f,0.556005f,0.538648f,0.708741f,
0.999955f,0.999887f,0.999546f,0.998977f,0.998179f,0.997148f,0.995881f,0.994375f,0.992629f,0.990641f,0.988414f,
0.985952f,0.983266f,0.980353f,0.977229f,0.973904f,0.970388f,0.966755f,0.962942f,0.958904f,0.954639f,0.950151f,
0.945442f,0.940529f,0.935418f,0.930119f,0.924672f,0.919137f,0.913371f,0.907377f,0.901155f,0.894706f,0.888051f,
0.881208f,0.874248f,0.867067f,0.859614f,0.851884f,0.843885f,0.835641f,0.827222f,0.818502f,0.80943f,0.800013f,
0.790265f,0.780252f,0.769787f,0.758834f,0.747431f,0.735596f,0.723268f,0.710318f,0.696696f,0.682603f,0.667806f,
0.65232f,0.636395f,0.619626f,0.60235f,0.584744f,0.566715f,0.548508f,0.530267f,0.512071f,0.693905f,
0.999954f,0.999885f,0.999538f,0.99896f,0.998147f,0.997098f,0.995809f,0.994276f,0.992499f,0.990477f,0.98821f,
0.985706f,0.982971f,0.980003f,0.976817f,0.973421f,0.969823f,0.966072f,0.962172f,0.958038f,0.953668f,0.94907f,
0.944238f,0.939194f,0.93393f,0.928466f,0.922816f,0.917062f,0.911102f,0.904902f,0.898451f,0.891761f,0.884834f,
0.877684f,0.870354f,0.862852f,0.855057f,0.846962f,0.838561f,0.829865f,0.820922f,0.81173f,0.802147f,0.792176f,
0.781824f,0.771127f,0.75998f,0.748295f,0.736103f,0.72354f,0.710279f,0.696358f,0.681909f,0.666783f,0.650914f,
0.634577f,0.617412f,0.599537f,0.581377f,0.562529f,0.543609f,0.52449f,0.505393f,0.486384f,0.678874f,
0.999953f,0.999882f,0.999529f,0.998939f,0.99811f,0.99704f,0.995725f,0.994161f,0.992349f,0.990286f,0.987975f,
0.98542f,0.982628f,0.979599f,0.976341f,0.972866f,0.969178f,0.965309f,0.961297f,0.957056f,0.952565f,0.947845f,
0.942875f,0.937683f,0.932253f,0.926612f,0.920755f,0.914744f,0.908575f,0.902144f,0.895451f,0.888494f,0.881279f,
0.873811f,0.866105f,0.858231f,0.85007f,0.841584f,0.832764f,0.823611f,0.814136f,0.804417f,0.794309f,0.783772f,
0.772802f,0.761378f,0.749542f,0.737136f,0.724245f,0.710792f,0.696639f,0.681899f,0.666545f,0.650397f,0.633774f,
0.616356f,0.598136f,0.579598f,0.560262f,0.540735f,0.520783f,0.500896f,0.481144f,0.461581f,0.663661f,
    };
    *n = 64;
    return data;
}
/* The albedo integrands at (u1, u2) of the unit square: eta = 0, f cos / pdf
 * at wi = mf_brdf_sample(u) (G2 / G1, smooth except where wi crosses the
 * horizon); eta > 0 (wo above, lo = Lambda(wo)), the dielectric's reflected
 * and transmitted weights F (1 + lo) G2 and (1 - F) (1 + lo) G2 at the
 * visible normal m(u). 0 where there is no sample. */
MF_INLINE mf_real mf__albedo_weight(const mf_ndf *d, mf_vec3 wo, mf_real eta, mf_real lo, mf_real u1, mf_real u2)
{
    mf_real v = MF_R(0.0);
    if (!(eta > MF_R(0.0))) {
        mf_vec3 wi = mf_brdf_sample(d, wo, u1, u2);
        mf_real pdf;
        if (!(wi.z > MF_R(0.0))) return MF_R(0.0);
        pdf = mf_brdf_pdf(d, wo, wi);
        if (!(pdf > MF_R(0.0))) return MF_R(0.0);
        v = mf_brdf(d, wo, wi) * wi.z / pdf;
    } else {
        mf_vec3 m = mf_sample_visible(d, wo, u1, u2), wr, wt;
        mf_real F;
        if (!(m.z > MF_R(0.0)) || !(mf_dot(wo, m) > MF_R(0.0))) return MF_R(0.0);
        F = mf_fresnel_dielectric(mf_dot(wo, m), eta);
        wr = mf_reflect(wo, m);
        if (wr.z > MF_R(0.0)) v += F * (MF_R(1.0) + lo) * mf__dielectric_G2(d, wo, wr);
        if (F < MF_R(1.0) && mf_refract(wo, m, eta, &wt) && wt.z < MF_R(0.0))
            v += (MF_R(1.0) - F) * (MF_R(1.0) + lo) * mf__dielectric_G2(d, wo, wt);
    }
    return v == v && v < MF_BIG ? v : MF_R(0.0);
}

/* The albedo by (8 panels)^2 Gauss-Legendre nodes over the unit square,
 * clamped to [0, 1]. */
MF_INLINE mf_real mf__albedo_quad(const mf_ndf *d, mf_vec3 wo, mf_real eta, mf_real lo, int panels)
{
    double sum = 0.0, h = 1.0 / (double)panels;
    int p1, p2, i, j;
    for (p1 = 0; p1 < panels; ++p1)
        for (i = 0; i < 8; ++i) {
            mf_real u1 = mf__gl_node01(p1, i, panels);
            for (p2 = 0; p2 < panels; ++p2)
                for (j = 0; j < 8; ++j) {
                    mf_real v = mf__albedo_weight(d, wo, eta, lo, u1, mf__gl_node01(p2, j, panels));
                    if (v != MF_R(0.0)) sum += (double)mf__gl_w(i) * (double)mf__gl_w(j) * (double)v;
                }
        }
    sum *= h * h;
    return sum > 0.0 ? (sum < 1.0 ? (mf_real)sum : MF_R(1.0)) : MF_R(0.0);
}

MFDEF mf_real mf_albedo_integrate(const mf_ndf *d, mf_vec3 wo, int panels)
{
    if (!d || d->type < 0 || d->type >= MF_NDF_KIND_COUNT || panels < 1 || panels > 64) return MF_R(0.0);
    if (!(wo.z > MF_R(0.0)) || !(wo.z <= MF_R(1.0)) || !(wo.x == wo.x) || !(wo.y == wo.y)) return MF_R(0.0);
    return mf__albedo_quad(d, wo, MF_R(0.0), MF_R(0.0), panels);
}

/* 2 int_0^1 e(x) mu dmu with mu = x^2 (dmu = 2 x dx) for e piecewise linear
 * on n nodes x_i = i / (n - 1): 3-point Gauss-Legendre per segment is exact
 * (degree 4). */
MF_INLINE double mf__energy_avg_1d(const double *e, int n)
{
    static const double gx[3] = { -0.774596669241483377, 0.0, 0.774596669241483377 };
    static const double gw[3] = { 0.555555555555555556, 0.888888888888888889, 0.555555555555555556 };
    double sum = 0.0, h = 1.0 / (double)(n - 1);
    int i, k;
    for (i = 0; i + 1 < n; ++i)
        for (k = 0; k < 3; ++k) {
            double s = 0.5 + 0.5 * gx[k], x = h * ((double)i + s);
            double v = e[i] + (e[i + 1] - e[i]) * s;
            sum += 0.5 * h * gw[k] * v * 4.0 * x * x * x;
        }
    return sum;
}

/* The table node i of n: mu = x^2, x = i / (n - 1) (mu >= 1e-4), at
 * azimuth phi; and back, the segment i and fraction of |mu| in [0, 1]. */
MF_INLINE mf_vec3 mf__energy_node_dir(int i, int n, mf_real phi)
{
    mf_real x = (mf_real)i / (mf_real)(n - 1), mu = mf_max(x * x, MF_R(1e-4));
    mf_real s = MF_SQRT(MF_R(1.0) - mu * mu);
    return mf_vec3_make(s * MF_COS(phi), s * MF_SIN(phi), mu);
}
MF_INLINE mf_real mf__energy_segment(mf_real mu, int n, int *i)
{
    mf_real x = mf_clamp(MF_SQRT(mf_min(MF_FABS(mu), MF_R(1.0))), MF_R(0.0), MF_R(1.0)) * (mf_real)(n - 1);
    *i = (int)x;
    if (*i > n - 2) *i = n - 2;
    return x - (mf_real)*i;
}
/* |w.z| / |w|, or -1 when w is zero or not finite */
MF_INLINE mf_real mf__energy_mu(mf_vec3 w)
{
    mf_real len = MF_SQRT(w.x * w.x + w.y * w.y + w.z * w.z);
    return len > MF_R(0.0) && len < MF_BIG ? MF_FABS(w.z) / len : MF_R(-1.0);
}

/* bilinear read of the built-in table of kind k (0 GGX, 1 Beckmann): the
 * E_avg column when mu < 0 */
MF_INLINE mf_real mf__energy_lookup(int k, mf_real alpha, mf_real mu)
{
    int n, i, j, col;
    const float *t = mf__energy_data(&n);
    mf_real r = mf_clamp(MF_SQRT(mf_max(alpha, MF_R(0.0))), MF_R(0.0), MF_R(1.0)) * (mf_real)(n - 1);
    mf_real fr, fx, v0, v1;
    const float *blk = t + (size_t)k * (size_t)n * (size_t)(n + 1);
    i = (int)r; if (i > n - 2) i = n - 2;
    fr = r - (mf_real)i;
    if (mu < MF_R(0.0)) {
        col = n;
        return (mf_real)blk[i * (n + 1) + col] * (MF_R(1.0) - fr) + (mf_real)blk[(i + 1) * (n + 1) + col] * fr;
    }
    fx = mf__energy_segment(mu, n, &j);
    v0 = (mf_real)blk[i * (n + 1) + j] * (MF_R(1.0) - fx) + (mf_real)blk[i * (n + 1) + j + 1] * fx;
    v1 = (mf_real)blk[(i + 1) * (n + 1) + j] * (MF_R(1.0) - fx) + (mf_real)blk[(i + 1) * (n + 1) + j + 1] * fx;
    return v0 * (MF_R(1.0) - fr) + v1 * fr;
}

/* the built-in table of d (0 GGX, 1 Beckmann), -1 when none */
MF_INLINE int mf__energy_kind(const mf_ndf *d)
{
    if (!d || d->transformed) return -1;
    if (d->type == MF_NDF_GGX) return 0;
    if (d->type == MF_NDF_BECKMANN) return 1;
    return -1;
}

MFDEF mf_real mf_albedo(const mf_ndf *d, mf_vec3 wo)
{
    int k = mf__energy_kind(d);
    mf_real mu, len;
    if (!d || !(wo.z > MF_R(0.0))) return MF_R(0.0);
    mu = mf__energy_mu(wo);
    if (!(mu >= MF_R(0.0))) return MF_R(0.0);
    if (k >= 0) return mf__energy_lookup(k, MF_SQRT(d->ax * d->ay), mu);
    len = MF_SQRT(wo.x * wo.x + wo.y * wo.y + wo.z * wo.z);
    return mf_albedo_integrate(d, mf_scale(wo, MF_R(1.0) / len), 1);
}

MFDEF mf_real mf_albedo_average(const mf_ndf *d)
{
    int k = mf__energy_kind(d), i, j, n_phi;
    double e[17], sum = 0.0;
    if (!d || d->type < 0 || d->type >= MF_NDF_KIND_COUNT) return MF_R(0.0);
    if (k >= 0) return mf__energy_lookup(k, MF_SQRT(d->ax * d->ay), MF_R(-1.0));
    /* other kinds: 17 nodes in x (mu = x^2), 8 azimuths unless isotropic */
    n_phi = (!d->transformed && d->ax == d->ay && d->type != MF_NDF_LEADR && d->type != MF_NDF_TABULATED) ? 1 : 8;
    for (j = 0; j < n_phi; ++j) {
        mf_real phi = MF_R(2.0) * MF_PI * (mf_real)j / (mf_real)n_phi;
        for (i = 0; i < 17; ++i) e[i] = (double)mf_albedo_integrate(d, mf__energy_node_dir(i, 17, phi), 1);
        sum += mf__energy_avg_1d(e, 17);
    }
    return (mf_real)(sum / (double)n_phi);
}

MF_INLINE mf_real mf__ms_lobe(mf_real eo, mf_real ei, mf_real eavg)
{
    mf_real den = MF_PI * (MF_R(1.0) - eavg);
    if (!(den > MF_R(1e-6))) return MF_R(0.0);   /* E_avg = 1: nothing to put back */
    return mf_clamp((MF_R(1.0) - eo) * (MF_R(1.0) - ei) / den, MF_R(0.0), MF_BIG);
}

MFDEF mf_real mf_brdf_ms(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    if (!d || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ms_lobe(mf_albedo(d, wo), mf_albedo(d, wi), mf_albedo_average(d));
}

MFDEF mf_real mf_ms_turquin_scale(const mf_ndf *d, mf_vec3 wo, mf_real f0)
{
    mf_real e = mf_albedo(d, wo);
    if (!(e > MF_R(1e-6))) return MF_R(1.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    if (!(f0 == f0)) return MF_R(1.0);
    return MF_R(1.0) + f0 * (MF_R(1.0) - e) / e;
}

MFDEF void mf_albedo_table_release(mf_albedo_table *t)
{
    if (!t) return;
    if (t->E) MF_FREE(t->E);
    t->E = 0;
    t->n_mu = t->n_phi = 0;
    t->E_avg = MF_R(0.0);
}

MFDEF mf_result mf_albedo_table_build(mf_albedo_table *t, const mf_ndf *d, int n_mu, int n_phi, int panels)
{
    int i, j;
    double *row, sum = 0.0;
    if (t) { t->E = 0; t->n_mu = t->n_phi = 0; t->E_avg = MF_R(0.0); }
    if (!t || !d || d->type < 0 || d->type >= MF_NDF_KIND_COUNT || n_mu < 2 || n_mu > 1024 ||
        n_phi < 1 || n_phi > 1024 || panels < 1 || panels > 64)
        return MF_ERROR_INVALID_ARGUMENT;
    t->E = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)n_mu * (size_t)n_phi);
    if (!t->E) return MF_ERROR_OUT_OF_MEMORY;
    row = (double *)MF_MALLOC(sizeof(double) * (size_t)n_mu);
    if (!row) { MF_FREE(t->E); t->E = 0; return MF_ERROR_OUT_OF_MEMORY; }
    for (j = 0; j < n_phi; ++j) {
        mf_real phi = MF_R(2.0) * MF_PI * (mf_real)j / (mf_real)n_phi;
        for (i = 0; i < n_mu; ++i) {
            mf_real e = mf_albedo_integrate(d, mf__energy_node_dir(i, n_mu, phi), panels);
            if (!(e >= MF_R(0.0)) || !(e <= MF_R(1.0))) { MF_FREE(row); mf_albedo_table_release(t); return MF_ERROR_INVALID_DATA; }
            t->E[(size_t)j * (size_t)n_mu + (size_t)i] = e;
            row[i] = (double)e;
        }
        sum += mf__energy_avg_1d(row, n_mu);
    }
    MF_FREE(row);
    t->n_mu = n_mu;
    t->n_phi = n_phi;
    t->E_avg = (mf_real)(sum / (double)n_phi);
    return MF_SUCCESS;
}

MFDEF mf_real mf_albedo_table_eval(const mf_albedo_table *t, mf_vec3 wo)
{
    mf_real mu, fx, ph, fp, v0, v1;
    int i, j0, j1;
    const mf_real *E;
    if (!t || !t->E || t->n_mu < 2 || t->n_phi < 1 || !(wo.z > MF_R(0.0))) return MF_R(0.0);
    mu = mf__energy_mu(wo);
    if (!(mu >= MF_R(0.0))) return MF_R(0.0);
    fx = mf__energy_segment(mu, t->n_mu, &i);
    E = t->E;
    if (t->n_phi == 1) return E[i] * (MF_R(1.0) - fx) + E[i + 1] * fx;
    ph = MF_ATAN2(wo.y, wo.x);
    if (!(ph == ph)) ph = MF_R(0.0);
    if (ph < MF_R(0.0)) ph += MF_R(2.0) * MF_PI;
    ph *= (mf_real)t->n_phi / (MF_R(2.0) * MF_PI);
    j0 = (int)ph; if (j0 < 0) j0 = 0; if (j0 > t->n_phi - 1) j0 = t->n_phi - 1;
    fp = mf_clamp(ph - (mf_real)j0, MF_R(0.0), MF_R(1.0));
    j1 = (j0 + 1) % t->n_phi;
    v0 = E[(size_t)j0 * (size_t)t->n_mu + (size_t)i] * (MF_R(1.0) - fx) + E[(size_t)j0 * (size_t)t->n_mu + (size_t)i + 1] * fx;
    v1 = E[(size_t)j1 * (size_t)t->n_mu + (size_t)i] * (MF_R(1.0) - fx) + E[(size_t)j1 * (size_t)t->n_mu + (size_t)i + 1] * fx;
    return v0 * (MF_R(1.0) - fp) + v1 * fp;
}

MFDEF mf_real mf_albedo_table_average(const mf_albedo_table *t)
{
    return (t && t->E) ? t->E_avg : MF_R(0.0);
}

MFDEF mf_real mf_brdf_ms_table(const mf_albedo_table *t, mf_vec3 wo, mf_vec3 wi)
{
    if (!t || !t->E || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ms_lobe(mf_albedo_table_eval(t, wo), mf_albedo_table_eval(t, wi), t->E_avg);
}

/* ---- rough dielectrics */
MFDEF mf_real mf_dielectric_albedo_integrate(const mf_ndf *d, mf_vec3 wo, mf_real eta, int panels)
{
    if (!d || d->type < 0 || d->type >= MF_NDF_KIND_COUNT || panels < 1 || panels > 64) return MF_R(0.0);
    if (!(eta > MF_R(0.0)) || !(eta < MF_BIG) || !(wo.x == wo.x) || !(wo.y == wo.y) || !(MF_FABS(wo.z) <= MF_R(1.0))) return MF_R(0.0);
    if (!(wo.z != MF_R(0.0))) return MF_R(0.0);
    if (wo.z < MF_R(0.0)) { wo = mf_scale(wo, MF_R(-1.0)); eta = MF_R(1.0) / eta; }   /* as mf_dielectric_sample */
    return mf__albedo_quad(d, wo, eta, mf_lambda(d, wo), panels);
}

MFDEF void mf_dielectric_ms_release(mf_dielectric_ms_table *t)
{
    if (!t) return;
    if (t->E) MF_FREE(t->E);
    t->E = 0;
    t->n_mu = 0;
    t->E1_avg = t->E2_avg = t->x = t->y = t->eta = MF_R(0.0);
}

MFDEF mf_result mf_dielectric_ms_build(mf_dielectric_ms_table *t, const mf_ndf *d, mf_real eta, int n_mu, int panels)
{
    int i, s;
    double *row, avg[2], x, y;
    if (t) { t->E = 0; t->n_mu = 0; t->E1_avg = t->E2_avg = t->x = t->y = t->eta = MF_R(0.0); }
    if (!t || !d || d->type < 0 || d->type >= MF_NDF_KIND_COUNT || n_mu < 2 || n_mu > 1024 ||
        panels < 1 || panels > 64 || !(eta > MF_R(1e-3)) || !(eta < MF_R(1e3)))
        return MF_ERROR_INVALID_ARGUMENT;
    t->E = (mf_real *)MF_MALLOC(sizeof(mf_real) * 2 * (size_t)n_mu);
    if (!t->E) return MF_ERROR_OUT_OF_MEMORY;
    row = (double *)MF_MALLOC(sizeof(double) * (size_t)n_mu);
    if (!row) { MF_FREE(t->E); t->E = 0; return MF_ERROR_OUT_OF_MEMORY; }
    for (s = 0; s < 2; ++s) {
        for (i = 0; i < n_mu; ++i) {
            mf_vec3 w = mf__energy_node_dir(i, n_mu, MF_R(0.0));
            mf_real e;
            if (s) w.z = -w.z;
            e = mf_dielectric_albedo_integrate(d, w, eta, panels);
            if (!(e >= MF_R(0.0)) || !(e <= MF_R(1.0))) { MF_FREE(row); mf_dielectric_ms_release(t); return MF_ERROR_INVALID_DATA; }
            t->E[(size_t)s * (size_t)n_mu + (size_t)i] = e;
            row[i] = (double)e;
        }
        avg[s] = mf__energy_avg_1d(row, n_mu);
    }
    MF_FREE(row);
    /* shares: x from above, y from below = x (1 - E1avg) / (eta^2 (1 - E2avg)) */
    /* from the averages as stored, so that reciprocity holds in mf_real */
    avg[0] = (double)(mf_real)avg[0];
    avg[1] = (double)(mf_real)avg[1];
    x = 1.0 - (double)mf_fresnel_dielectric_average(eta);
    y = 1.0 - avg[1] > 1e-9 ? x * (1.0 - avg[0]) / ((double)eta * (double)eta * (1.0 - avg[1])) : 0.0;
    if (y > 1.0) { x /= y; y = 1.0; }
    t->n_mu = n_mu;
    t->eta = eta;
    t->E1_avg = (mf_real)avg[0];
    t->E2_avg = (mf_real)avg[1];
    t->x = (mf_real)x;
    t->y = (mf_real)y;
    return MF_SUCCESS;
}

MFDEF mf_real mf_dielectric_albedo(const mf_dielectric_ms_table *t, mf_vec3 wo)
{
    mf_real mu, fx;
    const mf_real *E;
    int i;
    if (!t || !t->E || t->n_mu < 2 || !(wo.z != MF_R(0.0))) return MF_R(0.0);
    mu = mf__energy_mu(wo);
    if (!(mu >= MF_R(0.0))) return MF_R(0.0);
    E = t->E + (wo.z < MF_R(0.0) ? t->n_mu : 0);
    fx = mf__energy_segment(mu, t->n_mu, &i);
    return E[i] * (MF_R(1.0) - fx) + E[i + 1] * fx;
}

/* importance-form lobe value (1 - E(wo)) (1 - E(wi)) share / (pi (1 - E_avg of wi's side)) */
MF_INLINE mf_real mf__dielectric_ms_imp(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_vec3 wi)
{
    int below_o = wo.z < MF_R(0.0), below_i = wi.z < MF_R(0.0);
    mf_real share = below_o ? (below_i ? MF_R(1.0) - t->y : t->y) : (below_i ? t->x : MF_R(1.0) - t->x);
    mf_real ea = below_i ? t->E2_avg : t->E1_avg, den = MF_PI * (MF_R(1.0) - ea);
    if (!(den > MF_R(1e-6))) return MF_R(0.0);
    return mf_clamp(share * (MF_R(1.0) - mf_dielectric_albedo(t, wo)) * (MF_R(1.0) - mf_dielectric_albedo(t, wi)) / den,
                    MF_R(0.0), MF_BIG);
}

MFDEF mf_real mf_dielectric_bsdf_ms(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_vec3 wi)
{
    mf_real f, e;
    if (!t || !t->E || !(wo.z != MF_R(0.0)) || !(wi.z != MF_R(0.0)) || !(wo.z == wo.z) || !(wi.z == wi.z)) return MF_R(0.0);
    f = mf__dielectric_ms_imp(t, wo, wi);
    if (wo.z * wi.z > MF_R(0.0)) return f;
    e = wo.z > MF_R(0.0) ? t->eta : MF_R(1.0) / t->eta;   /* eta_i / eta_o */
    return f / (e * e);
}

MFDEF mf_vec3 mf_dielectric_ms_sample(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_real u1, mf_real u2, mf_real u3)
{
    mf_vec3 w;
    mf_real share;
    if (!t || !t->E || !(wo.z != MF_R(0.0)) || !(wo.z == wo.z)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    w = mf_brdf_ms_sample(0, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0)), u1, u2);
    share = wo.z < MF_R(0.0) ? t->y : t->x;   /* transmitted share */
    if (!(mf__u01(u3) >= share)) w.z = -w.z;  /* transmission: the other side */
    if (wo.z < MF_R(0.0)) w.z = -w.z;
    return w;
}

MFDEF mf_real mf_dielectric_ms_pdf(const mf_dielectric_ms_table *t, mf_vec3 wo, mf_vec3 wi)
{
    mf_real share;
    if (!t || !t->E || !(wo.z != MF_R(0.0)) || !(wi.z != MF_R(0.0)) || !(wo.z == wo.z) || !(wi.z == wi.z)) return MF_R(0.0);
    share = wo.z < MF_R(0.0) ? t->y : t->x;
    if (wo.z * wi.z < MF_R(0.0)) return share * mf_min(MF_FABS(wi.z), MF_R(1.0)) / MF_PI;
    return (MF_R(1.0) - share) * mf_min(MF_FABS(wi.z), MF_R(1.0)) / MF_PI;
}

#ifdef __cplusplus
}
#endif
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
