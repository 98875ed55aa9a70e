"""Webots' ``DistanceSensor`` (``controller.DistanceSensor``)."""

from typing import List

from webots_vehicle import _native

from .sensor import _Sensor


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
