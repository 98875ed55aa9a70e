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
use crate::energy::EnergyParams;
use crate::params::{GearRatios, gear_ratios_times};

/// N per lbf (exact: 0.453 592 37 kg × 9.806 65 m/s²).
const N_PER_LBF: f64 = 4.448_221_615_260_5;
/// m/s per mph (exact).
const MS_PER_MPH: f64 = 0.447_04;
/// kg per lb (exact).
const KG_PER_LB: f64 = 0.453_592_37;
/// m³ per litre (exact).
const M3_PER_LITRE: f64 = 1e-3;
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
    /// "Test Veh Displacement (L)" (litres): the combustion engine's swept volume, `None` for
    /// an electric car. It sizes the fuel model's friction ([`Model::energy_params`]). Read
    /// on the same test vehicle's rows of the fuel-economy results the consumption tests
    /// cite (`22-testcar-2023-06-13.xlsx`, `19tstcar-2020-10-02.xlsx`).
    pub displacement_l: Option<f64>,
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
    displacement_l: None,
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
    displacement_l: Some(1.798),
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
    displacement_l: Some(3.0),
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
    displacement_l: Some(3.0),
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
    displacement_l: Some(5.0),
};

/// A test vehicle's stepped transmission: its gearbox's ratios and the EPA row's "Axle
/// Ratio", whose products are the overall ratios a world's `gearRatio` holds
/// (`transmission = "epa"`, [`Model::epa_transmission`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpaTransmission {
    /// The gearbox, as the ratios' source names it.
    pub gearbox: &'static str,
    /// Its ratios, reverse (negative) then first gear up (dimensionless, input over output
    /// speed).
    pub ratios: &'static [f64],
    /// The test vehicle's "Axle Ratio" (dimensionless): the final drive after the gearbox.
    pub axle_ratio: f64,
}

impl EpaTransmission {
    /// The overall ratios (engine speed over wheel spin), reverse first: each gearbox ratio
    /// times the axle ratio, in the form of Webots' `gearRatio`.
    pub fn overall<T: Real>(&self) -> GearRatios<T> {
        gear_ratios_times(self.ratios, self.axle_ratio)
    }
}

/// ZF's eight-speed 8HP as Wikipedia's "ZF 8HP transmission" lists its 2008 8HP 70
/// (reverse −3.297, then 4.696 … 0.667): the ratios Webots' RangeRoverSportSVR has as its
/// `gearRatio`, without the axle. The EPA does not say which generation the test vehicles
/// carry; the table's 2010 and 2014 rows differ from this one by at most 0.4 % (first gear
/// 4.714, second 3.143) and have the same top gear.
const ZF_8HP: [f64; 9] = [
    -3.297, 4.696, 3.130, 2.104, 1.667, 1.285, 1.000, 0.839, 0.667,
];

/// The Ford 6F55 six-speed of the MKZ 3.0 V6 as Wikipedia's "GM–Ford 6-speed automatic
/// transmission" lists the family's ratios (4.484 … 0.742, reverse 2.88), close to Webots'
/// LincolnMKZ's `gearRatio` (4.58 … 0.75, reverse 2.94), which has no axle either.
const FORD_6F: [f64; 7] = [-2.88, 4.484, 2.872, 1.842, 1.414, 1.000, 0.742];

impl Model {
    /// The EPA test vehicle's transmission (gearbox ratios from the sources on
    /// [`EpaTransmission`]'s constants, the axle ratio from the EPA row of
    /// [`Model::epa_test_car`]'s test vehicle), for the combustion cars with a stepped
    /// gearbox: BmwX5 (8 gears, axle 3.38), LincolnMKZ (6, 2.77) and RangeRoverSportSVR (8,
    /// 3.31); `None` for the others. Webots' BmwX5 has five overall ratios of its own; the
    /// MKZ's and the Range Rover's are their gearboxes' without the final drive, so their
    /// engines turn 2.8–3.3 times slower than the real cars' and cannot follow a drive cycle.
    ///
    /// ```
    /// use vehicle_model::Model;
    /// let x5 = Model::BmwX5.epa_transmission().unwrap();
    /// let overall = x5.overall::<f64>();
    /// // Eighth gear 0.667 × axle 3.38.
    /// assert!((overall[8] - 2.254_46).abs() < 1e-9);
    /// ```
    pub const fn epa_transmission(self) -> Option<EpaTransmission> {
        match self {
            Model::BmwX5 => Some(EpaTransmission {
                gearbox: "ZF 8HP",
                ratios: &ZF_8HP,
                axle_ratio: 3.38,
            }),
            Model::LincolnMKZ => Some(EpaTransmission {
                gearbox: "Ford 6F55",
                ratios: &FORD_6F,
                axle_ratio: 2.77,
            }),
            Model::RangeRoverSportSVR => Some(EpaTransmission {
                gearbox: "ZF 8HP",
                ratios: &ZF_8HP,
                axle_ratio: 3.31,
            }),
            _ => None,
        }
    }

    /// The model's energy accounting defaults ([`EnergyParams::of_engine_displacing`]): its
    /// engine's, with a combustion engine's friction sized from the EPA test vehicle's
    /// displacement ([`EpaTestCar::displacement_l`]) where there is one, else from the torque
    /// curve. Webots' LincolnMKZ and RangeRoverSportSVR keep the Car PROTO's curve
    /// `150 + 0.1·rpm` N·m, which at 5500 rpm implies a 7 l engine; their real engines are
    /// 3.0 and 5.0 l.
    pub fn energy_params<T: Real>(self) -> EnergyParams<T> {
        EnergyParams::of_engine_displacing(&self.params::<T>().engine, self.engine_displacement())
    }

    /// The real car's engine displacement (m³): the EPA test vehicle's
    /// ([`EpaTestCar::displacement_l`]), `None` without one or for an electric car.
    pub fn engine_displacement<T: Real>(self) -> Option<T> {
        self.epa_test_car()
            .and_then(|car| car.displacement_l)
            .map(|litres| T::from_f64(litres * M3_PER_LITRE))
    }

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
    fn the_epa_transmissions_are_the_gearboxes_times_the_axles() {
        // First and top gears by hand: 4.696·3.38, 0.667·3.38; 4.484·2.77, 0.742·2.77;
        // 4.696·3.31, 0.667·3.31; reverse negative.
        let cases = [
            (Model::BmwX5, 9, 15.872_48, 2.254_46),
            (Model::LincolnMKZ, 7, 12.420_68, 2.055_34),
            (Model::RangeRoverSportSVR, 9, 15.543_76, 2.207_77),
        ];
        for (model, len, first, top) in cases {
            let overall = model.epa_transmission().unwrap().overall::<f64>();
            assert_eq!(overall.len(), len, "{model}");
            assert!((overall[1] - first).abs() < 1e-9, "{model}: {}", overall[1]);
            assert!((overall[len - 1] - top).abs() < 1e-9, "{model}");
            assert!(overall[0] < 0.0, "{model}");
            // A world's gearRatio must take it as it is.
            let mut p = model.params::<f64>();
            p.gear_ratios = overall;
            assert_eq!(p.validate().len(), 0, "{model}");
        }
        for model in Model::ALL {
            let combustion =
                model.params::<f64>().engine.engine_type == powertrain::EngineType::Combustion;
            assert_eq!(
                model.epa_transmission().is_some(),
                combustion && model.epa_test_car().is_some(),
                "{model}"
            );
        }
    }

    #[test]
    fn the_real_displacement_sizes_the_friction_and_an_electric_car_burns_nothing() {
        for (model, litres) in [
            (Model::BmwX5, 3.0),
            (Model::LincolnMKZ, 3.0),
            (Model::RangeRoverSportSVR, 5.0),
            (Model::ToyotaPrius, 1.798),
        ] {
            let fuel = model.energy_params::<f64>().fuel.unwrap();
            let t0 = 125.0e3 * litres * 1e-3 / (4.0 * core::f64::consts::PI);
            assert!((fuel.friction_torque - t0).abs() < 1e-9, "{model}");
        }
        assert_eq!(Model::TeslaModel3.engine_displacement::<f64>(), None);
        assert_eq!(Model::TeslaModel3.energy_params::<f64>().fuel, None);
        // Without a test car, the curve rule.
        let bus = Model::Bus.params::<f64>().engine;
        assert_eq!(
            Model::Bus.energy_params::<f64>(),
            EnergyParams::of_engine(&bus)
        );
    }

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
