"""Runs a command with stderr on a pseudo-terminal (the CLI shows its progress line only there):
shared by progress_line_test.py and sink_paths_test.py."""
import os, pty, select, subprocess, time

# How long the terminal must stay quiet after the child's exit before its output counts as
# complete: the kernel hands what the child wrote to the master side through a work queue, so
# the last bytes can arrive a moment after the exit.
QUIET_AFTER_EXIT = 0.3


def run_with_terminal_stderr(args, cwd, timeout=120):
    """(exit status, everything written to stderr as bytes).

    The parent keeps its own descriptor of the terminal's slave side open while it reads: so the
    terminal is never hung up when the child exits, and no output still buffered in it is lost
    (reading the master after a hang-up can fail with EIO before everything was read, which made
    the comparisons of sink_paths_test.py fail now and then on a loaded machine)."""
    master, slave = pty.openpty()
    p = subprocess.Popen(args, cwd=cwd, stderr=slave, stdout=subprocess.DEVNULL)
    deadline = time.monotonic() + timeout
    out = b""
    quiet_since = None
    try:
        while True:
            ready, _, _ = select.select([master], [], [], 0.05)
            if ready:
                out += os.read(master, 65536)
                quiet_since = None
                continue
            if p.poll() is None:
                if time.monotonic() > deadline:
                    p.kill()
                    raise subprocess.TimeoutExpired(args, timeout)
                continue
            quiet_since = quiet_since or time.monotonic()
            if time.monotonic() - quiet_since >= QUIET_AFTER_EXIT:
                break
    finally:
        os.close(slave)
        os.close(master)
    return p.wait(), out
