//! World files giving a car air (`aero = true`, `[vehicle.aero]`) and the world a `wind`: what
//! reaches the built car and the world, and every error located at its key.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::{Location, WorldFileError, WorldFileErrorKind, parse_str};
use sim::{CarBuilder, Simulation, World};
use vehicle_model::{Aero, Model};

fn aero_of(text: &str) -> Option<Aero<f64>> {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    w.car().unwrap().aero
}

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
}

#[test]
fn without_the_key_or_with_false_there_is_no_air_as_in_webots() {
    assert_eq!(aero_of("[vehicle]\nmodel = \"BmwX5\"\n"), None);
    assert_eq!(
        aero_of("[vehicle]\nmodel = \"BmwX5\"\naero = false\n"),
        None
    );
}

#[test]
fn true_gives_the_model_s_coefficients_and_a_table_overrides_them() {
    assert_eq!(
        aero_of("[vehicle]\nmodel = \"BmwX5\"\naero = true\n"),
        Some(Model::BmwX5.aero())
    );
    let text = "[vehicle]\nmodel = \"TeslaModel3\"\n[vehicle.aero]\ndrag_coefficient = 0.3\n\
                lift_coefficient_rear = -0.2\nair_density = 1.0\n";
    assert_eq!(
        aero_of(text),
        Some(Aero {
            drag_coefficient: 0.3,
            lift_coefficient_rear: -0.2,
            air_density: 1.0,
            ..Model::TeslaModel3.aero()
        })
    );
}

#[test]
fn the_world_s_air_and_wind_reach_the_simulated_car() {
    let text = "wind = [3, -4, 0]\n[vehicle]\nmodel = \"ToyotaPrius\"\naero = true\n";
    let w = parse_str("w.toml", text).unwrap();
    assert_eq!(w.config.wind.as_slice(), &[3.0, -4.0, 0.0]);
    let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
    let (id, _) = sim.add_car(CarBuilder::from(w.car().unwrap())).unwrap();
    let spec = sim.world().vehicle(id).unwrap().spec();
    assert_eq!(spec.aero, Some(Model::ToyotaPrius.aero()));
}

#[test]
fn bad_values_are_located_at_their_key() {
    let cases = [
        // A drag area (Cd·A, m²) typed in as the coefficient.
        (
            "[vehicle]\n[vehicle.aero]\ndrag_coefficient = 6.6\n",
            "vehicle.aero.drag_coefficient",
            3,
        ),
        (
            "[vehicle]\n[vehicle.aero]\nfrontal_area = 0\n",
            "vehicle.aero.frontal_area",
            3,
        ),
        (
            "[vehicle]\n[vehicle.aero]\nair_density = 1000\n",
            "vehicle.aero.air_density",
            3,
        ),
        (
            "[vehicle]\naero.lift_coefficient_front = nan\n",
            "vehicle.aero.lift_coefficient_front",
            2,
        ),
        ("wind = [80, 0, 0]\n[vehicle]\n", "wind", 1),
    ];
    for (text, key, line) in cases {
        let e = err(text);
        assert!(
            matches!(e.kind, WorldFileErrorKind::InvalidValue(_)),
            "{text}: {e:?}"
        );
        assert_eq!(e.key.as_deref(), Some(key), "{text}");
        assert_eq!(e.location.map(|l: Location| l.line), Some(line), "{text}");
    }
}

#[test]
fn wrong_types_and_unknown_keys_are_named() {
    let e = err("[vehicle]\naero = \"yes\"\n");
    assert!(
        matches!(e.kind, WorldFileErrorKind::WrongType { .. }),
        "{e:?}"
    );
    assert_eq!(e.key.as_deref(), Some("vehicle.aero"));
    let e = err("[vehicle]\n[vehicle.aero]\ndrag = 0.3\n");
    match &e.kind {
        WorldFileErrorKind::UnknownKey { suggestions } => {
            assert!(suggestions.iter().any(|s| s == "drag_coefficient"), "{e:?}");
        }
        other => panic!("expected an unknown key, got {other:?}"),
    }
    let e = err("wind = [1, 2]\n[vehicle]\n");
    assert_eq!(e.key.as_deref(), Some("wind"));
}
