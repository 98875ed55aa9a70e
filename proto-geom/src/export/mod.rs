//! Export of wheels and vehicle layouts to Wavefront OBJ and binary glTF 2.0 (`std` feature).
//!
//! A [`Scene`] is a small node tree of named, placed [`RenderMesh`]es and line sets with PBR
//! materials, optionally animated ([`Animation`]). Build one with [`Scene::wheel`] or
//! [`Scene::vehicle`], or node by node (a vehicle inside a larger scene with
//! [`Scene::add_vehicle`]), then write it with [`Scene::write_obj`] (+ [`Scene::write_mtl`]) or
//! [`Scene::to_glb`] (the only one of the two that carries the animations).
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

mod animation;
mod camera;
mod car_body;
mod glb;
mod obj;

pub use animation::{Animation, AnimationError, Channel, Interpolation, Keyframes, Property};
pub use camera::{Camera, CameraError, look_at};
pub use car_body::{BELTLINE, NOSE_RAKE, TAIL_RAKE, car_body};
pub use glb::vehicle_to_gltf;

use std::string::{String, ToString};
use std::vec::Vec;

use ackermann::{PerWheel, Real, Wheel};
use nalgebra::{Isometry3, Point3, Vector3};

use crate::glue::{identity, isometry_f64};
use crate::layout::VehicleLayout;
use crate::mesh::BoxMesh;
use crate::render::RenderMesh;
use crate::wheel::{PbrAppearance, ValidWheel, WheelShape, WheelSide};

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
    /// Linear RGB light the surface emits, each in [0, 1] (glTF `emissiveFactor`; OBJ `Ke`):
    /// lamps, and lines that keep their colour whatever the lighting.
    pub emissive: [f32; 3],
}

impl Material {
    /// A material named `name` of base colour `base_color` (linear RGB), `roughness` and
    /// `metalness`, each clamped to [0, 1] (NaN becomes 0), emitting nothing.
    pub fn new(name: &str, base_color: [f32; 3], roughness: f32, metalness: f32) -> Self {
        Material {
            name: name.to_string(),
            base_color: base_color.map(unit_clamp),
            roughness: unit_clamp(roughness),
            metalness: unit_clamp(metalness),
            emissive: [0.0; 3],
        }
    }

    /// The material emitting `emissive` (linear RGB, each clamped to [0, 1]).
    pub fn with_emissive(mut self, emissive: [f32; 3]) -> Self {
        self.emissive = emissive.map(unit_clamp);
        self
    }

    /// A material named `name` from a Webots `PBRAppearance`.
    pub fn from_appearance<T: Real>(name: &str, a: &PbrAppearance<T>) -> Self {
        let c = |v: T| v.to_f64() as f32;
        Material::new(name, a.base_color.map(c), c(a.roughness), c(a.metalness))
    }
}

/// `v` clamped to [0, 1], NaN to 0.
fn unit_clamp(v: f32) -> f32 {
    if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) }
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
    /// Whether the node and its children show at rest. glTF gets a hidden node with scale 0,
    /// so that an animation's [`Keyframes::Scale`] can show it; OBJ leaves it out.
    pub visible: bool,
    /// Index into [`Scene::cameras`] of the camera the node holds (glTF only; OBJ has no
    /// cameras).
    pub camera: Option<usize>,
}

/// What a [`SceneMesh`] draws, in its node's frame (m).
#[derive(Debug, Clone, PartialEq)]
pub enum Geometry {
    /// Shaded triangles.
    Triangles(RenderMesh),
    /// Separate line segments: points 0–1, 2–3, … (an odd last point is ignored).
    Segments(Vec<[f32; 3]>),
    /// One connected line through the points in order.
    Polyline(Vec<[f32; 3]>),
    /// Separate points (glTF's `POINTS` mode; OBJ `p` elements), e.g. a lidar's returns.
    Points(Vec<[f32; 3]>),
}

impl Geometry {
    /// Number of triangles (0 for lines).
    pub fn triangle_count(&self) -> usize {
        match self {
            Geometry::Triangles(m) => m.triangle_count(),
            Geometry::Segments(_) | Geometry::Polyline(_) | Geometry::Points(_) => 0,
        }
    }
}

/// A mesh of a [`Scene`] with its material.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneMesh {
    /// Mesh name.
    pub name: String,
    /// The geometry, in the node's frame.
    pub geometry: Geometry,
    /// Index into [`Scene::materials`].
    pub material: usize,
}

/// The nodes [`Scene::add_vehicle`] made, to animate them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct VehicleNodes {
    /// The vehicle's root node, at the vehicle origin (rear-axle centre at wheel-centre height):
    /// move it to move the car.
    pub root: usize,
    /// The body box.
    pub chassis: usize,
    /// Each wheel's node, at rest at [`WheelFrame::pose`](crate::WheelFrame): turn it by the
    /// steering and spin angles (the tyre, rim and hub below it follow).
    pub wheels: PerWheel<usize>,
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
    /// Animations, checked by [`Scene::add_animation`].
    pub animations: Vec<Animation>,
    /// Cameras, each held by a node ([`Scene::add_camera`]).
    pub cameras: Vec<Camera>,
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

    /// Adds a triangle mesh with a material index and returns its index.
    pub fn add_mesh(&mut self, name: &str, mesh: RenderMesh, material: usize) -> usize {
        self.add_geometry(name, Geometry::Triangles(mesh), material)
    }

    /// Adds any geometry with a material index and returns its index.
    pub fn add_geometry(&mut self, name: &str, geometry: Geometry, material: usize) -> usize {
        self.meshes.push(SceneMesh {
            name: name.to_string(),
            geometry,
            material,
        });
        self.meshes.len() - 1
    }

    /// Adds `animation` after checking it against the scene's nodes, and returns its index.
    ///
    /// # Errors
    /// The [`AnimationError`] of [`Animation::validate`]; the scene is then unchanged.
    pub fn add_animation(&mut self, animation: Animation) -> Result<usize, AnimationError> {
        animation.validate(self.nodes.len())?;
        self.animations.push(animation);
        Ok(self.animations.len() - 1)
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
            visible: true,
            camera: None,
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
        let body = Material::new("chassis", [0.45, 0.5, 0.55], 0.5, 0.2);
        scene.add_vehicle(None, name, layout, chassis, body);
        scene
    }

    /// Adds a vehicle as [`Scene::vehicle`] builds it, under `parent` (or as a root), its body
    /// box in `body`, and returns its nodes. Wheels with identical geometry share meshes, with
    /// those of the vehicles added before too.
    pub fn add_vehicle<T: Real>(
        &mut self,
        parent: Option<usize>,
        name: &str,
        layout: &VehicleLayout<T>,
        chassis: &ChassisBox<T>,
        body: Material,
    ) -> VehicleNodes {
        let chassis_mesh = BoxMesh::new(chassis.centre, chassis.size);
        let chassis_mesh = RenderMesh::from_mesh(&chassis_mesh, &identity::<T>());
        self.add_vehicle_with(parent, name, layout, chassis_mesh, body)
    }

    /// Adds a vehicle as [`Scene::add_vehicle`] does, with a car-shaped body ([`car_body`]:
    /// lower body and tapered greenhouse) filling `chassis` instead of the box.
    pub fn add_car<T: Real>(
        &mut self,
        parent: Option<usize>,
        name: &str,
        layout: &VehicleLayout<T>,
        chassis: &ChassisBox<T>,
        body: Material,
    ) -> VehicleNodes {
        let mesh = car_body(chassis, layout.dimensions().wheelbase);
        self.add_vehicle_with(parent, name, layout, mesh, body)
    }

    fn add_vehicle_with<T: Real>(
        &mut self,
        parent: Option<usize>,
        name: &str,
        layout: &VehicleLayout<T>,
        chassis_mesh: RenderMesh,
        body: Material,
    ) -> VehicleNodes {
        let root = self.add_node(parent, name, Isometry3::identity(), None);
        let body = self.add_material(body);
        let chassis_mesh = self.add_mesh("chassis", chassis_mesh, body);
        let chassis = self.add_node(
            Some(root),
            "chassis",
            Isometry3::identity(),
            Some(chassis_mesh),
        );

        let mut wheels = PerWheel::splat(root);
        for wheel in Wheel::ALL {
            let node_name = match wheel {
                Wheel::FrontRight => "front_right_wheel",
                Wheel::FrontLeft => "front_left_wheel",
                Wheel::RearRight => "rear_right_wheel",
                Wheel::RearLeft => "rear_left_wheel",
            };
            let pose = isometry_f64(&layout.frame(wheel).pose);
            wheels[wheel] = self.add_wheel(Some(root), node_name, layout.wheel(wheel), pose);
        }
        VehicleNodes {
            root,
            chassis,
            wheels,
        }
    }

    /// Adds one wheel as a node `name` at `pose` (the wheel frame, axle = local x, as
    /// [`WheelFrame::pose`](crate::WheelFrame)) under `parent`, with the `tyre` (turned by π
    /// about z for a left wheel, as `wheelSide` does), `rim` and `hub` below it, and returns the
    /// node. Wheels of identical geometry share meshes.
    pub fn add_wheel<T: Real>(
        &mut self,
        parent: Option<usize>,
        name: &str,
        wheel: &ValidWheel<T>,
        pose: Isometry3<f64>,
    ) -> usize {
        let parts = self.wheel_parts(wheel);
        let node = self.add_node(parent, name, pose, None);
        let tyre = match wheel.params().side {
            WheelSide::Right => Isometry3::identity(),
            WheelSide::Left => Isometry3::rotation(Vector3::z() * core::f64::consts::PI),
        };
        for (part, mesh) in parts {
            let t = if part == "tyre" {
                tyre
            } else {
                Isometry3::identity()
            };
            self.add_node(Some(node), part, t, Some(mesh));
        }
        node
    }

    /// The meshes of `wheel`: those of an earlier wheel of identical geometry (and materials)
    /// if the scene has one, else new ones.
    fn wheel_parts<T: Real>(&mut self, wheel: &ValidWheel<T>) -> WheelParts {
        let fresh = self.add_wheel_meshes(wheel);
        // A wheel of the same geometry and materials gives meshes equal to earlier ones: reuse
        // those and drop the copies (they are the last ones added).
        let first_new = fresh.first().map_or(self.meshes.len(), |(_, m)| *m);
        let earlier = (0..first_new).find(|&start| {
            fresh.iter().enumerate().all(|(k, (_, m))| {
                let (a, b) = (self.meshes.get(start + k), self.meshes.get(*m));
                start + k < first_new && a.is_some() && a == b
            })
        });
        match earlier {
            Some(start) => {
                self.meshes.truncate(first_new);
                fresh
                    .into_iter()
                    .enumerate()
                    .map(|(k, (part, _))| (part, start + k))
                    .collect()
            }
            None => fresh,
        }
    }

    /// Total triangle count over all mesh instances (a shared mesh counts once per node).
    pub fn instance_triangle_count(&self) -> usize {
        self.nodes
            .iter()
            .filter_map(|n| n.mesh)
            .filter_map(|m| self.meshes.get(m))
            .map(|m| m.geometry.triangle_count())
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
            let Some(node) = self.nodes.get(i).filter(|n| n.visible) else {
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
