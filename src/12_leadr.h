/* @optional MF_NO_LEADR */
/* @api */
/* ======================================================================== */
/* == 12. LEADR slope moments                                               */
/* ======================================================================== */
/* Dupuy, Heitz et al. 2013 (LEADR mapping). A surface patch is summarized by
 * the first and second moments of its slopes (Eq. 9), which filter linearly
 * (mip maps, bilinear lookups) and define a Gaussian slope distribution
 * (Eq. 8): the mean gives the mesonormal (Eq. 11), the centered second
 * moments the covariance. A roughness alpha of the microsurface adds
 * alpha^2 / 2 to the variances (alpha = sqrt(2) sigma). Texture-space moments
 * move to the surface's tangent frame by the texture Jacobian (Eq. 12). */

typedef struct mf_leadr { mf_real E_x, E_y, E_xx, E_yy, E_xy; } mf_leadr;

MF_INLINE mf_leadr mf__leadr_make(mf_real ex, mf_real ey, mf_real exx, mf_real eyy, mf_real exy)
{
    mf_leadr m;
    m.E_x = ex; m.E_y = ey; m.E_xx = exx; m.E_yy = eyy; m.E_xy = exy;
    return m;
}

/* Moments of a single slope (x, y) = (-n.x/n.z, -n.y/n.z). */
MF_INLINE mf_leadr mf_leadr_from_slope(mf_real x, mf_real y)
{
    return mf__leadr_make(x, y, x * x, y * y, x * y);
}
/* Moments of a unit normal (0 for normals at or below the horizon). */
MF_INLINE mf_leadr mf_leadr_from_normal(mf_vec3 n)
{
    if (!(n.z > MF_R(0.0))) return mf__leadr_make(0, 0, 0, 0, 0);
    return mf_leadr_from_slope(-n.x / n.z, -n.y / n.z);
}
MF_INLINE mf_leadr mf_leadr_add(mf_leadr a, mf_leadr b)
{
    return mf__leadr_make(a.E_x + b.E_x, a.E_y + b.E_y, a.E_xx + b.E_xx, a.E_yy + b.E_yy, a.E_xy + b.E_xy);
}
MF_INLINE mf_leadr mf_leadr_scale(mf_leadr a, mf_real s)
{
    return mf__leadr_make(a.E_x * s, a.E_y * s, a.E_xx * s, a.E_yy * s, a.E_xy * s);
}
/* (1 - t) a + t b */
MF_INLINE mf_leadr mf_leadr_lerp(mf_leadr a, mf_leadr b, mf_real t)
{
    return mf_leadr_add(mf_leadr_scale(a, MF_R(1.0) - t), mf_leadr_scale(b, t));
}
/* Adds the microsurface roughness: alpha^2 / 2 to each variance. */
MF_INLINE mf_leadr mf_leadr_with_roughness(mf_leadr a, mf_real alpha_x, mf_real alpha_y)
{
    a.E_xx += MF_R(0.5) * alpha_x * alpha_x;
    a.E_yy += MF_R(0.5) * alpha_y * alpha_y;
    return a;
}
/* Eq. 12: texture-space moments (slopes along u, v) to the tangent frame
 * (x, y) with the Jacobian duv_dxy = [du/dx du/dy; dv/dx dv/dy]: the slopes
 * move by A = duv_dxy^T, first moments by A, second moments by A E A^T. */
MF_INLINE mf_leadr mf_leadr_deform(mf_leadr a, mf_mat2 duv_dxy)
{
    mf_real a00 = duv_dxy.m00, a01 = duv_dxy.m10, a10 = duv_dxy.m01, a11 = duv_dxy.m11;   /* A */
    mf_leadr r;
    r.E_x = a00 * a.E_x + a01 * a.E_y;
    r.E_y = a10 * a.E_x + a11 * a.E_y;
    r.E_xx = a00 * a00 * a.E_xx + MF_R(2.0) * a00 * a01 * a.E_xy + a01 * a01 * a.E_yy;
    r.E_yy = a10 * a10 * a.E_xx + MF_R(2.0) * a10 * a11 * a.E_xy + a11 * a11 * a.E_yy;
    r.E_xy = a00 * a10 * a.E_xx + (a00 * a11 + a01 * a10) * a.E_xy + a01 * a11 * a.E_yy;
    return r;
}
/* Scaling the displacement by eta scales first moments by eta, second by eta^2. */
MF_INLINE mf_leadr mf_leadr_height_scale(mf_leadr a, mf_real eta)
{
    mf_real e2 = eta * eta;
    return mf__leadr_make(a.E_x * eta, a.E_y * eta, a.E_xx * e2, a.E_yy * e2, a.E_xy * e2);
}
/* The mesonormal (Eq. 11): (-E_x, -E_y, 1) normalized. */
MF_INLINE mf_vec3 mf_leadr_mean_normal(mf_leadr a)
{
    mf_vec3 n = mf_normalize(mf_vec3_make(-a.E_x, -a.E_y, MF_R(1.0)));
    return n.z > MF_R(0.0) ? n : mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(1.0));
}
/* forward declaration: defined below */
MF_INLINE mf_result mf_leadr_to_covariance(mf_leadr a, mf_real *var_x, mf_real *var_y, mf_real *cov_xy);

/* The non-centered anisotropic Beckmann distribution of the moments (Eq. 8,
 * 10) as an mf_ndf: every generic operation works (D, Lambda of Eq. 13-15
 * exact, G1, G2, D_visible, both samplers exact, the BRDF of Eq. 16-17). The
 * covariance goes through mf_leadr_to_covariance's guard. */
MF_INLINE mf_ndf mf_leadr_ndf(mf_leadr a)
{
    mf_real vx, vy, c;
    mf_leadr_to_covariance(a, &vx, &vy, &c);
    return mf__leadr_ndf_make(a.E_x == a.E_x && MF_FABS(a.E_x) < MF_BIG ? a.E_x : MF_R(0.0),
                              a.E_y == a.E_y && MF_FABS(a.E_y) < MF_BIG ? a.E_y : MF_R(0.0), vx, vy, c);
}

/* Eq. 17 with L = F = 1: the radiance reflected toward wo from a directional
 * light along wi, (w_nbar . w_g)/(w_nbar . wo) D(wh) / (4 (1 + Lambda(wo) +
 * Lambda(wi))) (supplement Sec. 3.3); = mf_brdf(mf_leadr_ndf(a)) wi.z. */
MF_INLINE mf_real mf_leadr_specular(mf_leadr a, mf_vec3 wo, mf_vec3 wi)
{
    mf_ndf d = mf_leadr_ndf(a);
    return mf_brdf(&d, wo, wi) * mf_max(wi.z, MF_R(0.0));
}

/* The slope sample grid of Sec. 5.1: n x n points p_j uniform in [-l, l]
 * with Gaussian weights, warped by the Cholesky factor of the covariance
 * and shifted by the mean. l = 0.45 (n - 1) (the paper's 1.8 at n = 5),
 * at most 4.5; the sums converge to the integrals as n grows (test_leadr). */
#define MF_LEADR_GRID_MAX 33
MF_INLINE mf_real mf__leadr_grid_l(int n) { return mf_min(MF_R(0.45) * (mf_real)(n - 1), MF_R(4.5)); }

typedef mf_vec3 (*mf_env_fn)(mf_vec3 wi, mf_real solid_angle, void *ctx);

/* The 1D points and Gaussian weights of the grid; returns the weight sum. */
MF_INLINE mf_real mf__leadr_grid_points(int n, mf_real *p1, mf_real *w1)
{
    mf_real lim = mf__leadr_grid_l(n), wsum = MF_R(0.0);
    int j;
    for (j = 0; j < n; ++j) {
        p1[j] = n > 1 ? -lim + MF_R(2.0) * lim * (mf_real)j / (mf_real)(n - 1) : MF_R(0.0);
        w1[j] = MF_EXP(MF_R(-0.5) * p1[j] * p1[j]);
        wsum += w1[j];
    }
    return wsum;
}

/* The micronormal of grid point (pj, pk): the sample scaled, correlated and
 * shifted to the slope distribution (Sec. 5.1, Cholesky of the covariance). */
MF_INLINE mf_vec3 mf__leadr_grid_normal(const mf_ndf *d, mf_real pj, mf_real pk)
{
    mf_real l00 = MF_SQRT(d->p.leadr.vx), sy2 = MF_SQRT(d->p.leadr.vy), r = d->p.leadr.cxy / (l00 * sy2);
    mf_real sx = pj * l00 + d->p.leadr.mx;
    mf_real sy = (r * pj + MF_SQRT(mf_max(MF_R(1.0) - r * r, MF_R(0.0))) * pk) * sy2 + d->p.leadr.my;
    return mf_normalize(mf_vec3_make(-sx, -sy, MF_R(1.0)));
}

/* Sum over the grid of g(wn) <wn, wo> / (wn . wg) W, where g is the
 * lighting term of the shading mode (0: environment specular, Eq. 22;
 * 1: diffuse under one directional light, Eq. 20-21), divided by the mean
 * surface's projected area wo . (-E_x, -E_y, 1). */
MF_INLINE mf_vec3 mf__leadr_grid(mf_leadr a, mf_vec3 wo, int n, int mode, mf_vec3 wl, int shadowing,
                                 mf_env_fn env, void *ctx)
{
    mf_ndf d = mf_leadr_ndf(a);
    mf_real lam_o, w1[MF_LEADR_GRID_MAX], p1[MF_LEADR_GRID_MAX], wsum, proj, area;
    mf_vec3 acc = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    int j, k;
    n = n < 1 ? 1 : (n > MF_LEADR_GRID_MAX ? MF_LEADR_GRID_MAX : n);
    proj = mf__mean_surface_proj(&d, wo);
    if (!(wo.z > MF_R(0.0)) || !(proj > MF_R(0.0))) return acc;
    wsum = mf__leadr_grid_points(n, p1, w1);
    lam_o = mf_lambda(&d, wo);
    if (mode == 1 && shadowing) lam_o += mf_lambda(&d, wl);   /* the light is fixed: once */
    /* slope-space area of one sample, overestimated along the longest axis */
    area = MF_R(2.0) * (n > 1 ? mf__leadr_grid_l(n) : MF_R(1.0)) * MF_SQRT(mf_max(d.p.leadr.vx, d.p.leadr.vy)) / (mf_real)n;
    area *= area;
    for (j = 0; j < n; ++j)
        for (k = 0; k < n; ++k) {
            mf_real W = w1[j] * w1[k] / (wsum * wsum), on, g;
            mf_vec3 wn = mf__leadr_grid_normal(&d, p1[j], p1[k]), wi;
            on = mf_dot(wn, wo);
            if (!(on > MF_R(0.0))) continue;
            if (mode == 0) {
                mf_vec3 L;
                mf_real sa;
                wi = mf_reflect(wo, wn);
                if (!(wi.z > MF_R(0.0))) continue;
                /* solid angle of the sample: |d wi / d slope| A = 4 (wo.wn) cos^3 A */
                sa = MF_R(4.0) * on * wn.z * wn.z * wn.z * area;
                L = env ? env(wi, sa, ctx) : mf_vec3_make(MF_R(1.0), MF_R(1.0), MF_R(1.0));
                g = MF_R(1.0) / (MF_R(1.0) + lam_o + (shadowing ? mf_lambda(&d, wi) : MF_R(0.0)));
                acc = mf_add(acc, mf_scale(L, g * on / wn.z * W));
            } else {
                mf_real ni = mf_dot(wn, wl);
                if (!(ni > MF_R(0.0))) continue;
                g = ni / (MF_R(1.0) + lam_o);
                acc = mf_add(acc, mf_scale(mf_vec3_make(MF_R(1.0), MF_R(1.0), MF_R(1.0)), g * on / wn.z * W * MF_INV_PI));
            }
        }
    return mf_scale(acc, MF_R(1.0) / proj);
}

/* Specular microfacets under environment lighting (Eq. 19, 22; Algorithm 1):
 * env(wi, solid_angle, ctx) returns the prefiltered radiance for a direction
 * and the solid angle one sample covers, alpha = |d wi / d slope| A with
 * A = (2 l max(sigma_x, sigma_y) / n)^2; a cube map of size s would use
 * LOD = log2(sqrt(alpha / (4 pi)) s) (supplement, Algorithm 1).
 * n x n slope samples (5 is the paper's default); no Fresnel (F = 1);
 * self_shadowing = 0 drops Lambda(wi) (supplement Sec. 1.5). */
MF_INLINE mf_vec3 mf_leadr_specular_env(mf_leadr a, mf_vec3 wo, int n, int self_shadowing, mf_env_fn env, void *ctx)
{
    return mf__leadr_grid(a, wo, n, 0, wo, self_shadowing, env, ctx);
}

/* Diffuse microfacets (albedo 1) under one directional light along wi of
 * radiance 1 (Eq. 20-21, Algorithm 2), n x n slope samples (5 by default). */
MF_INLINE mf_real mf_leadr_diffuse(mf_leadr a, mf_vec3 wo, mf_vec3 wi, int grid_n)
{
    return mf__leadr_grid(a, wo, grid_n > 0 ? grid_n : 5, 1, wi, 1, (mf_env_fn)0, (void *)0).x;
}
/* The same without self-shadowing (1 / (1 + Lambda(wo)), supplement Sec. 1.5). */
MF_INLINE mf_real mf_leadr_diffuse_noshadow(mf_leadr a, mf_vec3 wo, mf_vec3 wi, int grid_n)
{
    return mf__leadr_grid(a, wo, grid_n > 0 ? grid_n : 5, 1, wi, 0, (mf_env_fn)0, (void *)0).x;
}

/* Second-order spherical harmonics of a radiance environment (Ramamoorthi &
 * Hanrahan 2001; LEADR Algorithm 2), coefficients ordered L00, L1-1, L10,
 * L11, L2-2, L2-1, L20, L21, L22. Adds a directional light of radiance L. */
MF_INLINE void mf_sh9_add_directional(mf_real sh[9], mf_vec3 dir, mf_real L)
{
    mf_real x = dir.x, y = dir.y, z = dir.z;
    sh[0] += MF_R(0.282095) * L;
    sh[1] += MF_R(0.488603) * y * L; sh[2] += MF_R(0.488603) * z * L; sh[3] += MF_R(0.488603) * x * L;
    sh[4] += MF_R(1.092548) * x * y * L; sh[5] += MF_R(1.092548) * y * z * L;
    sh[6] += MF_R(0.315392) * (MF_R(3.0) * z * z - MF_R(1.0)) * L;
    sh[7] += MF_R(1.092548) * x * z * L; sh[8] += MF_R(0.546274) * (x * x - y * y) * L;
}
/* Irradiance E(n) of the SH9 environment (Ramamoorthi & Hanrahan Eq. 13). */
MF_INLINE mf_real mf_sh9_irradiance(const mf_real sh[9], mf_vec3 n)
{
    const mf_real c1 = MF_R(0.429043), c2 = MF_R(0.511664), c3 = MF_R(0.743125), c4 = MF_R(0.886227), c5 = MF_R(0.247708);
    mf_real x = n.x, y = n.y, z = n.z;
    return c1 * sh[8] * (x * x - y * y) + c3 * sh[6] * z * z + c4 * sh[0] - c5 * sh[6] +
           MF_R(2.0) * c1 * (sh[4] * x * y + sh[7] * x * z + sh[5] * y * z) +
           MF_R(2.0) * c2 * (sh[3] * x + sh[1] * y + sh[2] * z);
}

/* Diffuse microfacets (albedo 1) under an SH9 environment, without
 * self-shadowing (supplement, Simplified Algorithm 3): the ratio
 * sum E(wn) S W / (pi sum S W), S = <wn, wo> / (wn . wg), over n x n slope
 * samples plus the artificial micronormal of supplement Sec. 3.7 (the
 * mesonormal bent toward wo, weight 1e-5), which keeps the result defined
 * when the mesonormal faces away from wo (low tessellation silhouettes). */
MF_INLINE mf_real mf_leadr_diffuse_sh9(mf_leadr a, mf_vec3 wo, const mf_real sh[9], int n)
{
    mf_ndf d = mf_leadr_ndf(a);
    mf_real w1[MF_LEADR_GRID_MAX], p1[MF_LEADR_GRID_MAX], wsum, num, den, on;
    mf_vec3 nb = mf_leadr_mean_normal(a), nt;
    int j, k;
    n = n < 1 ? 5 : (n > MF_LEADR_GRID_MAX ? MF_LEADR_GRID_MAX : n);
    if (!(wo.z > MF_R(0.0)) || !sh) return MF_R(0.0);
    wsum = mf__leadr_grid_points(n, p1, w1);
    /* the artificial micronormal */
    nt = mf_normalize(mf_add(nb, mf_scale(wo, -mf_dot(nb, wo) * MF_R(1.01))));
    on = mf_max(mf_dot(nt, wo), MF_R(0.0));
    den = MF_R(1e-5) * on / mf_max(nt.z, MF_R(1e-6));
    num = den * mf_sh9_irradiance(sh, nt);
    for (j = 0; j < n; ++j)
        for (k = 0; k < n; ++k) {
            mf_vec3 wn = mf__leadr_grid_normal(&d, p1[j], p1[k]);
            mf_real S = mf_max(mf_dot(wn, wo), MF_R(0.0)) / wn.z * w1[j] * w1[k] / (wsum * wsum);
            num += S * mf_sh9_irradiance(sh, wn);
            den += S;
        }
    return den > MF_R(0.0) ? num / (MF_PI * den) : MF_R(0.0);
}

/* Covariance (Eq. 9) with its validity guard: variances in
 * [MF_LEADR_MIN_VARIANCE, MF_LEADR_MAX_VARIANCE] and |correlation| at most
 * MF_LEADR_MAX_CORRELATION (filtering and float round-off can break the
 * first and last; the upper bound, alpha = sqrt(2 var) = MF_ALPHA_MAX, keeps
 * the determinant and D finite in float). The outputs are always written;
 * returns MF_SUCCESS if the moments were valid as given,
 * MF_ERROR_INVALID_DATA if the guard changed them (non-finite moments give an
 * isotropic variance of MF_LEADR_MIN_VARIANCE). */
#define MF_LEADR_MIN_VARIANCE MF_R(1e-8)
#define MF_LEADR_MAX_VARIANCE MF_R(5e7)
#define MF_LEADR_MAX_CORRELATION MF_R(0.999)
MF_INLINE mf_result mf_leadr_to_covariance(mf_leadr a, mf_real *var_x, mf_real *var_y, mf_real *cov_xy)
{
    mf_real sx = a.E_xx - a.E_x * a.E_x, sy = a.E_yy - a.E_y * a.E_y, c = a.E_xy - a.E_x * a.E_y, lim;
    int ok = 1;
    if (!(sx < MF_BIG) || !(sy < MF_BIG) || !(MF_FABS(c) < MF_BIG)) { sx = sy = MF_LEADR_MIN_VARIANCE; c = MF_R(0.0); ok = 0; }
    if (!(sx >= MF_LEADR_MIN_VARIANCE)) { sx = MF_LEADR_MIN_VARIANCE; ok = 0; }
    if (!(sy >= MF_LEADR_MIN_VARIANCE)) { sy = MF_LEADR_MIN_VARIANCE; ok = 0; }
    if (sx > MF_LEADR_MAX_VARIANCE) { sx = MF_LEADR_MAX_VARIANCE; ok = 0; }
    if (sy > MF_LEADR_MAX_VARIANCE) { sy = MF_LEADR_MAX_VARIANCE; ok = 0; }
    lim = MF_LEADR_MAX_CORRELATION * MF_SQRT(sx * sy);
    if (MF_FABS(c) > lim) { c = c > MF_R(0.0) ? lim : -lim; ok = 0; }
    if (var_x) *var_x = sx;
    if (var_y) *var_y = sy;
    if (cov_xy) *cov_xy = c;
    return ok ? MF_SUCCESS : MF_ERROR_INVALID_DATA;
}

/* A mip pyramid of moments over a periodic (tiling) texture. Level 0 holds
 * width x height texels; each next level halves both sizes (down to 1) and
 * holds exactly the mean of its 2x2 children. Sizes must be powers of two.
 * Built by mf_leadr_map_from_heights / mf_leadr_map_from_normals (implementation section). */
typedef struct mf_leadr_map {
    int width, height, levels;
    mf_leadr *texels;      /* all levels, level 0 first, rows top to bottom */
    size_t offset[32];     /* first texel of each level */
} mf_leadr_map;

MF_INLINE int mf__leadr_level_w(const mf_leadr_map *m, int l) { int w = m->width >> l; return w > 0 ? w : 1; }
MF_INLINE int mf__leadr_level_h(const mf_leadr_map *m, int l) { int h = m->height >> l; return h > 0 ? h : 1; }

/* Bilinear lookup at (u, v) in level l, wrapping (texel centers at (i + 1/2) / size). */
MF_INLINE mf_leadr mf__leadr_bilinear(const mf_leadr_map *m, int l, mf_real u, mf_real v)
{
    int w = mf__leadr_level_w(m, l), h = mf__leadr_level_h(m, l), x0, y0, x1, y1;
    mf_real x = u * (mf_real)w - MF_R(0.5), y = v * (mf_real)h - MF_R(0.5), fx, fy, fl;
    const mf_leadr *t = m->texels + m->offset[l];
    fl = (mf_real)(int)x; if (fl > x) fl -= MF_R(1.0);
    fx = x - fl; x0 = (int)fl;
    fl = (mf_real)(int)y; if (fl > y) fl -= MF_R(1.0);
    fy = y - fl; y0 = (int)fl;
    x0 %= w; if (x0 < 0) x0 += w;
    y0 %= h; if (y0 < 0) y0 += h;
    x1 = (x0 + 1) % w; y1 = (y0 + 1) % h;
    return mf_leadr_lerp(mf_leadr_lerp(t[y0 * w + x0], t[y0 * w + x1], fx),
                         mf_leadr_lerp(t[y1 * w + x0], t[y1 * w + x1], fx), fy);
}

/* Trilinear lookup for a footprint of width `footprint` in texture units (the
 * texture spans [0,1]^2 and tiles): the level where a texel has that width,
 * bilinear within the two nearest levels, linear between them. */
MF_INLINE mf_leadr mf_leadr_map_lookup(const mf_leadr_map *m, mf_real u, mf_real v, mf_real footprint)
{
    mf_real lod, f;
    int l0;
    if (!m || !m->texels || m->levels < 1 || !(u == u) || !(v == v)) return mf__leadr_make(0, 0, 0, 0, 0);
    /* keep the coordinates small (wrap happens per texel); beyond 2^23 every
     * float is an integer, and an infinite coordinate goes to the edge 0:
     * no out-of-range conversion to int */
    u = MF_FABS(u) < MF_R(8388608.0) ? u - (mf_real)(int)u : MF_R(0.0);
    v = MF_FABS(v) < MF_R(8388608.0) ? v - (mf_real)(int)v : MF_R(0.0);
    lod = footprint > MF_R(0.0) ? MF_LOG(footprint * (mf_real)(m->width > m->height ? m->width : m->height)) * MF_R(1.4426950408889634) : MF_R(0.0);
    lod = mf_clamp(lod, MF_R(0.0), (mf_real)(m->levels - 1));
    l0 = (int)lod;
    if (l0 >= m->levels - 1) return mf__leadr_bilinear(m, m->levels - 1, u, v);
    f = lod - (mf_real)l0;
    return mf_leadr_lerp(mf__leadr_bilinear(m, l0, u, v), mf__leadr_bilinear(m, l0 + 1, u, v), f);
}

/* ---- LEADR moment maps ----
 * From a height map (heights in texture units: the texture spans [0,1]^2, so
 * the slope along u is (h[x+1] - h[x-1]) width / 2, periodic) or from a normal
 * map (unit normals, 3 per texel, z > 0), plus a base microsurface roughness
 * (alpha_x, alpha_y added as alpha^2/2 to the variances). Row-major, rows top
 * to bottom. width and height must be powers of two, at most 2^15. Errors:
 * NULL or zero size or non-power-of-two, alpha NaN, negative or above
 * MF_ALPHA_MAX (MF_ERROR_INVALID_ARGUMENT); non-finite heights or slopes
 * whose square exceeds MF_BIG / 4, invalid normals - not unit within 1e-3,
 * or z below MF_LEADR_MIN_NORMAL_Z, whose slope variance would overflow -
 * (MF_ERROR_INVALID_DATA); allocation (MF_ERROR_OUT_OF_MEMORY); nothing
 * stays allocated on failure. */
#define MF_LEADR_MIN_NORMAL_Z MF_R(1e-4)
MFDEF mf_result mf_leadr_map_from_heights(mf_leadr_map *m, const mf_real *heights, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y);
MFDEF mf_result mf_leadr_map_from_normals(mf_leadr_map *m, const mf_real *normals_xyz, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y);
MFDEF void mf_leadr_map_release(mf_leadr_map *m);
MFDEF size_t mf_leadr_map_memory_bytes(const mf_leadr_map *m);
/* @impl */
/* ---- LEADR moment maps ---- */


/* allocates the pyramid for level 0 already filled in m->texels[0..w*h) */
static mf_result mf__leadr_alloc(mf_leadr_map *m, int w, int h)
{
    size_t total = 0;
    int l, ww = w, hh = h;
    m->width = w; m->height = h; m->levels = 0;
    for (l = 0; l < 32; ++l) {
        m->offset[l] = total;
        total += (size_t)ww * (size_t)hh;
        ++m->levels;
        if (ww == 1 && hh == 1) break;
        ww = ww > 1 ? ww / 2 : 1; hh = hh > 1 ? hh / 2 : 1;
    }
    /* at most 2^30 * 4/3 texels (sizes up to 2^15): check the bytes anyway */
    if (total > (size_t)-1 / sizeof(mf_leadr)) return MF_ERROR_OUT_OF_MEMORY;
    m->texels = (mf_leadr *)MF_MALLOC(sizeof(mf_leadr) * total);
    return m->texels ? MF_SUCCESS : MF_ERROR_OUT_OF_MEMORY;
}

/* coarser levels: the mean of the 2x2 children (a 2x1 or 1x2 pair once one
 * side has reached 1) */
static void mf__leadr_reduce(mf_leadr_map *m)
{
    int l;
    for (l = 1; l < m->levels; ++l) {
        size_t pw = (size_t)mf__leadr_level_w(m, l - 1), ph = (size_t)mf__leadr_level_h(m, l - 1);
        size_t w = (size_t)mf__leadr_level_w(m, l), h = (size_t)mf__leadr_level_h(m, l), x, y;
        const mf_leadr *src = m->texels + m->offset[l - 1];
        mf_leadr *dst = m->texels + m->offset[l];
        size_t sx = pw > w ? 2 : 1, sy = ph > h ? 2 : 1;
        for (y = 0; y < h; ++y)
            for (x = 0; x < w; ++x) {
                mf_leadr acc = src[(y * sy) * pw + x * sx];
                if (sx == 2) acc = mf_leadr_add(acc, src[(y * sy) * pw + x * sx + 1]);
                if (sy == 2) {
                    acc = mf_leadr_add(acc, src[(y * sy + 1) * pw + x * sx]);
                    if (sx == 2) acc = mf_leadr_add(acc, src[(y * sy + 1) * pw + x * sx + 1]);
                }
                dst[y * w + x] = mf_leadr_scale(acc, MF_R(1.0) / (mf_real)(sx * sy));
            }
    }
}

/* the base roughness: finite, 0 to MF_ALPHA_MAX */
MF_INLINE int mf__leadr_alpha_ok(mf_real a) { return a >= MF_R(0.0) && a <= MF_ALPHA_MAX; }

MFDEF mf_result mf_leadr_map_from_heights(mf_leadr_map *m, const mf_real *heights, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y)
{
    size_t x, y, w = (size_t)width, h = (size_t)height, i;
    mf_result r;
    if (!m) return MF_ERROR_INVALID_ARGUMENT;
    m->texels = 0; m->width = m->height = m->levels = 0;
    if (!heights || !mf__pow2(width) || !mf__pow2(height) || width > (1 << 15) || height > (1 << 15) ||
        !mf__leadr_alpha_ok(alpha_x) || !mf__leadr_alpha_ok(alpha_y))
        return MF_ERROR_INVALID_ARGUMENT;
    /* allocation first: a size the allocator refuses never reads the data */
    r = mf__leadr_alloc(m, width, height);
    if (r != MF_SUCCESS) { m->width = m->height = m->levels = 0; return r; }
    for (i = 0; i < w * h; ++i)
        if (!mf__finite_bits(heights[i]) || !(MF_FABS(heights[i]) < MF_BIG)) { mf_leadr_map_release(m); return MF_ERROR_INVALID_DATA; }
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            size_t xp = (x + 1) % w, xm = (x + w - 1) % w, yp = (y + 1) % h, ym = (y + h - 1) % h;
            /* rows run top to bottom, v grows downward with the row index */
            mf_real su = (heights[y * w + xp] - heights[y * w + xm]) * (mf_real)width * MF_R(0.5);
            mf_real sv = (heights[yp * w + x] - heights[ym * w + x]) * (mf_real)height * MF_R(0.5);
            if (!(su * su < MF_R(0.25) * MF_BIG) || !(sv * sv < MF_R(0.25) * MF_BIG)) {
                mf_leadr_map_release(m);
                return MF_ERROR_INVALID_DATA;
            }
            m->texels[y * w + x] = mf_leadr_with_roughness(mf_leadr_from_slope(su, sv), alpha_x, alpha_y);
        }
    mf__leadr_reduce(m);
    return MF_SUCCESS;
}

MFDEF mf_result mf_leadr_map_from_normals(mf_leadr_map *m, const mf_real *normals_xyz, int width, int height,
                                          mf_real alpha_x, mf_real alpha_y)
{
    size_t i, n_texels = (size_t)width * (size_t)height;
    mf_result r;
    if (!m) return MF_ERROR_INVALID_ARGUMENT;
    m->texels = 0; m->width = m->height = m->levels = 0;
    if (!normals_xyz || !mf__pow2(width) || !mf__pow2(height) || width > (1 << 15) || height > (1 << 15) ||
        !mf__leadr_alpha_ok(alpha_x) || !mf__leadr_alpha_ok(alpha_y))
        return MF_ERROR_INVALID_ARGUMENT;
    r = mf__leadr_alloc(m, width, height);
    if (r != MF_SUCCESS) { m->width = m->height = m->levels = 0; return r; }
    for (i = 0; i < n_texels; ++i) {
        const mf_real *n = normals_xyz + 3 * i;
        mf_real l2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (!(n[2] >= MF_LEADR_MIN_NORMAL_Z) || !(MF_FABS(l2 - MF_R(1.0)) < MF_R(1e-3))) {
            mf_leadr_map_release(m);
            return MF_ERROR_INVALID_DATA;
        }
    }
    for (i = 0; i < n_texels; ++i) {
        const mf_real *n = normals_xyz + 3 * i;
        m->texels[i] = mf_leadr_with_roughness(mf_leadr_from_normal(mf_vec3_make(n[0], n[1], n[2])), alpha_x, alpha_y);
    }
    mf__leadr_reduce(m);
    return MF_SUCCESS;
}

MFDEF void mf_leadr_map_release(mf_leadr_map *m)
{
    if (!m) return;
    MF_FREE(m->texels);
    m->texels = 0;
    m->width = m->height = m->levels = 0;
}

MFDEF size_t mf_leadr_map_memory_bytes(const mf_leadr_map *m)
{
    if (!m || !m->texels || m->levels < 1) return 0;
    return sizeof(mf_leadr) * (m->offset[m->levels - 1] + 1);
}
