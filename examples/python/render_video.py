"""Render the demo scene into an MP4 through ffmpeg, notebook style.

    PYTHONPATH=build/python python3 examples/python/render_video.py -o demo.mp4

Loads models/jonswap.xml (the fleet on an irregular sea), renders a frame
every 1/fps seconds of simulated time from its "overview" camera, and pipes
the raw RGB frames to the ffmpeg program (Debian's ffmpeg), which writes
H.264 into the MP4. A frame is also a numpy array: frames[-1] is (h, w, 3).
"""
import argparse
import os
import pathlib
import subprocess

import mjbuoy

ROOT = pathlib.Path(__file__).resolve().parents[2]

p = argparse.ArgumentParser(description="render the demo scene to an MP4")
p.add_argument("-o", "--output", default="demo.mp4", help="the MP4 to write")
p.add_argument("--model", default=str(ROOT / "models" / "jonswap.xml"))
p.add_argument("--duration", type=float, default=4.0, help="simulated seconds")
p.add_argument("--fps", type=int, default=20)
p.add_argument("--size", default="640x360", help="WIDTHxHEIGHT in pixels")
p.add_argument("--camera", default="overview", help="model camera; '' follows the hulls")
args = p.parse_args()
w, h = (int(v) for v in args.size.split("x"))

sim = mjbuoy.Sim(args.model)
steps = max(1, round(1 / (args.fps * sim.timestep)))
tmp = args.output + ".part.mp4"  # written whole, then renamed: no half-written video
ff = subprocess.Popen(["ffmpeg", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
                       "-s", f"{w}x{h}", "-r", str(args.fps), "-i", "-", "-c:v", "libx264",
                       "-pix_fmt", "yuv420p", "-f", "mp4", tmp], stdin=subprocess.PIPE)
nframes = round(args.duration * args.fps)
for i in range(nframes):
    frame = sim.render(w, h, camera=args.camera)  # (h, w, 3) uint8, top row first
    ff.stdin.write(frame.tobytes())
    sim.step(steps)
ff.stdin.close()
if ff.wait() != 0:
    raise SystemExit("ffmpeg failed; is Debian's ffmpeg installed?")
os.replace(tmp, args.output)
print(f"wrote {args.output}: {nframes} frames of {w}x{h} at {args.fps} fps")
