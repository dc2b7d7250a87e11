/* Fuzz target: mf_ibm_load of arbitrary bytes, then every query on what it
 * accepted (bin counts, normals, texel bins, weights, BRDF, pdf, sampling).
 * The first byte picks a mode: 0 mutates a valid saved map (so the fuzzer
 * reaches past the checksum), otherwise the bytes are loaded as they are. */
#include "fuzz_common.h"

static void fz_query(const mf_ibm *ibm, fz_in *in)
{
    int nb = mf_ibm_bin_count(ibm), i, bins[MF_IBM_MAX_WINDOW];
    mf_real w[MF_IBM_MAX_WINDOW], pdf;
    mf_footprint f;
    mf_vec3 wo, wi;
    mf_sample s;
    for (i = 0; i < nb && i < 64; ++i) {
        mf_vec3 n = mf_ibm_bin_normal(ibm, i);
        FZ_VEC(n, "bin_normal");
        if (mf_ibm_bin_texels(ibm, i) < 0) FZ_FAIL("negative texel count");
    }
    for (i = 0; i < 8; ++i) {
        int b = mf_ibm_texel_bin(ibm, (int)fz_u32(in), (int)fz_u32(in));
        if (b < -1 || b >= nb) FZ_FAIL("texel bin %d of %d", b, nb);
    }
    f.u = fz_real(in); f.v = fz_real(in); f.ax = fz_real(in); f.ay = fz_real(in); f.bx = fz_real(in); f.by = fz_real(in);
    if (nb > 0) {
        mf_real x = mf_ibm_bin_weight(ibm, (int)(fz_u32(in) % (unsigned)nb), &f);
        if (!(x >= MF_R(0.0) && x <= MF_R(1.0001))) FZ_FAIL("bin weight %g", (double)x);
        int k = mf_ibm_neighbourhood_weights(ibm, &f, (int)(fz_u32(in) % (unsigned)nb), bins, w);
        if (k < 0 || k > MF_IBM_MAX_WINDOW) FZ_FAIL("window %d", k);
        for (i = 0; i < k; ++i) FZ_NONNEG(w[i], "window weight");
    }
    wo = mf_normalize(mf_vec3_make(fz_real(in), fz_real(in), MF_R(1.0)));
    wi = mf_normalize(mf_vec3_make(fz_real(in), fz_real(in), MF_R(1.0)));
    FZ_NONNEG(mf_ibm_brdf(ibm, &f, wo, wi), "ibm_brdf");
    FZ_NONNEG(mf_ibm_pdf(ibm, &f, wo, wi), "ibm_pdf");
    FZ_NONNEG(mf_ibm_brdf_and_pdf(ibm, &f, wo, wi, &pdf), "ibm_brdf_pdf");
    FZ_NONNEG(pdf, "ibm_brdf_pdf pdf");
    s = mf_ibm_sample(ibm, &f, wo, fz_unit(in), fz_unit(in), fz_unit(in), fz_unit(in));
    FZ_SAMPLE(s, "ibm_sample");
}

static unsigned char *fz_valid;
static size_t fz_valid_n;

static void fz_make_valid(void)
{
    mf_real n[8 * 8 * 3];
    mf_ibm ibm;
    int i;
    if (fz_valid) return;
    for (i = 0; i < 64; ++i) {
        mf_vec3 v = mf_normalize(mf_vec3_make(MF_R(0.05) * (mf_real)(i % 7 - 3), MF_R(0.04) * (mf_real)(i % 5 - 2), MF_R(1.0)));
        n[3 * i] = v.x; n[3 * i + 1] = v.y; n[3 * i + 2] = v.z;
    }
    if (mf_ibm_build(&ibm, n, 8, 8, MF_R(0.2)) != MF_SUCCESS) abort();
    if (mf_ibm_save(&ibm, NULL, 0, &fz_valid_n) != MF_SUCCESS) abort();   /* buf NULL: the size */
    fz_valid = (unsigned char *)malloc(fz_valid_n);
    if (!fz_valid || mf_ibm_save(&ibm, fz_valid, fz_valid_n, &fz_valid_n) != MF_SUCCESS) abort();
    mf_ibm_release(&ibm);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = { data, size };
    mf_ibm ibm;
    unsigned mode = fz_u8(&in);
    if (mode == 0) {
        /* the valid map with a few bytes overwritten */
        unsigned char *buf;
        unsigned k, nmod = fz_u8(&in) % 8u;
        fz_make_valid();
        buf = (unsigned char *)malloc(fz_valid_n);
        memcpy(buf, fz_valid, fz_valid_n);
        for (k = 0; k < nmod; ++k) {
            size_t at = fz_u32(&in) % fz_valid_n;
            buf[at] = (unsigned char)fz_u8(&in);
        }
        /* odd count: restore the checksum so the validator behind it is reached */
        if ((nmod & 1u) && fz_valid_n >= 4u * MF__IBM_HEADER) {
            unsigned int *w = (unsigned int *)(void *)buf;
            w[MF__IBM_HEADER - 1] = mf__ibm_checksum(w, fz_valid_n / 4u);
        }
        if (mf_ibm_load(&ibm, buf, fz_valid_n) == MF_SUCCESS) { fz_query(&ibm, &in); mf_ibm_release(&ibm); }
        free(buf);
        return 0;
    }
    {
        /* the rest as a buffer (own copy so ASan sees its exact end), the
         * query inputs from its tail */
        size_t n = in.n;
        unsigned char *buf = (unsigned char *)malloc(n ? n : 1);
        fz_in q;
        memcpy(buf, in.p, n);
        q.p = in.p + n / 2; q.n = n - n / 2;
        if (mf_ibm_load(&ibm, buf, n) == MF_SUCCESS) { fz_query(&ibm, &q); mf_ibm_release(&ibm); }
        free(buf);
    }
    return 0;
}
