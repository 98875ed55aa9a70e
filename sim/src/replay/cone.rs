//! The replay's traffic cones (`[[cone]]`): the cone's own polyhedron, flat-shaded, in its own
//! colour.

use proto_geom::RenderMesh;
use proto_geom::export::{Material, Scene};

use super::shapes::push_face;
use crate::world::Cone;

/// The mesh of `cone` in a frame at its base's centre (m) and the index of its material in
/// `scene` (one per colour: `Scene::add_material` shares equal materials).
pub(super) fn mesh(scene: &mut Scene, cone: &Cone) -> (RenderMesh, usize) {
    let (corners, faces) = cone.polyhedron();
    let mut mesh = RenderMesh::default();
    for face in &faces {
        let points: Vec<[f64; 3]> = face
            .iter()
            .filter_map(|&k| corners.get(k))
            .map(|p| [p.x, p.y, p.z])
            .collect();
        push_face(&mut mesh, &points);
    }
    // A cone's plastic: rough and not metallic, as the replay's other solids.
    let paint = Material::new("cone", cone.color.map(|c| c as f32), 0.8, 0.0);
    (mesh, scene.add_material(paint))
}
