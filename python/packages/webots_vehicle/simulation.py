"""The Pythonic simulator API: :class:`Simulation`, :class:`SimCar`, :class:`RunResult`."""

import json
import operator
import os
import warnings
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

from webots_vehicle import _native
from webots_vehicle._world_text import document
from webots_vehicle.telemetry import COLUMNS, Telemetry

__all__ = ["Placement", "RunResult", "SimBody", "SimCar", "Simulation", "VehicleWarning"]


class Placement(NamedTuple):
    """Where a car or body is and how it moves, world frame (x east, y north, z up)."""

    #: Position (m): a car's origin (rear-axle centre), a body's centre. Webots ``translation``.
    translation: Tuple[float, float, float]
    #: Orientation as Webots' ``rotation``: unit axis and angle (rad).
    rotation: Tuple[float, float, float, float]
    #: Velocity of that position (m/s).
    velocity: Tuple[float, float, float]
    #: Angular velocity (rad/s).
    angular_velocity: Tuple[float, float, float]


def _vector(name: str, values: Sequence[float], n: int) -> List[float]:
    items = [float(v) for v in values]
    if len(items) != n:
        raise ValueError(f"{name} needs {n} numbers, not {len(items)}")
    return items


class _Placed:
    """What a supervisor does to a car or a body (see :class:`SimCar`, :class:`SimBody`)."""

    _kind = ""

    def __init__(self, simulation: "Simulation", index: int) -> None:
        self._core = simulation._core
        self._index = index

    @property
    def placement(self) -> Placement:
        """Its pose and velocity now (after the last step, or as set since)."""
        t, r, v, w = self._core.placement(self._kind, self._index)
        return Placement(tuple(t), tuple(r), tuple(v), tuple(w))  # type: ignore[arg-type]

    def set_pose(
        self,
        translation: Sequence[float],
        rotation: Sequence[float] = (0.0, 0.0, 1.0, 0.0),
    ) -> None:
        """Puts it at ``translation`` (m) turned by Webots ``rotation`` (axis, angle in rad).
        A car keeps its velocity in its own frame, its suspension deflection and steering
        (put it down at the height it stood at for its springs to stay settled). Values out of
        range (beyond 10 km, NaN) raise ValueError and move nothing."""
        self._core.set_pose(
            self._kind,
            self._index,
            _vector("translation", translation, 3),
            _vector("rotation", rotation, 4),
        )

    def set_velocity(
        self,
        velocity: Sequence[float],
        angular_velocity: Sequence[float] = (0.0, 0.0, 0.0),
    ) -> None:
        """Sets its velocity (m/s, world; a car's at its origin) and angular velocity (rad/s,
        world). A car's wheels spin at free rolling for it and its suspension stops moving.
        Beyond 200 m/s or 20 rad/s on an axis raises ValueError."""
        self._core.set_velocity(
            self._kind,
            self._index,
            _vector("velocity", velocity, 3),
            _vector("angular_velocity", angular_velocity, 3),
        )

    def reset_physics(self) -> None:
        """Stops it (Webots ``Node.resetPhysics``): no velocity, no wheel spin."""
        self.set_velocity((0.0, 0.0, 0.0))


class SimBody(_Placed):
    """A dynamic body (``[[body]]``) of a :class:`Simulation`, for placing it."""

    _kind = "body"

    def __repr__(self) -> str:
        return f"<SimBody {self._index}>"

#: The scenarios of :meth:`Simulation.run` (``vehicle-sim --scenario``); ``square`` and
#: ``spin`` are for a DifferentialWheels world, the others for a car (the five handling
#: manoeuvres, ISO 7401, ISO 4138, FMVSS 126, split-μ braking and ISO 3888-2, among them).
SCENARIOS: Tuple[str, ...] = (
    "accel-speed",
    "accel-torque",
    "brake",
    "circle",
    "lane-change",
    "step-steer",
    "constant-radius",
    "sine-with-dwell",
    "split-mu",
    "iso-3888",
    "test-track",
    "ftp75",
    "hwfet",
    "wltc",
    "square",
    "spin",
)


class VehicleWarning(UserWarning):
    """A value accepted with a warning: a world-file field replaced by its default, or a
    driver command clamped or refused (the text is Webots')."""


def _warn(text: Optional[str]) -> None:
    if text:
        warnings.warn(text, VehicleWarning, stacklevel=3)


class SimCar(_Placed):
    """A car of a :class:`Simulation`, driven through the Webots driver library's commands
    (the same rules as ``vehicle.Driver``: clamped values come with a
    :class:`VehicleWarning`), and placed as a Webots supervisor would (:meth:`set_pose`,
    :meth:`set_velocity`, :meth:`reset_physics`)."""

    _kind = "car"

    def __init__(self, simulation: "Simulation", index: int) -> None:
        super().__init__(simulation, index)
        self._simulation = simulation

    @property
    def index(self) -> int:
        """The car's position in ``Simulation.cars``."""
        return self._index

    @property
    def model(self) -> str:
        """The Webots model name, e.g. ``"BmwX5"`` (``"Car"`` for the plain PROTO)."""
        return self._core.model(self._index)

    @property
    def wheelbase(self) -> float:
        """Distance between the axles (m)."""
        return self._core.geometry(self._index)[0]

    @property
    def track_front(self) -> float:
        """Distance between the front wheels (m)."""
        return self._core.geometry(self._index)[1]

    @property
    def track_rear(self) -> float:
        """Distance between the rear wheels (m)."""
        return self._core.geometry(self._index)[2]

    @property
    def front_wheel_radius(self) -> float:
        """Front tyre radius (m)."""
        return self._core.geometry(self._index)[3]

    @property
    def rear_wheel_radius(self) -> float:
        """Rear tyre radius (m)."""
        return self._core.geometry(self._index)[4]

    def set_cruising_speed(self, speed: float) -> None:
        """Cruise control to ``speed`` km/h (negative: reverse); selects SPEED mode."""
        _warn(self._core.set_cruising_speed(self._index, float(speed)))

    def set_steering_angle(self, angle: float) -> None:
        """Ackermann steering to ``angle`` rad (positive turns right)."""
        _warn(self._core.set_steering_angle(self._index, float(angle)))

    def set_throttle(self, throttle: float) -> None:
        """Throttle from 0 to 1; selects TORQUE mode."""
        _warn(self._core.set_throttle(self._index, float(throttle)))

    def set_brake_intensity(self, intensity: float) -> None:
        """Brake intensity from 0 to 1."""
        _warn(self._core.set_brake_intensity(self._index, float(intensity)))

    def set_gear(self, gear: int) -> None:
        """Gear: -1 reverse, 0 neutral, 1.. forward (TORQUE mode)."""
        g = max(-(2**31), min(2**31 - 1, operator.index(gear)))
        _warn(self._core.set_gear(self._index, g))

    @property
    def state(self) -> Optional[Dict[str, float]]:
        """The last sample (column name to value, NaN where a quantity does not exist), or
        None before the first step. Kept apart from the recording: O(1) whatever the run's
        length, and there with ``record=False`` too."""
        row = self._core.last_sample(self._index)
        return None if row is None else dict(zip(COLUMNS, row))

    @property
    def telemetry(self) -> Telemetry:
        """The samples the run keeps (``Simulation(record=...)``): the car's state at the
        first step's start, then one per step (the rows of ``telemetry.csv``, as
        ``vehicle-sim`` records them); the last N of them with ``record=N``, none with
        ``record=False``. Read-only arrays over the recorded memory, no copy, while the
        samples are all in memory (always with ``record=N``; up to 16,384 samples with
        ``record=True``, whose older samples then wait in a temporary file and are read back
        into a new table at each access)."""
        return Telemetry(self._core.telemetry(self._index), f"car {self._index} ({self.model})")

    @property
    def samples_recorded(self) -> int:
        """The samples recorded so far, kept or not (``len(telemetry)`` is those kept)."""
        return self._core.recorded_count(self._index)

    def __repr__(self) -> str:
        return f"<SimCar {self._index}: {self.model}>"


class RunResult:
    """What :meth:`Simulation.run` returns: the metrics of ``vehicle-sim --scenario NAME
    --json`` and the telemetry of each single scenario."""

    def __init__(self, report: Dict[str, Any], telemetry: Dict[str, Telemetry]) -> None:
        self._report = report
        self._telemetry = telemetry

    @property
    def scenario(self) -> str:
        """The scenario asked for."""
        return self._report["scenario"]

    @property
    def metrics(self) -> Dict[str, Dict[str, Union[float, bool, None]]]:
        """Single scenario name to its metrics (the JSON keys, units in the names, e.g.
        ``max_lateral_accel_mps2``; ``None`` for a metric not reached; each ends with its
        ``sim_seconds``)."""
        return self._report["scenarios"]

    @property
    def telemetry(self) -> Dict[str, Telemetry]:
        """Single scenario name to its telemetry (the rows of ``telemetry.csv``)."""
        return self._telemetry

    @property
    def sim_seconds(self) -> float:
        """Simulated time of the whole run (s)."""
        return self._report["sim_seconds"]

    @property
    def wall_seconds(self) -> float:
        """Wall-clock time of the run (s)."""
        return self._report["wall_seconds"]

    @property
    def warnings(self) -> List[str]:
        """The world file's warnings and the scenarios' notes."""
        return self._report["warnings"]

    def to_dict(self) -> Dict[str, Any]:
        """The whole ``vehicle-sim --json`` object (world, vehicle, scenario, sim_seconds,
        wall_seconds, realtime_factor, scenarios, warnings)."""
        return self._report

    def __repr__(self) -> str:
        return f"<RunResult {self.scenario}: {self.metrics!r}>"


class Simulation:
    """A simulated world with its cars, stepped from Python.

    ``Simulation()`` is the default world (a BmwX5 on flat ground, ``basicTimeStep`` 10 ms);
    ``Simulation("ToyotaPrius")`` the default world with a shipped model;
    ``Simulation("my_world.toml")`` a world file (``sim/README.md``, "World files");
    ``Simulation(model="ToyotaPrius", basicTimeStep=20, duration=30.0, ground={"friction":
    0.8})`` a world from keyword arguments in world-file vocabulary (``model=`` is short for
    ``vehicle={"model": ...}``). A world that cannot be loaded raises
    :class:`~webots_vehicle.WorldError` naming the file (or the keyword arguments), line and
    key. Fields replaced by their defaults give a :class:`VehicleWarning`.

    The world's car is ``cars[0]`` (also ``car``); :meth:`add_car` adds more. :meth:`step`
    runs every car's driver library and one ``basicTimeStep`` of physics and records one
    telemetry sample per car. :meth:`run` runs a ``vehicle-sim`` scenario on a fresh copy of
    the world.

    ``record`` says how much of the run each car's :attr:`SimCar.telemetry` keeps: ``True``
    every sample (memory beyond 16,384 samples moves to a temporary file), ``False`` none
    (:attr:`SimCar.state`, the last sample, is still there: a long run in flat memory), or a
    whole number ``N`` the last ``N`` samples (a ring in memory, 2 x 344 bytes per sample).
    Anything else raises ValueError naming ``record``. A bounded recording (``False`` or
    ``N``) also keeps no device rows and only the first replay frame in :meth:`save`.
    """

    def __init__(
        self,
        world: Union[str, "os.PathLike[str]", None] = None,
        *,
        record: Union[bool, int] = True,
        **fields: Any,
    ) -> None:
        if world is not None and fields:
            raise TypeError("Simulation() takes a world or keyword arguments, not both")
        if fields:
            if "model" in fields:
                vehicle = dict(fields.pop("vehicle", {}))
                vehicle.setdefault("model", fields.pop("model"))
                fields["vehicle"] = vehicle
            self._core = _native.Simulation.parse("<Simulation keyword arguments>", document(fields))
        else:
            self._core = _native.Simulation.load("" if world is None else os.fspath(world))
        self._core.set_record(record)
        for w in self._core.warnings:
            _warn(w)
        self._cars = [SimCar(self, i) for i in range(self._core.car_count)]

    @property
    def source(self) -> str:
        """Where the world came from (a path, ``<default world>``, ...)."""
        return self._core.source

    @property
    def vehicle(self) -> str:
        """What the world file drives: its car model, or ``"DifferentialWheels"``."""
        return self._core.vehicle

    @property
    def warnings(self) -> List[str]:
        """Every warning so far (world-file fields and car parameters replaced by defaults)."""
        return self._core.warnings

    @property
    def time(self) -> float:
        """Simulated time (s)."""
        return self._core.time

    @property
    def basic_time_step(self) -> int:
        """The step (ms)."""
        return self._core.basic_time_step

    @property
    def duration(self) -> Optional[float]:
        """The world's duration (s), after which :meth:`step` returns False; None if unset."""
        return self._core.duration

    @property
    def is_over(self) -> bool:
        """True once the world's duration has elapsed."""
        return self._core.is_over

    @property
    def cars(self) -> List[SimCar]:
        """The cars, the world file's first."""
        return list(self._cars)

    @property
    def car(self) -> SimCar:
        """The world file's car (``cars[0]``); IndexError in a world without a car."""
        if not self._cars:
            raise IndexError(f"the world {self.source} has no car (it holds a {self.vehicle})")
        return self._cars[0]

    def add_car(self, model: str = "Car", **fields: Any) -> SimCar:
        """Adds a car of the shipped ``model`` with ``fields`` overriding its ``Car`` fields in
        world-file vocabulary, e.g. ``add_car("ToyotaPrius", translation=[0, 5, 0.4],
        rotation=[0, 0, 1, 0.5], mounting="joints")`` (m, rad). Cars are added before the
        first step (the run is recorded from then on): afterwards this raises SimulationError."""
        text = "[vehicle]\n" + document({"model": model, **fields})
        index, car_warnings = self._core.add_car("<add_car keyword arguments>", text)
        for w in car_warnings:
            _warn(w)
        car = SimCar(self, index)
        self._cars.append(car)
        return car

    def step(self, steps: int = 1, drivers: bool = True) -> bool:
        """Advances ``steps`` basic time steps: each runs every car's driver library, then the
        physics, then records a sample per car. Returns False once the world's duration has
        elapsed (the steps past it are not run), True otherwise. With ``drivers=False`` only
        the physics runs, with the commands in force (Webots' ``wb_robot_step`` without
        ``wbu_driver_step``); a steering angle set since still acts, as in Webots."""
        return self._core.step(max(0, int(steps)), bool(drivers))

    @property
    def bodies(self) -> List[SimBody]:
        """The dynamic bodies (``[[body]]``), in the world file's order."""
        return [SimBody(self, i) for i in range(self._core.body_count)]

    def reset(self) -> None:
        """Back to the world as loaded (Webots ``Supervisor.simulationReset``): time 0, every
        car and body where the world file put it, drivers and devices as new; cars added and
        telemetry recorded since are dropped (recording starts again at the next step)."""
        self._core.simulation_reset()
        del self._cars[self._core.car_count :]

    def snapshot(self) -> "_native.Snapshot":
        """The whole state of the simulation now, as an opaque object for :meth:`restore`:
        the physics (bodies, joints, contacts and their solver caches), every car's driver
        library and devices (with their noise generators), the time, and how far the
        telemetry has been recorded. Its ``time`` attribute is the simulated time (s)."""
        return self._core.snapshot()

    def restore(self, snapshot: "_native.Snapshot") -> None:
        """Puts the simulation back in the state of ``snapshot`` (taken of this simulation;
        it stays valid and can be restored again): stepping on repeats, bit for bit, what
        followed it. Cars added and telemetry recorded since are dropped. A snapshot of another
        simulation raises :class:`~webots_vehicle.SimulationError`."""
        self._core.restore(snapshot)
        del self._cars[self._core.car_count :]

    def save(self, directory: Union[str, "os.PathLike[str]"]) -> List[str]:
        """Writes the run so far into ``directory`` (created if needed) as ``vehicle-sim``
        writes a run: ``telemetry.csv``, ``devices.csv`` (the enabled devices' readings),
        ``metrics.json`` and ``replay.glb`` (the SVG plots
        are drawn from them by ``vehicle-sim plot DIRECTORY``). Returns the paths written;
        none before the first step."""
        return [str(p) for p in self._core.save(os.fspath(directory))]

    def run_for(self, seconds: float) -> bool:
        """Steps for ``seconds`` of simulated time (rounded up to whole steps); as
        :meth:`step`."""
        steps = -(-int(round(float(seconds) * 1e6)) // (self.basic_time_step * 1000))
        return self.step(steps)

    def run(self, scenario: str) -> RunResult:
        """Runs the ``vehicle-sim`` scenario ``scenario`` (see ``SCENARIOS``) on a fresh copy
        of the world this simulation was built from (cars added and time stepped here do not
        take part) and returns its metrics, as ``vehicle-sim --scenario NAME --json``
        reports them, and its telemetry."""
        report, tables = self._core.run(scenario)
        telemetry = {name: Telemetry(table, name) for name, table in tables}
        return RunResult(json.loads(report), telemetry)

    def __repr__(self) -> str:
        return f"<Simulation {self.source}: {len(self._cars)} car(s), t = {self.time:.3f} s>"
