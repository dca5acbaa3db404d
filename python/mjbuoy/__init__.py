"""mjbuoy: buoyancy and hydrodynamics of floating bodies for MuJoCo.

Sim is one scene, Batch n copies of it stepped in parallel, Error mjbuoy's
own errors (a RuntimeError). Units are SI: m, kg, s, N, rad (angles of
waves and wind in degrees, as in the MJCF). Quick start: docs/python.md.
"""

from ._mjbuoy import PARTS, Batch, Error, Sim, __version__

__all__ = ["Sim", "Batch", "Error", "PARTS", "__version__"]
