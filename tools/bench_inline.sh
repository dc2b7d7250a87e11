#!/bin/sh
# bench_inline.sh - the hot paths at three builds: -O2 (the reference), -O3
# -march=native, and -O2 in a large translation unit (bench/big_tu.h adds 48
# functions calling the whole inline API). Runs the bench's core sections
# (`bench sections`: ggx, kinds, transformed, leadr, ltc) one at a time, each section in the
# three builds in turn, the builds' order rotating from round to round; the
# short sections (under 0.4 s) run 4 times a round. Prints per line the best
# (least) ns of each build over all runs and the ratios of the bests, O3/O2
# and bigTU/O2 (below 1 is faster). Best of many short runs: this shared
# machine's speed changes by up to 2x on some lines from one run to the next
# (seconds apart), so a
# line's runs spread over time, and a build's best is its time in the fast
# state as long as one of its runs met it (20 runs a line and build at the
# default 5 rounds; 5 for the LTC lines, whose times hardly move).
# Usage: tools/bench_inline.sh [CC] [ROUNDS] [extra flags, e.g. -DMF_USE_DOUBLE]
CC=${1:-cc}; ROUNDS=${2:-5}; EXTRA=$3
B=build/bench_inline
set -e
mkdir -p $B
$CC -std=c99 -O2 $EXTRA -I. bench/bench.c -o $B/o2 -lm
$CC -std=c99 -O3 -march=native $EXTRA -I. bench/bench.c -o $B/o3 -lm
$CC -std=c99 -O2 -DMF_BENCH_BIG_TU $EXTRA -I. bench/bench.c -o $B/big -lm
sections=$(./$B/o2 sections)   # the bench's own list
r=1
while [ $r -le "$ROUNDS" ]; do
  case $((r % 3)) in
    1) builds="o2 o3 big" ;;
    2) builds="o3 big o2" ;;
    *) builds="big o2 o3" ;;
  esac
  for s in $sections; do
    n=4; [ $s = ltc ] && n=1
    for v in $builds; do
      i=1
      while [ $i -le $n ]; do
        ./$B/$v core:$s | awk -v v=$v '$1 == "bench" && $3 ~ /^[0-9.]+$/ { print v, $2, $3 }'
        i=$((i + 1))
      done
    done
  done
  r=$((r + 1))
done > $B/raw.txt
awk '
function least(s,   a, n, i, m) {
  n = split(s, a, " "); m = a[1] + 0;
  for (i = 2; i <= n; ++i) if (a[i] + 0 < m) m = a[i] + 0;
  return m
}
{ key = $2; if (!(key in seen)) { seen[key] = 1; order[++nk] = key }
  t[$1, key] = t[$1, key] " " $3 }
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
