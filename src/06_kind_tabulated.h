/* ======================================================================== */
/* == 6. Distribution kinds: tabulated (piecewise-linear)                   */
/* ======================================================================== */
/* Ribardiere et al. 2019, Sec. 3: D piecewise linear in theta through control
 * points (Eq. 11), each curve normalized (Eq. 12); anisotropic from two curves
 * by Eq. 10. Lambda by the split integration of Eq. 13-14 (precomputed at
 * build time), NDF sampling by Eq. 15-18, visible normals by an exact
 * inversion. Builders: mf_tabulated_build, mf_tabulated_from_ndf. Cold. */
/* @decl */
/* A tabulated (piecewise-linear) distribution: the arrays of one built NDF, all
 * in one allocation (block, bytes) owned until mf_tabulated_release. Fields are
 * filled by the builders; read them, do not write them. For CUDA, copy block to
 * the device and use mf_tabulated_rebase (below) to point a copy of the
 * struct at it; pass that struct by value to the kernel and take its address. */
typedef struct mf_tabulated {
    int n;              /* control points, theta[0] = 0 < ... < theta[n-1] = pi/2 */
    int aniso;          /* 0: one curve (dy == dx, cy == cx) */
    int n_lam;          /* nodes of the projected-area table */
    mf_real inv_h;      /* 1 / spacing when the control points are uniform, else 0 */
    mf_real inv_hl;     /* the same for the projected-area nodes */
    mf_real wx, wy;     /* Eq. 10 weights D_y(0)/c and D_x(0)/c, c = (D_x(0) + D_y(0))/2; 1, 1 if c = 0 */
    mf_real scale;      /* median tan(theta) of D cos: a characteristic slope (used by no formula) */
    mf_real *theta;     /* n control angles */
    mf_real *dx, *dy;   /* the normalized curves at the control points (Eq. 11-12) */
    mf_real *cx, *cy;   /* cumulative D cos mass 2 pi int_0^theta D cos sin, 0 .. 1 */
    mf_real *lt;        /* n_lam view angles theta_o of the table, 0 .. pi/2 */
    mf_real *li;        /* per node: I0, dI0/dtheta_o, I2, dI2/dtheta_o (mf__tabulated_lambda) */
    void *block;        /* the allocation holding every array above */
    size_t bytes;
} mf_tabulated;
typedef struct mf_ndf_tabulated {
    const mf_tabulated *tab;   /* the tables of a built distribution; 0: every function returns 0 */
} mf_ndf_tabulated;
/* @api */
/* The distribution of a built mf_tabulated (builders below); a
 * NULL or released table gives a distribution whose every function returns 0.
 * ax = ay = the table's characteristic slope (informative only). */
MF_INLINE mf_ndf mf_tabulated_ndf(const mf_tabulated *t)
{
    mf_real s = t && t->block ? t->scale : MF_R(1.0);
    mf_ndf d = mf__ndf_init(MF_NDF_TABULATED, s, s);
    d.p.tabulated.tab = t && t->block && t->n >= 2 ? t : (const mf_tabulated *)0;
    return d;
}

/* ---- Tabulated (piecewise-linear) distributions: builders ----
 * (Ribardiere et al. 2019, Sec. 3.) mf_tabulated_build takes n control points
 * theta[0] = 0 < theta[1] < ... < theta[n-1] = pi/2 (the ends may be off by up
 * to 1e-4 rad; they are snapped) and the curve D_x at them (per steradian,
 * >= 0, finite, not all 0; any scale: each curve is normalized by Eq. 12).
 * D_y = NULL (or equal to D_x) gives an isotropic distribution; otherwise D_x
 * is the curve at phi = 0 and D_y at phi = pi/2, combined by Eq. 10 (whose
 * weights D_y(0)/c, D_x(0)/c become 1, 1 when both curves vanish at the pole).
 * Any number of lobes. 2 <= n <= MF_TABULATED_MAX_POINTS = 4096; consecutive
 * angles at least 16 ulps apart. Build cost grows as n^2: the projected-area
 * table integrates over the control segments for 1 to 8 view angles per
 * segment (timings: docs/PERFORMANCE.md). Errors:
 * NULL or bad n (MF_ERROR_INVALID_ARGUMENT), unordered, too close or
 * non-finite angles, negative, non-finite or all-zero values
 * (MF_ERROR_INVALID_DATA), allocation
 * (MF_ERROR_OUT_OF_MEMORY); nothing stays allocated on failure.
 * mf_tabulated_from_ndf tabulates any distribution at about n control points
 * placed to equidistribute the linear-interpolation error relative to D
 * (density sqrt(|D''| / D) over 8 n candidate angles that cover both uniform
 * theta and tan(theta) scaled by the median slope), so narrow lobes and long
 * tails are both resolved; D_x and D_y are the means of the slices phi = 0, pi and
 * phi = pi/2, 3 pi/2 (so a general transformed or non-centered distribution is
 * approximated by its Eq. 10 form, which is not elliptical anisotropy: for GGX
 * 0.3 x 0.1 D differs by up to 40% on the x axis and 3x elsewhere; for
 * elliptical anisotropy tabulate the isotropic base of roughness
 * sqrt(ax ay) and apply mf_transformed with M = diag(a/ax, a/ay), exact to the
 * tabulation error). The distribution refers to t: keep t alive and unchanged
 * while it is used. (mf_tabulated_from_ndf is defined in 09_tabulated_from_ndf.h,
 * after mf_D.) */
#define MF_TABULATED_MAX_POINTS 4096
MFDEF mf_result mf_tabulated_build(mf_tabulated *t, const mf_real *theta, const mf_real *D_x,
                                   const mf_real *D_y, int n);
MFDEF mf_result mf_tabulated_from_ndf(mf_tabulated *t, const mf_ndf *d, int n);
MFDEF void mf_tabulated_release(mf_tabulated *t);
MFDEF size_t mf_tabulated_memory_bytes(const mf_tabulated *t);

/* A copy of t whose arrays live in block (a copy of t->block, e.g. in device
 * memory): every array keeps its offset. */
MF_INLINE mf_tabulated mf_tabulated_rebase(const mf_tabulated *t, void *block)
{
    mf_tabulated r = *t;
    mf_real *ob = (mf_real *)t->block, *nb = (mf_real *)block;
    r.theta = nb + (t->theta - ob); r.dx = nb + (t->dx - ob); r.dy = nb + (t->dy - ob);
    r.cx = nb + (t->cx - ob); r.cy = nb + (t->cy - ob); r.lt = nb + (t->lt - ob); r.li = nb + (t->li - ob);
    r.block = block;
    return r;
}
/* The kind's entries of the generic dispatch (05_ndf.h). */
MF_COLD mf_real mf__tabulated_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__tabulated_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__tabulated_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__tabulated_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
/* @cold */
/* Index i of the interval [x[i], x[i+1]] holding v (clamped to 0 .. n-2): direct
 * when the nodes are uniform (inv_h > 0), else by bisection. */
MF_INLINE int mf__tab_find(const mf_real *x, int n, mf_real inv_h, mf_real v)
{
    int lo = 0, hi = n - 1;
    if (!(v > x[0])) return 0;   /* also NaN */
    if (inv_h > MF_R(0.0)) {
        int i = (int)mf_clamp(v * inv_h, MF_R(0.0), (mf_real)(n - 2));
        /* round-off may put v one interval off */
        if (i > 0 && v < x[i]) --i;
        else if (i < n - 2 && v >= x[i + 1]) ++i;
        return i;
    }
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (v < x[mid]) hi = mid; else lo = mid;
    }
    return lo;
}

/* 1 if the control angles a < b are far enough apart to be told apart
 * (16 ulps): the builders reject (or, from an ndf, merge) closer ones. */
MF_INLINE int mf__tab_gap_ok(mf_real a, mf_real b)
{
    return b - a > MF_R(16.0) * MF_EPS * (MF_R(1.0) + MF_FABS(b));
}

/* The curve c (dx or dy) at theta in interval i (Eq. 11). */
MF_INLINE mf_real mf__tab_curve(const mf_tabulated *t, const mf_real *c, int i, mf_real theta)
{
    mf_real f = (theta - t->theta[i]) / (t->theta[i + 1] - t->theta[i]);
    f = mf_clamp(f, MF_R(0.0), MF_R(1.0));
    return c[i] + (c[i + 1] - c[i]) * f;
}

/* Eq. 10 at polar angle theta and cos^2(phi) = c2, per solid angle. */
MF_INLINE mf_real mf__tab_D_angles(const mf_tabulated *t, mf_real theta, mf_real c2)
{
    int i = mf__tab_find(t->theta, t->n, t->inv_h, theta);
    mf_real vx = mf__tab_curve(t, t->dx, i, theta);
    if (!t->aniso) return vx;
    return c2 * t->wx * vx + (MF_R(1.0) - c2) * t->wy * mf__tab_curve(t, t->dy, i, theta);
}

/* Eq. 10 as P + Q cos(2 phi) at theta in control segment i (mf__tabulated_lambda):
 * P = (wx D_x + wy D_y) / 2, Q = (wx D_x - wy D_y) / 2; one curve: P = D_x, Q = 0. */
MF_INLINE void mf__tab_PQ(const mf_tabulated *t, int i, mf_real theta, mf_real *P, mf_real *Q)
{
    mf_real vx = mf__tab_curve(t, t->dx, i, theta), vy;
    if (!t->aniso) { *P = vx; *Q = MF_R(0.0); return; }
    vy = mf__tab_curve(t, t->dy, i, theta);
    *P = MF_R(0.5) * (t->wx * vx + t->wy * vy);
    *Q = MF_R(0.5) * (t->wx * vx - t->wy * vy);
}

/* Tabulated D, homogeneous of degree -4 in wm. */
MF_COLD mf_real mf__tabulated_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real s2, l2, c2;
    if (!d->p.tabulated.tab || !(wm.z > MF_R(0.0))) return MF_R(0.0);
    s2 = wm.x * wm.x + wm.y * wm.y;
    l2 = s2 + wm.z * wm.z;
    if (!(l2 < MF_BIG)) return MF_R(0.0);
    c2 = s2 > MF_R(0.0) ? wm.x * wm.x / s2 : MF_R(0.5);   /* any phi at the pole */
    return mf__tab_D_angles(d->p.tabulated.tab, MF_ATAN2(MF_SQRT(s2), wm.z), c2) / (l2 * l2);
}

/* Tabulated Lambda (Ribardiere et al. 2019, Eq. 13-14). Write Eq. 10 as
 * D = P(theta) + Q(theta) cos(2 phi), P = (wx D_x + wy D_y)/2, Q = (wx D_x - wy D_y)/2.
 * For a view at (theta_o, phi_o), the azimuthal integral of the clamped
 * <o.m> = max(0, a cos(psi) + b), a = sin theta_o sin theta, b = cos theta_o cos theta,
 * psi = phi - phi_o, against 1 and cos(2 psi) is (mf__tab_J)
 *   J0 = 2 pi b, J2 = 0                               where a <= b (I1 + I2 of Eq. 14),
 *   J0 = 2 (a sin p + b p), J2 = (2/3) a sin^3 p, p = acos(-b/a)  beyond (I3),
 * so the projected area I = integral <o.m> D dm = I0(theta_o) + cos(2 phi_o) I2(theta_o),
 *   I0 = int sin theta P J0 dtheta,  I2 = int sin theta Q J2 dtheta,
 * and Lambda = I / cos theta_o - 1. The part theta <= pi/2 - theta_o is the
 * closed-form cumulative mass of the curves; the rest is integrated once, at
 * build time, on nodes theta_o mirrored from the control points (where I has
 * its kinks) and subdivided; Lambda interpolates I0 and I2 by cubic Hermite
 * with their exact theta_o-derivatives. */
MF_INLINE void mf__tab_J(mf_real a, mf_real b, mf_real *j0, mf_real *j2)
{
    mf_real c, sp;
    if (!(a > b)) { *j0 = MF_R(2.0) * MF_PI * b; *j2 = MF_R(0.0); return; }
    c = mf_clamp(-b / a, MF_R(-1.0), MF_R(1.0));
    sp = MF_SQRT(mf_max(MF_R(1.0) - c * c, MF_R(0.0)));
    *j0 = MF_R(2.0) * (a * sp + b * MF_ACOS(c));
    *j2 = MF_R(2.0) / MF_R(3.0) * a * sp * sp * sp;
}

/* Cubic Hermite interpolation of column k (0: I0, 2: I2) of the table at theta_o. */
MF_INLINE mf_real mf__tab_I(const mf_tabulated *t, int j, int k, mf_real to)
{
    const mf_real *a = t->li + 4 * j, *b = a + 4;
    mf_real h = t->lt[j + 1] - t->lt[j], s = h > MF_R(0.0) ? mf_clamp((to - t->lt[j]) / h, MF_R(0.0), MF_R(1.0)) : MF_R(0.0);
    mf_real s2 = s * s, s3 = s2 * s;
    return (MF_R(2.0) * s3 - MF_R(3.0) * s2 + MF_R(1.0)) * a[k] + (s3 - MF_R(2.0) * s2 + s) * h * a[k + 1] +
           (MF_R(3.0) * s2 - MF_R(2.0) * s3) * b[k] + (s3 - s2) * h * b[k + 1];
}

/* The projected area I0 + cos(2 phi_o) I2 of the table at theta_o (k2 = cos 2 phi_o). */
MF_INLINE mf_real mf__tab_area(const mf_tabulated *t, mf_real to, mf_real k2)
{
    int j = mf__tab_find(t->lt, t->n_lam, t->inv_hl, to);
    mf_real I = mf__tab_I(t, j, 0, to);
    return t->aniso ? I + k2 * mf__tab_I(t, j, 2, to) : I;
}

/* Symmetric in w.z like the other kinds; scale-free in w (transforms pass M^-1 w). */
MF_COLD mf_real mf__tabulated_lambda(const mf_ndf *d, mf_vec3 w)
{
    const mf_tabulated *t = d->p.tabulated.tab;
    mf_real s2, z, to, I, co;
    if (!t) return MF_R(0.0);
    z = mf_max(mf_max(MF_FABS(w.x), MF_FABS(w.y)), MF_FABS(w.z));   /* scale-free: bring w near unit length */
    if (!(z > MF_R(0.0)) || !(z < MF_BIG)) return MF_R(0.0);
    w = mf_scale(w, MF_R(1.0) / z);
    s2 = w.x * w.x + w.y * w.y;
    z = MF_FABS(w.z);
    if (!(s2 > MF_R(0.0))) return MF_R(0.0);
    to = MF_ATAN2(MF_SQRT(s2), z);
    I = mf__tab_area(t, to, (w.x * w.x - w.y * w.y) / s2);
    co = mf_max(z / MF_SQRT(s2 + z * z), MF_R(1e-15));
    return mf_clamp(I / co - MF_R(1.0), MF_R(0.0), MF_BIG);
}

/* ---- Tabulated kinds (Ribardiere et al. 2019, Sec. 3.2) ---- */

/* sin(h) cos(h) - h without cancellation at small h */
MF_INLINE mf_real mf__sincos_minus_h(mf_real h)
{
    mf_real h2 = h * h;
    if (MF_FABS(h) < MF_R(0.1))
        return h * h2 * (MF_R(-2.0) / MF_R(3.0) + h2 * (MF_R(2.0) / MF_R(15.0) - h2 * (MF_R(4.0) / MF_R(315.0))));
    return MF_SIN(h) * MF_COS(h) - h;
}

/* D cos mass 2 pi int_{ta}^{x} (da + s (t - ta)) cos t sin t dt of a linear
 * piece (Eq. 12, 17-18): 2 pi [da sin(h) sin(ta + x) / 2 + s (cos 2x (sin h cos h - h)
 * + sin 2x sin^2 h) / 4], h = x - ta, written so that short pieces keep their digits. */
MF_INLINE mf_real mf__tab_piece_mass(mf_real ta, mf_real da, mf_real s, mf_real x)
{
    mf_real h = x - ta, sh = MF_SIN(h);
    return MF_R(2.0) * MF_PI * (MF_R(0.5) * da * sh * MF_SIN(ta + x) +
                                MF_R(0.25) * s * (MF_COS(MF_R(2.0) * x) * mf__sincos_minus_h(h) + MF_SIN(MF_R(2.0) * x) * sh * sh));
}

/* The curve mixture ax D_x + ay D_y on control segment i: its value at theta[i] and slope. */
MF_INLINE void mf__tab_mix(const mf_tabulated *t, int i, mf_real ax, mf_real ay, mf_real *da, mf_real *s)
{
    const mf_real *dy = t->aniso ? t->dy : t->dx;
    mf_real a = ax * t->dx[i] + ay * dy[i], b = ax * t->dx[i + 1] + ay * dy[i + 1];
    *da = a;
    *s = (b - a) / (t->theta[i + 1] - t->theta[i]);
}

/* theta whose cumulative mass of the mixture ax C_x + ay C_y is target (Eq. 17-18):
 * the control segment by bisection of the cumulative masses, then safeguarded
 * Newton on the closed-form mass of the linear piece. */
MF_INLINE mf_real mf__tab_invert(const mf_tabulated *t, mf_real ax, mf_real ay, mf_real target)
{
    const mf_real *cy = t->aniso ? t->cy : t->cx;
    int lo = 0, hi = t->n - 1, it;
    mf_real ta, tb, da, sl, rem, seg, x, blo, bhi;
    if (!(target > MF_R(0.0))) return MF_R(0.0);
    if (!(target < ax * t->cx[hi] + ay * cy[hi])) return t->theta[hi];
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (ax * t->cx[mid] + ay * cy[mid] <= target) lo = mid; else hi = mid;
    }
    ta = t->theta[lo]; tb = t->theta[hi];
    rem = target - (ax * t->cx[lo] + ay * cy[lo]);
    seg = (ax * t->cx[hi] + ay * cy[hi]) - (ax * t->cx[lo] + ay * cy[lo]);
    mf__tab_mix(t, lo, ax, ay, &da, &sl);
    x = ta + (tb - ta) * mf_clamp(rem / mf_max(seg, MF_TINY), MF_R(0.0), MF_R(1.0));
    blo = ta; bhi = tb;
    for (it = 0; it < 60; ++it) {
        mf_real f = mf__tab_piece_mass(ta, da, sl, x) - rem;
        mf_real df = MF_R(2.0) * MF_PI * mf_max(da + sl * (x - ta), MF_R(0.0)) * MF_COS(x) * MF_SIN(x);
        if (mf__newton_step(&x, f, df, &blo, &bhi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + x))) break;
    }
    MF__SOLVER_DONE(MF__SITE_TAB_THETA, it, 60);
    return x;
}

/* Cumulative mass of the mixture ax C_x + ay C_y up to theta. */
MF_INLINE mf_real mf__tab_mass_to(const mf_tabulated *t, mf_real ax, mf_real ay, mf_real theta)
{
    const mf_real *cy = t->aniso ? t->cy : t->cx;
    int k = mf__tab_find(t->theta, t->n, t->inv_h, theta);
    mf_real da, sl;
    mf__tab_mix(t, k, ax, ay, &da, &sl);
    return ax * t->cx[k] + ay * cy[k] + mf__tab_piece_mass(t->theta[k], da, sl, mf_clamp(theta, t->theta[k], t->theta[k + 1]));
}

/* NDF sampling (Eq. 15-18): phi from its marginal (1 + k cos 2 phi) / (2 pi),
 * k = (wx - wy)/2, whose CDF (phi + k sin(2 phi)/2) / (2 pi) (Eq. 16) is
 * inverted by safeguarded Newton; theta given phi from the mixture
 * cos^2(phi) wx C_x + sin^2(phi) wy C_y (Eq. 17-18). */
MF_COLD mf_vec3 mf__tabulated_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    const mf_tabulated *t = d->p.tabulated.tab;
    mf_real phi, cp, sp, th, ax = MF_R(1.0), ay = MF_R(0.0), st;
    if (!t) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));
    phi = MF_R(2.0) * MF_PI * u2;
    if (t->aniso) {
        mf_real k = MF_R(0.5) * (t->wx - t->wy), lo = MF_R(0.0), hi = MF_R(2.0) * MF_PI, target = phi;
        int i;
        for (i = 0; i < 60; ++i)
            if (mf__newton_step(&phi, phi + MF_R(0.5) * k * MF_SIN(MF_R(2.0) * phi) - target,
                                MF_R(1.0) + k * MF_COS(MF_R(2.0) * phi), &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + phi)))
                break;
        MF__SOLVER_DONE(MF__SITE_TAB_PHI, i, 60);
    }
    cp = MF_COS(phi); sp = MF_SIN(phi);
    if (t->aniso) { ax = cp * cp * t->wx; ay = sp * sp * t->wy; }
    th = mf__tab_invert(t, ax, ay, u1 * (ax + ay));
    st = MF_SIN(th);
    return mf_vec3_make(st * cp, st * sp, mf_max(MF_COS(th), MF_R(0.0)));   /* float pi/2 is above pi/2 */
}

/* Integrals over theta in [ta, tb], inside control segment i, of sin(theta) P J0
 * and sin(theta) Q J2 (out[0], out[1]; mf__tab_lambda) for the view (so, co) =
 * (sin, cos theta_o) and, when deriv, of their theta_o-derivatives (out[2],
 * out[3]). Gauss-Legendre panels of at most 0.1 rad, 8 points (4 on pieces
 * under 0.05 rad: the integrand is smooth within a segment); with subst the
 * variable is theta = ta + (tb - ta) s^2, which smooths the (theta -
 * theta_c)^(3/2) onset of J0 at theta_c = pi/2 - theta_o. */
MF_INLINE void mf__tab_outer(const mf_tabulated *t, int i, mf_real ta, mf_real tb, mf_real so, mf_real co,
                             int subst, int deriv, mf_real out[4])
{
    mf_real L = tb - ta;
    int np, p, g, k, ng;
    for (k = 0; k < 4; ++k) out[k] = MF_R(0.0);
    if (!(L > MF_R(0.0))) return;
    np = 1 + (int)(L * MF_R(10.0));
    ng = subst || L >= MF_R(0.05) ? MF__GL_N : 4;
    for (p = 0; p < np; ++p)
        for (g = 0; g < ng; ++g) {
            mf_real xi = ng == 4 ? mf__gl4_xi(g) : mf__gl_xi(g), gw = ng == 4 ? mf__gl4_w(g) : mf__gl_w(g);
            mf_real u = ((mf_real)p + MF_R(0.5) + MF_R(0.5) * xi) / (mf_real)np;
            mf_real th = subst ? ta + L * u * u : ta + L * u, wgt = gw / (mf_real)np * (subst ? MF_R(2.0) * L * u : L);
            mf_real sn = MF_SIN(th), cs = MF_COS(th), a = so * sn, b = co * cs, j0, j2, P, Q;
            mf__tab_PQ(t, i, th, &P, &Q);
            mf__tab_J(a, b, &j0, &j2);
            wgt *= sn;
            out[0] += wgt * P * j0;
            if (t->aniso) out[1] += wgt * Q * j2;
            if (deriv) {
                /* d/dtheta_o under the integral; the clamp's boundary terms vanish */
                mf_real ad = co * sn, bd = -so * cs, dj0, dj2;
                if (a > b) {
                    mf_real c = mf_clamp(-b / a, MF_R(-1.0), MF_R(1.0)), spp = MF_SQRT(mf_max(MF_R(1.0) - c * c, MF_R(0.0)));
                    dj0 = MF_R(2.0) * (ad * spp + bd * MF_ACOS(c));
                    dj2 = MF_R(2.0) * spp * (ad * (MF_R(1.0) - MF_R(2.0) / MF_R(3.0) * spp * spp) + bd * c);
                } else { dj0 = MF_R(2.0) * MF_PI * bd; dj2 = MF_R(0.0); }
                out[2] += wgt * P * dj0;
                if (t->aniso) out[3] += wgt * Q * dj2;
            }
        }
}

/* Antiderivative in psi = phi - phi_o of (a cos psi + b)(P + Qc cos 2psi - Qs sin 2psi),
 * the azimuthal visible density of Eq. 10 (Qc = Q cos 2phi_o, Qs = Q sin 2phi_o). */
MF_INLINE mf_real mf__tab_G(mf_real psi, mf_real a, mf_real b, mf_real P, mf_real Qc, mf_real Qs)
{
    mf_real sn = MF_SIN(psi), cs = MF_COS(psi);
    mf_real s2 = MF_R(2.0) * sn * cs, c2 = cs * cs - sn * sn;
    mf_real s3 = sn * (MF_R(3.0) - MF_R(4.0) * sn * sn), c3 = cs * (MF_R(4.0) * cs * cs - MF_R(3.0));
    return P * (a * sn + b * psi) + Qc * (a * (MF_R(0.5) * sn + s3 / MF_R(6.0)) + MF_R(0.5) * b * s2) +
           Qs * (a * (c3 / MF_R(6.0) + MF_R(0.5) * cs) + MF_R(0.5) * b * c2);
}

/* Exact visible-normal sampling of a tabulated kind. The visible density
 * max(0, w.m) D(m) / I factors into a marginal in theta, sin(theta) [P J0 +
 * cos(2 phi_o) Q J2] (see mf__tab_lambda), and phi given theta. Its total is the
 * projected area of the table. Inside theta_c = pi/2 - theta_o the marginal is
 * cos(theta_o) times the D cos mass of the curve mixture (closed form,
 * inverted as in NDF sampling); beyond it the control segments' masses are
 * integrated by Gauss-Legendre (substitution at theta_c) from theta_c on until
 * the target is reached, and that segment is inverted by safeguarded Newton on
 * its partial integral. phi given theta: the cosine-clamped density of mf__sample_phi_cos
 * for one curve; for two, Newton on the closed-form CDF mf__tab_G. No rejection;
 * deterministic in (u1, u2). Cost grows with the number of control segments
 * beyond theta_c (see make bench). */
MF_COLD mf_vec3 mf__tabulated_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    const mf_tabulated *t = d->p.tabulated.tab;
    mf_real s2, len, so, co, cp = MF_R(1.0), sp = MF_R(0.0), k2, tc, mxw, myw, cin, inner, outer, target;
    mf_real o[4], th, sn, a, b, P, Q, psi, cps, sps, lastm = MF_R(0.0);
    int k, j, i, nseg, last = 0;
    if (!t || !(w.z >= MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    len = mf_max(mf_max(MF_FABS(w.x), MF_FABS(w.y)), w.z);   /* scale-free: bring w near unit length */
    if (!(len > MF_R(0.0)) || !(len < MF_BIG)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    w = mf_scale(w, MF_R(1.0) / len);
    s2 = w.x * w.x + w.y * w.y;
    len = MF_SQRT(s2 + w.z * w.z);   /* in [1, sqrt 3] */
    so = MF_SQRT(s2) / len; co = w.z / len;
    if (s2 > MF_R(0.0)) { cp = w.x / MF_SQRT(s2); sp = w.y / MF_SQRT(s2); }
    k2 = cp * cp - sp * sp;   /* cos(2 phi_o) */
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    u2 = mf_clamp(u2, MF_R(0.0), MF_R(1.0));
    tc = MF_R(0.5) * MF_PI - MF_ATAN2(MF_SQRT(s2), w.z);
    k = mf__tab_find(t->theta, t->n, t->inv_h, tc);
    mxw = t->aniso ? MF_R(0.5) * t->wx : MF_R(1.0);
    myw = t->aniso ? MF_R(0.5) * t->wy : MF_R(0.0);
    cin = mf__tab_mass_to(t, mxw, myw, tc);
    inner = co * cin;
    /* the total from the projected-area table (what D_visible divides by, to
     * its interpolation error ~1e-9); the outer segments are integrated one by
     * one from theta_c until the target is reached */
    outer = mf__tab_area(t, MF_R(0.5) * MF_PI - tc, k2) - inner;
    target = u1 * (inner + mf_max(outer, MF_R(0.0)));
    nseg = t->n - 1 - k;
    if (target <= inner || !(outer > MF_R(0.0))) {
        th = co > MF_R(0.0) ? mf__tab_invert(t, mxw, myw, mf_min(target / co, cin)) : tc;
        th = mf_min(th, tc);
    } else {
        mf_real rem = target - inner, lo, hi, ta, m = MF_R(0.0);
        for (j = 0; j < nseg; ++j) {
            mf__tab_outer(t, k + j, j == 0 ? tc : t->theta[k + j], t->theta[k + j + 1], so, co, j == 0, 0, o);
            m = o[0] + k2 * o[1];
            if (rem <= m) break;
            if (m > MF_R(0.0)) { last = j; lastm = m; }
            rem -= m;
        }
        if (j == nseg) { j = last; m = lastm; rem = m; }   /* the table's total was a hair above the sum */
        ta = j == 0 ? tc : t->theta[k + j];
        lo = ta; hi = t->theta[k + j + 1];
        th = ta + (hi - ta) * mf_clamp(rem / mf_max(m, MF_TINY), MF_R(0.0), MF_R(1.0));
        for (i = 0; i < 60; ++i) {
            mf_real f, ss = MF_SIN(th), jj0, jj2;
            mf__tab_outer(t, k + j, ta, th, so, co, j == 0, 0, o);
            f = o[0] + k2 * o[1] - rem;
            mf__tab_PQ(t, k + j, th, &P, &Q);
            mf__tab_J(so * ss, co * MF_COS(th), &jj0, &jj2);   /* the derivative: the integrand at th */
            if (mf__newton_step(&th, f, ss * (P * jj0 + k2 * Q * jj2), &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + th))) break;
        }
    }
    /* phi given theta */
    sn = MF_SIN(th);
    a = so * sn; b = co * MF_COS(th);
    mf__tab_PQ(t, mf__tab_find(t->theta, t->n, t->inv_h, th), th, &P, &Q);
    if (!t->aniso || !(P > MF_R(0.0))) {
        psi = mf__sample_phi_cos(a > MF_R(1e-30) * b ? b / a : MF_R(1e30), u2);
    } else {
        mf_real pmax = a > b ? MF_ACOS(-b / a) : MF_PI, lo = -pmax, hi = pmax, g0, g1, tg, s2o = MF_R(2.0) * cp * sp;
        g0 = mf__tab_G(-pmax, a, b, P, Q * k2, Q * s2o);
        g1 = mf__tab_G(pmax, a, b, P, Q * k2, Q * s2o);
        tg = g0 + u2 * (g1 - g0);
        psi = -pmax + MF_R(2.0) * pmax * u2;
        for (i = 0; i < 60; ++i) {
            mf_real f = mf__tab_G(psi, a, b, P, Q * k2, Q * s2o) - tg;
            mf_real df = (a * MF_COS(psi) + b) * (P + Q * (k2 * MF_COS(MF_R(2.0) * psi) - s2o * MF_SIN(MF_R(2.0) * psi)));
            if (mf__newton_step(&psi, f, mf_max(df, MF_R(0.0)), &lo, &hi, MF_R(4.0) * MF_EPS * (MF_R(1.0) + MF_FABS(psi)))) break;
        }
    }
    cps = MF_COS(psi); sps = MF_SIN(psi);
    /* z >= 8 eps: theta = pi/2 rounds to cos < 0 in float (u1 = 1 - 2^-24),
     * and atan2 must give the D lookup an angle below the last node */
    return mf_normalize(mf_vec3_make(sn * (cp * cps - sp * sps), sn * (sp * cps + cp * sps), mf_max(MF_COS(th), MF_R(8.0) * MF_EPS)));
}
/* @impl */
/* ---- Tabulated (piecewise-linear) distributions ---- */

static void mf__tab_zero(mf_tabulated *t)
{
    t->n = t->aniso = t->n_lam = 0;
    t->inv_h = t->inv_hl = t->wx = t->wy = t->scale = MF_R(0.0);
    t->theta = t->dx = t->dy = t->cx = t->cy = t->lt = t->li = (mf_real *)0;
    t->block = (void *)0;
    t->bytes = 0;
}

/* normalizes curve c in place (Eq. 12) and fills its cumulative mass; 0 if its mass is not positive */
static int mf__tab_normalize(const mf_real *th, mf_real *c, mf_real *cum, int n)
{
    mf_real total = MF_R(0.0);
    int i;
    cum[0] = MF_R(0.0);
    for (i = 0; i + 1 < n; ++i) {
        total += mf__tab_piece_mass(th[i], c[i], (c[i + 1] - c[i]) / (th[i + 1] - th[i]), th[i + 1]);
        cum[i + 1] = total;
    }
    if (!(total > MF_R(0.0)) || !(total < MF_BIG)) return 0;
    for (i = 0; i < n; ++i) { c[i] /= total; cum[i] /= total; }
    cum[n - 1] = MF_R(1.0);
    return 1;
}

/* I0, dI0, I2, dI2 at theta_o (mf__tabulated_lambda): the closed-form part inside
 * theta_c = pi/2 - theta_o, the integrated part beyond. */
static void mf__tab_node(const mf_tabulated *t, mf_real to, mf_real *out)
{
    mf_real so = MF_SIN(to), co = mf_max(MF_COS(to), MF_R(0.0)), tc = mf_max(MF_R(0.5) * MF_PI - to, MF_R(0.0)), o[4];
    mf_real mxw = t->aniso ? MF_R(0.5) * t->wx : MF_R(1.0), myw = t->aniso ? MF_R(0.5) * t->wy : MF_R(0.0);
    mf_real cin = mf__tab_mass_to(t, mxw, myw, tc);
    int k = mf__tab_find(t->theta, t->n, t->inv_h, tc), j;
    out[0] = co * cin; out[1] = -so * cin; out[2] = out[3] = MF_R(0.0);
    for (j = k; j < t->n - 1; ++j) {
        mf__tab_outer(t, j, j == k ? mf_min(tc, t->theta[k + 1]) : t->theta[j], t->theta[j + 1], so, co, j == k, 1, o);
        out[0] += o[0]; out[2] += o[1]; out[1] += o[2]; out[3] += o[3];
    }
}

MFDEF mf_result mf_tabulated_build(mf_tabulated *t, const mf_real *theta, const mf_real *D_x,
                                   const mf_real *D_y, int n)
{
    const mf_real hpi = MF_R(0.5) * MF_PI;
    mf_real *blk, h, c0;
    int i, j, q, aniso = 0, sub, nl, uniform = 1;
    size_t count;
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    mf__tab_zero(t);
    if (!theta || !D_x || n < 2 || n > MF_TABULATED_MAX_POINTS) return MF_ERROR_INVALID_ARGUMENT;
    h = hpi / (mf_real)(n - 1);
    for (i = 0; i < n; ++i) {
        if (!mf__finite_bits(theta[i]) || !(MF_FABS(theta[i]) < MF_R(10.0))) return MF_ERROR_INVALID_DATA;
        if (i > 0 && !mf__tab_gap_ok(i == 1 ? MF_R(0.0) : theta[i - 1], i == n - 1 ? hpi : theta[i]))
            return MF_ERROR_INVALID_DATA;   /* unordered, or too close once the ends are snapped */
        if (!mf__finite_bits(D_x[i]) || !(D_x[i] >= MF_R(0.0) && D_x[i] < MF_BIG)) return MF_ERROR_INVALID_DATA;
        if (D_y && (!mf__finite_bits(D_y[i]) || !(D_y[i] >= MF_R(0.0) && D_y[i] < MF_BIG))) return MF_ERROR_INVALID_DATA;
        if (D_y && D_y[i] != D_x[i]) aniso = 1;
        if (!(MF_FABS(theta[i] - h * (mf_real)i) <= MF_R(1e-4) * h)) uniform = 0;
    }
    if (!(MF_FABS(theta[0]) <= MF_R(1e-4)) || !(MF_FABS(theta[n - 1] - hpi) <= MF_R(1e-4))) return MF_ERROR_INVALID_DATA;
    /* projected-area nodes: the mirrored control points, each interval cut in sub */
    sub = n - 1 >= 512 ? 1 : n - 1 >= 128 ? 2 : n - 1 >= 32 ? 4 : 8;
    nl = (n - 1) * sub + 1;
    count = (size_t)n * (aniso ? 5u : 3u) + (size_t)nl * 5u;
    blk = (mf_real *)MF_MALLOC(sizeof(mf_real) * count);
    if (!blk) return MF_ERROR_OUT_OF_MEMORY;
    t->block = blk; t->bytes = sizeof(mf_real) * count;
    t->n = n; t->aniso = aniso; t->n_lam = nl;
    t->theta = blk; t->dx = blk + n; t->cx = blk + 2 * n;
    t->dy = aniso ? blk + 3 * n : t->dx;
    t->cy = aniso ? blk + 4 * n : t->cx;
    t->lt = blk + (size_t)n * (aniso ? 5u : 3u);
    t->li = t->lt + nl;
    for (i = 0; i < n; ++i) {
        t->theta[i] = theta[i];
        t->dx[i] = D_x[i];
        if (aniso) t->dy[i] = D_y[i];
    }
    t->theta[0] = MF_R(0.0); t->theta[n - 1] = hpi;
    if (!mf__tab_normalize(t->theta, t->dx, t->cx, n) || (aniso && !mf__tab_normalize(t->theta, t->dy, t->cy, n))) {
        mf_tabulated_release(t);
        return MF_ERROR_INVALID_DATA;
    }
    c0 = MF_R(0.5) * (t->dx[0] + t->dy[0]);   /* Eq. 10 */
    t->wx = c0 > MF_R(0.0) ? t->dy[0] / c0 : MF_R(1.0);
    t->wy = c0 > MF_R(0.0) ? t->dx[0] / c0 : MF_R(1.0);
    t->inv_h = uniform ? MF_R(1.0) / h : MF_R(0.0);
    t->inv_hl = uniform ? (mf_real)sub / h : MF_R(0.0);
    for (j = 0; j + 1 < n; ++j) {
        mf_real a = hpi - t->theta[n - 1 - j], b = hpi - t->theta[n - 2 - j];
        for (q = 0; q < sub; ++q) t->lt[j * sub + q] = a + (b - a) * (mf_real)q / (mf_real)sub;
    }
    t->lt[0] = MF_R(0.0); t->lt[nl - 1] = hpi;
    for (j = 0; j < nl; ++j) mf__tab_node(t, t->lt[j], t->li + 4 * j);
    {   /* characteristic slope: the median of D cos */
        mf_real mxw = aniso ? MF_R(0.5) * t->wx : MF_R(1.0), myw = aniso ? MF_R(0.5) * t->wy : MF_R(0.0);
        t->scale = mf_clamp(MF_TAN(mf_min(mf__tab_invert(t, mxw, myw, MF_R(0.5)), MF_R(1.5706))), MF_R(1e-4), MF_R(1e4));
    }
    return MF_SUCCESS;
}

MFDEF void mf_tabulated_release(mf_tabulated *t)
{
    if (!t) return;
    MF_FREE(t->block);
    mf__tab_zero(t);
}

MFDEF size_t mf_tabulated_memory_bytes(const mf_tabulated *t)
{
    return t && t->block ? t->bytes : 0;
}
