//! Distribution of the output torque to the driven wheels.

use ackermann::{DifferentialRatios, DriveType, PerWheel, Real};

/// Splits the wheel-side output torque (N·m) between the driven wheels with the geometric
/// differential ratios (dimensionless; after the optional [`crate::LimitedSlip::apply`]), as
/// Webots does in torque mode (spec §2.4):
///
/// * traction: `FR = out·ρf`, `FL = out·(1 − ρf)`;
/// * propulsion: `RR = out·ρr`, `RL = out·(1 − ρr)`;
/// * 4x4: `FR = out·ρf·ρc`, `FL = out·(1 − ρf)·ρc`, `RR = out·ρr·(1 − ρc)`,
///   `RL = out·(1 − ρr)·(1 − ρc)`.
///
/// Non-driven wheels get 0, and the four torques add up to `out` (up to rounding). A
/// non-finite `output` counts as 0 and a non-finite ratio as 0.5 (even split), so the result
/// is always finite (a product that overflows is reported as 0).
///
/// ```
/// use ackermann::{DifferentialRatios, DriveType};
/// use powertrain::split_torque;
/// let t = split_torque(1000.0_f64, DriveType::FourByFour, &DifferentialRatios::new(0.4, 0.45, 0.6));
/// assert!((t.as_array()[0] - 240.0).abs() < 1e-9); // 1000 · 0.4 · 0.6
/// assert!((t.into_iter().sum::<f64>() - 1000.0).abs() < 1e-9);
/// ```
pub fn split_torque<T: Real>(
    output: T,
    drive: DriveType,
    ratios: &DifferentialRatios<T>,
) -> PerWheel<T> {
    let out = output.finite_or(T::ZERO);
    let front = ratios.front.finite_or(T::HALF);
    let rear = ratios.rear.finite_or(T::HALF);
    let (front_share, rear_share) = match drive {
        DriveType::Traction => (T::ONE, T::ZERO),
        DriveType::Propulsion => (T::ZERO, T::ONE),
        DriveType::FourByFour => {
            let central = ratios.central.finite_or(T::HALF);
            (central, T::ONE - central)
        }
    };
    PerWheel::new(
        out * front * front_share,
        out * (T::ONE - front) * front_share,
        out * rear * rear_share,
        out * (T::ONE - rear) * rear_share,
    )
    .map(|t| t.finite_or(T::ZERO))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn traction_and_propulsion_drive_one_axle() {
        // Binary-exact ratios so the products are exact.
        let r = DifferentialRatios::new(0.25_f64, 0.375, 0.6);
        let t = split_torque(100.0, DriveType::Traction, &r);
        assert_eq!(t.into_array(), [25.0, 75.0, 0.0, 0.0]);
        let t = split_torque(100.0, DriveType::Propulsion, &r);
        assert_eq!(t.into_array(), [0.0, 0.0, 37.5, 62.5]);
    }

    #[test]
    fn four_by_four_uses_the_central_ratio() {
        let r = DifferentialRatios::new(0.4_f64, 0.45, 0.6);
        let t = split_torque(100.0, DriveType::FourByFour, &r).into_array();
        // 100·0.4·0.6 = 24, 100·0.6·0.6 = 36, 100·0.45·0.4 = 18, 100·0.55·0.4 = 22.
        let expected = [24.0, 36.0, 18.0, 22.0];
        for (a, e) in t.iter().zip(expected) {
            assert!((a - e).abs() < 1e-12, "{a} vs {e}");
        }
    }

    #[test]
    fn ratios_above_one_give_negative_shares_but_keep_the_sum() {
        // A limited-slip factor can push a ratio to 2 (spec §2.4): the left wheel then brakes.
        let r = DifferentialRatios::new(1.5_f64, 0.5, 0.5);
        let t = split_torque(100.0, DriveType::Traction, &r);
        assert_eq!(t.into_array(), [150.0, -50.0, 0.0, 0.0]);
    }

    #[test]
    fn bad_inputs_give_finite_torques() {
        let nan = DifferentialRatios::new(f32::NAN, f32::INFINITY, f32::NAN);
        let t = split_torque(100.0_f32, DriveType::FourByFour, &nan);
        assert_eq!(t.into_array(), [25.0, 25.0, 25.0, 25.0]);
        let even = DifferentialRatios::EVEN;
        for out in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            let t = split_torque(out, DriveType::FourByFour, &even);
            assert_eq!(t.into_array(), [0.0; 4]);
        }
        let huge = DifferentialRatios::new(f32::MAX, 0.5, 0.5);
        let t = split_torque(f32::MAX, DriveType::Traction, &huge);
        assert!(t.iter().all(|x| x.is_finite()));
    }
}
