//! The devices of the cars as the `Simulation` runs them: their sampling after each step,
//! enabling, the cameras' Recognition, the displays, the keyboards, the looks of the world's
//! things for the cameras, and the last images a recorded run saves.

use std::path::{Path, PathBuf};

use proto_geom::nalgebra::{Isometry3, Translation3};

use super::EnergyMeter;
use super::{Controlled, Simulation};
use crate::appearance::{Appearance, Appearances, SceneObject, lane_color};
use crate::config::Obstacle;
use crate::devices::Surroundings;
use crate::devices::camera::roads;
use crate::devices::camera::solids::Solids;
use crate::devices::rays::Reds;
use crate::devices::{
    ChassisMotion, Device, DeviceSettings, Display, DisplayImage, GpsFrame, PixelFormat, save_png,
};
use crate::error::SimError;
use crate::keyboard::Keyboard;
use crate::report::OutputError;
use crate::vehicle::VehicleId;
use crate::world::World;

/// The red of every surface of `world` as `looks` colours it: the obstacles, the dynamic
/// boxes, the cars' bodies, the robots' bodies, the road lanes; the ground for the rest.
fn reds(world: &World, looks: &Appearances) -> Reds {
    let vehicles = world.vehicles().len();
    let red = |object: SceneObject| looks.color(object, vehicles)[0];
    // A cone's own colour is its default (as the camera and the replay draw it); a look set
    // in the world file overrides it, as for any obstacle.
    let obstacle_red = |i: usize| match world.config().obstacles.get(i) {
        Some(Obstacle::Cone { cone, .. }) if looks.explicit(SceneObject::Obstacle(i)).is_none() => {
            cone.color[0]
        }
        _ => red(SceneObject::Obstacle(i)),
    };
    let colliders = world
        .obstacle_colliders()
        .iter()
        .map(|&(i, c)| (c, obstacle_red(i)))
        .chain(
            world
                .lane_colliders()
                .iter()
                .map(|&(c, kind)| (c, lane_color(kind)[0])),
        )
        .collect();
    let boxes = world.body_handles().iter().enumerate();
    let bodies = boxes
        .map(|(i, &b)| (b, red(SceneObject::Body(i))))
        .chain(world.vehicles().iter().enumerate().flat_map(|(i, v)| {
            let r = red(SceneObject::Car(i));
            v.bodies().into_iter().map(move |b| (b, r))
        }))
        .chain(world.robots().iter().enumerate().flat_map(|(i, robot)| {
            let r = red(SceneObject::Robot(i));
            robot.bodies().into_iter().map(move |b| (b, r))
        }))
        .collect();
    Reds {
        colliders,
        bodies,
        ..Reds::default()
    }
}

impl Simulation {
    /// Car `id`, to change.
    pub(super) fn car_mut(&mut self, id: VehicleId) -> Result<&mut Controlled, SimError> {
        self.cars
            .iter_mut()
            .find(|c| c.id == id)
            .ok_or(SimError::UnknownVehicle(id.index()))
    }

    /// Samples every enabled device whose period has come, on its car's chassis as the step
    /// left it (Webots refreshes its sensors at the end of each step). The world's solids are
    /// gathered once, and only when a camera renders; a car's ray scene is built only when one
    /// of its ray devices samples.
    pub(super) fn refresh_devices(&mut self) -> Result<(), SimError> {
        let now_ms = self.world.time_ms();
        let gravity = self.world.config().gravity;
        let solids = if self.cars.iter().any(|c| c.devices.renders_at(now_ms)) {
            let roads = self
                .road_patches
                .get_or_insert_with(|| roads::patches(&self.world.config().roads).into())
                .clone();
            Some(Solids::of(&self.world, &self.appearances, roads))
        } else {
            None
        };
        for car in &mut self.cars {
            if !car.devices.any_enabled()
                || car.energy.as_ref().is_some_and(EnergyMeter::powered_off)
            {
                continue;
            }
            let s = self.world.vehicle(car.id)?.state();
            let chassis = ChassisMotion {
                pose: Isometry3::from_parts(Translation3::from(s.position.coords), s.orientation),
                velocity: s.velocity,
                angular_velocity: s.angular_velocity,
                gravity,
            };
            let scene = match car.devices.scene_needed(now_ms) {
                Some(radar) => {
                    let scene = self.world.scene(car.id, radar)?;
                    Some(if car.devices.infra_red_due(now_ms) {
                        scene.with_reds(reds(&self.world, &self.appearances))
                    } else {
                        scene
                    })
                }
                None => None,
            };
            car.devices.refresh(
                &chassis,
                now_ms,
                scene.as_ref(),
                solids.as_ref(),
                car.id,
                Surroundings {
                    roads: &self.world.config().roads,
                    gps: &self.gps,
                },
            );
        }
        Ok(())
    }

    /// The sensor devices of car `id`, in the order its builder (or world file) lists them,
    /// each with its name, kind, sampling period and last sample.
    ///
    /// ```
    /// use sim::devices::{DeviceKind, DeviceSettings, DeviceSpec, Reading};
    /// use sim::{CarBuilder, Simulation, World, WorldConfig};
    /// use vehicle_model::Model;
    /// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    /// let gyro = DeviceSpec::new(DeviceSettings::default_of(DeviceKind::Gyro));
    /// let (car, _) = sim.add_car(CarBuilder::of_model(Model::BmwX5).device(gyro))?;
    /// sim.enable_device(car, 0, 20)?; // ms
    /// sim.step()?;
    /// let Reading::Vector(w) = *sim.devices(car)?[0].reading() else { unreachable!() };
    /// assert!(w.x.is_nan()); // no sample before one full period
    /// sim.step()?;
    /// let Reading::Vector(w) = *sim.devices(car)?[0].reading() else { unreachable!() };
    /// assert!(w.z.abs() < 1e-3); // rad/s: a parked car hardly turns
    /// # Ok::<(), sim::SimError>(())
    /// ```
    pub fn devices(&self, id: VehicleId) -> Result<&[Device], SimError> {
        self.car(id).map(|c| c.devices.all())
    }

    /// Display `index` of car `id`, to draw into (Webots: the `wb_display_*` functions).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Device`] for an index the car does not have
    /// or a device that is no display.
    pub fn display_mut(&mut self, id: VehicleId, index: usize) -> Result<&mut Display, SimError> {
        let car = self.car_mut(id)?;
        Ok(car.devices.display_mut(index)?)
    }

    /// The keyboard of car `id`'s controller: the keys its programme presses
    /// ([`crate::keyboard`]).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn keyboard(&self, id: VehicleId) -> Result<&Keyboard, SimError> {
        self.car(id).map(|c| &c.keyboard)
    }

    /// Enables car `id`'s keyboard with a period of `period_ms` ms (0 disables) (Webots:
    /// `wb_keyboard_enable`).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn enable_keyboard(&mut self, id: VehicleId, period_ms: u32) -> Result<(), SimError> {
        let now_ms = self.world.time_ms();
        let car = self.car_mut(id)?;
        car.keyboard.enable(period_ms, now_ms);
        Ok(())
    }

    /// The next key car `id`'s keyboard holds, −1 when none is left (Webots:
    /// `wb_keyboard_get_key`).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn next_key(&mut self, id: VehicleId) -> Result<i32, SimError> {
        let car = self.car_mut(id)?;
        Ok(car.keyboard.next_key())
    }

    /// The world's GPS frame (Webots' `WorldInfo.gpsCoordinateSystem` and `gpsReference`).
    pub fn gps_frame(&self) -> &GpsFrame {
        &self.gps
    }

    /// Sets the world's GPS frame: the GPS devices report in it from their next sample.
    ///
    /// # Errors
    /// [`SimError::Param`] for a reference [`GpsFrame::validate`] refuses.
    pub fn set_gps_frame(&mut self, frame: GpsFrame) -> Result<(), SimError> {
        frame.validate()?;
        self.gps = frame;
        Ok(())
    }

    /// Gives `object` the look `appearance`: its colour in camera images, its recognition
    /// colours and model for a camera's Recognition ([`crate::appearance`]).
    ///
    /// # Errors
    /// [`SimError::Param`] for a colour out of [0, 1].
    pub fn set_appearance(
        &mut self,
        object: SceneObject,
        appearance: Appearance,
    ) -> Result<(), SimError> {
        self.appearances.set(object, appearance)?;
        Ok(())
    }

    /// Enables the Recognition of camera `index` of car `id` with a sampling period of
    /// `period_ms` ms (Webots: `wb_camera_recognition_enable`; 0 disables). The camera itself
    /// need not be enabled.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Device`] for an index the car does not have
    /// or a device without Recognition.
    pub fn enable_recognition(
        &mut self,
        id: VehicleId,
        index: usize,
        period_ms: u32,
    ) -> Result<(), SimError> {
        let now_ms = self.world.time_ms();
        let car = self.car_mut(id)?;
        Ok(car.devices.enable_recognition(index, period_ms, now_ms)?)
    }

    /// Enables device `index` of car `id` with a sampling period of `period_ms` ms (Webots:
    /// `wb_<device>_enable`; 0 disables, as `wb_<device>_disable`). Its first sample comes one
    /// full period from now ([`crate::devices`]).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Device`] for an index the car does not have.
    pub fn enable_device(
        &mut self,
        id: VehicleId,
        index: usize,
        period_ms: u32,
    ) -> Result<(), SimError> {
        let now_ms = self.world.time_ms();
        let car = self.car_mut(id)?;
        Ok(car.devices.enable(index, period_ms, now_ms)?)
    }

    /// Draws (`true`) or not the radars' targets in the replay of runs recorded from now on
    /// ([`crate::replay::overlay`]; the world file's `replayOverlay`).
    pub fn set_replay_overlay(&mut self, on: bool) {
        self.replay_overlay = on;
    }

    /// True when the replay draws the radars' targets ([`Simulation::set_replay_overlay`]).
    pub fn replay_overlay(&self) -> bool {
        self.replay_overlay
    }

    /// Disables every device of every car, as a Webots controller finds them when it starts:
    /// the C and Python controllers call this, so that the world file's `samplingPeriod` (for
    /// runs without a controller) leaves a controller's devices as Webots does, and a
    /// controller enables what it reads.
    pub fn disable_devices(&mut self) {
        let now_ms = self.world.time_ms();
        for car in &mut self.cars {
            car.devices.disable_all(now_ms);
        }
    }

    /// Enables (`true`) or disables the point cloud of lidar `index` of car `id` (Webots:
    /// `wb_lidar_enable_point_cloud`, `wb_lidar_disable_point_cloud`); another device is left
    /// as it is.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Device`] for an index the car does not have.
    pub fn enable_point_cloud(
        &mut self,
        id: VehicleId,
        index: usize,
        enabled: bool,
    ) -> Result<(), SimError> {
        let car = self.car_mut(id)?;
        Ok(car.devices.enable_point_cloud(index, enabled)?)
    }

    /// Writes the last image of every camera that took one and every display into `dir` as
    /// `<car>-<device>.png` (characters other than letters, digits, `-` and `_` written `_`).
    pub(super) fn save_images(&self, dir: &Path) -> Result<Vec<PathBuf>, OutputError> {
        let mut written = Vec::new();
        for car in &self.cars {
            for d in car.devices.all() {
                let image = match (d.settings(), d.camera(), d.display()) {
                    (DeviceSettings::Camera(s), Some(c), _) if c.has_image() => {
                        DisplayImage::from_bytes(s.width, s.height, c.image(), PixelFormat::Bgra)
                    }
                    (_, _, Some(display)) => Some(display.image().clone()),
                    _ => None,
                };
                let Some(image) = image else {
                    continue;
                };
                let name: String = format!("{}-{}", car.name, d.name())
                    .chars()
                    .map(|c| {
                        if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                            c
                        } else {
                            '_'
                        }
                    })
                    .collect();
                let path = dir.join(format!("{name}.png"));
                save_png(&path, &image).map_err(|e| OutputError::Io {
                    path: path.clone(),
                    source: std::io::Error::other(e.to_string()),
                })?;
                written.push(path);
            }
        }
        Ok(written)
    }
}
