//! Structure-aware world files: TOML documents built from the loader's real section and key
//! names (the car's from `CarField`), each key mostly with a value of its own shape (so that
//! many documents load and reach the simulation) and sometimes with one of any shape; numbers
//! are plausible or hostile.

use proptest::prelude::*;
use vehicle_model::{CarField, CarParams, FieldKind, Model};

use crate::strategies::hostile;

/// The shape of a key's value.
#[derive(Debug, Clone, Copy)]
enum Shape {
    /// A number.
    Number,
    /// A list of `.0..=.1` numbers.
    List(usize, usize),
    /// A string.
    Text,
    /// A boolean.
    Bool,
}

/// Strings a value may take: the valid names of every closed set, and near misses.
const NAMES: [&str; 16] = [
    "BmwX5",
    "Truck",
    "cast",
    "joints",
    "webots",
    "magic-formula",
    "passenger-car",
    "tractor",
    "4x4",
    "traction",
    "propulsion",
    "combustion engine",
    "electric engine",
    "power-split hybrid",
    "",
    "bmwx5",
];

/// A `[[vehicle.programme]]` step's commands (issue #37: programme times were unbounded).
const PROGRAMME: [(&str, Shape); 9] = [
    ("cruising_speed", Shape::Number),
    ("steering_angle", Shape::Number),
    ("throttle", Shape::Number),
    ("brake_intensity", Shape::Number),
    ("gear", Shape::Number),
    ("indicator", Shape::Text),
    ("hazard_flashers", Shape::Bool),
    ("dipped_beams", Shape::Bool),
    ("antifog_lights", Shape::Bool),
];

/// `[differential_wheels]`: the Webots node fields, then the simulator's own keys.
const ROBOT: [(&str, Shape); 17] = [
    ("motorConsumption", Shape::Number),
    ("axleLength", Shape::Number),
    ("wheelRadius", Shape::Number),
    ("maxSpeed", Shape::Number),
    ("maxAcceleration", Shape::Number),
    ("speedUnit", Shape::Number),
    ("slipNoise", Shape::Number),
    ("encoderNoise", Shape::Number),
    ("encoderResolution", Shape::Number),
    ("maxForce", Shape::Number),
    ("physics", Shape::Bool),
    ("seed", Shape::Number),
    ("translation", Shape::List(3, 3)),
    ("rotation", Shape::List(4, 4)),
    ("bodyMass", Shape::Number),
    ("wheelMass", Shape::Number),
    ("wheelWidth", Shape::Number),
];

/// Keys and the shapes of their values.
type Keys = &'static [(&'static str, Shape)];

/// Each object table: its header, required keys, then optional keys.
const OBJECTS: [(&str, Keys, Keys); 4] = [
    ("[ground]", &[], &[("friction", Shape::Number)]),
    (
        "[[box]]",
        &[
            ("translation", Shape::List(3, 3)),
            ("size", Shape::List(3, 3)),
        ],
        &[("rotation", Shape::List(4, 4)), ("friction", Shape::Number)],
    ),
    (
        "[[ramp]]",
        &[
            ("start", Shape::List(2, 2)),
            ("length", Shape::Number),
            ("width", Shape::Number),
            ("height", Shape::Number),
        ],
        &[("rotation", Shape::List(4, 4)), ("friction", Shape::Number)],
    ),
    (
        "[[body]]",
        &[
            ("translation", Shape::List(3, 3)),
            ("size", Shape::List(3, 3)),
            ("mass", Shape::Number),
        ],
        &[("rotation", Shape::List(4, 4)), ("friction", Shape::Number)],
    ),
];

/// A number as TOML text: `nan`, `inf`, an integer or an exponent form.
pub fn toml_number(x: f64) -> String {
    if x.is_nan() {
        "nan".to_string()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.to_string()
    } else if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{x:.0}")
    } else {
        format!("{x:e}")
    }
}

/// A number: mostly a small integer or a value of everyday magnitude, sometimes hostile.
fn number() -> BoxedStrategy<String> {
    prop_oneof![
        6 => (1..60i32).prop_map(f64::from),
        8 => 0.01..5.0f64,
        1 => hostile(),
        1 => -50.0..5000.0f64,
    ]
    .prop_map(toml_number)
    .boxed()
}

/// A value of `shape`.
fn shaped(shape: Shape) -> BoxedStrategy<String> {
    match shape {
        Shape::Number => number(),
        Shape::List(min, max) => prop::collection::vec(number(), min..=max)
            .prop_map(|v| format!("[{}]", v.join(", ")))
            .boxed(),
        Shape::Text => prop::sample::select(NAMES.to_vec())
            .prop_map(|s| format!("{s:?}"))
            .boxed(),
        Shape::Bool => any::<bool>().prop_map(|b| b.to_string()).boxed(),
    }
}

/// A value for a key of `shape`: mostly of that shape, sometimes of any shape.
fn value(shape: Shape) -> BoxedStrategy<String> {
    prop_oneof![
        60 => shaped(shape),
        1 => shaped(Shape::Number),
        1 => shaped(Shape::List(0, 7)),
        1 => shaped(Shape::Text),
        1 => shaped(Shape::Bool),
        1 => Just("[1, \"a\"]".to_string()),
        1 => Just("{ model = \"webots\" }".to_string()),
    ]
    .boxed()
}

/// Lines `key = value` for every key of `required` and up to `max` keys of `optional`, each key
/// once.
fn entries(
    required: Vec<(String, Shape)>,
    optional: Vec<(String, Shape)>,
    max: usize,
) -> BoxedStrategy<String> {
    let required: Vec<_> = required
        .into_iter()
        .map(|(k, s)| value(s).prop_map(move |v| (k.clone(), v)))
        .collect();
    let optional = prop::sample::subsequence(optional.clone(), 0..=max.min(optional.len()))
        .prop_flat_map(|keys| {
            keys.into_iter()
                .map(|(k, s)| value(s).prop_map(move |v| (k.clone(), v)))
                .collect::<Vec<_>>()
        });
    (required, optional)
        .prop_map(|(r, o)| {
            r.into_iter()
                .chain(o)
                .map(|(k, v)| format!("{k} = {v}\n"))
                .collect()
        })
        .boxed()
}

/// Owned `(key, shape)` pairs.
fn owned(keys: &[(&str, Shape)]) -> Vec<(String, Shape)> {
    keys.iter().map(|(k, s)| ((*k).to_string(), *s)).collect()
}

/// The `[vehicle]` keys but `model`: `tyre`, `mounting`, every Car field and every wheel field
/// of every wheel slot.
fn vehicle_keys() -> Vec<(String, Shape)> {
    let mut keys = owned(&[("tyre", Shape::Text), ("mounting", Shape::Text)]);
    for field in CarField::ALL {
        let shape = match field.kind() {
            FieldKind::Number => Shape::Number,
            FieldKind::Numbers { min, max } => Shape::List(min, max.min(8)),
            FieldKind::Text => Shape::Text,
        };
        keys.push((field.webots_name().to_string(), shape));
    }
    for slot in CarParams::<f64>::WHEEL_SLOT_NAMES {
        for field in CarParams::<f64>::WHEEL_FIELD_NAMES {
            keys.push((format!("{slot}.{field}"), Shape::Number));
        }
    }
    keys
}

/// A world file: root keys, a car (with a valid model most of the time) or a robot, and
/// optional ground, boxes, ramps and bodies.
pub fn document() -> impl Strategy<Value = String> {
    let root = entries(
        Vec::new(),
        owned(&[
            ("basicTimeStep", Shape::Number),
            ("duration", Shape::Number),
            ("gravity", Shape::Number),
        ]),
        2,
    );
    let model = prop_oneof![
        8 => prop::sample::select(Model::ALL.to_vec()).prop_map(|m| format!("{:?}", m.webots_name())),
        1 => value(Shape::Text),
    ]
    .prop_map(|m| format!("model = {m}\n"));
    // Programme steps: a time (`at`, s: everyday or hostile) and up to two commands.
    let step = entries(owned(&[("at", Shape::Number)]), owned(&PROGRAMME), 2)
        .prop_map(|e| format!("[[vehicle.programme]]\n{e}"));
    let car = (
        model,
        entries(Vec::new(), vehicle_keys(), 3),
        prop::collection::vec(step, 0..3),
    )
        .prop_map(|(m, e, steps)| format!("[vehicle]\n{m}{e}{}", steps.concat()));
    let robot =
        entries(Vec::new(), owned(&ROBOT), 3).prop_map(|e| format!("[differential_wheels]\n{e}"));
    let object = prop::sample::select(OBJECTS.to_vec()).prop_flat_map(|(header, req, opt)| {
        entries(owned(req), owned(opt), 2).prop_map(move |e| format!("{header}\n{e}"))
    });
    (
        root,
        prop_oneof![3 => car, 1 => robot],
        prop::collection::vec(object, 0..3),
    )
        .prop_map(|(root, vehicle, objects)| format!("{root}{vehicle}{}", objects.concat()))
}
