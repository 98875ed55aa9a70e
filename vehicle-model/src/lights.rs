//! Lights: the LED states the driver library writes, and the indicator blink clock.

use ackermann::Real;

/// Default duration of each on and each off phase of the indicators (s).
///
/// Webots: `DEFAULT_INDICATOR_PERIOD` in `car.c`, read back by `wbu_car_get_indicator_period`.
pub const DEFAULT_INDICATOR_PERIOD: f64 = 0.34;

/// The state of every LED of the Webots `VehicleLights` group (plus the interior indicator
/// LEDs some models have). `true` = lit.
///
/// The host renders whichever lights its model has; the driver sets all of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Lights {
    /// Webots LED `front_lights`: on with the dipped beams.
    pub front: bool,
    /// Webots LED `rear_lights`: on with the dipped beams.
    pub rear: bool,
    /// Webots LED `antifog_lights`.
    pub antifog: bool,
    /// Webots LED `brake_lights`: on while the brake intensity is > 0.
    pub brake: bool,
    /// Webots LED `backwards_lights`: on in reverse (torque mode with gear −1, or speed mode
    /// with a negative cruising speed).
    pub backwards: bool,
    /// Webots LED `right_indicators`: follows the blink clock while the right indicator or the
    /// hazard flashers are on.
    pub right_indicator: bool,
    /// Webots LED `left_indicators`.
    pub left_indicator: bool,
    /// Webots LED `interior_right_indicators`: always equal to `right_indicator`.
    pub interior_right_indicator: bool,
    /// Webots LED `interior_left_indicators`: always equal to `left_indicator`.
    pub interior_left_indicator: bool,
}

impl Lights {
    /// All lights off (the state after `wbu_driver_init`).
    pub const OFF: Lights = Lights {
        front: false,
        rear: false,
        antifog: false,
        brake: false,
        backwards: false,
        right_indicator: false,
        left_indicator: false,
        interior_right_indicator: false,
        interior_left_indicator: false,
    };

    /// Sets the right indicator LED and its interior copy, as Webots'
    /// `_wbu_car_set_led_state_if_exist` does.
    #[inline]
    pub fn set_right_indicators(&mut self, on: bool) {
        self.right_indicator = on;
        self.interior_right_indicator = on;
    }

    /// Sets the left indicator LED and its interior copy.
    #[inline]
    pub fn set_left_indicators(&mut self, on: bool) {
        self.left_indicator = on;
        self.interior_left_indicator = on;
    }
}

/// The blink clock: true during the "on" phases `[2k·P, (2k+1)·P)` of simulation time
/// `time` (s) for indicator period `period` (s, > 0).
///
/// Webots: `((int)(t / indicator_period) % 2) == 0` in `wbu_driver_step`, so every car blinks in
/// phase and the first phase (from t = 0) is "on". The quotient is truncated toward zero like
/// the C cast. A NaN or infinite quotient counts as "off".
#[inline]
pub fn blink_on<T: Real>(time: T, period: T) -> bool {
    let q = (time / period).trunc();
    if !q.is_finite() {
        return false;
    }
    // Parity of an integral float without an integer cast (which could overflow).
    q - T::TWO * (q * T::HALF).trunc() == T::ZERO
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blink_timeline_at_0_34_s() {
        // Phases of 0.34 s: on [0, 0.34), off [0.34, 0.68), on [0.68, 1.02), …
        let p = 0.34_f64;
        assert!(blink_on(0.0, p));
        assert!(blink_on(0.339, p));
        assert!(!blink_on(0.34, p));
        assert!(!blink_on(0.679, p));
        assert!(blink_on(0.68, p));
        assert!(blink_on(1.0, p));
        assert!(!blink_on(1.02, p));
        // f32 agrees away from the phase edges.
        assert!(blink_on(0.1_f32, 0.34));
        assert!(!blink_on(0.5_f32, 0.34));
    }

    #[test]
    fn blink_handles_degenerate_inputs() {
        assert!(!blink_on(f64::NAN, 0.34));
        assert!(!blink_on(1.0, 0.0)); // quotient +inf
        assert!(!blink_on(f32::INFINITY, 0.34));
        // Beyond 2^53 every float is an even integer: the clock stays "on", no overflow.
        assert!(blink_on(1e300_f64, 0.34));
    }

    #[test]
    fn indicator_setters_mirror_interior_leds() {
        let mut l = Lights::OFF;
        l.set_right_indicators(true);
        assert!(l.right_indicator && l.interior_right_indicator);
        assert!(!l.left_indicator && !l.interior_left_indicator);
        l.set_left_indicators(true);
        l.set_right_indicators(false);
        assert_eq!(
            (
                l.right_indicator,
                l.interior_right_indicator,
                l.left_indicator
            ),
            (false, false, true)
        );
    }
}
