"""Batch throughput: worlds x steps per second of mjbuoy.Batch against a
Python loop over n mjbuoy.Sim, side by side (docs/python.md, "Benchmarks").

    PYTHONPATH=build/python python3 examples/python/batch_throughput.py --n 1 4 8 16

Each world is models/motorboat.xml (one Wigley hull of 576 triangles, cpu
backend, radiation on) with its thruster driven by random actions, one
control step = one 2 ms physics step (nstep=1, the learning-loop case) and,
with --nstep, several physics steps per call.
"""
import argparse
import os
import pathlib
import time

import numpy as np

import mjbuoy

ROOT = pathlib.Path(__file__).resolve().parents[2]


def loop_rate(model, n, steps, nstep, rng):
    sims = [mjbuoy.Sim(model) for _ in range(n)]
    acts = rng.uniform(-100, 100, size=(steps, n, 1))
    t = time.perf_counter()
    for k in range(steps):
        for i, s in enumerate(sims):
            s.ctrl[:] = acts[k, i]
            s.step(nstep)
        obs = np.stack([s.qpos for s in sims])  # the same stacked observation
    dt = time.perf_counter() - t
    assert obs.shape[0] == n
    return n * steps * nstep / dt


def batch_rate(model, n, steps, nstep, rng, threads):
    b = mjbuoy.Batch(model, n, threads=threads)
    acts = rng.uniform(-100, 100, size=(steps, n, 1))
    t = time.perf_counter()
    for k in range(steps):
        b.step(acts[k], nstep=nstep)
    dt = time.perf_counter() - t
    return n * steps * nstep / dt


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--model", default=str(ROOT / "models" / "motorboat.xml"))
    p.add_argument("--n", type=int, nargs="+", default=[1, 4, 8, 16])
    p.add_argument("--steps", type=int, default=500, help="control steps timed")
    p.add_argument("--nstep", type=int, default=1, help="physics steps per control step")
    p.add_argument("--threads", type=int, default=None, help="Batch threads (default: cores)")
    args = p.parse_args()
    rng = np.random.default_rng(0)
    print(f"cores: {os.cpu_count()}, model: {args.model}, nstep {args.nstep}")
    print(f"{'n':>4} {'Sim loop [worlds*steps/s]':>26} {'Batch [worlds*steps/s]':>23} {'ratio':>6}")
    for n in args.n:
        loop = loop_rate(args.model, n, args.steps, args.nstep, rng)
        batch = batch_rate(args.model, n, args.steps, args.nstep, rng, args.threads)
        print(f"{n:>4} {loop:>26.0f} {batch:>23.0f} {batch / loop:>6.2f}")


if __name__ == "__main__":
    main()
