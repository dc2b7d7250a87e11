#!/bin/sh
# Examples stay buildable and their image output stays valid: every example
# passes the compiler's front end with -Werror (-fsyntax-only; make demo
# builds and links them; with the OpenEXR writer too when found), and
# tests/examples_check.c checks the PNG writer, sRGB, the font and the colour map.
CC=$1; WARN=$2; B=$3; EXR_DEFS=$4; EXR_LIBS=$5
fail() { echo "examples check: $*"; exit 1; }
mkdir -p $B/examples_check
for e in examples/*.c; do
  # shellcheck disable=SC2086
  $CC -std=c99 -fsyntax-only $WARN -Werror $EXR_DEFS -I. "$e" || fail "$e does not compile"
done
$CC -std=c99 -O0 $WARN -Werror -I. tests/examples_check.c -o $B/examples_check/check -lm || fail "examples_check.c"
$B/examples_check/check $B/examples_check
