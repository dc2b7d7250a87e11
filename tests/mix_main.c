/* The link-mixing checks of tests/config_check.sh. Built with or without
 * MF_USE_DOUBLE against implementations of either precision: a unit calls a
 * non-inline function (mf_tabulated_from_ndf) and a cold path (GTR Lambda). */
#include "microfacet.h"
#include <stdio.h>

#ifdef MIX_BOTH
double mix_other(void);   /* tests/mix_other.c, the other precision */
#endif

int main(void)
{
    mf_tabulated t;
    mf_ndf g = mf_gtr(MF_R(0.3), MF_R(1.5));
    mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.3));
    mf_vec3 w = mf_vec3_make(MF_R(0.6), MF_R(0.0), MF_R(0.8));
    double a, b = 0.0;
    if (mf_tabulated_from_ndf(&t, &d, 64) != MF_SUCCESS) return 1;
    a = (double)mf_lambda(&g, w);
    mf_tabulated_release(&t);
#ifdef MIX_BOTH
    b = mix_other();
    if (!(b > 0.0) || b - a > 1e-5 * a || a - b > 1e-5 * a) { printf("precisions disagree: %g %g\n", a, b); return 1; }
#endif
    printf("sizeof(mf_real) = %d, GTR Lambda %.7f %.7f\n", (int)sizeof(mf_real), a, b);
    return a > 0.0 ? 0 : 1;
}
