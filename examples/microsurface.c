/* Demonstrates microsurface generation from a distribution (Ribardiere et al.
 * 2019, Algorithm 1: mf_microsurface_generate_ex) and the virtual
 * gonioreflectometer (mf_gonio_measure): for each distribution in the list
 * below, a periodic 256 x 256 height field is generated (200 iterations), lit
 * by a collimated beam at theta_i = 1 rad with mirror facets, and the light
 * leaving after the first bounce is compared with the single-scattering Smith
 * model (mf_brdf cos with the height-correlated G2, integrated over each
 * sensor cell by mf_gonio_model). One row per distribution, four panels
 * over a strip that holds their scales:
 *   1. the height field (gray, mean -+ 2.5 standard deviations; its bar in
 *      standard deviations below);
 *   2. the measured first-bounce lobe, f cos per steradian over the sensor's
 *      equal-solid-angle cells, seen from above (orthographic projection of
 *      the hemisphere, dotted rings at theta_o = 30 and 60 degrees; the
 *      light comes from the right, the lobe lies left);
 *   3. the model over the same cells, same colour scale (one colour bar
 *      under panels 2 and 3, ticks with three significant digits);
 *   4. the in-plane slice (phi = 0 and pi) from theta_o = -90 to +90 degrees,
 *      axes with tick labels: measured cells (red), model cells (green), the
 *      exact model mf_brdf cos (white); the light arrives at the right
 *      edge's side.
 * The list is one line per distribution (add an mf_ndf there to see it); the
 * last one is a two-lobe tabulated distribution (mf_tabulated_build).
 * Prints, per distribution, the Schwarz statistics, the first-bounce energy
 * (measured and model), the energy of the longer paths and the relative L1
 * distance of the lobes. Writes base.png (panels and rows labelled, scales
 * under each row), base.pfm (the same display values, linear) and, built
 * with OpenEXR, base.exr.
 *
 *   cc -O2 -I. examples/microsurface.c -o microsurface -lm   (from the repo root)
 *   ./microsurface [base]                                    (default: microsurface)
 */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "example_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIZE 256          /* height field */
#define P 256             /* panel size in pixels */
#define GAP 4
#define STRIP 40          /* under each row: colour bars and axis titles */
#define RH (P + STRIP)    /* row height */
#define PANELS 4
#define W (PANELS * P + (PANELS - 1) * GAP)
/* the slice plot's axes inside panel 4 (offsets from its top left) */
#define PL 34             /* left: room for the y tick labels */
#define PR (P - 8)
#define PT 44             /* top: below the legend */
#define PB (P - 18)       /* bottom: room for the x tick labels */
#define RINGS 16
#define RAYS 600000
#define THETA_I 1.0

typedef struct { const char *name; mf_ndf d; } entry;

static void put(float *img, int x, int y, float r, float g, float b)
{
    if (x < 0 || y < 0 || x >= W) return;
    img[3 * (y * W + x)] = r; img[3 * (y * W + x) + 1] = g; img[3 * (y * W + x) + 2] = b;
}

/* false colour for t in [0, 1]: the examples' colour map */
static void ramp(float t, float *c)
{
    unsigned char b[3];
    ex_colormap_rgb((double)t, b);
    c[0] = b[0] / 255.0f; c[1] = b[1] / 255.0f; c[2] = b[2] / 255.0f;
}

/* gray for t in [0, 1]: the height panel's map */
static void gray(double t, unsigned char out[3])
{
    t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
    out[0] = out[1] = out[2] = (unsigned char)(255.0 * t + 0.5);
}

/* a polar map of per-cell values (divided by the cell solid angle), with
 * dotted rings at theta_o = 30 and 60 degrees (radius sin theta_o) */
static void polar(float *img, int x0, int y0, const mf_gonio *g, const mf_real *v, double vmax)
{
    int x, y;
    double om = (double)mf_gonio_cell_solid_angle(g);
    for (y = 0; y < P; ++y)
        for (x = 0; x < P; ++x) {
            double u = (2.0 * x + 1.0) / P - 1.0, w = 1.0 - (2.0 * y + 1.0) / P, r2 = u * u + w * w, r = sqrt(r2);
            float c[3] = { 0.08f, 0.08f, 0.08f };
            if (r2 < 1.0) {
                int cell = mf_gonio_cell(g, mf_vec3_make((mf_real)u, (mf_real)w, (mf_real)sqrt(1.0 - r2)));
                if (cell >= 0) ramp((float)((double)v[cell] / om / vmax), c);
                if ((fabs(r - 0.5) < 1.0 / P || fabs(r - 0.8660254037844386) < 1.0 / P) && (x + y) % 6 < 3)
                    c[0] = c[1] = c[2] = 0.55f;
            }
            put(img, x0 + x, y0 + y, c[0], c[1], c[2]);
        }
}

/* a line of the plot, clipped to the panel */
static void hline(float *img, int x0, int x1, int y, float v)
{
    int x;
    for (x = x0; x <= x1; ++x) put(img, x, y, v, v, v);
}
static void vline(float *img, int x, int y0, int y1, float v)
{
    int y;
    for (y = y0; y <= y1; ++y) put(img, x, y, v, v, v);
}

int main(int argc, char **argv)
{
    const char *base = argc > 1 ? argv[1] : "microsurface";
    entry list[8];   /* room for two more */
    double row_vmax[8], row_ymax[8], row_ystep[8];
    int n = 0, e, H, status = 0;
    ex_image im;
    float *img;
    mf_real *h = (mf_real *)malloc(sizeof(mf_real) * SIZE * SIZE), *model;
    mf_gonio g;
    mf_gonio_config cfg;
    mf_tabulated tab;
    mf_vec3 wi = mf_vec3_make((mf_real)sin(THETA_I), MF_R(0.0), (mf_real)cos(THETA_I));
    /* the distributions, one line each */
    list[n].name = "Beckmann 0.4"; list[n++].d = mf_beckmann(MF_R(0.4), MF_R(0.4));
    list[n].name = "GGX 0.3"; list[n++].d = mf_ggx(MF_R(0.3), MF_R(0.3));
    list[n].name = "Student-t 0.3, gamma 3"; list[n++].d = mf_student_t(MF_R(0.3), MF_R(0.3), MF_R(3.0));
    list[n].name = "GTR 0.4, gamma 2.5"; list[n++].d = mf_gtr(MF_R(0.4), MF_R(2.5));
    list[n].name = "Beckmann 0.4 sheared [1 0.5; 0 0.6]";
    list[n++].d = mf_transformed(mf_beckmann(MF_R(0.4), MF_R(0.4)), mf_mat2_make(MF_R(1.0), MF_R(0.5), MF_R(0.0), MF_R(0.6)));
    {   /* a two-lobe tabulated distribution (Ribardiere et al. 2019, Sec. 3): a
         * central lobe and a ring of facets tilted by about 0.6 rad */
        mf_real th[46], dv[46];
        int i;
        for (i = 0; i < 46; ++i) {
            double a = 1.5707963267948966 * i / 45.0;
            th[i] = (mf_real)a;
            dv[i] = (mf_real)(exp(-(a / 0.25) * (a / 0.25)) + 0.5 * exp(-((a - 0.6) / 0.1) * ((a - 0.6) / 0.1)));
        }
        if (mf_tabulated_build(&tab, th, dv, NULL, 46) == MF_SUCCESS) {
            list[n].name = "tabulated, two lobes (0 and 0.6 rad)"; list[n++].d = mf_tabulated_ndf(&tab);
        }
    }

    H = n * RH + (n - 1) * GAP;
    if (!h || ex_image_init(&im, W, H) || mf_gonio_init(&g, RINGS) != MF_SUCCESS) { fprintf(stderr, "out of memory\n"); return 1; }
    img = im.lin;
    model = (mf_real *)malloc(sizeof(mf_real) * (size_t)g.cells);
    memset(&cfg, 0, sizeof cfg);   /* all-zero: the defaults (mirror facets, no absorption) */
    cfg.wi = wi; cfg.rays = RAYS; cfg.seed = 1;
    for (e = 0; e < n; ++e) {
        mf_microsurface_stats st;
        const mf_ndf *d = &list[e].d;
        int y0 = e * (RH + GAP), x, y, c;
        double lo = 1e30, hi = -1e30, vmax = 0.0, l1 = 0.0, sm = 0.0, om = (double)mf_gonio_cell_solid_angle(&g);
        row_vmax[e] = row_ymax[e] = 1.0; row_ystep[e] = 0.5;   /* scales of a row that failed */
        /* 200 re-matching iterations; NULL options: the defaults */
        if (mf_microsurface_generate_ex(d, SIZE, 200, (mf_u64)(e + 1), NULL, h, &st) != MF_SUCCESS ||
            mf_gonio_measure(&g, h, SIZE, &cfg) != MF_SUCCESS || mf_gonio_model(&g, d, wi, 8, model) != MF_SUCCESS) {
            fprintf(stderr, "%s: failed\n", list[e].name);
            status = 1;
            continue;
        }
        for (c = 0; c < g.cells; ++c) {
            l1 += fabs((double)g.first[c] - (double)model[c]);
            sm += (double)model[c];
            if ((double)model[c] / om > vmax) vmax = (double)model[c] / om;
        }
        row_vmax[e] = vmax;
        printf("%-38s below %.2f  first bounce %.4f (model %.4f)  longer paths %.4f  lobe L1 %.3f  lost %d\n",
               list[e].name, (double)st.below, (double)g.energy_first, sm, (double)g.energy_multi, l1 / sm, g.lost);
        /* 1. heights */
        {   /* gray scale over mean -+ 2.5 standard deviations (heavy tails leave a few spikes) */
            double s1 = 0.0, s2 = 0.0, sd;
            for (c = 0; c < SIZE * SIZE; ++c) { s1 += (double)h[c]; s2 += (double)h[c] * (double)h[c]; }
            s1 /= SIZE * SIZE;
            sd = sqrt(s2 / (SIZE * SIZE) - s1 * s1);
            lo = s1 - 2.5 * sd; hi = s1 + 2.5 * sd;
        }
        for (y = 0; y < P; ++y)
            for (x = 0; x < P; ++x) {
                float v = (float)(((double)h[(y * SIZE / P) * SIZE + x * SIZE / P] - lo) / (hi - lo + 1e-30));
                v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
                put(img, x, y0 + y, v, v, v);
            }
        /* 2, 3. measured and model lobes */
        polar(img, P + GAP, y0, &g, g.first, vmax);
        polar(img, 2 * (P + GAP), y0, &g, model, vmax);
        /* 4. in-plane slice: theta_o from -90 (phi = pi) to 90 degrees
         * (phi = 0) across [PL, PR], f cos per sr from 0 at PB up to ymax at
         * PT, a nice round value above the lobe's largest cell */
        {
            int x0 = 3 * (P + GAP), pw = PR - PL;
            double ystep = ex_nice_step(1.1 * vmax, 4), ymax = ceil(1.1 * vmax / ystep) * ystep, t;
            row_ymax[e] = ymax; row_ystep[e] = ystep;
            for (y = 0; y < P; ++y)
                for (x = 0; x < P; ++x) put(img, x0 + x, y0 + y, 0.08f, 0.08f, 0.08f);
            for (t = 0.0; t <= ymax * (1.0 + 1e-9); t += ystep) {   /* grid and y ticks */
                int yy = PB - (int)floor(t / ymax * (PB - PT) + 0.5);
                hline(img, x0 + PL, x0 + PR, y0 + yy, t == 0.0 ? 0.6f : 0.2f);
                hline(img, x0 + PL - 3, x0 + PL - 1, y0 + yy, 0.6f);
            }
            for (c = -90; c <= 90; c += 30) {                          /* x ticks */
                int xx = PL + (int)floor((c + 90) / 180.0 * pw + 0.5);
                vline(img, x0 + xx, y0 + PT, y0 + PB, c == 0 ? 0.35f : 0.2f);
                vline(img, x0 + xx, y0 + PB + 1, y0 + PB + 3, 0.6f);
            }
            vline(img, x0 + PL, y0 + PT, y0 + PB, 0.6f);
            for (x = 0; x <= pw; ++x) {
                double th = ((double)x / pw - 0.5) * 3.14159265358979323846;
                mf_vec3 wo = mf_vec3_make((mf_real)sin(th), MF_R(0.0), (mf_real)cos(th));
                int cell = mf_gonio_cell(&g, wo);
                double vm = cell >= 0 ? (double)g.first[cell] / om : 0.0, vd = cell >= 0 ? (double)model[cell] / om : 0.0;
                double ve = (double)(mf_brdf(d, wo, wi) * wo.z);
                int ym = PB - (int)floor(vm / ymax * (PB - PT) + 0.5), yd = PB - (int)floor(vd / ymax * (PB - PT) + 0.5);
                int ye = PB - (int)floor(ve / ymax * (PB - PT) + 0.5);
                if (ye >= PT) put(img, x0 + PL + x, y0 + ye, 1.0f, 1.0f, 1.0f);
                if (yd >= PT) { put(img, x0 + PL + x, y0 + yd, 0.1f, 0.9f, 0.1f); if (yd + 1 <= PB) put(img, x0 + PL + x, y0 + yd + 1, 0.1f, 0.9f, 0.1f); }
                if (ym >= PT) { put(img, x0 + PL + x, y0 + ym, 1.0f, 0.15f, 0.1f); if (ym + 1 <= PB) put(img, x0 + PL + x, y0 + ym + 1, 1.0f, 0.15f, 0.1f); }
            }
        }
        /* the strip under the row: background */
        for (y = P; y < RH; ++y)
            for (x = 0; x < W; ++x) put(img, x, y0 + y, 0.0f, 0.0f, 0.0f);
    }
    ex_direct(&im, 0, 0, W, H);
    for (e = 0; e < n; ++e) {
        int y0 = e * (RH + GAP), x0 = 3 * (P + GAP), c, pw = PR - PL;
        double t;
        char buf[32];
        ex_text(&im, 6, y0 + 6, 1, list[e].name);
        ex_text(&im, P + GAP + 6, y0 + 6, 1, "measured, first bounce");
        ex_text(&im, 2 * (P + GAP) + 6, y0 + 6, 1, "Smith model");
        for (c = 1; c <= 2; ++c) {   /* the rings of panels 2 and 3, on the light's side */
            ex_text(&im, c * (P + GAP) + P / 2 + P / 4 + 3, y0 + P / 2 + 3, 1, "30");
            ex_text(&im, c * (P + GAP) + P / 2 + (int)(0.866 * P / 2) + 3, y0 + P / 2 + 3, 1, "60");
        }
        ex_text(&im, x0 + 6, y0 + 6, 1, "slice phi = 0, pi");
        ex_text(&im, x0 + 6, y0 + 18, 1, "red measured, green model");
        ex_text(&im, x0 + 6, y0 + 30, 1, "white exact f cos");
        for (t = 0.0; t <= row_ymax[e] * (1.0 + 1e-9); t += row_ystep[e]) {   /* y tick labels */
            int yy = PB - (int)floor(t / row_ymax[e] * (PB - PT) + 0.5);
            ex_tick_text(buf, sizeof buf, t, row_ymax[e], 0);
            ex_text(&im, x0 + PL - 5 - ex_text_width(buf, 1), y0 + yy - 3, 1, buf);
        }
        for (c = -90; c <= 90; c += 30) {                                    /* x tick labels */
            int xx = PL + (int)floor((c + 90) / 180.0 * pw + 0.5);
            snprintf(buf, sizeof buf, "%d", c);
            ex_text(&im, x0 + xx - ex_text_width(buf, 1) / 2, y0 + PB + 6, 1, buf);
        }
        /* the strip: scales and axis titles */
        ex_colorbar_map(&im, 8, y0 + P + 16, P - 16, 6, -2.5, 2.5, gray, "height - mean, in standard deviations");
        ex_colorbar(&im, P + GAP + 8, y0 + P + 16, 2 * P + GAP - 16, 6, row_vmax[e],
                    "f cos per sr, panels 2 and 3; rings: theta_o = 30, 60 deg");
        ex_text(&im, x0 + 6, y0 + P + 6, 1, "x: theta_o in deg (phi = pi left)");
        ex_text(&im, x0 + 6, y0 + P + 18, 1, "y: f cos per sr");
        ex_label(&im, x0 + 6, y0 + P + 30, 1, "light at theta_i = %g rad", THETA_I);
    }
    if (ex_write(&im, base)) status = 1;
    mf_gonio_release(&g);
    mf_tabulated_release(&tab);
    free(model); ex_image_free(&im); free(h);
    return status;
}
