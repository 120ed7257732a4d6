#!/usr/bin/env python3
"""Where the instructions of an ncoffset run go, stage by stage (docs/performance.md §24).

  stage_profile.py NCOFFSET PROGRAM [--init FILE ...] [--blocks N] [--callgrind-out F]
  stage_profile.py NCOFFSET --suite DIR [--blocks N]
  stage_profile.py --from CALLGRIND.OUT --blocks N

runs `valgrind --tool=callgrind NCOFFSET -q -o /dev/null PROGRAM --init ...` (the whole process)
and splits its instructions into the pipeline's stages: process start-up, file mapping, the
structure pre-scan, reading lines, parsing, collecting the words, block end, motion building,
SAR, radius compensation, placement, CSV writing and the rest; per stage the instructions, the
instructions per block and the share. `--suite DIR` writes the four programs of §24 (plain G1,
the G41/G42 contour with integral coordinates and with decimals, a WHILE loop with expressions)
into DIR and prints a table for each. The binary needs its symbols (any build that is not
stripped; a `-g` build adds nothing at function level, its code is the same).

How a stage is counted: the callgrind file holds, per function, its own instructions and, per
call arc (caller -> callee), the instructions spent in the callee and below for those calls.
A function is *owned* by a stage when its name matches one of the stage's patterns (STAGES);
every other function (std::, libc, libm, geometry, helpers) belongs to whoever calls it. A
stage's cost is the own instructions of its functions plus the inclusive cost of their calls
into functions no stage owns, less what those calls spend again in owned functions (a helper
that calls back into a stage; split by the arc's share of the helper's cost). So every
instruction is counted once: the stages add up to the process total.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

# (stage, name patterns). The first matching stage owns a function; patterns are matched at the
# start of the demangled name. Owning only the entry functions of a stage is enough: what they
# call and no stage owns is theirs.
STAGES = [
    ("process start-up, CLI, exit", [r"main$", r"_GLOBAL__sub_I", r"ncoffset::cli::"]),
    ("file mapping (SourceFile)", [r"ncoffset::lang::SourceFile::"]),
    ("pre-scan (ProgramIndex)", [r"ncoffset::lang::ProgramIndex::"]),
    # The block loop reads each line and, since docs/performance.md section 34, scans, collects
    # and ends a plain line (X, Y, Z, G0..G3, G40..G42, F, CR= alone) inline: plainLine and
    # finishPlainBlock are no functions of their own any more (section 30 had them as a stage
    # "plain line"). The other lines are parsed, collected and ended in the stages below.
    ("reading lines and plain lines (Interpreter::run)",
     [r"ncoffset::interp::Interpreter::run\(", r"ncoffset::interp::ProgramFlow::",
      r"ncoffset::interp::Interpreter::plainLine\(",
      r"ncoffset::interp::Interpreter::finishPlainBlock\("]),
    ("parsing (parseBlock)", [r"ncoffset::lang::parseBlock\(", r"ncoffset::lang::Parser::"]),
    ("collecting words (executeBlock, collectWord, assign)",
     [r"ncoffset::interp::Interpreter::executeBlock\("]),
    ("block end (finishBlock)", [r"ncoffset::interp::Interpreter::finishBlock\("]),
    ("motion building (MotionBuilder)", [r"ncoffset::interp::MotionBuilder::"]),
    ("SAR (SmoothApproach)", [r"ncoffset::trc::SmoothApproach::"]),
    ("radius compensation (RadiusCompensation)", [r"ncoffset::trc::"]),
    ("placement (Placement)", [r"ncoffset::place::"]),
    ("CSV writing (sink chain, CsvWriter)",
     [r"ncoffset::out::", r"ncoffset::SwitchSink::", r"\(anonymous namespace\)::MessagePrinter::",
      r"ncoffset::motionName\("]),
    ("rest (Channel: set-up, init files, end of run)", [r"ncoffset::Channel::"]),
]
STAGE_INDEX = {name: i for i, (name, _) in enumerate(STAGES)}
START_UP = 0  # the stage that gets what runs outside every owned function (the dynamic loader)


class Profile:
    """Own costs and call arcs of one callgrind output file (format version 1, event Ir)."""

    def __init__(self, path):
        self.self_cost = {}  # function -> own instructions
        self.arcs = {}  # (caller, callee) -> inclusive instructions of those calls
        self.total = 0
        names = {}
        fn = callee = None
        in_call = False
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith(("fn=", "cfn=")):
                    key, _, rest = line.rstrip("\n").partition("=")
                    m = re.match(r"\((\d+)\)(?: (.*))?$", rest)
                    name = (names.setdefault(m.group(1), m.group(2)) if m.group(2) is not None
                            else names[m.group(1)]) if m else rest
                    if key == "fn":
                        fn = name
                    else:
                        callee = name
                elif line.startswith("calls="):
                    in_call = True
                elif line.startswith("summary:") or line.startswith("totals:"):
                    self.total = max(self.total, int(line.split()[1]))
                elif line[:1] in "0123456789+-*" and fn is not None:
                    parts = line.split()
                    cost = int(parts[1]) if len(parts) > 1 else 0
                    if in_call:
                        self.arcs[(fn, callee)] = self.arcs.get((fn, callee), 0) + cost
                        in_call = False
                    else:
                        self.self_cost[fn] = self.self_cost.get(fn, 0) + cost
        self.callees = {}
        self.inclusive = {}
        for (caller, callee), cost in self.arcs.items():
            self.callees.setdefault(caller, []).append(callee)
            if caller != callee:
                self.inclusive[callee] = self.inclusive.get(callee, 0) + cost


def owner(name, compiled):
    for index, patterns in enumerate(compiled):
        if any(p.match(name) for p in patterns):
            return index
    return None


def stage_costs(profile):
    """Instructions per stage (index into STAGES), adding up to the process total, and per stage
    the parts: {function: instructions}, an owned function's own instructions under its name, a
    call into an unowned function under the callee's name."""
    compiled = [[re.compile(p) for p in patterns] for _, patterns in STAGES]
    owners = {}
    leak_memo = {}

    def own(name):
        if name not in owners:
            owners[name] = owner(name, compiled)
        return owners[name]

    def share(g, cost):
        incl = profile.inclusive.get(g, 0)
        return cost / incl if incl else 0

    def leak(g, visiting):
        """Instructions that calls of the unowned `g` spend in owned functions (all callers)."""
        if g in leak_memo:
            return leak_memo[g]
        if g in visiting:
            return 0
        visiting.add(g)
        total = 0
        for h in profile.callees.get(g, ()):
            if h != g:
                cost = profile.arcs[(g, h)]
                total += cost if own(h) is not None else leak(h, visiting) * share(h, cost)
        visiting.discard(g)
        leak_memo[g] = total
        return total

    costs = [0.0] * len(STAGES)
    parts = [{} for _ in STAGES]
    for f in set(profile.self_cost) | set(profile.callees):
        s = own(f)
        if s is None:
            continue
        items = [(f, profile.self_cost.get(f, 0))]
        for g in profile.callees.get(f, ()):
            if g != f and own(g) is None:
                cost = profile.arcs[(f, g)]
                items.append((g, cost - leak(g, set()) * share(g, cost)))
        for name, cost in items:
            costs[s] += cost
            parts[s][name] = parts[s].get(name, 0) + cost
    outside = profile.total - sum(costs)  # the loader and libc around main
    costs[START_UP] += outside
    parts[START_UP]["(outside main: loader, libc)"] = outside
    return costs, parts


def short(name, width=70):
    """A function name without its parameter list, at most `width` characters."""
    name = re.sub(r"( \[clone [^]]*\]| const)+$", "", name)
    if name.endswith(")"):
        depth = 0
        for i in range(len(name) - 1, -1, -1):
            depth += {")": 1, "(": -1}.get(name[i], 0)
            if depth == 0:
                name = name[:i] if i > 0 else name
                break
    return name if len(name) <= width else "..." + name[-(width - 3):]


def print_table(title, costs, total, blocks, parts=None, top=0):
    print(f"\n{title}: {total:,} instructions, {blocks:,} blocks, "
          f"{total / blocks:,.0f} per block (whole process)")
    print(f"  {'stage':<56} {'instructions':>14} {'per block':>10} {'share':>7}")
    for (name, _), cost in zip(STAGES, costs):
        print(f"  {name:<56} {cost:14,.0f} {cost / blocks:10,.1f} {100 * cost / total:6.1f} %")
        if parts and top:
            for fn, c in sorted(parts[STAGE_INDEX[name]].items(), key=lambda kv: -kv[1])[:top]:
                if c >= 0.5 * blocks:  # at least half an instruction per block
                    print(f"      {short(fn, 66):<66} {c / blocks:10,.1f}")
    print(f"  {'whole process':<56} {total:14,} {total / blocks:10,.1f} {100.0:6.1f} %")


def count_blocks(path):
    """Lines that are blocks: not empty, not only a comment."""
    with open(path, encoding="latin-1") as f:
        return sum(1 for line in f if line.strip() and not line.lstrip().startswith(";"))


def run_callgrind(ncoffset, program, inits, out):
    argv = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", ncoffset, "-q", "-o",
            os.devnull, program]
    for init in inits:
        argv += ["--init", init]
    p = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed ({p.returncode}):\n{p.stderr[-2000:]}")


def loop_program(path, blocks):
    """bench/interp_bench.cpp's BM_LoopArcsExpr program as a file, with about `blocks` executed
    lines: the text of its loopProgram() (string literals and the pass count) and its lines per
    pass, taken from that source. Returns (passes, executed lines)."""
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "interp_bench.cpp")) as f:
        source = f.read()
    body = re.search(r"std::string loopProgram\(long iterations\) \{(.*?)\n\}", source, re.S)
    if not body:
        raise SystemExit("stage_profile: loopProgram() not found in bench/interp_bench.cpp")
    lines_per_pass = int(re.search(r"kLoopLinesPerIteration = (\d+);", source).group(1))
    passes = max(1, blocks // lines_per_pass)
    text = ""
    for literal, count in re.findall(r'"((?:[^"\\]|\\.)*)"|(std::to_string\(iterations\))',
                                     body.group(1)):
        text += str(passes) if count else literal.encode().decode("unicode_escape")
    with open(path, "w") as f:
        f.write(text)
    # The passes, the lines before and after the loop, and the WHILE test that ends it.
    return passes, passes * lines_per_pass + text.count("\n") - lines_per_pass + 1


def suite(directory, blocks):
    """The four programs of §24: (title, program, inits, blocks)."""
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path.insert(0, here)
    import trc_contour

    os.makedirs(directory, exist_ok=True)
    plain = os.path.join(directory, "PLAIN.MPF")
    subprocess.run([sys.executable, os.path.join(here, "gen_program.py"), str(blocks), plain],
                   check=True)
    out = [(f"plain G1 (bench/gen_program.py {blocks})", plain, [], blocks + 1)]
    for decimals in (False, True):
        p = trc_contour.write(os.path.join(directory, "decimals" if decimals else "integral"),
                              blocks, decimals)
        title = "G41/G42 contour" + (", decimals in every coordinate" if decimals else "")
        out.append((f"{title} (bench/trc_contour.py)", p["mpf"], [p["init"]], p["blocks"]))
    loop = os.path.join(directory, "LOOP.MPF")
    passes, lines = loop_program(loop, blocks)
    out.append((f"WHILE loop with expressions, {passes:,} passes (executed lines)", loop, [],
                lines))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("ncoffset", nargs="?", help="the ncoffset binary (with its symbols)")
    ap.add_argument("program", nargs="?", help="the part program")
    ap.add_argument("--init", action="append", default=[], help="init file (repeatable)")
    ap.add_argument("--blocks", type=int, help="blocks for the per-block column (default: the "
                    "program's non-comment lines; with --suite the programs' size, 100000)")
    ap.add_argument("--suite", metavar="DIR", help="write the four programs of §24 here and "
                    "profile each")
    ap.add_argument("--functions", type=int, default=0, metavar="N",
                    help="under each stage its N costliest parts (own code, unowned callees)")
    ap.add_argument("--callgrind-out", help="keep the callgrind file here")
    ap.add_argument("--from", dest="from_file", help="read this callgrind file, run nothing")
    a = ap.parse_args()
    if a.from_file:
        if not a.blocks:
            ap.error("--from needs --blocks")
        profile = Profile(a.from_file)
        costs, parts = stage_costs(profile)
        print_table(a.from_file, costs, profile.total, a.blocks, parts, a.functions)
        return 0
    if not a.ncoffset or not (a.program or a.suite):
        ap.error("give NCOFFSET and PROGRAM, or NCOFFSET --suite DIR, or --from FILE")
    if not shutil.which("valgrind"):
        print("stage_profile: SKIP: valgrind is not on PATH")
        return 77  # ctest's SKIP_RETURN_CODE
    jobs = (suite(a.suite, a.blocks or 100000) if a.suite
            else [(a.program, a.program, a.init, a.blocks or count_blocks(a.program))])
    failures = []
    for title, program, inits, blocks in jobs:
        with tempfile.TemporaryDirectory() as tmp:
            out = a.callgrind_out if a.callgrind_out and not a.suite else os.path.join(tmp, "cg")
            run_callgrind(a.ncoffset, program, inits, out)
            profile = Profile(out)
            costs, parts = stage_costs(profile)
            print_table(title, costs, profile.total, blocks, parts, a.functions)
            if a.suite and "contour" in title:
                failures += [f"{title}: {name}" for (name, _), cost in zip(STAGES, costs)
                             if cost <= 0 and name != STAGES[-1][0]]
    if failures:
        # A stage without instructions on the contour: a function of STAGES was renamed or
        # inlined away, and its cost is counted in the stage of its caller.
        print("\nstage_profile: FAIL: no instructions in\n  " + "\n  ".join(failures) +
              "\n(update STAGES in bench/stage_profile.py)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
