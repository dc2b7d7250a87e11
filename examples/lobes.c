/* Shows the lobes of a modern material model (OpenPBR-style) on spheres, each
 * rendered twice: in a white furnace (radiance 1 from every direction: a
 * material that neither loses nor gains energy disappears) and under a
 * procedural sky (a horizon-to-zenith gradient, a dark ground and a sun).
 * Rows:
 *   1. diffuse: energy-preserving Oren-Nayar (EON, mf_eon_brdf/_sample),
 *      rho 0.8 at sigma 0, 0.5, 1, and rho 1 at sigma 0 and 1 (invisible in
 *      the furnace);
 *   2. sheen: the Charlie distribution (mf_charlie, sampled by
 *      mf_brdf_sample) over a dark EON base scaled by 1 - E_sheen(wo), at
 *      alpha 0.15, 0.3, 0.6, 1, and alpha 0.3 over a white base (rho 1:
 *      invisible in the furnace when E_sheen is the sheen's true albedo);
 *   3. fuzz: the volumetric sheen (mf_sheen_*, an LTC of a fibre layer) over
 *      the same bases, scaled by 1 - mf_sheen_albedo(wo);
 *   4. metals: GGX (alpha 0.3) with the F82-tint Fresnel (mf_fresnel_f82) of
 *      gold, copper and aluminium plus the Kulla-Conty compensation lobe
 *      (mf_brdf_ms, mf_ms_fresnel of mf_fresnel_f82_average), then a white
 *      conductor (f0 = tint = 1) at alpha 0.8 without and with compensation;
 *   5. thin film: oil (n 1.5) on iron, GGX alpha 0.15, film thickness 100
 *      to 800 nm (mf_fresnel_thin_film_rgb).
 * The sky term is one importance sample per lobe and pixel sample (the
 * sampler's record: direction and weight); the sun is evaluated directly.
 * 32 jittered samples a pixel (16 on the sheen row). Prints one check per
 * lobe (the furnace sphere's mean radiance over the background's for the
 * energy-preserving spheres, the thin film at zero thickness against the
 * bare conductor's Fresnel) and the count of non-finite samples; the exit
 * status is 1 when a check fails. Writes base.png (tone mapped, labelled), base.pfm (linear)
 * and, built with OpenEXR, base.exr.
 *
 *   cc -O2 -I. examples/lobes.c -o lobes -lm      (from the repo root)
 *   ./lobes [base]                                (default: lobes)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COLS 5                 /* spheres per row and background */
#define ROWS 5
#define CELL 100
#define HEAD 18                /* the background titles above the grid */
#define W (2 * COLS * CELL)
#define H (HEAD + ROWS * CELL)
#define SPP 16                 /* pixel samples of the sheen row (its MIS counts) */
/* pixel samples per row: the sheen row's Charlie evaluations cost about 10x
 * the other rows' samples, so it takes half as many */
static const int row_spp[ROWS] = { 32, SPP, 32, 32, 32 };
#define NMU 64                 /* sheen albedo table: mu = (i / (NMU - 1))^2 */
#define NFILM 256              /* thin-film table: cos = i / (NFILM - 1) */
#define SHEEN_STRIDE 4         /* the Charlie sampler (a numerical inversion, about
                                  50x a GGX sample) on every 4th pixel sample */

enum { ROW_EON, ROW_SHEEN, ROW_FUZZ, ROW_METAL, ROW_FILM };

/* ---- materials */
static const mf_real eon_rho[COLS] = { MF_R(0.8), MF_R(0.8), MF_R(0.8), MF_R(1.0), MF_R(1.0) };
static const mf_real eon_sigma[COLS] = { MF_R(0.0), MF_R(0.5), MF_R(1.0), MF_R(0.0), MF_R(1.0) };

static const mf_real sheen_alpha[COLS] = { MF_R(0.15), MF_R(0.3), MF_R(0.6), MF_R(1.0), MF_R(0.3) };
/* a dark red velvet base (EON, sigma 1); the last column's base is white */
static const mf_real sheen_base[3] = { MF_R(0.08), MF_R(0.01), MF_R(0.02) };
#define SHEEN_SIGMA MF_R(1.0)

/* F82-tint parameters (f0 = base_color, tint = specular_color) of the
 * OpenPBR example materials (AcademySoftwareFoundation/OpenPBR,
 * examples/open_pbr_{gold,copper,aluminum_brushed}.mtlx; Hoffman 2023's
 * model). Copper and aluminium are given there in linear Rec.709; gold is
 * given in ACEScg (f0 0.929 0.788 0.374, tint 0.974 1.0 0.984) and is taken
 * to linear Rec.709 here by the AP1-to-Rec.709 matrix, clamped to [0, 1]. */
static const char *const metal_names[COLS] = { "gold", "copper", "aluminium", "white, ss", "white, +ms" };
static const mf_real metal_f0[COLS][3] = {
    { MF_R(1.0), MF_R(0.774), MF_R(0.307) },
    { MF_R(0.988), MF_R(0.688), MF_R(0.448) },
    { MF_R(0.912), MF_R(0.914), MF_R(0.920) },
    { MF_R(1.0), MF_R(1.0), MF_R(1.0) },
    { MF_R(1.0), MF_R(1.0), MF_R(1.0) },
};
static const mf_real metal_tint[COLS][3] = {
    { MF_R(0.957), MF_R(1.0), MF_R(0.982) },
    { MF_R(0.999), MF_R(0.946), MF_R(0.705) },
    { MF_R(0.970), MF_R(0.979), MF_R(0.988) },
    { MF_R(1.0), MF_R(1.0), MF_R(1.0) },
    { MF_R(1.0), MF_R(1.0), MF_R(1.0) },
};
static const mf_real metal_alpha[COLS] = { MF_R(0.3), MF_R(0.3), MF_R(0.3), MF_R(0.8), MF_R(0.8) };
static const int metal_ms[COLS] = { 1, 1, 1, 0, 1 };

/* thin film: oil (n 1.5) on iron; the iron's complex index per channel
 * (about 650, 550, 450 nm) is approximate, illustrative: a base of moderate
 * reflectance, so that the interference colours show (on silver, F near 0.95
 * leaves them faint) */
static const mf_real film_nm[COLS] = { MF_R(100.0), MF_R(250.0), MF_R(400.0), MF_R(600.0), MF_R(800.0) };
#define FILM_ETA MF_R(1.5)
#define FILM_ALPHA MF_R(0.15)
static const mf_real fe_eta[3] = { MF_R(2.9), MF_R(2.9), MF_R(2.4) };
static const mf_real fe_kap[3] = { MF_R(3.1), MF_R(2.9), MF_R(2.9) };

/* per column: the sheen albedo table and the metals' multiple-scattering factors */
static mf_real sheen_E[COLS][NMU];
static mf_real metal_fms[COLS][3];
static mf_real film_F[COLS][NFILM][3];

/* ---- environment: the furnace (1 everywhere) or the sky (y up) */
static void env(int furnace, mf_vec3 d, mf_real out[3])
{
    if (furnace) out[0] = out[1] = out[2] = MF_R(1.0);
    else ex_sky(d, out);
}
/* the sun: a directional light of irradiance sun_e (sky only) */
static const mf_real sun_e[3] = { MF_R(3.0), MF_R(2.8), MF_R(2.5) };

/* the sheen albedo E(mu), linear in sqrt(mu) over the table */
static mf_real sheen_albedo(int col, mf_real mu)
{
    mf_real x = MF_SQRT(mf_clamp(mu, MF_R(0.0), MF_R(1.0))) * (mf_real)(NMU - 1), f;
    int i = (int)x;
    if (i >= NMU - 1) return sheen_E[col][NMU - 1];
    f = x - (mf_real)i;
    return sheen_E[col][i] + f * (sheen_E[col][i + 1] - sheen_E[col][i]);
}

/* the thin-film reflectance (mf_fresnel_thin_film_rgb, tabulated in main:
 * it sums a Fourier series per call), linear in cos */
static void film_fresnel(int col, mf_real cth, mf_real F[3])
{
    mf_real x = mf_clamp(MF_FABS(cth), MF_R(0.0), MF_R(1.0)) * (mf_real)(NFILM - 1), f;
    int i = (int)x, c;
    if (i >= NFILM - 1) i = NFILM - 2;
    f = x - (mf_real)i;
    for (c = 0; c < 3; ++c) F[c] = film_F[col][i][c] + f * (film_F[col][i + 1][c] - film_F[col][i][c]);
}

/* Radiance toward the viewer (+z) from the sphere point with normal n, for
 * material (row, col) in the furnace or the sky; u: 4 random numbers. */
static void shade(int row, int col, int furnace, mf_vec3 n, mf_vec3 sun_w, const mf_real u[4], int sheen_on,
                  mf_real out[3])
{
    mf_basis fr = mf_basis_from_normal(n);
    mf_vec3 t = fr.t, b = fr.b, wo = mf_vec3_make(t.z, b.z, n.z), sun;
    mf_real L[3], sunz;
    mf_sample s;
    int c;
#define TO_WORLD(w) mf_add(mf_add(mf_scale(t, (w).x), mf_scale(b, (w).y)), mf_scale(n, (w).z))
    sun = mf_vec3_make(mf_dot(sun_w, t), mf_dot(sun_w, b), mf_dot(sun_w, n));
    sunz = furnace ? MF_R(0.0) : sun.z;   /* no sun in the furnace */
    out[0] = out[1] = out[2] = MF_R(0.0);
    switch (row) {
    case ROW_EON: {
        mf_real rho = eon_rho[col], sg = eon_sigma[col];
        s = mf_eon_sample(wo, rho, sg, u[0], u[1]);
        if (s.lobe != MF_LOBE_NONE) {
            env(furnace, TO_WORLD(s.wi), L);
            for (c = 0; c < 3; ++c) out[c] += s.weight * L[c];   /* grey rho: one weight */
        }
        if (sunz > MF_R(0.0))
            for (c = 0; c < 3; ++c) out[c] += mf_eon_brdf(wo, sun, rho, sg) * sunz * sun_e[c];
        break;
    }
    case ROW_SHEEN: {
        /* f = f_sheen + (1 - E_sheen(wo)) f_base: the base sees what the
         * sheen does not reflect (albedo scaling, as OpenPBR's fuzz layer);
         * E_sheen from the table of mf_albedo built in main. */
        mf_ndf d = mf_charlie(sheen_alpha[col]);
        mf_real scale = MF_R(1.0) - sheen_albedo(col, wo.z), base[3];
        for (c = 0; c < 3; ++c) base[c] = col == COLS - 1 ? MF_R(1.0) : sheen_base[c];
        /* The sheen lobe by two strategies, combined by the balance
         * heuristic over a pixel's samples (Veach 1997, multi-sample MIS):
         * the Charlie sampler on one pixel sample in SHEEN_STRIDE and the
         * base's EON direction on every one; SPP f L cos / (n_c p_c + n_b p_b)
         * a sample (the pixel divides by SPP). Charlie's sampled directions
         * fall below the horizon often at grazing views (weight 0), so its
         * sampler alone leaves the rim noisy. */
        if (sheen_on) {
            s = mf_brdf_sample(&d, wo, u[0], u[1]);
            if (s.lobe != MF_LOBE_NONE) {
                mf_real den = (mf_real)(SPP / SHEEN_STRIDE) * s.pdf + (mf_real)SPP * mf_eon_pdf(wo, s.wi, SHEEN_SIGMA);
                env(furnace, TO_WORLD(s.wi), L);
                for (c = 0; c < 3; ++c) out[c] += (mf_real)SPP * s.weight * s.pdf / den * L[c];
            }
        }
        s = mf_eon_sample(wo, MF_R(1.0), SHEEN_SIGMA, u[2], u[3]);   /* the base: per-channel weights */
        if (s.lobe != MF_LOBE_NONE) {
            mf_real fcos = mf_brdf(&d, wo, s.wi) * s.wi.z;
            mf_real den = (mf_real)(SPP / SHEEN_STRIDE) * mf_brdf_pdf(&d, wo, s.wi) + (mf_real)SPP * s.pdf;
            env(furnace, TO_WORLD(s.wi), L);
            for (c = 0; c < 3; ++c)
                out[c] += (scale * mf_eon_brdf(wo, s.wi, base[c], SHEEN_SIGMA) * s.wi.z / s.pdf
                           + (den > MF_R(0.0) ? (mf_real)SPP * fcos / den : MF_R(0.0))) * L[c];
        }
        if (sunz > MF_R(0.0)) {
            mf_real fs = mf_brdf(&d, wo, sun);
            for (c = 0; c < 3; ++c)
                out[c] += (fs + scale * mf_eon_brdf(wo, sun, base[c], SHEEN_SIGMA)) * sunz * sun_e[c];
        }
        break;
    }
    case ROW_FUZZ: {
        /* The volumetric sheen (mf_sheen_*, OpenPBR's fuzz) over the same
         * bases, albedo-scaled by its own albedo mf_sheen_albedo: one sample
         * from either lobe with probability 1/2 (u[0] picks), weighted by
         * the mixture pdf (the one-sample balance heuristic). */
        mf_real a = sheen_alpha[col], scale = MF_R(1.0) - mf_sheen_albedo(wo.z, a), base[3];
        for (c = 0; c < 3; ++c) base[c] = col == COLS - 1 ? MF_R(1.0) : sheen_base[c];
        s = u[0] < MF_R(0.5) ? mf_sheen_sample(wo, a, MF_R(2.0) * u[0], u[1])
                             : mf_eon_sample(wo, MF_R(1.0), SHEEN_SIGMA, MF_R(2.0) * u[0] - MF_R(1.0), u[1]);
        if (s.lobe != MF_LOBE_NONE) {
            mf_real pm = MF_R(0.5) * (mf_sheen_pdf(wo, s.wi, a) + mf_eon_pdf(wo, s.wi, SHEEN_SIGMA));
            mf_real ff = mf_sheen_brdf(wo, s.wi, a);
            env(furnace, TO_WORLD(s.wi), L);
            if (pm > MF_R(0.0))
                for (c = 0; c < 3; ++c)
                    out[c] += (ff + scale * mf_eon_brdf(wo, s.wi, base[c], SHEEN_SIGMA)) * s.wi.z / pm * L[c];
        }
        if (sunz > MF_R(0.0)) {
            mf_real ff = mf_sheen_brdf(wo, sun, a);
            for (c = 0; c < 3; ++c)
                out[c] += (ff + scale * mf_eon_brdf(wo, sun, base[c], SHEEN_SIGMA)) * sunz * sun_e[c];
        }
        break;
    }
    case ROW_METAL: {
        mf_ndf d = mf_ggx(metal_alpha[col], metal_alpha[col]);
        const mf_real *f0 = metal_f0[col], *tn = metal_tint[col];
        s = mf_brdf_sample(&d, wo, u[0], u[1]);
        if (s.lobe != MF_LOBE_NONE) {
            mf_real cw = mf_dot(wo, mf_normalize(mf_add(wo, s.wi)));
            env(furnace, TO_WORLD(s.wi), L);
            for (c = 0; c < 3; ++c) out[c] += s.weight * mf_fresnel_f82(cw, f0[c], tn[c]) * L[c];
        }
        if (metal_ms[col]) {
            s = mf_brdf_ms_sample(&d, wo, u[2], u[3]);
            if (s.lobe != MF_LOBE_NONE) {
                env(furnace, TO_WORLD(s.wi), L);
                for (c = 0; c < 3; ++c) out[c] += s.weight * metal_fms[col][c] * L[c];
            }
        }
        if (sunz > MF_R(0.0)) {
            mf_real fs = mf_brdf(&d, wo, sun), fm = metal_ms[col] ? mf_brdf_ms(&d, wo, sun) : MF_R(0.0);
            mf_real cs = mf_dot(wo, mf_normalize(mf_add(wo, sun)));
            for (c = 0; c < 3; ++c)
                out[c] += (fs * mf_fresnel_f82(cs, f0[c], tn[c]) + fm * metal_fms[col][c]) * sunz * sun_e[c];
        }
        break;
    }
    default: {
        mf_ndf d = mf_ggx(FILM_ALPHA, FILM_ALPHA);
        mf_real F[3];
        s = mf_brdf_sample(&d, wo, u[0], u[1]);
        if (s.lobe != MF_LOBE_NONE) {
            mf_real cw = mf_dot(wo, mf_normalize(mf_add(wo, s.wi)));
            film_fresnel(col, cw, F);
            env(furnace, TO_WORLD(s.wi), L);
            for (c = 0; c < 3; ++c) out[c] += s.weight * F[c] * L[c];
        }
        if (sunz > MF_R(0.0)) {
            mf_real fs = mf_brdf(&d, wo, sun);
            film_fresnel(col, mf_dot(wo, mf_normalize(mf_add(wo, sun))), F);
            for (c = 0; c < 3; ++c) out[c] += fs * F[c] * sunz * sun_e[c];
        }
        break;
    }
    }
#undef TO_WORLD
}

/* the label of sphere (row, col): two lines */
static void labels(int row, int col, char *l1, char *l2, size_t n)
{
    switch (row) {
    case ROW_EON:
        snprintf(l1, n, "EON rho %#.3g", (double)eon_rho[col]);
        snprintf(l2, n, "sigma %#.3g", (double)eon_sigma[col]);
        break;
    case ROW_SHEEN:
        snprintf(l1, n, "Charlie a %#.3g", (double)sheen_alpha[col]);
        snprintf(l2, n, col == COLS - 1 ? "on white" : "on dark red");
        break;
    case ROW_FUZZ:
        snprintf(l1, n, "fuzz a %#.3g", (double)sheen_alpha[col]);
        snprintf(l2, n, col == COLS - 1 ? "on white" : "on dark red");
        break;
    case ROW_METAL:
        snprintf(l1, n, "F82 %s", metal_names[col]);
        snprintf(l2, n, "GGX a %#.3g", (double)metal_alpha[col]);
        break;
    default:
        snprintf(l1, n, "oil n %#.3g/iron", (double)FILM_ETA);
        snprintf(l2, n, "film %.0f nm", (double)film_nm[col]);
        break;
    }
}

int main(int argc, char **argv)
{
    const char *base = argc > 1 ? argv[1] : "lobes";
    const mf_real radius = MF_R(0.42) * CELL;
    mf_vec3 sun_w = mf_normalize(mf_vec3_make(MF_R(-0.5), MF_R(0.6), MF_R(0.7)));
    double fsum[ROWS][COLS], fn[ROWS][COLS];   /* furnace: sum of sphere samples (channel mean), count */
    ex_image im;
    long bad = 0;
    int px, py, i, c, k, err, fail = 0;
    double film_dev = 0.0;
    if (ex_image_init(&im, W, H)) return 1;
    memset(fsum, 0, sizeof fsum);
    memset(fn, 0, sizeof fn);

    /* sheen albedo tables: mf_albedo (numerical integration for Charlie) */
    for (k = 0; k < COLS; ++k) {
        mf_ndf d = mf_charlie(sheen_alpha[k]);
        for (i = 0; i < NMU; ++i) {
            mf_real x = (mf_real)i / (mf_real)(NMU - 1), mu = mf_max(x * x, MF_R(1e-4));
            sheen_E[k][i] = mf_albedo(&d, mf_vec3_make(MF_SQRT(MF_R(1.0) - mu * mu), MF_R(0.0), mu));
        }
    }
    /* thin film per column and cos */
    for (k = 0; k < COLS; ++k)
        for (i = 0; i < NFILM; ++i)
            mf_fresnel_thin_film_rgb((mf_real)i / (mf_real)(NFILM - 1), MF_R(1.0), FILM_ETA, film_nm[k], fe_eta, fe_kap,
                                     film_F[k][i]);
    /* metals: Kulla-Conty factor per channel from the F82 average */
    for (k = 0; k < COLS; ++k) {
        mf_ndf d = mf_ggx(metal_alpha[k], metal_alpha[k]);
        mf_real eavg = mf_albedo_average(&d);
        for (c = 0; c < 3; ++c)
            metal_fms[k][c] = mf_ms_fresnel(mf_fresnel_f82_average(metal_f0[k][c], metal_tint[k][c]), eavg);
    }

    for (py = HEAD; py < H; ++py) {
        int row = (py - HEAD) / CELL;
        for (px = 0; px < W; ++px) {
            int furnace = px < COLS * CELL, col = (px / CELL) % COLS, s;
            mf_real sum[3] = { 0, 0, 0 }, v[3], sh[4];
            rng r;
            rng_seed(&r, (uint64_t)(py * W + px));
            for (k = 0; k < 4; ++k) sh[k] = rng_u(&r);   /* per-pixel shift of the point set */
            int n = row_spp[row];
            for (s = 0; s < n; ++s) {
                /* stratified u[0], golden-ratio u[1] (and a second pair), shifted */
                mf_real u[4], x, y, z2;
                u[0] = ((mf_real)s + MF_R(0.5)) / (mf_real)n + sh[0];
                u[1] = (mf_real)s * MF_R(0.618034) + sh[1];
                u[2] = ((mf_real)((s * 7) % n) + MF_R(0.5)) / (mf_real)n + sh[2];
                u[3] = (mf_real)s * MF_R(0.7548777) + sh[3];
                for (k = 0; k < 4; ++k) u[k] -= (mf_real)(int)u[k];
                x = ((mf_real)(px % CELL) + rng_u(&r) - MF_R(0.5) * CELL) / radius;
                y = (MF_R(0.5) * CELL - (mf_real)((py - HEAD) % CELL) - rng_u(&r)) / radius;
                z2 = MF_R(1.0) - x * x - y * y;
                if (z2 <= MF_R(0.0)) {
                    /* the background: the environment seen through a narrow view */
                    env(furnace, mf_normalize(mf_vec3_make(MF_R(0.3) * x * radius / CELL, MF_R(0.3) * y * radius / CELL + MF_R(0.05), MF_R(-1.0))), v);
                } else {
                    shade(row, col, furnace, mf_vec3_make(x, y, MF_SQRT(z2)), sun_w, u, s % SHEEN_STRIDE == 0, v);
                    if (furnace && finite3(v)) {
                        fsum[row][col] += ((double)v[0] + (double)v[1] + (double)v[2]) / 3.0;
                        fn[row][col] += 1.0;
                    }
                }
                if (!finite3(v)) { ++bad; continue; }   /* guard: never let NaN through */
                for (c = 0; c < 3; ++c) sum[c] += v[c];
            }
            for (c = 0; c < 3; ++c) ex_px(&im, px, py)[c] = (float)(sum[c] / (mf_real)n);
        }
    }

    /* thin film at zero thickness is the bare conductor (checked over the angle) */
    for (i = 0; i <= 64; ++i) {
        mf_real cth = mf_max((mf_real)i / MF_R(64.0), MF_R(1e-3)), F[3];
        mf_fresnel_thin_film_rgb(cth, MF_R(1.0), FILM_ETA, MF_R(0.0), fe_eta, fe_kap, F);
        for (c = 0; c < 3; ++c) {
            double e = fabs((double)F[c] - (double)mf_fresnel_conductor(cth, fe_eta[c], fe_kap[c]));
            if (e > film_dev) film_dev = e;
        }
    }

    ex_tonemap_all(&im, 1.0);
    for (k = 0; k < 2; ++k) {
        const char *title = k == 0 ? "white furnace (radiance 1)" : "sky (gradient, ground, sun)";
        ex_text(&im, k * COLS * CELL + (COLS * CELL - ex_text_width(title, 1)) / 2, 5, 1, title);
    }
    for (py = 0; py < ROWS; ++py)
        for (px = 0; px < 2 * COLS; ++px) {
            char l1[64], l2[64];
            labels(py, px % COLS, l1, l2, sizeof l1);
            ex_text(&im, px * CELL + 3, HEAD + py * CELL + 3, 1, l1);
            ex_text(&im, px * CELL + 3, HEAD + py * CELL + CELL - 10, 1, l2);
        }
    err = ex_write(&im, base);
    ex_image_free(&im);

    {
        /* furnace ratios: the background is exactly 1 */
        double eon0 = fsum[ROW_EON][3] / fn[ROW_EON][3], eon1 = fsum[ROW_EON][4] / fn[ROW_EON][4];
        double sh = fsum[ROW_SHEEN][4] / fn[ROW_SHEEN][4], fz = fsum[ROW_FUZZ][4] / fn[ROW_FUZZ][4];
        double ss = fsum[ROW_METAL][3] / fn[ROW_METAL][3], ms = fsum[ROW_METAL][4] / fn[ROW_METAL][4];
        int ok_eon = fabs(eon0 - 1.0) < 1e-2 && fabs(eon1 - 1.0) < 1e-2;
        int ok_fz = fabs(fz - 1.0) < 1e-2, ok_sh = fabs(sh - 1.0) < 1e-2, ok_ms = fabs(ms - 1.0) < 1e-2, ok_film = film_dev < 1e-3;
        printf("EON diffuse: furnace sphere / background at rho 1: %.4f (sigma 0), %.4f (sigma 1) (1 within 1e-2): %s\n",
               eon0, eon1, ok_eon ? "ok" : "FAIL");
        printf("Charlie sheen over a white base (alpha 0.3): furnace sphere / background %.4f (1 within 1e-2): %s\n",
               sh, ok_sh ? "ok" : "FAIL");
        printf("volumetric sheen over a white base (alpha 0.3): furnace sphere / background %.4f (1 within 1e-2): %s\n",
               fz, ok_fz ? "ok" : "FAIL");
        printf("F82 / GGX alpha 0.8, f0 = tint = 1: furnace %.4f single scattering, %.4f with mf_brdf_ms (1 within 1e-2): %s\n",
               ss, ms, ok_ms ? "ok" : "FAIL");
        printf("thin film at 0 nm vs mf_fresnel_conductor: max |difference| %.2e over the angle (below 1e-3): %s\n",
               film_dev, ok_film ? "ok" : "FAIL");
        fail = !(ok_eon && ok_sh && ok_fz && ok_ms && ok_film);
    }
    printf("non-finite samples: %ld\n", bad);
    return bad != 0 || err || fail;
}
