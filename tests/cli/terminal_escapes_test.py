#!/usr/bin/env python3
"""Program text on stderr is escaped (issue 14, finding 10): MSG texts, alarm texts that quote
program text and file names reach a terminal with control characters (C0, DEL, C1) and invalid
UTF-8 bytes as \\xNN; printable ASCII and valid UTF-8 stay as they are."""
import os, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
d = tempfile.mkdtemp(prefix="ncoffset-escapes-")
fails = []


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail!r}]"))
    if not cond:
        fails.append(name)


def run(name, text):
    path = os.path.join(d, name)
    with open(path, "wb") as f:
        f.write(text)
    return subprocess.run([binary, os.path.basename(path)], cwd=d, capture_output=True, timeout=20)


def clean(err):
    return not any(b < 0x20 and b != 0x0A or b == 0x7F for b in err) and b"\xc2\x9b" not in err


p = run("MSG.MPF", b'G90 G1 X1 F100\nMSG("a\x1b[31mred\x07 tab\there \xc2\x9b2J Ma\xc3\x9f \xb5 \x7f")\nM30\n')
check("MSG: exit 0", p.returncode == 0, p.stderr)
check("MSG: escaped", b"MSG.MPF:2: message: a\\x1b[31mred\\x07 tab\\x09here \\xc2\\x9b2J Ma\xc3\x9f \\xb5 \\x7f\n"
      == p.stderr, p.stderr)
check("MSG: no raw control character", clean(p.stderr), p.stderr)

p = run("TOOL.MPF", b'G90 G1 X1 F100\nT="\x1b]0;owned\x07"\nM30\n')
check("alarm quoting program text: exit 2", p.returncode == 2, p.stderr)
check("alarm quoting program text: escaped", b"\\x1b]0;owned\\x07" in p.stderr, p.stderr)
check("alarm quoting program text: no raw control character", clean(p.stderr), p.stderr)

p = run("E\x1b[2J.MPF", b"G90 G1 X1 F100\nR1=1/0\nM30\n")
check("file name in an alarm: exit 2", p.returncode == 2, p.stderr)
check("file name in an alarm: escaped", p.stderr.startswith(b"E\\x1b[2J.MPF:2: alarm 14051: "), p.stderr)
check("file name in an alarm: no raw control character", clean(p.stderr), p.stderr)

p = subprocess.run([binary, "NO\x1b[2JSUCH.MPF"], cwd=d, capture_output=True, timeout=20)
check("file name in a file error: exit 1", p.returncode == 1, p.stderr)
check("file name in a file error: escaped", b"NO\\x1b[2JSUCH.MPF: cannot read" in p.stderr, p.stderr)

p = subprocess.run([binary, "--max-blocks", "1\x1b[2J", "P.MPF"], cwd=d, capture_output=True,
                   timeout=20)
check("usage error quoting an argument: exit 1", p.returncode == 1, p.stderr)
check("usage error quoting an argument: escaped", b"'1\\x1b[2J'" in p.stderr, p.stderr)

print("all escape checks hold" if not fails else f"{len(fails)} escape checks fail")
sys.exit(1 if fails else 0)
