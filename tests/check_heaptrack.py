#!/usr/bin/env python3
"""Runs a command under heaptrack and checks its allocation record.

usage: check_heaptrack.py OUT_PREFIX MAX_CALLS MAX_LEAKED -- COMMAND [ARG]...

The command must exit 0. heaptrack (Debian package heaptrack) records every
malloc/new of the process; heaptrack_print summarises the record. Checked:
  calls to allocation functions <= MAX_CALLS: loading the fleet makes about
    98 000; one allocation per step would add one per 2 ms of simulated
    time (1.8 million in an hour), so a limit of 200 000 catches any
    per-step allocation in runs of 200 s or more
  total memory leaked <= MAX_LEAKED bytes: what is still allocated at exit
    (one-time allocations of MuJoCo and the C++ runtime, about 150 KiB)
Prints "FAIL <what>" for each failed check (the CTest entry matches it).
"""
import re
import subprocess
import sys

UNITS = {"": 1, "B": 1, "K": 1024, "M": 1024 ** 2, "G": 1024 ** 3}


def size(text):
    m = re.fullmatch(r"([0-9.]+)([KMG]?)B?", text.strip())
    return float(m.group(1)) * UNITS[m.group(2)]


def main():
    if "--" not in sys.argv:
        sys.exit(__doc__)
    i = sys.argv.index("--")
    prefix, max_calls, max_leaked = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    cmd = sys.argv[i + 1:]
    failed = False
    run = subprocess.run(["heaptrack", "-o", prefix] + cmd)
    if run.returncode != 0:
        print("FAIL the command exited with status %d" % run.returncode)
        failed = True
    out = subprocess.run(["heaptrack_print", "-f", prefix + ".zst", "-p", "0", "-a", "0", "-T", "0"],
                         capture_output=True, text=True)
    calls = re.search(r"calls to allocation functions: (\d+)", out.stdout)
    leaked = re.search(r"total memory leaked: (\S+)", out.stdout)
    peak = re.search(r"peak heap memory consumption: (\S+)", out.stdout)
    if out.returncode != 0 or not calls or not leaked:
        print(out.stdout + out.stderr)
        print("FAIL heaptrack_print gave no summary for %s.zst" % prefix)
        return 1
    n, lk = int(calls.group(1)), size(leaked.group(1))
    print("[heaptrack] calls to allocation functions %d (limit %d), peak heap %s, "
          "leaked at exit %s (limit %.0f B); record %s.zst"
          % (n, max_calls, peak.group(1) if peak else "?", leaked.group(1), max_leaked, prefix))
    if n > max_calls:
        print("FAIL %d allocation calls > %d: something allocates while stepping "
              "(heaptrack_print -f %s.zst -a shows where)" % (n, max_calls, prefix))
        failed = True
    if lk > max_leaked:
        print("FAIL %s leaked at exit > %.0f B (heaptrack_print -f %s.zst -l shows where)"
              % (leaked.group(1), max_leaked, prefix))
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
