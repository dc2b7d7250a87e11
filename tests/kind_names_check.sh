#!/bin/sh
# Part of `make test` (step kinds): no module but src/05_ndf.h, a kind's
# own src/06_kind_<name>.h and the dispatch src/07_ndf_dispatch.h (switches
# generated from MF__NDF_KINDS) tests a distribution kind by name (DESIGN.md);
# the others ask the traits and dispatch functions of 05_ndf.h. Counts, in every
# other module (comments left out), the kind constants MF_NDF_<NAME> of the
# lines of MF__NDF_KINDS, switches on a kind and comparisons of a kind with a
# number; lists them and fails when there is any.
cd "$(dirname "$0")/.." || exit 1
names=$(sed -n 's/^ *X(\([A-Z_][A-Z_0-9]*\), *[a-z_][a-z_0-9]*[,)].*/\1/p' src/05_ndf.h | tr '\n' '|' | sed 's/|$//')
if [ -z "$names" ]; then echo "kind_names_check: no kind lines found in src/05_ndf.h"; exit 1; fi
n=0
for f in src/*.h; do
  case $f in src/05_ndf.h|src/06_kind_*.h|src/07_ndf_dispatch.h) continue ;; esac
  # comments out (one-line /* */ and the " * " lines of block comments), line numbers kept
  hits=$(sed -e 's#/\*.*\*/##g' -e 's#^ *\*.*##' -e 's#/\*.*##' "$f" |
         grep -nE "MF_NDF_($names)([^A-Z_0-9]|\$)|switch *\([^)]*type *\)|type *([!=<>]=|[<>]) *[0-9]")
  if [ -n "$hits" ]; then
    c=$(printf '%s\n' "$hits" | wc -l)
    n=$((n + c))
    printf '%s\n' "$hits" | sed "s#^#$f:#"
  fi
done
if [ "$n" -ne 0 ]; then
  echo "kind_names_check: $n test(s) of a kind by name outside src/05_ndf.h, src/06_kind_*.h and src/07_ndf_dispatch.h (use a trait of MF__NDF_KINDS)"
  exit 1
fi
echo "kind_names_check: no module outside src/05_ndf.h, src/06_kind_*.h and src/07_ndf_dispatch.h tests a kind by name ($(echo "$names" | tr '|' ' '))"
