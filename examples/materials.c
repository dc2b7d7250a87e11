/* Materials of microfacet.h: energy compensation of rough conductors and
 * rough glass. Two environments, each two rows of spheres (orthographic view):
 *   rows 1-2  a white furnace (radiance 1 everywhere): a conductor with F = 1
 *             should vanish into the background. Row 1 single scattering
 *             (mf_brdf), row 2 with the compensation lobe (mf_brdf_ms,
 *             Kulla & Conty 2017): the rough spheres of row 1 are darker,
 *             those of row 2 match the background.
 *   rows 3-4  a procedural sky and a checkered ground, the conductor gold (exact Fresnel
 *             per RGB channel; the compensation lobe scaled by
 *             mf_ms_fresnel(F_avg, E_avg), F_avg from
 *             mf_fresnel_conductor_average).
 * Columns 1-6: GGX alpha 0.05, 0.2, 0.4, 0.6, 0.8, 1. Columns 7-8: a smooth
 * glass sphere (GGX alpha 0.001) and a rough one (alpha 0.3), eta 1.5, path
 * traced through the sphere with mf_dielectric_sample (radiance transport,
 * up to 32 interface events); in the compensated rows each event picks the
 * single-scattering lobe with probability E(wo) (mf_dielectric_ms_table_albedo)
 * and the compensation lobe (mf_dielectric_ms_table_sample) otherwise, so the rough
 * glass sphere no longer darkens in the furnace. Conductors: one sample of
 * the single-scattering lobe (mf_brdf_sample) plus, in the compensated rows,
 * one of the compensation lobe (mf_brdf_ms_sample, weight pi f_ms). 64
 * samples per pixel (about 4 s on one core). Writes base.png, base.pfm (and base.exr with OpenEXR), prints the
 * mean of each furnace sphere and the count of non-finite samples (exit
 * status 1 when not 0).
 *
 *   cc -O2 -I. examples/materials.c -o materials -lm      (from the repo root)
 *   ./materials [base]                                    (default: materials)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COLS 8
#define ROWS 4
#define CELL 96
#define W (COLS * CELL)
#define H (ROWS * CELL)
#define SPP 64

static const mf_real alphas[COLS] = { MF_R(0.05), MF_R(0.2), MF_R(0.4), MF_R(0.6), MF_R(0.8), MF_R(1.0), MF_R(0.001), MF_R(0.3) };
/* gold, complex IOR at roughly 650, 550, 450 nm */
static const mf_real eta_au[3] = { MF_R(0.16), MF_R(0.42), MF_R(1.37) };
static const mf_real kap_au[3] = { MF_R(3.6), MF_R(2.35), MF_R(1.84) };
#define GLASS MF_R(1.5)

/* environment radiance along the world direction d (y up); furnace: 1 */
static void env(int furnace, mf_vec3 d, mf_real out[3])
{
    static const mf_real hor[3] = { MF_R(1.0), MF_R(0.9), MF_R(0.75) };
    static const mf_real zen[3] = { MF_R(0.2), MF_R(0.4), MF_R(0.9) };
    static const mf_real gnd[3] = { MF_R(0.15), MF_R(0.12), MF_R(0.09) };
    int c;
    if (furnace) { out[0] = out[1] = out[2] = MF_R(1.0); return; }
    if (d.y >= MF_R(0.0)) {
        mf_real t = MF_SQRT(mf_min(d.y, MF_R(1.0)));
        for (c = 0; c < 3; ++c) out[c] = hor[c] + (zen[c] - hor[c]) * t;
        /* a sun-like bright patch */
        if (mf_dot(d, mf_normalize(mf_vec3_make(MF_R(-0.5), MF_R(0.6), MF_R(0.6)))) > MF_R(0.9))
            for (c = 0; c < 3; ++c) out[c] += MF_R(3.0);
    } else {
        /* a checkered ground, so that refraction shows */
        mf_real s = d.y < MF_R(-1e-3) ? MF_R(1.0) / -d.y : MF_R(1e3);
        int k = ((int)MF_FLOOR(d.x * s * MF_R(2.0)) + (int)MF_FLOOR(d.z * s * MF_R(2.0))) & 1;
        for (c = 0; c < 3; ++c) out[c] = gnd[c] * (k ? MF_R(2.5) : MF_R(1.0));
    }
}

/* conductor at the sphere normal n, viewer along +z; comp: add the lobe */
static void conductor(const mf_ndf *d, int furnace, int comp, mf_vec3 n, mf_real u1, mf_real u2,
                      mf_real u3, mf_real u4, const mf_real ms_f[3], mf_real out[3])
{
    mf_basis f = mf_basis_from(n, mf_vec3_make(MF_R(1.0), MF_R(0.0), MF_R(0.0)));
    mf_vec3 wo = mf_to_local(&f, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0))), wh;
    mf_real L[3];
    mf_sample s;
    int c;
    out[0] = out[1] = out[2] = MF_R(0.0);
    s = mf_brdf_sample(d, wo, u1, u2);   /* weight f cos / pdf = G2 / G1, Fresnel apart */
    if (s.lobe != MF_LOBE_NONE) {
        wh = mf_normalize(mf_add(wo, s.wi));
        env(furnace, mf_to_world(&f, s.wi), L);
        for (c = 0; c < 3; ++c)
            out[c] += s.weight * L[c] * (furnace ? MF_R(1.0) : mf_fresnel_conductor(mf_dot(s.wi, wh), eta_au[c], kap_au[c]));
    }
    if (!comp) return;
    s = mf_brdf_ms_sample(d, wo, u3, u4);   /* weight pi f_ms */
    if (s.lobe != MF_LOBE_NONE) {
        env(furnace, mf_to_world(&f, s.wi), L);
        for (c = 0; c < 3; ++c) out[c] += s.weight * L[c] * (furnace ? MF_R(1.0) : ms_f[c]);
    }
}

/* glass sphere of radius 1 at the origin, entered at p (on the sphere) by a
 * ray along dir: interface events until the path leaves */
static void glass(const mf_ndf *d, const mf_dielectric_ms_table *t, int furnace, mf_vec3 p, mf_vec3 dir, rng *r, mf_real out[3])
{
    mf_real thr = MF_R(1.0), L[3];
    int k, c;
    out[0] = out[1] = out[2] = MF_R(0.0);
    for (k = 0; k < 32; ++k) {
        mf_vec3 n = mf_normalize(p), wo, wi;
        mf_basis f = mf_basis_from(n, mf_vec3_make(MF_R(0.0), MF_R(1.0), MF_R(0.0)));
        mf_sample s;
        mf_real b, tt, e;
        wo = mf_to_local(&f, mf_scale(dir, MF_R(-1.0)));   /* outward normal: air above, glass below */
        /* compensated: the single-scattering lobe with probability E(wo),
         * the compensation lobe otherwise */
        e = t ? mf_dielectric_ms_table_albedo(t, wo) : MF_R(1.0);
        if (!t || rng_u(r) < e) {
            s = mf_dielectric_sample(d, wo, GLASS, MF_RADIANCE, rng_u(r), rng_u(r), rng_u(r));
            if (s.lobe == MF_LOBE_NONE) return;
            thr *= s.weight / e;
        } else {
            s = mf_dielectric_ms_table_sample(t, wo, MF_RADIANCE, rng_u(r), rng_u(r), rng_u(r));
            if (s.lobe == MF_LOBE_NONE) return;
            thr *= s.weight / (MF_R(1.0) - e);
        }
        wi = mf_to_world(&f, s.wi);
        dir = wi;
        if (s.wi.z > MF_R(0.0)) {   /* outside: leaves the convex sphere */
            env(furnace, dir, L);
            for (c = 0; c < 3; ++c) out[c] = thr * L[c];
            return;
        }
        /* inside: next hit of the sphere, p + t dir, t = -2 p.dir */
        b = mf_dot(p, dir);
        tt = MF_R(-2.0) * b;
        if (!(tt > MF_R(0.0))) return;
        p = mf_normalize(mf_add(p, mf_scale(dir, tt)));
    }
}

int main(int argc, char **argv)
{
    const char *base = argc > 1 ? argv[1] : "materials";
    const mf_real radius = MF_R(0.44) * CELL;
    mf_real ms_f[COLS][3], mean[ROWS][COLS];
    mf_dielectric_ms_table gt[2];
    long bad = 0, cnt[ROWS][COLS];
    ex_image im;
    int px, py, s, c, col, row, err;
    if (ex_image_init(&im, W, H)) return 1;
    for (col = 0; col < COLS; ++col) {
        mf_ndf d = mf_ggx(alphas[col], alphas[col]);
        for (c = 0; c < 3; ++c)
            ms_f[col][c] = mf_ms_fresnel(mf_fresnel_conductor_average(eta_au[c], kap_au[c]), mf_albedo_average(&d));
    }
    for (col = 0; col < 2; ++col) {
        mf_ndf d = mf_ggx(alphas[6 + col], alphas[6 + col]);
        if (mf_dielectric_ms_table_build(&gt[col], &d, GLASS, 32, 4) != MF_SUCCESS) { fprintf(stderr, "table build failed\n"); return 1; }
    }
    memset(mean, 0, sizeof mean);
    memset(cnt, 0, sizeof cnt);
    for (py = 0; py < H; ++py) {
        row = py / CELL;
        for (px = 0; px < W; ++px) {
            int furnace = row < 2, comp = row % 2 == 1;
            mf_ndf d;
            mf_real sum[3] = { 0, 0, 0 }, v[3];
            int inside = 0;
            rng r;
            col = px / CELL;
            d = mf_ggx(alphas[col], alphas[col]);
            rng_seed(&r, (uint64_t)(py * W + px));
            for (s = 0; s < SPP; ++s) {
                mf_real x = ((mf_real)(px % CELL) + rng_u(&r) - MF_R(0.5) * CELL) / radius;
                mf_real y = (MF_R(0.5) * CELL - (mf_real)(py % CELL) - rng_u(&r)) / radius;
                if (x * x + y * y >= MF_R(1.0)) {
                    if (furnace) v[0] = v[1] = v[2] = MF_R(1.0);
                    else v[0] = v[1] = v[2] = MF_R(0.08);
                } else {
                    mf_vec3 n = mf_vec3_make(x, y, MF_SQRT(mf_max(MF_R(1.0) - x * x - y * y, MF_R(0.0))));
                    inside = 1;
                    if (col < 6) conductor(&d, furnace, comp, n, rng_u(&r), rng_u(&r), rng_u(&r), rng_u(&r), ms_f[col], v);
                    else glass(&d, comp ? &gt[col - 6] : NULL, furnace, n, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(-1.0)), &r, v);
                }
                if (!finite3(v)) { ++bad; continue; }
                for (c = 0; c < 3; ++c) sum[c] += v[c];
            }
            for (c = 0; c < 3; ++c) ex_px(&im, px, py)[c] = (float)(sum[c] / (mf_real)SPP);
            /* mean over the pixels well inside the disc (fully covered) */
            {
                mf_real cx = ((mf_real)(px % CELL) + MF_R(0.5) - MF_R(0.5) * CELL) / radius;
                mf_real cy = (MF_R(0.5) * CELL - (mf_real)(py % CELL) - MF_R(0.5)) / radius;
                if (inside && cx * cx + cy * cy < MF_R(0.9)) {
                    mean[row][col] += (sum[0] + sum[1] + sum[2]) / (MF_R(3.0) * (mf_real)SPP);
                    ++cnt[row][col];
                }
            }
        }
    }
    ex_tonemap_all(&im, 1.0);
    for (row = 0; row < ROWS; ++row)
        for (col = 0; col < COLS; ++col) {
            static const char *const rn[ROWS] = { "furnace", "furnace+ms", "sky", "sky+ms" };
            ex_text(&im, col * CELL + 3, row * CELL + 3, 1, rn[row]);
            ex_label(&im, col * CELL + 3, row * CELL + CELL - 10, 1, col < 6 ? "ggx %g" : "glass %g", (double)alphas[col]);
        }
    mf_dielectric_ms_table_release(&gt[0]);
    mf_dielectric_ms_table_release(&gt[1]);
    err = ex_write(&im, base);
    ex_image_free(&im);
    printf("furnace (radiance 1), mean over each sphere: columns GGX alpha 0.05 0.2 0.4 0.6 0.8 1, glass 0.001, glass 0.3\n");
    for (row = 0; row < 2; ++row) {
        printf("  %-22s", row ? "compensated:" : "single scattering:");
        for (col = 0; col < COLS; ++col) printf(" %.3f", cnt[row][col] ? (double)(mean[row][col] / (mf_real)cnt[row][col]) : 0.0);
        printf("\n");
    }
    printf("non-finite samples: %ld\n", bad);
    return bad != 0 || err;
}
