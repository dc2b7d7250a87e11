/* @optional MF_NO_IBM */
/* @api */
/* ======================================================================== */
/* == 15b. Inverse Bin Map: footprints (periods, pieces, exact areas)       */
/* ======================================================================== */
/* A pixel footprint (mf_footprint) cut into the period cells of the tiled
 * map and the convex pieces each texel or kd node is clipped against, with
 * exact areas (closed form for one cutting edge, Green's theorem else). */
/* ---- footprints: periods, pieces, exact areas ---- */

#define MF__IBM_NONE 0     /* no texel (center not finite) */
#define MF__IBM_POINT 1    /* degenerate footprint: the texel at the center */
#define MF__IBM_EXACT 2    /* full periods plus exact pieces */
#define MF__IBM_GLOBAL 3   /* too many periods: the whole map's histogram */

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
/* @cold */
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
