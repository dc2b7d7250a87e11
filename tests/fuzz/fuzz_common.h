/* Shared helpers of the libFuzzer targets (the implementation is compiled
 * once, in fuzz_impl.c): a byte reader that yields raw
 * float bit patterns, ints and small choices, and the checks that abort. */
#ifndef MF_FUZZ_COMMON_H
#define MF_FUZZ_COMMON_H
#include "microfacet.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>

typedef struct { const uint8_t *p; size_t n; } fz_in;

static uint32_t fz_u32(fz_in *in)
{
    uint32_t v = 0;
    size_t k = in->n < 4 ? in->n : 4;
    memcpy(&v, in->p, k);
    in->p += k; in->n -= k;
    return v;
}
static unsigned fz_u8(fz_in *in)
{
    unsigned v = 0;
    if (in->n) { v = in->p[0]; in->p++; in->n--; }
    return v;
}
/* a raw bit pattern (any float: NaN, Inf, subnormals) in mf_real */
static mf_real fz_real(fz_in *in)
{
    uint32_t b = fz_u32(in);
    float f;
    memcpy(&f, &b, 4);
    return (mf_real)f;
}
/* a value in [0, 1] half the time, a raw pattern otherwise */
static mf_real fz_unit(fz_in *in)
{
    uint32_t b = fz_u32(in);
    if (b & 1u) return (mf_real)((double)(b >> 1) / 2147483647.0);
    { float f; memcpy(&f, &b, 4); return (mf_real)f; }
}
static int fz_finite(double x) { return x == x && x - x == 0.0; }

/* what the target was doing, printed with a failure */
static char fz_ctx[1024];
#define FZ_FAIL(...) do { fprintf(stderr, "fuzz check failed: " __VA_ARGS__); \
    fprintf(stderr, "\n  input: %s\n", fz_ctx); abort(); } while (0)
/* finite and >= 0 */
#define FZ_NONNEG(x, what) do { double fz_v_ = (double)(x); \
    if (!fz_finite(fz_v_) || fz_v_ < 0.0) FZ_FAIL("%s = %g", what, fz_v_); } while (0)
#define FZ_FIN(x, what) do { double fz_v_ = (double)(x); \
    if (!fz_finite(fz_v_)) FZ_FAIL("%s = %g", what, fz_v_); } while (0)
#define FZ_VEC(v, what) do { FZ_FIN((v).x, what ".x"); FZ_FIN((v).y, what ".y"); FZ_FIN((v).z, what ".z"); } while (0)
/* a sampler's record (the 0.4 contract): every field finite, pdf and weight
 * >= 0; a direction only with pdf > 0; no sample: MF_LOBE_NONE and zeros */
#define FZ_SAMPLE(r, what) do { FZ_VEC((r).wi, what ".wi"); FZ_NONNEG((r).pdf, what ".pdf"); \
    FZ_NONNEG((r).weight, what ".weight"); \
    if ((r).lobe == MF_LOBE_NONE) { \
        if ((r).pdf != 0 || (r).weight != 0 || (r).wi.x != 0 || (r).wi.y != 0 || (r).wi.z != 0) \
            FZ_FAIL("%s: no sample (MF_LOBE_NONE) with nonzero fields", what); \
    } else if ((r).lobe != MF_LOBE_REFLECTION && (r).lobe != MF_LOBE_TRANSMISSION) FZ_FAIL("%s: lobe %d", what, (r).lobe); \
    else if (!((r).pdf > 0)) FZ_FAIL("%s: a direction with pdf 0", what); } while (0)

#endif
