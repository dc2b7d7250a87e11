#!/bin/sh
# sum_results.sh DIR STEP...: one line per step, then the total
# "N passed, N failed" as the last line; exits non-zero on any failure or
# missing step.
dir=$1; shift
passed=0; failed=0
for s in "$@"; do
  if [ -f "$dir/$s" ]; then
    read -r p f < "$dir/$s"
    printf '  %-12s %s passed, %s failed\n' "$s" "$p" "$f"
  else
    p=0; f=1; printf '  %-12s FAIL: did not run\n' "$s"
  fi
  passed=$((passed + p)); failed=$((failed + f))
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
