"""Sweeps from Python: a sweep file's cases by index, each run into the row that
``vehicle-sim sweep`` writes for it, and ``results.csv`` as a pandas DataFrame.

A sweep file names a base world, a scenario and axes over world-file keys (see the Sweeps
section of ``sim/README.md``). The cases are numbered from 0; a case's values depend on its
index alone (random axes too), so any scheduler can run any case anywhere::

    import webots_vehicle as wv

    sweep = wv.Sweep("examples/sweeps/brake.toml")
    len(sweep)                      # 84 cases
    sweep.case(5)                   # {"ground.friction": 0.6, "vehicle.brakeCoefficient": 750,
                                    #  "vehicle.mass": 2002.3}
    row = sweep.run_case(5)         # {"case": 5, ..., "stop_distance_m": 89.9126, ..., "error": None}
    sweep.run_case_csv(5)           # its line of results.csv, byte for byte

``examples/sweeps/ray_sweep.py`` spreads a sweep over a Ray cluster this way and writes the
``results.csv`` of ``vehicle-sim sweep``.
"""

import os
from typing import Any, Dict, List, Optional, Union

from webots_vehicle import _native

__all__ = ["Sweep", "load_results", "run_case"]

PathLike = Union[str, "os.PathLike[str]"]


class Sweep:
    """A loaded sweep file (a relative ``world`` path is relative to the file). Raises
    :class:`webots_vehicle.WorldError` (with ``file``, ``line``, ``column``, ``key``) when the
    sweep file or its base world is invalid."""

    def __init__(self, path: PathLike) -> None:
        self._core = _native.Sweep(os.fspath(path))

    @classmethod
    def from_text(cls, text: str, name: str = "<sweep>", directory: PathLike = ".") -> "Sweep":
        """A sweep from sweep-file ``text``; ``name`` names it in messages and ``directory`` is
        where a relative ``world`` path starts."""
        sweep = cls.__new__(cls)
        sweep._core = _native.Sweep.parse(name, text, os.fspath(directory))
        return sweep

    def __len__(self) -> int:
        return len(self._core)

    def __repr__(self) -> str:
        return f"Sweep({self.file!r}: {len(self)} cases of {self.scenario})"

    @property
    def file(self) -> str:
        """The sweep file, as given."""
        return self._core.file

    @property
    def world(self) -> str:
        """The base world: its path, or the default world's name."""
        return self._core.world

    @property
    def scenario(self) -> str:
        """The scenario every case runs, e.g. ``"brake"``."""
        return self._core.scenario

    @property
    def fingerprint(self) -> str:
        """The sweep's fingerprint (as in ``sweep.json``): shards of one sweep share it."""
        return self._core.fingerprint

    @property
    def axes(self) -> List[str]:
        """The axes' world-file keys, in the sweep file's order."""
        return self._core.axes

    @property
    def metrics(self) -> List[str]:
        """The metric columns."""
        return self._core.metrics

    @property
    def columns(self) -> List[str]:
        """Every column of ``results.csv``: ``case``, the axes, the metrics, ``notes``,
        ``error``, ``checksum``."""
        return self._core.columns

    @property
    def warnings(self) -> List[str]:
        """The base world's warnings (values it replaced by their defaults)."""
        return self._core.warnings

    def case(self, index: int) -> Dict[str, Any]:
        """Case ``index``'s axis values by key (IndexError past the last case)."""
        return dict(zip(self.axes, self._core.values(index)))

    def run_case(self, index: int) -> Dict[str, Any]:
        """Runs case ``index`` and returns its row by column, as ``results.csv`` has it: the
        case index, the axis values, the metrics (float, bool, or None when not measured or
        when the case failed), ``notes`` and ``error`` (None when empty) and ``checksum`` (the
        row's, as ``results.csv`` has it: 16 hexadecimal digits). A case whose world is
        invalid is a row with its ``error``, not an exception. The GIL is released while the
        case runs."""
        values, _ = self._core.run_case(index)
        return dict(zip(self.columns, values))

    def run_case_csv(self, index: int) -> str:
        """Runs case ``index`` and returns its line of ``results.csv`` (with its line end),
        exactly as ``vehicle-sim sweep`` writes it."""
        _, line = self._core.run_case(index)
        return line

    def csv_header(self) -> str:
        """The header line of ``results.csv`` (with its line end)."""
        return self._core.csv_header()

    def shard(self, index: int, count: int) -> range:
        """The cases of shard ``index`` of ``count`` (``vehicle-sim sweep --shard I/N``)."""
        if not 0 <= index < count:
            raise ValueError(f"shard {index}/{count}: need 0 <= index < count")
        return range(index, len(self), count)


def run_case(sweep_file: PathLike, index: int) -> Dict[str, Any]:
    """Loads ``sweep_file`` and runs its case ``index``: :meth:`Sweep.run_case`."""
    return Sweep(sweep_file).run_case(index)


def load_results(path: PathLike, index: Optional[str] = "case") -> Any:
    """``results.csv`` (or the ``results.csv`` of an output directory) as a
    ``pandas.DataFrame`` indexed by ``case`` (``index=None`` keeps it a column). Numbers are
    floats or integers, ``true``/``false`` booleans, empty cells NaN (a metric not measured, or
    every metric of a failed case, whose ``error`` says why); ``notes`` and ``error`` are
    text (NaN when empty), and so is ``checksum`` (16 hexadecimal digits of the row's other
    cells, which ``vehicle-sim sweep-merge`` and ``sweep --resume`` check)."""
    try:
        import pandas
    except ImportError as e:
        raise ImportError(
            "load_results() needs pandas: pip install pandas (or pip install './python[pandas]')"
        ) from e
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "results.csv")
    # notes and error stay text columns even when every cell is empty; a checksum of digits
    # only must not become a number.
    frame = pandas.read_csv(
        path,
        true_values=["true"],
        false_values=["false"],
        dtype={"notes": "object", "error": "object", "checksum": "object"},
    )
    return frame.set_index(index) if index is not None else frame
