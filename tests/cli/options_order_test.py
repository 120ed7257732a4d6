#!/usr/bin/env python3
"""The PROGRAM argument may follow a repeated --init (each --init takes exactly one file):
`ncoffset --init A --init B PROGRAM` runs like `ncoffset PROGRAM --init A --init B`."""
import os
import subprocess
import sys

cli = sys.argv[1]
examples = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")
before = subprocess.run([cli, "--init", "tools.INI", "--init", "frames.INI", "frames.MPF"],
                        cwd=examples, capture_output=True, text=True)
after = subprocess.run([cli, "frames.MPF", "--init", "tools.INI", "--init", "frames.INI"],
                       cwd=examples, capture_output=True, text=True)
assert before.returncode == 0, before.stderr
assert after.returncode == 0, after.stderr
assert before.stdout == after.stdout and before.stdout.count("\n") > 2, (before.stdout, after.stdout)
print("ok")
