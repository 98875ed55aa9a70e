//! Capped cylinders and boxes: the Tractor wheels, stand-ins for custom wheel meshes, bounding
//! cylinders and simple chassis shapes.

use ackermann::Real;
use nalgebra::{Point3, Vector3};

use super::{TriMesh, circle_angle, idx};
use crate::glue::x_axis;

/// A closed cylinder of radius `radius` and length `height` (m) about the local x axis, centred
/// on the origin, with S segments.
///
/// Vertices: the side (2 rings of S + 1, the last repeating the first for the texture seam),
/// then each cap (centre and S rim points, −x cap first): 4S + 4 vertices, 4S triangles. Side
/// normals are smooth, cap normals flat (±x); the normal list is indexed like the vertices.
/// Texture coordinates: u = i/S, v = 0 (−x) or 1 (+x) on the side, a planar disc map on the caps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderMesh<T> {
    radius: T,
    half_height: T,
    s: u32,
}

impl<T: Real> CylinderMesh<T> {
    /// A cylinder of `radius` and `height` (m) with `subdivision` segments (at least 3; fewer
    /// are raised to 3, non-finite sizes become 0).
    pub fn new(radius: T, height: T, subdivision: u32) -> Self {
        CylinderMesh {
            radius: radius.finite_or(T::ZERO).abs(),
            half_height: height.finite_or(T::ZERO).abs() * T::HALF,
            s: subdivision.max(3),
        }
    }

    #[inline]
    fn side_len(&self) -> usize {
        2 * (self.s as usize + 1)
    }

    #[inline]
    fn cap_len(&self) -> usize {
        self.s as usize + 1
    }

    /// (part, index within part): part 0 side, 1 the −x cap, 2 the +x cap.
    fn split(&self, vertex: usize) -> Option<(usize, usize)> {
        let side = self.side_len();
        let cap = self.cap_len();
        if vertex < side {
            Some((0, vertex))
        } else if vertex < side + cap {
            Some((1, vertex - side))
        } else if vertex < side + 2 * cap {
            Some((2, vertex - side - cap))
        } else {
            None
        }
    }
}

impl<T: Real> TriMesh<T> for CylinderMesh<T> {
    fn vertex_count(&self) -> usize {
        4 * self.s as usize + 4
    }

    fn triangle_count(&self) -> usize {
        4 * self.s as usize
    }

    fn normal_count(&self) -> usize {
        self.vertex_count()
    }

    fn position(&self, vertex: usize) -> Option<Point3<T>> {
        let h = self.half_height;
        let (part, k) = self.split(vertex)?;
        let ring = self.s as usize + 1;
        let (x, i, r) = match part {
            0 => (if k < ring { -h } else { h }, k % ring, self.radius),
            1 | 2 if k == 0 => {
                return Some(Point3::new(
                    if part == 1 { -h } else { h },
                    T::ZERO,
                    T::ZERO,
                ));
            }
            1 => (-h, k - 1, self.radius),
            _ => (h, k - 1, self.radius),
        };
        let a = circle_angle(i, self.s, T::ZERO);
        Some(Point3::new(x, r * a.cos(), r * a.sin()))
    }

    fn triangle(&self, triangle: usize) -> Option<[u32; 3]> {
        let s = self.s as usize;
        if triangle >= self.triangle_count() {
            return None;
        }
        if triangle < 2 * s {
            let (i, second) = (triangle / 2, triangle % 2 == 1);
            let (a, b) = (i, i + 1);
            let (c, d) = (s + 1 + i + 1, s + 1 + i);
            return Some(if second {
                [idx(c), idx(d), idx(a)]
            } else {
                [idx(a), idx(b), idx(c)]
            });
        }
        let k = triangle - 2 * s;
        let (cap, i) = (k / s, k % s);
        let base = self.side_len() + cap * self.cap_len();
        let centre = idx(base);
        let p = |j: usize| idx(base + 1 + j % s);
        Some(if cap == 0 {
            [centre, p(i + 1), p(i)]
        } else {
            [centre, p(i), p(i + 1)]
        })
    }

    fn normal(&self, normal: usize) -> Option<Vector3<T>> {
        let (part, k) = self.split(normal)?;
        Some(match part {
            0 => {
                let a = circle_angle(k % (self.s as usize + 1), self.s, T::ZERO);
                Vector3::new(T::ZERO, a.cos(), a.sin())
            }
            1 => -x_axis::<T>().into_inner(),
            _ => x_axis().into_inner(),
        })
    }

    fn triangle_normals(&self, triangle: usize) -> Option<[u32; 3]> {
        self.triangle(triangle)
    }

    fn crease_angle(&self) -> T {
        // Webots `Cylinder`: smooth side, sharp cap edges.
        T::FRAC_PI_2 * T::HALF
    }

    fn has_tex_coords(&self) -> bool {
        true
    }

    fn tex_coord(&self, vertex: usize) -> Option<[T; 2]> {
        let (part, k) = self.split(vertex)?;
        let s = T::from_f64(f64::from(self.s));
        Some(match part {
            0 => {
                let ring = self.s as usize + 1;
                let u = T::from_f64((k % ring) as f64) / s;
                [u, if k < ring { T::ZERO } else { T::ONE }]
            }
            _ if k == 0 => [T::HALF, T::HALF],
            _ => {
                let a = circle_angle(k - 1, self.s, T::ZERO);
                [T::HALF + T::HALF * a.cos(), T::HALF + T::HALF * a.sin()]
            }
        })
    }
}

/// An axis-aligned box (m): 6 faces of 4 vertices (24 vertices, 12 triangles), flat normals.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxMesh<T: Real> {
    centre: Point3<T>,
    half: Vector3<T>,
}

/// (normal, u axis, v axis) of each face, with u × v = normal.
const FACES: [([i8; 3], [i8; 3], [i8; 3]); 6] = [
    ([1, 0, 0], [0, 1, 0], [0, 0, 1]),
    ([-1, 0, 0], [0, 0, 1], [0, 1, 0]),
    ([0, 1, 0], [0, 0, 1], [1, 0, 0]),
    ([0, -1, 0], [1, 0, 0], [0, 0, 1]),
    ([0, 0, 1], [1, 0, 0], [0, 1, 0]),
    ([0, 0, -1], [0, 1, 0], [1, 0, 0]),
];

fn axis<T: Real>(a: [i8; 3]) -> Vector3<T> {
    Vector3::new(
        T::from_i32(i32::from(a[0])),
        T::from_i32(i32::from(a[1])),
        T::from_i32(i32::from(a[2])),
    )
}

impl<T: Real> BoxMesh<T> {
    /// A box centred on `centre` (m, mesh frame) with full edge lengths `size` = (x, y, z) (m).
    /// Negative or non-finite sizes are taken as their absolute value or 0.
    pub fn new(centre: Point3<T>, size: Vector3<T>) -> Self {
        BoxMesh {
            centre,
            half: size.map(|v| v.finite_or(T::ZERO).abs() * T::HALF),
        }
    }

    fn face(&self, f: usize) -> Option<(Vector3<T>, Vector3<T>, Vector3<T>)> {
        let (n, u, v) = FACES.get(f)?;
        Some((axis(*n), axis(*u), axis(*v)))
    }
}

impl<T: Real> TriMesh<T> for BoxMesh<T> {
    fn vertex_count(&self) -> usize {
        24
    }

    fn triangle_count(&self) -> usize {
        12
    }

    fn normal_count(&self) -> usize {
        24
    }

    fn position(&self, vertex: usize) -> Option<Point3<T>> {
        let (n, u, v) = self.face(vertex / 4)?;
        let (su, sv) = match vertex % 4 {
            0 => (-T::ONE, -T::ONE),
            1 => (T::ONE, -T::ONE),
            2 => (T::ONE, T::ONE),
            _ => (-T::ONE, T::ONE),
        };
        let scale = |d: Vector3<T>, k: T| d.component_mul(&self.half) * k;
        Some(self.centre + scale(n, T::ONE) + scale(u, su) + scale(v, sv))
    }

    fn triangle(&self, triangle: usize) -> Option<[u32; 3]> {
        if triangle >= 12 {
            return None;
        }
        let b = idx(4 * (triangle / 2));
        Some(if triangle.is_multiple_of(2) {
            [b, b + 1, b + 2]
        } else {
            [b, b + 2, b + 3]
        })
    }

    fn normal(&self, normal: usize) -> Option<Vector3<T>> {
        self.face(normal / 4).map(|(n, _, _)| n)
    }

    fn triangle_normals(&self, triangle: usize) -> Option<[u32; 3]> {
        self.triangle(triangle)
    }

    fn crease_angle(&self) -> T {
        T::ZERO
    }
}
