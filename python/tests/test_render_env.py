# pictures through the offscreen renderer, and the station-keeping env
import math

import numpy as np
import pytest

import mjbuoy
from mjbuoy.envs import StationKeeping


def test_render_shows_the_barge_on_the_sea(models):
    sim = mjbuoy.Sim(str(models / "barge.xml"))
    sim.forward()
    img = sim.render(320, 240)  # the free camera frames the hull bodies
    assert img.shape == (240, 320, 3) and img.dtype == np.uint8
    # the centre is the barge, rgba 0.8 0.4 0.1 in models/barge.xml: red
    # over green over blue (lit, so not the exact values)
    r, g, b = img[100:140, 140:180].reshape(-1, 3).mean(axis=0)
    assert r > 1.5 * g > 1.5 * b
    # the sea around it is blue-green, not the barge's colour
    r, g, b = img[-10:].reshape(-1, 3).mean(axis=0)
    assert b > r and g > r
    with pytest.raises(ValueError, match="16 to 8192"):
        sim.render(8, 8)
    with pytest.raises(mjbuoy.Error, match="render"):
        sim.render(64, 64, camera="nonexistent")


def test_station_keeping_thrust_follows_newton():
    # from rest in a nearly calm sea, full surge thrust F = 400 N on the
    # 500 kg barge (radiation off: no added mass) against the simple damping
    # C_lin r_s v (docs/physics.md section 4.3: C_lin 3000 N s/m, r_s the wet
    # fraction of the hull's area, 3.5 of 7 m^2 at the 0.25 m draft):
    # x(t) = (F / c) (t - tau (1 - exp(-t / tau))), c = 1500 N s/m,
    # tau = m / c. The viscous and pressure drag only take from it (within 10 %)
    env = StationKeeping(hs=0.01, tp=4.0)
    obs, info = env.reset(seed=0)
    assert obs.shape == (6,) and "sea_seed" in info
    for _ in range(10):  # 10 x 0.05 s
        obs, reward, terminated, truncated, _ = env.step([1.0, 0.0, 0.0])
    x = obs[0]
    c, tau, t = 1500.0, 500.0 / 1500.0, 0.5
    expect = 400.0 / c * (t - tau * (1 - math.exp(-t / tau)))
    assert 0.9 * expect < x <= expect, (x, expect)
    assert reward < 0 and not terminated and not truncated
    # actions beyond [-1, 1] are clipped: 5 acts as 1
    env.reset(seed=0)
    for _ in range(10):
        obs2, *_ = env.step([5.0, 0.0, 0.0])
    assert obs2[0] == x


def test_station_keeping_pd_beats_doing_nothing():
    def pd(o):
        x, y, yaw, vx, vy, wz = o
        fx, fy = -0.8 * x - 1.5 * vx, -0.8 * y - 1.5 * vy
        c, s = math.cos(yaw), math.sin(yaw)
        return [c * fx + s * fy, -s * fx + c * fy, -1.5 * yaw - wz]

    env = StationKeeping(hs=0.5, max_steps=200)
    returns = {}
    for name, policy in (("pd", pd), ("idle", lambda o: [0.0, 0.0, 0.0])):
        obs, _ = env.reset(seed=4)
        ret, done = 0.0, False
        while not done:
            obs, r, term, trunc, _ = env.step(policy(obs))
            assert np.all(np.abs(obs[:2]) <= env.max_distance)
            assert -math.pi <= obs[2] <= math.pi
            ret += r
            done = term or trunc
        returns[name] = ret
    assert returns["pd"] > returns["idle"]
    with pytest.raises(ValueError):
        env.step([np.nan, 0, 0])
