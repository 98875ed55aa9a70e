//! Webots' `DistanceSensor` (spec §6): one or several rays cast from the device along its +x
//! axis, their distances combined by the sensor's `type`, then the `lookupTable`.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_8, PI, TAU};

use proto_geom::nalgebra::Vector3;

use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::lookup::LookupTable;
use super::noise::discretize;
use super::rays::Scene;
use super::{DevicePoint, check_resolution};

/// The `type` field: how the rays' distances make one distance.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DistanceSensorType {
    /// `"generic"`: the weighted mean of the rays' distances, a miss counting as the range.
    Generic,
    /// `"infra-red"` (or `"infrared"`): the weighted mean distance lengthened by how little
    /// red the surfaces hit reflect, scaled by `redColorSensitivity` (spec §6).
    InfraRed,
    /// `"sonar"`: the nearest ray whose incidence on the surface is below π/8 rad; the range
    /// if none.
    Sonar,
    /// `"laser"`: one ray along +x.
    Laser,
}

impl DistanceSensorType {
    /// Every type.
    pub const ALL: [DistanceSensorType; 4] = [
        DistanceSensorType::Generic,
        DistanceSensorType::InfraRed,
        DistanceSensorType::Sonar,
        DistanceSensorType::Laser,
    ];

    /// The `type` string.
    pub const fn webots_name(self) -> &'static str {
        match self {
            DistanceSensorType::Generic => "generic",
            DistanceSensorType::InfraRed => "infra-red",
            DistanceSensorType::Sonar => "sonar",
            DistanceSensorType::Laser => "laser",
        }
    }

    /// The `WbDistanceSensorType` value (`WB_DISTANCE_SENSOR_GENERIC` 0, `_INFRA_RED` 1,
    /// `_SONAR` 2, `_LASER` 3).
    pub const fn webots_value(self) -> i32 {
        match self {
            DistanceSensorType::Generic => 0,
            DistanceSensorType::InfraRed => 1,
            DistanceSensorType::Sonar => 2,
            DistanceSensorType::Laser => 3,
        }
    }
}

/// The fields of a `DistanceSensor` node, with Webots' defaults ([`Default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct DistanceSensorSettings {
    /// `lookupTable`: rows `[distance (m), value, relative noise]`; default
    /// `[[0, 0, 0], [0.1, 1000, 0]]`. Its largest input is the rays' length (m).
    pub lookup_table: LookupTable,
    /// `type` (default generic).
    pub sensor_type: DistanceSensorType,
    /// `numberOfRays` (≥ 1; default 1); a laser has one whatever this says.
    pub number_of_rays: u32,
    /// `aperture` (rad, ≥ 0; default 1.5708): the cone the rays spread over.
    pub aperture: f64,
    /// `gaussianWidth` (> 0; default 1): the width of the rays' weights, relative to the
    /// aperture.
    pub gaussian_width: f64,
    /// `resolution` (the value's unit, −1 or > 0; default −1: none).
    pub resolution: f64,
    /// `redColorSensitivity` (≥ 0, dimensionless; default 1): how much an infra-red sensor's
    /// distance grows on surfaces that reflect little red; no effect on the other types.
    pub red_color_sensitivity: f64,
}

impl Default for DistanceSensorSettings {
    fn default() -> Self {
        DistanceSensorSettings {
            lookup_table: LookupTable::new(vec![[0.0, 0.0, 0.0], [0.1, 1000.0, 0.0]])
                .unwrap_or_default(),
            sensor_type: DistanceSensorType::Generic,
            number_of_rays: 1,
            aperture: WEBOTS_APERTURE,
            gaussian_width: 1.0,
            resolution: -1.0,
            red_color_sensitivity: 1.0,
        }
    }
}

/// Webots' default `aperture` (rad): the node's value as written in `DistanceSensor.wrl`, a
/// rounded π/2 kept as Webots has it.
#[allow(
    clippy::approx_constant,
    reason = "Webots' literal field value, not π/2"
)]
const WEBOTS_APERTURE: f64 = 1.5708;

/// The most rays a distance sensor may cast: Webots sets no bound, but each ray is a cast per
/// sample and real sensors model their cone with a few dozen.
pub const MAX_DISTANCE_SENSOR_RAYS: u32 = 1000;

impl DistanceSensorSettings {
    /// Checks every field against its range (Webots turns a negative aperture or red colour
    /// sensitivity positive and a non-positive gaussian width into 1; here they are refused).
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::check(
            "numberOfRays",
            f64::from(self.number_of_rays),
            "at least 1 and at most 1000",
            |n| (1.0..=f64::from(MAX_DISTANCE_SENSOR_RAYS)).contains(&n),
        )?;
        ParamError::check(
            "aperture",
            self.aperture,
            "finite, >= 0 and at most 2π",
            |a| (0.0..=TAU).contains(&a),
        )?;
        ParamError::positive("gaussianWidth", self.gaussian_width)?;
        ParamError::non_negative("redColorSensitivity", self.red_color_sensitivity)?;
        check_resolution("resolution", self.resolution)
    }

    /// The rays' length (m): the lookup table's largest input; `None` for an empty table.
    pub fn range(&self) -> Option<f64> {
        self.lookup_table.rows().last().map(|r| r[0])
    }

    /// The largest value of the table (`wb_distance_sensor_get_max_value`), 0 if empty.
    pub fn max_value(&self) -> f64 {
        let rows = self.lookup_table.rows();
        rows.iter().map(|r| r[1]).reduce(f64::max).unwrap_or(0.0)
    }

    /// The smallest value of the table (`wb_distance_sensor_get_min_value`), 0 if empty.
    pub fn min_value(&self) -> f64 {
        let rows = self.lookup_table.rows();
        rows.iter().map(|r| r[1]).reduce(f64::min).unwrap_or(0.0)
    }

    /// The number of rays cast: 1 for a laser or an aperture of 0, else `numberOfRays`.
    fn ray_count(&self) -> u32 {
        if self.sensor_type == DistanceSensorType::Laser || self.aperture == 0.0 {
            1
        } else {
            self.number_of_rays
        }
    }
}

/// Webots' ray pattern for `n` rays: `(α, ρ)` pairs, α the angle around +x (rad) and ρ the
/// fraction of the half-aperture the ray leans by.
fn pattern(n: u32) -> Vec<(f64, f64)> {
    let ring =
        |count: u32, step: f64, rho: f64| (0..count).map(move |k| (f64::from(k) * step, rho));
    let third = 2.0 * PI / 3.0;
    match n {
        0 | 1 => vec![(0.0, 0.0)],
        2 => vec![(FRAC_PI_2, 1.0), (-FRAC_PI_2, 1.0)],
        3 => vec![(0.0, 1.0), (third, 1.0), (-third, 1.0)],
        4 => vec![(0.0, 0.0), (0.0, 1.0), (third, 1.0), (-third, 1.0)],
        5 => vec![
            (0.0, 0.0),
            (0.0, 1.0),
            (FRAC_PI_2, 1.0),
            (PI, 1.0),
            (-FRAC_PI_2, 1.0),
        ],
        6..=8 => {
            let step = match n {
                6 => TAU / 5.0,
                7 => PI / 3.0,
                _ => TAU / 7.0,
            };
            std::iter::once((0.0, 0.0))
                .chain(ring(n - 1, step, 1.0))
                .collect()
        }
        9 => [(0.0, 0.3), (third, 0.3), (-third, 0.3)]
            .into_iter()
            .chain(ring(6, PI / 3.0, 1.0))
            .collect(),
        10 => [(0.0, 0.0), (0.0, 0.5), (third, 0.5), (-third, 0.5)]
            .into_iter()
            .chain(ring(6, PI / 3.0, 1.0))
            .collect(),
        _ => {
            // Cones c = 0, 1, … of up to 3c + 1 rays, the last taking what is left.
            let mut sizes = Vec::new();
            let mut left = n;
            let mut c = 0;
            while left > 0 {
                let size = (3 * c + 1).min(left);
                sizes.push(size);
                left -= size;
                c += 1;
            }
            let last = (sizes.len() - 1) as f64;
            sizes
                .iter()
                .enumerate()
                .flat_map(|(c, &m)| ring(m, TAU / f64::from(m), c as f64 / last))
                .collect()
        }
    }
}

/// The unit directions (device axes) of the rays of `settings` and their weights (summing to
/// 1).
pub(crate) fn rays(settings: &DistanceSensorSettings) -> Vec<(Vector3<f64>, f64)> {
    let n = settings.ray_count();
    let spread = settings.aperture * settings.gaussian_width;
    let mut rays: Vec<(Vector3<f64>, f64)> = pattern(n)
        .into_iter()
        .map(|(alpha, rho)| {
            let a = alpha + FRAC_PI_2;
            let theta = rho * settings.aperture / 2.0;
            let dir = Vector3::new(theta.cos(), -theta.sin() * a.cos(), theta.sin() * a.sin());
            let weight = if n > 1 {
                (-(theta / spread).powi(2)).exp()
            } else {
                1.0
            };
            (dir, weight)
        })
        .collect();
    let total: f64 = rays.iter().map(|r| r.1).sum();
    for r in &mut rays {
        r.1 /= total;
    }
    rays
}

/// The distance (m) the sensor at `point` measures in `scene` along `rays`, before its table.
fn distance(
    settings: &DistanceSensorSettings,
    range: f64,
    rays: &[(Vector3<f64>, f64)],
    scene: &Scene<'_>,
    point: &DevicePoint,
) -> f64 {
    let cast = |dir: &Vector3<f64>| {
        let world = point.rotation * dir;
        scene
            .cast(&point.position, &world, range)
            .map(|h| (h, world))
    };
    match settings.sensor_type {
        DistanceSensorType::Generic => rays
            .iter()
            .map(|(dir, w)| w * cast(dir).map_or(range, |(h, _)| h.distance))
            .sum(),
        DistanceSensorType::InfraRed => {
            // d̄ = Σ wᵢdᵢ and F = Σ wᵢfᵢ, fᵢ = 0.2 + 0.8·red on a hit (roughness and occlusion
            // 0: no surface here is PBR), 1 on a miss (which counts as the range, as in
            // generic); F ≥ 0.2, so d̄/F is finite.
            let (mean, factor) = rays
                .iter()
                .fold((0.0, 0.0), |(d, f), (dir, w)| match cast(dir) {
                    Some((h, _)) => (
                        d + w * h.distance,
                        f + w * (0.2 + 0.8 * scene.red(h.collider)),
                    ),
                    None => (d + w * range, f + w),
                });
            mean + (mean / factor - mean) * settings.red_color_sensitivity
        }
        DistanceSensorType::Laser => rays
            .first()
            .and_then(|(dir, _)| cast(dir))
            .map_or(range, |(h, _)| h.distance),
        DistanceSensorType::Sonar => rays
            .iter()
            .filter_map(|(dir, _)| cast(dir))
            // The echo comes back only from a surface the ray meets within π/8 of its normal.
            .filter(|(h, world)| h.normal.dot(world).abs().min(1.0).acos() < FRAC_PI_8)
            .map(|(h, _)| h.distance)
            .fold(range, f64::min),
    }
}

/// The sensor's value at `point` in `scene`: its table at the measured distance, then
/// `resolution`; 0 for an empty table (no rays).
pub(crate) fn measure(
    settings: &DistanceSensorSettings,
    scene: &Scene<'_>,
    point: &DevicePoint,
    rng: &mut SplitMix64,
) -> f64 {
    let Some(range) = settings.range() else {
        return 0.0;
    };
    let d = distance(settings, range, &rays(settings), scene, point);
    discretize(settings.lookup_table.apply(d, rng), settings.resolution)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ray_weights_are_gaussian_and_sum_to_one() {
        for n in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 25] {
            let s = DistanceSensorSettings {
                number_of_rays: n,
                ..DistanceSensorSettings::default()
            };
            let r = rays(&s);
            assert_eq!(r.len(), n as usize, "{n} rays");
            let total: f64 = r.iter().map(|r| r.1).sum();
            // Tolerance: n additions in f64.
            assert!((total - 1.0).abs() < 1e-12);
            for (dir, _) in &r {
                assert!((dir.norm() - 1.0).abs() < 1e-12);
                // No ray leans more than half the aperture from +x.
                assert!(dir.x.min(1.0).acos() <= s.aperture / 2.0 + 1e-12);
            }
        }
        // Two rays lean ±aperture/2 about +z (α' = π or 0): in the x–y plane, equal weights.
        let s = DistanceSensorSettings {
            number_of_rays: 2,
            ..DistanceSensorSettings::default()
        };
        let r = rays(&s);
        let h = s.aperture / 2.0;
        assert!((r[0].0 - Vector3::new(h.cos(), h.sin(), 0.0)).norm() < 1e-12);
        assert!((r[1].0 - Vector3::new(h.cos(), -h.sin(), 0.0)).norm() < 1e-12);
        assert_eq!(r[0].1, 0.5);
        // A laser casts one ray whatever `numberOfRays` says.
        let laser = DistanceSensorSettings {
            number_of_rays: 5,
            sensor_type: DistanceSensorType::Laser,
            ..DistanceSensorSettings::default()
        };
        assert_eq!(rays(&laser), vec![(Vector3::x(), 1.0)]);
    }

    #[test]
    fn table_bounds() {
        let s = DistanceSensorSettings::default();
        assert_eq!(
            (s.min_value(), s.max_value(), s.range()),
            (0.0, 1000.0, Some(0.1))
        );
        let empty = DistanceSensorSettings {
            lookup_table: LookupTable::default(),
            ..s
        };
        assert_eq!(
            (empty.min_value(), empty.max_value(), empty.range()),
            (0.0, 0.0, None)
        );
    }
}
