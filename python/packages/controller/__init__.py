"""Webots' ``controller`` module, for vehicle controllers: ``Robot`` and ``Supervisor``.

A controller written for Webots runs unchanged::

    from controller import Robot
    robot = Robot()
    timestep = int(robot.getBasicTimeStep())   # ms
    while robot.step(timestep) != -1:
        print(robot.getTime())                 # s

The robot is the one of the world named by the environment variable ``VEHICLE_WORLD`` (a
world file or a shipped car model name; unset: a BmwX5 on flat ground, ``basicTimeStep``
10 ms), loaded when the first ``Robot`` (or ``Supervisor``, ``Driver``, ``Car``) is created,
as the C API loads it in ``wb_robot_init``. A world that cannot be loaded raises
:class:`WorldError`, whose message names the file, line and key. The world's ``duration``
makes ``step`` return -1. With ``VEHICLE_OUT=DIR`` the run is recorded and written into
``DIR`` (``telemetry.csv``, ``metrics.json``, ``replay.glb``) when it ends or the process exits.

Only the calls a vehicle controller uses exist: ``step``, ``getTime``, ``getBasicTimeStep``,
``getDevice`` and ``getName``. Devices are names only (there is no device API, as in the C
API of this simulator): ``getDevice`` returns a :class:`Device` for the car's devices and
``None`` for names the robot does not have. Warnings go to stderr with Webots' texts.
"""

import atexit
import numbers
import operator
import sys
from typing import Dict, Optional

from webots_vehicle import _native
from webots_vehicle._native import WorldError

__all__ = ["Device", "Robot", "Supervisor", "WorldError"]

_INT_MIN = -(2**31)
_INT_MAX = 2**31 - 1


def _c_int(value: object) -> int:
    """``value`` as a C ``int``: an integer (TypeError otherwise, as Webots' ctypes binding
    raises), saturated to the ``int`` range so that the C API's range warning applies."""
    return max(_INT_MIN, min(_INT_MAX, operator.index(value)))  # type: ignore[arg-type]


def _c_double(value: object) -> float:
    """``value`` as a C ``double``: a real number (TypeError otherwise, as ctypes raises). NaN
    and infinities pass: the C API refuses them with a warning."""
    if not isinstance(value, numbers.Real):
        raise TypeError(f"a number is required, not {type(value).__name__}")
    return float(value)


class Device:
    """A device of the robot, known by name only (Webots: ``controller.Device``)."""

    def __init__(self, name: str, tag: int) -> None:
        self._name = name
        self._tag = tag

    def getName(self) -> str:
        """The device name, e.g. ``"right_steer"``."""
        return self._name

    @property
    def name(self) -> str:
        """The device name."""
        return self._name

    def __repr__(self) -> str:
        return f"Device({self._name!r})"


class Robot:
    """The robot of the controller process (Webots: ``controller.Robot``).

    Creating it loads the world named by ``VEHICLE_WORLD`` (see the module docs). Only one
    robot exists per process: creating a second prints Webots' error on stderr and gives an
    object that controls the same robot.
    """

    created: Optional["Robot"] = None

    def __init__(self) -> None:
        if Robot.created is not None:
            print(
                "Error: only one Robot instance can be created per controller process.",
                file=sys.stderr,
            )
        _native.wb_robot_init()
        if Robot.created is None:
            # The process ends with wb_robot_cleanup, as a Webots controller's does: a run
            # recorded under VEHICLE_OUT writes its outputs then if it has not ended before.
            atexit.register(_native.wb_robot_cleanup)
        Robot.created = self
        self._devices: Dict[str, Device] = {}

    def step(self, timestep: Optional[int] = None) -> int:
        """Advances the simulation by ``timestep`` ms (None: ``getBasicTimeStep()``), rounded
        up to whole basic time steps, with the commands in force. Returns 0, or -1 once the
        world's ``duration`` has elapsed. The driver library does not run: a ``Driver`` steps
        with ``Driver.step()``. A negative ``timestep`` advances nothing, with a warning."""
        if timestep is None:
            timestep = int(_native.wb_robot_get_basic_time_step())
        return _native.wb_robot_step(_c_int(timestep))

    def getTime(self) -> float:
        """Simulated time since the world was loaded (s)."""
        return _native.wb_robot_get_time()

    def getBasicTimeStep(self) -> float:
        """The world's ``basicTimeStep`` (ms)."""
        return _native.wb_robot_get_basic_time_step()

    def getDevice(self, name: str) -> Optional[Device]:
        """The device ``name`` (e.g. ``"right_steer"``, ``"engine_speaker"``), or None if
        the robot has no such device."""
        device = self._devices.get(name)
        if device is None:
            tag = _native.wb_robot_get_device(str(name))
            if tag == 0:
                return None
            device = Device(str(name), tag)
            self._devices[name] = device
        return device

    def getName(self) -> str:
        """The robot's name: ``"vehicle"`` for a car (the ``name`` default of Webots' car
        PROTOs), ``"robot"`` for a DifferentialWheels robot (the ``Robot`` default)."""
        return "vehicle" if _native.wbu_driver_initialization_is_possible() else "robot"


class Supervisor(Robot):
    """A robot with supervisor rights (Webots: ``controller.Supervisor``). Here it adds
    nothing to :class:`Robot`: the vehicle controllers' calls are all ``Robot`` calls."""
