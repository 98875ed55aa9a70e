//! The devices of one car: built from their specs on the car's sensor slots, enabled and
//! sampled together at each step end.

use proto_geom::SensorSlots;
use proto_geom::nalgebra::{Isometry3, Translation3, Vector3};

use super::camera::solids::Solids;
use super::gps::GpsNoise;
use super::rays::Scene;
use super::triaxial::PreviousVelocity;
use super::{
    CAR_DEVICE_NAMES, CameraState, ChassisMotion, Device, DeviceError, DeviceKind, DeviceSettings,
    DeviceSpec, Display, DistanceSensorType, GpsReading, InertialUnitReading, LidarReading,
    MAX_SAMPLING_PERIOD_MS, Reading, RoadSensorReading, Surroundings,
};
use crate::error::{ParamError, Rule};
use crate::rng::SplitMix64;
use crate::sampling::Schedule;
use crate::vehicle::VehicleId;

/// The devices of one car, in the order they were given.
#[derive(Debug, Clone, Default)]
pub(crate) struct CarDevices {
    devices: Vec<Device>,
}

/// How far apart two devices' noise streams start (draws): more than any run draws.
const STREAM_SPACING: u64 = 1 << 40;

impl CarDevices {
    /// Builds `specs` on a car whose sensor slots are `slots` (`None`: a model without them),
    /// their noise drawn from `seed`'s stream.
    ///
    /// # Errors
    /// [`DeviceError`]: a field out of range, a name taken twice or one of
    /// [`CAR_DEVICE_NAMES`], a slot the car does not have.
    pub(crate) fn build(
        specs: &[DeviceSpec],
        slots: Option<&SensorSlots<f64>>,
        seed: u64,
    ) -> Result<CarDevices, DeviceError> {
        let mut devices: Vec<Device> = Vec::with_capacity(specs.len());
        for (k, spec) in specs.iter().enumerate() {
            let name = spec.device_name().to_string();
            spec.settings
                .validate()
                .map_err(|error| DeviceError::Field {
                    name: name.clone(),
                    error,
                })?;
            for (field, &v) in ["translation"; 3].iter().zip(spec.translation.iter()) {
                ParamError::finite(field, v).map_err(|error| DeviceError::Field {
                    name: name.clone(),
                    error,
                })?;
            }
            for &c in spec.rotation.coords.iter() {
                ParamError::finite("rotation", c).map_err(|error| DeviceError::Field {
                    name: name.clone(),
                    error,
                })?;
            }
            let period_ms = match spec.sampling_period_ms {
                None => 0,
                Some(p) if (1..=MAX_SAMPLING_PERIOD_MS).contains(&p) => p,
                Some(p) => {
                    return Err(DeviceError::Field {
                        name,
                        error: ParamError {
                            field: "samplingPeriod",
                            value: f64::from(p),
                            rule: Rule::Text("a whole number of ms from 1 to 65535"),
                        },
                    });
                }
            };
            if CAR_DEVICE_NAMES.contains(&name.as_str()) {
                return Err(DeviceError::ReservedName(name));
            }
            if devices.iter().any(|d| d.name == name) {
                return Err(DeviceError::DuplicateName(name));
            }
            let slot = match spec.slot {
                None => Isometry3::identity(),
                Some(slot) => slots
                    .map(|s| s.get(slot))
                    .ok_or_else(|| DeviceError::NoSlot {
                        name: name.clone(),
                        slot,
                    })?,
            };
            let own = Isometry3::from_parts(Translation3::from(spec.translation), spec.rotation);
            let mut rng = SplitMix64::new(seed);
            rng.advance((k as u64).wrapping_mul(STREAM_SPACING));
            let reading = match &spec.settings {
                DeviceSettings::Gps(_) => Reading::Gps(GpsReading::unsampled()),
                DeviceSettings::InertialUnit(_) => {
                    Reading::InertialUnit(InertialUnitReading::unsampled())
                }
                DeviceSettings::Gyro(_)
                | DeviceSettings::Accelerometer(_)
                | DeviceSettings::Compass(_) => Reading::Vector(Vector3::repeat(f64::NAN)),
                DeviceSettings::DistanceSensor(_) => Reading::Distance(f64::NAN),
                DeviceSettings::Radar(_) => Reading::Radar(None),
                DeviceSettings::Lidar(s) => Reading::Lidar(LidarReading::unsampled(s)),
                DeviceSettings::Camera(_) => Reading::Camera,
                DeviceSettings::Display(_) => Reading::Display,
                DeviceSettings::RoadSensor(_) => Reading::Road(RoadSensorReading::unsampled()),
            };
            let display = match &spec.settings {
                DeviceSettings::Display(s) => Some(Box::new(Display::new(s))),
                _ => None,
            };
            let camera = match &spec.settings {
                DeviceSettings::Camera(s) => Some(Box::new(CameraState::new(s))),
                _ => None,
            };
            devices.push(Device {
                name,
                settings: spec.settings.clone(),
                mount: slot * own,
                schedule: Schedule::new(period_ms),
                rng,
                gps_noise: GpsNoise::default(),
                previous_velocity: PreviousVelocity::default(),
                point_cloud: false,
                reading,
                camera,
                display,
            });
        }
        Ok(CarDevices { devices })
    }

    /// Starts the sampling of the devices built enabled ([`DeviceSpec::sampling_period_ms`])
    /// at `now_ms`, the time their car joins the world: their first sample comes one full
    /// period later, as after a controller's enable.
    pub(crate) fn start_at(&mut self, now_ms: u64) {
        for d in &mut self.devices {
            d.schedule.restart(now_ms);
        }
    }

    /// Disables every device at `now_ms`.
    pub(crate) fn disable_all(&mut self, now_ms: u64) {
        for d in &mut self.devices {
            d.enable(0, now_ms);
        }
    }

    /// The devices, in order.
    pub(crate) fn all(&self) -> &[Device] {
        &self.devices
    }

    /// Device `index`, to change.
    fn device_mut(&mut self, index: usize) -> Result<&mut Device, DeviceError> {
        let count = self.devices.len();
        self.devices
            .get_mut(index)
            .ok_or(DeviceError::Unknown { index, count })
    }

    /// Enables device `index` with a period of `period_ms` ms (0 disables) at `now_ms`.
    pub(crate) fn enable(
        &mut self,
        index: usize,
        period_ms: u32,
        now_ms: u64,
    ) -> Result<(), DeviceError> {
        let device = self.device_mut(index)?;
        device.enable(period_ms, now_ms);
        Ok(())
    }

    /// Display `index`, to draw into.
    pub(crate) fn display_mut(&mut self, index: usize) -> Result<&mut Display, DeviceError> {
        let device = self.device_mut(index)?;
        let name = device.name.clone();
        device.display_mut().ok_or(DeviceError::NotDisplay(name))
    }

    /// Enables the Recognition of camera `index` with a period of `period_ms` ms (0
    /// disables) at `now_ms`.
    pub(crate) fn enable_recognition(
        &mut self,
        index: usize,
        period_ms: u32,
        now_ms: u64,
    ) -> Result<(), DeviceError> {
        let device = self.device_mut(index)?;
        let has = matches!(&device.settings, DeviceSettings::Camera(s) if s.recognition.is_some());
        match device.camera.as_mut() {
            Some(c) if has => {
                c.enable_recognition(period_ms, now_ms);
                Ok(())
            }
            _ => Err(DeviceError::NoRecognition(device.name.clone())),
        }
    }

    /// Enables or disables the point cloud of device `index` (a lidar; the others have
    /// none, and are left as they are).
    pub(crate) fn enable_point_cloud(
        &mut self,
        index: usize,
        enabled: bool,
    ) -> Result<(), DeviceError> {
        let device = self.device_mut(index)?;
        device.point_cloud = enabled && device.kind() == DeviceKind::Lidar;
        Ok(())
    }

    /// True if a device (or a camera's Recognition) is enabled: else a step need not measure
    /// the chassis.
    pub(crate) fn any_enabled(&self) -> bool {
        self.devices.iter().any(|d| {
            d.schedule.is_enabled()
                || d.camera
                    .as_ref()
                    .is_some_and(|c| c.recognition_period_ms() != 0)
        })
    }

    /// True if a camera renders at `now_ms`: the world's solids are then needed.
    pub(crate) fn renders_at(&self, now_ms: u64) -> bool {
        self.devices.iter().any(|d| d.renders_at(now_ms))
    }

    /// What the devices sampling at `now_ms` need of the world: `None` if no ray device
    /// samples (no scene to build), else whether a radar does (the scene's targets).
    pub(crate) fn scene_needed(&self, now_ms: u64) -> Option<bool> {
        let mut due = self
            .devices
            .iter()
            .filter(|d| d.kind().casts_rays() && d.due(now_ms))
            .peekable();
        due.peek()?;
        Some(due.any(|d| d.kind() == DeviceKind::Radar))
    }

    /// True if an infra-red distance sensor samples at `now_ms`: the scene then needs the
    /// surfaces' red.
    pub(crate) fn infra_red_due(&self, now_ms: u64) -> bool {
        self.devices.iter().any(|d| {
            matches!(&d.settings, DeviceSettings::DistanceSensor(s)
                if s.sensor_type == DistanceSensorType::InfraRed)
                && d.due(now_ms)
        })
    }

    /// Samples every device whose period has come, at `now_ms`, on `chassis` of car `own`;
    /// cameras render `solids` (given whenever [`CarDevices::renders_at`] is true), the ray
    /// devices measure in `scene` (given whenever [`CarDevices::scene_needed`] is `Some`).
    pub(crate) fn refresh(
        &mut self,
        chassis: &ChassisMotion,
        now_ms: u64,
        scene: Option<&Scene<'_>>,
        solids: Option<&Solids>,
        own: VehicleId,
        world: Surroundings<'_>,
    ) {
        for d in &mut self.devices {
            d.refresh(chassis, now_ms, scene, solids, own, world);
        }
    }
}
