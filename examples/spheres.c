/* Demonstrates the analytic distributions of microfacet.h on a grid of silver
 * spheres: rows GGX, Beckmann, GTR (gamma 1.5), Student-t (gamma 3) and the
 * Charlie sheen (Estevez & Kulla 2017, its exact Smith masking; alpha is its
 * own parameter, the exponent 1/alpha of sin theta_m: the light gathers at
 * grazing angles, the rim of the sphere); columns alpha 0.05, 0.15, 0.3,
 * 0.5, 0.8. Each sphere is lit by one
 * directional light (mf_brdf) and a procedural sky sampled by visible-normal
 * importance sampling (mf_brdf_sample's record: direction and weight), with exact
 * conductor Fresnel per RGB channel. 32 jittered samples per pixel; the sky
 * gets 32 of them on the GGX and Beckmann rows but only 8 on the GTR,
 * Student-t and Charlie rows, whose exact VNDF samplers (Charlie's a
 * numerical inversion) are far slower (about 13 s in all on one core). Writes base.png (tone mapped, each sphere labelled with its
 * distribution and alpha), base.pfm (linear) and, built with OpenEXR,
 * base.exr, and prints the count of non-finite samples (expected 0; the exit
 * status is 1 otherwise).
 *
 *   cc -O2 -I. examples/spheres.c -o spheres -lm      (from the repo root)
 *   ./spheres [base]                                  (default: spheres)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COLS 5
#define ROWS 5
#define CELL 128
#define W (COLS * CELL)
#define H (ROWS * CELL)
#define SPP 32   /* pixel samples: position jitter and the directional light */

static const char *const row_names[ROWS] = { "GGX", "Beckmann", "GTR(1.5)", "Student-t(3)", "Charlie" };
/* sky samples per pixel and row: exact GTR / Student-t visible-normal sampling
 * costs about 150-300x a GGX sample, Charlie's numerical one about 200x, so
 * those rows take fewer (stratified) */
static const int sky_spp[ROWS] = { 32, 32, 8, 8, 8 };
static const mf_real alphas[COLS] = { MF_R(0.05), MF_R(0.15), MF_R(0.3), MF_R(0.5), MF_R(0.8) };
/* silver, complex IOR at roughly 650, 550, 450 nm */
static const mf_real eta[3] = { MF_R(0.155), MF_R(0.117), MF_R(0.138) };
static const mf_real kap[3] = { MF_R(4.83), MF_R(3.12), MF_R(2.15) };


static mf_ndf make_ndf(int row, mf_real a)
{
    static mf_gtr_table gtr;   /* GTR at a non-integer gamma: its Lambda rule built once per roughness */
    switch (row) {
    case 0: return mf_ggx(a, a);
    case 1: return mf_beckmann(a, a);
    case 2:
        if (gtr.alpha != a) mf_gtr_table_build(&gtr, a, MF_R(1.5));
        return mf_gtr_table_ndf(&gtr);
    case 3: return mf_student_t(a, a, MF_R(3.0));
    default: return mf_charlie(a);
    }
}


/* Radiance seen along -z at cell-local position (x, y), |(x, y)| < 1 on the
 * sphere; the sky term (one sample from u1, u2) is scaled by sky_w, 0 skips it. */
static void shade(const mf_ndf *d, mf_real x, mf_real y, mf_real sky_w, mf_real u1, mf_real u2,
                  mf_real out[3])
{
    mf_vec3 n = mf_vec3_make(x, y, MF_SQRT(mf_max(MF_R(1.0) - x * x - y * y, MF_R(0.0))));
    mf_basis fr = mf_basis_from_normal(n);
    mf_vec3 t = fr.t, b = fr.b, wo, wi, wh, lw;
    mf_real f, sk[3];
    mf_sample s;
    int c;
    /* world -> local: components along (t, b, n); the viewer is at +z */
    wo = mf_vec3_make(t.z, b.z, n.z);
    out[0] = out[1] = out[2] = MF_R(0.0);
    /* directional light, radiance 3 */
    lw = mf_normalize(mf_vec3_make(MF_R(-0.5), MF_R(0.6), MF_R(0.7)));
    wi = mf_vec3_make(mf_dot(lw, t), mf_dot(lw, b), mf_dot(lw, n));
    f = MF_R(3.0) * mf_brdf(d, wo, wi) * wi.z;
    if (f > MF_R(0.0)) {
        wh = mf_normalize(mf_add(wo, wi));
        for (c = 0; c < 3; ++c) out[c] += f * mf_fresnel_conductor(mf_dot(wi, wh), eta[c], kap[c]);
    }
    /* sky, one importance sample through the visible normals of wo */
    if (sky_w <= MF_R(0.0)) return;
    s = mf_brdf_sample(d, wo, u1, u2);
    if (s.lobe == MF_LOBE_NONE) return;
    wi = s.wi;
    f = sky_w * s.weight;
    wh = mf_normalize(mf_add(wo, wi));
    ex_sky(mf_add(mf_add(mf_scale(t, wi.x), mf_scale(b, wi.y)), mf_scale(n, wi.z)), sk);
    for (c = 0; c < 3; ++c) out[c] += f * mf_fresnel_conductor(mf_dot(wi, wh), eta[c], kap[c]) * sk[c];
}

int main(int argc, char **argv)
{
    const char *base = argc > 1 ? argv[1] : "spheres";
    const mf_real radius = MF_R(0.44) * CELL, bg = MF_R(0.04);
    ex_image im;
    long bad = 0;
    int px, py, s, c, err;
    if (ex_image_init(&im, W, H)) return 1;

    for (py = 0; py < H; ++py) {
        int row = py / CELL;
        for (px = 0; px < W; ++px) {
            int col = px / CELL;
            mf_ndf d = make_ndf(row, alphas[col]);
            int stride = SPP / sky_spp[row];
            mf_real sum[3] = { 0, 0, 0 }, v[3], sh1, sh2;
            rng r;
            rng_seed(&r, (uint64_t)(py * W + px));
            sh1 = rng_u(&r); sh2 = rng_u(&r);   /* per-pixel shift of the sky point set */
            for (s = 0; s < SPP; ++s) {
                /* sky sample j: u1 stratified, u2 golden-ratio sequence, both shifted */
                mf_real j = (mf_real)(s / stride);
                mf_real u1 = j / (mf_real)sky_spp[row] + sh1, u2 = j * MF_R(0.618034) + sh2;
                /* jittered position in the cell, y up, in sphere radii */
                mf_real x = ((mf_real)(px % CELL) + rng_u(&r) - MF_R(0.5) * CELL) / radius;
                mf_real y = (MF_R(0.5) * CELL - (mf_real)(py % CELL) - rng_u(&r)) / radius;
                if (x * x + y * y >= MF_R(1.0)) { v[0] = v[1] = v[2] = bg; }
                else shade(&d, x, y, s % stride ? MF_R(0.0) : (mf_real)stride,
                           u1 - (mf_real)(int)u1, u2 - (mf_real)(int)u2, v);
                if (!finite3(v)) { ++bad; continue; }   /* guard: never let NaN through */
                for (c = 0; c < 3; ++c) sum[c] += v[c];
            }
            for (c = 0; c < 3; ++c) ex_px(&im, px, py)[c] = (float)(sum[c] / (mf_real)SPP);
        }
    }

    ex_tonemap_all(&im, 1.0);
    for (py = 0; py < ROWS; ++py)
        for (px = 0; px < COLS; ++px) {
            ex_text(&im, px * CELL + 4, py * CELL + 4, 1, row_names[py]);
            ex_label(&im, px * CELL + 4, py * CELL + CELL - 11, 1, "alpha %g", (double)alphas[px]);
        }
    err = ex_write(&im, base);
    ex_image_free(&im);

    printf("rows: %s, %s, %s, %s, %s; columns: alpha = 0.05 0.15 0.3 0.5 0.8\n",
           row_names[0], row_names[1], row_names[2], row_names[3], row_names[4]);
    printf("non-finite samples: %ld\n", bad);
    return bad != 0 || err;
}
