//! Physics simulation of Webots-style vehicles on rapier3d.
//!
//! * [`World`]: a fixed-step rapier world (flat ground, static boxes and ramps) holding cars
//!   ([`Vehicle`], built from a [`VehicleSpec`]) and legacy [`DifferentialWheels`] robots;
//! * [`Simulation`]: a world whose cars are driven by `vehicle_model::Driver<f64>`, stepped
//!   like a Webots controller calling `wbu_driver_step()`, with [`CarTelemetry`];
//! * [`motor`]: the Webots motor semantics (velocity ramp, position servo) the joints emulate;
//! * [`world_file`]: TOML worlds in Webots vocabulary (`basicTimeStep`, `[vehicle]` with any
//!   `Car` field, `[differential_wheels]`, obstacles), loaded by path or model name;
//! * [`scenario`], [`telemetry`], [`report`], [`cli`]: the `vehicle-sim` command's driving
//!   programmes, metrics, CSV, SVG plots and JSON (see `README.md`).
//!
//! The public API is in f64 and SI units (m, m/s, rad, rad/s, N·m, s; the step in ms as
//! Webots' `basicTimeStep`); rapier (pinned `=0.36.1`) runs in f32 inside and is never exposed.
//!
//! # Physics choices
//!
//! * Cars are rapier **multibodies** (exact joints) of chassis, two steering knuckles and four
//!   cylindrical wheels; see the `vehicle` module docs (on [`Vehicle`]) for the joint layout
//!   and how each Webots device maps onto it.
//! * One rapier step with one solver substep per `basicTimeStep`: rapier computes the contact
//!   points at the start of a step and re-evaluates them as body-fixed points only between
//!   solver substeps, which a spinning wheel breaks (at 100 km/h with 2 substeps the car sank
//!   by 3 cm and ran 4 % slow). [`World::step`] splits a step into up to [`MAX_SUBSTEPS`] rapier
//!   steps only when a wheel would turn more than [`MAX_WHEEL_ROTATION_PER_SUBSTEP`] in it
//!   (above 134 km/h for a 0.374 m tyre at 10 ms).
//! * Tyre friction gets 16 solver sweeps per step ([`SolverSettings::friction_iterations`]):
//!   rapier solves a multibody contact's friction one world axis at a time (x, then y on flat
//!   ground, no coupling term), exact only while a wheel points along a world axis. A wheel is
//!   light along its heading (it spins) and heavy across it, so at other headings one sweep
//!   overshoots by up to 2×: with one sweep a free wheel at 20 km/h jumped between 7.5 and
//!   21 rad/s from step to step. With 16 it rolls within 1.1 % of its kinematic rate in a
//!   turn (the scrub of the tyre's two tread edges) and within 0.05 % straight at 45°.
//! * The wheel position sensors integrate the solved wheel speeds (see
//!   [`VehicleState::wheel_angles`]), not rapier's joint coordinates.
//! * Every body is created in a fixed order and never sleeps; nothing iterates a hash map: the
//!   same world and commands give bit-identical results on the same machine.
//! * A body whose state stops being finite ends the simulation with [`SimError::NonFinite`].
//!
//! # Cost
//!
//! One BmwX5 step (10 ms) takes about 50 µs at rest and 55 µs at 50 or 100 km/h on the 2-core
//! development machine (release build, `cargo run --release -p sim --example step_cost`), and
//! 8 cars cost 8 times one. The 16 friction sweeps take 11 µs of it (38 and 43 µs with one
//! sweep). Most of the rest is rapier's multibody bookkeeping for the car's 16 degrees of
//! freedom (7 links): the dense mass-matrix update (Jᵀ·M·J per link), an LU solve per contact
//! and motor row to build the constraints, the link Jacobians and the forward kinematics; the
//! narrow phase is about 5 %.
//!
//! ```
//! use sim::{Simulation, VehiclePlacement, World, WorldConfig};
//! use vehicle_model::Model;
//!
//! let mut sim = Simulation::new(World::new(WorldConfig::default())?);
//! let (car, _report) = sim.add_car(Model::ToyotaPrius.params(), VehiclePlacement::default())?;
//! sim.driver_mut(car)?.set_cruising_speed(30.0); // km/h, the Webots driver API
//! for _ in 0..200 {
//!     sim.step()?;
//! }
//! let t = sim.telemetry(car)?;
//! assert!(t.speed > 5.0 && t.speed < 30.0 / 3.6 + 0.1); // m/s, measured on the chassis
//! # Ok::<(), sim::SimError>(())
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

pub mod cli;
pub mod motor;
pub mod placement;
pub mod report;
pub mod rng;
pub mod scenario;
pub mod telemetry;
pub mod world_file;

mod config;
mod diff_wheels;
mod error;
mod geom;
mod simulation;
mod vehicle;
mod world;

pub use config::{
    DEFAULT_BASIC_TIME_STEP_MS, DEFAULT_FRICTION, Obstacle, SolverSettings, WorldConfig,
};
pub use diff_wheels::{
    DifferentialWheels, DifferentialWheelsParams, RobotBody, RobotId, RobotMode, RobotPlacement,
    RobotPose, RobotWarning,
};
pub use error::{BodyOwner, BodyPart, ParamError, SimError};
pub use simulation::{CarTelemetry, Simulation};
pub use vehicle::{
    ChassisSpec, SpringDamper, SteeringSpec, Vehicle, VehicleId, VehiclePlacement, VehicleSpec,
    VehicleState, WheelSpec,
};
pub use world::{MAX_SUBSTEPS, MAX_WHEEL_ROTATION_PER_SUBSTEP, World};
