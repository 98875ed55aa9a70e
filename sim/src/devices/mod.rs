//! Webots sensor devices on a car: `GPS`, `InertialUnit`, `Gyro`, `Accelerometer`,
//! `Compass`, the ray-based `DistanceSensor`, `Radar` and `Lidar`, `Camera` (with its `Recognition`) and `Display`, mounted in the Car PROTO's sensor slots (or anywhere on the chassis), sampled as
//! Webots samples them. The measurements are written here once; the C API and Python only
//! marshal them.
//!
//! * **Mounting.** A device's frame on the chassis is its slot's frame (`proto_geom`'s
//!   [`SensorSlots`](proto_geom::SensorSlots); no slot: the car frame, origin at the rear-axle
//!   centre at wheel-centre height) composed with its own `translation` (m) and `rotation`.
//!   The device rides on the chassis body: its point moves with the chassis' velocity and
//!   angular velocity.
//! * **Sampling** (spec §2). Enabling with a period of `p` ms at time `t` sets the last
//!   sample time to `t`; after each step the device samples iff `now − last ≥ p`, and then
//!   `last = now`: the first value comes one full period after enabling (the effective period
//!   is `p` rounded up to whole steps), and every value is NaN before it. A disabled device
//!   keeps its last sample and costs nothing.
//! * **Noise** comes from a [`SplitMix64`] per device: device `k` of a car (in the order the
//!   car lists them) draws from the car's `seed` stream starting at draw `k·2⁴⁰`, so devices
//!   never share draws, adding a device leaves the others' noise unchanged, and the same
//!   world gives the same readings on every run.
//! * **Rays.** The ray devices see the world through one module, `rays`: every collider
//!   (ground, ramps, boxes, other cars, robots) but their own car's, after the step. The
//!   radar's targets are the other cars and the dynamic boxes whose `radarCrossSection` (m²)
//!   is above 0.
//! * **World frame.** The world is Webots' default ENU: x east, y north, z up. The compass
//!   points to world +y; the inertial unit's yaw is 0 with the device's x axis along world +x.

pub mod camera;
mod car_devices;
pub mod display;
mod distance_sensor;
mod gps;
mod gps_frame;
mod inertial_unit;
mod lidar;
mod lookup;
mod noise;
mod png_file;
mod radar;
pub(crate) mod rays;
mod record;
mod road_sensor;
mod spec;
mod triaxial;

use proto_geom::SensorSlot;
use proto_geom::nalgebra::{Isometry3, Point3, UnitQuaternion, Vector3};

use crate::error::{ParamError, SimError};
use crate::rng::SplitMix64;
use crate::road::RoadNetwork;
use crate::sampling::Schedule;
use crate::vehicle::VehicleId;
use camera::solids::Solids;

pub use camera::{CameraSettings, CameraState, Occlusion, RecognitionObject, RecognitionSettings};
pub use display::{Display, DisplayImage, DisplaySettings, FONT_FAMILIES, FontError, PixelFormat};
pub use distance_sensor::{DistanceSensorSettings, DistanceSensorType, MAX_DISTANCE_SENSOR_RAYS};
pub use gps::{GpsReading, GpsSettings};
pub use gps_frame::{GpsCoordinateSystem, GpsFrame};
pub use inertial_unit::{InertialUnitReading, InertialUnitSettings};
pub use lidar::{
    LidarPoint, LidarProjection, LidarReading, LidarSettings, LidarType, MAX_LIDAR_LAYERS,
    MAX_LIDAR_RESOLUTION,
};
pub use lookup::LookupTable;
pub use png_file::{ImageFileError, load_png, save_png};
pub use radar::{RadarSettings, RadarTarget};
pub use record::RecordedQuantity;
pub use road_sensor::{DEFAULT_LOOKAHEAD, MAX_LOOKAHEAD, RoadSensorReading, RoadSensorSettings};
pub use spec::{Axes, DeviceKind, DeviceSettings, DeviceSpec, MAX_SAMPLING_PERIOD_MS};
pub use triaxial::TriaxialSettings;

pub(crate) use car_devices::CarDevices;
use gps::GpsNoise;
use rays::Scene;
use spec::check_resolution;
use triaxial::{PreviousVelocity, Quantity};

/// The names of a car's own devices (the Car PROTO and Webots' car library): a sensor added to
/// a car may not take one of them, so that a name finds one device.
pub const CAR_DEVICE_NAMES: [&str; 27] = [
    "right_steer",
    "left_steer",
    "right_steer_sensor",
    "left_steer_sensor",
    "right_front_wheel",
    "left_front_wheel",
    "right_rear_wheel",
    "left_rear_wheel",
    "right_front_sensor",
    "left_front_sensor",
    "right_rear_sensor",
    "left_rear_sensor",
    "right_front_brake",
    "left_front_brake",
    "right_rear_brake",
    "left_rear_brake",
    "front_lights",
    "antifog_lights",
    "right_indicators",
    "left_indicators",
    "rear_lights",
    "backwards_lights",
    "brake_lights",
    "engine_speaker",
    "right_wiper_motor",
    "left_wiper_motor",
    "wiper_sensor",
];

/// Why the devices of a car cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DeviceError {
    /// A field is out of its range.
    #[error("device '{name}': {error}")]
    Field {
        /// The device's name.
        name: String,
        /// The field and its value.
        error: ParamError,
    },
    /// Two devices of the car have this name.
    #[error("two devices of the car are named '{0}': device names must be unique on a car")]
    DuplicateName(String),
    /// The name is one of the car's own devices ([`CAR_DEVICE_NAMES`]).
    #[error("'{0}' is the name of one of the car's own devices: choose another")]
    ReservedName(String),
    /// The device's slot is not known for this car: only the shipped models with the four
    /// slots have their frames.
    #[error(
        "device '{name}': the car has no {} frame (only the shipped models with sensor slots \
         have them; leave `slot` out to mount it in the car's frame)",
        .slot.webots_name()
    )]
    NoSlot {
        /// The device's name.
        name: String,
        /// The slot asked for.
        slot: SensorSlot,
    },
    /// Recognition asked of a device that is no camera with a `recognition` node.
    #[error("device '{0}' has no Recognition (a Camera with a `recognition` node)")]
    NoRecognition(String),
    /// A display asked of a device that is no `Display`.
    #[error("device '{0}' is no Display")]
    NotDisplay(String),
    /// A device index the car does not have.
    #[error("no device {index} on this car (it has {count})")]
    Unknown {
        /// The index asked for.
        index: usize,
        /// How many devices the car has.
        count: usize,
    },
}

/// A sample of a device, by kind.
#[derive(Debug, Clone, PartialEq)]
pub enum Reading {
    /// A GPS's position and speed.
    Gps(GpsReading),
    /// An inertial unit's orientation.
    InertialUnit(InertialUnitReading),
    /// A gyro's angular velocity (rad/s), an accelerometer's specific force (m/s²) or a
    /// compass' north vector, device axes.
    Vector(Vector3<f64>),
    /// A camera's: its image and objects are in [`Device::camera`].
    Camera,
    /// A display's: no measurement; its image is in [`Device::display`].
    Display,
    /// A distance sensor's value (the lookup table's unit; NaN before the first sample).
    Distance(f64),
    /// A radar's targets, `None` before the first sample.
    Radar(Option<Vec<RadarTarget>>),
    /// A lidar's range image.
    Lidar(LidarReading),
    /// A road sensor's place on the roads (a project extension).
    Road(RoadSensorReading),
}

/// A device on a car: its fields, its frame on the chassis, its sampling state and its last
/// sample.
#[derive(Debug, Clone)]
pub struct Device {
    name: String,
    settings: DeviceSettings,
    /// Device frame → car frame (m).
    mount: Isometry3<f64>,
    schedule: Schedule,
    rng: SplitMix64,
    /// A GPS's correlated position noise.
    gps_noise: GpsNoise,
    /// An accelerometer's velocity at its previous sample.
    previous_velocity: PreviousVelocity,
    /// A lidar's point cloud is enabled (Webots computes it only then).
    point_cloud: bool,
    reading: Reading,
    /// A camera's image, objects and Recognition sampling.
    camera: Option<Box<CameraState>>,
    /// A display's image and drawing context.
    display: Option<Box<Display>>,
}

impl Device {
    /// Its name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its kind.
    pub fn kind(&self) -> DeviceKind {
        self.settings.kind()
    }

    /// Its node fields.
    pub fn settings(&self) -> &DeviceSettings {
        &self.settings
    }

    /// Its frame on the car: device coordinates → car coordinates (m).
    pub fn mount(&self) -> &Isometry3<f64> {
        &self.mount
    }

    /// Its sampling period (ms), 0 when disabled.
    pub fn period_ms(&self) -> u32 {
        self.schedule.period_ms()
    }

    /// Its last sample (NaN before the first), kept while disabled.
    pub fn reading(&self) -> &Reading {
        &self.reading
    }

    /// A camera's image and recognised objects (`None` for other devices).
    pub fn camera(&self) -> Option<&CameraState> {
        self.camera.as_deref()
    }

    /// A display's image and context (`None` for other devices).
    pub fn display(&self) -> Option<&Display> {
        self.display.as_deref()
    }

    /// A display to draw into (`None` for other devices).
    pub fn display_mut(&mut self) -> Option<&mut Display> {
        self.display.as_deref_mut()
    }

    /// True if a camera of it is to render at `now_ms` (its image or its Recognition due).
    fn renders_at(&self, now_ms: u64) -> bool {
        self.camera
            .as_ref()
            .is_some_and(|c| self.due(now_ms) || c.recognition_due(now_ms))
    }

    /// True if its point cloud is enabled (a lidar; always false for the others).
    pub fn point_cloud_enabled(&self) -> bool {
        self.point_cloud
    }

    /// A lidar's point cloud (device axes, m) converted from its last range image, if the
    /// lidar and its cloud are enabled (Webots' `wb_lidar_get_point_cloud`); `None`
    /// otherwise.
    pub fn point_cloud(&self) -> Option<Vec<LidarPoint>> {
        match (&self.settings, &self.reading) {
            (DeviceSettings::Lidar(s), Reading::Lidar(r))
                if self.point_cloud && self.schedule.is_enabled() =>
            {
                Some(r.point_cloud(s, self.schedule.period_ms()))
            }
            _ => None,
        }
    }

    /// True if it samples at `now_ms`: enabled, and a full period has passed.
    /// A rotating lidar refreshes at every step (its head turns whatever the period).
    fn due(&self, now_ms: u64) -> bool {
        let rotating = matches!(&self.settings, DeviceSettings::Lidar(s)
            if s.lidar_type == LidarType::Rotating);
        if rotating {
            self.schedule.due_every_step(now_ms)
        } else {
            self.schedule.due(now_ms)
        }
    }

    /// Enables it with a period of `period_ms` ms at time `now_ms` (0 disables). A new period
    /// (or enabling a disabled device) restarts the wait for a full period; enabling again
    /// with the period in force changes nothing, so a controller that enables in its loop
    /// still gets samples.
    fn enable(&mut self, period_ms: u32, now_ms: u64) {
        self.schedule.enable(period_ms, now_ms);
    }

    /// Samples if enabled and a full period has passed since the last sample; a camera
    /// renders `solids` (seen from car `own`) when its image or its Recognition is due; a ray
    /// device measures in `scene` (and keeps its sample without one).
    fn refresh(
        &mut self,
        chassis: &ChassisMotion,
        now_ms: u64,
        scene: Option<&Scene<'_>>,
        solids: Option<&Solids>,
        own: VehicleId,
        world: Surroundings<'_>,
    ) {
        if let (DeviceSettings::Camera(settings), Some(camera), Some(solids)) =
            (&self.settings, self.camera.as_mut(), solids)
        {
            let image = self.schedule.due(now_ms);
            if image || camera.recognition_due(now_ms) {
                if image {
                    self.schedule.sampled(now_ms);
                }
                let pose = chassis.pose * self.mount;
                let view = camera::View {
                    pose: &pose,
                    solids,
                    own: Some(own),
                };
                camera.sample(settings, &view, image, now_ms, &mut self.rng);
            }
            return;
        }
        if !self.due(now_ms) || (self.kind().casts_rays() && scene.is_none()) {
            return;
        }
        // Whole ms: exact in f64.
        let dt = self.schedule.sampled(now_ms) as f64 / 1000.0;
        let point = chassis.point(&self.mount);
        let rng = &mut self.rng;
        let vector = |quantity: Quantity,
                      previous: &mut PreviousVelocity,
                      settings: &TriaxialSettings,
                      rng: &mut SplitMix64| {
            let v = triaxial::physical(quantity, &point, dt, previous);
            Reading::Vector(triaxial::respond(settings, &v, rng))
        };
        let previous = &mut self.previous_velocity;
        self.reading = match &self.settings {
            DeviceSettings::Gps(s) => Reading::Gps(gps::measure(
                s,
                world.gps,
                &point,
                dt,
                &mut self.gps_noise,
                rng,
            )),
            DeviceSettings::InertialUnit(s) => {
                Reading::InertialUnit(inertial_unit::measure(s, &point, rng))
            }
            DeviceSettings::Gyro(s) => vector(Quantity::AngularVelocity, previous, s, rng),
            DeviceSettings::Accelerometer(s) => vector(Quantity::SpecificForce, previous, s, rng),
            DeviceSettings::Compass(s) => vector(Quantity::North, previous, s, rng),
            DeviceSettings::Camera(_) => Reading::Camera,
            DeviceSettings::Display(_) => Reading::Display,
            DeviceSettings::DistanceSensor(s) => match scene {
                Some(scene) => Reading::Distance(distance_sensor::measure(s, scene, &point, rng)),
                None => return,
            },
            DeviceSettings::Radar(s) => match scene {
                Some(scene) => Reading::Radar(Some(radar::measure(s, scene, &point, rng))),
                None => return,
            },
            DeviceSettings::Lidar(s) => match scene {
                Some(scene) => {
                    let time = now_ms as f64 / 1000.0;
                    let previous = match &self.reading {
                        Reading::Lidar(r) => r,
                        _ => &LidarReading::unsampled(s),
                    };
                    Reading::Lidar(lidar::measure(s, scene, &point, time, (previous, dt), rng))
                }
                None => return,
            },
            DeviceSettings::RoadSensor(s) => {
                Reading::Road(road_sensor::measure(s, world.roads, &point))
            }
        };
    }
}

/// What the devices read of the world besides its rays and solids: the roads (a road
/// sensor's) and the frame a GPS reports in.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Surroundings<'a> {
    /// The world's roads.
    pub roads: &'a RoadNetwork,
    /// The world's GPS frame.
    pub gps: &'a GpsFrame,
}

/// The chassis' motion after a step, from which each device's point is measured.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ChassisMotion {
    /// Car frame → world (m).
    pub pose: Isometry3<f64>,
    /// Velocity of the car frame's origin (m/s, world axes).
    pub velocity: Vector3<f64>,
    /// Angular velocity (rad/s, world axes).
    pub angular_velocity: Vector3<f64>,
    /// Gravity (m/s², world axes).
    pub gravity: Vector3<f64>,
}

impl ChassisMotion {
    /// The motion of the chassis point at device frame `mount`.
    fn point(&self, mount: &Isometry3<f64>) -> DevicePoint {
        let offset = self.pose.rotation * mount.translation.vector;
        DevicePoint {
            position: self.pose.translation.vector.into(),
            rotation: self.pose.rotation * mount.rotation,
            velocity: self.velocity + self.angular_velocity.cross(&offset),
            angular_velocity: self.angular_velocity,
            gravity: self.gravity,
        }
        .moved_by(offset)
    }
}

/// A device's point on the chassis and its frame, in the world.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DevicePoint {
    /// Position (m).
    pub position: Point3<f64>,
    /// Device → world.
    pub rotation: UnitQuaternion<f64>,
    /// Velocity (m/s, world axes).
    pub velocity: Vector3<f64>,
    /// Angular velocity of the body it rides on (rad/s, world axes).
    pub angular_velocity: Vector3<f64>,
    /// Gravity (m/s², world axes).
    pub gravity: Vector3<f64>,
}

impl DevicePoint {
    fn moved_by(mut self, offset: Vector3<f64>) -> Self {
        self.position += offset;
        self
    }
}

impl From<DeviceError> for SimError {
    fn from(e: DeviceError) -> Self {
        SimError::Device(e)
    }
}
