//! The radar overlay of `replay.glb` (opt-in: the world file's `replayOverlay = true`, or
//! [`Simulation::set_replay_overlay`]): every radar's targets drawn as small red boxes that
//! move with the keyframes, so a viewer shows what the radar saw beside what was there.
//!
//! Design. glTF animates nodes, not vertex data, so each radar gets a fixed pool of
//! [`MAX_TARGET_MARKERS`] marker nodes; at each keyframe marker k sits at target k of the
//! radar's last sample (step-interpolated translation: a sample is an instant, not a track) and
//! shows (scale 1) or hides (scale 0) whether that target exists. The file grows by 24 bytes
//! per marker and keyframe (a translation and a scale), at most 8 × 24 × 36,001 ≈ 7 MB per
//! radar for the longest recording ([`super::MAX_FRAMES`]), a few kB for a typical minute.
//! A radar reports more than eight targets only for a crowd of cars; the first eight in its
//! order are drawn. Lidars draw their returns as points ([`super::lidar_overlay`]).
//!
//! Where. A target at distance `d` (m) and azimuth `a` (rad, > 0 to the right) is at
//! `(d·cos a, −d·sin a, 0)` in the radar's frame (Webots gives no elevation: the target is
//! drawn in the radar's horizontal plane), placed in the world by the radar's pose at the
//! keyframe (the chassis' pose composed with the device's mount): the pose the radar had when
//! it sampled whenever the radar's period is a multiple of the keyframes'.

use proto_geom::export::{Animation, Interpolation, Keyframes, Material, Scene};
use proto_geom::nalgebra::{Isometry3, Point3, Translation3, Vector3};

use crate::devices::{DeviceKind, Reading};
use crate::simulation::Simulation;

use super::recorder::{Frame, Recording};

/// Markers per radar: targets beyond the eighth of a sample are not drawn.
pub const MAX_TARGET_MARKERS: usize = 8;

/// Edge of a marker box (m): visible from a car's length away, small beside a car.
const MARKER_SIZE: f64 = 0.4;

/// A radar whose targets the replay draws.
#[derive(Debug, Clone, PartialEq)]
pub struct OverlayRadar {
    /// Its car's index, in the simulation's order.
    pub car: usize,
    /// Its index in the car's devices.
    pub device: usize,
    /// `<car>/<device>`, naming its marker nodes.
    pub name: String,
}

/// Every radar of every car of `sim`, in car and device order.
pub(crate) fn radars(sim: &Simulation) -> Vec<OverlayRadar> {
    let mut out = Vec::new();
    for (car, id) in sim.car_ids().enumerate() {
        let name = sim.car_name(id).unwrap_or_default();
        for (device, d) in sim.devices(id).unwrap_or_default().iter().enumerate() {
            if d.kind() == DeviceKind::Radar {
                out.push(OverlayRadar {
                    car,
                    device,
                    name: format!("{name}/{}", d.name()),
                });
            }
        }
    }
    out
}

/// The world positions (m) of the targets of each of `radars` now, at most
/// [`MAX_TARGET_MARKERS`] each (none before a radar's first sample).
pub(crate) fn targets(sim: &Simulation, radars: &[OverlayRadar]) -> Vec<Vec<Point3<f64>>> {
    let ids: Vec<_> = sim.car_ids().collect();
    radars
        .iter()
        .map(|r| {
            let Some(&id) = ids.get(r.car) else {
                return Vec::new();
            };
            let (Ok(vehicle), Ok(devices)) = (sim.world().vehicle(id), sim.devices(id)) else {
                return Vec::new();
            };
            let Some(device) = devices.get(r.device) else {
                return Vec::new();
            };
            let Reading::Radar(Some(found)) = device.reading() else {
                return Vec::new();
            };
            let s = vehicle.state();
            let chassis =
                Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation);
            let pose = chassis * device.mount();
            found
                .iter()
                .take(MAX_TARGET_MARKERS)
                .map(|t| {
                    let (sin, cos) = t.azimuth.sin_cos();
                    pose * Point3::new(t.distance * cos, -t.distance * sin, 0.0)
                })
                .collect()
        })
        .collect()
}

/// The marker nodes of each radar of `recording` under node `world`: one pool of
/// [`MAX_TARGET_MARKERS`] per radar, named `<car>/<device> target <k>`.
pub(crate) fn add_markers(
    scene: &mut Scene,
    world: usize,
    recording: &Recording,
) -> Vec<Vec<usize>> {
    if recording.radars.is_empty() {
        return Vec::new();
    }
    let red =
        Material::new("radar target", [0.9, 0.1, 0.1], 0.6, 0.0).with_emissive([0.6, 0.0, 0.0]);
    let red = scene.add_material(red);
    let size = Vector3::repeat(MARKER_SIZE);
    let mesh = scene.add_mesh(
        "radar target",
        super::scene::box_mesh(Point3::origin(), size),
        red,
    );
    recording
        .radars
        .iter()
        .map(|r| {
            (0..MAX_TARGET_MARKERS)
                .map(|k| {
                    let name = format!("{} target {k}", r.name);
                    scene.add_node(Some(world), &name, Isometry3::identity(), Some(mesh))
                })
                .collect()
        })
        .collect()
}

/// The channels of the markers `nodes` over `frames` on timeline `t`: marker k of radar r at
/// target k of the frame (held where it was last while hidden), shown iff that target exists.
pub(crate) fn add_channels(a: &mut Animation, t: usize, frames: &[Frame], nodes: &[Vec<usize>]) {
    for (r, pool) in nodes.iter().enumerate() {
        for (k, &node) in pool.iter().enumerate() {
            let mut at = Point3::origin();
            let (mut translations, mut scales) = (Vec::new(), Vec::new());
            for f in frames {
                let target = f.radar_targets.get(r).and_then(|ts| ts.get(k));
                if let Some(p) = target {
                    at = *p;
                }
                translations.push([at.x as f32, at.y as f32, at.z as f32]);
                scales.push(if target.is_some() { [1.0; 3] } else { [0.0; 3] });
            }
            a.add_channel(
                node,
                t,
                Interpolation::Step,
                Keyframes::Translation(translations),
            );
            a.add_channel(node, t, Interpolation::Step, Keyframes::Scale(scales));
        }
    }
}
