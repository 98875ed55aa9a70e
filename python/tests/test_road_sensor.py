"""The project's RoadSensor extension through the Python controller API (controller.RoadSensor),
against the closed forms of a straight road, in its own controller process."""

import json
import math

from conftest import run_controller

# A straight road along x (one 3.5 m lane each way, no borders) and a BmwX5 whose origin is
# at (20, -1.2), 0.55 m left of the right lane's centre, heading 0.05 rad to the left.
WORLD = """
[[road]]
id = "straight"
numberOfLanes = 2
numberOfForwardLanes = 1
width = 7.0
rightBorder = false
leftBorder = false
[[road.segment]]
type = "straight"
length = 200
[vehicle]
model = "BmwX5"
translation = [20, -1.2, 0]
rotation = [0, 0, 1, 0.05]
[[vehicle.device]]
type = "RoadSensor"
name = "lanes"
lookahead = 15
"""

SCRIPT = """
import json
from controller import Robot, RoadSensor
robot = Robot()
lanes = robot.getDevice("lanes")
before = lanes.getLateralOffset()
lanes.enable(10)
robot.step(10)
out = {
    "kind": type(lanes).__name__,
    "before_nan": before != before,
    "period": lanes.getSamplingPeriod(),
    "lookahead": lanes.getLookahead(),
    "road": lanes.getRoad(),
    "lane": lanes.getLane(),
    "station": lanes.getStation(),
    "offset": lanes.getLateralOffset(),
    "heading": lanes.getHeadingError(),
    "curvature": [lanes.getCurvature(), lanes.getCurvatureAhead()],
    "lines": [lanes.getLeftLineDistance(), lanes.getRightLineDistance()],
    "edges": [lanes.getLeftEdgeDistance(), lanes.getRightEdgeDistance()],
    "width": lanes.getLaneWidth(),
}
print(json.dumps(out))
"""


def test_road_sensor_reads_the_straight_road(tmp_path):
    world = tmp_path / "road.toml"
    world.write_text(WORLD)
    script = tmp_path / "road.py"
    script.write_text(SCRIPT)
    out = run_controller(script, str(world))
    assert out.returncode == 0, out.stderr
    r = json.loads(out.stdout.splitlines()[-1])
    # The one read before enabling prints the disabled-device error.
    assert out.stderr.splitlines() == [
        "Error: vehicle_road_sensor_get_lateral_offset() called for a disabled device! "
        "Please use: vehicle_road_sensor_enable()."
    ]
    assert r["kind"] == "RoadSensor" and r["before_nan"] and r["period"] == 10
    assert r["lookahead"] == 15.0 and r["road"] == 0 and r["lane"] == -1
    # The closed forms: 1 cm and 1 mrad, what the parked body's settling in one step leaves.
    assert abs(r["station"] - 20.0) < 0.01
    assert abs(r["offset"] - 0.55) < 0.01
    assert abs(r["heading"] - 0.05) < 1e-3
    assert r["curvature"] == [0.0, 0.0]
    assert abs(r["lines"][0] - 1.2) < 0.01 and abs(r["lines"][1] - 2.3) < 0.01
    assert abs(r["edges"][0] - 4.7) < 0.01 and abs(r["edges"][1] - 2.3) < 0.01
    assert r["width"] == 3.5
    assert not math.isnan(r["offset"])
