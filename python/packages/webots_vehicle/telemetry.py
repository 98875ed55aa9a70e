"""Per-step telemetry as numpy arrays."""

from typing import Any, Dict, Iterator, Sequence, Union

import numpy as np

from webots_vehicle import _native

#: The telemetry columns, in order: those of ``vehicle-sim``'s ``telemetry.csv`` after
#: ``scenario``. Units are in the names (``time_s``, ``x_m``, ``yaw_rad``, ``speed_kmh``,
#: ``lateral_accel_mps2``, ``fr_fx_n``, ...); ``rpm`` is in rpm; ``gear``, ``throttle``,
#: ``brake``, ``*_slip_ratio`` and ``*_friction_use`` have no unit.
COLUMNS: Sequence[str] = tuple(_native.Simulation.columns())


class Telemetry:
    """One sample per step, one float64 array per column (NaN where a quantity does not
    exist: no ``rpm`` or ``gear`` in SPEED mode, no estimated speed before the wheels can be
    measured).

    ``t["speed_kmh"]`` or ``t.speed_kmh`` is a column; ``len(t)`` the number of samples;
    ``t.to_pandas()`` a DataFrame with the same columns (needs pandas).
    """

    def __init__(self, table: Union[bytes, bytearray], name: str = "") -> None:
        data = np.frombuffer(table, dtype=np.float64).reshape(-1, len(COLUMNS))
        # A bytearray (a simulation's telemetry) is taken as it is; bytes are read-only.
        if not data.flags.writeable:
            data = data.copy()
        self._data = data
        self._name = name

    @property
    def name(self) -> str:
        """What was recorded: the scenario name, or ``"car <i> (<model>)"``."""
        return self._name

    @property
    def columns(self) -> Sequence[str]:
        """The column names, in order."""
        return COLUMNS

    def __len__(self) -> int:
        return self._data.shape[0]

    def __contains__(self, column: object) -> bool:
        return column in COLUMNS

    def __iter__(self) -> Iterator[str]:
        return iter(COLUMNS)

    def __getitem__(self, column: str) -> "np.ndarray[Any, np.dtype[np.float64]]":
        try:
            i = COLUMNS.index(column)
        except ValueError:
            raise KeyError(f"no telemetry column {column!r} (columns: {', '.join(COLUMNS)})") from None
        return self._data[:, i]

    def __getattr__(self, column: str) -> "np.ndarray[Any, np.dtype[np.float64]]":
        if column.startswith("_") or column not in COLUMNS:
            raise AttributeError(column)
        return self[column]

    def __repr__(self) -> str:
        return f"<Telemetry {self._name!r}: {len(self)} samples x {len(COLUMNS)} columns>"

    def to_numpy(self) -> "np.ndarray[Any, np.dtype[np.float64]]":
        """All samples as one (samples x columns) array, columns in ``columns`` order."""
        return self._data

    def to_dict(self) -> Dict[str, "np.ndarray[Any, np.dtype[np.float64]]"]:
        """Column name to array."""
        return {c: self[c] for c in COLUMNS}

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame`` with the same columns (ImportError without pandas)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError(
                "Telemetry.to_pandas() needs pandas: pip install pandas "
                "(or pip install './python[pandas]')"
            ) from e
        return pandas.DataFrame(self._data, columns=list(COLUMNS))
