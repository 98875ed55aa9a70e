//! The US EPA's coast-down coefficients of the real cars behind the shipped models, and the
//! road-load set ([`RoadLoad`]) each model derives from them ([`Model::road_load`]).
//!
//! The EPA publishes, for every car tested for fuel economy, the road-load curve the
//! dynamometer is set to: `F(v) = A + B·v + C·v²` ("Target Coef A (lbf)", "Target Coef B
//! (lbf/mph)", "Target Coef C (lbf/mph**2)"), fitted by the maker to coast-downs of the real
//! car at its test weight ("Equivalent Test Weight (lbs.)"), in the yearly files *Data on Cars
//! Used for Testing Fuel Economy* (epa.gov/compliance-and-fuel-economy-data/
//! data-cars-used-testing-fuel-economy). The rows below are copied from those files; each
//! was read in two copies where one could be found (`vehicle-model/README.md` names them).
//!
//! The model's losses are physical terms, not a polynomial (crate::road_load): a car rolling
//! at `v` is slowed by `c_rr·m·g + Σ_w (T₀ + b·v/r_w)/r_w + ½·ρ·Cd·A·v²`. The set is derived
//! term by term:
//! * `T₀` keeps the estimate of [`RoadLoad::default`] (1 N·m per wheel): a coast-down cannot
//!   tell a constant drag torque from rolling resistance, both are in `A`;
//! * `c_rr = (A − Σ_w T₀/r_w) / (m_test·g)`: the rest of `A` is the tyres' rolling resistance
//!   at the EPA test mass (`g` = 9.81 m/s², the simulation's);
//! * `b = max(B, 0) / Σ_w (1/r_w²)`: `B` is the viscous drag seen at the road; a negative
//!   `B` (the fit's artefact, some cars have one) is no loss a wheel can have, so `b = 0`;
//! * `C` is the air, `½·ρ·Cd·A`: the model's [`Model::aero`] keeps the maker's published `Cd`
//!   where there is one, and takes `Cd·A = 2·C/ρ` from the EPA where there is none
//!   ([`Model::epa_drag_area`]).

use ackermann::Real;

use super::Model;
use crate::RoadLoad;

/// N per lbf (exact: 0.453 592 37 kg × 9.806 65 m/s²).
const N_PER_LBF: f64 = 4.448_221_615_260_5;
/// m/s per mph (exact).
const MS_PER_MPH: f64 = 0.447_04;
/// kg per lb (exact).
const KG_PER_LB: f64 = 0.453_592_37;
/// The gravity the rolling resistance is referred to (m/s²): the simulation's static loads'.
const GRAVITY: f64 = 9.81;

/// One test car's row of the EPA's *Data on Cars Used for Testing Fuel Economy*, in the
/// file's units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpaTestCar {
    /// The file's "Model Year".
    pub model_year: u16,
    /// "Represented Test Veh Make" and "Represented Test Veh Model".
    pub name: &'static str,
    /// "Test Vehicle ID".
    pub test_vehicle_id: &'static str,
    /// The EPA file the row is read from.
    pub file: &'static str,
    /// "Target Coef A (lbf)".
    pub a_lbf: f64,
    /// "Target Coef B (lbf/mph)".
    pub b_lbf_per_mph: f64,
    /// "Target Coef C (lbf/mph**2)".
    pub c_lbf_per_mph2: f64,
    /// "Equivalent Test Weight (lbs.)".
    pub test_weight_lb: f64,
}

impl EpaTestCar {
    /// `A` (N).
    pub fn a(&self) -> f64 {
        self.a_lbf * N_PER_LBF
    }

    /// `B` (N·s/m).
    pub fn b(&self) -> f64 {
        self.b_lbf_per_mph * N_PER_LBF / MS_PER_MPH
    }

    /// `C` (N·s²/m²).
    pub fn c(&self) -> f64 {
        self.c_lbf_per_mph2 * N_PER_LBF / (MS_PER_MPH * MS_PER_MPH)
    }

    /// The test mass (kg).
    pub fn test_mass(&self) -> f64 {
        self.test_weight_lb * KG_PER_LB
    }

    /// The road load `A + B·v + C·v²` at `speed` (m/s), in N.
    pub fn force(&self, speed: f64) -> f64 {
        self.a() + (self.b() + self.c() * speed) * speed
    }
}

/// MY2022 Tesla Model 3 RWD: the rear-drive single-motor car, as the shipped model (Webots'
/// R2021c, rear drive, 147 kW).
const TESLA_MODEL_3: EpaTestCar = EpaTestCar {
    model_year: 2022,
    name: "Tesla Model 3 RWD",
    test_vehicle_id: "3R022-043763",
    file: "22-tstcar-2022-04-15.csv",
    a_lbf: 37.17,
    b_lbf_per_mph: 0.047,
    c_lbf_per_mph2: 0.0144,
    test_weight_lb: 4250.0,
};

/// MY2022 Toyota Prius (fourth generation, the shipped model's), configuration 2.
const TOYOTA_PRIUS: EpaTestCar = EpaTestCar {
    model_year: 2022,
    name: "TOYOTA PRIUS",
    test_vehicle_id: "16-ZV1H",
    file: "22-tstcar-2022-04-15.csv",
    a_lbf: 18.272,
    b_lbf_per_mph: 0.29545,
    c_lbf_per_mph2: 0.013793,
    test_weight_lb: 3375.0,
};

/// MY2022 BMW X5 xDrive40i (G05, the body of the shipped model's Cd), configuration 1.
const BMW_X5: EpaTestCar = EpaTestCar {
    model_year: 2022,
    name: "BMW X5 xDrive40i",
    test_vehicle_id: "LL66867",
    file: "22-tstcar-2022-04-15.csv",
    a_lbf: 65.2,
    b_lbf_per_mph: -0.383,
    c_lbf_per_mph2: 0.03345,
    test_weight_lb: 5250.0,
};

/// MY2019 Lincoln MKZ 3.0 V6 (393 hp, the shipped model's 298 kW), listed as "Ford MKZ";
/// the first of its two test vehicles (the second, HR600088, is 11 % above it at 80 km/h:
/// the spread between two cars of one configuration).
const LINCOLN_MKZ: EpaTestCar = EpaTestCar {
    model_year: 2019,
    name: "Ford MKZ",
    test_vehicle_id: "HR600087",
    file: "19tstcar-2020-10-02.xlsx",
    a_lbf: 30.74,
    b_lbf_per_mph: 0.6011,
    c_lbf_per_mph2: 0.01427,
    test_weight_lb: 4500.0,
};

/// MY2022 Land Rover Range Rover Sport SVR (5.0 V8, 575 hp).
const RANGE_ROVER_SPORT_SVR: EpaTestCar = EpaTestCar {
    model_year: 2022,
    name: "Land Rover Range Rover Sport SVR",
    test_vehicle_id: "JA164790",
    file: "22-tstcar-2022-04-15.csv",
    a_lbf: 56.65,
    b_lbf_per_mph: 0.1154,
    c_lbf_per_mph2: 0.03412,
    test_weight_lb: 5500.0,
};

impl Model {
    /// The EPA test car the model's road-load set is derived from, `None` for a model the EPA
    /// has not tested: the CitroenCZero (not sold in the US), the vans, buses, lorries and
    /// the tractor (not light-duty passenger cars) and the plain `Car` (no real car).
    pub const fn epa_test_car(self) -> Option<EpaTestCar> {
        match self {
            Model::TeslaModel3 => Some(TESLA_MODEL_3),
            Model::ToyotaPrius => Some(TOYOTA_PRIUS),
            Model::BmwX5 => Some(BMW_X5),
            Model::LincolnMKZ => Some(LINCOLN_MKZ),
            Model::RangeRoverSportSVR => Some(RANGE_ROVER_SPORT_SVR),
            _ => None,
        }
    }

    /// The drag area `Cd·A` (m²) of the EPA's `C` in sea-level air (`2·C/ρ`), `None` without
    /// an [`Model::epa_test_car`].
    pub fn epa_drag_area(self) -> Option<f64> {
        self.epa_test_car()
            .map(|car| 2.0 * car.c() / crate::aero::SEA_LEVEL_AIR_DENSITY)
    }

    /// The model's road-load set (`losses = "road-load"`): derived from its
    /// [`Model::epa_test_car`] as the module documentation says (the rolling resistance from
    /// `A` at the test mass, the viscous drag from `B`, the estimated constant drag kept), or
    /// [`RoadLoad::default`] for a model without one.
    ///
    /// ```
    /// use vehicle_model::{Model, RoadLoad};
    /// let tesla = Model::TeslaModel3.road_load::<f64>();
    /// // 37.17 lbf (165.34 N) less 4 × 1 N·m over the 0.36 m tyres, at 4250 lb (1927.8 kg).
    /// let c_rr = (165.340_397 - 4.0 / 0.36) / (1_927.767_573 * 9.81);
    /// assert!((tesla.rolling_resistance.unwrap() - c_rr).abs() < 1e-9);
    /// assert_eq!(Model::Bus.road_load::<f64>(), RoadLoad::default());
    /// ```
    pub fn road_load<T: Real>(self) -> RoadLoad<T> {
        let default = RoadLoad::<f64>::default();
        let Some(car) = self.epa_test_car() else {
            return RoadLoad::default();
        };
        let p = self.params::<f64>();
        let (front, rear) = (p.radius_front(), p.radius_rear());
        // Σ_w 1/r_w and Σ_w 1/r_w² over two wheels per axle.
        let inverse = 2.0 * (1.0 / front + 1.0 / rear);
        let inverse_sq = 2.0 * (1.0 / (front * front) + 1.0 / (rear * rear));
        let rolling = car.a() - default.drag_torque * inverse;
        let rolling_resistance = if rolling > 0.0 {
            rolling / (car.test_mass() * GRAVITY)
        } else {
            0.0
        };
        let viscous = if car.b() > 0.0 { car.b() } else { 0.0 };
        RoadLoad {
            drag_torque: T::from_f64(default.drag_torque),
            viscous_drag: T::from_f64(viscous / inverse_sq),
            rolling_resistance: Some(T::from_f64(rolling_resistance)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_units_convert_exactly() {
        let car = TESLA_MODEL_3;
        // 37.17 lbf, 0.047 lbf/mph, 0.0144 lbf/mph² and 4250 lb in SI.
        assert!((car.a() - 165.340_397).abs() < 1e-6);
        assert!((car.b() - 0.467_668).abs() < 1e-6);
        assert!((car.c() - 0.320_521).abs() < 1e-6);
        assert!((car.test_mass() - 1_927.767_573).abs() < 1e-6);
        let v = 20.0;
        assert!((car.force(v) - (car.a() + car.b() * v + car.c() * v * v)).abs() < 1e-9);
    }

    #[test]
    fn without_a_published_cd_the_air_is_the_epa_s_c() {
        for model in [Model::LincolnMKZ, Model::RangeRoverSportSVR] {
            let c = model.epa_test_car().unwrap().c();
            let aero = model.aero::<f64>();
            // ½·ρ·Cd·A at 1 m/s is C.
            assert!((aero.drag_at(1.0) - c).abs() < 1e-12, "{model}");
        }
    }

    #[test]
    fn the_set_gives_back_a_and_b_at_the_test_mass() {
        for model in Model::ALL {
            let Some(car) = model.epa_test_car() else {
                assert_eq!(model.road_load::<f64>(), RoadLoad::default());
                continue;
            };
            let set = model.road_load::<f64>();
            assert_eq!(set.validated(), Ok(set), "{model}");
            let p = model.params::<f64>();
            let radii = [
                p.radius_front(),
                p.radius_front(),
                p.radius_rear(),
                p.radius_rear(),
            ];
            let c_rr = set.rolling_resistance.unwrap();
            let a: f64 = c_rr * car.test_mass() * GRAVITY
                + radii.iter().map(|r| set.drag_torque / r).sum::<f64>();
            assert!((a - car.a()).abs() < 1e-9, "{model}: A {a} N");
            let b: f64 = radii.iter().map(|r| set.viscous_drag / (r * r)).sum();
            assert!((b - car.b().max(0.0)).abs() < 1e-9, "{model}: B {b} N·s/m");
        }
    }
}
