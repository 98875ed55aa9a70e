//! A yaw-rate stability controller (ESC) as firmware would hold it: `no_std`, no heap, `f32`,
//! one call per control period with the sensor values, brake torques for single wheels out.
//!
//! The reference yaw rate is the single-track model's steady state for the driver's steering,
//! `r_ref = v·δ/(L + K·v²)`, no larger than the grip allows (`|r_ref| ≤ a_max/v`). When the
//! car yaws more to the left than that by more than a dead band (oversteer in a left turn, or
//! a yaw left while the driver already steers right), the front right wheel is braked: its
//! brake force, at half the track from the centre line, turns the car right; the other way
//! round the front left wheel. The torque grows with the excess yaw rate up to a cap.

#![no_std]

/// The controller's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EscParams {
    /// Wheelbase (m, > 0).
    pub wheelbase: f32,
    /// Understeer gradient of the reference (rad per m/s²): the car as it should behave.
    pub understeer_gradient: f32,
    /// Largest lateral acceleration the reference asks for (m/s², > 0): about the road's
    /// grip.
    pub max_lateral_accel: f32,
    /// Excess yaw rate tolerated before braking (rad/s, ≥ 0).
    pub dead_band: f32,
    /// Brake torque per rad/s of excess yaw rate beyond the dead band (N·m·s/rad, ≥ 0).
    pub gain: f32,
    /// Largest brake torque on one wheel (N·m, ≥ 0).
    pub max_torque: f32,
}

/// Below this speed (m/s) the controller does nothing: yaw at walking pace is manoeuvring.
const MIN_SPEED: f32 = 5.0;

impl EscParams {
    /// The reference yaw rate (rad/s, left positive) at `speed` (m/s, > 0) for the road-wheel
    /// steering `steering` (rad, left positive).
    pub fn reference_yaw_rate(&self, speed: f32, steering: f32) -> f32 {
        let r = speed * steering / (self.wheelbase + self.understeer_gradient * speed * speed);
        let limit = self.max_lateral_accel / speed;
        r.clamp(-limit, limit)
    }

    /// The brake torques (N·m, ≥ 0) to add on the wheels `[front right, front left, rear
    /// right, rear left]` at `speed` (m/s, forward), road-wheel `steering` (rad, left
    /// positive) and measured `yaw_rate` (rad/s, left positive). Non-finite input brakes
    /// nothing.
    pub fn brake_torques(&self, speed: f32, steering: f32, yaw_rate: f32) -> [f32; 4] {
        if !(speed.is_finite() && steering.is_finite() && yaw_rate.is_finite()) || speed < MIN_SPEED
        {
            return [0.0; 4];
        }
        let excess = yaw_rate - self.reference_yaw_rate(speed, steering);
        let torque = |e: f32| ((e - self.dead_band) * self.gain).clamp(0.0, self.max_torque);
        if excess > 0.0 {
            [torque(excess), 0.0, 0.0, 0.0]
        } else {
            [0.0, torque(-excess), 0.0, 0.0]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: EscParams = EscParams {
        wheelbase: 2.9,
        understeer_gradient: 0.0,
        max_lateral_accel: 8.0,
        dead_band: 0.05,
        gain: 5000.0,
        max_torque: 2500.0,
    };

    #[test]
    fn brakes_the_wheel_that_turns_the_car_back() {
        // 20 m/s, 0.02 rad left: r_ref = 20·0.02/2.9 = 0.138 rad/s.
        let r_ref = P.reference_yaw_rate(20.0, 0.02);
        assert!((r_ref - 0.4 / 2.9).abs() < 1e-6);
        // Within the dead band: nothing.
        assert_eq!(P.brake_torques(20.0, 0.02, r_ref + 0.04), [0.0; 4]);
        // 0.15 rad/s too much to the left: the front right wheel, (0.15 − 0.05)·5000.
        let t = P.brake_torques(20.0, 0.02, r_ref + 0.15);
        assert!((t[0] - 500.0).abs() < 0.1 && t[1] == 0.0, "{t:?}");
        // Too little: the front left; far too much: capped.
        assert!(P.brake_torques(20.0, 0.02, r_ref - 0.15)[1] > 0.0);
        assert_eq!(P.brake_torques(20.0, 0.02, 5.0)[0], 2500.0);
        // The grip limit caps the reference: 8/20 = 0.4 rad/s.
        assert!((P.reference_yaw_rate(20.0, 0.5) - 0.4).abs() < 1e-6);
        assert_eq!(P.brake_torques(2.0, 0.0, 1.0), [0.0; 4]);
        assert_eq!(P.brake_torques(f32::NAN, 0.0, 1.0), [0.0; 4]);
    }
}
