/* Demonstrates the Inverse Bin Map (mf_ibm_build, mf_ibm_brdf with pixel
 * footprints) on a car-paint flake plane: a 2048 x 2048 tiling normal map of
 * Voronoi flakes (about 4 texels across) whose normals follow GTR (alpha 0.08,
 * gamma 1.5; thesis Sec. 5.5.4), Beckmann flake roughness 0.02, over a dark
 * red base, lit by a low sun placed so its mirror highlight is in the middle
 * of the view. Columns: the same perspective view ever farther away, the
 * texture tile spanning 8, 2, 1/2 and 1/8 of the panel width at the panel
 * center (about 1.3, 5, 20 and 80 texels per pixel). The map is that large so
 * that even at 80 texels per pixel a tile spans 25 pixels: a 512 x 512 tile
 * would repeat every 6 pixels there, and the box filter of a texture that
 * repeats within a few pixels is streaky (moire along the lines of constant
 * tile phase, which converge to the vanishing point), in the IBM row and, up
 * to noise, in a converged reference alike. Rows:
 *   1. IBM: the filtered glint BRDF over each pixel's footprint (the
 *      parallelogram of its ray differentials on the plane), one evaluation
 *      per pixel;
 *   2. one normal-map sample per pixel (the texel at the pixel center): the
 *      glints alias into sparkling noise as texels shrink below a pixel;
 *   3. reference: 64 jittered normal-map samples per pixel, which converge to
 *      what row 1 computes in one step.
 * Prints per panel the mean radiance of each row (equal up to noise: the IBM
 * is the pixel's exact box filter, up to the binning) and the RMS per-pixel
 * deviation of rows 2 and 3 from row 1, and the count of non-finite values
 * (expected 0; the exit status is 1 otherwise). About 5 s on one core at -O2.
 * Writes base.png (tone mapped; rows, texel density and the deviations
 * labelled), base.pfm (linear) and, built with OpenEXR, base.exr.
 *
 *   cc -O2 -I. examples/glints.c -o glints -lm      (from the repo root)
 *   ./glints [base]                                (default: glints)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define PW 200            /* panel size */
#define PH 150
#define COLS 4
#define ROWS 3
#define W (COLS * PW)
#define H (ROWS * PH)
#define N 2048            /* normal map size */
#define CELL 4            /* flake spacing in texels */
#define REF_SPP 64        /* 8 x 8 jittered */

static const mf_real tiles[COLS] = { MF_R(0.125), MF_R(0.5), MF_R(2.0), MF_R(8.0) };  /* tiles across the panel */
static const mf_real flake_alpha = MF_R(0.02), gtr_alpha = MF_R(0.08);
static const mf_real view_deg = MF_R(60.0), vfov_deg = MF_R(30.0);
static const mf_real sun_rgb[3] = { MF_R(0.06), MF_R(0.056), MF_R(0.05) };   /* irradiance */
static const mf_real base_rgb[3] = { MF_R(2.0), MF_R(0.12), MF_R(0.16) };  /* diffuse base (times the sun) */
static const mf_real flake_rgb[3] = { MF_R(0.9), MF_R(0.9), MF_R(0.92) };  /* flake reflectance */
static const mf_real ambient = MF_R(0.01);

/* Voronoi flakes around a jittered grid, tiling, normals from GTR */
static mf_real *make_flakes(void)
{
    const int g = N / CELL;
    mf_ndf gtr = mf_gtr(gtr_alpha, MF_R(1.5));
    mf_real *m = (mf_real *)malloc(sizeof(mf_real) * 3 * N * N), *sx, *sy;
    mf_vec3 *fn = (mf_vec3 *)malloc(sizeof(mf_vec3) * g * g);
    rng r;
    int i, x, y;
    sx = (mf_real *)malloc(sizeof(mf_real) * 2 * g * g);
    if (!m || !fn || !sx) { free(m); free(fn); free(sx); return NULL; }
    sy = sx + g * g;
    rng_seed(&r, 7);
    for (i = 0; i < g * g; ++i) {
        mf_vec3 t = mf_sample_D(&gtr, rng_u(&r), rng_u(&r));
        if (t.z < MF_R(0.3)) t = mf_normalize(mf_vec3_make(t.x, t.y, MF_R(0.3)));
        fn[i] = t;
        sx[i] = ((mf_real)(i % g) + rng_u(&r)) * CELL;
        sy[i] = ((mf_real)(i / g) + rng_u(&r)) * CELL;
    }
    for (y = 0; y < N; ++y)
        for (x = 0; x < N; ++x) {
            int cx = x / CELL, cy = y / CELL, dx, dy, best = 0;
            mf_real bd = MF_BIG;
            for (dy = -1; dy <= 1; ++dy)
                for (dx = -1; dx <= 1; ++dx) {
                    int gx = (cx + dx + g) % g, gy = (cy + dy + g) % g, k = gy * g + gx;
                    mf_real ox = sx[k] + (mf_real)((cx + dx) - gx) * CELL - ((mf_real)x + MF_R(0.5));
                    mf_real oy = sy[k] + (mf_real)((cy + dy) - gy) * CELL - ((mf_real)y + MF_R(0.5));
                    if (ox * ox + oy * oy < bd) { bd = ox * ox + oy * oy; best = k; }
                }
            m[3 * (y * N + x)] = fn[best].x;
            m[3 * (y * N + x) + 1] = fn[best].y;
            m[3 * (y * N + x) + 2] = fn[best].z;
        }
    free(fn);
    free(sx);
    return m;
}

/* the view: camera at height 1 over the plane z = 0 looking along +y */
typedef struct view { mf_vec3 fwd, up; mf_real tan_h, tan_v; } view;

/* direction through panel coordinates (fx, fy) in [0, PW) x [0, PH) */
static mf_vec3 ray(const view *v, mf_real fx, mf_real fy)
{
    mf_real sx = (MF_R(2.0) * fx / (mf_real)PW - MF_R(1.0)) * v->tan_h;
    mf_real sy = (MF_R(1.0) - MF_R(2.0) * fy / (mf_real)PH) * v->tan_v;
    return mf_normalize(mf_add(v->fwd, mf_add(mf_vec3_make(sx, MF_R(0.0), MF_R(0.0)), mf_scale(v->up, sy))));
}

/* texture coordinates of the plane point seen along d (d.z < 0) */
static void hit_uv(mf_vec3 d, mf_real tile, mf_real *u, mf_real *v)
{
    mf_real t = MF_R(1.0) / -d.z;
    *u = t * d.x / tile;
    *v = t * d.y / tile;
}

/* radiance toward wo: diffuse base + IBM flakes under the sun + ambient */
static void shade(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 sun, mf_real out[3])
{
    mf_real flakes = mf_ibm_brdf(ibm, f, wo, sun) * sun.z;
    int c;
    for (c = 0; c < 3; ++c)
        out[c] = sun_rgb[c] * (base_rgb[c] * sun.z * MF_INV_PI + flake_rgb[c] * flakes) + ambient * base_rgb[c];
}

/* the box-filtered radiance of pixel (fx, fy) by n (a multiple of 64)
 * jittered point samples, 8 x 8 strata */
static void reference(const mf_ibm *ibm, const view *v, mf_vec3 sun, mf_real tile, mf_real fx, mf_real fy, int n, rng *r,
                      mf_real out[3])
{
    mf_footprint f;
    int s, c;
    f.ax = f.ay = f.bx = f.by = MF_R(0.0);
    out[0] = out[1] = out[2] = MF_R(0.0);
    for (s = 0; s < n; ++s) {
        mf_real one[3];
        mf_vec3 ds = ray(v, fx + ((mf_real)(s & 7) + rng_u(r)) / MF_R(8.0), fy + ((mf_real)((s >> 3) & 7) + rng_u(r)) / MF_R(8.0));
        hit_uv(ds, tile, &f.u, &f.v);
        shade(ibm, &f, mf_scale(ds, MF_R(-1.0)), sun, one);
        for (c = 0; c < 3; ++c) out[c] += one[c] / (mf_real)n;
    }
}

int main(int argc, char **argv)
{
    static const char *const row_names[ROWS] = { "IBM, pixel footprint", "1 normal-map sample", "reference, 64 samples" };
    const char *base = argc > 1 ? argv[1] : "glints";
    const mf_real deg = MF_PI / MF_R(180.0), th = view_deg * deg;
    ex_image im;
    float *img;
    mf_real *nm = make_flakes(), center_width;
    mf_vec3 sun;
    mf_ibm ibm;
    mf_result res;
    view v;
    double sum[ROWS][COLS], dev[2][COLS];
    long bad = 0;
    int px, py, c, col, s, err;
    if (!nm || ex_image_init(&im, W, H)) { fprintf(stderr, "out of memory\n"); free(nm); return 1; }
    img = im.lin;
    res = mf_ibm_build(&ibm, nm, N, N, flake_alpha);
    free(nm);
    if (res != MF_SUCCESS) { fprintf(stderr, "IBM: %s\n", mf_result_string(res)); ex_image_free(&im); return 1; }
    v.fwd = mf_vec3_make(MF_R(0.0), MF_SIN(th), -MF_COS(th));
    v.up = mf_vec3_make(MF_R(0.0), MF_COS(th), MF_SIN(th));
    v.tan_v = MF_SIN(MF_R(0.5) * vfov_deg * deg) / MF_COS(MF_R(0.5) * vfov_deg * deg);
    v.tan_h = v.tan_v * (mf_real)PW / (mf_real)PH;
    sun = mf_vec3_make(MF_R(0.0), MF_SIN(th), MF_COS(th));   /* the mirror of the center view */
    center_width = MF_R(2.0) * v.tan_h / MF_COS(th);
    for (col = 0; col < COLS; ++col) { sum[0][col] = sum[1][col] = sum[2][col] = dev[0][col] = dev[1][col] = 0.0; }
    for (py = 0; py < PH; ++py)
        for (px = 0; px < W; ++px) {
            mf_real fx = (mf_real)(px % PW), fy = (mf_real)py, tile, u1, v1, val[3][3];
            mf_vec3 d, wo;
            mf_footprint f;
            rng r;
            col = px / PW;
            tile = center_width / tiles[col];
            d = ray(&v, fx + MF_R(0.5), fy + MF_R(0.5));
            wo = mf_scale(d, MF_R(-1.0));
            /* row 1: the footprint from the ray differentials */
            hit_uv(d, tile, &f.u, &f.v);
            hit_uv(ray(&v, fx + MF_R(1.5), fy + MF_R(0.5)), tile, &u1, &v1);
            f.ax = u1 - f.u; f.ay = v1 - f.v;
            hit_uv(ray(&v, fx + MF_R(0.5), fy + MF_R(1.5)), tile, &u1, &v1);
            f.bx = u1 - f.u; f.by = v1 - f.v;
            shade(&ibm, &f, wo, sun, val[0]);
            /* row 2: the texel at the pixel center (a zero-area footprint) */
            f.ax = f.ay = f.bx = f.by = MF_R(0.0);
            shade(&ibm, &f, wo, sun, val[1]);
            /* row 3: jittered point samples */
            rng_seed(&r, (uint64_t)(py * W + px));
            reference(&ibm, &v, sun, tile, fx, fy, REF_SPP, &r, val[2]);
            for (s = 0; s < ROWS; ++s) {
                if (!finite3(val[s])) { ++bad; continue; }
                for (c = 0; c < 3; ++c) img[3 * ((s * PH + py) * W + px) + c] = (float)val[s][c];
            }
            /* panel means, and the per-pixel deviations of rows 2 and 3 from row 1 */
            for (c = 0; c < 3; ++c) {
                for (s = 0; s < ROWS; ++s) sum[s][col] += (double)val[s][c];
                dev[0][col] += (double)((val[1][c] - val[0][c]) * (val[1][c] - val[0][c]));
                dev[1][col] += (double)((val[2][c] - val[0][c]) * (val[2][c] - val[0][c]));
            }
        }
    mf_ibm_release(&ibm);
    ex_tonemap_all(&im, 1.0);
    for (col = 0; col < COLS; ++col) {
        double np = 3.0 * PW * PH, m = sum[0][col] / np;
        /* the tile's width, and the texels per pixel at the panel center */
        if (tiles[col] < MF_R(1.0)) ex_label(&im, col * PW + 4, 4, 1, "tile %g panels, %.3g texel/px", 1.0 / (double)tiles[col],
                                             (double)N * (double)tiles[col] / PW);
        else ex_label(&im, col * PW + 4, 4, 1, "tile 1/%g panel, %.3g texel/px", (double)tiles[col], (double)N * (double)tiles[col] / PW);
        for (s = 0; s < ROWS; ++s) {
            ex_text(&im, col * PW + 4, s * PH + (s ? 4 : 16), 1, row_names[s]);
            if (s) ex_label(&im, col * PW + 4, s * PH + PH - 12, 1, "RMS dev. %.3g%% of IBM", 100.0 * sqrt(dev[s - 1][col] / np) / m);
        }
    }
    ex_label(&im, 4, 2 * PH - 38, 1, "normals: GTR %.3g, gamma 1.5", (double)gtr_alpha);
    ex_label(&im, 4, 2 * PH - 26, 1, "flakes: Beckmann %.3g", (double)flake_alpha);
    err = ex_write(&im, base);
    ex_image_free(&im);
    printf("%d x %d panels of %d x %d; the tile spans %g, %g, 1/%g and 1/%g of the panel width (%.3g, %.3g, %.3g, %.3g "
           "texels per pixel at the center)\n", COLS, ROWS, PW, PH, 1.0 / (double)tiles[0], 1.0 / (double)tiles[1], (double)tiles[2],
           (double)tiles[3], (double)N * (double)tiles[0] / PW, (double)N * (double)tiles[1] / PW, (double)N * (double)tiles[2] / PW,
           (double)N * (double)tiles[3] / PW);
    printf("rows: IBM over the pixel footprint, one normal-map sample per pixel, %d-sample reference\n", REF_SPP);
    printf("panel means (IBM, one sample, %d samples) and RMS per-pixel deviation from IBM, %% of the IBM mean:\n", REF_SPP);
    for (col = 0; col < COLS; ++col) {
        double np = 3.0 * PW * PH, m = sum[0][col] / np;
        printf("panel %d: means %.4f %.4f %.4f; deviation: one sample %.0f%%, %d samples %.0f%%\n", col + 1, m,
               sum[1][col] / np, sum[2][col] / np, 100.0 * sqrt(dev[0][col] / np) / m, REF_SPP, 100.0 * sqrt(dev[1][col] / np) / m);
    }
    printf("non-finite values: %ld\n", bad);
    return bad != 0 || err;
}
