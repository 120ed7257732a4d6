#!/usr/bin/env python3
"""Regenerates the cases of tests/programs/bad/ whose bytes are awkward to type: very long
lines, NUL/control/non-ASCII bytes, CRLF mixes, a missing final newline, binary garbage.
Run from anywhere: python3 tests/programs/bad/generate.py  (output is deterministic)."""
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    if isinstance(data, str):
        data = data.encode("ascii")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


# About 1 MB in one block (default --max-line-length 65536): alarm 99001 at line 5.
write("line_1mb.MPF",
      "; Checks: a single block of about 1 MB (R1=1+1+...). Longer than the default\n"
      "; --max-line-length 65536: alarm 99001 at line 5, without reading it all into an\n"
      "; expression. Row: line 4 X1. Line 6 never runs. Status 2.\n"
      "G90 G1 X1 F100\n" + "R1=1" + "+1" * 524286 + "\n" + "G1 X2\nM30\n")

# About 2 KB in one block against --max-line-length 1000 (stands in for a 10 MB line).
write("line_length_limit.MPF",
      "; Checks: --max-line-length 1000 and a block of about 2 KB (stand-in for a 10 MB line,\n"
      "; which is too big to commit): alarm 99001 at line 5. Row: line 4 X1. Status 2.\n"
      ";\n"
      "G90 G1 X1 F100\n" + "R1=1" + "+1" * 1000 + "\n" + "G1 X2\nM30\n")

# 200 nested parentheses (default --max-expression-depth 64): alarm 99003.
write("parens_200.MPF",
      "; Checks: an expression nested 200 parentheses deep: alarm 99003 (limit 64) at line 4,\n"
      "; no stack overflow. Row: line 3 X1. Status 2.\n"
      "G90 G1 X1 F100\n" + "R1=" + "(" * 200 + "1" + ")" * 200 + "\n" + "G1 X2\nM30\n")

# 200 nested function calls.
write("function_nest_200.MPF",
      "; Checks: 200 nested function calls SIN(SIN(...)): alarm 99003 at line 4, no stack\n"
      "; overflow. Row: line 3 X1. Status 2.\n"
      "G90 G1 X1 F100\n" + "R1=" + "SIN(" * 200 + "1" + ")" * 200 + "\n" + "G1 X2\nM30\n")

# 30000 unary minus signs: recursion without parentheses.
write("unary_minus_chain.MPF",
      "; Checks: 30000 unary minus signs in a row (R1=---...1): the parser must count them as\n"
      "; nesting (alarm 99003 at line 5) instead of recursing until the stack overflows.\n"
      "; Row: line 4 X1. Status 2.\n"
      "G90 G1 X1 F100\n" + "R1=" + "-" * 30000 + "1\n" + "G1 X2\nM30\n")

# 10000 NOT operators.
write("not_chain.MPF",
      "; Checks: 10000 NOT operators in a row: alarm 99003 at line 4, no stack overflow.\n"
      "; Row: line 3 X1. Status 2.\n"
      "G90 G1 X1 F100\n" + "R1=" + "NOT " * 10000 + "1\n" + "G1 X2\nM30\n")

# 20 nested IF: the 17th (line 21) exceeds the 16 control structures of one level.
lines = ["; Checks: 20 nested IF structures. 16 per program level are allowed; the 17th IF (line 21)",
         "; raises 12641 in the load-time pre-scan, so nothing runs (no rows) although line 4 moves.",
         "; Lines 5..24 hold IF 1..20, closed by 20 ENDIF.",
         "G90 G1 X1 F100"]
lines += ["  " * i + "IF R1==0" for i in range(20)]
lines += ["  " * 20 + "G1 X2"]
lines += ["  " * i + "ENDIF" for i in reversed(range(20))]
lines += ["M30"]
write("if_nested_20.MPF", "\n".join(lines) + "\n")

# NUL byte inside a block.
write("nul_byte.MPF",
      b"; Checks: a NUL byte (0x00) inside a block, between 'X' and '2' on line 5: alarm 99011\n"
      b"; (byte not allowed outside comments and strings) at line 5; the NUL in the comment of\n"
      b"; line 4 is allowed. Row: line 4 X1. Status 2.\n"
      b"G90 G1 X1 F100 ; comment with \x00 NUL is fine\n"
      b"G1 X\x002\n"
      b"G1 X3\nM30\n")

# Control character (0x07 BEL, 0x1B ESC) inside a block.
write("control_char.MPF",
      b"; Checks: a control character (0x1B ESC) inside a block on line 4: alarm 99011 at line 4.\n"
      b"; Row: line 3 X1. Status 2.\n"
      b"G90 G1 X1 F100\n"
      b"G1 X2 \x1b[31m\n"
      b"G1 X3\nM30\n")

# Non-ASCII byte (Latin-1 micro sign) outside a comment.
write("non_ascii_byte.MPF",
      b"; Checks: a non-ASCII byte (0xB5, Latin-1 micro sign) outside a comment on line 5:\n"
      b"; alarm 99011 at line 5. In the comment of line 4 the same byte is allowed.\n"
      b"; Row: line 4 X1. Status 2.\n"
      b"G90 G1 X1 F100 ; 5 \xb5m is fine here\n"
      b"G1 X2 \xb5\n"
      b"G1 X3\nM30\n")

# UTF-8 text outside a comment.
write("utf8_outside_comment.MPF",
      "; Checks: UTF-8 text outside a comment: a variable name with a German umlaut on line 5\n"
      "; (first byte 0xC3) raises 99011 at line 5. UTF-8 in the comment of line 4 is allowed.\n"
      "; Row: line 4 X1. Status 2.\n"
      "G90 G1 X1 F100 ; Fräsen: Maß prüfen\n"
      "MAß=1\n"
      "G1 X3\nM30\n".encode("utf-8"))

# CRLF mixed with LF.
write("crlf_mixed.MPF",
      b"; Checks: CRLF and LF line ends mixed in one file. Both end a line; the line numbers\r\n"
      b"; count each ending once. Expected: no alarm; rows on lines 4, 5, 6, 7 (X1..X4).\n"
      b"; (Lines 1, 4 and 6 end with CRLF, the others with LF.)\r\n"
      b"G90 G1 X1 F100\r\n"
      b"G1 X2\n"
      b"G1 X3\r\n"
      b"G1 X4\n"
      b"M30\n")

# Last line without a newline: it still runs.
write("no_final_newline.MPF",
      b"; Checks: the last line has no newline at the end of the file; it is still a block and\n"
      b"; runs. Expected: rows line 3 X1, line 4 X2; no alarm.\n"
      b"G90 G1 X1 F100\n"
      b"G1 X2")

# An empty file: valid, no motion.
write("empty.MPF", b"")

# Binary garbage, deterministic. The first byte is forced to 0xFF so the first line is bad at
# column 1 whatever the generator yields.
rng = random.Random(20240611)
garbage = bytes([0xFF]) + bytes(rng.randrange(256) for _ in range(4095))
write("binary_garbage.MPF", garbage)

# A subprogram of binary garbage, called by sub_garbage.MPF.
rng = random.Random(7)
write("GARBAGE_SUB.SPF", bytes([0x80]) + bytes(rng.randrange(256) for _ in range(1023)))

# A tool name ($TC_TP2) of 200 characters, the STRING maximum: stored and selected by T="...".
name200 = "T" + "A" * 199
write("tool_name_200.MPF",
      "; Checks: a tool name ($TC_TP2) of 200 characters, the longest STRING (docs/limits.md), is\n"
      "; stored and selects its tool with T=\"...\" (line 7). Tool 1: length 10 ($TC_DP3), so\n"
      "; the carrier reference point (MCS) is 10 mm above the tool tip once Z moves (line 8).\n"
      "; Rows: line 6 X1 Z0; line 8 X2 Z10. Status 0.\n"
      f"$TC_TP2[1]=\"{name200}\" $TC_DP1[1,1]=120 $TC_DP3[1,1]=10\n"
      "G90 G1 X1 Z0 F100\n"
      f"T=\"{name200}\" D1\n"
      "G1 X2 Z0\n"
      "M30\n")

# A tool name of 300 characters: longer than any STRING, so the value range alarm 12160 of an
# over-long string (issue 14, finding 10: it used to be accepted).
write("tool_name_too_long.MPF",
      "; Checks: a tool name ($TC_TP2) of 300 characters, beyond the 200 of any STRING\n"
      "; (docs/limits.md): value range alarm 12160 at line 5, as for an over-long string value.\n"
      "; It used to be stored and selectable. Row: line 4 X1. Status 2.\n"
      "G90 G1 X1 F100\n"
      f"$TC_TP2[1]=\"{'N' * 300}\"\n"
      "G1 X2\n"
      "M30\n")

# MSG text with terminal escape sequences (ESC, BEL, a C1 CSI) and UTF-8: on stderr the
# control characters are written as \\xNN, the UTF-8 stays (issue 14, finding 10).
write("msg_terminal_escape.MPF",
      "; Checks: MSG texts with terminal control sequences (ESC [2J clears the screen, ESC ]0;\n"
      "; sets the window title, BEL, the C1 CSI U+009B) reach stderr escaped as \\xNN; the\n"
      "; UTF-8 umlaut stays. No alarm. Row: line 4 X1. Status 0.\n"
      "G90 G1 X1 F100\n".encode() +
      b'MSG("clear\x1b[2J title\x1b]0;owned\x07 csi\xc2\x9b31m Ma\xc3\x9f")\n'
      b"M30\n")

# Operator chains as long as the default --max-line-length 65536 allows (issue 14, item 1): a
# left-associative chain builds a tree as deep as it is long, which the evaluator walks in a
# loop; these crashed with a stack overflow before.
LIMIT = 65536


def chain(prefix, op_operand, suffix=""):
    """prefix + op_operand repeated, + suffix, exactly LIMIT characters (pads with blanks)."""
    n = (LIMIT - len(prefix) - len(suffix)) // len(op_operand)
    text = prefix + op_operand * n + suffix
    return text + " " * (LIMIT - len(text))


write("chain_plus_assign.MPF",
      "; Checks: R1=1+1+...+1 with 32766 '+' in a block of exactly 65536 characters (the default\n"
      "; --max-line-length) evaluates: R1 = 32767; row line 5 X32767. Status 0.\n"
      "G90 G1 X1 F100\n" + chain("R1=1", "+1") + "\n" + "G1 X=R1\nM30\n")

write("chain_minus_axis.MPF",
      "; Checks: an axis word G1 F100 X=1-0-0-...-0 of exactly 65536 characters evaluates:\n"
      "; X = 1; row line 3 X1 F100. Status 0.\n" + chain("G90 G1 F100 X=1", "-0") + "\n" +
      "M30\n")

write("chain_mul_if.MPF",
      "; Checks: an IF condition 1*1*...*1==1 of exactly 65536 characters evaluates (TRUE):\n"
      "; row line 5 X2 inside the IF. Status 0.\n"
      "G90 G1 X1 F100\n" + chain("IF 1", "*1", "==1") + "\n" + "G1 X2\nENDIF\nM30\n")

write("CHAIN_DP6.INI",
      "; Init file of chain_init: the radius $TC_DP6[1,1]=0+0+...+0+5 in one block of exactly\n"
      "; 65536 characters.\n"
      "CHANDATA(1)\n$TC_DP1[1,1]=120\n" + chain("$TC_DP6[1,1]=0", "+0", "+5") + "\nM17\n")

write("chain_init.MPF",
      "; Checks: an init file whose $TC_DP6[1,1]=0+0+...+5 fills the default line limit (65536\n"
      "; characters) sets the radius 5: R1=$TC_DP6[1,1] gives X5 (row line 5). Status 0.\n"
      "T1 D1\nR1=$TC_DP6[1,1]\nG90 G1 X=R1 F100\nM30\n")

# Nesting at and beyond the largest --max-expression-depth (1000, Limits::kMaxExpressionDepth).
write("depth_limit_1000.MPF",
      "; Checks: --max-expression-depth 1000 (the largest allowed): 999 nested parentheses are\n"
      "; 1000 levels with the expression itself and evaluate (R1 = 7, row line 6 X7); 1000\n"
      "; nested ABS( are 1001 levels: alarm 99003 naming the limit 1000 at line 7. Status 2.\n"
      "G90 G1 X1 F100\n"
      "R1=" + "(" * 999 + "7" + ")" * 999 + "\n"
      "G1 X=R1\n"
      "R2=" + "ABS(" * 1000 + "1" + ")" * 1000 + "\n"
      "G1 X=R2\nM30\n")

# A CR inside a line (issue 14, item 7): not a blank and not a line end (only CR LF is), so
# "G1 X10 F100<CR>Y10<CR>Z-5<CR><LF>" is no diagonal move but alarm 99011 naming the byte.
write("cr_inside_line.MPF",
      b"; Checks: a lone CR inside a block on line 5 (G1 X10 F100<CR>Y10<CR>Z-5<CR><LF>): the\n"
      b"; reader ends lines at LF and takes a CR only directly before it, so the first CR (column\n"
      b"; 12) is alarm 99011 - it used to be a blank and made one diagonal move. Row: line 4.\n"
      b"G90 G1 X1 F100\r\n"
      b"G1 X10 F100\rY10\rZ-5\r\n"
      b"M30\r\n")

# A form feed inside a line: alarm 99011 as well.
write("form_feed_inside_line.MPF",
      b"; Checks: a form feed (0x0C) between two words on line 4: alarm 99011 at line 4 (it\n"
      b"; used to be taken as a blank). Row: line 3 X1. Status 2.\n"
      b"G90 G1 X1 F100\n"
      b"G1 X2\x0cY2\n"
      b"M30\n")
