#!/usr/bin/env bash
# The browser test of the HTML report (ctest browser_report): installs playwright-core from
# tests/browser/package-lock.json into BUILD_DIR/browser-test and runs report_test.js with
# Debian's chromium. Skips (exit 77) only where chromium or npm is missing and CI is not set;
# in CI (CI=true) a missing browser is a failure.
# usage: run.sh NCOFFSET EXAMPLES_DIR BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
ncoffset="$1" examples="$2" out="$3/browser-test"
for need in /usr/bin/chromium node npm; do
  if ! command -v "$need" >/dev/null 2>&1; then
    if [ "${CI:-}" = "true" ]; then
      echo "FAIL: $need is missing (scripts/install-deps.sh installs chromium and Node.js)"; exit 1
    fi
    echo "SKIP: $need is not installed (scripts/install-deps.sh installs it); the browser test needs it"
    exit 77
  fi
done
mkdir -p "$out"
# npm ci only when the lock file changed since the last install.
if ! cmp -s "$here/package-lock.json" "$out/package-lock.json" || [ ! -d "$out/node_modules/playwright-core" ]; then
  cp "$here/package.json" "$here/package-lock.json" "$out/"
  (cd "$out" && npm ci --no-audit --no-fund --loglevel=error)
fi
exec node "$here/report_test.js" "$ncoffset" "$examples" "$out"
