#!/usr/bin/env python3
"""End-to-end tests of mjbuoy-sweep (docs/sweeps.md).

check_sweep.py MODE BIN [ARGS]; prints "FAIL ..." and exits 1 on a failure.
  list BIN                expansion of tests/sweeps/expand.xml
  invalid BIN FILE        an invalid sweep: exit 2 and the 'expect output' regex of its comment
  local BIN               --jobs 1 and 2 merge identically; a killed run resumes only the
                          missing cases; a crashing case and failing checks are recorded
  slurm BIN               the same sweep as a Slurm array on a local single-node Slurm
  rao BIN                 examples/rao/rao.xml against the hydrostatic heave prediction
  sensor BIN              statistics of sensors (sensors.xml) against Archimedes; an
                          unknown sensor makes the case invalid (sensor_unknown.xml)
  stale BIN               a changed model (mass), hull mesh or included file reruns its
                          cases and merge publishes no stale result; the heavier barge
                          floats deeper by the Archimedes ratio of the masses
  inject BIN              a newline or shell characters in the sweep's name or any
                          sbatch option are refused naming the option and its form;
                          nothing of them reaches a script; --shard 0/2/3 is refused
  fifo BIN                a FIFO in the results folder is refused by run and merge
                          (they blocked forever), naming it; run does not write its
                          manifest over the sweep file
  mooring BIN             a tiny examples/mooring/pretension.xml (two lengths, calm, 20 s):
                          the fairlead tension at rest against the elastic catenary
  cluster BIN             the scripts run as they are on a cluster: --time and --mem
                          from the measured case, --jobs 0 from the CPU allocation
                          (taskset, SLURM_CPUS_PER_TASK), one shared radiation cache
                          filled by a precompute job first, and a node that cannot
                          run mjbuoy stops with what is missing
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BARGE = os.path.join(HERE, "barge.xml")
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(args, env=None, ok=(0, 1)):
    r = subprocess.run(args, capture_output=True, text=True, env=env)
    if r.returncode not in ok:
        print(r.stdout, r.stderr)
        raise SystemExit(f"FAIL {' '.join(args)}: exit {r.returncode}")
    return r


def read(path):
    with open(path, "rb") as f:
        return f.read()


def rows(out):
    import csv
    with open(os.path.join(out, "sweep.csv")) as f:
        return {r["id"]: r for r in csv.DictReader(f)}


def mode_list(bin_):
    out = run([bin_, "list", os.path.join(HERE, "expand.xml")], ok=(0,)).stdout.splitlines()
    check(len(out) == 24, f"24 cases = 4 densities x 2 zipped hulls x 3 time steps (got {len(out)})")
    # first axis slowest: index 7 = 1 * 6 + 0 * 3 + 1
    check(out[0] == "0 rho-0.hull-0.dt-0 rho=1000 damp=3000 300 visc=1 dt=0.001", "case 0: " + out[0])
    check(out[7] == "7 rho-1.hull-0.dt-1 rho=1010 damp=3000 300 visc=1 dt=0.002", "case 7: " + out[7])
    # zipped: damp and visc change together; log range 0.001 * 2^k
    check(out[23] == "23 rho-3.hull-1.dt-2 rho=1030 damp=1500 150 visc=3 dt=0.004", "case 23: " + out[23])


def mode_invalid(bin_, file):
    text = open(file).read()
    pats = [re.sub(r"\s*-->\s*$", "", p) for p in re.findall(r"expect output: (.*)", text)]
    with tempfile.TemporaryDirectory() as d:
        r = subprocess.run([bin_, "run", file, "--out", d], capture_output=True, text=True)
        check(r.returncode == 2, f"exit 2 (got {r.returncode})")
        check(not os.path.exists(os.path.join(d, "cases")), "nothing run")
    for p in pats:
        check(re.search(p, r.stdout + r.stderr, re.M) is not None, f"output matches {p!r}: {r.stderr.strip()}")


def local_run(bin_, out, jobs, env=None, ok=(1,)):
    r = run([bin_, "run", BARGE, "--out", out, "--jobs", str(jobs)], env=env, ok=ok)
    m = run([bin_, "merge", out])
    return r, m


def check_barge(out):
    """the physics of the barge sweep: draft from Archimedes, failing drops"""
    rs = rows(out)
    check(len(rs) == 6, f"6 rows (got {len(rs)})")
    for id_, r in rs.items():
        rho = float(r["density"])
        # box 2 x 1 m, 500 kg: draft m / (rho L B); centre 0.25 m above the keel
        z0 = 0.25 - 500 / (rho * 2 * 1)
        check(abs(float(r["z_mean"]) - z0) < 0.00125,
              f"{id_}: settled z {r['z_mean']} = 0.25 - m / (rho L B) = {z0:.6f} +- 1.25 mm")
        want = "fail" if r["drop"] == "0.3" else "pass"
        check(r["status"] == want, f"{id_}: dropped from {r['drop']} m: {r['status']} (expected {want})")


def mode_local(bin_):
    with tempfile.TemporaryDirectory() as d:
        o1, o2, o3, o4 = (os.path.join(d, n) for n in ("j1", "j2", "resume", "crash"))
        local_run(bin_, o1, 1)
        local_run(bin_, o2, 2)
        check_barge(o1)
        for f in ("sweep.csv", "junit.xml"):
            check(read(os.path.join(o1, f)) == read(os.path.join(o2, f)), f"{f} identical with --jobs 1 and 2")
        check(os.path.getsize(os.path.join(o1, "plots", "z_max-drop-density.png")) > 1000, "plot written")

        # another sweep's directory is refused, its results untouched
        before = read(os.path.join(o1, "sweep.json"))
        r = subprocess.run([bin_, "run", os.path.join(HERE, "expand.xml"), "--out", o1], capture_output=True, text=True)
        check(r.returncode == 2 and "holds the results of another sweep" in r.stderr, "another sweep's --out refused")
        check(read(os.path.join(o1, "sweep.json")) == before, "its manifest untouched")

        # killed after 2 cases (the runner SIGKILLs itself), then resumed
        env = dict(os.environ, MJBUOY_SWEEP_TEST_STOP_AFTER="2")
        r = subprocess.run([bin_, "run", BARGE, "--out", o3, "--jobs", "1"], env=env, capture_output=True)
        check(r.returncode == -9, f"first run killed (status {r.returncode})")
        cases = os.path.join(o3, "cases")
        first = {f: os.stat(os.path.join(cases, f)) for f in os.listdir(cases)}
        check(len(first) == 2 and all(f.endswith(".json") for f in first),
              f"2 results after the kill, no partial file: {sorted(first)}")
        r, _ = local_run(bin_, o3, 2)
        check("4 to run (2 complete)" in r.stdout, "the re-run runs the 4 missing cases: " + r.stdout.splitlines()[0])
        for f, st in first.items():
            now = os.stat(os.path.join(cases, f))
            check((now.st_ino, now.st_mtime_ns) == (st.st_ino, st.st_mtime_ns), f"{f} kept (same inode, mtime)")
        check(read(os.path.join(o1, "sweep.csv")) == read(os.path.join(o3, "sweep.csv")), "resumed sweep.csv identical")
        r = run([bin_, "run", BARGE, "--out", o3])
        check("0 to run (6 complete)" in r.stdout, "a third run has nothing to do")

        # one case's process dies (SIGKILL via the test hook): recorded, the others complete
        env = dict(os.environ, MJBUOY_SWEEP_TEST_CRASH="drop-1.density-0")
        local_run(bin_, o4, 2, env=env)
        r4, r1 = rows(o4), rows(o1)
        check(r4["drop-1.density-0"]["status"] == "crash", "the killed case is recorded as a crash")
        j = json.load(open(os.path.join(o4, "cases", "drop-1.density-0.json")))
        check(j.get("signal") == 9, f"with its signal 9: {j.get('error')}")
        check(all(r4[k] == r1[k] for k in r1 if k != "drop-1.density-0"), "the other 5 rows as in the full run")
        junit = read(os.path.join(o4, "junit.xml")).decode()
        check('type="crash"' in junit and "signal 9" in junit, "JUnit reports the crash")
        # a re-run retries the crashed case only
        r, _ = local_run(bin_, o4, 2)
        check("1 to run (5 complete)" in r.stdout, "the re-run retries the crash only")
        check(read(os.path.join(o1, "sweep.csv")) == read(os.path.join(o4, "sweep.csv")), "then identical")


def mode_slurm(bin_):
    sys.path.insert(0, HERE)
    from slurm_local import LocalSlurm
    with tempfile.TemporaryDirectory() as d:
        local, remote = os.path.join(d, "local"), os.path.join(d, "slurm")
        local_run(bin_, local, 2)
        t0 = time.time()
        with LocalSlurm(os.path.join(d, "cluster")) as env:
            print(f"slurm up in {time.time() - t0:.1f} s")
            # sbatch passes the submitter's environment on: without a cache
            # of the user's the scripts share DIR/radcache
            env = {k: v for k, v in env.items() if k != "MJBUOY_RADIATION_CACHE"}
            r = run([bin_, "slurm", BARGE, "--out", remote, "--shards", "3", "--time", "5",
                     "--mem", "200M"], env=env, ok=(0,))
            print(r.stdout.strip())
            check("Submitted batch job" in r.stdout, "sbatch accepted the array")
            script = open(os.path.join(remote, "sweep.sbatch")).read()
            check("#SBATCH --array=0-2" in script and "--shard \"${SLURM_ARRAY_TASK_ID}/3\"" in script,
                  "one array task per shard")
            done = False
            while time.time() - t0 < 90:
                q = subprocess.run(["squeue", "-h"], env=env, capture_output=True, text=True).stdout
                n = len(os.listdir(os.path.join(remote, "cases"))) if os.path.isdir(os.path.join(remote, "cases")) else 0
                if not q.strip() and n >= 6:
                    done = True
                    break
                time.sleep(0.5)
            check(done, f"array finished within 90 s ({time.time() - t0:.1f} s)")
            logs = sorted(os.listdir(os.path.join(remote, "slurm")))
            arr = [f for f in logs if re.match(r"^[0-9]+_[0-9]+\.out$", f)]
            pre = [f for f in logs if f.startswith("precompute_")]
            check(len(arr) == 3 and len(pre) == 1, f"3 array task logs and the precompute job's: {logs}")
            if pre:
                t = open(os.path.join(remote, "slurm", pre[0])).read()
                check("mjbuoy-sweep: precompute barge: 6 case(s), radiation cache " +
                      os.path.join(remote, "radcache") + ":" in t and " 0 computed" not in t,
                      f"the precompute job filled the shared cache: {t.strip()}")
        run([bin_, "merge", remote])
        for f in ("sweep.csv", "junit.xml"):
            check(read(os.path.join(local, f)) == read(os.path.join(remote, f)), f"{f} identical locally and on Slurm")


def mode_rao(bin_):
    with tempfile.TemporaryDirectory() as d:
        run([bin_, "run", os.path.join(ROOT, "examples", "rao", "rao.xml"), "--out", d, "--jobs", "2"], ok=(0,))
        run([bin_, "merge", d], ok=(0,))
        rs = rows(d)
        check(len(rs) >= 8, f"at least 8 wave periods ({len(rs)})")
        # examples/rao/column.xml: C = rho g A_wp = 9810 N/m, m = 4000 kg
        wn = math.sqrt(1000 * 9.81 * 1.0 / 4000)
        zeta = 626.4 / (2 * math.sqrt(9810 * 4000))
        for r in rs.values():
            T = float(r["period"])
            lam = float(r["wavelength"])
            check(abs(T - math.sqrt(2 * math.pi * lam / 9.81)) < 1e-9 * T,
                  f"period {T:.4f} s from deep-water dispersion lambda = g T^2 / 2 pi")
            # the wave at the body is the input sinusoid of 0.1 m (steepness 0); the
            # response's up-crossings are one wave period apart
            check(abs(float(r["eta_amp"]) - 0.1) < 1e-6, f"T = {T:5.2f} s: wave amplitude {r['eta_amp']} = 0.1 m")
            check(abs(float(r["heave_tz"]) / T - 1) < 1e-3, f"T = {T:5.2f} s: zero-crossing period {r['heave_tz']}")
            w = 2 * math.pi / T
            x = w / wn
            # m z'' + C z = F_FK with linear wave pressure (mjbuoy's default,
            # docs/physics.md section 11): on a wall-sided hull only the flat bottom,
            # at the draft d = 4 m, takes vertical pressure, whose dynamic part
            # rho g A e^(-k d) cos(theta) decays with depth (Newman 1977, section 6.3;
            # Faltinsen 1990, section 3.2): F_FK = C eta e^(-k d) in waves much longer
            # than the bottom, so RAO = e^(-k d) / |1 - (w/wn)^2|
            k = 2 * math.pi / lam
            decay = math.exp(-k * 4.0)
            undamped = decay / abs(1 - x * x)
            # the same with the joint's damping c z' and the bottom's finite length B = 1 m
            # (the pressure averaged over it: sin(k B / 2) / (k B / 2))
            kb = math.pi / lam
            damped = decay * math.sin(kb) / kb / math.sqrt((1 - x * x) ** 2 + (2 * zeta * x) ** 2)
            rao = float(r["heave_rao"])
            check(abs(rao / undamped - 1) < 0.05,
                  f"T = {T:5.2f} s: RAO {rao:.4f} vs e^(-kd)/|1-(w/wn)^2| = {undamped:.4f} "
                  f"({100 * (rao / undamped - 1):+.2f}%, within 5%)")
            check(abs(rao / damped - 1) < 0.005,
                  f"T = {T:5.2f} s: RAO {rao:.4f} vs damped, finite-length {damped:.4f} "
                  f"({100 * (rao / damped - 1):+.3f}%, within 0.5%)")
            ph = float(r["heave_phase"])
            # in phase below resonance, in antiphase above (lag atan(2 zeta x / (1 - x^2)))
            lag = math.degrees(math.atan2(2 * zeta * x, 1 - x * x))
            check(abs(-ph - lag) < 1 or abs(360 - ph - lag) < 1 if x > 1 else abs(-ph - lag) < 1,
                  f"T = {T:5.2f} s: phase {ph:.2f} deg vs -{lag:.2f} deg")
        check(os.path.getsize(os.path.join(d, "plots", "heave_rao-period.png")) > 1000, "RAO curve plotted")


def mode_sensor(bin_):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "s")
        run([bin_, "run", os.path.join(HERE, "sensors.xml"), "--out", out], ok=(0,))
        run([bin_, "merge", out], ok=(0,))
        rs = rows(out)
        check(len(rs) == 2, f"2 rows (got {len(rs)})")
        for id_, r in rs.items():
            rho = float(r["density"])
            # Archimedes: the barge (500 kg) at rest displaces m / rho and
            # its buoyancy carries the weight m g (g = 9.81)
            v, fz = float(r["volume"]), float(r["fz"])
            check(abs(v - 500 / rho) < 1e-6, f"{id_}: submerged_volume sensor {v} = m / rho = {500 / rho:.9f}")
            check(abs(fz - 4905) < 0.01, f"{id_}: wrench sensor index 2 {fz} = m g = 4905 N")
        bad = os.path.join(d, "bad")
        r = run([bin_, "run", os.path.join(HERE, "sensor_unknown.xml"), "--out", bad], ok=(1,))
        case = json.loads(read(os.path.join(bad, "cases", "case.json")))
        check(case["status"] == "invalid", f"unknown sensor: case {case['status']} (expected invalid)")
        want = r'sensor_unknown\.xml:4: <stat name="v">: no sensor "volume" in the model \(sensors: displacement,'
        check(re.search(want, case.get("error", "")) is not None, f"unknown sensor: {case.get('error')}")


def catenary_tension(X, Z, L, EA, W):
    """fairlead tension of a line with its anchor on a frictionless bed:
    Jonkman 2007 (NREL/TP-500-41958) eqs. 4-1 to 4-4 with C_B = 0 (Irvine
    1981 sec. 2.2 with an elastic line), solved by nested bisection"""
    def end(H, V):
        if V < W * L:
            x = L - V / W + H / W * math.asinh(V / H) + H * L / EA
            z = H / W * (math.sqrt(1 + (V / H) ** 2) - 1) + V * V / (2 * EA * W)
        else:
            Va = V - W * L
            x = H / W * (math.asinh(V / H) - math.asinh(Va / H)) + H * L / EA
            z = (H / W * (math.sqrt(1 + (V / H) ** 2) - math.sqrt(1 + (Va / H) ** 2))
                 + (V * L - W * L * L / 2) / EA)
        return x, z

    def v_for(H):  # the height grows with V
        lo, hi = 0.0, 4 * W * L
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if end(H, mid)[1] < Z else (lo, mid)
        return 0.5 * (lo + hi)

    lo, hi = 1e-6 * W * L, 100 * W * L  # the span grows with H
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if end(mid, v_for(mid))[0] < X else (lo, mid)
    H = math.sqrt(lo * hi)
    return math.hypot(H, v_for(H))


def mode_mooring(bin_):
    """a tiny version of examples/mooring/pretension.xml: two chain lengths,
    calm water with no current, 20 s; the buoy at rest holds line a at the
    catenary's fairlead tension for its span and height (the buoy's mean z
    gives the fairlead 2 m below it; anchor 101.5 m out, 50 m deep; chain
    30 kg/m, d 0.07 m, EA 1.2e8 N, rho 1025, g 9.81), within 1%, and the
    shorter chain pulls harder"""
    ex = os.path.join(ROOT, "examples", "mooring")
    with tempfile.TemporaryDirectory() as d:
        sw = os.path.join(d, "tiny.xml")
        open(sw, "w").write(
            '<sweep scenario="%s" name="tiny">\n'
            '  <axis name="duration" set="@duration" values="20"/>\n'
            '  <axis name="current" set="sea@current" format="0 {}" values="0"/>\n'
            '  <zip name="length">\n'
            '    <axis name="length" set="numeric[name=mjbuoy.line.a.length]@data" values="128 132"/>\n'
            '    <axis name="lb" set="numeric[name=mjbuoy.line.b.length]@data" values="128 132"/>\n'
            '    <axis name="lc" set="numeric[name=mjbuoy.line.c.length]@data" values="128 132"/>\n'
            '  </zip>\n'
            '  <stat name="tension" stat="mean" sensor="tension_a" from="12"/>\n'
            '  <stat name="z" stat="mean" body="buoy" quantity="z" from="12"/>\n'
            '  <stat name="x" stat="mean" body="buoy" quantity="x" from="12"/>\n'
            '</sweep>\n' % os.path.join(ex, "moored_current.xml"))
        out = os.path.join(d, "o")
        run([bin_, "run", sw, "--out", out, "--jobs", "2"], ok=(0,))
        run([bin_, "merge", out], ok=(0,))
        rs = rows(out)
        check(len(rs) == 2, f"2 rows (got {len(rs)})")
        W = (30 - 1025 * math.pi * 0.07 ** 2 / 4) * 9.81
        t = {}
        for r in rs.values():
            L = float(r["length"])
            X = 101.5 - 1.5 - float(r["x"])
            Z = 50 + float(r["z"]) - 2
            Tc = catenary_tension(X, Z, L, 1.2e8, W)
            T = float(r["tension"])
            t[L] = T
            check(abs(T / Tc - 1) < 0.01, f"L = {L:g} m: fairlead tension {T:.1f} N, catenary "
                  f"{Tc:.1f} N ({100 * (T / Tc - 1):+.3f}%, within 1%)")
        check(t.get(128, 0) > t.get(132, 1e30), f"the shorter chain pulls harder: {t}")


def small_sweep(d, model_xml, extra_files=()):
    """a 2-case sweep in d of a 0.5 s drop of the model text model_xml"""
    open(os.path.join(d, "model.xml"), "w").write(model_xml)
    open(os.path.join(d, "base.xml"), "w").write(
        '<scenario model="model.xml" duration="0.5">\n  <init body="barge" pos="0 0 0.3"/>\n'
        '  <check kind="finite"/>\n</scenario>\n')
    open(os.path.join(d, "s.xml"), "w").write(
        '<sweep scenario="base.xml" name="s">\n'
        '  <axis name="drop" set="init[body=barge]@pos" format="0 0 {}" values="0.25 0.3"/>\n'
        '  <stat name="z_end" stat="mean" body="barge" quantity="z" from="0.45"/>\n</sweep>\n')
    return os.path.join(d, "s.xml")


def barge_text():
    return open(os.path.join(ROOT, "models", "barge.xml")).read()


def mode_stale(bin_):
    with tempfile.TemporaryDirectory() as d:
        sw, out = small_sweep(d, barge_text()), os.path.join(d, "out")
        r = run([bin_, "run", sw, "--out", out], ok=(0,))
        check("2 to run (0 complete)" in r.stdout, "first run runs both cases")
        run([bin_, "merge", out], ok=(0,))
        z500 = {k: float(v["z_end"]) for k, v in rows(out).items()}
        # the model changes (500 -> 800 kg): merge does not publish the old results
        m = os.path.join(d, "model.xml")
        open(m, "w").write(barge_text().replace('mass="500"', 'mass="800"'))
        r = run([bin_, "merge", out], ok=(1,))
        st = {k: v["status"] for k, v in rows(out).items()}
        check(set(st.values()) == {"stale"}, f"after the model changed, merge marks both stale ({st})")
        check(all(v["z_end"] == "" for v in rows(out).values()), "and publishes no statistic of them")
        r = run([bin_, "run", sw, "--out", out], ok=(0,))
        check("2 to run (0 complete)" in r.stdout, f"the rerun runs both cases: {r.stdout.splitlines()[0]}")
        run([bin_, "merge", out], ok=(0,))
        z800 = {k: float(v["z_end"]) for k, v in rows(out).items()}
        # a 2 x 1 m waterplane: the draft is m / (rho 2 m^2), 0.25 m at 500 kg and
        # 0.4 m at 800 kg, so the centre 0.25 m above the bottom sits 0.15 m lower
        # at rest (Archimedes); after 0.5 s of a heavily damped drop the barge is
        # on its way down, heavier deeper: below the light one in both cases
        check(all(z800[k] < z500[k] for k in z500), f"the heavier barge floats lower: {z500} -> {z800}")
        r = run([bin_, "run", sw, "--out", out], ok=(0,))
        check("0 to run (2 complete)" in r.stdout, "unchanged files: nothing reruns")
        # an included file the model reads
        open(os.path.join(d, "inc.xml"), "w").write('<mujoco><option timestep="0.002"/></mujoco>')
        open(m, "w").write(barge_text().replace('<option timestep="0.002"/>', '<include file="inc.xml"/>'))
        run([bin_, "run", sw, "--out", out], ok=(0,))
        open(os.path.join(d, "inc.xml"), "w").write('<mujoco><option timestep="0.001"/></mujoco>')
        r = run([bin_, "run", sw, "--out", out], ok=(0,))
        check("2 to run (0 complete)" in r.stdout, "a changed included file reruns the cases")
        # a hull mesh: a 2 x 1 x 0.5 m box as an OBJ, then moved 1 mm
        box = ["v %g %g %g" % (x, y, z) for x in (-1, 1) for y in (-0.5, 0.5) for z in (-0.25, 0.25)]
        faces = ["f 1 3 4 2", "f 5 6 8 7", "f 1 2 6 5", "f 3 7 8 4", "f 1 5 7 3", "f 2 4 8 6"]
        os.mkdir(os.path.join(d, "meshes"))
        obj = os.path.join(d, "meshes", "box.obj")
        open(obj, "w").write("\n".join(box + faces) + "\n")
        mesh_model = barge_text().replace('<worldbody>', '<asset><mesh name="box" file="box.obj"/></asset>'
                                          '\n  <worldbody>').replace('<option', '<compiler meshdir="meshes"/>\n  <option')
        mesh_model = mesh_model.replace('type="box" size="1 0.5 0.25"', 'type="mesh" mesh="box"')
        open(m, "w").write(mesh_model)
        r = run([bin_, "run", sw, "--out", out], ok=(0,))
        check("2 to run" in r.stdout, "the mesh model runs")
        open(obj, "w").write("\n".join(box + faces).replace("0.25\n", "0.251\n") + "\n")
        r = run([bin_, "run", sw, "--out", out], ok=(0, 1))
        check("2 to run (0 complete)" in r.stdout, f"a changed mesh reruns the cases: {r.stdout.splitlines()[0]}")


def mode_inject(bin_):
    with tempfile.TemporaryDirectory() as d:
        sw = small_sweep(d, barge_text())
        out = os.path.join(d, "out")
        pwned = os.path.join(d, "PWNED")
        base = [bin_, "slurm", sw, "--out", out, "--dry-run", "--time", "5", "--mem", "1G"]
        for opt, val in (("--partition", "p\ntouch " + pwned), ("--partition", "a;touch " + pwned),
                         ("--account", "a$(touch %s)" % pwned), ("--mem", "4G\ntouch " + pwned),
                         ("--time", "5`touch %s`" % pwned), ("--sbatch", "--qos=long\ntouch " + pwned),
                         ("--sbatch", "--x y")):
            args = [a for a in base]
            if opt in ("--time", "--mem"):
                i = args.index(opt)
                del args[i:i + 2]
            r = subprocess.run(args + [opt, val], capture_output=True, text=True)
            check(r.returncode == 2 and opt in r.stderr and "expected" in r.stderr and not r.stdout,
                  f"{opt} {val!r} refused naming the option and the form: {r.returncode} {r.stderr.strip()}")
        r = subprocess.run([bin_, "slurm", sw, "--out", os.path.join(d, "a\nb"), "--dry-run", "--time", "5",
                            "--mem", "1G"], capture_output=True, text=True)
        check(r.returncode == 2 and "--out" in r.stderr, f"--out with a newline refused: {r.stderr.strip()}")
        bad = os.path.join(d, "bad.xml")
        open(bad, "w").write(open(sw).read().replace('name="s"', 'name="x&#10;touch %s"' % pwned))
        r = subprocess.run([bin_, "slurm", bad, "--out", out, "--dry-run", "--time", "5", "--mem", "1G"],
                           capture_output=True, text=True)
        check(r.returncode == 2 and "name=" in r.stderr and "letters, digits" in r.stderr,
              f"a newline in the sweep's name refused: {r.stderr.strip()}")
        # accepted values are written as given, and the script is bash that
        # parses (bash -n)
        r = run([bin_, "slurm", sw, "--out", out, "--dry-run", "--time", "1-12:00:00", "--mem", "4G",
                 "--partition", "compute,long", "--account", "proj_1", "--sbatch=--qos=long"], ok=(0,))
        for line in ("#SBATCH --time=1-12:00:00", "#SBATCH --mem=4G", "#SBATCH --partition=compute,long",
                     "#SBATCH --account=proj_1", "#SBATCH --qos=long"):
            check(line in r.stdout.splitlines(), f"the script holds {line}")
        pre, arr = r.stdout.split("# ---- then")
        for part in (pre, arr.split("\n", 1)[1]):
            p = subprocess.run(["bash", "-n"], input=part, capture_output=True, text=True)
            check(p.returncode == 0, f"bash -n accepts the script: {p.stderr.strip()}")
        check(not os.path.exists(pwned), "nothing ran")
        r = subprocess.run([bin_, "run", sw, "--out", out, "--shard", "0/2/3"], capture_output=True, text=True)
        check(r.returncode == 2 and "0/2/3" in r.stderr, f"--shard 0/2/3 refused: {r.stderr.strip()}")


def mode_fifo(bin_):
    with tempfile.TemporaryDirectory() as d:
        sw, out = small_sweep(d, barge_text()), os.path.join(d, "out")
        run([bin_, "run", sw, "--out", out], ok=(0,))
        f = os.path.join(out, "cases", "drop-1.json")
        os.remove(f)
        os.mkfifo(f)
        for cmd in (["merge", out], ["run", sw, "--out", out]):
            try:
                r = subprocess.run([bin_] + cmd, capture_output=True, text=True, timeout=30)
                check(r.returncode == 2 and "drop-1.json is a FIFO" in r.stderr,
                      f"{cmd[0]}: refused naming the FIFO: {r.returncode} {r.stderr.strip()}")
            except subprocess.TimeoutExpired:
                check(False, f"{cmd[0]} with a FIFO in cases/ finished within 30 s")
        # outputs never replace inputs: a sweep file where run writes its manifest
        o = os.path.join(d, "o")
        os.mkdir(o)
        sj = os.path.join(o, "sweep.json")
        open(sj, "w").write(open(sw).read().replace('scenario="base.xml"', 'scenario="../base.xml"'))
        before = read(sj)
        r = subprocess.run([bin_, "run", sj, "--out", o], capture_output=True, text=True)
        check(r.returncode == 2 and "same file as the sweep file" in r.stderr and read(sj) == before,
              f"run --out onto the sweep file's directory refused, the file intact: {r.stderr.strip()}")


def mode_cluster(bin_):
    with tempfile.TemporaryDirectory() as d:
        sw, out = small_sweep(d, barge_text()), os.path.join(d, "out")
        # --time and --mem from case 0's measured cost, as estimate suggests:
        # time 2 x (cases per task / jobs) x wall + 1 min, memory 1.5 x peak x jobs in 64 MiB steps
        r = run([bin_, "slurm", sw, "--out", out, "--dry-run", "--shards", "1"], ok=(0,))
        m = re.search(r"wall ([0-9.]+) s, peak RSS ([0-9.]+) MiB", r.stderr)
        check(m is not None, f"the measurement is printed: {r.stderr.strip()}")
        if m:
            wall, rss = float(m.group(1)), float(m.group(2))
            minutes = math.ceil((2 * 2 * wall + 60) / 60)
            mem = math.ceil(1.5 * rss / 64) * 64
            for line in (f"#SBATCH --time={minutes}", f"#SBATCH --mem={mem}M"):
                check(line in r.stdout.splitlines(), f"{line} from wall {wall} s and {rss} MiB")
        check(r.stdout.count("if [ -z \"${MJBUOY_RADIATION_CACHE:-}\" ]") == 2 and
              r.stdout.count("export MJBUOY_RADIATION_CACHE='%s/radcache'" % out) == 2,
              "both scripts share one radiation cache in the output directory")
        check(" precompute '%s'" % sw in r.stdout, "the first job precomputes the radiation")
        check("--jobs 0 --shard" in r.stdout, "the array's tasks run one case per allocated CPU")
        # --jobs 0: the CPUs of the allocation, not the node's
        ncpu = len(os.sched_getaffinity(0))
        r = run([bin_, "run", sw, "--out", os.path.join(d, "o1"), "--jobs", "0"], ok=(0,))
        check(f"{min(ncpu, 1000)} job(s)" in r.stdout.splitlines()[0], f"--jobs 0: {ncpu} CPU(s): {r.stdout.splitlines()[0]}")
        if shutil.which("taskset") and ncpu > 1:
            r = run(["taskset", "-c", "0", bin_, "run", sw, "--out", os.path.join(d, "o2"), "--jobs", "0"], ok=(0,))
            check(", 1 job(s)" in r.stdout.splitlines()[0], f"taskset -c 0: 1 job: {r.stdout.splitlines()[0]}")
        r = run([bin_, "run", sw, "--out", os.path.join(d, "o3"), "--jobs", "0"],
                env=dict(os.environ, SLURM_CPUS_PER_TASK="1"), ok=(0,))
        check(", 1 job(s)" in r.stdout.splitlines()[0], f"SLURM_CPUS_PER_TASK=1: 1 job: {r.stdout.splitlines()[0]}")
        # precompute attaches every case: the second run reads the cache
        env = dict(os.environ, MJBUOY_RADIATION_CACHE=os.path.join(d, "rc"))
        p1 = run([bin_, "precompute", sw], env=env, ok=(0,))
        check("2 case(s)" in p1.stdout and os.path.join(d, "rc") in p1.stdout, f"precompute: {p1.stdout.strip()}")
        # a node that cannot run mjbuoy: the script stops before running, saying what is missing
        r = run([bin_, "slurm", sw, "--out", out, "--dry-run", "--time", "5", "--mem", "1G"], ok=(0,))
        fake = os.path.join(d, "fake-sweep")
        open(fake, "w").write("#!/bin/sh\necho '%s: error while loading shared libraries: libmujoco.so.2.2.2: "
                              "cannot open shared object file' >&2\nexit 127\n" % fake)
        os.chmod(fake, 0o755)
        arr = r.stdout.split("# ---- then")[1].split("\n", 1)[1].replace(bin_, fake)
        p = subprocess.run(["bash", "-s"], input=arr, capture_output=True, text=True,
                           env=dict(os.environ, SLURM_ARRAY_TASK_ID="0"))
        check(p.returncode == 2 and "does not run on" in p.stderr and "libmujoco.so.2.2.2" in p.stderr and
              "install the runtime libraries" in p.stderr, f"a node without the libraries: {p.stderr.strip()}")


if __name__ == "__main__":
    mode, bin_ = sys.argv[1], os.path.abspath(sys.argv[2])
    {"list": lambda: mode_list(bin_), "invalid": lambda: mode_invalid(bin_, sys.argv[3]),
     "local": lambda: mode_local(bin_), "slurm": lambda: mode_slurm(bin_),
     "rao": lambda: mode_rao(bin_), "sensor": lambda: mode_sensor(bin_),
     "stale": lambda: mode_stale(bin_), "inject": lambda: mode_inject(bin_),
     "fifo": lambda: mode_fifo(bin_), "cluster": lambda: mode_cluster(bin_),
     "mooring": lambda: mode_mooring(bin_)}[mode]()
    if failures:
        print(f"FAIL {len(failures)} check(s) failed")
        sys.exit(1)
