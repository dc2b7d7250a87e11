/* A second translation unit that includes the header without the
 * implementation: the two link together (and inline functions agree). */
#include "mf_test.h"

void test_tu2(void)
{
    mf_ndf d = mf_ggx(MF_R(0.25), MF_R(0.25));
    MFT_NEAR(mf_D(&d, mf_vec3_make(0, 0, 1)), 1.0 / (3.14159265358979323846 * 0.0625), MFT_TOL(1e-12, 1e-6), 0,
             "second translation unit: D");
    MFT_CHECK(mf_result_string(MF_ERROR_INVALID_DATA)[0] == 'i', "second translation unit: mf_result_string links");
}
