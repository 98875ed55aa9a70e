//! The replay's node tree: the ground and its grid, the obstacles and boxes, every car and
//! robot, and per part of the run its trajectories and cones.

use ackermann::{PerWheel, Wheel};
use proto_geom::export::{BELTLINE, Geometry, Material, NOSE_RAKE, Scene, TAIL_RAKE, VehicleNodes};
use proto_geom::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proto_geom::{BoxMesh, CylinderMesh, RenderMesh, WheelParams, WheelSide};

use super::Part;
use super::recorder::{CarModel, Recording, RobotModel};
use super::shapes::{self, Rect};
use crate::attitude::RollPitchYaw;
use crate::body::BodySpec;
use crate::config::Obstacle;

/// Body colours of the cars and robots, in order (linear RGB), reused past the last.
const PALETTE: [[f32; 3]; 5] = [
    [0.1, 0.25, 0.7],
    [0.1, 0.5, 0.2],
    [0.75, 0.75, 0.75],
    [0.5, 0.15, 0.55],
    [0.85, 0.6, 0.05],
];
/// The body colour of car (or robot) `i` (linear RGB, 0–1): its material's base colour, which
/// `report.html`'s viewer and its browser check look for on screen.
pub fn car_colour(i: usize) -> [f32; 3] {
    PALETTE[i % PALETTE.len()]
}

/// Most grid lines across the ground patch's longer side.
const MAX_GRID_LINES: f64 = 150.0;
/// Height of the grid lines above the ground, per metre of the patch's longer side: enough for
/// a renderer's depth buffer to keep them in front at any distance the whole patch is seen
/// from.
const LIFT_PER_SPAN: f64 = 2e-4;
/// Largest spacing of the cones along a lane-change cone line (m).
const CONE_SPACING: f64 = 3.0;

/// The nodes of a car the animations move.
pub(crate) struct CarNodes {
    pub(crate) vehicle: VehicleNodes,
    pub(crate) brake_lights: usize,
    pub(crate) left_indicators: usize,
    pub(crate) right_indicators: usize,
    /// Wheel rest rotations (wheel frame to car frame).
    pub(crate) wheel_rest: PerWheel<UnitQuaternion<f64>>,
    /// Wheel centres at unloaded springs (m, car frame).
    pub(crate) wheel_centres: PerWheel<Vector3<f64>>,
}

/// The nodes of a robot the animations move.
pub(crate) struct RobotNodes {
    pub(crate) root: usize,
    /// `[left, right]` wheel nodes and their rest poses (robot frame).
    pub(crate) wheels: [(usize, Isometry3<f64>); 2],
}

/// Every animated node of the replay.
pub(crate) struct Nodes {
    pub(crate) cars: Vec<CarNodes>,
    pub(crate) robots: Vec<RobotNodes>,
    pub(crate) bodies: Vec<usize>,
    /// One group per part (its trajectories and cones).
    pub(crate) parts: Vec<usize>,
    /// Each overlay radar's pool of target markers ([`super::overlay`]).
    pub(crate) radar_markers: Vec<Vec<usize>>,
    /// Each part's lidar clouds ([`super::lidar_overlay`]).
    pub(crate) lidar_clouds: Vec<Vec<super::lidar_overlay::CloudNode>>,
}

/// A frame at `at` (m) turned by `yaw` (rad) about +z.
fn pose(at: Point3<f64>, yaw: f64) -> Isometry3<f64> {
    Isometry3::from_parts(
        Translation3::from(at.coords),
        UnitQuaternion::from_euler_angles(0.0, 0.0, yaw),
    )
}

/// Two meshes as one.
fn merge(mut a: RenderMesh, b: RenderMesh) -> RenderMesh {
    let base = u32::try_from(a.vertices.len()).unwrap_or(u32::MAX);
    a.vertices.extend(b.vertices);
    a.indices.extend(b.indices.into_iter().map(|i| i + base));
    a
}

pub(super) fn box_mesh(centre: Point3<f64>, size: Vector3<f64>) -> RenderMesh {
    let mesh = BoxMesh::new(centre, size);
    RenderMesh::from_mesh(&mesh, &Isometry3::identity())
}

/// The ground rectangle the run covers: every position of every car and robot (with the
/// vehicle's reach around its origin), obstacle, box and cone line, plus a margin.
fn extent(parts: &[Part<'_>], first: &Recording) -> Rect {
    let mut rect = [f64::INFINITY, f64::INFINITY, -f64::INFINITY, -f64::INFINITY];
    let mut add = |x: f64, y: f64, reach: f64| {
        if x.is_finite() && y.is_finite() {
            rect = [
                rect[0].min(x - reach),
                rect[1].min(y - reach),
                rect[2].max(x + reach),
                rect[3].max(y + reach),
            ];
        }
    };
    let car_reach: Vec<f64> = first.cars.iter().map(car_reach).collect();
    let robot_reach: Vec<f64> = first.robots.iter().map(|r| r.params.axle_length).collect();
    for part in parts {
        for frame in &part.recording.frames {
            for (c, reach) in frame.cars.iter().zip(&car_reach) {
                add(c.position.x, c.position.y, *reach);
            }
            for (r, reach) in frame.robots.iter().zip(&robot_reach) {
                add(r.position.x, r.position.y, *reach);
            }
            for b in &frame.bodies {
                add(b.position.x, b.position.y, 0.0);
            }
        }
        for p in part.guides.iter().flatten() {
            add(p[0], p[1], shapes::CONE_RADIUS);
        }
    }
    for road in &first.roads.roads {
        for s in road.stations(0.0, road.length()) {
            let (_, edges) = road.lane_edges(s);
            for (_, _, t) in edges {
                let p = road.surface_point(s, t);
                add(p.x, p.y, 0.0);
            }
        }
    }
    let footprints = first.obstacles.iter().map(Obstacle::footprint);
    for corner in footprints
        .chain(first.bodies.iter().map(BodySpec::footprint))
        .flatten()
    {
        add(corner.x, corner.y, 0.0);
    }
    if !(rect[0] <= rect[2] && rect[1] <= rect[3]) {
        rect = [-1.0, -1.0, 1.0, 1.0];
    }
    let margin = 0.1 * (rect[2] - rect[0]).max(rect[3] - rect[1]);
    [
        rect[0] - margin,
        rect[1] - margin,
        rect[2] + margin,
        rect[3] + margin,
    ]
}

/// How far the body of `car` reaches from the car origin (m).
fn car_reach(car: &CarModel) -> f64 {
    let b = &car.body;
    let x = (b.centre.x.abs() + b.size.x / 2.0).max(1e-3);
    x.hypot(b.size.y / 2.0)
}

/// The replay scene of `parts` (its static parts from the first part's recording) and the
/// nodes its animations move.
pub(crate) fn build(parts: &[Part<'_>]) -> (Scene, Nodes) {
    let empty = Recording::default();
    let first = parts.first().map_or(&empty, |p| p.recording);
    let mut scene = Scene::new();
    let world = scene.add_node(None, "world", Isometry3::identity(), None);

    let rect = extent(parts, first);
    super::cameras::add_overview(&mut scene, world, rect);
    // A chase camera sees across the whole run from anywhere in it.
    let far = 2.0 * (rect[2] - rect[0]).hypot(rect[3] - rect[1]);
    let span = (rect[2] - rect[0]).max(rect[3] - rect[1]);
    let step = shapes::grid_step(span, MAX_GRID_LINES);
    let rect = [
        (rect[0] / step).floor() * step,
        (rect[1] / step).floor() * step,
        (rect[2] / step).ceil() * step,
        (rect[3] / step).ceil() * step,
    ];
    let lift = LIFT_PER_SPAN * span;
    let ground = Material::new("ground", [0.3, 0.33, 0.3], 0.95, 0.0);
    let ground = scene.add_material(ground);
    let mesh = scene.add_mesh("ground", shapes::ground(rect, 0.0), ground);
    let ground = scene.add_node(Some(world), "ground", Isometry3::identity(), Some(mesh));
    let grid = Material::new("grid", [0.15; 3], 1.0, 0.0).with_emissive([0.15; 3]);
    let grid = scene.add_material(grid);
    let grid_lines = Geometry::Segments(shapes::grid(rect, step, lift));
    let mesh = scene.add_geometry("grid", grid_lines, grid);
    scene.add_node(Some(ground), "grid", Isometry3::identity(), Some(mesh));

    add_obstacles(&mut scene, world, first);
    add_roads(&mut scene, world, first, lift);
    let bodies = add_bodies(&mut scene, world, first);
    let cars = first
        .cars
        .iter()
        .enumerate()
        .map(|(i, car)| add_car(&mut scene, world, i, car, first, far))
        .collect();
    let robots = first
        .robots
        .iter()
        .enumerate()
        .map(|(i, robot)| add_robot(&mut scene, world, i, robot, first))
        .collect();
    let groups = parts
        .iter()
        .map(|part| add_part(&mut scene, world, part, lift))
        .collect();
    let radar_markers = super::overlay::add_markers(&mut scene, world, first);
    let lidar_clouds = parts
        .iter()
        .enumerate()
        .map(|(p, part)| super::lidar_overlay::add_clouds(&mut scene, world, part.recording, p))
        .collect();
    (
        scene,
        Nodes {
            cars,
            robots,
            bodies,
            parts: groups,
            radar_markers,
            lidar_clouds,
        },
    )
}

/// Each road's lanes (asphalt, a lighter grey for shoulders and borders) and its painted
/// lines in their colours, the lines `lift` (m) above the lanes so that they never flicker
/// into them.
fn add_roads(scene: &mut Scene, world: usize, first: &Recording, lift: f64) {
    if first.roads.is_empty() {
        return;
    }
    let asphalt = scene.add_material(Material::new(
        "asphalt",
        crate::appearance::ASPHALT_COLOR.map(|c| c as f32),
        0.9,
        0.0,
    ));
    let verge = scene.add_material(Material::new(
        "road_border",
        crate::appearance::VERGE_COLOR.map(|c| c as f32),
        0.9,
        0.0,
    ));
    let mut paints: Vec<([f64; 3], usize)> = Vec::new();
    for road in &first.roads.roads {
        let node = scene.add_node(
            Some(world),
            &format!("road_{}", road.id),
            Isometry3::identity(),
            None,
        );
        for m in road.lane_meshes(crate::ROAD_LIFT) {
            let material = if m.kind == crate::road::LaneKind::Driving {
                asphalt
            } else {
                verge
            };
            let name = format!("road_{}_section_{}_lane_{}", road.id, m.section + 1, m.lane);
            let mesh = scene.add_mesh(
                &name,
                shapes::surface(&m.vertices, &m.triangles, 0.0),
                material,
            );
            scene.add_node(Some(node), &name, Isometry3::identity(), Some(mesh));
        }
        for (i, strip) in road
            .mark_strips(crate::ROAD_LIFT + lift)
            .into_iter()
            .enumerate()
        {
            let paint = match paints.iter().find(|(c, _)| *c == strip.colour) {
                Some(&(_, m)) => m,
                None => {
                    let colour = strip.colour.map(|c| c as f32);
                    let m = scene.add_material(Material::new(
                        &format!("paint_{}", paints.len()),
                        colour,
                        0.6,
                        0.0,
                    ));
                    paints.push((strip.colour, m));
                    m
                }
            };
            let name = format!("road_{}_line_{i}", road.id);
            let mesh = scene.add_mesh(
                &name,
                shapes::surface(&strip.vertices, &strip.triangles, 0.0),
                paint,
            );
            scene.add_node(Some(node), &name, Isometry3::identity(), Some(mesh));
        }
    }
}

fn add_obstacles(scene: &mut Scene, world: usize, first: &Recording) {
    if first.obstacles.is_empty() {
        return;
    }
    let concrete = Material::new("obstacle", [0.55, 0.55, 0.52], 0.9, 0.0);
    let concrete = scene.add_material(concrete);
    for (i, o) in first.obstacles.iter().enumerate() {
        let (mesh, name) = match *o {
            Obstacle::Box { half_extents, .. } => (
                box_mesh(Point3::origin(), 2.0 * half_extents),
                format!("box_{i}"),
            ),
            Obstacle::Ramp {
                length,
                width,
                height,
                ..
            } => (shapes::ramp(length, width, height), format!("ramp_{i}")),
            Obstacle::Cone { ref cone, .. } => {
                let (mesh, paint) = super::cone::mesh(scene, cone);
                let (at, yaw) = o.placement();
                let name = format!("cone_{i}");
                let mesh = scene.add_mesh(&name, mesh, paint);
                scene.add_node(Some(world), &name, pose(at, yaw), Some(mesh));
                continue;
            }
        };
        let (at, yaw) = o.placement();
        let mesh = scene.add_mesh(&name, mesh, concrete);
        scene.add_node(Some(world), &name, pose(at, yaw), Some(mesh));
    }
}

fn add_bodies(scene: &mut Scene, world: usize, first: &Recording) -> Vec<usize> {
    if first.bodies.is_empty() {
        return Vec::new();
    }
    let wood = Material::new("body", [0.65, 0.45, 0.25], 0.8, 0.0);
    let wood = scene.add_material(wood);
    let start = first.frames.first().map(|f| &f.bodies);
    first
        .bodies
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let name = format!("body_{i}");
            let mesh = scene.add_mesh(&name, box_mesh(Point3::origin(), b.size), wood);
            let at = start.and_then(|s| s.get(i)).map_or_else(
                || pose(b.center, b.yaw),
                |p| world_pose(&p.position, &p.roll_pitch_yaw),
            );
            scene.add_node(Some(world), &name, at, Some(mesh))
        })
        .collect()
}

fn add_car(
    scene: &mut Scene,
    world: usize,
    i: usize,
    car: &CarModel,
    first: &Recording,
    far: f64,
) -> CarNodes {
    let colour = PALETTE[i % PALETTE.len()];
    let body = Material::new(&format!("{}_body", car.name), colour, 0.4, 0.3);
    let vehicle = scene.add_car(Some(world), &car.name, &car.layout, &car.body, body);
    if let Some(f) = first.frames.first().and_then(|f| f.cars.get(i))
        && let Some(n) = scene.nodes.get_mut(vehicle.root)
    {
        n.transform = world_pose(&f.position, &f.roll_pitch_yaw);
    }
    super::cameras::add_chase(scene, vehicle.root, &car.body, far);
    // Lamps on the body's faces, sized by it.
    let b = &car.body;
    let (l, w, h) = (b.size.x, b.size.y, b.size.z);
    let (rear, front, bottom) = (
        b.centre.x - l / 2.0,
        b.centre.x + l / 2.0,
        b.centre.z - h / 2.0,
    );
    let lamp = Vector3::new(0.03 * l, 0.15 * w, 0.08 * h);
    let lamp_at = |x: f64, y: f64, z: f64| box_mesh(Point3::new(x, y, bottom + z * h), lamp);
    // The tail and the nose slope in towards the beltline: a lamp at height share `z` sits on
    // the sloped face.
    let (rear, front) = (
        |z: f64| rear + TAIL_RAKE * l * z / BELTLINE,
        |z: f64| front - NOSE_RAKE * l * z / BELTLINE,
    );
    let red =
        Material::new("brake_light", [0.6, 0.0, 0.0], 0.3, 0.0).with_emissive([1.0, 0.0, 0.0]);
    let amber =
        Material::new("indicator", [1.0, 0.45, 0.0], 0.3, 0.0).with_emissive([1.0, 0.45, 0.0]);
    let (red, amber) = (scene.add_material(red), scene.add_material(amber));
    // Below the beltline (`proto_geom::export::BELTLINE`), on the tail's and the nose's faces.
    let brake = merge(
        lamp_at(rear(0.4), -0.35 * w, 0.4),
        lamp_at(rear(0.4), 0.35 * w, 0.4),
    );
    let side = |y: f64| merge(lamp_at(front(0.3), y, 0.3), lamp_at(rear(0.3), y, 0.3));
    let mut lamps = |name: &str, mesh: RenderMesh, material: usize| {
        let mesh = scene.add_mesh(name, mesh, material);
        let node = scene.add_node(Some(vehicle.root), name, Isometry3::identity(), Some(mesh));
        if let Some(n) = scene.nodes.get_mut(node) {
            n.visible = false;
        }
        node
    };
    let brake_lights = lamps("brake_lights", brake, red);
    let left_indicators = lamps("left_indicators", side(0.45 * w), amber);
    let right_indicators = lamps("right_indicators", side(-0.45 * w), amber);
    let frames = car.layout.frames();
    CarNodes {
        vehicle,
        brake_lights,
        left_indicators,
        right_indicators,
        wheel_rest: PerWheel::from_fn(|w| frames[w].pose.rotation),
        wheel_centres: PerWheel::from_fn(|w| frames[w].pose.translation.vector),
    }
}

/// The frame of a body (a car, a box) at `position` (m) turned by `attitude`, in the world.
pub(crate) fn world_pose(position: &Point3<f64>, attitude: &RollPitchYaw) -> Isometry3<f64> {
    Isometry3::from_parts(Translation3::from(position.coords), attitude.rotation())
}

/// A `VehicleWheel` of radius `radius` and width `width` (m): the PROTO's default wheel with
/// every length scaled to them.
fn robot_wheel(radius: f64, width: f64, side: WheelSide) -> proto_geom::ValidWheel<f64> {
    let d = WheelParams::<f64>::default();
    let (s, t) = (radius / d.tire_radius, width / d.thickness);
    let params = WheelParams {
        tire_radius: radius,
        thickness: width,
        rim_radius: d.rim_radius * s,
        rim_beam_width: d.rim_beam_width * s,
        central_inner_radius: d.central_inner_radius * s,
        central_outer_radius: d.central_outer_radius * s,
        rim_beam_thickness: d.rim_beam_thickness * t,
        rim_beam_offset: d.rim_beam_offset * t,
        side,
        ..d
    };
    params.validate().0
}

fn add_robot(
    scene: &mut Scene,
    world: usize,
    i: usize,
    robot: &RobotModel,
    first: &Recording,
) -> RobotNodes {
    let p = &robot.params;
    let (r, half_axle) = (p.wheel_radius, p.axle_length / 2.0);
    let start = first.frames.first().and_then(|f| f.robots.get(i));
    let at = start.map_or(Isometry3::identity(), |f| pose(f.position, f.heading));
    let root = scene.add_node(Some(world), &robot.name, at, None);
    let colour = PALETTE[i % PALETTE.len()];
    let shell = Material::new(&format!("{}_body", robot.name), colour, 0.4, 0.1);
    let shell = scene.add_material(shell);
    // The physics mode's cylinder: radius axleLength/2, height wheelRadius, at axle height
    // (CylinderMesh's axis is x: stood up about y).
    let cylinder = CylinderMesh::new(half_axle, r, 32);
    let mesh = RenderMesh::from_mesh(&cylinder, &Isometry3::identity());
    let mesh = scene.add_mesh(&format!("{}_body", robot.name), mesh, shell);
    let upright = Isometry3::from_parts(
        Translation3::new(0.0, 0.0, r),
        UnitQuaternion::from_euler_angles(0.0, core::f64::consts::FRAC_PI_2, 0.0),
    );
    scene.add_node(Some(root), "body", upright, Some(mesh));
    // Wheels one fifth of the axle wide (the e-puck's 1 cm on its 5.2 cm axle).
    let width = p.axle_length / 5.0;
    let wheel = |y: f64, yaw: f64| pose(Point3::new(0.0, y, r), yaw);
    let left = wheel(half_axle, -core::f64::consts::FRAC_PI_2);
    let right = wheel(-half_axle, core::f64::consts::FRAC_PI_2);
    let l = scene.add_wheel(
        Some(root),
        "left_wheel",
        &robot_wheel(r, width, WheelSide::Left),
        left,
    );
    let rn = scene.add_wheel(
        Some(root),
        "right_wheel",
        &robot_wheel(r, width, WheelSide::Right),
        right,
    );
    RobotNodes {
        root,
        wheels: [(l, left), (rn, right)],
    }
}

/// A part's group: one trajectory line per car and robot (its origin's path on the ground) and
/// the cones of its course.
fn add_part(scene: &mut Scene, world: usize, part: &Part<'_>, lift: f64) -> usize {
    let group = scene.add_node(
        Some(world),
        &format!("scenario_{}", part.name),
        Isometry3::identity(),
        None,
    );
    let rec = part.recording;
    let z = 2.0 * lift;
    // Closer points than this add nothing to the line (m).
    let gap = 0.5 * lift;
    let mut line = |name: String, colour: [f32; 3], points: Vec<[f64; 2]>| {
        let mut kept: Vec<[f32; 3]> = Vec::with_capacity(points.len());
        let mut last: Option<[f64; 2]> = None;
        for p in points {
            if last.is_none_or(|q| (p[0] - q[0]).hypot(p[1] - q[1]) >= gap) {
                kept.push([p[0] as f32, p[1] as f32, z as f32]);
                last = Some(p);
            }
        }
        if kept.len() < 2 {
            return;
        }
        let m = Material::new(&format!("{name}_line"), colour, 1.0, 0.0).with_emissive(colour);
        let m = scene.add_material(m);
        let mesh = scene.add_geometry(&name, Geometry::Polyline(kept), m);
        scene.add_node(Some(group), &name, Isometry3::identity(), Some(mesh));
    };
    for i in 0..rec.cars.len() {
        let points = rec
            .frames
            .iter()
            .filter_map(|f| f.cars.get(i).map(|c| [c.position.x, c.position.y]))
            .collect();
        line(
            format!("trajectory_{}", rec.cars[i].name),
            PALETTE[i % PALETTE.len()],
            points,
        );
    }
    for i in 0..rec.robots.len() {
        let points = rec
            .frames
            .iter()
            .filter_map(|f| f.robots.get(i).map(|r| [r.position.x, r.position.y]))
            .collect();
        line(
            format!("trajectory_{}", rec.robots[i].name),
            PALETTE[i % PALETTE.len()],
            points,
        );
    }
    if !part.guides.is_empty() {
        let orange = Material::new("cone", [1.0, 0.3, 0.0], 0.6, 0.0);
        let orange = scene.add_material(orange);
        let cone = scene.add_mesh("cone", shapes::cone(), orange);
        let mut n = 0;
        for guide in part.guides {
            for w in guide.windows(2) {
                let ([x0, y0], [x1, y1]) = (w[0], w[1]);
                let count = ((x1 - x0).hypot(y1 - y0) / CONE_SPACING).ceil().max(1.0) as usize;
                for k in 0..=count {
                    let f = k as f64 / count as f64;
                    let at = pose(
                        Point3::new(x0 + f * (x1 - x0), y0 + f * (y1 - y0), 0.0),
                        0.0,
                    );
                    scene.add_node(Some(group), &format!("cone_{n}"), at, Some(cone));
                    n += 1;
                }
            }
        }
    }
    group
}

/// The wheel node's rotation (car frame) at steering angle `steering` (rad, positive = right)
/// and spin angle `spin` (rad, positive = rolling forward): the rest rotation, then the spin
/// about the car's y axis (the axle), then the steering about −z.
pub(crate) fn wheel_rotation(
    rest: &UnitQuaternion<f64>,
    steering: f64,
    spin: f64,
) -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(0.0, 0.0, -steering)
        * UnitQuaternion::from_euler_angles(0.0, spin, 0.0)
        * rest
}

/// The steering angle (rad) of `wheel` in a frame.
pub(crate) fn steering_of(wheel: Wheel, steering: &ackermann::WheelAngles<f64>) -> f64 {
    match wheel {
        Wheel::FrontRight => steering.right,
        Wheel::FrontLeft => steering.left,
        Wheel::RearRight | Wheel::RearLeft => 0.0,
    }
}
