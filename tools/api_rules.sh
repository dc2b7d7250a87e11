#!/bin/sh
# The 0.4 API rules (shared contract: "0.4 conventions"), checked on every
# public function of the generated header; prints each name or argument
# order outside them and exits 1 if there is any. Needs sh and awk.
#   - names: mf_ lower snake case (kind constructors and the literature's
#     symbols D, G1, G2 excepted)
#   - lobe samplers (a name ending in _sample or _sample_<variant> that
#     takes wo) return mf_sample
#   - Fresnel functions take the cosine first
#   - the object acted on first: a pointer to a library object (mf_ndf, a
#     table, an IBM, an LTC, a map, a sensor) is the first parameter, or the
#     second after the object a builder fills
#   - directions wo before wi; the transport mode after eta and the material
#     parameters, before the random numbers; random numbers u1, u2... after
#     every other input, only outputs (pointers) after them
#   - builders, loaders, savers, fitters and generators return mf_result;
#     an int is a predicate named as a question (_is_, _has_), a count or an
#     index (names below), or a contract signature listed here with its reason
# Deprecated 0.3 names (MF_DEPRECATED) are not checked.
set -e
cd "$(dirname "$0")/.."
awk '
BEGIN {
    # int-returning functions that are counts or indices
    split("mf_ibm_bin_count mf_ibm_bin_of mf_ibm_texel_bin mf_ibm_bin_texels mf_ibm_neighbourhood_weights mf_gonio_cell", a, " ")
    for (i in a) intok[a[i]] = 1
    # contract signatures (shared/API.md) kept as they are
    intok["mf_refract"] = 1   # API.md: int mf_refract(wi, n, eta, *wt), 1 = refracted
    # distribution samplers: they return a normal (the density is the
    # distribution itself), not a lobe sample
    split("mf_sample_D mf_sample_visible mf_ggx_sample_visible mf_beckmann_sample_visible mf_ltc_sample", b, " ")
    for (i in b) normal_sampler[b[i]] = 1
    bad = 0; n = 0
}
function trim(s) { sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s); return s }
function pname(p,   q) { q = p; sub(/\[.*$/, "", q); sub(/^.*[ *]/, "", q); return q }
function complain(msg) { print "api rules: " name ": " msg; bad = 1 }
/^(MF_INLINE|MF_FORCE_INLINE|MFDEF|MF_COLD) [^(]*[ *]mf_[a-z][A-Za-z0-9_]*\(/ {
    decl = $0
    while (decl !~ /\)/ && (getline line) > 0) decl = decl " " line
    sub(/\).*$/, "", decl)
    head = decl; sub(/\(.*$/, "", head)
    name = head; sub(/^.*[ *]/, "", name)
    if (name ~ /^mf__/) next
    if (seen[name]++) next
    ++n
    ret = head; sub(/^(MF_INLINE|MF_FORCE_INLINE|MFDEF|MF_COLD) /, "", ret); sub(/[ *]*mf_[A-Za-z0-9_]*$/, "", ret)
    args = decl; sub(/^[^(]*\(/, "", args)
    np = split(args, P, ",")
    for (i = 1; i <= np; ++i) { P[i] = trim(P[i]); N[i] = pname(P[i]) }
    nm = name; gsub(/(^|_)(D|G1|G2)(_|$)/, "_", nm)   # the literature symbols D, G1, G2
    if (nm !~ /^mf_[a-z0-9_]*$/) complain("not lower snake case")
    # lobe samplers return the record
    has_wo = 0; for (i = 1; i <= np; ++i) if (N[i] == "wo") has_wo = i
    if (name ~ /_sample(_[a-z]+)?$/ && has_wo && !(name in normal_sampler) && ret != "mf_sample") complain("a lobe sampler returns mf_sample")
    # Fresnel: cosine first
    if (name ~ /^mf_fresnel_/ && name !~ /_average$/ && N[1] !~ /^cos/) complain("a Fresnel function takes the cosine first")
    # object first
    for (i = 1; i <= np; ++i)
        if (P[i] ~ /^(const )?mf_(ndf|ibm|ltc|tabulated|albedo_table|dielectric_ms_table|ltc_table|leadr_map|gonio) \*/ && i > 1) {
            first_obj = (P[1] ~ /\*/ && P[1] !~ /mf_real|void|char/)
            if (!(i == 2 && first_obj)) complain("the object " N[i] " is not first")
            break
        }
    # wo before wi
    iwi = 0; for (i = 1; i <= np; ++i) if (N[i] == "wi") iwi = i
    if (has_wo && iwi && iwi < has_wo) complain("wi before wo")
    # transport after eta and before the random numbers; random numbers last but outputs
    im = 0; ie = 0; iu = 0
    for (i = 1; i <= np; ++i) {
        if (P[i] ~ /^mf_transport /) im = i
        if (N[i] == "eta") ie = i
        if (N[i] ~ /^u[0-9]$/ && !iu) iu = i
    }
    if (im && ie && im < ie) complain("the transport mode before eta")
    if (im && iu && im > iu) complain("the transport mode after the random numbers")
    if (iu) for (i = iu; i <= np; ++i) if (N[i] !~ /^u[0-9]$/ && P[i] !~ /\*/) complain("an input (" N[i] ") after the random numbers")
    # a distribution is passed as an mf_ndf (or a family of them), never as a kind number
    for (i = 1; i <= np; ++i) if (N[i] == "kind" && P[i] ~ /^int /) complain("a distribution passed as an int kind")
    # a builder fills the object given first
    for (i = 2; i <= np; ++i)
        if (P[i] ~ /^mf_(ndf|ibm|ltc|tabulated|albedo_table|dielectric_ms_table|ltc_table|leadr_map|gonio|ltc_fit_result) \*/) complain("the filled object " N[i] " is not first")
    # fallible operations return mf_result
    if ((name ~ /_(build|build_ex|load|save|generate|generate_ex|measure|init|from_heights|from_normals|from_ndf|export_rgba16f|model)$/ ||
         name == "mf_microsurface_integrate" || name == "mf_ltc_fit") && ret != "mf_result")
        complain("a builder, loader or generator returns mf_result")
    if (ret == "int" && !(name in intok) && name !~ /_(is|has)_/) complain("int return: not a predicate named as a question, a count or an index")
}
END {
    if (n < 100) { print "api rules: only " n " public functions found: the pattern is broken"; exit 1 }
    if (bad) exit 1
    print "api rules: " n " public functions follow the 0.4 rules"
}
' microfacet.h
