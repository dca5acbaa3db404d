#!/usr/bin/env python3
"""Run mjbuoy-sim with a CSV and check statistics of its columns.

check_csv.py SIM MODEL --duration S --from T0 [--mean COL=VALUE:TOL]...
  [--mean-abs COL=MAX]... [--within COL=LO:HI]...
Exits 1 with the failing check, the measured value and the bound.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sim")
    ap.add_argument("model")
    ap.add_argument("--duration", type=float, required=True)
    ap.add_argument("--from", dest="t0", type=float, default=0.0)
    ap.add_argument("--arg", action="append", default=[], help="extra mjbuoy-sim argument")
    ap.add_argument("--mean", action="append", default=[])
    ap.add_argument("--mean-abs", action="append", default=[])
    ap.add_argument("--within", action="append", default=[])
    a = ap.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.csv")
        cmd = [a.sim, a.model, "--duration", str(a.duration), "--csv", out] + a.arg
        subprocess.run(cmd, check=True)
        with open(out) as f:
            rows = [r for r in csv.DictReader(f) if float(r["time"]) >= a.t0]
    if not rows:
        print("no rows after t =", a.t0)
        return 1

    def col(name):
        if name not in rows[0]:
            sys.exit("no column %s; columns: %s" % (name, ", ".join(rows[0])))
        return [float(r[name]) for r in rows]

    failed = 0

    def report(ok, what, value, bound):
        nonlocal failed
        print("%s %s = %.6g (bound %s)" % ("ok  " if ok else "FAIL", what, value, bound))
        failed += not ok

    for spec in a.mean:
        name, rest = spec.split("=")
        want, tol = map(float, rest.split(":"))
        m = sum(col(name)) / len(rows)
        report(abs(m - want) <= tol, "mean " + name, m, "%g +- %g" % (want, tol))
    for spec in a.mean_abs:
        name, most = spec.split("=")
        m = sum(abs(v) for v in col(name)) / len(rows)
        report(m <= float(most), "mean |%s|" % name, m, "<= " + most)
    for spec in a.within:
        name, rest = spec.split("=")
        lo, hi = map(float, rest.split(":"))
        vals = col(name)
        bad = [v for v in vals if not (lo <= v <= hi) or math.isnan(v)]
        report(not bad, "range " + name, bad[0] if bad else vals[-1], "[%g, %g]" % (lo, hi))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
