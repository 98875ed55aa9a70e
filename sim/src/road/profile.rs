//! Piecewise cubic functions of the station: a road's elevation (m), superelevation (rad) and
//! lane offset (m), and each lane's width (m), as OpenDRIVE writes them.

/// One cubic piece a + b·ds + c·ds² + d·ds³ from station `s` on (ds = station − s, m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cubic {
    /// Where this piece starts (m, station; for a lane width, from its lane section's start).
    pub s: f64,
    /// Coefficients a (unit of the value), b (per m), c (per m²), d (per m³).
    pub coefficients: [f64; 4],
}

impl Cubic {
    /// A constant piece from `s`.
    pub fn constant(s: f64, value: f64) -> Cubic {
        Cubic {
            s,
            coefficients: [value, 0.0, 0.0, 0.0],
        }
    }
}

/// A function of the station made of [`Cubic`] pieces sorted by their start; before the first
/// piece it is the first piece extended, and zero when there is none.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Profile {
    pieces: Vec<Cubic>,
}

impl Profile {
    /// The profile of `pieces`, sorted by their start (a stable sort: of pieces that start at
    /// the same station, the last given wins, as in OpenDRIVE).
    pub fn new(mut pieces: Vec<Cubic>) -> Profile {
        pieces.sort_by(|a, b| a.s.total_cmp(&b.s));
        Profile { pieces }
    }

    /// The same value `value` everywhere.
    pub fn constant(value: f64) -> Profile {
        Profile {
            pieces: vec![Cubic::constant(0.0, value)],
        }
    }

    /// Its pieces, by start.
    pub fn pieces(&self) -> &[Cubic] {
        &self.pieces
    }

    /// The piece in force at `s`.
    fn piece(&self, s: f64) -> Option<&Cubic> {
        let i = self.pieces.partition_point(|p| p.s <= s);
        self.pieces.get(i.saturating_sub(1))
    }

    /// The value at `s` (m).
    pub fn value(&self, s: f64) -> f64 {
        self.eval(s).0
    }

    /// The value and its first and second derivatives by the station at `s` (m).
    pub fn eval(&self, s: f64) -> (f64, f64, f64) {
        self.piece(s).map_or((0.0, 0.0, 0.0), |p| {
            super::plan::cubic(&p.coefficients, s - p.s)
        })
    }

    /// True when no piece has a non-finite coefficient or start.
    pub(crate) fn is_finite(&self) -> bool {
        self.pieces
            .iter()
            .all(|p| p.s.is_finite() && p.coefficients.iter().all(|c| c.is_finite()))
    }
}
