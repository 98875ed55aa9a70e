//! Aerodynamic drag and lift of a car body, in the convention of SAE J1594 (*Vehicle
//! Aerodynamics Terminology*): the drag acts at ground level midway between the axles, and
//! the lift is given as a front and a rear coefficient acting at the two axles, which folds
//! the pitching moment of the drag and of the body into the two lift forces. With that
//! convention a car model needs no centre-of-pressure height, and the axle loads it changes
//! are exactly the published front and rear lift.
//!
//! Forces (N) for a car moving at `v` (m/s) relative to the air, dynamic pressure
//! `q = ½·ρ·|v|²` (Pa):
//! * drag `D = q·Cd·A`, opposite to the air-relative velocity;
//! * lift at the front axle `q·CLf·A` and at the rear axle `q·CLr·A`, along the car's up
//!   axis (positive up: a negative coefficient is downforce).
//!
//! Frame and units: the car's frame (x forward, y left, z up); m, m/s, m², kg/m³, N.

use ackermann::Real;

/// Air density (kg/m³) of the ISA standard atmosphere at sea level, 15 °C: the default.
pub const SEA_LEVEL_AIR_DENSITY: f64 = 1.225;

/// The aerodynamic coefficients of a car body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aero<T> {
    /// Drag coefficient `Cd` (dimensionless, ≥ 0), referred to [`Aero::frontal_area`].
    pub drag_coefficient: T,
    /// Frontal area `A` (m², > 0) the coefficients are referred to.
    pub frontal_area: T,
    /// Front-axle lift coefficient `CLf` (dimensionless; negative for downforce).
    pub lift_coefficient_front: T,
    /// Rear-axle lift coefficient `CLr` (dimensionless; negative for downforce).
    pub lift_coefficient_rear: T,
    /// Air density `ρ` (kg/m³, > 0); [`SEA_LEVEL_AIR_DENSITY`] by default.
    pub air_density: T,
}

/// The aerodynamic forces on a car at one instant (N), in the car's frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AeroForces<T> {
    /// The drag force `[x, y, z]` (N), acting at ground level midway between the axles,
    /// opposite to the car's velocity relative to the air.
    pub drag: [T; 3],
    /// The lift at the front axle (N, along the car's z; negative = downforce).
    pub lift_front: T,
    /// The lift at the rear axle (N, along the car's z; negative = downforce).
    pub lift_rear: T,
}

/// Which coefficient of an [`Aero`] is out of range, and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AeroError {
    /// The field's name as world files spell it, e.g. `"drag_coefficient"`.
    pub field: &'static str,
    /// The rejected value.
    pub value: f64,
    /// What the field must satisfy, completing "must be …".
    pub rule: &'static str,
}

impl core::fmt::Display for AeroError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "invalid {} = {}: must be {}",
            self.field, self.value, self.rule
        )
    }
}

impl core::error::Error for AeroError {}

/// Largest drag coefficient accepted: a square plate across the flow has about 1.2
/// (Hoerner, *Fluid-Dynamic Drag*, 1965, ch. 3); 2 leaves room for odd bodies and refuses typos such as
/// a drag *area* entered as a coefficient.
const MAX_DRAG_COEFFICIENT: f64 = 2.0;
/// Largest magnitude of a lift coefficient accepted: racing cars reach about −3 over their
/// frontal area (Katz, *Race Car Aerodynamics*, 1995); beyond 5 it is a typo.
const MAX_LIFT_COEFFICIENT: f64 = 5.0;
/// Largest frontal area accepted (m²): a 4 m tall, 2.6 m wide lorry has about 10 m²;
/// 20 m² is no road vehicle.
const MAX_FRONTAL_AREA: f64 = 20.0;
/// Densest air accepted (kg/m³): sea-level air at −50 °C is 1.58; 2 refuses water-like
/// values typed in by mistake.
const MAX_AIR_DENSITY: f64 = 2.0;

impl<T: Real> Aero<T> {
    /// Checks every coefficient: `Cd` in [0, 2], `A` in (0, 20] m², lift coefficients in
    /// [−5, 5], `ρ` in (0, 2] kg/m³ (the bounds' reasons are at their constants).
    ///
    /// # Errors
    /// The first [`AeroError`] in field order.
    pub fn validated(self) -> Result<Self, AeroError> {
        let check = |field, value: T, rule, ok: fn(f64) -> bool| {
            let v = value.to_f64();
            if v.is_finite() && ok(v) {
                Ok(())
            } else {
                Err(AeroError {
                    field,
                    value: v,
                    rule,
                })
            }
        };
        check(
            "drag_coefficient",
            self.drag_coefficient,
            "within [0, 2]",
            |v| (0.0..=MAX_DRAG_COEFFICIENT).contains(&v),
        )?;
        check(
            "frontal_area",
            self.frontal_area,
            "within (0, 20] m²",
            |v| v > 0.0 && v <= MAX_FRONTAL_AREA,
        )?;
        let lift = |v: f64| v.abs() <= MAX_LIFT_COEFFICIENT;
        check(
            "lift_coefficient_front",
            self.lift_coefficient_front,
            "within [-5, 5]",
            lift,
        )?;
        check(
            "lift_coefficient_rear",
            self.lift_coefficient_rear,
            "within [-5, 5]",
            lift,
        )?;
        check(
            "air_density",
            self.air_density,
            "within (0, 2] kg/m³",
            |v| v > 0.0 && v <= MAX_AIR_DENSITY,
        )?;
        Ok(self)
    }

    /// The forces on the car moving at `air_velocity` (m/s, the car's velocity minus the
    /// wind's, in the car's frame). Finite for every finite input.
    pub fn forces(&self, air_velocity: [T; 3]) -> AeroForces<T> {
        let [x, y, z] = air_velocity;
        let speed_sq = x * x + y * y + z * z;
        let speed = speed_sq.sqrt();
        // ½·ρ·A: the dynamic pressure per unit speed squared times the reference area.
        let half_rho_a = T::HALF * self.air_density * self.frontal_area;
        // D = ½ρ·Cd·A·|v|², along −v/|v|: each component is −½ρ·Cd·A·|v|·v_i.
        let drag_per_velocity = half_rho_a * self.drag_coefficient * speed;
        let q_a = half_rho_a * speed_sq;
        AeroForces {
            drag: [
                -drag_per_velocity * x,
                -drag_per_velocity * y,
                -drag_per_velocity * z,
            ],
            lift_front: q_a * self.lift_coefficient_front,
            lift_rear: q_a * self.lift_coefficient_rear,
        }
    }

    /// The drag force's magnitude (N) at `speed` (m/s) through still air: `½·ρ·Cd·A·v²`.
    pub fn drag_at(&self, speed: T) -> T {
        T::HALF * self.air_density * self.drag_coefficient * self.frontal_area * speed * speed
    }
}

/// A car body of drag coefficient `cd` over frontal area `area` (m²) without lift, in sea-level
/// air.
fn body<T: Real>(cd: f64, area: f64, lift_front: f64, lift_rear: f64) -> Aero<T> {
    Aero {
        drag_coefficient: T::from_f64(cd),
        frontal_area: T::from_f64(area),
        lift_coefficient_front: T::from_f64(lift_front),
        lift_coefficient_rear: T::from_f64(lift_rear),
        air_density: T::from_f64(SEA_LEVEL_AIR_DENSITY),
    }
}

/// The body of `model`, whose maker publishes no drag coefficient, of frontal area `area`
/// (m²): `Cd` is the EPA's drag area ([`crate::Model::epa_drag_area`]) over `area`.
fn epa_body<T: Real>(model: crate::Model, area: f64) -> Aero<T> {
    // Every model routed here has an EPA test car (`model/epa.rs`).
    let drag_area = model.epa_drag_area().unwrap_or(0.0);
    body(drag_area / area, area, 0.0, 0.0)
}

impl crate::Model {
    /// The model's aerodynamic coefficients. Webots' models have none: these are the real
    /// cars' where the maker published a drag coefficient, else the drag area of the US EPA's
    /// coast-down coefficients ([`crate::Model::epa_drag_area`]) where the EPA tested the car,
    /// else a value typical of the body class, and the table in `vehicle-model/README.md`
    /// says which is which and where each number comes from. The frontal areas are `0.84 × width × height` of the real car (a
    /// passenger car's front fills about 0.8–0.85 of its bounding rectangle; for the vans,
    /// buses and lorries, whose fronts are nearly rectangular, `0.95 × width × height`): an
    /// estimate, since makers rarely publish the area. No shipped model's lift is published: front and rear lift are 0.
    pub fn aero<T: Real>(self) -> Aero<T> {
        use crate::Model as M;
        match self {
            // Tesla's published Cd 0.23 (Model 3 launch, 2017); 1.849 m × 1.443 m.
            M::TeslaModel3 => body(0.23, 2.24, 0.0, 0.0),
            // Toyota's published Cd 0.24 (fourth-generation Prius, 2015); 1.760 m × 1.470 m.
            M::ToyotaPrius => body(0.24, 2.17, 0.0, 0.0),
            // BMW's published Cd 0.33 (X5 G05, 2018); 2.004 m × 1.745 m.
            M::BmwX5 => body(0.33, 2.94, 0.0, 0.0),
            // No published Cd: the EPA's drag area (`Model::epa_drag_area`) over the
            // estimated area; 1.864 m × 1.476 m.
            M::LincolnMKZ => epa_body(M::LincolnMKZ, 2.31),
            // No published Cd: the EPA's drag area; 1.983 m × 1.803 m.
            M::RangeRoverSportSVR => epa_body(M::RangeRoverSportSVR, 3.00),
            // Class-typical city-car Cd; 1.475 m × 1.608 m.
            M::CitroenCZero => body(0.35, 1.99, 0.0, 0.0),
            // Class-typical van Cd; 1.993 m × 2.426 m.
            M::MercedesBenzSprinter => body(0.35, 4.59, 0.0, 0.0),
            // Class-typical minibus Cd; 2.2 m × 2.7 m.
            M::GreenPowerEVStar => body(0.50, 5.64, 0.0, 0.0),
            // Class-typical city-bus Cd; 2.55 m × 3.0 m.
            M::Bus => body(0.65, 7.27, 0.0, 0.0),
            // Class-typical rigid-lorry Cd; 2.5 m × 3.4 m.
            M::Truck => body(0.70, 8.08, 0.0, 0.0),
            // Class-typical open tractor Cd (bluff body with open wheels); 2.0 m × 2.8 m.
            M::Tractor => body(0.90, 5.32, 0.0, 0.0),
            // The plain `Car`: a class-typical saloon, 1.8 m × 1.45 m.
            _ => body(0.30, 2.19, 0.0, 0.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Model;

    #[test]
    fn the_drag_at_100_km_h_is_the_textbook_product() {
        // ½ · 1.225 · 0.23 · 2.24 · (27.7…)² = 243.49 N.
        let aero = Model::TeslaModel3.aero::<f64>();
        let v = 100.0 / 3.6;
        let expected = 0.5 * 1.225 * 0.23 * 2.24 * v * v;
        let f = aero.forces([v, 0.0, 0.0]);
        assert!((f.drag[0] + expected).abs() < 1e-9, "{:?}", f.drag);
        assert_eq!([f.drag[1], f.drag[2]], [0.0, 0.0]);
        assert!((aero.drag_at(v) - expected).abs() < 1e-9);
        assert!((expected - 243.4877).abs() < 1e-4);
    }

    #[test]
    fn drag_opposes_the_air_relative_velocity_and_lift_follows_its_sign() {
        let aero = Aero {
            lift_coefficient_front: -0.1,
            lift_coefficient_rear: 0.2,
            ..Model::BmwX5.aero::<f64>()
        };
        let v = [20.0, -5.0, 1.0];
        let f = aero.forces(v);
        // Anti-parallel: the dot product is −|D|·|v|.
        let speed_sq: f64 = v.iter().map(|x| x * x).sum();
        let dot: f64 = (0..3).map(|i| f.drag[i] * v[i]).sum();
        assert!((dot + aero.drag_at(speed_sq.sqrt()) * speed_sq.sqrt()).abs() < 1e-9);
        let q_a = 0.5 * 1.225 * aero.frontal_area * speed_sq;
        assert!((f.lift_front + 0.1 * q_a).abs() < 1e-9);
        assert!((f.lift_rear - 0.2 * q_a).abs() < 1e-9);
        // Symmetry: the reversed flow gives the reversed drag and the same lift.
        let r = aero.forces([-20.0, 5.0, -1.0]);
        assert_eq!(r.drag, [-f.drag[0], -f.drag[1], -f.drag[2]]);
        assert_eq!([r.lift_front, r.lift_rear], [f.lift_front, f.lift_rear]);
    }

    #[test]
    fn still_air_gives_no_force_and_f32_agrees_with_f64() {
        let a32 = Model::Bus.aero::<f32>();
        let zero = a32.forces([0.0; 3]);
        assert_eq!(zero.drag, [0.0; 3]);
        let f32_drag = a32.forces([30.0, 0.0, 0.0]).drag[0];
        let f64_drag = Model::Bus.aero::<f64>().forces([30.0, 0.0, 0.0]).drag[0];
        // f32 carries 24 bits: a relative error of a few 1e-7.
        assert!(((f64::from(f32_drag) - f64_drag) / f64_drag).abs() < 1e-6);
    }

    #[test]
    fn every_model_is_valid_and_bad_values_are_named() {
        for model in Model::ALL {
            assert!(model.aero::<f64>().validated().is_ok(), "{model:?}");
        }
        let bad = Aero {
            frontal_area: f64::NAN,
            ..Model::Car.aero::<f64>()
        };
        let e = bad.validated().unwrap_err();
        assert_eq!(e.field, "frontal_area");
        assert!(e.value.is_nan());
        let dense = Aero {
            air_density: 1000.0,
            ..Model::Car.aero::<f64>()
        };
        assert_eq!(dense.validated().unwrap_err().field, "air_density");
        let area_as_cd = Aero {
            drag_coefficient: 0.3 * 2.2 * 10.0,
            ..Model::Car.aero::<f64>()
        };
        assert_eq!(
            area_as_cd.validated().unwrap_err().field,
            "drag_coefficient"
        );
    }
}
