/* @optional MF_NO_IBM */
/* @api */
/* ======================================================================== */
/* == 15. Inverse Bin Map: overview, layout and the packed bit format       */
/* ======================================================================== */
/* The Inverse Bin Map in five modules: this one (the mf_ibm type, its
 * packed layout, bins), 15_ibm_2_footprint.h (footprint geometry),
 * 15_ibm_3_traverse.h (bin weights by kd traversal), 15_ibm_4_brdf.h (the
 * filtered BRDF, pdf and sampling), 15_ibm_5_build.h (build, save, load). */
/* Atanasov et al. 2021 (thesis ch. 5): the filtered BRDF of a normal map over a
 * pixel footprint A (Eq. 5.1-5.3) grouped by directional bins (binned BRDF,
 * Eq. 5.7-5.8), truncated to the 21 bins around the half vector's bin (Eq.
 * 5.13, bin resolution Eq. 5.14), each texel a Beckmann flake lobe with Smith
 * shadowing (texel contribution C, Eq. 3.29); bin weights from the Inverse Bin
 * Map (Eq. 5.15, 5.17) with node-level prefiltering; sampling and pdf Eq. 5.16. */

/* Use: build once per normal map and flake roughness (mf_ibm_build,
 * 15_ibm_5_build.h; about 0.05-0.13 s and 16-28 MB for a 2048^2 map), then per shading point
 * pass the pixel footprint in texture space (e.g. from ray differentials):
 *
 *     mf_ibm ibm;
 *     mf_ibm_build(&ibm, normals_xyz, 2048, 2048, 0.01f);   // check the mf_result
 *     mf_footprint fp = { u, v, dudx, dvdx, dudy, dvdy };
 *     mf_real f = mf_ibm_brdf(&ibm, &fp, wo, wi);           // no Fresnel, no cosine
 *     mf_sample s = mf_ibm_sample(&ibm, &fp, wo, u1, u2, u3, u4);  // s.wi, s.pdf, s.weight
 *     mf_real pdf, f2 = mf_ibm_brdf_and_pdf(&ibm, &fp, wo, wi, &pdf);  // both, one query
 *     mf_ibm_release(&ibm);
 *
 * The map's normals and wo, wi share the shading frame: x along u (texel
 * columns), y along v (rows), z the macro normal. The model (thesis Eq. 3.27-
 * 3.29, 5.2): each texel is a flat facet of normal t_k carrying a Beckmann
 * microsurface of roughness alpha around t_k; its contribution
 *     C(wo, wi, t) = D(h; t) G2(wo, wi; t) G_x(wo, wi, t) / (4 wo.z wi.z)
 * has D and the Smith G2 measured from t (height-correlated) and G_x the
 * Smith G2 of the normal map's own distribution (mf_ibm_set_shadowing). The
 * filtered BRDF is sum_k w_k C(t_k), w_k the texel's share of the footprint
 * (Eq. 5.2-5.3); the IBM groups texels by bin (Eq. 5.7), represents each bin by
 * its texels' mean normal, and keeps the bins around the half vector's bin
 * (Eq. 5.13): measured loss about 1% of the albedo (tests). Sampling picks a
 * texel by area, then a visible normal of its lobe, and returns no sample when
 * the truncation would not count it, so mf_ibm_pdf is its exact density and
 * integrates to 1 minus the no-sample mass (truncation, wi below the horizon,
 * wo behind the bin normal). Queries cost the footprint's perimeter in texels
 * (exact areas at the boundary, whole kd nodes inside), not its area. */

/* Layout of the single integer array (32-bit words), built by mf_ibm_build:
 *   header   MF__IBM_HEADER words: magic, version, sizes, parameters, checksum
 *   index    b*b + 1 packed fields: start of bin j's block in the lists (the
 *            index I of Sec. 5.4.4)
 *   means    b*b words: mean normal of each bin, 16 + 16 bits inside the bin
 *   lists    packed fields of kx + ky bits, one block per bin: the inverse
 *            bin map B^-1 (Eq. 5.17), the bin's texel positions as Morton
 *            codes, sorted; a bin of n >= MF_IBM_TREE_MIN texels puts first
 *            the top k levels of its kd-tree (forest F): the 2^k - 1 inner
 *            boundaries of its level-k nodes in its list (the outer two are 0
 *            and n), k = floor(log2(2 n / MF_IBM_TREE_MIN)): its level-k
 *            nodes hold 10 to 20 texels on average (the leaf size of Sec.
 *            5.4.4 is 10), so that the splits a traversal meets above its
 *            leaves are mostly read, not searched; n follows from the
 *            block's length n + 2^k - 1 (strictly increasing in n)
 *   bin map  N packed fields (row-major): the bin of each texel (Eq. 5.15),
 *            stored as ix | iy << s (s bits per axis)
 * Each packed section ends with a spare word, the bin map with two (the
 * reads of mf__ibm_get).
 * The kd-trees split the larger side of the power-of-two box holding the map
 * in the middle (x first on ties). The Morton code interleaves the bits in
 * exactly that order, so sorting a bin's positions by it makes every node a
 * contiguous range (Sec. 5.4.4): nodes down to level k are read from the
 * stored boundaries, deeper splits are found by binary search on the node's
 * bit, so no pointers are stored at all. */
#define MF_IBM_MAGIC 0x4d464942u          /* "BIFM" in little-endian bytes */
#define MF_IBM_VERSION 2u                 /* 1 (0.2.0): n and all 2^k + 1 boundaries stored, wider fields */
#define MF_IBM_LEAF 24                    /* leaf size L of Sec. 5.4.4 (10 there; tuned: docs/PERFORMANCE.md) */
#define MF_IBM_TREE_MIN 20                /* bins this large store the top of their kd-tree */
#define MF_IBM_MAX_RES 1024               /* bins per axis at most (index memory b^2) */
#define MF_IBM_MAX_RADIUS 8               /* neighbourhood radius in bins at most */
#define MF_IBM_MAX_WINDOW 289             /* (2 MF_IBM_MAX_RADIUS + 1)^2 */
#define MF_IBM_BATCH 21                   /* bins per kd traversal (the 21 of Sec. 5.4.2) */
#define MF_IBM_MAX_PIECES 64              /* period cells cut by the footprint, exact up to this */
#define MF_IBM_MIN_AREA MF_R(1e-6)        /* footprints smaller than this (texel^2): point lookup */
#ifndef MF_IBM_DIRECT_TEXELS
#define MF_IBM_DIRECT_TEXELS 2048         /* direct texel sum (Eq. 5.2) up to this bounding box (bench) */
#endif
#define MF__IBM_HEADER 16
#define MF__IBM_STACK 32
/* a node of at most MF_IBM_LEAF texels is still split while they are sparse
 * (its box holds over 2^MF__IBM_SPARSE_BITS cells per texel) and more than
 * MF__IBM_LEAF_MIN: its children are likely inside or outside the piece */
#ifndef MF__IBM_LEAF_MIN
#define MF__IBM_LEAF_MIN 4
#endif
#ifndef MF__IBM_SPARSE_BITS
#define MF__IBM_SPARSE_BITS 3
#endif
/* leaf size of a traversal for one bin: smaller than MF_IBM_LEAF, since a
 * leaf's texels cost more than the nodes that sort them in or out (tuned:
 * docs/PERFORMANCE.md) */
#ifndef MF__IBM_LEAF_ONE
#define MF__IBM_LEAF_ONE 12
#endif
/* bins of fewer texels skip mf__ibm_bin_near's kd-top box test: the
 * few-texel path's scan of their lists costs less than the test (tuned:
 * docs/PERFORMANCE.md) */
#define MF__IBM_NEAR_MIN 128u

/* Parallelogram footprint in texture space, tiled with period 1: center
 * (u, v), edges a = (ax, ay), b = (bx, by); corners (u,v) +- a/2 +- b/2. Texel
 * (x, y) of a width x height map covers [x/width, (x+1)/width) x [y/height,
 * (y+1)/height). */
typedef struct mf_footprint { mf_real u, v, ax, ay, bx, by; } mf_footprint;

/* A built Inverse Bin Map (mf_ibm_build, mf_ibm_load). Everything it holds is
 * `data` (one allocation, `words` 32-bit words); the other fields are derived
 * from its header. The queries below only read `data`: copy it to the GPU and
 * point a copy of this struct at the copy to use them in device code. */
typedef struct mf_ibm {
    unsigned int *data;         /* the single integer array (layout above) */
    size_t words;               /* its length in 32-bit words */
    int width, height;          /* map size in texels */
    int res;                    /* b, bins per axis: b*b bins over [-1,1]^2 (Sec. 5.4.2) */
    int radius;                 /* neighbourhood radius: bins with dx^2+dy^2 <= r(r+1); 2 -> 21 bins */
    int kx, ky;                 /* log2 of the power-of-two box holding the map */
    int off_bits, pos_bits, list_bits, bin_bits, axis_bits;   /* widths of the packed fields */
    unsigned int list_len;      /* fields in the lists section */
    size_t off_at, mean_at, pos_at, bin_at;       /* word offsets of the sections */
    mf_real alpha;              /* Beckmann flake roughness */
    mf_real cut;                /* cut of the flake lobe in sigmas (3, Sec. 5.4.1) */
    mf_real shadow_ax, shadow_ay;   /* Beckmann roughness fitted to the map's slopes */
    int has_shadow;             /* 1: G_x is the Smith G2 of `shadow`; 0: G_x = 1 */
    mf_ndf shadow;              /* distribution of the normal map for G_x (Sec. 3.2.3) */
} mf_ibm;

/* The checksum of a map's array (mf_ibm_load checks it): a 4-lane
 * multiplicative hash of the words, the checksum word itself (word 15, lane 3)
 * taken as 0. */
MF_INLINE unsigned int mf__ibm_checksum(const unsigned int *w, size_t n)
{
    unsigned int h0 = 0x811c9dc5u, h1 = 0x01000193u, h2 = 0x9e3779b9u, h3 = 0x7f4a7c15u;
    size_t i;
    for (i = 0; i + 4u <= n; i += 4u) {
        unsigned int v3 = i + 3u == MF__IBM_HEADER - 1 ? 0u : w[i + 3u];
        h0 = (h0 ^ w[i]) * 0x01000193u + 1u;
        h1 = (h1 ^ w[i + 1u]) * 0x01000193u + 3u;
        h2 = (h2 ^ w[i + 2u]) * 0x01000193u + 5u;
        h3 = (h3 ^ v3) * 0x01000193u + 7u;
    }
    for (; i < n; ++i) h0 = (h0 ^ w[i]) * 0x01000193u + 11u;
    return h0 ^ (h1 * 0x9e3779b1u) ^ (h2 * 0x85ebca77u) ^ (h3 * 0xc2b2ae3du);
}

/* floor and ceiling of x as int, for |x| below 2^31 (coordinates in texels):
 * the conversion and one compare (libm's floor is a call, or a longer
 * sequence, on baseline x86-64) */
MF_INLINE int mf__ibm_ifloor(mf_real x)
{
    int i = (int)x;
    return i - (x < (mf_real)i);
}
MF_INLINE int mf__ibm_iceil(mf_real x)
{
    int i = (int)x;
    return i + (x > (mf_real)i);
}

/* ---- bins (Sec. 5.4.2): b x b squares over [-1,1]^2 of (n.x, n.y) ---- */

MF_INLINE int mf__ibm_cell(mf_real v, int b)
{
    mf_real f = (mf_real)b * (MF_R(0.5) * v + MF_R(0.5)), top = (mf_real)(b - 1);
    int c;
    f = f > MF_R(0.0) ? f : MF_R(0.0);           /* also NaN; a max and a min, no branch (the build's hot loop) */
    c = (int)(f < top ? f : top);                /* truncation = floor for f >= 0 */
    return (unsigned int)c < (unsigned int)b ? c : 0;   /* in range even where -ffast-math let NaN through */
}

/* b*b: the number of bins (those outside the unit disk stay empty). */
MF_INLINE int mf_ibm_bin_count(const mf_ibm *ibm)
{
    return ibm && ibm->data ? ibm->res * ibm->res : 0;
}

/* beta(n) = floor(b (n.x/2 + 1/2)) + b floor(b (n.y/2 + 1/2)) for the
 * normalized n; -1 for n below the horizon, zero or not finite. */
MF_INLINE int mf_ibm_bin_of(const mf_ibm *ibm, mf_vec3 n)
{
    if (!ibm || !ibm->data) return -1;
    n = mf_normalize(n);
    if (!(n.z >= MF_R(0.0)) || mf_dot(n, n) == MF_R(0.0)) return -1;
    return mf__ibm_cell(n.x, ibm->res) + ibm->res * mf__ibm_cell(n.y, ibm->res);
}

/* Number of texels in bin `bin`. */
MF_COLD int mf_ibm_bin_texels(const mf_ibm *ibm, int bin);

/* The normal that represents bin `bin` in C and in sampling: the mean of the
 * bin's texel normals (their (x, y) averaged, rounded to a multiple of 1/65536
 * of the bin - exact for the normal (0,0,1) - lifted to the hemisphere); the
 * bin center beta^-1(j, 1/2, 1/2) for an empty bin. The thesis uses the center; the mean is exact for a bin whose texels
 * share one normal (flat regions, flakes) and never farther from them. */
MF_COLD mf_vec3 mf_ibm_bin_normal(const mf_ibm *ibm, int bin);

/* The bin of texel (x, y) (wrapped into the map) from the bin map. */
MF_COLD int mf_ibm_texel_bin(const mf_ibm *ibm, int x, int y);

/* Sets the distribution whose Smith G2 is the normal map's shadowing G_x of
 * Eq. 3.29 (e.g. the GTR the flakes were drawn from, as in Sec. 5.5.4); NULL:
 * G_x = 1. mf_ibm_build and mf_ibm_load set mf_beckmann(shadow_ax, shadow_ay),
 * the Beckmann roughness of the map's RMS slopes (sqrt(2 E[s^2]) per axis). */
MF_COLD void mf_ibm_set_shadowing(mf_ibm *ibm, const mf_ndf *d);

/* bit length of v (0 for 0): one instruction where there is one, else by
 * halving (no loop over the bits) */
MF_INLINE int mf__ibm_bitlen32(unsigned int v)
{
#ifdef MF__CLZ32
    return v ? 32 - MF__CLZ32(v) : 0;
#else
    int k = 0;
    if (v >> 16) { k += 16; v >>= 16; }
    if (v >> 8) { k += 8; v >>= 8; }
    if (v >> 4) { k += 4; v >>= 4; }
    if (v >> 2) { k += 2; v >>= 2; }
    if (v >> 1) { k += 1; v >>= 1; }
    return k + (int)v;
#endif
}

/* stored kd-tree levels of a bin of n texels: floor(log2(2 n / MF_IBM_TREE_MIN)) (0 below it), within the tree's depth */
MF_INLINE int mf__ibm_tree_levels(const mf_ibm *ibm, unsigned int n)
{
    int k = mf__ibm_bitlen32(n / (unsigned int)MF_IBM_TREE_MIN);
    k = k < 24 ? k : 24;
    return k < ibm->kx + ibm->ky ? k : ibm->kx + ibm->ky;
}

/* the block length of a bin of n texels: n, or n + 2^k - 1 with the top k
 * levels of its kd-tree (the inner boundaries of its level-k nodes) */
MF_INLINE unsigned int mf__ibm_block_len(const mf_ibm *ibm, unsigned int n)
{
    return n < (unsigned int)MF_IBM_TREE_MIN ? n : n + (1u << mf__ibm_tree_levels(ibm, n)) - 1u;
}

/* The texel count of a bin whose block has length len: len = n + 2^k(n) - 1
 * is strictly increasing in n; *k: the stored levels (0: none, len = n). */
MF_INLINE unsigned int mf__ibm_block_texels(const mf_ibm *ibm, unsigned int len, int *k)
{
    unsigned int n = len;
    if (len < (unsigned int)MF_IBM_TREE_MIN) { *k = 0; return len; }
    for (*k = mf__ibm_tree_levels(ibm, len); *k > 0; --*k) {
        n = len + 1u - (1u << *k);
        if (mf__ibm_tree_levels(ibm, n) == *k) return n;
    }
    return len;   /* none (not a valid block: mf_ibm_load rejects it) */
}
/* @cold */
/* one field of `w` bits (w <= 32) of a packed array, without a branch: every
 * packed section of a map ends with a spare word, the last with two, so the
 * 8 bytes from the field's first byte lie in the array. On 64-bit
 * little-endian hosts one unaligned 8-byte read (the fields' bits in order),
 * else the field's first word and the next. */
#if !defined(__CUDA_ARCH__) && ((defined(__x86_64__) || defined(_M_X64)) || \
    (defined(__aarch64__) && !defined(__AARCH64EB__)) || defined(_M_ARM64))
#define MF__IBM_GET64 1
#define MF__IBM_TWICE(m) (((size_t)(m) << 32) | (size_t)(m))   /* m in both halves; no long long literal: C++98 */
#endif
MF_INLINE unsigned int mf__ibm_get(const unsigned int *base, size_t i, int w)
{
    size_t bit = i * (size_t)w;
#ifdef MF__IBM_GET64
    size_t v;   /* 64 bits here */
    memcpy(&v, (const unsigned char *)base + (bit >> 3), sizeof v);
    return (unsigned int)((v >> (bit & 7u)) & (((size_t)1 << w) - 1u));
#else
    const unsigned int *p = base + (bit >> 5);
    unsigned int sh = (unsigned int)(bit & 31u);
    /* the two words shifted right by sh; (p[1] << 1) << (31 - sh) keeps both
     * shifts below 32 (no 64-bit type: C++98) */
    unsigned int v = (p[0] >> sh) | (((p[1] << 1) & 0xffffffffu) << (31u - sh));
    return w > 0 ? v & ((2u << (w - 1)) - 1u) & 0xffffffffu : 0u;
#endif
}
/* bit b of field i alone (mf__ibm_get(base, i, w) >> b & 1): one word read,
 * fields being stored lowest bit first, one after another */
MF_INLINE unsigned int mf__ibm_get_bit(const unsigned int *base, size_t i, int w, int b)
{
    size_t bit = i * (size_t)w + (size_t)b;
    return (base[bit >> 5] >> (bit & 31u)) & 1u;
}

/* bits of x spread to the even positions (x < 2^16) and back */
MF_INLINE unsigned int mf__ibm_spread(unsigned int x)
{
    x &= 0xffffu;
    x = (x | (x << 8)) & 0x00ff00ffu;
    x = (x | (x << 4)) & 0x0f0f0f0fu;
    x = (x | (x << 2)) & 0x33333333u;
    return (x | (x << 1)) & 0x55555555u;
}
/* mf__ibm_spread of a and of b: at once in one 64-bit word where packed
 * fields are read as such (a in its upper half; mf__ibm_code_box) */
MF_INLINE void mf__ibm_spread2(unsigned int a, unsigned int b, unsigned int *sa, unsigned int *sb)
{
#ifdef MF__IBM_GET64
    size_t t = ((size_t)(a & 0xffffu) << 32) | (size_t)(b & 0xffffu);
    t = (t | (t << 8)) & MF__IBM_TWICE(0x00ff00ffu);
    t = (t | (t << 4)) & MF__IBM_TWICE(0x0f0f0f0fu);
    t = (t | (t << 2)) & MF__IBM_TWICE(0x33333333u);
    t = (t | (t << 1)) & MF__IBM_TWICE(0x55555555u);
    *sa = (unsigned int)(t >> 32);
    *sb = (unsigned int)t;
#else
    *sa = mf__ibm_spread(a);
    *sb = mf__ibm_spread(b);
#endif
}
MF_INLINE unsigned int mf__ibm_compact(unsigned int x)
{
    x &= 0x55555555u;
    x = (x | (x >> 1)) & 0x33333333u;
    x = (x | (x >> 2)) & 0x0f0f0f0fu;
    x = (x | (x >> 4)) & 0x00ff00ffu;
    return (x | (x >> 8)) & 0xffffu;
}

/* Morton code in the kd split order: the larger side of the box splits first
 * (x on ties), so the code's bits from the top are the kd-tree's decisions. */
MF_INLINE unsigned int mf__ibm_morton(int kx, int ky, unsigned int x, unsigned int y)
{
    int k = kx < ky ? kx : ky;
    unsigned int m = (1u << k) - 1u, lo = (mf__ibm_spread(x & m) << 1) | mf__ibm_spread(y & m);
    unsigned int hi = kx > ky ? x >> k : y >> k;
    return (hi << (2 * k)) | lo;
}
MF_INLINE void mf__ibm_unmorton(int kx, int ky, unsigned int c, int *x, int *y)
{
    int k = kx < ky ? kx : ky;
    unsigned int lo = k > 0 ? c & ((1u << (2 * k)) - 1u) : 0u, hi = c >> (2 * k);
    unsigned int ux = mf__ibm_compact(lo >> 1), uy = mf__ibm_compact(lo);
    if (kx > ky) ux |= hi << k;
    else uy |= hi << k;
    *x = (int)ux;
    *y = (int)uy;
}

/* (x, y) of a code from its x bits cx and y bits cy (the code masked): the
 * 2 kmin interleaved bits (mask lom) compacted, the bits above them one
 * axis's own (mf__ibm_unmorton's result, without splitting the code) */
MF_INLINE void mf__ibm_unmorton_masked(unsigned int cx, unsigned int cy, unsigned int lom, int kmin, int *x, int *y)
{
#ifdef MF__IBM_GET64
    /* both compactions at once, x in the upper half of a 64-bit word (the
     * leaf loop's texel decode) */
    size_t t = ((size_t)((cx & lom) >> 1) << 32) | (size_t)(cy & lom);
    t = (t | (t >> 1)) & MF__IBM_TWICE(0x33333333u);
    t = (t | (t >> 2)) & MF__IBM_TWICE(0x0f0f0f0fu);
    t = (t | (t >> 4)) & MF__IBM_TWICE(0x00ff00ffu);
    t = (t | (t >> 8)) & MF__IBM_TWICE(0x0000ffffu);
    *x = (int)((unsigned int)(t >> 32) | ((cx & ~lom) >> kmin));
    *y = (int)((unsigned int)t | ((cy & ~lom) >> kmin));
#else
    *x = (int)(mf__ibm_compact((cx & lom) >> 1) | ((cx & ~lom) >> kmin));
    *y = (int)(mf__ibm_compact(cy & lom) | ((cy & ~lom) >> kmin));
#endif
}

/* start of bin j's block in the lists section */
MF_INLINE unsigned int mf__ibm_off(const mf_ibm *ibm, int j)
{
    return mf__ibm_get(ibm->data + ibm->off_at, (size_t)j, ibm->off_bits);
}

/* Node size 2^lx x 2^ly of the kd-trees at level l: the larger side split
 * first, x on ties (the order of the Morton code's bits). */
MF_INLINE void mf__ibm_node_dims(const mf_ibm *ibm, int l, int *lx, int *ly)
{
    int kx = ibm->kx, ky = ibm->ky, d = kx > ky ? kx - ky : ky - kx, m;
    if (l <= d) { *lx = kx > ky ? kx - l : kx; *ly = kx > ky ? ky : ky - l; return; }
    m = l - d;   /* then alternately, x first */
    *lx = (kx < ky ? kx : ky) - (m + 1) / 2;
    *ly = (kx < ky ? kx : ky) - m / 2;
}

/* 1 if bin j holds no texel (its block is empty) */
MF_INLINE int mf__ibm_bin_empty(const mf_ibm *ibm, int j)
{
    return mf__ibm_off(ibm, j) == mf__ibm_off(ibm, j + 1);
}

/* Bin j's texel count; *base: the first of its positions, *tab: its first
 * inner level-k node boundary (boundary i, 0 < i < 2^k, is field tab + i - 1;
 * values relative to base), *k: the stored levels (0: none). */
MF_INLINE unsigned int mf__ibm_bin_info(const mf_ibm *ibm, int j, unsigned int *base, unsigned int *tab, int *k)
{
    unsigned int s = mf__ibm_off(ibm, j), n = mf__ibm_block_texels(ibm, mf__ibm_off(ibm, j + 1) - s, k);
    *tab = s;
    *base = *k > 0 ? s + (1u << *k) - 1u : s;
    return n;
}

/* boundary i (0 <= i <= 2^k) of the level-k nodes of a bin of n texels
 * whose inner boundaries start at field tab of the lists pos (w bits): its
 * first node's start 0, its end n, else the stored field */
MF_INLINE unsigned int mf__ibm_bound(const unsigned int *pos, int w, unsigned int tab, int k, unsigned int n, unsigned int i)
{
    if (i == 0u) return 0u;
    if (i >= 1u << k) return n;
    return mf__ibm_get(pos, (size_t)tab + (size_t)i - 1u, w);
}

MF_COLD int mf_ibm_bin_texels(const mf_ibm *ibm, int bin)
{
    unsigned int base, tab;
    int k;
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return 0;
    return (int)mf__ibm_bin_info(ibm, bin, &base, &tab, &k);
}

MF_COLD mf_vec3 mf_ibm_bin_normal(const mf_ibm *ibm, int bin)
{
    unsigned int q;
    mf_real b, x, y, r2;
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    q = ibm->data[ibm->mean_at + (size_t)bin];
    b = (mf_real)ibm->res;
    x = MF_R(2.0) * ((mf_real)(bin % ibm->res) + (mf_real)(q >> 16) * MF_R(1.52587890625e-5)) / b - MF_R(1.0);
    y = MF_R(2.0) * ((mf_real)(bin / ibm->res) + (mf_real)(q & 0xffffu) * MF_R(1.52587890625e-5)) / b - MF_R(1.0);
    r2 = x * x + y * y;
    if (r2 > MF_R(1.0)) { mf_real s = MF_R(1.0) / MF_SQRT(r2); x *= s; y *= s; r2 = MF_R(1.0); }
    return mf_vec3_make(x, y, MF_SQRT(MF_R(1.0) - r2));
}

MF_COLD int mf_ibm_texel_bin(const mf_ibm *ibm, int x, int y)
{
    unsigned int v;
    if (!ibm || !ibm->data) return -1;
    x %= ibm->width; if (x < 0) x += ibm->width;
    y %= ibm->height; if (y < 0) y += ibm->height;
    v = mf__ibm_get(ibm->data + ibm->bin_at, (size_t)y * (size_t)ibm->width + (size_t)x, ibm->bin_bits);
    return (int)(v & ((1u << ibm->axis_bits) - 1u)) + ibm->res * (int)(v >> ibm->axis_bits);
}

MF_COLD void mf_ibm_set_shadowing(mf_ibm *ibm, const mf_ndf *d)
{
    if (!ibm) return;
    ibm->has_shadow = d ? 1 : 0;
    if (d) ibm->shadow = *d;
}
