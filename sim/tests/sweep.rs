//! Sweeps: the same results whole, in shards merged, on any number of threads; the physics
//! of real sweeps; failing cases; random axes; colours. The errors of sweep files and of
//! merges are in `sweep_errors.rs`.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[path = "support/sweep.rs"]
mod support;

use std::path::{Path, PathBuf};

use sim::sweep::{self, AxisValue, CaseError, RESULTS_CSV, Row, Shard, Sweep};
use support::{SHORT, metric, parse, read, rows, scratch, write};

#[test]
fn whole_sharded_and_threaded_runs_write_the_same_results() {
    let dir = scratch("shards");
    let sweep = parse(SHORT).unwrap();
    assert_eq!(sweep.len(), 12);
    write(&sweep, Shard::WHOLE, 2, &dir.join("whole"));
    write(&sweep, Shard::WHOLE, 1, &dir.join("one-thread"));
    let shards: Vec<PathBuf> = (0..3)
        .map(|i| {
            let d = dir.join(format!("shard-{i}"));
            write(&sweep, Shard::new(i, 3).unwrap(), 2, &d);
            d
        })
        .collect();
    // The shards are handed over in another order than their index: the merge orders them.
    let given = [shards[2].clone(), shards[0].clone(), shards[1].clone()];
    let summary = sweep::merge(&given, &dir.join("merged")).unwrap();
    assert_eq!((summary.shards, summary.rows, summary.errors), (3, 12, 6));
    let whole = read(&dir.join("whole").join(RESULTS_CSV));
    assert_eq!(read(&dir.join("one-thread").join(RESULTS_CSV)), whole);
    assert_eq!(read(&dir.join("merged").join(RESULTS_CSV)), whole);
    // And row by row through the library, as the Python package does.
    let lines: String =
        sweep.columns().csv_header() + &rows(&sweep).iter().map(Row::csv_line).collect::<String>();
    assert_eq!(lines, whole);
    // Shard 1 holds cases 1, 4, 7, 10.
    let shard1 = read(&shards[1].join(RESULTS_CSV));
    let cases: Vec<&str> = shard1
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(cases, ["1", "4", "7", "10"]);
    // The wall times are apart, one per case.
    let timings = read(&dir.join("merged").join(sweep::TIMINGS_CSV));
    assert_eq!(timings.lines().count(), 13);
    assert!(timings.starts_with("case,wall_seconds\n0,"));
    // Plots of each numeric axis (here all three), from the merged rows too.
    for axis in ["ground.friction", "vehicle.time0To100", "vehicle.mass"] {
        let svg = read(&dir.join("merged/plots").join(format!("{axis}.svg")));
        assert!(
            svg.contains("12 cases") && svg.contains("time_0_100_nominal_s"),
            "{axis}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_invalid_value_fails_its_cases_only_naming_the_key() {
    let sweep = parse(SHORT).unwrap();
    // Cases 6 to 11 have friction −1, the first axis (the slowest).
    for row in &rows(&sweep) {
        let failed = row.values[0] == AxisValue::Integer(-1);
        assert_eq!(row.error.is_some(), failed, "case {}", row.case);
        if failed {
            assert_eq!(
                row.error.as_ref().unwrap().to_string(),
                "invalid 'ground.friction': -1: must be finite and >= 0"
            );
            assert!(row.metrics.iter().all(|c| *c == sweep::Cell::Empty));
            // The error cell, then the row's checksum (16 hexadecimal digits).
            let line = row.csv_line();
            let (before, checksum) = line.trim_end().rsplit_once(',').unwrap();
            assert!(before.ends_with(",invalid 'ground.friction': -1: must be finite and >= 0"));
            assert_eq!(checksum, row.checksum());
            assert!(checksum.len() == 16 && checksum.bytes().all(|b| b.is_ascii_hexdigit()));
        } else {
            // Complete: within 2 s a car has neither reached 100 km/h (empty) nor failed;
            // every other metric has its value.
            let empty: Vec<&String> = sweep
                .columns()
                .metrics
                .iter()
                .zip(&row.metrics)
                .filter(|(_, c)| **c == sweep::Cell::Empty)
                .map(|(m, _)| m)
                .collect();
            assert_eq!(empty, ["time_0_100_s"], "case {}", row.case);
            assert_eq!(metric(&sweep, row, "sim_seconds"), 2.0);
            // The nominal 0-100 time is the axis's value.
            let nominal = row.values[1].as_f64().unwrap();
            assert_eq!(metric(&sweep, row, "time_0_100_nominal_s"), nominal);
        }
    }
    // A negative mass is a value that a world file replaces by the default with a warning
    // (as Webots does); in a sweep the case fails instead, naming the key.
    let sweep = parse(
        "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 0.5\n[axes]\n\
         \"vehicle.mass\" = [2000, -100]\n",
    )
    .unwrap();
    let all = rows(&sweep);
    assert_eq!(all[0].error, None);
    let Some(CaseError::Replaced { key, message }) = &all[1].error else {
        panic!("{:?}", all[1].error)
    };
    assert_eq!(key, "vehicle.mass");
    assert!(message.contains("'mass' value -100"), "{message}");
    // The message has a comma: the CSV quotes it.
    assert!(
        all[1].csv_line().starts_with(
            "1,-100,,,,,,,,,\"invalid 'vehicle.mass': a world file would replace the value: "
        ),
        "{}",
        all[1].csv_line()
    );
}

/// The product of friction [0.6, 0.8, 1.0] and brakeCoefficient [500, 1000, 3000] of a BmwX5
/// braking from 100 km/h, as (friction, brakeCoefficient, stopping distance (m)).
fn braking_sweep() -> Vec<(f64, f64, f64)> {
    let sweep = parse(
        "world = \"BmwX5\"\nscenario = \"brake\"\n[axes]\n\
         \"ground.friction\" = [0.6, 0.8, 1.0]\n\"vehicle.brakeCoefficient\" = [500, 1000, 3000]\n",
    )
    .unwrap();
    let dir = scratch("brake");
    write(&sweep, Shard::WHOLE, 2, &dir);
    let text = read(&dir.join(RESULTS_CSV));
    std::fs::remove_dir_all(&dir).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let cells: Vec<&str> = l.split(',').collect();
            let num = |name: &str| cells[col(name)].parse::<f64>().unwrap();
            // Every case started braking from 100 km/h (within the cruise control's creep).
            assert!((num("initial_speed_kmh") - 99.5).abs() < 0.5, "{l}");
            (
                num("ground.friction"),
                num("vehicle.brakeCoefficient"),
                num("stop_distance_m"),
            )
        })
        .collect()
}

#[test]
fn braking_distance_falls_as_friction_and_brake_torque_rise() {
    let cases = braking_sweep();
    let distance = |mu: f64, c: f64| {
        cases
            .iter()
            .find(|&&(m, k, _)| m == mu && k == c)
            .map(|&(.., d)| d)
            .unwrap()
    };
    for mu in [0.6, 0.8, 1.0] {
        // Brake-limited: 500 and 1000 N·m per wheel decelerate the 2.1 t car at 2.5 and
        // 5 m/s² (its `stop_distance_expected_m`, v0²/2a), below the grip μ·g (5.9 to
        // 9.8 m/s²), so the tyres roll and twice the torque doubles the brakes' deceleration:
        // the distance falls, but not to half, since the rolling resistance and the wheels'
        // damping decelerate the car by the same amount in both.
        let (d500, d1000) = (distance(mu, 500.0), distance(mu, 1000.0));
        assert!(
            d1000 < d500 && d1000 > 0.5 * d500,
            "μ {mu}: {d500} m, {d1000} m"
        );
        // 3000 N·m (15 m/s² of torque) locks the wheels at any of these frictions: the stop is
        // grip-limited, shorter than at 500 N·m. (Not always shorter than at 1000 N·m: a
        // locked tyre slides with less friction than its peak, and Webots' cars have no ABS;
        // on μ 0.6 the locked car stops in 95 m, the rolling one in 70 m.)
        assert!(distance(mu, 3000.0) < d500);
    }
    // Where the brakes limit, the friction does not matter: the three distances at 500 N·m
    // agree within 1 % (the tyres' slip under 2.5 m/s² is a small part of the grip at every
    // friction).
    let d: Vec<f64> = [0.6, 0.8, 1.0].map(|mu| distance(mu, 500.0)).to_vec();
    assert!((d[0] - d[2]).abs() < 0.01 * d[2], "{d:?}");
    // Where the grip limits (wheels locked at 3000 N·m), the deceleration is the tyres'
    // sliding friction, proportional to the ground's: the distance falls as it rises.
    let locked: Vec<f64> = [0.6, 0.8, 1.0].map(|mu| distance(mu, 3000.0)).to_vec();
    assert!(locked[0] > locked[1] && locked[1] > locked[2], "{locked:?}");
}

#[test]
fn time_to_100_rises_with_mass() {
    // Full throttle through the automatic gearbox: the same engine torque at the wheels
    // accelerates a heavier car less (a = F/m, less the mass-proportional rolling
    // resistance), so it takes longer to reach 100 km/h.
    let sweep = parse(
        "world = \"BmwX5\"\nscenario = \"accel-torque\"\n[axes]\n\"vehicle.mass\" = [1800, 2400, 3000]\n",
    )
    .unwrap();
    // (While the driven wheels spin at the traction limit, μ·m·g, the acceleration does not
    // depend on the mass; the time still rises, by less than the mass, since the phases where
    // the engine limits scale with it.)
    let t: Vec<f64> = rows(&sweep)
        .iter()
        .map(|r| metric(&sweep, r, "time_0_100_s"))
        .collect();
    assert!(t[0] < t[1] && t[1] < t[2], "{t:?}");
}

#[test]
fn random_axes_are_the_same_on_any_shard_count() {
    let text = "world = \"BmwX5\"\nscenario = \"brake\"\ncombine = \"zip\"\n[axes]\n\
                \"vehicle.mass\" = { uniform = [1800, 2600], count = 50, seed = 42 }\n\
                \"ground.friction\" = { normal = [0.8, 0.05], count = 50, seed = 42 }\n";
    let sweep = parse(text).unwrap();
    assert_eq!(sweep.len(), 50);
    let whole: Vec<Vec<AxisValue>> = (0..50).map(|i| sweep.values(i).unwrap()).collect();
    for n in [2, 3, 7, 50] {
        // Each shard on its own (as a separate process would load the sweep), in its order.
        let mut got: Vec<(usize, Vec<AxisValue>)> = (0..n)
            .flat_map(|i| {
                let own = parse(text).unwrap();
                Shard::new(i, n)
                    .unwrap()
                    .cases(50)
                    .map(move |c| (c, own.values(c).unwrap()))
                    .collect::<Vec<_>>()
            })
            .collect();
        got.sort_by_key(|(c, _)| *c);
        let values: Vec<Vec<AxisValue>> = got.into_iter().map(|(_, v)| v).collect();
        assert_eq!(values, whole, "{n} shards");
    }
    // Case 7 backwards equals case 7 forwards: no draw depends on another.
    assert_eq!(sweep.values(7).unwrap(), whole[7]);
    // Same seed, other axes: independent streams (the key is part of the draw).
    let masses: Vec<f64> = whole.iter().map(|v| v[0].as_f64().unwrap()).collect();
    assert!(masses.iter().all(|m| (1800.0..2600.0).contains(m)));
    let frictions: Vec<f64> = whole.iter().map(|v| v[1].as_f64().unwrap()).collect();
    let mean = frictions.iter().sum::<f64>() / 50.0;
    // The mean of 50 draws of sd 0.05 is within 4 standard errors (0.028) of 0.8.
    assert!((mean - 0.8).abs() < 0.03, "{mean}");
    // Another seed, other values.
    let other = parse(&text.replace("seed = 42 }\n\"ground", "seed = 43 }\n\"ground")).unwrap();
    assert_ne!(other.values(0).unwrap()[0], whole[0][0]);
    assert_eq!(other.values(0).unwrap()[1], whole[0][1]);
}

#[test]
fn the_example_sweeps_load() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/sweeps");
    let brake = Sweep::load(dir.join("brake.toml")).unwrap();
    assert_eq!(brake.len(), 3 * 7 * 4);
    assert_eq!(
        brake.columns().axes,
        [
            "ground.friction",
            "vehicle.brakeCoefficient",
            "vehicle.mass"
        ]
    );
    let bench = Sweep::load(dir.join("brake-10000.toml")).unwrap();
    assert_eq!(bench.len(), 10_000);
    assert_eq!(Shard::new(0, 10).unwrap().len(bench.len()), 1000);
    let models = Sweep::load(dir.join("models.toml")).unwrap();
    assert_eq!(models.len(), 4 * 2 * 3);
    assert_eq!(
        models.color_by(),
        &sweep::ColorBy::Axis("vehicle.tyre".into())
    );
}

#[test]
fn color_by_names_an_axis_of_few_values() {
    let err = |text: &str| parse(text).err().map(|e| e.to_string());
    let axes = "[axes]\n\"ground.friction\" = [0.6, 0.8]\n\
                \"vehicle.brakeCoefficient\" = { from = 500, to = 2000, steps = 8 }\n";
    assert_eq!(
        err(&format!("color_by = \"ground.frction\"\n{axes}")).as_deref(),
        Some(
            "s.toml:1:1: invalid 'color_by': 'ground.frction' is not an axis of this sweep (its \
             axes: ground.friction, vehicle.brakeCoefficient; or \"none\")"
        )
    );
    assert_eq!(
        err(&format!("color_by = \"vehicle.brakeCoefficient\"\n{axes}")).as_deref(),
        Some(
            "s.toml:1:1: invalid 'color_by': 'vehicle.brakeCoefficient' has more than 7 \
             distinct values, one colour each"
        )
    );
    assert_eq!(
        err(&format!("color_by = 3\n{axes}")).as_deref(),
        Some("s.toml:1:1: 'color_by' takes a string, found an integer")
    );
    let off = parse(&format!("color_by = \"none\"\n{axes}")).unwrap();
    assert_eq!(off.color_by(), &sweep::ColorBy::Off);
    assert_eq!(parse(axes).unwrap().color_by(), &sweep::ColorBy::Auto);
}

#[test]
fn shards_record_the_colour_axis_and_the_merge_draws_with_it() {
    // Two models × two frictions, 1 s each: the model axis is categorical (a box and strip
    // per model), and every plot but its own is coloured by it.
    let sweep = parse(
        "world = \"ToyotaPrius\"\nscenario = \"accel-speed\"\ncolor_by = \"vehicle.model\"\n\
         [set]\nduration = 1\n[axes]\n\"ground.friction\" = [0.8, 1.0]\n\
         \"vehicle.model\" = [\"ToyotaPrius\", \"BmwX5\"]\n",
    )
    .unwrap();
    let dir = scratch("colour");
    let shards: Vec<PathBuf> = (0..2)
        .map(|i| {
            let d = dir.join(format!("shard-{i}"));
            write(&sweep, Shard::new(i, 2).unwrap(), 1, &d);
            d
        })
        .collect();
    let merged = dir.join("merged");
    sweep::merge(&shards, &merged).unwrap();
    let manifest = sweep::Manifest::read(&merged).unwrap();
    assert_eq!(manifest.color_by.as_deref(), Some("vehicle.model"));
    let friction = read(&merged.join("plots/ground.friction.svg"));
    // The legend: headed by the colour axis, each model once.
    assert!(
        friction.contains(">\nvehicle.model (lines:\n<"),
        "{friction}"
    );
    for model in ["ToyotaPrius", "BmwX5"] {
        assert_eq!(
            friction.matches(&format!(">\n{model}\n<")).count(),
            1,
            "{model}"
        );
    }
    // The model's own plot: a column per model, named once, uncoloured (the legend names
    // the cases and explains the boxes).
    let models = read(&merged.join("plots/vehicle.model.svg"));
    for text in ["ToyotaPrius", "BmwX5", "cases", "boxes: quartiles, median"] {
        assert_eq!(
            models.matches(&format!(">\n{text}\n<")).count(),
            1,
            "{text}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn axes_give_finite_values_inside_their_intervals() {
    // Issue #37: draws over [0.99999, 1) rounded to the excluded 1.0 (3 cases of 20, then
    // "must be in [-10, 1)"), and a range from −1e308 to 1e308 gave NaN and inf.
    let text = "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 0.05\n[axes]\n\
                \"vehicle.tyre.lateral.curvature\" = { uniform = [0.99999, 1.0], count = 20, \
                seed = 1 }\n";
    let sweep = parse(text).unwrap();
    for row in rows(&sweep) {
        let x = row.values[0].as_f64().unwrap();
        assert!((0.99999..1.0).contains(&x), "{x}");
        assert!(row.error.is_none(), "case {}: {:?}", row.case, row.error);
    }
    let text = "world = \"BmwX5\"\nscenario = \"brake\"\n[axes]\n\
                \"vehicle.mass\" = { from = -1e308, to = 1e308, steps = 5 }\n";
    let sweep = parse(text).unwrap();
    let values: Vec<f64> = (0..5)
        .map(|i| sweep.case(i).unwrap().values[0].as_f64().unwrap())
        .collect();
    assert_eq!(values, [-1e308, -5e307, 0.0, 5e307, 1e308]);
    // A normal draw that would overflow is the sweep file's error.
    let e = parse(
        "world = \"BmwX5\"\nscenario = \"brake\"\n[axes]\n\
         \"vehicle.mass\" = { normal = [0, 1e308], count = 2, seed = 1 }\n",
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "s.toml:4:20: invalid 'axes.vehicle.mass.normal': [0, 1e308]: the draws would overflow \
         (|mean| + 9 standard deviations must be finite)"
    );
}
