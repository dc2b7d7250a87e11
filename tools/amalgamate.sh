#!/bin/sh
# Assembles the single header microfacet.h from the module sources src/*.h.
#
#   sh tools/amalgamate.sh > microfacet.h      (what `make header` runs)
#
# Modules are read in file-name order (src/00_intro.h ... src/99_outro.h); the
# number in a name is the module's place in the dependency order: a module may
# use only what the modules before it define. Inside a module, marker lines
# start its parts, and the header gathers each part from every module in turn:
#
#   /* @decl */  types needed before the mf_ndf type (configuration, vectors,
#                the per-kind parameter structs); outside extern "C"
#   /* @api */   declarations and the hot inline paths: what every includer
#                compiles (the default part)
#   /* @cold */  code that device code may call but host includers need not
#                compile: emitted once in the implementation on host builds,
#                and in every translation unit under nvcc
#   /* @impl */  the implementation section (builders, loaders, fitters,
#                generators, data tables)
#
# A module whose first line is "/* @optional MF_NO_X */" can be left out by
# defining MF_NO_X: each of its parts is wrapped in #ifndef MF_NO_X.
#
# 00_intro.h (the top comment) and 99_outro.h (the license) are copied as they
# are. Every function declared with MFDEF or MF_COLD in a module gets a
# precision-tagged symbol name (see MF__SYM in 01_config.h), listed where
# 01_config.h holds the line "/* @symbols */". Needs only sh and awk.
#
#   sh tools/amalgamate.sh --ordered > ordered.h   (module by module)
#
# --ordered prints the code module by module instead: every @decl part first
# (as in the header: the kinds' parameter structs that the mf_ndf type of
# 05_ndf.h holds), then each module's @api, @cold and @impl parts in turn,
# after a line "/* @module src/NN_name.h */", with no section guards.
# tools/prefix_check.sh (run by `make header`) compiles it: a module that uses
# a later one fails there, named.
#
#   sh tools/amalgamate.sh --readme > README.md.tmp   (also run by `make header`)
#   sh tools/amalgamate.sh --api > docs/API.md          (likewise)
#
# --readme prints README.md with the block between its lines
# "<!-- api-index:begin -->" and "<!-- api-index:end -->" replaced by the
# compact API index (one line per module naming its functions); --api prints
# docs/API.md, one line per public function with its signature, grouped by
# module. Both come from tools/api_index.awk on the same module sources;
# `make test` fails when the committed files differ.
set -e
cd "$(dirname "$0")/.."
files=$(ls src/[0-9]*.h | LC_ALL=C sort)
ordered=0
if [ "${1:-}" = --ordered ]; then ordered=1; shift; fi
if [ "${1:-}" = --api ]; then
    awk -f tools/api_index.awk $files
    exit
fi
if [ "${1:-}" = --readme ]; then
    awk -v compact=1 -f tools/api_index.awk $files | awk '
    NR == FNR { idx = idx $0 "\n"; next }
    $0 == "<!-- api-index:begin -->" { printf "%s\n%s", $0, idx; inside = 1; begun++; next }
    $0 == "<!-- api-index:end -->" { inside = 0; ended++ }
    !inside { print }
    END {
        if (begun != 1 || ended != 1) {
            print "amalgamate.sh: README.md needs one <!-- api-index:begin --> line and one <!-- api-index:end --> line after it" > "/dev/stderr"
            exit 1
        }
    }' - README.md
    exit
fi
awk -v ordered="$ordered" '
function emit(s) { printf "%s", s }
function close_guard() { if (guard != "") for (p in open_) if (open_[p]) { buf[p] = buf[p] "#endif /* " guard " */\n"; open_[p] = 0 } }
FNR == 1 {
    close_guard(); guard = ""; ++nfile
    if ($0 ~ /^\/\* @optional MF_NO_[A-Z_]+ \*\/$/) { guard = $3 }
    part = "api"; base = FILENAME; sub(/^.*\//, "", base)
    names = names " " base
    if (base ~ /^00_/) part = "intro"
    if (base ~ /^99_/) part = "outro"
}
/^\/\* @optional MF_NO_[A-Z_]+ \*\/$/ { next }
/^\/\* @(decl|api|cold|impl) \*\/$/ { part = $2; sub(/^@/, "", part); next }
{
    if (guard != "" && !open_[part]) { buf[part] = buf[part] "#ifndef " guard "\n"; open_[part] = 1 }
    if (part == "decl" && $0 == "/* @symbols */") { buf[part] = buf[part] "@SYMBOLS@\n"; next }
    buf[part] = buf[part] $0 "\n"
    if (ordered && part != "decl") mod[nfile, part] = mod[nfile, part] $0 "\n"
    if ((part == "api" || part == "decl") && $0 ~ /^(MFDEF|MF_COLD) [^(]*[ *]mf_[A-Za-z0-9_]+\(/) {
        s = $0; sub(/\(.*/, "", s); sub(/^.*[ *]/, "", s)
        if (!(s in seen)) { seen[s] = 1; syms = syms "#define " s " MF__SYM(" s ")\n" }
    }
}
END {
    close_guard()
    if (ordered) {
        n = split(names, list, " ")
        d = buf["decl"]; sub(/@SYMBOLS@\n/, syms, d)
        emit(d)
        for (i = 1; i <= n; ++i) {
            if (list[i] ~ /^(00|99)_/) continue
            emit("/* @module src/" list[i] " */\n" mod[i, "api"] mod[i, "cold"] mod[i, "impl"])
        }
        exit
    }
    emit("/* microfacet.h - GENERATED FILE, do not edit: edit the module sources in\n")
    emit(" * src/ and run `make header` (tools/amalgamate.sh). Assembled from:\n")
    n = split(names, list, " ")
    line = " *  "
    for (i = 1; i <= n; ++i) {
        if (length(line) + length(list[i]) > 78) { emit(line "\n"); line = " *  " }
        line = line " " list[i]
    }
    emit(line "\n */\n")
    emit(buf["intro"])
    emit("#ifndef MICROFACET_H\n#define MICROFACET_H\n\n")
    d = buf["decl"]; sub(/@SYMBOLS@\n/, syms, d)
    emit(d)
    emit("\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n")
    emit(buf["api"])
    emit("\n#ifdef __cplusplus\n}\n#endif\n\n#endif /* MICROFACET_H */\n\n")
    emit("/* ======================================================================== */\n")
    emit("/* == Cold paths: compiled once, in the implementation, on host builds;    */\n")
    emit("/* == in every translation unit under nvcc (device code calls them).       */\n")
    emit("/* ======================================================================== */\n")
    emit("#if (defined(MICROFACET_IMPLEMENTATION) || defined(__CUDACC__)) && !defined(MICROFACET_COLD_DONE)\n")
    emit("#define MICROFACET_COLD_DONE\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n")
    emit(buf["cold"])
    emit("\n#ifdef __cplusplus\n}\n#endif\n#endif /* cold paths */\n\n")
    emit("/* ======================================================================== */\n")
    emit("/* == Implementation: builders, loaders, fitters, generators, data tables  */\n")
    emit("/* ======================================================================== */\n")
    emit("#if defined(MICROFACET_IMPLEMENTATION) && !defined(MICROFACET_IMPLEMENTATION_DONE)\n")
    emit("#define MICROFACET_IMPLEMENTATION_DONE\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n")
    emit(buf["impl"])
    emit("\n#ifdef __cplusplus\n}\n#endif\n#endif /* MICROFACET_IMPLEMENTATION */\n")
    emit(buf["outro"])
}
' $files
