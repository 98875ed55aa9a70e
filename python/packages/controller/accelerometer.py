"""Webots' ``Accelerometer`` (``controller.Accelerometer``)."""

from .sensor import _Triaxial


class Accelerometer(_Triaxial):
    """Webots' ``Accelerometer``: specific force (m/s², +9.81 on z upright at rest)."""

    _kind = "accelerometer"
