//! World files choosing the tyres: `tyre = "…"`, `[vehicle.tyre]` with the class, coefficient
//! overrides and Webots' force-dependent slip, what reaches the built car, and every error with
//! its location and message.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::{self, Location, NameSet, WorldFileError, WorldFileErrorKind, parse_str};
use sim::{Simulation, TyreChoice, VehiclePlacement, VehicleSpec, World};
use vehicle_model::{
    Direction, MagicFormula, Model, TyreClass, TyreField, TyreModel, WebotsContact,
};

fn tyre_of(text: &str) -> TyreChoice {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    w.car().unwrap().tyre.clone()
}

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
}

fn at(line: u32, column: u32) -> Option<Location> {
    Some(Location { line, column })
}

fn magic(class: TyreClass, overrides: Vec<(TyreField, f64)>) -> TyreChoice {
    TyreChoice::MagicFormula { class, overrides }
}

fn webots(force_dependent_slip: [f64; 2]) -> TyreChoice {
    TyreChoice::Webots(WebotsContact {
        force_dependent_slip,
    })
}

/// The front and rear slip-based tyres of the car a world file describes, as built.
fn built(text: &str) -> [MagicFormula<f64>; 2] {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    let car = w.car().unwrap();
    let spec = VehicleSpec::from_car_with(&car.params, &car.tyre).unwrap();
    [spec.tyres.front, spec.tyres.rear].map(|t| match t {
        TyreModel::MagicFormula(m) => m,
        TyreModel::Webots(_) => panic!("expected the slip-based tyre"),
    })
}

#[test]
fn without_a_tyre_key_the_car_rolls_on_its_class() {
    for (model, class) in [
        ("BmwX5", TyreClass::PassengerCar),
        ("Truck", TyreClass::Commercial),
        ("MercedesBenzSprinter", TyreClass::Commercial),
        ("Tractor", TyreClass::Tractor),
    ] {
        let text = format!("[vehicle]\nmodel = \"{model}\"\n");
        assert_eq!(tyre_of(&text), magic(class, Vec::new()), "{model}");
    }
    // The plain Car PROTO when `model` is absent.
    assert_eq!(
        tyre_of("[vehicle]\nwheelbase = 3\n"),
        magic(TyreClass::PassengerCar, Vec::new())
    );
    // A model name given to `load` is the default world with that car, on its class.
    let bus = world_file::load("Bus").unwrap();
    assert_eq!(
        bus.car().unwrap().tyre,
        magic(TyreClass::Commercial, Vec::new())
    );
    assert_eq!(
        world_file::default_world().car().unwrap().tyre,
        TyreChoice::default()
    );
}

#[test]
fn string_form_names_the_model() {
    assert_eq!(
        tyre_of("[vehicle]\nmodel = \"BmwX5\"\ntyre = \"webots\"\n"),
        webots([0.0, 0.0])
    );
    // "magic-formula" keeps the model's class.
    assert_eq!(
        tyre_of("[vehicle]\nmodel = \"Truck\"\ntyre = \"magic-formula\"\n"),
        magic(TyreClass::Commercial, Vec::new())
    );
}

#[test]
fn table_form_with_class_and_overrides_reaches_the_built_car() {
    let text = r#"
[vehicle]
model = "BmwX5"

[vehicle.tyre]
class = "tractor"
rolling_resistance = 0.02
nominal_load = 5000

[vehicle.tyre.lateral]
shape = 1.4
stiffness = 12

[vehicle.tyre.longitudinal]
peak_friction = 0.9
"#;
    use Direction::{Lateral, Longitudinal};
    assert_eq!(
        tyre_of(text),
        magic(
            TyreClass::Tractor,
            vec![
                (TyreField::RollingResistance, 0.02),
                (TyreField::NominalLoad, 5000.0),
                (TyreField::Shape(Lateral), 1.4),
                (TyreField::Stiffness(Lateral), 12.0),
                (TyreField::PeakFriction(Longitudinal), 0.9),
            ]
        )
    );
    let radius = Model::BmwX5.params::<f64>().wheels.0[0].tire_radius;
    for tyre in built(text) {
        let p = tyre.params();
        // The overrides, on both axles; the explicit nominal load replaces the static load.
        assert_eq!(p.rolling_resistance, 0.02);
        assert_eq!(p.nominal_load, 5000.0);
        assert_eq!(p.lateral.shape, 1.4);
        assert_eq!(p.lateral.stiffness, 12.0);
        assert_eq!(p.longitudinal.peak_friction, 0.9);
        // Everything else is the tractor set: μ_y 0.7, C_x 1.5, σ_y 1.2 radii.
        assert_eq!(p.lateral.peak_friction, 0.7);
        assert_eq!(p.longitudinal.shape, 1.5);
        assert!((p.lateral.relaxation_length - 1.2 * radius).abs() < 1e-12);
    }
}

#[test]
fn without_a_nominal_load_the_tyres_get_the_mean_static_wheel_load() {
    let [front, rear] =
        built("[vehicle]\nmodel = \"BmwX5\"\n[vehicle.tyre]\nclass = \"commercial\"\n");
    let car = Model::BmwX5.params::<f64>();
    let spec = VehicleSpec::from_car(&car).unwrap();
    let mean = spec.static_wheel_loads().iter().sum::<f64>() / 4.0;
    assert_eq!(front.params().nominal_load, mean);
    assert_eq!(rear.params().nominal_load, mean);
    assert_eq!(front.params().lateral.stiffness, 10.0);
}

#[test]
fn dotted_and_inline_tables_are_the_same_table() {
    let dotted = "[vehicle]\ntyre.class = \"commercial\"\ntyre.lateral.curvature = -1\n";
    let inline = "[vehicle]\ntyre = { class = \"commercial\", lateral = { curvature = -1 } }\n";
    let want = magic(
        TyreClass::Commercial,
        vec![(TyreField::Curvature(Direction::Lateral), -1.0)],
    );
    assert_eq!(tyre_of(dotted), want);
    assert_eq!(tyre_of(inline), want);
}

#[test]
fn force_dependent_slip_one_value_is_both_directions() {
    let with = |v: &str| {
        tyre_of(&format!(
            "[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\nforce_dependent_slip = {v}\n"
        ))
    };
    assert_eq!(with("0.001"), webots([0.001, 0.001]));
    assert_eq!(with("[0.002]"), webots([0.002, 0.002]));
    assert_eq!(with("[0.001, 0]"), webots([0.001, 0.0]));
    assert_eq!(
        tyre_of("[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\n"),
        webots([0.0, 0.0])
    );
}

#[test]
fn the_world_s_tyres_reach_a_simulated_car() {
    let w = parse_str(
        "w.toml",
        "[vehicle]\nmodel = \"ToyotaPrius\"\ntyre = { model = \"webots\", force_dependent_slip = [0.001, 0.002] }\n",
    )
    .unwrap();
    let car = w.car().unwrap();
    let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
    let (id, _) = sim
        .add_car(
            sim::CarBuilder::new(car.params.clone())
                .tyre(car.tyre.clone())
                .placement(VehiclePlacement::default()),
        )
        .unwrap();
    let contact = TyreModel::Webots(WebotsContact {
        force_dependent_slip: [0.001, 0.002],
    });
    let spec = *sim.world().vehicle(id).unwrap().spec();
    assert_eq!((spec.tyres.front, spec.tyres.rear), (contact, contact));
    // `add_car` keeps the passenger-car slip-based tyre.
    let (id, _) = sim
        .add_car(sim::CarBuilder::new(Model::Truck.params()).placement(VehiclePlacement::default()))
        .unwrap();
    let TyreModel::MagicFormula(front) = sim.world().vehicle(id).unwrap().spec().tyres.front else {
        panic!("expected the slip-based tyre");
    };
    assert_eq!(front.params().lateral.stiffness, 18.0);
}

#[test]
fn unknown_keys_are_located_with_suggestions() {
    let e = err("[vehicle]\n[vehicle.tyre]\nrolling_resistence = 0.01\n");
    assert_eq!(e.location, at(3, 1));
    assert_eq!(e.key.as_deref(), Some("vehicle.tyre.rolling_resistence"));
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: unknown key 'vehicle.tyre.rolling_resistence'; did you mean \
         'rolling_resistance'?"
    );
    let e = err("[vehicle]\n[vehicle.tyre.lateral]\nstifness = 10\n");
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: unknown key 'vehicle.tyre.lateral.stifness'; did you mean 'stiffness'?"
    );
    let e = err("[vehicle]\nmodel = \"BmwX5\"\ntyres = \"webots\"\n");
    assert_eq!(e.location, at(3, 1));
    assert_eq!(e.suggestions().first().map(String::as_str), Some("tyre"));
}

#[test]
fn misplaced_coefficients_are_told_where_they_belong() {
    let e = err("[vehicle]\n[vehicle.tyre]\nshape = 1.5\n");
    assert_eq!(e.location, at(3, 1));
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: 'vehicle.tyre.shape' is a curve coefficient: set it in \
         [vehicle.tyre.longitudinal] or [vehicle.tyre.lateral]"
    );
    let e = err("[vehicle]\n[vehicle.tyre.longitudinal]\nnominal_load = 4000\n");
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: 'vehicle.tyre.longitudinal.nominal_load' is a tyre-wide coefficient: \
         set it in [vehicle.tyre]"
    );
}

#[test]
fn wrong_types_name_what_the_key_takes() {
    let cases = [
        (
            "[vehicle]\ntyre = 1\n",
            "w.toml:2:1: 'vehicle.tyre' takes \"magic-formula\", \"webots\" or a table \
             [vehicle.tyre], found an integer",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nclass = 2\n",
            "w.toml:3:1: 'vehicle.tyre.class' takes a string, found an integer",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nmodel = true\n",
            "w.toml:3:1: 'vehicle.tyre.model' takes a string, found a boolean",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nnominal_load = \"heavy\"\n",
            "w.toml:3:1: 'vehicle.tyre.nominal_load' takes a number, found a string",
        ),
        (
            "[vehicle]\n[vehicle.tyre.lateral]\nshape = [1.3]\n",
            "w.toml:3:1: 'vehicle.tyre.lateral.shape' takes a number, found a list of 1 values",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nlateral = 3\n",
            "w.toml:3:1: 'vehicle.tyre.lateral' takes a table, found an integer",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\nforce_dependent_slip = \"x\"\n",
            "w.toml:4:1: 'vehicle.tyre.force_dependent_slip' takes a number or a list of 1 or \
             2 numbers (m/s per N), found a string",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\nforce_dependent_slip = [0, 0, 0]\n",
            "w.toml:4:1: 'vehicle.tyre.force_dependent_slip' takes a number or a list of 1 or \
             2 numbers (m/s per N), found a list of 3 values",
        ),
    ];
    for (text, message) in cases {
        let e = err(text);
        assert!(
            matches!(e.kind, WorldFileErrorKind::WrongType { .. }),
            "{text}: {e:?}"
        );
        assert_eq!(e.to_string(), message, "{text}");
    }
}

#[test]
fn unknown_names_suggest_the_valid_ones() {
    let e = err("[vehicle]\ntyre = \"magic_formula\"\n");
    assert_eq!(e.location, at(2, 1));
    assert_eq!(
        e.kind,
        WorldFileErrorKind::UnknownName {
            what: NameSet::TyreModel,
            name: "magic_formula".into(),
            suggestions: vec!["magic-formula".into()],
        }
    );
    assert_eq!(
        e.to_string(),
        "w.toml:2:1: unknown tyre model 'magic_formula'; did you mean 'magic-formula'?"
    );
    // Nothing close: every name of the small set is offered.
    let e = err("[vehicle]\n[vehicle.tyre]\nmodel = \"pacejka\"\n");
    assert_eq!(e.key.as_deref(), Some("vehicle.tyre.model"));
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: unknown tyre model 'pacejka'; did you mean 'magic-formula' or 'webots'?"
    );
    let e = err("[vehicle]\n[vehicle.tyre]\nclass = \"passenger\"\n");
    assert_eq!(e.suggestions(), ["passenger-car"]);
    let e = err("[vehicle]\n[vehicle.tyre]\nclass = \"truck\"\n");
    assert_eq!(
        e.to_string(),
        "w.toml:3:1: unknown tyre class 'truck'; did you mean 'passenger-car', 'commercial' or \
         'tractor'?"
    );
}

#[test]
fn values_out_of_range_are_located_at_their_key() {
    let cases = [
        (
            "[vehicle]\n[vehicle.tyre.lateral]\nshape = 2.5\n",
            "w.toml:3:1: invalid 'vehicle.tyre.lateral.shape': 2.5: must be in (1, 2)",
        ),
        (
            "[vehicle]\n[vehicle.tyre.longitudinal]\ncurvature = 1\n",
            "w.toml:3:1: invalid 'vehicle.tyre.longitudinal.curvature': 1: must be in [-10, 1)",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nclass = \"commercial\"\nnominal_load = 0\n",
            "w.toml:4:1: invalid 'vehicle.tyre.nominal_load': 0: must be in [1, 1e6] N",
        ),
        (
            "[vehicle]\ntyre.lateral.relaxation_length = nan\n",
            // A dotted key is located at its last part.
            "w.toml:2:14: invalid 'vehicle.tyre.lateral.relaxation_length': NaN: must be in \
             [0.001, 10] m",
        ),
        (
            "[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\nforce_dependent_slip = [0.001, -0.1]\n",
            "w.toml:4:1: invalid 'vehicle.tyre.force_dependent_slip': -0.1 m/s per N: must be \
             finite and in [0, 1]",
        ),
    ];
    for (text, message) in cases {
        let e = err(text);
        assert!(
            matches!(e.kind, WorldFileErrorKind::InvalidValue(_)),
            "{text}: {e:?}"
        );
        assert_eq!(e.to_string(), message, "{text}");
    }
    // The first bad value in file order is the one reported.
    let e =
        err("[vehicle]\n[vehicle.tyre]\nload_sensitivity = 2\n[vehicle.tyre.lateral]\nshape = 3\n");
    assert_eq!(e.key.as_deref(), Some("vehicle.tyre.load_sensitivity"));
    assert_eq!(e.location, at(3, 1));
}

#[test]
fn keys_of_the_other_model_are_errors() {
    let e = err("[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\nrolling_resistance = 0.01\n");
    assert_eq!(e.location, at(4, 1));
    assert_eq!(e.key.as_deref(), Some("vehicle.tyre.rolling_resistance"));
    assert_eq!(
        e.to_string(),
        "w.toml:4:1: 'vehicle.tyre.rolling_resistance' belongs to the magic-formula tyre; it \
         does not apply with model = \"webots\""
    );
    for key in ["class = \"tractor\"", "lateral.shape = 1.5"] {
        let e = err(&format!(
            "[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\n{key}\n"
        ));
        assert!(
            matches!(e.kind, WorldFileErrorKind::Structure(_)),
            "{key}: {e:?}"
        );
        assert_eq!(e.location, at(4, 1), "{key}");
        assert!(
            e.to_string().contains("belongs to the magic-formula tyre"),
            "{e}"
        );
    }
    for model in ["", "model = \"magic-formula\"\n"] {
        let e = err(&format!(
            "[vehicle]\n[vehicle.tyre]\n{model}force_dependent_slip = 0.001\n"
        ));
        assert_eq!(e.key.as_deref(), Some("vehicle.tyre.force_dependent_slip"));
        assert_eq!(
            e.to_string(),
            format!(
                "w.toml:{}:1: 'vehicle.tyre.force_dependent_slip' belongs to the webots tyre \
                 (Webots' ContactProperties.forceDependentSlip); it applies only with \
                 model = \"webots\"",
                if model.is_empty() { 3 } else { 4 }
            )
        );
    }
}
