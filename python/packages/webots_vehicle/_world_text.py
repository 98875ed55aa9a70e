"""Keyword arguments as world-file text, so that ``Simulation(**fields)`` and
``Simulation.add_car(**fields)`` go through the world-file loader (its validation, defaults,
warnings and error messages) instead of a second copy of it."""

import json
import math
import numbers
import os
import re
from typing import Any, Mapping

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def _key(key: object) -> str:
    if not isinstance(key, str):
        raise TypeError(f"world-file keys are strings, not {type(key).__name__} ({key!r})")
    return key if _BARE_KEY.fullmatch(key) else json.dumps(key)


def value(v: Any, where: str) -> str:
    """``v`` as a TOML value; ``where`` (the dotted key) names it in a TypeError."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(v, (str, os.PathLike)):
        # A JSON string literal is a TOML basic string (same escapes, \uXXXX included).
        return json.dumps(os.fspath(v))
    if isinstance(v, Mapping):
        items = ", ".join(f"{_key(k)} = {value(x, f'{where}.{k}')}" for k, x in v.items())
        return "{" + items + "}"
    if hasattr(v, "__iter__"):
        return "[" + ", ".join(value(x, f"{where}[{i}]") for i, x in enumerate(v)) + "]"
    raise TypeError(f"{where}: a {type(v).__name__} cannot go in a world file ({v!r})")


def document(fields: Mapping[str, Any]) -> str:
    """A world file with one top-level ``key = value`` line per field (tables inline)."""
    return "".join(f"{_key(k)} = {value(v, k)}\n" for k, v in fields.items())
