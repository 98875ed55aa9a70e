//! Webots' sampling schedule of a device (webots-devices spec §2), kept once for every sampled
//! thing: sensors, a camera's Recognition, the keyboard and the battery sensor.
//!
//! The rules: a device enabled with period `p` ms at time `t` samples at the first step end a
//! full period later (at `t + p` or after), then a full period after each sample; enabling
//! again with the period in force changes nothing (a controller that enables in its loop
//! still gets samples), a new period restarts the wait; period 0 disables, and the last
//! sample is kept.

/// When a device samples: its period and the time of its last sample (or of enabling).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Schedule {
    /// The sampling period (ms), 0 when disabled.
    period_ms: u32,
    /// The time of the last sample, or of enabling (ms).
    last_ms: u64,
}

impl Schedule {
    /// A schedule enabled at time 0 with `period_ms` (0: disabled).
    pub(crate) fn new(period_ms: u32) -> Self {
        Schedule {
            period_ms,
            last_ms: 0,
        }
    }

    /// The sampling period (ms), 0 when disabled.
    pub(crate) fn period_ms(&self) -> u32 {
        self.period_ms
    }

    /// True while enabled (a period other than 0).
    pub(crate) fn is_enabled(&self) -> bool {
        self.period_ms != 0
    }

    /// Sets the period to `period_ms` (0 disables) at `now_ms`. A new period restarts the wait
    /// for a full period; the period in force changes nothing. Returns true if it restarted.
    pub(crate) fn enable(&mut self, period_ms: u32, now_ms: u64) -> bool {
        if period_ms == self.period_ms {
            return false;
        }
        self.period_ms = period_ms;
        self.last_ms = now_ms;
        true
    }

    /// Restarts the wait at `now_ms` without changing the period: a device built enabled
    /// starts sampling when its car joins the world.
    pub(crate) fn restart(&mut self, now_ms: u64) {
        self.last_ms = now_ms;
    }

    /// The time since the last sample (or enabling) at `now_ms` (ms); 0 if `now_ms` is
    /// earlier, so a clock set back never makes a device due early.
    pub(crate) fn elapsed_ms(&self, now_ms: u64) -> u64 {
        now_ms.saturating_sub(self.last_ms)
    }

    /// True if a sample is due at `now_ms`: enabled, and a full period has passed.
    pub(crate) fn due(&self, now_ms: u64) -> bool {
        self.is_enabled() && self.elapsed_ms(now_ms) >= u64::from(self.period_ms)
    }

    /// True if a device that refreshes at every step while enabled (a rotating lidar, whose
    /// head turns whatever the period) samples at `now_ms`: enabled, and time has passed.
    pub(crate) fn due_every_step(&self, now_ms: u64) -> bool {
        self.is_enabled() && self.elapsed_ms(now_ms) >= 1
    }

    /// True if enabled and the last sample (or enabling) was at `now_ms`: after a step's
    /// sampling, where enabling cannot have happened at the same time, a sample taken then.
    pub(crate) fn sampled_at(&self, now_ms: u64) -> bool {
        self.is_enabled() && self.last_ms == now_ms
    }

    /// Records a sample taken at `now_ms`; returns the time since the previous one (ms).
    pub(crate) fn sampled(&mut self, now_ms: u64) -> u64 {
        let elapsed = self.elapsed_ms(now_ms);
        self.last_ms = now_ms;
        elapsed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_sample_is_due_a_full_period_after_enabling_then_every_period() {
        let mut s = Schedule::default();
        assert!(!s.due(10), "disabled");
        assert!(s.enable(30, 10));
        assert!(!s.due(20) && !s.due(39), "less than 30 ms passed");
        assert!(s.due(40));
        assert_eq!(s.sampled(40), 30);
        assert!(!s.due(60) && s.due(70));
    }

    #[test]
    fn enabling_with_the_period_in_force_keeps_the_schedule_and_a_new_one_restarts_it() {
        let mut s = Schedule::new(30);
        s.sampled(30);
        assert!(!s.enable(30, 50), "same period: no restart");
        assert!(s.due(60));
        assert!(s.enable(20, 50), "new period: the wait restarts at 50");
        assert!(!s.due(60) && s.due(70));
        assert!(s.enable(0, 70));
        assert!(!s.due(1_000) && !s.is_enabled());
        assert_eq!(s.period_ms(), 0);
    }

    #[test]
    fn a_clock_set_back_is_never_due_early_and_never_underflows() {
        let mut s = Schedule::new(10);
        s.restart(100);
        assert_eq!(s.elapsed_ms(50), 0);
        assert!(!s.due(50) && !s.due_every_step(50));
        assert!(!s.due_every_step(100) && s.due_every_step(101));
    }
}
