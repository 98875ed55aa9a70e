//! The rotating lidar (spec §8): its head turns `−2π·frequency·dt` per step, only the columns
//! swept in a step are rewritten, it refreshes at every step whatever its period, and column
//! `j` looks along azimuth `−π − j·2π/hres`. A fixed lidar of 360° turned by half a column
//! looks along the same azimuths: after a full turn both images are the same.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::f64::consts::{PI, TAU};

use sim::devices::{LidarReading, Reading};
use sim::{Simulation, VehicleId, world_file};

/// 360 columns: one per degree.
const HRES: u32 = 360;

fn image(sim: &Simulation, id: VehicleId, name: &str) -> LidarReading {
    let d = sim.devices(id).unwrap();
    match d.iter().find(|d| d.name() == name).unwrap().reading() {
        Reading::Lidar(r) => r.clone(),
        other => panic!("{name}: {other:?}"),
    }
}

/// A parked car with a rotating lidar (10 Hz: 36° per 10 ms step) and a fixed 360° lidar
/// turned by half a column, both 1 m above the car's origin, a 1 × 1 × 2 m box at bearing 45°
/// (centre (5, 5, 1)) and a wall 12 m behind. The car settles for 3 s before the lidars are
/// enabled, so that both see the scene from the same pose.
fn scene() -> (Simulation, VehicleId) {
    let half_column = PI / f64::from(HRES);
    let text = format!(
        "[vehicle]\nmodel = \"BmwX5\"\n\
         [[vehicle.device]]\ntype = \"Lidar\"\nname = \"rotating\"\nsensorType = \"rotating\"\n\
         horizontalResolution = {HRES}\nfieldOfView = {TAU}\nnumberOfLayers = 1\nmaxRange = 20\n\
         translation = [0, 0, 1]\n\
         [[vehicle.device]]\ntype = \"Lidar\"\nname = \"fixed\"\n\
         horizontalResolution = {HRES}\nfieldOfView = {TAU}\nnumberOfLayers = 1\nmaxRange = 20\n\
         translation = [0, 0, 1]\nrotation = [0, 0, 1, {half_column}]\n\
         [[box]]\ntranslation = [5, 5, 1]\nsize = [1, 1, 2]\n\
         [[box]]\ntranslation = [-12.5, 0, 2]\nsize = [1, 30, 4]\n"
    );
    let description = world_file::parse_str("rotating.toml", &text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    for _ in 0..300 {
        sim.step().unwrap();
    }
    // A period of 100 ms: the rotating lidar still refreshes at every 10 ms step.
    sim.enable_device(id, 0, 100).unwrap();
    sim.enable_device(id, 1, 10).unwrap();
    (sim, id)
}

/// The clockwise angle (deg, in (0, 360]) from azimuth 0 to column `j`: `−θ_j mod 360` with
/// `θ_j = −180 − j` (deg); the column at the head's start is swept at the end of a turn.
fn clockwise(j: u32) -> u32 {
    (180 + j - 1) % 360 + 1
}

#[test]
fn the_head_rewrites_the_columns_it_sweeps() {
    let (mut sim, id) = scene();
    // The fixed lidar's image at each step: a column of the rotating one holds the value of
    // the step that swept it, cast from the pose of that step.
    let mut fixed = Vec::new();
    for k in 1..=12u32 {
        sim.step().unwrap();
        fixed.push(image(&sim, id, "fixed").range_image);
        let rotating = image(&sim, id, "rotating");
        // Sampled at this step, the head 36°·k clockwise.
        assert_eq!(rotating.time, sim.world().time());
        let turned = f64::from(36 * k % 360).to_radians();
        assert!(
            (rotating.head - turned).abs() < 1e-9,
            "{k}: {}",
            rotating.head
        );
        for j in 0..HRES {
            let got = rotating.range_image[j as usize];
            // The last step whose sweep reached the column: step s sweeps (36(s−1), 36s].
            let c = clockwise(j);
            let expected = if c <= 36 * k {
                let first = c.div_ceil(36);
                let last = first + (k - first) / 10 * 10;
                fixed[last as usize - 1][j as usize]
            } else {
                f32::INFINITY
            };
            // Tolerance: the same rays cast in f32 from the same pose.
            assert!(
                got == expected || (got - expected).abs() < 1e-4,
                "step {k} column {j}: {got} vs {expected}"
            );
        }
    }
}

#[test]
fn a_box_at_45_degrees_appears_at_the_ninth_step() {
    // Column 135 looks along −180° − 135° ≡ 45°: 315° clockwise from the head's start, swept
    // in the ninth 36° step (288° → 324°), not before.
    let (mut sim, id) = scene();
    for _ in 0..8 {
        sim.step().unwrap();
    }
    assert_eq!(image(&sim, id, "rotating").range_image[135], f32::INFINITY);
    sim.step().unwrap();
    let r = f64::from(image(&sim, id, "rotating").range_image[135]);
    // The box's near corner region: between the distance to its centre (7.07 m) less its
    // half diagonal (0.71 m) and the centre itself.
    assert!((6.3..7.08).contains(&r), "{r}");
    // Its point lies along 45°.
    sim.enable_point_cloud(id, 0, true).unwrap();
    let cloud = sim.devices(id).unwrap()[0].point_cloud().unwrap();
    let p = cloud[135];
    let azimuth = f64::from(p.y).atan2(f64::from(p.x));
    // Tolerance: f32 coordinates.
    assert!((azimuth - PI / 4.0).abs() < 1e-5, "{azimuth}");
}

#[test]
fn a_full_turn_is_the_fixed_image() {
    let (mut sim, id) = scene();
    for _ in 0..10 {
        sim.step().unwrap();
    }
    let rotating = image(&sim, id, "rotating").range_image;
    let fixed = image(&sim, id, "fixed").range_image;
    let mut finite = 0;
    for (j, (r, f)) in rotating.iter().zip(&fixed).enumerate() {
        // Tolerance: f32 ray casts, 1e-5 m at 12 m.
        assert!(r == f || (r - f).abs() < 1e-4, "column {j}: {r} vs {f}");
        finite += usize::from(r.is_finite());
    }
    // The box and the wall behind: some columns see something, not all.
    assert!(finite > 20 && finite < 200, "{finite}");
}

#[test]
fn rotating_fields_are_read_and_checked() {
    let head = "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.device]]\ntype = \"Lidar\"\n";
    let e = world_file::parse_str("w.toml", &format!("{head}sensorType = \"spinning\"\n"))
        .expect_err("an unknown type is refused");
    assert_eq!(e.key.as_deref(), Some("vehicle.device[1].sensorType"));
    assert!(e.to_string().contains("rotating"), "{e}");
    let e = world_file::parse_str(
        "w.toml",
        &format!("{head}sensorType = \"rotating\"\nrotatingHead = \"head\"\n"),
    )
    .expect_err("rotatingHead is refused");
    assert_eq!(e.key.as_deref(), Some("vehicle.device[1].rotatingHead"));
}
