//! `[vehicle.battery]`, `[vehicle.motor]` and Webots' Robot `battery` field in world files:
//! each value reaches the car's energy parts, and each bad value is refused naming its file,
//! line and key.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::world_file::{CarDescription, WebotsBattery, WorldFileError, parse_str};
use vehicle_model::Model;
use vehicle_model::energy::{Battery, EnergyParams};

fn car(text: &str) -> CarDescription {
    parse_str("w.toml", text).unwrap().car().unwrap().clone()
}

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
}

/// The defaults of `model`: its engine type's, a combustion engine's friction sized from the
/// real car's displacement (`Model::energy_params`).
fn defaults(model: Model) -> EnergyParams<f64> {
    model.energy_params()
}

#[test]
fn every_battery_and_motor_value_is_overridable() {
    let c = car("[vehicle]
model = \"TeslaModel3\"
[vehicle.battery]
capacity = 150
ocv = [300, 310, 320, 330, 340, 350, 360, 370, 380, 390, 400]
resistance = 0.08
max_discharge_current = 600
max_charge_current = 250
state_of_charge = 0.4
[vehicle.motor]
copper = 0.05
iron = 2
windage = 1e-6
constant = 300
regen_max_share = 0.7
regen_max_power = 60000
regen_fade_speed = 3
");
    let e = c.energy.unwrap();
    let b = e.battery.unwrap();
    assert_eq!(b.capacity, 150.0);
    assert_eq!(b.ocv[0], 300.0);
    assert_eq!(b.ocv[10], 400.0);
    assert_eq!(b.resistance, 0.08);
    assert_eq!(
        (b.max_discharge_current, b.max_charge_current),
        (600.0, 250.0)
    );
    assert_eq!(c.state_of_charge, 0.4);
    let m = e.motor.unwrap();
    assert_eq!(
        (m.copper, m.iron, m.windage, m.constant),
        (0.05, 2.0, 1e-6, 300.0)
    );
    let r = e.regen.unwrap();
    assert_eq!(
        (r.max_share, r.max_power, r.fade_speed),
        (0.7, 60_000.0, 3.0)
    );
    // The fuel model is untouched (the Tesla has none).
    assert_eq!(e.fuel, defaults(Model::TeslaModel3).fuel);
}

#[test]
fn a_partial_table_keeps_the_engine_type_s_other_defaults() {
    let c = car("[vehicle]\nmodel = \"ToyotaPrius\"\n[vehicle.battery]\nresistance = 0.5\n");
    let d = defaults(Model::ToyotaPrius);
    let e = c.energy.unwrap();
    assert_eq!(
        e.battery.unwrap(),
        Battery {
            resistance: 0.5,
            ..d.battery.unwrap()
        }
    );
    assert_eq!((e.motor, e.regen, e.fuel), (d.motor, d.regen, d.fuel));
    assert_eq!(c.state_of_charge, 1.0);
    assert_eq!(c.webots_battery, None);
    // `energy = true` alone: the defaults, full.
    let c = car("[vehicle]\nmodel = \"ToyotaPrius\"\nenergy = true\n");
    assert_eq!((c.energy, c.state_of_charge), (Some(d), 1.0));
}

#[test]
fn webots_battery_field_scales_the_default_pack_and_sets_its_charge() {
    // 10 kWh full, 3.6 MJ (1 kWh) left.
    let c = car("[vehicle]\nmodel = \"TeslaModel3\"\nbattery = [3.6e6, 3.6e7, 500]\n");
    assert_eq!(
        c.webots_battery,
        Some(WebotsBattery {
            energy: 3.6e6,
            max_energy: 3.6e7,
            charging_rate: 500.0
        })
    );
    let pack = c.energy.unwrap().battery.unwrap();
    let default = defaults(Model::TeslaModel3).battery.unwrap();
    // The energy is linear in the capacity: the full pack holds maxEnergy to rounding.
    assert!(
        (pack.energy(1.0) - 3.6e7).abs() < 1e-6,
        "{}",
        pack.energy(1.0)
    );
    // The C-rates are kept: current limits over capacity unchanged (to rounding).
    let c_rate = |b: &Battery<f64>| b.max_discharge_current / b.capacity;
    assert!((c_rate(&pack) - c_rate(&default)).abs() < 1e-12);
    assert_eq!(pack.ocv, default.ocv);
    // The starting charge holds the field's energy; bisection to 2⁻⁶⁰ of the charge is
    // far below 1 mJ of a 36 MJ pack.
    assert!((pack.energy(c.state_of_charge) - 3.6e6).abs() < 1e-3);
    // An empty and a full field.
    let c = car("[vehicle]\nmodel = \"TeslaModel3\"\nbattery = [0, 1000, 0]\n");
    assert!(c.state_of_charge < 1e-15);
    let c = car("[vehicle]\nmodel = \"TeslaModel3\"\nbattery = [1000, 1000, 0]\n");
    assert!((c.state_of_charge - 1.0).abs() < 1e-15);
}

/// The error's line, key and message.
fn refusal(text: &str) -> (u32, String, String) {
    let e = err(text);
    assert_eq!(e.file, "w.toml");
    (
        e.location.unwrap().line,
        e.key.clone().unwrap(),
        e.to_string(),
    )
}

#[test]
fn bad_values_are_refused_with_file_line_and_key() {
    let tesla = "[vehicle]\nmodel = \"TeslaModel3\"\n";
    for (table, line, key, why) in [
        (
            "[vehicle.battery]\ncapacity = 0\n",
            4,
            "vehicle.battery.capacity",
            "> 0",
        ),
        (
            "[vehicle.battery]\nresistance = nan\n",
            4,
            "vehicle.battery.resistance",
            "> 0",
        ),
        (
            "[vehicle.battery]\nocv = [1, 2, 3, 4, 5, 5, 6, 7, 8, 9, 10]\n",
            4,
            "vehicle.battery.ocv",
            "greater than the voltage before it",
        ),
        (
            "[vehicle.battery]\nocv = [1, 2]\n",
            4,
            "vehicle.battery.ocv",
            "11 numbers",
        ),
        (
            "[vehicle.battery]\nmax_charge_current = -1\n",
            4,
            "vehicle.battery.max_charge_current",
            "> 0",
        ),
        (
            "[vehicle.battery]\nstate_of_charge = 1.5\n",
            4,
            "vehicle.battery.state_of_charge",
            "[0, 1]",
        ),
        (
            "[vehicle.battery]\ncapasity = 1\n",
            4,
            "vehicle.battery.capasity",
            "capacity",
        ),
        (
            "[vehicle.motor]\niron = -2\n",
            4,
            "vehicle.motor.iron",
            ">= 0",
        ),
        (
            "[vehicle.motor]\nregen_max_share = 1.2\n",
            4,
            "vehicle.motor.regen_max_share",
            "[0, 1]",
        ),
        (
            "[vehicle.motor]\nregen_max_power = inf\n",
            4,
            "vehicle.motor.regen_max_power",
            ">= 0",
        ),
        (
            "[vehicle.motor]\nregen_fade_speed = 0\n",
            4,
            "vehicle.motor.regen_fade_speed",
            "> 0",
        ),
        (
            "battery = [-1, 100, 0]\n",
            3,
            "vehicle.battery",
            "energy in [0, maxEnergy",
        ),
        (
            "battery = [200, 100, 0]\n",
            3,
            "vehicle.battery",
            "energy in [0, maxEnergy",
        ),
        ("battery = [0, 0, 0]\n", 3, "vehicle.battery", "maxEnergy"),
        (
            "battery = [0, 100, -5]\n",
            3,
            "vehicle.battery",
            "chargingRate",
        ),
        ("battery = [0, 100]\n", 3, "vehicle.battery", "3 numbers"),
        (
            "battery = 5\n",
            3,
            "vehicle.battery",
            "[energy, maxEnergy, chargingRate]",
        ),
    ] {
        let (l, k, message) = refusal(&format!("{tesla}{table}"));
        assert_eq!((l, k.as_str()), (line, key), "{message}");
        assert!(message.contains(why), "{table}: {message}");
    }
}

#[test]
fn tables_on_a_combustion_car_or_with_energy_off_are_refused_not_ignored() {
    let (line, key, message) =
        refusal("[vehicle]\nmodel = \"BmwX5\"\n[vehicle.battery]\ncapacity = 5\n");
    assert_eq!((line, key.as_str()), (3, "vehicle.battery"));
    assert!(message.contains("needs an electric machine"), "{message}");
    let (line, key, message) =
        refusal("[vehicle]\nmodel = \"TeslaModel3\"\nenergy = false\nbattery = [1, 2, 0]\n");
    assert_eq!((line, key.as_str()), (4, "vehicle.battery"));
    assert!(message.contains("energy = false"), "{message}");
    let (_, key, _) = refusal("[vehicle]\nmodel = \"BmwX5\"\n[vehicle.motor]\niron = 1\n");
    assert_eq!(key, "vehicle.motor");
}

#[test]
fn the_charge_sustaining_threshold_is_a_power_split_hybrid_s_and_checked() {
    let prius = "[vehicle]\nmodel = \"ToyotaPrius\"\n[vehicle.battery]\n";
    // The default, then a value, then 0: never.
    let e = car(&format!("{prius}capacity = 6.5\n")).energy.unwrap();
    assert_eq!(e.sustain_below, Some(vehicle_model::energy::SUSTAIN_BELOW));
    for (v, expected) in [(0.35, 0.35), (0.0, 0.0)] {
        let e = car(&format!("{prius}sustain_below = {v}\n"))
            .energy
            .unwrap();
        assert_eq!(e.sustain_below, Some(expected));
    }
    let (line, key, message) = refusal(&format!("{prius}sustain_below = 1.5\n"));
    assert_eq!((line, key.as_str()), (4, "vehicle.battery.sustain_below"));
    assert!(message.contains("within [0, 1]"), "{message}");
    // An electric car has no engine to charge with.
    let (line, key, message) =
        refusal("[vehicle]\nmodel = \"TeslaModel3\"\n[vehicle.battery]\nsustain_below = 0.4\n");
    assert_eq!((line, key.as_str()), (4, "vehicle.battery.sustain_below"));
    assert!(message.contains("power-split hybrid"), "{message}");
}
