"""Webots' ``InertialUnit`` (``controller.InertialUnit``)."""

from typing import List

from webots_vehicle import _native

from .sensor import _Sensor


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
