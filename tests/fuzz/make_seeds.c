/* Writes the seed corpora of the fuzz targets into argv[1]/<target>/ from the
 * readable descriptions below (no committed blobs). A seed is a list of
 * items: B(n) a byte, F(x) a float's 4 little-endian bytes. */
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <sys/stat.h>

typedef struct { char kind; double v; } item;
#define B(n) { 'b', n }
#define F(x) { 'f', x }
#define END { 0, 0 }

static const char *root;

static void put(const char *target, const char *name, const item *it)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", root, target);
    mkdir(path, 0777);
    snprintf(path, sizeof path, "%s/%s/%s", root, target, name);
    f = fopen(path, "wb");
    if (!f) { perror(path); exit(1); }
    for (; it->kind; ++it) {
        if (it->kind == 'b') fputc((int)it->v & 255, f);
        else {
            float x = (float)it->v;
            unsigned char c[4];
            unsigned int u;
            memcpy(&u, &x, 4);
            c[0] = (unsigned char)u; c[1] = (unsigned char)(u >> 8); c[2] = (unsigned char)(u >> 16); c[3] = (unsigned char)(u >> 24);
            fwrite(c, 1, 4, f);
        }
    }
    fclose(f);
}

int main(int argc, char **argv)
{
    char name[64];
    int kind, tf, n;
    if (argc < 2) { fprintf(stderr, "usage: make_seeds dir\n"); return 1; }
    root = argv[1];
    mkdir(root, 0777);
    /* generic: kind, alpha_x, alpha_y, gamma, transform flags (+ their floats),
     * three directions (mode byte + xyz), u1, u2 */
    for (kind = 0; kind < 7; ++kind)
        for (tf = 0; tf < 3; ++tf) {
            item s[] = { B(kind), F(0.3), F(0.1), F(2.0), B(tf), F(-0.5), F(1), F(0.2), F(0), F(1),
                         B(3), F(0.3), F(0.1), F(0.9), B(3), F(-0.2), F(0.4), F(0.8), B(3), F(0), F(0), F(1),
                         F(0.25), F(0.75), END };
            snprintf(name, sizeof name, "k%d_t%d", kind, tf);
            put("generic", name, s);
        }
    {
        item s[] = { B(1), F(1e4), F(1e4), F(1), B(1), F(-0.5), B(1), F(1), F(0), F(1e-20), B(1), F(1), F(0), F(1e-20),
                     B(1), F(0), F(0), F(1), F(0.5), F(0.5), END };
        item t[] = { B(0), F(0.01), F(0.01), F(1), B(0), B(3), F(0), F(0), F(1), B(3), F(0), F(0), F(1), B(3), F(0), F(0), F(1),
                     F(0), F(0), END };
        put("generic", "stretched_huge", s);
        put("generic", "beckmann_normal", t);
    }
    /* ibm_load: mode 0 (a valid map with n bytes changed), and raw bytes */
    for (n = 0; n < 6; ++n) {
        item s[] = { B(0), B(n), F(17), F(200), F(3), F(40), F(60), F(1), F(99), F(7), END };
        snprintf(name, sizeof name, "m%d", n);
        put("ibm_load", name, s);
    }
    {
        item s[] = { B(1), B('M'), B('F'), B('I'), B('B'), F(1), F(2), F(3), F(4), F(5), F(6), F(7), F(8), END };
        put("ibm_load", "raw", s);
    }
    /* builders: 0 ibm, 1 tabulated, 2 leadr, 3 microsurface, 4 integrate */
    {
        item ibm[] = { B(0), B(3), B(4), B(0), F(0.2), B(0), B(128), B(128), B(128), B(140), B(130), B(120), B(100),
                       B(128), B(128), B(90), B(200), B(60), END };
        item tab[] = { B(1), B(8), B(0), B(200), B(150), B(100), B(60), B(30), B(10), B(5), B(1),
                       F(0.3), F(0.2), F(0.1), F(0.5), F(0.5), F(0.5), END };
        item lh[] = { B(2), B(2), B(2), B(0), F(0.1), F(0.1), F(0), F(0.01), F(0.02), F(0.01), F(0), F(0.03), F(0.01), F(0),
                      F(0.02), F(0.01), F(0), F(0.01), F(0), F(0.01), F(0.02), F(0.01), F(0.3), F(0.6), F(0.01), F(0.1), F(0.2), END };
        item ln[] = { B(2), B(2), B(2), B(1), F(0.1), F(0.1), B(100), B(128), B(128), B(100), B(130), B(120), B(100), B(128),
                      B(128), B(90), B(200), B(60), B(100), B(128), B(128), B(100), B(130), B(120), END };
        item mi[] = { B(3), B(1), B(2), B(0), F(0.3), F(0.3), B(1), B(2), B(3), B(4), END };
        item in[] = { B(4), B(0), F(0.1), F(-0.1), F(0.2), F(0), F(0.3), F(0.1), END };
        put("builders", "ibm", ibm); put("builders", "tabulated", tab); put("builders", "leadr_heights", lh);
        put("builders", "leadr_normals", ln); put("builders", "microsurface", mi); put("builders", "integrate", in);
    }
    /* ltc: vertex count, two-sided, mode, 9 matrix entries, vertices, w, u, table args */
    {
        item quad[] = { B(4), B(0), B(0), F(1), F(0), F(0.2), F(0), F(1), F(0), F(0.1), F(0), F(1),
                        F(-1), F(-1), F(1), F(1), F(-1), F(1), F(1), F(1), F(1), F(-1), F(1), F(1),
                        F(0), F(0), F(1), F(0.3), F(0.7), F(0.8), F(0.2), END };
        item tri[] = { B(3), B(1), B(1), F(0.5), F(0.1), F(0.2), F(0.7), F(1), F(0), F(0), F(0), F(0),
                       F(0), F(0), F(1), F(1), F(0), F(-0.5), F(0), F(1), F(2), F(0.2), F(0.1), F(1), F(0.5), F(0.5),
                       F(0.5), F(0.5), END };
        item deg[] = { B(5), B(0), B(2), F(0), F(0), F(0), F(0), F(0), F(0), F(0), F(0), F(0), F(0.5), F(0.3),
                       F(1), F(1), F(1), F(1), F(1), F(1), F(-1), F(0), F(0.001), F(0), F(-1), F(0.001), F(1e30), F(1), F(1),
                       F(0), F(0), F(1), F(0.1), F(0.9), F(0.9), F(0.04), END };
        put("ltc", "quad", quad); put("ltc", "triangle", tri); put("ltc", "degenerate", deg);
    }
    return 0;
}
