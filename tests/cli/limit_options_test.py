#!/usr/bin/env python3
"""The --max-* limit options are parsed strictly (issue 14, finding 9): decimal digits only,
within the documented range (docs/limits.md); anything else is a usage error (exit 1) naming the
option. A value that CLI11 alone would read differently (hex, octal, clamped) must not slip
through and change or switch off a guard."""
import os, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-limits-")
prog = os.path.join(d, "P.MPF")
with open(prog, "w") as f:
    f.write("G90 G1 F100\n" + "".join(f"X{i}\n" for i in range(1, 21)) + "M30\n")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail}]"))
    if not cond:
        fails.append(name)


def run(*args):
    return subprocess.run([binary, *args, prog], capture_output=True, text=True, timeout=20)


options = ["--max-blocks", "--max-blocks-without-motion", "--max-line-length", "--max-expression-depth", "--max-program-levels",
           "--max-control-depth", "--max-variables", "--max-array-elements",
           "--max-total-elements"]
bad = ["0", "-1", "+5", " 5", "5 ", "0x10", "1e3", "1.5", "", "abc", "99999999999999999999",
       "18446744073709551617"]
for opt in options:
    # The stack-safe caps (docs/limits.md): line length 4 MiB, expression depth 1000.
    top = {"--max-blocks": "1000000000000", "--max-blocks-without-motion": "1000000000000",
           "--max-line-length": "4194304",
           "--max-expression-depth": "1000"}.get(opt, "2147483647")
    for value in bad + [str(int(top) + 1)]:
        p = run(opt, value)
        check(f"{opt} {value!r}: exit 1", p.returncode == 1, (p.returncode, p.stderr))
        check(f"{opt} {value!r}: names the option and range",
              p.stderr.startswith(f"{opt}: ") and f"1..{top}" in p.stderr, p.stderr)
        check(f"{opt} {value!r}: no output", p.stdout == "", p.stdout[:80])
    p = run(opt, top)
    check(f"{opt} {top}: the largest value is accepted", p.returncode == 0, p.stderr)

# Decimal, not octal: 010 is ten blocks, so block 11 (line 11) is the first one refused.
p = run("--max-blocks", "010")
check("--max-blocks 010 is ten", "P.MPF:11: alarm 99002:" in p.stderr, p.stderr)
check("--max-blocks 010: exit 2", p.returncode == 2, p.returncode)
p = run("--max-blocks", "10")
check("--max-blocks 10 the same", "P.MPF:11: alarm 99002:" in p.stderr, p.stderr)

print("all limit option checks hold" if not fails else f"{len(fails)} limit option checks fail")
sys.exit(1 if fails else 0)
