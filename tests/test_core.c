/* Small math: vectors, frames, special functions. */
#include "mf_test.h"
#include <stdio.h>

/* The header states its version in its first lines ("Version X.Y.Z.") and in
 * the newest REVISIONS entry; both must match the MF_VERSION_* macros. */
static int version_documented(void)
{
    char line[256], want[64], rev[64];
    int top = 0, newest = -1;
    FILE *f = fopen("microfacet.h", "r");
    if (!f) return 0;
    snprintf(want, sizeof want, "Version %d.%d.%d.", MF_VERSION_MAJOR, MF_VERSION_MINOR, MF_VERSION_PATCH);
    snprintf(rev, sizeof rev, "## %d.%d.%d", MF_VERSION_MAJOR, MF_VERSION_MINOR, MF_VERSION_PATCH);
    while (fgets(line, sizeof line, f)) {
        if (strstr(line, " * Version ") == line) top = strstr(line, want) != NULL;
        if (strstr(line, "#ifndef MICROFACET_H")) break;
    }
    fclose(f);
    /* the newest entry of CHANGELOG.md is the first "## N.N.N" heading */
    f = fopen("CHANGELOG.md", "r");
    if (!f) return 0;
    while (newest < 0 && fgets(line, sizeof line, f))
        if (!strncmp(line, "## ", 3) && line[3] >= '0' && line[3] <= '9') newest = !strncmp(line, rev, strlen(rev));
    fclose(f);
    return top && newest == 1;
}

void test_core(void)
{
    int i;
    mft_rng r;
    double worst = 0.0;
    mft_seed(&r, 1);
    /* frame: orthonormal and right-handed for random normals, including poles */
    for (i = 0; i < 200; ++i) {
        mf_vec3 n = i == 0 ? mf_vec3_make(0, 0, 1) : i == 1 ? mf_vec3_make(0, 0, -1)
                  : mf_normalize(mf_vec3_make((mf_real)(mft_u01(&r) - .5), (mf_real)(mft_u01(&r) - .5), (mf_real)(mft_u01(&r) - .5)));
        mf_vec3 t, b, c;
        double e;
        { mf_basis fr_ = mf_basis_from_normal(n); t = fr_.t; b = fr_.b; }
        c = mf_cross(t, b);
        e = fabs(mf_dot(t, n)) + fabs(mf_dot(b, n)) + fabs(mf_dot(t, b)) + fabs(mf_dot(t, t) - 1) +
            fabs(mf_dot(b, b) - 1) + fabs(c.x - n.x) + fabs(c.y - n.y) + fabs(c.z - n.z);
        if (e > worst) worst = e;
    }
    MFT_CHECK(worst < MFT_TOL(1e-12, 1e-5), "mf_frame orthonormal, t x b = n");
    {
        mf_vec3 z = mf_normalize(mf_vec3_make(0, 0, 0));
        MFT_CHECK(z.x == 0 && z.y == 0 && z.z == 0, "normalize(0) = 0");
    }
    /* erfinv against erf */
    worst = 0.0;
    for (i = 1; i < 2000; ++i) {
        double y = -1.0 + 2.0 * i / 2000.0, x = mf_erfinv((mf_real)y);
        double e = fabs(erf(x) - y);
        if (e > worst) worst = e;
    }
    MFT_CHECK(worst < MFT_TOL(1e-14, 1e-6), "erfinv(erf) round trip");
    MFT_CHECK(mft_finite(mf_erfinv(1)) && mft_finite(mf_erfinv(-1)), "erfinv(+-1) finite");
    /* incomplete beta against known values: I_x(1, 1/2) = 1 - sqrt(1 - x), I_x(a,1) = x^a */
    worst = 0.0;
    for (i = 1; i < 100; ++i) {
        double x = i / 100.0;
        double e1 = fabs(mf__betainc(1, 0.5, (mf_real)x, (mf_real)log(2.0)) - (1 - sqrt(1 - x)));
        double e2 = fabs(mf__betainc(2.5, 1, (mf_real)x, (mf_real)log(1 / 2.5)) - pow(x, 2.5));
        if (e1 > worst) worst = e1;
        if (e2 > worst) worst = e2;
    }
    MFT_CHECK(worst < MFT_TOL(1e-13, 2e-6), "incomplete beta closed forms");
    MFT_CHECK(!strcmp(mf_result_string(MF_SUCCESS), "success"), "mf_result_string");
    MFT_CHECK(strcmp(mf_result_string(MF_ERROR_INVALID_ARGUMENT), "unknown result") != 0, "error names");
    MFT_CHECK(version_documented(), "version macros match the header's top comment and CHANGELOG.md's newest entry");
#if !defined(__FAST_MATH__)
    MFT_CHECK(MF_FAST_MATH == 0, "MF_FAST_MATH is 0 without -ffast-math");
#endif
}
