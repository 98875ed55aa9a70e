#![no_std]
#![forbid(unsafe_code)]
//! Ackermann steering geometry for car-like vehicles, as computed by the Webots automobile
//! `driver` library, plus odometry.
//!
//! * [`Geometry::wheel_angles`]: right and left front-wheel angles from a central steering angle
//!   (Webots: `wbu_driver_set_steering_angle`), and the inverses
//!   [`Geometry::central_angle_from_right`], [`Geometry::central_angle_from_left`],
//!   [`Geometry::steering_angle_for_curvature`];
//! * [`Geometry::turning`]: signed turning radii of the rear-axle centre, the virtual front wheel
//!   and each wheel, with a straight line as its own [`Turning::Straight`] variant;
//! * [`Geometry::differential_ratios`]: the geometric front/rear/central torque and speed split
//!   of Webots' driver library;
//! * [`Geometry::wheel_speed_targets`]: the cruise-control wheel speeds of Webots' speed mode;
//! * [`Odometry`]: dead reckoning of the rear-axle centre by exact arc integration (not in
//!   Webots).
//!
//! # Conventions
//!
//! Units are SI: m, rad, m/s, rad/s, s. Vehicle frame: x forward, y left, z up, origin at the
//! rear-axle centre. A **positive steering angle turns right** (as in Webots), and turning radii
//! are positive when the turning centre is on the right. Odometry yaw is counter-clockwise
//! about +z (ROS REP 103), so a right turn has a negative yaw rate. Wheels are ordered
//! front-right, front-left, rear-right, rear-left ([`Wheel`], [`PerWheel`]).
//!
//! # Robustness
//!
//! `no_std`, no allocation, generic over [`Real`] (`f32` for firmware, `f64` elsewhere; all
//! transcendental functions come from `libm` or are polynomials of plain arithmetic, so host and
//! target agree bit for bit). No function panics, and none returns NaN or ∞ for any input: bad
//! dimensions are rejected by [`Geometry::new`], a NaN steering angle means straight ahead, angles
//! beyond ±π/2 mean the pivot at ±π/2 ([`effective_steering_angle`]), and Webots' divisions by
//! zero are replaced by documented limits. Where this crate deliberately differs from Webots is listed in the
//! workspace's `COMPATIBILITY.md`.
//!
//! # Example
//!
//! ```
//! use ackermann::{DriveType, Geometry, Turning, Wheel};
//!
//! // BMW X5: wheelbase, front and rear track, front and rear tyre radius (m).
//! let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374)?;
//!
//! // Steer 0.2 rad to the right: the inner (right) wheel turns more than the outer one.
//! let angles = g.wheel_angles(0.2);
//! assert!((angles.right - 0.211_326).abs() < 1e-6 && (angles.left - 0.189_812).abs() < 1e-6);
//!
//! // The rear-axle centre follows a circle of radius L / tan δ = 14.775 m, centre on the right.
//! let Turning::Circle(radii) = g.turning(0.2) else { unreachable!() };
//! assert!((radii.rear_axle - 14.774_799).abs() < 1e-6);
//!
//! // Cruise at 20 km/h with rear-wheel drive: the outer (left) rear wheel spins faster.
//! let targets = g.wheel_speed_targets(20.0 / 3.6, DriveType::Propulsion, g.ackermann_ratios(0.2));
//! let (inner, outer) = (targets[Wheel::RearRight].unwrap(), targets[Wheel::RearLeft].unwrap());
//! assert!((inner - 14.036_040).abs() < 1e-6 && (outer - 15.672_814).abs() < 1e-6); // rad/s
//! # Ok::<(), ackermann::GeometryError>(())
//! ```

mod cruise;
mod differential;
mod drive;
mod geometry;
pub mod odometry;
mod real;
mod steering;
mod turning;
mod wheel;

pub use differential::DifferentialRatios;
pub use drive::DriveType;
pub use geometry::{Geometry, GeometryError, GeometryField, WheelAngles};
pub use odometry::{Odometry, OdometryWarning, Pose, SpeedSource, Velocity};
pub use real::Real;
pub use steering::effective_steering_angle;
pub use turning::{Turning, TurningRadii};
pub use wheel::{PerWheel, Wheel};

// Compiles and runs the README's example as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctest;
