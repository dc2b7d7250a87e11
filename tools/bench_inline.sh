#!/bin/sh
# bench_inline.sh - the hot paths at three builds: -O2 (the reference), -O3
# -march=native, and -O2 in a large translation unit (bench/big_tu.h adds 48
# functions calling the whole inline API). Runs the bench's core section of
# each build ROUNDS times (default 5), alternating, and prints per line the
# best (least) ns of each build over the rounds and the ratios of the bests,
# O3/O2 and bigTU/O2 (below 1 is faster). Best rather than median: on a
# machine whose speed state changes between runs, a round whose binary ran
# slow drops out as long as one round of each build ran fast. Usage: tools/bench_inline.sh [CC] [ROUNDS] [extra flags, e.g. -DMF_USE_DOUBLE]
CC=${1:-cc}; ROUNDS=${2:-5}; EXTRA=$3
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
function least(s,   a, n, i, m) {
  n = split(s, a, " "); m = a[1] + 0;
  for (i = 2; i <= n; ++i) if (a[i] + 0 < m) m = a[i] + 0;
  return m
}
{ key = $3; if (!(key in seen)) { seen[key] = 1; order[++nk] = key }
  t[$1, key] = t[$1, key] " " $4 }
END {
  printf "%-44s %10s %10s %10s %7s %7s\n", "line", "O2_ns", "O3nat_ns", "bigTU_ns", "O3/O2", "big/O2";
  for (k = 1; k <= nk; ++k) {
    key = order[k];
    if (t["o2", key] == "" || t["o3", key] == "" || t["big", key] == "") continue;
    o2 = least(t["o2", key]); o3 = least(t["o3", key]); bg = least(t["big", key]);
    if (!(o2 > 0)) continue;
    printf "%-44s %10.2f %10.2f %10.2f %7.3f %7.3f\n", key, o2, o3, bg, o3 / o2, bg / o2
  }
}' $B/raw.txt
