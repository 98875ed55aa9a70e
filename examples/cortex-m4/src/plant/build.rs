//! The plant's constants from the car's parameters: the masses and inertias of body and
//! wheels, the static loads and load transfer, and the tyres fitted to them.

use ackermann::{PerWheel, Pose, Wheel, WheelAngles};
use vehicle_model::actuator::{PositionServo, SteeringMotor, WheelSpin};
use vehicle_model::{CarParams, MagicFormula, TransientSlip, TyreClass, TyreError};

use super::Plant;

/// Standard gravity (m/s²), as the sim crate's static loads use.
const GRAVITY: f32 = 9.81;
/// Webots' `Physics {}` density for a wheel whose model gives no mass (kg/m³), as the sim crate
/// gives such a wheel.
const DEFAULT_WHEEL_DENSITY: f32 = vehicle_model::DEFAULT_WHEEL_DENSITY as f32;

/// The physical constants of the plant that the car's parameters do not give.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Environment {
    /// Drag coefficient × frontal area (m²).
    pub drag_area: f32,
    /// Friction of the road (dimensionless): the ground's `friction` (Webots'
    /// `coulombFriction`), multiplying the tyres' peak friction.
    pub road_friction: f32,
    /// The kind of tyre the car rolls on, with its default coefficients.
    pub tyres: TyreClass,
}

impl Environment {
    /// A large SUV on passenger-car tyres on dry asphalt: CdA 0.95 m² (Cd 0.33 × 2.9 m²),
    /// road friction 1.
    pub const SUV_ON_ASPHALT: Environment = Environment {
        drag_area: 0.95,
        road_friction: 1.0,
        tyres: TyreClass::PassengerCar,
    };
}

/// A wheel's mass and moments of inertia: a uniform cylinder, as Webots computes them.
#[derive(Debug, Clone, Copy)]
struct WheelMass {
    /// Mass (kg).
    mass: f32,
    /// Moment of inertia about the axle (kg·m²).
    axial: f32,
    /// Moment of inertia about a diameter (kg·m²): about the steering axis, and about the
    /// vertical for the car's yaw.
    transverse: f32,
}

/// The constants of one wheel.
#[derive(Debug, Clone, Copy)]
pub(super) struct Corner {
    /// Contact point − centre of mass, in body axes (m).
    pub(super) arm: [f32; 2],
    /// Tyre radius (m).
    pub(super) radius: f32,
    /// Spin inertia (kg·m²) and `wheelsDampingConstant` (N·m·s/rad).
    pub(super) spin: WheelSpin<f32>,
    /// Load on the wheel at rest (N).
    pub(super) static_load: f32,
    /// Change of load per m/s² of forward and of leftward acceleration (kg).
    pub(super) transfer: [f32; 2],
    /// The tyre, fitted to the wheel's radius and static load.
    pub(super) tyre: MagicFormula<f32>,
}

impl Plant {
    /// A car at rest at the origin, heading along +x, with straight wheels, built from the
    /// driver's validated parameters (pass `driver.params()`).
    ///
    /// Wheel masses and inertias come from the wheels' `Physics` (a uniform cylinder, as
    /// Webots computes it); a wheel without mass gets Webots' `Physics {}` (1000 kg/m³ over
    /// its cylinder), as in the sim crate. The tyres are `environment.tyres` fitted to each
    /// axle's radius and static wheel load.
    ///
    /// # Errors
    /// The tyre coefficient that the fitted tyre refuses (not for a validated car).
    // Called once: out of line, its temporaries (four validated wheels, two tyre fits) do not
    // stay in the caller's stack frame for the whole run (1.3 KiB of the firmware's stack).
    #[inline(never)]
    pub fn new(params: &CarParams<f32>, environment: Environment) -> Result<Self, TyreError> {
        let wheelbase = params.wheelbase;
        let half_track = |w: Wheel| {
            let track = if w.is_front() {
                params.track_front
            } else {
                params.track_rear
            };
            if w.is_right() {
                -0.5 * track
            } else {
                0.5 * track
            }
        };
        let centre = |w: Wheel| [if w.is_front() { wheelbase } else { 0.0 }, half_track(w)];
        let wheel_mass = PerWheel::from_fn(|w| {
            let (valid, _) = params.wheels[w].validate();
            match valid.mass_properties().filter(|m| m.axial > 0.0) {
                Some(m) => WheelMass {
                    mass: m.mass,
                    axial: m.axial,
                    transverse: m.transverse,
                },
                None => {
                    let p = valid.params();
                    let r2 = p.tire_radius * p.tire_radius;
                    let mass = DEFAULT_WHEEL_DENSITY * core::f32::consts::PI * r2 * p.thickness;
                    WheelMass {
                        mass,
                        axial: 0.5 * mass * r2,
                        transverse: mass * (3.0 * r2 + p.thickness * p.thickness) / 12.0,
                    }
                }
            }
        });
        let body = &params.body;
        let [body_x, body_y, body_z] = body.center_of_mass;
        let mass = body.mass + wheel_mass.iter().map(|m| m.mass).sum::<f32>();
        let [com_x, com_y] = Wheel::ALL
            .iter()
            .fold([body.mass * body_x, body.mass * body_y], |[mx, my], &w| {
                let [x, y] = centre(w);
                [mx + wheel_mass[w].mass * x, my + wheel_mass[w].mass * y]
            })
            .map(|moment| moment / mass);
        let squared_distance = |[x, y]: [f32; 2]| {
            let [dx, dy] = [x - com_x, y - com_y];
            dx * dx + dy * dy
        };
        // The body's own inertia and the wheels' (each spinning about a diameter to turn),
        // moved to the common centre of mass.
        let yaw_inertia = params.body_inertia()[2]
            + body.mass * squared_distance([body_x, body_y])
            + Wheel::ALL
                .iter()
                .map(|&w| {
                    let m = wheel_mass[w];
                    m.transverse + m.mass * squared_distance(centre(w))
                })
                .sum::<f32>();

        // The sim crate's static loads, so that the tyres are fitted to the same loads.
        let front_share = (body_x / wheelbase).clamp(0.0, 1.0);
        let static_load = |w: Wheel| {
            let share = if w.is_front() {
                front_share
            } else {
                1.0 - front_share
            };
            GRAVITY * (0.5 * share * body.mass + wheel_mass[w].mass)
        };
        let fit = |w: Wheel| {
            let load = static_load(w).max(1.0);
            environment
                .tyres
                .params(params.axle_radius(w), load)
                .validate()
        };
        let (front_tyre, rear_tyre) = (fit(Wheel::FrontRight)?, fit(Wheel::RearRight)?);
        // Centre of mass over the road, which is one rear tyre radius below the car frame (the
        // wheel centres are at the frame's height: only the body lifts the centre of mass).
        let height = body.mass * body_z / mass + params.radius_rear();
        let roll_stiffness = [
            params.suspension_front_spring_constant * params.track_front * params.track_front,
            params.suspension_rear_spring_constant * params.track_rear * params.track_rear,
        ];
        let corners = PerWheel::from_fn(|w| {
            let (axle_roll, track) = if w.is_front() {
                (roll_stiffness[0], params.track_front)
            } else {
                (roll_stiffness[1], params.track_rear)
            };
            let pitch = 0.5 * mass * height / wheelbase;
            let roll = axle_roll / (roll_stiffness[0] + roll_stiffness[1]) * mass * height / track;
            let [x, y] = centre(w);
            Corner {
                arm: [x - com_x, y - com_y],
                radius: params.axle_radius(w),
                spin: WheelSpin {
                    inertia: wheel_mass[w].axial,
                    damping: params.wheels_damping_constant,
                },
                static_load: static_load(w),
                transfer: [
                    if w.is_front() { -pitch } else { pitch },
                    if w.is_right() { roll } else { -roll },
                ],
                tyre: if w.is_front() { front_tyre } else { rear_tyre },
            }
        });

        let steering_motor = |w: Wheel| SteeringMotor {
            servo: PositionServo::steering(params.min_steering_angle, params.max_steering_angle),
            max_torque: params.max_steering_torque,
            inertia: wheel_mass[w].transverse,
        };
        Ok(Plant {
            steering_motors: [
                steering_motor(Wheel::FrontRight),
                steering_motor(Wheel::FrontLeft),
            ],
            corners,
            mass,
            yaw_inertia,
            centre_of_mass: [com_x, com_y],
            environment,
            time_ms: 0,
            velocity: [0.0; 3],
            acceleration: [0.0; 2],
            wheel_speed: PerWheel::splat(0.0),
            wheel_angle: PerWheel::splat(0.0),
            steering: WheelAngles::STRAIGHT,
            steering_rate: WheelAngles::new(0.0, 0.0),
            wheel_motors: PerWheel::splat(None),
            slips: PerWheel::splat(TransientSlip::default()),
            spin_steps: PerWheel::splat(None),
            forces: PerWheel::splat([0.0; 2]),
            pose: Pose::ORIGIN,
            distance: 0.0,
            faults: 0,
        })
    }
}
