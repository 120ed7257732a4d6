#!/usr/bin/env bash
# Renders the pictures of docs/radius-compensation.md, docs/smooth-approach.md, docs/cycles.md
# and docs/threads.md: every
# docs/pictures/NAME.MPF becomes NAME.svg (programmed path dashed, compensated path solid);
# the cutting edge position pictures sl1.svg ... sl9.svg of docs/turning.md are drawn by
# scripts/turning-pictures.py from ncoffset's output for sl1.MPF ... sl9.MPF.
set -euo pipefail
cd "$(dirname "$0")/../docs/pictures"
for program in *.MPF; do
  [[ $program == sl[1-9].MPF ]] && continue
  # A first line "; view: yz" (or zx) draws that side view (docs/cycles.md: drilling).
  view=$(sed -n '1s/^; view: \([a-z]*\).*/\1/p' "$program")
  ../../build/ncoffset ${view:+--view "$view"} "$program" -o "${program%.MPF}.svg" \
    2> >(grep -v "warning 10763" >&2 || true)
done
../../scripts/turning-pictures.py ../../build/ncoffset
