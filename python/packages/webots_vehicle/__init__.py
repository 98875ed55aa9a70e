"""The vehicle simulator from Python.

Two APIs in one package:

* Webots' own modules, ``controller`` (``Robot``, ``Supervisor``) and ``vehicle``
  (``Driver``, ``Car``), so that a Webots car controller runs unchanged; the world comes from
  the environment variable ``VEHICLE_WORLD``.
* This package's simulator API: :class:`Simulation` (a world from a world file, a model name
  or keyword arguments), its cars (:class:`SimCar`), stepping, telemetry as numpy arrays
  (:class:`Telemetry`, ``to_pandas()``), and the ``vehicle-sim`` scenarios with their metrics
  (:meth:`Simulation.run`), snapshots (:meth:`Simulation.snapshot`, :meth:`Simulation.restore`)
  and supervisor placement (:meth:`SimCar.set_pose`, :meth:`SimCar.set_velocity`,
  :meth:`Simulation.reset`); sweeps: :class:`Sweep` (a sweep file's cases by index, each run
  into its row of ``vehicle-sim sweep``'s ``results.csv``), :func:`run_case` and
  :func:`load_results` (``results.csv`` as a pandas DataFrame); :func:`camera_image`, a
  controller camera's image as a numpy array; the ray devices' samples as numpy arrays:
  :mod:`webots_vehicle.devices`.

Units: m, m/s, rad (positive steering turns right), rad/s, N, s; km/h where the Webots driver
API uses it (cruising speed, ``speed_kmh``); ms for ``basicTimeStep``. Frame: x forward, y
left, z up.
"""

from webots_vehicle._native import SimulationError, WorldError
from webots_vehicle.images import camera_image
from webots_vehicle.simulation import (
    SCENARIOS,
    Placement,
    RunResult,
    SimBody,
    SimCar,
    Simulation,
    VehicleWarning,
)
from webots_vehicle.sweep import Sweep, load_results, run_case
from webots_vehicle.telemetry import COLUMNS, Telemetry

__all__ = [
    "COLUMNS",
    "SCENARIOS",
    "Placement",
    "RunResult",
    "SimBody",
    "SimCar",
    "Simulation",
    "SimulationError",
    "Sweep",
    "Telemetry",
    "VehicleWarning",
    "WorldError",
    "camera_image",
    "load_results",
    "run_case",
]
