"""Webots' ``GPS`` (``controller.GPS``)."""

from typing import List

from webots_vehicle import _native

from ._c import _c_double
from .sensor import _Sensor


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
