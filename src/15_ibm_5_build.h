/* @optional MF_NO_IBM */
/* @api */
/* ======================================================================== */
/* == 15e. Inverse Bin Map: build, save, load                               */
/* ======================================================================== */
/* The builder of the packed array of 15_ibm_1_format.h from a normal map,
 * and its save and load (validated: a loaded map is safe to query). */
/* ---- Inverse Bin Map: builder, queries, filtered BRDF ---- */
#define MF_IBM_MIN_CUT MF_R(0.1)
/* Builds the Inverse Bin Map of a normal map (Sec. 5.4): normals_xyz holds
 * width*height unit normals (x, y, z; z > 0, length within 1e-3 of 1;
 * normalized before binning), row-major, texel (x, y) at index y*width + x.
 * flake_alpha is the Beckmann flake roughness (clamped to [MF_ALPHA_MIN,
 * MF_ALPHA_MAX] and rounded to float, so that a saved map reloads
 * bit-identically); the bin resolution is b = floor(5 / sin(theta0)),
 * theta0 = atan(3 sigma), sigma = alpha / sqrt(2) (Eq. 5.14), at most
 * MF_IBM_MAX_RES. mf_ibm_build_ex also takes options (NULL or all-zero:
 * the defaults): the resolution b (0: Eq. 5.14) and the cut in sigmas (0: 3,
 * else in [MF_IBM_MIN_CUT, 10]: a cut that rounds to 0 in float would not
 * reload); the neighbourhood radius r grows with b so
 * that the bins around h cover the cut cone: r = max(2, ceil(b sin(theta0)/2
 * - 1/2)), at most MF_IBM_MAX_RADIUS (r = 2, the 21 bins, at the default b).
 * width and height in [1, 16384]; powers of two build fastest. Errors: NULL,
 * sizes, alpha <= 0 or NaN, resolution or cut out of range
 * (MF_ERROR_INVALID_ARGUMENT); a NaN, non-unit or below-horizon normal
 * (MF_ERROR_INVALID_DATA); allocation (MF_ERROR_OUT_OF_MEMORY). Nothing stays
 * allocated on failure, and *ibm is zeroed. Cost: two passes over the
 * normals (binning in 8 x 8 tiles, then a counting sort in Morton order)
 * and the kd-tree tops (timings: docs/PERFORMANCE.md, `make bench`). */
typedef struct mf_ibm_options {
    int resolution;          /* bins per axis b; 0: Eq. 5.14 */
    mf_real cut_sigmas;      /* the lobe's cut in sigmas; 0: 3 */
} mf_ibm_options;
MFDEF mf_result mf_ibm_build(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha);
MFDEF mf_result mf_ibm_build_ex(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha,
                                const mf_ibm_options *options);
MFDEF void mf_ibm_release(mf_ibm *ibm);
/* Bytes held: the single integer array (ibm->words * 4). */
MFDEF size_t mf_ibm_memory_bytes(const mf_ibm *ibm);
/* Save and load (no stdio): mf_ibm_save writes the bytes the map needs to
 * *bytes and copies the integer array (native byte order) to buf when cap is
 * large enough. buf NULL: a size query (MF_SUCCESS); cap too small:
 * MF_ERROR_BUFFER_TOO_SMALL, nothing written; an empty map or NULL:
 * MF_ERROR_INVALID_ARGUMENT, *bytes = 0. mf_ibm_load copies such a buffer (any alignment) into
 * a new map after validating everything a query reads: magic, version, sizes,
 * a checksum, the index, every texel position (in range, sorted, each texel
 * exactly once, in the bin the bin map gives it) and the bin map; a corrupted
 * or foreign buffer gives MF_ERROR_INVALID_DATA and nothing allocated.
 * mf_ibm_set_shadowing is not saved: set it again after loading. */
MFDEF mf_result mf_ibm_save(const mf_ibm *ibm, void *buf, size_t cap, size_t *bytes);
MFDEF mf_result mf_ibm_load(mf_ibm *ibm, const void *buf, size_t bytes);
/* @impl */
/* ---- Inverse Bin Map ---- */

/* mf_real <-> float bits, without a header for memcpy */
static unsigned int mf__ibm_fbits(mf_real v)
{
    float f = (float)v;
    unsigned int u = 0u;
    const unsigned char *s = (const unsigned char *)&f;
    unsigned char *d = (unsigned char *)&u;
    size_t i;
    for (i = 0; i < sizeof(float) && i < sizeof(unsigned int); ++i) d[i] = s[i];
    return u;
}
static mf_real mf__ibm_bitsf(unsigned int u)
{
    float f = 0.0f;
    const unsigned char *s = (const unsigned char *)&u;
    unsigned char *d = (unsigned char *)&f;
    size_t i;
    for (i = 0; i < sizeof(float) && i < sizeof(unsigned int); ++i) d[i] = s[i];
    return (mf_real)f;
}

static int mf__ibm_bitlen(size_t v)
{
    int n = 0;
    while (v) { ++n; v >>= 1; }
    return n;
}

/* ORs v (< 2^w) into field i (w bits) of a zeroed packed array; the word
 * after the field's first gets the bits past it, none when the field ends
 * inside (no branch: every packed section ends with a spare word) */
MF_INLINE void mf__ibm_put(unsigned int *base, size_t i, int w, unsigned int v)
{
    size_t bit = i * (size_t)w;
    unsigned int *p = base + (bit >> 5), s = (unsigned int)(bit & 31u);
    p[0] |= v << s;
    p[1] |= (v >> 1) >> (31u - s);
}

/* 1 if a and b have the same bits (not ==, which -ffast-math may let hold
 * for a NaN) */
static int mf__ibm_same_bits(mf_real a, mf_real b)
{
    union { mf_real f; unsigned int u[sizeof(mf_real) / sizeof(unsigned int)]; } x, y;
    unsigned int d = 0u;
    size_t i;
    x.f = a; y.f = b;
    for (i = 0; i < sizeof(mf_real) / sizeof(unsigned int); ++i) d |= x.u[i] ^ y.u[i];
    return d == 0u;
}

/* A sequential writer of w-bit fields into a zeroed packed array: fields
 * gather in acc and reach memory one word at a time (no read-modify-write
 * chain per field); flush ORs the partial last word (a spare word ends
 * every packed section, so it may be the word past the last field). */
typedef struct mf__ibm_writer { unsigned int *p, acc, fill, w; } mf__ibm_writer;
MF_INLINE void mf__ibm_writer_at(mf__ibm_writer *r, unsigned int *base, size_t i, int w)
{
    size_t bit = i * (size_t)w;
    r->p = base + (bit >> 5);
    r->fill = (unsigned int)(bit & 31u);
    r->acc = 0u;
    r->w = (unsigned int)w;
}
MF_INLINE void mf__ibm_writer_push(mf__ibm_writer *r, unsigned int v)
{
    r->acc |= v << r->fill;
    r->fill += r->w;
    if (r->fill >= 32u) {   /* a word is complete; the field's rest starts the next */
        *r->p++ |= r->acc;
        r->fill -= 32u;
        r->acc = r->fill ? v >> (r->w - r->fill) : 0u;
    }
}
MF_INLINE void mf__ibm_writer_flush(mf__ibm_writer *r) { *r->p |= r->acc; }

/* The derived fields of a map from its header values; returns the word count
 * (0 if the sizes are out of range). */
static size_t mf__ibm_layout(mf_ibm *ibm, int width, int height, int res, int radius, unsigned int list_len)
{
    size_t n, bins, words;
    if (width < 1 || width > 16384 || height < 1 || height > 16384 || res < 1 || res > MF_IBM_MAX_RES ||
        radius < 0 || radius > MF_IBM_MAX_RADIUS || list_len < (unsigned int)width * (unsigned int)height ||
        list_len > 0x7fffffffu)
        return 0;
    n = (size_t)width * (size_t)height;
    bins = (size_t)res * (size_t)res;
    ibm->width = width; ibm->height = height; ibm->res = res; ibm->radius = radius;
    ibm->kx = mf__ibm_bitlen((size_t)width - 1u);
    ibm->ky = mf__ibm_bitlen((size_t)height - 1u);
    ibm->list_len = list_len;
    ibm->off_bits = mf__ibm_bitlen(list_len);
    ibm->pos_bits = ibm->kx + ibm->ky > 0 ? ibm->kx + ibm->ky : 1;
    ibm->list_bits = ibm->pos_bits;   /* inner boundaries are below 2^pos_bits too */
    ibm->axis_bits = res > 1 ? mf__ibm_bitlen((size_t)res - 1u) : 1;
    ibm->bin_bits = 2 * ibm->axis_bits;
    ibm->off_at = MF__IBM_HEADER;
    ibm->mean_at = ibm->off_at + ((bins + 1u) * (size_t)ibm->off_bits + 31u) / 32u + 1u;
    ibm->pos_at = ibm->mean_at + bins;
    ibm->bin_at = ibm->pos_at + ((size_t)list_len * (size_t)ibm->list_bits + 31u) / 32u + 1u;
    words = ibm->bin_at + (n * (size_t)ibm->bin_bits + 31u) / 32u + 2u;   /* two spare words (mf__ibm_get) */
    if (words >= (size_t)0xffffffffu) return 0;
    return words;
}

static void mf__ibm_set_fields(mf_ibm *ibm)
{
    const unsigned int *h = ibm->data;
    ibm->alpha = mf__ibm_bitsf(h[7]);
    ibm->cut = mf__ibm_bitsf(h[8]);
    ibm->shadow_ax = mf__ibm_bitsf(h[9]);
    ibm->shadow_ay = mf__ibm_bitsf(h[10]);
    ibm->shadow = mf_beckmann(ibm->shadow_ax, ibm->shadow_ay);
    ibm->has_shadow = 1;
}

static void mf__ibm_zero(mf_ibm *ibm)
{
    ibm->data = 0; ibm->words = 0;
    ibm->width = ibm->height = ibm->res = ibm->radius = ibm->kx = ibm->ky = 0;
    ibm->off_bits = ibm->pos_bits = ibm->list_bits = ibm->bin_bits = ibm->axis_bits = 0;
    ibm->list_len = 0u;
    ibm->off_at = ibm->mean_at = ibm->pos_at = ibm->bin_at = 0;
    ibm->alpha = ibm->cut = ibm->shadow_ax = ibm->shadow_ay = MF_R(0.0);
    ibm->has_shadow = 0;
    ibm->shadow = mf_beckmann(MF_R(1.0), MF_R(1.0));
}

/* the resolution (Eq. 5.14) and the neighbourhood radius for a cut */
static void mf__ibm_resolution(mf_real alpha, mf_real cut, int resolution, int *res, int *radius)
{
    mf_real cs = cut * alpha / MF_SQRT(MF_R(2.0));              /* tan(theta0), theta0 = atan(cut sigma) */
    mf_real s0 = cs / MF_SQRT(MF_R(1.0) + cs * cs), r;          /* sin(theta0) */
    if (resolution > 0) *res = resolution;
    else {
        mf_real b = MF_FLOOR(MF_R(5.0) / s0);                   /* Eq. 5.14 */
        *res = !(b < (mf_real)MF_IBM_MAX_RES) ? MF_IBM_MAX_RES : (b < MF_R(1.0) ? 1 : (int)b);
    }
    r = MF_CEIL((mf_real)*res * s0 * MF_R(0.5) - MF_R(0.5));
    *radius = r > MF_R(2.0) ? (r < (mf_real)MF_IBM_MAX_RADIUS ? (int)r : MF_IBM_MAX_RADIUS) : 2;
}

MFDEF mf_result mf_ibm_build_ex(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha,
                                const mf_ibm_options *options)
{
    int resolution = options ? options->resolution : 0;
    mf_real cut_sigmas = options ? options->cut_sigmas : MF_R(0.0);
    mf_ibm L;
    size_t n, bins, words, i, ncodes, bmw;
    unsigned int *data = 0, *cur = 0, *st = 0, *list, *bmap = 0, *t32 = 0, start = 0u, bad = 0u, none;
    unsigned short *t16 = 0;
    void *tmp = 0;
    double *sums = 0, sxx = 0.0, syy = 0.0;
    unsigned char tile[64];
    mf_real alpha, cut;
    int res, radius, x, y, kmin;
    if (!ibm) return MF_ERROR_INVALID_ARGUMENT;
    mf__ibm_zero(ibm);
    mf__ibm_zero(&L);
    if (!normals_xyz || width < 1 || width > 16384 || height < 1 || height > 16384 || !(flake_alpha > MF_R(0.0)) ||
        resolution < 0 || resolution > MF_IBM_MAX_RES || !(cut_sigmas >= MF_R(0.0)) || !(cut_sigmas <= MF_R(10.0)) ||
        (cut_sigmas > MF_R(0.0) && cut_sigmas < MF_IBM_MIN_CUT))
        return MF_ERROR_INVALID_ARGUMENT;
    alpha = mf__ibm_bitsf(mf__ibm_fbits(mf__clamp_alpha(flake_alpha)));
    cut = mf__ibm_bitsf(mf__ibm_fbits(cut_sigmas > MF_R(0.0) ? cut_sigmas : MF_R(3.0)));
    mf__ibm_resolution(alpha, cut, resolution, &res, &radius);
    n = (size_t)width * (size_t)height;
    bins = (size_t)res * (size_t)res;
    words = mf__ibm_layout(&L, width, height, res, radius, (unsigned int)n);
    if (!words) return MF_ERROR_INVALID_ARGUMENT;
    ncodes = (size_t)1 << (L.kx + L.ky);
    kmin = L.kx < L.ky ? L.kx : L.ky;
    bmw = words - L.bin_at;   /* the bin map's words, its spare words too: the array's end (the lists' length does not change it) */
    /* every texel's bin j by its Morton code (16 bits when the bins allow);
     * codes outside the map hold `none` */
    none = bins < 0xffffu ? 0xffffu : 0xffffffffu;
    tmp = MF_MALLOC(ncodes * (none == 0xffffu ? sizeof(unsigned short) : sizeof(unsigned int)));
    cur = (unsigned int *)MF_MALLOC((bins + 1u) * sizeof(unsigned int));
    sums = (double *)MF_MALLOC(2u * bins * sizeof(double));
    bmap = (unsigned int *)MF_MALLOC(bmw * sizeof(unsigned int));
    if (!tmp || !cur || !sums || !bmap) {
        MF_FREE(tmp); MF_FREE(cur); MF_FREE(sums); MF_FREE(bmap);
        return MF_ERROR_OUT_OF_MEMORY;
    }
    if (none == 0xffffu) t16 = (unsigned short *)tmp;
    else t32 = (unsigned int *)tmp;
    for (i = 0; i <= bins; ++i) cur[i] = 0u;
    for (i = 0; i < 2u * bins; ++i) sums[i] = 0.0;
    for (i = 0; i < bmw; ++i) bmap[i] = 0u;
    if (ncodes != n) {
        if (t16) for (i = 0; i < ncodes; ++i) t16[i] = 0xffffu;
        else for (i = 0; i < ncodes; ++i) t32[i] = 0xffffffffu;
    }
    /* pass 1, in 8 x 8 tiles: validate, bin (Eq. 5.15), count, per-bin sums,
     * the bin map (bins as ix | iy << s), the bins by Morton code. The
     * tile's rows are binned, counted and summed first (contiguous normals,
     * no branch: a bad normal only sets a flag, checked once per tile; a
     * texel with its left neighbour's normal takes its results, and such a
     * run reaches its bin's count and sums at once); then the tile's bins
     * go to the Morton-ordered table (its 64 consecutive codes when both
     * sides have 8 texels or more). */
    for (i = 0; i < 64u; ++i) tile[i] = (unsigned char)(mf__ibm_compact((unsigned int)i >> 1) | (mf__ibm_compact((unsigned int)i) << 3));
    for (y = 0; y < height; y += 8)
        for (x = 0; x < width; x += 8) {
            unsigned int q, tj[64], bc[8], mb;
            int w8 = width - x < 8 ? width - x : 8, h8 = height - y < 8 ? height - y : 8, r, c;
            for (r = 0; r < h8; ++r) {
                size_t k = (size_t)(y + r) * (size_t)width + (size_t)x;
                const mf_real *nv = normals_xyz + 3u * k;
                unsigned int rj = 0u, rc = 0u;   /* the run of one normal: its bin and length */
                mf_real rx = MF_R(0.0), ry = MF_R(0.0);
                for (c = 0; c < w8; ++c, nv += 3) {
                    mf_real nx = nv[0], ny = nv[1], nz = nv[2], l2, il;
                    unsigned int ix, iy;
                    if (c > 0 && mf__ibm_same_bits(nx, nv[-3]) && mf__ibm_same_bits(ny, nv[-2]) &&
                        mf__ibm_same_bits(nz, nv[-1])) {
                        /* the left neighbour's normal, bit for bit (flakes, flat
                         * regions): its results (and its validity) */
                        tj[8 * r + c] = rj;
                        bc[c] = bc[c - 1];
                        ++rc;
                        continue;
                    }
                    /* the previous run into its bin (none at c = 0: adds 0) */
                    cur[rj] += rc;
                    sums[2u * rj] += (double)rx * rc;
                    sums[2u * rj + 1u] += (double)ry * rc;
                    /* l2 is finite iff the three are and it does not overflow */
                    l2 = nx * nx + ny * ny + nz * nz;
                    bad |= (unsigned int)(!mf__finite_bits(l2)) | (unsigned int)(!(nz > MF_R(0.0))) |
                           (unsigned int)(!(MF_FABS(l2 - MF_R(1.0)) < MF_R(1e-3)));
                    /* 1/sqrt(l2) by two Newton steps from 1 (|l2 - 1| < 1e-3:
                     * error < 1e-12, no sqrt or division in the hot loop) */
                    il = MF_R(1.5) - MF_R(0.5) * l2;
                    il *= MF_R(1.5) - MF_R(0.5) * l2 * il * il;
                    nx *= il; ny *= il;
                    ix = (unsigned int)mf__ibm_cell(nx, res); iy = (unsigned int)mf__ibm_cell(ny, res);
                    rj = tj[8 * r + c] = ix + (unsigned int)res * iy;
                    rc = 1u; rx = nx; ry = ny;
                    bc[c] = ix | (iy << L.axis_bits);
                }
                cur[rj] += rc;
                sums[2u * rj] += (double)rx * rc;
                sums[2u * rj + 1u] += (double)ry * rc;
                {
                    mf__ibm_writer wr;
                    mf__ibm_writer_at(&wr, bmap, k, L.bin_bits);
                    for (c = 0; c < w8; ++c) mf__ibm_writer_push(&wr, bc[c]);
                    mf__ibm_writer_flush(&wr);
                }
            }
            if (bad) {
                MF_FREE(tmp); MF_FREE(cur); MF_FREE(sums); MF_FREE(bmap);
                return MF_ERROR_INVALID_DATA;
            }
            mb = mf__ibm_morton(L.kx, L.ky, (unsigned int)x, (unsigned int)y);
            if (w8 == 8 && h8 == 8 && kmin >= 3 && t16)   /* the tile's 64 consecutive codes */
                for (q = 0; q < 64u; ++q) t16[mb + q] = (unsigned short)tj[tile[q]];
            else
                for (q = 0; q < 64u; ++q) {
                    unsigned int t = tile[q], code;   /* t = column + 8 row */
                    if ((int)(t & 7u) >= w8 || (int)(t >> 3) >= h8) continue;
                    code = kmin >= 3 ? mb + q : mf__ibm_morton(L.kx, L.ky, (unsigned int)x + (t & 7u), (unsigned int)y + (t >> 3));
                    if (t16) t16[code] = (unsigned short)tj[t];
                    else t32[code] = tj[t];
                }
        }
    /* block sizes: n, or n + 2^k - 1 with the top k levels of the kd-tree */
    for (i = 0; i < bins; ++i) start += mf__ibm_block_len(&L, cur[i]);
    words = mf__ibm_layout(&L, width, height, res, radius, start);
    data = words ? (unsigned int *)MF_MALLOC(words * sizeof(unsigned int)) : 0;
    if (!data) {
        MF_FREE(tmp); MF_FREE(cur); MF_FREE(sums); MF_FREE(bmap);
        return words ? MF_ERROR_OUT_OF_MEMORY : MF_ERROR_INVALID_ARGUMENT;
    }
    for (i = 0; i < L.bin_at; ++i) data[i] = 0u;
    for (i = 0; i < bmw; ++i) data[L.bin_at + i] = bmap[i];
    MF_FREE(bmap);
    list = data + L.pos_at;
    /* means, quantized inside their bin; the index (Sec. 5.4.4) */
    start = 0u;
    for (i = 0; i < bins; ++i) {
        unsigned int c = cur[i], q = 0x80008000u;
        if (c) {
            double fx = (sums[2u * i] / c + 1.0) * 0.5 * res - (double)(i % (size_t)res);
            double fy = (sums[2u * i + 1u] / c + 1.0) * 0.5 * res - (double)(i / (size_t)res);
            unsigned int qx, qy;
            fx = fx < 0.0 ? 0.0 : (fx > 1.0 ? 1.0 : fx);
            fy = fy < 0.0 ? 0.0 : (fy > 1.0 ? 1.0 : fy);
            qx = (unsigned int)(fx * 65536.0 + 0.5); qy = (unsigned int)(fy * 65536.0 + 0.5);
            q = ((qx > 65535u ? 65535u : qx) << 16) | (qy > 65535u ? 65535u : qy);
            {   /* slope moments of the map from the bins' mean normals */
                double ax = sums[2u * i] / c, ay = sums[2u * i + 1u] / c, z2 = 1.0 - ax * ax - ay * ay;
                z2 = z2 > 1e-12 ? z2 : 1e-12;
                sxx += c * ax * ax / z2;
                syy += c * ay * ay / z2;
            }
        }
        data[L.mean_at + i] = q;
        mf__ibm_put(data + L.off_at, i, L.off_bits, start);
        start += mf__ibm_block_len(&L, c);
    }
    mf__ibm_put(data + L.off_at, bins, L.off_bits, start);
    MF_FREE(sums);
    /* per bin, the write state of pass 2 (4 words, in place of the sums):
     * st[4j] the cursor of its positions, st[4j + 1] the Morton code of the
     * next inner level-k node boundary of its kd-tree top (0xffffffff: none
     * left, or no tree), st[4j + 2] its first position, st[4j + 3] k << 26 |
     * that node */
    st = (unsigned int *)MF_MALLOC(4u * bins * sizeof(unsigned int) + sizeof(unsigned int));
    if (!st) {
        MF_FREE(tmp); MF_FREE(cur); MF_FREE(data);
        return MF_ERROR_OUT_OF_MEMORY;
    }
    start = 0u;
    for (i = 0; i < bins; ++i) {
        unsigned int c = cur[i], len = mf__ibm_block_len(&L, c), *b = st + 4u * i;
        int k = len == c ? 0 : mf__ibm_tree_levels(&L, c);
        b[0] = b[2] = start + (len - c);   /* after the tree's inner boundaries */
        b[1] = len == c ? 0xffffffffu : 1u << (L.kx + L.ky - k);   /* node 0 starts at 0: not stored */
        b[3] = (unsigned int)k << 26 | 1u;
        start += len;
    }
    MF_FREE(cur);
    /* pass 2, in Morton order: the inverse bin map (Eq. 5.17) - positions
     * grouped by bin, each group sorted because the codes come in order -
     * and the forest (Sec. 5.4.4): a bin's inner level-k node boundary is
     * written when its first position at or past the node arrives. One
     * cursor per texel, no per-run state: runs of one bin are short on
     * smooth and noisy maps, where switching state cost more. */
    for (i = 0; i < ncodes; ++i) {
        unsigned int j = t16 ? (unsigned int)t16[i] : t32[i], code = (unsigned int)i, *b, c;
        if (j == none) continue;
        b = st + 4u * j;
        c = b[0]++;
        if (code >= b[1]) {   /* the level-k nodes up to this one start at this position */
            unsigned int node = b[3] & 0x03ffffffu, tk = b[3] >> 26, shift = (unsigned int)(L.kx + L.ky) - tk;
            do {
                mf__ibm_put(list, b[2] - (1u << tk) + node, L.list_bits, c - b[2]);
                ++node;
            } while (code >= node << shift);
            b[1] = node < 1u << tk ? node << shift : 0xffffffffu;
            b[3] = tk << 26 | node;
        }
        mf__ibm_put(list, c, L.list_bits, code);
    }
    MF_FREE(tmp);
    /* the remaining inner node boundaries of each tree: the bin's count */
    for (i = 0; i < bins; ++i) {
        unsigned int *b = st + 4u * i, node, kn = 1u << (b[3] >> 26);
        for (node = b[3] & 0x03ffffffu; node < kn; ++node)
            mf__ibm_put(list, b[2] - kn + node, L.list_bits, b[0] - b[2]);
    }
    MF_FREE(st);
    data[0] = MF_IBM_MAGIC;
    data[1] = MF_IBM_VERSION;
    data[2] = (unsigned int)words;
    data[3] = (unsigned int)width;
    data[4] = (unsigned int)height;
    data[5] = (unsigned int)res;
    data[6] = (unsigned int)radius;
    data[7] = mf__ibm_fbits(alpha);
    data[8] = mf__ibm_fbits(cut);
    data[9] = mf__ibm_fbits(MF_SQRT((mf_real)(2.0 * sxx / (double)n)));
    data[10] = mf__ibm_fbits(MF_SQRT((mf_real)(2.0 * syy / (double)n)));
    data[11] = L.list_len;
    data[MF__IBM_HEADER - 1] = mf__ibm_checksum(data, words);
    *ibm = L;
    ibm->data = data;
    ibm->words = words;
    mf__ibm_set_fields(ibm);
    return MF_SUCCESS;
}

MFDEF mf_result mf_ibm_build(mf_ibm *ibm, const mf_real *normals_xyz, int width, int height, mf_real flake_alpha)
{
    return mf_ibm_build_ex(ibm, normals_xyz, width, height, flake_alpha, 0);
}

MFDEF void mf_ibm_release(mf_ibm *ibm)
{
    if (!ibm) return;
    MF_FREE(ibm->data);
    mf__ibm_zero(ibm);
}

MFDEF size_t mf_ibm_memory_bytes(const mf_ibm *ibm)
{
    return ibm && ibm->data ? ibm->words * sizeof(unsigned int) : 0u;
}

MFDEF mf_result mf_ibm_save(const mf_ibm *ibm, void *buf, size_t cap, size_t *bytes)
{
    size_t n, i;
    if (bytes) *bytes = 0u;
    if (!ibm || !ibm->data || !bytes) return MF_ERROR_INVALID_ARGUMENT;
    n = ibm->words * sizeof(unsigned int);
    *bytes = n;
    if (!buf) return MF_SUCCESS;
    if (cap < n) return MF_ERROR_BUFFER_TOO_SMALL;
    {
        const unsigned char *s = (const unsigned char *)ibm->data;
        unsigned char *d = (unsigned char *)buf;
        for (i = 0; i < n; ++i) d[i] = s[i];
    }
    return MF_SUCCESS;
}

/* every check a query relies on; 1 if the array is a valid map */
static int mf__ibm_valid(mf_ibm *L, const unsigned int *w, size_t words)
{
    size_t n, bins, j, total = 0;
    mf_real a, c, sx, sy;
    unsigned int prev_end = 0u, amask;
    const unsigned int *list;
    if (words < MF__IBM_HEADER || w[0] != MF_IBM_MAGIC || w[1] != MF_IBM_VERSION || (size_t)w[2] != words) return 0;
    if (w[3] > 16384u || w[4] > 16384u || w[5] > (unsigned int)MF_IBM_MAX_RES || w[6] > (unsigned int)MF_IBM_MAX_RADIUS) return 0;
    if (mf__ibm_layout(L, (int)w[3], (int)w[4], (int)w[5], (int)w[6], w[11]) != words) return 0;
    for (j = 12; j < MF__IBM_HEADER - 1; ++j) if (w[j] != 0u) return 0;
    a = mf__ibm_bitsf(w[7]); c = mf__ibm_bitsf(w[8]); sx = mf__ibm_bitsf(w[9]); sy = mf__ibm_bitsf(w[10]);
    /* alpha as the builder stores it: clamped like every alpha, rounded to float */
    if (!(a > MF_R(0.0)) || a != mf__ibm_bitsf(mf__ibm_fbits(mf__clamp_alpha(a))) || !(c > MF_R(0.0)) || !(c <= MF_R(10.0)) || !(sx >= MF_R(0.0)) ||
        !(sx < MF_BIG) || !(sy >= MF_R(0.0)) || !(sy < MF_BIG))
        return 0;
    if (mf__ibm_checksum(w, words) != w[MF__IBM_HEADER - 1]) return 0;
    L->data = (unsigned int *)0;
    n = (size_t)L->width * (size_t)L->height;
    bins = (size_t)L->res * (size_t)L->res;
    list = w + L->pos_at;
    amask = (1u << L->axis_bits) - 1u;
    /* the bin map: both bin coordinates in range */
    for (j = 0; j < n; ++j) {
        unsigned int v = mf__ibm_get(w + L->bin_at, j, L->bin_bits);
        if ((v & amask) >= (unsigned int)L->res || (v >> L->axis_bits) >= (unsigned int)L->res) return 0;
    }
    /* the index and the blocks: contiguous and in range, each of a length
     * some texel count gives; the kd-tree tops monotone from 0 to n; the
     * positions in the map, sorted, each in the level-k node its boundaries
     * give and in the bin the bin map gives it - with N positions in all,
     * every texel appears exactly once */
    if (mf__ibm_get(w + L->off_at, 0, L->off_bits) != 0u) return 0;
    for (j = 0; j < bins; ++j) {
        unsigned int s = mf__ibm_get(w + L->off_at, j, L->off_bits), e = mf__ibm_get(w + L->off_at, j + 1u, L->off_bits);
        unsigned int want = (unsigned int)(j % (size_t)L->res) | ((unsigned int)(j / (size_t)L->res) << L->axis_bits);
        unsigned int cnt, base, tab = 0u, q, t;
        int k = 0, shift;
        if (s != prev_end || e < s || e > L->list_len) return 0;
        prev_end = e;
        if (e - s < (unsigned int)MF_IBM_TREE_MIN) { cnt = e - s; base = s; }
        else {   /* a length some n >= MF_IBM_TREE_MIN gives (then k > 0) */
            cnt = mf__ibm_block_texels(L, e - s, &k);
            if (k == 0 || (size_t)cnt > n) return 0;
            tab = s;
            base = s + (1u << k) - 1u;
            for (t = 0; t < (1u << k); ++t)
                if (mf__ibm_bound(list, L->list_bits, tab, k, cnt, t) > mf__ibm_bound(list, L->list_bits, tab, k, cnt, t + 1u)) return 0;
        }
        total += cnt;
        shift = L->kx + L->ky - k;
        for (q = 0; q < cnt; ++q) {
            unsigned int code = mf__ibm_get(list, base + q, L->list_bits);
            int x, y;
            if (code >> L->pos_bits) return 0;
            if (q > 0 && code <= mf__ibm_get(list, base + q - 1u, L->list_bits)) return 0;
            mf__ibm_unmorton(L->kx, L->ky, code, &x, &y);
            if (x >= L->width || y >= L->height || mf__ibm_morton(L->kx, L->ky, (unsigned int)x, (unsigned int)y) != code) return 0;
            if (mf__ibm_get(w + L->bin_at, (size_t)y * (size_t)L->width + (size_t)x, L->bin_bits) != want) return 0;
            if (k > 0) {
                unsigned int idx = code >> shift;
                if (q < mf__ibm_bound(list, L->list_bits, tab, k, cnt, idx) || q >= mf__ibm_bound(list, L->list_bits, tab, k, cnt, idx + 1u)) return 0;
            }
        }
    }
    return prev_end == L->list_len && total == n;
}

MFDEF mf_result mf_ibm_load(mf_ibm *ibm, const void *buf, size_t bytes)
{
    mf_ibm L;
    unsigned int *data;
    size_t words, i;
    if (!ibm) return MF_ERROR_INVALID_ARGUMENT;
    mf__ibm_zero(ibm);
    if (!buf) return MF_ERROR_INVALID_ARGUMENT;
    if (bytes % sizeof(unsigned int) != 0u || bytes < MF__IBM_HEADER * sizeof(unsigned int)) return MF_ERROR_INVALID_DATA;
    words = bytes / sizeof(unsigned int);
    data = (unsigned int *)MF_MALLOC(bytes);
    if (!data) return MF_ERROR_OUT_OF_MEMORY;
    {
        const unsigned char *s = (const unsigned char *)buf;
        unsigned char *d = (unsigned char *)data;
        for (i = 0; i < bytes; ++i) d[i] = s[i];
    }
    mf__ibm_zero(&L);
    if (!mf__ibm_valid(&L, data, words)) {
        MF_FREE(data);
        return MF_ERROR_INVALID_DATA;
    }
    *ibm = L;
    ibm->data = data;
    ibm->words = words;
    mf__ibm_set_fields(ibm);
    return MF_SUCCESS;
}
