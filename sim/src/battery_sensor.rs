//! Webots' battery sensor (`wb_robot_battery_sensor_enable`, `…_get_value`): the energy left
//! in the robot's battery (J), sampled as every device is (spec §2: a sample at the first
//! step end a full period after enabling, then every period; the reading kept between).
//!
//! A car's battery is its traction battery's stored energy at its state of charge
//! (`vehicle_model::energy::Battery::energy`); a car without a battery reads NaN, as does
//! any sensor before its first sample.

use crate::sampling::Schedule;

/// A controller's battery sensor: its sampling and its last reading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatterySensor {
    schedule: Schedule,
    /// The last sample (J), NaN before the first.
    value: f64,
}

impl Default for BatterySensor {
    fn default() -> Self {
        BatterySensor {
            schedule: Schedule::default(),
            value: f64::NAN,
        }
    }
}

impl BatterySensor {
    /// Its sampling period (ms), 0 when disabled.
    pub fn period_ms(&self) -> u32 {
        self.schedule.period_ms()
    }

    /// Its last sample (J): the battery's energy at the last sample time; NaN before the
    /// first sample and for a car without a battery.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// Enables it with a period of `period_ms` (0 disables) at `now_ms`. A new period
    /// restarts the wait for a full period; the period in force changes nothing, so a
    /// controller that enables in its loop still gets samples (as every device).
    pub fn enable(&mut self, period_ms: u32, now_ms: u64) {
        self.schedule.enable(period_ms, now_ms);
    }

    /// The step end at `now_ms` with `energy` (J; `None` without a battery) in the battery:
    /// samples it if a full period has passed since the last sample.
    pub(crate) fn refresh(&mut self, now_ms: u64, energy: Option<f64>) {
        if self.schedule.due(now_ms) {
            self.schedule.sampled(now_ms);
            self.value = energy.unwrap_or(f64::NAN);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_sample_comes_a_full_period_after_enabling_then_every_period() {
        let mut s = BatterySensor::default();
        s.refresh(10, Some(1.0));
        assert!(s.value().is_nan(), "disabled: no sample");
        s.enable(30, 10);
        s.refresh(20, Some(2.0));
        s.refresh(30, Some(3.0));
        assert!(s.value().is_nan(), "20 ms of 30 passed");
        s.refresh(40, Some(4.0));
        assert_eq!(s.value(), 4.0);
        // Enabling again with the same period keeps the schedule.
        s.enable(30, 50);
        s.refresh(50, Some(5.0));
        s.refresh(60, Some(6.0));
        assert_eq!(s.value(), 4.0);
        s.refresh(70, Some(7.0));
        assert_eq!(s.value(), 7.0);
        // Disabled: the last reading stays.
        s.enable(0, 70);
        s.refresh(200, Some(8.0));
        assert_eq!((s.value(), s.period_ms()), (7.0, 0));
        // No battery: NaN.
        s.enable(10, 200);
        s.refresh(210, None);
        assert!(s.value().is_nan());
    }
}
