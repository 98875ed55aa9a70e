//! The FMU's variables: the driver's commands as inputs, what an ECU sees and a test bench
//! logs as outputs, and the world-file keys a user tunes as parameters. One table drives the
//! model description, `fmi2GetReal`/`fmi2SetReal` and their integer twins, so a variable
//! cannot be described one way and served another.

use sim::world_file::{Setting, WorldDescription};
use sim::{CarTelemetry, TyreChoice};
use vehicle_model::{Direction, TyreField, Wheel};

/// The FMI type of a variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `fmi2Real` (f64).
    Real,
    /// `fmi2Integer` (i32).
    Integer,
}

/// What a variable is to the importing tool.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// The independent variable: simulated time (FMI 3.0 requires one; FMI 2.0 allows it).
    Independent,
    /// Fixed before initialisation ends: a world-file key.
    Parameter,
    /// Set by the tool before each `fmi2DoStep`: a driver command.
    Input,
    /// Read by the tool after each step: a measurement.
    Output,
}

/// One scalar variable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variable {
    /// Its name in `modelDescription.xml` (parameters: the world file's dotted key).
    pub name: &'static str,
    /// Its value reference.
    pub reference: u32,
    /// Its type.
    pub kind: Kind,
    /// Input, output or parameter.
    pub causality: Causality,
    /// Its unit, one of [`UNITS`]; `None` for a dimensionless number or an enumeration.
    pub unit: Option<&'static str>,
    /// What it is, for the tool's user.
    pub description: &'static str,
}

/// A unit of the model description: its name and SI base-unit exponents `[kg, m, s, rad]`,
/// with the factor to SI (`rpm` is rad/s × π/30).
pub const UNITS: [(&str, [i32; 4], f64); 11] = [
    ("kg", [1, 0, 0, 0], 1.0),
    ("s", [0, 0, 1, 0], 1.0),
    ("m", [0, 1, 0, 0], 1.0),
    ("m/s", [0, 1, -1, 0], 1.0),
    ("m/s2", [0, 1, -2, 0], 1.0),
    ("rad", [0, 0, 0, 1], 1.0),
    ("rad/s", [0, 0, -1, 1], 1.0),
    ("rpm", [0, 0, -1, 1], core::f64::consts::PI / 30.0),
    ("N", [1, 1, -2, 0], 1.0),
    ("N.m", [1, 2, -2, 0], 1.0),
    ("W", [1, 2, -3, 0], 1.0),
];

const fn real(
    name: &'static str,
    reference: u32,
    causality: Causality,
    unit: Option<&'static str>,
    description: &'static str,
) -> Variable {
    Variable {
        name,
        reference,
        kind: Kind::Real,
        causality,
        unit,
        description,
    }
}

const fn integer(
    name: &'static str,
    reference: u32,
    causality: Causality,
    description: &'static str,
) -> Variable {
    Variable {
        name,
        reference,
        kind: Kind::Integer,
        causality,
        unit: None,
        description,
    }
}

mod table;

pub use table::VARIABLES;

/// Value reference of the independent variable, time.
pub const TIME: u32 = 99;

/// Value reference of the first input.
pub const STEERING_ANGLE: u32 = 0;
/// Value reference of the throttle input.
pub const THROTTLE: u32 = 1;
/// Value reference of the brake input.
pub const BRAKE_INTENSITY: u32 = 2;
/// Value reference of the cruising-speed input.
pub const CRUISING_SPEED: u32 = 3;
/// Value reference of the control-mode input.
pub const CONTROL_MODE: u32 = 4;
/// Value reference of the gear input.
pub const GEAR: u32 = 5;
/// Value reference of the indicator input.
pub const INDICATOR: u32 = 6;

/// Value reference of the tyre-model parameter.
pub const TYRE_MODEL: u32 = 1006;

/// The world-file value of parameter `reference` set to `value`: the number, or for the tyre
/// model the name its integer stands for.
///
/// # Errors
/// A tyre-model integer that names no model.
pub fn setting(reference: u32, value: f64) -> Result<Setting, String> {
    if reference != TYRE_MODEL {
        return Ok(Setting::Number(value));
    }
    match value {
        0.0 => Ok(Setting::Text("magic-formula".to_string())),
        1.0 => Ok(Setting::Text("webots".to_string())),
        _ => Err(format!(
            "vehicle.tyre.model = {value}: 0 (magic-formula) or 1 (webots)"
        )),
    }
}

/// The tyre coefficient of parameter `reference`, if it is one.
fn tyre_field(reference: u32) -> Option<TyreField> {
    Some(match reference {
        1007 => TyreField::PeakFriction(Direction::Longitudinal),
        1008 => TyreField::PeakFriction(Direction::Lateral),
        1009 => TyreField::Stiffness(Direction::Longitudinal),
        1010 => TyreField::Stiffness(Direction::Lateral),
        1011 => TyreField::RollingResistance,
        _ => return None,
    })
}

/// The variable of value reference `reference` and type `kind`, if there is one.
pub fn find(reference: u32, kind: Kind) -> Option<&'static Variable> {
    VARIABLES
        .iter()
        .find(|v| v.reference == reference && v.kind == kind)
}

/// The start value of every input (the driver at rest in torque control, first gear).
pub fn input_start(reference: u32) -> f64 {
    match reference {
        CONTROL_MODE | GEAR => 1.0,
        _ => 0.0,
    }
}

/// The value of parameter `reference` for car `driven` of the world of `description`, `None`
/// for an unknown reference or car, or a magic-formula coefficient of a car on Webots'
/// contact (the model description then leaves the parameter out).
pub fn parameter_of(description: &WorldDescription, driven: usize, reference: u32) -> Option<f64> {
    let car = description.cars.get(driven)?;
    let p = &car.params;
    if let Some(field) = tyre_field(reference) {
        return match &car.tyre {
            // The coefficients that do not depend on the tyre's radius or load: the class's
            // default unless the world sets them.
            TyreChoice::MagicFormula { class, overrides } => Some(
                overrides
                    .iter()
                    .rev()
                    .find(|(f, _)| *f == field)
                    .map_or_else(|| class.params::<f64>(1.0, 1.0).get(field), |(_, v)| *v),
            ),
            TyreChoice::Webots(_) => None,
        };
    }
    Some(match reference {
        1000 => p.body.mass,
        1001 => p.brake_coefficient,
        1002 => p.engine.max_torque,
        1003 => p.engine.max_power,
        1004 => p.time_0_to_100,
        1005 => description.config.ground_friction,
        TYRE_MODEL => match car.tyre {
            TyreChoice::MagicFormula { .. } => 0.0,
            TyreChoice::Webots(_) => 1.0,
        },
        _ => return None,
    })
}

/// The value of output `reference` in `telemetry`, `None` for an unknown reference.
pub fn output_of(t: &CarTelemetry, reference: u32) -> Option<f64> {
    let s = &t.state;
    Some(match reference {
        100 => s.position.x,
        101 => s.position.y,
        102 => s.position.z,
        103 => s.roll_pitch_yaw.roll,
        104 => s.roll_pitch_yaw.pitch,
        105 => s.roll_pitch_yaw.yaw,
        106 => t.speed,
        107 => s.velocity.x,
        108 => s.velocity.y,
        109 => s.yaw_rate,
        110 => s.longitudinal_acceleration,
        111 => s.lateral_acceleration,
        112 => s.wheel_speeds[Wheel::FrontRight],
        113 => s.wheel_speeds[Wheel::FrontLeft],
        114 => s.wheel_speeds[Wheel::RearRight],
        115 => s.wheel_speeds[Wheel::RearLeft],
        116 => t.rpm.unwrap_or(0.0),
        117 => t.gear.map_or(0.0, |g| f64::from(g.number())),
        118 => s.tyres[Wheel::FrontRight].slip_ratio,
        119 => s.tyres[Wheel::FrontLeft].slip_ratio,
        120 => s.tyres[Wheel::RearRight].slip_ratio,
        121 => s.tyres[Wheel::RearLeft].slip_ratio,
        122 => s.tyres[Wheel::FrontRight].slip_angle,
        123 => s.tyres[Wheel::FrontLeft].slip_angle,
        124 => s.tyres[Wheel::RearRight].slip_angle,
        125 => s.tyres[Wheel::RearLeft].slip_angle,
        126 => s.tyres[Wheel::FrontRight].fz,
        127 => s.tyres[Wheel::FrontLeft].fz,
        128 => s.tyres[Wheel::RearRight].fz,
        129 => s.tyres[Wheel::RearLeft].fz,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::Causality::{Independent, Input, Output, Parameter};
    use super::*;

    #[test]
    fn references_are_unique_and_units_are_defined() {
        for (i, a) in VARIABLES.iter().enumerate() {
            for b in &VARIABLES[i + 1..] {
                assert_ne!(a.reference, b.reference, "{} and {}", a.name, b.name);
                assert_ne!(a.name, b.name);
            }
            if let Some(unit) = a.unit {
                assert!(UNITS.iter().any(|(u, _, _)| *u == unit), "{}", a.name);
            }
            assert_eq!(find(a.reference, a.kind), Some(a));
        }
    }

    #[test]
    fn every_parameter_and_output_is_served() {
        let world = sim::world_file::default_world();
        let (sim, _) = sim::Simulation::from_description(&world).unwrap();
        let id = sim.car_ids().next().unwrap();
        let t = sim.telemetry(id).unwrap();
        for v in &VARIABLES {
            match v.causality {
                Parameter => assert!(parameter_of(&world, 0, v.reference).is_some(), "{}", v.name),
                Output => assert!(output_of(&t, v.reference).is_some(), "{}", v.name),
                Input | Independent => {}
            }
        }
    }
}
