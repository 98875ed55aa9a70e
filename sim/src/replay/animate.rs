//! One glTF animation per part of a run, from its recording's frames.

use ackermann::Wheel;
use proto_geom::export::{Animation, Interpolation, Keyframes};
use proto_geom::nalgebra::{Isometry3, UnitQuaternion, Vector3};

use super::Part;
use super::recorder::{CarFrame, Frame};
use super::scene::{Nodes, steering_of, wheel_rotation, world_pose};

/// Whether a light is on in a car's frame.
type LightOf = fn(&CarFrame) -> bool;

fn quat(q: &UnitQuaternion<f64>) -> [f32; 4] {
    q.coords.map(|c| c as f32).into()
}

fn vec3(v: &Vector3<f64>) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

/// Moves `node` through `poses` on timeline `t`, linearly.
fn add_poses(a: &mut Animation, node: usize, t: usize, poses: &[Isometry3<f64>]) {
    let translations = poses.iter().map(|p| vec3(&p.translation.vector)).collect();
    let rotations = poses.iter().map(|p| quat(&p.rotation)).collect();
    a.add_channel(
        node,
        t,
        Interpolation::Linear,
        Keyframes::Translation(translations),
    );
    a.add_channel(
        node,
        t,
        Interpolation::Linear,
        Keyframes::Rotation(rotations),
    );
}

/// Shown (scale 1) or hidden (scale 0).
fn visibility(on: bool) -> [f32; 3] {
    if on { [1.0; 3] } else { [0.0; 3] }
}

/// A light's switching times and states from `state` per frame: the first frame, then each
/// change.
fn switches(
    times: &[f32],
    frames: &[Frame],
    state: impl Fn(&Frame) -> Option<bool>,
) -> (Vec<f32>, Vec<[f32; 3]>) {
    let (mut at, mut values) = (Vec::new(), Vec::new());
    let mut last = None;
    for (t, f) in times.iter().zip(frames) {
        let on = state(f).unwrap_or(false);
        if last != Some(on) {
            at.push(*t);
            values.push(visibility(on));
            last = Some(on);
        }
    }
    (at, values)
}

/// The animation of part `index` of `parts` over the scene's `nodes`, named after the part:
/// time 0 at the first frame, in s of simulated time; `None` for a part without frames.
pub(crate) fn animation(parts: &[Part<'_>], index: usize, nodes: &Nodes) -> Option<Animation> {
    let part = parts.get(index)?;
    let frames = &part.recording.frames;
    let t0 = frames.first()?.time;
    let mut a = Animation::new(part.name);
    let times: Vec<f32> = frames.iter().map(|f| (f.time - t0) as f32).collect();
    let t = a.add_timeline(times.clone());
    let linear = Interpolation::Linear;

    for (i, car) in nodes.cars.iter().enumerate() {
        let car_frames: Vec<&CarFrame> = frames.iter().filter_map(|f| f.cars.get(i)).collect();
        if car_frames.len() != frames.len() {
            continue;
        }
        let poses: Vec<_> = car_frames
            .iter()
            .map(|c| world_pose(&c.position, &c.roll_pitch_yaw))
            .collect();
        add_poses(&mut a, car.vehicle.root, t, &poses);
        for w in Wheel::ALL {
            let node = car.vehicle.wheels[w];
            let centre = car.wheel_centres[w];
            let translations = car_frames
                .iter()
                .map(|c| vec3(&(centre + Vector3::z() * c.suspension[w])))
                .collect();
            let rotations = car_frames
                .iter()
                .map(|c| {
                    let q = wheel_rotation(
                        &car.wheel_rest[w],
                        steering_of(w, &c.steering),
                        c.wheel_angles[w],
                    );
                    quat(&q)
                })
                .collect();
            a.add_channel(node, t, linear, Keyframes::Translation(translations));
            a.add_channel(node, t, linear, Keyframes::Rotation(rotations));
        }
        let lights: [(usize, LightOf); 3] = [
            (car.brake_lights, |c| c.lights.brake),
            (car.left_indicators, |c| c.lights.left_indicator),
            (car.right_indicators, |c| c.lights.right_indicator),
        ];
        for (node, on) in lights {
            let (at, values) = switches(&times, frames, |f| f.cars.get(i).map(on));
            let line = a.add_timeline(at);
            a.add_channel(node, line, Interpolation::Step, Keyframes::Scale(values));
        }
    }

    for (i, robot) in nodes.robots.iter().enumerate() {
        let robot_frames: Vec<_> = frames.iter().filter_map(|f| f.robots.get(i)).collect();
        if robot_frames.len() != frames.len() {
            continue;
        }
        let translations = robot_frames
            .iter()
            .map(|r| vec3(&r.position.coords))
            .collect();
        let rotations = robot_frames
            .iter()
            .map(|r| quat(&UnitQuaternion::from_euler_angles(0.0, 0.0, r.heading)))
            .collect();
        a.add_channel(robot.root, t, linear, Keyframes::Translation(translations));
        a.add_channel(robot.root, t, linear, Keyframes::Rotation(rotations));
        for (side, (node, rest)) in robot.wheels.iter().enumerate() {
            let rotations = robot_frames
                .iter()
                .map(|r| quat(&wheel_rotation(&rest.rotation, 0.0, r.wheel_angles[side])))
                .collect();
            a.add_channel(*node, t, linear, Keyframes::Rotation(rotations));
        }
    }

    for (i, &node) in nodes.bodies.iter().enumerate() {
        let poses: Vec<_> = frames
            .iter()
            .filter_map(|f| f.bodies.get(i))
            .map(|p| world_pose(&p.position, &p.roll_pitch_yaw))
            .collect();
        if poses.len() != frames.len() {
            continue;
        }
        add_poses(&mut a, node, t, &poses);
    }

    super::overlay::add_channels(&mut a, t, frames, &nodes.radar_markers);
    if let Some(clouds) = nodes.lidar_clouds.get(index) {
        super::lidar_overlay::add_channels(&mut a, &times, clouds);
    }

    // Only this part's trajectories and cones show while it plays.
    if nodes.parts.len() > 1 {
        let start = a.add_timeline(vec![0.0]);
        for (k, &group) in nodes.parts.iter().enumerate() {
            let shown = Keyframes::Scale(vec![visibility(k == index)]);
            a.add_channel(group, start, Interpolation::Step, shown);
        }
    }
    (!a.channels.is_empty()).then_some(a)
}
