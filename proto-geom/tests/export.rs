//! OBJ and glTF export, parsed back.
#![cfg(feature = "std")]
// Test helpers outside #[test] functions unwrap too: a failed lookup is a failed test.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::FRAC_PI_4;

use ackermann::Wheel;
use proto_geom::export::{
    Animation, AnimationError, ChassisBox, Geometry, Interpolation, Keyframes, Material, Property,
    Scene, vehicle_to_gltf,
};
use proto_geom::nalgebra::{Isometry3, Vector3};
use proto_geom::{RenderMesh, ShippedVehicle, TriMesh, WheelPreset};

fn bmw_wheel() -> proto_geom::ValidWheel<f64> {
    WheelPreset::BmwX5Wheel.params::<f64>().validate().0
}

#[test]
fn render_mesh_splits_only_sharp_edges() {
    let w = bmw_wheel();
    let id = Isometry3::identity();
    // Tyre: smooth, one normal per vertex → Webots' 370 vertices.
    let tyre = RenderMesh::from_mesh(&w.tyre(), &id);
    assert_eq!((tyre.vertices.len(), tyre.triangle_count()), (370, 648));
    // Rim contour: the two inner rings carry an annulus and a cylinder normal:
    // 4·37 + 2·37 = 222 vertices.
    let rim = RenderMesh::from_mesh(&w.rim_contour(), &id);
    assert_eq!((rim.vertices.len(), rim.triangle_count()), (222, 216));
    // Rim centre: flat, three vertices per triangle (85 triangles).
    let hub = RenderMesh::from_mesh(&w.rim_centre(), &id);
    assert_eq!((hub.vertices.len(), hub.triangle_count()), (255, 85));
}

#[test]
fn wheel_obj_has_three_named_objects() {
    let w = bmw_wheel();
    let scene = Scene::wheel(&w);
    let mut out = Vec::new();
    scene.write_obj(&mut out, Some("wheel.mtl")).unwrap();
    let text = String::from_utf8(out).unwrap();
    let objects: Vec<_> = text.lines().filter_map(|l| l.strip_prefix("o ")).collect();
    assert_eq!(objects, ["tyre", "rim", "hub"]);
    assert!(text.contains("mtllib wheel.mtl"));
    let count = |p: &str| text.lines().filter(|l| l.starts_with(p)).count();
    assert_eq!(count("f "), 648 + 216 + 85);
    assert_eq!(count("v "), 370 + 222 + 255);
    assert_eq!(count("vn "), count("v "));
    // The largest radius written is the tread, 0.374 m.
    let max_r = text
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let c: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
            c[1].hypot(c[2])
        })
        .fold(0.0, f64::max);
    assert!((max_r - 0.374).abs() < 1e-6);
    let mut mtl = Vec::new();
    scene.write_mtl(&mut mtl).unwrap();
    let mtl = String::from_utf8(mtl).unwrap();
    assert!(mtl.contains("newmtl tyre") && mtl.contains("newmtl rim"));
    // BmwX5Wheel rim: baseColor 0.7, roughness 0.5.
    assert!(mtl.contains("Kd 0.7 0.7 0.7") && mtl.contains("Pr 0.5"));
}

/// Parses a .glb with the `gltf` crate (which validates the document) and returns, per mesh,
/// its name, vertex count and triangle count, read from the buffers.
fn parse_glb(bytes: &[u8]) -> (gltf::Gltf, Vec<(String, usize, usize)>) {
    let doc = gltf::Gltf::from_slice(bytes).expect("valid glTF");
    let blob = doc.blob.clone().expect("binary chunk");
    let mut meshes = Vec::new();
    for mesh in doc.meshes() {
        let prim = mesh.primitives().next().unwrap();
        assert_eq!(prim.mode(), gltf::mesh::Mode::Triangles);
        let reader = prim.reader(|_| Some(&blob));
        let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
        let normals: Vec<[f32; 3]> = reader.read_normals().unwrap().collect();
        assert_eq!(normals.len(), positions.len());
        for n in &normals {
            let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((l - 1.0).abs() < 1e-5);
        }
        let indices: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
        assert!(indices.iter().all(|&i| (i as usize) < positions.len()));
        meshes.push((
            mesh.name().unwrap().to_string(),
            positions.len(),
            indices.len() / 3,
        ));
    }
    (doc, meshes)
}

#[test]
fn wheel_glb_round_trip() {
    let w = bmw_wheel();
    let glb = Scene::wheel(&w).to_glb().unwrap();
    let (doc, meshes) = parse_glb(&glb);
    assert_eq!(
        meshes,
        [
            ("tyre".to_string(), 370, w.tyre().triangle_count()),
            ("rim".to_string(), 222, w.rim_contour().triangle_count()),
            ("hub".to_string(), 255, w.rim_centre().triangle_count()),
        ]
    );
    // The tyre has texture coordinates; v is flipped to glTF's top-left origin (1 − 10·i/S).
    let tyre = doc.meshes().next().unwrap().primitives().next().unwrap();
    let blob = doc.blob.clone().unwrap();
    let uv: Vec<[f32; 2]> = tyre
        .reader(|_| Some(&blob))
        .read_tex_coords(0)
        .unwrap()
        .into_f32()
        .collect();
    assert_eq!(uv[0], [0.0, 1.0]);
    assert_eq!(uv[369], [1.0, -9.0]);
    // Materials: tyre and rim (the hub shares the rim's).
    assert_eq!(doc.materials().count(), 2);
}

#[test]
fn vehicle_glb_round_trip() {
    let layout = ShippedVehicle::BmwX5.layout::<f64>();
    let chassis = ChassisBox::from_extents(-1.0, 3.85, 1.75, 0.0, 1.45);
    let scene = Scene::vehicle("BmwX5", &layout, &chassis);
    // 4 identical wheels share their meshes: chassis + tyre + rim + hub.
    assert_eq!(scene.meshes.len(), 4);
    assert_eq!(scene.instance_triangle_count(), 12 + 4 * (648 + 216 + 85));
    let (doc, meshes) = parse_glb(&scene.to_glb().unwrap());
    let names: Vec<_> = meshes.iter().map(|m| m.0.as_str()).collect();
    assert_eq!(names, ["chassis", "tyre", "rim", "hub"]);
    assert_eq!((meshes[0].1, meshes[0].2), (24, 12));
    // Node placement: the front-right wheel at (L, −Tf/2, 0) = (2.995, −0.814, 0) in the
    // vehicle frame, under a root that turns z-up into glTF's y-up.
    let fr = doc
        .nodes()
        .find(|n| n.name() == Some("front_right_wheel"))
        .unwrap();
    let (t, _, _) = fr.transform().decomposed();
    assert_eq!(t, [2.995, -0.814, 0.0]);
    let scene_root = doc.default_scene().unwrap().nodes().next().unwrap();
    assert_eq!(scene_root.name(), Some("webots_to_gltf"));
    let (_, r, _) = scene_root.transform().decomposed();
    assert_eq!(r, [-0.5, -0.5, -0.5, 0.5]);
    // That rotation maps vehicle up (+z) to glTF up (+y) and forward (+x) to glTF +z.
    let q = vehicle_to_gltf();
    assert!((q * Vector3::z() - Vector3::y()).norm() < 1e-15);
    assert!((q * Vector3::x() - Vector3::z()).norm() < 1e-15);
    // Every wheel node has tyre, rim and hub children; left tyres are turned by π about z.
    let fl = doc
        .nodes()
        .find(|n| n.name() == Some("front_left_wheel"))
        .unwrap();
    let tyre = fl.children().find(|c| c.name() == Some("tyre")).unwrap();
    let (_, r, _) = tyre.transform().decomposed();
    assert!((r[2].abs() - 1.0).abs() < 1e-6 && r[3].abs() < 1e-6);
    assert_eq!(fl.children().count(), 3);
}

#[test]
fn every_shipped_vehicle_exports() {
    for v in ShippedVehicle::ALL {
        let layout = v.layout::<f64>();
        let d = layout.dimensions();
        let chassis = ChassisBox::from_extents(-0.5, d.wheelbase + 0.5, d.track_front, 0.0, 1.0);
        let scene = Scene::vehicle(v.proto_name(), &layout, &chassis);
        if v == ShippedVehicle::CitroenCZero {
            // Chassis, then the front wheels' meshes and the rear wheels' (both rear slots
            // hold the rear wheel, whose tyre is wider).
            assert_eq!(scene.meshes.len(), 7);
        }
        let (_, meshes) = parse_glb(&scene.to_glb().unwrap());
        assert!(meshes.len() >= 2, "{v:?}");
        // Non-VehicleWheel wheels are a single cylinder: 4S triangles (Tractor: S = 24).
        if v == ShippedVehicle::Tractor {
            let tyre_triangles: Vec<_> = meshes.iter().skip(1).map(|m| m.2).collect();
            assert_eq!(tyre_triangles, [96, 96]);
        }
    }
}

#[test]
fn f32_meshes_export_too() {
    let (w, _) = WheelPreset::TruckWheel.params::<f32>().validate();
    let glb = Scene::wheel(&w).to_glb().unwrap();
    let (_, meshes) = parse_glb(&glb);
    assert_eq!(meshes[2].2, w.rim_centre().triangle_count());
}

/// A scene with one node carrying a polyline and one carrying segments, and an animation that
/// moves, turns and hides them.
fn animated_scene() -> (Scene, Animation) {
    let mut scene = Scene::new();
    let red = scene.add_material(
        Material::new("red", [1.0, 0.0, 0.0], 1.0, 0.0).with_emissive([1.0, 0.0, 0.0]),
    );
    let path = scene.add_geometry(
        "path",
        Geometry::Polyline(vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 2.0, 0.0]]),
        red,
    );
    let grid = scene.add_geometry(
        "grid",
        // The odd last point is ignored: two segments.
        Geometry::Segments(vec![
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0; 3],
            [0.0, 1.0, 0.0],
            [5.0; 3],
        ]),
        red,
    );
    let a = scene.add_node(None, "a", Isometry3::identity(), Some(path));
    let b = scene.add_node(Some(a), "b", Isometry3::identity(), Some(grid));
    let mut anim = Animation::new("drive");
    let t = anim.add_timeline(vec![0.0, 0.5, 1.0]);
    let lights = anim.add_timeline(vec![0.0, 0.75]);
    anim.add_channel(
        a,
        t,
        Interpolation::Linear,
        Keyframes::Translation(vec![[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]),
    );
    // Half turns about z given with alternating signs: the writer makes them continuous.
    let (s, c) = (FRAC_PI_4.sin() as f32, FRAC_PI_4.cos() as f32);
    anim.add_channel(
        a,
        t,
        Interpolation::Linear,
        Keyframes::Rotation(vec![
            [0.0, 0.0, 0.0, 2.0],
            [0.0, 0.0, -s, -c],
            [0.0, 0.0, -1.0, 0.0],
        ]),
    );
    anim.add_channel(
        b,
        lights,
        Interpolation::Step,
        Keyframes::Scale(vec![[1.0; 3], [0.0; 3]]),
    );
    (scene, anim)
}

#[test]
fn animations_and_lines_round_trip() {
    let (mut scene, anim) = animated_scene();
    assert_eq!(scene.add_animation(anim), Ok(0));
    let glb = scene.to_glb().unwrap();
    let doc = gltf::Gltf::from_slice(&glb).expect("valid glTF");
    let blob = doc.blob.clone().unwrap();
    let modes: Vec<_> = doc
        .meshes()
        .map(|m| {
            let p = m.primitives().next().unwrap();
            let n = p.reader(|_| Some(&blob)).read_positions().unwrap().count();
            (p.mode(), n)
        })
        .collect();
    assert_eq!(
        modes,
        [
            (gltf::mesh::Mode::LineStrip, 3),
            (gltf::mesh::Mode::Lines, 4)
        ]
    );
    let red = doc.materials().next().unwrap();
    assert_eq!(red.emissive_factor(), [1.0, 0.0, 0.0]);
    let anims: Vec<_> = doc.animations().collect();
    assert_eq!(anims.len(), 1);
    assert_eq!(anims[0].name(), Some("drive"));
    let mut seen = Vec::new();
    for channel in anims[0].channels() {
        let reader = channel.reader(|_| Some(&blob));
        let times: Vec<f32> = reader.read_inputs().unwrap().collect();
        let node = channel.target().node().name().unwrap().to_string();
        let interpolation = channel.sampler().interpolation();
        match reader.read_outputs().unwrap() {
            gltf::animation::util::ReadOutputs::Translations(v) => {
                assert_eq!(times, [0.0, 0.5, 1.0]);
                assert_eq!(v.last(), Some([2.0, 0.0, 0.0]));
                seen.push((node, "translation", interpolation));
            }
            gltf::animation::util::ReadOutputs::Rotations(r) => {
                let q: Vec<[f32; 4]> = r.into_f32().collect();
                // Normalised, and each within 90° of the previous one in 4-D.
                assert_eq!(q[0], [0.0, 0.0, 0.0, 1.0]);
                for w in q.windows(2) {
                    let dot: f32 = w[0].iter().zip(&w[1]).map(|(a, b)| a * b).sum();
                    assert!(dot > 0.0, "{q:?}");
                }
                assert_eq!(q[2], [0.0, 0.0, 1.0, 0.0]);
                seen.push((node, "rotation", interpolation));
            }
            gltf::animation::util::ReadOutputs::Scales(v) => {
                assert_eq!(times, [0.0, 0.75]);
                assert_eq!(v.collect::<Vec<_>>(), [[1.0; 3], [0.0; 3]]);
                seen.push((node, "scale", interpolation));
            }
            gltf::animation::util::ReadOutputs::MorphTargetWeights(_) => unreachable!(),
        }
    }
    use gltf::animation::Interpolation as I;
    assert_eq!(
        seen,
        [
            ("a".to_string(), "translation", I::Linear),
            ("a".to_string(), "rotation", I::Linear),
            ("b".to_string(), "scale", I::Step),
        ]
    );
    // Two timelines, stored once each although the first drives two channels.
    let inputs: std::collections::BTreeSet<usize> =
        anims[0].samplers().map(|s| s.input().index()).collect();
    assert_eq!(inputs.len(), 2);
}

#[test]
fn bad_animations_are_refused_with_their_reason() {
    let (mut scene, anim) = animated_scene();
    let mut late = anim.clone();
    late.timelines[0][2] = 0.5;
    assert_eq!(
        scene.add_animation(late),
        Err(AnimationError::BadTime {
            timeline: 0,
            index: 2,
            time: 0.5
        })
    );
    let mut short = anim.clone();
    short.timelines[1].push(2.0);
    assert_eq!(
        scene.add_animation(short),
        Err(AnimationError::CountMismatch {
            channel: 2,
            times: 3,
            values: 2
        })
    );
    let mut twice = anim.clone();
    twice.channels.push(twice.channels[0].clone());
    assert_eq!(
        scene.add_animation(twice),
        Err(AnimationError::DuplicateTarget {
            channel: 3,
            node: 0,
            property: Property::Translation
        })
    );
    let mut lost = anim.clone();
    lost.channels[2].node = 7;
    assert_eq!(
        scene.add_animation(lost),
        Err(AnimationError::UnknownNode {
            channel: 2,
            node: 7
        })
    );
    let mut nan = anim.clone();
    nan.channels[1].values = Keyframes::Rotation(vec![[0.0; 4]; 3]);
    assert_eq!(
        scene.add_animation(nan.clone()),
        Err(AnimationError::BadValue { channel: 1 })
    );
    assert_eq!(
        scene.add_animation(Animation::new("empty")),
        Err(AnimationError::NoChannel)
    );
    assert!(scene.animations.is_empty());
    // Pushed past the check, the writer refuses it too.
    scene.animations.push(nan);
    let e = scene.to_glb().unwrap_err();
    assert_eq!(e.kind(), std::io::ErrorKind::InvalidInput);
    assert!(e.to_string().contains("channel 1"), "{e}");
}

#[test]
fn two_vehicles_share_wheel_meshes_and_name_their_nodes() {
    let layout = ShippedVehicle::BmwX5.layout::<f64>();
    let chassis = ChassisBox::from_extents(-1.0, 3.85, 1.75, 0.0, 1.45);
    let mut scene = Scene::new();
    let world = scene.add_node(None, "world", Isometry3::identity(), None);
    let grey = Material::new("grey", [0.5; 3], 0.5, 0.0);
    let blue = Material::new("blue", [0.1, 0.2, 0.8], 0.5, 0.0);
    let a = scene.add_vehicle(Some(world), "car0", &layout, &chassis, grey);
    let b = scene.add_vehicle(Some(world), "car1", &layout, &chassis, blue);
    // Two chassis (two materials), one tyre, rim and hub for all eight wheels.
    assert_eq!(scene.meshes.len(), 5);
    assert_eq!(scene.nodes[world].children, [a.root, b.root]);
    assert_eq!(
        scene.nodes[b.wheels[Wheel::RearLeft]].name,
        "rear_left_wheel"
    );
    assert_eq!(scene.nodes[a.chassis].name, "chassis");
    assert_ne!(a.wheels[Wheel::FrontRight], b.wheels[Wheel::FrontRight]);
}

#[test]
fn a_camera_looks_from_its_eye_at_its_target_in_the_gltf_frame() {
    use proto_geom::export::{Camera, CameraError};
    use proto_geom::nalgebra::{Point3, Quaternion, UnitQuaternion};

    let mut scene = Scene::new();
    let car = scene.add_node(None, "car", Isometry3::translation(10.0, 0.0, 0.0), None);
    let (eye, target) = (Point3::new(-6.0, 1.0, 2.5), Point3::new(1.4, 0.0, 0.5));
    let camera = Camera::perspective("chase", 0.7, 0.1, 500.0).unwrap();
    let node = scene
        .add_camera(Some(car), "chase_camera", eye, target, camera)
        .unwrap();
    assert_eq!(scene.nodes[node].camera, Some(0));
    assert_eq!(scene.nodes[car].children, [node]);

    let glb = scene.to_glb().unwrap();
    let doc = gltf::Gltf::from_slice(&glb).unwrap();
    let cam = doc.cameras().next().unwrap();
    assert_eq!(cam.name(), Some("chase"));
    let gltf::camera::Projection::Perspective(p) = cam.projection() else {
        panic!("a perspective camera");
    };
    // f32 in the file: equal to f32 rounding.
    assert_eq!((p.yfov(), p.znear(), p.zfar()), (0.7, 0.1, Some(500.0)));
    // The camera node's world rotation: the root's (z-up to y-up), the car's (none), its own.
    let gltf_node = doc
        .nodes()
        .find(|n| n.name() == Some("chase_camera"))
        .unwrap();
    assert_eq!(gltf_node.camera().map(|c| c.index()), Some(0));
    let [x, y, z, w] = gltf_node.transform().decomposed().1;
    let own = UnitQuaternion::from_quaternion(Quaternion::new(
        f64::from(w),
        f64::from(x),
        f64::from(y),
        f64::from(z),
    ));
    let world = vehicle_to_gltf() * own;
    // glTF cameras look along −z with +y up.
    let look = world * -Vector3::z();
    let expected = vehicle_to_gltf() * (target - eye).normalize();
    assert!((look - expected).norm() < 1e-6, "{look} vs {expected}");
    let up = world * Vector3::y();
    // Up is glTF's +y side (the vehicle frame's +z), and square to the view.
    assert!(up.y > 0.9 && up.dot(&look).abs() < 1e-6, "{up}");

    // Implausible values are refused, naming the value.
    assert_eq!(
        Camera::perspective("c", 3.2, 0.1, 1.0),
        Err(CameraError::FieldOfView(3.2))
    );
    assert_eq!(
        Camera::perspective("c", 0.7, 0.0, 1.0),
        Err(CameraError::Near(0.0))
    );
    assert_eq!(
        Camera::perspective("c", 0.7, 2.0, 1.0),
        Err(CameraError::Far(1.0))
    );
    let c = Camera::perspective("c", 0.7, 0.1, 1.0).unwrap();
    assert_eq!(
        scene.add_camera(None, "c", eye, eye, c),
        Err(CameraError::NoDirection(0.0))
    );
    assert_eq!(scene.cameras.len(), 1);
}
