# shared paths of the mjbuoy pytest suite: the models and mjbuoy-sim (CTest
# sets MJBUOY_MODELS and MJBUOY_SIM; by hand they default to the source tree
# and build/tools)
import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def models():
    return pathlib.Path(os.environ.get("MJBUOY_MODELS", ROOT / "models"))


@pytest.fixture
def sim_exe():
    return os.environ.get("MJBUOY_SIM", str(ROOT / "build" / "tools" / "mjbuoy-sim"))


# a box barge with a stern motor in a JONSWAP sea of 16 components: small
# enough to step fast, random enough that seeds matter
WAVY = """
<mujoco>
  <option timestep="0.002"/>
  <custom>
    <numeric name="mjbuoy.sea.density" data="1000"/>
    <text name="mjbuoy.hulls" data="hull"/>
    <text name="mjbuoy.radiation" data="off"/>
    <numeric name="mjbuoy.hull.damping" data="3000 300"/>
    <text name="mjbuoy.spectrum.sea.type" data="jonswap"/>
    <numeric name="mjbuoy.spectrum.sea.hs" data="0.5"/>
    <numeric name="mjbuoy.spectrum.sea.tp" data="4"/>
    <numeric name="mjbuoy.spectrum.sea.components" data="16"/>
    <numeric name="mjbuoy.spectrum.sea.spreading" data="10"/>
  </custom>
  <worldbody>
    <body name="barge" pos="0 0 0">
      <freejoint/>
      <geom name="hull" type="box" size="1 0.5 0.25" mass="500"/>
      <site name="stern" pos="-1 0 0"/>
    </body>
  </worldbody>
  <actuator>
    <motor name="thrust" site="stern" gear="1 0 0 0 0 0" ctrllimited="true" ctrlrange="-500 500"/>
  </actuator>
</mujoco>
"""


@pytest.fixture
def wavy():
    return WAVY
