/* @optional MF_NO_IBM */
/* @api */
/* ======================================================================== */
/* == 15c. Inverse Bin Map: bin weights (the kd-tree traversal)             */
/* ======================================================================== */
/* The weight of a bin, or of a window of bins, over a footprint (Eq. 5.3,
 * 5.8, 5.15, 5.17): direct texel sums for small footprints, the kd-trees of
 * the bins' texel lists for large ones, early exits for empty bins. */
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
/* @cold */
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
