#!/usr/bin/env python3
"""End-to-end checks of mjbuoy-sim's pictures (--render, --snapshot).

check_render.py SIM MODELS_DIR CASE, CASE one of:
  video     a 2 s clip decodes (ffprobe) to the requested size, fps and frame
            count, and the sea moves between frames on a wavy sea
  snapshot  a still of the barge: sea-coloured pixels below the horizon and
            hull-coloured pixels on the deck, in regions computed from the
            camera that mjbuoy-sim reports (no golden image); with
            --show-wet the hull side below the waterline is wet-coloured
            and the side above it is not
  errors    missing ffmpeg (PATH = an empty directory) and unwritable outputs
            give clear errors
Pictures are decoded with the ffmpeg program (raw rgb24), no Python imaging.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import camproj

failed = 0


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what))
    failed += not ok


def run(cmd, env=None):
    print("$", " ".join(cmd))
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    return p


def rgb(path, w, h, frame=None):
    """pixels of a PNG (or of frame `frame` of a video) as rows of (r,g,b)"""
    cmd = ["ffmpeg", "-v", "error", "-i", path]
    if frame is not None:
        cmd += ["-vf", "select=eq(n\\,%d)" % frame, "-vframes", "1"]
    cmd += ["-f", "rawvideo", "-pix_fmt", "rgb24", "-"]
    raw = subprocess.run(cmd, capture_output=True, check=True).stdout
    assert len(raw) >= 3 * w * h, (len(raw), w, h)
    return [[tuple(raw[3 * (y * w + x):3 * (y * w + x) + 3]) for x in range(w)] for y in range(h)]


def wavy_model(tmp, models):
    """the barge on a Gerstner sea, written next to nothing else"""
    src = open(os.path.join(models, "barge.xml")).read()
    src = src.replace('<numeric name="mjbuoy.sea.level" data="0"/>',
                      '<numeric name="mjbuoy.sea.level" data="0"/>\n'
                      '    <numeric name="mjbuoy.wave.swell" data="0.3 8 0 0 0.5"/>')
    assert "mjbuoy.wave.swell" in src
    f = os.path.join(tmp, "barge_waves.xml")
    open(f, "w").write(src)
    return f


def video(sim, models, tmp):
    w, h, fps, dur = 640, 360, 30, 2
    out = os.path.join(tmp, "clip.mp4")
    p = run([sim, wavy_model(tmp, models), "--duration", str(dur), "--render", out,
             "--width", str(w), "--height", str(h), "--fps", str(fps)])
    print(p.stdout + p.stderr)
    check(p.returncode == 0, "mjbuoy-sim --render exits 0")
    if p.returncode:
        return
    q = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                        "-show_entries", "stream=codec_name,width,height,r_frame_rate,nb_read_frames",
                        "-of", "default=noprint_wrappers=1", out],
                       capture_output=True, text=True, check=True).stdout
    print(q)
    info = dict(l.split("=", 1) for l in q.split())
    check(info.get("codec_name") == "h264", "codec h264 (%s)" % info.get("codec_name"))
    check(info.get("width") == str(w) and info.get("height") == str(h),
          "size %sx%s == %dx%d" % (info.get("width"), info.get("height"), w, h))
    check(info.get("r_frame_rate") == "%d/1" % fps, "fps %s == %d/1" % (info.get("r_frame_rate"), fps))
    check(info.get("nb_read_frames") == str(fps * dur),
          "decoded frames %s == %d" % (info.get("nb_read_frames"), fps * dur))
    # the sea moves: the lower quarter of the picture (sea in front of the
    # barge) changes between the first and the middle frame
    a, b = rgb(out, w, h, 0), rgb(out, w, h, fps * dur // 2)
    diff = [abs(a[y][x][c] - b[y][x][c]) for y in range(3 * h // 4, h) for x in range(0, w, 2)
            for c in range(3)]
    mean = sum(diff) / len(diff)
    check(mean > 2.0, "the sea moves: mean |frame 0 - frame %d| in the lower quarter = %.2f > 2"
          % (fps * dur // 2, mean))


def rotation(roll, pitch, yaw):
    """R = Rz(yaw) Ry(pitch) Rx(roll), degrees"""
    r, p, y = (math.radians(v) for v in (roll, pitch, yaw))
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def snapshot(sim, models, tmp):
    w, h, t = 640, 360, 3.0
    png = os.path.join(tmp, "barge.png")
    p = run([sim, os.path.join(models, "barge.xml"), "--duration", str(t), "--snapshot",
             "%g:%s" % (t, png), "--width", str(w), "--height", str(h)])
    print(p.stdout + p.stderr)
    check(p.returncode == 0, "mjbuoy-sim --snapshot exits 0")
    if p.returncode:
        return
    m = re.search(r"free camera: lookat (\S+) (\S+) (\S+) distance (\S+) azimuth (\S+) "
                  r"elevation (\S+) fovy (\S+) deg", p.stdout)
    pose = re.search(r"barge\s+pos\s+(\S+)\s+(\S+)\s+(\S+) m\s+roll\s+(\S+) pitch\s+(\S+) yaw\s+(\S+) deg",
                     p.stdout)
    check(bool(m and pose), "camera and barge pose reported")
    if not (m and pose):
        return
    look = [float(v) for v in m.group(1, 2, 3)]
    dist, az, el, fovy = (float(v) for v in m.group(4, 5, 6, 7))
    project, horizon = camproj.projector(look, dist, az, el, fovy, w, h)
    pos = [float(v) for v in pose.group(1, 2, 3)]
    R = rotation(*(float(v) for v in pose.group(4, 5, 6)))
    half = (1.0, 0.5, 0.25)  # models/barge.xml

    def corner(sx, sy, sz, shrink=1.0):
        c = (sx * half[0] * shrink, sy * half[1] * shrink, sz * half[2])
        return project([pos[i] + sum(R[i][k] * c[k] for k in range(3)) for i in range(3)])

    img = rgb(png, w, h)
    box = [corner(sx, sy, sz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    x0, x1 = min(p[0] for p in box), max(p[0] for p in box)
    y0, y1 = min(p[1] for p in box), max(p[1] for p in box)
    print("hull bounding box in the picture: x %.0f..%.0f, y %.0f..%.0f; horizon row %.0f"
          % (x0, x1, y0, y1, horizon))
    # deck: the top face shrunk to 70% (projected quad, point-in-convex-polygon)
    deck = [corner(sx, sy, 1, 0.7) for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]

    def inside(px, py, poly):
        s = 0
        for i in range(len(poly)):
            (ax, ay), (bx, by) = poly[i], poly[(i + 1) % len(poly)]
            c = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
            if c != 0:
                if s and (c > 0) != (s > 0):
                    return False
                s = c
        return True

    hull_px = [img[y][x] for y in range(max(0, int(y0)), min(h, int(y1) + 1))
               for x in range(max(0, int(x0)), min(w, int(x1) + 1)) if inside(x + .5, y + .5, deck)]
    orange = [p for p in hull_px if p[0] > 120 and p[0] > 1.6 * p[2] and p[0] > p[1]]
    check(len(hull_px) > 200, "deck region has %d pixels (> 200)" % len(hull_px))
    if hull_px:
        fr = len(orange) / len(hull_px)
        check(fr > 0.9, "deck pixels hull-coloured (orange): %.1f%% > 90%%" % (100 * fr))
    # sea: below the horizon, away from the hull's box (20 px margin)
    sea_px = [img[y][x] for y in range(max(0, int(math.ceil(horizon)) + 5), h, 2)
              for x in range(0, w, 2)
              if not (x0 - 20 <= x <= x1 + 20 and y0 - 20 <= y <= y1 + 20)]
    blue_green = [p for p in sea_px if p[2] > p[0] + 20 and p[1] > p[0] + 10]
    check(len(sea_px) > 1000, "sea region has %d pixels (> 1000)" % len(sea_px))
    if sea_px:
        fr = len(blue_green) / len(sea_px)
        check(fr > 0.9, "sea pixels blue-green: %.1f%% > 90%%" % (100 * fr))
    # wet part of the hull: just below the waterline, inside the hull's
    # outline, the picture is tinted by the water (bluer than the deck)
    wet = [corner(sx, -1, sz, 0.7) for sx, sz in ((-1, -0.8), (1, -0.8))]
    wx0, wx1 = int(min(p[0] for p in wet)), int(max(p[0] for p in wet))
    wy = int(sum(p[1] for p in wet) / 2)
    if 0 <= wy < h:
        strip = [img[wy][x] for x in range(max(0, wx0), min(w, wx1))]
        tinted = [p for p in strip if p[2] >= p[0] - 10]
        check(strip and len(tinted) > 0.8 * len(strip),
              "wet hull side (row %d) seen through the water: %d of %d pixels blue-tinted"
              % (wy, len(tinted), len(strip)))
    # --show-wet: the same side below the waterline (the barge floats at its
    # analytic draft, 0.25 m = half its height, so its centre is at the
    # surface) turns magenta seen through the water (blue well above green,
    # red near green); 0.15 m above the surface it stays the dry hull colour
    wpng = os.path.join(tmp, "barge_wet.png")
    p = run([sim, os.path.join(models, "barge.xml"), "--duration", str(t), "--snapshot",
             "%g:%s" % (t, wpng), "--width", str(w), "--height", str(h), "--show-wet"])
    check(p.returncode == 0, "mjbuoy-sim --show-wet exits 0")
    if p.returncode:
        return
    wimg = rgb(wpng, w, h)
    dry = [corner(sx, -1, sz, 0.7) for sx, sz in ((-1, 0.6), (1, 0.6))]
    dy = int(sum(p[1] for p in dry) / 2)
    magenta = lambda p: p[2] > p[1] + 25 and p[0] > p[1] - 15
    for name, im, row, want in (("--show-wet, wet side", wimg, wy, True),
                                ("no --show-wet, wet side", img, wy, False),
                                ("--show-wet, dry side", wimg, dy, False)):
        strip = [im[row][x] for x in range(max(0, wx0), min(w, wx1))] if 0 <= row < h else []
        n = len([p for p in strip if magenta(p)])
        ok = strip and (n > 0.8 * len(strip) if want else n < 0.05 * len(strip))
        check(ok, "%s (row %d): %d of %d pixels wet-coloured (%s)"
              % (name, row, n, len(strip), "> 80%" if want else "< 5%"))


def errors(sim, models, tmp):
    model = os.path.join(models, "barge.xml")
    empty = os.path.join(tmp, "empty")
    os.mkdir(empty)
    env = dict(os.environ, PATH=empty)
    out = os.path.join(tmp, "x.mp4")
    p = run([sim, model, "--duration", "0.1", "--render", out], env=env)
    print(p.stderr)
    check(p.returncode != 0, "no ffmpeg on PATH: exit status %d != 0" % p.returncode)
    check("ffmpeg" in p.stderr and "Debian package ffmpeg" in p.stderr,
          "no ffmpeg: the error names the program and the Debian package")
    check(not os.path.exists(out), "no ffmpeg: no output file left behind")
    bad = os.path.join(tmp, "no-such-dir", "clip.mp4")
    p = run([sim, model, "--duration", "0.1", "--render", bad])
    print(p.stderr)
    check(p.returncode != 0 and "cannot write " + bad in p.stderr,
          "unwritable --render path: clear error (exit %d)" % p.returncode)
    bad = os.path.join(tmp, "no-such-dir", "still.png")
    p = run([sim, model, "--duration", "0.1", "--snapshot", "0:" + bad])
    print(p.stderr)
    check(p.returncode != 0 and "cannot write " + bad in p.stderr,
          "unwritable --snapshot path: clear error (exit %d)" % p.returncode)
    p = run([sim, model, "--duration", "0.1", "--snapshot", "5:" + os.path.join(tmp, "a.png")])
    check(p.returncode != 0 and "after the end" in p.stderr, "snapshot after the run: clear error")


def main():
    sim, models, case = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as tmp:
        {"video": video, "snapshot": snapshot, "errors": errors}[case](sim, models, tmp)
    print("FAILED" if failed else "PASSED")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
