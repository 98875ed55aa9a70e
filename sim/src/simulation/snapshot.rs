//! Snapshots of a [`Simulation`]: its whole state copied out, to be put back any number of
//! times, so that a run restored and continued equals the run never interrupted, bit for bit.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use super::recording::RecordingMark;
use super::{Controlled, Named, Simulation};
use crate::appearance::Appearances;
use crate::devices::camera::roads::Patch;
use crate::world::WorldSnapshot;

/// Numbers the simulations of this process, so that a snapshot knows whose it is.
static NEXT_SIMULATION: AtomicU64 = AtomicU64::new(0);

/// A fresh simulation serial number.
pub(super) fn next_serial() -> u64 {
    NEXT_SIMULATION.fetch_add(1, Ordering::Relaxed)
}

/// Why a snapshot cannot be restored.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SnapshotError {
    /// The snapshot was taken of another simulation.
    #[error("the snapshot was taken of another simulation")]
    OtherSimulation,
    /// The recording the snapshot knows is not the simulation's recording now: it was
    /// restarted, or its device readings were handed over, since.
    #[error(
        "the snapshot's recording is no longer the simulation's (restarted or handed over since)"
    )]
    OtherRecording,
    /// [`Simulation::simulation_reset`] on a simulation not built from a world description.
    #[error("the simulation was not loaded from a world description: there is nothing to reset to")]
    NotLoaded,
    /// A log's temporary file could not be shortened back to the snapshot's length.
    #[error("the telemetry's temporary file could not be shortened: {0}")]
    Io(String),
}

/// The whole state of a [`Simulation`] at one instant (see [`Simulation::snapshot`]): the
/// world (`WorldSnapshot`: rapier's sets, islands, broad and narrow phase with their contact
/// caches, every car's wheel, suspension and motor state), each car's driver library (control
/// mode, targets, gearbox, cruise control), sensor devices (enabled state, last readings, noise
/// generators) and keyboard, the lane followers, the `duration`, and how far the recording had
/// got (the samples after it are dropped on restore; the samples before it are not copied).
#[derive(Clone)]
pub struct Snapshot {
    origin: u64,
    world: WorldSnapshot,
    cars: Vec<Controlled>,
    robots: Vec<Named>,
    duration: Option<f64>,
    recording: Option<RecordingMark>,
    replay_overlay: bool,
    appearances: Appearances,
    road_patches: Option<Arc<[Patch]>>,
}

impl Snapshot {
    /// Simulated time when the snapshot was taken (ms).
    pub fn time_ms(&self) -> u64 {
        self.world.time_ms()
    }
}

impl Simulation {
    /// A copy of this simulation's whole state, for [`Simulation::restore`].
    ///
    /// ```
    /// use sim::{CarBuilder, Simulation, World, WorldConfig};
    /// use vehicle_model::Model;
    /// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    /// let (id, _) = sim.add_car(CarBuilder::of_model(Model::BmwX5))?;
    /// sim.driver_mut(id)?.set_cruising_speed(30.0);
    /// let snap = sim.snapshot();
    /// for _ in 0..50 {
    ///     sim.step()?;
    /// }
    /// let first = sim.telemetry(id)?.state;
    /// sim.restore(&snap)?;
    /// for _ in 0..50 {
    ///     sim.step()?;
    /// }
    /// assert_eq!(sim.telemetry(id)?.state, first); // bit for bit
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            origin: self.serial,
            world: self.world.snapshot(),
            cars: self.cars.clone(),
            robots: self.robots.clone(),
            duration: self.duration,
            recording: self.recording.as_ref().map(|r| r.mark()),
            replay_overlay: self.replay_overlay,
            appearances: self.appearances.clone(),
            road_patches: self.road_patches.clone(),
        }
    }

    /// Puts this simulation back in the state of `snap` (which stays valid: it can be restored
    /// again). A recording started after the snapshot is dropped; one that was under way loses
    /// the samples recorded since.
    ///
    /// # Errors
    /// [`SnapshotError::OtherSimulation`] for a snapshot of another simulation,
    /// [`SnapshotError::OtherRecording`] if the recording was restarted (or its device rows
    /// handed over) since the snapshot; the simulation is then unchanged.
    /// [`SnapshotError::Io`] if a log's temporary file cannot be shortened.
    pub fn restore(&mut self, snap: &Snapshot) -> Result<(), SnapshotError> {
        if snap.origin != self.serial {
            return Err(SnapshotError::OtherSimulation);
        }
        match (&mut self.recording, &snap.recording) {
            (Some(recording), Some(mark)) => recording.rewind(mark)?,
            (None, Some(_)) => return Err(SnapshotError::OtherRecording),
            (recording, None) => *recording = None,
        }
        self.world.restore(&snap.world);
        self.cars.clone_from(&snap.cars);
        self.robots.clone_from(&snap.robots);
        self.duration = snap.duration;
        self.replay_overlay = snap.replay_overlay;
        self.appearances.clone_from(&snap.appearances);
        self.road_patches.clone_from(&snap.road_patches);
        Ok(())
    }

    /// Puts the simulation back as [`Simulation::from_description`] built it: time 0, every car
    /// and body where the world file put it, the drivers and devices as new, no recording
    /// (the next [`Simulation::record`] starts one). Webots: `wb_supervisor_simulation_reset`.
    ///
    /// # Errors
    /// [`SnapshotError::NotLoaded`] for a simulation built with [`Simulation::new`].
    pub fn simulation_reset(&mut self) -> Result<(), SnapshotError> {
        let loaded = self.loaded.take().ok_or(SnapshotError::NotLoaded)?;
        // Dropping the recording cannot fail: the loaded state has none.
        self.recording = None;
        let restored = self.restore(&loaded);
        self.loaded = Some(loaded);
        restored
    }
}
