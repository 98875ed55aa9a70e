//! The GPS frames (spec §3): `gpsReference` added in local mode; in WGS84 mode the reference
//! read back at the origin and a move of 1000 m north read as the latitude change the
//! ellipsoid's meridian radius gives. The UTM series itself is checked against Snyder's
//! published example in `sim::devices::gps_frame`'s unit test.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::devices::{GpsCoordinateSystem, GpsFrame, GpsReading, Reading};
use sim::nalgebra::Point3;
use sim::{Simulation, world_file};

/// Webots' WGS84 ellipsoid: semi-major axis (m) and flattening, and UTM's k0.
const A: f64 = 6_378_137.0;
const F: f64 = 1.0 / 298.257_223_6;
const K0: f64 = 0.9996;

/// The meridian's radius of curvature (m) at latitude `phi` (rad): `a(1−e²)/(1−e²sin²φ)^{3/2}`.
fn meridian_radius(phi: f64) -> f64 {
    let e2 = F * (2.0 - F);
    A * (1.0 - e2) / (1.0 - e2 * phi.sin().powi(2)).powf(1.5)
}

/// The latitude change (°) of `north` m along a central meridian, where UTM's grid north is
/// true north and its scale is k0: `north / (k0·ρ(φ_mid))`, ρ taken at the middle latitude
/// (its variation over 1 km changes the result by ~1e-12°).
fn latitude_change(lat: f64, north: f64) -> f64 {
    let first = north / (K0 * meridian_radius(lat.to_radians()));
    let mid = lat.to_radians() + first / 2.0;
    (north / (K0 * meridian_radius(mid))).to_degrees()
}

fn wgs84(reference: [f64; 3]) -> GpsFrame {
    GpsFrame {
        system: GpsCoordinateSystem::Wgs84,
        reference,
    }
}

#[test]
fn the_reference_reads_back_at_the_origin() {
    // North and south of the equator, on and off their zone's central meridian.
    for reference in [
        [45.0, 3.0, 100.0],
        [46.5, 6.6, 372.0],
        [-33.9, 18.4, 10.0],
        [0.0, -179.0, 0.0],
    ] {
        let p = wgs84(reference).coordinates(&Point3::origin());
        // Tolerance: 1e-8° (1.1 mm): Snyder's forward and inverse series are truncated at
        // different orders (e⁶ and e1⁴), so a round trip returns within ~0.15 mm, not exactly.
        assert!((p.x - reference[0]).abs() < 1e-8, "{reference:?}: {p}");
        assert!((p.y - reference[1]).abs() < 1e-8, "{reference:?}: {p}");
        assert_eq!(p.z, reference[2]);
    }
}

#[test]
fn a_thousand_metres_north_on_the_central_meridian() {
    // Zone 31's central meridian is 3° E.
    for lat in [45.0, -20.0, 60.0] {
        let frame = wgs84([lat, 3.0, 0.0]);
        let p = frame.coordinates(&Point3::new(0.0, 1000.0, 0.0));
        // Tolerance: 1e-8° (1 mm), the series' accuracy.
        assert!(
            (p.x - lat - latitude_change(lat, 1000.0)).abs() < 1e-8,
            "{lat}: {}",
            p.x - lat
        );
        assert!((p.y - 3.0).abs() < 1e-12, "{p}");
        // Up is altitude.
        assert_eq!(frame.coordinates(&Point3::new(0.0, 0.0, 7.0)).z, 7.0);
    }
}

fn gps(root: &str, translation: [f64; 3]) -> (GpsReading, Point3<f64>, Simulation) {
    let text = format!(
        "{root}\n[vehicle]\nmodel = \"BmwX5\"\ntranslation = {translation:?}\n[[vehicle.device]]\ntype = \"GPS\"\n"
    );
    let description = world_file::parse_str("gps.toml", &text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    sim.enable_device(id, 0, 10).unwrap();
    sim.step().unwrap();
    let Reading::Gps(g) = *sim.devices(id).unwrap()[0].reading() else {
        panic!()
    };
    let position = sim.world().vehicle(id).unwrap().state().position;
    (g, position, sim)
}

#[test]
fn a_car_reads_its_gps_in_the_worlds_frame() {
    // Local: the world position plus the reference.
    let (g, p, sim) = gps("gpsReference = [10, 20, 30]", [0.0, 0.0, 0.0]);
    assert_eq!(sim.gps_frame().system, GpsCoordinateSystem::Local);
    assert_eq!(
        g.position,
        p + sim::nalgebra::Vector3::new(10.0, 20.0, 30.0)
    );
    // WGS84, the car 1000 m north of the origin on zone 31's central meridian.
    let (g, p, sim) = gps(
        "gpsCoordinateSystem = \"WGS84\"\ngpsReference = [45, 3, 100]",
        [0.0, 1000.0, 0.0],
    );
    assert_eq!(sim.gps_frame().system.webots_value(), 1);
    // The car is within a millimetre of x = 0 and y = 1000 m (a parked car after one step).
    let expected = 45.0 + latitude_change(45.0, p.y);
    // Tolerance: the 1 mm of the series plus the car's x offset's effect (none to first
    // order on the meridian).
    assert!(
        (g.position.x - expected).abs() < 1e-8,
        "{} vs {expected}",
        g.position.x
    );
    let east = (p.x / (K0 * A * 45f64.to_radians().cos())).to_degrees();
    assert!((g.position.y - 3.0 - east).abs() < 1e-8, "{}", g.position.y);
    assert!((g.position.z - 100.0 - p.z).abs() < 1e-9);
}

#[test]
fn gps_world_keys_are_checked() {
    let car = "[vehicle]\nmodel = \"BmwX5\"\n";
    let e = world_file::parse_str("w.toml", &format!("gpsCoordinateSystem = \"ECEF\"\n{car}"))
        .expect_err("an unknown system is refused");
    assert_eq!(e.key.as_deref(), Some("gpsCoordinateSystem"));
    assert!(e.to_string().contains("WGS84"), "{e}");
    let e = world_file::parse_str(
        "w.toml",
        &format!("gpsCoordinateSystem = \"WGS84\"\ngpsReference = [95, 0, 0]\n{car}"),
    )
    .expect_err("a latitude beyond UTM is refused");
    assert_eq!(e.key.as_deref(), Some("gpsReference"));
}
