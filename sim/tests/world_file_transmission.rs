//! World files choosing a car's transmission (`transmission = "webots" | "epa"`): the EPA
//! test vehicle's overall ratios reach the car, the model's own stay without the key, every
//! refusal is located at its key; and the energy accounting of a shipped combustion model
//! sizes its engine's friction from the real car's displacement.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::{CarDescription, Location, WorldFileErrorKind, parse_str};
use vehicle_model::Model;

fn car_of(text: &str) -> CarDescription {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    w.car().unwrap().clone()
}

#[test]
fn epa_gives_the_test_vehicle_s_gearbox_times_its_axle_and_webots_the_model_s_own() {
    for model in [Model::BmwX5, Model::LincolnMKZ, Model::RangeRoverSportSVR] {
        let name = model.webots_name();
        let own = car_of(&format!("[vehicle]\nmodel = \"{name}\"\n"));
        assert_eq!(own.params.gear_ratios, model.params::<f64>().gear_ratios);
        let webots = car_of(&format!(
            "[vehicle]\nmodel = \"{name}\"\ntransmission = \"webots\"\n"
        ));
        assert_eq!(webots.params.gear_ratios, own.params.gear_ratios);
        let epa = car_of(&format!(
            "[vehicle]\nmodel = \"{name}\"\ntransmission = \"epa\"\n"
        ));
        let t = model.epa_transmission().unwrap();
        let expected: Vec<f64> = t.ratios.iter().map(|r| r * t.axle_ratio).collect();
        assert_eq!(
            epa.params.gear_ratios.as_slice(),
            expected.as_slice(),
            "{name}"
        );
    }
    // Golden numbers: the MKZ's first gear 4.484 × 2.77 = 12.42068, the Range Rover's top
    // gear 0.667 × 3.31 = 2.20777, reverse stays negative.
    let mkz = car_of("[vehicle]\nmodel = \"LincolnMKZ\"\ntransmission = \"epa\"\n");
    assert!((mkz.params.gear_ratios[1] - 12.420_68).abs() < 1e-9);
    assert!(mkz.params.gear_ratios[0] < 0.0);
    let rr = car_of("[vehicle]\nmodel = \"RangeRoverSportSVR\"\ntransmission = \"epa\"\n");
    assert_eq!(rr.params.gear_ratios.len(), 9);
    assert!((rr.params.gear_ratios[8] - 2.207_77).abs() < 1e-9);
}

#[test]
fn epa_is_refused_without_a_test_vehicle_transmission_with_gear_ratio_and_misspelt() {
    let cases = [
        // The TeslaModel3 has one reduction gear, the Bus no EPA test vehicle.
        (
            "[vehicle]\nmodel = \"TeslaModel3\"\ntransmission = \"epa\"\n",
            "vehicle.transmission",
            3,
        ),
        (
            "[vehicle]\nmodel = \"Bus\"\ntransmission = \"epa\"\n",
            "vehicle.transmission",
            3,
        ),
        // Two sets of ratios for one car: the Webots field is blamed.
        (
            "[vehicle]\nmodel = \"BmwX5\"\ntransmission = \"epa\"\ngearRatio = [-10, 10, 5]\n",
            "vehicle.gearRatio",
            4,
        ),
    ];
    for (text, key, line) in cases {
        let e = parse_str("w.toml", text).expect_err(text);
        assert!(
            matches!(
                e.kind,
                WorldFileErrorKind::InvalidValue(_) | WorldFileErrorKind::Structure(_)
            ),
            "{text}: {e:?}"
        );
        assert_eq!(e.key.as_deref(), Some(key), "{text}");
        assert_eq!(e.location.map(|l: Location| l.line), Some(line), "{text}");
    }
    let e = parse_str(
        "w.toml",
        "[vehicle]\nmodel = \"BmwX5\"\ntransmission = \"EPA\"\n",
    )
    .unwrap_err();
    match &e.kind {
        WorldFileErrorKind::UnknownName { suggestions, .. } => {
            assert!(suggestions.iter().any(|s| s == "epa"), "{e:?}");
        }
        other => panic!("expected an unknown name, got {other:?}"),
    }
    let e = parse_str("w.toml", "[vehicle]\ntransmission = 8\n").unwrap_err();
    assert!(
        matches!(e.kind, WorldFileErrorKind::WrongType { .. }),
        "{e:?}"
    );
}

#[test]
fn a_shipped_combustion_car_s_fuel_friction_comes_from_its_real_displacement() {
    // The MKZ's curve 150 + 0.1·rpm peaks at 700 N·m at 5500 rpm: 70 N·m of friction by the
    // curve rule; its 3.0 l engine has 125 kPa · 0.003 m³ / (4π) = 29.842 N·m.
    let car = car_of("[vehicle]\nmodel = \"LincolnMKZ\"\nenergy = true\n");
    let fuel = car.energy.unwrap().fuel.unwrap();
    let expected = 125.0e3 * 0.003 / (4.0 * std::f64::consts::PI);
    assert!((fuel.friction_torque - expected).abs() < 1e-9, "{fuel:?}");
    assert_eq!(Some(fuel), Model::LincolnMKZ.energy_params::<f64>().fuel);
    // The plain Car, with no real engine behind it, keeps the curve rule: a tenth of its
    // curve's peak, 150 + 0.1·rpm at engineMaxRPM.
    let car = car_of("[vehicle]\nmodel = \"Car\"\nenergy = true\n");
    let fuel = car.energy.unwrap().fuel.unwrap();
    let peak = 150.0 + 0.1 * Model::Car.params::<f64>().engine.max_rpm;
    assert!((fuel.friction_torque - 0.1 * peak).abs() < 1e-9, "{fuel:?}");
}
