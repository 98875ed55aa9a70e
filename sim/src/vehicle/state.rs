//! What identifies a car, where it starts, and what it measures after a step.

use ackermann::{PerWheel, WheelAngles};
use proto_geom::nalgebra::{Point3, UnitQuaternion, Vector3};

use crate::attitude::RollPitchYaw;

/// Handle of a car in a [`World`](crate::World).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct VehicleId(pub(crate) usize);

impl VehicleId {
    /// The car's index in its world (0 for the first car added).
    pub const fn index(self) -> usize {
        self.0
    }
}

/// Where a car starts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VehiclePlacement {
    /// World x of the car origin (m).
    pub x: f64,
    /// World y of the car origin (m).
    pub y: f64,
    /// Heading (rad, counter-clockwise about +z from +x).
    pub yaw: f64,
    /// Height of the car origin (m); `None` puts the rear wheels on the ground (z = 0), or on
    /// the surface of the road under the car origin if there is one, with unloaded springs:
    /// the body then settles by the static deflection of the springs in about half a second.
    pub z: Option<f64>,
}

/// The physical state of a car after a step: what a test bench would measure on the body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VehicleState {
    /// Position of the car origin (rear-axle centre at wheel-centre height), m, world frame.
    pub position: Point3<f64>,
    /// Roll, pitch and yaw of the chassis (rad, z-y-x convention; yaw in (−π, π]).
    pub roll_pitch_yaw: RollPitchYaw,
    /// Orientation of the chassis: car frame → world.
    pub orientation: UnitQuaternion<f64>,
    /// Velocity of the car origin (m/s, world frame), from the chassis rigid body.
    pub velocity: Vector3<f64>,
    /// Signed speed along the chassis x axis (m/s, positive forward).
    pub forward_speed: f64,
    /// Yaw rate (rad/s, counter-clockwise about world +z).
    pub yaw_rate: f64,
    /// Angular velocity of the chassis (rad/s, world axes).
    pub angular_velocity: Vector3<f64>,
    /// Acceleration of the centre of mass along the chassis x axis over the last step (m/s²).
    pub longitudinal_acceleration: f64,
    /// Acceleration of the centre of mass along the chassis y axis (left) over the last step
    /// (m/s²): positive in a left turn.
    pub lateral_acceleration: f64,
    /// Wheel spin speeds relative to the chassis (rad/s, positive = rolling forward).
    pub wheel_speeds: PerWheel<f64>,
    /// Continuous wheel rotation angles (rad, positive = rolling forward): the Webots wheel
    /// position sensors.
    ///
    /// Each step adds `wheel_speeds · dt`, the rotation at the end-of-step spin rate.
    pub wheel_angles: PerWheel<f64>,
    /// Measured front steering angles (rad, positive = right): the Webots steering sensors.
    pub steering: WheelAngles<f64>,
    /// Suspension compression of each wheel from its unloaded position (m, positive = wheel
    /// pushed up toward the body).
    pub suspension: PerWheel<f64>,
    /// Wiper angle (rad), `None` for a car without wipers.
    pub wiper: Option<f64>,
    /// What each tyre did over the last step.
    pub tyres: PerWheel<TyreTelemetry>,
}

/// What a tyre did over a step: its slips and the forces of the road on it (all zero in the
/// air).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TyreTelemetry {
    /// Slip ratio `κ = (ω·r − v_x)/max(|v_x|, 1 m/s)` at the end of the step (dimensionless:
    /// positive driving, −1 locked), measured against at least walking pace so that it stays
    /// finite at standstill.
    pub slip_ratio: f64,
    /// Slip angle `α = atan2(−v_y, max(|v_x|, 1 m/s))` at the end of the step (rad, positive
    /// when the road pushes the tyre to its left).
    pub slip_angle: f64,
    /// Force of the road along the wheel's heading (N).
    pub fx: f64,
    /// Force of the road along the wheel's axis (N, to the left of an unsteered wheel).
    pub fy: f64,
    /// Load: the suspension force (N, ≥ 0).
    pub fz: f64,
    /// How much of the grip the force uses (dimensionless, 0–1): the radius of the force in the
    /// friction ellipse (slip-based tyre) or the larger axis over `μ·F_z` (Webots' pyramid).
    pub friction_use: f64,
}
