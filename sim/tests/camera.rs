//! The camera against the pinhole model: a box of known colour and place covers the pixels
//! its projection predicts, an upward face shows its own colour, nothing behind the camera
//! (nor the camera's own car) appears, and Recognition reports the box where it is.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::devices::{CameraState, DeviceSettings};
use sim::nalgebra::{Isometry3, Point3, Translation3};
use sim::{Simulation, VehicleId, world_file};

/// The simulation of world `text` and its one car.
fn world(text: &str) -> (Simulation, VehicleId) {
    let description = world_file::parse_str("camera.toml", text).unwrap();
    let (sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    (sim, id)
}

/// Enables camera 0 of `id` (and its Recognition) every `period_ms` and steps until its first
/// image; returns the camera's world pose at that instant (camera frame → world).
fn first_image(sim: &mut Simulation, id: VehicleId, period_ms: u32) -> Isometry3<f64> {
    sim.enable_device(id, 0, period_ms).unwrap();
    if matches!(sim.devices(id).unwrap()[0].settings(), DeviceSettings::Camera(s) if s.recognition.is_some())
    {
        sim.enable_recognition(id, 0, period_ms).unwrap();
    }
    let steps = period_ms / sim.world().config().basic_time_step_ms;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let s = sim.world().vehicle(id).unwrap().state();
    let car = Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation);
    car * sim.devices(id).unwrap()[0].mount()
}

fn camera(sim: &Simulation, id: VehicleId) -> &CameraState {
    sim.devices(id).unwrap()[0].camera().unwrap()
}

/// The RGB of pixel (`i`, `j`) of a BGRA `image` `width` pixels wide.
fn rgb(image: &[u8], width: usize, i: usize, j: usize) -> [u8; 3] {
    let k = 4 * (j * width + i);
    [image[k + 2], image[k + 1], image[k]]
}

/// Where camera point `p` (x > 0) falls on the image (px): Webots' planar pinhole,
/// u = w/2 − f·y/x, v = h/2 − f·z/x with f = (w/2)/tan(fov/2).
fn pinhole(p: &Point3<f64>, width: f64, height: f64, fov: f64) -> [f64; 2] {
    let f = width / 2.0 / (fov / 2.0).tan();
    [width / 2.0 - f * p.y / p.x, height / 2.0 - f * p.z / p.x]
}

const BOX_AHEAD: &str = r#"
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Camera"
translation = [4.5, 0, 0.6]
width = 128
height = 64
fieldOfView = 1.0
recognition = { maxRange = 50 }

[[box]]
translation = [15, 0.5, 1.0]
size = [1, 2, 2]
color = [0.8, 0.2, 0.1]
recognitionColors = [[1, 0, 0]]

[[box]]
translation = [-10, 0, 1.0]
size = [1, 4, 2]
color = [0.0, 1.0, 1.0]
recognitionColors = [[0, 1, 1]]
"#;

#[test]
fn a_box_covers_the_pixels_the_pinhole_predicts() {
    let (mut sim, id) = world(BOX_AHEAD);
    let pose = first_image(&mut sim, id, 50);
    let (w, h, fov) = (128.0, 64.0, 1.0);
    // The box's face towards the camera: x = 14.5, y in [−0.5, 1.5], z in [0, 2] (world).
    let to_camera = pose.inverse();
    let corners: Vec<[f64; 2]> = [(-0.5, 0.0), (1.5, 0.0), (-0.5, 2.0), (1.5, 2.0)]
        .iter()
        .map(|&(y, z)| pinhole(&(to_camera * Point3::new(14.5, y, z)), w, h, fov))
        .collect();
    let lo_u = corners.iter().map(|c| c[0]).fold(f64::INFINITY, f64::min);
    let hi_u = corners.iter().map(|c| c[0]).fold(-f64::INFINITY, f64::max);
    let lo_v = corners.iter().map(|c| c[1]).fold(f64::INFINITY, f64::min);
    let hi_v = corners.iter().map(|c| c[1]).fold(-f64::INFINITY, f64::max);
    // A face turned away from the light is lit by the ambient half alone: 0.5 × colour.
    let face = [0.8, 0.2, 0.1].map(|c: f64| (c * 0.5 * 255.0).round() as u8);
    let image = camera(&sim, id).image();
    let (mut inside, mut outside) = (0, 0);
    for j in 0..64 {
        for i in 0..128 {
            let (u, v) = (i as f64 + 0.5, j as f64 + 0.5);
            // The car settles by millimetres: the face's projected edges are exact, but
            // the corners' projections are not a perfect rectangle when the camera has
            // a little pitch or roll; pixels within 0.5 px of an edge are left out.
            let margin = 0.5;
            let is_in =
                u > lo_u + margin && u < hi_u - margin && v > lo_v + margin && v < hi_v - margin;
            let is_out =
                u < lo_u - margin || u > hi_u + margin || v < lo_v - margin || v > hi_v + margin;
            let px = rgb(image, 128, i, j);
            if is_in {
                assert_eq!(px, face, "pixel ({i}, {j}) inside the box's projection");
                inside += 1;
            } else if is_out {
                assert_ne!(px, face, "pixel ({i}, {j}) outside the box's projection");
                outside += 1;
            }
        }
    }
    // About 17 × 17 px for 2 m at 10.5 m with f = 111 px.
    assert!(inside > 200, "{inside}");
    assert!(outside > 7000, "{outside}");
    // Nothing behind the camera: the cyan box 14.5 m behind it shows nowhere.
    assert!(image.chunks_exact(4).all(|p| p[..3] != [255, 255, 0]));
}

#[test]
fn recognition_reports_the_box_where_it_is() {
    let (mut sim, id) = world(BOX_AHEAD);
    let pose = first_image(&mut sim, id, 50);
    let objects = camera(&sim, id).objects();
    // The red box alone: the cyan one is behind the camera.
    assert_eq!(objects.len(), 1, "{objects:?}");
    let o = &objects[0];
    let expected = pose.inverse() * Point3::new(15.0, 0.5, 1.0);
    // Within 1 cm (the issue's bound); the render and the expectation share the pose, so
    // the difference is rounding (< 1e-9 m).
    assert!(
        (o.position - expected.coords).norm() < 0.01,
        "{:?} vs {expected}",
        o.position
    );
    assert!(
        (o.size[0] - 2.0).abs() < 0.05 && (o.size[1] - 2.0).abs() < 0.05,
        "{:?}",
        o.size
    );
    assert_eq!(o.colors, vec![[1.0, 0.0, 0.0]]);
    // The box's axes are the world's; the camera is level within the car's settling (mrad).
    assert!(o.orientation[3].abs() < 0.01, "{:?}", o.orientation);
    // Its image rectangle is the projection of its eight corners, widened to whole pixels
    // (so within 1 px at each edge).
    let projected: Vec<[f64; 2]> = (0..8)
        .map(|k| {
            let s = |bit: i32, half: f64| if k & bit == 0 { -half } else { half };
            let corner = Point3::new(15.0 + s(1, 0.5), 0.5 + s(2, 1.0), 1.0 + s(4, 1.0));
            pinhole(&(pose.inverse() * corner), 128.0, 64.0, 1.0)
        })
        .collect();
    let span = |axis: usize| {
        let lo = projected
            .iter()
            .map(|p| p[axis])
            .fold(f64::INFINITY, f64::min);
        let hi = projected
            .iter()
            .map(|p| p[axis])
            .fold(-f64::INFINITY, f64::max);
        (lo, hi)
    };
    let ((u0, u1), (v0, v1)) = (span(0), span(1));
    let [cu, cv] = o.position_on_image.map(f64::from);
    let [sw, sh] = o.size_on_image.map(f64::from);
    assert!(
        (sw - (u1 - u0)).abs() <= 2.0 && (sh - (v1 - v0)).abs() <= 2.0,
        "{sw} × {sh}"
    );
    assert!((cu - (u0 + u1) / 2.0).abs() <= 1.0 && (cv - (v0 + v1) / 2.0).abs() <= 1.0);
}

#[test]
fn an_upward_face_shows_its_own_colour() {
    // A camera 3 m up, pitched 90° down, over a wide flat box top of a given colour.
    let (mut sim, id) = world(
        r#"
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Camera"
translation = [1.5, 0, 3.0]
rotation = [0, 1, 0, 1.5707963]
width = 32
height = 32

[[box]]
translation = [1.5, 0, 0.05]
size = [20, 20, 0.1]
color = [0.2, 0.6, 0.9]
"#,
    );
    first_image(&mut sim, id, 20);
    let image = camera(&sim, id).image();
    let colour = [0.2, 0.6, 0.9].map(|c: f64| c * 255.0);
    let mut seen = 0;
    for j in 0..32 {
        for i in 0..32 {
            let px = rgb(image, 32, i, j);
            // The car's own body (below the camera) is not drawn: every pixel is the top.
            for (p, c) in px.iter().zip(colour) {
                // ±5 per channel is the issue's bound; the render rounds once (±0.5).
                assert!((f64::from(*p) - c).abs() <= 5.0, "({i}, {j}): {px:?}");
            }
            seen += 1;
        }
    }
    assert_eq!(seen, 32 * 32);
}

#[test]
fn no_image_before_the_first_period_and_none_while_disabled() {
    let (mut sim, id) = world(BOX_AHEAD);
    sim.enable_device(id, 0, 30).unwrap();
    sim.step().unwrap();
    sim.step().unwrap();
    assert!(camera(&sim, id).image().iter().all(|&b| b == 0));
    sim.step().unwrap();
    assert!(camera(&sim, id).image().iter().any(|&b| b != 0));
    // Recognition was never enabled: no objects.
    assert!(camera(&sim, id).objects().is_empty());
    let before = camera(&sim, id).image().to_vec();
    sim.enable_device(id, 0, 0).unwrap();
    for _ in 0..5 {
        sim.step().unwrap();
    }
    assert_eq!(camera(&sim, id).image(), &before[..]);
}

#[test]
fn camera_fields_are_checked() {
    for (field, error) in [
        ("width = 0", "width"),
        ("width = 10.5", "width"),
        ("fieldOfView = 4", "fieldOfView"),
        ("near = 0", "near"),
        ("far = 0.001", "far"),
        ("noise = 2", "noise"),
        ("projection = \"spherical\"", "projection"),
        ("recognition = { occlusion = 3 }", "occlusion"),
        ("recognition = { maxRange = -1 }", "maxRange"),
        ("recognition = { foo = 1 }", "foo"),
    ] {
        let text = format!("[vehicle]\n[[vehicle.device]]\ntype = \"Camera\"\n{field}\n");
        let e = world_file::parse_str("camera.toml", &text)
            .unwrap_err()
            .to_string();
        assert!(e.contains(error), "{field}: {e}");
        assert!(e.contains("camera.toml"), "{field}: {e}");
    }
    let e = world_file::parse_str(
        "camera.toml",
        "[vehicle]\n[[box]]\ntranslation = [0, 0, 1]\nsize = [1, 1, 1]\ncolor = [2, 0, 0]\n",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("color"), "{e}");
}

/// A box hidden behind a nearer one, both with recognition colours, 30 m and 15 m ahead.
fn hidden_behind(occlusion: u8, max_objects: i32) -> String {
    format!(
        r#"
[vehicle]
model = "BmwX5"
[[vehicle.device]]
type = "Camera"
translation = [4.5, 0, 0.6]
width = 128
height = 64
fieldOfView = 1.0
recognition = {{ maxRange = 50, occlusion = {occlusion}, maxObjects = {max_objects} }}

[[box]]
translation = [15, 0, 1]
size = [1, 4, 3]
recognitionColors = [[1, 0, 0]]

[[box]]
translation = [30, 0, 1]
size = [1, 2, 2]
recognitionColors = [[0, 0, 1]]
"#
    )
}

#[test]
fn occlusion_hides_what_is_behind_and_max_objects_keeps_the_largest() {
    // The far box (2 m × 2 m at 25.5 m from the camera) lies wholly behind the near one
    // (4 m × 3 m at 10.5 m): with occlusion its centre's pixel shows the near box.
    let colours = |occlusion: u8, max_objects: i32| {
        let (mut sim, id) = world(&hidden_behind(occlusion, max_objects));
        first_image(&mut sim, id, 50);
        camera(&sim, id)
            .objects()
            .iter()
            .map(|o| o.colors[0])
            .collect::<Vec<_>>()
    };
    assert_eq!(colours(1, -1), vec![[1.0, 0.0, 0.0]]);
    assert_eq!(colours(2, -1), vec![[1.0, 0.0, 0.0]]);
    assert_eq!(colours(0, -1), vec![[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    // Without occlusion but one object at most: the larger on the image, the near box.
    assert_eq!(colours(0, 1), vec![[1.0, 0.0, 0.0]]);
    assert_eq!(colours(0, 0), Vec::<[f64; 3]>::new());
}

#[test]
fn a_saved_run_holds_the_last_image_of_each_camera_and_display() {
    let (mut sim, id) = world(&format!(
        "{BOX_AHEAD}\n[[vehicle.device]]\ntype = \"Display\"\nname = \"dash board\"\nwidth = 8\nheight = 4\n"
    ));
    sim.record("camera");
    first_image(&mut sim, id, 50);
    let dir = std::env::temp_dir().join(format!("sim-camera-save-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let written = sim.save("camera.toml", &[], &dir).unwrap();
    let car = sim.car_name(id).unwrap().to_string();
    let camera_png = dir.join(format!("{car}-camera.png"));
    let display_png = dir.join(format!("{car}-dash_board.png"));
    assert!(
        written.contains(&camera_png) && written.contains(&display_png),
        "{written:?}"
    );
    // The PNG holds the camera's BGRA image as RGBA.
    let saved = sim::devices::load_png(&camera_png).unwrap();
    let image = camera(&sim, id).image();
    assert_eq!((saved.width, saved.height), (128, 64));
    assert_eq!(saved.rgba()[..4], [image[2], image[1], image[0], image[3]]);
    // The display is untouched: opaque black.
    let display = sim::devices::load_png(&display_png).unwrap();
    assert!(display.pixels.iter().all(|&p| p == 0xFF00_0000));
    std::fs::remove_dir_all(&dir).unwrap();
}
