"""Telemetry without copies (issue #33): ``Simulation(record=...)``, read-only numpy arrays over
the recorded memory, ``to_pandas``/``to_polars``, and a run recorded with ``record=False`` in
flat memory."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import webots_vehicle as wv
from webots_vehicle.telemetry import COLUMNS

# Rows kept in memory before a `record=True` run moves them to its temporary file
# (sim::telemetry::MEMORY_ROWS).
MEMORY_ROWS = 16_384


def bits(a: np.ndarray) -> np.ndarray:
    """The values' bit patterns: equal bits, NaN included, compare equal."""
    return np.ascontiguousarray(a).view(np.uint64)


def cruising(record, steps):
    sim = wv.Simulation(record=record)
    sim.car.set_cruising_speed(30.0)
    sim.step(steps)
    return sim


@pytest.mark.parametrize("record", [0, -3, 2.5, "10", None, [5]])
def test_a_bad_record_value_is_refused_naming_the_argument(record):
    with pytest.raises(ValueError, match=r"record must be True.*not "):
        wv.Simulation(record=record)


def test_record_accepts_numpy_integers():
    sim = cruising(np.int64(3), 10)
    assert len(sim.car.telemetry) == 3


def test_a_ring_keeps_exactly_the_last_n_samples():
    full = cruising(True, 100).car
    ring = cruising(10, 100).car
    # The t = 0 sample and 100 steps were recorded; the ring holds the last 10, the same
    # values to the bit as the full recording's last 10 (the runs are deterministic).
    assert (ring.samples_recorded, len(ring.telemetry)) == (101, 10)
    assert np.array_equal(bits(ring.telemetry.to_numpy()), bits(full.telemetry.to_numpy()[-10:]))
    assert ring.telemetry.time_s[-1] == full.telemetry.time_s[-1] == pytest.approx(1.0, abs=1e-12)
    latest, state = ring.telemetry.latest, ring.state
    assert np.array_equal(bits(np.array(list(latest.values()))), bits(np.array(list(state.values()))))


def test_record_false_keeps_only_the_last_sample():
    car = cruising(False, 50).car
    assert (car.samples_recorded, len(car.telemetry)) == (51, 0)
    assert car.telemetry.latest is None
    assert car.state["time_s"] == pytest.approx(0.5, abs=1e-12)
    assert car.telemetry.to_numpy().shape == (0, len(COLUMNS))


def test_arrays_share_the_recorded_memory_and_are_read_only():
    sim = cruising(True, 200)
    first, second = sim.car.telemetry, sim.car.telemetry
    # Two reads show the same memory: neither copied the table.
    assert np.shares_memory(first.x_m, second.x_m)
    assert np.shares_memory(first.to_numpy(), second.to_numpy())
    assert first.x_m.__array_interface__["data"][0] == second.x_m.__array_interface__["data"][0]
    column = first.speed_kmh
    assert not column.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        column[0] = 1.0
    # The memory an array shows stays valid and unchanged as the run goes on (the log grows
    # into a new block rather than write where it was shared).
    kept = first.to_numpy().copy()
    sim.step(1000)
    assert np.array_equal(bits(first.to_numpy()), bits(kept))
    assert len(sim.car.telemetry) == 1201


def test_a_released_buffer_releases_the_recorded_memory():
    sim = cruising(True, 10)
    rows = sim._core.telemetry(0)
    held = sys.getrefcount(rows)
    view = memoryview(rows)
    # The buffer holds the rows (and so the engine's block) while it exists, and lets go.
    assert sys.getrefcount(rows) == held + 1
    assert view.readonly and view.format == "d" and view.shape == (11, len(COLUMNS))
    view.release()
    assert sys.getrefcount(rows) == held
    # numpy cannot make a view of it writable: the buffer is read-only.
    with pytest.raises(ValueError):
        np.frombuffer(rows, dtype=np.float64).setflags(write=True)


def test_shared_values_equal_the_copying_path_bit_for_bit():
    steps = MEMORY_ROWS + 1000
    # Kept whole past MEMORY_ROWS samples, the rows move to the temporary file and each read
    # copies them back (a bytearray); a ring of all of them stays in memory, shared.
    copied = cruising(True, steps)
    shared = cruising(steps + 1, steps)
    assert isinstance(copied._core.telemetry(0), bytearray)
    assert isinstance(shared._core.telemetry(0), wv._native.TelemetryRows)
    a, b = copied.car.telemetry, shared.car.telemetry
    assert len(a) == len(b) == steps + 1
    assert np.array_equal(bits(a.to_numpy()), bits(b.to_numpy()))
    assert not a.to_numpy().flags.writeable


def test_to_pandas_is_the_table_over_the_same_memory():
    pandas = pytest.importorskip("pandas")
    t = cruising(True, 300).car.telemetry
    df = t.to_pandas()
    assert isinstance(df, pandas.DataFrame)
    assert list(df.columns) == list(COLUMNS)
    assert np.array_equal(bits(df.to_numpy()), bits(t.to_numpy()))
    assert np.shares_memory(df["x_m"].to_numpy(), t.to_numpy())
    # Columns can be replaced; values changed in place need a frame of its own.
    df["x_m"] = df["x_m"] * 2.0
    assert np.array_equal(bits(df["x_m"].to_numpy()), bits(t.x_m * 2.0))
    with pytest.raises(ValueError, match="read-only"):
        df.iloc[0, 2] = 1.0  # y_m, still the recorded memory
    kept = t.to_numpy().copy()
    own = t.to_pandas(copy=True)
    own.iloc[0, 2] = 1.0
    assert own.iloc[0, 2] == 1.0
    assert np.array_equal(bits(t.to_numpy()), bits(kept))


def test_to_polars_is_the_table():
    polars = pytest.importorskip("polars")
    t = cruising(True, 300).car.telemetry
    df = t.to_polars()
    assert isinstance(df, polars.DataFrame)
    assert df.columns == list(COLUMNS)
    assert np.array_equal(bits(df.to_numpy()), bits(t.to_numpy()))


@pytest.mark.parametrize("library, method", [("pandas", "to_pandas"), ("polars", "to_polars")])
def test_a_missing_dataframe_library_says_how_to_install_it(monkeypatch, library, method):
    t = cruising(True, 5).car.telemetry
    monkeypatch.setitem(sys.modules, library, None)  # import raises ImportError
    with pytest.raises(ImportError, match=f"pip install {library}"):
        getattr(t, method)()


def test_a_long_unrecorded_run_keeps_its_memory_flat():
    steps = 100_000
    # A fresh interpreter: its peak resident set (VmHWM) is this run's alone, not the
    # tests' before it. 100 steps first let the physics make its caches.
    script = textwrap.dedent(
        f"""
        import webots_vehicle as wv

        def peak():
            with open("/proc/self/status") as f:
                line = next(l for l in f if l.startswith("VmHWM:"))
            return int(line.split()[1]) * 1024

        sim = wv.Simulation(record=False)
        sim.car.set_cruising_speed(30.0)
        sim.step(100)
        before = peak()
        sim.step({steps})
        state = sim.car.state
        print(before, peak(), sim.car.samples_recorded, len(sim.car.telemetry), state["time_s"])
        """
    )
    try:
        open("/proc/self/status").close()
    except OSError:
        pytest.skip("no /proc/self/status: the memory bound is checked on Linux only")
    out = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=True
    ).stdout.split()
    before, peak, recorded, held = (int(v) for v in out[:4])
    # The sample at the first step's start and one per step (100 + steps) were recorded.
    assert (recorded, held) == (100 + steps + 1, 0)
    assert float(out[4]) == pytest.approx((100 + steps) * 0.01, abs=1e-9)
    # Holding the run's rows would take 10^5 x 344 B = 34 MB; the bound is half of that, so a
    # leak of one row per step fails it, with room for the allocator's slack.
    print(f"peak RSS {peak >> 20} MB, {before >> 20} MB before the {steps} steps")
    assert peak - before < steps * len(COLUMNS) * 8 // 2, (before, peak)
    # And the bound for the whole interpreter (numpy and the extension loaded: 30 MB
    # on the CI machine, flat over the run).
    assert peak < 50 << 20, peak


ENERGY_COLUMNS = ("wheel_power_w", "battery_power_w", "soc_percent", "fuel_rate_gps", "drag_force_n")


def test_energy_columns_are_the_engines_accounting():
    # The CSV's energy columns, last, with their units in their names (W, W, %, g/s, N).
    assert tuple(COLUMNS[-5:]) == ENERGY_COLUMNS
    sim = wv.Simulation(vehicle={"model": "TeslaModel3", "energy": True, "aero": True})
    car = sim.car
    car.set_gear(1)
    car.set_throttle(1.0)
    sim.step(300)
    t = car.telemetry
    # An electric car at full throttle: at 3 s the battery gives more than the wheels take
    # (the machine's losses), its charge falls from 100 %, it burns no fuel (NaN), and the
    # air pushes back with ½ρCdAv² > 0 once it moves.
    assert t.battery_power_w[-1] > t.wheel_power_w[-1] > 0.0
    assert t.soc_percent[0] == 100.0 and t.soc_percent[-1] < 100.0
    assert np.isnan(t.fuel_rate_gps).all()
    assert np.isnan(t.drag_force_n[0]) and t.drag_force_n[-1] > 0.0
    # A car without energy accounting or air has none of them.
    plain = wv.Simulation(model="BmwX5")
    plain.car.set_cruising_speed(30.0)
    plain.step(10)
    for column in ENERGY_COLUMNS:
        assert np.isnan(plain.car.telemetry[column]).all(), column
