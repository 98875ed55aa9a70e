"""numpy arrays of the ray devices' samples, for controllers that use Webots' ``controller``
classes: a :class:`controller.Lidar`'s range image as a ``(layers, horizontalResolution)``
float32 array and its point cloud as a structured array of ``WbLidarPoint``'s C layout, a
:class:`controller.Radar`'s targets as a structured array. Each call copies the last sample
(m, rad, dBm, s; ``inf`` where a lidar ray has no return)."""

from typing import Optional

import numpy as np

#: ``WbLidarPoint``: x, y, z (m, lidar axes), layer_id, time (s); 20 bytes.
LIDAR_POINT = np.dtype(
    [("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("layer_id", "<i4"), ("time", "<f4")]
)
#: ``WbRadarTarget``: distance (m), received_power (dBm), speed (m/s, > 0 receding),
#: azimuth (rad, > 0 to the right); 32 bytes.
RADAR_TARGET = np.dtype(
    [("distance", "<f8"), ("received_power", "<f8"), ("speed", "<f8"), ("azimuth", "<f8")]
)


def range_image(lidar) -> Optional[np.ndarray]:
    """The lidar's range image, one row per layer (layer 0 the highest, column 0 the
    leftmost); None where ``getRangeImage`` gives None."""
    buffer = lidar.getRangeImage(data_type="buffer")
    if buffer is None:
        return None
    image = np.frombuffer(buffer, dtype="<f4")
    return image.reshape(lidar.getNumberOfLayers(), lidar.getHorizontalResolution())


def point_cloud(lidar) -> Optional[np.ndarray]:
    """The lidar's point cloud as a structured array (fields ``x``, ``y``, ``z``,
    ``layer_id``, ``time``); None if the lidar or its point cloud is disabled."""
    buffer = lidar.getPointCloud(data_type="buffer")
    if buffer is None:
        return None
    return np.frombuffer(buffer, dtype=LIDAR_POINT)


def radar_targets(radar) -> np.ndarray:
    """The radar's targets as a structured array (fields ``distance``, ``received_power``,
    ``speed``, ``azimuth``), empty before the first sample."""
    return np.array(
        [(t.distance, t.received_power, t.speed, t.azimuth) for t in radar.getTargets()],
        dtype=RADAR_TARGET,
    )
