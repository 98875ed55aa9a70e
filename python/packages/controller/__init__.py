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
``getDevice``, ``getNumberOfDevices``, ``getDeviceByIndex``, ``getKeyboard`` and ``getName``. ``getDevice``
returns the devices a world file puts on the car (``[[vehicle.device]]``) as :class:`GPS`,
:class:`InertialUnit`, :class:`Gyro`, :class:`Accelerometer`, :class:`Compass`,
:class:`DistanceSensor`, :class:`Radar` (with :class:`RadarTarget`), :class:`Lidar` (with
:class:`LidarPoint`), :class:`Camera`, :class:`Display` and the project's
:class:`RoadSensor` extension, with
Webots' method names, measured by the same engine code as the C API's; the car's own devices
(motors, brakes, lights) as a plain :class:`Device` (names and node types only); ``None`` for
names the robot does not have. Warnings and errors go to stderr with Webots' texts.

:class:`Supervisor` adds Webots' calls for placing the world's cars and dynamic bodies
(``getFromDef``, ``Node.getField("translation"/"rotation")``, ``Field.get/setSFVec3f``,
``get/setSFRotation``, ``Node.getVelocity/setVelocity``, ``resetPhysics``,
``simulationReset``).
"""

# One module per device kind, named as Webots' own controller package names them
# (controller/robot.py, controller/gps.py, ...), so ``from controller.gps import GPS`` works
# here as it does in Webots; ``from controller import GPS`` is what controllers write.
from webots_vehicle._native import WorldError

from .accelerometer import Accelerometer
from .camera import Camera, CameraRecognitionObject
from .compass import Compass
from .device import Device
from .display import Display, ImageRef
from .distance_sensor import DistanceSensor
from .field import Field
from .gps import GPS
from .gyro import Gyro
from .inertial_unit import InertialUnit
from .keyboard import Keyboard
from .lidar import Lidar
from .lidar_point import LidarPoint
from .node import Node
from .radar import Radar
from .radar_target import RadarTarget
from .road_sensor import RoadSensor
from .robot import Robot
from .supervisor import Supervisor

__all__ = [
    "Accelerometer",
    "Camera",
    "CameraRecognitionObject",
    "Compass",
    "Device",
    "Display",
    "DistanceSensor",
    "GPS",
    "Gyro",
    "ImageRef",
    "InertialUnit",
    "Keyboard",
    "Lidar",
    "LidarPoint",
    "Field",
    "Node",
    "Radar",
    "RadarTarget",
    "RoadSensor",
    "Robot",
    "Supervisor",
    "WorldError",
]
