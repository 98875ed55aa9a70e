//! Export of wheels and vehicle layouts to Wavefront OBJ and binary glTF 2.0 (`std` feature).
//!
//! A [`Scene`] is a small node tree of named, placed [`RenderMesh`]es with PBR materials.
//! Build one with [`Scene::wheel`] or [`Scene::vehicle`], then write it with
//! [`Scene::write_obj`] (+ [`Scene::write_mtl`]) or [`Scene::to_glb`].
//!
//! ```
//! use proto_geom::export::Scene;
//! use proto_geom::WheelPreset;
//!
//! let (wheel, _) = WheelPreset::BmwX5Wheel.params::<f64>().validate();
//! let scene = Scene::wheel(&wheel);
//! let mut obj = Vec::new();
//! scene.write_obj(&mut obj, None).unwrap();
//! let text = String::from_utf8(obj).unwrap();
//! assert!(text.contains("o tyre") && text.contains("o rim") && text.contains("o hub"));
//! let glb = scene.to_glb().unwrap();
//! assert_eq!(&glb[0..4], b"glTF");
//! ```

mod glb;
mod obj;

pub use glb::vehicle_to_gltf;

use std::string::{String, ToString};
use std::vec::Vec;

use ackermann::{Real, Wheel};
use nalgebra::{Isometry3, Point3, Vector3};

use crate::glue::{identity, isometry_f64};
use crate::layout::VehicleLayout;
use crate::mesh::BoxMesh;
use crate::render::RenderMesh;
use crate::wheel::{PbrAppearance, ValidWheel, WheelParams, WheelShape, WheelSide};

/// The parts of one wheel in a scene: (node name, mesh index).
type WheelParts = Vec<(&'static str, usize)>;

/// A PBR material (glTF metallic-roughness; OBJ gets a Phong approximation in the MTL file).
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// Material name.
    pub name: String,
    /// Linear RGB base colour, each in [0, 1].
    pub base_color: [f32; 3],
    /// Roughness in [0, 1].
    pub roughness: f32,
    /// Metalness in [0, 1].
    pub metalness: f32,
}

impl Material {
    /// A material named `name` from a Webots `PBRAppearance`.
    pub fn from_appearance<T: Real>(name: &str, a: &PbrAppearance<T>) -> Self {
        let c = |v: T| (v.to_f64() as f32).clamp(0.0, 1.0);
        Material {
            name: name.to_string(),
            base_color: a.base_color.map(c),
            roughness: c(a.roughness),
            metalness: c(a.metalness),
        }
    }
}

/// A node of a [`Scene`]: a named frame, placed relative to its parent, with an optional mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    /// Node name (OBJ object names are built from it).
    pub name: String,
    /// Placement relative to the parent (translation in m), in the vehicle frame convention
    /// (z up).
    pub transform: Isometry3<f64>,
    /// Index into [`Scene::meshes`].
    pub mesh: Option<usize>,
    /// Indices into [`Scene::nodes`].
    pub children: Vec<usize>,
}

/// A mesh of a [`Scene`] with its material.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneMesh {
    /// Mesh name.
    pub name: String,
    /// The geometry, in the node's frame.
    pub mesh: RenderMesh,
    /// Index into [`Scene::materials`].
    pub material: usize,
}

/// An axis-aligned box standing in for the vehicle body, in the vehicle frame (m).
///
/// The body shape is not this crate's business (it belongs to the car model above it), so the
/// exporter takes it as a parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChassisBox<T: Real> {
    /// Box centre (m, vehicle frame: x forward, y left, z up from the wheel-centre plane).
    pub centre: Point3<T>,
    /// Full lengths along x, y, z (m).
    pub size: Vector3<T>,
}

impl<T: Real> ChassisBox<T> {
    /// A box spanning x ∈ [`rear`, `front`], y ∈ ±`width`/2 and z ∈ [`bottom`, `top`] (m).
    pub fn from_extents(rear: T, front: T, width: T, bottom: T, top: T) -> Self {
        ChassisBox {
            centre: Point3::new((rear + front) * T::HALF, T::ZERO, (bottom + top) * T::HALF),
            size: Vector3::new((front - rear).abs(), width.abs(), (top - bottom).abs()),
        }
    }
}

/// A node tree of placed meshes (z-up vehicle frame), ready to be written as OBJ or glTF.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Scene {
    /// All nodes.
    pub nodes: Vec<Node>,
    /// Root node indices.
    pub roots: Vec<usize>,
    /// Meshes, shared between nodes.
    pub meshes: Vec<SceneMesh>,
    /// Materials.
    pub materials: Vec<Material>,
}

/// The wheel with the fields that do not change its meshes normalised, to share meshes.
fn mesh_key<T: Real>(w: &ValidWheel<T>) -> WheelParams<T> {
    WheelParams {
        name: "",
        side: WheelSide::Right,
        contact_material: "",
        physics: crate::wheel::WheelPhysics::None,
        ..*w.params()
    }
}

impl Scene {
    /// An empty scene.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a material (or finds an equal one) and returns its index.
    pub fn add_material(&mut self, material: Material) -> usize {
        if let Some(i) = self.materials.iter().position(|m| *m == material) {
            return i;
        }
        self.materials.push(material);
        self.materials.len() - 1
    }

    /// Adds a mesh with a material index and returns its index.
    pub fn add_mesh(&mut self, name: &str, mesh: RenderMesh, material: usize) -> usize {
        self.meshes.push(SceneMesh {
            name: name.to_string(),
            mesh,
            material,
        });
        self.meshes.len() - 1
    }

    /// Adds a node under `parent` (or as a root) and returns its index.
    pub fn add_node(
        &mut self,
        parent: Option<usize>,
        name: &str,
        transform: Isometry3<f64>,
        mesh: Option<usize>,
    ) -> usize {
        let index = self.nodes.len();
        self.nodes.push(Node {
            name: name.to_string(),
            transform,
            mesh,
            children: Vec::new(),
        });
        match parent.and_then(|p| self.nodes.get_mut(p)) {
            Some(p) => p.children.push(index),
            None => self.roots.push(index),
        }
        index
    }

    /// Adds the meshes of `wheel` and returns `(name, mesh index, tyre?)` for each part: `tyre`,
    /// `rim` (rim contour) and `hub` (rim centre with beams) for a `VehicleWheel`; a single
    /// `tyre` cylinder for the other shapes (the Tractor's real cylinder, or the bounding
    /// cylinder standing in for a custom mesh).
    fn add_wheel_meshes<T: Real>(&mut self, wheel: &ValidWheel<T>) -> WheelParts {
        let p = wheel.params();
        let tyre_mat = self.add_material(Material::from_appearance("tyre", &p.tire_appearance));
        let id = identity::<T>();
        match p.shape {
            WheelShape::VehicleWheel => {
                let rim_mat =
                    self.add_material(Material::from_appearance("rim", &p.rim_appearance));
                let tyre = RenderMesh::from_mesh(&wheel.tyre(), &id);
                let rim = RenderMesh::from_mesh(&wheel.rim_contour(), &id);
                let hub = RenderMesh::from_mesh(&wheel.rim_centre(), &id);
                std::vec![
                    ("tyre", self.add_mesh("tyre", tyre, tyre_mat)),
                    ("rim", self.add_mesh("rim", rim, rim_mat)),
                    ("hub", self.add_mesh("hub", hub, rim_mat)),
                ]
            }
            WheelShape::Cylinder | WheelShape::CustomMesh => {
                let cylinder =
                    crate::mesh::CylinderMesh::new(p.tire_radius, p.thickness, wheel.subdivision());
                let tyre = RenderMesh::from_mesh(&cylinder, &id);
                std::vec![("tyre", self.add_mesh("tyre", tyre, tyre_mat))]
            }
        }
    }

    /// A single wheel in its own frame (axle = x): one root node `wheel` with the children
    /// `tyre`, `rim` and `hub` (see [`WheelShape`] for the other shapes).
    pub fn wheel<T: Real>(wheel: &ValidWheel<T>) -> Self {
        let mut scene = Scene::new();
        let root = scene.add_node(None, "wheel", Isometry3::identity(), None);
        for (name, mesh) in scene.add_wheel_meshes(wheel) {
            scene.add_node(Some(root), name, Isometry3::identity(), Some(mesh));
        }
        scene
    }

    /// A whole vehicle: root `name` at the vehicle origin, a `chassis` box, and one node per
    /// wheel (`front_right_wheel`, …, placed by [`WheelFrame::pose`](crate::WheelFrame)) with
    /// its `tyre` (turned by π on left wheels, as `wheelSide` does), `rim` and `hub`. Wheels
    /// with identical geometry share meshes.
    pub fn vehicle<T: Real>(
        name: &str,
        layout: &VehicleLayout<T>,
        chassis: &ChassisBox<T>,
    ) -> Self {
        let mut scene = Scene::new();
        let root = scene.add_node(None, name, Isometry3::identity(), None);
        let body = Material {
            name: "chassis".to_string(),
            base_color: [0.45, 0.5, 0.55],
            roughness: 0.5,
            metalness: 0.2,
        };
        let body = scene.add_material(body);
        let chassis_mesh = BoxMesh::new(chassis.centre, chassis.size);
        let chassis_mesh = RenderMesh::from_mesh(&chassis_mesh, &identity::<T>());
        let chassis_mesh = scene.add_mesh("chassis", chassis_mesh, body);
        scene.add_node(
            Some(root),
            "chassis",
            Isometry3::identity(),
            Some(chassis_mesh),
        );

        let mut shared: Vec<(WheelParams<T>, WheelParts)> = Vec::new();
        for wheel in Wheel::ALL {
            let valid = layout.wheel(wheel);
            let key = mesh_key(valid);
            let parts = match shared.iter().find(|(k, _)| *k == key) {
                Some((_, parts)) => parts.clone(),
                None => {
                    let parts = scene.add_wheel_meshes(valid);
                    shared.push((key, parts.clone()));
                    parts
                }
            };
            let frame = layout.frame(wheel);
            let node_name = match wheel {
                Wheel::FrontRight => "front_right_wheel",
                Wheel::FrontLeft => "front_left_wheel",
                Wheel::RearRight => "rear_right_wheel",
                Wheel::RearLeft => "rear_left_wheel",
            };
            let pose = isometry_f64(&frame.pose);
            let node = scene.add_node(Some(root), node_name, pose, None);
            let tyre_local = pose.inverse() * isometry_f64(&frame.tyre_pose);
            for (part, mesh) in parts {
                let t = if part == "tyre" {
                    tyre_local
                } else {
                    Isometry3::identity()
                };
                scene.add_node(Some(node), part, t, Some(mesh));
            }
        }
        scene
    }

    /// Total triangle count over all mesh instances (a shared mesh counts once per node).
    pub fn instance_triangle_count(&self) -> usize {
        self.nodes
            .iter()
            .filter_map(|n| n.mesh)
            .filter_map(|m| self.meshes.get(m))
            .map(|m| m.mesh.triangle_count())
            .sum()
    }

    /// Visits every node with a mesh, depth first, with its world transform and its name path
    /// (ancestor names joined by `.`, without the root's).
    fn for_each_instance(&self, mut f: impl FnMut(&str, &Isometry3<f64>, &SceneMesh)) {
        let mut stack: Vec<(usize, Isometry3<f64>, String)> = self
            .roots
            .iter()
            .rev()
            .filter_map(|&r| {
                let n = self.nodes.get(r)?;
                Some((r, n.transform, String::new()))
            })
            .collect();
        while let Some((i, world, path)) = stack.pop() {
            let Some(node) = self.nodes.get(i) else {
                continue;
            };
            // A root's own name is not part of the object names, so a single wheel gives `tyre`.
            let name = if self.roots.contains(&i) {
                String::new()
            } else if path.is_empty() {
                node.name.clone()
            } else {
                std::format!("{path}.{}", node.name)
            };
            if let Some(mesh) = node.mesh.and_then(|m| self.meshes.get(m)) {
                let label = if name.is_empty() {
                    node.name.as_str()
                } else {
                    &name
                };
                f(label, &world, mesh);
            }
            for &c in node.children.iter().rev() {
                if let Some(child) = self.nodes.get(c) {
                    stack.push((c, world * child.transform, name.clone()));
                }
            }
        }
    }
}
