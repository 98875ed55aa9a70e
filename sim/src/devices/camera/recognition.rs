//! Webots' `Recognition` (spec §9): the solids with recognition colours a camera sees, each
//! with its position, orientation and size in the camera frame and its rectangle on the image.

use proto_geom::nalgebra::{Isometry3, Point3, Vector3};

use super::raster::{Frame, Pinhole};
use super::solids::Solid;
use crate::error::ParamError;
use crate::vehicle::VehicleId;

/// How Recognition treats a solid hidden behind another (the `occlusion` field).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Occlusion {
    /// 0: every solid in the field of view is reported, hidden or not.
    Off,
    /// 1 (default): reported iff the pixel at the projection of its centre shows it (when
    /// that pixel is off the image: iff any pixel shows it).
    Centre,
    /// 2: reported iff any pixel of the image shows it (Webots checks its outline).
    Outline,
}

/// The fields of a `Recognition` node, with Webots' defaults ([`Default`]). `frameColor`,
/// `frameThickness` and `segmentation` are not held: there is no window to frame the objects
/// in, and no segmentation image (`COMPATIBILITY.md`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecognitionSettings {
    /// `maxRange` (m, > 0; default 100): farther solids (distance of their centre) are not
    /// reported.
    pub max_range: f64,
    /// `maxObjects` (−1: all, default; else ≥ 0): the most reported, the largest on the image
    /// first.
    pub max_objects: i32,
    /// `occlusion` (default 1).
    pub occlusion: Occlusion,
}

impl Default for RecognitionSettings {
    fn default() -> Self {
        RecognitionSettings {
            max_range: 100.0,
            max_objects: -1,
            occlusion: Occlusion::Centre,
        }
    }
}

impl RecognitionSettings {
    /// Checks every field against Webots' range.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("maxRange", self.max_range)?;
        ParamError::check(
            "maxObjects",
            f64::from(self.max_objects),
            "-1 (all) or >= 0",
            |n| n >= -1.0,
        )?;
        Ok(())
    }
}

/// A recognised object: Webots' `WbCameraRecognitionObject`.
#[derive(Debug, Clone, PartialEq)]
pub struct RecognitionObject {
    /// The solid's id: 1 + its index among the world's obstacles, dynamic boxes, cars and
    /// robots, in that order.
    pub id: i32,
    /// Its bounding box's centre (m, camera frame: x forward, y left, z up).
    pub position: Vector3<f64>,
    /// Its orientation relative to the camera, axis–angle `[x, y, z, angle]` (rad; identity
    /// `[0, 0, 1, 0]`).
    pub orientation: [f64; 4],
    /// Its bounding box's extent along the camera's y and z axes (m).
    pub size: [f64; 2],
    /// The centre of its rectangle on the image (px, from the top-left corner).
    pub position_on_image: [i32; 2],
    /// The width and height of its rectangle on the image (px).
    pub size_on_image: [i32; 2],
    /// Its `recognitionColors` (RGB, each in [0, 1]).
    pub colors: Vec<[f64; 3]>,
    /// Its `model`.
    pub model: String,
}

/// The objects `frame` (rendered at `pose`, camera frame → world) shows, as `settings` select
/// them, solids of car `own` excepted.
pub(crate) fn recognise(
    settings: &RecognitionSettings,
    pin: &Pinhole,
    pose: &Isometry3<f64>,
    solids: &[Solid],
    own: Option<VehicleId>,
    frame: &Frame,
) -> Vec<RecognitionObject> {
    let to_camera = pose.inverse();
    let mut found: Vec<RecognitionObject> = Vec::new();
    for s in solids {
        if s.appearance.recognition_colors.is_empty() || (own.is_some() && s.owner == own) {
            continue;
        }
        let local = to_camera * s.pose;
        let centre = local * s.centre;
        if centre.coords.norm() > settings.max_range || centre.x <= pin.near {
            continue;
        }
        let corners: Vec<Point3<f64>> = (0..8)
            .map(|k| {
                let sign = |bit: usize| if k & bit == 0 { -1.0 } else { 1.0 };
                let h = s.half;
                local * (s.centre + Vector3::new(sign(1) * h.x, sign(2) * h.y, sign(4) * h.z))
            })
            .collect();
        let Some(rect) = rectangle(pin, &corners) else {
            continue;
        };
        let visible = match settings.occlusion {
            Occlusion::Off => true,
            Occlusion::Centre => {
                let [u, v] = pin.project(&centre);
                if (0.0..pin.width as f64).contains(&u) && (0.0..pin.height as f64).contains(&v) {
                    frame.ids[v as usize * pin.width + u as usize] == s.id
                } else {
                    frame.ids.contains(&s.id)
                }
            }
            Occlusion::Outline => frame.ids.contains(&s.id),
        };
        if !visible {
            continue;
        }
        let (lo_y, hi_y) = extent(&corners, 1);
        let (lo_z, hi_z) = extent(&corners, 2);
        let orientation = local
            .rotation
            .axis_angle()
            .map_or([0.0, 0.0, 1.0, 0.0], |(a, t)| [a.x, a.y, a.z, t]);
        let [u0, v0, u1, v1] = rect;
        found.push(RecognitionObject {
            id: s.id,
            position: centre.coords,
            orientation,
            size: [hi_y - lo_y, hi_z - lo_z],
            position_on_image: [(u0 + u1) / 2, (v0 + v1) / 2],
            size_on_image: [u1 - u0, v1 - v0],
            colors: s.appearance.recognition_colors.clone(),
            model: s.appearance.model.clone(),
        });
    }
    if let Ok(n) = usize::try_from(settings.max_objects) {
        // The largest on the image first; ties keep the world's order.
        found.sort_by_key(|o| {
            std::cmp::Reverse(i64::from(o.size_on_image[0]) * i64::from(o.size_on_image[1]))
        });
        found.truncate(n);
    }
    found
}

/// The smallest and largest coordinate `axis` of `points`.
fn extent(points: &[Point3<f64>], axis: usize) -> (f64, f64) {
    points
        .iter()
        .fold((f64::INFINITY, -f64::INFINITY), |(lo, hi), p| {
            (lo.min(p[axis]), hi.max(p[axis]))
        })
}

/// The pixel rectangle `[u0, v0, u1, v1)` the box of camera-frame `corners` covers on the
/// image, clipped to it; `None` if it misses the image. Corners behind the near plane stretch
/// the rectangle to the image's edge on their side.
fn rectangle(pin: &Pinhole, corners: &[Point3<f64>]) -> Option<[i32; 4]> {
    let (w, h) = (pin.width as f64, pin.height as f64);
    let (mut lo_u, mut lo_v, mut hi_u, mut hi_v) =
        (f64::INFINITY, f64::INFINITY, -f64::INFINITY, -f64::INFINITY);
    for p in corners {
        if p.x > pin.near {
            let [u, v] = pin.project(p);
            lo_u = lo_u.min(u);
            hi_u = hi_u.max(u);
            lo_v = lo_v.min(v);
            hi_v = hi_v.max(v);
        } else {
            // Behind the camera: its side of the image is the side its y and z point to.
            if p.y > 0.0 {
                lo_u = f64::NEG_INFINITY;
            } else {
                hi_u = f64::INFINITY;
            }
            if p.z > 0.0 {
                lo_v = f64::NEG_INFINITY;
            } else {
                hi_v = f64::INFINITY;
            }
        }
    }
    let (u0, u1) = (lo_u.max(0.0).floor(), hi_u.min(w).ceil());
    let (v0, v1) = (lo_v.max(0.0).floor(), hi_v.min(h).ceil());
    (u0 < u1 && v0 < v1).then_some([u0 as i32, v0 as i32, u1 as i32, v1 as i32])
}
