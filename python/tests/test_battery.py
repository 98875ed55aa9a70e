"""Webots' battery sensor through the Python API (controller.Robot.batterySensorEnable ...),
in a controller process as Webots starts one: a TeslaModel3 whose Webots battery field holds
20 kJ of 1 kWh, driven at full throttle until the controller is stopped at 0 energy."""

import json
import math

from conftest import run_controller

WORLD = """
[vehicle]
model = "TeslaModel3"
battery = [20000, 3.6e6, 0]
"""

SCRIPT = """
import json, math
from vehicle import Driver
driver = Driver()
print("call: disabled", flush=True)
disabled = driver.batterySensorGetValue()
driver.batterySensorEnable(30)
readings = []
t = 0
while driver.step() != -1:
    t += 10
    if t == 30:
        driver.setGear(1)
        driver.setThrottle(1.0)
    v = driver.batterySensorGetValue()
    readings.append([t, None if math.isnan(v) else v])
    if t > 30000:
        break
stopped_at = driver.getTime()
again = driver.step()
print(json.dumps({"disabled": None if math.isnan(disabled) else disabled,
                  "period": driver.batterySensorGetSamplingPeriod(),
                  "readings": readings, "stopped_at": stopped_at, "again": again,
                  "time_after": driver.getTime()}))
"""


def test_battery_sensor_samples_and_the_controller_stops_at_zero(tmp_path):
    world = tmp_path / "battery.toml"
    world.write_text(WORLD)
    script = tmp_path / "battery.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    *calls, last = out.stdout.splitlines()
    r = json.loads(last)
    assert calls == ["call: disabled"]
    assert out.stderr.splitlines() == [
        "Error: wb_robot_battery_sensor_get_value() called for a disabled device! Please use: "
        "wb_robot_battery_sensor_enable()."
    ]
    assert r["disabled"] is None and r["period"] == 30
    readings = r["readings"]
    # NaN before the first sample, a full period after enabling at 0.
    assert [v for t, v in readings if t < 30] == [None, None]
    # The first sample, standing without throttle: the field's 20 kJ (the engine's pack holds
    # it at its starting charge to the bisection's resolution, far below 1 mJ).
    assert readings[2][0] == 30
    assert math.isclose(readings[2][1], 20000.0, abs_tol=1e-3)
    samples = [v for t, v in readings if t % 30 == 0]
    # Between samples the reading holds.
    for t, v in readings[3:]:
        if t % 30:
            assert v == samples[t // 30 - 1], t
    # At full throttle every sample is lower than the one before (from the fifth on, once
    # the wheels are driven).
    assert all(b < a for a, b in zip(samples[4:], samples[5:])), samples
    # The controller stopped when the energy reached 0: the last reading is the last sample
    # before (no sensor refreshes once the battery is empty); stepping again returns -1 and
    # time stands.
    assert 0 < readings[-1][1] < 20000
    assert readings[-1][0] < 30000
    assert r["again"] == -1 and r["time_after"] == r["stopped_at"]
