"""Webots' ``Node`` (``controller.Node``): node type numbers and the supervisor's nodes."""

from typing import List, Optional

from webots_vehicle import _native

from ._c import _c_double
from .field import Field


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
