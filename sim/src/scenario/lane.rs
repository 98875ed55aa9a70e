//! The double-lane-change track (after ISO 3888-1): cone gates and the reference path the
//! driver model follows.

use core::f64::consts::PI;

/// A gate of the track: a lane bounded by cones on both sides, along x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneSection {
    /// Where the gate starts, along the track (m from the track entry).
    pub start: f64,
    /// Where it ends (m from the track entry).
    pub end: f64,
    /// Lateral position of the lane's centre line (m, positive = left).
    pub center: f64,
    /// Width between the cones (m).
    pub width: f64,
}

impl LaneSection {
    /// How far (m) the point `(x, y)` (track frame) is outside this lane: 0 inside it or
    /// beyond its ends.
    pub fn excursion(&self, x: f64, y: f64) -> f64 {
        if x < self.start || x > self.end {
            return 0.0;
        }
        ((y - self.center).abs() - self.width / 2.0).max(0.0)
    }
}

/// Length of the entry gate, the first transition, the offset gate, the return transition
/// and the exit gate (m): ISO 3888-1 sections 1 to 5 and 6 merged.
const SECTIONS: [f64; 5] = [15.0, 30.0, 25.0, 25.0, 30.0];

/// The three gates of a double lane change for a vehicle `vehicle_width` wide (m), with the
/// offset lane `offset` to the left (m, between lane centre lines): ISO 3888-1 widths
/// 1.1·w + 0.25, 1.2·w + 0.25 and 1.3·w + 0.25 m.
///
/// ```
/// use sim::scenario::double_lane_change;
/// let gates = double_lane_change(1.878, 3.5);
/// assert_eq!((gates[1].start, gates[1].end, gates[1].center), (45.0, 70.0, 3.5));
/// assert!((gates[0].width - 2.3158).abs() < 1e-9); // 1.1·1.878 + 0.25
/// ```
pub fn double_lane_change(vehicle_width: f64, offset: f64) -> [LaneSection; 3] {
    let [s1, s2, s3, s4, s5] = SECTIONS;
    let lane = |start: f64, length: f64, center: f64, factor: f64| LaneSection {
        start,
        end: start + length,
        center,
        width: factor * vehicle_width + 0.25,
    };
    [
        lane(0.0, s1, 0.0, 1.1),
        lane(s1 + s2, s3, offset, 1.2),
        lane(s1 + s2 + s3 + s4, s5, 0.0, 1.3),
    ]
}

/// Total length of the track (m).
pub(crate) const TRACK_LENGTH: f64 =
    SECTIONS[0] + SECTIONS[1] + SECTIONS[2] + SECTIONS[3] + SECTIONS[4];

/// The reference path's lateral position (m) at `x` along the track: the lane centres joined
/// by half-cosine transitions, so the path's heading is continuous.
pub(crate) fn reference_y(x: f64, offset: f64) -> f64 {
    let [s1, s2, s3, s4, _] = SECTIONS;
    let blend = |u: f64| 0.5 * (1.0 - (PI * u.clamp(0.0, 1.0)).cos());
    if x < s1 + s2 {
        offset * blend((x - s1) / s2)
    } else {
        offset * (1.0 - blend((x - s1 - s2 - s3) / s4))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_path_joins_the_lane_centres() {
        let gates = double_lane_change(1.9, 3.5);
        for g in gates {
            for x in [g.start, 0.5 * (g.start + g.end), g.end] {
                assert!((reference_y(x, 3.5) - g.center).abs() < 1e-12, "x = {x}");
            }
        }
        // Mid-transition: half the offset.
        assert!((reference_y(30.0, 3.5) - 1.75).abs() < 1e-12);
        assert!((reference_y(82.5, 3.5) - 1.75).abs() < 1e-12);
        assert_eq!(TRACK_LENGTH, 125.0);
    }

    #[test]
    fn excursion_outside_a_gate() {
        let g = LaneSection {
            start: 45.0,
            end: 70.0,
            center: 3.5,
            width: 2.5,
        };
        assert_eq!(g.excursion(50.0, 3.5), 0.0);
        assert_eq!(g.excursion(50.0, 4.75), 0.0);
        assert!((g.excursion(50.0, 5.0) - 0.25).abs() < 1e-12);
        assert!((g.excursion(50.0, 1.0) - 1.25).abs() < 1e-12);
        assert_eq!(g.excursion(40.0, 0.0), 0.0);
    }
}
