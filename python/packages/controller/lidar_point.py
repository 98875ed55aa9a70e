"""Webots' ``LidarPoint`` (``controller.LidarPoint``)."""


class LidarPoint:
    """A point of a :class:`Lidar`'s point cloud (Webots: ``controller.LidarPoint``)."""

    def __init__(self, x: float, y: float, z: float, layer_id: int, time: float):
        self.x = x
        """Position along the lidar's x axis (m; inf where there is no return)."""
        self.y = y
        """Along its y axis (m)."""
        self.z = z
        """Along its z axis (m)."""
        self.layer_id = layer_id
        """The layer (0 the highest)."""
        self.time = time
        """When the ray was cast (s)."""

    def __repr__(self) -> str:
        return (
            f"LidarPoint(x={self.x}, y={self.y}, z={self.z}, layer_id={self.layer_id}, "
            f"time={self.time})"
        )
