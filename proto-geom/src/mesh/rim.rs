//! The `VehicleWheel` rim: the round contour and the centre with its beams.

use ackermann::Real;
use nalgebra::{Point3, Vector3};

use super::{TriMesh, circle_angle, idx};
use crate::glue::{normalize, x_axis};
use crate::wheel::ValidWheel;

/// The rim contour of a `VehicleWheel` (Webots "Round contour" IndexedFaceSet): an annulus from
/// `rimRadius` to 0.9·`rimRadius` on each face (x = ±`thickness`/2) joined by an inner cylinder
/// at 0.9·`rimRadius`.
///
/// Webots' vertex order and topology: 4 rings of S + 1 vertices (outer at −T/2, inner at −T/2,
/// inner at +T/2, outer at +T/2; a ring point at angle θ = 2πi/S and radius ρ is
/// `(x, ρ·cos θ, ρ·sin θ)`), 4(S + 1) vertices and 6S triangles.
///
/// Normals reproduce Webots' `creaseAngle 2π/S + 0.01` rad: smooth around the axle, sharp
/// between the annuli and the cylinder. The normal list is `[−x, +x]` followed by the S + 1
/// inward radial normals of the inner cylinder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RimContourMesh<T> {
    s: u32,
    half_thickness: T,
    rim_radius: T,
}

impl<T: Real> RimContourMesh<T> {
    /// The rim contour of `wheel`.
    pub fn new(wheel: &ValidWheel<T>) -> Self {
        let p = wheel.params();
        RimContourMesh {
            s: wheel.subdivision(),
            half_thickness: p.thickness * T::HALF,
            rim_radius: p.rim_radius,
        }
    }

    /// Vertex count `4(S + 1)` for `subdivision` S.
    #[inline]
    pub const fn vertex_count_for(subdivision: u32) -> usize {
        4 * (subdivision as usize + 1)
    }

    /// Triangle count `6S` for `subdivision` S.
    #[inline]
    pub const fn triangle_count_for(subdivision: u32) -> usize {
        6 * subdivision as usize
    }

    #[inline]
    fn ring_len(&self) -> usize {
        self.s as usize + 1
    }
}

impl<T: Real> TriMesh<T> for RimContourMesh<T> {
    fn vertex_count(&self) -> usize {
        Self::vertex_count_for(self.s)
    }

    fn triangle_count(&self) -> usize {
        Self::triangle_count_for(self.s)
    }

    fn normal_count(&self) -> usize {
        2 + self.ring_len()
    }

    fn position(&self, vertex: usize) -> Option<Point3<T>> {
        if vertex >= self.vertex_count() {
            return None;
        }
        let (ring, i) = (vertex / self.ring_len(), vertex % self.ring_len());
        let h = self.half_thickness;
        let inner = self.rim_radius * T::from_f64(0.9);
        let (x, radius) = match ring {
            0 => (-h, self.rim_radius),
            1 => (-h, inner),
            2 => (h, inner),
            _ => (h, self.rim_radius),
        };
        let a = circle_angle(i, self.s, T::ZERO);
        Some(Point3::new(x, radius * a.cos(), radius * a.sin()))
    }

    fn triangle(&self, triangle: usize) -> Option<[u32; 3]> {
        if triangle >= self.triangle_count() {
            return None;
        }
        let s = self.s as usize;
        let (j, k) = (triangle / (2 * s), triangle % (2 * s));
        let i = k / 2;
        let o0 = self.ring_len() * j;
        let o1 = o0 + self.ring_len();
        Some(if k.is_multiple_of(2) {
            [idx(o0 + i + 1), idx(o0 + i), idx(o1 + i)]
        } else {
            [idx(o1 + i), idx(o1 + i + 1), idx(o0 + i + 1)]
        })
    }

    fn normal(&self, normal: usize) -> Option<Vector3<T>> {
        match normal {
            0 => Some(-x_axis::<T>().into_inner()),
            1 => Some(x_axis().into_inner()),
            n if n < self.normal_count() => {
                let a = circle_angle(n - 2, self.s, T::ZERO);
                Some(Vector3::new(T::ZERO, -a.cos(), -a.sin()))
            }
            _ => None,
        }
    }

    fn triangle_normals(&self, triangle: usize) -> Option<[u32; 3]> {
        let corners = self.triangle(triangle)?;
        let strip = triangle / (2 * self.s as usize);
        let len = self.ring_len();
        Some(match strip {
            0 => [0; 3],
            1 => corners.map(|v| idx(2 + v as usize % len)),
            _ => [1; 3],
        })
    }

    fn crease_angle(&self) -> T {
        T::TAU / T::from_f64(f64::from(self.s)) + T::from_f64(0.01)
    }
}

/// The rim centre of a `VehicleWheel` (Webots "center" IndexedFaceSet): a hub disc of radius
/// `centralOuterRadius` and N = `rimBeamNumber` beams out to `rimRadius`, all
/// `rimBeamThickness` thick along the axle and shifted by `rimBeamOffset`/2 towards −x.
///
/// The vertex list is Webots' (10N + 12 vertices): the front hub centre, ten blocks of N + 1
/// circle points (the last point of each block repeats the first), the back hub centre. With
/// b = `rimBeamThickness` and off = `rimBeamOffset`, the front face points sit at
/// x = −b/2 − off/2 (inner hub circle and beam centre lines) or −b/2.5 − off/2 (beam edges),
/// the back face at b/2 − off/2.
///
/// The triangles are a **corrected** version of Webots' (17N instead of 17N + 7): Webots'
/// index formulas forget the leading hub vertex, so each index points one vertex early; its
/// loops that start at i = 0 therefore emit a degenerate fan triangle, two coincident
/// back-to-back triangles and four triangles cutting through the hub. Here every loop runs over
/// the N beams (p = 0 … N − 1), giving the closed front face (hub fan, N gaps, N two-part
/// beams), the side walls, the back of the beams and the back hub disc. The beam ends at `rimRadius` stay open
/// (they are hidden inside the rim contour), and 7 duplicate seam points are left unreferenced
/// so the vertex numbering matches Webots. Normals are flat (Webots `creaseAngle` 0): one per
/// triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RimCentreMesh<T> {
    n: u32,
    x_front: T,
    x_edge: T,
    x_back: T,
    inner_radius: T,
    outer_radius: T,
    rim_radius: T,
    hub_shift: T,
    rim_shift: T,
}

impl<T: Real> RimCentreMesh<T> {
    /// The rim centre of `wheel`.
    pub fn new(wheel: &ValidWheel<T>) -> Self {
        let p = wheel.params();
        let b = p.rim_beam_thickness;
        let half_off = p.rim_beam_offset * T::HALF;
        let half_width = p.rim_beam_width * T::HALF;
        RimCentreMesh {
            n: wheel.rim_beam_number(),
            x_front: -b * T::HALF - half_off,
            x_edge: -b / T::from_f64(2.5) - half_off,
            x_back: b * T::HALF - half_off,
            inner_radius: p.central_inner_radius,
            outer_radius: p.central_outer_radius,
            rim_radius: p.rim_radius,
            hub_shift: half_width.atan2(p.central_outer_radius),
            rim_shift: half_width.atan2(p.rim_radius),
        }
    }

    /// Vertex count `10N + 12` for `rimBeamNumber` N (as in Webots).
    #[inline]
    pub const fn vertex_count_for(rim_beam_number: u32) -> usize {
        10 * rim_beam_number as usize + 12
    }

    /// Triangle count `17N` for `rimBeamNumber` N (Webots emits 17N + 7, see the type docs).
    #[inline]
    pub const fn triangle_count_for(rim_beam_number: u32) -> usize {
        17 * rim_beam_number as usize
    }

    /// Index of point `p` (0 ..= N) of block `m` (0 ..= 9).
    #[inline]
    fn v(&self, m: usize, p: usize) -> u32 {
        idx(1 + (self.n as usize + 1) * m + p)
    }

    /// Index of the back hub centre.
    #[inline]
    fn back_centre(&self) -> u32 {
        idx(1 + (self.n as usize + 1) * 10)
    }

    /// (radius, angular shift, x) of block `m`.
    fn block(&self, m: usize) -> (T, T, T) {
        let (ro, rr) = (self.outer_radius, self.rim_radius);
        let (h, r) = (self.hub_shift, self.rim_shift);
        match m {
            0 => (self.inner_radius, T::ZERO, self.x_front),
            1 => (ro, h, self.x_edge),
            2 => (ro, -h, self.x_edge),
            3 => (rr, T::ZERO, self.x_front),
            4 => (rr, r, self.x_edge),
            5 => (rr, -r, self.x_edge),
            6 => (ro, h, self.x_back),
            7 => (ro, -h, self.x_back),
            8 => (rr, r, self.x_back),
            _ => (rr, -r, self.x_back),
        }
    }
}

impl<T: Real> TriMesh<T> for RimCentreMesh<T> {
    fn vertex_count(&self) -> usize {
        Self::vertex_count_for(self.n)
    }

    fn triangle_count(&self) -> usize {
        Self::triangle_count_for(self.n)
    }

    fn normal_count(&self) -> usize {
        self.triangle_count()
    }

    fn position(&self, vertex: usize) -> Option<Point3<T>> {
        let len = self.n as usize + 1;
        if vertex == 0 {
            return Some(Point3::new(self.x_edge, T::ZERO, T::ZERO));
        }
        if vertex == self.back_centre() as usize {
            return Some(Point3::new(self.x_back, T::ZERO, T::ZERO));
        }
        if vertex >= self.vertex_count() {
            return None;
        }
        let (m, p) = ((vertex - 1) / len, (vertex - 1) % len);
        let (radius, shift, x) = self.block(m);
        let a = circle_angle(p, self.n, shift);
        Some(Point3::new(x, radius * a.cos(), radius * a.sin()))
    }

    fn triangle(&self, triangle: usize) -> Option<[u32; 3]> {
        let n = self.n as usize;
        if triangle >= self.triangle_count() {
            return None;
        }
        if triangle < n {
            let p = triangle;
            return Some([0, self.v(0, p + 1), self.v(0, p)]);
        }
        let k = triangle - n;
        let (group, p, second) = (k / (2 * n), (k % (2 * n)) / 2, k % 2 == 1);
        let v = |m, q| self.v(m, q);
        let q = p + 1;
        // Each group is a quad (a, b, c, d) split as (a, b, c), (c, d, a), except the back hub.
        let quad = match group {
            // Front, between beams p and p + 1: inner circle arc to hub outer arc.
            0 => [v(0, p), v(0, q), v(2, q), v(1, p)],
            // Front, beam p, +β half then −β half.
            1 => [v(0, p), v(1, p), v(4, p), v(3, p)],
            2 => [v(0, p), v(3, p), v(5, p), v(2, p)],
            // Side walls: hub between beams, then both sides of beam p.
            3 => [v(1, p), v(2, q), v(7, q), v(6, p)],
            4 => [v(1, p), v(6, p), v(8, p), v(4, p)],
            5 => [v(2, p), v(5, p), v(9, p), v(7, p)],
            // Back of beam p.
            6 => [v(8, p), v(6, p), v(7, p), v(9, p)],
            // Back hub disc: the sector under beam p, then the gap to beam p + 1.
            _ => {
                let c = self.back_centre();
                return Some(if second {
                    [c, v(6, p), v(7, q)]
                } else {
                    [c, v(7, p), v(6, p)]
                });
            }
        };
        let [a, b, c, d] = quad;
        Some(if second { [c, d, a] } else { [a, b, c] })
    }

    fn normal(&self, normal: usize) -> Option<Vector3<T>> {
        let [a, b, c] = self.triangle_positions(normal)?;
        // Every corrected triangle has positive area for valid parameters; the fallback only
        // keeps a unit vector for pathological inputs.
        Some(normalize((b - a).cross(&(c - a))).unwrap_or(-x_axis::<T>().into_inner()))
    }

    fn triangle_normals(&self, triangle: usize) -> Option<[u32; 3]> {
        (triangle < self.triangle_count()).then(|| [idx(triangle); 3])
    }

    fn crease_angle(&self) -> T {
        T::ZERO
    }
}

impl<T: Real> ValidWheel<T> {
    /// The rim contour mesh (see [`RimContourMesh`]).
    #[inline]
    pub fn rim_contour(&self) -> RimContourMesh<T> {
        RimContourMesh::new(self)
    }

    /// The rim centre (hub and beams) mesh (see [`RimCentreMesh`]).
    #[inline]
    pub fn rim_centre(&self) -> RimCentreMesh<T> {
        RimCentreMesh::new(self)
    }
}
