/* microfacet.h - microfacet BRDF/NDF math in one dependency-free C header.
 * Version 0.4.0.  MIT licensed (see the end of this file).
 *
 * QUICK START
 *
 *     #include "microfacet.h"     // in every file that uses it
 *     // in exactly one C or C++ file per precision the program uses, before
 *     // the include, even if it calls only inline functions (without it the
 *     // link fails on mf_precision_is_float_... or mf_precision_is_double_...,
 *     // as it does when files disagree on MF_USE_DOUBLE):
 *     #define MICROFACET_IMPLEMENTATION
 *
 *     mf_ndf    d  = mf_ggx(0.3f, 0.1f);                    // anisotropic GGX
 *     mf_vec3   wo = mf_vec3_make(0.3f, 0.2f, 0.93f);       // unit, local frame
 *     mf_sample s  = mf_brdf_sample(&d, wo, u1, u2);       // u in [0, 1]
 *     if (s.lobe != MF_LOBE_NONE) {                        // else: no sample
 *         // s.wi, s.pdf (per solid angle), s.weight = f cos / pdf = G2 / G1(wo)
 *         mf_real f = mf_brdf(&d, wo, s.wi);               // D G2 / (4 |wo.z| |wi.z|)
 *     }
 *     // every sampler returns this record: mf_brdf_sample_bounded,
 *     // mf_dielectric_sample (with an mf_transport), mf_brdf_ms_sample, ...
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
 *         Newton steps for the numerical samplers)
 *   == 4b. Utilities: the rejection samplers' random stream, quadrature rules
 *          (Gauss-Legendre, Gauss-Jacobi); PCG32, sorting, selection and an
 *          FFT for the microsurface generator and the gonioreflectometer
 *   == 5. Distributions: the mf_ndf value type, its kinds (MF__NDF_KINDS
 *         and their traits) and the inline front ends of the one dispatch
 *   == 5b. Numerical visible-normal sampling of the heavy-tailed kinds and
 *          of Charlie (through the trait ISO)
 *   == 6. Distribution kinds, one module each: Beckmann, Charlie (sheen),
 *         GGX, GTR, LEADR (non-centered Beckmann), Student-t, tabulated
 *         (piecewise-linear)
 *   == 7. The kinds' dispatch: the cold switches of the generic operations
 *   == 8. Linearly transformed microsurfaces: any 2x2 transform of any
 *         distribution, stretch anisotropy, deformation tracking; mf_D
 *   == 9. Smith masking: Lambda, G1, G2 (height-correlated, separable), D_visible
 *   == 9b. Tabulating any distribution (mf_tabulated_from_ndf)
 *   == 10. Sampling: NDF (D cos) and visible normals (VNDF) for every kind
 *   == 11. Specular microfacet BRDF: eval, sample, pdf; GGX bounded VNDF
 *         sampling; Fresnel averages
 *   == 11b. Rough dielectric BSDF (reflection and transmission), refraction
 *   == 12. LEADR slope moments: the linear type, deformation, height scaling,
 *          mean normal, covariance; moment mip maps
 *   == 13. Linearly Transformed Cosines: eval, sample, polygon integration with
 *          horizon clipping, vector form factor, sphere lights, multi-scale
 *          roughness, fitting and tables
 *   == 13a. LTC of anisotropic GGX: lookup in the view's azimuth, symmetries
 *   == 13b. LTC light shapes: ellipses, disks, lines, tubes, textured quads
 *   == 14. The built-in GGX and Beckmann LTC tables (generated data)
 *   == 14a. The built-in anisotropic GGX LTC table (generated data)
 *   == 15. Inverse Bin Map: compact integral histograms of normal maps;
 *          overview, the mf_ibm type and its packed bit format
 *   == 15b. IBM footprints: periods, pieces, exact areas
 *   == 15c. IBM bin weights: the kd-tree traversal
 *   == 15d. IBM filtered glint BRDF, sampling and pdf
 *   == 15e. IBM build, save, load
 *   == 16. Microsurface generation from any distribution
 *   == 16b. A virtual gonioreflectometer
 *   == 17. The built-in GGX and Beckmann albedo tables (generated data)
 *   == 18. Energy compensation (Kulla & Conty 2017): albedo, the multiple-
 *          scattering lobe and its sampling, Turquin scaling, table builders
 *          for any kind, rough dielectrics of a given eta
 *   == 19. F82-tint and thin-film Fresnel
 *   == 20. EON: energy-preserving Oren-Nayar diffuse
 *   == 21. Sheen: the Charlie distribution with its exact Smith Lambda
 *   == 97. Deprecated 0.3 names (MF_NO_DEPRECATED drops them)
 *
 * ADDING A DISTRIBUTION KIND
 *
 *   1. Write src/06_kind_<name>.h (06_kind_ggx.h shows the layout of an
 *      inline kind, 06_kind_student_t.h of a cold one): its parameter struct
 *      mf_ndf_<name> in the @decl part (at most a pointer and six mf_real:
 *      mf_ndf stays within 64 bytes in float; larger data goes in a built
 *      object it points to, like mf_tabulated or mf_gtr_table), a constructor
 *      that fills mf_ndf through mf__ndf_init, and mf__<name>_D, _lambda,
 *      _sample_D and _sample_visible (contract in 05_ndf.h). A kind may use
 *      modules 1-5b and the kinds whose files sort before its own, nothing
 *      later (tools/prefix_check.sh, run by `make header`, checks it);
 *      07_ndf_dispatch.h then reaches it through its traits by itself.
 *   2. Add its line X(NAME, name, INL, CEN, ISO, TR, ETAB, AXES, PREP) to
 *      MF__NDF_KINDS in src/05_ndf.h: the digits are its traits (what the
 *      front ends inline, whether its mean slope is 0, which numerical
 *      sampler, Trowbridge-Reitz forms, energy table, isotropy
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
 *     are clamped to it (NaN: 0), 1 read as MF_U_MAX, the largest mf_real
 *     below 1. A sample record never carries a zero pdf:
 *     mf_brdf_sample returns a direction only
 *     where mf_brdf_pdf is positive.
 *   - Transforms: mf_transform_is_valid also requires |det M| > 1/MF_BIG, so
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
 *                           (one file per precision of every program; see
 *                           the precision guard in section 1)
 *   MFDEF                   storage of non-inline functions (default extern)
 *   MF_MALLOC(n) / MF_FREE(p)  allocator pair (default malloc/free); define
 *                           both or neither (one alone is an #error)
 *   MF_NO_LEADR, MF_NO_LTC_TABLE, MF_NO_IBM, MF_NO_MICROSURFACE,
 *   MF_NO_ENERGY_TABLES     leave out a module (see section 1)
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
 *   CHANGELOG.md (beside this header in its repository) lists every change
 *   of API or numeric output by version.
 */
