#!/bin/sh
# The README's quick start is a complete program: extract the first C block
# after "## Quick start", compile it as C99 and C++11 with -Werror, run both.
CC=$1; CXX=$2; WARN=$3; B=$4
fail() { echo "readme check: $*"; exit 1; }
awk '/^## Quick start/ { q = 1 } q && /^```c$/ { c = 1; next } c && /^```$/ { exit } c { print }' README.md > $B/quickstart.c
[ -s $B/quickstart.c ] || fail "no C block under '## Quick start' in README.md"
grep -q "int main" $B/quickstart.c || fail "the quick start is not a complete program"
$CC -std=c99 $WARN -Werror -I. $B/quickstart.c -o $B/quickstart -lm || fail "does not compile as C99"
$CXX -x c++ -std=c++11 $WARN -Werror -I. $B/quickstart.c -o $B/quickstart_cxx -lm || fail "does not compile as C++11"
out=$($B/quickstart) || fail "the program fails"
echo "$out" | grep -q "throughput" || fail "the program printed no sample: $out"
[ "$out" = "$($B/quickstart_cxx)" ] || fail "C and C++ builds print different results"
echo "$out"
echo "readme check: the quick start compiles (C99, C++11, -Werror) and runs"
