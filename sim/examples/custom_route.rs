//! A car driving a route of its own with its own controller, through the public API, with the
//! same CSV, JSON and plots as `vehicle-sim`.
//!
//! ```text
//! cargo run --release -p sim --example custom_route -- [OUT_DIR]
//! ```
//!
//! A ToyotaPrius laps a 60 m × 30 m rounded rectangle of waypoints (bends of 10 m radius)
//! with a pure-pursuit steering controller and a speed controller that slows for the bends,
//! driving only through the Webots driver API (`set_steering_angle`,
//! `set_cruising_speed`). The simulation records the run (`Simulation::record`); its report
//! (`Simulation::report`: the telemetry, the standard motion metrics, the replay) gets a
//! cross-track error of its own and the waypoints drawn as cones, and `report::write_outputs`
//! writes it as `telemetry.csv`, `metrics.json`, the SVG plots and `replay.glb` into OUT_DIR
//! (default `custom-route-out`).

use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::path::PathBuf;

use sim::report;
use sim::scenario::Metric;
use sim::telemetry::Sample;
use sim::{CarBuilder, Simulation, World, WorldConfig};
use vehicle_model::Model;

/// Straight lengths of the route (m) and the radius of its four bends (m).
const LENGTH: f64 = 60.0;
const WIDTH: f64 = 30.0;
const BEND_RADIUS: f64 = 10.0;
/// Distance between two waypoints (m).
const SPACING: f64 = 2.0;
/// Cruising speeds on the straights and in the bends (km/h): 25 km/h on a 10 m bend is
/// v²/r = 4.8 m/s² at steady speed (more while the car is still slowing from 45 km/h).
const STRAIGHT_KMH: f64 = 45.0;
const BEND_KMH: f64 = 25.0;
/// Look-ahead of the pure-pursuit controller (m).
const LOOKAHEAD: f64 = 6.0;
/// Laps to drive.
const LAPS: usize = 2;

/// The route's waypoints (m), counter-clockwise from the start, and whether each is in a bend.
fn route() -> Vec<([f64; 2], bool)> {
    let (a, b, r) = (
        LENGTH / 2.0 - BEND_RADIUS,
        WIDTH / 2.0 - BEND_RADIUS,
        BEND_RADIUS,
    );
    // Centre of the rectangle at (LENGTH / 2, WIDTH / 2): the car starts at the origin,
    // on the bottom straight, heading +x.
    let (cx, cy) = (LENGTH / 2.0, WIDTH / 2.0);
    let mut points = Vec::new();
    // Straights and bends in turn: (start, direction) of each straight, then the bend's centre.
    let sides = [
        (
            [cx - a, cy - b - r],
            [1.0, 0.0],
            2.0 * a,
            [cx + a, cy - b],
            -FRAC_PI_2,
        ),
        (
            [cx + a + r, cy - b],
            [0.0, 1.0],
            2.0 * b,
            [cx + a, cy + b],
            0.0,
        ),
        (
            [cx + a, cy + b + r],
            [-1.0, 0.0],
            2.0 * a,
            [cx - a, cy + b],
            FRAC_PI_2,
        ),
        (
            [cx - a - r, cy + b],
            [0.0, -1.0],
            2.0 * b,
            [cx - a, cy - b],
            PI,
        ),
    ];
    for (start, dir, len, centre, angle0) in sides {
        let n = (len / SPACING).round() as usize;
        for k in 0..n {
            let s = len * k as f64 / n as f64;
            points.push(([start[0] + dir[0] * s, start[1] + dir[1] * s], false));
        }
        let n = (FRAC_PI_2 * r / SPACING).round() as usize;
        for k in 0..n {
            let t = angle0 + FRAC_PI_2 * k as f64 / n as f64;
            points.push(([centre[0] + r * t.cos(), centre[1] + r * t.sin()], true));
        }
    }
    // Shift so that the first waypoint is at the origin.
    let [x0, y0] = points[0].0;
    points
        .into_iter()
        .map(|([x, y], bend)| ([x - x0, y - y0], bend))
        .collect()
}

/// Index of the waypoint nearest to `(x, y)`, searching forward from `from`.
fn nearest(route: &[([f64; 2], bool)], from: usize, x: f64, y: f64) -> usize {
    let n = route.len();
    (from..from + n / 4)
        .min_by(|&i, &j| {
            let d = |k: usize| {
                let [px, py] = route[k % n].0;
                (px - x).hypot(py - y)
            };
            d(i).total_cmp(&d(j))
        })
        .map_or(from, |i| i % n)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "custom-route-out".into()),
    );
    let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    let model = Model::ToyotaPrius;
    let (car, _) = sim.add_car(CarBuilder::of_model(model))?;
    let wheelbase = sim.driver(car)?.params().wheelbase;
    let route = route();
    let n = route.len();
    let lap_length = route.len() as f64 * SPACING;

    // Every step of every vehicle is recorded (in bounded memory) for the report.
    sim.record("custom-route");
    let (mut index, mut laps, mut max_error) = (0, 0, 0.0_f64);
    while laps < LAPS && sim.world().time() < 120.0 {
        let s = Sample::of_car(&sim, car)?;
        let previous = index;
        index = nearest(&route, index, s.x, s.y);
        if index < previous {
            laps += 1;
        }
        let ([px, py], _) = route[index];
        max_error = max_error.max((px - s.x).hypot(py - s.y));
        // Pure pursuit: aim at the waypoint LOOKAHEAD ahead; Webots steering is positive to
        // the right, so a target to the left gives a negative angle.
        let ahead = (LOOKAHEAD / SPACING).round() as usize;
        let ([tx, ty], _) = route[(index + ahead) % n];
        let alpha = ((ty - s.y).atan2(tx - s.x) - s.yaw + PI).rem_euclid(TAU) - PI;
        let distance = (tx - s.x).hypot(ty - s.y).max(1e-3);
        let steering = -(2.0 * wheelbase * alpha.sin() / distance).atan();
        // Slow down a few waypoints before a bend.
        let bend_ahead = (0..8).any(|k| route[(index + k) % n].1);
        let driver = sim.driver_mut(car)?;
        driver.set_steering_angle(steering);
        driver.set_cruising_speed(if bend_ahead { BEND_KMH } else { STRAIGHT_KMH });
        sim.step()?;
    }

    // The recorded run (telemetry, motion metrics, replay), with this route's own metrics and
    // its waypoints drawn as cones.
    let mut report = sim.report("custom route").ok_or("not recording")??;
    let result = &mut report.results[0];
    result.metrics.push(Metric::number(
        "max_route_error_m",
        "largest distance from the route",
        "m",
        max_error,
    ));
    result.metrics.push(Metric::number(
        "lap_length_m",
        "route length",
        "m",
        lap_length,
    ));
    result.cones = route.iter().map(|(p, _)| *p).collect();
    let written = report::write_outputs(&report, &[], &out)?;
    print!("{}", report::summary_table(&report));
    let names: Vec<String> = written
        .iter()
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .collect();
    println!("outputs in {}: {}", out.display(), names.join(", "));
    Ok(())
}
