#!/bin/sh
# Each module may use only the modules before it (tools/amalgamate.sh). This
# compiles the code module by module (sh tools/amalgamate.sh --ordered: every
# @decl part, then each module's @api, @cold and @impl parts in file-name
# order) as C99 with MICROFACET_IMPLEMENTATION defined, in float: a name used
# before the module that declares it is an error there, so this is every
# prefix of the module list at once (the header made of the first K modules,
# K = 1..N), in one compile. Then the whole header in double. A failure names
# the module that uses a later one.
#
#   sh tools/prefix_check.sh [CC]       (run by `make header`, make test step prefix)
#
# Syntax only (-fsyntax-only); an implicit function declaration is an error.
# A declaration whose definition comes later (05_ndf.h declares the functions
# the kinds' traits promise; they define them) passes.
set -e
cd "$(dirname "$0")/.."
cc=${1:-cc}
tmp=${TMPDIR:-/tmp}/mf_prefix.$$
mkdir -p "$tmp"
trap 'rm -rf "$tmp"' EXIT INT TERM
sh tools/amalgamate.sh --ordered > "$tmp/ordered.h"
sh tools/amalgamate.sh > "$tmp/microfacet.h"
n=$(grep -c '^/\* @module ' "$tmp/ordered.h")
# gcc reports an error inside a macro at the macro's definition unless told
# not to; clang reports it where the macro is used, and knows no such option
track=
printf 'int x;\n' > "$tmp/p.c"
$cc -ftrack-macro-expansion=0 -fsyntax-only "$tmp/p.c" > /dev/null 2>&1 && track=-ftrack-macro-expansion=0
printf '#define MICROFACET_IMPLEMENTATION\n#include "ordered.h"\n' > "$tmp/o.c"
printf '#define MICROFACET_IMPLEMENTATION\n#include "microfacet.h"\n' > "$tmp/h.c"
for t in o:float h:double; do
    def=; [ ${t#*:} = double ] && def=-DMF_USE_DOUBLE
    if ! $cc -std=c99 -fsyntax-only $def -Werror=implicit-function-declaration -Werror=implicit-int $track \
            -I"$tmp" "$tmp/${t%:*}.c" > "$tmp/err" 2>&1; then
        line=$(sed -n 's/^[^:]*ordered\.h:\([0-9][0-9]*\):[0-9]*: error.*/\1/p' "$tmp/err" | head -n 1)
        if [ -n "$line" ]; then
            mod=$(awk -v l="$line" 'NR > l { exit } /^\/\* @module / { m = $3 } END { print m }' "$tmp/ordered.h")
            echo "prefix_check: $mod uses a later module (or an undeclared name): it does not compile after the modules before it:"
        else
            echo "prefix_check: the header does not compile (${t#*:}):"
        fi
        grep -E 'error' "$tmp/err" | sed "s|$tmp/||" | head -n 8
        exit 1
    fi
done
echo "prefix_check: each of the $n modules compiles after the ones before it (float); the header in double"
