/* Demonstrates LEADR mapping (mf_leadr_map_from_heights, mf_leadr_map_lookup,
 * mf_leadr_specular, mf_leadr_specular_env, mf_leadr_diffuse) against naive
 * mip-mapped normals on an ocean-like sea: a tiling height field of eight
 * periodic waves (RMS slope about 0.25) repeated over a large plane, seen by a
 * perspective camera 72 degrees off the normal, facing a low sun (15 degrees
 * up) so its glitter path is on screen, under a gradient sky.
 * The sea is displaced, as LEADR displaces its mesosurface (Dupuy et al.
 * 2013): each camera ray marches to its first hit with the waves, each wave
 * filtered by the sample's footprint as the moments are (the box of the
 * lookup), and is shaded there. A flat plane would put samples on wave backs
 * that face away from the eye (steep waves, grazing view): no facet is
 * visible there and both shadings give 0 (black), while the eye sees the
 * wave in front. The moments' mean slopes come from box-filtered central
 * differences of the height map read back trilinearly, so where a ray grazes
 * a crest the displaced sea and the moments may still disagree on the side
 * it sees: such a sample (a handful in the whole image) is left out of its
 * pixel's average and counted.
 * Columns: the same view ever farther away, the texture tile spanning 1/2,
 * 1/8, 1/32 and 1/128 of the panel width at the panel center. Rows:
 *   1. LEADR: slope moments filtered over each sample's footprint shade a
 *      non-centered anisotropic Beckmann lobe (sun, 5x5 sky grid, diffuse);
 *   2. naive: the filtered mean normal alone with the base roughness, as an
 *      ordinary normal-mapped material: at a distance the sea turns into a
 *      flat mirror with a tiny, too-sharp sun highlight.
 * Both rows use water's Fresnel factor (eta 1.33) at the half vector.
 * 4 jittered samples per pixel. Writes base.png (tone mapped, rows and tile
 * sizes labelled), base.pfm (linear) and, built with OpenEXR, base.exr, and
 * prints the count of non-finite samples (expected 0) and of the grazing
 * samples left out (expected below 1e-4 of all); the exit status is 1
 * otherwise.
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

/* Sky radiance along d (z is up): bright hazy horizon, blue zenith. Below
 * the horizon, where a reflected ray would meet the sea again, the horizon's
 * radiance stands in for that second bounce (both rows alike). */
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
static const int wave_k[NWAVES][2] = { { 1, 3 }, { -3, 2 }, { 2, 5 }, { 7, 4 },
                                       { -4, 9 }, { 10, 7 }, { 5, 16 }, { -19, 11 } };
static const mf_real wave_ph[NWAVES] = { MF_R(0.3), MF_R(1.7), MF_R(4.1), MF_R(2.2),
                                         MF_R(5.0), MF_R(0.9), MF_R(3.3), MF_R(1.2) };
static mf_real wave_len[NWAVES], wave_amp[NWAVES];   /* |k|, height amplitude */

/* The sea's height at (u, v), wave i weighted by w[i] (1: unfiltered) */
static mf_real sea_height(mf_real u, mf_real v, const mf_real *w)
{
    mf_real s = MF_R(0.0);
    int i;
    u -= MF_FLOOR(u); v -= MF_FLOOR(v);   /* one period: small sine arguments */
    for (i = 0; i < NWAVES; ++i)
        if (w[i] != MF_R(0.0))
            s += w[i] * wave_amp[i] * MF_SIN(MF_R(2.0) * MF_PI * ((mf_real)wave_k[i][0] * u + (mf_real)wave_k[i][1] * v) + wave_ph[i]);
    return s;
}

static void make_heights(mf_real *h)
{
    static const mf_real one[NWAVES] = { 1, 1, 1, 1, 1, 1, 1, 1 };
    int x, y, i;
    for (i = 0; i < NWAVES; ++i) {
        wave_len[i] = MF_SQRT((mf_real)(wave_k[i][0] * wave_k[i][0] + wave_k[i][1] * wave_k[i][1]));
        wave_amp[i] = MF_R(0.125) / (MF_R(2.0) * MF_PI * wave_len[i]);
    }
    for (y = 0; y < N; ++y)
        for (x = 0; x < N; ++x) h[y * N + x] = sea_height((mf_real)x / N, (mf_real)y / N, one);
}

/* the mean normal (-E_x, -E_y, 1) of the moments faces the eye */
static int faces(mf_leadr a, mf_vec3 wo) { return wo.z - a.E_x * wo.x - a.E_y * wo.y > MF_R(0.0); }

/* sin(pi x) / (pi x): a sine of frequency x (cycles per unit) averaged over a
 * box of unit width keeps this much of its amplitude */
static mf_real sinc(mf_real x)
{
    return MF_FABS(x) < MF_R(1e-4) ? MF_R(1.0) : MF_SIN(MF_PI * x) / (MF_PI * x);
}

/* above the sea at distance t along the ray: > 0 */
static mf_real above(mf_vec3 d, mf_real t, mf_real cam_h, mf_real tile, const mf_real *w)
{
    return (cam_h + t * d.z) / tile - sea_height(t * d.x / tile, t * d.y / tile, w);
}

/* Distance along the unit ray from (0, 0, cam_h) in direction d (d.z < 0) to
 * its first hit with the sea displaced by tile * height (texture units are
 * tiles), and in *m the moments there (lookup with footprint foot, texture
 * units). The waves are filtered like the moments: the lookup reads the mip
 * level whose texels are foot wide, box averages, in which a wave of (k_x,
 * k_y) cycles per tile keeps sinc(k_x foot) sinc(k_y foot) of its amplitude
 * (below 1e-3 it is dropped). Steps of an eighth of the shortest wave kept,
 * across the slab the heights can reach, then bisection, give each crossing
 * from above to below, where the filtered surface faces the ray. The
 * moments' mean normal (box-filtered central differences, read trilinearly)
 * can still face away where the ray grazes a crest: such a crossing is taken
 * as a graze past the crest and the march goes on to the next (the last one
 * is returned if none faces the eye). */
static mf_real march(const mf_leadr_map *map, mf_vec3 d, mf_real cam_h, mf_real tile, mf_real foot, mf_leadr *m)
{
    mf_real w[NWAVES], a = MF_R(0.0), kmax = MF_R(0.0), t0, t1, dt, ta, tb, hl, last = MF_R(-1.0);
    mf_vec3 wo = mf_scale(d, MF_R(-1.0));
    int i, j, n, up = 1;
    for (i = 0; i < NWAVES; ++i) {
        w[i] = sinc((mf_real)wave_k[i][0] * foot) * sinc((mf_real)wave_k[i][1] * foot);
        if (MF_FABS(w[i]) < MF_R(1e-3)) { w[i] = MF_R(0.0); continue; }
        a += MF_FABS(w[i]) * wave_amp[i];
        kmax = mf_max(kmax, wave_len[i]);
    }
    if (!(a > MF_R(0.0))) {   /* flat at this footprint: the plane */
        t0 = cam_h / -d.z;
        *m = mf_leadr_map_lookup(map, t0 * d.x / tile, t0 * d.y / tile, foot);
        return t0;
    }
    t0 = (cam_h - a * tile) / -d.z;
    t1 = (cam_h + a * tile) / -d.z;
    hl = MF_SQRT(d.x * d.x + d.y * d.y) / tile;      /* tiles per unit of t */
    dt = MF_R(1.0) / (MF_R(8.0) * kmax * mf_max(hl, MF_R(1e-6)));
    n = (int)MF_CEIL((t1 - t0) / dt);
    if (n < 1) n = 1;
    dt = (t1 - t0) / (mf_real)n;
    ta = t0;
    for (j = 1; j <= n; ++j) {
        tb = j == n ? t1 : t0 + (mf_real)j * dt;
        if (!(above(d, tb, cam_h, tile, w) > MF_R(0.0))) {
            if (up) {   /* a crossing in [ta, tb] */
                mf_real lo = ta, hi = tb;
                for (i = 0; i < 20; ++i) {
                    mf_real tm = MF_R(0.5) * (lo + hi);
                    if (above(d, tm, cam_h, tile, w) > MF_R(0.0)) lo = tm;
                    else hi = tm;
                }
                *m = mf_leadr_map_lookup(map, hi * d.x / tile, hi * d.y / tile, foot);
                if (faces(*m, wo)) return hi;
                last = hi;
            }
            up = 0;
        } else up = 1;
        ta = tb;
    }
    if (!(last > MF_R(0.0))) last = t1;   /* at t1 the ray is below every height */
    *m = mf_leadr_map_lookup(map, last * d.x / tile, last * d.y / tile, foot);
    return last;
}

/* LEADR: the whole filtered slope distribution; wo, sun in the plane's frame */
static mf_vec3 shade_leadr(mf_leadr a, mf_vec3 wo, mf_vec3 sun)
{
    mf_vec3 wo_ctx = wo, c = mf_vec3_make(0, 0, 0);
    mf_real spec, diff;
    /* a mean surface facing away from the viewer has no visible facet: 0, as
     * the grid integrals give (mf_leadr_specular alone is not 0 there in
     * float builds); the displaced sea leaves no such hit (counted in main) */
    if (!faces(a, wo)) return c;
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
    c = mf_scale(sky(r), fresnel(wo, r));   /* below the horizon: see sky() */
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
    long bad = 0, away = 0;
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
            int used = 0;
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
                    const mf_real t = cam_h / -d.z;
                    /* footprint: the pixel's cross-section t * pix_angle is
                     * stretched by 1/|d.z| along the view on the plane; use the
                     * geometric mean of the two axes, in texture units */
                    mf_real foot = t * pix_angle / (MF_SQRT(-d.z) * tile);
                    mf_leadr a;
                    march(&map, d, cam_h, tile, foot, &a);   /* the displaced sea */
                    /* the two filters disagree at this graze: no hit to shade */
                    if (!faces(a, wo)) { ++away; continue; }
                    v = row == 0 ? shade_leadr(a, wo, sun) : shade_naive(a, wo, sun);
                }
                vv[0] = v.x; vv[1] = v.y; vv[2] = v.z;
                if (!finite3(vv)) { ++bad; continue; }
                for (c = 0; c < 3; ++c) sum[c] += vv[c];
                ++used;
            }
            for (c = 0; c < 3; ++c) img[3 * (py * W + px) + c] = (float)(sum[c] / (mf_real)(used > 0 ? used : 1));
        }
    mf_leadr_map_release(&map);
    ex_tonemap_all(&im, 1.0);
    for (px = 0; px < COLS; ++px) {
        ex_label(&im, px * PW + 4, 4, 1, "tile: 1/%g panel width", (double)tiles[px]);
        ex_text(&im, px * PW + 4, 16, 1, "LEADR moments");
        ex_text(&im, px * PW + 4, PH + 4, 1, "naive mip-mapped normals");
    }
    ex_label(&im, 4, H - 24, 1, "8 waves, RMS slope %.3g", (double)MF_SQRT(top.E_xx + top.E_yy - base_alpha * base_alpha));
    ex_label(&im, 4, H - 12, 1, "base Beckmann alpha %.3g", (double)base_alpha);
    err = ex_write(&im, base);
    ex_image_free(&im);
    printf("%d x %d panels of %d x %d: the tile spans 1/%g, 1/%g, 1/%g, 1/%g of the panel width\n",
           COLS, 2, PW, PH, (double)tiles[0], (double)tiles[1], (double)tiles[2], (double)tiles[3]);
    printf("rows: LEADR moments, naive mip-mapped normals (base alpha %g, RMS slope %.3f)\n", (double)base_alpha,
           (double)MF_SQRT(top.E_xx + top.E_yy - base_alpha * base_alpha));
    printf("non-finite samples: %ld; grazing samples left out (mean normal facing away at the hit): %ld of %ld\n", bad,
           away, (long)W * H * SPP);
    return bad != 0 || away * 10000L > (long)W * H * SPP || err;
}
