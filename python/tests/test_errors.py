# bad input raises a Python exception naming the problem; nothing crashes
import numpy as np
import pytest

import mjbuoy


def test_version_is_the_library_version():
    major, minor, patch = (int(x) for x in mjbuoy.__version__.split("."))
    assert major >= 0 and minor >= 0 and patch >= 0


def test_missing_file_and_bad_mjcf():
    with pytest.raises(mjbuoy.Error, match="no model file /nonexistent.xml"):
        mjbuoy.Sim("/nonexistent.xml")
    with pytest.raises(mjbuoy.Error, match="cannot parse"):
        mjbuoy.Sim("<mujoco><worldbody></mujoco>")
    with pytest.raises(TypeError):
        mjbuoy.Sim(None)


def test_bad_mjbuoy_entry_in_the_scene(wavy):
    # mjb_attach's validator: the entry, its value and the accepted range
    bad = wavy.replace('name="mjbuoy.sea.density" data="1000"',
                       'name="mjbuoy.sea.density" data="-5"')
    with pytest.raises(mjbuoy.Error, match="mjbuoy.sea.density"):
        mjbuoy.Sim(bad)


def test_bad_overrides(wavy):
    # the same checks as mjbuoy-sim --set (tools/sim/simsea.cc, mjb_attach)
    with pytest.raises(mjbuoy.Error, match=r"mjbuoy.spectrum.sea.hs.*out of range"):
        mjbuoy.Sim(wavy, spectrum__sea__hs=-1)
    with pytest.raises(mjbuoy.Error, match="is not a list of finite numbers"):
        mjbuoy.Sim(wavy, **{"mjbuoy.spectrum.sea.hs": "big"})
    with pytest.raises(mjbuoy.Error, match="unknown|not an mjbuoy|mjbuoy.sea.densty"):
        mjbuoy.Sim(wavy, sea__densty=1000)
    with pytest.raises(mjbuoy.Error, match="already set"):
        mjbuoy.Sim(wavy, seed=3, spectrum__sea__seed=4)
    with pytest.raises(mjbuoy.Error, match="has no wave spectrum"):
        mjbuoy.Sim(wavy, calm=True, seed=3)
    with pytest.raises(TypeError, match="override mjbuoy.sea.density"):
        mjbuoy.Sim(wavy, sea__density={"a": 1})


def test_overrides_take_effect(wavy):
    # Archimedes again: density 500 doubles the draft of 0.25 m to 0.5 m,
    # the whole box height; 800 -> T = 500 / (800 * 2) = 0.3125 m
    sim = mjbuoy.Sim(wavy, calm=True, sea__density=800)
    sim.step(5000)
    assert abs((0.25 - sim.qpos[2]) - 0.3125) < 1e-3


def test_bad_arguments_of_members(wavy):
    sim = mjbuoy.Sim(wavy)
    with pytest.raises(ValueError, match="n = 0 must be >= 1"):
        sim.step(0)
    with pytest.raises(ValueError, match=r"ctrl: shape \(2,\), expected \(1,\)"):
        sim.ctrl = [1.0, 2.0]
    with pytest.raises(TypeError, match="qpos: got None"):
        sim.qpos = None
    with pytest.raises(TypeError, match="dtype"):
        sim.qvel = ["a"] * sim.nv
    with pytest.raises(ValueError):
        sim.body_xpos[0, 0] = 1.0  # computed by MuJoCo: read-only
    with pytest.raises(KeyError, match='no body named "hul"; bodies in the model: world, barge'):
        sim.body_id("hul")
    with pytest.raises(ValueError, match="not a force family"):
        sim.wrench("buoyancy")
    with pytest.raises(mjbuoy.Error, match="radiation off"):
        sim.radiation("barge")
    with pytest.raises(ValueError, match="timestep"):
        sim.timestep = -1
    # a qpos with NaN is refused before MuJoCo sees it
    with pytest.raises(ValueError, match="element 2 is nan"):
        sim.qpos = np.array([0, 0, np.nan, 1, 0, 0, 0])
    # a non-contiguous array of the right length is fine
    wide = np.zeros((sim.nv, 2))
    sim.qvel = wide[:, 1]
    assert np.array_equal(sim.qvel, np.zeros(sim.nv))


def test_bad_sea_keeps_the_old_one(wavy):
    sim = mjbuoy.Sim(wavy)
    before = sim.waves()
    with pytest.raises(mjbuoy.Error, match="hs"):
        sim.set_sea(spectra=[{"type": "jonswap", "hs": -2.0, "tp": 5.0}])
    np.testing.assert_array_equal(sim.waves(), before)
    with pytest.raises(ValueError, match=r'spectra\[0\]\["hz"\]: unknown key'):
        sim.set_sea(spectra=[{"hz": 1.0}])
    with pytest.raises(ValueError, match=r"waves: shape \(1, 4\), expected \(any, 5\)"):
        sim.set_sea(waves=[[0.1, 20, 0, 0]])


def test_set_sea_regular_wave_heights():
    # one Airy wave of amplitude a, length L, along +x: eta = a cos(k x - w t),
    # k = 2 pi / L, w = sqrt(g k) in deep water (docs/physics.md)
    # a calm scene reserves no components: sea.capacity makes room for set_sea's
    sim = mjbuoy.Sim("""<mujoco><custom><text name="mjbuoy.hulls" data="h"/>
      <numeric name="mjbuoy.sea.capacity" data="4"/></custom>
      <worldbody><body><freejoint/><geom name="h" type="box" size="1 1 1" mass="1000"/></body>
      </worldbody></mujoco>""")
    sim.set_sea(waves=[[0.2, 30.0, 0.0, 0.0, 0.0]])
    k = 2 * np.pi / 30.0
    w = np.sqrt(9.81 * k)
    x = np.linspace(-20, 20, 41)
    np.testing.assert_allclose(sim.sea_height(x, 0.0, 3.0), 0.2 * np.cos(k * x - w * 3.0),
                               atol=1e-9)
    comp = sim.waves()
    assert comp.shape == (1, 6)
    np.testing.assert_allclose(comp[0, :3], [0.2, w, k], rtol=1e-12)
