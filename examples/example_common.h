/* Shared by the examples: a small RNG, a finiteness guard and the image
 * writers (tonemapped PPM, linear PFM). Include after microfacet.h. */
#ifndef MF_EXAMPLE_COMMON_H
#define MF_EXAMPLE_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* PCG32 (O'Neill), one stream per pixel; u in [0, 1) with 24 random bits. */
typedef struct rng { uint64_t s; } rng;
static inline uint32_t rng_next(rng *r)
{
    uint64_t old = r->s;
    uint32_t x, rot;
    r->s = old * 6364136223846793005ULL + 1442695040888963407ULL;
    x = (uint32_t)(((old >> 18) ^ old) >> 27);
    rot = (uint32_t)(old >> 59);
    return (x >> rot) | (x << ((32u - rot) & 31u));
}
static inline mf_real rng_u(rng *r) { return (mf_real)(rng_next(r) >> 8) * MF_R(5.9604644775390625e-8); }
static inline void rng_seed(rng *r, uint64_t pixel)
{
    r->s = pixel * 0x9E3779B97F4A7C15ULL + 1u;
    rng_next(r);
}

/* 1 if all three values are finite */
static inline int finite3(const mf_real v[3])
{
    int c;
    for (c = 0; c < 3; ++c)
        if (!(MF_FABS(v[c]) < MF_BIG)) return 0;   /* false for NaN and Inf */
    return 1;
}

/* Little-endian float32 regardless of the host byte order. */
static inline void put_f32(FILE *fp, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    fputc((int)(u & 255u), fp); fputc((int)((u >> 8) & 255u), fp);
    fputc((int)((u >> 16) & 255u), fp); fputc((int)(u >> 24), fp);
}

/* Writes img (w x h RGB, linear, top row first) as a PPM (Reinhard c/(1+c),
 * gamma 2.2; columns from linear_x0 on are written linearly, for difference
 * panels) and a PFM (rows bottom to top, negative scale = little-endian).
 * Returns 0 on success. */
static inline int write_images(const char *ppm_path, const char *pfm_path, const float *img, int w, int h, int linear_x0)
{
    FILE *fp = fopen(ppm_path, "wb");
    int i, y;
    if (!fp) { perror(ppm_path); return 1; }
    fprintf(fp, "P6\n%d %d\n255\n", w, h);
    for (i = 0; i < 3 * w * h; ++i) {
        mf_real v = (mf_real)img[i];
        if ((i / 3) % w < linear_x0) v = MF_POW(v / (MF_R(1.0) + v), MF_R(1.0) / MF_R(2.2));
        fputc((int)(mf_clamp(v, MF_R(0.0), MF_R(1.0)) * MF_R(255.0) + MF_R(0.5)), fp);
    }
    fclose(fp);
    fp = fopen(pfm_path, "wb");
    if (!fp) { perror(pfm_path); return 1; }
    fprintf(fp, "PF\n%d %d\n-1.0\n", w, h);
    for (y = h - 1; y >= 0; --y)
        for (i = 0; i < 3 * w; ++i) put_f32(fp, img[3 * w * y + i]);
    fclose(fp);
    return 0;
}

#endif
