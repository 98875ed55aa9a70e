//! Notes on results that are not a car's (issue #37): a centre of mass outside the body, tyres
//! without grip at the car's load, a time step too long for the body's motion. None on the
//! shipped models at the default step of 10 ms.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::scenario::{self, Scenario, plausibility_notes};
use sim::world_file::{self as wf, parse_str};
use vehicle_model::Model;

fn notes(text: &str) -> Vec<String> {
    plausibility_notes(&parse_str("p.toml", text).unwrap())
}

#[test]
fn the_shipped_models_get_no_note_at_the_default_step() {
    for model in Model::ALL {
        for step in [8, 10] {
            let mut world = wf::with_model(model);
            world.config.basic_time_step_ms = step;
            let n = plausibility_notes(&world);
            assert!(n.is_empty(), "{model:?} at {step} ms: {n:?}");
        }
    }
}

#[test]
fn stiff_springs_need_short_steps() {
    // The Truck's springs give the shortest bounce period of the shipped models, 0.15 s
    // (2π·√(m/k) of its lighter corner): 16 ms is more than a tenth of it; the
    // MercedesBenzSprinter's 0.31 s takes 32 ms.
    let note = |model: &str, step: u32| {
        notes(&format!(
            "basicTimeStep = {step}\n[vehicle]\nmodel = \"{model}\"\n"
        ))
    };
    assert!(note("Truck", 15).is_empty());
    assert!(note("Truck", 16)[0].contains("of Truck on its springs (0.15 s)"));
    assert!(note("MercedesBenzSprinter", 16).is_empty());
    assert!(note("MercedesBenzSprinter", 32)[0].contains("(0.31 s)"));
}

#[test]
fn the_issue_s_worlds_get_their_notes() {
    // A BmwX5 at 1000 ms (yaw 0.631 rad on a straight stop) and at 100 ms (rocking ±1.2 cm at
    // rest).
    for step in [100, 1000] {
        let n = notes(&format!(
            "basicTimeStep = {step}\n[vehicle]\nmodel = \"BmwX5\"\n"
        ));
        assert_eq!(n.len(), 1, "{n:?}");
        assert!(
            n[0].starts_with(&format!(
                "basicTimeStep {step} ms is more than a tenth of the bounce period of BmwX5"
            )),
            "{}",
            n[0]
        );
    }
    // centerOfMass 1000 m ahead (997 m/s² on joints).
    let n = notes("[vehicle]\nmodel = \"BmwX5\"\ncenterOfMass = [1000, 0, 0]\n");
    assert!(
        n.iter().any(|m| m.starts_with(
            "the centre of mass (1000.000, 0.000, 0.000) m of BmwX5 lies outside its body"
        )),
        "{n:?}"
    );
    // A tyre whose nominal load is 1 N with full load sensitivity (0.75 m/s² of grip).
    let n = notes(
        "[vehicle]\nmodel = \"BmwX5\"\n[vehicle.tyre]\nnominal_load = 1\nload_sensitivity = 1\n",
    );
    assert_eq!(n.len(), 2, "{n:?}");
    assert!(
        n[0].starts_with("the front tyres of BmwX5 reach a friction of 0."),
        "{}",
        n[0]
    );
    assert!(
        n[1].starts_with("the rear tyres of BmwX5 reach a friction of 0."),
        "{}",
        n[1]
    );
}

#[test]
fn a_run_carries_its_notes() {
    let world = parse_str(
        "p.toml",
        "basicTimeStep = 100\nduration = 1\n[vehicle]\nmodel = \"BmwX5\"\n",
    )
    .unwrap();
    let report = scenario::run(&world, Scenario::Brake, &mut |_| {}).unwrap();
    assert!(
        report.results[0]
            .notes
            .iter()
            .any(|n| n.starts_with("basicTimeStep 100 ms is more than a tenth")),
        "{:?}",
        report.results[0].notes
    );
}
