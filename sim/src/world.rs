//! The simulated world: rapier bodies, the ground and obstacles, dynamic boxes, cars and
//! DifferentialWheels robots, stepped at a fixed `basicTimeStep`.

use std::panic::{AssertUnwindSafe, catch_unwind};

use proto_geom::nalgebra::Point2;
use rapier3d::na::Unit;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, ColliderHandle, IntegrationParameters, PhysicsWorld,
    Pose, RigidBodyHandle, Rotation, TriMeshFlags, Vector,
};

use crate::body::{self, BodyPose};
use crate::config::{Obstacle, WorldConfig, ramp_corners};
use crate::diff_wheels::{
    DifferentialWheels, DifferentialWheelsParams, RobotId, RobotMode, RobotPlacement,
};
use crate::error::{BodyOwner, BodyPart, SimError, panic_message};
use crate::geom::{self, G_ROAD, G_STATIC};
use crate::ground::{Ground, Surface};
use crate::road::{LaneKind, RoadError};
use crate::vehicle::{Vehicle, VehicleId, VehiclePlacement, VehicleSpec, WheelRoadHooks};

mod contact;
mod scene;
mod snapshot;
mod supervisor;
pub(crate) use snapshot::WorldSnapshot;
pub use supervisor::{Placement, rotation_from_axis_angle};

/// A physics world with a flat ground at z = 0, static obstacles, cars and DifferentialWheels
/// robots, advanced by [`World::step`] in fixed steps of `basicTimeStep`.
///
/// Everything is stored in insertion order and stepped in that order, so the same world built
/// the same way with the same commands produces bit-identical results on the same machine.
///
/// ```
/// use sim::{World, WorldConfig, DifferentialWheelsParams, RobotMode, RobotPlacement};
/// let mut world = World::new(WorldConfig::default())?;
/// let params = DifferentialWheelsParams { slip_noise: 0.0, ..Default::default() };
/// let id = world.add_differential_wheels(params, RobotMode::Kinematics, RobotPlacement::default())?;
/// world.robot_mut(id)?.set_speed(5.0, 5.0);
/// for _ in 0..100 {
///     world.step()?;
/// }
/// assert_eq!(world.time_ms(), 1000);
/// assert!(world.robot(id)?.pose().position.x > 0.0);
/// # Ok::<(), sim::SimError>(())
/// ```
pub struct World {
    config: WorldConfig,
    physics: PhysicsWorld,
    /// The friction of what the cars' wheels stand on, in f64 (rapier's colliders keep theirs
    /// in f32 for its own contacts).
    ground: Ground,
    vehicles: Vec<Vehicle>,
    robots: Vec<DifferentialWheels>,
    /// The dynamic boxes, in `config.bodies` order.
    bodies: Vec<RigidBodyHandle>,
    /// The static obstacles' colliders, with each one's index in `config.obstacles`.
    obstacles: Vec<(usize, ColliderHandle)>,
    /// The road lanes' colliders, with each lane's kind (its colour to an infra-red sensor).
    lanes: Vec<(ColliderHandle, LaneKind)>,
    time_ms: u64,
    last_substeps: usize,
    failure: Option<SimError>,
    /// Whose part of the step runs (a vehicle's, a robot's, or rapier's for the whole world),
    /// for the [`SimError::Panic`] of a step that panics.
    stepping: BodyOwner,
}

impl World {
    /// Builds the ground and obstacles of `config`, or names the first invalid field.
    pub fn new(config: WorldConfig) -> Result<World, SimError> {
        config.validate()?;
        config.roads.validate()?;
        let mut physics = PhysicsWorld::new();
        physics.gravity = geom::vector(&config.gravity);
        physics.integration_parameters = integration_parameters(&config);
        let mut world = World {
            physics,
            ground: Ground::new(config.ground_friction),
            vehicles: Vec::new(),
            robots: Vec::new(),
            bodies: Vec::new(),
            obstacles: Vec::new(),
            lanes: Vec::new(),
            time_ms: 0,
            last_substeps: 1,
            failure: None,
            stepping: BodyOwner::World,
            config,
        };
        world.build_static()?;
        // The ground and obstacles enter rapier's query structure in a step; the car wheels
        // look for them before the first one. Nothing moves in this step: the dynamic boxes
        // come after it, so that they start falling at time 0.
        world.physics.step();
        world.bodies = body::build(&mut world.physics, &world.config.bodies);
        for (h, spec) in world.bodies.iter().zip(&world.config.bodies) {
            let Some(b) = world.physics.bodies.get(*h) else {
                continue;
            };
            for &c in b.colliders() {
                world
                    .ground
                    .add(c, Surface::Uniform(spec.friction_or_default()));
            }
        }
        Ok(world)
    }

    fn build_static(&mut self) -> Result<(), SimError> {
        let mu = self.config.ground_friction;
        let statics = |b: ColliderBuilder, friction: f64| {
            b.friction(friction as f32)
                .friction_combine_rule(CoefficientCombineRule::Multiply)
                .collision_groups(geom::groups(G_STATIC))
        };
        let ground = self.physics.insert_collider(
            statics(
                ColliderBuilder::halfspace(Unit::new_unchecked(Vector::Z)),
                mu,
            ),
            None,
        );
        self.ground.add(ground, Surface::Uniform(mu));
        for (i, o) in self.config.obstacles.iter().enumerate() {
            let (at, yaw) = o.placement();
            let mut pose = geom::pose_xyz_yaw(&at, yaw);
            let shape = match *o {
                Obstacle::Box { half_extents, .. } => {
                    let half = geom::vector(&half_extents);
                    ColliderBuilder::cuboid(half.x, half.y, half.z)
                }
                Obstacle::Cone { ref cone, .. } => {
                    // rapier's cone stands on y, centred on its axis' middle: turned a
                    // quarter about x, its y becomes the world's z.
                    pose = Pose::from_parts(
                        geom::point(&cone.centre()),
                        Rotation::from_rotation_x(core::f32::consts::FRAC_PI_2),
                    );
                    ColliderBuilder::cone((cone.height / 2.0) as f32, cone.radius as f32)
                }
                Obstacle::Ramp {
                    length,
                    width,
                    height,
                    ..
                } => {
                    let points = ramp_corners(length, width, height)
                        .map(|[x, y, z]| Vector::new(x as f32, y as f32, z as f32));
                    match ColliderBuilder::convex_hull(&points) {
                        Some(b) => b,
                        // Validated dimensions always give a hull; skip rather than panic.
                        None => continue,
                    }
                }
            };
            let friction = o.friction().unwrap_or(mu);
            let collider = statics(shape, friction).position(pose);
            let handle = self.physics.insert_collider(collider, None);
            self.ground.add(handle, Surface::Uniform(friction));
            self.obstacles.push((i, handle));
        }
        // Each lane of each lane section is a collider of its own with its own friction: the
        // wheels' code asks the ground for the collider's friction and does not change.
        for road in &self.config.roads.roads {
            for mesh in road.lane_meshes(ROAD_LIFT) {
                let vertices = mesh.vertices.iter().map(geom::point).collect();
                let builder = ColliderBuilder::trimesh_with_flags(
                    vertices,
                    mesh.triangles,
                    TriMeshFlags::FIX_INTERNAL_EDGES,
                )
                .map_err(|e| RoadError {
                    road: road.id.clone(),
                    field: format!("lane section {} lane {}", mesh.section + 1, mesh.lane),
                    message: format!("its surface is no triangle mesh: {e}"),
                })?;
                let collider =
                    statics(builder, mesh.friction).collision_groups(geom::groups(G_ROAD));
                let handle = self.physics.insert_collider(collider, None);
                self.ground.add(handle, Surface::Uniform(mesh.friction));
                self.lanes.push((handle, mesh.kind));
            }
        }
        Ok(())
    }

    /// The configuration this world was built from.
    pub fn config(&self) -> &WorldConfig {
        &self.config
    }

    /// The step length (s): `basicTimeStep / 1000`.
    pub fn dt(&self) -> f64 {
        self.config.dt()
    }

    /// Simulated time (ms): the number of steps times `basicTimeStep`.
    pub fn time_ms(&self) -> u64 {
        self.time_ms
    }

    /// Simulated time (s). Webots: `wb_robot_get_time`.
    pub fn time(&self) -> f64 {
        self.time_ms as f64 / 1000.0
    }

    /// Adds a car built from `spec` at `placement`; fails on an invalid field.
    pub fn add_vehicle(
        &mut self,
        spec: VehicleSpec,
        placement: VehiclePlacement,
    ) -> Result<VehicleId, SimError> {
        if let Some(e) = &self.failure {
            return Err(e.clone());
        }
        let id = VehicleId(self.vehicles.len());
        let mut placement = placement;
        // A car given no height starts on what is under it: a road's surface, else the
        // ground.
        if placement.z.is_none()
            && let Some((i, at)) = self
                .config
                .roads
                .locate(&Point2::new(placement.x, placement.y))
        {
            let road = &self.config.roads.roads[i];
            let surface = road.surface_point(at.s, at.t).z + ROAD_LIFT;
            placement.z = Some(surface + crate::vehicle::rest_height(&spec));
        }
        // Built under the same guard as a step (see `step`): shapes and joints go through
        // parry's and rapier's assertions.
        let built = catch_unwind(AssertUnwindSafe(|| {
            Vehicle::new(id, &mut self.physics, spec, placement)
        }))
        .unwrap_or_else(|payload| {
            let e = SimError::PanicWhileAdding {
                owner: BodyOwner::Vehicle(id.0),
                message: panic_message(payload.as_ref()),
            };
            self.failure = Some(e.clone());
            Err(e)
        });
        self.vehicles.push(built?);
        Ok(id)
    }

    /// The car `id`.
    pub fn vehicle(&self, id: VehicleId) -> Result<&Vehicle, SimError> {
        self.vehicles
            .get(id.0)
            .ok_or(SimError::UnknownVehicle(id.0))
    }

    /// The car `id`, to command it.
    pub fn vehicle_mut(&mut self, id: VehicleId) -> Result<&mut Vehicle, SimError> {
        self.vehicles
            .get_mut(id.0)
            .ok_or(SimError::UnknownVehicle(id.0))
    }

    /// All cars in insertion order.
    pub fn vehicles(&self) -> &[Vehicle] {
        &self.vehicles
    }

    /// Car `id`'s mechanical energy (J): the kinetic energy of its rapier bodies (the chassis
    /// and, on joints, the wheels: translation of the centre of mass and rotation), their
    /// potential energy in the world's gravity (zero at the world's origin), the energy held in
    /// its suspension springs (`½·k·x²` at each wheel's compression), and, for a cast car,
    /// whose wheels are no bodies, the wheels' spin energy `½·I·ω²` relative to the chassis,
    /// and, on both, the engaged engine's `½·J·ω²` with each torque-driven wheel's share of its
    /// reflected inertia (`Commands::driveline`).
    ///
    /// rapier computes a body's mass properties in a step: before the world's first step the
    /// bodies count for nothing here.
    ///
    /// Only the engine and gravity put energy into a car; the tyres, brakes, dampers and
    /// contacts take it out. A car whose throttle is off cannot gain it: the tests hold every
    /// car to that (issue #37, where a rolled car was thrown 76 m up).
    pub fn mechanical_energy(&self, id: VehicleId) -> Result<f64, SimError> {
        let vehicle = self.vehicle(id)?;
        let g = self.physics.gravity;
        let gravity = [g.x, g.y, g.z].map(f64::from);
        let mut energy = 0.0;
        for body in vehicle
            .bodies()
            .into_iter()
            .filter_map(|h| self.physics.bodies.get(h))
        {
            let com = body.center_of_mass();
            let height = -(gravity[0] * f64::from(com.x)
                + gravity[1] * f64::from(com.y)
                + gravity[2] * f64::from(com.z));
            energy += f64::from(body.kinetic_energy()) + f64::from(body.mass()) * height;
        }
        let (spec, state) = (vehicle.spec(), vehicle.state());
        for (w, x) in state.suspension.0.iter().enumerate() {
            let springs = if w < 2 {
                spec.front_suspension
            } else {
                spec.rear_suspension
            };
            energy += 0.5 * springs.stiffness * x * x;
        }
        for (w, omega) in state.wheel_speeds.iter_wheels() {
            // A cast car's wheels are no bodies: their own spin counts here (on joints it never
            // did); the engaged engine's share counts on both.
            let own = (!vehicle.on_joints()).then(|| spec.wheels[w].spin_inertia());
            let inertia = own.unwrap_or(0.0) + vehicle.reflected_inertia(w);
            energy += 0.5 * inertia * omega * omega;
        }
        Ok(energy)
    }

    /// Adds a DifferentialWheels robot at `placement`; fails on an invalid field.
    pub fn add_differential_wheels(
        &mut self,
        params: DifferentialWheelsParams,
        mode: RobotMode,
        placement: RobotPlacement,
    ) -> Result<RobotId, SimError> {
        if let Some(e) = &self.failure {
            return Err(e.clone());
        }
        let id = RobotId(self.robots.len());
        let now = self.time_ms;
        let built = catch_unwind(AssertUnwindSafe(|| {
            DifferentialWheels::new(id, &mut self.physics, params, mode, placement, now)
        }))
        .unwrap_or_else(|payload| {
            let e = SimError::PanicWhileAdding {
                owner: BodyOwner::Robot(id.0),
                message: panic_message(payload.as_ref()),
            };
            self.failure = Some(e.clone());
            Err(e)
        });
        self.robots.push(built?);
        Ok(id)
    }

    /// The robot `id`.
    pub fn robot(&self, id: RobotId) -> Result<&DifferentialWheels, SimError> {
        self.robots.get(id.0).ok_or(SimError::UnknownRobot(id.0))
    }

    /// The robot `id`, to command it.
    pub fn robot_mut(&mut self, id: RobotId) -> Result<&mut DifferentialWheels, SimError> {
        self.robots
            .get_mut(id.0)
            .ok_or(SimError::UnknownRobot(id.0))
    }

    /// All robots in insertion order.
    pub fn robots(&self) -> &[DifferentialWheels] {
        &self.robots
    }

    /// The poses of the dynamic boxes after the last step, in the order of
    /// [`WorldConfig::bodies`]. A box whose state stopped being finite ends the step with
    /// [`SimError::NonFinite`] first, so every pose here is finite.
    pub fn bodies(&self) -> Vec<BodyPose> {
        self.bodies
            .iter()
            .filter_map(|h| body::pose(&self.physics, *h))
            .collect()
    }

    /// The dynamic boxes' rapier bodies, in the order of [`WorldConfig::bodies`].
    pub(crate) fn body_handles(&self) -> &[RigidBodyHandle] {
        &self.bodies
    }

    /// The static obstacles' colliders, each with its index in [`WorldConfig::obstacles`].
    pub(crate) fn obstacle_colliders(&self) -> &[(usize, ColliderHandle)] {
        &self.obstacles
    }

    /// The road lanes' colliders, each with its lane's kind.
    pub(crate) fn lane_colliders(&self) -> &[(ColliderHandle, LaneKind)] {
        &self.lanes
    }

    /// Advances the world by one `basicTimeStep`: applies every vehicle's and robot's commands,
    /// steps rapier (1 to [`MAX_SUBSTEPS`] times, see [`World::last_substeps`]), then reads the
    /// sensors back.
    ///
    /// Fails with [`SimError::NonFinite`] if any body's state stops being finite, and with
    /// [`SimError::Panic`] if a panic (a rapier or parry assertion) interrupts the step; the
    /// world then keeps returning that error and never steps again.
    pub fn step(&mut self) -> Result<(), SimError> {
        if let Some(e) = &self.failure {
            return Err(e.clone());
        }
        // Why the engine catches panics: the step runs rapier and parry, which assert on
        // geometry and numbers that this crate validates but cannot prove in every case (f32
        // roundings of shapes, degenerate contacts). Uncaught, such a panic would end a
        // `vehicle-sim` run with exit code 101, take down a whole sweep's thread pool, or reach
        // a C controller's guard or Python as a bare `PanicException`, none of them saying
        // which vehicle. Caught here, it is the run's typed error naming whose part of the
        // step was running, and the world, possibly left half-stepped, is marked failed and
        // never steps again, so no caller builds on a state that a panic interrupted (reading
        // it stays memory-safe: all of it is safe Rust). This relies on `panic = "unwind"`,
        // the default of every profile of the workspace; under `panic = "abort"` the process
        // ends as it would have anyway.
        let start_ms = self.time_ms;
        let result =
            catch_unwind(AssertUnwindSafe(|| self.step_inner())).unwrap_or_else(|payload| {
                Err(SimError::Panic {
                    owner: self.stepping,
                    time_ms: start_ms,
                    message: panic_message(payload.as_ref()),
                })
            });
        if let Err(e) = &result {
            self.failure = Some(e.clone());
        }
        result
    }

    /// The number of rapier steps that make up the coming `basicTimeStep`.
    ///
    /// One rapier step with one solver substep is exact for a rolling wheel of a physics-mode
    /// DifferentialWheels robot whatever its speed: rapier computes the contact points at the
    /// start of the step and only re-evaluates them (as points fixed to each body) between
    /// solver substeps, which a spinning wheel would break (at 80 rad/s a wheel turns 0.4 rad in
    /// a 5 ms substep and its contact point rises by r·(1 − cos 0.4) = 3 cm in the solver's
    /// eyes). What still depends on the rotation per step is rapier's implicit gyroscopic term,
    /// first order in ω·dt: as a margin, a step in which a robot wheel would turn more than
    /// [`MAX_WHEEL_ROTATION_PER_SUBSTEP`] (judged from the wheel speeds of the previous step) is
    /// split into equal rapier steps; at most [`MAX_SUBSTEPS`]. Car wheels are not rapier
    /// bodies (their spin does not enter rapier) and never split a step.
    fn substeps(&self, dt: f64) -> usize {
        let rotation = self
            .robots
            .iter()
            .map(|r| r.max_wheel_rotation(dt))
            .fold(0.0_f64, f64::max);
        let mut n = (rotation / MAX_WHEEL_ROTATION_PER_SUBSTEP).ceil();
        if self.vehicles.iter().any(Vehicle::on_joints) {
            n = n.max((dt / MAX_JOINTS_SUBSTEP).ceil());
        }
        if n.is_finite() && n > 1.0 {
            (n as usize).min(MAX_SUBSTEPS)
        } else {
            1
        }
    }

    /// Why the world stopped stepping, if a step failed ([`World::step`]).
    pub fn failure(&self) -> Option<&SimError> {
        self.failure.as_ref()
    }

    /// The number of rapier steps the last `basicTimeStep` took (1 to [`MAX_SUBSTEPS`]).
    pub fn last_substeps(&self) -> usize {
        self.last_substeps
    }

    /// The owner and part of the rapier body `handle` (`World`/`Other` for none of ours).
    fn owner_of(&self, handle: Option<RigidBodyHandle>) -> (BodyOwner, BodyPart) {
        let Some(h) = handle else {
            return (BodyOwner::World, BodyPart::Other);
        };
        let vehicle = self
            .vehicles
            .iter()
            .enumerate()
            .find_map(|(i, v)| v.part_of(h).map(|part| (BodyOwner::Vehicle(i), part)));
        let robot = || {
            self.robots
                .iter()
                .enumerate()
                .find_map(|(i, r)| r.part_of(h).map(|part| (BodyOwner::Robot(i), part)))
        };
        let body = || {
            self.bodies
                .iter()
                .position(|b| *b == h)
                .map(|i| (BodyOwner::World, BodyPart::Box(i)))
        };
        vehicle
            .or_else(robot)
            .or_else(body)
            .unwrap_or((BodyOwner::World, BodyPart::Other))
    }

    fn step_inner(&mut self) -> Result<(), SimError> {
        let dt = self.dt();
        let substeps = self.substeps(dt);
        let sub_dt = dt / substeps as f64;
        for (i, r) in self.robots.iter_mut().enumerate() {
            self.stepping = BodyOwner::Robot(i);
            r.pre_step(&mut self.physics, dt);
        }
        self.physics.integration_parameters.dt = sub_dt as f32;
        let wind = geom::vector(&self.config.wind);
        for k in 0..substeps {
            // A car on joints hands rapier forces that hold for one rapier step (its tyre
            // loads are the last step's contact impulses), so it is solved again before each;
            // a cast car sets its chassis velocity for the whole basicTimeStep.
            for (i, v) in self.vehicles.iter_mut().enumerate() {
                self.stepping = BodyOwner::Vehicle(i);
                if v.on_joints() {
                    v.pre_step(&mut self.physics, &self.ground, wind, sub_dt);
                } else if k == 0 {
                    v.pre_step(&mut self.physics, &self.ground, wind, dt);
                }
            }
            self.stepping = BodyOwner::World;
            self.physics.step_with_events(&WheelRoadHooks, &());
        }
        self.last_substeps = substeps;
        self.time_ms += u64::from(self.config.basic_time_step_ms);
        let quarantined = self.physics.quarantine();
        let diverged = self
            .bodies
            .iter()
            .position(|h| geom::finite_body(&self.physics, *h).is_none())
            .map(|i| (BodyOwner::World, BodyPart::Box(i)))
            .or_else(|| {
                let handle = quarantined
                    .colliders()
                    .iter()
                    .find_map(|c| self.physics.colliders.get(*c).and_then(|c| c.parent()))
                    .or_else(|| quarantined.bodies().first().copied());
                (!quarantined.is_empty()).then(|| self.owner_of(handle))
            });
        if let Some((owner, part)) = diverged {
            return Err(SimError::diverged(owner, self.time_ms)(part));
        }
        for (i, v) in self.vehicles.iter_mut().enumerate() {
            self.stepping = BodyOwner::Vehicle(i);
            v.post_step(&self.physics, dt, self.time_ms)?;
        }
        for (i, r) in self.robots.iter_mut().enumerate() {
            self.stepping = BodyOwner::Robot(i);
            r.post_step(&self.physics, dt, self.time_ms)?;
        }
        self.stepping = BodyOwner::World;
        Ok(())
    }
}

/// Height (m) of a road's colliders above its profile: where a road lies on the flat ground
/// (z = 0) the wheels' shape casts and contacts meet the road, with its lanes' friction,
/// rather than the ground plane at the same height. The geometry ([`crate::road`]) answers
/// the profile's exact heights.
pub const ROAD_LIFT: f64 = 1e-3;

/// Largest wheel rotation (rad) per rapier step before the world splits its steps.
pub const MAX_WHEEL_ROTATION_PER_SUBSTEP: f64 = 1.0;

/// Longest rapier step (s) of a world with a car on joints: the wheel bodies on their stiff
/// suspension springs (truck: 10⁶ N/m on 35 kg, a period of 37 ms) need a few steps per
/// period, and the tyre forces are held for one step.
pub const MAX_JOINTS_SUBSTEP: f64 = 0.02;

/// Largest number of rapier steps per `basicTimeStep`.
pub const MAX_SUBSTEPS: usize = 8;

/// rapier's parameters for `config`.
///
/// Contact recycling is off: it would reuse a robot wheel's contact points for several steps
/// while the wheel rolls (they move with the tyre), which makes the ride bumpy; the ground
/// contacts are few and cheap to recompute.
///
/// Friction stays out of the biased pass (`friction_in_bias_pass: false`, rapier's default):
/// with it in, the friction also answers the contacts' position-correction velocities, which
/// makes a driven wheel slip and a braked one grip too hard. It is solved in the
/// `friction_iterations` unbiased sweeps (see [`SolverSettings`](crate::SolverSettings)).
fn integration_parameters(config: &WorldConfig) -> IntegrationParameters {
    IntegrationParameters {
        dt: config.dt() as f32,
        num_solver_iterations: config.solver.iterations,
        num_internal_pgs_iterations: config.solver.pgs_iterations,
        contact_recycling: false,
        num_internal_stabilization_iterations: config.solver.friction_iterations,
        ..IntegrationParameters::default()
    }
}

mod cone;
pub use cone::{
    CONE_COLOR, CONE_HEIGHTS, CONE_RADII, Cone, DEFAULT_CONE_HEIGHT, DEFAULT_CONE_RADIUS,
    DEFAULT_CONE_RCS,
};

// The ground's friction as both mountings read it in a world.
#[cfg(test)]
mod ground_tests;

#[cfg(test)]
mod tests;
