"""Sweeps from Python: cases by index, rows identical to vehicle-sim sweep's, results.csv as a
DataFrame, and the Ray example on a local Ray instance."""

import importlib.util
import math
import os
import subprocess
import sys

import pytest

import webots_vehicle as wv
from conftest import ROOT

# 3 frictions (one invalid) x 2 brake torques of a BmwX5 braking from 100 km/h: 6 cases.
SWEEP = """\
world = "BmwX5"
scenario = "brake"
[axes]
"ground.friction" = [0.8, -1, 1.0]
"vehicle.brakeCoefficient" = [700, 1400]
"""


@pytest.fixture(scope="module")
def sweep_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("sweep") / "brake.toml"
    path.write_text(SWEEP)
    return path


@pytest.fixture(scope="module")
def cli_results(sweep_file, vehicle_sim, tmp_path_factory):
    """results.csv of `vehicle-sim sweep` on the sweep file."""
    out = tmp_path_factory.mktemp("cli")
    subprocess.run(
        [str(vehicle_sim), "sweep", str(sweep_file), "--out", str(out), "-q"], check=True
    )
    return (out / "results.csv").read_text()


def test_cases_by_index_and_rows_identical_to_the_cli(sweep_file, cli_results):
    sweep = wv.Sweep(sweep_file)
    assert len(sweep) == 6
    assert sweep.scenario == "brake"
    assert sweep.axes == ["ground.friction", "vehicle.brakeCoefficient"]
    assert sweep.columns[:4] == ["case", "ground.friction", "vehicle.brakeCoefficient",
                                 "initial_speed_kmh"]
    assert sweep.columns[-3:] == ["notes", "error", "checksum"]
    assert sweep.case(3) == {"ground.friction": -1, "vehicle.brakeCoefficient": 1400}
    with pytest.raises(IndexError):
        sweep.case(6)
    # Row by row, the CSV lines are the CLI's, byte for byte.
    lines = [sweep.run_case_csv(i) for i in range(len(sweep))]
    assert sweep.csv_header() + "".join(lines) == cli_results
    # The dictionaries hold the same values, typed.
    row = sweep.run_case(5)
    assert list(row) == sweep.columns
    assert row["case"] == 5 and row["ground.friction"] == 1.0
    assert row["vehicle.brakeCoefficient"] == 1400
    assert row["at_rest"] is True and row["error"] is None and row["notes"] is None
    cells = lines[5].rstrip("\n").split(",")
    assert row["checksum"] == cells[-1] and len(cells[-1]) == 16
    for column, cell in zip(sweep.columns[:-1], cells):
        value = row[column]
        if isinstance(value, bool):
            assert cell == str(value).lower()
        elif isinstance(value, (int, float)):
            assert float(cell) == value, column
        else:
            assert value is None and cell == ""
    # A case whose world is invalid: the error names the key; no metric.
    failed = wv.run_case(sweep_file, 2)
    assert failed["error"] == "invalid 'ground.friction': -1: must be finite and >= 0"
    assert all(failed[m] is None for m in sweep.metrics)
    assert list(sweep.shard(1, 4)) == [1, 5]


def test_results_load_as_a_dataframe(sweep_file, vehicle_sim, tmp_path):
    pandas = pytest.importorskip("pandas")
    subprocess.run(
        [str(vehicle_sim), "sweep", str(sweep_file), "--out", str(tmp_path), "-q"], check=True
    )
    frame = wv.load_results(tmp_path)
    assert list(frame.index) == list(range(6))
    assert frame.index.name == "case"
    assert list(frame.columns) == wv.Sweep(sweep_file).columns[1:]
    assert frame["at_rest"].dropna().tolist() == [True] * 4
    failed = frame[frame["error"].notna()]
    assert list(failed.index) == [2, 3]
    assert failed["stop_distance_m"].isna().all()
    ok = frame[frame["error"].isna()]
    # The stronger brake stops sooner on either friction.
    for mu in (0.8, 1.0):
        d = ok[ok["ground.friction"] == mu].set_index("vehicle.brakeCoefficient")["stop_distance_m"]
        assert d[1400] < d[700]
    assert pandas.api.types.is_float_dtype(frame["stop_distance_m"])
    assert frame["notes"].dtype == object and frame["error"].dtype == object
    assert all(isinstance(c, str) and len(c) == 16 for c in frame["checksum"])
    assert math.isclose(frame.loc[0, "initial_speed_kmh"], 99.5, abs_tol=0.5)


def test_sweep_errors_raise_world_error_with_the_location(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('scenario = "brake"\n[axes]\n"vehicle.brakeCoeficient" = [900]\n')
    with pytest.raises(wv.WorldError) as e:
        wv.Sweep(bad)
    assert (e.value.file, e.value.line, e.value.column) == (str(bad), 3, 1)
    assert e.value.key == "vehicle.brakeCoeficient"
    assert "did you mean 'brakeCoefficient'?" in str(e.value)
    with pytest.raises(wv.WorldError, match="cannot read the sweep file"):
        wv.Sweep(tmp_path / "missing.toml")
    s = wv.Sweep.from_text('[axes]\n"ground.friction" = [0.5]\n', "inline")
    assert (len(s), s.scenario, s.world) == (1, "test-track", "<default world>")


def ray_or_skip():
    """Ray, required when WEBOTS_VEHICLE_REQUIRE_RAY is set (as .ci/run does)."""
    if os.environ.get("WEBOTS_VEHICLE_REQUIRE_RAY"):
        import ray  # noqa: F401  (an ImportError fails the test)
    else:
        pytest.importorskip("ray")


def test_ray_example_writes_the_cli_results(sweep_file, cli_results, tmp_path):
    ray_or_skip()
    script = ROOT / "examples" / "sweeps" / "ray_sweep.py"
    out = subprocess.run(
        [sys.executable, str(script), str(sweep_file), "--out", str(tmp_path), "--num-cpus", "2",
         "--cases-per-task", "2", "--in-flight", "2"],
        capture_output=True, text=True, timeout=600,
    )
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "results.csv").read_text() == cli_results


def test_ray_tasks_over_case_indices_in_process(sweep_file, cli_results, tmp_path):
    ray_or_skip()
    import ray

    spec = importlib.util.spec_from_file_location(
        "ray_sweep", ROOT / "examples" / "sweeps" / "ray_sweep.py"
    )
    example = importlib.util.module_from_spec(spec)
    sys.modules["ray_sweep"] = example
    spec.loader.exec_module(example)
    # The example's module is not importable on the workers: ship its functions by value.
    from ray import cloudpickle

    cloudpickle.register_pickle_by_value(example)
    ray.init(num_cpus=2, include_dashboard=False)
    try:
        assert example.run(str(sweep_file), str(tmp_path), cases_per_task=1) == 6
    finally:
        ray.shutdown()
    assert (tmp_path / "results.csv").read_text() == cli_results
