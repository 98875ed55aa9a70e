"""Webots' ``Compass`` (``controller.Compass``)."""

from .sensor import _Triaxial


class Compass(_Triaxial):
    """Webots' ``Compass``: the north direction (world +y) in the device's axes."""

    _kind = "compass"
