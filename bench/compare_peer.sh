#!/bin/sh
# Throughput of ncoffset vs LinuxCNC rs274 on the same 1,000,000-block plain G1 program, both
# writing their output to a file (docs/performance.md). Runs them alternately RUNS times and
# prints "tool user sys wall" seconds of each run; compare the minima.
#   compare_peer.sh NCOFFSET RS274_ROOT PROGRAM.MPF PROGRAM.ngc [RUNS]
set -eu
NCO=$1; ROOT=$2; MPF=$3; NGC=$4; RUNS=${5:-5}
TMP=$(mktemp -d)
printf 'T1 P1 Z1.9685 D0.23622\n' > "$TMP/tool.tbl"
: > "$TMP/params.var"
i=0
while [ "$i" -lt "$RUNS" ]; do
  /usr/bin/time -a -o "$TMP/times" -f "ncoffset %U %S %e" "$NCO" -o "$TMP/out.csv" "$MPF"
  HOME=$TMP LD_LIBRARY_PATH="$ROOT/usr/lib" /usr/bin/time -a -o "$TMP/times" -f "rs274 %U %S %e" \
    "$ROOT/usr/bin/rs274" -g -t "$TMP/tool.tbl" -v "$TMP/params.var" "$NGC" "$TMP/out.txt" \
    2>/dev/null
  i=$((i + 1))
done
cat "$TMP/times"
echo "rows: ncoffset $(($(wc -l < "$TMP/out.csv") - 1)) segments;" \
  "rs274 $(grep -c STRAIGHT_FEED "$TMP/out.txt") STRAIGHT_FEED"
rm -rf "$TMP"
