//! World files choosing a car's wheel losses (`losses = "webots" | "road-load"`,
//! `[vehicle.losses]`): what reaches the built car, the air that comes with the road-load
//! set, and every error located at its key.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::{CarDescription, Location, WorldFileErrorKind, parse_str};
use sim::{CarBuilder, Simulation, World};
use vehicle_model::{Model, RoadLoad, TyreModel};

fn car_of(text: &str) -> CarDescription {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    w.car().unwrap().clone()
}

#[test]
fn without_the_key_or_with_webots_the_wheels_keep_webots_damping_alone() {
    for text in [
        "[vehicle]\nmodel = \"BmwX5\"\n",
        "[vehicle]\nmodel = \"BmwX5\"\nlosses = \"webots\"\n",
    ] {
        let car = car_of(text);
        assert_eq!(car.road_load, None, "{text}");
        assert_eq!(car.aero, None, "{text}");
    }
}

#[test]
fn road_load_gives_the_model_s_set_and_its_air_unless_aero_says_otherwise() {
    let car = car_of("[vehicle]\nmodel = \"BmwX5\"\nlosses = \"road-load\"\n");
    assert_eq!(car.road_load, Some(Model::BmwX5.road_load()));
    assert_eq!(car.aero, Some(Model::BmwX5.aero()));
    let car = car_of("[vehicle]\nmodel = \"BmwX5\"\nlosses = \"road-load\"\naero = false\n");
    assert_eq!(car.road_load, Some(Model::BmwX5.road_load()));
    assert_eq!(car.aero, None);
    // A model the EPA has not tested keeps the tyre's rolling resistance.
    let car = car_of("[vehicle]\nmodel = \"Bus\"\nlosses = \"road-load\"\n");
    assert_eq!(car.road_load, Some(RoadLoad::default()));
}

#[test]
fn a_table_overrides_the_default_values_and_reaches_the_simulated_car() {
    let text = "[vehicle]\nmodel = \"TeslaModel3\"\n[vehicle.losses]\nviscous_drag = 0.05\n";
    let w = parse_str("w.toml", text).unwrap();
    let expected = RoadLoad {
        viscous_drag: 0.05,
        ..Model::TeslaModel3.road_load()
    };
    assert_eq!(w.car().unwrap().road_load, Some(expected));
    let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
    let (id, _) = sim.add_car(CarBuilder::from(w.car().unwrap())).unwrap();
    let spec = sim.world().vehicle(id).unwrap().spec();
    assert_eq!(spec.road_load, Some(expected));
    assert_eq!(spec.aero, Some(Model::TeslaModel3.aero()));
}

#[test]
fn the_set_s_rolling_resistance_reaches_the_tyres_unless_the_tyre_writes_its_own() {
    let c_rr = |text: &str| {
        let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
        let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
        let (id, _) = sim.add_car(CarBuilder::from(w.car().unwrap())).unwrap();
        match sim.world().vehicle(id).unwrap().spec().tyres.rear {
            TyreModel::MagicFormula(t) => t.params().rolling_resistance,
            TyreModel::Webots(_) => panic!("{text}"),
        }
    };
    let model = "[vehicle]\nmodel = \"TeslaModel3\"\n";
    let derived = Model::TeslaModel3
        .road_load::<f64>()
        .rolling_resistance
        .unwrap();
    assert_eq!(c_rr(&format!("{model}losses = \"road-load\"\n")), derived);
    // Webots' losses keep the tyre class's.
    assert_eq!(c_rr(model), 0.012);
    assert_eq!(
        c_rr(&format!(
            "{model}[vehicle.losses]\nrolling_resistance = 0.01\n"
        )),
        0.01
    );
    assert_eq!(
        c_rr(&format!(
            "{model}losses = \"road-load\"\n[vehicle.tyre]\nrolling_resistance = 0.02\n"
        )),
        0.02
    );
}

#[test]
fn bad_values_names_and_types_are_located_at_their_key() {
    let invalid = [
        // Webots' damping of a lorry's wheel, 30, typed in as the driveline's.
        (
            "[vehicle]\n[vehicle.losses]\nviscous_drag = 30\n",
            "vehicle.losses.viscous_drag",
            3,
        ),
        (
            "[vehicle]\n[vehicle.losses]\ndrag_torque = -1\n",
            "vehicle.losses.drag_torque",
            3,
        ),
        (
            "[vehicle]\nlosses.viscous_drag = nan\n",
            "vehicle.losses.viscous_drag",
            2,
        ),
        // A rolling resistance typed in per cent.
        (
            "[vehicle]\n[vehicle.losses]\nrolling_resistance = 1.2\n",
            "vehicle.losses.rolling_resistance",
            3,
        ),
    ];
    for (text, key, line) in invalid {
        let e = parse_str("w.toml", text).expect_err(text);
        assert!(
            matches!(e.kind, WorldFileErrorKind::InvalidValue(_)),
            "{text}: {e:?}"
        );
        assert_eq!(e.key.as_deref(), Some(key), "{text}");
        assert_eq!(e.location.map(|l: Location| l.line), Some(line), "{text}");
    }
    let e = parse_str("w.toml", "[vehicle]\nlosses = \"roadload\"\n").unwrap_err();
    match &e.kind {
        WorldFileErrorKind::UnknownName { suggestions, .. } => {
            assert!(suggestions.iter().any(|s| s == "road-load"), "{e:?}");
        }
        other => panic!("expected an unknown name, got {other:?}"),
    }
    assert_eq!(e.key.as_deref(), Some("vehicle.losses"));
    let e = parse_str("w.toml", "[vehicle]\nlosses = true\n").unwrap_err();
    assert!(
        matches!(e.kind, WorldFileErrorKind::WrongType { .. }),
        "{e:?}"
    );
    let e = parse_str("w.toml", "[vehicle]\n[vehicle.losses]\ndrag = 1\n").unwrap_err();
    match &e.kind {
        WorldFileErrorKind::UnknownKey { suggestions } => {
            assert!(suggestions.iter().any(|s| s == "drag_torque"), "{e:?}");
        }
        other => panic!("expected an unknown key, got {other:?}"),
    }
}
