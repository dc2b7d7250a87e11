/* @optional MF_NO_MICROSURFACE */
/* @api */
/* ======================================================================== */
/* == 16b. A virtual gonioreflectometer                                     */
/* ======================================================================== */
/* The virtual gonioreflectometer (Ribardiere et al. 2019, Sec. 2): a
 * collimated beam from wi lights a periodic height field (heights in units of
 * the grid spacing, as mf_microsurface_generate makes them) traced as a
 * triangle mesh with mirror or Lambertian facets; every bounce is followed and the light leaving the
 * surface is recorded in a hemispherical sensor of equal-solid-angle cells
 * (rings of equal area whose sector counts keep the cells near square,
 * after Beckers and Beckers 2012), separately for the first bounce and for
 * the rest. A cell holds the fraction of the incident power it receives, an
 * estimate of the integral over the cell of f(wi, wo) cos(theta_o) dwo.
 * Rays start uniformly over one period, wrap around it and march the cells
 * with a 2D DDA; intersections are exact (the height above the surface is
 * linear on each triangle piece of the path). Rays still bouncing after
 * max_bounces, or still crossing the surface after 64 size + 65536 squares in
 * one flight, are counted as lost, with their power: at incidence within
 * about 0.001 rad of the horizon most rays are (a flight from the top of the
 * surface then spans more squares than that). */
#define MF_FACET_MIRROR 0
#define MF_FACET_LAMBERT 1
/* A measurement's configuration; all-zero means the defaults. */
typedef struct mf_gonio_config {
    mf_vec3 wi;              /* toward the light, wi.z > 0; zero: (0, 0, 1) */
    int facet;               /* MF_FACET_MIRROR (0) or MF_FACET_LAMBERT */
    mf_real absorption;      /* power lost at each bounce, [0, 1]; 0: none */
    int rays;                /* 0: 1000000 */
    int max_bounces;         /* 0: 100 */
    mf_u64 seed;
    mf_progress_fn progress; /* called about 100 times with (rays done, rays, ctx); may be NULL */
    void *ctx;
} mf_gonio_config;

typedef struct mf_gonio {
    int rings, cells;        /* rings of the sensor (the first is the polar cap), cells in all */
    int *ring_first;         /* rings + 1 entries: index of the first cell of each ring */
    mf_real *ring_z;         /* rings + 1 entries: cos(theta) of the ring boundaries, 1 down to 0 */
    mf_real *first;          /* per cell: power fraction leaving after exactly one bounce */
    mf_real *multi;          /* per cell: after two bounces or more */
    int rays;                /* rays traced by the last measurement */
    int lost;                /* rays still on the surface after max_bounces or the step budget */
    int leaks;               /* rays found below the surface and put back (rounding; should be 0) */
    mf_real energy_first, energy_multi, energy_lost;   /* totals, fractions of the incident power */
    mf_real mean_bounces;    /* mean number of bounces per ray */
} mf_gonio;

/* Allocates a sensor of `rings` rings (1..1024) with zero readings. */
MFDEF mf_result mf_gonio_init(mf_gonio *g, int rings);
MFDEF void mf_gonio_release(mf_gonio *g);
/* Cell of a direction (w.z > 0), -1 below the horizon or for NaN. */
MFDEF int mf_gonio_cell(const mf_gonio *g, mf_vec3 w);
/* Center of a cell: middle of its cos(theta) range and of its azimuth range. */
MFDEF mf_vec3 mf_gonio_cell_center(const mf_gonio *g, int cell);
/* Every cell has the solid angle 2 pi / cells. */
MFDEF mf_real mf_gonio_cell_solid_angle(const mf_gonio *g);
/* The cell is cos(theta) in [z_lo, z_hi], phi in [phi_lo, phi_hi) (radians, 0 to 2 pi). */
MFDEF void mf_gonio_cell_bounds(const mf_gonio *g, int cell, mf_real *z_lo, mf_real *z_hi,
                                mf_real *phi_lo, mf_real *phi_hi);
/* Traces c->rays rays over the height field (size x size, power of two,
 * 4..MF_MICROSURFACE_MAX_SIZE) and replaces the readings of g. Errors: NULL,
 * uninitialized g, bad size or configuration (MF_ERROR_INVALID_ARGUMENT),
 * non-finite heights (MF_ERROR_INVALID_DATA), allocation. */
MFDEF mf_result mf_gonio_measure(mf_gonio *g, const mf_real *heights, int size, const mf_gonio_config *c);
/* The single-scattering model for comparison: out[cell] = integral over the
 * cell of mf_brdf(d, wo, wi) wo.z dwo, by an n x n midpoint rule in
 * (cos theta, phi) per cell (n in 1..64). */
MFDEF mf_result mf_gonio_model(const mf_gonio *g, const mf_ndf *d, mf_vec3 wi, int n, mf_real *out);
/* @impl */
/* ---- The virtual gonioreflectometer ---- */

MFDEF void mf_gonio_release(mf_gonio *g)
{
    if (!g) return;
    MF_FREE(g->ring_first); MF_FREE(g->ring_z); MF_FREE(g->first); MF_FREE(g->multi);
    g->ring_first = 0; g->ring_z = 0; g->first = g->multi = 0;
    g->rings = g->cells = 0;
}

static void mf__gonio_clear(mf_gonio *g)
{
    int i;
    for (i = 0; i < g->cells; ++i) g->first[i] = g->multi[i] = MF_R(0.0);
    g->rays = g->lost = g->leaks = 0;
    g->energy_first = g->energy_multi = g->energy_lost = g->mean_bounces = MF_R(0.0);
}

/* Equal-area sensor (after Beckers and Beckers 2012): a polar cap and rings
 * of width delta in theta, ring k cut into round(2 pi sin(theta_k) / delta)
 * sectors so the cells are near square; the ring boundaries are then placed
 * so that every cell has exactly the solid angle 2 pi / cells:
 * cos(theta) at the end of ring k is 1 - (cells in rings 0..k) / cells. The
 * cap's angular radius delta / sqrt(pi) gives it the area of a square cell. */
MFDEF mf_result mf_gonio_init(mf_gonio *g, int rings)
{
    int k, total = 0;
    double c = 0.5641895835477563, delta;   /* 1/sqrt(pi) */
    if (!g) return MF_ERROR_INVALID_ARGUMENT;
    g->ring_first = 0; g->ring_z = 0; g->first = g->multi = 0; g->rings = g->cells = 0;
    if (rings < 1 || rings > 1024) return MF_ERROR_INVALID_ARGUMENT;
    g->ring_first = (int *)MF_MALLOC(sizeof(int) * (size_t)(rings + 1));
    g->ring_z = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)(rings + 1));
    if (!g->ring_first || !g->ring_z) { mf_gonio_release(g); return MF_ERROR_OUT_OF_MEMORY; }
    delta = 1.5707963267948966 / ((double)(rings - 1) + c);
    g->ring_first[0] = 0;
    for (k = 0; k < rings; ++k) {
        int cnt = 1;
        if (k > 0) {
            double mid = c * delta + ((double)k - 0.5) * delta;
            cnt = (int)((double)MF_SIN((mf_real)mid) * 6.283185307179586 / delta + 0.5);
            if (cnt < 1) cnt = 1;
        }
        total += cnt;
        g->ring_first[k + 1] = total;
    }
    g->rings = rings;
    g->cells = total;
    for (k = 0; k <= rings; ++k) g->ring_z[k] = (mf_real)(1.0 - (double)g->ring_first[k] / (double)total);
    g->ring_z[rings] = MF_R(0.0);
    g->first = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)total);
    g->multi = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)total);
    if (!g->first || !g->multi) { mf_gonio_release(g); return MF_ERROR_OUT_OF_MEMORY; }
    mf__gonio_clear(g);
    return MF_SUCCESS;
}

/* ring holding cos(theta) = z: ring_z[k] >= z > ring_z[k + 1] */
static int mf__gonio_ring(const mf_gonio *g, mf_real z)
{
    int lo = 0, hi = g->rings - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (z > g->ring_z[mid + 1]) hi = mid; else lo = mid + 1;
    }
    return lo;
}

MFDEF int mf_gonio_cell(const mf_gonio *g, mf_vec3 w)
{
    int k, n, j;
    mf_real phi;
    if (!g || !g->ring_z || !(w.z > MF_R(0.0)) || !(MF_FABS(w.x) < MF_BIG) || !(MF_FABS(w.y) < MF_BIG)) return -1;
    k = mf__gonio_ring(g, mf_min(w.z, MF_R(1.0)));
    n = g->ring_first[k + 1] - g->ring_first[k];
    if (n == 1) return g->ring_first[k];
    phi = MF_ATAN2(w.y, w.x);
    if (phi < MF_R(0.0)) phi += MF_R(2.0) * MF_PI;
    j = (int)(phi * (mf_real)n / (MF_R(2.0) * MF_PI));
    if (j >= n) j = n - 1;
    if (j < 0) j = 0;
    return g->ring_first[k] + j;
}

static int mf__gonio_ring_of_cell(const mf_gonio *g, int cell)
{
    int lo = 0, hi = g->rings - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (g->ring_first[mid] <= cell) lo = mid; else hi = mid - 1;
    }
    return lo;
}

MFDEF void mf_gonio_cell_bounds(const mf_gonio *g, int cell, mf_real *z_lo, mf_real *z_hi,
                                mf_real *phi_lo, mf_real *phi_hi)
{
    int k, n;
    mf_real a = MF_R(0.0), b = MF_R(0.0), p0 = MF_R(0.0), p1 = MF_R(0.0);
    if (g && g->ring_z && cell >= 0 && cell < g->cells) {
        k = mf__gonio_ring_of_cell(g, cell);
        n = g->ring_first[k + 1] - g->ring_first[k];
        a = g->ring_z[k + 1]; b = g->ring_z[k];
        p0 = MF_R(2.0) * MF_PI * (mf_real)(cell - g->ring_first[k]) / (mf_real)n;
        p1 = MF_R(2.0) * MF_PI * (mf_real)(cell - g->ring_first[k] + 1) / (mf_real)n;
    }
    if (z_lo) *z_lo = a;
    if (z_hi) *z_hi = b;
    if (phi_lo) *phi_lo = p0;
    if (phi_hi) *phi_hi = p1;
}

MFDEF mf_vec3 mf_gonio_cell_center(const mf_gonio *g, int cell)
{
    mf_real z0, z1, p0, p1, z, s, p;
    if (!g || !g->ring_z || cell < 0 || cell >= g->cells) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (cell == 0) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));   /* the polar cap */
    mf_gonio_cell_bounds(g, cell, &z0, &z1, &p0, &p1);
    z = MF_R(0.5) * (z0 + z1);
    s = MF_SQRT(mf_max(MF_R(1.0) - z * z, MF_R(0.0)));
    p = MF_R(0.5) * (p0 + p1);
    return mf_vec3_make(s * MF_COS(p), s * MF_SIN(p), z);
}

MFDEF mf_real mf_gonio_cell_solid_angle(const mf_gonio *g)
{
    if (!g || g->cells < 1) return MF_R(0.0);
    return MF_R(2.0) * MF_PI / (mf_real)g->cells;
}

MFDEF mf_result mf_gonio_model(const mf_gonio *g, const mf_ndf *d, mf_vec3 wi, int n, mf_real *out)
{
    int c, i, j;
    mf__ndf_prep pr;
    if (!g || !g->ring_z || !d || !out || n < 1 || n > 64 || !(wi.z > MF_R(0.0))) return MF_ERROR_INVALID_ARGUMENT;
    d = mf__ndf_prepare(d, &pr);   /* trait PREP: a GTR's Lambda rule built once */
    wi = mf_normalize(wi);
    for (c = 0; c < g->cells; ++c) {
        mf_real z0, z1, p0, p1;
        double sum = 0.0;
        mf_gonio_cell_bounds(g, c, &z0, &z1, &p0, &p1);
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                mf_real z = z0 + (z1 - z0) * ((mf_real)i + MF_R(0.5)) / (mf_real)n;
                mf_real p = p0 + (p1 - p0) * ((mf_real)j + MF_R(0.5)) / (mf_real)n;
                mf_real s = MF_SQRT(mf_max(MF_R(1.0) - z * z, MF_R(0.0)));
                mf_vec3 wo = mf_vec3_make(s * MF_COS(p), s * MF_SIN(p), z);
                sum += (double)(mf_brdf(d, wo, wi) * z);
            }
        out[c] = (mf_real)(sum * (double)mf_gonio_cell_solid_angle(g) / (double)(n * n));
    }
    return MF_SUCCESS;
}

/* The height field as traced: double heights, the top of every grid square
 * (for skipping squares the ray passes over) and of the whole field. */
typedef struct mf__tracer {
    const double *h;
    const double *top;
    int n;
    double zmax;
    long max_steps;
} mf__tracer;

/* height above the triangle tri (0: below-left of the diagonal u + v = 1, 1:
 * above-right) of square corners h00 h10 h01 h11, at local (u, v) and height z */
static double mf__tri_gap(const double *c, int tri, double u, double v, double z)
{
    if (!tri) return z - (c[0] + (c[1] - c[0]) * u + (c[2] - c[0]) * v);
    return z - (c[3] + (c[3] - c[2]) * (u - 1.0) + (c[3] - c[1]) * (v - 1.0));
}

/* March from o along d (unit) over the periodic field: 1 with the hit
 * parameter, the facet (square << 1 | triangle) and its slope; 0 when the ray
 * rises above every vertex; -1 after max_steps squares. skip: the facet the
 * ray leaves (a plane cannot be hit twice in a row). The height above the
 * surface is linear along the ray on each triangle piece, so the first
 * crossing is exact; a piece that starts below the surface (rounding at an
 * edge) is a hit at its start, counted in *leak. */
static int mf__trace(const mf__tracer *T, const double o[3], const double d[3], long skip, double *thit,
                     long *facet, double *slope, int *leak)
{
    int n = T->n, mk = T->n - 1, ix = (int)o[0], iy = (int)o[1], stx = d[0] > 0.0 ? 1 : -1, sty = d[1] > 0.0 ? 1 : -1;
    double inf = 1e300, tdx = d[0] != 0.0 ? 1.0 / mf__absd(d[0]) : inf, tdy = d[1] != 0.0 ? 1.0 / mf__absd(d[1]) : inf;
    double tmx = d[0] > 0.0 ? ((double)ix + 1.0 - o[0]) * tdx : (d[0] < 0.0 ? (o[0] - (double)ix) * tdx : inf);
    double tmy = d[1] > 0.0 ? ((double)iy + 1.0 - o[1]) * tdy : (d[1] < 0.0 ? (o[1] - (double)iy) * tdy : inf);
    double tesc = d[2] > 0.0 ? (T->zmax - o[2]) / d[2] : inf, t0 = 0.0, dsum = d[0] + d[1];
    long step;
    for (step = 0; step < T->max_steps; ++step) {
        double t1 = tmx < tmy ? tmx : tmy, za, zb;
        size_t sq;
        if (t0 >= tesc) return 0;
        if (t1 > tesc) t1 = tesc;
        za = o[2] + t0 * d[2];
        zb = o[2] + t1 * d[2];
        sq = (size_t)(iy & mk) * (size_t)n + (size_t)(ix & mk);
        if (!((za < zb ? za : zb) > T->top[sq])) {
            double c[4], ta[2], tb[2], s0 = o[0] - (double)ix + o[1] - (double)iy;
            int np = 1, p;
            c[0] = T->h[sq];
            c[1] = T->h[(size_t)(iy & mk) * (size_t)n + (size_t)((ix + 1) & mk)];
            c[2] = T->h[(size_t)((iy + 1) & mk) * (size_t)n + (size_t)(ix & mk)];
            c[3] = T->h[(size_t)((iy + 1) & mk) * (size_t)n + (size_t)((ix + 1) & mk)];
            ta[0] = t0; tb[0] = t1;
            if (dsum != 0.0) {   /* the diagonal u + v = 1 splits the path in two pieces */
                double td = (1.0 - s0) / dsum;
                if (td > t0 && td < t1) { tb[0] = td; ta[1] = td; tb[1] = t1; np = 2; }
            }
            for (p = 0; p < np; ++p) {
                double tm = 0.5 * (ta[p] + tb[p]), fa, fb, tol;
                int tri = s0 + tm * dsum > 1.0 ? 1 : 0;
                long id = ((long)sq << 1) | tri;
                if (id == skip) continue;
                fa = mf__tri_gap(c, tri, o[0] + ta[p] * d[0] - (double)ix, o[1] + ta[p] * d[1] - (double)iy, o[2] + ta[p] * d[2]);
                fb = mf__tri_gap(c, tri, o[0] + tb[p] * d[0] - (double)ix, o[1] + tb[p] * d[1] - (double)iy, o[2] + tb[p] * d[2]);
                tol = 1e-9 * (1.0 + mf__absd(za));
                if (fb > 0.0 && fa > -tol) continue;   /* stays above (or starts on it and rises) */
                if (fa > 0.0) *thit = ta[p] + (tb[p] - ta[p]) * fa / (fa - fb);
                else { *thit = ta[p]; if (fa < -tol) ++*leak; }
                *facet = id;
                if (!tri) { slope[0] = c[1] - c[0]; slope[1] = c[2] - c[0]; }
                else { slope[0] = c[3] - c[2]; slope[1] = c[3] - c[1]; }
                return 1;
            }
        }
        if (tmx < tmy) { ix += stx; t0 = tmx; tmx += tdx; }
        else { iy += sty; t0 = tmy; tmy += tdy; }
    }
    return -1;
}

/* wrap a coordinate into [0, n) */
static double mf__wrap(double x, int n)
{
    double f = (double)n;
    if (x >= 0.0 && x < f) return x;
    x -= f * (double)(long)(x / f);
    if (x < 0.0) x += f;
    if (x >= f) x -= f;
    return x;
}

MFDEF mf_result mf_gonio_measure(mf_gonio *g, const mf_real *heights, int size, const mf_gonio_config *config)
{
    mf_gonio_config cz;
    const mf_gonio_config *c = &cz;
    mf__tracer T;
    mf__pcg rng;
    double *h, *top, *acc, e1 = 0.0, em = 0.0, el = 0.0, bounces = 0.0, zmax = -1e300;
    size_t i, n2;
    int n = size, r, x, y, leak = 0, lost = 0, every;
    mf_vec3 wi;
    if (!g || !g->ring_z || !g->first || !heights || !mf__pow2(size) || size < 4 || size > MF_MICROSURFACE_MAX_SIZE)
        return MF_ERROR_INVALID_ARGUMENT;
    if (config) cz = *config; else memset(&cz, 0, sizeof cz);
    if (cz.wi.x == MF_R(0.0) && cz.wi.y == MF_R(0.0) && cz.wi.z == MF_R(0.0)) cz.wi.z = MF_R(1.0);
    if (cz.rays == 0) cz.rays = 1000000;
    if (cz.max_bounces == 0) cz.max_bounces = 100;
    wi = mf_normalize(c->wi);
    if (!(wi.z > MF_R(0.0)) || (c->facet != MF_FACET_MIRROR && c->facet != MF_FACET_LAMBERT) ||
        !(c->absorption >= MF_R(0.0) && c->absorption <= MF_R(1.0)) || c->rays < 1 || c->max_bounces < 1)
        return MF_ERROR_INVALID_ARGUMENT;
    n2 = (size_t)n * (size_t)n;
    for (i = 0; i < n2; ++i)
        if (!mf__finite_bits(heights[i]) || !(MF_FABS(heights[i]) < MF_BIG)) return MF_ERROR_INVALID_DATA;
    h = (double *)MF_MALLOC(sizeof(double) * n2);
    top = (double *)MF_MALLOC(sizeof(double) * n2);
    acc = (double *)MF_MALLOC(sizeof(double) * 2 * (size_t)g->cells);
    if (!h || !top || !acc) { MF_FREE(h); MF_FREE(top); MF_FREE(acc); return MF_ERROR_OUT_OF_MEMORY; }
    for (i = 0; i < n2; ++i) { h[i] = (double)heights[i]; if (h[i] > zmax) zmax = h[i]; }
    for (y = 0; y < n; ++y)
        for (x = 0; x < n; ++x) {
            double a = h[(size_t)y * (size_t)n + (size_t)x], b = h[(size_t)y * (size_t)n + (size_t)((x + 1) & (n - 1))];
            double cc = h[(size_t)((y + 1) & (n - 1)) * (size_t)n + (size_t)x];
            double dd = h[(size_t)((y + 1) & (n - 1)) * (size_t)n + (size_t)((x + 1) & (n - 1))];
            double mx = a > b ? a : b;
            if (cc > mx) mx = cc;
            if (dd > mx) mx = dd;
            top[(size_t)y * (size_t)n + (size_t)x] = mx;
        }
    for (i = 0; i < 2 * (size_t)g->cells; ++i) acc[i] = 0.0;
    T.h = h; T.top = top; T.n = n; T.zmax = zmax; T.max_steps = 64L * n + 65536L;
    mf__pcg_seed(&rng, c->seed, 0x676fu);
    every = c->rays / 100 > 0 ? c->rays / 100 : 1;
    for (r = 0; r < c->rays; ++r) {
        double o[3], d[3], w = 1.0;
        long skip = -1;
        int hits = 0, done = 0;
        mf_vec3 dir = mf_scale(wi, MF_R(-1.0));
        o[0] = mf__pcg_u01(&rng) * (double)n;
        o[1] = mf__pcg_u01(&rng) * (double)n;
        o[2] = zmax;
        while (!done) {
            double t = 0.0, sl[2] = { 0.0, 0.0 };
            long facet;
            int res;
            d[0] = (double)dir.x; d[1] = (double)dir.y; d[2] = (double)dir.z;
            res = mf__trace(&T, o, d, skip, &t, &facet, sl, &leak);
            if (res == 0) {   /* leaves the surface: record */
                int cell = mf_gonio_cell(g, dir);
                if (cell >= 0) acc[2 * cell + (hits > 1 ? 1 : 0)] += w;
                if (hits > 1) em += w; else e1 += w;
                bounces += (double)hits;
                done = 1;
            } else if (res < 0 || hits >= c->max_bounces) {
                ++lost; el += w; bounces += (double)hits; done = 1;
            } else {
                mf_vec3 m = mf_normalize(mf_vec3_make((mf_real)-sl[0], (mf_real)-sl[1], MF_R(1.0)));
                ++hits;
                o[0] = mf__wrap(o[0] + t * d[0], n);
                o[1] = mf__wrap(o[1] + t * d[1], n);
                o[2] = o[2] + t * d[2];
                skip = facet;
                w *= 1.0 - (double)c->absorption;
                if (c->facet == MF_FACET_MIRROR) dir = mf_normalize(mf_reflect(mf_scale(dir, MF_R(-1.0)), m));
                else {   /* cosine-distributed about the facet normal */
                    mf_vec3 tt, bb, l;
                    mf_real u1 = mf__u01_real(mf__pcg_u01(&rng)), u2 = mf__u01_real(mf__pcg_u01(&rng));
                    l = mf__sample_cosine(u1, u2);
                    { mf_basis fr_ = mf_basis_from_normal(m); tt = fr_.t; bb = fr_.b; }
                    dir = mf_normalize(mf_add(mf_add(mf_scale(tt, l.x), mf_scale(bb, l.y)), mf_scale(m, l.z)));
                }
                if (!(w > 0.0)) { bounces += (double)hits; done = 1; }   /* absorbed */
            }
        }
        if (c->progress && ((r + 1) % every == 0 || r + 1 == c->rays)) c->progress(r + 1, c->rays, c->ctx);
    }
    for (i = 0; i < (size_t)g->cells; ++i) {
        g->first[i] = (mf_real)(acc[2 * i] / (double)c->rays);
        g->multi[i] = (mf_real)(acc[2 * i + 1] / (double)c->rays);
    }
    g->rays = c->rays; g->lost = lost; g->leaks = leak;
    g->energy_first = (mf_real)(e1 / (double)c->rays);
    g->energy_multi = (mf_real)(em / (double)c->rays);
    g->energy_lost = (mf_real)(el / (double)c->rays);
    g->mean_bounces = (mf_real)(bounces / (double)c->rays);
    MF_FREE(h); MF_FREE(top); MF_FREE(acc);
    return MF_SUCCESS;
}
