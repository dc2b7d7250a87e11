/* Demonstrates LEADR mapping (mf_leadr_map_from_heights, mf_leadr_map_lookup,
 * mf_leadr_specular, mf_leadr_specular_env, mf_leadr_diffuse) against naive
 * mip-mapped normals on a tiling, ocean-like height field seen at increasing
 * distances. Columns: the texture tiles 2, 8, 32 and 128 times across the
 * panel (the same surface ever farther away; a pixel covers 1/100 to 1.3 of a
 * tile). Rows:
 *   1. LEADR: slope moments filtered over the pixel footprint shade a
 *      non-centered anisotropic Beckmann lobe (sun, sky, diffuse);
 *   2. naive: only the filtered mean normal with the base roughness, as an
 *      ordinary normal-mapped material: far away the glitter collapses into a
 *      too-sharp mirror highlight instead of the broadened lobe.
 * Orthographic view 60 degrees from the normal, the sun at the mirror
 * direction. 4 jittered samples per pixel. Writes a tonemapped PPM and a
 * linear PFM and prints the count of non-finite values (expected 0; the exit
 * status is 1 otherwise).
 *
 *   cc -O2 -I. examples/leadr_zoom.c -o leadr_zoom -lm   (from the repo root)
 *   ./leadr_zoom [out.ppm] [out.pfm]                    (leadr_zoom.ppm, .pfm)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define PW 200
#define PH 150
#define COLS 4
#define W (COLS * PW)
#define H (2 * PH)
#define N 256             /* height map size */
#define SPP 4

static const mf_real tiles[COLS] = { MF_R(2.0), MF_R(8.0), MF_R(32.0), MF_R(128.0) };
static const mf_real base_alpha = MF_R(0.05);
static const mf_real sun = MF_R(0.15), albedo = MF_R(0.5);

/* sky radiance: bright horizon, blue zenith */
static mf_vec3 sky(mf_vec3 wi, mf_real solid_angle, void *ctx)
{
    mf_real t = MF_SQRT(mf_clamp(wi.z, MF_R(0.0), MF_R(1.0)));
    (void)solid_angle; (void)ctx;
    return mf_vec3_make(MF_R(0.9) - MF_R(0.7) * t, MF_R(0.95) - MF_R(0.55) * t, MF_R(1.0) - MF_R(0.1) * t);
}

/* periodic waves with integer wave vectors: RMS slope about 0.25 */
static void make_heights(mf_real *h)
{
    static const int k[4][2] = { { 3, 1 }, { 1, 4 }, { -5, 2 }, { 7, 6 } };
    static const mf_real ph[4] = { MF_R(0.3), MF_R(1.7), MF_R(4.1), MF_R(2.2) };
    int x, y, i;
    for (y = 0; y < N; ++y)
        for (x = 0; x < N; ++x) {
            mf_real u = (mf_real)x / N, v = (mf_real)y / N, s = MF_R(0.0);
            for (i = 0; i < 4; ++i)
                s += MF_R(0.005) * MF_SIN(MF_R(2.0) * MF_PI * ((mf_real)k[i][0] * u + (mf_real)k[i][1] * v) + ph[i]);
            h[y * N + x] = s;
        }
}

/* LEADR shading of the moments a */
static mf_vec3 shade_leadr(mf_leadr a, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 env = mf_leadr_specular_env(a, wo, 5, 1, sky, NULL);
    mf_real spec = sun * mf_leadr_specular(a, wo, wi), diff = sun * albedo * mf_leadr_diffuse(a, wo, wi, 5);
    return mf_add(env, mf_vec3_make(spec + diff, spec + diff, spec + diff));
}

/* naive: the filtered mean normal with the base roughness */
static mf_vec3 shade_naive(mf_leadr a, mf_vec3 wo, mf_vec3 wi)
{
    mf_vec3 n = mf_leadr_mean_normal(a), t, b, lo, li, r;
    mf_ndf d = mf_beckmann(base_alpha, base_alpha);
    mf_real spec, diff;
    mf_frame(n, &t, &b);
    lo = mf_vec3_make(mf_dot(wo, t), mf_dot(wo, b), mf_dot(wo, n));
    li = mf_vec3_make(mf_dot(wi, t), mf_dot(wi, b), mf_dot(wi, n));
    spec = sun * mf_brdf(&d, lo, li) * mf_max(li.z, MF_R(0.0));
    diff = sun * albedo * mf_max(li.z, MF_R(0.0)) * MF_INV_PI;
    r = mf_reflect(wo, n);
    return mf_add(r.z > MF_R(0.0) ? sky(r, MF_R(0.0), NULL) : mf_vec3_make(0, 0, 0), mf_vec3_make(spec + diff, spec + diff, spec + diff));
}

int main(int argc, char **argv)
{
    const char *ppm_path = argc > 1 ? argv[1] : "leadr_zoom.ppm";
    const char *pfm_path = argc > 2 ? argv[2] : "leadr_zoom.pfm";
    const mf_real th = MF_R(1.0471975512);   /* 60 degrees */
    const mf_vec3 wo = mf_vec3_make(MF_R(0.0), -MF_SIN(th), MF_COS(th)), wi = mf_vec3_make(MF_R(0.0), MF_SIN(th), MF_COS(th));
    mf_real *h = (mf_real *)malloc(sizeof(mf_real) * N * N);
    float *img = (float *)malloc(sizeof(float) * 3 * W * H);
    mf_leadr_map map;
    long bad = 0;
    int px, py, s, c;
    if (!h || !img) { fprintf(stderr, "out of memory\n"); free(h); free(img); return 1; }
    make_heights(h);
    if (mf_leadr_map_from_heights(&map, h, N, N, base_alpha, base_alpha) != MF_SUCCESS) {
        fprintf(stderr, "moment map: failed\n");
        free(h); free(img);
        return 1;
    }
    for (py = 0; py < H; ++py)
        for (px = 0; px < W; ++px) {
            int col = px / PW, row = py / PH;
            mf_real sum[3] = { 0, 0, 0 };
            /* the view is 60 degrees off the normal: a pixel is 1/cos longer along y */
            mf_real foot = tiles[col] / (mf_real)PW / MF_COS(th);
            rng r;
            rng_seed(&r, (uint64_t)(py * W + px));
            for (s = 0; s < SPP; ++s) {
                mf_real x = ((mf_real)(px % PW) + rng_u(&r)) / (mf_real)PW;
                mf_real y = ((mf_real)(py % PH) + rng_u(&r)) / (mf_real)PW / MF_COS(th);
                mf_leadr a = mf_leadr_map_lookup(&map, tiles[col] * x, tiles[col] * y, foot);
                mf_vec3 v = row == 0 ? shade_leadr(a, wo, wi) : shade_naive(a, wo, wi);
                mf_real vv[3];
                vv[0] = v.x; vv[1] = v.y; vv[2] = v.z;
                if (!finite3(vv)) { ++bad; continue; }
                for (c = 0; c < 3; ++c) sum[c] += vv[c];
            }
            for (c = 0; c < 3; ++c) img[3 * (py * W + px) + c] = (float)(sum[c] / (mf_real)SPP);
        }
    mf_leadr_map_release(&map);
    free(h);
    if (write_images(ppm_path, pfm_path, img, W, H, W)) { free(img); return 1; }
    free(img);
    printf("columns: the texture tiles 2, 8, 32, 128 times across the panel; rows: LEADR, naive mip-mapped normals\n");
    printf("non-finite samples: %ld\n", bad);
    printf("wrote %s (tonemapped) and %s (linear)\n", ppm_path, pfm_path);
    return bad != 0;
}
