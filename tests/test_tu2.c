/* A second translation unit that includes the header without the
 * implementation: it links with the first (tests/main.c, which holds the
 * implementation), and the inline and cold paths give bit-identical results
 * in both units. */
#include "mf_test.h"

void test_tu2(void)
{
    double here[MFT_TU_VALUES], there[MFT_TU_VALUES];
    int i, same = 1;
    mf_ndf d = mf_ggx(MF_R(0.25), MF_R(0.25));
    mft_tu_values(here);
    mft_tu_values_main(there);
    for (i = 0; i < MFT_TU_VALUES; ++i) same = same && here[i] == there[i] && mft_finite(here[i]);
    MFT_CHECK(same, "two translation units: D, Lambda, samples, BRDF of GGX, Beckmann, GTR, Student-t agree bit for bit");
    MFT_NEAR(mf_D(&d, mf_vec3_make(0, 0, 1)), 1.0 / (3.14159265358979323846 * 0.0625), MFT_TOL(1e-12, 1e-6), 0,
             "second translation unit: D");
    MFT_CHECK(mf_result_string(MF_ERROR_INVALID_DATA)[0] == 'i', "second translation unit: mf_result_string links");
}
