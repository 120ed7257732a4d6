#!/usr/bin/env bash
# Installs the Debian packages ncoffset builds and tests with (only those that are missing).
set -euo pipefail
packages=(cmake ninja-build g++ clang-14 clang-format-14 libclang-rt-14-dev libfmt-dev libcli11-dev
          libgtest-dev libgmock-dev libbenchmark-dev python3 pkg-config
          python3-dev pybind11-dev python3-numpy python3-pytest
          chromium)  # the browser test of the HTML report (tests/browser/)
# Node.js with npm for the browser test's playwright-core (tests/browser/package.json): Debian's
# packages unless a Node.js with npm is installed already (NodeSource's nodejs has npm inside).
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
