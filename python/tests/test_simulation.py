"""The package's own simulator API: webots_vehicle.Simulation."""

import csv
import json
import math
import os
import subprocess

import numpy as np
import pytest

import webots_vehicle as wv
from conftest import ROOT, WORLDS

# Differences in timing only, and in the files listed: everything else of the JSON object is
# deterministic. The package writes the data files only (the plots need vehicle-sim).
TIMING = {"wall_seconds", "realtime_factor", "files"}


def test_a_scenario_gives_the_metrics_and_telemetry_of_vehicle_sim(vehicle_sim, tmp_path):
    result = wv.Simulation("BmwX5").run("lane-change")
    out = subprocess.run(
        [str(vehicle_sim), "--world", "BmwX5", "--scenario", "lane-change", "--json",
         "--out", str(tmp_path)],
        capture_output=True, text=True, check=True,
    )
    cli = json.loads(out.stdout)
    ours = result.to_dict()
    assert {k: v for k, v in ours.items() if k not in TIMING} == {
        k: v for k, v in cli.items() if k not in TIMING
    }
    assert set(ours) == set(cli)
    assert ours["files"] == [f for f in cli["files"] if not f.endswith(".svg")]
    assert ours["files"] == ["telemetry.csv", "metrics.json", "replay.glb", "report.html"]
    metrics = result.metrics["lane-change"]
    assert metrics == cli["scenarios"]["lane-change"]
    assert metrics["left_track"] is False and 2.0 < metrics["max_lateral_accel_mps2"] < 5.0
    assert result.sim_seconds == metrics["sim_seconds"]

    # The telemetry arrays have the CSV's columns and its values: the CSV rounds to 1e-6
    # (half away from zero, Rust's f64::round), so ours are rounded the same way first.
    with open(tmp_path / "telemetry.csv", newline="") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    telemetry = result.telemetry["lane-change"]
    assert header == ["scenario", "car", *telemetry.columns]
    # The state at time 0, then one sample per 10 ms step.
    assert len(telemetry) == len(rows) == 1 + round(metrics["sim_seconds"] / 0.01)
    scaled = telemetry.to_numpy() * 1e6
    rounded = np.sign(scaled) * np.floor(np.abs(scaled) + 0.5) / 1e6
    expected = np.array([[float(v) if v else math.nan for v in row[2:]] for row in rows])
    np.testing.assert_array_equal(rounded, expected)


def test_a_world_from_a_file_a_model_or_keywords():
    default = wv.Simulation()
    assert (default.source, default.vehicle, default.basic_time_step) == ("<default world>", "BmwX5", 10)
    prius = wv.Simulation("ToyotaPrius")
    assert prius.car.model == "ToyotaPrius" and prius.car.wheelbase == 2.8
    from_file = wv.Simulation(WORLDS / "cruise_8s.toml")
    assert from_file.duration == 8.0 and from_file.source == str(WORLDS / "cruise_8s.toml")
    keywords = wv.Simulation(
        model="TeslaModel3", basicTimeStep=20, duration=2.0, ground={"friction": 0.8},
        vehicle={"wheelbase": 3.0, "tyre": {"model": "webots"}},
    )
    assert keywords.basic_time_step == 20 and keywords.duration == 2.0
    assert keywords.car.model == "TeslaModel3" and keywords.car.wheelbase == 3.0
    with pytest.raises(TypeError):
        wv.Simulation("BmwX5", duration=1.0)


def test_the_brake_balance_is_a_vehicle_key():
    # The default world's stop from 100 km/h (figures of `vehicle-sim --scenario brake`, whose
    # metrics the binding returns unrounded): with Webots' equal brakes the BmwX5 locks its rear
    # wheels and slides 47.00 m; proportioned (front share 0.58) no wheel locks and the brakes
    # stop it in 40.81 m, under the 42.14 m of the brake torque alone (rolling resistance and
    # wheel damping help). A share of 0.5 is Webots' split exactly.
    def stop(**vehicle):
        sim = wv.Simulation(vehicle={"model": "BmwX5", **vehicle})
        return sim.run("brake").metrics["brake"]["stop_distance_m"]

    equal = stop()
    assert equal == pytest.approx(47.0009, abs=1e-3)
    assert stop(brake_balance="proportioned") == pytest.approx(40.8103, abs=1e-3)
    assert stop(brake_balance=0.5) == equal
    with pytest.raises(wv.WorldError) as e:
        stop(brake_balance=1.5)
    assert e.value.key == "vehicle.brake_balance"


def test_a_broken_world_raises_with_the_file_line_and_key():
    with pytest.raises(wv.WorldError) as e:
        wv.Simulation(WORLDS / "misspelt_key.toml")
    assert (e.value.file, e.value.line, e.value.column, e.value.key) == (
        str(WORLDS / "misspelt_key.toml"), 5, 1, "vehicle.wheelbse")
    with pytest.raises(wv.WorldError, match="unknown key 'vehicle.wheelbse'"):
        wv.Simulation(model="BmwX5", vehicle={"wheelbse": 2.0})
    with pytest.raises(wv.WorldError, match="BmwX5"):
        wv.Simulation("BmwX6")


def test_fields_replaced_by_defaults_warn():
    with pytest.warns(wv.VehicleWarning, match="invalid 'wheelbase' value -2"):
        sim = wv.Simulation(model="BmwX5", vehicle={"wheelbase": -2})
    # The Car PROTO's default.
    assert sim.car.wheelbase == 4.0
    assert any("wheelbase" in w for w in sim.warnings)


def test_cars_step_and_record_telemetry_as_numpy_arrays():
    sim = wv.Simulation(model="BmwX5", duration=3.0)
    first = sim.car
    second = sim.add_car("ToyotaPrius", translation=[0, 10, 0.4])
    assert [c.model for c in sim.cars] == ["BmwX5", "ToyotaPrius"]
    assert first.state is None
    first.set_cruising_speed(30)  # km/h
    second.set_throttle(0.5)
    second.set_gear(1)
    second.set_steering_angle(0.1)  # rad, right
    assert sim.step(100) is True
    assert sim.time == pytest.approx(1.0)
    assert sim.run_for(2.0) is False  # the world ends at 3 s
    assert sim.is_over and sim.step() is False and sim.time == pytest.approx(3.0)

    # The state at the start, then one sample per step.
    t1, t2 = first.telemetry, second.telemetry
    assert len(t1) == len(t2) == 301
    assert list(t1.columns) == list(wv.COLUMNS) and len(wv.COLUMNS) == 43
    np.testing.assert_allclose(t1.time_s, np.arange(0, 301) * 0.01, rtol=0, atol=1e-12)
    # Speed mode: no engine model, so no rpm or gear (NaN); torque mode has both.
    assert np.isnan(t1["rpm"]).all() and np.isnan(t1["gear"]).all()
    assert (t2.gear[-50:] == 1).all() and (t2.rpm[-50:] > 0).all()
    assert np.all(np.diff(t1.x_m[:150]) > 0)  # driving forward
    # The second car turns right (positive steering): its heading falls.
    assert t2.yaw_rad[-1] < -0.05
    assert t2.y_m[0] == pytest.approx(10.0, abs=0.01)
    assert first.state["time_s"] == pytest.approx(3.0)
    assert first.state["speed_kmh"] == t1.speed_kmh[-1]

    pandas = pytest.importorskip("pandas")
    frame = t1.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(wv.COLUMNS) and len(frame) == 301
    assert frame["speed_kmh"].iloc[-1] == t1.speed_kmh[-1]


def test_driver_commands_warn_and_clamp_as_the_driver_library_does():
    sim = wv.Simulation("BmwX5")
    with pytest.warns(wv.VehicleWarning, match="NaN"):
        sim.car.set_steering_angle(float("nan"))
    with pytest.warns(wv.VehicleWarning, match="only 6 gears"):
        sim.car.set_gear(10**12)
    with pytest.warns(wv.VehicleWarning, match="'throttle' should be smaller or equal to 1"):
        sim.car.set_throttle(float("inf"))
    sim.step(10)
    state = sim.car.state
    for column in ("x_m", "y_m", "yaw_rad", "speed_kmh", "throttle", "steering_rad"):
        assert math.isfinite(state[column]), column


def test_unknown_scenarios_and_wrong_vehicles_are_errors():
    with pytest.raises(ValueError, match="unknown scenario 'drift'"):
        wv.Simulation().run("drift")
    with pytest.raises(RuntimeError, match="needs a world with one DifferentialWheels robot"):
        wv.Simulation().run("square")
    robot = wv.Simulation(ROOT / "sim" / "worlds" / "e-puck.toml")
    assert robot.vehicle == "DifferentialWheels" and robot.cars == []
    with pytest.raises(IndexError):
        robot.car
    spin = robot.run("spin")
    assert spin.metrics["spin"]["turns"] > 0
    assert set(wv.SCENARIOS) >= {"lane-change", "test-track", "square", "spin", "sine-with-dwell"}


def test_save_writes_the_run_as_vehicle_sim_writes_one(tmp_path):
    sim = wv.Simulation(model="ToyotaPrius", duration=1.0)
    assert sim.save(tmp_path / "empty") == []  # nothing recorded before the first step
    sim.car.set_cruising_speed(20)
    sim.run_for(1.0)
    written = sim.save(tmp_path / "run")
    assert [os.path.basename(p) for p in written] == [
        "telemetry.csv",
        "devices.csv",
        "metrics.json",
        "replay.glb",
        "report.html",
    ]
    # The car has no device: the readings' file is its header alone.
    devices = (tmp_path / "run" / "devices.csv").read_text()
    assert devices == "time,car,device,quantity,value\n"
    with open(tmp_path / "run" / "telemetry.csv", newline="") as f:
        rows = list(csv.reader(f))
    # The header, the start and 100 steps; the values are the telemetry's, rounded to 1e-6.
    assert len(rows) == 102 and rows[1][:2] == ["simulation", "ToyotaPrius"]
    np.testing.assert_allclose(
        [float(r[2]) for r in rows[1:]], sim.car.telemetry.time_s, rtol=0, atol=1e-6
    )
    metrics = json.loads((tmp_path / "run" / "metrics.json").read_text())
    assert metrics["scenario"] == "simulation"
    assert metrics["scenarios"]["simulation"]["vehicles"]["ToyotaPrius"]["distance_m"] > 1.0


def test_cars_are_added_before_the_first_step():
    sim = wv.Simulation(model="BmwX5")
    sim.step()
    with pytest.raises(wv.SimulationError, match="add every vehicle before recording starts"):
        sim.add_car("ToyotaPrius", translation=[0, 10, 0.4])
    # The project's exception is a RuntimeError, as these errors were before it existed.
    assert issubclass(wv.SimulationError, RuntimeError)


def test_the_outputs_world_drives_the_same_car_as_vehicle_sim(vehicle_sim, tmp_path):
    # A BmwX5 on joints, Webots' tyre contact and proportioned brakes: built by the package
    # from the world file, driven with its programme's commands at the same instants, it
    # writes the rows vehicle-sim writes for the programme.
    world = WORLDS / "outputs.toml"
    sim = wv.Simulation(str(world))
    car = sim.car
    car.set_cruising_speed(40)
    sim.run_for(1.5)
    car.set_steering_angle(0.1)
    sim.run_for(1.5)
    car.set_brake_intensity(0.6)
    assert sim.run_for(1.0) is False  # duration = 4 s
    sim.save(tmp_path / "package")
    subprocess.run(
        [str(vehicle_sim), "--world", str(world), "--out", str(tmp_path / "cli")],
        capture_output=True, text=True, check=True,
    )

    def rows(directory):
        with open(directory / "telemetry.csv", newline="") as f:
            return [row[1:] for row in csv.reader(f)][1:]

    package, cli = rows(tmp_path / "package"), rows(tmp_path / "cli")
    assert len(package) == 401
    assert package == cli
