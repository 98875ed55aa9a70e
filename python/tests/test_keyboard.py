"""The keys a world's programme presses, read through Webots' Python API (controller.Keyboard
from Robot.getKeyboard()), in a controller process as Webots starts one."""

import json

from conftest import run_controller

# 'A' and CONTROL+UP at 50 ms, 'B' at 200 ms.
WORLD = """
[vehicle]
model = "BmwX5"
[[vehicle.programme]]
at = 0.05
key = "A"
[[vehicle.programme]]
at = 0.05
key = "CONTROL+UP"
[[vehicle.programme]]
at = 0.2
key = "b"
"""

SCRIPT = """
import json
from controller import Keyboard, Robot
robot = Robot()
keyboard = robot.getKeyboard()
print("call: disabled", flush=True)
disabled = keyboard.getKey()
keyboard.enable(20)
seen = []
for t in range(10, 260, 10):
    robot.step(10)
    key = keyboard.getKey()
    while key != -1:
        seen.append([t, key])
        key = keyboard.getKey()
print(json.dumps({"disabled": disabled, "seen": seen, "period": keyboard.getSamplingPeriod(),
                  "same": robot.getKeyboard() is keyboard,
                  "up": Keyboard.CONTROL | Keyboard.UP}))
"""


def test_programmed_keys_arrive_at_their_times(tmp_path):
    world = tmp_path / "keys.toml"
    world.write_text(WORLD)
    script = tmp_path / "keys.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    *calls, last = out.stdout.splitlines()
    r = json.loads(last)
    assert calls == ["call: disabled"]
    assert out.stderr.splitlines() == [
        "Error: wb_keyboard_get_key() called for a disabled device! Please use: "
        "wb_keyboard_enable()."
    ]
    assert r["disabled"] == -1 and r["period"] == 20 and r["same"]
    # Samples every 20 ms from enabling at 0: the presses at 50 ms arrive at 60 ms, the one
    # at 200 ms at 200 ms (a letter arrives upper-case), each once.
    assert r["seen"] == [[60, 65], [60, r["up"]], [200, 66]]
