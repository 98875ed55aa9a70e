//! What a run's recording keeps of a device's sample: one value per quantity, for the
//! `devices.csv` a recorded run writes beside its telemetry.
//!
//! Scalar devices give every value of every sample. A radar gives its number of targets and,
//! per target, each of its four quantities. A lidar gives a summary of its range image (how
//! many rays returned and the closest return), since its image (180 to 115,200 values per
//! sample) would make the file hundreds of times longer than the rest. A camera and a display
//! give no rows: their images are saved as PNG files at the end of the run.

use std::fmt;

use super::{Device, Reading};

/// What a recorded value measures: a quantity of the device's sample, for a radar of one of
/// its targets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct RecordedQuantity {
    /// The quantity's name, e.g. `x`, `speed`, `distance`.
    pub name: &'static str,
    /// The radar target (0 the first of the sample's list), `None` for a quantity of the
    /// whole sample.
    pub target: Option<u16>,
}

impl RecordedQuantity {
    /// A quantity of the whole sample.
    const fn of_sample(name: &'static str) -> Self {
        RecordedQuantity { name, target: None }
    }
}

impl fmt::Display for RecordedQuantity {
    /// `name`, or `target<k>.name` for radar target `k`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.target {
            Some(k) => write!(f, "target{k}.{}", self.name),
            None => f.write_str(self.name),
        }
    }
}

impl Device {
    /// True if the device took a sample at `now_ms` (ms): it is enabled and its last sample is
    /// from then. Only meaningful after a step's sampling, where enabling (which also sets the
    /// last sample time) cannot have happened at the same time.
    pub(crate) fn sampled_at(&self, now_ms: u64) -> bool {
        self.schedule.sampled_at(now_ms)
    }

    /// Calls `f` on each value the recording keeps of the last sample, with what it measures
    /// (units: those of [`Reading`]).
    pub fn for_each_recorded(&self, mut f: impl FnMut(RecordedQuantity, f64)) {
        let mut scalar = |name, value| f(RecordedQuantity::of_sample(name), value);
        match &self.reading {
            Reading::Gps(r) => {
                scalar("x", r.position.x);
                scalar("y", r.position.y);
                scalar("z", r.position.z);
                scalar("speed", r.speed);
                scalar("speed_vector_x", r.speed_vector.x);
                scalar("speed_vector_y", r.speed_vector.y);
                scalar("speed_vector_z", r.speed_vector.z);
            }
            // In the order of Webots' `wb_inertial_unit_get_quaternion`: x, y, z, w.
            Reading::InertialUnit(r) => {
                scalar("qx", r.quaternion.i);
                scalar("qy", r.quaternion.j);
                scalar("qz", r.quaternion.k);
                scalar("qw", r.quaternion.w);
            }
            Reading::Vector(v) => {
                scalar("x", v.x);
                scalar("y", v.y);
                scalar("z", v.z);
            }
            Reading::Camera | Reading::Display | Reading::Radar(None) => {}
            Reading::Distance(v) => scalar("value", *v),
            Reading::Radar(Some(targets)) => {
                scalar("targets", targets.len() as f64);
                for (k, t) in (0..=u16::MAX).zip(targets) {
                    let target = Some(k);
                    for (name, value) in [
                        ("distance", t.distance),
                        ("received_power", t.received_power),
                        ("speed", t.speed),
                        ("azimuth", t.azimuth),
                    ] {
                        f(RecordedQuantity { name, target }, value);
                    }
                }
            }
            // Off the roads the road and lane are absent: NaN in the file, like the other values.
            Reading::Road(r) => {
                let index = |v: Option<f64>| v.unwrap_or(f64::NAN);
                scalar("road", index(r.road.map(|i| i as f64)));
                scalar("lane", index(r.lane.map(f64::from)));
                scalar("s", r.s);
                scalar("lateral_offset", r.lateral_offset);
                scalar("heading_error", r.heading_error);
                scalar("curvature", r.curvature);
                scalar("curvature_ahead", r.curvature_ahead);
                scalar("left_line", r.left_line);
                scalar("right_line", r.right_line);
                scalar("left_edge", r.left_edge);
                scalar("right_edge", r.right_edge);
                scalar("lane_width", r.lane_width);
            }
            Reading::Lidar(r) => {
                let returns = r.range_image.iter().filter(|v| v.is_finite());
                scalar("returns", returns.clone().count() as f64);
                if let Some(closest) = returns.copied().reduce(f32::min) {
                    scalar("closest", f64::from(closest));
                }
            }
        }
    }
}
