//! Full-throttle launches in torque mode (issue #35): every model, ground friction 0.5, 1 and
//! 1.5, both mountings, measured for what the launch chatter showed — the last time a driven
//! wheel's slip ratio flips sign after the first 0.2 s, the engine speed's local extrema per
//! gear, and how far the car strays from its line (|y| / distance, |yaw|).
//!
//! `launch_report` prints the table (run with `--nocapture`); it is the diagnosis harness of
//! ARCHITECTURE.md's "Launch" section. `LAUNCH_MODELS` (comma-separated model names) and
//! `LAUNCH_CAST_ONLY` (set: skip the joints mounting) choose a part of the matrix, since the
//! whole of it takes minutes of a release build.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::{Mounting, Simulation, TyreChoice, VehiclePlacement, World, WorldConfig};
use vehicle_model::{AutoShiftParams, Model, Wheel, WheelDrive};

/// What one launch did.
#[derive(Debug, Clone, Copy)]
struct Launch {
    /// Last time (s after the throttle) a driven wheel's slip ratio changed sign, after 0.2 s.
    last_flip: Option<f64>,
    /// Most local extrema of the engine speed within one gear (between shifts).
    rpm_extrema: usize,
    /// Distance along x (m).
    x: f64,
    /// Sideways offset (m).
    y: f64,
    /// Heading (rad).
    yaw: f64,
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
    let mut last_flip = None;
    let mut last_sign = [0.0_f64; 4];
    // Engine speed: the last two values and the extrema counted in the current gear.
    let (mut gear, mut rpms, mut extrema, mut most) = (1, Vec::new(), 0, 0);
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
        let rpm = driver.rpm().unwrap_or(0.0);
        if g != gear {
            (gear, extrema) = (g, 0);
            rpms.clear();
        }
        rpms.push(rpm);
        if let [.., a, b, c] = rpms[..]
            && (b - a) * (c - b) < 0.0
        {
            extrema += 1;
            most = most.max(extrema);
        }
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
    let cast_only = std::env::var("LAUNCH_CAST_ONLY").is_ok();
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
