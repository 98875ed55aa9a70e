//! The state of a [`World`], copied out and put back: see [`WorldSnapshot`].

use rapier3d::prelude::{
    BroadPhaseBvh, CCDSolver, ColliderHandle, ColliderSet, ImpulseJointSet, IntegrationParameters,
    IslandManager, MultibodyJointSet, NarrowPhase, RigidBodyHandle, RigidBodySet, SoftBodySet,
    Vector,
};

use super::World;
use crate::config::WorldConfig;
use crate::diff_wheels::DifferentialWheels;
use crate::error::{BodyOwner, SimError};
use crate::ground::Ground;
use crate::vehicle::Vehicle;

/// Everything a [`World`] is at one instant: rapier's sets (bodies, colliders, both joint
/// sets), its island manager, broad phase (its BVH and pair cache) and narrow phase (the
/// contact graph with every manifold's warm-start impulses), the CCD solver's state, and the
/// world's own cars (wheel spin, suspension, motor and tyre state, road caches), robots, time
/// and failure.
///
/// rapier's pipelines are not in it: they hold only scratch buffers, rebuilt every step
/// (rapier's own `PhysicsWorld` leaves them out of its serialised form for that reason). A
/// world restored from a snapshot therefore steps bit for bit as the world it was taken from.
#[derive(Clone)]
pub(crate) struct WorldSnapshot {
    config: WorldConfig,
    gravity: Vector,
    integration_parameters: IntegrationParameters,
    islands: IslandManager,
    broad_phase: BroadPhaseBvh,
    narrow_phase: NarrowPhase,
    bodies: RigidBodySet,
    colliders: ColliderSet,
    impulse_joints: ImpulseJointSet,
    multibody_joints: MultibodyJointSet,
    soft_bodies: SoftBodySet,
    ccd_solver: CCDSolver,
    ground: Ground,
    vehicles: Vec<Vehicle>,
    robots: Vec<DifferentialWheels>,
    box_bodies: Vec<RigidBodyHandle>,
    obstacles: Vec<(usize, ColliderHandle)>,
    time_ms: u64,
    last_substeps: usize,
    failure: Option<SimError>,
    stepping: BodyOwner,
}

impl World {
    /// A copy of the whole state of this world (see [`WorldSnapshot`]).
    pub(crate) fn snapshot(&self) -> WorldSnapshot {
        let p = &self.physics;
        WorldSnapshot {
            config: self.config.clone(),
            gravity: p.gravity,
            integration_parameters: p.integration_parameters,
            islands: p.islands.clone(),
            broad_phase: p.broad_phase.clone(),
            narrow_phase: p.narrow_phase.clone(),
            bodies: p.bodies.clone(),
            colliders: p.colliders.clone(),
            impulse_joints: p.impulse_joints.clone(),
            multibody_joints: p.multibody_joints.clone(),
            soft_bodies: p.soft_bodies.clone(),
            ccd_solver: p.ccd_solver.clone(),
            ground: self.ground.clone(),
            vehicles: self.vehicles.clone(),
            robots: self.robots.clone(),
            box_bodies: self.bodies.clone(),
            obstacles: self.obstacles.clone(),
            time_ms: self.time_ms,
            last_substeps: self.last_substeps,
            failure: self.failure.clone(),
            stepping: self.stepping,
        }
    }

    /// Puts this world back in the state of `snap`, which keeps its copy (a snapshot can be
    /// restored any number of times).
    pub(crate) fn restore(&mut self, snap: &WorldSnapshot) {
        let p = &mut self.physics;
        p.gravity = snap.gravity;
        p.integration_parameters = snap.integration_parameters;
        p.islands = snap.islands.clone();
        p.broad_phase = snap.broad_phase.clone();
        p.narrow_phase = snap.narrow_phase.clone();
        p.bodies = snap.bodies.clone();
        p.colliders = snap.colliders.clone();
        p.impulse_joints = snap.impulse_joints.clone();
        p.multibody_joints = snap.multibody_joints.clone();
        p.soft_bodies = snap.soft_bodies.clone();
        p.ccd_solver = snap.ccd_solver.clone();
        self.config = snap.config.clone();
        self.ground = snap.ground.clone();
        self.vehicles = snap.vehicles.clone();
        self.robots = snap.robots.clone();
        self.bodies = snap.box_bodies.clone();
        self.obstacles = snap.obstacles.clone();
        self.time_ms = snap.time_ms;
        self.last_substeps = snap.last_substeps;
        self.failure = snap.failure.clone();
        self.stepping = snap.stepping;
    }
}

impl WorldSnapshot {
    /// Simulated time when the snapshot was taken (ms).
    pub(crate) fn time_ms(&self) -> u64 {
        self.time_ms
    }
}
