/* @api */
/* ======================================================================== */
/* == 13b. LTC light shapes: ellipses, disks, lines, tubes, textured quads  */
/* ======================================================================== */
/* Heitz & Hill 2017 (disks, lines: "Real-Time Line- and Disk-Light Shading
 * with Linearly Transformed Cosines", SIGGRAPH course; "Linear-Light Shading
 * with LTC", GPU Zen) and Heitz et al. 2016 Sec. 5.3 (textured polygons).
 * Every shape is integrated in the cosine space of the LTC: points move by
 * M^-1, an ellipse stays an ellipse and a line stays a line. Positions are
 * relative to the shading point, in the frame of the LTC (z = normal). Bad
 * input (NaN, zero axes, a light through the shading point) gives 0. */

/* The cone from the origin through the ellipse c + u cos t + v sin t: w is
 * inside when w = s (c + a u + b v), s > 0, a^2 + b^2 <= 1. With B = [u v c]
 * and its cofactor rows n1 = v x c, n2 = c x u, n3 = u x v (B^-1 = rows / det B),
 * its dual quadric is P = B diag(1, 1, -1) B^T = u u^T + v v^T - c c^T, of
 * eigenvalues p1, p2 > 0 > p3 (Sylvester); the eigenvector of p3 is the axis
 * of the (right, elliptic) cone, whose half-angle tangents are
 * sqrt(p1 / -p3) and sqrt(p2 / -p3). The cosine form factor of a right
 * elliptic cone of tangents t1, t2 about its axis is
 * t1 t2 / sqrt((1 + t1^2)(1 + t2^2)) (the disk of radius t: t^2 / (1 + t^2),
 * sin^2 of its half-angle), which with p1 p2 p3 = det P = -(det B)^2 and
 * p1 + p2 = tr P - p3 is
 *   |det B| / sqrt(2 |p3|^3 + p3^2 tr P + (det B)^2),
 * free of p1 and p2. p3 is the single negative root of the characteristic
 * cubic x^3 - tr x^2 + e2 x + (det B)^2 (e2 = |n3|^2 - |n1|^2 - |n2|^2,
 * Cauchy-Binet), found by Newton's method from below (-|c|^2 <= p3: the
 * iterates rise monotonically, the cubic being concave there), so that small
 * and huge ellipses keep their relative accuracy. Heitz & Hill 2017 reach the
 * same cone through the ellipse's principal axes and a cubic of their own. */
MF__LTC_RARE mf_real mf__ellipse_cone(mf_vec3 c, mf_vec3 u, mf_vec3 v, mf_vec3 *axis, mf_real *pm)
{
    mf_real s = mf_max(mf_max(mf_dot(c, c), mf_dot(u, u)), mf_dot(v, v)), det, tr, e2, d2, x, f, df, den, ff;
    mf_vec3 n1, n2, n3, r0, r1, r2, a0, a1, a2;
    mf_real P[6];   /* xx yy zz xy xz yz */
    int i;
    *axis = mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    if (!(s > MF_R(0.0)) || !(s < MF_BIG)) return MF_R(0.0);
    s = MF_R(1.0) / MF_SQRT(s);   /* the form factor is scale-free: largest length 1 */
    c = mf_scale(c, s); u = mf_scale(u, s); v = mf_scale(v, s);
    n1 = mf_cross(v, c); n2 = mf_cross(c, u); n3 = mf_cross(u, v);
    det = mf_dot(c, n3);
    d2 = det * det;
    if (!(d2 > MF_R(0.0))) return MF_R(0.0);   /* edge-on, or degenerate axes */
    tr = mf_dot(u, u) + mf_dot(v, v) - mf_dot(c, c);
    e2 = mf_dot(n3, n3) - mf_dot(n1, n1) - mf_dot(n2, n2);
    x = -mf_dot(c, c);
    for (i = 0; i < 60; ++i) {
        f = ((x - tr) * x + e2) * x + d2;
        df = (MF_R(3.0) * x - MF_R(2.0) * tr) * x + e2;
        if (!(df > MF_R(0.0))) break;
        den = f / df;
        if (!(den < MF_R(0.0))) break;      /* at (or, rounded, past) the root */
        x -= den;
        if (!(x < MF_R(0.0))) return MF_R(0.0);
        if (-den <= MF_R(4.0) * MF_EPS * -x) break;
    }
    x = mf_min(x, -MF_EPS * MF_EPS);
    den = MF_R(2.0) * -x * x * x + x * x * tr + d2;
    if (!(den > MF_R(0.0))) return MF_R(0.0);
    ff = MF_FABS(det) / MF_SQRT(den);
    /* the axis: null vector of P - p3 I, the largest cross product of two rows */
    P[0] = u.x * u.x + v.x * v.x - c.x * c.x - x; P[1] = u.y * u.y + v.y * v.y - c.y * c.y - x;
    P[2] = u.z * u.z + v.z * v.z - c.z * c.z - x; P[3] = u.x * u.y + v.x * v.y - c.x * c.y;
    P[4] = u.x * u.z + v.x * v.z - c.x * c.z; P[5] = u.y * u.z + v.y * v.z - c.y * c.z;
    r0 = mf_vec3_make(P[0], P[3], P[4]); r1 = mf_vec3_make(P[3], P[1], P[5]); r2 = mf_vec3_make(P[4], P[5], P[2]);
    a0 = mf_cross(r0, r1); a1 = mf_cross(r1, r2); a2 = mf_cross(r2, r0);
    if (mf_dot(a1, a1) > mf_dot(a0, a0)) a0 = a1;
    if (mf_dot(a2, a2) > mf_dot(a0, a0)) a0 = a2;
    if (!(mf_dot(a0, a0) > MF_R(0.0))) a0 = c;
    a0 = mf_normalize(a0);
    /* inside the cone: on the side of the ellipse's plane where c is */
    if (mf_dot(a0, n3) * det < MF_R(0.0)) a0 = mf_scale(a0, MF_R(-1.0));
    *axis = a0;
    if (pm) {   /* P - p3 I (xx yy zz xy xz yz), p3, det P = -(det B)^2 and the
                 * scale s^2 of P, for the principal frame */
        for (i = 0; i < 6; ++i) pm[i] = P[i];
        pm[6] = x;
        pm[7] = d2;
        pm[8] = s * s;
    }
    return mf_min(ff, MF_R(1.0));
}

/* Vector form factor of the ellipse c + u cos t + v sin t (not clipped; the
 * disk of radius r: u, v orthogonal of length r): F.z is its cosine form
 * factor, |F| and F / |F| feed mf_sphere_form_factor. As for polygons, the
 * front face is the one seen counterclockwise (u x v towards the shading
 * point); F points away from a back face. */
MF_INLINE mf_vec3 mf_ellipse_vector_form_factor(mf_vec3 c, mf_vec3 u, mf_vec3 v)
{
    mf_vec3 a;
    mf_real ff = mf__ellipse_cone(c, u, v, &a, 0);
    if (mf_dot(c, mf_cross(u, v)) > MF_R(0.0)) ff = -ff;
    return mf_scale(a, ff);
}

/* Integral of D over the ellipse (Heitz & Hill 2017): its vector form factor
 * in the cosine space, exact (the cone's F.z) when the transformed ellipse
 * lies above the horizon, the horizon-clipped sphere of the same vector form
 * factor (mf_sphere_form_factor) when it crosses it, 0 below. */
MF_INLINE mf_real mf_ltc_integrate_ellipse(const mf_ltc *l, mf_vec3 center, mf_vec3 axis_u, mf_vec3 axis_v,
                                           int two_sided)
{
    mf_vec3 c = mf__mat3_apply(l->Minv, center), u = mf__mat3_apply(l->Minv, axis_u), v = mf__mat3_apply(l->Minv, axis_v), a;
    mf_real ez = MF_SQRT(u.z * u.z + v.z * v.z), ff;
    if (!two_sided && !(mf_dot(c, mf_cross(u, v)) < MF_R(0.0))) return MF_R(0.0);   /* back face */
    if (!(c.z + ez > MF_R(0.0))) return MF_R(0.0);                                  /* below (or NaN) */
    ff = mf__ellipse_cone(c, u, v, &a, 0);
    if (c.z - ez >= MF_R(0.0)) return mf_max(ff * a.z, MF_R(0.0));
    return mf_sphere_form_factor(mf_scale(a, ff));
}

/* h(z) = atanh(sqrt z) / sqrt z (0 < z < 1), atan(sqrt -z) / sqrt -z (z < 0),
 * 1 at 0; omz = 1 - z, given without cancellation:
 * atanh(r) = log(1 + r) - log(1 - r^2) / 2 */
MF_INLINE mf_real mf__atanh_ratio(mf_real z, mf_real omz)
{
    mf_real r;
    if (MF_FABS(z) < MF_R(1e-2))   /* 1 + z/3 + z^2/5 + ...: the rest below 1e-14 */
        return MF_R(1.0) + z * (MF_R(1.0) / MF_R(3.0) + z * (MF_R(0.2) + z * (MF_R(1.0) / MF_R(7.0) + z * (MF_R(1.0) / MF_R(9.0) + z * (MF_R(1.0) / MF_R(11.0) + z / MF_R(13.0))))));
    r = MF_SQRT(MF_FABS(z));
    return z > MF_R(0.0) ? (MF_LOG1P(r) - MF_R(0.5) * MF_LOG(omz)) / r : MF_ATAN(r) / r;
}

/* The cosine form factor of the part of the cone through the ellipse
 * c + u cos t + v sin t (cosine space) above the horizon, in closed form.
 * By Stokes, the integral of w over a spherical region is half the integral
 * of w x dw along its boundary: the visible arc of the cone, closed along
 * the horizon by a great arc (its signed angle). In the cone's principal
 * frame (axis a, e1, e2 = a x e1, half-angle tangents t1, t2, from
 * mf__ellipse_cone) the boundary is Q = a + t1 cos f e1 + t2 sin f e2, and
 *   (Q x Q').z / |Q|^2 = (t1 t2 a.z - t2 e1.z cos f - t1 e2.z sin f) / (A cos^2 f + B sin^2 f),
 * A = 1 + t1^2, B = 1 + t2^2, whose three terms integrate to
 *   atan(sqrt(B / A) tan f) / sqrt(A B),  s / A h((A - B) s^2 / A) (s = sin f),
 *   -c / B h((B - A) c^2 / B) (c = cos f)
 * (h: mf__atanh_ratio); the first is unwrapped as f + the angle between f
 * and atan(sqrt(B / A) tan f), continuous. Exact up to rounding: double
 * 1e-13, float 1e-5 of |F| in the tests. */
MF__LTC_RARE mf_real mf__ellipse_clipped(mf_vec3 c, mf_vec3 u, mf_vec3 v)
{
    mf_vec3 a, b1, b2, e1, e2, x0, x1;
    mf_real pm[9], ff = mf__ellipse_cone(c, u, v, &a, pm), s11, s12, s22, th, A, B, t1, t2, X, Y, R, ph, be, f0, f1, k, sum, j0;
    if (!(ff > MF_R(0.0))) return MF_R(0.0);
    { mf_basis fr_ = mf_basis_from_normal(a); b1 = fr_.t; b2 = fr_.b; }
    /* P - p3 I restricted to the plane normal to the axis: eigenvalues p1 - p3, p2 - p3 */
#define MF__PQ(p, q) ((p).x * (pm[0] * (q).x + pm[3] * (q).y + pm[4] * (q).z) + (p).y * (pm[3] * (q).x + pm[1] * (q).y + pm[5] * (q).z) + \
                      (p).z * (pm[4] * (q).x + pm[5] * (q).y + pm[2] * (q).z))
    s11 = MF__PQ(b1, b1); s12 = MF__PQ(b1, b2); s22 = MF__PQ(b2, b2);
    /* e1: the larger; t1^2 = p1 / -p3 with p1 = e1.P e1 from c, u, v, and
     * t2^2 = p2 / -p3 from p1 p2 p3 = det P (p - p3 would lose small t to
     * cancellation) */
    th = MF_R(0.5) * MF_ATAN2(MF_R(2.0) * s12, s11 - s22);
    e1 = mf_add(mf_scale(b1, MF_COS(th)), mf_scale(b2, MF_SIN(th)));
    e2 = mf_cross(a, e1);
#undef MF__PQ
    s11 = mf_dot(e1, u); s12 = mf_dot(e1, v); s22 = mf_dot(e1, c);
    t1 = MF_SQRT(mf_max((s11 * s11 + s12 * s12 - s22 * s22) * pm[8] / -pm[6], MF_R(0.0)));
    A = MF_R(1.0) + t1 * t1;
    if (!(t1 > MF_R(0.0))) return MF_R(0.0);
    t2 = MF_SQRT(pm[7] / (-pm[6] * pm[6] * pm[6])) / t1;
    if (!(t2 < t1)) t2 = t1;   /* rounding (t2 <= t1), or an underflow of p3^3 */
    B = MF_R(1.0) + t2 * t2;
    /* visible where Q.z = a.z + R cos(f - ph) > 0 */
    X = t1 * e1.z; Y = t2 * e2.z;
    R = MF_SQRT(X * X + Y * Y);
    if (!(R > MF_FABS(a.z))) return a.z > MF_R(0.0) ? mf_min(ff * a.z, MF_R(1.0)) : MF_R(0.0);
    ph = MF_ATAN2(Y, X);
    be = MF_ACOS(mf_clamp(-a.z / R, MF_R(-1.0), MF_R(1.0)));
    f0 = ph - be; f1 = ph + be;
    k = MF_SQRT(B / A);
    j0 = (f1 - f0 + MF_ATAN2((k - MF_R(1.0)) * MF_SIN(f1) * MF_COS(f1), MF_COS(f1) * MF_COS(f1) + k * MF_SIN(f1) * MF_SIN(f1)) -
          MF_ATAN2((k - MF_R(1.0)) * MF_SIN(f0) * MF_COS(f0), MF_COS(f0) * MF_COS(f0) + k * MF_SIN(f0) * MF_SIN(f0))) / MF_SQRT(A * B);
    sum = t1 * t2 * a.z * j0;
    {
        mf_real s0 = MF_SIN(f0), s1 = MF_SIN(f1), c0 = MF_COS(f0), c1 = MF_COS(f1), D = A - B;
        /* 1 - D s^2 / A = (A c^2 + B s^2) / A, 1 + D c^2 / B = (A c^2 + B s^2) / B */
        mf_real q0 = A * c0 * c0 + B * s0 * s0, q1 = A * c1 * c1 + B * s1 * s1;
        sum -= t2 * e1.z * (s1 * mf__atanh_ratio(D * s1 * s1 / A, q1 / A) - s0 * mf__atanh_ratio(D * s0 * s0 / A, q0 / A)) / A;
        sum += t1 * e2.z * (c1 * mf__atanh_ratio(-D * c1 * c1 / B, q1 / B) - c0 * mf__atanh_ratio(-D * c0 * c0 / B, q0 / B)) / B;
        /* the horizon arc, from the exit point back to the entry */
        x1 = mf_add(a, mf_add(mf_scale(e1, t1 * c1), mf_scale(e2, t2 * s1)));
        x0 = mf_add(a, mf_add(mf_scale(e1, t1 * c0), mf_scale(e2, t2 * s0)));
    }
    sum += MF_ATAN2(x1.x * x0.y - x1.y * x0.x, x1.x * x0.x + x1.y * x0.y);
    sum = MF_FABS(sum) * MF_R(0.15915494309189533577);
    return sum == sum ? mf_min(sum, MF_R(1.0)) : MF_R(0.0);
}

/* The same as mf_ltc_integrate_ellipse with the horizon clipped exactly
 * (closed form, mf__ellipse_clipped) instead of by the sphere approximation:
 * about a dozen trigonometric functions more where the transformed ellipse
 * crosses the horizon. */
MF_INLINE mf_real mf_ltc_integrate_ellipse_clipped(const mf_ltc *l, mf_vec3 center, mf_vec3 axis_u, mf_vec3 axis_v,
                                                   int two_sided)
{
    mf_vec3 c = mf__mat3_apply(l->Minv, center), u = mf__mat3_apply(l->Minv, axis_u), v = mf__mat3_apply(l->Minv, axis_v), a;
    mf_real ez = MF_SQRT(u.z * u.z + v.z * v.z), ff;
    if (!two_sided && !(mf_dot(c, mf_cross(u, v)) < MF_R(0.0))) return MF_R(0.0);
    if (!(c.z + ez > MF_R(0.0))) return MF_R(0.0);
    ff = mf__ellipse_cone(c, u, v, &a, 0);
    if (c.z - ez >= MF_R(0.0)) return mf_max(ff * a.z, MF_R(0.0));
    if (!(ff > MF_R(0.0))) return MF_R(0.0);
    return mf__ellipse_clipped(c, u, v);
}

/* The same for a disk of the given center, radius and unit normal: the face
 * normal points to is the front. */
MF_INLINE mf_real mf_ltc_integrate_disk(const mf_ltc *l, mf_vec3 center, mf_vec3 normal, mf_real radius, int two_sided)
{
    mf_vec3 t, b, n;
    mf_real len = MF_SQRT(mf_dot(normal, normal));
    if (!(len > MF_R(0.0)) || !(len < MF_BIG) || !(radius > MF_R(0.0)) || !(radius < MF_BIG)) return MF_R(0.0);
    n = mf_scale(normal, MF_R(1.0) / len);
    { mf_basis fr_ = mf_basis_from_normal(n); t = fr_.t; b = fr_.b; }
    if (mf_dot(mf_cross(t, b), n) < MF_R(0.0)) b = mf_scale(b, MF_R(-1.0));   /* t x b = n */
    return mf_ltc_integrate_ellipse(l, center, mf_scale(t, radius), mf_scale(b, radius), two_sided);
}

/* Cosine-lobe integral of a line segment a b per unit width (Heitz & Hill
 * 2017 Eq. 1.20): (1/pi) int max(0, w.z) |w x T| / |p|^2 dl, clipped at the
 * horizon; d > 0 is the distance of the line from the origin. With T the
 * unit tangent, l1, l2 = p.T at the ends and p0 the line's nearest point, in
 * closed form
 *   (1/2pi) [ (p0.z/d) (l2/|b|^2 - l1/|a|^2 + theta/d) + T.z d (1/|a|^2 - 1/|b|^2) ],
 * theta = atan2(d (l2 - l1), a.b) the angle a and b subtend. (The second
 * term's antiderivative is -d / (d^2 + l^2): the chapter's Eq. 1.23 is off.) */
MF_INLINE mf_real mf__line_cosine(mf_vec3 a, mf_vec3 b, mf_real d, mf_real len)
{
    mf_vec3 e;
    mf_real l1, l2, r1, r2, tz, p0z, res;
    if (!(a.z > MF_R(0.0)) || !(b.z > MF_R(0.0))) {   /* clip (len: of the clipped segment) */
        if (!(a.z > MF_R(0.0)) && !(b.z > MF_R(0.0))) return MF_R(0.0);
        if (a.z < MF_R(0.0)) a = mf_scale(mf__vsub(mf_scale(a, b.z), mf_scale(b, a.z)), MF_R(1.0) / (b.z - a.z));
        else if (b.z < MF_R(0.0)) b = mf_scale(mf__vsub(mf_scale(b, a.z), mf_scale(a, b.z)), MF_R(1.0) / (a.z - b.z));
        e = mf__vsub(b, a);
        len = MF_SQRT(mf_dot(e, e));
    } else e = mf__vsub(b, a);
    r1 = mf_dot(a, a); r2 = mf_dot(b, b);
    if (!(len > MF_R(0.0)) || !(r1 > MF_R(0.0)) || !(r2 > MF_R(0.0))) return MF_R(0.0);
    l1 = mf_dot(a, e) / len; l2 = l1 + len; tz = e.z / len;
    p0z = a.z - l1 * tz;
    res = (p0z / d) * (l2 / r2 - l1 / r1 + MF_ATAN2(d * len, mf_dot(a, b)) / d) + tz * d * (MF_R(1.0) / r1 - MF_R(1.0) / r2);
    return mf_max(res * MF_R(0.15915494309189533577), MF_R(0.0));
}

/* Integral of D over a thin cylinder of the given radius along p1 p2 (Heitz &
 * Hill 2017): its silhouette, a strip of width 2 radius across the plane of
 * the line and the shading point (unit normal n), becomes in the cosine space
 * a strip of width 2 radius / |M^T n| (first order in the radius),
 * integrated by mf__line_cosine. With a = M^-1 p1, b = M^-1 p2,
 * a x b = det(M^-1) M^T (p1 x p2), so 1 / |M^T n| = |det M^-1| |p1 x p2| / |a x b|.
 * Exact as the radius goes to 0; the error is of first order in
 * radius / length (the cylinder's rounded ends: mf_ltc_integrate_tube). */
MF_INLINE mf_real mf_ltc_integrate_line(const mf_ltc *l, mf_vec3 p1, mf_vec3 p2, mf_real radius)
{
    mf_vec3 a = mf__mat3_apply(l->Minv, p1), b = mf__mat3_apply(l->Minv, p2), c = mf_cross(a, b), e = mf__vsub(b, a);
    mf_real cl = MF_SQRT(mf_dot(c, c)), el = MF_SQRT(mf_dot(e, e)), n = MF_SQRT(mf_dot(mf_cross(p1, p2), mf_cross(p1, p2)));
    if (!(cl > MF_R(0.0)) || !(el > MF_R(0.0)) || !(radius > MF_R(0.0)) || !(radius < MF_BIG) || !(n < MF_BIG)) return MF_R(0.0);
    return mf__cap(MF_R(2.0) * radius * l->det_inv * n / cl * mf__line_cosine(a, b, cl / el, el));
}

/* A closed tube (cylinder with flat end caps, Heitz & Hill 2017): the line
 * plus its ends. The silhouette of the closed cylinder, a convex body, is the
 * line's strip plus, at each end, the outer half of the cap disk's outline,
 * whether that cap faces the shading point or not; so each cap counts as half
 * a two-sided disk (exact ellipses), which leaves an error of second order in
 * radius / length (the line alone is of first order). */
MF_INLINE mf_real mf_ltc_integrate_tube(const mf_ltc *l, mf_vec3 p1, mf_vec3 p2, mf_real radius)
{
    mf_vec3 t = mf__vsub(p2, p1);
    mf_real line = mf_ltc_integrate_line(l, p1, p2, radius);
    if (!(line >= MF_R(0.0))) return MF_R(0.0);
    return line + MF_R(0.5) * (mf_ltc_integrate_disk(l, p1, t, radius, 1) + mf_ltc_integrate_disk(l, p2, t, radius, 1));
}

/* Textured quad light (Heitz et al. 2016 Sec. 5.3): for the parallelogram
 * q[0..3] with texture coordinates (0,0) (1,0) (1,1) (0,1) at q0 q1 q2 q3
 * (q3 = q0 + q2 - q1 assumed), the integral of D L over it is approximated
 * by mf_ltc_integrate (returned) times the prefiltered texture fetched at
 * uv[2] with level of detail *lod. uv: where the direction of the vector form
 * factor of the quad in the cosine space meets its plane (the orthogonal
 * projection of the shading point onto the plane when that ray misses it);
 * affine coordinates survive the linear map, so uv is that of the original
 * quad; it can leave [0, 1] (prefiltered textures carry a border). lod:
 * log2(tex_size r / sqrt(A)), the lobe's footprint (r, the distance to the
 * plane, in units of the quad's size sqrt(A), both in the cosine space) in
 * texels of a tex_size texture, clamped to [0, log2 tex_size]. */
MF_INLINE mf_real mf_ltc_integrate_textured(const mf_ltc *l, const mf_vec3 *q, int two_sided, mf_real tex_size,
                                            mf_real *uv, mf_real *lod)
{
    mf_vec3 p[4], e1, e2, nrm, F, x;
    mf_real g11, g12, g22, det, h, s, fn, r1, r2, fp, res;
    int i;
    if (uv) uv[0] = uv[1] = MF_R(0.5);
    if (lod) *lod = MF_R(0.0);
    if (!q) return MF_R(0.0);
    res = mf_ltc_integrate(l, q, 4, two_sided);
    for (i = 0; i < 4; ++i) p[i] = mf__mat3_apply(l->Minv, q[i]);
    e1 = mf__vsub(p[1], p[0]); e2 = mf__vsub(p[3], p[0]); nrm = mf_cross(e1, e2);
    g11 = mf_dot(e1, e1); g12 = mf_dot(e1, e2); g22 = mf_dot(e2, e2);
    det = mf_dot(nrm, nrm);   /* = g11 g22 - g12^2 */
    h = mf_dot(nrm, p[0]);    /* distance times |nrm| */
    if (!(det > MF_R(0.0)) || !(det < MF_BIG) || !(h == h)) return res;
    F = mf_polygon_vector_form_factor(p, 4);
    fn = mf_dot(F, nrm);
    s = fn != MF_R(0.0) ? h / fn : MF_R(-1.0);
    if (s > MF_R(0.0) && s < MF_BIG) x = mf_scale(F, s);
    else x = mf_scale(nrm, h / det);
    x = mf__vsub(x, p[0]);
    r1 = mf_dot(x, e1); r2 = mf_dot(x, e2);
    if (uv) {
        mf_real a = (g22 * r1 - g12 * r2) / det, b = (g11 * r2 - g12 * r1) / det;
        if (a == a && b == b && MF_FABS(a) < MF_BIG && MF_FABS(b) < MF_BIG) { uv[0] = a; uv[1] = b; }
    }
    if (lod && tex_size > MF_R(1.0) && tex_size < MF_BIG) {
        fp = MF_FABS(h) / (MF_SQRT(det) * MF_SQRT(MF_SQRT(det)));   /* r / sqrt(A) = |h| / |nrm|^(3/2) */
        fp = MF_LOG(mf_max(tex_size * fp, MF_R(1.0))) * MF_R(1.4426950408889634);
        *lod = mf_clamp(fp, MF_R(0.0), MF_LOG(tex_size) * MF_R(1.4426950408889634));
    }
    return res;
}
