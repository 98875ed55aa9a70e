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

import atexit
import numbers
import operator
import struct
import sys
from typing import Dict, List, Optional, Set, Union

from webots_vehicle import _native
from webots_vehicle._native import WorldError

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


class Node:
    """Webots' node types (``WbNodeType``, R2023b numbering) of the devices there are, and,
    from :meth:`Supervisor.getFromDef`, a car or dynamic body a supervisor moves."""

    NO_NODE = 0
    ACCELEROMETER = 35
    BRAKE = 37
    CAMERA = 38
    COMPASS = 39
    DISPLAY = 41
    DISTANCE_SENSOR = 42
    GPS = 44
    GYRO = 45
    INERTIAL_UNIT = 46
    LED = 47
    LIDAR = 48
    POSITION_SENSOR = 52
    RADAR = 54
    ROTATIONAL_MOTOR = 57
    SPEAKER = 59
    SOLID = 80

    def __init__(self, kind: str, index: int, def_name: str) -> None:
        self._kind = kind
        self._index = index
        self._def = def_name

    def getDef(self) -> str:
        """The node's DEF name (a car's ``name``; ``body[N]`` for the N-th ``[[body]]``)."""
        return self._def

    def getTypeName(self) -> str:
        """``"Car"`` or ``"Solid"``."""
        return "Car" if self._kind == "car" else "Solid"

    def getField(self, name: str) -> Optional["Field"]:
        """The field ``"translation"`` or ``"rotation"`` (the ones a supervisor sets here),
        None for any other name (Webots: a field the node does not have)."""
        if name not in ("translation", "rotation"):
            return None
        return Field(self, name)

    def getPosition(self) -> List[float]:
        """The node's position (m, world)."""
        return list(_native.supervisor_placement(self._kind, self._index)[0])

    def getVelocity(self) -> List[float]:
        """Linear (m/s; a car's at its origin) and angular (rad/s) velocity, world: six
        numbers."""
        _, _, v, w = _native.supervisor_placement(self._kind, self._index)
        return list(v) + list(w)

    def setVelocity(self, velocity: List[float]) -> None:
        """Sets the six numbers of :meth:`getVelocity`. A car's wheels spin at free rolling
        for it and its suspension stops moving. ValueError beyond 200 m/s or 20 rad/s."""
        values = [_c_double(v) for v in velocity]
        if len(values) != 6:
            raise ValueError(f"setVelocity needs 6 numbers, not {len(values)}")
        _native.supervisor_set_velocity(self._kind, self._index, values[:3], values[3:])

    def resetPhysics(self) -> None:
        """Stops the node: no velocity, no wheel spin, no suspension motion."""
        _native.supervisor_set_velocity(self._kind, self._index, [0.0] * 3, [0.0] * 3)

    def __repr__(self) -> str:
        return f"<Node {self._def}>"


class Field:
    """A node's ``translation`` (``SFVec3f``, m) or ``rotation`` (``SFRotation``: axis and
    angle in rad) field, from :meth:`Node.getField`. Setting one moves the node at once,
    keeping the other (a car keeps its velocity in its own frame, its suspension deflection
    and steering)."""

    SF_VEC3F = 5
    SF_ROTATION = 6

    def __init__(self, node: Node, name: str) -> None:
        self._node = node
        self._name = name

    def getName(self) -> str:
        return self._name

    def getType(self) -> int:
        """``SF_VEC3F`` for translation, ``SF_ROTATION`` for rotation."""
        return Field.SF_VEC3F if self._name == "translation" else Field.SF_ROTATION

    def _pose(self):
        translation, rotation, _, _ = _native.supervisor_placement(
            self._node._kind, self._node._index
        )
        return list(translation), list(rotation)

    def _check(self, name: str) -> None:
        if self._name != name:
            raise TypeError(f"the field {self._name} is not of the type of get/set{name}")

    def getSFVec3f(self) -> List[float]:
        """The translation (m)."""
        self._check("translation")
        return self._pose()[0]

    def setSFVec3f(self, value: List[float]) -> None:
        """Moves the node to ``value`` (m); ValueError beyond 10 km or for NaN."""
        self._check("translation")
        values = [_c_double(v) for v in value]
        if len(values) != 3:
            raise ValueError(f"setSFVec3f needs 3 numbers, not {len(values)}")
        _native.supervisor_set_pose(
            self._node._kind, self._node._index, values, self._pose()[1]
        )

    def getSFRotation(self) -> List[float]:
        """The rotation: unit axis and angle (rad, in [0, π])."""
        self._check("rotation")
        return self._pose()[1]

    def setSFRotation(self, value: List[float]) -> None:
        """Turns the node to ``value`` (axis of any non-zero length, angle in rad)."""
        self._check("rotation")
        values = [_c_double(v) for v in value]
        if len(values) != 4:
            raise ValueError(f"setSFRotation needs 4 numbers, not {len(values)}")
        _native.supervisor_set_pose(
            self._node._kind, self._node._index, self._pose()[0], values
        )


class Device:
    """A device of the robot (Webots: ``controller.Device``)."""

    def __init__(self, name: str, tag: int) -> None:
        self._name = name
        self._tag = tag

    def getName(self) -> str:
        """The device name, e.g. ``"right_steer"``."""
        return self._name

    def getModel(self) -> str:
        """The device's ``model`` field: ``""`` for every device here."""
        return ""

    def getNodeType(self) -> int:
        """Its node type (``Node.GPS``...)."""
        return _native.wb_device_get_node_type(self._tag)

    @property
    def name(self) -> str:
        """The device name."""
        return self._name

    def __repr__(self) -> str:
        return f"Device({self._name!r})"


class _Sensor(Device):
    """A sensor: enable, disable and the sampling period (ms), shared by every kind."""

    _kind = ""

    def enable(self, samplingPeriod: int) -> None:
        """Samples every ``samplingPeriod`` ms (negative: Webots' error, ignored); the first
        sample comes one full period later, the values are NaN before it."""
        _native.sensor_enable(self._kind, self._tag, _c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops sampling; the last sample stays readable (with Webots' error)."""
        _native.sensor_disable(self._kind, self._tag)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.sensor_get_sampling_period(self._kind, self._tag)


class GPS(_Sensor):
    """Webots' ``GPS``: the device's world position (m; x east, y north, z up, plus the world's
    ``gpsReference``; or latitude °, longitude °, altitude m when its ``gpsCoordinateSystem`` is
    ``"WGS84"``) and velocity (m/s)."""

    _kind = "gps"
    LOCAL = 0
    WGS84 = 1

    def getValues(self) -> List[float]:
        """The position ``[x, y, z]`` (m), or ``[latitude, longitude, altitude]`` (°, °, m)."""
        return list(_native.wb_gps_get_values(self._tag) or [])

    def getSpeed(self) -> float:
        """The speed (m/s)."""
        return _native.wb_gps_get_speed(self._tag)

    def getSpeedVector(self) -> List[float]:
        """The velocity ``[vx, vy, vz]`` (m/s, world axes)."""
        return list(_native.wb_gps_get_speed_vector(self._tag) or [])

    def getCoordinateSystem(self) -> int:
        """The world's ``gpsCoordinateSystem``: ``GPS.LOCAL`` or ``GPS.WGS84``."""
        return _native.wb_gps_get_coordinate_system(self._tag)

    @staticmethod
    def convertToDegreesMinutesSeconds(decimal: float) -> str:
        """``"D° M′ S″"`` of a decimal angle (degrees), each part truncated as Webots does."""
        return _native.wb_gps_convert_to_degrees_minutes_seconds(_c_double(decimal))


class InertialUnit(_Sensor):
    """Webots' ``InertialUnit``: the device's orientation in the ENU world."""

    _kind = "inertial_unit"

    def getRollPitchYaw(self) -> List[float]:
        """``[roll, pitch, yaw]`` (rad); yaw 0 with the x axis east, π/2 north."""
        return list(_native.wb_inertial_unit_get_roll_pitch_yaw(self._tag))

    def getQuaternion(self) -> List[float]:
        """The orientation quaternion ``[x, y, z, w]``."""
        return list(_native.wb_inertial_unit_get_quaternion(self._tag) or [])

    def getNoise(self) -> float:
        """The ``noise`` field."""
        return _native.wb_inertial_unit_get_noise(self._tag)


class _Triaxial(_Sensor):
    """A three-axis sensor with a lookup table."""

    def getValues(self) -> List[float]:
        """The three values in the device's axes (NaN on a disabled axis)."""
        return list(_native.triaxial_get_values(self._kind, self._tag) or [])

    def getLookupTable(self) -> List[float]:
        """The ``lookupTable``, flat: ``[input, output, noise]`` row after row."""
        return _native.triaxial_get_lookup_table(self._kind, self._tag)


class Gyro(_Triaxial):
    """Webots' ``Gyro``: angular velocity (rad/s)."""

    _kind = "gyro"


class Accelerometer(_Triaxial):
    """Webots' ``Accelerometer``: specific force (m/s², +9.81 on z upright at rest)."""

    _kind = "accelerometer"


class Compass(_Triaxial):
    """Webots' ``Compass``: the north direction (world +y) in the device's axes."""

    _kind = "compass"


class CameraRecognitionObject:
    """An object a camera's Recognition reports (Webots: ``CameraRecognitionObject``):
    positions and sizes in m in the camera frame (x forward, y left, z up), the orientation as
    axis-angle ``[x, y, z, angle]`` (rad), image values in pixels from the top-left corner."""

    def __init__(self, fields: tuple) -> None:  # type: ignore[type-arg]
        (
            self._id,
            self._position,
            self._orientation,
            self._size,
            self._position_on_image,
            self._size_on_image,
            self._colors,
            self._model,
        ) = fields

    def getId(self) -> int:
        """The object's id."""
        return self._id

    def getPosition(self) -> List[float]:
        """Its centre (m, camera frame)."""
        return list(self._position)

    def getOrientation(self) -> List[float]:
        """Its orientation relative to the camera, ``[x, y, z, angle]``."""
        return list(self._orientation)

    def getSize(self) -> List[float]:
        """Its extent along the camera's y and z (m)."""
        return list(self._size)

    def getPositionOnImage(self) -> List[int]:
        """The centre of its rectangle on the image (px)."""
        return list(self._position_on_image)

    def getSizeOnImage(self) -> List[int]:
        """The width and height of its rectangle on the image (px)."""
        return list(self._size_on_image)

    def getNumberOfColors(self) -> int:
        """How many recognition colours it has."""
        return len(self._colors)

    def getColors(self) -> List[float]:
        """Its recognition colours, flat: ``[r, g, b]`` after ``[r, g, b]``."""
        return [c for rgb in self._colors for c in rgb]

    def getModel(self) -> str:
        """Its ``model``."""
        return self._model

    def __repr__(self) -> str:
        return f"CameraRecognitionObject(id={self._id}, position={self._position})"


class Camera(Device):
    """Webots' ``Camera``: a BGRA image of the world through a planar pinhole, rendered by
    the engine (the world's boxes, ramps, cars, robots and ground), and its Recognition."""

    def enable(self, samplingPeriod: int) -> None:
        """Renders every ``samplingPeriod`` ms; the first image comes one period later."""
        _native.wb_camera_enable(self._tag, _c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops rendering."""
        _native.wb_camera_enable(self._tag, 0)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.wb_camera_get_sampling_period(self._tag)

    def getImage(self) -> Optional[bytes]:
        """The last image: BGRA bytes, row-major from the top-left (``None``, with Webots'
        error, while disabled)."""
        return _native.wb_camera_get_image(self._tag)

    def getImageArray(self) -> Optional[List[List[List[int]]]]:
        """The last image as ``[x][y][r, g, b]`` (Webots' layout: column first)."""
        image = self.getImage()
        if image is None:
            return None
        w, h = self.getWidth(), self.getHeight()
        return [
            [
                [image[4 * (y * w + x) + 2], image[4 * (y * w + x) + 1], image[4 * (y * w + x)]]
                for y in range(h)
            ]
            for x in range(w)
        ]

    def getWidth(self) -> int:
        """The image width (px)."""
        return _native.wb_camera_get_size(self._tag)[0]

    def getHeight(self) -> int:
        """The image height (px)."""
        return _native.wb_camera_get_size(self._tag)[1]

    def getFov(self) -> float:
        """The horizontal field of view (rad)."""
        return _native.wb_camera_get_optics(self._tag)[0]

    def getMinFov(self) -> float:
        """The smallest field of view (rad): the field of view, there being no Zoom."""
        return _native.wb_camera_get_optics(self._tag)[1]

    def getMaxFov(self) -> float:
        """The largest field of view (rad): the field of view, there being no Zoom."""
        return _native.wb_camera_get_optics(self._tag)[2]

    def getNear(self) -> float:
        """The near plane (m)."""
        return _native.wb_camera_get_optics(self._tag)[3]

    def saveImage(self, filename: str, quality: int) -> int:
        """Saves the last image as a PNG file (``quality`` is for JPEG, not written here):
        0, or -1 with Webots' error."""
        return _native.wb_camera_save_image(self._tag, str(filename), _c_int(quality))

    def hasRecognition(self) -> bool:
        """True if the camera has a Recognition node."""
        return _native.wb_camera_has_recognition(self._tag)

    def recognitionEnable(self, samplingPeriod: int) -> None:
        """Recognises objects every ``samplingPeriod`` ms."""
        _native.wb_camera_recognition_enable(self._tag, _c_int(samplingPeriod))

    def recognitionDisable(self) -> None:
        """Stops recognising."""
        _native.wb_camera_recognition_enable(self._tag, 0)

    def getRecognitionSamplingPeriod(self) -> int:
        """Recognition's sampling period (ms), 0 when disabled."""
        return _native.wb_camera_recognition_get_sampling_period(self._tag)

    def getRecognitionNumberOfObjects(self) -> int:
        """How many objects the last Recognition sample found."""
        return _native.wb_camera_recognition_get_number_of_objects(self._tag)

    def getRecognitionObjects(self) -> List[CameraRecognitionObject]:
        """The objects of the last Recognition sample."""
        return [
            CameraRecognitionObject(o)
            for o in _native.wb_camera_recognition_get_objects(self._tag)
        ]

    def hasRecognitionSegmentation(self) -> bool:
        """False: no segmentation image is rendered."""
        return _native.wb_camera_recognition_has_segmentation(self._tag)

    @staticmethod
    def imageGetRed(image: bytes, width: int, x: int, y: int) -> int:
        """The red channel of pixel (x, y) of a BGRA image ``width`` pixels wide."""
        return image[4 * (y * width + x) + 2]

    @staticmethod
    def imageGetGreen(image: bytes, width: int, x: int, y: int) -> int:
        """The green channel of pixel (x, y)."""
        return image[4 * (y * width + x) + 1]

    @staticmethod
    def imageGetBlue(image: bytes, width: int, x: int, y: int) -> int:
        """The blue channel of pixel (x, y)."""
        return image[4 * (y * width + x)]

    @staticmethod
    def imageGetGray(image: bytes, width: int, x: int, y: int) -> int:
        """The mean of the three channels of pixel (x, y), truncated."""
        k = 4 * (y * width + x)
        return (image[k] + image[k + 1] + image[k + 2]) // 3

    imageGetGrey = imageGetGray


class ImageRef:
    """An image held by the display library (Webots: ``ImageRef``)."""

    def __init__(self, handle: int) -> None:
        self._handle = handle


class Display(Device):
    """Webots' ``Display``: an image to draw into (pixels (0, 0) top-left, opaque black at
    first; colour ``0xRRGGBB``, alpha and opacity in [0, 1], blended as Webots does). Text
    draws with a bitmap font whatever the family; no camera attachment; image files are
    PNG."""

    RGB = 3
    RGBA = 4
    ARGB = 5
    BGRA = 6
    ABGR = 7

    def getWidth(self) -> int:
        """Width (px)."""
        return _native.wb_display_get_size(self._tag)[0]

    def getHeight(self) -> int:
        """Height (px)."""
        return _native.wb_display_get_size(self._tag)[1]

    def setColor(self, color: int) -> None:
        """The drawing colour, ``0xRRGGBB``."""
        _native.wb_display_set_color(self._tag, _c_int(color))

    def setAlpha(self, alpha: float) -> None:
        """The alpha of what is drawn (0: transparent)."""
        _native.wb_display_set_alpha(self._tag, _c_double(alpha))

    def setOpacity(self, opacity: float) -> None:
        """The weight of what is drawn against what was there."""
        _native.wb_display_set_opacity(self._tag, _c_double(opacity))

    def drawPixel(self, x: int, y: int) -> None:
        """Draws pixel (x, y)."""
        _native.wb_display_draw(self._tag, "pixel", [_c_int(x), _c_int(y)])

    def drawLine(self, x1: int, y1: int, x2: int, y2: int) -> None:
        """Draws a line (Bresenham)."""
        _native.wb_display_draw(self._tag, "line", [_c_int(v) for v in (x1, y1, x2, y2)])

    def drawRectangle(self, x: int, y: int, width: int, height: int) -> None:
        """Draws a rectangle's outline, top-left (x, y)."""
        _native.wb_display_draw(self._tag, "rectangle", [_c_int(v) for v in (x, y, width, height)])

    def fillRectangle(self, x: int, y: int, width: int, height: int) -> None:
        """Fills a rectangle, top-left (x, y)."""
        _native.wb_display_draw(
            self._tag, "fill_rectangle", [_c_int(v) for v in (x, y, width, height)]
        )

    def drawOval(self, cx: int, cy: int, a: int, b: int) -> None:
        """Draws an ellipse's outline of centre (cx, cy) and radii a, b."""
        _native.wb_display_draw(self._tag, "oval", [_c_int(v) for v in (cx, cy, a, b)])

    def fillOval(self, cx: int, cy: int, a: int, b: int) -> None:
        """Fills an ellipse of centre (cx, cy) and radii a, b."""
        _native.wb_display_draw(self._tag, "fill_oval", [_c_int(v) for v in (cx, cy, a, b)])

    def drawPolygon(self, x: List[int], y: List[int]) -> None:
        """Draws the closed polygon of corners (x[i], y[i])."""
        _native.wb_display_polygon(self._tag, [_c_int(v) for v in x], [_c_int(v) for v in y], False)

    def fillPolygon(self, x: List[int], y: List[int]) -> None:
        """Fills the polygon of corners (x[i], y[i])."""
        _native.wb_display_polygon(self._tag, [_c_int(v) for v in x], [_c_int(v) for v in y], True)

    def setFont(self, font: str, size: int, antiAliasing: bool) -> None:
        """The font of ``drawText``: one of Webots' 13 families (all drawn with the same
        bitmap font), ``size`` the character height (px, > 0); ``antiAliasing`` changes
        nothing on a bitmap font."""
        _native.wb_display_set_font(self._tag, str(font), _c_int(size), bool(antiAliasing))

    def drawText(self, text: str, x: int, y: int) -> None:
        """Draws ``text`` with its top-left corner at (x, y); ``\\n`` starts a new line."""
        _native.wb_display_draw_text(self._tag, str(text), _c_int(x), _c_int(y))

    def imageNew(
        self, data: bytes, format: int, width: Optional[int] = None, height: Optional[int] = None
    ) -> Optional[ImageRef]:
        """An image from ``data`` (``width * height`` pixels of ``format``; without sizes:
        the display's)."""
        w = self.getWidth() if width is None else _c_int(width)
        h = self.getHeight() if height is None else _c_int(height)
        handle = _native.wb_display_image_new(self._tag, w, h, bytes(data), _c_int(format))
        return ImageRef(handle) if handle else None

    def imageCopy(self, x: int, y: int, width: int, height: int) -> Optional[ImageRef]:
        """A copy of a rectangle of the display; None off the display."""
        handle = _native.wb_display_image_copy(
            self._tag, _c_int(x), _c_int(y), _c_int(width), _c_int(height)
        )
        return ImageRef(handle) if handle else None

    def imagePaste(self, ir: ImageRef, x: int, y: int, blend: bool = False) -> None:
        """Pastes ``ir`` with its top-left pixel at (x, y), over what is there by its alpha
        if ``blend``."""
        _native.wb_display_image_paste(self._tag, ir._handle, _c_int(x), _c_int(y), bool(blend))

    def imageSave(self, ir: Optional[ImageRef], filename: str) -> None:
        """Saves ``ir`` (None: the display itself) as a PNG file."""
        _native.wb_display_image_save(self._tag, ir._handle if ir else 0, str(filename))

    def imageLoad(self, filename: str) -> Optional[ImageRef]:
        """The image of a PNG file; None (with Webots' error) if it cannot be read."""
        handle = _native.wb_display_image_load(self._tag, str(filename))
        return ImageRef(handle) if handle else None

    def imageDelete(self, ir: ImageRef) -> None:
        """Frees ``ir``."""
        _native.wb_display_image_delete(self._tag, ir._handle)


class Keyboard:
    """Webots' ``Keyboard``: the keys the world's programme presses
    (``[[vehicle.programme]] at = 2.0, key = "A"``); there is no window to type in. A press is
    held by the keyboard's first sample at or after its time; ``getKey`` returns the keys of
    the last sample in turn, then -1."""

    END = 312
    HOME = 313
    LEFT = 314
    UP = 315
    RIGHT = 316
    DOWN = 317
    PAGEUP = 366
    PAGEDOWN = 367
    NUMPAD_HOME = 375
    NUMPAD_LEFT = 376
    NUMPAD_UP = 377
    NUMPAD_RIGHT = 378
    NUMPAD_DOWN = 379
    NUMPAD_END = 382
    KEY = 0x0000FFFF
    SHIFT = 0x00010000
    CONTROL = 0x00020000
    ALT = 0x00040000

    def enable(self, samplingPeriod: int) -> None:
        """Samples the keys every ``samplingPeriod`` ms."""
        _native.wb_keyboard_enable(_c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops sampling the keys."""
        _native.wb_keyboard_enable(0)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.wb_keyboard_get_sampling_period()

    def getKey(self) -> int:
        """The next key (ASCII or a constant above, with the modifier bits), -1 when none
        is left."""
        return _native.wb_keyboard_get_key()

class DistanceSensor(_Sensor):
    """Webots' ``DistanceSensor``: the ``lookupTable``'s value for the distance (m) its rays
    measure (types generic, sonar, laser)."""

    _kind = "distance_sensor"
    GENERIC = 0
    INFRA_RED = 1
    SONAR = 2
    LASER = 3

    def getValue(self) -> float:
        """The value (NaN before the first sample)."""
        return _native.wb_distance_sensor_get_value(self._tag)

    def getMaxValue(self) -> float:
        """The largest value of the lookup table (0 if empty)."""
        return _native.wb_distance_sensor_get_max_value(self._tag)

    def getMinValue(self) -> float:
        """The smallest value of the lookup table (0 if empty)."""
        return _native.wb_distance_sensor_get_min_value(self._tag)

    def getAperture(self) -> float:
        """The ``aperture`` field (rad)."""
        return _native.wb_distance_sensor_get_aperture(self._tag)

    def getLookupTable(self) -> List[float]:
        """The ``lookupTable``, flat: ``[distance, value, noise]`` row after row."""
        return _native.wb_distance_sensor_get_lookup_table(self._tag)

    def getType(self) -> int:
        """The ``type`` (``DistanceSensor.GENERIC``, ``SONAR``, ``LASER``)."""
        return _native.wb_distance_sensor_get_type(self._tag)


class RadarTarget:
    """A target of a :class:`Radar` (Webots: ``controller.RadarTarget``)."""

    def __init__(self, distance: float, received_power: float, speed: float, azimuth: float):
        self.distance = distance
        """Distance (m)."""
        self.received_power = received_power
        """Received power (dBm)."""
        self.speed = speed
        """Radial speed (m/s, positive when the target moves away)."""
        self.azimuth = azimuth
        """Azimuth (rad, positive to the right)."""

    def __repr__(self) -> str:
        return (
            f"RadarTarget(distance={self.distance}, received_power={self.received_power}, "
            f"speed={self.speed}, azimuth={self.azimuth})"
        )


class Radar(_Sensor):
    """Webots' ``Radar``: the other cars and boxes with a ``radarCrossSection`` in its field of
    view."""

    _kind = "radar"

    def getNumberOfTargets(self) -> int:
        """The number of targets of the last sample (0 before the first)."""
        return _native.wb_radar_get_number_of_targets(self._tag)

    def getTargets(self) -> List[RadarTarget]:
        """The targets of the last sample."""
        return [RadarTarget(*t) for t in _native.wb_radar_get_targets(self._tag)]

    def getMinRange(self) -> float:
        """``minRange`` (m)."""
        return _native.radar_get_field("min_range", self._tag)

    def getMaxRange(self) -> float:
        """``maxRange`` (m)."""
        return _native.radar_get_field("max_range", self._tag)

    def getHorizontalFov(self) -> float:
        """``horizontalFieldOfView`` (rad)."""
        return _native.radar_get_field("horizontal_fov", self._tag)

    def getVerticalFov(self) -> float:
        """``verticalFieldOfView`` (rad)."""
        return _native.radar_get_field("vertical_fov", self._tag)


class LidarPoint:
    """A point of a :class:`Lidar`'s point cloud (Webots: ``controller.LidarPoint``)."""

    def __init__(self, x: float, y: float, z: float, layer_id: int, time: float):
        self.x = x
        """Position along the lidar's x axis (m; inf where there is no return)."""
        self.y = y
        """Along its y axis (m)."""
        self.z = z
        """Along its z axis (m)."""
        self.layer_id = layer_id
        """The layer (0 the highest)."""
        self.time = time
        """When the ray was cast (s)."""

    def __repr__(self) -> str:
        return (
            f"LidarPoint(x={self.x}, y={self.y}, z={self.z}, layer_id={self.layer_id}, "
            f"time={self.time})"
        )


#: The C layout of ``WbLidarPoint``: three floats, an int, a float (20 bytes).
_POINT = struct.Struct("=fffif")


class Lidar(_Sensor):
    """Webots' ``Lidar`` (fixed type): range images (m, ``inf`` where nothing lies within
    ``[minRange, maxRange)``), layer 0 the highest, column 0 the leftmost; and point clouds."""

    _kind = "lidar"

    def enablePointCloud(self) -> None:
        """Computes the point cloud from each range image."""
        _native.lidar_set_point_cloud(self._tag, True)

    def disablePointCloud(self) -> None:
        """Stops computing the point cloud."""
        _native.lidar_set_point_cloud(self._tag, False)

    def isPointCloudEnabled(self) -> bool:
        """True if the point cloud is computed."""
        return _native.wb_lidar_is_point_cloud_enabled(self._tag)

    def getRangeImage(self, data_type: str = "list") -> Union[List[float], bytes, None]:
        """The range image, ``horizontalResolution`` values per layer: a list, or with
        ``data_type="buffer"`` the C array's bytes (floats)."""
        image = _native.wb_lidar_get_range_image(self._tag)
        if image is None or data_type == "list":
            return image
        if data_type == "buffer":
            return struct.pack(f"={len(image)}f", *image)
        raise ValueError(f"data_type must be 'list' or 'buffer', not {data_type!r}")

    def getRangeImageArray(self) -> Optional[List[List[float]]]:
        """The range image as one list per layer."""
        image = _native.wb_lidar_get_range_image(self._tag)
        if image is None:
            return None
        width = self.getHorizontalResolution()
        return [image[i : i + width] for i in range(0, len(image), width)]

    def getLayerRangeImage(self, layer: int) -> Optional[List[float]]:
        """The range image of ``layer`` (None, with Webots' error, for a layer it lacks or a
        disabled lidar)."""
        return _native.wb_lidar_get_layer_range_image(self._tag, _c_int(layer))

    @staticmethod
    def _points(points, data_type: str):
        if points is None:
            return None
        if data_type == "list":
            return [LidarPoint(*p) for p in points]
        if data_type == "buffer":
            return b"".join(_POINT.pack(*p) for p in points)
        raise ValueError(f"data_type must be 'list' or 'buffer', not {data_type!r}")

    def getPointCloud(self, data_type: str = "list"):
        """The point cloud: :class:`LidarPoint` objects, or with ``data_type="buffer"`` the C
        array's bytes (``WbLidarPoint``); None if the lidar or its cloud is disabled."""
        return self._points(_native.wb_lidar_get_point_cloud(self._tag), data_type)

    def getLayerPointCloud(self, layer: int, data_type: str = "list"):
        """The points of ``layer``."""
        points = _native.wb_lidar_get_layer_point_cloud(self._tag, _c_int(layer))
        return self._points(points, data_type)

    def getNumberOfPoints(self) -> int:
        """``horizontalResolution · numberOfLayers`` (0 if the lidar or its cloud is disabled)."""
        return _native.lidar_get_count("number_of_points", self._tag)

    def getHorizontalResolution(self) -> int:
        """``horizontalResolution``."""
        return _native.lidar_get_count("horizontal_resolution", self._tag)

    def getNumberOfLayers(self) -> int:
        """``numberOfLayers``."""
        return _native.lidar_get_count("number_of_layers", self._tag)

    def getFrequency(self) -> float:
        """The frequency (Hz)."""
        return _native.lidar_get_field("frequency", self._tag)

    def setFrequency(self, frequency: float) -> None:
        """Sets the frequency (Hz), within ``[minFrequency, maxFrequency]``."""
        _native.wb_lidar_set_frequency(self._tag, _c_double(frequency))

    def getMinFrequency(self) -> float:
        """``minFrequency`` (Hz)."""
        return _native.lidar_get_field("min_frequency", self._tag)

    def getMaxFrequency(self) -> float:
        """``maxFrequency`` (Hz)."""
        return _native.lidar_get_field("max_frequency", self._tag)

    def getFov(self) -> float:
        """``fieldOfView`` (rad)."""
        return _native.lidar_get_field("fov", self._tag)

    def getVerticalFov(self) -> float:
        """``verticalFieldOfView`` (rad)."""
        return _native.lidar_get_field("vertical_fov", self._tag)

    def getMinRange(self) -> float:
        """``minRange`` (m)."""
        return _native.lidar_get_field("min_range", self._tag)

    def getMaxRange(self) -> float:
        """``maxRange`` (m)."""
        return _native.lidar_get_field("max_range", self._tag)


class RoadSensor(Device):
    """The project's RoadSensor extension (``type = "RoadSensor"`` in the world file; no
    Webots device measures roads): where the device is in its lane, in the lane's travel
    direction. Offsets and distances in m (offset positive left of the lane centre,
    distances positive inside the lane or road), heading error in rad (positive pointing
    left), curvatures in 1/m (positive turning left); NaN before the first sample and off
    the roads. C: the ``vehicle_road_sensor_*`` functions of ``webots/vehicle/road_sensor.h``."""

    NODE_TYPE = 1000

    def enable(self, samplingPeriod: int) -> None:
        """Samples every ``samplingPeriod`` ms; the first sample comes one period later."""
        _native.vehicle_road_sensor_enable(self._tag, _c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops sampling; the last sample stays readable (with an error)."""
        _native.vehicle_road_sensor_disable(self._tag)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.vehicle_road_sensor_get_sampling_period(self._tag)

    def _number(self, which: str) -> float:
        return _native.vehicle_road_sensor_get_number(self._tag, which)

    def getLookahead(self) -> float:
        """The ``lookahead`` field (m)."""
        return self._number("lookahead")

    def getRoad(self) -> int:
        """The road's index (0: the world's first ``[[road]]``), -1 off the roads."""
        return _native.vehicle_road_sensor_get_place(self._tag, "road")

    def getLane(self) -> int:
        """The lane (1, 2, ... left of the reference line, -1, -2, ... right), 0 off the
        roads."""
        return _native.vehicle_road_sensor_get_place(self._tag, "lane")

    def getStation(self) -> float:
        """The station along the road (m)."""
        return self._number("station")

    def getLateralOffset(self) -> float:
        """The offset from the lane centre (m, positive left)."""
        return self._number("lateral_offset")

    def getHeadingError(self) -> float:
        """The heading minus the lane's travel direction (rad, positive left)."""
        return self._number("heading_error")

    def getCurvature(self) -> float:
        """The lane's curvature at the device (1/m, positive turning left)."""
        return self._number("curvature")

    def getCurvatureAhead(self) -> float:
        """The lane's curvature ``lookahead`` m ahead (1/m)."""
        return self._number("curvature_ahead")

    def getLeftLineDistance(self) -> float:
        """The distance to the lane's left line (m, positive inside)."""
        return self._number("left_line_distance")

    def getRightLineDistance(self) -> float:
        """The distance to the lane's right line (m, positive inside)."""
        return self._number("right_line_distance")

    def getLeftEdgeDistance(self) -> float:
        """The distance to the road's left edge (m, positive on the road)."""
        return self._number("left_edge_distance")

    def getRightEdgeDistance(self) -> float:
        """The distance to the road's right edge (m, positive on the road)."""
        return self._number("right_edge_distance")

    def getLaneWidth(self) -> float:
        """The lane's width (m)."""
        return self._number("lane_width")


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


class Supervisor(Robot):
    """A robot with supervisor rights (Webots: ``controller.Supervisor``): Webots' subset for
    placing things (COMPATIBILITY.md): :meth:`getFromDef` finds a car (DEF = its ``name``) or
    a dynamic body (``body[1]``, ``body[2]``, ... in the world file's order), whose
    ``translation``/``rotation`` fields and velocity it reads and sets, and
    :meth:`simulationReset` puts the world back as loaded."""

    def getFromDef(self, name: str) -> Optional[Node]:
        """The node of DEF name ``name``, None if there is none."""
        found = _native.supervisor_node_from_def(str(name))
        return None if found is None else Node(found[0], found[1], str(name))

    def simulationReset(self) -> None:
        """The world back as loaded: time 0, every car and body where the world file put
        them, the other cars' programmes from their start. The controller goes on, its
        devices enabled as it left them."""
        _native.supervisor_simulation_reset()
