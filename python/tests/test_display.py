"""Drawing into a car's Display through Webots' Python API (controller.Display), in a
controller process as Webots starts one. The pixels each primitive gives are the engine's
(tested in sim/src/devices/display.rs); here: the calls, image handles and misuse messages."""

import json

from conftest import run_controller

WORLD = """
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Display"
width = 16
height = 8
"""

SCRIPT = """
import json
from controller import Display, Robot
robot = Robot()
display = robot.getDevice("display")
display.setColor(0xFF0000)
display.setAlpha(1.0)
display.setOpacity(0.5)
display.drawPixel(1, 1)
display.drawLine(0, 7, 15, 7)
display.drawRectangle(0, 0, 4, 4)
display.fillRectangle(4, 4, 2, 2)
display.drawOval(10, 3, 3, 2)
display.fillOval(10, 3, 1, 1)
display.drawPolygon([0, 4, 0], [0, 0, 4])
display.fillPolygon([0, 4, 0], [0, 0, 4])
copy = display.imageCopy(0, 0, 4, 4)
off = display.imageCopy(20, 20, 2, 2)
made = display.imageNew(bytes([255, 0, 0]), Display.RGB, 1, 1)
display.imagePaste(copy, 12, 4, True)
display.imagePaste(made, 0, 0)
display.imageDelete(copy)
import os
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "display.png")
display.imageSave(None, path)
loaded = display.imageLoad(path)
print("call: bad colour", flush=True)
display.setColor(-1)
robot.step(10)
print(json.dumps({"kind": type(display).__name__, "size": [display.getWidth(), display.getHeight()],
                  "copy": copy is not None, "off": off is None, "made": made is not None,
                  "loaded": loaded is not None}))
"""


def test_display_draws_and_reports_misuse(tmp_path):
    world = tmp_path / "display.toml"
    world.write_text(WORLD)
    script = tmp_path / "display.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    *calls, last = out.stdout.splitlines()
    r = json.loads(last)
    assert calls == ["call: bad colour"]
    assert out.stderr.splitlines() == [
        "Error: wb_display_set_color(): color must be in [0, 0xFFFFFF]."
    ]
    assert r == {
        "kind": "Display",
        "size": [16, 8],
        "copy": True,
        "off": True,
        "made": True,
        "loaded": True,
    }
    assert (tmp_path / "display.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
