//! Kinematics mode of the DifferentialWheels robot: acceleration-limited wheel speeds, slip
//! noise and midpoint pose integration in the plane (spec §7.3, FLU formulas of Webots'
//! `WbKinematicDifferentialWheels`).

use crate::rng::SplitMix64;

use super::RobotPose;

/// Moves `actual` toward `target` by at most `max_step` without overshooting (rad/s).
fn approach(actual: f64, target: f64, max_step: f64) -> f64 {
    if actual < target {
        (actual + max_step).min(target)
    } else if actual > target {
        (actual - max_step).max(target)
    } else {
        actual
    }
}

/// One kinematics step of `dt` seconds.
///
/// 1. each actual wheel speed (rad/s, `[left, right]`) moves toward its target by at most
///    `max_acceleration·dt`;
/// 2. with `slip_noise ≠ 0`, each speed is multiplied by `1 − s + 2·s·U` (one draw per wheel,
///    left first);
/// 3. the pose advances by midpoint integration: `Δ = (n_R − n_L)·dt·r/(2·axle)` (half the
///    heading change), `a = θ + Δ`, `v = ½(n_L + n_R)·r·dt`, `x += v·cos a`, `y += v·sin a`,
///    `θ += 2Δ`. The height never changes.
///
/// Returns the noisy speeds `[n_L, n_R]` (rad/s) that moved the robot: the wheels turn by
/// `n·dt` and the encoders count from them.
#[allow(clippy::too_many_arguments)]
pub(crate) fn step(
    actual: &mut [f64; 2],
    target: [f64; 2],
    max_acceleration: f64,
    slip_noise: f64,
    wheel_radius: f64,
    axle_length: f64,
    dt: f64,
    pose: &mut RobotPose,
    rng: &mut SplitMix64,
) -> [f64; 2] {
    let max_step = max_acceleration * dt;
    for (a, t) in actual.iter_mut().zip(target) {
        *a = approach(*a, t, max_step);
    }
    let mut n = *actual;
    if slip_noise != 0.0 {
        for s in &mut n {
            *s *= rng.noise_factor(slip_noise);
        }
    }
    let [n_l, n_r] = n;
    let half_turn = (n_r - n_l) * dt * wheel_radius / (2.0 * axle_length);
    let a = pose.heading + half_turn;
    let v = 0.5 * (n_l + n_r) * wheel_radius * dt;
    pose.position.x += v * a.cos();
    pose.position.y += v * a.sin();
    pose.heading += 2.0 * half_turn;
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn acceleration_limit_without_overshoot() {
        assert_eq!(approach(0.0, 1.0, 0.3), 0.3);
        assert_eq!(approach(0.9, 1.0, 0.3), 1.0);
        assert_eq!(approach(0.0, -1.0, 0.3), -0.3);
        assert_eq!(approach(2.0, 2.0, 0.3), 2.0);
    }

    #[test]
    fn one_midpoint_step() {
        let mut pose = RobotPose::default();
        let mut actual = [1.0, 3.0];
        let mut rng = SplitMix64::new(0);
        let n = step(
            &mut actual,
            [1.0, 3.0],
            10.0,
            0.0,
            0.5,
            1.0,
            1.0,
            &mut pose,
            &mut rng,
        );
        assert_eq!(n, [1.0, 3.0]);
        // Δ = (3 − 1)·1·0.5/(2·1) = 0.5; v = 0.5·4·0.5 = 1.
        assert!((pose.heading - 1.0).abs() < 1e-15);
        assert!((pose.position.x - 0.5_f64.cos()).abs() < 1e-15);
        assert!((pose.position.y - 0.5_f64.sin()).abs() < 1e-15);
    }
}
