//! The rear-axle centre's pose over a step: along the exact arc of the step's mean body
//! velocities.

use ackermann::{Pose, Real};

use super::Plant;

impl Plant {
    /// Moves the rear-axle centre along the arc of constant body velocity `velocity` (m/s)
    /// that turns by `turn` (rad) in `dt` (s).
    pub(super) fn advance_pose(&mut self, velocity: [f32; 2], turn: f32, dt: f32) {
        let half = 0.5 * turn;
        // The chord of the arc: the travelled vector times sin(h)/h, turned by half the turn.
        let sinc = if half == 0.0 {
            1.0
        } else {
            Real::sin(half) / half
        };
        let [dx, dy] = velocity.map(|v| v * dt * sinc);
        let heading = self.pose.yaw + half;
        let (sin, cos) = (Real::sin(heading), Real::cos(heading));
        let next = Pose::new(
            self.pose.x + dx * cos - dy * sin,
            self.pose.y + dx * sin + dy * cos,
            wrap_angle(self.pose.yaw + turn),
        );
        let distance = self.distance + Real::hypot(velocity[0], velocity[1]) * dt;
        if next.is_finite() && distance.is_finite() {
            self.pose = next;
            self.distance = distance;
        } else {
            self.fault();
        }
    }
}

/// `angle` (rad) in (−π, π].
fn wrap_angle(angle: f32) -> f32 {
    use core::f32::consts::{PI, TAU};
    // `%` is the exact fmod; the corrections are exact too.
    let r = angle % TAU;
    if r > PI {
        r - TAU
    } else if r <= -PI {
        r + TAU
    } else {
        r
    }
}
