/* Test runner: runs every module, ends with "N passed, N failed". */
#define MICROFACET_IMPLEMENTATION
#include "mf_test.h"
#include <stdlib.h>
#include <time.h>

int mft_passed = 0, mft_failed = 0, mft_verbose = 0;

int mft_check(int ok, const char *file, int line, const char *what)
{
    if (ok) ++mft_passed;
    else {
        ++mft_failed;
        printf("FAIL %s:%d: %s\n", file, line, what);
    }
    return ok;
}

int mft_finite(double x) { return x == x && x - x == 0.0; }

int mft_near(double got, double want, double rel, double abs_tol, const char *file, int line, const char *what)
{
    double err = fabs(got - want);
    int ok = mft_finite(got) && err <= abs_tol + rel * fabs(want);
    if (!ok || mft_verbose) printf("%s %s:%d: %s: got %.12g want %.12g (err %.3g, rel %.3g)\n",
                                   ok ? "ok  " : "FAIL", file, line, what, got, want, err,
                                   want != 0.0 ? err / fabs(want) : err);
    return mft_check(ok, file, line, what) ;
}

void mft_seed(mft_rng *r, unsigned long long seed) { r->s = seed * 6364136223846793005ULL + 1442695040888963407ULL; }

static unsigned mft_next32(mft_rng *r)
{
    unsigned long long old = r->s;
    unsigned xs, rot;
    r->s = old * 6364136223846793005ULL + 1442695040888963407ULL;
    xs = (unsigned)(((old >> 18u) ^ old) >> 27u);
    rot = (unsigned)(old >> 59u);
    return (xs >> rot) | (xs << ((32u - rot) & 31u));
}

double mft_u01(mft_rng *r)
{
    unsigned long long a = mft_next32(r) >> 5, b = mft_next32(r) >> 6;
    return ((double)a * 67108864.0 + (double)b) * (1.0 / 9007199254740992.0);
}

void mft_gl(int n, double *x, double *w)
{
    /* Newton on the Legendre polynomial, nodes mapped to [0,1] */
    int i, j;
    for (i = 0; i < n; ++i) {
        double z = cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5)), pp = 0.0, z1;
        do {
            double p1 = 1.0, p2 = 0.0;
            for (j = 0; j < n; ++j) {
                double p3 = p2;
                p2 = p1;
                p1 = ((2.0 * j + 1.0) * z * p2 - j * p3) / (j + 1);
            }
            pp = n * (z * p1 - p2) / (z * z - 1.0);
            z1 = z;
            z = z1 - p1 / pp;
        } while (fabs(z - z1) > 1e-15);
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * pp * pp);
    }
}

double mft_chi2_z(double chi2, int k)
{
    double h = 2.0 / (9.0 * k);
    return (pow(chi2 / k, 1.0 / 3.0) - (1.0 - h)) / sqrt(h);
}

double mft_chi2(const double *obs, const double *expct, int n, int *dof)
{
    double chi2 = 0.0, po = 0.0, pe = 0.0;
    int i, k = 0;
    for (i = 0; i < n; ++i) {
        if (expct[i] < 5.0) { po += obs[i]; pe += expct[i]; continue; }
        chi2 += (obs[i] - expct[i]) * (obs[i] - expct[i]) / expct[i];
        ++k;
    }
    if (pe >= 5.0) {
        chi2 += (po - pe) * (po - pe) / pe;
        ++k;
    }
    *dof = k - 1 > 0 ? k - 1 : 1;
    /* a pooled remainder too small for the statistic must still hold few samples */
    if (pe < 5.0 && po > pe + 10.0) return 1e3;
    return mft_chi2_z(chi2, *dof);
}

mf_vec3 mft_dir(double theta, double phi)
{
    return mf_vec3_make((mf_real)(sin(theta) * cos(phi)), (mf_real)(sin(theta) * sin(phi)), (mf_real)cos(theta));
}

const mft_case mft_cases[] = {
    { "beckmann 0.02", MF_NDF_BECKMANN, 0.02, 0.02, 0 },
    { "beckmann 0.3x0.1", MF_NDF_BECKMANN, 0.3, 0.1, 0 },
    { "beckmann 1.0", MF_NDF_BECKMANN, 1.0, 1.0, 0 },
    { "ggx 0.02", MF_NDF_GGX, 0.02, 0.02, 0 },
    { "ggx 0.5x0.05", MF_NDF_GGX, 0.5, 0.05, 0 },
    { "ggx 1.0", MF_NDF_GGX, 1.0, 1.0, 0 },
    { "gtr 0.02 g0.5", MF_NDF_GTR, 0.02, 0.02, 0.5 },
    { "gtr 0.2 g1", MF_NDF_GTR, 0.2, 0.2, 1.0 },
    { "gtr 0.5 g1.7", MF_NDF_GTR, 0.5, 0.5, 1.7 },
    { "gtr 0.3 g2", MF_NDF_GTR, 0.3, 0.3, 2.0 },
    { "gtr 0.6 g3", MF_NDF_GTR, 0.6, 0.6, 3.0 },
    { "gtr 0.1 g4", MF_NDF_GTR, 0.1, 0.1, 4.0 },
    { "gtr 1.0 g2.5", MF_NDF_GTR, 1.0, 1.0, 2.5 },
    { "student 0.05 g1.6", MF_NDF_STUDENT_T, 0.05, 0.05, 1.6 },
    { "student 0.4x0.1 g3", MF_NDF_STUDENT_T, 0.4, 0.1, 3.0 },
    { "student 0.8 g10", MF_NDF_STUDENT_T, 0.8, 0.8, 10.0 },
    { "student 0.2 g2", MF_NDF_STUDENT_T, 0.2, 0.2, 2.0 },
};
const int mft_ncases = (int)(sizeof(mft_cases) / sizeof(mft_cases[0]));

/* GTR with its Lambda rule in a table (a ring of 64, one per call): Lambda at
 * a non-integer gamma at full speed (test_ndf checks that mf_gtr by value
 * gives the same bits) */
mf_ndf mft_gtr(double alpha, double gamma)
{
    static mf_gtr_table tabs[64];
    static unsigned next = 0;
    mf_gtr_table *t = &tabs[next++ & 63u];
    mf_gtr_table_build(t, (mf_real)alpha, (mf_real)gamma);
    return mf_gtr_table_ndf(t);
}

mf_ndf mft_make(const mft_case *c)
{
    switch (c->kind) {
    case MF_NDF_BECKMANN: return mf_beckmann((mf_real)c->ax, (mf_real)c->ay);
    case MF_NDF_GGX: return mf_ggx((mf_real)c->ax, (mf_real)c->ay);
    case MF_NDF_GTR: return mft_gtr(c->ax, c->gamma);
    default: return mf_student_t((mf_real)c->ax, (mf_real)c->ay, (mf_real)c->gamma);
    }
}

void mft_tu_values_main(double *out) { mft_tu_values(out); }

/* Modules named on the command line run (all when none is named); -v prints
 * every check. Each module says when it starts, so its information lines sit
 * under its own name, and ends with its count and CPU time. */
static int mft_argc;
static char **mft_argv;
static int mft_selected(const char *name)
{
    int i, any = 0;
    for (i = 1; i < mft_argc; ++i) {
        if (!strcmp(mft_argv[i], "-v")) continue;
        any = 1;
        if (!strcmp(mft_argv[i], name)) return 1;
    }
    return !any;
}

static void mft_run(const char *name, void (*fn)(void))
{
    int f0 = mft_failed, p0 = mft_passed;
    clock_t t0;
    if (!mft_selected(name)) return;
    printf("  %s ...\n", name);
    t0 = clock();
    fn();
    printf("  %-17s %d passed, %d failed  (%.1f s)\n", name, mft_passed - p0, mft_failed - f0,
           (double)(clock() - t0) / CLOCKS_PER_SEC);
}

int main(int argc, char **argv)
{
    int i;
    mft_argc = argc;
    mft_argv = argv;
    for (i = 1; i < argc; ++i)
        if (!strcmp(argv[i], "-v")) mft_verbose = 1;
    setvbuf(stdout, NULL, _IOLBF, 0); /* stream progress through a pipe */
    printf("microfacet.h tests, mf_real = %s, %s\n", MFT_REAL_NAME,
#ifdef __cplusplus
           "C++"
#else
           "C"
#endif
    );
#define MFT_RUN(name) mft_run(#name, name)
    MFT_RUN(test_core);
    MFT_RUN(test_ndf);
    MFT_RUN(test_sampling);
    MFT_RUN(test_brdf);
    MFT_RUN(test_ltmd);
    MFT_RUN(test_ltc);
    MFT_RUN(test_ltc_shapes);
    MFT_RUN(test_leadr);
    MFT_RUN(test_tabulated);
    MFT_RUN(test_ibm);
    MFT_RUN(test_microsurface);
    MFT_RUN(test_materials);
    MFT_RUN(test_dielectric);
    MFT_RUN(test_energy);
    MFT_RUN(test_material_lobes);
    MFT_RUN(test_sheen);
    MFT_RUN(test_robust);
    MFT_RUN(test_samplers);
    MFT_RUN(test_fuzzfound);
    MFT_RUN(test_float);
    MFT_RUN(test_tu2);
    printf("%d passed, %d failed\n", mft_passed, mft_failed);
    return mft_failed ? 1 : 0;
}
