#!/usr/bin/env python3
"""Runs a command and samples /proc/PID/status every 10 ms (docs/performance.md).

  rss_breakdown.py CMD ARGS...

Prints the peak of VmHWM (what /usr/bin/time reports as maximum resident set size), RssAnon
(heap, stacks: memory the program allocated) and RssFile (file pages mapped into the process,
e.g. the memory-mapped part program, plus the shared libraries).
"""
import subprocess
import sys
import time


def status(pid):
    out = {}
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                key, _, value = line.partition(":")
                if key in ("VmHWM", "RssAnon", "RssFile"):
                    out[key] = int(value.split()[0])
    except OSError:
        pass
    return out


def main():
    p = subprocess.Popen(sys.argv[1:])
    peak = {"VmHWM": 0, "RssAnon": 0, "RssFile": 0}
    start = time.monotonic()
    while p.poll() is None:
        for k, v in status(p.pid).items():
            peak[k] = max(peak[k], v)
        time.sleep(0.01)
    elapsed = time.monotonic() - start
    print(f"exit={p.returncode} wall={elapsed:.2f}s "
          + " ".join(f"peak_{k}={v / 1024:.1f}MiB" for k, v in peak.items()))


if __name__ == "__main__":
    main()
