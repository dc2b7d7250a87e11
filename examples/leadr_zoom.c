/* Demonstrates LEADR mapping (mf_leadr_map_from_heights, mf_leadr_map_lookup,
 * mf_leadr_specular, mf_leadr_specular_env, mf_leadr_diffuse) against naive
 * mip-mapped normals on an ocean-like sea: a tiling height field of eight
 * periodic waves (RMS slope about 0.25) repeated over a large plane, seen by a
 * perspective camera 72 degrees off the normal, facing a low sun (15 degrees
 * up) so its glitter path is on screen, under a gradient sky.
 * Columns: the same view ever farther away, the texture tile spanning 1/2,
 * 1/8, 1/32 and 1/128 of the panel width at the panel center. Rows:
 *   1. LEADR: slope moments filtered over each sample's footprint shade a
 *      non-centered anisotropic Beckmann lobe (sun, 5x5 sky grid, diffuse);
 *   2. naive: the filtered mean normal alone with the base roughness, as an
 *      ordinary normal-mapped material: at a distance the sea turns into a
 *      flat mirror with a tiny, too-sharp sun highlight.
 * Both rows use water's Fresnel factor (eta 1.33) at the half vector.
 * 4 jittered samples per pixel (about 3.5 s on one core at -O2). Writes
 * base.png (tone mapped, rows and tile sizes labelled), base.pfm (linear) and,
 * built with OpenEXR, base.exr, and prints the count of non-finite samples
 * (expected 0; the exit status is 1 otherwise).
 *
 *   cc -O2 -I. examples/leadr_zoom.c -o leadr_zoom -lm   (from the repo root)
 *   ./leadr_zoom [base]                                 (default: leadr_zoom)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define PW 240            /* panel size */
#define PH 180
#define COLS 4
#define W (COLS * PW)
#define H (2 * PH)
#define N 512             /* height map size */
#define NWAVES 8
#define SPP 4             /* 2x2 jittered */
#define GRID 5            /* LEADR slope grid, the paper's default */

/* tiles across the panel width at the center ray's hit point */
static const mf_real tiles[COLS] = { MF_R(2.0), MF_R(8.0), MF_R(32.0), MF_R(128.0) };
static const mf_real base_alpha = MF_R(0.05);
static const mf_real view_deg = MF_R(72.0), vfov_deg = MF_R(30.0), sun_deg = MF_R(15.0);
static const mf_real sun_rgb[3] = { MF_R(6.0), MF_R(5.2), MF_R(4.2) };       /* irradiance */
static const mf_real albedo[3] = { MF_R(0.03), MF_R(0.09), MF_R(0.11) };     /* water body */

/* Sky radiance along d (z is up): bright hazy horizon, blue zenith. */
static mf_vec3 sky(mf_vec3 d)
{
    mf_real t = MF_SQRT(mf_clamp(d.z, MF_R(0.0), MF_R(1.0)));
    return mf_vec3_make(MF_R(0.95) - MF_R(0.75) * t, MF_R(1.0) - MF_R(0.6) * t, MF_R(1.05) - MF_R(0.15) * t);
}

/* Fresnel of water for the half vector of wo and wi */
static mf_real fresnel(mf_vec3 wo, mf_vec3 wi)
{
    return mf_fresnel_dielectric(mf_dot(wo, mf_normalize(mf_add(wo, wi))), MF_R(1.33));
}

/* environment callback of mf_leadr_specular_env: the sky times Fresnel, for
 * the view direction in ctx; a gradient needs no prefiltering (solid angle) */
static mf_vec3 sky_env(mf_vec3 wi, mf_real solid_angle, void *ctx)
{
    mf_vec3 wo = *(const mf_vec3 *)ctx;
    (void)solid_angle;
    return mf_scale(sky(wi), fresnel(wo, wi));
}

/* Periodic waves with integer wave vectors (tileable on [0,1]^2), heights in
 * texture units; each wave has slope amplitude 0.125, so RMS slope 0.25. */
static void make_heights(mf_real *h)
{
    static const int k[NWAVES][2] = { { 1, 3 }, { -3, 2 }, { 2, 5 }, { 7, 4 },
                                      { -4, 9 }, { 10, 7 }, { 5, 16 }, { -19, 11 } };
    static const mf_real ph[NWAVES] = { MF_R(0.3), MF_R(1.7), MF_R(4.1), MF_R(2.2),
                                        MF_R(5.0), MF_R(0.9), MF_R(3.3), MF_R(1.2) };
    mf_real amp[NWAVES];
    int x, y, i;
    for (i = 0; i < NWAVES; ++i)
        amp[i] = MF_R(0.125) / (MF_R(2.0) * MF_PI * MF_SQRT((mf_real)(k[i][0] * k[i][0] + k[i][1] * k[i][1])));
    for (y = 0; y < N; ++y)
        for (x = 0; x < N; ++x) {
            mf_real u = (mf_real)x / N, v = (mf_real)y / N, s = MF_R(0.0);
            for (i = 0; i < NWAVES; ++i)
                s += amp[i] * MF_SIN(MF_R(2.0) * MF_PI * ((mf_real)k[i][0] * u + (mf_real)k[i][1] * v) + ph[i]);
            h[y * N + x] = s;
        }
}

/* LEADR: the whole filtered slope distribution; wo, sun in the plane's frame */
static mf_vec3 shade_leadr(mf_leadr a, mf_vec3 wo, mf_vec3 sun)
{
    mf_vec3 wo_ctx = wo, c = mf_vec3_make(0, 0, 0);
    mf_real spec, diff;
    /* the mean surface faces away from the viewer (steep wave backs under a
     * small footprint): black, as the grid integrals give; mf_leadr_specular
     * alone is not 0 there in float builds */
    if (!(wo.z - a.E_x * wo.x - a.E_y * wo.y > MF_R(0.0))) return c;
    c = mf_leadr_specular_env(a, wo, GRID, 1, sky_env, &wo_ctx);
    spec = mf_leadr_specular(a, wo, sun) * fresnel(wo, sun);
    diff = mf_leadr_diffuse(a, wo, sun, GRID);
    c.x += sun_rgb[0] * (spec + diff * albedo[0]);
    c.y += sun_rgb[1] * (spec + diff * albedo[1]);
    c.z += sun_rgb[2] * (spec + diff * albedo[2]);
    return c;
}

/* naive: the mesonormal with the base roughness (Beckmann), mirror sky */
static mf_vec3 shade_naive(mf_leadr a, mf_vec3 wo, mf_vec3 sun)
{
    mf_vec3 n = mf_leadr_mean_normal(a), lo, li, r, c = mf_vec3_make(0, 0, 0);
    mf_basis fr = mf_basis_from_normal(n);
    mf_vec3 t = fr.t, b = fr.b;
    mf_ndf d = mf_beckmann(base_alpha, base_alpha);
    mf_real spec, diff;
    lo = mf_vec3_make(mf_dot(wo, t), mf_dot(wo, b), mf_dot(wo, n));
    li = mf_vec3_make(mf_dot(sun, t), mf_dot(sun, b), mf_dot(sun, n));
    if (!(lo.z > MF_R(0.0))) return c;
    r = mf_reflect(wo, n);
    if (r.z > MF_R(0.0)) c = mf_scale(sky(r), fresnel(wo, r));
    spec = mf_brdf(&d, lo, li) * mf_max(li.z, MF_R(0.0)) * fresnel(wo, sun);
    diff = mf_max(li.z, MF_R(0.0)) * MF_INV_PI;
    c.x += sun_rgb[0] * (spec + diff * albedo[0]);
    c.y += sun_rgb[1] * (spec + diff * albedo[1]);
    c.z += sun_rgb[2] * (spec + diff * albedo[2]);
    return c;
}

int main(int argc, char **argv)
{
    const char *base = argc > 1 ? argv[1] : "leadr_zoom";
    const mf_real deg = MF_PI / MF_R(180.0), cam_h = MF_R(1.0);
    const mf_real th = view_deg * deg, se = sun_deg * deg;
    /* camera at (0, 0, cam_h) looking along +y, tilted th from straight down */
    const mf_vec3 fwd = mf_vec3_make(MF_R(0.0), MF_SIN(th), -MF_COS(th));
    const mf_vec3 up = mf_vec3_make(MF_R(0.0), MF_COS(th), MF_SIN(th));
    const mf_vec3 sun = mf_vec3_make(MF_R(0.0), MF_COS(se), MF_SIN(se));
    const mf_real tan_v = MF_SIN(MF_R(0.5) * vfov_deg * deg) / MF_COS(MF_R(0.5) * vfov_deg * deg);
    const mf_real tan_h = tan_v * (mf_real)PW / (mf_real)PH;
    const mf_real pix_angle = MF_R(2.0) * tan_v / (mf_real)PH;
    /* width of the view at the center ray's hit point, in world units */
    const mf_real center_width = MF_R(2.0) * tan_h * cam_h / MF_COS(th);
    mf_real *h = (mf_real *)malloc(sizeof(mf_real) * N * N);
    ex_image im;
    float *img;
    mf_leadr_map map;
    mf_leadr top;
    mf_result res;
    long bad = 0;
    int px, py, s, c, err;
    if (!h || ex_image_init(&im, W, H)) { fprintf(stderr, "out of memory\n"); free(h); return 1; }
    img = im.lin;
    make_heights(h);
    res = mf_leadr_map_from_heights(&map, h, N, N, base_alpha, base_alpha);
    free(h);
    if (res != MF_SUCCESS) {
        fprintf(stderr, "moment map: %s\n", mf_result_string(res));
        ex_image_free(&im);
        return 1;
    }
    top = map.texels[map.offset[map.levels - 1]];   /* the mean over the whole tile */
    for (py = 0; py < H; ++py)
        for (px = 0; px < W; ++px) {
            int col = px / PW, row = py / PH;
            mf_real tile = center_width / tiles[col];   /* tile size in world units */
            mf_real sum[3] = { 0, 0, 0 };
            rng r;
            rng_seed(&r, (uint64_t)(py * W + px));
            for (s = 0; s < SPP; ++s) {
                mf_real sx = (MF_R(2.0) * ((mf_real)(px % PW) + (mf_real)(s & 1) * MF_R(0.5) + MF_R(0.5) * rng_u(&r)) / (mf_real)PW - MF_R(1.0)) * tan_h;
                mf_real sy = (MF_R(1.0) - MF_R(2.0) * ((mf_real)(py % PH) + (mf_real)(s >> 1) * MF_R(0.5) + MF_R(0.5) * rng_u(&r)) / (mf_real)PH) * tan_v;
                mf_vec3 d = mf_normalize(mf_add(fwd, mf_add(mf_vec3_make(sx, MF_R(0.0), MF_R(0.0)), mf_scale(up, sy))));
                mf_vec3 v, wo = mf_scale(d, MF_R(-1.0));
                mf_real vv[3];
                if (d.z > MF_R(-1e-3)) {
                    v = sky(d);   /* above the horizon */
                } else {
                    mf_real t = cam_h / -d.z;
                    /* footprint: the pixel's cross-section t * pix_angle is
                     * stretched by 1/|d.z| along the view on the plane; use the
                     * geometric mean of the two axes, in texture units */
                    mf_real foot = t * pix_angle / (MF_SQRT(-d.z) * tile);
                    mf_leadr a = mf_leadr_map_lookup(&map, t * d.x / tile, t * d.y / tile, foot);
                    v = row == 0 ? shade_leadr(a, wo, sun) : shade_naive(a, wo, sun);
                }
                vv[0] = v.x; vv[1] = v.y; vv[2] = v.z;
                if (!finite3(vv)) { ++bad; continue; }
                for (c = 0; c < 3; ++c) sum[c] += vv[c];
            }
            for (c = 0; c < 3; ++c) img[3 * (py * W + px) + c] = (float)(sum[c] / (mf_real)SPP);
        }
    mf_leadr_map_release(&map);
    ex_tonemap_all(&im, 1.0);
    for (px = 0; px < COLS; ++px) {
        ex_label(&im, px * PW + 4, 4, 1, "tile: 1/%g panel width", (double)tiles[px]);
        ex_text(&im, px * PW + 4, 16, 1, "LEADR moments");
        ex_text(&im, px * PW + 4, PH + 4, 1, "naive mip-mapped normals");
    }
    ex_label(&im, 4, H - 12, 1, "8 waves, RMS slope %.3f; base Beckmann alpha %g", (double)MF_SQRT(top.E_xx + top.E_yy - base_alpha * base_alpha),
             (double)base_alpha);
    err = ex_write(&im, base);
    ex_image_free(&im);
    printf("%d x %d panels of %d x %d: the tile spans 1/%g, 1/%g, 1/%g, 1/%g of the panel width\n",
           COLS, 2, PW, PH, (double)tiles[0], (double)tiles[1], (double)tiles[2], (double)tiles[3]);
    printf("rows: LEADR moments, naive mip-mapped normals (base alpha %g, RMS slope %.3f)\n", (double)base_alpha,
           (double)MF_SQRT(top.E_xx + top.E_yy - base_alpha * base_alpha));
    printf("non-finite samples: %ld\n", bad);
    return bad != 0 || err;
}
