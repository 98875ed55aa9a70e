//! Webots' `GPS` (spec §3): the world position of the device point and its velocity.

use proto_geom::nalgebra::{Point3, Vector3};

use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::gps_frame::{GpsCoordinateSystem, GpsFrame};
use super::noise::{discretize, gaussian};
use super::{DevicePoint, check_resolution};

/// The fields of a `GPS` node, with Webots' defaults ([`Default`]).
///
/// `type` ("satellite" / "laser") is ignored by Webots and not held. The frame the position
/// is reported in is the world's ([`GpsFrame`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GpsSettings {
    /// `accuracy` (m, ≥ 0; default 0): standard deviation of the position noise.
    pub accuracy: f64,
    /// `noiseCorrelation` (in [0, 1]; default 0): correlation of the position noise with the
    /// noise one second earlier.
    pub noise_correlation: f64,
    /// `resolution` (m, −1 or > 0; default −1: none).
    pub resolution: f64,
    /// `speedNoise` (≥ 0; default 0): relative standard deviation of the scalar speed.
    pub speed_noise: f64,
    /// `speedResolution` (m/s, −1 or > 0; default −1: none).
    pub speed_resolution: f64,
}

impl Default for GpsSettings {
    fn default() -> Self {
        GpsSettings {
            accuracy: 0.0,
            noise_correlation: 0.0,
            resolution: -1.0,
            speed_noise: 0.0,
            speed_resolution: -1.0,
        }
    }
}

impl GpsSettings {
    /// Checks every field against Webots' range.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::non_negative("accuracy", self.accuracy)?;
        ParamError::check(
            "noiseCorrelation",
            self.noise_correlation,
            "in [0, 1]",
            |c| (0.0..=1.0).contains(&c),
        )?;
        check_resolution("resolution", self.resolution)?;
        ParamError::non_negative("speedNoise", self.speed_noise)?;
        check_resolution("speedResolution", self.speed_resolution)?;
        Ok(())
    }
}

/// A GPS sample: what `wb_gps_get_values`, `wb_gps_get_speed` and
/// `wb_gps_get_speed_vector` return. NaN before the first sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GpsReading {
    /// The device point's world position (m) with the position noise and `resolution`, in the
    /// world's [`GpsFrame`]: plus `gpsReference` (m) in local mode, `[latitude °, longitude °,
    /// altitude m]` in WGS84 mode.
    pub position: Point3<f64>,
    /// Its speed (m/s), with `speedNoise` and `speedResolution`.
    pub speed: f64,
    /// Its velocity (m/s, world axes), exact.
    pub speed_vector: Vector3<f64>,
}

impl GpsReading {
    /// The reading before the first sample: every value NaN.
    pub(crate) fn unsampled() -> Self {
        GpsReading {
            position: Point3::new(f64::NAN, f64::NAN, f64::NAN),
            speed: f64::NAN,
            speed_vector: Vector3::repeat(f64::NAN),
        }
    }
}

/// The GPS's correlated position noise (one standard normal per axis). Webots keeps one such
/// vector for all the GPS devices of a simulation (a bug); here each device has its own.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct GpsNoise(Vector3<f64>);

/// Measures the GPS at `point`, `dt` s after its previous sample, in the world's `frame`.
pub(crate) fn measure(
    settings: &GpsSettings,
    frame: &GpsFrame,
    point: &DevicePoint,
    dt: f64,
    noise: &mut GpsNoise,
    rng: &mut SplitMix64,
) -> GpsReading {
    let mut position = point.position;
    if settings.accuracy != 0.0 {
        // ρ = correlation^Δt: the noise decorrelates over time whatever the sampling period.
        let rho = if settings.noise_correlation == 0.0 {
            0.0
        } else {
            settings.noise_correlation.powf(dt)
        };
        let fresh = (1.0 - rho * rho).sqrt();
        for i in 0..3 {
            noise.0[i] = rho * noise.0[i] + fresh * gaussian(rng);
            position[i] += settings.accuracy * noise.0[i];
        }
    }
    // Spec §3: the reference is added before `resolution` in local mode; in WGS84 mode the
    // noisy, discretised world position is projected.
    let position = match frame.system {
        GpsCoordinateSystem::Local => frame.coordinates(&position),
        GpsCoordinateSystem::Wgs84 => position,
    }
    .map(|p| discretize(p, settings.resolution));
    let position = match frame.system {
        GpsCoordinateSystem::Local => position,
        GpsCoordinateSystem::Wgs84 => frame.coordinates(&position),
    };
    let mut speed = point.velocity.norm();
    // Webots' code makes `speedNoise` relative (its manual says absolute).
    if settings.speed_noise > 0.0 {
        speed *= 1.0 + settings.speed_noise * gaussian(rng);
    }
    GpsReading {
        position,
        speed: discretize(speed, settings.speed_resolution),
        speed_vector: point.velocity,
    }
}
