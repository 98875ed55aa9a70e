//! The car library's functions (Webots `wbu_car_*`).

use ackermann::{DriveType, Real, Wheel, WheelAngles};
use powertrain::{EngineType, LimitedSlip};

use super::Driver;
use crate::warning::Warning;

impl<T: Real> Driver<T> {
    /// The driven axle(s). Webots: `wbu_car_get_type`.
    pub fn drive_type(&self) -> DriveType {
        self.car.drive
    }

    /// The engine model. Webots: `wbu_car_get_engine_type`.
    pub fn engine_type(&self) -> EngineType {
        self.car.powertrain.engine().engine_type()
    }

    /// Sets the duration of each on and each off phase of the indicators (s, > 0; default
    /// 0.34). Webots: `wbu_car_set_indicator_period`.
    ///
    /// A period that is NaN, infinite, zero or negative is refused (Webots stores it and then
    /// divides by it): `Warning: wbu_car_set_indicator_period() called with an invalid 'period'
    /// argument (0)`.
    pub fn set_indicator_period(&mut self, period: T) -> Option<Warning> {
        if period.is_finite() && period > T::ZERO {
            self.indicator_period = period;
            None
        } else {
            Some(self.warn(Warning::InvalidArgument {
                function: "wbu_car_set_indicator_period",
                argument: "period",
                value: period.to_f64(),
            }))
        }
    }

    /// The indicator period (s). Webots: `wbu_car_get_indicator_period`.
    pub fn indicator_period(&self) -> T {
        self.indicator_period
    }

    /// The backwards-light state of the last step. Webots: `wbu_car_get_backwards_lights`.
    pub fn backwards_lights(&self) -> bool {
        self.lights.backwards
    }

    /// The brake-light state (set by [`Driver::set_brake_intensity`]). Webots:
    /// `wbu_car_get_brake_lights`.
    pub fn brake_lights(&self) -> bool {
        self.lights.brake
    }

    /// Distance between the front wheel centres (m). Webots: `wbu_car_get_track_front`.
    pub fn track_front(&self) -> T {
        self.car.geometry.track_front()
    }

    /// Distance between the rear wheel centres (m). Webots: `wbu_car_get_track_rear`.
    pub fn track_rear(&self) -> T {
        self.car.geometry.track_rear()
    }

    /// Distance between the axles (m). Webots: `wbu_car_get_wheelbase`.
    pub fn wheelbase(&self) -> T {
        self.car.geometry.wheelbase()
    }

    /// Front tyre radius (m). Webots: `wbu_car_get_front_wheel_radius`.
    pub fn front_wheel_radius(&self) -> T {
        self.car.geometry.radius_front()
    }

    /// Rear tyre radius (m). Webots: `wbu_car_get_rear_wheel_radius`.
    pub fn rear_wheel_radius(&self) -> T {
        self.car.geometry.radius_rear()
    }

    /// The last encoder reading of `wheel` (rad), 0 before the first sample (Webots: NaN).
    /// Webots: `wbu_car_get_wheel_encoder` (see
    /// [`wheel_from_webots_index`](crate::wheel_from_webots_index) for raw indices).
    pub fn wheel_encoder(&self, wheel: Wheel) -> T {
        self.wheel_speeds.encoders()[wheel]
    }

    /// The angular speed of `wheel` over the previous step (rad/s, positive = rolling
    /// forward), 0 until measurable. Webots: `wbu_car_get_wheel_speed`.
    pub fn wheel_speed(&self, wheel: Wheel) -> T {
        self.wheel_speeds.speeds()[wheel]
    }

    /// Commands the right steering motor directly to `angle` (rad, positive = right), without
    /// Ackermann and without changing the driver's steering angle (so speed-mode targets are
    /// not recomputed and, while that angle is 0, the differential stays even). The angle is
    /// used by the front differential ratio. Webots: `wbu_car_set_right_steering_angle`.
    ///
    /// A NaN or infinite angle is refused: `Warning: wbu_car_set_right_steering_angle() called
    /// with an invalid 'angle' argument (NaN)`.
    pub fn set_right_steering_angle(&mut self, angle: T) -> Option<Warning> {
        self.set_wheel_angle(angle, "wbu_car_set_right_steering_angle", |a, x| {
            a.right = x
        })
    }

    /// Commands the left steering motor directly to `angle` (rad); see
    /// [`Driver::set_right_steering_angle`]. Webots: `wbu_car_set_left_steering_angle`.
    pub fn set_left_steering_angle(&mut self, angle: T) -> Option<Warning> {
        self.set_wheel_angle(angle, "wbu_car_set_left_steering_angle", |a, x| a.left = x)
    }

    fn set_wheel_angle(
        &mut self,
        angle: T,
        function: &'static str,
        set: impl FnOnce(&mut WheelAngles<T>, T),
    ) -> Option<Warning> {
        if angle.is_finite() {
            set(&mut self.wheel_angles, angle);
            self.wheel_angles_direct = true;
            self.ratios = self
                .car
                .geometry
                .differential_ratios(self.steering_angle, self.wheel_angles);
            None
        } else {
            Some(self.warn(Warning::InvalidArgument {
                function,
                argument: "angle",
                value: angle.to_f64(),
            }))
        }
    }

    /// The measured right front-wheel steering angle (rad), 0 before the first sample. Webots:
    /// `wbu_car_get_right_steering_angle`.
    pub fn right_steering_angle(&self) -> T {
        self.measured_steering.right
    }

    /// The measured left front-wheel steering angle (rad), 0 before the first sample. Webots:
    /// `wbu_car_get_left_steering_angle`.
    pub fn left_steering_angle(&self) -> T {
        self.measured_steering.left
    }

    /// The front-wheel angles the steering motors are commanded to (rad): Ackermann angles of
    /// the driver's steering angle, or those set directly. Not in Webots.
    pub fn commanded_wheel_angles(&self) -> WheelAngles<T> {
        self.wheel_angles
    }

    /// Turns the limited-slip differential on or off (default on); its states are kept.
    /// Webots: `wbu_car_enable_limited_slip_differential`.
    pub fn enable_limited_slip_differential(&mut self, enable: bool) {
        self.limited_slip.set_enabled(enable);
    }

    /// The limited-slip differential and its slip states. Not in Webots.
    pub fn limited_slip(&self) -> &LimitedSlip<T> {
        &self.limited_slip
    }

    /// Turns the indicator auto-cancel on or off (default on). Webots:
    /// `wbu_car_enable_indicator_auto_disabling`.
    pub fn enable_indicator_auto_disabling(&mut self, enable: bool) {
        self.indicator_auto_disabling = enable;
    }

    /// True while the indicator auto-cancel is on. Not in Webots.
    pub fn indicator_auto_disabling(&self) -> bool {
        self.indicator_auto_disabling
    }
}
