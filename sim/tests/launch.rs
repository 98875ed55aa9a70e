//! Full-throttle launches in torque mode (issue #35): every model, ground friction 0.5, 1 and
//! 1.5, both mountings, measured for what the launch chatter showed — the last time a driven
//! wheel's slip ratio flips sign after the first 0.2 s, the engine speed's local extrema per
//! gear, and how far the car strays from its line (|y| / distance, |yaw|).
//!
//! `launch_report` (ignored: `--ignored --nocapture`; `LAUNCH_SECONDS`, `LAUNCH_DT_MS`,
//! `LAUNCH_MODELS=BmwX5,Bus` to choose) prints the whole matrix — every model, three
//! frictions, both mountings — with the sim's default [`DrivelineModel::Inertial`]; it is the
//! harness of ARCHITECTURE.md's "Launch" section. The tests that run by default take a
//! representative subset, within `cargo test`'s time: the BmwX5 (rear-driven combustion, the
//! worst chatter before the driveline's inertia) and the MercedesBenzSprinter (a van) on every
//! friction on joints (the mounting that turned), the BmwX5 at 1 and 32 ms, and the BmwX5 with
//! Webots' limiter, which must still chatter, to show that the criteria see chatter.
//!
//! The criteria (issue #35): no sign change of a driven wheel's slip ratio after the first
//! 0.2 s; an engine speed without oscillation, defined as at most one local extremum per gear
//! (its rise, and one turn where the gearbox is about to shift or the engine reaches its top
//! speed), an extremum counting once the speed has come back from it by more than 1 % of
//! `engineMaxRPM` ([`REVERSAL`]); |y| ≤ 0.2 % of the distance and |yaw| ≤ 0.01 rad (the straight-line bounds of
//! `suite::tyre_straight`).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::{Mounting, Simulation, TyreChoice, VehiclePlacement, World, WorldConfig};
use vehicle_model::{AutoShiftParams, DrivelineModel, Model, Wheel, WheelDrive};

/// What one launch did.
#[derive(Debug, Clone, Copy)]
struct Launch {
    /// Last time (s after the throttle) a driven wheel's slip ratio changed sign, after 0.2 s.
    last_flip: Option<f64>,
    /// Most turns (local extrema, [`Turns`]) of the engine speed within one gear (between
    /// shifts).
    rpm_extrema: usize,
    /// Distance along x (m).
    x: f64,
    /// Sideways offset (m).
    y: f64,
    /// Heading (rad).
    yaw: f64,
}

/// How a launch is run.
#[derive(Debug, Clone, Copy)]
struct Run {
    mounting: Mounting,
    /// Step (ms).
    dt_ms: u32,
    /// Time at full throttle (s).
    seconds: f64,
    driveline: DrivelineModel,
}

/// Launches `model` at full throttle (automatic gearbox from first) on friction `mu` as `run`
/// says, after a 1 s settle.
fn launch(model: Model, mu: f64, run_as: Run) -> Launch {
    let Run {
        mounting,
        dt_ms,
        seconds,
        driveline,
    } = run_as;
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
                .driveline(driveline)
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
    let mut last_flip = None;
    let mut last_sign = [0.0_f64; 4];
    // Engine speed: its turns counted in the current gear, and the most in one gear.
    let swing = REVERSAL * d.powertrain().engine().max_rpm();
    let (mut gear, mut turns, mut most) = (1, Turns::new(swing), 0);
    for k in 0..steps {
        sim.step().unwrap();
        let t = (k + 1) as f64 * dt;
        let vehicle = sim.world().vehicle(id).unwrap();
        let commands = vehicle.commands().unwrap();
        let tel = sim.telemetry(id).unwrap();
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            if !matches!(commands.drive[w], WheelDrive::Torque(_)) {
                continue;
            }
            let s = tel.state.tyres[w].slip_ratio;
            let sign = if s > 0.0 {
                1.0
            } else if s < 0.0 {
                -1.0
            } else {
                0.0
            };
            if t > 0.2 && sign * last_sign[i] < 0.0 {
                last_flip = Some(t);
            }
            if sign != 0.0 {
                last_sign[i] = sign;
            }
        }
        let driver = sim.driver(id).unwrap();
        let g = driver.gear().map_or(0, |g| g.number());
        // The speed the engine turns at (Webots' estimate with its limiter).
        let rpm = driver.engine_rpm();
        if g != gear {
            (gear, turns) = (g, Turns::new(swing));
        }
        turns.push(rpm);
        most = most.max(turns.count);
    }
    let s = sim.telemetry(id).unwrap().state;
    Launch {
        last_flip,
        rpm_extrema: most,
        x: s.position.x,
        y: s.position.y,
        yaw: s.roll_pitch_yaw.yaw,
    }
}

/// The share of `engineMaxRPM` by which the engine speed must come back from its last
/// extreme for that extreme to count as a turn (dimensionless): 1 %, 40–65 rpm on the shipped
/// engines. A spinning wheel held on the governor's droop line wobbles by under 1 rpm (the
/// Sprinter on 0.5: 3946.6 to 3948.2 rpm), which is no oscillation; the launch chatter swung
/// the engine by hundreds of rpm every few steps, and the same count sees it
/// (`webots_limiter_still_chatters`).
const REVERSAL: f64 = 0.01;

/// Counts the turns of a signal: a maximum or minimum counts once the signal has come back
/// from it by more than `swing`.
struct Turns {
    swing: f64,
    /// The extreme since the last turn, and the direction (+1 rising, −1 falling, 0 not yet
    /// known) toward it.
    extreme: Option<f64>,
    direction: i8,
    count: usize,
}

impl Turns {
    fn new(swing: f64) -> Self {
        Turns {
            swing,
            extreme: None,
            direction: 0,
            count: 0,
        }
    }

    fn push(&mut self, x: f64) {
        let Some(e) = self.extreme else {
            self.extreme = Some(x);
            return;
        };
        let (rising, falling) = (x - e > self.swing, e - x > self.swing);
        match self.direction {
            1 if x > e => self.extreme = Some(x),
            -1 if x < e => self.extreme = Some(x),
            1 if falling => {
                (self.count, self.direction, self.extreme) = (self.count + 1, -1, Some(x))
            }
            -1 if rising => {
                (self.count, self.direction, self.extreme) = (self.count + 1, 1, Some(x))
            }
            0 if rising => (self.direction, self.extreme) = (1, Some(x)),
            0 if falling => (self.direction, self.extreme) = (-1, Some(x)),
            _ => {}
        }
    }
}

fn run(sim: &mut Simulation, steps: f64) {
    for _ in 0..steps.round() as usize {
        sim.step().unwrap();
    }
}

#[test]
#[ignore = "diagnosis table: run with --ignored --nocapture"]
fn launch_report() {
    let seconds: f64 = std::env::var("LAUNCH_SECONDS").map_or(8.0, |s| s.parse().unwrap());
    let dt_ms: u32 = std::env::var("LAUNCH_DT_MS").map_or(10, |s| s.parse().unwrap());
    let only = std::env::var("LAUNCH_MODELS").unwrap_or_default();
    for mounting in [Mounting::Cast, Mounting::Joints] {
        for model in Model::ALL {
            if !only.is_empty() && !only.split(',').any(|m| m == model.to_string()) {
                continue;
            }
            for mu in [0.5, 1.0, 1.5] {
                let run_as = Run {
                    mounting,
                    dt_ms,
                    seconds,
                    driveline: DrivelineModel::Inertial,
                };
                let l = launch(model, mu, run_as);
                println!(
                    "{mounting:?} {model} mu {mu}: last flip {:?} s, rpm extrema/gear {}, x {:.1} m, |y|/x {:.2e}, yaw {:.2e}",
                    l.last_flip,
                    l.rpm_extrema,
                    l.x,
                    l.y.abs() / l.x,
                    l.yaw
                );
            }
        }
    }
}

impl Launch {
    /// Checks the criteria (module docs) for the launch called `what`.
    fn check(&self, what: &str) {
        assert_eq!(self.last_flip, None, "{what}: {self:?}");
        assert!(self.rpm_extrema <= 1, "{what}: {self:?}");
        // It moved forward (the sideways bound is a share of the distance): the slowest run,
        // the BmwX5 on 0.5 at 1 ms over 2 s, covers 3.3 m.
        assert!(self.x > 1.0, "{what}: {self:?}");
        assert!(self.y.abs() <= 0.002 * self.x, "{what}: {self:?}");
        assert!(self.yaw.abs() <= 0.01, "{what}: {self:?}");
    }
}

const JOINTS_10_MS: Run = Run {
    mounting: Mounting::Joints,
    dt_ms: 10,
    seconds: 5.0,
    driveline: DrivelineModel::Inertial,
};

#[test]
fn launches_on_every_friction_neither_chatter_nor_turn() {
    for model in [Model::BmwX5, Model::MercedesBenzSprinter] {
        for mu in [0.5, 1.0, 1.5] {
            launch(model, mu, JOINTS_10_MS).check(&format!("{model} mu {mu}"));
        }
    }
}

#[test]
fn launches_are_clean_at_1_and_32_ms() {
    // 1 ms: 2 s (2 000 steps) covers the spin-up beyond the grip on 0.5; 32 ms: 5 s.
    for (dt_ms, seconds) in [(1, 2.0), (32, 5.0)] {
        let run_as = Run {
            dt_ms,
            seconds,
            ..JOINTS_10_MS
        };
        launch(Model::BmwX5, 0.5, run_as).check(&format!("BmwX5 at {dt_ms} ms"));
    }
}

#[test]
fn webots_limiter_still_chatters() {
    // The same launch with Webots' wheel-acceleration limiter instead of the engine's inertia
    // (ARCHITECTURE.md: flips until 3–5 s and hundreds of engine-speed extrema at 10 ms).
    let run_as = Run {
        driveline: DrivelineModel::Webots,
        ..JOINTS_10_MS
    };
    let l = launch(Model::BmwX5, 0.5, run_as);
    assert!(l.last_flip.is_some_and(|t| t > 1.0), "{l:?}");
    assert!(l.rpm_extrema > 10, "{l:?}");
}
