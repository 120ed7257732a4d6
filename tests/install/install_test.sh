#!/usr/bin/env bash
# The installed package works for a consumer: cmake --install into a temporary prefix, then
#  * the public headers compile on their own with only the prefix's include/ (no src/ header),
#  * examples/embed configures with find_package(ncoffset) (CMAKE_PREFIX_PATH), builds and runs
#    examples/lentoax.MPF with the path and the final tool as expected,
#  * pkg-config --cflags --libs ncoffset (PKG_CONFIG_PATH) builds a program against the
#    shared library, which runs,
#  * the source tree as a subproject (add_subdirectory) configures without tests, benchmarks,
#    the CLI and -Werror.
# Usage: install_test.sh SOURCE_DIR BUILD_DIR [EXTRA_CXX_FLAGS] (e.g. the sanitizer flags the
# build was made with: a consumer of an instrumented library links with them too).
set -euo pipefail  # (no `| grep -q` below: with pipefail, its early exit fails the pipe)
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
flags=${3:-}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/ncoffset-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fails=0
check() {  # check NAME COMMAND...: runs the command, prints ok/FAIL
  local name=$1
  shift
  if "$@" >"$tmp/check.log" 2>&1; then
    echo "ok   $name"
  else
    echo "FAIL $name"
    sed 's/^/     /' "$tmp/check.log" | tail -20
    fails=$((fails + 1))
  fi
}

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >"$tmp/install.log"
libdir=$(dirname "$(find "$prefix" -name libncoffset.a | head -1)")
check "installed: headers, version.hpp, static and shared library, CMake package, ncoffset.pc" \
  test -f "$prefix/include/ncoffset/channel.hpp" -a -f "$prefix/include/ncoffset/version.hpp" \
  -a -f "$libdir/libncoffset.a" -a -L "$libdir/libncoffset.so" -a -f "$libdir/libncoffset.so.0.1" \
  -a -f "$libdir/cmake/ncoffset/ncoffsetConfig.cmake" \
  -a -f "$libdir/cmake/ncoffset/ncoffsetConfigVersion.cmake" \
  -a -f "$libdir/pkgconfig/ncoffset.pc" -a -x "$prefix/bin/ncoffset"

# Every installed header on its own, with nothing but the prefix and the system headers.
headers_alone() {
  local h
  for h in "$prefix"/include/ncoffset/*.hpp; do
    ! grep -nE '^#include "' "$h" | grep -v '"ncoffset/' || return 1
    echo "#include <ncoffset/$(basename "$h")>" |
      c++ -std=c++20 -fsyntax-only -I"$prefix/include" -x c++ - || return 1
  done
}
check "public headers include no internal header and compile alone" headers_alone

# The version header matches project(VERSION) and the CLI.
version_matches() {
  grep -q '#define NCOFFSET_VERSION_STRING "0.1.0"' "$prefix/include/ncoffset/version.hpp" &&
    grep -q 'project(ncoffset VERSION 0.1.0' "$src/CMakeLists.txt" &&
    test "$("$prefix/bin/ncoffset" --version)" = "ncoffset 0.1.0"
}
check "NCOFFSET_VERSION_STRING, project(VERSION) and ncoffset --version agree" version_matches

embed() {
  cmake -S "$src/examples/embed" -B "$tmp/embed" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_FLAGS="$flags" &&
    cmake --build "$tmp/embed" &&
    (cd "$src" && "$tmp/embed/embed_example" --init examples/tools.INI examples/lentoax.MPF) \
      >"$tmp/embed.out" || return 1
  cat "$tmp/embed.out"
  grep -qx 'ncoffset 0.1.0' "$tmp/embed.out" &&
    grep -qx 'segment line 7 G0 to 0 0 50' "$tmp/embed.out" &&
    grep -qx 'segment line 9 G0 to 10 10 105' "$tmp/embed.out" &&
    grep -qx 'tool line 8 D: T1 D1 radius 4 length 0 0 100' "$tmp/embed.out" &&
    grep -q '^message line 11: G17: AXIND = (3, 2, 1), status 0' "$tmp/embed.out" &&
    grep -qE '"\$P_TOOLNO": ?1\b' "$tmp/embed.out" &&
    grep -qx end "$tmp/embed.out"
}
check "examples/embed: find_package(ncoffset), builds, runs examples/lentoax.MPF" embed

pkgconfig() {
  local cflags
  cflags=$(PKG_CONFIG_PATH="$libdir/pkgconfig" pkg-config --cflags --libs ncoffset) || return 1
  echo "pkg-config: $cflags"
  [[ $cflags == *-I*/include* && $cflags == *-L*-lncoffset* ]] || return 1
  cat >"$tmp/pc.cpp" <<'CPP'
#include <ncoffset/channel.hpp>
#include <ncoffset/version.hpp>
#include <cstdio>
struct Count : ncoffset::PathSink {
  int n = 0;
  void segment(const ncoffset::Segment&) override { ++n; }
  void finish(const ncoffset::Alarm*) override {}
};
int main() {
  ncoffset::Channel channel;
  Count sink;
  auto r = channel.runText("T.MPF", "G1 X10 F100\nG2 X20 Y0 I5 J0\nM30\n", sink);
  std::printf("%s %d %d\n", NCOFFSET_VERSION_STRING, sink.n,
              r.status == ncoffset::RunResult::Status::Ok);
}
CPP
  # shellcheck disable=SC2086
  c++ -std=c++20 $flags "$tmp/pc.cpp" -o "$tmp/pc" $cflags &&
    test "$(LD_LIBRARY_PATH="$libdir" "$tmp/pc")" = "0.1.0 2 1" &&
    [[ $(LD_LIBRARY_PATH="$libdir" ldd "$tmp/pc") == *"libncoffset.so.0.1 => $libdir/"* ]]
}
check "pkg-config --cflags --libs ncoffset: builds against libncoffset.so, runs" pkgconfig

subproject() {
  mkdir -p "$tmp/sub"
  cat >"$tmp/sub/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.20)
project(consumer LANGUAGES CXX)
enable_testing()
add_subdirectory("$src" ncoffset)
CMAKE
  cmake -S "$tmp/sub" -B "$tmp/sub/build" -G Ninja >/dev/null || return 1
  local cache=$tmp/sub/build/CMakeCache.txt
  grep -qx 'NCOFFSET_WERROR:BOOL=OFF' "$cache" && grep -qx 'NCOFFSET_TESTS:BOOL=OFF' "$cache" &&
    grep -qx 'NCOFFSET_BENCH:BOOL=OFF' "$cache" &&
    ! grep -qE 'ncoffset_unit_tests|ncoffset_golden_tests|ncoffset_bench|-Werror' \
      "$tmp/sub/build/build.ninja" &&
    grep -q 'libncoffset.a' "$tmp/sub/build/build.ninja" &&
    [[ $(cd "$tmp/sub/build" && ctest -N) == *"Total Tests: 0"* ]]
}
check "add_subdirectory: the library without tests, benchmarks and -Werror" subproject

if [ "$fails" -ne 0 ]; then
  echo "$fails install checks fail"
  exit 1
fi
echo "all install checks hold"
