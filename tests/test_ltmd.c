/* Linearly transformed microsurfaces (thesis ch. 4), by numerical integration
 * and chi-square, for every distribution under random invertible M (entries in
 * (-10, 10)) and near-singular M (condition number ~1e3):
 *   normalization (Eq. 3.5), masking constraint (Eq. 3.9) for views up to 89
 *   degrees, integral of D_visible, chi-square of both samplers, the BRDF.
 * Tolerances as in test_ndf: 1e-7 relative in double where the base is exact
 * (measured ~1e-9); GTR at non-integer gamma carries its spline error (6%,
 * the gamma < 1 bound of test_ndf);
 * float builds 2e-4 (1e-3 for near-singular M, whose inverse loses digits).
 * Also: diagonal M on shape-invariant kinds equals elliptical anisotropy
 * (Eq. 4.22-4.23); stretch matrix properties (Eq. 4.25); composition;
 * identity costs nothing; invalid M rejected; tension matrix of a known
 * deformation (its rotation-free part, as both frames follow the texture u
 * axis); the Jacobian of a nonlinear map. */
#include "mf_test.h"
#include "quad.h"
#include <stdlib.h>

static mf_mat2 random_M(mft_rng *r, int near_singular)
{
    mf_mat2 M;
    do {
        M = mf_mat2_make((mf_real)(20 * mft_u01(r) - 10), (mf_real)(20 * mft_u01(r) - 10),
                         (mf_real)(20 * mft_u01(r) - 10), (mf_real)(20 * mft_u01(r) - 10));
        if (near_singular) {   /* second row = t * first row + a small perturbation */
            double t = 2 * mft_u01(r) - 1, e = 0.01 * (mft_u01(r) + 0.5);
            M.m10 = (mf_real)(t * M.m00 + e * M.m01);
            M.m11 = (mf_real)(t * M.m01 - e * M.m00);
        }
    } while (fabs((double)mf_mat2_det(M)) < 1e-3);
    return M;
}

static void integrals(const char *name, const mf_ndf *d, int spline, int near_singular)
{
    const double thetas[] = { 0.3, 1.0, 1.5533 };
    char msg[400];
    int j;
    double tol = spline ? 0.06 : near_singular ? MFT_TOL(1e-7, 1e-3) : MFT_TOL(1e-7, 2e-4);
    snprintf(msg, sizeof msg, "transformed normalization %s", name);
    MFT_NEAR(mft_norm_integral(d), 1.0, near_singular ? MFT_TOL(1e-7, 1e-3) : MFT_TOL(1e-7, 2e-4), 0.0, msg);
    for (j = 0; j < 3; ++j) {
        mf_vec3 v = mft_dir(thetas[j], 0.8 + 2.1 * j);
        double area = mft_visible_integral(d, v, 0);
        snprintf(msg, sizeof msg, "transformed masking constraint %s theta=%.3f", name, thetas[j]);
        MFT_NEAR(area / ((double)v.z * (1.0 + mf_lambda(d, v))), 1.0, tol, 0.0, msg);
        snprintf(msg, sizeof msg, "transformed integral D_visible %s theta=%.3f", name, thetas[j]);
        MFT_NEAR(mft_visible_integral(d, v, 1), 1.0, tol, 0.0, msg);
    }
}

static void test_random_transforms(void)
{
    static const mft_case bases[] = {
        { "beckmann 0.2x0.4", MF_NDF_BECKMANN, 0.2, 0.4, 0 },
        { "ggx 0.3", MF_NDF_GGX, 0.3, 0.3, 0 },
        { "gtr 0.3 g1", MF_NDF_GTR, 0.3, 0.3, 1.0 },
        { "gtr 0.5 g3", MF_NDF_GTR, 0.5, 0.5, 3.0 },
        { "gtr 0.4 g1.7", MF_NDF_GTR, 0.4, 0.4, 1.7 },
        { "student 0.3x0.15 g3", MF_NDF_STUDENT_T, 0.3, 0.15, 3.0 },
    };
    mft_rng r;
    int b, k;
    char name[160];
    const char *only = getenv("MFT_CASE");
    mft_seed(&r, 4242);
    for (b = 0; b < 6; ++b) {
        int slow = bases[b].kind == MF_NDF_GTR || bases[b].kind == MF_NDF_STUDENT_T;
        for (k = 0; k < 3; ++k) {
            int ns = k == 2, spline;
            mf_mat2 M = random_M(&r, ns);
            mft_case c = bases[b];
            mf_ndf d;
            if (k == 1) {   /* random parameters of the same kind */
                double f = 0.5 + mft_u01(&r);
                c.ax *= f; c.ay *= 0.5 + mft_u01(&r);
                if (c.kind == MF_NDF_GTR) { c.ay = c.ax; c.gamma = 0.5 + 3.4 * mft_u01(&r); }
                if (c.kind == MF_NDF_STUDENT_T) c.gamma = 1.7 + 6.0 * mft_u01(&r);
            }
            spline = c.kind == MF_NDF_GTR && fabs(c.gamma - floor(c.gamma + 0.5)) > 1e-9;
            d = mf_transformed(mft_make(&c), M);
            if (only && !strstr(bases[b].name, only)) continue;
            snprintf(name, sizeof name, "%s a=%.3f,%.3f g=%.3f M=[%.2f %.2f; %.2f %.2f]", bases[b].name, c.ax, c.ay, c.gamma,
                     (double)M.m00, (double)M.m01, (double)M.m10, (double)M.m11);
            MFT_CHECK(d.transformed == 1, "random M accepted");
            if (mft_full || (b + k) % 2 == 0) integrals(name, &d, spline, ns);   /* make test: half of them */
            mft_sampler_check(name, &d, mf_vec3_make(0, 0, 1), 0, slow ? 30000 : 100000, 0, 900 + 10 * b + k);
            mft_sampler_check(name, &d, mft_dir(0.4 + 0.5 * k, 1.0 + k), 1, slow ? 30000 : 100000, spline, 950 + 10 * b + k);
            if (k == 0) mft_brdf_check(name, d, mft_dir(0.7, 2.0), slow ? 20000 : 60000, 990 + b, spline);
        }
    }
}

static void test_properties(void)
{
    mft_rng r;
    int i, k, bad;
    double worst;
    mft_seed(&r, 77);
    /* diagonal M on shape-invariant kinds = elliptical anisotropy (Eq. 4.22) */
    for (k = 0; k < 3; ++k) {
        mf_real a = MF_R(0.3), ax = MF_R(0.12), ay = MF_R(0.45);
        mf_mat2 M = mf_mat2_make(a / ax, 0, 0, a / ay);
        mf_ndf t = k == 0 ? mf_transformed(mf_ggx(a, a), M) : k == 1 ? mf_transformed(mf_beckmann(a, a), M)
                                                             : mf_transformed(mf_student_t(a, a, MF_R(2.5)), M);
        mf_ndf e = k == 0 ? mf_ggx(ax, ay) : k == 1 ? mf_beckmann(ax, ay) : mf_student_t(ax, ay, MF_R(2.5));
        worst = 0.0;
        for (i = 0; i < 200; ++i) {
            mf_vec3 m = mf_sample_D(&e, (mf_real)mft_u01(&r), (mf_real)mft_u01(&r));
            mf_vec3 v = mft_dir(1.55 * mft_u01(&r), 6.283 * mft_u01(&r));
            double e1 = fabs(mf_D(&t, m) / mf_D(&e, m) - 1.0);
            double e2 = fabs((1.0 + mf_lambda(&t, v)) / (1.0 + mf_lambda(&e, v)) - 1.0);
            if (e1 > worst) worst = e1;
            if (e2 > worst) worst = e2;
        }
        MFT_CHECK(worst < MFT_TOL(1e-12, 2e-5), k == 0 ? "diagonal M = elliptical anisotropy (GGX)"
                                              : k == 1 ? "diagonal M = elliptical anisotropy (Beckmann)"
                                                       : "diagonal M = elliptical anisotropy (Student-t)");
    }
    /* stretch matrices (Eq. 4.25) */
    bad = 0;
    for (i = -9; i <= 9; ++i) {
        mf_real s = (mf_real)(i / 10.0);
        mf_mat2 A = mf_stretch_matrix(s), B = mf_stretch_matrix(-s), P = mf_mat2_mul(A, B);
        if (fabs((double)mf_mat2_det(A) - 1.0) > MFT_TOL(1e-14, 1e-6)) ++bad;
        if (A.m01 != A.m10) ++bad;
        if (fabs((double)P.m00 - 1) + fabs((double)P.m11 - 1) + fabs((double)P.m01) + fabs((double)P.m10) > MFT_TOL(1e-14, 1e-6)) ++bad;
    }
    {
        mf_mat2 I0 = mf_stretch_matrix(0);
        MFT_CHECK(bad == 0 && I0.m00 == 1 && I0.m11 == 1 && I0.m01 == 0, "stretch matrix: det 1, symmetric, M_0 = I, M_s^-1 = M_-s");
        MFT_CHECK(mf_stretch_matrix(MF_R(0.5)).m00 == 2 && mf_stretch_matrix(MF_R(-0.5)).m11 == 2, "stretch matrix values (Eq. 4.24)");
    }
    /* identity costs nothing, invalid M rejected, composition */
    {
        mf_ndf g = mf_gtr(MF_R(0.3), MF_R(1.7)), gi = mf_transformed(g, mf_mat2_make(1, 0, 0, 1));
        mf_ndf gs = mf_transformed(g, mf_mat2_make(1, 2, 2, 4)), gn = mf_transformed(g, mf_mat2_make(1, (mf_real)HUGE_VAL, 0, 1));
        mf_mat2 M1 = random_M(&r, 0), M2 = random_M(&r, 0);
        mf_ndf c1 = mf_transformed(mf_transformed(g, M1), M2), c2 = mf_transformed(g, mf_mat2_mul(M2, M1));
        mf_ndf back = mf_transformed(mf_stretched(g, MF_R(0.5)), mf_stretch_matrix(MF_R(-0.5)));
        mf_vec3 m = mft_dir(0.3, 1.0), v = mft_dir(1.1, 2.0);
        MFT_CHECK(gi.transformed == 0 && mf_D(&gi, m) == mf_D(&g, m), "identity transform is the base itself");
        MFT_CHECK(gs.transformed == 0 && mf_D(&gs, m) == mf_D(&g, m), "singular M rejected (base returned)");
        MFT_CHECK(!mf_transform_is_valid(mf_mat2_make(1, 2, 2, 4)) && mf_transform_is_valid(mf_mat2_make(1, 2, 3, 4)), "mf_transform_valid");
        MFT_CHECK(gn.transformed == 0 && mf_D(&gn, m) == mf_D(&g, m), "M with an infinite entry rejected (base returned)");
        MFT_NEAR(mf_D(&c1, m), mf_D(&c2, m), MFT_TOL(1e-10, 1e-4), 0, "composition: D of (M2 o M1) = D of M2 M1");
        MFT_NEAR(mf_lambda(&c1, v), mf_lambda(&c2, v), MFT_TOL(1e-10, 1e-4), 1e-7, "composition: Lambda");
        MFT_CHECK(back.transformed == 0 || fabs((double)mf_D(&back, m) / (double)mf_D(&g, m) - 1.0) < MFT_TOL(1e-12, 1e-5),
                  "stretch then inverse stretch is the base");
        {
            mf_mat2 nanm = mf_mat2_make(1, 0, 0, 1);
            nanm.m01 = (mf_real)(HUGE_VAL - HUGE_VAL);
            MFT_CHECK(mf_transformed(g, nanm).transformed == 0, "NaN entry rejected");
        }
    }
    /* anisotropic GTR through the transform */
    {
        mf_ndf a = mf_gtr_anisotropic(MF_R(0.1), MF_R(0.4), MF_R(1.5));
        MFT_CHECK(a.transformed == 1, "mf_gtr_anisotropic is a transformed GTR");
        MFT_NEAR(mft_norm_integral(&a), 1.0, MFT_TOL(1e-7, 2e-4), 0, "anisotropic GTR normalized");
    }
}

static void map_fig42(mf_real u, mf_real v, mf_real out[2], void *ctx)
{
    (void)ctx;
    out[0] = u;
    out[1] = v + MF_R(2.0) * u * u * u * u * u;   /* T(u, v) = (u, v + 2u^5), thesis Fig. 4.2 */
}

static void test_deformation(void)
{
    mft_rng r;
    int i, bad = 0;
    mft_seed(&r, 5);
    /* a known tangent-plane deformation A of a triangle placed anywhere in 3D */
    for (i = 0; i < 50; ++i) {
        mf_mat2 A = random_M(&r, 0), T;
        mf_vec3 n = mf_normalize(mf_vec3_make((mf_real)(mft_u01(&r) - .5), (mf_real)(mft_u01(&r) - .5), (mf_real)(mft_u01(&r) - .5)));
        mf_vec3 U, V, rest[3], def[3];
        mf_real uv[6];
        int k;
        { mf_basis fr_ = mf_basis_from_normal(n); U = fr_.t; V = fr_.b; }
        for (k = 0; k < 3; ++k) {
            double x = k == 0 ? 0 : 2 * mft_u01(&r) - 1, y = k == 0 ? 0 : 2 * mft_u01(&r) - 1;
            if (k == 2) { x = -y * 0.5 + 0.3; y = x + 0.7; }
            uv[2 * k] = (mf_real)(0.5 + 0.3 * x); uv[2 * k + 1] = (mf_real)(0.2 + 0.3 * y);   /* u along U, v along V */
            rest[k] = mf_add(mf_scale(U, (mf_real)x), mf_scale(V, (mf_real)y));
            def[k] = mf_add(mf_scale(U, A.m00 * (mf_real)x + A.m01 * (mf_real)y), mf_scale(V, A.m10 * (mf_real)x + A.m11 * (mf_real)y));
            rest[k] = mf_add(rest[k], mf_vec3_make(3, -1, 2));
        }
        if (mf_tension_from_triangles(rest, def, uv, &T) != MF_SUCCESS) { ++bad; continue; }
        /* Both frames keep U along the texture u axis (Sec. 4.4.1), so the
         * rotation of the deformation drops out: T is R of A = Q R
         * (Gram-Schmidt on the columns of A). */
        {
            double c0 = sqrt((double)A.m00 * A.m00 + (double)A.m10 * A.m10);
            double q0x = A.m00 / c0, q0y = A.m10 / c0, r01 = q0x * A.m01 + q0y * A.m11;
            double px = A.m01 - r01 * q0x, py = A.m11 - r01 * q0y, r11 = sqrt(px * px + py * py);
            double err = fabs(T.m00 - c0) + fabs(T.m01 - r01) + fabs((double)T.m10) + fabs(T.m11 - r11);
            if (err > MFT_TOL(1e-9, 1e-3) * (1 + c0 + r11)) {
                if (mft_verbose && bad < 3) printf("    T=[%g %g; %g %g] R=[%g %g; 0 %g]\n", (double)T.m00, (double)T.m01,
                                                   (double)T.m10, (double)T.m11, c0, r01, r11);
                ++bad;
            }
        }
    }
    MFT_CHECK(bad == 0, "tension matrix of a known deformation");
    {
        mf_vec3 p[3];
        mf_real uv[6] = { 0, 0, 1, 0, 2, 0 };
        mf_mat2 T;
        p[0] = mf_vec3_make(0, 0, 0); p[1] = mf_vec3_make(1, 0, 0); p[2] = mf_vec3_make(0, 1, 0);
        MFT_CHECK(mf_tension_from_triangles(p, p, uv, &T) == MF_ERROR_INVALID_DATA, "degenerate texture coordinates rejected");
        MFT_CHECK(mf_tension_from_triangles(p, p, NULL, &T) == MF_ERROR_INVALID_ARGUMENT, "NULL rejected");
        MFT_CHECK(mf_tension_matrix(mf_mat2_make(1, 2, 2, 4), mf_mat2_make(1, 0, 0, 1), &T) == MF_ERROR_INVALID_DATA,
                  "singular rest edges rejected");
    }
    {
        mf_mat2 J = mf_jacobian_2d(map_fig42, NULL, MF_R(0.7), MF_R(0.3), MF_R(1e-3));
        double u4 = 0.7 * 0.7 * 0.7 * 0.7;
        MFT_NEAR(J.m10, 10.0 * u4, MFT_TOL(1e-5, 2e-3), 0, "Jacobian of (u, v + 2u^5): d/du = 10 u^4");
        MFT_CHECK(fabs((double)J.m00 - 1) < 1e-4 && fabs((double)J.m11 - 1) < 1e-4 && fabs((double)J.m01) < 1e-4,
                  "Jacobian of (u, v + 2u^5): other entries");
    }
}

void test_ltmd(void)
{
    test_properties();
    test_deformation();
    test_random_transforms();
}
