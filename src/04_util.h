/* ======================================================================== */
/* == 4b. Utilities: random numbers, sorting, FFT, quadrature rules         */
/* ======================================================================== */
/* Tools that are not about light, each with its users: the rejection
 * samplers' uniform stream (GTR, Student-t); quadrature rules (Gauss-Legendre
 * with Legendre polynomials: the numerical samplers, tables and fits;
 * Gauss-Jacobi: the GTR Lambda mixture); and, for the microsurface generator
 * and the gonioreflectometer only (so under their opt-out MF_NO_MICROSURFACE),
 * 64-bit integers, PCG32, heapsort, selection and a radix-2 FFT. */
/* @api */
/* Uniforms for the extra draws of the rejection samplers (GTR, Student-t):
 * a counter seeded by the bits of the caller's (u1, u2) rounded to float
 * (u2's multiplied by an odd constant) and hashed by an integer mixer
 * (xor-shift-multiply rounds), so every sampler
 * stays a function of (u1, u2) and float and double builds draw the same
 * stream (double adds 32 lower bits from a second hash). */
MF_INLINE unsigned int mf__mix32(unsigned int x)
{
    x ^= x >> 16; x *= 0x7feb352du; x &= 0xffffffffu;
    x ^= x >> 15; x *= 0x846ca68bu; x &= 0xffffffffu;
    return x ^ (x >> 16);
}
MF_INLINE unsigned int mf__float_bits(mf_real x)
{
    union { float f; unsigned int u; } v;
    v.f = (float)x;
    return v.u;
}
MF_INLINE unsigned int mf__stream_seed(mf_real u1, mf_real u2)
{
    return mf__mix32(mf__float_bits(u1) ^ ((mf__float_bits(u2) * 0x9e3779b1u) & 0xffffffffu));
}
/* the next uniform in [0, 1) */
MF_INLINE mf_real mf__stream_next(unsigned int *s)
{
    mf_real u;
    *s = (*s + 0x9e3779b9u) & 0xffffffffu;
    u = (mf_real)(mf__mix32(*s) >> 8) * MF_R(5.9604644775390625e-8);
#ifdef MF_USE_DOUBLE
    u += (mf_real)mf__mix32(*s ^ 0x632be5abu) * MF_R(1.3877787807814457e-17);   /* 2^-56 */
#endif
    return u;
}
/* a proposal's next two uniforms, in this order (two mf__stream_next calls
 * as the arguments of one call would leave their order to the compiler) */
MF_INLINE void mf__stream_next2(unsigned int *s, mf_real *u1, mf_real *u2)
{
    *u1 = mf__stream_next(s);
    *u2 = mf__stream_next(s);
}

#ifndef MF_NO_MICROSURFACE
/* 64-bit seeds: unsigned long long (C99, C++11; C++98 compilers accept it
 * as an extension, quietly here) */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wlong-long"
#endif
typedef unsigned long long mf_u64;
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif
/* @cold */
/* 8-point Gauss-Legendre rule: nodes xi on [-1, 1], weights normalized to sum 1. */
#define MF__GL_N 8
MF_INLINE mf_real mf__gl_xi(int i)
{
    const mf_real x[MF__GL_N] = {
        MF_R(-0.96028985649753623), MF_R(-0.79666647741362674), MF_R(-0.52553240991632899),
        MF_R(-0.18343464249564980), MF_R(0.18343464249564980), MF_R(0.52553240991632899),
        MF_R(0.79666647741362674), MF_R(0.96028985649753623) };
    return x[i];
}
MF_INLINE mf_real mf__gl_w(int i)
{
    const mf_real w[MF__GL_N] = {
        MF_R(0.050614268145188130), MF_R(0.11119051722668724), MF_R(0.15685332293894364),
        MF_R(0.18134189168918100), MF_R(0.18134189168918100), MF_R(0.15685332293894364),
        MF_R(0.11119051722668724), MF_R(0.050614268145188130) };
    return w[i];
}

/* node i of the 8-point rule in panel p of `panels` equal panels of [0, 1] */
MF_INLINE mf_real mf__gl_node01(int p, int i, int panels)
{
    return ((mf_real)p + MF_R(0.5) + MF_R(0.5) * mf__gl_xi(i)) / (mf_real)panels;
}

/* 4-point Gauss-Legendre rule on [-1, 1], weights normalized to sum 1. */
MF_INLINE mf_real mf__gl4_xi(int i)
{
    const mf_real x[4] = { MF_R(-0.86113631159405258), MF_R(-0.33998104358485626), MF_R(0.33998104358485626),
                           MF_R(0.86113631159405258) };
    return x[i];
}
MF_INLINE mf_real mf__gl4_w(int i)
{
    const mf_real w[4] = { MF_R(0.17392742256872693), MF_R(0.32607257743127307), MF_R(0.32607257743127307),
                           MF_R(0.17392742256872693) };
    return w[i];
}

/* Legendre polynomials P_0..P_(MF__GL_N) at x. */
MF_INLINE void mf__legendre(mf_real x, mf_real *p)
{
    int n;
    p[0] = MF_R(1.0);
    p[1] = x;
    for (n = 1; n < MF__GL_N; ++n)
        p[n + 1] = ((mf_real)(2 * n + 1) * x * p[n] - (mf_real)n * p[n - 1]) / (mf_real)(n + 1);
}

/* the most nodes mf__gauss_jacobi takes (the GTR mixture's MF__GTR_NQ) */
#define MF__GJ_MAX 24
/* n-point Gauss-Jacobi rule (n <= MF__GJ_MAX) for the weight (1-x)^ea (1+x)^eb
 * on [-1, 1] by Golub and Welsch (1969): nodes are the eigenvalues of the
 * Jacobi matrix of the polynomials' recurrence, weights the squared first
 * components of its unit eigenvectors (unnormalized: the caller normalizes).
 * Implicit QL with Wilkinson shifts, at most 60 sweeps per eigenvalue. In
 * double in every build: float nodes would move b = exp(y) by 2e-6 at alpha
 * 1e-4. */
MF_INLINE void mf__gauss_jacobi(int n, double ea, double eb, double *x, double *w)
{
    double e[MF__GJ_MAX];
    int i, l, m, it;
    for (i = 0; i < n; ++i) {
        double s = 2.0 * i + ea + eb, k = i + 1.0, t = 2.0 * k + ea + eb;
        x[i] = i == 0 ? (eb - ea) / (ea + eb + 2.0) : (eb - ea) * (eb + ea) / (s * (s + 2.0));
        e[i] = i + 1 < n ? sqrt(4.0 * k * (k + ea) * (k + eb) * (k + ea + eb) /
                                   (t * t * (t + 1.0) * (t - 1.0))) : 0.0;
        w[i] = i == 0 ? 1.0 : 0.0;   /* first row of the eigenvector matrix */
    }
    for (l = 0; l < n; ++l) {
        for (it = 0; it < 60; ++it) {
            double g, r, s, c, pp, f, bb;
            for (m = l; m < n - 1; ++m)
                if (fabs(e[m]) <= 2.220446049250313e-16 * (fabs(x[m]) + fabs(x[m + 1]))) break;
            if (m == l) break;
            g = (x[l + 1] - x[l]) / (2.0 * e[l]);
            r = sqrt(g * g + 1.0);
            g = x[m] - x[l] + e[l] / (g + (g >= 0.0 ? r : -r));
            s = c = 1.0; pp = 0.0;
            for (i = m - 1; i >= l; --i) {
                f = s * e[i]; bb = c * e[i];
                r = sqrt(f * f + g * g); e[i + 1] = r;
                if (r == 0.0) { x[i + 1] -= pp; e[m] = 0.0; break; }
                s = f / r; c = g / r; g = x[i + 1] - pp;
                r = (x[i] - g) * s + 2.0 * c * bb;
                pp = s * r; x[i + 1] = g + pp; g = c * r - bb;
                f = w[i + 1]; w[i + 1] = s * w[i] + c * f; w[i] = c * w[i] - s * f;
            }
            if (r == 0.0 && i >= l) continue;
            x[l] -= pp; e[l] = g; e[m] = 0.0;
        }
    }
    for (i = 0; i < n; ++i) w[i] *= w[i];
}
/* @impl */
#ifndef MF_NO_MICROSURFACE
/* PCG32 (O'Neill 2014), the generator's and the tracer's own: deterministic
 * for a seed, no global state. The multiplier is built from 32-bit halves so
 * that C++98 sees no long long literal. */
typedef struct mf__pcg { mf_u64 s, inc; } mf__pcg;
static unsigned mf__pcg_next(mf__pcg *r)
{
    mf_u64 old = r->s;
    unsigned xs, rot;
    r->s = old * (((mf_u64)0x5851F42Du << 32) | (mf_u64)0x4C957F2Du) + r->inc;
    xs = (unsigned)(((old >> 18) ^ old) >> 27);
    rot = (unsigned)(old >> 59);
    return (xs >> rot) | (xs << ((32u - rot) & 31u));
}
static void mf__pcg_seed(mf__pcg *r, mf_u64 seed, unsigned stream)
{
    r->s = 0;
    r->inc = ((mf_u64)stream << 1) | 1u;
    mf__pcg_next(r);
    r->s += seed;
    mf__pcg_next(r);
}
/* uniform in [0, 1), 53 bits */
static double mf__pcg_u01(mf__pcg *r)
{
    double a = (double)(mf__pcg_next(r) >> 5), b = (double)(mf__pcg_next(r) >> 6);
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
}
/* uniform integer in [0, n) */
static unsigned mf__pcg_below(mf__pcg *r, unsigned n)
{
    return (unsigned)(((mf_u64)mf__pcg_next(r) * (mf_u64)n) >> 32);
}
/* a double in [0, 1) as an mf_real strictly below 1 (float rounds 1 - 2^-30 up) */
static mf_real mf__u01_real(double u)
{
    mf_real r = (mf_real)u;
    return r < MF_R(1.0) ? r : MF_R(1.0) - MF_EPS;
}

/* sqrt in double through MF_SQRT (float in float builds) and two Newton steps */
static double mf__sqrt_d(double x)
{
    double y;
    if (!(x > 0.0)) return 0.0;
    if (x < 1e-30) return 1e-30 * mf__sqrt_d(x * 1e60);   /* below float's range */
    if (x > 1e30) return 1e30 * mf__sqrt_d(x * 1e-60);
    y = (double)MF_SQRT((mf_real)x);
    if (!(y > 0.0)) y = x;
    y = 0.5 * (y + x / y);
    return 0.5 * (y + x / y);
}

/* In-place heapsort of doubles (no qsort: stdlib.h is optional here). */
static void mf__sort_d(double *a, size_t n)
{
    size_t start, end, root, child;
    double t;
    if (n < 2) return;
    for (start = n / 2; start-- > 0;) {
        for (root = start; (child = 2 * root + 1) < n; root = child) {
            if (child + 1 < n && a[child] < a[child + 1]) ++child;
            if (!(a[root] < a[child])) break;
            t = a[root]; a[root] = a[child]; a[child] = t;
        }
    }
    for (end = n - 1; end > 0; --end) {
        t = a[0]; a[0] = a[end]; a[end] = t;
        for (root = 0; (child = 2 * root + 1) < end; root = child) {
            if (child + 1 < end && a[child] < a[child + 1]) ++child;
            if (!(a[root] < a[child])) break;
            t = a[root]; a[root] = a[child]; a[child] = t;
        }
    }
}

/* The k-th smallest of a[0..n) (Hoare's selection; reorders a). */
static double mf__select_d(double *a, size_t n, size_t k)
{
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        double p = a[lo + (hi - lo) / 2], t;
        size_t i = lo, j = hi;
        while (i <= j) {
            while (a[i] < p) ++i;
            while (p < a[j]) --j;
            if (i <= j) {
                t = a[i]; a[i] = a[j]; a[j] = t;
                ++i;
                if (j == 0) break;
                --j;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else break;
    }
    return a[k];
}

/* ---- FFT: radix-2, complex, double precision (interleaved re, im), for
 * power-of-two sizes. Twiddles cos/sin(2 pi k / n), k < n/2, from the
 * half-angle recursion cos(a/2) = sqrt((1 + cos a)/2), sin(a/2) = sin a /
 * (2 cos(a/2)) and products over the bits of k: accurate to a few ulps of
 * double without a double-precision libm call. */
static void mf__fft_twiddles(double *c, double *s, int n)
{
    double bc[32], bs[32];
    int logn = 0, j, k;
    while ((1 << logn) < n) ++logn;
    bc[0] = 1.0; bs[0] = 0.0;       /* angle 2 pi / 2^j for j = 0, 1, 2 ... */
    bc[1] = -1.0; bs[1] = 0.0;
    bc[2] = 0.0; bs[2] = 1.0;
    for (j = 3; j <= logn && j < 32; ++j) {
        bc[j] = mf__sqrt_d(0.5 * (1.0 + bc[j - 1]));
        bs[j] = bs[j - 1] / (2.0 * bc[j]);
    }
    for (k = 0; k < n / 2; ++k) {
        double cr = 1.0, ci = 0.0;
        for (j = 0; j < logn; ++j)
            if (k & (1 << j)) {          /* rotate by 2 pi 2^j / n = 2 pi / 2^(logn - j) */
                double ar = bc[logn - j], ai = bs[logn - j], t = cr * ar - ci * ai;
                ci = cr * ai + ci * ar;
                cr = t;
            }
        c[k] = cr; s[k] = ci;
    }
}

/* forward: sum a_k e^{-2 pi i jk/n}; inverse: e^{+...}, unscaled */
static void mf__fft1(double *a, int n, const double *c, const double *s, int inverse)
{
    int i, j, len, k;
    for (i = 1, j = 0; i < n; ++i) {
        int bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) {
            double t = a[2 * i]; a[2 * i] = a[2 * j]; a[2 * j] = t;
            t = a[2 * i + 1]; a[2 * i + 1] = a[2 * j + 1]; a[2 * j + 1] = t;
        }
    }
    for (i = 0; i < n; i += 2) {   /* first stage: twiddle 1 */
        double *p = a + 2 * i, tr = p[2], ti = p[3];
        p[2] = p[0] - tr; p[3] = p[1] - ti;
        p[0] += tr; p[1] += ti;
    }
    for (len = 4; len <= n; len <<= 1) {   /* one twiddle per k, all blocks */
        int half = len >> 1, step = n / len;
        for (k = 0; k < half; ++k) {
            double wr = c[k * step], wi = inverse ? s[k * step] : -s[k * step];
            for (i = k; i < n; i += len) {
                double *p = a + 2 * i, *q = a + 2 * (i + half);
                double tr = q[0] * wr - q[1] * wi, ti = q[0] * wi + q[1] * wr;
                q[0] = p[0] - tr; q[1] = p[1] - ti;
                p[0] += tr; p[1] += ti;
            }
        }
    }
}

/* Transform of the columns of an n x n row-major array, 8 at a time
 * through tmp (16 n doubles) to stay in cache. */
static void mf__fft_columns(double *a, int n, const double *c, const double *s, int inverse, double *tmp)
{
    int x, y, b, nb;
    nb = n < 8 ? n : 8;
    for (x = 0; x < n; x += nb) {
        for (y = 0; y < n; ++y)
            for (b = 0; b < nb; ++b) {
                const double *p = a + 2 * ((size_t)y * (size_t)n + (size_t)(x + b));
                tmp[2 * ((size_t)b * (size_t)n + (size_t)y)] = p[0];
                tmp[2 * ((size_t)b * (size_t)n + (size_t)y) + 1] = p[1];
            }
        for (b = 0; b < nb; ++b) mf__fft1(tmp + 2 * (size_t)b * (size_t)n, n, c, s, inverse);
        for (y = 0; y < n; ++y)
            for (b = 0; b < nb; ++b) {
                double *p = a + 2 * ((size_t)y * (size_t)n + (size_t)(x + b));
                p[0] = tmp[2 * ((size_t)b * (size_t)n + (size_t)y)];
                p[1] = tmp[2 * ((size_t)b * (size_t)n + (size_t)y) + 1];
            }
    }
}

/* forward 2D transform: rows, then columns */
static void mf__fft2(double *a, int n, const double *c, const double *s, double *tmp)
{
    int y;
    for (y = 0; y < n; ++y) mf__fft1(a + 2 * (size_t)y * (size_t)n, n, c, s, 0);
    mf__fft_columns(a, n, c, s, 0, tmp);
}

/* inverse 2D transform of a Hermitian spectrum (a real result, unscaled, into
 * out): columns, then the rows two at a time (rows A, B with real inverses a,
 * b: the inverse of A + iB is a + ib), a quarter less work */
static void mf__ifft2_real(double *a, int n, const double *c, const double *s, double *tmp, double *out)
{
    int x, y;
    mf__fft_columns(a, n, c, s, 1, tmp);
    for (y = 0; y < n; y += 2) {
        const double *ra = a + 2 * (size_t)y * (size_t)n, *rb = a + 2 * (size_t)(y + 1) * (size_t)n;
        for (x = 0; x < n; ++x) {
            tmp[2 * x] = ra[2 * x] - rb[2 * x + 1];
            tmp[2 * x + 1] = ra[2 * x + 1] + rb[2 * x];
        }
        mf__fft1(tmp, n, c, s, 1);
        for (x = 0; x < n; ++x) {
            out[(size_t)y * (size_t)n + (size_t)x] = tmp[2 * x];
            out[(size_t)(y + 1) * (size_t)n + (size_t)x] = tmp[2 * x + 1];
        }
    }
}
#endif /* MF_NO_MICROSURFACE */
