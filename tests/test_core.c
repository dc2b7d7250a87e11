/* Small math: vectors, frames, special functions. */
#include "mf_test.h"

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
        mf_frame(n, &t, &b);
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
    MFT_CHECK(MF_VERSION_MAJOR == 0 && MF_VERSION_MINOR == 2 && MF_VERSION_PATCH == 0, "version macros");
}
