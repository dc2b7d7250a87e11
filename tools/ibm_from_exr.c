/* ibm_from_exr: builds the Inverse Bin Map of an EXR normal map and saves it
 * (mf_ibm_save's bytes; reload with mf_ibm_load).
 *   ibm_from_exr in.exr out.ibm [flake_alpha (0.01)] [--encoded]
 * RGB holds the normal's xyz in [-1,1] (--encoded: in [0,1], mapped by 2c-1);
 * normals are renormalized. Needs OpenEXR 3 (Core API). */
#define MICROFACET_IMPLEMENTATION
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "microfacet.h"
#include "tools/exr_io.h"
#include "tools/ibm_exr.h"

int main(int argc, char **argv)
{
    const char *in = NULL, *outp = NULL;
    double alpha = 0.01;
    int encoded = 0, npos = 0, i, used = 0, nb;
    mf_ibm ibm;
    mf_result r;
    size_t bytes;
    void *buf;
    FILE *f;
    unsigned char *mark;

    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--encoded") == 0) encoded = 1;
        else if (npos == 0) { in = argv[i]; ++npos; }
        else if (npos == 1) { outp = argv[i]; ++npos; }
        else if (npos == 2) {
            char *end;
            alpha = strtod(argv[i], &end);
            if (*end || !(alpha > 0.0)) { fprintf(stderr, "ibm_from_exr: bad flake_alpha '%s'\n", argv[i]); return 2; }
            ++npos;
        } else { npos = 99; }
    }
    if (npos < 2 || npos > 3) {
        fprintf(stderr, "usage: ibm_from_exr in.exr out.ibm [flake_alpha (default 0.01)] [--encoded]\n");
        return 2;
    }
    r = mfx_ibm_from_exr(&ibm, in, encoded, (mf_real)alpha);
    if (r != MF_SUCCESS) { fprintf(stderr, "ibm_from_exr: %s: %s\n", in, mf_result_string(r)); return 1; }
    r = mf_ibm_save(&ibm, NULL, 0, &bytes);   /* buf NULL: the size query */
    if (r != MF_SUCCESS) { fprintf(stderr, "ibm_from_exr: save: %s\n", mf_result_string(r)); mf_ibm_release(&ibm); return 1; }
    buf = malloc(bytes ? bytes : 1);
    if (!buf) { mf_ibm_release(&ibm); fprintf(stderr, "ibm_from_exr: %s\n", mf_result_string(MF_ERROR_OUT_OF_MEMORY)); return 1; }
    r = mf_ibm_save(&ibm, buf, bytes, &bytes);
    if (r != MF_SUCCESS) { fprintf(stderr, "ibm_from_exr: save: %s\n", mf_result_string(r)); free(buf); mf_ibm_release(&ibm); return 1; }
    f = fopen(outp, "wb");
    if (!f || fwrite(buf, 1, bytes, f) != bytes || fclose(f) != 0) {
        fprintf(stderr, "ibm_from_exr: cannot write %s\n", outp);
        free(buf); mf_ibm_release(&ibm); return 1;
    }
    free(buf);
    /* occupied bins: the bin of each texel's normal */
    nb = mf_ibm_bin_count(&ibm);
    mark = (unsigned char *)calloc((size_t)nb, 1);
    if (mark) {
        float *px = NULL; int w, h, c;
        mf_real *nrm = NULL;
        if (mfx_exr_read(in, &px, &w, &h, &c) == 0 && mfx_normals_from_rgb(px, w, h, c, encoded, &nrm) == MF_SUCCESS) {
            size_t k, n = (size_t)w * (size_t)h, neg = 0;
            for (k = 0; k < n * (size_t)c; ++k) neg += px[k] < 0.0f;
            if (!encoded && neg == 0)
                fprintf(stderr, "ibm_from_exr: note: no negative component in %s; if it is stored in [0,1], pass --encoded\n", in);
            for (k = 0; k < n; ++k) {
                int b = mf_ibm_bin_of(&ibm, mf_vec3_make(nrm[3 * k], nrm[3 * k + 1], nrm[3 * k + 2]));
                if (b >= 0 && b < nb && !mark[b]) { mark[b] = 1; ++used; }
            }
        }
        free(px); free(nrm); free(mark);
    }
    printf("%s: %d x %d texels, flake alpha %g, %d x %d bins (%d occupied), radius %d\n",
           in, ibm.width, ibm.height, (double)ibm.alpha, ibm.res, ibm.res, used, ibm.radius);
    printf("%s: %lu bytes\n", outp, (unsigned long)bytes);
    mf_ibm_release(&ibm);
    return 0;
}
