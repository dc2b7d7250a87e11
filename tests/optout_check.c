/* Compiled by tests/config_check.sh under -Werror with each module opt-out
 * (MF_NO_LEADR, MF_NO_LTC_TABLE, MF_NO_IBM, MF_NO_MICROSURFACE) and with all
 * of them: the header must compile cleanly, the opted-out module must be
 * gone, and the rest must still work. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"

#if defined(MF_NO_IBM) && defined(MF_IBM_MAGIC)
#error "MF_NO_IBM left the Inverse Bin Map in"
#endif
#if defined(MF_NO_MICROSURFACE) && defined(MF_FACET_MIRROR)
#error "MF_NO_MICROSURFACE left microsurface generation in"
#endif
#if defined(MF_NO_LEADR) && defined(MF_LEADR_GRID_MAX)
#error "MF_NO_LEADR left the LEADR moments in"
#endif

int main(void)
{
    mf_ndf d = mf_ggx(MF_R(0.3), MF_R(0.2));
    mf_vec3 wo = mf_vec3_make(MF_R(0.3), MF_R(0.2), MF_R(0.93));
    mf_vec3 wi = mf_brdf_sample(&d, wo, MF_R(0.4), MF_R(0.7)).wi;
    mf_real f = mf_brdf(&d, wo, wi) + mf_brdf_pdf(&d, wo, wi);
#ifndef MF_NO_LTC_TABLE
    mf_ltc l = mf_ltc_ggx(MF_R(0.5), MF_R(0.3));
    f += mf_ltc_eval(&l, wo);
    f += mf_sheen_brdf(wo, wi, MF_R(0.5));
#endif
#ifndef MF_NO_LEADR
    f += mf_leadr_specular(mf_leadr_with_roughness(mf_leadr_from_slope(MF_R(0.1), MF_R(0.0)), MF_R(0.2), MF_R(0.2)), wo, wi);
#endif
    return f > MF_R(0.0) ? 0 : 1;
}
