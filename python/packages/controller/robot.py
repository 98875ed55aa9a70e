"""Webots' ``Robot`` (``controller.Robot``): the controller's robot and its devices."""

import atexit
import sys
from typing import Dict, Optional, Set

from webots_vehicle import _native

from ._c import _c_int
from .accelerometer import Accelerometer
from .camera import Camera
from .compass import Compass
from .device import Device
from .display import Display
from .distance_sensor import DistanceSensor
from .gps import GPS
from .gyro import Gyro
from .inertial_unit import InertialUnit
from .keyboard import Keyboard
from .lidar import Lidar
from .node import Node
from .radar import Radar
from .road_sensor import RoadSensor

_SENSOR_CLASSES = {
    RoadSensor.NODE_TYPE: RoadSensor,
    Node.CAMERA: Camera,
    Node.DISPLAY: Display,
    Node.GPS: GPS,
    Node.INERTIAL_UNIT: InertialUnit,
    Node.GYRO: Gyro,
    Node.ACCELEROMETER: Accelerometer,
    Node.COMPASS: Compass,
    Node.DISTANCE_SENSOR: DistanceSensor,
    Node.RADAR: Radar,
    Node.LIDAR: Lidar,
}


def _device(name: str, tag: int) -> Device:
    """The device with ``tag`` as its class."""
    cls = _SENSOR_CLASSES.get(_native.wb_device_get_node_type(tag), Device)
    return cls(name, tag)


class Robot:
    """The robot of the controller process (Webots: ``controller.Robot``).

    Creating it loads the world named by ``VEHICLE_WORLD`` (see the module docs). Only one
    robot exists per process: creating a second prints Webots' error on stderr and gives an
    object that controls the same robot. A process that serves several cars through the
    project's extension :mod:`webots_vehicle.controllers` has one robot per car's
    controller: created while that controller is selected.
    """

    created: Optional["Robot"] = None
    #: The cars whose controller has a Robot (``None``: the process's one controller).
    _controllers: Set[Optional[str]] = set()

    def __init__(self) -> None:
        if Robot.created is None:
            Robot._controllers = set()
        controller = _native.controllers_current()  # None until a world is loaded
        if Robot.created is not None and controller in Robot._controllers:
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
        Robot._controllers.add(_native.controllers_current())
        self._devices: Dict[str, Device] = {}
        self._keyboard: Optional[Keyboard] = None

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

    def batterySensorEnable(self, samplingPeriod: int) -> None:
        """Samples the battery's energy every ``samplingPeriod`` ms: the first value a full
        period later. A car's battery is its traction battery when the world file accounts
        its energy (Webots' ``battery = [energy, maxEnergy, chargingRate]``,
        ``[vehicle.battery]`` or ``energy = true``)."""
        _native.wb_robot_battery_sensor_enable(_c_int(samplingPeriod))

    def batterySensorDisable(self) -> None:
        """Stops sampling the battery."""
        _native.wb_robot_battery_sensor_disable()

    def batterySensorGetSamplingPeriod(self) -> int:
        """The battery sensor's period (ms), 0 when disabled."""
        return _native.wb_robot_battery_sensor_get_sampling_period()

    def batterySensorGetValue(self) -> float:
        """The battery's energy at the last sample (J); NaN before the first sample and
        without a battery. When the energy of Webots' ``battery`` field reaches 0 the
        controller is stopped: ``step`` returns -1 from then on."""
        return _native.wb_robot_battery_sensor_get_value()

    def getDevice(self, name: str) -> Optional[Device]:
        """The device ``name`` (e.g. ``"right_steer"``, ``"engine_speaker"``), or None if
        the robot has no such device."""
        device = self._devices.get(name)
        if device is None:
            tag = _native.wb_robot_get_device(str(name))
            if tag == 0:
                return None
            device = _device(str(name), tag)
            self._devices[name] = device
        return device

    def getKeyboard(self) -> Keyboard:
        """The keyboard (one per robot)."""
        if self._keyboard is None:
            self._keyboard = Keyboard()
        return self._keyboard

    def getNumberOfDevices(self) -> int:
        """The number of devices: a car's 27 car-library tags (those its model lacks
        included), then its sensors."""
        return _native.wb_robot_get_number_of_devices()

    def getDeviceByIndex(self, index: int) -> Optional[Device]:
        """The device of ``index`` (0 to ``getNumberOfDevices() - 1``), None for a hole of the
        car's table or (with Webots' error) an index out of range."""
        tag = _native.wb_robot_get_device_by_index(_c_int(index))
        name = _native.wb_device_get_name(tag) if tag else None
        return None if name is None else self.getDevice(name)

    def getName(self) -> str:
        """The robot's name: ``"vehicle"`` for a car (the ``name`` default of Webots' car
        PROTOs), ``"robot"`` for a DifferentialWheels robot (the ``Robot`` default)."""
        return "vehicle" if _native.wbu_driver_initialization_is_possible() else "robot"
