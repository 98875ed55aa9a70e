"""The ray devices of a world file's car through Webots' Python API (controller.Radar,
RadarTarget, Lidar, LidarPoint, DistanceSensor), in the world of the C test
(capi/tests/worlds/rays.toml): a parked car 30 m ahead with a radar cross-section of 10 m², a
lidar tilted 0.2 rad down at the ground, a distance sensor facing a box 5 m to the left."""

import json
import math
import struct

from conftest import ROOT, run_controller

WORLD = ROOT / "capi" / "tests" / "worlds" / "rays.toml"

SCRIPT = """
import json
from controller import DistanceSensor, Lidar, LidarPoint, Radar, RadarTarget, Robot
robot = Robot()
gps = robot.getDevice("gps")
radar = robot.getDevice("radar")
lidar = robot.getDevice("lidar")
left = robot.getDevice("left")
kinds = [type(d).__name__ for d in (radar, lidar, left)]
print("call: disabled radar", flush=True)
before = radar.getTargets()
for d in (gps, radar, lidar, left):
    d.enable(10)
lidar.enablePointCloud()
for _ in range(200):
    robot.step(10)
print("call: bad layer", flush=True)
bad = lidar.getLayerRangeImage(3)
print("call: wrong tag", flush=True)
wrong = DistanceSensor("radar", radar._tag).getValue()
targets = radar.getTargets()
cloud = lidar.getPointCloud()
out = {
    "kinds": kinds,
    "before": len(before),
    "bad": bad,
    "wrong": str(wrong),
    "gps": gps.getValues(),
    "targets": [[t.distance, t.received_power, t.speed, t.azimuth] for t in targets],
    "count": radar.getNumberOfTargets(),
    "fov": [radar.getHorizontalFov(), radar.getMaxRange(), lidar.getFov(), lidar.getMaxRange()],
    "image": lidar.getRangeImage(),
    "array": lidar.getRangeImageArray(),
    "buffer": lidar.getRangeImage(data_type="buffer").hex(),
    "cloud": [[p.x, p.y, p.z, p.layer_id, p.time] for p in cloud],
    "cloud_buffer": lidar.getPointCloud(data_type="buffer").hex(),
    "points": lidar.getNumberOfPoints(),
    "distance": left.getValue(),
    "type": left.getType(),
    "table": left.getLookupTable(),
}
from webots_vehicle import devices
image = devices.range_image(lidar)
points = devices.point_cloud(lidar)
found = devices.radar_targets(radar)
out["numpy"] = {
    "image": [list(image.shape), image.dtype.str, image[0].tolist() == out["image"]],
    "points": [points.dtype.itemsize, points["z"].tolist() == [p[2] for p in out["cloud"]]],
    "targets": [found.shape[0], found["distance"].tolist() == [t[0] for t in out["targets"]]],
}
print(json.dumps(out))
"""


def test_ray_devices(tmp_path):
    script = tmp_path / "rays.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(WORLD))
    assert out.returncode == 0, out.stderr
    *calls, last = out.stdout.splitlines()
    r = json.loads(last)
    assert calls == ["call: disabled radar", "call: bad layer", "call: wrong tag"]
    assert out.stderr.splitlines() == [
        "Error: wb_radar_get_targets() called for a disabled device! Please use: wb_radar_enable().",
        "Error: wb_lidar_get_layer_range_image() called with a 'layer' argument (3) bigger or "
        "equal to the number of layers of this lidar (1).",
        "Error: wb_distance_sensor_get_value(): invalid device tag.",
    ]
    assert r["kinds"] == ["Radar", "Lidar", "DistanceSensor"]
    assert r["before"] == 0 and r["bad"] is None and r["wrong"] == "nan"
    assert r["fov"] == [0.78, 50.0, 0.8, 30.0]
    # One target 30 m ahead, parked (a few mrad of pitch and roll: the tolerances), with the
    # radar equation's power for 20 dBm, 20 dBi, 24 GHz and 10 m² (1e-9: the same formula).
    assert r["count"] == 1
    d, power, speed, azimuth = r["targets"][0]
    assert abs(d - 30.0) < 0.05 and abs(speed) < 0.01 and abs(azimuth) < 0.005
    lam = 0.299792458 / 24.0
    pr = 0.1 * 100.0**2 * lam**2 * 10.0 / ((4 * math.pi) ** 3 * d**4)
    assert abs(power - 10 * math.log10(pr / 0.001)) < 1e-9
    # Every lidar ray meets the ground at h / sin(0.2) (5 cm: the body's pitch); the array is
    # the image by layer, the buffer its floats, the cloud the image converted.
    h = r["gps"][2]
    image = r["image"]
    assert len(image) == 9 and all(abs(v - h / math.sin(0.2)) < 0.05 for v in image)
    assert r["array"] == [image]
    assert list(struct.unpack("=9f", bytes.fromhex(r["buffer"]))) == image
    assert r["points"] == 9
    for j, (x, y, z, layer, _) in enumerate(r["cloud"]):
        theta = 0.4 - (j + 0.5) * 0.8 / 9
        # 1e-4 m: the conversion is done in f64 and stored in f32.
        assert abs(x - image[j] * math.cos(theta) * math.cos(-0.2)) < 1e-4
        assert abs(y - image[j] * math.sin(theta) * math.cos(-0.2)) < 1e-4
        assert abs(z - image[j] * math.sin(-0.2)) < 1e-4
        assert layer == 0
    unpacked = [list(p) for p in struct.iter_unpack("=fffif", bytes.fromhex(r["cloud_buffer"]))]
    assert unpacked == r["cloud"]
    # The distance sensor: 100·(5 − y) by its table (1 cm of roll: ±1).
    assert abs(r["distance"] - 100.0 * (5.0 - r["gps"][1])) < 1.0
    assert r["type"] == 0 and r["table"] == [0.0, 0.0, 0.0, 10.0, 1000.0, 0.0]
    # webots_vehicle.devices: the same samples as numpy arrays.
    assert r["numpy"] == {
        "image": [[1, 9], "<f4", True],
        "points": [20, True],
        "targets": [1, True],
    }
