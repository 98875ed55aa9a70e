//! Webots sensor devices on a car against analytic values: a steady circle (GPS, gyro,
//! accelerometer, inertial unit), a car parked on a 10 % slope (accelerometer), a car heading
//! north-east (compass), lookup tables and resolution, sampling periods, noise.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::devices::{GpsReading, InertialUnitReading, Reading};
use sim::nalgebra::{Matrix3, Point3, Vector3};
use sim::{CarBuilder, Simulation, VehicleId, VehiclePlacement, World, world_file};

/// The simulation of world `text` and its one car.
fn world(text: &str) -> (Simulation, VehicleId) {
    let description = world_file::parse_str("devices.toml", text).unwrap();
    let (sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    (sim, id)
}

/// Device `name` of car `id`: its index and last reading.
fn reading(sim: &Simulation, id: VehicleId, name: &str) -> (usize, Reading) {
    let devices = sim.devices(id).unwrap();
    let i = devices.iter().position(|d| d.name() == name).unwrap();
    (i, devices[i].reading().clone())
}

fn enable(sim: &mut Simulation, id: VehicleId, name: &str, period_ms: u32) {
    let (i, _) = reading(sim, id, name);
    sim.enable_device(id, i, period_ms).unwrap();
}

fn vector(sim: &Simulation, id: VehicleId, name: &str) -> Vector3<f64> {
    match reading(sim, id, name).1 {
        Reading::Vector(v) => v,
        other => panic!("{name}: {other:?}"),
    }
}

fn gps(sim: &Simulation, id: VehicleId, name: &str) -> GpsReading {
    match reading(sim, id, name).1 {
        Reading::Gps(g) => g,
        other => panic!("{name}: {other:?}"),
    }
}

fn inertial_unit(sim: &Simulation, id: VehicleId, name: &str) -> InertialUnitReading {
    match reading(sim, id, name).1 {
        Reading::InertialUnit(u) => u,
        other => panic!("{name}: {other:?}"),
    }
}

/// Centre and radius (m) of the least-squares circle through `points` (Kåsa's fit:
/// x² + y² + a·x + b·y + c = 0 is linear in a, b, c).
fn circle(points: &[Point3<f64>]) -> (Point3<f64>, f64) {
    let mut m = Matrix3::zeros();
    let mut r = Vector3::zeros();
    for p in points {
        let row = Vector3::new(p.x, p.y, 1.0);
        m += row * row.transpose();
        r -= row * (p.x * p.x + p.y * p.y);
    }
    let abc = m.lu().solve(&r).unwrap();
    let centre = Point3::new(-abc.x / 2.0, -abc.y / 2.0, 0.0);
    let radius = (centre.x * centre.x + centre.y * centre.y - abc.z).sqrt();
    (centre, radius)
}

const G: f64 = 9.81; // m/s², the world's default gravity

#[test]
fn steady_circle() {
    // A BmwX5 at 20 km/h with 0.15 rad of steering to the right; the devices on the roof slot
    // (1 m ahead of the rear axle, 1.45 m up), so the device point is not the car's origin.
    let (mut sim, id) = world(
        r#"
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "GPS"
slot = "top"
[[vehicle.device]]
type = "Gyro"
slot = "top"
[[vehicle.device]]
type = "Accelerometer"
slot = "top"
[[vehicle.device]]
type = "InertialUnit"
slot = "top"
"#,
    );
    for name in ["gps", "gyro", "accelerometer", "inertial unit"] {
        enable(&mut sim, id, name, 10);
    }
    sim.driver_mut(id).unwrap().set_cruising_speed(20.0);
    sim.driver_mut(id).unwrap().set_steering_angle(0.15);
    // 15 s to reach the steady turn, then 10 s of samples.
    for _ in 0..1500 {
        sim.step().unwrap();
    }
    let mut track = Vec::new();
    let mut samples = Vec::new();
    for _ in 0..1000 {
        sim.step().unwrap();
        let g = gps(&sim, id, "gps");
        track.push(g.position);
        samples.push((
            g,
            vector(&sim, id, "gyro"),
            vector(&sim, id, "accelerometer"),
            inertial_unit(&sim, id, "inertial unit"),
            sim.telemetry(id).unwrap(),
        ));
    }
    let (centre, radius) = circle(&track);
    let mut worst = [0.0f64; 6];
    for (g, gyro, accel, unit, telemetry) in &samples {
        // The GPS point's distance from the centre is the fitted radius (the turn is steady):
        // 2 cm, the spread of the steady turn's radius over the samples.
        let r = (g.position - centre).xy().norm();
        worst[0] = worst[0].max((r - radius).abs());
        // Rigid planar motion: speed = R·|ω| at the device point.
        let v = g.speed;
        worst[1] = worst[1].max((v - radius * gyro.z.abs()).abs());
        // A right turn: the yaw rate is negative, as the telemetry's.
        assert!(gyro.z < 0.0);
        // The chassis' angular velocity in its own axes (the top slot is not rotated).
        let s = &telemetry.state;
        let body_rate = s.orientation.inverse() * s.angular_velocity;
        worst[2] = worst[2].max((gyro - body_rate).norm());
        // The accelerometer gives Rᵀ(a − g), a = v²/R towards the centre (horizontal), with the
        // device's orientation measured by the inertial unit.
        let to_centre = (centre - g.position).xy().normalize();
        let a = Vector3::new(to_centre.x, to_centre.y, 0.0) * (v * v / radius);
        let q = sim::nalgebra::UnitQuaternion::new_normalize(unit.quaternion);
        let expected = q.inverse() * (a + Vector3::new(0.0, 0.0, G));
        worst[3] = worst[3].max((accel - expected).norm());
        // The lateral specific force is mostly the centripetal v²/R (the body's roll adds
        // g·sin φ, a few hundredths of g).
        worst[4] = worst[4].max((accel.y + v * v / radius).abs());
        // Heading: the inertial unit's yaw is the chassis' (same orientation on the top slot).
        let yaw = unit.roll_pitch_yaw().yaw;
        worst[5] = worst[5].max((yaw - telemetry.state.roll_pitch_yaw.yaw).abs());
    }
    let v = samples[0].0.speed;
    assert!((v - 20.0 / 3.6).abs() < 0.3, "{v} m/s");
    assert!(radius > 10.0 && radius < 40.0, "{radius} m");
    // Tolerances: 2 cm of radius and 0.02 m/s of speed for the steady turn's own wobble
    // (the cruise control holds the speed within a few mm/s); 1e-12 rad/s between the gyro
    // and the telemetry (the same f64 rotation of the same f32 values); 0.03 m/s² for the accelerometer
    // (its finite difference over one 10 ms step rotates the centripetal by ωΔt/2, 1 mrad, and
    // the turn's wobble); 0.3 m/s² for the roll's g·sin φ; 1e-6 rad of heading (f32).
    let limits = [0.02, 0.02, 1e-12, 0.03, 0.3, 1e-6];
    for (i, (w, limit)) in worst.iter().zip(limits).enumerate() {
        assert!(
            w < &limit,
            "check {i}: {w} >= {limit} (R = {radius} m, v = {v} m/s)"
        );
    }
}

#[test]
fn accelerometer_on_a_ten_percent_slope() {
    // A 40 m ramp rising 4 m (10 %) along +x; the car stands on its middle facing uphill,
    // dropped from 0.8 m above the slope (its `translation` z is not used: a world file's car
    // starts on the flat ground) and held by its brakes.
    let description = world_file::parse_str(
        "slope.toml",
        r#"
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Accelerometer"
[[vehicle.device]]
type = "InertialUnit"
[[ramp]]
start = [0, 0]
length = 40
width = 6
height = 4
"#,
    )
    .unwrap();
    let mut sim = Simulation::new(World::new(description.config.clone()).unwrap());
    let placement = VehiclePlacement {
        x: 18.0,
        y: 0.0,
        yaw: 0.0,
        z: Some(2.6),
    };
    let car = CarBuilder::from(&description.cars[0]).placement(placement);
    let (id, _) = sim.add_car(car).unwrap();
    sim.driver_mut(id).unwrap().set_brake_intensity(1.0);
    for _ in 0..300 {
        sim.step().unwrap();
    }
    enable(&mut sim, id, "accelerometer", 10);
    enable(&mut sim, id, "inertial unit", 10);
    // The first sample includes v/Δt from v_prev = 0 (Webots); the car is at rest, so no.
    for _ in 0..200 {
        sim.step().unwrap();
    }
    let a = vector(&sim, id, "accelerometer");
    let theta = 0.1f64.atan();
    // Nose up: gravity's reaction leans forward in the car frame.
    let expected = Vector3::new(G * theta.sin(), 0.0, G * theta.cos());
    // Tolerance 0.06 m/s² (g·6 mrad): the body is not parallel to the slope. It sits 3 mrad
    // nose-up on its springs on flat ground (the compass test sees it), and the downhill rear
    // axle's extra load adds about 2 mrad (measured: 5 mrad in all).
    assert!((a - expected).norm() < 0.06, "{a} vs {expected}");
    // The same through the inertial unit's pitch: nose up is negative pitch (ENU); 6 mrad.
    let pitch = inertial_unit(&sim, id, "inertial unit")
        .roll_pitch_yaw()
        .pitch;
    assert!((pitch + theta).abs() < 6e-3, "{pitch}");
    // At rest the accelerometer reads −g in its own frame: |a| = g, and its tilt is the
    // inertial unit's pitch. Tolerances 1e-3 m/s² and 1e-4 rad: the car creeps by less
    // than 0.1 mm/s² on its springs after 3 s.
    assert!((a.norm() - G).abs() < 1e-3, "{}", a.norm());
    assert!((a.x.atan2(a.z) + pitch).abs() < 1e-4, "{a} {pitch}");
}

#[test]
fn compass_of_a_car_heading_north_east() {
    let (mut sim, id) = world(
        r#"
[vehicle]
model = "BmwX5"
rotation = [0, 0, 1, 0.7853981633974483]
[[vehicle.device]]
type = "Compass"
[[vehicle.device]]
type = "Compass"
name = "rear compass"
slot = "rear"
[[vehicle.device]]
type = "Compass"
name = "scaled"
lookupTable = [[-1, -100, 0], [1, 100, 0]]
resolution = 0.7
zAxis = false
"#,
    );
    for name in ["compass", "rear compass", "scaled"] {
        enable(&mut sim, id, name, 10);
    }
    for _ in 0..100 {
        sim.step().unwrap();
    }
    let n = vector(&sim, id, "compass");
    // Exactly world +y in the chassis axes the telemetry gives, normalised as Webots does (the
    // f32 orientation is a unit quaternion to 1e-7 only); 1e-12: f64 rounding.
    let q = sim.telemetry(id).unwrap().state.orientation;
    assert!(
        (n - (q.inverse() * Vector3::y()).normalize()).norm() < 1e-12,
        "{n}"
    );
    // North (world +y) in a frame turned π/4 from east: (sin π/4, cos π/4, 0). Tolerance 5e-3:
    // the parked body's pitch on its suspension (3 mrad nose down, measured).
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!((n - Vector3::new(h, h, 0.0)).norm() < 5e-3, "{n}");
    // Heading clockwise from north of the x axis: atan2(n_y, n_x) = π/4 (north-east); the
    // pitch leaves it (1e-5 rad: it tilts n out of the horizontal plane only).
    assert!((n.y.atan2(n.x) - std::f64::consts::FRAC_PI_4).abs() < 1e-5);
    // The rear slot faces backward: north is mirrored in x and y.
    let rear = vector(&sim, id, "rear compass");
    assert!(
        (rear + Vector3::new(n.x, n.y, -n.z)).norm() < 1e-6,
        "{rear}"
    );
    // The lookup table maps [-1, 1] to [-100, 100], then resolution 0.7 with C's truncation.
    let scaled = vector(&sim, id, "scaled");
    for i in 0..2 {
        let table = -100.0 + (n[i] + 1.0) / 2.0 * 200.0;
        let expected = (table / 0.7 + 0.5).trunc() * 0.7;
        assert_eq!(scaled[i], expected, "axis {i}");
    }
    assert!(scaled.z.is_nan(), "zAxis false reads NaN");
}

#[test]
fn sampling_periods() {
    let (mut sim, id) = world(
        "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"GPS\"\n\
         [[vehicle.device]]\ntype = \"Gyro\"\n",
    );
    sim.driver_mut(id).unwrap().set_cruising_speed(30.0);
    for _ in 0..50 {
        sim.step().unwrap();
    }
    // 25 ms at 10 ms steps: samples at 30, 60, 90 ms after enabling (whole steps).
    enable(&mut sim, id, "gps", 25);
    assert_eq!(sim.devices(id).unwrap()[0].period_ms(), 25);
    let mut seen = Vec::new();
    for k in 1..=9 {
        sim.step().unwrap();
        let g = gps(&sim, id, "gps");
        seen.push((k * 10, g.position.x));
    }
    let x = |ms: u32| seen.iter().find(|(t, _)| *t == ms).unwrap().1;
    assert!(
        x(10).is_nan() && x(20).is_nan(),
        "NaN before the first period"
    );
    assert!(x(30).is_finite());
    assert_eq!(x(40), x(30));
    assert_eq!(x(50), x(30));
    assert!(x(60) > x(30), "the car moves forward");
    assert_eq!(x(70), x(60));
    assert!(x(90) > x(60));
    // The gyro was never enabled: NaN, and costs nothing.
    assert!(vector(&sim, id, "gyro").x.is_nan());
    // Disabled: the last sample stays.
    sim.enable_device(id, 0, 0).unwrap();
    let kept = gps(&sim, id, "gps").position;
    for _ in 0..5 {
        sim.step().unwrap();
    }
    assert_eq!(gps(&sim, id, "gps").position, kept);
    assert_eq!(sim.devices(id).unwrap()[0].period_ms(), 0);
    assert!(sim.enable_device(id, 2, 10).is_err(), "no third device");
}

/// GPS positions of a parked car sampled `n` times with `seed`.
fn noisy_positions(seed: u64, n: usize) -> Vec<Point3<f64>> {
    let (mut sim, id) = world(&format!(
        "[vehicle]\nmodel = \"BmwX5\"\nseed = {seed}\n[[vehicle.device]]\ntype = \"GPS\"\n\
         accuracy = 0.5\n"
    ));
    enable(&mut sim, id, "gps", 10);
    (0..n)
        .map(|_| {
            sim.step().unwrap();
            gps(&sim, id, "gps").position
        })
        .collect()
}

#[test]
fn gps_noise_is_seeded_and_of_the_stated_accuracy() {
    let a = noisy_positions(7, 2000);
    assert_eq!(a, noisy_positions(7, 2000), "same seed, same noise");
    assert_ne!(
        a[..10],
        noisy_positions(8, 10)[..],
        "another seed, other noise"
    );
    // Uncorrelated noise of s.d. 0.5 m about the parked car (which moves by far less): the
    // sample s.d. of 2000 draws has a standard error of 0.5/√4000 = 0.008 m; 5 of them.
    let mean = a.iter().map(|p| p.x).sum::<f64>() / a.len() as f64;
    let sd = (a.iter().map(|p| (p.x - mean).powi(2)).sum::<f64>() / a.len() as f64).sqrt();
    assert!((sd - 0.5).abs() < 0.04, "{sd}");
}

/// The error of the world `text`, as `(line, key, message)`.
fn refused(text: &str) -> (u32, String, String) {
    let e = world_file::parse_str("w.toml", text).expect_err("the world should be refused");
    let line = e.location.map_or(0, |l| l.line);
    (line, e.key.clone().unwrap_or_default(), e.to_string())
}

#[test]
fn device_tables_are_read_with_webots_defaults_and_located_errors() {
    let d = world_file::parse_str(
        "w.toml",
        "[vehicle]\nmodel = \"ToyotaPrius\"\nseed = 5\n[[vehicle.device]]\ntype = \"GPS\"\n\
         slot = \"front\"\ntranslation = [0.1, 0, 0.2]\nrotation = [0, 0, 1, 1.5]\n\
         [[vehicle.device]]\ntype = \"Accelerometer\"\nname = \"imu accel\"\n",
    )
    .unwrap();
    let car = &d.cars[0];
    assert_eq!(car.seed, 5);
    assert_eq!(car.devices.len(), 2);
    assert_eq!(car.devices[0].device_name(), "gps");
    assert_eq!(
        car.devices[0].settings,
        sim::devices::DeviceSettings::Gps(sim::devices::GpsSettings::default())
    );
    assert_eq!(car.devices[1].device_name(), "imu accel");
    // The device point of the front slot (3.635 m ahead, 0.4 m up) plus its translation.
    let (mut sim, id) = world(
        "[vehicle]\nmodel = \"ToyotaPrius\"\n[[vehicle.device]]\ntype = \"GPS\"\n\
         slot = \"front\"\ntranslation = [0.1, 0, 0.2]\n",
    );
    let mount = *sim.devices(id).unwrap()[0].mount();
    // 1e-12 m: the sum 0.4 + 0.2 in f64.
    assert!((mount.translation.vector - Vector3::new(3.735, 0.0, 0.6)).norm() < 1e-12);
    enable(&mut sim, id, "gps", 10);
    sim.step().unwrap();
    let t = sim.telemetry(id).unwrap().state;
    let expected = t.position + t.orientation * mount.translation.vector;
    // 1e-9 m: f64 rounding of the same composition.
    assert!((gps(&sim, id, "gps").position - expected).norm() < 1e-9);

    let device = "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\n";
    let (line, key, text) = refused(&format!("{device}type = \"GPS\"\naccuracyy = 1\n"));
    assert_eq!((line, key.as_str()), (5, "vehicle.device[1].accuracyy"));
    assert!(text.contains("did you mean 'accuracy'?"), "{text}");
    let (line, key, text) = refused(&format!("{device}type = \"Gyroscope\"\n"));
    assert_eq!((line, key.as_str()), (4, "vehicle.device[1].type"));
    assert!(text.contains("Gyro"), "{text}");
    let (_, key, text) = refused(&format!("{device}name = \"x\"\n"));
    assert_eq!(key, "vehicle.device[1].type");
    assert!(text.contains("missing key"), "{text}");
    let (line, key, text) = refused(&format!("{device}type = \"GPS\"\naccuracy = -1\n"));
    assert_eq!((line, key.as_str()), (5, "vehicle.device[1].accuracy"));
    assert!(text.contains("-1: must be finite and >= 0"), "{text}");
    let (_, key, _) = refused(&format!("{device}type = \"GPS\"\nnoiseCorrelation = 2\n"));
    assert_eq!(key, "vehicle.device[1].noiseCorrelation");
    let (_, key, _) = refused(&format!("{device}type = \"Compass\"\nresolution = 0\n"));
    assert_eq!(key, "vehicle.device[1].resolution");
    let (_, key, _) = refused(&format!("{device}type = \"InertialUnit\"\nnoise = 1\n"));
    assert_eq!(key, "vehicle.device[1].noise");
    let (_, key, text) = refused(&format!(
        "{device}type = \"Gyro\"\nlookupTable = [[0, 0, 0], [0, 1, 0]]\n"
    ));
    assert_eq!(key, "vehicle.device[1].lookupTable");
    assert!(text.contains("strictly increasing"), "{text}");
    let (_, key, text) = refused(&format!(
        "{device}type = \"Gyro\"\nlookupTable = [[0, 0]]\n"
    ));
    assert_eq!(key, "vehicle.device[1].lookupTable");
    assert!(text.contains("row 1"), "{text}");
    let (_, key, text) = refused(&format!("{device}type = \"Gyro\"\nslot = \"roof\"\n"));
    assert_eq!(key, "vehicle.device[1].slot");
    assert!(text.contains("front") && text.contains("center"), "{text}");
    let (_, key, text) = refused(&format!(
        "{device}type = \"Gyro\"\nrotation = [0, 0, 0, 1]\n"
    ));
    assert_eq!(key, "vehicle.device[1].rotation");
    assert!(text.contains("axis"), "{text}");
    let (line, key, text) = refused(&format!(
        "{device}type = \"Gyro\"\n[[vehicle.device]]\ntype = \"Gyro\"\n"
    ));
    // No `name` key: located at the second table's header.
    assert_eq!((line, key.as_str()), (5, "vehicle.device[2].name"));
    assert!(text.contains("\"gyro\" is taken"), "{text}");
    let (_, key, text) = refused(&format!(
        "{device}type = \"Gyro\"\nname = \"right_steer\"\n"
    ));
    assert_eq!(key, "vehicle.device[1].name");
    assert!(text.contains("car's own devices"), "{text}");
    // The plain Car and the Tractor have no slot frames.
    let (_, key, text) =
        refused("[vehicle]\n[[vehicle.device]]\ntype = \"Gyro\"\nslot = \"top\"\n");
    assert_eq!(key, "vehicle.device[1].slot");
    assert!(text.contains("Car model has no sensor slots"), "{text}");
}

#[test]
fn the_sensors_world_has_one_of_each_device() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/worlds/sensors.toml");
    let description = world_file::load(path).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    let kinds: Vec<_> = sim.devices(id).unwrap().iter().map(|d| d.kind()).collect();
    assert_eq!(kinds, sim::devices::DeviceKind::ALL);
    for i in 0..kinds.len() {
        sim.enable_device(id, i, 20).unwrap();
    }
    sim.enable_recognition(id, 5, 20).unwrap();
    for _ in 0..100 {
        sim.step().unwrap();
    }
    // The camera recognises the red box 15 m ahead of the origin along the heading and 5 m
    // to the left (the front slot a few metres ahead of the origin on the car's centre line;
    // 5 cm for the settling body).
    let camera = sim.devices(id).unwrap()[5].camera().unwrap();
    assert_eq!(camera.objects().len(), 1);
    let seen = camera.objects()[0].position;
    assert!(
        seen.x > 10.0 && seen.x < 15.0 && (seen.y - 5.0).abs() < 0.05,
        "{seen}"
    );
    // The rear slot faces backward and the car heads north-east: north is behind-right,
    // (−sin π/4, −cos π/4, 0) in the compass' axes; 5e-3 for the body's pitch on its springs.
    let n = vector(&sim, id, "rear compass");
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!((n + Vector3::new(h, h, 0.0)).norm() < 5e-3, "{n}");
    // The gyro's resolution of 1e-3 rad/s: every value a whole number of steps.
    let w = vector(&sim, id, "gyro");
    assert!(
        w.iter()
            .all(|c| ((c / 1e-3) - (c / 1e-3).round()).abs() < 1e-6),
        "{w}"
    );
}
