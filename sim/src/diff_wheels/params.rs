//! The fields of the Webots `DifferentialWheels` node and the simulation mode.

use crate::error::ParamError;
use proto_geom::plausible;

/// The fields of a Webots `DifferentialWheels` node (spec §7.1), with the Webots defaults.
///
/// ```
/// use sim::DifferentialWheelsParams;
/// let p = DifferentialWheelsParams::default();
/// assert_eq!((p.axle_length, p.wheel_radius, p.max_speed), (0.1, 0.01, 10.0));
/// assert!(p.validate().is_ok());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DifferentialWheelsParams {
    /// Power drawn by each motor at full speed (W). Webots: `motorConsumption`, default 0.
    /// Stored and reported; no battery is simulated.
    pub motor_consumption: f64,
    /// Distance between the two wheels (m, > 0). Webots: `axleLength`, default 0.1.
    pub axle_length: f64,
    /// Radius of both wheels (m, > 0). Webots: `wheelRadius`, default 0.01.
    pub wheel_radius: f64,
    /// Largest wheel speed (rad/s, > 0). Webots: `maxSpeed`, default 10.
    pub max_speed: f64,
    /// Largest wheel acceleration in kinematics mode (rad/s², > 0). Webots: `maxAcceleration`,
    /// default 10.
    pub max_acceleration: f64,
    /// Unit of the speed commands (rad/s per unit, > 0). Webots: `speedUnit`, default 1.
    pub speed_unit: f64,
    /// Multiplicative uniform noise on the wheel speeds in kinematics mode (≥ 0, e.g. 0.1 =
    /// ±10 %). Webots: `slipNoise`, default 0.1.
    pub slip_noise: f64,
    /// Multiplicative uniform noise on the encoder increments (≥ 0), or −1 for no encoders.
    /// Webots: `encoderNoise`, default −1.
    pub encoder_noise: f64,
    /// Encoder increments per radian of wheel rotation (≥ 0, or the Webots default −1, which the
    /// Webots code does not special-case: it multiplies). Webots: `encoderResolution`.
    pub encoder_resolution: f64,
    /// Largest motor torque of each wheel in physics mode (N·m, ≥ 0). Webots: `maxForce`,
    /// default 0.3.
    pub max_force: f64,
    /// Seed of the robot's noise generator: the same seed gives the same noise.
    pub seed: u64,
}

impl Default for DifferentialWheelsParams {
    fn default() -> Self {
        DifferentialWheelsParams {
            motor_consumption: 0.0,
            axle_length: 0.1,
            wheel_radius: 0.01,
            max_speed: 10.0,
            max_acceleration: 10.0,
            speed_unit: 1.0,
            slip_noise: 0.1,
            encoder_noise: -1.0,
            encoder_resolution: -1.0,
            max_force: 0.3,
            seed: 0,
        }
    }
}

impl DifferentialWheelsParams {
    /// Checks every field against its Webots range; the lengths, speeds and units must be
    /// strictly positive because the kinematics divides by them, and the lengths, power,
    /// torque and wheel surface speed within their plausible ranges
    /// ([`proto_geom::plausible`]).
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::within("motorConsumption", self.motor_consumption, plausible::POWER)?;
        ParamError::within("axleLength", self.axle_length, plausible::LENGTH)?;
        ParamError::within("wheelRadius", self.wheel_radius, plausible::LENGTH)?;
        ParamError::positive("maxSpeed", self.max_speed)?;
        // The wheel's surface speed at maxSpeed, not the angular speed itself, is what must
        // stay physical.
        ParamError::check(
            "maxSpeed",
            self.max_speed,
            "such that maxSpeed × wheelRadius is at most 1000 m/s",
            |v| plausible::SPEED.contains(v * self.wheel_radius),
        )?;
        ParamError::positive("maxAcceleration", self.max_acceleration)?;
        ParamError::positive("speedUnit", self.speed_unit)?;
        ParamError::non_negative("slipNoise", self.slip_noise)?;
        ParamError::check(
            "encoderNoise",
            self.encoder_noise,
            "-1 or finite and >= 0",
            |v| v == -1.0 || (v.is_finite() && v >= 0.0),
        )?;
        ParamError::check(
            "encoderResolution",
            self.encoder_resolution,
            "-1 or finite and >= 0",
            |v| v == -1.0 || (v.is_finite() && v >= 0.0),
        )?;
        ParamError::within("maxForce", self.max_force, plausible::TORQUE)?;
        Ok(())
    }

    /// True if the node simulates encoders (Webots: `encoderNoise ≥ 0`).
    pub fn has_encoders(&self) -> bool {
        self.encoder_noise >= 0.0
    }
}

/// The bodies of a DifferentialWheels robot simulated in physics mode.
///
/// The robot is a vertical cylinder of radius `axleLength/2` and height `wheelRadius`, centred
/// at wheel-axle height, carrying two frictionless caster balls (radius `wheelRadius/4`, at
/// ±0.8·`axleLength/2` along x) that keep it level, and two wheels on hinges along the axle
/// (y axis), with the mass and inertia of a cylinder `wheelWidth` wide, that touch the ground
/// at one point under their mid-plane (a ball of `wheelRadius`). Webots takes the geometry from the robot's own solids; these defaults
/// stand in for them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobotBody {
    /// Mass of the body with its casters (kg, > 0).
    pub body_mass: f64,
    /// Mass of each wheel (kg, > 0).
    pub wheel_mass: f64,
    /// Width of each wheel (m, > 0).
    pub wheel_width: f64,
}

impl Default for RobotBody {
    /// A 0.5 kg body with 50 g, 1 cm wide wheels.
    fn default() -> Self {
        RobotBody {
            body_mass: 0.5,
            wheel_mass: 0.05,
            wheel_width: 0.01,
        }
    }
}

impl RobotBody {
    /// Checks that masses and width are finite and positive.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::within("robot.body_mass", self.body_mass, plausible::MASS)?;
        ParamError::within("robot.wheel_mass", self.wheel_mass, plausible::MASS)?;
        ParamError::within("robot.wheel_width", self.wheel_width, plausible::LENGTH)?;
        Ok(())
    }
}

/// How a DifferentialWheels robot moves (Webots decides from the presence of `Physics` nodes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RobotMode {
    /// 2-D kinematics with the acceleration limit and slip noise; no body in the physics world,
    /// no gravity, no collisions.
    Kinematics,
    /// Rigid bodies on the physics world: two hinge motors with torque `maxForce`, friction on
    /// the ground.
    Physics(RobotBody),
}

/// Where a robot starts: the ground projection of its axle midpoint and its heading.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RobotPlacement {
    /// World x of the robot origin (m).
    pub x: f64,
    /// World y of the robot origin (m).
    pub y: f64,
    /// Height of the robot origin (m): the ground is at 0.
    pub z: f64,
    /// Heading (rad, counter-clockwise about +z from +x): the direction of forward motion.
    pub heading: f64,
}

impl RobotPlacement {
    pub(crate) fn validate(&self) -> Result<(), ParamError> {
        ParamError::within("robot.x", self.x, plausible::POSITION)?;
        ParamError::within("robot.y", self.y, plausible::POSITION)?;
        ParamError::within("robot.z", self.z, plausible::POSITION)?;
        ParamError::finite("robot.heading", self.heading)?;
        Ok(())
    }
}
