"""Webots' ``Radar`` (``controller.Radar``)."""

from typing import List

from webots_vehicle import _native

from .radar_target import RadarTarget
from .sensor import _Sensor


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
