/* ibm_exr.h - the core of ibm_from_exr: an EXR normal map to an Inverse Bin
 * Map. Include after microfacet.h (any configuration) and tools/exr_io.h. */
#ifndef MFX_IBM_EXR_H
#define MFX_IBM_EXR_H

/* Unit normals (3 mf_real per texel, *out malloc'd) from interleaved float
 * pixels of nch >= 3 channels: RGB = xyz in [-1,1], or in [0,1] mapped by
 * 2c - 1 when encoded. A NaN, infinite or zero-length normal gives
 * MF_ERROR_INVALID_DATA; nothing stays allocated on failure. */
MFX__EXR_FN mf_result mfx_normals_from_rgb(const float *px, int w, int h, int nch, int encoded, mf_real **out)
{
    size_t n, i;
    mf_real *nrm;
    if (out) *out = NULL;
    if (!px || !out || w < 1 || h < 1 || nch < 3) return MF_ERROR_INVALID_ARGUMENT;
    n = (size_t)w * (size_t)h;
    if (n > SIZE_MAX / (3 * sizeof(mf_real))) return MF_ERROR_OUT_OF_MEMORY;
    nrm = (mf_real *)malloc(n * 3 * sizeof(mf_real));
    if (!nrm) return MF_ERROR_OUT_OF_MEMORY;
    for (i = 0; i < n; ++i) {
        double v[3], len;
        int c;
        for (c = 0; c < 3; ++c) {
            v[c] = (double)px[i * (size_t)nch + (size_t)c];
            if (encoded) v[c] = 2.0 * v[c] - 1.0;
        }
        len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(len > 0.0) || !(len < 1e30)) { free(nrm); return MF_ERROR_INVALID_DATA; }
        for (c = 0; c < 3; ++c) nrm[i * 3 + (size_t)c] = (mf_real)(v[c] / len);
    }
    *out = nrm;
    return MF_SUCCESS;
}

/* Reads an EXR normal map (mfx_exr_read) and builds its IBM (mf_ibm_build).
 * An unreadable file or one without RGB gives MF_ERROR_INVALID_DATA (the
 * reason is on stderr). */
MFX__EXR_FN mf_result mfx_ibm_from_exr(mf_ibm *ibm, const char *path, int encoded, mf_real flake_alpha)
{
    float *px = NULL;
    mf_real *nrm = NULL;
    int w, h, nch;
    mf_result r;
    if (!ibm || !path) return MF_ERROR_INVALID_ARGUMENT;
    memset(ibm, 0, sizeof *ibm);
    if (mfx_exr_read(path, &px, &w, &h, &nch) != 0) return MF_ERROR_INVALID_DATA;
    if (nch < 3) { free(px); fprintf(stderr, "exr: %s: a normal map needs R,G,B\n", path); return MF_ERROR_INVALID_DATA; }
    r = mfx_normals_from_rgb(px, w, h, nch, encoded, &nrm);
    free(px);
    if (r != MF_SUCCESS) return r;
    r = mf_ibm_build(ibm, nrm, w, h, flake_alpha);
    free(nrm);
    return r;
}

#endif /* MFX_IBM_EXR_H */
