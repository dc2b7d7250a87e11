/* Fuzz target: the builders on arbitrary data and sizes, then queries on what
 * they accepted. The first byte picks: mf_ibm_build_ex, mf_tabulated_build
 * followed by every generic operation, the LEADR map builders and lookups,
 * mf_microsurface_generate / mf_microsurface_integrate at small sizes (odd
 * ones included, which must be rejected). */
#include "fuzz_common.h"

#define FZ_MAXN 4096

static mf_real fz_buf[FZ_MAXN * 3];

static int fz_fill(fz_in *in, int n)
{
    int i;
    for (i = 0; i < n; ++i) fz_buf[i] = fz_real(in);
    return n;
}

/* plausible unit normals from the bytes, with a raw one now and then */
static void fz_normals(fz_in *in, int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        unsigned k = fz_u8(in);
        mf_vec3 v;
        if (k == 255u) { v.x = fz_real(in); v.y = fz_real(in); v.z = fz_real(in); }
        else v = mf_normalize(mf_vec3_make(MF_R(0.01) * (mf_real)((int)fz_u8(in) - 128), MF_R(0.01) * (mf_real)((int)fz_u8(in) - 128), MF_R(0.2) + MF_R(0.01) * (mf_real)k));
        fz_buf[3 * i] = v.x; fz_buf[3 * i + 1] = v.y; fz_buf[3 * i + 2] = v.z;
    }
}

static void fz_generic(const mf_ndf *d, fz_in *in)
{
    mf_vec3 wo = mf_normalize(mf_vec3_make(fz_real(in), fz_real(in), MF_R(1.0)));
    mf_vec3 wi = mf_normalize(mf_vec3_make(fz_real(in), fz_real(in), MF_R(1.0)));
    mf_vec3 s;
    mf_sample r;
    mf_real u1 = fz_unit(in), u2 = fz_unit(in);
    FZ_NONNEG(mf_D(d, wo), "D");
    FZ_NONNEG(mf_lambda(d, wo), "lambda");
    FZ_NONNEG(mf_G2(d, wo, wi, wo), "G2");
    FZ_NONNEG(mf_D_visible(d, wo, wi), "D_visible");
    FZ_NONNEG(mf_projected_area(d, wo), "projected_area");
    FZ_NONNEG(mf_brdf(d, wo, wi), "brdf");
    FZ_NONNEG(mf_brdf_pdf(d, wo, wi), "pdf");
    s = mf_sample_D(d, u1, u2);
    FZ_VEC(s, "sample_D");
    s = mf_sample_visible(d, wo, u1, u2);
    FZ_VEC(s, "sample_visible");
    r = mf_brdf_sample(d, wo, u1, u2);
    FZ_SAMPLE(r, "brdf_sample");
    if (r.lobe != MF_LOBE_NONE && !(mf_brdf_pdf(d, wo, r.wi) > MF_R(0.0))) FZ_FAIL("pdf of a returned sample is 0");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = { data, size };
    unsigned which = fz_u8(&in) % 5u;
    if (which == 0) {
        mf_ibm ibm;
        mf_ibm_options o;
        int w = 1 + (int)(fz_u8(&in) % 24u), h = 1 + (int)(fz_u8(&in) % 24u), res = (int)(fz_u8(&in) % 40u);
        /* raw alpha one time in 64: small alphas give up to 1024^2 bins, slow */
        unsigned am = fz_u8(&in);
        mf_real alpha = (am & 63u) == 0u ? fz_real(&in) : MF_R(0.1) + MF_R(0.004) * (mf_real)fz_u8(&in);
        unsigned cm = fz_u8(&in);
        mf_real cut = (cm & 15u) == 1u ? fz_real(&in) : (cm & 1u) ? MF_R(1.0) + MF_R(0.03) * (mf_real)fz_u8(&in) : MF_R(0.0);
        /* an arbitrary alpha or cut with Eq. 5.14's resolution reaches 1024^2
         * bins (0.5 s a build under ASan, over the 1 s limit on a busy
         * machine): give those an explicit resolution */
        if (((am & 63u) == 0u || (cm & 15u) == 1u) && res == 0) res = 1 + (int)(cm >> 2);
        o.resolution = res;
        o.cut_sigmas = cut;
        fz_normals(&in, w * h);
        if (mf_ibm_build_ex(&ibm, fz_buf, w, h, alpha, &o) == MF_SUCCESS) {
            mf_footprint f;
            mf_ibm ld;
            mf_sample r;
            size_t n = 0, m = 0;
            void *buf;
            mf_real pdf;
            mf_vec3 wo = mf_normalize(mf_vec3_make(fz_real(&in), fz_real(&in), MF_R(1.0)));
            mf_vec3 wi = mf_normalize(mf_vec3_make(fz_real(&in), fz_real(&in), MF_R(1.0)));
            if (mf_ibm_save(&ibm, NULL, 0, &n) != MF_SUCCESS || n == 0) FZ_FAIL("save size query");
            buf = malloc(n);
            if (!buf) abort();
            if (mf_ibm_save(&ibm, buf, n - 1, &m) != MF_ERROR_BUFFER_TOO_SMALL || m != n) FZ_FAIL("save into a short buffer");
            if (mf_ibm_save(&ibm, buf, n, &m) != MF_SUCCESS || m != n) FZ_FAIL("save size");
            if (mf_ibm_load(&ld, buf, n) != MF_SUCCESS) FZ_FAIL("a saved map does not load");
            mf_ibm_release(&ld);
            free(buf);
            f.u = fz_real(&in); f.v = fz_real(&in); f.ax = fz_real(&in); f.ay = fz_real(&in);
            f.bx = fz_real(&in); f.by = fz_real(&in);
            {
                int b = mf_ibm_bin_of(&ibm, wo);
                mf_real x = mf_ibm_bin_weight(&ibm, b < 0 ? 0 : b, &f);
                if (!(x >= MF_R(0.0) && x <= MF_R(1.0001))) FZ_FAIL("bin weight %g", (double)x);
            }
            FZ_NONNEG(mf_ibm_brdf_and_pdf(&ibm, &f, wo, wi, &pdf), "ibm brdf");
            FZ_NONNEG(pdf, "ibm pdf");
            r = mf_ibm_sample(&ibm, &f, wo, fz_unit(&in), fz_unit(&in), fz_unit(&in), fz_unit(&in));
            FZ_SAMPLE(r, "ibm sample");
            mf_ibm_release(&ibm);
        }
    } else if (which == 1) {
        mf_tabulated t;
        int n = (int)(fz_u8(&in) % 40u), i;
        unsigned mode = fz_u8(&in);
        mf_real *th = fz_buf, *dx = fz_buf + 64, *dy = fz_buf + 128;
        for (i = 0; i < n; ++i) {
            /* sorted angles most of the time, raw patterns otherwise */
            if (mode & 1u) th[i] = fz_real(&in);
            else th[i] = (mf_real)1.5707963267948966 * (mf_real)i / (mf_real)(n > 1 ? n - 1 : 1);
            dx[i] = (mode & 2u) ? fz_real(&in) : (mf_real)(fz_u8(&in) + 1u);
            dy[i] = (mode & 4u) ? fz_real(&in) : dx[i];
        }
        if (mf_tabulated_build(&t, th, dx, (mode & 8u) ? NULL : dy, n) == MF_SUCCESS) {
            mf_ndf d = mf_tabulated_ndf(&t);
            fz_generic(&d, &in);
            d = mf_stretched(d, fz_real(&in));
            fz_generic(&d, &in);
            mf_tabulated_release(&t);
        }
    } else if (which == 2) {
        mf_leadr_map m;
        int w = 1 << (fz_u8(&in) % 6u), h = 1 << (fz_u8(&in) % 6u), r, k;
        unsigned mode = fz_u8(&in);
        mf_real ax = fz_real(&in), ay = fz_real(&in);
        if (mode & 4u) w += 1;   /* not a power of two: rejected */
        if (mode & 1u) { fz_normals(&in, w * h); r = mf_leadr_map_from_normals(&m, fz_buf, w, h, ax, ay); }
        else { fz_fill(&in, w * h); r = mf_leadr_map_from_heights(&m, fz_buf, w, h, ax, ay); }
        if (r == MF_SUCCESS) {
            for (k = 0; k < 4; ++k) {
                mf_leadr a = mf_leadr_map_lookup(&m, fz_real(&in), fz_real(&in), fz_real(&in));
                mf_ndf d = mf_leadr_ndf(a);
                mf_vec3 wo = mf_normalize(mf_vec3_make(fz_real(&in), fz_real(&in), MF_R(1.0)));
                FZ_FIN(a.E_x, "E_x"); FZ_FIN(a.E_y, "E_y"); FZ_FIN(a.E_xx, "E_xx");
                FZ_FIN(a.E_yy, "E_yy"); FZ_FIN(a.E_xy, "E_xy");
                FZ_NONNEG(mf_D(&d, wo), "leadr D");
                FZ_NONNEG(mf_leadr_specular(a, wo, wo), "leadr specular");
            }
            mf_leadr_map_release(&m);
        }
    } else if (which == 3) {
        /* small sizes, odd ones included; few iterations */
        static mf_real hbuf[16 * 16];
        int sizes[6] = { 7, 8, 9, 15, 16, 3 };
        int s = sizes[fz_u8(&in) % 6u], it = (int)(fz_u8(&in) % 4u) - 1;
        mf_ndf d;
        switch (fz_u8(&in) % 4u) {
        case 0: d = mf_beckmann(fz_real(&in), fz_real(&in)); break;
        case 1: d = mf_ggx(fz_real(&in), fz_real(&in)); break;
        case 2: d = mf_student_t(fz_real(&in), fz_real(&in), fz_real(&in)); break;
        default: d = mf_gtr(fz_real(&in), fz_real(&in)); break;
        }
        if (mf_microsurface_generate(&d, s, it, fz_u32(&in), hbuf) == MF_SUCCESS) {
            int i;
            if (s & (s - 1)) FZ_FAIL("size %d accepted", s);
            for (i = 0; i < s * s; ++i) FZ_FIN(hbuf[i], "height");
        }
    } else {
        static mf_real hbuf[16 * 16];
        int sizes[4] = { 8, 16, 9, 12 };
        int s = sizes[fz_u8(&in) % 4u], i;
        fz_fill(&in, 2 * 16 * 16);
        if (mf_microsurface_integrate(fz_buf, s, hbuf) == MF_SUCCESS) {
            if (s & (s - 1)) FZ_FAIL("size %d accepted", s);
            for (i = 0; i < s * s; ++i) FZ_FIN(hbuf[i], "integrated height");
        }
    }
    return 0;
}
