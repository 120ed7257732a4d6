#!/usr/bin/env python3
"""Outputs are written safely (issue 14, findings 2 and 3): an output (-o, --vars) that is the
same file as an input or as the other output is refused (exit 1) and nothing is touched; an
output goes to a temporary file beside its target and is renamed onto it at the end, so a write
error (exit 1) leaves the target as it was and no temporary file behind; a device is written
directly, with its errors checked too."""
import json, os, resource, signal, subprocess, sys, tempfile

binary = os.path.abspath(sys.argv[1])
fails = []
PROGRAM = b"; a small program\nG90 G1 X1 F100\nY2\nM30\n"
INIT = b"R1=5\n"


def check(name, cond, detail=""):
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f"  [{detail!r}]"))
    if not cond:
        fails.append(name)


def fresh():
    d = tempfile.mkdtemp(prefix="ncoffset-outputs-")
    for name, data in (("P.MPF", PROGRAM), ("T.INI", INIT)):
        with open(os.path.join(d, name), "wb") as f:
            f.write(data)
    return d


def read(d, name):
    with open(os.path.join(d, name), "rb") as f:
        return f.read()


def leftovers(d):
    return [n for n in os.listdir(d) if ".ncoffset-" in n]


def run(d, *args, preexec=None, stdout=subprocess.PIPE):
    return subprocess.run([binary, *args], cwd=d, stdout=stdout, stderr=subprocess.PIPE,
                          timeout=20, preexec_fn=preexec)


# An output that is an input, by every spelling: refused before anything is opened.
for what, args, link in [
        ("-o = program", ["P.MPF", "-o", "P.MPF"], None),
        ("-o = ./program", ["P.MPF", "-o", "./P.MPF"], None),
        ("-o = program by absolute path", ["P.MPF", "-o", "{d}/P.MPF"], None),
        ("-o = program via ../", ["P.MPF", "-o", "../{base}/P.MPF"], None),
        ("-o = hard link to the program", ["P.MPF", "-o", "HARD.CSV"], "hard"),
        ("-o = symlink to the program", ["P.MPF", "-o", "SOFT.CSV"], "soft"),
        ("-o = init file", ["--init", "T.INI", "P.MPF", "-o", "T.INI"], None),
        ("-o = hard link to the init file", ["--init", "T.INI", "P.MPF", "-o", "HARDINI"], "hardini"),
        ("--vars = program", ["P.MPF", "--vars", "P.MPF"], None),
        ("--vars = symlink to the program", ["P.MPF", "--vars", "SOFT.CSV"], "soft"),
        ("--vars = init file", ["--init", "T.INI", "P.MPF", "--vars", "./T.INI"], None)]:
    d = fresh()
    if link == "hard":
        os.link(os.path.join(d, "P.MPF"), os.path.join(d, "HARD.CSV"))
    elif link == "soft":
        os.symlink("P.MPF", os.path.join(d, "SOFT.CSV"))
    elif link == "hardini":
        os.link(os.path.join(d, "T.INI"), os.path.join(d, "HARDINI"))
    args = [a.format(d=d, base=os.path.basename(d)) for a in args]
    p = run(d, *args)
    err = p.stderr.decode()
    check(f"{what}: exit 1", p.returncode == 1, (p.returncode, err))
    check(f"{what}: names both paths", "is the same file as" in err and args[-1] in err, err)
    check(f"{what}: program unchanged", read(d, "P.MPF") == PROGRAM)
    check(f"{what}: init file unchanged", read(d, "T.INI") == INIT)
    check(f"{what}: nothing run", p.stdout == b"", p.stdout)
    check(f"{what}: no temporary file", not leftovers(d), leftovers(d))

# The two outputs the same file: existing, not yet existing (two spellings), via a link.
for what, setup, args in [
        ("-o = --vars, existing", "out", ["P.MPF", "-o", "out.csv", "--vars", "out.csv"]),
        ("-o = --vars, not yet existing", None, ["P.MPF", "-o", "out.csv", "--vars", "./out.csv"]),
        ("-o = --vars, a link to it", "link", ["P.MPF", "-o", "out.csv", "--vars", "l.json"]),
        ("-o = --vars, a dangling link to it", "dangling", ["P.MPF", "-o", "l.json", "--vars", "out.csv"])]:
    d = fresh()
    if setup == "out":
        with open(os.path.join(d, "out.csv"), "wb") as f:
            f.write(b"old\n")
    if setup in ("link", "dangling"):
        os.symlink("out.csv", os.path.join(d, "l.json"))
    p = run(d, *args)
    err = p.stderr.decode()
    check(f"{what}: exit 1", p.returncode == 1, (p.returncode, err))
    check(f"{what}: names both", f"--vars {args[-1]} is the same file as -o {args[2]}" in err, err)
    exists = os.path.exists(os.path.join(d, "out.csv"))
    check(f"{what}: untouched", read(d, "out.csv") == b"old\n" if setup == "out" else not exists)
    check(f"{what}: no temporary file", not leftovers(d), leftovers(d))

# Devices take both outputs; /dev/full fails each (ENOSPC), stdout included.
d = fresh()
p = run(d, "P.MPF", "-o", "/dev/null", "--vars", "/dev/null")
check("/dev/null for both outputs: exit 0", p.returncode == 0, p.stderr)
for what, args, out in [("-o /dev/full", ["-o", "/dev/full"], None),
                        ("--vars /dev/full", ["--vars", "/dev/full"], None),
                        ("stdout on /dev/full", [], "/dev/full")]:
    with open(out or os.devnull, "wb") as sink:
        p = run(d, "P.MPF", *args, stdout=sink)
    err = p.stderr.decode()
    check(f"{what}: exit 1", p.returncode == 1, (p.returncode, err))
    check(f"{what}: says why", "cannot write: No space left on device" in err, err)

# A missing folder, a directory as output.
d = fresh()
p = run(d, "P.MPF", "-o", "no/such/dir/out.csv")
check("-o into a missing directory: exit 1", p.returncode == 1, p.stderr)
check("-o into a missing directory: says why", b"No such file or directory" in p.stderr, p.stderr)
p = run(d, "P.MPF", "--vars", "no/such/dir/v.json")
check("--vars into a missing directory: exit 1", p.returncode == 1, p.stderr)
p = run(d, "P.MPF", "-o", ".")
check("-o a directory: exit 1", p.returncode == 1, p.stderr)

# Success: the target is replaced (its permissions kept), no temporary file stays.
d = fresh()
target = os.path.join(d, "out.csv")
with open(target, "wb") as f:
    f.write(b"old content\n" * 1000)
os.chmod(target, 0o640)
p = run(d, "P.MPF", "-o", "out.csv", "--vars", "v.json")
check("success: exit 0", p.returncode == 0, p.stderr)
check("success: the path written", read(d, "out.csv").startswith(b"line,motion,") and
      read(d, "out.csv").count(b"\n") == 3, read(d, "out.csv"))
check("success: the variables written", read(d, "v.json").startswith(b"{"), read(d, "v.json"))
check("success: permissions kept", os.stat(target).st_mode & 0o777 == 0o640, oct(os.stat(target).st_mode))
check("success: no temporary file", not leftovers(d), leftovers(d))

# A hard link of the replaced file keeps its old contents (the target is exchanged with the
# temporary file, then the old contents' temporary name removed: docs/robustness.md).
d = fresh()
target = os.path.join(d, "out.csv")
with open(target, "wb") as f:
    f.write(b"old content\n")
os.link(target, os.path.join(d, "keep.csv"))
p = run(d, "P.MPF", "-o", "out.csv")
check("hard link: exit 0", p.returncode == 0, p.stderr)
check("hard link: the target replaced", read(d, "out.csv").startswith(b"line,motion,"))
check("hard link: the link keeps the old contents", read(d, "keep.csv") == b"old content\n")
check("hard link: no temporary file", not leftovers(d), leftovers(d))

# A target name near NAME_MAX still gets a temporary file name that fits beside it.
long_name = "L" * 250 + ".csv"
p = run(d, "P.MPF", "-o", long_name)
check("a 254-byte target name: exit 0", p.returncode == 0, p.stderr)
check("a 254-byte target name: written", read(d, long_name).startswith(b"line,motion,"))
check("a 254-byte target name: no temporary file", not leftovers(d), leftovers(d))

# An alarm: the path up to it is written, as before (exit 2), and the variables too.
with open(os.path.join(d, "A.MPF"), "wb") as f:
    f.write(b"G90 G1 X1 F100\nR2=7\nR1=1/0\nX3\nM30\n")
p = run(d, "A.MPF", "-o", "out.csv", "--vars", "v.json")
check("alarm: exit 2", p.returncode == 2, p.stderr)
check("alarm: the row before it", read(d, "out.csv").count(b"\n") == 2, read(d, "out.csv"))
check("alarm: the variables", json.loads(read(d, "v.json"))["R"] == {"2": 7}, read(d, "v.json"))
check("alarm: no temporary file", not leftovers(d), leftovers(d))

# A write error on a regular file (the file size limit: EFBIG): exit 1, target untouched.
with open(os.path.join(d, "BIG.MPF"), "wb") as f:
    f.write(b"G90 G1 F100\n" + b"".join(b"X%d\n" % (i % 50 + 1) for i in range(20000)) + b"M30\n")
before = read(d, "out.csv")


def small_files():
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (50000, 50000))


p = run(d, "BIG.MPF", "-o", "out.csv", preexec=small_files)
check("write error: exit 1", p.returncode == 1, p.stderr)
check("write error: says why", b"out.csv: cannot write: File too large" in p.stderr, p.stderr)
check("write error: target untouched", read(d, "out.csv") == before)
check("write error: no temporary file", not leftovers(d), leftovers(d))
p = run(d, "BIG.MPF", "--format", "svg", "-o", "out.csv", preexec=small_files)
check("write error (svg): exit 1", p.returncode == 1, p.stderr)
check("write error (svg): target untouched", read(d, "out.csv") == before)
check("write error (svg): no temporary file", not leftovers(d), leftovers(d))

print("all output safety checks hold" if not fails else f"{len(fails)} output safety checks fail")
sys.exit(1 if fails else 0)
