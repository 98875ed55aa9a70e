//! Sounds of the `engine_speaker`: the engine loop (volume and pitch from the engine state) and
//! the indicator blinker.

use ackermann::{PerWheel, Real};
use powertrain::{EngineType, Powertrain};

use crate::mode::ControlMode;

/// The blinker sound file Webots loops on the `engine_speaker` while an indicator or the hazard
/// flashers are on (volume 1, pitch 1, balance 0).
pub const BLINKER_SOUND_FILE: &str = "sounds/blinker.wav";

/// Weight of the throttle (or its speed-mode estimate) in the engine volume (Webots:
/// `THROTTLE_TO_VOLUME_GAIN`).
const THROTTLE_TO_VOLUME_GAIN: f64 = 0.2;

/// Weight of the engine speed in the engine volume (Webots: `RPM_TO_VOLUME_GAIN`).
const RPM_TO_VOLUME_GAIN: f64 = 0.5;

/// Speed deficit (km/h) that counts as full throttle for the speed-mode volume.
const FULL_THROTTLE_SPEED_DEFICIT: f64 = 25.0;

/// How one looping sound of the `engine_speaker` should be playing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoundCommand<T: Real> {
    /// True while the sound loops; false = stopped.
    pub playing: bool,
    /// Volume (dimensionless gain, 1 = the file's level).
    pub volume: T,
    /// Pitch (dimensionless playback-rate factor, 1 = the file's pitch).
    pub pitch: T,
}

impl<T: Real> SoundCommand<T> {
    /// Stopped, with unit volume and pitch.
    pub const STOPPED: Self = SoundCommand {
        playing: false,
        volume: T::ONE,
        pitch: T::ONE,
    };
}

/// Both sounds of the `engine_speaker`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sounds<T: Real> {
    /// The engine loop (Webots field `engineSound`; never playing for a car without one).
    pub engine: SoundCommand<T>,
    /// The blinker loop [`BLINKER_SOUND_FILE`] (volume 1, pitch 1): playing while an indicator
    /// or the hazard flashers are on.
    pub blinker: bool,
}

impl<T: Real> Sounds<T> {
    /// Everything silent.
    pub const SILENT: Self = Sounds {
        engine: SoundCommand::STOPPED,
        blinker: false,
    };
}

/// What the engine-sound update reads from the driver state.
pub(crate) struct EngineSoundInput<'a, T: Real> {
    pub mode: ControlMode,
    /// Estimated engine speed of the last step (rpm), torque mode.
    pub rpm: T,
    pub throttle: T,
    /// The four wheel speeds (rad/s), or `None` while they cannot be measured yet.
    pub wheel_speeds: Option<&'a PerWheel<T>>,
    /// Cruise-control target (km/h).
    pub cruising_speed: T,
    /// Estimated vehicle speed (km/h).
    pub current_speed: T,
}

/// Step 8 of `wbu_driver_step` (spec §3.5): the engine loop's volume and pitch, or `None`
/// when Webots leaves the sound untouched (speed mode before the wheel speeds are measurable).
///
/// Deliberate difference: in speed mode the rpm factor of the volume uses
/// `min(rpm, engineMaxRPM)` as intended; Webots uses `max`, which makes it always ≥ 1.
pub(crate) fn engine_sound<T: Real>(
    powertrain: &Powertrain<T>,
    rpm_reference: T,
    input: &EngineSoundInput<'_, T>,
) -> Option<SoundCommand<T>> {
    let engine = powertrain.engine();
    let min_rpm = engine.min_rpm();
    let max_rpm = engine.max_rpm();
    let throttle_gain = T::from_f64(THROTTLE_TO_VOLUME_GAIN);
    let rpm_gain = T::from_f64(RPM_TO_VOLUME_GAIN);
    let rpm_factor = |rpm: T| (T::ONE - rpm_gain) + rpm_gain * rpm.min(max_rpm) / max_rpm;

    let mut volume = T::ONE;
    let mut rpm = T::ZERO;
    match input.mode {
        ControlMode::Torque => {
            rpm = input.rpm;
            volume *= (T::ONE - throttle_gain) + throttle_gain * input.throttle;
            volume *= rpm_factor(rpm);
        }
        ControlMode::Speed => {
            let virtual_gear = powertrain.speed_mode_virtual_gear(input.wheel_speeds?)?;
            rpm = virtual_gear.rpm;
            let full = T::from_f64(FULL_THROTTLE_SPEED_DEFICIT);
            let deficit = (input.cruising_speed - input.current_speed).clamp(T::ZERO, full);
            volume *= (T::ONE - throttle_gain) + throttle_gain * deficit / full;
            volume *= rpm_factor(rpm);
        }
        ControlMode::Undefined => {}
    }

    let mut stop = false;
    match engine.engine_type() {
        EngineType::PowerSplitHybrid => {
            if rpm > min_rpm {
                rpm = engine.params().hybrid_power_split_rpm;
            } else {
                stop = true;
            }
        }
        EngineType::ParallelHybrid => stop = rpm < min_rpm,
        EngineType::Combustion | EngineType::Electric => {}
    }
    let rpm = rpm.max(min_rpm);
    Some(SoundCommand {
        playing: !stop,
        volume: volume.finite_or(T::ONE),
        pitch: (rpm / rpm_reference).finite_or(T::ONE),
    })
}
