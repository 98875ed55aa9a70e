//! Webots' `Radar` (spec §7): the targets (solids with a `radarCrossSection` above 0) in its
//! field of view, with their distance, received power from the radar equation, radial speed
//! and azimuth.

use core::f64::consts::{FRAC_PI_2, PI};

use proto_geom::nalgebra::Vector3;

use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::DevicePoint;
use super::noise::gaussian;
use super::rays::Scene;

/// Speed of light over 10⁹ (m·GHz): the wavelength (m) is this over the frequency (GHz).
const LIGHT_SPEED_M_GHZ: f64 = 0.299_792_458;

/// The fields of a `Radar` node, with the defaults of Webots' `Radar.wrl` ([`Default`]; three
/// differ from its manual: `minRadialSpeed` 0, `maxRadialSpeed` 0, `transmittedPower` 20 dBm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadarSettings {
    /// `minRange` (m, ≥ 0; default 1).
    pub min_range: f64,
    /// `maxRange` (m, > `minRange`; default 50).
    pub max_range: f64,
    /// `horizontalFieldOfView` (rad, in (0, π); default 0.78).
    pub horizontal_field_of_view: f64,
    /// `verticalFieldOfView` (rad, in (0, π/2); default 0.1).
    pub vertical_field_of_view: f64,
    /// `minAbsoluteRadialSpeed` (m/s, ≥ 0; default 0): slower targets are not reported.
    pub min_absolute_radial_speed: f64,
    /// `minRadialSpeed` (m/s; default 0). With `maxRadialSpeed` both 0: no limit.
    pub min_radial_speed: f64,
    /// `maxRadialSpeed` (m/s, > `minRadialSpeed` unless both are 0; default 0).
    pub max_radial_speed: f64,
    /// `cellDistance` (m, ≥ 0; default 0): targets nearer to each other merge.
    pub cell_distance: f64,
    /// `cellSpeed` (m/s, ≥ 0; default 0): and, if above 0, of closer radial speeds.
    pub cell_speed: f64,
    /// `rangeNoise` (m, ≥ 0; default 0): standard deviation of the distance.
    pub range_noise: f64,
    /// `speedNoise` (m/s, ≥ 0; default 0): standard deviation of the radial speed.
    pub speed_noise: f64,
    /// `angularNoise` (rad, ≥ 0; default 0): standard deviation of the azimuth.
    pub angular_noise: f64,
    /// `antennaGain` (dBi; default 20).
    pub antenna_gain: f64,
    /// `frequency` (GHz, > 0; default 24).
    pub frequency: f64,
    /// `transmittedPower` (dBm; default 20).
    pub transmitted_power: f64,
    /// `minDetectableSignal` (dBm; default −100).
    pub min_detectable_signal: f64,
    /// `occlusion` (default false): a target hidden behind another solid is not reported.
    pub occlusion: bool,
}

impl Default for RadarSettings {
    fn default() -> Self {
        RadarSettings {
            min_range: 1.0,
            max_range: 50.0,
            horizontal_field_of_view: 0.78,
            vertical_field_of_view: 0.1,
            min_absolute_radial_speed: 0.0,
            min_radial_speed: 0.0,
            max_radial_speed: 0.0,
            cell_distance: 0.0,
            cell_speed: 0.0,
            range_noise: 0.0,
            speed_noise: 0.0,
            angular_noise: 0.0,
            antenna_gain: 20.0,
            frequency: 24.0,
            transmitted_power: 20.0,
            min_detectable_signal: -100.0,
            occlusion: false,
        }
    }
}

impl RadarSettings {
    /// The Delphi ESR in its mid-range mode, as Webots' `DelphiEsr` PROTO gives it (spec §12):
    /// 1–60 m, 1.578 rad wide, 76.5 GHz, 31 dBm.
    pub fn delphi_esr() -> Self {
        RadarSettings {
            min_range: 1.0,
            max_range: 60.0,
            horizontal_field_of_view: 1.578,
            vertical_field_of_view: 0.07854,
            cell_distance: 1.25,
            range_noise: 0.25,
            angular_noise: 0.0175,
            speed_noise: 0.12,
            min_radial_speed: -100.0,
            max_radial_speed: 40.0,
            antenna_gain: 20.0,
            frequency: 76.5,
            transmitted_power: 31.0,
            min_detectable_signal: -80.0,
            ..RadarSettings::default()
        }
    }

    /// The Delphi ESR in its long-range mode (`DelphiEsr { longRangeMode TRUE }`, spec §12):
    /// 1–174 m, 0.349 rad (20°) wide.
    pub fn delphi_esr_long_range() -> Self {
        RadarSettings {
            max_range: 174.0,
            horizontal_field_of_view: 0.349_065_556,
            cell_distance: 2.5,
            range_noise: 0.5,
            angular_noise: 0.00873,
            min_detectable_signal: -90.0,
            ..RadarSettings::delphi_esr()
        }
    }

    /// Checks every field. Webots corrects some out-of-range fields with a warning; here they
    /// are refused.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::non_negative("minRange", self.min_range)?;
        ParamError::check(
            "maxRange",
            self.max_range,
            "finite and above minRange",
            |r| r.is_finite() && r > self.min_range,
        )?;
        ParamError::check(
            "horizontalFieldOfView",
            self.horizontal_field_of_view,
            "in (0, π) rad",
            |a| a > 0.0 && a < PI,
        )?;
        ParamError::check(
            "verticalFieldOfView",
            self.vertical_field_of_view,
            "in (0, π/2) rad",
            |a| a > 0.0 && a < FRAC_PI_2,
        )?;
        ParamError::non_negative("minAbsoluteRadialSpeed", self.min_absolute_radial_speed)?;
        ParamError::finite("minRadialSpeed", self.min_radial_speed)?;
        ParamError::check(
            "maxRadialSpeed",
            self.max_radial_speed,
            "finite and above minRadialSpeed (or both 0: no limit)",
            |s| {
                s.is_finite()
                    && (s > self.min_radial_speed || (s == 0.0 && self.min_radial_speed == 0.0))
            },
        )?;
        ParamError::non_negative("cellDistance", self.cell_distance)?;
        ParamError::non_negative("cellSpeed", self.cell_speed)?;
        ParamError::non_negative("rangeNoise", self.range_noise)?;
        ParamError::non_negative("speedNoise", self.speed_noise)?;
        ParamError::non_negative("angularNoise", self.angular_noise)?;
        ParamError::finite("antennaGain", self.antenna_gain)?;
        ParamError::positive("frequency", self.frequency)?;
        ParamError::finite("transmittedPower", self.transmitted_power)?;
        ParamError::finite("minDetectableSignal", self.min_detectable_signal)?;
        Ok(())
    }

    /// The power (W) the radar receives from a target of cross-section `rcs` (m²) at `d` (m):
    /// the radar equation `P_t·G²·λ²·σ / ((4π)³·d⁴)`.
    pub fn received_power(&self, rcs: f64, d: f64) -> f64 {
        let transmitted = dbm_to_watts(self.transmitted_power);
        let gain = 10f64.powf(self.antenna_gain / 10.0);
        let wavelength = LIGHT_SPEED_M_GHZ / self.frequency;
        transmitted * gain * gain * wavelength * wavelength * rcs / ((4.0 * PI).powi(3) * d.powi(4))
    }
}

/// A power in dBm as W.
fn dbm_to_watts(dbm: f64) -> f64 {
    10f64.powf(dbm / 10.0) / 1000.0
}

/// A target the radar reports: Webots' `WbRadarTarget`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadarTarget {
    /// Distance (m), with `rangeNoise`, within [`minRange`, `maxRange`].
    pub distance: f64,
    /// Received power (dBm).
    pub received_power: f64,
    /// Radial speed (m/s, > 0 receding), with `speedNoise`.
    pub speed: f64,
    /// Azimuth (rad, > 0 to the right, i.e. towards the device's −y), with `angularNoise`.
    pub azimuth: f64,
}

/// True if a sphere of `radius` (m) centred at `centre` (m, device axes) meets the radar's
/// field of view: its centre within the fields of view widened by the angle the sphere
/// subtends, and its near side within `maxRange`. (Webots intersects the target's bounding
/// object with the radar's frustum: a car close ahead stays seen though its origin is below
/// the narrow vertical field of view.)
fn in_view(s: &RadarSettings, centre: &Vector3<f64>, radius: f64) -> bool {
    let distance = centre.norm();
    if distance - radius > s.max_range {
        return false;
    }
    if distance <= radius {
        // The radar is inside the sphere.
        return centre.x + radius > 0.0;
    }
    let margin = (radius / distance).asin();
    let azimuth = centre.y.atan2(centre.x).abs();
    let elevation = centre.z.atan2(centre.x.hypot(centre.y)).abs();
    azimuth <= s.horizontal_field_of_view / 2.0 + margin
        && elevation <= s.vertical_field_of_view / 2.0 + margin
}

/// The targets of the radar at `point` in `scene`, in the scene's order and merged by cell;
/// the power still in W.
fn detect(
    s: &RadarSettings,
    scene: &Scene<'_>,
    point: &DevicePoint,
    rng: &mut SplitMix64,
) -> Vec<RadarTarget> {
    let to_device = point.rotation.inverse();
    let threshold = dbm_to_watts(s.min_detectable_signal);
    let speed_limits = !(s.min_radial_speed == 0.0 && s.max_radial_speed == 0.0);
    let noisy = |sd: f64, rng: &mut SplitMix64| if sd > 0.0 { sd * gaussian(rng) } else { 0.0 };
    let mut out = Vec::new();
    for echo in scene.echoes() {
        if !in_view(
            s,
            &(to_device * (echo.centre - point.position)),
            echo.radius,
        ) {
            continue;
        }
        let world = echo.position - point.position;
        let range = world.norm();
        if range.is_nan() || range <= 0.0 {
            continue;
        }
        let local = to_device * world;
        let left = local.y.atan2(local.x);
        let line = world / range;
        if s.occlusion
            && scene
                .cast(&point.position, &line, range)
                .is_some_and(|h| !scene.reaches(h.collider, echo))
        {
            continue;
        }
        let d = range + noisy(s.range_noise, rng);
        if d < s.min_range - echo.half_length {
            continue;
        }
        let d = d.max(s.min_range);
        let d = d.min(s.max_range);
        let power = s.received_power(echo.cross_section, d);
        if power < threshold {
            continue;
        }
        let speed = line.dot(&(echo.velocity - point.velocity)) + noisy(s.speed_noise, rng);
        if speed_limits && (speed < s.min_radial_speed || speed > s.max_radial_speed) {
            continue;
        }
        if s.min_absolute_radial_speed > 0.0 && speed.abs() < s.min_absolute_radial_speed {
            continue;
        }
        let half = s.horizontal_field_of_view / 2.0;
        let azimuth = (-left).clamp(-half, half) + noisy(s.angular_noise, rng);
        out.push(RadarTarget {
            distance: d,
            received_power: power,
            speed,
            azimuth,
        });
    }
    out
}

/// Merges the targets closer than `cellDistance` (and, if `cellSpeed` > 0, of radial speeds
/// closer than it) into the first of them: power-weighted means of distance, speed and
/// azimuth, summed power (W).
fn merge(s: &RadarSettings, targets: &mut Vec<RadarTarget>) {
    if s.cell_distance <= 0.0 {
        return;
    }
    let mut i = 0;
    while i < targets.len() {
        let mut j = i + 1;
        while j < targets.len() {
            let (a, b) = (targets[i], targets[j]);
            let near = (a.distance - b.distance).abs() < s.cell_distance
                && (s.cell_speed <= 0.0 || (a.speed - b.speed).abs() < s.cell_speed);
            if !near {
                j += 1;
                continue;
            }
            let p = a.received_power + b.received_power;
            let mean = |x: f64, y: f64| (x * a.received_power + y * b.received_power) / p;
            targets[i] = RadarTarget {
                distance: mean(a.distance, b.distance),
                received_power: p,
                speed: mean(a.speed, b.speed),
                azimuth: mean(a.azimuth, b.azimuth),
            };
            targets.remove(j);
            // The fused target moved: compare it with every later one again.
            j = i + 1;
        }
        i += 1;
    }
}

/// The radar's sample at `point` in `scene`: its targets, power in dBm.
pub(crate) fn measure(
    s: &RadarSettings,
    scene: &Scene<'_>,
    point: &DevicePoint,
    rng: &mut SplitMix64,
) -> Vec<RadarTarget> {
    let mut targets = detect(s, scene, point, rng);
    merge(s, &mut targets);
    for t in &mut targets {
        t.received_power = 10.0 * (t.received_power / 0.001).log10();
    }
    targets
}

#[cfg(test)]
mod tests {
    use super::*;

    fn target(distance: f64, power: f64, speed: f64, azimuth: f64) -> RadarTarget {
        RadarTarget {
            distance,
            received_power: power,
            speed,
            azimuth,
        }
    }

    #[test]
    fn cells_merge_by_power_weighted_means() {
        let s = RadarSettings {
            cell_distance: 1.0,
            ..RadarSettings::default()
        };
        let mut t = vec![
            target(10.0, 3.0, 1.0, 0.1),
            target(10.5, 1.0, 5.0, -0.1),
            target(20.0, 1.0, 0.0, 0.0),
        ];
        merge(&s, &mut t);
        assert_eq!(t.len(), 2);
        // (10·3 + 10.5·1)/4, (1·3 + 5·1)/4, (0.3 − 0.1)/4; tolerance: a few f64 roundings.
        assert!((t[0].distance - 10.125).abs() < 1e-12);
        assert!((t[0].speed - 2.0).abs() < 1e-12);
        assert!((t[0].azimuth - 0.05).abs() < 1e-12);
        assert_eq!(t[0].received_power, 4.0);
        assert_eq!(t[1], target(20.0, 1.0, 0.0, 0.0));
        // With a cell speed, targets of different speeds stay apart.
        let s = RadarSettings {
            cell_speed: 1.0,
            ..s
        };
        let mut t = vec![target(10.0, 3.0, 1.0, 0.1), target(10.5, 1.0, 5.0, -0.1)];
        merge(&s, &mut t);
        assert_eq!(t.len(), 2);
    }

    #[test]
    fn presets_are_valid() {
        for s in [
            RadarSettings::default(),
            RadarSettings::delphi_esr(),
            RadarSettings::delphi_esr_long_range(),
        ] {
            assert_eq!(s.validate(), Ok(()));
        }
        let bad = RadarSettings {
            max_range: 0.5,
            ..RadarSettings::default()
        };
        assert_eq!(bad.validate().unwrap_err().field, "maxRange");
    }
}
