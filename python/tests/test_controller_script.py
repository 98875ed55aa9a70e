"""Webots controller scripts run unchanged, each in its own process with VEHICLE_WORLD, as
Webots starts a controller."""

import csv
import json
import subprocess

from conftest import TESTS, WORLDS, run_controller


def test_a_weaving_cruise_controller_reaches_20_kmh_and_ends_with_the_world():
    out = run_controller(TESTS / "controllers" / "weave.py", str(WORLDS / "cruise_8s.toml"))
    assert out.returncode == 0, out.stderr
    # Every call is valid: the C API prints nothing.
    assert out.stderr == ""
    *lines, last = out.stdout.splitlines()
    rows = [tuple(map(float, line.split())) for line in lines]
    # duration = 8 s at 10 ms steps: the step that reaches 8 s returns -1, so the loop body
    # ran at t = 0.01 ... 7.99 s and the script ends at 8 s.
    assert len(rows) == 799
    assert rows[0][0] == 0.01 and rows[-1][0] == 7.99
    assert last == "end 8.0"
    # 20 +- 1 km/h from 6 s on: the cruise control has settled (time0To100 = 7 s ramps the
    # wheels to 20 km/h in 1.4 s; the weave ends at 3 s). The tolerance is the issue's.
    settled = [v for t, v in rows if t >= 6.0]
    assert settled and all(abs(v - 20.0) <= 1.0 for v in settled), settled[:5]


def test_a_robot_controller_steps_with_its_time_step_until_the_end(tmp_path):
    script = tmp_path / "robot_controller.py"
    script.write_text(
        "from controller import Robot\n"
        "robot = Robot()\n"
        "timestep = int(robot.getBasicTimeStep())\n"
        "steps = 0\n"
        "while robot.step(32) != -1:\n"
        "    steps += 1\n"
        "print(timestep, steps, robot.getTime(), robot.getName())\n"
    )
    out = run_controller(script, str(WORLDS / "cruise_8s.toml"))
    assert out.returncode == 0, out.stderr
    # 32 ms rounds up to 4 steps of 10 ms: 8 s are 200 calls of 40 ms, the 200th returns -1.
    assert out.stdout.split() == ["10", "199", "8.0", "vehicle"]


def test_a_broken_world_ends_the_controller_with_the_world_file_error(tmp_path):
    world = WORLDS / "misspelt_key.toml"
    out = run_controller(TESTS / "controllers" / "weave.py", str(world))
    assert out.returncode == 1
    assert out.stdout == ""
    last = out.stderr.strip().splitlines()[-1]
    assert last == (
        f"webots_vehicle.WorldError: cannot load the world VEHICLE_WORLD={world}: "
        f"{world}:5:1: unknown key 'vehicle.wheelbse'; did you mean 'wheelbase' or 'wheels'?"
    )


def _rows(directory):
    """The telemetry rows of a run's ``telemetry.csv`` without the run's name."""
    with open(directory / "telemetry.csv", newline="") as f:
        return [row[1:] for row in csv.reader(f)][1:]


def test_a_driver_controller_with_vehicle_out_writes_the_outputs_of_its_programme(
    tmp_path, vehicle_sim
):
    # The commands of the world's programme, given through the driver library at the same
    # instants (before the step that starts there).
    script = tmp_path / "programme_controller.py"
    script.write_text(
        "from vehicle import Driver\n"
        "driver = Driver()\n"
        "driver.getDevice('gps').enable(50)\n"
        "done = set()\n"
        "while True:\n"
        "    t = driver.getTime()\n"
        "    if 'speed' not in done:\n"
        "        driver.setCruisingSpeed(40.0); done.add('speed')\n"
        "    if t >= 1.5 - 1e-9 and 'steer' not in done:\n"
        "        driver.setSteeringAngle(0.1); done.add('steer')\n"
        "    if t >= 3.0 - 1e-9 and 'brake' not in done:\n"
        "        driver.setBrakeIntensity(0.6); done.add('brake')\n"
        "    if driver.step() == -1:\n"
        "        break\n"
    )
    world = WORLDS / "outputs.toml"
    out = run_controller(script, str(world), out=tmp_path / "controller")
    assert out.returncode == 0, out.stderr
    assert out.stderr == (
        f"Warning: {world}: the world's programme is not run: the controller drives "
        "(vehicle-sim runs programmes).\n"
    )
    programme = subprocess.run(
        [str(vehicle_sim), "--world", str(world), "--out", str(tmp_path / "programme")],
        capture_output=True,
        text=True,
    )
    assert programme.returncode == 0, programme.stderr
    controller_rows, programme_rows = _rows(tmp_path / "controller"), _rows(tmp_path / "programme")
    assert len(controller_rows) == 401  # 4 s of 10 ms steps, and the start
    assert controller_rows == programme_rows
    metrics = json.loads((tmp_path / "controller" / "metrics.json").read_text())
    assert metrics["scenario"] == "controller"
    assert (tmp_path / "controller" / "replay.glb").read_bytes()[:4] == b"glTF"
    # The GPS the controller enabled: 80 samples in 4 s at 50 ms, 7 values each.
    with open(tmp_path / "controller" / "devices.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["time", "car", "device", "quantity", "value"]
    assert len(rows) == 1 + 80 * 7
    assert rows[1][:4] == ["0.05", "BmwX5", "gps", "x"]
