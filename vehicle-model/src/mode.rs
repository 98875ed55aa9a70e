//! The driver's discrete states: control mode, indicator and wiper modes.
//!
//! Each enum keeps the Webots ABI value as its discriminant and converts from raw integers
//! (what a C caller passes) with a typed warning for out-of-range values.

use core::fmt;

use crate::warning::{EnumKind, Warning};

/// How the driven wheels are actuated (Webots: `WbuDriverControlMode`).
///
/// The mode is chosen by the last call of [`Driver::set_cruising_speed`](crate::Driver::set_cruising_speed)
/// (→ [`ControlMode::Speed`]) or [`Driver::set_throttle`](crate::Driver::set_throttle)
/// (→ [`ControlMode::Torque`]); before either, it is [`ControlMode::Undefined`] and the driven
/// wheels are held at zero speed (Webots' parking behaviour).
#[repr(i8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum ControlMode {
    /// No mode chosen yet (Webots `UNDEFINED_CONTROL_MODE` = −1).
    #[default]
    Undefined = -1,
    /// Cruise control: wheel velocities are imposed, no engine model (Webots `SPEED` = 0).
    Speed = 0,
    /// Throttle, engine model and gearbox (Webots `TORQUE` = 1).
    Torque = 1,
}

impl ControlMode {
    /// The Webots `WbuDriverControlMode` value (−1, 0 or 1).
    #[inline]
    pub const fn webots_value(self) -> i32 {
        self as i32
    }

    /// The mode with Webots value `v`, or `None` outside −1..=1.
    #[inline]
    pub const fn from_webots_value(v: i32) -> Option<ControlMode> {
        match v {
            -1 => Some(ControlMode::Undefined),
            0 => Some(ControlMode::Speed),
            1 => Some(ControlMode::Torque),
            _ => None,
        }
    }

    /// The Webots enumerator name (`"UNDEFINED_CONTROL_MODE"`, `"SPEED"`, `"TORQUE"`).
    #[inline]
    pub const fn webots_name(self) -> &'static str {
        match self {
            ControlMode::Undefined => "UNDEFINED_CONTROL_MODE",
            ControlMode::Speed => "SPEED",
            ControlMode::Torque => "TORQUE",
        }
    }
}

impl fmt::Display for ControlMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// The turn-indicator lever (Webots: `WbuDriverIndicatorState`).
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum IndicatorState {
    /// Lever in the centre, no indicator (Webots `OFF` = 0).
    #[default]
    Off = 0,
    /// Right indicator blinking (Webots `RIGHT` = 1).
    Right = 1,
    /// Left indicator blinking (Webots `LEFT` = 2).
    Left = 2,
}

impl IndicatorState {
    /// The Webots `WbuDriverIndicatorState` value (0, 1 or 2).
    #[inline]
    pub const fn webots_value(self) -> i32 {
        self as i32
    }

    /// The state with Webots value `v`, or `None` outside 0..=2.
    #[inline]
    pub const fn from_webots_value(v: i32) -> Option<IndicatorState> {
        match v {
            0 => Some(IndicatorState::Off),
            1 => Some(IndicatorState::Right),
            2 => Some(IndicatorState::Left),
            _ => None,
        }
    }

    /// Converts a raw Webots value, with a warning for values outside 0..=2.
    ///
    /// Webots stores any value unchecked in `wbu_driver_set_indicator`; this crate refuses it
    /// (see `COMPATIBILITY.md`).
    ///
    /// # Errors
    /// [`Warning::InvalidEnumValue`] naming the rejected value.
    #[inline]
    pub const fn try_from_webots_value(v: i32) -> Result<IndicatorState, Warning> {
        match IndicatorState::from_webots_value(v) {
            Some(s) => Ok(s),
            None => Err(Warning::InvalidEnumValue {
                kind: EnumKind::IndicatorState,
                value: v as i64,
            }),
        }
    }

    /// The Webots enumerator name (`"OFF"`, `"RIGHT"`, `"LEFT"`).
    #[inline]
    pub const fn webots_name(self) -> &'static str {
        match self {
            IndicatorState::Off => "OFF",
            IndicatorState::Right => "RIGHT",
            IndicatorState::Left => "LEFT",
        }
    }
}

impl fmt::Display for IndicatorState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// The windscreen-wiper switch (Webots: `WbuDriverWiperMode`).
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum WiperMode {
    /// Parked at the motors' minimum position (Webots `DOWN` = 0).
    #[default]
    Down = 0,
    /// One sweep every 4 s at 2 rad/s (Webots `SLOW` = 1).
    Slow = 1,
    /// Continuous sweeps at 2 rad/s (Webots `NORMAL` = 2).
    Normal = 2,
    /// Continuous sweeps at 4 rad/s (Webots `FAST` = 3).
    Fast = 3,
}

impl WiperMode {
    /// The Webots `WbuDriverWiperMode` value (0 to 3).
    #[inline]
    pub const fn webots_value(self) -> i32 {
        self as i32
    }

    /// The mode with Webots value `v`, or `None` outside 0..=3.
    #[inline]
    pub const fn from_webots_value(v: i32) -> Option<WiperMode> {
        match v {
            0 => Some(WiperMode::Down),
            1 => Some(WiperMode::Slow),
            2 => Some(WiperMode::Normal),
            3 => Some(WiperMode::Fast),
            _ => None,
        }
    }

    /// Converts a raw Webots value, with a warning for values outside 0..=3.
    ///
    /// # Errors
    /// [`Warning::InvalidEnumValue`] naming the rejected value.
    #[inline]
    pub const fn try_from_webots_value(v: i32) -> Result<WiperMode, Warning> {
        match WiperMode::from_webots_value(v) {
            Some(m) => Ok(m),
            None => Err(Warning::InvalidEnumValue {
                kind: EnumKind::WiperMode,
                value: v as i64,
            }),
        }
    }

    /// The Webots enumerator name (`"DOWN"`, `"SLOW"`, `"NORMAL"`, `"FAST"`).
    #[inline]
    pub const fn webots_name(self) -> &'static str {
        match self {
            WiperMode::Down => "DOWN",
            WiperMode::Slow => "SLOW",
            WiperMode::Normal => "NORMAL",
            WiperMode::Fast => "FAST",
        }
    }
}

impl fmt::Display for WiperMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn webots_values_round_trip() {
        for m in [
            ControlMode::Undefined,
            ControlMode::Speed,
            ControlMode::Torque,
        ] {
            assert_eq!(ControlMode::from_webots_value(m.webots_value()), Some(m));
        }
        assert_eq!(ControlMode::Undefined.webots_value(), -1);
        assert_eq!(ControlMode::from_webots_value(2), None);
        assert_eq!(IndicatorState::Left.webots_value(), 2);
        assert_eq!(WiperMode::Fast.webots_value(), 3);
        for v in 0..4 {
            assert_eq!(
                WiperMode::try_from_webots_value(v).unwrap().webots_value(),
                v
            );
        }
    }

    #[test]
    fn raw_values_out_of_range_are_warnings() {
        assert_eq!(
            IndicatorState::try_from_webots_value(3),
            Err(Warning::InvalidEnumValue {
                kind: EnumKind::IndicatorState,
                value: 3
            })
        );
        assert!(WiperMode::try_from_webots_value(-1).is_err());
        assert!(WiperMode::try_from_webots_value(i32::MIN).is_err());
        assert!(IndicatorState::try_from_webots_value(i32::MAX).is_err());
    }
}
