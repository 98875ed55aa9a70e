"""Webots' ``RadarTarget`` (``controller.RadarTarget``)."""


class RadarTarget:
    """A target of a :class:`Radar` (Webots: ``controller.RadarTarget``)."""

    def __init__(self, distance: float, received_power: float, speed: float, azimuth: float):
        self.distance = distance
        """Distance (m)."""
        self.received_power = received_power
        """Received power (dBm)."""
        self.speed = speed
        """Radial speed (m/s, positive when the target moves away)."""
        self.azimuth = azimuth
        """Azimuth (rad, positive to the right)."""

    def __repr__(self) -> str:
        return (
            f"RadarTarget(distance={self.distance}, received_power={self.received_power}, "
            f"speed={self.speed}, azimuth={self.azimuth})"
        )
