/* microfacet.h - GENERATED FILE, do not edit: edit the module sources in
 * src/ and run `make header` (tools/amalgamate.sh). Assembled from:
 *   00_intro.h 01_config.h 02_vec.h 03_fresnel.h 04_special.h 05_ndf.h
 *   06_kind_beckmann.h 06_kind_ggx.h 06_kind_gtr.h 06_kind_leadr.h
 *   06_kind_student_t.h 06_kind_tabulated.h 07_numeric_vndf.h 08_transform.h
 *   09_smith.h 10_sampling.h 11_brdf.h 11_dielectric.h 12_leadr.h 13_ltc.h
 *   14_ltc_table.h 15_ibm.h 16_microsurface.h 17_energy_table.h 18_energy.h
 *   99_outro.h
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
#if defined(__CUDACC__)
#define MF__LTC_NOINLINE static __noinline__ MF_HD
#elif defined(__GNUC__) || defined(__clang__)
#define MF__LTC_NOINLINE static __attribute__((noinline, unused))
#else
#define MF__LTC_NOINLINE MF_INLINE
#endif

/* theta / sin theta for d = cos theta in [0, 1]: a (2, 2) rational fit,
 * relative error 5.6e-7 (minimax in the relative error, fitted in long
 * double; a (3, 3) fit reaches 1.1e-9 at two more multiply-adds). */
MF__LTC_HOT mf_real mf__ts_p(mf_real d)
{
    return MF_R(1.5707954524054327) + d * (MF_R(0.90581169693094948) + d * MF_R(0.026032047669933955));
}
MF__LTC_HOT mf_real mf__ts_q(mf_real d)
{
    return MF_R(1.0) + d * (MF_R(1.2132377142117774) + d * MF_R(0.28940008969878159));
}
MF__LTC_HOT mf_real mf__theta_sin(mf_real d) { return mf__ts_p(d) / mf__ts_q(d); }

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
/* the z component beyond pi/2: c = a x (a + b), pi / |c| - f(-d) over one
 * division */
MF__LTC_HOT mf_real mf__edge_z_obtuse(mf_real ax, mf_real ay, mf_real az, mf_real bx, mf_real by, mf_real bz, mf_real d)
{
    mf_real cx = ay * (az + bz) - az * (ay + by), cy = az * (ax + bx) - ax * (az + bz);
    mf_real cz = ax * (ay + by) - ay * (ax + bx), s2 = cx * cx + cy * cy + cz * cz, sn, p, q;
    if (!(s2 > MF_R(1e-30))) return MF_R(0.0);
    sn = MF_SQRT(s2);
    p = mf__ts_p(-d); q = mf__ts_q(-d);
    return cz * (MF_PI * q - p * sn) / (sn * q);
}
/* its z component only (scalar arguments, then vectors) */
MF__LTC_HOT mf_real mf__edge_zs(mf_real ax, mf_real ay, mf_real az, mf_real bx, mf_real by, mf_real bz)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_vector_exact(mf_vec3_make(ax, ay, az), mf_vec3_make(bx, by, bz)).z;
#else
    mf_real d = ax * bx + ay * by + az * bz;
    if (d >= MF_R(0.0)) return (ax * (by - ay) - ay * (bx - ax)) * mf__theta_sin(d);
    return mf__edge_z_obtuse(ax, ay, az, bx, by, bz, d);
#endif
}
MF__LTC_HOT mf_real mf__edge_z(mf_vec3 a, mf_vec3 b) { return mf__edge_zs(a.x, a.y, a.z, b.x, b.y, b.z); }
/* an edge along the horizon (unit a, b with z = 0), often obtuse in clipped
 * lights: a x b = (0, 0, c) with sin theta = |c|, so beyond pi/2 the edge is
 * sign(c) pi - c f(-d), no square root */
MF__LTC_HOT mf_real mf__edge_z_horizon(mf_real ax, mf_real ay, mf_real bx, mf_real by)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_zs(ax, ay, MF_R(0.0), bx, by, MF_R(0.0));
#else
    mf_real d = ax * bx + ay * by, c;
    if (d >= MF_R(0.0)) return (ax * (by - ay) - ay * (bx - ax)) * mf__theta_sin(d);
    c = ax * (ay + by) - ay * (ax + bx);
    if (c == MF_R(0.0)) return MF_R(0.0);   /* antipodal */
    return (c > MF_R(0.0) ? MF_PI : -MF_PI) - c * mf__theta_sin(-d);
#endif
}
/* Sums of edges as one fraction n / q: an acute edge adds c p(d) / q(d),
 * the rational fit's own numerator and denominator, so that a quad pays one
 * division for its edges (q in [1, 2.5] per acute edge: no overflow for the
 * five edges of a clipped quad); an obtuse edge adds its value. */
MF__LTC_HOT void mf__edge_add(mf_real ax, mf_real ay, mf_real az, mf_real bx, mf_real by, mf_real bz, mf_real *n, mf_real *q)
{
#ifdef MF_LTC_EXACT_EDGE
    *n += mf__edge_zs(ax, ay, az, bx, by, bz) * *q;
#else
    mf_real d = ax * bx + ay * by + az * bz, c, qd;
    if (d >= MF_R(0.0)) {
        c = ax * (by - ay) - ay * (bx - ax);
        qd = mf__ts_q(d);
        *n = *n * qd + c * mf__ts_p(d) * *q;
        *q *= qd;
    } else *n += mf__edge_z_obtuse(ax, ay, az, bx, by, bz, d) * *q;
#endif
}
/* the same for an edge along the horizon (mf__edge_z_horizon) */
MF__LTC_HOT void mf__edge_add_horizon(mf_real ax, mf_real ay, mf_real bx, mf_real by, mf_real *n, mf_real *q)
{
#ifdef MF_LTC_EXACT_EDGE
    *n += mf__edge_z_horizon(ax, ay, bx, by) * *q;
#else
    mf_real d = ax * bx + ay * by, c, qd;
    if (d >= MF_R(0.0)) {
        c = ax * (by - ay) - ay * (bx - ax);
        qd = mf__ts_q(d);
        *n = *n * qd + c * mf__ts_p(d) * *q;
    } else {
        c = ax * (ay + by) - ay * (ax + bx);
        if (c == MF_R(0.0)) return;   /* antipodal */
        qd = mf__ts_q(-d);
        *n = *n * qd + ((c > MF_R(0.0) ? MF_PI : -MF_PI) * qd - c * mf__ts_p(-d)) * *q;
    }
    *q *= qd;
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

/* x, y, z transformed by the row-major A in place; the sparse form
 * [a 0 b; 0 c 0; d 0 e] of the LTC tables (and of mf_ltc_from_inverse) in 5
 * products instead of 9 */
#define MF__LTC_XF(A, x, y, z) do { \
        mf_real tx_ = (A)[0] * (x) + (A)[1] * (y) + (A)[2] * (z), tz_ = (A)[6] * (x) + (A)[7] * (y) + (A)[8] * (z); \
        (y) = (A)[3] * (x) + (A)[4] * (y) + (A)[5] * (z); (x) = tx_; (z) = tz_; \
    } while (0)
#define MF__LTC_SPARSE(A) ((A)[1] == MF_R(0.0) && (A)[3] == MF_R(0.0) && (A)[5] == MF_R(0.0) && (A)[7] == MF_R(0.0))
#define MF__LTC_XF_SPARSE(A, x, y, z) do { \
        mf_real tx_ = (A)[0] * (x) + (A)[2] * (z); \
        (z) = (A)[6] * (x) + (A)[8] * (z); (y) *= (A)[4]; (x) = tx_; \
    } while (0)
/* A quad, the common light, in scalar temporaries (no vertex structs in
 * memory: gcc pairs x with y across them, and the shuffles cost more than
 * the pairing saves). Above the horizon: normalized and summed straight. A
 * planar quad crosses the horizon at most twice, so its vertices above it
 * form one run s..s+k-1 (start and length per pattern of signs: the nibbles
 * of two constants, patterns 0-7 and 8-15); the run, the exit point and the entry point make the
 * clipped polygon. The two patterns with two runs go to the general loop. */
MF__LTC_RARE mf_real mf__quad_two_runs(mf_real x0, mf_real y0, mf_real z0, mf_real x1, mf_real y1, mf_real z1,
                                       mf_real x2, mf_real y2, mf_real z2, mf_real x3, mf_real y3, mf_real z3)
{
    mf_vec3 v[4];
    v[0] = mf_vec3_make(x0, y0, z0); v[1] = mf_vec3_make(x1, y1, z1);
    v[2] = mf_vec3_make(x2, y2, z2); v[3] = mf_vec3_make(x3, y3, z3);
    return mf__polygon_clipped((const mf_real *)0, v, 4);
}
/* the unit vector of (x, y, z) in place (0 stays 0) */
#define MF__LTC_UNIT(x, y, z) do { \
        mf_real l2_ = (x) * (x) + (y) * (y) + (z) * (z), r_ = l2_ > MF_R(0.0) ? MF_R(1.0) / MF_SQRT(l2_) : MF_R(0.0); \
        (x) *= r_; (y) *= r_; (z) *= r_; \
    } while (0)
/* the unit horizon point of the segment from u (above) to d (below, or on
 * it): u.z d - d.z u (both weights >= 0), z = 0 */
#define MF__LTC_HORIZON(hx, hy, ux, uy, uz, dx, dy, dz) do { \
        mf_real hz_ = MF_R(0.0); \
        hx = (uz) * (dx) - (dz) * (ux); hy = (uz) * (dy) - (dz) * (uy); \
        MF__LTC_UNIT(hx, hy, hz_); \
    } while (0)
MF__LTC_NOINLINE mf_real mf__quad_clipped(mf_real x0, mf_real y0, mf_real z0, mf_real x1, mf_real y1, mf_real z1,
                                          mf_real x2, mf_real y2, mf_real z2, mf_real x3, mf_real y3, mf_real z3, int cfg)
{
    int code = (int)((cfg < 8 ? 0x85024100u >> (4 * cfg) : 0x09A6B073u >> (4 * cfg - 32)) & 15u), s = code & 3, k = (code >> 2) + 1;
    mf_real t, sum, ax, ay, az, ex, ey, nx, ny;
    if (cfg == 0) return MF_R(0.0);
    if (cfg == 5 || cfg == 10) return mf__quad_two_runs(x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3);
    for (; s > 0; --s) {   /* rotate: the run starts at vertex 0 */
        t = x0; x0 = x1; x1 = x2; x2 = x3; x3 = t;
        t = y0; y0 = y1; y1 = y2; y2 = y3; y3 = t;
        t = z0; z0 = z1; z1 = z2; z2 = z3; z3 = t;
    }
    /* the horizon points from the vertices as they are (u.z d - d.z u scales
     * with u): off the dependency chain of the normalizations */
    if (k == 1) MF__LTC_HORIZON(ex, ey, x0, y0, z0, x1, y1, z1);
    else if (k == 2) MF__LTC_HORIZON(ex, ey, x1, y1, z1, x2, y2, z2);
    else MF__LTC_HORIZON(ex, ey, x2, y2, z2, x3, y3, z3);
    MF__LTC_HORIZON(nx, ny, x0, y0, z0, x3, y3, z3);
    MF__LTC_UNIT(x0, y0, z0);
    ax = x0; ay = y0; az = z0;
    sum = MF_R(0.0); t = MF_R(1.0);
    if (k >= 2) {
        MF__LTC_UNIT(x1, y1, z1);
        mf__edge_add(x0, y0, z0, x1, y1, z1, &sum, &t);
        ax = x1; ay = y1; az = z1;
        if (k == 3) {
            MF__LTC_UNIT(x2, y2, z2);
            mf__edge_add(x1, y1, z1, x2, y2, z2, &sum, &t);
            ax = x2; ay = y2; az = z2;
        }
    }
    mf__edge_add(ax, ay, az, ex, ey, MF_R(0.0), &sum, &t);
    mf__edge_add_horizon(ex, ey, nx, ny, &sum, &t);
    mf__edge_add(nx, ny, MF_R(0.0), x0, y0, z0, &sum, &t);
    return sum / t;
}
MF_INLINE mf_real mf__quad_sum(const mf_real *A, const mf_vec3 *p)
{
    mf_real x0 = p[0].x, y0 = p[0].y, z0 = p[0].z, x1 = p[1].x, y1 = p[1].y, z1 = p[1].z;
    mf_real x2 = p[2].x, y2 = p[2].y, z2 = p[2].z, x3 = p[3].x, y3 = p[3].y, z3 = p[3].z, n0, q0, n1, q1;
    int cfg;
    if (!A) {
    } else if (MF__LTC_SPARSE(A)) {
        MF__LTC_XF_SPARSE(A, x0, y0, z0); MF__LTC_XF_SPARSE(A, x1, y1, z1);
        MF__LTC_XF_SPARSE(A, x2, y2, z2); MF__LTC_XF_SPARSE(A, x3, y3, z3);
    } else {
        MF__LTC_XF(A, x0, y0, z0); MF__LTC_XF(A, x1, y1, z1); MF__LTC_XF(A, x2, y2, z2); MF__LTC_XF(A, x3, y3, z3);
    }
    cfg = (z0 > MF_R(0.0)) | (z1 > MF_R(0.0)) << 1 | (z2 > MF_R(0.0)) << 2 | (z3 > MF_R(0.0)) << 3;
    if (cfg != 15) return mf__quad_clipped(x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3, cfg);
    MF__LTC_UNIT(x0, y0, z0); MF__LTC_UNIT(x1, y1, z1); MF__LTC_UNIT(x2, y2, z2); MF__LTC_UNIT(x3, y3, z3);
    n0 = n1 = MF_R(0.0); q0 = q1 = MF_R(1.0);
    mf__edge_add(x0, y0, z0, x1, y1, z1, &n0, &q0); mf__edge_add(x1, y1, z1, x2, y2, z2, &n0, &q0);
    mf__edge_add(x2, y2, z2, x3, y3, z3, &n1, &q1); mf__edge_add(x3, y3, z3, x0, y0, z0, &n1, &q1);
    return (n0 * q1 + n1 * q0) / (q0 * q1);
}

/* Other polygons above the horizon in blocks of 16 vertices (transform and
 * normalize into three scalar buffers, then the edges as one fraction, q
 * below 2.5^16); the first vertex below the horizon hands over to the
 * clipping loop. */
MF__LTC_NOINLINE mf_real mf__ngon_sum(const mf_real *A, const mf_vec3 *p, int n)
{
    mf_real ux[16], uy[16], uz[16], x, y, z, px = MF_R(0.0), py = MF_R(0.0), pz = MF_R(0.0);
    mf_real fx = MF_R(0.0), fy = MF_R(0.0), fz = MF_R(0.0), sum = MF_R(0.0);
    int base, k, m, sparse = A && MF__LTC_SPARSE(A);
    for (base = 0; base < n; base += 16) {
        m = n - base < 16 ? n - base : 16;
        for (k = 0; k < m; ++k) {
            x = p[base + k].x; y = p[base + k].y; z = p[base + k].z;
            if (!A) {
            } else if (sparse) MF__LTC_XF_SPARSE(A, x, y, z);
            else MF__LTC_XF(A, x, y, z);
            if (!(z > MF_R(0.0))) goto clip;
            MF__LTC_UNIT(x, y, z);
            ux[k] = x; uy[k] = y; uz[k] = z;
        }
        if (base == 0) { fx = ux[0]; fy = uy[0]; fz = uz[0]; }
        else sum += mf__edge_zs(px, py, pz, ux[0], uy[0], uz[0]);
        for (k = 0; k + 1 < m; ++k) sum += mf__edge_zs(ux[k], uy[k], uz[k], ux[k + 1], uy[k + 1], uz[k + 1]);
        px = ux[m - 1]; py = uy[m - 1]; pz = uz[m - 1];
    }
    return sum + mf__edge_zs(px, py, pz, fx, fy, fz);
clip:
    return mf__polygon_clipped(A, p, n);
}

/* The signed sum of the polygon transformed by A, clipped at the horizon. */
MF_INLINE mf_real mf__polygon_sum(const mf_real *A, const mf_vec3 *p, int n)
{
    if (!p || n < 3) return MF_R(0.0);
    if (n == 4) return mf__quad_sum(A, p);
    return mf__ngon_sum(A, p, n);
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
 * (upload the table instead). Fitted in about 200 s (double, one core). */
#ifndef MF_NO_LTC_TABLE
MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha);
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha);
#endif
/* Generated by tools/ltc_fit.c (`make ltc-table`): do not edit. */
/* ======================================================================== */
/* == 14. The built-in LTC table of GGX                                     */
/* ======================================================================== */
/* 64 x 64 LTC fits of the GGX BRDF times cos(theta_i) (mf_ltc_table_build,
 * fitted in double), rows sqrt(alpha), columns sqrt(1 - cos theta_o), six
 * floats per entry: inv0..inv3 with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3],
 * the albedo and the Fresnel column. Read through mf_ltc_ggx, mf_ltc_ggx_albedo,
 * mf_ltc_ggx_fresnel and mf_ltc_ggx_table (13_ltc.h). */
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
    {   /* mf_ltc_from_inverse with c = 1 */
        mf_ltc l;
        mf_real q = v[0] * v[3] - v[1] * v[2], rq, h = MF_LTC_MIN_DET_REL * MF_LTC_MIN_DET_REL;
        if (!(q * q > h * (v[0] * v[0] + v[1] * v[1]) * (v[2] * v[2] + v[3] * v[3])) || !(MF_FABS(q) * MF_BIG > MF_R(1.0)) ||
            !(MF_FABS(v[0]) + MF_FABS(v[1]) + MF_FABS(v[2]) + MF_FABS(v[3]) < MF_BIG))
            return mf_ltc_from_inverse(MF_R(1.0), MF_R(0.0), MF_R(1.0), MF_R(0.0), MF_R(1.0));
        rq = MF_R(1.0) / q;
        l.Minv[0] = v[0]; l.Minv[1] = MF_R(0.0); l.Minv[2] = v[1];
        l.Minv[3] = MF_R(0.0); l.Minv[4] = MF_R(1.0); l.Minv[5] = MF_R(0.0);
        l.Minv[6] = v[2]; l.Minv[7] = MF_R(0.0); l.Minv[8] = v[3];
        l.M[0] = v[3] * rq; l.M[1] = MF_R(0.0); l.M[2] = -v[1] * rq;
        l.M[3] = MF_R(0.0); l.M[4] = MF_R(1.0); l.M[5] = MF_R(0.0);
        l.M[6] = -v[2] * rq; l.M[7] = MF_R(0.0); l.M[8] = v[0] * rq;
        l.det_inv = MF_FABS(q);
        return l;
    }
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
#endif
#ifndef MF_NO_LTC_TABLE
static const float *mf__ltc_ggx_data(int *n)
{
    static const float data[64 * 64 * 6] = {
1.0f,1.587e-14f,-6.18342e-22f,0.002f,1.0f,4.26386e-21f, 0.999496f,0.0224408f,-4.48815e-05f,0.00199899f,1.0f,2.3843e-18f,
0.997985f,0.0448391f,-8.96782e-05f,0.00199597f,1.0f,1.16261e-15f, 0.99547f,0.0671527f,-0.000134305f,0.00199094f,1.0f,6.24941e-14f,
0.991954f,0.0893392f,-0.000178678f,0.00198391f,1.0f,1.08813e-12f, 0.987442f,0.111356f,-0.000222713f,0.00197488f,1.0f,1.00501e-11f,
0.981942f,0.133162f,-0.000266325f,0.00196388f,1.0f,6.19597e-11f, 0.975461f,0.154715f,-0.00030943f,0.00195092f,1.0f,2.88719e-10f,
0.96801f,0.175973f,-0.000351946f,0.00193602f,1.0f,1.0957e-09f, 0.9596f,0.196895f,-0.00039379f,0.0019192f,1.0f,3.55419e-09f,
0.950244f,0.21744f,-0.000434879f,0.00190049f,1.0f,1.01854e-08f, 0.939957f,0.237567f,-0.000475133f,0.00187991f,1.0f,2.6403e-08f,
0.928754f,0.257235f,-0.00051447f,0.00185751f,1.0f,6.30015e-08f, 0.916653f,0.276406f,-0.000552811f,0.00183331f,1.0f,1.40225e-07f,
0.903673f,0.295039f,-0.000590077f,0.00180735f,1.0f,2.94142e-07f, 0.889835f,0.313095f,-0.00062619f,0.00177967f,1.0f,5.86267e-07f,
0.87516f,0.330537f,-0.000661073f,0.00175032f,1.0f,1.11765e-06f, 0.859673f,0.347326f,-0.00069465f,0.00171935f,1.0f,2.04896e-06f,
0.843399f,0.363425f,-0.000726848f,0.0016868f,1.0f,3.6284e-06f, 0.826363f,0.378797f,-0.000757593f,0.00165273f,1.0f,6.22991e-06f,
0.808595f,0.393407f,-0.000786813f,0.00161719f,1.0f,1.04042e-05f, 0.790123f,0.40722f,-0.000814439f,0.00158025f,1.0f,1.6946e-05f,
0.77098f,0.420202f,-0.000840402f,0.00154196f,1.0f,2.69819e-05f, 0.751199f,0.432319f,-0.000864635f,0.0015024f,1.0f,4.20823e-05f,
0.730812f,0.443538f,-0.000887074f,0.00146163f,1.0f,6.44038e-05f, 0.709856f,0.453829f,-0.000907655f,0.00141971f,1.0f,9.68679e-05f,
0.688369f,0.46316f,-0.000926317f,0.00137674f,1.0f,0.000143383f, 0.666389f,0.471503f,-0.000943003f,0.00133278f,1.0f,0.000209115f,
0.643957f,0.478828f,-0.000957654f,0.00128792f,1.0f,0.000300825f, 0.621114f,0.48511f,-0.000970216f,0.00124223f,1.0f,0.000427269f,
0.597904f,0.490321f,-0.000980639f,0.00119581f,1.0f,0.000599685f, 0.574373f,0.494438f,-0.000988872f,0.00114875f,1.0f,0.000832372f,
0.550565f,0.497437f,-0.00099487f,0.00110113f,1.0f,0.00114338f, 0.52653f,0.499296f,-0.000998588f,0.00105306f,1.0f,0.00155533f,
0.502317f,0.499995f,-0.000999986f,0.00100464f,1.0f,0.00209635f, 0.477976f,0.499515f,-0.000999026f,0.000955957f,1.0f,0.00280123f,
0.453561f,0.497839f,-0.000995674f,0.000907128f,1.0f,0.00371267f, 0.429126f,0.494952f,-0.000989899f,0.000858257f,1.0f,0.00488284f,
0.404726f,0.490839f,-0.000981674f,0.000809458f,1.0f,0.00637507f, 0.380418f,0.48549f,-0.000970975f,0.000760842f,1.0f,0.0082659f,
0.356261f,0.478894f,-0.000957783f,0.000712529f,1.0f,0.0106473f, 0.332315f,0.471044f,-0.000942082f,0.000664638f,1.0f,0.0136293f,
0.308643f,0.461934f,-0.000923862f,0.000617292f,0.999999f,0.0173429f, 0.285306f,0.45156f,-0.000903115f,0.000570619f,0.999999f,0.0219437f,
0.26237f,0.439923f,-0.00087984f,0.000524747f,0.999999f,0.0276152f, 0.239901f,0.427023f,-0.000854041f,0.00047981f,0.999999f,0.0345734f,
0.217967f,0.412865f,-0.000825724f,0.000435942f,0.999999f,0.0430717f, 0.196637f,0.397455f,-0.000794906f,0.000393283f,0.999999f,0.0534058f,
0.175982f,0.380805f,-0.000761605f,0.000351974f,0.999999f,0.0659202f, 0.156074f,0.362926f,-0.000725847f,0.000312159f,0.999999f,0.0810146f,
0.136988f,0.343835f,-0.000687666f,0.000273987f,0.999998f,0.0991513f, 0.118799f,0.323552f,-0.000647099f,0.000237609f,0.999998f,0.120864f,
0.101583f,0.302099f,-0.000604195f,0.000203178f,0.999998f,0.146765f, 0.0854194f,0.279505f,-0.000559006f,0.000170851f,0.999997f,0.17756f,
0.0703879f,0.2558f,-0.000511596f,0.000140788f,0.999997f,0.214052f, 0.0565699f,0.231019f,-0.000462035f,0.000113153f,0.999996f,0.257159f,
0.0440487f,0.205203f,-0.000410404f,8.81107e-05f,0.999995f,0.307928f, 0.0329086f,0.178397f,-0.000356792f,6.58308e-05f,0.999993f,0.367544f,
0.0232358f,0.150651f,-0.000301301f,4.64855e-05f,0.999989f,0.43735f, 0.0151179f,0.122021f,-0.000244042f,3.02499e-05f,0.999984f,0.518862f,
0.00864401f,0.0925697f,-0.000185139f,1.73023e-05f,0.999971f,0.613786f, 0.00390477f,0.0623649f,-0.000124731f,7.82395e-06f,0.999936f,0.724008f,
0.000992413f,0.0314853f,-6.29632e-05f,1.99942e-06f,0.999515f,0.851221f, 3.05349e-06f,0.00186218f,-3.1516e-06f,2.45476e-08f,0.892067f,0.874534f,
1.0f,-2.73541e-13f,-6.18342e-22f,0.002f,1.0f,4.26386e-21f, 0.999496f,0.0224408f,-4.48815e-05f,0.00199899f,1.0f,2.3843e-18f,
0.997985f,0.0448391f,-8.96782e-05f,0.00199597f,1.0f,1.16261e-15f, 0.99547f,0.0671527f,-0.000134305f,0.00199094f,1.0f,6.24941e-14f,
0.991954f,0.0893392f,-0.000178678f,0.00198391f,1.0f,1.08813e-12f, 0.987442f,0.111356f,-0.000222713f,0.00197488f,1.0f,1.00501e-11f,
0.981942f,0.133162f,-0.000266325f,0.00196388f,1.0f,6.19597e-11f, 0.975461f,0.154715f,-0.00030943f,0.00195092f,1.0f,2.88719e-10f,
0.96801f,0.175973f,-0.000351946f,0.00193602f,1.0f,1.0957e-09f, 0.9596f,0.196895f,-0.00039379f,0.0019192f,1.0f,3.55419e-09f,
0.950244f,0.21744f,-0.000434879f,0.00190049f,1.0f,1.01854e-08f, 0.939957f,0.237567f,-0.000475133f,0.00187991f,1.0f,2.6403e-08f,
0.928754f,0.257235f,-0.00051447f,0.00185751f,1.0f,6.30015e-08f, 0.916653f,0.276406f,-0.000552811f,0.00183331f,1.0f,1.40225e-07f,
0.903673f,0.295039f,-0.000590077f,0.00180735f,1.0f,2.94142e-07f, 0.889835f,0.313095f,-0.00062619f,0.00177967f,1.0f,5.86267e-07f,
0.87516f,0.330537f,-0.000661073f,0.00175032f,1.0f,1.11765e-06f, 0.859673f,0.347326f,-0.00069465f,0.00171935f,1.0f,2.04896e-06f,
0.843399f,0.363425f,-0.000726848f,0.0016868f,1.0f,3.6284e-06f, 0.826363f,0.378797f,-0.000757593f,0.00165273f,1.0f,6.22991e-06f,
0.808595f,0.393407f,-0.000786813f,0.00161719f,1.0f,1.04042e-05f, 0.790123f,0.40722f,-0.000814439f,0.00158025f,1.0f,1.6946e-05f,
0.77098f,0.420202f,-0.000840402f,0.00154196f,1.0f,2.69819e-05f, 0.751199f,0.432319f,-0.000864635f,0.0015024f,1.0f,4.20823e-05f,
0.730812f,0.443538f,-0.000887074f,0.00146163f,1.0f,6.44038e-05f, 0.709856f,0.453829f,-0.000907655f,0.00141971f,1.0f,9.68679e-05f,
0.688369f,0.46316f,-0.000926317f,0.00137674f,1.0f,0.000143383f, 0.666389f,0.471503f,-0.000943003f,0.00133278f,1.0f,0.000209115f,
0.643957f,0.478828f,-0.000957654f,0.00128792f,1.0f,0.000300825f, 0.621114f,0.48511f,-0.000970216f,0.00124223f,1.0f,0.000427269f,
0.597904f,0.490321f,-0.000980639f,0.00119581f,1.0f,0.000599685f, 0.574373f,0.494438f,-0.000988872f,0.00114875f,1.0f,0.000832372f,
0.550565f,0.497437f,-0.00099487f,0.00110113f,1.0f,0.00114338f, 0.52653f,0.499296f,-0.000998588f,0.00105306f,1.0f,0.00155533f,
0.502317f,0.499995f,-0.000999986f,0.00100464f,1.0f,0.00209635f, 0.477976f,0.499515f,-0.000999026f,0.000955957f,1.0f,0.00280123f,
0.453561f,0.497839f,-0.000995674f,0.000907128f,1.0f,0.00371267f, 0.429126f,0.494952f,-0.000989899f,0.000858257f,1.0f,0.00488284f,
0.404726f,0.490839f,-0.000981674f,0.000809458f,1.0f,0.00637507f, 0.380418f,0.48549f,-0.000970975f,0.000760842f,1.0f,0.0082659f,
0.356261f,0.478894f,-0.000957783f,0.000712529f,1.0f,0.0106473f, 0.332315f,0.471044f,-0.000942082f,0.000664638f,1.0f,0.0136293f,
0.308643f,0.461933f,-0.000923862f,0.000617292f,0.999999f,0.0173429f, 0.285306f,0.45156f,-0.000903115f,0.000570619f,0.999999f,0.0219437f,
0.26237f,0.439923f,-0.00087984f,0.000524747f,0.999999f,0.0276152f, 0.239901f,0.427023f,-0.000854041f,0.00047981f,0.999999f,0.0345734f,
0.217966f,0.412865f,-0.000825724f,0.000435942f,0.999999f,0.0430717f, 0.196637f,0.397455f,-0.000794906f,0.000393283f,0.999999f,0.0534058f,
0.175982f,0.380805f,-0.000761605f,0.000351974f,0.999999f,0.0659202f, 0.156074f,0.362926f,-0.000725847f,0.000312159f,0.999999f,0.0810146f,
0.136988f,0.343835f,-0.000687666f,0.000273987f,0.999998f,0.0991513f, 0.118799f,0.323552f,-0.000647099f,0.000237609f,0.999998f,0.120864f,
0.101583f,0.302099f,-0.000604195f,0.000203178f,0.999998f,0.146765f, 0.0854194f,0.279505f,-0.000559006f,0.000170851f,0.999997f,0.17756f,
0.0703878f,0.255799f,-0.000511596f,0.000140788f,0.999997f,0.214052f, 0.05657f,0.231019f,-0.000462035f,0.000113153f,0.999996f,0.257159f,
0.0440487f,0.205203f,-0.000410404f,8.81106e-05f,0.999995f,0.307928f, 0.0329086f,0.178397f,-0.000356792f,6.58308e-05f,0.999993f,0.367544f,
0.0232358f,0.150651f,-0.000301301f,4.64855e-05f,0.999989f,0.43735f, 0.0151179f,0.122021f,-0.000244042f,3.02499e-05f,0.999984f,0.518862f,
0.00864402f,0.0925699f,-0.00018514f,1.73023e-05f,0.999971f,0.613786f, 0.00390476f,0.0623647f,-0.000124731f,7.82393e-06f,0.999936f,0.724008f,
0.000992415f,0.0314853f,-6.29632e-05f,1.99942e-06f,0.999515f,0.851221f, 3.04814e-06f,0.00185874f,-3.14609e-06f,2.45047e-08f,0.892067f,0.874534f,
1.0f,1.66411e-13f,-3.86281e-22f,0.00201562f,1.0f,4.6087e-21f, 0.999496f,0.0224408f,-4.5232e-05f,0.00201461f,1.0f,2.433e-18f,
0.997985f,0.0448391f,-9.03786e-05f,0.00201156f,1.0f,1.16528e-15f, 0.99547f,0.0671527f,-0.000135354f,0.00200649f,1.0f,6.25409e-14f,
0.991954f,0.0893392f,-0.000180074f,0.0019994f,1.0f,1.08854e-12f, 0.987442f,0.111356f,-0.000224452f,0.00199031f,1.0f,1.00524e-11f,
0.981942f,0.133162f,-0.000268405f,0.00197922f,1.0f,6.19689e-11f, 0.975461f,0.154715f,-0.000311847f,0.00196616f,1.0f,2.8875e-10f,
0.96801f,0.175973f,-0.000354695f,0.00195114f,1.0f,1.09579e-09f, 0.9596f,0.196895f,-0.000396866f,0.00193419f,1.0f,3.55441e-09f,
0.950244f,0.21744f,-0.000438276f,0.00191533f,1.0f,1.01859e-08f, 0.939957f,0.237567f,-0.000478844f,0.0018946f,1.0f,2.64041e-08f,
0.928754f,0.257235f,-0.000518488f,0.00187202f,1.0f,6.30037e-08f, 0.916653f,0.276406f,-0.000557129f,0.00184763f,1.0f,1.40229e-07f,
0.903673f,0.295039f,-0.000594686f,0.00182146f,1.0f,2.94149e-07f, 0.889835f,0.313095f,-0.000631081f,0.00179357f,1.0f,5.86279e-07f,
0.87516f,0.330537f,-0.000666236f,0.00176399f,1.0f,1.11767e-06f, 0.859673f,0.347326f,-0.000700076f,0.00173278f,1.0f,2.04899e-06f,
0.843399f,0.363425f,-0.000732525f,0.00169997f,1.0f,3.62845e-06f, 0.826363f,0.378797f,-0.00076351f,0.00166564f,1.0f,6.22999e-06f,
0.808595f,0.393407f,-0.000792958f,0.00162982f,1.0f,1.04043e-05f, 0.790123f,0.40722f,-0.0008208f,0.00159259f,1.0f,1.69462e-05f,
0.77098f,0.420202f,-0.000846966f,0.00155401f,1.0f,2.69822e-05f, 0.751199f,0.432319f,-0.000871388f,0.00151413f,1.0f,4.20826e-05f,
0.730812f,0.443538f,-0.000894002f,0.00147304f,1.0f,6.44043e-05f, 0.709856f,0.453829f,-0.000914744f,0.0014308f,1.0f,9.68686e-05f,
0.688369f,0.46316f,-0.000933552f,0.00138749f,1.0f,0.000143383f, 0.666389f,0.471503f,-0.000950368f,0.00134319f,1.0f,0.000209116f,
0.643957f,0.478828f,-0.000965133f,0.00129798f,1.0f,0.000300827f, 0.621114f,0.48511f,-0.000977794f,0.00125193f,1.0f,0.000427271f,
0.597904f,0.490321f,-0.000988298f,0.00120515f,1.0f,0.000599687f, 0.574373f,0.494438f,-0.000996596f,0.00115772f,1.0f,0.000832375f,
0.550565f,0.497437f,-0.00100264f,0.00110973f,1.0f,0.00114338f, 0.52653f,0.499296f,-0.00100639f,0.00106129f,1.0f,0.00155533f,
0.502317f,0.499995f,-0.0010078f,0.00101248f,1.0f,0.00209636f, 0.477976f,0.499515f,-0.00100683f,0.000963424f,1.0f,0.00280123f,
0.453561f,0.497839f,-0.00100345f,0.000914213f,1.0f,0.00371268f, 0.429126f,0.494952f,-0.00099763f,0.000864961f,1.0f,0.00488285f,
0.404726f,0.490839f,-0.000989341f,0.00081578f,1.0f,0.00637509f, 0.380418f,0.48549f,-0.000978559f,0.000766785f,1.0f,0.00826591f,
0.356261f,0.478894f,-0.000965264f,0.000718094f,1.0f,0.0106473f, 0.332315f,0.471044f,-0.00094944f,0.000669829f,0.999999f,0.0136293f,
0.308643f,0.461933f,-0.000931078f,0.000622114f,0.999999f,0.017343f, 0.285306f,0.45156f,-0.000910169f,0.000575076f,0.999999f,0.0219437f,
0.26237f,0.439923f,-0.000886712f,0.000528846f,0.999999f,0.0276152f, 0.239901f,0.427023f,-0.000860711f,0.000483557f,0.999999f,0.0345735f,
0.217967f,0.412865f,-0.000832174f,0.000439347f,0.999999f,0.0430717f, 0.196637f,0.397455f,-0.000801114f,0.000396355f,0.999999f,0.0534058f,
0.175982f,0.380805f,-0.000767553f,0.000354723f,0.999999f,0.0659202f, 0.156074f,0.362926f,-0.000731516f,0.000314597f,0.999999f,0.0810146f,
0.136988f,0.343835f,-0.000693036f,0.000276127f,0.999998f,0.0991514f, 0.118799f,0.323552f,-0.000652153f,0.000239465f,0.999998f,0.120864f,
0.101583f,0.302099f,-0.000608914f,0.000204765f,0.999998f,0.146765f, 0.0854194f,0.279505f,-0.000563372f,0.000172186f,0.999997f,0.17756f,
0.0703879f,0.2558f,-0.000515592f,0.000141888f,0.999997f,0.214052f, 0.0565699f,0.231019f,-0.000465644f,0.000114037f,0.999996f,0.257159f,
0.0440487f,0.205203f,-0.000413609f,8.8799e-05f,0.999994f,0.307928f, 0.0329086f,0.178397f,-0.000359579f,6.63452e-05f,0.999993f,0.367543f,
0.0232358f,0.150651f,-0.000303654f,4.68488e-05f,0.999989f,0.437349f, 0.0151179f,0.122021f,-0.000245948f,3.04864e-05f,0.999983f,0.518861f,
0.00864401f,0.0925697f,-0.000186586f,1.74377e-05f,0.999971f,0.613784f, 0.00390478f,0.0623649f,-0.000125705f,7.88529e-06f,0.999935f,0.724004f,
0.000992422f,0.0314854f,-6.34543e-05f,2.0153e-06f,0.999487f,0.851188f, 2.91199e-06f,0.00177667f,-3.13965e-06f,2.47161e-08f,0.892164f,0.874482f,
1.0f,-2.00368e-12f,-2.5211e-21f,0.00453515f,1.0f,1.5205e-17f, 0.999496f,0.0224408f,-0.000101772f,0.00453287f,1.0f,1.62772e-16f,
0.997985f,0.0448391f,-0.000203351f,0.00452602f,1.0f,3.54341e-15f, 0.99547f,0.0671527f,-0.000304546f,0.00451461f,1.0f,8.57956e-14f,
0.991954f,0.0893392f,-0.000405165f,0.00449866f,1.0f,1.24324e-12f, 0.987442f,0.111356f,-0.000505016f,0.0044782f,1.0f,1.08059e-11f,
0.981942f,0.133162f,-0.000603908f,0.00445326f,1.0f,6.48598e-11f, 0.975461f,0.154715f,-0.000701653f,0.00442387f,1.0f,2.9799e-10f,
0.96801f,0.175973f,-0.000798061f,0.00439008f,1.0f,1.12141e-09f, 0.9596f,0.196895f,-0.000892944f,0.00435193f,1.0f,3.61788e-09f,
0.950243f,0.21744f,-0.000986116f,0.0043095f,1.0f,1.03294e-08f, 0.939956f,0.237566f,-0.00107739f,0.00426285f,1.0f,2.67051e-08f,
0.928753f,0.257235f,-0.00116659f,0.00421204f,1.0f,6.35961e-08f, 0.916652f,0.276406f,-0.00125353f,0.00415716f,1.0f,1.41334e-07f,
0.903672f,0.295038f,-0.00133803f,0.0040983f,1.0f,2.96118e-07f, 0.889834f,0.313095f,-0.00141992f,0.00403554f,1.0f,5.8965e-07f,
0.87516f,0.330536f,-0.00149902f,0.00396899f,1.0f,1.12324e-06f, 0.859673f,0.347325f,-0.00157516f,0.00389876f,1.0f,2.05791e-06f,
0.843398f,0.363424f,-0.00164817f,0.00382495f,1.0f,3.64235e-06f, 0.826363f,0.378797f,-0.00171788f,0.00374769f,1.0f,6.25109e-06f,
0.808595f,0.393407f,-0.00178414f,0.00366711f,1.0f,1.04356e-05f, 0.790123f,0.40722f,-0.00184678f,0.00358334f,1.0f,1.69918e-05f,
0.770981f,0.420202f,-0.00190566f,0.00349653f,1.0f,2.70473e-05f, 0.751199f,0.432319f,-0.00196061f,0.00340682f,1.0f,4.21741e-05f,
0.730812f,0.443538f,-0.00201149f,0.00331436f,1.0f,6.45306e-05f, 0.709857f,0.453829f,-0.00205815f,0.00321933f,0.999999f,9.70404e-05f,
0.68837f,0.46316f,-0.00210047f,0.00312188f,0.999999f,0.000143614f, 0.66639f,0.471503f,-0.0021383f,0.0030222f,0.999999f,0.000209422f,
0.643958f,0.478829f,-0.00217152f,0.00292047f,0.999999f,0.000301227f, 0.621115f,0.48511f,-0.00220001f,0.00281688f,0.999999f,0.000427789f,
0.597906f,0.490322f,-0.00222364f,0.00271162f,0.999999f,0.000600349f, 0.574374f,0.494439f,-0.00224231f,0.00260491f,0.999999f,0.000833213f,
0.550566f,0.497438f,-0.00225591f,0.00249694f,0.999999f,0.00114443f, 0.526531f,0.499297f,-0.00226434f,0.00238794f,0.999999f,0.00155664f,
0.502318f,0.499996f,-0.00226751f,0.00227814f,0.999999f,0.00209796f, 0.477978f,0.499516f,-0.00226533f,0.00216775f,0.999999f,0.00280318f,
0.453563f,0.49784f,-0.00225773f,0.00205703f,0.999998f,0.00371503f, 0.429128f,0.494953f,-0.00224463f,0.00194622f,0.999998f,0.00488565f,
0.404728f,0.490841f,-0.00222598f,0.00183557f,0.999998f,0.0063784f, 0.38042f,0.485491f,-0.00220172f,0.00172533f,0.999998f,0.00826979f,
0.356263f,0.478896f,-0.00217181f,0.00161578f,0.999998f,0.0106518f, 0.332318f,0.471045f,-0.0021362f,0.00150719f,0.999997f,0.0136344f,
0.308645f,0.461935f,-0.00209489f,0.00139983f,0.999997f,0.0173487f, 0.285308f,0.451562f,-0.00204784f,0.001294f,0.999997f,0.0219502f,
0.262372f,0.439925f,-0.00199507f,0.00118999f,0.999996f,0.0276222f, 0.239903f,0.427025f,-0.00193656f,0.00108809f,0.999996f,0.034581f,
0.217969f,0.412867f,-0.00187236f,0.000988626f,0.999995f,0.0430795f, 0.196639f,0.397458f,-0.00180247f,0.000891897f,0.999995f,0.0534136f,
0.175984f,0.380807f,-0.00172696f,0.00079823f,0.999994f,0.0659274f, 0.156077f,0.362929f,-0.00164588f,0.000707952f,0.999993f,0.0810206f,
0.13699f,0.343838f,-0.0015593f,0.000621399f,0.999992f,0.0991551f, 0.118801f,0.323554f,-0.00146732f,0.000538912f,0.99999f,0.120864f,
0.101585f,0.302102f,-0.00137003f,0.000460841f,0.999989f,0.14676f, 0.0854216f,0.279508f,-0.00126757f,0.000387542f,0.999986f,0.177546f,
0.07039f,0.255803f,-0.00116007f,0.000319376f,0.999983f,0.214024f, 0.0565721f,0.231022f,-0.00104769f,0.000256714f,0.999978f,0.257113f,
0.0440508f,0.205207f,-0.000930616f,0.000199932f,0.999972f,0.307853f, 0.0329107f,0.178402f,-0.000809054f,0.000149413f,0.999962f,0.367424f,
0.0232379f,0.150656f,-0.000683232f,0.000105549f,0.999946f,0.437161f, 0.01512f,0.122027f,-0.000553403f,6.87352e-05f,0.999915f,0.518557f,
0.00864603f,0.0925772f,-0.000419851f,3.93771e-05f,0.999849f,0.613261f, 0.00390718f,0.0623821f,-0.000282824f,1.78897e-05f,0.999201f,0.722591f,
0.000994768f,0.0315172f,-0.000142794f,4.68307e-06f,0.997003f,0.847012f, 1.03469e-05f,0.00318642f,-1.29733e-05f,2.67692e-07f,0.925506f,0.883569f,
1.0f,1.78766e-11f,-4.679e-21f,0.00806252f,1.0f,4.69449e-15f, 0.999496f,0.0224408f,-0.000180926f,0.00805846f,1.0f,1.37807e-14f,
0.997985f,0.0448391f,-0.000361511f,0.00804628f,1.0f,7.24701e-14f, 0.99547f,0.0671527f,-0.000541411f,0.008026f,1.0f,4.00409e-13f,
0.991954f,0.0893392f,-0.000720287f,0.00799765f,1.0f,2.49961e-12f, 0.987442f,0.111356f,-0.000897799f,0.00796128f,1.0f,1.52112e-11f,
0.981942f,0.133162f,-0.00107361f,0.00791693f,1.0f,7.85234e-11f, 0.975461f,0.154715f,-0.00124737f,0.00786468f,1.0f,3.35911e-10f,
0.96801f,0.175973f,-0.00141876f,0.00780461f,1.0f,1.21686e-09f, 0.9596f,0.196895f,-0.00158744f,0.00773681f,1.0f,3.83863e-09f,
0.950244f,0.21744f,-0.00175308f,0.00766137f,1.0f,1.08041e-08f, 0.939956f,0.237566f,-0.00191534f,0.00757843f,1.0f,2.76636e-08f,
0.928752f,0.257235f,-0.00207392f,0.0074881f,1.0f,6.54292e-08f, 0.916651f,0.276405f,-0.00222847f,0.00739054f,1.0f,1.44678e-07f,
0.903671f,0.295038f,-0.00237869f,0.0072859f,1.0f,3.01968e-07f, 0.889833f,0.313094f,-0.00252427f,0.00717433f,1.0f,5.99515e-07f,
0.875158f,0.330536f,-0.00266488f,0.00705602f,0.999999f,1.13935e-06f, 0.859671f,0.347325f,-0.00280023f,0.00693116f,0.999999f,2.08344e-06f,
0.843397f,0.363424f,-0.00293002f,0.00679996f,0.999999f,3.68179e-06f, 0.826362f,0.378796f,-0.00305395f,0.00666261f,0.999999f,6.31058e-06f,
0.808594f,0.393407f,-0.00317174f,0.00651937f,0.999999f,1.05235e-05f, 0.790123f,0.40722f,-0.0032831f,0.00637045f,0.999999f,1.71189e-05f,
0.770981f,0.420202f,-0.00338775f,0.00621612f,0.999999f,2.7228e-05f, 0.7512f,0.432318f,-0.00348543f,0.00605664f,0.999999f,4.24266e-05f,
0.730813f,0.443538f,-0.00357588f,0.00589229f,0.999999f,6.48782e-05f, 0.709858f,0.453829f,-0.00365884f,0.00572335f,0.999998f,9.75121e-05f,
0.688372f,0.463161f,-0.00373406f,0.00555012f,0.999998f,0.000144245f, 0.666392f,0.471504f,-0.00380131f,0.00537293f,0.999998f,0.000210256f,
0.64396f,0.47883f,-0.00386037f,0.00519208f,0.999998f,0.000302316f, 0.621118f,0.485111f,-0.003911f,0.00500793f,0.999997f,0.000429195f,
0.597909f,0.490323f,-0.00395301f,0.00482082f,0.999997f,0.000602146f, 0.574378f,0.49444f,-0.00398619f,0.00463112f,0.999997f,0.000835483f,
0.55057f,0.49744f,-0.00401036f,0.00443919f,0.999997f,0.00114728f, 0.526536f,0.499299f,-0.00402534f,0.00424543f,0.999996f,0.00156016f,
0.502323f,0.499998f,-0.00403097f,0.00405023f,0.999996f,0.00210228f, 0.477983f,0.499519f,-0.00402709f,0.00385401f,0.999996f,0.00280843f,
0.453568f,0.497844f,-0.00401357f,0.0036572f,0.999995f,0.00372135f, 0.429133f,0.494957f,-0.00399028f,0.00346021f,0.999995f,0.00489319f,
0.404733f,0.490845f,-0.00395712f,0.00326352f,0.999994f,0.0063873f, 0.380426f,0.485496f,-0.00391399f,0.00306756f,0.999993f,0.00828019f,
0.356269f,0.4789f,-0.00386081f,0.00287282f,0.999993f,0.0106638f, 0.332323f,0.47105f,-0.00379751f,0.00267979f,0.999992f,0.0136482f,
0.308651f,0.461941f,-0.00372406f,0.00248896f,0.999991f,0.0173642f, 0.285314f,0.451568f,-0.00364043f,0.00230084f,0.99999f,0.0219674f,
0.262378f,0.439931f,-0.00354661f,0.00211595f,0.999989f,0.027641f, 0.239909f,0.427031f,-0.00344261f,0.00193482f,0.999987f,0.034601f,
0.217975f,0.412874f,-0.00332846f,0.00175801f,0.999985f,0.0431002f, 0.196645f,0.397465f,-0.00320423f,0.00158607f,0.999983f,0.0534341f,
0.17599f,0.380814f,-0.00307f,0.00141957f,0.999981f,0.0659466f, 0.156083f,0.362936f,-0.00292586f,0.0012591f,0.999978f,0.0810365f,
0.136997f,0.343846f,-0.00277196f,0.00110524f,0.999974f,0.0991651f, 0.118807f,0.323563f,-0.00260844f,0.00095862f,0.99997f,0.120864f,
0.101591f,0.30211f,-0.00243551f,0.000819845f,0.999964f,0.146745f, 0.0854276f,0.279517f,-0.00225336f,0.000689553f,0.999956f,0.177508f,
0.0703958f,0.255812f,-0.00206227f,0.000568386f,0.999946f,0.213952f, 0.0565779f,0.231033f,-0.00186251f,0.000457002f,0.999932f,0.25699f,
0.0440565f,0.205218f,-0.0016544f,0.00035607f,0.999911f,0.307654f, 0.0329163f,0.178413f,-0.00143832f,0.000266272f,0.999878f,0.367111f,
0.0232435f,0.15067f,-0.00121467f,0.000188303f,0.999822f,0.436664f, 0.0151265f,0.122052f,-0.000983748f,0.000122883f,0.999421f,0.517535f,
0.00865268f,0.0926104f,-0.000746311f,7.07058e-05f,0.99891f,0.61141f, 0.00391336f,0.0624232f,-0.000502857f,3.25038e-05f,0.997643f,0.719257f,
0.00100155f,0.0316125f,-0.000253968f,9.02604e-06f,0.990212f,0.836244f, 2.81504e-05f,0.00503575f,-3.77666e-05f,1.36751e-06f,0.952901f,0.880247f,
1.0f,8.2747e-12f,-3.26692e-21f,0.0125978f,1.0f,3.89588e-13f, 0.999496f,0.0224408f,-0.000282693f,0.0125914f,1.0f,6.56917e-13f,
0.997986f,0.0448391f,-0.000564852f,0.0125724f,1.0f,1.80124e-12f, 0.99547f,0.0671527f,-0.000845942f,0.0125407f,1.0f,5.22028e-12f,
0.991954f,0.0893392f,-0.00112543f,0.0124964f,1.0f,1.53391e-11f, 0.987443f,0.111356f,-0.00140279f,0.0124396f,1.0f,4.75984e-11f,
0.981943f,0.133162f,-0.00167748f,0.0123703f,1.0f,1.55939e-10f, 0.975462f,0.154715f,-0.00194898f,0.0122887f,1.0f,5.11501e-10f,
0.968012f,0.175973f,-0.00221677f,0.0121948f,1.0f,1.59536e-09f, 0.959602f,0.196895f,-0.00248032f,0.0120889f,1.0f,4.61574e-09f,
0.950246f,0.21744f,-0.00273912f,0.011971f,0.999999f,1.23279e-08f, 0.939958f,0.237567f,-0.00299265f,0.0118414f,0.999999f,3.05268e-08f,
0.928754f,0.257235f,-0.00324041f,0.0117003f,0.999999f,7.06011e-08f, 0.916651f,0.276405f,-0.00348189f,0.0115478f,0.999999f,1.53689e-07f,
0.90367f,0.295038f,-0.00371659f,0.0113843f,0.999999f,3.17161e-07f, 0.889831f,0.313094f,-0.00394404f,0.01121f,0.999999f,6.24373e-07f,
0.875157f,0.330535f,-0.00416373f,0.0110252f,0.999999f,1.17892e-06f, 0.85967f,0.347324f,-0.0043752f,0.0108301f,0.999998f,2.14488e-06f,
0.843396f,0.363423f,-0.00457798f,0.0106251f,0.999998f,3.775e-06f, 0.826361f,0.378795f,-0.0047716f,0.0104105f,0.999998f,6.44906e-06f,
0.808594f,0.393406f,-0.00495562f,0.0101867f,0.999998f,1.07252e-05f, 0.790124f,0.407219f,-0.0051296f,0.00995404f,0.999997f,1.74077e-05f,
0.770982f,0.420201f,-0.0052931f,0.00971293f,0.999997f,2.76344e-05f, 0.751201f,0.432318f,-0.00544571f,0.00946376f,0.999997f,4.29899e-05f,
0.730816f,0.443538f,-0.00558701f,0.00920699f,0.999996f,6.56476e-05f, 0.709861f,0.45383f,-0.00571661f,0.00894305f,0.999996f,9.85488e-05f,
0.688375f,0.463162f,-0.00583412f,0.00867242f,0.999995f,0.000145625f, 0.666397f,0.471505f,-0.00593918f,0.00839558f,0.999995f,0.000212069f,
0.643966f,0.478832f,-0.00603143f,0.00811305f,0.999995f,0.000304672f, 0.621124f,0.485114f,-0.00611053f,0.00782536f,0.999994f,0.000432223f,
0.597916f,0.490326f,-0.00617614f,0.00753304f,0.999993f,0.000605998f, 0.574385f,0.494444f,-0.00622797f,0.00723667f,0.999993f,0.000840334f,
0.550578f,0.497444f,-0.00626571f,0.00693684f,0.999992f,0.00115332f, 0.526544f,0.499304f,-0.0062891f,0.00663413f,0.999991f,0.00156763f,
0.502332f,0.500004f,-0.00629787f,0.00632919f,0.99999f,0.00211142f, 0.477993f,0.499525f,-0.0062918f,0.00602266f,0.999989f,0.00281951f,
0.453578f,0.49785f,-0.00627066f,0.00571518f,0.999988f,0.00373465f, 0.429144f,0.494964f,-0.00623426f,0.00540746f,0.999987f,0.00490902f,
0.404745f,0.490853f,-0.00618244f,0.00510018f,0.999985f,0.00640594f, 0.380437f,0.485504f,-0.00611503f,0.00479406f,0.999984f,0.00830193f,
0.356281f,0.47891f,-0.00603193f,0.00448985f,0.999982f,0.0106889f, 0.332336f,0.47106f,-0.00593303f,0.0041883f,0.99998f,0.0136767f,
0.308663f,0.461951f,-0.00581826f,0.0038902f,0.999978f,0.0173964f, 0.285326f,0.451579f,-0.00568759f,0.00359632f,0.999975f,0.022003f,
0.262391f,0.439943f,-0.005541f,0.0033075f,0.999972f,0.0276798f, 0.239922f,0.427044f,-0.00537851f,0.00302456f,0.999968f,0.0346422f,
0.217988f,0.412887f,-0.00520018f,0.00274836f,0.999964f,0.0431428f, 0.196658f,0.397478f,-0.00500609f,0.00247977f,0.999959f,0.0534763f,
0.176003f,0.380829f,-0.00479637f,0.00221968f,0.999953f,0.0659857f, 0.156096f,0.362951f,-0.00457119f,0.00196901f,0.999946f,0.0810687f,
0.137009f,0.343861f,-0.00433075f,0.00172868f,0.999937f,0.099185f, 0.11882f,0.323579f,-0.00407529f,0.00149964f,0.999926f,0.120864f,
0.101604f,0.302128f,-0.00380512f,0.00128287f,0.999911f,0.146713f, 0.08544f,0.279535f,-0.00352058f,0.00107934f,0.999892f,0.177429f,
0.0704084f,0.255832f,-0.00322205f,0.000890074f,0.999866f,0.213804f, 0.0565902f,0.231054f,-0.00290999f,0.000716088f,0.999827f,0.256738f,
0.044069f,0.205242f,-0.00258487f,0.000558435f,0.999744f,0.307232f, 0.0329311f,0.178454f,-0.00224686f,0.000418239f,0.999292f,0.36622f,
0.0232581f,0.150717f,-0.00189744f,0.000296459f,0.998989f,0.435266f, 0.0151395f,0.122096f,-0.00153703f,0.000194234f,0.998597f,0.51561f,
0.00866585f,0.09267f,-0.00116613f,0.000112719f,0.997413f,0.608093f, 0.00392717f,0.0625192f,-0.000785785f,5.30246e-05f,0.994035f,0.712457f,
0.00102049f,0.0319319f,-0.000397788f,1.62753e-05f,0.976238f,0.815451f, 6.24257e-05f,0.00726793f,-8.79939e-05f,4.77167e-06f,0.96849f,0.861776f,
1.0f,-5.70266e-11f,-5.93756e-21f,0.018141f,1.0f,1.37998e-11f, 0.999496f,0.0224408f,-0.000407068f,0.0181319f,1.0f,1.80909e-11f,
0.997986f,0.0448391f,-0.000813367f,0.0181045f,1.0f,3.3518e-11f, 0.995471f,0.0671527f,-0.00121813f,0.0180589f,1.0f,6.8905e-11f,
0.991955f,0.0893393f,-0.00162058f,0.0179951f,1.0f,1.43925e-10f, 0.987444f,0.111357f,-0.00201996f,0.0179133f,1.0f,3.02215e-10f,
0.981944f,0.133163f,-0.0024155f,0.0178135f,1.0f,6.47656e-10f, 0.975464f,0.154716f,-0.00280645f,0.0176959f,0.999999f,1.4371e-09f,
0.968014f,0.175974f,-0.00319205f,0.0175608f,0.999999f,3.29428e-09f, 0.959604f,0.196896f,-0.00357155f,0.0174082f,0.999999f,7.65765e-09f,
0.950249f,0.217441f,-0.0039442f,0.0172385f,0.999999f,1.76428e-08f, 0.939962f,0.237567f,-0.00430926f,0.0170519f,0.999999f,3.9592e-08f,
0.928758f,0.257236f,-0.004666f,0.0168487f,0.999998f,8.5703e-08f, 0.916656f,0.276406f,-0.0050137f,0.0166292f,0.999998f,1.78279e-07f,
0.903674f,0.295038f,-0.00535164f,0.0163938f,0.999998f,3.56325e-07f, 0.889834f,0.313094f,-0.00567911f,0.0161428f,0.999997f,6.85448e-07f,
0.875157f,0.330534f,-0.00599542f,0.0158766f,0.999997f,1.27227e-06f, 0.85967f,0.347323f,-0.00629989f,0.0155957f,0.999997f,2.28488e-06f,
0.843395f,0.363421f,-0.00659184f,0.0153005f,0.999996f,3.98121e-06f, 0.826361f,0.378794f,-0.00687062f,0.0149916f,0.999996f,6.74769e-06f,
0.808594f,0.393405f,-0.00713556f,0.0146693f,0.999995f,1.11508e-05f, 0.790125f,0.407218f,-0.00738603f,0.0143344f,0.999994f,1.80051e-05f,
0.770984f,0.420201f,-0.00762142f,0.0139872f,0.999994f,2.84612e-05f, 0.751205f,0.432318f,-0.00784112f,0.0136285f,0.999993f,4.41188e-05f,
0.73082f,0.443539f,-0.00804454f,0.0132588f,0.999992f,6.71693e-05f, 0.709867f,0.453831f,-0.0082311f,0.0128788f,0.999991f,0.000100575f,
0.688383f,0.463164f,-0.00840027f,0.0124892f,0.999991f,0.000148293f, 0.666405f,0.471508f,-0.0085515f,0.0120906f,0.99999f,0.000215543f,
0.643976f,0.478835f,-0.00868428f,0.0116839f,0.999988f,0.000309149f, 0.621135f,0.485119f,-0.00879811f,0.0112697f,0.999987f,0.000437933f,
0.597928f,0.490332f,-0.00889255f,0.0108489f,0.999986f,0.000613209f, 0.574399f,0.494451f,-0.00896712f,0.0104222f,0.999985f,0.000849355f,
0.550593f,0.497451f,-0.00902142f,0.00999057f,0.999983f,0.00116451f, 0.52656f,0.499313f,-0.00905505f,0.00955482f,0.999981f,0.00158136f,
0.502349f,0.500014f,-0.00906764f,0.00911583f,0.999979f,0.00212814f, 0.478011f,0.499537f,-0.00905885f,0.00867456f,0.999977f,0.00283968f,
0.453597f,0.497863f,-0.00902837f,0.00823195f,0.999975f,0.00375877f, 0.429164f,0.494978f,-0.00897593f,0.00778897f,0.999972f,0.00493758f,
0.404765f,0.490867f,-0.00890127f,0.00734664f,0.999969f,0.00643946f, 0.380459f,0.485521f,-0.00880419f,0.006906f,0.999966f,0.00834085f,
0.356303f,0.478927f,-0.0086845f,0.0064681f,0.999962f,0.0107336f, 0.332358f,0.471079f,-0.00854208f,0.00603404f,0.999958f,0.0137275f,
0.308686f,0.461971f,-0.00837682f,0.00560493f,0.999953f,0.0174533f, 0.28535f,0.4516f,-0.00818865f,0.00518193f,0.999948f,0.0220658f,
0.262414f,0.439964f,-0.00797758f,0.0047662f,0.999941f,0.0277479f, 0.239945f,0.427067f,-0.00774363f,0.00435894f,0.999934f,0.0347144f,
0.218011f,0.412911f,-0.00748686f,0.00396139f,0.999925f,0.043217f, 0.196681f,0.397503f,-0.00720742f,0.00357479f,0.999915f,0.0535493f,
0.176027f,0.380855f,-0.0069055f,0.00320044f,0.999902f,0.0660529f, 0.156119f,0.362979f,-0.00658131f,0.00283964f,0.999886f,0.0811234f,
0.137033f,0.34389f,-0.00623516f,0.00249373f,0.999866f,0.0992173f, 0.118843f,0.32361f,-0.00586741f,0.00216408f,0.999841f,0.12086f,
0.101627f,0.302161f,-0.00547847f,0.00185208f,0.999803f,0.146652f, 0.0854646f,0.279574f,-0.00506862f,0.00155919f,0.99969f,0.177254f,
0.0704365f,0.255887f,-0.00463806f,0.00128695f,0.999336f,0.213356f, 0.0566186f,0.231116f,-0.00418866f,0.00103658f,0.999123f,0.256017f,
0.0440962f,0.205308f,-0.00372072f,0.000809661f,0.99892f,0.306181f, 0.032955f,0.178511f,-0.00323496f,0.000607748f,0.99866f,0.364922f,
0.0232828f,0.150789f,-0.00273183f,0.000432464f,0.997957f,0.433186f, 0.0151646f,0.122187f,-0.00221287f,0.000285298f,0.996853f,0.512201f,
0.00869115f,0.0927894f,-0.00167904f,0.000167869f,0.994412f,0.602332f, 0.00395569f,0.0627364f,-0.00113191f,8.17488e-05f,0.98734f,0.700967f,
0.00107403f,0.0329749f,-0.000580261f,2.85746e-05f,0.955301f,0.784166f, 0.000126707f,0.0102878f,-0.000178616f,1.32526e-05f,0.977647f,0.834944f,
1.0f,7.63304e-11f,-4.71925e-20f,0.0246925f,1.0f,2.65246e-10f, 0.999496f,0.0224408f,-0.000554048f,0.0246801f,1.0f,3.08067e-10f,
0.997986f,0.0448391f,-0.00110705f,0.0246428f,1.0f,4.49918e-10f, 0.995471f,0.0671527f,-0.00165795f,0.0245807f,1.0f,7.34082e-10f,
0.991956f,0.0893393f,-0.00220571f,0.0244939f,1.0f,1.24455e-09f, 0.987445f,0.111357f,-0.00274929f,0.0243825f,0.999999f,2.13064e-09f,
0.981946f,0.133163f,-0.00328764f,0.0242467f,0.999999f,3.66172e-09f, 0.975466f,0.154716f,-0.00381974f,0.0240867f,0.999999f,6.34752e-09f,
0.968017f,0.175974f,-0.00434455f,0.0239028f,0.999999f,1.11916e-08f, 0.959609f,0.196896f,-0.00486105f,0.0236952f,0.999998f,2.01939e-08f,
0.950254f,0.217441f,-0.00536822f,0.0234642f,0.999998f,3.72864e-08f, 0.939968f,0.237569f,-0.00586506f,0.0232103f,0.999997f,6.99786e-08f,
0.928766f,0.257238f,-0.00635057f,0.0229337f,0.999997f,1.32108e-07f, 0.916664f,0.276408f,-0.00682377f,0.022635f,0.999996f,2.48241e-07f,
0.903683f,0.295041f,-0.00728367f,0.0223145f,0.999996f,4.60457e-07f, 0.889842f,0.313096f,-0.00772931f,0.0219729f,0.999995f,8.38466e-07f,
0.875165f,0.330536f,-0.00815976f,0.0216106f,0.999994f,1.49428e-06f, 0.859675f,0.347324f,-0.00857407f,0.0212283f,0.999994f,2.60295e-06f,
0.843399f,0.363422f,-0.00897134f,0.0208266f,0.999993f,4.43131e-06f, 0.826364f,0.378794f,-0.00935067f,0.0204062f,0.999992f,7.37696e-06f,
0.808597f,0.393404f,-0.00971118f,0.0199677f,0.999991f,1.20202e-05f, 0.790129f,0.407218f,-0.010052f,0.0195118f,0.99999f,1.91926e-05f,
0.770989f,0.4202f,-0.0103723f,0.0190394f,0.999988f,3.00652e-05f, 0.751211f,0.432319f,-0.0106712f,0.0185513f,0.999987f,4.62622e-05f,
0.730829f,0.44354f,-0.0109479f,0.0180483f,0.999986f,7.00037e-05f, 0.709878f,0.453833f,-0.0112017f,0.0175312f,0.999984f,0.000104286f,
0.688395f,0.463167f,-0.0114319f,0.0170011f,0.999982f,0.000153103f, 0.66642f,0.471513f,-0.0116376f,0.0164588f,0.999981f,0.000221719f,
0.643992f,0.478842f,-0.0118182f,0.0159054f,0.999979f,0.000317006f, 0.621154f,0.485127f,-0.011973f,0.0153419f,0.999976f,0.00044784f,
0.597949f,0.490341f,-0.0121014f,0.0147693f,0.999974f,0.000625591f, 0.574421f,0.494462f,-0.0122028f,0.0141888f,0.999971f,0.000864698f,
0.550617f,0.497464f,-0.0122766f,0.0136016f,0.999968f,0.00118336f, 0.526586f,0.499327f,-0.0123223f,0.0130087f,0.999965f,0.00160433f,
0.502377f,0.50003f,-0.0123393f,0.0124115f,0.999962f,0.00215588f, 0.47804f,0.499555f,-0.0123273f,0.0118112f,0.999958f,0.00287291f,
0.453628f,0.497883f,-0.0122857f,0.0112091f,0.999953f,0.00379822f, 0.429197f,0.495001f,-0.0122142f,0.0106065f,0.999948f,0.00498401f,
0.404799f,0.490892f,-0.0121126f,0.0100047f,0.999943f,0.0064936f, 0.380493f,0.485547f,-0.0119804f,0.00940532f,0.999937f,0.00840337f,
0.356338f,0.478955f,-0.0118174f,0.00880964f,0.99993f,0.010805f, 0.332395f,0.47111f,-0.0116236f,0.0082192f,0.999922f,0.0138082f,
0.308723f,0.462004f,-0.0113986f,0.00763551f,0.999913f,0.0175432f, 0.285388f,0.451634f,-0.0111425f,0.00706012f,0.999902f,0.0221644f,
0.262453f,0.440002f,-0.0108553f,0.00649465f,0.999889f,0.027854f, 0.239985f,0.427107f,-0.0105369f,0.00594071f,0.999875f,0.0348259f,
0.218051f,0.412952f,-0.0101875f,0.00539997f,0.999857f,0.0433305f, 0.196721f,0.397546f,-0.00980724f,0.00487414f,0.999834f,0.0536592f,
0.176067f,0.380902f,-0.00939637f,0.00436498f,0.9998f,0.0661498f, 0.156161f,0.363031f,-0.00895488f,0.00387434f,0.999708f,0.0811791f,
0.137082f,0.343964f,-0.00848248f,0.00340421f,0.999419f,0.0991439f, 0.118893f,0.323691f,-0.00798161f,0.00295598f,0.999246f,0.120665f,
0.101677f,0.302247f,-0.00745228f,0.00253169f,0.9991f,0.146315f, 0.085512f,0.27966f,-0.00689504f,0.00213329f,0.998959f,0.176763f,
0.0704783f,0.255962f,-0.00631054f,0.00176275f,0.998798f,0.212771f, 0.0566588f,0.231192f,-0.00569957f,0.00142211f,0.998565f,0.255178f,
0.044138f,0.205399f,-0.00506246f,0.0011135f,0.998003f,0.304793f, 0.0329969f,0.178616f,-0.00440158f,0.000838791f,0.997394f,0.362805f,
0.0233246f,0.150911f,-0.00371733f,0.000600211f,0.996232f,0.43f, 0.015207f,0.12234f,-0.00301128f,0.000399803f,0.994078f,0.507083f,
0.00873638f,0.0930136f,-0.00228533f,0.000239678f,0.98944f,0.593548f, 0.00401312f,0.063223f,-0.00154321f,0.000121959f,0.976768f,0.683747f,
0.00121061f,0.0357235f,-0.000822036f,5.01176e-05f,0.931933f,0.746048f, 0.000217099f,0.0131269f,-0.000321358f,3.0791e-05f,0.983365f,0.803594f,
1.0f,4.9043e-10f,-2.68046e-20f,0.0322525f,1.0f,3.17746e-09f, 0.999496f,0.0224408f,-0.000723631f,0.0322362f,0.999999f,3.46814e-09f,
0.997986f,0.0448391f,-0.00144589f,0.0321875f,0.999999f,4.39192e-09f, 0.995472f,0.0671528f,-0.00216541f,0.0321064f,0.999999f,6.11107e-09f,
0.991957f,0.0893394f,-0.00288082f,0.0319931f,0.999999f,8.92097e-09f, 0.987447f,0.111357f,-0.00359077f,0.0318476f,0.999999f,1.3296e-08f,
0.981949f,0.133163f,-0.00429388f,0.0316703f,0.999998f,1.99771e-08f, 0.97547f,0.154716f,-0.00498881f,0.0314614f,0.999998f,3.0139e-08f,
0.968022f,0.175975f,-0.00567422f,0.0312211f,0.999997f,4.57085e-08f, 0.959615f,0.196897f,-0.00634877f,0.03095f,0.999997f,6.99542e-08f,
0.950262f,0.217443f,-0.00701112f,0.0306484f,0.999996f,1.08536e-07f, 0.939977f,0.237571f,-0.00765998f,0.0303168f,0.999995f,1.71292e-07f,
0.928777f,0.25724f,-0.00829402f,0.0299556f,0.999994f,2.75175e-07f, 0.916678f,0.276411f,-0.00891197f,0.0295655f,0.999994f,4.48865e-07f,
0.903699f,0.295044f,-0.00951254f,0.0291471f,0.999992f,7.39825e-07f, 0.889859f,0.3131f,-0.0100945f,0.0287009f,0.999991f,1.22472e-06f,
0.875182f,0.330541f,-0.0106565f,0.0282279f,0.99999f,2.02446e-06f, 0.859691f,0.347328f,-0.0111975f,0.0277286f,0.999989f,3.32533e-06f,
0.843413f,0.363425f,-0.0117162f,0.027204f,0.999987f,5.40818e-06f, 0.826376f,0.378796f,-0.0122114f,0.0266549f,0.999986f,8.68793e-06f,
0.808608f,0.393406f,-0.0126821f,0.0260823f,0.999984f,1.3766e-05f, 0.790139f,0.407219f,-0.013127f,0.0254871f,0.999982f,2.14994e-05f,
0.771001f,0.420202f,-0.0135451f,0.0248703f,0.99998f,3.30896e-05f, 0.751224f,0.432321f,-0.0139353f,0.024233f,0.999978f,5.01964e-05f,
0.730844f,0.443544f,-0.0142965f,0.0235762f,0.999975f,7.50818e-05f, 0.709895f,0.453838f,-0.0146278f,0.0229012f,0.999972f,0.00011079f,
0.688415f,0.463173f,-0.0149281f,0.0222091f,0.999969f,0.000161369f, 0.666443f,0.471521f,-0.0151966f,0.0215012f,0.999966f,0.000232145f,
0.644018f,0.478852f,-0.0154322f,0.0207788f,0.999963f,0.000330055f, 0.621183f,0.485139f,-0.0156342f,0.0200431f,0.999959f,0.00046405f,
0.597981f,0.490356f,-0.0158017f,0.0192958f,0.999955f,0.000645576f, 0.574456f,0.494479f,-0.0159339f,0.0185381f,0.99995f,0.000889153f,
0.550656f,0.497484f,-0.0160301f,0.0177715f,0.999945f,0.00121306f, 0.526628f,0.499351f,-0.0160895f,0.0169977f,0.999939f,0.00164012f,
0.50242f,0.500056f,-0.0161116f,0.0162182f,0.999933f,0.00219869f, 0.478086f,0.499584f,-0.0160957f,0.0154347f,0.999926f,0.0029237f,
0.453677f,0.497915f,-0.0160412f,0.0146489f,0.999919f,0.003858f, 0.429247f,0.495035f,-0.0159478f,0.0138624f,0.99991f,0.00505377f,
0.404851f,0.49093f,-0.0158148f,0.0130771f,0.9999f,0.00657426f, 0.380548f,0.485589f,-0.0156421f,0.0122949f,0.999889f,0.00849574f,
0.356394f,0.479f,-0.0154292f,0.0115175f,0.999875f,0.0109097f, 0.332452f,0.471157f,-0.0151759f,0.010747f,0.99986f,0.0139252f,
0.308782f,0.462055f,-0.0148821f,0.00998532f,0.99984f,0.017672f, 0.285448f,0.451689f,-0.0145475f,0.00923452f,0.999811f,0.0223027f,
0.262516f,0.440064f,-0.0141719f,0.00849675f,0.999746f,0.0279928f, 0.240058f,0.427188f,-0.0137538f,0.00777445f,0.999512f,0.0349208f,
0.218129f,0.413047f,-0.0132965f,0.00706919f,0.999354f,0.0433853f, 0.196802f,0.397652f,-0.0127994f,0.00638329f,0.99923f,0.0536697f,
0.176147f,0.381012f,-0.0122629f,0.00571905f,0.999123f,0.0661075f, 0.156239f,0.363142f,-0.011687f,0.00507881f,0.999018f,0.081084f,
0.137151f,0.34406f,-0.0110723f,0.00446497f,0.99891f,0.0990459f, 0.11896f,0.323786f,-0.0104194f,0.00387992f,0.998789f,0.120503f,
0.101742f,0.302344f,-0.00972902f,0.00332617f,0.998638f,0.146034f, 0.0855772f,0.279767f,-0.00900098f,0.00280635f,0.998287f,0.176227f,
0.0705449f,0.256083f,-0.00823765f,0.00232289f,0.99788f,0.211875f, 0.0567251f,0.231324f,-0.00744017f,0.00187826f,0.997415f,0.253812f,
0.044203f,0.205541f,-0.00660894f,0.00147531f,0.9966f,0.302791f, 0.033063f,0.178783f,-0.00574614f,0.00111658f,0.9954f,0.359735f,
0.023391f,0.151108f,-0.00485314f,0.000804778f,0.993394f,0.425324f, 0.0152767f,0.122602f,-0.00393206f,0.00054264f,0.989702f,0.499693f,
0.00881825f,0.0934635f,-0.00298635f,0.000332975f,0.981913f,0.581053f, 0.00413751f,0.0644246f,-0.00202876f,0.000179088f,0.962525f,0.660666f,
0.00147941f,0.0406876f,-0.00115791f,8.86371e-05f,0.911906f,0.706376f, 0.000368195f,0.017051f,-0.000543407f,6.45994e-05f,0.987183f,0.769869f,
1.0f,9.86939e-10f,-6.36671e-20f,0.0408214f,0.999999f,2.58836e-08f, 0.999496f,0.0224408f,-0.000915824f,0.0408009f,0.999999f,2.7311e-08f,
0.997987f,0.0448392f,-0.00182991f,0.0407393f,0.999998f,3.17469e-08f, 0.995473f,0.0671528f,-0.00274053f,0.0406366f,0.999998f,3.96654e-08f,
0.991959f,0.0893395f,-0.00364594f,0.0404932f,0.999998f,5.19018e-08f, 0.98745f,0.111357f,-0.00454442f,0.0403091f,0.999997f,6.97301e-08f,
0.981953f,0.133163f,-0.00543425f,0.0400847f,0.999997f,9.49996e-08f, 0.975476f,0.154717f,-0.00631371f,0.0398203f,0.999996f,1.3037e-07f,
0.96803f,0.175976f,-0.0071811f,0.0395164f,0.999995f,1.79721e-07f, 0.959624f,0.196899f,-0.00803473f,0.0391733f,0.999994f,2.48866e-07f,
0.950273f,0.217445f,-0.00887291f,0.0387917f,0.999993f,3.46751e-07f, 0.939991f,0.237573f,-0.00969399f,0.038372f,0.999992f,4.87443e-07f,
0.928793f,0.257243f,-0.0104963f,0.037915f,0.99999f,6.93294e-07f, 0.916697f,0.276415f,-0.0112782f,0.0374215f,0.999989f,9.99856e-07f,
0.903721f,0.29505f,-0.0120381f,0.036892f,0.999987f,1.46326e-06f, 0.889885f,0.313107f,-0.0127744f,0.0363275f,0.999985f,2.17105e-06f,
0.87521f,0.330549f,-0.0134855f,0.035729f,0.999983f,3.25766e-06f, 0.85972f,0.347337f,-0.0141699f,0.0350972f,0.999981f,4.92607e-06f,
0.843442f,0.363434f,-0.0148261f,0.0344334f,0.999979f,7.47753e-06f, 0.826403f,0.378804f,-0.0154525f,0.0337387f,0.999976f,1.13517e-05f,
0.808633f,0.393413f,-0.0160478f,0.0330142f,0.999973f,1.71796e-05f, 0.790162f,0.407226f,-0.0166105f,0.0322611f,0.99997f,2.58536e-05f,
0.771023f,0.420208f,-0.0171393f,0.0314808f,0.999967f,3.86165e-05f, 0.751247f,0.432327f,-0.0176327f,0.0306746f,0.999963f,5.71764e-05f,
0.730869f,0.44355f,-0.0180895f,0.0298438f,0.999959f,8.38508e-05f, 0.709923f,0.453846f,-0.0185084f,0.02899f,0.999954f,0.000121747f,
0.688447f,0.463184f,-0.0188881f,0.0281146f,0.999949f,0.000174983f, 0.666478f,0.471534f,-0.0192274f,0.0272192f,0.999944f,0.000248964f,
0.644057f,0.478867f,-0.0195253f,0.0263056f,0.999938f,0.000350712f, 0.621227f,0.485157f,-0.0197805f,0.0253753f,0.999932f,0.000489268f,
0.598028f,0.490378f,-0.0199921f,0.0244301f,0.999925f,0.000676172f, 0.574509f,0.494505f,-0.0201591f,0.0234719f,0.999917f,0.000926036f,
0.550712f,0.497514f,-0.0202804f,0.0225026f,0.999908f,0.00125723f, 0.526688f,0.499384f,-0.0203553f,0.0215242f,0.999898f,0.00169265f,
0.502485f,0.500094f,-0.0203828f,0.0205386f,0.999886f,0.0022607f, 0.478154f,0.499626f,-0.0203623f,0.0195479f,0.999872f,0.00299631f,
0.453749f,0.497963f,-0.020293f,0.0185544f,0.999854f,0.00394217f, 0.429323f,0.495088f,-0.0201743f,0.0175601f,0.999829f,0.00514992f,
0.404932f,0.490991f,-0.0200051f,0.0165674f,0.999779f,0.00668049f, 0.380642f,0.485668f,-0.0197834f,0.015579f,0.999613f,0.00859625f,
0.356502f,0.479099f,-0.0195111f,0.0145969f,0.999439f,0.0109987f, 0.332565f,0.471268f,-0.0191891f,0.0136233f,0.999325f,0.0140077f,
0.308899f,0.462176f,-0.0188165f,0.0126608f,0.999229f,0.0177473f, 0.285567f,0.451818f,-0.0183929f,0.0117119f,0.999143f,0.0223693f,
0.262634f,0.440196f,-0.0179181f,0.0107794f,0.999064f,0.0280535f, 0.240166f,0.427309f,-0.0173922f,0.00986586f,0.998982f,0.0350093f,
0.218232f,0.413164f,-0.0168153f,0.00897408f,0.998902f,0.043484f, 0.196901f,0.397767f,-0.0161877f,0.00810689f,0.998815f,0.0537627f,
0.176244f,0.381128f,-0.0155097f,0.00726711f,0.998719f,0.0661773f, 0.156335f,0.363263f,-0.0147818f,0.00645776f,0.998588f,0.0811024f,
0.137248f,0.34419f,-0.0140034f,0.00568196f,0.998318f,0.0989399f, 0.11906f,0.323932f,-0.0131767f,0.00494265f,0.997978f,0.120204f,
0.101842f,0.3025f,-0.0123035f,0.00424262f,0.997675f,0.145508f, 0.0856761f,0.279932f,-0.0113837f,0.00358531f,0.997237f,0.175428f,
0.0706423f,0.256257f,-0.0104183f,0.00297391f,0.996588f,0.210635f, 0.0568237f,0.23152f,-0.00940955f,0.00241164f,0.995708f,0.251899f,
0.0443012f,0.205758f,-0.00835878f,0.00190177f,0.994441f,0.299971f, 0.0331639f,0.179043f,-0.00726807f,0.00144772f,0.992494f,0.355527f,
0.0234949f,0.151427f,-0.00613935f,0.00105289f,0.989237f,0.418918f, 0.0153931f,0.123077f,-0.00497654f,0.000720824f,0.983393f,0.489654f,
0.00897057f,0.0944001f,-0.0037883f,0.000455457f,0.971718f,0.564595f, 0.00438483f,0.0669102f,-0.00261138f,0.000262393f,0.946075f,0.632811f,
0.00177932f,0.0446441f,-0.00158836f,0.000152201f,0.898569f,0.668629f, 0.000587871f,0.0215003f,-0.000864831f,0.000123882f,0.989821f,0.734956f,
1.0f,4.22994e-10f,-1.82715e-19f,0.0504001f,0.999996f,1.52281e-07f, 0.999497f,0.0224408f,-0.00113065f,0.0503747f,0.999996f,1.5759e-07f,
0.997987f,0.0448391f,-0.00225915f,0.0502986f,0.999996f,1.73878e-07f, 0.995474f,0.0671529f,-0.00338336f,0.050172f,0.999996f,2.02254e-07f,
0.991962f,0.0893397f,-0.00450113f,0.0499949f,0.999995f,2.44634e-07f, 0.987454f,0.111357f,-0.00561034f,0.0497677f,0.999994f,3.03861e-07f,
0.981959f,0.133164f,-0.00670884f,0.0494907f,0.999993f,3.83902e-07f, 0.975484f,0.154718f,-0.00779452f,0.0491644f,0.999992f,4.90164e-07f,
0.96804f,0.175977f,-0.00886528f,0.0487892f,0.999991f,6.30022e-07f, 0.959638f,0.196901f,-0.00991903f,0.0483658f,0.999989f,8.13672e-07f,
0.950289f,0.217447f,-0.0109537f,0.0478947f,0.999987f,1.05552e-06f, 0.94001f,0.237577f,-0.0119672f,0.0473768f,0.999985f,1.37642e-06f,
0.928816f,0.257248f,-0.0129575f,0.0468128f,0.999983f,1.80708e-06f, 0.916724f,0.276421f,-0.0139226f,0.0462036f,0.999981f,2.39337e-06f,
0.903751f,0.295057f,-0.0148605f,0.0455502f,0.999978f,3.20405e-06f, 0.88992f,0.313116f,-0.0157692f,0.0448535f,0.999975f,4.34211e-06f,
0.875249f,0.33056f,-0.0166467f,0.0441148f,0.999972f,5.96073e-06f, 0.859764f,0.34735f,-0.0174913f,0.0433353f,0.999968f,8.28553e-06f,
0.843488f,0.363448f,-0.0183009f,0.042516f,0.999964f,1.16449e-05f, 0.82645f,0.37882f,-0.0190737f,0.0416586f,0.99996f,1.65109e-05f,
0.808678f,0.393428f,-0.0198081f,0.0407644f,0.999955f,2.35526e-05f, 0.790205f,0.40724f,-0.0205022f,0.0398351f,0.99995f,3.37068e-05f,
0.771065f,0.420221f,-0.0211543f,0.0388722f,0.999944f,4.82679e-05f, 0.751288f,0.43234f,-0.0217628f,0.0378774f,0.999938f,6.90026e-05f,
0.730911f,0.443564f,-0.0223261f,0.0368524f,0.999931f,9.82941e-05f, 0.709968f,0.453861f,-0.0228425f,0.0357991f,0.999923f,0.000139321f,
0.688496f,0.463201f,-0.0233106f,0.0347192f,0.999914f,0.000196279f, 0.666532f,0.471554f,-0.0237288f,0.0336147f,0.999903f,0.000274647f,
0.644117f,0.478892f,-0.0240957f,0.0324878f,0.99989f,0.000381504f, 0.621293f,0.485187f,-0.02441f,0.0313404f,0.999873f,0.000525894f,
0.598101f,0.490413f,-0.0246701f,0.0301747f,0.999847f,0.000719178f, 0.57459f,0.494548f,-0.0248744f,0.0289931f,0.999801f,0.000975074f,
0.55081f,0.497572f,-0.02502f,0.0277982f,0.999681f,0.0013078f, 0.52681f,0.499466f,-0.0251063f,0.0265924f,0.99949f,0.00173815f,
0.50262f,0.500191f,-0.0251371f,0.0253776f,0.999378f,0.00230606f, 0.478299f,0.499737f,-0.0251097f,0.0241566f,0.999288f,0.0030429f,
0.4539f,0.498083f,-0.0250228f,0.0229319f,0.999211f,0.00399096f, 0.429479f,0.495219f,-0.0248755f,0.0217064f,0.999141f,0.00520182f,
0.40509f,0.491127f,-0.0246669f,0.0204828f,0.999076f,0.00673846f, 0.380793f,0.485801f,-0.0243965f,0.019264f,0.999013f,0.00867622f,
0.356644f,0.479225f,-0.0240637f,0.0180528f,0.998952f,0.0111062f, 0.332705f,0.471395f,-0.0236682f,0.0168523f,0.998891f,0.0141361f,
0.309036f,0.462303f,-0.0232097f,0.0156656f,0.99883f,0.0178945f, 0.285702f,0.451948f,-0.0226879f,0.0144958f,0.998763f,0.0225321f,
0.262768f,0.440329f,-0.0221029f,0.0133462f,0.998687f,0.0282263f, 0.2403f,0.427447f,-0.0214544f,0.01222f,0.998594f,0.0351841f,
0.218368f,0.413311f,-0.0207424f,0.0111208f,0.99845f,0.04364f, 0.197044f,0.397934f,-0.0199658f,0.0100525f,0.998155f,0.0538453f,
0.17639f,0.38131f,-0.0191285f,0.00901758f,0.997914f,0.0661761f, 0.15648f,0.363452f,-0.0182306f,0.00801996f,0.997679f,0.0809989f,
0.137392f,0.344387f,-0.0172719f,0.00706344f,0.997387f,0.0987248f, 0.119201f,0.324136f,-0.0162523f,0.00615197f,0.996902f,0.119789f,
0.101982f,0.302717f,-0.0151752f,0.00528894f,0.996395f,0.144799f, 0.085817f,0.280166f,-0.0140404f,0.00447852f,0.995654f,0.174285f,
0.0707837f,0.256513f,-0.0128505f,0.00372448f,0.994712f,0.208931f, 0.0569653f,0.231802f,-0.0116066f,0.00303096f,0.993355f,0.24936f,
0.0445045f,0.206356f,-0.0103137f,0.00240257f,0.991386f,0.296209f, 0.0333129f,0.179433f,-0.0089666f,0.00184168f,0.988382f,0.349939f,
0.023659f,0.151967f,-0.00757703f,0.00135446f,0.983509f,0.410539f, 0.0155989f,0.124024f,-0.00615073f,0.000945081f,0.975048f,0.476797f,
0.00929029f,0.0966521f,-0.00471316f,0.000619656f,0.959302f,0.54442f, 0.00479927f,0.0708787f,-0.00332667f,0.000385518f,0.929574f,0.602007f,
0.002241f,0.0501994f,-0.00217066f,0.000256784f,0.892223f,0.633824f, 0.000893985f,0.0264585f,-0.00131104f,0.000221307f,0.991712f,0.699651f,
1.0f,3.67031e-09f,1.45251e-19f,0.0609893f,0.999989f,6.77482e-07f, 0.999497f,0.0224407f,-0.00136813f,0.0609586f,0.999989f,6.93002e-07f,
0.997988f,0.0448392f,-0.00273366f,0.0608666f,0.999989f,7.40263e-07f, 0.995476f,0.0671529f,-0.00409398f,0.0607133f,0.999988f,8.21385e-07f,
0.991965f,0.0893398f,-0.0054465f,0.0604991f,0.999987f,9.40004e-07f, 0.98746f,0.111358f,-0.00678862f,0.0602242f,0.999986f,1.10142e-06f,
0.981967f,0.133165f,-0.00811777f,0.0598891f,0.999984f,1.31287e-06f, 0.975495f,0.154719f,-0.00943138f,0.0594943f,0.999982f,1.58393e-06f,
0.968054f,0.175979f,-0.0107269f,0.0590405f,0.99998f,1.92712e-06f, 0.959655f,0.196903f,-0.0120018f,0.0585282f,0.999978f,2.35898e-06f,
0.950311f,0.217451f,-0.0132535f,0.0579584f,0.999975f,2.90158e-06f, 0.940036f,0.237581f,-0.0144796f,0.0573319f,0.999971f,3.585e-06f,
0.928847f,0.257254f,-0.0156776f,0.0566497f,0.999967f,4.45107e-06f, 0.916759f,0.276429f,-0.016845f,0.0559128f,0.999963f,5.55885e-06f,
0.903793f,0.295067f,-0.0179794f,0.0551225f,0.999958f,6.99279e-06f, 0.889967f,0.313128f,-0.0190784f,0.05428f,0.999952f,8.87423e-06f,
0.875303f,0.330574f,-0.0201397f,0.0533866f,0.999946f,1.13776e-05f, 0.859823f,0.347367f,-0.0211609f,0.0524437f,0.999938f,1.47522e-05f,
0.843553f,0.363469f,-0.0221398f,0.0514529f,0.999929f,1.93519e-05f, 0.826519f,0.378843f,-0.023074f,0.0504159f,0.999918f,2.5672e-05f,
0.808748f,0.393452f,-0.0239613f,0.0493344f,0.999904f,3.43945e-05f, 0.790275f,0.407264f,-0.0247996f,0.0482104f,0.999884f,4.64333e-05f,
0.771133f,0.420246f,-0.0255865f,0.0470458f,0.999852f,6.29465e-05f, 0.751357f,0.432365f,-0.0263191f,0.0458426f,0.999793f,8.51855e-05f,
0.730989f,0.443594f,-0.0269932f,0.044603f,0.999661f,0.000113708f, 0.710067f,0.453905f,-0.027608f,0.0433295f,0.999471f,0.000151258f,
0.688614f,0.463258f,-0.028169f,0.0420245f,0.999361f,0.000206968f, 0.666667f,0.471624f,-0.0286712f,0.0406902f,0.999274f,0.000284824f,
0.644266f,0.478974f,-0.0291124f,0.0393287f,0.999201f,0.000391692f, 0.621455f,0.485281f,-0.0294906f,0.0379427f,0.999138f,0.000536753f,
0.598273f,0.490518f,-0.0298041f,0.0365347f,0.999081f,0.000731625f, 0.574768f,0.494662f,-0.0300513f,0.0351074f,0.999028f,0.000991008f,
0.550986f,0.497689f,-0.0302308f,0.0336638f,0.998978f,0.0013334f, 0.526975f,0.499575f,-0.0303413f,0.0322065f,0.99893f,0.00178191f,
0.502783f,0.500302f,-0.0303816f,0.0307387f,0.998885f,0.00236503f, 0.478462f,0.49985f,-0.0303504f,0.0292635f,0.99884f,0.00311766f,
0.454064f,0.498201f,-0.0302465f,0.027784f,0.998793f,0.00408236f, 0.429645f,0.495342f,-0.0300694f,0.0263034f,0.998748f,0.00531161f,
0.405258f,0.491257f,-0.029818f,0.0248253f,0.998697f,0.00686731f, 0.380962f,0.485934f,-0.0294916f,0.0233529f,0.998643f,0.00882527f,
0.356817f,0.479368f,-0.0290897f,0.0218899f,0.998582f,0.011275f, 0.332881f,0.471547f,-0.0286115f,0.0204399f,0.998502f,0.0143221f,
0.309216f,0.462466f,-0.028056f,0.0190068f,0.998376f,0.0180884f, 0.285892f,0.452132f,-0.0274215f,0.0175947f,0.998131f,0.0227067f,
0.262965f,0.440532f,-0.0267122f,0.0162068f,0.997927f,0.02838f, 0.240499f,0.427662f,-0.0259277f,0.014847f,0.997744f,0.0353127f,
0.218566f,0.413533f,-0.0250676f,0.0135196f,0.997554f,0.0437396f, 0.197238f,0.398158f,-0.0241317f,0.0122288f,0.997315f,0.0539271f,
0.176582f,0.381541f,-0.0231185f,0.0109791f,0.996924f,0.0661624f, 0.156676f,0.363705f,-0.0220329f,0.00977454f,0.996528f,0.0808483f,
0.137587f,0.344651f,-0.020874f,0.00861937f,0.996061f,0.0983838f, 0.119396f,0.324417f,-0.0196422f,0.00751851f,0.995399f,0.119192f,
0.102178f,0.303017f,-0.0183404f,0.00647617f,0.994607f,0.143819f, 0.0860142f,0.280494f,-0.0169695f,0.00549725f,0.993544f,0.172786f,
0.0709847f,0.256882f,-0.0155317f,0.00458644f,0.992111f,0.206673f, 0.0571686f,0.232214f,-0.0140289f,0.00374856f,0.990106f,0.246034f,
0.0446597f,0.206588f,-0.0124648f,0.00298864f,0.987235f,0.291354f, 0.0335421f,0.180077f,-0.0108431f,0.00231178f,0.982916f,0.342833f,
0.0239232f,0.15291f,-0.0091715f,0.00172351f,0.9761f,0.400057f, 0.0159252f,0.125566f,-0.00746692f,0.00123012f,0.964836f,0.461186f,
0.00972562f,0.0994215f,-0.00577837f,0.00084059f,0.945631f,0.521258f, 0.00542082f,0.0763394f,-0.00421463f,0.00056675f,0.915043f,0.570139f,
0.00270334f,0.0537563f,-0.00288996f,0.00041446f,0.891472f,0.601605f, 0.0013063f,0.0319007f,-0.00190972f,0.000373296f,0.993115f,0.6645f,
1.0f,3.01683e-09f,-5.22874e-19f,0.0725894f,0.999959f,2.36031e-06f, 0.999497f,0.0224407f,-0.00162817f,0.0725529f,0.999959f,2.39674e-06f,
0.997989f,0.0448391f,-0.00325322f,0.0724433f,0.999958f,2.50711e-06f, 0.995479f,0.0671529f,-0.00487205f,0.0722609f,0.999956f,2.69458e-06f,
0.991969f,0.08934f,-0.00648155f,0.072006f,0.999953f,2.96449e-06f, 0.987467f,0.111358f,-0.00807861f,0.0716789f,0.999949f,3.32442e-06f,
0.981977f,0.133166f,-0.00966014f,0.0712801f,0.999943f,3.78427e-06f, 0.975509f,0.15472f,-0.0112231f,0.0708103f,0.999937f,4.35629e-06f,
0.968072f,0.175981f,-0.0127643f,0.0702702f,0.999928f,5.05492e-06f, 0.959679f,0.196907f,-0.0142807f,0.0696605f,0.999916f,5.89614e-06f,
0.950339f,0.217455f,-0.0157692f,0.0689823f,0.9999f,6.89509e-06f, 0.940071f,0.237587f,-0.0172266f,0.0682365f,0.999876f,8.05914e-06f,
0.928887f,0.257262f,-0.0186495f,0.0674242f,0.999838f,9.36695e-06f, 0.916806f,0.276439f,-0.020034f,0.0665464f,0.999774f,1.07066e-05f,
0.903845f,0.295078f,-0.0213749f,0.0656039f,0.999652f,1.16987e-05f, 0.890024f,0.313141f,-0.022666f,0.0645976f,0.999427f,1.15148e-05f,
0.875363f,0.330588f,-0.0239183f,0.0635329f,0.99928f,1.24464e-05f, 0.859884f,0.347382f,-0.0251266f,0.0624106f,0.999178f,1.45536e-05f,
0.843614f,0.363483f,-0.0262862f,0.0612321f,0.999098f,1.79895e-05f, 0.82658f,0.378858f,-0.027394f,0.0599991f,0.999033f,2.31997e-05f,
0.808819f,0.393471f,-0.0284472f,0.058714f,0.998977f,3.08717e-05f, 0.79036f,0.407291f,-0.0294429f,0.0573789f,0.998927f,4.19919e-05f,
0.77124f,0.420284f,-0.0303789f,0.0559959f,0.998884f,5.79666e-05f, 0.751487f,0.432417f,-0.0312524f,0.0545675f,0.998845f,8.06251e-05f,
0.731133f,0.443656f,-0.0320612f,0.0530959f,0.998808f,0.000112483f, 0.710212f,0.453969f,-0.0328027f,0.0515837f,0.998774f,0.000156854f,
0.688762f,0.463326f,-0.0334749f,0.0500336f,0.998741f,0.000218071f, 0.666817f,0.471696f,-0.0340757f,0.0484483f,0.998712f,0.000301907f,
0.644421f,0.479051f,-0.0346027f,0.0468308f,0.998681f,0.000415522f, 0.621614f,0.485363f,-0.0350545f,0.0451841f,0.998652f,0.000568426f,
0.59844f,0.490608f,-0.0354288f,0.0435113f,0.998622f,0.000772331f, 0.574941f,0.494759f,-0.0357238f,0.0418157f,0.99859f,0.00104217f,
0.551164f,0.497792f,-0.0359382f,0.0401006f,0.998558f,0.00139667f, 0.527159f,0.499687f,-0.0360702f,0.0383695f,0.998523f,0.0018589f,
0.502973f,0.500422f,-0.0361183f,0.0366259f,0.998484f,0.00245732f, 0.478659f,0.49998f,-0.0360811f,0.0348736f,0.998438f,0.0032267f,
0.45427f,0.498343f,-0.0359574f,0.0331163f,0.998378f,0.0042091f, 0.42986f,0.495498f,-0.0357454f,0.0313581f,0.998292f,0.00545452f,
0.405487f,0.491433f,-0.035443f,0.0296032f,0.998141f,0.00701961f, 0.381206f,0.486135f,-0.0350496f,0.0278556f,0.997927f,0.00897647f,
0.357068f,0.479584f,-0.0345694f,0.0261189f,0.99777f,0.0114306f, 0.333137f,0.471777f,-0.034f,0.0243974f,0.99763f,0.0144837f,
0.309474f,0.462708f,-0.0333403f,0.0226957f,0.997482f,0.0182585f, 0.286146f,0.452376f,-0.03259f,0.0210184f,0.997313f,0.0229008f,
0.26322f,0.440785f,-0.0317478f,0.0193704f,0.997082f,0.0285746f, 0.24076f,0.427936f,-0.0308128f,0.0177565f,0.996738f,0.0354665f,
0.218829f,0.413823f,-0.0297897f,0.0161807f,0.996423f,0.0438409f, 0.197501f,0.398463f,-0.028677f,0.0146484f,0.996061f,0.0539525f,
0.176849f,0.381866f,-0.0274734f,0.0131648f,0.995547f,0.0660796f, 0.156941f,0.364043f,-0.0261832f,0.0117347f,0.994991f,0.0806041f,
0.137853f,0.345013f,-0.024805f,0.0103635f,0.994255f,0.0978828f, 0.119663f,0.3248f,-0.0233422f,0.00905641f,0.99337f,0.118371f,
0.102448f,0.303436f,-0.0217952f,0.00781903f,0.992207f,0.142516f, 0.0862835f,0.280941f,-0.0201664f,0.00665676f,0.990686f,0.170819f,
0.0712583f,0.257379f,-0.0184586f,0.00557537f,0.988645f,0.203776f, 0.0574736f,0.232881f,-0.0166764f,0.00458095f,0.985845f,0.241841f,
0.0449757f,0.20737f,-0.0148216f,0.00367874f,0.981869f,0.285309f, 0.0338921f,0.181119f,-0.012903f,0.00287553f,0.97602f,0.334131f,
0.0243917f,0.154798f,-0.0109415f,0.00217963f,0.967137f,0.387522f, 0.0165124f,0.128574f,-0.00896158f,0.00159787f,0.953279f,0.443179f,
0.0104692f,0.104243f,-0.00704406f,0.00114331f,0.931917f,0.496116f, 0.00638148f,0.0843494f,-0.00533917f,0.000833214f,0.903705f,0.538581f,
0.00360477f,0.0626575f,-0.00388659f,0.00066333f,0.894446f,0.571213f, 0.00184562f,0.0377953f,-0.00269053f,0.000600502f,0.994186f,0.629887f,
1.0f,-8.94742e-09f,-1.47347e-19f,0.0851625f,0.999203f,5.47751e-06f, 0.999498f,0.02244f,-0.00189564f,0.0851176f,0.99916f,5.40512e-06f,
0.997991f,0.0448375f,-0.00378355f,0.0849825f,0.999018f,5.11695e-06f, 0.995483f,0.0671501f,-0.00565483f,0.0847557f,0.998736f,4.36723e-06f,
0.991976f,0.0893362f,-0.00751824f,0.0844455f,0.998465f,3.47317e-06f, 0.987476f,0.111354f,-0.00938254f,0.0840596f,0.998367f,3.08984e-06f,
0.981991f,0.133162f,-0.0112325f,0.0835923f,0.998315f,2.88129e-06f, 0.975528f,0.154718f,-0.0130626f,0.0830429f,0.998284f,2.78983e-06f,
0.968097f,0.175979f,-0.0148683f,0.0824118f,0.998265f,2.80277e-06f, 0.959708f,0.196906f,-0.0166458f,0.0816996f,0.998252f,2.92072e-06f,
0.950376f,0.217456f,-0.0183914f,0.0809074f,0.998244f,3.15799e-06f, 0.940113f,0.23759f,-0.0201015f,0.0800364f,0.998239f,3.54433e-06f,
0.928936f,0.257266f,-0.0217726f,0.0790878f,0.998236f,4.12061e-06f, 0.916861f,0.276445f,-0.0234011f,0.0780631f,0.998234f,4.95356e-06f,
0.903906f,0.295087f,-0.0249837f,0.0769639f,0.998232f,6.13588e-06f, 0.890091f,0.313153f,-0.026517f,0.0757919f,0.998231f,7.81625e-06f,
0.875436f,0.330603f,-0.0279977f,0.074549f,0.998231f,1.01901e-05f, 0.859965f,0.3474f,-0.0294225f,0.0732372f,0.99823f,1.35461e-05f,
0.843703f,0.363506f,-0.0307883f,0.0718588f,0.998229f,1.82912e-05f, 0.826681f,0.378886f,-0.032092f,0.0704162f,0.998227f,2.49942e-05f,
0.80893f,0.393505f,-0.0333307f,0.0689121f,0.998225f,3.44421e-05f, 0.790483f,0.407331f,-0.0345015f,0.067349f,0.998223f,4.77272e-05f,
0.771371f,0.42033f,-0.0356015f,0.0657297f,0.998219f,6.63028e-05f, 0.751625f,0.432468f,-0.0366278f,0.0640569f,0.998214f,9.21307e-05f,
0.73128f,0.443713f,-0.0375777f,0.0623334f,0.998207f,0.000127818f, 0.710369f,0.454033f,-0.0384486f,0.0605623f,0.9982f,0.000176842f,
0.688927f,0.463397f,-0.0392378f,0.0587468f,0.99819f,0.000243645f, 0.666994f,0.471775f,-0.0399428f,0.0568902f,0.998176f,0.000334031f,
0.644608f,0.479138f,-0.0405614f,0.0549958f,0.99816f,0.000455455f, 0.621812f,0.485461f,-0.0410909f,0.0530672f,0.998136f,0.000617262f,
0.598647f,0.490715f,-0.0415293f,0.0511082f,0.998105f,0.000831346f, 0.575161f,0.494878f,-0.041874f,0.0491226f,0.998057f,0.00111214f,
0.5514f,0.497927f,-0.0421225f,0.0471144f,0.99798f,0.00147723f, 0.527416f,0.499845f,-0.0422712f,0.0450881f,0.997838f,0.00194631f,
0.503253f,0.500606f,-0.0423203f,0.0430476f,0.997661f,0.00254853f, 0.478955f,0.500185f,-0.0422735f,0.0409967f,0.997539f,0.00332677f,
0.454576f,0.498566f,-0.0421267f,0.0389399f,0.997429f,0.00432059f, 0.43017f,0.495731f,-0.0418782f,0.0368818f,0.997322f,0.00558108f,
0.405801f,0.491678f,-0.0415267f,0.0348273f,0.997208f,0.00716916f, 0.381516f,0.486383f,-0.0410704f,0.0327808f,0.997076f,0.00915786f,
0.357383f,0.479845f,-0.040508f,0.0307478f,0.9969f,0.0116315f, 0.333464f,0.472063f,-0.0398374f,0.0287338f,0.996634f,0.0146854f,
0.309811f,0.463017f,-0.0390618f,0.0267428f,0.996366f,0.0184548f, 0.286486f,0.452702f,-0.0381816f,0.0247801f,0.996109f,0.0230887f,
0.263561f,0.441126f,-0.0371946f,0.0228515f,0.995801f,0.028746f, 0.241105f,0.428297f,-0.0360996f,0.0209629f,0.995376f,0.0356067f,
0.219175f,0.414202f,-0.0349001f,0.019119f,0.994929f,0.0439176f, 0.19785f,0.398863f,-0.0335957f,0.0173263f,0.994392f,0.053925f,
0.177199f,0.382289f,-0.032186f,0.0155904f,0.993716f,0.0659121f, 0.157293f,0.364491f,-0.0306738f,0.0139173f,0.992909f,0.080218f,
0.13821f,0.345495f,-0.02906f,0.0123129f,0.991922f,0.0972065f, 0.120025f,0.325327f,-0.0273462f,0.0107838f,0.990664f,0.117268f,
0.102812f,0.304001f,-0.0255345f,0.00933601f,0.989061f,0.140832f, 0.0866611f,0.28159f,-0.0236282f,0.00797633f,0.986976f,0.168332f,
0.0716645f,0.258179f,-0.0216317f,0.00671156f,0.984212f,0.200181f, 0.05788f,0.233748f,-0.0195475f,0.00554787f,0.980457f,0.236705f,
0.0454404f,0.208573f,-0.0173866f,0.00449348f,0.975229f,0.278029f, 0.0344667f,0.182999f,-0.0151639f,0.00355657f,0.967762f,0.323861f,
0.0250503f,0.157372f,-0.0129045f,0.00274587f,0.956913f,0.37313f, 0.0173681f,0.132805f,-0.0106694f,0.00207454f,0.941099f,0.423342f,
0.0117833f,0.112988f,-0.00860511f,0.00156578f,0.91926f,0.470027f, 0.00750275f,0.0920543f,-0.00669756f,0.00120796f,0.895925f,0.508123f,
0.00465812f,0.0708989f,-0.00511923f,0.00102212f,0.899549f,0.54208f, 0.00253609f,0.0441423f,-0.00368562f,0.000928488f,0.995023f,0.596087f,
1.0f,7.80679e-10f,-2.08854e-18f,0.0985842f,0.996055f,4.61736e-07f, 0.999498f,0.0224405f,-0.00220873f,0.0985347f,0.996055f,4.75647e-07f,
0.997993f,0.0448387f,-0.00441322f,0.0983862f,0.996054f,5.18299e-07f, 0.995487f,0.0671526f,-0.00660926f,0.098139f,0.996052f,5.92504e-07f,
0.991983f,0.0893399f,-0.00879263f,0.0977935f,0.996049f,7.0315e-07f, 0.987488f,0.111359f,-0.0109591f,0.0973503f,0.996046f,8.57529e-07f,
0.982007f,0.133167f,-0.0131045f,0.0968099f,0.996042f,1.06585e-06f, 0.975549f,0.154723f,-0.0152247f,0.0961733f,0.996037f,1.342e-06f,
0.968124f,0.175986f,-0.0173155f,0.0954414f,0.996031f,1.70468e-06f, 0.959741f,0.196914f,-0.0193728f,0.0946154f,0.996025f,2.17907e-06f,
0.950414f,0.217465f,-0.0213925f,0.0936964f,0.996017f,2.79924e-06f, 0.940155f,0.2376f,-0.0233705f,0.0926861f,0.996008f,3.61163e-06f,
0.928983f,0.257277f,-0.0252943f,0.0915962f,0.99612f,4.72315e-06f, 0.916915f,0.276457f,-0.0271656f,0.0904237f,0.996292f,6.18657e-06f,
0.903968f,0.295101f,-0.0289855f,0.0891647f,0.996459f,8.10406e-06f, 0.890161f,0.313169f,-0.0307508f,0.08782f,0.996607f,1.06488e-05f,
0.875516f,0.330622f,-0.0324574f,0.0863917f,0.996735f,1.40641e-05f, 0.860058f,0.347423f,-0.0341012f,0.0848824f,0.996845f,1.86839e-05f,
0.843813f,0.363536f,-0.035678f,0.0832948f,0.996938f,2.49674e-05f, 0.82681f,0.378924f,-0.0371841f,0.0816319f,0.997017f,3.35414e-05f,
0.809077f,0.393552f,-0.0386156f,0.0798968f,0.997085f,4.5259e-05f, 0.790647f,0.407387f,-0.0399689f,0.0780928f,0.997141f,6.12649e-05f,
0.77155f,0.420394f,-0.0412403f,0.0762228f,0.997186f,8.30855e-05f, 0.75182f,0.432542f,-0.0424265f,0.0742904f,0.997218f,0.000112728f,
0.731489f,0.443797f,-0.0435239f,0.072299f,0.997236f,0.000152787f, 0.710592f,0.454128f,-0.0445288f,0.0702522f,0.997235f,0.000206542f,
0.689168f,0.463505f,-0.0454375f,0.0681538f,0.997202f,0.000277957f, 0.667259f,0.471901f,-0.0462452f,0.0660079f,0.997115f,0.000371515f,
0.644902f,0.479288f,-0.0469498f,0.0638185f,0.996978f,0.000493948f, 0.622127f,0.48563f,-0.047557f,0.0615897f,0.996895f,0.000659869f,
0.598981f,0.490904f,-0.0480611f,0.0593256f,0.996829f,0.00088006f, 0.575508f,0.495083f,-0.0484588f,0.0570306f,0.996768f,0.00116927f,
0.551759f,0.498149f,-0.0487475f,0.0547094f,0.996707f,0.00154616f, 0.527777f,0.500075f,-0.0489246f,0.0523666f,0.99664f,0.00203372f,
0.503614f,0.500842f,-0.048988f,0.050007f,0.996561f,0.00266014f, 0.479323f,0.500434f,-0.0489354f,0.0476359f,0.99646f,0.00345916f,
0.454955f,0.498833f,-0.048764f,0.0452584f,0.996316f,0.00447059f, 0.430569f,0.496029f,-0.0484707f,0.0428801f,0.996092f,0.00573995f,
0.40621f,0.491996f,-0.0480602f,0.0405058f,0.995889f,0.00733842f, 0.381939f,0.486728f,-0.0475309f,0.0381409f,0.995695f,0.00933947f,
0.357812f,0.48021f,-0.04688f,0.0357912f,0.995478f,0.0118261f, 0.333895f,0.472443f,-0.0461056f,0.0334629f,0.995199f,0.0148952f,
0.310247f,0.463416f,-0.0452062f,0.0311621f,0.994831f,0.0186606f, 0.286929f,0.453126f,-0.0441863f,0.0288941f,0.994468f,0.0232799f,
0.264009f,0.441573f,-0.0430431f,0.0266655f,0.994038f,0.0289054f, 0.241555f,0.428766f,-0.0417756f,0.0244831f,0.993491f,0.0357158f,
0.219631f,0.414699f,-0.0403876f,0.0223527f,0.992891f,0.0439448f, 0.198307f,0.399385f,-0.0388764f,0.0202812f,0.992137f,0.0538183f,
0.177662f,0.382847f,-0.0372458f,0.0182754f,0.991249f,0.0656265f, 0.157762f,0.36509f,-0.0354959f,0.0163422f,0.990162f,0.0796707f,
0.138681f,0.346133f,-0.0336286f,0.0144886f,0.988815f,0.0962886f, 0.1205f,0.32601f,-0.0316463f,0.0127218f,0.987135f,0.115845f,
0.103332f,0.304857f,-0.0295547f,0.0110502f,0.985004f,0.138717f, 0.0871783f,0.282495f,-0.0273518f,0.00947914f,0.982254f,0.16527f,
0.0722435f,0.259366f,-0.0250509f,0.00801918f,0.978655f,0.195831f, 0.0585147f,0.235246f,-0.0226533f,0.00667633f,0.973843f,0.230597f,
0.0461653f,0.210594f,-0.0201778f,0.00546112f,0.96731f,0.269537f, 0.0353516f,0.186007f,-0.0176525f,0.00438472f,0.958296f,0.312163f,
0.0265156f,0.163958f,-0.0151795f,0.00347239f,0.945825f,0.357228f, 0.0186726f,0.139204f,-0.0126563f,0.00269805f,0.928968f,0.402321f,
0.0133422f,0.121982f,-0.0104427f,0.0021335f,0.908323f,0.443836f, 0.00871952f,0.0985731f,-0.00829416f,0.00171739f,0.891322f,0.479062f,
0.00571382f,0.0767384f,-0.00655959f,0.00150935f,0.905551f,0.513838f, 0.0034014f,0.0508961f,-0.00492789f,0.00138789f,0.995685f,0.563292f,
1.0f,-1.33251e-08f,-7.67588e-19f,0.113194f,0.99601f,1.32041e-06f, 0.999498f,0.0224403f,-0.0025351f,0.113137f,0.99601f,1.35011e-06f,
0.997995f,0.0448384f,-0.00506531f,0.112967f,0.996008f,1.4407e-06f, 0.995492f,0.0671522f,-0.00758579f,0.112683f,0.996005f,1.59669e-06f,
0.991992f,0.0893397f,-0.0100916f,0.112287f,0.996001f,1.82584e-06f, 0.987503f,0.111359f,-0.012578f,0.111778f,0.995995f,2.13959e-06f,
0.982028f,0.133168f,-0.0150402f,0.111158f,0.995989f,2.55367e-06f, 0.975578f,0.154725f,-0.0174732f,0.110428f,0.995981f,3.08901e-06f,
0.968162f,0.175989f,-0.0198723f,0.109588f,0.995971f,3.77303e-06f, 0.95979f,0.196919f,-0.0222328f,0.108641f,0.99596f,4.64151e-06f,
0.950476f,0.217474f,-0.02455f,0.107587f,0.995947f,5.74117e-06f, 0.940234f,0.237612f,-0.0268192f,0.106428f,0.995931f,7.13327e-06f,
0.929077f,0.257295f,-0.0290357f,0.105167f,0.995913f,8.8985e-06f, 0.917024f,0.27648f,-0.0311948f,0.103804f,0.995892f,1.11437e-05f,
0.90409f,0.29513f,-0.0332921f,0.102343f,0.995868f,1.40101e-05f, 0.890294f,0.313203f,-0.0353229f,0.100785f,0.995838f,1.76843e-05f,
0.875656f,0.33066f,-0.0372826f,0.0991329f,0.995801f,2.24093e-05f, 0.860204f,0.347465f,-0.0391666f,0.0973899f,0.995754f,2.84938e-05f,
0.843966f,0.363582f,-0.0409705f,0.095559f,0.995691f,3.6312e-05f, 0.826979f,0.378978f,-0.0426893f,0.0936438f,0.995604f,4.62771e-05f,
0.809279f,0.393622f,-0.0443176f,0.0916478f,0.995476f,5.8764e-05f, 0.790899f,0.407482f,-0.0458495f,0.0895743f,0.995287f,7.40408e-05f,
0.771852f,0.420518f,-0.0472928f,0.0874279f,0.995142f,9.60688e-05f, 0.752167f,0.432695f,-0.0486421f,0.0852116f,0.995028f,0.000126991f,
0.731875f,0.443978f,-0.0498915f,0.082929f,0.994927f,0.000169288f, 0.711013f,0.454337f,-0.0510369f,0.0805838f,0.994832f,0.000226511f,
0.689617f,0.46374f,-0.0520747f,0.0781804f,0.99474f,0.00030338f, 0.667727f,0.472158f,-0.0530012f,0.0757232f,0.994647f,0.000405869f,
0.645383f,0.479564f,-0.053813f,0.0732166f,0.994548f,0.000541604f, 0.622625f,0.485928f,-0.0545067f,0.0706653f,0.99444f,0.000720092f,
0.599498f,0.491227f,-0.0550791f,0.0680745f,0.994313f,0.000953084f, 0.576046f,0.495434f,-0.055526f,0.0654513f,0.994183f,0.00125473f,
0.552312f,0.498522f,-0.0558431f,0.0628051f,0.994074f,0.00164159f, 0.528345f,0.500474f,-0.0560319f,0.060136f,0.993962f,0.0021378f,
0.50419f,0.50126f,-0.0560957f,0.0574475f,0.993893f,0.00277718f, 0.479901f,0.500867f,-0.0560295f,0.054745f,0.993822f,0.00359193f,
0.455537f,0.499283f,-0.0558302f,0.0520345f,0.993726f,0.00462238f, 0.431152f,0.496494f,-0.0554949f,0.0493222f,0.99358f,0.00591614f,
0.406799f,0.492483f,-0.0550202f,0.0466143f,0.993352f,0.00752854f, 0.38253f,0.487232f,-0.05441f,0.0439162f,0.993121f,0.00954026f,
0.358405f,0.480734f,-0.0536623f,0.041235f,0.992866f,0.0120351f, 0.334489f,0.472986f,-0.0527737f,0.0385777f,0.992535f,0.0151055f,
0.310845f,0.463984f,-0.0517439f,0.0359512f,0.99212f,0.0188664f, 0.28753f,0.453717f,-0.0505754f,0.0333618f,0.99167f,0.0234638f,
0.264612f,0.442191f,-0.0492644f,0.0308175f,0.991094f,0.0290399f, 0.24216f,0.429411f,-0.0478148f,0.028325f,0.990442f,0.0357877f,
0.22024f,0.41538f,-0.0462243f,0.0258922f,0.989637f,0.043901f, 0.198924f,0.40011f,-0.0444959f,0.0235265f,0.988683f,0.0536195f,
0.17828f,0.383608f,-0.04263f,0.0212357f,0.987525f,0.065199f, 0.158384f,0.365898f,-0.0406282f,0.0190276f,0.986109f,0.0789247f,
0.139332f,0.347052f,-0.0384939f,0.0169109f,0.984362f,0.0951051f, 0.121179f,0.327058f,-0.0362301f,0.0148934f,0.982195f,0.114068f,
0.104008f,0.305957f,-0.0338395f,0.0129835f,0.979457f,0.136133f, 0.0879247f,0.283886f,-0.0313307f,0.0111908f,0.975969f,0.161604f,
0.0730842f,0.261179f,-0.0287177f,0.00952649f,0.97146f,0.19071f, 0.0594363f,0.237505f,-0.026f,0.00799578f,0.965561f,0.223541f,
0.0472182f,0.213595f,-0.0232114f,0.00661368f,0.957767f,0.259925f, 0.0367485f,0.190941f,-0.0204232f,0.00540191f,0.947441f,0.299253f,
0.0276464f,0.167829f,-0.0176287f,0.00435711f,0.933924f,0.340233f, 0.0205157f,0.147897f,-0.0149822f,0.00351307f,0.917099f,0.380738f,
0.0144866f,0.125633f,-0.0124314f,0.00284888f,0.89912f,0.418134f, 0.0100398f,0.104166f,-0.0101686f,0.00239833f,0.889126f,0.451439f,
0.00730512f,0.086411f,-0.00838643f,0.00219536f,0.911692f,0.486366f, 0.00446838f,0.0580427f,-0.00645173f,0.00201512f,0.996209f,0.531638f,
1.0f,1.04096e-08f,-5.20905e-19f,0.128815f,0.995874f,3.2778e-06f, 0.9995f,0.0224399f,-0.00288291f,0.12875f,0.995873f,3.33257e-06f,
0.997997f,0.0448377f,-0.00576018f,0.128556f,0.995868f,3.49869e-06f, 0.995499f,0.0671514f,-0.00862622f,0.128233f,0.99586f,3.78162e-06f,
0.992003f,0.0893388f,-0.0114754f,0.127782f,0.995848f,4.19042e-06f, 0.987521f,0.111358f,-0.0143021f,0.127204f,0.995832f,4.73771e-06f,
0.982054f,0.133168f,-0.0171006f,0.126498f,0.995811f,5.43925e-06f, 0.975613f,0.154726f,-0.0198653f,0.125667f,0.995783f,6.31308e-06f,
0.968207f,0.175992f,-0.0225904f,0.124712f,0.995747f,7.37733e-06f, 0.959848f,0.196924f,-0.0252702f,0.123633f,0.995699f,8.64551e-06f,
0.950548f,0.217481f,-0.0278986f,0.122434f,0.995634f,1.01167e-05f, 0.94032f,0.237622f,-0.0304692f,0.121114f,0.995544f,1.17564e-05f,
0.92918f,0.257308f,-0.0329752f,0.119676f,0.995418f,1.34623e-05f, 0.917145f,0.276498f,-0.0354091f,0.118123f,0.995239f,1.50122e-05f,
0.904231f,0.295152f,-0.0377729f,0.116458f,0.995056f,1.6868e-05f, 0.890455f,0.313232f,-0.0400707f,0.114687f,0.994938f,2.01208e-05f,
0.875839f,0.330698f,-0.0422918f,0.11281f,0.994842f,2.47146e-05f, 0.860404f,0.34751f,-0.0444295f,0.110831f,0.994757f,3.0987e-05f,
0.844179f,0.363633f,-0.0464787f,0.108753f,0.99468f,3.94575e-05f, 0.827195f,0.379033f,-0.0484346f,0.106579f,0.994606f,5.08546e-05f,
0.809493f,0.393677f,-0.0502924f,0.104314f,0.994533f,6.61344e-05f, 0.791104f,0.407535f,-0.0520478f,0.101962f,0.994459f,8.6604e-05f,
0.772058f,0.420571f,-0.0536959f,0.099527f,0.994381f,0.000113926f, 0.752382f,0.432752f,-0.0552323f,0.0970122f,0.994295f,0.000150271f,
0.732109f,0.444045f,-0.0566522f,0.0944224f,0.994195f,0.000198399f, 0.711271f,0.454418f,-0.057951f,0.0917619f,0.994076f,0.000261764f,
0.689908f,0.463841f,-0.0591235f,0.0890358f,0.993922f,0.000344465f, 0.668056f,0.472285f,-0.0601648f,0.0862492f,0.993718f,0.000451455f,
0.645748f,0.479717f,-0.061077f,0.0834072f,0.993515f,0.000592323f, 0.623022f,0.486108f,-0.0618599f,0.0805149f,0.993343f,0.000778846f,
0.599924f,0.491432f,-0.0625075f,0.0775779f,0.993175f,0.00102226f, 0.576499f,0.495665f,-0.0630154f,0.074602f,0.992995f,0.00133728f,
0.552795f,0.498786f,-0.0633798f,0.0715931f,0.992791f,0.0017419f, 0.528863f,0.500776f,-0.0635969f,0.0685576f,0.992545f,0.00225764f,
0.504757f,0.501618f,-0.0636627f,0.065502f,0.992235f,0.00290998f, 0.480496f,0.501263f,-0.0635819f,0.0624313f,0.991943f,0.00373991f,
0.456165f,0.499726f,-0.0633511f,0.0593534f,0.991642f,0.00478714f, 0.4318f,0.496973f,-0.0629656f,0.0562744f,0.991297f,0.00609809f,
0.407469f,0.493002f,-0.0624219f,0.0532022f,0.990873f,0.00772691f, 0.383224f,0.487798f,-0.0617241f,0.0501432f,0.990433f,0.00975113f,
0.359118f,0.481344f,-0.0608693f,0.0471046f,0.989951f,0.0122512f, 0.335223f,0.473644f,-0.0598539f,0.0440946f,0.989368f,0.0153157f,
0.311588f,0.464678f,-0.0586811f,0.0411195f,0.988744f,0.0190676f, 0.288289f,0.454463f,-0.0573484f,0.0381887f,0.988002f,0.023627f,
0.265389f,0.442994f,-0.0558585f,0.0353095f,0.987178f,0.0291528f, 0.243352f,0.430979f,-0.0542284f,0.0325017f,0.9862f,0.0358071f,
0.22103f,0.416272f,-0.0524015f,0.0297382f,0.985067f,0.043789f, 0.199725f,0.401063f,-0.0504388f,0.0270634f,0.983737f,0.0533153f,
0.179111f,0.384668f,-0.0483224f,0.0244743f,0.982157f,0.0646246f, 0.159284f,0.367167f,-0.0460562f,0.0219803f,0.980269f,0.0779805f,
0.140196f,0.3483f,-0.0436371f,0.0195876f,0.977982f,0.0936578f, 0.12209f,0.328497f,-0.0410771f,0.0173092f,0.975184f,0.11194f,
0.105028f,0.307794f,-0.0383845f,0.0151556f,0.971722f,0.133097f, 0.089044f,0.286149f,-0.0355627f,0.0131343f,0.967402f,0.157366f,
0.0742306f,0.263683f,-0.0326253f,0.0112569f,0.961943f,0.18489f, 0.060712f,0.240664f,-0.0295939f,0.00953548f,0.955003f,0.215665f,
0.048801f,0.218273f,-0.0265308f,0.00799284f,0.946146f,0.249418f, 0.0389829f,0.199111f,-0.0235584f,0.00666326f,0.934929f,0.285482f,
0.0303269f,0.179202f,-0.0205927f,0.00551771f,0.92112f,0.322647f, 0.0226635f,0.15682f,-0.0176326f,0.00455302f,0.905388f,0.359167f,
0.016725f,0.136019f,-0.0149301f,0.00382725f,0.891349f,0.393299f, 0.0124214f,0.117003f,-0.0125808f,0.00335265f,0.888598f,0.425177f,
0.00845123f,0.0894113f,-0.0103304f,0.003043f,0.917545f,0.459656f, 0.0061988f,0.0695749f,-0.00843294f,0.00290109f,0.99663f,0.501226f,
0.999999f,2.25737e-08f,-9.03621e-19f,0.145376f,0.994898f,6.03928e-06f, 0.999501f,0.0224378f,-0.00323233f,0.145302f,0.994875f,6.04634e-06f,
0.998001f,0.0448334f,-0.00645623f,0.145079f,0.994806f,6.04972e-06f, 0.995506f,0.0671447f,-0.00966309f,0.144707f,0.994684f,5.99203e-06f,
0.992019f,0.0893297f,-0.0128441f,0.144187f,0.994498f,5.76462e-06f, 0.987543f,0.111347f,-0.0159995f,0.143523f,0.994295f,5.44194e-06f,
0.982087f,0.133157f,-0.0191426f,0.142727f,0.994205f,5.60613e-06f, 0.975658f,0.154716f,-0.0222542f,0.141792f,0.994151f,6.06107e-06f,
0.968265f,0.175983f,-0.025325f,0.140719f,0.994113f,6.78954e-06f, 0.95992f,0.196917f,-0.0283477f,0.139509f,0.994082f,7.81827e-06f,
0.950634f,0.217477f,-0.0313156f,0.138164f,0.994055f,9.20411e-06f, 0.940424f,0.237624f,-0.0342225f,0.136685f,0.994029f,1.10238e-05f,
0.929303f,0.257315f,-0.0370621f,0.135074f,0.994002f,1.33853e-05f, 0.917288f,0.276512f,-0.0398283f,0.133335f,0.993972f,1.64291e-05f,
0.904396f,0.295175f,-0.0425152f,0.13147f,0.993939f,2.03474e-05f, 0.890647f,0.313264f,-0.0451167f,0.129481f,0.993899f,2.53776e-05f,
0.876059f,0.330741f,-0.0476269f,0.127372f,0.993853f,3.18436e-05f, 0.860654f,0.347566f,-0.0500399f,0.125147f,0.993795f,4.01431e-05f,
0.844454f,0.363701f,-0.0523495f,0.122808f,0.993722f,5.07817e-05f, 0.827488f,0.379109f,-0.0545499f,0.120361f,0.993627f,6.43721e-05f,
0.809791f,0.393758f,-0.0566349f,0.11781f,0.993501f,8.16277e-05f, 0.791404f,0.407617f,-0.0585983f,0.11516f,0.993331f,0.000103341f,
0.77237f,0.42066f,-0.0604408f,0.112418f,0.99315f,0.000131774f, 0.752714f,0.432852f,-0.0621648f,0.109588f,0.993009f,0.000170856f,
0.732466f,0.44416f,-0.0637612f,0.106675f,0.992877f,0.00022298f, 0.711656f,0.45455f,-0.0652237f,0.103684f,0.992743f,0.000291827f,
0.690317f,0.46399f,-0.0665471f,0.100618f,0.992599f,0.000382185f, 0.668485f,0.47245f,-0.0677264f,0.0974847f,0.992435f,0.000499968f,
0.646207f,0.479905f,-0.0687564f,0.0942893f,0.992239f,0.000652359f, 0.623519f,0.486327f,-0.0696319f,0.0910382f,0.991996f,0.000848045f,
0.60046f,0.491684f,-0.0703531f,0.0877373f,0.991733f,0.00110043f, 0.577073f,0.495954f,-0.0709212f,0.0843927f,0.991492f,0.00142758f,
0.553403f,0.49911f,-0.0713293f,0.0810114f,0.991237f,0.00184646f, 0.529493f,0.501126f,-0.0715722f,0.0776002f,0.990942f,0.00237844f,
0.505408f,0.501995f,-0.0716458f,0.0741666f,0.990589f,0.00304918f, 0.481181f,0.501683f,-0.0715515f,0.0707172f,0.990212f,0.00389514f,
0.456872f,0.500179f,-0.0712886f,0.0672592f,0.989825f,0.00495873f, 0.432537f,0.49747f,-0.0708514f,0.0638012f,0.989377f,0.00628365f,
0.408233f,0.493544f,-0.0702382f,0.0603507f,0.98886f,0.00792618f, 0.384004f,0.488372f,-0.0694506f,0.0569147f,0.988313f,0.0099598f,
0.359926f,0.481969f,-0.0684847f,0.053503f,0.987672f,0.0124567f, 0.336051f,0.474315f,-0.0673421f,0.0501227f,0.986972f,0.0155163f,
0.312446f,0.465414f,-0.0660204f,0.0467834f,0.986158f,0.01924f, 0.289643f,0.455999f,-0.0645438f,0.0435083f,0.985247f,0.023758f,
0.266275f,0.443822f,-0.0628427f,0.0402607f,0.984189f,0.0292076f, 0.243871f,0.431185f,-0.0609877f,0.0370962f,0.982968f,0.0357521f,
0.221983f,0.417282f,-0.0589564f,0.0340083f,0.981549f,0.0435733f, 0.200742f,0.402239f,-0.0567529f,0.0310078f,0.97989f,0.052873f,
0.180164f,0.385971f,-0.0543773f,0.0281032f,0.977928f,0.0638699f, 0.160293f,0.368427f,-0.0518288f,0.0253025f,0.975593f,0.0767999f,
0.141421f,0.350144f,-0.0491302f,0.0226248f,0.97279f,0.091907f, 0.123302f,0.3304f,-0.0462634f,0.0200692f,0.969396f,0.109432f,
0.106477f,0.310477f,-0.0432721f,0.0176619f,0.965257f,0.129598f, 0.0905032f,0.289019f,-0.040126f,0.0153966f,0.960169f,0.152573f,
0.0757989f,0.26708f,-0.0368733f,0.0132983f,0.953872f,0.178431f, 0.0625691f,0.245338f,-0.0335607f,0.0113867f,0.946083f,0.207098f,
0.0509229f,0.224321f,-0.0302352f,0.00967768f,0.93648f,0.238241f, 0.0414241f,0.206941f,-0.027047f,0.00821499f,0.924866f,0.2712f,
0.0325998f,0.186515f,-0.0238071f,0.006935f,0.911461f,0.304924f, 0.0246874f,0.162999f,-0.0205841f,0.00585498f,0.897613f,0.338079f,
0.018671f,0.141953f,-0.0176858f,0.00505255f,0.887338f,0.369637f, 0.0139959f,0.120581f,-0.0150891f,0.0045077f,0.889922f,0.400258f,
0.0110466f,0.103285f,-0.0129941f,0.00426731f,0.922905f,0.43377f, 0.00786723f,0.0778437f,-0.0106539f,0.0040133f,0.996969f,0.472122f,
1.0f,3.84863e-08f,-1.52293e-18f,0.162718f,0.991797f,3.49105e-06f, 0.999502f,0.0224385f,-0.0036346f,0.162637f,0.991795f,3.55751e-06f,
0.998005f,0.044835f,-0.00726206f,0.162393f,0.991789f,3.75958e-06f, 0.995515f,0.0671476f,-0.0108753f,0.161987f,0.991779f,4.10547e-06f,
0.992035f,0.0893348f,-0.014467f,0.161419f,0.991763f,4.6091e-06f, 0.987568f,0.111354f,-0.0180303f,0.160691f,0.991743f,5.29042e-06f,
0.982122f,0.133165f,-0.021557f,0.159804f,0.991723f,6.18149e-06f, 0.975705f,0.154724f,-0.0250239f,0.158774f,0.991817f,7.40228e-06f,
0.968328f,0.175991f,-0.0284386f,0.157593f,0.991939f,8.89735e-06f, 0.96f,0.196926f,-0.0317991f,0.156259f,0.992051f,1.06912e-05f,
0.950735f,0.217487f,-0.0350993f,0.15477f,0.992138f,1.28399e-05f, 0.940545f,0.237636f,-0.0383317f,0.15313f,0.992195f,1.54047e-05f,
0.929447f,0.257331f,-0.0414883f,0.15134f,0.992217f,1.84405e-05f, 0.917456f,0.276532f,-0.0445608f,0.149404f,0.992199f,2.1981e-05f,
0.90459f,0.2952f,-0.0475409f,0.147324f,0.992131f,2.60196e-05f, 0.890867f,0.313296f,-0.0504218f,0.145105f,0.992017f,3.0631e-05f,
0.876306f,0.330781f,-0.0532125f,0.142755f,0.991945f,3.73089e-05f, 0.860929f,0.347615f,-0.0559012f,0.140275f,0.991888f,4.63347e-05f,
0.844759f,0.363762f,-0.0584789f,0.137668f,0.991831f,5.82402e-05f, 0.827823f,0.379185f,-0.0609385f,0.134941f,0.991768f,7.38179e-05f,
0.810153f,0.393847f,-0.0632734f,0.132098f,0.991694f,9.41174e-05f, 0.79179f,0.407719f,-0.0654773f,0.129144f,0.991603f,0.000120464f,
0.772775f,0.420774f,-0.0675444f,0.126085f,0.991488f,0.000154528f, 0.753143f,0.43298f,-0.069468f,0.122929f,0.991339f,0.000198325f,
0.732931f,0.444309f,-0.0712416f,0.119679f,0.991145f,0.000254292f, 0.712154f,0.45472f,-0.0728662f,0.116341f,0.990945f,0.000327467f,
0.690847f,0.464182f,-0.0743405f,0.112922f,0.990765f,0.000424153f, 0.669058f,0.472673f,-0.0756563f,0.109427f,0.990576f,0.000549925f,
0.646813f,0.480155f,-0.0768066f,0.105864f,0.990362f,0.000712135f, 0.624175f,0.486617f,-0.0777865f,0.102238f,0.99011f,0.000919964f,
0.601153f,0.49201f,-0.0785896f,0.0985575f,0.989803f,0.00118438f, 0.577787f,0.496303f,-0.0792201f,0.0948278f,0.989502f,0.00152417f,
0.554149f,0.499493f,-0.0796727f,0.0910577f,0.989184f,0.00195709f, 0.53028f,0.501553f,-0.0799407f,0.0872544f,0.988822f,0.00250402f,
0.50623f,0.502465f,-0.0800202f,0.0834269f,0.988395f,0.00319036f, 0.482033f,0.502193f,-0.0799141f,0.0795813f,0.987957f,0.004054f,
0.457759f,0.500738f,-0.079617f,0.0757275f,0.987467f,0.00513153f, 0.433456f,0.498077f,-0.0791244f,0.0718734f,0.986901f,0.00646743f,
0.409181f,0.494198f,-0.0784397f,0.0680278f,0.986296f,0.00812244f, 0.384991f,0.489093f,-0.0775567f,0.0642f,0.985594f,0.0101561f,
0.360956f,0.482764f,-0.0764786f,0.060399f,0.984826f,0.0126504f, 0.337559f,0.475805f,-0.0752215f,0.0566494f,0.983943f,0.0156892f,
0.313515f,0.466312f,-0.0737234f,0.0529129f,0.98295f,0.0193789f, 0.290286f,0.456255f,-0.07205f,0.0492488f,0.981819f,0.023836f,
0.267426f,0.444907f,-0.0701763f,0.0456486f,0.980518f,0.0291939f, 0.245069f,0.432391f,-0.0681079f,0.0421253f,0.97902f,0.0356039f,
0.22322f,0.418602f,-0.0658444f,0.0386876f,0.977287f,0.0432351f, 0.201958f,0.403568f,-0.0633858f,0.0353452f,0.975261f,0.0522702f,
0.18148f,0.387559f,-0.0607465f,0.0321147f,0.972891f,0.0629112f, 0.161776f,0.370455f,-0.0579259f,0.0290043f,0.970086f,0.0753639f,
0.142863f,0.352165f,-0.0549216f,0.0260214f,0.96675f,0.0898405f, 0.124991f,0.333154f,-0.0517657f,0.0231889f,0.962759f,0.106543f,
0.108304f,0.313745f,-0.0484705f,0.0205184f,0.957962f,0.125644f, 0.0924536f,0.292829f,-0.0450179f,0.018008f,0.952174f,0.147261f,
0.0788385f,0.274768f,-0.0415949f,0.0157353f,0.945179f,0.171412f, 0.0657384f,0.254026f,-0.0380086f,0.0136262f,0.93676f,0.197967f,
0.0535589f,0.231366f,-0.0343228f,0.0117084f,0.926776f,0.226589f, 0.0439525f,0.213691f,-0.0308642f,0.0100898f,0.915286f,0.25667f,
0.0352385f,0.194013f,-0.0274163f,0.00868943f,0.902912f,0.287345f, 0.0282205f,0.176178f,-0.0242237f,0.00757819f,0.891521f,0.317671f,
0.0222753f,0.156724f,-0.0211887f,0.00671559f,0.885438f,0.347132f, 0.0179774f,0.139198f,-0.018555f,0.006169f,0.893105f,0.376585f,
0.0128439f,0.108f,-0.015712f,0.00570735f,0.927674f,0.408787f, 0.00983493f,0.0863507f,-0.0132599f,0.00544186f,0.997244f,0.444364f,
1.0f,2.81302e-08f,-2.15173e-18f,0.181298f,0.991047f,6.70898e-06f, 0.999502f,0.0224359f,-0.00403413f,0.181206f,0.991037f,6.7876e-06f,
0.99801f,0.0448301f,-0.00805947f,0.180933f,0.991006f,7.02133e-06f, 0.995526f,0.0671404f,-0.0120672f,0.180478f,0.990952f,7.40279e-06f,
0.992055f,0.0893254f,-0.0160483f,0.179842f,0.990872f,7.91609e-06f, 0.987599f,0.111343f,-0.0199937f,0.179025f,0.990762f,8.53111e-06f,
0.982167f,0.133152f,-0.023894f,0.178029f,0.990615f,9.19498e-06f, 0.975767f,0.154711f,-0.02774f,0.176856f,0.990424f,9.8209e-06f,
0.968408f,0.17598f,-0.0315362f,0.175512f,0.99025f,1.07004e-05f, 0.9601f,0.196918f,-0.0352835f,0.174003f,0.990139f,1.22398e-05f,
0.950857f,0.217485f,-0.0389653f,0.172328f,0.990046f,1.43466e-05f, 0.940692f,0.23764f,-0.0425716f,0.170488f,0.989959f,1.70945e-05f,
0.929619f,0.257342f,-0.0460939f,0.168486f,0.989873f,2.06105e-05f, 0.917654f,0.276552f,-0.0495239f,0.166324f,0.989781f,2.50559e-05f,
0.904816f,0.29523f,-0.0528537f,0.164007f,0.98968f,3.06417e-05f, 0.891123f,0.313337f,-0.0560751f,0.161537f,0.989564f,3.76198e-05f,
0.876592f,0.330833f,-0.05918f,0.158918f,0.989428f,4.62961e-05f, 0.861245f,0.347679f,-0.0621605f,0.156155f,0.989264f,5.70215e-05f,
0.845104f,0.363837f,-0.0650081f,0.153252f,0.989063f,7.01901e-05f, 0.828195f,0.379269f,-0.0677174f,0.150219f,0.988862f,8.67563e-05f,
0.810564f,0.393948f,-0.0702907f,0.147073f,0.98876f,0.000109138f, 0.792251f,0.407843f,-0.0727217f,0.143809f,0.988681f,0.000138424f,
0.773287f,0.420923f,-0.0750036f,0.140432f,0.9886f,0.00017638f, 0.753706f,0.433156f,-0.0771295f,0.136946f,0.988498f,0.000225259f,
0.733534f,0.444509f,-0.0790922f,0.133356f,0.988362f,0.000287879f, 0.712806f,0.454951f,-0.0808843f,0.129668f,0.988178f,0.000367621f,
0.69156f,0.464454f,-0.0825071f,0.12589f,0.987981f,0.000470735f, 0.669841f,0.472997f,-0.0839583f,0.122029f,0.987787f,0.000604685f,
0.647638f,0.480514f,-0.0852269f,0.118089f,0.987563f,0.000776427f, 0.625f,0.486983f,-0.086306f,0.114079f,0.987294f,0.000995007f,
0.602014f,0.492408f,-0.0871916f,0.110009f,0.986971f,0.00127193f, 0.578699f,0.49675f,-0.0878866f,0.105885f,0.986643f,0.00162535f,
0.555109f,0.49999f,-0.088383f,0.101715f,0.986276f,0.00207211f, 0.531275f,0.502092f,-0.0886732f,0.0975093f,0.985841f,0.00263219f,
0.507261f,0.503049f,-0.0887601f,0.0932756f,0.985373f,0.00333541f, 0.483109f,0.502835f,-0.0886386f,0.0890229f,0.984854f,0.0042131f,
0.45888f,0.50144f,-0.0883037f,0.084761f,0.984256f,0.00530135f, 0.434618f,0.498842f,-0.0877575f,0.0804988f,0.983608f,0.00664946f,
0.410407f,0.495058f,-0.0869948f,0.0762473f,0.982863f,0.00830678f, 0.386351f,0.490142f,-0.0860198f,0.0720176f,0.982042f,0.0103402f,
0.362228f,0.483727f,-0.0848165f,0.0678103f,0.981104f,0.0128194f, 0.338442f,0.476246f,-0.0833996f,0.0636474f,0.980045f,0.0158304f,
0.314908f,0.467503f,-0.0817639f,0.0595349f,0.97885f,0.0194715f, 0.291709f,0.457528f,-0.0799081f,0.0554829f,0.977487f,0.0238527f,
0.269011f,0.446488f,-0.0778416f,0.0515087f,0.975924f,0.0290983f, 0.246532f,0.433815f,-0.0755461f,0.0476097f,0.974131f,0.0353495f,
0.224835f,0.420352f,-0.0730497f,0.0438142f,0.972064f,0.0427609f, 0.203847f,0.405921f,-0.0703534f,0.0401319f,0.969662f,0.0514978f,
0.184405f,0.392194f,-0.0675305f,0.0366111f,0.966865f,0.0617399f, 0.163798f,0.373308f,-0.0643414f,0.0331315f,0.963586f,0.073668f,
0.14503f,0.355491f,-0.0610524f,0.0298452f,0.959731f,0.0874638f, 0.127618f,0.337822f,-0.0576388f,0.0267423f,0.955178f,0.10329f,
0.110664f,0.317892f,-0.0540097f,0.0237862f,0.94979f,0.121279f, 0.0954293f,0.299027f,-0.0503296f,0.0210553f,0.94342f,0.141505f,
0.081355f,0.279697f,-0.0465496f,0.0185293f,0.935913f,0.163947f, 0.0685084f,0.260021f,-0.0427104f,0.0162256f,0.927156f,0.188449f,
0.0573559f,0.241702f,-0.0389461f,0.0141922f,0.917176f,0.214689f, 0.0485309f,0.227942f,-0.0354412f,0.0124874f,0.906291f,0.242149f,
0.0394342f,0.207342f,-0.0317254f,0.0109384f,0.895462f,0.27016f, 0.0315864f,0.185802f,-0.0281966f,0.00967913f,0.886873f,0.298095f,
0.0258305f,0.167844f,-0.0250198f,0.00875528f,0.884838f,0.325776f, 0.0204298f,0.144741f,-0.0220271f,0.00809551f,0.896711f,0.354053f,
0.0155527f,0.117314f,-0.0190256f,0.00759293f,0.932076f,0.384816f, 0.0121575f,0.0952427f,-0.0162984f,0.00725538f,0.997466f,0.41797f,
1.0f,-9.5814e-08f,-2.08087e-19f,0.200511f,0.987368f,5.50221e-06f, 0.999505f,0.0224348f,-0.00446369f,0.200411f,0.987364f,5.59934e-06f,
0.998017f,0.0448257f,-0.00890025f,0.200125f,0.987444f,6.04501e-06f, 0.99554f,0.0671315f,-0.0133038f,0.199654f,0.987615f,6.79391e-06f,
0.992079f,0.0893128f,-0.0176859f,0.198985f,0.987768f,7.68475e-06f, 0.987637f,0.111329f,-0.0220381f,0.198116f,0.987889f,8.75194e-06f,
0.982221f,0.133137f,-0.0263507f,0.19705f,0.987977f,1.00457e-05f, 0.97584f,0.154697f,-0.0306135f,0.195786f,0.988031f,1.1617e-05f,
0.968503f,0.175967f,-0.0348167f,0.194329f,0.988052f,1.35144e-05f, 0.960219f,0.196907f,-0.0389502f,0.192679f,0.988037f,1.57804e-05f,
0.951001f,0.217476f,-0.0430041f,0.190841f,0.987985f,1.8449e-05f, 0.940867f,0.237634f,-0.0469685f,0.188817f,0.98789f,2.15379e-05f,
0.929828f,0.25734f,-0.0508333f,0.186611f,0.987749f,2.50396e-05f, 0.917897f,0.276555f,-0.0546025f,0.18423f,0.987617f,2.95987e-05f,
0.905097f,0.295242f,-0.0582715f,0.18168f,0.987511f,3.57695e-05f, 0.891441f,0.313359f,-0.0618255f,0.178962f,0.987403f,4.36918e-05f,
0.876953f,0.330869f,-0.0652545f,0.176081f,0.987283f,5.37391e-05f, 0.861653f,0.347732f,-0.0685492f,0.173041f,0.987145f,6.64014e-05f,
0.845557f,0.363908f,-0.0717004f,0.169846f,0.986981f,8.22744e-05f, 0.828694f,0.379361f,-0.0746992f,0.166503f,0.986782f,0.000102084f,
0.811096f,0.394055f,-0.0775376f,0.163019f,0.98654f,0.00012669f, 0.79281f,0.407966f,-0.0802216f,0.159403f,0.986312f,0.000158897f,
0.773883f,0.421066f,-0.0827432f,0.155663f,0.986085f,0.000200729f, 0.754353f,0.43333f,-0.0850923f,0.151806f,0.985839f,0.000254369f,
0.734252f,0.444725f,-0.0872603f,0.147836f,0.985562f,0.000322735f, 0.713632f,0.455236f,-0.0892397f,0.143763f,0.98524f,0.000409339f,
0.692437f,0.464779f,-0.091028f,0.139591f,0.984899f,0.000520227f, 0.670714f,0.473324f,-0.0926223f,0.135325f,0.984554f,0.000662825f,
0.648563f,0.480884f,-0.0940144f,0.130979f,0.984174f,0.000844036f, 0.626016f,0.487428f,-0.0951961f,0.126558f,0.983739f,0.00107273f,
0.6031f,0.492918f,-0.0961687f,0.122072f,0.983283f,0.00136286f, 0.579838f,0.497315f,-0.0969262f,0.117529f,0.982795f,0.00172928f,
0.556302f,0.500614f,-0.0974604f,0.112937f,0.982242f,0.00218801f, 0.532533f,0.502788f,-0.0977736f,0.108308f,0.981654f,0.00276317f,
0.508581f,0.503821f,-0.0978595f,0.103649f,0.981008f,0.00347992f, 0.484493f,0.50369f,-0.097714f,0.0989718f,0.98029f,0.00436871f,
0.460347f,0.502405f,-0.0973383f,0.0942907f,0.979541f,0.00546842f, 0.436264f,0.500032f,-0.0967316f,0.0896193f,0.978738f,0.00682114f,
0.411937f,0.496141f,-0.0958771f,0.08495f,0.977856f,0.00847888f, 0.387871f,0.491237f,-0.094793f,0.0803094f,0.976882f,0.0105029f,
0.363856f,0.48499f,-0.0934645f,0.0756979f,0.975783f,0.0129607f, 0.340155f,0.477659f,-0.0919029f,0.0711353f,0.974545f,0.0159337f,
0.316765f,0.469165f,-0.0901052f,0.0666306f,0.973142f,0.0195127f, 0.293597f,0.459289f,-0.0880652f,0.0621904f,0.971547f,0.0238014f,
0.27081f,0.448158f,-0.0857855f,0.0578277f,0.969729f,0.0289163f, 0.248671f,0.436123f,-0.083285f,0.0535668f,0.967642f,0.0349843f,
0.227042f,0.422869f,-0.0805562f,0.049412f,0.965248f,0.0421472f, 0.206055f,0.408528f,-0.0775992f,0.0453738f,0.962482f,0.0505535f,
0.185911f,0.393406f,-0.0744418f,0.0414778f,0.959286f,0.0603614f, 0.166183f,0.37649f,-0.0710489f,0.0377136f,0.955573f,0.0717265f,
0.148235f,0.360741f,-0.0675505f,0.0341575f,0.951257f,0.0848013f, 0.130429f,0.342284f,-0.0638083f,0.0307443f,0.946231f,0.0997166f,
0.114155f,0.324406f,-0.0599742f,0.0275545f,0.94039f,0.116571f, 0.098955f,0.305917f,-0.0560136f,0.0245737f,0.933627f,0.135403f,
0.084757f,0.286454f,-0.0519398f,0.0218105f,0.925867f,0.15617f, 0.0738295f,0.273785f,-0.0482055f,0.0194489f,0.917121f,0.178717f,
0.063094f,0.257841f,-0.0443057f,0.017274f,0.907571f,0.202752f, 0.0514396f,0.232786f,-0.0400209f,0.0152059f,0.897767f,0.227857f,
0.0434679f,0.217447f,-0.0363681f,0.0136275f,0.888911f,0.253549f, 0.036088f,0.198847f,-0.032762f,0.0123058f,0.883322f,0.279435f,
0.0287296f,0.173233f,-0.0290984f,0.0111895f,0.885085f,0.305543f, 0.0243217f,0.15545f,-0.0262231f,0.01059f,0.900394f,0.33262f,
0.0186934f,0.127001f,-0.0228218f,0.00994954f,0.93638f,0.361924f, 0.014887f,0.104537f,-0.0198018f,0.0095252f,0.997646f,0.39294f,
1.0f,1.09272e-07f,-8.88235e-19f,0.220973f,0.985766f,9.01426e-06f, 0.999506f,0.0224283f,-0.0048811f,0.220861f,0.985747f,9.0919e-06f,
0.998023f,0.0448145f,-0.00975087f,0.220528f,0.985691f,9.31917e-06f, 0.995556f,0.0671178f,-0.0145979f,0.219973f,0.985595f,9.67816e-06f,
0.992108f,0.0892961f,-0.019411f,0.219198f,0.985457f,1.01359e-05f, 0.987681f,0.111308f,-0.0241791f,0.218204f,0.985275f,1.06462e-05f,
0.982282f,0.133116f,-0.028918f,0.217004f,0.985154f,1.16639e-05f, 0.975923f,0.154677f,-0.0336091f,0.215598f,0.985062f,1.31974e-05f,
0.968612f,0.175949f,-0.0382361f,0.213982f,0.984972f,1.52328e-05f, 0.960356f,0.196893f,-0.042787f,0.21216f,0.984875f,1.78243e-05f,
0.951171f,0.217467f,-0.047251f,0.210134f,0.984763f,2.10484e-05f, 0.941065f,0.23763f,-0.0516175f,0.207906f,0.984631f,2.49996e-05f,
0.930061f,0.257344f,-0.0558715f,0.205486f,0.984501f,2.97912e-05f, 0.918171f,0.276566f,-0.059998f,0.202885f,0.984401f,3.5543e-05f,
0.905412f,0.295258f,-0.0639955f,0.200098f,0.98428f,4.23523e-05f, 0.891803f,0.313384f,-0.0678683f,0.197129f,0.984168f,5.10193e-05f,
0.877363f,0.330905f,-0.0716127f,0.193985f,0.984074f,6.23499e-05f, 0.862109f,0.347781f,-0.0752133f,0.190667f,0.983969f,7.67064e-05f,
0.846067f,0.363974f,-0.0786596f,0.18718f,0.983837f,9.47344e-05f, 0.829259f,0.379447f,-0.0819414f,0.18353f,0.983671f,0.000117262f,
0.811718f,0.394165f,-0.0850492f,0.179724f,0.983461f,0.000145277f, 0.793488f,0.408099f,-0.0879824f,0.175772f,0.983229f,0.000180869f,
0.774633f,0.421234f,-0.0907404f,0.171686f,0.983f,0.000226882f, 0.755214f,0.433556f,-0.0933107f,0.167472f,0.982742f,0.000285378f,
0.735171f,0.444985f,-0.0956812f,0.163133f,0.982443f,0.000359261f, 0.714516f,0.455477f,-0.0978431f,0.158676f,0.982094f,0.000452346f,
0.693359f,0.465043f,-0.0998019f,0.154112f,0.981741f,0.000571614f, 0.67173f,0.473651f,-0.101545f,0.14945f,0.981354f,0.000722695f,
0.649666f,0.481275f,-0.103064f,0.144698f,0.98091f,0.000912669f, 0.627159f,0.487852f,-0.104357f,0.139865f,0.980433f,0.00115256f,
0.604305f,0.493396f,-0.105421f,0.13496f,0.979919f,0.00145464f, 0.581125f,0.497865f,-0.106245f,0.129994f,0.979337f,0.00183182f,
0.557668f,0.50124f,-0.106831f,0.124976f,0.978718f,0.00230424f, 0.533988f,0.503507f,-0.107171f,0.119917f,0.978026f,0.00289103f,
0.510159f,0.504672f,-0.107266f,0.114829f,0.977275f,0.00361923f, 0.486291f,0.504784f,-0.107112f,0.109725f,0.976438f,0.00451761f,
0.462165f,0.503547f,-0.106699f,0.104605f,0.975526f,0.00562369f, 0.437885f,0.500978f,-0.10602f,0.0994796f,0.974509f,0.00697768f,
0.413755f,0.497339f,-0.105089f,0.0943743f,0.973385f,0.00862974f, 0.389718f,0.492501f,-0.103896f,0.0892932f,0.972139f,0.0106371f,
0.365971f,0.486639f,-0.102453f,0.0842583f,0.970749f,0.0130648f, 0.342284f,0.479372f,-0.100744f,0.07927f,0.969195f,0.0159881f,
0.31885f,0.470863f,-0.0987727f,0.0743429f,0.967454f,0.0194923f, 0.295968f,0.461474f,-0.0965559f,0.0695012f,0.965497f,0.0236733f,
0.273577f,0.45106f,-0.0940953f,0.0647568f,0.963292f,0.0286379f, 0.251368f,0.439007f,-0.0913585f,0.0600987f,0.960795f,0.0345021f,
0.229786f,0.425935f,-0.0883846f,0.0555645f,0.957962f,0.0413925f, 0.20976f,0.413575f,-0.0852628f,0.0512174f,0.954739f,0.0494419f,
0.188971f,0.397324f,-0.0817832f,0.0469395f,0.951063f,0.0587872f, 0.171054f,0.384556f,-0.0783046f,0.0429466f,0.946863f,0.0695631f,
0.151655f,0.365744f,-0.0743782f,0.0389957f,0.94206f,0.081894f, 0.13462f,0.349423f,-0.0704471f,0.0353331f,0.936576f,0.0958856f,
0.119674f,0.335455f,-0.0665342f,0.0319636f,0.930336f,0.111607f, 0.103563f,0.314845f,-0.0621732f,0.0286659f,0.92329f,0.129076f,
0.089991f,0.29771f,-0.0579952f,0.0257398f,0.915445f,0.14824f, 0.0797531f,0.287736f,-0.0541544f,0.0232374f,0.906921f,0.168953f,
0.0683594f,0.269908f,-0.0499216f,0.0208388f,0.898046f,0.190975f, 0.0564695f,0.244687f,-0.0454305f,0.0186092f,0.889655f,0.213982f,
0.0485272f,0.2301f,-0.0416545f,0.0169376f,0.883075f,0.237637f, 0.0415244f,0.213548f,-0.0379809f,0.0155623f,0.880582f,0.26174f,
0.0335946f,0.186621f,-0.0340258f,0.0143138f,0.885828f,0.286405f, 0.0286148f,0.167747f,-0.0308519f,0.0136179f,0.903917f,0.312258f,
0.0234666f,0.143221f,-0.0274534f,0.0130106f,0.940079f,0.340099f, 0.0191056f,0.119637f,-0.0240797f,0.0124748f,0.99779f,0.36926f,
1.0f,-2.90336e-08f,-5.11644e-18f,0.242098f,0.982009f,9.25071e-06f, 0.999508f,0.0224255f,-0.00535085f,0.241977f,0.981997f,9.37778e-06f,
0.99803f,0.0448091f,-0.01069f,0.241615f,0.981959f,9.76e-06f, 0.995573f,0.0671102f,-0.0160058f,0.241013f,0.981896f,1.04001e-05f,
0.992137f,0.0892847f,-0.021272f,0.240183f,0.981866f,1.13753e-05f, 0.987729f,0.111292f,-0.0264773f,0.23913f,0.981878f,1.26663e-05f,
0.982354f,0.133093f,-0.0316258f,0.237842f,0.981865f,1.41855e-05f, 0.97602f,0.154646f,-0.0367084f,0.23632f,0.98181f,1.59158e-05f,
0.968735f,0.175912f,-0.0417176f,0.234567f,0.981718f,1.79244e-05f, 0.960514f,0.196853f,-0.0466626f,0.232594f,0.98166f,2.07534e-05f,
0.951367f,0.217427f,-0.0515218f,0.2304f,0.981599f,2.43898e-05f, 0.941303f,0.237593f,-0.0562803f,0.227986f,0.981519f,2.89209e-05f,
0.930345f,0.257313f,-0.0609255f,0.225356f,0.981412f,3.4487e-05f, 0.918499f,0.276544f,-0.0654451f,0.222513f,0.981271f,4.12535e-05f,
0.90579f,0.29525f,-0.0698278f,0.219464f,0.98109f,4.9412e-05f, 0.892233f,0.313389f,-0.0740629f,0.216213f,0.980868f,5.92385e-05f,
0.877846f,0.330926f,-0.0781564f,0.21277f,0.980659f,7.19873e-05f, 0.862649f,0.34782f,-0.0820921f,0.209137f,0.980441f,8.81323e-05f,
0.846666f,0.364035f,-0.0858568f,0.205322f,0.980197f,0.000108315f, 0.829921f,0.379532f,-0.0894392f,0.20133f,0.979917f,0.000133398f,
0.812458f,0.394282f,-0.0928293f,0.197171f,0.979591f,0.000164425f, 0.79435f,0.408273f,-0.0960335f,0.192859f,0.979264f,0.00020413f,
0.775596f,0.42146f,-0.0990404f,0.188401f,0.978919f,0.000254486f, 0.756175f,0.433782f,-0.101835f,0.183799f,0.978535f,0.00031774f,
0.736241f,0.445273f,-0.10441f,0.179069f,0.978108f,0.000396858f, 0.715638f,0.455797f,-0.10676f,0.17422f,0.977717f,0.000497486f,
0.694583f,0.465429f,-0.108883f,0.169262f,0.977313f,0.000624284f, 0.673016f,0.474081f,-0.110765f,0.164199f,0.97686f,0.000782864f,
0.65102f,0.481755f,-0.112411f,0.159041f,0.976386f,0.000982777f, 0.62862f,0.488415f,-0.11381f,0.153796f,0.975864f,0.00123299f,
0.605867f,0.494044f,-0.114957f,0.148475f,0.975282f,0.00154492f, 0.583474f,0.499187f,-0.115876f,0.14312f,0.974653f,0.00193425f,
0.559504f,0.502142f,-0.116482f,0.137647f,0.973949f,0.00241672f, 0.536087f,0.504672f,-0.116857f,0.132168f,0.973182f,0.00301457f,
0.512189f,0.505794f,-0.116947f,0.126639f,0.972328f,0.00375106f, 0.488163f,0.505764f,-0.116766f,0.12109f,0.971385f,0.00465605f,
0.46414f,0.504652f,-0.116311f,0.115532f,0.970347f,0.00576411f, 0.440025f,0.502287f,-0.115574f,0.109974f,0.969193f,0.00711458f,
0.41615f,0.498979f,-0.114571f,0.104444f,0.967912f,0.00875426f, 0.392515f,0.494684f,-0.113298f,0.0989525f,0.966488f,0.010737f,
0.36863f,0.4887f,-0.111722f,0.0934821f,0.964904f,0.0131245f, 0.344975f,0.481534f,-0.109866f,0.0880681f,0.963136f,0.0159869f,
0.321905f,0.473613f,-0.107753f,0.082742f,0.961159f,0.0194027f, 0.29945f,0.464966f,-0.105383f,0.0775123f,0.958943f,0.0234601f,
0.27641f,0.453607f,-0.10267f,0.0723301f,0.956458f,0.0282566f, 0.25486f,0.442748f,-0.099767f,0.0673162f,0.953662f,0.0338971f,
0.233507f,0.430212f,-0.0965921f,0.0624224f,0.950507f,0.0404933f, 0.212918f,0.416884f,-0.0931693f,0.0576745f,0.946951f,0.0481635f,
0.196416f,0.409553f,-0.0899149f,0.0533293f,0.942932f,0.057025f, 0.17433f,0.388209f,-0.0857103f,0.0487291f,0.938396f,0.0671927f,
0.156279f,0.372621f,-0.0816821f,0.0445481f,0.933286f,0.0787703f, 0.140127f,0.358701f,-0.0776336f,0.040663f,0.927547f,0.0918397f,
0.123454f,0.340401f,-0.0732168f,0.0368933f,0.921151f,0.106452f, 0.110124f,0.32782f,-0.0690872f,0.0335726f,0.9141f,0.122612f,
0.0954776f,0.307952f,-0.0644666f,0.0303154f,0.906484f,0.140265f, 0.0828781f,0.29017f,-0.0599972f,0.0274319f,0.898521f,0.159288f,
0.0718156f,0.273126f,-0.0556376f,0.0248925f,0.890663f,0.179493f, 0.0645439f,0.265847f,-0.0519265f,0.0229267f,0.883729f,0.200645f,
0.0528156f,0.236244f,-0.0471138f,0.0207544f,0.879109f,0.222528f, 0.0453972f,0.218496f,-0.0431826f,0.019242f,0.878995f,0.245038f,
0.0390302f,0.199679f,-0.0395312f,0.018116f,0.886824f,0.268339f, 0.0326022f,0.175095f,-0.0358295f,0.0172052f,0.907131f,0.292948f,
0.0276041f,0.152856f,-0.0322721f,0.016555f,0.943237f,0.319388f, 0.0229051f,0.129617f,-0.0286112f,0.0159172f,0.997905f,0.346904f,
0.999998f,1.83176e-07f,-1.2125e-19f,0.264106f,0.977872f,1.03025e-05f, 0.99951f,0.0224101f,-0.00576242f,0.263993f,0.977954f,1.05668e-05f,
0.998041f,0.0447826f,-0.0115381f,0.263632f,0.978077f,1.11908e-05f, 0.995595f,0.0670733f,-0.0172953f,0.263008f,0.978161f,1.20489e-05f,
0.992177f,0.0892415f,-0.0230205f,0.262123f,0.978203f,1.31773e-05f, 0.987788f,0.111246f,-0.0287004f,0.260977f,0.978202f,1.46127e-05f,
0.982436f,0.133044f,-0.0343216f,0.259574f,0.978158f,1.63886e-05f, 0.976133f,0.154597f,-0.0398711f,0.257916f,0.978069f,1.85331e-05f,
0.968884f,0.175864f,-0.0453355f,0.256006f,0.977932f,2.10673e-05f, 0.960701f,0.196804f,-0.0507052f,0.253848f,0.977755f,2.40734e-05f,
0.951592f,0.21738f,-0.0559876f,0.251453f,0.977602f,2.81163e-05f, 0.941578f,0.237551f,-0.0611614f,0.248822f,0.97744f,3.3226e-05f,
0.930665f,0.257276f,-0.0662104f,0.245957f,0.977256f,3.95301e-05f, 0.918875f,0.276516f,-0.071121f,0.242865f,0.977041f,4.72086e-05f,
0.906221f,0.29523f,-0.0758697f,0.239562f,0.976843f,5.64956e-05f, 0.892726f,0.31338f,-0.0804554f,0.236048f,0.976636f,6.77817e-05f,
0.878405f,0.330929f,-0.0848851f,0.232329f,0.976448f,8.22356e-05f, 0.863279f,0.347841f,-0.0891415f,0.228406f,0.976246f,0.000100295f,
0.847381f,0.364079f,-0.0932119f,0.224286f,0.97601f,0.000122633f, 0.830748f,0.379613f,-0.0970844f,0.219977f,0.975728f,0.000150116f,
0.813462f,0.394435f,-0.100761f,0.215491f,0.975426f,0.000184695f, 0.795443f,0.408464f,-0.104232f,0.210835f,0.975106f,0.000228352f,
0.776684f,0.421644f,-0.10748f,0.206011f,0.974742f,0.000282774f, 0.757328f,0.433996f,-0.110499f,0.201035f,0.974328f,0.000350524f,
0.737441f,0.445512f,-0.113292f,0.195918f,0.973895f,0.000436147f, 0.717021f,0.456143f,-0.115842f,0.190668f,0.973414f,0.00054317f,
0.696006f,0.465802f,-0.11814f,0.185291f,0.972877f,0.000676575f, 0.674571f,0.474546f,-0.120188f,0.179802f,0.972308f,0.000844022f,
0.65272f,0.482329f,-0.121972f,0.174212f,0.971673f,0.00105211f, 0.630497f,0.489132f,-0.123493f,0.16853f,0.970993f,0.00131173f,
0.607945f,0.494935f,-0.124741f,0.16277f,0.970242f,0.00163353f, 0.585046f,0.499669f,-0.125708f,0.156934f,0.96943f,0.00203239f,
0.561674f,0.503154f,-0.126384f,0.151034f,0.968538f,0.00252425f, 0.538055f,0.505512f,-0.126773f,0.145087f,0.96757f,0.00313011f,
0.514456f,0.506935f,-0.126875f,0.139113f,0.966508f,0.00387278f, 0.490572f,0.50707f,-0.126676f,0.133111f,0.965345f,0.00478048f,
0.466779f,0.506231f,-0.126187f,0.127109f,0.964072f,0.00588595f, 0.443136f,0.504438f,-0.12541f,0.121125f,0.962675f,0.00722732f,
0.419176f,0.501086f,-0.12432f,0.115147f,0.961138f,0.00884807f, 0.395318f,0.49656f,-0.122925f,0.1092f,0.959443f,0.0107986f,
0.372057f,0.491436f,-0.121257f,0.103324f,0.957573f,0.0131366f, 0.348746f,0.484821f,-0.119271f,0.0974988f,0.955541f,0.0159271f,
0.32559f,0.476867f,-0.116987f,0.0917531f,0.953302f,0.0192419f, 0.302716f,0.467656f,-0.114405f,0.0860959f,0.950824f,0.0231619f,
0.281288f,0.458964f,-0.11163f,0.0806168f,0.948067f,0.0277741f, 0.259526f,0.447917f,-0.108525f,0.0752226f,0.944996f,0.0331738f,
0.238441f,0.43603f,-0.105139f,0.0699625f,0.941567f,0.0394596f, 0.217704f,0.422599f,-0.101487f,0.0648558f,0.937741f,0.0467347f,
0.198638f,0.410113f,-0.0977105f,0.0599994f,0.933469f,0.0551003f, 0.181751f,0.399841f,-0.0938868f,0.0554383f,0.92871f,0.0646532f,
0.162773f,0.382677f,-0.0895412f,0.0508976f,0.92343f,0.075479f, 0.147816f,0.372005f,-0.0854643f,0.0468365f,0.917611f,0.0876433f,
0.130228f,0.351883f,-0.0807144f,0.042734f,0.911265f,0.101185f, 0.116957f,0.339729f,-0.0763646f,0.0391701f,0.904455f,0.116101f,
0.102104f,0.319755f,-0.0715299f,0.0356793f,0.897343f,0.132348f, 0.0923803f,0.311498f,-0.0674637f,0.032886f,0.89023f,0.149825f,
0.0801139f,0.291377f,-0.062704f,0.0300633f,0.883652f,0.168396f, 0.06943f,0.271888f,-0.0580898f,0.0276188f,0.878488f,0.187898f,
0.0602112f,0.252852f,-0.0537494f,0.0256032f,0.876114f,0.208201f, 0.0520617f,0.232907f,-0.049522f,0.0239299f,0.878568f,0.22929f,
0.0450541f,0.212224f,-0.0456324f,0.0226958f,0.888608f,0.25133f, 0.0386803f,0.189544f,-0.0417043f,0.0216971f,0.909962f,0.274688f,
0.0329309f,0.165514f,-0.0378053f,0.020916f,0.945868f,0.299771f, 0.0274514f,0.140811f,-0.03377f,0.0201236f,0.997993f,0.32584f,
1.0f,2.41778e-07f,-8.0184e-19f,0.287095f,0.973936f,1.28874e-05f, 0.999515f,0.0223982f,-0.00623346f,0.286952f,0.973906f,1.29553e-05f,
0.998053f,0.0447554f,-0.0124543f,0.286525f,0.973824f,1.31705e-05f, 0.995619f,0.0670365f,-0.0186833f,0.285832f,0.973804f,1.38992e-05f,
0.99222f,0.0891966f,-0.0248838f,0.284865f,0.973777f,1.50519e-05f, 0.987852f,0.111193f,-0.0310351f,0.283619f,0.973721f,1.66102e-05f,
0.982533f,0.132986f,-0.0371221f,0.282096f,0.973627f,1.85976e-05f, 0.976263f,0.154535f,-0.0431301f,0.280298f,0.973491f,2.10448e-05f,
0.969053f,0.175798f,-0.0490448f,0.278228f,0.97331f,2.3983e-05f, 0.960913f,0.196734f,-0.0548413f,0.275903f,0.973137f,2.75145e-05f,
0.951855f,0.217305f,-0.0605326f,0.273333f,0.973019f,3.2162e-05f, 0.941896f,0.237475f,-0.0661041f,0.270511f,0.972899f,3.79679e-05f,
0.931041f,0.2572f,-0.0715406f,0.267438f,0.972753f,4.50608e-05f, 0.919313f,0.276443f,-0.0768283f,0.264119f,0.97257f,5.36333e-05f,
0.906731f,0.295165f,-0.0819541f,0.260558f,0.972339f,6.39182e-05f, 0.893307f,0.313329f,-0.0869215f,0.256766f,0.972104f,7.69058e-05f,
0.879068f,0.330898f,-0.091714f,0.252746f,0.971848f,9.30809e-05f, 0.864041f,0.347837f,-0.0963147f,0.248506f,0.971552f,0.000112965f,
0.848281f,0.36412f,-0.100711f,0.244055f,0.971205f,0.000137255f, 0.831874f,0.379741f,-0.104906f,0.239406f,0.970843f,0.000167748f,
0.814509f,0.394525f,-0.10888f,0.234557f,0.97045f,0.000205792f, 0.796639f,0.408616f,-0.112624f,0.229528f,0.970007f,0.000252803f,
0.777983f,0.421843f,-0.116128f,0.224319f,0.969526f,0.000311301f, 0.758841f,0.434305f,-0.119394f,0.218954f,0.969014f,0.000384533f,
0.739033f,0.445866f,-0.1224f,0.213432f,0.968446f,0.00047524f, 0.718747f,0.456581f,-0.125148f,0.207775f,0.967856f,0.000588466f,
0.697973f,0.466396f,-0.127624f,0.201997f,0.967251f,0.000729174f, 0.676569f,0.475168f,-0.129815f,0.196089f,0.966602f,0.000903643f,
0.654812f,0.483024f,-0.131729f,0.19008f,0.965909f,0.00112022f, 0.632762f,0.489964f,-0.133359f,0.18398f,0.96515f,0.00138777f,
0.610633f,0.496118f,-0.134711f,0.177812f,0.964329f,0.00171819f, 0.587667f,0.500817f,-0.135745f,0.171544f,0.963434f,0.00212501f,
0.564169f,0.504207f,-0.136459f,0.165194f,0.962451f,0.00262411f, 0.540739f,0.50675f,-0.136877f,0.158813f,0.96138f,0.00323524f,
0.517335f,0.50838f,-0.136991f,0.152404f,0.960208f,0.00398089f, 0.493982f,0.509086f,-0.136804f,0.145989f,0.958923f,0.00488741f,
0.470765f,0.508917f,-0.136317f,0.139584f,0.957512f,0.00598579f, 0.446927f,0.506971f,-0.135479f,0.133152f,0.955964f,0.00731191f,
0.422781f,0.503456f,-0.134284f,0.126706f,0.954265f,0.00890691f, 0.399418f,0.499598f,-0.132825f,0.120352f,0.952392f,0.0108174f,
0.376516f,0.495024f,-0.131063f,0.114064f,0.95033f,0.0130966f, 0.353258f,0.488574f,-0.128959f,0.10782f,0.948061f,0.0158047f,
0.330348f,0.481074f,-0.126547f,0.101667f,0.945553f,0.0190071f, 0.308709f,0.47387f,-0.123924f,0.0956889f,0.942785f,0.0227769f,
0.286367f,0.463904f,-0.120877f,0.089734f,0.939726f,0.027193f, 0.265057f,0.453757f,-0.117607f,0.0839665f,0.936345f,0.032339f,
0.243999f,0.442074f,-0.114054f,0.0783508f,0.932611f,0.0383029f, 0.224098f,0.430394f,-0.110268f,0.0729289f,0.928491f,0.0451741f,
0.206062f,0.420204f,-0.106445f,0.067833f,0.923956f,0.0530398f, 0.187046f,0.40573f,-0.102157f,0.0627911f,0.918983f,0.0619825f,
0.171238f,0.395735f,-0.0980293f,0.0581975f,0.913561f,0.0720721f, 0.154797f,0.381881f,-0.0935478f,0.0537386f,0.907707f,0.083364f,
0.137378f,0.362558f,-0.0885975f,0.0493636f,0.901474f,0.0958868f, 0.123746f,0.34959f,-0.0840267f,0.0455479f,0.894976f,0.10964f,
0.109442f,0.331446f,-0.0791283f,0.0418948f,0.888436f,0.124589f, 0.0993973f,0.322206f,-0.0748071f,0.0388804f,0.882211f,0.140661f,
0.0901558f,0.312293f,-0.0705636f,0.0362325f,0.87694f,0.15776f, 0.078459f,0.290301f,-0.0656441f,0.0335639f,0.873625f,0.175786f,
0.0682846f,0.268765f,-0.0609563f,0.0313298f,0.873491f,0.19468f, 0.0592881f,0.246465f,-0.0563959f,0.0294655f,0.878338f,0.214466f,
0.0547363f,0.236499f,-0.0530184f,0.0285217f,0.890479f,0.235301f, 0.0475638f,0.21203f,-0.0493116f,0.0276954f,0.912484f,0.257461f,
0.0384314f,0.176073f,-0.0438175f,0.0260634f,0.948031f,0.281256f, 0.0338753f,0.156937f,-0.0397422f,0.0253112f,0.99806f,0.306025f,
0.999997f,1.80511e-07f,-5.45908e-18f,0.310813f,0.96892f,1.46664e-05f, 0.999514f,0.0223835f,-0.00671968f,0.310659f,0.96889f,1.47723e-05f,
0.998062f,0.0447264f,-0.0134233f,0.310199f,0.968801f,1.50841e-05f, 0.995647f,0.0669917f,-0.0201198f,0.309445f,0.968722f,1.58154e-05f,
0.992268f,0.0891389f,-0.0267939f,0.308399f,0.968659f,1.70819e-05f, 0.987931f,0.111124f,-0.0334152f,0.307055f,0.968566f,1.88097e-05f,
0.982648f,0.132906f,-0.0399658f,0.305414f,0.968435f,2.10178e-05f, 0.976413f,0.154441f,-0.0464103f,0.303492f,0.968322f,2.3784e-05f,
0.969249f,0.175691f,-0.0527474f,0.301287f,0.968188f,2.70959e-05f, 0.961163f,0.19662f,-0.0589839f,0.298803f,0.96805f,3.12541e-05f,
0.952161f,0.217189f,-0.0651113f,0.296042f,0.967911f,3.65408e-05f, 0.942263f,0.237358f,-0.0711076f,0.293007f,0.96774f,4.30086e-05f,
0.931475f,0.257085f,-0.0769557f,0.289699f,0.967526f,5.08111e-05f, 0.91982f,0.276332f,-0.0826415f,0.286126f,0.967262f,6.01654e-05f,
0.907318f,0.295066f,-0.0881684f,0.282298f,0.966991f,7.19257e-05f, 0.893987f,0.313247f,-0.0935158f,0.27822f,0.96669f,8.64302e-05f,
0.87987f,0.330843f,-0.098667f,0.273899f,0.966344f,0.000104112f, 0.865014f,0.34783f,-0.10361f,0.269344f,0.965952f,0.000125689f,
0.8494f,0.36416f,-0.108348f,0.26457f,0.965545f,0.000152676f, 0.832984f,0.379765f,-0.112847f,0.259587f,0.965135f,0.000185916f,
0.815866f,0.394638f,-0.117103f,0.254402f,0.964695f,0.00022669f, 0.798157f,0.408789f,-0.12112f,0.24903f,0.964242f,0.000277568f,
0.779888f,0.422194f,-0.124884f,0.243478f,0.963743f,0.000340353f, 0.7606f,0.434583f,-0.128366f,0.237718f,0.963197f,0.000417948f,
0.740803f,0.446145f,-0.13158f,0.231799f,0.96261f,0.000514269f, 0.720663f,0.456938f,-0.134521f,0.225745f,0.961961f,0.000633024f,
0.700078f,0.466871f,-0.137181f,0.219556f,0.961265f,0.000780197f, 0.678907f,0.475802f,-0.139539f,0.213232f,0.960497f,0.000961423f,
0.657661f,0.484033f,-0.141613f,0.206814f,0.95967f,0.00118509f, 0.635623f,0.491005f,-0.14337f,0.20028f,0.958765f,0.00145988f,
0.613036f,0.496807f,-0.144799f,0.193637f,0.957781f,0.00179708f, 0.590546f,0.501908f,-0.145922f,0.186934f,0.956716f,0.00221017f,
0.567506f,0.505717f,-0.146709f,0.180155f,0.955554f,0.00271425f, 0.544627f,0.508807f,-0.147184f,0.173347f,0.954289f,0.00332789f,
0.521845f,0.511101f,-0.147348f,0.166528f,0.952914f,0.00407273f, 0.49814f,0.511516f,-0.147137f,0.159643f,0.951417f,0.00497387f,
0.474274f,0.510697f,-0.146569f,0.152734f,0.949785f,0.0060603f, 0.450865f,0.50926f,-0.145681f,0.145857f,0.948007f,0.00736573f,
0.427709f,0.506962f,-0.144488f,0.139041f,0.946067f,0.00892832f, 0.406416f,0.505784f,-0.143113f,0.132409f,0.943947f,0.0107912f,
0.381309f,0.498509f,-0.141084f,0.125546f,0.94165f,0.0130035f, 0.359061f,0.493513f,-0.138932f,0.118953f,0.939161f,0.0156197f,
0.336908f,0.487243f,-0.136436f,0.112436f,0.936446f,0.0187f, 0.31657f,0.482179f,-0.133821f,0.10619f,0.933476f,0.0223095f,
0.293087f,0.470657f,-0.130477f,0.0997398f,0.930225f,0.0265189f, 0.271826f,0.460753f,-0.12709f,0.0936387f,0.926668f,0.0314029f,
0.251405f,0.450371f,-0.123394f,0.0876858f,0.922782f,0.0370383f, 0.236955f,0.449037f,-0.120212f,0.082457f,0.918543f,0.0435029f,
0.212767f,0.42748f,-0.115341f,0.0764446f,0.91394f,0.050872f, 0.195012f,0.41577f,-0.111058f,0.071212f,0.908968f,0.0592157f,
0.178116f,0.403542f,-0.106624f,0.0662522f,0.903644f,0.068594f, 0.162731f,0.392213f,-0.102091f,0.0615976f,0.898016f,0.0790526f,
0.149812f,0.384318f,-0.0978165f,0.0574561f,0.892174f,0.0906174f, 0.131856f,0.360838f,-0.092315f,0.0529604f,0.886278f,0.103291f,
0.120145f,0.350164f,-0.0877399f,0.0493606f,0.880597f,0.117052f, 0.106057f,0.329357f,-0.0825139f,0.0457493f,0.875533f,0.131853f,
0.096923f,0.317786f,-0.077976f,0.0428692f,0.871693f,0.147637f, 0.0863562f,0.30174f,-0.0733391f,0.0402765f,0.869949f,0.164346f,
0.0768855f,0.283256f,-0.0686342f,0.0379826f,0.871519f,0.181962f, 0.0670552f,0.25897f,-0.0637841f,0.035934f,0.878129f,0.200534f,
0.0616833f,0.246235f,-0.0600742f,0.0348465f,0.892098f,0.220226f, 0.0536074f,0.220031f,-0.0553299f,0.0334457f,0.91503f,0.241247f,
0.0462778f,0.19315f,-0.05071f,0.0323412f,0.949764f,0.263822f, 0.0398218f,0.168255f,-0.0460416f,0.0312795f,0.998107f,0.287416f,
1.0f,-1.26989e-07f,-5.38451e-18f,0.335273f,0.963091f,1.63917e-05f, 0.999519f,0.0223617f,-0.00719591f,0.335108f,0.963059f,1.65121e-05f,
0.998077f,0.0446836f,-0.0143788f,0.334616f,0.962973f,1.68986e-05f, 0.995679f,0.0669318f,-0.0215657f,0.333818f,0.962926f,1.78571e-05f,
0.992322f,0.0890595f,-0.0287147f,0.332699f,0.962853f,1.92947e-05f, 0.98802f,0.111027f,-0.0358039f,0.33126f,0.962735f,2.12039e-05f,
0.982774f,0.13279f,-0.042801f,0.329512f,0.962609f,2.36449e-05f, 0.976586f,0.154307f,-0.0496905f,0.327458f,0.962472f,2.66302e-05f,
0.969474f,0.175545f,-0.0564862f,0.325104f,0.962332f,3.04162e-05f, 0.961445f,0.196467f,-0.0631774f,0.322449f,0.962183f,3.52149e-05f,
0.95251f,0.217028f,-0.06974f,0.319494f,0.961996f,4.10647e-05f, 0.942683f,0.237192f,-0.0761559f,0.316243f,0.96176f,4.80897e-05f,
0.931977f,0.256918f,-0.0824158f,0.312703f,0.961484f,5.66137e-05f, 0.920418f,0.276174f,-0.0885169f,0.308884f,0.961194f,6.72618e-05f,
0.908029f,0.294922f,-0.0944351f,0.304791f,0.960862f,8.02322e-05f, 0.894849f,0.31313f,-0.100152f,0.300431f,0.960477f,9.58812e-05f,
0.880942f,0.330777f,-0.105659f,0.295831f,0.96011f,0.000115266f, 0.866282f,0.347816f,-0.110948f,0.290998f,0.959728f,0.000139099f,
0.85081f,0.364178f,-0.115999f,0.285924f,0.959301f,0.000168089f, 0.834346f,0.379749f,-0.120801f,0.280592f,0.958848f,0.00020396f,
0.817355f,0.39466f,-0.125355f,0.275052f,0.958352f,0.000248061f, 0.799857f,0.408887f,-0.12965f,0.269318f,0.957801f,0.000302108f,
0.781354f,0.422168f,-0.133664f,0.263361f,0.957213f,0.000368961f, 0.76252f,0.434767f,-0.137401f,0.257234f,0.95656f,0.000450908f,
0.743147f,0.446556f,-0.140851f,0.250935f,0.955861f,0.000552123f, 0.72552f,0.458859f,-0.144086f,0.244624f,0.955092f,0.000676242f,
0.703071f,0.467696f,-0.146854f,0.23789f,0.954266f,0.000829062f, 0.682664f,0.477167f,-0.149407f,0.231188f,0.953365f,0.00101631f,
0.661113f,0.485224f,-0.151618f,0.224331f,0.952392f,0.00124585f, 0.638979f,0.49215f,-0.153485f,0.217345f,0.951341f,0.00152663f,
0.617171f,0.498599f,-0.155042f,0.210301f,0.950202f,0.00186912f, 0.594621f,0.503688f,-0.156239f,0.203163f,0.948999f,0.00228607f,
0.572442f,0.508302f,-0.157126f,0.196008f,0.947716f,0.00279254f, 0.54989f,0.511766f,-0.157646f,0.18878f,0.946333f,0.00340597f,
0.526298f,0.513336f,-0.157779f,0.181476f,0.944836f,0.00414659f, 0.502586f,0.513775f,-0.157544f,0.17414f,0.943212f,0.00503806f,
0.479977f,0.514338f,-0.157034f,0.16689f,0.941451f,0.00610781f, 0.457198f,0.513696f,-0.156174f,0.159655f,0.939538f,0.00738684f,
0.433917f,0.511358f,-0.15493f,0.152419f,0.937457f,0.00891061f, 0.410863f,0.508069f,-0.153338f,0.145236f,0.93519f,0.0107188f,
0.388313f,0.504144f,-0.151393f,0.138114f,0.932726f,0.0128566f, 0.367219f,0.500858f,-0.149266f,0.131219f,0.930043f,0.0153731f,
0.347911f,0.49875f,-0.14707f,0.124643f,0.927125f,0.018323f, 0.32268f,0.48681f,-0.143707f,0.117482f,0.923953f,0.0217648f,
0.300435f,0.477321f,-0.140383f,0.110768f,0.920505f,0.025761f, 0.280248f,0.469332f,-0.136953f,0.104371f,0.916772f,0.0303783f,
0.263287f,0.465177f,-0.133571f,0.0984005f,0.912735f,0.0356838f, 0.240142f,0.448277f,-0.129054f,0.0919951f,0.908388f,0.0417453f,
0.225563f,0.445054f,-0.125404f,0.0866043f,0.903736f,0.0486284f, 0.204411f,0.427081f,-0.120469f,0.0807202f,0.898796f,0.0563938f,
0.193404f,0.427586f,-0.116879f,0.0761217f,0.893607f,0.0650929f, 0.171621f,0.402744f,-0.111174f,0.0705356f,0.888246f,0.0747661f,
0.156509f,0.389583f,-0.106274f,0.065864f,0.882835f,0.0854383f, 0.145121f,0.382827f,-0.101907f,0.0618995f,0.877574f,0.0971194f,
0.128099f,0.358636f,-0.0961922f,0.0574994f,0.872774f,0.109797f, 0.117666f,0.348384f,-0.0915464f,0.0541209f,0.868949f,0.123447f,
0.108218f,0.338367f,-0.0870628f,0.0512026f,0.866646f,0.138039f, 0.0991627f,0.326565f,-0.0829662f,0.0488744f,0.86669f,0.153557f,
0.0861068f,0.296622f,-0.0768658f,0.0457194f,0.870178f,0.170014f, 0.0797256f,0.284094f,-0.0729221f,0.0441928f,0.878488f,0.187475f,
0.0700005f,0.258007f,-0.0678036f,0.0422904f,0.893375f,0.206069f, 0.0621792f,0.234238f,-0.0629773f,0.0408604f,0.917093f,0.226003f,
0.0536867f,0.205128f,-0.0578838f,0.0394909f,0.951087f,0.247424f, 0.0483956f,0.185913f,-0.0533111f,0.0385704f,0.998136f,0.269963f,
1.0f,1.60135e-07f,-3.01838e-18f,0.360421f,0.956404f,1.80415e-05f, 0.999523f,0.0223308f,-0.00766263f,0.360249f,0.956379f,1.81861e-05f,
0.998096f,0.0446313f,-0.0153507f,0.35975f,0.956396f,1.8899e-05f, 0.995714f,0.0668518f,-0.0230122f,0.358907f,0.95637f,2.00498e-05f,
0.992393f,0.0889529f,-0.0306256f,0.357719f,0.956287f,2.16349e-05f, 0.988124f,0.110893f,-0.0381718f,0.356184f,0.956142f,2.36746e-05f,
0.98292f,0.132632f,-0.0456266f,0.354316f,0.955964f,2.62434e-05f, 0.976788f,0.154132f,-0.0529889f,0.352136f,0.955834f,2.96977e-05f,
0.969735f,0.175354f,-0.0602434f,0.349633f,0.955684f,3.40089e-05f, 0.961774f,0.196258f,-0.0673714f,0.346805f,0.955491f,3.92332e-05f,
0.952924f,0.216807f,-0.0743572f,0.343659f,0.955245f,4.5493e-05f, 0.943199f,0.236968f,-0.0812036f,0.340203f,0.954984f,5.3324e-05f,
0.932614f,0.256699f,-0.0878852f,0.336441f,0.954684f,6.28824e-05f, 0.921209f,0.27597f,-0.0943821f,0.332381f,0.95433f,7.43849e-05f,
0.908902f,0.294716f,-0.100683f,0.328024f,0.953945f,8.84472e-05f, 0.895883f,0.312947f,-0.10677f,0.323404f,0.953568f,0.000105735f,
0.882062f,0.330595f,-0.112631f,0.318525f,0.953152f,0.000126647f, 0.867418f,0.347613f,-0.11826f,0.313381f,0.952708f,0.000152293f,
0.851985f,0.363963f,-0.123641f,0.307977f,0.952224f,0.000183696f, 0.835903f,0.379656f,-0.128761f,0.302329f,0.951685f,0.000221913f,
0.819966f,0.394977f,-0.133641f,0.296501f,0.951108f,0.000268949f, 0.801732f,0.408877f,-0.138196f,0.290362f,0.950468f,0.000326282f,
0.78382f,0.422416f,-0.142487f,0.284062f,0.949781f,0.000396756f, 0.76537f,0.435209f,-0.146475f,0.277566f,0.949028f,0.0004828f,
0.746341f,0.447198f,-0.150157f,0.270889f,0.948219f,0.000588383f, 0.72708f,0.45854f,-0.153532f,0.264067f,0.947337f,0.000717268f,
0.707669f,0.469274f,-0.156606f,0.25713f,0.946396f,0.00087491f, 0.687602f,0.479037f,-0.159348f,0.250069f,0.94541f,0.00106726f,
0.665253f,0.486572f,-0.16165f,0.242731f,0.944356f,0.00130154f, 0.64372f,0.493983f,-0.163664f,0.235376f,0.943222f,0.0015865f,
0.621646f,0.50026f,-0.165286f,0.227869f,0.942004f,0.00193257f, 0.599628f,0.50583f,-0.166575f,0.220317f,0.940688f,0.00235162f,
0.578021f,0.510995f,-0.167571f,0.212788f,0.939266f,0.00285787f, 0.555105f,0.514172f,-0.168134f,0.205122f,0.937728f,0.00346781f,
0.531965f,0.516218f,-0.168317f,0.197408f,0.936066f,0.00420073f, 0.509794f,0.518298f,-0.168199f,0.189758f,0.934268f,0.00507852f,
0.487325f,0.519137f,-0.16771f,0.182105f,0.932325f,0.00612677f, 0.463704f,0.517658f,-0.166741f,0.174351f,0.930224f,0.00737426f,
0.440875f,0.515921f,-0.165482f,0.166719f,0.92795f,0.00885338f, 0.4186f,0.513682f,-0.163865f,0.159149f,0.925493f,0.0106011f,
0.399042f,0.513715f,-0.162202f,0.151947f,0.922836f,0.0126576f, 0.37888f,0.511889f,-0.160161f,0.144797f,0.919969f,0.0150683f,
0.352848f,0.500748f,-0.156981f,0.137051f,0.916876f,0.0178819f, 0.338443f,0.504857f,-0.154932f,0.130706f,0.913543f,0.0211506f,
0.309746f,0.48587f,-0.150644f,0.122901f,0.909961f,0.0249308f, 0.290992f,0.48038f,-0.147248f,0.116271f,0.906126f,0.0292805f,
0.272077f,0.473048f,-0.143547f,0.109822f,0.902064f,0.0342592f, 0.252264f,0.462344f,-0.139351f,0.103417f,0.897765f,0.0399263f,
0.233376f,0.451205f,-0.134933f,0.0972716f,0.893244f,0.0463391f, 0.215977f,0.440724f,-0.130469f,0.0915105f,0.888537f,0.0535508f,
0.200921f,0.432869f,-0.12605f,0.0861902f,0.883702f,0.0616073f, 0.185914f,0.422986f,-0.121389f,0.0811073f,0.87884f,0.0705458f,
0.171765f,0.412506f,-0.116633f,0.0763642f,0.874101f,0.0803926f, 0.152367f,0.386969f,-0.110666f,0.0712401f,0.869705f,0.0911617f,
0.140781f,0.376901f,-0.105953f,0.0673299f,0.865954f,0.102852f, 0.128951f,0.362849f,-0.100928f,0.0636121f,0.86329f,0.115462f,
0.114487f,0.338944f,-0.0952426f,0.0598679f,0.8623f,0.128985f, 0.109068f,0.336704f,-0.0912535f,0.057575f,0.863752f,0.143425f,
0.0958658f,0.308562f,-0.0855775f,0.0545994f,0.868768f,0.158815f, 0.0888918f,0.295045f,-0.081306f,0.0528882f,0.878734f,0.175235f,
0.0783449f,0.267178f,-0.075886f,0.0507743f,0.894706f,0.192804f, 0.0698284f,0.242509f,-0.0707247f,0.0491376f,0.918662f,0.211688f,
0.0641192f,0.224177f,-0.0661792f,0.048203f,0.952043f,0.232037f, 0.0561615f,0.197643f,-0.0607998f,0.0467783f,0.998151f,0.253614f,
0.999993f,3.44723e-07f,-7.91158e-18f,0.386239f,0.948961f,1.98939e-05f, 0.999526f,0.0223063f,-0.0081914f,0.386063f,0.948965f,2.01815e-05f,
0.998115f,0.0445664f,-0.0163349f,0.38554f,0.948988f,2.10226e-05f, 0.995755f,0.066746f,-0.0244437f,0.384644f,0.948947f,2.22572e-05f,
0.992462f,0.0888066f,-0.0324994f,0.383383f,0.948836f,2.38938e-05f, 0.988236f,0.110714f,-0.0405077f,0.381766f,0.948704f,2.61715e-05f,
0.983096f,0.132429f,-0.0484447f,0.379797f,0.948543f,2.91743e-05f, 0.977038f,0.153905f,-0.0562696f,0.377479f,0.948355f,3.2927e-05f,
0.970064f,0.175101f,-0.0639577f,0.374822f,0.948147f,3.7489e-05f, 0.962171f,0.195982f,-0.0715248f,0.371829f,0.94793f,4.32268e-05f,
0.953393f,0.216512f,-0.0789482f,0.3685f,0.947679f,5.02624e-05f, 0.943754f,0.236653f,-0.0862055f,0.364841f,0.947374f,5.87179e-05f,
0.933258f,0.256369f,-0.0932892f,0.360858f,0.947029f,6.90219e-05f, 0.921953f,0.27563f,-0.100187f,0.356561f,0.946648f,8.16482e-05f,
0.909892f,0.29441f,-0.106871f,0.351961f,0.946216f,9.68464e-05f, 0.89717f,0.312697f,-0.11333f,0.347083f,0.945782f,0.000115424f,
0.883363f,0.330319f,-0.119556f,0.341935f,0.945318f,0.000138038f, 0.868857f,0.347349f,-0.125524f,0.336492f,0.944804f,0.000165416f,
0.8537f,0.363768f,-0.131235f,0.330781f,0.944253f,0.00019893f, 0.838662f,0.379825f,-0.136688f,0.324859f,0.943641f,0.000239548f,
0.82146f,0.394608f,-0.141838f,0.318637f,0.942985f,0.000289254f, 0.80464f,0.40908f,-0.146711f,0.312234f,0.942262f,0.000349625f,
0.78727f,0.422869f,-0.151278f,0.305604f,0.941485f,0.000423403f, 0.769275f,0.435913f,-0.155523f,0.298761f,0.940638f,0.000513094f,
0.751074f,0.448399f,-0.159461f,0.291764f,0.93973f,0.000622417f, 0.732709f,0.460344f,-0.163087f,0.28465f,0.93878f,0.000755437f,
0.72013f,0.4746f,-0.166887f,0.278236f,0.937767f,0.000917043f, 0.69103f,0.479479f,-0.169124f,0.269664f,0.936682f,0.00111324f,
0.669422f,0.487535f,-0.171583f,0.261937f,0.935516f,0.00135115f, 0.648635f,0.495513f,-0.17375f,0.254206f,0.934262f,0.00163901f,
0.627956f,0.502935f,-0.175587f,0.246432f,0.932909f,0.00198652f, 0.606954f,0.509437f,-0.177062f,0.238586f,0.931454f,0.0024053f,
0.585679f,0.514994f,-0.17817f,0.23068f,0.929886f,0.0029087f, 0.561669f,0.517258f,-0.178698f,0.222472f,0.928198f,0.00351223f,
0.539729f,0.520534f,-0.179014f,0.214451f,0.926381f,0.00423388f, 0.517686f,0.522834f,-0.178898f,0.206356f,0.924426f,0.00509417f,
0.494642f,0.523139f,-0.178367f,0.198234f,0.922324f,0.00611671f, 0.471727f,0.522515f,-0.177445f,0.190129f,0.920061f,0.00732783f,
0.450337f,0.522539f,-0.176281f,0.182215f,0.917631f,0.0087576f, 0.430291f,0.523142f,-0.174903f,0.17452f,0.915027f,0.0104393f,
0.408914f,0.520854f,-0.172857f,0.166611f,0.91226f,0.0124098f, 0.384592f,0.513884f,-0.170362f,0.158729f,0.909307f,0.0147099f,
0.367355f,0.514865f,-0.168167f,0.15157f,0.906153f,0.0173831f, 0.341152f,0.501904f,-0.164591f,0.143618f,0.902791f,0.0204766f,
0.321784f,0.497103f,-0.161345f,0.136417f,0.899213f,0.0240398f, 0.306547f,0.497009f,-0.158353f,0.129861f,0.895423f,0.0281248f,
0.282017f,0.481183f,-0.153849f,0.12251f,0.891427f,0.0327839f, 0.262856f,0.471688f,-0.149624f,0.115843f,0.887245f,0.0380693f,
0.247058f,0.466395f,-0.145604f,0.10977f,0.882909f,0.044032f, 0.235139f,0.465866f,-0.142101f,0.104499f,0.878476f,0.0507195f,
0.210402f,0.440141f,-0.135874f,0.0976675f,0.874023f,0.0581736f, 0.194934f,0.429124f,-0.131092f,0.0923302f,0.869672f,0.06643f,
0.179405f,0.415566f,-0.125884f,0.0871219f,0.865589f,0.0755162f, 0.165517f,0.402881f,-0.120874f,0.0824766f,0.862006f,0.0854511f,
0.154215f,0.393531f,-0.116063f,0.0783851f,0.859239f,0.0962458f, 0.141576f,0.378322f,-0.11081f,0.0744127f,0.857781f,0.107915f,
0.126182f,0.352561f,-0.104875f,0.0704f,0.858261f,0.120464f, 0.120433f,0.349508f,-0.100763f,0.0680145f,0.861308f,0.133921f,
0.106135f,0.31914f,-0.0947448f,0.0647361f,0.867771f,0.148333f, 0.101806f,0.31338f,-0.0908806f,0.0633214f,0.878669f,0.163776f,
0.0891835f,0.281088f,-0.084833f,0.0607637f,0.895751f,0.180384f, 0.0825856f,0.263657f,-0.0799937f,0.0593948f,0.919753f,0.198271f,
0.0736256f,0.23674f,-0.0745703f,0.0578876f,0.952675f,0.217634f, 0.0672506f,0.216491f,-0.0693725f,0.0566902f,0.998152f,0.238317f,
1.0f,-5.08357e-07f,-1.09121e-17f,0.412705f,0.940817f,2.22747e-05f, 0.99953f,0.0222545f,-0.00863913f,0.412507f,0.940779f,2.24804e-05f,
0.998133f,0.0444704f,-0.0172573f,0.411919f,0.940667f,2.30959e-05f, 0.995804f,0.0666085f,-0.0258451f,0.410965f,0.940576f,2.43626e-05f,
0.992554f,0.0886278f,-0.0343734f,0.409649f,0.940506f,2.63182e-05f, 0.988371f,0.110489f,-0.0428278f,0.407952f,0.940385f,2.88616e-05f,
0.983276f,0.132156f,-0.0511899f,0.405876f,0.9402f,3.20228e-05f, 0.977271f,0.153593f,-0.0594655f,0.403433f,0.939992f,3.61137e-05f,
0.970365f,0.174758f,-0.0676196f,0.400624f,0.939744f,4.11888e-05f, 0.962559f,0.195606f,-0.0756109f,0.397464f,0.939477f,4.73404e-05f,
0.953892f,0.216107f,-0.0834504f,0.393961f,0.93919f,5.49143e-05f, 0.944369f,0.236227f,-0.091121f,0.39011f,0.938868f,6.4161e-05f,
0.93403f,0.25593f,-0.0985992f,0.385921f,0.938487f,7.52463e-05f, 0.922935f,0.2752f,-0.105884f,0.381406f,0.938071f,8.88196e-05f,
0.911165f,0.294017f,-0.112952f,0.376574f,0.937602f,0.000105217f, 0.89841f,0.312251f,-0.119789f,0.371457f,0.937091f,0.000125033f,
0.885032f,0.329966f,-0.126364f,0.366023f,0.936565f,0.000149157f, 0.87073f,0.347024f,-0.132674f,0.360307f,0.93599f,0.000178267f,
0.856012f,0.363554f,-0.138718f,0.354326f,0.935374f,0.000213712f, 0.840567f,0.379409f,-0.144481f,0.348101f,0.934696f,0.000256565f,
0.824938f,0.394766f,-0.149965f,0.341658f,0.933965f,0.000308676f, 0.80884f,0.409545f,-0.15514f,0.334973f,0.933169f,0.000371805f,
0.792036f,0.423632f,-0.159984f,0.328037f,0.932306f,0.000448367f, 0.774145f,0.436786f,-0.164457f,0.320803f,0.931378f,0.000541309f,
0.756766f,0.449802f,-0.168637f,0.313486f,0.930389f,0.000653807f, 0.735766f,0.460179f,-0.17237f,0.305826f,0.929347f,0.000790014f,
0.716547f,0.471072f,-0.175802f,0.298112f,0.928237f,0.000954842f, 0.695866f,0.480434f,-0.178821f,0.290176f,0.927047f,0.00115388f,
0.67596f,0.489726f,-0.181531f,0.282213f,0.925768f,0.00139387f, 0.656166f,0.498524f,-0.183909f,0.2742f,0.924397f,0.00168282f,
0.636174f,0.50658f,-0.185933f,0.266124f,0.922925f,0.00203003f, 0.616904f,0.514628f,-0.187669f,0.258091f,0.921345f,0.00244632f,
0.591423f,0.516617f,-0.188488f,0.249279f,0.919651f,0.00294438f, 0.574537f,0.525429f,-0.189648f,0.241391f,0.917835f,0.00353864f,
0.548501f,0.525027f,-0.189627f,0.232474f,0.915888f,0.00424576f, 0.526106f,0.527051f,-0.189588f,0.224029f,0.913805f,0.00508503f,
0.503952f,0.528349f,-0.189154f,0.215598f,0.911579f,0.00607784f, 0.483f,0.529973f,-0.188428f,0.207317f,0.909226f,0.0072487f,
0.461102f,0.529569f,-0.187178f,0.198939f,0.906722f,0.00862475f, 0.439006f,0.52783f,-0.185578f,0.190668f,0.904057f,0.0102365f,
0.416594f,0.524465f,-0.183493f,0.182381f,0.901223f,0.0121173f, 0.397178f,0.523663f,-0.181398f,0.174558f,0.898212f,0.0143038f,
0.37513f,0.518175f,-0.178589f,0.166521f,0.895016f,0.0168347f, 0.354313f,0.5129f,-0.175574f,0.158769f,0.891639f,0.0197527f,
0.341464f,0.517924f,-0.173232f,0.152075f,0.888083f,0.0231016f, 0.313515f,0.498972f,-0.168522f,0.143775f,0.884358f,0.0269275f,
0.296511f,0.494963f,-0.164848f,0.13685f,0.880483f,0.0312772f, 0.281823f,0.49334f,-0.161337f,0.130508f,0.87649f,0.0361972f,
0.25833f,0.474896f,-0.155989f,0.123151f,0.872424f,0.041733f, 0.241441f,0.465701f,-0.151471f,0.116927f,0.868354f,0.0479277f,
0.225004f,0.455324f,-0.146725f,0.110984f,0.864376f,0.0548204f, 0.208511f,0.442494f,-0.141584f,0.105198f,0.860622f,0.0624461f,
0.194853f,0.433174f,-0.136829f,0.100158f,0.857337f,0.070834f, 0.180101f,0.418887f,-0.131524f,0.0951623f,0.85474f,0.080008f,
0.16815f,0.408223f,-0.126551f,0.0908457f,0.85314f,0.0899924f, 0.154848f,0.392231f,-0.121197f,0.0866934f,0.852925f,0.100802f,
0.144235f,0.378978f,-0.116039f,0.0831128f,0.85462f,0.112469f, 0.132063f,0.359237f,-0.110493f,0.07968f,0.858856f,0.125028f,
0.123351f,0.345496f,-0.105882f,0.0773572f,0.866623f,0.138535f, 0.112327f,0.321616f,-0.100272f,0.074714f,0.878794f,0.153078f,
0.103844f,0.302419f,-0.0949824f,0.0726989f,0.896312f,0.168757f, 0.0918842f,0.271065f,-0.0887365f,0.0702887f,0.920488f,0.185731f,
0.0866706f,0.25613f,-0.0839504f,0.069357f,0.952993f,0.204157f, 0.077463f,0.229257f,-0.0780813f,0.0677025f,0.99814f,0.224019f,
1.0f,-5.5871e-07f,1.09738e-17f,0.439616f,0.931403f,2.39764e-05f, 0.999535f,0.0221943f,-0.00909255f,0.43944f,0.931467f,2.44222e-05f,
0.998161f,0.0443508f,-0.0181633f,0.438857f,0.931463f,2.53489e-05f, 0.995859f,0.0664269f,-0.027195f,0.43786f,0.931379f,2.67503e-05f,
0.992646f,0.0883915f,-0.0361738f,0.43646f,0.931227f,2.87004e-05f, 0.988518f,0.110202f,-0.0450888f,0.434674f,0.931074f,3.14543e-05f,
0.983494f,0.131815f,-0.0538926f,0.432506f,0.930904f,3.49938e-05f, 0.977556f,0.153196f,-0.0625785f,0.429947f,0.930679f,3.93447e-05f,
0.970731f,0.17431f,-0.0711515f,0.42701f,0.930427f,4.48307e-05f, 0.963038f,0.195123f,-0.079579f,0.423693f,0.930119f,5.15154e-05f,
0.954493f,0.215589f,-0.0878355f,0.420006f,0.929763f,5.95923e-05f, 0.945144f,0.235687f,-0.0959081f,0.415978f,0.929404f,6.95181e-05f,
0.935022f,0.255382f,-0.103775f,0.411597f,0.928995f,8.14331e-05f, 0.924229f,0.27467f,-0.111437f,0.406881f,0.928547f,9.59043e-05f,
0.912678f,0.293488f,-0.118877f,0.401855f,0.928045f,0.000113364f, 0.900241f,0.311765f,-0.126072f,0.396494f,0.927487f,0.000134428f,
0.887032f,0.32948f,-0.133009f,0.390817f,0.926877f,0.000159906f, 0.873413f,0.346709f,-0.139665f,0.384859f,0.926237f,0.000190648f,
0.859147f,0.363337f,-0.146046f,0.378656f,0.925554f,0.000227802f, 0.843958f,0.379234f,-0.152107f,0.372122f,0.924817f,0.000272707f,
0.828253f,0.394529f,-0.157853f,0.365326f,0.924016f,0.000326876f, 0.812457f,0.409405f,-0.163296f,0.358321f,0.923155f,0.000392428f,
0.79587f,0.42358f,-0.168384f,0.351043f,0.922221f,0.00047149f, 0.779488f,0.437509f,-0.173173f,0.343639f,0.921215f,0.000566887f,
0.767865f,0.453925f,-0.177949f,0.336672f,0.920134f,0.000682008f, 0.742007f,0.461482f,-0.181576f,0.328056f,0.918998f,0.000820717f,
0.722778f,0.472399f,-0.185218f,0.320017f,0.917792f,0.000987623f, 0.705778f,0.484357f,-0.18863f,0.312077f,0.916505f,0.00118826f,
0.684907f,0.493073f,-0.191464f,0.303678f,0.915129f,0.00142905f, 0.664645f,0.501615f,-0.193935f,0.295211f,0.913659f,0.00171756f,
0.644574f,0.509657f,-0.196086f,0.28676f,0.912085f,0.00206257f, 0.62118f,0.514293f,-0.197562f,0.277834f,0.910405f,0.00247432f,
0.603143f,0.522681f,-0.19909f,0.269484f,0.908608f,0.00296454f, 0.580295f,0.526179f,-0.199831f,0.260569f,0.906691f,0.00354675f,
0.558612f,0.529857f,-0.200315f,0.251828f,0.904647f,0.00423662f, 0.536769f,0.532506f,-0.200359f,0.243044f,0.902472f,0.00505148f,
0.514799f,0.534094f,-0.199887f,0.234154f,0.900184f,0.00601138f, 0.494305f,0.536267f,-0.199249f,0.225581f,0.89776f,0.00713841f,
0.471702f,0.535158f,-0.197965f,0.216784f,0.895195f,0.00845775f, 0.450512f,0.534508f,-0.196463f,0.208257f,0.892479f,0.00999649f,
0.430391f,0.534049f,-0.194586f,0.199833f,0.889612f,0.0117852f, 0.40877f,0.530576f,-0.192304f,0.191494f,0.886587f,0.0138563f,
0.387788f,0.526568f,-0.189613f,0.183251f,0.88341f,0.0162455f, 0.369147f,0.524464f,-0.186783f,0.17537f,0.880085f,0.0189899f,
0.351082f,0.521906f,-0.183723f,0.16776f,0.876622f,0.0221293f, 0.328589f,0.511343f,-0.179711f,0.159781f,0.873043f,0.0257046f,
0.318504f,0.518266f,-0.177076f,0.153501f,0.869373f,0.0297576f, 0.291117f,0.496321f,-0.171569f,0.145225f,0.865656f,0.0343304f,
0.277745f,0.495286f,-0.167848f,0.138962f,0.861948f,0.0394641f, 0.260014f,0.485093f,-0.163123f,0.132349f,0.85836f,0.0451984f,
0.242045f,0.472264f,-0.158039f,0.125938f,0.855005f,0.0515707f, 0.225247f,0.459261f,-0.152948f,0.120005f,0.852011f,0.0586157f,
0.210631f,0.448193f,-0.147909f,0.114585f,0.849557f,0.0663644f, 0.195057f,0.43251f,-0.142446f,0.109308f,0.847882f,0.0748461f,
0.182488f,0.420653f,-0.137342f,0.10477f,0.847291f,0.0840894f, 0.168171f,0.402314f,-0.131625f,0.100225f,0.848161f,0.0941208f,
0.157059f,0.388548f,-0.126356f,0.0964821f,0.851028f,0.104982f, 0.144286f,0.368005f,-0.120719f,0.0929169f,0.856631f,0.116714f,
0.136472f,0.356263f,-0.115901f,0.0904204f,0.865475f,0.129384f, 0.123692f,0.329406f,-0.110042f,0.0875508f,0.878476f,0.143076f,
0.115125f,0.310856f,-0.104514f,0.0853459f,0.896622f,0.15791f, 0.104238f,0.284009f,-0.0984495f,0.0830817f,0.921095f,0.174012f,
0.0979408f,0.266953f,-0.093163f,0.0818189f,0.953287f,0.191577f, 0.0908649f,0.247154f,-0.087696f,0.080615f,0.998117f,0.210666f,
1.0f,-2.8283e-07f,9.81512e-18f,0.467085f,0.921331f,2.63956e-05f, 0.999551f,0.0221134f,-0.00950926f,0.466869f,0.921288f,2.66227e-05f,
0.998186f,0.0441967f,-0.0190309f,0.466239f,0.92122f,2.74826e-05f, 0.995921f,0.0662046f,-0.0285147f,0.465198f,0.921124f,2.90129e-05f,
0.992748f,0.0880916f,-0.0379094f,0.463748f,0.921002f,3.12006e-05f, 0.988688f,0.109828f,-0.0472329f,0.461889f,0.920838f,3.41166e-05f,
0.983724f,0.131377f,-0.0564736f,0.459621f,0.920633f,3.79097e-05f, 0.977874f,0.152696f,-0.0655919f,0.456942f,0.920365f,4.25888e-05f,
0.971159f,0.173749f,-0.0745658f,0.45388f,0.92009f,4.84396e-05f, 0.963614f,0.194506f,-0.0833865f,0.450434f,0.919777f,5.56078e-05f,
0.955263f,0.214935f,-0.0920335f,0.446605f,0.919406f,6.42479e-05f, 0.946153f,0.23501f,-0.100503f,0.442402f,0.918993f,7.47975e-05f,
0.936373f,0.254717f,-0.108761f,0.437837f,0.91852f,8.74413e-05f, 0.926026f,0.274049f,-0.116794f,0.432939f,0.918031f,0.000102796f,
0.914521f,0.292812f,-0.124591f,0.427731f,0.91749f,0.000121199f, 0.901868f,0.31095f,-0.132112f,0.422101f,0.916904f,0.000143451f,
0.889064f,0.328711f,-0.139371f,0.416183f,0.916254f,0.000170141f, 0.875217f,0.345791f,-0.146349f,0.409951f,0.91555f,0.000202363f,
0.86138f,0.362478f,-0.153042f,0.403469f,0.91478f,0.00024106f, 0.847425f,0.378718f,-0.159447f,0.396788f,0.913974f,0.000287663f,
0.833494f,0.394669f,-0.165529f,0.389841f,0.913115f,0.000343763f, 0.817747f,0.409585f,-0.171248f,0.382574f,0.912189f,0.000411184f,
0.802481f,0.424431f,-0.176648f,0.375127f,0.911193f,0.000492236f, 0.785544f,0.438096f,-0.181693f,0.367449f,0.910126f,0.000589697f,
0.767574f,0.450791f,-0.18633f,0.359479f,0.908978f,0.000706661f, 0.749516f,0.462983f,-0.190607f,0.351349f,0.907748f,0.000846946f,
0.730443f,0.474059f,-0.194397f,0.342875f,0.906446f,0.00101501f, 0.712344f,0.485258f,-0.19793f,0.334502f,0.905073f,0.0012161f,
0.692909f,0.495001f,-0.200977f,0.325846f,0.903615f,0.00145633f, 0.672725f,0.503592f,-0.203649f,0.31712f,0.902062f,0.0017428f,
0.65208f,0.511164f,-0.205879f,0.308244f,0.900412f,0.00208387f, 0.632406f,0.518853f,-0.207754f,0.29937f,0.898654f,0.00248901f,
0.612029f,0.525286f,-0.209204f,0.290418f,0.896784f,0.00296916f, 0.598712f,0.537232f,-0.210827f,0.282207f,0.894799f,0.00353708f,
0.577327f,0.541536f,-0.211421f,0.273126f,0.892691f,0.00420682f, 0.547529f,0.536875f,-0.210748f,0.26298f,0.890458f,0.00499473f,
0.531223f,0.544144f,-0.211086f,0.254655f,0.888115f,0.00591884f, 0.506239f,0.54187f,-0.209981f,0.245123f,0.885656f,0.00699977f,
0.484244f,0.541492f,-0.208762f,0.236016f,0.883068f,0.00825971f, 0.465148f,0.543288f,-0.207472f,0.227361f,0.88035f,0.00972371f,
0.450744f,0.549765f,-0.20634f,0.21938f,0.877503f,0.0114192f, 0.428302f,0.545712f,-0.203903f,0.210524f,0.874528f,0.0133752f,
0.40252f,0.535912f,-0.200626f,0.201357f,0.871432f,0.0156237f, 0.392176f,0.544992f,-0.198959f,0.194315f,0.868229f,0.0181986f,
0.370593f,0.538002f,-0.195523f,0.18604f,0.864936f,0.0211351f, 0.346073f,0.524991f,-0.191171f,0.177438f,0.861579f,0.0244701f,
0.327123f,0.518208f,-0.18727f,0.169791f,0.858195f,0.0282411f, 0.307563f,0.508738f,-0.183028f,0.162355f,0.85484f,0.0324862f,
0.297172f,0.512569f,-0.179589f,0.156138f,0.851614f,0.0372435f, 0.278682f,0.500456f,-0.174834f,0.149274f,0.848587f,0.0425501f,
0.259881f,0.487527f,-0.169684f,0.142586f,0.845868f,0.0484419f, 0.241962f,0.472788f,-0.164298f,0.136208f,0.843599f,0.0549534f,
0.226676f,0.460578f,-0.159176f,0.13055f,0.841967f,0.062118f, 0.210643f,0.444337f,-0.153597f,0.125012f,0.841203f,0.0699678f,
0.20484f,0.446767f,-0.149591f,0.121238f,0.841597f,0.0785356f, 0.191484f,0.431506f,-0.144112f,0.116768f,0.843624f,0.0878617f,
0.176414f,0.409686f,-0.138077f,0.112332f,0.84771f,0.09798f, 0.16493f,0.393181f,-0.132689f,0.108889f,0.854309f,0.108957f,
0.151419f,0.368586f,-0.126687f,0.105419f,0.86414f,0.120853f, 0.141083f,0.348884f,-0.121068f,0.102715f,0.877973f,0.133759f,
0.128688f,0.322124f,-0.114739f,0.0998436f,0.896683f,0.147784f, 0.122526f,0.308159f,-0.109376f,0.0982216f,0.921275f,0.16307f,
0.114125f,0.286936f,-0.103607f,0.0966348f,0.953381f,0.179833f, 0.10399f,0.260841f,-0.0975183f,0.0949771f,0.998083f,0.198205f,
1.0f,-7.36841e-07f,-2.46396e-17f,0.494885f,0.910113f,2.85119e-05f, 0.999551f,0.0220238f,-0.00994282f,0.49466f,0.910068f,2.87747e-05f,
0.998214f,0.0440079f,-0.0198599f,0.494001f,0.909969f,2.96409e-05f, 0.995983f,0.0659178f,-0.0297362f,0.49293f,0.909896f,3.132e-05f,
0.992857f,0.0877145f,-0.0395491f,0.491423f,0.909759f,3.36604e-05f, 0.988859f,0.109364f,-0.0492866f,0.489486f,0.909558f,3.67432e-05f,
0.983996f,0.130828f,-0.0589234f,0.487135f,0.909339f,4.07877e-05f, 0.978284f,0.152066f,-0.068422f,0.484371f,0.909076f,4.57908e-05f,
0.971753f,0.173054f,-0.0777922f,0.481201f,0.908774f,5.20188e-05f, 0.964425f,0.193759f,-0.0870048f,0.477622f,0.908412f,5.959e-05f,
0.95608f,0.214098f,-0.0960301f,0.473626f,0.908007f,6.87729e-05f, 0.947113f,0.234108f,-0.104854f,0.469268f,0.907574f,7.99013e-05f,
0.937595f,0.253777f,-0.113464f,0.464544f,0.907088f,9.32726e-05f, 0.927332f,0.273032f,-0.121857f,0.459491f,0.906549f,0.000109385f,
0.916104f,0.291776f,-0.130001f,0.454064f,0.905949f,0.000128715f, 0.904117f,0.310009f,-0.13787f,0.448284f,0.905303f,0.00015192f,
0.892428f,0.328008f,-0.145451f,0.442167f,0.904619f,0.000179806f, 0.878761f,0.345046f,-0.152754f,0.43579f,0.903875f,0.000213194f,
0.865883f,0.361935f,-0.159787f,0.429201f,0.903072f,0.000253291f, 0.852823f,0.378437f,-0.166508f,0.42233f,0.902201f,0.000301348f,
0.838964f,0.394419f,-0.172887f,0.415147f,0.901259f,0.000358907f, 0.824903f,0.41012f,-0.178922f,0.407725f,0.900264f,0.000427869f,
0.809454f,0.424894f,-0.184626f,0.400122f,0.899212f,0.000510484f, 0.791622f,0.438107f,-0.189811f,0.391967f,0.898089f,0.000609302f,
0.774164f,0.451088f,-0.19462f,0.383621f,0.896889f,0.000727413f, 0.756419f,0.463428f,-0.199107f,0.375216f,0.895608f,0.000868457f,
0.739195f,0.475661f,-0.203244f,0.366717f,0.89424f,0.0010367f, 0.721763f,0.487323f,-0.207006f,0.358097f,0.892783f,0.00123711f,
0.702004f,0.496849f,-0.210279f,0.34921f,0.891246f,0.00147546f, 0.682386f,0.505851f,-0.21314f,0.340218f,0.88963f,0.00175846f,
0.663851f,0.515066f,-0.215641f,0.33122f,0.887921f,0.00209383f, 0.643094f,0.52191f,-0.217521f,0.321839f,0.886114f,0.00249056f,
0.627813f,0.532583f,-0.219466f,0.313108f,0.884202f,0.00295877f, 0.602721f,0.534367f,-0.220236f,0.303267f,0.882181f,0.00351006f,
0.581684f,0.538699f,-0.220947f,0.293929f,0.880048f,0.00415766f, 0.562737f,0.544165f,-0.221364f,0.284759f,0.8778f,0.00491628f,
0.544799f,0.549908f,-0.221448f,0.27571f,0.875436f,0.00580267f, 0.522189f,0.550173f,-0.220741f,0.266245f,0.87297f,0.00683525f,
0.49948f,0.549208f,-0.219544f,0.256773f,0.870407f,0.00803455f, 0.481867f,0.552728f,-0.218451f,0.247984f,0.867737f,0.0094229f,
0.45857f,0.548792f,-0.216454f,0.238727f,0.864968f,0.0110251f, 0.438264f,0.547028f,-0.214274f,0.22983f,0.862103f,0.0128676f,
0.420767f,0.547642f,-0.212048f,0.221431f,0.859156f,0.014979f, 0.406271f,0.551135f,-0.209863f,0.2136f,0.856142f,0.0173894f,
0.379546f,0.537091f,-0.205697f,0.204307f,0.853089f,0.0201311f, 0.364542f,0.537476f,-0.202671f,0.196704f,0.850026f,0.0232371f,
0.348023f,0.534509f,-0.199235f,0.189226f,0.846997f,0.0267416f, 0.324344f,0.519112f,-0.194221f,0.180808f,0.844083f,0.0306797f,
0.316615f,0.526788f,-0.191339f,0.174908f,0.841365f,0.0350864f, 0.297305f,0.514766f,-0.186518f,0.167751f,0.838925f,0.0399971f,
0.277288f,0.498974f,-0.18105f,0.160553f,0.836873f,0.0454462f, 0.258785f,0.483424f,-0.175706f,0.154002f,0.835357f,0.0514687f,
0.243499f,0.471427f,-0.170585f,0.14817f,0.834557f,0.058099f, 0.237337f,0.474521f,-0.166663f,0.143886f,0.834698f,0.0653723f,
0.219811f,0.453777f,-0.160524f,0.138218f,0.836148f,0.0733262f, 0.205899f,0.437428f,-0.154961f,0.133559f,0.83924f,0.082002f,
0.19003f,0.414743f,-0.148734f,0.128824f,0.844309f,0.0914496f, 0.184539f,0.411219f,-0.144436f,0.126278f,0.851885f,0.10172f,
0.172404f,0.390959f,-0.138702f,0.122984f,0.862655f,0.112898f, 0.157838f,0.36294f,-0.132058f,0.119359f,0.877174f,0.125065f,
0.148847f,0.345427f,-0.12641f,0.117091f,0.896252f,0.138335f, 0.140281f,0.326527f,-0.120413f,0.114955f,0.921055f,0.152868f,
0.128007f,0.297764f,-0.113743f,0.112585f,0.953229f,0.168876f, 0.120064f,0.277857f,-0.108028f,0.111419f,0.998039f,0.186585f,
0.999997f,3.71229e-07f,-3.83512e-17f,0.522978f,0.897842f,3.05806e-05f, 0.999556f,0.0219065f,-0.0103322f,0.522744f,0.897795f,3.08646e-05f,
0.998243f,0.0437732f,-0.0206232f,0.522071f,0.89771f,3.1826e-05f, 0.996072f,0.0655665f,-0.0308833f,0.520967f,0.897625f,3.35925e-05f,
0.993046f,0.0872541f,-0.0410795f,0.519409f,0.897465f,3.60488e-05f, 0.989096f,0.10879f,-0.0511942f,0.517406f,0.897261f,3.93474e-05f,
0.984294f,0.130142f,-0.0611937f,0.514979f,0.897034f,4.36208e-05f, 0.978653f,0.151272f,-0.0710655f,0.512117f,0.896747f,4.89122e-05f,
0.972188f,0.172152f,-0.0808063f,0.508836f,0.896411f,5.54783e-05f, 0.964947f,0.192749f,-0.0903657f,0.505142f,0.89603f,6.34329e-05f,
0.956972f,0.213035f,-0.0997418f,0.501049f,0.895617f,7.31339e-05f, 0.948367f,0.233001f,-0.108913f,0.496563f,0.895143f,8.47627e-05f,
0.939239f,0.252644f,-0.117875f,0.491698f,0.894615f,9.87965e-05f, 0.929159f,0.271828f,-0.126613f,0.486554f,0.894036f,0.000115584f,
0.918341f,0.290554f,-0.135075f,0.480984f,0.893418f,0.000135728f, 0.907122f,0.308881f,-0.143265f,0.475059f,0.892744f,0.000159836f,
0.895317f,0.32671f,-0.151181f,0.468834f,0.892005f,0.000188637f, 0.88365f,0.344218f,-0.158832f,0.462372f,0.891204f,0.00022312f,
0.871963f,0.361379f,-0.16619f,0.455678f,0.890352f,0.000264313f, 0.858212f,0.377638f,-0.173113f,0.448417f,0.889445f,0.000313491f,
0.84429f,0.39357f,-0.179704f,0.44091f,0.888474f,0.000372215f, 0.835518f,0.411785f,-0.186186f,0.433716f,0.887433f,0.000442321f,
0.814647f,0.423811f,-0.191968f,0.425478f,0.886318f,0.000525921f, 0.79858f,0.437909f,-0.197445f,0.417185f,0.885126f,0.000625523f,
0.782061f,0.451352f,-0.20258f,0.408801f,0.883875f,0.000744082f, 0.765854f,0.464613f,-0.207339f,0.400268f,0.882553f,0.000885071f,
0.749699f,0.477493f,-0.211744f,0.391643f,0.88115f,0.00105253f, 0.739042f,0.49355f,-0.216184f,0.383638f,0.879663f,0.00125116f,
0.711718f,0.49809f,-0.219074f,0.373484f,0.878086f,0.00148639f, 0.693065f,0.507771f,-0.222078f,0.364168f,0.876416f,0.00176451f,
0.682587f,0.522967f,-0.225313f,0.355798f,0.874656f,0.00209278f, 0.655853f,0.525412f,-0.226958f,0.345527f,0.872818f,0.00247945f,
0.636088f,0.532362f,-0.228767f,0.336137f,0.870891f,0.00293388f, 0.616382f,0.538655f,-0.230134f,0.32669f,0.868869f,0.00346691f,
0.595294f,0.542996f,-0.230779f,0.316822f,0.866748f,0.00409046f, 0.583899f,0.5554f,-0.232017f,0.308335f,0.864527f,0.00481814f,
0.554926f,0.550741f,-0.231231f,0.29775f,0.862209f,0.00566528f, 0.535006f,0.553582f,-0.230892f,0.288361f,0.859791f,0.00664836f,
0.51693f,0.557424f,-0.23026f,0.279182f,0.85728f,0.00778623f, 0.50109f,0.562881f,-0.229388f,0.270293f,0.854702f,0.00909903f,
0.477922f,0.55936f,-0.227526f,0.260823f,0.852062f,0.0106093f, 0.456232f,0.556163f,-0.225245f,0.251472f,0.849364f,0.0123406f,
0.439776f,0.558033f,-0.223107f,0.24286f,0.846625f,0.0143189f, 0.421518f,0.556674f,-0.220582f,0.234389f,0.843865f,0.0165716f,
0.398708f,0.548003f,-0.217077f,0.225454f,0.841114f,0.0191275f, 0.385453f,0.550707f,-0.214296f,0.217837f,0.838409f,0.022017f,
0.36772f,0.545468f,-0.210511f,0.209752f,0.835799f,0.0252714f, 0.344076f,0.53116f,-0.205866f,0.201391f,0.833354f,0.0289226f,
0.33568f,0.537211f,-0.20286f,0.195198f,0.831183f,0.0330041f, 0.315215f,0.523577f,-0.197754f,0.187532f,0.829365f,0.0375492f,
0.294669f,0.507345f,-0.192398f,0.180197f,0.828011f,0.0425915f, 0.290078f,0.516115f,-0.189401f,0.175608f,0.827264f,0.0481661f,
0.269216f,0.493509f,-0.182804f,0.168221f,0.827299f,0.0543081f, 0.253027f,0.479581f,-0.17768f,0.16275f,0.828364f,0.0610551f,
0.234835f,0.458042f,-0.171496f,0.156864f,0.830796f,0.0684474f, 0.220464f,0.441298f,-0.165827f,0.151977f,0.834825f,0.076529f,
0.214499f,0.438769f,-0.161433f,0.148792f,0.840814f,0.0853554f, 0.197978f,0.413134f,-0.154954f,0.144233f,0.849394f,0.0949859f,
0.192184f,0.406253f,-0.15042f,0.142005f,0.860857f,0.105493f, 0.178849f,0.382537f,-0.143887f,0.138418f,0.876026f,0.116975f,
0.163568f,0.352395f,-0.136813f,0.134781f,0.89559f,0.129547f, 0.154058f,0.332706f,-0.13063f,0.132476f,0.920468f,0.143357f,
0.146991f,0.316375f,-0.124834f,0.131057f,0.952847f,0.158664f, 0.136893f,0.29291f,-0.11884f,0.129758f,0.997986f,0.175755f,
0.999999f,4.15087e-07f,-9.80311e-18f,0.551301f,0.88453f,3.26268e-05f, 0.99958f,0.021759f,-0.0106724f,0.551066f,0.884481f,3.29211e-05f,
0.99828f,0.0434842f,-0.0213284f,0.550371f,0.884401f,3.39622e-05f, 0.99614f,0.0651341f,-0.0319327f,0.549234f,0.884304f,3.58062e-05f,
0.993135f,0.0866752f,-0.0424727f,0.547632f,0.884131f,3.83792e-05f, 0.989263f,0.108075f,-0.0529341f,0.54558f,0.883927f,4.18835e-05f,
0.984561f,0.129288f,-0.0632685f,0.543088f,0.883676f,4.63298e-05f, 0.979048f,0.15029f,-0.0734889f,0.540159f,0.883379f,5.19307e-05f,
0.972765f,0.171052f,-0.083555f,0.536794f,0.883018f,5.8763e-05f, 0.965771f,0.191541f,-0.0934464f,0.533016f,0.882632f,6.71434e-05f,
0.958151f,0.211748f,-0.103147f,0.528834f,0.882185f,7.72153e-05f, 0.949987f,0.231661f,-0.112651f,0.524251f,0.881684f,8.93799e-05f,
0.941323f,0.251264f,-0.121938f,0.519354f,0.881131f,0.000103924f, 0.931815f,0.27044f,-0.130975f,0.514067f,0.880536f,0.000121354f,
0.921638f,0.289184f,-0.139752f,0.508396f,0.879884f,0.000142179f, 0.910488f,0.30739f,-0.148222f,0.502261f,0.879167f,0.000167002f,
0.898514f,0.325023f,-0.156409f,0.495822f,0.878394f,0.000196631f, 0.887572f,0.342542f,-0.164337f,0.48924f,0.877574f,0.000231947f,
0.875722f,0.35953f,-0.17193f,0.482299f,0.876693f,0.000273983f, 0.863654f,0.376263f,-0.179177f,0.475019f,0.875744f,0.000324014f,
0.85144f,0.392837f,-0.186099f,0.467506f,0.874724f,0.000383539f, 0.837769f,0.408595f,-0.192714f,0.459858f,0.873644f,0.000454328f,
0.822782f,0.423487f,-0.1989f,0.451829f,0.872506f,0.000538417f, 0.815433f,0.442308f,-0.205047f,0.444311f,0.871297f,0.000638205f,
0.792581f,0.452268f,-0.210117f,0.435083f,0.870013f,0.000756526f, 0.775708f,0.465089f,-0.214979f,0.426096f,0.868649f,0.000896673f,
0.766768f,0.482387f,-0.219976f,0.41798f,0.867204f,0.00106245f, 0.74122f,0.488857f,-0.223665f,0.408033f,0.865694f,0.00125829f,
0.723183f,0.499447f,-0.227382f,0.398807f,0.86411f,0.00148931f, 0.706223f,0.510251f,-0.2307f,0.38951f,0.862445f,0.00176138f,
0.687984f,0.519624f,-0.233554f,0.380051f,0.860693f,0.00208114f, 0.676321f,0.53343f,-0.236423f,0.371215f,0.858854f,0.00245634f,
0.649762f,0.535177f,-0.237802f,0.360669f,0.856926f,0.00289562f, 0.63677f,0.547017f,-0.239804f,0.351701f,0.854915f,0.00340884f,
0.610971f,0.547455f,-0.240277f,0.341133f,0.852836f,0.00400706f, 0.593075f,0.553834f,-0.241071f,0.331668f,0.850679f,0.00470256f,
0.572368f,0.55686f,-0.241189f,0.321885f,0.848447f,0.00550941f, 0.552218f,0.559493f,-0.24089f,0.31217f,0.84614f,0.00644261f,
0.534771f,0.56394f,-0.240429f,0.302853f,0.843765f,0.00751909f, 0.525005f,0.575695f,-0.240336f,0.294571f,0.841332f,0.00875738f,
0.500909f,0.571627f,-0.238469f,0.284705f,0.838852f,0.0101774f, 0.474454f,0.56325f,-0.235741f,0.274468f,0.83636f,0.0118011f,
0.46169f,0.569416f,-0.234225f,0.266259f,0.833878f,0.0136515f, 0.442866f,0.567453f,-0.231754f,0.257544f,0.831425f,0.0157537f,
0.4175f,0.555754f,-0.227855f,0.247861f,0.82903f,0.0181336f, 0.405288f,0.55964f,-0.225324f,0.240265f,0.826737f,0.0208194f,
0.387556f,0.554985f,-0.221866f,0.232252f,0.824595f,0.0238397f, 0.370091f,0.549178f,-0.218113f,0.224512f,0.82267f,0.0272246f,
0.353957f,0.543831f,-0.213906f,0.216897f,0.821062f,0.0310051f, 0.332853f,0.529218f,-0.208819f,0.208994f,0.81989f,0.0352133f,
0.315126f,0.517765f,-0.204116f,0.202062f,0.819251f,0.0398823f, 0.306867f,0.519721f,-0.200363f,0.196632f,0.819281f,0.0450465f,
0.286165f,0.499327f,-0.194313f,0.189516f,0.820145f,0.0507423f, 0.269728f,0.483745f,-0.188813f,0.183527f,0.822106f,0.0570082f,
0.262774f,0.482952f,-0.184524f,0.179287f,0.825435f,0.0638864f, 0.243817f,0.458616f,-0.178055f,0.173481f,0.830345f,0.071425f,
0.229294f,0.440093f,-0.172252f,0.168899f,0.837284f,0.0796768f, 0.22235f,0.433624f,-0.167342f,0.165743f,0.846614f,0.0887112f,
0.207149f,0.408771f,-0.161165f,0.161907f,0.858895f,0.0986023f, 0.198651f,0.394574f,-0.15531f,0.158935f,0.874626f,0.109444f,
0.184772f,0.369698f,-0.148456f,0.155464f,0.894596f,0.121357f, 0.177101f,0.354543f,-0.14248f,0.153428f,0.919802f,0.134501f,
0.164371f,0.327929f,-0.135711f,0.15106f,0.952255f,0.149154f, 0.156514f,0.309863f,-0.130052f,0.150305f,0.997924f,0.165667f,
0.999996f,-4.11644e-08f,-2.31293e-17f,0.579734f,0.870148f,3.4561e-05f, 0.999582f,0.0215794f,-0.0109739f,0.5795f,0.87012f,3.49124e-05f,
0.998317f,0.0431349f,-0.021958f,0.578795f,0.870045f,3.603e-05f, 0.996202f,0.0646078f,-0.0328604f,0.57763f,0.869926f,3.79115e-05f,
0.993249f,0.0859793f,-0.0437154f,0.576002f,0.869768f,4.06627e-05f, 0.989482f,0.107209f,-0.0544782f,0.57391f,0.86954f,4.42749e-05f,
0.984919f,0.128261f,-0.0651258f,0.571378f,0.869288f,4.89619e-05f, 0.979596f,0.149111f,-0.0756395f,0.568394f,0.868972f,5.47588e-05f,
0.973584f,0.169736f,-0.0860128f,0.564978f,0.868606f,6.19164e-05f, 0.966949f,0.190111f,-0.0961969f,0.561143f,0.868197f,7.05795e-05f,
0.959801f,0.210231f,-0.106197f,0.556896f,0.867738f,8.10655e-05f, 0.951653f,0.229975f,-0.115977f,0.552178f,0.867213f,9.36191e-05f,
0.943097f,0.24942f,-0.125555f,0.547242f,0.866647f,0.000108641f, 0.933504f,0.268392f,-0.134863f,0.541819f,0.866032f,0.000126604f,
0.923788f,0.287066f,-0.143903f,0.536002f,0.865353f,0.00014797f, 0.913497f,0.30528f,-0.152681f,0.529888f,0.864612f,0.000173392f,
0.903323f,0.323177f,-0.161183f,0.523524f,0.863828f,0.000203655f, 0.893348f,0.340785f,-0.16939f,0.516878f,0.862984f,0.000239582f,
0.882488f,0.357998f,-0.177237f,0.50979f,0.862075f,0.000282222f, 0.871431f,0.375101f,-0.184763f,0.502443f,0.861096f,0.000332803f,
0.861564f,0.392706f,-0.191991f,0.494972f,0.860067f,0.000392768f, 0.846191f,0.407574f,-0.198868f,0.487255f,0.858976f,0.000463807f,
0.831231f,0.422428f,-0.205151f,0.478754f,0.857817f,0.000547881f, 0.815277f,0.436398f,-0.211084f,0.470121f,0.856585f,0.000647298f,
0.800824f,0.450831f,-0.216713f,0.461484f,0.85528f,0.000764737f, 0.786424f,0.464955f,-0.221984f,0.452762f,0.853918f,0.00090331f,
0.77641f,0.481439f,-0.227115f,0.444394f,0.852486f,0.00106659f, 0.76152f,0.494618f,-0.231662f,0.435501f,0.850981f,0.00125876f,
0.736512f,0.500748f,-0.23516f,0.425313f,0.849399f,0.00148454f, 0.723482f,0.514206f,-0.238812f,0.416083f,0.847738f,0.00174941f,
0.700888f,0.520462f,-0.241517f,0.405878f,0.846007f,0.0020596f, 0.681972f,0.528608f,-0.244095f,0.396154f,0.844215f,0.00242215f,
0.674636f,0.545102f,-0.247057f,0.387666f,0.842352f,0.00284509f, 0.646096f,0.54446f,-0.248066f,0.376763f,0.840417f,0.00333742f,
0.627687f,0.551006f,-0.249194f,0.366729f,0.838414f,0.00390938f, 0.616873f,0.563564f,-0.250745f,0.357939f,0.836341f,0.00457199f,
0.593175f,0.564129f,-0.250748f,0.347574f,0.834211f,0.00533802f, 0.569813f,0.563785f,-0.250299f,0.33727f,0.832049f,0.00622147f,
0.553037f,0.568798f,-0.250031f,0.327864f,0.829852f,0.00723743f, 0.547028f,0.584069f,-0.250417f,0.319905f,0.827629f,0.00840265f,
0.522303f,0.579482f,-0.248654f,0.30981f,0.825396f,0.00973547f, 0.495291f,0.570813f,-0.246121f,0.299427f,0.823169f,0.0112553f,
0.482227f,0.576463f,-0.244644f,0.290965f,0.820974f,0.0129837f, 0.462696f,0.57371f,-0.242131f,0.28189f,0.818849f,0.0149429f,
0.439579f,0.564963f,-0.238847f,0.272566f,0.81685f,0.0171574f, 0.424579f,0.564999f,-0.236049f,0.264423f,0.815008f,0.0196523f,
0.406004f,0.559212f,-0.232427f,0.255971f,0.813374f,0.0224546f, 0.397455f,0.565603f,-0.2298f,0.249208f,0.812014f,0.0255924f,
0.371673f,0.54679f,-0.224612f,0.240275f,0.811005f,0.0290951f, 0.353718f,0.536913f,-0.220179f,0.232787f,0.810473f,0.0329934f,
0.345869f,0.540743f,-0.216985f,0.227212f,0.810553f,0.0373198f, 0.323024f,0.519809f,-0.210912f,0.219219f,0.811356f,0.0421084f,
0.306716f,0.506779f,-0.205839f,0.212868f,0.813035f,0.0473957f, 0.296096f,0.501203f,-0.201057f,0.207429f,0.815839f,0.0532211f,
0.278484f,0.482274f,-0.195188f,0.201467f,0.820018f,0.0596285f, 0.272164f,0.480335f,-0.191118f,0.197944f,0.825761f,0.0666672f,
0.252114f,0.453225f,-0.184114f,0.192001f,0.833558f,0.0743935f, 0.245451f,0.447323f,-0.179248f,0.188861f,0.843624f,0.082873f,
0.230061f,0.423461f,-0.172912f,0.184763f,0.856535f,0.0921883f, 0.221925f,0.411188f,-0.167022f,0.181731f,0.872833f,0.102435f,
0.205554f,0.382377f,-0.159925f,0.177941f,0.89316f,0.113732f, 0.196149f,0.364632f,-0.153523f,0.175485f,0.918782f,0.126254f,
0.186573f,0.345214f,-0.147127f,0.173603f,0.951457f,0.140296f, 0.179183f,0.328744f,-0.141695f,0.173341f,0.997854f,0.156274f,
1.0f,3.55629e-07f,-1.70217e-17f,0.608185f,0.854743f,3.64287e-05f, 0.99959f,0.0213744f,-0.0112593f,0.607952f,0.854729f,3.68396e-05f,
0.998348f,0.0427077f,-0.0224738f,0.607239f,0.854653f,3.7986e-05f, 0.996294f,0.0639783f,-0.0336727f,0.606058f,0.854529f,3.99625e-05f,
0.993442f,0.08514f,-0.0447762f,0.60441f,0.85436f,4.2789e-05f, 0.98982f,0.106176f,-0.0558086f,0.602302f,0.854142f,4.65852e-05f,
0.985314f,0.127026f,-0.0667167f,0.599712f,0.853866f,5.14008e-05f, 0.98005f,0.147673f,-0.077492f,0.596684f,0.853554f,5.74457e-05f,
0.97418f,0.168107f,-0.0881175f,0.593223f,0.853176f,6.48172e-05f, 0.967731f,0.188297f,-0.0985628f,0.589331f,0.852756f,7.37787e-05f,
0.960763f,0.20823f,-0.10881f,0.585016f,0.852287f,8.45707e-05f, 0.953436f,0.227914f,-0.118856f,0.58033f,0.851755f,9.74723e-05f,
0.945464f,0.247261f,-0.128704f,0.575408f,0.851176f,0.000112899f, 0.93673f,0.266199f,-0.138272f,0.569975f,0.850549f,0.00013126f,
0.927794f,0.284816f,-0.147569f,0.564132f,0.849859f,0.000153061f, 0.918549f,0.30303f,-0.156614f,0.558034f,0.849109f,0.000178934f,
0.909741f,0.320979f,-0.165383f,0.55169f,0.848315f,0.000209627f, 0.900503f,0.338724f,-0.17382f,0.54493f,0.847461f,0.000245967f,
0.888899f,0.355636f,-0.18183f,0.537545f,0.846541f,0.00028896f, 0.877189f,0.372368f,-0.189505f,0.529903f,0.845562f,0.000339793f,
0.865569f,0.388906f,-0.196984f,0.522442f,0.844531f,0.000399843f, 0.852292f,0.404566f,-0.204021f,0.514494f,0.843437f,0.000470742f,
0.839188f,0.420134f,-0.210631f,0.506162f,0.842276f,0.000554355f, 0.82533f,0.435011f,-0.216907f,0.497724f,0.841047f,0.000652869f,
0.811783f,0.449775f,-0.222779f,0.489075f,0.839765f,0.000768822f, 0.798345f,0.464319f,-0.228303f,0.48035f,0.838421f,0.000905136f,
0.781033f,0.476166f,-0.233233f,0.471066f,0.837007f,0.00106517f, 0.76407f,0.487753f,-0.237777f,0.4617f,0.835524f,0.00125279f,
0.747929f,0.499354f,-0.241852f,0.452122f,0.833977f,0.0014725f, 0.731605f,0.510358f,-0.245624f,0.442685f,0.832376f,0.00172928f,
0.716155f,0.521454f,-0.248975f,0.43317f,0.830715f,0.0020289f, 0.698751f,0.53063f,-0.251902f,0.423589f,0.828991f,0.00237793f,
0.67902f,0.537459f,-0.254039f,0.413366f,0.827204f,0.00278362f, 0.661583f,0.545354f,-0.255953f,0.403469f,0.825359f,0.00325433f,
0.648514f,0.556205f,-0.257692f,0.393977f,0.823477f,0.00379934f, 0.643348f,0.573205f,-0.261506f,0.388207f,0.821557f,0.00442877f,
0.614414f,0.569623f,-0.259726f,0.374788f,0.819604f,0.00515435f, 0.58863f,0.567109f,-0.259147f,0.363899f,0.817623f,0.00598846f,
0.57242f,0.572513f,-0.25908f,0.354416f,0.815627f,0.0069451f, 0.567304f,0.58816f,-0.259699f,0.346483f,0.813629f,0.00803951f,
0.54204f,0.583195f,-0.25805f,0.336176f,0.81167f,0.00928814f, 0.514961f,0.574552f,-0.255536f,0.325455f,0.809763f,0.010709f,
0.500849f,0.578709f,-0.254091f,0.316769f,0.80793f,0.0123213f, 0.489247f,0.584837f,-0.25273f,0.308802f,0.806202f,0.0141459f,
0.475009f,0.587284f,-0.250613f,0.300527f,0.804617f,0.0162048f, 0.44549f,0.569786f,-0.246089f,0.290036f,0.803229f,0.0185217f,
0.439184f,0.579558f,-0.244169f,0.28328f,0.802121f,0.0211216f, 0.420002f,0.571959f,-0.240441f,0.275047f,0.801346f,0.0240308f,
0.394032f,0.553384f,-0.235534f,0.266117f,0.800975f,0.0272774f, 0.384087f,0.555002f,-0.232114f,0.259499f,0.801101f,0.030891f,
0.362083f,0.537932f,-0.226862f,0.251481f,0.801874f,0.034903f, 0.356308f,0.542898f,-0.223534f,0.24623f,0.803437f,0.0393474f,
0.333207f,0.520337f,-0.217561f,0.238682f,0.805912f,0.0442605f, 0.316011f,0.504563f,-0.212083f,0.232315f,0.80951f,0.0496826f,
0.304868f,0.496482f,-0.207013f,0.22703f,0.814499f,0.0556579f, 0.298514f,0.494574f,-0.202699f,0.223191f,0.821054f,0.0622369f,
0.279906f,0.471405f,-0.196555f,0.217981f,0.829599f,0.0694777f, 0.272666f,0.464131f,-0.191471f,0.214574f,0.840413f,0.0774475f,
0.252807f,0.43402f,-0.184318f,0.20946f,0.853944f,0.0862266f, 0.24423f,0.421451f,-0.178356f,0.206307f,0.870766f,0.0959159f,
0.229197f,0.396355f,-0.171295f,0.202483f,0.891587f,0.106643f, 0.220552f,0.380853f,-0.165306f,0.200542f,0.917434f,0.118585f,
0.210835f,0.362288f,-0.158676f,0.198478f,0.950464f,0.132047f, 0.199081f,0.338688f,-0.152825f,0.197925f,0.997777f,0.147532f,
0.999997f,-4.30399e-07f,-4.78778e-17f,0.636588f,0.838358f,3.82686e-05f, 0.999603f,0.021118f,-0.0114636f,0.636345f,0.838325f,3.86419e-05f,
0.998394f,0.0422111f,-0.0229248f,0.635628f,0.838251f,3.98469e-05f, 0.996372f,0.0632225f,-0.0343163f,0.634439f,0.838129f,4.18782e-05f,
0.993537f,0.0841444f,-0.0456591f,0.632768f,0.837952f,4.48083e-05f, 0.989933f,0.104922f,-0.0568938f,0.630646f,0.837734f,4.871e-05f,
0.985598f,0.125536f,-0.0680243f,0.628056f,0.837459f,5.36903e-05f, 0.980595f,0.145962f,-0.07902f,0.62502f,0.837137f,5.9896e-05f,
0.975011f,0.166174f,-0.089854f,0.621552f,0.836765f,6.74766e-05f, 0.96896f,0.186173f,-0.100527f,0.617661f,0.836336f,7.66738e-05f,
0.962545f,0.205941f,-0.110994f,0.61336f,0.835864f,8.77152e-05f, 0.957571f,0.22581f,-0.121226f,0.608541f,0.835336f,0.000100901f,
0.948676f,0.244713f,-0.131334f,0.603796f,0.834751f,0.000116622f, 0.940851f,0.26358f,-0.141132f,0.598403f,0.834122f,0.000135291f,
0.931879f,0.281906f,-0.150621f,0.592458f,0.833436f,0.000157404f, 0.922338f,0.299758f,-0.159852f,0.586241f,0.832689f,0.000183571f,
0.913717f,0.317495f,-0.168814f,0.579811f,0.831894f,0.000214508f, 0.904543f,0.334995f,-0.177423f,0.572918f,0.831047f,0.000251047f,
0.894863f,0.352303f,-0.185689f,0.565655f,0.830137f,0.000294145f, 0.885116f,0.369569f,-0.193636f,0.558167f,0.829169f,0.000344937f,
0.873977f,0.386155f,-0.201334f,0.550708f,0.828152f,0.00040475f, 0.86182f,0.402159f,-0.208639f,0.542885f,0.827076f,0.000475117f,
0.858139f,0.42229f,-0.215786f,0.535327f,0.825937f,0.000557829f, 0.835272f,0.432424f,-0.221857f,0.525846f,0.82474f,0.000654944f,
0.820972f,0.446566f,-0.227794f,0.51685f,0.823494f,0.000768852f, 0.815071f,0.465105f,-0.233833f,0.508783f,0.822189f,0.000902299f,
0.793159f,0.474161f,-0.238847f,0.499186f,0.820823f,0.00105845f, 0.777923f,0.486612f,-0.243717f,0.490016f,0.819397f,0.0012409f,
0.762434f,0.498478f,-0.248019f,0.480447f,0.817926f,0.00145373f, 0.74616f,0.509313f,-0.251902f,0.470794f,0.816405f,0.00170169f,
0.730578f,0.520126f,-0.255349f,0.461041f,0.814832f,0.00199005f, 0.712864f,0.528863f,-0.258358f,0.451209f,0.813207f,0.0023248f,
0.695141f,0.536981f,-0.260891f,0.441263f,0.81154f,0.00271271f, 0.678986f,0.545672f,-0.263103f,0.431498f,0.809845f,0.00316125f,
0.667469f,0.557499f,-0.265224f,0.422263f,0.808124f,0.00367912f, 0.656852f,0.569718f,-0.266996f,0.41313f,0.806379f,0.00427556f,
0.633419f,0.571432f,-0.26776f,0.403117f,0.804615f,0.00496091f, 0.608887f,0.569406f,-0.267329f,0.392035f,0.802851f,0.00574682f,
0.592525f,0.574501f,-0.267345f,0.382347f,0.801115f,0.00664589f, 0.584792f,0.587207f,-0.267705f,0.373815f,0.799415f,0.00767201f,
0.559325f,0.581843f,-0.26628f,0.363468f,0.797768f,0.00884014f, 0.537584f,0.578823f,-0.264737f,0.353664f,0.796197f,0.0101669f,
0.521569f,0.580743f,-0.263179f,0.344524f,0.794728f,0.0116696f, 0.518005f,0.596009f,-0.262795f,0.33757f,0.793423f,0.0133676f,
0.491386f,0.583505f,-0.259254f,0.327228f,0.792315f,0.0152813f, 0.468199f,0.573806f,-0.255951f,0.317894f,0.791442f,0.0174324f,
0.455713f,0.575485f,-0.253357f,0.310103f,0.790861f,0.0198447f, 0.452689f,0.587883f,-0.251677f,0.304065f,0.790649f,0.0225428f,
0.427059f,0.570755f,-0.246917f,0.294979f,0.790915f,0.0255535f, 0.403336f,0.553907f,-0.242028f,0.286422f,0.791729f,0.0289055f,
0.394808f,0.555774f,-0.238593f,0.280235f,0.793188f,0.0326293f, 0.372648f,0.537331f,-0.233265f,0.272504f,0.795473f,0.0367582f,
0.365792f,0.538853f,-0.229484f,0.267236f,0.79872f,0.0413285f, 0.343038f,0.515724f,-0.223335f,0.259858f,0.803074f,0.0463803f,
0.335149f,0.512753f,-0.218829f,0.255071f,0.808833f,0.0519586f, 0.314978f,0.489536f,-0.212747f,0.249088f,0.81615f,0.0581144f,
0.305574f,0.480886f,-0.207492f,0.244735f,0.825392f,0.0649063f, 0.298669f,0.474962f,-0.202804f,0.241732f,0.836887f,0.0724036f,
0.279614f,0.447748f,-0.195869f,0.236708f,0.851034f,0.0806882f, 0.270278f,0.434722f,-0.189794f,0.233365f,0.868361f,0.089862f,
0.261389f,0.420663f,-0.183552f,0.230497f,0.889601f,0.100055f, 0.243213f,0.390455f,-0.176352f,0.227077f,0.915889f,0.111457f,
0.233686f,0.372965f,-0.169716f,0.225082f,0.949359f,0.124376f, 0.226198f,0.357241f,-0.164549f,0.225688f,0.997692f,0.139397f,
0.999999f,-1.20439e-07f,-1.45072e-17f,0.66481f,0.820992f,3.9958e-05f, 0.999602f,0.0208247f,-0.0116407f,0.664565f,0.820945f,4.03186e-05f,
0.998409f,0.0416156f,-0.0232492f,0.663856f,0.820883f,4.15743e-05f, 0.99642f,0.0623395f,-0.0348194f,0.662662f,0.82075f,4.36435e-05f,
0.993672f,0.0829652f,-0.0463179f,0.661013f,0.820588f,4.66711e-05f, 0.990198f,0.103459f,-0.0577273f,0.658891f,0.820362f,5.06585e-05f,
0.986065f,0.123798f,-0.0690237f,0.656318f,0.820095f,5.57721e-05f, 0.981369f,0.143962f,-0.0801864f,0.653303f,0.819776f,6.21168e-05f,
0.976224f,0.163941f,-0.0911983f,0.649858f,0.819402f,6.98578e-05f, 0.97072f,0.183721f,-0.102034f,0.645997f,0.818988f,7.92395e-05f,
0.963981f,0.203144f,-0.112663f,0.641604f,0.818514f,9.04739e-05f, 0.957536f,0.22241f,-0.123114f,0.637049f,0.817994f,0.000103868f,
0.950598f,0.241373f,-0.133332f,0.632061f,0.817424f,0.000119787f, 0.943031f,0.259959f,-0.143314f,0.626698f,0.816797f,0.000138659f,
0.938351f,0.278788f,-0.152936f,0.620609f,0.816127f,0.000160961f, 0.928061f,0.296153f,-0.162483f,0.614976f,0.815402f,0.000187277f,
0.920442f,0.313898f,-0.171608f,0.608473f,0.814618f,0.000218295f, 0.91221f,0.331539f,-0.180378f,0.601526f,0.813792f,0.000254817f,
0.903212f,0.348915f,-0.188828f,0.594298f,0.812911f,0.000297769f, 0.893453f,0.365997f,-0.196935f,0.586757f,0.811971f,0.000348241f,
0.883751f,0.383017f,-0.204805f,0.579285f,0.810985f,0.000407495f, 0.8694f,0.397724f,-0.212161f,0.57113f,0.80995f,0.000476985f,
0.857471f,0.4133f,-0.219245f,0.562999f,0.808859f,0.000558401f, 0.845231f,0.428546f,-0.225873f,0.554447f,0.807712f,0.000653688f,
0.832636f,0.443316f,-0.232102f,0.5457f,0.806524f,0.000765084f, 0.820198f,0.457844f,-0.238028f,0.536989f,0.805287f,0.000895155f,
0.806582f,0.471411f,-0.243605f,0.528217f,0.803997f,0.00104682f, 0.790246f,0.482945f,-0.248479f,0.518662f,0.802659f,0.00122348f,
0.775623f,0.495054f,-0.252964f,0.509081f,0.801287f,0.00142891f, 0.76011f,0.506117f,-0.257066f,0.499481f,0.799875f,0.00166744f,
0.746188f,0.517737f,-0.260826f,0.48995f,0.798423f,0.00194398f, 0.730249f,0.527551f,-0.264231f,0.480473f,0.796934f,0.00226402f,
0.713428f,0.536185f,-0.267045f,0.470666f,0.79543f,0.00263375f, 0.69616f,0.543831f,-0.269223f,0.46049f,0.793908f,0.00306006f,
0.682967f,0.553989f,-0.271382f,0.451003f,0.792376f,0.00355081f, 0.672245f,0.565764f,-0.273252f,0.441732f,0.790837f,0.00411445f,
0.647904f,0.565683f,-0.273883f,0.431184f,0.789309f,0.00476059f, 0.628658f,0.568841f,-0.274391f,0.421203f,0.787818f,0.00549965f,
0.612778f,0.574113f,-0.274588f,0.411468f,0.786369f,0.00634322f, 0.607583f,0.588593f,-0.275443f,0.403393f,0.784979f,0.0073039f,
0.578133f,0.579593f,-0.273995f,0.392643f,0.783666f,0.00839547f, 0.560422f,0.580584f,-0.272997f,0.383282f,0.782473f,0.00963304f,
0.543511f,0.581267f,-0.271337f,0.373712f,0.781434f,0.0110327f, 0.532398f,0.587155f,-0.270097f,0.365413f,0.780574f,0.0126123f,
0.519976f,0.590882f,-0.268604f,0.357437f,0.779933f,0.0143905f, 0.507573f,0.595287f,-0.267794f,0.351023f,0.779566f,0.0163879f,
0.478634f,0.576451f,-0.262606f,0.339594f,0.779557f,0.0186266f, 0.466978f,0.577847f,-0.259621f,0.331742f,0.779951f,0.02113f,
0.446787f,0.567381f,-0.255774f,0.323469f,0.780818f,0.0239237f, 0.442637f,0.575831f,-0.253399f,0.317754f,0.782288f,0.0270352f,
0.414166f,0.551828f,-0.247905f,0.308819f,0.78446f,0.0304943f, 0.403948f,0.549889f,-0.244117f,0.302686f,0.787427f,0.0343337f,
0.384397f,0.533714f,-0.238975f,0.295593f,0.791409f,0.0385895f, 0.373637f,0.528083f,-0.234405f,0.28987f,0.7965f,0.0433014f,
0.366797f,0.526492f,-0.230114f,0.285212f,0.802983f,0.0485146f, 0.342993f,0.499414f,-0.223564f,0.278422f,0.811015f,0.0542803f,
0.335135f,0.493594f,-0.21882f,0.274573f,0.820922f,0.0606576f, 0.327637f,0.486623f,-0.213924f,0.271262f,0.833048f,0.0677163f,
0.305701f,0.456417f,-0.206754f,0.265753f,0.847761f,0.0755405f, 0.295124f,0.44182f,-0.200397f,0.261983f,0.865634f,0.0842329f,
0.280165f,0.419455f,-0.193539f,0.258243f,0.887387f,0.0939303f, 0.271013f,0.404597f,-0.187497f,0.256336f,0.91418f,0.104824f,
0.260864f,0.387016f,-0.180869f,0.254434f,0.948251f,0.117244f, 0.251633f,0.369102f,-0.175798f,0.255479f,0.9976f,0.131829f,
1.00001f,9.36165e-07f,4.11925e-17f,0.692752f,0.80269f,4.14761e-05f, 0.99961f,0.0204832f,-0.011749f,0.692511f,0.80266f,4.18812e-05f,
0.998439f,0.0409294f,-0.0234671f,0.691804f,0.802591f,4.31452e-05f, 0.996536f,0.0613121f,-0.0351448f,0.690628f,0.802466f,4.52697e-05f,
0.993909f,0.081606f,-0.0467564f,0.688993f,0.802305f,4.8352e-05f, 0.990441f,0.101757f,-0.0582757f,0.686871f,0.802085f,5.2421e-05f,
0.986387f,0.121765f,-0.0696814f,0.684309f,0.801827f,5.76265e-05f, 0.981844f,0.141604f,-0.0809645f,0.681325f,0.801513f,6.40793e-05f,
0.976863f,0.161246f,-0.092086f,0.67792f,0.801157f,7.19485e-05f, 0.971539f,0.180693f,-0.103046f,0.674093f,0.800746f,8.14429e-05f,
0.966005f,0.19993f,-0.113809f,0.669858f,0.800295f,9.28216e-05f, 0.960486f,0.218986f,-0.1244f,0.665412f,0.799792f,0.000106351f,
0.954344f,0.23771f,-0.134765f,0.660546f,0.799237f,0.000122385f, 0.94778f,0.256066f,-0.144882f,0.655291f,0.79864f,0.00014134f,
0.949718f,0.275365f,-0.154789f,0.649837f,0.797989f,0.0001637f, 0.934904f,0.291906f,-0.164355f,0.643769f,0.797294f,0.000190024f,
0.926227f,0.309209f,-0.173532f,0.637011f,0.796552f,0.000220964f, 0.918145f,0.326671f,-0.18234f,0.629733f,0.795755f,0.000257286f,
0.908602f,0.343486f,-0.190949f,0.622631f,0.794918f,0.000299885f, 0.899233f,0.360358f,-0.199193f,0.61515f,0.794033f,0.000349787f,
0.894461f,0.379158f,-0.207287f,0.607965f,0.793095f,0.000408193f, 0.87896f,0.392936f,-0.214896f,0.600142f,0.792117f,0.000476481f,
0.867947f,0.408626f,-0.222143f,0.592093f,0.791097f,0.00055624f, 0.857018f,0.424172f,-0.22896f,0.583671f,0.790028f,0.000649298f,
0.843565f,0.438196f,-0.235225f,0.574646f,0.788917f,0.000757748f, 0.829965f,0.451761f,-0.241149f,0.565612f,0.787773f,0.000883991f,
0.817033f,0.465318f,-0.246911f,0.556965f,0.78659f,0.00103076f, 0.803457f,0.478133f,-0.25222f,0.548039f,0.785366f,0.00120114f,
0.790534f,0.490974f,-0.257022f,0.538788f,0.784118f,0.0013987f, 0.77623f,0.502567f,-0.261417f,0.529454f,0.782846f,0.00162739f,
0.760618f,0.512855f,-0.265107f,0.519465f,0.781549f,0.00189172f, 0.74547f,0.522852f,-0.268748f,0.51014f,0.780231f,0.00219679f,
0.728566f,0.531134f,-0.271689f,0.500258f,0.778912f,0.00254818f, 0.713675f,0.540206f,-0.274328f,0.490586f,0.777596f,0.00295239f,
0.699519f,0.549315f,-0.276591f,0.480985f,0.776286f,0.00341633f, 0.684732f,0.557372f,-0.278328f,0.471209f,0.774991f,0.00394793f,
0.66643f,0.561917f,-0.279648f,0.461486f,0.773736f,0.00455586f, 0.671711f,0.582999f,-0.283947f,0.457296f,0.772536f,0.00524975f,
0.634733f,0.572801f,-0.281104f,0.442336f,0.771402f,0.00604012f, 0.62026f,0.578346f,-0.28119f,0.432838f,0.77035f,0.00693851f,
0.615508f,0.592154f,-0.281766f,0.424806f,0.769415f,0.00795754f, 0.588783f,0.584783f,-0.280303f,0.414439f,0.768632f,0.00911118f,
0.56778f,0.581432f,-0.278919f,0.40494f,0.768021f,0.0104143f, 0.553203f,0.583456f,-0.277547f,0.396179f,0.767614f,0.0118831f,
0.544725f,0.590918f,-0.276351f,0.388387f,0.767473f,0.0135354f, 0.531385f,0.592438f,-0.274497f,0.380381f,0.767652f,0.0153903f,
0.51534f,0.589998f,-0.271891f,0.372038f,0.768192f,0.0174685f, 0.487932f,0.573314f,-0.267841f,0.362454f,0.769163f,0.0197925f,
0.476669f,0.573421f,-0.265009f,0.355268f,0.770675f,0.0223865f, 0.47441f,0.584125f,-0.263753f,0.35087f,0.772784f,0.025277f,
0.450859f,0.566591f,-0.258106f,0.341349f,0.775611f,0.0284932f, 0.430415f,0.552242f,-0.253665f,0.334166f,0.779293f,0.032067f,
0.41358f,0.540203f,-0.248765f,0.327091f,0.783941f,0.0360338f, 0.404742f,0.537426f,-0.244597f,0.32171f,0.78976f,0.0404331f,
0.384283f,0.517345f,-0.23897f,0.315135f,0.796916f,0.04531f, 0.372845f,0.508028f,-0.233908f,0.310016f,0.805627f,0.0507157f,
0.365452f,0.502945f,-0.229271f,0.306199f,0.816181f,0.0567095f, 0.346615f,0.480467f,-0.22315f,0.301148f,0.828906f,0.0633618f,
0.334951f,0.466258f,-0.217151f,0.297007f,0.844219f,0.0707574f, 0.32275f,0.450063f,-0.210675f,0.292945f,0.862635f,0.0790023f,
0.313271f,0.436698f,-0.204544f,0.290134f,0.884872f,0.0882337f, 0.303477f,0.420054f,-0.198149f,0.287763f,0.912176f,0.098652f,
0.287289f,0.396274f,-0.191576f,0.28602f,0.946978f,0.110606f, 0.278097f,0.378891f,-0.186771f,0.287788f,0.997501f,0.12479f,
0.999993f,5.06691e-07f,-4.40938e-17f,0.720327f,0.783539f,4.28626e-05f, 0.999618f,0.0200854f,-0.0117966f,0.720098f,0.78351f,4.3274e-05f,
0.998471f,0.0401383f,-0.023568f,0.719403f,0.783445f,4.45594e-05f, 0.996564f,0.0601253f,-0.0352934f,0.718248f,0.783327f,4.67187e-05f,
0.993916f,0.0800207f,-0.0469596f,0.716632f,0.783171f,4.98426e-05f, 0.990662f,0.0997925f,-0.0585336f,0.714581f,0.782966f,5.39777e-05f,
0.986839f,0.119421f,-0.0699988f,0.712076f,0.782714f,5.92364e-05f, 0.982608f,0.138888f,-0.0813402f,0.709159f,0.782421f,6.5771e-05f,
0.978076f,0.15818f,-0.0925332f,0.705836f,0.782081f,7.37229e-05f, 0.973342f,0.17729f,-0.103561f,0.702104f,0.781693f,8.32925e-05f,
0.96853f,0.196226f,-0.114401f,0.69798f,0.781264f,9.47297e-05f, 0.963975f,0.21499f,-0.125088f,0.693704f,0.780786f,0.000108323f,
0.956798f,0.233132f,-0.135495f,0.688751f,0.78027f,0.0001244f, 0.950827f,0.251126f,-0.145706f,0.683605f,0.779702f,0.00014335f,
0.953727f,0.269884f,-0.155442f,0.677155f,0.779095f,0.000165644f, 0.93793f,0.286086f,-0.165307f,0.672093f,0.778443f,0.000191823f,
0.931285f,0.30345f,-0.174616f,0.665543f,0.777744f,0.000222515f, 0.924516f,0.320907f,-0.183605f,0.658662f,0.777009f,0.000258456f,
0.916045f,0.337754f,-0.19231f,0.651597f,0.776229f,0.000300487f, 0.908427f,0.354916f,-0.200714f,0.64434f,0.775406f,0.000349591f,
0.90087f,0.37212f,-0.208772f,0.636817f,0.77455f,0.000406896f, 0.887947f,0.386697f,-0.216542f,0.629211f,0.773651f,0.000473708f,
0.895056f,0.411421f,-0.225069f,0.624456f,0.772714f,0.000551512f, 0.86555f,0.416853f,-0.23074f,0.61262f,0.771749f,0.000642014f,
0.854912f,0.431849f,-0.237321f,0.604152f,0.770748f,0.000747181f, 0.849399f,0.449424f,-0.243681f,0.595908f,0.769713f,0.000869213f,
0.830917f,0.459589f,-0.249469f,0.587068f,0.768661f,0.0010107f, 0.816205f,0.471381f,-0.254739f,0.577811f,0.767584f,0.00117448f,
0.803941f,0.484199f,-0.259713f,0.568675f,0.766483f,0.00136382f, 0.804809f,0.503041f,-0.265658f,0.562373f,0.765376f,0.00158238f,
0.776661f,0.506948f,-0.268324f,0.549926f,0.764265f,0.00183434f, 0.774038f,0.524661f,-0.272565f,0.54155f,0.763149f,0.0021243f,
0.752761f,0.530106f,-0.275666f,0.531667f,0.762039f,0.00245747f, 0.739701f,0.54031f,-0.278567f,0.522199f,0.760957f,0.00283978f,
0.718378f,0.543957f,-0.280665f,0.512017f,0.759901f,0.00327753f, 0.712738f,0.558644f,-0.283212f,0.503407f,0.758881f,0.00377796f,
0.701236f,0.568536f,-0.285036f,0.494253f,0.75792f,0.00434906f, 0.675893f,0.56679f,-0.285715f,0.483902f,0.757038f,0.00499956f,
0.655243f,0.567714f,-0.286135f,0.473904f,0.756246f,0.00573919f, 0.640174f,0.572382f,-0.28635f,0.464332f,0.75556f,0.00657852f,
0.632759f,0.582968f,-0.286856f,0.455992f,0.755025f,0.00752922f, 0.608542f,0.577978f,-0.286166f,0.446499f,0.754661f,0.00860393f,
0.600406f,0.58672f,-0.285837f,0.438304f,0.754494f,0.00981666f, 0.577679f,0.580724f,-0.284114f,0.428722f,0.754567f,0.0111825f,
0.562373f,0.580792f,-0.282331f,0.419832f,0.75494f,0.0127179f, 0.553519f,0.586593f,-0.280812f,0.412066f,0.755644f,0.0144409f,
0.531537f,0.577561f,-0.278156f,0.40337f,0.756739f,0.0163709f, 0.523267f,0.581033f,-0.276074f,0.396271f,0.758317f,0.0185295f,
0.499648f,0.568604f,-0.272453f,0.387692f,0.760423f,0.0209396f, 0.48771f,0.566787f,-0.269411f,0.380699f,0.763169f,0.0236272f,
0.479082f,0.567705f,-0.26635f,0.374419f,0.766653f,0.0266201f, 0.457561f,0.552149f,-0.261942f,0.366991f,0.770986f,0.0299498f,
0.451389f,0.553697f,-0.258409f,0.361538f,0.776313f,0.0336509f, 0.439449f,0.545011f,-0.25408f,0.355741f,0.7828f,0.0377625f,
0.415502f,0.523739f,-0.248447f,0.348861f,0.790608f,0.0423293f, 0.402607f,0.512921f,-0.243243f,0.343339f,0.79997f,0.0474025f,
0.3948f,0.507526f,-0.238588f,0.339372f,0.811156f,0.0530416f, 0.386689f,0.50026f,-0.233686f,0.33586f,0.824489f,0.059317f,
0.363912f,0.472082f,-0.22683f,0.33032f,0.840374f,0.0663145f, 0.351554f,0.456572f,-0.220551f,0.326378f,0.859274f,0.0741413f,
0.341925f,0.443639f,-0.21451f,0.323645f,0.882088f,0.0829397f, 0.332139f,0.429394f,-0.208371f,0.321651f,0.909935f,0.0929133f,
0.32212f,0.413408f,-0.202086f,0.320456f,0.945548f,0.104428f, 0.31616f,0.400713f,-0.197781f,0.323408f,0.997395f,0.118244f,
1.0f,3.57623e-07f,1.01405e-17f,0.747445f,0.763609f,4.40974e-05f, 0.999618f,0.0196333f,-0.0117814f,0.747207f,0.763571f,4.44887e-05f,
0.998473f,0.039235f,-0.023543f,0.746541f,0.763517f,4.58032e-05f, 0.996631f,0.0587753f,-0.0352615f,0.74542f,0.763408f,4.79864e-05f,
0.994106f,0.0782274f,-0.0469134f,0.743857f,0.76326f,5.11276e-05f, 0.991032f,0.0975671f,-0.0584867f,0.741866f,0.763072f,5.53085e-05f,
0.987534f,0.116771f,-0.0699527f,0.739444f,0.762839f,6.06097e-05f, 0.983437f,0.135796f,-0.0812888f,0.736577f,0.762566f,6.71712e-05f,
0.978836f,0.154622f,-0.092484f,0.733289f,0.762251f,7.5162e-05f, 0.974263f,0.173291f,-0.103517f,0.729627f,0.761896f,8.47691e-05f,
0.96967f,0.191774f,-0.114381f,0.72565f,0.761499f,9.62181e-05f, 0.965502f,0.210099f,-0.12509f,0.721525f,0.76106f,0.000109788f,
0.960742f,0.228083f,-0.135578f,0.716968f,0.760584f,0.000125808f, 0.955682f,0.245679f,-0.145861f,0.712122f,0.760065f,0.000144658f,
0.955495f,0.263989f,-0.15573f,0.706164f,0.759512f,0.000166787f, 0.94485f,0.280204f,-0.165561f,0.700853f,0.758914f,0.000192704f,
0.938698f,0.297386f,-0.1749f,0.694342f,0.758286f,0.000223013f, 0.93042f,0.314016f,-0.183877f,0.687292f,0.757619f,0.000258408f,
0.921513f,0.330281f,-0.192537f,0.679967f,0.756915f,0.000299693f, 0.914289f,0.347061f,-0.200983f,0.67279f,0.756182f,0.00034779f,
0.905674f,0.363173f,-0.209238f,0.665785f,0.755412f,0.000403767f, 0.895925f,0.378672f,-0.217089f,0.658326f,0.754615f,0.00046884f,
0.893062f,0.397384f,-0.224568f,0.650573f,0.753793f,0.000544413f, 0.876804f,0.409394f,-0.231649f,0.642478f,0.75294f,0.000632089f,
0.864824f,0.423248f,-0.238155f,0.633664f,0.752071f,0.000733689f, 0.855048f,0.437952f,-0.244527f,0.625339f,0.751183f,0.000851261f,
0.857596f,0.45905f,-0.250864f,0.617688f,0.750276f,0.000987172f, 0.843004f,0.470766f,-0.256451f,0.608989f,0.749364f,0.00114408f,
0.818189f,0.476129f,-0.261312f,0.599407f,0.748449f,0.001325f, 0.806549f,0.488487f,-0.266043f,0.590348f,0.747529f,0.0015333f,
0.794205f,0.500033f,-0.2705f,0.581491f,0.746622f,0.0017728f, 0.784796f,0.513109f,-0.274343f,0.572127f,0.745734f,0.00204776f,
0.765041f,0.519022f,-0.277767f,0.56269f,0.744868f,0.00236295f, 0.750543f,0.527592f,-0.28084f,0.553343f,0.744037f,0.00272378f,
0.736116f,0.535698f,-0.283369f,0.543746f,0.74326f,0.00313604f, 0.723185f,0.544377f,-0.285662f,0.534488f,0.742543f,0.0036064f,
0.70757f,0.550476f,-0.287317f,0.524821f,0.741896f,0.00414212f, 0.69263f,0.556394f,-0.288951f,0.515922f,0.741353f,0.00475126f,
0.687228f,0.569261f,-0.290507f,0.507638f,0.740925f,0.00544272f, 0.664372f,0.56746f,-0.290823f,0.497949f,0.740628f,0.00622624f,
0.650012f,0.571773f,-0.290984f,0.488798f,0.7405f,0.00711257f, 0.642492f,0.581211f,-0.291269f,0.480627f,0.740572f,0.00811349f,
0.616577f,0.573575f,-0.290023f,0.4707f,0.740864f,0.00924195f, 0.60804f,0.580734f,-0.289471f,0.46269f,0.741426f,0.010512f,
0.587044f,0.57519f,-0.287807f,0.453684f,0.742307f,0.011939f, 0.573745f,0.576101f,-0.286261f,0.445623f,0.74354f,0.01354f,
0.56039f,0.57605f,-0.284297f,0.437699f,0.745204f,0.0153333f, 0.557619f,0.585732f,-0.282892f,0.431387f,0.747354f,0.0173395f,
0.534524f,0.573681f,-0.279719f,0.423141f,0.750059f,0.0195806f, 0.525522f,0.575072f,-0.277263f,0.416768f,0.753427f,0.0220814f,
0.500999f,0.558159f,-0.273002f,0.408449f,0.757532f,0.024869f, 0.487974f,0.552825f,-0.269362f,0.401852f,0.762509f,0.0279741f,
0.477597f,0.54927f,-0.265525f,0.39575f,0.768486f,0.0314308f, 0.476713f,0.55805f,-0.265034f,0.395416f,0.7756f,0.0352773f,
0.448391f,0.52849f,-0.256693f,0.384162f,0.784045f,0.0395581f, 0.440735f,0.524757f,-0.25231f,0.379628f,0.794041f,0.0443239f,
0.428693f,0.512306f,-0.247861f,0.375822f,0.805835f,0.0496341f, 0.419603f,0.506252f,-0.242606f,0.371641f,0.819763f,0.0555598f,
0.395987f,0.478521f,-0.235833f,0.365943f,0.836205f,0.062187f, 0.3835f,0.463746f,-0.229669f,0.362037f,0.855713f,0.0696247f,
0.371732f,0.448607f,-0.223412f,0.358867f,0.87908f,0.0780177f, 0.362152f,0.435378f,-0.21773f,0.357603f,0.907619f,0.0875785f,
0.350291f,0.417964f,-0.211272f,0.356188f,0.94397f,0.0986777f, 0.34483f,0.405937f,-0.20762f,0.360664f,0.997283f,0.112155f,
1.0f,-8.19185e-07f,-4.51825e-17f,0.773993f,0.742966f,4.51329e-05f, 0.999631f,0.019127f,-0.011707f,0.773774f,0.742943f,4.55536e-05f,
0.998539f,0.0382197f,-0.0233872f,0.773124f,0.742885f,4.68516e-05f, 0.996694f,0.0572601f,-0.0350406f,0.772039f,0.74279f,4.90581e-05f,
0.994205f,0.0762066f,-0.0466182f,0.770532f,0.74266f,5.22172e-05f, 0.991187f,0.0950404f,-0.0581226f,0.768613f,0.742486f,5.6397e-05f,
0.987768f,0.113741f,-0.069525f,0.766282f,0.74228f,6.17202e-05f, 0.984093f,0.132285f,-0.0808124f,0.763561f,0.742035f,6.82936e-05f,
0.98023f,0.150662f,-0.0919596f,0.760447f,0.741753f,7.62747e-05f, 0.976299f,0.168876f,-0.102955f,0.756966f,0.741434f,8.58523e-05f,
0.972416f,0.186906f,-0.11378f,0.753115f,0.74108f,9.72565e-05f, 0.969076f,0.204766f,-0.124474f,0.749237f,0.740691f,0.000110755f,
0.965342f,0.222266f,-0.134964f,0.744966f,0.740268f,0.000126651f, 0.959752f,0.239248f,-0.145185f,0.74005f,0.739809f,0.000145311f,
0.953828f,0.255992f,-0.155116f,0.73457f,0.739321f,0.000167161f, 0.947387f,0.272526f,-0.164789f,0.728746f,0.738796f,0.000192693f,
0.941626f,0.289187f,-0.174119f,0.722349f,0.738247f,0.000222482f, 0.935512f,0.305816f,-0.183146f,0.715594f,0.737663f,0.000257184f,
0.928748f,0.32224f,-0.191879f,0.708638f,0.737057f,0.000297557f, 0.921934f,0.338678f,-0.200368f,0.701668f,0.736423f,0.000344474f,
0.914675f,0.354795f,-0.208736f,0.695106f,0.735765f,0.000398936f, 0.904493f,0.369623f,-0.216556f,0.687582f,0.73509f,0.000462083f,
0.895184f,0.384685f,-0.223978f,0.679651f,0.734392f,0.000535219f, 0.884934f,0.399022f,-0.231116f,0.67175f,0.733684f,0.000619838f,
0.875566f,0.413589f,-0.237884f,0.663631f,0.732964f,0.000717627f, 0.866481f,0.428105f,-0.24436f,0.655526f,0.732233f,0.000830519f,
0.85605f,0.441633f,-0.25041f,0.647141f,0.731507f,0.000960684f, 0.844702f,0.45439f,-0.256244f,0.639016f,0.730781f,0.00111057f,
0.831014f,0.465413f,-0.261384f,0.629987f,0.73006f,0.00128295f, 0.82005f,0.477655f,-0.266277f,0.621224f,0.729362f,0.00148096f,
0.807444f,0.488517f,-0.270782f,0.612379f,0.728684f,0.00170809f, 0.79524f,0.499242f,-0.274802f,0.603257f,0.728035f,0.00196822f,
0.791955f,0.515112f,-0.278874f,0.595073f,0.727436f,0.00226583f, 0.770688f,0.519143f,-0.282067f,0.585807f,0.726888f,0.00260575f,
0.756447f,0.527003f,-0.284873f,0.576556f,0.726402f,0.00299341f, 0.742365f,0.53449f,-0.287339f,0.567455f,0.726004f,0.00343484f,
0.730165f,0.542724f,-0.289519f,0.558588f,0.7257f,0.00393679f, 0.717035f,0.549655f,-0.29132f,0.54978f,0.725506f,0.00450659f,
0.701738f,0.554266f,-0.292629f,0.540863f,0.725458f,0.00515254f, 0.694891f,0.564641f,-0.293746f,0.532376f,0.725566f,0.00588358f,
0.672526f,0.562469f,-0.293877f,0.522903f,0.725855f,0.00670962f, 0.658633f,0.566009f,-0.293858f,0.513997f,0.726371f,0.00764156f,
0.648098f,0.571781f,-0.29381f,0.505825f,0.727132f,0.00869151f, 0.641558f,0.580299f,-0.293691f,0.498309f,0.728181f,0.00987251f,
0.615233f,0.570182f,-0.292171f,0.489226f,0.729572f,0.0111992f, 0.612304f,0.58042f,-0.291501f,0.48234f,0.731335f,0.0126874f,
0.587042f,0.569166f,-0.289177f,0.47354f,0.733553f,0.0143547f, 0.573998f,0.568171f,-0.287107f,0.465941f,0.736263f,0.0162204f,
0.560899f,0.566153f,-0.284556f,0.458388f,0.739566f,0.0183058f, 0.557076f,0.572703f,-0.282616f,0.452592f,0.743517f,0.0206347f,
0.541498f,0.566295f,-0.279721f,0.446093f,0.748248f,0.0232335f, 0.528335f,0.5601f,-0.27648f,0.439836f,0.753836f,0.0261319f,
0.518014f,0.55721f,-0.273302f,0.434491f,0.76042f,0.0293632f, 0.491584f,0.535554f,-0.268061f,0.426707f,0.768169f,0.0329653f,
0.478016f,0.526089f,-0.263359f,0.420606f,0.77724f,0.0369819f, 0.469139f,0.521379f,-0.259152f,0.416132f,0.787839f,0.0414632f,
0.457555f,0.51135f,-0.254383f,0.411607f,0.800218f,0.0464689f, 0.448927f,0.503626f,-0.249585f,0.407947f,0.814733f,0.0520695f,
0.439612f,0.494961f,-0.244407f,0.404534f,0.831729f,0.0583523f, 0.415325f,0.467169f,-0.237764f,0.39964f,0.851834f,0.0654274f,
0.405f,0.454673f,-0.231852f,0.396916f,0.875802f,0.0734423f, 0.395444f,0.442174f,-0.226382f,0.39605f,0.905046f,0.0826134f,
0.384131f,0.426179f,-0.219905f,0.394641f,0.942248f,0.0933248f, 0.379974f,0.415697f,-0.216944f,0.400879f,0.997165f,0.106493f,
1.0f,-2.47858e-07f,-1.07662e-17f,0.799898f,0.72171f,4.59825e-05f, 0.999632f,0.0185565f,-0.0115652f,0.799696f,0.7217f,4.64288e-05f,
0.998525f,0.0370913f,-0.0231172f,0.79908f,0.721647f,4.77241e-05f, 0.996736f,0.0555596f,-0.0346184f,0.798059f,0.721566f,4.99264e-05f,
0.994361f,0.0739528f,-0.0460718f,0.796634f,0.721451f,5.30824e-05f, 0.991549f,0.0922364f,-0.0574489f,0.794813f,0.721304f,5.7266e-05f,
0.98846f,0.110381f,-0.0687269f,0.79261f,0.721126f,6.2568e-05f, 0.985215f,0.12839f,-0.079899f,0.790033f,0.720912f,6.91092e-05f,
0.981901f,0.146249f,-0.090936f,0.787084f,0.720672f,7.70512e-05f, 0.977382f,0.163823f,-0.101812f,0.783598f,0.720398f,8.65697e-05f,
0.973433f,0.181245f,-0.112535f,0.779905f,0.720098f,9.78774e-05f, 0.971818f,0.198688f,-0.12303f,0.775523f,0.719764f,0.000111226f,
0.966813f,0.215447f,-0.133565f,0.772254f,0.719406f,0.00012692f, 0.963053f,0.232027f,-0.143758f,0.767758f,0.719017f,0.000145304f,
0.958956f,0.248456f,-0.153653f,0.762584f,0.718607f,0.000166787f, 0.953991f,0.264773f,-0.163252f,0.75683f,0.718168f,0.000191834f,
0.948908f,0.281151f,-0.172538f,0.750603f,0.717711f,0.000220988f, 0.942562f,0.297262f,-0.181552f,0.744114f,0.717228f,0.000254868f,
0.935261f,0.312973f,-0.190201f,0.737104f,0.716731f,0.000294189f, 0.927536f,0.328473f,-0.19862f,0.730133f,0.716215f,0.000339774f,
0.927852f,0.347201f,-0.206762f,0.723057f,0.715686f,0.000392557f, 0.913016f,0.359269f,-0.214912f,0.71686f,0.715147f,0.000453607f,
0.904561f,0.3741f,-0.222391f,0.709257f,0.714596f,0.000524138f, 0.895987f,0.388597f,-0.229649f,0.701848f,0.714046f,0.000605539f,
0.887547f,0.403029f,-0.236505f,0.694056f,0.713493f,0.000699384f, 0.876331f,0.415872f,-0.242748f,0.685374f,0.712946f,0.000807436f,
0.867722f,0.429738f,-0.248938f,0.677433f,0.712411f,0.000931723f, 0.881123f,0.454866f,-0.257746f,0.677165f,0.711887f,0.00107452f,
0.855881f,0.459584f,-0.260368f,0.661499f,0.711392f,0.00123837f, 0.834901f,0.465709f,-0.265343f,0.6529f,0.710924f,0.00142615f,
0.824651f,0.477419f,-0.269999f,0.644359f,0.710493f,0.00164107f, 0.813564f,0.488245f,-0.274393f,0.636044f,0.710115f,0.00188674f,
0.800658f,0.497579f,-0.278004f,0.626749f,0.709791f,0.0021672f, 0.800302f,0.514364f,-0.281814f,0.618741f,0.709539f,0.00248694f,
0.777715f,0.516569f,-0.284805f,0.609767f,0.709373f,0.00285095f, 0.763635f,0.52368f,-0.28758f,0.601151f,0.7093f,0.00326476f,
0.749379f,0.530001f,-0.289776f,0.592169f,0.709348f,0.00373459f, 0.736857f,0.536994f,-0.291659f,0.583382f,0.709531f,0.00426724f,
0.722292f,0.541895f,-0.293048f,0.574425f,0.709863f,0.00487023f, 0.731957f,0.560044f,-0.297524f,0.572247f,0.710383f,0.00555191f,
0.698577f,0.553563f,-0.295304f,0.557989f,0.711104f,0.00632153f, 0.682702f,0.555177f,-0.295736f,0.549664f,0.712062f,0.00718923f,
0.670188f,0.558809f,-0.295776f,0.541438f,0.713295f,0.00816611f, 0.658175f,0.562187f,-0.295575f,0.533571f,0.714829f,0.00926469f,
0.651127f,0.569069f,-0.295183f,0.526191f,0.716727f,0.0104985f, 0.643303f,0.574573f,-0.29449f,0.519058f,0.719015f,0.0118825f,
0.615684f,0.561445f,-0.292475f,0.510451f,0.721774f,0.0134334f, 0.611884f,0.569179f,-0.291301f,0.504112f,0.72504f,0.0151696f,
0.588284f,0.557177f,-0.28863f,0.496035f,0.728914f,0.0171116f, 0.575051f,0.553959f,-0.285989f,0.488834f,0.733452f,0.0192824f,
0.562781f,0.550736f,-0.283274f,0.482342f,0.738759f,0.0217072f, 0.552551f,0.548461f,-0.280321f,0.476306f,0.744955f,0.0244151f,
0.546692f,0.549848f,-0.277348f,0.471076f,0.752148f,0.0274386f, 0.540746f,0.550101f,-0.274332f,0.466632f,0.760488f,0.0308151f,
0.515084f,0.528687f,-0.269546f,0.460049f,0.770153f,0.0345872f, 0.507755f,0.525491f,-0.265711f,0.455972f,0.781348f,0.0388054f,
0.495168f,0.515158f,-0.261249f,0.451716f,0.794312f,0.0435282f, 0.487702f,0.509186f,-0.25731f,0.449345f,0.809408f,0.0488269f,
0.461708f,0.482828f,-0.250394f,0.442691f,0.826992f,0.0547886f, 0.449477f,0.470052f,-0.244868f,0.439459f,0.847679f,0.0615252f,
0.437646f,0.456411f,-0.239001f,0.436685f,0.872336f,0.0691868f, 0.427765f,0.444245f,-0.233702f,0.436097f,0.902262f,0.0779953f,
0.415797f,0.428744f,-0.227905f,0.435987f,0.940413f,0.0883459f, 0.409499f,0.415708f,-0.225551f,0.444028f,0.997041f,0.101227f,
1.0f,4.31376e-07f,-6.97312e-17f,0.825092f,0.699955f,4.66878e-05f, 0.99964f,0.017936f,-0.0113657f,0.824901f,0.699937f,4.7105e-05f,
0.998592f,0.0358371f,-0.0227023f,0.824321f,0.699897f,4.8401e-05f, 0.996877f,0.0536958f,-0.034017f,0.823355f,0.69983f,5.05965e-05f,
0.994468f,0.0714656f,-0.0452699f,0.822f,0.699737f,5.37363e-05f, 0.991729f,0.0891291f,-0.0564498f,0.820277f,0.699616f,5.78887e-05f,
0.988821f,0.106668f,-0.0675483f,0.818218f,0.699468f,6.31485e-05f, 0.985715f,0.124054f,-0.0785354f,0.815775f,0.6993f,6.96452e-05f,
0.982515f,0.141279f,-0.089405f,0.812973f,0.699103f,7.75079e-05f, 0.979353f,0.158341f,-0.100137f,0.809868f,0.698883f,8.6914e-05f,
0.976356f,0.17521f,-0.110721f,0.806447f,0.69864f,9.80688e-05f, 0.973575f,0.191834f,-0.121137f,0.802687f,0.698374f,0.000111218f,
0.971739f,0.208167f,-0.131496f,0.799382f,0.698089f,0.000126647f, 0.968724f,0.224219f,-0.141562f,0.795096f,0.697783f,0.000144688f,
0.961998f,0.239828f,-0.151276f,0.789769f,0.69746f,0.000165724f, 0.957309f,0.255508f,-0.160765f,0.784224f,0.69712f,0.000190197f,
0.951952f,0.271123f,-0.169963f,0.778232f,0.696767f,0.000218615f, 0.946316f,0.286668f,-0.178884f,0.771931f,0.6964f,0.000251567f,
0.943514f,0.303282f,-0.187378f,0.764789f,0.696023f,0.000289721f, 0.934824f,0.317639f,-0.195878f,0.75862f,0.69564f,0.000333847f,
0.92906f,0.333069f,-0.203998f,0.751871f,0.695251f,0.00038482f, 0.922545f,0.348073f,-0.211992f,0.745549f,0.694864f,0.000443638f,
0.912929f,0.361672f,-0.219521f,0.738447f,0.694476f,0.000511428f, 0.903492f,0.375213f,-0.226532f,0.730546f,0.694099f,0.000589487f,
0.895162f,0.388867f,-0.233465f,0.723273f,0.69373f,0.000679274f, 0.886777f,0.402384f,-0.239951f,0.715516f,0.693381f,0.000782426f,
0.878699f,0.415824f,-0.246171f,0.707842f,0.693054f,0.000900808f, 0.878995f,0.433437f,-0.252172f,0.700386f,0.692753f,0.00103651f,
0.860283f,0.440768f,-0.25781f,0.692782f,0.692493f,0.00119188f, 0.87527f,0.466123f,-0.266266f,0.693305f,0.692271f,0.00136957f,
0.837603f,0.462163f,-0.2676f,0.676175f,0.692108f,0.00157257f, 0.827756f,0.473129f,-0.272009f,0.667932f,0.692006f,0.00180418f,
0.815152f,0.482099f,-0.275949f,0.659394f,0.691976f,0.00206807f, 0.805062f,0.49214f,-0.279649f,0.651151f,0.692037f,0.00236842f,
0.803971f,0.505746f,-0.283106f,0.643164f,0.692192f,0.00270981f, 0.782571f,0.509231f,-0.286041f,0.634849f,0.692468f,0.00309734f,
0.768414f,0.515104f,-0.288417f,0.626137f,0.692875f,0.00353674f, 0.756509f,0.521967f,-0.290619f,0.617893f,0.693431f,0.00403425f,
0.745494f,0.528901f,-0.292451f,0.609713f,0.694166f,0.00459694f, 0.740213f,0.53954f,-0.29413f,0.602027f,0.69509f,0.00523242f,
0.726411f,0.543433f,-0.295269f,0.594087f,0.696248f,0.00594937f, 0.708268f,0.543135f,-0.295936f,0.586016f,0.697653f,0.00675714f,
0.701361f,0.550988f,-0.296481f,0.578551f,0.699351f,0.00766629f, 0.683449f,0.549105f,-0.296392f,0.57068f,0.701372f,0.00868832f,
0.671538f,0.551504f,-0.296052f,0.563175f,0.703765f,0.00983616f, 0.658978f,0.552654f,-0.295261f,0.555647f,0.706572f,0.0111239f,
0.648681f,0.554777f,-0.294075f,0.548239f,0.709858f,0.0125675f, 0.639703f,0.557284f,-0.292842f,0.541573f,0.713669f,0.0141844f,
0.618676f,0.548275f,-0.291053f,0.534757f,0.718094f,0.0159942f, 0.606721f,0.546215f,-0.288843f,0.528017f,0.723201f,0.0180191f,
0.602576f,0.550752f,-0.28687f,0.522568f,0.729079f,0.0202836f, 0.579643f,0.536569f,-0.283528f,0.515501f,0.735841f,0.0228158f,
0.567667f,0.531615f,-0.280342f,0.50961f,0.743613f,0.0256475f, 0.556522f,0.526652f,-0.277107f,0.504526f,0.752535f,0.0288154f,
0.543431f,0.518811f,-0.27309f,0.498933f,0.762782f,0.0323616f, 0.533555f,0.513037f,-0.269465f,0.494995f,0.774566f,0.0363355f,
0.522509f,0.505189f,-0.26508f,0.49059f,0.788122f,0.0407959f, 0.513705f,0.498447f,-0.260613f,0.48704f,0.803797f,0.0458137f,
0.504352f,0.49026f,-0.255868f,0.48398f,0.821993f,0.0514766f, 0.493658f,0.478264f,-0.250443f,0.480706f,0.843322f,0.0578975f,
0.484268f,0.47018f,-0.245679f,0.479851f,0.868625f,0.0652293f, 0.465253f,0.448738f,-0.240335f,0.479202f,0.89942f,0.0736998f,
0.454693f,0.435402f,-0.234881f,0.479842f,0.938622f,0.0837189f, 0.451946f,0.425892f,-0.232833f,0.489211f,0.996912f,0.0963293f,
1.0f,-8.39712e-07f,1.31169e-18f,0.849502f,0.677779f,4.71913e-05f, 0.99964f,0.0172489f,-0.0110933f,0.849319f,0.67776f,4.7598e-05f,
0.998583f,0.0344791f,-0.0221796f,0.848786f,0.677732f,4.88886e-05f, 0.996887f,0.0516539f,-0.0332223f,0.847901f,0.677684f,5.10644e-05f,
0.994689f,0.0687523f,-0.0442199f,0.846659f,0.677611f,5.41673e-05f, 0.992157f,0.0857409f,-0.0551496f,0.845063f,0.677521f,5.82762e-05f,
0.989506f,0.102611f,-0.0659994f,0.843145f,0.677415f,6.34842e-05f, 0.986791f,0.119331f,-0.0767543f,0.840879f,0.677287f,6.98917e-05f,
0.98409f,0.135906f,-0.0873913f,0.838299f,0.677144f,7.76418e-05f, 0.980778f,0.152258f,-0.0978909f,0.835279f,0.676982f,8.68981e-05f,
0.977376f,0.168381f,-0.108241f,0.83192f,0.676806f,9.78604e-05f, 0.974289f,0.184298f,-0.118446f,0.828362f,0.676616f,0.000110762f,
0.975621f,0.200133f,-0.128448f,0.824276f,0.676411f,0.000125873f, 0.96963f,0.215328f,-0.138477f,0.821232f,0.676197f,0.000143504f,
0.966249f,0.230551f,-0.148122f,0.816687f,0.675971f,0.000164018f, 0.964947f,0.246314f,-0.157271f,0.81045f,0.67574f,0.000187835f,
0.957835f,0.260872f,-0.166516f,0.805655f,0.675499f,0.000215432f, 0.953253f,0.276045f,-0.175302f,0.799592f,0.67526f,0.000247364f,
0.946584f,0.290654f,-0.18378f,0.793086f,0.675015f,0.000284254f, 0.939348f,0.304919f,-0.191957f,0.786303f,0.674777f,0.000326825f,
0.934029f,0.31972f,-0.199971f,0.779787f,0.674542f,0.000375894f, 0.9316f,0.335701f,-0.207597f,0.77273f,0.674319f,0.000432391f,
0.928446f,0.351276f,-0.215163f,0.766343f,0.674107f,0.000497359f, 0.913908f,0.361735f,-0.222564f,0.76024f,0.673915f,0.000572005f,
0.912103f,0.378435f,-0.229356f,0.752923f,0.673745f,0.000657671f, 0.899019f,0.388378f,-0.236034f,0.746123f,0.673604f,0.000755879f,
0.888834f,0.400146f,-0.242021f,0.73804f,0.673499f,0.000868358f, 0.881134f,0.412797f,-0.247935f,0.730635f,0.673433f,0.000997027f,
0.883611f,0.429831f,-0.253496f,0.72308f,0.67342f,0.00114408f, 0.861873f,0.435197f,-0.258786f,0.715604f,0.67346f,0.00131193f,
0.875946f,0.460895f,-0.266472f,0.715415f,0.673572f,0.00150333f, 0.84299f,0.456553f,-0.268315f,0.700383f,0.673758f,0.00172133f,
0.833699f,0.466886f,-0.272514f,0.69258f,0.674034f,0.0019693f, 0.822533f,0.475629f,-0.276341f,0.684691f,0.674412f,0.00225113f,
0.811591f,0.484166f,-0.27966f,0.676412f,0.674903f,0.00257095f, 0.809428f,0.497759f,-0.282954f,0.668941f,0.675529f,0.0029336f,
0.790269f,0.500055f,-0.285807f,0.661258f,0.676298f,0.00334422f, 0.787389f,0.512484f,-0.288347f,0.653719f,0.677241f,0.00380875f,
0.771046f,0.515425f,-0.290371f,0.645841f,0.678367f,0.00433354f, 0.755451f,0.518111f,-0.291808f,0.637545f,0.679713f,0.00492586f,
0.744766f,0.523715f,-0.293154f,0.629898f,0.681293f,0.00559369f, 0.741631f,0.534512f,-0.294693f,0.623524f,0.68315f,0.00634578f,
0.725561f,0.534826f,-0.294924f,0.615214f,0.685302f,0.00719196f, 0.727518f,0.548286f,-0.29572f,0.608965f,0.687805f,0.00814318f,
0.698272f,0.537013f,-0.295175f,0.600791f,0.690684f,0.00921152f, 0.698594f,0.54818f,-0.295311f,0.594895f,0.694001f,0.0104104f,
0.673126f,0.538017f,-0.294136f,0.587211f,0.697798f,0.0117548f, 0.661113f,0.537539f,-0.292755f,0.579992f,0.702138f,0.0132616f,
0.649143f,0.536574f,-0.29124f,0.573419f,0.707103f,0.0149496f, 0.638737f,0.536193f,-0.289566f,0.567413f,0.712756f,0.0168399f,
0.634699f,0.540321f,-0.287736f,0.561988f,0.719191f,0.0189565f, 0.622957f,0.537034f,-0.285176f,0.556045f,0.726516f,0.0213265f,
0.600907f,0.523289f,-0.282693f,0.551176f,0.734853f,0.023981f, 0.588082f,0.516857f,-0.279247f,0.545365f,0.744346f,0.026956f,
0.580029f,0.51427f,-0.276136f,0.541154f,0.755161f,0.0302926f, 0.572682f,0.511352f,-0.272638f,0.537159f,0.767501f,0.0340402f,
0.553309f,0.495994f,-0.26868f,0.533282f,0.781651f,0.0382569f, 0.5422f,0.487339f,-0.264302f,0.529608f,0.797912f,0.0430131f,
0.53007f,0.477103f,-0.25964f,0.526444f,0.816728f,0.0483974f, 0.518928f,0.466904f,-0.254949f,0.524366f,0.838699f,0.0545234f,
0.507884f,0.455599f,-0.249885f,0.522798f,0.864737f,0.0615457f, 0.497893f,0.444808f,-0.245243f,0.523527f,0.896352f,0.0696981f,
0.4866f,0.431479f,-0.240531f,0.525831f,0.936707f,0.0794079f, 0.479519f,0.418117f,-0.239984f,0.539315f,0.996776f,0.0917728f,
1.0f,1.16576e-06f,-2.34604e-17f,0.873054f,0.655279f,4.74888e-05f, 0.999653f,0.0165133f,-0.0107677f,0.872891f,0.655277f,4.79182e-05f,
0.998654f,0.0330047f,-0.021528f,0.872415f,0.655257f,4.91844e-05f, 0.997044f,0.0494464f,-0.0322492f,0.871596f,0.655225f,5.13265e-05f,
0.994905f,0.0658186f,-0.0429239f,0.870437f,0.655181f,5.43893e-05f, 0.99237f,0.0820803f,-0.0535453f,0.868963f,0.655124f,5.84409e-05f,
0.989821f,0.0982111f,-0.0640873f,0.867194f,0.655058f,6.35643e-05f, 0.987245f,0.11421f,-0.0745399f,0.865116f,0.65498f,6.98627e-05f,
0.984696f,0.130047f,-0.0848936f,0.862754f,0.654891f,7.74687e-05f, 0.982183f,0.145709f,-0.0951194f,0.860046f,0.654796f,8.65447e-05f,
0.979784f,0.161165f,-0.10522f,0.857052f,0.654691f,9.72774e-05f, 0.977661f,0.176372f,-0.115173f,0.853778f,0.654582f,0.000109887f,
0.983918f,0.191968f,-0.124562f,0.847464f,0.654468f,0.000124624f, 0.974802f,0.206038f,-0.134715f,0.84716f,0.654349f,0.000141787f,
0.970441f,0.220562f,-0.144107f,0.842754f,0.654232f,0.00016172f, 0.965498f,0.234941f,-0.153228f,0.837688f,0.654113f,0.000184814f,
0.961262f,0.249286f,-0.162101f,0.832286f,0.654001f,0.000211522f, 0.955853f,0.263446f,-0.170705f,0.826468f,0.653892f,0.00024236f,
0.951199f,0.277743f,-0.17905f,0.820417f,0.653794f,0.000277913f, 0.946424f,0.291985f,-0.18716f,0.81424f,0.653707f,0.000318855f,
0.941078f,0.305953f,-0.194999f,0.807879f,0.653638f,0.000365946f, 0.936025f,0.319999f,-0.202625f,0.801556f,0.653587f,0.000420053f,
0.941188f,0.338038f,-0.209734f,0.794182f,0.653562f,0.000482148f, 0.936059f,0.352093f,-0.216927f,0.788046f,0.653564f,0.00055334f,
0.914829f,0.35883f,-0.224027f,0.782441f,0.653604f,0.000634884f, 0.915918f,0.375341f,-0.230315f,0.774868f,0.65368f,0.000728182f,
0.899553f,0.383318f,-0.236725f,0.768629f,0.653808f,0.000834827f, 0.891998f,0.395235f,-0.242572f,0.761414f,0.653985f,0.000956605f,
0.884641f,0.407077f,-0.248138f,0.754241f,0.654229f,0.00109551f, 0.887024f,0.422038f,-0.254475f,0.750182f,0.654539f,0.0012538f,
0.883383f,0.436961f,-0.258407f,0.739926f,0.654933f,0.00143399f, 0.864394f,0.442036f,-0.262958f,0.7324f,0.655415f,0.0016389f,
0.847935f,0.44756f,-0.267429f,0.725532f,0.656001f,0.00187164f, 0.839155f,0.456967f,-0.271252f,0.71777f,0.656702f,0.00213579f,
0.832691f,0.467508f,-0.274861f,0.710327f,0.657533f,0.00243521f, 0.819119f,0.473387f,-0.278097f,0.702799f,0.65851f,0.00277426f,
0.808792f,0.48085f,-0.280945f,0.695161f,0.659649f,0.00315785f, 0.805441f,0.492195f,-0.283623f,0.687984f,0.660971f,0.00359135f,
0.787932f,0.494029f,-0.286037f,0.681018f,0.662496f,0.00408073f, 0.786786f,0.506068f,-0.288126f,0.674142f,0.66425f,0.00463274f,
0.769179f,0.506579f,-0.289668f,0.666851f,0.666259f,0.00525478f, 0.754878f,0.508494f,-0.290625f,0.659093f,0.66855f,0.00595515f,
0.742943f,0.511729f,-0.291301f,0.651601f,0.671163f,0.006743f, 0.734459f,0.51673f,-0.291843f,0.644677f,0.674125f,0.00762861f,
0.722061f,0.51806f,-0.292181f,0.638202f,0.67749f,0.0086234f, 0.719154f,0.526046f,-0.29232f,0.632161f,0.681294f,0.00974009f,
0.701449f,0.522083f,-0.292288f,0.62662f,0.685591f,0.0109931f, 0.689823f,0.522046f,-0.291299f,0.619935f,0.69045f,0.0123982f,
0.686656f,0.528019f,-0.290265f,0.614069f,0.695933f,0.0139737f, 0.665282f,0.51861f,-0.288685f,0.607958f,0.702117f,0.0157399f,
0.654608f,0.516939f,-0.286884f,0.602308f,0.709091f,0.0177199f, 0.642104f,0.512996f,-0.284456f,0.596285f,0.71696f,0.01994f,
0.633214f,0.511319f,-0.282446f,0.592088f,0.725846f,0.0224307f, 0.621439f,0.50628f,-0.279478f,0.586846f,0.735885f,0.0252268f,
0.611516f,0.50206f,-0.276633f,0.582881f,0.747265f,0.0283695f, 0.60271f,0.498008f,-0.273234f,0.578757f,0.760182f,0.0319067f,
0.595365f,0.494534f,-0.269904f,0.575857f,0.774907f,0.0358965f, 0.586976f,0.489136f,-0.266101f,0.573045f,0.791765f,0.0404094f,
0.571798f,0.476708f,-0.261756f,0.570223f,0.811209f,0.0455337f, 0.56249f,0.468902f,-0.257496f,0.568804f,0.833832f,0.051384f,
0.55225f,0.459398f,-0.252808f,0.567843f,0.860645f,0.0581182f, 0.542807f,0.448266f,-0.248485f,0.569237f,0.893133f,0.0659736f,
0.533935f,0.438852f,-0.244424f,0.573177f,0.93467f,0.07539f, 0.534032f,0.431429f,-0.24354f,0.586825f,0.996635f,0.0875332f,
0.999998f,1.45329e-06f,-2.49801e-17f,0.895715f,0.632572f,4.76118e-05f, 0.999671f,0.0157199f,-0.0103849f,0.895582f,0.632582f,4.80501e-05f,
0.998673f,0.0314205f,-0.0207586f,0.89514f,0.632572f,4.92933e-05f, 0.997092f,0.0470765f,-0.0311037f,0.894411f,0.632558f,5.13951e-05f,
0.995086f,0.062663f,-0.0414029f,0.893386f,0.632544f,5.44062e-05f, 0.992883f,0.078149f,-0.0516551f,0.892077f,0.632524f,5.83834e-05f,
0.990623f,0.093512f,-0.0618375f,0.890472f,0.6325f,6.3403e-05f, 0.988375f,0.108737f,-0.071933f,0.888591f,0.632475f,6.95711e-05f,
0.986154f,0.123809f,-0.0819368f,0.886409f,0.632447f,7.70102e-05f, 0.984059f,0.138701f,-0.0918335f,0.883969f,0.63242f,8.58749e-05f,
0.980537f,0.153317f,-0.101579f,0.880994f,0.632394f,9.63434e-05f, 0.977975f,0.167745f,-0.111214f,0.877958f,0.632369f,0.000108617f,
0.976104f,0.181922f,-0.120698f,0.874667f,0.63235f,0.00012294f, 0.984334f,0.196802f,-0.129595f,0.868219f,0.632336f,0.00013959f,
0.974515f,0.209863f,-0.139216f,0.867518f,0.63233f,0.00015889f, 0.969565f,0.223477f,-0.148236f,0.863731f,0.632334f,0.000181211f,
0.966136f,0.23725f,-0.156886f,0.858697f,0.632351f,0.000206976f, 0.962083f,0.250842f,-0.165292f,0.853342f,0.632385f,0.000236666f,
0.958064f,0.264533f,-0.173463f,0.847726f,0.632436f,0.000270831f, 0.951776f,0.27758f,-0.181312f,0.841569f,0.632512f,0.000310097f,
0.950134f,0.292116f,-0.188693f,0.834269f,0.632612f,0.000355169f, 0.94028f,0.303535f,-0.196332f,0.829114f,0.632745f,0.000406848f,
0.935508f,0.316685f,-0.20354f,0.823013f,0.63291f,0.00046605f, 0.955282f,0.336726f,-0.212875f,0.826076f,0.633118f,0.000533791f,
0.948566f,0.351371f,-0.219826f,0.820397f,0.633369f,0.000611235f, 0.91746f,0.353737f,-0.22394f,0.805367f,0.633675f,0.000699684f,
0.914523f,0.367354f,-0.229964f,0.798428f,0.634036f,0.000800606f, 0.901702f,0.376001f,-0.235798f,0.791762f,0.634467f,0.000915641f,
0.903357f,0.392017f,-0.241436f,0.785321f,0.634968f,0.00104665f, 0.887313f,0.397891f,-0.246503f,0.77794f,0.635556f,0.0011957f,
0.879262f,0.408119f,-0.251401f,0.770928f,0.636233f,0.0013651f, 0.875034f,0.419976f,-0.255965f,0.763809f,0.637017f,0.00155749f,
0.862226f,0.426913f,-0.260613f,0.757801f,0.637914f,0.00177571f, 0.882221f,0.450654f,-0.268381f,0.761471f,0.638942f,0.00202309f,
0.844878f,0.44426f,-0.26854f,0.74442f,0.640111f,0.00230318f, 0.83623f,0.452443f,-0.271875f,0.737299f,0.64144f,0.00262005f,
0.832615f,0.463087f,-0.274836f,0.730052f,0.642944f,0.0029782f, 0.818219f,0.466939f,-0.277644f,0.723288f,0.644644f,0.00338261f,
0.806769f,0.472251f,-0.279785f,0.715687f,0.646563f,0.00383893f, 0.806977f,0.483865f,-0.282097f,0.709399f,0.648719f,0.00435335f,
0.787208f,0.483188f,-0.283993f,0.70296f,0.651149f,0.00493286f, 0.77931f,0.489146f,-0.285389f,0.696152f,0.65387f,0.00558512f,
0.782995f,0.502438f,-0.286738f,0.690126f,0.656924f,0.00631883f, 0.762935f,0.498743f,-0.287317f,0.683149f,0.660346f,0.00714366f,
0.745141f,0.496801f,-0.287762f,0.676747f,0.664172f,0.00807044f, 0.736076f,0.499652f,-0.287957f,0.670664f,0.668453f,0.00911129f,
0.727925f,0.502621f,-0.288012f,0.665184f,0.673244f,0.0102797f, 0.723886f,0.508272f,-0.287642f,0.659632f,0.678599f,0.011591f,
0.706737f,0.503211f,-0.286754f,0.653819f,0.684586f,0.0130626f, 0.702154f,0.503828f,-0.285409f,0.647911f,0.691283f,0.0147141f,
0.684501f,0.500054f,-0.284485f,0.643913f,0.698779f,0.0165678f, 0.673911f,0.497864f,-0.282679f,0.638885f,0.707178f,0.0186494f,
0.664062f,0.495488f,-0.280713f,0.634476f,0.716594f,0.0209882f, 0.658211f,0.495808f,-0.278241f,0.629963f,0.727186f,0.0236188f,
0.652479f,0.495231f,-0.275817f,0.626584f,0.739117f,0.0265812f, 0.630741f,0.480684f,-0.272856f,0.623074f,0.752603f,0.0299231f,
0.621822f,0.476104f,-0.26988f,0.620641f,0.767902f,0.0337017f, 0.611122f,0.469188f,-0.266478f,0.618405f,0.785368f,0.0379877f,
0.600141f,0.461106f,-0.262562f,0.616206f,0.805453f,0.0428692f, 0.590122f,0.453206f,-0.258789f,0.615702f,0.828797f,0.0484616f,
0.579392f,0.444005f,-0.254731f,0.615998f,0.85637f,0.0549251f, 0.571768f,0.436249f,-0.251196f,0.619295f,0.889832f,0.0625035f,
0.562017f,0.425646f,-0.247846f,0.625202f,0.932518f,0.0716441f, 0.556828f,0.414302f,-0.249475f,0.646386f,0.996489f,0.0835878f,
1.0f,1.26565e-06f,-3.97607e-17f,0.917448f,0.609762f,4.75738e-05f, 0.999677f,0.0148789f,-0.00994654f,0.917328f,0.609776f,4.80046e-05f,
0.99875f,0.0297433f,-0.0198825f,0.916942f,0.60978f,4.92222e-05f, 0.997274f,0.0445687f,-0.0297934f,0.916291f,0.609787f,5.12797e-05f,
0.995433f,0.0593306f,-0.0396636f,0.915384f,0.609801f,5.42262e-05f, 0.993122f,0.0739845f,-0.0494886f,0.914182f,0.609819f,5.81142e-05f,
0.990917f,0.0885216f,-0.0592532f,0.912748f,0.609841f,6.30162e-05f, 0.988749f,0.102916f,-0.0689365f,0.911033f,0.609871f,6.9034e-05f,
0.986623f,0.117168f,-0.0785422f,0.909118f,0.609907f,7.62836e-05f, 0.984563f,0.131253f,-0.0880491f,0.906905f,0.609951f,8.4912e-05f,
0.982658f,0.14514f,-0.0974416f,0.904447f,0.610006f,9.50838e-05f, 0.980964f,0.158793f,-0.106716f,0.901739f,0.610071f,0.000106991f,
0.979553f,0.172186f,-0.115858f,0.898815f,0.61015f,0.000120863f, 0.983873f,0.185655f,-0.124556f,0.893497f,0.610244f,0.000136963f,
0.976988f,0.198433f,-0.133772f,0.892716f,0.610354f,0.000155594f, 0.97299f,0.211354f,-0.142369f,0.888571f,0.610486f,0.000177105f,
0.969095f,0.224207f,-0.150738f,0.88394f,0.610639f,0.000201888f, 0.97164f,0.238688f,-0.158362f,0.876111f,0.610818f,0.000230392f,
0.960591f,0.249586f,-0.16682f,0.873872f,0.611026f,0.000263128f, 0.956574f,0.26228f,-0.174508f,0.86842f,0.611265f,0.000300681f,
0.952348f,0.274896f,-0.181958f,0.862772f,0.611542f,0.000343707f, 0.951479f,0.288743f,-0.18896f,0.856001f,0.611858f,0.000392951f,
0.943086f,0.2996f,-0.196174f,0.851169f,0.612223f,0.000449261f, 0.938532f,0.311857f,-0.202966f,0.845381f,0.612635f,0.000513583f,
0.938527f,0.326079f,-0.209141f,0.838031f,0.613108f,0.000586992f, 0.930898f,0.33671f,-0.215731f,0.833253f,0.61364f,0.000670688f,
0.91961f,0.34552f,-0.222049f,0.828272f,0.614245f,0.000766025f, 0.912342f,0.356045f,-0.227706f,0.8217f,0.614925f,0.000874528f,
0.905675f,0.366461f,-0.233293f,0.815797f,0.615692f,0.000997903f, 0.899113f,0.376777f,-0.238462f,0.809322f,0.616553f,0.00113807f,
0.892042f,0.386574f,-0.243305f,0.802654f,0.61752f,0.00129719f, 0.885271f,0.396323f,-0.24797f,0.796314f,0.618602f,0.00147763f,
0.879422f,0.406255f,-0.252294f,0.789765f,0.61981f,0.00168206f, 0.876225f,0.417348f,-0.256313f,0.783177f,0.621162f,0.00191358f,
0.861526f,0.421873f,-0.260372f,0.777569f,0.622666f,0.00217545f, 0.866733f,0.437063f,-0.263669f,0.770597f,0.624344f,0.00247141f,
0.843313f,0.43604f,-0.267087f,0.764849f,0.626208f,0.00280568f, 0.834856f,0.442911f,-0.2699f,0.758263f,0.628281f,0.00318291f,
0.826547f,0.449376f,-0.272395f,0.751688f,0.630585f,0.00360835f, 0.81722f,0.454716f,-0.274669f,0.745393f,0.633138f,0.00408774f,
0.808166f,0.46006f,-0.276607f,0.739105f,0.635975f,0.00462766f, 0.799836f,0.46531f,-0.278317f,0.733101f,0.639119f,0.00523536f,
0.800309f,0.47658f,-0.279766f,0.727304f,0.642601f,0.00591891f, 0.780622f,0.472384f,-0.280857f,0.721494f,0.646464f,0.00668754f,
0.770426f,0.474995f,-0.281485f,0.715423f,0.650746f,0.00755134f, 0.770261f,0.48372f,-0.282075f,0.710174f,0.655491f,0.00852186f,
0.769718f,0.484162f,-0.281876f,0.703872f,0.660751f,0.00961214f, 0.749668f,0.485837f,-0.282321f,0.700115f,0.666586f,0.0108368f,
0.732427f,0.48099f,-0.281758f,0.694813f,0.673063f,0.0122123f, 0.722935f,0.480947f,-0.280882f,0.689711f,0.680259f,0.0137578f,
0.712966f,0.480089f,-0.279757f,0.684986f,0.688263f,0.0154947f, 0.704675f,0.479657f,-0.27855f,0.681055f,0.697176f,0.0174479f,
0.696328f,0.478508f,-0.276691f,0.676556f,0.707119f,0.0196462f, 0.691999f,0.479608f,-0.274971f,0.673471f,0.718248f,0.0221232f,
0.686049f,0.479434f,-0.272607f,0.669878f,0.730722f,0.0249182f, 0.666106f,0.467252f,-0.270259f,0.667442f,0.744763f,0.0280783f,
0.657684f,0.463387f,-0.267334f,0.664769f,0.760649f,0.0316604f, 0.650634f,0.459984f,-0.264468f,0.663509f,0.778734f,0.0357345f,
0.642616f,0.454397f,-0.261209f,0.662558f,0.799475f,0.0403891f, 0.634333f,0.44899f,-0.257842f,0.662806f,0.823548f,0.0457407f,
0.625627f,0.441719f,-0.254303f,0.664207f,0.851942f,0.0519511f, 0.617647f,0.434539f,-0.25106f,0.668269f,0.886333f,0.0592672f,
0.599605f,0.418017f,-0.249703f,0.679805f,0.930255f,0.0681505f, 0.600192f,0.410889f,-0.251717f,0.703656f,0.996337f,0.0799151f,
0.999998f,-1.95371e-06f,-8.47376e-17f,0.938218f,0.586948f,4.73801e-05f, 0.999695f,0.0139908f,-0.00945679f,0.93811f,0.586961f,4.77912e-05f,
0.998798f,0.027972f,-0.0189069f,0.93778f,0.586978f,4.89799e-05f, 0.997378f,0.0419147f,-0.0283322f,0.937213f,0.587007f,5.09877e-05f,
0.995608f,0.055803f,-0.0377214f,0.936426f,0.587051f,5.38591e-05f, 0.993678f,0.0695972f,-0.0470741f,0.935403f,0.587108f,5.76467e-05f,
0.991748f,0.0832669f,-0.0563705f,0.934143f,0.587177f,6.24182e-05f, 0.989844f,0.0968137f,-0.0655948f,0.932643f,0.587263f,6.82691e-05f,
0.987997f,0.110211f,-0.0747462f,0.930909f,0.587364f,7.53097e-05f, 0.986236f,0.123444f,-0.0838111f,0.928939f,0.587482f,8.36796e-05f,
0.983262f,0.136448f,-0.0927514f,0.926534f,0.58762f,9.35309e-05f, 0.981462f,0.149288f,-0.101598f,0.924053f,0.587777f,0.000105046f,
0.979366f,0.161878f,-0.110324f,0.921379f,0.587956f,0.00011844f, 0.977964f,0.174215f,-0.118919f,0.918489f,0.588161f,0.000133962f,
0.977427f,0.18639f,-0.127443f,0.915862f,0.58839f,0.000151898f, 0.975456f,0.198597f,-0.135789f,0.912821f,0.588651f,0.000172566f,
0.972948f,0.210698f,-0.143889f,0.908991f,0.588942f,0.000196334f, 0.969873f,0.222723f,-0.151736f,0.904514f,0.589269f,0.000223622f,
0.973883f,0.236789f,-0.158727f,0.896119f,0.589635f,0.000254911f, 0.962749f,0.246548f,-0.166774f,0.894641f,0.590042f,0.000290744f,
0.957106f,0.25793f,-0.173951f,0.889332f,0.590497f,0.00033173f, 0.952297f,0.269385f,-0.180931f,0.883961f,0.591002f,0.000378559f,
0.947299f,0.280667f,-0.187682f,0.878459f,0.591563f,0.000432007f, 0.942562f,0.29186f,-0.19421f,0.872861f,0.592186f,0.000492962f,
0.938102f,0.303069f,-0.200548f,0.867341f,0.592875f,0.000562415f, 0.933611f,0.314151f,-0.206664f,0.861802f,0.593639f,0.000641482f,
0.928935f,0.324857f,-0.21276f,0.857052f,0.594482f,0.000731405f, 0.923479f,0.335106f,-0.21854f,0.851916f,0.595416f,0.000833603f,
0.917712f,0.345197f,-0.223923f,0.846106f,0.596444f,0.000949652f, 0.91117f,0.354794f,-0.229055f,0.840273f,0.59758f,0.00108133f,
0.903536f,0.363524f,-0.233972f,0.834551f,0.59883f,0.0012306f, 0.89573f,0.372038f,-0.23844f,0.828131f,0.600207f,0.00139969f,
0.889149f,0.380784f,-0.242719f,0.821998f,0.601726f,0.00159111f, 0.882502f,0.389216f,-0.246761f,0.815953f,0.603392f,0.00180758f,
0.8768f,0.397755f,-0.250549f,0.809985f,0.605229f,0.00205231f, 0.869078f,0.404967f,-0.254028f,0.803917f,0.607247f,0.00232867f,
0.861525f,0.411912f,-0.257628f,0.799108f,0.609463f,0.0026406f, 0.85636f,0.419875f,-0.260513f,0.792987f,0.611902f,0.00299245f,
0.845314f,0.424479f,-0.263549f,0.788202f,0.614578f,0.00338907f, 0.836785f,0.429929f,-0.265856f,0.782127f,0.617518f,0.00383592f,
0.828753f,0.435168f,-0.26783f,0.77602f,0.620752f,0.00433902f, 0.819819f,0.439603f,-0.269543f,0.770073f,0.624303f,0.00490534f,
0.821105f,0.449793f,-0.271036f,0.764422f,0.628204f,0.0055424f, 0.803051f,0.447675f,-0.272572f,0.759806f,0.632493f,0.00625887f,
0.793947f,0.450459f,-0.273274f,0.753803f,0.63721f,0.00706449f, 0.785546f,0.453372f,-0.27398f,0.748774f,0.642403f,0.00797009f,
0.785821f,0.461188f,-0.274701f,0.744728f,0.648121f,0.00898808f, 0.779673f,0.463887f,-0.274549f,0.739273f,0.654421f,0.0101325f,
0.759387f,0.457891f,-0.274697f,0.735602f,0.661372f,0.0114192f, 0.750508f,0.458393f,-0.274275f,0.731408f,0.669052f,0.0128665f,
0.746545f,0.461751f,-0.27339f,0.727002f,0.677551f,0.0144952f, 0.746584f,0.468391f,-0.273311f,0.72575f,0.686967f,0.0163296f,
0.739943f,0.466079f,-0.270972f,0.719578f,0.697427f,0.0183975f, 0.717044f,0.455406f,-0.270034f,0.718199f,0.709075f,0.0207318f,
0.711487f,0.455324f,-0.267942f,0.714923f,0.722099f,0.0233711f, 0.696499f,0.447531f,-0.266158f,0.713638f,0.736707f,0.026362f,
0.687815f,0.44362f,-0.263775f,0.711977f,0.753178f,0.0297607f, 0.677653f,0.438381f,-0.261236f,0.711233f,0.771876f,0.033637f,
0.668902f,0.433202f,-0.258495f,0.711338f,0.793288f,0.0380796f, 0.661742f,0.428461f,-0.255898f,0.713426f,0.818097f,0.0432052f,
0.652907f,0.422079f,-0.253256f,0.717163f,0.847318f,0.049178f, 0.646202f,0.41594f,-0.250701f,0.72325f,0.882762f,0.0562522f,
0.63883f,0.408348f,-0.249057f,0.734621f,0.928002f,0.0648997f, 0.639714f,0.401271f,-0.252442f,0.764353f,0.996181f,0.0764954f,
0.999995f,5.67777e-07f,-2.27848e-18f,0.957999f,0.564219f,4.70336e-05f, 0.99972f,0.0130646f,-0.00892035f,0.957911f,0.564229f,4.7418e-05f,
0.998904f,0.0261229f,-0.0178402f,0.957628f,0.56426f,4.85764e-05f, 0.997603f,0.0391512f,-0.0267311f,0.957153f,0.564312f,5.05312e-05f,
0.995913f,0.0521244f,-0.0355943f,0.956457f,0.564385f,5.33184e-05f, 0.993971f,0.0650145f,-0.0444257f,0.955565f,0.564481f,5.69953e-05f,
0.992074f,0.0777899f,-0.0532037f,0.954473f,0.5646f,6.1626e-05f, 0.990214f,0.0904356f,-0.0619215f,0.953165f,0.564742f,6.72957e-05f,
0.988414f,0.102953f,-0.0705775f,0.951692f,0.564908f,7.41115e-05f, 0.986641f,0.115315f,-0.0791499f,0.949957f,0.565102f,8.22053e-05f,
0.984962f,0.127511f,-0.0876341f,0.948026f,0.565323f,9.17168e-05f, 0.983416f,0.139502f,-0.0960226f,0.945894f,0.565571f,0.000102819f,
0.98208f,0.151285f,-0.1043f,0.943571f,0.565853f,0.000115716f, 0.98097f,0.162812f,-0.112465f,0.941053f,0.566168f,0.000130643f,
0.980059f,0.174148f,-0.120499f,0.938291f,0.566518f,0.000147857f, 0.978112f,0.185444f,-0.128415f,0.935516f,0.566908f,0.00016766f,
0.975225f,0.196652f,-0.136162f,0.932337f,0.567338f,0.000190398f, 0.972697f,0.20779f,-0.143702f,0.928653f,0.567813f,0.000216468f,
0.969686f,0.218882f,-0.151016f,0.924443f,0.568337f,0.000246309f, 0.968705f,0.230402f,-0.157883f,0.918518f,0.568911f,0.000280419f,
0.96185f,0.240554f,-0.165083f,0.915506f,0.569544f,0.000319371f, 0.958089f,0.251294f,-0.17179f,0.910613f,0.570235f,0.000363812f,
0.954327f,0.261996f,-0.178309f,0.90569f,0.570994f,0.00041446f, 0.950377f,0.272567f,-0.18462f,0.900656f,0.571824f,0.000472125f,
0.945903f,0.282823f,-0.190705f,0.895449f,0.572729f,0.000537728f, 0.941594f,0.293071f,-0.196588f,0.89025f,0.573722f,0.000612314f,
0.93503f,0.302397f,-0.202121f,0.884403f,0.574802f,0.000697018f, 0.931212f,0.312556f,-0.207511f,0.878877f,0.575983f,0.000793159f,
0.926083f,0.321774f,-0.213065f,0.874937f,0.577271f,0.000902198f, 0.920863f,0.330843f,-0.218303f,0.870528f,0.578673f,0.00102576f,
0.915043f,0.339653f,-0.223029f,0.86498f,0.580205f,0.0011657f, 0.90804f,0.347782f,-0.227461f,0.859207f,0.581872f,0.00132404f,
0.901687f,0.355699f,-0.231881f,0.854283f,0.583688f,0.00150313f, 0.895399f,0.363623f,-0.235925f,0.848897f,0.585669f,0.00170551f,
0.895175f,0.374076f,-0.23925f,0.841847f,0.587825f,0.00193405f, 0.882225f,0.378212f,-0.243175f,0.837815f,0.590174f,0.00219209f,
0.876563f,0.385426f,-0.246367f,0.832166f,0.592735f,0.00248312f, 0.869594f,0.391857f,-0.24937f,0.826782f,0.595525f,0.00281128f,
0.862756f,0.397859f,-0.252187f,0.82169f,0.598563f,0.00318104f, 0.883118f,0.417359f,-0.25833f,0.82816f,0.601878f,0.00359759f,
0.848468f,0.40878f,-0.257393f,0.812846f,0.605494f,0.00406657f, 0.851112f,0.41907f,-0.258917f,0.806391f,0.609439f,0.00459446f,
0.831793f,0.41666f,-0.261089f,0.802888f,0.613743f,0.00518843f, 0.823679f,0.420311f,-0.26245f,0.797816f,0.618445f,0.00585668f,
0.815689f,0.423554f,-0.263637f,0.793171f,0.623584f,0.00660832f, 0.808019f,0.426373f,-0.26439f,0.788185f,0.629207f,0.00745382f,
0.80387f,0.430978f,-0.265347f,0.784781f,0.635366f,0.00840496f, 0.804147f,0.438032f,-0.265439f,0.779804f,0.642118f,0.00947512f,
0.783813f,0.431762f,-0.265681f,0.776274f,0.649529f,0.0106796f, 0.777238f,0.4334f,-0.265599f,0.772792f,0.657676f,0.0120361f,
0.769319f,0.433867f,-0.265241f,0.769584f,0.666652f,0.0135645f, 0.761246f,0.433664f,-0.264502f,0.766322f,0.676561f,0.0152886f,
0.753523f,0.43329f,-0.263411f,0.763152f,0.687526f,0.0172353f, 0.749979f,0.434831f,-0.262172f,0.760671f,0.699693f,0.0194369f,
0.74569f,0.435714f,-0.260673f,0.75862f,0.713248f,0.0219315f, 0.735847f,0.432154f,-0.259117f,0.757663f,0.728418f,0.0247646f,
0.730279f,0.431455f,-0.257156f,0.756827f,0.745489f,0.0279924f, 0.726738f,0.427383f,-0.255909f,0.759468f,0.764808f,0.0316837f,
0.71885f,0.426685f,-0.253131f,0.759109f,0.786906f,0.0359277f, 0.697134f,0.41182f,-0.251797f,0.764769f,0.812462f,0.0408419f,
0.689145f,0.406457f,-0.249839f,0.77056f,0.842594f,0.0465919f, 0.68395f,0.401823f,-0.248019f,0.779039f,0.879062f,0.0534365f,
0.678281f,0.395786f,-0.247119f,0.793361f,0.925698f,0.0618661f, 0.685928f,0.392704f,-0.249953f,0.823518f,0.996019f,0.0733101f,
1.0f,-7.25506e-07f,3.16981e-17f,0.976799f,0.54166f,4.65373e-05f, 0.999748f,0.0121043f,-0.00834463f,0.976718f,0.541669f,4.68967e-05f,
0.998979f,0.0242003f,-0.016688f,0.976485f,0.541715f,4.80242e-05f, 0.997764f,0.0362755f,-0.0250072f,0.976085f,0.54179f,4.99203e-05f,
0.99623f,0.0483053f,-0.0333048f,0.975516f,0.541892f,5.2618e-05f, 0.994549f,0.060261f,-0.0415707f,0.974771f,0.542027f,5.61763e-05f,
0.992888f,0.0721031f,-0.0497912f,0.973858f,0.542194f,6.06564e-05f, 0.991234f,0.0838366f,-0.0579621f,0.972746f,0.542392f,6.6134e-05f,
0.989628f,0.0954467f,-0.0660718f,0.971448f,0.542624f,7.27131e-05f, 0.98809f,0.106906f,-0.0741109f,0.969952f,0.542892f,8.05169e-05f,
0.985765f,0.118205f,-0.0820635f,0.968149f,0.543195f,8.96741e-05f, 0.98391f,0.129345f,-0.0899311f,0.966233f,0.543537f,0.00010035f,
0.981987f,0.140282f,-0.0977086f,0.964195f,0.54392f,0.000112739f, 0.980515f,0.151027f,-0.105381f,0.961943f,0.544344f,0.00012705f,
0.979257f,0.16153f,-0.112941f,0.959556f,0.544814f,0.000143529f, 0.978128f,0.17186f,-0.12037f,0.956902f,0.545331f,0.00016246f,
0.9775f,0.182179f,-0.127758f,0.954728f,0.545898f,0.000184171f, 0.97584f,0.192496f,-0.13496f,0.952017f,0.54652f,0.000209013f,
0.973489f,0.202681f,-0.141942f,0.948605f,0.547199f,0.000237405f, 0.970623f,0.212801f,-0.148709f,0.944671f,0.547939f,0.000269822f,
0.967651f,0.222852f,-0.155298f,0.940567f,0.548746f,0.000306777f, 0.96432f,0.232734f,-0.161728f,0.936416f,0.549621f,0.000348868f,
0.959025f,0.242193f,-0.16793f,0.931888f,0.550573f,0.00039678f, 0.955441f,0.251863f,-0.173968f,0.927392f,0.551606f,0.000451246f,
0.950735f,0.261169f,-0.179779f,0.922606f,0.552724f,0.000513133f, 0.945849f,0.270262f,-0.185372f,0.917671f,0.553938f,0.000583396f,
0.941342f,0.279275f,-0.190793f,0.912803f,0.555252f,0.000663089f, 0.937306f,0.288348f,-0.196001f,0.907838f,0.556673f,0.00075344f,
0.933061f,0.297226f,-0.201072f,0.903179f,0.558213f,0.000855781f, 0.928955f,0.305958f,-0.205904f,0.898334f,0.559878f,0.000971649f,
0.924484f,0.314223f,-0.210791f,0.894605f,0.561678f,0.00110272f, 0.926611f,0.325564f,-0.214738f,0.887837f,0.563628f,0.00125093f,
0.914006f,0.329765f,-0.219553f,0.885532f,0.565736f,0.00141839f, 0.90833f,0.337175f,-0.223549f,0.880765f,0.568015f,0.0016075f,
0.903283f,0.344654f,-0.227138f,0.875331f,0.570484f,0.00182096f, 0.895912f,0.350602f,-0.23089f,0.871417f,0.573154f,0.00206179f,
0.889597f,0.356975f,-0.234183f,0.866663f,0.576043f,0.0023333f, 0.886661f,0.36477f,-0.236974f,0.860984f,0.579171f,0.00263932f,
0.877266f,0.368806f,-0.239808f,0.856406f,0.582562f,0.00298416f, 0.872339f,0.374919f,-0.24251f,0.852269f,0.586236f,0.00337252f,
0.866124f,0.380108f,-0.244841f,0.847745f,0.590219f,0.00380976f, 0.86054f,0.385436f,-0.246877f,0.843139f,0.59454f,0.00430197f,
0.851428f,0.388395f,-0.248726f,0.838834f,0.599232f,0.00485602f, 0.854281f,0.397473f,-0.249894f,0.833204f,0.60433f,0.00547956f,
0.837347f,0.39532f,-0.25202f,0.831722f,0.609876f,0.0061813f, 0.831203f,0.398853f,-0.252861f,0.82696f,0.615915f,0.0069711f,
0.833932f,0.406721f,-0.253691f,0.823158f,0.622497f,0.00786031f, 0.816925f,0.403135f,-0.254973f,0.821802f,0.629681f,0.00886175f,
0.807737f,0.403801f,-0.255191f,0.818037f,0.637536f,0.00999008f, 0.801954f,0.405677f,-0.25537f,0.815219f,0.646142f,0.0112622f,
0.794183f,0.406185f,-0.255262f,0.812518f,0.655581f,0.0126977f, 0.787935f,0.406966f,-0.254916f,0.810202f,0.665972f,0.0143193f,
0.779232f,0.406139f,-0.254352f,0.808319f,0.677432f,0.0161536f, 0.772718f,0.405777f,-0.253515f,0.806749f,0.690113f,0.0182318f,
0.765789f,0.40484f,-0.252557f,0.806031f,0.704205f,0.0205914f, 0.761045f,0.404524f,-0.251211f,0.805362f,0.719933f,0.0232775f,
0.756185f,0.404121f,-0.249607f,0.805244f,0.737587f,0.0263452f, 0.750928f,0.402604f,-0.247872f,0.806158f,0.757552f,0.0298636f,
0.73696f,0.394924f,-0.247229f,0.812293f,0.780342f,0.0339215f, 0.731292f,0.391767f,-0.245481f,0.81668f,0.806688f,0.0386371f,
0.723769f,0.387234f,-0.244168f,0.824543f,0.837685f,0.0441788f, 0.718647f,0.383067f,-0.242963f,0.835333f,0.875215f,0.0508085f,
0.715494f,0.378656f,-0.243623f,0.855917f,0.923292f,0.0590311f, 0.720468f,0.373689f,-0.250314f,0.902297f,0.995852f,0.0703424f,
1.0f,-4.66888e-06f,-7.83502e-17f,0.994574f,0.519353f,4.58963e-05f, 0.99977f,0.0111204f,-0.00773737f,0.994513f,0.519367f,4.62466e-05f,
0.999102f,0.0222264f,-0.0154581f,0.994324f,0.519425f,4.73343e-05f, 0.99802f,0.0333145f,-0.0231765f,0.993996f,0.519521f,4.91669e-05f,
0.996547f,0.0443746f,-0.030868f,0.993516f,0.519653f,5.17732e-05f, 0.99491f,0.0553683f,-0.0385273f,0.992912f,0.519827f,5.52063e-05f,
0.993278f,0.0662683f,-0.0461571f,0.99214f,0.52004f,5.95271e-05f, 0.991662f,0.0770583f,-0.0537398f,0.991236f,0.520294f,6.48055e-05f,
0.990088f,0.0877272f,-0.0612676f,0.990163f,0.520591f,7.11393e-05f, 0.988502f,0.0982832f,-0.0687399f,0.988906f,0.52093f,7.86419e-05f,
0.986978f,0.1087f,-0.0761409f,0.987504f,0.521315f,8.74357e-05f, 0.985508f,0.118963f,-0.0834664f,0.985949f,0.521747f,9.7677e-05f,
0.984125f,0.129076f,-0.0907136f,0.984235f,0.522228f,0.000109545f, 0.982837f,0.13898f,-0.0978653f,0.982366f,0.52276f,0.000123232f,
0.9817f,0.148692f,-0.104923f,0.980373f,0.523346f,0.000138975f, 0.98073f,0.158194f,-0.111876f,0.978201f,0.523988f,0.000157038f,
0.978331f,0.167584f,-0.118679f,0.975619f,0.52469f,0.000177711f, 0.986295f,0.1745f,-0.124863f,0.969016f,0.525454f,0.000201345f,
0.975457f,0.186208f,-0.132063f,0.971111f,0.526284f,0.000228313f, 0.973062f,0.195375f,-0.138448f,0.967874f,0.527185f,0.000259049f,
0.970615f,0.204488f,-0.144727f,0.96475f,0.52816f,0.000294056f, 0.967661f,0.213489f,-0.150786f,0.961063f,0.529214f,0.000333865f,
0.964675f,0.222426f,-0.156689f,0.957313f,0.530355f,0.000379118f, 0.961133f,0.231104f,-0.162381f,0.953177f,0.531583f,0.000430496f,
0.957173f,0.239633f,-0.167919f,0.949063f,0.532908f,0.000488801f, 0.953448f,0.248129f,-0.173261f,0.944789f,0.534337f,0.000554904f,
0.949788f,0.256523f,-0.178475f,0.940702f,0.535874f,0.00062982f, 0.945968f,0.264762f,-0.183498f,0.936522f,0.537529f,0.000714634f,
0.946361f,0.274522f,-0.187944f,0.930379f,0.539311f,0.000810629f, 0.937941f,0.280655f,-0.192923f,0.927771f,0.541228f,0.000919193f,
0.933577f,0.288292f,-0.197358f,0.923404f,0.543289f,0.0010419f, 0.92922f,0.295768f,-0.201645f,0.919264f,0.545509f,0.00118053f,
0.92494f,0.303074f,-0.205698f,0.914952f,0.547896f,0.00133707f, 0.920856f,0.310043f,-0.209838f,0.911897f,0.550464f,0.00151374f,
0.91987f,0.318565f,-0.213175f,0.906261f,0.553229f,0.00171304f, 0.910257f,0.322697f,-0.217117f,0.904109f,0.556206f,0.00193778f,
0.904305f,0.32855f,-0.220338f,0.899823f,0.559413f,0.00219111f, 0.898305f,0.334117f,-0.223358f,0.895632f,0.562867f,0.00247656f,
0.898938f,0.344055f,-0.226045f,0.891041f,0.56659f,0.00279812f, 0.885947f,0.344157f,-0.228888f,0.887979f,0.570606f,0.00316027f,
0.881979f,0.349682f,-0.231232f,0.883908f,0.574941f,0.00356809f, 0.876311f,0.354291f,-0.233486f,0.880439f,0.579624f,0.00402727f,
0.868768f,0.357769f,-0.23531f,0.876303f,0.584686f,0.00454423f, 0.86227f,0.361353f,-0.236972f,0.872536f,0.590165f,0.00512629f,
0.855545f,0.364538f,-0.238362f,0.868749f,0.5961f,0.00578179f, 0.850095f,0.367948f,-0.239736f,0.865899f,0.602537f,0.00652003f,
0.845655f,0.371438f,-0.240838f,0.863046f,0.609526f,0.00735185f, 0.841616f,0.375f,-0.241448f,0.85947f,0.617129f,0.00828955f,
0.830591f,0.374472f,-0.242216f,0.857514f,0.625416f,0.00934724f, 0.828984f,0.378427f,-0.242494f,0.854868f,0.634458f,0.0105412f,
0.828188f,0.382754f,-0.242261f,0.851545f,0.644356f,0.0118903f, 0.831116f,0.388808f,-0.243118f,0.85319f,0.655214f,0.0134167f,
0.806421f,0.37841f,-0.243091f,0.852892f,0.667159f,0.0151463f, 0.800264f,0.378388f,-0.242717f,0.852607f,0.680347f,0.0171097f,
0.795355f,0.378652f,-0.241955f,0.852235f,0.694966f,0.0193434f, 0.791409f,0.379126f,-0.240755f,0.851681f,0.71125f,0.021892f,
0.787694f,0.379338f,-0.239625f,0.85281f,0.729505f,0.0248104f, 0.783479f,0.377926f,-0.238342f,0.854981f,0.750119f,0.0281668f,
0.796695f,0.385235f,-0.242363f,0.878039f,0.773609f,0.0320502f, 0.762359f,0.367665f,-0.237786f,0.872044f,0.800756f,0.0365795f,
0.757792f,0.364964f,-0.237415f,0.883578f,0.83267f,0.0419246f, 0.754154f,0.361818f,-0.237158f,0.898348f,0.871332f,0.0483541f,
0.752478f,0.358585f,-0.239147f,0.925406f,0.92079f,0.0563805f, 0.760209f,0.355106f,-0.247135f,0.981009f,0.99568f,0.0675761f,
1.00001f,-1.0975e-06f,-1.21823e-16f,1.01136f,0.497368f,4.51182e-05f, 0.999796f,0.0101037f,-0.00709062f,1.01132f,0.497398f,4.54794e-05f,
0.999199f,0.0202033f,-0.0141742f,1.01117f,0.497465f,4.65206e-05f, 0.998224f,0.0302898f,-0.0212508f,1.01091f,0.497581f,4.82862e-05f,
0.996968f,0.0403452f,-0.0283026f,1.01054f,0.497744f,5.08001e-05f, 0.995533f,0.0503503f,-0.035333f,1.01005f,0.497953f,5.41013e-05f,
0.994053f,0.0602845f,-0.0423334f,1.00944f,0.498212f,5.82584e-05f, 0.992607f,0.0701141f,-0.0492929f,1.0087f,0.49852f,6.33318e-05f,
0.991168f,0.0798458f,-0.0562107f,1.00781f,0.498877f,6.94128e-05f, 0.989769f,0.0894689f,-0.063075f,1.00679f,0.499288f,7.66089e-05f,
0.987959f,0.0989652f,-0.0698745f,1.00556f,0.499752f,8.50329e-05f, 0.986101f,0.108342f,-0.0766134f,1.00419f,0.50027f,9.48368e-05f,
0.984628f,0.117575f,-0.0832782f,1.00275f,0.500847f,0.000106176f, 0.982845f,0.126659f,-0.0898688f,1.00119f,0.501482f,0.000119242f,
0.981392f,0.135577f,-0.096374f,0.999461f,0.502179f,0.000134251f, 0.980089f,0.144319f,-0.102788f,0.997665f,0.502942f,0.000151441f,
0.978863f,0.152854f,-0.109109f,0.995736f,0.503772f,0.000171102f, 0.9777f,0.161266f,-0.115323f,0.993665f,0.504673f,0.000193533f,
0.976399f,0.169538f,-0.121401f,0.991279f,0.50565f,0.000219108f, 0.97586f,0.177833f,-0.127452f,0.989474f,0.506704f,0.000248211f,
0.974468f,0.186054f,-0.133348f,0.987248f,0.507842f,0.000281314f, 0.972819f,0.194263f,-0.138974f,0.983928f,0.509069f,0.000318911f,
0.969766f,0.202242f,-0.144606f,0.98149f,0.510387f,0.000361597f, 0.966899f,0.210211f,-0.149975f,0.978126f,0.511804f,0.00041f,
0.963872f,0.218013f,-0.155182f,0.974632f,0.513327f,0.00046487f, 0.9606f,0.225647f,-0.160269f,0.971255f,0.51496f,0.000527011f,
0.957291f,0.233222f,-0.165195f,0.967788f,0.516711f,0.000597347f, 0.951968f,0.240267f,-0.169936f,0.964149f,0.51859f,0.000676921f,
0.948363f,0.247504f,-0.174541f,0.960622f,0.520603f,0.000766889f, 0.944504f,0.25454f,-0.178909f,0.956682f,0.522759f,0.000868547f,
0.940512f,0.261429f,-0.183104f,0.952727f,0.52507f,0.000983368f, 0.940478f,0.269654f,-0.186776f,0.947029f,0.527547f,0.00111299f,
0.931961f,0.274496f,-0.191102f,0.945536f,0.5302f,0.00125926f, 0.927992f,0.280874f,-0.19474f,0.941483f,0.533043f,0.00142427f,
0.924169f,0.287159f,-0.198302f,0.93797f,0.53609f,0.00161032f, 0.91982f,0.293076f,-0.20165f,0.934349f,0.539358f,0.00182006f,
0.918141f,0.299858f,-0.204598f,0.929813f,0.542865f,0.00205641f, 0.9454f,0.312962f,-0.210672f,0.940172f,0.546629f,0.00232267f,
0.909072f,0.310329f,-0.210673f,0.92432f,0.55067f,0.00262259f, 0.901447f,0.31376f,-0.213749f,0.923058f,0.555014f,0.00296045f,
0.896433f,0.318399f,-0.216141f,0.91975f,0.559684f,0.00334094f, 0.892033f,0.322886f,-0.218235f,0.91613f,0.564711f,0.00376941f,
0.88656f,0.326797f,-0.220313f,0.913394f,0.570125f,0.00425203f, 0.882279f,0.331144f,-0.221856f,0.909441f,0.575965f,0.00479564f,
0.900691f,0.343696f,-0.226486f,0.919015f,0.582273f,0.00540825f, 0.869178f,0.336191f,-0.225211f,0.905613f,0.589092f,0.00609871f,
0.865092f,0.339511f,-0.226628f,0.904125f,0.596471f,0.00687731f, 0.858569f,0.341445f,-0.2275f,0.901544f,0.60448f,0.00775587f,
0.853435f,0.343898f,-0.228094f,0.89889f,0.613176f,0.008748f, 0.856116f,0.34923f,-0.22881f,0.897862f,0.622651f,0.00986941f,
0.841151f,0.346175f,-0.229372f,0.897339f,0.632989f,0.0111383f, 0.835095f,0.347023f,-0.229675f,0.896961f,0.644303f,0.0125762f,
0.830939f,0.34819f,-0.229643f,0.896497f,0.656725f,0.0142082f, 0.823996f,0.347927f,-0.229655f,0.897475f,0.670412f,0.0160644f,
0.820475f,0.348751f,-0.229518f,0.899179f,0.685551f,0.0181807f, 0.814065f,0.34779f,-0.229041f,0.901048f,0.702402f,0.020601f,
0.808472f,0.346847f,-0.228609f,0.904597f,0.721253f,0.0233793f, 0.803812f,0.34587f,-0.227986f,0.909056f,0.742515f,0.026584f,
0.800445f,0.344999f,-0.227593f,0.916248f,0.76672f,0.0303036f, 0.794614f,0.34256f,-0.226924f,0.924521f,0.794673f,0.0346579f,
0.792265f,0.341154f,-0.227028f,0.93838f,0.827528f,0.0398189f, 0.790994f,0.339418f,-0.226926f,0.954416f,0.867287f,0.0460576f,
0.794182f,0.33882f,-0.22784f,0.978671f,0.918196f,0.0539013f, 0.804323f,0.335458f,-0.234143f,1.03158f,0.995504f,0.0649967f,
0.999998f,-1.83397e-06f,-9.68441e-17f,1.02716f,0.475796f,4.42616e-05f, 0.999828f,0.00907701f,-0.00642177f,1.02712f,0.475822f,4.45946e-05f,
0.999321f,0.0181522f,-0.0128398f,1.02701f,0.475903f,4.55994e-05f, 0.998483f,0.0272136f,-0.01924f,1.02681f,0.476038f,4.72939e-05f,
0.997338f,0.0362525f,-0.025637f,1.02653f,0.476228f,4.97095e-05f, 0.996005f,0.0452529f,-0.0320027f,1.02615f,0.476474f,5.28808e-05f,
0.994596f,0.0542024f,-0.038349f,1.02568f,0.476776f,5.68687e-05f, 0.993177f,0.0630638f,-0.0446627f,1.0251f,0.477133f,6.1732e-05f,
0.991753f,0.071842f,-0.0509341f,1.02441f,0.477551f,6.75593e-05f, 0.990341f,0.0805259f,-0.0571672f,1.02361f,0.478028f,7.44435e-05f,
0.988946f,0.0891008f,-0.0633491f,1.0227f,0.478566f,8.24972e-05f, 0.987542f,0.0975693f,-0.0694757f,1.02169f,0.479168f,9.18592e-05f,
0.986153f,0.105924f,-0.0755439f,1.02056f,0.479833f,0.000102672f, 0.984783f,0.114151f,-0.0815453f,1.01932f,0.480568f,0.000115123f,
0.983458f,0.122258f,-0.0874758f,1.01801f,0.481372f,0.000129398f, 0.982185f,0.130186f,-0.0933346f,1.01659f,0.482248f,0.000145739f,
0.980946f,0.137983f,-0.0991052f,1.01506f,0.483201f,0.000164392f, 0.979782f,0.145582f,-0.104794f,1.01347f,0.484233f,0.00018566f,
0.978662f,0.153026f,-0.110391f,1.01176f,0.485346f,0.000209867f, 0.976108f,0.160424f,-0.115853f,1.00968f,0.486548f,0.000237386f,
0.974749f,0.167642f,-0.121216f,1.00755f,0.487841f,0.000268647f, 0.974104f,0.174809f,-0.126541f,1.00589f,0.489228f,0.000304109f,
0.972057f,0.181968f,-0.131741f,1.00405f,0.490717f,0.000344323f, 0.969676f,0.189018f,-0.136743f,1.00153f,0.492314f,0.000389886f,
0.966612f,0.195867f,-0.141657f,0.999201f,0.494021f,0.000441464f, 0.963746f,0.202669f,-0.146396f,0.99648f,0.495849f,0.000499822f,
0.960806f,0.20938f,-0.151003f,0.993745f,0.497804f,0.000565824f, 0.957737f,0.215935f,-0.155475f,0.990972f,0.499892f,0.000640423f,
0.954174f,0.222246f,-0.159778f,0.987987f,0.502123f,0.000724687f, 0.950869f,0.228525f,-0.163895f,0.98473f,0.504506f,0.000819842f,
0.94844f,0.234825f,-0.167884f,0.981623f,0.507053f,0.000927236f, 0.94481f,0.240798f,-0.171764f,0.978752f,0.509772f,0.0010484f,
0.941801f,0.246776f,-0.175444f,0.975622f,0.512676f,0.00118507f, 0.937775f,0.252363f,-0.178947f,0.9724f,0.515778f,0.00133915f,
0.933799f,0.257828f,-0.182371f,0.969647f,0.519093f,0.00151282f, 0.932419f,0.264151f,-0.185175f,0.964532f,0.522637f,0.00170855f,
0.925899f,0.268208f,-0.188592f,0.963528f,0.526426f,0.00192906f, 0.921874f,0.273111f,-0.191438f,0.960487f,0.530482f,0.00217749f,
0.919239f,0.278261f,-0.194162f,0.957761f,0.534823f,0.00245733f, 0.914269f,0.282531f,-0.19674f,0.955243f,0.539475f,0.00277252f,
0.909218f,0.286568f,-0.199142f,0.952801f,0.544464f,0.00312763f, 0.905605f,0.290773f,-0.20132f,0.950241f,0.549818f,0.00352766f,
0.909087f,0.297906f,-0.20258f,0.944362f,0.555568f,0.00397834f, 0.896748f,0.297765f,-0.20556f,0.947428f,0.561752f,0.00448637f,
0.893189f,0.301677f,-0.206992f,0.94433f,0.568413f,0.00505917f, 0.898212f,0.30351f,-0.208156f,0.941057f,0.575596f,0.00570528f,
0.883983f,0.306838f,-0.210401f,0.943649f,0.583352f,0.00643451f, 0.878129f,0.30886f,-0.211647f,0.94282f,0.591747f,0.00725826f,
0.873459f,0.310996f,-0.212604f,0.941776f,0.600845f,0.00818946f, 0.869274f,0.313037f,-0.213518f,0.941649f,0.610729f,0.00924336f,
0.863287f,0.314065f,-0.214111f,0.941263f,0.621495f,0.0104377f, 0.859297f,0.315494f,-0.214766f,0.942369f,0.633256f,0.0117931f,
0.85484f,0.316527f,-0.214956f,0.942709f,0.646147f,0.0133343f, 0.853437f,0.318459f,-0.214604f,0.941965f,0.660325f,0.0150904f,
0.853203f,0.321227f,-0.214545f,0.943901f,0.675988f,0.017097f, 0.849957f,0.322079f,-0.213729f,0.943947f,0.693384f,0.0193971f,
0.835362f,0.316313f,-0.215732f,0.958123f,0.712832f,0.0220443f, 0.831869f,0.315968f,-0.215874f,0.965921f,0.734751f,0.0251066f,
0.8289f,0.315315f,-0.215766f,0.974511f,0.759685f,0.0286724f, 0.824562f,0.313906f,-0.216275f,0.98825f,0.788452f,0.0328621f,
0.8226f,0.312845f,-0.216702f,1.00428f,0.82224f,0.0378492f, 0.821646f,0.311436f,-0.217634f,1.0261f,0.863203f,0.0439122f,
0.824108f,0.310764f,-0.220256f,1.06035f,0.915638f,0.0515899f, 0.831994f,0.307853f,-0.228735f,1.12933f,0.995323f,0.0625906f,
1.0f,2.87877e-07f,-3.28208e-17f,1.04198f,0.454678f,4.33032e-05f, 0.999854f,0.00804085f,-0.00573076f,1.04195f,0.454704f,4.36116e-05f,
0.999419f,0.016072f,-0.0114573f,1.04187f,0.454799f,4.45829e-05f, 0.998721f,0.0241014f,-0.0171766f,1.04173f,0.45495f,4.6204e-05f,
0.997778f,0.0321174f,-0.0228811f,1.04153f,0.455168f,4.85214e-05f, 0.996646f,0.0400953f,-0.0285695f,1.04125f,0.455445f,5.15585e-05f,
0.995381f,0.0480378f,-0.034237f,1.04089f,0.455788f,5.5376e-05f, 0.994103f,0.0559188f,-0.0398751f,1.04046f,0.456195f,6.00291e-05f,
0.992831f,0.0637349f,-0.045488f,1.03995f,0.456667f,6.55991e-05f, 0.99155f,0.0714598f,-0.0510571f,1.03935f,0.457207f,7.21718e-05f,
0.990274f,0.0791104f,-0.0565915f,1.03866f,0.457815f,7.9859e-05f, 0.988666f,0.0866529f,-0.0620748f,1.03783f,0.458493f,8.87757e-05f,
0.987011f,0.0941083f,-0.067508f,1.03694f,0.459245f,9.90754e-05f, 0.985611f,0.101463f,-0.0728877f,1.03596f,0.460071f,0.000110908f,
0.984222f,0.108714f,-0.0782091f,1.03492f,0.460975f,0.000124473f, 0.982648f,0.115844f,-0.0834645f,1.0338f,0.461959f,0.000139972f,
0.981078f,0.122864f,-0.0886567f,1.03263f,0.463025f,0.000157647f, 0.979697f,0.129739f,-0.0937747f,1.03139f,0.464179f,0.000177778f,
0.978243f,0.136497f,-0.0988099f,1.03003f,0.465423f,0.00020066f, 0.976915f,0.143077f,-0.103771f,1.02865f,0.46676f,0.000226646f,
0.975569f,0.149537f,-0.108648f,1.02722f,0.468197f,0.000256131f, 0.974262f,0.155848f,-0.113433f,1.02574f,0.469738f,0.000289549f,
0.972811f,0.162058f,-0.118112f,1.02407f,0.471386f,0.000327393f, 0.97128f,0.168193f,-0.122685f,1.02228f,0.473148f,0.000370227f,
0.970498f,0.174279f,-0.12725f,1.02124f,0.475031f,0.00041868f, 0.969403f,0.180295f,-0.131676f,1.01984f,0.477041f,0.000473453f,
0.967026f,0.186215f,-0.135926f,1.01788f,0.479184f,0.000535339f, 0.973899f,0.193369f,-0.139128f,1.00911f,0.481469f,0.000605225f,
0.962162f,0.197647f,-0.14404f,1.01361f,0.483905f,0.000684122f, 0.959056f,0.203169f,-0.147904f,1.01139f,0.486501f,0.00077314f,
0.955903f,0.208609f,-0.151666f,1.00932f,0.489266f,0.000873554f, 0.952647f,0.21383f,-0.155266f,1.00701f,0.492212f,0.000986786f,
0.949066f,0.218851f,-0.158727f,1.00468f,0.495351f,0.00111445f, 0.94575f,0.223838f,-0.162064f,1.00243f,0.498696f,0.00125832f,
0.942862f,0.228744f,-0.1653f,1.00044f,0.502261f,0.00142044f, 0.939899f,0.233473f,-0.168317f,0.998011f,0.506063f,0.00160311f,
0.935921f,0.23794f,-0.171257f,0.996028f,0.510119f,0.00180888f, 0.932374f,0.24229f,-0.174032f,0.993986f,0.514449f,0.00204071f,
0.928953f,0.246505f,-0.176614f,0.991764f,0.519073f,0.00230185f, 0.926814f,0.250835f,-0.179128f,0.990084f,0.524016f,0.00259605f,
0.922244f,0.254495f,-0.181433f,0.988174f,0.529303f,0.00292755f, 0.921991f,0.258358f,-0.183104f,0.983784f,0.534964f,0.00330115f,
0.915271f,0.261645f,-0.185581f,0.984708f,0.541031f,0.0037223f, 0.910502f,0.264556f,-0.18753f,0.983795f,0.547544f,0.00419724f,
0.90528f,0.267217f,-0.189264f,0.982703f,0.554539f,0.00473306f, 0.902625f,0.270338f,-0.19093f,0.982333f,0.56207f,0.00533798f,
0.899463f,0.273053f,-0.192235f,0.981095f,0.570185f,0.00602145f, 0.894054f,0.275023f,-0.193545f,0.980987f,0.578949f,0.00679416f,
0.891773f,0.277608f,-0.19469f,0.981156f,0.588433f,0.0076688f, 0.887897f,0.279441f,-0.195777f,0.982151f,0.598718f,0.00866f,
0.882678f,0.280674f,-0.196522f,0.982621f,0.609901f,0.00978474f, 0.883115f,0.283623f,-0.196793f,0.98193f,0.622096f,0.0110634f,
0.882845f,0.286461f,-0.196733f,0.980917f,0.635442f,0.0125198f, 0.884434f,0.288011f,-0.197087f,0.983335f,0.650104f,0.0141825f,
0.881714f,0.289277f,-0.196481f,0.9824f,0.666284f,0.0160865f, 0.86508f,0.284963f,-0.199893f,1.00314f,0.684235f,0.018274f,
0.862606f,0.285303f,-0.199905f,1.00856f,0.704284f,0.0207983f, 0.861956f,0.286361f,-0.199754f,1.01498f,0.726843f,0.0237266f,
0.860599f,0.286405f,-0.19944f,1.0227f,0.752518f,0.0271478f, 0.860525f,0.28735f,-0.199423f,1.03428f,0.782104f,0.0311826f,
0.852151f,0.283303f,-0.202756f,1.06637f,0.816891f,0.0360063f, 0.852325f,0.282699f,-0.203966f,1.09103f,0.859002f,0.0419014f,
0.85372f,0.281992f,-0.207269f,1.13185f,0.913017f,0.0494248f, 0.865185f,0.280528f,-0.214571f,1.20155f,0.995137f,0.0603451f,
1.0f,-2.54821e-08f,-1.55732e-16f,1.05584f,0.434062f,4.22428e-05f, 0.99989f,0.00699699f,-0.00502223f,1.05583f,0.4341f,4.2557e-05f,
0.999542f,0.0139952f,-0.010048f,1.05576f,0.4342f,4.34774e-05f, 0.998973f,0.0209791f,-0.015058f,1.05567f,0.434372f,4.50347e-05f,
0.998174f,0.0279554f,-0.020065f,1.05552f,0.434611f,4.72468e-05f, 0.997208f,0.0349165f,-0.0250517f,1.05534f,0.434921f,5.01524e-05f,
0.996091f,0.0418476f,-0.030026f,1.0551f,0.435301f,5.3799e-05f, 0.994894f,0.0487243f,-0.0349751f,1.0548f,0.435751f,5.82402e-05f,
0.993662f,0.0555611f,-0.0399012f,1.05446f,0.436275f,6.35557e-05f, 0.992409f,0.0623344f,-0.0447981f,1.05404f,0.436871f,6.98181e-05f,
0.991151f,0.0690235f,-0.0496599f,1.05358f,0.437546f,7.71389e-05f, 0.989879f,0.0756541f,-0.0544885f,1.05304f,0.438296f,8.56249e-05f,
0.988584f,0.0821997f,-0.0592729f,1.05245f,0.439125f,9.5407e-05f, 0.987249f,0.0886708f,-0.0640141f,1.05179f,0.440037f,0.000106647f,
0.98593f,0.0950652f,-0.0687101f,1.05108f,0.441033f,0.000119508f, 0.984594f,0.101354f,-0.0733493f,1.05031f,0.442116f,0.000134186f,
0.983225f,0.107548f,-0.0779371f,1.0495f,0.443289f,0.000150916f, 0.981817f,0.113631f,-0.082461f,1.04855f,0.444555f,0.000169942f,
0.980419f,0.119608f,-0.0869184f,1.04758f,0.445919f,0.000191548f, 0.979026f,0.125485f,-0.0913147f,1.04661f,0.447383f,0.000216054f,
0.977586f,0.131234f,-0.0956436f,1.04558f,0.448953f,0.000243833f, 0.976196f,0.136856f,-0.0999006f,1.04456f,0.450633f,0.000275289f,
0.974738f,0.142356f,-0.104077f,1.04347f,0.452429f,0.000310879f, 0.973326f,0.147736f,-0.108177f,1.04237f,0.454346f,0.000351124f,
0.971902f,0.152958f,-0.112176f,1.04106f,0.456389f,0.000396602f, 0.970578f,0.158086f,-0.116097f,1.03984f,0.458567f,0.000447971f,
0.969014f,0.163149f,-0.11993f,1.03863f,0.460886f,0.000505965f, 0.973421f,0.16803f,-0.123233f,1.03373f,0.463354f,0.000571409f,
0.96709f,0.17299f,-0.127324f,1.03624f,0.465978f,0.000645236f, 0.964682f,0.177896f,-0.130994f,1.03598f,0.46877f,0.000728498f,
0.962553f,0.182583f,-0.134395f,1.03438f,0.471738f,0.000822374f, 0.962637f,0.187297f,-0.137519f,1.03154f,0.474895f,0.000928174f,
0.957759f,0.191674f,-0.140945f,1.0318f,0.478251f,0.00104739f, 0.954758f,0.196073f,-0.144064f,1.0306f,0.481822f,0.00118174f,
0.951469f,0.20024f,-0.146991f,1.02891f,0.48562f,0.00133308f, 0.948324f,0.204308f,-0.149861f,1.02768f,0.489662f,0.00150357f,
0.94636f,0.208348f,-0.15263f,1.02663f,0.493966f,0.00169563f, 0.948389f,0.213014f,-0.154572f,1.02099f,0.498552f,0.00191199f,
0.939828f,0.215717f,-0.157716f,1.0242f,0.50344f,0.00215575f, 0.937886f,0.219357f,-0.160083f,1.02319f,0.508655f,0.00243044f,
0.934111f,0.222662f,-0.16234f,1.02238f,0.514221f,0.00274003f, 0.930062f,0.225785f,-0.164445f,1.02159f,0.520172f,0.00308907f,
0.9281f,0.229009f,-0.166486f,1.02136f,0.526539f,0.00348273f, 0.92464f,0.231871f,-0.168309f,1.02073f,0.533357f,0.00392698f,
0.920858f,0.234472f,-0.170095f,1.02092f,0.540674f,0.00442855f, 0.916969f,0.236887f,-0.171731f,1.02121f,0.548533f,0.00499522f,
0.914945f,0.239404f,-0.173202f,1.02155f,0.556989f,0.00563613f, 0.910224f,0.241307f,-0.174593f,1.02252f,0.566108f,0.0063615f,
0.908946f,0.243654f,-0.175774f,1.0234f,0.57596f,0.00718342f, 0.904942f,0.245313f,-0.176914f,1.02518f,0.586629f,0.00811621f,
0.900317f,0.246608f,-0.178027f,1.02804f,0.598216f,0.00917619f, 0.899622f,0.248472f,-0.178662f,1.02942f,0.610838f,0.0103832f,
0.899939f,0.250795f,-0.178725f,1.02877f,0.624628f,0.0117604f, 0.900724f,0.252694f,-0.17888f,1.03016f,0.639767f,0.0133358f,
0.888318f,0.250814f,-0.181007f,1.04438f,0.656455f,0.0151436f, 0.88557f,0.251414f,-0.18169f,1.05191f,0.674953f,0.0172257f,
0.883949f,0.251965f,-0.182097f,1.05963f,0.695593f,0.0196345f, 0.881735f,0.252159f,-0.182782f,1.07098f,0.718823f,0.0224372f,
0.878285f,0.251917f,-0.183248f,1.08331f,0.745227f,0.0257221f, 0.87714f,0.251952f,-0.184211f,1.10111f,0.775644f,0.0296109f,
0.876848f,0.25181f,-0.185111f,1.12178f,0.811419f,0.034281f, 0.876417f,0.251616f,-0.186892f,1.15163f,0.854728f,0.0400192f,
0.880323f,0.251531f,-0.189549f,1.19225f,0.910311f,0.0473943f, 0.89094f,0.250605f,-0.196328f,1.26622f,0.994946f,0.0582485f,
1.0f,3.32735e-07f,-4.57709e-17f,1.06876f,0.414009f,4.11325e-05f, 0.999905f,0.0059587f,-0.00431198f,1.06875f,0.414046f,4.14258e-05f,
0.999634f,0.0119149f,-0.00860606f,1.06872f,0.414157f,4.23057e-05f, 0.999185f,0.017868f,-0.0129129f,1.06866f,0.414343f,4.37925e-05f,
0.998579f,0.0238065f,-0.017198f,1.06858f,0.414605f,4.59046e-05f, 0.997805f,0.0297257f,-0.0214803f,1.06846f,0.414942f,4.8676e-05f,
0.996909f,0.0356344f,-0.0257442f,1.06833f,0.415356f,5.21546e-05f, 0.995895f,0.0415184f,-0.0299913f,1.06814f,0.415846f,5.63856e-05f,
0.994817f,0.0473634f,-0.0342197f,1.06793f,0.416417f,6.14468e-05f, 0.993705f,0.0531579f,-0.0384255f,1.06768f,0.417068f,6.74097e-05f,
0.992571f,0.0589035f,-0.0426034f,1.06739f,0.417799f,7.43635e-05f, 0.991445f,0.0645997f,-0.0467521f,1.06707f,0.418615f,8.24244e-05f,
0.990279f,0.0702268f,-0.0508726f,1.0667f,0.419516f,9.17109e-05f, 0.989122f,0.075794f,-0.0549525f,1.0663f,0.420506f,0.000102362f,
0.987932f,0.081291f,-0.0589949f,1.06584f,0.421585f,0.000114538f, 0.986359f,0.0867193f,-0.0629965f,1.0653f,0.422758f,0.000128428f,
0.985118f,0.0920722f,-0.0669531f,1.0648f,0.424028f,0.000144237f, 0.983817f,0.097364f,-0.0708644f,1.06423f,0.425397f,0.000162199f,
0.982504f,0.102557f,-0.0747275f,1.06366f,0.426869f,0.000182578f, 0.981182f,0.107682f,-0.0785353f,1.06309f,0.42845f,0.000205672f,
0.979831f,0.11271f,-0.0822902f,1.06249f,0.430141f,0.00023182f, 0.978396f,0.117643f,-0.0859858f,1.06184f,0.431949f,0.0002614f,
0.976936f,0.122482f,-0.0896195f,1.0612f,0.433879f,0.000294841f, 0.975343f,0.127209f,-0.093189f,1.06054f,0.435937f,0.000332622f,
0.973765f,0.131835f,-0.0966976f,1.05992f,0.438128f,0.000375284f, 0.97206f,0.136338f,-0.100118f,1.05908f,0.440459f,0.000423434f,
0.970362f,0.140759f,-0.10348f,1.0584f,0.442937f,0.000477751f, 0.969878f,0.144971f,-0.106795f,1.05801f,0.445572f,0.000539013f,
0.968181f,0.149171f,-0.110007f,1.05737f,0.44837f,0.000608092f, 0.966645f,0.153188f,-0.11312f,1.05656f,0.451342f,0.000685944f,
0.964801f,0.157192f,-0.116165f,1.05591f,0.454497f,0.000773668f, 0.962842f,0.161096f,-0.119123f,1.05525f,0.457847f,0.000872525f,
0.963019f,0.164773f,-0.121916f,1.05398f,0.461404f,0.000983871f, 0.960609f,0.16851f,-0.124853f,1.05474f,0.465182f,0.00110931f,
0.965289f,0.171818f,-0.127087f,1.05045f,0.469194f,0.00125061f, 0.956387f,0.175714f,-0.130243f,1.0546f,0.473458f,0.00140975f,
0.954525f,0.179095f,-0.132717f,1.05397f,0.47799f,0.00158903f, 0.952124f,0.182418f,-0.13513f,1.05377f,0.482812f,0.00179102f,
0.957049f,0.18592f,-0.136721f,1.04813f,0.487945f,0.00201862f, 0.948331f,0.18861f,-0.139677f,1.05383f,0.493412f,0.00227516f,
0.945035f,0.191512f,-0.141778f,1.05387f,0.49924f,0.00256442f, 0.941635f,0.194267f,-0.143744f,1.0539f,0.505462f,0.00289065f,
0.939595f,0.196997f,-0.145666f,1.0545f,0.512107f,0.00325882f, 0.936959f,0.199532f,-0.147438f,1.05505f,0.519218f,0.00367451f,
0.935215f,0.202004f,-0.149138f,1.05604f,0.526834f,0.00414423f, 0.930943f,0.204159f,-0.150729f,1.05727f,0.535004f,0.00467541f,
0.931938f,0.206458f,-0.151891f,1.05658f,0.543785f,0.00527663f, 0.925094f,0.208067f,-0.153547f,1.06042f,0.553243f,0.00595794f,
0.92336f,0.209986f,-0.154887f,1.0632f,0.563448f,0.00673092f, 0.920524f,0.211594f,-0.155997f,1.06563f,0.574489f,0.0076091f,
0.91717f,0.213015f,-0.157103f,1.06923f,0.586467f,0.00860888f, 0.915523f,0.214377f,-0.158107f,1.07338f,0.599496f,0.00974897f,
0.911373f,0.215403f,-0.158933f,1.07777f,0.613728f,0.0110521f, 0.910635f,0.216535f,-0.15981f,1.08396f,0.629331f,0.0125458f,
0.907983f,0.217313f,-0.160555f,1.0908f,0.646519f,0.0142636f, 0.905232f,0.217959f,-0.161268f,1.09909f,0.665556f,0.0162467f,
0.903604f,0.218498f,-0.161954f,1.10919f,0.686799f,0.0185468f, 0.902225f,0.218899f,-0.162624f,1.12122f,0.710683f,0.0212311f,
0.899075f,0.219051f,-0.16333f,1.13583f,0.737825f,0.0243878f, 0.898433f,0.219263f,-0.164296f,1.15501f,0.769091f,0.0281387f,
0.898652f,0.219428f,-0.165353f,1.1781f,0.805835f,0.0326635f, 0.898166f,0.219574f,-0.167148f,1.21081f,0.850386f,0.0382537f,
0.901535f,0.219717f,-0.169866f,1.25578f,0.907524f,0.0454894f, 0.914291f,0.219761f,-0.176149f,1.33521f,0.994752f,0.05629f,
0.999996f,1.94827e-06f,-1.8587e-17f,1.08078f,0.394545f,3.99652e-05f, 0.999932f,0.00492208f,-0.00358224f,1.08078f,0.394583f,4.02378e-05f,
0.999736f,0.00984909f,-0.00716325f,1.08076f,0.394702f,4.1077e-05f, 0.999405f,0.0147633f,-0.01074f,1.08074f,0.394903f,4.24961e-05f,
0.998937f,0.0196754f,-0.0143108f,1.0807f,0.395183f,4.45052e-05f, 0.998345f,0.0245717f,-0.0178685f,1.08065f,0.395546f,4.71469e-05f,
0.997631f,0.0294617f,-0.0214244f,1.08059f,0.395989f,5.0457e-05f, 0.996825f,0.034328f,-0.024957f,1.08051f,0.396517f,5.44856e-05f,
0.995926f,0.0391749f,-0.0284807f,1.08043f,0.397128f,5.9292e-05f, 0.994948f,0.043995f,-0.0319822f,1.08032f,0.397827f,6.49579e-05f,
0.993904f,0.0487756f,-0.0354697f,1.08019f,0.398611f,7.15627e-05f, 0.992849f,0.0535216f,-0.0389293f,1.08006f,0.399486f,7.92064e-05f,
0.991756f,0.0582191f,-0.0423671f,1.07991f,0.40045f,8.80022e-05f, 0.990636f,0.06287f,-0.0457767f,1.07974f,0.401509f,9.80832e-05f,
0.989489f,0.0674741f,-0.0491562f,1.07955f,0.402664f,0.000109602f, 0.988296f,0.072019f,-0.0525079f,1.07933f,0.403918f,0.000122727f,
0.987084f,0.0765115f,-0.0558205f,1.0791f,0.405274f,0.00013765f, 0.985847f,0.0809502f,-0.0591004f,1.07888f,0.406736f,0.000154589f,
0.984575f,0.0853326f,-0.062344f,1.07864f,0.408305f,0.000173789f, 0.983288f,0.0896354f,-0.0655403f,1.07837f,0.409989f,0.000195529f,
0.981981f,0.0938834f,-0.0686942f,1.07808f,0.411791f,0.000220121f, 0.980608f,0.0980759f,-0.0718071f,1.07781f,0.413713f,0.000247918f,
0.979199f,0.102195f,-0.0748731f,1.07755f,0.415764f,0.000279318f, 0.977771f,0.10623f,-0.0778866f,1.0773f,0.417949f,0.00031477f,
0.976586f,0.110175f,-0.0808468f,1.07702f,0.420273f,0.000354769f, 0.975114f,0.114073f,-0.0837577f,1.0768f,0.422743f,0.000399878f,
0.973558f,0.117878f,-0.0866094f,1.07655f,0.425366f,0.000450738f, 0.972015f,0.121604f,-0.0894128f,1.07643f,0.42815f,0.000508078f,
0.971076f,0.125233f,-0.0921563f,1.07635f,0.431105f,0.000572672f, 0.969311f,0.12876f,-0.09483f,1.0762f,0.434239f,0.000645464f,
0.967932f,0.132199f,-0.0974549f,1.07627f,0.437564f,0.000727444f, 0.966603f,0.135523f,-0.100006f,1.07629f,0.441089f,0.000819793f,
0.964779f,0.138778f,-0.102479f,1.07626f,0.444829f,0.000923792f, 0.962731f,0.141949f,-0.104876f,1.07625f,0.448795f,0.00104092f,
0.96109f,0.145012f,-0.107223f,1.07651f,0.453004f,0.00117284f, 0.959384f,0.147949f,-0.109471f,1.07662f,0.457471f,0.00132144f,
0.957423f,0.150845f,-0.111679f,1.07714f,0.462214f,0.00148883f, 0.956702f,0.153493f,-0.113801f,1.07763f,0.467252f,0.00167744f,
0.954486f,0.156196f,-0.115841f,1.07829f,0.472611f,0.00189001f, 0.953383f,0.158696f,-0.117831f,1.07931f,0.478312f,0.0021297f,
0.951375f,0.161107f,-0.119684f,1.07996f,0.484382f,0.00240004f, 0.956445f,0.163042f,-0.121084f,1.07752f,0.490854f,0.00270509f,
0.948566f,0.165639f,-0.123297f,1.08324f,0.497762f,0.00304955f, 0.948147f,0.167714f,-0.12483f,1.08386f,0.505141f,0.00343876f,
0.955221f,0.169689f,-0.125762f,1.08035f,0.51304f,0.00387886f, 0.942885f,0.171786f,-0.128015f,1.08923f,0.521506f,0.00437699f,
0.940804f,0.173558f,-0.129387f,1.09158f,0.530596f,0.00494136f, 0.938607f,0.175258f,-0.130683f,1.09437f,0.540374f,0.00558162f,
0.936842f,0.176862f,-0.131904f,1.09769f,0.550917f,0.00630891f, 0.93488f,0.178336f,-0.133045f,1.10159f,0.562315f,0.00713643f,
0.936197f,0.179294f,-0.133742f,1.10296f,0.574664f,0.00807972f, 0.948258f,0.18154f,-0.135465f,1.11424f,0.588098f,0.00915726f,
0.928872f,0.181909f,-0.136011f,1.1172f,0.602754f,0.0103912f, 0.927036f,0.182821f,-0.136828f,1.12387f,0.618813f,0.0118085f,
0.925899f,0.183679f,-0.137682f,1.13241f,0.636492f,0.0134417f, 0.923102f,0.184366f,-0.13836f,1.14139f,0.656072f,0.0153318f,
0.921757f,0.18498f,-0.13916f,1.1532f,0.677894f,0.0175298f, 0.920854f,0.185472f,-0.139827f,1.16618f,0.702433f,0.0201026f,
0.918787f,0.185886f,-0.140676f,1.18319f,0.730321f,0.0231382f, 0.918156f,0.186228f,-0.141534f,1.20311f,0.762442f,0.0267591f,
0.918332f,0.186467f,-0.142601f,1.22832f,0.800203f,0.0311466f, 0.919029f,0.186918f,-0.144311f,1.26339f,0.84595f,0.0365974f,
0.923419f,0.187182f,-0.146825f,1.31165f,0.904712f,0.0437056f, 0.936797f,0.187915f,-0.152048f,1.39276f,0.994552f,0.0544597f,
0.999997f,-2.40098e-06f,1.18911e-17f,1.09191f,0.375695f,3.87386e-05f, 0.999954f,0.0038945f,-0.00284754f,1.09191f,0.375738f,3.90032e-05f,
0.999808f,0.00780536f,-0.00571229f,1.09192f,0.375866f,3.98054e-05f, 0.999571f,0.0117048f,-0.00856613f,1.09192f,0.376078f,4.1153e-05f,
0.999244f,0.01559f,-0.0114065f,1.09193f,0.376376f,4.30665e-05f, 0.998826f,0.0194706f,-0.0142509f,1.09194f,0.376759f,4.55753e-05f,
0.998323f,0.0233457f,-0.0170808f,1.09196f,0.377231f,4.87231e-05f, 0.997736f,0.0272056f,-0.0199064f,1.09196f,0.37779f,5.25504e-05f,
0.99707f,0.0310496f,-0.0227156f,1.09198f,0.378438f,5.71162e-05f, 0.996342f,0.0348783f,-0.0255135f,1.092f,0.379177f,6.24875e-05f,
0.995536f,0.0386881f,-0.0282946f,1.09201f,0.380008f,6.87451e-05f, 0.994694f,0.0424727f,-0.0310627f,1.09203f,0.380933f,7.59838e-05f,
0.993802f,0.0462278f,-0.0338101f,1.09205f,0.381955f,8.43098e-05f, 0.992874f,0.0499499f,-0.0365425f,1.09208f,0.383075f,9.38438e-05f,
0.991911f,0.0536433f,-0.0392461f,1.09209f,0.384297f,0.000104726f, 0.990932f,0.0572977f,-0.0419331f,1.09212f,0.385621f,0.000117113f,
0.989923f,0.0609127f,-0.0445916f,1.09216f,0.387054f,0.000131185f, 0.988905f,0.0644902f,-0.0472242f,1.09221f,0.388597f,0.000147144f,
0.987849f,0.0680227f,-0.0498327f,1.09227f,0.390253f,0.000165222f, 0.986778f,0.0715173f,-0.0524085f,1.09236f,0.392029f,0.000185674f,
0.985594f,0.0749571f,-0.0549508f,1.09244f,0.393927f,0.000208789f, 0.984378f,0.0783486f,-0.0574629f,1.09254f,0.395951f,0.000234893f,
0.983144f,0.0816909f,-0.059941f,1.09266f,0.398109f,0.000264356f, 0.981853f,0.0849749f,-0.0623788f,1.09278f,0.400406f,0.000297604f,
0.980562f,0.0882085f,-0.0647803f,1.09297f,0.402848f,0.000335087f, 0.979251f,0.0913813f,-0.0671373f,1.0931f,0.405441f,0.000377333f,
0.97789f,0.0945021f,-0.0694602f,1.09334f,0.408193f,0.000424953f, 0.976465f,0.0975719f,-0.0717385f,1.09362f,0.411112f,0.00047858f,
0.975248f,0.100562f,-0.0739697f,1.09388f,0.414207f,0.000539001f, 0.973782f,0.103504f,-0.0761563f,1.09423f,0.417487f,0.000607033f,
0.972754f,0.106365f,-0.0782998f,1.09471f,0.420963f,0.000683642f, 0.971246f,0.109183f,-0.0803875f,1.09515f,0.424647f,0.000769916f,
0.970311f,0.111914f,-0.0824414f,1.09589f,0.42855f,0.000867058f, 0.968662f,0.114552f,-0.0844258f,1.09648f,0.432687f,0.00097644f,
0.966852f,0.117146f,-0.0863672f,1.09725f,0.437071f,0.00109963f, 0.965159f,0.119678f,-0.0882492f,1.09808f,0.441721f,0.00123839f,
0.96347f,0.122104f,-0.0900673f,1.09898f,0.446656f,0.00139472f, 0.961944f,0.124466f,-0.0918312f,1.1f,0.451894f,0.0015709f,
0.960527f,0.126729f,-0.0935461f,1.10128f,0.457457f,0.0017695f, 0.959638f,0.128889f,-0.0952114f,1.10286f,0.463373f,0.00199352f,
0.957918f,0.130996f,-0.0967929f,1.10432f,0.469666f,0.00224626f, 0.955612f,0.133029f,-0.0983173f,1.106f,0.47637f,0.00253165f,
0.954299f,0.134911f,-0.0997866f,1.10809f,0.48352f,0.00285407f, 0.952289f,0.136786f,-0.101191f,1.11037f,0.491153f,0.00321861f,
0.951591f,0.138428f,-0.102542f,1.11302f,0.499316f,0.00363119f, 0.949466f,0.140114f,-0.103818f,1.11589f,0.508058f,0.00409857f,
0.947863f,0.141646f,-0.105025f,1.1191f,0.517438f,0.00462862f, 0.946952f,0.143016f,-0.106192f,1.12292f,0.527521f,0.00523064f,
0.945087f,0.144366f,-0.107258f,1.12683f,0.538385f,0.00591536f, 0.943655f,0.145628f,-0.108288f,1.13165f,0.550124f,0.0066955f,
0.9421f,0.146729f,-0.109258f,1.13706f,0.562837f,0.00758611f, 0.940591f,0.147746f,-0.110147f,1.14293f,0.576652f,0.00860516f,
0.939888f,0.148675f,-0.111018f,1.15009f,0.591721f,0.0097743f, 0.937966f,0.149518f,-0.111782f,1.15772f,0.608228f,0.0111197f,
0.937437f,0.150206f,-0.112571f,1.16713f,0.62639f,0.0126736f, 0.935588f,0.150913f,-0.113266f,1.17757f,0.646502f,0.0144762f,
0.935236f,0.151409f,-0.113992f,1.19027f,0.668914f,0.0165783f, 0.934591f,0.151901f,-0.114688f,1.20482f,0.694103f,0.0190459f,
0.933846f,0.152349f,-0.115483f,1.22317f,0.722726f,0.0219672f, 0.933823f,0.152693f,-0.116323f,1.24493f,0.755705f,0.0254653f,
0.935005f,0.152924f,-0.117345f,1.27226f,0.794476f,0.0297235f, 0.937813f,0.153242f,-0.118725f,1.30819f,0.841482f,0.0350427f,
0.948901f,0.154808f,-0.120129f,1.35048f,0.901908f,0.0420336f, 0.955931f,0.155394f,-0.125527f,1.4469f,0.994349f,0.0527482f,
1.0f,1.47174e-06f,-1.30817e-17f,1.10219f,0.357486f,3.74763e-05f, 0.999974f,0.00289324f,-0.00213369f,1.1022f,0.357534f,3.77347e-05f,
0.999878f,0.00578396f,-0.00426155f,1.10222f,0.357669f,3.84999e-05f, 0.999728f,0.00868245f,-0.00639086f,1.10226f,0.357892f,3.97801e-05f,
0.999514f,0.0115676f,-0.00851808f,1.1023f,0.358203f,4.15961e-05f, 0.999246f,0.0144413f,-0.010631f,1.10236f,0.358606f,4.39791e-05f,
0.998911f,0.0173231f,-0.0127473f,1.10244f,0.3591f,4.69639e-05f, 0.998516f,0.0201881f,-0.0148574f,1.10252f,0.359686f,5.05942e-05f,
0.998066f,0.0230421f,-0.0169551f,1.10263f,0.360367f,5.49235e-05f, 0.997566f,0.0258901f,-0.0190509f,1.10275f,0.361141f,6.00133e-05f,
0.997015f,0.0287162f,-0.0211278f,1.10289f,0.362013f,6.594e-05f, 0.9964f,0.0315367f,-0.0232017f,1.10304f,0.362982f,7.27878e-05f,
0.995736f,0.0343334f,-0.0252545f,1.10321f,0.364053f,8.06577e-05f, 0.995044f,0.0371184f,-0.0273017f,1.1034f,0.365225f,8.96618e-05f,
0.994303f,0.039883f,-0.0293264f,1.10361f,0.366504f,9.99306e-05f, 0.99352f,0.0426181f,-0.0313421f,1.10384f,0.36789f,0.000111612f,
0.992728f,0.0453406f,-0.0333388f,1.10409f,0.369388f,0.000124875f, 0.991892f,0.0480274f,-0.0353159f,1.10437f,0.371002f,0.000139902f,
0.99105f,0.0506898f,-0.0372778f,1.10469f,0.372732f,0.000156904f, 0.990189f,0.0533241f,-0.0392135f,1.10503f,0.374587f,0.000176122f,
0.989389f,0.0559214f,-0.0411302f,1.1054f,0.376569f,0.000197839f, 0.988462f,0.0584972f,-0.0430265f,1.1058f,0.378683f,0.000222343f,
0.98752f,0.061031f,-0.0448977f,1.10623f,0.380933f,0.000249976f, 0.986554f,0.0635367f,-0.0467432f,1.10672f,0.383328f,0.000281144f,
0.985563f,0.0660071f,-0.0485597f,1.10725f,0.385873f,0.000316252f, 0.984563f,0.0684382f,-0.0503534f,1.10783f,0.388574f,0.000355821f,
0.983447f,0.0708227f,-0.052117f,1.10847f,0.391439f,0.000400367f, 0.982288f,0.0731835f,-0.0538521f,1.10914f,0.394476f,0.000450545f,
0.981155f,0.0754778f,-0.0555552f,1.10986f,0.397694f,0.000507037f, 0.979978f,0.0777518f,-0.057228f,1.1107f,0.401102f,0.000570623f,
0.978871f,0.0799713f,-0.0588649f,1.11155f,0.404713f,0.000642209f, 0.977641f,0.0821383f,-0.0604696f,1.1125f,0.408536f,0.000722805f,
0.976651f,0.08427f,-0.0620415f,1.11355f,0.412584f,0.000813544f, 0.975728f,0.086341f,-0.06358f,1.11473f,0.416872f,0.000915708f,
0.974492f,0.0883741f,-0.0650748f,1.11601f,0.421416f,0.00103076f, 0.973172f,0.0903514f,-0.0665325f,1.1174f,0.426232f,0.00116036f,
0.971881f,0.0922578f,-0.0679577f,1.11891f,0.431337f,0.00130641f, 0.970411f,0.0941367f,-0.0693317f,1.12056f,0.436755f,0.00147102f,
0.969258f,0.0959289f,-0.0706725f,1.12233f,0.442504f,0.00165663f, 0.968285f,0.097661f,-0.0719644f,1.12433f,0.448616f,0.00186607f,
0.966955f,0.0993741f,-0.0732233f,1.12656f,0.455113f,0.00210249f, 0.965636f,0.100996f,-0.0744388f,1.129f,0.462029f,0.00236954f,
0.964297f,0.102551f,-0.0755991f,1.13162f,0.469402f,0.00267146f, 0.963235f,0.104023f,-0.0767143f,1.13448f,0.47727f,0.00301308f,
0.961943f,0.105444f,-0.0777911f,1.13771f,0.485678f,0.00340003f, 0.96047f,0.106831f,-0.0788303f,1.14136f,0.494677f,0.00383879f,
0.959125f,0.108107f,-0.0798035f,1.14524f,0.50433f,0.00433688f, 0.958185f,0.109281f,-0.0807393f,1.14966f,0.514703f,0.00490326f,
0.956886f,0.110415f,-0.0816381f,1.15459f,0.525872f,0.00554823f, 0.955839f,0.111473f,-0.0824797f,1.16001f,0.537935f,0.00628413f,
0.954543f,0.112455f,-0.0832827f,1.16622f,0.550996f,0.00712551f, 0.953415f,0.11336f,-0.0840386f,1.17307f,0.565185f,0.0080898f,
0.952692f,0.114125f,-0.0847673f,1.18091f,0.580653f,0.00919815f, 0.951484f,0.114893f,-0.0854567f,1.18995f,0.597593f,0.0104762f,
0.950867f,0.115537f,-0.0861092f,1.19996f,0.61623f,0.0119556f, 0.949952f,0.116102f,-0.0867526f,1.21191f,0.636861f,0.0136758f,
0.949653f,0.116567f,-0.0873806f,1.22554f,0.659846f,0.0156874f, 0.948807f,0.117017f,-0.0880003f,1.24172f,0.685693f,0.0180557f,
0.949158f,0.117358f,-0.0887003f,1.26148f,0.715048f,0.0208689f, 0.949013f,0.117674f,-0.0894685f,1.28543f,0.748888f,0.0242508f,
0.94961f,0.117957f,-0.0904669f,1.31632f,0.788659f,0.028386f, 0.951601f,0.118368f,-0.0917886f,1.35705f,0.836911f,0.0335805f,
0.955097f,0.118999f,-0.0938955f,1.41639f,0.899029f,0.0404605f, 0.96051f,0.121144f,-0.0985307f,1.52393f,0.994141f,0.0511471f,
0.999999f,-1.22254e-06f,-1.04881e-16f,1.11165f,0.339943f,3.62082e-05f, 0.999978f,0.00191104f,-0.0014193f,1.11165f,0.339989f,3.64465e-05f,
0.999933f,0.0038142f,-0.00283109f,1.11169f,0.340127f,3.71681e-05f, 0.99984f,0.00571789f,-0.00423438f,1.11176f,0.340359f,3.83845e-05f,
0.99972f,0.00761641f,-0.00563902f,1.11184f,0.340685f,4.01102e-05f, 0.999565f,0.00951654f,-0.00704767f,1.11196f,0.341102f,4.23698e-05f,
0.999369f,0.0114101f,-0.00844879f,1.11209f,0.341615f,4.51988e-05f, 0.999148f,0.0132973f,-0.00984208f,1.11226f,0.342225f,4.86385e-05f,
0.998894f,0.0151813f,-0.011239f,1.11245f,0.34293f,5.27365e-05f, 0.99861f,0.0170533f,-0.0126245f,1.11267f,0.343735f,5.75537e-05f,
0.998283f,0.0189241f,-0.0140037f,1.11291f,0.34464f,6.31582e-05f, 0.997938f,0.0207814f,-0.0153809f,1.11319f,0.345646f,6.96293e-05f,
0.997555f,0.0226305f,-0.0167426f,1.11349f,0.346758f,7.70599e-05f, 0.997152f,0.0244692f,-0.0181038f,1.11383f,0.347974f,8.55547e-05f,
0.996716f,0.0262931f,-0.0194499f,1.11421f,0.349301f,9.52396e-05f, 0.996247f,0.0281112f,-0.020794f,1.1146f,0.350739f,0.00010625f,
0.995763f,0.0299052f,-0.0221218f,1.11505f,0.352293f,0.000118732f, 0.99524f,0.0316948f,-0.0234373f,1.11552f,0.353965f,0.000132863f,
0.994695f,0.0334698f,-0.0247502f,1.11604f,0.355759f,0.000148856f, 0.994104f,0.0352235f,-0.0260402f,1.11661f,0.357682f,0.000166912f,
0.993499f,0.0369557f,-0.0273209f,1.11722f,0.359734f,0.000187294f, 0.992869f,0.0386811f,-0.0285915f,1.11788f,0.361923f,0.000210285f,
0.99225f,0.0403839f,-0.0298463f,1.11859f,0.364253f,0.000236199f, 0.991617f,0.0420566f,-0.0310809f,1.11936f,0.366732f,0.000265398f,
0.990993f,0.0437142f,-0.0323022f,1.12019f,0.369365f,0.00029829f, 0.990298f,0.045353f,-0.0335062f,1.12109f,0.372158f,0.000335312f,
0.98958f,0.0469658f,-0.0346951f,1.12204f,0.37512f,0.000377007f, 0.988852f,0.0485526f,-0.0358659f,1.12307f,0.378259f,0.000423938f,
0.988116f,0.0501185f,-0.0370167f,1.12416f,0.381583f,0.000476752f, 0.987363f,0.0516542f,-0.0381478f,1.12534f,0.385104f,0.000536188f,
0.986549f,0.0531644f,-0.03926f,1.12662f,0.38883f,0.000603084f, 0.985735f,0.0546517f,-0.040354f,1.12801f,0.392775f,0.000678384f,
0.984959f,0.0561054f,-0.0414261f,1.1295f,0.396951f,0.000763153f, 0.984271f,0.0575197f,-0.0424704f,1.13111f,0.401374f,0.000858597f,
0.983406f,0.0589159f,-0.0434932f,1.13282f,0.406058f,0.000966077f, 0.982559f,0.0602769f,-0.0444965f,1.13463f,0.411018f,0.00108715f,
0.981759f,0.0616071f,-0.0454689f,1.13664f,0.416278f,0.00122362f, 0.980863f,0.0628999f,-0.0464263f,1.13882f,0.421854f,0.00137746f,
0.980037f,0.0641579f,-0.0473481f,1.14117f,0.427774f,0.00155101f, 0.979235f,0.0653607f,-0.0482473f,1.14369f,0.43406f,0.00174685f,
0.978327f,0.0665484f,-0.0491227f,1.1464f,0.440741f,0.00196808f, 0.977568f,0.0676995f,-0.0499699f,1.14936f,0.447852f,0.00221813f,
0.976696f,0.0688021f,-0.0507897f,1.15264f,0.455428f,0.00250098f, 0.975834f,0.0698542f,-0.051579f,1.15617f,0.463511f,0.00282126f,
0.9749f,0.0708551f,-0.0523328f,1.15995f,0.472146f,0.00318432f, 0.974134f,0.0718319f,-0.0530604f,1.16417f,0.481389f,0.00359642f,
0.97344f,0.0727374f,-0.0537697f,1.16884f,0.491294f,0.0040647f, 0.972436f,0.0736323f,-0.0544338f,1.17385f,0.501938f,0.00459781f,
0.971723f,0.0744561f,-0.0550837f,1.17943f,0.513396f,0.00520568f, 0.971042f,0.0752309f,-0.0557011f,1.18569f,0.525767f,0.0059002f,
0.97016f,0.0759598f,-0.0562846f,1.19253f,0.539159f,0.00669546f, 0.969605f,0.0766125f,-0.0568445f,1.20028f,0.553705f,0.00760855f,
0.968887f,0.077236f,-0.05737f,1.20892f,0.569566f,0.0086599f, 0.96823f,0.0777906f,-0.0578931f,1.21876f,0.586923f,0.00987466f,
0.967768f,0.0783018f,-0.0583905f,1.22992f,0.606026f,0.0112839f, 0.967367f,0.0787437f,-0.0588775f,1.2428f,0.627164f,0.0129266f,
0.96706f,0.0791557f,-0.0593457f,1.25774f,0.65073f,0.0148525f, 0.966739f,0.0794937f,-0.0598569f,1.27547f,0.677206f,0.0171272f,
0.966812f,0.0797924f,-0.0603911f,1.29675f,0.707298f,0.0198382f, 0.967122f,0.0800915f,-0.0609858f,1.32281f,0.742001f,0.02311f,
0.967522f,0.0804079f,-0.0617517f,1.35636f,0.782797f,0.0271286f, 0.968526f,0.0807871f,-0.0627911f,1.40117f,0.83233f,0.0322067f,
0.970631f,0.0814349f,-0.0644565f,1.46722f,0.896078f,0.038979f, 0.974287f,0.0833062f,-0.0679795f,1.58663f,0.993928f,0.0496483f,
1.0f,-1.93946e-06f,2.57983e-17f,1.12032f,0.323064f,3.49186e-05f, 0.999997f,0.000941647f,-0.000701914f,1.12033f,0.323111f,3.51452e-05f,
0.999968f,0.00188272f,-0.0014049f,1.12038f,0.323253f,3.58281e-05f, 0.999934f,0.00282811f,-0.00211003f,1.12047f,0.32349f,3.69769e-05f,
0.999886f,0.00375839f,-0.00280501f,1.1206f,0.323825f,3.86113e-05f, 0.999817f,0.00469773f,-0.00349531f,1.12075f,0.324257f,4.07534e-05f,
0.99974f,0.00562801f,-0.00418767f,1.12095f,0.324786f,4.3432e-05f, 0.999654f,0.00656233f,-0.00488527f,1.12119f,0.325412f,4.66843e-05f,
0.99954f,0.00749025f,-0.00557523f,1.12145f,0.326139f,5.05583e-05f, 0.99943f,0.00841452f,-0.00625932f,1.12177f,0.326968f,5.51121e-05f,
0.999294f,0.00934635f,-0.00695483f,1.12212f,0.3279f,6.04111e-05f, 0.999144f,0.0102638f,-0.00763624f,1.12251f,0.328937f,6.65223e-05f,
0.998976f,0.011173f,-0.00831197f,1.12294f,0.330081f,7.35309e-05f, 0.998806f,0.0120826f,-0.00899075f,1.12342f,0.331333f,8.15399e-05f,
0.998609f,0.0129917f,-0.00966213f,1.12394f,0.3327f,9.06715e-05f, 0.998415f,0.0138897f,-0.0103316f,1.12451f,0.334179f,0.000101029f,
0.998194f,0.0147823f,-0.0109931f,1.12512f,0.335779f,0.000112777f, 0.997973f,0.0156712f,-0.0116516f,1.12579f,0.3375f,0.00012607f,
0.997732f,0.0165491f,-0.0123087f,1.12651f,0.339345f,0.000141085f, 0.997477f,0.0174167f,-0.0129507f,1.12729f,0.341324f,0.000158047f,
0.997218f,0.0182795f,-0.013593f,1.12812f,0.343435f,0.000177174f, 0.996952f,0.0191397f,-0.0142316f,1.12901f,0.345685f,0.00019873f,
0.996668f,0.0199905f,-0.0148608f,1.12996f,0.348083f,0.000223029f, 0.996391f,0.0208234f,-0.0154776f,1.13098f,0.350631f,0.000250377f,
0.996071f,0.0216496f,-0.0160901f,1.13207f,0.353337f,0.000281165f, 0.995759f,0.022474f,-0.016698f,1.13323f,0.356207f,0.000315832f,
0.995445f,0.0232808f,-0.017298f,1.13448f,0.359251f,0.00035484f, 0.995106f,0.0240822f,-0.0178889f,1.13582f,0.362475f,0.000398728f,
0.994754f,0.0248656f,-0.0184708f,1.13724f,0.36589f,0.000448107f, 0.994408f,0.0256433f,-0.0190443f,1.13877f,0.369506f,0.000503667f,
0.99404f,0.0264029f,-0.0196102f,1.14038f,0.373332f,0.000566187f, 0.993686f,0.0271563f,-0.0201696f,1.1421f,0.377381f,0.000636543f,
0.9933f,0.0278881f,-0.0207087f,1.14395f,0.381668f,0.000715731f, 0.99295f,0.028605f,-0.0212403f,1.14593f,0.386207f,0.000804902f,
0.992544f,0.0293216f,-0.0217731f,1.14805f,0.39101f,0.000905351f, 0.992149f,0.0300036f,-0.0222769f,1.15031f,0.3961f,0.00101848f,
0.991745f,0.0306869f,-0.0227875f,1.15274f,0.401492f,0.00114605f, 0.991342f,0.0313485f,-0.0232679f,1.15531f,0.407212f,0.00128985f,
0.990952f,0.0319889f,-0.0237484f,1.15811f,0.413279f,0.00145217f, 0.990543f,0.0326239f,-0.0242199f,1.16113f,0.419722f,0.00163544f,
0.990123f,0.0332353f,-0.0246756f,1.16437f,0.426569f,0.00184252f, 0.989685f,0.0338323f,-0.0251154f,1.16782f,0.433856f,0.00207671f,
0.98931f,0.0343934f,-0.0255428f,1.17157f,0.441618f,0.00234182f, 0.988896f,0.0349504f,-0.0259526f,1.17567f,0.449898f,0.00264223f,
0.988442f,0.0354885f,-0.0263479f,1.18009f,0.458743f,0.00298303f, 0.98806f,0.0359967f,-0.0267429f,1.18485f,0.468204f,0.00337027f,
0.98768f,0.0364874f,-0.0271075f,1.19011f,0.47835f,0.00381074f, 0.987234f,0.0369618f,-0.0274735f,1.19583f,0.489244f,0.00431279f,
0.98685f,0.0374134f,-0.0278234f,1.20209f,0.500975f,0.00488598f, 0.986476f,0.037822f,-0.0281558f,1.20903f,0.513638f,0.00554178f,
0.986063f,0.0382188f,-0.0284689f,1.21668f,0.527348f,0.00629395f, 0.985766f,0.0385949f,-0.0287696f,1.22522f,0.54224f,0.0071589f,
0.98536f,0.038953f,-0.0290745f,1.23478f,0.558466f,0.00815678f, 0.985112f,0.0392783f,-0.0293588f,1.24551f,0.576239f,0.00931205f,
0.984779f,0.0395852f,-0.0296392f,1.25778f,0.595792f,0.0106552f, 0.984547f,0.0398548f,-0.0299072f,1.27176f,0.617433f,0.0122248f,
0.984321f,0.0401009f,-0.0301849f,1.28806f,0.641558f,0.0140701f, 0.984194f,0.0403171f,-0.0304689f,1.30725f,0.66868f,0.016256f,
0.984072f,0.0405387f,-0.0307831f,1.33029f,0.699499f,0.0188703f, 0.984166f,0.0407389f,-0.0311303f,1.35875f,0.73505f,0.0220376f,
0.984321f,0.0409582f,-0.0315662f,1.39493f,0.776877f,0.0259465f, 0.984806f,0.0412708f,-0.0321697f,1.44369f,0.827646f,0.0309116f,
0.985552f,0.0417273f,-0.0331089f,1.51564f,0.893089f,0.037586f, 0.987388f,0.0428531f,-0.0350919f,1.64747f,0.993712f,0.0482446f,
0.999999f,1.37191e-06f,-7.7813e-17f,1.12822f,0.306855f,3.36198e-05f, 1.0f,8.85742e-07f,-2.19791e-16f,1.12824f,0.306903f,3.38347e-05f,
0.999998f,3.07393e-06f,-7.82808e-17f,1.1283f,0.307049f,3.44822e-05f, 1.0f,-2.26771e-06f,-2.29701e-17f,1.12842f,0.307293f,3.55708e-05f,
1.0f,8.30245e-07f,1.59766e-17f,1.12858f,0.307633f,3.71148e-05f, 0.999996f,7.58773e-07f,-1.69682e-16f,1.12879f,0.308071f,3.9134e-05f,
0.999993f,-3.40995e-06f,-1.26354e-16f,1.12905f,0.308612f,4.16669e-05f, 1.00001f,1.70373e-06f,-2.11828e-16f,1.12936f,0.309257f,4.47539e-05f,
1.0f,2.91235e-06f,-2.03593e-17f,1.12972f,0.310002f,4.84203e-05f, 0.999997f,-1.17932e-06f,-1.17896e-16f,1.13011f,0.310846f,5.27121e-05f,
0.999999f,-7.8801e-07f,-6.40791e-17f,1.13057f,0.311798f,5.77068e-05f, 0.999998f,-1.26748e-06f,-4.6115e-17f,1.13108f,0.312862f,6.34842e-05f,
1.0f,9.6742e-07f,-1.71327e-16f,1.13164f,0.314027f,7.00812e-05f, 0.999998f,-3.55991e-06f,-1.02576e-16f,1.13225f,0.315311f,7.76399e-05f,
1.0f,-2.76582e-06f,-6.15667e-17f,1.13293f,0.316706f,8.62294e-05f, 1.0f,3.83509e-06f,3.66943e-17f,1.13365f,0.31822f,9.59793e-05f,
0.999996f,-1.46569e-06f,-1.6618e-16f,1.13444f,0.319854f,0.000107024f, 0.999999f,-3.46299e-06f,-5.82408e-17f,1.13529f,0.321614f,0.000119522f,
0.999995f,-3.90609e-06f,-1.33387e-16f,1.13619f,0.323497f,0.0001336f, 1.0f,-1.09063e-06f,-1.33876e-16f,1.13717f,0.325523f,0.000149549f,
0.999994f,6.72796e-07f,7.53416e-17f,1.13822f,0.32768f,0.000167487f, 1.0f,2.25617e-06f,-7.02988e-17f,1.13934f,0.329976f,0.000187663f,
1.0f,-1.20092e-06f,-7.22539e-17f,1.14054f,0.332429f,0.000210451f, 1.0f,-1.39709e-06f,1.87266e-17f,1.14182f,0.335035f,0.000236091f,
0.999996f,2.47824e-06f,-4.96611e-17f,1.14318f,0.337801f,0.000264929f, 0.999993f,3.4718e-08f,1.36443e-16f,1.14462f,0.340734f,0.000297365f,
1.00001f,8.44456e-07f,-7.33772e-17f,1.14616f,0.343844f,0.000333854f, 0.999995f,3.76112e-06f,-4.8863e-17f,1.14778f,0.347139f,0.0003749f,
1.0f,-2.99242e-06f,-1.07653e-16f,1.14952f,0.350628f,0.000421071f, 1.0f,6.9213e-07f,2.57746e-18f,1.15135f,0.354322f,0.000472998f,
1.00001f,-3.06064e-06f,-3.6192e-17f,1.15331f,0.358228f,0.000531385f, 0.999999f,-2.63485e-06f,5.42951e-17f,1.15539f,0.362366f,0.000597138f,
0.999994f,-1.40361e-06f,-1.34993e-16f,1.1576f,0.36675f,0.000671218f, 1.0f,-2.66825e-06f,-1.9204e-17f,1.15997f,0.371382f,0.000754486f,
1.0f,6.46235e-07f,-4.99017e-17f,1.16247f,0.376293f,0.000848403f, 0.999992f,4.80511e-07f,1.47359e-17f,1.16513f,0.381489f,0.000954111f,
0.999994f,1.0121e-06f,-7.35428e-17f,1.16797f,0.387002f,0.00107344f, 1.0f,-4.49258e-06f,-1.97365e-16f,1.17102f,0.392841f,0.00120789f,
1.0f,-3.05954e-06f,1.06661e-17f,1.17425f,0.399035f,0.00135963f, 1.0f,1.8091e-06f,1.55046e-16f,1.17774f,0.40562f,0.00153124f,
0.999995f,-5.28323e-06f,-1.42464e-16f,1.18144f,0.412616f,0.00172517f, 1.00001f,5.64285e-07f,-4.27681e-17f,1.18545f,0.420058f,0.00194455f,
1.0f,-4.21099e-06f,-1.03019e-17f,1.18973f,0.427986f,0.00219308f, 0.999998f,-5.3554e-06f,-6.20113e-17f,1.19434f,0.436448f,0.00247518f,
1.0f,1.52025e-06f,-3.0988e-17f,1.19933f,0.445481f,0.0027952f, 0.999992f,-4.18631e-06f,-2.52188e-17f,1.20474f,0.45515f,0.00315929f,
0.999987f,-1.70318e-07f,-1.45742e-16f,1.21056f,0.465506f,0.00357354f, 0.999999f,5.16816e-06f,-2.61277e-16f,1.21694f,0.476642f,0.00404671f,
0.999985f,8.67487e-06f,-7.67965e-17f,1.22391f,0.488629f,0.00458747f, 1.0f,1.09325e-06f,-2.67223e-17f,1.23155f,0.501563f,0.00520679f,
1.0f,5.47783e-07f,-1.53718e-16f,1.24f,0.51558f,0.00591896f, 0.999994f,3.17438e-06f,-6.12709e-17f,1.24933f,0.530792f,0.00673851f,
1.0f,-5.18836e-06f,-8.9979e-17f,1.25974f,0.547387f,0.00768639f, 1.00002f,-1.31053e-06f,-7.34727e-17f,1.27146f,0.565554f,0.00878571f,
1.00001f,-2.26061e-06f,-5.29103e-17f,1.28471f,0.585542f,0.0100664f, 0.999994f,1.10648e-05f,-7.76429e-17f,1.29984f,0.607676f,0.0115672f,
1.00001f,1.74648e-05f,-1.00082e-16f,1.31739f,0.632343f,0.0133356f, 1.0f,-1.03747e-05f,-2.99725e-16f,1.33797f,0.660095f,0.0154377f,
1.00002f,1.15255e-05f,-8.78592e-17f,1.36269f,0.691648f,0.0179607f, 1.0f,-4.40859e-06f,-6.95933e-17f,1.39307f,0.728045f,0.0210292f,
1.00001f,1.07776e-08f,6.34365e-17f,1.43185f,0.770889f,0.0248329f, 0.999991f,1.11927e-05f,-1.82278e-16f,1.48396f,0.822965f,0.0296947f,
0.999959f,4.6722e-05f,7.44277e-17f,1.56131f,0.89013f,0.0362789f, 0.999977f,2.01186e-05f,-2.2143e-16f,1.70562f,0.993491f,0.0469292f,
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
