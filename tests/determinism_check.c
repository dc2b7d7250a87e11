/* Part of `make test` (tests/config_check.sh): the samplers are functions of
 * their uniforms alone, whatever compiles them. Built by each compiler at
 * hand (contraction off), this prints a digest of the bits of samples from
 * every kind and operation that draws more uniforms from a hash of (u1, u2)
 * (GTR's and Student-t's rejection samplers, their numerical fallback) or
 * branches on them; the digests must agree. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <string.h>

static unsigned long long digest = 1469598103934665603ull;
static void eat(mf_real x)
{
    unsigned char b[sizeof(mf_real)];
    size_t i;
    memcpy(b, &x, sizeof b);
    for (i = 0; i < sizeof b; ++i) { digest ^= b[i]; digest *= 1099511628211ull; }
}
static void eat3(mf_vec3 v) { eat(v.x); eat(v.y); eat(v.z); }

int main(void)
{
    mf_ndf d[8];
    int k, i, j, n = 0;
    d[0] = mf_gtr(MF_R(0.3), MF_R(0.5));
    d[1] = mf_gtr(MF_R(0.3), MF_R(2.5));
    d[2] = mf_gtr(MF_R(0.02), MF_R(1.5));
    d[3] = mf_student_t(MF_R(0.2), MF_R(0.3), MF_R(3.0));
    d[4] = mf_student_t(MF_R(0.1), MF_R(0.1), MF_R(1.6));
    d[5] = mf_beckmann(MF_R(0.3), MF_R(0.1));
    d[6] = mf_ggx(MF_R(0.4), MF_R(0.2));
    d[7] = mf_transformed(mf_gtr(MF_R(0.1), MF_R(1.2)), mf_mat2_make(MF_R(1.2), MF_R(0.3), MF_R(0.0), MF_R(0.7)));
    for (k = 0; k < 8; ++k)
        for (i = 0; i < 24; ++i)
            for (j = 0; j < 24; ++j) {
                mf_real u1 = ((mf_real)i + MF_R(0.37)) / MF_R(24.0), u2 = ((mf_real)j + MF_R(0.61)) / MF_R(24.0);
                mf_real t = MF_R(1.55) * (mf_real)((i * 7 + j) % 24) / MF_R(23.0), p = MF_R(0.7) * (mf_real)j;
                mf_vec3 wo = mf_vec3_make(MF_SIN(t) * MF_COS(p), MF_SIN(t) * MF_SIN(p), MF_COS(t));
                mf_vec3 wi = mf_brdf_sample(&d[k], wo, u2, u1).wi;
                eat3(mf_sample_visible(&d[k], wo, u1, u2));
                eat3(mf_sample_D(&d[k], u1, u2));
                eat3(wi);
                eat3(mf_dielectric_sample(&d[k], wo, MF_R(1.5), MF_RADIANCE, u1, u2, MF_R(0.5) * (u1 + u2)).wi);
                eat(mf_brdf_pdf(&d[k], wo, wi));
                n += 4;
            }
    printf("%d samples, digest %016llx\n", n, digest);
    return 0;
}
