# physics through the Python module: equilibrium draft, sensors against the
# C API, controls against mjbuoy-sim --ctrl
import csv
import subprocess

import numpy as np

import mjbuoy

# a box barge with a wrench sensor, a submerged-volume sensor and a wave
# gauge at a site (docs/mjcf.md section 7), in regular waves
SENSED = """
<mujoco>
  <option timestep="0.002"/>
  <custom>
    <numeric name="mjbuoy.sea.density" data="1000"/>
    <text name="mjbuoy.hulls" data="hull"/>
    <text name="mjbuoy.radiation" data="off"/>
    <numeric name="mjbuoy.hull.damping" data="3000 300"/>
    <numeric name="mjbuoy.wave.swell" data="0.1 20 30 0 0"/>
    <text name="mjbuoy.sensor.w" data="wrench"/>
    <text name="mjbuoy.sensor.vol" data="submerged_volume"/>
    <text name="mjbuoy.sensor.gauge" data="elevation"/>
  </custom>
  <worldbody>
    <site name="post" pos="3 1 0"/>
    <body name="barge" pos="0 0 0.05">
      <freejoint/>
      <geom name="hull" type="box" size="1 0.5 0.25" mass="{mass}"/>
    </body>
  </worldbody>
  <sensor>
    <user name="w" objtype="body" objname="barge" dim="6" datatype="real" needstage="acc"/>
    <user name="vol" objtype="body" objname="barge" dim="1" datatype="real" needstage="acc"/>
    <user name="gauge" objtype="site" objname="post" dim="1" datatype="real" needstage="pos"/>
  </sensor>
</mujoco>
"""


def test_barge_settles_at_its_analytic_draft(models):
    # Archimedes: a box of mass M floats with draft T = M / (rho L B);
    # models/barge.xml: 500 kg, 2 x 1 m, rho 1000 -> T = 0.25 m, so the
    # centre of the 0.5 m high box sits at 0.25 - T = 0 m
    sim = mjbuoy.Sim(str(models / "barge.xml"))
    sim.step(5000)  # 10 s: heave period 2 pi sqrt(M / (rho g L B)) = 1.0 s, half critical
    draft = 0.25 - sim.qpos[2]
    assert abs(draft - 500 / (1000 * 2 * 1)) < 1e-3
    # the buoyancy carries the weight: F_z = M g (pressure family)
    fz = sim.wrench("pressure")[sim.body_id("barge"), 2]
    assert abs(fz - 500 * 9.81) < 0.01 * 500 * 9.81


def test_mass_override_through_inline_mjcf_changes_the_draft():
    # T = M / (rho L B) = 300 / 2000 = 0.15 m: the centre 0.10 m above the level
    sim = mjbuoy.Sim(SENSED.replace("{mass}", "300"), calm=True)
    sim.step(5000)
    assert abs(sim.qpos[2] - 0.10) < 1e-3
    # submerged volume sensor = M / rho = 0.3 m^3 at rest (section 9 of docs/physics.md)
    lo, hi = sim.sensor_range("vol")
    sim.forward()
    assert abs(sim.sensordata[lo] - 0.3) < 1e-3 * 0.3


def test_sensors_through_numpy_equal_the_c_api():
    sim = mjbuoy.Sim(SENSED.replace("{mass}", "500"))
    for _ in range(50):
        sim.step(7)
        sim.forward()
        lo, hi = sim.sensor_range("w")
        # the wrench sensor is mjb_wrench of the same mj_forward (docs/mjcf.md section 7)
        np.testing.assert_array_equal(sim.sensordata[lo:hi], sim.wrench()[sim.body_id("barge")])
        g = sim.sensor_range("gauge")[0]
        # the wave gauge is mjb_seaHeight at the site's x, y and the state's time
        # (the gauge may take the vector path: within round-off, docs/robustness.md)
        assert abs(sim.sensordata[g] - sim.sea_height(3.0, 1.0)) < 1e-12
    # and a regular wave of amplitude 0.1 m moves the gauge by about that much
    # once the start-up ramp (3 periods of 3.58 s, docs/physics.md section 6) is over
    heights = sim.sea_height(3.0, 1.0, np.linspace(20, 30, 400))
    assert abs(heights.max() - 0.1) < 0.01 and abs(heights.min() + 0.1) < 0.01


def test_writing_ctrl_moves_the_boat_as_the_cli_ctrl_does(models, sim_exe, tmp_path):
    model = str(models / "motorboat.xml")
    out = tmp_path / "run.csv"
    subprocess.run([sim_exe, model, "--ctrl", "60", "--duration", "2", "--interval", "0.5",
                    "--csv", str(out)], check=True, capture_output=True, timeout=300)
    rows = list(csv.DictReader(open(out)))
    sim = mjbuoy.Sim(model)
    sim.ctrl[0] = 60.0  # through the view: d->ctrl itself
    sim.forward()  # as mjbuoy-sim does before its first step
    boat = sim.body_id("boat")
    n = round(0.5 / sim.timestep)
    x0 = sim.body_xpos[boat, 0]
    for r in rows[1:]:
        sim.step(n)
        assert abs(sim.time - float(r["time"])) < 1e-9
        # the CSV's %.9g: agreement to its printed digits
        for k, c in enumerate("xyz"):
            assert abs(sim.body_xpos[boat, k] - float(r["boat." + c])) < 1e-8
    # 60 N of thrust along +x moves the boat forward
    # and no further than Newton without drag or added mass allows: F t^2 / (2 M)
    assert 0.01 < sim.body_xpos[boat, 0] - x0 < 60 * 2.0**2 / (2 * 176.2)


def test_radiation_coefficients_of_a_hemisphere():
    # a sphere of density 500 floats half submerged: a hemisphere, whose
    # heave added mass at infinite frequency is exactly half its displaced
    # mass, rho (2/3) pi R^3 / 2 (half the double body, a sphere in unbounded
    # fluid: 0.5 rho (4/3) pi R^3; Hulme 1982, J. Fluid Mech. 121)
    sim = mjbuoy.Sim("""<mujoco><custom><numeric name="mjbuoy.sea.density" data="1000"/>
      <text name="mjbuoy.hulls" data="h"/><text name="mjbuoy.radiation" data="on"/></custom>
      <worldbody><body name="ball"><freejoint/>
      <geom name="h" type="sphere" size="0.5" mass="261.799"/></body></worldbody></mujoco>""")
    c = sim.radiation("ball")
    m0 = 1000 * 2 / 3 * np.pi * 0.5**3
    assert abs(c["Ainf"][2, 2] / m0 - 0.5) < 0.02
    nw = len(c["omega"])
    assert c["A"].shape == (nw, 6, 6) and c["B"].shape == (nw, 6, 6)
    # radiation damping is positive (energy goes out in waves) and the
    # added mass tends to A(inf) from above at high frequency (Hulme's curve)
    assert np.all(c["B"][:, 2, 2] > 0)
    assert c["A"][-1, 2, 2] < c["A"][0, 2, 2]
    # long waves: the heave exciting force tends to the hydrostatic and
    # inertial force of the undisturbed wave, |X3| = C33 - w^2 (rho V + A33)
    # per unit amplitude (Newman, Marine Hydrodynamics, 1977, section 6.17),
    # C33 = rho g pi R^2; at the lowest frequency (kR = 0.05) within 2 %
    w0 = c["omega"][0]
    long_wave = 1000 * 9.81 * np.pi * 0.25 - w0**2 * (m0 + c["A"][0, 2, 2])
    assert c["X"].shape == (nw, len(c["heading"]), 6) and len(c["heading"]) > 0
    assert abs(abs(c["X"][0, 0, 2]) / long_wave - 1) < 0.02
