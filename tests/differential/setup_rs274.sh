#!/usr/bin/env bash
# Installs LinuxCNC's standalone rs274ngc interpreter (`rs274`) "light": its runtime libraries
# from Debian, and the binary plus LinuxCNC's own shared libraries unpacked from the
# linuxcnc-uspace package into a cache directory (no real-time kernel, no 1 GB of dependencies).
# rs274 is a test-time oracle only: nothing of it is linked into or shipped with ncoffset.
#
# Usage: setup_rs274.sh [CACHE_DIR]
#   CACHE_DIR defaults to $RS274_CACHE_DIR, else ${XDG_CACHE_HOME:-$HOME/.cache}/ncoffset/rs274.
# Prints the path of the rs274 binary on stdout (run it with LD_LIBRARY_PATH=<CACHE_DIR>/lib).
# Exit status: 0 ready; 77 the package cannot be had here (no network, no Debian package,
# not root) - the caller should SKIP; 1 anything else (a broken install: a real failure).
# Idempotent and quiet: a second run only checks that the binary starts.
set -euo pipefail

skip() { echo "setup_rs274: SKIP: $*" >&2; exit 77; }
fail() { echo "setup_rs274: ERROR: $*" >&2; exit 1; }

default_cache="${XDG_CACHE_HOME:-${HOME:-/tmp}/.cache}/ncoffset/rs274"
dir="${1:-${RS274_CACHE_DIR:-$default_cache}}"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
bin="$dir/bin/rs274"
runtime_libs=(libboost-python1.74.0 libedit2 libtirpc3)

# rs274 starts (all its libraries resolve) and interprets a one-line program.
smoke_test() {
  local t
  t="$(mktemp -d)"
  printf 'G21 G90\nG1 X1 F100\nM2\n' >"$t/s.ngc"
  : >"$t/tool.tbl"
  local ok=1
  if HOME="$t" LD_LIBRARY_PATH="$dir/lib" "$bin" -g -t "$t/tool.tbl" -v "$t/p.var" \
       "$t/s.ngc" "$t/out.txt" </dev/null >/dev/null 2>&1 &&
     grep -q 'STRAIGHT_FEED(1.0000' "$t/out.txt"; then
    ok=0
  fi
  rm -rf "$t"
  return $ok
}

# One installer at a time per cache directory (ctest -j, or the Release and ASan builds).
exec 9>"$dir/.lock"
command -v flock >/dev/null && flock 9

if [ -x "$bin" ] && smoke_test; then
  echo "$bin"
  exit 0
fi

command -v apt-get >/dev/null && command -v dpkg >/dev/null ||
  skip "no apt-get/dpkg on this machine: cannot install LinuxCNC's rs274 (Debian package linuxcnc-uspace)"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null && sudo -n true 2>/dev/null; then SUDO="sudo -n"
  else skip "not root and no password-less sudo: cannot apt-get install rs274's runtime libraries"; fi
fi
export DEBIAN_FRONTEND=noninteractive

# The package lists are refreshed only when apt does not know a package we need.
# (Output is captured before grep: `grep -q` closing a pipe early fails it under pipefail.)
apt_updated=0
has_candidate() {
  local policy
  policy="$(apt-cache policy "$1" 2>/dev/null || true)"
  grep -q 'Candidate: [^(]' <<<"$policy"
}
ensure_known() {  # ensure_known PACKAGE...
  local p
  for p in "$@"; do
    if ! has_candidate "$p"; then
      if [ $apt_updated -eq 0 ]; then
        apt_updated=1
        $SUDO apt-get update -qq >/dev/null 2>&1 ||
          skip "apt-get update failed (no network?): cannot fetch LinuxCNC's rs274"
      fi
      has_candidate "$p" ||
        skip "Debian package $p is not available here: cannot install LinuxCNC's rs274"
    fi
  done
}

missing=()
for p in "${runtime_libs[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)"
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  ensure_known "${missing[@]}"
  $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null 2>&1 ||
    skip "apt-get install ${missing[*]} failed (no network?): rs274's runtime libraries are missing"
fi

ensure_known linuxcnc-uspace
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get download -qq linuxcnc-uspace >/dev/null 2>&1) ||
  skip "apt-get download linuxcnc-uspace failed (no network?): cannot install LinuxCNC's rs274"
deb="$(ls "$work"/linuxcnc-uspace_*.deb 2>/dev/null | head -n 1)"
[ -n "$deb" ] || skip "apt-get download linuxcnc-uspace produced no .deb"
dpkg -x "$deb" "$work/root" || fail "dpkg -x $deb failed"
[ -x "$work/root/usr/bin/rs274" ] || fail "the package has no usr/bin/rs274"

# Keep only the binary and LinuxCNC's own shared libraries (about 5 MB of the 90 MB).
rm -rf "$dir/bin" "$dir/lib"
mkdir -p "$dir/bin" "$dir/lib"
cp -p "$work/root/usr/bin/rs274" "$dir/bin/"
cp -P -p "$work/root/usr/lib/"lib*.so* "$dir/lib/"
dpkg-deb -f "$deb" Version >"$dir/VERSION"

smoke_test || fail "rs274 was unpacked into $dir but does not run (try: LD_LIBRARY_PATH=$dir/lib ldd $bin)"
echo "$bin"
