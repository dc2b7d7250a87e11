/* Built with -ffast-math (make test, float and double): what the header
 * promises to keep under __FAST_MATH__ (see "FAST MATH" in its
 * introduction): NaN and Inf data never index memory - builders reject them,
 * queries with NaN or Inf arguments return without a crash and in range.
 * Inputs are read through volatile so nothing is folded at compile time. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int passed = 0, failed = 0;
static void check(int ok, const char *what)
{
    if (ok) ++passed;
    else { ++failed; printf("FAIL fast-math: %s\n", what); }
}

int main(void)
{
    volatile float vnan_bits = 0.0f, vinf_src = 1e30f;
    mf_real nan, inf, n[16 * 16 * 3], h[64];
    mf_ibm ibm;
    mf_leadr_map m;
    mf_footprint f;
    int i, j;
    unsigned int u = 0x7fc00000u;
    float fn;
    memcpy(&fn, &u, 4);
    check(MF_FAST_MATH == 1, "MF_FAST_MATH detects -ffast-math");
    vnan_bits = fn;
    nan = (mf_real)vnan_bits;
    inf = (mf_real)(vinf_src * vinf_src);
    for (i = 0; i < 256; ++i) { n[3 * i] = 0; n[3 * i + 1] = 0; n[3 * i + 2] = 1; }
    for (i = 0; i < 64; ++i) h[i] = MF_R(0.01) * (mf_real)(i % 5);
    /* IBM: a NaN or Inf normal is invalid data */
    n[3 * 20] = nan;
    check(mf_ibm_build(&ibm, n, 16, 16, MF_R(0.2)) == MF_ERROR_INVALID_DATA, "ibm_build with a NaN normal");
    n[3 * 20] = 0; n[3 * 21 + 2] = inf;
    check(mf_ibm_build(&ibm, n, 16, 16, MF_R(0.2)) == MF_ERROR_INVALID_DATA, "ibm_build with an Inf normal");
    n[3 * 21 + 2] = 1;
    if (mf_ibm_build(&ibm, n, 16, 16, MF_R(0.2)) == MF_SUCCESS) {
        const mf_real bad[3] = { nan, inf, -inf };
        int ok = 1;
        j = mf_ibm_bin_of(&ibm, mf_vec3_make(0, 0, 1));
        for (i = 0; i < 18; ++i) {
            mf_real w;
            f.u = MF_R(0.5); f.v = MF_R(0.5); f.ax = MF_R(1e-5); f.ay = 0; f.bx = 0; f.by = MF_R(1e-5);
            (&f.u)[i % 6] = bad[i / 6];
            w = mf_ibm_bin_weight(&ibm, j, &f);
            ok = ok && w >= MF_R(0.0) && w <= MF_R(1.0);
            (void)mf_ibm_brdf(&ibm, &f, mf_vec3_make(0, 0, 1), mf_vec3_make(0, 0, 1));
            (void)mf_ibm_sample(&ibm, &f, mf_vec3_make(0, 0, 1), MF_R(0.5), MF_R(0.5), MF_R(0.5), MF_R(0.5)).wi;
        }
        check(ok, "ibm_bin_weight, brdf, sample with NaN / Inf footprints");
        check(mf_ibm_bin_of(&ibm, mf_vec3_make(nan, 0, 1)) < mf_ibm_bin_count(&ibm), "ibm_bin_of(NaN) in range");
        mf_ibm_release(&ibm);
    } else check(0, "ibm_build of a flat map");
    /* LEADR maps: NaN alpha rejected, lookups at NaN / Inf stay in the map */
    check(mf_leadr_map_from_heights(&m, h, 8, 8, nan, MF_R(0.1)) == MF_ERROR_INVALID_ARGUMENT, "leadr alpha NaN");
    if (mf_leadr_map_from_heights(&m, h, 8, 8, MF_R(0.1), MF_R(0.1)) == MF_SUCCESS) {
        mf_leadr a = mf_leadr_map_lookup(&m, inf, MF_R(0.5), MF_R(0.1));
        mf_leadr b = mf_leadr_map_lookup(&m, MF_R(3e9), -inf, inf);
        check(a.E_xx >= MF_R(0.0) && b.E_xx >= MF_R(0.0), "leadr lookups at Inf and 3e9");
        mf_leadr_map_release(&m);
    } else check(0, "leadr map builds");
    /* LTC lookups with NaN */
    {
        mf_ltc l = mf_ltc_ggx(nan, MF_R(0.5));
        mf_real a = mf_ltc_ggx_albedo(MF_R(0.5), nan);
        check(a >= MF_R(0.0) && a <= MF_R(1.0) && l.Minv[8] != MF_R(0.0), "ltc lookups with NaN: in the table");
    }
    /* other builders: NaN data is invalid data */
    {
        mf_tabulated t;
        mf_real th[3] = { 0, MF_R(0.7853981633974483), MF_R(1.5707963267948966) }, dx[3] = { 3, 2, 1 }, g[128], hh[64];
        mf_gonio go;
        mf_gonio_config c;
        dx[1] = nan;
        check(mf_tabulated_build(&t, th, dx, NULL, 3) == MF_ERROR_INVALID_DATA, "tabulated_build with a NaN value");
        for (i = 0; i < 128; ++i) g[i] = 0;
        g[5] = nan;
        check(mf_microsurface_integrate(g, 8, hh) == MF_ERROR_INVALID_DATA, "microsurface_integrate with a NaN gradient");
        for (i = 0; i < 64; ++i) hh[i] = 0;
        hh[9] = nan;
        if (mf_gonio_init(&go, 4) == MF_SUCCESS) {
            memset(&c, 0, sizeof c);   /* all-zero: the defaults */
            c.wi = mf_vec3_make(0, 0, 1);
            c.rays = 100;
            check(mf_gonio_measure(&go, hh, 8, &c) == MF_ERROR_INVALID_DATA, "gonio_measure with a NaN height");
            mf_gonio_release(&go);
        } else check(0, "gonio_init");
    }
    /* microsurface: the iteration cap */
    {
        mf_ndf d = mf_beckmann(MF_R(0.3), MF_R(0.3));
        mf_real hh[64];
        check(mf_microsurface_generate(&d, 8, 0x7fffffff, 1, hh) == MF_ERROR_INVALID_ARGUMENT, "microsurface iteration cap");
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
