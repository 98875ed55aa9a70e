"""Writes an OpenDRIVE file with an independent tool, PyPI's ``scenariogeneration``, and that
tool's own view of its geometry, as fixtures of ``sim/tests/opendrive_independent.rs``.

Outputs, beside this script:

* ``scenariogeneration.xodr``: one road of a line, a clothoid from straight into a left turn,
  an arc, a clothoid through straight into a right turn, and a line, starting off the origin
  at a heading; two lanes each side of different widths (one widening linearly) with marks.
* ``scenariogeneration.json``: for each geometry the tool wrote, its type, ``s``, length and
  the start and end point and heading as the tool computes them (its ``PlanView``'s adjusted
  geometries; the spirals' ends come from its clothoid library, ``pyclothoids``), and the
  lanes' ids and width polynomials.

The file header's ``date`` (the tool writes the time of the run) is set to a fixed value so
that a re-run gives the same bytes: ``.ci/run`` re-runs this script and fails if the
fixtures changed. Run: ``python sim/tests/opendrive/generate.py [DIR]`` (``pip install
scenariogeneration==0.16.7``, the version the fixtures were written with).
"""

import json
import math
import re
import sys
from pathlib import Path

from scenariogeneration import xodr

# The outputs' directory: this script's, or the one given as the first argument (.ci/run
# writes a fresh pair there and compares it with the committed one).
OUT = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent
XODR = OUT / "scenariogeneration.xodr"
JSON = OUT / "scenariogeneration.json"
FIXED_DATE = "2026-11-28T00:00:00"
# Stations (m) at which the lanes' widths are given, as the tool evaluates them.
WIDTH_STATIONS = [0.0, 100.0, 230.0]


def road() -> xodr.Road:
    plan = xodr.PlanView(x_start=12.5, y_start=-4.0, h_start=0.3)
    plan.add_geometry(xodr.Line(50.0))
    plan.add_geometry(xodr.Spiral(0.0, 0.02, length=40.0))
    plan.add_geometry(xodr.Arc(0.02, length=60.0))
    plan.add_geometry(xodr.Spiral(0.02, -0.01, length=50.0))
    plan.add_geometry(xodr.Line(30.0))

    mark = xodr.RoadMark(xodr.RoadMarkType.solid, 0.15)
    broken = xodr.RoadMark(xodr.RoadMarkType.broken, 0.12)
    centre = xodr.Lane(lane_type=xodr.LaneType.median)
    centre.add_roadmark(xodr.RoadMark(xodr.RoadMarkType.solid, 0.15))
    section = xodr.LaneSection(0, centre)
    for a, b, m in [(3.5, 0.0, broken), (3.25, 0.0, mark)]:
        lane = xodr.Lane(a=a, b=b)
        lane.add_roadmark(m)
        section.add_left_lane(lane)
    for a, b, m in [(3.75, 0.0, broken), (2.0, 0.004, mark)]:
        lane = xodr.Lane(a=a, b=b)
        lane.add_roadmark(m)
        section.add_right_lane(lane)
    lanes = xodr.Lanes()
    lanes.add_lanesection(section)
    return xodr.Road(1, plan, lanes)


def main() -> None:
    r = road()
    odr = xodr.OpenDrive("scenariogeneration fixture")
    odr.add_road(r)
    odr.adjust_roads_and_lanes()
    odr.write_xml(str(XODR))
    text = re.sub(r'date="[^"]*"', f'date="{FIXED_DATE}"', XODR.read_text(), count=1)
    XODR.write_text(text)

    geometries = []
    for g in r.planview._adjusted_geometries:
        x, y, h, length = g.get_end_data()
        geometries.append(
            {
                "type": type(g.geom_type).__name__,
                "s": g.s,
                "length": length,
                "start": {"x": g.x, "y": g.y, "heading": g.heading},
                "end": {"x": x, "y": y, "heading": h},
            }
        )
    section = r.lanes.lanesections[0]
    lanes = [
        {"id": lane.lane_id, "widths": {str(s): lane.get_width(s) for s in WIDTH_STATIONS}}
        for lane in section.leftlanes + section.rightlanes
    ]
    out = {
        "tool": "scenariogeneration",
        "geometries": geometries,
        "lanes": lanes,
        "total_length": sum(g["length"] for g in geometries),
    }
    assert all(math.isfinite(v) for g in geometries for p in ("start", "end") for v in g[p].values())
    JSON.write_text(json.dumps(out, indent=2) + "\n")


if __name__ == "__main__":
    main()
