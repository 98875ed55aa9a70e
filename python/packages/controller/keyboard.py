"""Webots' ``Keyboard`` (``controller.Keyboard``)."""

from webots_vehicle import _native

from ._c import _c_int


class Keyboard:
    """Webots' ``Keyboard``: the keys the world's programme presses
    (``[[vehicle.programme]] at = 2.0, key = "A"``); there is no window to type in. A press is
    held by the keyboard's first sample at or after its time; ``getKey`` returns the keys of
    the last sample in turn, then -1."""

    END = 312
    HOME = 313
    LEFT = 314
    UP = 315
    RIGHT = 316
    DOWN = 317
    PAGEUP = 366
    PAGEDOWN = 367
    NUMPAD_HOME = 375
    NUMPAD_LEFT = 376
    NUMPAD_UP = 377
    NUMPAD_RIGHT = 378
    NUMPAD_DOWN = 379
    NUMPAD_END = 382
    KEY = 0x0000FFFF
    SHIFT = 0x00010000
    CONTROL = 0x00020000
    ALT = 0x00040000

    def enable(self, samplingPeriod: int) -> None:
        """Samples the keys every ``samplingPeriod`` ms."""
        _native.wb_keyboard_enable(_c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops sampling the keys."""
        _native.wb_keyboard_enable(0)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.wb_keyboard_get_sampling_period()

    def getKey(self) -> int:
        """The next key (ASCII or a constant above, with the modifier bits), -1 when none
        is left."""
        return _native.wb_keyboard_get_key()
