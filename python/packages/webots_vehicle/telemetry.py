"""Per-step telemetry as numpy arrays."""

import importlib
from typing import Any, Dict, Iterator, Optional, Sequence, Union

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
    ``t.latest`` the last sample; ``t.to_pandas()`` / ``t.to_polars()`` a DataFrame with the
    same columns (needs pandas / polars).

    The arrays are read-only. A simulation's telemetry shows the recorded memory itself while
    the run is all in memory (``Simulation(record=N)``, or ``record=True`` up to 16,384
    samples): no copy is made, however often it is read, and the memory stays valid as the
    simulation goes on. Each column is a strided view of the (samples x columns) table, whose
    rows are samples.
    """

    def __init__(self, table: Union[bytes, bytearray, Any, None], name: str = "") -> None:
        if table is None:
            data = np.empty((0, len(COLUMNS)), dtype=np.float64)
        else:
            # A buffer of float64 values, row-major: the recorded rows (_native.TelemetryRows,
            # read-only, no copy), a bytearray read back from a log's temporary file, or bytes
            # (a scenario's table).
            data = np.frombuffer(table, dtype=np.float64).reshape(-1, len(COLUMNS))
        data.flags.writeable = False
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

    @property
    def latest(self) -> Optional[Dict[str, float]]:
        """The last sample (column name to value), None if there is none. O(1); for a
        simulation's car, :attr:`SimCar.state` gives it without building the table."""
        if len(self) == 0:
            return None
        return dict(zip(COLUMNS, self._data[-1].tolist()))

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
        """All samples as one read-only (samples x columns) array, columns in ``columns``
        order (no copy)."""
        return self._data

    def to_dict(self) -> Dict[str, "np.ndarray[Any, np.dtype[np.float64]]"]:
        """Column name to array (views, no copy)."""
        return {c: self[c] for c in COLUMNS}

    def to_pandas(self, copy: bool = False) -> Any:
        """A ``pandas.DataFrame`` with the same columns. Without ``copy`` it is over the same
        memory (pandas keeps the read-only table as its one float64 block): columns can be
        added or replaced, but changing values in place raises ValueError ("read-only");
        ``copy=True`` gives a frame of its own. ImportError without pandas."""
        pandas = _optional("pandas", "to_pandas")
        return pandas.DataFrame(self._data, columns=list(COLUMNS), copy=bool(copy))

    def to_polars(self) -> Any:
        """A ``polars.DataFrame`` with the same columns. Polars keeps each column as one
        contiguous Arrow array and the table's rows are samples, so this copies the values
        once (a column of the table is strided). ImportError without polars."""
        polars = _optional("polars", "to_polars")
        return polars.from_numpy(self._data, schema=list(COLUMNS), orient="row")


def _optional(module: str, method: str) -> Any:
    """The optional dependency ``module``, or an ImportError that says how to install it."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        raise ImportError(
            f"Telemetry.{method}() needs {module}: pip install {module} "
            f"(or pip install './python[{module}]')"
        ) from e
