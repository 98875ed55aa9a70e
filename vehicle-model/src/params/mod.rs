//! The parameters of a car: the Webots `Car` and `AckermannVehicle` PROTO fields, the four
//! `VehicleWheel`s, the body's mass properties and the model's optional equipment.

mod body;
mod field;
mod path;
mod set;
mod sound_name;
mod validate;
mod warning;

use ackermann::{DriveType, Geometry, GeometryError, PerWheel, Real, Wheel};
use powertrain::{Brake, Engine, EngineParams, Gearbox, MAX_GEAR_RATIOS, PowertrainError};
use proto_geom::{SensorSlots, WheelParams};

use crate::brake_balance::wheel_mass;
use crate::wipers::WiperRange;

pub use body::{
    BODY_HEIGHT_PER_TRACK, BODY_LENGTH_PER_WHEELBASE, BodyPhysics, is_physical_inertia,
};
pub use field::{CarField, FieldError, FieldKind, FieldValue, NumberRule};
pub use path::{FieldPath, WheelSetting, WheelSlot, wheel_slot_name};
pub use sound_name::EngineSound;
pub use warning::{MAX_PARAM_WARNINGS, ParamReport, ParamWarning, Refusal};

/// The `gearRatio` table: total engine-to-wheel ratios, reverse first (at most
/// [`MAX_GEAR_RATIOS`]).
pub type GearRatios<T> = heapless::Vec<T, MAX_GEAR_RATIOS>;

/// The `Car` PROTO default `gearRatio` `[-12, 10, 6.5, 4.5, 3.5, 2.75]`.
pub const DEFAULT_GEAR_RATIOS: [f64; 6] = [-12.0, 10.0, 6.5, 4.5, 3.5, 2.75];

/// Body mass used when a model has no `Physics` node (the plain `Car` has `physics NULL`), kg.
pub const DEFAULT_BODY_MASS: f64 = 1500.0;

/// The acceleration and velocity limit of a driven wheel's motor in speed mode, derived by the
/// `Car` PROTO from `time0To100`, `maxVelocity` and the tyre radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelMotor<T: Real> {
    /// `(1000/36) / time0To100 / r` (rad/s²): 0 to 100 km/h in `time0To100` seconds at
    /// constant acceleration. Webots motor field `acceleration`.
    pub acceleration: T,
    /// `maxVelocity / r` (rad/s). Webots motor field `maxVelocity`.
    pub max_velocity: T,
}

/// All parameters of a car, in the car frame (x forward, y left, z up, origin at the rear-axle
/// centre at wheel-centre height).
///
/// Fields are public and unvalidated; [`CarParams::validate`] (called by
/// [`Driver::new`](crate::Driver::new)) replaces every invalid value by its default and reports
/// it. [`Default`] gives the plain Webots `Car`; [`Model::params`](crate::Model::params) the
/// shipped models. Fields can also be set by their Webots names with
/// [`CarParams::set_field`].
#[derive(Debug, Clone, PartialEq)]
pub struct CarParams<T: Real> {
    /// Initial position of the car origin in the world (m). Webots field `translation`
    /// (default `0 0 0.4`: 0.4 m wheels on the ground).
    pub translation: [T; 3],
    /// Initial orientation, axis (x, y, z) and angle (rad). Webots field `rotation`
    /// (default `0 0 1 0`).
    pub rotation: [T; 4],
    /// Distance between the front wheel centres (m, > 0). Webots field `trackFront`
    /// (default 1.7).
    pub track_front: T,
    /// Distance between the rear wheel centres (m, > 0). Webots field `trackRear`
    /// (default 1.7).
    pub track_rear: T,
    /// Distance between the front and rear axles (m, > 0). Webots field `wheelbase`
    /// (default 4).
    pub wheelbase: T,
    /// Lower limit of the steering motors (rad; negative = left). Webots field
    /// `minSteeringAngle` (default −1).
    pub min_steering_angle: T,
    /// Upper limit of the steering motors (rad). Webots field `maxSteeringAngle` (default 1).
    pub max_steering_angle: T,
    /// Front suspension stiffness (N/m, ≥ 0). Webots field `suspensionFrontSpringConstant`
    /// (default 100 000).
    pub suspension_front_spring_constant: T,
    /// Front suspension damping (N·s/m, ≥ 0). Webots field `suspensionFrontDampingConstant`
    /// (default 4000).
    pub suspension_front_damping_constant: T,
    /// Rear suspension stiffness (N/m, ≥ 0). Webots field `suspensionRearSpringConstant`
    /// (default 100 000).
    pub suspension_rear_spring_constant: T,
    /// Rear suspension damping (N·s/m, ≥ 0). Webots field `suspensionRearDampingConstant`
    /// (default 4000).
    pub suspension_rear_damping_constant: T,
    /// Viscous damping of every wheel axle (N·m·s/rad, > 0). Webots field
    /// `wheelsDampingConstant` (default 5).
    pub wheels_damping_constant: T,
    /// Torque limit of the steering motors (N·m, ≥ 0). Webots field `maxSteeringTorque`
    /// (default 10 000).
    pub max_steering_torque: T,
    /// The four wheels in slot order FR, FL, RR, RL (Webots fields `wheelFrontRight`,
    /// `wheelFrontLeft`, `wheelRearRight`, `wheelRearLeft`). Like Webots, the front tyre radius
    /// is the front-right wheel's and the rear radius the rear-right wheel's.
    pub wheels: PerWheel<WheelParams<T>>,
    /// Driven axle(s). Webots field `type` (default `"traction"`).
    pub drive_type: DriveType,
    /// Engine model and its fields (Webots fields `engineType`, `engineMaxTorque`,
    /// `engineMaxPower`, `engineMinRPM`, `engineMaxRPM`, `engineFunctionCoefficients`,
    /// `hybridPowerSplitRatio`, `hybridPowerSplitRPM`).
    pub engine: EngineParams<T>,
    /// Engine sound file. Webots field `engineSound` (default `"sounds/engine.wav"`).
    pub engine_sound: EngineSound,
    /// Engine speed at which the engine sound plays at pitch 1 (rpm, > 0). Webots field
    /// `engineSoundRpmReference` (default 1000).
    pub engine_sound_rpm_reference: T,
    /// Brake torque per wheel at full intensity (N·m, > 0). Webots field `brakeCoefficient`
    /// (default 700).
    pub brake_coefficient: T,
    /// Time from 0 to 100 km/h in speed mode (s, > 0), which sets the wheel motors'
    /// acceleration. Webots field `time0To100` (default 10).
    pub time_0_to_100: T,
    /// Top speed in speed mode (m/s, > 0), which sets the wheel motors' velocity limit. Webots
    /// field `maxVelocity` (default 50).
    pub max_velocity: T,
    /// Total engine-to-wheel ratios, reverse first (2 to [`MAX_GEAR_RATIOS`] finite non-zero
    /// values). Webots field `gearRatio` (default [`DEFAULT_GEAR_RATIOS`]).
    pub gear_ratios: GearRatios<T>,
    /// Mass properties of the body without the wheels (Webots: the `Car`'s `physics` node).
    pub body: BodyPhysics<T>,
    /// Range of the two wiper motors, `None` for a car without wipers (Webots: devices
    /// `right_wiper_motor`, `left_wiper_motor` and `wiper_sensor` present).
    pub wipers: Option<WiperRange<T>>,
    /// Frames of the model's sensor slots (Webots fields `sensorsSlotFront`, `sensorsSlotTop`,
    /// `sensorsSlotRear`, `sensorsSlotCenter`) as nalgebra `Isometry3`s in the vehicle frame
    /// (translations in m), `None` for a car without them.
    pub sensor_slots: Option<SensorSlots<T>>,
}

impl<T: Real> Default for CarParams<T> {
    /// The plain Webots `Car` PROTO (R2022b) with default `VehicleWheel`s and no wipers
    /// ([`Model::Car`](crate::Model::Car)). The `Car` has `physics NULL`; the body here is
    /// [`DEFAULT_BODY_MASS`] at mid-wheelbase with the derived box inertia.
    fn default() -> Self {
        crate::Model::Car.params()
    }
}

/// Converts a ratio table (at most [`MAX_GEAR_RATIOS`] entries are kept).
pub(crate) fn gear_ratios<T: Real>(ratios: &[f64]) -> GearRatios<T> {
    gear_ratios_times(ratios, 1.0)
}

/// [`gear_ratios`] with each ratio multiplied by `factor` (a final drive, dimensionless).
pub(crate) fn gear_ratios_times<T: Real>(ratios: &[f64], factor: f64) -> GearRatios<T> {
    let mut table = GearRatios::new();
    for &r in ratios.iter().take(MAX_GEAR_RATIOS) {
        // Cannot fail: at most MAX_GEAR_RATIOS values are pushed.
        let _ = table.push(T::from_f64(r * factor));
    }
    table
}

impl<T: Real> CarParams<T> {
    /// Front tyre radius (m): the front-right wheel's `tireRadius` (as the `Car` PROTO reads it).
    #[inline]
    pub fn radius_front(&self) -> T {
        self.wheels[Wheel::FrontRight].tire_radius
    }

    /// Rear tyre radius (m): the rear-right wheel's `tireRadius`.
    #[inline]
    pub fn radius_rear(&self) -> T {
        self.wheels[Wheel::RearRight].tire_radius
    }

    /// The tyre radius (m) the car library uses for `wheel`'s axle.
    #[inline]
    pub fn axle_radius(&self, wheel: Wheel) -> T {
        if wheel.is_front() {
            self.radius_front()
        } else {
            self.radius_rear()
        }
    }

    /// The steering geometry (wheelbase, tracks, front and rear tyre radii).
    ///
    /// # Errors
    /// [`GeometryError`] if a dimension is not finite and > 0 (never after
    /// [`CarParams::validate`]).
    pub fn geometry(&self) -> Result<Geometry<T>, GeometryError> {
        Geometry::new(
            self.wheelbase,
            self.track_front,
            self.track_rear,
            self.radius_front(),
            self.radius_rear(),
        )
    }

    /// The engine model.
    ///
    /// # Errors
    /// [`PowertrainError`] naming the invalid engine field (never after
    /// [`CarParams::validate`]).
    pub fn engine(&self) -> Result<Engine<T>, PowertrainError> {
        Engine::new(self.engine)
    }

    /// The gearbox.
    ///
    /// # Errors
    /// [`PowertrainError`] if `gearRatio` is invalid (never after [`CarParams::validate`]).
    pub fn gearbox(&self) -> Result<Gearbox<T>, PowertrainError> {
        Gearbox::new(&self.gear_ratios)
    }

    /// The wheel brakes.
    ///
    /// # Errors
    /// [`PowertrainError`] if `brakeCoefficient` is invalid (never after
    /// [`CarParams::validate`]).
    pub fn brake(&self) -> Result<Brake<T>, PowertrainError> {
        Brake::new(self.brake_coefficient)
    }

    /// The speed-mode motor limits of a wheel on the axle of `wheel` (whether driven or not):
    /// acceleration `(1000/36)/time0To100/r` (rad/s²) and velocity limit `maxVelocity/r`
    /// (rad/s), with `r` that axle's tyre radius (Webots: the `Car` PROTO's wheel motors).
    ///
    /// A quotient beyond the float range (e.g. `time0To100 = 1e-38` s in `f32`, which
    /// validation accepts as positive) saturates at `T::MAX` instead of becoming +∞.
    pub fn wheel_motor(&self, wheel: Wheel) -> WheelMotor<T> {
        let r = self.axle_radius(wheel);
        WheelMotor {
            // 100 km/h reached in `time0To100` at constant acceleration (Webots: 1000/36).
            acceleration: (T::from_f64(100.0 / crate::KMH_PER_MS) / self.time_0_to_100 / r)
                .min(T::MAX),
            max_velocity: (self.max_velocity / r).min(T::MAX),
        }
    }

    /// The motor limits of the driven wheels (`None` for a wheel without motor).
    pub fn wheel_motors(&self) -> PerWheel<Option<WheelMotor<T>>> {
        PerWheel::from_fn(|w| self.drive_type.drives(w).then(|| self.wheel_motor(w)))
    }

    /// The car's mass (kg): the body's plus the four wheels' as their `physics` gives them (a
    /// density over the tyre's cylinder; none for `physics NULL`).
    pub fn vehicle_mass(&self) -> T {
        Wheel::ALL
            .into_iter()
            .fold(self.body.mass, |m, w| m + wheel_mass(&self.wheels[w]))
    }

    /// The tyre radius (m) of the driven wheels: the front's (traction), the rear's
    /// (propulsion), or their mean (4x4, whose overall ratio turns both axles).
    pub fn driven_radius(&self) -> T {
        match self.drive_type {
            DriveType::Traction => self.radius_front(),
            DriveType::Propulsion => self.radius_rear(),
            DriveType::FourByFour => T::HALF * (self.radius_front() + self.radius_rear()),
        }
    }

    /// The engine's rotating inertia (kg·m², ≥ 0) by Wong's passenger-car correlation,
    /// `0.0025·m·r²` of [`vehicle_mass`](Self::vehicle_mass) and
    /// [`driven_radius`](Self::driven_radius) ([`Driveline`](crate::Driveline), whose docs give
    /// the source and say where it is an assumption). The [`Driver`](crate::Driver) engages it
    /// through the gear each step ([`Commands::driveline`](crate::Commands::driveline)).
    pub fn engine_inertia(&self) -> T {
        crate::Driveline::engine_inertia_of(self.vehicle_mass(), self.driven_radius())
    }

    /// The body inertia a simulator should use (kg·m², `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` about
    /// the centre of mass): the model's, or the derived box of
    /// [`BodyPhysics::box_inertia`] sized from the wheelbase and the wider track.
    pub fn body_inertia(&self) -> [T; 6] {
        let track = self.track_front.max(self.track_rear);
        self.body.inertia_or_derived(self.wheelbase, track)
    }
}
