//! Lanes: the strips beside a road's reference line, their widths, kinds, friction and the
//! lines painted on their outer edges, grouped in lane sections along the road.

use super::profile::Profile;

/// What a lane is for (OpenDRIVE's lane `type`, the kinds this crate tells apart).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LaneKind {
    /// A lane cars drive in.
    Driving,
    /// A hard shoulder.
    Shoulder,
    /// The border of the road (a kerb's or verge's strip).
    Border,
    /// A sidewalk.
    Sidewalk,
    /// Any other kind (parking, biking, median, …): surface, not a driving lane.
    Other,
}

/// How a painted line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    /// One continuous line.
    Solid,
    /// One dashed line: `DASH` m painted, `GAP` m unpainted, repeated.
    Dashed,
    /// Two continuous lines side by side.
    DoubleSolid,
    /// Two dashed lines side by side.
    DoubleDashed,
}

impl LineStyle {
    /// Length of a painted dash (m) and of the gap after it (m), OpenDRIVE's and Webots'
    /// usual 3 m and 9 m; a continuous line is one dash.
    pub const DASH: (f64, f64) = (3.0, 9.0);

    /// True for the dashed styles.
    pub fn is_dashed(self) -> bool {
        matches!(self, LineStyle::Dashed | LineStyle::DoubleDashed)
    }

    /// True for the double styles.
    pub fn is_double(self) -> bool {
        matches!(self, LineStyle::DoubleSolid | LineStyle::DoubleDashed)
    }
}

/// A line painted along a lane's outer edge (for the centre lane, along the reference line).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadMark {
    /// Where it starts, from the start of its lane section (m); it runs to the next mark's
    /// start or the section's end.
    pub s_offset: f64,
    /// Its style.
    pub style: LineStyle,
    /// Its colour (red, green, blue, each 0 to 1): white [1, 1, 1], yellow [1, 0.8, 0].
    pub colour: [f64; 3],
    /// Its width (m, > 0); a double line is two of them with one width between.
    pub width: f64,
}

/// One lane of a lane section.
#[derive(Debug, Clone, PartialEq)]
pub struct Lane {
    /// OpenDRIVE's lane id: 1, 2, … outwards on the left of the reference line, −1, −2, …
    /// on the right (0, the centre lane, has no width and holds the centre line's marks).
    pub id: i32,
    /// What it is for.
    pub kind: LaneKind,
    /// Its width (m) as a function of the station from the lane section's start.
    pub width: Profile,
    /// Its surface's Coulomb friction (dimensionless); `None` = the road's.
    pub friction: Option<f64>,
    /// The lines painted on its outer edge, by start.
    pub marks: Vec<RoadMark>,
}

/// The lanes of a stretch of road, from station `s` to the next section's start.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneSection {
    /// Where it starts (m, station).
    pub s: f64,
    /// Its left lanes, ids 1, 2, … from the reference line outwards.
    pub left: Vec<Lane>,
    /// The marks on the reference line (the centre lane's).
    pub centre_marks: Vec<RoadMark>,
    /// Its right lanes, ids −1, −2, … from the reference line outwards.
    pub right: Vec<Lane>,
}

impl LaneSection {
    /// The lateral positions (m, t, from the lane offset outwards) of the outer edge of each
    /// lane on `side` at `ds` (m) from the section's start: left edges increase, right edges
    /// decrease from `t0`.
    pub fn edges(lanes: &[Lane], ds: f64, t0: f64, sign: f64) -> impl Iterator<Item = f64> + '_ {
        lanes.iter().scan(t0, move |t, lane| {
            *t += sign * lane.width.value(ds).max(0.0);
            Some(*t)
        })
    }

    /// Every lane, left ones then right ones.
    pub fn lanes(&self) -> impl Iterator<Item = &Lane> {
        self.left.iter().chain(&self.right)
    }
}
