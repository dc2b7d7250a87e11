/* ======================================================================== */
/* == 9b. Tabulating any distribution: mf_tabulated_from_ndf                */
/* ======================================================================== */
/* The builder of a tabulated kind (06_kind_tabulated.h) from any mf_ndf,
 * transformed or not: it evaluates D through mf_D (08_transform.h), so it
 * follows the front ends. Contract with the declaration in 06_kind_tabulated.h. */
/* @impl */
/* D of d averaged over the azimuths phi0 and phi0 + pi, at polar angle th */
static mf_real mf__tab_slice(const mf_ndf *d, mf_real th, mf_real phi0)
{
    mf_real st = MF_SIN(th), ct = MF_COS(th), c = MF_COS(phi0), s = MF_SIN(phi0);
    return MF_R(0.5) * (mf_D(d, mf_vec3_make(st * c, st * s, ct)) + mf_D(d, mf_vec3_make(-st * c, -st * s, ct)));
}

MFDEF mf_result mf_tabulated_from_ndf(mf_tabulated *t, const mf_ndf *d, int n)
{
    const mf_real hpi = MF_R(0.5) * MF_PI;
    mf_real *th, *dx, *dy, *cth, *cx, *cy, *cum, *err, scale = MF_R(1.0), total = MF_R(0.0), fmax = MF_R(0.0);
    int i, j, m, M, iso = 1, K = 800, *best;
    char *sel;
    mf_result r;
    if (!t) return MF_ERROR_INVALID_ARGUMENT;
    mf__tab_zero(t);
    if (!d || n < 4 || n > MF_TABULATED_MAX_POINTS) return MF_ERROR_INVALID_ARGUMENT;
    M = 8 * n;   /* candidate angles */
    th = (mf_real *)MF_MALLOC(sizeof(mf_real) * (3 * (size_t)n + 5 * (size_t)M) + (sizeof(int) + 1) * (size_t)M);
    if (!th) return MF_ERROR_OUT_OF_MEMORY;
    dx = th + n; dy = th + 2 * n; cth = th + 3 * n; cx = cth + M; cy = cx + M; cum = cy + M; err = cum + M;
    best = (int *)(void *)(err + M);
    sel = (char *)(void *)(best + M);
    /* the median tan(theta) of D cos over a log grid of tan(theta) in [1e-5, 1e5]
     * (two passes: the total, then the median) */
    for (j = 0; j < 2; ++j) {
        mf_real acc = MF_R(0.0), prev_t = MF_R(0.0), prev_f = MF_R(0.0);
        for (i = 0; i <= K; ++i) {
            mf_real tt = MF_ATAN(MF_R(1e-5) * MF_POW(MF_R(10.0), MF_R(10.0) * (mf_real)i / (mf_real)K));
            mf_real f = MF_R(0.5) * (mf__tab_slice(d, tt, MF_R(0.0)) + mf__tab_slice(d, tt, hpi)) * MF_COS(tt) * MF_SIN(tt);
            acc += MF_R(0.5) * (f + prev_f) * (tt - prev_t);
            prev_t = tt; prev_f = f;
            if (j == 1 && acc >= MF_R(0.5) * total) { scale = MF_TAN(tt); break; }
        }
        total = acc;
    }
    if (!(total > MF_R(0.0)) || !(total < MF_BIG)) { MF_FREE(th); return MF_ERROR_INVALID_DATA; }
    /* candidates: half uniform in theta, half at tan(theta) = s tan(pi q / 2), merged */
    for (i = 0; i < M / 2; ++i) cth[i] = hpi * (mf_real)i / (mf_real)(M / 2 - 1);
    for (i = M / 2; i < M; ++i) cth[i] = MF_ATAN(scale * MF_TAN(hpi * (mf_real)(i - M / 2 + 1) / (mf_real)(M - M / 2 + 1)));
    {   /* merge the two sorted halves (through err, free until phase 2) */
        int a = 0, b = M / 2, k = 0;
        while (a < M / 2 || b < M) err[k++] = b >= M || (a < M / 2 && cth[a] <= cth[b]) ? cth[a++] : cth[b++];
        for (i = 0; i < M; ++i) cth[i] = err[i];
    }
    for (i = 1, m = 1; i < M; ++i)
        if (mf__tab_gap_ok(cth[m - 1], cth[i])) cth[m++] = cth[i];
    cth[m - 1] = hpi;
    M = m;
    for (i = 0; i < M; ++i) {
        cx[i] = mf__tab_slice(d, cth[i], MF_R(0.0));
        cy[i] = mf__tab_slice(d, cth[i], hpi);
        fmax = mf_max(fmax, mf_max(cx[i], cy[i]));
    }
    /* Control points are candidates. Phase 1 (3/4 of them) equidistributes the
     * error of linear interpolation relative to D (floored at 1e-4 of its
     * peak): density sqrt(|D''| / D) plus a floor so flat parts keep points.
     * Phase 2 adds the rest to the segments whose interpolated D cos mass is
     * most wrong (e.g. a wide segment from a small value to zero beyond the end
     * of a lobe, which no curvature sees), a quarter of them per pass. */
    cum[0] = MF_R(0.0);
    for (i = 1; i < M; ++i) {
        mf_real rho = MF_R(0.0), h = cth[i] - cth[i - 1];
        int a = i > 1 ? i - 1 : 1, k;
        for (k = 0; k < 2; ++k) {
            const mf_real *f = k ? cy : cx;
            mf_real h0 = cth[a] - cth[a - 1], h1 = cth[a + 1 < M ? a + 1 : a] - cth[a];
            mf_real d2 = a + 1 < M ? MF_R(2.0) * ((f[a + 1] - f[a]) / h1 - (f[a] - f[a - 1]) / h0) / (h0 + h1) : MF_R(0.0);
            rho = mf_max(rho, MF_SQRT(MF_FABS(d2) / (MF_R(0.5) * (f[i] + f[i - 1]) + MF_R(1e-4) * fmax)));
        }
        cum[i] = cum[i - 1] + h * (rho + MF_R(2.0) / hpi);
    }
    for (i = 0; i < M; ++i) sel[i] = (char)(i == 0 || i == M - 1);
    for (i = 1, j = 1, m = 2; i < (3 * n) / 4 - 1; ++i) {
        mf_real target = cum[M - 1] * (mf_real)i / (mf_real)((3 * n) / 4 - 1);
        while (j < M - 1 && cum[j] < target) ++j;
        if (!sel[j]) { sel[j] = 1; ++m; }
    }
    while (m < n) {
        /* mass error of each segment, in units of the total */
        mf_real emax = MF_R(0.0), thr;
        int a = 0, nseg = 0, added = 0, want;
        for (i = 1; i < M; ++i) {
            if (!sel[i]) continue;
            err[nseg] = MF_R(0.0); best[nseg] = -1;
            {
                mf_real be = -MF_R(1.0);
                int k, c2;
                for (k = a + 1; k < i; ++k)
                    for (c2 = 0; c2 < 2; ++c2) {
                        const mf_real *f = c2 ? cy : cx;
                        mf_real fr = (cth[k] - cth[a]) / (cth[i] - cth[a]), lin = f[a] + (f[i] - f[a]) * fr;
                        mf_real dev = MF_FABS(lin - f[k]);
                        err[nseg] += dev * MF_COS(cth[k]) * MF_SIN(cth[k]) * (cth[k + 1] - cth[k - 1]) * MF_R(0.5) / total;
                        /* split where the interpolant is furthest off: right after the end of a lobe,
                         * mid-way inside one */
                        if (dev > be) { be = dev; best[nseg] = k; }
                    }
            }
            emax = mf_max(emax, err[nseg]);
            ++nseg; a = i;
        }
        want = n - m < nseg / 4 + 1 ? n - m : nseg / 4 + 1;
        if (!(emax > MF_R(0.0)) || want <= 0) break;
        /* threshold: bisect for about `want` segments above it */
        {
            mf_real lo = MF_R(0.0), hi = emax;
            int it, cnt;
            for (it = 0; it < 40; ++it) {
                thr = MF_R(0.5) * (lo + hi);
                for (cnt = 0, i = 0; i < nseg; ++i) cnt += err[i] > thr;
                if (cnt > want) lo = thr; else hi = thr;
            }
            thr = hi;
        }
        for (i = 0; i < nseg && m < n; ++i)
            if ((err[i] >= thr || (added == 0 && err[i] == emax)) && best[i] > 0 && !sel[best[i]]) { sel[best[i]] = 1; ++m; ++added; }
        if (!added) break;
    }
    for (i = 0, m = 0; i < M; ++i)
        if (sel[i]) {
            th[m] = cth[i]; dx[m] = cx[i]; dy[m] = cy[i];
            if (MF_FABS(dx[m] - dy[m]) > MF_R(1e-6) * mf_max(dx[m], dy[m])) iso = 0;
            ++m;
        }
    r = mf_tabulated_build(t, th, dx, iso ? (const mf_real *)0 : dy, m);
    MF_FREE(th);
    return r;
}
