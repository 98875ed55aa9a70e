//! The frame a GPS reports in (spec §3): Webots' `WorldInfo.gpsCoordinateSystem` and
//! `gpsReference`, and the UTM projection a WGS84 GPS goes through.
//!
//! The projection is the transverse Mercator series of Snyder, *Map Projections — A Working
//! Manual* (USGS Professional Paper 1395, 1987), eqs. 8-9 to 8-25 (pp. 61–64), with
//! `k0 = 0.9996` and a false easting of 500 000 m, on the ellipsoid Webots uses (`a = 6 378 137 m`, `f = 1/298.2572236`). Its error is
//! below a millimetre within a few degrees of the central meridian.

use proto_geom::nalgebra::{Point3, Vector3};

use crate::error::ParamError;

/// Webots' WGS84 semi-major axis (m).
const A: f64 = 6_378_137.0;
/// Webots' WGS84 flattening, as its code writes it.
const F: f64 = 1.0 / 298.257_223_6;
/// UTM's scale on the central meridian.
const K0: f64 = 0.9996;
/// UTM's false easting (m).
const FALSE_EASTING: f64 = 500_000.0;

/// `WorldInfo.gpsCoordinateSystem`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GpsCoordinateSystem {
    /// `"local"`: the world position (m) plus `gpsReference` (m).
    #[default]
    Local,
    /// `"WGS84"`: latitude (°), longitude (°) and altitude (m), `gpsReference` being those of
    /// the world's origin.
    Wgs84,
}

impl GpsCoordinateSystem {
    /// The field's string.
    pub const fn webots_name(self) -> &'static str {
        match self {
            GpsCoordinateSystem::Local => "local",
            GpsCoordinateSystem::Wgs84 => "WGS84",
        }
    }

    /// `WbGpsCoordinateSystem`: `WB_GPS_LOCAL_COORDINATE` 0, `WB_GPS_WGS84_COORDINATE` 1.
    pub const fn webots_value(self) -> i32 {
        match self {
            GpsCoordinateSystem::Local => 0,
            GpsCoordinateSystem::Wgs84 => 1,
        }
    }
}

/// The world's GPS frame: its coordinate system and reference ([`Default`]: local, `[0, 0, 0]`,
/// Webots' defaults). The world's axes are east (x), north (y) and up (z).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct GpsFrame {
    /// `gpsCoordinateSystem`.
    pub system: GpsCoordinateSystem,
    /// `gpsReference`: added to the world position in local mode (m); the origin's
    /// `[latitude °, longitude °, altitude m]` in WGS84 mode.
    pub reference: [f64; 3],
}

impl GpsFrame {
    /// Checks the reference: finite; in WGS84 mode a latitude in [−80°, 84°] (where UTM is
    /// defined) and a longitude in [−180°, 180°].
    ///
    /// # Errors
    /// A [`ParamError`] naming `gpsReference` and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        for r in self.reference {
            ParamError::finite("gpsReference", r)?;
        }
        if self.system == GpsCoordinateSystem::Wgs84 {
            let [lat, lon, _] = self.reference;
            ParamError::check(
                "gpsReference",
                lat,
                "a latitude in [-80, 84] degrees (UTM's extent)",
                |l| (-80.0..=84.0).contains(&l),
            )?;
            ParamError::check(
                "gpsReference",
                lon,
                "a longitude in [-180, 180] degrees",
                |l| (-180.0..=180.0).contains(&l),
            )?;
        }
        Ok(())
    }

    /// What a GPS at world position `p` (m) reports: `p + reference` in local mode; in WGS84
    /// mode the reference projected to UTM (its own zone and hemisphere), moved by `p` along
    /// east, north and up, and projected back: `[latitude °, longitude °, altitude m]`.
    pub fn coordinates(&self, p: &Point3<f64>) -> Point3<f64> {
        match self.system {
            GpsCoordinateSystem::Local => p + Vector3::from(self.reference),
            GpsCoordinateSystem::Wgs84 => {
                let [lat, lon, alt] = self.reference;
                let zone = ((lon + 180.0) / 6.0).floor().clamp(0.0, 59.0);
                let meridian = (zone * 6.0 - 180.0 + 3.0).to_radians();
                // The southern false northing (10⁷ m) is added on the way there and taken off
                // on the way back: it cancels, so it is not written.
                let e = Ellipsoid::new(A, F);
                let (x, y) = e.forward(lat.to_radians(), lon.to_radians() - meridian);
                let (phi, dlambda) = e.inverse(x + p.x, y + p.y);
                Point3::new(
                    phi.to_degrees(),
                    (meridian + dlambda).to_degrees(),
                    alt + p.z,
                )
            }
        }
    }
}

/// An ellipsoid's constants for Snyder's series.
struct Ellipsoid {
    /// Semi-major axis (m).
    a: f64,
    /// First eccentricity squared.
    e2: f64,
    /// Second eccentricity squared.
    ep2: f64,
}

impl Ellipsoid {
    /// The ellipsoid of semi-major axis `a` (m) and flattening `f`.
    fn new(a: f64, f: f64) -> Self {
        let e2 = f * (2.0 - f);
        Ellipsoid {
            a,
            e2,
            ep2: e2 / (1.0 - e2),
        }
    }

    /// The meridian's length (m) from the equator to latitude `phi` (rad), eq. 3-21.
    fn meridian(&self, phi: f64) -> f64 {
        let (e2, e4, e6) = (self.e2, self.e2 * self.e2, self.e2 * self.e2 * self.e2);
        self.a
            * ((1.0 - e2 / 4.0 - 3.0 * e4 / 64.0 - 5.0 * e6 / 256.0) * phi
                - (3.0 * e2 / 8.0 + 3.0 * e4 / 32.0 + 45.0 * e6 / 1024.0) * (2.0 * phi).sin()
                + (15.0 * e4 / 256.0 + 45.0 * e6 / 1024.0) * (4.0 * phi).sin()
                - (35.0 * e6 / 3072.0) * (6.0 * phi).sin())
    }

    /// UTM `(x, y)` (m, with the false easting, without a false northing) of latitude `phi` and
    /// longitude `dlambda` from the central meridian (rad), eqs. 8-9 and 8-10.
    fn forward(&self, phi: f64, dlambda: f64) -> (f64, f64) {
        let (s, c) = phi.sin_cos();
        let n = self.a / (1.0 - self.e2 * s * s).sqrt();
        let t = (s / c).powi(2);
        let cc = self.ep2 * c * c;
        let a = dlambda * c;
        let x = K0
            * n
            * (a + (1.0 - t + cc) * a.powi(3) / 6.0
                + (5.0 - 18.0 * t + t * t + 72.0 * cc - 58.0 * self.ep2) * a.powi(5) / 120.0);
        let y = K0
            * (self.meridian(phi)
                + n * (s / c)
                    * (a * a / 2.0
                        + (5.0 - t + 9.0 * cc + 4.0 * cc * cc) * a.powi(4) / 24.0
                        + (61.0 - 58.0 * t + t * t + 600.0 * cc - 330.0 * self.ep2) * a.powi(6)
                            / 720.0));
        (x + FALSE_EASTING, y)
    }

    /// Latitude and longitude from the central meridian (rad) of UTM `(x, y)` (m, with the
    /// false easting, without the false northing), eqs. 8-12 to 8-25 and 3-26.
    fn inverse(&self, x: f64, y: f64) -> (f64, f64) {
        let (e2, e4, e6) = (self.e2, self.e2 * self.e2, self.e2 * self.e2 * self.e2);
        let mu = y / K0 / (self.a * (1.0 - e2 / 4.0 - 3.0 * e4 / 64.0 - 5.0 * e6 / 256.0));
        let r = (1.0 - e2).sqrt();
        let e1 = (1.0 - r) / (1.0 + r);
        let phi1 = mu
            + (3.0 * e1 / 2.0 - 27.0 * e1.powi(3) / 32.0) * (2.0 * mu).sin()
            + (21.0 * e1 * e1 / 16.0 - 55.0 * e1.powi(4) / 32.0) * (4.0 * mu).sin()
            + (151.0 * e1.powi(3) / 96.0) * (6.0 * mu).sin()
            + (1097.0 * e1.powi(4) / 512.0) * (8.0 * mu).sin();
        let (s, c) = phi1.sin_cos();
        let c1 = self.ep2 * c * c;
        let t1 = (s / c).powi(2);
        let w = 1.0 - e2 * s * s;
        let n1 = self.a / w.sqrt();
        let r1 = self.a * (1.0 - e2) / w.powf(1.5);
        let d = (x - FALSE_EASTING) / (n1 * K0);
        let phi = phi1
            - (n1 * (s / c) / r1)
                * (d * d / 2.0
                    - (5.0 + 3.0 * t1 + 10.0 * c1 - 4.0 * c1 * c1 - 9.0 * self.ep2) * d.powi(4)
                        / 24.0
                    + (61.0 + 90.0 * t1 + 298.0 * c1 + 45.0 * t1 * t1
                        - 252.0 * self.ep2
                        - 3.0 * c1 * c1)
                        * d.powi(6)
                        / 720.0);
        let lambda = (d - (1.0 + 2.0 * t1 + c1) * d.powi(3) / 6.0
            + (5.0 - 2.0 * c1 + 28.0 * t1 - 3.0 * c1 * c1 + 8.0 * self.ep2 + 24.0 * t1 * t1)
                * d.powi(5)
                / 120.0)
            / c;
        (phi, lambda)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snyders_worked_example() {
        // Snyder (1987), p. 269–270: φ = 40°30′ N, λ = 73°30′ W on the Clarke 1866 ellipsoid
        // (a = 6 378 206.4 m, e² = 0.006 768 66), central meridian 75° W, k0 = 0.9996:
        // x = 127 106.5 m, y = 4 484 124.4 m (published to 0.1 m).
        let clarke = Ellipsoid {
            a: 6_378_206.4,
            e2: 0.006_768_66,
            ep2: 0.006_768_66 / (1.0 - 0.006_768_66),
        };
        let (phi, dlambda) = (40.5f64.to_radians(), 1.5f64.to_radians());
        let (x, y) = clarke.forward(phi, dlambda);
        // Tolerance: the published rounding (0.05 m).
        assert!((x - FALSE_EASTING - 127_106.5).abs() < 0.05, "{x}");
        assert!((y - 4_484_124.4).abs() < 0.05, "{y}");
        // And back, to the series' sub-millimetre accuracy (1e-10 rad ≈ 0.6 mm).
        let (p, l) = clarke.inverse(x, y);
        assert!((p - phi).abs() < 1e-10 && (l - dlambda).abs() < 1e-10);
    }
}
