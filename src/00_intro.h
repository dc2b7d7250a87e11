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
 *   1. Write src/06_kind_<name>.h (06_kind_ggx.h shows the layout of an
 *      inline kind, 06_kind_student_t.h of a cold one): its parameter struct
 *      mf_ndf_<name> in the @decl part (at most a pointer and six mf_real:
 *      mf_ndf stays within 64 bytes in float; larger data goes in a built
 *      object it points to, like mf_tabulated or mf_gtr_table), a constructor
 *      that fills mf_ndf through mf__ndf_init, and mf__<name>_D, _lambda,
 *      _sample_D and _sample_visible (contract in 05_ndf.h).
 *   2. Add its line X(NAME, name, INL, CEN, ISO, LTC, TR, ETAB, AXES, PREP) to
 *      MF__NDF_KINDS in src/05_ndf.h: the digits are its traits (what the
 *      front ends inline, whether its mean slope is 0, which numerical
 *      sampler, LTC family, Trowbridge-Reitz forms, energy table, isotropy
 *      at ax = ay, built object), and each trait names the functions the
 *      module must then define (05_ndf.h lists them). Other modules never
 *      test a kind by name; they ask its traits (tests/kind_names_check.sh,
 *      part of `make test`, counts such tests).
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
 *          mixture of GGX, gamma-3 or gamma-4 GTR, with 4-24 nodes as alpha
 *          falls; 4.7-18.4x GGX's Lambda in float; the rule lives in an
 *          mf_gtr_table, mf_gtr_table_build / mf_gtr_table_ndf, and mf_gtr
 *          at a non-integer gamma builds it at each call of Lambda); mf_ndf
 *          is 64 bytes in float, 128 in double (was 376 and 720): M^-1 is
 *          derived from M and 1 / det M, type is a byte, each kind's parameters fit in
 *          32 bytes (LEADR keeps its covariance, Student-t the envelope's
 *          masses; the rest is derived where used); every kind's traits are
 *          digits of its line in MF__NDF_KINDS, which no other module
 *          bypasses by testing a kind by name, and an unknown kind is no
 *          distribution (0, no sample: two fallbacks took it for Student-t,
 *          mf_sample_D for a delta at the normal); GTR and Student-t NDF
 *          sampling by the closed-form inverse CDF with one pow (1.7-2.4x
 *          GGX), visible normals by exact rejection from GGX and from exact
 *          GGX mixtures (2.7-4.6x GGX; was 115-160); no lost samples at
 *          grazing views for any kind. LTC: rational
 *          edge, one normalization per vertex; tables store M^-1 with a unit
 *          middle entry (the published normalization: the raw data of
 *          mf_ltc_ggx_table, mf_ltc_table and mf_ltc_fit_result.inv changed
 *          meaning), mf_ltc_table_export_rgba16f (the published ltc_1 and
 *          ltc_2 textures in ltc_code's layout and channel order, the
 *          horizon-clipped sphere table in ltc_2.w). MF_FORCE_INLINE on the hot
 *          paths; Beckmann visible normals in closed form at normal
 *          incidence; mf_clamp as a max and a min (no compare-and-blend at
 *          -march=native); faster IBM queries and build (the build 1.3-1.6x
 *          the first 0.3.0 builder's on flake, smooth and rough maps), in
 *          map format 2 (MF_IBM_VERSION 2, smaller: maps saved by 0.2.0
 *          are rebuilt); MF_FAST_MATH; solver iteration
 *          caps reported to tests (MF__SOLVER_DONE). The slope-space and GGX
 *          visible-normal samplers take their azimuth from a polynomial
 *          (CUDA's sincospi on the device) instead of libm sin / cos.
 */
