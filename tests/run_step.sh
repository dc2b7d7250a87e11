#!/bin/sh
# One step of make test: run_step.sh TAG RESULT KIND COMMAND...
# Streams the command's output with "[TAG]" in front of every line (the "ok"
# lines of -v left out) and writes "passed failed" to RESULT. KIND "tests": the
# command is a test binary whose last line is "N passed, N failed" (a non-zero
# exit with no failure counted is one failure); KIND "check": the command is one
# check, passed when it exits 0. Always exits 0, so make runs every step; the
# total is summed by sum_results.sh.
tag=$1; res=$2; kind=$3; shift 3
rm -f "$res"
{ "$@" 2>&1; echo "__mft_rc $?"; } | {
  rc=1; last=
  while IFS= read -r line; do
    case $line in
      "__mft_rc "*) rc=${line#__mft_rc }; continue ;;
      "ok "*) continue ;;
    esac
    printf '[%s] %s\n' "$tag" "$line"
    last=$line
  done
  if [ "$kind" = check ]; then
    if [ "$rc" -eq 0 ]; then p=1; f=0; else p=0; f=1; echo "[$tag] FAIL (exit $rc)"; fi
  else
    p=$(printf '%s\n' "$last" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\1/p')
    f=$(printf '%s\n' "$last" | sed -n 's/^\([0-9]*\) passed, \([0-9]*\) failed$/\2/p')
    if [ -z "$p" ]; then p=0; f=1; echo "[$tag] FAIL: did not finish (exit $rc)"
    elif [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; echo "[$tag] FAIL: exit $rc"; fi
  fi
  echo "$p $f" > "$res"
}
exit 0
