//! Webots' `Lidar` (spec §8): a range image of `numberOfLayers` rows of
//! `horizontalResolution` rays, each cast through the world, and the point cloud it converts
//! to. A fixed lidar casts its whole image at each sample; a rotating one turns its head at
//! `defaultFrequency` and rewrites, at every step, the columns its head swept in that step.

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use proto_geom::nalgebra::Vector3;

use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::noise::gaussian;
use super::rays::Scene;
use super::{DevicePoint, check_resolution};

/// The `projection` field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LidarProjection {
    /// `"cylindrical"`: each value is the distance from the lidar along its ray (m).
    Cylindrical,
    /// `"planar"`: each value is the depth along the lidar's +x axis (m); a rotating lidar's,
    /// along its head's x axis.
    Planar,
}

impl LidarProjection {
    /// The `projection` string.
    pub const fn webots_name(self) -> &'static str {
        match self {
            LidarProjection::Cylindrical => "cylindrical",
            LidarProjection::Planar => "planar",
        }
    }
}

/// The `type` field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LidarType {
    /// `"fixed"`: the image spans `fieldOfView` around +x, cast whole at each sample.
    Fixed,
    /// `"rotating"`: the head turns clockwise (seen from +z) at `defaultFrequency` turns per
    /// second; the image spans a full turn, column `j` at azimuth `−π − j·2π/hres`.
    Rotating,
}

impl LidarType {
    /// The `type` string.
    pub const fn webots_name(self) -> &'static str {
        match self {
            LidarType::Fixed => "fixed",
            LidarType::Rotating => "rotating",
        }
    }
}

/// Slack (rad) on the bounds of a rotating head's sweep: its angle sums one turn per step in
/// f64, so a column exactly at a step's end may fall an ulp past it; within the slack it
/// belongs to the step that ends there, not to the next.
const SWEEP_SLACK: f64 = 1e-9;

/// Angles (rad) as Webots writes them in `Lidar.wrl` and the `SickLms291` and `VelodynePuck`
/// PROTOs (spec §12): rounded multiples of π, kept as Webots has them.
#[allow(
    clippy::approx_constant,
    reason = "Webots' literal field values, not π"
)]
mod webots {
    /// `Lidar.fieldOfView`'s default.
    pub(super) const DEFAULT_FOV: f64 = 1.5708;
    /// The SICK LMS 291's `fieldOfView`.
    pub(super) const SICK_FOV: f64 = 3.14159;
    /// The VLP-16's `fieldOfView`.
    pub(super) const VLP16_FOV: f64 = 6.28318;
    /// The VLP-16's `verticalFieldOfView` (±15°).
    pub(super) const VLP16_VERTICAL_FOV: f64 = 0.5236;
}

/// The most rays per layer (`horizontalResolution`): 0.01° over a full turn. More is a typo.
pub const MAX_LIDAR_RESOLUTION: u32 = 36_000;
/// The most layers (`numberOfLayers`): real lidars have at most a few hundred.
pub const MAX_LIDAR_LAYERS: u32 = 512;

/// The fields of a `Lidar` node, with Webots' defaults ([`Default`]). `rotatingHead` is not
/// supported (`COMPATIBILITY.md`). A fixed lidar samples at its sampling period and holds the
/// frequencies for the getters; a rotating one turns at `defaultFrequency`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LidarSettings {
    /// `type` (default fixed).
    pub lidar_type: LidarType,
    /// `tiltAngle` (rad, in [−π/2, π/2]; default 0): added to every layer's elevation.
    pub tilt_angle: f64,
    /// `horizontalResolution` (rays per layer, 1 to [`MAX_LIDAR_RESOLUTION`]; default 512).
    pub horizontal_resolution: u32,
    /// `fieldOfView` (rad, in (0, π] planar, (0, 2π] cylindrical; default 1.5708).
    pub field_of_view: f64,
    /// `verticalFieldOfView` (rad, in (0, π]; default 0.2): from the first layer to the last.
    pub vertical_field_of_view: f64,
    /// `numberOfLayers` (1 to [`MAX_LIDAR_LAYERS`]; default 4).
    pub number_of_layers: u32,
    /// `near` (m, > 0 and ≤ `minRange`; default 0.01): nothing nearer is seen.
    pub near: f64,
    /// `minRange` (m, ≥ `near`, < `maxRange`; default 0.01): nearer values read +∞.
    pub min_range: f64,
    /// `maxRange` (m; default 1): values at or beyond it read +∞.
    pub max_range: f64,
    /// `projection` (default cylindrical).
    pub projection: LidarProjection,
    /// `noise` (≥ 0; default 0): standard deviation of each value as a fraction of
    /// `maxRange`.
    pub noise: f64,
    /// `resolution` (m, −1 or > 0; default −1: none).
    pub resolution: f64,
    /// `defaultFrequency` (Hz, in [`minFrequency`, `maxFrequency`]; default 10).
    pub default_frequency: f64,
    /// `minFrequency` (Hz, > 0; default 1).
    pub min_frequency: f64,
    /// `maxFrequency` (Hz, ≥ `minFrequency`; default 25).
    pub max_frequency: f64,
}

impl Default for LidarSettings {
    fn default() -> Self {
        LidarSettings {
            lidar_type: LidarType::Fixed,
            tilt_angle: 0.0,
            horizontal_resolution: 512,
            field_of_view: webots::DEFAULT_FOV,
            vertical_field_of_view: 0.2,
            number_of_layers: 4,
            near: 0.01,
            min_range: 0.01,
            max_range: 1.0,
            projection: LidarProjection::Cylindrical,
            noise: 0.0,
            resolution: -1.0,
            default_frequency: 10.0,
            min_frequency: 1.0,
            max_frequency: 25.0,
        }
    }
}

impl LidarSettings {
    /// The SICK LMS 291 as Webots' `SickLms291` PROTO gives it (spec §12): 180 rays over
    /// 3.14159 rad in one layer, 80 m, no noise.
    pub fn sick_lms_291() -> Self {
        LidarSettings {
            horizontal_resolution: 180,
            field_of_view: webots::SICK_FOV,
            vertical_field_of_view: webots::SICK_FOV / 180.0,
            number_of_layers: 1,
            max_range: 80.0,
            ..LidarSettings::default()
        }
    }

    /// The Velodyne VLP-16 ("Puck") as Webots' `VelodynePuck` PROTO gives it (spec §12): 16
    /// layers over 0.5236 rad (±15°), 3600 rays per turn, 1–100 m, noise 0.003 of the range,
    /// 5 Hz (5 to 20).
    pub fn velodyne_vlp16() -> Self {
        LidarSettings {
            horizontal_resolution: 3600,
            field_of_view: webots::VLP16_FOV,
            vertical_field_of_view: webots::VLP16_VERTICAL_FOV,
            number_of_layers: 16,
            near: 0.01,
            min_range: 1.0,
            max_range: 100.0,
            noise: 0.003,
            default_frequency: 5.0,
            min_frequency: 5.0,
            max_frequency: 20.0,
            ..LidarSettings::default()
        }
    }

    /// Checks every field. Webots corrects some inconsistent fields with a warning; here they
    /// are refused.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::check("tiltAngle", self.tilt_angle, "in [-π/2, π/2] rad", |a| {
            (-FRAC_PI_2..=FRAC_PI_2).contains(&a)
        })?;
        ParamError::check(
            "horizontalResolution",
            f64::from(self.horizontal_resolution),
            "at least 1 and at most 36000",
            |n| (1.0..=f64::from(MAX_LIDAR_RESOLUTION)).contains(&n),
        )?;
        let (widest, rule) = match self.projection {
            LidarProjection::Planar => (PI, "in (0, π] rad for a planar projection"),
            LidarProjection::Cylindrical => (TAU, "in (0, 2π] rad"),
        };
        ParamError::check("fieldOfView", self.field_of_view, rule, |a| {
            a > 0.0 && a <= widest
        })?;
        ParamError::check(
            "verticalFieldOfView",
            self.vertical_field_of_view,
            "in (0, π] rad",
            |a| a > 0.0 && a <= PI,
        )?;
        ParamError::check(
            "numberOfLayers",
            f64::from(self.number_of_layers),
            "at least 1 and at most 512",
            |n| (1.0..=f64::from(MAX_LIDAR_LAYERS)).contains(&n),
        )?;
        ParamError::positive("near", self.near)?;
        ParamError::check("minRange", self.min_range, "finite and >= near", |r| {
            r.is_finite() && r >= self.near
        })?;
        ParamError::check(
            "maxRange",
            self.max_range,
            "finite and above minRange",
            |r| r.is_finite() && r > self.min_range,
        )?;
        ParamError::non_negative("noise", self.noise)?;
        check_resolution("resolution", self.resolution)?;
        ParamError::positive("minFrequency", self.min_frequency)?;
        ParamError::check(
            "maxFrequency",
            self.max_frequency,
            "finite and >= minFrequency",
            |f| f.is_finite() && f >= self.min_frequency,
        )?;
        ParamError::check(
            "defaultFrequency",
            self.default_frequency,
            "within [minFrequency, maxFrequency]",
            |f| f >= self.min_frequency && f <= self.max_frequency,
        )?;
        Ok(())
    }

    /// The number of values of a range image: `horizontalResolution · numberOfLayers`.
    pub fn number_of_points(&self) -> usize {
        self.horizontal_resolution as usize * self.number_of_layers as usize
    }

    /// The azimuth of column `j` (rad, > 0 towards +y): `fov/2 − (j + ½)·fov/hres` for a
    /// fixed lidar, `−π − j·2π/hres` for a rotating one.
    pub fn azimuth(&self, j: u32) -> f64 {
        let hres = f64::from(self.horizontal_resolution);
        match self.lidar_type {
            LidarType::Fixed => {
                let step = self.field_of_view / hres;
                self.field_of_view / 2.0 - (f64::from(j) + 0.5) * step
            }
            LidarType::Rotating => -PI - f64::from(j) * TAU / hres,
        }
    }

    /// True if column `j` of a rotating lidar is swept as its head turns clockwise from
    /// `from` by `turn` (rad): its azimuth lies in `(from, from + turn]` clockwise (the head
    /// starts at azimuth 0, so `from` is the angle turned so far), so that each column is
    /// swept once a turn.
    fn swept(&self, j: u32, from: f64, turn: f64) -> bool {
        if turn >= TAU {
            return true;
        }
        // The clockwise angle from azimuth 0 to the column, then from the head to it.
        let column = (-self.azimuth(j)).rem_euclid(TAU);
        let ahead = (column - from).rem_euclid(TAU);
        ahead > SWEEP_SLACK && ahead <= turn + SWEEP_SLACK
    }

    /// The elevation of layer `i` (rad, > 0 up; layer 0 the highest): `vFOV/2 −
    /// i·vFOV/(layers − 1) + tilt`, or the tilt for one layer.
    pub fn elevation(&self, i: u32) -> f64 {
        if self.number_of_layers == 1 {
            return self.tilt_angle;
        }
        let step = self.vertical_field_of_view / f64::from(self.number_of_layers - 1);
        self.vertical_field_of_view / 2.0 - f64::from(i) * step + self.tilt_angle
    }

    /// The unit direction (device axes) of the ray of layer `i`, column `j`.
    pub fn direction(&self, i: u32, j: u32) -> Vector3<f64> {
        let (theta, phi) = (self.azimuth(j), self.elevation(i));
        Vector3::new(theta.cos() * phi.cos(), theta.sin() * phi.cos(), phi.sin())
    }

    /// The cosine between the ray `dir` (device axes) and the axis a planar image measures
    /// depth along: the lidar's +x for a fixed lidar, the head's x axis (which faces the
    /// column) for a rotating one.
    fn depth_cosine(&self, dir: &Vector3<f64>) -> f64 {
        match self.lidar_type {
            LidarType::Fixed => dir.x,
            LidarType::Rotating => dir.x.hypot(dir.y),
        }
    }

    /// Every ray's direction, as [`LidarSettings::direction`] gives it, from the sines and
    /// cosines of each column's azimuth and each layer's elevation computed once: a 16 × 1800
    /// image needs 3,632 of them instead of 115,200.
    fn directions(&self) -> Directions {
        Directions {
            columns: (0..self.horizontal_resolution)
                .map(|j| self.azimuth(j).sin_cos())
                .collect(),
            layers: (0..self.number_of_layers)
                .map(|i| self.elevation(i).sin_cos())
                .collect(),
        }
    }
}

/// The sines and cosines of a lidar's ray angles (see [`LidarSettings::directions`]).
struct Directions {
    /// `(sin θ, cos θ)` of each column's azimuth θ.
    columns: Vec<(f64, f64)>,
    /// `(sin φ, cos φ)` of each layer's elevation φ.
    layers: Vec<(f64, f64)>,
}

impl Directions {
    /// The unit direction (device axes) of the ray of layer `i`, column `j` (in range).
    fn at(&self, i: usize, j: usize) -> Vector3<f64> {
        let ((st, ct), (sp, cp)) = (self.columns[j], self.layers[i]);
        Vector3::new(ct * cp, st * cp, sp)
    }
}

/// A lidar sample: its range image (m, row-major, layer 0 first, column 0 leftmost; `+∞` where
/// nothing is within [`minRange`, `maxRange`)), in f32 as Webots' image, and its time.
#[derive(Debug, Clone, PartialEq)]
pub struct LidarReading {
    /// The values, `horizontalResolution · numberOfLayers` of them.
    pub range_image: Vec<f32>,
    /// Simulated time of the sample (s); NaN before the first.
    pub time: f64,
    /// The angle (rad, in [0, 2π)) a rotating lidar's head has turned clockwise since it was
    /// built; 0 for a fixed lidar.
    pub head: f64,
}

impl LidarReading {
    /// The reading before the first sample: every value `+∞` (no return), time NaN.
    pub(crate) fn unsampled(settings: &LidarSettings) -> Self {
        LidarReading {
            range_image: vec![f32::INFINITY; settings.number_of_points()],
            time: f64::NAN,
            head: 0.0,
        }
    }

    /// The range image converted to points (device axes, m), in the image's order: value `r`
    /// of layer `i`, column `j` at `r·(cos θ cos φ, sin θ cos φ, sin φ)` for a cylindrical
    /// image, at depth `r` along that ray for a planar one (`±∞` stays infinite), stamped
    /// `time − j·period/hres` with `period_ms` the sampling period.
    pub fn point_cloud(&self, settings: &LidarSettings, period_ms: u32) -> Vec<LidarPoint> {
        let hres = settings.horizontal_resolution;
        let column_time = f64::from(period_ms) / 1000.0 / f64::from(hres);
        let mut points = Vec::with_capacity(self.range_image.len());
        let directions = settings.directions();
        for i in 0..settings.number_of_layers {
            for j in 0..hres {
                let r = f64::from(self.range_image[(i * hres + j) as usize]);
                let dir = directions.at(i as usize, j as usize);
                let scale = match settings.projection {
                    LidarProjection::Cylindrical => r,
                    LidarProjection::Planar => r / settings.depth_cosine(&dir),
                };
                let p = dir * scale;
                points.push(LidarPoint {
                    x: p.x as f32,
                    y: p.y as f32,
                    z: p.z as f32,
                    layer_id: i as i32,
                    time: (self.time - f64::from(j) * column_time) as f32,
                });
            }
        }
        points
    }
}

/// A point of the cloud: Webots' `WbLidarPoint` (20 bytes, C layout).
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C)]
pub struct LidarPoint {
    /// Position along the lidar's x axis (m).
    pub x: f32,
    /// Along its y axis (m).
    pub y: f32,
    /// Along its z axis (m).
    pub z: f32,
    /// The layer (0 the highest).
    pub layer_id: i32,
    /// When the ray was cast (s of simulated time).
    pub time: f32,
}

/// The lidar's sample at `point` in `scene` at time `time` (s), `dt` (s) after `previous`: a
/// fixed lidar's whole image; a rotating lidar's `previous` image with the columns its head
/// sweeps in `dt` rewritten.
pub(crate) fn measure(
    s: &LidarSettings,
    scene: &Scene<'_>,
    point: &DevicePoint,
    time: f64,
    (previous, dt): (&LidarReading, f64),
    rng: &mut SplitMix64,
) -> LidarReading {
    let directions = s.directions();
    let (columns, head): (Vec<u32>, f64) = match s.lidar_type {
        LidarType::Fixed => ((0..s.horizontal_resolution).collect(), 0.0),
        LidarType::Rotating => {
            let turn = TAU * s.default_frequency * dt;
            let swept = (0..s.horizontal_resolution)
                .filter(|&j| s.swept(j, previous.head, turn))
                .collect();
            (swept, (previous.head + turn).rem_euclid(TAU))
        }
    };
    let mut range_image = if previous.range_image.len() == s.number_of_points() {
        previous.range_image.clone()
    } else {
        vec![f32::INFINITY; s.number_of_points()]
    };
    let hres = s.horizontal_resolution as usize;
    for i in 0..directions.layers.len() {
        for &j in &columns {
            let dir = directions.at(i, j as usize);
            let world = point.rotation * dir;
            // Nothing nearer than `near` is seen: the ray starts there.
            let start = point.position + world * s.near;
            let hit = scene.distance(&start, &world, s.max_range - s.near);
            let value = hit.map_or(f64::INFINITY, |d| {
                let r = s.near + d;
                match s.projection {
                    LidarProjection::Cylindrical => r,
                    LidarProjection::Planar => r * s.depth_cosine(&dir),
                }
            });
            range_image[i * hres + j as usize] = respond(s, value, rng);
        }
    }
    LidarReading {
        range_image,
        time,
        head,
    }
}

/// A measured value `r` (m) as the image holds it: `+∞` outside [`minRange`, `maxRange`), the
/// noise on values strictly inside, then `resolution`.
fn respond(s: &LidarSettings, r: f64, rng: &mut SplitMix64) -> f32 {
    if !(r >= s.min_range && r < s.max_range) {
        return f32::INFINITY;
    }
    let mut r = r;
    if s.noise > 0.0 && r > s.min_range {
        r += s.noise * s.max_range * gaussian(rng);
    }
    if s.resolution != -1.0 {
        r = (r / s.resolution + 0.5).floor() * s.resolution;
    }
    r as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid_and_rays_span_the_fields_of_view() {
        for s in [
            LidarSettings::default(),
            LidarSettings::sick_lms_291(),
            LidarSettings::velodyne_vlp16(),
        ] {
            assert_eq!(s.validate(), Ok(()));
        }
        let s = LidarSettings::velodyne_vlp16();
        // Layer 0 at +vFOV/2, layer 15 at −vFOV/2; columns half a step inside ±fov/2.
        assert!((s.elevation(0) - 0.2618).abs() < 1e-12);
        assert!((s.elevation(15) + 0.2618).abs() < 1e-12);
        let step = webots::VLP16_FOV / 3600.0;
        let edge = webots::VLP16_FOV / 2.0 - step / 2.0;
        assert!((s.azimuth(0) - edge).abs() < 1e-12);
        assert!((s.azimuth(3599) + edge).abs() < 1e-12);
    }

    #[test]
    fn the_tabulated_directions_are_exactly_the_per_ray_ones() {
        // The table only hoists the sines and cosines: every component is bit-identical.
        let s = LidarSettings {
            tilt_angle: -0.1,
            ..LidarSettings::velodyne_vlp16()
        };
        let d = s.directions();
        for i in 0..s.number_of_layers {
            for j in (0..s.horizontal_resolution).step_by(7) {
                assert_eq!(d.at(i as usize, j as usize), s.direction(i, j));
            }
        }
    }

    #[test]
    fn values_outside_the_range_are_infinite() {
        let s = LidarSettings {
            min_range: 0.5,
            max_range: 10.0,
            resolution: 0.25,
            ..LidarSettings::default()
        };
        let mut rng = SplitMix64::new(1);
        assert_eq!(respond(&s, 0.4, &mut rng), f32::INFINITY);
        assert_eq!(respond(&s, 10.0, &mut rng), f32::INFINITY);
        assert_eq!(respond(&s, f64::INFINITY, &mut rng), f32::INFINITY);
        // floor(3.13/0.25 + 0.5)·0.25 = floor(13.02)·0.25 = 3.25.
        assert_eq!(respond(&s, 3.13, &mut rng), 3.25);
    }
}
