//! Full-throttle launches in torque mode (issue #35): every model, ground friction 0.5, 1 and
//! 1.5, both mountings, measured for what the launch chatter showed — the last time a driven
//! wheel's slip ratio flips sign after the first 0.2 s, the engine speed's local extrema per
//! gear, and how far the car strays from its line (|y| / distance, |yaw|) — and held to the
//! issue's criteria ([`Launch::failures`]).
//!
//! `launch_matrix` runs the whole matrix, prints the table (run with `--ignored --nocapture`)
//! and fails on any launch that strays from its line or misses another criterion without
//! being one of the measured [`KNOWN_MISSES`]; it is the harness of ARCHITECTURE.md's
//! "Launch" section. `LAUNCH_MODELS` (comma-separated model names) and `LAUNCH_CAST_ONLY`
//! (set: skip the joints mounting) choose a part of the matrix, `LAUNCH_SECONDS` and
//! `LAUNCH_DT_MS` the run's length (s) and step (ms), since the whole of it takes minutes of
//! a release build. The other tests are short launches of cars that chattered before the
//! engine's inertia reached the driven wheels.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::{Mounting, Simulation, TyreChoice, VehiclePlacement, World, WorldConfig};
use vehicle_model::{AutoShiftParams, Model, Wheel, WheelDrive};

/// What one launch did.
#[derive(Debug, Clone, Copy)]
struct Launch {
    /// Last time (s after the throttle) a driven wheel's slip ratio changed sign, after
    /// [`SETTLED_AFTER`].
    last_flip: Option<f64>,
    /// Largest |slip ratio| (dimensionless) on either side of those sign changes: how far from
    /// rolling the wheels were that flipped.
    flip_slip: f64,
    /// Last time (s) a driven tyre's longitudinal force changed sign after [`SETTLED_AFTER`]:
    /// the tyre switching between driving and braking, which the chatter did every few steps.
    last_force_flip: Option<f64>,
    /// Most turns of the engine speed within one gear (between shifts), as a tachometer of
    /// [`RPM_RESOLUTION`] sees them ([`Turns`]).
    rpm_extrema: usize,
    /// Most local extrema of the engine speed within one gear, of any size (the ripple of
    /// the solver's round-off included).
    rpm_raw_extrema: usize,
    /// The engine speed's wiggle (rpm): within each gear, the changes of engine speed between
    /// consecutive turns but the largest (a launch's one turn, as where spinning wheels
    /// catch the car), the largest of them over the gears; 0 with two turns or fewer.
    rpm_wiggle: f64,
    /// Steps after [`SETTLED_AFTER`] in which a wheel's acceleration exceeded
    /// [`ACCELERATION_THRESHOLD`], so that Webots' limiter scaled a later torque down.
    limited: usize,
    /// Distance along x (m).
    x: f64,
    /// Sideways offset (m).
    y: f64,
    /// Heading (rad).
    yaw: f64,
}

/// Time after the throttle (s) from which a driven wheel's slip must keep its sign (issue #35).
const SETTLED_AFTER: f64 = 0.2;
/// Most turns of the engine speed within one gear of a launch without oscillation: the
/// launches that did not chatter before any fix had 0 to 2, the rise and its one turn at a
/// shift (ARCHITECTURE.md, "Launch chatter").
const MAX_RPM_EXTREMA: usize = 2;
/// The resolution of an engine-speed reading (rpm): the OBD-II engine speed (SAE J1979 /
/// ISO 15031-5, PID 0x0C, `(256·A + B)/4`) counts quarter revolutions per minute. A swing of
/// the engine speed smaller than this is no oscillation a scan tool, an ECU's log or a
/// driver could see; the solver's round-off leaves ripples of a few thousandths of an rpm
/// where the speed turns.
const RPM_RESOLUTION: f64 = 0.25;

/// The turns of a signal with a hysteresis of [`RPM_RESOLUTION`]: a maximum (minimum) counts
/// once the signal has fallen (risen) that far below (above) it, and the next turn is looked
/// for from there.
#[derive(Debug, Default)]
struct Turns {
    /// The first value, until the signal has moved [`RPM_RESOLUTION`] from it.
    start: Option<f64>,
    /// The direction the signal moves in (+1 rising, −1 falling, 0 not yet known).
    direction: f64,
    /// The extreme reached in that direction.
    extreme: f64,
    /// The values at the turns (rpm).
    turns: Vec<f64>,
}

impl Turns {
    /// The next value (rpm).
    fn see(&mut self, value: f64) {
        let Some(start) = self.start else {
            self.start = Some(value);
            return;
        };
        if self.direction == 0.0 {
            if (value - start).abs() >= RPM_RESOLUTION {
                self.direction = (value - start).signum();
                self.extreme = value;
            }
        } else if (value - self.extreme) * self.direction > 0.0 {
            self.extreme = value;
        } else if (self.extreme - value) * self.direction >= RPM_RESOLUTION {
            self.turns.push(self.extreme);
            self.direction = -self.direction;
            self.extreme = value;
        }
    }
}
/// Wheel acceleration (rad/s²) above which the driver library's limiter scales the torque down
/// (Webots' `ACCELERATION_THRESHOLD`, `powertrain::WHEEL_ACCELERATION_LIMIT`; sim's tests do
/// not depend on `powertrain`).
const ACCELERATION_THRESHOLD: f64 = 50.0;
/// Most sideways offset per distance covered (dimensionless; issue #35: 0.2 %).
const MAX_SIDEWAYS: f64 = 0.002;
/// Most heading at the end (rad; issue #35).
const MAX_YAW: f64 = 0.01;

impl Launch {
    /// The criteria of issue #35 this launch misses, by name (empty: it holds them all): no
    /// sign flip of a driven wheel's slip after [`SETTLED_AFTER`], at most
    /// [`MAX_RPM_EXTREMA`] engine-speed extrema in one gear, and [`Launch::crooked`].
    fn failures(&self) -> Vec<String> {
        let mut failures = Vec::new();
        if let Some(t) = self.last_flip {
            failures.push(format!("slip flip at {t:.2} s"));
        }
        if self.rpm_extrema > MAX_RPM_EXTREMA {
            failures.push(format!("{} rpm turns in a gear", self.rpm_extrema));
        }
        failures.extend(self.crooked());
        failures
    }

    /// The straightness criteria of issue #35 this launch misses: |y| ≤ [`MAX_SIDEWAYS`] of
    /// the distance and |yaw| ≤ [`MAX_YAW`].
    fn crooked(&self) -> Vec<String> {
        let mut failures = Vec::new();
        let sideways = self.y.abs() / self.x.abs().max(f64::MIN_POSITIVE);
        if sideways > MAX_SIDEWAYS || !sideways.is_finite() {
            failures.push(format!("|y|/x {sideways:.2e}"));
        }
        if self.yaw.abs() > MAX_YAW || !self.yaw.is_finite() {
            failures.push(format!("yaw {:.2e} rad", self.yaw));
        }
        failures
    }

    /// One line of the table.
    fn line(&self) -> String {
        format!(
            "last flip {:?} s (|slip| ≤ {:.3}), last force flip {:?} s, rpm turns/gear {} \
             (raw extrema {}, wiggle {:.3} rpm), limiter steps {}, x {:.1} m, |y|/x {:.2e}, \
             yaw {:.2e}",
            self.last_flip,
            self.flip_slip,
            self.last_force_flip,
            self.rpm_extrema,
            self.rpm_raw_extrema,
            self.rpm_wiggle,
            self.limited,
            self.x,
            self.y.abs() / self.x,
            self.yaw
        )
    }
}

/// The sign changes of one quantity per wheel after [`SETTLED_AFTER`].
#[derive(Debug, Default)]
struct Flips {
    /// Each wheel's last non-zero value.
    last: [f64; 4],
    /// When the last change of sign happened (s).
    at: Option<f64>,
    /// The largest magnitude on either side of a change of sign.
    size: f64,
}

impl Flips {
    /// Wheel `i`'s `value` at time `t` (s).
    fn see(&mut self, i: usize, value: f64, t: f64) {
        if t > SETTLED_AFTER && value * self.last[i] < 0.0 {
            self.at = Some(t);
            self.size = self.size.max(value.abs()).max(self.last[i].abs());
        }
        if value != 0.0 {
            self.last[i] = value;
        }
    }
}

/// Launches `model` at full throttle (automatic gearbox from first) on friction `mu`, mounting
/// `mounting`, step `dt_ms`, for `seconds` after a 1 s settle.
fn launch(model: Model, mu: f64, mounting: Mounting, dt_ms: u32, seconds: f64) -> Launch {
    let world = World::new(WorldConfig {
        ground_friction: mu,
        basic_time_step_ms: dt_ms,
        ..WorldConfig::default()
    })
    .unwrap();
    let mut sim = Simulation::new(world);
    let (id, _) = sim
        .add_car(
            sim::CarBuilder::new(model.params())
                .tyre(TyreChoice::of_model(model))
                .mounting(mounting)
                .placement(VehiclePlacement::default()),
        )
        .unwrap();
    let dt = sim.world().dt();
    run(&mut sim, 1.0 / dt);
    let d = sim.driver_mut(id).unwrap();
    let auto = AutoShiftParams::for_engine(d.powertrain().engine());
    let _ = d.set_automatic_gearbox(Some(auto));
    d.set_gear(1);
    d.set_throttle(1.0);
    let steps = (seconds / dt).round() as usize;
    let (mut slips, mut forces) = (Flips::default(), Flips::default());
    // Engine speed in the current gear: its values, its local extrema, and its turns as a
    // tachometer resolves them.
    let (mut gear, mut rpms, mut extrema, mut turns) = (1, Vec::new(), 0, Turns::default());
    let (mut most, mut most_raw, mut wiggle) = (0, 0, 0.0_f64);
    let (mut speeds, mut limited) = (sim.world().vehicle(id).unwrap().state().wheel_speeds, 0);
    for k in 0..steps {
        sim.step().unwrap();
        let t = (k + 1) as f64 * dt;
        let vehicle = sim.world().vehicle(id).unwrap();
        let commands = vehicle.commands().unwrap();
        let tel = sim.telemetry(id).unwrap();
        let now = tel.state.wheel_speeds;
        let fastest = Wheel::ALL.map(|w| (now[w] - speeds[w]).abs() / dt);
        if t > SETTLED_AFTER && fastest.into_iter().any(|a| a > ACCELERATION_THRESHOLD) {
            limited += 1;
        }
        speeds = now;
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            if matches!(commands.drive[w], WheelDrive::Torque(_)) {
                slips.see(i, tel.state.tyres[w].slip_ratio, t);
                forces.see(i, tel.state.tyres[w].fx, t);
            }
        }
        let driver = sim.driver(id).unwrap();
        let g = driver.gear().map_or(0, |g| g.number());
        let rpm = driver.rpm().unwrap_or(0.0);
        if g != gear {
            wiggle = wiggle.max(wiggle_of(&turns.turns));
            (gear, extrema, turns) = (g, 0, Turns::default());
            rpms.clear();
        }
        rpms.push(rpm);
        if let [.., a, b, c] = rpms[..]
            && (b - a) * (c - b) < 0.0
        {
            extrema += 1;
            most_raw = most_raw.max(extrema);
        }
        turns.see(rpm);
        most = most.max(turns.turns.len());
    }
    wiggle = wiggle.max(wiggle_of(&turns.turns));
    let s = sim.telemetry(id).unwrap().state;
    Launch {
        last_flip: slips.at,
        flip_slip: slips.size,
        last_force_flip: forces.at,
        rpm_extrema: most,
        rpm_raw_extrema: most_raw,
        rpm_wiggle: wiggle,
        limited,
        x: s.position.x,
        y: s.position.y,
        yaw: s.roll_pitch_yaw.yaw,
    }
}

/// The largest change between consecutive `extrema` (rpm) but the largest one, 0 for fewer
/// than three ([`Launch::rpm_wiggle`]).
fn wiggle_of(extrema: &[f64]) -> f64 {
    let mut swings: Vec<f64> = extrema.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    swings.sort_by(f64::total_cmp);
    swings.iter().rev().nth(1).copied().unwrap_or(0.0)
}

fn run(sim: &mut Simulation, steps: f64) {
    for _ in 0..steps.round() as usize {
        sim.step().unwrap();
    }
}

/// Asserts that `model`'s launch on `mu`, `mounting`, at `dt_ms` over `seconds` holds every
/// criterion, and prints its line.
fn assert_clean(model: Model, mu: f64, mounting: Mounting, dt_ms: u32, seconds: f64) {
    let l = launch(model, mu, mounting, dt_ms, seconds);
    println!("{mounting:?} {model} mu {mu} at {dt_ms} ms: {}", l.line());
    let failures = l.failures();
    assert!(
        failures.is_empty(),
        "{model} mu {mu} {mounting:?} at {dt_ms} ms: {failures:?}"
    );
}

/// The BmwX5 chattered on every friction before its wheels carried its engine (at 10 ms over
/// 8 s on 1: slip flips until 7.5 s, 315 engine-speed extrema in a gear; ARCHITECTURE.md).
#[test]
fn a_bmw_x5_launches_without_chatter() {
    assert_clean(Model::BmwX5, 1.0, Mounting::Cast, 10, 3.0);
}

/// The TeslaModel3 on 0.5 chattered and, on joints, drifted (|y|/x 0.41 %, yaw 0.0074 rad at
/// 10 ms over 8 s; ARCHITECTURE.md): its electric machine's single reduction gear is where
/// the borrowed passenger-car inertia correlation is an assumption.
#[test]
fn a_tesla_model3_launches_straight_on_joints() {
    assert_clean(Model::TeslaModel3, 0.5, Mounting::Joints, 10, 3.0);
}

/// At 1 ms the TeslaModel3 chattered even on 1.5 (3 059 engine-speed extrema in a gear over
/// 8 s): the limiter's input, a second difference, is the largest at the shortest step.
#[test]
fn a_tesla_model3_launches_without_chatter_at_1_ms() {
    assert_clean(Model::TeslaModel3, 1.5, Mounting::Cast, 1, 2.0);
}

/// At 32 ms the Bus chattered on 1 (slip flips until 3.8 s, 17 extrema in a gear over 8 s).
#[test]
fn a_bus_launches_without_chatter_at_32_ms() {
    assert_clean(Model::Bus, 1.0, Mounting::Cast, 32, 3.0);
}

/// The launches (model, friction, step in ms; either mounting) that miss the slip-flip
/// criterion of issue #35 over 8 s with the engine's inertia on the driven wheels
/// (ARCHITECTURE.md, "Launch chatter", has the numbers). None of them switches a tyre
/// between driving and braking, turns its engine speed more than twice in a gear, or
/// strays from its line:
///
/// * the slips that flip before 0.41 s stay under 0.07: one swing of the wheels and their
///   share of the engine on the tyres' carcass springs (the transient slip) below 2 m/s,
///   the tyre force keeping its sign;
/// * the 4x4 Truck on 0.5 at 32 ms: its rear wheels, given a fifth of the torque, spend it on
///   their equal share of the engine, and their slip passes zero at the shift at 2.7 s.
///
/// A full run of the matrix also fails on an entry that no longer misses.
const KNOWN_MISSES: &[(Model, f64, u32)] = &[
    (Model::Bus, 1.5, 1),
    (Model::Truck, 1.0, 1),
    (Model::Truck, 1.5, 1),
    (Model::Tractor, 0.5, 1),
    (Model::Car, 0.5, 1),
    (Model::Bus, 1.5, 10),
    (Model::Tractor, 0.5, 10),
    (Model::Truck, 0.5, 32),
    (Model::Truck, 1.0, 32),
    (Model::Truck, 1.5, 32),
    (Model::Tractor, 0.5, 32),
    (Model::Tractor, 1.0, 32),
];

/// Every model on 0.5, 1 and 1.5 on both mountings at `LAUNCH_DT_MS` (10 by default) over
/// `LAUNCH_SECONDS` (8): prints the table, and fails if a launch strays from its line, or
/// misses another criterion without being one of [`KNOWN_MISSES`], or (a full run) if one
/// of those no longer misses.
#[test]
#[ignore = "the whole matrix: run with --ignored --nocapture (release)"]
fn launch_matrix() {
    let seconds: f64 = std::env::var("LAUNCH_SECONDS").map_or(8.0, |s| s.parse().unwrap());
    let dt_ms: u32 = std::env::var("LAUNCH_DT_MS").map_or(10, |s| s.parse().unwrap());
    let only = std::env::var("LAUNCH_MODELS").unwrap_or_default();
    let cast_only = std::env::var("LAUNCH_CAST_ONLY").is_ok();
    let mut failed = Vec::new();
    // The known misses of this step that missed on some mounting.
    let mut still_missing = Vec::new();
    for mounting in [Mounting::Cast, Mounting::Joints] {
        if cast_only && mounting == Mounting::Joints {
            continue;
        }
        for model in Model::ALL {
            if !only.is_empty() && !only.split(',').any(|m| m == model.to_string()) {
                continue;
            }
            for mu in [0.5, 1.0, 1.5] {
                let l = launch(model, mu, mounting, dt_ms, seconds);
                let known = KNOWN_MISSES.contains(&(model, mu, dt_ms));
                if known && !l.failures().is_empty() {
                    still_missing.push((model, mu));
                }
                let failures = if known { l.crooked() } else { l.failures() };
                let note = if known { " (known)" } else { "" };
                println!(
                    "{mounting:?} {model} mu {mu}: {}{note} {:?}",
                    l.line(),
                    l.failures()
                );
                if !failures.is_empty() {
                    failed.push(format!("{mounting:?} {model} mu {mu}: {failures:?}"));
                }
            }
        }
    }
    if only.is_empty() && !cast_only {
        for &(model, mu, dt) in KNOWN_MISSES {
            if dt == dt_ms && !still_missing.contains(&(model, mu)) {
                failed.push(format!(
                    "{model} mu {mu} at {dt} ms: a known miss that passes"
                ));
            }
        }
    }
    assert!(
        failed.is_empty(),
        "{} launches miss a criterion:\n{}",
        failed.len(),
        failed.join("\n")
    );
}
