/* The precision-guard checks of tests/config_check.sh, first file: only
 * inline functions, no implementation. guard_make hands its mf_ndf to another
 * file (wrong when that file has the other precision: the link must fail);
 * guard_value keeps it to itself (right in any program). */
#include "microfacet.h"

mf_ndf guard_make(void);
double guard_value(void);

mf_ndf guard_make(void) { return mf_ggx(MF_R(0.3), MF_R(0.3)); }

double guard_value(void)
{
    mf_ndf d = guard_make();
    return (double)mf_brdf(&d, mf_vec3_make(MF_R(0.6), MF_R(0.0), MF_R(0.8)),
                           mf_vec3_make(MF_R(-0.3), MF_R(0.1), MF_R(0.9486833)));
}
