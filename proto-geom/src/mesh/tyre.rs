//! The `VehicleWheel` tyre (Webots `DEF TIRE` IndexedFaceSet).

use ackermann::Real;
use nalgebra::{Point3, Vector3};

use super::{TriMesh, circle_angle, idx};
use crate::wheel::ValidWheel;

/// The tyre of a `VehicleWheel`, with Webots' vertex order, triangle topology and texture
/// coordinates (spec §4.4).
///
/// With S = `subdivision`, E = `edgeSubdivision`: 2E + 4 rings of S + 1 vertices (the last
/// vertex of a ring repeats the first, for the texture seam), (2E + 4)(S + 1) vertices and
/// 2S(2E + 3) triangles (default wheel: 370 vertices, 648 triangles). The rings run from the
/// +x sidewall at `rimRadius`, over the +x shoulder (a quarter circle of radius
/// `thickness·curvatureFactor/2`), across the tread at `tireRadius`, over the −x shoulder, to
/// the −x sidewall. A ring point at angle θ = 2πi/S and radius ρ is `(x, −ρ·cos θ, ρ·sin θ)`.
///
/// Normals are smooth everywhere (Webots `creaseAngle 1.5` rad exceeds every angle between
/// neighbouring faces, at most 45°): each vertex carries the exact normal of the rounded profile
/// it samples, so the normal list is indexed like the vertices. With `curvatureFactor` 0 the
/// shoulders collapse, their triangles have zero area (as in Webots) and the sidewall/tread edge
/// is sharp, which the per-ring normals reproduce.
///
/// Texture coordinates: u = 0 on the +x sidewall ring, 0.125 + 0.125·j/E on the +x shoulder,
/// 0.75 + 0.125·j/E on the −x shoulder, 1 on the −x sidewall; v = 10·i/S around the axle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TyreMesh<T> {
    s: u32,
    e: u32,
    half_thickness: T,
    tire_radius: T,
    curvature: T,
    rim_radius: T,
}

/// One ring of the tyre profile.
struct Ring<T> {
    /// Lateral position (m).
    x: T,
    /// Distance from the axle (m).
    radius: T,
    /// Profile normal: axial component.
    nx: T,
    /// Profile normal: radial component.
    nr: T,
    /// Texture u.
    u: T,
}

impl<T: Real> TyreMesh<T> {
    /// The tyre of `wheel`.
    pub fn new(wheel: &ValidWheel<T>) -> Self {
        let p = wheel.params();
        TyreMesh {
            s: wheel.subdivision(),
            e: wheel.edge_subdivision(),
            half_thickness: p.thickness * T::HALF,
            tire_radius: p.tire_radius,
            curvature: p.curvature_factor,
            rim_radius: p.rim_radius,
        }
    }

    /// Vertex count `(2E + 4)(S + 1)` for `subdivision` S and `edgeSubdivision` E.
    #[inline]
    pub const fn vertex_count_for(subdivision: u32, edge_subdivision: u32) -> usize {
        (2 * edge_subdivision as usize + 4) * (subdivision as usize + 1)
    }

    /// Triangle count `2S(2E + 3)` for `subdivision` S and `edgeSubdivision` E.
    #[inline]
    pub const fn triangle_count_for(subdivision: u32, edge_subdivision: u32) -> usize {
        2 * subdivision as usize * (2 * edge_subdivision as usize + 3)
    }

    /// Vertices per ring, S + 1.
    #[inline]
    fn ring_len(&self) -> usize {
        self.s as usize + 1
    }

    /// Ring `r` (0 ..= 2E + 3) of the profile.
    fn ring(&self, r: usize) -> Ring<T> {
        let e = self.e as usize;
        let h = self.half_thickness;
        let c = self.curvature;
        let big_r = self.tire_radius;
        let beta = T::PI / T::from_f64(2.0 * f64::from(self.e));
        let rho = |i: usize| big_r - h * c * (T::ONE - (beta * T::from_f64(i as f64)).sin());
        let frac = |i: usize| T::from_f64(i as f64) / T::from_f64(f64::from(self.e));
        let eighth = T::from_f64(0.125);
        if r == 0 {
            Ring {
                x: h,
                radius: self.rim_radius,
                nx: T::ONE,
                nr: T::ZERO,
                u: T::ZERO,
            }
        } else if r <= e + 1 {
            let i = r - 1;
            let a = beta * T::from_f64(i as f64);
            Ring {
                x: h * (T::ONE - c * (T::ONE - a.cos())),
                radius: rho(i),
                nx: a.cos(),
                nr: a.sin(),
                u: eighth + eighth * frac(i),
            }
        } else if r <= 2 * e + 2 {
            let i = r - e - 2;
            let a = beta * T::from_f64(i as f64);
            Ring {
                x: -h * (T::ONE - c * (T::ONE - a.sin())),
                radius: rho(e - i),
                nx: -a.sin(),
                nr: a.cos(),
                u: T::from_f64(0.75) + eighth * frac(i),
            }
        } else {
            Ring {
                x: -h,
                radius: self.rim_radius,
                nx: -T::ONE,
                nr: T::ZERO,
                u: T::ONE,
            }
        }
    }

    /// Splits a vertex index into (ring, column), `None` if out of range.
    fn split(&self, vertex: usize) -> Option<(usize, usize)> {
        (vertex < self.vertex_count()).then(|| (vertex / self.ring_len(), vertex % self.ring_len()))
    }
}

impl<T: Real> TriMesh<T> for TyreMesh<T> {
    fn vertex_count(&self) -> usize {
        Self::vertex_count_for(self.s, self.e)
    }

    fn triangle_count(&self) -> usize {
        Self::triangle_count_for(self.s, self.e)
    }

    fn normal_count(&self) -> usize {
        self.vertex_count()
    }

    fn position(&self, vertex: usize) -> Option<Point3<T>> {
        let (r, i) = self.split(vertex)?;
        let ring = self.ring(r);
        let a = circle_angle(i, self.s, T::ZERO);
        Some(Point3::new(
            ring.x,
            -(ring.radius * a.cos()),
            ring.radius * a.sin(),
        ))
    }

    fn triangle(&self, triangle: usize) -> Option<[u32; 3]> {
        if triangle >= self.triangle_count() {
            return None;
        }
        let s = self.s as usize;
        let j = triangle / (2 * s);
        let k = triangle % (2 * s);
        let i = k / 2;
        let o0 = self.ring_len() * j;
        let o1 = o0 + self.ring_len();
        Some(if k.is_multiple_of(2) {
            [idx(o0 + i), idx(o0 + i + 1), idx(o1 + i + 1)]
        } else {
            [idx(o1 + i + 1), idx(o1 + i), idx(o0 + i)]
        })
    }

    fn normal(&self, normal: usize) -> Option<Vector3<T>> {
        let (r, i) = self.split(normal)?;
        let ring = self.ring(r);
        let a = circle_angle(i, self.s, T::ZERO);
        Some(Vector3::new(
            ring.nx,
            -(ring.nr * a.cos()),
            ring.nr * a.sin(),
        ))
    }

    fn triangle_normals(&self, triangle: usize) -> Option<[u32; 3]> {
        self.triangle(triangle)
    }

    fn crease_angle(&self) -> T {
        T::from_f64(1.5)
    }

    fn has_tex_coords(&self) -> bool {
        true
    }

    fn tex_coord(&self, vertex: usize) -> Option<[T; 2]> {
        let (r, i) = self.split(vertex)?;
        let v = T::from_f64(10.0) * T::from_f64(i as f64) / T::from_f64(f64::from(self.s));
        Some([self.ring(r).u, v])
    }
}

impl<T: Real> ValidWheel<T> {
    /// The `VehicleWheel` tyre mesh (see [`TyreMesh`]). Built from the fields whatever the
    /// wheel's [`WheelShape`](crate::WheelShape); for the other shapes use
    /// [`ValidWheel::bounding_cylinder`]'s mesh.
    #[inline]
    pub fn tyre(&self) -> TyreMesh<T> {
        TyreMesh::new(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rings_of_default_wheel() {
        let m = ValidWheel::<f64>::default().tyre();
        // E = 3: 10 rings. Ring 0: sidewall at +T/2 = 0.15 m, ρrim 0.28 m.
        let a = m.ring(0);
        assert_eq!((a.x, a.radius), (0.15, 0.28));
        // Ring 1 = B_0: x = 0.15, ρ_0 = 0.4 − 0.15·0.35 = 0.3475 m.
        let b0 = m.ring(1);
        assert!((b0.x - 0.15).abs() < 1e-15 && (b0.radius - 0.3475).abs() < 1e-15);
        // Ring 4 = B_3: x = 0.15·(1 − 0.35) = 0.0975 m, ρ_3 = R = 0.4 m.
        let b3 = m.ring(4);
        assert!((b3.x - 0.0975).abs() < 1e-15 && (b3.radius - 0.4).abs() < 1e-15);
        // Ring 5 = C_0: x = −0.0975, ρ = R. Ring 9 = D: x = −0.15, ρrim.
        let c0 = m.ring(5);
        assert!((c0.x + 0.0975).abs() < 1e-15 && (c0.radius - 0.4).abs() < 1e-15);
        let d = m.ring(9);
        assert_eq!((d.x, d.radius, d.u), (-0.15, 0.28, 1.0));
        // u of C_1 = 0.75 + 0.125/3.
        assert!((m.ring(6).u - (0.75 + 0.125 / 3.0)).abs() < 1e-15);
    }
}
