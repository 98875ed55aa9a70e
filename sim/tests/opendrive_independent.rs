//! An OpenDRIVE file written by an independent tool, PyPI's `scenariogeneration`
//! (`opendrive/generate.py`), read with `sim::road::opendrive`: its plan view and lane widths
//! against the tool's own computation of them (`opendrive/scenariogeneration.json`).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde_json::Value;
use sim::road::opendrive;

const XODR: &str = include_str!("opendrive/scenariogeneration.xodr");
const JSON: &str = include_str!("opendrive/scenariogeneration.json");

/// Start points and headings (m, rad) are the file's own numbers, written by the tool in
/// Python's shortest round-trip form: they read back to the same f64, so only the last bit of
/// an arithmetic step may differ.
const START_TOLERANCE: f64 = 1e-12;

/// End points (m): both sides evaluate the same closed forms (line, arc) or Fresnel integrals
/// (the clothoid: ours `sim::road`'s, the tool's from `pyclothoids`) in f64, each to about
/// 1e-12 relative over these 40 to 60 m segments; 1e-9 m leaves three orders of magnitude for
/// differences of algorithm, and a wrong formula (a sign, a factor of the curvature rate, an
/// arc's centre) moves an end by centimetres or more.
const END_TOLERANCE: f64 = 1e-9;

/// End headings (rad): the heading is a polynomial in s on both sides, exact to rounding.
const HEADING_TOLERANCE: f64 = 1e-12;

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

#[test]
fn the_plan_view_is_the_tools_own() {
    let imported = opendrive::parse_str("scenariogeneration.xodr", XODR).unwrap();
    let expected: Value = serde_json::from_str(JSON).unwrap();
    let road = imported.network.road("1").expect("road 1");
    let geometries = expected["geometries"].as_array().unwrap();
    assert_eq!(road.segments.len(), geometries.len());
    assert!((road.length() - f(&expected["total_length"])).abs() < START_TOLERANCE);
    for (k, (segment, g)) in road.segments.iter().zip(geometries).enumerate() {
        let start = &g["start"];
        assert!(
            (segment.s - f(&g["s"])).abs() < START_TOLERANCE,
            "geometry {k}: s"
        );
        assert!(
            (segment.length - f(&g["length"])).abs() < START_TOLERANCE,
            "geometry {k}"
        );
        assert!(
            (segment.start.x - f(&start["x"])).abs() < START_TOLERANCE,
            "geometry {k}"
        );
        assert!(
            (segment.start.y - f(&start["y"])).abs() < START_TOLERANCE,
            "geometry {k}"
        );
        assert!((segment.heading - f(&start["heading"])).abs() < START_TOLERANCE);
        let end = segment.end();
        let (x, y, heading) = (
            f(&g["end"]["x"]),
            f(&g["end"]["y"]),
            f(&g["end"]["heading"]),
        );
        let miss = ((end.point.x - x).powi(2) + (end.point.y - y).powi(2)).sqrt();
        assert!(
            miss < END_TOLERANCE,
            "geometry {k} ({}): end {} m from the tool's",
            g["type"],
            miss
        );
        assert!(
            (end.heading - heading).abs() < HEADING_TOLERANCE,
            "geometry {k}: end heading {} against {heading}",
            end.heading
        );
    }
}

#[test]
fn the_lane_widths_are_the_tools_own() {
    let imported = opendrive::parse_str("scenariogeneration.xodr", XODR).unwrap();
    let expected: Value = serde_json::from_str(JSON).unwrap();
    let road = imported.network.road("1").unwrap();
    let lanes = expected["lanes"].as_array().unwrap();
    for lane in lanes {
        let id = lane["id"].as_i64().unwrap() as i32;
        for (station, width) in lane["widths"].as_object().unwrap() {
            let s: f64 = station.parse().unwrap();
            let (_, edges) = road.lane_edges(s);
            let &(_, inner, outer) = edges
                .iter()
                .find(|(l, _, _)| l.id == id)
                .unwrap_or_else(|| panic!("lane {id} at s = {s}"));
            // A polynomial of degree one at most, evaluated in f64 on both sides.
            assert!(
                ((outer - inner).abs() - f(width)).abs() < 1e-12,
                "lane {id} at s = {s}: {} m against {width}",
                (outer - inner).abs()
            );
        }
    }
    // Two lanes each side, as written.
    assert_eq!(lanes.len(), 4);
}
