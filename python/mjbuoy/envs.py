"""A Gymnasium-style station-keeping task: hold a thruster barge at a point.

StationKeeping follows the Gymnasium API (reset -> (obs, info), step ->
(obs, reward, terminated, truncated, info)) without needing gymnasium;
where gymnasium is importable it is a gymnasium.Env with Box spaces and is
registered as "mjbuoy/StationKeeping-v0".

The vessel: the 2 x 1 x 0.5 m, 500 kg box barge of models/barge.xml with
three thrusters at its centre of mass (surge and sway force along its own
axes, yaw moment), in a JONSWAP sea of significant height hs [m] and peak
period tp [s], spread about +x (cos^2s spreading, s = 10), a new random sea
(spectrum seed) each episode.

Observation (6,) float64, world frame, relative to the station (0, 0) and
heading 0:
    [x, y, yaw, vx, vy, wz]: x, y [m], yaw [rad, wrapped to (-pi, pi]],
    vx, vy [m/s], wz [rad/s]. Bounds: x, y in [-max_distance, max_distance],
    yaw in [-pi, pi], velocities unbounded.
Action (3,) float64 in [-1, 1]: surge and sway thrust as fractions of
    max_force [N] (default 400), yaw moment as a fraction of max_moment
    [N m] (default 200), in the barge's own axes. Values outside are clipped.
Reward per step: -(x^2 + y^2) - yaw^2 - 0.01 |action|^2 (m^2, rad^2).
Terminated when the barge is more than max_distance [m] (default 10) from
the station; truncated after max_steps (default 600) steps of control_dt
[s] (default 0.05 s: 25 physics steps of 2 ms), i.e. 30 s.
"""

import math

import numpy as np

from ._mjbuoy import Sim

SCENE = """
<mujoco model="station">
  <option timestep="0.002"/>
  <custom>
    <numeric name="mjbuoy.sea.density" data="1000"/>
    <text name="mjbuoy.hulls" data="hull"/>
    <!-- no panel solution: the simple damping stands for the radiated waves -->
    <text name="mjbuoy.radiation" data="off"/>
    <numeric name="mjbuoy.hull.damping" data="3000 300"/>
    <text name="mjbuoy.spectrum.sea.type" data="jonswap"/>
    <numeric name="mjbuoy.spectrum.sea.components" data="24"/>
  </custom>
  <visual><global offwidth="1280" offheight="720"/></visual>
  <worldbody>
    <light pos="0 0 10" dir="0 0 -1"/>
    <body name="barge" pos="0 0 0">
      <freejoint/>
      <geom name="hull" type="box" size="1 0.5 0.25" mass="500" rgba="0.8 0.4 0.1 1"/>
      <site name="cg" pos="0 0 0"/>
    </body>
  </worldbody>
  <actuator>
    <motor name="surge" site="cg" gear="{F} 0 0 0 0 0" ctrllimited="true" ctrlrange="-1 1"/>
    <motor name="sway" site="cg" gear="0 {F} 0 0 0 0" ctrllimited="true" ctrlrange="-1 1"/>
    <motor name="yaw" site="cg" gear="0 0 0 0 0 {M}" ctrllimited="true" ctrlrange="-1 1"/>
  </actuator>
</mujoco>
"""

try:  # gymnasium is optional
    import gymnasium as _gym
    from gymnasium import spaces as _spaces
    _Base = _gym.Env
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None
    _Base = object


def _yaw(q):
    """heading [rad] of the unit quaternion q = (w, x, y, z)"""
    w, x, y, z = q
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


class StationKeeping(_Base):
    """Hold a thruster barge at (0, 0), heading 0, in irregular seas (module docstring)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 20}

    def __init__(self, hs=0.5, tp=4.0, max_force=400.0, max_moment=200.0, control_dt=0.05,
                 max_steps=600, max_distance=10.0, backend="cpu", render_mode=None):
        self.hs, self.tp = float(hs), float(tp)
        self.max_force, self.max_moment = float(max_force), float(max_moment)
        self.max_steps, self.max_distance = int(max_steps), float(max_distance)
        self.render_mode = render_mode
        scene = SCENE.replace("{F}", repr(self.max_force)).replace("{M}", repr(self.max_moment))
        self.sim = Sim(scene, backend=backend, spectrum__sea__hs=self.hs,
                       spectrum__sea__tp=self.tp, spectrum__sea__spreading=10)
        self.frame_skip = max(1, round(control_dt / self.sim.timestep))
        self._body = self.sim.body_id("barge")
        big = np.finfo(np.float64).max
        d = self.max_distance
        self.observation_low = np.array([-d, -d, -math.pi, -big, -big, -big])
        self.observation_high = -self.observation_low
        self.action_low, self.action_high = -np.ones(3), np.ones(3)
        if _gym is not None:
            self.observation_space = _spaces.Box(self.observation_low, self.observation_high,
                                                 dtype=np.float64)
            self.action_space = _spaces.Box(self.action_low, self.action_high, dtype=np.float64)
        self._rng = np.random.default_rng()
        self._steps = 0

    def _obs(self):
        q, v = self.sim.qpos, self.sim.qvel
        return np.array([q[0], q[1], _yaw(q[3:7]), v[0], v[1], v[5]])

    def reset(self, seed=None, options=None):
        """New episode: the barge at rest on the station, a new random sea. Returns (obs, info)."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self.sim.reset()
        sea_seed = int(self._rng.integers(0, 2**31))
        self.sim.set_sea(spectra=[{"type": "jonswap", "hs": self.hs, "tp": self.tp, "n": 24,
                                   "spread": 10.0, "seed": sea_seed}])
        self._steps = 0
        self.sim.forward()
        return self._obs(), {"sea_seed": sea_seed}

    def step(self, action):
        """Apply action (3,) in [-1, 1] for control_dt seconds.

        Returns (obs, reward, terminated, truncated, info)."""
        a = np.clip(np.asarray(action, dtype=np.float64).reshape(3), -1.0, 1.0)
        if not np.all(np.isfinite(a)):
            raise ValueError(f"action {action!r} is not finite")
        # the motors' gears (max_force, max_moment) act along the barge's own axes
        self.sim.ctrl[:] = a
        self.sim.step(self.frame_skip)
        self._steps += 1
        obs = self._obs()
        dist2 = obs[0] ** 2 + obs[1] ** 2
        reward = -(dist2 + obs[2] ** 2 + 0.01 * float(a @ a))
        terminated = bool(dist2 > self.max_distance ** 2)
        truncated = self._steps >= self.max_steps
        return obs, reward, terminated, truncated, {"distance": math.sqrt(dist2)}

    def render(self):
        """An RGB frame (480, 640, 3) uint8 of the barge and the sea."""
        return self.sim.render(640, 480)

    def close(self):
        self.sim.close()


if _gym is not None:  # pragma: no cover - depends on the machine
    try:
        _gym.register(id="mjbuoy/StationKeeping-v0", entry_point="mjbuoy.envs:StationKeeping")
    except Exception:  # already registered on a reload
        pass
