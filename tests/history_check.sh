#!/bin/sh
# Comments in src/ state the rule, the paper and equation, and a one-line
# reason; measurement histories (callgrind counts, timings, before/after
# figures, speed ratios) belong in commit messages and docs/PERFORMANCE.md.
# Fails on any src/ line matching these patterns (generated tables excepted).
cd "$(dirname "$0")/.."
pat='callgrind|instructions|[0-9] ?(ms|us|µs)\b|[0-9]+(\.[0-9]+)? s (on|of|for|here)\b|one core|README.s machine|[0-9]+(\.[0-9]+)?(-[0-9.]+)?x (faster|slower|GGX|the|a )|[0-9]+% (fewer|more|faster|slower)|\b(faster|slower) than\b|instead of [0-9.]+-[0-9.]+|\bwas [0-9]|-> [0-9.,]+[MkG]\b|measured (faster|slower)|cache misses|[0-9.]+[Mk]? misses|twice the misses|G/s|ns/op|\bns a call'
hits=$(grep -nEi "$pat" $(ls src/*.h | grep -v -e 14_ltc_table -e 17_energy_table) | grep -v "^src/[^:]*:[0-9]*:#define MF__SITE")
if [ -n "$hits" ]; then
    echo "history check: measurement histories in src/ (move them to the commit body or docs/PERFORMANCE.md):"
    echo "$hits"
    exit 1
fi
echo "history check: no measurement histories in src/"
