"""C argument conversions shared by the device classes: Webots' ctypes binding raises TypeError where a value is not an int or a real, and the C API warns about the rest."""

import numbers
import operator


_INT_MIN = -(2**31)
_INT_MAX = 2**31 - 1


def _c_int(value: object) -> int:
    """``value`` as a C ``int``: an integer (TypeError otherwise, as Webots' ctypes binding
    raises), saturated to the ``int`` range so that the C API's range warning applies."""
    return max(_INT_MIN, min(_INT_MAX, operator.index(value)))  # type: ignore[arg-type]


def _c_double(value: object) -> float:
    """``value`` as a C ``double``: a real number (TypeError otherwise, as ctypes raises). NaN
    and infinities pass: the C API refuses them with a warning."""
    if not isinstance(value, numbers.Real):
        raise TypeError(f"a number is required, not {type(value).__name__}")
    return float(value)
