"""The camera of a world file's car through Webots' Python API (controller.Camera and
CameraRecognitionObject), in its own process as Webots starts a controller."""

import json

from conftest import run_controller

# A BmwX5 at the origin heading east with a 64 x 32 camera 4.5 m ahead of its rear axle, and a
# red box whose face towards the camera is 10 m ahead of it (x = 14.5 m, y in [-1, 1], z in
# [0, 2]); a cyan box behind the car.
WORLD = """
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Camera"
translation = [4.5, 0, 0.6]
width = 64
height = 32
fieldOfView = 1.0
recognition = { maxRange = 50 }
[[box]]
translation = [15, 0, 1]
size = [1, 2, 2]
color = [0.8, 0.2, 0.1]
recognitionColors = [[1, 0, 0]]
[[box]]
translation = [-10, 0, 1]
size = [1, 4, 2]
color = [0, 1, 1]
recognitionColors = [[0, 1, 1]]
"""

SCRIPT = """
import json
from controller import Camera, Robot
from webots_vehicle import camera_image
robot = Robot()
camera = robot.getDevice("camera")
print("call: disabled", flush=True)
before = camera.getImage()
camera.enable(20)
camera.recognitionEnable(20)
robot.step(10)
robot.step(10)
image = camera.getImage()
w, h = camera.getWidth(), camera.getHeight()
objects = camera.getRecognitionObjects()
array = camera.getImageArray()
view = camera_image(camera)
out = {
    "kind": type(camera).__name__,
    "before": before,
    "size": [w, h, len(image)],
    "fov": camera.getFov(),
    "near": camera.getNear(),
    "centre": [
        Camera.imageGetRed(image, w, w // 2, h // 2),
        Camera.imageGetGreen(image, w, w // 2, h // 2),
        Camera.imageGetBlue(image, w, w // 2, h // 2),
        Camera.imageGetGray(image, w, w // 2, h // 2),
    ],
    "array_centre": array[w // 2][h // 2],
    "numpy": [list(view.shape), [int(c) for c in view[h // 2, w // 2]]],
    "count": camera.getRecognitionNumberOfObjects(),
    "objects": [
        {
            "position": o.getPosition(),
            "size": o.getSize(),
            "colors": o.getColors(),
            "n": o.getNumberOfColors(),
            "model": o.getModel(),
            "on_image": o.getPositionOnImage(),
        }
        for o in objects
    ],
}
print(json.dumps(out))
"""


def test_camera_image_and_recognition(tmp_path):
    world = tmp_path / "camera.toml"
    world.write_text(WORLD)
    script = tmp_path / "camera.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    *calls, last = out.stdout.splitlines()
    r = json.loads(last)
    assert calls == ["call: disabled"]
    assert out.stderr.splitlines() == [
        "Error: wb_camera_get_image() called for a disabled device! Please use: "
        "wb_camera_enable()."
    ]
    assert r["kind"] == "Camera" and r["before"] is None
    assert r["size"] == [64, 32, 64 * 32 * 4]
    assert r["fov"] == 1.0 and r["near"] == 0.01
    # The box's face towards the camera, turned away from the light: half its colour,
    # 0.5 x (0.8, 0.2, 0.1) x 255 rounded = (102, 26, 13); gray (102 + 26 + 13) // 3 = 47.
    assert r["centre"] == [102, 26, 13, 47]
    assert r["array_centre"] == [102, 26, 13]
    assert r["numpy"] == [[32, 64, 4], [13, 26, 102, 255]]  # rows, columns, BGRA
    # The red box alone (the cyan one is behind the camera), 10.5 m ahead of the camera
    # (+- 5 cm: the car settles by millimetres), centred, 2 m x 2 m.
    assert r["count"] == 1 and len(r["objects"]) == 1
    o = r["objects"][0]
    assert abs(o["position"][0] - 10.5) < 0.05 and abs(o["position"][1]) < 0.01
    assert all(abs(s - 2.0) < 0.01 for s in o["size"])
    assert o["colors"] == [1.0, 0.0, 0.0] and o["n"] == 1 and o["model"] == ""
    assert abs(o["on_image"][0] - 32) <= 1
