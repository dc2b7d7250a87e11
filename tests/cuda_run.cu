// `make cuda-run`: the library run on a CUDA GPU (skipped without nvcc or a
// GPU; never part of `make test`). Every case is computed twice from the same
// inputs, by a kernel and by the host build of the same header, and the two are
// compared output by output: the generic operations of the four analytic
// kinds, transformed and tabulated distributions, dielectrics, LTC polygons and
// the Inverse Bin Map queries on a map copied to the device. Then the
// throughput of GGX evaluation and sampling, in samples per second, each rate
// the best of 5 launches of about 1.4e8 samples (inputs hashed in the kernel;
// the hashing alone is timed too).
//   ./build/cuda_run            float build (MF_USE_DOUBLE for the double one)
//   ./build/cuda_run --host     the host half alone (checks this file on a
//                               machine with no GPU; compares nothing)
//   --cases N (at most 262144), --first K (cases K .. K+N-1), --no-rates,
//   --skip MASK (groups of outputs left out: 1 kinds, 2 dielectric, 4 LTC,
//   8 tabulated, 16 IBM, 32/64/128/256 one IBM query), --block B (threads
//   per block, 128), --stack S (stack limit; 0: the kernel's local memory
//   + 1 KB, -1: the driver's): to narrow down a failing case
// Prints "cuda-run: N passed, N failed" last and exits non-zero on a failure.
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
#include <cuda_runtime.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#define NOUT 20
#define NCASE (1 << 18)

static int passed, failed;
static void check(int ok, const char *what)
{
    if (ok) ++passed;
    else { ++failed; printf("FAIL %s\n", what); }
}
#define CUDA_OK(x) do { cudaError_t e_ = (x); if (e_ != cudaSuccess) { \
    printf("FAIL %s: %s\n", #x, cudaGetErrorString(e_)); ++failed; goto done; } } while (0)

// ---- inputs: a hash of the case index (the library's mf__mix32), the
// same on host and device ----
// uniform in [0, 1), 24 bits
MF_HD static mf_real rnd(unsigned i, unsigned k)
{
    return (mf_real)(mf__mix32(i * 0x9e3779b9u + k * 0x85ebca6bu + 0x632be5abu) >> 8) * MF_R(5.9604644775390625e-8);
}
// directions of the upper hemisphere up to polar angle tmax
MF_HD static mf_vec3 dir(mf_real u1, mf_real u2, mf_real tmax)
{
    mf_real t = tmax * u1, p = MF_R(6.283185307179586) * u2;
    return mf_vec3_make(MF_SIN(t) * MF_COS(p), MF_SIN(t) * MF_SIN(p), MF_COS(t));
}
MF_HD static mf_real alpha_of(mf_real u)    // 1e-3 .. 1, log-uniform
{
    return MF_EXP(MF_R(-6.907755) * u);
}

// ---- the compared cases: outputs o[0..NOUT) of case i ----
struct world {
    mf_tabulated tab;   // rebased onto device memory for the kernel
    mf_ibm ibm;         // data pointing at device memory for the kernel
    unsigned skip;      // groups of outputs left at 0 (--skip: bits of the groups below)
};
static const char *out_name[NOUT] = {
    "D", "lambda", "G2", "brdf", "brdf_pdf", "sample.x", "sample.z", "sample_weight",
    "visible.x", "visible.z", "dielectric_bsdf", "dielectric_pdf", "dielectric_sample.z",
    "ltc_integrate", "tabulated_brdf", "tabulated_sample.z", "ibm_bin_weight", "ibm_brdf",
    "ibm_pdf", "ibm_sample.z"};
// 1: a direction component (absolute error), 0: a value (relative error)
static const int out_dir[NOUT] = {0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1};

MF_HD static void run_case(const world *w, unsigned i, mf_real *o)
{
    mf_real ax = alpha_of(rnd(i, 0)), ay = (i & 8) ? alpha_of(rnd(i, 1)) : ax;
    mf_ndf d;
    switch (i & 3) {
    case 0: d = mf_ggx(ax, ay); break;
    case 1: d = mf_beckmann(ax, ay); break;
    case 2: d = mf_gtr(MF_R(0.02) + ax, MF_R(1.2) + rnd(i, 2)); break;
    default: d = mf_student_t(MF_R(0.02) + ax, MF_R(0.02) + ay, MF_R(1.6) + MF_R(8.0) * rnd(i, 2)); break;
    }
    if (i & 4) d = mf_transformed(d, mf_mat2_make(MF_R(1.0), MF_R(0.4) * rnd(i, 3), MF_R(0.0), MF_R(0.5) + rnd(i, 4)));
    mf_vec3 wo = dir(rnd(i, 5), rnd(i, 6), MF_R(1.5707)), wi = dir(rnd(i, 7), rnd(i, 8), MF_R(1.5707));
    mf_vec3 wm = mf_normalize(mf_vec3_make(wo.x + wi.x, wo.y + wi.y, wo.z + wi.z));
    mf_real u1 = rnd(i, 9), u2 = rnd(i, 10), u3 = rnd(i, 11), eta = MF_R(1.05) + rnd(i, 12);
    for (int k = 0; k < NOUT; ++k) o[k] = 0;
    if (!(w->skip & 1)) {
    o[0] = mf_D(&d, wm);
    o[1] = mf_lambda(&d, wo);
    o[2] = mf_G2(&d, wo, wi, wm);
    o[3] = mf_brdf(&d, wo, wi);
    o[4] = mf_brdf_pdf(&d, wo, wi);
    mf_vec3 s = mf_brdf_sample(&d, wo, u1, u2).wi;
    o[5] = s.x; o[6] = s.z;
    // the sample weight G2 / G1 = (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)) at
    // a given direction, not the record's: near the horizon the weight amplifies
    // the sample's rounding (fused multiply-adds alone move the record's weight
    // beyond 1e-4 in 15 of 2^18 cases on the host)
    mf_real lo = mf_lambda(&d, wo);
    o[7] = (MF_R(1.0) + lo) / (MF_R(1.0) + lo + mf_lambda(&d, wi));
    mf_vec3 v = mf_sample_visible(&d, wo, u1, u2);
    o[8] = v.x; o[9] = v.z;
    }
    mf_vec3 wt = mf_vec3_make(-wi.x, -wi.y, -wi.z);
    if (!(w->skip & 2)) {
    o[10] = mf_dielectric_bsdf(&d, wo, wt, eta, MF_RADIANCE);
    o[11] = mf_dielectric_pdf(&d, wo, wt, eta);
    o[12] = mf_dielectric_sample(&d, wo, eta, MF_RADIANCE, u1, u2, u3).wi.z;
    }
    if (!(w->skip & 4)) {   // a quad light over the shading point, through a GGX LTC
        mf_ltc l = mf_ltc_from_inverse(MF_R(1.0) + rnd(i, 13), MF_R(0.3), MF_R(1.5), MF_R(-0.2), MF_R(1.0));
        mf_real cx = MF_R(4.0) * rnd(i, 14) - MF_R(2.0), h = MF_R(0.2) + rnd(i, 15);
        mf_vec3 q[4];
        q[0] = mf_vec3_make(cx - 1, -1, h); q[1] = mf_vec3_make(cx - 1, 1, h);   // facing the point
        q[2] = mf_vec3_make(cx + 1, 1, h); q[3] = mf_vec3_make(cx + 1, -1, h);
        o[13] = mf_ltc_integrate(&l, q, 4, 0);
    }
    if (!(w->skip & 8)) {
        mf_ndf t = mf_tabulated_ndf(&w->tab);
        o[14] = mf_brdf(&t, wo, wi);
        o[15] = mf_brdf_sample(&t, wo, u1, u2).wi.z;
    }
    if (!(w->skip & 16)) {   // footprints of 0.1 to 1e5 texels, sheared, anywhere on the map
        mf_real side = MF_EXP(MF_R(-1.15) + MF_R(6.9) * rnd(i, 16)) / (mf_real)w->ibm.width;
        mf_footprint f;
        f.u = rnd(i, 17); f.v = rnd(i, 18);
        f.ax = side; f.ay = MF_R(0.3) * side * rnd(i, 19);
        f.bx = MF_R(-0.2) * side * rnd(i, 20); f.by = side * (MF_R(0.5) + rnd(i, 21));
        mf_vec3 h = (i & 16) ? mf_ibm_bin_normal(&w->ibm, (int)(mf__mix32(i) % (unsigned)mf_ibm_bin_count(&w->ibm))) : wm;
        // the bin of the footprint's centre texel, or of h
        int bin = (i & 32) ? mf_ibm_bin_of(&w->ibm, h)
                           : mf_ibm_texel_bin(&w->ibm, (int)(f.u * (mf_real)w->ibm.width), (int)(f.v * (mf_real)w->ibm.height));
        if (!(w->skip & 32)) o[16] = mf_ibm_bin_weight(&w->ibm, bin, &f);
        // wi mirrored about h: a direction on the map's glints
        mf_vec3 wg = mf_reflect(wo, h);
        if (wg.z <= MF_R(0.0)) wg = wi;
        if (!(w->skip & 64)) o[17] = mf_ibm_brdf(&w->ibm, &f, wo, wg);
        if (!(w->skip & 128)) o[18] = mf_ibm_pdf(&w->ibm, &f, wo, wg);
        if (!(w->skip & 256)) o[19] = mf_ibm_sample(&w->ibm, &f, wo, u1, u2, u3, rnd(i, 22)).wi.z;
    }
}

__global__ void k_cases(world w, mf_real *out, int n, unsigned first)
{
    int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) run_case(&w, first + (unsigned)i, out + (size_t)NOUT * (size_t)i);
}

// ---- throughput: each thread takes `per` samples, alpha per thread ----
enum { R_INPUTS, R_GGX_BRDF, R_GGX_BRDF_PDF, R_GGX_SAMPLE, R_GGX_VNDF, R_BECKMANN_VNDF, R_COUNT };
static const char *rate_name[R_COUNT] = {
    "inputs alone (hash, 2 directions)", "GGX mf_brdf", "GGX mf_brdf + mf_brdf_pdf",
    "GGX mf_brdf_sample (record)", "GGX mf_sample_visible", "Beckmann mf_sample_visible"};

template <int op> __global__ void k_rate(int per, mf_real *sink)
{
    unsigned t = blockIdx.x * blockDim.x + threadIdx.x;
    mf_real a = MF_R(0.02) + MF_R(0.6) * rnd(t, 0);
    mf_ndf g = mf_ggx(a, a), b = mf_beckmann(a, a);
    mf_real acc = 0;
    for (int k = 0; k < per; ++k) {
        unsigned i = t * (unsigned)per + (unsigned)k;
        mf_real u1 = rnd(i, 1), u2 = rnd(i, 2);
        mf_vec3 wo = dir(u1, u2, MF_R(1.55));
        mf_vec3 wi = mf_vec3_make(wo.y, -wo.x, wo.z);   // a second direction, no extra hashing
        switch (op) {
        case R_INPUTS: acc += wo.x + wi.y; break;
        case R_GGX_BRDF: acc += mf_brdf(&g, wo, wi); break;
        case R_GGX_BRDF_PDF: acc += mf_brdf(&g, wo, wi) + mf_brdf_pdf(&g, wo, wi); break;
        case R_GGX_SAMPLE: acc += mf_brdf_sample(&g, wo, u2, u1).weight; break;
        case R_GGX_VNDF: acc += mf_sample_visible(&g, wo, u2, u1).z; break;
        default: acc += mf_sample_visible(&b, wo, u2, u1).z; break;
        }
    }
    sink[t] = acc;
}

// ---- host-side setup ----
static mf_real *flake_map(int w, int h, int cell)
{
    mf_real *n = (mf_real *)malloc(sizeof(mf_real) * 3 * (size_t)w * (size_t)h);
    mf_ndf g = mf_ggx(MF_R(0.3), MF_R(0.3));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            unsigned c = (unsigned)((y / cell) * (w / cell) + x / cell);
            mf_vec3 m = mf_sample_D(&g, rnd(c, 30), rnd(c, 31));
            if (m.z < MF_R(0.2)) m = mf_normalize(mf_vec3_make(m.x, m.y, MF_R(0.2)));
            n[3 * (y * w + x)] = m.x; n[3 * (y * w + x) + 1] = m.y; n[3 * (y * w + x) + 2] = m.z;
        }
    return n;
}

int main(int argc, char **argv)
{
    int host_only = 0, rates = 1, n = NCASE;
    unsigned first = 0;
    int stack = 0, block = 128;
    unsigned skip = 0;
    for (int a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "--host")) host_only = 1;
        else if (!strcmp(argv[a], "--no-rates")) rates = 0;
        else if (!strcmp(argv[a], "--cases") && a + 1 < argc) n = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--first") && a + 1 < argc) first = (unsigned)atoi(argv[++a]);
        else if (!strcmp(argv[a], "--stack") && a + 1 < argc) stack = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--block") && a + 1 < argc) block = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--skip") && a + 1 < argc) skip = (unsigned)atoi(argv[++a]);
    }
    if (n < 1 || n > NCASE) n = NCASE;
    world w, wd;
    w.skip = skip;
    mf_real *hout = (mf_real *)malloc(sizeof(mf_real) * NOUT * (size_t)n);
    mf_real *dres = (mf_real *)malloc(sizeof(mf_real) * NOUT * (size_t)n);
    mf_real *dout = 0, *sink = 0;
    void *dtab = 0;
    unsigned int *dibm = 0;
    mf_real *map = flake_map(512, 512, 4);
    mf_ndf g0 = mf_ggx(MF_R(0.25), MF_R(0.4));
    printf("cuda-run: %s build, %d cases x %d outputs\n", sizeof(mf_real) == 8 ? "double" : "float", n, NOUT);
    check(mf_tabulated_from_ndf(&w.tab, &g0, 64) == MF_SUCCESS, "tabulated build");
    check(mf_ibm_build(&w.ibm, map, 512, 512, MF_R(0.01)) == MF_SUCCESS, "ibm build (512^2 flakes, alpha 0.01)");
    if (failed) goto done;
    for (int i = 0; i < n; ++i) run_case(&w, first + (unsigned)i, hout + (size_t)NOUT * i);
    {
        int bad = 0;
        for (size_t k = 0; k < (size_t)NOUT * n; ++k) bad += !isfinite((double)hout[k]);
        check(bad == 0, "host outputs finite");
        for (int k = 0; k < NOUT; ++k) {   // no output compared only as zeros
            int nz = 0;
            char what[96];
            for (int i = 0; i < n; ++i) nz += hout[(size_t)NOUT * i + k] != 0;
            snprintf(what, sizeof what, "host %s nonzero in %d of %d cases (at least 10%%)", out_name[k], nz, n);
            check(nz * 10 >= n, what);
        }
    }
    if (host_only) { printf("cuda-run: host half only (--host): nothing compared\n"); goto done; }
    {
        cudaDeviceProp p;
        int dev = 0;
        CUDA_OK(cudaGetDevice(&dev));
        CUDA_OK(cudaGetDeviceProperties(&p, dev));
        printf("device: %s, %d SMs, compute capability %d.%d\n", p.name, p.multiProcessorCount, p.major, p.minor);
        {   // the IBM queries keep their clipping buffers and traversal stack
            // in local memory: 14 KB per thread in float, 18 KB in double
            cudaFuncAttributes fa;
            size_t lim = 0;
            CUDA_OK(cudaFuncGetAttributes(&fa, k_cases));
            CUDA_OK(cudaDeviceGetLimit(&lim, cudaLimitStackSize));
            printf("k_cases: %zu bytes of local memory per thread (stack limit %zu)\n", (size_t)fa.localSizeBytes, lim);
            if (stack >= 0) {
                CUDA_OK(cudaDeviceSetLimit(cudaLimitStackSize, stack ? (size_t)stack : fa.localSizeBytes + 1024));
                CUDA_OK(cudaDeviceGetLimit(&lim, cudaLimitStackSize));
                printf("stack limit set to %zu\n", lim);
            }
        }
        CUDA_OK(cudaMalloc(&dtab, w.tab.bytes));
        CUDA_OK(cudaMemcpy(dtab, w.tab.block, w.tab.bytes, cudaMemcpyHostToDevice));
        CUDA_OK(cudaMalloc((void **)&dibm, w.ibm.words * sizeof(unsigned int)));
        CUDA_OK(cudaMemcpy(dibm, w.ibm.data, w.ibm.words * sizeof(unsigned int), cudaMemcpyHostToDevice));
        wd = w;
        wd.tab = mf_tabulated_rebase(&w.tab, dtab);
        wd.ibm.data = dibm;
        CUDA_OK(cudaMalloc((void **)&dout, sizeof(mf_real) * NOUT * (size_t)n));
        k_cases<<<(n + block - 1) / block, block>>>(wd, dout, n, first);
        CUDA_OK(cudaGetLastError());
        CUDA_OK(cudaDeviceSynchronize());
        CUDA_OK(cudaMemcpy(dres, dout, sizeof(mf_real) * NOUT * (size_t)n, cudaMemcpyDeviceToHost));
        // Tolerances: float 1e-4 (fused multiply-adds and the device's own
        // expf/erff/sqrtf move results by a few ulp, which grazing angles and
        // tiny roughness amplify), the IBM BRDF and pdf (float sums of
        // flake lobes near their cut: 1.6e-3 from double at p99 on the host) 5e-3,
        // the LTC quad (float sums of edge terms that cancel for the wide,
        // low quads: float's own error from double exceeds 1e-4) 1e-3;
        // double 1e-9. A branch (rejection, reflect or refract) can flip on
        // one ulp, so 1 case in 1e4 may differ beyond it; a non-finite
        // result never.
        for (int k = 0; k < NOUT; ++k) {
            int ibm_sum = k == 17 || k == 18;
            double tol = sizeof(mf_real) == 8 ? (ibm_sum ? 1e-8 : 1e-9) : (ibm_sum ? 5e-3 : k == 13 ? 1e-3 : 1e-4);
            double worst = 0, sum = 0;
            int over = 0, nonfinite = 0;
            for (int i = 0; i < n; ++i) {
                double h = (double)hout[(size_t)NOUT * i + k], dv = (double)dres[(size_t)NOUT * i + k];
                if (!isfinite(dv)) { ++nonfinite; continue; }
                double e = fabs(dv - h) / (out_dir[k] ? 1.0 : fmax(fabs(h), 1e-3));
                sum += e;
                if (e > worst) worst = e;
                over += e > tol;
            }
            char what[160];
            printf("  %-20s mean err %.2e, max %.2e, beyond %.0e: %d of %d\n", out_name[k], sum / n, worst, tol, over, n);
            snprintf(what, sizeof what, "%s: device finite (%d non-finite)", out_name[k], nonfinite);
            check(nonfinite == 0, what);
            snprintf(what, sizeof what, "%s: device = host within %.0e in all but 1 in 1e4 (%d over)", out_name[k], tol, over);
            check(over <= n / 10000, what);
        }
    }
    if (rates) {   // throughput
        cudaEvent_t e0, e1;
        int blocks = 132 * 16, threads = 256, per = 256;
        double samples = (double)blocks * threads * per;
        CUDA_OK(cudaMalloc((void **)&sink, sizeof(mf_real) * (size_t)blocks * threads));
        CUDA_OK(cudaEventCreate(&e0));
        CUDA_OK(cudaEventCreate(&e1));
        printf("throughput (%s, %.3g samples per launch, best of 5 launches):\n", sizeof(mf_real) == 8 ? "double" : "float", samples);
        for (int op = 0; op < R_COUNT; ++op) {
            void (*k)(int, mf_real *) = op == R_INPUTS ? k_rate<R_INPUTS> : op == R_GGX_BRDF ? k_rate<R_GGX_BRDF>
                : op == R_GGX_BRDF_PDF ? k_rate<R_GGX_BRDF_PDF> : op == R_GGX_SAMPLE ? k_rate<R_GGX_SAMPLE>
                : op == R_GGX_VNDF ? k_rate<R_GGX_VNDF> : k_rate<R_BECKMANN_VNDF>;
            float best = 1e30f;
            k<<<blocks, threads>>>(per, sink);   // warm-up
            CUDA_OK(cudaDeviceSynchronize());
            for (int r = 0; r < 5; ++r) {
                float ms = 0;
                CUDA_OK(cudaEventRecord(e0));
                k<<<blocks, threads>>>(per, sink);
                CUDA_OK(cudaEventRecord(e1));
                CUDA_OK(cudaEventSynchronize(e1));
                CUDA_OK(cudaEventElapsedTime(&ms, e0, e1));
                if (ms < best) best = ms;
            }
            CUDA_OK(cudaGetLastError());
            printf("  %-36s %8.2f G samples/s  (%.3f ms per launch)\n", rate_name[op], samples / (best * 1e-3) / 1e9, best);
        }
    }
done:
    if (dout) cudaFree(dout);
    if (sink) cudaFree(sink);
    if (dtab) cudaFree(dtab);
    if (dibm) cudaFree(dibm);
    mf_tabulated_release(&w.tab);
    mf_ibm_release(&w.ibm);
    free(map); free(hout); free(dres);
    printf("cuda-run: %d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
