//! Drive-cycle speed traces: the regulatory 1 Hz speed-versus-time tables a chassis
//! dynamometer test follows, and the tolerance band around them.
//!
//! The tables ship as data in `sim/data/cycles/`, each with its source in its header:
//! the EPA Urban Dynamometer Driving Schedule (40 CFR 86 Appendix I(a)), from which FTP-75
//! is built, the Highway Fuel Economy Driving Schedule (40 CFR 600 Appendix I), and the WLTC
//! class 3b of UN GTR No. 15 (ECE/TRANS/180/Add.15, Annex 1). The EPA regulations define the
//! trace as "a smooth trace drawn through the specified speed versus time relationships"
//! (40 CFR 600.109(b)(1)); [`Trace::speed`] draws it with straight lines between the
//! seconds, for the WLTC too.

use core::fmt;

/// m/s per mph (exact: 1 mile = 1609.344 m).
pub const MS_PER_MPH: f64 = 0.447_04;

/// The EPA UDDS table (mph, 1 Hz), with its header.
const UDDS: &str = include_str!("../../data/cycles/udds.txt");
/// The EPA HWFET table (mph, 1 Hz), with its header.
const HWFET: &str = include_str!("../../data/cycles/hwfet.txt");
/// The GTR 15 WLTC class 3b table (km/h, 1 Hz), with its header.
const WLTC3B: &str = include_str!("../../data/cycles/wltc3b.txt");
/// m/s per km/h.
const MS_PER_KMH: f64 = 1.0 / 3.6;

/// Length of the FTP-75's hot-start phase (s): the first 505 s of the UDDS driven again
/// after the 10-minute soak (40 CFR 86.137-94(b)(27)).
const FTP75_HOT_START_S: usize = 505;

/// Half-width of the EPA's speed tolerance band (m/s): 2 mph (40 CFR 86.115-78(c), 40 CFR
/// 600.109-08(b)(2)).
pub const EPA_SPEED_TOLERANCE: f64 = 2.0 * MS_PER_MPH;

/// Half-width of the EPA band's time window (s): the band's edges are the highest and lowest
/// trace speeds within 1 s of the time (same sections).
pub const EPA_TIME_TOLERANCE: f64 = 1.0;

/// A regulatory drive cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Cycle {
    /// EPA FTP-75: the UDDS (1369 s, cold start and stabilised phases) followed by its first
    /// 505 s again (hot start); 1874 s, the 10-minute engine-off soak between them left out.
    Ftp75,
    /// EPA Highway Fuel Economy Test: 765 s.
    Hwfet,
    /// WLTC class 3b of UN GTR No. 15 (cars of more than 34 W/kg and at least 120 km/h):
    /// 1800 s in four phases, Low, Medium, High and Extra High.
    Wltc,
    /// EPA Urban Dynamometer Driving Schedule (UDDS, LA-4): 1369 s, the FTP-75's cold start
    /// and stabilised phases alone.
    Udds,
}

/// A trace's tolerance band: the half-widths the car's speed may stray from the trace.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    /// In speed (m/s).
    pub speed: f64,
    /// In time (s): the band's edges are the highest and lowest trace speeds this close.
    pub time: f64,
    /// "time outside the tolerance band (…)", for the metrics table.
    pub outside_label: &'static str,
}

impl Band {
    /// The EPA's band, ±2 mph and ±1 s: its cycles', and a user's trace's.
    pub const EPA: Band = Band {
        speed: EPA_SPEED_TOLERANCE,
        time: EPA_TIME_TOLERANCE,
        outside_label: "time outside the tolerance band (±2 mph, ±1 s)",
    };

    /// GTR No. 15's band for the WLTC, ±2 km/h and ±1 s.
    pub const WLTC: Band = Band {
        speed: 2.0 * MS_PER_KMH,
        time: 1.0,
        outside_label: "time outside the tolerance band (±2 km/h, ±1 s)",
    };
}

impl Cycle {
    /// Every cycle shipped.
    pub const ALL: [Cycle; 4] = [Cycle::Ftp75, Cycle::Hwfet, Cycle::Wltc, Cycle::Udds];

    /// The cycle's name, e.g. `"ftp75"`.
    pub const fn name(self) -> &'static str {
        match self {
            Cycle::Ftp75 => "ftp75",
            Cycle::Hwfet => "hwfet",
            Cycle::Wltc => "wltc",
            Cycle::Udds => "udds",
        }
    }

    /// The cycle named `name`, or `None`.
    pub fn from_name(name: &str) -> Option<Cycle> {
        Cycle::ALL.into_iter().find(|c| c.name() == name)
    }

    /// The cycle's speed trace.
    pub fn trace(self) -> Trace {
        // The shipped tables are well formed (the `shipped_tables_parse` test reads them).
        let table = |text| Trace::from_table(text, MS_PER_MPH).unwrap_or_default();
        match self {
            Cycle::Ftp75 => {
                let udds = table(UDDS);
                let mut speeds = udds.speeds.clone();
                // The hot start repeats seconds 1..=505: second 0 of the repeat is the
                // UDDS's last second (both at rest), so the trace stays at 1 Hz.
                speeds.extend_from_slice(&udds.speeds[1..=FTP75_HOT_START_S]);
                Trace { speeds }
            }
            Cycle::Hwfet => table(HWFET),
            Cycle::Wltc => Trace::from_table(WLTC3B, MS_PER_KMH).unwrap_or_default(),
            Cycle::Udds => table(UDDS),
        }
    }

    /// Half-width of the speed tolerance band (m/s): [`EPA_SPEED_TOLERANCE`] (2 mph) for the
    /// EPA cycles (40 CFR 86.115-78(c), 40 CFR 600.109-08(b)(2)), 2 km/h for the WLTC (GTR
    /// No. 15, Annex 6, §2.6.8.3, speed trace tolerances).
    pub const fn speed_tolerance(self) -> f64 {
        match self {
            Cycle::Ftp75 | Cycle::Hwfet | Cycle::Udds => EPA_SPEED_TOLERANCE,
            Cycle::Wltc => 2.0 * MS_PER_KMH,
        }
    }

    /// Half-width of the band's time window (s): [`EPA_TIME_TOLERANCE`], the band's edges
    /// being the highest and lowest trace speeds within 1 s of the time (the same ±1.0 s in
    /// GTR No. 15).
    pub const fn time_tolerance(self) -> f64 {
        EPA_TIME_TOLERANCE
    }

    /// The cycle's tolerance band.
    pub const fn band(self) -> Band {
        match self {
            Cycle::Ftp75 | Cycle::Hwfet | Cycle::Udds => Band::EPA,
            Cycle::Wltc => Band::WLTC,
        }
    }
}

impl fmt::Display for Cycle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A table that is not a 1 Hz speed trace.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line} of the speed table: {reason}")]
pub struct TraceError {
    /// The 1-based line.
    pub line: usize,
    /// What is wrong with it.
    pub reason: String,
}

/// A speed trace sampled once a second from time 0.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Trace {
    /// Speed at each whole second (m/s).
    speeds: Vec<f64>,
}

impl Trace {
    /// A trace of `speeds` (m/s), one a second from 0 s.
    ///
    /// # Errors
    /// A [`TraceError`] naming the first speed that is negative or not finite, or an empty
    /// trace.
    pub fn new(speeds: Vec<f64>) -> Result<Self, TraceError> {
        if speeds.is_empty() {
            return Err(TraceError {
                line: 0,
                reason: "no speeds".into(),
            });
        }
        if let Some((i, v)) = speeds
            .iter()
            .enumerate()
            .find(|(_, v)| !v.is_finite() || **v < 0.0)
        {
            return Err(TraceError {
                line: i + 1,
                reason: format!("speed {v} is not a finite speed ≥ 0"),
            });
        }
        Ok(Trace { speeds })
    }

    /// Reads a table of `time speed` lines (s, then speed in units of `scale` m/s; `#` starts
    /// a comment), its times 0, 1, 2 … s.
    ///
    /// # Errors
    /// A [`TraceError`] naming the line whose time is not the next second or whose speed is
    /// not a finite speed ≥ 0.
    pub fn from_table(text: &str, scale: f64) -> Result<Self, TraceError> {
        let mut speeds = Vec::new();
        for (i, line) in text.lines().enumerate() {
            let body = line.split('#').next().unwrap_or("").trim();
            if body.is_empty() {
                continue;
            }
            let err = |reason: String| TraceError {
                line: i + 1,
                reason,
            };
            let mut fields = body.split_whitespace();
            let (Some(t), Some(v), None) = (fields.next(), fields.next(), fields.next()) else {
                return Err(err(format!("'{body}' is not 'time speed'")));
            };
            let t: f64 = t.parse().map_err(|_| err(format!("time '{t}'")))?;
            let v: f64 = v.parse().map_err(|_| err(format!("speed '{v}'")))?;
            if t != speeds.len() as f64 {
                return Err(err(format!("time {t} s, expected {} s", speeds.len())));
            }
            if !v.is_finite() || v < 0.0 {
                return Err(err(format!("speed {v} is not a finite speed ≥ 0")));
            }
            speeds.push(v * scale);
        }
        Trace::new(speeds).map_err(|e| TraceError {
            line: text.lines().count(),
            ..e
        })
    }

    /// The speeds at each whole second (m/s).
    pub fn speeds(&self) -> &[f64] {
        &self.speeds
    }

    /// Duration (s): the last sample's time.
    pub fn duration(&self) -> f64 {
        self.speeds.len().saturating_sub(1) as f64
    }

    /// The trace's speed at `t` s (m/s): straight lines between the seconds, the end speeds
    /// outside.
    pub fn speed(&self, t: f64) -> f64 {
        let last = self.speeds.len().saturating_sub(1);
        // NaN lands here too: the first speed.
        if t.is_nan() || t <= 0.0 {
            return self.speeds.first().copied().unwrap_or(0.0);
        }
        let i = t.floor() as usize;
        if i >= last {
            return self.speeds.get(last).copied().unwrap_or(0.0);
        }
        let f = t - i as f64;
        self.speeds[i] + f * (self.speeds[i + 1] - self.speeds[i])
    }

    /// The trace's acceleration at `t` s (m/s²): the slope of the second it lies in.
    pub fn acceleration(&self, t: f64) -> f64 {
        let last = self.speeds.len().saturating_sub(1);
        if t.is_nan() || t < 0.0 || t >= last as f64 {
            return 0.0;
        }
        let i = t.floor() as usize;
        self.speeds[i + 1] - self.speeds[i]
    }

    /// The tolerance band at `t` s (m/s): the lowest trace speed within `window` s of `t`
    /// less `tolerance`, and the highest plus `tolerance` (the EPA's definition; the lower
    /// edge not below 0).
    pub fn band(&self, t: f64, window: f64, tolerance: f64) -> (f64, f64) {
        let (a, b) = (t - window, t + window);
        let mut lo = self.speed(a).min(self.speed(b));
        let mut hi = self.speed(a).max(self.speed(b));
        let first = a.max(0.0).ceil() as usize;
        let end = (b.floor().max(0.0) as usize).min(self.speeds.len().saturating_sub(1));
        for &v in self.speeds.get(first..=end).unwrap_or(&[]) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        ((lo - tolerance).max(0.0), hi + tolerance)
    }

    /// Distance (m): the trace integrated with straight lines between the seconds.
    pub fn distance(&self) -> f64 {
        self.speeds.windows(2).map(|w| 0.5 * (w[0] + w[1])).sum()
    }

    /// Highest speed (m/s).
    pub fn max_speed(&self) -> f64 {
        self.speeds.iter().copied().fold(0.0, f64::max)
    }

    /// Mean speed over the duration, stops included (m/s).
    pub fn mean_speed(&self) -> f64 {
        let d = self.duration();
        if d > 0.0 { self.distance() / d } else { 0.0 }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// m per mile.
    const M_PER_MILE: f64 = 1609.344;

    #[test]
    fn shipped_tables_parse() {
        assert_eq!(
            Trace::from_table(UDDS, 1.0).unwrap().speeds().len(),
            1370,
            "UDDS: 0..=1369 s"
        );
        assert_eq!(Trace::from_table(HWFET, 1.0).unwrap().speeds().len(), 766);
        assert_eq!(
            Trace::from_table(WLTC3B, 1.0).unwrap().speeds().len(),
            1801,
            "WLTC: 0..=1800 s"
        );
    }

    /// The WLTC class 3b's published phase figures (GTR No. 15 Annex 1; the durations and
    /// top speeds also as a second source gives them, evdb.nz "WLTP Explained": 9:49, 7:13,
    /// 7:35 and 5:23 min; 56.5, 76.6, 97.4 and 131.3 km/h; the whole cycle's 1800 s and mean
    /// 46.5 km/h as Mercedes-Benz's WLTP page gives them). Each phase ends where the next
    /// begins (the GTR's phases share their boundary second); distances are integrated with
    /// straight lines between the seconds and published to the metre, hence 0.5 m, plus 0.1 m
    /// for the table's 0.1 km/h resolution over a phase of a few hundred seconds (m).
    #[test]
    fn the_wltc_matches_its_published_phases() {
        let wltc = Cycle::Wltc.trace();
        let v = wltc.speeds();
        let phases = [
            (0, 589, 3095.0, 56.5),
            (589, 1022, 4756.0, 76.6),
            (1022, 1477, 7162.0, 97.4),
            (1477, 1800, 8254.0, 131.3),
        ];
        for (start, end, metres, top_kmh) in phases {
            let phase = Trace::new(v[start..=end].to_vec()).unwrap();
            assert!(
                (phase.distance() - metres).abs() <= 0.6,
                "{start}–{end} s: {} m",
                phase.distance()
            );
            assert!(
                (phase.max_speed() * 3.6 - top_kmh).abs() < 1e-9,
                "{start} s"
            );
        }
        assert_eq!(wltc.duration(), 1800.0);
        assert!((wltc.distance() / 1000.0 - 23.27).abs() <= 0.005);
        assert!((wltc.mean_speed() * 3.6 - 46.5).abs() <= 0.05);
    }

    #[test]
    fn traces_match_their_published_duration_distance_and_speeds() {
        // UDDS: 1369 s, 7.45 mi, 56.7 mph top (EPA; 40 CFR 86.115).
        let udds = Trace::from_table(UDDS, MS_PER_MPH).unwrap();
        assert_eq!(udds.duration(), 1369.0);
        assert!((udds.distance() / M_PER_MILE - 7.45).abs() <= 0.005);
        assert!((udds.max_speed() / MS_PER_MPH - 56.7).abs() < 1e-9);
        // FTP-75: 1874 s, 11.04 mi (17.77 km), mean 21.2 mph (34.1 km/h) (EPA).
        let ftp = Cycle::Ftp75.trace();
        assert_eq!(ftp.duration(), 1874.0);
        assert!(
            (ftp.distance() / M_PER_MILE - 11.04).abs() <= 0.005,
            "{} mi",
            ftp.distance() / M_PER_MILE
        );
        assert!((ftp.mean_speed() / MS_PER_MPH - 21.2).abs() <= 0.05);
        // HWFET: 765 s, 10.26 mi, mean 48.3 mph, top 59.9 mph (96.4 km/h) (EPA; 40 CFR
        // 600.111 rounds them to 10.2 mi and 60 mph).
        let hw = Cycle::Hwfet.trace();
        assert_eq!(hw.duration(), 765.0);
        assert!((hw.distance() / M_PER_MILE - 10.26).abs() <= 0.005);
        assert!((hw.mean_speed() / MS_PER_MPH - 48.3).abs() <= 0.05);
        assert!((hw.max_speed() / MS_PER_MPH - 59.9).abs() < 1e-9);
        assert!((hw.max_speed() * 3.6 - 96.4).abs() < 0.05);
    }

    #[test]
    fn the_udds_table_is_the_cfr_one_at_spot_checks() {
        // 40 CFR 86 Appendix I(a): 21 s 3.0 mph, 26 s 16.9, 164 s 3.3, 240 s 56.7 mph.
        let udds = Trace::from_table(UDDS, 1.0).unwrap();
        for (t, v) in [(20, 0.0), (21, 3.0), (26, 16.9), (164, 3.3), (240, 56.7)] {
            assert_eq!(udds.speeds()[t], v, "{t} s");
        }
    }

    #[test]
    fn the_band_spans_the_trace_within_a_second_plus_the_tolerance() {
        let t = Trace::new(vec![0.0, 1.0, 3.0, 3.0, 0.0]).unwrap();
        assert_eq!(t.band(2.0, 1.0, 0.5), (0.5, 3.5));
        assert_eq!(t.band(0.0, 1.0, 0.5), (0.0, 1.5));
        // Between the seconds the window's ends are interpolated: at 0.5 s, [−0.5, 1.5] s
        // spans 0 to 2 m/s.
        assert_eq!(t.band(0.5, 1.0, 0.5), (0.0, 2.5));
        assert_eq!(t.speed(1.5), 2.0);
        assert_eq!(t.acceleration(1.5), 2.0);
    }

    #[test]
    fn bad_tables_name_their_line() {
        let e = Trace::from_table("0 0\n2 1\n", 1.0).unwrap_err();
        assert_eq!(e.line, 2);
        let e = Trace::from_table("# c\n0 -1\n", 1.0).unwrap_err();
        assert_eq!(e.line, 2);
        assert!(Trace::from_table("# nothing\n", 1.0).is_err());
        assert!(Trace::new(vec![f64::NAN]).is_err());
    }
}
