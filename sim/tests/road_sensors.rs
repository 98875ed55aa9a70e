//! The sensors see the road: a camera looking down at a road sees its asphalt and its painted
//! lines in their colours at the pixels the pinhole model predicts, a lidar tilted down on a
//! grade reads the range to the road's plane, and a lidar sees a box beside the road.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::devices::{Device, Reading};
use sim::nalgebra::{Isometry3, Point3, Translation3, Vector3};
use sim::{Simulation, VehicleId, world_file};

/// The simulation of world `text` and its one car.
fn world(text: &str) -> (Simulation, VehicleId) {
    let description = world_file::parse_str("road_sensors.toml", text).unwrap();
    let (sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    (sim, id)
}

/// Enables every device of `id` every `period_ms`, holds the car on its brakes and steps
/// until their first sample.
fn first_sample(sim: &mut Simulation, id: VehicleId, period_ms: u32) {
    for i in 0..sim.devices(id).unwrap().len() {
        sim.enable_device(id, i, period_ms).unwrap();
    }
    sim.driver_mut(id).unwrap().set_brake_intensity(1.0);
    let steps = period_ms / sim.world().config().basic_time_step_ms;
    for _ in 0..steps {
        sim.step().unwrap();
    }
}

/// Device `i` of car `id` and its world pose now (device frame → world).
fn device(sim: &Simulation, id: VehicleId, i: usize) -> (&Device, Isometry3<f64>) {
    let s = sim.world().vehicle(id).unwrap().state();
    let car = Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation);
    let d = &sim.devices(id).unwrap()[i];
    (d, car * d.mount())
}

/// A colour (0 to 1) as the camera's bytes for an upward face (lit fully: `raster::shade`).
fn bytes(c: [f64; 3]) -> [u8; 3] {
    c.map(|c| (c * 255.0).round() as u8)
}

/// Three lanes of 3.5 m (two forward, right of the reference line, one back), a dashed white
/// line between the forward lanes (t = −3.5 m) and a continuous yellow one on the reference
/// line (t = 0); a BmwX5 in the right-hand forward lane with a camera 5 m ahead of it, about
/// 4 m above the road, looking straight down (turned +π/2 about y: its x axis down, its z
/// axis, the image's up, forward).
const LINES: &str = r#"
[[road]]
id = "lines"
numberOfLanes = 3
numberOfForwardLanes = 2
laneWidths = [3.5, 3.5, 3.5]
[[road.line]]
type = "dashed"
color = [1, 1, 1]
[[road.line]]
type = "continuous"
color = [0.85, 0.75, 0.3]
[[road.segment]]
type = "straight"
length = 100

[[vehicle]]
model = "BmwX5"
translation = [10, -1.75, 0]
[[vehicle.device]]
type = "Camera"
translation = [5, 0, 3.5]
rotation = [0, 1, 0, 1.5707963267948966]
width = 128
height = 64
fieldOfView = 1.0
"#;

#[test]
fn a_camera_looking_down_sees_the_asphalt_and_the_lines_where_the_pinhole_puts_them() {
    let (mut sim, id) = world(LINES);
    first_sample(&mut sim, id, 50);
    let (d, pose) = device(&sim, id, 0);
    let image = d.camera().unwrap().image();
    let (w, h, fov) = (128.0, 64.0, 1.0_f64);
    let f = w / 2.0 / (fov / 2.0).tan();
    let (white, yellow) = (bytes([1.0; 3]), bytes([0.85, 0.75, 0.3]));
    let asphalt = bytes(sim::appearance::ASPHALT_COLOR);
    // A line is 0.15 m wide (the default): half 0.075 m. Pixels whose centre's ground point is
    // within 5 mm of a line's edge or a dash's end are left out: the paint lies 6 mm above
    // z = 0, where the ground point is computed, which moves it by < 4 mm at these angles.
    let m = 0.005;
    let (mut n_white, mut n_yellow, mut n_asphalt) = (0, 0, 0);
    for j in 0..64 {
        for i in 0..128 {
            let (u, v) = (i as f64 + 0.5, j as f64 + 0.5);
            // The pinhole inverted: u = w/2 − f·y/x, v = h/2 − f·z/x.
            let dir = pose.rotation * Vector3::new(1.0, (w / 2.0 - u) / f, (h / 2.0 - v) / f);
            let o = pose.translation.vector;
            let g = Point3::from(o + dir * (-o.z / dir.z));
            let k = 4 * (j * 128 + i);
            let px = [image[k + 2], image[k + 1], image[k]];
            let expected = if g.y.abs() < 0.075 - m {
                Some(yellow)
            } else if (g.y + 3.5).abs() < 0.075 - m && g.x > 12.0 + m && g.x < 15.0 - m {
                // The dashes: 3 m painted from s = 0, 9 m unpainted: [12, 15) is the second.
                Some(white)
            } else if (g.y.abs() > 0.075 + m && (g.y + 3.5).abs() > 0.075 + m)
                || (g.x > 15.0 + m && g.x < 24.0 - m)
            {
                Some(asphalt)
            } else {
                None
            };
            match expected {
                Some(e) => assert_eq!(px, e, "pixel ({i}, {j}) over ({:.3}, {:.3})", g.x, g.y),
                None => continue,
            }
            n_white += usize::from(expected == Some(white));
            n_yellow += usize::from(expected == Some(yellow));
            n_asphalt += usize::from(expected == Some(asphalt));
        }
    }
    // The footprint is about 4.4 × 2.2 m at 3.4 cm a pixel: a 0.14 m wide line is 4 pixels
    // across, the yellow one about 64 long, the dash's end inside the image.
    assert!(n_yellow > 150, "{n_yellow}");
    assert!(n_white > 60, "{n_white}");
    assert!(n_asphalt > 6000, "{n_asphalt}");
}

/// The single ray (m) of a one-layer, one-column lidar: its range image's only value.
fn range(d: &Device) -> f64 {
    match d.reading() {
        Reading::Lidar(r) => f64::from(r.range_image[0]),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_lidar_tilted_down_on_a_grade_reads_the_range_to_the_road() {
    // A 10 % grade from x = 20 m (reached along a first 20 m whose grade grows from 0: z(20) =
    // 0.1·20/2 = 1 m), a braked car on it at x = 40 m, and a lidar of one ray (one layer,
    // one column straight ahead) tilted 0.3 rad down, 1.5 m above the car's origin.
    let text = r#"
[[road]]
id = "climb"
numberOfLanes = 2
laneWidths = [3.5, 3.5]
[[road.segment]]
type = "straight"
length = 20
grade = 0.1
[[road.segment]]
type = "straight"
length = 100
grade = 0.1

[[vehicle]]
model = "BmwX5"
translation = [40, -1.75, 0]
[[vehicle.device]]
type = "Lidar"
translation = [2, 0, 1.5]
tiltAngle = -0.3
numberOfLayers = 1
horizontalResolution = 1
fieldOfView = 0.01
minRange = 0.1
maxRange = 30
"#;
    let (mut sim, id) = world(text);
    first_sample(&mut sim, id, 100);
    let (d, pose) = device(&sim, id, 0);
    // The ray in the device frame (azimuth 0, elevation −0.3), in world axes.
    let dir = pose.rotation * Vector3::new(0.3_f64.cos(), 0.0, -(0.3_f64.sin()));
    let o = pose.translation.vector;
    // The lane's plane: z = 1 + 0.1·(x − 20) + 1 mm (`sim::ROAD_LIFT`), flat across.
    let expected = (1.0 + 0.1 * (o.x - 20.0) + sim::ROAD_LIFT - o.z) / (dir.z - 0.1 * dir.x);
    let r = range(d);
    // f32 in rapier (vertices at ~10 m, the ray's time of impact) and in the image: 1e-4 m.
    assert!((r - expected).abs() < 1e-4, "{r} vs {expected}");
    // The hit is on the grade, well past its start, and nearer than the flat ground would be.
    assert!(o.x + r * dir.x > 25.0, "{}", o.x + r * dir.x);
    assert!(r < -o.z / dir.z);
}

#[test]
fn a_lidar_sees_a_box_beside_the_road() {
    // A flat two-lane road (t from −3.5 to 3.5 m), a 1 m box beside it (its near face at
    // y = 5.5 m) and a lidar of one horizontal ray turned to the left (+π/2 about z), 0.5 m
    // above the ground.
    let text = r#"
[[road]]
id = "flat"
numberOfLanes = 2
laneWidths = [3.5, 3.5]
[[road.segment]]
type = "straight"
length = 100

[[box]]
translation = [40, 6, 0.5]
size = [1, 1, 1]

[[vehicle]]
model = "BmwX5"
translation = [40, -1.75, 0]
[[vehicle.device]]
type = "Lidar"
translation = [0, 0, 0.2]
rotation = [0, 0, 1, 1.5707963267948966]
numberOfLayers = 1
horizontalResolution = 1
fieldOfView = 0.01
minRange = 0.1
maxRange = 30
"#;
    let (mut sim, id) = world(text);
    first_sample(&mut sim, id, 100);
    let (d, pose) = device(&sim, id, 0);
    let dir = pose.rotation * Vector3::x();
    let o = pose.translation.vector;
    assert!(
        (o.z - 0.5).abs() < 0.4,
        "the ray meets the box's face: {}",
        o.z
    );
    let expected = (5.5 - o.y) / dir.y;
    let r = range(d);
    // f32 in rapier and in the image: 1e-4 m.
    assert!((r - expected).abs() < 1e-4, "{r} vs {expected}");
}
