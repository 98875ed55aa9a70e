"""Webots' ``Device`` (``controller.Device``): the base of every device."""

from webots_vehicle import _native


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
