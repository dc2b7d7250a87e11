/* Regenerates the built-in LTC tables of microfacet.h with the library's own
 * fitter (mf_ltc_table_build) and prints them as a C array to stdout.
 *   cc -O2 -DMF_USE_DOUBLE -I. tools/ltc_fit.c -o ltc_fit -lm
 *   ./ltc_fit [kind] [gamma] [n] > table.inc     (kind: ggx, beckmann, gtr, student_t)
 * The header's table is the GGX one at n = 64; stderr shows the progress,
 * the time and the value ranges (for float16 packing). */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* a float literal: %.6g with a decimal point or exponent, and the f suffix */
static void print_float(double v)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.6g", v);
    if (!strpbrk(buf, ".e")) strcat(buf, ".0");
    else if (!strchr(buf, '.')) { char *e = strchr(buf, 'e'); memmove(e + 2, e, strlen(e) + 1); e[0] = '.'; e[1] = '0'; }
    printf("%sf,", buf);
}

static void progress(int done, int total, void *ctx)
{
    (void)ctx;
    if (done % 256 == 0 || done == total) fprintf(stderr, "\r%d / %d", done, total);
}

int main(int argc, char **argv)
{
    mf_ltc_table t;
    int kind = MF_NDF_GGX, n = 64, i, k;
    double gamma = 2.0, lo[6], hi[6];
    clock_t t0 = clock();
    if (argc > 1) {
        if (!strcmp(argv[1], "beckmann")) kind = MF_NDF_BECKMANN;
        else if (!strcmp(argv[1], "gtr")) kind = MF_NDF_GTR;
        else if (!strcmp(argv[1], "student_t")) kind = MF_NDF_STUDENT_T;
    }
    if (argc > 2) gamma = atof(argv[2]);
    if (argc > 3) n = atoi(argv[3]);
    if (mf_ltc_table_build(&t, kind, (mf_real)gamma, n, n, progress, NULL) != MF_SUCCESS) {
        fprintf(stderr, "fit failed\n");
        return 1;
    }
    fprintf(stderr, "\nfitted %d x %d in %.1f s\n", n, n, (double)(clock() - t0) / CLOCKS_PER_SEC);
    for (k = 0; k < 6; ++k) { lo[k] = 1e30; hi[k] = -1e30; }
    printf("/* %d x %d entries [sqrt(alpha)][sqrt(1 - cos theta)]: inv0 inv1 inv2 inv3 albedo fresnel */\n", n, n);
    for (i = 0; i < n * n; ++i) {
        for (k = 0; k < 6; ++k) {
            double v = t.data[6 * i + k];
            if (v < lo[k]) lo[k] = v;
            if (v > hi[k]) hi[k] = v;
            print_float(v);
        }
        printf(i % 2 == 1 ? "\n" : " ");
    }
    for (k = 0; k < 6; ++k) fprintf(stderr, "column %d in [%g, %g]\n", k, lo[k], hi[k]);
    mf_ltc_table_release(&t);
    return 0;
}
