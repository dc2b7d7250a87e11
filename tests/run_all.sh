#!/bin/sh
# Runs the header warning check (when given make) and each test binary; sums
# their "N passed, N failed" lines; the last line printed is the total.
make_cmd=$1; shift
passed=0; failed=0
if [ -n "$make_cmd" ]; then
  if $make_cmd --no-print-directory header-check; then passed=$((passed + 1)); echo "header check: ok (microfacet.h is src/ assembled)"
  else failed=$((failed + 1)); echo "FAIL header check"; fi
  if $make_cmd --no-print-directory config-check; then passed=$((passed + 1))
  else failed=$((failed + 1)); echo "FAIL config check"; fi
  if $make_cmd --no-print-directory fastmath-check; then passed=$((passed + 1)); echo "fast-math check: ok (NaN/Inf data never index memory under -ffast-math)"
  else failed=$((failed + 1)); echo "FAIL fast-math check (build/fastmath_f, build/fastmath_d)"; fi
  fz=$($make_cmd --no-print-directory -s fuzz-smoke 2>&1)
  printf '%s\n' "$fz"
  passed=$((passed + $(printf '%s\n' "$fz" | grep -c '^fuzz ok')))
  failed=$((failed + $(printf '%s\n' "$fz" | grep -c '^FAIL')))
  if $make_cmd --no-print-directory warnings; then passed=$((passed + 1)); echo "warnings check: ok"
  else failed=$((failed + 1)); echo "FAIL warnings check"; fi
fi
for b in "$@"; do
  out=$("$b" 2>&1); rc=$?
  printf '%s\n' "$out" | grep -v '^ok ' | sed '$d'
  line=$(printf '%s\n' "$out" | tail -n 1)
  p=$(printf '%s\n' "$line" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\1/p')
  f=$(printf '%s\n' "$line" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\2/p')
  if [ -z "$p" ]; then echo "FAIL $b did not finish (exit $rc)"; failed=$((failed + 1)); continue; fi
  echo "$b: $line"
  passed=$((passed + p)); failed=$((failed + f))
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then failed=$((failed + 1)); fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
