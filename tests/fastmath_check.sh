#!/bin/sh
# The NaN/Inf robustness subset (tests/fastmath_check.c) built with
# -O1 -ffast-math (the folds that assume no NaN or Inf happen from -O1; part
# of make test: float, the default precision; make
# check-all: float and double).
# usage: sh tests/fastmath_check.sh CC "TWARN" BUILD_DIR [PRECISIONS]
CC=$1; TWARN=$2; B=$3; PRECS=${4:-float double}
mkdir -p "$B" || exit 1
for prec in $PRECS; do
  def=; [ $prec = double ] && def=-DMF_USE_DOUBLE
  $CC -std=c99 -O1 -ffast-math $TWARN $def -I. tests/fastmath_check.c -o "$B/fastmath_$prec" -lm || exit 1
  "./$B/fastmath_$prec" >/dev/null || { echo "fastmath: the $prec build failed its checks"; exit 1; }
  echo "fastmath: the -ffast-math build in $prec: ok"
done
