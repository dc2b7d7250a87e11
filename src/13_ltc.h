/* @api */
/* ======================================================================== */
/* == 13. Linearly Transformed Cosines                                      */
/* ======================================================================== */
/* Heitz, Dupuy, Hill, Neubelt 2016; Tao et al. 2021 Eq. 1: a clamped cosine
 * D_o(w) = max(0, w.z)/pi transformed by a 3x3 matrix M,
 *   D(w) = D_o(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3,
 * integrates to 1 over the sphere, and its integral over a polygon is the
 * cosine form factor of the polygon transformed by M^-1 (Heitz 2017), clipped
 * exactly at the horizon. Polygons are given by their vertices relative to the
 * shading point (any length); the front face is the one whose vertices run
 * counterclockwise seen from the shading point. The fitter, the tables and the
 * built-in GGX table are non-inline (implementation section). */

typedef struct mf_ltc {
    mf_real M[9];       /* row-major */
    mf_real Minv[9];
    mf_real det_inv;    /* |det M^-1| */
} mf_ltc;

MF_FORCE_INLINE mf_vec3 mf__mat3_apply(const mf_real *a, mf_vec3 v)
{
    return mf_vec3_make(a[0] * v.x + a[1] * v.y + a[2] * v.z, a[3] * v.x + a[4] * v.y + a[5] * v.z,
                        a[6] * v.x + a[7] * v.y + a[8] * v.z);
}

/* A 3x3 matrix is singular for the LTC code when |det| is at most
 * MF_LTC_MIN_DET_REL times the product of its row lengths (Hadamard's bound:
 * the ratio is 1 for orthogonal rows, scale-free, and a rounding-level
 * remainder for parallel rows: float gives 4e-7 for two equal rows of
 * 4.9609375, which an absolute test accepted). */
#ifdef MF_USE_DOUBLE
#define MF_LTC_MIN_DET_REL 1e-12
#else
#define MF_LTC_MIN_DET_REL 1e-5f
#endif

/* Inverse of a row-major 3x3 matrix; returns its determinant (0: singular,
 * not finite, or an inverse that is not finite). */
MF_INLINE mf_real mf__mat3_inverse(const mf_real *a, mf_real *inv)
{
    mf_real c0 = a[4] * a[8] - a[5] * a[7], c1 = a[5] * a[6] - a[3] * a[8], c2 = a[3] * a[7] - a[4] * a[6];
    mf_real det = a[0] * c0 + a[1] * c1 + a[2] * c2, r, rel, s = MF_R(0.0);
    int i;
    if (!(det != MF_R(0.0)) || !(MF_FABS(det) < MF_BIG)) return MF_R(0.0);
    rel = MF_FABS(det) / MF_SQRT(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) / MF_SQRT(a[3] * a[3] + a[4] * a[4] + a[5] * a[5]) /
          MF_SQRT(a[6] * a[6] + a[7] * a[7] + a[8] * a[8]);
    if (!(rel > MF_LTC_MIN_DET_REL)) return MF_R(0.0);
    r = MF_R(1.0) / det;
    inv[0] = c0 * r; inv[1] = (a[2] * a[7] - a[1] * a[8]) * r; inv[2] = (a[1] * a[5] - a[2] * a[4]) * r;
    inv[3] = c1 * r; inv[4] = (a[0] * a[8] - a[2] * a[6]) * r; inv[5] = (a[2] * a[3] - a[0] * a[5]) * r;
    inv[6] = c2 * r; inv[7] = (a[1] * a[6] - a[0] * a[7]) * r; inv[8] = (a[0] * a[4] - a[1] * a[3]) * r;
    for (i = 0; i < 9; ++i) s += MF_FABS(inv[i]);
    if (!(s < MF_BIG)) return MF_R(0.0);
    return det;
}

/* The LTC of the row-major matrix m[9]. A singular or non-finite M gives the
 * clamped cosine itself (M = I). */
MF_INLINE mf_ltc mf_ltc_from_matrix9(const mf_real m[9])
{
    mf_ltc l;
    mf_real det;
    int i;
    for (i = 0; i < 9; ++i) l.M[i] = m[i];
    det = mf__mat3_inverse(l.M, l.Minv);
    if (!(MF_FABS(det) * MF_BIG > MF_R(1.0))) {   /* singular, or 1/det overflows */
        for (i = 0; i < 9; ++i) l.M[i] = l.Minv[i] = (i % 4 == 0) ? MF_R(1.0) : MF_R(0.0);
        det = MF_R(1.0);
    }
    l.det_inv = MF_R(1.0) / MF_FABS(det);
    return l;
}

/* The same from M[row][col] (the API form; in C, passing a non-const array
 * to a const 2D-array parameter draws a -Wpedantic warning before C23:
 * mf_ltc_from_matrix9 avoids it). */
MF_INLINE mf_ltc mf_ltc_from_matrix(const mf_real M[3][3])
{
    mf_real m[9];
    int i;
    for (i = 0; i < 9; ++i) m[i] = M[i / 3][i % 3];
    return mf_ltc_from_matrix9(m);
}

/* The LTC of the usual 4/5-coefficient tables, which store the inverse
 * M^-1 = [a 0 b; 0 c 0; d 0 e] (e = 1 in 4-coefficient tables). Its inverse
 * in closed form, k = ae - bd: M = [e/k 0 -b/k; 0 1/c 0; -d/k 0 a/k],
 * |det M^-1| = |c k|; singular (the Hadamard test above), non-finite or
 * overflowing input gives M = I. */
MF_INLINE mf_ltc mf_ltc_from_inverse(mf_real a, mf_real b, mf_real c, mf_real d, mf_real e)
{
    mf_ltc l;
    mf_real k = a * e - b * d, rk, rc, h = MF_LTC_MIN_DET_REL * MF_LTC_MIN_DET_REL;
    if (!(k * k > h * (a * a + b * b) * (d * d + e * e)) || !(c * c > MF_R(0.0)) ||
        !(MF_FABS(k) < MF_BIG) || !(MF_FABS(c * k) < MF_BIG) || !(MF_FABS(c * k) * MF_BIG > MF_R(1.0)) ||
        !(MF_FABS(a) + MF_FABS(b) + MF_FABS(d) + MF_FABS(e) < MF_BIG)) {
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        return mf_ltc_from_matrix9(I9);
    }
    rk = MF_R(1.0) / k; rc = MF_R(1.0) / c;
    l.Minv[0] = a; l.Minv[1] = MF_R(0.0); l.Minv[2] = b;
    l.Minv[3] = MF_R(0.0); l.Minv[4] = c; l.Minv[5] = MF_R(0.0);
    l.Minv[6] = d; l.Minv[7] = MF_R(0.0); l.Minv[8] = e;
    l.M[0] = e * rk; l.M[1] = MF_R(0.0); l.M[2] = -b * rk;
    l.M[3] = MF_R(0.0); l.M[4] = rc; l.M[5] = MF_R(0.0);
    l.M[6] = -d * rk; l.M[7] = MF_R(0.0); l.M[8] = a * rk;
    l.det_inv = MF_FABS(c * k);
    return l;
}

/* D(w), per steradian: |det M^-1| (M^-1 w).z / (pi |M^-1 w|^4) where positive. */
MF_FORCE_INLINE mf_real mf_ltc_eval(const mf_ltc *l, mf_vec3 w)
{
    mf_vec3 v = mf__mat3_apply(l->Minv, w);
    mf_real l2 = mf_dot(v, v);
    if (!(v.z > MF_R(0.0)) || !(l2 > MF_R(0.0))) return MF_R(0.0);
    return mf__cap(l->det_inv * v.z / (MF_PI * l2 * l2));
}

/* A direction with density mf_ltc_eval: a cosine-distributed direction moved by M. */
MF_INLINE mf_vec3 mf_ltc_sample(const mf_ltc *l, mf_real u1, mf_real u2)
{
    return mf_normalize(mf__mat3_apply(l->M, mf__sample_cosine(u1, u2)));
}

/* the per-edge and per-vertex helpers must inline into the polygon loops;
 * the rare ones stay out of line when optimizing. Unoptimized, they are plain
 * static inline: gcc emits every static non-inline function at -O0, used or
 * not, while an unused static inline one costs nothing (and nothing is
 * inlined at -O0 anyway). */
#define MF__LTC_HOT MF_FORCE_INLINE
#if defined(__CUDACC__)
#define MF__LTC_RARE static __noinline__ MF_HD
#define MF__LTC_NOINLINE static __noinline__ MF_HD
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE__)
#define MF__LTC_RARE static __attribute__((noinline, cold, unused))
#define MF__LTC_NOINLINE static __attribute__((noinline, unused))
#else
#define MF__LTC_RARE MF_INLINE
#define MF__LTC_NOINLINE MF_INLINE
#endif

/* theta / sin theta for d = cos theta in [0, 1]: a (2, 2) rational fit,
 * relative error 5.6e-7 (minimax in the relative error, fitted in long
 * double). Each edge then errs by at most about 5.6e-7 theta, so a polygon's
 * float error is bounded by about 1e-6 K relative, K = (sum of its edge
 * lengths theta) / |2 pi form factor| (tests/test_ltc.c). The (3, 3) fit
 * p = 1.5707963252192132 + 1.6387276960562109 d + 0.35586584306581215 d^2
 * + 0.0045738615736021417 d^3, q = 1 + 1.6798660847363001 d
 * + 0.79599037681132534 d^2 + 0.094107260786142122 d^3 (Remez, 1.0e-9)
 * would bring that to about 2.5e-7 K at two more multiply-adds per edge
 * (docs/ACCURACY.md: the trade). */
MF__LTC_HOT mf_real mf__ts_p(mf_real d)
{
    return MF_R(1.5707954524054327) + d * (MF_R(0.90581169693094948) + d * MF_R(0.026032047669933955));
}
MF__LTC_HOT mf_real mf__ts_q(mf_real d)
{
    return MF_R(1.0) + d * (MF_R(1.2132377142117774) + d * MF_R(0.28940008969878159));
}
MF__LTC_HOT mf_real mf__theta_sin(mf_real d) { return mf__ts_p(d) / mf__ts_q(d); }

/* Integral of the cosine lobe's vector irradiance over the great arc from a to
 * b (unit vectors): (theta / sin theta) (a x b). a x b is formed as
 * a x (b - a) for theta <= pi/2 and a x (a + b) beyond, where the
 * differences are exact, so short and nearly antipodal arcs keep their
 * relative accuracy; theta / sin theta is the rational fit for theta <= pi/2
 * and pi / sin theta - (pi - theta) / sin(pi - theta) beyond, with sin theta
 * = |a x b| (no 1 - d^2). The exact atan2 form is used with MF_USE_DOUBLE or
 * MF_LTC_EXACT_EDGE. A zero or exactly antipodal arc gives 0. */
#if defined(MF_USE_DOUBLE) && !defined(MF_LTC_EXACT_EDGE)
#define MF_LTC_EXACT_EDGE
#endif
MF__LTC_HOT mf_vec3 mf__vsub(mf_vec3 a, mf_vec3 b) { return mf_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
MF_INLINE mf_vec3 mf__edge_vector_fast(mf_vec3 a, mf_vec3 b)
{
    mf_real d = mf_dot(a, b), s2, f;
    mf_vec3 c;
    if (d >= MF_R(0.0)) return mf_scale(mf_cross(a, mf__vsub(b, a)), mf__theta_sin(d));
    c = mf_cross(a, mf_add(a, b));
    s2 = mf_dot(c, c);
    if (!(s2 > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    f = MF_SQRT(s2);
    return mf_scale(c, MF_PI / f - mf__theta_sin(-d));
}
MF_INLINE mf_vec3 mf__edge_vector_exact(mf_vec3 a, mf_vec3 b)
{
    mf_real d = mf_dot(a, b), s;
    mf_vec3 c = d >= MF_R(0.0) ? mf_cross(a, mf__vsub(b, a)) : mf_cross(a, mf_add(a, b));
    s = MF_SQRT(mf_dot(c, c));
    if (!(s > MF_R(1e-30))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    return mf_scale(c, MF_ATAN2(s, d) / s);
}
/* the z component beyond pi/2: c = a x (a + b), pi / |c| - f(-d) over one
 * division */
MF__LTC_HOT mf_real mf__edge_z_obtuse(mf_real ax, mf_real ay, mf_real az, mf_real bx, mf_real by, mf_real bz, mf_real d)
{
    mf_real cx = ay * (az + bz) - az * (ay + by), cy = az * (ax + bx) - ax * (az + bz);
    mf_real cz = ax * (ay + by) - ay * (ax + bx), s2 = cx * cx + cy * cy + cz * cz, sn, p, q;
    if (!(s2 > MF_R(1e-30))) return MF_R(0.0);
    sn = MF_SQRT(s2);
    p = mf__ts_p(-d); q = mf__ts_q(-d);
    return cz * (MF_PI * q - p * sn) / (sn * q);
}
/* its z component only (scalar arguments, then vectors) */
MF__LTC_HOT mf_real mf__edge_zs(mf_real ax, mf_real ay, mf_real az, mf_real bx, mf_real by, mf_real bz)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_vector_exact(mf_vec3_make(ax, ay, az), mf_vec3_make(bx, by, bz)).z;
#else
    mf_real d = ax * bx + ay * by + az * bz;
    if (d >= MF_R(0.0)) return (ax * (by - ay) - ay * (bx - ax)) * mf__theta_sin(d);
    return mf__edge_z_obtuse(ax, ay, az, bx, by, bz, d);
#endif
}
MF__LTC_HOT mf_real mf__edge_z(mf_vec3 a, mf_vec3 b) { return mf__edge_zs(a.x, a.y, a.z, b.x, b.y, b.z); }
/* an edge along the horizon (unit a, b with z = 0), often obtuse in clipped
 * lights: a x b = (0, 0, c) with sin theta = |c|, so beyond pi/2 the edge is
 * sign(c) pi - c f(-d), no square root */
MF__LTC_HOT mf_real mf__edge_z_horizon(mf_real ax, mf_real ay, mf_real bx, mf_real by)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_zs(ax, ay, MF_R(0.0), bx, by, MF_R(0.0));
#else
    mf_real d = ax * bx + ay * by, c;
    if (d >= MF_R(0.0)) return (ax * (by - ay) - ay * (bx - ax)) * mf__theta_sin(d);
    c = ax * (ay + by) - ay * (ax + bx);
    if (c == MF_R(0.0)) return MF_R(0.0);   /* antipodal */
    return (c > MF_R(0.0) ? MF_PI : -MF_PI) - c * mf__theta_sin(-d);
#endif
}
/* Sums of edges as one fraction n / q: an acute edge adds c p(d) / q(d),
 * the rational fit's own numerator and denominator, so that a quad pays one
 * division for its edges (q in [1, 2.5] per acute edge: no overflow for the
 * five edges of a clipped quad); an obtuse edge adds its value. */
MF__LTC_HOT void mf__edge_add(mf_real ax, mf_real ay, mf_real az, mf_real bx, mf_real by, mf_real bz, mf_real *n, mf_real *q)
{
#ifdef MF_LTC_EXACT_EDGE
    *n += mf__edge_zs(ax, ay, az, bx, by, bz) * *q;
#else
    mf_real d = ax * bx + ay * by + az * bz, c, qd;
    if (d >= MF_R(0.0)) {
        c = ax * (by - ay) - ay * (bx - ax);
        qd = mf__ts_q(d);
        *n = *n * qd + c * mf__ts_p(d) * *q;
        *q *= qd;
    } else *n += mf__edge_z_obtuse(ax, ay, az, bx, by, bz, d) * *q;
#endif
}
/* the same for an edge along the horizon (mf__edge_z_horizon) */
MF__LTC_HOT void mf__edge_add_horizon(mf_real ax, mf_real ay, mf_real bx, mf_real by, mf_real *n, mf_real *q)
{
#ifdef MF_LTC_EXACT_EDGE
    *n += mf__edge_z_horizon(ax, ay, bx, by) * *q;
#else
    mf_real d = ax * bx + ay * by, c, qd;
    if (d >= MF_R(0.0)) {
        c = ax * (by - ay) - ay * (bx - ax);
        qd = mf__ts_q(d);
        *n = *n * qd + c * mf__ts_p(d) * *q;
    } else {
        c = ax * (ay + by) - ay * (ax + bx);
        if (c == MF_R(0.0)) return;   /* antipodal */
        qd = mf__ts_q(-d);
        *n = *n * qd + ((c > MF_R(0.0) ? MF_PI : -MF_PI) * qd - c * mf__ts_p(-d)) * *q;
    }
    *q *= qd;
#endif
}
MF_INLINE mf_vec3 mf__edge_vector(mf_vec3 a, mf_vec3 b)
{
#ifdef MF_LTC_EXACT_EDGE
    return mf__edge_vector_exact(a, b);
#else
    return mf__edge_vector_fast(a, b);
#endif
}

#define MF__LTC_T(A, v) ((A) ? mf__mat3_apply((A), (v)) : (v))
MF__LTC_HOT mf_vec3 mf__unit_or_zero(mf_vec3 v)
{
    mf_real l2 = v.x * v.x + v.y * v.y + v.z * v.z, r = l2 > MF_R(0.0) ? MF_R(1.0) / MF_SQRT(l2) : MF_R(0.0);
    return mf_vec3_make(v.x * r, v.y * r, v.z * r);
}

/* Signed cosine form factor (z component of the vector form factor, times
 * 2 pi) of the polygon p[0..n-1] transformed by A (NULL: identity), clipped
 * to z >= 0 on the fly: every edge is cut where it crosses the horizon and the
 * exit and entry points are joined along the horizon, so no vertex buffer is
 * needed and any n works. Each vertex is transformed and normalized once. */
MF_INLINE mf_real mf__polygon_clipped(const mf_real *A, const mf_vec3 *p, int n)
{
    int i, j, s = -1;
    mf_real sum = MF_R(0.0);
    mf_vec3 exit_pt = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0)), a, an, b, bn, first, first_n;
    for (i = 0; i < n; ++i) {
        a = A ? mf__mat3_apply(A, p[i]) : p[i];
        if (a.z > MF_R(0.0)) { s = i; break; }
    }
    if (s < 0) return MF_R(0.0);   /* entirely below the horizon */
    first = a;
    first_n = an = mf__unit_or_zero(a);
    for (i = 1, j = s; i <= n; ++i) {
        if (++j == n) j = 0;
        if (i == n) { b = first; bn = first_n; }
        else {
            b = A ? mf__mat3_apply(A, p[j]) : p[j];
            bn = b.z > MF_R(0.0) ? mf__unit_or_zero(b) : b;
        }
        if (a.z > MF_R(0.0)) {
            if (b.z > MF_R(0.0)) sum += mf__edge_z(an, bn);
            else {   /* leaves: a.z b - b.z a is on the segment and on the horizon */
                mf_vec3 x = mf__vsub(mf_scale(b, a.z), mf_scale(a, b.z));
                x.z = MF_R(0.0);
                x = mf__unit_or_zero(x);
                sum += mf__edge_z(an, x);
                exit_pt = x;
            }
        } else if (b.z > MF_R(0.0)) {   /* enters: along the horizon, then up */
            mf_vec3 x = mf__vsub(mf_scale(a, b.z), mf_scale(b, a.z));
            x.z = MF_R(0.0);
            x = mf__unit_or_zero(x);
            sum += mf__edge_z(exit_pt, x) + mf__edge_z(x, bn);
        }
        a = b; an = bn;
    }
    return sum;
}

/* x, y, z transformed by the row-major A in place; the sparse form
 * [a 0 b; 0 c 0; d 0 e] of the LTC tables (and of mf_ltc_from_inverse) in 5
 * products instead of 9 */
#define MF__LTC_XF(A, x, y, z) do { \
        mf_real tx_ = (A)[0] * (x) + (A)[1] * (y) + (A)[2] * (z), tz_ = (A)[6] * (x) + (A)[7] * (y) + (A)[8] * (z); \
        (y) = (A)[3] * (x) + (A)[4] * (y) + (A)[5] * (z); (x) = tx_; (z) = tz_; \
    } while (0)
#define MF__LTC_SPARSE(A) ((A)[1] == MF_R(0.0) && (A)[3] == MF_R(0.0) && (A)[5] == MF_R(0.0) && (A)[7] == MF_R(0.0))
#define MF__LTC_XF_SPARSE(A, x, y, z) do { \
        mf_real tx_ = (A)[0] * (x) + (A)[2] * (z); \
        (z) = (A)[6] * (x) + (A)[8] * (z); (y) *= (A)[4]; (x) = tx_; \
    } while (0)
/* A quad, the common light, in scalar temporaries (no vertex structs in
 * memory: gcc pairs x with y across them, and the shuffles cost more than
 * the pairing saves). Above the horizon: normalized and summed straight. A
 * planar quad crosses the horizon at most twice, so its vertices above it
 * form one run s..s+k-1 (start and length per pattern of signs: the nibbles
 * of two constants, patterns 0-7 and 8-15); the run, the exit point and the entry point make the
 * clipped polygon. The two patterns with two runs go to the general loop. */
MF__LTC_RARE mf_real mf__quad_two_runs(mf_real x0, mf_real y0, mf_real z0, mf_real x1, mf_real y1, mf_real z1,
                                       mf_real x2, mf_real y2, mf_real z2, mf_real x3, mf_real y3, mf_real z3)
{
    mf_vec3 v[4];
    v[0] = mf_vec3_make(x0, y0, z0); v[1] = mf_vec3_make(x1, y1, z1);
    v[2] = mf_vec3_make(x2, y2, z2); v[3] = mf_vec3_make(x3, y3, z3);
    return mf__polygon_clipped((const mf_real *)0, v, 4);
}
/* the unit vector of (x, y, z) in place (0 stays 0) */
#define MF__LTC_UNIT(x, y, z) do { \
        mf_real l2_ = (x) * (x) + (y) * (y) + (z) * (z), r_ = l2_ > MF_R(0.0) ? MF_R(1.0) / MF_SQRT(l2_) : MF_R(0.0); \
        (x) *= r_; (y) *= r_; (z) *= r_; \
    } while (0)
/* the unit horizon point of the segment from u (above) to d (below, or on
 * it): u.z d - d.z u (both weights >= 0), z = 0 */
#define MF__LTC_HORIZON(hx, hy, ux, uy, uz, dx, dy, dz) do { \
        mf_real hz_ = MF_R(0.0); \
        hx = (uz) * (dx) - (dz) * (ux); hy = (uz) * (dy) - (dz) * (uy); \
        MF__LTC_UNIT(hx, hy, hz_); \
    } while (0)
MF__LTC_NOINLINE mf_real mf__quad_clipped(mf_real x0, mf_real y0, mf_real z0, mf_real x1, mf_real y1, mf_real z1,
                                          mf_real x2, mf_real y2, mf_real z2, mf_real x3, mf_real y3, mf_real z3, int cfg)
{
    int code = (int)((cfg < 8 ? 0x85024100u >> (4 * cfg) : 0x09A6B073u >> (4 * cfg - 32)) & 15u), s = code & 3, k = (code >> 2) + 1;
    mf_real t, sum, ax, ay, az, ex, ey, nx, ny;
    if (cfg == 0) return MF_R(0.0);
    if (cfg == 5 || cfg == 10) return mf__quad_two_runs(x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3);
    for (; s > 0; --s) {   /* rotate: the run starts at vertex 0 */
        t = x0; x0 = x1; x1 = x2; x2 = x3; x3 = t;
        t = y0; y0 = y1; y1 = y2; y2 = y3; y3 = t;
        t = z0; z0 = z1; z1 = z2; z2 = z3; z3 = t;
    }
    /* the horizon points from the vertices as they are (u.z d - d.z u scales
     * with u): off the dependency chain of the normalizations */
    if (k == 1) MF__LTC_HORIZON(ex, ey, x0, y0, z0, x1, y1, z1);
    else if (k == 2) MF__LTC_HORIZON(ex, ey, x1, y1, z1, x2, y2, z2);
    else MF__LTC_HORIZON(ex, ey, x2, y2, z2, x3, y3, z3);
    MF__LTC_HORIZON(nx, ny, x0, y0, z0, x3, y3, z3);
    MF__LTC_UNIT(x0, y0, z0);
    ax = x0; ay = y0; az = z0;
    sum = MF_R(0.0); t = MF_R(1.0);
    if (k >= 2) {
        MF__LTC_UNIT(x1, y1, z1);
        mf__edge_add(x0, y0, z0, x1, y1, z1, &sum, &t);
        ax = x1; ay = y1; az = z1;
        if (k == 3) {
            MF__LTC_UNIT(x2, y2, z2);
            mf__edge_add(x1, y1, z1, x2, y2, z2, &sum, &t);
            ax = x2; ay = y2; az = z2;
        }
    }
    mf__edge_add(ax, ay, az, ex, ey, MF_R(0.0), &sum, &t);
    mf__edge_add_horizon(ex, ey, nx, ny, &sum, &t);
    mf__edge_add(nx, ny, MF_R(0.0), x0, y0, z0, &sum, &t);
    return sum / t;
}
MF_INLINE mf_real mf__quad_sum(const mf_real *A, const mf_vec3 *p)
{
    mf_real x0 = p[0].x, y0 = p[0].y, z0 = p[0].z, x1 = p[1].x, y1 = p[1].y, z1 = p[1].z;
    mf_real x2 = p[2].x, y2 = p[2].y, z2 = p[2].z, x3 = p[3].x, y3 = p[3].y, z3 = p[3].z, n0, q0, n1, q1;
    int cfg;
    if (!A) {
    } else if (MF__LTC_SPARSE(A)) {
        MF__LTC_XF_SPARSE(A, x0, y0, z0); MF__LTC_XF_SPARSE(A, x1, y1, z1);
        MF__LTC_XF_SPARSE(A, x2, y2, z2); MF__LTC_XF_SPARSE(A, x3, y3, z3);
    } else {
        MF__LTC_XF(A, x0, y0, z0); MF__LTC_XF(A, x1, y1, z1); MF__LTC_XF(A, x2, y2, z2); MF__LTC_XF(A, x3, y3, z3);
    }
    cfg = (z0 > MF_R(0.0)) | (z1 > MF_R(0.0)) << 1 | (z2 > MF_R(0.0)) << 2 | (z3 > MF_R(0.0)) << 3;
    if (cfg != 15) return mf__quad_clipped(x0, y0, z0, x1, y1, z1, x2, y2, z2, x3, y3, z3, cfg);
    MF__LTC_UNIT(x0, y0, z0); MF__LTC_UNIT(x1, y1, z1); MF__LTC_UNIT(x2, y2, z2); MF__LTC_UNIT(x3, y3, z3);
    n0 = n1 = MF_R(0.0); q0 = q1 = MF_R(1.0);
    mf__edge_add(x0, y0, z0, x1, y1, z1, &n0, &q0); mf__edge_add(x1, y1, z1, x2, y2, z2, &n0, &q0);
    mf__edge_add(x2, y2, z2, x3, y3, z3, &n1, &q1); mf__edge_add(x3, y3, z3, x0, y0, z0, &n1, &q1);
    return (n0 * q1 + n1 * q0) / (q0 * q1);
}

/* A triangle as the quad above: in scalar temporaries, its three edges
 * over one division above the horizon; crossing it, as the quad
 * (v0, v1, v2, v2), whose zero edge v2 v2 adds 0. */
MF_INLINE mf_real mf__tri_sum(const mf_real *A, const mf_vec3 *p)
{
    mf_real x0 = p[0].x, y0 = p[0].y, z0 = p[0].z, x1 = p[1].x, y1 = p[1].y, z1 = p[1].z;
    mf_real x2 = p[2].x, y2 = p[2].y, z2 = p[2].z, n0, q0, n1, q1;
    int cfg;
    if (!A) {
    } else if (MF__LTC_SPARSE(A)) {
        MF__LTC_XF_SPARSE(A, x0, y0, z0); MF__LTC_XF_SPARSE(A, x1, y1, z1); MF__LTC_XF_SPARSE(A, x2, y2, z2);
    } else {
        MF__LTC_XF(A, x0, y0, z0); MF__LTC_XF(A, x1, y1, z1); MF__LTC_XF(A, x2, y2, z2);
    }
    cfg = (z0 > MF_R(0.0)) | (z1 > MF_R(0.0)) << 1 | (z2 > MF_R(0.0)) << 2;
    if (cfg != 7) return mf__quad_clipped(x0, y0, z0, x1, y1, z1, x2, y2, z2, x2, y2, z2, cfg | (cfg & 4) << 1);
    MF__LTC_UNIT(x0, y0, z0); MF__LTC_UNIT(x1, y1, z1); MF__LTC_UNIT(x2, y2, z2);
    n0 = n1 = MF_R(0.0); q0 = q1 = MF_R(1.0);
    mf__edge_add(x0, y0, z0, x1, y1, z1, &n0, &q0); mf__edge_add(x1, y1, z1, x2, y2, z2, &n0, &q0);
    mf__edge_add(x2, y2, z2, x0, y0, z0, &n1, &q1);
    return (n0 * q1 + n1 * q0) / (q0 * q1);
}

/* The clipped rest of a polygon, streamed: vertices i..n-1 are transformed
 * and (those above the horizon) normalized once each, and every edge is
 * summed as it is met, so no vertex buffer is needed and any n works. An
 * edge leaving the horizon ends at its exit point, one entering it starts at
 * its entry point, and the horizon arc from the exit point to the next entry
 * point joins them (the first entry, met before any exit, waits for the last
 * exit). (ax, ay, az) is vertex i-1, unit when above; (fx, fy, fz) is vertex
 * 0, unit when above. The horizon point u.z d - d.z u of an edge from u
 * (above) to d (below) is a positive combination, so u may be unit. */
/* one vertex (x, y, z) of the clipping stream below, unit when above */
#define MF__LTC_CLIP_STEP() do { \
        if (az > MF_R(0.0)) { \
            if (z > MF_R(0.0)) sum += mf__edge_zs(ax, ay, az, x, y, z); \
            else {   /* leaves */ \
                MF__LTC_HORIZON(ex, ey, ax, ay, az, x, y, z); \
                sum += mf__edge_zs(ax, ay, az, ex, ey, MF_R(0.0)); \
                have_exit = 1; \
            } \
        } else if (z > MF_R(0.0)) {   /* enters */ \
            MF__LTC_HORIZON(hx, hy, x, y, z, ax, ay, az); \
            if (have_exit) sum += mf__edge_z_horizon(ex, ey, hx, hy); \
            else { gx = hx; gy = hy; first_entry = 1; } \
            sum += mf__edge_zs(hx, hy, MF_R(0.0), x, y, z); \
        } \
        ax = x; ay = y; az = z; \
    } while (0)
MF__LTC_NOINLINE mf_real mf__ngon_clipped(const mf_real *A, const mf_vec3 *p, int n, int i, mf_real sum,
                                          mf_real ax, mf_real ay, mf_real az, mf_real fx, mf_real fy, mf_real fz)
{
    mf_real x, y, z, ex = MF_R(0.0), ey = MF_R(0.0), hx, hy, gx = MF_R(0.0), gy = MF_R(0.0);
    int first_entry = 0, have_exit = 0;
    if (A && MF__LTC_SPARSE(A))   /* the loop per form of A */
        for (; i < n; ++i) {
            x = p[i].x; y = p[i].y; z = p[i].z;
            MF__LTC_XF_SPARSE(A, x, y, z);
            if (z > MF_R(0.0)) MF__LTC_UNIT(x, y, z);
            MF__LTC_CLIP_STEP();
        }
    else
        for (; i < n; ++i) {
            x = p[i].x; y = p[i].y; z = p[i].z;
            if (A) MF__LTC_XF(A, x, y, z);
            if (z > MF_R(0.0)) MF__LTC_UNIT(x, y, z);
            MF__LTC_CLIP_STEP();
        }
    x = fx; y = fy; z = fz;   /* back to vertex 0 */
    MF__LTC_CLIP_STEP();
    return first_entry ? sum + mf__edge_z_horizon(ex, ey, gx, gy) : sum;
}

/* Other polygons: above the horizon in blocks of 16 vertices (transform and
 * normalize into three scalar buffers, then the edges); the first vertex
 * below the horizon hands the rest to the streaming clip above. */
MF__LTC_NOINLINE mf_real mf__ngon_sum(const mf_real *A, const mf_vec3 *p, int n)
{
    mf_real ux[16], uy[16], uz[16], x, y, z, px = MF_R(0.0), py = MF_R(0.0), pz = MF_R(0.0);
    mf_real fx = MF_R(0.0), fy = MF_R(0.0), fz = MF_R(0.0), sum = MF_R(0.0);
    int base, k, m, sparse = A && MF__LTC_SPARSE(A);
    for (base = 0; base < n; base += 16) {
        m = n - base < 16 ? n - base : 16;
        for (k = 0; k < m; ++k) {
            x = p[base + k].x; y = p[base + k].y; z = p[base + k].z;
            if (!A) {
            } else if (sparse) MF__LTC_XF_SPARSE(A, x, y, z);
            else MF__LTC_XF(A, x, y, z);
            if (!(z > MF_R(0.0))) goto clip;
            MF__LTC_UNIT(x, y, z);
            ux[k] = x; uy[k] = y; uz[k] = z;
        }
        if (base == 0) { fx = ux[0]; fy = uy[0]; fz = uz[0]; }
        else sum += mf__edge_zs(px, py, pz, ux[0], uy[0], uz[0]);
        for (k = 0; k + 1 < m; ++k) sum += mf__edge_zs(ux[k], uy[k], uz[k], ux[k + 1], uy[k + 1], uz[k + 1]);
        px = ux[m - 1]; py = uy[m - 1]; pz = uz[m - 1];
    }
    return sum + mf__edge_zs(px, py, pz, fx, fy, fz);
clip:   /* vertex base + k is below: the edges so far, then the rest */
    if (base + k == 0) { px = fx = x; py = fy = y; pz = fz = z; k = 1; }
    else if (k > 0) {
        if (base == 0) { fx = ux[0]; fy = uy[0]; fz = uz[0]; }
        else sum += mf__edge_zs(px, py, pz, ux[0], uy[0], uz[0]);
        for (m = 0; m + 1 < k; ++m) sum += mf__edge_zs(ux[m], uy[m], uz[m], ux[m + 1], uy[m + 1], uz[m + 1]);
        px = ux[k - 1]; py = uy[k - 1]; pz = uz[k - 1];
    }
    return mf__ngon_clipped(A, p, n, base + k, sum, px, py, pz, fx, fy, fz);
}

/* The signed sum of the polygon transformed by A, clipped at the horizon. */
MF_INLINE mf_real mf__polygon_sum(const mf_real *A, const mf_vec3 *p, int n)
{
    if (!p || n < 3) return MF_R(0.0);
    if (n == 4) return mf__quad_sum(A, p);
    if (n == 3) return mf__tri_sum(A, p);
    return mf__ngon_sum(A, p, n);
}

/* the cosine form factor: the sum over 2 pi */
MF_INLINE mf_real mf__polygon_form_factor(const mf_real *A, const mf_vec3 *p, int n)
{
    return mf__polygon_sum(A, p, n) * MF_R(0.15915494309189533577);
}

MF_INLINE mf_real mf__sided(mf_real ff, int two_sided)
{
    /* counterclockwise seen from the shading point is the front */
    ff = -ff;
    if (!(ff == ff)) return MF_R(0.0);
    if (two_sided) return MF_FABS(ff);
    return mf_max(ff, MF_R(0.0));
}

/* Integral of D over the spherical polygon seen through verts[0..n-1]
 * (positions relative to the shading point, any length, n >= 3), clipped at
 * the horizon; two_sided counts both faces of the polygon. */
MF_INLINE mf_real mf_ltc_integrate(const mf_ltc *l, const mf_vec3 *verts, int n, int two_sided)
{
    return mf__sided(mf__polygon_form_factor(l->Minv, verts, n), two_sided);
}

/* Cosine form factor of a polygon: integral over it of max(0, w.z)/pi,
 * clipped at the horizon (the irradiance of a unit-radiance light, / pi). */
MF_INLINE mf_real mf_polygon_irradiance(const mf_vec3 *verts, int n, int two_sided)
{
    return mf__sided(mf__polygon_form_factor((const mf_real *)0, verts, n), two_sided);
}

/* Vector form factor F of a polygon (not clipped; Heitz 2017): F.z is its
 * unclipped cosine form factor, |F| and F / |F| feed mf_sphere_form_factor. */
MF_INLINE mf_vec3 mf_polygon_vector_form_factor(const mf_vec3 *verts, int n)
{
    mf_vec3 f = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    int i;
    if (!verts || n < 3) return f;
    for (i = 0; i < n; ++i) f = mf_add(f, mf__edge_vector(mf_normalize(verts[i]), mf_normalize(verts[(i + 1) % n])));
    return mf_scale(f, MF_R(-0.15915494309189533577));
}

/* The sphere form factor below (mf_sphere_form_factor) from co = cos omega
 * in [-1, 1], s2 = sin^2 sigma in (0, 1] and x = cot sigma */
MF_INLINE mf_real mf__sphere_form_factor_cs(mf_real co, mf_real s2, mf_real x)
{
    mf_real so = MF_SQRT(MF_R(1.0) - co * co), y, z;
    if (co >= MF_SQRT(s2)) return co * s2;      /* omega <= pi/2 - sigma: fully above */
    if (co <= -MF_SQRT(s2)) return MF_R(0.0);    /* omega >= pi/2 + sigma: fully below */
    y = so > MF_R(0.0) ? -x * co / so : MF_R(0.0);
    y = mf_clamp(y, MF_R(-1.0), MF_R(1.0));
    z = so * MF_SQRT(MF_R(1.0) - y * y);
    return mf_max(((co * MF_ACOS(y) - x * z) * s2 + MF_ATAN2(z, x)) * MF_INV_PI, MF_R(0.0));
}
/* Cosine form factor of a uniform sphere light of angular radius sigma whose
 * center lies at angle omega from the normal, clipped at the horizon
 * (Snyder 1996), from F = its vector form factor: |F| = sin^2 sigma,
 * F.z / |F| = cos omega. Applied to the vector form factor of a polygon or a
 * disk, it is the sphere approximation of their horizon-clipped form factor
 * (Hill & Heitz 2016). */
MF_INLINE mf_real mf_sphere_form_factor(mf_vec3 F)
{
    mf_real len = MF_SQRT(mf_dot(F, F)), s2;
    if (!(len > MF_R(0.0))) return MF_R(0.0);
    s2 = mf_min(len, MF_R(1.0));                 /* sin^2 sigma */
    return mf__sphere_form_factor_cs(mf_clamp(F.z / len, MF_R(-1.0), MF_R(1.0)), s2,
                                     MF_SQRT(mf_max(MF_R(1.0) / s2 - MF_R(1.0), MF_R(0.0))));  /* cot sigma */
}

/* Multi-scale roughness (Tao et al. 2021). The meso-scale normals of a
 * footprint, summarized by the length of their mean (an unnormalized mip-mapped
 * normal), are an LTC with M = diag(a, a, 1), i.e. a GGX lobe of roughness a;
 * Eq. 5 fits a from the mean length (result clamped to [0, 1]; a mean length
 * below about 0.65 gives 1). */
MF_INLINE mf_real mf_ltc_meso_alpha(mf_real mean_normal_length)
{
    mf_real b = mf_clamp(mean_normal_length, MF_R(0.0), MF_R(1.0)), b2 = b * b, b3 = b2 * b, b4 = b2 * b2;
    mf_real num = MF_R(1.629) * b4 + MF_R(17.05) * b3 - MF_R(18.96) * b2 - MF_R(23.37) * b + MF_R(23.65);
    mf_real den = b3 - MF_R(28.07) * b2 + MF_R(31.1) * b - MF_R(3.545);
    if (!(den > MF_R(0.0))) return MF_R(1.0);
    return mf_clamp(num / den, MF_R(0.0), MF_R(1.0));
}

/* Roughness of the convolution of micro- and meso-scale lobes (Tao Eq. 7),
 * clamped to [0, 1]. */
MF_INLINE mf_real mf_ltc_combined_alpha(mf_real alpha_micro, mf_real alpha_meso)
{
    mf_real a = mf_clamp(alpha_micro, MF_R(0.0), MF_R(1.0)), m = mf_clamp(alpha_meso, MF_R(0.0), MF_R(1.0));
    return mf_clamp(MF_R(0.07) * a * a + MF_R(0.94) * a + m - MF_R(0.83) * a * m, MF_R(0.0), MF_R(1.0));
}

/* ---- LTC fitting and tables (Heitz et al. 2016, Sec. 4; Hill & Heitz 2016) ----
 * mf_ltc_fit fits, for one view direction wo = (sin t, 0, cos t), the LTC that
 * best matches the normalized lobe f(wo, wi) wi.z / albedo: M = B L with B the
 * frame whose z is the lobe's average direction and L = [m11 0 m13; 0 m22 0;
 * 0 0 1], found by Nelder-Mead on the cubed error estimated with multiple
 * importance sampling from the LTC and the BRDF (32 x 32 stratified samples
 * each, deterministic; the albedo from 256 x 256). The BRDF is either the specular microfacet BRDF of d
 * (brdf = NULL) or a callback returning f(wo, wi) wi.z (d = NULL; its side of
 * the estimate samples the cosine). Also returned: the albedo, integral of
 * f cos, and the Fresnel term, integral of f cos (1 - wo.h)^5, so that with
 * Schlick's F the lobe integrates to f0 albedo + (1 - f0) fresnel... written
 * out: (albedo - fresnel) f0 + fresnel. */
typedef mf_real (*mf_brdf_cos_fn)(mf_vec3 wo, mf_vec3 wi, void *ctx);
typedef struct mf_ltc_fit_result {
    mf_ltc ltc;          /* the fitted distribution */
    mf_real inv[4];      /* M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (normalized, table form) */
    mf_real albedo;      /* integral of f cos */
    mf_real fresnel;     /* integral of f cos (1 - wo.h)^5 */
    mf_real error;       /* the fitted L3 error estimate */
    mf_real params[3];   /* m11, m22, m13: pass as guess to the next fit */
} mf_ltc_fit_result;
MFDEF mf_result mf_ltc_fit(mf_ltc_fit_result *out, const mf_ndf *d, mf_brdf_cos_fn brdf, void *ctx,
                           mf_real cos_theta_o, const mf_real *guess);

/* A table of fits over view angle and roughness for a family of
 * distributions: family(alpha, family_ctx) returns the family's mf_ndf at
 * roughness alpha (any kind, e.g. mf_gtr(alpha, 1.5)), n_theta points in t = sqrt(1 - cos theta_o) and n_alpha points in
 * sqrt(alpha) (alpha clamped below at MF_LTC_ALPHA_MIN). data holds, per
 * entry [alpha][theta], the six floats inv0 inv1 inv2 inv3 albedo fresnel
 * with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (middle entry 1: blending
 * this form between entries keeps the lobe; the form with a last entry of 1
 * has entries growing like 1 / alpha and bends it between rows). */
#define MF_LTC_ALPHA_MIN MF_R(1e-3)
typedef struct mf_ltc_table { int n_theta, n_alpha; float *data; } mf_ltc_table;
typedef void (*mf_progress_fn)(int done, int total, void *ctx);
typedef mf_ndf (*mf_ndf_family_fn)(mf_real alpha, void *ctx);
MFDEF mf_result mf_ltc_table_build(mf_ltc_table *t, mf_ndf_family_fn family, void *family_ctx, int n_theta, int n_alpha,
                                   mf_progress_fn progress, void *progress_ctx);
MFDEF void mf_ltc_table_release(mf_ltc_table *t);
/* Bilinear lookup of the four M^-1 entries (and of the albedo and Fresnel
 * columns when asked for); M follows in closed form. */
MFDEF mf_ltc mf_ltc_table_lookup(const mf_ltc_table *t, mf_real cos_theta_o, mf_real alpha,
                                 mf_real *albedo, mf_real *fresnel);

/* Export of a table (mf_ltc_table.data, mf_ltc_ggx_table, n_theta x n_alpha
 * entries of six floats) as the two RGBA half-float (IEEE binary16) textures
 * ltc_1 and ltc_2 of the published code (Heitz et al. 2016, ltc_code:
 * fit/fitLTC.cpp packTab, the webgl shaders), in their layout, so that the
 * published shaders read them unchanged. Each texture is n_alpha wide and
 * n_theta high, first row first (v = 0, as glTexImage2D takes it): texel
 * (column j = alpha index, row i = theta index) at [4 (i n_alpha + j)];
 * u runs over sqrt(alpha) (ltc_code's "roughness"), v over
 * sqrt(1 - cos theta_o). With M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3]:
 *   ltc_1 = (inv0, inv2, inv1, inv3) = (Minv00, Minv20, Minv02, Minv22);
 *   ltc_2 = (albedo, fresnel, 0, sphere).
 * GLSL lookup, linear filtering, clamp to edge (the published shaders with
 * LUT_SIZE = n_alpha along u and n_theta along v; texel centres on the
 * fitted nodes; the same values as mf_ltc_table_lookup):
 *   uv = vec2(sqrt(alpha), sqrt(1 - NdotV)) * (n - 1) / n + 0.5 / n;
 *   t1 = texture(ltc_1, uv); t2 = texture(ltc_2, uv);
 *   Minv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w));
 *   (column-major: the same matrix), in the frame (T1, T2, N) with T1 along
 *   V - N (N.V); spec *= f0 t2.x + (1 - f0) t2.y (Schlick).
 * sphere is ltc_code's table of the horizon-clipped sphere (Hill & Heitz
 * 2017, the "clipless" path, its own 2D parameterization of the same
 * texture): at column j and row i, z = 2 j / (n_alpha - 1) - 1 and
 * len = i / (n_theta - 1), the cosine form factor of a uniform sphere light
 * whose vector form factor F has |F| = len (= sin^2 of its angular radius)
 * and F.z / |F| = z (cosine of its centre's angle to the normal), clipped at
 * the horizon (mf_sphere_form_factor), divided by len (max(z, 0) at
 * len = 0). Shaders read it with F the (unclipped) vector form factor of
 * the transformed light: uv = vec2(z * 0.5 + 0.5, len) * (n - 1) / n +
 * 0.5 / n, form factor = len * texture(ltc_2, uv).w. Rounding is to nearest
 * even; magnitudes below 2^-24 flush to 0, above 65504 give the largest
 * finite half. Returns MF_ERROR_INVALID_ARGUMENT on null pointers or sizes
 * below 2 or above 4096, and MF_ERROR_INVALID_DATA (textures untouched) when
 * an entry is not finite. */
MFDEF mf_result mf_ltc_table_export_rgba16f(const float *data, int n_theta, int n_alpha, unsigned short *tex1,
                                            unsigned short *tex2);

/* Built-in table (tools/ltc_fit.c): the LTC of the GGX BRDF cos for
 * wo = (sin theta_o, 0, cos theta_o), isotropic alpha in [0, 1] (clamped below
 * at MF_LTC_ALPHA_MIN), normalized: f cos ~= mf_ltc_ggx_albedo mf_ltc_eval.
 * mf_ltc_ggx_fresnel is the integral of f cos (1 - wo.h)^5 (Schlick split).
 * mf_ltc_ggx_table exposes the raw 64 x 64 x 6 floats for GPU textures: rows
 * sqrt(alpha), columns sqrt(1 - cos theta_o), entries inv0 inv1 inv2 inv3
 * albedo fresnel with M^-1 = [inv0 0 inv1; 0 1 0; inv2 0 inv3] (the
 * published normalization, middle entry 1, but not the published texture
 * layout: mf_ltc_table_export_rgba16f writes that). Not available in CUDA
 * device code (upload the table instead). The entries are the
 * mf_ltc_table_build fit refined on integrated polygons (tools/ltc_fit.c: per entry, the mean
 * relative error of the lobe's integral over 56 lights around and away from
 * the mirror direction, the small and thin ones near it held to the plain
 * fit's error): over 512 square lights near and away from the lobe the mean
 * relative error is 0.196 where the plain fit (and the published table)
 * give 0.286; disks and tubes near the lobe stay at the plain fit's
 * accuracy (max 0.079 / 0.070 against 0.074 / 0.090); same integration
 * cost (the refit's time: docs/PERFORMANCE.md). */
#ifndef MF_NO_LTC_TABLE
MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha);
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha);
/* The same for the Beckmann BRDF (table 14_ltc_table_beckmann.h, same layout,
 * 64 x 64, the plain mf_ltc_table_build fit: about 4 min). */
MFDEF mf_ltc mf_ltc_beckmann(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_beckmann_albedo(mf_real cos_theta_o, mf_real alpha);
MFDEF mf_real mf_ltc_beckmann_fresnel(mf_real cos_theta_o, mf_real alpha);
MFDEF const float *mf_ltc_beckmann_table(int *n_theta, int *n_alpha);
/* The LTC of anisotropic GGX (ax along x = the tangent, ay along y) for the
 * view wo in the shading frame (not the LTC frame: the azimuth matters), and
 * its albedo (the integral of f cos): f cos ~= mf_ltc_ggx_aniso_albedo
 * mf_ltc_eval; integrate any light with mf_ltc_integrate & co. as for the
 * isotropic mf_ltc_ggx. Equals mf_ltc_ggx in mf_basis_ltc's frame when
 * ax = ay (the last slice of the table is that table, rotated). Alphas are
 * clamped to [MF_LTC_ALPHA_MIN, 1], views below the horizon to the horizon;
 * NaN gives the clamped cosine (M = I) and albedo 0. Lookup and its
 * parameterization: 13_ltc_aniso.h; table: 14_ltc_table_aniso.h
 * (resolution and fit there, accuracy in docs/ACCURACY.md). Not available
 * in CUDA device code. */
MFDEF mf_ltc mf_ltc_ggx_aniso(mf_vec3 wo, mf_real ax, mf_real ay);
MFDEF mf_real mf_ltc_ggx_aniso_albedo(mf_vec3 wo, mf_real ax, mf_real ay);
/* The raw table for GPU textures: dims[4] = n_theta, n_phi, n_alpha, n_v;
 * n_alpha * n_v * n_theta * n_phi entries of eight IEEE binary16 values
 * (p q r t u v w albedo, M^-1 as above with s = (1 + q^2) / p), entry
 * ((ia n_v + iv) n_theta + it) n_phi + ip at nodes sqrt(1 - cos theta_o) =
 * it / (n_theta - 1), azimuth = (pi/2) ip / (n_phi - 1), sqrt(alpha_x) =
 * ia / (n_alpha - 1) (alpha clamped below at MF_LTC_ALPHA_MIN) and
 * sqrt(alpha_y / alpha_x) = iv / n_v; the slice iv = n_v (isotropic) is
 * mf_ltc_ggx's table, rotated. mf_ltc_ggx_aniso_export_rgba16f lays it out
 * as two RGBA half-float textures (shader recipe there). */
MFDEF const unsigned short *mf_ltc_ggx_aniso_table(int dims[4]);
/* Two RGBA16F textures of width n_phi n_theta and height n_alpha n_v
 * (texel (x = it n_phi + ip, y = ia n_v + iv) at [4 (y width + x)]):
 * tex1 = (p, q, r, t), tex2 = (u, v, w, albedo). Shader lookup (the same
 * values as mf_ltc_ggx_aniso): mirror the view into x, y >= 0 and swap x
 * and y when alpha_x < alpha_y (swap the alphas too); t = sqrt(1 - cos
 * theta_o) (n_theta - 1), f = azimuth / (pi/2) (n_phi - 1), a = sqrt(alpha_x)
 * (n_alpha - 1), g = sqrt(alpha_y / alpha_x) n_v; fetch with texelFetch the
 * 16 corners (floor, floor + 1 in each, clamped; for g's upper node at n_v
 * use the isotropic texture's M^-1 = [a 0 b; 0 1 0; c 0 d] at (cos theta_o,
 * alpha_x) rotated to the azimuth, R M^-1 R^T); per corner, M^-1 = [p q r;
 * q s t; u v w] with s = (1 + q^2) / p, its inverse M scaled to a unit last
 * column; blend those M multilinearly (in the shading frame: T = tangent of
 * alpha_x, B, N); then undo the mirror (negate the entries (0,1), (1,0),
 * (0,2), (2,0) for x, (0,1), (1,0), (1,2), (2,1) for y) and the swap
 * (exchange rows 0 and 1 and columns 0 and 1), and integrate with inverse(M).
 * Returns MF_ERROR_INVALID_ARGUMENT on null pointers. */
MFDEF mf_result mf_ltc_ggx_aniso_export_rgba16f(unsigned short *tex1, unsigned short *tex2);
#endif
/* @impl */
/* ---- LTC fitting ---- */

typedef struct mf__fit_ctx {
    const mf_ndf *d;
    mf_brdf_cos_fn brdf;
    void *ctx;
    mf_vec3 wo, X, Z;          /* view; frame of the lobe (Y = (0,1,0)) */
    mf_real albedo;
    int n;                     /* samples per technique */
    mf_vec3 *bw;               /* BRDF-side samples: directions, f/albedo, pdf */
    mf_real *bf, *bp;
} mf__fit_ctx;

static mf_real mf__fit_f(const mf__fit_ctx *c, mf_vec3 wi)
{
    if (c->brdf) return wi.z > MF_R(0.0) ? c->brdf(c->wo, wi, c->ctx) : MF_R(0.0);
    return mf_brdf(c->d, c->wo, wi) * mf_max(wi.z, MF_R(0.0));
}

static mf_real mf__fit_pdf(const mf__fit_ctx *c, mf_vec3 wi)
{
    if (c->brdf) return mf_max(wi.z, MF_R(0.0)) * MF_INV_PI;
    return mf_brdf_pdf(c->d, c->wo, wi);
}

static mf_ltc mf__fit_ltc(const mf__fit_ctx *c, const mf_real *p)
{
    /* M = [X Y Z] [m11 0 m13; 0 m22 0; 0 0 1] */
    mf_real m11 = MF_FABS(p[0]) + MF_R(1e-7), m22 = MF_FABS(p[1]) + MF_R(1e-7), m13 = p[2], m[9];
    m[0] = c->X.x * m11; m[1] = MF_R(0.0); m[2] = c->X.x * m13 + c->Z.x;
    m[3] = MF_R(0.0);    m[4] = m22;       m[5] = MF_R(0.0);
    m[6] = c->X.z * m11; m[7] = MF_R(0.0); m[8] = c->X.z * m13 + c->Z.z;
    return mf_ltc_from_matrix9(m);
}

static mf_real mf__fit_error(const mf__fit_ctx *c, const mf_real *p)
{
    mf_ltc l = mf__fit_ltc(c, p);
    mf_real err = MF_R(0.0);
    int i, j, k = 0, n1 = 1;
    while (n1 * n1 < c->n) ++n1;
    /* LTC side: stratified samples of the current LTC */
    for (i = 0; i < n1; ++i)
        for (j = 0; j < n1; ++j) {
            mf_vec3 w = mf_ltc_sample(&l, ((mf_real)i + MF_R(0.5)) / (mf_real)n1, ((mf_real)j + MF_R(0.5)) / (mf_real)n1);
            mf_real dl = mf_ltc_eval(&l, w), f = mf__fit_f(c, w) / c->albedo, pb = mf__fit_pdf(c, w), e = MF_FABS(f - dl);
            if (dl + pb > MF_R(0.0)) err += e * e * e / (dl + pb);
            ++k;
        }
    /* BRDF side: fixed samples */
    for (i = 0; i < c->n; ++i) {
        mf_real dl = mf_ltc_eval(&l, c->bw[i]), e = MF_FABS(c->bf[i] - dl);
        if (dl + c->bp[i] > MF_R(0.0)) err += e * e * e / (dl + c->bp[i]);
    }
    return err / (mf_real)(k + c->n);
}

/* Nelder-Mead in 3 dimensions (standard coefficients). */
static mf_real mf__nelder_mead(const mf__fit_ctx *c, mf_real *x, mf_real step, int max_iter)
{
    mf_real s[4][3], f[4], xr[3], xe[3], xc[3], cen[3];
    int i, j, it;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 3; ++j) s[i][j] = x[j];
        if (i > 0) s[i][i - 1] += step * (MF_FABS(x[i - 1]) > MF_R(0.1) ? MF_FABS(x[i - 1]) : MF_R(0.1));
        f[i] = mf__fit_error(c, s[i]);
    }
    for (it = 0; it < max_iter; ++it) {
        int lo = 0, hi = 0, nh = 0;
        mf_real fr;
        for (i = 1; i < 4; ++i) { if (f[i] < f[lo]) lo = i; if (f[i] > f[hi]) hi = i; }
        nh = lo;
        for (i = 0; i < 4; ++i) if (i != hi && f[i] > f[nh]) nh = i;
        /* converged: relative spread 1e-7 (double) or 1.2e-5 (float) */
        if (MF_FABS(f[hi] - f[lo]) <= mf_max(MF_R(1e-7), MF_R(100.0) * MF_EPS) * (MF_FABS(f[lo]) + MF_R(1e-12))) break;
        for (j = 0; j < 3; ++j) {
            cen[j] = MF_R(0.0);
            for (i = 0; i < 4; ++i) if (i != hi) cen[j] += s[i][j] / MF_R(3.0);
            xr[j] = cen[j] + (cen[j] - s[hi][j]);
        }
        fr = mf__fit_error(c, xr);
        if (fr < f[lo]) {
            mf_real fe;
            for (j = 0; j < 3; ++j) xe[j] = cen[j] + MF_R(2.0) * (xr[j] - cen[j]);
            fe = mf__fit_error(c, xe);
            if (fe < fr) { for (j = 0; j < 3; ++j) s[hi][j] = xe[j]; f[hi] = fe; }
            else { for (j = 0; j < 3; ++j) s[hi][j] = xr[j]; f[hi] = fr; }
        } else if (fr < f[nh]) {
            for (j = 0; j < 3; ++j) s[hi][j] = xr[j];
            f[hi] = fr;
        } else {
            mf_real fc;
            for (j = 0; j < 3; ++j) xc[j] = cen[j] + MF_R(0.5) * (s[hi][j] - cen[j]);
            fc = mf__fit_error(c, xc);
            if (fc < f[hi]) { for (j = 0; j < 3; ++j) s[hi][j] = xc[j]; f[hi] = fc; }
            else {
                for (i = 0; i < 4; ++i) if (i != lo) {
                    for (j = 0; j < 3; ++j) s[i][j] = s[lo][j] + MF_R(0.5) * (s[i][j] - s[lo][j]);
                    f[i] = mf__fit_error(c, s[i]);
                }
            }
        }
    }
    MF__SOLVER_DONE(MF__SITE_LTC_FIT, it, max_iter);
    {
        int lo = 0;
        for (i = 1; i < 4; ++i) if (f[i] < f[lo]) lo = i;
        for (j = 0; j < 3; ++j) x[j] = s[lo][j];
        return f[lo];
    }
}

MFDEF mf_result mf_ltc_fit(mf_ltc_fit_result *out, const mf_ndf *d, mf_brdf_cos_fn brdf, void *ctx,
                           mf_real cos_theta_o, const mf_real *guess)
{
    mf__fit_ctx c;
    mf__ndf_prep pr;
    mf_real ct, st, sum = MF_R(0.0), fres = MF_R(0.0), p[3];
    mf_vec3 avg = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    int i, j, n1 = 32, k;
    if (!out || (!d && !brdf) || !(cos_theta_o > MF_R(0.0)) || !(cos_theta_o <= MF_R(1.0)))
        return MF_ERROR_INVALID_ARGUMENT;
    if (d) d = mf__ndf_prepare(d, &pr);   /* trait PREP: a GTR's Lambda rule built once */
    ct = cos_theta_o; st = MF_SQRT(mf_max(MF_R(1.0) - ct * ct, MF_R(0.0)));
    c.d = d; c.brdf = brdf; c.ctx = ctx; c.wo = mf_vec3_make(st, MF_R(0.0), ct);
    c.n = n1 * n1;
    c.bw = (mf_vec3 *)MF_MALLOC(sizeof(mf_vec3) * (size_t)c.n);
    c.bf = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)c.n);
    c.bp = (mf_real *)MF_MALLOC(sizeof(mf_real) * (size_t)c.n);
    if (!c.bw || !c.bf || !c.bp) { MF_FREE(c.bw); MF_FREE(c.bf); MF_FREE(c.bp); return MF_ERROR_OUT_OF_MEMORY; }
    /* Albedo, Fresnel term and average direction by importance sampling (the
     * BRDF's own sampler, or the cosine) on a 256 x 256 grid, fine enough for
     * the heavy GGX tail (1% of the lobe beyond 45 degrees at alpha 0.1) that a
     * 32 x 32 midpoint grid misses; the error estimate uses every 8th point. */
    for (i = 0, k = 0; i < 8 * n1; ++i)
        for (j = 0; j < 8 * n1; ++j) {
            mf_real u1 = ((mf_real)i + MF_R(0.5)) / (mf_real)(8 * n1), u2 = ((mf_real)j + MF_R(0.5)) / (mf_real)(8 * n1), f, pdf, w;
            mf_vec3 wi, h;
            wi = brdf ? mf__sample_cosine(u1, u2) : mf_brdf_sample(d, c.wo, u1, u2).wi;
            f = mf__fit_f(&c, wi);
            pdf = mf__fit_pdf(&c, wi);
            w = pdf > MF_R(0.0) ? f / pdf : MF_R(0.0);
            if (i % 8 == 4 && j % 8 == 4) { c.bw[k] = wi; c.bf[k] = f; c.bp[k] = pdf; ++k; }
            sum += w;
            h = mf_normalize(mf_add(c.wo, wi));
            {
                mf_real q = MF_R(1.0) - mf_clamp(mf_dot(c.wo, h), MF_R(0.0), MF_R(1.0)), q2 = q * q;
                fres += w * q2 * q2 * q;
            }
            avg = mf_add(avg, mf_scale(wi, w));
        }
    c.albedo = sum / (mf_real)(64 * c.n);
    out->albedo = c.albedo;
    out->fresnel = fres / (mf_real)(64 * c.n);
    if (!(c.albedo > MF_R(1e-12))) {   /* no lobe: the clamped cosine, zero albedo */
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        out->ltc = mf_ltc_from_matrix9(I9);
        out->inv[0] = out->inv[3] = MF_R(1.0); out->inv[1] = out->inv[2] = MF_R(0.0);
        out->error = MF_R(0.0);
        out->params[0] = out->params[1] = MF_R(1.0); out->params[2] = MF_R(0.0);
        MF_FREE(c.bw); MF_FREE(c.bf); MF_FREE(c.bp);
        return MF_SUCCESS;
    }
    for (k = 0; k < c.n; ++k) c.bf[k] /= c.albedo;
    avg.y = MF_R(0.0);
    c.Z = mf_normalize(avg);
    if (!(c.Z.z > MF_R(0.0))) c.Z = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
    c.X = mf_vec3_make(c.Z.z, MF_R(0.0), -c.Z.x);
    if (guess) { p[0] = guess[0]; p[1] = guess[1]; p[2] = guess[2]; }
    else { p[0] = p[1] = MF_R(0.5); p[2] = MF_R(0.0); }
    out->error = mf__nelder_mead(&c, p, MF_R(0.1), 400);
    out->error = mf__nelder_mead(&c, p, MF_R(0.02), 400);   /* restart: Nelder-Mead can stall */
    out->params[0] = MF_FABS(p[0]); out->params[1] = MF_FABS(p[1]); out->params[2] = p[2];
    out->ltc = mf__fit_ltc(&c, p);
    /* normalized inverse, table form (the LTC is invariant to scaling M) */
    {
        const mf_real *iv = out->ltc.Minv;
        out->inv[0] = iv[0] / iv[4]; out->inv[1] = iv[2] / iv[4];
        out->inv[2] = iv[6] / iv[4]; out->inv[3] = iv[8] / iv[4];
    }
    MF_FREE(c.bw); MF_FREE(c.bf); MF_FREE(c.bp);
    return MF_SUCCESS;
}

/* grid: t = sqrt(1 - cos theta) in [0, 1], v = sqrt(alpha) in [0, 1] */
static mf_real mf__ltc_grid_cos(int i, int n)
{
    mf_real t = (mf_real)i / (mf_real)(n - 1);
    return mf_max(MF_R(1.0) - t * t, MF_R(1e-3));
}
static mf_real mf__ltc_grid_alpha(int j, int n)
{
    mf_real v = (mf_real)j / (mf_real)(n - 1);
    return mf_max(v * v, MF_LTC_ALPHA_MIN);
}

MFDEF mf_result mf_ltc_table_build(mf_ltc_table *t, mf_ndf_family_fn family, void *family_ctx, int n_theta, int n_alpha,
                                   mf_progress_fn progress, void *progress_ctx)
{
    int i, j, done = 0;
    mf_real prev0[3], prev[3];
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    t->data = 0; t->n_theta = t->n_alpha = 0;
    if (!family || n_theta < 2 || n_alpha < 2 || n_theta > 4096 || n_alpha > 4096)
        return MF_ERROR_INVALID_ARGUMENT;
    t->data = (float *)MF_MALLOC(sizeof(float) * 6 * (size_t)n_theta * (size_t)n_alpha);
    if (!t->data) return MF_ERROR_OUT_OF_MEMORY;
    t->n_theta = n_theta; t->n_alpha = n_alpha;
    /* roughest first, each view angle warm-started from its neighbour */
    prev0[0] = prev0[1] = MF_R(1.0); prev0[2] = MF_R(0.0);
    for (j = n_alpha - 1; j >= 0; --j) {
        mf_ndf d = family(mf__ltc_grid_alpha(j, n_alpha), family_ctx);
        prev[0] = prev0[0]; prev[1] = prev0[1]; prev[2] = prev0[2];
        for (i = 0; i < n_theta; ++i) {
            mf_ltc_fit_result r;
            float *e = t->data + 6 * ((size_t)j * (size_t)n_theta + (size_t)i);
            mf_result res = mf_ltc_fit(&r, &d, 0, 0, mf__ltc_grid_cos(i, n_theta), prev);
            if (res != MF_SUCCESS) { mf_ltc_table_release(t); return res; }
            e[0] = (float)r.inv[0]; e[1] = (float)r.inv[1]; e[2] = (float)r.inv[2]; e[3] = (float)r.inv[3];
            e[4] = (float)r.albedo; e[5] = (float)r.fresnel;
            prev[0] = r.params[0]; prev[1] = r.params[1]; prev[2] = r.params[2];
            if (i == 0) { prev0[0] = r.params[0]; prev0[1] = r.params[1]; prev0[2] = r.params[2]; }
            if (progress) progress(++done, n_theta * n_alpha, progress_ctx);
        }
    }
    return MF_SUCCESS;
}

MFDEF void mf_ltc_table_release(mf_ltc_table *t)
{
    if (!t) return;
    MF_FREE(t->data);
    t->data = 0;
    t->n_theta = t->n_alpha = 0;
}

/* Bilinear lookup in (sqrt(1 - cos theta_o), sqrt(alpha)) of the four
 * stored M^-1 entries (middle entry 1); the albedo and Fresnel columns only
 * when asked for; M in closed form (mf_ltc_from_inverse). */
static mf_ltc mf__ltc_lookup(const float *data, int nt, int na, mf_real cos_theta_o, mf_real alpha,
                             mf_real *albedo, mf_real *fresnel)
{
    mf_real ct, a, x, y, fx, fy, w00, w10, w01, w11, v[4];
    const float *e00, *e10, *e01, *e11;
    int ix, iy, k;
    if (!(cos_theta_o == cos_theta_o) || !(alpha == alpha)) {
        /* NaN: no lookup (its conversion to int is undefined) */
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        if (albedo) *albedo = MF_R(0.0);
        if (fresnel) *fresnel = MF_R(0.0);
        return mf_ltc_from_matrix9(I9);
    }
    ct = mf_clamp(cos_theta_o, MF_R(0.0), MF_R(1.0)); a = mf_clamp(alpha, MF_R(0.0), MF_R(1.0));
    x = MF_SQRT(MF_R(1.0) - ct) * (mf_real)(nt - 1); y = MF_SQRT(a) * (mf_real)(na - 1);
    ix = (int)x; iy = (int)y;
    if (ix > nt - 2) ix = nt - 2;
    if (iy > na - 2) iy = na - 2;
    fx = mf_clamp(x - (mf_real)ix, MF_R(0.0), MF_R(1.0)); fy = mf_clamp(y - (mf_real)iy, MF_R(0.0), MF_R(1.0));
    e00 = data + 6 * (iy * nt + ix); e10 = e00 + 6; e01 = e00 + 6 * nt; e11 = e01 + 6;
    w00 = (MF_R(1.0) - fx) * (MF_R(1.0) - fy); w10 = fx * (MF_R(1.0) - fy);
    w01 = (MF_R(1.0) - fx) * fy; w11 = fx * fy;
    for (k = 0; k < 4; ++k)
        v[k] = w00 * (mf_real)e00[k] + w10 * (mf_real)e10[k] + w01 * (mf_real)e01[k] + w11 * (mf_real)e11[k];
    if (albedo) *albedo = w00 * (mf_real)e00[4] + w10 * (mf_real)e10[4] + w01 * (mf_real)e01[4] + w11 * (mf_real)e11[4];
    if (fresnel) *fresnel = w00 * (mf_real)e00[5] + w10 * (mf_real)e10[5] + w01 * (mf_real)e01[5] + w11 * (mf_real)e11[5];
    {   /* mf_ltc_from_inverse with c = 1 */
        mf_ltc l;
        mf_real q = v[0] * v[3] - v[1] * v[2], rq, h = MF_LTC_MIN_DET_REL * MF_LTC_MIN_DET_REL;
        if (!(q * q > h * (v[0] * v[0] + v[1] * v[1]) * (v[2] * v[2] + v[3] * v[3])) || !(MF_FABS(q) * MF_BIG > MF_R(1.0)) ||
            !(MF_FABS(v[0]) + MF_FABS(v[1]) + MF_FABS(v[2]) + MF_FABS(v[3]) < MF_BIG))
            return mf_ltc_from_inverse(MF_R(1.0), MF_R(0.0), MF_R(1.0), MF_R(0.0), MF_R(1.0));
        rq = MF_R(1.0) / q;
        l.Minv[0] = v[0]; l.Minv[1] = MF_R(0.0); l.Minv[2] = v[1];
        l.Minv[3] = MF_R(0.0); l.Minv[4] = MF_R(1.0); l.Minv[5] = MF_R(0.0);
        l.Minv[6] = v[2]; l.Minv[7] = MF_R(0.0); l.Minv[8] = v[3];
        l.M[0] = v[3] * rq; l.M[1] = MF_R(0.0); l.M[2] = -v[1] * rq;
        l.M[3] = MF_R(0.0); l.M[4] = MF_R(1.0); l.M[5] = MF_R(0.0);
        l.M[6] = -v[2] * rq; l.M[7] = MF_R(0.0); l.M[8] = v[0] * rq;
        l.det_inv = MF_FABS(q);
        return l;
    }
}

MFDEF mf_ltc mf_ltc_table_lookup(const mf_ltc_table *t, mf_real cos_theta_o, mf_real alpha,
                                 mf_real *albedo, mf_real *fresnel)
{
    if (!t || !t->data || t->n_theta < 2 || t->n_alpha < 2) {
        const mf_real I9[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        if (albedo) *albedo = MF_R(0.0);
        if (fresnel) *fresnel = MF_R(0.0);
        return mf_ltc_from_matrix9(I9);
    }
    return mf__ltc_lookup(t->data, t->n_theta, t->n_alpha, cos_theta_o, alpha, albedo, fresnel);
}

/* float to IEEE binary16, round to nearest even (finite input) */
static unsigned short mf__half_bits(float f)
{
    union { float f; unsigned int u; } v;
    unsigned int sign, e, m, h;
    v.f = f;
    sign = (v.u >> 16) & 0x8000u;
    e = (v.u >> 23) & 0xffu;
    m = v.u & 0x7fffffu;
    if (e >= 143u) return (unsigned short)(sign | 0x7bffu);   /* >= 65536: the largest finite */
    if (e >= 113u) {                                           /* normal half */
        h = ((e - 112u) << 10) | (m >> 13);
        m &= 0x1fffu;
        if (m > 0x1000u || (m == 0x1000u && (h & 1u))) ++h;   /* may carry into the exponent: still right */
        if (h > 0x7bffu) h = 0x7bffu;
        return (unsigned short)(sign | h);
    }
    if (e < 102u) return (unsigned short)sign;                 /* below half the smallest subnormal */
    {   /* subnormal half: value = m' 2^-24 */
        unsigned int full = m | 0x800000u, shift = 126u - e, rem, half;
        h = full >> shift;
        rem = full & ((1u << shift) - 1u);
        half = 1u << (shift - 1u);
        if (rem > half || (rem == half && (h & 1u))) ++h;
        return (unsigned short)(sign | h);
    }
}

/* ltc_2.w: the horizon-clipped sphere form factor of |F| = len, F.z / |F| = z,
 * divided by len (its limit max(z, 0) at len = 0). cot sigma from 1 - len:
 * through |F| (mf_sphere_form_factor), a float len one ulp below 1 gives
 * cot sigma = 2.4e-4 instead of 0, and the form factor, whose slope in cot
 * sigma is -2 sin omega / pi there, moves by 1.5e-4. */
static mf_real mf__ltc_sphere_ratio(mf_real z, mf_real len)
{
    if (!(len > MF_R(0.0))) return mf_max(z, MF_R(0.0));
    return mf__sphere_form_factor_cs(z, len, MF_SQRT((MF_R(1.0) - len) / len)) / len;
}

MFDEF mf_result mf_ltc_table_export_rgba16f(const float *data, int n_theta, int n_alpha, unsigned short *tex1,
                                            unsigned short *tex2)
{
    size_t i, n, e, o;
    int r, c;
    if (!data || !tex1 || !tex2 || n_theta < 2 || n_alpha < 2 || n_theta > 4096 || n_alpha > 4096)
        return MF_ERROR_INVALID_ARGUMENT;
    n = (size_t)n_theta * (size_t)n_alpha;
    for (i = 0; i < 6 * n; ++i)
        if (!mf__finite_bits((mf_real)data[i])) return MF_ERROR_INVALID_DATA;
    /* texel (column c = alpha index, row r = theta index); entry [c][r] of the table */
    for (r = 0; r < n_theta; ++r)
        for (c = 0; c < n_alpha; ++c) {
            e = 6 * ((size_t)c * (size_t)n_theta + (size_t)r);
            o = 4 * ((size_t)r * (size_t)n_alpha + (size_t)c);
            tex1[o] = mf__half_bits(data[e]);            /* Minv00 */
            tex1[o + 1] = mf__half_bits(data[e + 2]);    /* Minv20 */
            tex1[o + 2] = mf__half_bits(data[e + 1]);    /* Minv02 */
            tex1[o + 3] = mf__half_bits(data[e + 3]);    /* Minv22 */
            tex2[o] = mf__half_bits(data[e + 4]);
            tex2[o + 1] = mf__half_bits(data[e + 5]);
            tex2[o + 2] = 0;
            tex2[o + 3] = mf__half_bits((float)mf__ltc_sphere_ratio(
                (mf_real)(2 * c) / (mf_real)(n_alpha - 1) - MF_R(1.0), (mf_real)r / (mf_real)(n_theta - 1)));
        }
    return MF_SUCCESS;
}

#ifndef MF_NO_LTC_TABLE
static const float *mf__ltc_ggx_data(int *n);        /* the built-in tables: 14_ltc_table.h */
static const float *mf__ltc_beckmann_data(int *n);   /* 14_ltc_table_beckmann.h */
/* lookup in a built-in table (data(&n): n x n entries); albedo and Fresnel
 * through alb and fr when not null */
static mf_ltc mf__ltc_builtin(const float *(*data)(int *), mf_real c, mf_real alpha, mf_real *alb, mf_real *fr)
{
    int n;
    const float *t = data(&n);
    return mf__ltc_lookup(t, n, n, c, alpha, alb, fr);
}
static const float *mf__ltc_builtin_table(const float *(*data)(int *), int *n_theta, int *n_alpha)
{
    int n;
    const float *t = data(&n);
    if (n_theta) *n_theta = n;
    if (n_alpha) *n_alpha = n;
    return t;
}
MFDEF mf_ltc mf_ltc_ggx(mf_real cos_theta_o, mf_real alpha) { return mf__ltc_builtin(mf__ltc_ggx_data, cos_theta_o, alpha, 0, 0); }
MFDEF mf_real mf_ltc_ggx_albedo(mf_real cos_theta_o, mf_real alpha)
{
    mf_real a;
    mf__ltc_builtin(mf__ltc_ggx_data, cos_theta_o, alpha, &a, 0);
    return a;
}
MFDEF mf_real mf_ltc_ggx_fresnel(mf_real cos_theta_o, mf_real alpha)
{
    mf_real f;
    mf__ltc_builtin(mf__ltc_ggx_data, cos_theta_o, alpha, 0, &f);
    return f;
}
MFDEF const float *mf_ltc_ggx_table(int *n_theta, int *n_alpha) { return mf__ltc_builtin_table(mf__ltc_ggx_data, n_theta, n_alpha); }
MFDEF mf_ltc mf_ltc_beckmann(mf_real cos_theta_o, mf_real alpha) { return mf__ltc_builtin(mf__ltc_beckmann_data, cos_theta_o, alpha, 0, 0); }
MFDEF mf_real mf_ltc_beckmann_albedo(mf_real cos_theta_o, mf_real alpha)
{
    mf_real a;
    mf__ltc_builtin(mf__ltc_beckmann_data, cos_theta_o, alpha, &a, 0);
    return a;
}
MFDEF mf_real mf_ltc_beckmann_fresnel(mf_real cos_theta_o, mf_real alpha)
{
    mf_real f;
    mf__ltc_builtin(mf__ltc_beckmann_data, cos_theta_o, alpha, 0, &f);
    return f;
}
MFDEF const float *mf_ltc_beckmann_table(int *n_theta, int *n_alpha) { return mf__ltc_builtin_table(mf__ltc_beckmann_data, n_theta, n_alpha); }
#endif
