#!/usr/bin/env python3
"""Checks the size rules of docs/architecture.md: no source file in src/ over 500 lines, no
function over 80 lines (from the line of its opening brace to its closing brace).

Functions are found by brace matching on the text with comments, strings and character literals
blanked: a `{` whose statement text before it ends in `)` (optionally followed by const,
noexcept, override, final, a trailing return type or a member-initialiser list) and does not
start with a control keyword opens a function body. Lambdas count as part of their function.
Exit status 1 and one line per violation when a rule is broken."""
import re
import sys
from pathlib import Path

MAX_FILE_LINES = 500
MAX_FUNCTION_LINES = 80
CONTROL = re.compile(r"^(if|for|while|switch|catch|do|else|return|case)\b")


def blank(text: str) -> str:
    """Replaces comments and string/char literals by spaces, keeping newlines."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            # a digit separator (1'000) is no character literal
            if c == "'" and i > 0 and text[i - 1].isalnum() and j - i > 3:
                out.append(c)
                i += 1
                continue
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def is_function_head(head: str) -> bool:
    head = " ".join(head.split())
    if not head or CONTROL.match(head) or "=" in head.split("(")[0]:
        return False
    if re.search(r"\]\s*\([^()]*\)\s*(mutable\s*)?(->\s*[\w:<>&* ]+)?$", head):
        return False  # a lambda
    # a constructor's member-initialiser list: `) : a_(x), b_{y}` (a single colon, not `::`)
    head = re.sub(r"\)\s*(?<!:):(?!:)\s*\w.*$", ")", head)
    return bool(re.search(r"\)\s*(const|noexcept|override|final|\s|->\s*[\w:<>&*, ]+)*$", head))


def functions(text: str):
    """Yields (first_line, line_count) of each function body."""
    b = blank(text)
    stack, last_stop = [], 0
    for i, c in enumerate(b):
        if c == "{":
            head = b[last_stop:i]
            stack.append((i, is_function_head(head) and not any(f for _, f in stack)))
            last_stop = i + 1
        elif c == "}":
            if stack:
                start, is_func = stack.pop()
                if is_func:
                    first = b.count("\n", 0, start) + 1
                    yield first, b.count("\n", start, i) + 1
            last_stop = i + 1
        elif c == ";":
            last_stop = i + 1


def main() -> int:
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    bad = []
    for path in sorted((root / "src").rglob("*")):
        if path.suffix not in (".cpp", ".hpp"):
            continue
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(root)
        lines = text.count("\n")
        if lines > MAX_FILE_LINES:
            bad.append(f"{rel}: {lines} lines (at most {MAX_FILE_LINES})")
        for first, count in functions(text):
            if count > MAX_FUNCTION_LINES:
                bad.append(f"{rel}:{first}: function of {count} lines (at most {MAX_FUNCTION_LINES})")
    for line in bad:
        print(line)
    print(f"check-size: {len(bad)} violation(s)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
