/* exr_check: tools/exr_io.h round trips and the EXR paths of the IBM and
 * LEADR builders. Needs OpenEXR 3 (Core API).
 *   exr_check TMPDIR     (writes a few small .exr files there) */
#define MICROFACET_IMPLEMENTATION
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>
#include "microfacet.h"
#include "tools/exr_io.h"
#include "tools/ibm_exr.h"

static int n_pass, n_fail;
#define CHECK(cond, ...) do { if (cond) ++n_pass; else { ++n_fail; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static char dir[4096];
static const char *tmp_path(const char *name)
{
    static char buf[2][4200];
    static int k;
    k ^= 1;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

/* deterministic pseudo-random floats in [0,1) */
static unsigned int rng = 12345u;
static double urand(void) { rng = rng * 1664525u + 1013904223u; return (double)(rng >> 8) / 16777216.0; }

static void check_roundtrips(void)
{
    enum { W = 7, H = 5 };
    float img[W * H * 4], *back = NULL;
    int i, w, h, c, nch, half, bad;
    for (i = 0; i < W * H * 4; ++i) img[i] = (float)(0.01 + 100.0 * urand() * urand()) * (i % 5 == 0 ? -1.0f : 1.0f);
    for (half = 0; half <= 1; ++half)
        for (nch = 1; nch <= 4; ++nch) {
            if (nch == 2) continue;
            bad = 0;
            CHECK(mfx_exr_write(tmp_path("rt.exr"), img, W, H, nch, half) == 0, "write %d ch half=%d", nch, half);
            if (mfx_exr_read(tmp_path("rt.exr"), &back, &w, &h, &c) != 0) { CHECK(0, "read %d ch half=%d", nch, half); continue; }
            CHECK(w == W && h == H && c == nch, "size %dx%dx%d, expected %dx%dx%d", w, h, c, W, H, nch);
            if (w == W && h == H && c == nch)
                for (i = 0; i < W * H * nch; ++i) {
                    /* float: bit-exact; half: round to nearest with a 10-bit mantissa,
                     * relative error at most 2^-11 for these normal-range values */
                    double v = img[i], r = back[i];
                    if (!half ? memcmp(&img[i], &back[i], sizeof(float)) != 0 : !(fabs(r - v) <= fabs(v) * (1.0 / 2048.0)))
                        ++bad;
                }
            CHECK(bad == 0, "%d of %d values differ (%d ch, half=%d)", bad, W * H * nch, nch, half);
            free(back); back = NULL;
        }
    /* a data window away from the origin (and several chunks: 40 rows) */
    {
        static float big[9 * 40 * 3];
        for (i = 0; i < 9 * 40 * 3; ++i) big[i] = (float)urand();
        CHECK(mfx_exr_write_at(tmp_path("dw.exr"), big, 9, 40, 3, 0, 5, -17) == 0, "write shifted data window");
        if (mfx_exr_read(tmp_path("dw.exr"), &back, &w, &h, &c) == 0) {
            CHECK(w == 9 && h == 40 && c == 3 && memcmp(big, back, sizeof big) == 0, "shifted data window read back exactly");
            free(back); back = NULL;
        } else CHECK(0, "read shifted data window");
    }
    /* values exactly representable in half come back exactly */
    for (i = 0; i < W * H * 3; ++i) img[i] = (float)((i % 64) - 32) / 16.0f;
    CHECK(mfx_exr_write(tmp_path("rt_exact.exr"), img, W, H, 3, 1) == 0, "write exact half");
    if (mfx_exr_read(tmp_path("rt_exact.exr"), &back, &w, &h, &c) == 0) {
        CHECK(c == 3 && memcmp(img, back, sizeof(float) * W * H * 3) == 0, "half-representable values exact");
        free(back);
    } else CHECK(0, "read exact half");
}

/* analytic bumps: h = A sin(2 pi 2x) sin(2 pi 3y) over the unit square */
static void bumps_normals(float *n, int size, int encoded)
{
    int x, y;
    const double A = 0.02, tau = 6.283185307179586;
    for (y = 0; y < size; ++y)
        for (x = 0; x < size; ++x) {
            double u = (x + 0.5) / size, v = (y + 0.5) / size;
            double hx = A * tau * 2 * cos(tau * 2 * u) * sin(tau * 3 * v);
            double hy = A * tau * 3 * sin(tau * 2 * u) * cos(tau * 3 * v);
            double l = sqrt(hx * hx + hy * hy + 1.0), nn[3];
            int c;
            nn[0] = -hx / l; nn[1] = -hy / l; nn[2] = 1.0 / l;
            for (c = 0; c < 3; ++c) n[(y * size + x) * 3 + c] = (float)(encoded ? 0.5 * nn[c] + 0.5 : nn[c]);
        }
}

static int same_ibm(const mf_ibm *a, const mf_ibm *b)
{
    size_t na = 0, nb = 0, wa = 0, wb = 0;
    unsigned char *ba, *bb;
    int same = 0, k;
    /* buf NULL: the size query */
    if (mf_ibm_save(a, NULL, 0, &na) != MF_SUCCESS || mf_ibm_save(b, NULL, 0, &nb) != MF_SUCCESS) return 0;
    if (na == 0 || na != nb) return 0;
    ba = (unsigned char *)malloc(na); bb = (unsigned char *)malloc(nb);
    if (ba && bb && mf_ibm_save(a, ba, na, &wa) == MF_SUCCESS && mf_ibm_save(b, bb, nb, &wb) == MF_SUCCESS && wa == na && wb == nb)
        same = memcmp(ba, bb, na) == 0;
    free(ba); free(bb);
    /* and the same filtered BRDF and bin weights at a few footprints */
    for (k = 0; same && k < 4; ++k) {
        mf_real s = (mf_real)(0.02 * (1 << (2 * k)));   /* 0.02 .. 1.28 of the texture */
        mf_footprint fp;
        mf_vec3 wo = mf_normalize(mf_vec3_make(MF_R(0.3), MF_R(-0.2), MF_R(1.0)));
        mf_vec3 wi = mf_normalize(mf_vec3_make(MF_R(-0.25), MF_R(0.15), MF_R(1.0)));
        mf_real fa, fb;
        int bin;
        fp.u = MF_R(0.37); fp.v = MF_R(0.61); fp.ax = s; fp.ay = 0; fp.bx = 0; fp.by = s;
        fa = mf_ibm_brdf(a, &fp, wo, wi); fb = mf_ibm_brdf(b, &fp, wo, wi);
        if (memcmp(&fa, &fb, sizeof fa) != 0 || !(fa >= 0)) same = 0;
        for (bin = 0; bin < mf_ibm_bin_count(a); bin += 97) {
            fa = mf_ibm_bin_weight(a, bin, &fp); fb = mf_ibm_bin_weight(b, bin, &fp);
            if (memcmp(&fa, &fb, sizeof fa) != 0) same = 0;
        }
    }
    return same;
}

static void check_ibm(void)
{
    enum { S = 32 };
    static float nf[S * S * 3];
    static mf_real nr[S * S * 3];
    float *back = NULL;
    mf_real *nt = NULL, *nb = NULL;
    mf_ibm a, b;
    int i, w, h, c, enc;
    for (enc = 0; enc <= 1; ++enc) {
        const char *p = tmp_path(enc ? "normals_enc.exr" : "normals.exr");
        bumps_normals(nf, S, enc);
        CHECK(mfx_exr_write(p, nf, S, S, 3, 0) == 0, "write normal map");
        CHECK(mfx_exr_read(p, &back, &w, &h, &c) == 0 && w == S && h == S && c == 3, "read normal map");
        if (!back) continue;
        if (!enc) {
            /* builder fed the EXR data vs fed the original array */
            for (i = 0; i < S * S * 3; ++i) nr[i] = (mf_real)nf[i];
            CHECK(mf_ibm_build(&a, nr, S, S, MF_R(0.05)) == MF_SUCCESS, "build from array");
            for (i = 0; i < S * S * 3; ++i) nr[i] = (mf_real)back[i];
            CHECK(mf_ibm_build(&b, nr, S, S, MF_R(0.05)) == MF_SUCCESS, "build from EXR data");
            CHECK(same_ibm(&a, &b), "IBM from EXR data identical to IBM from the array");
            mf_ibm_release(&a); mf_ibm_release(&b);
        }
        /* the tool's path (read, renormalize, build) vs the same conversion of the array */
        CHECK(mfx_normals_from_rgb(nf, S, S, 3, enc, &nt) == MF_SUCCESS, "normals from array");
        CHECK(nt && mf_ibm_build(&a, nt, S, S, MF_R(0.01)) == MF_SUCCESS, "build (tool conversion) from array");
        CHECK(mfx_ibm_from_exr(&b, p, enc, MF_R(0.01)) == MF_SUCCESS, "mfx_ibm_from_exr encoded=%d", enc);
        CHECK(same_ibm(&a, &b), "tool path identical to array path (encoded=%d)", enc);
        mf_ibm_release(&a); mf_ibm_release(&b);
        free(nt); nt = NULL; free(back); back = NULL;
    }
    /* Y-only file: not a normal map */
    CHECK(mfx_exr_write(tmp_path("y.exr"), nf, S, S, 1, 0) == 0, "write Y");
    CHECK(mfx_ibm_from_exr(&a, tmp_path("y.exr"), 0, MF_R(0.01)) != MF_SUCCESS && a.data == NULL, "Y file rejected as normal map");
    /* a zero normal */
    for (i = 0; i < 3; ++i) nf[i] = 0.0f;
    CHECK(mfx_normals_from_rgb(nf, S, S, 3, 0, &nb) == MF_ERROR_INVALID_DATA && nb == NULL, "zero normal rejected");
}

static void check_leadr(void)
{
    enum { S = 64 };
    static float hf[S * S];
    static mf_real hr[S * S];
    float *back = NULL;
    mf_leadr_map a, b;
    int x, y, w, h, c, k, same = 1;
    for (y = 0; y < S; ++y)
        for (x = 0; x < S; ++x)
            hf[y * S + x] = (float)(0.003 * sin(6.283185307179586 * (x / (double)S) * 3) * cos(6.283185307179586 * (y / (double)S) * 2)
                                   + 0.001 * urand());
    CHECK(mfx_exr_write(tmp_path("heights.exr"), hf, S, S, 1, 0) == 0, "write height map");
    CHECK(mfx_exr_read(tmp_path("heights.exr"), &back, &w, &h, &c) == 0 && w == S && h == S && c == 1, "read height map");
    if (!back) return;
    for (x = 0; x < S * S; ++x) hr[x] = (mf_real)hf[x];
    CHECK(mf_leadr_map_from_heights(&a, hr, S, S, MF_R(0.1), MF_R(0.1)) == MF_SUCCESS, "LEADR from array");
    for (x = 0; x < S * S; ++x) hr[x] = (mf_real)back[x];
    CHECK(mf_leadr_map_from_heights(&b, hr, S, S, MF_R(0.1), MF_R(0.1)) == MF_SUCCESS, "LEADR from EXR data");
    for (k = 0; k < 40; ++k) {
        mf_real u = (mf_real)urand(), v = (mf_real)urand(), fp = (mf_real)pow(2.0, -8.0 + 9.0 * urand());
        mf_leadr la = mf_leadr_map_lookup(&a, u, v, fp), lb = mf_leadr_map_lookup(&b, u, v, fp);
        if (memcmp(&la, &lb, sizeof la) != 0) same = 0;
    }
    CHECK(same, "LEADR lookups identical (40 points, footprints 2^-8..2^1)");
    CHECK(a.levels == b.levels && a.levels == 7, "levels %d %d", a.levels, b.levels);
    mf_leadr_map_release(&a); mf_leadr_map_release(&b);
    free(back);
}

static int write_bytes(const char *p, const unsigned char *b, size_t n)
{
    FILE *f = fopen(p, "wb");
    if (!f) return 1;
    if (fwrite(b, 1, n, f) != n) { fclose(f); return 1; }
    return fclose(f) != 0;
}

static void check_bad_files(void)
{
    static float img[48 * 48 * 3];
    unsigned char *bytes = NULL;
    size_t n = 0, cut;
    float *back = NULL;
    int i, w, h, c, all = 1;
    FILE *f;
    for (i = 0; i < 48 * 48 * 3; ++i) img[i] = (float)urand();
    CHECK(mfx_exr_write(tmp_path("good.exr"), img, 48, 48, 3, 0) == 0, "write good file");
    f = fopen(tmp_path("good.exr"), "rb");
    if (f) {
        fseek(f, 0, SEEK_END); n = (size_t)ftell(f); fseek(f, 0, SEEK_SET);
        bytes = (unsigned char *)malloc(n);
        if (!bytes || fread(bytes, 1, n, f) != n) n = 0;
        fclose(f);
    }
    CHECK(n > 100, "good file read back as bytes (%lu)", (unsigned long)n);
    if (n <= 100) { free(bytes); return; }
    /* truncated at many points: every read fails cleanly */
    for (cut = 0; cut < n; cut += (cut < 400 ? 7 : 97)) {
        write_bytes(tmp_path("trunc.exr"), bytes, cut);
        if (mfx_exr_read(tmp_path("trunc.exr"), &back, &w, &h, &c) == 0 || back != NULL) { all = 0; free(back); back = NULL; }
    }
    CHECK(all, "every truncation rejected");
    /* random bytes, and random bytes after a valid magic/version */
    for (i = 0; i < (int)n; ++i) bytes[i] = (unsigned char)(urand() * 256.0);
    write_bytes(tmp_path("random.bin"), bytes, n);
    CHECK(mfx_exr_read(tmp_path("random.bin"), &back, &w, &h, &c) != 0 && back == NULL, "random bytes rejected");
    bytes[0] = 0x76; bytes[1] = 0x2f; bytes[2] = 0x31; bytes[3] = 0x01; bytes[4] = 2; bytes[5] = bytes[6] = bytes[7] = 0;
    write_bytes(tmp_path("random_magic.exr"), bytes, n);
    CHECK(mfx_exr_read(tmp_path("random_magic.exr"), &back, &w, &h, &c) != 0 && back == NULL, "random bytes after magic rejected");
    free(bytes);
    CHECK(mfx_exr_read(tmp_path("does_not_exist.exr"), &back, &w, &h, &c) != 0 && back == NULL, "missing file rejected");
    CHECK(mfx_exr_write(tmp_path("no_such_dir/x.exr"), img, 4, 4, 3, 0) != 0, "unwritable path rejected");
    CHECK(mfx_exr_write(tmp_path("x.exr"), img, 4, 4, 2, 0) != 0, "2 channels rejected");
    CHECK(mfx_exr_write(tmp_path("x.exr"), img, 0, 4, 3, 0) != 0, "zero width rejected");
    CHECK(mfx_exr_read(NULL, &back, &w, &h, &c) != 0, "NULL path rejected");
}

int main(int argc, char **argv)
{
    clock_t t0 = clock();
    if (argc < 2) { fprintf(stderr, "usage: exr_check TMPDIR\n"); return 2; }
    snprintf(dir, sizeof dir, "%s", argv[1]);
    {
        int ma = 0, mi = 0, pa = 0;
        const char *ex = NULL;
        exr_get_library_version(&ma, &mi, &pa, &ex);
        printf("exr_check (OpenEXR %d.%d.%d, mf_real %s): expected error messages follow on stderr\n",
               ma, mi, pa, sizeof(mf_real) == 8 ? "double" : "float");
    }
    check_roundtrips();
    check_ibm();
    check_leadr();
    check_bad_files();
    printf("exr_check: %.2f s CPU\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    printf("%d passed, %d failed\n", n_pass, n_fail);
    return n_fail != 0;
}
