"""Runs a command with stderr on a pseudo-terminal (the CLI shows its progress line only there):
shared by progress_line_test.py and sink_paths_test.py."""
import os, pty, subprocess


def run_with_terminal_stderr(args, cwd, timeout=120):
    """(exit status, everything written to stderr as bytes)."""
    master, slave = pty.openpty()
    p = subprocess.Popen(args, cwd=cwd, stderr=slave, stdout=subprocess.DEVNULL)
    os.close(slave)
    out = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    p.wait(timeout=timeout)
    os.close(master)
    return p.returncode, out
