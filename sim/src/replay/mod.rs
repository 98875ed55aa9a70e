//! `replay.glb`: a run as an animated 3D scene (binary glTF 2.0), which Blender, three.js and
//! Babylon.js viewers, `<model-viewer>` and the Windows and macOS 3D viewers open.
//!
//! * [`Recorder`] samples a world after its steps, at most [`MAX_KEYFRAME_RATE`] frames per
//!   simulated second whatever `basicTimeStep` (a whole number of steps apart, plus the last
//!   step): each car's chassis pose, wheel spins, steering angles, suspension travel and lights,
//!   each robot's pose and wheel angles, each dynamic box's pose. It also keeps what to draw:
//!   each car's [`CarModel`] (its own `VehicleWheel`s on its `proto-geom` layout and a body
//!   box), each robot's fields, the obstacles and boxes.
//! * [`scene`] builds one `proto-geom` [`Scene`] of a run's [`Part`]s: a ground patch over
//!   the driven area with grid lines (1, 2 or 5 × 10ⁿ m apart, at most 150 across), every box,
//!   ramp and `[[body]]`, every car (a low-poly car body filling its body box, in its own
//!   colour; Webots wheel meshes; brake lights and indicators, emissive, shown while the
//!   recorded light commands have them on) and robot (its physics-mode cylinder on two scaled `VehicleWheel`s), and per
//!   part a group with one trajectory line per car and robot and the cones of its course; then
//!   one animation per part, named after it (`test-track` gives five), in seconds of simulated
//!   time from the part's start. Lights and the part groups show and hide through step-
//!   interpolated scale keyframes: while a part plays, only its own trajectories and cones
//!   show.
//! * Cameras (`cameras.rs`): per car a `chase_camera` node under the car's node, behind the
//!   body by [`CHASE_BEHIND`] body lengths and above its roof by [`CHASE_ABOVE`] body heights,
//!   looking at the body's centre; and an `overview_camera` under `world` looking down at
//!   [`OVERVIEW_PITCH`] rad on the centre of the ground rectangle the run covers, far enough
//!   for the whole rectangle to fit its vertical field of view ([`FIELD_OF_VIEW`]).
//! * [`to_glb`] writes the parts' scene as binary glTF; [`crate::report::write_data`] puts
//!   a run's in `replay.glb` beside the CSV and the metrics.
//!
//! Frames: the scene is built in this crate's z-up world frame (m) and `proto-geom`'s writer
//! turns it into glTF's y-up frame once, at its root node (`webots_to_gltf`).

mod animate;
mod cameras;
mod cone;
pub mod lidar_overlay;
pub mod overlay;
mod recorder;
mod scene;
mod shapes;

use std::io;

use proto_geom::export::{AnimationError, Scene};

pub use cameras::{CHASE_ABOVE, CHASE_BEHIND, FIELD_OF_VIEW, OVERVIEW_PITCH};
pub use scene::car_colour;

pub use recorder::{
    CarFrame, CarModel, Frame, MAX_FRAMES, MAX_KEYFRAME_RATE, Recorder, Recording, RobotFrame,
    RobotModel,
};

/// One part of a run: a recording, its name and the lines of its course.
#[derive(Debug, Clone, Copy)]
pub struct Part<'a> {
    /// The animation's name, e.g. the scenario's.
    pub name: &'a str,
    /// What was recorded.
    pub recording: &'a Recording,
    /// Lines of the course (m, world x and y), drawn as rows of traffic cones at most 3 m
    /// apart, e.g. the lane change's cone lines.
    pub guides: &'a [Vec<[f64; 2]>],
}

/// The replay scene of `parts`: the world and the vehicles of the first part's recording (every
/// part of a run has the same world), the parts' trajectories and cones, and one animation per
/// part that has frames.
///
/// # Errors
/// An [`AnimationError`] if a recording's frames are not in strictly increasing time (a
/// recording from [`Recorder`] always is).
pub fn scene(parts: &[Part<'_>]) -> Result<Scene, AnimationError> {
    scene_and_cars(parts).map(|(scene, _)| scene)
}

/// Where a viewer finds a car of the replay: glTF node indices, which stay unambiguous
/// whatever the names (three.js renames a node whose name another node has, e.g. a car
/// named `world` or `ground`, and lamps of the same name on every car).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct CarNode {
    /// The car's root node (it moves the car).
    pub(crate) root: usize,
    /// Its body's node: the visible body mesh, without the wheels and lamps.
    pub(crate) body: usize,
}

/// [`scene`], and the nodes of the first part's cars in order. [`Scene::to_glb`] writes the
/// scene's nodes in order, so their indices are the glTF file's.
fn scene_and_cars(parts: &[Part<'_>]) -> Result<(Scene, Vec<CarNode>), AnimationError> {
    let (mut scene, nodes) = scene::build(parts);
    for index in 0..parts.len() {
        if let Some(a) = animate::animation(parts, index, &nodes) {
            scene.add_animation(a)?;
        }
    }
    let cars = nodes
        .cars
        .iter()
        .map(|c| CarNode {
            root: c.vehicle.root,
            body: c.vehicle.chassis,
        })
        .collect();
    Ok((scene, cars))
}

/// The replay of `parts` (a run's, [`RunReport::replay_parts`](crate::scenario::RunReport::replay_parts))
/// as a binary glTF file.
///
/// # Errors
/// [`io::ErrorKind::InvalidData`] for the [`AnimationError`] of [`scene`], or an [`io::Error`]
/// if the file cannot be serialised (a buffer beyond 4 GiB).
pub fn to_glb(parts: &[Part<'_>]) -> io::Result<Vec<u8>> {
    to_glb_and_cars(parts).map(|(glb, _)| glb)
}

/// [`to_glb`], and the glTF nodes of the first part's cars in order.
///
/// # Errors
/// As [`to_glb`].
pub(crate) fn to_glb_and_cars(parts: &[Part<'_>]) -> io::Result<(Vec<u8>, Vec<CarNode>)> {
    let (scene, cars) =
        scene_and_cars(parts).map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))?;
    Ok((scene.to_glb()?, cars))
}
