/* Shared by the examples: a small RNG, a finiteness guard, and the output of
 * an example: a linear float image (written as PFM, and as EXR when built with
 * OpenEXR) and its display version (PNG: tone mapped with the sRGB transfer
 * function, panels labelled with a built-in 5x7 bitmap font, value panels
 * through a sequential or a diverging colour map with a colour bar whose ticks
 * carry three significant digits, plot axes with tick labels). A label that
 * the image edge would cut is counted and makes ex_write fail. No dependency:
 * the PNG writer stores deflate blocks uncompressed. Include after
 * microfacet.h. */
#ifndef MF_EXAMPLE_COMMON_H
#define MF_EXAMPLE_COMMON_H

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef MF_EXAMPLE_EXR
#include "../tools/exr_io.h"
#endif

/* PCG32 (O'Neill), one stream per pixel; u in [0, 1) with 24 random bits. */
typedef struct rng { uint64_t s; } rng;
static inline uint32_t rng_next(rng *r)
{
    uint64_t old = r->s;
    uint32_t x, rot;
    r->s = old * 6364136223846793005ULL + 1442695040888963407ULL;
    x = (uint32_t)(((old >> 18) ^ old) >> 27);
    rot = (uint32_t)(old >> 59);
    return (x >> rot) | (x << ((32u - rot) & 31u));
}
static inline mf_real rng_u(rng *r) { return (mf_real)(rng_next(r) >> 8) * MF_R(5.9604644775390625e-8); }
static inline void rng_seed(rng *r, uint64_t pixel)
{
    r->s = pixel * 0x9E3779B97F4A7C15ULL + 1u;
    rng_next(r);
}

/* 1 if all three values are finite */
/* Sky radiance along the world direction d (y is up): horizon-to-zenith
 * gradient above, darker ground below, with a sharp horizon line (the
 * spheres and lobes examples) */
static inline void ex_sky(mf_vec3 d, mf_real out[3])
{
    static const mf_real hor[3] = { MF_R(1.0), MF_R(0.9), MF_R(0.75) };
    static const mf_real zen[3] = { MF_R(0.2), MF_R(0.4), MF_R(0.9) };
    static const mf_real gnd[3] = { MF_R(0.12), MF_R(0.1), MF_R(0.08) };
    int c;
    if (d.y >= MF_R(0.0)) {
        mf_real t = MF_SQRT(mf_min(d.y, MF_R(1.0)));
        for (c = 0; c < 3; ++c) out[c] = hor[c] + (zen[c] - hor[c]) * t;
    } else {
        for (c = 0; c < 3; ++c) out[c] = gnd[c] * (MF_R(1.0) + MF_R(0.5) * d.y);
    }
}
static inline int finite3(const mf_real v[3])
{
    int c;
    for (c = 0; c < 3; ++c)
        if (!(MF_FABS(v[c]) < MF_BIG)) return 0;   /* false for NaN and Inf */
    return 1;
}

/* ---- the image of an example: linear RGB (top row first) and its display */
typedef struct ex_image {
    int w, h;
    float *lin;            /* w * h * 3, linear radiance: PFM and EXR */
    unsigned char *rgb;    /* w * h * 3, display: PNG */
    int cut;               /* labels that the image edge cut (ex_write fails on any) */
    char first_cut[64];    /* the first of them */
} ex_image;

static inline int ex_image_init(ex_image *im, int w, int h)
{
    im->w = w; im->h = h; im->cut = 0; im->first_cut[0] = 0;
    im->lin = (float *)calloc((size_t)w * (size_t)h * 3u, sizeof(float));
    im->rgb = (unsigned char *)calloc((size_t)w * (size_t)h * 3u, 1);
    if (im->lin && im->rgb) return 0;
    free(im->lin); free(im->rgb);
    im->lin = NULL; im->rgb = NULL;
    fprintf(stderr, "out of memory\n");
    return 1;
}
static inline void ex_image_free(ex_image *im) { free(im->lin); free(im->rgb); im->lin = NULL; im->rgb = NULL; }
static inline float *ex_px(ex_image *im, int x, int y) { return im->lin + 3 * ((size_t)y * (size_t)im->w + (size_t)x); }

/* sRGB transfer function (IEC 61966-2-1) of a value clamped to [0, 1], to 8 bits */
static inline unsigned char ex_srgb8(double v)
{
    v = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
    v = v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
    return (unsigned char)(v * 255.0 + 0.5);
}

/* Display of the rectangle (x0, y0, w, h): exposure, then Reinhard c / (1 + c)
 * per channel, then the sRGB transfer function. */
static inline void ex_tonemap(ex_image *im, int x0, int y0, int w, int h, double exposure)
{
    int x, y, c;
    for (y = y0; y < y0 + h && y < im->h; ++y)
        for (x = x0; x < x0 + w && x < im->w; ++x)
            for (c = 0; c < 3; ++c) {
                size_t i = 3 * ((size_t)y * (size_t)im->w + (size_t)x) + (size_t)c;
                double v = exposure * (double)im->lin[i];
                im->rgb[i] = ex_srgb8(v > 0.0 ? v / (1.0 + v) : 0.0);
            }
}
static inline void ex_tonemap_all(ex_image *im, double exposure) { ex_tonemap(im, 0, 0, im->w, im->h, exposure); }

/* Display of a rectangle holding display values already (false colour,
 * plots): each value in [0, 1] to 8 bits as it is. */
static inline void ex_direct(ex_image *im, int x0, int y0, int w, int h)
{
    int x, y, c;
    for (y = y0; y < y0 + h && y < im->h; ++y)
        for (x = x0; x < x0 + w && x < im->w; ++x)
            for (c = 0; c < 3; ++c) {
                size_t i = 3 * ((size_t)y * (size_t)im->w + (size_t)x) + (size_t)c;
                double v = (double)im->lin[i];
                im->rgb[i] = (unsigned char)((v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0) * 255.0 + 0.5);
            }
}

/* Colour map for values in [0, 1]: black, blue, magenta, orange, pale yellow
 * (piecewise linear in sRGB; brightness grows monotonically). */
static inline void ex_colormap_rgb(double t, unsigned char out[3])
{
    static const double k[5][3] = { { 0, 0, 0 }, { 40, 30, 150 }, { 190, 40, 130 }, { 250, 150, 40 }, { 255, 250, 190 } };
    int i, c;
    double s;
    t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
    s = t * 4.0;
    i = (int)s;
    if (i > 3) i = 3;
    s -= (double)i;
    for (c = 0; c < 3; ++c) out[c] = (unsigned char)(k[i][c] + s * (k[i + 1][c] - k[i][c]) + 0.5);
}

/* Diverging colour map for signed values, t in [0, 1] with 0.5 standing for
 * zero: near black at 0.5, through blue to pale cyan toward 0 (negative) and
 * through red-brown to pale orange toward 1 (positive); brightness grows with
 * |t - 0.5| the same way on both sides, so small errors stay dark either way. */
static inline void ex_diverging_rgb(double t, unsigned char out[3])
{
    static const double neg[3][3] = { { 18, 18, 18 }, { 30, 80, 190 }, { 170, 225, 255 } };
    static const double pos[3][3] = { { 18, 18, 18 }, { 190, 70, 30 }, { 255, 225, 150 } };
    const double (*k)[3];
    double s;
    int i, c;
    t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
    s = 2.0 * (t - 0.5);
    k = s < 0.0 ? neg : pos;
    s = 2.0 * (s < 0.0 ? -s : s);   /* [0, 2]: two linear pieces */
    i = s < 1.0 ? 0 : 1;
    s -= (double)i;
    for (c = 0; c < 3; ++c) out[c] = (unsigned char)(k[i][c] + s * (k[i + 1][c] - k[i][c]) + 0.5);
}

/* a colour map: value in [0, 1] to 8-bit RGB */
typedef void (*ex_cmap_fn)(double t, unsigned char out[3]);

/* Display of a value panel: the channel mean of the linear image over vmax,
 * through the colour map. */
static inline void ex_colormap(ex_image *im, int x0, int y0, int w, int h, double vmax)
{
    int x, y;
    for (y = y0; y < y0 + h && y < im->h; ++y)
        for (x = x0; x < x0 + w && x < im->w; ++x) {
            size_t i = 3 * ((size_t)y * (size_t)im->w + (size_t)x);
            double v = ((double)im->lin[i] + (double)im->lin[i + 1] + (double)im->lin[i + 2]) / 3.0;
            ex_colormap_rgb(vmax > 0.0 ? v / vmax : 0.0, im->rgb + i);
        }
}

/* ---- text: a 5x7 font for ASCII 32..126 (lower case drawn as upper case),
 * one byte per row, bit 4 the leftmost pixel; ex_text draws '|' one row
 * above and two below the capitals, so that it does not read as an I */
static const unsigned char ex_font[95][7] = {
    {0,0,0,0,0,0,0}, {4,4,4,4,4,0,4}, {10,10,0,0,0,0,0}, {10,10,31,10,31,10,10}, {4,15,20,14,5,30,4}, {24,25,2,4,8,19,3}, {12,18,20,8,21,18,13}, {4,4,8,0,0,0,0},
    {4,8,8,8,8,8,4}, {4,2,2,2,2,2,4}, {0,4,21,14,21,4,0}, {0,4,4,31,4,4,0}, {0,0,0,0,12,4,8}, {0,0,0,31,0,0,0}, {0,0,0,0,0,12,12}, {0,1,2,4,8,16,0},
    {14,17,19,21,25,17,14}, {4,12,4,4,4,4,14}, {14,17,1,2,4,8,31}, {31,2,4,2,1,17,14}, {2,6,10,18,31,2,2}, {31,16,30,1,1,17,14}, {6,8,16,30,17,17,14}, {31,1,2,4,8,8,8},
    {14,17,17,14,17,17,14}, {14,17,17,15,1,2,12}, {0,12,12,0,12,12,0}, {0,12,12,0,12,4,8}, {2,4,8,16,8,4,2}, {0,0,31,0,31,0,0}, {8,4,2,1,2,4,8}, {14,17,1,2,4,0,4},
    {14,17,23,21,23,16,15}, {14,17,17,31,17,17,17}, {30,17,17,30,17,17,30}, {14,17,16,16,16,17,14}, {30,17,17,17,17,17,30}, {31,16,16,30,16,16,31}, {31,16,16,30,16,16,16}, {14,17,16,23,17,17,15},
    {17,17,17,31,17,17,17}, {14,4,4,4,4,4,14}, {7,2,2,2,2,18,12}, {17,18,20,24,20,18,17}, {16,16,16,16,16,16,31}, {17,27,21,21,17,17,17}, {17,17,25,21,19,17,17}, {14,17,17,17,17,17,14},
    {30,17,17,30,16,16,16}, {14,17,17,17,21,18,13}, {30,17,17,30,20,18,17}, {15,16,16,14,1,1,30}, {31,4,4,4,4,4,4}, {17,17,17,17,17,17,14}, {17,17,17,17,17,10,4}, {17,17,17,21,21,21,10},
    {17,17,10,4,10,17,17}, {17,17,10,4,4,4,4}, {31,1,2,4,8,16,31}, {14,8,8,8,8,8,14}, {0,16,8,4,2,1,0}, {14,2,2,2,2,2,14}, {4,10,17,0,0,0,0}, {0,0,0,0,0,0,31},
    {8,4,2,0,0,0,0}, {14,17,17,31,17,17,17}, {30,17,17,30,17,17,30}, {14,17,16,16,16,17,14}, {30,17,17,17,17,17,30}, {31,16,16,30,16,16,31}, {31,16,16,30,16,16,16}, {14,17,16,23,17,17,15},
    {17,17,17,31,17,17,17}, {14,4,4,4,4,4,14}, {7,2,2,2,2,18,12}, {17,18,20,24,20,18,17}, {16,16,16,16,16,16,31}, {17,27,21,21,17,17,17}, {17,17,25,21,19,17,17}, {14,17,17,17,17,17,14},
    {30,17,17,30,16,16,16}, {14,17,17,17,21,18,13}, {30,17,17,30,20,18,17}, {15,16,16,14,1,1,30}, {31,4,4,4,4,4,4}, {17,17,17,17,17,17,14}, {17,17,17,17,17,10,4}, {17,17,17,21,21,21,10},
    {17,17,10,4,10,17,17}, {17,17,10,4,4,4,4}, {31,1,2,4,8,16,31}, {2,4,4,8,4,4,2}, {4,4,4,4,4,4,4}, {8,4,4,2,4,4,8}, {0,0,8,21,2,0,0},
};

/* Darkens the rectangle (behind text, for legibility on any background) */
static inline void ex_shade(ex_image *im, int x0, int y0, int w, int h)
{
    int x, y, c;
    for (y = y0 < 0 ? 0 : y0; y < y0 + h && y < im->h; ++y)
        for (x = x0 < 0 ? 0 : x0; x < x0 + w && x < im->w; ++x)
            for (c = 0; c < 3; ++c) {
                unsigned char *p = im->rgb + 3 * ((size_t)y * (size_t)im->w + (size_t)x) + c;
                *p = (unsigned char)(*p * 3 / 10);
            }
}

/* Width in pixels of a string at the given scale */
static inline int ex_text_width(const char *s, int scale) { return (int)strlen(s) * 6 * scale - scale; }

/* Draws s at (x, y) (top left) in white on a darkened box, 11 x (6 n + 3)
 * pixels at scale 1 from (x - 2, y - 2); scale 1 = 5x7. A box that the image
 * edge cuts counts in im->cut. */
static inline void ex_text(ex_image *im, int x, int y, int scale, const char *s)
{
    int i, gx, gy, sx, sy, bw = ex_text_width(s, scale) + 4 * scale;
    if ((x - 2 * scale < 0 || y - 2 * scale < 0 || x - 2 * scale + bw > im->w || y + 9 * scale > im->h) && !im->cut++) {
        size_t n = strlen(s) < sizeof im->first_cut ? strlen(s) : sizeof im->first_cut - 1;
        memcpy(im->first_cut, s, n);
        im->first_cut[n] = 0;
    }
    ex_shade(im, x - 2 * scale, y - 2 * scale, bw, 11 * scale);
    for (i = 0; s[i]; ++i) {
        int ch = (unsigned char)s[i];
        const unsigned char *g = ex_font[(ch >= 32 && ch < 127 ? ch : '?') - 32];
        int bar = ch == '|';   /* rows -1..8 instead of 0..6 */
        for (gy = -bar; gy < 7 + 2 * bar; ++gy)
            for (gx = 0; gx < 5; ++gx) {
                if (!(bar ? gx == 2 : (g[gy] & (16 >> gx)) != 0)) continue;
                for (sy = 0; sy < scale; ++sy)
                    for (sx = 0; sx < scale; ++sx) {
                        int px = x + (6 * i + gx) * scale + sx, py = y + gy * scale + sy;
                        if (px >= 0 && px < im->w && py >= 0 && py < im->h)
                            memset(im->rgb + 3 * ((size_t)py * (size_t)im->w + (size_t)px), 255, 3);
                    }
            }
    }
}

/* printf-style label */
static inline void ex_label(ex_image *im, int x, int y, int scale, const char *fmt, ...)
{
    char buf[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    ex_text(im, x, y, scale, buf);
}

/* Draws a filled rectangle of one display colour (clipped to the image). */
static inline void ex_fill(ex_image *im, int x0, int y0, int w, int h, const unsigned char c[3])
{
    int x, y;
    for (y = y0 < 0 ? 0 : y0; y < y0 + h && y < im->h; ++y)
        for (x = x0 < 0 ? 0 : x0; x < x0 + w && x < im->w; ++x)
            memcpy(im->rgb + 3 * ((size_t)y * (size_t)im->w + (size_t)x), c, 3);
}

/* A tick label: "0" for values within 1e-9 of the range of zero (no
 * "-1.39e-17"); else three significant digits, trailing zeros kept
 * ("%#.3g": 1.10, 0.500) when exact is set (a data value such as a
 * maximum), dropped ("%.3g": 0.25, 1) for round axis steps. */
static inline void ex_tick_text(char *buf, size_t n, double v, double range, int exact)
{
    if (v < 0.0 ? -v < 1e-9 * range : v < 1e-9 * range) snprintf(buf, n, "0");
    else snprintf(buf, n, exact ? "%#.3g" : "%.3g", v);
}

/* A horizontal colour bar at (x, y), w x h pixels, for values vmin..vmax
 * through the colour map, with tick marks and labels (three significant
 * digits, trailing zeros kept) at both ends and in the middle, and the
 * label (what the values are) above it. The bar takes 12 pixels above it
 * and 14 below. */
static inline void ex_colorbar_map(ex_image *im, int x, int y, int w, int h, double vmin, double vmax, ex_cmap_fn map,
                                   const char *label)
{
    static const unsigned char white[3] = { 255, 255, 255 };
    int i, k;
    char buf[64];
    for (i = 0; i < w; ++i) {
        unsigned char c[3];
        map((double)i / (double)(w - 1), c);
        ex_fill(im, x + i, y, 1, h, c);
    }
    for (k = 0; k < 3; ++k) {
        int tx = x + k * (w - 1) / 2, lx;
        ex_fill(im, tx, y + h, 1, 3, white);
        ex_tick_text(buf, sizeof buf, vmin + (vmax - vmin) * 0.5 * (double)k, vmax - vmin, 1);
        lx = tx - (k == 0 ? 0 : k == 1 ? ex_text_width(buf, 1) / 2 : ex_text_width(buf, 1) - 1);
        ex_text(im, lx, y + h + 5, 1, buf);
    }
    ex_text(im, x, y - 12, 1, label);
}

/* The same for values 0..vmax through the sequential colour map. */
static inline void ex_colorbar(ex_image *im, int x, int y, int w, int h, double vmax, const char *label)
{
    ex_colorbar_map(im, x, y, w, h, 0.0, vmax, ex_colormap_rgb, label);
}

/* A "nice" tick step for an axis spanning `range`: 1, 2, 2.5 or 5 times a
 * power of ten, giving about n intervals. */
static inline double ex_nice_step(double range, int n)
{
    double raw = range / (double)(n > 0 ? n : 1), p = pow(10.0, floor(log10(raw))), f = raw / p;
    return (f < 1.5 ? 1.0 : f < 2.25 ? 2.0 : f < 3.5 ? 2.5 : f < 7.5 ? 5.0 : 10.0) * p;
}

/* ---- writers */
static inline void ex_put_be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24); p[1] = (unsigned char)(v >> 16); p[2] = (unsigned char)(v >> 8); p[3] = (unsigned char)v;
}
static inline uint32_t ex_crc32(uint32_t crc, const unsigned char *p, size_t n)
{
    size_t i;
    int k;
    crc = ~crc;
    for (i = 0; i < n; ++i) {
        crc ^= p[i];
        for (k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}
/* one PNG chunk: length, type, data, CRC of type and data */
static inline void ex_png_chunk(FILE *fp, const char *type, const unsigned char *data, size_t n)
{
    unsigned char b[4];
    uint32_t crc = ex_crc32(0, (const unsigned char *)type, 4);
    if (n) crc = ex_crc32(crc, data, n);
    ex_put_be32(b, (uint32_t)n); fwrite(b, 1, 4, fp);
    fwrite(type, 1, 4, fp);
    if (n) fwrite(data, 1, n, fp);
    ex_put_be32(b, crc); fwrite(b, 1, 4, fp);
}

/* PNG (RFC 2083): 8-bit RGB, filter 0 on every row, the zlib stream (RFC 1950)
 * made of stored deflate blocks (RFC 1951, BTYPE 00) of up to 65535 bytes. */
static inline int ex_write_png(const char *path, const unsigned char *rgb, int w, int h)
{
    size_t row = 3u * (size_t)w + 1u, raw = row * (size_t)h, nblk = (raw + 65534u) / 65535u;
    size_t zn = 2u + raw + 5u * (nblk ? nblk : 1u) + 4u, pos = 0, done = 0, i;
    unsigned char *z = (unsigned char *)malloc(zn), ihdr[13];
    uint32_t a = 1, b = 0;
    FILE *fp;
    if (!z) { fprintf(stderr, "%s: out of memory\n", path); return 1; }
    z[pos++] = 0x78; z[pos++] = 0x01;
    while (done < raw || (raw == 0 && done == 0)) {
        size_t n = raw - done < 65535u ? raw - done : 65535u;
        z[pos++] = (unsigned char)(done + n == raw);   /* BFINAL, BTYPE 00 */
        z[pos++] = (unsigned char)(n & 255u); z[pos++] = (unsigned char)(n >> 8);
        z[pos++] = (unsigned char)(~n & 255u); z[pos++] = (unsigned char)((~n >> 8) & 255u);
        for (i = 0; i < n; ++i, ++done) {
            size_t y = done / row, x = done % row;
            unsigned char v = x == 0 ? 0 : rgb[y * 3u * (size_t)w + x - 1u];
            z[pos++] = v;
            a = (a + v) % 65521u; b = (b + a) % 65521u;   /* Adler-32 */
        }
        if (raw == 0) break;
    }
    ex_put_be32(z + pos, (b << 16) | a); pos += 4;
    ex_put_be32(ihdr, (uint32_t)w); ex_put_be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8; ihdr[9] = 2; ihdr[10] = ihdr[11] = ihdr[12] = 0;   /* 8 bit, RGB */
    fp = fopen(path, "wb");
    if (!fp) { perror(path); free(z); return 1; }
    fwrite("\x89PNG\r\n\x1a\n", 1, 8, fp);
    ex_png_chunk(fp, "IHDR", ihdr, 13);
    ex_png_chunk(fp, "IDAT", z, pos);
    ex_png_chunk(fp, "IEND", NULL, 0);
    free(z);
    return fclose(fp) != 0;
}

/* Little-endian float32 regardless of the host byte order. */
static inline void put_f32(FILE *fp, float v)
{
    uint32_t u;
    memcpy(&u, &v, 4);
    fputc((int)(u & 255u), fp); fputc((int)((u >> 8) & 255u), fp);
    fputc((int)((u >> 16) & 255u), fp); fputc((int)(u >> 24), fp);
}

/* PFM: rows bottom to top, negative scale = little-endian */
static inline int ex_write_pfm(const char *path, const float *img, int w, int h)
{
    FILE *fp = fopen(path, "wb");
    int i, y;
    if (!fp) { perror(path); return 1; }
    fprintf(fp, "PF\n%d %d\n-1.0\n", w, h);
    for (y = h - 1; y >= 0; --y)
        for (i = 0; i < 3 * w; ++i) put_f32(fp, img[3 * (size_t)w * (size_t)y + (size_t)i]);
    return fclose(fp) != 0;
}

/* Writes base.png (the display), base.pfm (linear) and, built with OpenEXR,
 * base.exr (linear, half float); prints each file written. 0 on success. */
static inline int ex_write(const ex_image *im, const char *base)
{
    char path[1024];
    int err = 0;
    if (im->cut) {
        fprintf(stderr, "%s: %d label(s) cut by the image edge, the first \"%s\"\n", base, im->cut, im->first_cut);
        err = 1;
    }
    snprintf(path, sizeof path, "%s.png", base);
    if (ex_write_png(path, im->rgb, im->w, im->h)) err = 1; else printf("wrote %s (%d x %d, labelled)\n", path, im->w, im->h);
    snprintf(path, sizeof path, "%s.pfm", base);
    if (ex_write_pfm(path, im->lin, im->w, im->h)) err = 1; else printf("wrote %s (linear)\n", path);
#ifdef MF_EXAMPLE_EXR
    snprintf(path, sizeof path, "%s.exr", base);
    if (mfx_exr_write(path, im->lin, im->w, im->h, 3, 1)) err = 1; else printf("wrote %s (linear, half)\n", path);
#endif
    return err;
}

#endif
