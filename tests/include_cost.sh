#!/bin/sh
# What including the header costs a file that calls a few functions (part of
# make test): the -O0 text of the object (`size`: code, constants, unwind
# tables) and the -O2 compile time over an empty file, for
#   none.c   the include alone                    limit 0 bytes
#   two.c    mf_ggx + mf_brdf                     limits 8192 bytes, 0.15 s
#   three.c  mf_ggx + mf_brdf_sample + mf_brdf    limit 16384 bytes (its -O2
#                                                 time printed, not checked)
# The header's hot paths are inline, so every includer compiles what it calls
# and only that (a static function that is not inline is emitted by every -O0
# includer, used or not: none.c catches one). The sampler includer gets the
# larger limits: the visible-normal sampler and its pdf check are most of its
# code (and clang's -O0 code is about a quarter larger than gcc's). Float, the
# default precision, with the compiler make uses.
#
# Timing on a noisy machine (make test runs its steps in parallel, and other
# jobs may share the cores): the time is the compiler's CPU time (user + sys,
# GNU time), not the wall clock, so waiting for a core does not count; noise
# only ever adds time, so each figure is the best of 3 runs, the includer and
# the empty file measured in turn; a figure over its limit is measured again,
# twice more (best of 9), before the step fails; if the machine is then
# overloaded (load average above the number of cores, where CPU time itself
# grows), the figure is printed and not counted. Without GNU time the timing
# is skipped, with a line saying so.
#
# The limit holds on this machine kind at its usual speed, where calib.c (30
# small loop functions, generated below) compiles at -O2 in CALIB_REF = 0.20 s
# of CPU. The same VM's CPU time for one compile moved by 1.7x within a day
# (the same header's two.c: 0.09 s, later 0.15 s, idle both times), so the
# limit is scaled by calib.c's time over CALIB_REF when that is above 1 (a
# slower machine or state), never below.
#
# usage: sh tests/include_cost.sh CC BUILD_DIR
CC=${1:-cc}; B=${2:-build}
T=$B/include_cost
mkdir -p "$T" || exit 1
fail=0
cat > "$T/empty.c" <<'EOF'
int mf_include_cost_empty;
EOF
awk 'BEGIN { for (i = 0; i < 30; ++i) printf "double f%d(const double *x, int n) { double s = 0; int i; for (i = 0; i < n; ++i) { s += x[i] * %d.5 - s * 0.25; if (s > %d) s = s / 3 + x[(i * 7) %% n]; } return s; }\n", i, i, i * 10 }' > "$T/calib.c"
CALIB_REF=0.20
cat > "$T/none.c" <<'EOF'
#include "microfacet.h"
EOF
cat > "$T/two.c" <<'EOF'
#include "microfacet.h"
mf_real two(mf_vec3 wo, mf_vec3 wi, mf_real alpha);
mf_real two(mf_vec3 wo, mf_vec3 wi, mf_real alpha)
{
    mf_ndf d = mf_ggx(alpha, alpha);
    return mf_brdf(&d, wo, wi);
}
EOF
# __typeof__: the file stays valid whatever record the sampler returns
cat > "$T/three.c" <<'EOF'
#include "microfacet.h"
#include <string.h>
void three(mf_vec3 wo, mf_vec3 wi, mf_real alpha, mf_real u1, mf_real u2, mf_real *f, void *sample);
void three(mf_vec3 wo, mf_vec3 wi, mf_real alpha, mf_real u1, mf_real u2, mf_real *f, void *sample)
{
    mf_ndf d = mf_ggx(alpha, alpha);
    __typeof__(mf_brdf_sample(&d, wo, u1, u2)) s = mf_brdf_sample(&d, wo, u1, u2);
    memcpy(sample, &s, sizeof s);
    *f = mf_brdf(&d, wo, wi);
}
EOF
GNU_TIME=
if [ -x /usr/bin/time ] && /usr/bin/time -f '%U' true >/dev/null 2>&1; then GNU_TIME=/usr/bin/time; fi
# cpu FILE: CPU seconds of one -O2 compile of FILE
cpu() {
  $GNU_TIME -f '%U %S' -o "$T/time" $CC -std=c99 -O2 -I. -c "$1" -o "$T/o2.o" || return 1
  awk '{ printf "%.2f\n", $1 + $2 }' "$T/time"
}
# extra FILE ROUNDS: best CPU seconds of FILE and of the empty file over
# ROUNDS interleaved runs, printed "file empty"
extra() {
  bf=99; be=99; i=0
  while [ $i -lt "$2" ]; do
    f=$(cpu "$1") || return 1
    e=$(cpu "$T/empty.c") || return 1
    bf=$(echo "$bf $f" | awk '{ print ($2 < $1) ? $2 : $1 }')
    be=$(echo "$be $e" | awk '{ print ($2 < $1) ? $2 : $1 }')
    i=$((i + 1))
  done
  echo "$bf $be"
}
# overloaded: 1 when the 1-minute load average exceeds the number of cores
# (Linux /proc/loadavg): CPU time itself then grows (shared caches and
# hyperthreads), and a timing over its limit is reported but not counted
ncpu() { getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1; }
overloaded() {
  [ -r /proc/loadavg ] || { echo 0; return; }
  awk -v n="$(ncpu)" '{ print ($1 > n) ? 1 : 0 }' /proc/loadavg
}
# the scale factor: calib.c's best CPU time of 5 over CALIB_REF, at least 1
scale=1
if [ -n "$GNU_TIME" ]; then
  bc=99; i=0
  while [ $i -lt 5 ]; do c=$(cpu "$T/calib.c") || exit 1; bc=$(echo "$bc $c" | awk '{ print ($2 < $1) ? $2 : $1 }'); i=$((i + 1)); done
  scale=$(echo "$bc $CALIB_REF" | awk '{ s = $1 / $2; printf "%.2f\n", (s > 1 ? s : 1) }')
  echo "include cost: calib.c at -O2: $bc s CPU (reference $CALIB_REF s): time limits scaled by $scale"
fi
for job in "none 0 -" "two 8192 0.15" "three 16384 info"; do
  set -- $job; name=$1; max_text=$2; max_s=$3
  $CC -std=c99 -O0 -I. -c "$T/$name.c" -o "$T/$name.o" || { echo "include cost: $name.c does not compile"; exit 1; }
  text=$(size "$T/$name.o" | awk 'NR == 2 { print $1 }')
  [ -n "$text" ] || { echo "include cost: no 'size' to measure $name.o"; exit 1; }
  emitted=$(nm "$T/$name.o" | awk '$2 == "t" || $2 == "T" { printf " %s", $3 }')
  if [ "$text" -gt "$max_text" ]; then
    echo "include cost: $name.c at -O0: $text bytes of text, over $max_text; functions emitted:$emitted"
    fail=1
  else
    echo "include cost: $name.c at -O0: $text bytes of text (limit $max_text)"
  fi
  [ "$max_s" = - ] && continue
  if [ -z "$GNU_TIME" ]; then
    echo "include cost: $name.c at -O2: timing skipped (no GNU time in /usr/bin/time)"
    continue
  fi
  r=$(extra "$T/$name.c" 3) || { echo "include cost: $name.c does not compile at -O2"; exit 1; }
  if [ "$max_s" = info ]; then
    echo "$r" | awk -v n="$name" '{ printf "include cost: %s.c at -O2: %.2f s CPU over an empty file (%.2f s against %.2f s, best of 3; not checked)\n", n, $1 - $2, $1, $2 }'
    continue
  fi
  max_s=$(echo "$max_s $scale" | awk '{ printf "%.3f\n", $1 * $2 }')
  over=$(echo "$r $max_s" | awk '{ print ($1 - $2 > $3 + 1e-9) ? 1 : 0 }')
  tries=1
  while [ "$over" = 1 ] && [ $tries -lt 3 ]; do
    r2=$(extra "$T/$name.c" 3) || exit 1
    r=$(echo "$r $r2" | awk '{ printf "%s %s\n", ($3 < $1) ? $3 : $1, ($4 < $2) ? $4 : $2 }')
    over=$(echo "$r $max_s" | awk '{ print ($1 - $2 > $3 + 1e-9) ? 1 : 0 }')
    tries=$((tries + 1))
  done
  msg=$(echo "$r" | awk -v n=$((tries * 3)) '{ printf "%.2f s CPU over an empty file (%.2f s against %.2f s, best of %d)", $1 - $2, $1, $2, n }')
  if [ "$over" = 1 ] && [ "$(overloaded)" = 1 ]; then
    echo "include cost: $name.c at -O2: $msg, over $max_s s, but the machine is overloaded ($(cat /proc/loadavg | cut -d' ' -f1) runnable jobs on $(ncpu) cores): not counted; rerun sh tests/include_cost.sh when it is quiet"
  elif [ "$over" = 1 ]; then
    echo "include cost: $name.c at -O2: $msg, over $max_s s"
    fail=1
  else
    echo "include cost: $name.c at -O2: $msg (limit $max_s s)"
  fi
done
[ $fail -eq 0 ] || exit 1
echo "include cost: ok"
