/* Inverse Bin Map (Atanasov et al. 2021, thesis ch. 5).
 *
 * Every query is compared with a computation written here from the
 * definitions, in double:
 *   - bin weights (Eq. 5.3, 5.8): the footprint parallelogram clipped against
 *     every texel of every period it reaches, summed per bin; random tiny,
 *     medium, huge (several periods), rotated, thin, wrapping, axis-aligned and
 *     boundary-aligned footprints on a non-power-of-two smooth map and a flake
 *     map, through the direct sum, the kd traversal, the texel lists of
 *     bins of few texels (one bin, and 21-bin sets of 49-1008 texels on a
 *     256^2 map), the neighbourhood query and the single-bin query. Tolerance 1e-9 absolute in double (exact
 *     clipping up to round-off on coordinates below 1e3 texels: seen 5e-12),
 *     2e-5 in float (round-off of texel coordinates < 64 at 6e-8 relative over
 *     a few hundred cut texels: seen 9e-7); all bins' weights sum to 1 (same);
 *     whole periods and the beyond-the-cap fallback give the map's histogram
 *     (1e-12 / 1e-6); 1x1 to 5x1 maps;
 *   - the texel contribution (Eq. 3.29): a map of one constant normal t gives
 *     the Beckmann BRDF of the lobe tilted to t inside the 21-bin neighbourhood
 *     (recomputed here from the thesis' binning) and 0 outside, the lobe
 *     evaluated independently with mf_brdf in t's frame times
 *     (wo.t)(wi.t)/(wo.z wi.z) and mf_G2 of the map's shadowing; 1e-9
 *     relative in double, 1e-3 in float (float round-off of the exponent
 *     tan^2/alpha^2 ~ 30 at the lobe's edge); a flat map is the plain Beckmann
 *     BRDF (1e-10 / 1e-4); reciprocity (1e-12 / 1e-5);
 *   - convergence of the binned BRDF (Eq. 5.13) to the texel sum with the
 *     true normals (Eq. 5.2) as the bins get finer (resolution x1, x2, x3 with
 *     a 5-sigma cut, so truncation is negligible): the L1 error over 160 glint
 *     directions must halve and end below 3% (seen 8.0%, 4.1%, 1.8%);
 *   - sampling: chi-square of the sampled half vectors against mf_ibm_pdf
 *     integrated over cells aligned with the bins (4 x 4 Gauss-Legendre per
 *     cell; fail at z >= 5) for six footprint kinds; every sample has pdf > 0;
 *     mf_ibm_brdf_pdf equals mf_ibm_brdf and mf_ibm_pdf (1e-12); the pdf's
 *     integral equals the fraction of samples returned (4 standard errors +
 *     2e-3 for the quadrature), and is 1 within 2e-3 with a 5-sigma cut and
 *     no horizon loss;
 *   - the truncation to the 21 bins, measured: albedo against the same
 *     binned BRDF over all bins (quadrature as above); must be in (0, 5%),
 *     seen 0.9-1.3%;
 *   - save / load round trip (bit-identical, equal queries); corrupted
 *     buffers rejected: bit flips, header words, truncation, and a broken
 *     index, position, bin map entry or kd-tree boundary under a recomputed
 *     checksum;
 *   - bad input to the builder (NULL, sizes, alpha, resolution, cut, NaN,
 *     non-unit and below-horizon normals: error, nothing allocated) and
 *     degenerate queries (NaN, huge, zero-area, below the horizon, NULL:
 *     finite, 0, no sample).
 * Maps are 8^2 to 64^2, the module takes about 2 s (double, -O2). */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

#define PI_D 3.14159265358979323846

/* ---- maps ---- */

/* periodic smooth height field of a few waves: normals from its analytic gradient */
static mf_real *map_smooth(int w, int h, double amp, unsigned long long seed)
{
    mf_real *n = (mf_real *)malloc(sizeof(mf_real) * 3 * (size_t)w * (size_t)h);
    double kx[6], ky[6], ph[6], a[6];
    int i, x, y;
    mft_rng r;
    mft_seed(&r, seed);
    for (i = 0; i < 6; ++i) {
        kx[i] = (double)(int)(mft_u01(&r) * 5) - 2.0;
        ky[i] = (double)(int)(mft_u01(&r) * 5) - 2.0;
        if (kx[i] == 0 && ky[i] == 0) kx[i] = 1;
        ph[i] = 2 * PI_D * mft_u01(&r);
        a[i] = amp * (0.5 + mft_u01(&r)) / 6.0;
    }
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            double gx = 0, gy = 0, l;
            for (i = 0; i < 6; ++i) {
                double c = cos(2 * PI_D * (kx[i] * (x + 0.5) / w + ky[i] * (y + 0.5) / h) + ph[i]);
                gx += a[i] * kx[i] * c;
                gy += a[i] * ky[i] * c;
            }
            l = sqrt(gx * gx + gy * gy + 1);
            n[3 * (y * w + x)] = (mf_real)(-gx / l);
            n[3 * (y * w + x) + 1] = (mf_real)(-gy / l);
            n[3 * (y * w + x) + 2] = (mf_real)(1 / l);
        }
    return n;
}

/* square flakes of `cell` texels with normals from GTR (car paint, Sec. 5.5.4) */
static mf_real *map_flakes(int w, int h, int cell, double alpha, unsigned long long seed)
{
    mf_real *n = (mf_real *)malloc(sizeof(mf_real) * 3 * (size_t)w * (size_t)h);
    mf_ndf g = mf_gtr((mf_real)alpha, MF_R(1.5));
    int x, y, cw = (w + cell - 1) / cell, ch = (h + cell - 1) / cell, c;
    mf_vec3 *fl = (mf_vec3 *)malloc(sizeof(mf_vec3) * (size_t)(cw * ch));
    mft_rng r;
    mft_seed(&r, seed);
    for (c = 0; c < cw * ch; ++c) {
        mf_vec3 m = mf_sample_D(&g, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
        if (m.z < MF_R(0.2)) m = mf_normalize(mf_vec3_make(m.x, m.y, MF_R(0.2)));
        fl[c] = m;
    }
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            mf_vec3 m = fl[(y / cell) * cw + x / cell];
            n[3 * (y * w + x)] = m.x; n[3 * (y * w + x) + 1] = m.y; n[3 * (y * w + x) + 2] = m.z;
        }
    free(fl);
    return n;
}

static mf_real *map_const(int w, int h, mf_vec3 t)
{
    mf_real *n = (mf_real *)malloc(sizeof(mf_real) * 3 * (size_t)w * (size_t)h);
    int i;
    for (i = 0; i < w * h; ++i) { n[3 * i] = t.x; n[3 * i + 1] = t.y; n[3 * i + 2] = t.z; }
    return n;
}

/* ---- brute force ---- */

/* |P ∩ [x0, x0+1] x [y0, y0+1]| for a convex counterclockwise polygon P */
static double clip_area(const double *px, const double *py, int n, double x0, double y0)
{
    double xa[16], ya[16], xb[16], yb[16], s = 0;
    int i, k, e, m = n;
    for (i = 0; i < n; ++i) { xa[i] = px[i]; ya[i] = py[i]; }
    for (e = 0; e < 4 && m > 0; ++e) {
        int o = 0;
        for (i = 0; i < m; ++i) {
            int j = (i + 1) % m;
            double di, dj;
            switch (e) {
            case 0: di = xa[i] - x0; dj = xa[j] - x0; break;
            case 1: di = x0 + 1 - xa[i]; dj = x0 + 1 - xa[j]; break;
            case 2: di = ya[i] - y0; dj = ya[j] - y0; break;
            default: di = y0 + 1 - ya[i]; dj = y0 + 1 - ya[j]; break;
            }
            if (di >= 0) { xb[o] = xa[i]; yb[o] = ya[i]; ++o; }
            if ((di >= 0) != (dj >= 0)) {
                double t = di / (di - dj);
                xb[o] = xa[i] + t * (xa[j] - xa[i]);
                yb[o] = ya[i] + t * (ya[j] - ya[i]);
                ++o;
            }
        }
        m = o;
        for (k = 0; k < m; ++k) { xa[k] = xb[k]; ya[k] = yb[k]; }
    }
    for (i = 0; i < m; ++i) s += xa[i] * ya[(i + 1) % m] - xa[(i + 1) % m] * ya[i];
    return 0.5 * fabs(s);
}

/* footprint corners in texels, counterclockwise, and its area */
static double fp_poly(const mf_footprint *f, int w, int h, double *px, double *py)
{
    double cx = f->u * w, cy = f->v * h, ax = f->ax * w, ay = f->ay * h, bx = f->bx * w, by = f->by * h;
    double cr = ax * by - ay * bx, s = cr > 0 ? 0.5 : -0.5;
    px[0] = cx - 0.5 * ax - s * bx; py[0] = cy - 0.5 * ay - s * by;
    px[1] = cx + 0.5 * ax - s * bx; py[1] = cy + 0.5 * ay - s * by;
    px[2] = cx + 0.5 * ax + s * bx; py[2] = cy + 0.5 * ay + s * by;
    px[3] = cx - 0.5 * ax + s * bx; py[3] = cy - 0.5 * ay + s * by;
    return fabs(cr);
}

/* texel weights w_k (Eq. 5.3) of the tiled map; returns 0 for degenerate */
static int brute_texel_weights(const mf_footprint *f, int w, int h, double *wk)
{
    double px[4], py[4], area = fp_poly(f, w, h, px, py), x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    int i, sx, sy, x, y;
    for (i = 0; i < w * h; ++i) wk[i] = 0;
    if (!(area > 1e-6)) return 0;
    for (i = 0; i < 4; ++i) { x0 = fmin(x0, px[i]); x1 = fmax(x1, px[i]); y0 = fmin(y0, py[i]); y1 = fmax(y1, py[i]); }
    for (sy = (int)floor(y0 / h); sy <= (int)floor(y1 / h); ++sy)
        for (sx = (int)floor(x0 / w); sx <= (int)floor(x1 / w); ++sx)
            for (y = 0; y < h; ++y) {
                double ty = y + (double)sy * h;
                if (ty + 1 < y0 || ty > y1) continue;
                for (x = 0; x < w; ++x) {
                    double tx = x + (double)sx * w;
                    if (tx + 1 < x0 || tx > x1) continue;
                    wk[y * w + x] += clip_area(px, py, 4, tx, ty) / area;
                }
            }
    return 1;
}

/* the bins' weights from texel weights wk: wb[j] = sum of wk over bin j's texels */
static void brute_bin_sums(const mf_ibm *ibm, const double *wk, double *wb)
{
    int i, n = ibm->width * ibm->height;
    for (i = 0; i < mf_ibm_bin_count(ibm); ++i) wb[i] = 0;
    for (i = 0; i < n; ++i) wb[mf_ibm_texel_bin(ibm, i % ibm->width, i / ibm->width)] += wk[i];
}

/* C(wo, wi, t) (Eq. 3.29) independently: the Beckmann BRDF in t's frame */
static double texel_C(double alpha, const mf_ndf *shadow, mf_vec3 wo, mf_vec3 wi, mf_vec3 t)
{
    mf_vec3 tt, tb, o, i;
    mf_ndf d = mf_beckmann((mf_real)alpha, (mf_real)alpha);
    double g = 1;
    if (!(wo.z > 0) || !(wi.z > 0)) return 0;
    { mf_basis fr_ = mf_basis_from_normal(t); tt = fr_.t; tb = fr_.b; }
    o = mf_vec3_make(mf_dot(wo, tt), mf_dot(wo, tb), mf_dot(wo, t));
    i = mf_vec3_make(mf_dot(wi, tt), mf_dot(wi, tb), mf_dot(wi, t));
    if (!(o.z > 0) || !(i.z > 0)) return 0;
    if (shadow) g = (double)mf_G2(shadow, wo, wi, t);
    return (double)mf_brdf(&d, o, i) * (double)o.z * (double)i.z / ((double)wo.z * (double)wi.z) * g;
}

static mf_footprint fp_make(double u, double v, double ax, double ay, double bx, double by)
{
    mf_footprint f;
    f.u = (mf_real)u; f.v = (mf_real)v; f.ax = (mf_real)ax; f.ay = (mf_real)ay; f.bx = (mf_real)bx; f.by = (mf_real)by;
    return f;
}

/* a parallelogram at (u, v): edge a of length s at angle ang, edge b
 * across it, asp times as long, skewed by sk */
static mf_footprint fp_rotated(double u, double v, double s, double ang, double asp, double sk)
{
    return fp_make(u, v, s * cos(ang), s * sin(ang), -s * asp * (sin(ang) + sk * cos(ang)), s * asp * (cos(ang) - sk * sin(ang)));
}

/* random footprint of a kind: 0 tiny, 1 medium, 2 large, 3 huge (periods),
 * 4 thin, 5 axis-aligned, 6 wrapping corner; sizes in texture units */
static mf_footprint fp_random(mft_rng *r, int kind, int w)
{
    double ang = 2 * PI_D * mft_u01(r), s, asp = 1.0, u = mft_u01(r), v = mft_u01(r), sk = 0.6 * mft_u01(r) - 0.3;
    double tex = 1.0 / w;
    switch (kind) {
    case 0: s = tex * (0.1 + 2 * mft_u01(r)); break;
    case 1: s = tex * (3 + 8 * mft_u01(r)); break;
    case 2: s = 0.3 + 0.6 * mft_u01(r); break;
    case 3: s = 2.0 + 3.0 * mft_u01(r); u = 100 * mft_u01(r) - 50; break;
    case 4: s = 0.5 + 0.5 * mft_u01(r); asp = 0.01 + 0.02 * mft_u01(r); break;
    case 5: s = tex * (2 + 30 * mft_u01(r)); ang = 0; sk = 0; asp = 0.3 + mft_u01(r); break;
    default: s = tex * (4 + 20 * mft_u01(r)); u = 1.0 - tex; v = -0.5 * tex; break;
    }
    return fp_rotated(u, v, s, ang, asp, sk);
}

/* the truncation of Eq. 5.13 (Sec. 5.4.2): the bin of t is among the bins
 * (dx, dy), dx^2 + dy^2 <= r (r + 1), around the bin of h (r = 2: the 5 x 5
 * square without its corners) */
static int in_neighbourhood(int b, int r, mf_vec3 t, mf_vec3 h)
{
    int dx = (int)floor(b * (0.5 * t.x + 0.5)) - (int)floor(b * (0.5 * h.x + 0.5));
    int dy = (int)floor(b * (0.5 * t.y + 0.5)) - (int)floor(b * (0.5 * h.y + 0.5));
    return dx * dx + dy * dy <= r * (r + 1);
}

/* footprints whose corners or edges lie exactly on texel and period edges */
#define NFIXED 8
static mf_footprint fixed_fp(int i, int w, int h)
{
    double tx = 1.0 / w, ty = 1.0 / h;
    switch (i) {
    case 0: return fp_make(0.25, 0.5, 1.5, 0.0, 0.0, 0.5);                 /* ends on the period edge */
    case 1: return fp_make(0.5 * tx, 0.5 * ty, tx, 0.0, 0.0, ty);          /* exactly texel (0, 0) */
    case 2: return fp_make(0.0, 0.0, 4 * tx, 0.0, 0.0, 6 * ty);            /* texel-aligned, wraps */
    case 3: return fp_make(0.5, 0.5, 0.3, 0.3, -0.3, 0.3);                 /* corners on texel corners */
    case 4: return fp_make(0.3, 0.6, 0.4, 0.1, -0.2, 0.3);                 /* a corner on x = 0 */
    case 5: return fp_make(0.5, 0.25, 1.0, 0.0, 0.0, 0.5);                 /* one period wide */
    case 6: return fp_make(0.1, 0.9, 2.0, 1.0, -1.0, 2.0);                 /* corners on period corners */
    default: return fp_make(0.5, 0.5, 0.5, 0.0, 0.0, 1e-3 * ty);          /* a thin strip */
    }
}

/* ---- tests ---- */

static void test_build_errors(void)
{
    mf_ibm ibm;
    mf_real *n = map_smooth(16, 16, 0.5, 1);
    mf_real good[3] = { 0, 0, 1 };
    int bad = 0, i;
    (void)good;
    MFT_CHECK(mf_ibm_build(NULL, n, 16, 16, MF_R(0.1)) == MF_ERROR_INVALID_ARGUMENT, "build: NULL map");
    MFT_CHECK(mf_ibm_build(&ibm, NULL, 16, 16, MF_R(0.1)) == MF_ERROR_INVALID_ARGUMENT && !ibm.data, "build: NULL normals");
    MFT_CHECK(mf_ibm_build(&ibm, n, 0, 16, MF_R(0.1)) == MF_ERROR_INVALID_ARGUMENT && !ibm.data, "build: zero width");
    MFT_CHECK(mf_ibm_build(&ibm, n, 16, -3, MF_R(0.1)) == MF_ERROR_INVALID_ARGUMENT && !ibm.data, "build: negative height");
    MFT_CHECK(mf_ibm_build(&ibm, n, 1 << 20, 1, MF_R(0.1)) == MF_ERROR_INVALID_ARGUMENT && !ibm.data, "build: too wide");
    MFT_CHECK(mf_ibm_build(&ibm, n, 16, 16, MF_R(0.0)) == MF_ERROR_INVALID_ARGUMENT && !ibm.data, "build: alpha 0");
    MFT_CHECK(mf_ibm_build(&ibm, n, 16, 16, (mf_real)sqrt(-1.0)) == MF_ERROR_INVALID_ARGUMENT && !ibm.data, "build: alpha NaN");
    MFT_CHECK(mf_ibm_build_ex(&ibm, n, 16, 16, MF_R(0.1), mft_ibm_o(MF_IBM_MAX_RES + 1, 0)) == MF_ERROR_INVALID_ARGUMENT, "build: resolution too large");
    MFT_CHECK(mf_ibm_build_ex(&ibm, n, 16, 16, MF_R(0.1), mft_ibm_o(-1, 0)) == MF_ERROR_INVALID_ARGUMENT, "build: negative resolution");
    MFT_CHECK(mf_ibm_build_ex(&ibm, n, 16, 16, MF_R(0.1), mft_ibm_o(0, MF_R(-1.0))) == MF_ERROR_INVALID_ARGUMENT, "build: negative cut");
    MFT_CHECK(mf_ibm_build_ex(&ibm, n, 16, 16, MF_R(0.1), mft_ibm_o(0, MF_R(11.0))) == MF_ERROR_INVALID_ARGUMENT, "build: cut too large");
    for (i = 0; i < 4; ++i) {
        mf_real keep[3];
        int k = 3 * (37 + 50 * i);
        keep[0] = n[k]; keep[1] = n[k + 1]; keep[2] = n[k + 2];
        if (i == 0) n[k] = (mf_real)sqrt(-1.0);                 /* NaN */
        if (i == 1) { n[k] = MF_R(0.5); n[k + 1] = MF_R(0.5); n[k + 2] = MF_R(0.5); }   /* not unit */
        if (i == 2) { n[k] = MF_R(0.6); n[k + 1] = MF_R(0.0); n[k + 2] = MF_R(-0.8); }  /* below the horizon */
        if (i == 3) { n[k] = MF_R(1.0); n[k + 1] = MF_R(0.0); n[k + 2] = MF_R(0.0); }   /* at the horizon */
        if (mf_ibm_build(&ibm, n, 16, 16, MF_R(0.1)) != MF_ERROR_INVALID_DATA || ibm.data) ++bad;
        n[k] = keep[0]; n[k + 1] = keep[1]; n[k + 2] = keep[2];
    }
    MFT_CHECK(bad == 0, "build: NaN, non-unit and below-horizon normals give MF_ERROR_INVALID_DATA, nothing allocated");
    MFT_CHECK(mf_ibm_build(&ibm, n, 16, 16, MF_R(0.1)) == MF_SUCCESS && ibm.data, "build: good input builds");
    mf_ibm_release(&ibm);
    MFT_CHECK(!ibm.data && mf_ibm_memory_bytes(&ibm) == 0, "release: empty");
    mf_ibm_release(&ibm);   /* twice is harmless */
    free(n);
}

/* resolution (Eq. 5.14), radius, bins, index, bin map, means */
static void test_structure(void)
{
    const double alphas[4] = { 0.0025, 0.01, 0.04, 0.16 };
    const int want_b[4] = { 942, 235, 59, 15 };   /* thesis Table 5.5 */
    mf_real *n = map_smooth(48, 40, 1.2, 3);
    mf_ibm ibm;
    int i, j, bad = 0, total = 0, badbin = 0;
    char msg[160];
    for (i = 0; i < 4; ++i) {
        double s = 3 * alphas[i] / sqrt(2.0), b = floor(5 / (s / sqrt(1 + s * s)));
        mf_ibm_build(&ibm, n, 48, 40, (mf_real)alphas[i]);
        snprintf(msg, sizeof msg, "Eq. 5.14 resolution at alpha %g: %d (thesis %d), radius 2", alphas[i], ibm.res, want_b[i]);
        MFT_CHECK(ibm.res == (int)b && ibm.res == want_b[i] && ibm.radius == 2 && mf_ibm_bin_count(&ibm) == ibm.res * ibm.res, msg);
        mf_ibm_release(&ibm);
    }
    mf_ibm_build(&ibm, n, 48, 40, MF_R(0.16));
    for (j = 0; j < mf_ibm_bin_count(&ibm); ++j) total += mf_ibm_bin_texels(&ibm, j);
    MFT_CHECK(total == 48 * 40, "bins hold every texel once");
    for (i = 0; i < 48 * 40; ++i) {
        mf_vec3 t = mf_vec3_make(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
        int b = ibm.res, want = (int)floor(b * (0.5 * t.x + 0.5)) + b * (int)floor(b * (0.5 * t.y + 0.5));
        int got = mf_ibm_texel_bin(&ibm, i % 48, i / 48);
        if (got != want || mf_ibm_bin_of(&ibm, t) != want) ++badbin;
        /* the bin's mean normal is inside the bin */
        {
            mf_vec3 m = mf_ibm_bin_normal(&ibm, got);
            if (mf_ibm_bin_of(&ibm, m) != got || fabs(mf_dot(m, m) - 1.0) > 1e-5) ++bad;
        }
    }
    MFT_CHECK(badbin == 0, "bin map and mf_ibm_bin_of follow beta(m) of Sec. 5.4.2");
    MFT_CHECK(bad == 0, "bin normals are unit and inside their bin");
    MFT_CHECK(mf_ibm_texel_bin(&ibm, -1, 40) == mf_ibm_texel_bin(&ibm, 47, 0), "texel lookup wraps");
    MFT_CHECK(mf_ibm_bin_of(&ibm, mf_vec3_make(0, 0, -1)) == -1 && mf_ibm_bin_of(&ibm, mf_vec3_make(0, 0, 0)) == -1,
              "bin_of: -1 below the horizon and for zero");
    MFT_CHECK(mf_ibm_memory_bytes(&ibm) == ibm.words * 4 && ibm.words > 48 * 40 / 4, "memory_bytes = words * 4");
    /* the packed reads' two spare words end the array, zero (the checksum
     * and saved files cover them) */
    MFT_CHECK(ibm.data[ibm.words - 1] == 0u && ibm.data[ibm.words - 2] == 0u, "the array ends with two zero spare words");
    /* neighbourhood: 21 bins of a dense map (Sec. 5.4.2) */
    {
        mf_real *d = (mf_real *)malloc(sizeof(mf_real) * 3 * 64 * 64);
        int bins[MF_IBM_MAX_WINDOW], k;
        mf_real w[MF_IBM_MAX_WINDOW];
        mf_footprint f = fp_make(0.5, 0.5, 1, 0, 0, 1);
        double sum = 0;
        mft_rng r;
        mf_ibm m2;
        mft_seed(&r, 5);
        for (k = 0; k < 64 * 64; ++k) {   /* uniform on the disk of radius 0.7 */
            double rr = 0.7 * sqrt(mft_u01(&r)), ph = 2 * PI_D * mft_u01(&r);
            d[3 * k] = (mf_real)(rr * cos(ph)); d[3 * k + 1] = (mf_real)(rr * sin(ph));
            d[3 * k + 2] = (mf_real)sqrt(1 - rr * rr);
        }
        mf_ibm_build(&m2, d, 64, 64, MF_R(0.16));
        k = mf_ibm_neighbourhood_weights(&m2, &f, mf_ibm_bin_of(&m2, mf_vec3_make(0, 0, 1)), bins, w);
        for (i = 0; i < k; ++i) sum += (double)w[i];
        snprintf(msg, sizeof msg, "neighbourhood of the center bin has 21 bins (got %d)", k);
        MFT_CHECK(k == 21, msg);
        MFT_CHECK(sum > 0.1 && sum < 1.0, "neighbourhood weights are a part of the whole");
        mf_ibm_release(&m2);
        free(d);
    }
    mf_ibm_release(&ibm);
    free(n);
    /* tiny and one-texel-wide maps (Morton codes of 0 bits along an axis) */
    {
        const int sizes[4][2] = { { 1, 1 }, { 1, 7 }, { 5, 1 }, { 3, 2 } };
        mf_footprint f = fp_make(0.3, 0.6, 0.7, 0.2, -0.1, 0.9), g = fp_make(0.1, 0.2, 0.05, 0, 0, 0.05);
        int nbad = 0, k;
        for (k = 0; k < 4; ++k) {
            mf_real *m = map_smooth(sizes[k][0], sizes[k][1], 0.5, 100 + k);
            mf_ibm t, l;
            double sf = 0, sg = 0;
            size_t nb;
            unsigned char *buf;
            if (mf_ibm_build(&t, m, sizes[k][0], sizes[k][1], MF_R(0.1)) != MF_SUCCESS) { ++nbad; free(m); continue; }
            for (i = 0; i < mf_ibm_bin_count(&t); ++i) { sf += (double)mf_ibm_bin_weight(&t, i, &f); sg += (double)mf_ibm_bin_weight(&t, i, &g); }
            if (fabs(sf - 1) > MFT_TOL(1e-12, 1e-5) || fabs(sg - 1) > MFT_TOL(1e-12, 1e-5)) ++nbad;
            nb = mft_ibm_bytes(&t);
            buf = (unsigned char *)malloc(nb);
            mf_ibm_save(&t, buf, nb, &nb);
            if (mf_ibm_load(&l, buf, nb) != MF_SUCCESS) ++nbad;
            mf_ibm_release(&l);
            mf_ibm_release(&t);
            free(buf);
            free(m);
        }
        MFT_CHECK(nbad == 0, "1x1, 1x7, 5x1 and 3x2 maps: weights sum to 1, save and load");
    }
}

/* bin weights against brute force */
static void check_weights(const char *name, const mf_real *n, int w, int h, double alpha, int trials, unsigned long long seed)
{
    mf_ibm ibm;
    double *wk = (double *)malloc(sizeof(double) * (size_t)(w * h));
    double *wb, err = 0, err_sum = 0, err_nb = 0;
    int nb, t, i, kinds = 7;
    mft_rng r;
    char msg[200];
    const double tol = MFT_TOL(1e-9, 2e-5);
    mf_ibm_build(&ibm, n, w, h, (mf_real)alpha);
    nb = mf_ibm_bin_count(&ibm);
    wb = (double *)malloc(sizeof(double) * (size_t)nb);
    mft_seed(&r, seed);
    for (t = 0; t < trials + NFIXED; ++t) {
        mf_footprint f = t < NFIXED ? fixed_fp(t, w, h) : fp_random(&r, t % kinds, w);
        double s = 0;
        int bins[MF_IBM_MAX_WINDOW], k, c;
        mf_real ww[MF_IBM_MAX_WINDOW];
        brute_texel_weights(&f, w, h, wk);
        brute_bin_sums(&ibm, wk, wb);
        for (i = 0; i < nb; ++i) {
            double g;
            if (mf_ibm_bin_texels(&ibm, i) == 0) continue;
            g = (double)mf_ibm_bin_weight(&ibm, i, &f);
            s += g;
            err = fmax(err, fabs(g - wb[i]));
        }
        err_sum = fmax(err_sum, fabs(s - 1));
        /* neighbourhood query: the same weights in one traversal */
        c = mf_ibm_texel_bin(&ibm, (int)(mft_u01(&r) * w), (int)(mft_u01(&r) * h));
        k = mf_ibm_neighbourhood_weights(&ibm, &f, c, bins, ww);
        for (i = 0; i < k; ++i) err_nb = fmax(err_nb, fabs((double)ww[i] - wb[bins[i]]));
    }
    snprintf(msg, sizeof msg, "bin weights = brute force over texels, %s (%d footprints, max err %.2e)", name, trials + NFIXED, err);
    MFT_NEAR(err, 0, 0, tol, msg);
    snprintf(msg, sizeof msg, "bin weights sum to 1, %s (max err %.2e)", name, err_sum);
    MFT_NEAR(err_sum, 0, 0, tol, msg);
    snprintf(msg, sizeof msg, "neighbourhood weights = brute force, %s (max err %.2e)", name, err_nb);
    MFT_NEAR(err_nb, 0, 0, tol, msg);
    mf_ibm_release(&ibm);
    free(wk);
    free(wb);
}

/* The lists' block lengths (layout in 15_ibm_1_format.h): n + 2^k(n) - 1 for a bin
 * with a stored kd-tree top is strictly increasing in n and gives n back;
 * lengths it skips give no tree (k = 0), which mf_ibm_load refuses at or
 * above MF_IBM_TREE_MIN. Every n up to 2^21, then every 997th up to 2^28
 * (the largest map). A flat power-of-two map puts every texel in one bin:
 * its inner node boundaries reach N - 1 and must fit the kx + ky bits of a
 * position. */
static void test_block_lengths(void)
{
    mf_ibm m;
    unsigned int n, prev = 0u, step = 1u;
    int bad = 0, k;
    char msg[160];
    memset(&m, 0, sizeof m);
    m.kx = m.ky = 14;
    for (n = 0u; n <= 1u << 28; n += step) {
        unsigned int len = mf__ibm_block_len(&m, n), got = mf__ibm_block_texels(&m, len, &k), l;
        int want_k = n < (unsigned int)MF_IBM_TREE_MIN ? 0 : mf__ibm_tree_levels(&m, n);
        if (got != n || k != want_k || (n >= (unsigned int)MF_IBM_TREE_MIN) != (k > 0) || (n > 0u && len <= prev)) ++bad;
        if (step == 1u && n > 0u)
            for (l = prev + 1u; l < len; ++l) {   /* skipped lengths */
                int k2;
                mf__ibm_block_texels(&m, l, &k2);
                if (k2 != 0) ++bad;
            }
        prev = len;
        if (n >= 1u << 21) step = 997u;
    }
    snprintf(msg, sizeof msg, "block lengths n + 2^k - 1: increasing, n recovered, skipped lengths refused (%d bad)", bad);
    MFT_CHECK(bad == 0, msg);
    {
        mf_real *fl = (mf_real *)malloc(sizeof(mf_real) * 3 * 64 * 64);
        mf_ibm a, b;
        mf_footprint f = { 0.3, 0.6, 0.25, 0.05, -0.1, 0.3 };
        unsigned char *buf;
        size_t bytes, i;
        int j;
        for (i = 0; i < 64 * 64; ++i) { fl[3 * i] = 0; fl[3 * i + 1] = 0; fl[3 * i + 2] = 1; }
        mf_ibm_build(&a, fl, 64, 64, MF_R(0.01));
        j = mf_ibm_bin_of(&a, mf_vec3_make(0, 0, 1));
        bytes = mft_ibm_bytes(&a);
        buf = (unsigned char *)malloc(bytes);
        mf_ibm_save(&a, buf, bytes, &bytes);
        MFT_CHECK(mf_ibm_bin_texels(&a, j) == 64 * 64 && mf_ibm_load(&b, buf, bytes) == MF_SUCCESS &&
                      fabs((double)mf_ibm_bin_weight(&b, j, &f) - 1.0) < 1e-6,
                  "flat 64x64 map: one bin of every texel, saved and loaded, weight 1");
        mf_ibm_release(&a);
        mf_ibm_release(&b);
        free(buf);
        free(fl);
    }
}

/* neighbourhood sets of a fine-binned smooth map (21 bins of 49 to 1008
 * texels in all, a few per bin) against footprints of 2,500 to 14,000 box
 * texels inside the period: the sets that mf__ibm_weights_few takes texel by
 * texel from the bins' lists (at most 48 texels per bin of the set) rather
 * than by kd traversal; the same bound as check_weights. The cases are
 * counted so that the check cannot pass without them. */
static void check_few_sets(void)
{
    const int W = 256;
    mf_real *s = map_smooth(W, W, 1.0, 41);
    double *wk = (double *)malloc(sizeof(double) * (size_t)(W * W)), *wb, err = 0;
    const double tol = MFT_TOL(1e-9, 2e-5);
    int t, i, q, cases = 0, nb;
    mf_ibm ibm;
    mft_rng r;
    char msg[200];
    mf_ibm_build(&ibm, s, W, W, (mf_real)0.02);
    nb = mf_ibm_bin_count(&ibm);
    wb = (double *)malloc(sizeof(double) * (size_t)nb);
    mft_seed(&r, 42);
    for (t = 0; t < 24; ++t) {
        double ang = 2 * PI_D * mft_u01(&r), len = (50 + 70 * mft_u01(&r)) / W, asp = 0.5 + 0.5 * mft_u01(&r);
        double sk = 0.6 * mft_u01(&r) - 0.3, u = 0.3 + 0.4 * mft_u01(&r), v = 0.3 + 0.4 * mft_u01(&r);
        mf_footprint f = fp_rotated(u, v, len, ang, asp, sk);
        brute_texel_weights(&f, W, W, wk);
        brute_bin_sums(&ibm, wk, wb);
        for (q = 0; q < 16; ++q) {
            /* a center bin of a texel near the footprint's center */
            int bins[MF_IBM_MAX_WINDOW], k, texels = 0;
            mf_real ww[MF_IBM_MAX_WINDOW];
            int c = mf_ibm_texel_bin(&ibm, (int)((u + 0.1 * (mft_u01(&r) - 0.5)) * W), (int)((v + 0.1 * (mft_u01(&r) - 0.5)) * W));
            k = mf_ibm_neighbourhood_weights(&ibm, &f, c, bins, ww);
            for (i = 0; i < k; ++i) {
                texels += mf_ibm_bin_texels(&ibm, bins[i]);
                err = fmax(err, fabs((double)ww[i] - wb[bins[i]]));
            }
            if (k > 1 && texels > 48 && texels <= 48 * k) ++cases;
        }
    }
    snprintf(msg, sizeof msg, "neighbourhood weights = brute force, sets of 49-1008 texels, smooth 256x256 alpha 0.02 (%d sets, max err %.2e)",
             cases, err);
    MFT_NEAR(err, 0, 0, tol, msg);
    MFT_CHECK(cases >= 200, "neighbourhood sets of 49 to 48 per bin texels: at least 200 of 384 queries");
    mf_ibm_release(&ibm);
    free(wb);
    free(wk);
    free(s);
}

static void test_weights(void)
{
    mf_real *s = map_smooth(48, 40, 1.0, 11), *fl = map_flakes(64, 64, 4, 0.05, 12);
    mf_ibm ibm;
    char msg[160];
    check_weights("smooth 48x40 alpha 0.1", s, 48, 40, 0.1, 70, 21);
    check_weights("smooth 48x40 alpha 0.02", s, 48, 40, 0.02, 35, 22);
    check_weights("flakes 64x64 alpha 0.01", fl, 64, 64, 0.01, 35, 23);
    {   /* bins large enough for stored kd-tree levels, footprints small
         * enough for the early exit on them (mf__ibm_box_empty): square and
         * non-square maps, whose node shapes alternate from the first
         * level or only after the longer side has been halved */
        mf_real *s2 = map_smooth(256, 64, 1.0, 13), *s3 = map_smooth(1024, 16, 1.0, 15), *f2 = map_flakes(128, 128, 4, 0.05, 14);
        check_weights("smooth 256x64 alpha 0.3", s2, 256, 64, 0.3, 60, 24);
        check_weights("smooth 1024x16 alpha 0.3", s3, 1024, 16, 0.3, 60, 26);
        check_weights("flakes 128x128 alpha 0.2", f2, 128, 128, 0.2, 60, 25);
        free(s2);
        free(s3);
        free(f2);
    }
    {   /* one bin holding most texels (flakes of a peaked GTR: the rest
         * scattered), so that it fills whole kd nodes, whose areas are then
         * taken at once: power-of-two and other sizes, flake cells aligned
         * with the nodes or not */
        mf_real *p1 = map_flakes(128, 128, 4, 0.002, 27), *p2 = map_flakes(96, 80, 3, 0.002, 28);
        check_weights("flakes 128x128, one bin of most texels, alpha 0.16", p1, 128, 128, 0.16, 60, 29);
        check_weights("flakes 96x80, one bin of most texels, alpha 0.16", p2, 96, 80, 0.16, 60, 30);
        free(p1);
        free(p2);
    }
    /* degenerate: zero area and NaN edges -> the texel at the center */
    mf_ibm_build(&ibm, s, 48, 40, MF_R(0.1));
    {
        mf_footprint f0 = fp_make(10.5 / 48 + 3, 7.25 / 40, 0, 0, 0, 0), fn = f0, fc = f0;
        int j = mf_ibm_texel_bin(&ibm, 10, 7);
        fn.ax = (mf_real)sqrt(-1.0);
        fc.u = (mf_real)sqrt(-1.0);
        MFT_CHECK(mf_ibm_bin_weight(&ibm, j, &f0) == 1 && mf_ibm_bin_weight(&ibm, j, &fn) == 1,
                  "zero-area and NaN-edge footprints look up the center texel");
        MFT_CHECK(mf_ibm_bin_weight(&ibm, j, &fc) == 0 && mf_ibm_bin_weight(&ibm, j, NULL) == 0 &&
                  mf_ibm_bin_weight(&ibm, -1, &f0) == 0 && mf_ibm_bin_weight(NULL, j, &f0) == 0,
                  "NaN center, NULL footprint, bad bin, NULL map: weight 0");
    }
    /* whole periods: an aligned 3 x 2 period footprint, exactly the first
     * period (its corners on the period's: one full period, no piece) and one
     * beyond the cap all give the map's histogram */
    {
        mf_footprint f = fp_make(0.0, 0.0, 3.0, 0.0, 0.0, 2.0), g = fp_make(0.37, 0.61, 300.0, 41.0, -17.0, 250.0);
        mf_footprint f1 = fp_make(0.5, 0.5, 1.0, 0.0, 0.0, 1.0);
        double e1 = 0, e2 = 0, e3 = 0;
        int j;
        for (j = 0; j < mf_ibm_bin_count(&ibm); ++j) {
            double want = mf_ibm_bin_texels(&ibm, j) / (48.0 * 40.0);
            e1 = fmax(e1, fabs((double)mf_ibm_bin_weight(&ibm, j, &f) - want));
            e2 = fmax(e2, fabs((double)mf_ibm_bin_weight(&ibm, j, &g) - want));
            e3 = fmax(e3, fabs((double)mf_ibm_bin_weight(&ibm, j, &f1) - want));
        }
        snprintf(msg, sizeof msg, "whole periods counted from bin sizes (err %.2e; exactly one period %.2e), beyond the cap: the histogram (err %.2e)", e1, e3, e2);
        MFT_CHECK(e1 < MFT_TOL(1e-12, 1e-6) && e3 < MFT_TOL(1e-12, 1e-6) && e2 < MFT_TOL(1e-12, 1e-6), msg);
    }
    mf_ibm_release(&ibm);
    free(s);
    free(fl);
}

/* Eq. 3.29 against the tilted Beckmann lobe: constant maps, the flat map */
static void test_texel_contribution(void)
{
    const mf_vec3 ts[3] = { { 0, 0, 1 }, { 0.3f, -0.2f, 0.932738f }, { -0.55f, 0.1f, 0.829156f } };
    const double alphas[3] = { 0.04, 0.16, 0.5 };
    int a, k, q, bad = 0, badr = 0, badn = 0, nz = 0, ncut = 0;
    double worst = 0, worst_r = 0;
    mft_rng r;
    char msg[200];
    mft_seed(&r, 31);
    for (k = 0; k < 3; ++k)
        for (a = 0; a < 3; ++a) {
            mf_vec3 t = mf_normalize(ts[k]);
            mf_real *n = map_const(8, 8, t);
            mf_ibm ibm;
            mf_footprint f = fp_make(mft_u01(&r), mft_u01(&r), 0.3, 0.1, -0.05, 0.4);
            mf_vec3 tb;
            mf_ibm_build(&ibm, n, 8, 8, (mf_real)alphas[a]);
            tb = mf_ibm_bin_normal(&ibm, mf_ibm_bin_of(&ibm, t));
            if (fabs((double)tb.x - t.x) + fabs((double)tb.y - t.y) > MFT_TOL(3e-5, 3e-5)) ++badn;
            for (q = 0; q < 200; ++q) {
                /* wi around the mirror direction of t, wo anywhere above */
                mf_vec3 wo = mft_dir(1.4 * mft_u01(&r), 2 * PI_D * mft_u01(&r)), m, wi;
                mf_ndf lobe = mf_beckmann((mf_real)(2 * alphas[a]), (mf_real)(2 * alphas[a]));
                mf_vec3 tt, tbb, mm;
                double want, got, rev;
                { mf_basis fr_ = mf_basis_from_normal(tb); tt = fr_.t; tbb = fr_.b; }
                mm = mf_sample_D(&lobe, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
                m = mf_normalize(mf_add(mf_add(mf_scale(tt, mm.x), mf_scale(tbb, mm.y)), mf_scale(tb, mm.z)));
                wi = mf_reflect(wo, m);
                if (q & 1) mf_ibm_set_shadowing(&ibm, NULL);
                else mf_ibm_set_shadowing(&ibm, &ibm.shadow);
                want = texel_C(ibm.alpha, (q & 1) ? NULL : &ibm.shadow, wo, wi, tb);
                if (!in_neighbourhood(ibm.res, 2, tb, mf_normalize(mf_add(wo, wi)))) { want = 0; ++ncut; }
                got = (double)mf_ibm_brdf(&ibm, &f, wo, wi);
                rev = (double)mf_ibm_brdf(&ibm, &f, wi, wo);
                if (want > 0) ++nz;
                worst = fmax(worst, fabs(got - want) / fmax(want, 1e-3));
                if (!(fabs(got - want) <= MFT_TOL(1e-9, 1e-3) * fmax(want, 1e-3))) ++bad;
                worst_r = fmax(worst_r, fabs(got - rev) / fmax(got, 1e-30));
                if (!(fabs(got - rev) <= MFT_TOL(1e-12, 1e-5) * got)) ++badr;
            }
            mf_ibm_release(&ibm);
            free(n);
        }
    MFT_CHECK(badn == 0, "constant map: the bin normal is the map's normal");
    snprintf(msg, sizeof msg, "constant map: brdf = tilted Beckmann lobe (Eq. 3.29) inside the 21 bins, 0 outside (%d nonzero, %d cut of 1800), worst rel %.2e", nz, ncut, worst);
    MFT_CHECK(bad == 0 && nz > 900 && ncut > 100, msg);
    snprintf(msg, sizeof msg, "reciprocity f(wo,wi) = f(wi,wo) (worst rel %.2e)", worst_r);
    MFT_CHECK(badr == 0, msg);
    /* the flat map is the plain Beckmann BRDF */
    {
        mf_real *n = map_const(8, 8, mf_vec3_make(0, 0, 1));
        mf_ibm ibm;
        mf_ndf d;
        mf_footprint f = fp_make(0.2, 0.7, 0.5, 0.0, 0.0, 0.5);
        double e = 0;
        mf_ibm_build(&ibm, n, 8, 8, MF_R(0.1));
        d = mf_beckmann(ibm.alpha, ibm.alpha);   /* alpha as stored (rounded to float) */
        mf_ibm_set_shadowing(&ibm, NULL);
        for (q = 0; q < 300; ++q) {
            mf_vec3 wo = mft_dir(1.5 * mft_u01(&r), 2 * PI_D * mft_u01(&r));
            mf_vec3 wi = mf_brdf_sample(&d, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
            double want = (double)mf_brdf(&d, wo, wi);
            if (!(wi.z > 0)) continue;
            if (!in_neighbourhood(ibm.res, 2, mf_vec3_make(0, 0, 1), mf_normalize(mf_add(wo, wi)))) want = 0;
            e = fmax(e, fabs((double)mf_ibm_brdf(&ibm, &f, wo, wi) - want) / fmax(want, 1e-3));
        }
        snprintf(msg, sizeof msg, "flat map = plain Beckmann BRDF (worst rel %.2e)", e);
        MFT_CHECK(e < MFT_TOL(1e-10, 1e-4), msg);
        mf_ibm_release(&ibm);
        free(n);
    }
}

/* the binned BRDF tends to the texel sum with the true normals (Eq. 5.2) */
static void test_convergence(void)
{
    const int W = 32;
    mf_real *n = map_smooth(W, W, 0.6, 41);
    double *wk = (double *)malloc(sizeof(double) * W * W), err[3] = { 0, 0, 0 };
    mf_footprint f = fp_make(0.4, 0.3, 0.45, 0.2, -0.15, 0.5);
    mf_vec3 wos[160], wis[160];
    double ref[160];
    int k, q, i;
    mft_rng r;
    char msg[200];
    const double alpha = 0.1;
    brute_texel_weights(&f, W, W, wk);
    mft_seed(&r, 42);
    for (q = 0; q < 160; ++q) {
        /* pairs near the mirror directions of the covered texels */
        int tk;
        mf_vec3 t, wo = mft_dir(1.2 * mft_u01(&r), 2 * PI_D * mft_u01(&r)), g;
        mf_ndf lobe = mf_beckmann((mf_real)alpha, (mf_real)alpha);
        do tk = (int)(mft_u01(&r) * W * W); while (wk[tk] == 0);
        t = mf_vec3_make(n[3 * tk], n[3 * tk + 1], n[3 * tk + 2]);
        g = mf_sample_D(&lobe, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
        {
            mf_vec3 tt, tb;
            { mf_basis fr_ = mf_basis_from_normal(t); tt = fr_.t; tb = fr_.b; }
            g = mf_normalize(mf_add(mf_add(mf_scale(tt, g.x), mf_scale(tb, g.y)), mf_scale(t, g.z)));
        }
        wos[q] = wo;
        wis[q] = mf_reflect(wo, g);
        ref[q] = 0;
        if (!(wis[q].z > 0)) { --q; continue; }
        for (i = 0; i < W * W; ++i)
            if (wk[i] > 0) ref[q] += wk[i] * texel_C(alpha, NULL, wo, wis[q], mf_vec3_make(n[3 * i], n[3 * i + 1], n[3 * i + 2]));
    }
    for (k = 0; k < 3; ++k) {
        mf_ibm ibm, base;
        double se = 0, sr = 0;
        mf_ibm_build_ex(&base, n, W, W, (mf_real)alpha, mft_ibm_o(0, MF_R(5.0)));
        mf_ibm_build_ex(&ibm, n, W, W, (mf_real)alpha, mft_ibm_o((k + 1) * base.res, MF_R(5.0)));
        mf_ibm_set_shadowing(&ibm, NULL);
        for (q = 0; q < 160; ++q) {
            se += fabs((double)mf_ibm_brdf(&ibm, &f, wos[q], wis[q]) - ref[q]);
            sr += ref[q];
        }
        err[k] = se / sr;
        if (mft_verbose) printf("    resolution %d (radius %d): relative L1 error %.4f\n", ibm.res, ibm.radius, err[k]);
        mf_ibm_release(&ibm);
        mf_ibm_release(&base);
    }
    snprintf(msg, sizeof msg, "binned BRDF -> texel sum (Eq. 5.2) as bins get finer: L1 err %.4f, %.4f, %.4f", err[0], err[1], err[2]);
    MFT_CHECK(err[1] < err[0] && err[2] < 0.5 * err[0] && err[2] < 0.03, msg);
    free(wk);
    free(n);
}

/* Integral over wi of g(wi), split into half-vector cells (the bins split
 * sub x sub): the integral over each cell of g(wi(h)) 4 (wo.h) / h.z dhx dhy,
 * 4 x 4 Gauss-Legendre nodes, so that the bin edges (where the neighbourhood
 * changes) are cell edges. Writes each cell's share to prob (if not NULL),
 * returns the total. */
typedef double (*wi_fn)(mf_vec3 wi, void *ctx);
static double h_cells(int res, int sub, mf_vec3 wo, wi_fn g, void *ctx, double *prob)
{
    double gx[4], gw[4], tot = 0;
    int nc = res * sub, cx, cy, i, j;
    mft_gl(4, gx, gw);
    for (cy = 0; cy < nc; ++cy)
        for (cx = 0; cx < nc; ++cx) {
            double x0 = -1 + 2.0 * cx / nc, y0 = -1 + 2.0 * cy / nc, d = 2.0 / nc, p = 0;
            double nx = fmin(fabs(x0), fabs(x0 + d)), ny = fmin(fabs(y0), fabs(y0 + d));
            if (x0 < 0 && x0 + d > 0) nx = 0;
            if (y0 < 0 && y0 + d > 0) ny = 0;
            if (nx * nx + ny * ny < 1)
                for (i = 0; i < 4; ++i)
                    for (j = 0; j < 4; ++j) {
                        double hx = x0 + d * gx[i], hy = y0 + d * gx[j], r2 = hx * hx + hy * hy, hz, c;
                        mf_vec3 h, wi;
                        if (r2 >= 1) continue;
                        hz = sqrt(1 - r2);
                        h = mf_vec3_make((mf_real)hx, (mf_real)hy, (mf_real)hz);
                        c = (double)mf_dot(wo, h);
                        if (c <= 0) continue;
                        wi = mf_normalize(mf_reflect(wo, h));
                        if (!(wi.z > 0)) continue;
                        p += gw[i] * gw[j] * d * d * g(wi, ctx) * 4 * c / hz;
                    }
            if (prob) prob[cy * nc + cx] = p;
            tot += p;
        }
    return tot;
}

/* what h_cells integrates: the pdf, the IBM BRDF cos, or the BRDF cos
 * summed over every bin (weights wbin, Eq. 5.7 without the truncation) */
typedef struct { const mf_ibm *ibm; const mf_footprint *f; mf_vec3 wo; const double *wbin; } q_ctx;
static double q_pdf(mf_vec3 wi, void *ctx)
{
    const q_ctx *q = (const q_ctx *)ctx;
    return (double)mf_ibm_pdf(q->ibm, q->f, q->wo, wi);
}
static double q_brdf_cos(mf_vec3 wi, void *ctx)
{
    const q_ctx *q = (const q_ctx *)ctx;
    return (double)mf_ibm_brdf(q->ibm, q->f, q->wo, wi) * (double)wi.z;
}
static double q_all_bins_cos(mf_vec3 wi, void *ctx)
{
    const q_ctx *q = (const q_ctx *)ctx;
    double v = 0;
    int j;
    for (j = 0; j < mf_ibm_bin_count(q->ibm); ++j)
        if (q->wbin[j] > 0) v += q->wbin[j] * texel_C(q->ibm->alpha, NULL, q->wo, wi, mf_ibm_bin_normal(q->ibm, j));
    return v * (double)wi.z;
}

/* sampling against the pdf: chi-square, pdf > 0 on samples, eval/pdf in one
 * call, and the integral of the pdf against the fraction of samples */
static void check_sampling(const char *name, const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, int n, int sub,
                           double want_norm, unsigned long long seed)
{
    int nc = ibm->res * sub, i, dof, got = 0, zero_pdf = 0, bad_pair = 0;
    double *prob = (double *)malloc(sizeof(double) * (size_t)(nc * nc + 1));
    double *obs = (double *)calloc((size_t)(nc * nc + 1), sizeof(double)), tot, z, frac, se;
    q_ctx qc;
    mft_rng r;
    char msg[240];
    qc.ibm = ibm; qc.f = f; qc.wo = wo; qc.wbin = NULL;
    tot = h_cells(ibm->res, sub, wo, q_pdf, &qc, prob);
    mft_seed(&r, seed);
    for (i = 0; i < n; ++i) {
        mf_vec3 wi = mf_ibm_sample(ibm, f, wo, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r), (mf_real)mft_u01(&r)).wi;
        mf_vec3 h;
        double p;
        if (!(wi.z > 0)) { obs[nc * nc] += 1; continue; }
        ++got;
        h = mf_normalize(mf_add(wo, wi));
        obs[(int)floor(nc * (0.5 * h.y + 0.5)) * nc + (int)floor(nc * (0.5 * h.x + 0.5))] += 1;
        p = (double)mf_ibm_pdf(ibm, f, wo, wi);
        if (!(p > 0)) ++zero_pdf;
        if (i % 16 == 0) {
            mf_real pp, ff = mf_ibm_brdf_and_pdf(ibm, f, wo, wi, &pp);
            if (fabs((double)pp - p) > 1e-12 * p || fabs((double)(ff - mf_ibm_brdf(ibm, f, wo, wi))) > 1e-12 * (double)ff) ++bad_pair;
        }
    }
    for (i = 0; i < nc * nc; ++i) prob[i] *= n;
    prob[nc * nc] = n * fmax(1 - tot, 0.0);
    z = mft_chi2(obs, prob, nc * nc + 1, &dof);
    snprintf(msg, sizeof msg, "sampling vs mf_ibm_pdf, %s: chi-square z = %.2f (dof %d)", name, z, dof);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(z < 5, msg);
    snprintf(msg, sizeof msg, "every sample has pdf > 0, %s (%d of %d)", name, zero_pdf, got);
    MFT_CHECK(zero_pdf == 0 && got > n / 2, msg);
    snprintf(msg, sizeof msg, "mf_ibm_brdf_pdf = mf_ibm_brdf and mf_ibm_pdf, %s", name);
    MFT_CHECK(bad_pair == 0, msg);
    frac = (double)got / n;
    se = sqrt(frac * (1 - frac) / n);
    snprintf(msg, sizeof msg, "integral of the pdf (%.5f) = fraction of samples returned (%.5f), %s", tot, frac, name);
    MFT_NEAR(tot, frac, 0, 4 * se + 2e-3, msg);
    if (want_norm > 0) {
        snprintf(msg, sizeof msg, "pdf integrates to 1 without truncation or horizon loss, %s (%.5f)", name, tot);
        MFT_NEAR(tot, want_norm, 0, 2e-3, msg);
    }
    free(prob);
    free(obs);
}

static void test_sampling_pdf(void)
{
    const int W = 32;
    mf_real *s = map_smooth(W, W, 0.6, 51), *fl = map_flakes(W, W, 4, 0.05, 52);
    mf_ibm a, b, c;
    mf_footprint med = fp_make(0.3, 0.6, 0.4, 0.1, -0.2, 0.3), tiny = fp_make(0.51, 0.22, 0.09, 0.03, 0.0, 0.08);
    mf_footprint huge = fp_make(0.2, 0.3, 301.0, 17.0, -23.0, 260.0), point = fp_make(0.77, 0.41, 0, 0, 0, 0);
    mf_footprint wrap = fp_make(0.99, 0.02, 0.2, 0.0, 0.0, 0.15);
    mf_ibm_build(&a, s, W, W, MF_R(0.1));
    mf_ibm_build_ex(&b, s, W, W, MF_R(0.1), mft_ibm_o(0, MF_R(5.0)));
    mf_ibm_build(&c, fl, W, W, MF_R(0.05));
    check_sampling("smooth, footprint 13x10 texels (kd traversal)", &a, &med, mft_dir(0.3, 0.4), 100000, 2, 0, 61);
    check_sampling("smooth, 5-sigma cut", &b, &med, mft_dir(0.3, 0.4), 100000, 2, 1.0, 62);
    check_sampling("flakes, footprint 3x3 texels (direct sum)", &c, &tiny, mft_dir(0.7, 2.0), 100000, 1, 0, 63);
    check_sampling("flakes, wrapping axis-aligned footprint", &c, &wrap, mft_dir(1.1, -1.0), 60000, 1, 0, 64);
    check_sampling("flakes, 8e4 periods (whole-map histogram)", &c, &huge, mft_dir(0.4, 0.3), 60000, 1, 0, 65);
    check_sampling("smooth, zero-area footprint (one texel)", &a, &point, mft_dir(0.9, 1.0), 60000, 2, 0, 66);
    mf_ibm_release(&a);
    mf_ibm_release(&b);
    mf_ibm_release(&c);
    free(s);
    free(fl);
}

/* packed fields of the documented layout (w bits each, little-end first) */
static unsigned int field_get(const unsigned int *base, size_t i, int w)
{
    unsigned int v = 0u;
    int b;
    for (b = 0; b < w; ++b) {
        size_t bit = i * (size_t)w + (size_t)b;
        v |= ((base[bit >> 5] >> (bit & 31u)) & 1u) << b;
    }
    return v;
}
static void field_set(unsigned int *base, size_t i, int w, unsigned int v)
{
    int b;
    for (b = 0; b < w; ++b) {
        size_t bit = i * (size_t)w + (size_t)b;
        base[bit >> 5] = (base[bit >> 5] & ~(1u << (bit & 31u))) | (((v >> b) & 1u) << (bit & 31u));
    }
}

static void test_save_load(void)
{
    const int W = 40, H = 24;
    mf_real *n = map_flakes(W, H, 3, 0.3, 71);
    mf_ibm a, b;
    size_t bytes, i;
    unsigned char *buf, *cpy;
    int q, same = 1, bad = 0, k;
    mft_rng r;
    char msg[160];
    for (i = 0; i < (size_t)(W * H); ++i)   /* a flat left half: one bin large enough for a stored kd-tree */
        if ((int)(i % W) < W / 2) { n[3 * i] = 0; n[3 * i + 1] = 0; n[3 * i + 2] = 1; }
    mf_ibm_build(&a, n, W, H, MF_R(0.03));
    bytes = mft_ibm_bytes(&a);
    MFT_CHECK(bytes == mf_ibm_memory_bytes(&a) && bytes > 0, "save: size query");
    buf = (unsigned char *)malloc(bytes + 1);
    cpy = (unsigned char *)malloc(bytes + 1);
    {
        size_t need = 0;
        MFT_CHECK(mf_ibm_save(&a, buf, bytes - 1, &need) == MF_ERROR_BUFFER_TOO_SMALL && need == bytes,
                  "save: too small a buffer is refused and the size returned");
    }
    MFT_CHECK(mf_ibm_save(&a, buf + 1, bytes, &bytes) == MF_SUCCESS, "save");   /* an odd address: load copies, so alignment does not matter */
    MFT_CHECK(mf_ibm_load(&b, buf + 1, bytes) == MF_SUCCESS && b.words == a.words &&
              memcmp(a.data, b.data, bytes) == 0, "load: round trip is bit-identical");
    mft_seed(&r, 72);
    for (q = 0; q < 200; ++q) {
        mf_footprint f = fp_random(&r, q % 7, W);
        mf_vec3 wo = mft_dir(1.2 * mft_u01(&r), 6.28 * mft_u01(&r)), wi = mft_dir(1.2 * mft_u01(&r), 6.28 * mft_u01(&r));
        mf_real pa, pb;
        if (mf_ibm_brdf_and_pdf(&a, &f, wo, wi, &pa) != mf_ibm_brdf_and_pdf(&b, &f, wo, wi, &pb) || pa != pb) same = 0;
    }
    MFT_CHECK(same, "load: queries of the loaded map equal the built one's");
    mf_ibm_release(&b);
    /* corruption: every header word, bit flips across the array, truncation */
    for (i = 0; i < 16; ++i) {
        memcpy(cpy, buf + 1, bytes);
        cpy[4 * i + (i % 4)] ^= 0x10;
        if (mf_ibm_load(&b, cpy, bytes) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    }
    for (k = 0; k < 200; ++k) {
        size_t at = (size_t)(mft_u01(&r) * (double)bytes);
        memcpy(cpy, buf + 1, bytes);
        cpy[at] ^= (unsigned char)(1u << (k % 8));
        if (mf_ibm_load(&b, cpy, bytes) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    }
    if (mf_ibm_load(&b, buf + 1, bytes - 4) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    if (mf_ibm_load(&b, buf + 1, bytes - 1) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    if (mf_ibm_load(&b, buf + 1, 12) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    snprintf(msg, sizeof msg, "load: bit flips, header changes and truncation are rejected (%d accepted)", bad);
    MFT_CHECK(bad == 0, msg);
    /* broken structure with a valid checksum: the index, a texel position, the
     * bin map, a kd-tree boundary */
    bad = 0;
    for (k = 0; k < 6; ++k) {
        unsigned int *w;
        float fa = k == 4 ? 1e-20f : 3e4f;
        memcpy(cpy, buf + 1, bytes);
        w = (unsigned int *)(void *)cpy;   /* malloc'd: aligned */
        if (k >= 4) memcpy(&w[7], &fa, 4);                         /* alpha outside the builder's clamp */
        if (k == 0) w[a.off_at + 1] ^= 1u;                        /* an index entry */
        if (k == 1) w[a.pos_at + 3] ^= 1u << 7;                   /* a position or tree boundary */
        if (k == 2) w[a.bin_at + 2] ^= 1u << 2;                   /* the bin map */
        if (k == 3) w[a.pos_at + 1] ^= 1u << 1;                   /* a tree boundary or position */
        w[15] = mf__ibm_checksum(w, bytes / 4);
        if (mf_ibm_load(&b, cpy, bytes) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    }
    /* a kd-tree boundary moved by one inside a large bin (packed fields read
     * and written here from the documented layout) */
    for (k = 0; k < mf_ibm_bin_count(&a); ++k)
        if (mf_ibm_bin_texels(&a, k) >= 4 * MF_IBM_TREE_MIN) break;
    if (k < mf_ibm_bin_count(&a)) {
        unsigned int *w, s0, t1, t2;
        memcpy(cpy, buf + 1, bytes);
        w = (unsigned int *)(void *)cpy;
        s0 = field_get(w + a.off_at, (size_t)k, a.off_bits);
        /* the block opens with the inner boundaries of its level-k nodes
         * (k >= 2 here): move the first, against the second */
        t1 = field_get(w + a.pos_at, (size_t)s0, a.list_bits);
        t2 = field_get(w + a.pos_at, (size_t)s0 + 1u, a.list_bits);
        field_set(w + a.pos_at, (size_t)s0, a.list_bits, t1 < t2 ? t1 + 1u : t1 - 1u);
        w[15] = mf__ibm_checksum(w, bytes / 4);
        if (mf_ibm_load(&b, cpy, bytes) != MF_ERROR_INVALID_DATA || b.data) ++bad;
    } else ++bad;
    snprintf(msg, sizeof msg, "load: broken index, positions, bin map, trees and alpha rejected even with a valid checksum (%d accepted)", bad);
    MFT_CHECK(bad == 0, msg);
    memcpy(cpy, buf + 1, bytes);
    ((unsigned int *)(void *)cpy)[15] = mf__ibm_checksum((unsigned int *)(void *)cpy, bytes / 4);
    MFT_CHECK(mf_ibm_load(&b, cpy, bytes) == MF_SUCCESS, "load: a recomputed checksum of the intact buffer is accepted");
    mf_ibm_release(&b);
    MFT_CHECK(mf_ibm_load(NULL, buf, bytes) == MF_ERROR_INVALID_ARGUMENT && mf_ibm_load(&b, NULL, bytes) == MF_ERROR_INVALID_ARGUMENT,
              "load: NULL arguments");
    {
        size_t need = 1;
        MFT_CHECK(mf_ibm_save(NULL, buf, bytes, &need) == MF_ERROR_INVALID_ARGUMENT && need == 0, "save: NULL map");
        MFT_CHECK(mf_ibm_save(&a, buf, bytes, NULL) == MF_ERROR_INVALID_ARGUMENT, "save: NULL size");
    }
    mf_ibm_release(&a);
    free(buf);
    free(cpy);
    free(n);
}

/* degenerate queries: 0 (never NaN), no sample; float-safe huge values */
static void test_degenerate(void)
{
    mf_real *n = map_smooth(16, 16, 0.5, 81);
    mf_ibm ibm, empty;
    mf_footprint f = fp_make(0.5, 0.5, 0.1, 0, 0, 0.1), bad[6];
    mf_vec3 up = mft_dir(0.3, 0.2), down = mft_dir(2.0, 0.0), zero = mf_vec3_make(0, 0, 0);
    mf_vec3 nanv = mf_vec3_make((mf_real)sqrt(-1.0), 0, 1);
    int i, j, nonfinite = 0, nonzero = 0;
    mf_real pdf;
    double big = MFT_TOL(1e300, 1e30);
    mf_ibm_build(&ibm, n, 16, 16, MF_R(0.1));
    empty.data = NULL;
    bad[0] = fp_make(sqrt(-1.0), 0.5, 0.1, 0, 0, 0.1);
    bad[1] = fp_make(0.5, 0.5, big, big, -big, big);
    bad[2] = fp_make(big, -big, 0.1, 0, 0, 0.1);
    bad[3] = fp_make(0.5, 0.5, 0.1, 0.1, 0.2, 0.2);         /* zero area: point */
    bad[4] = fp_make(0.5, 0.5, 1e-20, 0, 0, 1e-20);
    bad[5] = fp_make(-0.0, 1.0, 1e6, 0, 0, 1e-6);
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 40; ++j) {
            mf_vec3 wo = mft_dir(1.55 * (j % 8) / 7.0, j), wi = mft_dir(1.55 * (j / 8) / 4.0, -j);
            mf_real v = mf_ibm_brdf(&ibm, &bad[i], wo, wi) + mf_ibm_pdf(&ibm, &bad[i], wo, wi);
            mf_vec3 s = mf_ibm_sample(&ibm, &bad[i], wo, MF_R(0.3), MF_R(0.9), MF_R(1.0), MF_R(0.0)).wi;
            if (!mft_finite((double)v) || !mft_finite((double)s.x + (double)s.y + (double)s.z)) ++nonfinite;
            if (!mft_finite((double)mf_ibm_bin_weight(&ibm, j, &bad[i]))) ++nonfinite;
        }
    MFT_CHECK(nonfinite == 0, "NaN, huge, zero-area and needle footprints: finite results everywhere");
    if (mf_ibm_brdf(&ibm, &f, down, up) != 0 || mf_ibm_brdf(&ibm, &f, up, down) != 0) ++nonzero;
    if (mf_ibm_pdf(&ibm, &f, down, up) != 0 || mf_ibm_pdf(&ibm, &f, up, down) != 0) ++nonzero;
    if (mf_ibm_brdf(&ibm, &f, zero, up) != 0 || mf_ibm_brdf(&ibm, &f, nanv, up) != 0 || mf_ibm_pdf(&ibm, &f, up, nanv) != 0) ++nonzero;
    if (mf_ibm_sample(&ibm, &f, down, MF_R(0.5), MF_R(0.5), MF_R(0.5), MF_R(0.5)).wi.z != 0) ++nonzero;
    if (mf_ibm_sample(&ibm, NULL, up, MF_R(0.5), MF_R(0.5), MF_R(0.5), MF_R(0.5)).wi.z != 0) ++nonzero;
    if (mf_ibm_brdf(&empty, &f, up, up) != 0 || mf_ibm_brdf(NULL, &f, up, up) != 0 || mf_ibm_pdf(NULL, &f, up, up) != 0) ++nonzero;
    if (mf_ibm_brdf_and_pdf(NULL, &f, up, up, &pdf) != 0 || pdf != 0 || mf_ibm_sample(NULL, &f, up, 0, 0, 0, 0).wi.z != 0) ++nonzero;
    if (mf_ibm_bin_count(NULL) != 0 || mf_ibm_bin_of(NULL, up) != -1 || mf_ibm_texel_bin(NULL, 0, 0) != -1 ||
        mf_ibm_bin_texels(&ibm, -3) != 0 || mf_ibm_memory_bytes(NULL) != 0) ++nonzero;
    MFT_CHECK(nonzero == 0, "below the horizon, NULL and empty maps: 0 and no sample");
    mf_ibm_release(&ibm);
    free(n);
}

/* the truncation of Eq. 5.13 measured: directional albedo of the IBM BRDF
 * (21 bins) against the same binned BRDF summed over every bin (Eq. 5.7) */
static void test_truncation(void)
{
    const int W = 32;
    mf_real *maps[3];
    const char *names[3] = { "flat", "smooth", "flakes" };
    mf_footprint f = fp_make(0.37, 0.52, 0.2, 0.05, -0.04, 0.22);
    double *wk = (double *)malloc(sizeof(double) * W * W), worst = 0, mean = 0;
    int m, k, cnt = 0;
    char msg[200];
    maps[0] = map_const(W, W, mf_vec3_make(0, 0, 1));
    maps[1] = map_smooth(W, W, 0.5, 91);
    maps[2] = map_flakes(W, W, 3, 0.1, 92);
    brute_texel_weights(&f, W, W, wk);
    for (m = 0; m < 3; ++m) {
        mf_ibm ibm;
        double *wb;
        mf_ibm_build(&ibm, maps[m], W, W, MF_R(0.05));
        mf_ibm_set_shadowing(&ibm, NULL);
        wb = (double *)malloc(sizeof(double) * (size_t)mf_ibm_bin_count(&ibm));
        brute_bin_sums(&ibm, wk, wb);
        for (k = 0; k < 3; ++k) {
            mf_vec3 wo = mft_dir(0.6 * k, 0.7);
            q_ctx qc;
            double at, af, tr;
            qc.ibm = &ibm; qc.f = &f; qc.wo = wo; qc.wbin = wb;
            at = h_cells(ibm.res, 1, wo, q_brdf_cos, &qc, NULL);
            af = h_cells(ibm.res, 1, wo, q_all_bins_cos, &qc, NULL);
            tr = 1 - at / af;
            if (mft_verbose) printf("    truncation %s theta_o %.1f: albedo %.5f of %.5f (%.2f%%)\n", names[m], 0.6 * k, at, af, 100 * tr);
            worst = fmax(worst, fabs(tr));
            mean += tr; ++cnt;
            if (m == 0 && k == 0) {
                /* independent: the flat map's full sum is the Beckmann albedo */
                snprintf(msg, sizeof msg, "flat map, all bins: albedo = plain Beckmann's (%.6f)", af);
                MFT_CHECK(af > 0.95 && af <= 1 + 1e-6, msg);
            }
        }
        free(wb);
        mf_ibm_release(&ibm);
    }
    snprintf(msg, sizeof msg, "truncation to the 21 bins (Eq. 5.13) loses %.2f%% of the albedo on average, at most %.2f%%", 100 * mean / cnt, 100 * worst);
    if (mft_verbose) printf("    %s\n", msg);
    MFT_CHECK(worst < 0.05 && mean / cnt > 0, msg);
    for (m = 0; m < 3; ++m) free(maps[m]);
    free(wk);
}

int test_ibm_dummy;

/* Slivers (a parallelogram 1e-6 to 1e-3 texel thick, 1 to 30 long) on a
 * checkerboard of two bins: the weights equal the fractions of the center
 * line's length in each bin (its zero-thickness limit, computed here exactly
 * from the line's crossings of the texel grid), within 2e-3 + the thickness in
 * double and 1e-2 in float, where slivers thinner than 64 ulps of the map size
 * are widened to that (before, float round-off gave weights of 500). */
static void test_slivers(void)
{
    enum { S = 64 };
    mf_real *nm = (mf_real *)malloc(sizeof(mf_real) * 3 * S * S);
    mf_ibm ibm;
    mft_rng r;
    int i, k, bad = 0, b0, b1;
    double worst = 0.0;
    for (i = 0; i < S * S; ++i) {
        int odd = ((i % S) + (i / S)) & 1;
        nm[3 * i] = odd ? MF_R(0.28) : MF_R(0.0); nm[3 * i + 1] = MF_R(0.0);
        nm[3 * i + 2] = odd ? (mf_real)sqrt(1.0 - 0.28 * 0.28) : MF_R(1.0);
    }
    MFT_CHECK(mf_ibm_build(&ibm, nm, S, S, MF_R(0.05)) == MF_SUCCESS, "slivers: checkerboard map builds");
    b0 = mf_ibm_texel_bin(&ibm, 0, 0); b1 = mf_ibm_texel_bin(&ibm, 1, 0);
    MFT_CHECK(b0 != b1, "slivers: the checkerboard has two bins");
    mft_seed(&r, 515);
    for (k = 0; k < 400; ++k) {
        double L = 1.0 + 29.0 * mft_u01(&r), th = pow(10.0, -6.0 + 3.0 * mft_u01(&r)), ang = 6.283185307 * mft_u01(&r);
        double cx = S * mft_u01(&r), cy = S * mft_u01(&r), dx = L * cos(ang), dy = L * sin(ang), ts[256], even = 0.0;
        int nt = 0, q;
        mf_footprint f;
        double w0, w1, e;
        if (k % 4 == 0) { cx = S - 1e-4 * mft_u01(&r); }   /* at the period edge */
        f.u = (mf_real)(cx / S); f.v = (mf_real)(cy / S);
        f.ax = (mf_real)(dx / S); f.ay = (mf_real)(dy / S);
        f.bx = (mf_real)(-th * sin(ang) / S); f.by = (mf_real)(th * cos(ang) / S);
        /* the line from c - d/2 to c + d/2, as the parameters where it crosses grid lines */
        cx = (double)f.u * S; cy = (double)f.v * S; dx = (double)f.ax * S; dy = (double)f.ay * S;
        ts[nt++] = 0.0; ts[nt++] = 1.0;
        for (q = (int)floor(fmin(cx - dx / 2, cx + dx / 2)); q <= (int)ceil(fmax(cx - dx / 2, cx + dx / 2)) && nt < 250; ++q)
            if (dx != 0.0) { double t = (q - (cx - dx / 2)) / dx; if (t > 0 && t < 1) ts[nt++] = t; }
        for (q = (int)floor(fmin(cy - dy / 2, cy + dy / 2)); q <= (int)ceil(fmax(cy - dy / 2, cy + dy / 2)) && nt < 250; ++q)
            if (dy != 0.0) { double t = (q - (cy - dy / 2)) / dy; if (t > 0 && t < 1) ts[nt++] = t; }
        mft_median(ts, nt);   /* sorts */
        for (q = 0; q + 1 < nt; ++q) {
            double tm = 0.5 * (ts[q] + ts[q + 1]), x = cx - dx / 2 + tm * dx, y = cy - dy / 2 + tm * dy;
            long tx = (long)floor(x), ty = (long)floor(y);
            if (((tx + ty) % 2 + 2) % 2 == 0) even += ts[q + 1] - ts[q];
        }
        w0 = mf_ibm_bin_weight(&ibm, b0, &f); w1 = mf_ibm_bin_weight(&ibm, b1, &f);
        e = fabs(w0 - even) + fabs(w1 - (1.0 - even));
        if (e > worst) worst = e;
        if (!(e <= MFT_TOL(2e-3 + 2.0 * th, 1e-2))) {
            if (bad++ < 3) printf("    sliver L=%.3g thick=%.3g: weights %.6g %.6g, line fractions %.6g %.6g\n", L, th, w0, w1, even, 1.0 - even);
        }
    }
    if (mft_verbose) printf("    slivers: worst L1 against the line fractions %.3g\n", worst);
    MFT_CHECK(bad == 0, "sliver footprints: weights are the line's length fractions");
    mf_ibm_release(&ibm);
    free(nm);
}

/* The closed-form area of a unit square cut by one line against clipping the
 * square by the half-plane in double (the general path), for random lines,
 * lines through corners and nearly axis-aligned ones. */
static double halfplane_square(double a, double b, double c)
{
    double xa[8] = { 0, 1, 1, 0 }, ya[8] = { 0, 0, 1, 1 }, xb[8], yb[8], s = 0;
    int i, m = 0;
    for (i = 0; i < 4; ++i) {
        int k = (i + 1) % 4;
        double di = a * xa[i] + b * ya[i] + c, dk = a * xa[k] + b * ya[k] + c;
        if (di >= 0) { xb[m] = xa[i]; yb[m] = ya[i]; ++m; }
        if ((di >= 0) != (dk >= 0)) {
            double t = di / (di - dk);
            xb[m] = xa[i] + t * (xa[k] - xa[i]); yb[m] = ya[i] + t * (ya[k] - ya[i]); ++m;
        }
    }
    for (i = 0; i < m; ++i) s += xb[i] * yb[(i + 1) % m] - xb[(i + 1) % m] * yb[i];
    return 0.5 * s;
}
static void test_square_cut(void)
{
    mft_rng r;
    double err = 0;
    int t, bad = 0;
    char msg[160];
    mft_seed(&r, 77);
    for (t = 0; t < 200000; ++t) {
        double ang = 2 * PI_D * mft_u01(&r), a, b, c;
        mf_real v[4], got;
        if (t % 4 == 1) ang = (double)(t % 16) * 0.5 * PI_D / 4 + 1e-7 * (mft_u01(&r) - 0.5);   /* near the axes and diagonals */
        a = cos(ang); b = sin(ang);
        c = -1.5 * mft_u01(&r) * (fabs(a) + fabs(b)) + (a < 0 ? -a : 0) * 0 + 0.75 * (fabs(a) + fabs(b)) - 0.5 * (a + b);
        if (t % 4 == 2) c = -(a * (double)(t % 2) + b * (double)((t / 2) % 2));   /* through a corner */
        v[0] = (mf_real)c; v[1] = (mf_real)(c + a); v[2] = (mf_real)(c + a + b); v[3] = (mf_real)(c + b);
        got = mf__ibm_square_cut(v);
        if (!(got >= 0 && got <= 1)) { ++bad; continue; }
        err = fmax(err, fabs((double)got - halfplane_square(a, b, c)));
    }
    snprintf(msg, sizeof msg, "closed-form area of a texel cut by one edge = clipped polygon (200000 lines, max err %.2e)", err);
    if (mft_verbose) printf("     %s\n", msg);
    MFT_CHECK(bad == 0 && err < MFT_TOL(1e-13, 3e-6), msg);
}

/* |P ∩ box| by Green's theorem (mf__ibm_green_area, mf__ibm_rect_area's
 * general case) against P clipped to the box in double, for float
 * parallelograms: random, on a quarter-texel grid (corners and edges on
 * texel lines), with vertical or horizontal edges, and cut by the lines x =
 * c and y = c (as a period's border cuts a footprint: crossings at exactly
 * c); boxes of 1 to 4 texels a side over and around each, their texels
 * clipped in double (clip_area). */
static int clip_poly_d(double *x, double *y, int n, int axis, double c, double sgn)
{
    double xo[24], yo[24];
    int i, m = 0;
    for (i = 0; i < n; ++i) {
        int k = (i + 1) % n;
        double di = sgn * ((axis ? y[i] : x[i]) - c), dk = sgn * ((axis ? y[k] : x[k]) - c);
        if (di >= 0) { xo[m] = x[i]; yo[m] = y[i]; ++m; }
        if ((di >= 0) != (dk >= 0)) {
            double t = di / (di - dk);
            xo[m] = axis ? x[i] + t * (x[k] - x[i]) : c;
            yo[m] = axis ? c : y[i] + t * (y[k] - y[i]);
            ++m;
        }
    }
    for (i = 0; i < m; ++i) { x[i] = xo[i]; y[i] = yo[i]; }
    return m;
}
static void test_green_area(void)
{
    mft_rng r;
    double err = 0;
    long boxes = 0;
    int t, cut = 0, pieces = 0;
    char msg[200];
    mft_seed(&r, 91);
    for (t = 0; t < 40000; ++t) {
        double px[24], py[24], sc = t % 3 == 0 ? 1.0 : t % 3 == 1 ? 4.0 : 0.4, cx, cy, ax, ay, bx, by, lx = 1e9, hx = -1e9, ly = 1e9, hy = -1e9;
        mf_real fx[24], fy[24];
        int n = 4, i, k, x, y;
        cx = 8 + 4 * mft_u01(&r); cy = 8 + 4 * mft_u01(&r);
        ax = sc * (2 * mft_u01(&r) - 1); ay = sc * (2 * mft_u01(&r) - 1);
        bx = sc * (2 * mft_u01(&r) - 1); by = sc * (2 * mft_u01(&r) - 1);
        if (t % 5 == 0) {   /* corners on a quarter-texel grid */
            cx = 8 + floor(16 * mft_u01(&r)) / 4; cy = 8 + floor(16 * mft_u01(&r)) / 4;
            ax = (floor(17 * mft_u01(&r)) - 8) / 4; ay = (floor(17 * mft_u01(&r)) - 8) / 4;
            bx = (floor(17 * mft_u01(&r)) - 8) / 4; by = (floor(17 * mft_u01(&r)) - 8) / 4;
        }
        if (t % 7 == 0) ax = 0;    /* a vertical edge */
        if (t % 11 == 0) ay = 0;   /* a horizontal edge */
        if (ax * by - ay * bx < 0) { ax = -ax; ay = -ay; }   /* counterclockwise */
        if (!(fabs(ax * by - ay * bx) > 1e-3)) continue;
        px[0] = cx - 0.5 * ax - 0.5 * bx; py[0] = cy - 0.5 * ay - 0.5 * by;
        px[1] = cx + 0.5 * ax - 0.5 * bx; py[1] = cy + 0.5 * ay - 0.5 * by;
        px[2] = cx + 0.5 * ax + 0.5 * bx; py[2] = cy + 0.5 * ay + 0.5 * by;
        px[3] = cx - 0.5 * ax + 0.5 * bx; py[3] = cy - 0.5 * ay + 0.5 * by;
        for (i = 0; i < 4; ++i) { px[i] = (double)(mf_real)px[i]; py[i] = (double)(mf_real)py[i]; }
        if (t % 4 == 3) {   /* cut by a period's border: x >= c or y <= c, c an integer */
            n = clip_poly_d(px, py, n, 0, floor(cx), 1.0);
            n = clip_poly_d(px, py, n, 1, ceil(cy), -1.0);
            ++cut;
        }
        for (i = k = 0; i < n; ++i) {   /* float vertices, none repeated */
            mf_real vx = (mf_real)px[i], vy = (mf_real)py[i];
            if (k > 0 && vx == fx[k - 1] && vy == fy[k - 1]) continue;
            fx[k] = vx; fy[k] = vy; ++k;
        }
        while (k > 1 && fx[k - 1] == fx[0] && fy[k - 1] == fy[0]) --k;
        if (k < 3) continue;
        n = k;
        ++pieces;
        for (i = 0; i < n; ++i) {
            px[i] = (double)fx[i]; py[i] = (double)fy[i];
            lx = fmin(lx, px[i]); hx = fmax(hx, px[i]); ly = fmin(ly, py[i]); hy = fmax(hy, py[i]);
        }
        for (y = (int)floor(ly) - 1; y <= (int)ceil(hy); ++y)
            for (x = (int)floor(lx) - 1; x <= (int)ceil(hx); ++x) {
                int W = 1 + (x + y + t) % 4, H = 1 + (x + 2 * y + t) % 3, u, v;
                double want = 0, got;
                for (v = 0; v < H; ++v)   /* the box's texels, each clipped in double */
                    for (u = 0; u < W; ++u) want += clip_area(px, py, n, x + u, y + v);
                got = (double)mf__ibm_green_area(fx, fy, n, (mf_real)x, (mf_real)y, (mf_real)W, (mf_real)H);
                err = fmax(err, fabs(got - want) / (W * H));
                ++boxes;
            }
    }
    snprintf(msg, sizeof msg, "Green's-theorem area of a polygon in a box = the polygon clipped in double (%d polygons, %d cut by a border, %ld boxes, max err %.2e of the box)",
             pieces, cut, boxes, err);
    if (mft_verbose) printf("     %s\n", msg);
    MFT_CHECK(pieces > 30000 && cut > 7000 && err < MFT_TOL(1e-13, 1e-6), msg);
}

void test_ibm(void)
{
    test_square_cut();
    test_green_area();
    test_slivers();
    test_build_errors();
    test_structure();
    test_block_lengths();
    test_weights();
    check_few_sets();
    test_texel_contribution();
    test_convergence();
    test_sampling_pdf();
    test_truncation();
    test_save_load();
    test_degenerate();
}
