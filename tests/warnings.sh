#!/bin/sh
# The header compiles without a warning (-Werror) as C99, C11 and C++98..20,
# float and double, with gcc/g++ and (when present) clang/clang++, and in two
# translation units linked together; warn_check.c names every public function.
CC=$1; CXX=$2; HAVE_CLANG=$3; WARN=$4; B=$5
set -e
# every public function of the header (inline, cold or in the implementation)
# must be named in tests/warn_check.c, so each one is compiled and instantiated
missing=$(grep -oE '^(MF_INLINE|MF_FORCE_INLINE|MF_COLD|MFDEF) [^(]*[ *]mf_[a-z][A-Za-z0-9_]*\(' microfacet.h |
          sed -E 's/.*[ *](mf_[A-Za-z0-9_]*)\($/\1/' | sort -u |
          while read -r f; do grep -q "\b$f\b" tests/warn_check.c || printf '%s ' "$f"; done)
if [ -n "$missing" ]; then echo "warnings: tests/warn_check.c does not name: $missing"; exit 1; fi
run() { "$@" || { echo "warnings: failed: $*"; exit 1; }; }
# every standard compiles the header with -Werror; two units linked together
# and run once per language and precision (C99, C++11)
for prec in "" "-DMF_USE_DOUBLE"; do
  # each standard parses the whole header (front-end warnings: -fsyntax-only);
  # the one linked below compiles to an object
  run $CC -std=c11 $WARN -Werror $prec -I. -fsyntax-only tests/warn_check.c
  run $CC -std=c99 $WARN -Werror $prec -I. -c tests/warn_check.c -o $B/wc.o
  run $CC -std=c99 $WARN -Werror $prec -DMFT_SECOND_TU -I. -c tests/warn_check.c -o $B/wc2.o
  run $CC $B/wc.o $B/wc2.o -o $B/wc -lm
  run $B/wc
  for std in c++98 c++14 c++17 c++20; do
    run $CXX -x c++ -std=$std $WARN -Werror $prec -I. -fsyntax-only tests/warn_check.c
  done
  run $CXX -x c++ -std=c++11 $WARN -Werror $prec -I. -c tests/warn_check.c -o $B/wcx.o
  run $CXX -x c++ -std=c++11 $WARN -Werror $prec -DMFT_SECOND_TU -I. -c tests/warn_check.c -o $B/wcx2.o
  run $CXX $B/wcx.o $B/wcx2.o -o $B/wcx -lm
  run $B/wcx
  if [ "$HAVE_CLANG" = yes ]; then
    run clang -std=c99 $WARN -Werror $prec -I. -fsyntax-only tests/warn_check.c
    run clang++ -x c++ -std=c++17 $WARN -Werror $prec -I. -fsyntax-only tests/warn_check.c
  fi
  p=float; [ -n "$prec" ] && p=double
  echo "warnings: $p: every standard and compiler clean, two units linked and run"
done
