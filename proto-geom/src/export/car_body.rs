//! A low-poly car body: a lower body with a raked nose and tail, and a tapered greenhouse
//! between the axles, filling a [`ChassisBox`] exactly so that its bounding box is the car's
//! length, width and height.

use std::vec::Vec;

use ackermann::Real;
use nalgebra::{Point3, Vector3};

use super::ChassisBox;
use crate::render::{RenderMesh, RenderVertex};

/// Height of the beltline (where the greenhouse starts) above the body's bottom, as a share of
/// the body's height.
pub const BELTLINE: f64 = 0.55;
/// How far the greenhouse's base starts ahead of the body's rear, as a share of its length.
const CABIN_REAR: f64 = 0.2;
/// The greenhouse's base ends at this share of the wheelbase ahead of the rear axle (the
/// windscreen's foot)...
const CABIN_FRONT_OF_WHEELBASE: f64 = 0.8;
/// ...but leaves at least this share of the length for the bonnet...
const MIN_BONNET: f64 = 0.25;
/// ...and is at least this share of the length long.
const MIN_CABIN: f64 = 0.3;
/// Rake of the rear window and of the windscreen: how far the roof's ends move in from the
/// greenhouse base's, as shares of the length.
const REAR_WINDOW_RAKE: f64 = 0.06;
const WINDSCREEN_RAKE: f64 = 0.2;
/// Widths of the greenhouse at its base and at the roof, as shares of the body's width.
const CABIN_BASE_WIDTH: f64 = 0.9;
const ROOF_WIDTH: f64 = 0.72;
/// How far the tail's top edge (at the beltline) lies ahead of the body's rear, as a share of
/// its length: the tail slopes linearly from the bottom's rear edge to it.
pub const TAIL_RAKE: f64 = 0.03;
/// How far the nose's top edge (at the beltline) lies behind the body's front, as a share of
/// its length.
pub const NOSE_RAKE: f64 = 0.08;

/// A six-faced solid whose bottom face is `x0..x1` × ±`w0`/2 at height `z0` and whose top face
/// is `x2..x3` × ±`w1`/2 at `z1` (m, vehicle frame): flat-shaded, counter-clockwise seen from
/// outside.
struct Frustum {
    bottom: [f64; 4],
    top: [f64; 4],
}

impl Frustum {
    /// `bottom` and `top` are `[x_rear, x_front, width, z]` (m).
    fn corners(&self) -> [Point3<f64>; 8] {
        let face = |[x0, x1, w, z]: [f64; 4]| {
            [
                Point3::new(x0, -w / 2.0, z),
                Point3::new(x1, -w / 2.0, z),
                Point3::new(x1, w / 2.0, z),
                Point3::new(x0, w / 2.0, z),
            ]
        };
        let (b, t) = (face(self.bottom), face(self.top));
        [b[0], b[1], b[2], b[3], t[0], t[1], t[2], t[3]]
    }

    /// Appends the solid's six faces to `mesh`, two triangles each, with one normal per face.
    fn append_to(&self, mesh: &mut RenderMesh) {
        let c = self.corners();
        let centre = c.iter().fold(Vector3::zeros(), |s, p| s + p.coords) / 8.0;
        const FACES: [[usize; 4]; 6] = [
            [0, 3, 2, 1],
            [4, 5, 6, 7],
            [0, 1, 5, 4],
            [1, 2, 6, 5],
            [2, 3, 7, 6],
            [3, 0, 4, 7],
        ];
        for face in FACES {
            let [a, b, cc, d] = face.map(|i| c[i]);
            let mut normal = (cc - a).cross(&(d - b));
            let mut quad = [a, b, cc, d];
            // Outward: away from the solid's centre.
            let middle = (a.coords + b.coords + cc.coords + d.coords) / 4.0;
            if normal.dot(&(middle - centre)) < 0.0 {
                normal = -normal;
                quad.reverse();
            }
            let Some(normal) = normal.try_normalize(0.0) else {
                continue;
            };
            let base = u32::try_from(mesh.vertices.len()).unwrap_or(u32::MAX);
            for p in quad {
                mesh.vertices.push(RenderVertex {
                    position: [p.x as f32, p.y as f32, p.z as f32],
                    normal: [normal.x as f32, normal.y as f32, normal.z as f32],
                    tex_coord: [0.0; 2],
                });
            }
            mesh.indices
                .extend([base, base + 1, base + 2, base, base + 2, base + 3]);
        }
    }
}

/// The car body filling `chassis` (m, vehicle frame) for a car of wheelbase `wheelbase` (m,
/// rear axle at x = 0): a lower body from the chassis' bottom to the beltline
/// ([`BELTLINE`] of the height), the full length at the bottom with a raked nose and tail, the
/// full width; on it a greenhouse from behind the rear axle to the windscreen's foot, tapered
/// to the roof at the chassis' top. Its bounding box is the chassis box.
pub fn car_body<T: Real>(chassis: &ChassisBox<T>, wheelbase: T) -> RenderMesh {
    let f = |v: T| v.to_f64();
    let (c, s) = (chassis.centre, chassis.size);
    let (l, w, h) = (f(s.x), f(s.y), f(s.z));
    let (rear, front) = (f(c.x) - l / 2.0, f(c.x) + l / 2.0);
    let (bottom, top) = (f(c.z) - h / 2.0, f(c.z) + h / 2.0);
    let belt = bottom + BELTLINE * h;
    let cabin_rear = rear + CABIN_REAR * l;
    let cabin_front = (CABIN_FRONT_OF_WHEELBASE * f(wheelbase))
        .min(front - MIN_BONNET * l)
        .max(cabin_rear + MIN_CABIN * l);
    let parts = [
        Frustum {
            bottom: [rear, front, w, bottom],
            top: [rear + TAIL_RAKE * l, front - NOSE_RAKE * l, w, belt],
        },
        Frustum {
            bottom: [cabin_rear, cabin_front, CABIN_BASE_WIDTH * w, belt],
            top: [
                cabin_rear + REAR_WINDOW_RAKE * l,
                cabin_front - WINDSCREEN_RAKE * l,
                ROOF_WIDTH * w,
                top,
            ],
        },
    ];
    let mut mesh = RenderMesh {
        vertices: Vec::with_capacity(48),
        indices: Vec::with_capacity(72),
        has_tex_coords: false,
    };
    for p in &parts {
        p.append_to(&mut mesh);
    }
    mesh
}
