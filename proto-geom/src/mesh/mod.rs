//! Allocation-free triangle meshes: the `VehicleWheel` tyre, rim contour and rim centre, plus
//! cylinders and boxes for the other wheel shapes and chassis stand-ins.
//!
//! A mesh computes every vertex on demand from a handful of parameters, so nothing is stored
//! and nothing is allocated: read it through [`TriMesh`] one element at a time, iterate, or
//! copy it into caller-provided buffers with the `fill_*` methods.
//!
//! Normals follow the OBJ / VRML `normalIndex` model: a mesh has its own list of normals and
//! each triangle corner names one. Where Webots' `creaseAngle` smooths (the tyre, the rim
//! contour around the axle) neighbouring corners share a smooth normal; across sharper edges
//! (rim annulus to inner cylinder) and on the rim centre (`creaseAngle` 0) corners take the flat
//! normal of their face.

mod primitive;
mod rim;
mod tyre;

use core::fmt;

use ackermann::Real;
use nalgebra::{Point3, Vector3};

use crate::glue::{dot, norm};

pub use primitive::{BoxMesh, CylinderMesh};
pub use rim::{RimCentreMesh, RimContourMesh};
pub use tyre::TyreMesh;

/// A caller-provided buffer was shorter than the mesh data to copy.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BufferTooSmall {
    /// Elements needed.
    pub needed: usize,
    /// Elements provided.
    pub given: usize,
}

impl fmt::Display for BufferTooSmall {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "buffer too small: {} elements needed, {} given",
            self.needed, self.given
        )
    }
}

impl core::error::Error for BufferTooSmall {}

/// Copies `count` items produced by `get` into `out`.
fn fill<U>(
    out: &mut [U],
    count: usize,
    mut get: impl FnMut(usize) -> Option<U>,
) -> Result<usize, BufferTooSmall> {
    if out.len() < count {
        return Err(BufferTooSmall {
            needed: count,
            given: out.len(),
        });
    }
    for (i, slot) in out.iter_mut().take(count).enumerate() {
        if let Some(v) = get(i) {
            *slot = v;
        }
    }
    Ok(count)
}

/// An indexed triangle mesh whose elements are computed on demand.
///
/// Coordinates are in m in the mesh's own frame (for wheel parts: the wheel frame, axle = x).
/// Triangles are counter-clockwise seen from outside (right-hand rule gives the outward
/// normal). Every accessor returns `None` for an out-of-range index instead of panicking.
pub trait TriMesh<T: Real> {
    /// Number of vertices (positions).
    fn vertex_count(&self) -> usize;

    /// Number of triangles.
    fn triangle_count(&self) -> usize;

    /// Number of entries in the normal list.
    fn normal_count(&self) -> usize;

    /// Position of vertex `vertex` (m, mesh frame).
    fn position(&self, vertex: usize) -> Option<Point3<T>>;

    /// Vertex indices of triangle `triangle`, counter-clockwise seen from outside.
    fn triangle(&self, triangle: usize) -> Option<[u32; 3]>;

    /// Unit normal number `normal` (a direction in the mesh frame).
    fn normal(&self, normal: usize) -> Option<Vector3<T>>;

    /// Normal-list indices of the three corners of triangle `triangle`.
    fn triangle_normals(&self, triangle: usize) -> Option<[u32; 3]>;

    /// The Webots `creaseAngle` (rad) the normals reproduce.
    fn crease_angle(&self) -> T;

    /// True if the mesh has per-vertex texture coordinates.
    fn has_tex_coords(&self) -> bool {
        false
    }

    /// Texture coordinate `[u, v]` of vertex `vertex` (VRML convention: origin at the bottom
    /// left of the image), `None` if the mesh has none.
    fn tex_coord(&self, vertex: usize) -> Option<[T; 2]> {
        let _ = vertex;
        None
    }

    /// The three corner positions of triangle `triangle` (m).
    fn triangle_positions(&self, triangle: usize) -> Option<[Point3<T>; 3]> {
        let [a, b, c] = self.triangle(triangle)?;
        Some([
            self.position(a as usize)?,
            self.position(b as usize)?,
            self.position(c as usize)?,
        ])
    }

    /// The three corner unit normals of triangle `triangle`.
    fn corner_normals(&self, triangle: usize) -> Option<[Vector3<T>; 3]> {
        let [a, b, c] = self.triangle_normals(triangle)?;
        Some([
            self.normal(a as usize)?,
            self.normal(b as usize)?,
            self.normal(c as usize)?,
        ])
    }

    /// Iterates over the vertex positions (m).
    fn positions(&self) -> impl Iterator<Item = Point3<T>> + '_
    where
        Self: Sized,
    {
        (0..self.vertex_count()).filter_map(|i| self.position(i))
    }

    /// Iterates over the triangles' vertex indices.
    fn triangles(&self) -> impl Iterator<Item = [u32; 3]> + '_
    where
        Self: Sized,
    {
        (0..self.triangle_count()).filter_map(|i| self.triangle(i))
    }

    /// Copies the positions (m) into `out` as flat `[x, y, z]` triples (a vertex buffer);
    /// returns the number written.
    ///
    /// # Errors
    /// [`BufferTooSmall`] if `out` is shorter than [`TriMesh::vertex_count`] (nothing written).
    fn fill_positions(&self, out: &mut [[T; 3]]) -> Result<usize, BufferTooSmall> {
        fill(out, self.vertex_count(), |i| {
            self.position(i).map(|p| p.coords.into())
        })
    }

    /// Copies the triangles' vertex indices into `out`; returns the number written.
    ///
    /// # Errors
    /// [`BufferTooSmall`] if `out` is shorter than [`TriMesh::triangle_count`].
    fn fill_triangles(&self, out: &mut [[u32; 3]]) -> Result<usize, BufferTooSmall> {
        fill(out, self.triangle_count(), |i| self.triangle(i))
    }

    /// Copies the normal list into `out` as flat `[x, y, z]` unit vectors; returns the number
    /// written.
    ///
    /// # Errors
    /// [`BufferTooSmall`] if `out` is shorter than [`TriMesh::normal_count`].
    fn fill_normals(&self, out: &mut [[T; 3]]) -> Result<usize, BufferTooSmall> {
        fill(out, self.normal_count(), |i| self.normal(i).map(Into::into))
    }

    /// Copies the corners' normal indices into `out`; returns the number written.
    ///
    /// # Errors
    /// [`BufferTooSmall`] if `out` is shorter than [`TriMesh::triangle_count`].
    fn fill_triangle_normals(&self, out: &mut [[u32; 3]]) -> Result<usize, BufferTooSmall> {
        fill(out, self.triangle_count(), |i| self.triangle_normals(i))
    }

    /// Copies the texture coordinates into `out`; returns the number written (0 for a mesh
    /// without texture coordinates).
    ///
    /// # Errors
    /// [`BufferTooSmall`] if the mesh has texture coordinates and `out` is shorter than
    /// [`TriMesh::vertex_count`].
    fn fill_tex_coords(&self, out: &mut [[T; 2]]) -> Result<usize, BufferTooSmall> {
        if !self.has_tex_coords() {
            return Ok(0);
        }
        fill(out, self.vertex_count(), |i| self.tex_coord(i))
    }

    /// Signed volume enclosed by the triangles, `Σ p0·(p1 × p2) / 6` (m³): the volume of a
    /// closed, outward-wound surface; for an open surface, the volume of the cone it spans
    /// from the origin. For finite positions the result is finite: a volume beyond the range
    /// of `T` saturates at ±`T::MAX`.
    fn signed_volume(&self) -> T {
        let direct = triple_product_sum(self, T::ONE) / T::from_f64(6.0);
        if direct.is_finite() {
            return direct;
        }
        let scale = max_abs_coordinate(self);
        let scaled = triple_product_sum(self, scale) / T::from_f64(6.0);
        saturating_mul(saturating_mul(saturating_mul(scaled, scale), scale), scale)
    }

    /// Total surface area (m²). For finite positions the result is finite: an area beyond the
    /// range of `T` saturates at `T::MAX`.
    fn area(&self) -> T {
        let direct = double_area_sum(self, T::ONE) * T::HALF;
        if direct.is_finite() {
            return direct;
        }
        let scale = max_abs_coordinate(self);
        let scaled = double_area_sum(self, scale) * T::HALF;
        saturating_mul(saturating_mul(scaled, scale), scale)
    }
}

// Sizes near the range of `T` (e.g. a 10²⁰ m wheel in `f32`) overflow the products of
// `signed_volume` and `area` into ∞ or ∞ − ∞ = NaN. The fallback divides every coordinate by
// the largest magnitude, so each product stays below ~10, and scales the sum back with
// saturation. The direct sum runs first so that ordinary meshes get bit-identical results.

/// `Σ p0·(p1 × p2)` over the triangles, with every coordinate divided by `scale`.
fn triple_product_sum<T: Real, M: TriMesh<T> + ?Sized>(mesh: &M, scale: T) -> T {
    let mut v = T::ZERO;
    for t in 0..mesh.triangle_count() {
        if let Some([a, b, c]) = mesh.triangle_positions(t) {
            let [a, b, c] = [a, b, c].map(|p| scaled(&p, scale));
            v += dot(&a, &b.cross(&c));
        }
    }
    v
}

/// `Σ |(p1 − p0) × (p2 − p0)|` over the triangles, with every coordinate divided by `scale`.
fn double_area_sum<T: Real, M: TriMesh<T> + ?Sized>(mesh: &M, scale: T) -> T {
    let mut s = T::ZERO;
    for t in 0..mesh.triangle_count() {
        if let Some([a, b, c]) = mesh.triangle_positions(t) {
            let [a, b, c] = [a, b, c].map(|p| scaled(&p, scale));
            s += norm(&(b - a).cross(&(c - a)));
        }
    }
    s
}

/// The position vector of `p` (m) with every coordinate divided by `scale`.
#[inline]
fn scaled<T: Real>(p: &Point3<T>, scale: T) -> Vector3<T> {
    p.coords.map(|c| c / scale)
}

/// The largest coordinate magnitude of the mesh's vertices (m), at least `T::EPSILON` so that
/// dividing by it is safe.
fn max_abs_coordinate<T: Real, M: TriMesh<T> + ?Sized>(mesh: &M) -> T {
    let mut m = T::EPSILON;
    for i in 0..mesh.vertex_count() {
        if let Some(p) = mesh.position(i) {
            m = m.max(p.x.abs()).max(p.y.abs()).max(p.z.abs());
        }
    }
    m
}

/// `a·b` limited to ±`T::MAX` (finite operands give a finite result, never NaN).
#[inline]
fn saturating_mul<T: Real>(a: T, b: T) -> T {
    (a * b).clamp(-T::MAX, T::MAX)
}

/// Index of `i` in a `u32` index buffer. Mesh sizes are bounded by the wheel validation limits,
/// so every index fits; saturating keeps a corrupt value out of range rather than wrapping.
#[inline]
fn idx(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}

/// Point `(cos, sin)` of `circle(ρ, n, shift)` number `i`, i.e. angle `2π·i/n + shift` (rad).
#[inline]
fn circle_angle<T: Real>(i: usize, n: u32, shift: T) -> T {
    T::TAU * T::from_f64(i as f64) / T::from_f64(f64::from(n)) + shift
}
