//! What describes a device before it is built: its kind, its node fields and where it sits
//! on the car ([`DeviceSpec`]).

use proto_geom::SensorSlot;
use proto_geom::nalgebra::{UnitQuaternion, Vector3};

use crate::error::ParamError;

use super::{
    CameraSettings, DisplaySettings, DistanceSensorSettings, GpsSettings, InertialUnitSettings,
    LidarSettings, RadarSettings, RoadSensorSettings, TriaxialSettings,
};

/// The kinds of device.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DeviceKind {
    /// Webots `GPS`.
    Gps,
    /// Webots `InertialUnit`.
    InertialUnit,
    /// Webots `Gyro`.
    Gyro,
    /// Webots `Accelerometer`.
    Accelerometer,
    /// Webots `Compass`.
    Compass,
    /// Webots `Camera`.
    Camera,
    /// Webots `Display`.
    Display,
    /// Webots `DistanceSensor`.
    DistanceSensor,
    /// Webots `Radar`.
    Radar,
    /// Webots `Lidar`.
    Lidar,
    /// `RoadSensor`: where the car is on the roads (a project extension, no Webots node).
    RoadSensor,
}

impl DeviceKind {
    /// Every kind.
    pub const ALL: [DeviceKind; 11] = [
        DeviceKind::Gps,
        DeviceKind::InertialUnit,
        DeviceKind::Gyro,
        DeviceKind::Accelerometer,
        DeviceKind::Compass,
        DeviceKind::Camera,
        DeviceKind::Display,
        DeviceKind::DistanceSensor,
        DeviceKind::Radar,
        DeviceKind::Lidar,
        DeviceKind::RoadSensor,
    ];

    /// The Webots node name (`"GPS"`, `"InertialUnit"`, …).
    pub const fn webots_name(self) -> &'static str {
        match self {
            DeviceKind::Gps => "GPS",
            DeviceKind::InertialUnit => "InertialUnit",
            DeviceKind::Gyro => "Gyro",
            DeviceKind::Accelerometer => "Accelerometer",
            DeviceKind::Compass => "Compass",
            DeviceKind::Camera => "Camera",
            DeviceKind::Display => "Display",
            DeviceKind::DistanceSensor => "DistanceSensor",
            DeviceKind::Radar => "Radar",
            DeviceKind::Lidar => "Lidar",
            DeviceKind::RoadSensor => "RoadSensor",
        }
    }

    /// The kind of Webots node name `name` (exact).
    pub fn from_webots_name(name: &str) -> Option<DeviceKind> {
        DeviceKind::ALL
            .into_iter()
            .find(|k| k.webots_name() == name)
    }

    /// The node's default `name` field (`"gps"`, `"inertial unit"`, …).
    pub const fn default_name(self) -> &'static str {
        match self {
            DeviceKind::Gps => "gps",
            DeviceKind::InertialUnit => "inertial unit",
            DeviceKind::Gyro => "gyro",
            DeviceKind::Accelerometer => "accelerometer",
            DeviceKind::Compass => "compass",
            DeviceKind::Camera => "camera",
            DeviceKind::Display => "display",
            DeviceKind::DistanceSensor => "distance sensor",
            DeviceKind::Radar => "radar",
            DeviceKind::Lidar => "lidar",
            DeviceKind::RoadSensor => "road sensor",
        }
    }

    /// True for the devices that cast rays through the world (`DistanceSensor`, `Radar`,
    /// `Lidar`).
    pub const fn casts_rays(self) -> bool {
        matches!(
            self,
            DeviceKind::DistanceSensor | DeviceKind::Radar | DeviceKind::Lidar
        )
    }
}

/// The `xAxis`, `yAxis`, `zAxis` fields (default all true).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Axes {
    /// `xAxis`.
    pub x: bool,
    /// `yAxis`.
    pub y: bool,
    /// `zAxis`.
    pub z: bool,
}

impl Default for Axes {
    fn default() -> Self {
        Axes {
            x: true,
            y: true,
            z: true,
        }
    }
}

impl Axes {
    /// True when every axis is enabled.
    pub const fn all(self) -> bool {
        self.x && self.y && self.z
    }
}

/// A `resolution` field: −1 (none) or finite and > 0.
pub(crate) fn check_resolution(field: &'static str, value: f64) -> Result<(), ParamError> {
    ParamError::check(field, value, "-1 (none) or finite and > 0", |r| {
        r == -1.0 || (r.is_finite() && r > 0.0)
    })
    .map(|_| ())
}

/// A device's node fields, by kind.
#[derive(Debug, Clone, PartialEq)]
pub enum DeviceSettings {
    /// A `GPS`.
    Gps(GpsSettings),
    /// An `InertialUnit`.
    InertialUnit(InertialUnitSettings),
    /// A `Gyro` (rad/s).
    Gyro(TriaxialSettings),
    /// An `Accelerometer` (m/s²).
    Accelerometer(TriaxialSettings),
    /// A `Compass` (unitless).
    Compass(TriaxialSettings),
    /// A `Camera` (and its `Recognition`).
    Camera(CameraSettings),
    /// A `Display`.
    Display(DisplaySettings),
    /// A `DistanceSensor`.
    DistanceSensor(DistanceSensorSettings),
    /// A `Radar`.
    Radar(RadarSettings),
    /// A `Lidar`.
    Lidar(LidarSettings),
    /// A `RoadSensor` (a project extension).
    RoadSensor(RoadSensorSettings),
}

impl DeviceSettings {
    /// The kind of device.
    pub fn kind(&self) -> DeviceKind {
        match self {
            DeviceSettings::Gps(_) => DeviceKind::Gps,
            DeviceSettings::InertialUnit(_) => DeviceKind::InertialUnit,
            DeviceSettings::Gyro(_) => DeviceKind::Gyro,
            DeviceSettings::Accelerometer(_) => DeviceKind::Accelerometer,
            DeviceSettings::Compass(_) => DeviceKind::Compass,
            DeviceSettings::Camera(_) => DeviceKind::Camera,
            DeviceSettings::Display(_) => DeviceKind::Display,
            DeviceSettings::DistanceSensor(_) => DeviceKind::DistanceSensor,
            DeviceSettings::Radar(_) => DeviceKind::Radar,
            DeviceSettings::Lidar(_) => DeviceKind::Lidar,
            DeviceSettings::RoadSensor(_) => DeviceKind::RoadSensor,
        }
    }

    /// The Webots defaults of a `kind` node.
    pub fn default_of(kind: DeviceKind) -> Self {
        match kind {
            DeviceKind::Gps => DeviceSettings::Gps(GpsSettings::default()),
            DeviceKind::InertialUnit => {
                DeviceSettings::InertialUnit(InertialUnitSettings::default())
            }
            DeviceKind::Gyro => DeviceSettings::Gyro(TriaxialSettings::default()),
            DeviceKind::Accelerometer => DeviceSettings::Accelerometer(TriaxialSettings::default()),
            DeviceKind::Compass => DeviceSettings::Compass(TriaxialSettings::default()),
            DeviceKind::Camera => DeviceSettings::Camera(CameraSettings::default()),
            DeviceKind::Display => DeviceSettings::Display(DisplaySettings::default()),
            DeviceKind::DistanceSensor => {
                DeviceSettings::DistanceSensor(DistanceSensorSettings::default())
            }
            DeviceKind::Radar => DeviceSettings::Radar(RadarSettings::default()),
            DeviceKind::Lidar => DeviceSettings::Lidar(LidarSettings::default()),
            DeviceKind::RoadSensor => DeviceSettings::RoadSensor(RoadSensorSettings::default()),
        }
    }

    /// Checks every field against Webots' range.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        match self {
            DeviceSettings::Gps(s) => s.validate(),
            DeviceSettings::InertialUnit(s) => s.validate(),
            DeviceSettings::Gyro(s)
            | DeviceSettings::Accelerometer(s)
            | DeviceSettings::Compass(s) => s.validate(),
            DeviceSettings::Camera(s) => s.validate(),
            DeviceSettings::Display(s) => s.validate(),
            DeviceSettings::DistanceSensor(s) => s.validate(),
            DeviceSettings::Radar(s) => s.validate(),
            DeviceSettings::Lidar(s) => s.validate(),
            DeviceSettings::RoadSensor(s) => s.validate(),
        }
    }
}

/// A device to put on a car ([`CarBuilder::device`](crate::CarBuilder::device)): its node
/// fields, its name and where it sits.
///
/// ```
/// use sim::devices::{DeviceKind, DeviceSettings, DeviceSpec, GpsSettings};
/// use sim::nalgebra::Vector3;
/// use proto_geom::SensorSlot;
/// let gps = DeviceSpec::new(DeviceSettings::Gps(GpsSettings { accuracy: 0.5, ..GpsSettings::default() }))
///     .slot(SensorSlot::Top)
///     .translation(Vector3::new(0.0, 0.0, 0.1)); // m, in the slot's frame
/// assert_eq!(gps.kind(), DeviceKind::Gps);
/// assert_eq!(gps.device_name(), "gps");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DeviceSpec {
    /// The node fields.
    pub settings: DeviceSettings,
    /// The `name` field; `None`: the kind's Webots default.
    pub name: Option<String>,
    /// The sensor slot it sits in; `None`: the car frame (origin at the rear-axle centre).
    pub slot: Option<SensorSlot>,
    /// Its `translation` in the slot's frame (m).
    pub translation: Vector3<f64>,
    /// Its `rotation` in the slot's frame.
    pub rotation: UnitQuaternion<f64>,
    /// The sampling period it is enabled with when its car is added (ms, 1 to
    /// [`MAX_SAMPLING_PERIOD_MS`]); `None`: disabled until a controller enables it, as in
    /// Webots. A project extension (the world file's `samplingPeriod`) for runs without a
    /// controller; a controller's enable and disable calls still change it.
    pub sampling_period_ms: Option<u32>,
}

/// The longest sampling period (ms): Webots sends a period to the simulator as a 16-bit
/// unsigned integer (spec §2).
pub const MAX_SAMPLING_PERIOD_MS: u32 = 65_535;

impl DeviceSpec {
    /// A device of `settings`, named by default, at the car frame's origin.
    pub fn new(settings: DeviceSettings) -> Self {
        DeviceSpec {
            settings,
            name: None,
            slot: None,
            translation: Vector3::zeros(),
            rotation: UnitQuaternion::identity(),
            sampling_period_ms: None,
        }
    }

    /// Its name (unique on the car).
    #[must_use]
    pub fn name(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }

    /// The sensor slot it sits in.
    #[must_use]
    pub fn slot(mut self, slot: SensorSlot) -> Self {
        self.slot = Some(slot);
        self
    }

    /// Its translation in the slot's frame (m).
    #[must_use]
    pub fn translation(mut self, translation: Vector3<f64>) -> Self {
        self.translation = translation;
        self
    }

    /// Its rotation in the slot's frame.
    #[must_use]
    pub fn rotation(mut self, rotation: UnitQuaternion<f64>) -> Self {
        self.rotation = rotation;
        self
    }

    /// Enabled with a sampling period of `period_ms` ms when its car is added (checked then:
    /// 1 to [`MAX_SAMPLING_PERIOD_MS`]); the effective period is rounded up to whole steps,
    /// as Webots does.
    #[must_use]
    pub fn sampling_period(mut self, period_ms: u32) -> Self {
        self.sampling_period_ms = Some(period_ms);
        self
    }

    /// The kind of device.
    pub fn kind(&self) -> DeviceKind {
        self.settings.kind()
    }

    /// The name it has on the car: its `name`, or its kind's default.
    pub fn device_name(&self) -> &str {
        self.name
            .as_deref()
            .unwrap_or(self.settings.kind().default_name())
    }
}
