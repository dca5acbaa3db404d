# mooring lines through the Python module: node positions, segment
# tensions, the lines' wrench and the seabed against hand calculations
# (docs/mooring.md)
import math

import numpy as np
import pytest

import mjbuoy

# a vertical taut line of L = 100 m between two bodies of 1000 t on heave
# slides (heavy, so the line's EA / l0 stays slow against them at the
# 0.01 s step): the anchor site 100.1 m below the fairlead site, a chain
# of 100 kg/m, d 0.12 m, EA 5e8 N, 10 segments, in water of density 1000
# and 200 m depth
L, ZSPAN, MASS, DIAM, EA, NSEG, RHO, G = 100.0, 100.1, 100.0, 0.12, 5e8, 10, 1000.0, 9.81
VERTICAL = f"""
<mujoco>
  <option timestep="0.01" gravity="0 0 -{G}"/>
  <custom>
    <numeric name="mjbuoy.sea.density" data="{RHO}"/>
    <numeric name="mjbuoy.sea.depth" data="200"/>
    <numeric name="mjbuoy.linetype.chain.mass" data="{MASS}"/>
    <numeric name="mjbuoy.linetype.chain.diameter" data="{DIAM}"/>
    <numeric name="mjbuoy.linetype.chain.ea" data="{EA}"/>
    <text name="mjbuoy.line.v.type" data="chain"/>
    <numeric name="mjbuoy.line.v.length" data="{L}"/>
    <numeric name="mjbuoy.line.v.segments" data="{NSEG}"/>
    <text name="mjbuoy.line.v.anchor" data="a"/>
    <text name="mjbuoy.line.v.fairlead" data="f"/>
  </custom>
  <worldbody>
    <body name="top" pos="0 0 -5">
      <joint type="slide" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="1e6" diaginertia="1 1 1"/>
      <site name="f"/>
    </body>
    <body name="bottom" pos="0 0 {-5 - ZSPAN}">
      <joint type="slide" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="1e6" diaginertia="1 1 1"/>
      <site name="a"/>
    </body>
  </worldbody>
</mujoco>
"""

# submerged weight per length (m - rho pi d^2 / 4) g [N/m]
W = (MASS - RHO * math.pi * DIAM**2 / 4) * G


def test_vertical_line_tensions_match_hand_calculation():
    # a vertical elastic line whose tension grows by its submerged weight w
    # per length upwards: stretch = (T_a + w L / 2) L / EA = Z - L, so the
    # fairlead pulls down with T_f = EA (Z / L - 1) + w L / 2 and the anchor
    # up with T_a = EA (Z / L - 1) - w L / 2: their difference is the line's
    # submerged weight w L (Irvine 1981, Cables, sec. 2.2 with no span).
    # The lumped line holds the same ends exactly: its segment tensions step
    # by the node weight w l0 (l0 = L / N)
    sim = mjbuoy.Sim(VERTICAL)
    assert sim.line_count == 1
    sim.forward()  # the line put on its static equilibrium
    top, bottom = sim.body_id("top"), sim.body_id("bottom")
    wr = sim.line_wrench()
    assert wr.shape == (sim.nbody, 6)
    tf = EA * (ZSPAN / L - 1) + W * L / 2
    ta = EA * (ZSPAN / L - 1) - W * L / 2
    assert wr[top, 2] == pytest.approx(-tf, rel=1e-6)
    assert wr[bottom, 2] == pytest.approx(ta, rel=1e-6)
    assert wr[top, 2] + wr[bottom, 2] == pytest.approx(-W * L, rel=1e-6)
    assert np.all(np.abs(wr[:, :2]) < 1e-6 * tf)  # vertical: no horizontal pull
    t = sim.line_tensions(0)
    assert t.shape == (NSEG,)
    np.testing.assert_allclose(np.diff(t), W * L / NSEG, rtol=1e-6)
    # the segments' stretch adds up to the span: sum l0 (1 + T / EA) = Z
    assert np.sum(L / NSEG * (1 + t / EA)) == pytest.approx(ZSPAN, rel=1e-9)
    r = sim.line_nodes(0)
    assert r.shape == (NSEG + 1, 3)
    np.testing.assert_allclose(r[0], [0, 0, -5 - ZSPAN], atol=1e-9)
    np.testing.assert_allclose(r[-1], [0, 0, -5], atol=1e-9)
    # each segment's length is l0 (1 + T / EA) (Hooke)
    np.testing.assert_allclose(np.diff(r[:, 2]), L / NSEG * (1 + t / EA), rtol=1e-9)
    # mjb_seabed: level - depth
    assert sim.seabed == pytest.approx(-200)


def test_line_stays_at_rest_when_stepped():
    # started on its equilibrium with the bodies held by forces equal to the
    # line's pull and their weight, nothing moves: 1 s later the fairlead
    # tension is the hand value of the test above within 0.1%
    sim = mjbuoy.Sim(VERTICAL)
    top, bottom = sim.body_id("top"), sim.body_id("bottom")
    tf = EA * (ZSPAN / L - 1) + W * L / 2
    ta = EA * (ZSPAN / L - 1) - W * L / 2
    xf = np.zeros((sim.nbody, 6))
    xf[top, 2] = tf + 1e6 * G
    xf[bottom, 2] = -ta + 1e6 * G
    sim.xfrc_applied = xf
    sim.step(100)
    assert sim.line_wrench()[top, 2] == pytest.approx(-tf, rel=1e-3)
    assert abs(sim.qpos[0]) < 1e-3 and abs(sim.qpos[1]) < 1e-3


def test_line_queries_name_bad_input():
    sim = mjbuoy.Sim(VERTICAL)
    with pytest.raises(mjbuoy.Error, match="step"):
        sim.line_nodes(0)  # nothing stepped yet
    sim.forward()
    with pytest.raises(IndexError, match="line 3 out of range.*1 mooring line"):
        sim.line_nodes(3)
    with pytest.raises(IndexError, match="line -1"):
        sim.line_tensions(-1)
    free = mjbuoy.Sim('<mujoco><worldbody><body><freejoint/><geom type="box" size="1 1 1"/>'
                      '</body></worldbody></mujoco>')
    free.forward()
    assert free.line_count == 0
    assert free.seabed is None  # deep sea and no lines: no bed
    with pytest.raises(mjbuoy.Error, match="no mooring lines"):
        free.line_wrench()
