//! Perspective cameras of a [`Scene`](super::Scene) (glTF 2.0 `cameras`).
//!
//! A glTF camera looks along its node's −z axis with +y up. [`Scene::add_camera`] takes an eye
//! and a target point in the parent's frame (z-up, m) and orients the node so that the camera
//! looks from one at the other with the parent's +z up; the writer's root node then maps the
//! whole tree to glTF's y-up frame, cameras included.

use core::fmt;
use std::string::{String, ToString};

use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};

use super::Scene;

/// A perspective camera: vertical field of view and clipping distances.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    /// Camera name.
    pub name: String,
    /// Vertical field of view (rad), in (0, π).
    pub yfov: f64,
    /// Distance to the near clipping plane (m), > 0.
    pub znear: f64,
    /// Distance to the far clipping plane (m), > `znear`.
    pub zfar: f64,
}

/// Why a camera was refused: the field and the value given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CameraError {
    /// `yfov` (rad) not in (0, π) or not finite.
    FieldOfView(f64),
    /// `znear` (m) not finite and positive.
    Near(f64),
    /// `zfar` (m) not finite or not beyond `znear`.
    Far(f64),
    /// The eye and the target are the same point, or one is not finite: no direction to look
    /// along. The distance between them (m).
    NoDirection(f64),
}

impl fmt::Display for CameraError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            CameraError::FieldOfView(v) => {
                write!(f, "camera 'yfov' = {v} rad: must be in (0, π)")
            }
            CameraError::Near(v) => write!(f, "camera 'znear' = {v} m: must be positive"),
            CameraError::Far(v) => write!(f, "camera 'zfar' = {v} m: must be beyond 'znear'"),
            CameraError::NoDirection(d) => write!(
                f,
                "camera eye and target {d} m apart: they must be distinct finite points"
            ),
        }
    }
}

impl std::error::Error for CameraError {}

impl Camera {
    /// A perspective camera named `name` of vertical field of view `yfov` (rad) that shows
    /// what lies between `znear` and `zfar` (m) in front of it.
    ///
    /// # Errors
    /// A [`CameraError`] naming the first implausible value.
    pub fn perspective(name: &str, yfov: f64, znear: f64, zfar: f64) -> Result<Self, CameraError> {
        if !(yfov > 0.0 && yfov < core::f64::consts::PI) {
            return Err(CameraError::FieldOfView(yfov));
        }
        if !(znear.is_finite() && znear > 0.0) {
            return Err(CameraError::Near(znear));
        }
        if !(zfar.is_finite() && zfar > znear) {
            return Err(CameraError::Far(zfar));
        }
        Ok(Camera {
            name: name.to_string(),
            yfov,
            znear,
            zfar,
        })
    }
}

/// The node frame of a camera at `eye` looking at `target` (both m, in the parent's frame) with
/// the parent's +z up: the frame's −z points at the target and its +y is as near +z as the
/// direction allows (+x when looking straight up or down).
///
/// # Errors
/// [`CameraError::NoDirection`] if the points coincide or one is not finite.
pub fn look_at(eye: Point3<f64>, target: Point3<f64>) -> Result<Isometry3<f64>, CameraError> {
    let dir = target - eye;
    let distance = dir.norm();
    if !(distance.is_finite() && distance > 0.0) {
        return Err(CameraError::NoDirection(distance));
    }
    let up = if dir.cross(&Vector3::z()).norm() > 1e-9 * distance {
        Vector3::z()
    } else {
        Vector3::x()
    };
    // `face_towards` maps +z to its direction; the camera looks along −z.
    let rotation = UnitQuaternion::face_towards(&-dir, &up);
    Ok(Isometry3::from_parts(
        Translation3::from(eye.coords),
        rotation,
    ))
}

impl Scene {
    /// Adds `camera` and a node `name` under `parent` (or as a root) that holds it at `eye`,
    /// looking at `target` (both m, in the parent's frame) with the parent's +z up
    /// ([`look_at`]); returns the node. A camera under a moving node (a car) moves with it.
    ///
    /// # Errors
    /// [`CameraError::NoDirection`] if `eye` and `target` coincide or one is not finite; the
    /// scene is then unchanged.
    pub fn add_camera(
        &mut self,
        parent: Option<usize>,
        name: &str,
        eye: Point3<f64>,
        target: Point3<f64>,
        camera: Camera,
    ) -> Result<usize, CameraError> {
        let pose = look_at(eye, target)?;
        let node = self.add_node(parent, name, pose, None);
        self.cameras.push(camera);
        if let Some(n) = self.nodes.get_mut(node) {
            n.camera = Some(self.cameras.len() - 1);
        }
        Ok(node)
    }
}
