/* ======================================================================== */
/* == 7. The kinds' dispatch: the generic operations' switches              */
/* ======================================================================== */
/* The cold dispatch of the untransformed kinds declared in 05_ndf.h (the
 * front ends of modules 8-10 inline the kinds of INL > 0 and call these for
 * the others), with the trait entries ISO, LTC and PREP. It follows the kinds
 * (06_kind_*.h), whose functions it calls; every switch is generated from
 * MF__NDF_KINDS, so a new kind needs no line here. */
/* @cold */
#define MF__NDF_CASE_D(N, n, inl, cen, iso, tr, et, ax, pp) case MF_NDF_##N: return mf__##n##_D(d, wm);
#define MF__NDF_CASE_LAMBDA(N, n, inl, cen, iso, tr, et, ax, pp) case MF_NDF_##N: return mf__##n##_lambda(d, w);
#define MF__NDF_CASE_SAMPLE_D(N, n, inl, cen, iso, tr, et, ax, pp) case MF_NDF_##N: return mf__##n##_sample_D(d, u1, u2);
#define MF__NDF_CASE_SAMPLE_VISIBLE(N, n, inl, cen, iso, tr, et, ax, pp) case MF_NDF_##N: return mf__##n##_sample_visible(d, w, u1, u2);
MF_COLD mf_real mf__ndf_D(const mf_ndf *d, mf_vec3 wm)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_D)
    default: return MF_R(0.0);
    }
}
MF_COLD mf_real mf__ndf_lambda(const mf_ndf *d, mf_vec3 w)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_LAMBDA)
    default: return MF_R(0.0);
    }
}
MF_COLD mf_vec3 mf__ndf_sample_D(const mf_ndf *d, mf_real u1, mf_real u2)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_SAMPLE_D)
    default: return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    }
}
MF_COLD mf_vec3 mf__ndf_sample_visible(const mf_ndf *d, mf_vec3 w, mf_real u1, mf_real u2)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_SAMPLE_VISIBLE)
    default: return mf_vec3_make(MF_R(0.0), MF_R(0.0), MF_R(0.0));
    }
}
#define MF__NDF_CASE_PREP(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##pp(case MF_NDF_##N: return mf__##n##_prepare(d, &p->d, &p->s.n);)
MF_COLD const mf_ndf *mf__ndf_prepare(const mf_ndf *d, mf__ndf_prep *p)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_PREP)
    default: return d;
    }
}
#undef MF__NDF_CASE_PREP
#undef MF__NDF_CASE_D
#undef MF__NDF_CASE_LAMBDA
#undef MF__NDF_CASE_SAMPLE_D
#undef MF__NDF_CASE_SAMPLE_VISIBLE

/* The NDF-cos CDF inversion of the kinds of ISO > 0 (05_numeric_vndf.h; declared
 * in 05_ndf.h): tan^2 at mass t from the pole (q = 1 - t beyond), the mass
 * beyond tan2, and the exponent p of the sampler's substitution; unknown kinds
 * give 0, 0 and 4. */
#define MF__NDF_CASE_TAN2(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##iso(case MF_NDF_##N: return mf__##n##_tan2(d, t, q);)
#define MF__NDF_CASE_TAIL(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##iso(case MF_NDF_##N: return mf__##n##_tail(d, tan2);)
#define MF__NDF_CASE_VNDF_P(N, n, inl, cen, iso, tr, et, ax, pp) MF__IF##iso(case MF_NDF_##N: return mf__##n##_vndf_p(d);)
MF_INLINE mf_real mf__ndf_iso_tan2(const mf_ndf *d, mf_real t, mf_real q)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_TAN2)
    default: return MF_R(0.0);
    }
}
MF_INLINE mf_real mf__ndf_iso_tail(const mf_ndf *d, mf_real tan2)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_TAIL)
    default: return MF_R(0.0);
    }
}
MF_INLINE mf_real mf__ndf_iso_p(const mf_ndf *d)
{
    switch (d->type) {
    MF__NDF_KINDS(MF__NDF_CASE_VNDF_P)
    default: return MF_R(4.0);
    }
}
#undef MF__NDF_CASE_TAN2
#undef MF__NDF_CASE_TAIL
#undef MF__NDF_CASE_VNDF_P

