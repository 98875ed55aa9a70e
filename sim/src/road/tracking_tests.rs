//! The tracking measurement against closed forms on a straight road and an arc. The
//! nearest-point search is closed-form for lines and arcs, so the tolerance (1e-9 m, 1e-9
//! rad) is rounding only, far inside the 1 mm / 1 mrad the RoadSensor promises.

use core::f64::consts::PI;

use super::*;
use crate::road::{Curve, Road, RoadLink};

const TOL: f64 = 1e-9;

fn net(roads: Vec<Road>) -> RoadNetwork {
    RoadNetwork {
        roads,
        junctions: Vec::new(),
    }
}

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() < TOL, "{what}: {a} vs {b}");
}

#[test]
fn straight_road_right_lane_is_exact() {
    // A 3.5 m lane each way along heading 0.3 rad from (5, −2).
    let h = 0.3;
    let road = Road::two_way("s", Point2::new(5.0, -2.0), h, &[(100.0, Curve::Line)], 3.5).unwrap();
    let n = net(vec![road]);
    let (s, t) = (40.0, -1.0);
    let p = Point2::new(5.0, -2.0)
        + Vector2::new(h.cos(), h.sin()) * s
        + Vector2::new(-h.sin(), h.cos()) * t;
    let at = n.track(&p, h + 0.05, 10.0).unwrap();
    assert_eq!((at.road, at.lane, at.direction), (0, -1, 1.0));
    close(at.s, s, "s");
    close(at.lateral_offset, t + 1.75, "offset"); // left of the centre at t = −1.75 m
    close(at.heading_error, 0.05, "heading error");
    close(
        at.left_line,
        0.0 - t,
        "left line (the centre line at t = 0)",
    );
    close(at.right_line, t + 3.5, "right line (t = −3.5 m)");
    close(at.left_edge, 3.5 - t, "left edge (t = 3.5 m)");
    close(at.right_edge, t + 3.5, "right edge");
    close(at.lane_width, 3.5, "width");
    close(at.curvature, 0.0, "curvature");
    close(at.curvature_ahead, 0.0, "curvature ahead");
    // The same point against the left lane, driven the other way: its travel direction's
    // left is −t, so the point, 2.75 m to the −t side of that lane's centre, is left of it.
    let other = n.track_lane(0, 1, &p, h + PI - 0.02, 10.0).unwrap();
    assert_eq!(other.direction, -1.0);
    close(other.lateral_offset, 1.75 - t, "offset from the left lane");
    close(other.heading_error, -0.02, "heading error against s");
    // Its left line is the centre line (t = 0), crossed by 1 m; its right line is t = 3.5 m.
    close(
        other.left_line,
        t,
        "the left lane's left line, crossed: negative",
    );
    close(other.right_line, 3.5 - t, "its right line");
}

#[test]
fn arc_measurements_match_the_circle() {
    // A left-turning arc of radius 50 m about (0, 50), one 3.5 m lane each way.
    let radius = 50.0;
    let road = Road::two_way(
        "a",
        Point2::origin(),
        0.0,
        &[(
            PI * radius,
            Curve::Arc {
                curvature: 1.0 / radius,
            },
        )],
        3.5,
    )
    .unwrap();
    let n = net(vec![road]);
    let centre = Point2::new(0.0, radius);
    for (theta, t, yaw_error) in [(0.6_f64, -1.2, 0.03), (2.0, -2.9, -0.2), (1.1, 1.0, 0.0)] {
        // At angle θ along the arc the reference point is centre + R·(sin θ, −cos θ); a point
        // at t (left, towards the centre) is at radius R − t.
        let r = radius - t;
        let p = centre + Vector2::new(theta.sin(), -theta.cos()) * r;
        let lane = if t < 0.0 { -1 } else { 1 };
        let dir = travel_direction(lane);
        let yaw = theta + if dir > 0.0 { 0.0 } else { PI } + yaw_error;
        let at = n.track(&p, yaw, 10.0).unwrap();
        assert_eq!(at.lane, lane);
        close(at.s, radius * theta, "s = R·θ");
        close(at.lateral_offset, dir * (t - dir * -1.75), "offset");
        close(at.heading_error, yaw_error, "heading error");
        // The lane centre at t_c is a circle of radius R − t_c; driven along s it turns left,
        // against s right.
        let lane_radius = radius + 1.75 * dir;
        close(at.curvature, dir / lane_radius, "curvature");
        close(
            at.curvature_ahead,
            dir / lane_radius,
            "curvature ahead, still on the arc",
        );
        close(at.lane_width, 3.5, "width");
    }
}

#[test]
fn look_ahead_follows_links_and_stops_at_unlinked_ends() {
    let mut a = Road::two_way("a", Point2::origin(), 0.0, &[(100.0, Curve::Line)], 3.5).unwrap();
    let mut b = Road::two_way(
        "b",
        Point2::new(100.0, 0.0),
        0.0,
        &[(50.0, Curve::Arc { curvature: 0.02 })],
        3.5,
    )
    .unwrap();
    a.successor = Some(RoadLink::Road {
        id: "b".into(),
        contact: ContactPoint::Start,
    });
    b.predecessor = Some(RoadLink::Road {
        id: "a".into(),
        contact: ContactPoint::End,
    });
    let n = net(vec![a, b]);
    n.validate().unwrap();
    assert_eq!(n.advance(0, 95.0, 10.0), (1, 5.0));
    assert_eq!(n.advance(1, 3.0, -10.0), (0, 93.0));
    // b has no successor, a no predecessor: the look-ahead stops at their ends.
    assert_eq!(n.advance(1, 45.0, 10.0), (1, 50.0));
    assert_eq!(n.advance(0, 5.0, -10.0), (0, 0.0));
    let at = n.track(&Point2::new(95.0, -1.75), 0.0, 10.0).unwrap();
    close(at.curvature, 0.0, "on the straight");
    // The right lane's centre, 1.75 m outside the arc: κ / (1 + 1.75·κ).
    close(
        at.curvature_ahead,
        0.02 / (1.0 + 0.02 * 1.75),
        "on the arc 10 m ahead",
    );
}

#[test]
fn off_the_road_and_unknown_lanes_give_none() {
    let road = Road::two_way("s", Point2::origin(), 0.0, &[(100.0, Curve::Line)], 3.5).unwrap();
    let n = net(vec![road]);
    assert!(n.track(&Point2::new(50.0, 4.0), 0.0, 5.0).is_none());
    assert!(n.track(&Point2::new(-1.0, 0.5), 0.0, 5.0).is_none());
    assert!(
        n.track_lane(0, 2, &Point2::new(50.0, 1.0), 0.0, 5.0)
            .is_none()
    );
    assert!(
        n.track_lane(1, 1, &Point2::new(50.0, 1.0), 0.0, 5.0)
            .is_none()
    );
    // Measured against a lane it is not in, a point beyond the road gets negative distances.
    let at = n
        .track_lane(0, -1, &Point2::new(50.0, 4.0), 0.0, 5.0)
        .unwrap();
    close(at.left_edge, -0.5, "0.5 m beyond the left edge");
    close(at.left_line, -4.0, "4 m beyond the centre line");
}
