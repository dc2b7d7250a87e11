#!/bin/sh
# make test's fuzz step: builds the float fuzz targets and runs each for a
# few seconds. Prints "fuzz ok"/"FAIL fuzz" lines, one per target, or one
# line saying why it was skipped; the last line is "N passed, N failed".
make_cmd=$1; dir=$2; secs=$3; shift 3
if ! command -v clang >/dev/null 2>&1; then echo "fuzz: skipped (clang not found)"; echo "0 passed, 0 failed"; exit 0; fi
probe="$dir/probe"
mkdir -p "$dir"
printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }\n' > "$probe.c"
if ! clang -fsanitize=fuzzer,address,undefined "$probe.c" -o "$probe" >/dev/null 2>&1; then
  echo "fuzz: skipped (clang has no libFuzzer)"; echo "0 passed, 0 failed"; exit 0; fi
targets="$dir/make_seeds"
for t in "$@"; do targets="$targets $dir/fuzz_${t}_float"; done
if ! $make_cmd --no-print-directory -s $targets >/dev/null; then echo "FAIL fuzz: targets do not build"; echo "0 passed, 1 failed"; exit 0; fi
ok=0; bad=0
"./$dir/make_seeds" "$dir/seeds" || exit 1
for t in "$@"; do
  log="$dir/smoke_$t.log"
  rm -rf "$dir/smoke_corpus_$t"; mkdir -p "$dir/smoke_corpus_$t"
  "./$dir/fuzz_${t}_float" -max_total_time="$secs" -timeout=1 -print_final_stats=1 \
    -artifact_prefix="$dir/smoke_${t}_" "$dir/smoke_corpus_$t" "$dir/seeds/$t" > "$log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  if [ $rc -eq 0 ]; then echo "fuzz ok: $t (float) ${execs:-?} executions in $secs s"; ok=$((ok + 1))
  else echo "FAIL fuzz: $t (float), see $log"; bad=$((bad + 1)); fi
done
echo "$ok passed, $bad failed"
exit 0
