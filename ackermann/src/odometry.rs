//! Dead reckoning of the rear-axle centre from wheel speeds and the steering angle (an extension:
//! Webots has no odometry).
//!
//! # Model
//!
//! Kinematic bicycle model referenced at the rear-axle centre, with no tyre slip: the car turns
//! about the centre given by the central steering angle δ ([`Geometry::turning`]), so the
//! forward speed `v` of the rear-axle centre and the yaw rate `ψ̇` are tied by
//! `ψ̇ = −v·tan δ / L`. (The minus sign: positive δ steers right, which is a clockwise, i.e.
//! negative, yaw rate about +z.) `v` comes from the wheels chosen by [`SpeedSource`].
//!
//! Each step holds `v` and `ψ̇` constant over `dt` and moves the pose along the exact circular
//! arc (a straight segment when `ψ̇ = 0`), not an Euler step, so a constant-radius drive closes
//! its circle to rounding error whatever the step size.

use core::fmt;

use crate::drive::DriveType;
use crate::geometry::Geometry;
use crate::real::Real;
use crate::steering::sin_cos;
use crate::turning::Turning;
use crate::wheel::{PerWheel, Wheel};

/// A planar pose of the rear-axle centre in the odometry frame (x forward and y left at the
/// start, z up, as in ROS REP 103).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose<T: Real> {
    /// Position along the odometry frame's x axis (m).
    pub x: T,
    /// Position along the odometry frame's y axis (m).
    pub y: T,
    /// Heading: angle from the odometry x axis to the car's x axis, counter-clockwise about +z
    /// (rad, kept in (−π, π] by [`Odometry`]).
    pub yaw: T,
}

impl<T: Real> Pose<T> {
    /// The origin, heading along +x.
    pub const ORIGIN: Self = Pose {
        x: T::ZERO,
        y: T::ZERO,
        yaw: T::ZERO,
    };

    /// Builds a pose from a position (m) and a heading (rad, counter-clockwise).
    #[inline]
    pub const fn new(x: T, y: T, yaw: T) -> Self {
        Pose { x, y, yaw }
    }

    /// True if all three components are finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.yaw.is_finite()
    }
}

/// The planar velocity of the rear-axle centre, in the car's frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Velocity<T: Real> {
    /// Speed along the car's x axis (m/s, negative when reversing). The rear-axle centre has no
    /// lateral speed in this model.
    pub forward: T,
    /// Yaw rate about +z (rad/s, counter-clockwise positive: a right turn driving forward is
    /// negative).
    pub yaw_rate: T,
}

impl<T: Real> Velocity<T> {
    /// Builds from a forward speed (m/s) and a counter-clockwise yaw rate (rad/s).
    #[inline]
    pub const fn new(forward: T, yaw_rate: T) -> Self {
        Velocity { forward, yaw_rate }
    }
}

/// Which wheel speeds measure the car's speed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum SpeedSource {
    /// Mean ground speed of the two rear wheels (`(ωRR + ωRL)/2 · rr`), which is exactly the
    /// rear-axle centre's speed at any steering angle. The yaw rate is `−v·tan δ / L`, except at
    /// δ = ±π/2 where `v` is 0 while the car pivots; there it is `(vRR − vRL) / Tr`.
    #[default]
    RearWheels,
    /// The two front wheels: each wheel's ground speed `ω·rf` is scaled to the front-axle
    /// centre's speed by the ratio of their turning radii (|front virtual| / |wheel| radius),
    /// the two estimates are averaged into `vf`, then `v = vf·cos δ` and
    /// `ψ̇ = −vf·sin δ / L`. Well defined at every angle, including the pivot.
    FrontWheels,
}

impl SpeedSource {
    /// The axle that slips least for a drive type: the non-driven one (rear wheels for traction,
    /// front wheels for propulsion), and the rear wheels for 4x4, whose radii do not depend on
    /// the steering linkage.
    #[inline]
    pub const fn for_drive(drive: DriveType) -> SpeedSource {
        match drive {
            DriveType::Propulsion => SpeedSource::FrontWheels,
            DriveType::Traction | DriveType::FourByFour => SpeedSource::RearWheels,
        }
    }
}

/// Why an odometry step was ignored (the pose and velocity are left unchanged).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OdometryWarning {
    /// A wheel speed that the [`SpeedSource`] uses was NaN or infinite (rad/s).
    NonFiniteWheelSpeed {
        /// The offending wheel.
        wheel: Wheel,
        /// Its speed (rad/s), widened to `f64`.
        value: f64,
    },
    /// The steering angle was NaN or infinite (rad).
    NonFiniteSteering {
        /// The angle (rad), widened to `f64`.
        value: f64,
    },
    /// A velocity given to [`Odometry::integrate`] was NaN or infinite.
    NonFiniteVelocity {
        /// Forward speed (m/s), widened to `f64`.
        forward: f64,
        /// Yaw rate (rad/s), widened to `f64`.
        yaw_rate: f64,
    },
    /// The time step was negative, NaN or infinite (s).
    InvalidTimeStep {
        /// The time step (s), widened to `f64`.
        value: f64,
    },
    /// The step would move the pose, or the velocity, beyond the range of `T`.
    Overflow,
}

impl fmt::Display for OdometryWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OdometryWarning::NonFiniteWheelSpeed { wheel, value } => {
                write!(
                    f,
                    "odometry step ignored: {wheel:?} wheel speed is {value} rad/s"
                )
            }
            OdometryWarning::NonFiniteSteering { value } => {
                write!(f, "odometry step ignored: steering angle is {value} rad")
            }
            OdometryWarning::NonFiniteVelocity { forward, yaw_rate } => write!(
                f,
                "odometry step ignored: velocity is {forward} m/s, {yaw_rate} rad/s"
            ),
            OdometryWarning::InvalidTimeStep { value } => write!(
                f,
                "odometry step ignored: time step is {value} s (must be finite and >= 0)"
            ),
            OdometryWarning::Overflow => f.write_str(
                "odometry step ignored: the pose would leave the range of the float type",
            ),
        }
    }
}

impl core::error::Error for OdometryWarning {}

/// Integrates the pose of the rear-axle centre (see the [module documentation](self) for the
/// model).
///
/// ```
/// use ackermann::{Geometry, Odometry, PerWheel, SpeedSource};
/// let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374).unwrap();
/// let mut odo = Odometry::new(g, SpeedSource::RearWheels);
/// // 1 s straight ahead with all wheels at 10 rad/s: 3.74 m.
/// let pose = odo.update(PerWheel::splat(10.0), 0.0, 1.0).unwrap();
/// assert!((pose.x - 3.74).abs() < 1e-12 && pose.y == 0.0 && pose.yaw == 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Odometry<T: Real> {
    geometry: Geometry<T>,
    source: SpeedSource,
    pose: Pose<T>,
    velocity: Velocity<T>,
    distance: T,
}

impl<T: Real> Odometry<T> {
    /// Starts at [`Pose::ORIGIN`], at rest.
    pub fn new(geometry: Geometry<T>, source: SpeedSource) -> Self {
        Odometry {
            geometry,
            source,
            pose: Pose::ORIGIN,
            velocity: Velocity::default(),
            distance: T::ZERO,
        }
    }

    /// The vehicle geometry used.
    #[inline]
    pub fn geometry(&self) -> &Geometry<T> {
        &self.geometry
    }

    /// The wheels used to measure the speed.
    #[inline]
    pub fn source(&self) -> SpeedSource {
        self.source
    }

    /// Changes the wheels used to measure the speed from the next step on.
    #[inline]
    pub fn set_source(&mut self, source: SpeedSource) {
        self.source = source;
    }

    /// The current pose estimate.
    #[inline]
    pub fn pose(&self) -> Pose<T> {
        self.pose
    }

    /// The velocity of the last accepted step (zero before the first).
    #[inline]
    pub fn velocity(&self) -> Velocity<T> {
        self.velocity
    }

    /// Path length travelled by the rear-axle centre since the start or the last reset (m,
    /// never negative; reversing adds to it).
    #[inline]
    pub fn distance(&self) -> T {
        self.distance
    }

    /// Restarts from `pose` (the yaw is wrapped into (−π, π]), at rest, with a zero distance.
    ///
    /// # Errors
    /// [`OdometryWarning::Overflow`] if `pose` is not finite; nothing changes then.
    pub fn reset(&mut self, pose: Pose<T>) -> Result<(), OdometryWarning> {
        if !pose.is_finite() {
            return Err(OdometryWarning::Overflow);
        }
        self.pose = Pose::new(pose.x, pose.y, wrap_angle(pose.yaw));
        self.velocity = Velocity::default();
        self.distance = T::ZERO;
        Ok(())
    }

    /// The velocity of the rear-axle centre implied by the wheel angular speeds `wheel_speeds`
    /// (rad/s, positive = rolling forward) and the central steering angle `steering` (rad,
    /// positive = right; beyond ±π/2 it is clamped to ±π/2), with the configured
    /// [`SpeedSource`]. Only the two wheels of that source are read.
    ///
    /// # Errors
    /// A non-finite steering angle or used wheel speed, or a velocity beyond the range of `T`.
    pub fn velocity_from_wheels(
        &self,
        wheel_speeds: PerWheel<T>,
        steering: T,
    ) -> Result<Velocity<T>, OdometryWarning> {
        if !steering.is_finite() {
            return Err(OdometryWarning::NonFiniteSteering {
                value: steering.to_f64(),
            });
        }
        let (right, left, radius) = match self.source {
            SpeedSource::RearWheels => (
                Wheel::RearRight,
                Wheel::RearLeft,
                self.geometry.radius_rear(),
            ),
            SpeedSource::FrontWheels => (
                Wheel::FrontRight,
                Wheel::FrontLeft,
                self.geometry.radius_front(),
            ),
        };
        for wheel in [right, left] {
            let value = wheel_speeds[wheel];
            if !value.is_finite() {
                return Err(OdometryWarning::NonFiniteWheelSpeed {
                    wheel,
                    value: value.to_f64(),
                });
            }
        }
        let v_right = wheel_speeds[right] * radius;
        let v_left = wheel_speeds[left] * radius;
        let (s, c) = sin_cos(steering);
        let l = self.geometry.wheelbase();
        let velocity = match self.source {
            SpeedSource::RearWheels => {
                let v = (v_right + v_left) * T::HALF;
                let yaw_rate = if c == T::ZERO {
                    (v_right - v_left) / self.geometry.track_rear()
                } else {
                    -v * s / (l * c)
                };
                Velocity::new(v, yaw_rate)
            }
            SpeedSource::FrontWheels => {
                let (scale_right, scale_left) = match self.geometry.turning(steering) {
                    Turning::Straight => (T::ONE, T::ONE),
                    // |wheel radius| ≥ L > 0 for front wheels, so these divisions are safe.
                    Turning::Circle(r) => (
                        r.front_virtual / r.wheels[Wheel::FrontRight],
                        r.front_virtual / r.wheels[Wheel::FrontLeft],
                    ),
                };
                let vf = (v_right * scale_right + v_left * scale_left) * T::HALF;
                Velocity::new(vf * c, -vf * s / l)
            }
        };
        if velocity.forward.is_finite() && velocity.yaw_rate.is_finite() {
            Ok(velocity)
        } else {
            Err(OdometryWarning::Overflow)
        }
    }

    /// Advances by `dt` (s) with the wheel angular speeds `wheel_speeds` (rad/s) and the central
    /// steering angle `steering` (rad, positive = right), both held over the step, and returns
    /// the new pose.
    ///
    /// # Errors
    /// See [`Odometry::velocity_from_wheels`] and [`Odometry::integrate`]; the state is left
    /// unchanged on error.
    pub fn update(
        &mut self,
        wheel_speeds: PerWheel<T>,
        steering: T,
        dt: T,
    ) -> Result<Pose<T>, OdometryWarning> {
        check_time_step(dt)?;
        let velocity = self.velocity_from_wheels(wheel_speeds, steering)?;
        self.integrate(velocity, dt)
    }

    /// Advances by `dt` (s) with a velocity from another source (m/s and counter-clockwise
    /// rad/s, held over the step) along the exact arc, and returns the new pose.
    ///
    /// # Errors
    /// A non-finite velocity, a negative or non-finite `dt`, or a pose beyond the range of
    /// `T`; the state is left unchanged then.
    pub fn integrate(&mut self, velocity: Velocity<T>, dt: T) -> Result<Pose<T>, OdometryWarning> {
        check_time_step(dt)?;
        if !(velocity.forward.is_finite() && velocity.yaw_rate.is_finite()) {
            return Err(OdometryWarning::NonFiniteVelocity {
                forward: velocity.forward.to_f64(),
                yaw_rate: velocity.yaw_rate.to_f64(),
            });
        }
        let turn = velocity.yaw_rate * dt;
        let half_turn = turn * T::HALF;
        // The chord of the arc: length v·dt·sin(h)/h, direction halfway through the turn.
        // sin(h)/h loses no precision as h → 0; only h = 0 itself needs the limit.
        let sinc = if half_turn == T::ZERO {
            T::ONE
        } else {
            half_turn.sin() / half_turn
        };
        let travelled = velocity.forward * dt;
        let chord = travelled * sinc;
        let heading = self.pose.yaw + half_turn;
        let next = Pose::new(
            self.pose.x + chord * heading.cos(),
            self.pose.y + chord * heading.sin(),
            self.pose.yaw + turn,
        );
        let distance = self.distance + travelled.abs();
        if !(next.is_finite() && distance.is_finite()) {
            return Err(OdometryWarning::Overflow);
        }
        self.pose = Pose::new(next.x, next.y, wrap_angle(next.yaw));
        self.velocity = velocity;
        self.distance = distance;
        Ok(self.pose)
    }
}

fn check_time_step<T: Real>(dt: T) -> Result<(), OdometryWarning> {
    if dt.is_finite() && dt >= T::ZERO {
        Ok(())
    } else {
        Err(OdometryWarning::InvalidTimeStep { value: dt.to_f64() })
    }
}

/// `angle` (rad) wrapped into (−π, π]. Finite input gives finite output.
fn wrap_angle<T: Real>(angle: T) -> T {
    // `%` is the exact fmod: no precision is lost however many turns `angle` holds, and the
    // result lies in (−2π, 2π); the corrections below are exact too (Sterbenz).
    let r = angle % T::TAU;
    if r > T::PI {
        r - T::TAU
    } else if r <= -T::PI {
        r + T::TAU
    } else {
        r
    }
}
