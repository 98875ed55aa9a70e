//! Physics simulation of Webots-style vehicles on rapier3d.
//!
//! * [`World`]: a fixed-step rapier world (flat ground, static boxes and ramps, dynamic boxes)
//!   holding cars
//!   ([`Vehicle`], built from a [`VehicleSpec`]) and legacy [`DifferentialWheels`] robots;
//! * [`Simulation`]: a world whose cars are driven by `vehicle_model::Driver<f64>`, stepped
//!   like a Webots controller calling `wbu_driver_step()` (or `wb_robot_step()`), with
//!   [`CarTelemetry`]: the one way every front-end builds a run ([`CarBuilder`],
//!   [`Simulation::from_description`]), owns its duration and end, and records it
//!   ([`Simulation::record`], [`Simulation::save`]);
//! * [`motor`]: the Webots motor semantics (velocity ramp, position servo) the joints emulate,
//!   from [`vehicle_model::actuator`] in f64, and rapier's rigid velocity motor;
//! * [`world_file`]: TOML worlds in Webots vocabulary (`basicTimeStep`, `[vehicle]` or several
//!   `[[vehicle]]` with any `Car` field and a driving programme, `[differential_wheels]`,
//!   obstacles), loaded by path or model name;
//! * [`road`]: roads (reference lines of lines, arcs, clothoids and cubics; lanes, lines,
//!   grade and banking; station ↔ position) and the OpenDRIVE import; the world's roads
//!   ([`WorldConfig::roads`]) are rapier triangle meshes both wheel mountings drive on;
//! * [`programme`]: timed driver commands named after the Webots driver setters;
//! * [`scenario`], [`telemetry`], [`report`]: the `vehicle-sim` command's driving
//!   programmes, metrics, CSV and JSON (see `README.md`); the report takes any run, also one
//!   driven through this API (`examples/custom_route.rs`);
//! * with the `app` feature (default): `cli` (the `vehicle-sim` command), the SVG plots
//!   (`report::figures`, `report::write_outputs`) and the sweeps' thread pool and merges. The
//!   engine without it links no command-line, progress-bar, plotting or thread-pool crate
//!   (`capi` and the Python extension use it so).
//! * [`devices`]: Webots sensors on a car (GPS, InertialUnit, Gyro, Accelerometer,
//!   Compass), sampled by the [`Simulation`] as Webots samples them;
//! * [`replay`]: the run as an animated 3D scene, `replay.glb`.
//! * [`sweep`]: one scenario on many variants of a world (axes over world-file keys), on
//!   every core or split into shards for batch engines, one row of metrics per variant
//!   (`vehicle-sim sweep`).
//!
//! The public API is in f64 and SI units (m, m/s, rad, rad/s, N·m, s; the step in ms as
//! Webots' `basicTimeStep`), its geometry [`nalgebra`]'s (`Point3` for positions, `Vector3`
//! for velocities, offsets and sizes, `UnitQuaternion` for orientations; re-exported as
//! [`sim::nalgebra`](nalgebra), the version `proto-geom` uses), with roll, pitch and yaw as a
//! [`RollPitchYaw`]; rapier (pinned `=0.36.1`) runs in f32 inside and is never exposed.
//!
//! # Physics choices
//!
//! * A car is one rapier rigid body (the chassis, with the whole car's mass properties) on
//!   four shape-cast cylinder wheels whose suspension, tyre friction, brakes and spin this crate solves
//!   itself, as velocity constraints between the chassis and the wheel spins (exact at any
//!   heading, the friction limited to μ·N along each tyre axis, like ODE's friction pyramid); see the `vehicle` module docs
//!   (on [`Vehicle`]) for how each Webots device maps onto it. rapier integrates the chassis
//!   and resolves its collisions with walls, ramps, other cars and robots.
//! * One rapier step with one solver substep per `basicTimeStep`. A physics-mode
//!   DifferentialWheels robot's wheels are rapier bodies: rapier computes the contact points
//!   at the start of a step and re-evaluates them as body-fixed points only between solver
//!   substeps, which a spinning wheel breaks, so [`World::step`] splits a step into up to
//!   [`MAX_SUBSTEPS`] rapier steps only when a robot wheel would turn more than
//!   [`MAX_WHEEL_ROTATION_PER_SUBSTEP`] in it.
//! * Every body is created in a fixed order and never sleeps; nothing iterates a hash map: the
//!   same world and commands give bit-identical results on the same machine.
//! * A body whose state stops being finite ends the simulation with [`SimError::NonFinite`].
//!
//! # Cost
//!
//! One BmwX5 step (10 ms: the driver step, the four tyre shape casts, the tyre solve and one
//! rapier step) costs a few µs, over a thousand times real time; `benches` measures it with
//! criterion and callgrind and `benches/README.md` holds the figures of the last run
//! (`cargo run --release -p sim --example step_cost` times it on your machine).
//!
//! ```
//! use sim::{CarBuilder, Simulation, World, WorldConfig};
//! use vehicle_model::Model;
//!
//! let mut sim = Simulation::new(World::new(WorldConfig::default())?);
//! let (car, _report) = sim.add_car(CarBuilder::of_model(Model::ToyotaPrius))?;
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

pub mod appearance;
mod attitude;
pub mod battery_sensor;
mod body;
mod car_builder;
#[cfg(feature = "app")]
pub mod cli;
pub mod devices;
pub mod keyboard;
pub mod lane_following;
pub mod motor;
pub mod placement;
pub mod programme;
pub mod replay;
pub mod report;
pub mod rng;
pub mod road;
pub mod scenario;
pub mod sweep;
pub mod telemetry;
pub mod traffic;
pub mod vec_env;
pub mod world_file;

mod config;
mod diff_wheels;
mod error;
mod geom;
mod ground;
mod sampling;
mod simulation;
mod vehicle;
mod world;

/// The linear algebra of the public API (the version `proto-geom` re-exports).
pub use proto_geom::nalgebra;

pub use attitude::RollPitchYaw;
pub use body::{BodyPose, BodySpec};
pub use car_builder::CarBuilder;
pub use config::{
    DEFAULT_BASIC_TIME_STEP_MS, DEFAULT_FRICTION_ITERATIONS, Obstacle, SolverSettings, WorldConfig,
};
pub use diff_wheels::{
    DifferentialWheels, DifferentialWheelsParams, RobotBody, RobotId, RobotMode, RobotPlacement,
    RobotPose, RobotWarning,
};
pub use error::{BodyOwner, BodyPart, ParamError, Rule, SimError};
pub use geom::DEFAULT_FRICTION;
pub use simulation::{
    CarTelemetry, EnergyReport, MAX_DURATION, Simulation, Snapshot, SnapshotError,
};
pub use vehicle::{
    ChassisSpec, Mounting, SpringDamper, SteeringSpec, TyreChoice, TyreSpec, TyreTelemetry,
    Vehicle, VehicleId, VehiclePlacement, VehicleSpec, VehicleState, WheelSpec,
};
pub use world::{
    CONE_COLOR, CONE_HEIGHTS, CONE_RADII, Cone, DEFAULT_CONE_HEIGHT, DEFAULT_CONE_RADIUS,
    DEFAULT_CONE_RCS, MAX_SUBSTEPS, MAX_WHEEL_ROTATION_PER_SUBSTEP, Placement, ROAD_LIFT, World,
    rotation_from_axis_angle,
};
