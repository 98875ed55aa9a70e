"""Webots' ``Lidar`` (``controller.Lidar``)."""

import struct
from typing import List, Optional, Union

from webots_vehicle import _native

from ._c import _c_double, _c_int
from .lidar_point import LidarPoint
from .sensor import _Sensor


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
