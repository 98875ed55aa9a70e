"""What Webots' sensors share: enable, disable and the sampling period; and the three-axis
sensors' values and lookup table."""

from typing import List

from webots_vehicle import _native

from ._c import _c_int
from .device import Device


class _Sensor(Device):
    """A sensor: enable, disable and the sampling period (ms), shared by every kind."""

    _kind = ""

    def enable(self, samplingPeriod: int) -> None:
        """Samples every ``samplingPeriod`` ms (negative: Webots' error, ignored); the first
        sample comes one full period later, the values are NaN before it."""
        _native.sensor_enable(self._kind, self._tag, _c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops sampling; the last sample stays readable (with Webots' error)."""
        _native.sensor_disable(self._kind, self._tag)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.sensor_get_sampling_period(self._kind, self._tag)


class _Triaxial(_Sensor):
    """A three-axis sensor with a lookup table."""

    def getValues(self) -> List[float]:
        """The three values in the device's axes (NaN on a disabled axis)."""
        return list(_native.triaxial_get_values(self._kind, self._tag) or [])

    def getLookupTable(self) -> List[float]:
        """The ``lookupTable``, flat: ``[input, output, noise]`` row after row."""
        return _native.triaxial_get_lookup_table(self._kind, self._tag)
