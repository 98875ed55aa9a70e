//! Runtime warnings of the driver and car libraries, with Webots' exact texts.
//!
//! Webots prints these to `stderr` and carries on; here every setter or getter that would print
//! returns the warning as a value instead (nothing is allocated, nothing is printed), so a C
//! layer can print the identical text and firmware can count them.

use core::fmt;

use proto_geom::plausible::Compact;

/// Which enumeration a raw integer failed to convert to (see [`Warning::InvalidEnumValue`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EnumKind {
    /// `WbuDriverIndicatorState`, argument `state` of `wbu_driver_set_indicator`.
    IndicatorState,
    /// `WbuDriverWiperMode`, argument `mode` of `wbu_driver_set_wiper_mode`.
    WiperMode,
}

impl EnumKind {
    /// The Webots function that takes this enumeration.
    pub const fn function(self) -> &'static str {
        match self {
            EnumKind::IndicatorState => "wbu_driver_set_indicator",
            EnumKind::WiperMode => "wbu_driver_set_wiper_mode",
        }
    }

    /// The name of that function's argument.
    pub const fn argument(self) -> &'static str {
        match self {
            EnumKind::IndicatorState => "state",
            EnumKind::WiperMode => "mode",
        }
    }
}

/// A warning raised by a driver or car function. `Display` gives the text Webots prints (without
/// the trailing newline; see [`Warning::ends_with_newline`]).
///
/// Values are widened to `f64` (exact for `f32`), so the type is the same for both scalars.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// A function was called before the library was initialised. Never produced by this
    /// crate (a [`Driver`](crate::Driver) always exists once built); provided for C layers.
    ///
    /// `Warning: '<init>' should be called before to use '<function>'.`
    NotInitialised {
        /// The init function, e.g. `"wbu_driver_init()"`.
        init: &'static str,
        /// The function called too early, e.g. `"wbu_driver_step()"`.
        function: &'static str,
    },
    /// A negative value was clamped to 0.
    ///
    /// `Warning: '<argument>' should be bigger or equal to 0, used 0 instead.`
    ClampedToZero {
        /// `"throttle"` or `"intensity"`.
        argument: &'static str,
    },
    /// A value above 1 was clamped to 1.
    ///
    /// `Warning: '<argument>' should be smaller or equal to 1, used 1 instead.`
    ClampedToOne {
        /// `"throttle"` or `"intensity"`.
        argument: &'static str,
    },
    /// The argument was NaN, infinite (or, for the indicator period, not positive) and the call
    /// was ignored.
    ///
    /// `Warning: <function>() called with an invalid '<argument>' argument (<value>)`
    /// — Webots' text for NaN steering angles, reused for the other refused arguments.
    InvalidArgument {
        /// The Webots function name, e.g. `"wbu_driver_set_steering_angle"`.
        function: &'static str,
        /// The argument name, e.g. `"steering_angle"`.
        argument: &'static str,
        /// The refused value (printed `NaN`, `inf`, `-inf` or as a number).
        value: f64,
    },
    /// `set_gear` above the highest forward gear; the highest forward gear was used.
    ///
    /// `Warning: this car has only <gear_number> gears.` (`gear_number` counts the reverse
    /// ratio, as Webots' `wbu_driver_get_gear_number`).
    TooManyGears {
        /// Number of entries of `gearRatio`, reverse included.
        gear_number: usize,
    },
    /// `set_gear` below −1; −1 (reverse) was used.
    ///
    /// `Warning: Minimum gear value is -1` (Webots prints it without a newline).
    MinimumGear,
    /// `get_rpm` in speed mode; 0 was returned.
    ///
    /// `Warning: no engine model when cruise control is enable, call to 'wbu_driver_get_rpm()'
    /// is therefore not allowed.`
    NoEngineModel,
    /// `get_gear` in speed mode; 0 was returned.
    ///
    /// `Warning: no gear model when cruise control is enable, call to 'wbu_driver_get_gear()'
    /// is therefore not allowed.`
    NoGearModel,
    /// A raw wheel index outside 0..=3; the call returned 0.
    ///
    /// `Warning: maximum wheel index is 4.` (sic, Webots' text).
    WheelIndex {
        /// The rejected index.
        index: i64,
    },
    /// A raw integer is not a value of the enumeration; the call was ignored. (Webots stores
    /// such values unchecked.)
    ///
    /// `Warning: <function>() called with an invalid '<argument>' argument (<value>)`
    InvalidEnumValue {
        /// Which enumeration.
        kind: EnumKind,
        /// The rejected integer.
        value: i64,
    },
    /// A deprecated Webots name was called (for C layers; the Rust API has one name).
    ///
    /// `Warning: Deprecated '<function>' use '<replacement>' instead.`
    Deprecated {
        /// The deprecated function, e.g. `"wbu_driver_set_brake"`.
        function: &'static str,
        /// Its replacement, e.g. `"wbu_driver_set_brake_intensity"`.
        replacement: &'static str,
    },
}

impl Warning {
    /// False only for [`Warning::MinimumGear`], which Webots prints without a trailing newline.
    pub const fn ends_with_newline(&self) -> bool {
        !matches!(self, Warning::MinimumGear)
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Warning::NotInitialised { init, function } => {
                write!(
                    f,
                    "Warning: '{init}' should be called before to use '{function}'."
                )
            }
            Warning::ClampedToZero { argument } => write!(
                f,
                "Warning: '{argument}' should be bigger or equal to 0, used 0 instead."
            ),
            Warning::ClampedToOne { argument } => write!(
                f,
                "Warning: '{argument}' should be smaller or equal to 1, used 1 instead."
            ),
            Warning::InvalidArgument {
                function,
                argument,
                value,
            } => write!(
                f,
                "Warning: {function}() called with an invalid '{argument}' argument ({})",
                Compact(value)
            ),
            Warning::TooManyGears { gear_number } => {
                write!(f, "Warning: this car has only {gear_number} gears.")
            }
            Warning::MinimumGear => f.write_str("Warning: Minimum gear value is -1"),
            Warning::NoEngineModel => f.write_str(
                "Warning: no engine model when cruise control is enable, call to \
                 'wbu_driver_get_rpm()' is therefore not allowed.",
            ),
            Warning::NoGearModel => f.write_str(
                "Warning: no gear model when cruise control is enable, call to \
                 'wbu_driver_get_gear()' is therefore not allowed.",
            ),
            Warning::WheelIndex { .. } => f.write_str("Warning: maximum wheel index is 4."),
            Warning::InvalidEnumValue { kind, value } => write!(
                f,
                "Warning: {}() called with an invalid '{}' argument ({value})",
                kind.function(),
                kind.argument()
            ),
            Warning::Deprecated {
                function,
                replacement,
            } => write!(
                f,
                "Warning: Deprecated '{function}' use '{replacement}' instead."
            ),
        }
    }
}

impl core::error::Error for Warning {}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::string::ToString;

    use super::*;

    #[test]
    fn webots_texts_verbatim() {
        assert_eq!(
            Warning::ClampedToZero {
                argument: "throttle"
            }
            .to_string(),
            "Warning: 'throttle' should be bigger or equal to 0, used 0 instead."
        );
        assert_eq!(
            Warning::ClampedToOne {
                argument: "intensity"
            }
            .to_string(),
            "Warning: 'intensity' should be smaller or equal to 1, used 1 instead."
        );
        assert_eq!(
            Warning::InvalidArgument {
                function: "wbu_driver_set_steering_angle",
                argument: "steering_angle",
                value: f64::NAN
            }
            .to_string(),
            "Warning: wbu_driver_set_steering_angle() called with an invalid 'steering_angle' \
             argument (NaN)"
        );
        assert_eq!(
            Warning::InvalidArgument {
                function: "wbu_car_set_left_steering_angle",
                argument: "angle",
                value: f64::NEG_INFINITY
            }
            .to_string(),
            "Warning: wbu_car_set_left_steering_angle() called with an invalid 'angle' argument \
             (-inf)"
        );
        // Huge and tiny values in exponent form, not hundreds of digits.
        assert_eq!(
            Warning::InvalidArgument {
                function: "wbu_car_set_indicator_period",
                argument: "period",
                value: -1e308
            }
            .to_string(),
            "Warning: wbu_car_set_indicator_period() called with an invalid 'period' argument \
             (-1e308)"
        );
        assert_eq!(
            Warning::TooManyGears { gear_number: 6 }.to_string(),
            "Warning: this car has only 6 gears."
        );
        assert_eq!(
            Warning::MinimumGear.to_string(),
            "Warning: Minimum gear value is -1"
        );
        assert!(!Warning::MinimumGear.ends_with_newline());
        assert!(Warning::NoGearModel.ends_with_newline());
        assert_eq!(
            Warning::NoEngineModel.to_string(),
            "Warning: no engine model when cruise control is enable, call to \
             'wbu_driver_get_rpm()' is therefore not allowed."
        );
        assert_eq!(
            Warning::NoGearModel.to_string(),
            "Warning: no gear model when cruise control is enable, call to \
             'wbu_driver_get_gear()' is therefore not allowed."
        );
        assert_eq!(
            Warning::WheelIndex { index: 7 }.to_string(),
            "Warning: maximum wheel index is 4."
        );
        assert_eq!(
            Warning::Deprecated {
                function: "wbu_driver_set_brake",
                replacement: "wbu_driver_set_brake_intensity"
            }
            .to_string(),
            "Warning: Deprecated 'wbu_driver_set_brake' use 'wbu_driver_set_brake_intensity' \
             instead."
        );
        assert_eq!(
            Warning::NotInitialised {
                init: "wbu_driver_init()",
                function: "wbu_driver_step()"
            }
            .to_string(),
            "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_step()'."
        );
        assert_eq!(
            Warning::InvalidEnumValue {
                kind: EnumKind::WiperMode,
                value: -3
            }
            .to_string(),
            "Warning: wbu_driver_set_wiper_mode() called with an invalid 'mode' argument (-3)"
        );
    }
}
