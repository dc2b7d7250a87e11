/* @optional MF_NO_MICROSURFACE */
/* @api */
/* ======================================================================== */
/* == 16. Microsurface generation                                           */
/* ======================================================================== */
/* Ribardiere, Bringier, Meneveaux, Simonot 2019, "Microfacet BSDFs Generated
 * from NDFs and Explicit Microgeometry", Sec. 2 and 4: periodic height fields
 * whose normals follow any mf_ndf (Algorithm 1: slopes Q_m sampled from D,
 * Schwarz error Eq. 19, least-squares integration Eq. 20-21 with the discrete
 * derivatives of Eq. 22, re-matching); the virtual gonioreflectometer that
 * traces them is 16_microsurface_gonio.h. Everything is in the implementation
 * section (no inline part). */

/* ---- Microsurface generation ---- */
/* mf_microsurface_generate (Ribardiere et al. 2019, Algorithm 1): a periodic
 * size x size height field whose normals follow d. Row-major (x along a row,
 * y down the rows), heights in units of the grid spacing, mean 0: the central
 * difference (h[x+1] - h[x-1]) / 2 is the slope dh/dx (and likewise in y), and
 * the normal (-dh/dx, -dh/dy, 1)/|.| follows d's distribution. The surface is
 * also consistent as a triangle mesh (each grid square split by the diagonal
 * from (x+1, y) to (x, y+1), the geometry mf_gonio_measure traces): every
 * triangle's slope is a one-sided difference at one of its corners, and the
 * generator targets one-sided and central differences alike (see the
 * implementation). The surface converges toward one that is smooth over a
 * few cells (slopes of neighbours correlated, as they must be for the two
 * readings to agree): histograms match D to a few percent (total variation
 * over the slope plane 0.02 to 0.03 for Beckmann, 0.04 to 0.05 for the heavier
 * tails of GGX and Student-t, at 128^2 and 150 iterations; a random sample of
 * the same size scores 0.04). size must be a power of two in [MF_MICROSURFACE_MIN_SIZE,
 * MF_MICROSURFACE_MAX_SIZE]; memory about 100 bytes per cell; time linear
 * in cells times iterations (docs/PERFORMANCE.md).
 * Deterministic for a seed (within one build: float and double builds draw
 * different samples). d must be centered
 * (every periodic surface has mean slope 0): a LEADR distribution with a
 * non-zero mean slope is rejected. Errors: NULL pointers, bad size, negative
 * iterations or more than MF_MICROSURFACE_MAX_ITERATIONS, an invalid distribution (MF_ERROR_INVALID_ARGUMENT); allocation
 * (MF_ERROR_OUT_OF_MEMORY); nothing stays allocated on failure. */
#define MF_MICROSURFACE_MIN_SIZE 8
#define MF_MICROSURFACE_MAX_SIZE 4096
#define MF_MICROSURFACE_THRESHOLD MF_R(0.02)
/* the most re-matching iterations a call accepts (the paper uses 500; the
 * cap bounds a call's time at the largest size): more is an invalid argument */
#define MF_MICROSURFACE_MAX_ITERATIONS 100000
/* slopes drawn beyond this magnitude (heavy tails, u -> 1) are shortened to it */
#define MF_MICROSURFACE_MAX_SLOPE MF_R(1e3)

/* Options of mf_microsurface_generate_ex; all-zero (or NULL) means the defaults. */
typedef struct mf_microsurface_options {
    mf_real threshold;       /* Schwarz threshold on eps(x, y); 0: MF_MICROSURFACE_THRESHOLD */
    mf_real max_rematch;     /* at most this fraction of the cells, those of largest eps, is */
                             /* re-matched per iteration; 1: all above the threshold, as in */
                             /* the paper; 0 (default): 0.5 for light tails down to 0.25 for */
                             /* heavy ones (see the implementation) */
    int independent;         /* 0: jittered stratified random numbers for Q_m; 1: independent */
    mf_progress_fn progress; /* called after each iteration with (done, iterations, ctx); may be NULL */
    void *ctx;
    mf_real *gradients;      /* optional output, size*size*2: the final target gradient field, */
                             /* a permutation of the sampled slopes Q_m (x, y interleaved) */
    mf_real *schwarz;        /* optional output, size*size: the final eps(x, y) */
} mf_microsurface_options;

typedef struct mf_microsurface_stats {
    int iterations;          /* iterations done */
    mf_real below;           /* fraction of cells with eps <= threshold at the end */
    mf_real eps_mean;        /* mean of eps over the cells at the end */
    mf_real eps_median;
    int rematched;           /* cells above the threshold at the end (0 without iterations) */
    mf_real rms_target;      /* RMS of the sampled slopes |Q_m| (both components) */
    mf_real rms_central;     /* RMS of the central-difference slopes of the result */
    mf_real rms_triangle;    /* RMS of the triangle slopes of the result */
} mf_microsurface_stats;

MFDEF mf_result mf_microsurface_generate(const mf_ndf *d, int size, int iterations, mf_u64 seed,
                                         mf_real *heights);
MFDEF mf_result mf_microsurface_generate_ex(const mf_ndf *d, int size, int iterations, mf_u64 seed,
                                            const mf_microsurface_options *options, mf_real *heights,
                                            mf_microsurface_stats *stats);
/* Step 3 alone: the periodic height field (mean 0) whose triangles and
 * central differences best fit per-point slopes gradients_xy (size*size*2,
 * x and y interleaved) in the least-squares sense; the discrete Poisson
 * equation, solved by FFT in double. A field that is the central difference
 * of a smooth surface gives that surface back up to O(w^2) per Fourier mode w
 * (the mode's amplitude times cos^2(w/2)). Same size rules and errors as the
 * generator; non-finite input: MF_ERROR_INVALID_DATA. */
MFDEF mf_result mf_microsurface_integrate(const mf_real *gradients_xy, int size, mf_real *heights);

/* @impl */
/* ---- Generation (Ribardiere et al. 2019, Sec. 4.2, Algorithm 1) ----
 *
 * Discretization. A grid point (x, y) carries one target slope t = (tx, ty),
 * a sample of Q_m. The surface is the triangle mesh of the grid (squares cut
 * by the diagonal (x+1, y)-(x, y+1)); the triangle below-left of the
 * diagonal has the forward differences F = (h[x+1] - h[x], h[y+1] - h[y]) of
 * its corner (x, y) as slope, the one above-right the backward differences
 * B = (h[x] - h[x-1], h[y] - h[y-1]) of its corner (x+1, y+1). Integration
 * (Step 3) is the least-squares fit of both triangles of every point to its
 * target, sum |F - t|^2 + |B - t|^2: in Fourier, with the discrete symbols
 * (not the continuous ones of Eq. 21, which bias the discrete slopes),
 *     H = -i (sin wx Tx + sin wy Ty) / (2 (2 - cos wx - cos wy)),
 * the discrete Poisson equation "5-point Laplacian h = central divergence t".
 * Since (F + B) / 2 is the central difference of Eq. 22, a point whose two
 * triangles match t has its central difference at t as well: the API's
 * central differences and the traced triangles follow the same targets. The
 * Laplacian vanishes only at w = 0, so nothing is amplified (the central
 * symbol sin w alone vanishes at the Nyquist frequency and decouples the two
 * checkerboard sub-lattices).
 *
 * Schwarz error. Eq. 19, the discrete Schwarz condition, on the target
 * field around the grid square of corner (x, y), relative to the mean
 * cumulative slope of Q_m:
 *     eps(x, y) = |tx(x,y) + ty(x+1,y) - ty(x,y) - tx(x,y+1)| / mean(|tx| + |ty|);
 * threshold 0.02 is the paper's "2% of a cumulative dx and dy error". (The
 * residual of the fit, |F - t| + |B - t|, as the error instead re-matches
 * ~98% of the points every iteration for the same final histogram.)
 *
 * Re-matching (Step 2). Points with eps > threshold release their targets
 * into a pool; in a random order, each takes the unused pool value nearest
 * (Euclidean, slope space) to its central difference, found in a grid over
 * slope space by a spiral search of rings of cells; the search stops when
 * the next ring cannot hold anything nearer, so the match is exact. The grid
 * lines sit at quantiles of Q_m (a uniform grid in the marginal CDFs), so
 * heavy tails (GGX, Student-t) do not pile every sample into one cell: about
 * sixteen pool values per cell and O(1) work per query on average. The
 * targets stay a permutation of Q_m at every step. Before the search the
 * queries' spread is matched to the pool's (see mf__ms_rematch).
 *
 * At most a fraction max_rematch of the points, those of largest eps, are
 * re-matched per iteration. With every point above the threshold (the
 * paper), heavy tails never settle: on GGX 0.4 (128^2, 150 iterations) 90% of
 * the points exceed 0.02 every iteration and the surface ends with 35% too
 * few near-normal facets, its median slope 12% high. Measured over six seeds
 * (median slope length relative to D's, and the deficit at the normal):
 *     max_rematch   GGX 0.4            Beckmann 0.5
 *     1 (paper)     +12%, 35% too few  -0.5%
 *     0.5           +3..+10%, 7..27%   -0.7 .. -0.1%
 *     0.25          -1.5..+2.8%, 2..5% -3.2 .. -2.6%
 * so the default picks it from the tail weight of Q_m, w = r99 / r50 (the
 * 99th and 50th percentiles of |slope|; Beckmann 2.6, Student-t gamma 3 4.7,
 * GGX 10): 0.5 for w <= 3, 0.25 for w >= 6, linear between. It also makes
 * the iterations cheaper.
 *
 * Measured alternatives (Beckmann 0.5, 256^2, 200 iterations; total variation
 * of the central / triangle slope histograms against D, fraction of cells
 * below the threshold): the paper's continuous symbol with Eq. 19, 0.029 /
 * 0.027, 47%; the central symbol sin w alone, 0.011 / 0.54 (the triangles,
 * i.e. the traced surface, are 2.4 times too rough: checkerboard), 87%;
 * forward differences only, 0.035 / 0.027, 11%; this scheme, 0.033 / 0.030,
 * 51%, then 0.03 / 0.03 and 67% with the spread matching. All schemes that
 * keep the triangles right converge to surfaces whose neighbouring slopes are
 * correlated (0.97 to 0.99 at lag 1). */

static double mf__absd(double x) { return x < 0.0 ? -x : x; }
static double mf__mind(double a, double b) { return a < b ? a : b; }

typedef struct mf__ms {
    int n;
    size_t n2;
    double *tx, *ty, *h, *eps, *z, *tmp, *fc, *fs;
    double *px, *py, *qx, *qy, *sx, *sy, *ex, *ey;   /* pool (binned), queries, sorted Q_m, grid lines */
    int *cell, *start, *count, *bin;
    double sbar;          /* mean |tx| + |ty| of Q_m */
} mf__ms;

static void mf__ms_zero(mf__ms *m)
{
    m->tx = m->ty = m->h = m->eps = m->z = m->tmp = m->fc = m->fs = 0;
    m->px = m->py = m->qx = m->qy = m->sx = m->sy = m->ex = m->ey = 0;
    m->cell = m->start = m->count = m->bin = 0;
    m->n = 0; m->n2 = 0; m->sbar = 0.0;
}

static void mf__ms_free(mf__ms *m)
{
    MF_FREE(m->tx); MF_FREE(m->ty); MF_FREE(m->h); MF_FREE(m->eps); MF_FREE(m->z); MF_FREE(m->tmp);
    MF_FREE(m->fc); MF_FREE(m->fs); MF_FREE(m->px); MF_FREE(m->py); MF_FREE(m->qx); MF_FREE(m->qy);
    MF_FREE(m->sx); MF_FREE(m->sy); MF_FREE(m->ex); MF_FREE(m->ey); MF_FREE(m->cell); MF_FREE(m->start);
    MF_FREE(m->count); MF_FREE(m->bin);
}

static int mf__ms_alloc(mf__ms *m, int n)
{
    size_t n2 = (size_t)n * (size_t)n, nb = n2 / 16 + 2, ne = (size_t)n + 2;
    m->n = n; m->n2 = n2;
#define MF__MS_A(p, T, cnt) (m->p = (T *)MF_MALLOC(sizeof(T) * (cnt)))
    MF__MS_A(tx, double, n2); MF__MS_A(ty, double, n2); MF__MS_A(h, double, n2); MF__MS_A(eps, double, n2);
    MF__MS_A(z, double, 2 * n2); MF__MS_A(tmp, double, 16 * (size_t)n); MF__MS_A(fc, double, (size_t)n);
    MF__MS_A(fs, double, (size_t)n); MF__MS_A(px, double, n2); MF__MS_A(py, double, n2);
    MF__MS_A(qx, double, n2); MF__MS_A(qy, double, n2); MF__MS_A(sx, double, n2); MF__MS_A(sy, double, n2);
    MF__MS_A(ex, double, ne); MF__MS_A(ey, double, ne); MF__MS_A(cell, int, n2); MF__MS_A(start, int, nb + 1);
    MF__MS_A(count, int, nb); MF__MS_A(bin, int, n2);
#undef MF__MS_A
    return m->tx && m->ty && m->h && m->eps && m->z && m->tmp && m->fc && m->fs && m->px && m->py &&
           m->qx && m->qy && m->sx && m->sy && m->ex && m->ey && m->cell && m->start && m->count && m->bin;
}

/* cos and sin of 2 pi k / n for any k in [0, n) from the half table */
static void mf__ms_cs(const mf__ms *m, int k, double *c, double *s)
{
    int half = m->n / 2;
    if (k < half) { *c = m->fc[k]; *s = m->fs[k]; }
    else { *c = -m->fc[k - half]; *s = -m->fs[k - half]; }
}

/* Step 3: h from the targets (least squares over both triangles of every point) */
static void mf__ms_integrate(mf__ms *m)
{
    int n = m->n, kx, ky;
    size_t i, n2 = m->n2;
    double *z = m->z, inv = 1.0 / (double)n2;
    for (i = 0; i < n2; ++i) { z[2 * i] = m->tx[i]; z[2 * i + 1] = m->ty[i]; }
    mf__fft2(z, n, m->fc, m->fs, m->tmp);
    /* Z = FFT(tx + i ty): Tx(k) = (Z(k) + conj Z(-k)) / 2, Ty(k) = (Z(k) - conj Z(-k)) / 2i.
     * h is real: H(-k) = conj H(k), so each pair (k, -k) is solved once. */
    for (ky = 0; ky < n; ++ky)
        for (kx = 0; kx < n; ++kx) {
            size_t i0 = (size_t)ky * (size_t)n + (size_t)kx;
            size_t i1 = (size_t)((n - ky) & (n - 1)) * (size_t)n + (size_t)((n - kx) & (n - 1));
            double cx, sx, cy, sy, xr, xi, yr, yi, den, hr, hi;
            if (i1 < i0) continue;
            mf__ms_cs(m, kx, &cx, &sx);
            mf__ms_cs(m, ky, &cy, &sy);
            den = 2.0 * (2.0 - cx - cy);
            if (!(den > 1e-300)) { z[2 * i0] = z[2 * i0 + 1] = 0.0; continue; }   /* mean height 0 */
            xr = 0.5 * (z[2 * i0] + z[2 * i1]); xi = 0.5 * (z[2 * i0 + 1] - z[2 * i1 + 1]);
            yr = 0.5 * (z[2 * i0 + 1] + z[2 * i1 + 1]); yi = -0.5 * (z[2 * i0] - z[2 * i1]);
            /* H = -i (sx X + sy Y) / den */
            hr = (sx * xi + sy * yi) / den;
            hi = -(sx * xr + sy * yr) / den;
            z[2 * i0] = hr; z[2 * i0 + 1] = hi;
            z[2 * i1] = hr; z[2 * i1 + 1] = -hi;
        }
    mf__ifft2_real(z, n, m->fc, m->fs, m->tmp, m->h);
    for (i = 0; i < n2; ++i) m->h[i] *= inv;
}

/* one-sided differences of h at point i = (x, y) */
static void mf__ms_diff(const mf__ms *m, int x, int y, double *fx, double *fy, double *bx, double *by)
{
    int n = m->n, mk = n - 1;
    const double *h = m->h;
    double c = h[(size_t)y * (size_t)n + (size_t)x];
    *fx = h[(size_t)y * (size_t)n + (size_t)((x + 1) & mk)] - c;
    *bx = c - h[(size_t)y * (size_t)n + (size_t)((x - 1) & mk)];
    *fy = h[(size_t)((y + 1) & mk) * (size_t)n + (size_t)x] - c;
    *by = c - h[(size_t)((y - 1) & mk) * (size_t)n + (size_t)x];
}

/* the points with eps above the threshold, listed in m->cell with their
 * central differences (the queries); returns how many */
static int mf__ms_list(mf__ms *m, double threshold)
{
    int n = m->n, x, y, k = 0;
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            size_t i = (size_t)y * (size_t)n + (size_t)x;
            if (m->eps[i] > threshold) {
                double fx, fy, bx, by;
                mf__ms_diff(m, x, y, &fx, &fy, &bx, &by);
                m->cell[k] = (int)i;
                m->qx[k] = 0.5 * (fx + bx);   /* the central difference, Eq. 22 */
                m->qy[k] = 0.5 * (fy + by);
                ++k;
            }
        }
    return k;
}

/* eps of every point (Eq. 19 on the target field), then the list of the
 * points above the threshold; at most max_fraction of all points (those of
 * largest eps) when that is below 1 */
static int mf__ms_errors(mf__ms *m, double threshold, double max_fraction)
{
    int n = m->n, mk = n - 1, x, y, above = 0;
    double inv = 1.0 / m->sbar;
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            size_t i = (size_t)y * (size_t)n + (size_t)x;
            size_t ix = (size_t)y * (size_t)n + (size_t)((x + 1) & mk), iy = (size_t)((y + 1) & mk) * (size_t)n + (size_t)x;
            double e = mf__absd(m->tx[i] + m->ty[ix] - m->ty[i] - m->tx[iy]) * inv;
            m->eps[i] = e;
            if (e > threshold) ++above;
        }
    if ((double)above > max_fraction * (double)m->n2) {
        size_t i, r = (size_t)((1.0 - max_fraction) * (double)m->n2);
        double q;
        for (i = 0; i < m->n2; ++i) m->z[i] = m->eps[i];
        q = mf__select_d(m->z, m->n2, r < m->n2 ? r : m->n2 - 1);
        if (q > threshold) threshold = q;
    }
    return mf__ms_list(m, threshold);
}

/* bin of v among edges e[0..g] (grid cell index in [0, g)) */
static int mf__ms_bin(const double *e, int g, double v)
{
    int lo = 0, hi = g;   /* find the last j in [0, g) with e[j] <= v */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (e[mid] <= v) lo = mid; else hi = mid;
    }
    return lo;
}

/* Step 2: re-match the k points in m->cell (their targets form the pool;
 * m->qx, m->qy hold their central differences) */
static void mf__ms_rematch(mf__ms *m, int k, mf__pcg *rng)
{
    int n = m->n, g, j, q, nb;
    size_t m2 = m->n2;
    if (k <= 0) return;
    /* g x g cells, about sixteen pool values each (fewer, larger cells visit
     * fewer empty cells once the pool thins out); lines at quantiles of Q_m */
    g = 1;
    while ((g + 1) * (g + 1) * 16 <= k && g < n / 2) ++g;
    for (j = 0; j <= g; ++j) {
        size_t r = (size_t)((double)(m2 - 1) * (double)j / (double)g);
        m->ex[j] = m->sx[r]; m->ey[j] = m->sy[r];
    }
    nb = g * g;
    for (j = 0; j <= nb; ++j) m->start[j] = 0;
    for (j = 0; j < k; ++j) {
        int i = m->cell[j];
        m->bin[j] = mf__ms_bin(m->ey, g, m->ty[i]) * g + mf__ms_bin(m->ex, g, m->tx[i]);
        ++m->start[m->bin[j] + 1];
    }
    for (j = 0; j < nb; ++j) { m->start[j + 1] += m->start[j]; m->count[j] = 0; }
    for (j = 0; j < k; ++j) {   /* counting sort of the pool values into the cells */
        int i = m->cell[j], b = m->bin[j], p = m->start[b] + m->count[b]++;
        m->px[p] = m->tx[i]; m->py[p] = m->ty[i];
    }
    /* the queries' spread matched to the pool's, per axis, when they are
     * narrower (the median of |slope|, which heavy tails do not sway): early
     * on the integrated field is much smoother than its targets, and nearest
     * values to the shrunken queries would empty the middle of the pool
     * first. Measured on Beckmann 0.5, 128^2, 150 iterations: the density of
     * the smallest slopes 0.83 of D without, 0.93 with. Queries broader than
     * the pool (heavy tails later on) are left alone: shrinking them hurts. */
    {
        double f[2];
        int ax;
        for (ax = 0; ax < 2; ++ax) {
            const double *qa = ax ? m->qy : m->qx, *pa = ax ? m->py : m->px;
            double mq, mp;
            for (j = 0; j < k; ++j) { m->z[j] = mf__absd(qa[j]); m->z[k + j] = mf__absd(pa[j]); }
            mq = mf__select_d(m->z, (size_t)k, (size_t)k / 2);
            mp = mf__select_d(m->z + k, (size_t)k, (size_t)k / 2);
            f[ax] = mq > 0.0 && mp > 0.0 && mp > mq ? mp / mq : 1.0;
        }
        for (j = 0; j < k; ++j) { m->qx[j] *= f[0]; m->qy[j] *= f[1]; }
    }
    /* serve the points in a random order */
    for (j = k - 1; j > 0; --j) {
        int r = (int)mf__pcg_below(rng, (unsigned)(j + 1)), t = m->cell[j];
        double v;
        m->cell[j] = m->cell[r]; m->cell[r] = t;
        v = m->qx[j]; m->qx[j] = m->qx[r]; m->qx[r] = v;
        v = m->qy[j]; m->qy[j] = m->qy[r]; m->qy[r] = v;
    }
    for (q = 0; q < k; ++q) {
        int i = m->cell[q], bx, by, r, bestpos = -1, bestbin = -1, last;
        double cx = m->qx[q], cy = m->qy[q], bd = 1e300;
        bx = mf__ms_bin(m->ex, g, cx);
        by = mf__ms_bin(m->ey, g, cy);
        for (r = 0;; ++r) {   /* spiral: ring r is the border of the (2r+1)^2 square of cells */
            int yy, more = 0;
            double lb = 1e300;
            for (yy = by - r; yy <= by + r; ++yy) {
                int xx, step = (yy == by - r || yy == by + r || r == 0) ? 1 : 2 * r;
                if (yy < 0 || yy >= g) continue;
                for (xx = bx - r; xx <= bx + r; xx += step) {
                    int b, p, e;
                    if (xx < 0 || xx >= g) continue;
                    b = yy * g + xx;
                    for (p = m->start[b], e = p + m->count[b]; p < e; ++p) {
                        double dx = m->px[p] - cx, dy = m->py[p] - cy, d2 = dx * dx + dy * dy;
                        if (d2 < bd) { bd = d2; bestpos = p; bestbin = b; }
                    }
                }
            }
            /* anything beyond ring r is at least lb away */
            if (bx - r - 1 >= 0) { lb = mf__mind(lb, cx - m->ex[bx - r]); more = 1; }
            if (bx + r + 1 < g) { lb = mf__mind(lb, m->ex[bx + r + 1] - cx); more = 1; }
            if (by - r - 1 >= 0) { lb = mf__mind(lb, cy - m->ey[by - r]); more = 1; }
            if (by + r + 1 < g) { lb = mf__mind(lb, m->ey[by + r + 1] - cy); more = 1; }
            if (!more || (bestpos >= 0 && lb > 0.0 && bd <= lb * lb)) break;
        }
        /* take it; the last value of its cell moves into its place */
        m->tx[i] = m->px[bestpos]; m->ty[i] = m->py[bestpos];
        last = m->start[bestbin] + --m->count[bestbin];
        m->px[bestpos] = m->px[last]; m->py[bestpos] = m->py[last];
    }
}

/* 1 if d can be sampled and evaluated: finite roughness, a finite unit
 * sample with z > 0 and D > 0 there, and no mean slope (LEADR) */
static int mf__ms_ndf_ok(const mf_ndf *d)
{
    mf_vec3 m;
    mf_real v;
    if (!(d->ax > MF_R(0.0) && d->ax < MF_BIG) || !(d->ay > MF_R(0.0) && d->ay < MF_BIG)) return 0;
    if (d->transformed && !mf_transform_is_valid(d->M)) return 0;
    if (mf__ndf_tilted(d->type)) {
        mf__ndf_mean_slope(d, &m.x, &m.y);
        if (m.x != MF_R(0.0) || m.y != MF_R(0.0)) return 0;
    }
    m = mf_sample_D(d, MF_R(0.3), MF_R(0.2));
    v = mf_D(d, m);
    return m.z > MF_R(0.0) && m.z <= MF_R(1.0) && MF_FABS(m.x) <= MF_R(1.0) && MF_FABS(m.y) <= MF_R(1.0) &&
           v > MF_R(0.0) && v < MF_BIG;
}

MFDEF mf_result mf_microsurface_generate_ex(const mf_ndf *d, int size, int iterations, mf_u64 seed,
                                            const mf_microsurface_options *options, mf_real *heights,
                                            mf_microsurface_stats *stats)
{
    mf_microsurface_options oz;
    const mf_microsurface_options *o = options;
    mf__ms m;
    mf__pcg rng;
    int n = size, it, k = 0, x, y;
    size_t i, n2;
    double thr, cap, smax = (double)MF_MICROSURFACE_MAX_SLOPE, acc[4];
    if (stats) {
        stats->iterations = stats->rematched = 0;
        stats->below = stats->eps_mean = stats->eps_median = MF_R(0.0);
        stats->rms_target = stats->rms_central = stats->rms_triangle = MF_R(0.0);
    }
    if (!o) { memset(&oz, 0, sizeof oz); o = &oz; }
    if (!d || !heights || !mf__pow2(size) || size < MF_MICROSURFACE_MIN_SIZE || size > MF_MICROSURFACE_MAX_SIZE ||
        iterations < 0 || iterations > MF_MICROSURFACE_MAX_ITERATIONS || !(o->threshold >= MF_R(0.0) && o->threshold < MF_BIG) ||
        !(o->max_rematch >= MF_R(0.0) && o->max_rematch <= MF_R(1.0)) || !mf__ms_ndf_ok(d))
        return MF_ERROR_INVALID_ARGUMENT;
    thr = o->threshold > MF_R(0.0) ? (double)o->threshold : (double)MF_MICROSURFACE_THRESHOLD;
    mf__ms_zero(&m);
    if (!mf__ms_alloc(&m, n)) { mf__ms_free(&m); return MF_ERROR_OUT_OF_MEMORY; }
    n2 = m.n2;
    mf__fft_twiddles(m.fc, m.fs, n);
    /* Q_m: n^2 slopes drawn with density D cos (= the slope density P22),
     * stratified on an n x n grid of (u1, u2) when asked; then shuffled onto the grid */
    mf__pcg_seed(&rng, seed, 0x6d66u);
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            double u1 = mf__pcg_u01(&rng), u2 = mf__pcg_u01(&rng), sxv, syv, l;
            mf_vec3 w;
            if (!o->independent) { u1 = ((double)x + u1) / (double)n; u2 = ((double)y + u2) / (double)n; }
            w = mf_sample_D(d, mf__u01_real(u1), mf__u01_real(u2));
            i = (size_t)y * (size_t)n + (size_t)x;
            if (w.z > MF_R(0.0)) {
                sxv = -(double)w.x / (double)w.z; syv = -(double)w.y / (double)w.z;
                l = mf__sqrt_d(sxv * sxv + syv * syv);
                if (l > smax) { sxv *= smax / l; syv *= smax / l; }
            } else {   /* a horizontal normal: the steepest slope allowed, along it */
                l = mf__sqrt_d((double)w.x * (double)w.x + (double)w.y * (double)w.y);
                sxv = l > 0.0 ? -(double)w.x / l * smax : 0.0;
                syv = l > 0.0 ? -(double)w.y / l * smax : 0.0;
            }
            m.tx[i] = sxv; m.ty[i] = syv;
        }
    for (i = n2 - 1; i > 0; --i) {
        size_t r = (size_t)mf__pcg_below(&rng, (unsigned)(i + 1));
        double t = m.tx[i]; m.tx[i] = m.tx[r]; m.tx[r] = t;
        t = m.ty[i]; m.ty[i] = m.ty[r]; m.ty[r] = t;
    }
    m.sbar = 0.0;
    for (i = 0; i < n2; ++i) {
        m.sx[i] = m.tx[i]; m.sy[i] = m.ty[i];
        m.sbar += mf__absd(m.tx[i]) + mf__absd(m.ty[i]);
    }
    m.sbar = m.sbar / (double)n2 + 1e-300;
    mf__sort_d(m.sx, n2);
    mf__sort_d(m.sy, n2);
    cap = (double)o->max_rematch;
    if (!(cap > 0.0)) {   /* automatic: from the tail weight of Q_m, r99 / r50 of |slope| */
        double r50, r99, w;
        for (i = 0; i < n2; ++i) m.z[i] = m.tx[i] * m.tx[i] + m.ty[i] * m.ty[i];
        r50 = mf__select_d(m.z, n2, n2 / 2);
        r99 = mf__select_d(m.z, n2, n2 - 1 - n2 / 100);
        w = r50 > 0.0 ? mf__sqrt_d(r99 / r50) : 10.0;
        w = (w - 3.0) / 3.0;
        cap = 0.5 - 0.25 * (w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w));
    }
    /* Algorithm 1: integrate, then (compute errors, re-match, integrate) per iteration */
    mf__ms_integrate(&m);
    for (it = 0; it < iterations; ++it) {
        k = mf__ms_errors(&m, thr, cap);
        mf__ms_rematch(&m, k, &rng);
        mf__ms_integrate(&m);
        if (o->progress) o->progress(it + 1, iterations, o->ctx);
    }
    k = mf__ms_errors(&m, thr, 1.0);
    for (i = 0; i < n2; ++i) heights[i] = (mf_real)m.h[i];
    if (o->gradients)
        for (i = 0; i < n2; ++i) { o->gradients[2 * i] = (mf_real)m.tx[i]; o->gradients[2 * i + 1] = (mf_real)m.ty[i]; }
    if (o->schwarz)
        for (i = 0; i < n2; ++i) o->schwarz[i] = (mf_real)m.eps[i];
    if (stats) {
        acc[0] = acc[1] = acc[2] = acc[3] = 0.0;
        for (y = 0; y < n; ++y)
            for (x = 0; x < n; ++x) {
                double fx, fy, bx, by, cx, cy;
                i = (size_t)y * (size_t)n + (size_t)x;
                mf__ms_diff(&m, x, y, &fx, &fy, &bx, &by);
                cx = 0.5 * (fx + bx); cy = 0.5 * (fy + by);
                acc[0] += m.tx[i] * m.tx[i] + m.ty[i] * m.ty[i];
                acc[1] += cx * cx + cy * cy;
                acc[2] += 0.5 * (fx * fx + fy * fy + bx * bx + by * by);
                acc[3] += m.eps[i];
            }
        stats->iterations = iterations;
        stats->rematched = iterations > 0 ? k : 0;
        stats->below = (mf_real)(1.0 - (double)k / (double)n2);
        stats->eps_mean = (mf_real)(acc[3] / (double)n2);
        stats->rms_target = (mf_real)mf__sqrt_d(acc[0] / (2.0 * (double)n2));
        stats->rms_central = (mf_real)mf__sqrt_d(acc[1] / (2.0 * (double)n2));
        stats->rms_triangle = (mf_real)mf__sqrt_d(acc[2] / (2.0 * (double)n2));
        mf__sort_d(m.eps, n2);
        stats->eps_median = (mf_real)m.eps[n2 / 2];
    }
    mf__ms_free(&m);
    return MF_SUCCESS;
}

MFDEF mf_result mf_microsurface_generate(const mf_ndf *d, int size, int iterations, mf_u64 seed, mf_real *heights)
{
    return mf_microsurface_generate_ex(d, size, iterations, seed, 0, heights, 0);
}

MFDEF mf_result mf_microsurface_integrate(const mf_real *gradients_xy, int size, mf_real *heights)
{
    mf__ms m;
    size_t i, n2;
    if (!gradients_xy || !heights || !mf__pow2(size) || size < MF_MICROSURFACE_MIN_SIZE || size > MF_MICROSURFACE_MAX_SIZE)
        return MF_ERROR_INVALID_ARGUMENT;
    n2 = (size_t)size * (size_t)size;
    for (i = 0; i < 2 * n2; ++i)
        if (!mf__finite_bits(gradients_xy[i]) || !(MF_FABS(gradients_xy[i]) < MF_BIG)) return MF_ERROR_INVALID_DATA;
    mf__ms_zero(&m);
    m.n = size; m.n2 = n2;
    m.tx = (double *)MF_MALLOC(sizeof(double) * n2);
    m.ty = (double *)MF_MALLOC(sizeof(double) * n2);
    m.h = (double *)MF_MALLOC(sizeof(double) * n2);
    m.z = (double *)MF_MALLOC(sizeof(double) * 2 * n2);
    m.tmp = (double *)MF_MALLOC(sizeof(double) * 16 * (size_t)size);
    m.fc = (double *)MF_MALLOC(sizeof(double) * (size_t)size);
    m.fs = (double *)MF_MALLOC(sizeof(double) * (size_t)size);
    if (!m.tx || !m.ty || !m.h || !m.z || !m.tmp || !m.fc || !m.fs) { mf__ms_free(&m); return MF_ERROR_OUT_OF_MEMORY; }
    mf__fft_twiddles(m.fc, m.fs, size);
    for (i = 0; i < n2; ++i) { m.tx[i] = (double)gradients_xy[2 * i]; m.ty[i] = (double)gradients_xy[2 * i + 1]; }
    mf__ms_integrate(&m);
    for (i = 0; i < n2; ++i) heights[i] = (mf_real)m.h[i];
    mf__ms_free(&m);
    return MF_SUCCESS;
}
