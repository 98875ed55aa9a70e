//! Host tests of the plant (`cargo test --target x86_64-unknown-linux-gnu`), on the BmwX5: body
//! 2000 kg at (1.2975, 0, 0.1) m with Izz 4346.1 kg·m², four 30 kg wheels of radius 0.374 m
//! and width 0.25 m, wheelbase 2.995 m, tracks 1.628 m, equal springs front and rear,
//! `wheelsDampingConstant` 2 N·m·s/rad, `brakeCoefficient` 1800 N·m, front-wheel drive; on
//! passenger-car tyres (peak friction 1.0 forward and 0.95 sideways, 0.7456 on a locked
//! wheel) on a road of friction 1.

use ackermann::Geometry;
use ackermann::Wheel;
use vehicle_model::{Driver, Model, WheelDrive};

use super::solve::Spin;
use super::*;

/// The step sizes the plant must work at (ms).
const STEPS_MS: [u32; 3] = [1, 10, 32];

/// The driver and the plant of a BmwX5 at rest, for steps of `dt_ms`.
fn bmw(dt_ms: u32) -> (Driver<f32>, Plant) {
    let (driver, _) = Driver::new(Model::BmwX5.params(), dt_ms);
    let plant = Plant::new(driver.params(), Environment::SUV_ON_ASPHALT).unwrap();
    (driver, plant)
}

/// Runs the closed loop for `seconds` (s).
fn drive(driver: &mut Driver<f32>, plant: &mut Plant, seconds: f32, dt_ms: u32) {
    for _ in 0..steps(seconds, dt_ms) {
        let commands = *driver.step(&plant.sensors());
        plant.step(&commands, dt_ms);
    }
}

fn steps(seconds: f32, dt_ms: u32) -> u32 {
    (seconds * 1000.0 / dt_ms as f32).round() as u32
}

/// The driver's commands with every wheel free and braked by `brake` (N·m).
fn coasting(driver: &mut Driver<f32>, plant: &Plant, brake: f32) -> Commands<f32> {
    let mut commands = *driver.step(&plant.sensors());
    commands.drive = PerWheel::splat(WheelDrive::Free);
    commands.brake_torque = PerWheel::splat(brake);
    commands
}

/// The kinematic yaw rate `v·tan δ / L` (rad/s, counter-clockwise) of the plant's rear-axle
/// speed and true central steering angle.
fn kinematic_yaw_rate(geometry: &Geometry<f32>, plant: &Plant) -> f32 {
    let delta = geometry.central_angle_from_wheel_angles(plant.steering);
    -plant.speed() * Real::tan(delta) / geometry.wheelbase()
}

fn assert_close(actual: f32, expected: f32, tolerance: f32) {
    assert!(
        (actual - expected).abs() <= tolerance,
        "{actual} is not {expected} ± {tolerance}"
    );
}

#[test]
fn mass_loads_and_load_transfer() {
    let (_, plant) = bmw(10);
    // 2000 + 4 × 30 kg; the centre of mass (2000 × 1.2975 + 60 × 2.995) / 2120 m ahead of the
    // rear axle.
    assert_eq!(plant.mass, 2120.0);
    assert_close(plant.centre_of_mass[0], 1.308_821, 1e-5);
    assert_eq!(plant.centre_of_mass[1], 0.0);
    // 4346.1 + 2000 × 0.011321² + 4 × 30 × (3 × 0.374² + 0.25²)/12 + 30 × 2 × (1.686179² +
    // 1.308821² + 2 × 0.814²) kg·m².
    assert_close(plant.yaw_inertia, 4704.062, 0.01);
    for w in Wheel::ALL {
        let corner = plant.corners[w];
        // 0.5 × 30 × 0.374² kg·m².
        assert_close(corner.spin.inertia, 2.098_14, 1e-5);
        // 9.81 × (0.5 × 2000 × 1.2975/2.995 + 30) N in front, 9.81 × (0.5 × 2000 ×
        // 1.6975/2.995 + 30) N behind: 2 × (4544.21 + 5854.39) = 2120 × 9.81 N.
        let load = if w.is_front() { 4544.208 } else { 5854.392 };
        assert_close(corner.static_load, load, 0.01);
        // Centre of mass 2000 × 0.1/2120 + 0.374 m over the road: 0.5 × 2120 × 0.468340/2.995
        // kg per m/s² from each front wheel to each rear one; the equal roll stiffnesses take
        // half of 2120 × 0.468340/1.628 kg across each axle.
        let [pitch, roll] = corner.transfer;
        assert_close(pitch.abs(), 165.756, 0.01);
        assert_close(roll.abs(), 304.939, 0.01);
        assert_eq!(pitch < 0.0, w.is_front());
        assert_eq!(roll > 0.0, w.is_right());
    }
}

#[test]
fn rests_exactly_without_commands() {
    for dt in STEPS_MS {
        let (mut driver, mut plant) = bmw(dt);
        let commands = coasting(&mut driver, &plant, 0.0);
        for _ in 0..steps(2.0, dt) {
            plant.step(&commands, dt);
        }
        assert_eq!(plant.pose(), Pose::ORIGIN, "dt {dt} ms");
        assert_eq!(plant.velocity, [0.0; 3]);
        assert_eq!(plant.wheel_angle, PerWheel::splat(0.0));
        assert_eq!(plant.faults(), 0);
        // A step of 0 ms changes nothing.
        let time = plant.time();
        plant.step(&commands, 0);
        assert_eq!(plant.time(), time);
    }
}

#[test]
fn coasts_down_against_drag_wheel_damping_and_rolling_resistance() {
    let dt = 10;
    let (mut driver, mut plant) = bmw(dt);
    driver.set_cruising_speed(80.0);
    drive(&mut driver, &mut plant, 20.0, dt);
    let commands = coasting(&mut driver, &plant, 0.0);
    while plant.speed() > 20.0 {
        plant.step(&commands, dt);
    }
    // At 20 m/s: drag 0.5 × 1.225 × 0.95 × 20² = 232.75 N; rolling resistance 0.012 × 2120 ×
    // 9.81 = 249.57 N; wheel damping 4 × 2 × (20/0.374)/0.374 = 1143.87 N, less 0.94 % as
    // `WheelSpin` applies it implicitly to the spin before the tyre acts (÷ (1 + 2 × 0.01 /
    // 2.09814)) and 0.27 % as the wheels turn that much slower than they roll (the slip
    // carrying 345 N per tyre against a slip stiffness of 25 × 5199 N): 1130.0 N. Against the
    // mass and the wheels' spin inertia, 2120 + 4 × 2.09814/0.374² = 2180 kg: 0.7396 m/s².
    assert_close(plant.acceleration()[0], -0.7396, 0.002);
}

#[test]
fn front_wheel_drive_launch_is_limited_by_the_front_tyres() {
    let dt = 10;
    let (mut driver, mut plant) = bmw(dt);
    // The speed-mode ramp asks 27.78 m/s / 7 s = 3.97 m/s² of the front wheels.
    driver.set_cruising_speed(100.0);
    let mut peak_acceleration = 0.0_f32;
    let mut peak_slip = 0.0_f32;
    for _ in 0..steps(6.0, dt) {
        let commands = *driver.step(&plant.sensors());
        plant.step(&commands, dt);
        peak_acceleration = peak_acceleration.max(plant.acceleration()[0]);
        let wheel = plant.wheel_speed[Wheel::FrontRight] * 0.374;
        peak_slip = peak_slip.max((wheel - plant.speed()) / plant.speed().max(1.0));
    }
    // The front axle carries 2 × 4544.21 − 2 × 165.756·a N, with a peak friction of
    // 1 − 0.1 × (its relative load change): 2120·a ≤ μ·F_z gives a ≤ 3.751 m/s².
    assert!(peak_acceleration <= 3.751, "{peak_acceleration}");
    assert!(peak_acceleration > 3.0, "{peak_acceleration}");
    // So the imposed front wheels outrun the car, past the tyre's peak slip ratio 0.136.
    assert!(peak_slip > 0.136, "{peak_slip}");
}

#[test]
fn steady_turn_understeers_alike_at_every_step_size() {
    let mut yaw_rates = [0.0_f32; 3];
    for (dt, yaw_rate) in STEPS_MS.into_iter().zip(&mut yaw_rates) {
        let (mut driver, mut plant) = bmw(dt);
        let geometry = *driver.geometry();
        driver.set_cruising_speed(30.0);
        drive(&mut driver, &mut plant, 10.0, dt);
        driver.set_steering_angle(0.2);
        drive(&mut driver, &mut plant, 6.0, dt);
        // v·tan δ/L with v ≈ 8.18 m/s: 8.18 × tan 0.2 / 2.995 = 0.5537 rad/s; the tyres' slip
        // angles (0.03 rad) take a fraction of a percent off it at this 0.46 g, the lighter
        // front axle losing more side grip to the load transfer than the rear. (Below about
        // 0.35 g the car oversteers slightly instead: see the README.)
        let ratio = plant.yaw_rate() / kinematic_yaw_rate(&geometry, &plant);
        assert!((0.99..1.0).contains(&ratio), "dt {dt} ms: {ratio}");
        // Steady: the lateral acceleration is u·r, 8.18 × 0.552 = 4.52 m/s², within μ·g.
        let [u, _, r] = plant.velocity;
        assert_close(plant.acceleration()[1], u * r, 0.005);
        assert_close(plant.acceleration()[1], -4.52, 0.02);
        *yaw_rate = r;
    }
    let [fine, normal, coarse] = yaw_rates;
    assert_close(normal, fine, 0.001);
    assert_close(coarse, fine, 0.001);
}

#[test]
fn lateral_acceleration_stays_within_the_tyres_friction() {
    for dt in STEPS_MS {
        let (mut driver, mut plant) = bmw(dt);
        let geometry = *driver.geometry();
        driver.set_cruising_speed(60.0);
        drive(&mut driver, &mut plant, 15.0, dt);
        // Kinematically 16.6² × tan 0.2 / 2.995 = 18.7 m/s², twice what the tyres can give.
        driver.set_steering_angle(0.2);
        let mut peak = 0.0_f32;
        for _ in 0..steps(6.0, dt) {
            let commands = *driver.step(&plant.sensors());
            plant.step(&commands, dt);
            peak = peak.max(plant.acceleration()[1].abs());
        }
        // At most the sideways peak friction 0.95 × 9.81 m/s² (load transfer only lowers the
        // sum of the four peaks); the car ploughs on, turning far less than its wheels point.
        assert!(peak <= 0.95 * 9.81, "dt {dt} ms: {peak}");
        assert!(peak > 0.85 * 9.81, "dt {dt} ms: {peak}");
        let ratio = plant.yaw_rate() / kinematic_yaw_rate(&geometry, &plant);
        assert!(ratio < 0.8, "dt {dt} ms: {ratio}");
        assert!(plant.is_finite());
    }
}

#[test]
fn hard_stop_is_friction_limited_and_holds() {
    let mut distances = [0.0_f32; 3];
    for (dt, distance) in STEPS_MS.into_iter().zip(&mut distances) {
        let (mut driver, mut plant) = bmw(dt);
        driver.set_cruising_speed(100.0);
        drive(&mut driver, &mut plant, 15.0, dt);
        let v0 = plant.speed();
        let start = plant.distance();
        // Full brakes: 1800 N·m locks the rear wheels (5854 N × 1.0 × 0.374 m < 1800 N·m once
        // the load moves forward).
        let commands = coasting(&mut driver, &plant, 1800.0);
        while plant.speed() > 0.0 {
            plant.step(&commands, dt);
        }
        *distance = plant.distance() - start;
        // No shorter than at the peak friction 1.0 plus the drag at v0; no longer than on four
        // locked wheels (0.7456).
        let drag = 0.5 * 1.225 * 0.95 * v0 * v0 / 2120.0;
        let shortest = v0 * v0 / (2.0 * (9.81 + drag));
        let locked = v0 * v0 / (2.0 * 0.7456 * 9.81);
        assert!(
            (shortest..=locked).contains(distance),
            "dt {dt} ms: {distance} m not in {shortest}..{locked} m"
        );
        // The car rocks back onto its wound-up tyres, settles, and is held.
        for _ in 0..steps(1.0, dt) {
            plant.step(&commands, dt);
        }
        let settled = plant.distance();
        for _ in 0..steps(1.0, dt) {
            plant.step(&commands, dt);
        }
        assert!(plant.distance() - settled <= 1e-3, "dt {dt} ms");
        assert!(plant.speed().abs() <= 1e-3, "dt {dt} ms");
        assert_eq!(plant.wheel_speed, PerWheel::splat(0.0));
    }
    let [fine, normal, coarse] = distances;
    assert_close(normal, fine, 0.02 * fine);
    assert_close(coarse, fine, 0.02 * fine);
}

#[test]
fn non_finite_commands_are_counted_and_ignored() {
    let dt = 10;
    let (mut driver, mut plant) = bmw(dt);
    let mut commands = coasting(&mut driver, &plant, 0.0);
    commands.steering.right = f32::NAN;
    commands.brake_torque[Wheel::RearRight] = f32::INFINITY;
    commands.drive[Wheel::FrontLeft] = WheelDrive::Torque(f32::NAN);
    commands.drive[Wheel::FrontRight] = WheelDrive::Velocity {
        target: f32::NAN,
        acceleration: 1.0,
        max_velocity: 10.0,
    };
    for _ in 0..10 {
        plant.step(&commands, dt);
    }
    assert_eq!(plant.faults(), 40);
    assert!(plant.is_finite());
    assert_eq!(plant.pose(), Pose::ORIGIN);
    assert_eq!(plant.steering, WheelAngles::STRAIGHT);
}

/// In torque mode a driven wheel spins with its own inertia plus its equal share of the
/// engine's, reflected through the engaged gear (`Commands::driveline`), as the sim crate's
/// wheels do; an undriven wheel keeps its own.
#[test]
fn a_torque_driven_wheel_carries_its_share_of_the_engaged_engine() {
    let (mut driver, mut plant) = bmw(10);
    driver.set_gear(1);
    driver.set_throttle(1.0);
    let commands = *driver.step(&plant.sensors());
    let reflected = commands.driveline.reflected_inertia();
    // Wong's 0.0025·m·r² through the first gear's 12.5: hundreds of times a wheel's 2.1 kg·m².
    assert!(reflected > 100.0, "{reflected}");
    let is_driven = |w: Wheel| commands.drive[w].torque().is_some();
    let driven = Wheel::ALL.into_iter().filter(|w| is_driven(*w)).count();
    assert!(driven > 0);
    for w in Wheel::ALL {
        let own = plant.corners[w].spin.inertia;
        let Spin::Free { inertia, .. } = plant.spin(w, &commands, 0.01).0 else {
            panic!("{w:?} is not free");
        };
        let expected = if is_driven(w) {
            own + reflected / driven as f32
        } else {
            own
        };
        assert_close(inertia, expected, expected * 1e-6);
    }
}
