/* A program that uses microfacet.h as an installed or vendored package: it
 * checks that the header it got is the version the package announced. */
#define MICROFACET_IMPLEMENTATION
#include <microfacet.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    char got[32];
    mf_ndf d = mf_ggx(0.3f, 0.3f);
    mf_vec3 wo = mf_vec3_make(0.0f, 0.6f, 0.8f);
    mf_real f = mf_brdf(&d, wo, wo);
    sprintf(got, "%d.%d.%d", MF_VERSION_MAJOR, MF_VERSION_MINOR, MF_VERSION_PATCH);
#ifdef MF_EXPECT_VERSION
    if (strcmp(got, MF_EXPECT_VERSION) != 0) {
        printf("header %s, package %s\n", got, MF_EXPECT_VERSION);
        return 1;
    }
#endif
    if (!(f > 0.0f)) return 1;
    printf("microfacet %s: brdf %.4f\n", got, (double)f);
    return 0;
}
