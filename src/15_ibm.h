/* @optional MF_NO_IBM */
/* @api */
/* ======================================================================== */
/* == 15. Inverse Bin Map                                                   */
/* ======================================================================== */
/* Atanasov et al. 2021 (thesis ch. 5): the filtered BRDF of a normal map over a
 * pixel footprint A (Eq. 5.1-5.3) grouped by directional bins (binned BRDF,
 * Eq. 5.7-5.8), truncated to the 21 bins around the half vector's bin (Eq.
 * 5.13, bin resolution Eq. 5.14), each texel a Beckmann flake lobe with Smith
 * shadowing (texel contribution C, Eq. 3.29); bin weights from the Inverse Bin
 * Map (Eq. 5.15, 5.17) with node-level prefiltering; sampling and pdf Eq. 5.16. */

/* Use: build once per normal map and flake roughness (mf_ibm_build, section
 * 14; about 0.05-0.13 s and 16-28 MB for a 2048^2 map), then per shading point
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

/* ---- footprints: periods, pieces, exact areas ---- */

#define MF__IBM_NONE 0     /* no texel (center not finite) */
#define MF__IBM_POINT 1    /* degenerate footprint: the texel at the center */
#define MF__IBM_EXACT 2    /* full periods plus exact pieces */
#define MF__IBM_GLOBAL 3   /* too many periods: the whole map's histogram */

/* ---- bin weights: a window of bins around a center bin ---- */

/* Fraction of the footprint's area whose texels fall in `bin` (texels are
 * constant squares; Eq. 5.3, 5.8). Exact (polygon clipping) for any
 * parallelogram, rectangles through a fast path, wrapping across the border.
 * Footprints covering whole periods count them from the bin sizes; if the
 * footprint's boundary cuts more than MF_IBM_MAX_PIECES period cells the
 * weight is that of the whole map (n_bin / N) - exact when the footprint is a
 * union of whole periods, otherwise off by at most the cut cells' share of
 * the area. Zero area (< MF_IBM_MIN_AREA texels) or a non-finite edge: 1 for
 * the bin of the texel at the center, else 0; non-finite center: 0.
 * Cost: an empty bin (or, for the queries below, an empty neighbourhood:
 * two index reads a window row) returns before any footprint work, and so
 * does a bin of 128 or more whose stored kd-tree top has no texel near the
 * footprint, or bins of at most 48 texels in all none of which lies near it; footprints of up to MF_IBM_DIRECT_TEXELS bounding-box
 * texels visit the box (its bin-map rows prefetched), reading each texel's
 * bin before clipping it, unless the wanted bins hold fewer than 2 times
 * the box's texels (then their kd-trees are traversed); larger ones
 * traverse the kd-trees, where a kd node that the footprint's edge cuts and
 * whose texels all lie in the bin (flat regions) counts its box's area in
 * the footprint without descending. Footprints of a few texels get their
 * texels' areas row by row (two clips per row, then each texel's column
 * by Green's theorem along the row's edges); a texel
 * (or node) cut by one footprint edge gets its area in closed form, by
 * more edges by Green's theorem. Bins that hold at most 48 texels each on
 * average, for a footprint whose texel box meets at most 3 periods each
 * way (across the border too), take their texels from their lists without a
 * traversal: a texel's center in the footprint's coordinates decides it
 * wholly inside or outside, and only texels that the boundary may cut are
 * clipped (where the footprint's box would be visited, only a single bin,
 * of at most 128, which also skips the early exits above). */
MF_COLD mf_real mf_ibm_bin_weight(const mf_ibm *ibm, int bin, const mf_footprint *f);

/* The neighbourhood of `center_bin` (bins with dx^2 + dy^2 <= r(r+1), r =
 * ibm->radius: the 21 bins of Sec. 5.4.2 for r = 2) that hold texels, with
 * their weights, in one traversal. bins and weights must hold
 * MF_IBM_MAX_WINDOW entries; returns how many were written. */
MF_COLD int mf_ibm_neighbourhood_weights(const mf_ibm *ibm, const mf_footprint *f, int center_bin, int *bins,
                                           mf_real *weights);

/* ---- the filtered BRDF (Eq. 5.13), its pdf (Eq. 5.16) and sampling ---- */

/* Filtered glint BRDF over the footprint (Eq. 5.13 with F = 1, no cosine):
 * sum over the bins around the half vector's bin of W_j C(wo, wi, t_j). Each
 * bin is represented by its mean normal t_j (mf_ibm_bin_normal). Reciprocal.
 * Truncated like Eq. 5.13 (measured truncation: docs/ACCURACY.md); for
 * small footprints the same sum is taken texel by texel (Eq. 5.2). 0 below
 * the horizon and for degenerate input. */
MF_COLD mf_real mf_ibm_brdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi);

/* Density of mf_ibm_sample per unit solid angle of wi (Eq. 5.16 with the
 * visible-normal density of each bin's lobe): sum of W_j D_wo(h; t_j) /
 * (4 wo.h) over the same bins as mf_ibm_brdf. It integrates to 1 minus the
 * no-sample mass of mf_ibm_sample. */
MF_COLD mf_real mf_ibm_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi);

/* mf_ibm_brdf and (in *pdf) mf_ibm_pdf from one weight query (MIS needs both). */
MF_COLD mf_real mf_ibm_brdf_and_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf);

/* Samples wi (Sec. 5.4.3): (u1, u2) a point of the footprint, uniform by
 * area, whose texel's bin j gives the normal t_j; (u3, u4) a visible normal m
 * of the flake Beckmann around t_j for wo; wi = reflect(wo, m). The zero vector
 * (no sample) when wo.t_j <= 0, wi is below the horizon, or the bin j is not
 * in the neighbourhood of beta(h) that mf_ibm_pdf sums (the truncation of Eq.
 * 5.13) - so the density of the returned wi is exactly mf_ibm_pdf. */
MF_COLD mf_sample mf_ibm_sample(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                mf_real u3, mf_real u4);

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
/* Area of the unit square where a linear function is >= 0, from its values
 * v[0..3] at the corners (0,0), (1,0), (1,1), (0,1): the triangle, trapezoid
 * or pentagon that one line cuts, each from crossing fractions v_i / (v_i -
 * v_j) of opposite-signed values (no cancellation). */
MF_INLINE mf_real mf__ibm_square_cut(const mf_real *v)
{
    int k, neg = 0, m = 0;
    for (k = 0; k < 4; ++k) if (v[k] < MF_R(0.0)) { ++neg; m |= 1 << k; }
    if (neg == 0) return MF_R(1.0);
    if (neg == 4) return MF_R(0.0);
    if (m == 5 || m == 10) return MF_R(-1.0);   /* opposite corners below: not a single line */
    {   /* the corner i of the case, by the sign mask (two bits per mask): the
         * one below (neg 1), the one kept (neg 3), the first of the two
         * below (neg 2); only its fractions are divided out */
        int i = (int)((0x68fd210u >> (2 * m)) & 3u), p = (i + 3) & 3, n = (i + 1) & 3, o = (i + 2) & 3;
        mf_real a = v[i], tp = a / (a - v[p]);
        if (neg == 2) return MF_R(1.0) - MF_R(0.5) * (tp + v[n] / (v[n] - v[o]));   /* edge i..n below */
        tp *= a / (a - v[n]);
        return neg == 1 ? MF_R(1.0) - MF_R(0.5) * tp : MF_R(0.5) * tp;   /* corner i cut off / only corner i kept */
    }
}

/* |P ∩ box [X, X + W] x [Y, Y + H]| for a convex polygon P (x, y: n
 * counterclockwise vertices, none repeated) by Green's theorem: the area is
 * the boundary integral of u dv, u = x - X and v = y - Y. That boundary is
 * P's edges clipped to the box (Liang-Barsky; u dv of a segment by the
 * trapezoid rule) and the box's sides inside P, of which only the right one
 * (u = W) adds anything: W times P's chord there, between the crossings of
 * its lower and upper chains (the edges whose half-open x-ranges [x, x')
 * hold W). Each crossing is its edge's own clipping parameter, so that the
 * computed boundary closes (test_ibm: within 1e-6 of the box in float,
 * 1e-13 in double, of the float polygon clipped in double). */
MF_INLINE mf_real mf__ibm_green_area(const mf_real *x, const mf_real *y, int n, mf_real X, mf_real Y, mf_real W, mf_real H)
{
    mf_real s = MF_R(0.0), vb = MF_R(0.0), vt = MF_R(0.0);
    int i, cb = 0, ct = 0;
    for (i = 0; i < n; ++i) {
        int k = i + 1 == n ? 0 : i + 1;
        mf_real qx = x[i] - X, qk = x[k] - X, qy = y[i] - Y, dx = qk - qx, dy = y[k] - Y - qy;
        mf_real t0 = MF_R(0.0), t1 = MF_R(1.0), r, ta, tb;
        if (dx != MF_R(0.0)) {
            r = MF_R(1.0) / dx; ta = -qx * r; tb = (W - qx) * r;
            if (dx > MF_R(0.0) ? qx <= W && W < qk : qk <= W && W < qx) {   /* the chord's end on this edge */
                mf_real v = qy + mf_clamp(tb, MF_R(0.0), MF_R(1.0)) * dy;
                if (dx > MF_R(0.0)) { vb = v; cb = 1; }
                else { vt = v; ct = 1; }
            }
            if (dy == MF_R(0.0)) continue;   /* dv = 0 */
            t0 = mf_max(t0, mf_min(ta, tb)); t1 = mf_min(t1, mf_max(ta, tb));
        } else if (dy == MF_R(0.0) || !(qx >= MF_R(0.0) && qx <= W)) continue;   /* a vertical edge outside */
        r = MF_R(1.0) / dy; ta = -qy * r; tb = (H - qy) * r;
        t0 = mf_max(t0, mf_min(ta, tb)); t1 = mf_min(t1, mf_max(ta, tb));
        if (t1 > t0) s += dy * (t1 - t0) * (qx + MF_R(0.5) * dx * (t0 + t1));
    }
    if (cb && ct) s += W * mf_max(mf_clamp(vt, MF_R(0.0), H) - mf_clamp(vb, MF_R(0.0), H), MF_R(0.0));
    return mf_clamp(s, MF_R(0.0), W * H);
}

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

typedef struct mf__ibm_fp {
    int mode, tx, ty;          /* POINT: the texel */
    int direct;                /* sum the covered texels directly (Eq. 5.2) */
    int few;                   /* direct, and A is small (bounding box <= 16 texels) or thin */
    int tiny;                  /* few, small, neither thin nor axis-aligned: texel areas row by row */
    int bx0, by0, bx1, by1;    /* direct: texels [bx0, bx1) x [by0, by1) (unwrapped) hold A */
    int rect;                  /* axis-aligned: every piece is a rectangle */
    int inner;                 /* every corner in the first period: A is its only piece, unclipped */
    int row0, row1;            /* period rows touched */
    mf_real x[4], y[4];        /* corners in texels, counterclockwise, center in the first period */
    mf_real cx, cy, ax, ay, bx, by;   /* center and edges in texels */
    mf_real area;              /* |A| in texels */
    mf_real ex, ey;            /* half extents of A's bounding box */
    mf_real full;              /* periods entirely inside A */
} mf__ibm_fp;

/* A convex piece of the footprint inside one period, shifted to the first. */
typedef struct mf__ibm_piece {
    int ox, oy;                     /* integer origin of the relative coordinates */
    int bx0, by0, bx1, by1;         /* texels [bx0,bx1) x [by0,by1) it can touch */
    int n, rect;
    mf_real x[12], y[12];           /* vertices relative to the origin, counterclockwise */
    mf_real ea[12], eb[12], ec[12]; /* unit half-planes ea x + eb y + ec >= 0 */
    mf_real elo[12], ehi[12];       /* least and largest of ea x + eb y over the unit square */
    mf_real rx0, ry0, rx1, ry1;     /* the rectangle (rect) */
    int ix0, iy0, ix1, iy1;         /* texels [ix0,ix1) x [iy0,iy1) lie wholly inside (may be empty) */
} mf__ibm_piece;

/* Clips a convex polygon to coord >= value (sgn = 1) or <= value (sgn = -1)
 * along axis 0 (x) or 1 (y); crossing points get the exact value. */
MF_INLINE int mf__ibm_clip_axis(const mf_real *xi, const mf_real *yi, int n, int axis, mf_real value, mf_real sgn,
                                mf_real *xo, mf_real *yo)
{
    int i, m = 0;
    for (i = 0; i < n; ++i) {
        int k = i + 1 == n ? 0 : i + 1;
        mf_real di = sgn * ((axis ? yi[i] : xi[i]) - value), dk = sgn * ((axis ? yi[k] : xi[k]) - value);
        if (di >= MF_R(0.0)) { xo[m] = xi[i]; yo[m] = yi[i]; ++m; }
        if ((di >= MF_R(0.0)) != (dk >= MF_R(0.0))) {
            mf_real t = di / (di - dk);
            if (axis) { xo[m] = xi[i] + t * (xi[k] - xi[i]); yo[m] = value; }
            else { xo[m] = value; yo[m] = yi[i] + t * (yi[k] - yi[i]); }
            ++m;
        }
    }
    return m;
}

/* Shoelace area of a polygon (counterclockwise: positive), its coordinates
 * taken about (ox, oy). */
MF_INLINE mf_real mf__ibm_shoelace(const mf_real *x, const mf_real *y, int n, mf_real ox, mf_real oy)
{
    mf_real s = MF_R(0.0);
    int i;
    for (i = 0; i < n; ++i) {
        int k = i + 1 == n ? 0 : i + 1;
        s += (x[i] - ox) * (y[k] - oy) - (x[k] - ox) * (y[i] - oy);
    }
    return MF_R(0.5) * s;
}

/* The footprint clipped to period row `row` (y in [row H, (row+1) H]). */
MF_INLINE int mf__ibm_slab(const mf_ibm *ibm, const mf__ibm_fp *p, int row, mf_real *xo, mf_real *yo)
{
    mf_real tx[12], ty[12], H = (mf_real)ibm->height;
    int n = mf__ibm_clip_axis(p->x, p->y, 4, 1, (mf_real)row * H, MF_R(1.0), tx, ty);
    return mf__ibm_clip_axis(tx, ty, n, 1, (mf_real)(row + 1) * H, MF_R(-1.0), xo, yo);
}

/* Columns of a slab: all cells [*c0, *c1] it touches and the full ones
 * [*f0, *f1] (empty when *f1 < *f0): cells whose whole square lies inside A,
 * i.e. inside both chords of A at the slab's bottom and top (A is convex). */
MF_INLINE void mf__ibm_slab_columns(const mf_ibm *ibm, int row, const mf_real *x, const mf_real *y, int n, mf_real *c0,
                                    mf_real *c1, mf_real *f0, mf_real *f1)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, y0 = (mf_real)row * H, y1 = (mf_real)(row + 1) * H;
    mf_real lo = x[0], hi = x[0], l0 = MF_BIG, r0 = -MF_BIG, l1 = MF_BIG, r1 = -MF_BIG;
    int i;
    for (i = 0; i < n; ++i) {
        lo = mf_min(lo, x[i]); hi = mf_max(hi, x[i]);
        if (y[i] == y0) { l0 = mf_min(l0, x[i]); r0 = mf_max(r0, x[i]); }
        if (y[i] == y1) { l1 = mf_min(l1, x[i]); r1 = mf_max(r1, x[i]); }
    }
    *c0 = MF_FLOOR(lo / W);
    *c1 = MF_FLOOR(hi / W);
    if (*c1 > *c0 && hi == *c1 * W) *c1 -= MF_R(1.0);   /* touches the next column only on its edge */
    *f0 = MF_R(1.0); *f1 = MF_R(0.0);
    if (l0 <= r0 && l1 <= r1) {
        *f0 = MF_CEIL(mf_max(l0, l1) / W);
        *f1 = MF_FLOOR(mf_min(r0, r1) / W) - MF_R(1.0);
    }
}

/* A footprint's shape, the first half of mf__ibm_footprint: the center
 * wrapped into the first period, the edges in texels, |A|, the corners, and
 * whether they all lie in the first period (inner). 1 when the corners are
 * set (mode GLOBAL until mf__ibm_footprint has counted the cut cells);
 * 0 when the mode is final (NONE, POINT, or GLOBAL for a huge A). */
MF_INLINE int mf__ibm_footprint_shape(const mf_ibm *ibm, const mf_footprint *f, mf__ibm_fp *p)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, cross, ex, ey;
    int edges_ok;
    p->mode = MF__IBM_NONE;
    p->direct = p->few = p->tiny = p->inner = 0;
    p->full = MF_R(0.0);
    if (!f) return 0;
    /* bits, not comparisons, so that -ffast-math keeps NaN from the indices */
    if (!mf__finite_bits(f->u) || !mf__finite_bits(f->v)) return 0;
    edges_ok = mf__finite_bits(f->ax) && mf__finite_bits(f->ay) && mf__finite_bits(f->bx) && mf__finite_bits(f->by);
    p->cx = f->u * W; p->cy = f->v * H;
    if (!(MF_FABS(p->cx) < MF_BIG) || !(MF_FABS(p->cy) < MF_BIG)) return 0;
    if (!(p->cx >= MF_R(0.0) && p->cx < W)) p->cx -= W * MF_FLOOR(p->cx / W);   /* into the first period */
    if (!(p->cy >= MF_R(0.0) && p->cy < H)) p->cy -= H * MF_FLOOR(p->cy / H);
    if (!(p->cx >= MF_R(0.0)) || !(p->cx < W)) p->cx = MF_R(0.0);   /* rounding at the period edge */
    if (!(p->cy >= MF_R(0.0)) || !(p->cy < H)) p->cy = MF_R(0.0);
    p->tx = (int)p->cx; if (p->tx >= ibm->width || p->tx < 0) p->tx = p->tx < 0 ? 0 : ibm->width - 1;
    p->ty = (int)p->cy; if (p->ty >= ibm->height || p->ty < 0) p->ty = p->ty < 0 ? 0 : ibm->height - 1;
    if (!edges_ok) { p->mode = MF__IBM_POINT; return 0; }
    p->ax = f->ax * W; p->ay = f->ay * H; p->bx = f->bx * W; p->by = f->by * H;
    cross = p->ax * p->by - p->ay * p->bx;
    p->area = MF_FABS(cross);
    if (!(p->area >= MF_IBM_MIN_AREA)) { p->mode = MF__IBM_POINT; return 0; }
    {   /* a sliver thinner than 64 ulps of its coordinates would turn the
         * clipped areas into round-off (float): widen it across its longer
         * edge to that thickness (the sampler uses these same edges). 64
         * measured best against double: L1 of the weights <= 4e-3 for any
         * thickness (none: up to 1, as round-off; 1024: 0.65, as widening) */
        mf_real la2 = p->ax * p->ax + p->ay * p->ay, lb2 = p->bx * p->bx + p->by * p->by, lm, tmin, grow;
        /* lm <= l1, the larger L1 length: no sliver when the area passes with l1 */
        mf_real l1 = mf_max(MF_FABS(p->ax) + MF_FABS(p->ay), MF_FABS(p->bx) + MF_FABS(p->by));
        lm = l1 < MF_BIG && p->area >= MF_R(64.0) * MF_EPS * (mf_max(W, H) + l1) * l1 ? MF_R(0.0) : MF_SQRT(mf_max(la2, lb2));
        tmin = MF_R(64.0) * MF_EPS * (mf_max(W, H) + lm);
        if (lm > MF_R(0.0) && lm < MF_BIG && p->area < tmin * lm) {
            grow = (tmin * lm - p->area) / lm * (cross > MF_R(0.0) ? MF_R(1.0) : MF_R(-1.0));
            if (la2 >= lb2) { p->bx -= grow * p->ay / lm; p->by += grow * p->ax / lm; }   /* b moves along a's normal */
            else { p->ax += grow * p->by / lm; p->ay -= grow * p->bx / lm; }              /* a along b's */
            cross = p->ax * p->by - p->ay * p->bx;
            p->area = MF_FABS(cross);
        }
    }
    p->ex = ex = MF_R(0.5) * (MF_FABS(p->ax) + MF_FABS(p->bx));
    p->ey = ey = MF_R(0.5) * (MF_FABS(p->ay) + MF_FABS(p->by));
    p->mode = MF__IBM_GLOBAL;
    if (!(p->area < MF_BIG) || !(ex < (mf_real)MF_IBM_MAX_PIECES * W) || !(ey < (mf_real)MF_IBM_MAX_PIECES * H)) return 0;
    {
        mf_real sa = cross > MF_R(0.0) ? MF_R(0.5) : MF_R(-0.5);   /* counterclockwise corners */
        p->x[0] = p->cx - MF_R(0.5) * p->ax - sa * p->bx; p->y[0] = p->cy - MF_R(0.5) * p->ay - sa * p->by;
        p->x[1] = p->cx + MF_R(0.5) * p->ax - sa * p->bx; p->y[1] = p->cy + MF_R(0.5) * p->ay - sa * p->by;
        p->x[2] = p->cx + MF_R(0.5) * p->ax + sa * p->bx; p->y[2] = p->cy + MF_R(0.5) * p->ay + sa * p->by;
        p->x[3] = p->cx - MF_R(0.5) * p->ax + sa * p->bx; p->y[3] = p->cy - MF_R(0.5) * p->ay + sa * p->by;
    }
    p->rect = (p->ay == MF_R(0.0) && p->bx == MF_R(0.0)) || (p->ax == MF_R(0.0) && p->by == MF_R(0.0));
    {   /* clipping A to the period's row and column would keep its corners as they are */
        mf_real lx = mf_min(mf_min(p->x[0], p->x[1]), mf_min(p->x[2], p->x[3]));
        mf_real hx = mf_max(mf_max(p->x[0], p->x[1]), mf_max(p->x[2], p->x[3]));
        mf_real ly = mf_min(mf_min(p->y[0], p->y[1]), mf_min(p->y[2], p->y[3]));
        mf_real hy = mf_max(mf_max(p->y[0], p->y[1]), mf_max(p->y[2], p->y[3]));
        p->inner = lx >= MF_R(0.0) && hx <= W && ly >= MF_R(0.0) && hy <= H;
    }
    return 1;
}

/* The second half of mf__ibm_footprint, for a footprint whose shape is
 * set (mf__ibm_footprint_shape returned 1): the periods it covers entirely
 * and the cells its boundary cuts. More than MF_IBM_MAX_PIECES cut cells
 * (or rows): the whole map's histogram (MF__IBM_GLOBAL, see
 * mf_ibm_bin_weight). */
MF_INLINE void mf__ibm_footprint_cells(const mf_ibm *ibm, mf__ibm_fp *p)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, ex = p->ex, ey = p->ey, xs[12], ys[12];
    int row, pieces = 0;
    p->row0 = p->cy - ey >= MF_R(0.0) ? 0 : (int)MF_FLOOR((p->cy - ey) / H);   /* cy is in [0, H) */
    p->row1 = p->cy + ey < H ? 0 : (int)MF_FLOOR((p->cy + ey) / H);
    if (p->row1 > p->row0 && p->cy + ey == (mf_real)p->row1 * H) --p->row1;
    /* narrower than a period both ways: no full period and at most 4 cut
     * cells, so the count is only needed for wider footprints */
    if (!(MF_R(2.0) * ex < W && MF_R(2.0) * ey < H))
        for (row = p->row0; row <= p->row1; ++row) {
            mf_real c0, c1, f0, f1, nf = MF_R(0.0);
            int n = mf__ibm_slab(ibm, p, row, xs, ys);
            if (n < 3) continue;
            mf__ibm_slab_columns(ibm, row, xs, ys, n, &c0, &c1, &f0, &f1);
            if (f1 >= f0) { nf = f1 - f0 + MF_R(1.0); p->full += nf; }
            pieces += (int)(c1 - c0 + MF_R(1.0) - nf);
            if (pieces > MF_IBM_MAX_PIECES) { p->full = MF_R(0.0); return; }
        }
    p->mode = MF__IBM_EXACT;
    if (p->full > MF_R(0.0)) p->inner = 0;   /* A is the whole period: counted as full */
    if (p->inner) p->row0 = p->row1 = 0;      /* its only row (rounding in ey may reach the next) */
    p->direct = p->full == MF_R(0.0) && MF_R(4.0) * ex * ey <= (mf_real)MF_IBM_DIRECT_TEXELS;
    /* a few texels, or thin: their clipped areas give |A| (see mf__ibm_weights) */
    {
        int small = MF_R(4.0) * ex * ey <= MF_R(16.0), thin = MF_R(32.0) * p->area <= MF_R(4.0) * ex * ey;
        p->few = p->direct && (small || thin);
        p->tiny = p->direct && small && !thin && !p->rect;
    }
    if (p->direct) {
        p->bx0 = mf__ibm_ifloor(p->cx - ex); p->bx1 = mf__ibm_iceil(p->cx + ex);
        p->by0 = mf__ibm_ifloor(p->cy - ey); p->by1 = mf__ibm_iceil(p->cy + ey);
    }
}

/* Classifies a footprint: its shape (mf__ibm_footprint_shape), then its
 * periods and cut cells (mf__ibm_footprint_cells). Zero area or a
 * non-finite edge: the texel at the center; a non-finite center: nothing. */
MF_INLINE void mf__ibm_footprint(const mf_ibm *ibm, const mf_footprint *f, mf__ibm_fp *p)
{
    if (mf__ibm_footprint_shape(ibm, f, p)) mf__ibm_footprint_cells(ibm, p);
}

/* a piece's vertex count, rectangle flag and its extent [lx, hx] x [ly, hy]
 * (first-period coordinates) relative to its origin */
MF_INLINE void mf__ibm_piece_close(mf__ibm_piece *pc, const mf__ibm_fp *p, int m, mf_real lx, mf_real hx, mf_real ly, mf_real hy)
{
    pc->n = m;
    pc->rect = p->rect;
    pc->rx0 = lx - (mf_real)pc->ox; pc->rx1 = hx - (mf_real)pc->ox;
    pc->ry0 = ly - (mf_real)pc->oy; pc->ry1 = hy - (mf_real)pc->oy;
}

/* The polygon of the piece of slab (x, y, n) in column `col`, shifted to the
 * first period: vertices relative to (ox, oy), its texel box and rectangle;
 * 0 if it has no area. */
MF_INLINE int mf__ibm_piece_poly(const mf_ibm *ibm, const mf__ibm_fp *p, int row, int col, const mf_real *x,
                                 const mf_real *y, int n, mf__ibm_piece *pc)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, tx[12], ty[12], lx, ly, hx, hy, sx, sy;
    int i, m = n;
    if (p->inner) for (i = 0; i < n; ++i) { pc->x[i] = x[i]; pc->y[i] = y[i]; }
    else {
        m = mf__ibm_clip_axis(x, y, n, 0, (mf_real)col * W, MF_R(1.0), tx, ty);
        m = mf__ibm_clip_axis(tx, ty, m, 0, (mf_real)(col + 1) * W, MF_R(-1.0), pc->x, pc->y);
    }
    if (m < 3) return 0;
    sx = (mf_real)col * W; sy = (mf_real)row * H;
    lx = hx = pc->x[0] - sx; ly = hy = pc->y[0] - sy;
    for (i = 0; i < m; ++i) {
        pc->x[i] -= sx; pc->y[i] -= sy;
        lx = mf_min(lx, pc->x[i]); hx = mf_max(hx, pc->x[i]);
        ly = mf_min(ly, pc->y[i]); hy = mf_max(hy, pc->y[i]);
    }
    pc->ox = mf__ibm_ifloor(lx); pc->oy = mf__ibm_ifloor(ly);
    if (pc->ox < 0) pc->ox = 0;
    if (pc->oy < 0) pc->oy = 0;
    pc->bx0 = pc->ox; pc->by0 = pc->oy;
    pc->bx1 = mf__ibm_iceil(hx); pc->by1 = mf__ibm_iceil(hy);
    if (pc->bx1 > ibm->width) pc->bx1 = ibm->width;
    if (pc->by1 > ibm->height) pc->by1 = ibm->height;
    if (pc->bx1 <= pc->bx0 || pc->by1 <= pc->by0) return 0;
    /* relative coordinates, without repeated vertices (clipping a corner that
     * lies on a period edge repeats it; a zero-length edge has no half-plane) */
    {
        int k = 0;
        for (i = 0; i < m; ++i) {
            mf_real vx = pc->x[i] - (mf_real)pc->ox, vy = pc->y[i] - (mf_real)pc->oy;
            if (k > 0 && vx == pc->x[k - 1] && vy == pc->y[k - 1]) continue;
            pc->x[k] = vx; pc->y[k] = vy; ++k;
        }
        while (k > 1 && pc->x[k - 1] == pc->x[0] && pc->y[k - 1] == pc->y[0]) --k;
        m = k;
    }
    if (m < 3 || !(mf__ibm_shoelace(pc->x, pc->y, m, MF_R(0.0), MF_R(0.0)) > MF_R(0.0))) return 0;
    mf__ibm_piece_close(pc, p, m, lx, hx, ly, hy);
    return 1;
}

/* edge i's half-plane a x + b y + c >= 0 (a, b a unit normal) and the least
 * and largest of a x + b y over the unit square */
MF_INLINE void mf__ibm_half_plane(mf__ibm_piece *pc, int i, mf_real a, mf_real b, mf_real c)
{
    pc->ea[i] = a; pc->eb[i] = b; pc->ec[i] = c;
    pc->elo[i] = mf_min(a, MF_R(0.0)) + mf_min(b, MF_R(0.0));
    pc->ehi[i] = mf_max(a, MF_R(0.0)) + mf_max(b, MF_R(0.0));
}

/* A piece's polygon (mf__ibm_piece_poly) and the unit half-planes of its
 * edges: all that mf__ibm_texel_area needs; 0 if it has no area. */
MF_INLINE int mf__ibm_piece_edges(const mf_ibm *ibm, const mf__ibm_fp *p, int row, int col, const mf_real *x,
                                  const mf_real *y, int n, mf__ibm_piece *pc)
{
    int i, m;
    if (!mf__ibm_piece_poly(ibm, p, row, col, x, y, n, pc)) return 0;
    m = pc->n;
    for (i = 0; i < m; ++i) {
        int k = i + 1 == m ? 0 : i + 1;
        mf_real a = pc->y[i] - pc->y[k], b = pc->x[k] - pc->x[i], l = MF_SQRT(a * a + b * b);
        if (l > MF_R(0.0)) { a /= l; b /= l; }
        mf__ibm_half_plane(pc, i, a, b, l > MF_R(0.0) ? -(a * pc->x[i] + b * pc->y[i]) : MF_R(1.0));
    }
    return 1;
}

/* A itself as a piece, unclipped: for a footprint inside the period
 * (inner), mf__ibm_piece_edges without the clipping and the repeated-vertex
 * pass (a parallelogram's opposite edges share their normal); for one
 * across the period's border, the areas of its texels' images beyond it
 * (mf__ibm_weights_few). 0 where an edge rounds to zero length or A's box
 * holds no texel. */
MF_INLINE int mf__ibm_piece_inner(const mf__ibm_fp *p, mf__ibm_piece *pc)
{
    mf_real lx = mf_min(mf_min(p->x[0], p->x[1]), mf_min(p->x[2], p->x[3]));
    mf_real hx = mf_max(mf_max(p->x[0], p->x[1]), mf_max(p->x[2], p->x[3]));
    mf_real ly = mf_min(mf_min(p->y[0], p->y[1]), mf_min(p->y[2], p->y[3]));
    mf_real hy = mf_max(mf_max(p->y[0], p->y[1]), mf_max(p->y[2], p->y[3]));
    mf_real a[2], b[2];
    int i;
    pc->ox = pc->bx0 = mf__ibm_ifloor(lx); pc->oy = pc->by0 = mf__ibm_ifloor(ly);
    pc->bx1 = mf__ibm_iceil(hx); pc->by1 = mf__ibm_iceil(hy);
    if (pc->bx1 <= pc->bx0 || pc->by1 <= pc->by0) return 0;
    for (i = 0; i < 4; ++i) { pc->x[i] = p->x[i] - (mf_real)pc->ox; pc->y[i] = p->y[i] - (mf_real)pc->oy; }
    for (i = 0; i < 2; ++i) {   /* edges 0 -> 1 and 1 -> 2; 2 -> 3 and 3 -> 0 point back */
        mf_real ea = pc->y[i] - pc->y[i + 1], eb = pc->x[i + 1] - pc->x[i], l = MF_SQRT(ea * ea + eb * eb);
        if (!(l > MF_R(0.0))) return 0;
        a[i] = ea / l; b[i] = eb / l;
    }
    for (i = 0; i < 4; ++i) {
        mf_real ea = i < 2 ? a[i] : -a[i - 2], eb = i < 2 ? b[i] : -b[i - 2];
        mf__ibm_half_plane(pc, i, ea, eb, -(ea * pc->x[i] + eb * pc->y[i]));
    }
    mf__ibm_piece_close(pc, p, 4, lx, hx, ly, hy);
    return 1;
}

/* The whole piece: its polygon and edges (mf__ibm_piece_edges) and the
 * texels wholly inside; 0 if it has no area. */
MF_INLINE int mf__ibm_piece_make(const mf_ibm *ibm, const mf__ibm_fp *p, int row, int col, const mf_real *x,
                                 const mf_real *y, int n, mf__ibm_piece *pc)
{
    int i, m;
    if (!mf__ibm_piece_edges(ibm, p, row, col, x, y, n, pc)) return 0;
    m = pc->n;
    {   /* texels [ix0, ix1) x [iy0, iy1) wholly inside (area 1 without
         * clipping): the rectangle itself, or a square about the vertex
         * mean that every edge keeps, less a margin of 0.05 texel so
         * that these texels pass mf__ibm_texel_area's test as well */
        mf_real mx = MF_R(0.0), my = MF_R(0.0), h = MF_BIG, x0, x1, y0, y1;
        if (pc->rect) { x0 = pc->rx0; x1 = pc->rx1; y0 = pc->ry0; y1 = pc->ry1; }
        else {
            for (i = 0; i < m; ++i) { mx += pc->x[i]; my += pc->y[i]; }
            mx /= (mf_real)m; my /= (mf_real)m;
            /* unit normals: |a| + |b| <= sqrt 2, so d / sqrt 2 is a half side every edge keeps */
            for (i = 0; i < m; ++i)
                if (pc->ea[i] != MF_R(0.0) || pc->eb[i] != MF_R(0.0)) h = mf_min(h, pc->ea[i] * mx + pc->eb[i] * my + pc->ec[i]);
            h = MF_R(0.7064) * h - MF_R(0.05);
            x0 = mx - h; x1 = mx + h; y0 = my - h; y1 = my + h;
        }
        pc->ix0 = pc->ix1 = pc->iy0 = pc->iy1 = 0;
        if (x1 > x0 && y1 > y0 && MF_FABS(x0) < MF_BIG && MF_FABS(y0) < MF_BIG) {
            pc->ix0 = pc->ox + mf__ibm_iceil(x0); pc->ix1 = pc->ox + mf__ibm_ifloor(x1);
            pc->iy0 = pc->oy + mf__ibm_iceil(y0); pc->iy1 = pc->oy + mf__ibm_ifloor(y1);
            if (pc->ix0 < pc->bx0) pc->ix0 = pc->bx0;
            if (pc->iy0 < pc->by0) pc->iy0 = pc->by0;
            if (pc->ix1 > pc->bx1) pc->ix1 = pc->bx1;
            if (pc->iy1 > pc->by1) pc->iy1 = pc->by1;
            if (pc->ix1 <= pc->ix0 || pc->iy1 <= pc->iy0) pc->ix0 = pc->ix1 = pc->iy0 = pc->iy1 = 0;
        }
    }
    return 1;
}

/* The edges' part of mf__ibm_classify: -1 when box [X0, X1] x [Y0, Y1]
 * (relative coordinates) lies outside an edge, 1 when inside them all, else
 * 0. No early exit: where n is the constant 4 (a parallelogram, the common
 * piece) the loop becomes straight code without branches. */
MF_FORCE_INLINE int mf__ibm_classify_edges(const mf__ibm_piece *pc, int n, mf_real X0, mf_real Y0, mf_real X1, mf_real Y1)
{
    int i, out = 0, cut = 0;
    for (i = 0; i < n; ++i) {
        /* the least and largest of a x + b y over the box: the products at
         * its two x (y) bounds, ordered (rounding keeps their order) */
        mf_real a = pc->ea[i], b = pc->eb[i], ax0 = a * X0, ax1 = a * X1, by0 = b * Y0, by1 = b * Y1;
        mf_real lo = pc->ec[i] + mf_min(ax0, ax1) + mf_min(by0, by1);
        mf_real hi = pc->ec[i] + mf_max(ax0, ax1) + mf_max(by0, by1);
        out |= hi <= MF_R(0.0);
        cut |= lo < MF_R(0.0);
    }
    return out ? -1 : !cut;
}

/* Box [x0,x1) x [y0,y1) (texels) against a piece: -1 outside, 1 inside, 0
 * cut (separating axes: the box's and the piece's edges, exact for convex). */
MF_FORCE_INLINE int mf__ibm_classify(const mf__ibm_piece *pc, int x0, int y0, int x1, int y1)
{
    mf_real X0, Y0, X1, Y1;
    if (x1 <= pc->bx0 || x0 >= pc->bx1 || y1 <= pc->by0 || y0 >= pc->by1) return -1;
    X0 = (mf_real)(x0 - pc->ox); X1 = (mf_real)(x1 - pc->ox);
    Y0 = (mf_real)(y0 - pc->oy); Y1 = (mf_real)(y1 - pc->oy);
    if (pc->rect) {
        if (X1 <= pc->rx0 || X0 >= pc->rx1 || Y1 <= pc->ry0 || Y0 >= pc->ry1) return -1;
        return X0 >= pc->rx0 && X1 <= pc->rx1 && Y0 >= pc->ry0 && Y1 <= pc->ry1 ? 1 : 0;
    }
    return pc->n == 4 ? mf__ibm_classify_edges(pc, 4, X0, Y0, X1, Y1) : mf__ibm_classify_edges(pc, pc->n, X0, Y0, X1, Y1);
}

/* |piece ∩ box [X, X + W] x [Y, Y + H]| (relative coordinates): W H inside,
 * 0 outside (elo, ehi: the least and largest of ea x + eb y over the box
 * less its corner, per edge); one cutting edge in closed form, more by
 * mf__ibm_green_area. */
MF_INLINE mf_real mf__ibm_rect_area(const mf__ibm_piece *pc, mf_real X, mf_real Y, mf_real W, mf_real H,
                                    const mf_real *elo, const mf_real *ehi)
{
    mf_real cv = MF_R(0.0);
    int i, cut = 0, nc = 0;
    if (pc->rect) {
        mf_real w = mf_min(X + W, pc->rx1) - mf_max(X, pc->rx0);
        mf_real h = mf_min(Y + H, pc->ry1) - mf_max(Y, pc->ry0);
        return w > MF_R(0.0) && h > MF_R(0.0) ? w * h : MF_R(0.0);
    }
    for (i = 0; i < pc->n; ++i) {
        mf_real v = pc->ea[i] * X + pc->eb[i] * Y + pc->ec[i];
        if (v + ehi[i] <= MF_R(0.0)) return MF_R(0.0);
        if (v + elo[i] < MF_R(0.0)) { cut = i; cv = v; ++nc; }
    }
    if (nc == 0) return W * H;
    if (nc == 1) {   /* one edge cuts the box (most boundary texels): closed form */
        mf_real a = pc->ea[cut] * W, b = pc->eb[cut] * H, v[4], r;
        v[0] = cv; v[1] = cv + a; v[2] = cv + a + b; v[3] = cv + b;
        r = mf__ibm_square_cut(v);   /* the fraction of the box: the map to the unit square is affine */
        if (r >= MF_R(0.0)) return r * W * H;
    }
    return mf__ibm_green_area(pc->x, pc->y, pc->n, X, Y, W, H);
}

/* |piece ∩ texel (tx, ty)| in texels (mf__ibm_rect_area of the unit square) */
MF_INLINE mf_real mf__ibm_texel_area(const mf__ibm_piece *pc, int tx, int ty)
{
    return mf__ibm_rect_area(pc, (mf_real)(tx - pc->ox), (mf_real)(ty - pc->oy), MF_R(1.0), MF_R(1.0), pc->elo, pc->ehi);
}

/* |piece ∩ box [x0, x1) x [y0, y1)| in texels (mf__ibm_rect_area): the
 * weight of a kd node all of whose texels lie in one bin */
MF_INLINE mf_real mf__ibm_box_area(const mf__ibm_piece *pc, int x0, int y0, int x1, int y1)
{
    mf_real W = (mf_real)(x1 - x0), H = (mf_real)(y1 - y0), lo[12], hi[12];
    int i;
    for (i = 0; i < pc->n; ++i) {
        mf_real a = pc->ea[i] * W, b = pc->eb[i] * H;
        lo[i] = mf_min(a, MF_R(0.0)) + mf_min(b, MF_R(0.0));
        hi[i] = mf_max(a, MF_R(0.0)) + mf_max(b, MF_R(0.0));
    }
    return mf__ibm_rect_area(pc, (mf_real)(x0 - pc->ox), (mf_real)(y0 - pc->oy), W, H, lo, hi);
}

/* The bins whose weights a query needs: those of the window (cx + dx, cy + dy),
 * |dx|, |dy| <= r, that are listed; slot maps a window cell to its list entry. */
typedef struct mf__ibm_set {
    int cx, cy, r, side, n;
    int mapped;                      /* found in the bin map's rows (mf__ibm_direct_any) */
    int bin[MF_IBM_MAX_WINDOW];
    short slot[MF_IBM_MAX_WINDOW];
    mf_real w[MF_IBM_MAX_WINDOW];    /* accumulated area, then weight */
} mf__ibm_set;

MF_INLINE void mf__ibm_set_init(mf__ibm_set *s, int cx, int cy, int r)
{
    int i;
    s->cx = cx; s->cy = cy; s->r = r; s->side = 2 * r + 1; s->n = s->mapped = 0;
    for (i = 0; i < s->side * s->side; ++i) s->slot[i] = -1;
}

/* index in slot of window cell (dx, dy), |dx|, |dy| <= r */
MF_INLINE int mf__ibm_set_cell(const mf__ibm_set *s, int dx, int dy)
{
    return (dy + s->r) * s->side + dx + s->r;
}

/* adds window cell (dx, dy) (bin j) to the list */
MF_INLINE void mf__ibm_set_add(mf__ibm_set *s, int dx, int dy, int j)
{
    s->slot[mf__ibm_set_cell(s, dx, dy)] = (short)s->n;
    s->bin[s->n] = j;
    s->w[s->n] = MF_R(0.0);
    ++s->n;
}

/* list entry of a bin map value (ix | iy << s), or -1 */
MF_INLINE int mf__ibm_set_find(const mf_ibm *ibm, const mf__ibm_set *s, unsigned int v)
{
    int ix, iy, dx, dy;
    if (s->r == 0) return v == ((unsigned int)s->cx | ((unsigned int)s->cy << ibm->axis_bits)) ? s->slot[0] : -1;
    ix = (int)(v & ((1u << ibm->axis_bits) - 1u)); iy = (int)(v >> ibm->axis_bits);
    dx = ix - s->cx; dy = iy - s->cy;
    if (dx < -s->r || dx > s->r || dy < -s->r || dy > s->r) return -1;
    return s->slot[mf__ibm_set_cell(s, dx, dy)];
}

/* Direct texel sum over a piece (Eq. 5.2-5.3 grouped by bin): a texel's bin
 * is read first and its area clipped only when the bin is wanted. With
 * `all`, every texel's area is clipped and their sum returned (the piece's
 * area as the texel areas add up); otherwise 0. */
MF_INLINE mf_real mf__ibm_direct(const mf_ibm *ibm, const mf__ibm_piece *pc, mf__ibm_set *s, int all)
{
    mf_real tot = MF_R(0.0);
    int x, y;
    for (y = pc->by0; y < pc->by1; ++y)
        for (x = pc->bx0; x < pc->bx1; ++x) {
            int k = mf__ibm_set_find(ibm, s, mf__ibm_get(ibm->data + ibm->bin_at, (size_t)y * (size_t)ibm->width + (size_t)x, ibm->bin_bits));
            mf_real a;
            if (k < 0 && !all) continue;
            a = mf__ibm_texel_area(pc, x, y);
            if (!(a > MF_R(0.0))) continue;
            tot += a;
            if (k >= 0) s->w[k] += a;
        }
    return tot;
}

/* Direct texel sum over a piece of a few texels (Eq. 5.2-5.3), row by row:
 * the piece cut to each texel row once, that band's area in each texel's
 * column by Green's theorem along its edges alone (mf__ibm_texel_area would
 * clip the texel by every edge that cuts it: most texels of a piece this
 * small hold a corner). Returns the sum of all the texels' areas (the
 * piece's area as they add up). */
MF_INLINE mf_real mf__ibm_direct_rows(const mf_ibm *ibm, const mf__ibm_piece *pc, mf__ibm_set *s)
{
    mf_real tot = MF_R(0.0), ta[12], tb[12], bx[12], by[12], sl[12];
    int ty;
    for (ty = pc->by0; ty < pc->by1; ++ty) {
        mf_real Y = (mf_real)(ty - pc->oy), lo, hi;
        int n = mf__ibm_clip_axis(pc->x, pc->y, pc->n, 1, Y, MF_R(1.0), ta, tb), i, tx, x0, x1;
        n = mf__ibm_clip_axis(ta, tb, n, 1, Y + MF_R(1.0), MF_R(-1.0), bx, by);
        if (n < 3) continue;
        lo = hi = bx[0];
        for (i = 1; i < n; ++i) { lo = mf_min(lo, bx[i]); hi = mf_max(hi, bx[i]); }
        x0 = pc->ox + mf__ibm_ifloor(lo); x1 = pc->ox + mf__ibm_iceil(hi);
        if (x0 < pc->bx0) x0 = pc->bx0;
        if (x1 > pc->bx1) x1 = pc->bx1;
        /* each edge's slope, for its y across the texels' columns */
        for (i = 0; i < n; ++i) {
            int k = i + 1 == n ? 0 : i + 1;
            mf_real d = bx[k] - bx[i];
            sl[i] = d != MF_R(0.0) ? (by[k] - by[i]) / d : MF_R(0.0);
        }
        for (tx = x0; tx < x1; ++tx) {
            /* the band's area in column [X, X + 1] by Green's theorem,
             * -(y - Y) dx around it: its edges within the column, each a
             * trapezoid under its midpoint (the column's sides have dx = 0) */
            mf_real X = (mf_real)(tx - pc->ox), a = MF_R(0.0);
            int k;
            for (i = 0; i < n; ++i) {
                mf_real xa = bx[i], xb = bx[i + 1 == n ? 0 : i + 1], l, h;
                if (xa == xb) continue;
                l = mf_max(mf_min(xa, xb), X); h = mf_min(mf_max(xa, xb), X + MF_R(1.0));
                if (!(h > l)) continue;
                l = (h - l) * (by[i] - Y + MF_R(0.5) * sl[i] * (l + h - MF_R(2.0) * xa));
                a += xa < xb ? -l : l;   /* the lower chain runs right, the upper left */
            }
            if (!(a > MF_R(0.0))) continue;
            a = mf_min(a, MF_R(1.0));
            tot += a;
            k = mf__ibm_set_find(ibm, s, mf__ibm_get(ibm->data + ibm->bin_at, (size_t)ty * (size_t)ibm->width + (size_t)tx, ibm->bin_bits));
            if (k >= 0) s->w[k] += a;
        }
    }
    return tot;
}

/* The direct footprint's bounding box (wrapped), by its texels' bins: with
 * `collect` 0, 1 if one of them is listed in s (an index-only test that
 * spares the clipping when no texel is wanted); with `collect` 1, lists in s
 * (empty, centered on the half vector's bin) every bin of the box within its
 * radius, r(r+1), and returns how many: for a footprint of a few texels the
 * only bins that can have weight, found without reading the index. */
MF_INLINE int mf__ibm_direct_any(const mf_ibm *ibm, const mf__ibm_fp *p, mf__ibm_set *s, int collect)
{
    int x, y, W = ibm->width, H = ibm->height, r = s->r;
    for (y = p->by0; y < p->by1; ++y) {
        int ty = y >= 0 && y < H ? y : y % H;   /* no division inside the period */
        if (ty < 0) ty += H;
        for (x = p->bx0; x < p->bx1; ++x) {
            int tx = x >= 0 && x < W ? x : x % W, dx, dy;
            unsigned int v;
            if (tx < 0) tx += W;
            v = mf__ibm_get(ibm->data + ibm->bin_at, (size_t)ty * (size_t)W + (size_t)tx, ibm->bin_bits);
            if (!collect) {
                if (mf__ibm_set_find(ibm, s, v) >= 0) return 1;
                continue;
            }
            dx = (int)(v & ((1u << ibm->axis_bits) - 1u)) - s->cx; dy = (int)(v >> ibm->axis_bits) - s->cy;
            if (dx * dx + dy * dy > r * (r + 1)) continue;
            if (s->slot[mf__ibm_set_cell(s, dx, dy)] < 0) mf__ibm_set_add(s, dx, dy, (s->cx + dx) + ibm->res * (s->cy + dy));
        }
    }
    if (collect) s->mapped = 1;
    return collect ? s->n : 0;
}

/* the first of the positions base + [s, e) (sorted codes) whose code is at
 * least c, relative to base; e when none */
MF_INLINE unsigned int mf__ibm_lower(const unsigned int *pos, int w, unsigned int base, unsigned int s, unsigned int e, unsigned int c)
{
    unsigned int n = e - s;
    while (n > 0u) {
        unsigned int h = n >> 1;
        if (mf__ibm_get(pos, (size_t)base + s + h, w) < c) { s += h + 1u; n -= h + 1u; }
        else n = h;
    }
    return s;
}

/* first index in [s, e) whose Morton code has bit `bit` set (the codes of a
 * node's range share the bits above it): the two ends, then binary search */
MF_INLINE unsigned int mf__ibm_split(const mf_ibm *ibm, unsigned int s, unsigned int e, int bit)
{
    const unsigned int *pos = ibm->data + ibm->pos_at;
    int w = ibm->list_bits;
    /* all on one side (common where a bin's texels cluster): two reads */
    if (s >= e || mf__ibm_get_bit(pos, s, w, bit)) return s;
    if (!mf__ibm_get_bit(pos, e - 1u, w, bit)) return e;
    {   /* branchless lower bound: the first index with the bit set lies
         * in [s, s + n), e - 1 the last candidate */
        unsigned int n = e - s;
        while (n > 1u) {
            unsigned int h = n >> 1;
            s += mf__ibm_get_bit(pos, s + h - 1u, w, bit) ? 0u : h;
            n -= h;
        }
    }
    return s;
}

typedef struct mf__ibm_frame {
    int x0, y0, lx, ly;
    unsigned int pre;               /* the node's index in its level (its code prefix) */
    unsigned int act;               /* bit i: bin i has texels in the node */
} mf__ibm_frame;

/* Texels [x0, x1] x [y0, y1] (inclusive; none when x1 < x0 or y1 < y0) as
 * bounds on Morton codes: a code's x bits (masked by xm) and y bits (ym)
 * compare like x and y themselves, so that a texel's code is tested against
 * the box without decoding it. */
typedef struct mf__ibm_cbox {
    unsigned int xm, ym, x0, x1, y0, y1;
    unsigned int lom;   /* the interleaved bits, and their count per axis (mf__ibm_unmorton_masked) */
    int kmin;
} mf__ibm_cbox;
MF_INLINE mf__ibm_cbox mf__ibm_code_box(const mf_ibm *ibm, int x0, int y0, int x1, int y1)
{
    mf__ibm_cbox b;
    /* mf__ibm_morton of one axis alone: the low k bits spread (x to the
     * odd positions), the longer axis's bits above them */
    int kx = ibm->kx, ky = ibm->ky, k = kx < ky ? kx : ky;
    unsigned int lo = k >= 16 ? 0xffffffffu : (1u << (2 * k)) - 1u, m = (1u << k) - 1u;
    unsigned int hi = kx == ky ? 0u : ((1u << (kx > ky ? kx - k : ky - k)) - 1u) << (2 * k);
    b.xm = (0xaaaaaaaau & lo) | (kx > ky ? hi : 0u);
    b.ym = (0x55555555u & lo) | (ky > kx ? hi : 0u);
    b.lom = lo; b.kmin = k;
    b.x0 = b.y0 = 1u; b.x1 = b.y1 = 0u;
    if (x1 < x0 || y1 < y0) return b;
    mf__ibm_spread2((unsigned int)x0 & m, (unsigned int)x1 & m, &b.x0, &b.x1);
    mf__ibm_spread2((unsigned int)y0 & m, (unsigned int)y1 & m, &b.y0, &b.y1);
    b.x0 <<= 1; b.x1 <<= 1;
    if (kx > ky) { b.x0 |= ((unsigned int)x0 >> k) << (2 * k); b.x1 |= ((unsigned int)x1 >> k) << (2 * k); }
    if (ky > kx) { b.y0 |= ((unsigned int)y0 >> k) << (2 * k); b.y1 |= ((unsigned int)y1 >> k) << (2 * k); }
    return b;
}

/* the lowest set bit's index of v != 0 */
MF_INLINE int mf__ibm_low_bit(unsigned int v)
{
#ifdef MF__CTZ32
    return MF__CTZ32(v);   /* one instruction: the node loop's bin iteration */
#else
    return mf__ibm_bitlen32(v & (0u - v)) - 1;
#endif
}

/* The edges of a piece that may cut box [x0,x1) x [y0,y1) (texels), listed
 * in k, their count returned: those whose least value over the box is below
 * `margin`, a bound on the rounding of the edge functions. Every texel of
 * the box lies inside the other edges by mf__ibm_texel_area's own tests. */
MF_INLINE int mf__ibm_cut_edges(const mf__ibm_piece *pc, int x0, int y0, int x1, int y1, mf_real margin, int *k)
{
    mf_real X0 = (mf_real)(x0 - pc->ox), X1 = (mf_real)(x1 - pc->ox), Y0 = (mf_real)(y0 - pc->oy), Y1 = (mf_real)(y1 - pc->oy);
    int i, n = 0;
    for (i = 0; i < pc->n; ++i) {
        mf_real a = pc->ea[i], b = pc->eb[i];
        mf_real lo = pc->ec[i] + (a > MF_R(0.0) ? a * X0 : a * X1) + (b > MF_R(0.0) ? b * Y0 : b * Y1);
        if (!(lo >= margin)) k[n++] = i;
    }
    return n;
}

/* kd traversal of Sec. 5.4.4 for up to MF_IBM_BATCH bins at once (their trees
 * share the splits): each node is classified against the piece once; inside
 * nodes add their texel count (prefiltering, Fig. 5.4), outside nodes are
 * skipped, cut nodes descend down to leaves of at most MF_IBM_LEAF texels
 * (MF__IBM_LEAF_ONE for one bin), whose texels get exact areas - unless a
 * bin holds every texel of the node, whose exact area is then that of the
 * node's box in the piece. */
MF_FORCE_INLINE void mf__ibm_traverse(const mf_ibm *ibm, const mf__ibm_piece *pc, const int *bins, int nb, mf_real *acc)
{
    /* the current node (g[t]) and the second children still pending on its
     * path (g[1] .. g[t-1]); a node's ranges are [r[t][i], r[t-1][i]): the
     * current node starts at row t and each pending one at the row below,
     * where the node above it ends (r[0]: the bins' ends). A cut node puts
     * its split in row t+1 and swaps the two rows when both children hold
     * texels: nothing is copied. */
    mf__ibm_frame g[MF__IBM_STACK + 2];
    unsigned int rows[MF__IBM_STACK + 3][MF_IBM_BATCH], *r[MF__IBM_STACK + 3];
    unsigned int cnt[MF_IBM_BATCH], base[MF_IBM_BATCH], tab[MF_IBM_BATCH];
    int lev[MF_IBM_BATCH];
    mf_real frac[MF_IBM_BATCH];
    const unsigned int *pos = ibm->data + ibm->pos_at;
    int t = 1, top = 2, i, depth = ibm->kx + ibm->ky, jump = 1;
    /* the bins' act bits: where nb is a constant (mf__ibm_traverse_one),
     * the loops over a node's bins below become a single test */
    const unsigned int all = nb >= 32 ? 0xffffffffu : (1u << nb) - 1u;
    /* the piece's texel box and the texels wholly inside in Morton code */
    mf__ibm_cbox bb = mf__ibm_code_box(ibm, pc->bx0, pc->by0, pc->bx1 - 1, pc->by1 - 1);
    mf__ibm_cbox ib = mf__ibm_code_box(ibm, pc->ix0, pc->iy0, pc->ix1 - 1, pc->iy1 - 1);
    unsigned int xm = bb.xm, ym = bb.ym, bx0 = bb.x0, bx1 = bb.x1, by0 = bb.y0, by1 = bb.y1;
    unsigned int ix0 = ib.x0, ix1 = ib.x1, iy0 = ib.y0, iy1 = ib.y1;
    int kmin = bb.kmin;
    unsigned int lom = bb.lom;
    /* rounding bound of the edge functions of the piece's coordinates (at
     * most S, the texels its box spans, each), with room to spare */
    mf_real margin = MF_R(64.0) * (mf_real)MF_EPS * ((mf_real)(pc->bx1 - pc->ox + pc->by1 - pc->oy) + MF_R(2.0));
    /* the traversal starts at the least node that holds the piece's box: the
     * common prefix of its corners' codes (level l, index pre), each bin's
     * range in it from its stored boundaries, searched below them */
    {
        unsigned int c0 = bx0 | by0, c1 = bx1 | by1, pre;
        int b = mf__ibm_bitlen32(c0 ^ c1), l = depth - b;
        pre = l > 0 ? c0 >> b : 0u;
        mf__ibm_node_dims(ibm, l, &g[1].lx, &g[1].ly);
        mf__ibm_unmorton_masked((pre << b) & xm, (pre << b) & ym, lom, kmin, &g[1].x0, &g[1].y0);   /* b <= depth <= 28 */
        g[1].pre = pre; g[1].act = 0u;
        r[0] = rows[0]; r[1] = rows[1]; r[2] = rows[2];   /* the rows above: set as reached */
        for (i = 0; i < nb; ++i) {
            unsigned int nt = mf__ibm_bin_info(ibm, bins[i], &base[i], &tab[i], &lev[i]), s = 0u, e = nt;
            if (l > 0 && nt > 0u) {
                int k = lev[i] < l ? lev[i] : l;
                unsigned int q = pre >> (l - k);
                s = mf__ibm_bound(pos, ibm->list_bits, tab[i], lev[i], nt, q << (lev[i] - k));
                e = mf__ibm_bound(pos, ibm->list_bits, tab[i], lev[i], nt, (q + 1u) << (lev[i] - k));
                if (k < l) {   /* below the stored levels: the codes of the node */
                    s = mf__ibm_lower(pos, ibm->list_bits, base[i], s, e, pre << b);
                    e = mf__ibm_lower(pos, ibm->list_bits, base[i], s, e, (pre + 1u) << b);
                }
            }
            r[1][i] = base[i] + s;
            r[0][i] = base[i] + e;
            cnt[i] = 0u;
            frac[i] = MF_R(0.0);
            if (e > s) g[1].act |= 1u << i;
        }
    }
    /* a node visits only the bins with texels in it (its act bits): the
     * rows of the others are neither read nor written */
    for (;;) {
        mf__ibm_frame cur = g[t];
        unsigned int *cs = r[t], *ce = r[t - 1], *mm = r[t + 1], m1, lm = 0u, rm = 0u;
        int x1, y1, c = 2;
        if (jump) {
            /* down to the least node that holds the texels of every range at
             * once (codes sorted: the common prefix of the least and the
             * largest), past the nodes of one child (clustered texels) */
            unsigned int lo = 0xffffffffu, hi = 0u;
            jump = 0;
            for (m1 = cur.act & all; m1; m1 &= m1 - 1u) {
                unsigned int c0, c1;
                i = mf__ibm_low_bit(m1);
                c0 = mf__ibm_get(pos, cs[i], ibm->list_bits); c1 = mf__ibm_get(pos, ce[i] - 1u, ibm->list_bits);
                lo = c0 < lo ? c0 : lo;
                hi = c1 > hi ? c1 : hi;
            }
            if (lo > hi) c = -1;   /* no texel */
            else {
                unsigned int d;
                int b = mf__ibm_bitlen32(lo ^ hi);   /* bits below the common prefix */
                if (b < cur.lx + cur.ly) {
                    mf__ibm_node_dims(ibm, depth - b, &cur.lx, &cur.ly);   /* that node's sides */
                    d = lo >> b;
                    cur.pre = d;
                    d = b < 32 ? d << b : 0u;
                    mf__ibm_unmorton_masked(d & xm, d & ym, lom, kmin, &cur.x0, &cur.y0);
                }
            }
        }
        x1 = cur.x0 + (1 << cur.lx); y1 = cur.y0 + (1 << cur.ly);
        if (x1 > ibm->width) x1 = ibm->width;
        if (y1 > ibm->height) y1 = ibm->height;
        if (c == 2) c = mf__ibm_classify(pc, cur.x0, cur.y0, x1, y1);
        if (c > 0) {
            for (m1 = cur.act & all; m1; m1 &= m1 - 1u) { i = mf__ibm_low_bit(m1); cnt[i] += ce[i] - cs[i]; }
        } else if (c == 0) {
            int bit = cur.lx + cur.ly - 1;
            /* sparse leaves are split further in batches where the node is no
             * wider than the piece's box (larger ones: the tests on the codes
             * reject their texels outside it for less) */
            int sparse = nb > 1 && (1 << cur.lx) <= pc->bx1 - pc->bx0 && (1 << cur.ly) <= pc->by1 - pc->by0;
            int ek[12], ne = -1, box = 1;   /* the edges that may cut the node (leaves; -1: not yet known) */
            unsigned int cells = (unsigned int)(x1 - cur.x0) * (unsigned int)(y1 - cur.y0);
            /* a bin's texels in the node make a leaf when they are at most
             * `cap` and either at most MF__IBM_LEAF_MIN or at least `dense`
             * (not sparse: at most 2^MF__IBM_SPARSE_BITS cells per texel) */
            unsigned int cap = bit < 0 ? 0xffffffffu : nb == 1 ? (unsigned int)MF__IBM_LEAF_ONE : (unsigned int)MF_IBM_LEAF;
            unsigned int dense = !sparse || bit < MF__IBM_SPARSE_BITS ? 0u : 1u << (bit + 1 - MF__IBM_SPARSE_BITS);
            for (m1 = cur.act & all; m1; m1 &= m1 - 1u) {
                unsigned int s, e;
                i = mf__ibm_low_bit(m1);
                s = cs[i]; e = ce[i];
                if (e - s == cells) {   /* the bin fills the node (flat regions): its area at once, exact */
                    frac[i] += mf__ibm_box_area(pc, cur.x0, cur.y0, x1, y1);
                    cs[i] = mm[i] = e;
                    continue;
                }
                if (e - s <= cap && (e - s <= (unsigned int)MF__IBM_LEAF_MIN || e - s >= dense)) {
                    if (ne < 0) {
                        ne = pc->rect ? 0 : mf__ibm_cut_edges(pc, cur.x0, cur.y0, x1, y1, margin, ek);
                        /* the node within the piece's box and off its inside
                         * rectangle: the two tests below can be left out */
                        box = !(cur.x0 >= pc->bx0 && x1 <= pc->bx1 && cur.y0 >= pc->by0 && y1 <= pc->by1 &&
                                (x1 <= pc->ix0 || cur.x0 >= pc->ix1 || y1 <= pc->iy0 || cur.y0 >= pc->iy1));
                    }
                    for (; s < e; ++s) {
                        int x, y;
                        mf_real a;
                        unsigned int code = mf__ibm_get(pos, s, ibm->list_bits), cx = code & xm, cy = code & ym;
                        if (box) {
                            if (cx < bx0 || cx > bx1 || cy < by0 || cy > by1) continue;   /* outside the piece's box */
                            if (cx >= ix0 && cx <= ix1 && cy >= iy0 && cy <= iy1) { ++cnt[i]; continue; }   /* wholly inside */
                        }
                        mf__ibm_unmorton_masked(cx, cy, lom, kmin, &x, &y);
                        if (!pc->rect) {
                            /* mf__ibm_texel_area's tests, same operations,
                             * for the edges that may cut the node: a texel
                             * inside them all counts 1, one outside an edge
                             * 0; only texels that an edge cuts are clipped */
                            mf_real X = (mf_real)(x - pc->ox), Y = (mf_real)(y - pc->oy), vc = MF_R(0.0);
                            int j, cut = 0, kc = 0, out = 0;
                            for (j = 0; j < ne; ++j) {
                                int k = ek[j];
                                mf_real v = pc->ea[k] * X + pc->eb[k] * Y + pc->ec[k];
                                if (v + pc->ehi[k] <= MF_R(0.0)) { out = 1; break; }
                                if (v + pc->elo[k] < MF_R(0.0)) { ++cut; kc = k; vc = v; }
                            }
                            if (out) continue;
                            if (!cut) { ++cnt[i]; continue; }
                            if (cut == 1) {   /* mf__ibm_texel_area's closed form for one cutting edge, its values */
                                mf_real v4[4];
                                v4[0] = vc; v4[1] = vc + pc->ea[kc]; v4[2] = vc + pc->ea[kc] + pc->eb[kc]; v4[3] = vc + pc->eb[kc];
                                a = mf__ibm_square_cut(v4);
                                if (a >= MF_R(0.0)) {
                                    if (a >= MF_R(1.0)) ++cnt[i];
                                    else frac[i] += a;
                                    continue;
                                }
                            }
                        }
                        a = mf__ibm_texel_area(pc, x, y);
                        if (a >= MF_R(1.0)) ++cnt[i];
                        else frac[i] += a;
                    }
                    cs[i] = mm[i] = e;   /* both children empty */
                } else {
                    /* the split: stored down to level k, else binary search */
                    int l = depth - cur.lx - cur.ly, kk = lev[i];
                    unsigned int m = l < kk ? base[i] + mf__ibm_get(pos, (size_t)tab[i] + (size_t)(((2u * cur.pre + 1u) << (kk - l - 1)) - 1u), ibm->list_bits)
                                            : mf__ibm_split(ibm, s, e, bit);
                    mm[i] = m;
                    if (m > s) lm |= 1u << i;
                    if (e > m) rm |= 1u << i;
                }
            }
            if (bit >= 0 && (lm | rm)) {
                mf__ibm_frame right;
                if (cur.lx >= cur.ly) { --cur.lx; right.x0 = cur.x0 + (1 << cur.lx); right.y0 = cur.y0; }
                else { --cur.ly; right.x0 = cur.x0; right.y0 = cur.y0 + (1 << cur.ly); }
                right.lx = cur.lx; right.ly = cur.ly;
                cur.pre *= 2u;
                right.pre = cur.pre + 1u;
                cur.act = lm; right.act = rm;
                /* one child: its ranges are the node's (the split at
                 * an end for every bin) */
                if (lm && rm && t <= MF__IBM_STACK) {   /* (t <= depth + 1 <= 33 always) */
                    r[t] = mm; r[t + 1] = cs;
                    g[t] = right;
                    g[++t] = cur;
                    if (t + 1 > top) { top = t + 1; r[top] = rows[top]; }
                } else {
                    g[t] = lm ? cur : right;
                    jump = 1;
                }
                continue;
            }
        }
        if (t == 1) break;
        --t;
    }
    for (i = 0; i < nb; ++i) acc[i] += (mf_real)cnt[i] + frac[i];
}

/* mf__ibm_traverse for a set of one bin (mf_ibm_bin_weight), compiled for
 * nb = 1: the loops over a node's bins become one test */
static MF__NOINLINE MF_HD void mf__ibm_traverse_one(const mf_ibm *ibm, const mf__ibm_piece *pc, const int *bins, mf_real *acc)
{
    mf__ibm_traverse(ibm, pc, bins, 1, acc);
}

/* The weights of a set of bins that hold few texels, for a footprint
 * whose texel box meets at most 3 periods each way (A itself, across the
 * period's border too: a texel's images in that box, found by shifts of
 * whole periods; whole periods inside A count through them): at most 48 per bin of the
 * set (the 21 bins: 1008; measured against 32, 64 and limits of 1024 and
 * 4096 in all); a single bin, at most 128, also for a footprint of the
 * direct path.
 * Each texel of the bins by its position, no traversal and no bin-map
 * reads: A's texel box on the Morton codes first. Its center in
 * A's own coordinates, c + s a + t b with A at |s|, |t| <= 1/2, decides
 * the texels wholly inside or outside (the texel spans s +- rs, t +- rt);
 * only a texel that the boundary may cut is clipped (mf__ibm_texel_area, as
 * the traversal's leaves take it), against A's piece, made on first need.
 * rs and rt carry a margin for the rounding of s and t (coordinates up to
 * the map's size, and the cancellation in a thin A), so that only clipping
 * decides a texel near the boundary. 0 where the path does not apply (the
 * caller goes on). */
#define MF__IBM_FEW_TEXELS 48u
/* floor(a / b) for b > 0 */
MF_INLINE int mf__ibm_floor_div(int a, int b) { return a >= 0 ? a / b : -((b - 1 - a) / b); }
#define MF__IBM_FEW_ONE 128u     /* a single bin's limit */
#define MF__IBM_FEW_PERIODS 3   /* periods a footprint's box may meet each way */
static MF__NOINLINE MF_HD int mf__ibm_weights_few(const mf_ibm *ibm, const mf__ibm_fp *p, mf__ibm_set *s)
{
    mf__ibm_piece pc;
    mf__ibm_cbox bb[MF__IBM_FEW_PERIODS * MF__IBM_FEW_PERIODS];
    mf_real cr = p->ax * p->by - p->ay * p->bx, inv, rs, rt, err, tot = p->area, frac;
    unsigned int texels = 0u, n, base, tab, q, cnt;
    int i, j, k, x, y, made = 0, nb = 1, W = ibm->width, H = ibm->height, x0, y0, x1, y1;
    int sx[MF__IBM_FEW_PERIODS * MF__IBM_FEW_PERIODS], sy[MF__IBM_FEW_PERIODS * MF__IBM_FEW_PERIODS];
    /* a footprint of at most MF_IBM_DIRECT_TEXELS box texels: the bin map's
     * rows cost fewer cache lines than the lists of several bins, so one bin
     * only, and none where those rows are read already */
    if (p->direct && (s->n > 1 || s->mapped)) return 0;
    for (i = 0; i < s->n; ++i) {
        texels += mf__ibm_bin_info(ibm, s->bin[i], &base, &tab, &k);
        if (texels > (s->n == 1 ? MF__IBM_FEW_ONE : p->direct ? MF__IBM_FEW_TEXELS : MF__IBM_FEW_TEXELS * (unsigned int)s->n)) return 0;
    }
    /* a small footprint's weights are divided by its texels' areas as they
     * add up (mf__ibm_weights), which takes every texel it covers: here only
     * where the bins cannot hold them all */
    if ((size_t)texels >= (size_t)ibm->width * (size_t)ibm->height) return 0;
    inv = MF_R(1.0) / MF_FABS(cr);   /* |A| >= MF_IBM_MIN_AREA */
    err = MF_R(16.0) * MF_EPS * ((mf_real)(ibm->width + ibm->height) + p->ex + p->ey + MF_R(2.0)) * inv;
    rs = (MF_R(0.5) * inv + err) * (MF_FABS(p->bx) + MF_FABS(p->by));
    rt = (MF_R(0.5) * inv + err) * (MF_FABS(p->ax) + MF_FABS(p->ay));
    if (cr < MF_R(0.0)) inv = -inv;
    /* A's texel box as Morton-code bounds (most texels fail it, undecoded):
     * beyond the first period, its parts in each period it meets, shifted
     * into the first (x in [c W, c W + W) by -c W), each with the shift that
     * takes its texels back to their images in A */
    x0 = mf__ibm_ifloor(p->cx - p->ex); y0 = mf__ibm_ifloor(p->cy - p->ey);
    x1 = mf__ibm_iceil(p->cx + p->ex) - 1; y1 = mf__ibm_iceil(p->cy + p->ey) - 1;
    sx[0] = sy[0] = 0;
    if (x0 >= 0 && x1 < W && y0 >= 0 && y1 < H) bb[0] = mf__ibm_code_box(ibm, x0, y0, x1, y1);   /* inside the period */
    else {
        /* the periods met: c0..c1 across, r0..r1 down (floor division) */
        int c0 = mf__ibm_floor_div(x0, W), c1 = mf__ibm_floor_div(x1, W), r0 = mf__ibm_floor_div(y0, H), r1 = mf__ibm_floor_div(y1, H), c, r;
        if (c1 - c0 >= MF__IBM_FEW_PERIODS || r1 - r0 >= MF__IBM_FEW_PERIODS) return 0;
        for (nb = 0, r = r0; r <= r1; ++r)
            for (c = c0; c <= c1; ++c) {
                int u0 = c == c0 ? x0 - c * W : 0, u1 = c == c1 ? x1 - c * W : W - 1;
                int v0 = r == r0 ? y0 - r * H : 0, v1 = r == r1 ? y1 - r * H : H - 1;
                sx[nb] = c * W; sy[nb] = r * H;
                bb[nb++] = mf__ibm_code_box(ibm, u0, v0, u1, v1);
            }
    }
    for (i = 0; i < s->n; ++i) {
        n = mf__ibm_bin_info(ibm, s->bin[i], &base, &tab, &k);
        cnt = 0u; frac = MF_R(0.0);
        for (j = 0; j < nb; ++j) {
            const mf__ibm_cbox *b = bb + j;
            mf_real ox = p->cx - (mf_real)sx[j], oy = p->cy - (mf_real)sy[j];   /* A's center relative to the part */
            /* the part's codes lie in [x0 | y0, x1 | y1] (each axis's bits
             * compare like the axis): the sorted list from its lower bound */
            q = n > 8u ? mf__ibm_lower(ibm->data + ibm->pos_at, ibm->list_bits, base, 0u, n, b->x0 | b->y0) : 0u;
            for (; q < n; ++q) {
                unsigned int c = mf__ibm_get(ibm->data + ibm->pos_at, base + q, ibm->list_bits), mx = c & b->xm, my = c & b->ym;
                mf_real dx, dy, as, at, a;
                if (c > (b->x1 | b->y1)) break;
                if (mx < b->x0 || mx > b->x1 || my < b->y0 || my > b->y1) continue;
                mf__ibm_unmorton_masked(mx, my, b->lom, b->kmin, &x, &y);
                dx = (mf_real)x + MF_R(0.5) - ox; dy = (mf_real)y + MF_R(0.5) - oy;
                as = MF_FABS((dx * p->by - dy * p->bx) * inv);
                at = MF_FABS((p->ax * dy - p->ay * dx) * inv);
                if (as >= MF_R(0.5) + rs || at >= MF_R(0.5) + rt) continue;       /* wholly outside */
                if (as + rs <= MF_R(0.5) && at + rt <= MF_R(0.5)) { ++cnt; continue; }   /* wholly inside */
                if (!made) {
                    if (!mf__ibm_piece_inner(p, &pc)) {
                        if (!p->inner) return 0;   /* the caller's pieces decide */
                        if (!mf__ibm_piece_edges(ibm, p, 0, 0, p->x, p->y, 4, &pc)) {   /* no area */
                            for (i = 0; i < s->n; ++i) s->w[i] = MF_R(0.0);
                            return 1;
                        }
                    }
                    tot = mf__ibm_shoelace(pc.x, pc.y, pc.n, MF_R(0.0), MF_R(0.0));   /* as mf__ibm_weights takes |A| */
                    made = 1;
                }
                a = mf__ibm_texel_area(&pc, x + sx[j], y + sy[j]);
                if (a >= MF_R(1.0)) ++cnt;
                else frac += a;
            }
        }
        s->w[i] = mf_clamp(((mf_real)cnt + frac) / tot, MF_R(0.0), MF_R(1.0));
    }
    return 1;
}

/* W_j for every bin of the set (Eq. 5.8): full periods count each texel of the
 * bin once, the pieces by direct sum or kd traversal, all divided by |A|. */
MF_INLINE void mf__ibm_weights(const mf_ibm *ibm, const mf__ibm_fp *p, mf__ibm_set *s)
{
    mf_real tot, dtot = MF_R(0.0);
    int i, direct = p->direct;
    if (p->mode == MF__IBM_NONE) { for (i = 0; i < s->n; ++i) s->w[i] = MF_R(0.0); return; }
    if (p->mode == MF__IBM_POINT) {
        int k = mf__ibm_set_find(ibm, s, mf__ibm_get(ibm->data + ibm->bin_at, (size_t)p->ty * (size_t)ibm->width + (size_t)p->tx, ibm->bin_bits));
        for (i = 0; i < s->n; ++i) s->w[i] = i == k ? MF_R(1.0) : MF_R(0.0);
        return;
    }
    if (p->mode == MF__IBM_GLOBAL) {
        mf_real inv = MF_R(1.0) / ((mf_real)ibm->width * (mf_real)ibm->height);
        for (i = 0; i < s->n; ++i) s->w[i] = (mf_real)mf_ibm_bin_texels(ibm, s->bin[i]) * inv;
        return;
    }
    if (mf__ibm_weights_few(ibm, p, s)) return;
    for (i = 0; i < s->n; ++i) s->w[i] = p->full > MF_R(0.0) ? p->full * (mf_real)mf_ibm_bin_texels(ibm, s->bin[i]) : MF_R(0.0);
    if (direct && !p->few) {
        /* one bin, or wanted bins with fewer than 2 times the box's texels:
         * their kd traversal costs less than visiting the box (the factor 2
         * and the one-bin rule were tuned: docs/PERFORMANCE.md) */
        if (s->n == 1) direct = 0;
        else {
            double texels = 0.0;
            for (i = 0; i < s->n; ++i) texels += (double)mf_ibm_bin_texels(ibm, s->bin[i]);
            if (texels < 2.0 * (double)(p->bx1 - p->bx0) * (double)(p->by1 - p->by0)) direct = 0;
        }
    }
    if (direct && p->bx0 >= 0 && p->bx1 <= ibm->width && p->by0 >= 0 && p->by1 <= ibm->height) {
        /* start the loads of the box's bin-map rows together, not one
         * after another as the scan reaches them */
        int y;
        for (y = p->by0; y < p->by1; ++y) {
            size_t j = (size_t)y * (size_t)ibm->width;
            MF__PREFETCH(ibm->data + ibm->bin_at + (((j + (size_t)p->bx0) * (size_t)ibm->bin_bits) >> 5));
            MF__PREFETCH(ibm->data + ibm->bin_at + (((j + (size_t)p->bx1 - 1u) * (size_t)ibm->bin_bits) >> 5));
        }
    }
    if (direct && !mf__ibm_direct_any(ibm, p, s, 0)) return;   /* no wanted texel: all 0 */
    tot = p->full * (mf_real)ibm->width * (mf_real)ibm->height;
    {
        mf_real xs[12], ys[12], c0, c1, f0, f1, col;
        mf__ibm_piece pc;
        int row;
        for (row = p->row0; row <= p->row1; ++row) {
            int n = 4;
            if (p->inner) {   /* one piece, A itself (row 0, column 0) */
                for (i = 0; i < 4; ++i) { xs[i] = p->x[i]; ys[i] = p->y[i]; }
                c0 = c1 = MF_R(0.0); f0 = MF_R(1.0); f1 = MF_R(0.0);
            } else {
                n = mf__ibm_slab(ibm, p, row, xs, ys);
                if (n < 3) continue;
                mf__ibm_slab_columns(ibm, row, xs, ys, n, &c0, &c1, &f0, &f1);
            }
            for (col = c0; col <= c1; col += MF_R(1.0)) {
                if (col >= f0 && col <= f1) continue;
                if (p->tiny) {   /* the polygon is all the row sums need */
                    if (!mf__ibm_piece_poly(ibm, p, row, (int)col, xs, ys, n, &pc)) continue;
                    dtot += mf__ibm_direct_rows(ibm, &pc, s);
                    continue;
                }
                if (!mf__ibm_piece_make(ibm, p, row, (int)col, xs, ys, n, &pc)) continue;
                tot += mf__ibm_shoelace(pc.x, pc.y, pc.n, MF_R(0.0), MF_R(0.0));
                if (direct) dtot += mf__ibm_direct(ibm, &pc, s, p->few);
                else if (s->n == 1) mf__ibm_traverse_one(ibm, &pc, s->bin, s->w);
                else
                    for (i = 0; i < s->n; i += MF_IBM_BATCH)
                        mf__ibm_traverse(ibm, &pc, s->bin + i, s->n - i < MF_IBM_BATCH ? s->n - i : MF_IBM_BATCH, s->w + i);
            }
        }
    }
    /* |A| as the pieces add up, so that the weights of all bins sum to 1 even
     * where float round-off moves the corners of a thin footprint; for
     * small or thin footprints (few), as the texel areas themselves add up
     * (the clipped texels and the shoelace of the pieces round differently:
     * on a flat map, where one bin holds every texel, the weight of a
     * sub-texel footprint is then exactly 1) */
    if (direct && p->few && dtot > MF_R(0.0)) tot = dtot;
    if (!(tot > MF_R(0.0))) tot = p->area;
    for (i = 0; i < s->n; ++i) s->w[i] = mf_clamp(s->w[i] / tot, MF_R(0.0), MF_R(1.0));
}

/* The footprint near the texels, for the early exits: its center (texels,
 * less half a texel, in the first period) in e[0], e[1] and its half extents
 * widened by 1.5 texels in e[2], e[3]; 0 when it is not finite or not
 * narrower than a quarter period. */
MF_INLINE int mf__ibm_near_extent(const mf_ibm *ibm, const mf_footprint *f, mf_real *e)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height;
    if (!f || !mf__finite_bits(f->u) || !mf__finite_bits(f->v) || !mf__finite_bits(f->ax) || !mf__finite_bits(f->ay) ||
        !mf__finite_bits(f->bx) || !mf__finite_bits(f->by) || !(MF_FABS(f->u) < MF_R(4.0)) || !(MF_FABS(f->v) < MF_R(4.0)))
        return 0;
    e[2] = MF_R(0.5) * (MF_FABS(f->ax) + MF_FABS(f->bx)) * W + MF_R(1.5);
    e[3] = MF_R(0.5) * (MF_FABS(f->ay) + MF_FABS(f->by)) * H + MF_R(1.5);
    if (!(e[2] < MF_R(0.25) * W) || !(e[3] < MF_R(0.25) * H)) return 0;
    e[0] = f->u * W - MF_R(0.5); e[1] = f->v * H - MF_R(0.5);
    if (!(e[0] >= MF_R(0.0) && e[0] < W)) e[0] -= W * MF_FLOOR(e[0] / W);   /* into the first period */
    if (!(e[1] >= MF_R(0.0) && e[1] < H)) e[1] -= H * MF_FLOOR(e[1] / H);
    return 1;
}

/* The texel box [x0, x1] x [y0, y1] (inclusive) of a near extent e
 * (mf__ibm_near_extent), ok = 1 when it does not wrap; else ok = 0. */
typedef struct mf__ibm_box { int ok, x0, y0, x1, y1; } mf__ibm_box;

MF_INLINE mf__ibm_box mf__ibm_extent_box(const mf_ibm *ibm, const mf_real *e)
{
    mf__ibm_box b;
    b.ok = 0; b.x0 = b.y0 = b.x1 = b.y1 = 0;
    if (!(e[0] >= e[2] && e[0] + e[2] + MF_R(1.0) < (mf_real)ibm->width && e[1] >= e[3] && e[1] + e[3] + MF_R(1.0) < (mf_real)ibm->height))
        return b;
    b.x0 = (int)(e[0] - e[2]); b.x1 = (int)(e[0] + e[2]) + 1; b.y0 = (int)(e[1] - e[3]); b.y1 = (int)(e[1] + e[3]) + 1;
    b.ok = 1;
    return b;
}

/* The footprint's box (mf__ibm_extent_box), ok = 0 also where it has no near extent. */
MF_INLINE mf__ibm_box mf__ibm_near_box(const mf_ibm *ibm, const mf_footprint *f)
{
    mf_real e[4];
    mf__ibm_box b;
    if (mf__ibm_near_extent(ibm, f, e)) return mf__ibm_extent_box(ibm, e);
    b.ok = 0; b.x0 = b.y0 = b.x1 = b.y1 = 0;
    return b;
}

/* 1 if a bin of n texels (its stored kd-tree top: k levels, inner
 * boundaries at tab) has no texel in box b: the nodes of the deepest stored
 * level at which the box meets at most 4, their texel counts from their
 * boundaries (index reads only). 0 when it may have one, or the bin stores
 * no levels. */
MF_INLINE int mf__ibm_box_empty(const mf_ibm *ibm, unsigned int tab, int k, unsigned int n, const mf__ibm_box *b)
{
    const unsigned int *pos = ibm->data + ibm->pos_at;
    int l, lx = 0, ly = 0, gx, gy, d = ibm->kx + ibm->ky, w = ibm->list_bits;
    if (!b->ok || k <= 0) return 0;
    for (l = k; l > 0; --l) {
        mf__ibm_node_dims(ibm, l, &lx, &ly);
        if (((b->x1 >> lx) - (b->x0 >> lx) + 1) * ((b->y1 >> ly) - (b->y0 >> ly) + 1) <= 4) break;
    }
    if (l == 0) return 0;
    for (gy = b->y0 >> ly; gy <= b->y1 >> ly; ++gy)
        for (gx = b->x0 >> lx; gx <= b->x1 >> lx; ++gx) {
            unsigned int pre = mf__ibm_morton(ibm->kx, ibm->ky, (unsigned int)gx << lx, (unsigned int)gy << ly) >> (d - l);
            if (mf__ibm_bound(pos, w, tab, k, n, pre << (k - l)) != mf__ibm_bound(pos, w, tab, k, n, (pre + 1u) << (k - l)))
                return 0;
        }
    return 1;
}

/* A bin (its block [s0, s1) of the lists: mf__ibm_off of j and j + 1)
 * against footprint f: 0 empty, 1 no texel near the footprint
 * (mf__ibm_box_empty), 2 it may have some. *b is f's box, computed here on
 * first need (b->ok < 0 before). Blocks shorter than MF__IBM_NEAR_MIN get 2
 * untested. */
MF_INLINE int mf__ibm_bin_near(const mf_ibm *ibm, unsigned int s0, unsigned int s1, const mf_footprint *f, mf__ibm_box *b)
{
    unsigned int n;
    int k;
    if (s0 == s1) return 0;
    if (s1 - s0 < MF__IBM_NEAR_MIN) return 2;   /* untested (those below MF_IBM_TREE_MIN store no levels) */
    if (b->ok < 0) *b = mf__ibm_near_box(ibm, f);
    if (!b->ok) return 2;
    n = mf__ibm_block_texels(ibm, s1 - s0, &k);
    return mf__ibm_box_empty(ibm, s0, k, n, b) ? 1 : 2;
}

/* Row y of the window around bin (cx, cy) within radius r, dx^2 + dy^2 <=
 * r(r+1), clipped to the bin map: its cells x0 .. x1 (dx), 0 when none. */
MF_INLINE int mf__ibm_window_row(int res, int r, int cx, int cy, int y, int *x0, int *x1)
{
    int a = -r, e = r;
    if (cy + y < 0 || cy + y >= res) return 0;
    while (a * a + y * y > r * (r + 1)) { ++a; --e; }
    if (cx + a < 0) a = -cx;
    if (cx + e >= res) e = res - 1 - cx;
    *x0 = a; *x1 = e;
    return e >= a;
}

/* The non-empty bins of the window around bin (cx, cy) within the radius,
 * dx^2 + dy^2 <= r(r+1), in scan order: bin j[i] at (dx[i], dy[i]) and
 * mf__ibm_bin_near's verdict near[i] (1: none of its texels near the
 * footprint, 2: maybe); returns how many. */
MF_INLINE int mf__ibm_window(const mf_ibm *ibm, const mf_footprint *f, int cx, int cy, int *j, int *dx, int *dy, int *near)
{
    mf__ibm_box box;
    int r = ibm->radius, b = ibm->res, x, y, n = 0;
    box.ok = -1;
    if (f) {   /* a footprint the direct sum will visit: no box tests (they
                * would read every bin's list, which the scan of the bin map
                * never needs: measured +25% on 1e2-texel glint queries) */
        mf_real ex = MF_R(0.5) * (MF_FABS(f->ax) + MF_FABS(f->bx)) * (mf_real)ibm->width;
        mf_real ey = MF_R(0.5) * (MF_FABS(f->ay) + MF_FABS(f->by)) * (mf_real)ibm->height;
        if (MF_R(4.0) * ex * ey <= (mf_real)MF_IBM_DIRECT_TEXELS) box.ok = 0;
    }
    for (y = -r; y <= r; ++y) {
        unsigned int s0, s1;
        int x0, x1;
        if (!mf__ibm_window_row(b, r, cx, cy, y, &x0, &x1)) continue;
        /* neighbours in a row share their block boundary: one read per bin,
         * none past the two ends of a row without texels */
        s1 = mf__ibm_off(ibm, (cx + x0) + b * (cy + y));
        if (s1 == mf__ibm_off(ibm, (cx + x1 + 1) + b * (cy + y))) continue;
        for (x = x0; x <= x1; ++x) {
            int k = (cx + x) + b * (cy + y), c;
            s0 = s1; s1 = mf__ibm_off(ibm, k + 1);
            c = mf__ibm_bin_near(ibm, s0, s1, f, &box);
            if (c == 0) continue;
            j[n] = k; dx[n] = x; dy[n] = y; near[n] = c; ++n;
        }
    }
    return n;
}

/* 1 if no texel of the bins can meet the footprint, decided before any
 * footprint work for bins of few texels in all (at most 48): each texel
 * against the footprint's bounding box widened by a texel, across the
 * period. 0 when it may (or the footprint is large, wide or not finite). */
MF_INLINE int mf__ibm_far(const mf_ibm *ibm, const mf_footprint *f, const int *bins, int nb)
{
    mf_real W = (mf_real)ibm->width, H = (mf_real)ibm->height, e[4], cx, cy, ex, ey;
    unsigned int tot = 0u, n, base, tab, q;
    int i, k, x, y;
    mf__ibm_box bx;
    for (i = 0; i < nb; ++i) {
        tot += mf__ibm_bin_info(ibm, bins[i], &base, &tab, &k);
        if (tot > MF__IBM_FEW_TEXELS) return 0;
    }
    if (!mf__ibm_near_extent(ibm, f, e)) return 0;
    bx = mf__ibm_extent_box(ibm, e);
    if (bx.ok) {
        /* the box does not wrap: compare the Morton codes' x and y bits with
         * its corners' (masked, they order like x and y), no decoding */
        mf__ibm_cbox cb = mf__ibm_code_box(ibm, bx.x0, bx.y0, bx.x1, bx.y1);
        for (i = 0; i < nb; ++i) {
            n = mf__ibm_bin_info(ibm, bins[i], &base, &tab, &k);
            for (q = 0u; q < n; ++q) {
                unsigned int c = mf__ibm_get(ibm->data + ibm->pos_at, base + q, ibm->list_bits), mx = c & cb.xm, my = c & cb.ym;
                if (mx >= cb.x0 && mx <= cb.x1 && my >= cb.y0 && my <= cb.y1) return 0;
            }
        }
        return 1;
    }
    cx = e[0]; cy = e[1]; ex = e[2]; ey = e[3];
    for (i = 0; i < nb; ++i) {
        n = mf__ibm_bin_info(ibm, bins[i], &base, &tab, &k);
        for (q = 0u; q < n; ++q) {
            mf_real dx, dy;
            mf__ibm_unmorton(ibm->kx, ibm->ky, mf__ibm_get(ibm->data + ibm->pos_at, base + q, ibm->list_bits), &x, &y);
            dx = (mf_real)x - cx; dy = (mf_real)y - cy;   /* texel center minus footprint center */
            if (!(MF_FABS(dx) <= MF_R(0.5) * W)) dx -= W * MF_FLOOR(dx / W + MF_R(0.5));   /* nearest period */
            if (!(MF_FABS(dy) <= MF_R(0.5) * H)) dy -= H * MF_FLOOR(dy / H + MF_R(0.5));
            if (MF_FABS(dx) < ex && MF_FABS(dy) < ey) return 0;
        }
    }
    return 1;
}

/* The bins of the window around (cx, cy) that may hold texels of footprint
 * f (mf__ibm_window's verdict 2) in j, at (dx, dy); how many, 0 also when
 * none of their texels can meet it (mf__ibm_far). */
MF_INLINE int mf__ibm_near_bins(const mf_ibm *ibm, const mf_footprint *f, int cx, int cy, int *j, int *dx, int *dy)
{
    int verdict[MF_IBM_MAX_WINDOW], n = 0, i, nw = mf__ibm_window(ibm, f, cx, cy, j, dx, dy, verdict);
    for (i = 0; i < nw; ++i)
        if (verdict[i] == 2) { j[n] = j[i]; dx[n] = dx[i]; dy[n] = dy[i]; ++n; }
    return n == 0 || mf__ibm_far(ibm, f, j, n) ? 0 : n;
}

MF_COLD mf_real mf_ibm_bin_weight(const mf_ibm *ibm, int bin, const mf_footprint *f)
{
    mf__ibm_fp p;
    mf__ibm_set s;
    int shaped = -1;   /* mf__ibm_footprint_shape's result; -1: not called */
    if (!ibm || !ibm->data || bin < 0 || bin >= ibm->res * ibm->res) return MF_R(0.0);
    mf__ibm_set_init(&s, bin % ibm->res, bin / ibm->res, 0);
    mf__ibm_set_add(&s, 0, 0, bin);
    {   /* a bin of few texels and a footprint over at most 3 periods: its texels
         * against A at once (mf__ibm_weights_few), no early exits needed */
        unsigned int base, tab;
        int k;
        if (mf__ibm_bin_info(ibm, bin, &base, &tab, &k) <= MF__IBM_FEW_ONE) {
            shaped = mf__ibm_footprint_shape(ibm, f, &p);
            if (shaped && mf__ibm_weights_few(ibm, &p, &s)) return s.w[0];
        }
    }
    {
        mf__ibm_box nb;
        nb.ok = -1;
        if (mf__ibm_bin_near(ibm, mf__ibm_off(ibm, bin), mf__ibm_off(ibm, bin + 1), f, &nb) < 2 || mf__ibm_far(ibm, f, &bin, 1))
            return MF_R(0.0);   /* no footprint work */
    }
    if (shaped < 0) mf__ibm_footprint(ibm, f, &p);
    else if (shaped) mf__ibm_footprint_cells(ibm, &p);   /* the shape is set: its second half */
    mf__ibm_weights(ibm, &p, &s);
    return s.w[0];
}

MF_COLD int mf_ibm_neighbourhood_weights(const mf_ibm *ibm, const mf_footprint *f, int center_bin, int *bins,
                                           mf_real *weights)
{
    mf__ibm_fp p;
    mf__ibm_set s;
    int dx[MF_IBM_MAX_WINDOW], dy[MF_IBM_MAX_WINDOW], near[MF_IBM_MAX_WINDOW], cx, cy, i, n;
    if (!ibm || !ibm->data || center_bin < 0 || center_bin >= ibm->res * ibm->res) return 0;
    cx = center_bin % ibm->res; cy = center_bin / ibm->res;
    mf__ibm_set_init(&s, cx, cy, ibm->radius);
    /* every non-empty bin is listed; those whose stored kd-tree top puts no
     * texel near the footprint get weight 0 without a traversal */
    n = mf__ibm_window(ibm, f, cx, cy, bins, dx, dy, near);
    for (i = 0; i < n; ++i) {
        weights[i] = MF_R(0.0);
        if (near[i] == 2) mf__ibm_set_add(&s, dx[i], dy[i], bins[i]);
    }
    if (s.n == 0 || mf__ibm_far(ibm, f, s.bin, s.n)) return n;   /* no footprint work */
    mf__ibm_footprint(ibm, f, &p);
    mf__ibm_weights(ibm, &p, &s);
    for (i = 0; i < n; ++i) {
        int k = s.slot[mf__ibm_set_cell(&s, dx[i], dy[i])];
        if (k >= 0) weights[i] = s.w[k];
    }
    return n;
}

/* The flake Beckmann Lambda of a direction at sin^2 s2 and cosine c from a
 * bin normal; 0 where it is below 3e-19 (a = cot / alpha > 6), which adds
 * nothing to 1 + Lambda in float or double (Eq. 84 ~ exp(-a^2) / (2 a^3
 * sqrt(pi))): its exp and erfc spared, the sums bit for bit the same. */
MF_INLINE mf_real mf__ibm_flake_lambda(mf_real alpha, mf_real s2, mf_real c)
{
    if (MF_R(36.0) * alpha * alpha * s2 < c * c) return MF_R(0.0);
    return mf_beckmann_lambda(alpha, alpha, mf_vec3_make(MF_SQRT(s2), MF_R(0.0), c));
}

/* mean normals the BRDF keeps from its facing test: the 21 bins of the
 * default radius, without a window-sized array on a GPU thread's stack */
#define MF__IBM_KEPT_NORMALS 32
/* The lobes of the bins around beta(h): for each non-empty bin j of the
 * neighbourhood with wo.t_j > 0, the texel contribution C (Eq. 3.29, no
 * Fresnel) and the sampling density of wi through j,
 *   C_j   = D(h; t_j) G2(wo, wi; t_j) G_x(wo, wi, t_j) / (4 wo.z wi.z),
 *   pdf_j = D_wo(h; t_j) / (4 wo.h) = D(h; t_j) / (4 (wo.t_j) (1 + Lambda(wo; t_j))),
 * with D, Lambda the flake Beckmann measured from t_j (angles through |a x t|
 * so that tiny alpha stays exact in float) and G_x the Smith G2 of the map's
 * distribution (mf_ibm_set_shadowing). Returns the weighted sums. */
MF_INLINE mf_real mf__ibm_lobes(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, int want_f,
                                mf_real *pdf)
{
    mf__ibm_set s;
    mf__ibm_fp p;
    mf_real gx = MF_R(-1.0), a = ibm->alpha, sf = MF_R(0.0), spdf = MF_R(0.0);
    mf_vec3 h;
    int r = ibm->radius, b = ibm->res, cx, cy, i, small, nb = 0, known = 0;
    int near[MF_IBM_MAX_WINDOW], ndx[MF_IBM_MAX_WINDOW], ndy[MF_IBM_MAX_WINDOW];
    mf_vec3 tn[MF__IBM_KEPT_NORMALS];   /* the set's first mean normals, where the facing test read them (known) */
    h = mf_normalize(mf_add(wo, wi));
    if (!(h.z > MF_R(0.0))) return MF_R(0.0);
    cx = mf__ibm_cell(h.x, b); cy = mf__ibm_cell(h.y, b);
    /* the bins that may hold texels of the footprint, found before any
     * footprint work (none: 0) - but for footprints of at most 16 texels,
     * which read their texels' bins for less (mf__ibm_direct_any) */
    small = f && (mf_real)ibm->width * (mf_real)ibm->height * (MF_FABS(f->ax) + MF_FABS(f->bx)) * (MF_FABS(f->ay) + MF_FABS(f->by)) <= MF_R(16.0);
    if (!small && (nb = mf__ibm_near_bins(ibm, f, cx, cy, near, ndx, ndy)) == 0) return MF_R(0.0);
    mf__ibm_footprint(ibm, f, &p);
    if (p.mode == MF__IBM_NONE) return MF_R(0.0);
    mf__ibm_set_init(&s, cx, cy, r);
    /* a footprint of a few texels: the bins of its texels */
    if (p.mode == MF__IBM_EXACT && p.few) { if (!mf__ibm_direct_any(ibm, &p, &s, 1)) return MF_R(0.0); }
    else {   /* those bins; for a footprint of many texels only those that
         * face wo (and wi when only f is wanted), which spares their
         * traversal (small ones are checked after their weights) */
        if (small && (nb = mf__ibm_near_bins(ibm, f, cx, cy, near, ndx, ndy)) == 0) return MF_R(0.0);
        known = p.mode == MF__IBM_EXACT && !p.direct;
        for (i = 0; i < nb; ++i) {
            if (known) {
                mf_vec3 t = mf_ibm_bin_normal(ibm, near[i]);
                if (!(mf_dot(wo, t) > MF_R(0.0)) || !(mf_dot(h, t) > MF_R(0.0))) continue;
                if (!pdf && !(mf_dot(wi, t) > MF_R(0.0))) continue;
                if (s.n < MF__IBM_KEPT_NORMALS) tn[s.n] = t;
            }
            mf__ibm_set_add(&s, ndx[i], ndy[i], near[i]);
        }
    }
    if (s.n == 0) return MF_R(0.0);
    /* the bins' mean normals, read below unless the facing test has: their
     * loads start now, under the weights' work */
    for (i = known ? MF__IBM_KEPT_NORMALS : 0; i < s.n; ++i) MF__PREFETCH(ibm->data + ibm->mean_at + (size_t)s.bin[i]);
    mf__ibm_weights(ibm, &p, &s);
    for (i = 0; i < s.n; ++i) {
        mf_vec3 t, xh, xo;
        mf_real co, ci, ch, d, lo;
        if (!(s.w[i] > MF_R(0.0))) continue;
        t = known && i < MF__IBM_KEPT_NORMALS ? tn[i] : mf_ibm_bin_normal(ibm, s.bin[i]);
        co = mf_dot(wo, t); ci = mf_dot(wi, t); ch = mf_dot(h, t);
        if (!(co > MF_R(0.0)) || !(ch > MF_R(0.0))) continue;
        xh = mf_cross(h, t); xo = mf_cross(wo, t);
        d = mf_beckmann_D(a, a, mf_vec3_make(MF_SQRT(mf_dot(xh, xh)), MF_R(0.0), ch));
        if (!(d > MF_R(0.0))) continue;
        lo = mf__ibm_flake_lambda(a, mf_dot(xo, xo), co);
        spdf += s.w[i] * d / (MF_R(4.0) * co * (MF_R(1.0) + lo));
        if (want_f && ci > MF_R(0.0)) {
            mf_vec3 xi = mf_cross(wi, t);
            mf_real li = mf__ibm_flake_lambda(a, mf_dot(xi, xi), ci);
            if (gx < MF_R(0.0))
                gx = ibm->has_shadow ? MF_R(1.0) / (MF_R(1.0) + mf_lambda(&ibm->shadow, wo) + mf_lambda(&ibm->shadow, wi)) : MF_R(1.0);
            sf += s.w[i] * d * gx / ((MF_R(1.0) + lo + li) * MF_R(4.0) * wo.z * wi.z);
        }
    }
    if (pdf) *pdf = mf_min(spdf, MF_BIG);
    return mf_min(sf, MF_BIG);
}

MF_COLD mf_real mf_ibm_brdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi)
{
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ibm_lobes(ibm, f, wo, wi, 1, (mf_real *)0);
}

MF_COLD mf_real mf_ibm_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi)
{
    mf_real pdf = MF_R(0.0);
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    mf__ibm_lobes(ibm, f, wo, wi, 0, &pdf);
    return pdf;
}

MF_COLD mf_real mf_ibm_brdf_and_pdf(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_vec3 wi, mf_real *pdf)
{
    mf_real tmp = MF_R(0.0);
    if (!pdf) pdf = &tmp;
    *pdf = MF_R(0.0);
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0)) || !(wi.z > MF_R(0.0))) return MF_R(0.0);
    return mf__ibm_lobes(ibm, f, wo, wi, 1, pdf);
}

/* the direction of mf_ibm_sample (the zero vector: none) */
MF_INLINE mf_vec3 mf__ibm_sample_dir(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                     mf_real u3, mf_real u4)
{
    mf_vec3 none = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), t, tt, tb, o, m, wi, h;
    mf__ibm_fp p;
    int tx, ty, j, dx, dy, r;
    if (!ibm || !ibm->data || !(wo.z > MF_R(0.0))) return none;
    mf__ibm_footprint(ibm, f, &p);
    u1 = mf__u01(u1); u2 = mf__u01(u2);
    if (p.mode == MF__IBM_NONE) return none;
    if (p.mode == MF__IBM_POINT) { tx = p.tx; ty = p.ty; }
    else if (p.mode == MF__IBM_GLOBAL) {
        tx = (int)(u1 * (mf_real)ibm->width); ty = (int)(u2 * (mf_real)ibm->height);
    } else {
        mf_real x = p.cx + (u1 - MF_R(0.5)) * p.ax + (u2 - MF_R(0.5)) * p.bx;
        mf_real y = p.cy + (u1 - MF_R(0.5)) * p.ay + (u2 - MF_R(0.5)) * p.by;
        tx = (int)MF_FLOOR(x - (mf_real)ibm->width * MF_FLOOR(x / (mf_real)ibm->width));
        ty = (int)MF_FLOOR(y - (mf_real)ibm->height * MF_FLOOR(y / (mf_real)ibm->height));
    }
    if (tx < 0 || tx >= ibm->width) tx = 0;
    if (ty < 0 || ty >= ibm->height) ty = 0;
    j = mf_ibm_texel_bin(ibm, tx, ty);
    t = mf_ibm_bin_normal(ibm, j);
    if (!(mf_dot(wo, t) > MF_R(0.0))) return none;
    { mf_basis fr_ = mf_basis_from_normal(t); tt = fr_.t; tb = fr_.b; }
    o = mf_vec3_make(mf_dot(wo, tt), mf_dot(wo, tb), mf_dot(wo, t));
    m = mf_beckmann_sample_visible(ibm->alpha, ibm->alpha, o, u3, u4);
    m = mf_add(mf_add(mf_scale(tt, m.x), mf_scale(tb, m.y)), mf_scale(t, m.z));
    wi = mf_reflect(wo, m);
    if (!(wi.z > MF_R(0.0))) return none;
    h = mf_normalize(mf_add(wo, wi));
    if (!(h.z > MF_R(0.0))) return none;
    /* the pdf sums the bins around beta(h) only: outside, no sample */
    r = ibm->radius;
    dx = j % ibm->res - mf__ibm_cell(h.x, ibm->res);
    dy = j / ibm->res - mf__ibm_cell(h.y, ibm->res);
    if (dx * dx + dy * dy > r * (r + 1)) return none;
    {
        mf_real ch = mf_dot(h, t);
        mf_vec3 xh = mf_cross(h, t);
        if (!(ch > MF_R(0.0)) || !(mf_beckmann_D(ibm->alpha, ibm->alpha, mf_vec3_make(MF_SQRT(mf_dot(xh, xh)), MF_R(0.0), ch)) > MF_R(0.0)))
            return none;
    }
    return wi;
}
MF_COLD mf_sample mf_ibm_sample(const mf_ibm *ibm, const mf_footprint *f, mf_vec3 wo, mf_real u1, mf_real u2,
                                mf_real u3, mf_real u4)
{
    mf_sample s = mf__no_sample();
    mf_real fv, pdf = MF_R(0.0);
    mf_vec3 wi = mf__ibm_sample_dir(ibm, f, wo, u1, u2, u3, u4);
    if (!(wi.z > MF_R(0.0))) return s;
    fv = mf_ibm_brdf_and_pdf(ibm, f, wo, wi, &pdf);
    if (!(pdf > MF_R(0.0))) return s;
    s.wi = wi;
    s.pdf = pdf;
    s.weight = mf_min(fv * wi.z / pdf, MF_BIG);
    s.lobe = MF_LOBE_REFLECTION;
    return s;
}
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
