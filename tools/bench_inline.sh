#!/bin/sh
# bench_inline.sh - the hot paths at three builds: -O2 (the reference), -O3
# -march=native, and -O2 in a large translation unit (bench/big_tu.h adds 48
# functions calling the whole inline API). Runs the bench's core section of
# each build ROUNDS times (default 3), alternating, and prints per line the
# median ns of each build and the median ratios O3/O2 and bigTU/O2 (below 1
# is faster). Usage: tools/bench_inline.sh [CC] [ROUNDS] [extra flags, e.g. -DMF_USE_DOUBLE]
CC=${1:-cc}; ROUNDS=${2:-3}; EXTRA=$3
B=build/bench_inline
set -e
mkdir -p $B
$CC -std=c99 -O2 $EXTRA -I. bench/bench.c -o $B/o2 -lm
$CC -std=c99 -O3 -march=native $EXTRA -I. bench/bench.c -o $B/o3 -lm
$CC -std=c99 -O2 -DMF_BENCH_BIG_TU $EXTRA -I. bench/bench.c -o $B/big -lm
r=1
while [ $r -le "$ROUNDS" ]; do
  for v in o2 o3 big; do ./$B/$v core | awk -v v=$v -v r=$r '$1 == "bench" && $3 ~ /^[0-9.]+$/ { print v, r, $2, $3 }'; done
  r=$((r + 1))
done > $B/raw.txt
awk '
function median(s,   a, n, i, j, t) {
  n = split(s, a, " ");
  for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (a[j] + 0 < a[i] + 0) { t = a[i]; a[i] = a[j]; a[j] = t }
  return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
{ key = $3; if (!(key in seen)) { seen[key] = 1; order[++nk] = key }
  t[$1, key] = t[$1, key] " " $4; rr[$1, $2, key] = $4 }
END {
  printf "%-44s %10s %10s %10s %7s %7s\n", "line", "O2_ns", "O3nat_ns", "bigTU_ns", "O3/O2", "big/O2";
  for (k = 1; k <= nk; ++k) {
    key = order[k]; so = ""; sb = "";
    for (r = 1; r <= '"$ROUNDS"'; ++r) if (rr["o2", r, key] > 0) {
      so = so " " rr["o3", r, key] / rr["o2", r, key]; sb = sb " " rr["big", r, key] / rr["o2", r, key] }
    if (so == "") continue;
    printf "%-44s %10.2f %10.2f %10.2f %7.3f %7.3f\n", key, median(t["o2", key]), median(t["o3", key]),
           median(t["big", key]), median(so), median(sb)
  }
}' $B/raw.txt
