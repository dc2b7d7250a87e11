/* The other precision's half of the both-precisions program (tests/config_check.sh):
 * compiled with the opposite MF_USE_DOUBLE of tests/mix_main.c, with its own
 * implementation. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"

double mix_other(void)
{
    mf_ndf g = mf_gtr(MF_R(0.3), MF_R(1.5));
    return (double)mf_lambda(&g, mf_vec3_make(MF_R(0.6), MF_R(0.0), MF_R(0.8)));
}
