#!/bin/sh
# Runs each fuzz target for a time on its generated seed corpus; prints the
# executions and the result per target. Usage: run.sh dir seconds "precisions" targets...
dir=$1; secs=$2; precs=$3; shift 3
"./$dir/make_seeds" "$dir/seeds" || exit 1
fail=0
for p in $precs; do
  for t in "$@"; do
    mkdir -p "$dir/corpus_${t}_$p" "$dir/artifacts"
    log="$dir/fuzz_${t}_$p.log"
    "./$dir/fuzz_${t}_$p" -max_total_time="$secs" -timeout=1 -print_final_stats=1 \
      -artifact_prefix="$dir/artifacts/${t}_${p}_" "$dir/corpus_${t}_$p" "$dir/seeds/$t" > "$log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    if [ $rc -eq 0 ]; then echo "fuzz $t ($p): ${execs:-?} executions in $secs s, nothing found"
    else echo "FAIL fuzz $t ($p): finding after ${execs:-?} executions, see $log"; fail=1; fi
  done
done
exit $fail
