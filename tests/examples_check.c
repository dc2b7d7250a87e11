/* Checks of the examples' image output (examples/example_common.h): the PNG
 * writer against an independent reader (table-driven CRC-32, stored-block
 * inflate, Adler-32 recomputed), the sRGB transfer function at known points,
 * the font (every printable glyph drawn, none empty but the space) and the
 * colour map (brightness grows with the value). Last line "N passed, N failed". */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include "../examples/example_common.h"

static int passed, failed;
static void check(int ok, const char *what)
{
    if (ok) ++passed;
    else { ++failed; printf("FAIL %s\n", what); }
}

static uint32_t be32(const unsigned char *p) { return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3]; }

/* CRC-32 by the usual 256-entry table (the writer computes it bit by bit) */
static uint32_t crc_table(const unsigned char *p, size_t n)
{
    static uint32_t t[256];
    uint32_t c = 0xFFFFFFFFu;
    size_t i;
    if (!t[1]) {
        uint32_t k, j, v;
        for (k = 0; k < 256; ++k) {
            for (v = k, j = 0; j < 8; ++j) v = (v & 1u) ? 0xEDB88320u ^ (v >> 1) : v >> 1;
            t[k] = v;
        }
    }
    for (i = 0; i < n; ++i) c = t[(c ^ p[i]) & 255u] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

/* Reads a PNG written by ex_write_png back into rgb; 0 on success */
static int read_png(const char *path, unsigned char *rgb, int w, int h)
{
    FILE *fp = fopen(path, "rb");
    unsigned char *d, *z = NULL, *raw = NULL;
    long n;
    size_t pos = 8, zn = 0, rn = 0, i, row = 3u * (size_t)w + 1u;
    int ok = 1, y;
    uint32_t a = 1, b = 0;
    if (!fp) return 1;
    fseek(fp, 0, SEEK_END); n = ftell(fp); fseek(fp, 0, SEEK_SET);
    d = (unsigned char *)malloc((size_t)n);
    if (!d || fread(d, 1, (size_t)n, fp) != (size_t)n) ok = 0;
    fclose(fp);
    if (ok && memcmp(d, "\x89PNG\r\n\x1a\n", 8) != 0) ok = 0;
    while (ok && pos + 12 <= (size_t)n) {
        size_t len = be32(d + pos);
        const unsigned char *type = d + pos + 4;
        if (pos + 12 + len > (size_t)n || crc_table(type, len + 4) != be32(d + pos + 8 + len)) { ok = 0; break; }
        if (!memcmp(type, "IHDR", 4)) ok = be32(type + 4) == (uint32_t)w && be32(type + 8) == (uint32_t)h && type[12] == 8 && type[13] == 2;
        if (!memcmp(type, "IDAT", 4)) { z = (unsigned char *)realloc(z, zn + len); memcpy(z + zn, type + 4, len); zn += len; }
        pos += 12 + len;
        if (!memcmp(type, "IEND", 4)) break;
    }
    raw = (unsigned char *)malloc(row * (size_t)h);
    if (ok && z && raw && zn >= 6 && z[0] == 0x78 && (z[0] * 256 + z[1]) % 31 == 0) {
        size_t p = 2;
        int last = 0;
        while (!last && ok) {   /* stored blocks only */
            size_t len;
            if (p + 5 > zn || (z[p] & 6) != 0) { ok = 0; break; }
            last = z[p] & 1;
            len = (size_t)z[p + 1] | ((size_t)z[p + 2] << 8);
            if (((len ^ ((size_t)z[p + 3] | ((size_t)z[p + 4] << 8))) & 0xFFFFu) != 0xFFFFu || p + 5 + len > zn || rn + len > row * (size_t)h) { ok = 0; break; }
            memcpy(raw + rn, z + p + 5, len);
            rn += len; p += 5 + len;
        }
        for (i = 0; i < rn; ++i) { a = (a + raw[i]) % 65521u; b = (b + a) % 65521u; }
        ok = ok && rn == row * (size_t)h && p + 4 == zn && be32(z + p) == ((b << 16) | a);
        for (y = 0; ok && y < h; ++y) {
            if (raw[(size_t)y * row] != 0) ok = 0;
            memcpy(rgb + (size_t)y * 3u * (size_t)w, raw + (size_t)y * row + 1, 3u * (size_t)w);
        }
    } else ok = 0;
    free(d); free(z); free(raw);
    return !ok;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    char path[1024];
    int sizes[3][2] = { { 1, 1 }, { 37, 11 }, { 400, 300 } }, k, i, c;
    unsigned char cm[3], prev = 0;
    /* PNG round trip at sizes with one, several and many stored blocks */
    for (k = 0; k < 3; ++k) {
        ex_image im;
        unsigned char *back;
        int w = sizes[k][0], h = sizes[k][1];
        if (ex_image_init(&im, w, h)) return 1;
        for (i = 0; i < 3 * w * h; ++i) im.lin[i] = (float)((i * 7919) % 1000) / 250.0f;
        ex_tonemap_all(&im, 1.0);
        ex_text(&im, 2, 2, 1, "GGX alpha 0.3");
        snprintf(path, sizeof path, "%s/png_check_%d.png", dir, k);
        check(ex_write_png(path, im.rgb, w, h) == 0, "PNG written");
        back = (unsigned char *)calloc((size_t)w * (size_t)h * 3u, 1);
        check(back && read_png(path, back, w, h) == 0, "PNG read back: signature, IHDR, CRC-32, stored blocks, Adler-32");
        check(back && memcmp(back, im.rgb, (size_t)w * (size_t)h * 3u) == 0, "PNG pixels identical");
        free(back);
        ex_image_free(&im);
    }
    /* sRGB transfer function at known points (IEC 61966-2-1) */
    check(ex_srgb8(0.0) == 0 && ex_srgb8(1.0) == 255 && ex_srgb8(2.0) == 255 && ex_srgb8(-1.0) == 0, "sRGB ends");
    check(ex_srgb8(0.5) == 188, "sRGB(0.5) = 188");
    check(ex_srgb8(0.18) == 118, "sRGB(0.18) = 118");
    check(ex_srgb8(0.002) == 7, "sRGB linear segment: 12.92 * 0.002 -> 7");
    /* every printable glyph draws something (the space nothing) */
    for (c = 33; c < 127; ++c) {
        int bits = 0, r;
        for (r = 0; r < 7; ++r) bits |= ex_font[c - 32][r];
        if (!bits || (c != '?' && memcmp(ex_font[c - 32], ex_font['?' - 32], 7) == 0 && !(c >= 'a' && c <= 'z'))) {
            if (!((c == '@' || c == '$' || c == '&' || c == '\\' || c == '`' || c == '{' || c == '}') && bits)) {
                printf("glyph '%c' missing\n", c);
                check(0, "glyph");
            }
        }
    }
    check(ex_font[0][0] == 0 && ex_text_width("ab", 1) == 11, "space empty, width 6 per glyph less the last gap");
    /* colour map: brightness (sum of channels) non-decreasing over [0, 1] */
    for (i = 0, k = 1; i <= 100; ++i) {
        ex_colormap_rgb(i / 100.0, cm);
        if (i > 0 && (unsigned)(cm[0] + cm[1] + cm[2]) / 3u + 1u < prev) k = 0;
        prev = (unsigned char)((cm[0] + cm[1] + cm[2]) / 3);
    }
    check(k, "colour map brightness grows with the value");
    printf("%d passed, %d failed\n", passed, failed);
    return failed != 0;
}
