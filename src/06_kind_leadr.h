/* ======================================================================== */
/* == 6. Distribution kinds: LEADR (non-centered anisotropic Beckmann)      */
/* ======================================================================== */
/* The distribution of LEADR slope moments (Dupuy et al. 2013): Gaussian
 * slopes with a mean and a covariance, D = exp(-q/2) / (2 pi sqrt(det) cos^4)
 * (Eq. 8 and 10); the exact Smith Lambda of the shifted Gaussian (Eq. 13-15);
 * NDF sampling through the Cholesky factor; visible normals by a half-plane
 * inversion. Built from moments by mf_leadr_ndf (module 12). Cold. */
/* @decl */
typedef struct mf_ndf_leadr {
    mf_real mx, my;            /* mean slope */
    mf_real vx, vy, cxy;       /* covariance (its inverse and Cholesky factor are
                                  derived where needed: mf__leadr_inverse, mf__leadr_chol) */
    mf_real norm;              /* 1 / (2 pi sqrt(det)) (Eq. 8) */
} mf_ndf_leadr;
/* @api */
/* The distribution of slopes with mean (mx, my) (finite) and covariance
 * [vx c; c vy] (positive definite; mf_leadr_ndf ensures both). */
MF_INLINE mf_ndf mf__leadr_ndf_make(mf_real mx, mf_real my, mf_real vx, mf_real vy, mf_real c)
{
    mf_ndf d = mf__ndf_init(MF_NDF_LEADR, MF_SQRT(MF_R(2.0) * vx), MF_SQRT(MF_R(2.0) * vy));
    mf_ndf_leadr *p = &d.p.leadr;
    p->mx = mx; p->my = my;
    p->vx = vx; p->vy = vy; p->cxy = c;
    p->norm = MF_R(1.0) / (MF_R(2.0) * MF_PI * MF_SQRT(vx * vy - c * c));
    return d;
}
/* the inverse covariance (ixx, iyy, ixy) and the Cholesky factor L (L L^T =
 * covariance, l01 = 0) */
MF_INLINE void mf__leadr_inverse(const mf_ndf_leadr *p, mf_real *ixx, mf_real *iyy, mf_real *ixy)
{
    mf_real det = p->vx * p->vy - p->cxy * p->cxy;
    *ixx = p->vy / det; *iyy = p->vx / det; *ixy = -p->cxy / det;
}
MF_INLINE void mf__leadr_chol(const mf_ndf_leadr *p, mf_real *l00, mf_real *l10, mf_real *l11)
{
    *l00 = MF_SQRT(p->vx); *l10 = p->cxy / *l00;
    *l11 = MF_SQRT(mf_max(p->vy - *l10 * *l10, MF_R(1e-30)));
}

/* The kind's entries of the generic dispatch (05_ndf.h; CEN 0: the mean slope). */
MF_COLD mf_real mf__leadr_D(const mf_ndf *d, mf_vec3 wm);
MF_COLD mf_real mf__leadr_lambda(const mf_ndf *d, mf_vec3 w);
MF_COLD mf_vec3 mf__leadr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2);
MF_COLD mf_vec3 mf__leadr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2);
MF_FORCE_INLINE void mf__leadr_mean_slope(const mf_ndf *d, mf_real *mx, mf_real *my)
{
    *mx = d->p.leadr.mx; *my = d->p.leadr.my;
}
/* @cold */

/* Eq. 8 and 10: Gaussian slopes with mean and covariance, / cos^4 */
MF_COLD mf_real mf__leadr_D(const mf_ndf *d, mf_vec3 wm)
{
    const mf_ndf_leadr *p = &d->p.leadr;
    mf_real sx, sy, q, z2, ixx, iyy, ixy;
    if (!(wm.z > MF_R(0.0))) return MF_R(0.0);
    sx = -wm.x / wm.z - p->mx;
    sy = -wm.y / wm.z - p->my;
    mf__leadr_inverse(p, &ixx, &iyy, &ixy);
    q = ixx * sx * sx + MF_R(2.0) * ixy * sx * sy + iyy * sy * sy;
    if (!(q >= MF_R(0.0) && q < MF_R(160.0))) return MF_R(0.0);   /* q < 0: float overflow */
    z2 = wm.z * wm.z;
    /* capped: a mean slope far from the axis keeps q small at grazing wm,
     * where 1 / cos^4 overflows (float) */
    return mf__cap(p->norm * MF_EXP(MF_R(-0.5) * q) / (z2 * z2));
}

/* slope = mean + L n, n two standard normals */
MF_COLD mf_vec3 mf__leadr_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    const mf_ndf_leadr *p = &d->p.leadr;
    mf_real t = mf_clamp(u1, MF_R(0.0), MF_R(1.0)), l00, l10, l11;
    mf_real n1 = MF_R(1.4142135623730951) * mf_erfinv(MF_R(2.0) * t - MF_R(1.0));
    mf_real n2 = MF_R(1.4142135623730951) * mf_erfinv(MF_R(2.0) * u2 - MF_R(1.0));
    mf_real sx, sy;
    mf__leadr_chol(p, &l00, &l10, &l11);
    sx = p->mx + l00 * n1;
    sy = p->my + l10 * n1 + l11 * n2;
    return mf_normalize(mf_vec3_make(-sx, -sy, MF_R(1.0)));
}

/* LEADR Lambda (Eq. 13-15 and the supplement, Sec. 1.5): the exact Smith
 * Lambda of the shifted Gaussian relative to the mesonormal's projected area,
 * Lambda = exp(-nu^2) / (2 nu sqrt(pi)) - erfc(nu) / 2 with
 * nu = (cot theta - mu(phi)) / (sigma(phi) sqrt 2); +infinity (MF_BIG) for
 * nu <= 0, a direction below the mean surface. Not symmetric in w.z. */
MF_COLD mf_real mf__leadr_lambda(const mf_ndf *d, mf_vec3 w)
{
    mf_real sxy = MF_SQRT(w.x * w.x + w.y * w.y), cp, sp, mu, var, nu;
    if (!(sxy > MF_R(0.0))) return w.z > MF_R(0.0) ? MF_R(0.0) : MF_BIG;
    cp = w.x / sxy; sp = w.y / sxy;
    mu = cp * d->p.leadr.mx + sp * d->p.leadr.my;
    var = cp * cp * d->p.leadr.vx + sp * sp * d->p.leadr.vy + MF_R(2.0) * cp * sp * d->p.leadr.cxy;
    nu = (w.z / sxy - mu) / MF_SQRT(MF_R(2.0) * mf_max(var, MF_R(1e-30)));
    if (!(nu > MF_R(0.0))) return MF_BIG;
    if (nu > MF_R(30.0)) return MF_R(0.0);
    return mf_min(mf_max(MF_R(0.5) * (MF_EXP(-nu * nu) / (nu * MF_SQRT_PI) - MF_ERFC(nu)), MF_R(0.0)), MF_BIG);
}

/* LEADR visible normals: with slopes s = mean + L z (z standard normal), the
 * visibility weight max(0, w.z - s . w.xy) is a half-plane in z along
 * n = L^T w.xy, so z along n has the Beckmann-like visible density
 * max(0, c - z1) N(z1) (the inversion of mf__beckmann_visible_slopes) and z
 * across n stays standard normal. */
MF_COLD mf_vec3 mf__leadr_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real l00, l10, l11, nx, ny, k, cnum, x, y, ex = MF_R(1.0), ey = MF_R(0.0), z1, z2, sx, sy;
    mf__leadr_chol(&d->p.leadr, &l00, &l10, &l11);
    nx = l00 * w.x + l10 * w.y; ny = l11 * w.y; k = MF_SQRT(nx * nx + ny * ny);
    cnum = w.z - d->p.leadr.mx * w.x - d->p.leadr.my * w.y;
    if (w.z < MF_R(0.0) || !(cnum > MF_R(0.0))) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (k > MF_R(1e-30) * cnum) { ex = nx / k; ey = ny / k; }
    /* unit-Beckmann units (exp(-x^2)): z = sqrt(2) x, bound c = cnum / k */
    mf__beckmann_visible_slopes(k > MF_R(1e-30) * cnum ? MF_R(1.4142135623730951) * k / cnum : MF_R(0.0), u1, u2, &x, &y);
    z1 = MF_R(1.4142135623730951) * x; z2 = MF_R(1.4142135623730951) * y;
    /* z = z1 e + z2 e_perp, s = mean + L z */
    x = z1 * ex - z2 * ey; y = z1 * ey + z2 * ex;
    sx = d->p.leadr.mx + l00 * x;
    sy = d->p.leadr.my + l10 * x + l11 * y;
    return mf_normalize(mf_vec3_make(-sx, -sy, MF_R(1.0)));
}
