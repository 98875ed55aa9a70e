//! `webots/differential_wheels.h`: the legacy DifferentialWheels robot (Webots ≤ R2018a).
//!
//! The functions act on the world's `[differential_wheels]` robot, loading the world first if
//! needed; in a world whose robot is a car they print an error and return 0. Speeds are in
//! speed units (`speedUnit` rad/s each), encoders in increments (`encoderResolution` per rad),
//! sampling periods in ms. Error texts are Webots'.

use std::ffi::c_int;

use sim::{DifferentialWheels, RobotWarning};

use crate::message::{self, format_g};
use crate::session::with_differential_wheels;

/// Prints what Webots' controller library prints for `warning`.
fn report(warning: Option<RobotWarning>) {
    let Some(w) = warning else { return };
    match w {
        RobotWarning::InvalidNan { function } => {
            message::error(format_args!(
                "{function}(): invalid NaN value passed as argument."
            ));
        }
        RobotWarning::SpeedOverflow {
            left,
            right,
            max_speed,
            speed_unit,
        } => message::error(format_args!(
            "wb_differential_wheels_set_speed({},{}) overflows maxSpeed/speedUnit: {}/{}={}.",
            format_g(left),
            format_g(right),
            format_g(max_speed),
            format_g(speed_unit),
            format_g(max_speed / speed_unit)
        )),
        RobotWarning::Infinite {
            function,
            argument,
            value,
        } => message::error(format_args!(
            "{function}() called with an invalid '{argument}' argument ({})",
            format_g(value)
        )),
        RobotWarning::NegativePeriod { .. } => message::error(
            "wb_differential_wheels_enable_encoders() called with negative sampling period.",
        ),
    }
}

/// An encoder value; prints Webots' error first if the encoders are disabled.
fn encoder(function: &str, robot: &DifferentialWheels, value: f64) -> f64 {
    if robot.encoders_sampling_period() == 0 {
        message::error(format_args!(
            "{function}() called for a disabled device! Please use: \
             wb_differential_wheels_enable_encoders()."
        ));
    }
    value
}

/// A commanded speed for the getters: 0 before the first command (Webots: NaN).
fn command(speed: f64) -> f64 {
    if speed.is_nan() { 0.0 } else { speed }
}

entry_points! {
    /// Commands the wheel speeds (speed units), applied from the next step. NaN prints
    /// `Error: wb_differential_wheels_set_speed(): invalid NaN value passed as argument.` and
    /// is ignored; a speed above `maxSpeed/speedUnit` prints Webots' "overflows" error. Each
    /// wheel is limited to ±`maxSpeed` rad/s (Webots applies the command anyway). Webots:
    /// `wb_differential_wheels_set_speed`.
    fn wb_differential_wheels_set_speed(left: f64, right: f64) {
        with_differential_wheels("wb_differential_wheels_set_speed()", (), |r| {
            report(r.set_speed(left, right))
        })
    }

    /// The last commanded left speed (speed units; 0 before the first command). Webots:
    /// `wb_differential_wheels_get_left_speed`.
    fn wb_differential_wheels_get_left_speed() -> f64 {
        with_differential_wheels("wb_differential_wheels_get_left_speed()", 0.0, |r| {
            command(r.left_speed())
        })
    }

    /// The last commanded right speed (speed units; 0 before the first command). Webots:
    /// `wb_differential_wheels_get_right_speed`.
    fn wb_differential_wheels_get_right_speed() -> f64 {
        with_differential_wheels("wb_differential_wheels_get_right_speed()", 0.0, |r| {
            command(r.right_speed())
        })
    }

    /// The `maxSpeed` field (rad/s). Webots: `wb_differential_wheels_get_max_speed`.
    fn wb_differential_wheels_get_max_speed() -> f64 {
        with_differential_wheels("wb_differential_wheels_get_max_speed()", 0.0, |r| r.max_speed())
    }

    /// The `speedUnit` field (rad/s per unit). Webots: `wb_differential_wheels_get_speed_unit`.
    fn wb_differential_wheels_get_speed_unit() -> f64 {
        with_differential_wheels("wb_differential_wheels_get_speed_unit()", 0.0, |r| {
            r.speed_unit()
        })
    }

    /// Enables the encoders every `sampling_period` ms (0 disables them); a negative period
    /// prints Webots' error and is ignored. Webots: `wb_differential_wheels_enable_encoders`.
    fn wb_differential_wheels_enable_encoders(sampling_period: c_int) {
        with_differential_wheels("wb_differential_wheels_enable_encoders()", (), |r| {
            report(r.enable_encoders(sampling_period))
        })
    }

    /// Disables the encoders. Webots: `wb_differential_wheels_disable_encoders`.
    fn wb_differential_wheels_disable_encoders() {
        with_differential_wheels("wb_differential_wheels_disable_encoders()", (), |r| {
            r.disable_encoders()
        })
    }

    /// The encoder sampling period (ms), 0 when disabled. Webots:
    /// `wb_differential_wheels_get_encoders_sampling_period`.
    fn wb_differential_wheels_get_encoders_sampling_period() -> c_int {
        with_differential_wheels("wb_differential_wheels_get_encoders_sampling_period()", 0, |r| {
            c_int::try_from(r.encoders_sampling_period()).unwrap_or(c_int::MAX)
        })
    }

    /// The last sampled left encoder value (increments); while the encoders are disabled,
    /// Webots' error and the last sampled value. Webots:
    /// `wb_differential_wheels_get_left_encoder`.
    fn wb_differential_wheels_get_left_encoder() -> f64 {
        with_differential_wheels("wb_differential_wheels_get_left_encoder()", 0.0, |r| {
            encoder("wb_differential_wheels_get_left_encoder", r, r.left_encoder())
        })
    }

    /// The last sampled right encoder value (increments); see the left one. Webots:
    /// `wb_differential_wheels_get_right_encoder`.
    fn wb_differential_wheels_get_right_encoder() -> f64 {
        with_differential_wheels("wb_differential_wheels_get_right_encoder()", 0.0, |r| {
            encoder("wb_differential_wheels_get_right_encoder", r, r.right_encoder())
        })
    }

    /// Overwrites both encoder counts (increments) at the next step; NaN prints Webots' error
    /// and is ignored. Webots: `wb_differential_wheels_set_encoders`.
    fn wb_differential_wheels_set_encoders(left: f64, right: f64) {
        with_differential_wheels("wb_differential_wheels_set_encoders()", (), |r| {
            report(r.set_encoders(left, right))
        })
    }
}
