#!/usr/bin/env bash
# Renders the pictures of docs/radius-compensation.md and docs/smooth-approach.md: every
# docs/pictures/NAME.MPF becomes NAME.svg (programmed path dashed, compensated path solid).
set -euo pipefail
cd "$(dirname "$0")/../docs/pictures"
for program in *.MPF; do
  ../../build/ncoffset "$program" -o "${program%.MPF}.svg" 2> >(grep -v "warning 10763" >&2 || true)
done
