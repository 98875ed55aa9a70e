//! `report.html`: every run that writes files writes it (the CLI's `write_outputs` and a
//! recorded `Simulation`'s `save`, which controller runs use under `VEHICLE_OUT`), with the
//! run's own `replay.glb` embedded, the telemetry thinned to its cap, each car's colour and
//! the plots inline.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};

use base64::Engine as _;
use sim::report::{MAX_PAGE_ROWS, PAGE_COLUMNS, REPORT_HTML};
use sim::scenario::{self, Scenario};
use sim::world_file::{self, WorldDescription};
use sim::{Simulation, replay};

fn world(name: &str) -> WorldDescription {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("worlds")
        .join(name);
    world_file::load_file(&path).unwrap()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sim-report-page-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The text of the element `<script ... id="{id}">` of `html`.
fn script<'a>(html: &'a str, id: &str) -> &'a str {
    let open = html
        .find(&format!("id=\"{id}\">"))
        .unwrap_or_else(|| panic!("no script {id}"));
    let start = open + id.len() + 6;
    let end = start + html[start..].find("</script>").unwrap();
    &html[start..end]
}

/// The page of `dir` next to its replay: the embedded glb decodes to `replay.glb` byte for
/// byte; returns the page's data.
fn check_page(dir: &Path) -> (String, serde_json::Value) {
    let html = std::fs::read_to_string(dir.join(REPORT_HTML)).unwrap();
    let glb = base64::engine::general_purpose::STANDARD
        .decode(script(&html, "replay-glb"))
        .unwrap();
    assert_eq!(glb, std::fs::read(dir.join("replay.glb")).unwrap());
    let data: serde_json::Value = serde_json::from_str(script(&html, "report-data")).unwrap();
    (html, data)
}

/// The glTF node names of a replay.
fn node_names(glb: &[u8]) -> Vec<String> {
    let doc = gltf::Gltf::from_slice(glb).unwrap();
    doc.nodes()
        .filter_map(|n| n.name().map(str::to_string))
        .collect()
}

#[test]
fn write_outputs_writes_the_page_with_the_replay_the_plots_and_the_cars() {
    let report = scenario::run(&world("two-cars.toml"), Scenario::Programme, &mut |_| {}).unwrap();
    let dir = temp_dir("cli");
    let written = sim::report::write_outputs(&report, &[], &dir).unwrap();
    assert_eq!(written.last(), Some(&dir.join(REPORT_HTML)));
    let (html, data) = check_page(&dir);

    // One car entry per car of the replay, its node there and its colour the replay's.
    let glb = std::fs::read(dir.join("replay.glb")).unwrap();
    let nodes = node_names(&glb);
    let cars = data["cars"].as_array().unwrap();
    assert_eq!(cars.len(), 2);
    for (i, car) in cars.iter().enumerate() {
        let node = car["node"].as_str().unwrap();
        assert!(nodes.iter().any(|n| n == node), "{node} not in {nodes:?}");
        let colour: Vec<f32> = car["colour"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c.as_f64().unwrap() as f32)
            .collect();
        assert_eq!(colour, replay::car_colour(i));
    }
    // The two cars have distinct colours, which the browser check tells apart.
    assert_ne!(replay::car_colour(0), replay::car_colour(1));

    // The telemetry: the programme's vehicles in the CSV's order, the page's columns, at most
    // the cap of rows each; the last row at the run's end (24 s, the world's duration).
    let series = data["series"].as_array().unwrap();
    let names: Vec<&str> = series.iter().map(|s| s["car"].as_str().unwrap()).collect();
    assert_eq!(names[..2], ["prius", "bmw"]);
    assert_eq!(
        data["columns"].as_array().unwrap().len(),
        PAGE_COLUMNS.len()
    );
    for s in series {
        let rows = s["rows"].as_array().unwrap();
        assert!(
            !rows.is_empty() && rows.len() <= MAX_PAGE_ROWS,
            "{}",
            rows.len()
        );
        let last = rows.last().unwrap()[0].as_f64().unwrap();
        assert!((last - 24.0).abs() < 1e-9, "{last}");
    }

    // Every plot the run wrote is inline, and the metrics table lists the run's metrics.
    let svgs = written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .count();
    assert!(svgs > 0);
    assert_eq!(html.matches("<figure><svg").count(), svgs);
    for m in &report.results[0].metrics {
        assert!(html.contains(m.label), "{} not in the table", m.label);
    }
    // The page is offline: no URL to fetch anything from.
    assert!(
        !html.contains("src=\"http"),
        "the page loads a script from the network"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn cars_named_like_the_scene_nodes_are_found_by_index() {
    // Cars named `world` and `ground`, as the scene's root and ground nodes are: a glTF
    // loader renames one of each pair (three.js appends `_1`), so the page gives the viewer
    // node indices.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("worlds/two-cars.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("name = \"prius\"", "name = \"world\"")
        .replace("name = \"bmw\"", "name = \"ground\"");
    let world = world_file::parse_str("clash.toml", &text).unwrap();
    let report = scenario::run(&world, Scenario::Programme, &mut |_| {}).unwrap();
    let dir = temp_dir("clash");
    sim::report::write_outputs(&report, &[], &dir).unwrap();
    let (_, data) = check_page(&dir);
    let glb = std::fs::read(dir.join("replay.glb")).unwrap();
    let doc = gltf::Gltf::from_slice(&glb).unwrap();
    let nodes: Vec<gltf::Node<'_>> = doc.nodes().collect();
    let cars = data["cars"].as_array().unwrap();
    for (car, name) in cars.iter().zip(["world", "ground"]) {
        assert_eq!(car["node"], name);
        let index = |key: &str| usize::try_from(car[key].as_u64().unwrap()).unwrap();
        let (root, body) = (&nodes[index("root")], index("body"));
        // Two nodes have the name: the car's root is the one holding the car's body (its
        // chassis mesh) and chase camera, not the scene's.
        assert_eq!(nodes.iter().filter(|n| n.name() == Some(name)).count(), 2);
        assert_eq!(root.name(), Some(name));
        assert!(root.children().any(|c| c.index() == body), "{name}");
        assert!(nodes[body].mesh().is_some());
        assert!(root.children().any(|c| c.camera().is_some()), "{name}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_saved_simulation_writes_the_page_too() {
    // What a controller run writes under VEHICLE_OUT.
    let (mut sim, _) = Simulation::from_description(&world("two-cars.toml")).unwrap();
    sim.record("run");
    for _ in 0..50 {
        sim.step().unwrap();
    }
    let dir = temp_dir("save");
    let written = sim.save("two-cars.toml", &[], &dir).unwrap();
    assert!(written.contains(&dir.join(REPORT_HTML)), "{written:?}");
    let (html, data) = check_page(&dir);
    assert_eq!(data["parts"][0], "run");
    assert_eq!(data["cars"].as_array().unwrap().len(), 2);
    // No plots without the application's plotters.
    assert!(!html.contains("<figure>"));
    let metrics = std::fs::read_to_string(dir.join("metrics.json")).unwrap();
    assert!(metrics.contains("\"report.html\""), "{metrics}");
    std::fs::remove_dir_all(&dir).unwrap();
}
