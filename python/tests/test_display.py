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


TEXT_WORLD = """
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Display"
width = 20
height = 16
"""

TEXT_SCRIPT = """
import os
from controller import Robot
robot = Robot()
display = robot.getDevice("display")
display.setFont("Lucida Console", 10, True)
display.drawText("A", 7, 3)
print("call: bad family", flush=True)
display.setFont("Wingdings", 10, True)
display.imageSave(None, os.path.join(os.path.dirname(os.path.abspath(__file__)), "text.png"))
"""

# The 10 px font's "A" (embedded-graphics' 6x10, X11 misc-fixed): '#' drawn.
A_6X10 = [
    "......",
    "..#...",
    ".#.#..",
    "#...#.",
    "#...#.",
    "#####.",
    "#...#.",
    "#...#.",
    "......",
    "......",
]


def _rgba_png(data: bytes):
    """Width, height and rows of RGBA tuples of an 8-bit RGBA, non-interlaced PNG (the
    display's own PNG files), with the five PNG row filters undone."""
    import struct
    import zlib

    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind, body = data[pos + 4 : pos + 8], data[pos + 8 : pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 6, 0)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * 4, [], bytes(width * 4)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 4] if i >= 4 else 0
            b, c = prev[i], (prev[i - 4] if i >= 4 else 0)
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        prev = bytes(line)
        rows.append([tuple(line[4 * x : 4 * x + 4]) for x in range(width)])
    return width, height, rows


def test_draw_text_puts_the_glyph_at_x_y(tmp_path):
    world = tmp_path / "text.toml"
    world.write_text(TEXT_WORLD)
    script = tmp_path / "text.py"
    script.write_text(TEXT_SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == ["call: bad family"]
    assert out.stderr.startswith("Error: wb_display_set_font(): font 'Wingdings' is not one of")
    width, height, rows = _rgba_png((tmp_path / "text.png").read_bytes())
    assert (width, height) == (20, 16)
    white, black = (255, 255, 255, 255), (0, 0, 0, 255)
    # The glyph at (7, 3); every other pixel is still the display's opaque black.
    for y in range(height):
        for x in range(width):
            inside = 7 <= x < 13 and 3 <= y < 13
            drawn = inside and A_6X10[y - 3][x - 7] == "#"
            assert rows[y][x] == (white if drawn else black), (x, y)
