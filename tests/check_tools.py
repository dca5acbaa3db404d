#!/usr/bin/env python3
"""Robustness of the command-line tools (issue 11, docs/robustness.md "Tools").

check_tools.py BUILD_TOOLS_DIR MODELS_DIR CASE, CASE one of:
  outputs   outputs never replace inputs or each other (also through a link),
            and a run that fails leaves earlier files of the output names
            byte-identical (items 1, 2)
  writes    write errors (/dev/full) give a non-zero exit naming the output,
            in every tool (item 3)
  diverge   a hull of 1e-7 kg diverges in its first step: mjbuoy-sim and
            mjbuoy-scenario stop with a non-zero exit naming it, write no
            output and no MUJOCO_LOG.TXT (item 10)
  options   NaN, infinite and out-of-range numbers are refused at parse time
            with the option, the value and a compact range; clear messages
            for <init body="pattern"> and a model error after loading
            (items 11, 16)
  seaset    mjbuoy-sim --set/--spectrum/--calm change the sea the model
            compiles with (--print-sea), bad entries are refused naming them
            and their range, the model file and its directory are untouched;
            --print-sea's errors name only what the user gave (no
            mjbuoy.radiation the tool set itself)
  hydro     mjbuoy-hydro's tables are consistent (A_inf symmetric, K(0)
            from B, Haskind between X3 and B33); a second run reads the
            cache and prints the same tables; --plot writes a PNG (with
            gnuplot); no radiation and a full disk are refused (issue 16)
  guard     every tool that writes refuses an output over the model, a file
            the model reads (its hull mesh), a link to the model, ./model,
            and two outputs naming one file (mjbuoy-hydro -o/--plot,
            mjbuoy-sim, mjbuoy-view --screenshot, mjbuoy-scenario --junit),
            before anything is computed; the files stay byte-identical
  loadpath  a broken OBJ (face index past the vertices) is refused naming
            the file and line by every tool that loads a model (hydro
            crashed in MuJoCo's reader, exit 139); mjbuoy-view --exit-after
            nan and inf are refused with a compact range
  messages  usage errors exit with each tool's documented invalid-input
            status (1: sim, hydro, bench, hullgen; 2: scenario, sweep,
            view), not CLI11's 105/106; a run of 0 steps is refused;
            --set NAME=nan is "not a finite number", not a "text field"
  render    (label render) a failing ffmpeg is reported with its own
            reason and a non-zero exit (not SIGPIPE), nothing is left
            behind; a video name that is not .mp4 is refused up front (12)
Every run works on copies in a temporary directory; after each run the
directory must hold no temporary files (".NAME.tmp-*").
"""
import glob
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

failed = 0


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what))
    failed += not ok


def run(cmd, cwd=None, env=None, stdout=None):
    print("$", " ".join(cmd))
    try:
        p = subprocess.run(cmd, cwd=cwd, env=env, text=True, stderr=subprocess.PIPE,
                           stdout=stdout if stdout is not None else subprocess.PIPE, timeout=60)
    except subprocess.TimeoutExpired:
        check(False, "finished within 60 s")
        return subprocess.CompletedProcess(cmd, -9, "", "(killed after 60 s)")
    if p.stderr:
        print(p.stderr.rstrip())
    return p


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def no_temps(d, what):
    left = [f for f in os.listdir(d) if ".tmp-" in f or f.startswith("mjbuoy-")]
    check(not left, "%s: no temporary files left in %s (%s)" % (what, d, left))


def refused(p, what, *words):
    """non-zero exit (not a signal) and every word in the message"""
    msg = p.stderr
    check(p.returncode > 0, "%s: exit status %d > 0" % (what, p.returncode))
    for w in words:
        check(w in msg, "%s: the message names %r" % (what, w))


def barge(tmp, models, name="barge.xml", mass=None, z=None):
    src = open(os.path.join(models, "barge.xml")).read()
    if mass is not None:
        src = src.replace('mass="500"', 'mass="%s"' % mass)
    if z is not None:
        src = src.replace('pos="0 0 0.3"', 'pos="0 0 %s"' % z)
    f = os.path.join(tmp, name)
    open(f, "w").write(src)
    return f


def outputs(tools, models, tmp):
    sim, scen = os.path.join(tools, "mjbuoy-sim"), os.path.join(tools, "mjbuoy-scenario")
    model = barge(tmp, models)
    h = digest(model)
    # item 1: --snapshot onto the model emptied it before loading
    p = run([sim, model, "--duration", "0.05", "--snapshot", "0.05:" + model], cwd=tmp)
    refused(p, "--snapshot 0.05:MODEL", "--snapshot", model, "model")
    check(digest(model) == h, "the model is byte-identical after --snapshot onto it")
    # item 2: --csv onto the model, directly and through a symbolic link
    os.symlink("barge.xml", os.path.join(tmp, "link.xml"))
    for out in (model, os.path.join(tmp, "link.xml"), "./barge.xml"):
        p = run([sim, model, "--duration", "0.05", "--csv", out], cwd=tmp)
        refused(p, "--csv %s" % out, "--csv", "model")
        check(digest(model) == h, "the model is byte-identical after --csv %s" % out)
    # --csv and --snapshot to the same file
    same = os.path.join(tmp, "same.out")
    p = run([sim, model, "--duration", "0.05", "--csv", same, "--snapshot", "0.01:" + same], cwd=tmp)
    refused(p, "--csv and --snapshot to one file", "--csv", "--snapshot", "same file")
    check(not os.path.exists(same), "nothing written to the shared name")
    # item 1: a run that fails (here: the model does not load) leaves
    # existing pictures, plots, videos and CSVs of the output names untouched
    bad = os.path.join(tmp, "bad.xml")
    open(bad, "w").write("<mujoco><worldbody><body><geom type='nonsense'/></body></worldbody></mujoco>")
    olds = {}
    for name in ("old.png", "old_plot.png", "old.mp4", "old.csv"):
        f = os.path.join(tmp, name)
        open(f, "wb").write(b"earlier result " + name.encode())
        olds[f] = digest(f)
    p = run([sim, bad, "--duration", "0.05", "--snapshot", "0.01:" + os.path.join(tmp, "old.png"),
             "--plot", os.path.join(tmp, "old_plot.png"), "--render", os.path.join(tmp, "old.mp4"),
             "--csv", os.path.join(tmp, "old.csv")], cwd=tmp)
    refused(p, "a model that does not load", "cannot load")
    for f, d in olds.items():
        check(digest(f) == d and os.path.getsize(f) > 0,
              "%s byte-identical after the failed run (not emptied)" % os.path.basename(f))
    # mjbuoy-scenario: --junit onto the scenario or its model, --print-model with two files
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="barge.xml" duration="0.05"><check kind="finite"/></scenario>')
    hs = digest(sc)
    for out, role in ((sc, "scenario"), (model, "model")):
        p = run([scen, sc, "--junit", out], cwd=tmp)
        refused(p, "--junit onto the %s" % role, "--junit", role)
        check(digest(sc) == hs and digest(model) == h,
              "scenario and model byte-identical after --junit onto the %s" % role)
    sc2 = os.path.join(tmp, "sc2.xml")
    shutil.copy(sc, sc2)
    pm = os.path.join(tmp, "pm.xml")
    p = run([scen, sc, sc2, "--print-model", pm], cwd=tmp)
    refused(p, "--print-model with two scenarios", "--print-model", "2 scenario files")
    check(not os.path.exists(pm), "--print-model with two scenarios writes nothing")
    p = run([scen, sc, "--print-model", sc], cwd=tmp)
    refused(p, "--print-model onto the scenario", "--print-model", "scenario")
    check(digest(sc) == hs, "the scenario is byte-identical after --print-model onto it")
    # the normal case still works: a CSV written and in place, the old one replaced whole
    out = os.path.join(tmp, "old.csv")
    p = run([sim, model, "--duration", "0.05", "--interval", "0.01", "--csv", out], cwd=tmp)
    check(p.returncode == 0, "--csv to a new name: exit 0")
    rows = open(out).read().splitlines()
    check(rows[0].startswith("time,barge.x") and len(rows) == 7,
          "the CSV replaced the old file: a header and 6 rows (t = 0 .. 0.05 every 0.01 s), got %d lines"
          % len(rows))
    no_temps(tmp, "outputs")


def writes(tools, models, tmp):
    if not os.path.exists("/dev/full"):
        check(False, "/dev/full exists (Linux)")
        return
    sim = os.path.join(tools, "mjbuoy-sim")
    scen = os.path.join(tools, "mjbuoy-scenario")
    model = barge(tmp, models)
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="barge.xml" duration="0.05"><check kind="finite"/></scenario>')
    env = dict(os.environ, TMPDIR=tmp)
    cases = [
        ("mjbuoy-sim --csv", [sim, model, "--duration", "0.05", "--csv", "/dev/full"]),
        ("mjbuoy-sim --plot", [sim, model, "--duration", "0.05", "--plot", "/dev/full"]),
        ("mjbuoy-scenario --junit", [scen, sc, "--junit", "/dev/full"]),
        ("mjbuoy-scenario --print-model", [scen, sc, "--print-model", "/dev/full"]),
        ("mjbuoy-bench --json", [os.path.join(tools, "mjbuoy-bench"), "--boats", "1", "--tris", "64",
                                 "--backend", "cpu", "--steps", "2", "--reps", "1",
                                 "--json", "/dev/full"]),
        ("mjbuoy-hullgen -o", [os.path.join(tools, "mjbuoy-hullgen"), "--triangles", "64",
                               "-o", "/dev/full"]),
    ]
    for what, cmd in cases:
        p = run(cmd, cwd=tmp, env=env)
        refused(p, what + " /dev/full", "/dev/full", "No space left on device")
    # stdout on a full disk
    with open("/dev/full", "w") as full:
        p = run([os.path.join(tools, "mjbuoy-hullgen"), "--triangles", "64"], cwd=tmp, stdout=full)
    refused(p, "mjbuoy-hullgen > /dev/full", "stdout")
    no_temps(tmp, "writes")


def diverge(tools, models, tmp):
    # a 2 x 1 x 0.5 m box of 1e-7 kg with its centre on the surface: half its
    # volume (0.5 m^3) under water, rho g V = 4905 N of buoyancy accelerate it
    # at 4.9e10 m/s^2, beyond MuJoCo's bound on a sane qacc (mjMAXVAL =
    # 1e10), in the first step; MuJoCo resets it
    model = barge(tmp, models, "light.xml", mass="1e-7", z="0")
    csv = os.path.join(tmp, "light.csv")
    p = run([os.path.join(tools, "mjbuoy-sim"), model, "--duration", "0.5", "--csv", csv], cwd=tmp)
    refused(p, "mjbuoy-sim on a 1e-7 kg hull", "diverged", "MuJoCo reset the state")
    check(not os.path.exists(csv), "no CSV of the reset state")
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="light.xml" duration="0.5"><check kind="finite"/></scenario>')
    p = run([os.path.join(tools, "mjbuoy-scenario"), sc], cwd=tmp)
    check(p.returncode == 1 and "diverged" in p.stdout,
          "mjbuoy-scenario on a 1e-7 kg hull: exit 1 (a check fails), report says diverged")
    check(not os.path.exists(os.path.join(tmp, "MUJOCO_LOG.TXT")),
          "no MUJOCO_LOG.TXT in the working directory (MuJoCo's warnings went to stderr)")
    no_temps(tmp, "diverge")


def options(tools, models, tmp):
    sim = os.path.join(tools, "mjbuoy-sim")
    model = barge(tmp, models)
    for opt, val in (("--duration", "nan"), ("--interval", "nan"), ("--fps", "nan"),
                     ("--ctrl", "nan"), ("--duration", "inf"), ("--width", "1e9")):
        p = run([sim, model, opt, val], cwd=tmp)
        refused(p, "mjbuoy-sim %s %s" % (opt, val), opt, val)
    p = run([sim, model, "--duration", "-1"], cwd=tmp)
    refused(p, "mjbuoy-sim --duration -1", "--duration", "-1", "[0, 1e+09]")
    check(len(p.stderr.splitlines()[0]) < 100,
          "--duration -1: the message is short (%d characters; DBL_MAX in full made it 362)"
          % len(p.stderr.splitlines()[0]))
    hullgen = os.path.join(tools, "mjbuoy-hullgen")
    obj = os.path.join(tmp, "h.obj")
    for opt, val in (("--length", "nan"), ("--beam", "inf"), ("--draft", "0"), ("--freeboard", "-1")):
        p = run([hullgen, opt, val, "-o", obj], cwd=tmp)
        refused(p, "mjbuoy-hullgen %s %s" % (opt, val), opt, val, "(0, inf)")
    check(not os.path.exists(obj), "no mesh written for refused dimensions")
    p = run([os.path.join(tools, "mjbuoy-bench"), "--boats", "0"], cwd=tmp)
    refused(p, "mjbuoy-bench --boats 0", "--boats", "[1, 100000]")
    check("h*" not in p.stderr, "mjbuoy-bench --boats 0: no internal hull pattern in the message")
    # --baseline: a missing binary is refused by name; this build against
    # itself gives one row per cell with both times, and no files left over
    bench = os.path.join(tools, "mjbuoy-bench")
    p = run([bench, "--baseline", os.path.join(tmp, "none")], cwd=tmp)
    refused(p, "mjbuoy-bench --baseline to a missing file", "--baseline", "not an executable")
    p = run([bench, "--baseline", bench, "--boats", "1", "--tris", "64", "--backend", "cpu",
             "--steps", "2", "--reps", "2"], cwd=tmp, env=dict(os.environ, TMPDIR=tmp))
    rows = [l for l in p.stdout.splitlines() if l.startswith("| cpu | swell | linear | 1 | 64 |")]
    check(p.returncode == 0 and len(rows) == 1, "mjbuoy-bench --baseline: exit 0, one row")
    if rows:
        c = [x.strip() for x in rows[0].strip().strip("|").split("|")]
        check(len(c) == 20 and all(float(x) > 0 for x in c[5:14] + c[16:]),
              "mjbuoy-bench --baseline: times and ratios positive (%s)" % c)
        check(c[14] != "" and c[14] == c[15], "the same build's Newton steps per solve on both sides")
    no_temps(tmp, "mjbuoy-bench --baseline")
    # the baseline runs each cell with this run's options: a wrapper that
    # logs its arguments sees --integration vertex
    log = os.path.join(tmp, "baseline-args")
    wrap = os.path.join(tmp, "logging-bench")
    open(wrap, "w").write("#!/bin/sh\necho \"$@\" >> %s\nexec %s \"$@\"\n"
                          % (shlex.quote(log), shlex.quote(bench)))
    os.chmod(wrap, 0o755)
    p = run([bench, "--baseline", wrap, "--boats", "1", "--tris", "64", "--backend", "cpu",
             "--sea", "jonswap", "--integration", "vertex", "--steps", "2", "--reps", "1"],
            cwd=tmp, env=dict(os.environ, TMPDIR=tmp))
    said = open(log).read() if os.path.exists(log) else ""
    check(p.returncode == 0 and "--integration vertex" in said,
          "mjbuoy-bench --baseline --integration vertex: the baseline runs in vertex mode too "
          "(its arguments: %r)" % said)
    # <init body="bar*">: patterns are not supported there (not "no free joint")
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="barge.xml" duration="0.05">\n'
                        '  <init body="bar*" pos="0 0 0.3"/>\n  <check kind="finite"/>\n</scenario>')
    p = run([os.path.join(tools, "mjbuoy-scenario"), sc], cwd=tmp)
    refused(p, "<init body=\"bar*\">", "sc.xml:2", "patterns are not supported")
    # an error after the model is loaded (more controls than actuators):
    # a message, and (sanitizer builds) no leak of model, data or attachment
    p = run([sim, model, "--duration", "0.05", "--ctrl", "1", "2"], cwd=tmp)
    refused(p, "--ctrl with 2 values for 0 actuators", "--ctrl", "0 actuator")
    check("LeakSanitizer" not in p.stderr, "no leak on the error exit (LeakSanitizer)")
    no_temps(tmp, "options")


def sea_table(p):
    """--print-sea: [(amplitude, omega, k, direction, phase, steepness)], Hs"""
    rows, hs = [], None
    for line in p.stdout.splitlines():
        if line.startswith("# Hs = "):
            hs = float(line.split("=")[2].split()[0])
        elif line and not line.startswith("#"):
            rows.append([float(x) for x in line.split()[1:]])
    return rows, hs


def seaset(tools, models, tmp):
    sim = os.path.join(tools, "mjbuoy-sim")
    model = barge(tmp, models)
    before = digest(model)
    # a JONSWAP sea (docs/mjcf.md section 8) on the calm barge. Equal-energy
    # bins: every component has A = sqrt(2 m0 / n), m0 = Hs^2 / 16 (Hs = 4
    # sqrt(m0), DNV-RP-C205 (2010) 3.5.5) less the energy outside the default
    # range 0.5 wp to 4 wp: above 4 wp a PM tail holds 1 - exp(-5/4 4^-4) =
    # 0.49% of m0 (JONSWAP's A_g = 0.66 shrinks that tail; below 0.5 wp,
    # exp(-20)), and the JONSWAP normalisation keeps m0 within 0.12%: A within
    # 0.5% of sqrt(2 m0 / n)
    def jonswap(hs, tp, extra=()):
        args = [sim, model, "--calm", "--print-sea",
                "--set", "mjbuoy.spectrum.s.type=jonswap", "--set", "mjbuoy.spectrum.s.hs=%g" % hs,
                "--set", "mjbuoy.spectrum.s.tp=%g" % tp, "--set", "mjbuoy.spectrum.s.seed=7"]
        p = run(args + list(extra), cwd=tmp)
        check(p.returncode == 0, "--set jonswap hs=%g tp=%g: exit status 0" % (hs, tp))
        return sea_table(p)
    seas = {}
    for hs, tp in ((0.5, 4), (2, 4), (2, 8)):
        rows, printed = jonswap(hs, tp)
        seas[hs, tp] = rows
        check(len(rows) == 64, "hs=%g tp=%g: 64 components (the default), got %d" % (hs, tp, len(rows)))
        a = (2 * hs * hs / 16 / 64) ** 0.5
        worst = max(abs(r[0] / a - 1) for r in rows) if rows else 1
        check(worst < 0.005, "hs=%g tp=%g: every amplitude within 0.5%% of sqrt(2 Hs^2/16 / 64) = "
              "%.6g m (worst %.3g%%)" % (hs, tp, a, 100 * worst))
        check(printed is not None and abs(printed / hs - 1) < 0.005,
              "hs=%g: printed Hs %s within 0.5%%" % (hs, printed))
    # Hs scales the amplitudes only (S is proportional to Hs^2): same
    # seed, same frequencies, amplitudes x4 exactly
    lo, hi = seas[0.5, 4], seas[2, 4]
    check(len(lo) == len(hi) and all(abs(h[0] / l[0] - 4) < 1e-8 and abs(h[1] / l[1] - 1) < 1e-8
                                     for l, h in zip(lo, hi)),
          "hs 0.5 -> 2: every amplitude x4, frequencies unchanged")
    # Tp scales the frequencies: S(w) with wp = 2 pi / Tp is a function of
    # w / wp (times Hs^2 / wp), so the equal-energy quantiles scale as 1/Tp
    # and deep-water k = w^2 / g as 1/Tp^2
    t4, t8 = seas[2, 4], seas[2, 8]
    check(len(t4) == len(t8) and all(abs(b[1] / a[1] - 0.5) < 1e-6 and
                                     abs(b[2] / a[2] - 0.25) < 1e-6 for a, b in zip(t4, t8)),
          "tp 4 -> 8: every omega x1/2, every k x1/4")
    # --spectrum is shorthand for the same entries
    p = run([sim, model, "--calm", "--print-sea", "--spectrum", "s=jonswap:hs=2,tp=4,seed=7"], cwd=tmp)
    check(sea_table(p)[0] == hi, "--spectrum s=jonswap:hs=2,tp=4,seed=7 gives the --set sea")
    # overriding an entry of a model with two spectra: models/jonswap.xml's
    # wind sea (32 components, after the swell's 8 in label order) doubles,
    # the swell stays; run in the models directory, which must not change
    jm = os.path.join(models, "jonswap.xml")
    listing, jd = sorted(os.listdir(models)), digest(jm)
    p0 = run([sim, jm, "--print-sea"], cwd=tmp)
    p1 = run([sim, jm, "--print-sea", "--set", "mjbuoy.spectrum.windsea.hs=1"], cwd=tmp)
    r0, r1 = sea_table(p0)[0], sea_table(p1)[0]
    check(len(r0) == 40 and len(r1) == 40, "models/jonswap.xml: 8 + 32 components")
    check(r0[:8] == r1[:8], "the swell is unchanged")
    check(all(abs(b[0] / a[0] - 2) < 1e-9 for a, b in zip(r0[8:], r1[8:])),
          "windsea hs 0.5 -> 1: its amplitudes x2")
    a = (2 * 1.0 / 16 / 32) ** 0.5
    check(all(abs(b[0] / a - 1) < 0.005 for b in r1[8:]),
          "windsea amplitudes within 0.5%% of sqrt(2 (1 m)^2/16 / 32) = %.6g m" % a)
    check(digest(jm) == jd and sorted(os.listdir(models)) == listing,
          "models/jonswap.xml and its directory are untouched")
    # bad names and values: refused before simulating, naming the entry and
    # (mjbuoy's own validation) the accepted range or fields
    bad = (
        (["--set", "foo.bar=1"], "foo.bar", "mjbuoy."),
        (["--set", "mjbuoy.sea.level"], "mjbuoy.sea.level", "NAME=VALUE"),
        (["--set", "mjbuoy.hull.damping=abc"], "mjbuoy.hull.damping", "abc", "<numeric>"),
        (["--set", "mjbuoy.sea.level=1", "--set", "mjbuoy.sea.level=2"], "mjbuoy.sea.level", "once"),
        (["--spectrum", "jonswap:hs=80,tp=4"], "mjbuoy.spectrum.cli.hs", "80", "<= 50"),
        (["--set", "mjbuoy.spectrum.s.type=jonswap", "--set", "mjbuoy.spectrum.s.hz=1"],
         "mjbuoy.spectrum.s.hz", "spectrum fields are"),
        (["--spectrum", "storm:hs=1,tp=4"], "storm", "pm, jonswap, table"),
        (["--spectrum", "jonswap:hs=1"], "needs hs and tp"),
        (["--set", "mjbuoy.wind.speed=-3"], "mjbuoy.wind.speed", "-3", "<= 100"),
        (["--set", "mjbuoy.sea.integration=fast"], "mjbuoy.sea.integration", "fast", "exact",
         "vertex"),
    )
    for args, *words in bad:
        p = run([sim, model, "--print-sea"] + args, cwd=tmp)
        refused(p, " ".join(args), *words)
        check(not p.stdout, "%s: nothing printed" % " ".join(args))
        # --print-sea attaches without radiation (mjb_attachWithoutRadiation),
        # so an error names only what the user gave, never a radiation setting
        check("mjbuoy.radiation" not in p.stderr,
              "%s: the message does not mention mjbuoy.radiation" % " ".join(args))
    check(digest(model) == before, "the model file is unchanged")
    check(sorted(os.listdir(tmp)) == ["barge.xml"], "no other file in its directory")
    seaset_model_errors(sim, models, tmp)


def seaset_model_errors(sim, models, tmp):
    """--print-sea of a model whose own file is wrong: the error names the
    file's entry, and no option the user did not give"""
    src = open(os.path.join(models, "barge.xml")).read()
    hulls = '<text name="mjbuoy.hulls" data="barge_hull"/>'
    cases = (
        # a hull entry out of its range, no option given
        ("baddamp.xml", src.replace('data="3000 300"', 'data="-3000 300"'),
         ("mjbuoy.hull.damping", "-3000", ">= 0")),
        # the radiation switch given as a number: the file's own fault
        ("radnum.xml", src.replace(hulls, hulls + '<numeric name="mjbuoy.radiation" data="0"/>'),
         ("radnum.xml", "mjbuoy.radiation")),
    )
    for name, text, words in cases:
        f = os.path.join(tmp, name)
        with open(f, "w") as fh:
            fh.write(text)
        p = run([sim, f, "--print-sea"], cwd=tmp)
        refused(p, name + " --print-sea", *words)
        check("--set" not in p.stderr, "%s --print-sea: no --set blamed, none was given (%s)"
              % (name, p.stderr.strip()))
        if name != "radnum.xml":
            check("mjbuoy.radiation" not in p.stderr,
                  "%s --print-sea: the message does not mention mjbuoy.radiation" % name)
        os.remove(f)


def render(tools, models, tmp):
    sim = os.path.join(tools, "mjbuoy-sim")
    model = barge(tmp, models)
    # a failing ffmpeg: it exits at once, so the frames meet a closed pipe
    fake = os.path.join(tmp, "fakebin")
    os.mkdir(fake)
    with open(os.path.join(fake, "ffmpeg"), "w") as f:
        f.write("#!/bin/sh\necho 'Error: cannot encode (fake ffmpeg for the test)' >&2\nexit 1\n")
    os.chmod(os.path.join(fake, "ffmpeg"), 0o755)
    logs = os.path.join(tmp, "tmpdir")
    os.mkdir(logs)
    old = os.path.join(tmp, "clip.mp4")
    open(old, "wb").write(b"an earlier clip")
    h = digest(old)
    env = dict(os.environ, PATH=fake + os.pathsep + os.environ.get("PATH", ""), TMPDIR=logs)
    p = run([sim, model, "--duration", "0.2", "--render", old, "--width", "64", "--height", "48",
             "--progress", "off"], cwd=tmp, env=env)
    refused(p, "a failing ffmpeg", "ffmpeg failed", "cannot encode (fake ffmpeg for the test)")
    check(p.returncode != 141 and p.returncode >= 0, "not killed by SIGPIPE (%d)" % p.returncode)
    check(digest(old) == h, "the earlier clip.mp4 is byte-identical")
    check(not os.listdir(logs), "no ffmpeg log left in $TMPDIR (%s)" % os.listdir(logs))
    # names ffmpeg cannot or should not write H.264 MP4 to: refused before the run
    for name in ("video", "clip.gif"):
        out = os.path.join(tmp, name)
        p = run([sim, model, "--duration", "0.2", "--render", out], cwd=tmp)
        refused(p, "--render %s" % name, "--render", ".mp4")
        check(not os.path.exists(out), "--render %s: nothing written" % name)
    # the real ffmpeg on a full disk
    p = run([sim, model, "--duration", "0.1", "--render", "/dev/full", "--width", "64",
             "--height", "48", "--progress", "off"], cwd=tmp, env=dict(os.environ, TMPDIR=logs))
    refused(p, "--render /dev/full", "/dev/full", "No space left on device")
    check(not os.listdir(logs), "no temporary video or log left in $TMPDIR (%s)" % os.listdir(logs))
    no_temps(tmp, "render")


def hydro(tools, models, tmp):
    """mjbuoy-hydro on a floating box with radiation on: its tables are
    consistent (A_inf symmetric; K(0) = (2/pi) int_0^inf B dw, with B linear
    between the printed frequencies and from 0 at w = 0: the trapezoid rule
    is exact, plus the printed tail's B_N w_N / (p - 1), docs/physics.md
    section 14; the Haskind relation between the
    heave exciting force and B33); a model without radiation and a full disk
    are refused by name"""
    exe = os.path.join(tools, "mjbuoy-hydro")
    box = os.path.join(tmp, "box.xml")
    xml = ('<mujoco><custom><text name="mjbuoy.hulls" data="hull"/>%s'
           '<numeric name="mjbuoy.radiation.omega" data="1 9 6"/></custom><worldbody>'
           '<body name="boat"><freejoint/><geom name="hull" type="box" size="0.5 0.5 0.5" '
           'mass="500"/></body></worldbody></mujoco>')
    open(box, "w").write(xml % '<text name="mjbuoy.radiation" data="on"/>')
    out = os.path.join(tmp, "box.txt")
    p = run([exe, box, "--kt-step", "0.1", "-o", out], cwd=tmp)
    check(p.returncode == 0, "mjbuoy-hydro box.xml: exit 0")
    lines = open(out).read().split("\n") if os.path.exists(out) else []
    check(any('body "boat"' in l for l in lines), "the table names body boat")
    blocks, cur = [], []
    for l in lines:
        if l.startswith("#") or not l.strip():
            if cur:
                blocks.append(cur)
            cur = []
        else:
            cur.append([float(x) for x in l.split()])
    if cur:
        blocks.append(cur)
    check(len(blocks) == 4, "four tables: A_inf, A and B, K(t), X (%d)" % len(blocks))
    if len(blocks) == 4:
        a, ab, k, x = blocks
        big = max(abs(x) for r in a for x in r)
        check(all(abs(a[i][j] - a[j][i]) <= 1e-5 * big for i in range(6) for j in range(6)),
              "A_inf symmetric")
        check(a[2][2] > 0, "heave A_inf > 0 (%g kg)" % a[2][2])
        w = [0.0] + [r[0] for r in ab]
        b = [0.0] + [r[9] for r in ab]
        k0 = 2 / 3.141592653589793 * sum(0.5 * (b[i] + b[i + 1]) * (w[i + 1] - w[i])
                                          for i in range(len(w) - 1))
        # the tail beyond w_N, B_N (w_N / w)^p: (2/pi) B_N w_N / (p - 1)
        # (docs/physics.md section 14, "High-frequency tail")
        tl = [l for l in lines if l.startswith("# tail beyond")]
        check(len(tl) == 1, "the tail's exponents are printed")
        if tl:
            p = float(tl[0].split(":")[-1].split()[2])
            if p > 0:
                k0 += 2 / 3.141592653589793 * b[-1] * w[-1] / (p - 1)
        check(abs(k[0][3] - k0) <= 1e-4 * abs(k0), "heave K(0) %g = (2/pi) int B dw %g" % (k[0][3], k0))
        check(abs(k[1][0] - 0.1) < 1e-9, "K(t) at the --kt-step")
        # Haskind, deep water (Newman 1962, J. Ship Res. 6(3):10-17;
        # docs/physics.md section 15): B33 = omega k / (4 pi rho g^2)
        # int_0^2pi |X3|^2 dbeta, X3 from the diffraction solves and B33
        # from the radiation solve, within 2%; the trapezoid rule over the
        # uniform headings (exact for a trigonometric polynomial) at the
        # frequencies with kR <= 0.5 (R = sqrt(A_wp / pi)): omega 1 and 2.6
        # rad/s. This coarse box (4 x 4 squares a face) is 4.6% off at kR =
        # 1 with the lid, 2.7% without (docs/physics.md section 15)
        pi = 3.141592653589793
        head = [l for l in lines if l.startswith("# body")]
        rho = float(head[0].split("rho ")[1].split()[0]) if head else 1000.0
        g = float(head[0].split(" g ")[1].split()[0]) if head else 9.81
        rwp = (1.0 / pi) ** 0.5
        n = 0
        for r in ab:
            w = r[0]
            kk = w * w / g
            rows = [q for q in x if abs(q[0] - w) < 1e-9]
            if kk * rwp > 0.5 or not rows:
                continue
            n += 1
            hask = w * kk / (4 * pi * rho * g * g) * sum(q[4] ** 2 for q in rows) * 2 * pi / len(rows)
            check(abs(hask / r[9] - 1) <= 0.02, "Haskind heave at omega %g: B33 %g, from X3 %g" %
                  (w, r[9], hask))
        check(n == 2, "Haskind checked at 2 frequencies (%d)" % n)
        # the roll stiffness it prints: the 1 m cube of 500 kg floats at
        # draft 0.5 m with its COM at the waterline, C44 = rho g V GM =
        # rho g (B^4 / 12 + B^2 T (T / 2 - KG)) = -408.75 N m/rad (GM < 0;
        # K. J. Rawson and E. C. Tupper, "Basic Ship Theory", ch. 4), so it
        # gets no rollzeta share: B_1 0 (docs/physics.md section 14)
        rl = [l for l in lines if l.startswith("# roll about")]
        check(len(rl) == 1, "the roll stiffness and damping are printed")
        if rl:
            c44 = float(rl[0].split("C44 ")[1].split()[0])
            b1 = float(rl[0].split("B_1 ")[1].split()[0])
            want = rho * g * (1.0 / 12 + 0.5 * (0.25 - 0.5))
            check(abs(c44 - want) <= 0.01 * abs(want), "C44 %g N m/rad = rho g V GM %g" % (c44, want))
            check(b1 == 0, "no roll damping without roll restoring (B_1 %g)" % b1)
        check(len(x) == 6 * 36, "X at 6 frequencies x 36 headings (%d rows)" % len(x))
    # the cache (docs/mjcf.md section 11): a first run in an empty cache
    # directory solves and writes, a second reads and prints the same tables
    env = dict(os.environ, MJBUOY_RADIATION_CACHE=os.path.join(tmp, "radcache"))
    p1 = run([exe, box], cwd=tmp, env=env)
    p2 = run([exe, box], cwd=tmp, env=env)
    check("0 body(ies) read, 1 computed, 1 written" in p1.stderr, "first run solves and caches")
    check("1 body(ies) read, 0 computed, 0 written" in p2.stderr, "second run reads the cache")
    check(p1.returncode == 0 and p1.stdout == p2.stdout, "cached tables equal the computed ones")
    if shutil.which("gnuplot"):
        png = os.path.join(tmp, "hydro.png")
        p = run([exe, box, "--plot", png], cwd=tmp, env=env)
        check(p.returncode == 0 and os.path.exists(png) and
              open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n", "--plot writes a PNG")
    # coefficient files (docs/interchange.md): written in the three formats
    # and read back through mjbuoy.radiation.file.<body>, the Capytaine file
    # bit for bit, so the printed tables are the same; --convert refuses to
    # write over its input
    files = [os.path.join(tmp, f) for f in ("box.1", "box.nc", "box.h5")]
    p = run([exe, box] + sum([["--write", f] for f in files], []), cwd=tmp, env=env)
    check(p.returncode == 0 and all(os.path.exists(f) for f in files + [os.path.join(tmp, "box.3")]),
          "--write box.1 box.nc box.h5")
    imp = os.path.join(tmp, "boximp.xml")
    open(imp, "w").write(xml % ('<text name="mjbuoy.radiation" data="on"/>'
                                '<text name="mjbuoy.radiation.file.boat" data="%s"/>' % files[1]))
    p3 = run([exe, imp], cwd=tmp, env=env)
    check(p3.returncode == 0 and p3.stdout == p2.stdout,
          "tables from the Capytaine file equal the panel solver's")
    conv = os.path.join(tmp, "conv.h5")
    p = run([exe, "--convert", files[0], "--write", conv], cwd=tmp)
    check(p.returncode == 0 and os.path.exists(conv), "--convert box.1 --write conv.h5")
    p = run([exe, "--convert", files[1], "--write", files[1]], cwd=tmp)
    refused(p, "--convert onto its input", "refusing to overwrite an input")
    # radiation is on by default for a free body: off explicitly
    open(box, "w").write(xml % '<text name="mjbuoy.radiation" data="off"/>')
    p = run([exe, box], cwd=tmp)
    refused(p, "mjbuoy-hydro on a model without radiation", "mjbuoy.radiation")
    open(box, "w").write(xml % '<text name="mjbuoy.radiation" data="on"/>')
    p = run([exe, box, "-o", "/dev/full"], cwd=tmp)
    refused(p, "mjbuoy-hydro -o /dev/full", "/dev/full", "No space left on device")
    no_temps(tmp, "hydro")


def wigley(tmp, models, mesh="wigley_576.obj"):
    """models/wigley.xml and its hull mesh copied into tmp (meshdir meshes)"""
    os.makedirs(os.path.join(tmp, "meshes"), exist_ok=True)
    shutil.copy(os.path.join(models, "meshes", "wigley_576.obj"), os.path.join(tmp, "meshes", mesh))
    src = open(os.path.join(models, "wigley.xml")).read().replace("wigley_576.obj", mesh)
    f = os.path.join(tmp, "wigley.xml")
    open(f, "w").write(src)
    return f, os.path.join(tmp, "meshes", mesh)


def guard(tools, models, tmp):
    exe = lambda n: os.path.join(tools, n)
    model, mesh = wigley(tmp, models)
    os.symlink("wigley.xml", os.path.join(tmp, "link.xml"))
    h = (digest(model), digest(mesh))
    env = dict(os.environ, MJBUOY_RADIATION_CACHE=os.path.join(tmp, "rc"))
    for out, role in ((model, "model"), (os.path.join(tmp, "link.xml"), "model"),
                      ("./wigley.xml", "model"), (mesh, "wigley_576.obj"),
                      ("meshes/wigley_576.obj", "wigley_576.obj")):
        for opt in ("-o", "--plot"):
            p = run([exe("mjbuoy-hydro"), model, opt, out], cwd=tmp, env=env)
            refused(p, "mjbuoy-hydro %s %s" % (opt, out), opt, role, "refusing to overwrite")
            check((digest(model), digest(mesh)) == h, "model and mesh intact after hydro %s %s" % (opt, out))
        p = run([exe("mjbuoy-sim"), model, "--duration", "0.01", "--csv", out], cwd=tmp)
        refused(p, "mjbuoy-sim --csv %s" % out, "--csv", role, "refusing to overwrite")
        p = run([exe("mjbuoy-view"), model, "--screenshot", "1:" + out], cwd=tmp)
        refused(p, "mjbuoy-view --screenshot 1:%s" % out, "--screenshot", role, "refusing to overwrite")
        check((digest(model), digest(mesh)) == h, "model and mesh intact after sim and view onto %s" % out)
    p = run([exe("mjbuoy-hydro"), model, "-o", "same.txt", "--plot", "same.txt"], cwd=tmp, env=env)
    refused(p, "mjbuoy-hydro -o and --plot to one file", "-o", "--plot", "same file")
    check(not os.path.exists(os.path.join(tmp, "same.txt")), "nothing written to the shared name")
    check(not os.path.exists(os.path.join(tmp, "rc")), "refused before anything is computed (no cache)")
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="wigley.xml" duration="0.01"><check kind="finite"/></scenario>')
    p = run([exe("mjbuoy-scenario"), sc, "--junit", mesh], cwd=tmp)
    refused(p, "mjbuoy-scenario --junit onto the model's mesh", "--junit", "wigley_576.obj")
    check((digest(model), digest(mesh)) == h, "model and mesh byte-identical at the end")
    no_temps(tmp, "guard")


def loadpath(tools, models, tmp):
    exe = lambda n: os.path.join(tools, n)
    model, mesh = wigley(tmp, models, "bad.obj")
    lines = open(mesh).read().splitlines()
    nv = sum(1 for l in lines if l.startswith("v "))
    i = next(k for k, l in enumerate(lines) if l.startswith("f "))
    lines[i] = "f 1 2 %d" % (nv + 1000)  # past the last vertex
    open(mesh, "w").write("\n".join(lines) + "\n")
    env = dict(os.environ, MJBUOY_RADIATION_CACHE=os.path.join(tmp, "rc"))
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="wigley.xml" duration="0.01"><check kind="finite"/></scenario>')
    for cmd in ([exe("mjbuoy-hydro"), model], [exe("mjbuoy-sim"), model, "--duration", "0.01"],
                [exe("mjbuoy-view"), model, "--exit-after", "0"], [exe("mjbuoy-scenario"), sc]):
        p = run(cmd, cwd=tmp, env=env)
        refused(p, os.path.basename(cmd[0]) + " on a broken OBJ", "bad.obj", "line %d" % (i + 1),
                "out of range")
    check(not os.path.exists(os.path.join(tmp, "rc")), "hydro cached nothing of the broken hull")
    for v in ("nan", "inf", "-1"):
        p = run([exe("mjbuoy-view"), model, "--exit-after", v], cwd=tmp)
        refused(p, "mjbuoy-view --exit-after " + v, "--exit-after", v, "[0, 1e+09]")
        check(len(p.stderr.splitlines()[0]) < 100 if p.stderr else False,
              "--exit-after %s: the message is short (CLI11's range printed DBL_MAX in 300 digits)" % v)


def messages(tools, models, tmp):
    exe = lambda n: os.path.join(tools, n)
    model = barge(tmp, models)
    # each tool's documented status for invalid input (docs/robustness.md,
    # "Exit status"): a refused value and an unknown option alike
    for tool, args, status in (("mjbuoy-sim", [model, "--duration", "nan"], 1),
                               ("mjbuoy-sim", [], 1),
                               ("mjbuoy-hydro", [model, "--kt-step", "nan"], 1),
                               ("mjbuoy-bench", ["--boats", "0"], 1),
                               ("mjbuoy-hullgen", ["--length", "nan"], 1),
                               ("mjbuoy-scenario", ["--bogus"], 2),
                               ("mjbuoy-sweep", ["run", "x.xml", "--out", "o", "--jobs", "-1"], 2),
                               ("mjbuoy-view", [model, "--width", "nan"], 2)):
        p = run([exe(tool)] + args, cwd=tmp)
        check(p.returncode == status, "%s %s: exit %d (got %d)" % (tool, " ".join(args), status,
                                                                 p.returncode))
    for tool in ("mjbuoy-sim", "mjbuoy-sweep", "mjbuoy-scenario"):
        p = run([exe(tool), "--help"], cwd=tmp)
        check(p.returncode == 0, "%s --help: exit 0" % tool)
    # 0 steps: a duration under half a 2 ms step rounds to none (guard.h stepsFor)
    for d in ("0", "1e-9"):
        p = run([exe("mjbuoy-sim"), model, "--duration", d], cwd=tmp)
        refused(p, "mjbuoy-sim --duration %s" % d, "0 steps", "time step")
    sc = os.path.join(tmp, "sc.xml")
    open(sc, "w").write('<scenario model="barge.xml" duration="1e-9"><check kind="finite"/></scenario>')
    p = run([exe("mjbuoy-scenario"), sc], cwd=tmp)
    refused(p, "a scenario of duration 1e-9 s", "0 steps")
    # more steps than a double counts exactly (guard.h kMaxSteps): refused
    # with the bound, not cast to an undefined long
    fine = os.path.join(tmp, "fine.xml")
    open(fine, "w").write(open(model).read().replace('timestep="0.002"', 'timestep="1e-9"'))
    p = run([exe("mjbuoy-sim"), fine, "--duration", "1e9"], cwd=tmp)
    refused(p, "mjbuoy-sim --duration 1e9 at a 1e-9 s step", "1e+15 steps", "shorter duration")
    open(sc, "w").write('<scenario model="barge.xml" duration="1e300"><check kind="finite"/></scenario>')
    p = run([exe("mjbuoy-scenario"), sc], cwd=tmp)
    refused(p, "a scenario of duration 1e300 s", "1e+15 steps")
    for v in ("nan", "inf", "1 nan"):
        p = run([exe("mjbuoy-sim"), model, "--print-sea", "--set", "mjbuoy.wind.speed=" + v], cwd=tmp)
        refused(p, "--set mjbuoy.wind.speed=" + v, "mjbuoy.wind.speed", "finite")
        check("text" not in p.stderr, "--set mjbuoy.wind.speed=%s: not called a text entry" % v)


def benchscene(tools, models, tmp):
    """mjbuoy-bench --scene: a model's own scene timed as it is; its row's
    fields against the model (one hull, its timestep) and the definitions
    (the step holds mjbuoy's callback; real-time factor = simulated s per
    wall s = timestep / step time); the panel solve announced on stderr
    exactly when the model has radiation; a baseline without --scene named"""
    bench = os.path.join(tools, "mjbuoy-bench")
    src = open(os.path.join(models, "barge.xml")).read()
    dt = float(re.search(r'timestep="([^"]+)"', src).group(1)) if "timestep=" in src else 0.002
    for rad in ("on", "off"):
        model = os.path.join(tmp, "barge_%s.xml" % rad)
        open(model, "w").write(src.replace("<custom>", '<custom><text name="mjbuoy.radiation" '
                                           'data="%s"/>' % rad, 1))
        js = os.path.join(tmp, "scene_%s.json" % rad)
        p = run([bench, "--scene", model, "--steps", "50", "--reps", "1", "--json", js], cwd=tmp)
        check(p.returncode == 0 and "real-time factor" in p.stdout, "--scene (radiation %s): "
              "exit 0 and a table with the real-time factor" % rad)
        if p.returncode != 0:
            continue
        row = json.load(open(js))[0]
        check(row["hulls"] == 1 and abs(row["timestep_s"] - dt) < 1e-12,
              "one hull and the model's timestep %g s (got %s)" % (dt, row))
        check(0 < row["hydro_ms"] <= row["step_ms"], "hydro time within the step's")
        check(abs(row["rtf"] - row["timestep_s"] * 1e3 / row["step_ms"]) <= 1e-4 * row["rtf"],
              "real-time factor = timestep / step time")
        said = "radiation is on" in p.stderr
        check(said == (rad == "on"), "the panel solve announced on stderr: %s (radiation %s)"
              % (said, rad))
    fake = os.path.join(tmp, "old-bench")
    open(fake, "w").write("#!/bin/sh\necho 'The following arguments were not expected: "
                          "--scene' >&2\nexit 109\n")
    os.chmod(fake, 0o755)
    p = run([bench, "--scene", model, "--steps", "5", "--reps", "1", "--baseline", fake], cwd=tmp)
    refused(p, "--scene with a baseline lacking it", "has no --scene", "both builds")


def main():
    tools, models, case = sys.argv[1:4]
    tools, models = os.path.abspath(tools), os.path.abspath(models)
    with tempfile.TemporaryDirectory() as tmp:
        globals()[case](tools, models, tmp)
    print("%d check(s) failed" % failed if failed else "all checks passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
