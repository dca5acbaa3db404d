#!/usr/bin/env python3
"""End-to-end checks of mjbuoy-view under a virtual X server.

check_view.py VIEW MODEL CASE, run inside xvfb-run (CTest does that), CASE:
  screenshot  --screenshot 2:FILE at t = 2 s: hull-coloured pixels where the
              camera projects each barge's deck centre, wet-coloured ones
              (--show-wet) on its side below the waterline, and sea-coloured
              pixels where it projects open water between and in front of
              them, the projection computed here from the camera and the
              body poses the viewer prints (no golden image)
  screenshot_gl  the same with the gl backend: its EGL context (physics
              thread) and the window's GLX context (main thread) coexist
  errors      an unwritable or malformed --screenshot and a missing X server
              give clear errors before anything is written; bad --set and
              --spectrum values get mjbuoy-sim's very message (one
              validator), and --calm --spectrum reaches the overlay's sea
  guarded     the checks every tool runs: a scene that diverges in its first
              step (barges of 1e-7 kg, tests/check_tools.py "diverge") makes
              the viewer stop with exit 1 saying MuJoCo reset it (it exited
              0); a screenshot that cannot be written (/dev/full) names
              --screenshot once (it was printed twice)
  perturb     xdotool double-clicks the east barge (selects it) and
              ctrl + right-drags it to the right (mjPERT_TRANSLATE through
              xfrc_applied); compared with a run without interaction to the
              same simulated time, the east barge has moved more than 0.2 m
              and the west barge not at all (the barges do not touch, so it
              must follow the same steps bit for bit)
  close       started --paused, keys Right x 3, BackSpace, Right x 2 leave
              the time at 2 timesteps (0.004 s); ctrl+Q closes the window:
              exit status 0, final poses printed, no sanitizer report
  actuator    a motor on each barge: Up x 3 sets the first control to 3
              twentieths of its ctrlrange, ] and Up x 12 the second to its
              range's top, as the final controls printed show
MODEL is tests/viewer/two_barges.xml: two 2 x 1 x 0.5 m barges at x = -2, 2.
Waits are generous and poll (xdotool search --sync): the machine is shared
and the test also runs under ASan.
"""
import math
import os
import queue
import re
import subprocess
import sys
import tempfile
import threading
import time
import zlib

import camproj

failed = 0
HALF = (1.0, 0.5, 0.25)  # barge half sizes, tests/viewer/two_barges.xml


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what), flush=True)
    failed += not ok


def read_png(path):
    """8-bit RGB or RGBA PNG -> (width, height, rows of (r, g, b))"""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n = int.from_bytes(data[pos:pos + 4], "big")
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, ctype = body[0:4], body[4:8], body[8], body[9]
            w, h = int.from_bytes(w, "big"), int.from_bytes(h, "big")
            assert depth == 8 and ctype in (2, 6), (depth, ctype)
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def parse(out, when):
    """camera and body poses of the viewer's --print-final lines"""
    m = re.search(r"%s camera: lookat (\S+) (\S+) (\S+) distance (\S+) azimuth (\S+) "
                  r"elevation (\S+) fovy (\S+) deg" % when, out)
    cam = [float(v) for v in m.groups()] if m else None
    t = re.search(r"%s time (\S+)" % when, out)
    bodies = {}
    for b in re.finditer(r"%s body (\S+) pos (\S+) (\S+) (\S+) quat (\S+) (\S+) (\S+) (\S+)" % when, out):
        v = [float(x) for x in b.groups()[1:]]
        bodies[b.group(1)] = (v[:3], v[3:])
    return cam, float(t.group(1)) if t else None, bodies


def projector(cam, w, h):
    """pixel (x right, y down) of a world point seen by MuJoCo's free camera"""
    look, (dist, az, el, fovy) = cam[:3], cam[3:]
    return camproj.projector(look, dist, az, el, fovy, w, h)[0]


def rotate(q, v):
    """v rotated by unit quaternion q = (w, x, y, z)"""
    w, x, y, z = q
    R = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return [sum(R[i][k] * v[k] for k in range(3)) for i in range(3)]


def deck(pose):
    pos, quat = pose
    off = rotate(quat, (0, 0, HALF[2]))
    return [pos[i] + off[i] for i in range(3)]


def patch(img, w, h, px, py, r=3):
    x0, y0 = int(px), int(py)
    return [img[y][x] for y in range(max(0, y0 - r), min(h, y0 + r + 1))
            for x in range(max(0, x0 - r), min(w, x0 + r + 1))]


def orange(p):
    return p[0] > 120 and p[0] > 1.6 * p[2] and p[0] > p[1]


def blue_green(p):
    return p[2] > p[0] + 20 and p[1] > p[0] + 10


def screenshot(view, model, tmp, backend="cpu"):
    png = os.path.join(tmp, "shot.png")
    p = subprocess.run([view, model, "--screenshot", "2:" + png, "--exit-after", "2",
                        "--print-final", "--backend", backend, "--show-wet"],
                       capture_output=True, text=True,
                       timeout=600)
    print(p.stdout + p.stderr)
    check(p.returncode == 0, "mjbuoy-view exits 0 (%d)" % p.returncode)
    check(": %s on " % backend in p.stdout, "runs the %s backend" % backend)
    cam, t, bodies = parse(p.stdout, "final")
    check(cam is not None and t is not None and set(bodies) == {"west", "east"},
          "camera, time and both barges printed")
    if failed:
        return
    check(sorted(os.listdir(tmp)) == ["shot.png"], "no temporary file left next to the screenshot")
    check(abs(t - 2) < 1e-6, "final time %.9f s == 2 s (physics holds at the screenshot)" % t)
    w, h, img = read_png(png)
    print("screenshot %dx%d" % (w, h))
    check((w, h) == (1280, 800), "screenshot is the 1280x800 window")
    project = projector(cam, w, h)
    for name in ("west", "east"):
        px, py = project(deck(bodies[name]))
        ok_in = 10 <= px < w - 10 and 10 <= py < h - 10
        check(ok_in, "%s deck centre projects into the picture at (%.0f, %.0f)" % (name, px, py))
        if ok_in:
            pix = patch(img, w, h, px, py)
            n = sum(orange(q) for q in pix)
            check(n == len(pix), "%s deck centre: %d of %d pixels hull-coloured (orange), e.g. %s"
                  % (name, n, len(pix), pix[len(pix) // 2]))
    # --show-wet: each barge floats at its draft (centre at the surface), so
    # its side facing the camera is wet 0.15 m below the centre (magenta seen
    # through the water: blue well above green, red near green) and dry
    # 0.15 m above it
    magenta = lambda c: c[2] > c[1] + 25 and c[0] > c[1] - 15
    for name in ("west", "east"):
        pos, quat = bodies[name]
        for dz, want in ((-0.15, True), (0.15, False)):
            off = rotate(quat, (0, -HALF[1], dz))
            px, py = project([pos[i] + off[i] for i in range(3)])
            pix = patch(img, w, h, px, py, 2)
            n = sum(magenta(c) for c in pix)
            check(n == len(pix) if want else n == 0,
                  "%s side %+.2f m: %d of %d pixels wet-coloured (want %s), e.g. %s"
                  % (name, dz, n, len(pix), "all" if want else "none", pix[len(pix) // 2]))
    # open water on the still water level midway between the barges (the
    # gap is 2 m wide), 1.2 m towards the camera and 3 m away from it
    for q in ((0, -1.2, 0), (0, 0, 0), (0, 3, 0)):
        px, py = project(q)
        ok_in = 130 <= py < h - 40 and 10 <= px < w - 10  # below the overlay, above the help
        check(ok_in, "sea point %s projects into the picture at (%.0f, %.0f)" % (q, px, py))
        if ok_in:
            pix = patch(img, w, h, px, py)
            n = sum(blue_green(c) for c in pix)
            check(n == len(pix), "sea point %s: %d of %d pixels sea-coloured (blue-green), e.g. %s"
                  % (q, n, len(pix), pix[len(pix) // 2]))


def errors(view, model, tmp):
    bad = os.path.join(tmp, "no-such-dir", "shot.png")
    for args, want in ((["--screenshot", "1:" + bad], "cannot write " + bad),
                       (["--screenshot", "shot.png"], "expected TIME:FILE.png"),
                       (["--screenshot", "3:" + os.path.join(tmp, "a.png"), "--exit-after", "2"],
                        "after --exit-after")):
        p = subprocess.run([view, model] + args, capture_output=True, text=True, timeout=300)
        print(p.stderr)
        check(p.returncode != 0 and want in p.stderr,
              "%s: exit %d with \"%s\"" % (" ".join(args), p.returncode, want))
    check(os.listdir(tmp) == [], "nothing written into the directory")
    # --set, --spectrum and --calm: mjbuoy-sim's validator (tools/sim/simsea.h
    # parseEdits, seaopts.h), so the same bad value gets the same message
    sim = os.path.join(os.path.dirname(view), "mjbuoy-sim")
    for args in (["--spectrum", "jonswap:hs=abc"], ["--spectrum", "nosuch:hs=1"],
                 ["--set", "mjbuoy.wave.swell"], ["--set", "mjbuoy.spectrum.x.hs=-1"]):
        pv = subprocess.run([view, model] + args, capture_output=True, text=True, timeout=300)
        ps = subprocess.run([sim, model, "--duration", "0.01"] + args, capture_output=True,
                            text=True, timeout=300)
        ev = pv.stderr.replace("mjbuoy-view: ", "").strip()
        es = ps.stderr.replace("mjbuoy-sim: ", "").strip()
        print(pv.stderr)
        check(pv.returncode != 0 and ps.returncode != 0 and ev and ev == es,
              "%s: refused with mjbuoy-sim's message" % " ".join(args))
    # a valid edit reaches the scene: the calm swell replaced by a 6-component
    # JONSWAP spectrum, every component linear (docs/mjcf.md section 8)
    args = ["--calm", "--spectrum", "jonswap:hs=0.4,tp=5,components=6", "--set",
            "mjbuoy.radiation=off", "--exit-after", "0.01"]
    p = subprocess.run([view, model] + args, capture_output=True, text=True, timeout=300)
    print(p.stdout + p.stderr)
    check(p.returncode == 0 and "sea: 6 linear wave components (JONSWAP Hs 0.4 m Tp 5 s)"
          in p.stdout and "Gerstner" not in p.stdout, "%s: the overlay's sea is the edited one"
          % " ".join(args))
    check(os.listdir(tmp) == [], "nothing written into the directory")
    p = subprocess.run([view, model], capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, DISPLAY=":99999"))
    print(p.stderr)
    check(p.returncode != 0 and "no display" in p.stderr,
          "no X server: exit %d, says there is no display" % p.returncode)


def guarded(view, model, tmp):
    # 4905 N of buoyancy on 1e-7 kg: beyond MuJoCo's bound on qacc (1e10)
    # in the first step, so MuJoCo resets the state (check_tools.py, diverge)
    light = os.path.join(tmp, "light.xml")
    open(light, "w").write(open(model).read().replace('mass="500"', 'mass="1e-7"'))
    # in tmp, so a MUJOCO_LOG.TXT that other tests leave in the build's
    # test folder cannot be taken for the viewer's
    p = subprocess.run([view, light, "--exit-after", "1"], capture_output=True, text=True,
                       timeout=300, cwd=tmp)
    print(p.stderr)
    check(p.returncode == 1 and "diverged" in p.stderr and "MuJoCo reset the state" in p.stderr,
          "a diverging scene: exit %d (want 1), says diverged and MuJoCo reset it" % p.returncode)
    check(not os.path.exists(os.path.join(tmp, "MUJOCO_LOG.TXT")),
          "MuJoCo's warnings on stderr, no MUJOCO_LOG.TXT")
    p = subprocess.run([view, model, "--screenshot", "0.1:/dev/full", "--exit-after", "0.2"],
                       capture_output=True, text=True, timeout=300, env=dict(os.environ, TMPDIR=tmp))
    print(p.stderr)
    check(p.returncode != 0 and "No space left on device" in p.stderr and
          p.stderr.count("--screenshot") == 1,
          "--screenshot to /dev/full: exit %d, names --screenshot once" % p.returncode)


class Viewer:
    """mjbuoy-view in the background, its stdout read line by line"""

    def __init__(self, cmd):
        print("$", " ".join(cmd), flush=True)
        self.p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.lines, self.q = [], queue.Queue()
        self.err = []
        threading.Thread(target=self._read, args=(self.p.stdout, self.q), daemon=True).start()
        threading.Thread(target=self._read, args=(self.p.stderr, None), daemon=True).start()

    def _read(self, f, q):
        for line in f:
            (self.lines if q else self.err).append(line)
            if q:
                q.put(line)

    def wait_for(self, pattern, timeout):
        end = time.time() + timeout
        while time.time() < end:
            try:
                line = self.q.get(timeout=0.2)
            except queue.Empty:
                if self.p.poll() is not None and self.q.empty():
                    return None
                continue
            if re.search(pattern, line):
                return line
        return None

    def finish(self, timeout=120):
        try:
            rc = self.p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.p.kill()
            rc = self.p.wait()
        time.sleep(0.5)
        out, err = "".join(self.lines), "".join(self.err)
        print(out + err, flush=True)
        return rc, out, err


def xdo(*args, timeout=120):
    p = subprocess.run(["xdotool"] + [str(a) for a in args], capture_output=True, text=True,
                       timeout=timeout)
    return p.stdout.strip()


def window():
    """the viewer's window id, polling until it is mapped"""
    ids = xdo("search", "--sync", "--onlyvisible", "--name", "^mjbuoy-view: ").split()
    return ids[0] if ids else None


def close(view_proc, win):
    xdo("windowfocus", win)
    time.sleep(0.5)
    xdo("key", "ctrl+q")


def perturb(view, model, tmp):
    v = Viewer([view, model, "--print-final"])
    start = v.wait_for(r"start camera:", 300)
    win = window()
    check(bool(start and win), "the window appears and the start camera is printed")
    if not (start and win):
        v.p.kill()
        v.finish()
        return
    cam, _, bodies = parse("".join(v.lines), "start")
    w, h = (int(x) for x in xdo("getwindowgeometry", "--shell", win).split("WIDTH=")[1]
            .replace("HEIGHT=", " ").split()[:2])
    px, py = projector(cam, w, h)(deck(bodies["east"]))
    print("east deck centre at pixel (%.0f, %.0f) of %dx%d" % (px, py, w, h), flush=True)
    selected = None
    for attempt in range(4):  # a slow frame can split a double-click; try again
        xdo("mousemove", "--window", win, int(px), int(py))
        time.sleep(0.5)
        xdo("click", "--repeat", 2, "--delay", 60, 1)
        selected = v.wait_for(r"selected body|selection cleared", 30)
        if selected and "east" in selected:
            break
    check(bool(selected and "selected body east" in selected),
          "double-click on the east barge selects it (%s)" % (selected or "").strip())
    # ctrl + right drag to the right: translate the east barge towards +x
    xdo("keydown", "ctrl")
    xdo("mousedown", 3)
    for i in range(12):
        xdo("mousemove_relative", "--", 15, 0)
        time.sleep(0.1)
    time.sleep(3)
    xdo("mouseup", 3)
    xdo("keyup", "ctrl")
    time.sleep(1)
    close(v, win)
    rc, out, err = v.finish()
    check(rc == 0, "viewer exits 0 after ctrl+Q (%d)" % rc)
    _, t, moved = parse(out, "final")
    if t is None or set(moved) != {"west", "east"}:
        check(False, "final poses printed")
        return
    # the same run without interaction to the same time
    p = subprocess.run([view, model, "--exit-after", "%.9f" % t, "--print-final"],
                       capture_output=True, text=True, timeout=900)
    print(p.stdout + p.stderr)
    _, t2, ref = parse(p.stdout, "final")
    check(p.returncode == 0 and t2 is not None and abs(t2 - t) < 1e-9,
          "reference run to t = %.6f s exits 0 at the same time (%s)" % (t, t2))
    if set(ref) != {"west", "east"}:
        check(False, "reference poses printed")
        return
    dx = [moved["east"][0][i] - ref["east"][0][i] for i in range(3)]
    de = math.hypot(dx[0], dx[1])
    dw = max(abs(moved["west"][0][i] - ref["west"][0][i]) for i in range(3))
    check(de > 0.2, "east barge moved %.3f m horizontally by the drag (> 0.2 m), x by %+.3f m"
          % (de, dx[0]))
    check(dx[0] > 0.1, "towards +x, the drag direction (%+.3f m)" % dx[0])
    check(dw < 1e-9, "west barge unaffected: max |difference| %.2g m (< 1e-9 m)" % dw)


def keys_then_close(cmd, keys, pause):
    """run the viewer cmd, press keys in its window pause s apart, close it
    with ctrl+Q (exit status 0 checked); its stdout and stderr"""
    v = Viewer(cmd)
    start = v.wait_for(r"start camera:", 300)
    win = window()
    check(bool(start and win), "the window appears")
    if win:
        xdo("windowfocus", win)
        time.sleep(1)
        for k in keys:
            xdo("key", k)
            time.sleep(pause)
        time.sleep(2)
        close(v, win)
    rc, out, err = v.finish()
    check(rc == 0, "ctrl+Q: exit status 0 (%d)" % rc)
    return out, err


def close_case(view, model, tmp):
    # started paused: Right arrow x 3, Backspace (reset), Right arrow x 2
    # leave the model exactly 2 steps of its timestep (0.002 s) from t = 0
    out, err = keys_then_close([view, model, "--print-final", "--paused"],
                               ["Right"] * 3 + ["BackSpace"] + ["Right"] * 2, 0.5)
    _, t, _ = parse(out, "final")
    check(t is not None and abs(t - 0.004) < 1e-12,
          "paused, 3 steps, reset, 2 steps: final time %s == 2 x 0.002 s" % t)
    check("final body east" in out, "final poses printed on the way out")
    check("Sanitizer" not in err and "runtime error" not in err,
          "no sanitizer report on stderr")


def actuator(view, model, tmp):
    # a motor of ctrlrange [-300, 300] N on each barge (the motorboat's
    # thrust, models/motorboat.xml): a key press steps the chosen control by
    # a twentieth of the range, 30 N, and never past it. Started paused: Up
    # x 3 on the first (east_thrust: 90 N), ] to the next, Up x 12 on it
    # (west_thrust: 360 N asked, 300 N kept), one step (Right) to use them
    src = open(model).read()
    src = src.replace('<geom name="east_hull"', '<site name="east_s"/><geom name="east_hull"')
    src = src.replace('<geom name="west_hull"', '<site name="west_s"/><geom name="west_hull"')
    motors = "".join('<motor name="%s_thrust" site="%s_s" gear="1 0 0 0 0 0" ctrllimited="true" '
                     'ctrlrange="-300 300"/>' % (b, b) for b in ("east", "west"))
    src = src.replace("</worldbody>", "</worldbody><actuator>%s</actuator>" % motors)
    boats = os.path.join(tmp, "motor_barges.xml")
    open(boats, "w").write(src)
    out, _ = keys_then_close([view, boats, "--print-final", "--paused", "--set",
                              "mjbuoy.radiation=off"],
                             ["Up"] * 3 + ["bracketright"] + ["Up"] * 12 + ["Right"], 0.3)
    ctrl = dict((m.group(1), float(m.group(2)))
                for m in re.finditer(r"final ctrl (\S+) (\S+)", out))
    check(ctrl.get("east_thrust") == 90, "Up x 3: east_thrust = 3 x 600 / 20 = 90 N (%s)"
          % ctrl.get("east_thrust"))
    check(ctrl.get("west_thrust") == 300, "] then Up x 12: west_thrust held at its range's "
          "top, 300 N (%s)" % ctrl.get("west_thrust"))


def main():
    view, model, case = sys.argv[1:4]
    if "DISPLAY" not in os.environ:
        print("FAIL no DISPLAY: run under xvfb-run")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        {"screenshot": screenshot, "perturb": perturb, "close": close_case,
         "screenshot_gl": lambda *a: screenshot(*a, backend="gl"), "errors": errors,
         "guarded": guarded, "actuator": actuator}[case](view, model, tmp)
    print("FAILED" if failed else "PASSED")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
