#!/bin/sh
# The README's programs compile and run, so they cannot rot:
# - the quick start: the first C block after "## Quick start", a complete
#   program that defines the implementation itself;
# - every C block under "## Recipes": complete programs that include the
#   header only, linked with one implementation object per language.
# Each is compiled as C99 and C++11 with -Werror, must exit 0 and must print
# the same as C and as C++. ```cuda blocks need nvcc and no GPU; they are
# compiled (nvcc -c) only when README_NVCC names the compiler
# (README_NVCC=nvcc), so that make test does not depend on nvcc. The README
# stays at most 350 lines.
# Usage: sh tests/readme_check.sh CC CXX "WARNINGS" BUILD_DIR
CC=$1; CXX=$2; WARN=$3; B=$4
fail() { echo "readme check: $*"; exit 1; }
[ -d "$B" ] || fail "no build directory '$B'"
lines=$(wc -l < README.md)
[ "$lines" -le 350 ] || fail "README.md has $lines lines (at most 350)"

# both languages of one program: $1 the source, $2 the output name, $3 extra objects (C), $4 (C++)
build_and_run() {
    $CC -std=c99 $WARN -Werror -I. "$1" $3 -o "$2" -lm || fail "$1 does not compile as C99"
    $CXX -x c++ -std=c++11 $WARN -Werror -I. "$1" -x none $4 -o "$2_cxx" -lm || fail "$1 does not compile as C++11"
    out=$("$2") || fail "$1 fails (C): $out"
    out_cxx=$("$2_cxx") || fail "$1 fails (C++): $out_cxx"
    [ "$out" = "$out_cxx" ] || fail "$1: C and C++ builds print different results: '$out' / '$out_cxx'"
    [ -n "$out" ] || fail "$1 printed nothing"
    echo "$out"
}

awk '/^## Quick start/ { q = 1 } q && /^```c$/ { c = 1; next } c && /^```$/ { exit } c { print }' README.md > $B/quickstart.c
[ -s $B/quickstart.c ] || fail "no C block under '## Quick start' in README.md"
grep -q "int main" $B/quickstart.c || fail "the quick start is not a complete program"
build_and_run $B/quickstart.c $B/quickstart "" ""
echo "$out" | grep -q "throughput" || fail "the quick start printed no sample: $out"
echo "readme check: the quick start compiles (C99, C++11, -Werror) and runs"

# the recipes: $B/recipe_N.c (```c) and $B/recipe_N.cu (```cuda), N from 1;
# "Prints `TEXT`" in the prose before a block: $B/recipe_N.expect, TEXT
# without a trailing "..." (the program's output must contain it)
rm -f $B/recipe_*
awk -v dir="$B" '
    /^## / { r = ($0 ~ /^## Recipes/) }
    r && !f && /Prints `[^`]*`/ { e = $0; sub(/.*Prints `/, "", e); sub(/`.*/, "", e); sub(/,? *\.\.\.$/, "", e) }
    r && !f && /^```(c|cuda)$/ {
        n++; f = dir "/recipe_" n (($0 ~ /cuda/) ? ".cu" : ".c")
        if (e != "") { print e > (dir "/recipe_" n ".expect"); close(dir "/recipe_" n ".expect"); e = "" }
        next
    }
    f && /^```$/ { close(f); f = ""; next }
    f { print > f }
' README.md
ls $B/recipe_*.c > /dev/null 2>&1 || fail "no C block under '## Recipes' in README.md"
printf '#define MICROFACET_IMPLEMENTATION\n#include "microfacet.h"\n' > $B/readme_impl.c
$CC -std=c99 $WARN -Werror -I. -c $B/readme_impl.c -o $B/readme_impl.o || fail "the implementation does not compile as C99"
$CXX -x c++ -std=c++11 $WARN -Werror -I. -c $B/readme_impl.c -o $B/readme_impl_cxx.o ||
    fail "the implementation does not compile as C++11"
n=0
for src in $B/recipe_*.c; do
    grep -q "int main" $src || fail "$src (a recipe) is not a complete program"
    build_and_run $src ${src%.c} $B/readme_impl.o $B/readme_impl_cxx.o
    if [ -f ${src%.c}.expect ]; then
        want=$(cat ${src%.c}.expect)
        case "$out" in *"$want"*) ;; *) fail "$src prints '$out', the README says it prints '$want'" ;; esac
    fi
    n=$((n + 1))
done
echo "readme check: $n recipes compile (C99, C++11, -Werror) and run"
for src in $B/recipe_*.cu; do
    [ -f "$src" ] || continue
    if [ -n "$README_NVCC" ]; then
        $README_NVCC -std=c++17 -Werror all-warnings -I. -c $src -o ${src%.cu}.o || fail "$src does not compile with nvcc"
        echo "readme check: $src compiles with $README_NVCC"
    else
        echo "readme check: $src (CUDA) not compiled (README_NVCC=nvcc compiles it)"
    fi
done
