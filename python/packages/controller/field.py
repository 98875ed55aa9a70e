"""Webots' ``Field`` (``controller.Field``): a supervisor node's translation or rotation."""

from typing import TYPE_CHECKING, List

from webots_vehicle import _native

from ._c import _c_double

if TYPE_CHECKING:  # Node imports Field: only the annotation needs Node here
    from .node import Node


class Field:
    """A node's ``translation`` (``SFVec3f``, m) or ``rotation`` (``SFRotation``: axis and
    angle in rad) field, from :meth:`Node.getField`. Setting one moves the node at once,
    keeping the other (a car keeps its velocity in its own frame, its suspension deflection
    and steering)."""

    SF_VEC3F = 5
    SF_ROTATION = 6

    def __init__(self, node: "Node", name: str) -> None:
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
