#!/bin/sh
# Configuration checks of the generated header (part of make test):
#  1. each module opt-out (MF_NO_*), alone in one precision and all of them
#     together in both, compiles without a warning (-Werror, C99; all of them
#     also C++11) and leaves a working library;
#  2. defining only one of MF_MALLOC / MF_FREE stops with an #error saying so;
#  3. a unit built with MF_USE_DOUBLE does not link against a float
#     implementation (nor the reverse), and the error names the tagged symbol;
#  4. one program may hold both precisions (each unit with its own implementation);
#  4b. the precision guard: a float/double mix does not link even when the
#     unit of the other precision calls only inline functions (an mf_ndf handed
#     across, tests/guard_a.c and guard_b.c), and the error names the
#     precision; a program of inline calls only needs an implementation (the
#     error names the precision) and links with one; both precisions, each
#     with its implementation, link and agree;
#  5. the samplers draw the same samples whatever compiles them: the digest of
#     tests/determinism_check.c from CC and clang (when present) in float
#     and double, CXX in float, -O1, contraction off (C leaves argument evaluation order to the
#     compiler: two draws passed as arguments once differed between gcc and clang).
CC=$1; CXX=$2; WARN=$3; B=$4
fail() { echo "config check: $*"; exit 1; }
# each opt-out alone in one precision (they alternate), all of them in both
# (the whole header, no opt-out, is compiled with -Werror by tests/warnings.sh)
ALL_OUT="-DMF_NO_LEADR -DMF_NO_LTC_TABLE -DMF_NO_IBM -DMF_NO_MICROSURFACE"
for case in "-DMF_NO_LEADR|" "-DMF_NO_LTC_TABLE|-DMF_USE_DOUBLE" "-DMF_NO_IBM|" \
            "-DMF_NO_MICROSURFACE|-DMF_USE_DOUBLE" "-DMF_NO_ENERGY_TABLES|" "$ALL_OUT|" "$ALL_OUT|-DMF_USE_DOUBLE"; do
  opt=${case%|*}; prec=${case#*|}
  $CC -std=c99 $WARN -Werror $opt $prec -I. tests/optout_check.c -o $B/optout -lm || fail "opt-out '$opt $prec' (C)"
  $B/optout || fail "opt-out '$opt $prec' does not work"
done
echo "config check: module opt-outs: ok"
$CXX -x c++ -std=c++11 $WARN -Werror $ALL_OUT -I. -c tests/optout_check.c -o $B/optout_cxx.o || fail "opt-out '$ALL_OUT' (C++)"
for one in "-DMF_MALLOC(n)=malloc(n)" "-DMF_FREE(p)=free(p)"; do
  out=$($CC -std=c99 "$one" -I. -c tests/mix_impl.c -o $B/one.o 2>&1) && fail "$one alone compiled"
  echo "$out" | grep -q "define both or neither" || fail "$one alone: no clear #error"
done
echo "config check: the allocator pair: ok"
$CC -std=c99 -O0 -I. -c tests/mix_impl.c -o $B/impl_f.o || fail "float implementation"
$CC -std=c99 -O0 -DMF_USE_DOUBLE -I. -c tests/mix_impl.c -o $B/impl_d.o || fail "double implementation"
out=$($CC -std=c99 -DMF_USE_DOUBLE -I. tests/mix_main.c $B/impl_f.o -o $B/mix_bad -lm 2>&1) && fail "double unit linked against a float implementation"
echo "$out" | grep -q "mf_tabulated_from_ndf_f64" || fail "double vs float: the link error does not name mf_tabulated_from_ndf_f64"
out=$($CC -std=c99 -I. tests/mix_main.c $B/impl_d.o -o $B/mix_bad -lm 2>&1) && fail "float unit linked against a double implementation"
echo "$out" | grep -q "mf_tabulated_from_ndf_f32" || fail "float vs double: the link error does not name mf_tabulated_from_ndf_f32"
$CC -std=c99 -O0 -DMF_USE_DOUBLE -I. -c tests/mix_other.c -o $B/mix_other_d.o || fail "double half"
$CC -std=c99 -O1 -DMIX_BOTH -I. tests/mix_main.c $B/impl_f.o $B/mix_other_d.o -o $B/mix_both -lm || fail "both precisions in one program do not link"
$B/mix_both >/dev/null || fail "both precisions in one program disagree"
for lang in "$CC -std=c99" "$CXX -x c++ -std=c++11"; do
  ld=${lang%% *}
  for pa in float double; do
    if [ $pa = float ]; then da=; db=-DMF_USE_DOUBLE; impl_b=$B/impl_d.o; else da=-DMF_USE_DOUBLE; db=; impl_b=$B/impl_f.o; fi
    $lang -O2 $WARN -Werror $da -I. -c tests/guard_a.c -o $B/guard_a.o || fail "guard_a.c ($lang $pa)"
    $lang -O2 $WARN -Werror $db -DGUARD_MIX -I. -c tests/guard_b.c -o $B/guard_mix.o || fail "guard_b.c ($lang)"
    out=$($ld $B/guard_a.o $B/guard_mix.o $impl_b -o $B/guard_bad -lm 2>&1) &&
      fail "$lang: a $pa unit of inline calls linked with a unit and an implementation of the other precision"
    echo "$out" | grep -q "mf_precision_is_${pa}_" || fail "$lang: the float/double mix's link error does not name mf_precision_is_${pa}_...: $out"
  done
done
# the same where the linker drops unreferenced sections (-Wl,--gc-sections)
echo 'int main(void) { return 0; }' > $B/gc.c
if $CC -Wl,--gc-sections $B/gc.c -o $B/gc 2>/dev/null; then
  $CC -std=c99 -O2 -ffunction-sections -fdata-sections -I. -c tests/guard_a.c -o $B/guard_a.o || fail "guard_a.c (sections)"
  $CC -std=c99 -O2 -ffunction-sections -fdata-sections -DMF_USE_DOUBLE -DGUARD_MIX -I. -c tests/guard_b.c -o $B/guard_mix.o || fail "guard_b.c (sections)"
  out=$($CC -Wl,--gc-sections $B/guard_a.o $B/guard_mix.o $B/impl_d.o -o $B/guard_bad -lm 2>&1) &&
    fail "--gc-sections: a float unit of inline calls linked with a unit and an implementation of double precision"
  echo "$out" | grep -q "mf_precision_is_float_" || fail "--gc-sections: the link error does not name mf_precision_is_float_...: $out"
fi
$CC -std=c99 -O2 $WARN -Werror -I. -c tests/guard_a.c -o $B/guard_a.o || fail "guard_a.c"
$CC -std=c99 -O2 $WARN -Werror -I. -c tests/guard_b.c -o $B/guard_b.o || fail "guard_b.c"
out=$($CC $B/guard_a.o $B/guard_b.o -o $B/guard_bad -lm 2>&1) && fail "a program of inline calls linked without an implementation"
echo "$out" | grep -q "mf_precision_is_float_" || fail "no implementation: the link error does not name mf_precision_is_float_...: $out"
$CC $B/guard_a.o $B/guard_b.o $B/impl_f.o -o $B/guard_ok -lm || fail "inline calls with a float implementation do not link"
$B/guard_ok >/dev/null || fail "inline calls with a float implementation: wrong value"
$CC -std=c99 -O2 $WARN -Werror -I. -c tests/guard_a.c -o $B/guard_a.o || fail "guard_a.c"
$CC -std=c99 -O2 $WARN -Werror -DMF_USE_DOUBLE -I. -c tests/guard_b.c -o $B/guard_b.o || fail "guard_b.c (double)"
$CC $B/guard_a.o $B/impl_f.o $B/guard_b.o $B/impl_d.o -o $B/guard_both -lm || fail "float and double units of inline calls, each precision with its implementation, do not link"
$B/guard_both >/dev/null || fail "float and double units of inline calls disagree"
echo "config check: precision mixing (inline-only units too, --gc-sections): ok"
# the samplers need none of the large optional modules: left out, the
# implementation compiles in a fraction of the time
NO_BIG=$ALL_OUT
for prec in "" -DMF_USE_DOUBLE; do
  ref=""
  for c in "$CC -std=c99" "$CXX -x c++" clang; do
    [ "$c" = clang ] && { command -v clang >/dev/null 2>&1 || continue; c="clang -std=c99"; }
    [ -n "$prec" ] && [ "$c" = "$CXX -x c++" ] && continue
    $c -O1 -ffp-contract=off $prec $NO_BIG -I. tests/determinism_check.c -o $B/determinism -lm || fail "determinism check: $c $prec does not build"
    got=$($B/determinism) || fail "determinism check: $c $prec failed"
    [ -z "$ref" ] && { ref=$got; refc=$c; }
    [ "$got" = "$ref" ] || fail "samples differ between $refc and $c $prec: $ref / $got"
  done
done
echo "config check: the samplers draw the same samples under every compiler: ok"
