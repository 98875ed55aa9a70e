//! The physical description of a car as the simulator builds it: resolved masses, positions and
//! joint constants in f64 SI units.

use ackermann::{PerWheel, Wheel};
use proto_geom::nalgebra::{Point3, Vector3};
use proto_geom::plausible;
use proto_geom::{VehicleDimensions, VehicleLayout};
use vehicle_model::{Aero, CarParams, RoadLoad, TyreClass, TyreField, TyreModel, WebotsContact};

use crate::error::{ParamError, Rule};

/// Mass properties and collision box of the car body (without wheels), in the car frame
/// (x forward, y left, z up, origin at the rear-axle centre at wheel-centre height).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChassisSpec {
    /// Body mass (kg, > 0). Webots: `Physics.mass` of the Car.
    pub mass: f64,
    /// Centre of mass (m). Webots: `Physics.centerOfMass`.
    pub center_of_mass: Point3<f64>,
    /// Inertia about the centre of mass, `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` (kg·m²), the entries
    /// of the symmetric tensor. Webots: `Physics.inertiaMatrix`.
    pub inertia: [f64; 6],
    /// Centre of the chassis collision box (m).
    pub box_center: Point3<f64>,
    /// Half lengths of the chassis collision box along the car's x, y, z (m, > 0).
    pub box_half_extents: Vector3<f64>,
}

/// One wheel: where its centre is and what it is made of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelSpec {
    /// Wheel centre in the car frame at rest with unloaded springs (m): `(L, ∓Tf/2, 0)` for
    /// the front wheels, `(0, ∓Tr/2, 0)` for the rear ones.
    pub position: Point3<f64>,
    /// Tyre radius (m, > 0). Webots: `VehicleWheel.tireRadius`.
    pub radius: f64,
    /// Tyre width (m, > 0): the cylinder's length along the spin axis. Webots:
    /// `VehicleWheel.thickness`.
    pub width: f64,
    /// Wheel mass (kg, > 0); its spin inertia is that of a solid cylinder, `m·r²/2`.
    pub mass: f64,
}

impl WheelSpec {
    /// Inertia about the spin axis (kg·m²): a solid cylinder, `m·r²/2`.
    pub fn spin_inertia(&self) -> f64 {
        0.5 * self.mass * self.radius * self.radius
    }

    /// Inertia about a diameter through the centre (kg·m²): a solid cylinder,
    /// `m·(3·r² + w²)/12`. The steering motor turns the wheel about this axis.
    pub fn transverse_inertia(&self) -> f64 {
        self.mass * (3.0 * self.radius * self.radius + self.width * self.width) / 12.0
    }
}

/// A linear spring-damper (Webots suspension of an `AckermannVehicle` axle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringDamper {
    /// Spring constant (N/m, > 0). Webots: `suspension…SpringConstant`.
    pub stiffness: f64,
    /// Damping constant (N·s/m, ≥ 0). Webots: `suspension…DampingConstant`.
    pub damping: f64,
}

/// The front steering motors (Webots `right_steer`, `left_steer`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteeringSpec {
    /// Lowest steering angle (rad, ≤ 0 normally; negative = left). Webots: `minSteeringAngle`.
    pub min_angle: f64,
    /// Highest steering angle (rad; positive = right). Webots: `maxSteeringAngle`.
    pub max_angle: f64,
    /// Torque of each steering motor (N·m, ≥ 0). Webots: `maxSteeringTorque`.
    pub max_torque: f64,
}

/// Why a joints wheel's `tireRadius` must be at least half its `thickness`
/// ([`VehicleSpec::check_mounting`]), completing "must be at least <bound> …".
const JOINTS_TREAD: &str = "m, half the wheel's thickness: the joints mounting rounds the \
     tread across the whole width (use mounting = \"cast\" for a wheel wider than its diameter)";

/// How a car's wheels hang on its chassis in rapier (`[vehicle] mounting` in a world file).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mounting {
    /// One rigid chassis on four shape-cast wheels (`mounting = "cast"`, the default): the
    /// suspension, tyres, brakes and spins are solved by this crate; the wheels stand on static
    /// geometry only.
    #[default]
    Cast,
    /// Wheels as rapier bodies on suspension, steering and spin joints (`mounting = "joints"`),
    /// the tyre forces from the same solve: the wheels meet every body of the world.
    Joints,
}

/// Which tyre a car rolls on, before it is fitted to the car ([`VehicleSpec::from_car_with`]).
#[derive(Debug, Clone, PartialEq)]
pub enum TyreChoice {
    /// The slip-based tyre (`tyre = "magic-formula"`, the default): the default set of `class`
    /// for each axle's tyre radius and static load, then `overrides` (`[vehicle.tyre]`).
    MagicFormula {
        /// The default set the coefficients start from.
        class: TyreClass,
        /// Coefficients set explicitly, applied to both axles.
        overrides: Vec<(TyreField, f64)>,
    },
    /// Webots' ODE contact (`tyre = "webots"`): friction pyramid with the ground's friction and
    /// force-dependent slip.
    Webots(WebotsContact<f64>),
}

impl TyreChoice {
    /// The tyre a car of `model` rolls on when nothing else is said (in a world file or the C
    /// API): the slip-based tyre of the model's class, without overrides.
    pub fn of_model(model: vehicle_model::Model) -> Self {
        TyreChoice::MagicFormula {
            class: model.tyre_class(),
            overrides: Vec::new(),
        }
    }
}

impl Default for TyreChoice {
    /// The passenger-car slip-based tyre.
    fn default() -> Self {
        TyreChoice::MagicFormula {
            class: TyreClass::PassengerCar,
            overrides: Vec::new(),
        }
    }
}

/// The tyres of a car, one model per axle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TyreSpec {
    /// The front tyres.
    pub front: TyreModel<f64>,
    /// The rear tyres.
    pub rear: TyreModel<f64>,
}

impl TyreSpec {
    /// The tyre model of wheel `w`.
    pub fn of(&self, w: Wheel) -> &TyreModel<f64> {
        if w.is_front() {
            &self.front
        } else {
            &self.rear
        }
    }
}

/// Webots' density of a `Physics {}` node without a mass (kg/m³): a wheel whose model gives no
/// mass weighs its bounding cylinder of water.
const DEFAULT_DENSITY: f64 = 1000.0;

/// Height of the chassis collision box over the wider track (dimensionless): the proportions
/// `vehicle-model` gives a body without inertia data.
const BODY_HEIGHT_PER_TRACK: f64 = 0.75;

/// Standard gravity (m/s²), for the static wheel loads the tyres are scaled to.
const STANDARD_GRAVITY: f64 = 9.81;

/// Everything the simulator needs to build one car.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleSpec {
    /// The body.
    pub chassis: ChassisSpec,
    /// The four wheels, in Webots order FR, FL, RR, RL.
    pub wheels: PerWheel<WheelSpec>,
    /// Front suspension (both front wheels).
    pub front_suspension: SpringDamper,
    /// Rear suspension (both rear wheels).
    pub rear_suspension: SpringDamper,
    /// Steering motors.
    pub steering: SteeringSpec,
    /// Viscous damping of each wheel's spin joint (N·m·s/rad, ≥ 0). Webots:
    /// `wheelsDampingConstant`.
    pub wheels_damping: f64,
    /// Range of the kinematic wiper joint `[parked, fully swept]` (rad); `None` = no wipers.
    pub wiper_range: Option<[f64; 2]>,
    /// The tyres.
    pub tyres: TyreSpec,
    /// How the wheels hang on the chassis.
    pub mounting: Mounting,
    /// The body's aerodynamic drag and lift ([`Aero`], SAE J1594's convention: drag at ground
    /// level midway between the axles, lift at the axles), relative to the world's wind;
    /// `None` (the default, as in Webots): no air.
    pub aero: Option<Aero<f64>>,
    /// The wheels' driveline losses ([`RoadLoad`]: a constant and a viscous drag), which then
    /// replace [`VehicleSpec::wheels_damping`]; `None` (the default, as in Webots): the
    /// viscous `wheelsDampingConstant` alone.
    pub road_load: Option<RoadLoad<f64>>,
}

/// The tyre model of `choice` for a wheel of `radius` (m) carrying `load` (N) at rest.
fn fit_tyre(choice: &TyreChoice, radius: f64, load: f64) -> Result<TyreModel<f64>, ParamError> {
    match choice {
        TyreChoice::Webots(contact) => {
            contact
                .validate()
                .map(TyreModel::Webots)
                .map_err(|value| ParamError {
                    field: "forceDependentSlip",
                    value,
                    rule: Rule::Text("finite and in [0, 1] m/s per N"),
                })
        }
        TyreChoice::MagicFormula { class, overrides } => {
            let mut p = class.params(radius, load.max(1.0));
            for &(field, value) in overrides {
                p.set(field, value);
            }
            p.validate()
                .map(TyreModel::MagicFormula)
                .map_err(|e| ParamError {
                    field: e.field.path(),
                    value: e.value,
                    // `ParamError` says "must be" itself.
                    rule: Rule::Text(e.field.rule().trim_start_matches("must be ")),
                })
        }
    }
}

impl VehicleSpec {
    /// The car's mass as the road sees it when it speeds up or slows down (kg): the chassis
    /// and the wheels, plus each wheel's spin inertia over its radius squared (its own only:
    /// the engine's, engaged through a gear, is `Commands::driveline`'s).
    pub fn effective_mass(&self) -> f64 {
        self.chassis.mass
            + self
                .wheels
                .iter()
                .map(|w| w.mass + w.spin_inertia() / (w.radius * w.radius))
                .sum::<f64>()
    }

    /// The load on each wheel of the car at rest on level ground (N): the body's weight shared
    /// between the axles by its centre of mass, plus the wheel's own weight.
    pub fn static_wheel_loads(&self) -> PerWheel<f64> {
        let front_x = self.wheels[Wheel::FrontRight].position.x;
        let rear_x = self.wheels[Wheel::RearRight].position.x;
        let wheelbase = front_x - rear_x;
        let front_share = if wheelbase > 0.0 {
            ((self.chassis.center_of_mass.x - rear_x) / wheelbase).clamp(0.0, 1.0)
        } else {
            0.5
        };
        PerWheel::from_fn(|w| {
            let share = if w.is_front() {
                front_share
            } else {
                1.0 - front_share
            };
            STANDARD_GRAVITY * (0.5 * share * self.chassis.mass + self.wheels[w].mass)
        })
    }

    /// Checks that the wheels can hang on the car's [`Mounting`]: on `joints`, each wheel's
    /// `tireRadius` must be at least half its `thickness` (m). The joints wheel's collider is a
    /// cylinder whose tread is rounded across its whole width (`vehicle/joints.rs`, `Tread`):
    /// a round cylinder of border radius `thickness/2` around a core of radius
    /// `tireRadius − thickness/2`, which cannot be negative (rapier's shape asserts it). A
    /// wheel wider than its diameter has no such shape; the `cast` mounting's swept cylinder
    /// needs none and takes any plausible tyre. The error names the first wheel at fault
    /// (in wheel order).
    ///
    /// # Errors
    /// The wheel and a [`ParamError`] naming `tireRadius`, its value and the bound.
    pub fn check_mounting(&self) -> Result<(), (Wheel, ParamError)> {
        if self.mounting == Mounting::Cast {
            return Ok(());
        }
        for w in Wheel::ALL {
            let s = &self.wheels[w];
            ParamError::at_least("tireRadius", s.radius, 0.5 * s.width, JOINTS_TREAD)
                .map_err(|e| (w, e))?;
        }
        Ok(())
    }

    /// Checks every field: positive masses, lengths and spring constants, a physical inertia
    /// tensor, finite positions, `min_angle ≤ max_angle`, and wheels that the mounting can
    /// build ([`VehicleSpec::check_mounting`]).
    pub fn validate(&self) -> Result<(), ParamError> {
        let c = &self.chassis;
        ParamError::within("physics.mass", c.mass, plausible::MASS)?;
        for &v in c.center_of_mass.iter() {
            ParamError::within("physics.centerOfMass", v, plausible::OFFSET)?;
        }
        for &v in c.box_center.iter() {
            ParamError::within("chassis.box_center", v, plausible::OFFSET)?;
        }
        for &v in c.box_half_extents.iter() {
            ParamError::within("chassis.box_half_extents", v, plausible::LENGTH)?;
        }
        for v in c.inertia {
            ParamError::within("physics.inertiaMatrix", v, plausible::INERTIA)?;
        }
        let [xx, yy, zz, xy, xz, yz] = c.inertia;
        let det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
        ParamError::check(
            "physics.inertiaMatrix",
            det,
            "a finite positive-definite tensor (determinant shown)",
            |d| {
                c.inertia.iter().all(|v| v.is_finite())
                    && xx > 0.0
                    && xx * yy - xy * xy > 0.0
                    && d > 0.0
            },
        )?;
        for w in Wheel::ALL {
            let s = &self.wheels[w];
            for &v in s.position.iter() {
                ParamError::within("wheel.position", v, plausible::OFFSET)?;
            }
            ParamError::within("tireRadius", s.radius, plausible::LENGTH)?;
            ParamError::within("thickness", s.width, plausible::LENGTH)?;
            ParamError::within("wheel.mass", s.mass, plausible::MASS)?;
        }
        self.check_mounting().map_err(|(_, e)| e)?;
        if let Some(aero) = self.aero {
            aero.validated().map_err(|e| ParamError {
                field: e.field,
                value: e.value,
                rule: Rule::Text(e.rule),
            })?;
        }
        if let Some(losses) = self.road_load {
            losses.validated().map_err(|e| ParamError {
                field: e.field,
                value: e.value,
                rule: Rule::Text(e.rule),
            })?;
        }
        for (k, c) in [
            (
                "suspensionFrontSpringConstant",
                self.front_suspension.stiffness,
            ),
            (
                "suspensionRearSpringConstant",
                self.rear_suspension.stiffness,
            ),
        ] {
            ParamError::positive(k, c)?;
            ParamError::within(k, c, plausible::SPRING)?;
        }
        ParamError::within(
            "suspensionFrontDampingConstant",
            self.front_suspension.damping,
            plausible::DAMPER,
        )?;
        ParamError::within(
            "suspensionRearDampingConstant",
            self.rear_suspension.damping,
            plausible::DAMPER,
        )?;
        ParamError::within(
            "minSteeringAngle",
            self.steering.min_angle,
            plausible::STEERING_ANGLE,
        )?;
        ParamError::check(
            "maxSteeringAngle",
            self.steering.max_angle,
            "finite and >= minSteeringAngle",
            |v| plausible::STEERING_ANGLE.contains(v) && v >= self.steering.min_angle,
        )?;
        ParamError::within(
            "maxSteeringTorque",
            self.steering.max_torque,
            plausible::TORQUE,
        )?;
        ParamError::within(
            "wheelsDampingConstant",
            self.wheels_damping,
            plausible::ROTATIONAL_DAMPING,
        )?;
        if let Some([lo, hi]) = self.wiper_range {
            ParamError::finite("wiper.min", lo)?;
            ParamError::check("wiper.max", hi, "finite and > wiper.min", |v| {
                v.is_finite() && v > lo
            })?;
        }
        Ok(())
    }
}

impl VehicleSpec {
    /// The physical description of a car from its (validated) parameters: the proto-geom
    /// wheel layout, the tyre radius, width and mass of each `VehicleWheel` (a wheel without
    /// mass of its own gets the Webots default `Physics {}`: 1000 kg/m³ over its bounding
    /// cylinder), the body's mass properties, the suspension, steering and damping fields and
    /// the wipers.
    ///
    /// The chassis collision box spans the wheelbase plus one tyre radius at each end, the
    /// wider track, and from wheel-centre height up to `0.75·track` (the proportions
    /// `vehicle-model` uses for a body without inertia data). The tyres are the default
    /// passenger-car slip-based tyres ([`TyreChoice::default`]).
    pub fn from_car(params: &CarParams<f64>) -> Result<VehicleSpec, ParamError> {
        Self::from_car_with(params, &TyreChoice::default())
    }

    /// As [`VehicleSpec::from_car`], on the tyres of `tyre`. A slip-based tyre's nominal load
    /// is the car's mean static wheel load (its weight under 9.81 m/s² over four) and its
    /// relaxation lengths scale with its radius.
    ///
    /// # Errors
    /// A [`ParamError`] naming the first invalid field, tyre coefficients included
    /// (`tyre.lateral.shape`, `forceDependentSlip`, …).
    pub fn from_car_with(
        params: &CarParams<f64>,
        tyre: &TyreChoice,
    ) -> Result<VehicleSpec, ParamError> {
        let dims = VehicleDimensions {
            wheelbase: params.wheelbase,
            track_front: params.track_front,
            track_rear: params.track_rear,
        };
        let (layout, _) = VehicleLayout::new(dims, params.wheels);
        let wheels = PerWheel::from_fn(|w| {
            let valid = layout.wheel(w);
            let p = valid.params();
            let c = layout.frame(w).centre();
            let mass = valid.mass().unwrap_or(
                DEFAULT_DENSITY
                    * core::f64::consts::PI
                    * p.tire_radius
                    * p.tire_radius
                    * p.thickness,
            );
            WheelSpec {
                position: c,
                radius: p.tire_radius,
                width: p.thickness,
                mass,
            }
        });
        let (rf, rr) = (
            wheels[Wheel::FrontRight].radius,
            wheels[Wheel::RearRight].radius,
        );
        let l = params.wheelbase;
        let track = params.track_front.max(params.track_rear);
        let height = BODY_HEIGHT_PER_TRACK * track;
        let mut spec = VehicleSpec {
            chassis: ChassisSpec {
                mass: params.body.mass,
                center_of_mass: Point3::from(params.body.center_of_mass),
                inertia: params.body_inertia(),
                box_center: Point3::new((l + rf - rr) / 2.0, 0.0, height / 2.0),
                box_half_extents: Vector3::new((l + rf + rr) / 2.0, track / 2.0, height / 2.0),
            },
            wheels,
            front_suspension: SpringDamper {
                stiffness: params.suspension_front_spring_constant,
                damping: params.suspension_front_damping_constant,
            },
            rear_suspension: SpringDamper {
                stiffness: params.suspension_rear_spring_constant,
                damping: params.suspension_rear_damping_constant,
            },
            steering: SteeringSpec {
                min_angle: params.min_steering_angle,
                max_angle: params.max_steering_angle,
                max_torque: params.max_steering_torque,
            },
            wheels_damping: params.wheels_damping_constant,
            wiper_range: params.wipers.map(|r| [r.min, r.max]),
            // Replaced below, once the static loads are known.
            tyres: TyreSpec {
                front: TyreModel::Webots(WebotsContact::default()),
                rear: TyreModel::Webots(WebotsContact::default()),
            },
            mounting: Mounting::Cast,
            aero: None,
            road_load: None,
        };
        spec.validate()?;
        // One nominal load for all four tyres, the car's mean static wheel load: the tyre's
        // stiffness and friction per unit load then differ between a heavier and a lighter
        // axle as a real tyre's do, which makes a front-heavy car understeer.
        let nominal = spec.static_wheel_loads().iter().sum::<f64>() / 4.0;
        let fit = |w: Wheel| fit_tyre(tyre, spec.wheels[w].radius, nominal);
        spec.tyres = TyreSpec {
            front: fit(Wheel::FrontRight)?,
            rear: fit(Wheel::RearRight)?,
        };
        Ok(spec)
    }
}
