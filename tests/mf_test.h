/* mf_test.h - the tiny test harness of microfacet.h's tests, plus the shared
 * numerical tools (Gauss-Legendre quadrature, chi-square, a fixed-seed RNG).
 * Every check counts as one test; the runner prints "N passed, N failed". */
#ifndef MF_TEST_H
#define MF_TEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stddef.h>

/* The library allocates through the tests' counting allocator
 * (test_fuzzfound.c): it can fail at a chosen call and counts live blocks. */
#ifdef __cplusplus
extern "C" {
#endif
void *mft_malloc(size_t n);
void mft_free(void *p);
/* ... and reports the iterations of every solver loop (test_fuzzfound.c) */
void mft_solver_done(int site, int it, int cap);
/* calls and proposals of the GTR / Student-t rejection samplers (MF__SITE_REJECT) */
extern long mft_reject_calls, mft_reject_tries;
#ifdef __cplusplus
}
#endif
#define MF_MALLOC(n) mft_malloc(n)
#define MF_FREE(p) mft_free(p)
#define MF__SOLVER_DONE(site, it, cap) mft_solver_done((site), (it), (cap))
#include "microfacet.h"

#ifdef __cplusplus
extern "C" {
#endif

extern int mft_passed, mft_failed;
extern int mft_verbose;

/* Tolerance that depends on the build: double or float mf_real. */
#ifdef MF_USE_DOUBLE
#define MFT_TOL(dbl, flt) (dbl)
#define MFT_REAL_NAME "double"
#else
#define MFT_TOL(dbl, flt) (flt)
#define MFT_REAL_NAME "float"
#endif

int mft_check(int ok, const char *file, int line, const char *what);
int mft_near(double got, double want, double rel, double abs_tol, const char *file, int line, const char *what);
#define MFT_CHECK(cond, what) mft_check((cond) ? 1 : 0, __FILE__, __LINE__, what)
#define MFT_NEAR(got, want, rel, abs_tol, what) mft_near((double)(got), (double)(want), rel, abs_tol, __FILE__, __LINE__, what)

/* Deterministic RNG (PCG32), fixed seeds in every test. */
typedef struct { unsigned long long s; } mft_rng;
void mft_seed(mft_rng *r, unsigned long long seed);
double mft_u01(mft_rng *r); /* [0, 1) with 53 bits */

/* Gauss-Legendre: n-point nodes/weights on [0,1] (n <= 16). */
void mft_gl(int n, double *x, double *w);

/* Wilson-Hilferty z-score of a chi-square statistic with k degrees of freedom. */
double mft_chi2_z(double chi2, int k);

/* Chi-square of observed vs expected counts; bins with expected < 5 are pooled
 * (and if the pool expects < 5, it may hold at most 10 more than expected).
 * Returns the z-score; *dof receives the degrees of freedom. */
double mft_chi2(const double *obs, const double *expct, int n, int *dof);

int mft_finite(double x);

/* The robustness checks' special values: v = 0, -0, 1e-30, 1e-7, 0.5, 1, 1.5,
 * 1e30, inf, -1, NaN, -inf; d = the pole, two views, grazing, the +x axis,
 * below, zero, non-unit, NaN and Inf components, near the pole */
void mft_special_values(mf_real v[12], mf_vec3 d[10]);
/* A sampler's record on any input: empty (pdf 0, weight 0), or a finite
 * upper-hemisphere direction with pdf in (0, MF_BIG) and a weight in [0, MF_BIG] */
int mft_record_ok(mf_sample r);

mf_vec3 mft_dir(double theta, double phi);

/* Shared checks (test_sampling.c, test_brdf.c): chi-square of mf_sample_D
 * (visible = 0) or mf_sample_visible against their densities; BRDF sampling
 * against mf_brdf_pdf, weights, reciprocity and the white furnace. rescale /
 * spline: the density's normalization is not tested (GTR spline Lambda). */
void mft_sampler_check(const char *name, const mf_ndf *d, mf_vec3 v, int visible, int n, int rescale,
                       unsigned long long seed);
void mft_brdf_check(const char *name, mf_ndf d, mf_vec3 wo, int n, unsigned long long seed, int spline);

/* Test modules (tests/modules.h). */
#define MFT_MODULE(name) void name(void);
#define MFT_QUICK(name) void name(void);
#include "modules.h"
#undef MFT_MODULE
#undef MFT_QUICK

/* 1 under the runner's --full (make check-all): the long campaigns at their
 * full size (more samples, denser grids); 0 in make test */
extern int mft_full;
/* a sample count: n under --full, else n / 4 (at least 2000); chi-square
 * statistics and sigma-based bounds are computed from the count used */
#define MFT_N(n) (mft_full ? (n) : ((n) / 4 > 2000 ? (n) / 4 : (n) < 2000 ? (n) : 2000))

/* The same inline and cold-path computations, compiled in each unit that
 * calls them: test_tu2 compares its own with those of tests/main.c. The
 * inputs are read through volatile so that no unit folds the math at compile
 * time (gcc folds exp, log... correctly rounded, the library at run time may
 * differ by an ulp). */
#define MFT_TU_VALUES 16
static inline void mft_tu_values(double *out)
{
    static volatile double in[6] = { 0.2, 0.3, 1.5, 3.0, 0.36, 0.48 };
    mf_real a = (mf_real)in[0], b = (mf_real)in[1], wx = (mf_real)in[4], wy = (mf_real)in[5];
    mf_ndf k[4];
    mf_vec3 wo = mf_vec3_make(wx, wy, MF_SQRT(MF_R(1.0) - wx * wx - wy * wy)), wi = mf_vec3_make(-wy, wx, wo.z);
    int i;
    k[0] = mf_ggx(a, b);
    k[1] = mf_beckmann(a, b);
    k[2] = mf_gtr(a, (mf_real)in[2]);
    k[3] = mf_student_t(a, b, (mf_real)in[3]);
    for (i = 0; i < 4; ++i) {
        mf_vec3 m = mf_sample_visible(&k[i], wo, MF_R(0.3), MF_R(0.7));
        out[4 * i] = (double)mf_D(&k[i], m);
        out[4 * i + 1] = (double)mf_lambda(&k[i], wo);
        out[4 * i + 2] = (double)m.x + (double)mf_sample_D(&k[i], MF_R(0.6), MF_R(0.2)).y;
        out[4 * i + 3] = (double)mf_brdf(&k[i], wo, wi) + (double)mf_brdf_pdf(&k[i], wo, wi);
    }
}
void mft_tu_values_main(double *out);   /* tests/main.c */

#ifndef MF_NO_IBM
/* IBM build options (resolution, cut) for mf_ibm_build_ex, and the bytes a
 * saved map needs (mf_ibm_save's size query) */
static inline const mf_ibm_options *mft_ibm_o(int resolution, mf_real cut_sigmas)
{
    static mf_ibm_options o;
    o.resolution = resolution;
    o.cut_sigmas = cut_sigmas;
    return &o;
}
static inline size_t mft_ibm_bytes(const mf_ibm *ibm)
{
    size_t n = 0;
    mf_ibm_save(ibm, NULL, 0, &n);
    return n;
}
#endif

/* Families of distributions over alpha for mf_ltc_table_build */
static inline mf_ndf mft_family_ggx(mf_real a, void *c) { (void)c; return mf_ggx(a, a); }
static inline mf_ndf mft_family_beckmann(mf_real a, void *c) { (void)c; return mf_beckmann(a, a); }

/* Distributions under test, built from a parameter table. */
typedef struct { const char *name; int kind; double ax, ay, gamma; } mft_case;
mf_ndf mft_make(const mft_case *c);
mf_ndf mft_gtr(double alpha, double gamma);   /* mf_gtr through an mf_gtr_table */
extern const mft_case mft_cases[];
extern const int mft_ncases;

#ifdef __cplusplus
}
#endif
#endif
