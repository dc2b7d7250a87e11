#!/bin/sh
# Packaging check (part of make test when cmake is present): cmake configure
# and install to a temporary prefix; a consumer built with find_package, with
# add_subdirectory and with FetchContent; find_package refuses another minor
# version; pkg-config after cmake --install and after make install; LICENSE
# installed; each consumer runs and checks the header's version.
CC=$1; B=$2
if ! command -v cmake >/dev/null 2>&1; then
  echo "package check: cmake not found, skipped (apt-get install cmake to run it)"; exit 0
fi
root=$(pwd); W=$root/$B/package
rm -rf "$W"; mkdir -p "$W"
fail() { echo "package check: $*"; exit 1; }
quiet() { log=$W/log.txt; "$@" > "$log" 2>&1 || { cat "$log"; return 1; }; }
export CC
quiet cmake -S "$root" -B "$W/build" -DCMAKE_INSTALL_PREFIX="$W/prefix" || fail "configure"
quiet cmake --install "$W/build" || fail "install"
[ -f "$W/prefix/include/microfacet.h" ] || fail "no header installed"
[ -f "$W/prefix/share/licenses/microfacet/LICENSE" ] || fail "no LICENSE installed"
for how in find_package subdirectory fetchcontent; do
  quiet cmake -S "$root/tests/package" -B "$W/$how" -DMF_HOW=$how -DMF_ROOT="$root" \
        -DCMAKE_PREFIX_PATH="$W/prefix" || fail "$how: configure"
  quiet cmake --build "$W/$how" || fail "$how: build"
  "$W/$how/consumer" || fail "$how: the consumer fails"
done
# another minor version must not be accepted
sed 's/find_package(microfacet 0.4 REQUIRED)/find_package(microfacet 0.3 REQUIRED)/' \
  "$root/tests/package/CMakeLists.txt" > "$W/CMakeLists.txt"
cp "$root/tests/package/consumer.c" "$W/"
cmake -S "$W" -B "$W/wrong" -DMF_HOW=find_package -DCMAKE_PREFIX_PATH="$W/prefix" \
  > "$W/log.txt" 2>&1 && fail "find_package(microfacet 0.3) accepted version 0.4"
if command -v pkg-config >/dev/null 2>&1; then
  make -s -j1 install PREFIX="$W/makeprefix" > "$W/log.txt" 2>&1 || { cat "$W/log.txt"; fail "make install"; }
  [ -f "$W/makeprefix/share/licenses/microfacet/LICENSE" ] || fail "make install: no LICENSE"
  for p in prefix makeprefix; do
    v=$(PKG_CONFIG_PATH="$W/$p/share/pkgconfig" pkg-config --modversion microfacet) || fail "$p: pkg-config finds no microfacet"
    flags=$(PKG_CONFIG_PATH="$W/$p/share/pkgconfig" pkg-config --cflags --libs microfacet)
    # shellcheck disable=SC2086
    $CC -std=c99 -DMF_EXPECT_VERSION="\"$v\"" "$root/tests/package/consumer.c" $flags -o "$W/pc_$p" ||
      fail "$p: pkg-config build ($flags)"
    "$W/pc_$p" || fail "$p: the pkg-config consumer fails"
  done
else
  echo "package check: pkg-config not found, its part skipped"
fi
echo "package check: find_package, add_subdirectory, FetchContent, version check, pkg-config (cmake and make install): ok"
