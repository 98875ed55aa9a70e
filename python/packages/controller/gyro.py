"""Webots' ``Gyro`` (``controller.Gyro``)."""

from .sensor import _Triaxial


class Gyro(_Triaxial):
    """Webots' ``Gyro``: angular velocity (rad/s)."""

    _kind = "gyro"
