#!/usr/bin/env bash
# Makes `python3 -c "import ncoffset"` work with the module built in build/python (docs/python.md):
# writes ncoffset.pth (one line: the module's directory) into the site-packages of
# /usr/bin/python3, for which the module is built, and of the python3 on PATH when it is another
# interpreter of the same Python version (the same ABI tag, e.g. a pyenv 3.11). Nothing is copied:
# a rebuild is picked up; delete the ncoffset.pth files to undo.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
if [ ! -f "$build/python/module_dir.txt" ]; then
  echo "python-setup: no Python module in $build (pybind11-dev missing, or NCOFFSET_PYTHON=OFF)"
  exit 0
fi
module_dir=$(cat "$build/python/module_dir.txt")
declare -A seen=()
for py in /usr/bin/python3 "$(command -v python3 || true)"; do
  [ -x "$py" ] || continue
  real=$("$py" -c 'import sys; print(sys.executable)')
  [ -z "${seen[$real]:-}" ] || continue
  seen[$real]=1
  "$py" - "$module_dir" <<'PY'
import glob, os, sys, sysconfig
d = sys.argv[1]
if not glob.glob(os.path.join(d, "ncoffset" + sysconfig.get_config_var("EXT_SUFFIX"))):
    print(f"{sys.executable}: not set up (the module is built for another Python version)")
    sys.exit(0)
site = sysconfig.get_paths()["purelib"]
try:
    os.makedirs(site, exist_ok=True)
    with open(os.path.join(site, "ncoffset.pth"), "w") as f:
        f.write(d + "\n")
except OSError as e:  # not root: say how to use it instead of failing the demo
    print(f"{sys.executable}: cannot write {site}/ncoffset.pth ({e.strerror}); "
          f"use: export PYTHONPATH={d}")
    sys.exit(0)
try:
    import numpy  # noqa: F401
    extra = ""
except ImportError:
    extra = " (no numpy here: run() and Stream need it; /usr/bin/python3 has Debian's)"
print(f"{sys.executable}: import ncoffset from {d} via {site}/ncoffset.pth{extra}")
PY
done
