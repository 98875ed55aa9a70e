//! The lidar part of the replay overlay (opt-in, as the radar's: [`super::overlay`]): each
//! lidar's returns drawn as points, one glTF `POINTS` mesh per new sample kept at a keyframe,
//! shown from its keyframe until the lidar's next drawn sample (a step-interpolated scale
//! channel of three keys at most) and hidden before.
//!
//! Design. glTF animates nodes, not vertex data, so a changing cloud is a node per cloud. A
//! cloud is taken at a keyframe only when the lidar sampled since the last one taken (a
//! lidar slower than the keyframes is not drawn twice). Two caps bound the file and the
//! recording's memory: [`MAX_CLOUD_POINTS`] points per cloud (a VLP-16's 28,800 returns are
//! thinned to every 8th, a SICK LMS 291's 180 all kept) and [`MAX_OVERLAY_POINTS`] points in
//! all (12 MB of f32 positions, about the size of the rest of a 10-minute replay); past the
//! total cap, every other cloud goes and clouds are taken at half the rate from then on, as
//! the keyframes are thinned on a long run ([`super::MAX_FRAMES`]). A minute of a SICK
//! sampled at 10 Hz is 108,000 points (1.3 MB) and is kept whole.
//!
//! Where. A return of range `r` along the ray of layer `i`, column `j` is the lidar's point
//! cloud point ([`LidarReading::point_cloud`](crate::devices::LidarReading::point_cloud), in
//! the device's axes) placed in the world by the lidar's pose at the keyframe (the chassis'
//! pose composed with the device's mount), in f32; rays without a return (`+∞`) are left out.

use proto_geom::export::{Animation, Geometry, Interpolation, Keyframes, Material, Scene};
use proto_geom::nalgebra::{Isometry3, Point3, Translation3};

use crate::devices::{DeviceKind, DeviceSettings, Reading};
use crate::simulation::Simulation;

use super::recorder::{Frame, Recording};

/// The most points a cloud keeps: its returns thinned by a whole stride beyond it.
pub const MAX_CLOUD_POINTS: usize = 4096;

/// The most points all clouds of a recording keep together (12 bytes each in the file).
pub const MAX_OVERLAY_POINTS: usize = 1 << 20;

/// A lidar whose returns the replay draws.
#[derive(Debug, Clone, PartialEq)]
pub struct OverlayLidar {
    /// Its car's index, in the simulation's order.
    pub car: usize,
    /// Its index in the car's devices.
    pub device: usize,
    /// `<car>/<device>`, naming its cloud nodes.
    pub name: String,
}

/// Every lidar of every car of `sim`, in car and device order.
pub(crate) fn lidars(sim: &Simulation) -> Vec<OverlayLidar> {
    let mut out = Vec::new();
    for (car, id) in sim.car_ids().enumerate() {
        let name = sim.car_name(id).unwrap_or_default();
        for (device, d) in sim.devices(id).unwrap_or_default().iter().enumerate() {
            if d.kind() == DeviceKind::Lidar {
                out.push(OverlayLidar {
                    car,
                    device,
                    name: format!("{name}/{}", d.name()),
                });
            }
        }
    }
    out
}

/// What the recorder needs to keep the clouds within their caps.
#[derive(Debug, Clone)]
pub(crate) struct CloudBudget {
    /// A cloud is taken at every `every`-th keyframe (≥ 1).
    every: usize,
    /// Keyframes offered so far.
    offered: usize,
    /// Points held by the recording's frames (an upper bound once frames were thinned).
    points: usize,
    /// Per lidar, the time of the last sample taken (s); NaN before the first.
    last_sample: Vec<f64>,
}

impl CloudBudget {
    /// A budget for `lidars` lidars, nothing taken yet.
    pub(crate) fn new(lidars: usize) -> Self {
        CloudBudget {
            every: 1,
            offered: 0,
            points: 0,
            last_sample: vec![f64::NAN; lidars],
        }
    }

    /// The world positions (m, f32) of each of `lidars`' returns for a keyframe now: a
    /// lidar's new sample when this keyframe takes clouds, else an empty cloud.
    pub(crate) fn clouds(
        &mut self,
        sim: &Simulation,
        lidars: &[OverlayLidar],
    ) -> Vec<Vec<[f32; 3]>> {
        let due = self.offered.is_multiple_of(self.every);
        self.offered += 1;
        if !due {
            return Vec::new();
        }
        let ids: Vec<_> = sim.car_ids().collect();
        let clouds: Vec<Vec<[f32; 3]>> = lidars
            .iter()
            .zip(&mut self.last_sample)
            .map(|(l, last)| {
                let Some(&id) = ids.get(l.car) else {
                    return Vec::new();
                };
                let (Ok(vehicle), Ok(devices)) = (sim.world().vehicle(id), sim.devices(id)) else {
                    return Vec::new();
                };
                let Some(device) = devices.get(l.device) else {
                    return Vec::new();
                };
                let (Reading::Lidar(reading), DeviceSettings::Lidar(settings)) =
                    (device.reading(), device.settings())
                else {
                    return Vec::new();
                };
                // Before the first sample, or the sample already drawn.
                if reading.time.is_nan() || reading.time == *last {
                    return Vec::new();
                }
                *last = reading.time;
                let s = vehicle.state();
                let chassis =
                    Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation);
                world_points(
                    &(chassis * device.mount()),
                    &reading.point_cloud(settings, 0),
                )
            })
            .collect();
        self.points += clouds.iter().map(Vec::len).sum::<usize>();
        clouds
    }

    /// Keeps the clouds of `frames` within [`MAX_OVERLAY_POINTS`]: past it, the clouds of
    /// every other frame that holds some go, and clouds come half as often from now on.
    pub(crate) fn enforce(&mut self, frames: &mut [Frame]) {
        if self.points <= MAX_OVERLAY_POINTS {
            return;
        }
        self.points = held(frames);
        while self.points > MAX_OVERLAY_POINTS {
            let mut keep = true;
            for f in frames.iter_mut() {
                if f.lidar_points.iter().any(|c| !c.is_empty()) {
                    if !keep {
                        f.lidar_points.clear();
                    }
                    keep = !keep;
                }
            }
            let now = held(frames);
            self.every *= 2;
            if now == self.points {
                // One frame's clouds alone exceed the cap: nothing left to thin.
                break;
            }
            self.points = now;
        }
    }
}

/// Points held by `frames`.
fn held(frames: &[Frame]) -> usize {
    frames
        .iter()
        .flat_map(|f| &f.lidar_points)
        .map(Vec::len)
        .sum()
}

/// The returns of `cloud` (device axes, m) with a finite range, thinned to at most
/// [`MAX_CLOUD_POINTS`], placed by `pose` (device → world).
fn world_points(pose: &Isometry3<f64>, cloud: &[crate::devices::LidarPoint]) -> Vec<[f32; 3]> {
    let finite: Vec<_> = cloud
        .iter()
        .filter(|p| p.x.is_finite() && p.y.is_finite() && p.z.is_finite())
        .collect();
    let stride = finite.len().div_ceil(MAX_CLOUD_POINTS).max(1);
    finite
        .iter()
        .step_by(stride)
        .map(|p| {
            let w = pose * Point3::new(f64::from(p.x), f64::from(p.y), f64::from(p.z));
            [w.x as f32, w.y as f32, w.z as f32]
        })
        .collect()
}

/// A drawn cloud: the node and the index of the frame it belongs to.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CloudNode {
    node: usize,
    frame: usize,
    lidar: usize,
}

/// The cloud nodes of `recording` under node `world`, hidden at rest: one per lidar and frame
/// that holds a cloud, named `<car>/<device> cloud <frame>` (with ` part <p>` for a part
/// after the first, whose frames count anew).
pub(crate) fn add_clouds(
    scene: &mut Scene,
    world: usize,
    recording: &Recording,
    part: usize,
) -> Vec<CloudNode> {
    if recording.lidars.is_empty() {
        return Vec::new();
    }
    let green =
        Material::new("lidar point", [0.1, 0.9, 0.2], 0.6, 0.0).with_emissive([0.0, 0.6, 0.1]);
    let green = scene.add_material(green);
    let suffix = if part == 0 {
        String::new()
    } else {
        format!(" part {part}")
    };
    let mut out = Vec::new();
    for (k, f) in recording.frames.iter().enumerate() {
        for (l, cloud) in f.lidar_points.iter().enumerate() {
            let Some(lidar) = recording.lidars.get(l).filter(|_| !cloud.is_empty()) else {
                continue;
            };
            let name = format!("{} cloud {k}{suffix}", lidar.name);
            let mesh = scene.add_geometry(&name, Geometry::Points(cloud.clone()), green);
            let node = scene.add_node(Some(world), &name, Isometry3::identity(), Some(mesh));
            if let Some(n) = scene.nodes.get_mut(node) {
                n.visible = false;
            }
            out.push(CloudNode {
                node,
                frame: k,
                lidar: l,
            });
        }
    }
    out
}

/// The channels of the clouds `nodes` over `frames` (`times`: each frame's animation time,
/// s): a cloud shows from its frame until the next cloud of its lidar, hidden before.
pub(crate) fn add_channels(a: &mut Animation, times: &[f32], nodes: &[CloudNode]) {
    for (i, c) in nodes.iter().enumerate() {
        let Some(&shown) = times.get(c.frame) else {
            continue;
        };
        let next = nodes[i + 1..]
            .iter()
            .find(|n| n.lidar == c.lidar)
            .and_then(|n| times.get(n.frame));
        let (mut at, mut values) = (Vec::new(), Vec::new());
        if shown > 0.0 {
            at.push(0.0);
            values.push([0.0; 3]);
        }
        at.push(shown);
        values.push([1.0; 3]);
        if let Some(&hide) = next {
            at.push(hide);
            values.push([0.0; 3]);
        }
        let line = a.add_timeline(at);
        a.add_channel(c.node, line, Interpolation::Step, Keyframes::Scale(values));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::devices::LidarPoint;

    fn point(x: f32) -> LidarPoint {
        LidarPoint {
            x,
            y: 0.0,
            z: 0.0,
            layer_id: 0,
            time: 0.0,
        }
    }

    #[test]
    fn a_cloud_keeps_its_returns_thinned_to_the_cap() {
        // A VLP-16's 28,800 rays, one in ten without a return: 25,920 returns, every 7th kept
        // (⌈25,920 / 4,096⌉ = 7), 3,703 points, placed 1 m up.
        let cloud: Vec<LidarPoint> = (0..28_800)
            .map(|k| point(if k % 10 == 0 { f32::INFINITY } else { k as f32 }))
            .collect();
        let up = Isometry3::translation(0.0, 0.0, 1.0);
        let points = world_points(&up, &cloud);
        assert_eq!(points.len(), 25_920usize.div_ceil(7));
        assert!(points.len() <= MAX_CLOUD_POINTS);
        assert_eq!(points[0], [1.0, 0.0, 1.0]);
        assert_eq!(points[1], [8.0, 0.0, 1.0]);
    }

    #[test]
    fn past_the_total_cap_every_other_cloud_goes_and_clouds_come_half_as_often() {
        // 600 frames of 4,096 points: 2.46 M points, twice over the cap of 1,048,576 and
        // more; halving twice leaves 150 clouds, 614,400 points.
        let frames: Vec<Frame> = (0..600)
            .map(|_| Frame {
                lidar_points: vec![vec![[0.0; 3]; MAX_CLOUD_POINTS]],
                ..Frame::default()
            })
            .collect();
        let mut frames = frames;
        let mut budget = CloudBudget::new(1);
        budget.points = held(&frames);
        budget.enforce(&mut frames);
        assert_eq!(held(&frames), 150 * MAX_CLOUD_POINTS);
        assert_eq!(budget.every, 4);
        // The kept clouds are evenly spaced: frames 0, 4, 8, …
        for (k, f) in frames.iter().enumerate() {
            assert_eq!(f.lidar_points.is_empty(), k % 4 != 0, "frame {k}");
        }
    }
}
