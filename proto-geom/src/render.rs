//! Owned, shading-split meshes for renderers and exporters (`alloc` feature).

use alloc::collections::BTreeMap;
use alloc::vec::Vec;

use ackermann::Real;
use nalgebra::{Isometry3, Point3, Vector3};

use crate::glue::{isometry_f64, point_f64, to_f32, vector_f64};
use crate::mesh::TriMesh;

/// One vertex of a [`RenderMesh`]: single precision, as GPUs and glTF want it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RenderVertex {
    /// Position (m), a flat vertex-buffer entry.
    pub position: [f32; 3],
    /// Unit normal, a flat vertex-buffer entry.
    pub normal: [f32; 3],
    /// Texture coordinate `[u, v]` (VRML convention, origin bottom left); zero if the source
    /// mesh has none.
    pub tex_coord: [f32; 2],
}

/// A [`TriMesh`] flattened for rendering: one vertex per distinct (position, normal) pair, so
/// smooth corners share vertices and sharp edges split them.
///
/// The tyre keeps Webots' vertex count (its normals are per vertex); the rim contour gains
/// 2(S + 1) vertices along its two sharp edges; the flat-shaded rim centre gets three vertices per
/// triangle; vertices no triangle uses are dropped.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RenderMesh {
    /// The vertices.
    pub vertices: Vec<RenderVertex>,
    /// Triangle list: three indices into `vertices` per triangle, counter-clockwise seen from
    /// outside.
    pub indices: Vec<u32>,
    /// Whether the texture coordinates are meaningful.
    pub has_tex_coords: bool,
}

impl RenderMesh {
    /// Flattens `mesh`, mapping positions and normals through `transform` (mesh frame to the
    /// output frame, translation in m; identity for the mesh's own frame). The transform is
    /// applied in `f64`, then rounded to `f32`.
    pub fn from_mesh<T: Real, M: TriMesh<T> + ?Sized>(mesh: &M, transform: &Isometry3<T>) -> Self {
        let transform = isometry_f64(transform);
        let mut map: BTreeMap<(u32, u32), u32> = BTreeMap::new();
        let mut out = RenderMesh {
            vertices: Vec::new(),
            indices: Vec::with_capacity(3 * mesh.triangle_count()),
            has_tex_coords: mesh.has_tex_coords(),
        };
        for t in 0..mesh.triangle_count() {
            let (Some(corners), Some(normals)) = (mesh.triangle(t), mesh.triangle_normals(t))
            else {
                continue;
            };
            for (v, n) in corners.into_iter().zip(normals) {
                let next = u32::try_from(out.vertices.len()).unwrap_or(u32::MAX);
                let index = *map.entry((v, n)).or_insert_with(|| {
                    let p = mesh
                        .position(v as usize)
                        .map_or(Point3::origin(), |p| point_f64(&p));
                    let normal = mesh
                        .normal(n as usize)
                        .map_or(Vector3::x(), |n| vector_f64(&n));
                    let uv = mesh.tex_coord(v as usize).unwrap_or([T::ZERO; 2]);
                    out.vertices.push(RenderVertex {
                        position: to_f32((transform * p).coords.into()),
                        normal: to_f32((transform * normal).into()),
                        tex_coord: uv.map(|c| c.to_f64() as f32),
                    });
                    next
                });
                out.indices.push(index);
            }
        }
        out
    }

    /// Number of triangles.
    #[inline]
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Component-wise minimum and maximum of the positions (m); zeros for an empty mesh.
    pub fn bounds(&self) -> ([f32; 3], [f32; 3]) {
        let mut it = self.vertices.iter().map(|v| v.position);
        let Some(first) = it.next() else {
            return ([0.0; 3], [0.0; 3]);
        };
        it.fold((first, first), |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1]), lo[2].min(p[2])],
                [hi[0].max(p[0]), hi[1].max(p[1]), hi[2].max(p[2])],
            )
        })
    }
}
