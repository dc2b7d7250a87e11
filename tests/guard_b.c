/* The precision-guard checks of tests/config_check.sh, second file (the main
 * program): with GUARD_MIX it reads an mf_ndf made in tests/guard_a.c, which
 * is a float/double mix when the two files differ in MF_USE_DOUBLE; without
 * it the files exchange only a double, and their two BRDF values must agree. */
#include "microfacet.h"
#include <stdio.h>

mf_ndf guard_make(void);
double guard_value(void);

int main(void)
{
    mf_vec3 wo = mf_vec3_make(MF_R(0.6), MF_R(0.0), MF_R(0.8));
    mf_vec3 wi = mf_vec3_make(MF_R(-0.3), MF_R(0.1), MF_R(0.9486833));
#ifdef GUARD_MIX
    mf_ndf d = guard_make();
#else
    mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
#endif
    double here = (double)mf_brdf(&d, wo, wi), there = guard_value();
    printf("f = %.7f here, %.7f in guard_a.c\n", here, there);
    return here > 0.0 && here - there < 1e-5 * here && there - here < 1e-5 * here ? 0 : 1;
}
