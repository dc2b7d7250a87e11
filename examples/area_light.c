/* Demonstrates Linearly Transformed Cosines (mf_ltc_ggx, mf_ltc_integrate,
 * mf_polygon_irradiance) against Monte Carlo ground truth: a rough plane with
 * three spheres resting on it, lit only by one one-sided rectangular light of
 * radiance 5. Rows: GGX alpha 0.1, 0.25, 0.5. Columns:
 *   1. LTC: specular = mf_ltc_ggx_albedo * mf_ltc_integrate (the built-in GGX
 *      table), diffuse = albedo * mf_polygon_irradiance (exact form factor);
 *   2. Monte Carlo: 256 stratified samples of the light's area plus 256
 *      visible-normal BRDF samples (mf_brdf_sample) per pixel, combined by
 *      multiple importance sampling (balance heuristic, mf_brdf_pdf);
 *   3. |LTC - MC| (the channel mean) through a colour map, with its colour bar.
 * Neither column has shadows (LTC cannot), so both integrate the same thing.
 * Constant specular color 0.6 (no Fresnel), diffuse albedo about 0.3. Prints,
 * per row, the mean relative difference |LTC - MC| / MC over pixels whose MC
 * value is above 0.02, for the total and for the specular part alone (whose
 * energy-weighted sum |LTC - MC| / sum MC follows). The differences are the
 * LTC fit's: they barely move with 4x the samples. About 10 s on one core.
 * Writes base.png (tone mapped; rows, columns and each row's figures written
 * on the image), base.pfm (linear; column 3 holds |LTC - MC| per channel) and,
 * built with OpenEXR, base.exr, and prints the count of non-finite values
 * (expected 0; the exit status is 1 otherwise).
 *
 *   cc -O2 -I. examples/area_light.c -o area_light -lm   (from the repo root)
 *   ./area_light [base]                                 (default: area_light)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PW 360                   /* panel size */
#define PH 270
#define W (3 * PW)
#define H (3 * PH)
#define NLX 16                   /* light samples: NLX x NLY strata */
#define NLY 16
#define NL (NLX * NLY)
#define NBX 16                   /* BRDF samples: NBX x NBX strata */
#define NB (NBX * NBX)
#define LRAD MF_R(8.0)           /* light radiance */
#define DIFF_MAX 0.1             /* |LTC - MC| at the top of the colour map */
#define KS MF_R(0.6)             /* specular color */
#define LHU MF_R(1.2)            /* light half edges: horizontal, the other */
#define LHV MF_R(0.5)
#define THRESH MF_R(0.02)        /* MC value below which pixels skip the statistics */

static const mf_real alphas[3] = { MF_R(0.1), MF_R(0.25), MF_R(0.5) };
/* the light's center, high at the left and a little behind the spheres, and
 * the point it faces: the camera sees its front face, in the frame */
static const mf_real light_c[3] = { MF_R(-2.5), MF_R(1.7), MF_R(-0.6) }, light_aim[3] = { MF_R(0.5), MF_R(0.2), MF_R(0.3) };
/* spheres: center x, y, z, radius (resting on the plane y = 0) */
static const mf_real sph[3][4] = { { MF_R(-1.3), MF_R(0.5), MF_R(0.2), MF_R(0.5) },
                                   { MF_R(0.15), MF_R(0.65), MF_R(-0.7), MF_R(0.65) },
                                   { MF_R(1.35), MF_R(0.4), MF_R(0.6), MF_R(0.4) } };
/* diffuse albedo per object: plane, then the spheres */
static const mf_real kd[4][3] = { { MF_R(0.3), MF_R(0.3), MF_R(0.3) }, { MF_R(0.45), MF_R(0.2), MF_R(0.15) },
                                  { MF_R(0.2), MF_R(0.35), MF_R(0.3) }, { MF_R(0.2), MF_R(0.25), MF_R(0.45) } };

/* the light: center lc, half edges lu (along x) and lv; ln = lu x lv is its
 * emitting side. lq holds its corners, counterclockwise seen from the front. */
static mf_vec3 lc, lu, lv, ln, lq[4];
static mf_real larea;


static mf_vec3 sub(mf_vec3 a, mf_vec3 b) { return mf_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }

static void setup_light(void)
{
    static const mf_real su[4] = { -1, 1, 1, -1 }, sv[4] = { -1, -1, 1, 1 };
    int i;
    lc = mf_vec3_make(light_c[0], light_c[1], light_c[2]);
    ln = mf_normalize(sub(mf_vec3_make(light_aim[0], light_aim[1], light_aim[2]), lc));
    lu = mf_scale(mf_normalize(mf_cross(mf_vec3_make(MF_R(0.0), MF_R(1.0), MF_R(0.0)), ln)), LHU);
    lv = mf_scale(mf_cross(ln, mf_normalize(lu)), LHV);               /* so that lu x lv ~ ln */
    for (i = 0; i < 4; ++i) lq[i] = mf_add(lc, mf_add(mf_scale(lu, su[i]), mf_scale(lv, sv[i])));
    larea = MF_R(4.0) * LHU * LHV;
}

/* Distance along the unit ray (o, d) to the light's front face, or -1. */
static mf_real hit_light(mf_vec3 o, mf_vec3 d)
{
    mf_real den = mf_dot(d, ln), t, u, v;
    mf_vec3 q;
    if (!(den < MF_R(0.0))) return MF_R(-1.0);
    t = mf_dot(sub(lc, o), ln) / den;
    if (!(t > MF_R(1e-4))) return MF_R(-1.0);
    q = sub(mf_add(o, mf_scale(d, t)), lc);
    u = mf_dot(q, lu) / mf_dot(lu, lu);
    v = mf_dot(q, lv) / mf_dot(lv, lv);
    return (MF_FABS(u) <= MF_R(1.0) && MF_FABS(v) <= MF_R(1.0)) ? t : MF_R(-1.0);
}

/* Nearest hit of the camera ray: -1 miss, 0 plane, 1..3 spheres, 4 light. */
static int trace(mf_vec3 o, mf_vec3 d, mf_vec3 *p, mf_vec3 *n)
{
    mf_real best = MF_R(1e30), t;
    int obj = -1, i;
    if (d.y < MF_R(0.0)) { best = -o.y / d.y; obj = 0; *n = mf_vec3_make(MF_R(0.0), MF_R(1.0), MF_R(0.0)); }
    for (i = 0; i < 3; ++i) {
        mf_vec3 oc = sub(o, mf_vec3_make(sph[i][0], sph[i][1], sph[i][2]));
        mf_real b = mf_dot(oc, d), c = mf_dot(oc, oc) - sph[i][3] * sph[i][3], disc = b * b - c;
        if (disc < MF_R(0.0)) continue;
        t = -b - MF_SQRT(disc);
        if (!(t > MF_R(1e-4) && t < best)) continue;
        best = t; obj = i + 1;
        *n = mf_scale(mf_add(oc, mf_scale(d, t)), MF_R(1.0) / sph[i][3]);
    }
    t = hit_light(o, d);
    if (t > MF_R(0.0) && t < best) { best = t; obj = 4; }
    *p = mf_add(o, mf_scale(d, best));
    return obj;
}

/* Shades point p (normal n, unit direction to the eye v) both ways; spec and
 * diff (the diffuse form factor, to be multiplied by the albedo) per method. */
static void shade(mf_real alpha, mf_vec3 p, mf_vec3 n, mf_vec3 v, rng *r,
                  mf_real *spec_ltc, mf_real *ff_ltc, mf_real *spec_mc, mf_real *ff_mc)
{
    mf_ndf d = mf_ggx(alpha, alpha);
    mf_vec3 t, b, wo, verts[4];
    mf_real sl = MF_R(0.0), dl = MF_R(0.0), sb = MF_R(0.0);
    mf_ltc ltc;
    int i;
    *spec_ltc = *ff_ltc = *spec_mc = *ff_mc = MF_R(0.0);
    /* local frame: x axis in the plane of n and v, so wo = (sin, 0, cos) */
    t = sub(v, mf_scale(n, mf_dot(v, n)));
    if (mf_dot(t, t) > MF_R(1e-12)) { t = mf_normalize(t); b = mf_cross(n, t); }
    else mf_frame(n, &t, &b);
    wo = mf_vec3_make(mf_dot(v, t), MF_R(0.0), mf_dot(v, n));
    if (!(wo.z > MF_R(0.0))) return;
    /* LTC: the light's corners relative to p, in the local frame */
    for (i = 0; i < 4; ++i) {
        mf_vec3 q = sub(lq[i], p);
        verts[i] = mf_vec3_make(mf_dot(q, t), mf_dot(q, b), mf_dot(q, n));
    }
    ltc = mf_ltc_ggx(wo.z, alpha);
    *spec_ltc = mf_ltc_ggx_albedo(wo.z, alpha) * mf_ltc_integrate(&ltc, verts, 4, 0);
    *ff_ltc = mf_polygon_irradiance(verts, 4, 0);
    /* MC, light sampling: uniform on the area, pdf per solid angle dist^2 / (A cos_l) */
    for (i = 0; i < NL; ++i) {
        mf_real su = MF_R(2.0) * ((mf_real)(i % NLX) + rng_u(r)) / (mf_real)NLX - MF_R(1.0);
        mf_real sv = MF_R(2.0) * ((mf_real)(i / NLX) + rng_u(r)) / (mf_real)NLY - MF_R(1.0);
        mf_vec3 q = sub(mf_add(lc, mf_add(mf_scale(lu, su), mf_scale(lv, sv))), p), wi;
        mf_real dist2 = mf_dot(q, q), cl, pl;
        q = mf_scale(q, MF_R(1.0) / MF_SQRT(dist2));
        cl = -mf_dot(q, ln);
        wi = mf_vec3_make(mf_dot(q, t), mf_dot(q, b), mf_dot(q, n));
        if (!(cl > MF_R(0.0)) || !(wi.z > MF_R(0.0))) continue;
        pl = dist2 / (larea * cl);
        dl += wi.z * MF_INV_PI / pl;
        /* balance heuristic over both techniques: f cos / (NL pl + NB pb) */
        sl += mf_brdf(&d, wo, wi) * wi.z / ((mf_real)NL * pl + (mf_real)NB * mf_brdf_pdf(&d, wo, wi));
    }
    /* MC, BRDF sampling through the visible normals; a sample counts if it hits the light */
    for (i = 0; i < NB; ++i) {
        mf_real u1 = ((mf_real)(i % NBX) + rng_u(r)) / (mf_real)NBX;
        mf_vec3 wi = mf_brdf_sample(&d, wo, u1, ((mf_real)(i / NBX) + rng_u(r)) / (mf_real)NBX), w;
        mf_real tl, pl, pb;
        if (!(wi.z > MF_R(0.0))) continue;
        w = mf_add(mf_add(mf_scale(t, wi.x), mf_scale(b, wi.y)), mf_scale(n, wi.z));
        tl = hit_light(p, w);
        if (!(tl > MF_R(0.0))) continue;
        pl = tl * tl / (larea * -mf_dot(w, ln));
        pb = mf_brdf_pdf(&d, wo, wi);
        sb += mf_brdf_sample_weight(&d, wo, wi) * pb / ((mf_real)NL * pl + (mf_real)NB * pb);
    }
    *spec_mc = sl + sb;
    *ff_mc = dl / (mf_real)NL;
}

int main(int argc, char **argv)
{
    const char *base = argc > 1 ? argv[1] : "area_light";
    const mf_real bg = MF_R(0.01), tan_half = MF_R(0.42);    /* about 46 deg vertical field of view */
    mf_vec3 eye = mf_vec3_make(MF_R(-0.3), MF_R(1.6), MF_R(6.0));   /* looking at (-0.3, 0.7, 0) */
    mf_vec3 fwd = mf_normalize(sub(mf_vec3_make(MF_R(-0.3), MF_R(0.7), MF_R(0.0)), eye));
    mf_vec3 right = mf_normalize(mf_cross(fwd, mf_vec3_make(MF_R(0.0), MF_R(1.0), MF_R(0.0))));
    mf_vec3 cup = mf_cross(right, fwd);
    ex_image im;
    float *img;
    double stat[3][3];   /* per row: the three figures printed */
    long bad = 0;
    int row, px, py, c, err;
    if (ex_image_init(&im, W, H)) return 1;
    img = im.lin;
    setup_light();

    for (row = 0; row < 3; ++row) {
        mf_real rel = 0, rel_s = 0, dif_s = 0, sum_s = 0;   /* statistics of this row */
        long cnt = 0, cnt_s = 0;
        for (py = 0; py < PH; ++py) {
            for (px = 0; px < PW; ++px) {
                /* one ray through the pixel center, the same in all three panels */
                mf_real sx = (MF_R(2.0) * ((mf_real)px + MF_R(0.5)) / PW - MF_R(1.0)) * tan_half * PW / PH;
                mf_real sy = (MF_R(1.0) - MF_R(2.0) * ((mf_real)py + MF_R(0.5)) / PH) * tan_half;
                mf_vec3 dir = mf_normalize(mf_add(fwd, mf_add(mf_scale(right, sx), mf_scale(cup, sy)))), p, n;
                mf_real lt[3], mc[3], sl = 0, fl = 0, sm = 0, fm = 0, ml, mm;
                int obj = trace(eye, dir, &p, &n);
                float *out = img + 3 * ((row * PH + py) * W + px);
                rng r;
                rng_seed(&r, (uint64_t)((row * PH + py) * W + px));
                if (obj >= 0 && obj < 4) shade(alphas[row], p, n, mf_scale(dir, MF_R(-1.0)), &r, &sl, &fl, &sm, &fm);
                for (c = 0; c < 3; ++c) {
                    lt[c] = obj < 0 ? bg : obj == 4 ? LRAD : LRAD * (KS * sl + kd[obj][c] * fl);
                    mc[c] = obj < 0 ? bg : obj == 4 ? LRAD : LRAD * (KS * sm + kd[obj][c] * fm);
                    if (!(MF_FABS(lt[c]) < MF_BIG) || !(MF_FABS(mc[c]) < MF_BIG)) { ++bad; lt[c] = mc[c] = 0; }
                    out[c] = (float)lt[c];
                    out[c + PW * 3] = (float)mc[c];
                    out[c + PW * 6] = (float)MF_FABS(lt[c] - mc[c]);
                }
                if (obj < 0 || obj == 4) continue;
                /* statistics on the channel mean, and on the specular part alone */
                ml = (lt[0] + lt[1] + lt[2]) / MF_R(3.0);
                mm = (mc[0] + mc[1] + mc[2]) / MF_R(3.0);
                if (mm > THRESH) { rel += MF_FABS(ml - mm) / mm; ++cnt; }
                if (LRAD * KS * sm > THRESH) { rel_s += MF_FABS(sl - sm) / sm; ++cnt_s; }
                dif_s += MF_FABS(sl - sm); sum_s += sm;
            }
        }
        stat[row][0] = (double)(rel / (mf_real)(cnt > 0 ? cnt : 1));
        stat[row][1] = (double)(rel_s / (mf_real)(cnt_s > 0 ? cnt_s : 1));
        stat[row][2] = (double)(dif_s / mf_max(sum_s, MF_EPS));
        printf("alpha %.2f: mean |LTC - MC| / MC = %.4f (%ld px); specular only %.4f (%ld px), "
               "energy-weighted %.4f\n", (double)alphas[row], stat[row][0], cnt, stat[row][1], cnt_s, stat[row][2]);
    }

    ex_tonemap(&im, 0, 0, 2 * PW, H, 1.0);
    ex_colormap(&im, 2 * PW, 0, PW, H, DIFF_MAX);
    ex_text(&im, 8, 8, 2, "LTC");
    ex_text(&im, PW + 8, 8, 2, "Monte Carlo, MIS");
    ex_text(&im, PW + 8, 30, 1, "256 light + 256 BRDF samples");
    ex_text(&im, 2 * PW + 8, 8, 2, "|LTC - MC|");
    for (row = 0; row < 3; ++row) {
        int y = row * PH;
        ex_label(&im, 8, y + PH - 22, 2, "GGX alpha %g", (double)alphas[row]);
        ex_label(&im, 2 * PW + 8, y + (row ? 8 : 30), 1, "mean |LTC - MC| / MC: %.3f", stat[row][0]);
        ex_label(&im, 2 * PW + 8, y + (row ? 20 : 42), 1, "specular only: %.3f", stat[row][1]);
        ex_label(&im, 2 * PW + 8, y + (row ? 32 : 54), 1, "specular, energy-weighted: %.3f", stat[row][2]);
    }
    ex_colorbar(&im, 2 * PW + 8, H - 30, PW - 16, 10, DIFF_MAX, "|LTC - MC|, radiance");
    err = ex_write(&im, base);
    ex_image_free(&im);

    printf("rows: GGX alpha 0.1, 0.25, 0.5; columns: LTC, Monte Carlo, |LTC - MC|\n");
    printf("non-finite values: %ld\n", bad);
    return bad != 0 || err;
}
