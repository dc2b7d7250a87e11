#!/bin/sh
# What a file that only includes the header and calls mf_brdf_sample + mf_brdf
# costs: -O0 text bytes and emitted functions, best-of-3 -O2 compile seconds.
# usage: sh tools/includer_cost.sh [header ...]   (default: microfacet.h)
# e.g. compare with an earlier version:
#   git show v0.2.0-commit:microfacet.h > /tmp/old.h; sh tools/includer_cost.sh /tmp/old.h microfacet.h
CC=${CC:-cc}
T=${TMPDIR:-/tmp}/mf_includer.$$
mkdir -p "$T" && trap 'rm -rf "$T"' EXIT
[ $# -gt 0 ] || set -- microfacet.h
for h in "$@"; do
  cp "$h" "$T/h.h"
  # 0.4 samplers return the record mf_sample (MF_U_MAX came with it); earlier
  # headers return the direction
  printf '#include "h.h"\nfloat f(const mf_ndf *d, mf_vec3 wo, float u1, float u2) {\n#ifdef MF_U_MAX\n  mf_vec3 wi = mf_brdf_sample(d, wo, u1, u2).wi;\n#else\n  mf_vec3 wi = mf_brdf_sample(d, wo, u1, u2);\n#endif\n  return mf_brdf(d, wo, wi);\n}\n' > "$T/inc.c"
  $CC -std=c99 -O0 -c "$T/inc.c" -o "$T/o0.o" || exit 1
  text=$(size "$T/o0.o" | awk 'NR==2{print $1}')
  funcs=$(nm "$T/o0.o" | grep -c ' [tT] ')
  best=
  for i in 1 2 3; do
    s=$( { /usr/bin/time -f %e $CC -std=c99 -O2 -c "$T/inc.c" -o "$T/o2.o"; } 2>&1 )
    best=$(echo "$best $s" | awk '{m=$NF; for(i=1;i<NF;i++) if($i<m) m=$i; print m}')
  done
  echo "$h: -O0 text $text bytes, $funcs functions; -O2 compile ${best} s"
done
