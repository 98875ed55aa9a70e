"""The project's ``RoadSensor`` extension (no Webots device measures roads)."""

from webots_vehicle import _native

from ._c import _c_int
from .device import Device


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
