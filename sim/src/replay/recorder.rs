//! Sampling a run for its replay: what every car, robot and dynamic box looks like and where it
//! is, at most [`MAX_KEYFRAME_RATE`] times per simulated second.

use ackermann::{PerWheel, Wheel, WheelAngles};
use proto_geom::export::ChassisBox;
use proto_geom::nalgebra::Point3;
use proto_geom::{VehicleDimensions, VehicleLayout, WheelParams};
use vehicle_model::{CarParams, Lights};

use crate::attitude::RollPitchYaw;
use crate::body::{BodyPose, BodySpec};
use crate::config::Obstacle;
use crate::diff_wheels::{DifferentialWheels, DifferentialWheelsParams};
use crate::road::RoadNetwork;
use crate::simulation::Simulation;
use crate::vehicle::{Vehicle, VehicleSpec};
use crate::world::World;

use super::lidar_overlay::{self, CloudBudget, OverlayLidar};
use super::overlay::{self, OverlayRadar};

/// Most keyframes a replay holds per simulated second (Hz): a display's frame rate; more would
/// only grow the file.
pub const MAX_KEYFRAME_RATE: f64 = 60.0;

/// The most keyframes a recording holds (10 minutes at [`MAX_KEYFRAME_RATE`]): a longer run
/// halves its keyframe rate each time it reaches this, so that its replay stays bounded in
/// memory (a few kB a frame) and in file size.
pub const MAX_FRAMES: usize = 36_000;

/// How a car is drawn: its `proto-geom` wheel layout (the Webots `VehicleWheel` meshes of its
/// own wheels at its own wheelbase and tracks) and its body box.
#[derive(Debug, Clone, PartialEq)]
pub struct CarModel {
    /// The car's name: its world-file `name` for a simulation's car, else `car_<index>`; the
    /// replay's node of the car bears it.
    pub name: String,
    /// Wheels and their frames (m, car frame).
    pub layout: VehicleLayout<f64>,
    /// The body (m, car frame).
    pub body: ChassisBox<f64>,
}

impl CarModel {
    /// The look of `vehicle`: from its parameters `params` when known (the car's own wheels, and
    /// a body from its rear, front and roof sensor slots when the model has them), else from its
    /// spec (default `VehicleWheel`s of its tyre radius and width). A body without sensor slots
    /// spans the chassis collision box lengthwise and up to its top.
    pub fn new(name: &str, spec: &VehicleSpec, params: Option<&CarParams<f64>>) -> Self {
        let fr = spec.wheels[Wheel::FrontRight].position;
        let rr = spec.wheels[Wheel::RearRight].position;
        let fl = spec.wheels[Wheel::FrontLeft].position;
        let rl = spec.wheels[Wheel::RearLeft].position;
        let (dimensions, wheels) = match params {
            Some(p) => (
                VehicleDimensions {
                    wheelbase: p.wheelbase,
                    track_front: p.track_front,
                    track_rear: p.track_rear,
                },
                p.wheels,
            ),
            None => (
                VehicleDimensions {
                    wheelbase: fr.x - rr.x,
                    track_front: fl.y - fr.y,
                    track_rear: rl.y - rr.y,
                },
                PerWheel::from_fn(|w| {
                    WheelParams {
                        tire_radius: spec.wheels[w].radius,
                        thickness: spec.wheels[w].width,
                        ..WheelParams::default()
                    }
                    .in_slot(w)
                }),
            ),
        };
        // Invalid fields take their Webots defaults, as the car itself did.
        let (layout, _) = VehicleLayout::new(dimensions, wheels);
        let d = layout.dimensions();
        let radius = spec.wheels[Wheel::FrontRight].radius;
        let thickness = Wheel::ALL
            .iter()
            .map(|&w| spec.wheels[w].width)
            .fold(0.0, f64::max);
        // The tyres stick out of the body by a quarter of their width.
        let width = d.track_front.max(d.track_rear) + 0.5 * thickness;
        let (c, h) = (spec.chassis.box_center, spec.chassis.box_half_extents);
        let (rear, front, top) = match params.and_then(|p| p.sensor_slots) {
            Some(s) => (
                s.rear.translation.x,
                s.front.translation.x,
                s.top.translation.z,
            ),
            None => (c.x - h.x, c.x + h.x, c.z + h.z),
        };
        // A ground clearance of 60 % of the tyre radius.
        let body = ChassisBox::from_extents(rear, front, width, -0.4 * radius, top);
        CarModel {
            name: name.to_string(),
            layout,
            body,
        }
    }
}

/// How a DifferentialWheels robot is drawn: the cylinder of its physics mode (radius
/// `axleLength/2`, height `wheelRadius`, centred at axle height) on two wheels.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotModel {
    /// The robot's name: its world-file `name` for a simulation's or a named robot
    /// ([`Recorder::with_robot_names`]), else `robot_<index>`; the replay's node bears it.
    pub name: String,
    /// The robot's fields (m, rad/s).
    pub params: DifferentialWheelsParams,
}

/// Where a car is and what it shows at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CarFrame {
    /// Car origin (m, world frame).
    pub position: Point3<f64>,
    /// Roll, pitch, yaw of the chassis (rad, z-y-x convention).
    pub roll_pitch_yaw: RollPitchYaw,
    /// Continuous wheel rotation angles (rad, positive = rolling forward).
    pub wheel_angles: PerWheel<f64>,
    /// Front steering angles (rad, positive = right).
    pub steering: WheelAngles<f64>,
    /// Suspension compression (m, positive = wheel pushed up).
    pub suspension: PerWheel<f64>,
    /// The lights commanded (all off before the first command).
    pub lights: Lights,
}

impl CarFrame {
    fn of(vehicle: &Vehicle) -> Self {
        let s = vehicle.state();
        CarFrame {
            position: s.position,
            roll_pitch_yaw: s.roll_pitch_yaw,
            wheel_angles: s.wheel_angles,
            steering: s.steering,
            suspension: s.suspension,
            lights: vehicle.commands().map_or(Lights::OFF, |c| c.lights),
        }
    }
}

/// Where a robot is at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RobotFrame {
    /// Ground projection of the axle midpoint (m, world frame).
    pub position: Point3<f64>,
    /// Heading (rad, counter-clockwise about +z).
    pub heading: f64,
    /// Wheel rotation angles `[left, right]` (rad, positive = rolling forward).
    pub wheel_angles: [f64; 2],
}

/// Everything moving in a world at one instant.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Frame {
    /// Simulated time since the world was built (s).
    pub time: f64,
    /// One per car, in [`World::vehicles`] order.
    pub cars: Vec<CarFrame>,
    /// One per robot, in [`World::robots`] order.
    pub robots: Vec<RobotFrame>,
    /// One per dynamic box, in [`World::bodies`] order.
    pub bodies: Vec<BodyPose>,
    /// One per radar of [`Recording::radars`]: its targets' positions (m, world frame), at
    /// most [`MAX_TARGET_MARKERS`](super::overlay::MAX_TARGET_MARKERS); empty without the
    /// overlay.
    pub radar_targets: Vec<Vec<Point3<f64>>>,
    /// One per lidar of [`Recording::lidars`] when this keyframe took clouds: the returns of
    /// its sample since the last cloud taken (m, world frame, f32), empty if none
    /// ([`super::lidar_overlay`]); empty without the overlay.
    pub lidar_points: Vec<Vec<[f32; 3]>>,
}

impl Frame {
    fn of(world: &World) -> Self {
        Frame {
            time: world.time(),
            cars: world.vehicles().iter().map(CarFrame::of).collect(),
            robots: world
                .robots()
                .iter()
                .map(|r| {
                    let pose = r.pose();
                    RobotFrame {
                        position: pose.position,
                        heading: pose.heading,
                        wheel_angles: r.wheel_angles(),
                    }
                })
                .collect(),
            bodies: world.bodies(),
            radar_targets: Vec::new(),
            lidar_points: Vec::new(),
        }
    }
}

/// A world's run, sampled for its replay: what to draw and the frames.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Recording {
    /// The static obstacles.
    pub obstacles: Vec<Obstacle>,
    /// The roads, drawn with their lanes and painted lines.
    pub roads: RoadNetwork,
    /// The dynamic boxes as built.
    pub bodies: Vec<BodySpec>,
    /// One per car, in [`World::vehicles`] order.
    pub cars: Vec<CarModel>,
    /// One per robot, in [`World::robots`] order.
    pub robots: Vec<RobotModel>,
    /// The frames, in increasing time, the first at the start of the recording and the last at
    /// its end.
    pub frames: Vec<Frame>,
    /// The radars whose targets the replay draws ([`super::overlay`]); empty without the
    /// overlay.
    pub radars: Vec<OverlayRadar>,
    /// The lidars whose returns the replay draws ([`super::lidar_overlay`]); empty without
    /// the overlay.
    pub lidars: Vec<OverlayLidar>,
}

impl Recording {
    /// Simulated time from the first frame to the last (s).
    pub fn duration(&self) -> f64 {
        match (self.frames.first(), self.frames.last()) {
            (Some(a), Some(b)) => b.time - a.time,
            _ => 0.0,
        }
    }
}

/// Samples a world after each step, keeping one frame every whole number of steps so that at
/// most [`MAX_KEYFRAME_RATE`] frames fall in a simulated second, whatever `basicTimeStep`.
///
/// ```
/// use sim::replay::Recorder;
/// use sim::{Simulation, VehiclePlacement, World, WorldConfig};
/// use vehicle_model::Model;
///
/// let mut sim = Simulation::new(World::new(WorldConfig::default())?); // 10 ms steps
/// sim.add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(VehiclePlacement::default()))?;
/// let mut recorder = Recorder::for_simulation(&sim);
/// for _ in 0..101 {
///     sim.step()?;
///     recorder.sample(sim.world());
/// }
/// let recording = recorder.finish(sim.world());
/// // Every second step (50 Hz) from 0 to 1 s, then the last step: 52 frames.
/// assert_eq!(recording.frames.len(), 52);
/// assert_eq!(recording.frames.last().map(|f| f.time), Some(1.01));
/// # Ok::<(), sim::SimError>(())
/// ```
#[derive(Debug, Clone)]
pub struct Recorder {
    recording: Recording,
    /// Simulated time between two frames (ms): a whole number of steps.
    period_ms: u64,
    /// When the next frame is due (ms).
    next_ms: u64,
    /// The time of the last frame kept (ms).
    last_ms: u64,
    /// The lidar clouds' caps ([`super::lidar_overlay`]).
    clouds: CloudBudget,
}

impl Recorder {
    /// Starts recording `world`, its cars drawn with default wheels of their tyre sizes
    /// ([`CarModel::new`] without parameters) and named `car_<index>`, its robots named
    /// `robot_<index>`; the first frame is its present state.
    pub fn for_world(world: &World) -> Self {
        Self::with_params(world, |_| None, |_| None, |_| None)
    }

    /// The recorder with its robots named `names` in [`World::robots`] order (those past the
    /// last name keep theirs), e.g. after the world file's robot.
    pub fn with_robot_names<S: Into<String>>(mut self, names: impl IntoIterator<Item = S>) -> Self {
        for (robot, name) in self.recording.robots.iter_mut().zip(names) {
            robot.name = name.into();
        }
        self
    }

    /// Starts recording the world of `sim`, each car and robot named as the simulation names
    /// it ([`Simulation::car_name`], the world file's `name`), each car with a driver drawn
    /// from its parameters, and with [`Simulation::replay_overlay`] its radars' targets ([`super::overlay`]) and
    /// its lidars' returns ([`super::lidar_overlay`]) when sampled with
    /// [`Recorder::sample_simulation`].
    pub fn for_simulation(sim: &Simulation) -> Self {
        let mut recorder = Self::with_params(
            sim.world(),
            |v| sim.driver(v.id()).ok().map(|d| d.params()),
            |v| sim.car_name(v.id()).ok().map(str::to_string),
            |r| sim.robot_name(r.id()).ok().map(str::to_string),
        );
        if sim.replay_overlay() {
            let radars = overlay::radars(sim);
            let first = overlay::targets(sim, &radars);
            if let Some(f) = recorder.recording.frames.first_mut() {
                f.radar_targets = first;
            }
            recorder.recording.radars = radars;
            let lidars = lidar_overlay::lidars(sim);
            recorder.clouds = CloudBudget::new(lidars.len());
            let first = recorder.clouds.clouds(sim, &lidars);
            if let Some(f) = recorder.recording.frames.first_mut() {
                f.lidar_points = first;
            }
            recorder.recording.lidars = lidars;
        }
        recorder
    }

    fn with_params<'a>(
        world: &World,
        params: impl Fn(&Vehicle) -> Option<&'a CarParams<f64>>,
        car_name: impl Fn(&Vehicle) -> Option<String>,
        robot_name: impl Fn(&DifferentialWheels) -> Option<String>,
    ) -> Self {
        let step_ms = u64::from(world.config().basic_time_step_ms.max(1));
        let steps = (1000.0 / MAX_KEYFRAME_RATE / step_ms as f64)
            .ceil()
            .max(1.0) as u64;
        let first = Frame::of(world);
        let now = world.time_ms();
        Recorder {
            recording: Recording {
                obstacles: world.config().obstacles.clone(),
                roads: world.config().roads.clone(),
                bodies: world.config().bodies.clone(),
                cars: world
                    .vehicles()
                    .iter()
                    .enumerate()
                    .map(|(i, v)| {
                        let name = car_name(v).unwrap_or_else(|| format!("car_{i}"));
                        CarModel::new(&name, v.spec(), params(v))
                    })
                    .collect(),
                robots: world
                    .robots()
                    .iter()
                    .enumerate()
                    .map(|(i, r)| RobotModel {
                        name: robot_name(r).unwrap_or_else(|| format!("robot_{i}")),
                        params: *r.params(),
                    })
                    .collect(),
                frames: vec![first],
                radars: Vec::new(),
                lidars: Vec::new(),
            },
            clouds: CloudBudget::new(0),
            period_ms: steps * step_ms,
            next_ms: now + steps * step_ms,
            last_ms: now,
        }
    }

    /// Keeps a frame of `world` if one is due; call it after every step.
    pub fn sample(&mut self, world: &World) {
        if world.time_ms() >= self.next_ms {
            self.keep(Frame::of(world), world.time_ms());
        }
    }

    /// Keeps a frame of the world of `sim` if one is due, with its radars' targets when the
    /// recorder draws them; call it after every step.
    pub fn sample_simulation(&mut self, sim: &Simulation) {
        if sim.world().time_ms() >= self.next_ms {
            let frame = self.frame_of(sim);
            self.keep(frame, sim.world().time_ms());
        }
    }

    /// The frame of `sim` now, with the targets of the recording's radars and the clouds of
    /// its lidars.
    fn frame_of(&mut self, sim: &Simulation) -> Frame {
        let mut frame = Frame::of(sim.world());
        if !self.recording.radars.is_empty() {
            frame.radar_targets = overlay::targets(sim, &self.recording.radars);
        }
        if !self.recording.lidars.is_empty() {
            frame.lidar_points = self.clouds.clouds(sim, &self.recording.lidars);
        }
        frame
    }

    /// Keeps `frame`, due now (`now_ms`); the next is due one period later.
    fn keep(&mut self, frame: Frame, now_ms: u64) {
        self.push(frame, now_ms);
        self.next_ms = now_ms + self.period_ms;
    }

    /// Appends `frame` of time `now` (ms).
    fn push(&mut self, frame: Frame, now: u64) {
        self.recording.frames.push(frame);
        self.last_ms = now;
        if self.recording.frames.len() > MAX_FRAMES {
            // Every other frame goes, the first and the newest stay (MAX_FRAMES is even), and
            // the keyframes come half as often from now on: a run of any length keeps at most
            // MAX_FRAMES + 1 frames, evenly spaced.
            let mut index = 0;
            self.recording.frames.retain(|_| {
                index += 1;
                index % 2 == 1
            });
            self.period_ms *= 2;
            self.next_ms = self.last_ms + self.period_ms;
        }
        self.clouds.enforce(&mut self.recording.frames);
    }

    /// Ends the recording with the present state of `world` (unless the last frame is already
    /// of this instant), so that it ends at the run's simulated duration.
    pub fn finish(mut self, world: &World) -> Recording {
        if world.time_ms() > self.last_ms {
            self.push(Frame::of(world), world.time_ms());
        }
        self.recording
    }

    /// [`Recorder::finish`] on the world of `sim`, its last frame with the radars' targets.
    pub fn finish_simulation(mut self, sim: &Simulation) -> Recording {
        if sim.world().time_ms() > self.last_ms {
            let frame = self.frame_of(sim);
            self.push(frame, sim.world().time_ms());
        }
        self.recording
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::WorldConfig;

    #[test]
    fn a_long_run_keeps_at_most_max_frames_evenly_spaced() {
        // 100 ms steps: a keyframe every step (60 per second would be every 16.7 ms).
        let config = WorldConfig {
            basic_time_step_ms: 100,
            ..WorldConfig::default()
        };
        let mut world = World::new(config).unwrap();
        let mut recorder = Recorder::for_world(&world);
        let steps = 3 * MAX_FRAMES;
        for _ in 0..steps {
            world.step().unwrap();
            recorder.sample(&world);
        }
        let recording = recorder.finish(&world);
        let frames = &recording.frames;
        assert!(frames.len() <= MAX_FRAMES + 1, "{} frames", frames.len());
        // Halved twice: the first frame, then one every 4 steps (0.4 s) to the end.
        assert_eq!(frames.first().map(|f| f.time), Some(0.0));
        let end = steps as f64 * 0.1;
        assert!((frames.last().map_or(0.0, |f| f.time) - end).abs() < 1e-9);
        for pair in frames.windows(2) {
            let dt = pair[1].time - pair[0].time;
            assert!((dt - 0.4).abs() < 1e-9, "{dt}");
        }
    }
}
