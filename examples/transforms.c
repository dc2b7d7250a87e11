/* Demonstrates linearly transformed microsurfaces (mf_transformed; thesis
 * ch. 4, the experiment of Fig. 4.2): a rough silver plate with a GTR
 * distribution (gamma 1.7), lit by a point light above it and seen at an
 * angle, in four panels from left to right:
 *   1. the original microsurface, M = identity;
 *   2. stretched 5x along x = texture u, M = diag(5, 1): smoother along x, so
 *      the highlight gets narrower horizontally (and, D having the factor
 *      det M = 5, brighter: it looks taller once tonemapped);
 *   3. skewed, M = [a c; b d] with (a, b, c, d) = (1, 0, 2, 1), i.e.
 *      mf_mat2_make(1, 2, 0, 1) (row-major): the highlight is sheared;
 *   4. the nonlinear map T(u, v) = (u, v + 2 u^5): at each point M is the
 *      Jacobian of T, [1 0; 10 u^4 1], by mf_jacobian_2d (checked against the
 *      exact one); the shear grows with u and draws the right side of the
 *      highlight out into a streak toward u = 1.
 * alpha is 0.05 rather than the thesis' 0.0121 so that the highlight covers
 * enough pixels at this resolution. A thin dark 10x10 grid marks texture space.
 * Exact conductor Fresnel per RGB channel; 4 jittered samples per pixel.
 * Writes base.png (tone mapped, panels labelled), base.pfm (linear) and, built
 * with OpenEXR, base.exr, and prints the count of non-finite samples
 * (expected 0; the exit status is 1 otherwise).
 *
 *   cc -O2 -I. examples/transforms.c -o transforms -lm   (from the repo root)
 *   ./transforms [base]                                  (default: transforms)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PANELS 4
#define CELL 320
#define W (PANELS * CELL)
#define H CELL
#define SPP 4            /* 2x2 stratified, jittered */
#define ALPHA MF_R(0.05)
#define GAMMA MF_R(1.7)
#define LIGHT_I MF_R(0.3)      /* point light intensity */
#define GRID_W MF_R(0.035)     /* grid line half-width, in grid cells */

static const char *const panel_names[PANELS] = {
    "identity", "stretch diag(5, 1)", "skew [1 2; 0 1]", "Jacobian of (u, v + 2u^5)"
};
/* on the image: a short title (scale 2) and the matrix (scale 1), each
 * within its panel */
static const char *const panel_titles[PANELS] = { "identity", "stretch", "skew", "warp Jacobian" };
static const char *const panel_matrices[PANELS] = {
    "M = I", "M = diag(5, 1)", "M = [1 2; 0 1]", "M = Jacobian of (u, v + 2u^5)"
};
/* silver, complex IOR at roughly 650, 550, 450 nm */
static const mf_real eta[3] = { MF_R(0.155), MF_R(0.117), MF_R(0.138) };
static const mf_real kap[3] = { MF_R(4.83), MF_R(3.12), MF_R(2.15) };


static mf_vec3 sub(mf_vec3 a, mf_vec3 b) { return mf_add(a, mf_scale(b, MF_R(-1.0))); }

/* The nonlinear map of panel 4: T(u, v) = (u, v + 2 u^5). */
static void warp(mf_real u, mf_real v, mf_real out[2], void *ctx)
{
    (void)ctx;
    out[0] = u;
    out[1] = v + MF_R(2.0) * u * u * u * u * u;
}

/* M of panel p at texture point (u, v); *err collects the largest deviation
 * of the numerical Jacobian from the exact [1 0; 10 u^4 1]. */
static mf_mat2 panel_matrix(int p, mf_real u, mf_real v, mf_real *err)
{
    mf_mat2 J;
    mf_real e;
    switch (p) {
    case 0: return mf_mat2_make(MF_R(1.0), MF_R(0.0), MF_R(0.0), MF_R(1.0));
    case 1: return mf_mat2_make(MF_R(5.0), MF_R(0.0), MF_R(0.0), MF_R(1.0));
    case 2: return mf_mat2_make(MF_R(1.0), MF_R(2.0), MF_R(0.0), MF_R(1.0));
    default:
        J = mf_jacobian_2d(warp, NULL, u, v, MF_R(1e-3));
        e = MF_FABS(J.m00 - MF_R(1.0)) + MF_FABS(J.m01) + MF_FABS(J.m11 - MF_R(1.0))
          + MF_FABS(J.m10 - MF_R(10.0) * u * u * u * u);
        if (e > *err) *err = e;
        return J;
    }
}

/* 1 away from the grid lines of the 10x10 texture grid, a dark factor on them. */
static mf_real grid(mf_real u)
{
    mf_real f = MF_R(10.0) * u;
    f -= (mf_real)(int)f;
    return (f < GRID_W || f > MF_R(1.0) - GRID_W) ? MF_R(0.15) : MF_R(1.0);
}

/* Radiance along the ray eye + t dir in panel p. World z is up and the plate
 * is [0,1]^2 in the plane z = 0 with u along x and v along y, so the shading
 * frame (x along u, y along v, z the normal) is the world frame itself. */
static void shade(const mf_ndf *base, int p, mf_vec3 eye, mf_vec3 dir, mf_real out[3], mf_real *err)
{
    const mf_vec3 light = mf_vec3_make(MF_R(0.5), MF_R(1.0), MF_R(1.0));
    mf_real t = -eye.z / dir.z, r2, f;
    mf_vec3 x, wo, wi, wh;
    mf_ndf d;
    int c;
    out[0] = out[1] = out[2] = MF_R(0.03);   /* background */
    if (!(t > MF_R(0.0))) return;
    x = mf_add(eye, mf_scale(dir, t));
    if (x.x < MF_R(0.0) || x.x > MF_R(1.0) || x.y < MF_R(0.0) || x.y > MF_R(1.0)) return;
    d = mf_transformed(*base, panel_matrix(p, x.x, x.y, err));
    wo = mf_normalize(sub(eye, x));
    wi = sub(light, x);
    r2 = mf_dot(wi, wi);
    wi = mf_scale(wi, MF_R(1.0) / MF_SQRT(r2));
    f = LIGHT_I / r2 * mf_brdf(&d, wo, wi) * wi.z * grid(x.x) * grid(x.y);
    wh = mf_normalize(mf_add(wo, wi));
    for (c = 0; c < 3; ++c) out[c] = f * mf_fresnel_conductor(mf_dot(wi, wh), eta[c], kap[c]);
}

int main(int argc, char **argv)
{
    const char *base_path = argc > 1 ? argv[1] : "transforms";
    /* pinhole camera in front of the plate, looking down at its middle */
    const mf_vec3 eye = mf_vec3_make(MF_R(0.5), MF_R(-0.3), MF_R(1.6));
    const mf_vec3 fwd = mf_normalize(sub(mf_vec3_make(MF_R(0.5), MF_R(0.5), MF_R(0.0)), eye));
    const mf_vec3 right = mf_normalize(mf_cross(fwd, mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0))));
    const mf_vec3 up = mf_cross(right, fwd);
    const mf_real tan_half = MF_R(0.34);
    mf_gtr_table gtr;   /* GTR at a non-integer gamma: its Lambda rule built once */
    mf_ndf base;
    ex_image im;
    mf_real jac_err = MF_R(0.0);
    long bad = 0;
    int px, py, s, c, err;
    if (ex_image_init(&im, W, H)) return 1;
    mf_gtr_table_build(&gtr, ALPHA, GAMMA);
    base = mf_gtr_table_ndf(&gtr);

    for (py = 0; py < H; ++py) {
        for (px = 0; px < W; ++px) {
            mf_real sum[3] = { 0, 0, 0 }, v[3];
            rng r;
            rng_seed(&r, (uint64_t)(py * W + px));
            for (s = 0; s < SPP; ++s) {
                /* jittered position in the panel, in [-1, 1]^2, y up */
                mf_real jx = MF_R(0.5) * ((mf_real)(s % 2) + rng_u(&r));
                mf_real jy = MF_R(0.5) * ((mf_real)(s / 2) + rng_u(&r));
                mf_real sx = MF_R(2.0) * ((mf_real)(px % CELL) + jx) / CELL - MF_R(1.0);
                mf_real sy = MF_R(1.0) - MF_R(2.0) * ((mf_real)py + jy) / CELL;
                mf_vec3 dir = mf_add(fwd, mf_scale(mf_add(mf_scale(right, sx), mf_scale(up, sy)), tan_half));
                shade(&base, px / CELL, eye, mf_normalize(dir), v, &jac_err);
                if (!finite3(v)) { ++bad; continue; }   /* guard: never let NaN through */
                for (c = 0; c < 3; ++c) sum[c] += v[c];
            }
            for (c = 0; c < 3; ++c) ex_px(&im, px, py)[c] = (float)(sum[c] / (mf_real)SPP);
        }
    }

    ex_tonemap_all(&im, 1.0);
    for (px = 0; px < PANELS; ++px) {
        ex_label(&im, px * CELL + 8, 8, 2, "%d. %s", px + 1, panel_titles[px]);
        ex_text(&im, px * CELL + 8, 30, 1, panel_matrices[px]);
    }
    ex_label(&im, 6, H - 13, 1, "GTR gamma %.3g, alpha %.3g", (double)GAMMA, (double)ALPHA);
    err = ex_write(&im, base_path);
    ex_image_free(&im);

    printf("panels, left to right: 1. %s, 2. %s, 3. %s, 4. %s\n",
           panel_names[0], panel_names[1], panel_names[2], panel_names[3]);
    printf("max |mf_jacobian_2d - exact Jacobian| (sum of entries): %.2g\n", (double)jac_err);
    printf("non-finite samples: %ld\n", bad);
    return bad != 0 || err;
}
