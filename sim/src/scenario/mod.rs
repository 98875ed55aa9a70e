//! Driving programmes and their metrics: what `vehicle-sim --scenario` runs.
//!
//! A car is driven only through the [`vehicle_model::Driver`] API, exactly as a Webots
//! controller drives it with `wbu_driver_*`: each step the programme sets its commands, the
//! driver turns the sensor readings into actuator commands, and the world advances one
//! `basicTimeStep`. A DifferentialWheels robot is driven through
//! [`DifferentialWheels::set_speed`](crate::DifferentialWheels::set_speed)
//! (`wb_differential_wheels_set_speed`).
//!
//! | scenario | vehicle | what it does | metrics |
//! |---|---|---|---|
//! | `accel-speed` | car | cruise control to 100 km/h from rest | `time_0_100_s` |
//! | `accel-torque` | car | full throttle, automatic gearbox | `time_0_100_s`, `top_gear`, `max_rpm` |
//! | `brake` | car | brake intensity 1 from 100 km/h | `stop_distance_m`, `stop_time_s` |
//! | `circle` | car | steering 0.2 rad at 10 km/h | `turn_radius_m` vs `turn_radius_expected_m` |
//! | `lane-change` | car | ISO 3888-1-like double lane change at 60 km/h | `max_lateral_accel_mps2`, `left_track` |
//! | `step-steer` | car | ISO 7401 step steer at 80 km/h to 4 m/s² | `response_time_s`, `peak_response_time_s`, `overshoot_percent`, `steady_yaw_gain_per_s` |
//! | `constant-radius` | car | ISO 4138 steady-state driving on a 40 m radius, 0.5–4 m/s² | `understeer_gradient_rad_per_mps2` |
//! | `sine-with-dwell` | car | FMVSS 126 sine with dwell at 80 km/h | `yaw_ratio_1_0`, `yaw_ratio_1_75`, `lateral_displacement_m`, `passes_fmvss126` |
//! | `iso-3888` | car | ISO 3888-2 obstacle-avoidance lane change entered at 60 km/h, throttle released | `passed`, `entry_speed_kmh`, `cones_hit` |
//! | `split-mu` | car | braking from 80 km/h, right wheels on friction 0.3 | `stop_distance_m`, `heading_change_rad` |
//! | `test-track` | car | all five above, each on a fresh world | all of the above |
//! | `ftp75` | car | EPA FTP-75 drive cycle (1874 s) with the built-in [`CycleDriver`] | `distance_km`, `time_outside_band_s`, `battery_wh_per_km`, `fuel_l_per_100km`, … |
//! | `hwfet` | car | EPA Highway Fuel Economy Test (765 s), likewise | as `ftp75` |
//! | `wltc` | car | WLTC class 3b of UN GTR No. 15 (1800 s), likewise | as `ftp75` |
//! | `square` | robot | a square of side 10 × `axleLength`, open loop | final pose, `closure_error_m` |
//! | `spin` | robot | turns on the spot for 10 s | final pose, `turns` |
//! | `programme` | any | every car's and the robot's programme from the world file | per vehicle: [`motion_metrics`], a `cycle`'s metrics as `ftp75`'s ([`CycleCommand`]); for several cars `min_gap_m`, `touched` |
//!
//! The built-in car scenarios need a world with exactly one car (and no robot), the robot
//! scenarios one with exactly the robot; `programme` runs any world.

mod car;
mod car_programmes;
mod cycle_driver;
mod cycle_follow;
mod cycle_gears;
mod cycle_trace;
mod drive_cycles;
mod fit;
mod iso_3888;
mod lane;
mod lane_change;
mod lane_departure;
pub mod manoeuvre_metrics;
mod manoeuvres;
mod metrics;
mod plausibility;
mod programme;
mod result;
mod split_mu;

pub use plausibility::{
    MIN_STEPS_PER_BOUNCE, MIN_TYRE_FRICTION, bounce_period, notes as plausibility_notes,
};
mod robot;

use core::fmt;
use std::time::Instant;

pub use cycle_driver::{AuthorityError, BandMeter, CycleDriver, PedalAuthority, Pedals};
pub use cycle_follow::{CycleCommand, CycleSource, FUEL_DENSITY};
pub use cycle_trace::{
    Band, Cycle, EPA_SPEED_TOLERANCE, EPA_TIME_TOLERANCE, MS_PER_MPH, Trace, TraceError,
};
pub use fit::{Circle, fit_circle};
pub use lane::{LaneSection, double_lane_change};
pub use lane_departure::{DepartureMeter, LaneDeparture, Side};
pub use metrics::{MotionMeter, motion_metrics};
pub use programme::PROGRAMME_TAIL;
pub use result::{Metric, RunReport, ScenarioResult, Value};

use crate::config::Outline;
use crate::error::SimError;
use crate::world_file::WorldDescription;

/// A driving programme.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Scenario {
    /// Cruise control to 100 km/h from rest.
    AccelSpeed,
    /// Full throttle from rest with automatic gear changes.
    AccelTorque,
    /// Full braking from 100 km/h.
    Brake,
    /// Constant steering at low speed.
    Circle,
    /// A double lane change at 60 km/h.
    LaneChange,
    /// ISO 7401 step steer.
    StepSteer,
    /// ISO 4138 steady-state circular driving on a constant radius.
    ConstantRadius,
    /// FMVSS 126 sine with dwell.
    SineWithDwell,
    /// Straight-line braking on split friction.
    SplitMu,
    /// ISO 3888-2 obstacle-avoidance double lane change.
    Iso3888,
    /// Every car scenario in turn.
    TestTrack,
    /// The EPA FTP-75 drive cycle.
    Ftp75,
    /// The EPA Highway Fuel Economy Test drive cycle.
    Hwfet,
    /// The WLTC class 3b drive cycle of UN GTR No. 15.
    Wltc,
    /// A DifferentialWheels robot drives a square.
    Square,
    /// A DifferentialWheels robot turns on the spot.
    Spin,
    /// The programmes of the world file's cars and robot.
    Programme,
}

impl Scenario {
    /// Every scenario.
    pub const ALL: [Scenario; 17] = [
        Scenario::AccelSpeed,
        Scenario::AccelTorque,
        Scenario::Brake,
        Scenario::Circle,
        Scenario::LaneChange,
        Scenario::StepSteer,
        Scenario::ConstantRadius,
        Scenario::SineWithDwell,
        Scenario::SplitMu,
        Scenario::Iso3888,
        Scenario::TestTrack,
        Scenario::Ftp75,
        Scenario::Hwfet,
        Scenario::Wltc,
        Scenario::Square,
        Scenario::Spin,
        Scenario::Programme,
    ];

    /// The scenarios `test-track` runs, in order.
    pub const TEST_TRACK: [Scenario; 5] = [
        Scenario::AccelSpeed,
        Scenario::AccelTorque,
        Scenario::Brake,
        Scenario::Circle,
        Scenario::LaneChange,
    ];

    /// The command-line name, e.g. `"accel-speed"`.
    pub const fn name(self) -> &'static str {
        match self {
            Scenario::AccelSpeed => "accel-speed",
            Scenario::AccelTorque => "accel-torque",
            Scenario::Brake => "brake",
            Scenario::Circle => "circle",
            Scenario::LaneChange => "lane-change",
            Scenario::StepSteer => "step-steer",
            Scenario::ConstantRadius => "constant-radius",
            Scenario::SineWithDwell => "sine-with-dwell",
            Scenario::SplitMu => "split-mu",
            Scenario::Iso3888 => "iso-3888",
            Scenario::TestTrack => "test-track",
            Scenario::Ftp75 => "ftp75",
            Scenario::Hwfet => "hwfet",
            Scenario::Wltc => "wltc",
            Scenario::Square => "square",
            Scenario::Spin => "spin",
            Scenario::Programme => "programme",
        }
    }

    /// The scenario named `name`, or `None`.
    pub fn from_name(name: &str) -> Option<Scenario> {
        Scenario::ALL.into_iter().find(|s| s.name() == name)
    }

    /// One line on what it does.
    pub const fn description(self) -> &'static str {
        match self {
            Scenario::AccelSpeed => "cruise control to 100 km/h from rest",
            Scenario::AccelTorque => "full throttle from rest, automatic gearbox",
            Scenario::Brake => "brake intensity 1 from 100 km/h to a stop",
            Scenario::Circle => "steering 0.2 rad at 10 km/h: turn radius vs L/tan(delta)",
            Scenario::LaneChange => "ISO 3888-1-like double lane change (3.5 m) at 60 km/h",
            Scenario::StepSteer => {
                "ISO 7401 step steer at 80 km/h to 4 m/s²: yaw response times, overshoot, gain"
            }
            Scenario::ConstantRadius => {
                "ISO 4138 constant radius (40 m), 0.5-4 m/s²: understeer gradient"
            }
            Scenario::SineWithDwell => {
                "FMVSS 126 sine with dwell at 80 km/h: yaw-rate ratios, displacement, pass/fail"
            }
            Scenario::Iso3888 => {
                "ISO 3888-2 obstacle avoidance at 60 km/h, cones for the car's width: pass/fail"
            }
            Scenario::SplitMu => {
                "split-mu braking from 80 km/h, right wheels on friction 0.3: stop, heading"
            }
            Scenario::TestTrack => "all five car scenarios in turn",
            Scenario::Ftp75 => "EPA FTP-75 drive cycle (1874 s): band tracking, Wh/km, l/100 km",
            Scenario::Hwfet => "EPA highway cycle HWFET (765 s): band tracking, Wh/km, l/100 km",
            Scenario::Wltc => "WLTC class 3b, GTR 15 (1800 s): band tracking, Wh/km, l/100 km",
            Scenario::Square => "DifferentialWheels: drive a square, open loop",
            Scenario::Spin => "DifferentialWheels: turn on the spot for 10 s",
            Scenario::Programme => "the world file's driving programmes, every car and robot",
        }
    }

    /// What vehicles the scenario drives.
    pub const fn needs(self) -> Needs {
        match self {
            Scenario::Square | Scenario::Spin => Needs::OneRobot,
            Scenario::Programme => Needs::Any,
            _ => Needs::OneCar,
        }
    }

    /// What `vehicle-sim` runs on `world` without `--scenario`: `programme` when the world
    /// has a programme or more than one vehicle, else `test-track` for a car and `square` for
    /// a robot.
    pub fn default_for(world: &WorldDescription) -> Scenario {
        match (world.cars.len(), &world.robot) {
            _ if world.has_programme() => Scenario::Programme,
            (1, None) => Scenario::TestTrack,
            (0, Some(_)) => Scenario::Square,
            _ => Scenario::Programme,
        }
    }

    /// Checks that `world` holds what the scenario drives.
    ///
    /// # Errors
    /// [`ScenarioError::WrongVehicle`] naming what the world holds.
    pub fn check(self, world: &WorldDescription) -> Result<(), ScenarioError> {
        let ok = match self.needs() {
            Needs::OneCar => world.cars.len() == 1 && world.robot.is_none(),
            Needs::OneRobot => world.cars.is_empty() && world.robot.is_some(),
            Needs::Any => true,
        };
        if ok {
            Ok(())
        } else {
            Err(ScenarioError::WrongVehicle {
                scenario: self,
                vehicle: world.vehicles_label(),
            })
        }
    }

    /// The single scenarios this one runs (itself, or the five of `test-track`).
    pub fn parts(self) -> Vec<Scenario> {
        if self == Scenario::TestTrack {
            Scenario::TEST_TRACK.to_vec()
        } else {
            vec![self]
        }
    }

    /// The simulated time the scenario may take at most (s); it usually ends earlier.
    pub(crate) const fn time_limit(self) -> f64 {
        match self {
            Scenario::AccelSpeed | Scenario::AccelTorque => 60.0,
            Scenario::Brake => 90.0,
            Scenario::Circle => 90.0,
            Scenario::LaneChange => 60.0,
            Scenario::StepSteer | Scenario::SineWithDwell => 90.0,
            Scenario::ConstantRadius => 120.0,
            Scenario::SplitMu => 90.0,
            Scenario::Iso3888 => 60.0,
            Scenario::TestTrack => 360.0,
            // The trace and a few seconds to stop after it.
            Scenario::Ftp75 => 1880.0,
            Scenario::Hwfet => 770.0,
            Scenario::Wltc => 1805.0,
            Scenario::Square => 600.0,
            Scenario::Spin => 10.0,
            Scenario::Programme => f64::INFINITY,
        }
    }
}

/// What a scenario drives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    /// A world with exactly one car and no robot.
    OneCar,
    /// A world with the DifferentialWheels robot and no car.
    OneRobot,
    /// Any world.
    Any,
}

impl fmt::Display for Scenario {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why a scenario could not run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ScenarioError {
    /// The world does not hold what the scenario drives (see [`Scenario::needs`]).
    #[error("scenario '{scenario}' needs {}, but the world holds {vehicle}", match scenario.needs() {
        Needs::OneCar => "a world with one car",
        Needs::OneRobot => "a world with one DifferentialWheels robot",
        Needs::Any => "any world",
    })]
    WrongVehicle {
        /// The scenario asked for.
        scenario: Scenario,
        /// What the world holds ([`WorldDescription::vehicles_label`]).
        vehicle: String,
    },
    /// The simulator refused the world or diverged.
    #[error("simulation failed: {0}")]
    Sim(#[from] SimError),
    /// The drive-cycle driver refused the car's pedal authority.
    #[error("drive-cycle driver: {0}")]
    CycleDriver(#[from] AuthorityError),
    /// The run's recording could not be read back (its temporary file failed).
    #[error("the run's recording could not be read back: {0}")]
    Record(String),
}

/// Where a run is, for a progress display.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// The single scenario running.
    pub scenario: Scenario,
    /// Its position among the run's scenarios (0-based) and their number.
    pub index: usize,
    /// Number of single scenarios in the run.
    pub count: usize,
    /// Simulated time in this scenario (s).
    pub time: f64,
    /// Estimated fraction of the whole run done, in [0, 1].
    pub fraction: f64,
}

/// The simulated time (s) a single scenario may take on `world`: its own limit, cut to the
/// world's `duration` if that is shorter.
pub(crate) fn limit(scenario: Scenario, world: &WorldDescription) -> f64 {
    world
        .duration
        .map_or(scenario.time_limit(), |d| d.min(scenario.time_limit()))
}

/// The notes of a world before it runs: a car whose rotation tilts it starts level.
fn world_notes(world: &WorldDescription) -> Vec<String> {
    world
        .cars
        .iter()
        .filter_map(|car| {
            let [ax, ay, _, angle] = car.params.rotation;
            (angle != 0.0 && (ax != 0.0 || ay != 0.0)).then(|| {
                format!(
                    "the rotation {:?} of {} tilts it: only its heading is used, it starts level",
                    car.params.rotation, car.name
                )
            })
        })
        .collect()
}

/// Runs `scenario` on `world`, calling `progress` every few simulated seconds.
///
/// # Errors
/// [`ScenarioError::WrongVehicle`] when the world does not hold what the scenario drives
/// ([`Scenario::check`]), and [`ScenarioError::Sim`] if the world cannot be built or the
/// simulation diverges.
pub fn run(
    world: &WorldDescription,
    scenario: Scenario,
    progress: &mut dyn FnMut(Progress),
) -> Result<RunReport, ScenarioError> {
    scenario.check(world)?;
    let start = Instant::now();
    let parts = scenario.parts();
    let count = parts.len();
    let mut results = Vec::with_capacity(count);
    for (index, part) in parts.into_iter().enumerate() {
        let mut report = |time: f64, expected: f64| {
            let within = if expected > 0.0 {
                (time / expected).min(1.0)
            } else {
                1.0
            };
            progress(Progress {
                scenario: part,
                index,
                count,
                time,
                fraction: (index as f64 + within) / count as f64,
            });
        };
        let result = match (part.needs(), world.cars.first(), &world.robot) {
            (Needs::Any, ..) => programme::run(world, &mut report)?,
            (Needs::OneCar, Some(car), _) => car_programmes::run(world, car, part, &mut report)?,
            (_, _, Some(robot)) => robot::run(world, robot, part, &mut report)?,
            _ => {
                return Err(ScenarioError::WrongVehicle {
                    scenario,
                    vehicle: world.vehicles_label(),
                });
            }
        };
        results.push(result);
    }
    if let Some(first) = results.first_mut() {
        let mut notes = world_notes(world);
        notes.extend(plausibility::notes(world));
        notes.append(&mut first.notes);
        first.notes = notes;
    }
    let sim_seconds = results.iter().map(|r| r.sim_seconds).sum();
    Ok(RunReport {
        world: world.source.clone(),
        vehicle: world.vehicles_label(),
        scenario: scenario.name().to_string(),
        results,
        sim_seconds,
        wall_seconds: start.elapsed().as_secs_f64(),
        obstacles: Outline::of_world(&world.config),
    })
}
