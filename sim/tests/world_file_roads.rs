//! `[[road]]`, `[[junction]]` and `road = "file.xodr"` in world files: what they build, and
//! the errors and warnings that name file, line and key.
#![allow(clippy::unwrap_used, clippy::panic)]

use sim::nalgebra::Point2;
use sim::road::{LaneKind, LineStyle};
use sim::world_file::{load, parse_str};

const ROAD: &str = r#"
[vehicle]
model = "BmwX5"

[[road]]
id = "main"
start = [10, 5]
startingAngle = 0.5
numberOfLanes = 3
numberOfForwardLanes = 2
laneWidths = [3.0, 3.5, 4.0]
laneFriction = [0.9, 1.0, 0.5]
rightBorder = true
[[road.line]]
type = "dashed"
color = [1, 1, 1]
[[road.line]]
type = "continuous"
color = [1, 0.8, 0]
[[road.segment]]
type = "straight"
length = 40
grade = 0.05
[[road.segment]]
type = "clothoid"
length = 20
curvatureStart = 0
curvatureEnd = 0.02
banking = -0.05
[[road.segment]]
type = "arc"
radius = 50
angle = -0.5
"#;

#[test]
fn a_road_has_its_segments_lanes_lines_and_profiles() {
    let w = parse_str("w.toml", ROAD).unwrap();
    let road = &w.config.roads.roads[0];
    assert_eq!(road.id, "main");
    assert!((road.length() - (40.0 + 20.0 + 25.0)).abs() < 1e-12);
    let start = road.plan_at(0.0);
    assert_eq!((start.point, start.heading), (Point2::new(10.0, 5.0), 0.5));
    // The arc turns right: curvature −1/50.
    assert!((road.plan_at(70.0).curvature + 0.02).abs() < 1e-15);
    let sec = &road.sections[0];
    // Right to left: lanes −2 (3 m), −1 (3.5 m), then 1 (4 m); a border right of −2.
    assert_eq!(
        sec.right.iter().map(|l| l.id).collect::<Vec<_>>(),
        [-1, -2, -3]
    );
    assert_eq!(sec.right[2].kind, LaneKind::Border);
    assert_eq!(sec.right[1].width.value(0.0), 3.0);
    assert_eq!(sec.left[0].width.value(0.0), 4.0);
    assert_eq!(road.friction_at(1.0, 1.0), 0.5);
    assert_eq!(road.friction_at(1.0, -4.0), 0.9);
    // The dashed line between the two forward lanes is lane −1's outer edge; the yellow
    // continuous one is the centre line.
    assert_eq!(sec.right[0].marks[0].style, LineStyle::Dashed);
    assert_eq!(sec.centre_marks[0].colour, [1.0, 0.8, 0.0]);
    // Grade 0 → 0.05 over 40 m: z = 0.05·s²/80; then 0.05 constant.
    assert!((road.elevation.value(40.0) - 1.0).abs() < 1e-12);
    assert!((road.elevation.value(50.0) - 1.5).abs() < 1e-12);
    // Banking ramps to −0.05 rad over the clothoid, then stays.
    assert!((road.superelevation.value(50.0) + 0.025).abs() < 1e-12);
    assert!((road.superelevation.value(80.0) + 0.05).abs() < 1e-12);
}

#[test]
fn the_shipped_city_loop_is_closed_and_its_cars_stand_on_it() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("worlds");
    let w = load(dir.join("city-loop.toml").to_str().unwrap()).unwrap();
    let road = &w.config.roads.roads[0];
    let (a, b) = (road.plan_at(0.0), road.plan_at(road.length()));
    assert!((a.point - b.point).norm() < 1e-9);
    let (mut sim, _) = sim::Simulation::from_description(&w).unwrap();
    for _ in 0..300 {
        sim.step().unwrap();
    }
    // Two cars in the right lane, one in the left lane, two parked off the road; none has
    // moved out of its place in 3 s without its programme.
    let lanes = [Some(-1), Some(-1), Some(1), None, None];
    assert_eq!(sim.world().vehicles().len(), lanes.len());
    for (v, lane) in sim.world().vehicles().iter().zip(lanes) {
        let p = v.state().position;
        let at = road.locate(&Point2::new(p.x, p.y));
        assert_eq!(at.map(|a| a.lane), lane);
    }
}

fn error(text: &str) -> String {
    parse_str("w.toml", text).unwrap_err().to_string()
}

#[test]
fn bad_roads_name_file_line_and_key() {
    let bad_type = ROAD.replace("type = \"clothoid\"", "type = \"spiral\"");
    assert!(error(&bad_type).starts_with("w.toml:25:1: unknown road segment type 'spiral'; did you mean 'straight', 'arc' or 'clothoid'?"), "{}", error(&bad_type));
    let bad_radius = ROAD.replace("radius = 50", "radius = -50");
    assert!(
        error(&bad_radius).contains("'road[1].segment[3].radius': -50: must be > 0"),
        "{}",
        error(&bad_radius)
    );
    let bad_width = ROAD.replace("[3.0, 3.5, 4.0]", "[3.0, 35, 4.0]");
    assert!(
        error(&bad_width)
            .contains("'road[1].laneWidths': 35 m: each lane must be from 0.5 to 20 m wide"),
        "{}",
        error(&bad_width)
    );
    let no_id = ROAD.replace("id = \"main\"\n", "");
    assert!(error(&no_id).contains("'road[1].id'"), "{}", error(&no_id));
    let open = ROAD.replace("rightBorder = true", "rightBorder = true\nclosed = true");
    assert!(
        error(&open).contains("a closed road must end within 0.01 m"),
        "{}",
        error(&open)
    );
    let misspelt = ROAD.replace("laneFriction", "laneFrictions");
    assert!(
        error(&misspelt).contains("did you mean 'laneFriction'"),
        "{}",
        error(&misspelt)
    );
    let steep = ROAD.replace("grade = 0.05", "grade = 3");
    assert!(
        error(&steep).contains("'road[1].segment[1].grade': 3: must be within ±1"),
        "{}",
        error(&steep)
    );
    let lines = ROAD.replace("[[road.line]]\ntype = \"dashed\"\ncolor = [1, 1, 1]\n", "");
    assert!(
        error(&lines).contains("1 lines: a road of 3 lanes has 2 lines"),
        "{}",
        error(&lines)
    );
}

#[test]
fn two_roads_meet_at_a_junction() {
    let text = r#"
[vehicle]
model = "BmwX5"
[[road]]
id = "a"
successor = "b"
[[road.segment]]
type = "straight"
length = 50
[[road]]
id = "b"
start = [50, 0]
predecessor = "a"
[[road.segment]]
type = "arc"
radius = 30
angle = 1.0
[[junction]]
id = "j"
[[junction.connection]]
incoming = "a"
connecting = "b"
contactPoint = "start"
"#;
    let w = parse_str("w.toml", text).unwrap();
    assert_eq!(w.config.roads.junctions[0].connections[0].connecting, "b");
    let gap = text.replace("start = [50, 0]", "start = [51, 0]");
    let e = error(&gap);
    assert!(
        e.starts_with("w.toml:6:1: invalid 'road[1].successor'")
            && e.contains("1.000 m from the start of road 'b'"),
        "{e}"
    );
    let unknown = text.replace("connecting = \"b\"", "connecting = \"c\"");
    assert!(
        error(&unknown)
            .contains("'junction[1].connection[1].connecting': \"c\": no road has this id")
    );
}

#[test]
fn an_opendrive_file_is_read_relative_to_the_world_file() {
    let dir = std::env::temp_dir().join(format!("roads-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("maps")).unwrap();
    let xodr = r#"<OpenDRIVE><header revMajor="1" revMinor="5"/>
<road id="r" length="100"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
<lanes><laneSection s="0"><right><lane id="-1"><width sOffset="0" a="3.5"/></lane></right></laneSection></lanes>
<signals/></road></OpenDRIVE>"#;
    std::fs::write(dir.join("maps/r.xodr"), xodr).unwrap();
    let world = dir.join("w.toml");
    std::fs::write(
        &world,
        "road = \"maps/r.xodr\"\n[vehicle]\nmodel = \"BmwX5\"\n",
    )
    .unwrap();
    let w = load(world.to_str().unwrap()).unwrap();
    assert_eq!(w.config.roads.roads[0].id, "r");
    let warning = w.warnings[0].to_string();
    assert!(
        warning.contains("r.xodr:4: unsupported OpenDRIVE record <road/signals>"),
        "{warning}"
    );
    std::fs::write(dir.join("maps/r.xodr"), &xodr[..60]).unwrap();
    let e = load(world.to_str().unwrap()).unwrap_err().to_string();
    assert!(
        e.contains("w.toml:1:1: invalid 'road'") && e.contains("not well-formed XML"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_replay_shows_the_road_and_its_lines() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("worlds");
    let w = load(dir.join("city-loop.toml").to_str().unwrap()).unwrap();
    let (mut sim, _) = sim::Simulation::from_description(&w).unwrap();
    sim.record("programme");
    for _ in 0..10 {
        sim.step().unwrap();
    }
    let out = std::env::temp_dir().join(format!("roads-replay-{}", std::process::id()));
    sim.save("city-loop", &[], &out).unwrap();
    let glb = std::fs::read(out.join("replay.glb")).unwrap();
    let doc = gltf::Gltf::from_slice(&glb).unwrap();
    let names: Vec<&str> = doc.nodes().filter_map(|n| n.name()).collect();
    // The two lanes and two borders of the one section, and the line's two strands, dashed
    // into no pieces (a double continuous line).
    for n in [
        "road_loop",
        "road_loop_section_1_lane_-1",
        "road_loop_section_1_lane_1",
        "road_loop_section_1_lane_-2",
        "road_loop_line_0",
        "road_loop_line_1",
    ] {
        assert!(names.contains(&n), "{n}: {names:?}");
    }
    assert!(!names.contains(&"road_loop_line_2"));
    // The line's colour is its paint's.
    let paint = doc
        .materials()
        .find(|m| m.name() == Some("paint_0"))
        .unwrap();
    assert_eq!(
        paint.pbr_metallic_roughness().base_color_factor()[..3],
        [1.0, 0.8, 0.0]
    );
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn the_trajectory_plot_has_the_road_edges_and_lane_lines() {
    use sim::report::{Outline, OutlineKind};
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("worlds");
    let w = load(dir.join("city-loop.toml").to_str().unwrap()).unwrap();
    let outlines = Outline::of_world(&w.config);
    let kinds: Vec<OutlineKind> = outlines.iter().map(|o| o.kind).collect();
    // The centre line, then on each side the line between the lane and its border and the
    // border's outer edge.
    use OutlineKind::{LaneLine, RoadEdge};
    assert_eq!(kinds, [LaneLine, LaneLine, RoadEdge, LaneLine, RoadEdge]);
    let road = &w.config.roads.roads[0];
    // The right edge starts 3.5 + 0.8 m right of the reference line's start.
    assert_eq!(outlines[4].points[0], [0.0, -4.3]);
    let last = outlines[4].points.last().unwrap();
    let end = road.surface_point(road.length(), -4.3);
    assert!((last[0] - end.x).abs() < 1e-9 && (last[1] - end.y).abs() < 1e-9);
}

#[test]
fn the_shipped_hilly_road_and_highway_load_and_their_cars_stand_on_their_lanes() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("worlds");
    for (world, lanes) in [
        ("hilly-road.toml", vec![-1]),
        ("highway.toml", vec![-3, -3, -1]),
    ] {
        let w = load(dir.join(world).to_str().unwrap()).unwrap();
        assert!(w.warnings.is_empty(), "{world}: {:?}", w.warnings);
        let (mut sim, _) = sim::Simulation::from_description(&w).unwrap();
        for _ in 0..200 {
            sim.step().unwrap();
        }
        let road = &w.config.roads.roads[0];
        for (v, lane) in sim.world().vehicles().iter().zip(lanes) {
            let p = v.state().position;
            let at = road.locate(&Point2::new(p.x, p.y)).unwrap();
            assert_eq!(at.lane, lane, "{world}");
            // The car origin (wheel-centre height) stands one wheel radius or so above the
            // road's surface, not on the ground under it: between 0.2 and 0.6 m.
            let above = p.z - road.surface_point(at.s, at.t).z;
            assert!((0.2..0.6).contains(&above), "{world}: {above}");
        }
    }
    let hill = load(dir.join("hilly-road.toml").to_str().unwrap()).unwrap();
    let road = &hill.config.roads.roads[0];
    // The curve is banked by −0.1 rad and the crest is 8 m up.
    assert!((road.superelevation.value(200.0) + 0.1).abs() < 1e-12);
    assert!((road.elevation.value(200.0) - 8.0).abs() < 1e-12);
}
