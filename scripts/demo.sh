#!/usr/bin/env bash
# Installs what is missing, builds, and runs ncoffset on the shipped example.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
mkdir -p out
./build/ncoffset --init examples/frames.INI -o out/frames.csv examples/frames.MPF
./build/ncoffset --init examples/tools.INI --vars out/lentoax.json -o out/lentoax.csv \
  examples/lentoax.MPF
./build/ncoffset --init examples/tools.INI -o out/pocket.csv examples/pocket.MPF
./build/ncoffset --init examples/tools.INI -o out/pocket.html examples/pocket.MPF
./build/ncoffset --init examples/lathe.INI --init examples/lathe_tools.INI --view zx \
  -o out/lathe.html examples/lathe.MPF
./scripts/python-setup.sh
echo "wrote out/frames.csv, out/lentoax.csv, out/pocket.csv and the reports out/pocket.html, out/lathe.html:"
cat out/frames.csv out/lentoax.csv out/pocket.csv
