//! Binary glTF 2.0 (.glb) writer, on the `gltf-json` document model.

use std::collections::BTreeMap;
use std::io::{self, Write};
use std::string::{String, ToString};
use std::vec::Vec;

use gltf_json as json;
use json::validation::{Checked, USize64};

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::{Animation, Geometry, Interpolation, Keyframes, Scene};

/// The rotation from the Webots/vehicle frame (x forward, y left, z up) to glTF's (y up,
/// z forward, x left): glTF (x, y, z) = vehicle (y, z, x), a turn of −2π/3 rad about (1, 1, 1).
pub fn vehicle_to_gltf() -> UnitQuaternion<f64> {
    // w, i, j, k; already unit.
    UnitQuaternion::new_unchecked(Quaternion::new(0.5, -0.5, -0.5, -0.5))
}

fn u64_len(n: usize) -> USize64 {
    USize64(u64::try_from(n).unwrap_or(u64::MAX))
}

fn index_u32<T>(i: usize) -> json::Index<T> {
    json::Index::new(u32::try_from(i).unwrap_or(u32::MAX))
}

/// Appends `data` to the binary buffer as a new buffer view, 4-byte aligned.
fn push_view(
    root: &mut json::Root,
    bin: &mut Vec<u8>,
    data: &[u8],
    target: Option<json::buffer::Target>,
) -> json::Index<json::buffer::View> {
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let offset = bin.len();
    bin.extend_from_slice(data);
    root.push(json::buffer::View {
        buffer: json::Index::new(0),
        byte_length: u64_len(data.len()),
        byte_offset: Some(u64_len(offset)),
        byte_stride: None,
        name: None,
        target: target.map(Checked::Valid),
        extensions: None,
        extras: Default::default(),
    })
}

fn accessor(
    view: json::Index<json::buffer::View>,
    count: usize,
    component: json::accessor::ComponentType,
    type_: json::accessor::Type,
    bounds: Option<(&[f32], &[f32])>,
) -> json::Accessor {
    let (min, max) = match bounds {
        Some((lo, hi)) => (
            Some(json::Value::from(lo.to_vec())),
            Some(json::Value::from(hi.to_vec())),
        ),
        None => (None, None),
    };
    json::Accessor {
        buffer_view: Some(view),
        byte_offset: None,
        count: u64_len(count),
        component_type: Checked::Valid(json::accessor::GenericComponentType(component)),
        extensions: None,
        extras: Default::default(),
        type_: Checked::Valid(type_),
        min,
        max,
        name: None,
        normalized: false,
        sparse: None,
    }
}

fn f32_bytes(values: impl Iterator<Item = f32>) -> Vec<u8> {
    values.flat_map(f32::to_le_bytes).collect()
}

/// A primitive without material: positions, normals, texture coordinates if any, indices.
fn triangles(
    root: &mut json::Root,
    bin: &mut Vec<u8>,
    mesh: &crate::render::RenderMesh,
) -> json::mesh::Primitive {
    use json::accessor::{ComponentType, Type};
    use json::buffer::Target;

    let n = mesh.vertices.len();
    let positions = f32_bytes(mesh.vertices.iter().flat_map(|v| v.position));
    let view = push_view(root, bin, &positions, Some(Target::ArrayBuffer));
    let (lo, hi) = mesh.bounds();
    let pos = root.push(accessor(
        view,
        n,
        ComponentType::F32,
        Type::Vec3,
        Some((&lo, &hi)),
    ));
    let normals = f32_bytes(mesh.vertices.iter().flat_map(|v| v.normal));
    let view = push_view(root, bin, &normals, Some(Target::ArrayBuffer));
    let nor = root.push(accessor(view, n, ComponentType::F32, Type::Vec3, None));
    let mut attributes = BTreeMap::new();
    attributes.insert(Checked::Valid(json::mesh::Semantic::Positions), pos);
    attributes.insert(Checked::Valid(json::mesh::Semantic::Normals), nor);
    if mesh.has_tex_coords {
        // glTF puts the texture origin at the top left, VRML at the bottom left.
        let uv = f32_bytes(
            mesh.vertices
                .iter()
                .flat_map(|v| [v.tex_coord[0], 1.0 - v.tex_coord[1]]),
        );
        let view = push_view(root, bin, &uv, Some(Target::ArrayBuffer));
        let tex = root.push(accessor(view, n, ComponentType::F32, Type::Vec2, None));
        attributes.insert(Checked::Valid(json::mesh::Semantic::TexCoords(0)), tex);
    }
    let indices: Vec<u8> = mesh.indices.iter().flat_map(|i| i.to_le_bytes()).collect();
    let view = push_view(root, bin, &indices, Some(Target::ElementArrayBuffer));
    let ind = root.push(accessor(
        view,
        mesh.indices.len(),
        ComponentType::U32,
        Type::Scalar,
        None,
    ));
    json::mesh::Primitive {
        attributes,
        extensions: None,
        extras: Default::default(),
        indices: Some(ind),
        material: None,
        mode: Checked::Valid(json::mesh::Mode::Triangles),
        targets: None,
    }
}

/// A line or point primitive without material: positions only (no normals: lines and points
/// are not lit by the glTF lighting model).
fn lines(
    root: &mut json::Root,
    bin: &mut Vec<u8>,
    points: &[[f32; 3]],
    mode: json::mesh::Mode,
) -> json::mesh::Primitive {
    use json::accessor::{ComponentType, Type};

    let bytes = f32_bytes(points.iter().flatten().copied());
    let view = push_view(root, bin, &bytes, Some(json::buffer::Target::ArrayBuffer));
    let (lo, hi) = bounds(points);
    let pos = root.push(accessor(
        view,
        points.len(),
        ComponentType::F32,
        Type::Vec3,
        Some((&lo, &hi)),
    ));
    let mut attributes = BTreeMap::new();
    attributes.insert(Checked::Valid(json::mesh::Semantic::Positions), pos);
    json::mesh::Primitive {
        attributes,
        extensions: None,
        extras: Default::default(),
        indices: None,
        material: None,
        mode: Checked::Valid(mode),
        targets: None,
    }
}

/// Component-wise minimum and maximum of `points`; zeros for none.
fn bounds<const N: usize>(points: &[[f32; N]]) -> ([f32; N], [f32; N]) {
    let Some(&first) = points.first() else {
        return ([0.0; N], [0.0; N]);
    };
    points.iter().fold((first, first), |(mut lo, mut hi), p| {
        for k in 0..N {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
        (lo, hi)
    })
}

/// Unit quaternions `[x, y, z, w]`, each with the sign nearest the previous one: slerp between
/// two keyframes then turns the short way, whatever sign the caller gave.
fn continuous_rotations(values: &[[f32; 4]]) -> Vec<[f32; 4]> {
    let mut out: Vec<[f32; 4]> = Vec::with_capacity(values.len());
    for q in values {
        let norm = q.iter().map(|c| c * c).sum::<f32>().sqrt();
        let mut u = q.map(|c| c / norm);
        if let Some(p) = out.last()
            && p.iter().zip(&u).map(|(a, b)| a * b).sum::<f32>() < 0.0
        {
            u = u.map(|c| -c);
        }
        out.push(u);
    }
    out
}

/// Writes one animation: each timeline as an input accessor (with its min and max, as glTF
/// requires), each channel as an output accessor, a sampler and a channel. Animation data has
/// no buffer-view target (it is not vertex data).
fn push_animation(root: &mut json::Root, bin: &mut Vec<u8>, animation: &Animation) {
    use json::accessor::{ComponentType, Type};
    use json::animation::{Channel, Property, Sampler, Target};

    let inputs: Vec<_> = animation
        .timelines
        .iter()
        .map(|times| {
            let view = push_view(root, bin, &f32_bytes(times.iter().copied()), None);
            let lo = times.first().copied().unwrap_or(0.0);
            let hi = times.last().copied().unwrap_or(0.0);
            root.push(accessor(
                view,
                times.len(),
                ComponentType::F32,
                Type::Scalar,
                Some((&[lo], &[hi])),
            ))
        })
        .collect();
    let mut samplers = Vec::new();
    let mut channels = Vec::new();
    for c in &animation.channels {
        let Some(&input) = inputs.get(c.timeline) else {
            continue;
        };
        let (data, count, type_, path) = match &c.values {
            Keyframes::Translation(v) => (
                f32_bytes(v.iter().flatten().copied()),
                v.len(),
                Type::Vec3,
                Property::Translation,
            ),
            Keyframes::Scale(v) => (
                f32_bytes(v.iter().flatten().copied()),
                v.len(),
                Type::Vec3,
                Property::Scale,
            ),
            Keyframes::Rotation(v) => (
                f32_bytes(continuous_rotations(v).iter().flatten().copied()),
                v.len(),
                Type::Vec4,
                Property::Rotation,
            ),
        };
        let view = push_view(root, bin, &data, None);
        let output = root.push(accessor(view, count, ComponentType::F32, type_, None));
        let interpolation = match c.interpolation {
            Interpolation::Linear => json::animation::Interpolation::Linear,
            Interpolation::Step => json::animation::Interpolation::Step,
        };
        channels.push(Channel {
            sampler: index_u32(samplers.len()),
            target: Target {
                extensions: None,
                extras: Default::default(),
                node: index_u32(c.node),
                path: Checked::Valid(path),
            },
            extensions: None,
            extras: Default::default(),
        });
        samplers.push(Sampler {
            extensions: None,
            extras: Default::default(),
            input,
            interpolation: Checked::Valid(interpolation),
            output,
        });
    }
    root.push(json::Animation {
        extensions: None,
        extras: Default::default(),
        channels,
        name: Some(animation.name.clone()),
        samplers,
    });
}

impl Scene {
    /// Builds the glTF document and its binary buffer.
    fn gltf(&self) -> (json::Root, Vec<u8>) {
        let mut root = json::Root {
            asset: json::Asset {
                generator: Some("proto-geom".to_string()),
                ..Default::default()
            },
            ..Default::default()
        };
        let mut bin = Vec::new();

        for m in &self.materials {
            let [r, g, b] = m.base_color;
            root.push(json::Material {
                name: Some(m.name.clone()),
                pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                    base_color_factor: json::material::PbrBaseColorFactor([r, g, b, 1.0]),
                    metallic_factor: json::material::StrengthFactor(m.metalness),
                    roughness_factor: json::material::StrengthFactor(m.roughness),
                    ..Default::default()
                },
                emissive_factor: json::material::EmissiveFactor(m.emissive),
                ..Default::default()
            });
        }

        for sm in &self.meshes {
            let primitive = match &sm.geometry {
                Geometry::Triangles(mesh) => triangles(&mut root, &mut bin, mesh),
                Geometry::Segments(points) => {
                    let even = &points[..points.len() / 2 * 2];
                    lines(&mut root, &mut bin, even, json::mesh::Mode::Lines)
                }
                Geometry::Polyline(points) => {
                    lines(&mut root, &mut bin, points, json::mesh::Mode::LineStrip)
                }
                Geometry::Points(points) => {
                    lines(&mut root, &mut bin, points, json::mesh::Mode::Points)
                }
            };
            let primitive = json::mesh::Primitive {
                material: (sm.material < self.materials.len()).then(|| index_u32(sm.material)),
                ..primitive
            };
            root.push(json::Mesh {
                extensions: None,
                extras: Default::default(),
                name: Some(sm.name.clone()),
                primitives: std::vec![primitive],
                weights: None,
            });
        }

        for c in &self.cameras {
            root.push(json::Camera {
                name: Some(c.name.clone()),
                orthographic: None,
                perspective: Some(json::camera::Perspective {
                    // Without an aspect ratio the viewer uses its viewport's.
                    aspect_ratio: None,
                    yfov: c.yfov as f32,
                    zfar: Some(c.zfar as f32),
                    znear: c.znear as f32,
                    extensions: None,
                    extras: Default::default(),
                }),
                type_: Checked::Valid(json::camera::Type::Perspective),
                extensions: None,
                extras: Default::default(),
            });
        }

        let f = |v: Vector3<f64>| [v.x as f32, v.y as f32, v.z as f32];
        let node = |name: String,
                    translation: Vector3<f64>,
                    rotation: UnitQuaternion<f64>,
                    mesh: Option<usize>,
                    children: &[usize],
                    visible: bool,
                    camera: Option<usize>| json::Node {
            camera: camera.map(index_u32),
            children: (!children.is_empty())
                .then(|| children.iter().map(|&c| index_u32(c)).collect()),
            extensions: None,
            extras: Default::default(),
            matrix: None,
            mesh: mesh.map(index_u32),
            name: Some(name),
            rotation: Some(json::scene::UnitQuaternion(
                // glTF's order is [x, y, z, w], nalgebra's `coords`.
                rotation.coords.map(|c| c as f32).into(),
            )),
            scale: (!visible).then_some([0.0; 3]),
            translation: Some(f(translation)),
            skin: None,
            weights: None,
        };
        for n in &self.nodes {
            root.push(node(
                n.name.clone(),
                n.transform.translation.vector,
                n.transform.rotation,
                n.mesh,
                &n.children,
                n.visible,
                n.camera.filter(|&c| c < self.cameras.len()),
            ));
        }
        // A last node turns the z-up vehicle frame into glTF's y-up frame.
        let up = root.push(node(
            "webots_to_gltf".to_string(),
            Vector3::zeros(),
            vehicle_to_gltf(),
            None,
            &self.roots,
            true,
            None,
        ));
        for animation in &self.animations {
            push_animation(&mut root, &mut bin, animation);
        }
        let scene = root.push(json::Scene {
            extensions: None,
            extras: Default::default(),
            name: Some("scene".to_string()),
            nodes: std::vec![up],
        });
        root.scene = Some(scene);
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        if !bin.is_empty() {
            root.push(json::Buffer {
                byte_length: u64_len(bin.len()),
                name: None,
                uri: None,
                extensions: None,
                extras: Default::default(),
            });
        }
        (root, bin)
    }

    /// The scene as a binary glTF 2.0 file (.glb): one buffer, one mesh per [`super::SceneMesh`]
    /// (triangles with positions, normals, texture coordinates for the tyre and `u32` indices;
    /// or lines, `LINES` or `LINE_STRIP`, with positions only), metallic-roughness materials
    /// with their emission, the perspective cameras, the node tree under a root node that turns
    /// the z-up vehicle frame into glTF's y-up frame, and the animations (time in s, one input
    /// accessor per timeline).
    ///
    /// # Errors
    /// An animation that fails [`Animation::validate`] (pushed to [`Scene::animations`]
    /// directly), as [`io::ErrorKind::InvalidInput`]; a JSON serialisation failure or a file
    /// larger than 4 GiB, as [`io::Error`].
    pub fn to_glb(&self) -> io::Result<Vec<u8>> {
        for animation in &self.animations {
            animation
                .validate(self.nodes.len())
                .map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e))?;
        }
        let (root, bin) = self.gltf();
        let mut json_bytes = json::serialize::to_vec(&root).map_err(io::Error::other)?;
        while !json_bytes.len().is_multiple_of(4) {
            json_bytes.push(b' ');
        }
        let total = 12 + 8 + json_bytes.len() + if bin.is_empty() { 0 } else { 8 + bin.len() };
        let len32 = |n: usize| {
            u32::try_from(n).map_err(|_| io::Error::other("glTF binary larger than 4 GiB"))
        };
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&len32(total)?.to_le_bytes());
        out.extend_from_slice(&len32(json_bytes.len())?.to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&json_bytes);
        if !bin.is_empty() {
            out.extend_from_slice(&len32(bin.len())?.to_le_bytes());
            out.extend_from_slice(b"BIN\0");
            out.extend_from_slice(&bin);
        }
        Ok(out)
    }

    /// Writes [`Scene::to_glb`] to `w`.
    ///
    /// # Errors
    /// As [`Scene::to_glb`], plus any error of `w`.
    pub fn write_glb<W: Write>(&self, w: &mut W) -> io::Result<()> {
        w.write_all(&self.to_glb()?)
    }
}
