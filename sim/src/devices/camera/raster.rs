//! A small software rasteriser: the world's solids and the ground plane through Webots' planar
//! pinhole, with a depth buffer, flat shading under the default light, and per pixel the
//! solid it shows (for Recognition's occlusion).
//!
//! Why rasterise rather than cast one ray per pixel: the world holds a handful of convex
//! solids of 5 to 34 triangles, so projecting each triangle once and filling its pixels costs
//! a few µs per solid plus one depth comparison per covered pixel, where a ray per pixel
//! (32 768 at 256 × 128) through rapier's query pipeline costs a BVH descent each
//! (ARCHITECTURE.md, "Camera").

use proto_geom::nalgebra::{Isometry3, Point3, Vector3};

use super::solids::Solids;
use crate::appearance::GROUND_COLOR;
use crate::vehicle::VehicleId;

/// The share of a face's colour lit by the sky whatever its orientation.
const AMBIENT: f64 = 0.5;
/// Towards the default light (world axes, not normalised): high, from +x and a little +y,
/// so that a box's faces differ.
const TO_LIGHT: [f64; 3] = [0.5, 0.25, 1.0];

/// How bright a face of outward normal `n` (world, unit) is, in [AMBIENT, 1]: 1 for an
/// upward face, whose pixels thus show its colour exactly.
pub(crate) fn shade(n: &Vector3<f64>) -> f64 {
    let l = Vector3::from(TO_LIGHT).normalize();
    (AMBIENT + (1.0 - AMBIENT) * n.dot(&l).max(0.0) / l.z).min(1.0)
}

/// A colour (each channel in [0, 1]) at brightness `s`, as bytes.
pub(crate) fn bytes(colour: &[f64; 3], s: f64) -> [u8; 3] {
    colour.map(|c| (c * s * 255.0).round().clamp(0.0, 255.0) as u8)
}

/// The pinhole of a planar camera.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pinhole {
    /// Image width and height (px).
    pub width: usize,
    pub height: usize,
    /// Focal length (px): `(width/2) / tan(fov/2)`.
    pub focal: f64,
    /// Near plane (m, camera x).
    pub near: f64,
    /// Far plane (m, camera x), infinite for Webots' 0.
    pub far: f64,
}

impl Pinhole {
    /// Image coordinates (px, u right, v down) of camera point `p` (x > 0).
    pub(crate) fn project(&self, p: &Point3<f64>) -> [f64; 2] {
        [
            self.width as f64 / 2.0 - self.focal * p.y / p.x,
            self.height as f64 / 2.0 - self.focal * p.z / p.x,
        ]
    }
}

/// What a render leaves: colours (RGB), inverse depths (1/m along the camera axis, 0 where
/// nothing is) and the id of the solid each pixel shows (0: ground or sky).
#[derive(Debug, Clone, Default)]
pub(crate) struct Frame {
    pub rgb: Vec<[u8; 3]>,
    pub inverse_depth: Vec<f64>,
    pub ids: Vec<i32>,
}

/// A camera point with its image coordinates.
#[derive(Debug, Clone, Copy)]
struct Vertex {
    u: f64,
    v: f64,
    /// 1 / camera x (1/m).
    w: f64,
}

impl Frame {
    /// Renders `solids` (but those of car `own`), the roads and the ground seen by a camera
    /// at `pose` (camera frame → world, m; x forward, y left, z up) through `pin`, into this
    /// frame's buffers (reused).
    pub(crate) fn render(
        &mut self,
        pin: &Pinhole,
        pose: &Isometry3<f64>,
        solids: &Solids,
        own: Option<VehicleId>,
    ) {
        let (w, h) = (pin.width, pin.height);
        self.rgb.clear();
        self.rgb.resize(w * h, [0; 3]);
        self.inverse_depth.clear();
        self.inverse_depth.resize(w * h, 0.0);
        self.ids.clear();
        self.ids.resize(w * h, 0);
        self.ground(pin, pose);
        let to_camera = pose.inverse();
        // A road has thousands of triangles: a rotation matrix turns a point in 15 flops, the
        // isometry's quaternion in about twice that.
        let (turn, shift) = (
            to_camera.rotation.to_rotation_matrix().into_inner(),
            to_camera.translation.vector,
        );
        for patch in solids.roads.iter() {
            let centre = to_camera * patch.centre;
            if centre.x + patch.radius < pin.near || centre.x - patch.radius > pin.far {
                continue;
            }
            for (corners, colour) in &patch.triangles {
                // Both faces: a road is seen from above, whichever way its strip winds.
                let p = corners.map(|c| Point3::from(turn * c.coords + shift));
                self.triangle(pin, &p, *colour, 0);
            }
        }
        for s in solids
            .all
            .iter()
            .filter(|s| own.is_none() || s.owner != own)
        {
            let local = to_camera * s.pose;
            // Cull the solid whose bounding sphere is wholly behind the near plane or past
            // the far one.
            let centre = local * s.centre;
            let radius = s.half.norm();
            if centre.x + radius < pin.near || centre.x - radius > pin.far {
                continue;
            }
            for (corners, n) in &s.triangles {
                let p = corners.map(|c| local * c);
                let normal = local.rotation * n;
                // Back faces of a convex solid are hidden by its front faces.
                if normal.dot(&p[0].coords) >= 0.0 {
                    continue;
                }
                let colour = bytes(&s.appearance.color, shade(&(s.pose.rotation * n)));
                self.triangle(pin, &p, colour, s.id);
            }
        }
    }

    /// Fills every pixel whose ray meets the ground plane z = 0 in front of the camera with
    /// the ground's colour (lit as an upward face: exactly its colour).
    fn ground(&mut self, pin: &Pinhole, pose: &Isometry3<f64>) {
        let height = pose.translation.vector.z;
        if height <= 0.0 {
            return;
        }
        let r = pose.rotation.to_rotation_matrix();
        let m = r.matrix();
        let colour = bytes(&GROUND_COLOR, 1.0);
        let (cx, cy) = (pin.width as f64 / 2.0, pin.height as f64 / 2.0);
        for j in 0..pin.height {
            let b = (cy - (j as f64 + 0.5)) / pin.focal;
            for i in 0..pin.width {
                let a = (cx - (i as f64 + 0.5)) / pin.focal;
                // The ray (1, a, b) in camera axes: its world z per metre of camera x.
                let dz = m[(2, 0)] + a * m[(2, 1)] + b * m[(2, 2)];
                if dz >= 0.0 {
                    continue;
                }
                let inverse = -dz / height;
                if inverse * pin.far < 1.0 {
                    continue;
                }
                let k = j * pin.width + i;
                self.rgb[k] = colour;
                self.inverse_depth[k] = inverse;
            }
        }
    }

    /// Clips triangle `p` (camera frame, m) to the near plane and fills its pixels.
    fn triangle(&mut self, pin: &Pinhole, p: &[Point3<f64>; 3], colour: [u8; 3], id: i32) {
        let mut clipped: [Point3<f64>; 4] = [Point3::origin(); 4];
        let mut n = 0;
        for k in 0..3 {
            let (a, b) = (p[k], p[(k + 1) % 3]);
            let (da, db) = (a.x - pin.near, b.x - pin.near);
            if da >= 0.0 {
                clipped[n] = a;
                n += 1;
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                clipped[n] = a + (b - a) * t;
                n += 1;
            }
        }
        if n < 3 {
            return;
        }
        let vertex = |q: &Point3<f64>| {
            // On the near plane x may fall a rounding short of it: keep it positive.
            let x = q.x.max(pin.near);
            let [u, v] = pin.project(&Point3::new(x, q.y, q.z));
            Vertex { u, v, w: 1.0 / x }
        };
        let a = vertex(&clipped[0]);
        for k in 1..n - 1 {
            let (b, c) = (vertex(&clipped[k]), vertex(&clipped[k + 1]));
            self.fill(pin, [a, b, c], colour, id);
        }
    }

    /// Fills the pixels whose centres lie in the screen triangle `t`, nearer than what they
    /// show.
    fn fill(&mut self, pin: &Pinhole, t: [Vertex; 3], colour: [u8; 3], id: i32) {
        let [a, b, c] = t;
        let area = (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
        if area.abs() < 1e-12 || area.is_nan() {
            return;
        }
        let lo_u = a.u.min(b.u).min(c.u);
        let hi_u = a.u.max(b.u).max(c.u);
        let lo_v = a.v.min(b.v).min(c.v);
        let hi_v = a.v.max(b.v).max(c.v);
        // Pixel i covers [i, i + 1): its centre i + 0.5 is inside when i ≥ lo − 0.5.
        let first = |lo: f64| (lo - 0.5).ceil().max(0.0) as usize;
        let last = |hi: f64, size: usize| ((hi - 0.5).floor().min(size as f64 - 1.0)).max(-1.0);
        let (i0, j0) = (first(lo_u), first(lo_v));
        let (i1, j1) = (last(hi_u, pin.width), last(hi_v, pin.height));
        if i1 < 0.0 || j1 < 0.0 {
            return;
        }
        let (i1, j1) = (i1 as usize, j1 as usize);
        let far_inverse = 1.0 / pin.far;
        let inv_area = 1.0 / area;
        for j in j0..=j1 {
            let y = j as f64 + 0.5;
            for i in i0..=i1 {
                let x = i as f64 + 0.5;
                let wa = ((b.u - x) * (c.v - y) - (b.v - y) * (c.u - x)) * inv_area;
                let wb = ((c.u - x) * (a.v - y) - (c.v - y) * (a.u - x)) * inv_area;
                let wc = 1.0 - wa - wb;
                if wa < 0.0 || wb < 0.0 || wc < 0.0 {
                    continue;
                }
                // 1/x is affine in screen space: interpolated exactly.
                let inverse = wa * a.w + wb * b.w + wc * c.w;
                let k = j * pin.width + i;
                if inverse <= self.inverse_depth[k] || inverse < far_inverse {
                    continue;
                }
                self.inverse_depth[k] = inverse;
                self.rgb[k] = colour;
                self.ids[k] = id;
            }
        }
    }
}
