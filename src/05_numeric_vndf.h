/* ======================================================================== */
/* == 5b. Numerical visible-normal sampling of the heavy-tailed kinds       */
/* ======================================================================== */
/* An exact inversion of the distribution of visible normals for isotropic
 * kinds known through their NDF-sampling CDF (GTR, Student-t; the fallback of
 * their rejection samplers after 64 proposals, and under test): the marginal
 * of the D-cos mass by Gauss-Legendre panels, the azimuth given theta in
 * closed form (see mf__iso_sample_visible). Cold. It precedes the kinds,
 * which fall back on it, and reaches their CDF through the trait ISO
 * (mf__ndf_iso_tan2 and the others, declared in 05_ndf.h, defined with the
 * dispatch in 07_ndf_dispatch.h): no module circle. */
/* @api */
/* wm with density D_w(wm) for the view w of any length (w.z >= 0), of the
 * kind d stretched by (ax, ay) (GTR: 1, 1; Student-t: its roughness). */
MF_COLD mf_vec3 mf__iso_sample_visible_view(const mf_ndf *d, mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2);
/* The same for the untransformed d itself, stretched as its trait ISO says
 * (1: not, 2: by (ax, ay)); the zero vector for a kind without the trait. */
MF_INLINE mf_vec3 mf__iso_sample_visible_kind(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    int s = mf__ndf_iso(d->type) == 2;
    return mf__iso_sample_visible_view(d, s ? d->ax : MF_R(1.0), s ? d->ay : MF_R(1.0), w, u1, u2);
}
/* @cold */
/* The NDF-CDF inversion of an isotropic kind sampled numerically (trait ISO
 * of 05_ndf.h; GTR with its alpha, Student-t with unit roughness, stretched
 * by the caller): t is the D-cos mass from the pole (theta = 0) to theta, q =
 * 1 - t the mass beyond; both are passed so each end stays accurate. Returns
 * tan^2(theta). */
MF_INLINE mf_real mf__iso_tan2(const mf_ndf *d, mf_real t, mf_real q) { return mf__ndf_iso_tan2(d, t, q); }
/* Mass of D cos beyond the polar angle whose tan^2 is tan2 (inverse of the above). */
MF_INLINE mf_real mf__iso_tail(const mf_ndf *d, mf_real tan2) { return mf__ndf_iso_tail(d, tan2); }
/* Exponent p of the substitution q = qc (1 - s^2)^p: it must cancel the tail
 * tan(theta) ~ q^-beta (GTR: beta = 1/2 at every gamma; Student-t:
 * beta = 1/(2 gamma - 2)), p = 2 / (1 - beta). */
MF_INLINE mf_real mf__iso_p(const mf_ndf *d) { return mf__ndf_iso_p(d); }

/* State of the numerical VNDF sampler for one view (see mf__iso_sample_visible). */
typedef struct mf__iso_vis {
    const mf_ndf *d;
    mf_real tv;        /* tan(theta_v) */
    mf_real tc, qc;    /* D-cos mass inside / beyond theta_c = pi/2 - theta_v */
} mf__iso_vis;

/* Visible-normal weight over the D-cos CDF coordinate beyond theta_c, in the
 * variable s in [0,1] with q = qc (1 - s^2)^p: per unit of D-cos mass, D_w
 * integrated over phi is cos(theta_v) psi(theta), psi = (phi0 + sqrt(T^2-1))/pi,
 * T = tan(theta_v) tan(theta), phi0 = acos(-1/T) (psi = 1 for T <= 1); this
 * returns psi dt/ds. The substitution makes it smooth at both ends: ~s^3 at
 * theta_c, and tan(theta) ~ q^-beta is cancelled at the horizon. */
MF_INLINE mf_real mf__iso_vis_h(const mf__iso_vis *v, mf_real s, mf_real *t_out, mf_real *q_out)
{
    const mf_ndf *d = v->d;
    mf_real p = mf__iso_p(d), s2 = s * s, l = MF_LOG1P(-s2);
    mf_real q = v->qc * MF_EXP(p * l), t = v->tc - v->qc * MF_EXPM1(p * l);   /* each accurate at its end */
    mf_real T2, psi = MF_R(1.0);
    *t_out = t; *q_out = q;
    if (!(q > MF_R(0.0)) || !(s2 < MF_R(1.0))) return MF_R(0.0);
    T2 = v->tv * v->tv * mf__iso_tan2(d, t, q);
    if (T2 > MF_R(1.0)) {
        mf_real T = MF_SQRT(T2);
        psi = (MF_ACOS(-MF_R(1.0) / T) + MF_SQRT(T2 - MF_R(1.0))) * MF_INV_PI;
    }
    /* -dq/ds = p q 2 s / (1 - s^2) */
    return psi * p * q * MF_R(2.0) * s / (MF_R(1.0) - s2);
}

/* Exact visible-normal sampling for an isotropic distribution known through its
 * NDF-sampling CDF (mf__iso_tan2 / mf__iso_tail). The visible density over
 * (D-cos mass t, phi) factors into a marginal in t and phi given t:
 *   - inside theta_c = pi/2 - theta_v every azimuth faces the viewer and the
 *     marginal is the constant cos(theta_v): t is linear there (analytic);
 *   - beyond it the marginal cos(theta_v) psi is integrated on 8 panels (4 in
 *     float builds) of 8 Gauss-Legendre nodes: 64 (32) evaluations, relative
 *     error of the total measured below 2e-6 (6e-6) over GTR and Student-t
 *     parameters, typically 1e-9 (1e-7); inside the chosen panel the CDF of the Legendre
 *     interpolant through the same nodes is inverted by safeguarded Newton, so
 *     no further evaluation is needed;
 *   - phi given theta has density max(0, cot(theta_v) cot(theta) + cos(phi)).
 * cv, sv: cos and sin of the view's polar angle, the view along +x. Returns wm
 * in that frame. */
#ifdef MF_USE_DOUBLE
#define MF__ISO_PANELS 8   /* total mass to ~1e-8 relative */
#else
#define MF__ISO_PANELS 4   /* total mass to ~1e-5 relative, below float's sampling resolution */
#endif
MF_INLINE mf_vec3 mf__iso_sample_visible(const mf_ndf *d, mf_real cv, mf_real sv, mf_real u1, mf_real u2)
{
    mf_real hv[MF__ISO_PANELS][MF__GL_N], cum[MF__ISO_PANELS + 1];
    mf_real target, t, q, tan2, cphi, c2, ct, st, phi, tan2c;
    mf__iso_vis v;
    int k, i;
    u1 = mf_clamp(u1, MF_R(0.0), MF_R(1.0));
    if (!(sv > MF_R(1e-7) * cv)) {            /* normal incidence: the NDF-cos sampler */
        tan2 = mf__iso_tan2(d, u1, MF_R(1.0) - u1);
        cphi = MF_R(1e30);
    } else {
        v.d = d;
        v.tv = sv / mf_max(cv, MF_R(1e-30));
        tan2c = cv / sv; tan2c *= tan2c;
        v.qc = mf__iso_tail(d, tan2c);
        v.tc = MF_R(1.0) - v.qc;
        cum[0] = v.tc;                        /* masses in units of cos(theta_v) */
        for (k = 0; k < MF__ISO_PANELS; ++k) {
            mf_real sum = MF_R(0.0);
            for (i = 0; i < MF__GL_N; ++i) {
                mf_real s = mf__gl_node01(k, i, MF__ISO_PANELS);
                hv[k][i] = mf__iso_vis_h(&v, s, &t, &q);
                sum += mf__gl_w(i) * hv[k][i];
            }
            cum[k + 1] = cum[k] + sum / (mf_real)MF__ISO_PANELS;
        }
        target = u1 * cum[MF__ISO_PANELS];
        if (target <= v.tc) {
            t = target;
            q = MF_R(1.0) - t;
        } else {
            mf_real a[MF__GL_N], P[MF__GL_N + 1], lo = MF_R(-1.0), hi = MF_R(1.0), x, rem, width;
            int n;
            for (k = 0; k < MF__ISO_PANELS - 1 && cum[k + 1] < target; ++k) {}
            width = MF_R(1.0) / (mf_real)MF__ISO_PANELS;
            rem = (target - cum[k]) / width;     /* in units of the panel's own variable */
            /* Legendre coefficients of the interpolant: a_n = (2n+1) sum_i w_i h_i P_n(xi_i) */
            for (n = 0; n < MF__GL_N; ++n) a[n] = MF_R(0.0);
            for (i = 0; i < MF__GL_N; ++i) {
                mf__legendre(mf__gl_xi(i), P);
                for (n = 0; n < MF__GL_N; ++n) a[n] += mf__gl_w(i) * hv[k][i] * P[n];
            }
            for (n = 0; n < MF__GL_N; ++n) a[n] *= (mf_real)(2 * n + 1);
            x = MF_R(2.0) * mf_clamp(rem / mf_max((cum[k + 1] - cum[k]) / width, MF_R(1e-30)), MF_R(0.0), MF_R(1.0)) - MF_R(1.0);
            for (i = 0; i < 50; ++i) {
                /* F(x) = integral over [-1, x] of the interpolant / 2; F' = h(x) / 2 */
                mf_real F, dF = MF_R(0.0);
                mf__legendre(x, P);
                F = a[0] * (x + MF_R(1.0));
                for (n = 1; n < MF__GL_N; ++n) F += a[n] * (P[n + 1] - P[n - 1]) / (mf_real)(2 * n + 1);
                for (n = 0; n < MF__GL_N; ++n) dF += a[n] * P[n];
                if (mf__newton_step(&x, MF_R(0.5) * F - rem, MF_R(0.5) * dF, &lo, &hi, MF_R(8.0) * MF_EPS)) break;
            }
            MF__SOLVER_DONE(MF__SITE_NUM_VNDF, i, 50);
            mf__iso_vis_h(&v, ((mf_real)k + MF_R(0.5) + MF_R(0.5) * x) * width, &t, &q);
        }
        tan2 = mf__iso_tan2(d, t, q);
        /* phi | theta: max(0, cv cos(theta) + sv sin(theta) cos(phi)) -> c = 1/(tv tan) */
        cphi = tan2 > MF_R(0.0) ? MF_R(1.0) / (v.tv * MF_SQRT(tan2)) : MF_R(1e30);
    }
    /* the heaviest tails put visible mass beyond tan = 1e15 (Student-t gamma
     * 1.55: ~10%): those normals keep tan = 1e15, so none is horizontal (z = 0,
     * density 0); every reflection about them points below the horizon anyway */
    tan2 = mf_min(tan2, MF_R(1e30));
    c2 = MF_R(1.0) / (MF_R(1.0) + tan2); ct = MF_SQRT(c2); st = MF_SQRT(tan2) * ct;
    phi = mf__sample_phi_cos(cphi, u2);
    return mf_vec3_make(st * MF_COS(phi), st * MF_SIN(phi), ct);
}

MF_COLD mf_vec3 mf__iso_sample_visible_view(const mf_ndf *d, mf_real ax, mf_real ay, mf_vec3 w, mf_real u1, mf_real u2)
{
    mf_real cv, sv, cp, sp;
    mf_vec3 m;
    if (w.z < MF_R(0.0) || !mf__ndf_iso(d->type)) return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    mf__stretch_view(ax, ay, w, &cv, &sv, &cp, &sp);
    m = mf__iso_sample_visible(d, cv, sv, u1, u2);
    return mf_normalize(mf_vec3_make(ax * (cp * m.x - sp * m.y), ay * (sp * m.x + cp * m.y), m.z));
}
