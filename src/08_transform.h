/* @api */
/* ======================================================================== */
/* == 8. Linearly transformed microsurfaces                                 */
/* ======================================================================== */
/* Atanasov et al. 2022 (thesis ch. 4): the microsurface is transformed by a
 * tangential matrix M (Eq. 4.1: M acts on the xy plane, z is kept). Normals
 * transform by M^-T, so the statistics of the new surface are those of the old
 * one at transformed arguments:
 *   D_M(m)     = |det M| / |M^T m|^4 D(M^T m / |M^T m|)        (Eq. 4.14)
 *   G1_M(v, m) = G1(M^-1 v / |M^-1 v|, M^T m / |M^T m|)         (Eq. 4.4)
 *   sampling   u' ~ D cos or D_w with w = M^-1 v / |.|, then m' = M^-T u' / |.|
 *                                                              (Eq. 4.17-4.21)
 * This holds for every distribution, shape-invariant or not; mf_transformed
 * works on any mf_ndf and every generic operation honours it. A diagonal M on a
 * shape-invariant distribution equals elliptical anisotropy (Eq. 4.22-4.23). */

/* M with |det M| <= MF_TRANSFORM_MIN_DET times the squared Frobenius norm of
 * M (or with a non-finite entry) is not invertible enough to define a surface. */
#define MF_TRANSFORM_MIN_DET MF_R(1e-9)

/* 1 if M can transform a microsurface (finite, |det| above the threshold,
 * and |det| > 1/MF_BIG so that 1/det and with it M^-1 stay finite in mf_real:
 * diag(1e-20, 1e-20) passes the relative test but not this one in float). */
MF_INLINE int mf_transform_is_valid(mf_mat2 M)
{
    mf_real n2 = M.m00 * M.m00 + M.m01 * M.m01 + M.m10 * M.m10 + M.m11 * M.m11;
    mf_real det = MF_FABS(mf_mat2_det(M));
    return n2 < MF_BIG && det < MF_BIG && det > MF_TRANSFORM_MIN_DET * n2 && det * MF_BIG > MF_R(1.0);
}

/* The distribution of the microsurface transformed by M (row-major, acting
 * on the tangent-plane coordinates (x, y) of the shading frame). Transforming
 * a transformed distribution composes: mf_transformed(mf_transformed(b, M1), M2)
 * is b transformed by M2 M1. An M that fails mf_transform_is_valid is rejected:
 * base is returned unchanged. The identity gives back base itself, at no cost. */
MF_INLINE mf_ndf mf_transformed(mf_ndf base, mf_mat2 M)
{
    mf_ndf d = base;
    mf_mat2 P = base.transformed ? mf_mat2_mul(M, base.M) : M;
    if (!mf_transform_is_valid(M) || !mf_transform_is_valid(P)) return base;
    d.M = P;
    d.idet = MF_R(1.0) / mf_mat2_det(P);   /* finite and nonzero: P is valid */
    d.transformed = P.m00 == MF_R(1.0) && P.m01 == MF_R(0.0) && P.m10 == MF_R(0.0) && P.m11 == MF_R(1.0) ? 0 : 1;
    return d;
}

/* d rotated by angle (radians, counterclockwise about the normal): the
 * transform by the rotation R (thesis ch. 4; for a rotation M^-T = M), so
 * D_rotated(m) = D(R^-1 m). Turns an anisotropic lobe, e.g. to follow a
 * brushing direction, without rebuilding the frame. */
MF_INLINE mf_ndf mf_rotated(mf_ndf d, mf_real angle)
{
    mf_real c, s;
    if (!(angle == angle) || !(MF_FABS(angle) < MF_R(1e6))) return d;
    c = MF_COS(angle); s = MF_SIN(angle);
    return mf_transformed(d, mf_mat2_make(c, -s, s, c));
}

/* Stretch matrix M_s (Eq. 4.24): diag(1/(1-s), 1-s) for s in [0,1),
 * diag(1+s, 1/(1+s)) for s in (-1,0); det M_s = 1, M_s^-1 = M_-s (Eq. 4.25).
 * s is clamped to [-0.999, 0.999]. */
MF_INLINE mf_mat2 mf_stretch_matrix(mf_real s)
{
    s = s == s ? mf_clamp(s, MF_R(-0.999), MF_R(0.999)) : MF_R(0.0);
    if (s >= MF_R(0.0)) return mf_mat2_make(MF_R(1.0) / (MF_R(1.0) - s), MF_R(0.0), MF_R(0.0), MF_R(1.0) - s);
    return mf_mat2_make(MF_R(1.0) + s, MF_R(0.0), MF_R(0.0), MF_R(1.0) / (MF_R(1.0) + s));
}

/* Stretch anisotropy: s > 0 stretches along x (smoother in x), s < 0 along y. */
MF_INLINE mf_ndf mf_stretched(mf_ndf base, mf_real s)
{
    return mf_transformed(base, mf_stretch_matrix(s));
}

/* Anisotropic GTR by scaling the microsurface (Eq. 4.22 with alpha =
 * sqrt(alpha_x alpha_y)): exactly elliptical anisotropy for shape-invariant
 * kinds; for GTR (shape-variant) the closest analogue, which keeps the area
 * of the highlight of the isotropic GTR of roughness sqrt(alpha_x alpha_y). */
MF_INLINE mf_ndf mf_gtr_anisotropic(mf_real alpha_x, mf_real alpha_y, mf_real gamma)
{
    mf_real ax = mf_min(mf__clamp_alpha(alpha_x), MF_R(1.0)), ay = mf_min(mf__clamp_alpha(alpha_y), MF_R(1.0));
    mf_real a = MF_SQRT(ax * ay);
    return mf_transformed(mf_gtr(a, gamma), mf_mat2_make(a / ax, MF_R(0.0), MF_R(0.0), a / ay));
}

/* D of the untransformed distribution, homogeneous of degree -4 in wm: the
 * inline kinds (GGX, Beckmann) inline, the others through the dispatch
 * (05_ndf.h). */
MF_FORCE_INLINE mf_real mf__D_base(const mf_ndf *d, mf_vec3 wm)
{
    return mf__ndf_D_inline(d, wm);
}

/* D(wm), 1/sr; 0 if wm.z <= 0. Transformed kinds by Eq. 4.14. */
MF_FORCE_INLINE mf_real mf_D(const mf_ndf *d, mf_vec3 wm)
{
    mf_real r;
    if (!d->transformed) return mf__D_base(d, wm);
    /* |det M| |M^T m|^-4 D(M^T m / |M^T m|) = |det M| mf__D_base(M^T m),
     * capped at MF_BIG (a small M makes |M^T m|^-4 overflow) */
    r = mf__ndf_det(d) * mf__D_base(d, mf_mat2_apply_transpose(d->M, wm));
    return mf__cap(r);
}

/* Deformation tracking (thesis Sec. 4.4.1). The tension matrix T = D R^-1 maps
 * the edges of a rest triangle to those of its deformed state, both expressed
 * in the triangle's orthonormal tangent frame (U along the texture u axis,
 * V along the orthogonalized texture v axis);
 * use it as M in mf_transformed with the shading frame's x axis along U.
 * rest_edges and deformed_edges hold the two edge vectors as columns. */
MF_INLINE mf_result mf_tension_matrix(mf_mat2 rest_edges, mf_mat2 deformed_edges, mf_mat2 *T)
{
    mf_mat2 Ri;
    if (!T) return MF_ERROR_INVALID_ARGUMENT;
    if (!mf_transform_is_valid(rest_edges) || !mf_transform_is_valid(deformed_edges)) return MF_ERROR_INVALID_DATA;
    Ri = mf_mat2_inverse(rest_edges);
    *T = mf_mat2_mul(deformed_edges, Ri);
    return MF_SUCCESS;
}

/* Edges p1 - p0 and p2 - p0 of a triangle in its orthonormal tangent frame
 * (U, V): U along dP/du, V the part of dP/dv orthogonal to U (texture
 * coordinates uv = {u0, v0, u1, v1, u2, v2}), so the frame follows the
 * texture, not the winding. */
MF_INLINE mf_result mf__triangle_edges(const mf_vec3 p[3], const mf_real uv[6], mf_mat2 *E)
{
    mf_vec3 e1 = mf_add(p[1], mf_scale(p[0], MF_R(-1.0))), e2 = mf_add(p[2], mf_scale(p[0], MF_R(-1.0)));
    mf_real du1 = uv[2] - uv[0], dv1 = uv[3] - uv[1], du2 = uv[4] - uv[0], dv2 = uv[5] - uv[1];
    mf_real det = du1 * dv2 - du2 * dv1;
    mf_vec3 U, V;
    if (!(MF_FABS(det) > MF_R(0.0)) || !(MF_FABS(det) < MF_BIG)) return MF_ERROR_INVALID_DATA;
    /* [e1 e2] = [dP/du dP/dv] [du1 du2; dv1 dv2] */
    /* dP/du and dP/dv up to the factor 1/det, whose sign matters */
    U = mf_add(mf_scale(e1, dv2), mf_scale(e2, -dv1));
    V = mf_add(mf_scale(e2, du1), mf_scale(e1, -du2));
    if (det < MF_R(0.0)) { U = mf_scale(U, MF_R(-1.0)); V = mf_scale(V, MF_R(-1.0)); }
    U = mf_normalize(U);
    V = mf_normalize(mf_add(V, mf_scale(U, -mf_dot(V, U))));
    if (mf_dot(U, U) == MF_R(0.0) || mf_dot(V, V) == MF_R(0.0)) return MF_ERROR_INVALID_DATA;
    *E = mf_mat2_make(mf_dot(e1, U), mf_dot(e2, U), mf_dot(e1, V), mf_dot(e2, V));
    return MF_SUCCESS;
}

/* Tension matrix of a triangle from its rest and deformed vertex positions
 * and its texture coordinates (shared by both states). */
MF_INLINE mf_result mf_tension_from_triangles(const mf_vec3 rest[3], const mf_vec3 deformed[3],
                                              const mf_real uv[6], mf_mat2 *T)
{
    mf_mat2 R, D;
    mf_result r;
    if (!rest || !deformed || !uv || !T) return MF_ERROR_INVALID_ARGUMENT;
    r = mf__triangle_edges(rest, uv, &R);
    if (r != MF_SUCCESS) return r;
    r = mf__triangle_edges(deformed, uv, &D);
    if (r != MF_SUCCESS) return r;
    return mf_tension_matrix(R, D, T);
}

/* Jacobian of a nonlinear map (u, v) -> map(u, v) by central differences of
 * step h: the local linear transform of Fig. 4.2 (bottom right). */
typedef void (*mf_map2_fn)(mf_real u, mf_real v, mf_real out[2], void *ctx);
MF_INLINE mf_mat2 mf_jacobian_2d(mf_map2_fn map, void *ctx, mf_real u, mf_real v, mf_real h)
{
    mf_real a[2], b[2], c[2], e[2];
    map(u + h, v, a, ctx); map(u - h, v, b, ctx);
    map(u, v + h, c, ctx); map(u, v - h, e, ctx);
    return mf_mat2_make((a[0] - b[0]) / (MF_R(2.0) * h), (c[0] - e[0]) / (MF_R(2.0) * h),
                        (a[1] - b[1]) / (MF_R(2.0) * h), (c[1] - e[1]) / (MF_R(2.0) * h));
}
