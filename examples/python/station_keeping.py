"""Station keeping in irregular seas: a PD policy against a random one.

Runs a few episodes of mjbuoy.envs.StationKeeping with each policy and
plots the episode returns (matplotlib, PNG). No learning library needed.

    PYTHONPATH=build/python python3 examples/python/station_keeping.py -o returns.png
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from mjbuoy.envs import StationKeeping  # noqa: E402


def pd_policy(obs, kp=(0.8, 0.8, 1.5), kd=(1.5, 1.5, 1.0)):
    """thrust against the offset and its rate, turned into the barge's axes"""
    x, y, yaw, vx, vy, wz = obs
    fx, fy = -kp[0] * x - kd[0] * vx, -kp[1] * y - kd[1] * vy  # world frame
    c, s = np.cos(yaw), np.sin(yaw)
    return np.clip([c * fx + s * fy, -s * fx + c * fy, -kp[2] * yaw - kd[2] * wz], -1, 1)


def episode(env, policy, seed, rng):
    obs, _ = env.reset(seed=seed)
    ret, done = 0.0, False
    while not done:
        a = policy(obs) if policy else rng.uniform(-1, 1, 3)
        obs, r, terminated, truncated, _ = env.step(a)
        ret += r
        done = terminated or truncated
    return ret


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("-o", "--output", default="station_keeping.png", help="plot file (PNG)")
    p.add_argument("--episodes", type=int, default=5)
    p.add_argument("--hs", type=float, default=0.5, help="significant wave height [m]")
    args = p.parse_args()
    env = StationKeeping(hs=args.hs, max_steps=200)
    rng = np.random.default_rng(0)
    pd = [episode(env, pd_policy, s, rng) for s in range(args.episodes)]
    rnd = [episode(env, None, s, rng) for s in range(args.episodes)]
    for name, r in (("PD", pd), ("random", rnd)):
        print(f"{name:7s} mean return {np.mean(r):10.2f}  ({', '.join(f'{x:.1f}' for x in r)})")
    plt.figure(figsize=(6, 4))
    plt.plot(pd, "o-", label="PD policy")
    plt.plot(rnd, "s-", label="random policy")
    plt.xlabel("episode (sea seed)")
    plt.ylabel("episode return")
    plt.xticks(range(args.episodes))
    plt.title(f"Station keeping, JONSWAP Hs {args.hs} m, 10 s episodes")
    plt.legend()
    plt.tight_layout()
    plt.savefig(args.output, dpi=100)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
