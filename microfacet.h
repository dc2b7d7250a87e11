/* microfacet.h - GENERATED FILE, do not edit: edit the module sources in
 * src/ and run `make header` (tools/amalgamate.sh). Assembled from:
 *   00_intro.h 01_config.h 02_vec.h 03_fresnel.h 04_special.h 05_ndf.h
 *   06_kind_beckmann.h 06_kind_ggx.h 06_kind_gtr.h 06_kind_leadr.h
 *   06_kind_student_t.h 06_kind_tabulated.h 07_numeric_vndf.h 08_transform.h
 *   09_smith.h 10_sampling.h 11_brdf.h 11_dielectric.h 12_leadr.h 13_ltc.h
 *   14_ltc_table.h 15_ibm.h 16_microsurface.h 99_outro.h
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
 *          under -ffast-math.
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
/* x clamped to [lo, hi]; NaN gives lo */
MF_INLINE mf_real mf_clamp(mf_real x, mf_real lo, mf_real hi) { return x >= lo ? (x <= hi ? x : hi) : lo; }
MF_INLINE mf_real mf_max(mf_real a, mf_real b) { return a > b ? a : b; }
MF_INLINE mf_real mf_min(mf_real a, mf_real b) { return a < b ? a : b; }
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
MF_INLINE mf_real mf__cap(mf_real x) { return x < MF_BIG ? x : (x == x ? MF_BIG : MF_R(0.0)); }

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
MF_INLINE mf_real mf_fresnel_schlick_f90(mf_real f0, mf_real f90, mf_real cos_theta)
{
    mf_real m = MF_R(1.0) - mf_clamp(cos_theta, MF_R(0.0), MF_R(1.0)), m2;
    if (!(m == m)) m = MF_R(0.0);
    f0 = mf_clamp(f0, MF_R(0.0), MF_R(1.0));
    f90 = mf_clamp(f90, MF_R(0.0), MF_R(1.0));
    m2 = m * m;
    return f0 + (f90 - f0) * m2 * m2 * m;
}
/* Schlick's approximation f0 + (1 - f0)(1 - cos)^5: the f90 = 1 case. */
MF_INLINE mf_real mf_fresnel_schlick(mf_real f0, mf_real cos_theta)
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
MF_INLINE mf_real mf__q(mf_real ax, mf_real ay, mf_vec3 m)
{
    mf_real x = m.x / ax, y = m.y / ay;
    return x * x + y * y;
}

/* alpha_w^2 tan^2(theta) = 1/a^2, with w.z clamped so the horizon stays
 * finite, capped at MF_A2T2_MAX (alpha 1e4 under a stretch at the horizon
 * overflows float; NaN gives the cap too), so the Lambdas never see inf/inf */
#define MF_A2T2_MAX MF_R(1e30)
MF_INLINE mf_real mf__a2t2(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real x = ax * w.x, y = ay * w.y;
    mf_real r = (x * x + y * y) / mf_max(w.z * w.z, MF_R(1e-30));
    return r < MF_A2T2_MAX ? r : MF_A2T2_MAX;
}

/* wm from an unstretched slope direction (cos phi, sin phi) and squared unit
 * slope radius r2, stretched by (ax, ay): wm ~ (ax r cos, ay r sin, 1). */
MF_INLINE mf_vec3 mf__wm_from_slope(mf_real ax, mf_real ay, mf_real r2, mf_real cp, mf_real sp)
{
    if (!(r2 < MF_R(1e30))) return mf_normalize(mf_vec3_make(ax * cp, ay * sp, MF_R(0.0)));
    r2 = MF_SQRT(mf_max(r2, MF_R(0.0)));
    return mf_normalize(mf_vec3_make(ax * r2 * cp, ay * r2 * sp, MF_R(1.0)));
}

/* wm for the squared unit slope radius r2 at the azimuth 2 pi u2 (mf__wm_from_slope). */
MF_INLINE mf_vec3 mf__wm_from_slope_u(mf_real ax, mf_real ay, mf_real r2, mf_real u2)
{
    mf_real phi = MF_R(2.0) * MF_PI * u2;
    return mf__wm_from_slope(ax, ay, r2, MF_COS(phi), MF_SIN(phi));
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
MF_INLINE mf_real mf_beckmann_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real z2, e;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    z2 = wm.z * wm.z;
    e = mf__q(ax, ay, wm) / z2;                   /* tan^2 / alpha_projected^2 */
    if (!(e < MF_R(80.0))) return MF_R(0.0);     /* exp underflow (and NaN) */
    return MF_EXP(-e) / (MF_PI * ax * ay * z2 * z2);
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

MF_COLD void mf__beckmann_visible_slopes(mf_real tv, mf_real u1, mf_real u2, mf_real *sx, mf_real *sy);
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

/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_INLINE mf_real mf__beckmann_D(const mf_ndf *d, mf_vec3 wm) { return mf_beckmann_D(d->ax, d->ay, wm); }
MF_INLINE mf_real mf__beckmann_lambda(const mf_ndf *d, mf_vec3 w) { return mf_beckmann_lambda(d->ax, d->ay, w); }
MF_INLINE mf_vec3 mf__beckmann_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    return mf__wm_from_slope_u(d->ax, d->ay, -MF_LOG1P(-t), u2);
}
MF_INLINE mf_vec3 mf__beckmann_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
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

MF_INLINE mf_real mf_ggx_D(mf_real ax, mf_real ay, mf_vec3 wm)
{
    mf_real t;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    t = wm.z * wm.z + mf__q(ax, ay, wm);          /* cos^2 (1 + tan^2/alpha^2), no cos^4 underflow */
    return MF_R(1.0) / (MF_PI * ax * ay * t * t);
}

MF_INLINE mf_real mf_ggx_lambda(mf_real ax, mf_real ay, mf_vec3 w)
{
    mf_real a2t2 = mf__a2t2(ax, ay, w);
    return a2t2 / (MF_R(2.0) * (MF_R(1.0) + MF_SQRT(MF_R(1.0) + a2t2)));
}

/* GGX VNDF by spherical caps (Dupuy & Benyoub 2023, Listing 3), before the
 * final normalization; w need not be unit. (0,0,1) for degenerate input. k
 * scales the cap's lower bound -k v.z: 1 is the whole visible hemisphere, k < 1
 * the bounded cap of Eto & Tokuyoshi 2023 (mf_ggx_sample_visible_bounded). */
MF_INLINE mf_vec3 mf__ggx_vndf_unnormalized(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2, mf_real k)
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
MF_INLINE mf_vec3 mf_ggx_sample_visible(mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_vec3 h;
    if (w.z < MF_R(0.0)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    h = mf__ggx_vndf_unnormalized(ax, ay, w, u1, u2, MF_R(1.0));
    return mf_scale(h, MF_R(1.0) / MF_SQRT(mf_dot(h, h)));
}

/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_INLINE mf_real mf__ggx_D(const mf_ndf *d, mf_vec3 wm) { return mf_ggx_D(d->ax, d->ay, wm); }
MF_INLINE mf_real mf__ggx_lambda(const mf_ndf *d, mf_vec3 w) { return mf_ggx_lambda(d->ax, d->ay, w); }
MF_INLINE mf_vec3 mf__ggx_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), q = MF_R(1.0) - t;
    return mf__wm_from_slope_u(d->ax, d->ay, q > MF_R(0.0) ? t / q : MF_BIG, u2);
}
MF_INLINE mf_vec3 mf__ggx_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
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
MF_INLINE mf_real mf__D_base(const mf_ndf *d, mf_vec3 wm)
{
    if (d->type == MF_NDF_GGX) return mf_ggx_D(d->ax, d->ay, wm);
    if (d->type == MF_NDF_BECKMANN) return mf_beckmann_D(d->ax, d->ay, wm);
    return mf__ndf_D(d, wm);
}

/* D(wm), 1/sr; 0 if wm.z <= 0. Transformed kinds by Eq. 4.14. */
MF_INLINE mf_real mf_D(const mf_ndf *d, mf_vec3 wm)
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
MF_INLINE mf_real mf_lambda(const mf_ndf *d, mf_vec3 w)
{
    /* Lambda depends on w only through tan(theta) and phi: no normalization */
    if (d->transformed) w = mf_mat2_apply(d->Minv, w);
    if (d->type == MF_NDF_GGX) return mf_ggx_lambda(d->ax, d->ay, w);
    if (d->type == MF_NDF_BECKMANN) return mf_beckmann_lambda(d->ax, d->ay, w);
    return mf__ndf_lambda(d, w);
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

/* w . (-E_x, -E_y, 1): the projected area of the mean surface (unnormalized
 * mesonormal) toward w; w.z for every centered distribution. The mean slope of
 * a transformed distribution is M^-T times the base's (Eq. 4.16). */
MF_INLINE mf_real mf__mean_surface_proj(const mf_ndf *d, mf_vec3 w)
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
MF_INLINE mf_real mf_projected_area(const mf_ndf *d, mf_vec3 w)
{
    mf_real cz;
    if (d->type == MF_NDF_LEADR) return mf__cap(mf_max(mf__mean_surface_proj(d, w), MF_R(1e-15)) * (MF_R(1.0) + mf_lambda(d, w)));
    cz = mf_max(MF_FABS(w.z), MF_R(1e-15));
    return mf__cap(cz + cz * mf_lambda(d, w));
}

/* Distribution of visible normals (Heitz & d'Eon 2014 Eq. 2):
 * D_w(wm) = G1(w, wm) max(0, w.wm) D(wm) / w.z; integrates to 1 over wm. 0 if w.z < 0. */
MF_INLINE mf_real mf_D_visible(const mf_ndf *d, mf_vec3 w, mf_vec3 wm)
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
MF_INLINE mf_real mf__u01(mf_real u) { return u >= MF_R(0.0) ? (u <= MF_R(1.0) ? u : MF_R(1.0)) : MF_R(0.0); }

/* wm with density D(wm) wm.z. u1 picks the polar angle, u2 the azimuth.
 * Transformed kinds: M^-T applied to a sample of the base (Eq. 4.17-4.18). */
MF_INLINE mf_vec3 mf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
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
MF_INLINE mf_vec3 mf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
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

MF_INLINE mf_real mf_brdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
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

MF_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi);

/* Samples wi for wo; wi.z <= 0 (the zero vector) means no sample. A wi is
 * returned only where mf_brdf_pdf is positive (rounding can put a sampled
 * normal where D underflows to 0, e.g. Beckmann 0.01 at u = (0, 0)). */
MF_INLINE mf_vec3 mf_brdf_sample(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
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
MF_INLINE mf_real mf_brdf_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
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
MF_INLINE mf_real mf_brdf_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
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
MF_INLINE mf_real mf__ggx_bounded_k(mf_real ax, mf_real ay, mf_vec3 wo)
{
    mf_real a = mf_clamp(mf_min(ax, ay), MF_R(0.0), MF_R(1.0)), a2 = a * a;
    mf_real s = MF_R(1.0) + MF_SQRT(wo.x * wo.x + wo.y * wo.y), s2 = s * s;
    return (MF_R(1.0) - a2) * s2 / (s2 + a2 * wo.z * wo.z);   /* Eq. 5 */
}
MF_INLINE mf_vec3 mf_ggx_sample_visible_bounded(const mf_ndf *d, mf_vec3 wo, mf_real u1, mf_real u2)
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
MF_INLINE mf_real mf_ggx_brdf_pdf_bounded(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
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
MF_INLINE int mf_refract(mf_vec3 wi, mf_vec3 n, mf_real eta, mf_vec3 *wt)
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
MF_INLINE int mf__dielectric_half(mf_vec3 wo, mf_vec3 wi, mf_real e, mf_vec3 *h)
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
MF_INLINE int mf__dielectric_ok(mf_vec3 w, mf_real eta)
{
    return eta > MF_R(0.0) && eta < MF_BIG && MF_FABS(w.x) + MF_FABS(w.y) + MF_FABS(w.z) < MF_BIG && w.z != MF_R(0.0);
}

/* Prepares (wo, wi, eta) for the evaluation: inverts both when wo is below;
 * 0 when there is nothing to evaluate. */
MF_INLINE int mf__dielectric_setup(mf_vec3 *wo, mf_vec3 *wi, mf_real *eta)
{
    if (!mf__dielectric_ok(*wo, *eta) || !mf__dielectric_ok(*wi, *eta)) return 0;   /* NaN, infinite, horizon */
    if (wo->z < MF_R(0.0)) {
        *wo = mf_scale(*wo, MF_R(-1.0));
        *wi = mf_scale(*wi, MF_R(-1.0));
        *eta = MF_R(1.0) / *eta;
    }
    return 1;
}

MF_INLINE mf_real mf__dielectric_G2(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi)
{
    /* wi below: its masking on the lower side is Lambda(-wi) (see above) */
    return MF_R(1.0) / (MF_R(1.0) + mf_lambda(d, wo) + mf_lambda(d, wi.z < MF_R(0.0) ? mf_scale(wi, MF_R(-1.0)) : wi));
}

/* The common part of eval and pdf: after the setup, the half vector h, wo.h,
 * the Fresnel reflectance there and, for transmission, the Jacobian's
 * denominator (wi.h + wo.h / e)^2 (Walter Eq. 17). 0 when nothing to do. */
MF_INLINE int mf__dielectric_prep(mf_vec3 *wo, mf_vec3 *wi, mf_real *eta, mf_vec3 *h, mf_real *oh, mf_real *F, mf_real *den)
{
    mf_real x;
    if (!mf__dielectric_setup(wo, wi, eta) || !mf__dielectric_half(*wo, *wi, *eta, h)) return 0;
    *oh = mf_dot(*wo, *h);
    *F = mf_fresnel_dielectric(*oh, *eta);
    x = mf_dot(*wi, *h) + *oh / *eta;
    *den = x * x;
    return wi->z > MF_R(0.0) || *den > MF_R(0.0);
}

MF_INLINE mf_real mf_dielectric_bsdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
{
    mf_vec3 h;
    mf_real F, oh, den, g;
    if (!mf__dielectric_prep(&wo, &wi, &eta, &h, &oh, &F, &den)) return MF_R(0.0);
    g = mf_D(d, h) * mf__dielectric_G2(d, wo, wi) / wo.z;
    if (wi.z > MF_R(0.0)) return mf_min(F * g / (MF_R(4.0) * wi.z), MF_BIG);
    return mf_min((MF_R(1.0) - F) * g * MF_FABS(mf_dot(wi, h)) * oh / (den * -wi.z) / (eta * eta), MF_BIG);
}

/* Density of mf_dielectric_sample per unit solid angle of wi (either side). */
MF_INLINE mf_real mf_dielectric_pdf(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
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
MF_INLINE mf_vec3 mf_dielectric_sample(const mf_ndf *d, mf_vec3 wo, mf_real eta, mf_real u1, mf_real u2, mf_real u3)
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
MF_INLINE mf_real mf_dielectric_sample_weight(const mf_ndf *d, mf_vec3 wo, mf_vec3 wi, mf_real eta)
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

MF_INLINE mf_vec3 mf__mat3_apply(const mf_real *a, mf_vec3 v)
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
    if (!(MF_FABS(det) > MF_R(0.0))) {
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
    return mf__cap(l->det_inv * v.z / (MF_PI * l2 * l2));
}

/* A direction with density mf_ltc_eval: a cosine-distributed direction moved by M. */
MF_INLINE mf_vec3 mf_ltc_sample(const mf_ltc *l, mf_real u1, mf_real u2)
{
    return mf_normalize(mf__mat3_apply(l->M, mf__sample_cosine(u1, u2)));
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
 * table instead). Fitted in 185 s (double, one core). */
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
 * floats per entry: the inverse-matrix entries inv0..inv3 (mf_ltc_from_inverse),
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
 * the bin of the texel at the center, else 0; non-finite center: 0. */
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
/* Dimov's gamma = 4 Lambda (C.11) alone, for the gamma-4 mixture. */
MF_INLINE mf_real mf__gtr_lambda4(mf_real a2, mf_real t2)
{
    mf_real a2t2 = a2 * t2, qa = MF_SQRT(MF_R(1.0) + a2t2), ea = a2t2 / (qa + MF_R(1.0));
    mf_real a4 = a2 * a2, A4 = MF_R(8.0) * (a4 + a2 + MF_R(1.0));
    return a2t2 * (MF_R(12.0) * a4 - A4 * ea * (qa + MF_R(0.5)) / (qa + MF_R(1.0)) +
                   MF_R(3.0) * a2t2 * (MF_R(5.0) * a4 + MF_R(2.0) * a2 + MF_R(1.0))) /
           (MF_R(2.0) * A4 * qa * qa * qa);
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
    } else {
        mf_real lam[5];
        mf__gtr_lambda_nodes(d->ax * d->ax, p->L, t2, lam);
        return mf_max(lam[(int)p->gamma], MF_R(0.0));   /* C.11 can round to -4e-23 in float */
    }
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
                mf_real t = ((mf_real)p + MF_R(0.5) + MF_R(0.5) * mf__gl_xi(i)) / MF_R(8.0);
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
    p->direct = 0;
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
        mf_real a = pc->ea[i], b = pc->eb[i], v = a * X + b * Y + pc->ec[i];
        mf_real lo = v + mf_min(a, MF_R(0.0)) + mf_min(b, MF_R(0.0)), hi = v + mf_max(a, MF_R(0.0)) + mf_max(b, MF_R(0.0));
        if (hi <= MF_R(0.0)) return MF_R(0.0);
        if (lo < MF_R(0.0)) { cut[nc] = i; cv[nc] = v; ++nc; }
    }
    if (nc == 0) return MF_R(1.0);
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
    int lazy;                        /* bins of the window join when a texel of theirs is met */
    int bin[MF_IBM_MAX_WINDOW];
    short slot[MF_IBM_MAX_WINDOW];
    mf_real w[MF_IBM_MAX_WINDOW];    /* accumulated area, then weight */
} mf__ibm_set;

MF_INLINE void mf__ibm_set_init(mf__ibm_set *s, int cx, int cy, int r)
{
    int i;
    s->cx = cx; s->cy = cy; s->r = r; s->side = 2 * r + 1; s->n = 0; s->lazy = 0;
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

/* list entry of a bin map value (ix | iy << s), or -1; a lazy set adds the
 * bin when it is in the neighbourhood (dx^2 + dy^2 <= r (r + 1)) */
MF_INLINE int mf__ibm_set_find(const mf_ibm *ibm, mf__ibm_set *s, unsigned int v)
{
    int ix = (int)(v & ((1u << ibm->axis_bits) - 1u)), iy = (int)(v >> ibm->axis_bits);
    int dx = ix - s->cx, dy = iy - s->cy, k;
    if (dx < -s->r || dx > s->r || dy < -s->r || dy > s->r) return -1;
    k = s->slot[(dy + s->r) * s->side + dx + s->r];
    if (k < 0 && s->lazy && dx * dx + dy * dy <= s->r * (s->r + 1)) {
        k = s->n;
        mf__ibm_set_add(s, dx, dy, ix + ibm->res * iy);
    }
    return k;
}

/* Direct texel sum over a piece (Eq. 5.2-5.3 grouped by bin); returns the
 * piece's area as the texel areas add up (every bin, listed or not). */
MF_INLINE mf_real mf__ibm_direct(const mf_ibm *ibm, const mf__ibm_piece *pc, mf__ibm_set *s)
{
    mf_real tot = MF_R(0.0);
    int x, y;
    for (y = pc->by0; y < pc->by1; ++y)
        for (x = pc->bx0; x < pc->bx1; ++x) {
            mf_real a = mf__ibm_texel_area(pc, x, y);
            int k;
            if (!(a > MF_R(0.0))) continue;
            tot += a;
            k = mf__ibm_set_find(ibm, s, mf__ibm_get(ibm->data + ibm->bin_at, (size_t)y * (size_t)ibm->width + (size_t)x, ibm->bin_bits));
            if (k >= 0) s->w[k] += a;
        }
    return tot;
}

/* first index in [s, e) whose Morton code has bit `bit` set */
MF_INLINE unsigned int mf__ibm_split(const mf_ibm *ibm, unsigned int s, unsigned int e, int bit)
{
    const unsigned int *pos = ibm->data + ibm->pos_at;
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
    int i;
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
                if (p->direct) dtot += mf__ibm_direct(ibm, &pc, s);
                else
                    for (i = 0; i < s->n; i += MF_IBM_BATCH)
                        mf__ibm_traverse(ibm, &pc, s->bin + i, s->n - i < MF_IBM_BATCH ? s->n - i : MF_IBM_BATCH, s->w + i);
            }
        }
    }
    /* |A| as the pieces add up, so that the weights of all bins sum to 1 even
     * where float round-off moves the corners of a thin footprint; in the
     * direct sum, as the texel areas themselves add up (the clipped texels
     * and the shoelace of the pieces round differently: on a flat map, where
     * one bin holds every texel, the weight is then exactly 1) */
    if (p->direct && dtot > MF_R(0.0)) tot = dtot;
    if (!(tot > MF_R(0.0))) tot = p->area;
    for (i = 0; i < s->n; ++i) s->w[i] = mf_clamp(s->w[i] / tot, MF_R(0.0), MF_R(1.0));
}

MF_COLD mf_real mf_ibm_bin_weight(const mf_ibm *ibm, int bin, const mf_footprint *f)
{
    mf__ibm_fp p;
    mf__ibm_set s;
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return MF_R(0.0);
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
    mf__ibm_set_init(&s, cx, cy, r);
    if (p.mode == MF__IBM_POINT || (p.mode == MF__IBM_EXACT && p.direct)) s.lazy = 1;   /* few texels: their bins */
    else
        /* the kd traversal needs its bins up front: the non-empty bins of the
         * neighbourhood that face wo (and wi when only f is wanted) */
        for (dy = -r; dy <= r; ++dy)
            for (dx = -r; dx <= r; ++dx) {
                int j = (cx + dx) + b * (cy + dy);
                mf_vec3 t;
                if (dx * dx + dy * dy > r * (r + 1) || cx + dx < 0 || cx + dx >= b || cy + dy < 0 || cy + dy >= b) continue;
                if (mf_ibm_bin_texels(ibm, j) == 0) continue;
                t = mf_ibm_bin_normal(ibm, j);
                if (!(mf_dot(wo, t) > MF_R(0.0)) || !(mf_dot(h, t) > MF_R(0.0))) continue;
                if (!pdf && !(mf_dot(wi, t) > MF_R(0.0))) continue;
                mf__ibm_set_add(&s, dx, dy, j);
            }
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
    mf_real ct, a, x, y, fx, fy, v[6];
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
500.0f,7.93499e-12f,500.0f,-3.09171e-19f,1.0f,4.26386e-21f, 500.0f,11.226f,500.252f,-0.0224521f,1.0f,2.3843e-18f,
500.0f,22.4648f,501.009f,-0.0449296f,1.0f,1.16261e-15f, 500.0f,33.7291f,502.275f,-0.0674582f,1.0f,6.24941e-14f,
500.0f,45.0319f,504.056f,-0.0900638f,1.0f,1.08813e-12f, 500.0f,56.3863f,506.359f,-0.112773f,1.0f,1.00501e-11f,
500.0f,67.8056f,509.195f,-0.135611f,1.0f,6.19597e-11f, 500.0f,79.3036f,512.578f,-0.158607f,1.0f,2.88719e-10f,
500.0f,90.8943f,516.523f,-0.181788f,1.0f,1.0957e-09f, 500.0f,102.592f,521.05f,-0.205184f,1.0f,3.55419e-09f,
500.0f,114.413f,526.18f,-0.228825f,1.0f,1.01854e-08f, 500.0f,126.371f,531.939f,-0.252742f,1.0f,2.6403e-08f,
500.0f,138.484f,538.356f,-0.276968f,1.0f,6.30015e-08f, 500.0f,150.769f,545.462f,-0.301538f,1.0f,1.40225e-07f,
500.0f,163.244f,553.297f,-0.326488f,1.0f,2.94142e-07f, 500.0f,175.929f,561.902f,-0.351857f,1.0f,5.86267e-07f,
500.0f,188.843f,571.324f,-0.377686f,1.0f,1.11765e-06f, 500.0f,202.01f,581.616f,-0.40402f,1.0f,2.04896e-06f,
500.0f,215.452f,592.839f,-0.430904f,1.0f,3.6284e-06f, 500.0f,229.195f,605.061f,-0.458389f,1.0f,6.22991e-06f,
500.0f,243.266f,618.356f,-0.486531f,1.0f,1.04042e-05f, 500.0f,257.694f,632.812f,-0.515387f,1.0f,1.6946e-05f,
500.0f,272.511f,648.524f,-0.545021f,1.0f,2.69819e-05f, 499.999f,287.752f,665.602f,-0.575503f,1.0f,4.20823e-05f,
499.999f,303.455f,684.17f,-0.606909f,1.0f,6.44038e-05f, 499.999f,319.662f,704.367f,-0.639322f,1.0f,9.68679e-05f,
499.999f,336.418f,726.353f,-0.672834f,1.0f,0.000143383f, 499.999f,353.774f,750.311f,-0.707545f,1.0f,0.000209115f,
499.999f,371.785f,776.448f,-0.743568f,1.0f,0.000300825f, 499.999f,390.515f,805.003f,-0.781027f,1.0f,0.000427269f,
499.999f,410.032f,836.252f,-0.820061f,1.0f,0.000599685f, 499.999f,430.415f,870.513f,-0.860826f,1.0f,0.000832372f,
499.998f,451.75f,908.155f,-0.903496f,1.0f,0.00114338f, 499.998f,474.136f,949.61f,-0.948269f,1.0f,0.00155533f,
499.998f,497.687f,995.384f,-0.99537f,1.0f,0.00209635f, 499.998f,522.529f,1046.07f,-1.04505f,1.0f,0.00280123f,
499.997f,548.808f,1102.38f,-1.09761f,1.0f,0.00371267f, 499.997f,576.694f,1165.15f,-1.15338f,1.0f,0.00488284f,
499.997f,606.38f,1235.4f,-1.21276f,1.0f,0.00637507f, 499.996f,638.095f,1314.33f,-1.27618f,1.0f,0.0082659f,
499.996f,672.105f,1403.45f,-1.3442f,1.0f,0.0106473f, 499.995f,708.722f,1504.58f,-1.41744f,1.0f,0.0136293f,
499.994f,748.322f,1619.98f,-1.49664f,0.999999f,0.0173429f, 499.993f,791.351f,1752.48f,-1.58269f,0.999999f,0.0219437f,
499.992f,838.352f,1905.68f,-1.67669f,0.999999f,0.0276152f, 499.991f,889.984f,2084.16f,-1.77996f,0.999999f,0.0345734f,
499.99f,947.063f,2293.88f,-1.89412f,0.999999f,0.0430717f, 499.988f,1010.61f,2542.7f,-2.02121f,0.999999f,0.0534058f,
499.986f,1081.91f,2841.12f,-2.16381f,0.999999f,0.0659202f, 499.983f,1162.63f,3203.49f,-2.32525f,0.999999f,0.0810146f,
499.98f,1254.93f,3649.8f,-2.50984f,0.999998f,0.0991513f, 499.976f,1361.7f,4208.6f,-2.72338f,0.999998f,0.120864f,
499.971f,1486.87f,4921.8f,-2.97372f,0.999998f,0.146765f, 499.964f,1635.96f,5853.05f,-3.27189f,0.999997f,0.17756f,
499.955f,1816.91f,7102.86f,-3.63379f,0.999997f,0.214052f, 499.943f,2041.65f,8837.6f,-4.08328f,0.999996f,0.257159f,
499.925f,2328.93f,11349.4f,-4.65782f,0.999995f,0.307928f, 499.897f,2709.93f,15190.5f,-5.41984f,0.999993f,0.367544f,
499.851f,3240.82f,21512.1f,-6.48162f,0.999989f,0.43735f, 499.767f,4033.78f,33058.0f,-8.06753f,0.999984f,0.518862f,
499.588f,5350.14f,57795.8f,-10.7003f,0.999971f,0.613786f, 499.08f,7971.03f,127813.0f,-15.9422f,0.999936f,0.724008f,
496.351f,15747.2f,500146.0f,-31.4908f,0.999515f,0.851221f, 124.39f,75859.8f,4.07371e+07f,-128.387f,0.892067f,0.874534f,
500.0f,-1.36771e-10f,500.0f,-3.09171e-19f,1.0f,4.26386e-21f, 500.0f,11.226f,500.252f,-0.0224521f,1.0f,2.3843e-18f,
500.0f,22.4648f,501.009f,-0.0449296f,1.0f,1.16261e-15f, 500.0f,33.7291f,502.275f,-0.0674582f,1.0f,6.24941e-14f,
500.0f,45.0319f,504.056f,-0.0900638f,1.0f,1.08813e-12f, 500.0f,56.3863f,506.359f,-0.112773f,1.0f,1.00501e-11f,
500.0f,67.8056f,509.195f,-0.135611f,1.0f,6.19597e-11f, 500.0f,79.3036f,512.578f,-0.158607f,1.0f,2.88719e-10f,
500.0f,90.8943f,516.523f,-0.181788f,1.0f,1.0957e-09f, 500.0f,102.592f,521.05f,-0.205184f,1.0f,3.55419e-09f,
500.0f,114.413f,526.18f,-0.228825f,1.0f,1.01854e-08f, 500.0f,126.371f,531.939f,-0.252742f,1.0f,2.6403e-08f,
500.0f,138.484f,538.356f,-0.276968f,1.0f,6.30015e-08f, 500.0f,150.769f,545.462f,-0.301538f,1.0f,1.40225e-07f,
500.0f,163.244f,553.297f,-0.326488f,1.0f,2.94142e-07f, 500.0f,175.929f,561.902f,-0.351857f,1.0f,5.86267e-07f,
500.0f,188.843f,571.324f,-0.377686f,1.0f,1.11765e-06f, 500.0f,202.01f,581.616f,-0.40402f,1.0f,2.04896e-06f,
500.0f,215.452f,592.839f,-0.430904f,1.0f,3.6284e-06f, 500.0f,229.195f,605.061f,-0.458389f,1.0f,6.22991e-06f,
500.0f,243.266f,618.356f,-0.486531f,1.0f,1.04042e-05f, 500.0f,257.694f,632.812f,-0.515387f,1.0f,1.6946e-05f,
499.999f,272.511f,648.524f,-0.545021f,1.0f,2.69819e-05f, 499.999f,287.752f,665.602f,-0.575503f,1.0f,4.20823e-05f,
499.999f,303.455f,684.17f,-0.606909f,1.0f,6.44038e-05f, 499.999f,319.662f,704.367f,-0.639322f,1.0f,9.68679e-05f,
499.999f,336.418f,726.353f,-0.672834f,1.0f,0.000143383f, 499.999f,353.774f,750.311f,-0.707545f,1.0f,0.000209115f,
499.999f,371.785f,776.448f,-0.743568f,1.0f,0.000300825f, 499.999f,390.515f,805.003f,-0.781027f,1.0f,0.000427269f,
499.999f,410.032f,836.252f,-0.820061f,1.0f,0.000599685f, 499.999f,430.415f,870.513f,-0.860826f,1.0f,0.000832372f,
499.998f,451.75f,908.155f,-0.903496f,1.0f,0.00114338f, 499.998f,474.136f,949.61f,-0.948269f,1.0f,0.00155533f,
499.998f,497.687f,995.384f,-0.99537f,1.0f,0.00209635f, 499.998f,522.529f,1046.07f,-1.04505f,1.0f,0.00280123f,
499.997f,548.808f,1102.38f,-1.09761f,1.0f,0.00371267f, 499.997f,576.694f,1165.15f,-1.15338f,1.0f,0.00488284f,
499.997f,606.38f,1235.4f,-1.21276f,1.0f,0.00637507f, 499.996f,638.095f,1314.33f,-1.27618f,1.0f,0.0082659f,
499.996f,672.105f,1403.45f,-1.3442f,1.0f,0.0106473f, 499.995f,708.722f,1504.58f,-1.41744f,1.0f,0.0136293f,
499.994f,748.322f,1619.98f,-1.49664f,0.999999f,0.0173429f, 499.993f,791.351f,1752.48f,-1.58269f,0.999999f,0.0219437f,
499.992f,838.352f,1905.68f,-1.67669f,0.999999f,0.0276152f, 499.991f,889.983f,2084.16f,-1.77996f,0.999999f,0.0345734f,
499.99f,947.063f,2293.88f,-1.89412f,0.999999f,0.0430717f, 499.988f,1010.61f,2542.7f,-2.02121f,0.999999f,0.0534058f,
499.986f,1081.91f,2841.12f,-2.16381f,0.999999f,0.0659202f, 499.983f,1162.63f,3203.49f,-2.32525f,0.999999f,0.0810146f,
499.98f,1254.93f,3649.8f,-2.50984f,0.999998f,0.0991513f, 499.976f,1361.7f,4208.6f,-2.72338f,0.999998f,0.120864f,
499.971f,1486.87f,4921.8f,-2.97372f,0.999998f,0.146765f, 499.964f,1635.96f,5853.05f,-3.27189f,0.999997f,0.17756f,
499.955f,1816.91f,7102.86f,-3.63379f,0.999997f,0.214052f, 499.943f,2041.65f,8837.6f,-4.08328f,0.999996f,0.257159f,
499.925f,2328.93f,11349.4f,-4.65782f,0.999995f,0.307928f, 499.897f,2709.93f,15190.5f,-5.41984f,0.999993f,0.367544f,
499.851f,3240.82f,21512.1f,-6.48162f,0.999989f,0.43735f, 499.767f,4033.78f,33058.0f,-8.06753f,0.999984f,0.518862f,
499.588f,5350.15f,57795.8f,-10.7003f,0.999971f,0.613786f, 499.079f,7971.02f,127813.0f,-15.9422f,0.999936f,0.724008f,
496.352f,15747.3f,500146.0f,-31.4908f,0.999515f,0.851221f, 124.39f,75852.6f,4.08086e+07f,-128.387f,0.892067f,0.874534f,
496.125f,8.25607e-11f,496.125f,-1.91644e-19f,1.0f,4.6087e-21f, 496.125f,11.139f,496.375f,-0.0224521f,1.0f,2.433e-18f,
496.125f,22.2907f,497.126f,-0.0449296f,1.0f,1.16528e-15f, 496.125f,33.4677f,498.383f,-0.0674582f,1.0f,6.25409e-14f,
496.125f,44.6829f,500.149f,-0.0900638f,1.0f,1.08854e-12f, 496.125f,55.9493f,502.434f,-0.112772f,1.0f,1.00524e-11f,
496.125f,67.2801f,505.249f,-0.135611f,1.0f,6.19689e-11f, 496.125f,78.689f,508.606f,-0.158607f,1.0f,2.8875e-10f,
496.125f,90.1898f,512.52f,-0.181788f,1.0f,1.09579e-09f, 496.125f,101.797f,517.012f,-0.205184f,1.0f,3.55441e-09f,
496.125f,113.526f,522.102f,-0.228825f,1.0f,1.01859e-08f, 496.125f,125.392f,527.817f,-0.252742f,1.0f,2.64041e-08f,
496.125f,137.411f,534.183f,-0.276968f,1.0f,6.30037e-08f, 496.125f,149.601f,541.235f,-0.301538f,1.0f,1.40229e-07f,
496.125f,161.979f,549.009f,-0.326488f,1.0f,2.94149e-07f, 496.125f,174.565f,557.547f,-0.351857f,1.0f,5.86279e-07f,
496.125f,187.38f,566.896f,-0.377686f,1.0f,1.11767e-06f, 496.125f,200.445f,577.108f,-0.40402f,1.0f,2.04899e-06f,
496.125f,213.783f,588.245f,-0.430904f,1.0f,3.62845e-06f, 496.125f,227.419f,600.371f,-0.458389f,1.0f,6.22999e-06f,
496.125f,241.381f,613.564f,-0.486531f,1.0f,1.04043e-05f, 496.125f,255.697f,627.908f,-0.515387f,1.0f,1.69462e-05f,
496.124f,270.399f,643.498f,-0.545021f,1.0f,2.69822e-05f, 496.124f,285.522f,660.444f,-0.575503f,1.0f,4.20826e-05f,
496.124f,301.103f,678.867f,-0.606909f,1.0f,6.44043e-05f, 496.124f,317.185f,698.908f,-0.639322f,1.0f,9.68686e-05f,
496.124f,333.811f,720.724f,-0.672834f,1.0f,0.000143383f, 496.124f,351.032f,744.496f,-0.707545f,1.0f,0.000209116f,
496.124f,368.904f,770.43f,-0.743568f,1.0f,0.000300827f, 496.124f,387.488f,798.764f,-0.781027f,1.0f,0.000427271f,
496.124f,406.854f,829.771f,-0.820061f,1.0f,0.000599687f, 496.124f,427.079f,863.766f,-0.860826f,1.0f,0.000832375f,
496.123f,448.249f,901.117f,-0.903496f,1.0f,0.00114338f, 496.123f,470.462f,942.251f,-0.948269f,1.0f,0.00155533f,
496.123f,493.83f,987.67f,-0.99537f,1.0f,0.00209636f, 496.123f,518.479f,1037.96f,-1.04505f,1.0f,0.00280123f,
496.122f,544.555f,1093.84f,-1.09761f,1.0f,0.00371268f, 496.122f,572.224f,1156.12f,-1.15338f,1.0f,0.00488285f,
496.122f,601.681f,1225.82f,-1.21275f,1.0f,0.00637509f, 496.121f,633.15f,1304.15f,-1.27618f,1.0f,0.00826591f,
496.12f,666.896f,1392.58f,-1.3442f,1.0f,0.0106473f, 496.12f,703.23f,1492.92f,-1.41744f,0.999999f,0.0136293f,
496.119f,742.523f,1607.42f,-1.49664f,0.999999f,0.017343f, 496.118f,785.218f,1738.9f,-1.58269f,0.999999f,0.0219437f,
496.117f,831.854f,1890.91f,-1.67669f,0.999999f,0.0276152f, 496.116f,883.086f,2068.01f,-1.77996f,0.999999f,0.0345735f,
496.115f,939.723f,2276.1f,-1.89411f,0.999999f,0.0430717f, 496.113f,1002.78f,2522.99f,-2.02121f,0.999999f,0.0534058f,
496.111f,1073.53f,2819.1f,-2.16381f,0.999999f,0.0659202f, 496.108f,1153.62f,3178.67f,-2.32525f,0.999999f,0.0810146f,
496.105f,1245.2f,3621.52f,-2.50984f,0.999998f,0.0991514f, 496.101f,1351.14f,4175.98f,-2.72338f,0.999998f,0.120864f,
496.096f,1475.35f,4883.65f,-2.97372f,0.999998f,0.146765f, 496.089f,1623.28f,5807.69f,-3.27189f,0.999997f,0.17756f,
496.08f,1802.83f,7047.8f,-3.63379f,0.999997f,0.214052f, 496.067f,2025.83f,8769.1f,-4.08327f,0.999996f,0.257159f,
496.049f,2310.87f,11261.4f,-4.65781f,0.999994f,0.307928f, 496.021f,2688.92f,15072.7f,-5.41982f,0.999993f,0.367543f,
495.975f,3215.69f,21345.3f,-6.48158f,0.999989f,0.437349f, 495.89f,4002.49f,32801.5f,-8.06747f,0.999983f,0.518861f,
495.709f,5308.61f,57347.1f,-10.7001f,0.999971f,0.613784f, 495.198f,7909.01f,126818.0f,-15.9417f,0.999935f,0.724004f,
492.445f,15623.2f,496205.0f,-31.4863f,0.999487f,0.851188f, 117.818f,71883.2f,4.04595e+07f,-127.029f,0.892164f,0.874482f,
220.5f,-4.41811e-10f,220.5f,-5.55903e-19f,1.0f,1.5205e-17f, 220.5f,4.95068f,220.611f,-0.022452f,1.0f,1.62772e-16f,
220.5f,9.90697f,220.945f,-0.0449294f,1.0f,3.54341e-15f, 220.5f,14.8745f,221.503f,-0.0674579f,1.0f,8.57956e-14f,
220.5f,19.8591f,222.288f,-0.0900634f,1.0f,1.24324e-12f, 220.5f,24.8663f,223.304f,-0.112772f,1.0f,1.08059e-11f,
220.5f,29.9022f,224.555f,-0.13561f,1.0f,6.48598e-11f, 220.5f,34.9728f,226.047f,-0.158606f,1.0f,2.9799e-10f,
220.5f,40.0843f,227.787f,-0.181787f,1.0f,1.12141e-09f, 220.5f,45.2431f,229.783f,-0.205183f,1.0f,3.61788e-09f,
220.5f,50.4558f,232.045f,-0.228824f,1.0f,1.03294e-08f, 220.499f,55.7295f,234.585f,-0.25274f,1.0f,2.67051e-08f,
220.499f,61.0713f,237.415f,-0.276966f,1.0f,6.35961e-08f, 220.499f,66.489f,240.549f,-0.301536f,1.0f,1.41334e-07f,
220.499f,71.9905f,244.004f,-0.326485f,1.0f,2.96118e-07f, 220.499f,77.5844f,247.798f,-0.351854f,1.0f,5.8965e-07f,
220.499f,83.2797f,251.953f,-0.377683f,1.0f,1.12324e-06f, 220.499f,89.0862f,256.492f,-0.404016f,1.0f,2.05791e-06f,
220.499f,95.0141f,261.441f,-0.4309f,1.0f,3.64235e-06f, 220.499f,101.075f,266.831f,-0.458385f,1.0f,6.25109e-06f,
220.499f,107.28f,272.694f,-0.486525f,1.0f,1.04356e-05f, 220.499f,113.643f,279.069f,-0.51538f,1.0f,1.69918e-05f,
220.499f,120.177f,285.998f,-0.545014f,1.0f,2.70473e-05f, 220.499f,126.898f,293.529f,-0.575495f,1.0f,4.21741e-05f,
220.499f,133.823f,301.717f,-0.6069f,1.0f,6.45306e-05f, 220.498f,140.97f,310.624f,-0.639311f,0.999999f,9.70404e-05f,
220.498f,148.359f,320.32f,-0.672822f,0.999999f,0.000143614f, 220.498f,156.013f,330.884f,-0.707531f,0.999999f,0.000209422f,
220.498f,163.956f,342.41f,-0.743552f,0.999999f,0.000301227f, 220.498f,172.215f,355.003f,-0.781009f,0.999999f,0.000427789f,
220.497f,180.822f,368.783f,-0.820041f,0.999999f,0.000600349f, 220.497f,189.81f,383.891f,-0.860803f,0.999999f,0.000833213f,
220.496f,199.219f,400.49f,-0.90347f,0.999999f,0.00114443f, 220.496f,209.091f,418.771f,-0.948239f,0.999999f,0.00155664f,
220.495f,219.476f,438.956f,-0.995335f,0.999999f,0.00209796f, 220.495f,230.43f,461.307f,-1.04501f,0.999999f,0.00280318f,
220.494f,242.019f,486.137f,-1.09757f,0.999998f,0.00371503f, 220.493f,254.315f,513.817f,-1.15333f,0.999998f,0.00488565f,
220.492f,267.406f,544.791f,-1.21269f,0.999998f,0.0063784f, 220.491f,281.39f,579.599f,-1.27611f,0.999998f,0.00826979f,
220.49f,296.387f,618.896f,-1.34412f,0.999998f,0.0106518f, 220.488f,312.533f,663.487f,-1.41734f,0.999997f,0.0136344f,
220.487f,329.993f,714.371f,-1.49653f,0.999997f,0.0173487f, 220.485f,348.965f,772.796f,-1.58256f,0.999997f,0.0219502f,
220.482f,369.688f,840.344f,-1.67654f,0.999996f,0.0276222f, 220.48f,392.452f,919.038f,-1.77977f,0.999996f,0.034581f,
220.476f,417.617f,1011.5f,-1.8939f,0.999995f,0.0430795f, 220.473f,445.632f,1121.21f,-2.02094f,0.999995f,0.0534136f,
220.468f,477.065f,1252.77f,-2.16349f,0.999994f,0.0659274f, 220.462f,512.646f,1412.53f,-2.32485f,0.999993f,0.0810206f,
220.455f,553.329f,1609.27f,-2.50934f,0.999992f,0.0991551f, 220.446f,600.384f,1855.59f,-2.72274f,0.99999f,0.120864f,
220.434f,655.545f,2169.94f,-2.97289f,0.999989f,0.14676f, 220.419f,721.234f,2580.37f,-3.27079f,0.999986f,0.177546f,
220.399f,800.946f,3131.11f,-3.63229f,0.999983f,0.214024f, 220.37f,899.923f,3895.39f,-4.08115f,0.999978f,0.257113f,
220.329f,1026.39f,5001.71f,-4.65467f,0.999972f,0.307853f, 220.266f,1194.02f,6692.85f,-5.41488f,0.999962f,0.367424f,
220.163f,1427.36f,9474.31f,-6.47315f,0.999946f,0.437161f, 219.974f,1775.33f,14548.6f,-8.05123f,0.999915f,0.518557f,
219.57f,2351.04f,25395.5f,-10.6623f,0.999849f,0.613261f, 218.404f,3487.04f,55898.1f,-15.8094f,0.999201f,0.722591f,
212.418f,6730.04f,213535.0f,-30.4915f,0.997003f,0.847012f, 38.6524f,11903.3f,3.73564e+06f,-48.4635f,0.925506f,0.883569f,
124.031f,2.21725e-09f,124.031f,-5.8034e-19f,1.0f,4.69449e-15f, 124.031f,2.78475f,124.093f,-0.0224517f,1.0f,1.37807e-14f,
124.031f,5.57265f,124.281f,-0.0449289f,1.0f,7.24701e-14f, 124.031f,8.36689f,124.595f,-0.0674572f,1.0f,4.00409e-13f,
124.031f,11.1707f,125.037f,-0.0900623f,1.0f,2.49961e-12f, 124.031f,13.9873f,125.608f,-0.112771f,1.0f,1.52112e-11f,
124.031f,16.82f,126.312f,-0.135609f,1.0f,7.85234e-11f, 124.031f,19.6721f,127.151f,-0.158604f,1.0f,3.35911e-10f,
124.031f,22.5473f,128.129f,-0.181785f,1.0f,1.21686e-09f, 124.031f,25.4491f,129.252f,-0.20518f,1.0f,3.83863e-09f,
124.031f,28.3813f,130.525f,-0.22882f,1.0f,1.08041e-08f, 124.03f,31.3477f,131.953f,-0.252736f,1.0f,2.76636e-08f,
124.03f,34.3525f,133.545f,-0.276961f,1.0f,6.54292e-08f, 124.03f,37.3998f,135.308f,-0.30153f,1.0f,1.44678e-07f,
124.03f,40.4944f,137.251f,-0.326479f,1.0f,3.01968e-07f, 124.03f,43.6409f,139.386f,-0.351847f,1.0f,5.99515e-07f,
124.03f,46.8445f,141.723f,-0.377675f,0.999999f,1.13935e-06f, 124.03f,50.1106f,144.276f,-0.404006f,0.999999f,2.08344e-06f,
124.03f,53.445f,147.06f,-0.430888f,0.999999f,3.68179e-06f, 124.03f,56.854f,150.091f,-0.458372f,0.999999f,6.31058e-06f,
124.03f,60.3443f,153.389f,-0.48651f,0.999999f,1.05235e-05f, 124.029f,63.9232f,156.975f,-0.515363f,0.999999f,1.71189e-05f,
124.029f,67.5986f,160.872f,-0.544994f,0.999999f,2.7228e-05f, 124.029f,71.3792f,165.108f,-0.575473f,0.999999f,4.24266e-05f,
124.029f,75.2743f,169.713f,-0.606875f,0.999999f,6.48782e-05f, 124.029f,79.2943f,174.723f,-0.639283f,0.999998f,9.75121e-05f,
124.028f,83.4505f,180.176f,-0.672789f,0.999998f,0.000144245f, 124.028f,87.7555f,186.118f,-0.707494f,0.999998f,0.000210256f,
124.027f,92.223f,192.601f,-0.74351f,0.999998f,0.000302316f, 124.027f,96.8686f,199.683f,-0.780961f,0.999997f,0.000429195f,
124.026f,101.709f,207.434f,-0.819986f,0.999997f,0.000602146f, 124.026f,106.765f,215.931f,-0.860741f,0.999997f,0.000835483f,
124.025f,112.056f,225.266f,-0.903399f,0.999997f,0.00114728f, 124.024f,117.609f,235.547f,-0.948158f,0.999996f,0.00156016f,
124.023f,123.449f,246.899f,-0.995243f,0.999996f,0.00210228f, 124.022f,129.61f,259.47f,-1.04491f,0.999996f,0.00280843f,
124.021f,136.127f,273.434f,-1.09744f,0.999995f,0.00372135f, 124.019f,143.042f,289.0f,-1.15319f,0.999995f,0.00489319f,
124.018f,150.404f,306.418f,-1.21253f,0.999994f,0.0063873f, 124.016f,158.268f,325.992f,-1.27593f,0.999993f,0.00828019f,
124.013f,166.7f,348.089f,-1.34391f,0.999993f,0.0106638f, 124.011f,175.779f,373.163f,-1.41709f,0.999992f,0.0136482f,
124.008f,185.596f,401.774f,-1.49623f,0.999991f,0.0173642f, 124.004f,196.262f,434.624f,-1.58222f,0.99999f,0.0219674f,
124.0f,207.912f,472.602f,-1.67613f,0.999989f,0.027641f, 123.995f,220.708f,516.844f,-1.77929f,0.999987f,0.034601f,
123.99f,234.853f,568.825f,-1.89331f,0.999985f,0.0431002f, 123.983f,250.597f,630.49f,-2.02024f,0.999983f,0.0534341f,
123.974f,268.261f,704.439f,-2.16263f,0.999981f,0.0659466f, 123.964f,288.251f,794.221f,-2.32378f,0.999978f,0.0810365f,
123.952f,311.104f,904.778f,-2.50801f,0.999974f,0.0991651f, 123.936f,337.53f,1043.17f,-2.72104f,0.99997f,0.120864f,
123.915f,368.497f,1219.74f,-2.97069f,0.999964f,0.146745f, 123.888f,405.36f,1450.22f,-3.26786f,0.999956f,0.177508f,
123.852f,450.068f,1759.37f,-3.62829f,0.999946f,0.213952f, 123.802f,505.539f,2188.17f,-4.07549f,0.999932f,0.25699f,
123.73f,576.34f,2808.44f,-4.64628f,0.999911f,0.307654f, 123.619f,670.041f,3755.55f,-5.40169f,0.999878f,0.367111f,
123.437f,800.148f,5310.6f,-6.45065f,0.999822f,0.436664f, 123.097f,993.235f,8137.83f,-8.00557f,0.999421f,0.517535f,
122.376f,1309.8f,14143.1f,-10.5552f,0.99891f,0.61141f, 120.397f,1920.49f,30765.6f,-15.4707f,0.997643f,0.719257f,
110.962f,3502.37f,110791.0f,-28.1372f,0.990212f,0.836244f, 20.5851f,3682.42f,731254.0f,-27.617f,0.952901f,0.880247f,
79.379f,6.56837e-10f,79.379f,-2.59325e-19f,1.0f,3.89588e-13f, 79.379f,1.78222f,79.4191f,-0.0224512f,1.0f,6.56917e-13f,
79.379f,3.56647f,79.5393f,-0.0449279f,1.0f,1.80124e-12f, 79.379f,5.35477f,79.7402f,-0.0674556f,1.0f,5.22028e-12f,
79.379f,7.14918f,80.0229f,-0.0900602f,1.0f,1.53391e-11f, 79.379f,8.95178f,80.3885f,-0.112768f,1.0f,4.75984e-11f,
79.379f,10.7647f,80.8388f,-0.135605f,1.0f,1.55939e-10f, 79.379f,12.5901f,81.3758f,-0.1586f,1.0f,5.11501e-10f,
79.379f,14.4302f,82.0021f,-0.18178f,1.0f,1.59536e-09f, 79.379f,16.2873f,82.7207f,-0.205174f,1.0f,4.61574e-09f,
79.3789f,18.1639f,83.5352f,-0.228813f,0.999999f,1.23279e-08f, 79.3789f,20.0624f,84.4494f,-0.252728f,0.999999f,3.05268e-08f,
79.3788f,21.9854f,85.468f,-0.276952f,0.999999f,7.06011e-08f, 79.3786f,23.9357f,86.5963f,-0.301519f,0.999999f,1.53689e-07f,
79.3784f,25.9161f,87.8401f,-0.326466f,0.999999f,3.17161e-07f, 79.3783f,27.9298f,89.206f,-0.351832f,0.999999f,6.24373e-07f,
79.3781f,29.98f,90.7016f,-0.377657f,0.999999f,1.17892e-06f, 79.378f,32.0703f,92.3354f,-0.403986f,0.999998f,2.14488e-06f,
79.3778f,34.2042f,94.1169f,-0.430865f,0.999998f,3.775e-06f, 79.3776f,36.3859f,96.0568f,-0.458345f,0.999998f,6.44906e-06f,
79.3774f,38.6195f,98.1672f,-0.48648f,0.999998f,1.07252e-05f, 79.3772f,40.9099f,100.462f,-0.515329f,0.999997f,1.74077e-05f,
79.3769f,43.2621f,102.956f,-0.544955f,0.999997f,2.76344e-05f, 79.3766f,45.6814f,105.666f,-0.575427f,0.999997f,4.29899e-05f,
79.3762f,48.1741f,108.613f,-0.606823f,0.999996f,6.56476e-05f, 79.3758f,50.7466f,111.819f,-0.639224f,0.999996f,9.85488e-05f,
79.3753f,53.4063f,115.308f,-0.672722f,0.999995f,0.000145625f, 79.3747f,56.1611f,119.11f,-0.707418f,0.999995f,0.000212069f,
79.374f,59.0199f,123.258f,-0.743423f,0.999995f,0.000304672f, 79.3733f,61.9926f,127.79f,-0.780862f,0.999994f,0.000432223f,
79.3724f,65.0901f,132.749f,-0.819873f,0.999993f,0.000605998f, 79.3714f,68.3248f,138.185f,-0.860612f,0.999993f,0.000840334f,
79.3703f,71.7105f,144.158f,-0.903252f,0.999992f,0.00115332f, 79.3689f,75.2628f,150.736f,-0.94799f,0.999991f,0.00156763f,
79.3674f,78.9996f,157.998f,-0.995051f,0.99999f,0.00211142f, 79.3657f,82.941f,166.04f,-1.04469f,0.999989f,0.00281951f,
79.3638f,87.1101f,174.973f,-1.09719f,0.999988f,0.00373465f, 79.3615f,91.5336f,184.93f,-1.1529f,0.999987f,0.00490902f,
79.3589f,96.2423f,196.072f,-1.2122f,0.999985f,0.00640594f, 79.3559f,101.272f,208.591f,-1.27554f,0.999984f,0.00830193f,
79.3525f,106.665f,222.724f,-1.34346f,0.999982f,0.0106889f, 79.3485f,112.47f,238.76f,-1.41657f,0.99998f,0.0136767f,
79.3438f,118.748f,257.056f,-1.49562f,0.999978f,0.0173964f, 79.3384f,125.567f,278.062f,-1.5815f,0.999975f,0.022003f,
79.3321f,133.014f,302.343f,-1.67528f,0.999972f,0.0276798f, 79.3246f,141.192f,330.627f,-1.77828f,0.999968f,0.0346422f,
79.3157f,150.23f,363.854f,-1.8921f,0.999964f,0.0431428f, 79.305f,160.288f,403.264f,-2.01877f,0.999959f,0.0534763f,
79.2921f,171.569f,450.515f,-2.16084f,0.999953f,0.0659857f, 79.2763f,184.332f,507.87f,-2.32157f,0.999946f,0.0810687f,
79.2567f,198.916f,578.477f,-2.50524f,0.999937f,0.099185f, 79.2321f,215.771f,666.826f,-2.71751f,0.999926f,0.120864f,
79.2007f,235.51f,779.504f,-2.96611f,0.999911f,0.146713f, 79.1592f,258.986f,926.49f,-3.26178f,0.999892f,0.177429f,
79.1039f,287.428f,1123.5f,-3.61998f,0.999866f,0.213804f, 79.0268f,322.661f,1396.48f,-4.06374f,0.999827f,0.256738f,
78.9153f,367.532f,1790.72f,-4.62877f,0.999744f,0.307232f, 78.7376f,426.679f,2390.98f,-5.3722f,0.999292f,0.36622f,
78.4531f,508.39f,3373.15f,-6.40034f,0.998989f,0.435266f, 77.9449f,628.606f,5148.44f,-7.91331f,0.998597f,0.51561f,
76.8802f,822.134f,8871.63f,-10.3454f,0.997413f,0.608093f, 74.0631f,1179.06f,18859.2f,-14.8193f,0.994035f,0.712457f,
62.7018f,1961.98f,61442.8f,-24.4412f,0.976238f,0.815451f, 13.0826f,1523.14f,209570.0f,-18.4409f,0.96849f,0.861776f,
55.1236f,-3.14351e-09f,55.1236f,-3.273e-19f,1.0f,1.37998e-11f, 55.1236f,1.23764f,55.1514f,-0.0224504f,1.0f,1.80909e-11f,
55.1236f,2.47668f,55.2349f,-0.0449262f,1.0f,3.3518e-11f, 55.1236f,3.71854f,55.3744f,-0.0674531f,1.0f,6.8905e-11f,
55.1236f,4.96464f,55.5707f,-0.0900567f,1.0f,1.43925e-10f, 55.1236f,6.21643f,55.8246f,-0.112763f,1.0f,3.02215e-10f,
55.1236f,7.47538f,56.1372f,-0.1356f,1.0f,6.47656e-10f, 55.1236f,8.74299f,56.5101f,-0.158593f,0.999999f,1.4371e-09f,
55.1236f,10.0208f,56.945f,-0.181771f,0.999999f,3.29428e-09f, 55.1235f,11.3105f,57.444f,-0.205164f,0.999999f,7.65765e-09f,
55.1235f,12.6136f,58.0095f,-0.228801f,0.999999f,1.76428e-08f, 55.1234f,13.932f,58.6443f,-0.252714f,0.999999f,3.9592e-08f,
55.1233f,15.2674f,59.3517f,-0.276935f,0.999998f,8.5703e-08f, 55.1232f,16.6217f,60.1351f,-0.301499f,0.999998f,1.78279e-07f,
55.123f,17.997f,60.9988f,-0.326443f,0.999998f,3.56325e-07f, 55.1228f,19.3953f,61.9473f,-0.351805f,0.999997f,6.85448e-07f,
55.1225f,20.819f,62.9858f,-0.377627f,0.999997f,1.27227e-06f, 55.1223f,22.2704f,64.1203f,-0.403951f,0.999997f,2.28488e-06f,
55.122f,23.7522f,65.3573f,-0.430825f,0.999996f,3.98121e-06f, 55.1217f,25.2671f,66.7042f,-0.458299f,0.999996f,6.74769e-06f,
55.1214f,26.8182f,68.1694f,-0.486427f,0.999995f,1.11508e-05f, 55.1211f,28.4085f,69.7625f,-0.515268f,0.999994f,1.80051e-05f,
55.1207f,30.0418f,71.4939f,-0.544885f,0.999994f,2.84612e-05f, 55.1202f,31.7217f,73.3757f,-0.575348f,0.999993f,4.41188e-05f,
55.1197f,33.4524f,75.4216f,-0.606732f,0.999992f,6.71693e-05f, 55.1191f,35.2386f,77.647f,-0.63912f,0.999991f,0.000100575f,
55.1184f,37.0852f,80.0693f,-0.672604f,0.999991f,0.000148293f, 55.1175f,38.9978f,82.7087f,-0.707283f,0.99999f,0.000215543f,
55.1166f,40.9826f,85.588f,-0.74327f,0.999988f,0.000309149f, 55.1155f,43.0463f,88.7335f,-0.780688f,0.999987f,0.000437933f,
55.1143f,45.1966f,92.1755f,-0.819674f,0.999986f,0.000613209f, 55.1129f,47.442f,95.9489f,-0.860385f,0.999985f,0.000849355f,
55.1112f,49.7921f,100.094f,-0.902993f,0.999983f,0.00116451f, 55.1094f,52.2577f,104.659f,-0.947695f,0.999981f,0.00158136f,
55.1073f,54.8512f,109.699f,-0.994713f,0.999979f,0.00212814f, 55.1049f,57.5864f,115.28f,-1.0443f,0.999977f,0.00283968f,
55.1021f,60.4793f,121.478f,-1.09675f,0.999975f,0.00375877f, 55.0989f,63.5485f,128.387f,-1.15239f,0.999972f,0.00493758f,
55.0952f,66.8152f,136.117f,-1.21161f,0.999969f,0.00643946f, 55.091f,70.3042f,144.802f,-1.27486f,0.999966f,0.00834085f,
55.0861f,74.0444f,154.605f,-1.34267f,0.999962f,0.0107336f, 55.0805f,78.0702f,165.726f,-1.41565f,0.999958f,0.0137275f,
55.0739f,82.4222f,178.414f,-1.49454f,0.999953f,0.0174533f, 55.0663f,87.149f,192.978f,-1.58023f,0.999948f,0.0220658f,
55.0573f,92.3094f,209.811f,-1.67378f,0.999941f,0.0277479f, 55.0467f,97.9749f,229.413f,-1.77649f,0.999934f,0.0347144f,
55.0341f,104.234f,252.437f,-1.88996f,0.999925f,0.043217f, 55.019f,111.196f,279.737f,-2.01618f,0.999915f,0.0535493f,
55.0008f,119.001f,312.457f,-2.15767f,0.999902f,0.0660529f, 54.9785f,127.826f,352.157f,-2.31766f,0.999886f,0.0811234f,
54.951f,137.902f,401.006f,-2.50034f,0.999866f,0.0992173f, 54.9163f,149.537f,462.09f,-2.71127f,0.999841f,0.12086f,
54.8719f,163.147f,539.933f,-2.958f,0.999803f,0.146652f, 54.8133f,179.307f,641.357f,-3.2508f,0.99969f,0.177254f,
54.7315f,198.833f,777.033f,-3.60392f,0.999336f,0.213356f, 54.6208f,222.961f,964.714f,-4.04085f,0.999123f,0.256017f,
54.4626f,253.572f,1235.09f,-4.5954f,0.99892f,0.306181f, 54.2249f,293.725f,1645.42f,-5.32287f,0.99866f,0.364922f,
53.8376f,348.673f,2312.33f,-6.31689f,0.997957f,0.433186f, 53.1535f,428.279f,3505.11f,-7.75636f,0.996853f,0.512201f,
51.7735f,552.75f,5957.04f,-10.0021f,0.994412f,0.602332f, 48.3883f,767.429f,12232.6f,-13.8462f,0.98734f,0.700967f,
37.5868f,1153.99f,34996.1f,-20.3069f,0.955301f,0.784166f, 9.56095f,776.29f,75457.0f,-13.4778f,0.977647f,0.834944f,
40.4981f,3.09124e-09f,40.4981f,-1.91121e-18f,1.0f,2.65246e-10f, 40.4981f,0.909267f,40.5185f,-0.0224492f,1.0f,3.08067e-10f,
40.4981f,1.81957f,40.5799f,-0.0449238f,1.0f,4.49918e-10f, 40.4981f,2.73193f,40.6824f,-0.0674494f,1.0f,7.34082e-10f,
40.4981f,3.64742f,40.8266f,-0.0900516f,1.0f,1.24455e-09f, 40.4981f,4.56708f,41.013f,-0.112757f,0.999999f,2.13064e-09f,
40.4981f,5.492f,41.2427f,-0.135591f,0.999999f,3.66172e-09f, 40.4981f,6.42328f,41.5167f,-0.158583f,0.999999f,6.34752e-09f,
40.4981f,7.36208f,41.8361f,-0.181759f,0.999999f,1.11916e-08f, 40.498f,8.30955f,42.2027f,-0.205149f,0.999998f,2.01939e-08f,
40.498f,9.26694f,42.6181f,-0.228783f,0.999998f,3.72864e-08f, 40.4979f,10.2355f,43.0844f,-0.252693f,0.999997f,6.99786e-08f,
40.4978f,11.2166f,43.6039f,-0.27691f,0.999997f,1.32108e-07f, 40.4977f,12.2115f,44.1794f,-0.30147f,0.999996f,2.48241e-07f,
40.4975f,13.2219f,44.8138f,-0.326409f,0.999996f,4.60457e-07f, 40.4973f,14.2492f,45.5106f,-0.351766f,0.999995f,8.38466e-07f,
40.497f,15.2951f,46.2735f,-0.377581f,0.999994f,1.49428e-06f, 40.4966f,16.3613f,47.1068f,-0.403898f,0.999994f,2.60295e-06f,
40.4962f,17.4499f,48.0155f,-0.430763f,0.999993f,4.43131e-06f, 40.4958f,18.5627f,49.0048f,-0.458228f,0.999992f,7.37696e-06f,
40.4953f,19.7021f,50.081f,-0.486345f,0.999991f,1.20202e-05f, 40.4949f,20.8703f,51.251f,-0.515174f,0.99999f,1.91926e-05f,
40.4943f,22.07f,52.5226f,-0.544778f,0.999988f,3.00652e-05f, 40.4937f,23.304f,53.9046f,-0.575225f,0.999987f,4.62622e-05f,
40.493f,24.5752f,55.407f,-0.606592f,0.999986f,7.00037e-05f, 40.4922f,25.8871f,57.0411f,-0.63896f,0.999984f,0.000104286f,
40.4913f,27.2434f,58.8198f,-0.672421f,0.999982f,0.000153103f, 40.4902f,28.6481f,60.7578f,-0.707074f,0.999981f,0.000221719f,
40.489f,30.1056f,62.8718f,-0.743031f,0.999979f,0.000317006f, 40.4876f,31.6211f,65.1812f,-0.780415f,0.999976f,0.00044784f,
40.4859f,33.2f,67.708f,-0.819364f,0.999974f,0.000625591f, 40.484f,34.8487f,70.478f,-0.86003f,0.999971f,0.000864698f,
40.4819f,36.574f,73.5209f,-0.902588f,0.999968f,0.00118336f, 40.4795f,38.384f,76.8715f,-0.947231f,0.999965f,0.00160433f,
40.4767f,40.2876f,80.5703f,-0.994182f,0.999962f,0.00215588f, 40.4735f,42.295f,84.6654f,-1.04369f,0.999958f,0.00287291f,
40.4698f,44.4179f,89.2135f,-1.09605f,0.999953f,0.00379822f, 40.4656f,46.6697f,94.2822f,-1.15159f,0.999948f,0.00498401f,
40.4607f,49.066f,99.9527f,-1.21068f,0.999943f,0.0064936f, 40.4551f,51.6247f,106.323f,-1.27379f,0.999937f,0.00840337f,
40.4487f,54.3672f,113.512f,-1.34142f,0.99993f,0.010805f, 40.4413f,57.3182f,121.666f,-1.4142f,0.999922f,0.0138082f,
40.4326f,60.5073f,130.967f,-1.49284f,0.999913f,0.0175432f, 40.4225f,63.9697f,141.641f,-1.57824f,0.999902f,0.0221644f,
40.4106f,67.7484f,153.973f,-1.67142f,0.999889f,0.027854f, 40.3967f,71.8949f,168.33f,-1.77368f,0.999875f,0.0348259f,
40.3801f,76.4731f,185.186f,-1.88659f,0.999857f,0.0433305f, 40.3602f,81.5624f,205.165f,-2.0121f,0.999834f,0.0536592f,
40.3362f,87.263f,229.096f,-2.15267f,0.9998f,0.0661498f, 40.3065f,93.7015f,258.109f,-2.31133f,0.999708f,0.0811791f,
40.2684f,101.041f,293.754f,-2.49176f,0.999419f,0.0991439f, 40.2212f,109.504f,338.297f,-2.70016f,0.999246f,0.120665f,
40.1617f,119.386f,394.993f,-2.9436f,0.9991f,0.146315f, 40.0846f,131.094f,468.76f,-3.23212f,0.998959f,0.176763f,
39.982f,145.206f,567.296f,-3.57994f,0.998798f,0.212771f, 39.8414f,162.57f,703.182f,-4.00784f,0.998565f,0.255178f,
39.639f,184.463f,898.07f,-4.54644f,0.998003f,0.304793f, 39.3387f,212.945f,1192.19f,-5.24752f,0.997394f,0.362805f,
38.8606f,251.43f,1666.08f,-6.19337f,0.996232f,0.43f, 38.0362f,306.002f,2501.23f,-7.53192f,0.994078f,0.507083f,
36.4505f,388.078f,4172.27f,-9.53503f,0.98944f,0.593548f, 32.9054f,518.394f,8199.46f,-12.6535f,0.976768f,0.683747f,
24.1554f,712.793f,19953.1f,-16.4021f,0.931933f,0.746048f, 7.05073f,426.324f,32477.0f,-10.4368f,0.983365f,0.803594f,
31.0054f,1.5206e-08f,31.0054f,-8.31085e-19f,1.0f,3.17746e-09f, 31.0054f,0.696135f,31.021f,-0.0224477f,0.999999f,3.46814e-09f,
31.0054f,1.39306f,31.0679f,-0.0449208f,0.999999f,4.39192e-09f, 31.0054f,2.09157f,31.1464f,-0.0674448f,0.999999f,6.11107e-09f,
31.0054f,2.79246f,31.2568f,-0.0900453f,0.999999f,8.92097e-09f, 31.0054f,3.49655f,31.3995f,-0.112748f,0.999999f,1.3296e-08f,
31.0054f,4.20467f,31.5753f,-0.135581f,0.999998f,1.99771e-08f, 31.0054f,4.91766f,31.785f,-0.15857f,0.999998f,3.0139e-08f,
31.0053f,5.6364f,32.0296f,-0.181743f,0.999997f,4.57085e-08f, 31.0053f,6.36178f,32.3102f,-0.20513f,0.999997f,6.99542e-08f,
31.0053f,7.09475f,32.6281f,-0.22876f,0.999996f,1.08536e-07f, 31.0052f,7.83627f,32.985f,-0.252665f,0.999995f,1.71292e-07f,
31.0051f,8.58737f,33.3827f,-0.276877f,0.999994f,2.75175e-07f, 31.005f,9.3491f,33.8232f,-0.301431f,0.999994f,4.48865e-07f,
31.0048f,10.1226f,34.3088f,-0.326363f,0.999992f,7.39825e-07f, 31.0045f,10.9091f,34.8421f,-0.351712f,0.999991f,1.22472e-06f,
31.0042f,11.7097f,35.426f,-0.377518f,0.99999f,2.02446e-06f, 31.0038f,12.526f,36.0639f,-0.403825f,0.999989f,3.32533e-06f,
31.0033f,13.3593f,36.7593f,-0.430679f,0.999987f,5.40818e-06f, 31.0028f,14.2111f,37.5165f,-0.45813f,0.999986f,8.68793e-06f,
31.0022f,15.0833f,38.3402f,-0.486232f,0.999984f,1.3766e-05f, 31.0015f,15.9775f,39.2355f,-0.515044f,0.999982f,2.14994e-05f,
31.0008f,16.8957f,40.2086f,-0.544628f,0.99998f,3.30896e-05f, 31.0f,17.8402f,41.266f,-0.575053f,0.999978f,5.01964e-05f,
30.9991f,18.8132f,42.4156f,-0.606394f,0.999975f,7.50818e-05f, 30.9981f,19.8172f,43.6658f,-0.638734f,0.999972f,0.00011079f,
30.997f,20.8551f,45.0265f,-0.672162f,0.999969f,0.000161369f, 30.9956f,21.93f,46.5091f,-0.706778f,0.999966f,0.000232145f,
30.9941f,23.0453f,48.1261f,-0.742693f,0.999963f,0.000330055f, 30.9923f,24.2047f,49.8924f,-0.780029f,0.999959f,0.00046405f,
30.9903f,25.4126f,51.8249f,-0.818922f,0.999955f,0.000645576f, 30.9879f,26.6737f,53.9431f,-0.859525f,0.99995f,0.000889153f,
30.9853f,27.9933f,56.2698f,-0.90201f,0.999945f,0.00121306f, 30.9822f,29.3775f,58.8314f,-0.94657f,0.999939f,0.00164012f,
30.9787f,30.833f,61.659f,-0.993424f,0.999933f,0.00219869f, 30.9747f,32.3675f,64.789f,-1.04282f,0.999926f,0.0029237f,
30.9701f,33.99f,68.2647f,-1.09505f,0.999919f,0.003858f, 30.9648f,35.7107f,72.1376f,-1.15043f,0.99991f,0.00505377f,
30.9588f,37.5412f,76.4696f,-1.20935f,0.9999f,0.00657426f, 30.9518f,39.4953f,81.3348f,-1.27225f,0.999889f,0.00849574f,
30.9438f,41.5889f,86.8245f,-1.33963f,0.999875f,0.0109097f, 30.9344f,43.8409f,93.0493f,-1.41211f,0.99986f,0.0139252f,
30.9236f,46.2734f,100.147f,-1.4904f,0.99984f,0.017672f, 30.9109f,48.9132f,108.289f,-1.57534f,0.999811f,0.0223027f,
30.896f,51.792f,117.692f,-1.66792f,0.999746f,0.0279928f, 30.8778f,54.9477f,128.627f,-1.76911f,0.999512f,0.0349208f,
30.8563f,58.4292f,141.459f,-1.8809f,0.999354f,0.0433853f, 30.8308f,62.2958f,156.659f,-2.00515f,0.99923f,0.0536697f,
30.8001f,66.6215f,174.854f,-2.14421f,0.999123f,0.0661075f, 30.7628f,71.5013f,196.896f,-2.30112f,0.999018f,0.081084f,
30.7171f,77.0576f,223.966f,-2.47982f,0.99891f,0.0990459f, 30.6603f,83.4517f,257.737f,-2.68547f,0.998789f,0.120503f,
30.5882f,90.8986f,300.646f,-2.92499f,0.998638f,0.146034f, 30.4941f,99.6906f,356.334f,-3.20736f,0.998287f,0.176227f,
30.3695f,110.243f,430.499f,-3.5463f,0.99788f,0.211875f, 30.2008f,123.159f,532.407f,-3.9612f,0.997415f,0.253812f,
29.9619f,139.321f,677.825f,-4.47971f,0.9966f,0.302791f, 29.611f,160.117f,895.594f,-5.14621f,0.9954f,0.359735f,
29.0651f,187.763f,1242.58f,-6.03041f,0.993394f,0.425324f, 28.1526f,225.936f,1842.84f,-7.24616f,0.989702f,0.499693f,
26.4833f,280.693f,3003.23f,-8.9687f,0.981913f,0.581053f, 23.1032f,359.737f,5583.84f,-11.3283f,0.962525f,0.660666f,
16.6906f,459.035f,11282.0f,-13.0635f,0.911906f,0.706376f, 5.69966f,263.95f,15480.0f,-8.41195f,0.987183f,0.769869f,
24.4969f,2.4177e-08f,24.4969f,-1.55965e-18f,0.999999f,2.58836e-08f, 24.4969f,0.550007f,24.5093f,-0.0224462f,0.999999f,2.7311e-08f,
24.4969f,1.10064f,24.5463f,-0.0449177f,0.999998f,3.17469e-08f, 24.4969f,1.65252f,24.6083f,-0.0674398f,0.999998f,3.96654e-08f,
24.4969f,2.20629f,24.6955f,-0.0900384f,0.999998f,5.19018e-08f, 24.4969f,2.76258f,24.8083f,-0.112739f,0.999997f,6.97301e-08f,
24.4969f,3.32205f,24.9472f,-0.135569f,0.999997f,9.49996e-08f, 24.4969f,3.88537f,25.1128f,-0.158555f,0.999996f,1.3037e-07f,
24.4969f,4.45324f,25.306f,-0.181725f,0.999995f,1.79721e-07f, 24.4969f,5.02635f,25.5276f,-0.205107f,0.999994f,2.48866e-07f,
24.4969f,5.60545f,25.7787f,-0.228733f,0.999993f,3.46751e-07f, 24.4968f,6.19131f,26.0607f,-0.252632f,0.999992f,4.87443e-07f,
24.4967f,6.78473f,26.3748f,-0.276837f,0.99999f,6.93294e-07f, 24.4966f,7.38655f,26.7226f,-0.301384f,0.999989f,9.99856e-07f,
24.4964f,7.99766f,27.1061f,-0.326307f,0.999987f,1.46326e-06f, 24.4961f,8.619f,27.5273f,-0.351646f,0.999985f,2.17105e-06f,
24.4958f,9.25156f,27.9885f,-0.37744f,0.999983f,3.25766e-06f, 24.4954f,9.89641f,28.4923f,-0.403734f,0.999981f,4.92607e-06f,
24.4949f,10.5547f,29.0415f,-0.430572f,0.999979f,7.47753e-06f, 24.4942f,11.2276f,29.6396f,-0.458006f,0.999976f,1.13517e-05f,
24.4935f,11.9165f,30.29f,-0.486088f,0.999973f,1.71796e-05f, 24.4927f,12.6228f,30.9971f,-0.514877f,0.99997f,2.58536e-05f,
24.4918f,13.3481f,31.7654f,-0.544435f,0.999967f,3.86165e-05f, 24.4909f,14.094f,32.6003f,-0.574831f,0.999963f,5.71764e-05f,
24.4898f,14.8624f,33.5078f,-0.606139f,0.999959f,8.38508e-05f, 24.4886f,15.6553f,34.4947f,-0.63844f,0.999954f,0.000121747f,
24.4872f,16.4748f,35.5687f,-0.671825f,0.999949f,0.000174983f, 24.4856f,17.3235f,36.7387f,-0.706391f,0.999944f,0.000248964f,
24.4837f,18.204f,38.0148f,-0.74225f,0.999938f,0.000350712f, 24.4816f,19.1193f,39.4085f,-0.779521f,0.999932f,0.000489268f,
24.4792f,20.0727f,40.9331f,-0.818339f,0.999925f,0.000676172f, 24.4764f,21.0679f,42.6041f,-0.858858f,0.999917f,0.000926036f,
24.4732f,22.1091f,44.4392f,-0.901245f,0.999908f,0.00125723f, 24.4696f,23.2011f,46.4593f,-0.945692f,0.999898f,0.00169265f,
24.4654f,24.349f,48.6888f,-0.992415f,0.999886f,0.0022607f, 24.4606f,25.559f,51.1563f,-1.04166f,0.999872f,0.00299631f,
24.4551f,26.8381f,53.8957f,-1.09371f,0.999854f,0.00394217f, 24.4488f,28.194f,56.9474f,-1.14887f,0.999829f,0.00514992f,
24.4416f,29.636f,60.3596f,-1.2075f,0.999779f,0.00668049f, 24.4331f,31.1746f,64.1891f,-1.26988f,0.999613f,0.00859625f,
24.4231f,32.8219f,68.5077f,-1.33666f,0.999439f,0.0109987f, 24.4116f,34.5929f,73.4038f,-1.40855f,0.999325f,0.0140077f,
24.3982f,36.5046f,78.9842f,-1.48621f,0.999229f,0.0177473f, 24.3826f,38.5777f,85.3832f,-1.57044f,0.999143f,0.0223693f,
24.3644f,40.8369f,92.7698f,-1.66226f,0.999064f,0.0280535f, 24.3431f,43.3119f,101.36f,-1.76287f,0.998982f,0.0350093f,
24.318f,46.0397f,111.432f,-1.87376f,0.998902f,0.043484f, 24.2881f,49.0654f,123.352f,-1.99678f,0.998815f,0.0537627f,
24.2523f,52.4455f,137.606f,-2.13423f,0.998719f,0.0661773f, 24.2089f,56.2522f,154.852f,-2.28899f,0.998588f,0.0811024f,
24.1551f,60.576f,175.996f,-2.46454f,0.998318f,0.0989399f, 24.0882f,65.5381f,202.321f,-2.66592f,0.997978f,0.120204f,
24.0044f,71.3003f,235.703f,-2.89998f,0.997675f,0.145508f, 23.8964f,78.0775f,278.916f,-3.1751f,0.997237f,0.175428f,
23.754f,86.1683f,336.258f,-3.50324f,0.996588f,0.210635f, 23.5623f,96.0012f,414.655f,-3.90172f,0.995708f,0.251899f,
23.2947f,108.193f,525.825f,-4.39526f,0.994441f,0.299971f, 22.9076f,123.672f,690.74f,-5.02035f,0.992494f,0.355527f,
22.3147f,143.821f,949.769f,-5.83096f,0.989237f,0.418918f, 21.3549f,170.745f,1387.3f,-6.90396f,0.983393f,0.489654f,
19.6957f,207.264f,2195.6f,-8.31758f,0.971718f,0.564595f, 16.7109f,255.0f,3811.07f,-9.95216f,0.946075f,0.632811f,
11.6906f,293.324f,6570.27f,-10.436f,0.898569f,0.668629f, 4.74543f,173.555f,8072.22f,-6.9811f,0.989821f,0.734956f,
19.8412f,8.39271e-09f,19.8412f,-3.62529e-18f,0.999996f,1.52281e-07f, 19.8412f,0.445476f,19.8512f,-0.0224448f,0.999996f,1.5759e-07f,
19.8412f,0.891458f,19.8813f,-0.0449148f,0.999996f,1.73878e-07f, 19.8412f,1.33845f,19.9314f,-0.0674353f,0.999996f,2.02254e-07f,
19.8413f,1.78698f,20.002f,-0.0900319f,0.999995f,2.44634e-07f, 19.8413f,2.23754f,20.0934f,-0.11273f,0.999994f,3.03861e-07f,
19.8413f,2.69069f,20.2058f,-0.135558f,0.999993f,3.83902e-07f, 19.8413f,3.14695f,20.3399f,-0.15854f,0.999992f,4.90164e-07f,
19.8413f,3.60689f,20.4963f,-0.181706f,0.999991f,6.30022e-07f, 19.8413f,4.07108f,20.6758f,-0.205084f,0.999989f,8.13672e-07f,
19.8412f,4.54012f,20.8791f,-0.228703f,0.999987f,1.05552e-06f, 19.8412f,5.01462f,21.1074f,-0.252596f,0.999985f,1.37642e-06f,
19.8411f,5.49525f,21.3617f,-0.276794f,0.999983f,1.80708e-06f, 19.841f,5.98268f,21.6433f,-0.301331f,0.999981f,2.39337e-06f,
19.8408f,6.47763f,21.9538f,-0.326244f,0.999978f,3.20405e-06f, 19.8406f,6.98086f,22.2948f,-0.35157f,0.999975f,4.34211e-06f,
19.8402f,7.49316f,22.6681f,-0.37735f,0.999972f,5.96073e-06f, 19.8398f,8.01541f,23.0759f,-0.403627f,0.999968f,8.28553e-06f,
19.8393f,8.5485f,23.5205f,-0.430447f,0.999964f,1.16449e-05f, 19.8386f,9.09343f,24.0046f,-0.457858f,0.99996f,1.65109e-05f,
19.8378f,9.65126f,24.5312f,-0.485916f,0.999955f,2.35526e-05f, 19.8369f,10.2231f,25.1035f,-0.514676f,0.99995f,3.37068e-05f,
19.8359f,10.8103f,25.7253f,-0.544201f,0.999944f,4.82679e-05f, 19.8347f,11.4142f,26.401f,-0.574559f,0.999938f,6.90026e-05f,
19.8335f,12.0362f,27.1353f,-0.605824f,0.999931f,9.82941e-05f, 19.832f,12.678f,27.9337f,-0.638076f,0.999923f,0.000139321f,
19.8304f,13.3414f,28.8025f,-0.671404f,0.999914f,0.000196279f, 19.8286f,14.0282f,29.7488f,-0.705905f,0.999903f,0.000274647f,
19.8265f,14.7407f,30.7808f,-0.741687f,0.99989f,0.000381504f, 19.8241f,15.4812f,31.9077f,-0.778868f,0.999873f,0.000525894f,
19.8213f,16.2524f,33.1404f,-0.817575f,0.999847f,0.000719178f, 19.8181f,17.0574f,34.4909f,-0.85794f,0.999801f,0.000975074f,
19.8146f,17.8995f,35.9736f,-0.900061f,0.999681f,0.0013078f, 19.8106f,18.7823f,37.6048f,-0.944116f,0.99949f,0.00173815f,
19.8056f,19.71f,39.4048f,-0.990525f,0.999378f,0.00230606f, 19.8f,20.6874f,41.3966f,-1.03946f,0.999288f,0.0030429f,
19.7933f,21.7201f,43.6073f,-1.09118f,0.999211f,0.00399096f, 19.7858f,22.8144f,46.0693f,-1.14599f,0.999141f,0.00520182f,
19.7771f,23.9776f,48.8214f,-1.20427f,0.999076f,0.00673846f, 19.7671f,25.2181f,51.9103f,-1.26643f,0.999013f,0.00867622f,
19.7556f,26.5458f,55.3931f,-1.33297f,0.998952f,0.0111062f, 19.7424f,27.9721f,59.339f,-1.40445f,0.998891f,0.0141361f,
19.7271f,29.5108f,63.8343f,-1.48158f,0.99883f,0.0178945f, 19.7094f,31.1779f,68.9857f,-1.56514f,0.998763f,0.0225321f,
19.6887f,32.993f,74.928f,-1.65612f,0.998687f,0.0282263f, 19.6645f,34.9793f,81.833f,-1.75568f,0.998594f,0.0351841f,
19.6359f,37.1655f,89.9213f,-1.86518f,0.99845f,0.04364f, 19.6016f,39.5858f,99.4782f,-1.98616f,0.998155f,0.0538453f,
19.5607f,42.2851f,110.895f,-2.12125f,0.997914f,0.0661761f, 19.5113f,45.3185f,124.689f,-2.27315f,0.997679f,0.0809989f,
19.4511f,48.7564f,141.574f,-2.44526f,0.997387f,0.0987248f, 19.376f,52.6881f,162.549f,-2.6418f,0.996902f,0.119789f,
19.2822f,57.2358f,189.074f,-2.86924f,0.996395f,0.144799f, 19.1619f,62.5576f,223.288f,-3.13505f,0.995654f,0.174285f,
19.005f,68.8721f,268.494f,-3.45027f,0.994712f,0.208931f, 18.7945f,76.4781f,329.929f,-3.82935f,0.993355f,0.24936f,
18.5237f,85.8895f,416.221f,-4.29278f,0.991386f,0.296209f, 18.0884f,97.4292f,542.983f,-4.86871f,0.988382f,0.349939f,
17.4674f,112.198f,738.301f,-5.59413f,0.983509f,0.410539f, 16.5053f,131.231f,1058.11f,-6.50815f,0.975048f,0.476797f,
14.9926f,155.977f,1613.8f,-7.60609f,0.959302f,0.54442f, 12.4489f,183.853f,2593.91f,-8.6291f,0.929574f,0.602007f,
8.72716f,195.493f,3894.32f,-8.45325f,0.892223f,0.633824f, 4.03957f,119.556f,4518.61f,-5.9241f,0.991712f,0.699651f,
16.3963f,6.01796e-08f,16.3963f,2.38158e-18f,0.999989f,6.77482e-07f, 16.3963f,0.368131f,16.4046f,-0.0224436f,0.999989f,6.93002e-07f,
16.3963f,0.73668f,16.4294f,-0.0449123f,0.999989f,7.40263e-07f, 16.3963f,1.10607f,16.4709f,-0.0674313f,0.999988f,8.21385e-07f,
16.3964f,1.47671f,16.5292f,-0.0900261f,0.999987f,9.40004e-07f, 16.3964f,1.84905f,16.6046f,-0.112722f,0.999986f,1.10142e-06f,
16.3964f,2.22352f,16.6975f,-0.135547f,0.999984f,1.31287e-06f, 16.3964f,2.60057f,16.8083f,-0.158526f,0.999982f,1.58393e-06f,
16.3964f,2.98065f,16.9375f,-0.181687f,0.99998f,1.92712e-06f, 16.3964f,3.36424f,17.0858f,-0.20506f,0.999978f,2.35898e-06f,
16.3964f,3.75185f,17.2538f,-0.228673f,0.999975f,2.90158e-06f, 16.3964f,4.14397f,17.4423f,-0.252557f,0.999971f,3.585e-06f,
16.3963f,4.54114f,17.6524f,-0.276746f,0.999967f,4.45107e-06f, 16.3962f,4.94393f,17.885f,-0.301272f,0.999963f,5.55885e-06f,
16.3961f,5.35293f,18.1414f,-0.326171f,0.999958f,6.99279e-06f, 16.3959f,5.76876f,18.423f,-0.351482f,0.999952f,8.87423e-06f,
16.3956f,6.19209f,18.7313f,-0.377243f,0.999946f,1.13776e-05f, 16.3952f,6.62362f,19.0681f,-0.403498f,0.999938f,1.47522e-05f,
16.3947f,7.0641f,19.4352f,-0.430292f,0.999929f,1.93519e-05f, 16.394f,7.51434f,19.835f,-0.457673f,0.999918f,2.5672e-05f,
16.3932f,7.97521f,20.2698f,-0.485692f,0.999904f,3.43945e-05f, 16.3922f,8.44765f,20.7424f,-0.514404f,0.999884f,4.64333e-05f,
16.3911f,8.9327f,21.2559f,-0.543864f,0.999852f,6.29465e-05f, 16.39f,9.43152f,21.8138f,-0.574119f,0.999793f,8.51855e-05f,
16.3888f,9.9454f,22.42f,-0.605188f,0.999661f,0.000113708f, 16.3876f,10.4757f,23.079f,-0.637165f,0.999471f,0.000151258f,
16.386f,11.0235f,23.7956f,-0.670299f,0.999361f,0.000206968f, 16.384f,11.5906f,24.576f,-0.704623f,0.999274f,0.000284824f,
16.3816f,12.1787f,25.4267f,-0.740231f,0.999201f,0.000391692f, 16.3788f,12.7898f,26.3555f,-0.77724f,0.999138f,0.000536753f,
16.3755f,13.4261f,27.3713f,-0.815775f,0.999081f,0.000731625f, 16.3717f,14.0899f,28.484f,-0.855982f,0.999028f,0.000991008f,
16.3673f,14.7841f,29.7055f,-0.898024f,0.998978f,0.0013334f, 16.3624f,15.5116f,31.0496f,-0.942087f,0.99893f,0.00178191f,
16.3567f,16.276f,32.5323f,-0.988381f,0.998885f,0.00236503f, 16.3501f,17.081f,34.1722f,-1.03714f,0.99884f,0.00311766f,
16.3427f,17.9312f,35.992f,-1.08863f,0.998793f,0.00408236f, 16.3342f,18.8318f,38.0178f,-1.14317f,0.998748f,0.00531161f,
16.3244f,19.7886f,40.2816f,-1.20111f,0.998697f,0.00686731f, 16.3133f,20.8083f,42.8213f,-1.26287f,0.998643f,0.00882527f,
16.3005f,21.899f,45.6832f,-1.32891f,0.998582f,0.011275f, 16.2858f,23.0699f,48.9239f,-1.39978f,0.998502f,0.0143221f,
16.2687f,24.3316f,52.6128f,-1.4761f,0.998376f,0.0180884f, 16.2488f,25.697f,56.8352f,-1.55851f,0.998131f,0.0227067f,
16.2256f,27.1819f,61.7025f,-1.64821f,0.997927f,0.02838f, 16.1985f,28.8046f,67.3536f,-1.74632f,0.997744f,0.0353127f,
16.1666f,30.5877f,73.9668f,-1.85417f,0.997554f,0.0437396f, 16.129f,32.559f,81.7742f,-1.97335f,0.997315f,0.0539271f,
16.0835f,34.7515f,91.0821f,-2.10569f,0.996924f,0.0661624f, 16.029f,37.2094f,102.307f,-2.25411f,0.996528f,0.0808483f,
15.9625f,39.9856f,116.018f,-2.42176f,0.996061f,0.0983838f, 15.8803f,43.1491f,133.005f,-2.61251f,0.995399f,0.119192f,
15.7775f,46.7896f,154.412f,-2.83199f,0.994607f,0.143819f, 15.6468f,51.0245f,181.909f,-3.08691f,0.993544f,0.172786f,
15.4771f,56.009f,218.034f,-3.38643f,0.992111f,0.206673f, 15.2508f,61.9477f,266.769f,-3.74248f,0.990106f,0.246034f,
14.9432f,69.1246f,334.601f,-4.17073f,0.987235f,0.291354f, 14.5092f,77.8952f,432.567f,-4.69039f,0.982916f,0.342833f,
13.8805f,88.7203f,580.212f,-5.32142f,0.9761f,0.400057f, 12.9461f,102.076f,812.929f,-6.07008f,0.964836f,0.461186f,
11.57f,118.276f,1189.64f,-6.87418f,0.945631f,0.521258f, 9.56475f,134.697f,1764.45f,-7.43649f,0.915043f,0.570139f,
6.52255f,129.702f,2412.78f,-6.97282f,0.891472f,0.601605f, 3.49937f,85.4568f,2678.84f,-5.11584f,0.993115f,0.6645f,
13.7761f,4.15602e-08f,13.7761f,-7.20317e-18f,0.999959f,2.36031e-06f, 13.7761f,0.309302f,13.7831f,-0.0224411f,0.999959f,2.39674e-06f,
13.7761f,0.618955f,13.8039f,-0.0449072f,0.999958f,2.50711e-06f, 13.7762f,0.929312f,13.8387f,-0.0674231f,0.999956f,2.69458e-06f,
13.7762f,1.24073f,13.8877f,-0.090014f,0.999953f,2.96449e-06f, 13.7763f,1.55357f,13.9511f,-0.112706f,0.999949f,3.32442e-06f,
13.7763f,1.8682f,14.0292f,-0.135524f,0.999943f,3.78427e-06f, 13.7764f,2.185f,14.1222f,-0.158495f,0.999937f,4.35629e-06f,
13.7764f,2.50435f,14.2308f,-0.181646f,0.999928f,5.05492e-06f, 13.7765f,2.82666f,14.3553f,-0.205004f,0.999916f,5.89614e-06f,
13.7766f,3.15234f,14.4965f,-0.228598f,0.9999f,6.89509e-06f, 13.7767f,3.48182f,14.6549f,-0.252455f,0.999876f,8.05914e-06f,
13.7768f,3.81557f,14.8315f,-0.2766f,0.999838f,9.36695e-06f, 13.7769f,4.15407f,15.0271f,-0.301053f,0.999774f,1.07066e-05f,
13.7773f,4.49788f,15.243f,-0.325818f,0.999652f,1.16987e-05f, 13.778f,4.84757f,15.4804f,-0.350879f,0.999427f,1.15148e-05f,
13.7781f,5.20342f,15.7399f,-0.376472f,0.99928f,1.24464e-05f, 13.7779f,5.56607f,16.0229f,-0.402601f,0.999178f,1.45536e-05f,
13.7773f,5.93616f,16.3313f,-0.429289f,0.999098f,1.79895e-05f, 13.7765f,6.31438f,16.6669f,-0.456574f,0.999033f,2.31997e-05f,
13.7756f,6.70149f,17.0317f,-0.484504f,0.998977f,3.08717e-05f, 13.7744f,7.09827f,17.428f,-0.513132f,0.998927f,4.19919e-05f,
13.7731f,7.50562f,17.8584f,-0.54252f,0.998884f,5.79666e-05f, 13.7717f,7.92445f,18.3259f,-0.57273f,0.998845f,8.06251e-05f,
13.7701f,8.35576f,18.8338f,-0.603835f,0.998808f,0.000112483f, 13.7682f,8.80064f,19.386f,-0.635913f,0.998774f,0.000156854f,
13.766f,9.26031f,19.9866f,-0.669049f,0.998741f,0.000218071f, 13.7635f,9.73607f,20.6406f,-0.703341f,0.998712f,0.000301907f,
13.7606f,10.2294f,21.3535f,-0.738889f,0.998681f,0.000415522f, 13.7574f,10.7419f,22.1317f,-0.775815f,0.998652f,0.000568426f,
13.7536f,11.2754f,22.9825f,-0.814242f,0.998622f,0.000772331f, 13.7494f,11.8319f,23.9145f,-0.854316f,0.99859f,0.00104217f,
13.7445f,12.4136f,24.9373f,-0.896201f,0.998558f,0.00139667f, 13.739f,13.023f,26.0624f,-0.940075f,0.998523f,0.0018589f,
13.7327f,13.663f,27.3031f,-0.986141f,0.998484f,0.00245732f, 13.7256f,14.3369f,28.675f,-1.03463f,0.998438f,0.0032267f,
13.7174f,15.0482f,30.1966f,-1.08579f,0.998378f,0.0042091f, 13.7081f,15.8013f,31.8897f,-1.13991f,0.998292f,0.00545452f,
13.6974f,16.6007f,33.7802f,-1.19727f,0.998141f,0.00701961f, 13.6851f,17.452f,35.8994f,-1.25826f,0.997927f,0.00897647f,
13.6709f,18.3616f,38.2865f,-1.32354f,0.99777f,0.0114306f, 13.6546f,19.3372f,40.988f,-1.39359f,0.99763f,0.0144837f,
13.6358f,20.3875f,44.0612f,-1.46902f,0.997482f,0.0182585f, 13.6141f,21.5228f,47.5773f,-1.55054f,0.997313f,0.0229008f,
13.5888f,22.7556f,51.6252f,-1.63899f,0.997082f,0.0285746f, 13.559f,24.1002f,56.3174f,-1.7353f,0.996738f,0.0354665f,
13.524f,25.5751f,61.8019f,-1.84106f,0.996423f,0.0438409f, 13.4828f,27.2018f,68.2669f,-1.95769f,0.996061f,0.0539525f,
13.4334f,29.0065f,75.9601f,-2.08688f,0.995547f,0.0660796f, 13.3741f,31.0229f,85.2177f,-2.23127f,0.994991f,0.0806041f,
13.3019f,33.2913f,96.4928f,-2.39351f,0.994255f,0.0978828f, 13.213f,35.8641f,110.419f,-2.57743f,0.99337f,0.118371f,
13.1024f,38.8074f,127.893f,-2.78746f,0.992207f,0.142516f, 12.9618f,42.2039f,150.223f,-3.02946f,0.990686f,0.170819f,
12.7809f,46.1636f,179.36f,-3.31074f,0.988645f,0.203776f, 12.5462f,50.8367f,218.295f,-3.64038f,0.985845f,0.241841f,
12.2258f,56.3698f,271.832f,-4.02898f,0.981869f,0.285309f, 11.7864f,62.9862f,347.762f,-4.48716f,0.97602f,0.334131f,
11.1907f,71.0204f,458.793f,-5.01989f,0.967137f,0.387522f, 10.334f,80.4659f,625.832f,-5.60845f,0.953279f,0.443179f,
9.15687f,91.1761f,874.65f,-6.16109f,0.931917f,0.496116f, 7.65887f,101.234f,1200.17f,-6.40792f,0.903705f,0.538581f,
5.43436f,94.4591f,1507.55f,-5.85922f,0.894446f,0.571213f, 3.07347f,62.9396f,1665.27f,-4.48046f,0.994186f,0.629887f,
11.7423f,-1.05063e-07f,11.7423f,-1.73018e-18f,0.999203f,5.47751e-06f, 11.7425f,0.263635f,11.7484f,-0.0222708f,0.99916f,5.40512e-06f,
11.7435f,0.527609f,11.7671f,-0.0445216f,0.999018f,5.11695e-06f, 11.7453f,0.792278f,11.7986f,-0.0667192f,0.998736f,4.36723e-06f,
11.7469f,1.05792f,11.842f,-0.0890307f,0.998465f,3.47317e-06f, 11.7473f,1.32471f,11.8963f,-0.111618f,0.998367f,3.08984e-06f,
11.7474f,1.59299f,11.9628f,-0.134373f,0.998315f,2.88129e-06f, 11.7473f,1.8631f,12.042f,-0.157299f,0.998284f,2.78983e-06f,
11.7471f,2.13537f,12.1342f,-0.180415f,0.998265f,2.80277e-06f, 11.7468f,2.41012f,12.24f,-0.203744f,0.998252f,2.92072e-06f,
11.7465f,2.68772f,12.3598f,-0.227314f,0.998244f,3.15799e-06f, 11.7461f,2.96852f,12.4943f,-0.251155f,0.998239f,3.54433e-06f,
11.7456f,3.25292f,12.6442f,-0.275296f,0.998236f,4.12061e-06f, 11.7451f,3.5413f,12.8101f,-0.299772f,0.998234f,4.95356e-06f,
11.7445f,3.8341f,12.9931f,-0.324616f,0.998232f,6.13588e-06f, 11.7439f,4.13175f,13.194f,-0.349866f,0.998231f,7.81625e-06f,
11.7431f,4.43471f,13.414f,-0.375561f,0.998231f,1.01901e-05f, 11.7422f,4.74349f,13.6543f,-0.401742f,0.99823f,1.35461e-05f,
11.7411f,5.05861f,13.9162f,-0.428455f,0.998229f,1.82912e-05f, 11.7399f,5.38066f,14.2013f,-0.455747f,0.998227f,2.49942e-05f,
11.7386f,5.71025f,14.5112f,-0.483669f,0.998225f,3.44421e-05f, 11.7371f,6.04806f,14.848f,-0.512279f,0.998223f,4.77272e-05f,
11.7355f,6.39482f,15.2138f,-0.541635f,0.998219f,6.63028e-05f, 11.7337f,6.75131f,15.6111f,-0.571801f,0.998214f,9.21307e-05f,
11.7318f,7.11838f,16.0428f,-0.60285f,0.998207f,0.000127818f, 11.7295f,7.49695f,16.5119f,-0.63486f,0.9982f,0.000176842f,
11.7271f,7.88803f,17.0222f,-0.667913f,0.99819f,0.000243645f, 11.7242f,8.29273f,17.5777f,-0.702104f,0.998176f,0.000334031f,
11.721f,8.71228f,18.1832f,-0.737536f,0.99816f,0.000455455f, 11.7174f,9.14804f,18.844f,-0.774318f,0.998136f,0.000617262f,
11.7133f,9.60149f,19.5663f,-0.812576f,0.998105f,0.000831346f, 11.7087f,10.0744f,20.3572f,-0.852438f,0.998057f,0.00111214f,
11.7034f,10.5685f,21.2249f,-0.894046f,0.99798f,0.00147723f, 11.6975f,11.086f,22.1788f,-0.937523f,0.997838f,0.00194631f,
11.6906f,11.6291f,23.2301f,-0.983104f,0.997661f,0.00254853f, 11.6828f,12.2006f,24.3922f,-1.03114f,0.997539f,0.00332677f,
11.6738f,12.8035f,25.6806f,-1.08184f,0.997429f,0.00432059f, 11.6635f,13.4411f,27.1137f,-1.13547f,0.997322f,0.00558108f,
11.6518f,14.1176f,28.7131f,-1.19236f,0.997208f,0.00716916f, 11.6384f,14.8374f,30.5056f,-1.25288f,0.997076f,0.00915786f,
11.623f,15.6058f,32.5226f,-1.31743f,0.9969f,0.0116315f, 11.6053f,16.4289f,34.8023f,-1.38643f,0.996634f,0.0146854f,
11.5848f,17.3137f,37.3933f,-1.46065f,0.996366f,0.0184548f, 11.5611f,18.2688f,40.355f,-1.54082f,0.996109f,0.0230887f,
11.5337f,19.3041f,43.7609f,-1.62767f,0.995801f,0.028746f, 11.5015f,20.4312f,47.7034f,-1.72207f,0.995376f,0.0356067f,
11.4637f,21.6644f,52.3039f,-1.82541f,0.994929f,0.0439176f, 11.419f,23.0206f,57.7156f,-1.939f,0.994392f,0.053925f,
11.3659f,24.5208f,64.142f,-2.06448f,0.993716f,0.0659121f, 11.302f,26.1899f,71.8532f,-2.20401f,0.992909f,0.080218f,
11.2248f,28.0596f,81.2156f,-2.36013f,0.991922f,0.0972065f, 11.1301f,30.1681f,92.7317f,-2.53586f,0.990664f,0.117268f,
11.0124f,32.5622f,107.112f,-2.73505f,0.989061f,0.140832f, 10.8648f,35.3032f,125.371f,-2.9623f,0.986976f,0.168332f,
10.6778f,38.4678f,148.997f,-3.22306f,0.984212f,0.200181f, 10.4328f,42.133f,180.249f,-3.52343f,0.980457f,0.236705f,
10.1125f,46.4168f,222.545f,-3.86929f,0.975229f,0.278029f, 9.69098f,51.4538f,281.17f,-4.26362f,0.967762f,0.323861f,
9.12292f,57.3124f,364.183f,-4.6996f,0.956913f,0.37313f, 8.37204f,64.017f,482.036f,-5.14303f,0.941099f,0.423342f,
7.5255f,72.1609f,638.66f,-5.49574f,0.91926f,0.470027f, 6.21108f,76.2063f,827.841f,-5.54451f,0.895925f,0.508123f,
4.55733f,69.3649f,978.363f,-5.00846f,0.899549f,0.54208f, 2.73142f,47.5421f,1077.02f,-3.96949f,0.995023f,0.596087f,
10.1436f,7.9189e-09f,10.1436f,-2.11853e-17f,0.996055f,4.61736e-07f, 10.1436f,0.227742f,10.1487f,-0.0224157f,0.996055f,4.75647e-07f,
10.1436f,0.455742f,10.164f,-0.0448561f,0.996054f,5.18299e-07f, 10.1436f,0.68426f,10.1896f,-0.0673459f,0.996052f,5.92504e-07f,
10.1436f,0.913556f,10.2256f,-0.0899101f,0.996049f,7.0315e-07f, 10.1437f,1.1439f,10.2722f,-0.112574f,0.996046f,8.57529e-07f,
10.1437f,1.37555f,10.3295f,-0.135364f,0.996042f,1.06585e-06f, 10.1437f,1.6088f,10.3979f,-0.158305f,0.996037f,1.342e-06f,
10.1436f,1.84392f,10.4776f,-0.181426f,0.996031f,1.70468e-06f, 10.1436f,2.0812f,10.5691f,-0.204753f,0.996025f,2.17907e-06f,
10.1435f,2.32096f,10.6728f,-0.228317f,0.996017f,2.79924e-06f, 10.1434f,2.56349f,10.7891f,-0.252147f,0.996008f,3.61163e-06f,
10.1422f,2.80882f,10.9175f,-0.27615f,0.99612f,4.72315e-06f, 10.1402f,3.05735f,11.059f,-0.300425f,0.996292f,6.18657e-06f,
10.1382f,3.30961f,11.2152f,-0.325078f,0.996459f,8.10406e-06f, 10.1362f,3.56603f,11.3869f,-0.350157f,0.996607f,1.06488e-05f,
10.1343f,3.82701f,11.5752f,-0.3757f,0.996735f,1.40641e-05f, 10.1324f,4.093f,11.781f,-0.401746f,0.996845f,1.86839e-05f,
10.1304f,4.36445f,12.0056f,-0.428334f,0.996938f,2.49674e-05f, 10.1285f,4.64186f,12.2501f,-0.455509f,0.997017f,3.35414e-05f,
10.1265f,4.92575f,12.5161f,-0.483318f,0.997085f,4.5259e-05f, 10.1245f,5.2167f,12.8053f,-0.511813f,0.997141f,6.12649e-05f,
10.1223f,5.51534f,13.1194f,-0.54105f,0.997186f,8.30855e-05f, 10.12f,5.82231f,13.4607f,-0.57109f,0.997218f,0.000112728f,
10.1176f,6.13835f,13.8315f,-0.601998f,0.997236f,0.000152787f, 10.1149f,6.46425f,14.2344f,-0.633843f,0.997235f,0.000206542f,
10.112f,6.80086f,14.6727f,-0.66669f,0.997202f,0.000277957f, 10.1088f,7.14916f,15.1497f,-0.700601f,0.997115f,0.000371515f,
10.1053f,7.51018f,15.6694f,-0.735677f,0.996978f,0.000493948f, 10.1012f,7.88493f,16.2365f,-0.772158f,0.996895f,0.000659869f,
10.0965f,8.27474f,16.8561f,-0.810124f,0.996829f,0.00088006f, 10.0912f,8.68101f,17.5344f,-0.849697f,0.996768f,0.00116927f,
10.0853f,9.10536f,18.2784f,-0.891025f,0.996707f,0.00154616f, 10.0785f,9.5495f,19.0962f,-0.934272f,0.99664f,0.00203372f,
10.0709f,10.0154f,19.9972f,-0.979623f,0.996561f,0.00266014f, 10.0622f,10.5054f,20.9926f,-1.02728f,0.99646f,0.00345916f,
10.0524f,11.0219f,22.0954f,-1.07746f,0.996316f,0.00447059f, 10.0412f,11.5678f,23.3208f,-1.13038f,0.996092f,0.00573995f,
10.0284f,12.1463f,24.6878f,-1.1865f,0.995889f,0.00733842f, 10.0139f,12.7613f,26.2186f,-1.24619f,0.995695f,0.00933947f,
9.99721f,13.417f,27.9399f,-1.30982f,0.995478f,0.0118261f, 9.97806f,14.1184f,29.8838f,-1.37781f,0.995199f,0.0148952f,
9.95588f,14.8711f,32.0902f,-1.45068f,0.994831f,0.0186606f, 9.93037f,15.6823f,34.6091f,-1.52925f,0.994468f,0.0232799f,
9.90077f,16.5597f,37.5017f,-1.61419f,0.994038f,0.0289054f, 9.86621f,17.5128f,40.8446f,-1.70631f,0.993491f,0.0357158f,
9.8257f,18.5526f,44.7374f,-1.80684f,0.992891f,0.0439448f, 9.77788f,19.6924f,49.3068f,-1.91687f,0.992137f,0.0538183f,
9.72136f,20.9488f,54.7184f,-2.03803f,0.991249f,0.0656265f, 9.65362f,22.3403f,61.1912f,-2.17204f,0.990162f,0.0796707f,
9.5717f,23.89f,69.0195f,-2.32103f,0.988815f,0.0962886f, 9.47188f,25.626f,78.6049f,-2.48756f,0.987135f,0.115845f,
9.35111f,27.5884f,90.4962f,-2.67458f,0.985004f,0.138717f, 9.19686f,29.8018f,105.495f,-2.88547f,0.982254f,0.16527f,
9.00883f,32.3432f,124.701f,-3.12388f,0.978655f,0.195831f, 8.76451f,35.2359f,149.783f,-3.39308f,0.973843f,0.230597f,
8.45344f,38.5623f,183.113f,-3.69482f,0.96731f,0.269537f, 8.06246f,42.4217f,228.065f,-4.02591f,0.958296f,0.312163f,
7.63614f,47.2176f,287.986f,-4.3715f,0.945825f,0.357228f, 6.92077f,51.5944f,370.638f,-4.6909f,0.928968f,0.402321f,
6.25364f,57.1747f,468.713f,-4.89463f,0.908323f,0.443836f, 5.07718f,57.3969f,582.277f,-4.8295f,0.891322f,0.479062f,
3.78562f,50.8421f,662.538f,-4.34598f,0.905551f,0.513838f, 2.45077f,36.6716f,720.519f,-3.55064f,0.995685f,0.563292f,
8.83441f,-1.1772e-07f,8.83441f,-6.78119e-18f,0.99601f,1.32041e-06f, 8.83442f,0.198346f,8.83885f,-0.0224073f,0.99601f,1.35011e-06f,
8.83443f,0.396917f,8.85218f,-0.0448391f,0.996008f,1.4407e-06f, 8.83445f,0.595939f,8.87445f,-0.0673197f,0.996005f,1.59669e-06f,
8.83447f,0.79564f,8.90578f,-0.089874f,0.996001f,1.82584e-06f, 8.83449f,0.99625f,8.9463f,-0.112527f,0.995995f,2.13959e-06f,
8.83451f,1.198f,8.99619f,-0.135304f,0.995989f,2.55367e-06f, 8.83453f,1.40114f,9.05569f,-0.158232f,0.995981f,3.08901e-06f,
8.83454f,1.60592f,9.12507f,-0.181336f,0.995971f,3.77303e-06f, 8.83453f,1.81257f,9.20465f,-0.204645f,0.99596f,4.64151e-06f,
8.8345f,2.02138f,9.29481f,-0.228188f,0.995947f,5.74117e-06f, 8.83443f,2.2326f,9.396f,-0.251993f,0.995931f,7.13327e-06f,
8.83432f,2.44654f,9.50871f,-0.276092f,0.995913f,8.8985e-06f, 8.83417f,2.66348f,9.63352f,-0.300516f,0.995892f,1.11437e-05f,
8.83393f,2.88373f,9.77108f,-0.3253f,0.995868f,1.40101e-05f, 8.8336f,3.10763f,9.92212f,-0.350478f,0.995838f,1.76843e-05f,
8.83315f,3.33552f,10.0875f,-0.376087f,0.995801f,2.24093e-05f, 8.83258f,3.56777f,10.268f,-0.402163f,0.995754f,2.84938e-05f,
8.83188f,3.80479f,10.4647f,-0.428745f,0.995691f,3.6312e-05f, 8.83111f,4.04701f,10.6788f,-0.455869f,0.995604f,4.62771e-05f,
8.83032f,4.29494f,10.9113f,-0.483565f,0.995476f,5.8764e-05f, 8.82953f,4.5491f,11.1639f,-0.51186f,0.995287f,7.40408e-05f,
8.82844f,4.80989f,11.438f,-0.540935f,0.995142f,9.60688e-05f, 8.82704f,5.07788f,11.7355f,-0.570838f,0.995028f,0.000126991f,
8.82533f,5.35372f,12.0585f,-0.601618f,0.994927f,0.000169288f, 8.82327f,5.63806f,12.4094f,-0.63334f,0.994832f,0.000226511f,
8.82084f,5.93166f,12.7909f,-0.666083f,0.99474f,0.00030338f, 8.818f,6.23531f,13.206f,-0.699933f,0.994647f,0.000405869f,
8.81471f,6.54993f,13.6581f,-0.734983f,0.994548f,0.000541604f, 8.8109f,6.87647f,14.1512f,-0.771336f,0.99444f,0.000720092f,
8.80651f,7.21602f,14.6898f,-0.809101f,0.994313f,0.000953084f, 8.80113f,7.5695f,15.2785f,-0.848356f,0.994183f,0.00125473f,
8.79405f,7.93761f,15.9223f,-0.889148f,0.994074f,0.00164159f, 8.78584f,8.32236f,16.629f,-0.931753f,0.993962f,0.0021378f,
8.77653f,8.72552f,17.4072f,-0.976469f,0.993893f,0.00277718f, 8.76611f,9.14909f,18.2665f,-1.02346f,0.993822f,0.00359193f,
8.75451f,9.59522f,19.218f,-1.07295f,0.993726f,0.00462238f, 8.74154f,10.0663f,20.2749f,-1.12515f,0.99358f,0.00591614f,
8.72692f,10.5651f,21.4527f,-1.18033f,0.993352f,0.00752854f, 8.71043f,11.0946f,22.7706f,-1.23895f,0.993121f,0.00954026f,
8.69177f,11.6584f,24.2512f,-1.30138f,0.992866f,0.0120351f, 8.67054f,12.2606f,25.9217f,-1.36799f,0.992535f,0.0151055f,
8.6463f,12.9059f,27.8155f,-1.43928f,0.99212f,0.0188664f, 8.61851f,13.5999f,29.9744f,-1.51597f,0.99167f,0.0234638f,
8.58641f,14.3487f,32.4491f,-1.59859f,0.991094f,0.0290399f, 8.54932f,15.1601f,35.3044f,-1.68807f,0.990442f,0.0357877f,
8.50606f,16.0427f,38.6217f,-1.78526f,0.989637f,0.043901f, 8.4553f,17.0068f,42.5052f,-1.89131f,0.988683f,0.0536195f,
8.39528f,18.0643f,47.0905f,-2.00747f,0.987525f,0.065199f, 8.32388f,19.2298f,52.5551f,-2.13522f,0.986109f,0.0789247f,
8.23918f,20.5225f,59.1336f,-2.27628f,0.984362f,0.0951051f, 8.13645f,21.9599f,67.1438f,-2.43262f,0.982195f,0.114068f,
8.01078f,23.5651f,77.0209f,-2.60635f,0.979457f,0.136133f, 7.85686f,25.3678f,89.3589f,-2.79968f,0.975969f,0.161604f,
7.67168f,27.4161f,104.97f,-3.01451f,0.97146f,0.19071f, 7.43346f,29.7038f,125.066f,-3.25172f,0.965561f,0.223541f,
7.13947f,32.2959f,151.202f,-3.50961f,0.957767f,0.259925f, 6.80288f,35.347f,185.12f,-3.78073f,0.947441f,0.299253f,
6.34512f,38.5184f,229.51f,-4.04595f,0.933924f,0.340233f, 5.83983f,42.0992f,284.652f,-4.26472f,0.917099f,0.380738f,
5.08501f,44.0992f,351.016f,-4.3636f,0.89912f,0.418134f, 4.18615f,43.4326f,416.957f,-4.23988f,0.889126f,0.451439f,
3.32753f,39.3607f,455.506f,-3.82007f,0.911692f,0.486366f, 2.21743f,28.8036f,496.249f,-3.20167f,0.996209f,0.531638f,
7.7631f,8.08108e-08f,7.7631f,-4.04384e-18f,0.995874f,3.2778e-06f, 7.76311f,0.174291f,7.767f,-0.0223915f,0.995873f,3.33257e-06f,
7.76313f,0.348779f,7.77871f,-0.0448068f,0.995868f,3.49869e-06f, 7.76317f,0.523665f,7.79827f,-0.0672697f,0.99586f,3.78162e-06f,
7.76322f,0.699148f,7.8258f,-0.0898041f,0.995848f,4.19042e-06f, 7.76329f,0.875432f,7.8614f,-0.112434f,0.995832f,4.73771e-06f,
7.76337f,1.05272f,7.90524f,-0.135184f,0.995811f,5.43925e-06f, 7.76346f,1.23124f,7.95751f,-0.158078f,0.995783f,6.31308e-06f,
7.76355f,1.41119f,8.01848f,-0.181141f,0.995747f,7.37733e-06f, 7.76366f,1.5928f,8.08842f,-0.204396f,0.995699f,8.64551e-06f,
7.76379f,1.77632f,8.1677f,-0.227867f,0.995634f,1.01167e-05f, 7.76393f,1.96197f,8.25669f,-0.251575f,0.995544f,1.17564e-05f,
7.76412f,2.15003f,8.35588f,-0.275536f,0.995418f,1.34623e-05f, 7.76434f,2.34077f,8.46578f,-0.299766f,0.995239f,1.50122e-05f,
7.76446f,2.53442f,8.58681f,-0.324348f,0.995056f,1.6868e-05f, 7.76425f,2.7312f,8.71942f,-0.349394f,0.994938f,2.01208e-05f,
7.76383f,2.93145f,8.86445f,-0.374893f,0.994842f,2.47146e-05f, 7.76321f,3.1355f,9.02274f,-0.400876f,0.994757f,3.0987e-05f,
7.76237f,3.34367f,9.19517f,-0.42738f,0.99468f,3.94575e-05f, 7.76133f,3.55635f,9.38271f,-0.454447f,0.994606f,5.08546e-05f,
7.76014f,3.77395f,9.58641f,-0.482124f,0.994533f,6.61344e-05f, 7.75879f,3.99691f,9.80754f,-0.510461f,0.994459f,8.6604e-05f,
7.75727f,4.2257f,10.0475f,-0.539512f,0.994381f,0.000113926f, 7.75554f,4.4608f,10.308f,-0.569333f,0.994295f,0.000150271f,
7.75356f,4.70276f,10.5907f,-0.599987f,0.994195f,0.000198399f, 7.75127f,4.95214f,10.8978f,-0.631536f,0.994076f,0.000261764f,
7.74866f,5.2096f,11.2314f,-0.664042f,0.993922f,0.000344465f, 7.74564f,5.47582f,11.5943f,-0.697569f,0.993718f,0.000451455f,
7.74211f,5.75151f,11.9894f,-0.732274f,0.993515f,0.000592323f, 7.73797f,6.03749f,12.4201f,-0.768304f,0.993343f,0.000778846f,
7.73317f,6.33469f,12.8903f,-0.805738f,0.993175f,0.00102226f, 7.72766f,6.64413f,13.4045f,-0.844688f,0.992995f,0.00133728f,
7.72135f,6.96697f,13.9678f,-0.885278f,0.992791f,0.0017419f, 7.71415f,7.30446f,14.5863f,-0.927642f,0.992545f,0.00225764f,
7.70598f,7.65807f,15.2667f,-0.97192f,0.992235f,0.00290998f, 7.69639f,8.02904f,16.0176f,-1.01843f,0.991943f,0.00373991f,
7.68557f,8.41951f,16.8482f,-1.06736f,0.991642f,0.00478714f, 7.67311f,8.83123f,17.7701f,-1.1189f,0.991297f,0.00609809f,
7.65887f,9.26658f,18.7962f,-1.17329f,0.990873f,0.00772691f, 7.64259f,9.7281f,19.9429f,-1.23096f,0.990433f,0.00975113f,
7.62386f,10.2186f,21.2294f,-1.29222f,0.989951f,0.0122512f, 7.60237f,10.7415f,22.6785f,-1.3574f,0.989368f,0.0153157f,
7.57761f,11.3007f,24.3194f,-1.42709f,0.988744f,0.0190676f, 7.54906f,11.9004f,26.1857f,-1.50171f,0.988002f,0.023627f,
7.51609f,12.546f,28.321f,-1.58197f,0.987178f,0.0291528f, 7.48736f,13.2602f,30.7677f,-1.66848f,0.9862f,0.0358071f,
7.43254f,13.9979f,33.6268f,-1.76209f,0.985067f,0.043789f, 7.37991f,14.8194f,36.9503f,-1.86373f,0.983737f,0.0533153f,
7.31832f,15.7172f,40.8592f,-1.97441f,0.982157f,0.0646246f, 7.24667f,16.7044f,45.4953f,-2.09534f,0.980269f,0.0779805f,
7.15735f,17.7816f,51.0526f,-2.22779f,0.977982f,0.0936578f, 7.05348f,18.9781f,57.7726f,-2.37313f,0.975184f,0.11194f,
6.92997f,20.3089f,65.9823f,-2.5327f,0.971722f,0.133097f, 6.7795f,21.7864f,76.1365f,-2.70762f,0.967402f,0.157366f,
6.59426f,23.4242f,88.8347f,-2.89826f,0.961943f,0.18489f, 6.36696f,25.2388f,104.871f,-3.10356f,0.955003f,0.215665f,
6.10559f,27.3085f,125.112f,-3.31931f,0.946146f,0.249418f, 5.85042f,29.882f,150.077f,-3.53557f,0.934929f,0.285482f,
5.49629f,32.4777f,181.235f,-3.73212f,0.92112f,0.322647f, 4.97768f,34.443f,219.635f,-3.87273f,0.905388f,0.359167f,
4.36999f,35.5395f,261.284f,-3.901f,0.891349f,0.393299f, 3.70495f,34.8988f,298.272f,-3.7525f,0.888598f,0.425177f,
2.77727f,29.3826f,328.623f,-3.39479f,0.917545f,0.459656f, 2.13672f,23.9824f,344.699f,-2.90682f,0.99663f,0.501226f,
6.87869f,1.55278e-07f,6.8787f,-6.21574e-18f,0.994898f,6.03928e-06f, 6.87878f,0.154422f,6.88221f,-0.0222456f,0.994875f,6.04634e-06f,
6.87903f,0.309028f,6.8928f,-0.0445015f,0.994806f,6.04972e-06f, 6.87945f,0.464004f,6.91051f,-0.0667769f,0.994684f,5.99203e-06f,
6.88009f,0.619541f,6.93545f,-0.0890794f,0.994498f,5.76462e-06f, 6.88073f,0.775813f,6.96752f,-0.111477f,0.994295f,5.44194e-06f,
6.8809f,0.932949f,7.00641f,-0.134121f,0.994205f,5.60613e-06f, 6.88091f,1.09115f,7.05258f,-0.156949f,0.994151f,6.06107e-06f,
6.88082f,1.2506f,7.10634f,-0.179968f,0.994113f,6.78954e-06f, 6.88068f,1.4115f,7.16797f,-0.203195f,0.994082f,7.81827e-06f,
6.88049f,1.57406f,7.23779f,-0.226656f,0.994055f,9.20411e-06f, 6.88024f,1.73848f,7.3161f,-0.250375f,0.994029f,1.10238e-05f,
6.87994f,1.90499f,7.40334f,-0.274383f,0.994002f,1.33853e-05f, 6.87958f,2.07382f,7.49991f,-0.298709f,0.993972f,1.64291e-05f,
6.87913f,2.2452f,7.60633f,-0.323384f,0.993939f,2.03474e-05f, 6.8786f,2.41939f,7.72315f,-0.348443f,0.993899f,2.53776e-05f,
6.87795f,2.59665f,7.85102f,-0.37392f,0.993853f,3.18436e-05f, 6.87716f,2.77727f,7.99063f,-0.39985f,0.993795f,4.01431e-05f,
6.87621f,2.96154f,8.14279f,-0.426271f,0.993722f,5.07817e-05f, 6.87506f,3.14977f,8.30835f,-0.453219f,0.993627f,6.43721e-05f,
6.87372f,3.34232f,8.48827f,-0.480732f,0.993501f,8.16277e-05f, 6.87221f,3.53957f,8.68358f,-0.508843f,0.993331f,0.000103341f,
6.87053f,3.74193f,8.89538f,-0.537644f,0.99315f,0.000131774f, 6.86856f,3.9498f,9.12506f,-0.567258f,0.993009f,0.000170856f,
6.86631f,4.16366f,9.37423f,-0.597712f,0.992877f,0.00022298f, 6.86372f,4.38401f,9.64472f,-0.629064f,0.992743f,0.000291827f,
6.86075f,4.6114f,9.93856f,-0.661382f,0.992599f,0.000382185f, 6.85734f,4.8464f,10.258f,-0.694738f,0.992435f,0.000499968f,
6.85345f,5.08971f,10.6057f,-0.729206f,0.992239f,0.000652359f, 6.84898f,5.342f,10.9844f,-0.764865f,0.991996f,0.000848045f,
6.84384f,5.60405f,11.3977f,-0.80186f,0.991733f,0.00110043f, 6.83795f,5.87674f,11.8494f,-0.840371f,0.991492f,0.00142758f,
6.83117f,6.16098f,12.3439f,-0.880485f,0.991237f,0.00184646f, 6.82334f,6.45779f,12.8866f,-0.922319f,0.990942f,0.00237844f,
6.81449f,6.76848f,13.4832f,-0.966011f,0.990589f,0.00304918f, 6.8043f,7.09422f,14.1408f,-1.0118f,0.990212f,0.00389514f,
6.7927f,7.43659f,14.8679f,-1.05991f,0.989825f,0.00495873f, 6.77945f,7.79719f,15.6737f,-1.1105f,0.989377f,0.00628365f,
6.76434f,8.17792f,16.5698f,-1.16383f,0.98886f,0.00792618f, 6.74701f,8.58078f,17.5702f,-1.22026f,0.988313f,0.0099598f,
6.72722f,9.00827f,18.6905f,-1.28002f,0.987672f,0.0124567f, 6.70457f,9.46309f,19.9511f,-1.34355f,0.986972f,0.0155163f,
6.67857f,9.94828f,21.3751f,-1.41119f,0.986158f,0.01924f, 6.65719f,10.4807f,22.9841f,-1.48348f,0.985247f,0.023758f,
6.61377f,11.0237f,24.8381f,-1.5609f,0.984189f,0.0292076f, 6.57401f,11.6234f,26.9569f,-1.64404f,0.982968f,0.0357521f,
6.52732f,12.27f,29.4046f,-1.73359f,0.981549f,0.0435733f, 6.47393f,12.9722f,32.25f,-1.83028f,0.97989f,0.052873f,
6.41079f,13.734f,35.5831f,-1.93492f,0.977928f,0.0638699f, 6.33507f,14.5609f,39.5218f,-2.04837f,0.975593f,0.0767999f,
6.2507f,15.4761f,44.1994f,-2.17152f,0.97279f,0.091907f, 6.14382f,16.4631f,49.8276f,-2.3052f,0.969396f,0.109432f,
6.02865f,17.5789f,56.6191f,-2.45003f,0.965257f,0.129598f, 5.87813f,18.7716f,64.9495f,-2.60616f,0.960169f,0.152573f,
5.69988f,20.0837f,75.1974f,-2.77278f,0.953872f,0.178431f, 5.49494f,21.5461f,87.8219f,-2.94737f,0.946083f,0.207098f,
5.2619f,23.1792f,103.331f,-3.12422f,0.93648f,0.238241f, 5.0425f,25.1906f,121.729f,-3.2924f,0.924866f,0.2712f,
4.70077f,26.8948f,144.196f,-3.43288f,0.911461f,0.304924f, 4.21648f,27.8395f,170.795f,-3.51565f,0.897613f,0.338079f,
3.69537f,28.0953f,197.92f,-3.50037f,0.887338f,0.369637f, 3.10489f,26.7501f,221.843f,-3.3474f,0.889922f,0.400258f,
2.58866f,24.2038f,234.34f,-3.04503f,0.922905f,0.43377f, 1.96029f,19.3964f,249.172f,-2.65466f,0.996969f,0.472122f,
6.14559f,2.36521e-07f,6.14559f,-9.35931e-18f,0.991797f,3.49105e-06f, 6.1456f,0.137967f,6.14867f,-0.022348f,0.991795f,3.55751e-06f,
6.14563f,0.27609f,6.15791f,-0.0447191f,0.991789f,3.75958e-06f, 6.14566f,0.414525f,6.17335f,-0.0671367f,0.991779f,4.10547e-06f,
6.14571f,0.553434f,6.19505f,-0.0896241f,0.991763f,4.6091e-06f, 6.14577f,0.692974f,6.22314f,-0.112205f,0.991743f,5.29042e-06f,
6.14581f,0.833306f,6.25768f,-0.134897f,0.991723f,6.18149e-06f, 6.14524f,0.97449f,6.29825f,-0.157607f,0.991817f,7.40228e-06f,
6.14447f,1.11674f,6.34544f,-0.180455f,0.991939f,8.89735e-06f, 6.14367f,1.26026f,6.39965f,-0.203503f,0.992051f,1.06912e-05f,
6.14289f,1.40523f,6.4612f,-0.226784f,0.992138f,1.28399e-05f, 6.14215f,1.55186f,6.53041f,-0.250322f,0.992195f,1.54047e-05f,
6.14145f,1.70035f,6.60763f,-0.274139f,0.992217f,1.84405e-05f, 6.14078f,1.8509f,6.69327f,-0.298257f,0.992199f,2.1981e-05f,
6.14012f,2.00374f,6.78774f,-0.322695f,0.992131f,2.60196e-05f, 6.13944f,2.15909f,6.89154f,-0.347484f,0.992017f,3.0631e-05f,
6.13854f,2.31712f,7.00502f,-0.372755f,0.991945f,3.73089e-05f, 6.13746f,2.47811f,7.12888f,-0.398513f,0.991888f,4.63347e-05f,
6.13618f,2.64231f,7.26383f,-0.424781f,0.991831f,5.82402e-05f, 6.13471f,2.81f,7.41064f,-0.451593f,0.991768f,7.38179e-05f,
6.13299f,2.98149f,7.57016f,-0.47899f,0.991694f,9.41174e-05f, 6.13108f,3.1571f,7.74331f,-0.507012f,0.991603f,0.000120464f,
6.12898f,3.33721f,7.93113f,-0.535703f,0.991488f,0.000154528f, 6.12668f,3.52221f,8.13481f,-0.565109f,0.991339f,0.000198325f,
6.12416f,3.71252f,8.35571f,-0.595275f,0.991145f,0.000254292f, 6.12126f,3.90851f,8.59542f,-0.626315f,0.990945f,0.000327467f,
6.11793f,4.11066f,8.85569f,-0.658337f,0.990765f,0.000424153f, 6.11418f,4.31951f,9.13849f,-0.691384f,0.990576f,0.000549925f,
6.10988f,4.53561f,9.44612f,-0.725525f,0.990362f,0.000712135f, 6.1051f,4.75964f,9.78108f,-0.760836f,0.99011f,0.000919964f,
6.09951f,4.99211f,10.1464f,-0.797398f,0.989803f,0.00118438f, 6.09301f,5.23372f,10.5454f,-0.83541f,0.989502f,0.00152417f,
6.08569f,5.48545f,10.982f,-0.874969f,0.989184f,0.00195709f, 6.0774f,5.74817f,11.4607f,-0.91618f,0.988822f,0.00250402f,
6.06795f,6.02282f,11.9865f,-0.959166f,0.988395f,0.00319036f, 6.05711f,6.31044f,12.5658f,-1.00418f,0.987957f,0.004054f,
6.04483f,6.61237f,13.2053f,-1.05136f,0.987467f,0.00513153f, 6.03083f,6.92992f,13.9133f,-1.10089f,0.986901f,0.00646743f,
6.01491f,7.26466f,14.6999f,-1.15305f,0.986296f,0.00812244f, 5.99673f,7.61826f,15.5763f,-1.20805f,0.985594f,0.0101561f,
5.97619f,7.99292f,16.5566f,-1.26622f,0.984826f,0.0126504f, 5.95874f,8.39911f,17.6524f,-1.32784f,0.983943f,0.0156892f,
5.92513f,8.81282f,18.899f,-1.3933f,0.98295f,0.0193789f, 5.89428f,9.26428f,20.3051f,-1.46298f,0.981819f,0.023836f,
5.85835f,9.74635f,21.9065f,-1.53731f,0.980518f,0.0291939f, 5.81763f,10.2644f,23.7387f,-1.6168f,0.97902f,0.0356039f,
5.76981f,10.8201f,25.8481f,-1.70195f,0.977287f,0.0432351f, 5.71388f,11.4179f,28.2924f,-1.79334f,0.975261f,0.0522702f,
5.651f,12.068f,31.1384f,-1.89155f,0.972891f,0.0629112f, 5.57764f,12.7724f,34.4776f,-1.99715f,0.970086f,0.0753639f,
5.49021f,13.5337f,38.4299f,-2.11063f,0.96675f,0.0898405f, 5.3901f,14.3669f,43.124f,-2.23235f,0.962759f,0.106543f,
5.27838f,15.2909f,48.7368f,-2.3623f,0.957962f,0.125644f, 5.13404f,16.2611f,55.531f,-2.49989f,0.952174f,0.147261f,
5.01029f,17.4619f,63.5513f,-2.64341f,0.945179f,0.171412f, 4.82442f,18.6425f,73.3881f,-2.78938f,0.93676f,0.197967f,
4.5744f,19.7606f,85.4087f,-2.93147f,0.926776f,0.226589f, 4.35614f,21.179f,99.1101f,-3.05895f,0.915286f,0.25667f,
4.05534f,22.3274f,115.082f,-3.15513f,0.902912f,0.287345f, 3.72391f,23.2481f,131.958f,-3.19651f,0.891521f,0.317671f,
3.31695f,23.3374f,148.907f,-3.15515f,0.885438f,0.347132f, 2.91415f,22.5641f,162.101f,-3.00779f,0.893105f,0.376585f,
2.25041f,18.923f,175.213f,-2.75294f,0.927674f,0.408787f, 1.80728f,15.8679f,183.761f,-2.43666f,0.997244f,0.444364f,
5.51579f,1.5516e-07f,5.51578f,-1.18685e-17f,0.991047f,6.70898e-06f, 5.51582f,0.123814f,5.51857f,-0.0222626f,0.991037f,6.7876e-06f,
5.5159f,0.247772f,5.5269f,-0.0445439f,0.991006f,7.02133e-06f, 5.51605f,0.372014f,5.54084f,-0.0668622f,0.990952f,7.40279e-06f,
5.51626f,0.496689f,5.56044f,-0.0892354f,0.990872f,7.91609e-06f, 5.51654f,0.621941f,5.58581f,-0.111681f,0.990762f,8.53111e-06f,
5.51689f,0.747923f,5.61706f,-0.134214f,0.990615f,9.19498e-06f, 5.51731f,0.874786f,5.65433f,-0.156851f,0.990424f,9.8209e-06f,
5.51763f,1.00267f,5.69763f,-0.179681f,0.99025f,1.07004e-05f, 5.51773f,1.1317f,5.74703f,-0.202776f,0.990139f,1.22398e-05f,
5.51773f,1.26204f,5.8029f,-0.226112f,0.990046f,1.43466e-05f, 5.51765f,1.39388f,5.86552f,-0.249705f,0.989959f,1.70945e-05f,
5.51749f,1.52738f,5.93522f,-0.273578f,0.989873f,2.06105e-05f, 5.51726f,1.66273f,6.01236f,-0.297755f,0.989781f,2.50559e-05f,
5.51694f,1.80011f,6.09731f,-0.322265f,0.98968f,3.06417e-05f, 5.51653f,1.93972f,6.19053f,-0.347135f,0.989564f,3.76198e-05f,
5.51599f,2.08178f,6.29254f,-0.372393f,0.989428f,4.62961e-05f, 5.51532f,2.2265f,6.40388f,-0.398069f,0.989264f,5.70215e-05f,
5.51447f,2.37411f,6.5252f,-0.42419f,0.989063f,7.01901e-05f, 5.51323f,2.52477f,6.65693f,-0.45079f,0.988862f,8.67563e-05f,
5.51132f,2.67859f,6.79936f,-0.477932f,0.98876f,0.000109138f, 5.50905f,2.836f,6.95366f,-0.505682f,0.988681f,0.000138424f,
5.50649f,2.99735f,7.12089f,-0.534093f,0.9886f,0.00017638f, 5.50368f,3.16298f,7.30217f,-0.563213f,0.988498f,0.000225259f,
5.50059f,3.33326f,7.49874f,-0.593092f,0.988362f,0.000287879f, 5.49716f,3.50858f,7.712f,-0.62378f,0.988178f,0.000367621f,
5.49336f,3.68936f,7.94344f,-0.65539f,0.987981f,0.000470735f, 5.48922f,3.87611f,8.1948f,-0.688021f,0.987787f,0.000604685f,
5.48432f,4.06908f,8.46818f,-0.721717f,0.987563f,0.000776427f, 5.47865f,4.26881f,8.76583f,-0.756543f,0.987294f,0.000995007f,
5.47241f,4.47608f,9.09018f,-0.792587f,0.986971f,0.00127193f, 5.46537f,4.69143f,9.44424f,-0.830023f,0.986643f,0.00162535f,
5.45748f,4.91558f,9.83137f,-0.868925f,0.986276f,0.00207211f, 5.44846f,5.14917f,10.2554f,-0.909383f,0.985841f,0.00263219f,
5.4383f,5.39315f,10.7209f,-0.95159f,0.985373f,0.00333541f, 5.4268f,5.64838f,11.2331f,-0.995683f,0.984854f,0.0042131f,
5.41381f,5.91593f,11.7979f,-1.0418f,0.984256f,0.00530135f, 5.39907f,6.19689f,12.4225f,-1.09017f,0.983608f,0.00664946f,
5.38259f,6.4928f,13.1152f,-1.14096f,0.982863f,0.00830678f, 5.36467f,6.80587f,13.8855f,-1.19443f,0.982042f,0.0103402f,
5.34179f,7.13354f,14.747f,-1.25079f,0.981104f,0.0128194f, 5.31746f,7.48257f,15.7116f,-1.31034f,0.980045f,0.0158304f,
5.28946f,7.85258f,16.7969f,-1.37338f,0.97885f,0.0194715f, 5.25763f,8.24628f,18.0236f,-1.44023f,0.977487f,0.0238527f,
5.22263f,8.66822f,19.4142f,-1.51123f,0.975924f,0.0290983f, 5.1782f,9.11191f,21.0041f,-1.58678f,0.974131f,0.0353495f,
5.13156f,9.59398f,22.8237f,-1.66726f,0.972064f,0.0427609f, 5.07943f,10.1147f,24.9178f,-1.75305f,0.969662f,0.0514978f,
5.03687f,10.7124f,27.3141f,-1.84454f,0.966865f,0.0617399f, 4.94388f,11.2675f,30.1828f,-1.942f,0.963586f,0.073668f,
4.85941f,11.9112f,33.5062f,-2.04563f,0.959731f,0.0874638f, 4.77213f,12.6325f,37.3939f,-2.15534f,0.955178f,0.10329f,
4.65246f,13.3646f,42.0412f,-2.27063f,0.94979f,0.121279f, 4.53231f,14.202f,47.4939f,-2.39035f,0.94342f,0.141505f,
4.39061f,15.0949f,53.9686f,-2.51221f,0.935913f,0.163947f, 4.22224f,16.0253f,61.6311f,-2.63228f,0.927156f,0.188449f,
4.04138f,17.0306f,70.4613f,-2.74419f,0.917176f,0.214689f, 3.8864f,18.2538f,80.081f,-2.83817f,0.906291f,0.242149f,
3.60512f,18.9554f,91.4211f,-2.90037f,0.895462f,0.27016f, 3.26336f,19.1962f,103.315f,-2.91313f,0.886873f,0.298095f,
2.95027f,19.1706f,114.217f,-2.85768f,0.884838f,0.325776f, 2.5236f,17.8792f,123.525f,-2.7209f,0.896711f,0.354053f,
2.04831f,15.4504f,131.701f,-2.50569f,0.932076f,0.384816f, 1.67566f,13.1272f,137.829f,-2.24639f,0.997466f,0.41797f,
4.98725f,-4.77849e-07f,4.98725f,-1.03778e-18f,0.987368f,5.50221e-06f, 4.98727f,0.111944f,4.98974f,-0.0222727f,0.987364f,5.59934e-06f,
4.98698f,0.223989f,4.99688f,-0.0444735f,0.987444f,6.04501e-06f, 4.98633f,0.336239f,5.00867f,-0.0666345f,0.987615f,6.79391e-06f,
4.9857f,0.448842f,5.02551f,-0.0888808f,0.987768f,7.68475e-06f, 4.98514f,0.561935f,5.04754f,-0.111238f,0.987889f,8.75194e-06f,
4.98464f,0.675651f,5.07486f,-0.133726f,0.987977f,1.00457e-05f, 4.98421f,0.790132f,5.10761f,-0.156362f,0.988031f,1.1617e-05f,
4.98384f,0.905514f,5.14592f,-0.179164f,0.988052f,1.35144e-05f, 4.98352f,1.02194f,5.18998f,-0.202151f,0.988037f,1.57804e-05f,
4.98322f,1.13957f,5.23997f,-0.22534f,0.987985f,1.8449e-05f, 4.98296f,1.25854f,5.29614f,-0.248752f,0.98789f,2.15379e-05f,
4.98272f,1.37902f,5.35875f,-0.272403f,0.987749f,2.50396e-05f, 4.98234f,1.50114f,5.42799f,-0.296382f,0.987617f,2.95987e-05f,
4.98182f,1.62507f,5.50419f,-0.320737f,0.987511f,3.57695e-05f, 4.98117f,1.75098f,5.58777f,-0.345467f,0.987403f,4.36918e-05f,
4.9804f,1.87907f,5.6792f,-0.370593f,0.987283f,5.37391e-05f, 4.97948f,2.00954f,5.77898f,-0.396145f,0.987145f,6.64014e-05f,
4.97836f,2.14257f,5.88767f,-0.422148f,0.986981f,8.22744e-05f, 4.97704f,2.2784f,6.00589f,-0.448635f,0.986782f,0.000102084f,
4.97547f,2.41724f,6.13426f,-0.475636f,0.98654f,0.00012669f, 4.97362f,2.55933f,6.27341f,-0.503263f,0.986312f,0.000158897f,
4.97152f,2.70498f,6.42413f,-0.531553f,0.986085f,0.000200729f, 4.96921f,2.8545f,6.58737f,-0.560535f,0.985839f,0.000254369f,
4.96666f,3.00823f,6.76424f,-0.590249f,0.985562f,0.000322735f, 4.96393f,3.16656f,6.95587f,-0.62074f,0.98524f,0.000409339f,
4.96049f,3.32958f,7.16381f,-0.652106f,0.984899f,0.000520227f, 4.95631f,3.49767f,7.3896f,-0.684441f,0.984554f,0.000662825f,
4.95166f,3.67146f,7.63482f,-0.717783f,0.984174f,0.000844036f, 4.94646f,3.8514f,7.90148f,-0.752191f,0.983739f,0.00107273f,
4.94051f,4.03791f,8.19186f,-0.7878f,0.983283f,0.00136286f, 4.93359f,4.23143f,8.50856f,-0.824702f,0.982795f,0.00172928f,
4.92576f,4.43267f,8.85447f,-0.86296f,0.982242f,0.00218801f, 4.91685f,4.64222f,9.23295f,-0.902739f,0.981654f,0.00276317f,
4.90675f,4.86082f,9.64792f,-0.944141f,0.981008f,0.00347992f, 4.89526f,5.08923f,10.1039f,-0.987291f,0.98029f,0.00436871f,
4.88221f,5.32826f,10.6055f,-1.03232f,0.979541f,0.00546842f, 4.86797f,5.57951f,11.1583f,-1.07936f,0.978738f,0.00682114f,
4.84917f,5.84038f,11.7716f,-1.12863f,0.977856f,0.00847888f, 4.8297f,6.11681f,12.4518f,-1.18035f,0.976882f,0.0105029f,
4.80669f,6.40692f,13.2104f,-1.2347f,0.975783f,0.0129607f, 4.78181f,6.7148f,14.0577f,-1.29195f,0.974545f,0.0159337f,
4.75404f,7.0413f,15.0081f,-1.35231f,0.973142f,0.0195127f, 4.72094f,7.38521f,16.0797f,-1.41606f,0.971547f,0.0238014f,
4.68304f,7.74987f,17.2927f,-1.48347f,0.969729f,0.0289163f, 4.64226f,8.14166f,18.6683f,-1.55479f,0.967642f,0.0349843f,
4.59488f,8.55802f,20.238f,-1.6303f,0.965248f,0.0421472f, 4.54128f,9.0036f,22.0391f,-1.71022f,0.962482f,0.0505535f,
4.48218f,9.48475f,24.1093f,-1.79474f,0.959286f,0.0603614f, 4.40646f,9.98286f,26.5156f,-1.88391f,0.955573f,0.0717265f,
4.33974f,10.5611f,29.2761f,-1.97761f,0.951257f,0.0848013f, 4.24238f,11.1332f,32.5263f,-2.07545f,0.946231f,0.0997166f,
4.14287f,11.7732f,36.2917f,-2.17657f,0.94039f,0.116571f, 4.02686f,12.449f,40.6939f,-2.27941f,0.933627f,0.135403f,
3.88607f,13.1338f,45.8496f,-2.38142f,0.925867f,0.15617f, 3.79607f,14.0771f,51.4167f,-2.47857f,0.917121f,0.178717f,
3.65254f,14.9265f,57.8905f,-2.56488f,0.907571f,0.202752f, 3.38287f,15.3089f,65.7639f,-2.63193f,0.897767f,0.227857f,
3.18971f,15.9564f,73.3808f,-2.66872f,0.888911f,0.253549f, 2.93261f,16.1589f,81.2627f,-2.66233f,0.883322f,0.279435f,
2.56755f,15.4818f,89.3694f,-2.60051f,0.885085f,0.305543f, 2.29666f,14.6789f,94.4286f,-2.47621f,0.900394f,0.33262f,
1.87881f,12.7645f,100.507f,-2.29375f,0.93638f,0.361924f, 1.56291f,10.9748f,104.985f,-2.07888f,0.997646f,0.39294f,
4.52545f,4.94503e-07f,4.52544f,-4.01966e-18f,0.985766f,9.01426e-06f, 4.52549f,0.101549f,4.52773f,-0.0221003f,0.985747f,9.0919e-06f,
4.5256f,0.203214f,4.53457f,-0.044216f,0.985691f,9.31917e-06f, 4.5258f,0.305118f,4.546f,-0.0663623f,0.985595f,9.67816e-06f,
4.52607f,0.407376f,4.56208f,-0.0885546f,0.985457f,1.01359e-05f, 4.52641f,0.510111f,4.58287f,-0.11081f,0.985275f,1.06462e-05f,
4.52656f,0.613424f,4.6082f,-0.13326f,0.985154f,1.16639e-05f, 4.5266f,0.717432f,4.63827f,-0.155888f,0.985062f,1.31974e-05f,
4.52659f,0.822262f,4.67328f,-0.178688f,0.984972f,1.52328e-05f, 4.52656f,0.928039f,4.71342f,-0.201673f,0.984875f,1.78243e-05f,
4.5265f,1.0349f,4.75887f,-0.224861f,0.984763f,2.10484e-05f, 4.5264f,1.14297f,4.80987f,-0.248273f,0.984631f,2.49996e-05f,
4.52615f,1.25236f,4.86651f,-0.271899f,0.984501f,2.97912e-05f, 4.52558f,1.36317f,4.92891f,-0.295724f,0.984401f,3.5543e-05f,
4.52485f,1.47557f,4.99756f,-0.319821f,0.98428f,4.23523e-05f, 4.52395f,1.58974f,5.07281f,-0.344283f,0.984168f,5.10193e-05f,
4.52283f,1.70583f,5.15503f,-0.369166f,0.984074f,6.23499e-05f, 4.52155f,1.82403f,5.24475f,-0.394475f,0.983969f,7.67064e-05f,
4.52007f,1.94451f,5.34245f,-0.420235f,0.983837f,9.47344e-05f, 4.51839f,2.0675f,5.44871f,-0.446474f,0.983671f,0.000117262f,
4.51647f,2.19317f,5.56409f,-0.473221f,0.983461f,0.000145277f, 4.51429f,2.32175f,5.68917f,-0.500547f,0.983229f,0.000180869f,
4.51193f,2.45352f,5.8246f,-0.528527f,0.983f,0.000226882f, 4.50951f,2.58883f,5.97116f,-0.557174f,0.982742f,0.000285378f,
4.50658f,2.72775f,6.12998f,-0.586524f,0.982443f,0.000359261f, 4.503f,2.8705f,6.30217f,-0.616624f,0.982094f,0.000452346f,
4.49906f,3.01756f,6.48879f,-0.647593f,0.981741f,0.000571614f, 4.49469f,3.1693f,6.69122f,-0.67946f,0.981354f,0.000722695f,
4.48979f,3.32606f,6.91093f,-0.712271f,0.98091f,0.000912669f, 4.48405f,3.48803f,7.14977f,-0.746132f,0.980433f,0.00115256f,
4.47766f,3.65587f,7.40961f,-0.781128f,0.979919f,0.00145464f, 4.47041f,3.82992f,7.69268f,-0.817306f,0.979337f,0.00183182f,
4.46221f,4.0107f,8.00156f,-0.854815f,0.978718f,0.00230424f, 4.45298f,4.19879f,8.3391f,-0.893712f,0.978026f,0.00289103f,
4.44278f,4.395f,8.70863f,-0.934138f,0.977275f,0.00361923f, 4.43191f,4.60045f,9.11369f,-0.976188f,0.976438f,0.00451761f,
4.41819f,4.81379f,9.55977f,-1.02002f,0.975526f,0.00562369f, 4.40176f,5.03599f,10.0523f,-1.06574f,0.974509f,0.00697768f,
4.38419f,5.26986f,10.5961f,-1.11353f,0.973385f,0.00862974f, 4.36448f,5.51555f,11.1991f,-1.16354f,0.972139f,0.0106371f,
4.34345f,5.77557f,11.8683f,-1.21593f,0.970749f,0.0130648f, 4.31795f,6.04734f,12.6151f,-1.2709f,0.969195f,0.0159881f,
4.28891f,6.33367f,13.4512f,-1.32861f,0.967454f,0.0194923f, 4.25845f,6.6398f,14.3882f,-1.38927f,0.965497f,0.0236733f,
4.22468f,6.96545f,15.4424f,-1.45306f,0.963292f,0.0286379f, 4.18259f,7.30476f,16.6393f,-1.52014f,0.960795f,0.0345021f,
4.13548f,7.66559f,17.9971f,-1.59067f,0.957962f,0.0413925f, 4.09549f,8.07488f,19.5246f,-1.66472f,0.954739f,0.0494419f,
4.02584f,8.46459f,21.304f,-1.74231f,0.951063f,0.0587872f, 3.98294f,8.95428f,23.2847f,-1.8233f,0.946863f,0.0695631f,
3.88901f,9.37911f,25.6439f,-1.90734f,0.94206f,0.081894f, 3.81002f,9.8894f,28.3021f,-1.9938f,0.936576f,0.0958856f,
3.74409f,10.4949f,31.2856f,-2.08156f,0.930336f,0.111607f, 3.61277f,10.9833f,34.8846f,-2.16889f,0.92329f,0.129076f,
3.49618f,11.5661f,38.8503f,-2.25313f,0.915445f,0.14824f, 3.4321f,12.3825f,43.034f,-2.33048f,0.906921f,0.168953f,
3.28039f,12.9522f,47.9874f,-2.39561f,0.898046f,0.190975f, 3.0345f,13.1487f,53.7369f,-2.4413f,0.889655f,0.213982f,
2.86506f,13.5852f,59.0402f,-2.45929f,0.883075f,0.237637f, 2.66827f,13.7222f,64.2578f,-2.44057f,0.880582f,0.26174f,
2.34701f,13.0379f,69.8628f,-2.37713f,0.885828f,0.286405f, 2.10126f,12.3181f,73.4325f,-2.26554f,0.903917f,0.312258f,
1.80365f,11.008f,76.8603f,-2.11007f,0.940079f,0.340099f, 1.53154f,9.59036f,80.1619f,-1.93028f,0.99779f,0.36926f,
4.13057f,-1.19925e-07f,4.13056f,-2.11338e-17f,0.982009f,9.25071e-06f, 4.13059f,0.0926761f,4.13262f,-0.022113f,0.981997f,9.37778e-06f,
4.13066f,0.185456f,4.13881f,-0.044244f,0.981959f,9.76e-06f, 4.13078f,0.27845f,4.14915f,-0.0664106f,0.981896f,1.04001e-05f,
4.13075f,0.371736f,4.16348f,-0.0885657f,0.981866f,1.13753e-05f, 4.13052f,0.465404f,4.18183f,-0.110724f,0.981878f,1.26663e-05f,
4.13028f,0.559585f,4.20447f,-0.13297f,0.981865f,1.41855e-05f, 4.13008f,0.654391f,4.23155f,-0.155333f,0.98181f,1.59158e-05f,
4.12988f,0.749942f,4.26317f,-0.177849f,0.981718f,1.79244e-05f, 4.12957f,0.846336f,4.29933f,-0.200618f,0.98166f,2.07534e-05f,
4.1292f,0.943696f,4.34028f,-0.223619f,0.981599f,2.43898e-05f, 4.12878f,1.04214f,4.38624f,-0.246859f,0.981519f,2.89209e-05f,
4.12834f,1.14181f,4.43743f,-0.270353f,0.981412f,3.4487e-05f, 4.12784f,1.24282f,4.49411f,-0.294118f,0.981271f,4.12535e-05f,
4.12728f,1.34532f,4.55655f,-0.318174f,0.98109f,4.9412e-05f, 4.12664f,1.44945f,4.62507f,-0.342546f,0.980868f,5.92385e-05f,
4.12581f,1.55533f,4.69992f,-0.367329f,0.980659f,7.19873e-05f, 4.1248f,1.66312f,4.78155f,-0.392528f,0.980441f,8.81323e-05f,
4.1236f,1.773f,4.8704f,-0.418157f,0.980197f,0.000108315f, 4.12219f,1.88512f,4.96696f,-0.444241f,0.979917f,0.000133398f,
4.12057f,1.99969f,5.07174f,-0.470806f,0.979591f,0.000164425f, 4.11882f,2.11695f,5.18514f,-0.497948f,0.979264f,0.00020413f,
4.11674f,2.23704f,5.30784f,-0.52569f,0.978919f,0.000254486f, 4.11415f,2.36009f,5.44073f,-0.554056f,0.978535f,0.00031774f,
4.1115f,2.48661f,5.58445f,-0.583072f,0.978108f,0.000396858f, 4.10768f,2.61622f,5.73988f,-0.612792f,0.977717f,0.000497486f,
4.10359f,2.74975f,5.90799f,-0.643277f,0.977313f,0.000624284f, 4.09877f,2.88722f,6.09015f,-0.674575f,0.97686f,0.000782864f,
4.0934f,3.02912f,6.28768f,-0.706802f,0.976386f,0.000982777f, 4.08736f,3.17573f,6.50212f,-0.740005f,0.975864f,0.00123299f,
4.08059f,3.32745f,6.73513f,-0.774249f,0.975282f,0.00154492f, 4.07683f,3.4879f,6.98716f,-0.809643f,0.974653f,0.00193425f,
4.06477f,3.64805f,7.26496f,-0.846238f,0.973949f,0.00241672f, 4.05612f,3.81843f,7.56615f,-0.884157f,0.973182f,0.00301457f,
4.04448f,3.99399f,7.89646f,-0.92347f,0.972328f,0.00375106f, 4.0314f,4.17676f,8.25832f,-0.964293f,0.971385f,0.00465605f,
4.01743f,4.36809f,8.65563f,-1.00674f,0.970347f,0.00576411f, 4.00115f,4.56731f,9.09302f,-1.05092f,0.969193f,0.00711458f,
3.98441f,4.77746f,9.57447f,-1.09695f,0.967912f,0.00875426f, 3.9667f,4.99921f,10.1059f,-1.14497f,0.966488f,0.010737f,
3.94332f,5.22774f,10.6972f,-1.19511f,0.964904f,0.0131245f, 3.91713f,5.46774f,11.3548f,-1.24751f,0.963136f,0.0159869f,
3.89047f,5.72397f,12.0858f,-1.30228f,0.961159f,0.0194027f, 3.86326f,5.99861f,12.9012f,-1.35956f,0.958943f,0.0234601f,
3.8215f,6.27135f,13.8255f,-1.41947f,0.956458f,0.0282566f, 3.78602f,6.57714f,14.8553f,-1.48207f,0.953662f,0.0338971f,
3.74075f,6.89195f,16.0199f,-1.54739f,0.950507f,0.0404933f, 3.69172f,7.22822f,17.3387f,-1.61543f,0.946951f,0.0481635f,
3.68308f,7.6797f,18.7514f,-1.68603f,0.942932f,0.057025f, 3.57752f,7.96668f,20.5216f,-1.75891f,0.938396f,0.0671927f,
3.50809f,8.36447f,22.4477f,-1.83357f,0.933286f,0.0787703f, 3.44605f,8.82132f,24.5924f,-1.9092f,0.927547f,0.0918397f,
3.34624f,9.22664f,27.1052f,-1.98456f,0.921151f,0.106452f, 3.28016f,9.76452f,29.7862f,-2.05785f,0.9141f,0.122612f,
3.14947f,10.1582f,32.9865f,-2.12653f,0.906484f,0.140265f, 3.02123f,10.5778f,36.4538f,-2.18713f,0.898521f,0.159288f,
2.88504f,10.9722f,40.1728f,-2.23512f,0.890663f,0.179493f, 2.81523f,11.5955f,43.6173f,-2.26489f,0.883729f,0.200645f,
2.54479f,11.3829f,48.1826f,-2.27006f,0.879109f,0.222528f, 2.35928f,11.3552f,51.9697f,-2.24419f,0.878995f,0.245038f,
2.15445f,11.0222f,55.1997f,-2.18211f,0.886824f,0.268339f, 1.8949f,10.1768f,58.1219f,-2.08248f,0.907131f,0.292948f,
1.66742f,9.23321f,60.4047f,-1.94939f,0.943237f,0.319388f, 1.43902f,8.14321f,62.8253f,-1.79751f,0.997905f,0.346904f,
3.78635f,6.93568e-07f,3.78636f,-4.59095e-19f,0.977872f,1.03025e-05f, 3.78613f,0.0848891f,3.78798f,-0.021828f,0.977954f,1.05668e-05f,
3.78574f,0.169868f,3.79317f,-0.043766f,0.978077f,1.11908e-05f, 3.78542f,0.255024f,3.80217f,-0.0657597f,0.978161f,1.20489e-05f,
3.78516f,0.340457f,3.81501f,-0.0878235f,0.978203f,1.31773e-05f, 3.78496f,0.426265f,3.83175f,-0.109973f,0.978202f,1.46127e-05f,
3.7848f,0.512548f,3.85246f,-0.132223f,0.978158f,1.63886e-05f, 3.78469f,0.59941f,3.87723f,-0.154589f,0.978069f,1.85331e-05f,
3.78462f,0.686954f,3.90616f,-0.177088f,0.977932f,2.10673e-05f, 3.78456f,0.775286f,3.93937f,-0.199747f,0.977755f,2.40734e-05f,
3.78438f,0.864499f,3.97689f,-0.222657f,0.977602f,2.81163e-05f, 3.78415f,0.954705f,4.01894f,-0.245804f,0.97744f,3.3226e-05f,
3.78385f,1.04602f,4.06575f,-0.269195f,0.977256f,3.95301e-05f, 3.78348f,1.13856f,4.11751f,-0.292842f,0.977041f,4.72086e-05f,
3.78283f,1.23237f,4.17429f,-0.316702f,0.976843f,5.64956e-05f, 3.78197f,1.32761f,4.23642f,-0.340843f,0.976636f,6.77817e-05f,
3.78087f,1.4244f,4.30425f,-0.365366f,0.976448f,8.22356e-05f, 3.77958f,1.5229f,4.37817f,-0.390277f,0.976246f,0.000100295f,
3.77812f,1.62328f,4.45859f,-0.415593f,0.97601f,0.000122633f, 3.77652f,1.7257f,4.54593f,-0.441339f,0.975728f,0.000150116f,
3.77492f,1.8304f,4.64056f,-0.467586f,0.975426f,0.000184695f, 3.77282f,1.93736f,4.74304f,-0.494376f,0.975106f,0.000228352f,
3.77011f,2.04671f,4.85411f,-0.521719f,0.974742f,0.000282774f, 3.76714f,2.1588f,4.97425f,-0.549651f,0.974328f,0.000350524f,
3.76403f,2.27397f,5.10417f,-0.578261f,0.973895f,0.000436147f, 3.76057f,2.39234f,5.24471f,-0.60756f,0.973414f,0.00054317f,
3.75629f,2.51389f,5.39692f,-0.637593f,0.972877f,0.000676575f, 3.75174f,2.63927f,5.56167f,-0.668448f,0.972308f,0.000844022f,
3.74671f,2.76864f,5.74015f,-0.70014f,0.971673f,0.00105211f, 3.74115f,2.90234f,5.93366f,-0.732767f,0.970993f,0.00131173f,
3.73499f,3.0407f,6.14363f,-0.766364f,0.970242f,0.00163353f, 3.72797f,3.18394f,6.37209f,-0.801021f,0.96943f,0.00203239f,
3.71885f,3.33139f,6.62101f,-0.836792f,0.968538f,0.00252425f, 3.70849f,3.48419f,6.89241f,-0.873773f,0.96757f,0.00313011f,
3.69811f,3.64405f,7.18839f,-0.91203f,0.966508f,0.00387278f, 3.68543f,3.80937f,7.51252f,-0.951655f,0.965345f,0.00478048f,
3.67226f,3.98264f,7.86723f,-0.992741f,0.964072f,0.00588595f, 3.6585f,4.1646f,8.25593f,-1.03538f,0.962675f,0.00722732f,
3.64036f,4.35172f,8.68456f,-1.07967f,0.961138f,0.00884807f, 3.62014f,4.54728f,9.15755f,-1.12569f,0.959443f,0.0107986f,
3.60086f,4.75624f,9.67826f,-1.17356f,0.957573f,0.0131366f, 3.57693f,4.97258f,10.2565f,-1.2233f,0.955541f,0.0159271f,
3.54855f,5.19729f,10.8988f,-1.27502f,0.953302f,0.0192419f, 3.51604f,5.4318f,11.615f,-1.32881f,0.950824f,0.0231619f,
3.4892f,5.69316f,12.4044f,-1.3847f,0.948067f,0.0277741f, 3.4501f,5.95455f,13.2939f,-1.44271f,0.944996f,0.0331738f,
3.40813f,6.23233f,14.2934f,-1.50279f,0.941567f,0.0394596f, 3.35674f,6.51598f,15.4188f,-1.56481f,0.937741f,0.0467347f,
3.31067f,6.83528f,16.6668f,-1.62852f,0.933469f,0.0551003f, 3.27843f,7.21236f,18.0381f,-1.69354f,0.92871f,0.0646532f,
3.19805f,7.51856f,19.6473f,-1.75924f,0.92343f,0.075479f, 3.15601f,7.94263f,21.3509f,-1.82474f,0.917611f,0.0876433f,
3.04741f,8.23426f,23.4006f,-1.88876f,0.911265f,0.101185f, 2.98586f,8.67316f,25.5297f,-1.94956f,0.904455f,0.116101f,
2.86172f,8.96192f,28.0275f,-2.0048f,0.897343f,0.132348f, 2.80911f,9.47205f,30.4081f,-2.05144f,0.89023f,0.149825f,
2.66484f,9.69212f,33.2632f,-2.08573f,0.883652f,0.168396f, 2.51387f,9.84431f,36.2072f,-2.10327f,0.878488f,0.187898f,
2.3517f,9.87578f,39.0575f,-2.09932f,0.876114f,0.208201f, 2.17559f,9.7329f,41.7887f,-2.06946f,0.878568f,0.22929f,
1.98513f,9.35082f,44.0611f,-2.01061f,0.888608f,0.25133f, 1.78274f,8.73589f,46.089f,-1.92211f,0.909962f,0.274688f,
1.57443f,7.91323f,47.8102f,-1.80748f,0.945868f,0.299771f, 1.36414f,6.99728f,49.6929f,-1.67813f,0.997993f,0.32584f,
3.48317f,8.42155e-07f,3.48317f,-2.79295e-18f,0.973936f,1.28874e-05f, 3.48322f,0.0780556f,3.48491f,-0.021723f,0.973906f,1.29553e-05f,
3.4833f,0.156201f,3.4901f,-0.0434667f,0.973824f,1.31705e-05f, 3.48323f,0.234531f,3.49855f,-0.0653645f,0.973804f,1.38992e-05f,
3.48312f,0.313119f,3.51043f,-0.0873527f,0.973777f,1.50519e-05f, 3.48303f,0.392051f,3.52586f,-0.109425f,0.973721f,1.66102e-05f,
3.48297f,0.471421f,3.54489f,-0.131594f,0.973627f,1.85976e-05f, 3.48295f,0.551323f,3.56763f,-0.153872f,0.973491f,2.10448e-05f,
3.48295f,0.631849f,3.59417f,-0.176276f,0.97331f,2.3983e-05f, 3.48279f,0.713053f,3.62446f,-0.19877f,0.973137f,2.75145e-05f,
3.4824f,0.79502f,3.65854f,-0.221461f,0.973019f,3.2162e-05f, 3.48191f,0.877875f,3.69671f,-0.244367f,0.972899f,3.79679e-05f,
3.48133f,0.961716f,3.73918f,-0.267503f,0.972753f,4.50608e-05f, 3.48068f,1.04666f,3.78617f,-0.290885f,0.97257f,5.36333e-05f,
3.47995f,1.13282f,3.83791f,-0.314532f,0.972339f,6.39182e-05f, 3.47908f,1.22029f,3.8946f,-0.338525f,0.972104f,7.69058e-05f,
3.47806f,1.30921f,3.95653f,-0.36287f,0.971848f,9.30809e-05f, 3.47694f,1.39971f,4.02404f,-0.387575f,0.971552f,0.000112965f,
3.47577f,1.49196f,4.09743f,-0.412657f,0.971205f,0.000137255f, 3.47474f,1.58618f,4.177f,-0.438191f,0.970843f,0.000167748f,
3.47254f,1.682f,4.26336f,-0.464194f,0.97045f,0.000205792f, 3.47077f,1.78025f,4.35677f,-0.490677f,0.970007f,0.000252803f,
3.4682f,1.88055f,4.45794f,-0.517692f,0.969526f,0.000311301f, 3.46575f,1.98354f,4.56717f,-0.545293f,0.969014f,0.000384533f,
3.46262f,2.08903f,4.68534f,-0.573486f,0.968446f,0.00047524f, 3.45925f,2.19747f,4.81289f,-0.602324f,0.967856f,0.000588466f,
3.45536f,2.30892f,4.95056f,-0.63181f,0.967251f,0.000729174f, 3.45031f,2.42322f,5.09972f,-0.662018f,0.966602f,0.000903643f,
3.44492f,2.54116f,5.26094f,-0.69302f,0.965909f,0.00112022f, 3.43931f,2.66315f,5.43539f,-0.724858f,0.96515f,0.00138777f,
3.43415f,2.79013f,5.62392f,-0.757605f,0.964329f,0.00171819f, 3.42576f,2.91947f,5.82942f,-0.791317f,0.963434f,0.00212501f,
3.41519f,3.05221f,6.05348f,-0.826049f,0.962451f,0.00262411f, 3.40488f,3.19087f,6.29673f,-0.861878f,0.96138f,0.00323524f,
3.39449f,3.33574f,6.5615f,-0.898867f,0.960208f,0.00398089f, 3.3837f,3.48716f,6.84983f,-0.937082f,0.958923f,0.00488741f,
3.37264f,3.64597f,7.16416f,-0.976596f,0.957512f,0.00598579f, 3.35652f,3.80746f,7.51022f,-1.01748f,0.955964f,0.00731191f,
3.33671f,3.97342f,7.89229f,-1.05981f,0.954265f,0.00890691f, 3.31875f,4.15114f,8.30897f,-1.10364f,0.952392f,0.0108174f,
3.30092f,4.33988f,8.76702f,-1.14903f,0.95033f,0.0130966f, 3.27637f,4.53139f,9.27472f,-1.19606f,0.948061f,0.0158047f,
3.24932f,4.73187f,9.83606f,-1.24473f,0.945553f,0.0190071f, 3.22617f,4.95219f,10.4505f,-1.29507f,0.942785f,0.0227769f,
3.19129f,5.16977f,11.1441f,-1.34706f,0.939726f,0.027193f, 3.1567f,5.40403f,11.9095f,-1.40064f,0.936345f,0.032339f,
3.11418f,5.64224f,12.7631f,-1.45569f,0.932611f,0.0383029f, 3.07283f,5.90156f,13.712f,-1.51199f,0.928491f,0.0451741f,
3.03779f,6.19468f,14.7421f,-1.56923f,0.923956f,0.0530398f, 2.97886f,6.46159f,15.9258f,-1.62693f,0.918983f,0.0619825f,
2.94235f,6.79987f,17.1829f,-1.68442f,0.913561f,0.0720721f, 2.88055f,7.10627f,18.6086f,-1.74079f,0.907707f,0.083364f,
2.78299f,7.34465f,20.2579f,-1.7948f,0.901474f,0.0958868f, 2.71684f,7.67521f,21.9549f,-1.8448f,0.894976f,0.10964f,
2.6123f,7.91139f,23.8693f,-1.88874f,0.888436f,0.124589f, 2.55649f,8.2871f,25.7199f,-1.92403f,0.882211f,0.140661f,
2.48826f,8.61914f,27.5995f,-1.94752f,0.87694f,0.15776f, 2.3376f,8.64922f,29.794f,-1.9558f,0.873625f,0.175786f,
2.17954f,8.57855f,31.9185f,-1.94563f,0.873491f,0.19468f, 2.01212f,8.36453f,33.938f,-1.91396f,0.878338f,0.214466f,
1.91911f,8.2919f,35.061f,-1.85888f,0.890479f,0.235301f, 1.71739f,7.65577f,36.1071f,-1.7805f,0.912484f,0.257461f,
1.47454f,6.75556f,38.368f,-1.68119f,0.948031f,0.281256f, 1.33835f,6.20029f,39.5082f,-1.57014f,0.99806f,0.306025f,
3.21736f,5.8077e-07f,3.21737f,-1.75639e-17f,0.96892f,1.46664e-05f, 3.2174f,0.0720516f,3.21896f,-0.0216304f,0.96889f,1.47723e-05f,
3.21749f,0.144186f,3.22374f,-0.0432733f,0.968801f,1.50841e-05f, 3.21752f,0.21649f,3.23159f,-0.0650188f,0.968722f,1.58154e-05f,
3.21748f,0.289037f,3.24255f,-0.0868806f,0.968659f,1.70819e-05f, 3.21744f,0.361902f,3.25675f,-0.108825f,0.968566f,1.88097e-05f,
3.21743f,0.435167f,3.27424f,-0.130858f,0.968435f,2.10178e-05f, 3.21726f,0.508879f,3.29498f,-0.152921f,0.968322f,2.3784e-05f,
3.21703f,0.583134f,3.31909f,-0.175073f,0.968188f,2.70959e-05f, 3.21671f,0.658026f,3.34668f,-0.1974f,0.96805f,3.12541e-05f,
3.2163f,0.733642f,3.37789f,-0.219939f,0.967911f,3.65408e-05f, 3.21584f,0.810076f,3.41289f,-0.242682f,0.96774f,4.30086e-05f,
3.21532f,0.88742f,3.45186f,-0.26564f,0.967526f,5.08111e-05f, 3.21474f,0.96577f,3.49496f,-0.288829f,0.967262f,6.01654e-05f,
3.21404f,1.04523f,3.54235f,-0.312323f,0.966991f,7.19257e-05f, 3.21324f,1.1259f,3.59428f,-0.336122f,0.96669f,8.64302e-05f,
3.21239f,1.2079f,3.65098f,-0.360231f,0.966344f,0.000104112f, 3.21156f,1.2914f,3.71272f,-0.384677f,0.965952f,0.000125689f,
3.21049f,1.37642f,3.77972f,-0.409523f,0.965545f,0.000152676f, 3.20888f,1.46296f,3.85227f,-0.434718f,0.965135f,0.000185916f,
3.20699f,1.55124f,3.93078f,-0.460305f,0.964695f,0.00022669f, 3.20507f,1.64153f,4.01559f,-0.486368f,0.964242f,0.000277568f,
3.20311f,1.73401f,4.10714f,-0.512916f,0.963743f,0.000340353f, 3.19959f,1.82814f,4.20666f,-0.539991f,0.963197f,0.000417948f,
3.19588f,1.92471f,4.31408f,-0.567646f,0.96261f,0.000514269f, 3.19237f,2.02413f,4.42978f,-0.595897f,0.961961f,0.000633024f,
3.18861f,2.12643f,4.55465f,-0.62481f,0.961265f,0.000780197f, 3.18389f,2.23139f,4.68973f,-0.654402f,0.960497f,0.000961423f,
3.17997f,2.34043f,4.83527f,-0.684738f,0.95967f,0.00118509f, 3.17367f,2.45159f,4.99301f,-0.715849f,0.958765f,0.00145988f,
3.16589f,2.56566f,5.16429f,-0.747786f,0.957781f,0.00179708f, 3.15911f,2.68494f,5.34947f,-0.780607f,0.956716f,0.00221017f,
3.15009f,2.80712f,5.55077f,-0.814349f,0.955554f,0.00271425f, 3.14183f,2.93519f,5.76877f,-0.84907f,0.954289f,0.00332789f,
3.13367f,3.06915f,6.00498f,-0.884823f,0.952914f,0.00407273f, 3.12033f,3.20412f,6.26397f,-0.921661f,0.951417f,0.00497387f,
3.10522f,3.34369f,6.54732f,-0.959632f,0.949785f,0.0060603f, 3.09113f,3.4915f,6.85601f,-0.998791f,0.948007f,0.00736573f,
3.07615f,3.64614f,7.19215f,-1.03918f,0.946067f,0.00892832f, 3.0694f,3.81986f,7.55235f,-1.08084f,0.943947f,0.0107912f,
3.03721f,3.97073f,7.96521f,-1.12376f,0.94165f,0.0130035f, 3.01851f,4.14881f,8.40668f,-1.16796f,0.939161f,0.0156197f,
2.99643f,4.3335f,8.89392f,-1.21345f,0.936446f,0.0187f, 2.98117f,4.54072f,9.41708f,-1.26021f,0.933476f,0.0223095f,
2.93851f,4.71885f,10.0261f,-1.30817f,0.930225f,0.0265189f, 2.90293f,4.92054f,10.6793f,-1.35724f,0.926668f,0.0314029f,
2.86711f,5.13619f,11.4044f,-1.40723f,0.922782f,0.0370383f, 2.87368f,5.44571f,12.1275f,-1.45788f,0.918543f,0.0435029f,
2.78329f,5.59203f,13.0814f,-1.50882f,0.91394f,0.050872f, 2.73847f,5.83848f,14.0426f,-1.55954f,0.908968f,0.0592157f,
2.68845f,6.09101f,15.0938f,-1.60937f,0.903644f,0.068594f, 2.64185f,6.36735f,16.2344f,-1.65739f,0.898016f,0.0790526f,
2.60741f,6.6889f,17.4046f,-1.70246f,0.892174f,0.0906174f, 2.48971f,6.81337f,18.882f,-1.7431f,0.886278f,0.103291f,
2.43403f,7.094f,20.2591f,-1.77753f,0.880597f,0.117052f, 2.31821f,7.19916f,21.8582f,-1.80361f,0.875533f,0.131853f,
2.2609f,7.41293f,23.3268f,-1.81893f,0.871693f,0.147637f, 2.14408f,7.49172f,24.8284f,-1.82089f,0.869949f,0.164346f,
2.02423f,7.45753f,26.3279f,-1.80699f,0.871519f,0.181962f, 1.86607f,7.20682f,27.8288f,-1.77503f,0.878129f,0.200534f,
1.77014f,7.06629f,28.6973f,-1.72397f,0.892098f,0.220226f, 1.60282f,6.57877f,29.8992f,-1.65432f,0.91503f,0.241247f,
1.43092f,5.97225f,30.9203f,-1.56797f,0.949764f,0.263822f, 1.27309f,5.37907f,31.9698f,-1.47194f,0.998107f,0.287416f,
2.98265f,-3.78763e-07f,2.98265f,-1.60601e-17f,0.963091f,1.63917e-05f, 2.98268f,0.0667299f,2.98411f,-0.0214734f,0.963059f,1.65121e-05f,
2.98275f,0.133537f,2.9885f,-0.0429709f,0.962973f,1.68986e-05f, 2.9827f,0.200504f,2.99565f,-0.0646031f,0.962926f,1.78571e-05f,
2.98264f,0.267688f,3.00572f,-0.0863084f,0.962853f,1.92947e-05f, 2.98262f,0.335165f,3.01878f,-0.108084f,0.962735f,2.12039e-05f,
2.98252f,0.40299f,3.03479f,-0.129892f,0.962609f,2.36449e-05f, 2.98232f,0.471226f,3.05382f,-0.151746f,0.962472f,2.66302e-05f,
2.98205f,0.539967f,3.07594f,-0.173748f,0.962332f,3.04162e-05f, 2.9817f,0.609296f,3.10127f,-0.19593f,0.962183f,3.52149e-05f,
2.98131f,0.679288f,3.12995f,-0.218283f,0.961996f,4.10647e-05f, 2.98088f,0.750029f,3.16213f,-0.240815f,0.96176f,4.80897e-05f,
2.98039f,0.821605f,3.19793f,-0.26356f,0.961484f,5.66137e-05f, 2.97982f,0.894105f,3.23746f,-0.28657f,0.961194f,6.72618e-05f,
2.97919f,0.967621f,3.28094f,-0.309835f,0.960862f,8.02322e-05f, 2.97855f,1.04227f,3.32855f,-0.333361f,0.960477f,9.58812e-05f,
2.97786f,1.11813f,3.38031f,-0.35716f,0.96011f,0.000115266f, 2.97693f,1.19525f,3.43644f,-0.381266f,0.959728f,0.000139099f,
2.97565f,1.27369f,3.49743f,-0.405698f,0.959301f,0.000168089f, 2.97352f,1.35338f,3.56389f,-0.430522f,0.958848f,0.00020396f,
2.97163f,1.43485f,3.63567f,-0.455749f,0.958352f,0.000248061f, 2.96993f,1.51823f,3.71308f,-0.4814f,0.957801f,0.000302108f,
2.96686f,1.603f,3.79708f,-0.507532f,0.957213f,0.000368961f, 2.9643f,1.69016f,3.88751f,-0.534146f,0.95656f,0.000450908f,
2.96151f,1.77957f,3.98509f,-0.561303f,0.955861f,0.000552123f, 2.96586f,1.87578f,4.08791f,-0.589009f,0.955092f,0.000676242f,
2.95545f,1.96602f,4.20363f,-0.617321f,0.954266f,0.000829062f, 2.95285f,2.06398f,4.32548f,-0.646258f,0.953365f,0.00101631f,
2.94705f,2.16298f,4.4577f,-0.675867f,0.952392f,0.00124585f, 2.93994f,2.26438f,4.60099f,-0.706184f,0.951341f,0.00152663f,
2.9347f,2.37088f,4.75508f,-0.73724f,0.950202f,0.00186912f, 2.92682f,2.47924f,4.92216f,-0.769034f,0.948999f,0.00228607f,
2.9205f,2.59327f,5.10183f,-0.80163f,0.947716f,0.00279254f, 2.91286f,2.71091f,5.29717f,-0.835078f,0.946333f,0.00340597f,
2.90009f,2.82866f,5.51036f,-0.869419f,0.944836f,0.00414659f, 2.8861f,2.95035f,5.7425f,-0.904694f,0.943212f,0.00503806f,
2.87601f,3.08191f,5.99198f,-0.940943f,0.941451f,0.00610781f, 2.86365f,3.21753f,6.26349f,-0.978193f,0.939538f,0.00738684f,
2.84686f,3.35494f,6.56085f,-1.01647f,0.937457f,0.00891061f, 2.82893f,3.49822f,6.88534f,-1.05579f,0.93519f,0.0107188f,
2.81155f,3.65021f,7.24042f,-1.09615f,0.932726f,0.0128566f, 2.79853f,3.81698f,7.62087f,-1.13754f,0.930043f,0.0153731f,
2.79125f,4.00141f,8.02289f,-1.17992f,0.927125f,0.018323f, 2.74664f,4.14371f,8.51197f,-1.22323f,0.923953f,0.0217648f,
2.71229f,4.30919f,9.02787f,-1.26736f,0.920505f,0.025761f, 2.68511f,4.49675f,9.58117f,-1.31217f,0.916772f,0.0303783f,
2.67567f,4.72738f,10.1625f,-1.35742f,0.912735f,0.0356838f, 2.61038f,4.87284f,10.8701f,-1.40283f,0.908388f,0.0417453f,
2.60452f,5.13894f,11.5468f,-1.44801f,0.903736f,0.0486284f, 2.53234f,5.29088f,12.3885f,-1.49243f,0.898796f,0.0563938f,
2.54072f,5.61713f,13.1369f,-1.53542f,0.893607f,0.0650929f, 2.43311f,5.7098f,14.1772f,-1.57614f,0.888246f,0.0747661f,
2.37625f,5.91496f,15.1828f,-1.61353f,0.882835f,0.0854383f, 2.34446f,6.18465f,16.1552f,-1.64632f,0.877574f,0.0971194f,
2.22784f,6.23722f,17.3915f,-1.67293f,0.872774f,0.109797f, 2.17413f,6.43715f,18.4772f,-1.69152f,0.868949f,0.123447f,
2.11352f,6.60838f,19.5302f,-1.70036f,0.866646f,0.138039f, 2.02893f,6.68172f,20.4606f,-1.69754f,0.86669f,0.153557f,
1.88337f,6.48788f,21.8725f,-1.68125f,0.870178f,0.170014f, 1.80404f,6.42851f,22.6281f,-1.65009f,0.878488f,0.187475f,
1.65524f,6.10085f,23.646f,-1.60329f,0.893375f,0.206069f, 1.52175f,5.73264f,24.4736f,-1.54128f,0.917093f,0.226003f,
1.35947f,5.1943f,25.3223f,-1.46575f,0.951087f,0.247424f, 1.25474f,4.82009f,25.9266f,-1.38218f,0.998136f,0.269963f,
2.77453f,4.44299e-07f,2.77453f,-8.37458e-18f,0.956404f,1.80415e-05f, 2.77454f,0.0619871f,2.77586f,-0.0212704f,0.956379f,1.81861e-05f,
2.77441f,0.124062f,2.77971f,-0.0426704f,0.956396f,1.8899e-05f, 2.7743f,0.186265f,2.78624f,-0.0641176f,0.95637f,2.00498e-05f,
2.77423f,0.248667f,2.79549f,-0.0856136f,0.956287f,2.16349e-05f, 2.7742f,0.311336f,2.80754f,-0.107169f,0.956142f,2.36746e-05f,
2.77413f,0.374332f,2.82234f,-0.128774f,0.955964f,2.62434e-05f, 2.77389f,0.437705f,2.83981f,-0.150478f,0.955834f,2.96977e-05f,
2.77358f,0.501538f,2.86014f,-0.172305f,0.955684f,3.40089e-05f, 2.77324f,0.565904f,2.88346f,-0.194263f,0.955491f,3.92332e-05f,
2.77288f,0.63088f,2.90986f,-0.216369f,0.955245f,4.5493e-05f, 2.77246f,0.696549f,2.93942f,-0.238692f,0.954984f,5.3324e-05f,
2.772f,0.762985f,2.97229f,-0.26122f,0.954684f,6.28824e-05f, 2.77154f,0.830281f,3.00859f,-0.283957f,0.95433f,7.43849e-05f,
2.77084f,0.898457f,3.04856f,-0.306937f,0.953945f,8.84472e-05f, 2.77017f,0.967666f,3.09211f,-0.330144f,0.953568f,0.000105735f,
2.76921f,1.03789f,3.13947f,-0.353602f,0.953152f,0.000126647f, 2.76793f,1.10923f,3.191f,-0.377368f,0.952708f,0.000152293f,
2.7664f,1.18179f,3.247f,-0.401463f,0.952224f,0.000183696f, 2.76488f,1.25577f,3.30766f,-0.425899f,0.951685f,0.000221913f,
2.76547f,1.33212f,3.37267f,-0.450727f,0.951108f,0.000268949f, 2.76114f,1.40816f,3.44397f,-0.475945f,0.950468f,0.000326282f,
2.75933f,1.48706f,3.52036f,-0.501605f,0.949781f,0.000396756f, 2.75743f,1.56794f,3.60274f,-0.527711f,0.949028f,0.0004828f,
2.75516f,1.65086f,3.69155f,-0.554311f,0.948219f,0.000588383f, 2.75339f,1.73645f,3.78692f,-0.581415f,0.947337f,0.000717268f,
2.75218f,1.82504f,3.88908f,-0.609052f,0.946396f,0.00087491f, 2.74964f,1.91562f,3.99889f,-0.637217f,0.94541f,0.00106726f,
2.74069f,2.00457f,4.11978f,-0.665963f,0.944356f,0.00130154f, 2.73485f,2.09869f,4.24851f,-0.695329f,0.943222f,0.0015865f,
2.72808f,2.19538f,4.38848f,-0.725356f,0.942004f,0.00193257f, 2.72165f,2.29591f,4.5389f,-0.756069f,0.940688f,0.00235162f,
2.71642f,2.40143f,4.69951f,-0.787501f,0.939266f,0.00285787f, 2.70622f,2.50667f,4.87515f,-0.81968f,0.937728f,0.00346781f,
2.69475f,2.61498f,5.06565f,-0.852636f,0.936066f,0.00420073f, 2.68655f,2.73136f,5.26987f,-0.886387f,0.934268f,0.00507852f,
2.67607f,2.85076f,5.49135f,-0.920955f,0.932325f,0.00612677f, 2.6596f,2.96905f,5.73554f,-0.956353f,0.930224f,0.00737426f,
2.64442f,3.09456f,5.99812f,-0.99258f,0.92795f,0.00885338f, 2.63024f,3.22769f,6.28343f,-1.02963f,0.925493f,0.0106011f,
2.62619f,3.38088f,6.58124f,-1.06749f,0.922836f,0.0126576f, 2.61662f,3.53521f,6.9062f,-1.1061f,0.919969f,0.0150683f,
2.57458f,3.65374f,7.29656f,-1.14542f,0.916876f,0.0178819f, 2.58934f,3.86254f,7.65075f,-1.18534f,0.913543f,0.0211506f,
2.5203f,3.95335f,8.13665f,-1.22574f,0.909961f,0.0249308f, 2.50269f,4.13154f,8.60056f,-1.26642f,0.906126f,0.0292805f,
2.47743f,4.3074f,9.10565f,-1.30708f,0.902064f,0.0342592f, 2.4393f,4.47069f,9.66962f,-1.34747f,0.897765f,0.0399263f,
2.39922f,4.63861f,10.2805f,-1.38718f,0.893244f,0.0463391f, 2.36014f,4.8161f,10.9277f,-1.42572f,0.888537f,0.0535508f,
2.33114f,5.02225f,11.6023f,-1.46247f,0.883702f,0.0616073f, 2.29219f,5.21514f,12.3293f,-1.49664f,0.87884f,0.0705458f,
2.24929f,5.40183f,13.0951f,-1.52732f,0.874101f,0.0803926f, 2.13878f,5.4319f,14.037f,-1.55342f,0.869705f,0.0911617f,
2.09092f,5.59782f,14.8522f,-1.57364f,0.865954f,0.102852f, 2.02715f,5.70409f,15.7203f,-1.58662f,0.86329f,0.115462f,
1.91233f,5.66153f,16.7034f,-1.59088f,0.8623f,0.128985f, 1.89437f,5.8481f,17.3686f,-1.58495f,0.863752f,0.143425f,
1.7558f,5.65139f,18.3152f,-1.56737f,0.868768f,0.158815f, 1.68075f,5.57865f,18.9078f,-1.53732f,0.878734f,0.175235f,
1.543f,5.26207f,19.695f,-1.49458f,0.894706f,0.192804f, 1.42108f,4.9353f,20.351f,-1.43932f,0.918662f,0.211688f,
1.33019f,4.65068f,20.7456f,-1.37293f,0.952043f,0.232037f, 1.20059f,4.22511f,21.3774f,-1.29974f,0.998151f,0.253614f,
2.58905f,8.92512e-07f,2.58907f,-2.04836e-17f,0.948961f,1.98939e-05f, 2.58902f,0.0577788f,2.59025f,-0.0212178f,0.948965f,2.01815e-05f,
2.58888f,0.115595f,2.59377f,-0.042369f,0.948988f,2.10226e-05f, 2.58877f,0.173527f,2.5998f,-0.0635488f,0.948947f,2.22572e-05f,
2.5887f,0.231639f,2.60836f,-0.08477f,0.948836f,2.38938e-05f, 2.58859f,0.290006f,2.6194f,-0.106106f,0.948704f,2.61715e-05f,
2.58848f,0.348685f,2.63299f,-0.127554f,0.948543f,2.91743e-05f, 2.58832f,0.407719f,2.64915f,-0.149067f,0.948355f,3.2927e-05f,
2.58806f,0.467157f,2.66793f,-0.170635f,0.948147f,3.7489e-05f, 2.58767f,0.527077f,2.68941f,-0.192359f,0.94793f,4.32268e-05f,
2.58723f,0.58755f,2.71371f,-0.214242f,0.947679f,5.02624e-05f, 2.58676f,0.648648f,2.74092f,-0.236283f,0.947374f,5.87179e-05f,
2.58622f,0.710441f,2.77117f,-0.25852f,0.947029f,6.90219e-05f, 2.58568f,0.773021f,2.80457f,-0.280981f,0.946648f,8.16482e-05f,
2.58521f,0.836485f,2.84123f,-0.303646f,0.946216f,9.68464e-05f, 2.58488f,0.900928f,2.88115f,-0.326521f,0.945782f,0.000115424f,
2.58342f,0.966028f,2.92453f,-0.349646f,0.945318f,0.000138038f, 2.58211f,1.03227f,2.97184f,-0.373038f,0.944804f,0.000165416f,
2.58087f,1.09973f,3.02315f,-0.396744f,0.944253f,0.00019893f, 2.58162f,1.1692f,3.07826f,-0.420762f,0.943641f,0.000239548f,
2.57804f,1.23843f,3.13837f,-0.44514f,0.942985f,0.000289254f, 2.57704f,1.31017f,3.20272f,-0.469876f,0.942262f,0.000349625f,
2.57611f,1.38372f,3.27221f,-0.495014f,0.941485f,0.000423403f, 2.57488f,1.45907f,3.34716f,-0.520559f,0.940638f,0.000513094f,
2.57425f,1.53685f,3.42742f,-0.546539f,0.93973f,0.000622417f, 2.57408f,1.61723f,3.51309f,-0.572938f,0.93878f,0.000755437f,
2.58819f,1.70574f,3.59407f,-0.599801f,0.937767f,0.000917043f, 2.56256f,1.77806f,3.70831f,-0.627164f,0.936682f,0.00111324f,
2.55566f,1.86127f,3.81771f,-0.655055f,0.935516f,0.00135115f, 2.55161f,1.94926f,3.93381f,-0.683499f,0.934262f,0.00163901f,
2.54819f,2.04087f,4.05791f,-0.712515f,0.932909f,0.00198652f, 2.54396f,2.13524f,4.19136f,-0.742132f,0.931454f,0.0024053f,
2.53892f,2.2325f,4.33501f,-0.772366f,0.929886f,0.0029087f, 2.52467f,2.32504f,4.49494f,-0.803236f,0.928198f,0.00351223f,
2.5168f,2.42729f,4.66307f,-0.834757f,0.926381f,0.00423388f, 2.5087f,2.53365f,4.84599f,-0.866938f,0.924426f,0.00509417f,
2.49525f,2.639f,5.04455f,-0.899784f,0.922324f,0.00611671f, 2.48109f,2.74821f,5.25959f,-0.933287f,0.920061f,0.00732783f,
2.47147f,2.86771f,5.48803f,-0.967437f,0.917631f,0.0087576f, 2.46557f,2.99761f,5.73f,-1.0022f,0.915027f,0.0104393f,
2.45431f,3.12617f,6.00202f,-1.03749f,0.91226f,0.0124098f, 2.42294f,3.23748f,6.30003f,-1.07329f,0.909307f,0.0147099f,
2.42367f,3.39689f,6.59763f,-1.1095f,0.906153f,0.0173831f, 2.37541f,3.49472f,6.96292f,-1.14603f,0.902791f,0.0204766f,
2.35883f,3.644f,7.33046f,-1.18273f,0.899213f,0.0240398f, 2.36058f,3.82723f,7.70054f,-1.2194f,0.895423f,0.0281248f,
2.30199f,3.9277f,8.16258f,-1.2558f,0.891427f,0.0327839f, 2.26908f,4.07179f,8.63238f,-1.29161f,0.887245f,0.0380693f,
2.2507f,4.24885f,9.10999f,-1.32645f,0.882909f,0.044032f, 2.25016f,4.45811f,9.56951f,-1.35983f,0.878476f,0.0507195f,
2.15427f,4.50653f,10.2388f,-1.39118f,0.874023f,0.0581736f, 2.11127f,4.6477f,10.8307f,-1.41981f,0.869672f,0.06643f,
2.05924f,4.76994f,11.4782f,-1.44491f,0.865589f,0.0755162f, 2.00683f,4.88479f,12.1246f,-1.46555f,0.862006f,0.0854511f,
1.9674f,5.02049f,12.7575f,-1.48068f,0.859239f,0.0962458f, 1.90259f,5.0841f,13.4386f,-1.48913f,0.857781f,0.107915f,
1.79236f,5.00797f,14.2045f,-1.4897f,0.858261f,0.120464f, 1.7707f,5.13873f,14.7027f,-1.48149f,0.861308f,0.133921f,
1.63951f,4.92986f,15.4473f,-1.46355f,0.867771f,0.148333f, 1.60777f,4.94904f,15.7925f,-1.43523f,0.878669f,0.163776f,
1.46771f,4.62592f,16.4572f,-1.39611f,0.895751f,0.180384f, 1.39045f,4.43906f,16.8365f,-1.34681f,0.919753f,0.198271f,
1.27187f,4.08966f,17.2749f,-1.28819f,0.952675f,0.217634f, 1.18628f,3.81885f,17.6397f,-1.22371f,0.998152f,0.238317f,
2.42304f,-1.23177e-06f,2.42304f,-2.64404e-17f,0.940817f,2.22747e-05f, 2.42306f,0.0539493f,2.4242f,-0.020943f,0.940779f,2.24804e-05f,
2.42313f,0.107959f,2.42766f,-0.0418948f,0.940667f,2.30959e-05f, 2.42309f,0.162078f,2.4333f,-0.0628888f,0.940576f,2.43626e-05f,
2.42294f,0.21635f,2.44111f,-0.0839094f,0.940506f,2.63182e-05f, 2.42276f,0.270839f,2.45127f,-0.104982f,0.940385f,2.88616e-05f,
2.4226f,0.325606f,2.46381f,-0.126122f,0.9402f,3.20228e-05f, 2.42238f,0.380715f,2.47872f,-0.147399f,0.939992f,3.61137e-05f,
2.42213f,0.436215f,2.4961f,-0.168785f,0.939744f,4.11888e-05f, 2.42175f,0.492134f,2.51595f,-0.190233f,0.939477f,4.73404e-05f,
2.42129f,0.548551f,2.53832f,-0.211824f,0.93919f,5.49143e-05f, 2.42077f,0.605539f,2.56338f,-0.233578f,0.938868f,6.4161e-05f,
2.42026f,0.663168f,2.5912f,-0.255491f,0.938487f,7.52463e-05f, 2.41982f,0.721541f,2.62188f,-0.277616f,0.938071f,8.88196e-05f,
2.41962f,0.780768f,2.65552f,-0.299947f,0.937602f,0.000105217f, 2.41861f,0.840611f,2.6921f,-0.322485f,0.937091f,0.000125033f,
2.41797f,0.901491f,2.73207f,-0.345236f,0.936565f,0.000149157f, 2.41663f,0.963133f,2.77541f,-0.368226f,0.93599f,0.000178267f,
2.41589f,1.02604f,2.82226f,-0.391498f,0.935374f,0.000213712f, 2.41472f,1.08994f,2.87273f,-0.415055f,0.934696f,0.000256565f,
2.41452f,1.15544f,2.92691f,-0.438934f,0.933965f,0.000308676f, 2.41464f,1.22262f,2.98532f,-0.463142f,0.933169f,0.000371805f,
2.41447f,1.29142f,3.04844f,-0.487703f,0.932306f,0.000448367f, 2.41314f,1.36154f,3.11717f,-0.512641f,0.931378f,0.000541309f,
2.41404f,1.43484f,3.18994f,-0.537943f,0.930389f,0.000653807f, 2.40583f,1.50471f,3.26984f,-0.563621f,0.929347f,0.000790014f,
2.40362f,1.58019f,3.35445f,-0.589718f,0.928237f,0.000954842f, 2.39808f,1.65567f,3.44619f,-0.616251f,0.927047f,0.00115388f,
2.39522f,1.73531f,3.54343f,-0.643242f,0.925768f,0.00139387f, 2.39302f,1.8181f,3.64697f,-0.670711f,0.924397f,0.00168282f,
2.39052f,1.90355f,3.75765f,-0.698673f,0.922925f,0.00203003f, 2.39026f,1.99398f,3.87461f,-0.727142f,0.921345f,0.00244632f,
2.37253f,2.07244f,4.01156f,-0.756132f,0.919651f,0.00294438f, 2.38011f,2.17668f,4.14266f,-0.785646f,0.917835f,0.00353864f,
2.35941f,2.25843f,4.30155f,-0.815689f,0.915888f,0.00424576f, 2.34838f,2.3526f,4.4637f,-0.846262f,0.913805f,0.00508503f,
2.33746f,2.45062f,4.63827f,-0.877346f,0.911579f,0.00607784f, 2.32977f,2.55634f,4.82354f,-0.908889f,0.909226f,0.0072487f,
2.31781f,2.66197f,5.02667f,-0.940884f,0.906722f,0.00862475f, 2.30247f,2.76832f,5.24472f,-0.973303f,0.904057f,0.0102365f,
2.2842f,2.87565f,5.48302f,-1.00609f,0.901223f,0.0121173f, 2.27534f,2.99994f,5.72877f,-1.03919f,0.898212f,0.0143038f,
2.25275f,3.11177f,6.00526f,-1.07247f,0.895016f,0.0168347f, 2.23162f,3.23048f,6.29845f,-1.10584f,0.891639f,0.0197527f,
2.24538f,3.40572f,6.57572f,-1.13913f,0.888083f,0.0231016f, 2.1806f,3.4705f,6.95531f,-1.17212f,0.884358f,0.0269275f,
2.16669f,3.61683f,7.30728f,-1.20459f,0.880483f,0.0312772f, 2.15943f,3.78016f,7.66239f,-1.23622f,0.87649f,0.0361972f,
2.09767f,3.85621f,8.12012f,-1.26665f,0.872424f,0.041733f, 2.06488f,3.98283f,8.55233f,-1.29543f,0.868354f,0.0479277f,
2.02736f,4.10262f,9.01032f,-1.32204f,0.864376f,0.0548204f, 1.98207f,4.20628f,9.50584f,-1.34588f,0.860622f,0.0624461f,
1.94545f,4.32489f,9.98418f,-1.36613f,0.857337f,0.070834f, 1.89256f,4.40182f,10.5084f,-1.38211f,0.85474f,0.080008f,
1.85094f,4.49358f,11.0077f,-1.39303f,0.85314f,0.0899924f, 1.78615f,4.52435f,11.5349f,-1.398f,0.852925f,0.100802f,
1.73541f,4.55981f,12.0318f,-1.39616f,0.85462f,0.112469f, 1.65742f,4.5085f,12.5502f,-1.38671f,0.858856f,0.125028f,
1.59457f,4.46624f,12.927f,-1.36874f,0.866623f,0.138535f, 1.50342f,4.30462f,13.3844f,-1.34208f,0.878794f,0.153078f,
1.42841f,4.15989f,13.7554f,-1.30652f,0.896312f,0.168757f, 1.30724f,3.85645f,14.227f,-1.26246f,0.920488f,0.185731f,
1.24963f,3.69292f,14.4182f,-1.21041f,0.952993f,0.204157f, 1.14417f,3.38624f,14.7705f,-1.1533f,0.99814f,0.224019f,
2.27471f,-1.2709e-06f,2.27471f,2.49622e-17f,0.931403f,2.39764e-05f, 2.27457f,0.0505059f,2.27563f,-0.0206912f,0.931467f,2.44222e-05f,
2.27445f,0.10106f,2.27865f,-0.0413878f,0.931463f,2.53489e-05f, 2.27438f,0.151708f,2.28383f,-0.0621088f,0.931379f,2.67503e-05f,
2.27431f,0.202519f,2.29116f,-0.08288f,0.931227f,2.87004e-05f, 2.27416f,0.253527f,2.30058f,-0.10373f,0.931074f,3.14543e-05f,
2.27394f,0.304769f,2.3121f,-0.124605f,0.930904f,3.49938e-05f, 2.27367f,0.356313f,2.32587f,-0.145549f,0.930679f,3.93447e-05f,
2.27332f,0.408212f,2.34187f,-0.166627f,0.930427f,4.48307e-05f, 2.27296f,0.460529f,2.3602f,-0.187822f,0.930119f,5.15154e-05f,
2.27257f,0.513301f,2.38092f,-0.209129f,0.929763f,5.95923e-05f, 2.2721f,0.566585f,2.40398f,-0.230561f,0.929404f,6.95181e-05f,
2.2717f,0.620466f,2.42956f,-0.252129f,0.928995f,8.14331e-05f, 2.2715f,0.675062f,2.45772f,-0.27388f,0.928547f,9.59043e-05f,
2.27116f,0.730334f,2.48846f,-0.29582f,0.928045f,0.000113364f, 2.2705f,0.786304f,2.5221f,-0.317966f,0.927487f,0.000134428f,
2.26969f,0.843054f,2.55874f,-0.340335f,0.926877f,0.000159906f, 2.26944f,0.900873f,2.59835f,-0.362899f,0.926237f,0.000190648f,
2.26894f,0.959544f,2.64092f,-0.385697f,0.925554f,0.000227802f, 2.26796f,1.01911f,2.68729f,-0.408756f,0.924817f,0.000272707f,
2.26716f,1.07994f,2.73728f,-0.432088f,0.924016f,0.000326876f, 2.2674f,1.14256f,2.79079f,-0.455724f,0.923155f,0.000392428f,
2.26716f,1.20663f,2.84865f,-0.479667f,0.922221f,0.00047149f, 2.26833f,1.27316f,2.91003f,-0.503938f,0.921215f,0.000566887f,
2.28075f,1.34827f,2.97025f,-0.528554f,0.920134f,0.000682008f, 2.26183f,1.40672f,3.04826f,-0.553491f,0.918998f,0.000820717f,
2.25856f,1.47617f,3.12483f,-0.578776f,0.917792f,0.000987623f, 2.26155f,1.55205f,3.20434f,-0.604436f,0.916505f,0.00118826f,
2.25537f,1.62367f,3.29296f,-0.630485f,0.915129f,0.00142905f, 2.25143f,1.69918f,3.38741f,-0.656936f,0.913659f,0.00171756f,
2.24778f,1.77729f,3.48723f,-0.683798f,0.912085f,0.00206257f, 2.23579f,1.85108f,3.59927f,-0.71108f,0.910405f,0.00247432f,
2.23814f,1.93956f,3.71079f,-0.738782f,0.908608f,0.00296454f, 2.22703f,2.01935f,3.83776f,-0.766903f,0.906691f,0.00354675f,
2.21822f,2.10404f,3.97096f,-0.795443f,0.904647f,0.00423662f, 2.20853f,2.19099f,4.11449f,-0.824376f,0.902472f,0.00505148f,
2.19855f,2.28095f,4.27069f,-0.853656f,0.900184f,0.00601138f, 2.19125f,2.37727f,4.433f,-0.883268f,0.89776f,0.00713841f,
2.1759f,2.46862f,4.61288f,-0.91319f,0.895195f,0.00845775f, 2.16325f,2.56658f,4.80177f,-0.943368f,0.892479f,0.00999649f,
2.15375f,2.67247f,5.00418f,-0.973744f,0.889612f,0.0117852f, 2.13463f,2.77071f,5.22208f,-1.00423f,0.886587f,0.0138563f,
2.11616f,2.87349f,5.45701f,-1.03472f,0.88341f,0.0162455f, 2.10496f,2.99061f,5.70223f,-1.06508f,0.880085f,0.0189899f,
2.09276f,3.11102f,5.96089f,-1.09515f,0.876622f,0.0221293f, 2.05649f,3.20027f,6.25856f,-1.12473f,0.873043f,0.0257046f,
2.07493f,3.37629f,6.5146f,-1.15358f,0.869373f,0.0297576f, 2.00459f,3.4176f,6.88587f,-1.18141f,0.865656f,0.0343304f,
1.99871f,3.56418f,7.19621f,-1.20787f,0.861948f,0.0394641f, 1.96461f,3.66526f,7.55578f,-1.23252f,0.85836f,0.0451984f,
1.92194f,3.74998f,7.94043f,-1.25489f,0.855005f,0.0515707f, 1.87698f,3.82702f,8.333f,-1.27452f,0.852011f,0.0586157f,
1.8382f,3.91143f,8.72711f,-1.29082f,0.849557f,0.0663644f, 1.78447f,3.95681f,9.14848f,-1.30317f,0.847882f,0.0748461f,
1.7418f,4.01503f,9.54476f,-1.31089f,0.847291f,0.0840894f, 1.67793f,4.0141f,9.97754f,-1.31329f,0.848161f,0.0941208f,
1.62786f,4.02715f,10.3646f,-1.30963f,0.851028f,0.104982f, 1.55285f,3.96058f,10.7623f,-1.29921f,0.856631f,0.116714f,
1.50931f,3.94007f,11.0594f,-1.2818f,0.865475f,0.129384f, 1.4128f,3.76245f,11.4219f,-1.25689f,0.878476f,0.143076f,
1.34892f,3.6423f,11.717f,-1.2246f,0.896622f,0.15791f, 1.25464f,3.41843f,12.0363f,-1.18497f,0.921095f,0.174012f,
1.19704f,3.26273f,12.2221f,-1.13865f,0.953287f,0.191577f, 1.12715f,3.06586f,12.4046f,-1.08784f,0.998117f,0.210666f,
2.14094f,-6.0552e-07f,2.14094f,2.10135e-17f,0.921331f,2.63956e-05f, 2.14097f,0.0473655f,2.14193f,-0.0203682f,0.921288f,2.66227e-05f,
2.14093f,0.0947942f,2.14482f,-0.0408179f,0.92122f,2.74826e-05f, 2.14086f,0.142315f,2.14962f,-0.0612958f,0.921124f,2.90129e-05f,
2.14071f,0.189956f,2.15634f,-0.0817457f,0.921002f,3.12006e-05f, 2.14053f,0.237779f,2.16502f,-0.10226f,0.920838f,3.41166e-05f,
2.14029f,0.285837f,2.17571f,-0.12287f,0.920633f,3.79097e-05f, 2.14004f,0.33417f,2.18846f,-0.143545f,0.920365f,4.25888e-05f,
2.13968f,0.382807f,2.20322f,-0.164285f,0.92009f,4.84396e-05f, 2.1393f,0.431818f,2.22008f,-0.185125f,0.919777f,5.56078e-05f,
2.13895f,0.481265f,2.23912f,-0.206074f,0.919406f,6.42479e-05f, 2.13867f,0.531214f,2.26039f,-0.227175f,0.918993f,7.47975e-05f,
2.13863f,0.581763f,2.28396f,-0.248406f,0.91852f,8.74413e-05f, 2.13893f,0.632996f,2.30979f,-0.269771f,0.918031f,0.000102796f,
2.13807f,0.68457f,2.33792f,-0.291284f,0.91749f,0.000121199f, 2.13662f,0.736672f,2.3691f,-0.312987f,0.916904f,0.000143451f,
2.13624f,0.789823f,2.40279f,-0.334879f,0.916254f,0.000170141f, 2.13493f,0.843494f,2.43932f,-0.356991f,0.91555f,0.000202363f,
2.13494f,0.898403f,2.4785f,-0.379317f,0.91478f,0.00024106f, 2.13571f,0.954461f,2.52024f,-0.401844f,0.913974f,0.000287663f,
2.13804f,1.01239f,2.56515f,-0.424606f,0.913115f,0.000343763f, 2.13749f,1.0706f,2.61387f,-0.44762f,0.912189f,0.000411184f,
2.13922f,1.13143f,2.66576f,-0.470902f,0.911193f,0.000492236f, 2.13783f,1.19226f,2.72147f,-0.494471f,0.910126f,0.000589697f,
2.13524f,1.25401f,2.7818f,-0.518333f,0.908978f,0.000706661f, 2.13325f,1.31773f,2.84617f,-0.542501f,0.907748f,0.000846946f,
2.13035f,1.3826f,2.91651f,-0.566961f,0.906446f,0.00101501f, 2.12957f,1.45069f,2.98952f,-0.591715f,0.905073f,0.0012161f,
2.12649f,1.51912f,3.06893f,-0.616786f,0.903615f,0.00145633f, 2.12136f,1.58802f,3.15338f,-0.642182f,0.902062f,0.0017428f,
2.11547f,1.65831f,3.24419f,-0.66791f,0.900412f,0.00208387f, 2.11245f,1.73315f,3.34034f,-0.693969f,0.898654f,0.00248901f,
2.10741f,1.80872f,3.44331f,-0.720355f,0.896784f,0.00296916f, 2.12154f,1.90368f,3.5435f,-0.747065f,0.894799f,0.00353708f,
2.11378f,1.98273f,3.66131f,-0.77408f,0.892691f,0.00420682f, 2.08202f,2.0415f,3.80257f,-0.801383f,0.890458f,0.00499473f,
2.08605f,2.13679f,3.92688f,-0.828908f,0.888115f,0.00591884f, 2.06524f,2.21061f,4.07958f,-0.856636f,0.885656f,0.00699977f,
2.05174f,2.2943f,4.23701f,-0.884525f,0.883068f,0.00825971f, 2.04586f,2.38955f,4.3983f,-0.912523f,0.88035f,0.00972371f,
2.05463f,2.506f,4.55831f,-0.940563f,0.877503f,0.0114192f, 2.03445f,2.59216f,4.75004f,-0.968548f,0.874528f,0.0133752f,
1.99904f,2.6615f,4.9663f,-0.996371f,0.871432f,0.0156237f, 2.01825f,2.80468f,5.14628f,-1.0239f,0.868229f,0.0181986f,
1.992f,2.89186f,5.37518f,-1.05097f,0.864936f,0.0211351f, 1.95039f,2.95873f,5.63578f,-1.0774f,0.861579f,0.0244701f,
1.92662f,3.05203f,5.88959f,-1.10294f,0.858195f,0.0282411f, 1.89438f,3.13348f,6.15932f,-1.12733f,0.85484f,0.0324862f,
1.90326f,3.28279f,6.40459f,-1.15019f,0.851614f,0.0372435f, 1.86691f,3.35259f,6.69907f,-1.17123f,0.848587f,0.0425501f,
1.82263f,3.41919f,7.01333f,-1.19005f,0.845868f,0.0484419f, 1.77641f,3.47106f,7.34169f,-1.20623f,0.843599f,0.0549534f,
1.73631f,3.52798f,7.6599f,-1.21927f,0.841967f,0.062118f, 1.68499f,3.55437f,7.99925f,-1.22866f,0.841203f,0.0699678f,
1.68957f,3.68505f,8.24826f,-1.23386f,0.841597f,0.0785356f, 1.63987f,3.69543f,8.56402f,-1.23418f,0.843624f,0.0878617f,
1.57048f,3.64711f,8.90221f,-1.22919f,0.84771f,0.09798f, 1.51466f,3.61084f,9.18366f,-1.21857f,0.854309f,0.108957f,
1.43636f,3.49639f,9.48596f,-1.20175f,0.86414f,0.120853f, 1.37354f,3.39661f,9.73565f,-1.17867f,0.877973f,0.133759f,
1.2889f,3.22629f,10.0157f,-1.14919f,0.896683f,0.147784f, 1.24744f,3.13739f,10.1811f,-1.11357f,0.921275f,0.16307f,
1.18099f,2.96928f,10.3482f,-1.07215f,0.953381f,0.179833f, 1.0949f,2.74636f,10.5289f,-1.02676f,0.998083f,0.198205f,
2.02067f,-1.48891e-06f,2.02067f,-4.97887e-17f,0.910113f,2.85119e-05f, 2.02068f,0.0445231f,2.02159f,-0.0201003f,0.910068f,2.87747e-05f,
2.02067f,0.0890845f,2.02429f,-0.0402021f,0.909969f,2.96409e-05f, 2.02053f,0.133726f,2.02868f,-0.0603253f,0.909896f,3.132e-05f,
2.02037f,0.178491f,2.0349f,-0.0804787f,0.909759f,3.36604e-05f, 2.0202f,0.223426f,2.04296f,-0.100691f,0.909558f,3.67432e-05f,
2.01997f,0.268567f,2.05282f,-0.120959f,0.909339f,4.07877e-05f, 2.0197f,0.313945f,2.06453f,-0.141259f,0.909076f,4.57908e-05f,
2.01943f,0.359629f,2.07813f,-0.161663f,0.908774f,5.20188e-05f, 2.01922f,0.405674f,2.09371f,-0.182163f,0.908412f,5.959e-05f,
2.01864f,0.45204f,2.11137f,-0.202755f,0.908007f,6.87729e-05f, 2.01828f,0.49888f,2.13098f,-0.223441f,0.907574f,7.99013e-05f,
2.01831f,0.546292f,2.15265f,-0.244247f,0.907088f,9.32726e-05f, 2.01817f,0.594205f,2.17632f,-0.265199f,0.906549f,0.000109385f,
2.01757f,0.642588f,2.20233f,-0.286304f,0.905949f,0.000128715f, 2.01684f,0.691547f,2.23073f,-0.307552f,0.905303f,0.00015192f,
2.0183f,0.741819f,2.26159f,-0.328951f,0.904619f,0.000179806f, 2.01648f,0.791771f,2.29468f,-0.350522f,0.903875f,0.000213194f,
2.01743f,0.843276f,2.32991f,-0.372289f,0.903072f,0.000253291f, 2.01933f,0.896068f,2.36781f,-0.394261f,0.902201f,0.000301348f,
2.02088f,0.950071f,2.40878f,-0.416447f,0.901259f,0.000358907f, 2.02318f,1.00587f,2.45263f,-0.438829f,0.900264f,0.000427869f,
2.02302f,1.06191f,2.49924f,-0.461425f,0.899212f,0.000510484f, 2.01961f,1.11771f,2.55123f,-0.484253f,0.898089f,0.000609302f,
2.01805f,1.17587f,2.60674f,-0.507323f,0.896889f,0.000727413f, 2.01595f,1.2351f,2.66513f,-0.530645f,0.895608f,0.000868457f,
2.01571f,1.29708f,2.7269f,-0.554227f,0.89424f,0.0010367f, 2.01555f,1.36087f,2.79254f,-0.578072f,0.892783f,0.00123711f,
2.01027f,1.42278f,2.86361f,-0.602158f,0.891246f,0.00147546f, 2.00573f,1.48684f,2.93929f,-0.626481f,0.88963f,0.00175846f,
2.00426f,1.55505f,3.01914f,-0.651051f,0.887921f,0.00209383f, 1.99818f,1.62165f,3.10714f,-0.67587f,0.886114f,0.00249056f,
2.0051f,1.70095f,3.19378f,-0.700927f,0.884202f,0.00295877f, 1.98742f,1.76203f,3.29742f,-0.72621f,0.882181f,0.00351006f,
1.97899f,1.83275f,3.40218f,-0.751701f,0.880048f,0.00415766f, 1.97619f,1.91097f,3.51174f,-0.777372f,0.8778f,0.00491628f,
1.97598f,1.99452f,3.627f,-0.803192f,0.875436f,0.00580267f, 1.96131f,2.06642f,3.75594f,-0.82909f,0.87297f,0.00683525f,
1.94522f,2.13889f,3.89449f,-0.855012f,0.870407f,0.00803455f, 1.94314f,2.22888f,4.03251f,-0.880906f,0.867737f,0.0094229f,
1.9209f,2.29883f,4.18889f,-0.906704f,0.864968f,0.0110251f, 1.9069f,2.38014f,4.35104f,-0.932313f,0.862103f,0.0128676f,
1.90022f,2.4732f,4.51608f,-0.957625f,0.859156f,0.014979f, 1.90202f,2.58021f,4.68164f,-0.982505f,0.856142f,0.0173894f,
1.85773f,2.62885f,4.8946f,-1.0068f,0.853089f,0.0201311f, 1.85325f,2.73242f,5.08379f,-1.03034f,0.850026f,0.0232371f,
1.83919f,2.82471f,5.28468f,-1.05289f,0.846997f,0.0267416f, 1.79387f,2.87107f,5.53074f,-1.07419f,0.844083f,0.0306797f,
1.81018f,3.01179f,5.71728f,-1.09394f,0.841365f,0.0350864f, 1.7723f,3.06864f,5.96123f,-1.11187f,0.838925f,0.0399971f,
1.72708f,3.10784f,6.22846f,-1.12766f,0.836873f,0.0454462f, 1.6804f,3.13907f,6.49342f,-1.14093f,0.835357f,0.0514687f,
1.64338f,3.18167f,6.74902f,-1.15128f,0.834557f,0.058099f, 1.64948f,3.29789f,6.94994f,-1.1583f,0.834698f,0.0653723f,
1.59033f,3.28306f,7.23497f,-1.16139f,0.836148f,0.0733262f, 1.54164f,3.27517f,7.48732f,-1.16025f,0.83924f,0.082002f,
1.47512f,3.21945f,7.76253f,-1.15455f,0.844309f,0.0914496f, 1.46137f,3.25646f,7.91903f,-1.14379f,0.851885f,0.10172f,
1.40185f,3.17895f,8.13116f,-1.12781f,0.862655f,0.112898f, 1.32238f,3.04074f,8.37808f,-1.10639f,0.877174f,0.125065f,
1.27121f,2.95008f,8.54038f,-1.07959f,0.896252f,0.138335f, 1.22031f,2.84048f,8.69907f,-1.04749f,0.921055f,0.152868f,
1.13698f,2.64479f,8.88217f,-1.01028f,0.953229f,0.168876f, 1.07759f,2.49381f,8.97513f,-0.96957f,0.998039f,0.186585f,
1.91212f,7.09836e-07f,1.91213f,-7.33323e-17f,0.897842f,3.05806e-05f, 1.91213f,0.0419068f,1.91298f,-0.0197652f,0.897795f,3.08646e-05f,
1.91208f,0.0838453f,1.91545f,-0.0395026f,0.89771f,3.1826e-05f, 1.91197f,0.125855f,1.91951f,-0.0592808f,0.897625f,3.35925e-05f,
1.91188f,0.167987f,1.92526f,-0.079089f,0.897465f,3.60488e-05f, 1.91164f,0.210261f,1.93272f,-0.098944f,0.897261f,3.93474e-05f,
1.91133f,0.252713f,1.94183f,-0.118828f,0.897034f,4.36208e-05f, 1.91099f,0.295386f,1.95268f,-0.138768f,0.896747f,4.89122e-05f,
1.91061f,0.338325f,1.96527f,-0.158806f,0.896411f,5.54783e-05f, 1.91025f,0.381573f,1.97964f,-0.178891f,0.89603f,6.34329e-05f,
1.90994f,0.425177f,1.99581f,-0.199066f,0.895617f,7.31339e-05f, 1.90986f,0.469227f,2.01384f,-0.219334f,0.895143f,8.47627e-05f,
1.9102f,0.51382f,2.03377f,-0.23973f,0.894615f,9.87965e-05f, 1.90967f,0.55868f,2.05527f,-0.260224f,0.894036f,0.000115584f,
1.9093f,0.604084f,2.07907f,-0.28083f,0.893418f,0.000135728f, 1.90949f,0.650196f,2.105f,-0.301572f,0.892744f,0.000159836f,
1.90967f,0.696856f,2.13295f,-0.322461f,0.892005f,0.000188637f, 1.91112f,0.744461f,2.16276f,-0.343515f,0.891204f,0.00022312f,
1.91355f,0.793057f,2.19453f,-0.364709f,0.890352f,0.000264313f, 1.91387f,0.84216f,2.23007f,-0.386054f,0.889445f,0.000313491f,
1.91488f,0.89263f,2.26804f,-0.407574f,0.888474f,0.000372215f, 1.92642f,0.949434f,2.30566f,-0.429282f,0.887433f,0.000442321f,
1.91466f,0.996081f,2.3503f,-0.451183f,0.886318f,0.000525921f, 1.91421f,1.04968f,2.39702f,-0.47328f,0.885126f,0.000625523f,
1.91306f,1.10409f,2.44618f,-0.495546f,0.883875f,0.000744082f, 1.91336f,1.16076f,2.49833f,-0.518001f,0.882553f,0.000885071f,
1.91424f,1.21921f,2.55334f,-0.540656f,0.88115f,0.00105253f, 1.92641f,1.2865f,2.60663f,-0.563512f,0.879663f,0.00125116f,
1.90562f,1.33363f,2.67749f,-0.586569f,0.878086f,0.00148639f, 1.90315f,1.39433f,2.74599f,-0.609823f,0.876416f,0.00176451f,
1.91847f,1.46984f,2.81058f,-0.633262f,0.874656f,0.00209278f, 1.89813f,1.52061f,2.89413f,-0.656845f,0.872818f,0.00247945f,
1.89235f,1.58376f,2.97498f,-0.680575f,0.870891f,0.00293388f, 1.88675f,1.64883f,3.06101f,-0.704442f,0.868869f,0.00346691f,
1.87896f,1.71389f,3.15635f,-0.72842f,0.866748f,0.00409046f, 1.89372f,1.80129f,3.24322f,-0.752483f,0.864527f,0.00481814f,
1.86373f,1.84968f,3.35852f,-0.776596f,0.862209f,0.00566528f, 1.85533f,1.91975f,3.46788f,-0.800707f,0.859791f,0.00664836f,
1.85159f,1.99663f,3.58189f,-0.824765f,0.85728f,0.00778623f, 1.85387f,2.08248f,3.69968f,-0.848662f,0.854702f,0.00909903f,
1.83236f,2.1446f,3.83402f,-0.872339f,0.852062f,0.0106093f, 1.81425f,2.21163f,3.97659f,-0.895708f,0.849364f,0.0123406f,
1.81082f,2.29776f,4.1176f,-0.918668f,0.846625f,0.0143189f, 1.79837f,2.375f,4.26641f,-0.941095f,0.843865f,0.0165716f,
1.76847f,2.43066f,4.43549f,-0.962844f,0.841114f,0.0191275f, 1.76946f,2.52807f,4.5906f,-0.983748f,0.838409f,0.022017f,
1.75312f,2.60054f,4.76754f,-1.00362f,0.835799f,0.0252714f, 1.70849f,2.63745f,4.96546f,-1.02222f,0.833354f,0.0289226f,
1.71969f,2.75214f,5.12301f,-1.03925f,0.831183f,0.0330041f, 1.68087f,2.79194f,5.33243f,-1.05451f,0.829365f,0.0375492f,
1.63526f,2.81549f,5.54947f,-1.06771f,0.828011f,0.0425915f, 1.65185f,2.93902f,5.69451f,-1.07854f,0.827264f,0.0481661f,
1.60036f,2.93369f,5.94455f,-1.08669f,0.827299f,0.0543081f, 1.55469f,2.94673f,6.14438f,-1.09173f,0.828364f,0.0610551f,
1.49706f,2.92f,6.37497f,-1.09328f,0.830796f,0.0684474f, 1.45064f,2.90371f,6.57994f,-1.09113f,0.834825f,0.076529f,
1.4416f,2.94888f,6.7208f,-1.08496f,0.840814f,0.0853554f, 1.37263f,2.86436f,6.93325f,-1.07434f,0.849394f,0.0949859f,
1.35336f,2.86083f,7.04199f,-1.05926f,0.860857f,0.105493f, 1.29209f,2.76363f,7.22448f,-1.03951f,0.876026f,0.116975f,
1.21358f,2.61457f,7.41942f,-1.01507f,0.89559f,0.129547f, 1.16291f,2.51144f,7.54851f,-0.986064f,0.920468f,0.143357f,
1.12158f,2.41404f,7.63029f,-0.952518f,0.952847f,0.158664f, 1.05498f,2.25735f,7.70663f,-0.915857f,0.997986f,0.175755f,
1.81389f,7.52923e-07f,1.81389f,-1.77818e-17f,0.88453f,3.26268e-05f, 1.8139f,0.0394852f,1.81466f,-0.0193668f,0.884481f,3.29211e-05f,
1.81383f,0.0790088f,1.81696f,-0.0387527f,0.884401f,3.39622e-05f, 1.81369f,0.118591f,1.82072f,-0.0581405f,0.884304f,3.58062e-05f,
1.81351f,0.158273f,1.82605f,-0.0775571f,0.884131f,3.83792e-05f, 1.81323f,0.198091f,1.83291f,-0.0970236f,0.883927f,4.18835e-05f,
1.81289f,0.238061f,1.84132f,-0.116498f,0.883676f,4.63298e-05f, 1.81252f,0.278233f,1.85131f,-0.13605f,0.883379f,5.19307e-05f,
1.81218f,0.318655f,1.86291f,-0.155656f,0.883018f,5.8763e-05f, 1.8119f,0.359354f,1.87612f,-0.175316f,0.882632f,6.71434e-05f,
1.81182f,0.400406f,1.89095f,-0.195046f,0.882185f,7.72153e-05f, 1.81208f,0.44189f,1.90748f,-0.214879f,0.881684f,8.93799e-05f,
1.81249f,0.483801f,1.92547f,-0.234788f,0.881131f,0.000103924f, 1.81263f,0.526079f,1.94527f,-0.254783f,0.880536f,0.000121354f,
1.81283f,0.568816f,1.96697f,-0.274887f,0.879884f,0.000142179f, 1.81278f,0.612013f,1.991f,-0.295111f,0.879167f,0.000167002f,
1.81217f,0.655523f,2.01685f,-0.315453f,0.878394f,0.000196631f, 1.81418f,0.700151f,2.04399f,-0.335902f,0.877574f,0.000231947f,
1.81573f,0.74545f,2.0734f,-0.356479f,0.876693f,0.000273983f, 1.81814f,0.792101f,2.10518f,-0.377199f,0.875744f,0.000324014f,
1.82124f,0.840282f,2.13901f,-0.398068f,0.874724f,0.000383539f, 1.8218f,0.888526f,2.17459f,-0.419074f,0.873644f,0.000454328f,
1.821f,0.937274f,2.21323f,-0.44021f,0.872506f,0.000538417f, 1.83528f,0.995492f,2.25068f,-0.461495f,0.871297f,0.000638205f,
1.82168f,1.0395f,2.29841f,-0.482935f,0.870013f,0.000756526f, 1.8205f,1.09151f,2.34689f,-0.504531f,0.868649f,0.000896673f,
1.83446f,1.15409f,2.39246f,-0.526282f,0.867204f,0.00106245f, 1.81657f,1.19808f,2.45078f,-0.548154f,0.865694f,0.00125829f,
1.81337f,1.25235f,2.50748f,-0.570154f,0.86411f,0.00148931f, 1.81311f,1.30998f,2.56733f,-0.592284f,0.862445f,0.00176138f,
1.81024f,1.36725f,2.63122f,-0.614533f,0.860693f,0.00208114f, 1.82191f,1.43698f,2.69385f,-0.636889f,0.858854f,0.00245634f,
1.80154f,1.48384f,2.77262f,-0.659336f,0.856926f,0.00289562f, 1.81054f,1.55535f,2.84332f,-0.68184f,0.854915f,0.00340884f,
1.79101f,1.60482f,2.93141f,-0.704349f,0.852836f,0.00400706f, 1.78816f,1.66984f,3.01507f,-0.726846f,0.850679f,0.00470256f,
1.77818f,1.73f,3.1067f,-0.749301f,0.848447f,0.00550941f, 1.76897f,1.79227f,3.20339f,-0.771664f,0.84614f,0.00644261f,
1.76578f,1.86209f,3.30193f,-0.79388f,0.843765f,0.00751909f, 1.78227f,1.95435f,3.39477f,-0.815885f,0.841332f,0.00875738f,
1.75939f,2.00778f,3.5124f,-0.8376f,0.838852f,0.0101774f, 1.72863f,2.05215f,3.64341f,-0.858903f,0.83636f,0.0118011f,
1.73399f,2.13858f,3.75575f,-0.87969f,0.833878f,0.0136515f, 1.71957f,2.20332f,3.88283f,-0.899861f,0.831425f,0.0157537f,
1.68441f,2.2422f,4.03452f,-0.919285f,0.82903f,0.0181336f, 1.68684f,2.32927f,4.16208f,-0.937817f,0.826737f,0.0208194f,
1.66869f,2.38958f,4.30567f,-0.955284f,0.824595f,0.0238397f, 1.64843f,2.4461f,4.45411f,-0.9715f,0.82267f,0.0272246f,
1.63192f,2.50733f,4.61049f,-0.98621f,0.821062f,0.0310051f, 1.59264f,2.53222f,4.78482f,-0.999163f,0.81989f,0.0352133f,
1.55955f,2.5624f,4.94897f,-1.01017f,0.819251f,0.0398823f, 1.56061f,2.64311f,5.08564f,-1.01897f,0.819281f,0.0450465f,
1.50998f,2.63475f,5.2766f,-1.02531f,0.820145f,0.0507423f, 1.46969f,2.63582f,5.44879f,-1.0288f,0.822106f,0.0570082f,
1.46566f,2.69374f,5.57765f,-1.02921f,0.825435f,0.0638864f, 1.40544f,2.64361f,5.76432f,-1.02637f,0.830345f,0.071425f,
1.35758f,2.60566f,5.9207f,-1.01985f,0.837284f,0.0796768f, 1.34153f,2.61624f,6.03343f,-1.00965f,0.846614f,0.0887112f,
1.27943f,2.52473f,6.1764f,-0.995417f,0.858895f,0.0986023f, 1.24989f,2.48261f,6.29187f,-0.977193f,0.874626f,0.109444f,
1.18852f,2.37803f,6.43236f,-0.95492f,0.894596f,0.121357f, 1.15429f,2.31081f,6.5177f,-0.928643f,0.919802f,0.134501f,
1.08812f,2.17086f,6.61989f,-0.898391f,0.952255f,0.149154f, 1.04131f,2.06156f,6.65314f,-0.865252f,0.997924f,0.165667f,
1.72492f,-7.10056e-08f,1.72493f,-3.98964e-17f,0.870148f,3.4561e-05f, 1.7249f,0.0372379f,1.72562f,-0.0189368f,0.87012f,3.49124e-05f,
1.72482f,0.0745253f,1.72773f,-0.0379374f,0.870045f,3.603e-05f, 1.72464f,0.11185f,1.73121f,-0.0568884f,0.869926f,3.79115e-05f,
1.72438f,0.149269f,1.7361f,-0.0758946f,0.869768f,4.06627e-05f, 1.72411f,0.186804f,1.74243f,-0.0949245f,0.86954f,4.42749e-05f,
1.72376f,0.224477f,1.75016f,-0.11398f,0.869288f,4.89619e-05f, 1.72345f,0.262338f,1.75934f,-0.133076f,0.868972f,5.47588e-05f,
1.72322f,0.300429f,1.76998f,-0.152241f,0.868606f,6.19164e-05f, 1.72318f,0.338792f,1.78208f,-0.17143f,0.868197f,7.05795e-05f,
1.72348f,0.377505f,1.79567f,-0.190695f,0.867738f,8.10655e-05f, 1.72345f,0.416488f,1.81101f,-0.210036f,0.867213f,9.36191e-05f,
1.72336f,0.455776f,1.82734f,-0.229431f,0.866647f,0.000108641f, 1.72291f,0.495355f,1.84563f,-0.248908f,0.866032f,0.000126604f,
1.72348f,0.535568f,1.86566f,-0.268475f,0.865353f,0.00014797f, 1.72394f,0.576122f,1.88719f,-0.288138f,0.864612f,0.000173392f,
1.72546f,0.61731f,1.91013f,-0.30788f,0.863828f,0.000203655f, 1.72835f,0.659315f,1.93469f,-0.327718f,0.862984f,0.000239582f,
1.73108f,0.702246f,1.96159f,-0.347666f,0.862075f,0.000282222f, 1.73439f,0.746556f,1.99028f,-0.367729f,0.861096f,0.000332803f,
1.74063f,0.793392f,2.02032f,-0.387882f,0.860067f,0.000392768f, 1.73665f,0.83647f,2.05231f,-0.408139f,0.858976f,0.000463807f,
1.73624f,0.882349f,2.08876f,-0.42851f,0.857817f,0.000547881f, 1.73419f,0.928267f,2.12711f,-0.448999f,0.856585f,0.000647298f,
1.73532f,0.976916f,2.16692f,-0.469601f,0.85528f,0.000764737f, 1.73695f,1.02693f,2.20867f,-0.490288f,0.853918f,0.00090331f,
1.74712f,1.08336f,2.25026f,-0.511068f,0.852486f,0.00106659f, 1.74861f,1.13574f,2.2962f,-0.531944f,0.850981f,0.00125876f,
1.73169f,1.17736f,2.35121f,-0.552909f,0.849399f,0.00148454f, 1.73879f,1.23583f,2.40337f,-0.573954f,0.847738f,0.00174941f,
1.72684f,1.28231f,2.46379f,-0.595048f,0.846007f,0.0020596f, 1.72148f,1.33435f,2.52427f,-0.616163f,0.844215f,0.00242215f,
1.74025f,1.40611f,2.57954f,-0.637292f,0.842352f,0.00284509f, 1.71486f,1.4451f,2.65419f,-0.658414f,0.840417f,0.00333742f,
1.71158f,1.50249f,2.72681f,-0.679505f,0.838414f,0.00390938f, 1.7234f,1.57447f,2.79377f,-0.700523f,0.836341f,0.00457199f,
1.70662f,1.62305f,2.87709f,-0.721425f,0.834211f,0.00533802f, 1.68949f,1.67161f,2.96498f,-0.742133f,0.832049f,0.00622147f,
1.68679f,1.73486f,3.05005f,-0.762605f,0.829852f,0.00723743f, 1.70997f,1.82576f,3.12593f,-0.782786f,0.827629f,0.00840265f,
1.68589f,1.87045f,3.22779f,-0.802604f,0.825396f,0.00973547f, 1.65413f,1.90635f,3.33971f,-0.821974f,0.823169f,0.0112553f,
1.65734f,1.98121f,3.43684f,-0.840803f,0.820974f,0.0129837f, 1.64141f,2.03523f,3.54749f,-0.858956f,0.818849f,0.0149429f,
1.61274f,2.07276f,3.66883f,-0.876289f,0.81685f,0.0171574f, 1.60568f,2.13672f,3.78181f,-0.892693f,0.815008f,0.0196523f,
1.58614f,2.18467f,3.9067f,-0.908024f,0.813374f,0.0224546f, 1.59487f,2.2696f,4.01272f,-0.922123f,0.812014f,0.0255924f,
1.54687f,2.27569f,4.1619f,-0.934812f,0.811005f,0.0290951f, 1.51949f,2.30645f,4.29577f,-0.945838f,0.810473f,0.0329934f,
1.52223f,2.3799f,4.40117f,-0.954988f,0.810553f,0.0373198f, 1.47352f,2.37118f,4.56164f,-0.962105f,0.811356f,0.0421084f,
1.44087f,2.38072f,4.69775f,-0.96698f,0.813035f,0.0473957f, 1.42746f,2.41627f,4.82094f,-0.969281f,0.815839f,0.0532211f,
1.38228f,2.39381f,4.96358f,-0.968833f,0.820018f,0.0596285f, 1.37495f,2.42662f,5.05193f,-0.965515f,0.825761f,0.0666672f,
1.31309f,2.36053f,5.2083f,-0.958923f,0.833558f,0.0743935f, 1.29964f,2.36853f,5.2949f,-0.949102f,0.843624f,0.082873f,
1.24517f,2.29191f,5.41234f,-0.935856f,0.856535f,0.0921883f, 1.22117f,2.26262f,5.50265f,-0.919064f,0.872833f,0.102435f,
1.15518f,2.1489f,5.61985f,-0.898752f,0.89316f,0.113732f, 1.11775f,2.07785f,5.69848f,-0.874847f,0.918782f,0.126254f,
1.07471f,1.98852f,5.76026f,-0.847488f,0.951457f,0.140296f, 1.0337f,1.89652f,5.76898f,-0.817437f,0.997854f,0.156274f,
1.64424f,5.84738e-07f,1.64424f,-2.79877e-17f,0.854743f,3.64287e-05f, 1.64419f,0.0351581f,1.64487f,-0.0185201f,0.854729f,3.68396e-05f,
1.64408f,0.0703308f,1.6468f,-0.0370097f,0.854653f,3.7986e-05f, 1.64389f,0.105565f,1.65001f,-0.0555603f,0.854529f,3.99625e-05f,
1.64366f,0.140865f,1.65451f,-0.0740826f,0.85436f,4.2789e-05f, 1.6434f,0.176285f,1.6603f,-0.0926588f,0.854142f,4.65852e-05f,
1.64298f,0.211812f,1.66747f,-0.111248f,0.853866f,5.14008e-05f, 1.64249f,0.247489f,1.67593f,-0.129871f,0.853554f,5.74457e-05f,
1.64218f,0.283379f,1.68571f,-0.14854f,0.853176f,6.48172e-05f, 1.64208f,0.319511f,1.69684f,-0.167245f,0.852756f,7.37787e-05f,
1.64228f,0.355939f,1.70935f,-0.185995f,0.852287f,8.45707e-05f, 1.64292f,0.392731f,1.72316f,-0.204808f,0.851755f,9.74723e-05f,
1.64312f,0.429714f,1.7379f,-0.223674f,0.851176f,0.000112899f, 1.64346f,0.467037f,1.75446f,-0.242594f,0.850549f,0.00013126f,
1.64464f,0.504875f,1.77263f,-0.261586f,0.849859f,0.000153061f, 1.64604f,0.543032f,1.792f,-0.280652f,0.849109f,0.000178934f,
1.64901f,0.58181f,1.81261f,-0.299776f,0.848315f,0.000209627f, 1.65251f,0.621591f,1.8351f,-0.318976f,0.847461f,0.000245967f,
1.65363f,0.661593f,1.86031f,-0.33826f,0.846541f,0.00028896f, 1.65538f,0.702711f,1.88714f,-0.357622f,0.845562f,0.000339793f,
1.65677f,0.7444f,1.91409f,-0.377044f,0.844531f,0.000399843f, 1.65656f,0.786338f,1.94366f,-0.396547f,0.843437f,0.000470742f,
1.65795f,0.83004f,1.97565f,-0.416133f,0.842276f,0.000554355f, 1.65821f,0.874f,2.00914f,-0.435797f,0.841047f,0.000652869f,
1.65983f,0.919643f,2.04467f,-0.45551f,0.839765f,0.000768822f, 1.66201f,0.966628f,2.08182f,-0.475284f,0.838421f,0.000905136f,
1.65801f,1.01083f,2.12284f,-0.495117f,0.837007f,0.00106517f, 1.65491f,1.05643f,2.16591f,-0.515004f,0.835524f,0.00125279f,
1.65427f,1.10447f,2.21179f,-0.534927f,0.833977f,0.0014725f, 1.65265f,1.15287f,2.25894f,-0.55485f,0.832376f,0.00172928f,
1.65329f,1.20381f,2.30856f,-0.574774f,0.830715f,0.0020289f, 1.6496f,1.2527f,2.36078f,-0.594686f,0.828991f,0.00237793f,
1.64266f,1.3002f,2.41917f,-0.614563f,0.827204f,0.00278362f, 1.63974f,1.35166f,2.4785f,-0.634381f,0.825359f,0.00325433f,
1.64607f,1.41177f,2.53822f,-0.654079f,0.823477f,0.00379934f, 1.65723f,1.47654f,2.57594f,-0.673625f,0.821557f,0.00442877f,
1.63936f,1.51985f,2.66818f,-0.692996f,0.819604f,0.00515435f, 1.61756f,1.55842f,2.74801f,-0.712139f,0.817623f,0.00598846f,
1.61511f,1.61537f,2.82154f,-0.731005f,0.815627f,0.0069451f, 1.63732f,1.69752f,2.88615f,-0.74953f,0.813629f,0.00803951f,
1.61237f,1.73479f,2.97463f,-0.767604f,0.81167f,0.00928814f, 1.58228f,1.76538f,3.07262f,-0.785165f,0.809763f,0.010709f,
1.58112f,1.82691f,3.15688f,-0.802134f,0.80793f,0.0123213f, 1.58434f,1.89389f,3.23832f,-0.81842f,0.806202f,0.0141459f,
1.58059f,1.95418f,3.32749f,-0.833913f,0.804617f,0.0162048f, 1.53599f,1.96454f,3.44785f,-0.848477f,0.803229f,0.0185217f,
1.55035f,2.04589f,3.53008f,-0.861934f,0.802121f,0.0211216f, 1.52702f,2.0795f,3.63575f,-0.874181f,0.801346f,0.0240308f,
1.48067f,2.07948f,3.75775f,-0.885079f,0.800975f,0.0272774f, 1.48011f,2.13875f,3.85358f,-0.894469f,0.801101f,0.030891f,
1.4398f,2.13906f,3.97645f,-0.902106f,0.801874f,0.034903f, 1.44705f,2.20484f,4.06124f,-0.907825f,0.803437f,0.0393474f,
1.39603f,2.18004f,4.18968f,-0.91151f,0.805912f,0.0442605f, 1.36027f,2.1719f,4.30451f,-0.912911f,0.80951f,0.0496826f,
1.34285f,2.18685f,4.4047f,-0.91183f,0.814499f,0.0556579f, 1.33748f,2.21592f,4.48046f,-0.908183f,0.821054f,0.0622369f,
1.28409f,2.1626f,4.58755f,-0.901708f,0.829599f,0.0694777f, 1.27073f,2.16303f,4.6604f,-0.892332f,0.840413f,0.0774475f,
1.20695f,2.07209f,4.77418f,-0.879966f,0.853944f,0.0862266f, 1.18382f,2.04283f,4.84714f,-0.864519f,0.870766f,0.0959159f,
1.13193f,1.95747f,4.93868f,-0.845971f,0.891587f,0.106643f, 1.09978f,1.89912f,4.98649f,-0.824295f,0.917434f,0.118585f,
1.06226f,1.82533f,5.03833f,-0.799462f,0.950464f,0.132047f, 1.00584f,1.7112f,5.05242f,-0.772134f,0.997777f,0.147532f,
1.57087f,-6.76103e-07f,1.57087f,-7.521e-17f,0.838358f,3.82686e-05f, 1.57085f,0.0331863f,1.57147f,-0.0180148f,0.838325f,3.86419e-05f,
1.57072f,0.0664084f,1.57325f,-0.0360664f,0.838251f,3.98469e-05f, 1.57048f,0.099651f,1.5762f,-0.0540892f,0.838129f,4.18782e-05f,
1.57014f,0.132978f,1.58036f,-0.0721577f,0.837952f,4.48083e-05f, 1.56971f,0.166373f,1.58568f,-0.0902151f,0.837734f,4.871e-05f,
1.56928f,0.19988f,1.59221f,-0.108309f,0.837459f,5.36903e-05f, 1.5689f,0.233531f,1.59995f,-0.126428f,0.837137f,5.9896e-05f,
1.56867f,0.267353f,1.60887f,-0.144564f,0.836765f,6.74766e-05f, 1.56876f,0.301416f,1.61901f,-0.162754f,0.836336f,7.66738e-05f,
1.5693f,0.335759f,1.63036f,-0.180961f,0.835864f,8.77152e-05f, 1.57355f,0.371068f,1.64327f,-0.199208f,0.835336f,0.000100901f,
1.57119f,0.405291f,1.65619f,-0.217514f,0.834751f,0.000116622f, 1.57227f,0.440472f,1.67111f,-0.235848f,0.834122f,0.000135291f,
1.5729f,0.475824f,1.68788f,-0.25423f,0.833436f,0.000157404f, 1.57331f,0.511323f,1.70578f,-0.272673f,0.832689f,0.000183571f,
1.57589f,0.547584f,1.7247f,-0.291153f,0.831894f,0.000214508f, 1.57883f,0.584716f,1.74545f,-0.309684f,0.831047f,0.000251047f,
1.58199f,0.622822f,1.76786f,-0.328273f,0.830137f,0.000294145f, 1.58575f,0.662113f,1.79158f,-0.346915f,0.829169f,0.000344937f,
1.58701f,0.701197f,1.81584f,-0.365591f,0.828152f,0.00040475f, 1.58748f,0.740782f,1.84201f,-0.384315f,0.827076f,0.000475117f,
1.60302f,0.788844f,1.86802f,-0.403092f,0.825937f,0.000557829f, 1.58843f,0.822339f,1.9017f,-0.421905f,0.82474f,0.000654944f,
1.58842f,0.864016f,1.9348f,-0.440736f,0.823494f,0.000768852f, 1.602f,0.914153f,1.96548f,-0.459593f,0.822189f,0.000902299f,
1.58891f,0.94987f,2.00326f,-0.478473f,0.820823f,0.00105845f, 1.58755f,0.993053f,2.04075f,-0.497364f,0.819397f,0.0012409f,
1.58693f,1.03753f,2.08139f,-0.516225f,0.817926f,0.00145373f, 1.5849f,1.08182f,2.12407f,-0.535058f,0.816405f,0.00170169f,
1.58463f,1.12815f,2.169f,-0.553853f,0.814832f,0.00199005f, 1.5799f,1.1721f,2.21627f,-0.57259f,0.813207f,0.0023248f,
1.57534f,1.21692f,2.26622f,-0.591238f,0.81154f,0.00271271f, 1.57356f,1.2646f,2.31751f,-0.609744f,0.809845f,0.00316125f,
1.5807f,1.32026f,2.36819f,-0.628102f,0.808124f,0.00367912f, 1.58994f,1.37903f,2.42055f,-0.646275f,0.806379f,0.00427556f,
1.5713f,1.41753f,2.48067f,-0.664224f,0.804615f,0.00496091f, 1.55314f,1.45243f,2.55079f,-0.681901f,0.802851f,0.00574682f,
1.5497f,1.50256f,2.61542f,-0.699219f,0.801115f,0.00664589f, 1.56439f,1.57085f,2.67512f,-0.716141f,0.799415f,0.00767201f,
1.53886f,1.60081f,2.75128f,-0.732608f,0.797768f,0.00884014f, 1.52004f,1.63665f,2.82754f,-0.748553f,0.796197f,0.0101669f,
1.51388f,1.68564f,2.90256f,-0.763892f,0.794728f,0.0116696f, 1.53451f,1.76559f,2.96235f,-0.778489f,0.793423f,0.0133676f,
1.50166f,1.78318f,3.05597f,-0.792272f,0.792315f,0.0152813f, 1.47282f,1.80503f,3.14571f,-0.805147f,0.791442f,0.0174324f,
1.46955f,1.85579f,3.22474f,-0.817008f,0.790861f,0.0198447f, 1.48879f,1.93341f,3.28877f,-0.827707f,0.790649f,0.0225428f,
1.44776f,1.9349f,3.39008f,-0.837066f,0.790915f,0.0255535f, 1.40819f,1.93389f,3.49136f,-0.845007f,0.791729f,0.0289055f,
1.40885f,1.98324f,3.56843f,-0.851404f,0.793188f,0.0326293f, 1.3675f,1.97183f,3.66967f,-0.856005f,0.795473f,0.0367582f,
1.36879f,2.01639f,3.742f,-0.858728f,0.79872f,0.0413285f, 1.3201f,1.98464f,3.84826f,-0.85945f,0.803074f,0.0463803f,
1.31394f,2.01024f,3.92047f,-0.857912f,0.808833f,0.0519586f, 1.26452f,1.96531f,4.01464f,-0.854103f,0.81615f,0.0581144f,
1.24859f,1.96493f,4.08606f,-0.847826f,0.825392f,0.0649063f, 1.23554f,1.96483f,4.13682f,-0.838962f,0.836887f,0.0724036f,
1.18126f,1.89156f,4.22462f,-0.827472f,0.851034f,0.0806882f, 1.15817f,1.86284f,4.28512f,-0.81329f,0.868361f,0.089862f,
1.13402f,1.82502f,4.33845f,-0.796331f,0.889601f,0.100055f, 1.07106f,1.71949f,4.4038f,-0.776617f,0.915889f,0.111457f,
1.03823f,1.65702f,4.44283f,-0.754021f,0.949359f,0.124376f, 1.00226f,1.58289f,4.43089f,-0.729098f,0.997692f,0.139397f,
1.50419f,-1.81163e-07f,1.50419f,-2.18215e-17f,0.820992f,3.9958e-05f, 1.50415f,0.0313359f,1.50474f,-0.0175162f,0.820945f,4.03186e-05f,
1.50395f,0.0626877f,1.50635f,-0.0350214f,0.820883f,4.15743e-05f, 1.50366f,0.0940743f,1.50906f,-0.0525448f,0.82075f,4.36435e-05f,
1.50326f,0.125512f,1.51283f,-0.0700711f,0.820588f,4.66711e-05f, 1.50282f,0.157019f,1.5177f,-0.0876128f,0.820362f,5.06585e-05f,
1.50242f,0.188625f,1.52365f,-0.105168f,0.820095f,5.57721e-05f, 1.50217f,0.22036f,1.53068f,-0.12274f,0.819776f,6.21168e-05f,
1.50221f,0.252272f,1.5388f,-0.140336f,0.819402f,6.98578e-05f, 1.50267f,0.284399f,1.548f,-0.157948f,0.818988f,7.92395e-05f,
1.50245f,0.316618f,1.55859f,-0.175595f,0.818514f,9.04739e-05f, 1.50308f,0.349126f,1.56974f,-0.193257f,0.817994f,0.000103868f,
1.50397f,0.381882f,1.58213f,-0.210948f,0.817424f,0.000119787f, 1.50476f,0.414807f,1.59566f,-0.228682f,0.816797f,0.000138659f,
1.51198f,0.449217f,1.61132f,-0.246429f,0.816127f,0.000160961f, 1.5091f,0.481569f,1.62608f,-0.26421f,0.815402f,0.000187277f,
1.51271f,0.515878f,1.64346f,-0.282031f,0.814618f,0.000218295f, 1.51649f,0.551162f,1.66244f,-0.299867f,0.813792f,0.000254817f,
1.51979f,0.587104f,1.68266f,-0.317732f,0.812911f,0.000297769f, 1.5227f,0.623763f,1.70428f,-0.335633f,0.811971f,0.000348241f,
1.52559f,0.661188f,1.72627f,-0.353548f,0.810985f,0.000407495f, 1.52225f,0.696381f,1.75092f,-0.371475f,0.80995f,0.000476985f,
1.52304f,0.734105f,1.7762f,-0.389423f,0.808859f,0.000558401f, 1.52446f,0.772925f,1.8036f,-0.407384f,0.807712f,0.000653688f,
1.52581f,0.812381f,1.83251f,-0.425329f,0.806524f,0.000765084f, 1.5274f,0.852613f,1.86223f,-0.443263f,0.805287f,0.000895155f,
1.52699f,0.892458f,1.89316f,-0.461183f,0.803997f,0.00104682f, 1.52362f,0.931136f,1.92804f,-0.479077f,0.802659f,0.00122348f,
1.52358f,0.972447f,1.96432f,-0.496904f,0.801287f,0.00142891f, 1.5218f,1.01329f,2.00208f,-0.514666f,0.799875f,0.00166744f,
1.52299f,1.05671f,2.04102f,-0.532351f,0.798423f,0.00194398f, 1.51985f,1.09798f,2.08128f,-0.549939f,0.796934f,0.00226402f,
1.51578f,1.1392f,2.12465f,-0.567376f,0.79543f,0.00263375f, 1.51178f,1.18098f,2.1716f,-0.584646f,0.793908f,0.00306006f,
1.51433f,1.22835f,2.21728f,-0.60173f,0.792376f,0.00355081f, 1.52184f,1.28078f,2.26381f,-0.618593f,0.790837f,0.00411445f,
1.50261f,1.31193f,2.31919f,-0.635188f,0.789309f,0.00476059f, 1.49253f,1.35051f,2.37415f,-0.651445f,0.787818f,0.00549965f,
1.48925f,1.39528f,2.43032f,-0.667337f,0.786369f,0.00634322f, 1.50618f,1.45911f,2.47897f,-0.682815f,0.784979f,0.0073039f,
1.47241f,1.47613f,2.54684f,-0.697822f,0.783666f,0.00839547f, 1.46217f,1.51477f,2.60905f,-0.712263f,0.782473f,0.00963304f,
1.45436f,1.55539f,2.67586f,-0.726058f,0.781434f,0.0110327f, 1.45698f,1.60683f,2.73663f,-0.739154f,0.780574f,0.0126123f,
1.45473f,1.65311f,2.7977f,-0.751471f,0.779933f,0.0143905f, 1.44598f,1.69586f,2.84882f,-0.762895f,0.779566f,0.0163879f,
1.40943f,1.69747f,2.94469f,-0.773292f,0.779557f,0.0186266f, 1.40765f,1.74186f,3.01439f,-0.7826f,0.779951f,0.02113f,
1.38124f,1.75405f,3.09149f,-0.790723f,0.780818f,0.0239237f, 1.39302f,1.81219f,3.14708f,-0.797467f,0.782288f,0.0270352f,
1.34113f,1.78689f,3.23814f,-0.802752f,0.78446f,0.0304943f, 1.33454f,1.81669f,3.30375f,-0.8065f,0.787427f,0.0343337f,
1.30043f,1.80557f,3.38303f,-0.80846f,0.791409f,0.0385895f, 1.28898f,1.82179f,3.44982f,-0.808657f,0.7965f,0.0433014f,
1.28605f,1.84597f,3.50617f,-0.806819f,0.802983f,0.0485146f, 1.23191f,1.79373f,3.59167f,-0.802967f,0.811015f,0.0542803f,
1.22057f,1.79768f,3.64202f,-0.796946f,0.820922f,0.0606576f, 1.20783f,1.79392f,3.68648f,-0.788626f,0.833048f,0.0677163f,
1.15032f,1.71745f,3.7629f,-0.777993f,0.847761f,0.0755405f, 1.1265f,1.68645f,3.81705f,-0.764924f,0.865634f,0.0842329f,
1.08489f,1.62426f,3.87232f,-0.749445f,0.887387f,0.0939303f, 1.05726f,1.57839f,3.90113f,-0.731449f,0.91418f,0.104824f,
1.02527f,1.52109f,3.9303f,-0.710867f,0.948251f,0.117244f, 0.984945f,1.44475f,3.91422f,-0.688113f,0.9976f,0.131829f,
1.44353f,1.35137e-06f,1.44352f,5.94622e-17f,0.80269f,4.14761e-05f, 1.44346f,0.0295782f,1.44402f,-0.0169658f,0.80266f,4.18812e-05f,
1.44324f,0.0591632f,1.4455f,-0.0339215f,0.802591f,4.31452e-05f, 1.44294f,0.0887774f,1.44796f,-0.0508883f,0.802466f,4.52697e-05f,
1.44255f,0.118442f,1.45139f,-0.067862f,0.802305f,4.8352e-05f, 1.44196f,0.148146f,1.45588f,-0.0848422f,0.802085f,5.2421e-05f,
1.44144f,0.177939f,1.46133f,-0.101827f,0.801827f,5.76265e-05f, 1.44108f,0.207836f,1.46773f,-0.118834f,0.801513f,6.40793e-05f,
1.44097f,0.237854f,1.4751f,-0.135836f,0.801157f,7.19485e-05f, 1.44126f,0.268053f,1.48348f,-0.152867f,0.800746f,8.14429e-05f,
1.4421f,0.298466f,1.49285f,-0.169901f,0.800295f,9.28216e-05f, 1.44345f,0.329098f,1.50283f,-0.186952f,0.799792f,0.000106351f,
1.44478f,0.359868f,1.5139f,-0.204021f,0.799237f,0.000122385f, 1.44635f,0.390768f,1.52604f,-0.221095f,0.79864f,0.00014134f,
1.46147f,0.423746f,1.53885f,-0.238196f,0.797989f,0.0001637f, 1.45224f,0.453433f,1.55335f,-0.255302f,0.797294f,0.000190024f,
1.45402f,0.485406f,1.56983f,-0.272417f,0.796552f,0.000220964f, 1.45799f,0.518745f,1.58797f,-0.289551f,0.795755f,0.000257286f,
1.4593f,0.551668f,1.60609f,-0.30668f,0.794918f,0.000299885f, 1.46181f,0.585805f,1.62562f,-0.323812f,0.794033f,0.000349787f,
1.47124f,0.62365f,1.64483f,-0.340952f,0.793095f,0.000408193f, 1.46459f,0.654739f,1.66627f,-0.358076f,0.792117f,0.000476481f,
1.4659f,0.690138f,1.68892f,-0.375182f,0.791097f,0.00055624f, 1.46832f,0.726731f,1.71329f,-0.392275f,0.790028f,0.000649298f,
1.46797f,0.762549f,1.7402f,-0.40934f,0.788917f,0.000757748f, 1.46737f,0.798711f,1.768f,-0.426351f,0.787773f,0.000883991f,
1.46694f,0.835453f,1.79545f,-0.443315f,0.78659f,0.00103076f, 1.46606f,0.872443f,1.82469f,-0.460222f,0.785366f,0.00120114f,
1.46725f,0.911257f,1.85602f,-0.477038f,0.784118f,0.0013987f, 1.4661f,0.949219f,1.88874f,-0.493749f,0.782846f,0.00162739f,
1.46423f,0.987275f,1.92506f,-0.510346f,0.781549f,0.00189172f, 1.46131f,1.02492f,1.96025f,-0.526814f,0.780231f,0.00219679f,
1.45638f,1.06172f,1.99897f,-0.543098f,0.778912f,0.00254818f, 1.45474f,1.10114f,2.03838f,-0.559185f,0.777596f,0.00295239f,
1.45435f,1.14206f,2.07907f,-0.575051f,0.776286f,0.00341633f, 1.45314f,1.18286f,2.1222f,-0.590668f,0.774991f,0.00394793f,
1.4441f,1.21763f,2.16691f,-0.605973f,0.773736f,0.00455586f, 1.46888f,1.27488f,2.18677f,-0.620927f,0.772536f,0.00524975f,
1.43496f,1.29495f,2.26073f,-0.635499f,0.771402f,0.00604012f, 1.43301f,1.33617f,2.31033f,-0.649643f,0.77035f,0.00693851f,
1.44891f,1.39394f,2.35401f,-0.66328f,0.769415f,0.00795754f, 1.42067f,1.41102f,2.4129f,-0.676345f,0.768632f,0.00911118f,
1.40213f,1.43585f,2.4695f,-0.688792f,0.768021f,0.0104143f, 1.39635f,1.47271f,2.52411f,-0.700559f,0.767614f,0.0118831f,
1.40253f,1.52147f,2.57475f,-0.711535f,0.767473f,0.0135354f, 1.39698f,1.55748f,2.62894f,-0.721638f,0.767652f,0.0153903f,
1.38518f,1.58586f,2.6879f,-0.730816f,0.768192f,0.0174685f, 1.34619f,1.58176f,2.75897f,-0.738967f,0.769163f,0.0197925f,
1.34172f,1.61405f,2.81478f,-0.745942f,0.770675f,0.0223865f, 1.3521f,1.66479f,2.85006f,-0.751712f,0.772784f,0.025277f,
1.32081f,1.65986f,2.92955f,-0.756134f,0.775611f,0.0284932f, 1.28803f,1.6526f,2.99252f,-0.759098f,0.779293f,0.032067f,
1.26442f,1.65154f,3.05725f,-0.760536f,0.783941f,0.0360338f, 1.2581f,1.67053f,3.10838f,-0.760301f,0.78976f,0.0404331f,
1.21942f,1.64166f,3.17324f,-0.75831f,0.796916f,0.04531f, 1.20266f,1.63871f,3.22564f,-0.754503f,0.805627f,0.0507157f,
1.19351f,1.64254f,3.26585f,-0.748764f,0.816181f,0.0567095f, 1.15098f,1.59545f,3.32063f,-0.740998f,0.828906f,0.0633618f,
1.12775f,1.56986f,3.36692f,-0.731131f,0.844219f,0.0707574f, 1.10174f,1.53634f,3.41361f,-0.71916f,0.862635f,0.0790023f,
1.07975f,1.50516f,3.44668f,-0.704999f,0.884872f,0.0882337f, 1.05461f,1.45973f,3.47509f,-0.688586f,0.912176f,0.098652f,
1.00444f,1.38548f,3.49626f,-0.6698f,0.946978f,0.110606f, 0.966326f,1.31656f,3.47479f,-0.648988f,0.997501f,0.12479f,
1.38825f,7.03418e-07f,1.38826f,-6.12136e-17f,0.783539f,4.28626e-05f, 1.38817f,0.0278927f,1.3887f,-0.016382f,0.78351f,4.3274e-05f,
1.38792f,0.0557939f,1.39004f,-0.0327605f,0.783445f,4.45594e-05f, 1.38749f,0.0837111f,1.39228f,-0.0491382f,0.783327f,4.67187e-05f,
1.38693f,0.111662f,1.39542f,-0.0655283f,0.783171f,4.98426e-05f, 1.38635f,0.139652f,1.39942f,-0.0819132f,0.782966f,5.39777e-05f,
1.38586f,0.167708f,1.40434f,-0.0983024f,0.782714f,5.92364e-05f, 1.3856f,0.195848f,1.41012f,-0.114699f,0.782421f,6.5771e-05f,
1.3857f,0.224103f,1.41676f,-0.131097f,0.782081f,7.37229e-05f, 1.38632f,0.252512f,1.42429f,-0.147501f,0.781693f,8.32925e-05f,
1.38762f,0.281134f,1.43271f,-0.163903f,0.781264f,9.47297e-05f, 1.38961f,0.309916f,1.44154f,-0.180319f,0.780786f,0.000108323f,
1.38918f,0.338485f,1.4519f,-0.196726f,0.78027f,0.0001244f, 1.3909f,0.367355f,1.46283f,-0.213143f,0.779702f,0.00014335f,
1.40843f,0.398556f,1.47677f,-0.229552f,0.779095f,0.000165644f, 1.39554f,0.425665f,1.48789f,-0.245958f,0.778443f,0.000191823f,
1.39929f,0.455944f,1.50253f,-0.262367f,0.777744f,0.000222515f, 1.40363f,0.48721f,1.51823f,-0.278755f,0.777009f,0.000258456f,
1.40585f,0.518349f,1.53469f,-0.295137f,0.776229f,0.000300487f, 1.40986f,0.550822f,1.55198f,-0.311503f,0.775406f,0.000349591f,
1.41464f,0.584344f,1.57031f,-0.327837f,0.77455f,0.000406896f, 1.41121f,0.614574f,1.58929f,-0.344149f,0.773651f,0.000473708f,
1.43334f,0.658847f,1.60139f,-0.360425f,0.772714f,0.000551512f, 1.41287f,0.680443f,1.63233f,-0.376644f,0.771749f,0.000642014f,
1.41506f,0.714802f,1.65521f,-0.392816f,0.770748f,0.000747181f, 1.42539f,0.754183f,1.67811f,-0.408924f,0.769713f,0.000869213f,
1.41537f,0.782855f,1.70338f,-0.424941f,0.768661f,0.0010107f, 1.41258f,0.815806f,1.73067f,-0.440869f,0.767584f,0.00117448f,
1.41371f,0.85145f,1.75847f,-0.456698f,0.766483f,0.00136382f, 1.43109f,0.894497f,1.77818f,-0.472387f,0.765376f,0.00158238f,
1.4123f,0.921847f,1.81843f,-0.487927f,0.764265f,0.00183434f, 1.4293f,0.968812f,1.84655f,-0.503305f,0.763149f,0.0021243f,
1.41585f,0.997064f,1.88088f,-0.518494f,0.762039f,0.00245747f, 1.41651f,1.03468f,1.91498f,-0.53345f,0.760957f,0.00283978f,
1.40304f,1.06238f,1.95306f,-0.548156f,0.759901f,0.00327753f, 1.41583f,1.10973f,1.98646f,-0.562591f,0.758881f,0.00377796f,
1.41878f,1.15029f,2.02326f,-0.576701f,0.75792f,0.00434906f, 1.39675f,1.17129f,2.06653f,-0.590439f,0.757038f,0.00499956f,
1.38265f,1.19795f,2.11013f,-0.603783f,0.756246f,0.00573919f, 1.3787f,1.2327f,2.15363f,-0.616693f,0.75556f,0.00657852f,
1.38765f,1.27846f,2.19302f,-0.629082f,0.755025f,0.00752922f, 1.36292f,1.29447f,2.23965f,-0.640912f,0.754661f,0.00860393f,
1.36984f,1.33862f,2.28152f,-0.652143f,0.754494f,0.00981666f, 1.34745f,1.35455f,2.33252f,-0.662701f,0.754567f,0.0111825f,
1.33952f,1.38339f,2.38191f,-0.672487f,0.75494f,0.0127179f, 1.34328f,1.42354f,2.4268f,-0.681473f,0.755644f,0.0144409f,
1.31774f,1.43184f,2.47911f,-0.689579f,0.756739f,0.0163709f, 1.32048f,1.46625f,2.52353f,-0.696679f,0.758317f,0.0185295f,
1.28877f,1.46664f,2.57936f,-0.702755f,0.760423f,0.0209396f, 1.28109f,1.48881f,2.62675f,-0.707674f,0.763169f,0.0236272f,
1.27954f,1.51623f,2.67081f,-0.711371f,0.766653f,0.0266201f, 1.24679f,1.50453f,2.72487f,-0.713757f,0.770986f,0.0299498f,
1.24852f,1.5315f,2.76596f,-0.714749f,0.776313f,0.0336509f, 1.2353f,1.53204f,2.81103f,-0.714228f,0.7828f,0.0377625f,
1.19102f,1.50128f,2.86647f,-0.712166f,0.790608f,0.0423293f, 1.17262f,1.49392f,2.91258f,-0.708464f,0.79997f,0.0474025f,
1.16333f,1.49548f,2.94662f,-0.703029f,0.811156f,0.0530416f, 1.15134f,1.48949f,2.97743f,-0.695786f,0.824489f,0.059317f,
1.1017f,1.42916f,3.02737f,-0.686699f,0.840374f,0.0663145f, 1.07714f,1.3989f,3.06393f,-0.675754f,0.859274f,0.0741413f,
1.05648f,1.37076f,3.08981f,-0.662796f,0.882088f,0.0829397f, 1.0326f,1.33497f,3.10896f,-0.647816f,0.909935f,0.0929133f,
1.00519f,1.29006f,3.12055f,-0.630619f,0.945548f,0.104428f, 0.977591f,1.23903f,3.09207f,-0.611555f,0.997395f,0.118244f,
1.3379f,4.78461e-07f,1.33789f,1.35669e-17f,0.763609f,4.40974e-05f, 1.3378f,0.0262756f,1.33832f,-0.0157673f,0.763571f,4.44887e-05f,
1.33747f,0.0525557f,1.33951f,-0.0315361f,0.763517f,4.58032e-05f, 1.33701f,0.0788486f,1.34153f,-0.0473042f,0.763408f,4.79864e-05f,
1.33642f,0.105165f,1.34434f,-0.0630678f,0.76326f,5.11276e-05f, 1.33586f,0.131516f,1.34795f,-0.0788372f,0.763072f,5.53085e-05f,
1.33551f,0.157917f,1.35237f,-0.0946017f,0.762839f,6.06097e-05f, 1.33515f,0.184361f,1.35763f,-0.11036f,0.762566f,6.71712e-05f,
1.33486f,0.210861f,1.36372f,-0.126122f,0.762251f,7.5162e-05f, 1.33529f,0.237507f,1.37056f,-0.141877f,0.761896f,8.47691e-05f,
1.33628f,0.26428f,1.37807f,-0.157626f,0.761499f,9.62181e-05f, 1.33814f,0.291187f,1.38595f,-0.173368f,0.76106f,0.000109788f,
1.34001f,0.318121f,1.39476f,-0.189099f,0.760584f,0.000125808f, 1.34202f,0.344995f,1.40425f,-0.204825f,0.760065f,0.000144658f,
1.35308f,0.373835f,1.4161f,-0.22053f,0.759512f,0.000166787f, 1.34814f,0.399805f,1.42683f,-0.236227f,0.758914f,0.000192704f,
1.35192f,0.428299f,1.44021f,-0.251893f,0.758286f,0.000223013f, 1.35375f,0.456889f,1.45499f,-0.267539f,0.757619f,0.000258408f,
1.35523f,0.485731f,1.47066f,-0.283157f,0.756915f,0.000299693f, 1.35895f,0.515852f,1.48635f,-0.298731f,0.756182f,0.00034779f,
1.36031f,0.545481f,1.50199f,-0.314273f,0.755412f,0.000403767f, 1.36091f,0.575205f,1.51901f,-0.329759f,0.754615f,0.00046884f,
1.37273f,0.610822f,1.53711f,-0.345185f,0.753793f,0.000544413f, 1.36472f,0.637211f,1.55647f,-0.360555f,0.75294f,0.000632089f,
1.3648f,0.667938f,1.57812f,-0.375838f,0.752071f,0.000733689f, 1.36733f,0.700343f,1.59913f,-0.391031f,0.751183f,0.000851261f,
1.3884f,0.743175f,1.61894f,-0.406134f,0.750276f,0.000987172f, 1.38427f,0.773029f,1.64207f,-0.421109f,0.749364f,0.00114408f,
1.365f,0.794333f,1.66832f,-0.435952f,0.748449f,0.001325f, 1.36623f,0.827456f,1.69392f,-0.450655f,0.747529f,0.0015333f,
1.36581f,0.859914f,1.71972f,-0.465183f,0.746622f,0.0017728f, 1.37172f,0.896845f,1.74786f,-0.479515f,0.745734f,0.00204776f,
1.35961f,0.922394f,1.77718f,-0.493641f,0.744868f,0.00236295f, 1.35638f,0.953463f,1.8072f,-0.507533f,0.744037f,0.00272378f,
1.35379f,0.985199f,1.83909f,-0.521141f,0.74326f,0.00313604f, 1.35304f,1.0185f,1.87095f,-0.534458f,0.742543f,0.0036064f,
1.34821f,1.04888f,1.90541f,-0.547456f,0.741896f,0.00414212f, 1.34251f,1.07844f,1.93828f,-0.560067f,0.741353f,0.00475126f,
1.35378f,1.12139f,1.96991f,-0.572272f,0.740925f,0.00544272f, 1.33422f,1.1396f,2.00824f,-0.584042f,0.740628f,0.00622624f,
1.32982f,1.16975f,2.04583f,-0.595306f,0.7405f,0.00711257f, 1.33678f,1.20928f,2.08061f,-0.606018f,0.740572f,0.00811349f,
1.30991f,1.21856f,2.12449f,-0.616152f,0.740864f,0.00924195f, 1.31414f,1.25513f,2.16127f,-0.625627f,0.741426f,0.010512f,
1.29395f,1.26782f,2.20418f,-0.634378f,0.742307f,0.011939f, 1.28751f,1.2928f,2.24405f,-0.642385f,0.74354f,0.01354f,
1.28031f,1.31609f,2.28467f,-0.649526f,0.745204f,0.0153333f, 1.29262f,1.35779f,2.31811f,-0.655773f,0.747354f,0.0173395f,
1.26323f,1.35577f,2.36328f,-0.661054f,0.750059f,0.0195806f, 1.26095f,1.37984f,2.39942f,-0.665271f,0.753427f,0.0220814f,
1.22659f,1.36653f,2.44829f,-0.668386f,0.757532f,0.024869f, 1.21431f,1.37569f,2.48848f,-0.670301f,0.762509f,0.0279741f,
1.20681f,1.38792f,2.52685f,-0.67094f,0.768486f,0.0314308f, 1.2056f,1.4113f,2.52898f,-0.670265f,0.7756f,0.0352773f,
1.16719f,1.37569f,2.60307f,-0.668188f,0.784045f,0.0395581f, 1.16097f,1.38229f,2.63416f,-0.664625f,0.794041f,0.0443239f,
1.14068f,1.36316f,2.66084f,-0.659518f,0.805835f,0.0496341f, 1.12905f,1.36221f,2.69077f,-0.652796f,0.819763f,0.0555598f,
1.0821f,1.30764f,2.73266f,-0.644452f,0.836205f,0.062187f, 1.05928f,1.28094f,2.76215f,-0.634381f,0.855713f,0.0696247f,
1.03585f,1.25007f,2.78655f,-0.622547f,0.87908f,0.0780177f, 1.01272f,1.21749f,2.7964f,-0.608859f,0.907619f,0.0875785f,
0.983442f,1.17344f,2.8075f,-0.593148f,0.94397f,0.0986777f, 0.956097f,1.12553f,2.77266f,-0.575661f,0.997283f,0.112155f,
1.29201f,-1.05839e-06f,1.292f,-5.83758e-17f,0.742966f,4.51329e-05f, 1.29189f,0.0247192f,1.29237f,-0.0151297f,0.742943f,4.55536e-05f,
1.29156f,0.0494354f,1.29345f,-0.0302502f,0.742885f,4.68516e-05f, 1.29099f,0.0741673f,1.29527f,-0.045387f,0.74279f,4.90581e-05f,
1.29028f,0.0989012f,1.2978f,-0.0605013f,0.74266f,5.22172e-05f, 1.28958f,0.123652f,1.30105f,-0.0756201f,0.742486f,5.6397e-05f,
1.28904f,0.148432f,1.305f,-0.0907304f,0.74228f,6.17202e-05f, 1.28882f,0.173247f,1.30965f,-0.105836f,0.742035f,6.82936e-05f,
1.28902f,0.198123f,1.31502f,-0.120928f,0.741753f,7.62747e-05f, 1.28975f,0.223096f,1.32106f,-0.13601f,0.741434f,8.58523e-05f,
1.29119f,0.248177f,1.32782f,-0.151079f,0.74108f,9.72565e-05f, 1.29342f,0.273299f,1.33469f,-0.166134f,0.740691f,0.000110755f,
1.29582f,0.298357f,1.34234f,-0.181167f,0.740268f,0.000126651f, 1.29687f,0.323286f,1.35126f,-0.196182f,0.739809f,0.000145311f,
1.29849f,0.348492f,1.36134f,-0.211166f,0.739321f,0.000167161f, 1.30002f,0.373966f,1.37222f,-0.226127f,0.738796f,0.000192693f,
1.30356f,0.400342f,1.38437f,-0.241046f,0.738247f,0.000222482f, 1.30732f,0.42736f,1.39744f,-0.255936f,0.737663f,0.000257184f,
1.31061f,0.454731f,1.41116f,-0.270771f,0.737057f,0.000297557f, 1.31392f,0.482676f,1.42518f,-0.28556f,0.736423f,0.000344474f,
1.31588f,0.510418f,1.43863f,-0.300293f,0.735765f,0.000398936f, 1.31547f,0.53757f,1.45437f,-0.314953f,0.73509f,0.000462083f,
1.31712f,0.566004f,1.47134f,-0.329548f,0.734392f,0.000535219f, 1.31735f,0.594004f,1.48865f,-0.344051f,0.733684f,0.000619838f,
1.31936f,0.623222f,1.50686f,-0.358458f,0.732964f,0.000717627f, 1.32181f,0.653071f,1.52549f,-0.372769f,0.732233f,0.000830519f,
1.32282f,0.682437f,1.54526f,-0.386948f,0.731507f,0.000960684f, 1.32188f,0.711078f,1.56491f,-0.400998f,0.730781f,0.00111057f,
1.3191f,0.738765f,1.58733f,-0.414904f,0.73006f,0.00128295f, 1.32005f,0.768892f,1.60972f,-0.428633f,0.729362f,0.00148096f,
1.31854f,0.797736f,1.63298f,-0.442181f,0.728684f,0.00170809f, 1.31824f,0.827576f,1.65767f,-0.45553f,0.728035f,0.00196822f,
1.33085f,0.865628f,1.68047f,-0.468639f,0.727436f,0.00226583f, 1.3156f,0.886203f,1.70705f,-0.481502f,0.726888f,0.00260575f,
1.31201f,0.914053f,1.73444f,-0.494095f,0.726402f,0.00299341f, 1.30824f,0.941908f,1.76225f,-0.506365f,0.726004f,0.00343484f,
1.30716f,0.971599f,1.79023f,-0.518305f,0.7257f,0.00393679f, 1.30422f,0.999771f,1.81891f,-0.529885f,0.725506f,0.00450659f,
1.29744f,1.02478f,1.8489f,-0.541042f,0.725458f,0.00515254f, 1.30526f,1.0606f,1.87837f,-0.551764f,0.725566f,0.00588358f,
1.28614f,1.07567f,1.9124f,-0.562012f,0.725855f,0.00670962f, 1.28139f,1.10119f,1.94554f,-0.571711f,0.726371f,0.00764156f,
1.28127f,1.13039f,1.97697f,-0.580854f,0.727132f,0.00869151f, 1.28747f,1.16454f,2.00679f,-0.589374f,0.728181f,0.00987251f,
1.25756f,1.16548f,2.04405f,-0.597211f,0.729572f,0.0111992f, 1.26944f,1.20334f,2.07322f,-0.604347f,0.731335f,0.0126874f,
1.23969f,1.20194f,2.11175f,-0.610671f,0.733553f,0.0143547f, 1.23191f,1.21941f,2.1462f,-0.616188f,0.736263f,0.0162204f,
1.22363f,1.2351f,2.18156f,-0.620775f,0.739566f,0.0183058f, 1.23086f,1.26539f,2.2095f,-0.62444f,0.743517f,0.0206347f,
1.21387f,1.26945f,2.24168f,-0.627046f,0.748248f,0.0232335f, 1.20121f,1.27343f,2.27357f,-0.628598f,0.753836f,0.0261319f,
1.19223f,1.28244f,2.30155f,-0.629017f,0.76042f,0.0293632f, 1.15204f,1.25508f,2.34353f,-0.628208f,0.768169f,0.0329653f,
1.13649f,1.25079f,2.37752f,-0.626141f,0.77724f,0.0369819f, 1.12738f,1.25292f,2.40308f,-0.622764f,0.787839f,0.0414632f,
1.11163f,1.24233f,2.4295f,-0.618024f,0.800218f,0.0464689f, 1.10045f,1.23454f,2.4513f,-0.611809f,0.814733f,0.0520695f,
1.08671f,1.22353f,2.47198f,-0.604168f,0.831729f,0.0583523f, 1.03925f,1.16897f,2.50225f,-0.594944f,0.851834f,0.0654274f,
1.02037f,1.14552f,2.51943f,-0.584135f,0.875802f,0.0734423f, 0.99847f,1.11646f,2.52493f,-0.5716f,0.905046f,0.0826134f,
0.973367f,1.07992f,2.53395f,-0.557228f,0.942248f,0.0933248f, 0.947853f,1.03696f,2.49452f,-0.541172f,0.997165f,0.106493f,
1.25016f,-3.09861e-07f,1.25016f,-1.34594e-17f,0.72171f,4.59825e-05f, 1.25001f,0.0232044f,1.25047f,-0.014462f,0.7217f,4.64288e-05f,
1.24959f,0.0464174f,1.25144f,-0.0289298f,0.721647f,4.77241e-05f, 1.24895f,0.0696184f,1.25304f,-0.0433782f,0.721566f,4.99264e-05f,
1.2482f,0.0928316f,1.25528f,-0.0578331f,0.721451f,5.30824e-05f, 1.24753f,0.116048f,1.25816f,-0.0722797f,0.721304f,5.7266e-05f,
1.2471f,0.139263f,1.26166f,-0.0867096f,0.721126f,6.2568e-05f, 1.24706f,0.162512f,1.26577f,-0.101134f,0.720912f,6.91092e-05f,
1.24752f,0.185811f,1.27051f,-0.115535f,0.720672f,7.70512e-05f, 1.2473f,0.209065f,1.27616f,-0.129929f,0.720398f,8.65697e-05f,
1.24814f,0.232394f,1.28221f,-0.144294f,0.720098f,9.78774e-05f, 1.25311f,0.256198f,1.28945f,-0.158641f,0.719764f,0.000111226f,
1.25194f,0.278985f,1.29491f,-0.172954f,0.719406f,0.00012692f, 1.25437f,0.302213f,1.30249f,-0.187244f,0.719017f,0.000145304f,
1.25751f,0.325808f,1.31133f,-0.20149f,0.718607f,0.000166787f, 1.26051f,0.349845f,1.3213f,-0.215705f,0.718168f,0.000191834f,
1.26419f,0.374566f,1.33226f,-0.229865f,0.717711f,0.000220988f, 1.26669f,0.399484f,1.34388f,-0.243985f,0.717228f,0.000254868f,
1.26883f,0.424598f,1.35666f,-0.258038f,0.716731f,0.000294189f, 1.27037f,0.449881f,1.36961f,-0.272033f,0.716215f,0.000339774f,
1.28324f,0.480186f,1.38302f,-0.285956f,0.715686f,0.000392557f, 1.27363f,0.501171f,1.39497f,-0.299796f,0.715147f,0.000453607f,
1.27536f,0.527454f,1.40993f,-0.313555f,0.714596f,0.000524138f, 1.27661f,0.553678f,1.42481f,-0.327207f,0.714046f,0.000605539f,
1.27878f,0.580687f,1.44081f,-0.340757f,0.713493f,0.000699384f, 1.27862f,0.606781f,1.45906f,-0.354183f,0.712946f,0.000807436f,
1.2809f,0.634363f,1.47616f,-0.367472f,0.712411f,0.000931723f, 1.30119f,0.67172f,1.47674f,-0.380625f,0.711887f,0.00107452f,
1.29385f,0.694761f,1.51172f,-0.393603f,0.711392f,0.00123837f, 1.27876f,0.713293f,1.53163f,-0.406407f,0.710924f,0.00142615f,
1.2798f,0.740921f,1.55193f,-0.41902f,0.710493f,0.00164107f, 1.2791f,0.767629f,1.57222f,-0.431406f,0.710115f,0.00188674f,
1.27748f,0.793905f,1.59554f,-0.443565f,0.709791f,0.0021672f, 1.29344f,0.831308f,1.61618f,-0.455463f,0.709539f,0.00248694f,
1.27543f,0.847159f,1.63997f,-0.467071f,0.709373f,0.00285095f, 1.27029f,0.87113f,1.66348f,-0.478383f,0.7093f,0.00326476f,
1.26548f,0.895016f,1.68871f,-0.489347f,0.709348f,0.00373459f, 1.26308f,0.920486f,1.71414f,-0.499946f,0.709531f,0.00426724f,
1.25742f,0.943369f,1.74087f,-0.510159f,0.709863f,0.00487023f, 1.27909f,0.978674f,1.7475f,-0.519922f,0.710383f,0.00555191f,
1.25196f,0.992069f,1.79215f,-0.52923f,0.711104f,0.00632153f, 1.24203f,1.01003f,1.81929f,-0.538032f,0.712062f,0.00718923f,
1.23779f,1.03208f,1.84693f,-0.546278f,0.713295f,0.00816611f, 1.23353f,1.05363f,1.87417f,-0.553957f,0.714829f,0.00926469f,
1.23743f,1.08149f,1.90045f,-0.560981f,0.716727f,0.0104985f, 1.23937f,1.10695f,1.92657f,-0.567355f,0.719015f,0.0118825f,
1.20616f,1.0999f,1.95905f,-0.572974f,0.721774f,0.0134334f, 1.21379f,1.12907f,1.98369f,-0.577851f,0.72504f,0.0151696f,
1.18597f,1.12326f,2.01599f,-0.581873f,0.728914f,0.0171116f, 1.17637f,1.13322f,2.04568f,-0.585043f,0.733452f,0.0192824f,
1.16677f,1.1418f,2.07322f,-0.587289f,0.738759f,0.0217072f, 1.16008f,1.15149f,2.09949f,-0.588532f,0.744955f,0.0244151f,
1.16052f,1.16722f,2.1228f,-0.588754f,0.752148f,0.0274386f, 1.15883f,1.17888f,2.14302f,-0.587898f,0.760488f,0.0308151f,
1.11963f,1.1492f,2.17368f,-0.585906f,0.770153f,0.0345872f, 1.11357f,1.15247f,2.19312f,-0.582735f,0.781348f,0.0388054f,
1.09619f,1.14045f,2.21378f,-0.578348f,0.794312f,0.0435282f, 1.08536f,1.13317f,2.22546f,-0.572632f,0.809408f,0.0488269f,
1.04296f,1.09066f,2.25891f,-0.565618f,0.826992f,0.0547886f, 1.0228f,1.06962f,2.27553f,-0.557202f,0.847679f,0.0615252f,
1.0022f,1.04517f,2.28998f,-0.547308f,0.872336f,0.0691868f, 0.980893f,1.01868f,2.29307f,-0.535895f,0.902262f,0.0779953f,
0.953691f,0.983386f,2.29364f,-0.522733f,0.940413f,0.0883459f, 0.922237f,0.936219f,2.25211f,-0.507966f,0.997041f,0.101227f,
1.21199f,5.22822e-07f,1.21199f,-8.45133e-17f,0.699955f,4.66878e-05f, 1.21183f,0.0217432f,1.21227f,-0.0137782f,0.699937f,4.7105e-05f,
1.21141f,0.0434746f,1.21312f,-0.0275406f,0.699897f,4.8401e-05f, 1.21075f,0.0652159f,1.21454f,-0.0413151f,0.69983f,5.05965e-05f,
1.20982f,0.0869411f,1.21655f,-0.0550729f,0.699737f,5.37363e-05f, 1.20902f,0.108657f,1.2191f,-0.0688179f,0.699616f,5.78887e-05f,
1.20851f,0.130366f,1.22217f,-0.0825554f,0.699468f,6.31485e-05f, 1.20832f,0.15207f,1.22583f,-0.0962709f,0.6993f,6.96452e-05f,
1.20854f,0.17378f,1.23005f,-0.109973f,0.699103f,7.75079e-05f, 1.20927f,0.195515f,1.23477f,-0.123646f,0.698883f,8.6914e-05f,
1.21069f,0.217261f,1.24001f,-0.137295f,0.69864f,9.80688e-05f, 1.2129f,0.23899f,1.24582f,-0.150914f,0.698374f,0.000111218f,
1.21561f,0.260411f,1.25097f,-0.164497f,0.698089f,0.000126647f, 1.21837f,0.282003f,1.25771f,-0.178044f,0.697783f,0.000144688f,
1.21808f,0.303669f,1.26619f,-0.191544f,0.69746f,0.000165724f, 1.22071f,0.32581f,1.27515f,-0.204999f,0.69712f,0.000190197f,
1.22322f,0.348384f,1.28496f,-0.218396f,0.696767f,0.000218615f, 1.22591f,0.371365f,1.29545f,-0.231735f,0.6964f,0.000251567f,
1.23369f,0.396556f,1.30755f,-0.245007f,0.696023f,0.000289721f, 1.23227f,0.418707f,1.31818f,-0.258203f,0.69564f,0.000333847f,
1.23566f,0.442987f,1.33002f,-0.27132f,0.695251f,0.00038482f, 1.2374f,0.466868f,1.34129f,-0.284343f,0.694864f,0.000443638f,
1.23628f,0.489774f,1.35419f,-0.297274f,0.694476f,0.000511428f, 1.23673f,0.513606f,1.36884f,-0.310086f,0.694099f,0.000589487f,
1.23765f,0.53765f,1.3826f,-0.322789f,0.69373f,0.000679274f, 1.23935f,0.562369f,1.39759f,-0.335353f,0.693381f,0.000782426f,
1.24138f,0.587453f,1.41274f,-0.347777f,0.693054f,0.000900808f, 1.25501f,0.618855f,1.42778f,-0.360047f,0.692753f,0.00103651f,
1.24178f,0.63623f,1.44346f,-0.372138f,0.692493f,0.00119188f, 1.26246f,0.67232f,1.44237f,-0.384054f,0.692271f,0.00136957f,
1.23874f,0.683496f,1.47891f,-0.395756f,0.692108f,0.00157257f, 1.23928f,0.708349f,1.49716f,-0.407241f,0.692006f,0.00180418f,
1.23621f,0.731124f,1.51654f,-0.418489f,0.691976f,0.00206807f, 1.23637f,0.755799f,1.53574f,-0.429468f,0.692037f,0.00236842f,
1.25003f,0.78634f,1.55481f,-0.440176f,0.692192f,0.00270981f, 1.23269f,0.80213f,1.57518f,-0.450565f,0.692468f,0.00309734f,
1.22723f,0.822669f,1.59709f,-0.460629f,0.692875f,0.00353674f, 1.22434f,0.844753f,1.6184f,-0.470339f,0.693431f,0.00403425f,
1.2227f,0.867458f,1.64012f,-0.479653f,0.694166f,0.00459694f, 1.22954f,0.896205f,1.66106f,-0.488565f,0.69509f,0.00523242f,
1.22274f,0.914737f,1.68326f,-0.497014f,0.696248f,0.00594937f, 1.20862f,0.926827f,1.70644f,-0.504996f,0.697653f,0.00675714f,
1.21227f,0.952358f,1.72845f,-0.512453f,0.699351f,0.00766629f, 1.1976f,0.962195f,1.7523f,-0.519366f,0.701372f,0.00868832f,
1.19242f,0.979278f,1.77565f,-0.525685f,0.703765f,0.00983616f, 1.18597f,0.994614f,1.7997f,-0.531383f,0.706572f,0.0111239f,
1.18321f,1.01193f,1.82402f,-0.536399f,0.709858f,0.0125675f, 1.18119f,1.02901f,1.84647f,-0.540724f,0.713669f,0.0141844f,
1.15693f,1.02528f,1.87001f,-0.544272f,0.718094f,0.0159942f, 1.14905f,1.03446f,1.89388f,-0.547033f,0.723201f,0.0180191f,
1.15311f,1.05393f,1.91363f,-0.548962f,0.729079f,0.0202836f, 1.12443f,1.04087f,1.93986f,-0.550005f,0.735841f,0.0228158f,
1.11392f,1.04318f,1.96228f,-0.550111f,0.743613f,0.0256475f, 1.10306f,1.04386f,1.98206f,-0.549243f,0.752535f,0.0288154f,
1.08918f,1.03984f,2.00428f,-0.547348f,0.762782f,0.0323616f, 1.0779f,1.03645f,2.02022f,-0.544379f,0.774566f,0.0363355f,
1.06506f,1.02976f,2.03836f,-0.540329f,0.788122f,0.0407959f, 1.05475f,1.02342f,2.05322f,-0.535097f,0.803797f,0.0458137f,
1.04209f,1.01298f,2.0662f,-0.528675f,0.821993f,0.0514766f, 1.02694f,0.99492f,2.08027f,-0.52099f,0.843322f,0.0578975f,
1.0092f,0.979845f,2.08398f,-0.511991f,0.868625f,0.0652293f, 0.970891f,0.936427f,2.0868f,-0.501532f,0.89942f,0.0736998f,
0.94759f,0.907387f,2.08402f,-0.489496f,0.938622f,0.0837189f, 0.923825f,0.870568f,2.04411f,-0.475935f,0.996912f,0.0963293f,
1.17716f,-9.88475e-07f,1.17716f,1.54407e-18f,0.677779f,4.71913e-05f, 1.17699f,0.0203091f,1.17741f,-0.0130614f,0.67776f,4.7598e-05f,
1.17648f,0.0406217f,1.17815f,-0.026131f,0.677732f,4.88886e-05f, 1.17571f,0.0609197f,1.17938f,-0.0391818f,0.677684f,5.10644e-05f,
1.17484f,0.0812043f,1.18111f,-0.0522287f,0.677611f,5.41673e-05f, 1.17406f,0.101461f,1.18334f,-0.0652609f,0.677521f,5.82762e-05f,
1.17359f,0.1217f,1.18604f,-0.0782777f,0.677415f,6.34842e-05f, 1.17352f,0.141913f,1.18923f,-0.0912786f,0.677287f,6.98917e-05f,
1.17391f,0.162121f,1.19289f,-0.104248f,0.677144f,7.76418e-05f, 1.17419f,0.182284f,1.19721f,-0.117195f,0.676982f,8.68981e-05f,
1.17484f,0.2024f,1.20204f,-0.13011f,0.676806f,9.78604e-05f, 1.17616f,0.222485f,1.2072f,-0.142988f,0.676616f,0.000110762f,
1.18361f,0.242798f,1.21319f,-0.155831f,0.676411f,0.000125873f, 1.1807f,0.262202f,1.21768f,-0.168622f,0.676197f,0.000143504f,
1.18313f,0.2823f,1.22446f,-0.181369f,0.675971f,0.000164018f, 1.19063f,0.303922f,1.23388f,-0.194054f,0.67574f,0.000187835f,
1.18889f,0.323802f,1.24123f,-0.206684f,0.675499f,0.000215432f, 1.19217f,0.345232f,1.25064f,-0.219239f,0.67526f,0.000247364f,
1.19354f,0.366484f,1.2609f,-0.231727f,0.675015f,0.000284254f, 1.19464f,0.387788f,1.27177f,-0.244126f,0.674777f,0.000326825f,
1.1978f,0.410009f,1.2824f,-0.256443f,0.674542f,0.000375894f, 1.2056f,0.434435f,1.29411f,-0.268654f,0.674319f,0.000432391f,
1.21153f,0.458379f,1.3049f,-0.280766f,0.674107f,0.000497359f, 1.20213f,0.475817f,1.31537f,-0.292755f,0.673915f,0.000572005f,
1.21142f,0.502622f,1.32816f,-0.304621f,0.673745f,0.000657671f, 1.20492f,0.520529f,1.34026f,-0.316348f,0.673604f,0.000755879f,
1.20432f,0.542175f,1.35494f,-0.327924f,0.673499f,0.000868358f, 1.20598f,0.564984f,1.36867f,-0.339343f,0.673433f,0.000997027f,
1.22201f,0.594444f,1.38297f,-0.350578f,0.67342f,0.00114408f, 1.2044f,0.608154f,1.39742f,-0.361634f,0.67346f,0.00131193f,
1.22439f,0.644235f,1.39779f,-0.372472f,0.673572f,0.00150333f, 1.20361f,0.651861f,1.42779f,-0.383098f,0.673758f,0.00172133f,
1.20376f,0.674125f,1.44388f,-0.393476f,0.674034f,0.0019693f, 1.20132f,0.694663f,1.46051f,-0.403599f,0.674412f,0.00225113f,
1.19985f,0.715786f,1.47839f,-0.413446f,0.674903f,0.00257095f, 1.21001f,0.7441f,1.4949f,-0.422987f,0.675529f,0.0029336f,
1.1951f,0.756218f,1.51227f,-0.432216f,0.676298f,0.00334422f, 1.20448f,0.783952f,1.52971f,-0.441088f,0.677241f,0.00380875f,
1.19386f,0.798068f,1.54837f,-0.449602f,0.678367f,0.00433354f, 1.18494f,0.812666f,1.56852f,-0.457705f,0.679713f,0.00492586f,
1.18236f,0.831428f,1.58756f,-0.4654f,0.681293f,0.00559369f, 1.18942f,0.857244f,1.60379f,-0.472625f,0.68315f,0.00634578f,
1.17936f,0.869333f,1.62545f,-0.479384f,0.685302f,0.00719196f, 1.19468f,0.900358f,1.64213f,-0.485611f,0.687805f,0.00814318f,
1.16225f,0.893843f,1.66447f,-0.49131f,0.690684f,0.00921152f, 1.17432f,0.921474f,1.68097f,-0.496409f,0.694001f,0.0104104f,
1.14631f,0.916225f,1.70297f,-0.500904f,0.697798f,0.0117548f, 1.13987f,0.926804f,1.72416f,-0.504757f,0.702138f,0.0132616f,
1.13206f,0.935746f,1.74393f,-0.507901f,0.707103f,0.0149496f, 1.1257f,0.944979f,1.76239f,-0.510328f,0.712756f,0.0168399f,
1.12938f,0.961445f,1.7794f,-0.511996f,0.719191f,0.0189565f, 1.12034f,0.965812f,1.79842f,-0.512865f,0.726516f,0.0213265f,
1.09023f,0.949405f,1.8143f,-0.512891f,0.734853f,0.023981f, 1.07833f,0.947725f,1.83363f,-0.512037f,0.744346f,0.026956f,
1.07184f,0.95032f,1.8479f,-0.510273f,0.755161f,0.0302926f, 1.06613f,0.951956f,1.86165f,-0.507556f,0.767501f,0.0340402f,
1.03755f,0.930079f,1.87518f,-0.503823f,0.781651f,0.0382569f, 1.02378f,0.920189f,1.88819f,-0.499052f,0.797912f,0.0430131f,
1.00689f,0.906276f,1.89954f,-0.493196f,0.816728f,0.0483974f, 0.989628f,0.890415f,1.90706f,-0.486203f,0.838699f,0.0545234f,
0.971472f,0.871462f,1.91278f,-0.477977f,0.864737f,0.0615457f, 0.951036f,0.849638f,1.91012f,-0.468444f,0.896352f,0.0696981f,
0.925391f,0.820565f,1.90175f,-0.45743f,0.936707f,0.0794079f, 0.889127f,0.775274f,1.85421f,-0.44498f,0.996776f,0.0917728f,
1.14541f,1.33526e-06f,1.1454f,-2.68717e-17f,0.655279f,4.74888e-05f, 1.14522f,0.0189179f,1.14562f,-0.0123357f,0.655277f,4.79182e-05f,
1.1447f,0.0378315f,1.14624f,-0.0246763f,0.655257f,4.91844e-05f, 1.14393f,0.0567308f,1.14732f,-0.0370001f,0.655225f,5.13265e-05f,
1.14299f,0.0756156f,1.14885f,-0.049313f,0.655181f,5.43893e-05f, 1.14202f,0.0944578f,1.1508f,-0.0616197f,0.655124f,5.84409e-05f,
1.14141f,0.113252f,1.15314f,-0.0739019f,0.655058f,6.35643e-05f, 1.14117f,0.132017f,1.15591f,-0.0861617f,0.65498f,6.98627e-05f,
1.14134f,0.150734f,1.15908f,-0.0983984f,0.654891f,7.74687e-05f, 1.14201f,0.16942f,1.16273f,-0.110598f,0.654796f,8.65447e-05f,
1.1432f,0.188046f,1.16679f,-0.122769f,0.654691f,9.72774e-05f, 1.1451f,0.206578f,1.17126f,-0.134898f,0.654582f,0.000109887f,
1.16102f,0.226521f,1.17999f,-0.146982f,0.654468f,0.000124624f, 1.15067f,0.24321f,1.18041f,-0.159019f,0.654349f,0.000141787f,
1.15151f,0.261715f,1.18659f,-0.170995f,0.654232f,0.00016172f, 1.15257f,0.280463f,1.19376f,-0.182917f,0.654113f,0.000184814f,
1.15497f,0.29952f,1.20151f,-0.194766f,0.654001f,0.000211522f, 1.15655f,0.318761f,1.20997f,-0.206548f,0.653892f,0.00024236f,
1.15941f,0.338539f,1.21889f,-0.218243f,0.653794f,0.000277913f, 1.16234f,0.358599f,1.22814f,-0.229858f,0.653707f,0.000318855f,
1.16487f,0.378711f,1.23781f,-0.241372f,0.653638f,0.000365946f, 1.16776f,0.399222f,1.24757f,-0.252789f,0.653587f,0.000420053f,
1.1851f,0.425643f,1.25916f,-0.264088f,0.653562f,0.000482148f, 1.18782f,0.446792f,1.26896f,-0.275272f,0.653564f,0.00055334f,
1.1692f,0.458603f,1.27805f,-0.286319f,0.653604f,0.000634884f, 1.18203f,0.484394f,1.29054f,-0.297232f,0.65368f,0.000728182f,
1.17033f,0.498704f,1.30102f,-0.307983f,0.653808f,0.000834827f, 1.1715f,0.51908f,1.31335f,-0.31858f,0.653985f,0.000956605f,
1.17289f,0.539717f,1.32584f,-0.32899f,0.654229f,0.00109551f, 1.18241f,0.562581f,1.33301f,-0.339218f,0.654539f,0.0012538f,
1.19388f,0.590547f,1.35149f,-0.349234f,0.654933f,0.00143399f, 1.18022f,0.603545f,1.36537f,-0.359036f,0.655415f,0.0016389f,
1.16871f,0.616872f,1.3783f,-0.368597f,0.656001f,0.00187164f, 1.16911f,0.636648f,1.3932f,-0.377909f,0.656702f,0.00213579f,
1.17226f,0.65816f,1.4078f,-0.38695f,0.657533f,0.00243521f, 1.16551f,0.673573f,1.42288f,-0.395699f,0.65851f,0.00277426f,
1.16346f,0.69171f,1.43852f,-0.404143f,0.659649f,0.00315785f, 1.17073f,0.715416f,1.45352f,-0.412253f,0.660971f,0.00359135f,
1.15699f,0.725426f,1.46839f,-0.420014f,0.662496f,0.00408073f, 1.16709f,0.750684f,1.48337f,-0.427397f,0.66425f,0.00463274f,
1.15345f,0.75966f,1.49959f,-0.434382f,0.666259f,0.00525478f, 1.14533f,0.771506f,1.51724f,-0.440948f,0.66855f,0.00595515f,
1.14018f,0.785341f,1.53468f,-0.447054f,0.671163f,0.006743f, 1.13927f,0.801533f,1.55116f,-0.452696f,0.674125f,0.00762861f,
1.1314f,0.811749f,1.5669f,-0.457818f,0.67749f,0.0086234f, 1.13761f,0.832139f,1.58188f,-0.462413f,0.681294f,0.00974009f,
1.11942f,0.833174f,1.59586f,-0.466453f,0.685591f,0.0109931f, 1.11273f,0.842097f,1.61307f,-0.469886f,0.69045f,0.0123982f,
1.11821f,0.859869f,1.62848f,-0.472691f,0.695933f,0.0139737f, 1.09429f,0.853037f,1.64485f,-0.474844f,0.702117f,0.0157399f,
1.08683f,0.858264f,1.66028f,-0.476308f,0.709091f,0.0177199f, 1.07684f,0.860321f,1.67705f,-0.477048f,0.71696f,0.01994f,
1.06946f,0.863586f,1.68894f,-0.477033f,0.725846f,0.0224307f, 1.05895f,0.862714f,1.70403f,-0.476237f,0.735885f,0.0252268f,
1.04913f,0.861342f,1.71562f,-0.474595f,0.747265f,0.0283695f, 1.04139f,0.860479f,1.72784f,-0.472105f,0.760182f,0.0319067f,
1.03388f,0.858778f,1.73654f,-0.4687f,0.774907f,0.0358965f, 1.02431f,0.853574f,1.74506f,-0.464363f,0.791765f,0.0404094f,
1.00276f,0.836003f,1.7537f,-0.459042f,0.811209f,0.0455337f, 0.988901f,0.824365f,1.75808f,-0.452697f,0.833832f,0.051384f,
0.97254f,0.809023f,1.76105f,-0.445207f,0.860645f,0.0581182f, 0.953568f,0.787485f,1.75674f,-0.436522f,0.893133f,0.0659736f,
0.931536f,0.765647f,1.74466f,-0.426437f,0.93467f,0.07539f, 0.910036f,0.735193f,1.70409f,-0.415013f,0.996635f,0.0875332f,
1.11642f,1.62249e-06f,1.11643f,-2.78884e-17f,0.632572f,4.76118e-05f, 1.11623f,0.0175528f,1.11659f,-0.0115957f,0.632582f,4.80501e-05f,
1.11566f,0.0351012f,1.11714f,-0.0231904f,0.632572f,4.92933e-05f, 1.1148f,0.052634f,1.11805f,-0.0347756f,0.632558f,5.13951e-05f,
1.11384f,0.0701411f,1.11934f,-0.0463438f,0.632544f,5.44062e-05f, 1.113f,0.0876034f,1.12098f,-0.0579043f,0.632524f,5.83834e-05f,
1.11247f,0.105014f,1.123f,-0.0694435f,0.6325f,6.3403e-05f, 1.11229f,0.12237f,1.12538f,-0.0809518f,0.632475f,6.95711e-05f,
1.11253f,0.139675f,1.12815f,-0.0924368f,0.632447f,7.70102e-05f, 1.11323f,0.156907f,1.13126f,-0.103888f,0.63242f,8.58749e-05f,
1.11299f,0.174028f,1.13508f,-0.1153f,0.632394f,9.63434e-05f, 1.11392f,0.191062f,1.13901f,-0.126674f,0.632369f,0.000108617f,
1.11597f,0.20799f,1.14329f,-0.137994f,0.63235f,0.00012294f, 1.13374f,0.226673f,1.15178f,-0.149265f,0.632336f,0.00013959f,
1.12334f,0.241912f,1.15271f,-0.160476f,0.63233f,0.00015889f, 1.12253f,0.258734f,1.15777f,-0.171622f,0.632334f,0.000181211f,
1.12512f,0.27629f,1.16456f,-0.182703f,0.632351f,0.000206976f, 1.12743f,0.293953f,1.17186f,-0.1937f,0.632385f,0.000236666f,
1.13016f,0.31205f,1.17963f,-0.204621f,0.632436f,0.000270831f, 1.13096f,0.329836f,1.18826f,-0.215445f,0.632512f,0.000310097f,
1.13888f,0.350146f,1.19865f,-0.226178f,0.632612f,0.000355169f, 1.13408f,0.366096f,1.20611f,-0.236798f,0.632745f,0.000406848f,
1.13669f,0.384787f,1.21505f,-0.24731f,0.63291f,0.00046605f, 1.15641f,0.407622f,1.21054f,-0.257694f,0.633118f,0.000533791f,
1.15623f,0.428294f,1.21892f,-0.26795f,0.633369f,0.000611235f, 1.13918f,0.439225f,1.24167f,-0.278059f,0.633675f,0.000699684f,
1.1454f,0.460097f,1.25246f,-0.288021f,0.634036f,0.000800606f, 1.13885f,0.474891f,1.26301f,-0.297814f,0.634467f,0.000915641f,
1.1503f,0.499181f,1.27337f,-0.307437f,0.634968f,0.00104665f, 1.14059f,0.511467f,1.28545f,-0.316867f,0.635556f,0.0011957f,
1.14052f,0.529387f,1.29714f,-0.326101f,0.636233f,0.0013651f, 1.14562f,0.549845f,1.30923f,-0.335116f,0.637017f,0.00155749f,
1.1378f,0.563358f,1.31961f,-0.343907f,0.637914f,0.00177571f, 1.15857f,0.59182f,1.31325f,-0.35245f,0.638942f,0.00202309f,
1.13495f,0.596786f,1.34333f,-0.360738f,0.640111f,0.00230318f, 1.13418f,0.613649f,1.3563f,-0.368745f,0.64144f,0.00262005f,
1.14049f,0.634321f,1.36976f,-0.376461f,0.642944f,0.0029782f, 1.13125f,0.645579f,1.38257f,-0.383863f,0.644644f,0.00338261f,
1.12726f,0.659856f,1.39726f,-0.390932f,0.646563f,0.00383893f, 1.13755f,0.682078f,1.40964f,-0.397656f,0.648719f,0.00435335f,
1.11985f,0.687361f,1.42256f,-0.403996f,0.651149f,0.00493286f, 1.11945f,0.702642f,1.43647f,-0.409952f,0.65387f,0.00558512f,
1.13457f,0.728037f,1.44901f,-0.415486f,0.656924f,0.00631883f, 1.11679f,0.730065f,1.46381f,-0.420577f,0.660346f,0.00714366f,
1.10106f,0.734101f,1.47766f,-0.425213f,0.664172f,0.00807044f, 1.09753f,0.745011f,1.49106f,-0.429361f,0.668453f,0.00911129f,
1.09432f,0.755612f,1.50334f,-0.432981f,0.673244f,0.0102797f, 1.09741f,0.770539f,1.516f,-0.436064f,0.678599f,0.011591f,
1.08094f,0.769648f,1.52947f,-0.438584f,0.684586f,0.0130626f, 1.08372f,0.777618f,1.54342f,-0.440507f,0.691283f,0.0147141f,
1.06303f,0.776586f,1.55301f,-0.441807f,0.698779f,0.0165678f, 1.05482f,0.77927f,1.56523f,-0.442456f,0.707178f,0.0186494f,
1.04663f,0.78094f,1.5761f,-0.442433f,0.716594f,0.0209882f, 1.04484f,0.787043f,1.5874f,-0.441678f,0.727186f,0.0236188f,
1.04133f,0.790367f,1.59595f,-0.440192f,0.739117f,0.0265812f, 1.01231f,0.771472f,1.60495f,-0.437918f,0.752603f,0.0299231f,
1.0019f,0.767116f,1.61124f,-0.434842f,0.767902f,0.0337017f, 0.988223f,0.758707f,1.61706f,-0.430912f,0.785368f,0.0379877f,
0.973928f,0.748298f,1.62283f,-0.426094f,0.805453f,0.0428692f, 0.958454f,0.736079f,1.62416f,-0.420316f,0.828797f,0.0484616f,
0.940576f,0.720789f,1.62338f,-0.413527f,0.85637f,0.0549251f, 0.923257f,0.704429f,1.61474f,-0.405617f,0.889832f,0.0625035f,
0.898936f,0.680814f,1.59948f,-0.396425f,0.932518f,0.0716441f, 0.861448f,0.640951f,1.54706f,-0.385953f,0.996489f,0.0835878f,
1.08998f,1.37954e-06f,1.08998f,-4.33384e-17f,0.609762f,4.75738e-05f, 1.08977f,0.0162198f,1.09012f,-0.0108429f,0.609776f,4.80046e-05f,
1.08922f,0.0324375f,1.09058f,-0.0216834f,0.60978f,4.92222e-05f, 1.08838f,0.0486403f,1.09136f,-0.0325152f,0.609787f,5.12797e-05f,
1.08745f,0.064815f,1.09244f,-0.04333f,0.609801f,5.42262e-05f, 1.08635f,0.0809297f,1.09387f,-0.0541343f,0.609819f,5.81142e-05f,
1.08564f,0.0969836f,1.09559f,-0.0649173f,0.609841f,6.30162e-05f, 1.0853f,0.112966f,1.09765f,-0.0756685f,0.609871f,6.9034e-05f,
1.08525f,0.128881f,1.09997f,-0.0863938f,0.609907f,7.62836e-05f, 1.08563f,0.144726f,1.10265f,-0.0970874f,0.609951f,8.4912e-05f,
1.08647f,0.160474f,1.10565f,-0.107736f,0.610006f,9.50838e-05f, 1.08786f,0.176097f,1.10897f,-0.118345f,0.610071f,0.000106991f,
1.08983f,0.19157f,1.11258f,-0.128901f,0.61015f,0.000120863f, 1.10115f,0.207784f,1.1192f,-0.139403f,0.610244f,0.000136963f,
1.0944f,0.22228f,1.12018f,-0.149848f,0.610354f,0.000155594f, 1.09501f,0.237858f,1.1254f,-0.160222f,0.610486f,0.000177105f,
1.09634f,0.253645f,1.1313f,-0.17053f,0.610639f,0.000201888f, 1.10904f,0.27244f,1.14141f,-0.180755f,0.610818f,0.000230392f,
1.09924f,0.285609f,1.14433f,-0.190898f,0.611026f,0.000263128f, 1.10151f,0.30202f,1.15152f,-0.200949f,0.611265f,0.000300681f,
1.10382f,0.318619f,1.15905f,-0.210899f,0.611542f,0.000343707f, 1.11154f,0.337317f,1.16822f,-0.220748f,0.611858f,0.000392951f,
1.10799f,0.351987f,1.17485f,-0.230476f,0.612223f,0.000449261f, 1.11019f,0.368895f,1.1829f,-0.240088f,0.612635f,0.000513583f,
1.11992f,0.389101f,1.19327f,-0.249562f,0.613108f,0.000586992f, 1.11719f,0.404091f,1.20012f,-0.258902f,0.61364f,0.000670688f,
1.11027f,0.417158f,1.20733f,-0.268087f,0.614245f,0.000766025f, 1.11031f,0.433303f,1.21699f,-0.277116f,0.614925f,0.000874528f,
1.11017f,0.449206f,1.2258f,-0.28597f,0.615692f,0.000997903f, 1.11095f,0.465546f,1.2356f,-0.294644f,0.616553f,0.00113807f,
1.11137f,0.48162f,1.24587f,-0.303125f,0.61752f,0.00129719f, 1.11171f,0.497697f,1.25579f,-0.311397f,0.618602f,0.00147763f,
1.11352f,0.514399f,1.2662f,-0.319455f,0.61981f,0.00168206f, 1.11881f,0.532891f,1.27685f,-0.327274f,0.621162f,0.00191358f,
1.10797f,0.542553f,1.28606f,-0.334854f,0.622666f,0.00217545f, 1.12476f,0.567174f,1.2977f,-0.342162f,0.624344f,0.00247141f,
1.10259f,0.570099f,1.30745f,-0.349202f,0.626208f,0.00280568f, 1.10101f,0.584113f,1.3188f,-0.355945f,0.628281f,0.00318291f,
1.09959f,0.597822f,1.33034f,-0.362377f,0.630585f,0.00360835f, 1.09636f,0.610035f,1.34157f,-0.368489f,0.633138f,0.00408774f,
1.09344f,0.622456f,1.35299f,-0.374246f,0.635975f,0.00462766f, 1.09103f,0.634715f,1.36407f,-0.379643f,0.639119f,0.00523536f,
1.10038f,0.655269f,1.37494f,-0.384662f,0.642601f,0.00591891f, 1.08195f,0.654731f,1.38601f,-0.389272f,0.646464f,0.00668754f,
1.07688f,0.663936f,1.39777f,-0.393452f,0.650746f,0.00755134f, 1.08461f,0.681129f,1.40811f,-0.397191f,0.655491f,0.00852186f,
1.09355f,0.687856f,1.42071f,-0.400466f,0.660751f,0.00961214f, 1.07078f,0.693938f,1.42834f,-0.403249f,0.666586f,0.0108368f,
1.05414f,0.692259f,1.43924f,-0.405517f,0.673063f,0.0122123f, 1.04817f,0.697316f,1.44988f,-0.407246f,0.680259f,0.0137578f,
1.04085f,0.700874f,1.45988f,-0.408412f,0.688263f,0.0154947f, 1.03468f,0.704286f,1.46831f,-0.408997f,0.697176f,0.0174479f,
1.02922f,0.707271f,1.47807f,-0.408971f,0.707119f,0.0196462f, 1.02751f,0.712144f,1.48484f,-0.40829f,0.718248f,0.0221232f,
1.02414f,0.715703f,1.49281f,-0.40695f,0.730722f,0.0249182f, 0.997999f,0.700064f,1.49826f,-0.404918f,0.744763f,0.0280783f,
0.989342f,0.697064f,1.50428f,-0.402145f,0.760649f,0.0316604f, 0.980596f,0.693259f,1.50714f,-0.39859f,0.778734f,0.0357345f,
0.969901f,0.685822f,1.5093f,-0.394243f,0.799475f,0.0403891f, 0.957041f,0.677408f,1.50874f,-0.389015f,0.823548f,0.0457407f,
0.941916f,0.665033f,1.50556f,-0.382867f,0.851942f,0.0519511f, 0.924249f,0.650246f,1.4964f,-0.375686f,0.886333f,0.0592672f,
0.882026f,0.614908f,1.47101f,-0.367316f,0.930255f,0.0681505f, 0.852962f,0.583934f,1.42115f,-0.357727f,0.996337f,0.0799151f,
1.06585f,-2.08236e-06f,1.06585f,-9.03175e-17f,0.586948f,4.73801e-05f, 1.06565f,0.0149139f,1.06597f,-0.0100807f,0.586961f,4.77912e-05f,
1.06507f,0.0298278f,1.06635f,-0.0201614f,0.586978f,4.89799e-05f, 1.0642f,0.0447227f,1.06699f,-0.0302303f,0.587007f,5.09877e-05f,
1.0632f,0.0595914f,1.06789f,-0.0402823f,0.587051f,5.38591e-05f, 1.0623f,0.0744035f,1.06906f,-0.050325f,0.587108f,5.76467e-05f,
1.06167f,0.0891372f,1.0705f,-0.0603446f,0.587177f,6.24182e-05f, 1.06133f,0.103806f,1.07222f,-0.0703321f,0.587263f,6.82691e-05f,
1.06132f,0.11839f,1.07422f,-0.0802937f,0.587364f,7.53097e-05f, 1.06168f,0.132887f,1.0765f,-0.0902224f,0.587482f,8.36796e-05f,
1.06123f,0.147267f,1.07929f,-0.100106f,0.58762f,9.35309e-05f, 1.06213f,0.161558f,1.08219f,-0.109948f,0.587777f,0.000105046f,
1.06293f,0.175691f,1.08533f,-0.119738f,0.587956f,0.00011844f, 1.06475f,0.189675f,1.08874f,-0.129472f,0.588161f,0.000133962f,
1.06722f,0.203514f,1.09187f,-0.139151f,0.58839f,0.000151898f, 1.06862f,0.217564f,1.09551f,-0.148757f,0.588651f,0.000172566f,
1.07036f,0.231794f,1.10012f,-0.158296f,0.588942f,0.000196334f, 1.07226f,0.246235f,1.10557f,-0.167754f,0.589269f,0.000223622f,
1.08678f,0.264238f,1.11592f,-0.177127f,0.589635f,0.000254911f, 1.07613f,0.275583f,1.11777f,-0.186414f,0.590042f,0.000290744f,
1.07621f,0.290027f,1.12444f,-0.195598f,0.590497f,0.00033173f, 1.07731f,0.304747f,1.13127f,-0.204682f,0.591002f,0.000378559f,
1.07836f,0.319499f,1.13836f,-0.213649f,0.591563f,0.000432007f, 1.07985f,0.334371f,1.14566f,-0.222499f,0.592186f,0.000492962f,
1.08158f,0.349423f,1.15295f,-0.231221f,0.592875f,0.000562415f, 1.08332f,0.364528f,1.16036f,-0.239804f,0.593639f,0.000641482f,
1.08387f,0.37904f,1.16679f,-0.248246f,0.594482f,0.000731405f, 1.084f,0.393356f,1.17383f,-0.256528f,0.595416f,0.000833603f,
1.08463f,0.407982f,1.18188f,-0.264651f,0.596444f,0.000949652f, 1.08437f,0.422236f,1.19009f,-0.272596f,0.59758f,0.00108133f,
1.08266f,0.435592f,1.19825f,-0.280357f,0.59883f,0.0012306f, 1.08163f,0.44925f,1.20754f,-0.287925f,0.600207f,0.00139969f,
1.08169f,0.463242f,1.21655f,-0.29528f,0.601726f,0.00159111f, 1.08156f,0.477007f,1.22556f,-0.302421f,0.603392f,0.00180758f,
1.08249f,0.491065f,1.23459f,-0.309326f,0.605229f,0.00205231f, 1.08105f,0.503742f,1.24391f,-0.315988f,0.607247f,0.00232867f,
1.07811f,0.515464f,1.2514f,-0.322395f,0.609463f,0.0026406f, 1.07992f,0.529485f,1.26106f,-0.328522f,0.611902f,0.00299245f,
1.07246f,0.538541f,1.26871f,-0.334367f,0.614578f,0.00338907f, 1.06988f,0.549692f,1.27857f,-0.339914f,0.617518f,0.00383592f,
1.06795f,0.560769f,1.28863f,-0.345133f,0.620752f,0.00433902f, 1.0646f,0.570858f,1.29858f,-0.350023f,0.624303f,0.00490534f,
1.07415f,0.58841f,1.30818f,-0.354564f,0.628204f,0.0055424f, 1.05692f,0.589197f,1.31613f,-0.358739f,0.632493f,0.00625887f,
1.05325f,0.597581f,1.32661f,-0.362526f,0.63721f,0.00706449f, 1.04911f,0.605486f,1.33552f,-0.365905f,0.642403f,0.00797009f,
1.05518f,0.61927f,1.34277f,-0.368861f,0.648121f,0.00898808f, 1.05465f,0.627491f,1.35268f,-0.371377f,0.654421f,0.0101325f,
1.03233f,0.622471f,1.35943f,-0.373432f,0.661372f,0.0114192f, 1.02611f,0.626727f,1.36723f,-0.374996f,0.669052f,0.0128665f,
1.02688f,0.635145f,1.37551f,-0.376051f,0.677551f,0.0144952f, 1.02871f,0.645388f,1.37788f,-0.37659f,0.686967f,0.0163296f,
1.0283f,0.647711f,1.3897f,-0.376571f,0.697427f,0.0183975f, 0.998391f,0.634094f,1.39237f,-0.375988f,0.709075f,0.0207318f,
0.995194f,0.636886f,1.39875f,-0.374784f,0.722099f,0.0233711f, 0.975984f,0.627113f,1.40127f,-0.37296f,0.736707f,0.026362f,
0.966063f,0.623082f,1.40454f,-0.370483f,0.753178f,0.0297607f, 0.952786f,0.616368f,1.40601f,-0.367301f,0.771876f,0.033637f,
0.940343f,0.608996f,1.4058f,-0.363393f,0.793288f,0.0380796f, 0.927555f,0.600569f,1.40169f,-0.358689f,0.818097f,0.0432052f,
0.910403f,0.58854f,1.39438f,-0.353136f,0.847318f,0.049178f, 0.89347f,0.575099f,1.38265f,-0.346631f,0.882762f,0.0562522f,
0.869605f,0.555861f,1.36125f,-0.339028f,0.928002f,0.0648997f, 0.836935f,0.524982f,1.3083f,-0.330269f,0.996181f,0.0764954f,
1.04384f,5.9267e-07f,1.04384f,-2.37838e-18f,0.564219f,4.70336e-05f, 1.04365f,0.0136386f,1.04394f,-0.0093123f,0.564229f,4.7418e-05f,
1.0431f,0.0272788f,1.04425f,-0.0186296f,0.56426f,4.85764e-05f, 1.04226f,0.0409038f,1.04477f,-0.0279278f,0.564312f,5.05312e-05f,
1.04125f,0.0544974f,1.04552f,-0.0372147f,0.564385f,5.33184e-05f, 1.04019f,0.0680377f,1.0465f,-0.0464916f,0.564481f,5.69953e-05f,
1.03939f,0.0815004f,1.0477f,-0.0557415f,0.5646f,6.1626e-05f, 1.03887f,0.0948793f,1.04914f,-0.0649641f,0.564742f,6.72957e-05f,
1.03859f,0.108179f,1.05076f,-0.0741601f,0.564908f,7.41115e-05f, 1.03862f,0.12139f,1.05268f,-0.0833194f,0.565102f,8.22053e-05f,
1.03896f,0.134501f,1.05482f,-0.0924385f,0.565323f,9.17168e-05f, 1.03967f,0.147482f,1.0572f,-0.101515f,0.565571f,0.000102819f,
1.04081f,0.160332f,1.0598f,-0.110538f,0.565853f,0.000115716f, 1.04242f,0.17301f,1.06264f,-0.11951f,0.566168f,0.000130643f,
1.04452f,0.185602f,1.06577f,-0.128424f,0.566518f,0.000147857f, 1.04553f,0.198226f,1.06893f,-0.137267f,0.566908f,0.00016766f,
1.046f,0.210924f,1.07257f,-0.146043f,0.567338f,0.000190398f, 1.04743f,0.223754f,1.07683f,-0.154742f,0.567813f,0.000216468f,
1.04894f,0.236772f,1.08173f,-0.163359f,0.568337f,0.000246309f, 1.05464f,0.250841f,1.08871f,-0.171889f,0.568911f,0.000280419f,
1.05062f,0.262755f,1.09229f,-0.180319f,0.569544f,0.000319371f, 1.05214f,0.275961f,1.09816f,-0.188653f,0.570235f,0.000363812f,
1.0537f,0.289277f,1.10413f,-0.196877f,0.570994f,0.00041446f, 1.05521f,0.302631f,1.1103f,-0.204983f,0.571824f,0.000472125f,
1.05634f,0.315844f,1.11676f,-0.212971f,0.572729f,0.000537728f, 1.05767f,0.329201f,1.12328f,-0.220823f,0.573722f,0.000612314f,
1.05724f,0.341923f,1.13071f,-0.22854f,0.574802f,0.000697018f, 1.05955f,0.355632f,1.13782f,-0.236109f,0.575983f,0.000793159f,
1.05846f,0.367769f,1.14294f,-0.24352f,0.577271f,0.000902198f, 1.05782f,0.380049f,1.14873f,-0.250771f,0.578673f,0.00102576f,
1.05788f,0.392672f,1.1561f,-0.257843f,0.580205f,0.0011657f, 1.05683f,0.404771f,1.16386f,-0.264733f,0.581872f,0.00132404f,
1.05549f,0.416371f,1.17057f,-0.271433f,0.583688f,0.00150313f, 1.05478f,0.428348f,1.178f,-0.27792f,0.585669f,0.00170551f,
1.06335f,0.444352f,1.18786f,-0.284196f,0.587825f,0.00193405f, 1.05301f,0.451427f,1.19358f,-0.290249f,0.590174f,0.00219209f,
1.05335f,0.46316f,1.20168f,-0.296055f,0.592735f,0.00248312f, 1.05178f,0.473954f,1.20951f,-0.301615f,0.595525f,0.00281128f,
1.04998f,0.484196f,1.217f,-0.306913f,0.598563f,0.00318104f, 1.06636f,0.503959f,1.2075f,-0.311932f,0.601878f,0.00359759f,
1.04382f,0.5029f,1.23025f,-0.316657f,0.605494f,0.00406657f, 1.05546f,0.519686f,1.24009f,-0.321081f,0.609439f,0.00459446f,
1.036f,0.518952f,1.2455f,-0.325188f,0.613743f,0.00518843f, 1.03242f,0.526827f,1.25342f,-0.328961f,0.618445f,0.00585668f,
1.02839f,0.534001f,1.26076f,-0.332384f,0.623584f,0.00660832f, 1.02516f,0.540955f,1.26874f,-0.335442f,0.629207f,0.00745382f,
1.02432f,0.54917f,1.27424f,-0.338116f,0.635366f,0.00840496f, 1.03122f,0.56172f,1.28237f,-0.340392f,0.642118f,0.00947512f,
1.00971f,0.556198f,1.28821f,-0.342252f,0.649529f,0.0106796f, 1.00575f,0.560824f,1.29401f,-0.343687f,0.657676f,0.0120361f,
0.999656f,0.563768f,1.2994f,-0.344656f,0.666652f,0.0135645f, 0.993376f,0.565903f,1.30493f,-0.345158f,0.676561f,0.0152886f,
0.987382f,0.567764f,1.31035f,-0.345162f,0.687526f,0.0172353f, 0.985943f,0.571641f,1.31463f,-0.344659f,0.699693f,0.0194369f,
0.982955f,0.574351f,1.31818f,-0.343614f,0.713248f,0.0219315f, 0.971206f,0.570378f,1.31985f,-0.341995f,0.728418f,0.0247646f,
0.964921f,0.570084f,1.32131f,-0.339781f,0.745489f,0.0279924f, 0.956904f,0.56274f,1.31671f,-0.336958f,0.764808f,0.0316837f,
0.946965f,0.562086f,1.31733f,-0.333459f,0.786906f,0.0359277f, 0.911561f,0.538489f,1.30758f,-0.329246f,0.812462f,0.0408419f,
0.894343f,0.527483f,1.29776f,-0.324231f,0.842594f,0.0465919f, 0.877941f,0.515793f,1.28363f,-0.318365f,0.879062f,0.0534365f,
0.854945f,0.498872f,1.26046f,-0.311484f,0.925698f,0.0618661f, 0.832925f,0.476862f,1.2143f,-0.303518f,0.996019f,0.0733101f,
1.02376f,-7.42738e-07f,1.02375f,3.24509e-17f,0.54166f,4.65373e-05f, 1.02358f,0.0123928f,1.02384f,-0.00854354f,0.541669f,4.68967e-05f,
1.02304f,0.024783f,1.02408f,-0.0170898f,0.541715f,4.80242e-05f, 1.02221f,0.0371642f,1.0245f,-0.0256199f,0.54179f,4.99203e-05f,
1.02123f,0.0495177f,1.0251f,-0.0341407f,0.541892f,5.2618e-05f, 1.02029f,0.0618207f,1.02588f,-0.0426466f,0.542027f,5.61763e-05f,
1.01954f,0.0740386f,1.02684f,-0.0511278f,0.542194f,6.06564e-05f, 1.01901f,0.0861855f,1.02802f,-0.059586f,0.542392f,6.6134e-05f,
1.01871f,0.098252f,1.02939f,-0.0680137f,0.542624f,7.27131e-05f, 1.0187f,0.110218f,1.03098f,-0.0764068f,0.542892f,8.05169e-05f,
1.0182f,0.122094f,1.0329f,-0.0847634f,0.543195f,8.96741e-05f, 1.01829f,0.133865f,1.03495f,-0.0930739f,0.543537f,0.00010035f,
1.01845f,0.145491f,1.03713f,-0.101337f,0.54392f,0.000112739f, 1.01931f,0.157002f,1.03956f,-0.10955f,0.544344f,0.00012705f,
1.02053f,0.168338f,1.04215f,-0.117701f,0.544814f,0.000143529f, 1.02218f,0.179601f,1.04504f,-0.125791f,0.545331f,0.00016246f,
1.02385f,0.190818f,1.04742f,-0.133816f,0.545898f,0.000184171f, 1.02502f,0.202198f,1.0504f,-0.141762f,0.54652f,0.000209013f,
1.02623f,0.213662f,1.05418f,-0.149632f,0.547199f,0.000237405f, 1.02747f,0.225265f,1.05857f,-0.157419f,0.547939f,0.000269822f,
1.0288f,0.236934f,1.06319f,-0.165111f,0.548746f,0.000306777f, 1.0298f,0.248537f,1.0679f,-0.17271f,0.549621f,0.000348868f,
1.02912f,0.259895f,1.07309f,-0.180204f,0.550573f,0.00039678f, 1.03024f,0.271582f,1.07829f,-0.187588f,0.551606f,0.000451246f,
1.03049f,0.283078f,1.08389f,-0.19486f,0.552724f,0.000513133f, 1.03071f,0.294509f,1.08972f,-0.202003f,0.553938f,0.000583396f,
1.03127f,0.305953f,1.09553f,-0.209019f,0.555252f,0.000663089f, 1.03246f,0.317621f,1.10152f,-0.215899f,0.556673f,0.00075344f,
1.03308f,0.329089f,1.1072f,-0.222627f,0.558213f,0.000855781f, 1.03409f,0.340583f,1.11317f,-0.229207f,0.559878f,0.000971649f,
1.0334f,0.351243f,1.11781f,-0.235624f,0.561678f,0.00110272f, 1.04367f,0.366694f,1.12633f,-0.241866f,0.563628f,0.00125093f,
1.03215f,0.372392f,1.12926f,-0.247934f,0.565736f,0.00141839f, 1.0313f,0.382821f,1.13538f,-0.253813f,0.568015f,0.0016075f,
1.03193f,0.393741f,1.14242f,-0.259488f,0.570484f,0.00182096f, 1.02811f,0.402335f,1.14756f,-0.264959f,0.573154f,0.00206179f,
1.02646f,0.411896f,1.15385f,-0.270212f,0.576043f,0.0023333f, 1.02982f,0.423667f,1.16146f,-0.275236f,0.579171f,0.00263932f,
1.02436f,0.430644f,1.16767f,-0.280017f,0.582562f,0.00298416f, 1.02355f,0.439907f,1.17334f,-0.284546f,0.586236f,0.00337252f,
1.02168f,0.448375f,1.1796f,-0.288814f,0.590219f,0.00380976f, 1.02064f,0.457144f,1.18604f,-0.292807f,0.59454f,0.00430197f,
1.01501f,0.463017f,1.19213f,-0.296514f,0.599232f,0.00485602f, 1.0253f,0.477041f,1.20019f,-0.299919f,0.60433f,0.00547956f,
1.00676f,0.475303f,1.20232f,-0.30301f,0.609876f,0.0061813f, 1.00513f,0.482313f,1.20925f,-0.305771f,0.615915f,0.0069711f,
1.01309f,0.494099f,1.21483f,-0.308192f,0.622497f,0.00786031f, 0.994065f,0.49055f,1.21684f,-0.310261f,0.629681f,0.00886175f,
0.987409f,0.493622f,1.22244f,-0.311955f,0.637536f,0.00999008f, 0.983728f,0.49763f,1.22666f,-0.313253f,0.646142f,0.0112622f,
0.977434f,0.499908f,1.23074f,-0.314162f,0.655581f,0.0126977f, 0.972517f,0.502303f,1.23426f,-0.314632f,0.665972f,0.0143193f,
0.964016f,0.502449f,1.23714f,-0.314667f,0.677432f,0.0161536f, 0.957817f,0.502978f,1.23954f,-0.314243f,0.690113f,0.0182318f,
0.950073f,0.502264f,1.24065f,-0.313334f,0.704205f,0.0205914f, 0.944972f,0.502289f,1.24168f,-0.311924f,0.719933f,0.0232775f,
0.939076f,0.501861f,1.24186f,-0.309977f,0.737587f,0.0263452f, 0.93149f,0.499411f,1.24045f,-0.307473f,0.757552f,0.0298636f,
0.90726f,0.486185f,1.23108f,-0.30436f,0.780342f,0.0339215f, 0.895445f,0.479707f,1.22447f,-0.300585f,0.806688f,0.0386371f,
0.877781f,0.469635f,1.21279f,-0.296124f,0.837685f,0.0441788f, 0.860312f,0.45858f,1.19713f,-0.290858f,0.875215f,0.0508085f,
0.835939f,0.442398f,1.16834f,-0.284634f,0.923292f,0.0590311f, 0.798482f,0.414153f,1.10828f,-0.277418f,0.995852f,0.0703424f,
1.00546f,-4.69435e-06f,1.00546f,-7.87777e-17f,0.519353f,4.58963e-05f, 1.00529f,0.0111817f,1.00552f,-0.00778006f,0.519367f,4.62466e-05f,
1.0048f,0.0223533f,1.00571f,-0.0155463f,0.519425f,4.73343e-05f, 1.00405f,0.0335157f,1.00604f,-0.0233165f,0.519521f,4.91669e-05f,
1.00305f,0.0446642f,1.00653f,-0.0310694f,0.519653f,5.17732e-05f, 1.00201f,0.0557636f,1.00714f,-0.0388024f,0.519827f,5.52063e-05f,
1.00115f,0.0667933f,1.00792f,-0.0465228f,0.52004f,5.95271e-05f, 1.00043f,0.0777396f,1.00884f,-0.054215f,0.520294f,6.48055e-05f,
0.999924f,0.0885987f,1.00993f,-0.0618762f,0.520591f,7.11393e-05f, 0.999592f,0.0993858f,1.01122f,-0.069511f,0.52093f,7.86419e-05f,
0.999468f,0.110076f,1.01265f,-0.0771045f,0.521315f,8.74357e-05f, 0.999552f,0.120658f,1.01425f,-0.0846559f,0.521747f,9.7677e-05f,
0.999889f,0.131144f,1.01602f,-0.0921666f,0.522228f,0.000109545f, 1.00048f,0.141475f,1.01795f,-0.099622f,0.52276f,0.000123232f,
1.00135f,0.151668f,1.02002f,-0.107024f,0.523346f,0.000138975f, 1.00259f,0.161719f,1.02228f,-0.11437f,0.523988f,0.000157038f,
1.00278f,0.171772f,1.02499f,-0.121645f,0.52469f,0.000177711f, 1.01783f,0.18008f,1.03197f,-0.128855f,0.525454f,0.000201345f,
1.00448f,0.191748f,1.02975f,-0.135992f,0.526284f,0.000228313f, 1.00536f,0.20186f,1.03319f,-0.143043f,0.527185f,0.000259049f,
1.00608f,0.21196f,1.03654f,-0.150015f,0.52816f,0.000294056f, 1.00687f,0.222138f,1.04051f,-0.156895f,0.529214f,0.000333865f,
1.00769f,0.232344f,1.04459f,-0.163676f,0.530355f,0.000379118f, 1.00835f,0.242457f,1.04912f,-0.170357f,0.531583f,0.000430496f,
1.00855f,0.252495f,1.05367f,-0.176931f,0.532908f,0.000488801f, 1.00917f,0.262629f,1.05844f,-0.183386f,0.534337f,0.000554904f,
1.00966f,0.272693f,1.06304f,-0.189725f,0.535874f,0.00062982f, 1.01009f,0.282708f,1.06778f,-0.195935f,0.537529f,0.000714634f,
1.01718f,0.295065f,1.07483f,-0.202008f,0.539311f,0.000810629f, 1.01096f,0.302505f,1.07785f,-0.207942f,0.541228f,0.000919193f,
1.01102f,0.312205f,1.08295f,-0.213729f,0.543289f,0.0010419f, 1.01083f,0.321744f,1.08783f,-0.219354f,0.545509f,0.00118053f,
1.01092f,0.331246f,1.09295f,-0.224818f,0.547896f,0.00133707f, 1.00982f,0.339997f,1.09661f,-0.230112f,0.550464f,0.00151374f,
1.01502f,0.351516f,1.10344f,-0.235225f,0.553229f,0.00171304f, 1.0068f,0.356922f,1.10606f,-0.240145f,0.556206f,0.00193778f,
1.00498f,0.365127f,1.11133f,-0.244869f,0.559413f,0.00219111f, 1.00298f,0.373052f,1.11653f,-0.249386f,0.562867f,0.00247656f,
1.00886f,0.386127f,1.12228f,-0.253687f,0.56659f,0.00279812f, 0.997711f,0.387573f,1.12615f,-0.257762f,0.570606f,0.00316027f,
0.997817f,0.395609f,1.13134f,-0.261601f,0.574941f,0.00356809f, 0.995311f,0.402403f,1.1358f,-0.265193f,0.579624f,0.00402727f,
0.991401f,0.40827f,1.14116f,-0.268526f,0.584686f,0.00454423f, 0.988234f,0.41414f,1.14608f,-0.271589f,0.590165f,0.00512629f,
0.9848f,0.419612f,1.15108f,-0.274373f,0.5961f,0.00578179f, 0.981749f,0.424932f,1.15487f,-0.276864f,0.602537f,0.00652003f,
0.979849f,0.430381f,1.15869f,-0.279056f,0.609526f,0.00735185f, 0.979227f,0.436316f,1.16351f,-0.280927f,0.617129f,0.00828955f,
0.968603f,0.436695f,1.16616f,-0.282463f,0.625416f,0.00934724f, 0.969721f,0.442673f,1.16977f,-0.283663f,0.634458f,0.0105412f,
0.972571f,0.449483f,1.17434f,-0.284496f,0.644356f,0.0118903f, 0.974128f,0.455711f,1.17207f,-0.284952f,0.655214f,0.0134167f,
0.945515f,0.443679f,1.17248f,-0.285019f,0.667159f,0.0151463f, 0.938608f,0.443802f,1.17287f,-0.284676f,0.680347f,0.0171097f,
0.933258f,0.444305f,1.17339f,-0.283907f,0.694966f,0.0193434f, 0.929232f,0.44515f,1.17415f,-0.282682f,0.71125f,0.021892f,
0.923646f,0.44481f,1.17259f,-0.280983f,0.729505f,0.0248104f, 0.916369f,0.442028f,1.16962f,-0.278769f,0.750119f,0.0281668f,
0.907357f,0.438745f,1.1389f,-0.276027f,0.773609f,0.0320502f, 0.87422f,0.421613f,1.14673f,-0.272676f,0.800756f,0.0365795f,
0.85764f,0.413052f,1.13176f,-0.268698f,0.83267f,0.0419246f, 0.83949f,0.40276f,1.11315f,-0.263993f,0.871332f,0.0483541f,
0.813133f,0.387489f,1.08061f,-0.258424f,0.92079f,0.0563805f, 0.774925f,0.361981f,1.01936f,-0.251919f,0.99568f,0.0675761f,
0.988769f,-1.08517e-06f,0.988764f,-1.20454e-16f,0.497368f,4.51182e-05f, 0.98861f,0.00999063f,0.988811f,-0.00701129f,0.497398f,4.54794e-05f,
0.988162f,0.0199802f,0.988954f,-0.0140176f,0.497465f,4.65206e-05f, 0.987449f,0.0299628f,0.989206f,-0.0210214f,0.497581f,4.82862e-05f,
0.986565f,0.0399242f,0.989565f,-0.0280073f,0.497744f,5.08001e-05f, 0.985624f,0.0498491f,0.990046f,-0.0349813f,0.497953f,5.41013e-05f,
0.984761f,0.059721f,0.990653f,-0.0419377f,0.498212f,5.82584e-05f, 0.984046f,0.0695094f,0.991375f,-0.0488677f,0.49852f,6.33318e-05f,
0.983487f,0.079227f,0.99225f,-0.0557751f,0.498877f,6.94128e-05f, 0.98309f,0.0888652f,0.993252f,-0.0626494f,0.499288f,7.66089e-05f,
0.982501f,0.0984184f,0.994475f,-0.0694884f,0.499752f,8.50329e-05f, 0.981982f,0.107889f,0.995823f,-0.0762934f,0.50027f,9.48368e-05f,
0.981928f,0.117253f,0.997257f,-0.0830498f,0.500847f,0.000106176f, 0.98168f,0.126509f,0.998815f,-0.0897623f,0.501482f,0.000119242f,
0.981922f,0.13565f,1.00054f,-0.096426f,0.502179f,0.000134251f, 0.982383f,0.144657f,1.00234f,-0.103028f,0.502942f,0.000151441f,
0.983054f,0.153509f,1.00428f,-0.109576f,0.503772f,0.000171102f, 0.983933f,0.162294f,1.00637f,-0.116058f,0.504673f,0.000193533f,
0.984989f,0.17103f,1.0088f,-0.122469f,0.50565f,0.000219108f, 0.986242f,0.179725f,1.01064f,-0.128808f,0.506704f,0.000248211f,
0.987055f,0.188457f,1.01292f,-0.13507f,0.507842f,0.000281314f, 0.98871f,0.197437f,1.01633f,-0.141244f,0.509069f,0.000318911f,
0.988055f,0.206056f,1.01886f,-0.147334f,0.510387f,0.000361597f, 0.988522f,0.214912f,1.02236f,-0.153329f,0.511804f,0.00041f,
0.988959f,0.223688f,1.02603f,-0.159221f,0.513327f,0.00046487f, 0.989029f,0.232325f,1.0296f,-0.165012f,0.51496f,0.000527011f,
0.989153f,0.240985f,1.03328f,-0.170694f,0.516711f,0.000597347f, 0.987366f,0.249202f,1.03718f,-0.176255f,0.51859f,0.000676921f,
0.987238f,0.25765f,1.04099f,-0.181696f,0.520603f,0.000766889f, 0.987271f,0.266066f,1.04528f,-0.18701f,0.522759f,0.000868547f,
0.987179f,0.2744f,1.04962f,-0.192189f,0.52507f,0.000983368f, 0.993082f,0.284737f,1.05593f,-0.197222f,0.527547f,0.00111299f,
0.985644f,0.290308f,1.0576f,-0.20211f,0.5302f,0.00125926f, 0.985671f,0.298332f,1.06215f,-0.206844f,0.533043f,0.00142427f,
0.985286f,0.30615f,1.06613f,-0.211416f,0.53609f,0.00161032f, 0.98445f,0.313669f,1.07026f,-0.215819f,0.539358f,0.00182006f,
0.987447f,0.322492f,1.07548f,-0.220042f,0.542865f,0.00205641f, 1.00556f,0.332877f,1.06364f,-0.224079f,0.546629f,0.00232267f,
0.983503f,0.335738f,1.08188f,-0.227922f,0.55067f,0.00262259f, 0.976588f,0.339914f,1.08336f,-0.231566f,0.555014f,0.00296045f,
0.974648f,0.346179f,1.08725f,-0.235f,0.559684f,0.00334094f, 0.973698f,0.352446f,1.09155f,-0.238214f,0.564711f,0.00376941f,
0.970622f,0.357783f,1.09482f,-0.241203f,0.570125f,0.00425203f, 0.970133f,0.364118f,1.09958f,-0.243948f,0.575965f,0.00479564f,
0.980061f,0.373983f,1.08812f,-0.246444f,0.582273f,0.00540825f, 0.959767f,0.37123f,1.10422f,-0.248684f,0.589092f,0.00609871f,
0.956828f,0.375514f,1.10604f,-0.250661f,0.596471f,0.00687731f, 0.952332f,0.378733f,1.10921f,-0.252345f,0.60448f,0.00775587f,
0.949433f,0.382581f,1.11248f,-0.253751f,0.613176f,0.008748f, 0.953504f,0.388957f,1.11376f,-0.254839f,0.622651f,0.00986941f,
0.937384f,0.38578f,1.11441f,-0.255613f,0.632989f,0.0111383f, 0.931026f,0.386888f,1.11488f,-0.256059f,0.644303f,0.0125762f,
0.926873f,0.38839f,1.11545f,-0.256155f,0.656725f,0.0142082f, 0.918127f,0.387674f,1.11424f,-0.25589f,0.670412f,0.0160644f,
0.912472f,0.387855f,1.11213f,-0.255253f,0.685551f,0.0181807f, 0.903465f,0.385984f,1.10982f,-0.254195f,0.702402f,0.020601f,
0.893738f,0.383427f,1.10547f,-0.252719f,0.721253f,0.0233793f, 0.884227f,0.380472f,1.10004f,-0.250794f,0.742515f,0.026584f,
0.873612f,0.376534f,1.09141f,-0.248397f,0.76672f,0.0303036f, 0.859487f,0.370527f,1.08164f,-0.24545f,0.794673f,0.0346579f,
0.844291f,0.363557f,1.06567f,-0.241936f,0.827528f,0.0398189f, 0.828772f,0.355628f,1.04776f,-0.237764f,0.867287f,0.0460576f,
0.81149f,0.346205f,1.02179f,-0.232806f,0.918196f,0.0539013f, 0.779699f,0.325188f,0.969385f,-0.226975f,0.995504f,0.0649967f,
0.973554f,-1.78547e-06f,0.973556f,-9.42832e-17f,0.475796f,4.42616e-05f, 0.973428f,0.00883733f,0.973595f,-0.00625221f,0.475822f,4.45946e-05f,
0.973043f,0.0176749f,0.973704f,-0.0125022f,0.475903f,4.55994e-05f, 0.972416f,0.0265032f,0.973894f,-0.0187377f,0.476038f,4.72939e-05f,
0.971567f,0.0353157f,0.974159f,-0.0249745f,0.476228f,4.97095e-05f, 0.970626f,0.0440999f,0.974519f,-0.0311872f,0.476474f,5.28808e-05f,
0.969692f,0.0528452f,0.974961f,-0.0373888f,0.476776f,5.68687e-05f, 0.968858f,0.0615196f,0.975513f,-0.043569f,0.477133f,6.1732e-05f,
0.968124f,0.0701303f,0.976174f,-0.0497206f,0.477551f,6.75593e-05f, 0.967496f,0.0786683f,0.976932f,-0.0558485f,0.478028f,7.44435e-05f,
0.966991f,0.0871227f,0.977799f,-0.0619427f,0.478566f,8.24972e-05f, 0.966581f,0.0954983f,0.978774f,-0.068001f,0.479168f,9.18592e-05f,
0.966287f,0.10379f,0.979855f,-0.074022f,0.479833f,0.000102672f, 0.966114f,0.111987f,0.981042f,-0.0799994f,0.480568f,0.000115123f,
0.96606f,0.120095f,0.982309f,-0.0859282f,0.481372f,0.000129398f, 0.966154f,0.128061f,0.983678f,-0.0918112f,0.482248f,0.000145739f,
0.966387f,0.135935f,0.985159f,-0.0976344f,0.483201f,0.000164392f, 0.966759f,0.143647f,0.986708f,-0.103401f,0.484233f,0.00018566f,
0.967285f,0.151247f,0.988376f,-0.109107f,0.485346f,0.000209867f, 0.966751f,0.158886f,0.990414f,-0.114742f,0.486548f,0.000237386f,
0.967446f,0.166387f,0.992509f,-0.120308f,0.487841f,0.000268647f, 0.968397f,0.173785f,0.994141f,-0.1258f,0.489228f,0.000304109f,
0.968136f,0.181234f,0.995966f,-0.131209f,0.490717f,0.000344323f, 0.968193f,0.188729f,0.998471f,-0.136534f,0.492314f,0.000389886f,
0.967386f,0.196024f,1.0008f,-0.141771f,0.494021f,0.000441464f, 0.96715f,0.203385f,1.00353f,-0.146913f,0.495849f,0.000499822f,
0.966854f,0.210698f,1.00629f,-0.151953f,0.497804f,0.000565824f, 0.966462f,0.217903f,1.00911f,-0.156891f,0.499892f,0.000640423f,
0.965776f,0.224948f,1.01216f,-0.161721f,0.502123f,0.000724687f, 0.965614f,0.232069f,1.01551f,-0.166436f,0.504506f,0.000819842f,
0.966196f,0.239222f,1.01872f,-0.171027f,0.507053f,0.000927236f, 0.965321f,0.246026f,1.02171f,-0.175493f,0.509772f,0.0010484f,
0.965334f,0.252943f,1.02499f,-0.179828f,0.512676f,0.00118507f, 0.964392f,0.259526f,1.02838f,-0.184026f,0.515778f,0.00133915f,
0.963029f,0.265898f,1.0313f,-0.18808f,0.519093f,0.00151282f, 0.966706f,0.273864f,1.03677f,-0.191984f,0.522637f,0.00170855f,
0.960947f,0.27836f,1.03785f,-0.195731f,0.526426f,0.00192906f, 0.959799f,0.284347f,1.04114f,-0.199314f,0.530482f,0.00217749f,
0.959779f,0.290532f,1.0441f,-0.202725f,0.534823f,0.00245733f, 0.957106f,0.295768f,1.04685f,-0.205958f,0.539475f,0.00277252f,
0.954258f,0.300763f,1.04954f,-0.209007f,0.544464f,0.00312763f, 0.953027f,0.305999f,1.05236f,-0.211862f,0.549818f,0.00352766f,
0.962647f,0.315458f,1.05892f,-0.214516f,0.555568f,0.00397834f, 0.946507f,0.314287f,1.05549f,-0.216966f,0.561752f,0.00448637f,
0.945844f,0.319461f,1.05895f,-0.219195f,0.568413f,0.00505917f, 0.954472f,0.322521f,1.06264f,-0.221194f,0.575596f,0.00570528f,
0.936771f,0.325161f,1.05972f,-0.222965f,0.583352f,0.00643451f, 0.931386f,0.327592f,1.06065f,-0.224483f,0.591747f,0.00725826f,
0.927459f,0.330223f,1.06182f,-0.225748f,0.600845f,0.00818946f, 0.92314f,0.332435f,1.06197f,-0.22675f,0.610729f,0.00924336f,
0.917158f,0.333663f,1.0624f,-0.227472f,0.621495f,0.0104377f, 0.911847f,0.334788f,1.06116f,-0.2279f,0.633256f,0.0117931f,
0.906791f,0.335763f,1.06077f,-0.22802f,0.646147f,0.0133343f, 0.906017f,0.338079f,1.06161f,-0.227826f,0.660325f,0.0150904f,
0.903911f,0.340319f,1.05943f,-0.227296f,0.675988f,0.017097f, 0.900429f,0.341204f,1.05938f,-0.22642f,0.693384f,0.0193971f,
0.871873f,0.330139f,1.04371f,-0.225161f,0.712832f,0.0220443f, 0.861219f,0.327116f,1.03528f,-0.22349f,0.734751f,0.0251066f,
0.85058f,0.323562f,1.02616f,-0.221409f,0.759685f,0.0286724f, 0.834365f,0.317638f,1.01189f,-0.218846f,0.788452f,0.0328621f,
0.819093f,0.311511f,0.995736f,-0.215778f,0.82224f,0.0378492f, 0.800744f,0.303513f,0.97456f,-0.212098f,0.863203f,0.0439122f,
0.777205f,0.293077f,0.943086f,-0.20772f,0.915638f,0.0515899f, 0.736716f,0.272598f,0.885483f,-0.202541f,0.995323f,0.0625906f,
0.959715f,2.76279e-07f,0.959713f,-3.14985e-17f,0.454678f,4.33032e-05f, 0.959597f,0.00771711f,0.959737f,-0.00550003f,0.454704f,4.36116e-05f,
0.959252f,0.015426f,0.95981f,-0.0109969f,0.454799f,4.45829e-05f, 0.958712f,0.0231359f,0.95994f,-0.0164885f,0.45495f,4.6204e-05f,
0.957993f,0.0308368f,0.960127f,-0.0219687f,0.455168f,4.85214e-05f, 0.957163f,0.0385069f,0.960384f,-0.0274377f,0.455445f,5.15585e-05f,
0.956283f,0.0461509f,0.96072f,-0.0328921f,0.455788f,5.5376e-05f, 0.955442f,0.0537441f,0.96111f,-0.0383244f,0.456195f,6.00291e-05f,
0.954687f,0.0612863f,0.961581f,-0.0437404f,0.456667f,6.55991e-05f, 0.95401f,0.0687543f,0.962141f,-0.0491241f,0.457207f,7.21718e-05f,
0.953416f,0.0761659f,0.96278f,-0.0544852f,0.457815f,7.9859e-05f, 0.952629f,0.0834944f,0.96355f,-0.0598121f,0.458493f,8.87757e-05f,
0.951854f,0.0907561f,0.96438f,-0.0651033f,0.459245f,9.90754e-05f, 0.951401f,0.0979417f,0.96529f,-0.0703579f,0.460071f,0.000110908f,
0.95101f,0.105045f,0.966256f,-0.0755701f,0.460975f,0.000124473f, 0.950524f,0.112057f,0.967308f,-0.0807358f,0.461959f,0.000139972f,
0.950079f,0.118982f,0.968403f,-0.0858554f,0.463025f,0.000157647f, 0.949882f,0.125791f,0.969567f,-0.0909208f,0.464179f,0.000177778f,
0.949728f,0.132519f,0.97085f,-0.0959295f,0.465423f,0.00020066f, 0.94971f,0.139093f,0.972152f,-0.100881f,0.46676f,0.000226646f,
0.949716f,0.145574f,0.973499f,-0.105768f,0.468197f,0.000256131f, 0.949812f,0.151937f,0.974904f,-0.110587f,0.469738f,0.000289549f,
0.949944f,0.158249f,0.976494f,-0.115336f,0.471386f,0.000327393f, 0.950111f,0.164527f,0.978205f,-0.120011f,0.473148f,0.000370227f,
0.950315f,0.170654f,0.979203f,-0.124603f,0.475031f,0.00041868f, 0.95054f,0.176787f,0.980542f,-0.129114f,0.477041f,0.000473453f,
0.950042f,0.182944f,0.982437f,-0.133539f,0.479184f,0.000535339f, 0.965109f,0.191623f,0.990974f,-0.137872f,0.481469f,0.000605225f,
0.949242f,0.194993f,0.986572f,-0.142106f,0.483905f,0.000684122f, 0.948255f,0.200881f,0.988738f,-0.146238f,0.486501f,0.00077314f,
0.94708f,0.206684f,0.990771f,-0.150266f,0.489266f,0.000873554f, 0.946013f,0.212341f,0.993037f,-0.154185f,0.492212f,0.000986786f,
0.944646f,0.217832f,0.995344f,-0.157988f,0.495351f,0.00111445f, 0.943454f,0.223295f,0.997572f,-0.161671f,0.498696f,0.00125832f,
0.942446f,0.228643f,0.999559f,-0.165227f,0.502261f,0.00142044f, 0.941772f,0.233938f,1.00199f,-0.168652f,0.506063f,0.00160311f,
0.939653f,0.238889f,1.00399f,-0.17194f,0.510119f,0.00180888f, 0.938016f,0.243756f,1.00605f,-0.175085f,0.514449f,0.00204071f,
0.936668f,0.248552f,1.0083f,-0.178081f,0.519073f,0.00230185f, 0.936096f,0.253348f,1.01002f,-0.180922f,0.524016f,0.00259605f,
0.933281f,0.257541f,1.01197f,-0.183604f,0.529303f,0.00292755f, 0.937188f,0.262616f,1.01648f,-0.186122f,0.534964f,0.00330115f,
0.929485f,0.265708f,1.01553f,-0.188463f,0.541031f,0.0037223f, 0.9255f,0.268913f,1.01647f,-0.190619f,0.547544f,0.00419724f,
0.921214f,0.27192f,1.0176f,-0.192595f,0.554539f,0.00473306f, 0.918859f,0.2752f,1.01798f,-0.194364f,0.56207f,0.00533798f,
0.916795f,0.278315f,1.01927f,-0.19594f,0.570185f,0.00602145f, 0.911382f,0.280354f,1.01938f,-0.197296f,0.578949f,0.00679416f,
0.9089f,0.28294f,1.01921f,-0.198429f,0.588433f,0.0076688f, 0.904033f,0.284519f,1.01817f,-0.199334f,0.598718f,0.00866f,
0.898289f,0.285638f,1.01769f,-0.199998f,0.609901f,0.00978474f, 0.899366f,0.288842f,1.0184f,-0.200414f,0.622096f,0.0110634f,
0.900021f,0.292034f,1.01945f,-0.20056f,0.635442f,0.0125198f, 0.899423f,0.292892f,1.01695f,-0.200427f,0.650104f,0.0141825f,
0.89751f,0.294459f,1.01792f,-0.2f,0.666284f,0.0160865f, 0.862374f,0.284071f,0.996872f,-0.199268f,0.684235f,0.018274f,
0.855283f,0.282881f,0.991511f,-0.198208f,0.704284f,0.0207983f, 0.849236f,0.282135f,0.985243f,-0.196806f,0.726843f,0.0237266f,
0.841494f,0.280047f,0.977801f,-0.195012f,0.752518f,0.0271478f, 0.832001f,0.277825f,0.966853f,-0.192812f,0.782104f,0.0311826f,
0.799112f,0.26567f,0.937759f,-0.190136f,0.816891f,0.0360063f, 0.781208f,0.259111f,0.916562f,-0.186948f,0.859002f,0.0419014f,
0.754267f,0.249142f,0.883506f,-0.183124f,0.913017f,0.0494248f, 0.720058f,0.233471f,0.832258f,-0.178578f,0.995137f,0.0603451f,
0.947111f,-2.41343e-08f,0.947109f,-1.47495e-16f,0.434062f,4.22428e-05f, 0.94702f,0.00662702f,0.947124f,-0.00475668f,0.4341f,4.2557e-05f,
0.94675f,0.013256f,0.947183f,-0.00951734f,0.4342f,4.34774e-05f, 0.946291f,0.0198727f,0.947264f,-0.0142639f,0.434372f,4.50347e-05f,
0.945669f,0.0264849f,0.947399f,-0.0190096f,0.434611f,4.72468e-05f, 0.944915f,0.0330855f,0.947561f,-0.023738f,0.434921f,5.01524e-05f,
0.944075f,0.0396623f,0.947779f,-0.028458f,0.435301f,5.3799e-05f, 0.943202f,0.0461927f,0.948043f,-0.0331579f,0.435751f,5.82402e-05f,
0.942343f,0.0526915f,0.948353f,-0.0378404f,0.436275f,6.35557e-05f, 0.941527f,0.0591385f,0.948729f,-0.0425013f,0.436871f,6.98181e-05f,
0.940749f,0.0655135f,0.949148f,-0.0471346f,0.437546f,7.71389e-05f, 0.940018f,0.0718434f,0.949629f,-0.0517439f,0.438296f,8.56249e-05f,
0.93932f,0.0781035f,0.950167f,-0.0563192f,0.439125f,9.5407e-05f, 0.938641f,0.084305f,0.950763f,-0.0608623f,0.440037f,0.000106647f,
0.93802f,0.0904456f,0.951406f,-0.0653712f,0.441033f,0.000119508f, 0.937429f,0.0964989f,0.952097f,-0.0698356f,0.442116f,0.000134186f,
0.936848f,0.102475f,0.952832f,-0.0742609f,0.443289f,0.000150916f, 0.936354f,0.108369f,0.953695f,-0.0786426f,0.444555f,0.000169942f,
0.935892f,0.114176f,0.954584f,-0.0829709f,0.445919f,0.000191548f, 0.93543f,0.119897f,0.95547f,-0.0872484f,0.447383f,0.000216054f,
0.934968f,0.125513f,0.956405f,-0.091474f,0.448953f,0.000243833f, 0.934555f,0.131018f,0.957343f,-0.0956392f,0.450633f,0.000275289f,
0.934131f,0.136425f,0.95834f,-0.0997409f,0.452429f,0.000310879f, 0.933764f,0.141731f,0.959354f,-0.10378f,0.454346f,0.000351124f,
0.933569f,0.146925f,0.960559f,-0.107752f,0.456389f,0.000396602f, 0.933394f,0.152029f,0.961689f,-0.111649f,0.458567f,0.000447971f,
0.932976f,0.157081f,0.96281f,-0.115469f,0.460886f,0.000505965f, 0.941657f,0.162547f,0.967369f,-0.119212f,0.463354f,0.000571409f,
0.933268f,0.16694f,0.965027f,-0.122872f,0.465978f,0.000645236f, 0.931182f,0.171718f,0.965274f,-0.126445f,0.46877f,0.000728498f,
0.930557f,0.176513f,0.966759f,-0.129928f,0.471738f,0.000822374f, 0.933208f,0.181571f,0.969429f,-0.133315f,0.474895f,0.000928174f,
0.928245f,0.185767f,0.969184f,-0.136602f,0.478251f,0.00104739f, 0.926408f,0.190251f,0.970307f,-0.139786f,0.481822f,0.00118174f,
0.924739f,0.194615f,0.971907f,-0.142861f,0.48562f,0.00133308f, 0.922782f,0.198805f,0.973066f,-0.145825f,0.489662f,0.00150357f,
0.921812f,0.202944f,0.974061f,-0.148671f,0.493966f,0.00169563f, 0.928888f,0.208634f,0.979438f,-0.151394f,0.498552f,0.00191199f,
0.917623f,0.210621f,0.976373f,-0.15399f,0.50344f,0.00215575f, 0.91663f,0.214385f,0.977336f,-0.156455f,0.508655f,0.00243044f,
0.913667f,0.217789f,0.978115f,-0.158787f,0.514221f,0.00274003f, 0.910409f,0.221014f,0.978869f,-0.16097f,0.520172f,0.00308907f,
0.908692f,0.22422f,0.979089f,-0.163005f,0.526539f,0.00348273f, 0.905861f,0.227162f,0.979691f,-0.164891f,0.533357f,0.00392698f,
0.901989f,0.229667f,0.979509f,-0.166609f,0.540674f,0.00442855f, 0.89792f,0.231966f,0.979226f,-0.168164f,0.548533f,0.00499522f,
0.895646f,0.234354f,0.978906f,-0.169549f,0.556989f,0.00563613f, 0.890178f,0.235993f,0.977977f,-0.170748f,0.566108f,0.0063615f,
0.888161f,0.238083f,0.977133f,-0.171755f,0.57596f,0.00718342f, 0.882718f,0.239288f,0.975442f,-0.17257f,0.586629f,0.00811621f,
0.875763f,0.239883f,0.972727f,-0.173172f,0.598216f,0.00917619f, 0.87391f,0.241371f,0.97142f,-0.173555f,0.610838f,0.0103832f,
0.874776f,0.243782f,0.972039f,-0.173727f,0.624628f,0.0117604f, 0.874357f,0.245297f,0.970727f,-0.173644f,0.639767f,0.0133358f,
0.850568f,0.240155f,0.957503f,-0.173315f,0.656455f,0.0151436f, 0.841869f,0.239007f,0.950652f,-0.172724f,0.674953f,0.0172257f,
0.834208f,0.237787f,0.943728f,-0.17185f,0.695593f,0.0196345f, 0.823295f,0.235447f,0.933722f,-0.170668f,0.718823f,0.0224372f,
0.810745f,0.232545f,0.9231f,-0.169157f,0.745227f,0.0257221f, 0.796596f,0.228816f,0.908173f,-0.167296f,0.775644f,0.0296109f,
0.781659f,0.224474f,0.891441f,-0.165015f,0.811419f,0.034281f, 0.761023f,0.218487f,0.868334f,-0.162285f,0.854728f,0.0400192f,
0.738369f,0.210971f,0.838747f,-0.158984f,0.910311f,0.0473943f, 0.703624f,0.197916f,0.789755f,-0.155051f,0.994946f,0.0582485f,
0.935664f,3.11327e-07f,0.935661f,-4.2826e-17f,0.414009f,4.11325e-05f, 0.935587f,0.00557541f,0.935676f,-0.00403462f,0.414046f,4.14258e-05f,
0.935359f,0.0111488f,0.935701f,-0.0080527f,0.414157f,4.23057e-05f, 0.93499f,0.01672f,0.935753f,-0.0120832f,0.414343f,4.37925e-05f,
0.934494f,0.0222787f,0.935824f,-0.0160943f,0.414605f,4.59046e-05f, 0.933868f,0.027821f,0.935923f,-0.0201039f,0.414942f,4.8676e-05f,
0.93315f,0.0333554f,0.936044f,-0.0240977f,0.415356f,5.21546e-05f, 0.932367f,0.03887f,0.93621f,-0.0280781f,0.415846f,5.63856e-05f,
0.931535f,0.0443505f,0.936388f,-0.0320429f,0.416417f,6.14468e-05f, 0.930711f,0.049788f,0.936607f,-0.0359896f,0.417068f,6.74097e-05f,
0.929907f,0.0551847f,0.936867f,-0.0399137f,0.417799f,7.43635e-05f, 0.929125f,0.0605391f,0.937142f,-0.0438134f,0.418615f,8.24244e-05f,
0.92836f,0.0658357f,0.937473f,-0.0476917f,0.419516f,9.17109e-05f, 0.927617f,0.0710811f,0.937819f,-0.0515355f,0.420506f,0.000102362f,
0.926906f,0.0762695f,0.938228f,-0.0553507f,0.421585f,0.000114538f, 0.925896f,0.0814035f,0.938701f,-0.0591348f,0.422758f,0.000128428f,
0.925165f,0.0864687f,0.939141f,-0.0628784f,0.424028f,0.000144237f, 0.924437f,0.0914875f,0.939644f,-0.0665873f,0.425397f,0.000162199f,
0.923699f,0.0964184f,0.940148f,-0.0702549f,0.426869f,0.000182578f, 0.922949f,0.101291f,0.94065f,-0.0738743f,0.42845f,0.000205672f,
0.922203f,0.106081f,0.941186f,-0.0774504f,0.430141f,0.00023182f, 0.921419f,0.110792f,0.941765f,-0.0809784f,0.431949f,0.0002614f,
0.920598f,0.115418f,0.942333f,-0.0844514f,0.433879f,0.000294841f, 0.919664f,0.119947f,0.942914f,-0.0878692f,0.435937f,0.000332622f,
0.918715f,0.124382f,0.943467f,-0.091231f,0.438128f,0.000375284f, 0.917836f,0.128732f,0.944218f,-0.0945329f,0.440459f,0.000423434f,
0.916817f,0.132992f,0.944819f,-0.0977703f,0.442937f,0.000477751f, 0.916702f,0.137022f,0.945172f,-0.100939f,0.445572f,0.000539013f,
0.915648f,0.141077f,0.945741f,-0.104038f,0.44837f,0.000608092f, 0.914897f,0.144988f,0.946467f,-0.107064f,0.451342f,0.000685944f,
0.913715f,0.148869f,0.947051f,-0.110014f,0.454497f,0.000773668f, 0.912426f,0.152661f,0.947639f,-0.112885f,0.457847f,0.000872525f,
0.913697f,0.156334f,0.948784f,-0.115672f,0.461404f,0.000983871f, 0.910751f,0.159764f,0.948097f,-0.118373f,0.465182f,0.00110931f,
0.918926f,0.163566f,0.95197f,-0.120983f,0.469194f,0.00125061f, 0.906873f,0.166617f,0.948228f,-0.1235f,0.473458f,0.00140975f,
0.905643f,0.169923f,0.948789f,-0.12592f,0.47799f,0.00158903f, 0.903542f,0.17311f,0.948975f,-0.128235f,0.482812f,0.00179102f,
0.9131f,0.177383f,0.954079f,-0.130442f,0.487945f,0.00201862f, 0.89989f,0.178975f,0.948919f,-0.132543f,0.493412f,0.00227516f,
0.896725f,0.181722f,0.94888f,-0.13453f,0.49924f,0.00256442f, 0.893473f,0.184331f,0.948852f,-0.136391f,0.505462f,0.00289065f,
0.891033f,0.186815f,0.948316f,-0.138137f,0.512107f,0.00325882f, 0.888068f,0.189121f,0.947819f,-0.139745f,0.519218f,0.00367451f,
0.885586f,0.191284f,0.946933f,-0.141223f,0.526834f,0.00414423f, 0.880519f,0.193101f,0.945835f,-0.142564f,0.535004f,0.00467541f,
0.882035f,0.195403f,0.946453f,-0.143757f,0.543785f,0.00527663f, 0.872382f,0.196212f,0.94302f,-0.144798f,0.553243f,0.00595794f,
0.86847f,0.197503f,0.940554f,-0.14568f,0.563448f,0.00673092f, 0.863835f,0.198563f,0.938416f,-0.14639f,0.574489f,0.0076091f,
0.857787f,0.199223f,0.935254f,-0.146931f,0.586467f,0.00860888f, 0.852934f,0.199721f,0.931636f,-0.147298f,0.599496f,0.00974897f,
0.845613f,0.199861f,0.927846f,-0.147465f,0.613728f,0.0110521f, 0.840099f,0.199762f,0.922543f,-0.147431f,0.629331f,0.0125458f,
0.832402f,0.199224f,0.91676f,-0.147191f,0.646519f,0.0142636f, 0.823616f,0.198308f,0.90984f,-0.146728f,0.665556f,0.0162467f,
0.814651f,0.196989f,0.901558f,-0.146011f,0.686799f,0.0185468f, 0.804684f,0.195234f,0.891888f,-0.145042f,0.710683f,0.0212311f,
0.791559f,0.192855f,0.880414f,-0.143798f,0.737825f,0.0243878f, 0.777857f,0.189837f,0.865794f,-0.142247f,0.769091f,0.0281387f,
0.762796f,0.186256f,0.848823f,-0.140355f,0.805835f,0.0326635f, 0.741789f,0.181345f,0.825893f,-0.138047f,0.850386f,0.0382537f,
0.717908f,0.174965f,0.796318f,-0.135267f,0.907524f,0.0454894f, 0.684753f,0.164589f,0.748945f,-0.131926f,0.994752f,0.05629f,
0.925251f,1.80264e-06f,0.925255f,-1.71977e-17f,0.394545f,3.99652e-05f, 0.925196f,0.0045542f,0.925258f,-0.00331449f,0.394583f,4.02378e-05f,
0.925028f,0.00911309f,0.925272f,-0.00662796f,0.394702f,4.1077e-05f, 0.924742f,0.0136603f,0.925292f,-0.0099376f,0.394903f,4.24961e-05f,
0.924343f,0.0182061f,0.925326f,-0.0132422f,0.395183f,4.45052e-05f, 0.923834f,0.0227378f,0.925365f,-0.0165349f,0.395546f,4.71469e-05f,
0.92323f,0.0272645f,0.925422f,-0.0198267f,0.395989f,5.0457e-05f, 0.92255f,0.0317702f,0.925488f,-0.0230974f,0.396517f,5.44856e-05f,
0.921787f,0.0362586f,0.925558f,-0.0263605f,0.397128f,5.9292e-05f, 0.920978f,0.0407242f,0.925654f,-0.0296045f,0.397827f,6.49579e-05f,
0.920119f,0.0451547f,0.925763f,-0.0328365f,0.398611f,7.15627e-05f, 0.91925f,0.0495541f,0.925871f,-0.0360435f,0.399486f,7.92064e-05f,
0.918366f,0.0539108f,0.925999f,-0.0392319f,0.40045f,8.80022e-05f, 0.917475f,0.0582269f,0.926147f,-0.0423959f,0.401509f,9.80832e-05f,
0.916573f,0.062502f,0.92631f,-0.0455339f,0.402664f,0.000109602f, 0.915654f,0.0667255f,0.926498f,-0.0486484f,0.403918f,0.000122727f,
0.914726f,0.0709029f,0.926696f,-0.0517286f,0.405274f,0.00013765f, 0.913769f,0.0750316f,0.926887f,-0.0547794f,0.406736f,0.000154589f,
0.912791f,0.0791111f,0.927091f,-0.0577985f,0.408305f,0.000173789f, 0.91183f,0.0831214f,0.927328f,-0.0607773f,0.409989f,0.000195529f,
0.910865f,0.0870843f,0.927579f,-0.0637193f,0.411791f,0.000220121f, 0.909818f,0.0909959f,0.92781f,-0.0666233f,0.413713f,0.000247918f,
0.908729f,0.0948408f,0.928033f,-0.0694847f,0.415764f,0.000279318f, 0.907614f,0.0986079f,0.928248f,-0.0722981f,0.417949f,0.00031477f,
0.906749f,0.102296f,0.928488f,-0.0750653f,0.420273f,0.000354769f, 0.905565f,0.105936f,0.928676f,-0.0777838f,0.422743f,0.000399878f,
0.90433f,0.109496f,0.928892f,-0.0804508f,0.425366f,0.000450738f, 0.903003f,0.11297f,0.929001f,-0.0830645f,0.42815f,0.000508078f,
0.902195f,0.11635f,0.929067f,-0.0856194f,0.431105f,0.000572672f, 0.90068f,0.119643f,0.929196f,-0.0881156f,0.434239f,0.000645464f,
0.899337f,0.12283f,0.929133f,-0.0905485f,0.437564f,0.000727444f, 0.898089f,0.125917f,0.929119f,-0.0929171f,0.441089f,0.000819793f,
0.896416f,0.128944f,0.929142f,-0.0952173f,0.444829f,0.000923792f, 0.894525f,0.131893f,0.929154f,-0.0974463f,0.448795f,0.00104092f,
0.89278f,0.134705f,0.928924f,-0.0996017f,0.453004f,0.00117284f, 0.891109f,0.13742f,0.928835f,-0.101681f,0.457471f,0.00132144f,
0.888857f,0.140042f,0.928385f,-0.103681f,0.462214f,0.00148883f, 0.887779f,0.142435f,0.927958f,-0.105602f,0.467252f,0.00167744f,
0.885182f,0.144855f,0.927391f,-0.10743f,0.472611f,0.00189001f, 0.88333f,0.147035f,0.926522f,-0.109173f,0.478312f,0.0021297f,
0.880931f,0.149178f,0.925956f,-0.110822f,0.484382f,0.00240004f, 0.887636f,0.151312f,0.928057f,-0.112373f,0.490854f,0.00270509f,
0.875674f,0.15291f,0.923156f,-0.113822f,0.497762f,0.00304955f, 0.874786f,0.154738f,0.922627f,-0.115172f,0.505141f,0.00343876f,
0.884175f,0.157068f,0.925624f,-0.116408f,0.51304f,0.00387886f, 0.865644f,0.157713f,0.91808f,-0.117528f,0.521506f,0.00437699f,
0.861871f,0.158997f,0.9161f,-0.118532f,0.530596f,0.00494136f, 0.857671f,0.160146f,0.91377f,-0.119415f,0.540374f,0.00558162f,
0.853468f,0.161122f,0.911006f,-0.120166f,0.550917f,0.00630891f, 0.848664f,0.16189f,0.907779f,-0.120776f,0.562315f,0.00713643f,
0.848806f,0.162557f,0.906654f,-0.121257f,0.574664f,0.00807972f, 0.851033f,0.162927f,0.89747f,-0.121576f,0.588098f,0.00915726f,
0.831429f,0.162826f,0.895096f,-0.121743f,0.602754f,0.0103912f, 0.824864f,0.162672f,0.889786f,-0.121748f,0.618813f,0.0118085f,
0.817637f,0.162202f,0.883073f,-0.121583f,0.636492f,0.0134417f, 0.808756f,0.161529f,0.876128f,-0.121221f,0.656072f,0.0153318f,
0.799302f,0.160405f,0.867151f,-0.120672f,0.677894f,0.0175298f, 0.789632f,0.159042f,0.8575f,-0.119902f,0.702433f,0.0201026f,
0.776534f,0.157106f,0.845173f,-0.118896f,0.730321f,0.0231382f, 0.76315f,0.154789f,0.831177f,-0.11764f,0.762442f,0.0267591f,
0.74763f,0.151806f,0.814118f,-0.116094f,0.800203f,0.0311466f, 0.727431f,0.147949f,0.791521f,-0.114225f,0.84595f,0.0365974f,
0.704012f,0.142707f,0.762397f,-0.111939f,0.904712f,0.0437056f, 0.672617f,0.134922f,0.717996f,-0.10917f,0.994552f,0.0544597f,
0.915828f,-2.19889e-06f,0.91583f,1.08902e-17f,0.375695f,3.87386e-05f, 0.915784f,0.00356668f,0.915826f,-0.00260785f,0.375738f,3.90032e-05f,
0.915644f,0.0071483f,0.91582f,-0.00523142f,0.375866f,3.98054e-05f, 0.915423f,0.0107195f,0.915816f,-0.00784499f,0.376078f,4.1153e-05f,
0.915113f,0.0142774f,0.915806f,-0.0104461f,0.376376f,4.30665e-05f, 0.914726f,0.0178312f,0.915801f,-0.013051f,0.376759f,4.55753e-05f,
0.914253f,0.0213798f,0.915789f,-0.0156424f,0.377231f,4.87231e-05f, 0.913708f,0.0249144f,0.915782f,-0.0182299f,0.37779f,5.25504e-05f,
0.913088f,0.0284343f,0.915771f,-0.0208023f,0.378438f,5.71162e-05f, 0.912405f,0.0319399f,0.915754f,-0.0233641f,0.379177f,6.24875e-05f,
0.911659f,0.0354285f,0.915747f,-0.0259107f,0.380008f,6.87451e-05f, 0.910868f,0.0388934f,0.915727f,-0.028445f,0.380933f,7.59838e-05f,
0.910031f,0.0423311f,0.915707f,-0.0309602f,0.381955f,8.43098e-05f, 0.909162f,0.0457385f,0.915688f,-0.0334615f,0.383075f,9.38438e-05f,
0.908268f,0.0491199f,0.915675f,-0.0359367f,0.384297f,0.000104726f, 0.907346f,0.0524646f,0.91565f,-0.0383961f,0.385621f,0.000117113f,
0.906389f,0.0557726f,0.915615f,-0.0408287f,0.387054f,0.000131185f, 0.905414f,0.0590454f,0.915572f,-0.0432371f,0.388597f,0.000147144f,
0.9044f,0.0622765f,0.915524f,-0.0456231f,0.390253f,0.000165222f, 0.903344f,0.0654704f,0.915448f,-0.0479772f,0.392029f,0.000185674f,
0.902199f,0.0686147f,0.915386f,-0.0503012f,0.393927f,0.000208789f, 0.901004f,0.0717127f,0.915302f,-0.052596f,0.395951f,0.000234893f,
0.89977f,0.0747632f,0.915197f,-0.0548578f,0.398109f,0.000264356f, 0.898494f,0.0777605f,0.9151f,-0.0570828f,0.400406f,0.000297604f,
0.897153f,0.0807052f,0.914937f,-0.05927f,0.402848f,0.000335087f, 0.895851f,0.0835986f,0.914833f,-0.0614194f,0.405441f,0.000377333f,
0.894409f,0.0864346f,0.914631f,-0.0635304f,0.408193f,0.000424953f, 0.892877f,0.0892195f,0.914397f,-0.0655975f,0.411112f,0.00047858f,
0.891552f,0.0919321f,0.914179f,-0.0676215f,0.414207f,0.000539001f, 0.889923f,0.0945902f,0.913883f,-0.069598f,0.417487f,0.000607033f,
0.888596f,0.0971625f,0.913484f,-0.0715256f,0.420963f,0.000683642f, 0.88686f,0.0996969f,0.913116f,-0.0734031f,0.424647f,0.000769916f,
0.885407f,0.102121f,0.912499f,-0.0752276f,0.42855f,0.000867058f, 0.883432f,0.104473f,0.912012f,-0.0769974f,0.432687f,0.00097644f,
0.881158f,0.106763f,0.911368f,-0.0787123f,0.437071f,0.00109963f, 0.878951f,0.108988f,0.91068f,-0.0803668f,0.441721f,0.00123839f,
0.876693f,0.111107f,0.909932f,-0.0819552f,0.446656f,0.00139472f, 0.874492f,0.11315f,0.909088f,-0.0834827f,0.451894f,0.0015709f,
0.872193f,0.115074f,0.908035f,-0.0849432f,0.457457f,0.0017695f, 0.870138f,0.116868f,0.906735f,-0.0863315f,0.463373f,0.00199352f,
0.86743f,0.118622f,0.905537f,-0.0876495f,0.469666f,0.00224626f, 0.864023f,0.120279f,0.904157f,-0.0888943f,0.47637f,0.00253165f,
0.86121f,0.12175f,0.902453f,-0.0900527f,0.48352f,0.00285407f, 0.857636f,0.12319f,0.900604f,-0.0911331f,0.491153f,0.00321861f,
0.854961f,0.124371f,0.898454f,-0.0921295f,0.499316f,0.00363119f, 0.85086f,0.125563f,0.896146f,-0.093036f,0.508058f,0.00409857f,
0.84699f,0.126572f,0.893578f,-0.0938484f,0.517438f,0.00462862f, 0.843296f,0.127361f,0.890537f,-0.0945676f,0.527521f,0.00523064f,
0.838713f,0.128117f,0.887446f,-0.0951853f,0.538385f,0.00591536f, 0.833879f,0.128687f,0.883669f,-0.0956908f,0.550124f,0.0066955f,
0.828541f,0.129043f,0.879462f,-0.0960886f,0.562837f,0.00758611f, 0.822966f,0.12927f,0.874945f,-0.0963724f,0.576652f,0.00860516f,
0.817227f,0.129272f,0.869494f,-0.0965295f,0.591721f,0.0097743f, 0.810184f,0.129149f,0.863768f,-0.0965534f,0.608228f,0.0111197f,
0.8032f,0.128697f,0.856803f,-0.0964515f,0.62639f,0.0126736f, 0.794507f,0.128157f,0.849205f,-0.0961859f,0.646502f,0.0144762f,
0.785736f,0.127206f,0.840147f,-0.0957703f,0.668914f,0.0165783f, 0.775708f,0.126078f,0.829996f,-0.0951905f,0.694103f,0.0190459f,
0.763466f,0.124553f,0.817551f,-0.094413f,0.722726f,0.0219672f, 0.750101f,0.122652f,0.803259f,-0.0934374f,0.755705f,0.0254653f,
0.734914f,0.120198f,0.786f,-0.0922332f,0.794476f,0.0297235f, 0.71688f,0.11714f,0.764417f,-0.0907554f,0.841482f,0.0350427f,
0.702639f,0.114632f,0.740477f,-0.0889525f,0.901908f,0.0420336f, 0.660677f,0.107398f,0.691135f,-0.0867558f,0.994349f,0.0527482f,
0.907287f,1.33529e-06f,0.907287f,-1.18689e-17f,0.357486f,3.74763e-05f, 0.907251f,0.00262496f,0.907275f,-0.00193584f,0.357534f,3.77347e-05f,
0.907149f,0.00524755f,0.90726f,-0.00386633f,0.357669f,3.84999e-05f, 0.906983f,0.00787697f,0.90723f,-0.00579797f,0.357892f,3.97801e-05f,
0.906757f,0.0104941f,0.907198f,-0.00772758f,0.358203f,4.15961e-05f, 0.906461f,0.0131004f,0.907145f,-0.00964381f,0.358606f,4.39791e-05f,
0.906092f,0.0157134f,0.907079f,-0.0115629f,0.3591f,4.69639e-05f, 0.905666f,0.0183108f,0.907011f,-0.0134759f,0.359686f,5.05942e-05f,
0.905173f,0.0208975f,0.906927f,-0.0153771f,0.360367f,5.49235e-05f, 0.904617f,0.0234777f,0.906824f,-0.0172758f,0.361141f,6.00133e-05f,
0.904002f,0.0260372f,0.906709f,-0.0191568f,0.362013f,6.594e-05f, 0.903322f,0.0285907f,0.906585f,-0.0210343f,0.362982f,7.27878e-05f,
0.902577f,0.0311213f,0.906443f,-0.0228917f,0.364053f,8.06577e-05f, 0.901796f,0.0336399f,0.906288f,-0.0247432f,0.365225f,8.96618e-05f,
0.900957f,0.0361388f,0.906119f,-0.0265732f,0.366504f,9.99306e-05f, 0.900059f,0.038609f,0.905929f,-0.0283937f,0.36789f,0.000111612f,
0.899136f,0.041066f,0.905722f,-0.0301956f,0.369388f,0.000124875f, 0.898151f,0.0434885f,0.905493f,-0.0319783f,0.371002f,0.000139902f,
0.89713f,0.045886f,0.905231f,-0.033745f,0.372732f,0.000156904f, 0.896075f,0.0482558f,0.904953f,-0.0354864f,0.374587f,0.000176122f,
0.895053f,0.0505894f,0.904652f,-0.0372085f,0.376569f,0.000197839f, 0.893885f,0.0529001f,0.904319f,-0.0389097f,0.378683f,0.000222343f,
0.892687f,0.0551701f,0.903968f,-0.0405861f,0.380933f,0.000249976f, 0.891422f,0.0574099f,0.903571f,-0.0422358f,0.383328f,0.000281144f,
0.890104f,0.0596138f,0.903142f,-0.0438564f,0.385873f,0.000316252f, 0.888728f,0.0617766f,0.902662f,-0.0454521f,0.388574f,0.000355821f,
0.887212f,0.0638923f,0.902145f,-0.0470171f,0.391439f,0.000400367f, 0.885628f,0.065982f,0.901597f,-0.0485529f,0.394476f,0.000450545f,
0.884032f,0.0680064f,0.901012f,-0.0500559f,0.397694f,0.000507037f, 0.882304f,0.0700023f,0.90033f,-0.0515241f,0.401102f,0.000570623f,
0.880633f,0.0719455f,0.899642f,-0.0529573f,0.404713f,0.000642209f, 0.878776f,0.073832f,0.898874f,-0.0543545f,0.408536f,0.000722805f,
0.877058f,0.0756767f,0.898027f,-0.0557149f,0.412584f,0.000813544f, 0.875302f,0.0774545f,0.897076f,-0.0570361f,0.416872f,0.000915708f,
0.873193f,0.0791876f,0.896049f,-0.0583102f,0.421416f,0.00103076f, 0.870926f,0.0808586f,0.894935f,-0.0595422f,0.426232f,0.00116036f,
0.8686f,0.0824536f,0.89373f,-0.0607358f,0.431337f,0.00130641f, 0.866009f,0.0840089f,0.892415f,-0.0618726f,0.436755f,0.00147102f,
0.863614f,0.0854733f,0.891006f,-0.0629696f,0.442504f,0.00165663f, 0.861212f,0.0868616f,0.88942f,-0.0640065f,0.448616f,0.00186607f,
0.858328f,0.0882105f,0.887661f,-0.0649974f,0.455113f,0.00210249f, 0.855303f,0.0894565f,0.88574f,-0.0659335f,0.462029f,0.00236954f,
0.852142f,0.0906238f,0.883692f,-0.0668064f,0.469402f,0.00267146f, 0.849057f,0.0916926f,0.881464f,-0.0676209f,0.47727f,0.00301308f,
0.845508f,0.0926806f,0.878958f,-0.0683752f,0.485678f,0.00340003f, 0.841516f,0.0935999f,0.87615f,-0.0690672f,0.494677f,0.00383879f,
0.837492f,0.0943974f,0.873183f,-0.0696831f,0.50433f,0.00433688f, 0.833451f,0.0950553f,0.869822f,-0.0702289f,0.514703f,0.00490326f,
0.828768f,0.0956311f,0.866109f,-0.0707076f,0.525872f,0.00554823f, 0.823989f,0.0960965f,0.862058f,-0.0711023f,0.537935f,0.00628413f,
0.818496f,0.0964271f,0.857474f,-0.0714127f,0.550996f,0.00712551f, 0.81275f,0.0966352f,0.852463f,-0.0716398f,0.565185f,0.0080898f,
0.806742f,0.0966414f,0.846802f,-0.0717811f,0.580653f,0.00919815f, 0.7996f,0.0965529f,0.840372f,-0.0718154f,0.597593f,0.0104762f,
0.792417f,0.0962841f,0.833362f,-0.0717602f,0.61623f,0.0119556f, 0.78385f,0.0958015f,0.825147f,-0.0715836f,0.636861f,0.0136758f,
0.774884f,0.0951143f,0.815966f,-0.0712996f,0.659846f,0.0156874f, 0.764105f,0.0942374f,0.805333f,-0.0708696f,0.685693f,0.0180557f,
0.752419f,0.0930326f,0.792723f,-0.0703147f,0.715048f,0.0208689f, 0.738285f,0.0915445f,0.77795f,-0.069602f,0.748888f,0.0242508f,
0.721413f,0.0896114f,0.759694f,-0.0687272f,0.788659f,0.028386f, 0.701228f,0.0872244f,0.736892f,-0.0676383f,0.836911f,0.0335805f,
0.674317f,0.0840157f,0.706019f,-0.066292f,0.899029f,0.0404605f, 0.630286f,0.0794949f,0.6562f,-0.0646558f,0.994141f,0.0511471f,
0.899565f,-1.09976e-06f,0.899566f,-9.43474e-17f,0.339943f,3.62082e-05f, 0.89954f,0.0017191f,0.89956f,-0.00127674f,0.339989f,3.64465e-05f,
0.899468f,0.00343098f,0.899528f,-0.00254665f,0.340127f,3.71681e-05f, 0.899333f,0.00514311f,0.899477f,-0.00380872f,0.340359f,3.83845e-05f,
0.899154f,0.00685025f,0.899406f,-0.00507176f,0.340685f,4.01102e-05f, 0.898922f,0.00855835f,0.899313f,-0.00633806f,0.341102f,4.23698e-05f,
0.89864f,0.0102601f,0.899207f,-0.00759721f,0.341615f,4.51988e-05f, 0.898304f,0.0119552f,0.89907f,-0.00884873f,0.342225f,4.86385e-05f,
0.89792f,0.0136467f,0.898914f,-0.0101029f,0.34293f,5.27365e-05f, 0.897489f,0.0153264f,0.898739f,-0.0113461f,0.343735f,5.75537e-05f,
0.897003f,0.0170042f,0.898546f,-0.012583f,0.34464f,6.31582e-05f, 0.896466f,0.0186683f,0.898319f,-0.0138169f,0.345646f,6.96293e-05f,
0.895878f,0.0203238f,0.898074f,-0.0150361f,0.346758f,7.70599e-05f, 0.895243f,0.0219684f,0.8978f,-0.0162536f,0.347974f,8.55547e-05f,
0.894552f,0.0235981f,0.8975f,-0.0174563f,0.349301f,9.52396e-05f, 0.893812f,0.0252207f,0.897179f,-0.0186559f,0.350739f,0.00010625f,
0.893019f,0.0268195f,0.896819f,-0.0198392f,0.352293f,0.000118732f, 0.892175f,0.0284126f,0.896442f,-0.0210102f,0.353965f,0.000132863f,
0.891269f,0.0299897f,0.896022f,-0.0221767f,0.355759f,0.000148856f, 0.890287f,0.0315451f,0.895568f,-0.0233208f,0.357682f,0.000166912f,
0.889257f,0.0330782f,0.895076f,-0.0244543f,0.359734f,0.000187294f, 0.888169f,0.0346021f,0.894548f,-0.0255764f,0.361923f,0.000210285f,
0.887053f,0.0361024f,0.893981f,-0.026682f,0.364253f,0.000236199f, 0.885881f,0.0375721f,0.89337f,-0.0277668f,0.366732f,0.000265398f,
0.884665f,0.0390239f,0.892706f,-0.0288363f,0.369365f,0.00029829f, 0.883335f,0.0404543f,0.891989f,-0.0298872f,0.372158f,0.000335312f,
0.881945f,0.0418574f,0.891232f,-0.0309214f,0.37512f,0.000377007f, 0.880491f,0.043232f,0.890417f,-0.0319356f,0.378259f,0.000423938f,
0.878982f,0.0445831f,0.889554f,-0.0329283f,0.381583f,0.000476752f, 0.877391f,0.0459009f,0.88862f,-0.0338989f,0.385104f,0.000536188f,
0.875669f,0.0471892f,0.887608f,-0.0348475f,0.38883f,0.000603084f, 0.873869f,0.0484496f,0.886515f,-0.0357744f,0.392775f,0.000678384f,
0.872035f,0.0496729f,0.885351f,-0.0366767f,0.396951f,0.000763153f, 0.870183f,0.0508525f,0.884089f,-0.0375476f,0.401374f,0.000858597f,
0.868108f,0.0520084f,0.882756f,-0.0383939f,0.406058f,0.000966077f, 0.865977f,0.053125f,0.881348f,-0.0392169f,0.411018f,0.00108715f,
0.863735f,0.0542009f,0.879783f,-0.0400027f,0.416278f,0.00122362f, 0.861299f,0.0552326f,0.878103f,-0.040767f,0.421854f,0.00137746f,
0.858804f,0.0562213f,0.876297f,-0.041491f,0.427774f,0.00155101f, 0.856204f,0.0571488f,0.87436f,-0.0421855f,0.43406f,0.00174685f,
0.853394f,0.0580501f,0.8723f,-0.0428497f,0.440741f,0.00196808f, 0.850536f,0.0589021f,0.870053f,-0.0434764f,0.447852f,0.00221813f,
0.847355f,0.0596909f,0.867573f,-0.0440638f,0.455428f,0.00250098f, 0.844023f,0.0604187f,0.864925f,-0.044612f,0.463511f,0.00282126f,
0.84047f,0.0610848f,0.86211f,-0.0451166f,0.472146f,0.00318432f, 0.836765f,0.0617025f,0.858984f,-0.045578f,0.481389f,0.00359642f,
0.832823f,0.0622302f,0.855546f,-0.0460024f,0.491294f,0.0040647f, 0.828419f,0.0627275f,0.851901f,-0.0463722f,0.501938f,0.00459781f,
0.82389f,0.0631288f,0.847865f,-0.0467035f,0.513396f,0.00520568f, 0.818967f,0.0634491f,0.84339f,-0.0469778f,0.525767f,0.0059002f,
0.813529f,0.0636962f,0.838552f,-0.0471976f,0.539159f,0.00669546f, 0.807814f,0.0638287f,0.833137f,-0.0473593f,0.553705f,0.00760855f,
0.801447f,0.0638884f,0.827183f,-0.0474555f,0.569566f,0.0086599f, 0.794438f,0.0638276f,0.820505f,-0.0475016f,0.586923f,0.00987466f,
0.786852f,0.0636639f,0.813059f,-0.0474749f,0.606026f,0.0112839f, 0.778375f,0.0633598f,0.804633f,-0.0473748f,0.627164f,0.0129266f,
0.768886f,0.0629348f,0.795076f,-0.0471844f,0.65073f,0.0148525f, 0.757947f,0.0623249f,0.784024f,-0.0469293f,0.677206f,0.0171272f,
0.745566f,0.0615327f,0.771159f,-0.0465711f,0.707298f,0.0198382f, 0.731109f,0.0605463f,0.755964f,-0.0461031f,0.742001f,0.02311f,
0.713322f,0.0592821f,0.737267f,-0.0455274f,0.782797f,0.0271286f, 0.691227f,0.0576569f,0.713689f,-0.0448133f,0.83233f,0.0322067f,
0.661543f,0.0555028f,0.68156f,-0.043931f,0.896078f,0.038979f, 0.614059f,0.052505f,0.630265f,-0.0428451f,0.993928f,0.0496483f,
0.892607f,-1.73117e-06f,0.892605f,2.30277e-17f,0.323064f,3.49186e-05f, 0.892589f,0.000840506f,0.892591f,-0.000626522f,0.323111f,3.51452e-05f,
0.892527f,0.00168044f,0.892556f,-0.00125395f,0.323253f,3.58281e-05f, 0.892425f,0.00252405f,0.892484f,-0.00188317f,0.32349f,3.69769e-05f,
0.892281f,0.00335392f,0.892383f,-0.00250314f,0.323825f,3.86113e-05f, 0.892096f,0.00419159f,0.892259f,-0.00311873f,0.324257f,4.07534e-05f,
0.891869f,0.00502075f,0.892101f,-0.00373582f,0.324786f,4.3432e-05f, 0.891604f,0.00585302f,0.891913f,-0.00435723f,0.325412f,4.66843e-05f,
0.891293f,0.00667908f,0.891704f,-0.00497145f,0.326139f,5.05583e-05f, 0.890944f,0.00750114f,0.891451f,-0.00557988f,0.326968f,5.51121e-05f,
0.890544f,0.00832922f,0.891173f,-0.00619796f,0.3279f,6.04111e-05f, 0.890097f,0.00914362f,0.890859f,-0.00680281f,0.328937f,6.65223e-05f,
0.88961f,0.00994975f,0.890522f,-0.00740199f,0.330081f,7.35309e-05f, 0.889078f,0.0107552f,0.890141f,-0.00800303f,0.331333f,8.15399e-05f,
0.888492f,0.0115591f,0.889729f,-0.00859668f,0.3327f,9.06715e-05f, 0.887868f,0.0123518f,0.889278f,-0.00918768f,0.334179f,0.000101029f,
0.887186f,0.0131384f,0.888792f,-0.00977055f,0.335779f,0.000112777f, 0.886461f,0.0139202f,0.888261f,-0.0103496f,0.3375f,0.00012607f,
0.885685f,0.0146906f,0.887698f,-0.0109264f,0.339345f,0.000141085f, 0.884846f,0.01545f,0.887084f,-0.0114883f,0.341324f,0.000158047f,
0.883965f,0.0162035f,0.886431f,-0.0120493f,0.343435f,0.000177174f, 0.883035f,0.0169527f,0.885734f,-0.0126054f,0.345685f,0.00019873f,
0.882041f,0.0176914f,0.88499f,-0.0131517f,0.348083f,0.000223029f, 0.880996f,0.0184118f,0.884187f,-0.0136851f,0.350631f,0.000250377f,
0.879867f,0.0191239f,0.883337f,-0.014213f,0.353337f,0.000281165f, 0.878691f,0.0198318f,0.882433f,-0.0147349f,0.356207f,0.000315832f,
0.877443f,0.0205211f,0.881457f,-0.0152475f,0.359251f,0.00035484f, 0.876113f,0.0212025f,0.880422f,-0.0157498f,0.362475f,0.000398728f,
0.874708f,0.0218649f,0.879321f,-0.0162418f,0.36589f,0.000448107f, 0.873233f,0.0225185f,0.878144f,-0.0167236f,0.369506f,0.000503667f,
0.871674f,0.0231527f,0.8769f,-0.0171962f,0.373332f,0.000566187f, 0.870052f,0.0237776f,0.87558f,-0.0176601f,0.377381f,0.000636543f,
0.868309f,0.0243788f,0.874166f,-0.0181029f,0.381668f,0.000715731f, 0.866501f,0.0249623f,0.872654f,-0.0185354f,0.386207f,0.000804902f,
0.864545f,0.0255403f,0.87104f,-0.0189652f,0.39101f,0.000905351f, 0.862505f,0.0260831f,0.86933f,-0.019366f,0.3961f,0.00101848f,
0.860339f,0.0266209f,0.867501f,-0.0197682f,0.401492f,0.00114605f, 0.858076f,0.0271344f,0.86557f,-0.02014f,0.407212f,0.00128985f,
0.855661f,0.0276215f,0.863474f,-0.0205061f,0.413279f,0.00145217f, 0.853082f,0.0280965f,0.861227f,-0.0208589f,0.419722f,0.00163544f,
0.850353f,0.0285437f,0.858836f,-0.0211923f,0.426569f,0.00184252f, 0.847465f,0.0289706f,0.856298f,-0.0215063f,0.433856f,0.00207671f,
0.84443f,0.0293566f,0.853554f,-0.0218021f,0.441618f,0.00234182f, 0.841134f,0.0297281f,0.850579f,-0.0220748f,0.449898f,0.00264223f,
0.8376f,0.0300727f,0.847394f,-0.022327f,0.458743f,0.00298303f, 0.83391f,0.0303808f,0.843988f,-0.0225707f,0.468204f,0.00337027f,
0.829904f,0.0306588f,0.840256f,-0.0227773f,0.47835f,0.00381074f, 0.82556f,0.0309088f,0.836236f,-0.0229743f,0.489244f,0.00431279f,
0.820947f,0.0311237f,0.831886f,-0.0231459f,0.500975f,0.00488598f, 0.815927f,0.031283f,0.827112f,-0.023288f,0.513638f,0.00554178f,
0.810452f,0.0314123f,0.821906f,-0.0233988f,0.527348f,0.00629395f, 0.804564f,0.0315004f,0.816182f,-0.0234812f,0.54224f,0.0071589f,
0.798007f,0.0315467f,0.809864f,-0.0235464f,0.558466f,0.00815678f, 0.790933f,0.031536f,0.802886f,-0.0235718f,0.576239f,0.00931205f,
0.782952f,0.0314724f,0.795054f,-0.0235647f,0.595792f,0.0106552f, 0.774162f,0.0313383f,0.786312f,-0.0235164f,0.617433f,0.0122248f,
0.764191f,0.0311329f,0.776364f,-0.0234344f,0.641558f,0.0140701f, 0.752875f,0.0308412f,0.764966f,-0.0233077f,0.66868f,0.016256f,
0.73974f,0.0304734f,0.751713f,-0.0231401f,0.699499f,0.0188703f, 0.724318f,0.0299826f,0.735971f,-0.022911f,0.73505f,0.0220376f,
0.705641f,0.0293622f,0.716881f,-0.0226292f,0.776877f,0.0259465f, 0.682147f,0.0285871f,0.692671f,-0.022283f,0.827646f,0.0309116f,
0.650254f,0.0275311f,0.659787f,-0.0218448f,0.893089f,0.037586f, 0.599335f,0.0260114f,0.60699f,-0.0213004f,0.993712f,0.0482446f,
0.886354f,1.216e-06f,0.886355f,-6.897e-17f,0.306855f,3.36198e-05f, 0.886337f,7.85065e-07f,0.886336f,-1.94809e-16f,0.306903f,3.38347e-05f,
0.886287f,2.72439e-06f,0.886289f,-6.93794e-17f,0.307049f,3.44822e-05f, 0.886192f,-2.00962e-06f,0.886191f,-2.03559e-17f,0.307293f,3.55708e-05f,
0.886069f,7.35653e-07f,0.886067f,1.41563e-17f,0.307633f,3.71148e-05f, 0.885902f,6.72201e-07f,0.885906f,-1.50322e-16f,0.308071f,3.9134e-05f,
0.885698f,-3.0202e-06f,0.885704f,-1.11912e-16f,0.308612f,4.16669e-05f, 0.885461f,1.50858e-06f,0.885456f,-1.87565e-16f,0.309257f,4.47539e-05f,
0.885181f,2.57795e-06f,0.885179f,-1.80216e-17f,0.310002f,4.84203e-05f, 0.884868f,-1.04354e-06f,0.88487f,-1.04323e-16f,0.310846f,5.27121e-05f,
0.884512f,-6.97004e-07f,0.884512f,-5.66788e-17f,0.311798f,5.77068e-05f, 0.884111f,-1.1206e-06f,0.884113f,-4.07709e-17f,0.312862f,6.34842e-05f,
0.883677f,8.54886e-07f,0.883676f,-1.51397e-16f,0.314027f,7.00812e-05f, 0.883195f,-3.1441e-06f,0.883196f,-9.05944e-17f,0.315311f,7.76399e-05f,
0.882666f,-2.44129e-06f,0.882664f,-5.43427e-17f,0.316706f,8.62294e-05f, 0.882106f,3.38295e-06f,0.882104f,3.23682e-17f,0.31822f,9.59793e-05f,
0.881492f,-1.292e-06f,0.881495f,-1.46487e-16f,0.319854f,0.000107024f, 0.880832f,-3.05032e-06f,0.880833f,-5.13005e-17f,0.321614f,0.000119522f,
0.880127f,-3.43787e-06f,0.880131f,-1.17398e-16f,0.323497f,0.0001336f, 0.879374f,-9.59072e-07f,0.879374f,-1.17727e-16f,0.325523f,0.000149549f,
0.878563f,5.91098e-07f,0.878568f,6.61927e-17f,0.32768f,0.000167487f, 0.877704f,1.98025e-06f,0.877702f,-6.17014e-17f,0.329976f,0.000187663f,
0.876783f,-1.05294e-06f,0.876779f,-6.33507e-17f,0.332429f,0.000210451f, 0.875796f,-1.22356e-06f,0.875792f,1.64006e-17f,0.335035f,0.000236091f,
0.874753f,2.16785e-06f,0.874756f,-4.34413e-17f,0.337801f,0.000264929f, 0.873648f,3.03315e-08f,0.873653f,1.19204e-16f,0.340734f,0.000297365f,
0.872485f,7.3677e-07f,0.87248f,-6.40201e-17f,0.343844f,0.000333854f, 0.871242f,3.27686e-06f,0.871246f,-4.25717e-17f,0.347139f,0.0003749f,
0.869931f,-2.6032e-06f,0.869931f,-9.36503e-17f,0.350628f,0.000421071f, 0.868546f,6.01144e-07f,0.868542f,2.23863e-18f,0.354322f,0.000472998f,
0.867077f,-2.6538e-06f,0.867072f,-3.13811e-17f,0.358228f,0.000531385f, 0.865508f,-2.28048e-06f,0.865509f,4.69928e-17f,0.362366f,0.000597138f,
0.863849f,-1.21252e-06f,0.863854f,-1.16615e-16f,0.36675f,0.000671218f, 0.862092f,-2.30027e-06f,0.862088f,-1.65555e-17f,0.371382f,0.000754486f,
0.860242f,5.55917e-07f,0.86024f,-4.29274e-17f,0.376293f,0.000848403f, 0.858269f,4.12411e-07f,0.858276f,1.26475e-17f,0.381489f,0.000954111f,
0.856179f,8.66544e-07f,0.856184f,-6.29662e-17f,0.387002f,0.00107344f, 0.853961f,-3.83648e-06f,0.85396f,-1.68542e-16f,0.392841f,0.00120789f,
0.851605f,-2.60552e-06f,0.851605f,9.08333e-18f,0.399035f,0.00135963f, 0.849088f,1.53608e-06f,0.849087f,1.31648e-16f,0.40562f,0.00153124f,
0.84642f,-4.47186e-06f,0.846424f,-1.20585e-16f,0.412616f,0.00172517f, 0.843572f,4.76009e-07f,0.843563f,-3.60776e-17f,0.420058f,0.00194455f,
0.84053f,-3.53947e-06f,0.84053f,-8.65909e-18f,0.427986f,0.00219308f, 0.837282f,-4.48398e-06f,0.837283f,-5.1921e-17f,0.436448f,0.00247518f,
0.833804f,1.26759e-06f,0.8338f,-2.58378e-17f,0.445481f,0.0027952f, 0.830051f,-3.47487e-06f,0.830058f,-2.09331e-17f,0.45515f,0.00315929f,
0.82605f,-1.40693e-07f,0.826061f,-1.20391e-16f,0.465506f,0.00357354f, 0.821734f,4.24686e-06f,0.821735f,-2.14701e-16f,0.476642f,0.00404671f,
0.817039f,7.08781e-06f,0.817051f,-6.27466e-17f,0.488629f,0.00458747f, 0.811984f,8.87702e-07f,0.811983f,-2.1698e-17f,0.501563f,0.00520679f,
0.806456f,4.41761e-07f,0.806453f,-1.23966e-16f,0.51558f,0.00591896f, 0.800425f,2.54087e-06f,0.80043f,-4.90431e-17f,0.530792f,0.00673851f,
0.793816f,-4.11859e-06f,0.793814f,-7.14266e-17f,0.547387f,0.00768639f, 0.786512f,-1.03073e-06f,0.7865f,-5.77863e-17f,0.565554f,0.00878571f,
0.778392f,-1.75963e-06f,0.778386f,-4.11846e-17f,0.585542f,0.0100664f, 0.769323f,8.51244e-06f,0.769327f,-5.97328e-17f,0.607676f,0.0115672f,
0.759084f,1.32572e-05f,0.759079f,-7.59705e-17f,0.632343f,0.0133356f, 0.747404f,-7.75411e-06f,0.747403f,-2.24015e-16f,0.660095f,0.0154377f,
0.733854f,8.45788e-06f,0.733841f,-6.44747e-17f,0.691648f,0.0179607f, 0.717843f,-3.16466e-06f,0.71784f,-4.99568e-17f,0.728045f,0.0210292f,
0.698404f,7.52705e-09f,0.698395f,4.43038e-17f,0.770889f,0.0248329f, 0.673865f,7.54242e-06f,0.673872f,-1.22832e-16f,0.822965f,0.0296947f,
0.640463f,2.99249e-05f,0.640489f,4.76701e-17f,0.89013f,0.0362789f, 0.586283f,1.17955e-05f,0.586297f,-1.29824e-16f,0.993491f,0.0469292f,
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
