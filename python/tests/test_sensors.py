"""The sensors of a world file's car through Webots' Python API (controller.GPS, InertialUnit,
Gyro, Accelerometer, Compass), each controller in its own process as Webots starts one."""

import json
import math

from conftest import run_controller

WORLD = """
[vehicle]
model = "BmwX5"
rotation = [0, 0, 1, 0.7853981633974483]
[[vehicle.device]]
type = "GPS"
slot = "top"
[[vehicle.device]]
type = "InertialUnit"
[[vehicle.device]]
type = "Gyro"
[[vehicle.device]]
type = "Accelerometer"
lookupTable = [[-20, -2000, 0], [20, 2000, 0]]
[[vehicle.device]]
type = "Compass"
"""

SCRIPT = """
import json, sys
from controller import GPS, Accelerometer, Compass, Device, Gyro, InertialUnit, Node, Robot
robot = Robot()
gps = robot.getDevice("gps")
unit = robot.getDevice("inertial unit")
gyro = robot.getDevice("gyro")
accelerometer = robot.getDevice("accelerometer")
compass = robot.getDevice("compass")
steer = robot.getDevice("right_steer")
kinds = [type(d).__name__ for d in (gps, unit, gyro, accelerometer, compass, steer)]
print("call: disabled", flush=True)
before = gps.getValues()
print("call: negative", flush=True)
gps.enable(-1)
for d in (gps, unit, gyro, accelerometer, compass):
    d.enable(10)
robot.step(10)
first = gps.getSpeed()
for _ in range(299):
    robot.step(10)
print("call: wrong tag", flush=True)
wrong = GPS("compass", compass._tag).getValues()
out = {
    "kinds": kinds,
    "node": [steer.getNodeType(), gps.getNodeType()],
    "count": robot.getNumberOfDevices(),
    "by_index": robot.getDeviceByIndex(27).getName(),
    "hole": robot.getDeviceByIndex(6) is None,
    "before_nan": all(v != v for v in before),
    "period": gps.getSamplingPeriod(),
    "first": first,
    "gps": gps.getValues(),
    "speed": gps.getSpeed(),
    "rpy": unit.getRollPitchYaw(),
    "quaternion": unit.getQuaternion(),
    "gyro": gyro.getValues(),
    "accelerometer": accelerometer.getValues(),
    "table": accelerometer.getLookupTable(),
    "compass": compass.getValues(),
    "wrong": wrong,
    "dms": GPS.convertToDegreesMinutesSeconds(12.625),
}
print(json.dumps(out))
"""


def test_sensors_of_a_car_heading_north_east(tmp_path):
    world = tmp_path / "sensors.toml"
    world.write_text(WORLD)
    script = tmp_path / "sensors.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    *calls, last = out.stdout.splitlines()
    r = json.loads(last)
    assert calls == ["call: disabled", "call: negative", "call: wrong tag"]
    # Webots' messages, in the order of the calls above.
    assert out.stderr.splitlines() == [
        "Error: wb_gps_get_values() called for a disabled device! Please use: wb_gps_enable().",
        "Error: wb_gps_enable() called with negative sampling period.",
        "Error: wb_gps_get_values(): invalid device tag.",
    ]
    assert r["kinds"] == ["GPS", "InertialUnit", "Gyro", "Accelerometer", "Compass", "Device"]
    assert r["node"] == [57, 44]  # ROTATIONAL_MOTOR, GPS (R2023b numbering)
    assert r["count"] == 32 and r["by_index"] == "gps" and r["hole"]
    assert r["before_nan"] and r["period"] == 10
    assert r["wrong"] == []  # NULL in C
    assert r["dms"] == "12° 37′ 30″"
    # The first sample, one period after enabling, is a number: the car settling onto its
    # springs from its start, at most g·10 ms = 0.0981 m/s in its first step.
    assert 0.0 <= r["first"] <= 0.0982
    # A parked car heading north-east (pi/4 from east) after 3 s. Tolerances: 5e-3 for the
    # body's pitch on its springs (3 mrad), 5 (x100) m/s^2 and 1e-3 rad/s for what is left of
    # its settling, 2 cm for the roof slot's position.
    h = math.sqrt(0.5)
    assert abs(r["compass"][0] - h) < 5e-3 and abs(r["compass"][1] - h) < 5e-3
    assert abs(r["rpy"][2] - math.pi / 4) < 5e-3
    assert abs(r["quaternion"][3] - math.cos(math.pi / 8)) < 5e-3
    assert all(abs(w) < 1e-3 for w in r["gyro"])
    assert abs(r["accelerometer"][2] - 981.0) < 5.0
    assert r["table"] == [-20.0, -2000.0, 0.0, 20.0, 2000.0, 0.0]
    assert abs(r["gps"][0] - h) < 0.02 and abs(r["gps"][1] - h) < 0.02
    assert abs(r["speed"]) < 0.01
