//! Windscreen wipers: the two wiper motors' range, their command and the per-step sweep logic.

use ackermann::Real;

use crate::mode::WiperMode;

/// How close (rad) the wiper sensor must be to an end of the range to count as "at the end".
///
/// Webots compares the sensor with the motor limits for exact equality, which works there
/// because the wiper solids are moved kinematically; a physical or numerically integrated
/// wiper needs a tolerance.
pub const WIPER_END_TOLERANCE: f64 = 0.01;

/// Wiper velocity in every mode but [`WiperMode::Fast`] (rad/s).
pub const WIPER_SLOW_VELOCITY: f64 = 2.0;

/// Wiper velocity in [`WiperMode::Fast`] (rad/s).
pub const WIPER_FAST_VELOCITY: f64 = 4.0;

/// The position range of the wiper motors (rad), from the model.
///
/// Webots: `minPosition` / `maxPosition` of the `right_wiper_motor` (the left motor is commanded
/// to its own limits; the shipped BmwX5 uses [0, 1.6] rad for both).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WiperRange<T: Real> {
    /// Parked position (rad). Webots: `minPosition`.
    pub min: T,
    /// Fully swept position (rad). Webots: `maxPosition`.
    pub max: T,
}

impl<T: Real> WiperRange<T> {
    /// True if both ends are finite and `min < max`.
    pub fn is_valid(&self) -> bool {
        self.min.is_finite() && self.max.is_finite() && self.min < self.max
    }
}

/// The command for both wiper motors (position control).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WiperCommand<T: Real> {
    /// Target position of both wiper motors (rad).
    pub target: T,
    /// Maximum velocity of both wiper motors while moving to the target (rad/s).
    pub velocity: T,
}

/// The wiper state machine of the driver library.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wipers<T: Real> {
    range: WiperRange<T>,
    mode: WiperMode,
    command: WiperCommand<T>,
}

impl<T: Real> Wipers<T> {
    /// Parked wipers in mode [`WiperMode::Down`].
    pub(crate) fn new(range: WiperRange<T>) -> Self {
        Wipers {
            range,
            mode: WiperMode::Down,
            command: WiperCommand {
                target: range.min,
                velocity: T::from_f64(WIPER_SLOW_VELOCITY),
            },
        }
    }

    pub(crate) fn mode(&self) -> WiperMode {
        self.mode
    }

    pub(crate) fn command(&self) -> WiperCommand<T> {
        self.command
    }

    /// Webots `wbu_driver_set_wiper_mode`: store the mode, set the velocity, park on `Down`.
    pub(crate) fn set_mode(&mut self, mode: WiperMode) {
        self.mode = mode;
        self.command.velocity = T::from_f64(if mode == WiperMode::Fast {
            WIPER_FAST_VELOCITY
        } else {
            WIPER_SLOW_VELOCITY
        });
        if mode == WiperMode::Down {
            self.command.target = self.range.min;
        }
    }

    /// Step 2 of `wbu_driver_step`: reverse at the ends of the sweep; in slow mode stay down
    /// except during simulation seconds whose integer part is a multiple of 4.
    ///
    /// `sensor` is the wiper position sensor (rad); without a reading nothing happens, as in
    /// Webots without a `wiper_sensor`.
    pub(crate) fn step(&mut self, time: T, sensor: Option<T>) {
        let Some(position) = sensor.filter(|p| p.is_finite()) else {
            return;
        };
        if self.mode == WiperMode::Down {
            return;
        }
        let tolerance = T::from_f64(WIPER_END_TOLERANCE);
        let four = T::from_f64(4.0);
        let second = time.trunc();
        // `(int)t % 4 != 0`; a non-finite time never opens the slow-mode window.
        let stop = !second.is_finite() || second - four * (second / four).trunc() != T::ZERO;
        if (position - self.range.min).abs() <= tolerance {
            self.command.target = self.range.max;
        }
        if (position - self.range.max).abs() <= tolerance || (self.mode == WiperMode::Slow && stop)
        {
            self.command.target = self.range.min;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A range of [0, 1.6] rad, the BmwX5's.
    const RANGE: WiperRange<f64> = WiperRange { min: 0.0, max: 1.6 };

    fn at(w: &mut Wipers<f64>, t: f64, pos: f64) -> f64 {
        w.step(t, Some(pos));
        w.command().target
    }

    #[test]
    fn normal_mode_sweeps_continuously() {
        let mut w = Wipers::new(RANGE);
        w.set_mode(WiperMode::Normal);
        assert_eq!(w.command().velocity, 2.0);
        assert_eq!(at(&mut w, 1.5, 0.0), 1.6); // parked: go up
        assert_eq!(at(&mut w, 1.6, 0.8), 1.6); // mid-sweep: keep going
        assert_eq!(at(&mut w, 2.3, 1.595), 0.0); // within tolerance of the top: go down
        assert_eq!(at(&mut w, 2.9, 0.004), 1.6); // back at the bottom: up again
    }

    #[test]
    fn slow_mode_only_starts_in_multiples_of_four_seconds() {
        let mut w = Wipers::new(RANGE);
        w.set_mode(WiperMode::Slow);
        // floor(t) = 1, 2, 3: held down.
        for t in [1.0, 2.5, 3.99] {
            assert_eq!(at(&mut w, t, 0.0), 0.0, "t = {t}");
        }
        // floor(t) = 4: sweep starts; mid-sweep it continues while floor(t) mod 4 == 0.
        assert_eq!(at(&mut w, 4.0, 0.0), 1.6);
        assert_eq!(at(&mut w, 4.5, 0.9), 1.6);
        // Leaving the window pulls it back down even mid-sweep.
        assert_eq!(at(&mut w, 5.0, 1.2), 0.0);
        assert_eq!(at(&mut w, 8.2, 0.0), 1.6);
    }

    #[test]
    fn fast_mode_velocity_and_down_parks() {
        let mut w = Wipers::new(RANGE);
        w.set_mode(WiperMode::Fast);
        assert_eq!(w.command().velocity, 4.0);
        assert_eq!(at(&mut w, 0.1, 0.0), 1.6);
        w.set_mode(WiperMode::Down);
        assert_eq!(
            w.command(),
            WiperCommand {
                target: 0.0,
                velocity: 2.0
            }
        );
        // Down: the step logic is off, even at an end.
        assert_eq!(at(&mut w, 0.2, 1.6), 0.0);
        assert_eq!(at(&mut w, 0.3, 0.0), 0.0);
    }

    #[test]
    fn missing_or_invalid_sensor_changes_nothing() {
        let mut w = Wipers::new(RANGE);
        w.set_mode(WiperMode::Normal);
        w.step(1.0, None);
        assert_eq!(w.command().target, 0.0);
        w.step(1.0, Some(f64::NAN));
        assert_eq!(w.command().target, 0.0);
        w.step(f64::NAN, Some(0.0));
        assert_eq!(w.command().target, 1.6); // normal mode ignores the clock
        w.set_mode(WiperMode::Slow);
        w.step(f64::INFINITY, Some(0.0));
        assert_eq!(w.command().target, 0.0); // no slow-mode window at t = ∞
    }
}
